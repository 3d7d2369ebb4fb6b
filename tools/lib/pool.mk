# tools/lib/pool.mk - the local engine: one round of planned simulations run by GNU make's
# jobserver, one job per simulation (tools/run-simulation, one thread each).
#   make -f tools/lib/pool.mk OUT=RESULT_DIR [ID=PAPER/EXP] [LAUNCH=PREFIX]
# runs every simulation named in OUT/.plan (one name per line, from dpd_run's plan mode).
# Started by tools/run-experiment inside `make figures` / `make reproduce`, this make joins the
# jobserver of the top-level make, so the simulations of every experiment under way share one
# pool of -j slots (one per core by default); started alone it gets its own -j.
# LAUNCH prefixes the job: empty here, tools/slurm-sim for the Slurm engine (a job per
# simulation, the slot waits for it).
# A failed simulation does not stop the others: its status is in runs/NAME/.exit, and the
# experiment's next plan pass decides (tools/lib/exp.sh dpd_run).
TOOLS := $(patsubst %/lib/,%,$(dir $(lastword $(MAKEFILE_LIST))))
RUNS := $(shell cat '$(OUT)/.plan')
.PHONY: all $(RUNS)
all: $(RUNS)
# ID: the experiment (for the progress line of make figures / make reproduce: tools/progress, not
# started unless DPD_PROGRESS is set)
$(RUNS):
	@$(LAUNCH) '$(TOOLS)/run-simulation' '$(OUT)/runs/$@' || echo "pool: simulation $@ exited $$? (see $(OUT)/runs/$@)" >&2; \
	[ -z "$${DPD_PROGRESS:-}" ] || '$(TOOLS)/progress' done '$(ID)' '$(OUT)' '$@'

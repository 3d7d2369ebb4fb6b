# experiments.mk - results, figures and checks for every experiments/PAPER/EXP.
# results/PAPER/EXP/TIER/summary.tsv is made by tools/run-experiment from the experiment's
# run.sh, scenes and bin/dpd; figures/PAPER/EXP/*-TIER.png by gnuplot from its plot.gp.
# The simulations of all the experiments under way run in one pool: tools/run-experiment joins
# this make's jobserver (its recipes are marked `+`), so `make figures` runs one one-thread
# simulation per slot, JOBS slots (default: one per core), whichever experiment they belong to.
# ENGINE=slurm sends each simulation to Slurm instead (tools/slurm-sim; JOBS is then the number
# of simulations in flight, default 200).
EXP_IDS := $(patsubst experiments/%/run.sh,%,$(wildcard experiments/*/*/run.sh))
RESULTS := $(foreach e,$(EXP_IDS),results/$(e)/$(TIER)/summary.tsv)
FIG_STAMPS := $(foreach e,$(EXP_IDS),figures/$(e)/.stamp-$(TIER))
ENGINE ?= local
JOBS ?= $(if $(filter slurm,$(ENGINE)),200,$(shell nproc))
export DPD_ENGINE := $(ENGINE)
# a -j of our own unless the caller gave one (then we share its jobserver)
POOL_J = $(if $(findstring jobserver,$(MAKEFLAGS)),,-j$(JOBS))
# the sub-make and each tools/run-experiment end with the make that started them (SIGTERM when it
# ends, even by SIGKILL: prctl PR_SET_PDEATHSIG through util-linux's setpriv); run-experiment's
# own children end with it in turn (tools/lib/pdeath.sh), so a killed `make figures` leaves no
# experiment, pool, run-simulation or simulator running beside the next one
PDEATH := $(shell setpriv --pdeathsig TERM true >/dev/null 2>&1 && echo setpriv --pdeathsig TERM)

# results are files we keep, never intermediate ones that make may delete after plotting
.SECONDARY: $(RESULTS)
.SECONDEXPANSION:
results/%/$(TIER)/summary.tsv: $$(wildcard experiments/%/*) tools/run-experiment tools/run-simulation tools/lib/exp.sh $(BIN)
	+@$(PDEATH) tools/run-experiment $* $(TIER)

# the dependencies between experiments, declared once in each run.sh (`needs`, tools/lib/exp.sh)
build/needs.mk: $(wildcard experiments/*/*/run.sh) tools/lib/needs.awk
	@mkdir -p build && awk -f tools/lib/needs.awk $(wildcard experiments/*/*/run.sh) > $@
-include build/needs.mk
# a file, not a result: fig08 runs the m = 0 scene of fig06
results/phan-thien-2016/fig08-compressibility/$(TIER)/summary.tsv: experiments/phan-thien-2016/fig06-cylinder-exclusion/cylinder.cfg

PLOT = mkdir -p figures/$(1) && cd experiments/$(1) && \
       gnuplot -e "res='$(CURDIR)/results/$(1)/$(TIER)'; out='$(CURDIR)/figures/$(1)'; tier='$(TIER)'" plot.gp

figures/%/.stamp-$(TIER): results/%/$(TIER)/summary.tsv experiments/%/plot.gp
	@$(call PLOT,$*)
	@touch $@

# Plots from the results already there (e.g. the committed paper tier), no reruns.
plots:
	@for e in $(EXP_IDS); do \
	    if [ -f results/$$e/$(TIER)/summary.tsv ]; then ( $(call PLOT,$$e) ) || exit 1; \
	    else echo "plots: no $(TIER) results for $$e (make figures TIER=$(TIER))"; fi; done

# EXPERIMENTS="paper/exp ..." selects experiments (default: all)
EXPERIMENTS ?= $(EXP_IDS)
# One progress line over them all as simulations finish, "[12/401 simulations, 3.2 of 45 CPU-h,
# ETA 18:40]" (tools/progress: a ledger in build/progress-TIER, the cost model's projection of the
# experiments whose results are out of date, which `make -n` names: tools/run-experiment says so)
# PROGRESS_LINE=0: no line, no ledger and no projection (CI, whose log is read after the run: at the
# quick tier the projection and the hook after each of its 200 simulations cost about 50 CPU-s)
PROGRESS_LINE ?= 1
ifeq ($(PROGRESS_LINE),0)
PROGRESS =
PROGRESS_START = true
else
PROGRESS = DPD_PROGRESS='$(CURDIR)/build/progress-$(TIER)' DPD_PROGRESS_SLOTS=$(JOBS)
PROGRESS_START = $(PROGRESS) tools/progress start $(TIER) $$($(MAKE) -n --no-print-directory \
    $(foreach e,$(EXPERIMENTS),results/$(e)/$(TIER)/summary.tsv) 2>/dev/null | awk '$$1 == "tools/run-experiment" { print $$2 }')
endif
results: $(BIN)
	+@$(PROGRESS_START)
	+@$(PROGRESS) $(PDEATH) $(MAKE) --no-print-directory $(POOL_J) $(foreach e,$(EXPERIMENTS),results/$(e)/$(TIER)/summary.tsv)
figures: $(BIN)
	+@$(PROGRESS_START)
	+@$(PROGRESS) $(PDEATH) $(MAKE) --no-print-directory $(POOL_J) $(foreach e,$(EXPERIMENTS),figures/$(e)/.stamp-$(TIER))
	@echo "figures ($(TIER)) in figures/; check with: make check TIER=$(TIER)"

check:
	@tools/check --tier $(TIER)

# the committed record of the verdicts (results/verdicts.tsv: one row per experiment, from the tier
# its numbers come from) and of every band row behind them (results/checks.tsv), so that a commit
# that changes a band, the decision rule or a result shows which verdicts moved
verdicts:
	@tools/check --verdicts --tier auto > results/verdicts.tsv
	@tail -n +2 results/verdicts.tsv | while IFS=$$'\t' read -r id t _; do \
	    [ "$$t" = - ] || tools/check --tsv --tier "$$t" "$$id" | awk -F '\t' -v t="$$t" -v OFS='\t' \
	        '{ print $$1, t, $$2, $$13, $$3, $$4, $$5, $$6, $$7, $$9 }'; done | \
	    { printf 'experiment\ttier\tquantity\tkind\tvalue\tstderr\tlo\thi\tk_sigma\toutcome\n'; cat; } > results/checks.tsv
	@echo "verdicts: wrote results/verdicts.tsv and results/checks.tsv"

reproduce:
	$(PDEATH) $(MAKE) figures TIER=paper
	$(PDEATH) $(MAKE) check TIER=paper || true
	$(PDEATH) $(MAKE) paper

# verify-results: every result must still be what its current inputs give (it fails on a stale one)
paper: $(BIN)
	@tools/verify-results
	@$(MAKE) --no-print-directory build/cost.tsv
	@$(MAKE) --no-print-directory plots TIER=paper
	@set -o pipefail; $(MAKE) --no-print-directory plots TIER=reduced 2>&1 | { grep -v '^plots: no reduced results' || true; }
	@tools/render-paper

# paper.md's cost table of the paper tier (tools/cost): remade when a plan, a scene or a committed
# result's cost changes
build/cost.tsv: $(BIN) tools/cost tools/plan $(wildcard bench/speedup.tsv experiments/*/*/run.sh experiments/*/*/*.cfg) \
                $(wildcard results/*/*/paper/provenance.tsv results/*/*/reduced/provenance.tsv)
	@mkdir -p build && tools/cost table paper > $@.part && mv $@.part $@

.PHONY: results plots figures check verdicts reproduce paper

# experiments.mk - results, figures and checks for every experiments/PAPER/EXP.
# results/PAPER/EXP/TIER/summary.tsv is made by tools/run-experiment from the
# experiment's run.sh, scenes and bin/dpd; figures/PAPER/EXP/*-TIER.png by
# gnuplot from its plot.gp.
EXP_IDS := $(patsubst experiments/%/run.sh,%,$(wildcard experiments/*/*/run.sh))
RESULTS := $(foreach e,$(EXP_IDS),results/$(e)/$(TIER)/summary.tsv)
FIG_STAMPS := $(foreach e,$(EXP_IDS),figures/$(e)/.stamp-$(TIER))

.SECONDEXPANSION:
results/%/$(TIER)/summary.tsv: $$(wildcard experiments/%/*) tools/run-experiment tools/lib/exp.sh $(BIN)
	@tools/run-experiment $* $(TIER)

PLOT = mkdir -p figures/$(1) && cd experiments/$(1) && \
       gnuplot -e "res='$(CURDIR)/results/$(1)/$(TIER)'; out='$(CURDIR)/figures/$(1)'; tier='$(TIER)'" plot.gp

# results that read another experiment's result of the same tier (so `make -j` orders them)
results/phan-thien-2016/fig07-drag-velocity/$(TIER)/summary.tsv: results/phan-thien-2016/fig06-cylinder-exclusion/$(TIER)/summary.tsv
results/phan-thien-2016/fig13-shear-thinning/$(TIER)/summary.tsv: results/phan-thien-2016/fig10-11-colloid-structure/$(TIER)/summary.tsv
# paper tier: results that reuse another experiment's simulations (reuse_run, tools/lib/exp.sh)
results/mai-duy-2019/tab02-effective-viscosity/paper/summary.tsv \
results/mai-duy-2019/fig04-relative-viscosity-a353/paper/summary.tsv: results/mai-duy-2019/tab01-wavelengths/paper/summary.tsv
results/mai-duy-2019/tab02-readings/paper/summary.tsv: results/mai-duy-2019/tab01-wavelengths/paper/summary.tsv
results/mai-duy-2019/tab02-readings/paper/summary.tsv: results/mai-duy-2019/fig01-viscosity-wavenumber/paper/summary.tsv
results/mai-duy-2019/tab02-readings/paper/summary.tsv: results/mai-duy-2019/fig02-length-scale/paper/summary.tsv
results/mai-duy-2019/tab02-readings/paper/summary.tsv: results/mai-duy-2019/fig04-relative-viscosity-a353/paper/summary.tsv
results/mai-duy-2019/tab02-readings/paper/summary.tsv: results/mai-duy-2019/fig05-relative-viscosity-a650/paper/summary.tsv

figures/%/.stamp-$(TIER): results/%/$(TIER)/summary.tsv experiments/%/plot.gp
	@$(call PLOT,$*)
	@touch $@

# Plots from the results already there (e.g. the committed paper tier), no reruns.
plots:
	@for e in $(EXP_IDS); do \
	    if [ -f results/$$e/$(TIER)/summary.tsv ]; then ( $(call PLOT,$$e) ) || exit 1; \
	    else echo "plots: no $(TIER) results for $$e (make figures TIER=$(TIER))"; fi; done

results: $(RESULTS)
figures: $(FIG_STAMPS)
	@echo "figures ($(TIER)) in figures/; check with: make check TIER=$(TIER)"

check:
	@tools/check --tier $(TIER)

reproduce:
	$(MAKE) figures TIER=paper
	$(MAKE) check TIER=paper || true
	$(MAKE) paper

# verify-results: every result must still be what its current inputs give (it fails on a stale one)
paper: $(BIN)
	@tools/verify-results
	@$(MAKE) --no-print-directory plots TIER=paper
	@set -o pipefail; $(MAKE) --no-print-directory plots TIER=reduced 2>&1 | { grep -v '^plots: no reduced results' || true; }
	@tools/render-paper

.PHONY: results plots figures check reproduce paper


# fig07 takes the exclusion radius measured by fig06 at the same tier
results/phan-thien-2016/fig07-drag-velocity/$(TIER)/summary.tsv: results/phan-thien-2016/fig06-cylinder-exclusion/$(TIER)/summary.tsv
# fig08 runs the m = 0 scene of fig06
results/phan-thien-2016/fig08-compressibility/$(TIER)/summary.tsv: experiments/phan-thien-2016/fig06-cylinder-exclusion/cylinder.cfg
# fig13 takes the colloid radius and D measured by fig10-11 at the same tier
results/phan-thien-2016/fig13-shear-thinning/$(TIER)/summary.tsv: results/phan-thien-2016/fig10-11-colloid-structure/$(TIER)/summary.tsv

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

figures/%/.stamp-$(TIER): results/%/$(TIER)/summary.tsv experiments/%/plot.gp
	@mkdir -p figures/$*
	@cd experiments/$* && gnuplot -e "res='$(CURDIR)/results/$*/$(TIER)'; out='$(CURDIR)/figures/$*'; tier='$(TIER)'" plot.gp
	@touch $@

results: $(RESULTS)
figures: $(FIG_STAMPS)
	@echo "figures ($(TIER)) in figures/; check with: make check TIER=$(TIER)"

check:
	@tools/check --tier $(TIER)

reproduce:
	$(MAKE) figures TIER=paper
	$(MAKE) check TIER=paper || true
	$(MAKE) paper

paper: | $(BIN)
	@tools/render-paper

.PHONY: results


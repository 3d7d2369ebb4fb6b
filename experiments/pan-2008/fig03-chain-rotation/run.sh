#!/usr/bin/env bash
# Pan et al. 2008, Fig. 3: torque shape factor T_s = -T / (8 pi mu Omega N R^3)
# (eq. 24) of a straight chain of N touching spheres spinning about its axis.
. "$DPD_ROOT/tools/lib/exp.sh"
MU=3.6388 R=0.2737 OMEGA=-2.0 C=5.0      # paper mu and R; chain along x through the box centre
case $TIER in
    quick) NS="1 8"; len=(--set steps=6000 --set measure.every=2) ;;
    # reduced: the committed result, 10 + 100 time units per N (the scene's steps; README)
    reduced) NS="1 2 3 4 5 6 7 8"; len=() ;;
    # paper: 10 + 2000 time units per N: the length that decides T_s(1)'s band under issue 37's rule
    # (README; issue 38: T_s(1) to 0.8 %, a quarter of the paper value's distance to the band's edge)
    # N = 1 runs 10 + 4000 (2026-12-06): at 2000 it gave T_s(1) = 1.0358 +- 0.0071, its value + 2 se on
    # the band's edge 1.05 (UNRESOLVED; make check: 1.01 times the length decides); doubled for margin.
    # The same seed, so the first 2000 time units are the first run's (README: a length set after a
    # result, disclosed)
    paper) NS="1 2 3 4 5 6 7 8"; len=(--set steps=200000); len_N1=(--set steps=400000) ;;
esac
# the simulations: one chain of N spheres per N
simulations() {
for N in $NS; do
    pos=$("$ANALYSE" chain-positions $N $R $C)
    l=("${len[@]}"); [ "$N" = 1 ] && [ -n "${len_N1+x}" ] && l=("${len_N1[@]}")
    dpd_run N$N chain.cfg "${l[@]}" --set "types.[1].positions=$pos" --set "types.[1].spin=[$OMEGA,0.0,0.0]" \
        --set "seed=$((2400 + N))"
done
}
analysis() {
# the analysis
printf 'N\tTs\tTs_se\ttorque\ttorque_se\n' > "$OUT/shape_factor.tsv"
for N in $NS; do
    Ts=$("$ANALYSE" chain-shape-factor "$(get N$N torque_on_chain_x)" $MU $R $OMEGA $N)
    emit "Ts_N$N" $Ts
    printf '%s\t%s\t%s\n' $N "$Ts" "$(get N$N torque_on_chain_x)" >> "$OUT/shape_factor.tsv"
done
# the fall with N: (T_s(1) - T_s(8)) in units of its standard error
"$ANALYSE" diff-sigmas "$OUT/summary.tsv" Ts_N1 Ts_N8 Ts_drop_N8 >> "$OUT/summary.tsv"
# what paper.md says in words (issue 40 item 7): the single sphere's T_s against eq. 18's 1
emit_pct Ts_N1_pct_from_eq18 "$(get . Ts_N1)" 1
}
experiment

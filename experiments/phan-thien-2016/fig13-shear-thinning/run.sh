#!/usr/bin/env bash
# Fig. 13 of Phan-Thien et al. 2016: viscosity of the most dilute suspension (one
# massless spring colloid in the 6 x 6 box, phi = 0.0204) against the Peclet number
# Pe = rate a^2 / D (a, D of the colloid measured by fig10-11-colloid-structure at the
# same tier), Lees-Edwards shear at rates 0.25 ... 33, m = 0; the solvent alone at the
# same rates separates the solvent's own rate dependence from the colloid's.
. "$DPD_ROOT/tools/lib/exp.sh"
needs any phan-thien-2016/fig10-11-colloid-structure
scene=$DPD_ROOT/experiments/phan-thien-2016/fig12-relative-viscosity/shear.cfg
case $TIER in
    quick) rates="0.25 1 4 33"; tier=(--set equilibration=300 --set steps=8000) ;;
    paper) rates="0.25 0.5 1 2 4 8 16 33"; tier=(--set equilibration=1000 --set steps=40000) ;;
esac
# the simulations: the suspension (k1) and the solvent alone (k0) at each rate
simulations() {
n=0
for r in $rates; do
    n=$((n + 1))
    dpd_run "k1_rate$r" "$scene" "${tier[@]}" --set shear_rate=$r --set seed=$((1300 + n))
    dpd_run "k0_rate$r" "$scene" "${tier[@]}" --set shear_rate=$r --set seed=$((1400 + n)) \
        --set colloids2d.count=0 --set types.[1].count=0
done
}
analysis() {
f1011=$(upstream phan-thien-2016/fig10-11-colloid-structure)/summary.tsv
# the analysis
a=$("$ANALYSE" lookup "$f1011" colloid_radius | cut -f1) D=$("$ANALYSE" lookup "$f1011" D_colloid | cut -f1)
emit colloid_radius "$a" 0
emit D_colloid "$D" 0
printf 'rate\tPe\teta\teta_se\teta_solvent\teta_solvent_se\teta_r\teta_r_se\n' > "$OUT/thinning.tsv"
for r in $rates; do
    emit_from "k1_rate$r" viscosity "eta_rate$r"
    emit_from "k0_rate$r" viscosity "eta_solvent_rate$r"
    emit_ratio "eta_r_rate$r" "k1_rate$r" viscosity "k0_rate$r" viscosity
    e=$(get "k1_rate$r" viscosity) e0=$(get "k0_rate$r" viscosity)
    "$ANALYSE" thinning-row $r "$a" "$D" "$e" "$e0" >> "$OUT/thinning.tsv"
done
lo=${rates%% *} hi=${rates##* }
emit_ratio thinning_ratio "k1_rate$lo" viscosity "k1_rate$hi" viscosity
emit_ratio solvent_thinning_ratio "k0_rate$lo" viscosity "k0_rate$hi" viscosity
"$ANALYSE" significance "$OUT/summary.tsv" thinning_ratio thinning_significance > "$OUT/.rows"
cat "$OUT/.rows" >> "$OUT/summary.tsv"; rm "$OUT/.rows"
"$ANALYSE" relative-thinning "$OUT/thinning.tsv" $lo $hi >> "$OUT/summary.tsv"
# what paper.md says in words (issue 40 item 7): the suspension's thinning ratio against the
# solvent's, in standard errors
"$ANALYSE" sigmas thinning_ratio_sigmas_from_solvent "$(get . thinning_ratio)" "$(get . solvent_thinning_ratio)" >> "$OUT/summary.tsv"
}
experiment

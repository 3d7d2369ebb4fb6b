#!/usr/bin/env bash
# Fig. 12 of Phan-Thien et al. 2016: relative viscosity eta_r = eta / eta_solvent of
# k = 1, 2, 3, 4, 6, 8 massless spring colloids (3 particles each) in the 6 x 6 box of
# 144 solvent particles, phi = 3 k / (144 + 3 k), against Brady's 2D 1 + 2 phi (eq. 53);
# eta from Lees-Edwards simple shear at rate 1 (m = 0), the solvent alone at the same rate.
. "$DPD_ROOT/tools/lib/exp.sh"
case $TIER in
    quick) tier=(--set equilibration=300 --set steps=6000) ;;
    paper) tier=(--set equilibration=1000 --set steps=40000) ;;
esac
ks="1 2 3 4 6 8"
# the simulations: the solvent alone (k = 0) and the suspensions
simulations() {
dpd_run k0 shear.cfg "${tier[@]}" --set colloids2d.count=0 --set types.[1].count=0 --set seed=1200
for k in $ks; do
    dpd_run "k$k" shear.cfg "${tier[@]}" --set colloids2d.count=$k --set "types.[1].count=$((3 * k))" \
        --set seed=$((1200 + k))
done
}
analysis() {
# the analysis
emit_from k0 viscosity eta_solvent
printf 'k\tphi\teta\teta_se\teta_r\teta_r_se\teta_r_minus_1\teta_spring\teta_spring_se\n' > "$OUT/eta_r.tsv"
for k in $ks; do
    emit_from "k$k" viscosity "eta_k$k"
    emit_ratio "eta_r_k$k" "k$k" viscosity k0 viscosity
    e=$(get "k$k" viscosity) e0=$(get k0 viscosity) es=$(get "k$k" viscosity_spring)
    "$ANALYSE" fig12-row $k "$e" "$e0" "$es" >> "$OUT/eta_r.tsv"
done
# eq. 53 slope: eta_r - 1 = s phi through (0, 1), weighted (GSL gsl_fit_wmul), phi <= 0.06 (k = 1, 2, 3)
"$DPD" fit-line "$OUT/eta_r.tsv" --x phi --y eta_r_minus_1 --se eta_r_se --range 0:0.06 --origin > "$OUT/fit.tsv"
"$ANALYSE" slope-rows "$OUT/fit.tsv" eta_r_slope >> "$OUT/summary.tsv"
# the spring stress at the most concentrated suspension (the paper: oscillatory, zero mean)
emit_from k8 viscosity_spring eta_spring_k8
# what paper.md says in words (issue 40 item 7): the slope's distance from Brady's 2 in standard
# errors, and the suspension's viscosity above the solvent's at k = 8
"$ANALYSE" sigmas eta_r_slope_sigmas_from_2 "$(get . eta_r_slope)" 2 >> "$OUT/summary.tsv"
emit_minus eta_k8_minus_eta_solvent "$(get . eta_k8)" "$(get . eta_solvent)"
}
experiment

#!/usr/bin/env bash
# Shear viscosity of the mai-duy-2019 solvent against the repulsion a (section 4.3),
# eta = <T_xy> / rate under Lees-Edwards shear (eq. 11).
. "$DPD_ROOT/tools/lib/exp.sh"
case $TIER in
    quick) tier=(--set 'box=[8.0,8.0,8.0]' --set dt=0.01 --set equilibration=500 --set steps=4000) ;;
    paper) tier=() ;;
esac
A_VALUES="3.53 6.50 9.50 18.50"
printf 'a\teta\teta_se\tpaper\n' > "$OUT/eta.tsv"
paper_eta() { case $1 in 3.53) echo 29.08;; 6.50) echo 29.66;; 9.50) echo 30.22;; 18.50) echo 30.66;; esac; }
simulations() {
k=0
for a in $A_VALUES; do
    dpd_run a$a solvent-shear.cfg "${tier[@]}" --set "pairs.[0].a=$a" --set "seed=$((20190 + k))"
    k=$((k + 1))
done
}
analysis() {
for a in $A_VALUES; do
    emit_from a$a viscosity "eta_a$a"
    emit_from a$a temperature "temperature_a$a"
    v=$(get a$a viscosity)
    printf '%s\t%s\t%s\n' "$a" "$v" "$(paper_eta $a)" >> "$OUT/eta.tsv"
    cp "$OUT/runs/a$a/profile.tsv" "$OUT/profile_a$a.tsv"
done
emit_diff eta_diff_a6.50_a3.53 a6.50 viscosity a3.53 viscosity
emit_diff eta_diff_a9.50_a6.50 a9.50 viscosity a6.50 viscosity
emit_diff eta_diff_a18.50_a9.50 a18.50 viscosity a9.50 viscosity
# what the random stress costs (paper.md): the standard error of the viscosity with the random part
# of the stress over that without it, at a = 3.53 (a quotient of two errors, itself without one)
se_with=$(get a3.53 viscosity_with_random | cut -f2) se_without=$(get a3.53 viscosity | cut -f2)
emit random_stress_error_factor_a3.53 "$(printf '%.6g' "$(bc -l <<< "$se_with / $se_without")")" 0
}
experiment

#!/usr/bin/env bash
# Fig. 7 of Phan-Thien et al. 2016: drag on the 4-particle cylinder against the
# mean fluid velocity U under a body force P per fluid particle (m = 0),
# compared with Hasimoto's eq. 47, F = 4 pi eta U / (ln(h/a) - 1.3105), with
# eta measured here by Lees-Edwards shear of the same fluid and a the exclusion
# radius measured in fig06-cylinder-exclusion (same tier).
. "$DPD_ROOT/tools/lib/exp.sh"
needs any phan-thien-2016/fig06-cylinder-exclusion
# fig03's committed Couette viscosities, read against this experiment's Lees-Edwards solvent (paper.md)
needs any phan-thien-2016/fig03-couette-profile@paper
scene=$DPD_ROOT/experiments/phan-thien-2016/fig06-cylinder-exclusion/cylinder.cfg
case $TIER in
    quick) Ps="0.1 0.5 1.0"; tier=(--set equilibration=500 --set steps=8000); shear=(--set equilibration=300 --set steps=3000) ;;
    paper) Ps="0.1 0.2 0.3 0.4 0.5 0.6 0.7 0.8 0.9 1.0"; tier=(--set equilibration=1000 --set steps=50000)
           shear=(--set equilibration=1000 --set steps=20000) ;;
esac
# the simulations
simulations() {
dpd_run shear shear.cfg "${shear[@]}"
for P in $Ps; do   # sampled every step: the m = 0 velocities are nearly white in time
    dpd_run "P$P" "$scene" "${tier[@]}" --set "types.[0].body_force=[$P,0.0]" --set measure.every=1 \
        --set seed=$((7000 + 10#${P/./}))
done
}
analysis() {
fig06=$(upstream phan-thien-2016/fig06-cylinder-exclusion)/summary.tsv
# the analysis
emit_from shear viscosity eta_solvent
a=$("$ANALYSE" lookup "$fig06" exclusion_radius)
emit exclusion_radius "${a%%$'\t'*}" "${a##*$'\t'}"
nfluid=144; h=6.0
printf 'P\tdrag\tdrag_se\tU\tU_se\thasimoto_drag\thasimoto_drag_se\n' > "$OUT/drag.tsv"
for P in $Ps; do
    emit_from "P$P" force_on_cylinder_x "drag_P$P"
    emit_from "P$P" mean_velocity_fluid_x "velocity_P$P"
    drag=$(get "P$P" force_on_cylinder_x) U=$(get "P$P" mean_velocity_fluid_x) eta=$(get shear viscosity)
    "$ANALYSE" fig07-drag "$P" $nfluid $h "$drag" "$U" "$eta" "$a" >> "$OUT/summary.tsv" 2>> "$OUT/drag.tsv"
done
# what paper.md says in words (issue 40 item 7): the drive's effect on the fluid's velocity, and
# fig03's wall-driven eta and its Lees-Edwards eta at the channel's bulk density against this
# solvent's eta (density 4) in per cent
emit_ratio velocity_ratio_P1.0_P0.1 . velocity_P1.0 . velocity_P0.1
fig03=$(upstream phan-thien-2016/fig03-couette-profile@paper)/summary.tsv
emit_pct fig03_eta_pct_from_eta_solvent "$("$ANALYSE" lookup "$fig03" eta)" "$(get . eta_solvent)"
emit_pct fig03_eta_lees_edwards_bulk_density_pct_from_eta_solvent "$("$ANALYSE" lookup "$fig03" eta_lees_edwards_bulk_density)" "$(get . eta_solvent)"
}
experiment

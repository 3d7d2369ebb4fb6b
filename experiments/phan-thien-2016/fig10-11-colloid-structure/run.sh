#!/usr/bin/env bash
# Figs 10-11 of Phan-Thien et al. 2016: the conservative field of a 3-particle spring
# colloid (Fig. 10), the solvent RDF and the solvent distribution about the colloid
# centre (Fig. 11, eq. 48, dq = 0.01), the sizes where they reach 0.001, and the self
# diffusion of solvent and colloid from the MSD (eq. 52). No flow, m = 0, dt = 0.005.
. "$DPD_ROOT/tools/lib/exp.sh"
case $TIER in
    quick) tier=(--set equilibration=1000 --set steps=12000) ;;
    paper) tier=(--set equilibration=2000 --set steps=150000) ;;
esac
# the simulations
simulations() {
dpd_run field triangle.cfg
dpd_run colloid colloid.cfg "${tier[@]}"
}
analysis() {
# the analysis
cp "$OUT/runs/field/force_map.tsv" "$OUT/force_map.tsv"
emit_from colloid colloid_radius
emit_from colloid D D_solvent
emit_from colloid D_colloid
emit_from colloid colloid_spring_extension_rms
emit_from colloid colloid_spring_extension_max_relative
emit_from colloid mean_velocity_solvent_x
emit_from colloid mean_velocity_solvent_y
# solvent size: lower edge of the first RDF bin (dr = 0.01) where g reaches 0.001
"$ANALYSE" solvent-radius "$OUT/runs/colloid/rdf.tsv" >> "$OUT/summary.tsv"
for t in rdf msd colloid_msd colloid_around; do cp "$OUT/runs/colloid/$t.tsv" "$OUT/$t.tsv"; done
# what paper.md says in words (issue 40 item 7): the springs' rms extension over the sides' rest
# length r* = (a + H r_bar) / (a + H) = 0.2636 (README)
"$ANALYSE" div "$(get . colloid_spring_extension_rms)" 0.2636 colloid_spring_extension_rms_over_rest_length >> "$OUT/summary.tsv"
}
experiment

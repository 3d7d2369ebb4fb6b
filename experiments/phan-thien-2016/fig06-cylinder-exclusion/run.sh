#!/usr/bin/env bash
# Fig. 6 of Phan-Thien et al. 2016: the field of a 4-particle cylinder, the
# fluid density about it without flow, and the exclusion radius from g(q)
# (eq. 48, dq = 0.01, first q where g reaches 0.001).
. "$DPD_ROOT/tools/lib/exp.sh"
# run lengths (issue 37): long enough that the symmetry gate on the torque decides at its resolution,
# 1 % of the flow torque scale (paper tier; stderr 0.039 at 200000 steps, so 16 times as long) and
# 10 % (quick tier; 0.14 at 30000 steps, so 80000)
case $TIER in
    quick) tier=(--set equilibration=1000 --set steps=80000) ;;
    paper) tier=(--set equilibration=2000 --set steps=3200000) ;;
esac
simulations() {
dpd_run noflow cylinder.cfg "${tier[@]}"
}
analysis() {
for q in exclusion_radius force_on_cylinder_x force_on_cylinder_y torque_on_cylinder_z; do emit_from noflow $q; done
for t in around density_map force_map rdf; do cp "$OUT/runs/noflow/$t.tsv" "$OUT/$t.tsv"; done
}
experiment

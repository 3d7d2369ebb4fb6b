#!/usr/bin/env bash
# Viscosity of the Pan 2008 fluid by reverse Poiseuille flow, a parabola per half.
. "$DPD_ROOT/tools/lib/exp.sh"
G=0.05
case $TIER in
    quick) tier=(--set 'box=[6.0,6.0,16.0]' --set equilibration=2000 --set steps=16000 --set measure.profile.bins=32) ;;
    paper) tier=() ;;
esac
dpd_run rpf fluid-poiseuille.cfg "${tier[@]}" --set "types.[0].body_force=[$G,0.0,0.0]"
"$DPD" fit-poiseuille "$OUT/runs/rpf/profile.tsv" --force $G > "$OUT/fit.tsv"
awk -F'\t' 'NR > 1' "$OUT/fit.tsv" >> "$OUT/summary.tsv"
emit_from rpf temperature temperature
emit_from rpf rotational_temperature rotational_temperature
cp "$OUT/runs/rpf/profile.tsv" "$OUT/profile.tsv"

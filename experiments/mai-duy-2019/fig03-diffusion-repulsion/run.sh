#!/usr/bin/env bash
# D(t) of the mai-duy-2019 solvent for several repulsions (Fig. 3).
. "$DPD_ROOT/tools/lib/exp.sh"
case $TIER in
    quick) tier=(--set 'box=[8.0,8.0,8.0]' --set dt=0.01 --set equilibration=500 --set steps=3000
                 --set measure.msd.window=1000 --set measure.msd.origin_every=100) ;;
    paper) tier=() ;;
esac
k=0
for a in 3.53 6.50 9.50 18.50 500; do
    dpd_run a$a solvent-msd.cfg "${tier[@]}" --set "pairs.[0].a=$a" --set "seed=$((30190 + k))"
    emit_from a$a D "D_a$a"
    emit_from a$a D_t_ratio_late_half "D_t_flatness_a$a"
    emit_from a$a temperature "temperature_a$a"
    cp "$OUT/runs/a$a/msd.tsv" "$OUT/msd_a$a.tsv"
    k=$((k + 1))
done
emit_ratio D_ratio_a18.50_a3.53 a18.50 D a3.53 D
emit_ratio D_ratio_a500_a3.53 a500 D a3.53 D

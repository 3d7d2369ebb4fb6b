#!/usr/bin/env bash
# Fig. 8 of Phan-Thien et al. 2016: density residual (eq. 49) and mean |div u|
# of the flow past the cylinder array against the body force P, m = 0 against
# m = 1. Fields: time averages over the production run on 12 x 12 bins
# (0.5 x 0.5), the bins whose centre is within 1 of the cylinder centre left
# out (132 bins), n = 4. Each point: independent seeds, mean +- stderr.
. "$DPD_ROOT/tools/lib/exp.sh"
m0=$DPD_ROOT/experiments/phan-thien-2016/fig06-cylinder-exclusion/cylinder.cfg
m1=cylinder-m1.cfg
case $TIER in
    quick) Ps="0.1 1.0"; seeds="1 2"; tier=(--set equilibration=1000 --set steps=10000) ;;
    paper) Ps="0.1 0.2 0.3 0.4 0.5 0.6 0.7 0.8 0.9 1.0"; seeds="1 2 3"; tier=(--set equilibration=1000 --set steps=20000) ;;
esac
# the simulations: the flows, and the equation of state of the m = 1 fluid (Mach number, below)
simulations() {
for m in 0 1; do
    scene=$m0; [ $m = 1 ] && scene=$m1
    for P in $Ps; do
        for k in $seeds; do
            dpd_run "m${m}_P${P}_s$k" "$scene" "${tier[@]}" --set "types.[0].body_force=[$P,0.0]" --set measure.every=1 \
                --set 'measure.density_map.bins=[12,12]' --set seed=$((8000 + 100 * k + 10#${P/./} + 1000 * m))
        done
    done
done
for N in 137 151; do dpd_run "eos_N$N" eos-m1.cfg --set "types.[0].count=$N" --set seed=$((8500 + N)); done
}
analysis() {
# the analysis
printf 'P\tm\tresidual\tresidual_se\tdivu\tdivu_se\tU\tU_se\n' > "$OUT/fields.tsv"
for m in 0 1; do
    for P in $Ps; do
        rows=""
        for k in $seeds; do
            name="m${m}_P${P}_s$k"
            rows+="$("$ANALYSE" density-fields "$OUT/runs/$name/density_map.tsv" 6 3 3 1 4)"$'\t'"$(getv "$name" mean_velocity_fluid_x)"$'\n'
        done
        # mean and standard error over the seeds
        printf '%s' "$rows" | "$ANALYSE" fields-mean-row "$P" "$m" >> "$OUT/fields.tsv"
        # momentum balance: at m = 0 exact at every step; at m = 1 on average in the steady state
        emit_from "m${m}_P${P}_s1" force_on_cylinder_x "drag_m${m}_P$P"
        "$ANALYSE" force-balance "force_balance_m${m}_P$P" "$P" "$(get "m${m}_P${P}_s1" force_on_cylinder_x)" >> "$OUT/summary.tsv"
    done
done
# Mach number of the m = 1 runs: U / c_T with the isothermal speed of sound
# c_T = sqrt(dp/dn / m) from the pressure at n = 4 (1 -+ 5 %, runs eos_N137 and eos_N151), central difference
c2=$("$ANALYSE" eos-slope "$(get eos_N137 pressure)" "$(get eos_N151 pressure)")
"$ANALYSE" sound-speed "$c2" >> "$OUT/summary.tsv"
printf 'P\tmach\tmach_se\n' > "$OUT/mach.tsv"
"$ANALYSE" fig08-mach "$OUT/fields.tsv" "$c2" >> "$OUT/mach.tsv"
"$ANALYSE" fig08-mach-rows "$OUT/mach.tsv" >> "$OUT/summary.tsv"
# growths from P = 0.1 to P = 1.0 (first-order error propagation) and m = 1 over m = 0
"$ANALYSE" fig08-growths "$OUT/fields.tsv" >> "$OUT/summary.tsv"
# the residual and its growth by a second estimator, free of the statistical floor that the
# time-averaged fields carry (tools/analysis.py residual_floor_free: cross products of independent
# seeds, jackknife over the seeds; needs 3 seeds, the paper tier's)
if [ "$(echo $seeds | wc -w)" -ge 3 ]; then
    for m in 0 1; do
        for P in 0.1 1.0; do
            maps=(); for k in $seeds; do maps+=("$OUT/runs/m${m}_P${P}_s$k/density_map.tsv"); done
            "$ANALYSE" residual-floor-free "residual_floor_free_m${m}_P$P" 6 3 3 1 4 "${maps[@]}" >> "$OUT/summary.tsv"
        done
        emit "residual_floor_free_growth_m$m" "$("$ANALYSE" ratio "$(tsv_lookup "$OUT/summary.tsv" "residual_floor_free_m${m}_P1.0")" \
            "$(tsv_lookup "$OUT/summary.tsv" "residual_floor_free_m${m}_P0.1")")"
    done
fi
}
experiment

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
            rows+="$(num_awk -v L=6 -v cx=3 -v cy=3 -v rex=1 -v n0=4 -f fields.awk "$OUT/runs/$name/density_map.tsv")"$'\t'"$(get "$name" mean_velocity_fluid_x | cut -f1)"$'\n'
        done
        # mean and standard error over the seeds
        printf '%s' "$rows" | num_awk -F'\t' -v P="$P" -v m="$m" '
            { r[NR] = $1; d[NR] = $2; u[NR] = $4 }
            END { printf "%s\t%s", P, m
                  num_mean_se(r, NR, o); printf "\t%s", num_pair(o, "%.6g", "%.3g")
                  num_mean_se(d, NR, o); printf "\t%s", num_pair(o, "%.6g", "%.3g")
                  num_mean_se(u, NR, o); printf "\t%s\n", num_pair(o, "%.6g", "%.3g") }' \
            >> "$OUT/fields.tsv"
        # momentum balance: at m = 0 exact at every step; at m = 1 on average in the steady state
        emit_from "m${m}_P${P}_s1" force_on_cylinder_x "drag_m${m}_P$P"
        num_awk -F'\t' -v q="force_balance_m${m}_P$P" -v P="$P" -v v="$(get "m${m}_P${P}_s1" force_on_cylinder_x)" \
            'BEGIN { split(v, x, "\t"); num_div(x[1], x[2], 144 * P, o); o["v"] -= 1; print num_row(q, o) }' >> "$OUT/summary.tsv"
    done
done
# Mach number of the m = 1 runs: U / c_T with the isothermal speed of sound
# c_T = sqrt(dp/dn / m) from the pressure at n = 4 (1 -+ 5 %, runs eos_N137 and eos_N151), central difference
c2=$(num_awk -F'\t' -v lo="$(get eos_N137 pressure)" -v hi="$(get eos_N151 pressure)" 'BEGIN {
        split(lo, a, "\t"); split(hi, b, "\t"); dn = (151 - 137) / 36.0
        num_diff(b[1], b[2], a[1], a[2], o); num_div(o["v"], o["se"], dn, o); printf "%s", num_pair(o) }')
echo "$c2" | num_awk -F'\t' '{ num_sqrt($1, $2, o); printf "sound_speed_m1\t%s\n", num_pair(o, "%.6g", "%.3g") }' >> "$OUT/summary.tsv"
printf 'P\tmach\tmach_se\n' > "$OUT/mach.tsv"
num_awk -F'\t' -v c2="$c2" 'BEGIN { split(c2, x, "\t"); num_sqrt(x[1], x[2], cs) }
    NR > 1 && $2 == 1 { num_ratio($7, $8, cs["v"], cs["se"], o); printf "%s\t%s\n", $1, num_pair(o, "%.6g", "%.3g") }' \
    "$OUT/fields.tsv" >> "$OUT/mach.tsv"
awk -F'\t' 'NR > 1 && ($1 == "0.1" || $1 == "1.0") { printf "mach_m1_P%s\t%s\t%s\n", $1, $2, $3 }' "$OUT/mach.tsv" >> "$OUT/summary.tsv"
# growths from P = 0.1 to P = 1.0 (first-order error propagation) and m = 1 over m = 0
num_awk -F'\t' 'NR > 1 && ($1 == "0.1" || $1 == "1.0") { R[$2, $1] = $3; Rse[$2, $1] = $4; D[$2, $1] = $5; Dse[$2, $1] = $6 }
    function ratio(q, a, as, b, bs) { G[q] = num_ratio(a, as, b, bs, o); E[q] = o["se"]
                                      printf "%s\t%.6g\t%.3g\n", q, G[q], E[q] }
    END { for (m = 0; m <= 1; m++) {
              ratio("residual_growth_m" m, R[m, "1.0"], Rse[m, "1.0"], R[m, "0.1"], Rse[m, "0.1"])
              ratio("divu_growth_m" m, D[m, "1.0"], Dse[m, "1.0"], D[m, "0.1"], Dse[m, "0.1"]) }
          ratio("residual_growth_ratio_m1_m0", G["residual_growth_m1"], E["residual_growth_m1"], G["residual_growth_m0"], E["residual_growth_m0"])
          ratio("divu_growth_ratio_m1_m0", G["divu_growth_m1"], E["divu_growth_m1"], G["divu_growth_m0"], E["divu_growth_m0"]) }' \
    "$OUT/fields.tsv" >> "$OUT/summary.tsv"
}
experiment

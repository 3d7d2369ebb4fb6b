#!/usr/bin/env bash
# Shear-rate dependence of the spring-model suspension's relative viscosity at phi = 0.49
# (Mai-Duy et al. 2019, Figs 4-5): our fig04/fig05 shear at rate 0.1, a Peclet number two orders
# of magnitude above the paper's 0.18 (open choice, see fig04's README), and find eta_r(0.49)
# below the paper's and independent of a. This experiment lowers the rate at phi = 0.49 (the
# paper's 15^3 box, 13^3 colloids, dt = 0.005, the same run length: 10 + 50 time units) for
# a = 6.50 and 3.53, with the solvent sheared alike (eta_r = eta_susp / eta_solvent, eq. 11 for both).
# Paper tier: rate 0.1 is fig04's and fig05's own paper-tier runs (reuse_run), not new ones.
. "$DPD_ROOT/tools/lib/exp.sh"
needs paper mai-duy-2019/fig04-relative-viscosity-a353
needs paper mai-duy-2019/fig05-relative-viscosity-a650
FIG04=$DPD_ROOT/experiments/mai-duy-2019/fig04-relative-viscosity-a353
case $TIER in
    # quick: fig04's quick box for phi = 0.49 (13^3 colloids' lattice spacing, 7^3 colloids), short runs
    quick) PAIR=13:7; LSOLV=8; CASES="6.50:0.1 6.50:0.03"; PROD=6; run=(--set equilibration=400 --set steps=1200) ;;
    paper) PAIR=13:13; LSOLV=15; CASES="6.50:0.01 3.53:0.01 6.50:0.03"; PROD=50; run=() ;;
esac
lattice_pair "$PAIR" 2
# the simulations: per case a:rate (repulsion a between every pair), the suspension and the solvent
case_simulations() {
    local a=${1%:*} rate=${1#*:} n=$2
    dpd_run susp_a${a}_rate$rate "$FIG04/suspension-shear.cfg" "${run[@]}" "${geo[@]}" \
        --set "pairs.[0].a=$a" --set "pairs.[1].a=$a" --set "pairs.[2].a=$a" --set "shear_rate=$rate" \
        --set "colloids.per_axis=$kq" --set "seed=$((40600 + 2 * n))"
    dpd_run solvent_a${a}_rate$rate "$FIG04/solvent-shear.cfg" "${run[@]}" --set "box=[$LSOLV,$LSOLV,$LSOLV]" \
        --set "pairs.[0].a=$a" --set "shear_rate=$rate" --set "seed=$((40601 + 2 * n))"
}
simulations() {
cases=($CASES)
for ((j = 0; j < ${#cases[@]}; j++)); do case_simulations "${cases[j]}" $j; done
if [ "$TIER" = paper ]; then
    reuse_run susp_a6.50_rate0.1 mai-duy-2019/fig05-relative-viscosity-a650 paper susp_$tag
    reuse_run solvent_a6.50_rate0.1 mai-duy-2019/fig05-relative-viscosity-a650 paper solvent
    reuse_run susp_a3.53_rate0.1 mai-duy-2019/fig04-relative-viscosity-a353 paper susp_$tag
    reuse_run solvent_a3.53_rate0.1 mai-duy-2019/fig04-relative-viscosity-a353 paper solvent
    cases+=(6.50:0.1 3.53:0.1)
fi
}
analysis() {
# the analysis
# strain: rate x the production time (the strain the averaged stress was sampled over)
printf 'a\trate\teta_r\tse\teta_susp\tse\teta_solvent\tse\tstrain\n' > "$OUT/eta_r.tsv"
for c in $(printf '%s\n' "${cases[@]}" | LC_ALL=C sort -t: -k1,1 -k2,2g); do
    a=${c%:*} rate=${c#*:} s=a${c%:*}_rate${c#*:}
    emit_ratio eta_r_$s susp_$s viscosity solvent_$s viscosity
    emit_from susp_$s temperature temperature_susp_$s
    emit_from solvent_$s temperature temperature_solvent_$s
    printf '%s\t%s\t%s\t%s\t%s\t%.4g\n' "$a" "$rate" "$(get . eta_r_$s)" "$(get susp_$s viscosity)" \
        "$(get solvent_$s viscosity)" "$("$ANALYSE" times "$rate" "$PROD")" >> "$OUT/eta_r.tsv"
done
# the hypotheses (bands.tsv): eta_r rises as the rate falls; at a lower rate, a = 6.50 above a = 3.53
if [ "$TIER" = paper ]; then
    emit_diff eta_r_rise_a6.50_rate0.01_minus_0.1 . eta_r_a6.50_rate0.01 . eta_r_a6.50_rate0.1
    emit_diff eta_r_rise_a3.53_rate0.01_minus_0.1 . eta_r_a3.53_rate0.01 . eta_r_a3.53_rate0.1
    emit_diff eta_r_a6.50_minus_a3.53_rate0.01 . eta_r_a6.50_rate0.01 . eta_r_a3.53_rate0.01
    emit_diff eta_r_a6.50_minus_a3.53_rate0.1 . eta_r_a6.50_rate0.1 . eta_r_a3.53_rate0.1
else
    emit_diff eta_r_rise_a6.50_rate0.03_minus_0.1 . eta_r_a6.50_rate0.03 . eta_r_a6.50_rate0.1
fi
}
experiment

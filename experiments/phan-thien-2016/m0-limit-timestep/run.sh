#!/usr/bin/env bash
# Two checks of the m = 0 dynamics in the Couette channel (issue 3):
#  1. the m -> 0 limit: ordinary DPD (velocity Verlet) at m = 0.3, 0.1, 0.03 with dt = m / 30
#     (a tenth of the dissipative relaxation time m / (gamma sum_j w_D), about m / 30 here)
#     against the m = 0 solve: bulk shear rate of the time-averaged profile;
#  2. the time step of the m = 0 run: dt = 0.005 ... 0.1 at a fixed simulated time; "sound" =
#     viscosity within 10 % and bulk density within 10 % of the dt = 0.005 run.
. "$DPD_ROOT/tools/lib/exp.sh"
case $TIER in
    quick) T=4 TEQ=1 masses="0.3 0.1" dts="0.005 0.01 0.05" ;;
    paper) T=10 TEQ=2 masses="0.3 0.1 0.03" dts="0.005 0.01 0.02 0.05 0.1" ;;
esac
# fig03's committed m = 0 shear rate, the limit the inertial runs approach (paper.md)
needs any phan-thien-2016/fig03-couette-profile@paper
od=../fig03-couette-profile/couette.cfg
nsteps() { "$ANALYSE" steps-for $1 $2; }
# analyse NAME PREFIX: shear rate (blocks' bulk slopes), viscosity from the wall force, bulk density deviation
analyse() {
    local p=$OUT/runs/$1/profile.tsv g gse tau tause eta etase
    read -r g gse tau tause eta etase < <(couette_viscosity $1 10 2:10)   # tools/lib/exp.sh
    emit "shear_rate_$2" "$g" "$gse"
    emit "eta_$2" "$eta" "$etase"
    emit "density_bulk_max_rel_dev_$2" $(max_rel_dev "$p" 2:10)
    emit_from $1 temperature "temperature_$2"
}
mdt() { "$ANALYSE" quotient6 $1 30; }   # the time step of the inertial run at mass m
# the simulations: 1. the m = 0 solve and the inertial runs at decreasing m; 2. the m = 0 time steps
simulations() {
dpd_run m0 $od --set measure.profile.per_block=true --set dt=0.01 --set equilibration=$(nsteps $TEQ 0.01) --set steps=$(nsteps $T 0.01)
for m in $masses; do
    dt=$(mdt $m)
    every=$("$ANALYSE" sample-every 0.05 $dt)
    dpd_run m$m inertial.cfg --set measure.profile.per_block=true --set dt=$dt --set equilibration=$(nsteps $TEQ $dt) --set steps=$(nsteps $T $dt) \
        --set measure.every=$every $(for t in 0 1 2 3 4; do printf -- '--set types.[%d].mass=%s ' $t $m; done)
done
for dt in $dts; do
    dpd_run dt$dt $od --set measure.profile.per_block=true --set dt=$dt --set equilibration=$(nsteps $TEQ $dt) --set steps=$(nsteps $T $dt) \
        --set measure.every=$("$ANALYSE" sample-every 0.1 $dt) --set measure.blocks=10
done
}
analysis() {
# 1. m -> 0
analyse m0 m0
printf 'm\tdt\tshear_rate\tshear_rate_se\ttemperature\n' > "$OUT/m-limit.tsv"
for m in $masses; do
    dt=$(mdt $m)
    analyse m$m m$m
    printf '%s\t%s\t%s\t%s\n' $m $dt "$("$ANALYSE" lookup "$OUT/summary.tsv" shear_rate_m$m)" \
        "$(getv m$m temperature)" >> "$OUT/m-limit.tsv"
done
mmin=${masses##* }
"$ANALYSE" summary-diff "$OUT/summary.tsv" shear_rate_m$mmin shear_rate_m0 shear_rate_m_smallest_minus_m0 > "$OUT/.rows"
cat "$OUT/.rows" >> "$OUT/summary.tsv"; rm "$OUT/.rows"
# 2. time step of the m = 0 run
printf 'dt\tshear_rate\tshear_rate_se\teta\teta_se\tdensity_dev\tsound\n' > "$OUT/dt-scan.tsv"
for dt in $dts; do analyse dt$dt dt$dt; done
"$ANALYSE" dt-scan "$OUT/summary.tsv" "$dts" "$OUT/dt-scan.tsv" > "$OUT/.rows"
cat "$OUT/.rows" >> "$OUT/summary.tsv"; rm "$OUT/.rows"
# what paper.md says in words (issue 40 item 7): the largest sound m = 0 step over the inertial
# step 0.01; at the paper tier, the smallest mass's shear rate against fig03's m = 0 one and the
# viscosity at dt = 0.1 against dt = 0.005 (in standard errors and in per cent)
"$ANALYSE" div "$(get . dt_max_sound)" 0.01 dt_max_sound_over_0.01 >> "$OUT/summary.tsv"
if [ "$TIER" = paper ]; then
    fig03=$(upstream phan-thien-2016/fig03-couette-profile@paper)/summary.tsv
    "$ANALYSE" sigmas shear_rate_m0.03_sigmas_from_m0 "$(get . shear_rate_m0.03)" "$("$ANALYSE" lookup "$fig03" shear_rate)" >> "$OUT/summary.tsv"
    emit_pct shear_rate_m0.03_pct_from_m0 "$(get . shear_rate_m0.03)" "$("$ANALYSE" lookup "$fig03" shear_rate)"
    "$ANALYSE" sigmas eta_dt0.1_sigmas_from_dt0.005 "$(get . eta_dt0.1)" "$(get . eta_dt0.005)" >> "$OUT/summary.tsv"
    emit_pct eta_dt0.1_pct_from_dt0.005 "$(get . eta_dt0.1)" "$(get . eta_dt0.005)"
fi
}
experiment

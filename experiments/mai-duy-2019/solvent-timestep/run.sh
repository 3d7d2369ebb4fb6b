#!/usr/bin/env bash
# How large a step the stiff mai-duy-2019 solvent (dissipative relaxation time
# m / (gamma sum_j w_D) ~ 0.005) tolerates with the Groot-Warren velocity Verlet
# (lambda = 0.5): kinetic temperature and Lees-Edwards viscosity against dt, at a
# fixed physical run length. Sets the step of the tiers of the B experiments.
. "$DPD_ROOT/tools/lib/exp.sh"
case $TIER in
    quick) DTS="0.005 0.01 0.015 0.02"; T_RUN=10; T_EQ=2; box=(--set 'box=[8.0,8.0,8.0]') ;;
    paper) DTS="0.0025 0.005 0.0075 0.01 0.0125 0.015 0.0175 0.02"; T_RUN=20; T_EQ=2; box=() ;;
esac
printf 'dt\tT\tT_se\teta\teta_se\tcpu_seconds\n' > "$OUT/dt-scan.tsv"
# run_dt DT K: the run at step DT (seed 40190 + K), the same simulated time at every step
run_dt() {
    local dt=$1 steps eq every
    steps=$("$ANALYSE" steps-for $T_RUN $dt)
    eq=$("$ANALYSE" steps-for $T_EQ $dt)
    every=$("$ANALYSE" sample-every 0.05 $dt)   # sample every 0.05 time units
    dpd_run dt$dt solvent-shear.cfg "${box[@]}" --set dt=$dt --set steps=$steps --set equilibration=$eq \
        --set measure.every=$every --set "seed=$((40190 + $2))"
}
# the simulations (an unstable one is an outcome, not a failure: the analysis records a gap)
declare -A outcome=()   # dt -> the run's status (dpd_run: 0, or its recorded failure)
simulations() {
k=0
for dt in $DTS; do st=0; run_dt $dt $k || st=$?; outcome[$dt]=$st; k=$((k + 1)); done
}
analysis() {
# the analysis (each run's recorded outcome, from the simulations; nothing reruns)
best=0 k=0
for dt in $DTS; do
    if [ "${outcome[$dt]}" = 0 ]; then
        emit_from dt$dt temperature "T_dt$dt"
        emit_from dt$dt viscosity "eta_dt$dt"
        T=$(get dt$dt temperature) eta=$(get dt$dt viscosity) cpu=$(getv dt$dt cpu_seconds)
        printf '%s\t%s\t%s\t%s\n' "$dt" "$T" "$eta" "$cpu" >> "$OUT/dt-scan.tsv"
        # largest dt of the scan whose temperature is within 1 % of kBT = 1 (3 stderr allowed)
        best=$("$ANALYSE" within-1pct-best "$T" $dt $best)
    else
        echo "dt = $dt: unstable (dpd exited non-zero); recorded as a gap" >&2
        printf '%s\tnan\tnan\tnan\tnan\tnan\n' "$dt" >> "$OUT/dt-scan.tsv"
    fi
    k=$((k + 1))
done
emit dt_max_T1pct "$best" nan
case $TIER in
    quick) emit_ratio eta_ratio_dt0.01_dt0.005 dt0.01 viscosity dt0.005 viscosity ;;
    paper) emit_ratio eta_ratio_dt0.005_dt0.0025 dt0.005 viscosity dt0.0025 viscosity
           emit_ratio eta_ratio_dt0.01_dt0.0025 dt0.01 viscosity dt0.0025 viscosity ;;
esac
# what paper.md says in words (issue 40 item 7): the limit over the paper tier's step 0.005 (the limit
# is a rung of the ladder: no error)
emit dt_max_T1pct_over_0.005 "$("$ANALYSE" quotient "$best" 0.005)" nan
}
experiment

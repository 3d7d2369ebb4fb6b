#!/usr/bin/env bash
# Centre of mass of the m = 0 fluid in the Couette channel under Scheme 1 and
# the published Scheme 2 (Phan-Thien et al. 2016, section 3 and eqs 41-46):
# dt = 0.005, every step sampled; independent seeds give the error bars.
. "$DPD_ROOT/tools/lib/exp.sh"
case $TIER in
    quick) tier=(--set equilibration=20 --set steps=150); seeds=(1 2) ;;
    # paper: seeds 1-3, then five more (2026-12-06: a second look, README "Five more seeds"), decided
    # after the first three left com_x_amplitude_scheme1 UNRESOLVED (1.26 +- 0.40; 1.46 times the
    # seeds decide it) and before the new seeds ran. Seed 4's random start blows up at step 2 of its
    # equilibration under both schemes (a particle with three nearly collinear neighbours; README;
    # tests/blowup.sh m0-collinear): it has no production run, and seed 9 takes its place
    paper) tier=(); seeds=(1 2 3 5 6 7 8 9) ;;
esac
# amp NAME AXIS: largest |value| of the run's centre-of-mass velocity (v) or position
amp() { local lo hi; lo=$(getv "$1" "com_${2}_min"); hi=$(getv "$1" "com_${2}_max")
        "$ANALYSE" abs-max "$lo" "$hi" | tr -d '\n'; }
# emit_list AS VALUES...: mean and standard error over independent runs
emit_list() { local q=$1; shift
    "$ANALYSE" mean-list "$q" "$*" >> "$OUT/summary.tsv"; }
# the simulations
simulations() {
for solver in scheme1 scheme2_paper; do
    for seed in "${seeds[@]}"; do
        dpd_run "${solver}_s$seed" com.cfg "${tier[@]}" --set seed=$seed --set "overdamped.solver=\"$solver\""
    done
done
if [ "$TIER" = paper ]; then
    # the published Scheme 2's velocity sum is a solver-tolerance effect: one run at 1e-10
    dpd_run scheme2_tol1e-10 com.cfg --set seed=1 --set 'overdamped.solver="scheme2_paper"' --set overdamped.tolerance=1e-10
fi
}
analysis() {
# the analysis
for solver in scheme1 scheme2_paper; do
    short=${solver%_paper}
    runs=()
    for seed in "${seeds[@]}"; do runs+=("${solver}_s$seed"); done
    for q in vx vy x y; do
        vals=""; for r in "${runs[@]}"; do vals="$vals $(amp "$r" "$q")"; done
        emit_list "com_${q}_amplitude_$short" $vals
    done
    emit_mean "com_x_min_$short" com_x_min "${runs[@]}"
    emit_mean "com_x_max_$short" com_x_max "${runs[@]}"
    emit_mean "com_speed_max_$short" com_speed_max "${runs[@]}"
    emit_mean "com_displacement_max_$short" com_displacement_max "${runs[@]}"
    emit_mean "velocity_sum_max_$short" velocity_sum_max "${runs[@]}"
    emit_mean "iterations_$short" solver_iterations "${runs[@]}"
    cp "$OUT/runs/${runs[0]}/com.tsv" "$OUT/com_$short.tsv"
done
emit_ratio com_speed_ratio_scheme1_scheme2 scheme1_s1 com_speed_max scheme2_paper_s1 com_speed_max
sed -i '/^com_speed_ratio_scheme1_scheme2\t/s/\t[^\t]*$/\t0/' "$OUT/summary.tsv"   # extremes of one run each: no error
if [ "$TIER" = paper ]; then
    emit_from scheme2_tol1e-10 velocity_sum_max velocity_sum_max_scheme2_tol1e-10
    emit_from scheme2_tol1e-10 com_displacement_max com_displacement_max_scheme2_tol1e-10
fi
}
experiment

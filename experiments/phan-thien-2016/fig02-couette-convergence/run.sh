#!/usr/bin/env bash
# Picard iterations per step of the m = 0 Couette channel (Phan-Thien et al. 2016,
# Fig. 2 and section 4.1): Scheme 1, Scheme 2 as published, the consistent Scheme 2
# and PCG, each with the paper's rule (eq. 27, tolerance 1e-7), with the true
# error of every step against a PCG solve to a 1e-12 residual.
. "$DPD_ROOT/tools/lib/exp.sh"
case $TIER in
    quick) tier=(--set equilibration=20 --set steps=60) ;;
    paper) tier=() ;;
esac
solvers="scheme1 scheme2_paper scheme2_consistent pcg"
# the simulations
simulations() {
for solver in $solvers; do
    dpd_run $solver couette.cfg "${tier[@]}" --set "overdamped.solver=\"$solver\""
done
}
analysis() {
# the analysis
for solver in $solvers; do
    emit_from $solver solver_iterations "iterations_$solver"
    emit_from $solver solver_true_rel_error "true_error_$solver"
    emit_from $solver solver_seconds_per_step "seconds_per_step_$solver"
    cp "$OUT/runs/$solver/solver.tsv" "$OUT/solver_$solver.tsv"
done
# the paper names them Scheme 1 and Scheme 2
sed -i 's/^iterations_scheme2_paper\t/iterations_scheme2\t/; s/^true_error_scheme2_paper\t/true_error_scheme2\t/' "$OUT/summary.tsv"
emit_ratio cpu_ratio_scheme1_scheme2 scheme1 solver_seconds_per_step scheme2_paper solver_seconds_per_step
emit_ratio iteration_ratio_scheme1_pcg scheme1 solver_iterations pcg solver_iterations
cp "$OUT/runs/pcg/profile.tsv" "$OUT/profile_pcg.tsv"
}
experiment

#!/usr/bin/env bash
# The solvers of the m = 0 Couette channel (Fig. 2 set-up) compared at equal
# true relative error rather than at equal stopping rule (issue 3): each solver
# runs a ladder of eq. 27 tolerances; its iterations and CPU seconds per step
# are interpolated (linearly in log error) to the common true error E*. The
# published Scheme 2's error is measured against its own fixed point (it does
# not converge to A v = f; see fig02-couette-convergence), the others' against
# a tight PCG solve of A v = f.
. "$DPD_ROOT/tools/lib/exp.sh"
ESTAR=1e-6
scene=../fig02-couette-convergence/couette.cfg
case $TIER in
    quick) len=(--set equilibration=10 --set steps=10 --set measure.blocks=5) ;;
    paper) len=(--set equilibration=100 --set steps=100 --set measure.blocks=20) ;;
esac
declare -A ladder=([scheme1]="1e-7 1e-8 1e-9" [scheme2_paper]="1e-6 1e-7 1e-8"
                   [scheme2_consistent]="1e-6 1e-7 1e-8" [pcg]="1e-5 1e-6 1e-7 1e-8" [pcg_2level]="1e-5 1e-6 1e-7 1e-8")
solvers="scheme1 scheme2_paper scheme2_consistent pcg pcg_2level"
# the simulations
simulations() {
for solver in $solvers; do
    for tol in ${ladder[$solver]}; do
        dpd_run ${solver}_$tol $scene "${len[@]}" --set "overdamped.solver=\"$solver\"" --set overdamped.tolerance=$tol \
            --set overdamped.reference_own_fixed_point=true
    done
done
}
analysis() {
# the analysis
printf 'solver\ttolerance\titerations\titerations_se\ttrue_error\tcpu_seconds\tcpu_seconds_se\n' > "$OUT/ladder.tsv"
for solver in $solvers; do
    for tol in ${ladder[$solver]}; do
        name=${solver}_$tol
        printf '%s\t%s\t%s\t%s\t%s\n' $solver $tol "$(get $name solver_iterations)" "$(get $name solver_true_rel_error | cut -f1)" \
            "$(get $name solver_cpu_seconds_per_step)" >> "$OUT/ladder.tsv"
    done
done
# interpolate each solver to E*; then the ratios of issue 3
num_awk -F'\t' -v E="$ESTAR" 'NR>1 {s=$1; n[s]++; k=n[s]; le[s,k]=log($5); it[s,k]=$3; its[s,k]=$4; cs[s,k]=$6; css[s,k]=$7}
  function interp(s, a, as,   k, j, i1, i2, w) {   # bracket log E* (or the nearest two when outside the ladder)
      i1 = 0; for (k = 1; k <= n[s]; k++) for (j = 1; j <= n[s]; j++) if (k != j && le[s,k] >= log(E) && le[s,j] <= log(E) && (i1 == 0 || le[s,k]-le[s,j] < le[s,i1]-le[s,i2])) { i1 = k; i2 = j }
      if (i1 == 0) { extrap[s] = 1; i1 = 1; i2 = 2; for (k = 1; k <= n[s]; k++) if ((le[s,k]-log(E))^2 < (le[s,i1]-log(E))^2) i1 = k
                     for (k = 1; k <= n[s]; k++) if (k != i1 && (i2 == i1 || (le[s,k]-log(E))^2 < (le[s,i2]-log(E))^2)) i2 = k }
      w = (le[s,i1] == le[s,i2]) ? 0.5 : (log(E) - le[s,i2]) / (le[s,i1] - le[s,i2])
      V = num_lin2(w, a[s,i1], as[s,i1], 1 - w, a[s,i2], as[s,i2], o); VS = o["se"]
  }
  function ratio(q, v, vs, a, b) { num_ratio(v[a], vs[a], v[b], vs[b], o); printf "%s\t%s\n", q, num_pair(o, "%.6g", "%.4g") }
  END {
      split("scheme1 scheme2_paper scheme2_consistent pcg pcg_2level", S, " ")
      bi = bt = ""
      for (q = 1; q <= 5; q++) { s = S[q]
          interp(s, it, its); I[s] = V; IS[s] = VS
          interp(s, cs, css); C[s] = V; CS[s] = VS
          printf "iterations_at_Estar_%s\t%.6g\t%.4g\n", s, I[s], IS[s]
          printf "cpu_seconds_at_Estar_%s\t%.6g\t%.4g\n", s, C[s], CS[s]
          if (extrap[s]) printf "extrapolated_%s\t1\t0\n", s
          if (bi == "" || I[s] < I[bi]) bi = s
          if (bt == "" || C[s] < C[bt]) bt = s }
      ratio("iteration_ratio_scheme2_best", I, IS, "scheme2_paper", bi)
      ratio("time_ratio_scheme1_best", C, CS, "scheme1", bt)
      ratio("iteration_ratio_scheme1_scheme2", I, IS, "scheme1", "scheme2_paper")
      ratio("cpu_ratio_scheme1_scheme2_at_Estar", C, CS, "scheme1", "scheme2_paper")
      printf "best_iterations_is_pcg_2level\t%d\t0\n", bi == "pcg_2level"
      printf "best_time_is_pcg_2level\t%d\t0\n", bt == "pcg_2level"
  }' "$OUT/ladder.tsv" >> "$OUT/summary.tsv"
}
experiment

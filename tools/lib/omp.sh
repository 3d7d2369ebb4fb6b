# tools/lib/omp.sh - the OpenMP wait policy of every simulation the harness runs (sourced by
# tools/run-simulation, tools/run-experiment and bench/bench.sh, which measures it).
# An idle thread spins GOMP_SPINCOUNT = 3000 iterations (about 0.1 ms) and then sleeps: long enough
# to span the short serial gaps between a step's parallel loops on a quiet machine, short enough
# not to hold a core its partner needs on a busy one. Measured on this 2-core machine (2026-12-03,
# standard DPD, 2 threads over 1): quiet, 10125 particles: 1.82-1.89 (sleeping at once,
# OMP_WAIT_POLICY=PASSIVE: 1.31-1.36; libgomp's default spin of 300000: 1.87-1.91); under a load of
# 6 busy processes, 3000 particles: 0.98-1.19 (PASSIVE 0.87-0.96, the default spin 0.34: the
# collapse). make bench prints these ratios. A user's OMP_WAIT_POLICY or GOMP_SPINCOUNT wins.
# The results do not depend on it (tests/test_threads.c).
harness_omp() {
    if [ -z "${OMP_WAIT_POLICY:-}" ] && [ -z "${GOMP_SPINCOUNT:-}" ]; then export GOMP_SPINCOUNT=3000; fi
}

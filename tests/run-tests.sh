#!/bin/bash
# run-tests.sh BIN... - run cmocka test binaries and the scripts tests/scene_errors.sh,
# tests/checkpoint.sh, tests/io_errors.sh, tests/blowup.sh, tests/bare.sh (BARE: the bare build), tests/fit_line.sh, tests/tcaf_fit.sh,
# tests/analysis.py (the analysis layer, tools/analysis.py), tests/precision.sh (issue 38: the precision each claim needs),
# tests/claim_groups.sh (claims.tsv: every claim in one group), tests/bands_diff.sh (tools/bands-diff)
# tests/library_exits.sh and tests/h5md.sh (MDAnalysis reads the trajectories; skipped, saying so, without it),
# add up their checks, print "N passed, M failed" (", K skipped" when a suite could not run some
# of its checks and said so: "N passed, M failed, K skipped"), exit 1 if M > 0.
# TEST_SCRIPTS replaces the list of scripts (tests/skips.sh tests this summing).
# A binary that dies before cmocka's summary (crash, sanitizer abort) counts
# its unfinished tests as failed (at least one).
set -u
cd "$(dirname "$0")/.."
if [ "${SANITIZE:-}" = 1 ]; then
    export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=0:halt_on_error=1}"
    export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
    # libconfig 1.5's own scanner leak on some syntax errors (see the file)
    export LSAN_OPTIONS="${LSAN_OPTIONS:-suppressions=$PWD/tests/lsan.supp:print_suppressions=0}"
fi
# other jobs may share the 2 cores: idle OpenMP threads sleep instead of spinning
export OMP_WAIT_POLICY="${OMP_WAIT_POLICY:-PASSIVE}"
pass=0 fail=0 skip=0
t_start=$(date +%s.%N)
for bin in "$@"; do
    name=$(basename "$bin")
    log=$(mktemp)
    t0=$(date +%s.%N)
    "$bin" >"$log" 2>&1
    rc=$?
    t1=$(date +%s.%N)
    cat "$log"
    total=$(sed -n 's/.*Running \([0-9]*\) test(s).*/\1/p' "$log" | head -1)
    p=$(sed -n 's/^\[  PASSED  \] \([0-9]*\) test(s)\..*/\1/p' "$log" | tail -1)
    f=$(sed -n 's/^\[  FAILED  \] \([0-9]*\) test(s), listed below.*/\1/p' "$log" | tail -1)
    p=${p:-0}; f=${f:-0}
    if [ $((p + f)) -eq 0 ] || { [ -n "$total" ] && [ $((p + f)) -lt "$total" ]; }; then
        # no summary: the binary died
        ok=$(grep -c '^\[       OK \]' "$log")
        p=$ok
        f=$(( ${total:-1} - ok )); [ "$f" -lt 1 ] && f=1
        echo "$name: exited with status $rc before finishing" >&2
    elif [ $rc -ne 0 ] && [ "$f" -eq 0 ]; then
        f=1; echo "$name: exit status $rc although every test passed" >&2
    fi
    printf '%s: %d passed, %d failed (%.1f s)\n' "$name" "$p" "$f" "$(echo "$t1 - $t0" | bc)"
    pass=$((pass + p)); fail=$((fail + f))
    rm -f "$log"
done
scripts=${TEST_SCRIPTS:-tests/scene_errors.sh tests/checkpoint.sh tests/io_errors.sh tests/blowup.sh tests/bare.sh tests/fit_line.sh tests/tcaf_fit.sh tests/analysis.py tests/precision.sh tests/claim_groups.sh tests/bands_diff.sh tests/library_exits.sh tests/layers.sh tests/h5md.sh tests/skips.sh}
for script in $scripts; do
name=$(basename "$script")
log=$(mktemp)
t0=$(date +%s.%N)
DPD="${DPD:-bin/dpd}" BARE="${BARE:-build/dpd-bare}" "$script" >"$log" 2>&1
rc=$?
t1=$(date +%s.%N)
cat "$log"
line=$(grep -E '^[0-9]+ passed, [0-9]+ failed(, [0-9]+ skipped)?$' "$log" | tail -1)
s=0
if [[ $line =~ ^([0-9]+)\ passed,\ ([0-9]+)\ failed(,\ ([0-9]+)\ skipped)?$ ]]; then
    p=${BASH_REMATCH[1]} f=${BASH_REMATCH[2]} s=${BASH_REMATCH[4]:-0}
else
    p=0; f=1; echo "$name: no summary (status $rc)" >&2
fi
[ $rc -ne 0 ] && [ "$f" -eq 0 ] && f=1
printf '%s: %d passed, %d failed%s (%.1f s)\n' "$name" "$p" "$f" "$([ "$s" -gt 0 ] && echo ", $s skipped")" "$(echo "$t1 - $t0" | bc)"
pass=$((pass + p)); fail=$((fail + f)); skip=$((skip + s))
rm -f "$log"
done
printf 'all tests: %.1f s wall\n' "$(echo "$(date +%s.%N) - $t_start" | bc)"
echo "$pass passed, $fail failed$([ "$skip" -gt 0 ] && echo ", $skip skipped")"
[ "$fail" -eq 0 ]

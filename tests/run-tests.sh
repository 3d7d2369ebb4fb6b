#!/bin/bash
# run-tests.sh - run the test suites and add up their checks.
#
#   run-tests.sh --one SUITE LOG   run one suite (a cmocka binary tests/test_*, or a script) and write
#                                  its output to LOG, ending with its counts; always exits 0 (the
#                                  verdict is --sum's). make test runs one per suite, two at a time
#                                  under make -j2 (tests/tests.mk), so that the suites share the cores.
#   run-tests.sh --sum LOG...      print each log in the order given, a "NAME: N passed, M failed (T s)"
#                                  line per suite, the total "N passed, M failed" (", K skipped" when a
#                                  suite could not run some of its checks and said so), exit 1 if M > 0
#                                  or a log is missing (a suite that never ran counts as one failure).
#   run-tests.sh SUITE...          the suites and then those of TEST_SCRIPTS, one after another, and
#                                  their sum (tests/skips.sh tests the summing this way).
# The list of suites make test runs is tests/tests.mk's.
#
# A script ends with "N passed, M failed[, K skipped]". A binary that dies before cmocka's summary
# (crash, sanitizer abort) counts its unfinished tests as failed (at least one); a nonzero exit
# with nothing failed counts one failure.
set -u
cd "$(dirname "$0")/.."
if [ "${SANITIZE:-}" = 1 ]; then
    export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=0:halt_on_error=1}"
    export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
    # libconfig 1.5's own scanner leak on some syntax errors (see the file)
    export LSAN_OPTIONS="${LSAN_OPTIONS:-suppressions=$PWD/tests/lsan.supp:print_suppressions=0}"
fi
# other jobs share the 2 cores: idle OpenMP threads sleep instead of spinning
export OMP_WAIT_POLICY="${OMP_WAIT_POLICY:-PASSIVE}"

# counts of a cmocka binary's log: "P F"
cmocka_counts() {
    local log=$1 rc=$2 total p f ok
    total=$(sed -n 's/.*Running \([0-9]*\) test(s).*/\1/p' "$log" | head -1)
    p=$(sed -n 's/^\[  PASSED  \] \([0-9]*\) test(s)\..*/\1/p' "$log" | tail -1)
    f=$(sed -n 's/^\[  FAILED  \] \([0-9]*\) test(s), listed below.*/\1/p' "$log" | tail -1)
    p=${p:-0}; f=${f:-0}
    if [ $((p + f)) -eq 0 ] || { [ -n "$total" ] && [ $((p + f)) -lt "$total" ]; }; then
        ok=$(grep -c '^\[       OK \]' "$log")      # no summary: the binary died
        p=$ok; f=$(( ${total:-1} - ok )); [ "$f" -lt 1 ] && f=1
        echo "exited with status $rc before finishing" >> "$log"
    elif [ "$rc" -ne 0 ] && [ "$f" -eq 0 ]; then
        f=1; echo "exit status $rc although every test passed" >> "$log"
    fi
    echo "$p $f 0"
}
# counts of a script's log: "P F S"
script_counts() {
    local log=$1 rc=$2 line p f s=0
    line=$(grep -E '^[0-9]+ passed, [0-9]+ failed(, [0-9]+ skipped)?$' "$log" | tail -1)
    if [[ $line =~ ^([0-9]+)\ passed,\ ([0-9]+)\ failed(,\ ([0-9]+)\ skipped)?$ ]]; then
        p=${BASH_REMATCH[1]} f=${BASH_REMATCH[2]} s=${BASH_REMATCH[4]:-0}
    else
        p=0; f=1; echo "no summary (status $rc)" >> "$log"
    fi
    [ "$rc" -ne 0 ] && [ "$f" -eq 0 ] && f=1
    echo "$p $f $s"
}
# run_one SUITE LOG: the output, then a last line "suite-counts NAME P F S SECONDS"
run_one() {
    local suite=$1 log=$2 name rc t0 t1 counts
    name=$(basename "$suite")
    rm -f "$log"
    mkdir -p "$(dirname "$log")"
    t0=$(date +%s.%N)
    case $name in
        test_*) "$suite" > "$log.tmp" 2>&1 ;;
        *) DPD="${DPD:-bin/dpd}" BARE="${BARE:-build/dpd-bare}" "$suite" > "$log.tmp" 2>&1 ;;
    esac
    rc=$?
    t1=$(date +%s.%N)
    case $name in test_*) counts=$(cmocka_counts "$log.tmp" $rc) ;; *) counts=$(script_counts "$log.tmp" $rc) ;; esac
    echo "suite-counts $name $counts $(echo "$t1 - $t0" | bc)" >> "$log.tmp"
    mv "$log.tmp" "$log"
}
# sum LOG...
sum() {
    local pass=0 fail=0 skip=0 secs=0 log name p f s t
    for log in "$@"; do
        if [ ! -s "$log" ] || ! tail -1 "$log" | grep -q '^suite-counts '; then
            echo "$(basename "$log" .log): did not run (no $log)" >&2
            fail=$((fail + 1)); continue
        fi
        sed '$d' "$log"
        read -r _ name p f s t < <(tail -1 "$log")
        printf '%s: %d passed, %d failed%s (%.1f s)\n' "$name" "$p" "$f" "$([ "$s" -gt 0 ] && echo ", $s skipped")" "$t"
        pass=$((pass + p)); fail=$((fail + f)); skip=$((skip + s)); secs=$(echo "$secs + $t" | bc)
    done
    printf 'all tests: %d suites, %.1f s of suite time\n' $# "$secs"
    echo "$pass passed, $fail failed$([ "$skip" -gt 0 ] && echo ", $skip skipped")"
    [ "$fail" -eq 0 ]
}

case ${1:-} in
    --one) [ $# -eq 3 ] || { echo "usage: run-tests.sh --one SUITE LOG" >&2; exit 2; }
           run_one "$2" "$3"; exit 0 ;;
    --sum) shift; sum "$@"; exit ;;
esac
logs=$(mktemp -d)
trap 'rm -rf "$logs"' EXIT
list=()
for suite in "$@" ${TEST_SCRIPTS:-}; do
    run_one "$suite" "$logs/${#list[@]}.log"
    list+=("$logs/${#list[@]}.log")
done
sum "${list[@]}"

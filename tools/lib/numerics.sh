# shellcheck shell=bash
# tools/lib/numerics.sh - sourced (by tools/lib/exp.sh, the tests): num_awk, awk with the
# statistics library tools/lib/numerics.awk loaded before the program.
NUMERICS_AWK=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd -P)/numerics.awk

# NUM_AWK: the awk to run (default awk; tests/numerics.sh runs again under each other awk found)
# num_awk [-F SEP] [-v VAR=VALUE ...] PROGRAM [FILE...], or with -f PROGFILE instead of
# PROGRAM: as awk, with the num_* functions defined. POSIX awk takes either a program text
# or -f files, never both: a program text goes in as a second -f (a process substitution).
num_awk() {
    local opts=() progfile=0
    while [ $# -gt 1 ]; do
        case $1 in
            -F|-v) opts+=("$1" "$2"); shift 2 ;;
            -f) opts+=("$1" "$2"); progfile=1; shift 2 ;;
            -F?*|-v?*) opts+=("$1"); shift ;;
            *) break ;;
        esac
    done
    if [ $progfile = 1 ]; then ${NUM_AWK:-awk} -f "$NUMERICS_AWK" "${opts[@]}" "$@"
    else ${NUM_AWK:-awk} "${opts[@]}" -f "$NUMERICS_AWK" -f <(printf '%s\n' "$1") "${@:2}"; fi
}

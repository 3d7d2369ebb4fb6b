# shlib.sh - the common preamble of the shell tests, sourced from the repository
# root as `. tests/shlib.sh NAME`: DPD (the binary under test, made absolute),
# tmp (a fresh directory removed on exit), the pass/fail counters and ok/bad.
DPD=${DPD:-bin/dpd}
case $DPD in /*) ;; *) DPD=$PWD/$DPD ;; esac
tmp=$(mktemp -d "${TMPDIR:-/tmp}/dpd-$1-XXXXXX")
trap 'rm -rf "$tmp"' EXIT
pass=0 fail=0
ok()  { pass=$((pass + 1)); echo "PASS $1"; }
bad() { fail=$((fail + 1)); echo "FAIL $1: $2"; }
# refuse NAME EXPECTED-MESSAGE COMMAND ARGS...: the command fails, says EXPECTED-MESSAGE on stderr
# and writes nothing on stdout
refuse() {
    local name=$1 msg=$2; shift 2
    if "$@" > "$tmp/out" 2> "$tmp/err"; then bad "$name" "exit 0"
    elif ! grep -q -e "$msg" "$tmp/err"; then bad "$name" "message: $(cat "$tmp/err")"
    elif [ -s "$tmp/out" ]; then bad "$name" "wrote a table"
    else ok "$name"; fi
}

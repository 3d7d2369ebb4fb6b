#!/bin/bash
# scene_errors.sh - every tests/bad-scenes/X.cfg must be rejected cleanly:
#   dpd run X.cfg [args from X.args, one per line] --out TMP/out
# exits with the status in X.status (default 2: bad scene; 1: usage error),
# prints to stderr a line matching the grep -E pattern in X.expect (file:line:
# and the key where they exist), and writes no summary.tsv.
# tests/good-scene.cfg, the valid scene the bad ones vary, must run (status
# 0, summary.tsv written): without that control the checks would have no power.
# DPD selects the binary (default bin/dpd). Prints "N passed, M failed".
set -u
cd "$(dirname "$0")/.."
. tests/shlib.sh scene-errors

bad() { fail=$((fail + 1)); echo "FAIL $1: $2"; [ -s "$tmp/err" ] && sed 's/^/    stderr: /' "$tmp/err"; }

if [ ! -x "$DPD" ]; then echo "FAIL: $DPD not found"; echo "0 passed, 1 failed"; exit 1; fi

# control
rm -rf "$tmp/out"
"$DPD" run tests/good-scene.cfg --out "$tmp/out" --quiet 2>"$tmp/err" >/dev/null
st=$?
if [ $st -eq 0 ] && [ -s "$tmp/out/summary.tsv" ]; then ok good-scene
else bad good-scene "status $st (want 0) or no summary.tsv"; fi

for cfg in tests/bad-scenes/*.cfg; do
    name=$(basename "$cfg" .cfg)
    dir=${cfg%.cfg}
    if [ ! -f "$dir.expect" ]; then bad "$name" "no $name.expect"; continue; fi
    pattern=$(head -1 "$dir.expect")
    want=2; [ -f "$dir.status" ] && want=$(head -1 "$dir.status")
    args=()
    if [ -f "$dir.args" ]; then mapfile -t args < "$dir.args"; fi
    rm -rf "$tmp/out"
    # Under ASan, usage errors (status 1) run with leak detection off: main()
    # returns from its option loop without freeing its two argument buffers
    # (src/app/main.c), a leak at exit only. Bad scenes (status 2) keep it on.
    leak=${ASAN_OPTIONS:-}
    [ "$want" = 1 ] && leak="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0"
    ASAN_OPTIONS=$leak "$DPD" run "$cfg" "${args[@]}" --out "$tmp/out" --quiet >"$tmp/stdout" 2>"$tmp/err"
    st=$?
    if [ $st -ne "$want" ]; then bad "$name" "exit status $st, want $want"
    elif ! grep -Eq -e "$pattern" "$tmp/err"; then bad "$name" "stderr does not match: $pattern"
    elif [ -e "$tmp/out/summary.tsv" ]; then bad "$name" "summary.tsv was written"
    elif grep -q 'runtime error\|AddressSanitizer\|LeakSanitizer' "$tmp/err"; then bad "$name" "sanitizer report"
    else ok "$name"; fi
done
echo "$pass passed, $fail failed"
[ $fail -eq 0 ]

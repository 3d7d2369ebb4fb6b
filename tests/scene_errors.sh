#!/bin/bash
# scene_errors.sh - every tests/bad-scenes/X.cfg must be rejected cleanly:
#   dpd run X.cfg [args from X.args, one per line] --out TMP/out
# exits with the status in X.status (default 2: bad scene; 1: usage error),
# prints to stderr a line matching the grep -E pattern in X.expect (file:line:
# and the key where they exist), and writes no summary.tsv.
# tests/good-scene.cfg, the valid scene the bad ones vary, must run (status
# 0, summary.tsv written): without that control the checks would have no power.
# Then files that are no scene, as the scene or as an @include: a directory,
# /dev/zero, a FIFO, a file over the size limit: status 2 and a message naming
# the file (and the line of the @include), within 20 s and 1 GB (libconfig must
# never see them: it ends the process on a read error and reads /dev/zero for
# ever, and opening a FIFO waits for a writer).
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
# not_a_scene NAME PATTERN SCENE: dpd run SCENE stops with status 2, PATTERN on stderr, no summary
not_a_scene() {
    local name=$1 pattern=$2 scene=$3 st
    rm -rf "$tmp/out"
    # (no address-space cap under ASan, which reserves terabytes of shadow memory at start)
    ( [ "${SANITIZE:-}" = 1 ] || ulimit -v 1000000; timeout 20 "$DPD" run "$scene" --out "$tmp/out" --quiet ) >"$tmp/stdout" 2>"$tmp/err"
    st=$?
    if [ $st -ne 2 ]; then bad "$name" "exit status $st, want 2$([ $st = 124 ] && echo ' (timed out)')"
    elif ! grep -Eq -e "$pattern" "$tmp/err"; then bad "$name" "stderr does not match: $pattern"
    elif [ -e "$tmp/out/summary.tsv" ]; then bad "$name" "summary.tsv was written"
    elif grep -q 'runtime error\|AddressSanitizer\|LeakSanitizer' "$tmp/err"; then bad "$name" "sanitizer report"
    else ok "$name"; fi
}
mkdir -p "$tmp/special/adir"
mkfifo "$tmp/special/fifo"
truncate -s 100M "$tmp/special/huge.cfg"
cp tests/good-scene.cfg "$tmp/special/scene.cfg"
not_a_scene "scene is a directory" "'$tmp/special/adir' is a directory, not a regular file" "$tmp/special/adir"
not_a_scene "scene is /dev/zero" "'/dev/zero' is a character device, not a regular file" /dev/zero
not_a_scene "scene is a FIFO" "'$tmp/special/fifo' is a FIFO, not a regular file" "$tmp/special/fifo"
not_a_scene "scene over the size limit" "'$tmp/special/huge.cfg' has 104857600 bytes; a scene file may have at most" "$tmp/special/huge.cfg"
for what in adir:directory /dev/zero:"character device" fifo:FIFO huge.cfg:"104857600 bytes"; do
    target=${what%%:*} kind=${what#*:}
    case $target in /*) ;; *) target=$tmp/special/$target ;; esac
    { sed -n '1,/^steps/p' tests/good-scene.cfg; printf '  @include "%s"\n' "$target"; sed -n '/^types/,$p' tests/good-scene.cfg; } > "$tmp/special/inc.cfg"
    line=$(grep -n '@include' "$tmp/special/inc.cfg" | cut -d: -f1)
    not_a_scene "@include of a $kind" "inc\.cfg:$line: @include '$target'.* $kind" "$tmp/special/inc.cfg"
done
# control: an @include of a regular file works (the checks above have power)
{ sed -n '1,/^steps/p' tests/good-scene.cfg; echo '@include "types.inc"'; } > "$tmp/special/inc.cfg"
sed -n '/^types/,$p' tests/good-scene.cfg > "$tmp/special/types.inc"
rm -rf "$tmp/out"
if (cd "$tmp/special" && "$DPD" run inc.cfg --out "$tmp/out" --quiet >/dev/null 2>"$tmp/err") && [ -s "$tmp/out/summary.tsv" ]; then
    ok "@include of a regular file (control)"
else bad "@include of a regular file (control)" "$(cat "$tmp/err")"; fi
# steps = 0 (and steps below measure.every): no sample is taken; decided: the run is no error
# (an equilibration alone, e.g. for its final state or its cost), and its summary has the run's
# cost rows only and no measured quantity, never rows of nan; a note on stderr says so
for st in 0 5; do
    rm -rf "$tmp/out"
    "$DPD" run tests/good-scene.cfg --set steps=$st --out "$tmp/out" --quiet >/dev/null 2>"$tmp/err"; rc=$?
    if [ $rc -eq 0 ] && [ -s "$tmp/out/summary.tsv" ] && ! grep -qi 'nan' "$tmp/out/summary.tsv" \
       && ! grep -q '^temperature' "$tmp/out/summary.tsv" && grep -q '^particles' "$tmp/out/summary.tsv" \
       && grep -q "no sample was taken (steps = $st, measure.every = 10)" "$tmp/err"; then
        ok "steps = $st: no sample, a summary of the run's cost only (no nan), and a note"
    else bad "steps = $st" "status $rc; summary: $(tr '\n' '|' < "$tmp/out/summary.tsv" 2>/dev/null | head -c 300)"; fi
done
echo "$pass passed, $fail failed"
[ $fail -eq 0 ]

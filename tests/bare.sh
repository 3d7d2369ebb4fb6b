#!/bin/bash
# bare.sh - the bare build (make build/dpd-bare, -DDPD_BARE, src/core/modules.h: every
# optional module compiled out of the hot path) computes bin/dpd's numbers bit for
# bit on a scene without modules (the standard scene of make bench, small, with
# measurement steps): the same summary rows (all but times, rates and memory) and
# the same final state (17 digits). It refuses scenes that switch a module on
# (exit 2, naming the module). DPD and BARE select the binaries. Prints "N passed, M failed".
set -u
cd "$(dirname "$0")/.."
DPD=${DPD:-bin/dpd}
BARE=${BARE:-build/dpd-bare}
tmp=$(mktemp -d "${TMPDIR:-/tmp}/dpd-bare-XXXXXX")
trap 'rm -rf "$tmp"' EXIT
pass=0 fail=0
ok()  { pass=$((pass + 1)); echo "PASS $1"; }
bad() { fail=$((fail + 1)); echo "FAIL $1: $2"; }
if [ ! -x "$BARE" ]; then bad "bare build" "$BARE missing (make $BARE)"; echo "$pass passed, $fail failed"; exit 1; fi

small=(--set "box=[6.0,6.0,6.0]" --set steps=300 --set equilibration=100 --set "measure.every=20")
for t in 1 2; do
    for b in "$DPD" "$BARE"; do
        OMP_NUM_THREADS=$t "$b" run bench/standard.cfg --out "$tmp/$(basename "$b")-$t" --threads $t --quiet "${small[@]}" \
            >/dev/null 2>"$tmp/err" || bad "$(basename "$b") runs the standard scene ($t threads)" "$(cat "$tmp/err")"
    done
    a=$tmp/$(basename "$DPD")-$t z=$tmp/$(basename "$BARE")-$t
    strip() { grep -vE '(second|memory)' "$1/summary.tsv"; }
    if [ -s "$a/summary.tsv" ] && [ -s "$z/summary.tsv" ] && [ "$(strip "$a" | wc -l)" -gt 5 ] \
        && diff <(strip "$a") <(strip "$z") >/dev/null; then
        ok "bare = dpd: summary rows, standard scene, $t thread(s)"
    else bad "bare = dpd: summary rows, $t thread(s)" "$(diff <(strip "$a") <(strip "$z") 2>&1 | head -5)"; fi
    fs() { h5dump -m %.17g -d /results/final_state "$1/run.h5" 2>/dev/null | sed 1,2d; }
    if [ -n "$(fs "$a")" ] && [ "$(fs "$a")" = "$(fs "$z")" ]; then
        ok "bare = dpd: final state bit for bit, $t thread(s)"
    else bad "bare = dpd: final state, $t thread(s)" "differs or missing"; fi
done

# a module switched on: refused, naming it
refuse() {  # NAME MODULE-WORD --set ARGS...
    local name=$1 word=$2; shift 2
    "$BARE" run bench/standard.cfg --out "$tmp/refuse" --threads 1 --quiet "${small[@]}" "$@" >/dev/null 2>"$tmp/err"
    local rc=$?
    if [ $rc -eq 2 ] && grep -q "bare build" "$tmp/err" && grep -q "$word" "$tmp/err"; then ok "bare refuses $name"
    else bad "bare refuses $name" "exit $rc: $(head -c 300 "$tmp/err")"; fi
}
refuse "Lees-Edwards shear" shear_rate --set shear_rate=0.5
refuse "rotation" rotation --set rotation=true
refuse "a body force" "body force" --set 'types.[0].body_force=[0.1,0.0,0.0]'
refuse "frozen particles" frozen --set 'types.[0].frozen=true'
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]

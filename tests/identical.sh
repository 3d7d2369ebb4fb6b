#!/bin/bash
# identical.sh REF [NEW] - a refactor changes no number: the simulator REF (a
# binary built from an earlier commit) and NEW (default bin/dpd) give the same
# summary rows (times, rates and memory aside), the same final state and the
# same series, bit for bit, on one scene per model and module (standard, shear,
# rotation, the general weight exponent of one type (the mai-duy-2019
# solvent), frozen rotors, colloids 2D/3D, springs with m = 0, TCAF, the
# experiments' suspension and two-sphere scenes), each shortened, on 1 and 2
# threads. Not part of make test (it needs a second binary); run it around any
# change meant to keep behaviour (tools: make build/dpd-ref REF=<commit>).
# A REF from before the commit that brought weight_pow (src/pair/weight_pow.h,
# 2026-12-03) differs on purpose on the scenes with a weight exponent other
# than 2, 1 and 0.5 (checkpoint-colloids3d, suspension-shear): w_R = w_C^(s/2)
# is no longer libm's pow (within 1 ulp of it, test_forces). With libm's pow
# put back into weight_pow.c the 24 comparisons passed, so nothing else moved.
# A REF from before the TCAF sums went eight particles side by side (tcaf.c,
# 2026-12-03, after ba5bcb63) differs on purpose in the TCAF results of
# checkpoint-tcaf (its tcaf_* rows, in the 10th digit): J(k) is summed in
# another order; the trajectory and every other row are the same bits.
# Prints "N passed, M failed"; the exit status is the verdict.
set -u
cd "$(dirname "$0")/.."
REF=${1:?usage: tests/identical.sh REF-BINARY [NEW-BINARY]}
NEW=${2:-bin/dpd}
tmp=$(mktemp -d "${TMPDIR:-/tmp}/dpd-identical-XXXXXX")
trap 'rm -rf "$tmp"' EXIT
pass=0 fail=0
ok()  { pass=$((pass + 1)); echo "PASS $1"; }
bad() { fail=$((fail + 1)); echo "FAIL $1: $2"; }

# scene | overrides (short runs; measurement steps included)
scenes=(
  "bench/standard.cfg|--set box=[6.0,6.0,6.0] --set steps=200 --set equilibration=50 --set measure.every=10"
  "bench/pan-fluid.cfg|--set steps=60 --set equilibration=20 --set measure.every=10"
  "bench/mai-duy-solvent.cfg|--set box=[8.0,8.0,8.0] --set steps=60 --set equilibration=20 --set measure.every=10"
  "tests/checkpoint-shear.cfg|"
  "tests/checkpoint-rotation.cfg|"
  "tests/checkpoint-colloids2d.cfg|"
  "tests/checkpoint-colloids3d.cfg|"
  "tests/checkpoint-overdamped.cfg|"
  "tests/checkpoint-tcaf.cfg|"
  "experiments/mai-duy-2019/fig04-relative-viscosity-a353/suspension-shear.cfg|--set steps=40 --set equilibration=20"
  "experiments/pan-2008/tab03-two-spheres/two-spheres.cfg|--set steps=40 --set equilibration=20"
  "experiments/phan-thien-2016/fig12-relative-viscosity/shear.cfg|--set steps=30 --set equilibration=10"
  "experiments/phan-thien-2016/fig03-couette-profile/couette.cfg|--set steps=30 --set equilibration=10"
)
strip() { grep -vE '(second|memory)' "$1/summary.tsv"; }
dump() { h5dump -m %.17g -d "$2" "$1/run.h5" 2>/dev/null | sed 1,2d; }
series() { h5ls -r "$1/run.h5/series" 2>/dev/null | awk '$2 == "Dataset" { print $1 }'; }
for entry in "${scenes[@]}"; do
    cfg=${entry%%|*} args=${entry#*|}
    name=$(basename "$(dirname "$cfg")")/$(basename "$cfg" .cfg)
    [ -f "$cfg" ] || { bad "$name" "no scene $cfg"; continue; }
    for t in 1 2; do
        for b in ref new; do
            bin=$REF; [ $b = new ] && bin=$NEW
            # shellcheck disable=SC2086
            OMP_NUM_THREADS=$t "$bin" run "$cfg" --out "$tmp/$b" --threads $t --quiet $args >/dev/null 2>"$tmp/err.$b"
            echo $? > "$tmp/rc.$b"
        done
        what="$name, $t thread(s)"
        if [ "$(cat "$tmp/rc.ref")" != "$(cat "$tmp/rc.new")" ]; then
            bad "$what: exit status" "ref $(cat "$tmp/rc.ref"), new $(cat "$tmp/rc.new"): $(head -c 300 "$tmp/err.new")"
        elif [ "$(cat "$tmp/rc.ref")" != 0 ]; then
            bad "$what" "both fail ($(cat "$tmp/rc.ref")): $(head -c 300 "$tmp/err.ref")"
        else
            d=""
            diff <(strip "$tmp/ref") <(strip "$tmp/new") >/dev/null || d="summary rows"
            [ -n "$(dump "$tmp/ref" /results/final_state)" ] && [ "$(dump "$tmp/ref" /results/final_state)" = "$(dump "$tmp/new" /results/final_state)" ] || d="$d final_state"
            [ "$(series "$tmp/ref")" = "$(series "$tmp/new")" ] || d="$d series-names"
            for s in $(series "$tmp/ref"); do
                [ "$(dump "$tmp/ref" "/series/$s")" = "$(dump "$tmp/new" "/series/$s")" ] || d="$d /series/$s"
            done
            for f in "$tmp"/ref/*.tsv; do
                case $(basename "$f") in summary.tsv|provenance.tsv|solver.tsv) continue ;; esac
                cmp -s "$f" "$tmp/new/$(basename "$f")" || d="$d $(basename "$f")"
            done
            if [ -z "$d" ]; then ok "$what: identical"; else bad "$what" "differs:$d"; fi
        fi
        rm -rf "$tmp/ref" "$tmp/new"
    done
done
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]

#!/bin/bash
# precision.sh - experiments/methods/pan-estimators/precision.sh (issue 38 item 1): the stderr that
# decides a claim under issue 37's rule (half the distance of the assumed true value to the band's
# nearer edge, inside or outside) and the CPU-hours the plain time average needs for it, on a
# synthetic results tree whose answers are known by hand:
#  - one run: CPU = a / se^2 with a = se_now^2 x (production CPU, scaled by the run's cost class);
#  - two independent parts (a run and a reference run, the second's share given by a relative error):
#    CPU = (sqrt(a_1) + sqrt(a_2))^2 / se^2, the best split between them;
#  - equilibration counted once, not scaled; the verdict of value +- 2 se against the band.
# Prints "N passed, M failed".
set -u
cd "$(dirname "$0")/.."
. tests/shlib.sh precision
root=$PWD
t=$tmp/tree
mkdir -p "$t/experiments/pan-2008/fake" "$t/bench" "$t/results/pan-2008/fake/reduced/runs"
ln -s "$root/tools" "$t/tools"
# cost class "standard" (a plain scene), factor 0.5: committed CPU counts half
printf 'class\tcpu_time_new_over_base\nstandard\t0.5\n' > "$t/bench/speedup.tsv"
printf 'dimension = 3;\ndt = 0.01;\nequilibration = 0;\nsteps = 100;\n' > "$t/experiments/pan-2008/fake/plain.cfg"
printf 'quantity\ttier\tlo\thi\tk_sigma\tpaper\tsource\n' > "$t/experiments/pan-2008/fake/bands.tsv"
band() { printf '%s\tpaper\t%s\t%s\t2\t%s\tsynthetic\n' "$@" >> "$t/experiments/pan-2008/fake/bands.tsv"; }
band inside 0.9 1.1 1.0       # value 1.05 +- 0.02: PASS; paper 1.0
band two 1.5 2.1 1.8          # value 2.0 +- 0.05 from two parts
band outside 0.9 1.1 1.0      # value 1.3 +- 0.02: FAIL
band edge 0.9 1.1 1.0         # value 1.1 +- 0.05: UNRESOLVED, no run length decides it at our value
band eq 0.9 1.1 1.0           # value 1.0 +- 0.04, a run with a fifth of its steps equilibration
res=$t/results/pan-2008/fake/reduced
printf 'quantity\tvalue\tstderr\ninside\t1.05\t0.02\ntwo\t2.0\t0.05\nref\t10\t0.2\noutside\t1.3\t0.02\nedge\t1.1\t0.05\neq\t1.0\t0.04\n' > "$res/summary.tsv"
run() {   # NAME CPU_SECONDS STEPS [EQUILIBRATION]
    mkdir -p "$res/runs/$1"
    printf 'plain.cfg\n' > "$res/runs/$1/.args"
    [ -n "${4:-}" ] && printf -- '--set\nequilibration=%s\n' "$4" >> "$res/runs/$1/.args"
    printf 'quantity\tvalue\tstderr\nsteps\t%s\t0\ncpu_seconds\t%s\t0\n' "$3" "$2" > "$res/runs/$1/summary.tsv"
}
run r1 3600 10000; run r2 3600 10000; run r3 3600 10000; run r4 7200 10000 2000
printf '%s\n' "experiment	tier	quantity	groups	note" \
    "pan-2008/fake	reduced	inside	r1	" \
    "pan-2008/fake	reduced	two	r2|ref;r3	" \
    "pan-2008/fake	reduced	outside	r1	" \
    "pan-2008/fake	reduced	edge	r1	" \
    "pan-2008/fake	reduced	eq	r4	" > "$t/claims.tsv"

# the table's column C of quantity Q; check QUANTITY COLUMN EXPECTED WHY (numbers to 0.1 %)
col() { awk -F'\t' -v q="$1" -v c="$2" 'NR == 1 { for (i = 1; i <= NF; i++) k[$i] = i; next } $2 == q { print $k[c] }' "$tmp/p.tsv"; }
near() { awk -v a="$1" -v b="$2" 'BEGIN { d = a - b; exit !(d <= 1e-3 * (b < 0 ? -b : b) + 1e-12 && -d <= 1e-3 * (b < 0 ? -b : b) + 1e-12) }'; }
check() {
    local v; v=$(col "$1" "$2")
    if [ "$3" = inf ] || [ "$3" = PASS ] || [ "$3" = FAIL ] || [ "$3" = UNRESOLVED ] || [ "$3" = - ]; then
        [ "$v" = "$3" ] && ok "$1 $2 = $3 ($4)" || bad "$1 $2" "got '$v', want $3 ($4)"
    else
        near "$v" "$3" && ok "$1 $2 = $3 ($4)" || bad "$1 $2" "got '$v', want $3 ($4)"
    fi
}
# precision NAME CLAIMS [VAR=VALUE...]: precision.sh on the synthetic tree into $tmp/p.tsv; a failure
# is the check NAME's
precision() {
    local name=$1 claims=$2; shift 2
    env DPD_ROOT=$t "$@" experiments/methods/pan-estimators/precision.sh "$claims" > "$tmp/p.tsv" 2> "$tmp/err" && return 0
    bad "$name" "$(cat "$tmp/err")"; return 1
}
if precision "precision.sh on the synthetic tree" "$t/claims.tsv"; then
    check inside verdict_now PASS "1.05 +- 0.04 inside [0.9, 1.1]"
    check inside se_decides_paper 0.05 "paper 1.0: 0.1 from either edge, halved"
    check inside se_decides_ours 0.025 "1.05: 0.05 from 1.1, halved"
    check inside cpu_h_paper 0.08 "0.5 h x (0.02 / 0.05)^2"
    check inside cpu_h_ours 0.32 "0.5 h x (0.02 / 0.025)^2"
    check two se_decides_paper 0.15 "1.8: 0.3 from either edge"
    check two cpu_h_paper 0.108888889 "(sqrt(0.04^2 x 0.5) + sqrt(0.03^2 x 0.5))^2 / 0.15^2: the parts 0.04 (ref's 2 % of 2.0) and 0.03 (the rest of 0.05)"
    check two cpu_h_ours 0.98 "the same over 0.05^2"
    check outside verdict_now FAIL "1.3 +- 0.04 above 1.1"
    check outside se_decides_ours 0.1 "1.3 is 0.2 outside the band, halved"
    check edge verdict_now UNRESOLVED "1.1 +- 0.1 across the edge"
    check edge cpu_h_ours inf "a value on the edge is decided by no run length"
    check eq cpu_h_paper 0.712 "7200 s x 0.5 = 1 h, of which 0.8 h production: 0.8 h x (0.04 / 0.05)^2 + 0.2 h of equilibration, once"
    check eq prod_time_now 80 "8000 production steps x dt 0.01"
    [ "$(col inside experiment@tier)" = pan-2008/fake@reduced ] && ok "the row names its committed tier" ||
        bad "the row names its committed tier" "got '$(col inside experiment@tier)'"
fi
# issue 37's bands.tsv (a kind column; columns found by name; a gate row of the same name skipped)
mkdir -p "$t/experiments/pan-2008/fake2" "$t/results/pan-2008/fake2/reduced/runs"
cp "$t/experiments/pan-2008/fake/plain.cfg" "$t/experiments/pan-2008/fake2/"
printf 'quantity\ttier\tkind\tlo\thi\tk_sigma\tresolution\tpaper\tsource\n' > "$t/experiments/pan-2008/fake2/bands.tsv"
printf 'inside\tpaper\tgate\t0\t9\t3\t-\t-\tset-up\ninside\tpaper\tclaim\t0.9\t1.1\t-\t-\t1.0\tsynthetic\n' >> "$t/experiments/pan-2008/fake2/bands.tsv"
cp "$res/summary.tsv" "$t/results/pan-2008/fake2/reduced/"; cp -r "$res/runs/r1" "$t/results/pan-2008/fake2/reduced/runs/"
printf '%s\n' "experiment	tier	quantity	groups	note" "pan-2008/fake2	reduced	inside	r1	" > "$t/claims2.tsv"
if precision "precision.sh on issue 37's bands format" "$t/claims2.tsv"; then
    check inside se_decides_paper 0.05 "issue 37's format: the claim row's band, not the gate's"
    check inside cpu_h_ours 0.32 "issue 37's format: as before"
fi
# the relative mode (item 5): a stderr of 0.5 % of the paper's value and of ours, no band needed
printf '%s\n' "experiment	tier	quantity	groups	note	paper" "pan-2008/fake	reduced	inside	r1		1.0" > "$t/entries.tsv"
if precision "precision.sh PRECISION_REL=0.005" "$t/entries.tsv" PRECISION_REL=0.005; then
    check inside se_decides_paper 0.005 "0.5 % of the paper's 1.0"
    check inside cpu_h_paper 8 "0.5 h x (0.02 / 0.005)^2"
    check inside cpu_h_ours 7.256 "0.5 h x (0.02 / 0.00525)^2"
    check inside verdict_now - "no band"
fi
# runs named by a pattern, and a run whose binary has bench/speedup.tsv's speed-up already (its
# provenance commit descends from the commit measured there as new: tools/cost run-factor) counted at
# its own CPU, the older run at its class's factor: a synthetic history P0 -> A (new) -> B
h=$tmp/hist; mkdir -p "$h"
git -C "$h" init -q && git -C "$h" config user.email t@t && git -C "$h" config user.name t
for c in P0 A B; do git -C "$h" commit -q --allow-empty -m $c; done
cA=$(git -C "$h" rev-parse --short=7 HEAD~1) cB=$(git -C "$h" rev-parse --short=7 HEAD) cP=$(git -C "$h" rev-parse --short=7 HEAD~2)
cp -a "$h/.git" "$t/.git"
printf 'date, commits\t2026-12-04\t%s-dirty\tbase dpd %s\n' "$cA" "$cP" >> "$t/bench/speedup.tsv"
band glob 0.9 1.1 1.0
printf 'glob\t1.0\t0.02\n' >> "$res/summary.tsv"
run g_1 3600 10000; run g_2 3600 10000
printf 'git_commit\t%s-dirty\n' "$cB" > "$res/runs/g_1/provenance.tsv"
printf 'git_commit\t%s\n' "$cP" > "$res/runs/g_2/provenance.tsv"
printf '%s\n' "experiment	tier	quantity	groups	note" "pan-2008/fake	reduced	glob	g_*	" > "$t/claims3.tsv"
if precision "precision.sh with a run pattern and a sped-up binary's run" "$t/claims3.tsv"; then
    check glob cpu_h_paper 0.24 "g_* is g_1 and g_2: (1 h x 1 + 1 h x 0.5) x (0.02 / 0.05)^2; g_1 (commit B) has the speed-up, g_2 (P0) not"
    check glob longest_sim_h_paper 0.12 "two runs share it"
fi
rm -rf "$t/.git"
printf '%s\n' "experiment	tier	quantity	groups	note" "pan-2008/fake	reduced	glob	h_*	" > "$t/claims4.tsv"
refuse "a pattern that matches no committed run refused" "h_\\*" env DPD_ROOT=$t experiments/methods/pan-estimators/precision.sh "$t/claims4.tsv"
# a claim without a paper band is refused, naming it
printf '%s\n' "experiment	tier	quantity	groups	note" "pan-2008/fake	reduced	nosuch	r1	" > "$t/bad.tsv"
refuse "a claim without a band or value refused" "nosuch" env DPD_ROOT=$t experiments/methods/pan-estimators/precision.sh "$t/bad.tsv"
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]

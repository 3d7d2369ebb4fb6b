#!/bin/bash
# stage2_plan.sh - experiments/pan-2008/tab02-poiseuille/stage2-plan (the paper tier's second stage,
# fixed in its README on 2026-12-07), on synthetic results trees whose answers are worked by hand:
#  - only a claim row that tools/check leaves UNRESOLVED gets runs: n_extra = ceil(n1 ((3 se / d)^2 - 1)),
#    d the distance of the value to the band's nearer edge (inside or outside the band);
#  - a row with both claims unresolved takes the larger n_extra; a PASS, a FAIL or a gate gets none;
#  - above the 20 CPU-hour budget (at each row's mean CPU per run) every row's n_extra is scaled down
#    in proportion, rounded down, at least 1;
#  - no result, or a row without runs: an error, no plan.
# Prints "N passed, M failed".
set -u
cd "$(dirname "$0")/.."
. tests/shlib.sh stage2
root=$PWD
id=pan-2008/tab02-poiseuille
plan=$root/experiments/$id/stage2-plan

# tree NAME: an empty synthetic tree (tools linked, the six claim bands of Table 2 and one gate)
tree() {
    t=$tmp/$1; res=$t/results/$id/paper
    mkdir -p "$t/experiments/$id" "$res/runs"
    ln -s "$root/tools" "$t/tools"
    {
        printf 'quantity\ttier\tkind\tlo\thi\tk_sigma\tresolution\tpaper\tsource\texpect\n'
        for q in drag torque; do for r in 1 2 3; do
            printf '%s_ratio_row%s\tpaper\tclaim\t0.88\t1.12\t-\t-\t1\tsynthetic\t\n' "$q" "$r"
        done; done
        printf 'u_h_row1\tpaper\tgate\t0.88\t1.12\t-\t-\t1\tsynthetic, a gate: never extended\t\n'
    } > "$t/experiments/$id/bands.tsv"
    printf 'quantity\tvalue\tstderr\n' > "$res/summary.tsv"
}
# value QUANTITY VALUE STDERR: a row of the landed result
value() { printf '%s\t%s\t%s\n' "$@" >> "$res/summary.tsv"; }
# runs ROW N CPU: the row's N runs (row<R>, row<R>r2 ...), each of CPU seconds
runs() {
    local k name
    for k in $(seq "$2"); do
        name=row$1; [ "$k" -gt 1 ] && name=row$1r$k
        mkdir -p "$res/runs/$name"
        printf 'quantity\tvalue\tstderr\ncpu_seconds\t%s\t0\n' "$3" > "$res/runs/$name/summary.tsv"
    done
}
# planned NAME: stage2-plan on the current tree into $tmp/NAME.out; a failure is the check NAME's
planned() {
    DPD_ROOT=$t "$plan" > "$tmp/$1.out" 2> "$tmp/$1.err" && return 0
    bad "$1" "exit $?: $(cat "$tmp/$1.err")"; return 1
}
# says NAME PATTERN WHY: the last plan printed a line matching PATTERN (an ERE)
says() {
    grep -Eq -- "$2" "$tmp/$1.out" && ok "$1: $3" || bad "$1: $3" "no line /$2/ in: $(cat "$tmp/$1.out")"
}

# Over the budget. Row 1 (4 runs of 3600 s): the torque 1.10 +- 0.02 spans 1.12 (d = 0.02),
# n_extra = ceil(4 (3^2 - 1)) = 32; its drag passes. Row 2 (2 runs of 7200 s): the drag 0.90 +- 0.015
# (d = 0.02) gives ceil(2 (2.25^2 - 1)) = ceil(8.125) = 9, the torque 1.13 +- 0.01, outside the band
# but within 2 se of it (d = 0.01), ceil(2 (3^2 - 1)) = 16: the row takes 16. Row 3: drag passes,
# torque 1.30 +- 0.01 fails: nothing. The gate is unresolved and ignored. Before the budget
# 32 x 3600 + 16 x 7200 s = 64 CPU-h; scaled by 20 / 64 = 0.3125: 10 and 5 more, 20.0 CPU-h.
tree over
runs 1 4 3600; runs 2 2 7200; runs 3 1 1800
value drag_ratio_row1 1.00 0.01; value torque_ratio_row1 1.10 0.02
value drag_ratio_row2 0.90 0.015; value torque_ratio_row2 1.13 0.01
value drag_ratio_row3 1.00 0.01; value torque_ratio_row3 1.30 0.01
value u_h_row1 1.11 0.02
if planned over; then
    says over '^torque_ratio_row1 +UNRESOLVED .*n1 = 4: n_extra 32$' "row 1's torque: ceil(4 x (3^2 - 1)) = 32"
    says over '^drag_ratio_row1 +PASS .*n_extra 0$' "a passing claim gets no runs"
    says over '^drag_ratio_row2 +UNRESOLVED .*d = 0.0200, n1 = 2: n_extra 9$' "row 2's drag: ceil(2 x (2.25^2 - 1)) = ceil(8.125) = 9"
    says over '^torque_ratio_row2 +UNRESOLVED .*d = 0.0100, n1 = 2: n_extra 16$' "a value outside the band, within 2 se: d to the edge it lies beyond"
    says over '^torque_ratio_row3 +FAIL .*n_extra 0$' "a failing claim gets no runs"
    grep -q u_h "$tmp/over.out" && bad "over: a gate is not planned" "$(grep u_h "$tmp/over.out")" ||
        ok "over: a gate is not planned"
    says over '^second stage before the budget: 64.0 CPU-h \(budget 20\), scaled by 0.312$' "32 x 3600 + 16 x 7200 s = 64 CPU-h, scaled by 20 / 64"
    says over '^row 1: 4 runs of 3600 CPU-s each -> 10 more \(row_reps 4 -> 14\)$' "row 1: int(32 x 0.3125) = 10"
    says over '^row 2: 2 runs of 7200 CPU-s each -> 5 more \(row_reps 2 -> 7\)$' "row 2 takes the larger of its two claims: int(16 x 0.3125) = 5"
    says over '^row 3: 1 runs of 1800 CPU-s each -> 0 more \(row_reps 1 -> 1\)$' "row 3: nothing unresolved, nothing more"
    says over '^second stage: 20.0 CPU-h$' "10 x 3600 + 5 x 7200 s"
fi

# Under the budget: row 1's torque 1.10 +- 0.012 (d = 0.02): ceil(4 (1.8^2 - 1)) = ceil(8.96) = 9 runs,
# 9 CPU-h, unscaled; the row's CPU per run is the mean of its runs' (3000 and 4200 s: 3600).
tree under
runs 1 4 3000; sed -i 's/3000/4200/' "$res"/runs/row1r3/summary.tsv "$res"/runs/row1r4/summary.tsv
runs 2 3 7200; runs 3 1 1800
value drag_ratio_row1 1.00 0.01; value torque_ratio_row1 1.10 0.012
for q in drag_ratio_row2 torque_ratio_row2 drag_ratio_row3 torque_ratio_row3; do value $q 1.00 0.01; done
if planned under; then
    says under '^torque_ratio_row1 +UNRESOLVED .*n_extra 9$' "ceil(4 x (1.8^2 - 1)) = ceil(8.96) = 9"
    says under '^second stage before the budget: 9.0 CPU-h \(budget 20\)$' "9 x 3600 s, under the budget: not scaled"
    says under '^row 1: 4 runs of 3600 CPU-s each -> 9 more \(row_reps 4 -> 13\)$' "the row's mean CPU per run"
    says under '^row 2: 3 runs of 7200 CPU-s each -> 0 more' "row 2 decided: nothing more"
fi

# Scaled below one run: row 1's torque 1.10 +- 0.2 (d = 0.02) asks ceil(4 (30^2 - 1)) = 3596 runs, row 3's
# torque 0.90 +- 0.012 asks ceil(1 x (1.8^2 - 1)) = 3. Scale 72000 / (3596 x 3600 + 3 x 1800) = 0.00556:
# row 1 int(19.99) = 19, row 3 int(0.017) = 0, raised to 1.
tree floor
runs 1 4 3600; runs 2 3 7200; runs 3 1 1800
value drag_ratio_row1 1.00 0.01; value torque_ratio_row1 1.10 0.2
value drag_ratio_row2 1.00 0.01; value torque_ratio_row2 1.00 0.01
value drag_ratio_row3 1.00 0.01; value torque_ratio_row3 0.90 0.012
if planned floor; then
    says floor '^torque_ratio_row1 +UNRESOLVED .*n_extra 3596$' "ceil(4 x (30^2 - 1)) = 3596"
    says floor '^torque_ratio_row3 +UNRESOLVED .*n1 = 1: n_extra 3$' "a value below the band's middle: d to the lower edge"
    says floor '^row 1: .* -> 19 more' "int(3596 x 0.00556) = 19"
    says floor '^row 3: .* -> 1 more \(row_reps 1 -> 2\)$' "scaled to 0, at least 1"
fi

# Errors: no landed result; a row without runs.
tree none
rm "$res/summary.tsv"
refuse "no result: an error, no plan" "no result .*summary.tsv" env DPD_ROOT=$t "$plan"
tree norow
runs 1 1 3600; runs 3 1 1800
for q in drag torque; do for r in 1 2 3; do value ${q}_ratio_row$r 1.00 0.01; done; done
refuse "a row without runs: an error, no plan" "no runs of row 2" env DPD_ROOT=$t "$plan"

echo "$pass passed, $fail failed"
[ "$fail" = 0 ]

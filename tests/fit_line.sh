#!/bin/bash
# fit_line.sh - `dpd fit-line` (src/analysis/linefit.c, gsl_fit_wlinear / gsl_fit_wmul), used by the
# experiments for slopes of profiles and g(r): a noiseless line is returned exactly (slope,
# value at the range's centre, r2 = 1), over more rows than the first allocation (64); rows
# outside --range or with se <= 0 are skipped; --origin fits through (0, 0); fewer than 3
# usable rows, a missing column or file give a message and a non-zero exit, and no table.
# DPD selects the binary. Prints "N passed, M failed".
set -u
cd "$(dirname "$0")/.."
. tests/shlib.sh fit_line

# y = 0.1 + 2 x for x = 0, 0.001, ..., 0.999, se 0.01; one row with se = 0 and one outside the range
awk 'BEGIN { print "x\ty\tse"; for (i = 0; i < 1000; i++) printf "%.3f\t%.10g\t0.01\n", i / 1000, 0.1 + 2 * i / 1000
             print "0.5\t99\t0"; print "5\t99\t0.01" }' > "$tmp/line.tsv"
value() { awk -F'\t' -v q="$2" '$1 == q { print $2 }' "$1"; }
near() { awk -v a="$1" -v b="$2" -v t="$3" 'BEGIN { d = a - b; exit !(d < t && -d < t) }'; }

if "$DPD" fit-line "$tmp/line.tsv" --x x --y y --se se --range 0:1 > "$tmp/fit.tsv" 2> "$tmp/err"; then
    near "$(value "$tmp/fit.tsv" slope)" 2 1e-9 && ok "slope of a noiseless line" || bad "slope" "$(cat "$tmp/fit.tsv")"
    near "$(value "$tmp/fit.tsv" value_at_centre)" 1.1 1e-9 && ok "value at the centre of the range" || bad "value at centre" "$(cat "$tmp/fit.tsv")"
    near "$(value "$tmp/fit.tsv" r2)" 1 1e-12 && ok "r2 = 1" || bad "r2" "$(cat "$tmp/fit.tsv")"
    [ "$(value "$tmp/fit.tsv" points)" = 1000 ] && ok "1000 rows used (se = 0 and out-of-range rows skipped)" \
        || bad "points" "$(cat "$tmp/fit.tsv")"
else
    bad "fit-line on a 1000-row line" "$(cat "$tmp/err")"
fi
awk 'BEGIN { print "x\ty\tse"; for (i = 1; i <= 100; i++) printf "%d\t%.10g\t0.1\n", i, 3 * i }' > "$tmp/origin.tsv"
if "$DPD" fit-line "$tmp/origin.tsv" --x x --y y --se se --origin > "$tmp/fit.tsv" 2> "$tmp/err"; then
    near "$(value "$tmp/fit.tsv" slope)" 3 1e-9 && ok "--origin: slope through (0, 0)" || bad "--origin slope" "$(cat "$tmp/fit.tsv")"
else
    bad "fit-line --origin" "$(cat "$tmp/err")"
fi
refuse "two usable rows refused" "need at least 3" "$DPD" fit-line "$tmp/line.tsv" --x x --y y --se se --range 0.0005:0.0025
refuse "missing column named" "column 'z' not in the header" "$DPD" fit-line "$tmp/line.tsv" --x z --y y --se se
refuse "missing file named" "cannot open" "$DPD" fit-line "$tmp/none.tsv" --x x --y y --se se
refuse "bad range refused" "LO < HI" "$DPD" fit-line "$tmp/line.tsv" --x x --y y --se se --range 1:0
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]

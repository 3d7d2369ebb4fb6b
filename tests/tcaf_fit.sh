#!/bin/bash
# tcaf_fit.sh - `dpd tcaf-fit` (src/analysis/transverse_relaxation.c) on a synthetic tcaf.tsv in the
# simulator's layout: three shells n2 = 1, 2, 4 of a box L = 10 whose C/C0 are exact exponentials
# exp(-eta(k) k^2 t / rho) with eta(k) = 30 - 2 k^2 (rho = 4, lags every 0.01 to t = 2, se 0.01).
# Each model returns eta(k) per shell (exp and two-mode to the fit's tolerance, integral to the
# trapezoid rule's relative error dt^2 / (12 tau^2) < 1e-4) and eta(k -> 0) = 30 (degree 1 in
# k^2, exact); --kmax leaves out the shells above it; --table and --curves write their tables;
# a missing file, option or column, or a bad model, is refused with its message and no table.
# Several models in one call (--model a,b, files named through %m) give each model's own files.
# DPD selects the binary. Prints "N passed, M failed".
set -u
cd "$(dirname "$0")/.."
. tests/shlib.sh tcaf_fit

awk 'BEGIN { L = 10; rho = 4; split("1 2 4", n2, " ")
    printf "# C_perp(k,t)/C_perp(k,0) (synthetic)\nt"
    for (q = 1; q <= 3; q++) printf "\tc_n2_%d\tc_n2_%d_se", n2[q], n2[q]; printf "\n"
    for (l = 0; l <= 2000; l++) { t = l / 1000; printf "%.6g", t
        for (q = 1; q <= 3; q++) { k2 = (2 * 3.14159265358979 / L)^2 * n2[q]; eta = 30 - 2 * k2
            printf "\t%.10g\t%s", exp(-eta * k2 * t / rho), l ? "0.01" : "0" }
        printf "\n" } }' > "$tmp/tcaf.tsv"
value() { awk -F'\t' -v q="$2" '$1 == q { print $2 }' "$1"; }
near() { awk -v a="$1" -v b="$2" -v r="$3" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(d <= r * (b < 0 ? -b : b)) }'; }
want() { awk -v n2="$1" 'BEGIN { printf "%.12g", 30 - 2 * (2 * 3.14159265358979 / 10)^2 * n2 }'; }

for model in exp two-mode integral; do
    tol=1e-6; [ $model = integral ] && tol=1e-5
    if "$DPD" tcaf-fit "$tmp/tcaf.tsv" --rho 4 --box 10 --model $model --table "$tmp/t.tsv" --curves "$tmp/c.tsv" \
            > "$tmp/out" 2> "$tmp/err"; then
        good=1
        for n2 in 1 2 4; do near "$(value "$tmp/out" eta_n2_$n2)" "$(want $n2)" $tol || good=0; done
        [ $good = 1 ] && ok "$model: eta(k) of every shell" || bad "$model: eta(k)" "$(cat "$tmp/out")"
        near "$(value "$tmp/out" eta_k0)" 30 $tol && ok "$model: eta(k -> 0) of a law linear in k^2" \
            || bad "$model: eta_k0" "$(cat "$tmp/out")"
        [ "$(grep -vc '^#' "$tmp/t.tsv")" = 4 ] && head -1 "$tmp/t.tsv" | grep -q "by the $model model" \
            && ok "$model: --table, a header and three shells" || bad "$model: --table" "$(cat "$tmp/t.tsv")"
        # the fitted curve of the first shell at t = 1 against the exact exponential
        f=$(awk -F'\t' '$1 == "1" { print $2 }' "$tmp/c.tsv"); e=$(awk -F'\t' '$1 == "1" { print $2 }' "$tmp/tcaf.tsv")
        near "$f" "$e" 1e-4 && ok "$model: --curves, the fitted model" || bad "$model: --curves" "$f against $e"
    else
        bad "tcaf-fit --model $model" "$(cat "$tmp/err")"
    fi
done
"$DPD" tcaf-fit "$tmp/tcaf.tsv" --rho 4 --box 10 --model exp --kmax 0.9 > "$tmp/out" 2>&1
[ "$(value "$tmp/out" extrapolation_shells)" = 2 ] && ok "--kmax 0.9 keeps the shells n2 = 1, 2 (k = 0.63, 0.89)" \
    || bad "--kmax" "$(cat "$tmp/out")"
# several models from one fit: each model's files (--summary, --table, --curves through %m) are its
# own call's, byte for byte
# (on every tenth lag of the table: the same comparison at a tenth of the cost, which matters under ASan)
mkdir -p "$tmp/one" "$tmp/all"
awk '/^[#t]/ || (++n - 1) % 10 == 0' "$tmp/tcaf.tsv" > "$tmp/tenth.tsv"
for model in exp two-mode integral; do
    "$DPD" tcaf-fit "$tmp/tenth.tsv" --rho 4 --box 10 --model $model --table "$tmp/one/t_$model.tsv" \
        --curves "$tmp/one/c_$model.tsv" > "$tmp/one/s_$model.out"
done
if "$DPD" tcaf-fit "$tmp/tenth.tsv" --rho 4 --box 10 --model integral,exp,two-mode --table "$tmp/all/t_%m.tsv" \
        --curves "$tmp/all/c_%m.tsv" --summary "$tmp/all/s_%m.out" > "$tmp/out" 2> "$tmp/err"; then
    [ ! -s "$tmp/out" ] && diff -r "$tmp/one" "$tmp/all" > "$tmp/diff" && [ "$(ls "$tmp/all" | wc -l)" = 9 ] \
        && ok "--model integral,exp,two-mode: each model's summary, table and curves as its own call's" \
        || bad "--model with three models" "$(ls "$tmp/all"; cat "$tmp/diff")"
else
    bad "--model with three models" "$(cat "$tmp/err")"
fi
"$DPD" tcaf-fit "$tmp/tenth.tsv" --rho 4 --box 10 --model integral --summary "$tmp/s.out" > "$tmp/out" 2>&1
[ ! -s "$tmp/out" ] && cmp -s "$tmp/s.out" "$tmp/one/s_integral.out" && ok "--summary with one model: the rows there, none on stdout" \
    || bad "--summary with one model" "$(cat "$tmp/out")"
refuse "several models without --summary" "needs --summary" "$DPD" tcaf-fit "$tmp/tcaf.tsv" --rho 4 --box 10 --model two-mode,integral
refuse "several models, --summary without %m" "must name each model's file with %m" \
    "$DPD" tcaf-fit "$tmp/tcaf.tsv" --rho 4 --box 10 --model two-mode,integral --summary "$tmp/s.out"
refuse "several models, --table without %m" "--table '$tmp/t.tsv': with several models" \
    "$DPD" tcaf-fit "$tmp/tcaf.tsv" --rho 4 --box 10 --model two-mode,integral --summary "$tmp/s_%m.out" --table "$tmp/t.tsv"
refuse "a model twice" "integral twice" "$DPD" tcaf-fit "$tmp/tcaf.tsv" --rho 4 --box 10 --model integral,integral --summary "$tmp/s_%m.out"
refuse "an empty model in a list" "expected exp, two-mode or integral" "$DPD" tcaf-fit "$tmp/tcaf.tsv" --rho 4 --box 10 --model integral, --summary "$tmp/s_%m.out"
printf 'x\ty\n0\t1\n' > "$tmp/other.tsv"
refuse "missing file named" "cannot open" "$DPD" tcaf-fit "$tmp/none.tsv" --rho 4 --box 10
refuse "missing --rho refused" "usage" "$DPD" tcaf-fit "$tmp/tcaf.tsv" --box 10
refuse "unknown model refused" "expected exp, two-mode or integral" "$DPD" tcaf-fit "$tmp/tcaf.tsv" --rho 4 --box 10 --model three
refuse "not a tcaf.tsv" "expected the header of a tcaf.tsv" "$DPD" tcaf-fit "$tmp/other.tsv" --rho 4 --box 10
refuse "bad --order" "--order" "$DPD" tcaf-fit "$tmp/tcaf.tsv" --rho 4 --box 10 --order 1.5
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]

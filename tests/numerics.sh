#!/bin/bash
# numerics.sh - tools/lib/numerics.awk, the statistics of the experiments' analyses, through
# num_awk (tools/lib/numerics.sh): every function on inputs whose result is known in closed
# form. Tolerances: inputs of a few significant digits give results exact up to the roundings
# of at most ~20 operations, each within half an ulp (1.1e-16 relative), so a relative 1e-14
# holds every correct result and fails any wrong formula (a swapped n - 1, a missing square
# root, an unweighted fit, a different row order) by far more. Where the order of a sum or
# the form of a formula matters the expected value is the exact one and the wrong way's is
# off by O(1) (cancellation tests). Prints "N passed, M failed".
set -u
cd "$(dirname "$0")/.."
. tests/shlib.sh numerics
. tools/lib/numerics.sh

# is NAME GOT WANT [REL]: |GOT - WANT| <= REL |WANT| (default 1e-14; an absolute 1e-14 at 0),
# "nan" only for "nan"
is() {
    local rel=${4:-1e-14}
    if awk -v g="$2" -v w="$3" -v r="$rel" 'BEGIN {
            if (w "" == "nan" || g "" == "nan") exit !(w "" == g "")
            d = g - w; t = r * (w < 0 ? -w : w); if (t == 0) t = r
            exit !(d <= t && -d <= t) }'; then ok "$1"; else bad "$1" "got $2, want $3"; fi
}
# n PROGRAM: num_awk's output of a BEGIN-only program (%.17g: full precision)
n() { num_awk "BEGIN { $1 }"; }
# x EXPR: an expected value computed by plain awk, at full precision
x() { awk "BEGIN { printf \"%.17g\", $1 }"; }
# pair NAMES CALL WANT_VALUE WANT_ERROR: the value and the error that CALL leaves in o
pair() {
    local got; got=$(n "$2; printf \"%.17g %.17g\", o[\"v\"], o[\"se\"]")
    is "${1%%; *}" "${got% *}" "$3"; is "${1#*; }" "${got#* }" "$4"
}

# ---- formatting
is "num_fmt of a number" "$(n 'print num_fmt("%.3f", 1.5)')" 1.500
[ "$(n 'print num_fmt("%.3f", "nan")')" = nan ] && ok "num_fmt prints the string nan as nan" || bad "num_fmt nan" "$(n 'print num_fmt("%.3f", "nan")')"
got=$(n 'o["v"] = 1/3; o["se"] = 2/3; print num_row("q", o)')
[ "$got" = $'q\t0.3333333333\t0.6667' ] && ok "num_row: %.10g and %.4g" || bad "num_row" "$got"
[ "$(n 'v = num_set(o, 1.5, 0.25); print v, o["v"], o["se"]')" = "1.5 1.5 0.25" ] && ok "num_set fills o and returns the value" || bad "num_set" "$(n 'v = num_set(o, 1.5, 0.25); print v, o["v"], o["se"]')"
is "num_abs" "$(n 'print num_abs(-2.5) + num_abs(1)')" 3.5

# ---- means
is "num_mean of 1..4" "$(n 'x[1] = 1; x[2] = 2; x[3] = 3; x[4] = 4; printf "%.17g", num_mean(x, 4)')" 2.5
is "num_mean of nothing is nan" "$(n 'print num_mean(x, 0)')" nan
# 1..4: sample variance 5/3, standard error sqrt(5/3/4)
got=$(n 'x[1] = 1; x[2] = 2; x[3] = 3; x[4] = 4; num_mean_se(x, 4, o); printf "%.17g %.17g", o["v"], o["se"]')
is "num_mean_se: mean" "${got% *}" 2.5
is "num_mean_se: sd / sqrt(n)" "${got#* }" "$(awk 'BEGIN { printf "%.17g", sqrt(5 / 12) }')"
# the same shifted by 1e8: a one-pass variance (sum x^2 / n - mean^2) loses every digit here
got=$(n 'for (i = 1; i <= 4; i++) x[i] = 1e8 + i; num_mean_se(x, 4, o); printf "%.17g", o["se"]')
is "num_mean_se: two passes, no cancellation at an offset 1e8" "$got" "$(awk 'BEGIN { printf "%.17g", sqrt(5 / 12) }')"
is "num_mean_se: one value has no error" "$(n 'x[1] = 3; num_mean_se(x, 1, o); print o["se"]')" nan
# weights 1 and 4: (1 + 4 * 3) / 5, error 1 / sqrt(5); a row with se 0 is left out
got=$(n 'x[1] = 1; s[1] = 1; x[2] = 3; s[2] = 0.5; x[3] = 100; s[3] = 0; num_wmean_se(x, s, 3, o); printf "%.17g %.17g", o["v"], o["se"]')
is "num_wmean_se: weighted mean" "${got% *}" 2.6
is "num_wmean_se: 1 / sqrt(sum of weights)" "${got#* }" "$(awk 'BEGIN { printf "%.17g", 1 / sqrt(5) }')"
got=$(n 'x[1] = 1; s[1] = 3; x[2] = "nan"; s[2] = 1; x[3] = 2; s[3] = "nan"; num_wmean_se(x, s, 3, o); printf "%s %s", o["v"], o["se"]')
[ "$got" = "1 3" ] && ok "num_wmean_se: rows with a nan left out" || bad "num_wmean_se nan rows" "$got"
got=$(n 'x[1] = 1; s[1] = 0; num_wmean_se(x, s, 1, o); print o["v"] o["se"]')
[ "$got" = nannan ] && ok "num_wmean_se: no positive error gives nan" || bad "num_wmean_se nan" "$got"

# ---- combining values with errors
is "num_quad: 3, 4 -> 5" "$(n 'e[1] = 3; e[2] = 4; printf "%.17g", num_quad(e, 2)')" 5
got=$(n 'x[1] = 1; x[2] = -2; x[3] = 3; s[1] = 0.1; s[2] = 0.2; s[3] = 0.3; num_sum_linear(x, s, 3, o); printf "%.17g %.17g", o["v"], o["se"]')
is "num_sum_linear: value" "${got% *}" 2
is "num_sum_linear: errors added linearly" "${got#* }" 0.6
pair "num_sum: value; num_sum: quadrature" 'num_sum(5, 0.3, 3, 0.4, o)' 8 0.5
pair "num_diff: value; num_diff: quadrature" 'num_diff(5, 0.3, 3, 0.4, o)' 2 0.5
# 6 +- 5 % over 3 +- 4 %: 2 +- 2 sqrt(0.05^2 + 0.04^2); a negative ratio keeps a positive error
pair "num_ratio: value; num_ratio: relative errors in quadrature" 'num_ratio(6, 0.3, 3, 0.12, o)' 2 "$(x '2 * sqrt(0.0041)')"
pair "num_ratio: negative value; num_ratio: positive error" 'num_ratio(-6, 0.3, 3, 0.12, o)' -2 "$(x '2 * sqrt(0.0041)')"
pair "num_product: value; num_product: relative errors in quadrature" 'num_product(2, 0.1, 3, 0.3, o)' 6 "$(x '6 * sqrt(0.0125)')"
pair "num_rel2: the value given; num_rel2: its relative error" 'num_rel2(10, 2, 0.1, 3, 0.3, o)' 10 "$(x '10 * sqrt(0.0125)')"
pair "num_scale: value; num_scale: |factor| times the error" 'num_scale(2, 0.1, -3, o)' -6 0.3

pair "num_rel1: the value given; num_rel1: a's relative error" 'num_rel1(10, 4, 0.2, o)' 10 0.5
pair "num_relerr: the value given; num_relerr: relative errors in quadrature" 'r[1] = 0.03; r[2] = 0.04; num_relerr(-2, r, 2, o)' -2 0.1
# 2 / (4 +- 0.2): 0.5 +- 2 * 0.2 / 16
pair "num_inverse: c / a; num_inverse: c sa / a^2" 'num_inverse(2, 4, 0.2, o)' 0.5 0.025
pair "num_lin2: w1 a + w2 b; num_lin2: errors in quadrature" 'num_lin2(0.25, 8, 4, 0.75, 4, 4 / 3, o)' 5 "$(x 'sqrt(2)')"
pair "num_div: value; num_div: positive error" 'num_div(3, 0.3, -2, o)' -1.5 0.15
pair "num_sqrt: value; num_sqrt: sa / (2 sqrt a)" 'num_sqrt(16, 2, o)' 4 0.25
# num_sq is x * x in every awk: at this x mawk's x^2 (pow) differs from x * x in the last bit
got=$(n 'x = 45266225.18676623; printf "%d", num_sq(x) == x * x')
[ "$got" = 1 ] && ok "num_sq is x * x" || bad "num_sq" "differs from x * x"
is "num_uniform_se: (hi - lo) / sqrt(12)" "$(n 'printf "%.17g", num_uniform_se(1, 4)')" "$(awk 'BEGIN { printf "%.17g", 3 / sqrt(12) }')"
# leave-one-out estimates 1, 2, 3, 4: mean 2.5, error sqrt(3/4 * 5)
pair "num_jackknife_se: mean; num_jackknife_se: sqrt((n - 1) / n sum d^2)" 'x[1] = 1; x[2] = 2; x[3] = 3; x[4] = 4; num_jackknife_se(x, 4, o)' 2.5 "$(x 'sqrt(3.75)')"
is "num_jackknife_se: one estimate has no error" "$(n 'x[1] = 3; num_jackknife_se(x, 1, o); print o["se"]')" nan
is "num_project: (2, 4, 6.5) along (1, 2, 3)" "$(n 'x[1] = 2; x[2] = 4; x[3] = 6.5; w[1] = 1; w[2] = 2; w[3] = 3; printf "%.17g", num_project(x, w, 3)')" \
    "$(awk 'BEGIN { printf "%.17g", 29.5 / 14 }')"
is "num_project: along 0 is nan" "$(n 'x[1] = 1; w[1] = 0; print num_project(x, w, 1)')" nan
# 9, 10, 12 (mean 31/3): the largest deviation is 12's, 5/31, its error 0.4 / (31/3)
got=$(n 'x[1] = 9; x[2] = 10; x[3] = 12; s[1] = 0.1; s[2] = 0.2; s[3] = 0.4; num_max_rel_dev(x, s, 3, o); printf "%.17g %.17g", o["v"], o["se"]')
is "num_max_rel_dev: largest |x - mean| / mean" "${got% *}" "$(awk 'BEGIN { printf "%.17g", 5 / 31 }')"
is "num_max_rel_dev: that x's error / mean" "${got#* }" "$(awk 'BEGIN { printf "%.17g", 1.2 / 31 }')"

# a nan operand (a summary's nan, text) gives nan, never arithmetic on it (gawk reads it as 0)
for call in 'num_sum(1, 0.1, "nan", 0.2, o)' 'num_diff(1, "nan", 2, 0.2, o)' 'num_ratio(1, 0.1, "nan", "nan", o)' \
            'num_product("NaN", 0.1, 2, 0.2, o)' 'num_rel2(2, 1, 0.1, "-nan", 0.2, o)' 'num_rel1("nan", 1, 0.1, o)' \
            'num_inverse(2, "nan", 0.1, o)' 'num_lin2(0.5, 1, 0.1, 0.5, "nan", 0.1, o)' 'num_sqrt("nan", 1, o)' \
            'num_div(1, 0.1, "nan", o)' 'num_scale(1, "nan", 2, o)' 'r[1] = "nan"; num_relerr(1, r, 1, o)' \
            'x[1] = 1; x[2] = "nan"; num_mean_se(x, 2, o)' 'x[1] = 1; x[2] = "nan"; num_jackknife_se(x, 2, o)'; do
    got=$(n "$call; print num_pair(o)" 2>&1)
    [ "$got" = $'nan\tnan' ] && ok "nan operand: ${call%%(*}" || bad "nan operand: $call" "$got"
done
[ "$(n 'printf "%s %s", num_fmt("%.3f", "-nan"), num_isnan("NAN") + num_isnan("nano") * 2')" = "nan 1" ] &&
    ok "num_isnan: nan in any case and sign, nothing else" || bad "num_isnan" "$(n 'printf "%s %s", num_fmt("%.3f", "-nan"), num_isnan("NAN") + num_isnan("nano") * 2')"
got=$(n 'o["v"] = 2; o["se"] = 1/3; print num_pair(o, "%.2f", "%.1e")')
[ "$got" = $'2.00\t3.3e-01' ] && ok "num_pair: formats given" || bad "num_pair" "$got"

# ---- lines
# (0,0) (1,1) (2,1) (3,3): slope 0.9, intercept -0.1, residual sum of squares 0.7,
# slope error sqrt(0.7 / 2 * 4 / 20), intercept error sqrt(0.7 / 2 * 14 / 20)
pts='x[1] = 0; y[1] = 0; x[2] = 1; y[2] = 1; x[3] = 2; y[3] = 1; x[4] = 3; y[4] = 3'
got=$(n "$pts"'; num_line(x, y, 4, o); printf "%.17g %.17g %.17g %.17g %d", o["slope"], o["icpt"], o["slope_se"], o["icpt_se"], o["n"]')
read -r b a bs as np <<< "$got"
is "num_line: slope" "$b" 0.9; is "num_line: intercept" "$a" -0.1
is "num_line: slope error from the residuals" "$bs" "$(awk 'BEGIN { printf "%.17g", sqrt(0.07) }')"
is "num_line: intercept error from the residuals" "$as" "$(awk 'BEGIN { printf "%.17g", sqrt(0.245) }')"
[ "$np" = 4 ] && ok "num_line: points" || bad "num_line points" "$np"
got=$(n 'for (i = 1; i <= 10; i++) { x[i] = i; y[i] = 1 + 2 * i }; num_line(x, y, 10, o); printf "%.17g %.17g", o["slope"], o["slope_se"]')
is "num_line: an exact line" "${got% *}" 2; is "num_line: an exact line has no error" "${got#* }" 0
got=$(n 'x[1] = 0; y[1] = 0; x[2] = 1; y[2] = 2; num_line(x, y, 2, o); print o["slope"] " " o["slope_se"]')
[ "$got" = "2 nan" ] && ok "num_line: two points, slope without error" || bad "num_line two points" "$got"
got=$(n 'x[1] = 1; y[1] = 0; x[2] = 1; y[2] = 2; x[3] = 1; y[3] = 3; print num_line(x, y, 3, o)')
[ "$got" = nan ] && ok "num_line: equal x gives nan" || bad "num_line equal x" "$got"
# weights: a point of error 1/sqrt(2) counts as that point twice with error 1, so the
# weighted fit of (0,0) (1,1) (2,1 +- 0.707) (3,3) is the plain fit of five points:
# slope 22/26, intercept (6 - 8 * 22/26) / 5, errors sqrt(5/26) and sqrt(18/26)
got=$(n "$pts"'; for (i = 1; i <= 4; i++) s[i] = 1; s[3] = sqrt(0.5); x[5] = 9; y[5] = 99; s[5] = 0
    num_wline(x, y, s, 5, o); printf "%.17g %.17g %.17g %.17g %d", o["slope"], o["icpt"], o["slope_se"], o["icpt_se"], o["n"]')
read -r b a bs as np <<< "$got"
is "num_wline: slope" "$b" "$(awk 'BEGIN { printf "%.17g", 22 / 26 }')"
is "num_wline: intercept" "$a" "$(awk 'BEGIN { printf "%.17g", (6 - 8 * 22 / 26) / 5 }')"
is "num_wline: slope error from the weights" "$bs" "$(awk 'BEGIN { printf "%.17g", sqrt(5 / 26) }')"
is "num_wline: intercept error from the weights" "$as" "$(awk 'BEGIN { printf "%.17g", sqrt(18 / 26) }')"
[ "$np" = 4 ] && ok "num_wline: the row with error 0 left out" || bad "num_wline points" "$np"
got=$(n "$pts"'; for (i = 1; i <= 4; i++) s[i] = 1; x[5] = 9; y[5] = "nan"; s[5] = 1; x[6] = "nan"; y[6] = 1; s[6] = 1
    x[7] = 8; y[7] = 1; s[7] = "nan"; num_wline(x, y, s, 7, o); printf "%.17g %d", o["slope"], o["n"]')
is "num_wline: rows with a nan left out, slope" "${got% *}" 0.9
[ "${got#* }" = 4 ] && ok "num_wline: rows with a nan left out" || bad "num_wline nan rows" "$got"

# parabola: y = 1 - 2 x + 3 x^2 exactly at x = 0..4 (errors 1): c0 = 1; with unit errors the
# covariance of c0 is the (0, 0) element of the inverse of the normal matrix [[5, 10, 30],
# [10, 30, 100], [30, 100, 354]]: 620 / 700 (its cofactor over its determinant)
got=$(n 'for (i = 1; i <= 5; i++) { x[i] = i - 1; y[i] = 1 - 2 * x[i] + 3 * x[i] * x[i]; s[i] = 1 }
    num_wpoly2(x, y, s, 5, o); printf "%.17g %.17g", o["c0"], o["c0_se"]')
is "num_wpoly2: intercept of an exact parabola" "${got% *}" 1
is "num_wpoly2: its error from the normal matrix" "${got#* }" "$(awk 'BEGIN { printf "%.17g", sqrt(620 / 700) }')"
got=$(n 'for (i = 1; i <= 5; i++) { x[i] = i - 1; y[i] = 1 - 2 * x[i] + 3 * x[i] * x[i]; s[i] = 1 }; s[2] = 0.5; y[2] += 0.1
    num_wpoly2(x, y, s, 5, o); c = o["c0"]; for (i = 1; i <= 5; i++) s[i] *= 3; num_wpoly2(x, y, s, 5, o); printf "%.17g %.17g", c, o["c0"]')
is "num_wpoly2: weights scaled alike leave c0" "${got% *}" "${got#* }"
is "num_wpoly2: two points give nan" "$(n 'x[1] = 0; x[2] = 1; y[1] = 0; y[2] = 1; s[1] = s[2] = 1; print num_wpoly2(x, y, s, 2, o)')" nan
is "num_det3" "$(n 'printf "%.17g", num_det3(2, 0, 1, 1, 3, 2, 1, 1, 2)')" 6

# ---- interpolation: (1,10 +- 1) (2,20 +- 1) (4,0 +- 2) at 3 +- 0.5: 10, error
# sqrt((0.5 * 1)^2 + (0.5 * 2)^2 + (-10 * 0.5)^2)
tab='x[1] = 1; y[1] = 10; s[1] = 1; x[2] = 2; y[2] = 20; s[2] = 1; x[3] = 4; y[3] = 0; s[3] = 2'
got=$(n "$tab"'; num_interp(x, y, s, 3, 3, 0.5, o); printf "%.17g %.17g", o["v"], o["se"]')
is "num_interp: value" "${got% *}" 10; is "num_interp: error" "${got#* }" "$(awk 'BEGIN { printf "%.17g", sqrt(26.25) }')"
got=$(n "$tab"'; num_interp(x, y, s, 3, 2, 0, o); printf "%.17g %.17g", o["v"], o["se"]')
is "num_interp: at a node" "${got% *}" 20; is "num_interp: a node's error" "${got#* }" 1
got=$(n "$tab"'; num_interp(x, y, s, 3, 5, 0, o); print o["v"] o["se"]')
[ "$got" = nannan ] && ok "num_interp: outside the table gives nan" || bad "num_interp outside" "$got"

# crossing: y = 10, 20, 0 at x = 1, 2, 4 (errors 1, 1, 2) reaches 15 +- 1 at x = 1.5 (first pair);
# dx/dyq = 1/10, dx/dy1 = 1 * (15 - 20) / 100, dx/dy2 = -1 * (15 - 10) / 100
got=$(n "$tab"'; num_crossing(x, y, s, 3, 15, 1, o); printf "%.17g %.17g", o["v"], o["se"]')
is "num_crossing: the first crossing" "${got% *}" 1.5; is "num_crossing: error" "${got#* }" "$(awk 'BEGIN { printf "%.17g", sqrt(0.01 + 0.0025 + 0.0025) }')"
got=$(n "$tab"'; num_crossing(x, y, s, 3, 5, 1, o); printf "%.17g", o["v"]')
is "num_crossing: on the falling side" "$got" 3.5
got=$(n "$tab"'; num_crossing(x, y, s, 3, 25, 1, o); print o["v"] o["se"]')
[ "$got" = nannan ] && ok "num_crossing: never reached gives nan" || bad "num_crossing never" "$got"

# ---- blocks: rows of three blocks interleaved, each an exact line (slopes 2, 4, 9 and
# means 2, 3, 10 over x = 0, 1): mean slope 5, its error sd / sqrt(3) = sqrt(13 / 3); mean of
# the means 5, its error sqrt(19 / 3)
rows=$'7\t0\t1\n3\t0\t1\n7\t1\t3\n3\t1\t5\n1\t0\t5.5\n1\t1\t14.5'
got=$(printf '%s\n' "$rows" | num_awk -F'\t' '{ num_block_add($1, $2, $3) } END { num_block_slope(o); printf "%.17g %.17g", o["v"], o["se"] }')
is "num_block_slope: mean of the blocks' slopes" "${got% *}" 5
is "num_block_slope: their standard error" "${got#* }" "$(awk 'BEGIN { printf "%.17g", sqrt(13 / 3) }')"
got=$(printf '%s\n' "$rows" | num_awk -F'\t' '{ num_block_add($1, $2, $3) } END { num_block_mean(o); printf "%.17g %.17g", o["v"], o["se"] }')
is "num_block_mean: mean of the blocks' means" "${got% *}" 5
is "num_block_mean: their standard error" "${got#* }" "$(awk 'BEGIN { printf "%.17g", sqrt(19 / 3) }')"
got=$(printf '1\t0\t1\n1\t1\t2\n' | num_awk -F'\t' '{ num_block_add($1, $2, $3) } END { num_block_slope(o); print o["v"] o["se"] }')
[ "$got" = nannan ] && ok "num_block_slope: one block gives nan" || bad "one block" "$got"
# the order of the sum is the file's: block means 1e16, 1 (38 blocks), -1e16 in this order sum
# to 0 in double precision (1e16 + 1 rounds back to 1e16), and to a positive number in any order
# that does not put every 1 between the two; the 40 blocks' names are not in sorted order
got=$(awk 'BEGIN { for (b = 40; b >= 1; b--) { v = (b == 40) ? 1e16 : (b == 1) ? -1e16 : 1
                       printf "k%d\t0\t%.17g\n", b * 37 % 41, v } }' |
      num_awk -F'\t' '{ num_block_add($1, $2, $3) } END { num_block_mean(o); printf "%.17g", o["v"] * 40 }')
is "num_block_mean: blocks summed in the file's order" "$got" 0
got=$(printf '%s\n' "$rows" | num_awk -F'\t' '{ num_block_add($1, $2, $3) } END { for (j = 1; j <= NUM_NBLK; j++) printf "%s ", NUM_BLKS[j] }')
[ "$got" = "7 3 1 " ] && ok "num_block_add: blocks in the order of their first row" || bad "block order" "$got"

# ---- exp.sh's quoting helpers (issue 40 item 7: what paper.md says in words is a quantity the
# analysis writes): emit_pct, emit_minus, paper_number, in a scratch result directory
mkdir -p "$tmp/exp/res"
printf 'quantity\ttier\tkind\tlo\thi\tk_sigma\tresolution\tpaper\tsource\n' > "$tmp/exp/bands.tsv"
printf 'q\tpaper\tclaim\t1\t2\t-\t-\t1.5\tx\nq\treduced\tclaim\t1\t2\t-\t-\t1.25\tx\ng\tpaper\tgate\t1\t2\t-\t-\t9\tx\n' >> "$tmp/exp/bands.tsv"
expq() { ( cd "$tmp/exp" && DPD=true OUT="$tmp/exp/res" TIER=$1 DPD_ROOT="$OLDPWD" && export DPD OUT TIER DPD_ROOT && shift &&
           . "$DPD_ROOT/tools/lib/exp.sh" && "$@" ) 2> "$tmp/exp/err"; }
row() { awk -F'\t' -v q="$1" '$1 == q { print $2 " " $3 }' "$tmp/exp/res/summary.tsv"; }
expq reduced emit_pct p1 "$(printf '2.0\t0.1')" 1.6
got=$(row p1); is "emit_pct: 100 (a / b - 1) from an exact b" "${got% *}" 25; is "emit_pct: its error 100 se_a / b" "${got#* }" 6.25
expq reduced emit_pct p2 "$(printf '2\t0.1')" "$(printf '4\t0.2')"
got=$(row p2); is "emit_pct: a and b with errors" "${got% *}" -50; is "emit_pct: relative errors in quadrature" "${got#* }" "$(x '50 * sqrt(0.005)')" 1e-3
expq reduced emit_pct p3 "$(printf 'nan\t0.1')" 2
[ "$(row p3)" = "nan nan" ] && ok "emit_pct: a nan operand gives nan" || bad "emit_pct nan" "$(row p3)"
expq reduced emit_minus m1 "$(printf '2\t0.3')" "$(printf '1\t0.4')"
got=$(row m1); is "emit_minus: a - b" "${got% *}" 1; is "emit_minus: errors in quadrature" "${got#* }" 0.5
[ "$(expq reduced paper_number q)" = 1.25 ] && ok "paper_number: the claim row of the tier" || bad "paper_number reduced" "$(expq reduced paper_number q)"
[ "$(expq quick paper_number q)" = 1.5 ] && ok "paper_number: else the paper tier's" || bad "paper_number quick" "$(expq quick paper_number q)"
if expq paper paper_number g > /dev/null; then bad "paper_number: a gate has no paper number" "exit 0"
elif grep -q "no paper number for 'g' in bands.tsv" "$tmp/exp/err"; then ok "paper_number: a gate's row is refused, named"
else bad "paper_number: message" "$(cat "$tmp/exp/err")"; fi

# ---- num_awk passes awk's options and files through
got=$(printf 'a:4\n' | num_awk -F: -v k=2 -vj=3 '{ print $2 * k * j }')
[ "$got" = 24 ] && ok "num_awk: -F, -v VAR=VALUE and -vVAR=VALUE" || bad "num_awk options" "$got"
printf '1\n2\n' > "$tmp/f1"; printf '3\n' > "$tmp/f2"
got=$(num_awk '{ x[NR] = $1 } END { print num_mean(x, NR) }' "$tmp/f1" "$tmp/f2")
[ "$got" = 2 ] && ok "num_awk: files" || bad "num_awk files" "$got"
printf '{ x[NR] = $1 } END { print num_mean(x, NR) * k }\n' > "$tmp/prog.awk"
got=$(num_awk -v k=3 -f "$tmp/prog.awk" "$tmp/f1" "$tmp/f2")
[ "$got" = 6 ] && ok "num_awk: -f PROGFILE" || bad "num_awk -f" "$got"

# the same under each other awk installed (NUM_AWK: the library is meant to give the same
# numbers in any POSIX awk; mawk is Debian's default, gawk --posix the strictest at hand)
if [ -z "${NUM_AWK:-}" ]; then
    for a in gawk "gawk --posix" original-awk "busybox awk"; do
        command -v "${a%% *}" > /dev/null || continue
        [ "$a" != "busybox awk" ] || busybox awk 'BEGIN {}' 2> /dev/null || continue
        line=$(NUM_AWK=$a "$0" | tee /dev/stderr | tail -1)
        p=${line%% passed*}; f=${line#*, }; f=${f%% failed}
        echo "under $a: $line"; pass=$((pass + p)); fail=$((fail + ${f:-1}))
    done
fi
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]

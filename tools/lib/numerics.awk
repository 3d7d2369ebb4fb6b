# tools/lib/numerics.awk - the statistics of the experiments' analyses, in one place.
# Loaded before an analysis's own awk program by num_awk (tools/lib/numerics.sh):
#     num_awk -F'\t' 'PROGRAM calling num_* functions' FILE...
# POSIX awk (mawk, gawk, busybox). Every sum runs over indices 1..n in order, never
# `for (k in a)` (whose order awk leaves undefined): a result's rounding does not depend
# on the awk implementation. Tests: tests/numerics.sh (make test).
#
# Conventions. A sample is an array x[1..n] (se[1..n] for its errors). A function with
# one result returns it; one with a value and an error fills the array o: o["v"] and
# o["se"] (a fit: o["slope"], o["slope_se"], o["icpt"], o["icpt_se"], o["n"]) and returns
# o["v"] (the slope). An undefined result is the string "nan" (num_fmt and num_pair print it
# as nan whatever the awk). A "nan" operand (a summary's nan, read as text) makes the
# combinations of two values and the means "nan", as mawk's NaN arithmetic does, without
# computing with it: gawk reads the text nan as 0 (and stops on a division by it). The fits,
# interpolations and blocks take finite rows (their callers leave the nan rows out).
# Errors: first order, operands independent, unless said otherwise.
# Local variables are the extra parameters after the blank gap, as awk wants.

# num_fmt(FMT, X): X printed with FMT, "nan" for the text nan
function num_fmt(fmt, x) { return num_isnan(x) ? "nan" : sprintf(fmt, x) }
# num_pair(O[, VFMT, SEFMT]): "value<TAB>stderr" of O (default %.10g, %.4g: emit's convention)
function num_pair(o, vf, sf) {
    return num_fmt(vf == "" ? "%.10g" : vf, o["v"]) "\t" num_fmt(sf == "" ? "%.4g" : sf, o["se"])
}
# num_row(Q, O): the summary row "Q<TAB>value<TAB>stderr" of O
function num_row(q, o) { return q "\t" num_pair(o) }
# num_isnan(X): X is the text nan (any case and sign), a summary's undefined value
function num_isnan(x) { x = tolower(x ""); return x == "nan" || x == "-nan" || x == "+nan" }
# num_nan4(O, A, SA, B, SB): 1, with O set to nan, if an operand is nan
function num_nan4(o, a, sa, b, sb) {
    if (!(num_isnan(a) || num_isnan(sa) || num_isnan(b) || num_isnan(sb))) return 0
    num_set(o, "nan", "nan"); return 1
}
function num_abs(x) { return x < 0 ? -x : x }
# num_usable(V, SE): a value with a positive error, neither nan (a weighted fit's row)
function num_usable(v, se) { return !num_isnan(v) && !num_isnan(se) && se + 0 > 0 }
# num_sq(X): x * x (not x^2: mawk computes ^ with pow(), which this glibc rounds differently
# from x * x in the last bit for some x, and gawk multiplies: a square is the same everywhere)
function num_sq(x) { return x * x }
function num_set(o, v, se) { o["v"] = v; o["se"] = se; return v }

# num_mean(X, N): the arithmetic mean, "nan" for N < 1
function num_mean(x, n,    i, s) {
    if (n < 1) return "nan"
    for (i = 1; i <= n; i++) { if (num_isnan(x[i])) return "nan"; s += x[i] }
    return s / n
}
# num_mean_se(X, N, O): the mean and its standard error, sample standard deviation (two
# passes: no cancellation) / sqrt(N), for N independent values (runs, blocks, seeds);
# the error is "nan" for N < 2
function num_mean_se(x, n, o,    i, m, ss) {
    m = num_mean(x, n)
    if (n < 2 || m == "nan") return num_set(o, m, "nan")
    for (i = 1; i <= n; i++) ss += num_sq(x[i] - m)
    return num_set(o, m, sqrt(ss / (n - 1) / n))
}
# num_jackknife_se(X, N, O): X[1..N] the estimates leaving out one of N samples each: their
# mean and the jackknife error sqrt((N - 1) / N sum (x - mean)^2); "nan" for N < 2
function num_jackknife_se(x, n, o,    i, m, ss) {
    m = num_mean(x, n)
    if (n < 2 || m == "nan") return num_set(o, m, "nan")
    for (i = 1; i <= n; i++) ss += num_sq(x[i] - m)
    return num_set(o, m, sqrt((n - 1) / n * ss))
}
# num_project(X, W, N): the amplitude of X along W, sum x w / sum w^2 ("nan" for W = 0)
function num_project(x, w, n,    i, sxw, sww) {
    for (i = 1; i <= n; i++) { sxw += x[i] * w[i]; sww += w[i] * w[i] }
    return sww == 0 ? "nan" : sxw / sww
}
# num_max_rel_dev(X, SE, N, O): the largest |x - mean| / mean of X[1..N] (the first if tied),
# its error that x's SE / mean (the mean's own error neglected)
function num_max_rel_dev(x, se, n, o,    i, m, d, best, be) {
    m = num_mean(x, n)
    for (i = 1; i <= n; i++) { d = num_abs((x[i] - m) / m); if (d > best) { best = d; be = se[i] / m } }
    return num_set(o, best, be)
}
# num_wmean_se(X, SE, N, O): the inverse-variance weighted mean and its error
# 1 / sqrt(sum of the weights); values with an error <= 0 or nan are left out; "nan" when
# none is left
function num_wmean_se(x, se, n, o,    i, w, sw, swx) {
    for (i = 1; i <= n; i++) if (num_usable(x[i], se[i])) { w = 1 / num_sq(se[i]); sw += w; swx += w * x[i] }
    if (sw == 0) return num_set(o, "nan", "nan")
    return num_set(o, swx / sw, 1 / sqrt(sw))
}
# num_sum_linear(X, SE, N, O): the sum of X[1..N] with the errors added linearly (fully
# correlated operands, or an upper bound)
function num_sum_linear(x, se, n, o,    i, v, e) {
    for (i = 1; i <= n; i++) { v += x[i]; e += se[i] }
    return num_set(o, v, e)
}
# num_quad(E, N): the errors E[1..N] added in quadrature
function num_quad(e, n,    i, s) { for (i = 1; i <= n; i++) s += num_sq(e[i]); return sqrt(s) }

# two values with errors (a +- sa, b +- sb) into one
function num_sum(a, sa, b, sb, o) {
    if (num_nan4(o, a, sa, b, sb)) return "nan"
    return num_set(o, a + b, sqrt(num_sq(sa) + num_sq(sb)))
}
function num_diff(a, sa, b, sb, o) {
    if (num_nan4(o, a, sa, b, sb)) return "nan"
    return num_set(o, a - b, sqrt(num_sq(sa) + num_sq(sb)))
}
# num_rel2(X, A, SA, B, SB, O): X, a product or quotient of powers +-1 of a and b, whose
# relative error is a's and b's in quadrature
function num_rel2(x, a, sa, b, sb, o) {
    if (num_nan4(o, a, sa, b, sb) || num_nan4(o, x, 0, 0, 0)) return "nan"
    return num_set(o, x, num_abs(x) * sqrt(num_sq(sa / a) + num_sq(sb / b)))
}
function num_ratio(a, sa, b, sb, o) {
    if (num_nan4(o, a, sa, b, sb)) return "nan"
    return num_rel2(a / b, a, sa, b, sb, o)
}
function num_product(a, sa, b, sb, o) {
    if (num_nan4(o, a, sa, b, sb)) return "nan"
    return num_rel2(a * b, a, sa, b, sb, o)
}
# num_relerr(X, R, N, O): X with the relative errors R[1..N] in quadrature
function num_relerr(x, r, n, o,    i) {
    for (i = 1; i <= n; i++) if (num_nan4(o, x, r[i], 0, 0)) return "nan"
    return num_set(o, x, num_abs(x) * num_quad(r, n))
}
# num_rel1(X, A, SA, O): X, a power +-1 of a times an exact factor, with a's relative error
function num_rel1(x, a, sa, o) {
    if (num_nan4(o, x, a, sa, 0)) return "nan"
    return num_set(o, x, num_abs(x) * sa / num_abs(a))
}
# num_inverse(C, A, SA, O): c / a for an exact c, error |c| sa / a^2
function num_inverse(c, a, sa, o) {
    if (num_nan4(o, c, a, sa, 0)) return "nan"
    return num_set(o, c / a, num_abs(c) * sa / num_sq(a))
}
# num_lin2(W1, A, SA, W2, B, SB, O): w1 a + w2 b for exact weights, errors in quadrature
function num_lin2(w1, a, sa, w2, b, sb, o) {
    if (num_nan4(o, a, sa, b, sb)) return "nan"
    return num_set(o, w1 * a + w2 * b, sqrt(num_sq(w1 * sa) + num_sq(w2 * sb)))
}
# num_sqrt: sqrt(a +- sa), error sa / (2 sqrt(a))
function num_sqrt(a, sa, o,    r) {
    if (num_nan4(o, a, sa, 0, 0)) return "nan"
    r = sqrt(a); return num_set(o, r, 0.5 * sa / r)
}
# num_div: (a +- sa) / c for an exact c (a theory, a unit)
function num_div(a, sa, c, o) {
    if (num_nan4(o, a, sa, c, 0)) return "nan"
    return num_set(o, a / c, sa / num_abs(c))
}
# num_scale: f (a +- sa) for an exact factor f
function num_scale(a, sa, f, o) {
    if (num_nan4(o, a, sa, f, 0)) return "nan"
    return num_set(o, a * f, sa * num_abs(f))
}

# num_line(X, Y, N, O): unweighted least-squares line y = icpt + slope x; the errors from
# the residuals (N - 2 degrees of freedom; "nan" for N < 3); "nan" for N < 2 or equal x
function num_line(x, y, n, o,    i, sx, sy, sxx, sxy, d, b, a, r) {
    o["n"] = n
    for (i = 1; i <= n; i++) { sx += x[i]; sy += y[i]; sxx += x[i] * x[i]; sxy += x[i] * y[i] }
    d = n * sxx - num_sq(sx)
    if (n < 2 || d == 0) { o["slope"] = o["icpt"] = o["slope_se"] = o["icpt_se"] = "nan"; return "nan" }
    b = (n * sxy - sx * sy) / d; a = (sy - b * sx) / n
    o["slope"] = b; o["icpt"] = a
    if (n < 3) { o["slope_se"] = o["icpt_se"] = "nan"; return b }
    for (i = 1; i <= n; i++) r += num_sq(y[i] - a - b * x[i])
    o["slope_se"] = sqrt(r / (n - 2) * n / d); o["icpt_se"] = sqrt(r / (n - 2) * sxx / d)
    return b
}
# num_wline(X, Y, SE, N, O): the weighted (1 / SE^2) least-squares line; the errors from
# SE (not from the scatter), as a chi-square fit with known errors; rows with SE <= 0 or a
# nan are left out; "nan" for fewer than 2 rows or equal x
function num_wline(x, y, se, n, o,    i, w, sw, sx, sy, sxx, sxy, d, b, m) {
    for (i = 1; i <= n; i++) if (num_usable(y[i], se[i]) && !num_isnan(x[i])) {
        w = 1 / num_sq(se[i]); m++
        sw += w; sx += w * x[i]; sy += w * y[i]; sxx += w * x[i] * x[i]; sxy += w * x[i] * y[i]
    }
    o["n"] = m
    d = sw * sxx - num_sq(sx)
    if (m < 2 || d == 0) { o["slope"] = o["icpt"] = o["slope_se"] = o["icpt_se"] = "nan"; return "nan" }
    b = (sw * sxy - sx * sy) / d
    o["slope"] = b; o["icpt"] = (sy - b * sx) / sw
    o["slope_se"] = sqrt(sw / d); o["icpt_se"] = sqrt(sxx / d)
    return b
}

# num_wpoly2(X, Y, SE, N, O): the weighted (1 / SE^2) least-squares parabola
# y = c0 + c1 x + c2 x^2 (Cramer's rule on the normal equations); o["c0"] and its error
# o["c0_se"] from the inverse of the normal matrix; "nan" for fewer than 3 points
function num_wpoly2(x, y, se, n, o,    i, w, p, xp, S, B, D) {
    for (i = 1; i <= n; i++) {
        w = 1 / num_sq(se[i]); xp = 1
        for (p = 0; p <= 4; p++) { S[p] += w * xp; if (p <= 2) B[p] += w * y[i] * xp; xp *= x[i] }
    }
    D = num_det3(S[0], S[1], S[2], S[1], S[2], S[3], S[2], S[3], S[4])
    if (n < 3 || D == 0) { o["c0"] = o["c0_se"] = "nan"; return "nan" }
    o["c0"] = num_det3(B[0], S[1], S[2], B[1], S[2], S[3], B[2], S[3], S[4]) / D
    o["c0_se"] = sqrt((S[2] * S[4] - S[3] * S[3]) / D)
    return o["c0"]
}
function num_det3(a11, a12, a13, a21, a22, a23, a31, a32, a33) {
    return a11 * (a22 * a33 - a23 * a32) - a12 * (a21 * a33 - a23 * a31) + a13 * (a21 * a32 - a22 * a31)
}
# num_uniform_se(LO, HI): the standard deviation of a value known only to lie in [LO, HI]
# (uniform: (HI - LO) / sqrt(12)), e.g. a threshold between two rungs of a ladder
function num_uniform_se(lo, hi) { return (hi - lo) / sqrt(12) }

# num_interp(X, Y, SE, N, XQ, XQSE, O): Y (tabulated at increasing X[1..N]) at XQ, linear
# between the two bracketing points; the error from theirs (weights 1 - f, f) and, through
# the local slope, from XQ's; "nan" outside [X[1], X[N]]
function num_interp(x, y, se, n, xq, xqse, o,    i, f, b) {
    for (i = 1; i < n; i++) if (x[i] <= xq && xq <= x[i + 1]) {
        f = (xq - x[i]) / (x[i + 1] - x[i]); b = (y[i + 1] - y[i]) / (x[i + 1] - x[i])
        return num_set(o, (1 - f) * y[i] + f * y[i + 1],
                       sqrt(num_sq((1 - f) * se[i]) + num_sq(f * se[i + 1]) + num_sq(b * xqse)))
    }
    return num_set(o, "nan", "nan")
}

# num_crossing(X, Y, SE, N, YQ, YQSE, O): the x where the tabulated Y (at increasing X[1..N])
# first reaches YQ, linear between the two bracketing points (the first pair from X[1]);
# the errors of YQ and of the two points' Y propagated to first order (the x exact);
# "nan" when Y never reaches YQ
function num_crossing(x, y, se, n, yq, yqse, o,    i, f, dx, dy, e) {
    for (i = 1; i < n; i++) if ((y[i] - yq) * (y[i + 1] - yq) <= 0 && y[i] != y[i + 1]) {
        f = (yq - y[i]) / (y[i + 1] - y[i]); dx = x[i + 1] - x[i]; dy = y[i + 1] - y[i]
        # d x / d yq, d y[i], d y[i + 1]
        e[1] = dx / dy * yqse; e[2] = dx * (yq - y[i + 1]) / num_sq(dy) * se[i]; e[3] = -dx * (yq - y[i]) / num_sq(dy) * se[i + 1]
        return num_set(o, x[i] + f * (x[i + 1] - x[i]), num_quad(e, 3))
    }
    return num_set(o, "nan", "nan")
}

# Blocks. num_block_add(K, X, Y) collects the point (X, Y) of block K (rows read in any
# order); the blocks are kept in the order of their first row, so the statistics below
# sum them in the file's order.
function num_block_add(k, x, y) {
    if (!((k, 0) in NUM_BLK)) { NUM_BLK[k, 0] = 0; NUM_BLKS[++NUM_NBLK] = k }
    NUM_BLK[k, 0]++
    NUM_BLK[k, "x", NUM_BLK[k, 0]] = x; NUM_BLK[k, "y", NUM_BLK[k, 0]] = y
}
# num_block_slope(O): each block's straight-line slope (num_line), then their mean and
# standard error (num_mean_se: the blocks as independent samples); "nan" for fewer than
# 2 blocks
function num_block_slope(o,    j, i, k, m, x, y, l, s) {
    for (j = 1; j <= NUM_NBLK; j++) {
        k = NUM_BLKS[j]; m = NUM_BLK[k, 0]
        for (i = 1; i <= m; i++) { x[i] = NUM_BLK[k, "x", i]; y[i] = NUM_BLK[k, "y", i] }
        s[j] = num_line(x, y, m, l)
    }
    if (NUM_NBLK < 2) return num_set(o, "nan", "nan")
    return num_mean_se(s, NUM_NBLK, o)
}
# num_block_mean(O): each block's mean of y, then their mean and standard error
function num_block_mean(o,    j, i, k, m, y, s) {
    for (j = 1; j <= NUM_NBLK; j++) {
        k = NUM_BLKS[j]; m = NUM_BLK[k, 0]
        for (i = 1; i <= m; i++) y[i] = NUM_BLK[k, "y", i]
        s[j] = num_mean(y, m)
    }
    if (NUM_NBLK < 2) return num_set(o, "nan", "nan")
    return num_mean_se(s, NUM_NBLK, o)
}

# growth.awk - start-up of the Couette profile from per-block profiles of
# independent runs: block, t, pos, vx of each run's profile_blocks.tsv (vx_blocks.tsv.gz),
# concatenated, each run starting with its header line.
#   -v ts=T     steady profile = run-averaged profile over blocks with t >= T
#   -v name=Q   summary rows t90_Q and the growth/profile tables
#   -v out=DIR  where growth_Q.tsv and profiles_Q.tsv go
# a(t) = sum_y v(y,t) v_s(y) / sum_y v_s(y)^2 (projection on the steady profile);
# t90 = first time a reaches 0.9, linear interpolation between block times,
# from a = 0 at t = 0 (walls start). Error: jackknife over the runs.
BEGIN { FS = OFS = "\t" }
$1 == "block" { S++; next }
$4 == "nan" || $4 == "" { next }
{ b = $1 + 0; y = $3; v[S, b, y] = $4; t[b] = $2; bins[y] = 1; if (b > nb) nb = b }
function t90_without(ex,    s, b, y, n, m, num, den, vs, a, ap, tp) {
    for (y in bins) vs[y] = 0
    n = 0
    for (b = 0; b <= nb; b++) if (t[b] >= ts) { n++; for (y in bins) { m = 0; for (s = 1; s <= S; s++) if (s != ex) m += v[s, b, y]; vs[y] += m / (S - (ex > 0)) } }
    for (y in bins) vs[y] /= n
    ap = 0; tp = 0
    for (b = 0; b <= nb; b++) {
        num = den = 0
        for (y in bins) { m = 0; for (s = 1; s <= S; s++) if (s != ex) m += v[s, b, y]; m /= (S - (ex > 0)); num += m * vs[y]; den += vs[y] * vs[y]; prof[b, y] = m }
        a = num / den; A[b] = a
        if (a >= 0.9 && ap < 0.9) return tp + (t[b] - tp) * (0.9 - ap) / (a - ap)
        ap = a; tp = t[b]
    }
    return -1
}
END {
    full = t90_without(0)
    f = out "/growth_" name ".tsv"; print "t", "a" > f
    for (b = 0; b <= nb; b++) { t90_without(0); break }
    # growth curve of the full ensemble (recomputed: t90_without stops at the crossing)
    for (y in bins) vs2[y] = 0
    n = 0
    for (b = 0; b <= nb; b++) if (t[b] >= ts) { n++; for (y in bins) { m = 0; for (s = 1; s <= S; s++) m += v[s, b, y]; vs2[y] += m / S } }
    for (y in bins) vs2[y] /= n
    for (b = 0; b <= nb; b++) {
        num = den = 0
        for (y in bins) { m = 0; for (s = 1; s <= S; s++) m += v[s, b, y]; m /= S; P[b, y] = m; num += m * vs2[y]; den += vs2[y] * vs2[y] }
        print t[b], num / den > f
    }
    # profiles nearest t = 2, 4, ..., 20 and the steady one
    f = out "/profiles_" name ".tsv"
    hdr = "pos"; for (k = 2; k <= 20; k += 2) { best = 0; for (b = 0; b <= nb; b++) if ((t[b] - k)^2 < (t[best] - k)^2) best = b; pick[k] = best; hdr = hdr OFS "t" k }
    print hdr, "steady" > f
    ny = 0; for (y in bins) ys[++ny] = y + 0
    for (i = 1; i <= ny; i++) for (j = i + 1; j <= ny; j++) if (ys[j] < ys[i]) { q = ys[i]; ys[i] = ys[j]; ys[j] = q }
    for (i = 1; i <= ny; i++) { line = ys[i]; for (k = 2; k <= 20; k += 2) line = line OFS P[pick[k], ys[i]]; print line, vs2[ys[i]] > f }
    # jackknife over runs
    se = 0
    if (S > 1) {
        mj = 0; for (s = 1; s <= S; s++) { tj[s] = t90_without(s); mj += tj[s] / S }
        for (s = 1; s <= S; s++) se += (tj[s] - mj)^2
        se = sqrt((S - 1) / S * se)
    }
    printf "t90_%s\t%.6g\t%.4g\n", name, full, se
}

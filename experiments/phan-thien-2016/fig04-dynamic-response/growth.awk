# growth.awk - start-up of the Couette profile from per-block profiles of
# independent runs: block, t, pos, vx of each run's profile_blocks.tsv (vx_blocks.tsv.gz),
# concatenated, each run starting with its header line. Run with num_awk
# (tools/lib/numerics.sh: num_mean, num_project, num_jackknife_se).
#   -v ts=T     steady profile = run-averaged profile over blocks with t >= T
#   -v name=Q   summary rows t90_Q and the growth/profile tables
#   -v out=DIR  where growth_Q.tsv and profiles_Q.tsv go
# a(t) = sum_y v(y,t) v_s(y) / sum_y v_s(y)^2 (projection on the steady profile);
# t90 = first time a reaches 0.9, linear interpolation between block times,
# from a = 0 at t = 0 (walls start). Error: jackknife over the runs.
# The bins are summed in the order of their first row (not `for (y in ...)`, whose order
# awk leaves undefined).
BEGIN { FS = OFS = "\t" }
$1 == "block" { S++; next }
$4 == "nan" || $4 == "" { next }
{ b = $1 + 0; y = $3; v[S, b, y] = $4; t[b] = $2; if (b > nb) nb = b
  if (!(y in bins)) { bins[y] = 1; Y[++ny] = y } }
# profile(B, EX, M): block B's profile averaged over the runs but EX (0: all) into M[1..ny]
function profile(b, ex, m,    j, s, k, x) {
    for (j = 1; j <= ny; j++) { k = 0; for (s = 1; s <= S; s++) if (s != ex) x[++k] = v[s, b, Y[j]]; m[j] = num_mean(x, k) }
}
# growth(EX, A): a(t) of the runs but EX into A[0..nb]; with EX = 0 the steady profile and
# the block profiles are kept (STEADY[j], PROF[b, j]) for the tables
function growth(ex, a,    b, j, n, m, vs) {
    for (j = 1; j <= ny; j++) vs[j] = 0
    for (b = 0; b <= nb; b++) if (t[b] >= ts) { n++; profile(b, ex, m); for (j = 1; j <= ny; j++) vs[j] += m[j] }
    for (j = 1; j <= ny; j++) { vs[j] /= n; if (!ex) STEADY[j] = vs[j] }
    for (b = 0; b <= nb; b++) {
        profile(b, ex, m); a[b] = num_project(m, vs, ny)
        if (!ex) for (j = 1; j <= ny; j++) PROF[b, j] = m[j]
    }
}
# t90(A): the first time A reaches 0.9 (linear between block times, from 0 at t = 0); -1: never
function t90(a,    b, ap, tp) {
    for (b = 0; b <= nb; b++) {
        if (a[b] >= 0.9 && ap < 0.9) return tp + (t[b] - tp) * (0.9 - ap) / (a[b] - ap)
        ap = a[b]; tp = t[b]
    }
    return -1
}
END {
    growth(0, a); full = t90(a)
    f = out "/growth_" name ".tsv"; print "t", "a" > f
    for (b = 0; b <= nb; b++) print t[b], a[b] > f
    # profiles nearest t = 2, 4, ..., 20 and the steady one, by position
    f = out "/profiles_" name ".tsv"
    hdr = "pos"; for (k = 2; k <= 20; k += 2) { best = 0; for (b = 0; b <= nb; b++) if ((t[b] - k)^2 < (t[best] - k)^2) best = b; pick[k] = best; hdr = hdr OFS "t" k }
    print hdr, "steady" > f
    for (i = 1; i <= ny; i++) ord[i] = i
    for (i = 1; i <= ny; i++) for (j = i + 1; j <= ny; j++) if (Y[ord[j]] + 0 < Y[ord[i]] + 0) { q = ord[i]; ord[i] = ord[j]; ord[j] = q }
    for (i = 1; i <= ny; i++) { line = Y[ord[i]] + 0; for (k = 2; k <= 20; k += 2) line = line OFS PROF[pick[k], ord[i]]; print line, STEADY[ord[i]] > f }
    # jackknife over runs
    se = 0
    if (S > 1) { for (s = 1; s <= S; s++) { growth(s, aj); tj[s] = t90(aj) }; num_jackknife_se(tj, S, o); se = o["se"] }
    printf "t90_%s\t%.6g\t%.4g\n", name, full, se
}

# bands.awk -- evaluate one experiment's bands.tsv against one summary.tsv.
# POSIX awk (works with mawk and gawk).  Run by tools/check (make check), whose --tsv rows
# give the paper its verdicts (tools/check --verdicts, tools/lib/paper-filter.lua).
#
# usage: awk -v eid=ID -v tier=T -v sfile=PATH_OR_EMPTY -f bands.awk bands.tsv
#   sfile empty or unreadable -> every row MISSING (NOTRUN with -v notrun=1: a tier never run).
#
# bands.tsv: a header line naming the columns (any order); one row per quantity and tier:
#   quantity tier kind lo hi k_sigma resolution paper source [expect]
# kind (the decision rule, README "How to read a result"):
#   claim       a number or shape a paper states (or theory, with a stated tolerance). [lo, hi] is
#               the paper's number with its tolerance, never widened by the run's error; k_sigma
#               and resolution are "-". With the run's standard error se:
#                 PASS        the whole interval value +- 2 se lies inside [lo, hi]
#                 FAIL        it lies wholly outside
#                 UNRESOLVED  otherwise: the run cannot decide (column 15: the factor by which the
#                             run must grow, (2 se / d)^2, d = the value's distance to the nearest
#                             edge, assuming the value stays and se falls as 1/sqrt(run length)).
#               A standard error that is not a number (nan, inf, empty) decides nothing: UNRESOLVED.
#   gate        a check that the set-up is right (temperature, equipartition, spring extension,
#               force balance, conservation, symmetry). Two forms:
#                 range  lo < hi (or one side infinite), k_sigma and resolution "-": the claims'
#                        rule (value +- 2 se inside);
#                 exact  lo = hi = the exact value: PASS when |value - exact| <= k_sigma se and
#                        se <= resolution; UNRESOLVED when se > resolution (column 15: (se / res)^2).
#               A gate that does not pass makes the result invalid: tools/check fails on it.
#   regression  an exact gate against a committed reference of the tier itself (lo = hi = the
#               reference; the source names the commit it was taken from), to catch a regression
#               where the tier cannot decide the paper's claim. Never enters a verdict.
# expect = fail (claims only): a paper's claim already established not to reproduce and reported
#   in paper.md: FAIL shows as XFAIL, PASS as XPASS (tools/check fails: review the row).
#
# Output, one line per band row of the tier, tab-separated:
#   1 eid  2 quantity  3 value  4 stderr  5 lo  6 hi  7 k_sigma  8 paper  9 outcome  10 dist
#   11 source  12 note  13 kind  14 resolution  15 decide (run-length factor, or "-")
# outcome: PASS | FAIL | UNRESOLVED | XFAIL | XPASS | MISSING | NOTRUN | BAD (the row breaks the format)
# dist: the value's position relative to the band (for exact gates: relative to +- k se):
#   two-sided |value - mid| / half-width; one-sided 0 inside, else 1 + excess / |bound|
#   (a bound of 0: / the band's k se, or se, or 1); "inf" for a non-finite value; "-" when MISSING.
# A bands row whose tier column is "*" or "any" applies to every tier.

function trim(s) { sub(/^[ \t\r]+/, "", s); sub(/[ \t\r]+$/, "", s); return s }
function isnum(s) { return s ~ /^[+-]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][+-]?[0-9]+)?$/ }
function isneginf(s) { s = tolower(s); return s == "-inf" || s == "-infinity" }
function isposinf(s) { s = tolower(s); return s == "inf" || s == "+inf" || s == "infinity" || s == "+infinity" }
function absf(x) { return x < 0 ? -x : x }
function col(name) { return (name in C) ? trim($(C[name])) : "" }
function emit(verdict, dist, note, decide) {
    printf "%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n", \
        eid, q, v_s, se_s, slo, shi, sk, paper, verdict, dist, src, note, kind, sres, decide
}
# a row that breaks the format: BAD (tools/check fails; no verdict is drawn from it)
function bad(note) { v_s = (q in sval) ? sval[q] : "-"; se_s = (q in sval) ? sse[q] : "-"; emit("BAD", "inf", note, "-") }
# distance of v from [lo, hi] widened by w (lofree / hifree: that side open)
function distance(v, lo, hi, w,    h, s) {
    if (lofree && hifree) return 0
    if (!lofree && !hifree) {
        h = (hi - lo) / 2 + w
        if (h > 0) return absf(v - (lo + hi) / 2) / h
        return (v == lo) ? 0 : "inf"
    }
    if (!lofree) { if (v >= lo - w) return 0; s = absf(lo) > 1e-300 ? absf(lo) : (w > 0 ? w : 1); return 1 + (lo - w - v) / s }
    if (v <= hi + w) return 0
    s = absf(hi) > 1e-300 ? absf(hi) : (w > 0 ? w : 1)
    return 1 + (v - hi - w) / s
}
function fmt3(d) { return (d == "inf") ? d : sprintf("%.3g", d) }

BEGIN {
    FS = "\t"
    have = 0
    if (sfile != "") {
        first = 1
        while ((rc = (getline line < sfile)) > 0) {
            have = 1
            sub(/\r$/, "", line)
            if (line ~ /^[ \t]*$/ || line ~ /^[ \t]*#/) continue
            n = split(line, f, "\t")
            qq = trim(f[1])
            if (first) { first = 0; if (qq == "quantity") continue }
            if (qq in sval) continue             # first occurrence wins
            sval[qq] = (n >= 2) ? trim(f[2]) : ""
            sse[qq]  = (n >= 3) ? trim(f[3]) : "nan"
        }
        if (rc == 0) have = 1                   # readable (maybe empty) file
        close(sfile)
    }
}

{ sub(/\r$/, "") }
FNR == 1 {
    for (i = 1; i <= NF; i++) C[trim($i)] = i
    if (!("k_sigma" in C) && ("k" in C)) C["k_sigma"] = C["k"]
    for (i = split("quantity tier kind lo hi k_sigma resolution paper source", need, " "); i >= 1; i--)
        if (!(need[i] in C)) missing_cols = missing_cols " " need[i]
    next
}
/^[ \t]*$/ || /^[ \t]*#/ { next }

{
    q = col("quantity"); t = col("tier"); kind = tolower(col("kind")); slo = col("lo"); shi = col("hi")
    sk = col("k_sigma"); sres = col("resolution"); paper = col("paper"); src = col("source")
    expect = tolower(col("expect"))
    if (paper == "") paper = "-"
    if (t != tier && t != "*" && t != "any") next
    v_s = "-"; se_s = "-"
    if (missing_cols != "") { bad("bands.tsv header lacks the column(s)" missing_cols); next }

    if (!have)        { emit((notrun ? "NOTRUN" : "MISSING"), "-", (why != "" ? why : "no summary.tsv"), "-"); next }
    if (!(q in sval)) { emit("MISSING", "-", "quantity absent from summary.tsv", "-"); next }
    v_s = sval[q]; se_s = sse[q]

    # ---- the row itself
    if (kind != "claim" && kind != "gate" && kind != "regression") { bad("bad kind '" kind "' in bands.tsv (claim, gate or regression)"); next }
    if (expect == "fail" && kind != "claim") { bad("expect = fail marks a paper's claim, never a " kind); next }
    lofree = isneginf(slo); hifree = isposinf(shi)
    if ((!lofree && !isnum(slo)) || (!hifree && !isnum(shi)) || (!lofree && !hifree && slo + 0 > shi + 0)) { bad("bad lo/hi in bands.tsv"); next }
    if (lofree && hifree) { bad("a band open on both sides tests nothing"); next }
    exact = (!lofree && !hifree && slo + 0 == shi + 0)
    if (kind == "claim" && exact) { bad("a claim needs a band of nonzero width (the paper's tolerance)"); next }
    if (kind == "regression" && !exact) { bad("a regression reference is one value: lo = hi"); next }
    if (exact) {
        if (!isnum(sk) || sk + 0 < 0) { bad("bad k_sigma in bands.tsv (an exact gate needs k >= 0)"); next }
        if (!(isnum(sres) && sres + 0 > 0) && !(sres == "-" && sk + 0 == 0)) { bad("bad resolution in bands.tsv (an exact gate needs se <= resolution > 0, or k = 0)"); next }
    } else if ((sk != "-" && sk != "") || (sres != "-" && sres != "")) {
        bad("k_sigma and resolution are '-' for a band of nonzero width: it is never widened"); next
    }

    # ---- the value
    if (!isnum(v_s)) { emit(expect == "fail" ? "XFAIL" : "FAIL", "inf", expect == "fail" ? "known non-reproduction; value not finite" : "value not finite", "-"); next }
    v = v_s + 0
    known = isnum(se_s); se = known ? absf(se_s + 0) : 0

    if (exact) {
        k = sk + 0; w = k * se; x = slo + 0
        d = distance(v, x, x, w)
        if (!known && sk + 0 > 0) { emit("UNRESOLVED", fmt3(d), "no standard error: the gate cannot be decided", "inf"); next }
        if (sres != "-" && se > sres + 0) {
            emit("UNRESOLVED", fmt3(d), "stderr above the resolution " sres ": the tier cannot decide this gate", sprintf("%.3g", (se / sres) * (se / sres))); next
        }
        emit(absf(v - x) <= w ? "PASS" : "FAIL", fmt3(d), "", "-")
        next
    }

    # claims and range gates: value +- 2 se against the band as it stands
    d = distance(v, slo + 0, shi + 0, 0)
    if (!known) { out = "UNRESOLVED"; note = "no standard error: nothing decided" }
    else {
        a = v - 2 * se; b = v + 2 * se
        inside = (lofree || a >= slo + 0) && (hifree || b <= shi + 0)
        outside = (!lofree && b < slo + 0) || (!hifree && a > shi + 0)
        out = inside ? "PASS" : outside ? "FAIL" : "UNRESOLVED"; note = ""
    }
    decide = "-"
    if (out == "UNRESOLVED") {
        if (!known) decide = "inf"
        else {
            e = -1
            if (!lofree) e = absf(v - slo)
            if (!hifree && (e < 0 || absf(shi - v) < e)) e = absf(shi - v)
            decide = (e > 0) ? sprintf("%.3g", (2 * se / e) * (2 * se / e)) : "inf"
        }
        if (note == "") note = "value +- 2 se straddles a band edge: the run cannot decide"
    }
    if (expect == "fail") {
        if (out == "PASS") { out = "XPASS"; note = "known non-reproduction now passes: review bands.tsv" }
        else if (out == "FAIL") { out = "XFAIL"; note = "known non-reproduction" }
        else note = note "; known non-reproduction"
    }
    emit(out, fmt3(d), note, decide)
}

# verdict.awk -- one experiment's verdict from its evaluated band rows (lib/bands.awk output on
# stdin), one TSV line: id tier verdict claims_pass claims_fail claims_unresolved claims_missing
# gates_pass gates_total regressions_pass regressions_total decide worst cpu_seconds.
# usage: ... | awk -F '\t' -v id=ID -v t=TIER -v cpu=SECONDS -f verdict.awk   (run by tools/check --verdicts)
#
# The verdict counts the claims only (issue 37; README "How to read a result"):
#   invalid     a gate failed, could not be decided (its se above its resolution) or is missing:
#               the result is not evidence either way, whatever its claims say
#   [Re]        every claim PASS            [¬Re]  every claim FAIL (XFAIL counts as FAIL)
#   [~Re]       some claims PASS and some FAIL (others may be unresolved)
#   unresolved  otherwise: no claim shown false and not all shown, or none shown either way
#   missing     a claim's value is absent (the result does not hold the quantity), or XPASS
#   bad bands   a row of bands.tsv breaks the format (BAD)
#   gates only  the experiment states no claim at this tier
# Regression references (kind regression) never enter a verdict.
# decide: the largest run-length factor over the unresolved claims (bands.awk column 15).
# worst: the largest distance (column 10) over the claims.
{
    kind = $13; o = $9
    if (o == "BAD") { nbad++; next }
    if (kind == "regression") { rt++; if (o == "PASS") rp++; next }
    if (kind == "gate") { gt++; if (o == "PASS") gp++; next }
    if (o == "NOTRUN") { notrun++; next }
    n++
    if (o == "PASS") cp++
    else if (o == "FAIL" || o == "XFAIL") cf++
    else if (o == "UNRESOLVED") {
        cu++
        if ($15 == "inf") dinf = 1; else if ($15 != "-" && $15 + 0 > decide) decide = $15 + 0
    } else cm++                                 # MISSING, XPASS (a row to review) or a bad row
    if ($10 == "inf" || $10 == "-") inf = 1; else if ($10 + 0 > worst) worst = $10 + 0
}
END {
    if (nbad > 0) v = "bad bands"
    else if (n == 0 && gt == 0 && rt == 0) v = notrun ? "not run" : "no bands for tier " t
    else if (gp < gt) v = "invalid"
    else if (cm > 0) v = "missing"
    else if (n == 0) v = "gates only"
    else if (cp == n) v = "[Re]"
    else if (cf == n) v = "[¬Re]"
    else if (cp > 0 && cf > 0) v = "[~Re]"
    else v = "unresolved"
    printf "%s\t%s\t%s\t%d\t%d\t%d\t%d\t%d\t%d\t%d\t%d\t%s\t%s\t%s\n", id, t, v, cp, cf, cu, cm, gp, gt, rp, rt,
        dinf ? "inf" : (cu ? sprintf("%.3g", decide) : "-"), n ? (inf ? "inf" : sprintf("%.3g", worst + 0)) : "-", cpu
}

# verdict.awk -- one experiment's verdict from its evaluated band rows (lib/bands.awk output on
# stdin), one TSV line: id tier verdict claims_pass claims_fail claims_unresolved claims_missing
# gates_pass gates_total regressions_pass regressions_total decide worst cpu_seconds.
# usage: ... | awk -F '\t' -v id=ID -v t=TIER -v cpu=SECONDS -f verdict.awk   (run by tools/check --verdicts)
# Before issue 37 every row counted as a claim: [Re] all rows PASS, [~Re] (p/n) some, [¬Re] (0/n) none.
{ n++; if ($9 == "PASS") p++
  if ($10 == "inf" || $10 == "-") inf = 1; else if ($10 + 0 > worst) worst = $10 + 0 }
END {
    if (n == 0) { printf "%s\t%s\tno bands for tier %s\t0\t0\t0\t0\t0\t0\t0\t0\t-\t-\t%s\n", id, t, t, cpu; exit }
    v = (p == n) ? "[Re]" : (p > 0) ? sprintf("[~Re] (%d/%d)", p, n) : sprintf("[¬Re] (0/%d)", n)
    printf "%s\t%s\t%s\t%d\t%d\t0\t0\t0\t0\t0\t0\t-\t%s\t%s\n", id, t, v, p, n - p, inf ? "inf" : sprintf("%.3g", worst + 0), cpu
}

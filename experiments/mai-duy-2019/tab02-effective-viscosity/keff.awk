# keff.awk - the TCAF construction of Mai-Duy et al. 2019, section 4.2.3: the
# free system's k at which eta_free(k) equals the constrained eta(k -> 0).
# usage: num_awk -F'\t' -v ec=ETA -v se=SE -v tag=TAG -f keff.awk free/tcaf_eta.tsv
# (num_awk: tools/lib/numerics.sh)
# k_eff by linear interpolation of the free eta(k) between the two shells that
# bracket ETA (the first such pair from k -> 0; num_crossing); the errors of ETA and
# of the two shells (independent) propagated to first order. eta_eff = ETA (Table 2's
# "effective eta" is the constrained eta(k -> 0) by construction). No crossing:
# k_eff = lambda_eff = nan.
/^#/ || $1 == "k" { next }
$4 != "nan" { n++; k[n] = $1; v[n] = $4; s[n] = $5 }
END {
    num_crossing(k, v, s, n, ec, se, o)
    printf "k_eff_%s\t%s\t%s\n", tag, num_fmt("%.10g", o["v"]), num_fmt("%.4g", o["se"])
    if (o["v"] != "nan") num_inverse(2 * 3.14159265358979, o["v"], o["se"], o)
    printf "lambda_eff_%s\t%s\t%s\n", tag, num_fmt("%.10g", o["v"]), num_fmt("%.4g", o["se"])
    printf "eta_eff_%s\t%.10g\t%.4g\n", tag, ec, se
}

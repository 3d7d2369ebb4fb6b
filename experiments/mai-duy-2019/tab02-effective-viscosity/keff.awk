# keff.awk - the TCAF construction of Mai-Duy et al. 2019, section 4.2.3: the
# free system's k at which eta_free(k) equals the constrained eta(k -> 0).
# usage: awk -F'\t' -v ec=ETA -v se=SE -v tag=TAG -f keff.awk free/tcaf_eta.tsv
# k_eff by linear interpolation of the free eta(k) between the two shells that
# bracket ETA (the first such pair from k -> 0); the errors of ETA and of the two
# shells (independent) propagated to first order. eta_eff = ETA (Table 2's
# "effective eta" is the constrained eta(k -> 0) by construction). No crossing:
# k_eff = lambda_eff = nan.
/^#/ || $1 == "k" { next }
$4 != "nan" { n++; k[n] = $1; v[n] = $4; s[n] = $5 }
END {
    pi = 3.14159265358979
    for (i = 1; i < n; i++) if ((v[i] - ec) * (v[i + 1] - ec) <= 0 && v[i] != v[i + 1]) {
        f = (ec - v[i]) / (v[i + 1] - v[i]); ke = k[i] + f * (k[i + 1] - k[i])
        dk = k[i + 1] - k[i]; den = v[i + 1] - v[i]
        d_e = dk / den; d_1 = dk * (ec - v[i + 1]) / den ^ 2; d_2 = -dk * (ec - v[i]) / den ^ 2
        sk = sqrt((d_e * se) ^ 2 + (d_1 * s[i]) ^ 2 + (d_2 * s[i + 1]) ^ 2)
        printf "k_eff_%s\t%.10g\t%.4g\n", tag, ke, sk
        printf "lambda_eff_%s\t%.10g\t%.4g\n", tag, 2 * pi / ke, 2 * pi * sk / ke ^ 2
        found = 1; break
    }
    if (!found) printf "k_eff_%s\tnan\tnan\nlambda_eff_%s\tnan\tnan\n", tag, tag
    printf "eta_eff_%s\t%.10g\t%.4g\n", tag, ec, se
}

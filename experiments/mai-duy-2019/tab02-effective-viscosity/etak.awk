# etak.awk - eta_free(k) at k = 2 pi / lambda by linear interpolation between
# the two shells of a tcaf_eta.tsv that bracket k (error: the shells' errors
# weighted by the interpolation, in quadrature); nan outside the measured shells.
# usage: awk -F'\t' -v lambda=L -v name=NAME -f etak.awk tcaf_eta.tsv
/^#/ || $1 == "k" { next }
$4 != "nan" { n++; k[n] = $1; v[n] = $4; s[n] = $5 }
END {
    q = 2 * 3.14159265358979 / lambda
    for (i = 1; i < n; i++) if (k[i] <= q && q <= k[i + 1]) {
        f = (q - k[i]) / (k[i + 1] - k[i])
        printf "%s\t%.10g\t%.4g\n", name, (1 - f) * v[i] + f * v[i + 1], sqrt(((1 - f) * s[i]) ^ 2 + (f * s[i + 1]) ^ 2)
        exit
    }
    printf "%s\tnan\tnan\n", name
}

# etak.awk - eta_free(k) at k = 2 pi / lambda by linear interpolation between
# the two shells of a tcaf_eta.tsv that bracket k (num_interp; error: the shells'
# errors weighted by the interpolation, in quadrature); nan outside the measured shells.
# usage: num_awk -F'\t' -v lambda=L -v name=NAME -f etak.awk tcaf_eta.tsv
# (num_awk: tools/lib/numerics.sh)
/^#/ || $1 == "k" { next }
$4 != "nan" { n++; k[n] = $1; v[n] = $4; s[n] = $5 }
END { num_interp(k, v, s, n, 2 * 3.14159265358979 / lambda, 0, o); print num_row(name, o) }

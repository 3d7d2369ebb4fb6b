# fields.awk - eq. 49 density residual and mean |div u| from a density map
# (density_map.tsv: x y density vx vy, one block per grid row), over the bins
# whose centre lies at least rex from the cylinder centre (cx, cy).
# usage: num_awk -v L=6 -v cx=3 -v cy=3 -v rex=1 -v n0=4 -f fields.awk density_map.tsv
BEGIN { FS = "\t"; row = 0; col = 0 }
NR == 1 { next }
NF == 0 { if (col > 0) { nx = col; row++ }; col = 0; next }
{ X[col, row] = $1; Y[col, row] = $2; N[col, row] = $3; U[col, row] = $4; V[col, row] = $5; col++ }
END {
    if (col > 0) { nx = col; row++ }
    ny = row; dx = L / nx; dy = L / ny
    nb = 0; ss = 0; sdiv = 0
    for (j = 0; j < ny; j++) for (i = 0; i < nx; i++) {
        ddx = X[i, j] - cx; ddy = Y[i, j] - cy
        ddx -= L * int(ddx / L * 2); ddy -= L * int(ddy / L * 2)   # minimum image (|d| < L)
        if (ddx * ddx + ddy * ddy < rex * rex) continue
        ip = (i + 1) % nx; im = (i + nx - 1) % nx; jp = (j + 1) % ny; jm = (j + ny - 1) % ny
        div = (U[ip, j] - U[im, j]) / (2 * dx) + (V[i, jp] - V[i, jm]) / (2 * dy)
        ss += num_sq(N[i, j] - n0); sdiv += num_abs(div); nb++
    }
    printf "%.10g\t%.10g\t%d\n", sqrt(ss) / nb, sdiv / nb, nb                     # eq. 49
}

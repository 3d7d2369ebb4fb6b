# Fig. 12 of Phan-Thien et al. 2016: relative viscosity of massless spring colloids
# against the area fraction, with Brady's 2D 1 + 2 phi (eq. 53) and the fitted slope.
load '../../plot-style.gp'
set terminal @PNG size 1400,960
set output out.'/relative-viscosity-'.tier.'.png'
g(q) = system("awk -F'\t' '$1==\"".q."\"{print $2}' ".res."/summary.tsv") + 0
s = g("eta_r_slope")
set title "Relative viscosity, 6 x 6 box, Lees-Edwards shear rate 1, m = 0 (tier: ".tier.")"
set xlabel "phi = 3k / (144 + 3k)"; set ylabel "eta_r"; set key top left
set xrange [0:0.16]
# the claim's band on the slope: 1 + s phi for s in [lo, hi], shaded
slo = PAPER_AT("^eta_r_slope$", 3); shi = PAPER_AT("^eta_r_slope$", 4)
plot '+' u 1:(1 + slo * $1):(1 + shi * $1) w filledcurves fs transparent solid 0.18 noborder lc rgb '#c62828' t sprintf("paper: slope 2 (eq. 53), the band [%g, %g]", slo, shi), \
     res.'/eta_r.tsv' u 2:5:6 skip 1 w yerrorbars ls OURS t "this package", \
     1 + 2 * x w l lw 2 t "Brady 2D, eq. 53: 1 + 2 phi", \
     (x <= 0.06 ? 1 + s * x : 1/0) w l dt 2 t sprintf("fit through (0, 1), phi <= 0.06: slope %.2f", s)

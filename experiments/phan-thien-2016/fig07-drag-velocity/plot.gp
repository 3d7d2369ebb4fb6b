# Fig. 7 of Phan-Thien et al. 2016: drag on the cylinder against the mean
# velocity, with Hasimoto's eq. 47 from the measured eta and exclusion radius.
load '../../plot-style.gp'
set terminal @PNG size 1400,960
set output out.'/drag-velocity-'.tier.'.png'
set title "Drag on a 4-particle cylinder, periodic array h = 6, m = 0 (tier: ".tier.")"
set xlabel "mean fluid velocity U"; set ylabel "drag F"; set key top left
g(q) = system("awk -F'\t' '$1==\"".q."\"{print $2}' ".res."/summary.tsv") + 0
eta = g("eta_solvent"); a = g("exclusion_radius")
F(U) = 4 * pi * eta * U / (log(6.0 / a) - 1.3105)
F25(U) = 4 * pi * eta * U / (log(6.0 / 0.25) - 1.3105)
stats res.'/drag.tsv' u 4 skip 1 nooutput; set xrange [0:STATS_max * 1.05]; set yrange [0:*]
rlo = PAPER_AT("^hasimoto_ratio_", 3); rhi = PAPER_AT("^hasimoto_ratio_", 4)
plot '+' u 1:(rlo * F(x)):(rhi * F(x)) w filledcurves fs transparent solid 0.15 noborder lc rgb '#c62828' t sprintf("the band of the claim at P = 0.1: eq. 47 x [%g, %g]", rlo, rhi), \
     res.'/drag.tsv' u 4:2:5:3 skip 1 w xyerrorbars ls OURS t "this package", \
     F(x) w l lw 2 t sprintf("eq. 47, eta = %.3f, a = %.3f (measured exclusion radius)", eta, a), \
     F25(x) w l dt 2 t "eq. 47 with the paper's a = 0.25"

# eta(k) of the solvent from transverse current autocorrelation functions
# (Mai-Duy et al. 2019, eqs 22-28, Fig. 1).
load '../../plot-style.gp'
set terminal @PNG size 2000,880
set output out.'/eta-vs-k-'.tier.'.png'
rho = 4.0
array K[4]; array E[4]; array S[4]
do for [q=1:4] {
    stats res.'/tcaf_eta.tsv' every ::q::q u 1:4 nooutput
    K[q] = STATS_max_x; E[q] = STATS_max_y
}
# the package's k -> 0 fit (summary.tsv): eta(k) = eta_0 + eta_2 k^2 for k <= 2 (extrapolate_kmax)
stats res.'/summary.tsv' u (strcol(1) eq "eta_k0" ? $2 : NaN) nooutput
eta0 = STATS_max
stats res.'/summary.tsv' u (strcol(1) eq "eta_k2_coefficient" ? $2 : NaN) nooutput
eta2 = STATS_max
stats res.'/summary.tsv' u (strcol(1) eq "eta_k0" ? $3 : NaN) nooutput
eta0se = STATS_max
set multiplot layout 1,2 title "Transverse current autocorrelation and eta(k), a = 3.53 (tier: ".tier.")"
set xlabel "t"; set ylabel "C_{perp}(k,t) / C_{perp}(k,0)"; set logscale y; set yrange [0.02:1.2]; set xrange [0:1]
set key top right
plot for [q=1:4] res.'/tcaf.tsv' u 1:(column(2*q)):(column(2*q+1)) every 2 w yerrorbars pt 7 ps 0.8 lc q \
         t sprintf("k = %.3f", K[q]), \
     for [q=1:4] exp(-E[q] * K[q]**2 * x / rho) w l lc q dt 2 notitle, \
     0.3 w l lc rgb "gray" dt 3 t "fit window ends (C/C0 = 0.3)"
unset logscale y; set yrange [*:*]; set xrange [0:*]
set xlabel "k"; set ylabel "eta(k)"; set key bottom left; set xrange [-0.1:*]
plot res.'/tcaf_eta.tsv' u 1:4:5 w yerrorbars pt 7 lc rgb "#6a8fd0" t "TCAF, this package (eq. 28)", \
     '+' u (0):(eta0):(eta0se) every ::0::0 w yerrorbars ls OURS t "eta(k -> 0), this package", \
     PAPER_POINTS("^eta_k0$") u (0.08):2:3:4 w yerrorbars ls PAPER t "eta(k -> 0): the band (5 %)", \
     [0:2] eta0 + eta2 * x**2 w l lw 2 t sprintf("k -> 0 fit: %.2f %+.3f k^2", eta0, eta2), \
     'paper-table2.tsv' u 1:2 w p pt 6 ps 2.6 t "paper, Table 2 (free-system eta at k_eff)", \
     29.32 w l dt 2 lc rgb "black" t "Lees-Edwards shear, sec43 (29.32)"
unset multiplot

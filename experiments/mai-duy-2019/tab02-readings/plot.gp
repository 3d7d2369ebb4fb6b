# Mai-Duy et al. 2019, Table 2 and the TCAF eta_r of Figs 4-5 under five readings of section 4.2.3
# (README.md), and the constrained eta(k -> 0) by three estimators beside the suspension's viscosity.
load '../../plot-style.gp'
set terminal @PNG_BARE size 3000,1800 noenhanced font 'Sans,15'
set output out.'/readings-'.tier.'.png'
set multiplot layout 2,3 title "Table 2 and Figs 4-5 under five readings of section 4.2.3 (tier: ".tier.")"
p2 = '../tab02-effective-viscosity/paper-table2.tsv'
d = res.'/readings_data.tsv'
set xrange [0:0.52]; set xlabel "phi"
set key top left
set ylabel "eta_eff (a = 3.53)"; set logscale y
plot PAPER_POINTS("^reading_a_eta_eff_phi") u ($1 + 0.006):2:3:4 w yerrorbars ls PAPER t "Table 2, ".PAPER_TITLE, \
     for [i = 0:4] d index i u 2:5:6 w yerrorlines pt 5 + 2 * i lc i + 1 t "(".word("a b c d e", i + 1).")"
unset logscale y
set ylabel "k_eff (a = 3.53)"
plot PAPER_POINTS("^reading_a_k_eff_phi") u ($1 + 0.006):2:3:4 w yerrorbars ls PAPER t "Table 2, ".PAPER_TITLE, \
     for [i = 0:4] d index i u 2:3:4 w yerrorlines pt 5 + 2 * i lc i + 1 t "(".word("a b c d e", i + 1).")"
set ylabel "TCAF eta_r, a = 3.53"; set logscale y
plot (1 - x / 0.65)**-2 w l lc rgb "gray50" t "Quemada, eq. 34", \
     PAPER_POINTS("^reading_a_eta_r_a3.53_phi") u ($1 + 0.006):2:3:4 w yerrorbars ls PAPER t "paper, TCAF (0.49), ± tolerance", \
     for [i = 0:4] d index i u 2:7:8 w yerrorlines pt 5 + 2 * i lc i + 1 t "(".word("a b c d e", i + 1).")"
set ylabel "TCAF eta_r, a = 6.50"
plot (1 - x / 0.65)**-2 w l lc rgb "gray50" t "Quemada, eq. 34", \
     PAPER_POINTS("^reading_a_eta_r_a6.50_phi") u ($1 + 0.006):2:3:4 w yerrorbars ls PAPER t "paper, TCAF (0.49), ± tolerance", \
     for [i = 0:4] d index i u 2:9:10 w yerrorlines pt 5 + 2 * i lc i + 1 t "(".word("a b c d e", i + 1).")"
e = res.'/estimators_data.tsv'
set ylabel "eta(k -> 0), a = 3.53"
plot e index 0 u 2:3:4 w lp pt 7 lc rgb "black" t "suspension, shear (rate 0.1)", \
     e index 0 u 2:5:6 w yerrorlines pt 4 lc 1 t "constrained: exp (eq. 28, C/C0 >= 0.3)", \
     e index 0 u 2:7:8 w yerrorlines pt 6 lc 2 t "constrained: slow mode, rho of the particles", \
     e index 0 u 2:9:10 w yerrorlines pt 5 lc 3 t "constrained: integral", \
     e index 0 u 2:11:12 w yerrorlines pt 8 lc 4 dt 2 t "free: exp"
unset logscale y
set xrange [0:2]; set xlabel "t"; set ylabel "C(k,t) / C(k,0), smallest k, phi = 0.4940"; set key top right
c = res.'/curve_phi0.4940.tsv'
plot c skip 1 u 1:2:3 w yerrorbars pt 7 ps 0.8 lc 3 t "constrained (particles)", \
     c skip 1 u 1:4 w l lw 2 lc rgb "black" t "two-mode fit", \
     c skip 1 u 1:5 w l lc 1 t "free (same density)", \
     0.3 w l dt 3 lc rgb "gray50" t "C/C0 = 0.3 (eq. 28 fit window)"
unset multiplot

# eta_r(phi = 0.49) of the spring-model suspension against the shear rate, a = 6.50 and 3.53,
# with the paper's values at Pe = 0.18 (Mai-Duy et al. 2019, sec. 4.4) as horizontal lines.
load '../../plot-style.gp'
set terminal @PNG size 1400,960
set output out.'/eta-r-vs-rate-'.tier.'.png'
set title sprintf("eta_r(phi = 0.49) against the shear rate (tier: %s)", tier)
set xlabel "shear rate"; set ylabel "eta_r"; set logscale x; set xrange [0.005:0.2]; set key top right
plot res.'/eta_r.tsv' u ($1 == 6.50 ? $2 : 1/0):3:4 skip 1 w yerrorlines pt 7 lc 1 t "a = 6.50", \
     res.'/eta_r.tsv' u ($1 == 3.53 ? $2 : 1/0):3:4 skip 1 w yerrorlines pt 5 lc 2 t "a = 3.53", \
     6.69 w l dt 2 lc 1 t "paper, a = 6.50, Pe = 0.18", \
     5.17 w l dt 2 lc 2 t "paper, a = 3.53, Pe = 0.18"

# Stability map: every trial run (stable: filled green; stopped as unstable: red
# cross) and the bisected largest stable dt with its bracket, against gamma (two
# weight exponents s), the repulsion a, the mass m (and the m = 0 solver), and the
# spring stiffness H of a massless 2D colloid.
load '../../plot-style.gp'
set terminal @PNG size 2200,1640
set output out.'/stability-map-'.tier.'.png'
set datafile missing "nan"
t = res.'/trials.tsv'; d = res.'/dt-max.tsv'
is(f) = strcol(1) eq f
set multiplot layout 2,2 title "Largest stable dt (tier: ".tier."; stable = no blow-up detected, T <= 2 kBT)"
set logscale xy; set format y "10^{%T}"; set grid; set key bottom left font ",16"
set xlabel "gamma"; set ylabel "dt"
plot t u (is("gamma_s2") && $6==1 ? $3 : 1/0):5 w p pt 7 ps 1 lc rgb "#a0d0a0" t "stable trial", \
     t u (is("gamma_s2") && $6==0 ? $3 : 1/0):5 w p pt 2 ps 1 lc rgb "#e0a0a0" t "unstable trial", \
     t u ((is("gas_s2") || is("gas_s0.5") || is("gamma_s0.5")) && $6==1 ? $3*1.08 : 1/0):5 w p pt 7 ps 1 lc rgb "#a0d0a0" notitle, \
     t u ((is("gas_s2") || is("gas_s0.5") || is("gamma_s0.5")) && $6==0 ? $3*1.08 : 1/0):5 w p pt 2 ps 1 lc rgb "#e0a0a0" notitle, \
     d u (is("gamma_s2") ? $3 : 1/0):4:5 w yerrorlines pt 7 lc 1 t "fluid a = 25, s = 2", \
     d u (is("gamma_s0.5") ? $3 : 1/0):4:5 w yerrorlines pt 5 lc 2 t "fluid a = 25, s = 0.5", \
     d u (is("gas_s2") ? $3 : 1/0):4:5 w yerrorlines pt 6 dt 2 lc 1 t "gas a = 0, s = 2", \
     d u (is("gas_s0.5") ? $3 : 1/0):4:5 w yerrorlines pt 4 dt 2 lc 2 t "gas a = 0, s = 0.5", \
     [100:*] 1/x dt 3 lc rgb "gray" t "slope -1"
set xlabel "repulsion a (gamma = 4.5, s = 2)"
plot t u (is("a_gamma4.5") && $6==1 ? $3 : 1/0):5 w p pt 7 ps 1 lc rgb "#a0d0a0" t "stable trial", \
     t u (is("a_gamma4.5") && $6==0 ? $3 : 1/0):5 w p pt 2 ps 1 lc rgb "#e0a0a0" t "unstable trial", \
     d u (is("a_gamma4.5") ? $3 : 1/0):4:5 w yerrorlines pt 7 lc 1 t "dt_{max}", \
     [50:*] 1/sqrt(x) dt 2 lc rgb "gray" t "slope -1/2"
set xlabel "mass m (2D Phan-Thien fluid)"
m0 = 0; m0lo = 0; m0hi = 0
stats d u (is("mass_m0") ? $4 : 1/0) nooutput; m0 = STATS_max
plot t u (is("mass") && $6==1 ? $3 : 1/0):5 w p pt 7 ps 1 lc rgb "#a0d0a0" t "stable trial", \
     t u (is("mass") && $6==0 ? $3 : 1/0):5 w p pt 2 ps 1 lc rgb "#e0a0a0" t "unstable trial", \
     d u (is("mass") ? $3 : 1/0):4:5 w yerrorlines pt 7 lc 1 t "dt_{max}, velocity Verlet", \
     m0 w l lw 2 lc 3 t "dt_{max}, m = 0 solver", [*:0.3] x dt 2 lc rgb "gray" t "slope 1"
set xlabel "spring stiffness H (massless 2D colloid, m = 0)"
plot t u (is("spring_m0") && $6==1 ? $3 : 1/0):5 w p pt 7 ps 1 lc rgb "#a0d0a0" t "stable trial", \
     t u (is("spring_m0") && $6==0 ? $3 : 1/0):5 w p pt 2 ps 1 lc rgb "#e0a0a0" t "unstable trial", \
     d u (is("spring_m0") ? $3 : 1/0):4:5 w yerrorlines pt 7 lc 1 t "dt_{max}", \
     [3000:*] 10/x dt 2 lc rgb "gray" t "slope -1"
unset multiplot

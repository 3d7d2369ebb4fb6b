# Relative viscosity eta_r(phi) of the spring-model suspension under shear, by the four choices
# of the solvent viscosity, against Einstein (eq. 33) and Quemada (eq. 34, phi_m = 0.65)
# (Mai-Duy et al. 2019, Fig. 4: a = 3.53).
if (!exists("aij")) aij = "3.53"
if (!exists("fig")) fig = "Fig. 4"
set terminal pngcairo size 700,480 font ",10"
set output out.'/relative-viscosity-'.tier.'.png'
set datafile separator "\t"
set title sprintf("%s: eta_r(phi), a = %s (tier: %s)", fig, aij, tier)
set xlabel "phi"; set ylabel "eta_r"; set key top left; set xrange [0:0.52]; set yrange [0.5:60]; set logscale y
# the paper's quoted values (sec. 4.4)
if (aij eq "3.53") { p1 = 1.59; p2 = 5.17; p3 = 9.69 } else { p1 = 1.78; p2 = 6.69; p3 = 12.46 }
plot 1 + 2.5 * x w l lc rgb "gray40" dt 2 t "Einstein, eq. 33", \
     (1 - x / 0.65)**-2 w l lc rgb "black" t "Quemada, eq. 34", \
     res.'/eta_r.tsv' u 1:2:3 w yerrorlines pt 7 lc 1 t "original (solvent's shear viscosity)", \
     res.'/eta_r.tsv' u 1:4:5 w yerrorlines pt 5 lc 2 t "TCAF (constrained eta(k -> 0))", \
     res.'/eta_r.tsv' u 1:6:7 w yerrorlines pt 9 lc 3 t "cube (eq. 31)", \
     res.'/eta_r.tsv' u 1:8:9 w yerrorlines pt 11 lc 4 t "sphere (eq. 32)", \
     res.'/eta_r.tsv' u 1:10:11 w yerrorlines pt 8 lc 3 dt 3 t "cube, solvent's eta(k)", \
     res.'/eta_r.tsv' u 1:12:13 w yerrorlines pt 10 lc 4 dt 3 t "sphere, solvent's eta(k)", \
     '+' u (0.1854):(p1) every ::0::0 w p pt 6 ps 2 lc 1 t "paper, original", \
     '+' u (0.4940):(p2) every ::0::0 w p pt 6 ps 2 lc 1 notitle, \
     '+' u (0.4940):(p3) every ::0::0 w p pt 4 ps 2 lc 2 t "paper, TCAF"

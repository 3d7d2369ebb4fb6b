# Relative viscosity eta_r(phi) of the spring-model suspension under shear, by the four choices
# of the solvent viscosity, against Einstein (eq. 33) and Quemada (eq. 34, phi_m = 0.65)
# (Mai-Duy et al. 2019, Fig. 4: a = 3.53).
load '../../plot-style.gp'
if (!exists("aij")) aij = "3.53"
if (!exists("fig")) fig = "Fig. 4"
set terminal @PNG size 1400,960
set output out.'/relative-viscosity-'.tier.'.png'
set title sprintf("%s: eta_r(phi), a = %s (tier: %s)", fig, aij, tier)
set xlabel "phi"; set ylabel "eta_r"; set key top left; set xrange [0:0.52]; set yrange [0.5:60]; set logscale y
plot 1 + 2.5 * x w l lc rgb "gray40" dt 2 t "Einstein, eq. 33", \
     (1 - x / 0.65)**-2 w l lc rgb "black" t "Quemada, eq. 34", \
     res.'/eta_r.tsv' u 1:2:3 w yerrorlines ls OURS t "original (solvent's shear viscosity)", \
     res.'/eta_r.tsv' u 1:4:5 w yerrorlines pt 5 lc 2 t "TCAF (constrained eta(k -> 0))", \
     res.'/eta_r.tsv' u 1:6:7 w yerrorlines pt 9 lc 3 t "cube (eq. 31)", \
     res.'/eta_r.tsv' u 1:8:9 w yerrorlines pt 11 lc 4 t "sphere (eq. 32)", \
     res.'/eta_r.tsv' u 1:10:11 w yerrorlines pt 8 lc 3 dt 3 t "cube, solvent's eta(k)", \
     res.'/eta_r.tsv' u 1:12:13 w yerrorlines pt 10 lc 4 dt 3 t "sphere, solvent's eta(k)", \
     PAPER_POINTS("^eta_r_(original|tcaf)_phi") u ($1 + 0.01):2:3:4 w yerrorbars ls PAPER t PAPER_TITLE

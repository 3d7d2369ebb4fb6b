# Solvent viscosity against repulsion (Mai-Duy et al. 2019, section 4.3).
load '../../plot-style.gp'
set terminal @PNG size 1800,840
set output out.'/eta-vs-a-'.tier.'.png'
set multiplot layout 1,2 title "Solvent viscosity by Lees-Edwards shear, eta = <T_xy>/rate (tier: ".tier.")"
set xlabel "repulsion a"; set ylabel "eta"; set logscale x; set key top left
set xrange [3:25]; set key bottom right
plot res.'/eta.tsv' u 1:2:3 w yerrorbars ls OURS t "this package", \
     PAPER_POINTS("^eta_a") u ($1 * 1.05):2:3:4 w yerrorbars ls PAPER t "paper (sec. 4.3), ± tolerance", 30 w l dt 2 t "input eta = 30"
unset logscale x; set xrange [*:*]
set xlabel "y"; set ylabel "v_x"; set key top left
plot for [a in "3.53 6.50 9.50 18.50"] res.'/profile_a'.a.'.tsv' u 1:4:5 w yerrorlines t "a = ".a
unset multiplot

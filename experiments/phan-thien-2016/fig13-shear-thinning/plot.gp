# Fig. 13 of Phan-Thien et al. 2016: viscosity of the phi = 0.0204 suspension against Pe,
# with the solvent alone at the same shear rates.
load '../../plot-style.gp'
set terminal @PNG size 1400,960
set output out.'/shear-thinning-'.tier.'.png'
set title "One spring colloid in the 6 x 6 box, m = 0 (tier: ".tier.")"
set xlabel "Pe = rate a^2 / D"; set ylabel "viscosity"; set logscale x; set key top right
plot res.'/thinning.tsv' u 2:3:4 skip 1 w yerrorlines pt 7 t "suspension, phi = 0.0204", \
     res.'/thinning.tsv' u 2:5:6 skip 1 w yerrorlines pt 5 t "solvent alone (same rates)"

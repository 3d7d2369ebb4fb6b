# Pan et al. 2008, Fig. 3: torque shape factor of a chain of N touching spheres spinning about its axis.
set terminal pngcairo size 700,480 font ",10"
set output out.'/chain-'.tier.'.png'
set datafile separator "\t"
set title "Chain of N touching spheres spinning about its axis, 10^3 box (tier: ".tier.")"
set xlabel "N"; set ylabel "T_s = -T / (8 pi mu Omega N R^3) (eq. 24)"; set key top right
set xrange [0.5:8.5]; set yrange [0.5:1.2]
plot res.'/shape_factor.tsv' u 1:2:3 w yerrorbars pt 7 t "this package", 1 w l dt 2 t "single sphere (eq. 18)"

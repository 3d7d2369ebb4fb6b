# Pan et al. 2008, Table 1: torque on a spinning colloid in Couette flow; channel profiles.
set terminal pngcairo size 1000,420 font ",10"
set output out.'/couette-'.tier.'.png'
set datafile separator "\t"
set multiplot layout 1,3 title "Sphere in Couette flow, 15 x 6 x 8 channel, walls in z (tier: ".tier.")"
set xlabel "eq. 21 torque (paper mu, R; measured curl/2)"; set ylabel "simulated torque"; set key top left
set xrange [0:1.3]; set yrange [0:1.3]
plot res.'/table1.tsv' u 8:6:7 w yerrorbars pt 7 t "this package", \
     '' u 8:9 w p pt 6 ps 1.5 t "paper (T_{sim})", x w l dt 2 t "y = x"
set autoscale; set xrange [0:10]
set xlabel "z"; set ylabel "v_x"; set key top left
plot for [r in "1 4"] res.'/profile_row'.r.'.tsv' u 1:4:5 w yerrorbars pt 7 ps 0.5 t "row ".r
set ylabel "number density"; set yrange [2:4.5]
plot for [r in "1 4"] res.'/profile_row'.r.'.tsv' u 1:2:3 w yerrorbars pt 7 ps 0.5 t "row ".r, 3 w l dt 2 t "n = 3"
unset multiplot

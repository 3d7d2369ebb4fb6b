# Pan et al. 2008, Table 2: drag and torque on a fixed sphere near a wall in Poiseuille flow.
set terminal pngcairo size 1100,400 font ",10"
set output out.'/poiseuille-'.tier.'.png'
set datafile separator "\t"
set multiplot layout 1,3 title "Fixed sphere at h = 2 in a Poiseuille channel 15 x 6 x 8 (tier: ".tier.")"
set xlabel "eq. 22 drag (paper mu, R; measured u_h)"; set ylabel "simulated drag"; set key top left
set xrange [0:25]; set yrange [0:25]
plot res.'/table2.data.tsv' u 7:5:6 w yerrorbars pt 7 t "this package", '' u 7:8 w p pt 6 ps 1.5 t "paper F_{sim} (at our F_{the})", x w l dt 2 t "y = x"
set xlabel "eq. 22 torque"; set ylabel "simulated torque T_y"
set xrange [0:0.4]; set yrange [-0.1:0.5]
plot res.'/table2.data.tsv' u 11:9:10 w yerrorbars pt 7 t "this package", '' u 11:12 w p pt 6 ps 1.5 t "paper T_{sim}", x w l dt 2 t "y = x"
set autoscale; set xrange [0:10]; set yrange [*:*]
set xlabel "z"; set ylabel "v_x, channel without the sphere (g = 0.2)"; set key bottom center
plot res.'/profile_empty.tsv' u 1:4:5 w yerrorbars pt 7 ps 0.5 t "v_x(z)", '-' u 1:2 w p pt 2 ps 2 t "sphere centre z = 3"
3	0
e
unset multiplot

# Pan et al. 2008, Table 3: two fixed spheres side by side in a flow normal to their line of centres.
set terminal pngcairo size 900,400 font ",10"
set output out.'/two-spheres-'.tier.'.png'
set datafile separator "\t"
mu = 3.6388; R = 0.2737
t23(l) = (3*R/(4*l) - 9*R**2/(16*l**2) + 27*R**3/(64*l**3) - 273*R**4/(256*l**4) + 1683*R**5/(1024*l**5))/l
set multiplot layout 1,2 title "Two fixed spheres, flow normal to their line (tier: ".tier.")"
set xlabel "l"; set ylabel "drag per sphere / eq. 23"; set key bottom right
set xrange [0.8:2.2]; set yrange [0.7:1.4]
plot res.'/table3.data.tsv' u 2:($5/$7):($6/$7) w yerrorbars pt 7 t "this package (u held at 0.3)", \
     1 w l dt 2 lc rgb "gray" t "eq. 23", 0.9 w l dt 3 lc rgb "gray" t "+-10 %", 1.1 w l dt 3 lc rgb "gray" notitle, \
     '-' u 1:2 w p pt 6 ps 1.5 lc rgb "dark-orange" t "paper F_{sim}/F_{the}"
2.0	0.953
1.5	0.954
1.0	0.938
e
set ylabel "torque per sphere / u"; set yrange [*:*]; set key top right
plot res.'/table3.data.tsv' u 2:($9/$3):($10/$3) w yerrorbars pt 7 t "this package", \
     8*pi*mu*R**3*t23(x) w l dt 2 t "eq. 23", \
     '-' u 1:2 w p pt 6 ps 1.5 t "paper T_{sim}/u (u from its F_{the})"
2.0	0.0844
1.5	0.1460
1.0	0.3374
e
unset multiplot

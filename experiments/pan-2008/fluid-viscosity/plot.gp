# Reverse Poiseuille profile of the Pan 2008 fluid (viscosity by a parabola per half).
set terminal pngcairo size 900,420 font ",10"
set output out.'/profile-'.tier.'.png'
set datafile separator "\t"
set multiplot layout 1,2 title "Pan fluid, reverse Poiseuille flow, body force 0.05 (tier: ".tier.")"
set xlabel "z"; set ylabel "v_x"; set key bottom center
plot res.'/profile.tsv' u 1:4:5 w yerrorbars pt 7 ps 0.6 t "dt = 0.005", \
     res.'/profile_dt0.01.tsv' u 1:4:5 w yerrorbars pt 6 ps 0.6 t "dt = 0.01", 0 w l lc rgb "gray" notitle
set ylabel "number density"; set yrange [2.8:3.2]
plot res.'/profile.tsv' u 1:2:3 w yerrorbars pt 7 ps 0.6 t "dt = 0.005", 3 w l dt 2 t "n = 3"
unset multiplot

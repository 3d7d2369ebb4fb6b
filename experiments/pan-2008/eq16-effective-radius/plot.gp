# Pan et al. 2008, eqs 16-17: colloid MSD / 6t.
set terminal pngcairo size 600,420 font ",10"
set output out.'/msd-'.tier.'.png'
set datafile separator "\t"
set title "Colloid diffusion, MSD / 6t, 10^3 box, 27 colloids (tier: ".tier.")"
set xlabel "t"; set ylabel "MSD / 6t"; set key top right
plot res.'/msd.tsv' u 1:4:5 w yerrorbars pt 7 ps 0.5 t "this package", 0.0533 w l dt 2 t "paper D = 0.0533"

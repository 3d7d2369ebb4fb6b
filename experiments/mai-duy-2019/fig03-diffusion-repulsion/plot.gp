# D(t) = MSD / (6 t) of the solvent for several repulsions (Mai-Duy et al. 2019, Fig. 3).
set terminal pngcairo size 700,480 font ",10"
set output out.'/D-of-t-'.tier.'.png'
set datafile separator "\t"
set title "Diffusion coefficient against time (tier: ".tier.")"
set xlabel "t"; set ylabel "D(t) = MSD / 6t"; set logscale x; set key bottom left
plot for [a in "3.53 6.50 9.50 18.50 500"] res.'/msd_a'.a.'.tsv' u 1:4:5 w yerrorlines ps 0.3 t "a = ".a

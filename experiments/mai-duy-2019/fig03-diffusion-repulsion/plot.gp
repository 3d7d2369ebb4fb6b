# D(t) = MSD / (6 t) of the solvent for several repulsions (Mai-Duy et al. 2019, Fig. 3).
load '../../plot-style.gp'
set terminal @PNG size 1400,960
set output out.'/D-of-t-'.tier.'.png'
set title "Diffusion coefficient against time (tier: ".tier.")"
set xlabel "t"; set ylabel "D(t) = MSD / 6t"; set logscale x; set key bottom left
plot for [a in "3.53 6.50 9.50 18.50 500"] res.'/msd_a'.a.'.tsv' u 1:4:5 w yerrorlines ps 0.6 t "a = ".a

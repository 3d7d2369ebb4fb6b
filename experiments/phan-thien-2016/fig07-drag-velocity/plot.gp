# Fig. 7 of Phan-Thien et al. 2016: drag on the cylinder against the mean
# velocity, with Hasimoto's eq. 47 from the measured eta and exclusion radius.
set terminal pngcairo size 700,480 font ",10"
set output out.'/drag-velocity-'.tier.'.png'
set datafile separator "\t"
set title "Drag on a 4-particle cylinder, periodic array h = 6, m = 0 (tier: ".tier.")"
set xlabel "mean fluid velocity U"; set ylabel "drag F"; set key top left
g(q) = system("awk -F'\t' '$1==\"".q."\"{print $2}' ".res."/summary.tsv") + 0
eta = g("eta_solvent"); a = g("exclusion_radius")
F(U) = 4 * pi * eta * U / (log(6.0 / a) - 1.3105)
F25(U) = 4 * pi * eta * U / (log(6.0 / 0.25) - 1.3105)
set xrange [0:*]; set yrange [0:*]
plot res.'/drag.tsv' u 4:2:5:3 skip 1 w xyerrorbars pt 7 t "this package", \
     F(x) w l lw 2 t sprintf("eq. 47, eta = %.3f, a = %.3f (measured exclusion radius)", eta, a), \
     F25(x) w l dt 2 t "eq. 47 with the paper's a = 0.25"

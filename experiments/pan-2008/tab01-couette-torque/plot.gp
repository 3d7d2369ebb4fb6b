# Pan et al. 2008, Table 1: torque on a spinning colloid in Couette flow, simulated / eq. 21 per row
# (ours, and the paper's with its band from bands.tsv); the channel's profiles.
load '../../plot-style.gp'
set terminal @PNG size 2400,960
set output out.'/couette-'.tier.'.png'
set multiplot layout 1,3 title "Sphere in Couette flow, 15 x 6 x 8 channel, walls in z (tier: ".tier.")"
set xlabel "row of Table 1"; set ylabel "torque / eq. 21 (paper mu, R; measured curl/2)"; set key top right
set xrange [0.5:4.5]; set xtics 1; set autoscale y; set offsets 0, 0, graph 0.35, graph 0.05   # room above the data for the key
plot PAPER_POINTS("^torque_ratio_row") u ($1 + 0.15):2:3:4 w yerrorbars ls PAPER t "paper, ± its band", \
     res.'/table1.tsv' u 1:($6 / $8):($7 / $8) skip 1 w yerrorbars ls OURS t "this package", \
     1 w l dt 2 lw 2 lc rgb 'black' t "eq. 21"
set autoscale; set offsets 0, 0, 0, 0; set xrange [0:10]; set xtics autofreq
set xlabel "z"; set ylabel "v_x"; set key top left
plot for [r in "1 4"] res.'/profile_row'.r.'.tsv' u 1:4:5 w yerrorbars pt (r eq "1" ? 7 : 6) ps 1 lw 2 lc rgb (r eq "1" ? '#1f4e9c' : '#6a8fd0') t "this package, row ".r
set ylabel "number density"; set yrange [2:5]; set key top center
plot for [r in "1 4"] res.'/profile_row'.r.'.tsv' u 1:2:3 w yerrorbars pt (r eq "1" ? 7 : 6) ps 1 lw 2 lc rgb (r eq "1" ? '#1f4e9c' : '#6a8fd0') t "this package, row ".r, \
     3 w l dt 2 lw 2 lc rgb 'black' t "n = 3"
unset multiplot

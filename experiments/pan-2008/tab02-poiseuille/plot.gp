# Pan et al. 2008, Table 2: drag and torque on a fixed sphere near a wall in Poiseuille flow, simulated /
# eq. 22 per row (ours, and the paper's with its band from bands.tsv); the channel without the sphere.
load '../../plot-style.gp'
set terminal @PNG size 2400,960
set output out.'/poiseuille-'.tier.'.png'
set multiplot layout 1,3 title "Fixed sphere at h = 2 in a Poiseuille channel 15 x 6 x 8 (tier: ".tier.")"
set xlabel "row of Table 2 (body force 0.05, 0.1, 0.2)"; set key top right
set xrange [0.5:3.5]; set xtics 1; set autoscale y; set offsets 0, 0, graph 0.35, graph 0.05   # room above the data for the key
set ylabel "drag / eq. 22 (paper mu, R; measured u_h)"
plot PAPER_POINTS("^drag_ratio_row") u ($1 + 0.15):2:3:4 w yerrorbars ls PAPER t "paper, ± its band", \
     res.'/table2.data.tsv' u 1:($5 / $7):($6 / $7) skip 1 w yerrorbars ls OURS t "this package", \
     1 w l dt 2 lw 2 lc rgb 'black' t "eq. 22"
set ylabel "torque / eq. 22"
plot PAPER_POINTS("^torque_ratio_row") u ($1 + 0.15):2:3:4 w yerrorbars ls PAPER t "paper, ± its band", \
     res.'/table2.data.tsv' u 1:($9 / $11):($10 / $11) skip 1 w yerrorbars ls OURS t "this package", \
     1 w l dt 2 lw 2 lc rgb 'black' t "eq. 22"
set autoscale; set offsets 0, 0, 0, 0; set xrange [0:10]; set xtics autofreq; set yrange [0:*]; set offsets 0, 0, graph 0.2, 0
set xlabel "z"; set ylabel "v_x, channel without the sphere (g = 0.2)"; set key top right
plot res.'/profile_empty.tsv' u 1:4:5 w yerrorbars ls OURS ps 1 t "this package, v_x(z)", \
     '+' u (3):(0) every ::0::0 w p pt 2 ps 3 lw 3 lc rgb 'black' t "sphere centre z = 3"
unset multiplot

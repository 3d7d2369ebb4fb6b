# Pan et al. 2008, Table 3: two fixed spheres side by side in a flow normal to their line of centres;
# drag and torque per sphere over eq. 23 per row (ours, and the paper's with its band from bands.tsv);
# the reduced tier adds the gap scan (README): the drag over eq. 23 and the gap's fluid density against l.
load '../../plot-style.gp'
gap = (tier eq 'reduced')
set terminal @PNG size (gap ? 2900 : 2000),960
set output out.'/two-spheres-'.tier.'.png'
set multiplot layout 1,(gap ? 3 : 2) title "Two fixed spheres, flow normal to their line, u held at 0.3 (tier: ".tier.")"
set xlabel "row of Table 3 (l = 2, 1.5, 1)"; set key top right
set xrange [0.5:3.5]; set xtics 1
set ylabel "drag per sphere / eq. 23"; set autoscale y; set offsets 0, 0, graph 0.35, graph 0.05   # room above the data for the key
plot PAPER_POINTS("^drag_ratio_row") u ($1 + 0.15):2:3:4 w yerrorbars ls PAPER t "paper, ± its band", \
     res.'/table3.data.tsv' u 1:($5 / $7):($6 / $7) skip 1 w yerrorbars ls OURS t "this package", \
     1 w l dt 2 lw 2 lc rgb 'black' t "eq. 23"
set ylabel "torque per sphere / eq. 23"
plot PAPER_POINTS("^torque_ratio_row") u ($1 + 0.15):2:3:4 w yerrorbars ls PAPER t "paper, ± its band", \
     res.'/table3.data.tsv' u 1:($9 / $11):($10 / $11) skip 1 w yerrorbars ls OURS t "this package", \
     1 w l dt 2 lw 2 lc rgb 'black' t "eq. 23"
if (gap) {
    set xlabel "l (12^3 box, u = 0.3)"; set xrange [0.85:2.65]; set xtics 0.25
    set ylabel "drag per sphere / eq. 23"; set y2label "fluid density in the gap / bulk"
    set y2tics; set ytics nomirror; set y2range [0:1.6]; set offsets 0, 0, graph 0.35, graph 0.05
    plot res.'/gap_scan.tsv' u 1:5:6 skip 1 w yerrorbars ls OURS t "drag / eq. 23", \
         res.'/gap_scan.tsv' u 1:7:8 skip 1 axes x1y2 w yerrorlines lc rgb 'gray40' pt 6 ps 2 t "gap density (ball of 0.25)"
}
unset multiplot

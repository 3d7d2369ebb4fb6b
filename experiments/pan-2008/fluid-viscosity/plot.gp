# Reverse Poiseuille flow of the Pan 2008 fluid: the profile (viscosity by a parabola per half), the
# density, and the viscosity at both time steps against the paper's mu with its band.
load '../../plot-style.gp'
set terminal @PNG size 2400,1000
set output out.'/profile-'.tier.'.png'
S(q, c) = real(system("awk -F'\t' '$1==\"".q."\"{print $".c."}' ".res."/summary.tsv"))
set multiplot layout 1,3 title "Pan fluid, reverse Poiseuille flow, body force 0.05 (tier: ".tier.")"
set xlabel "z"; set ylabel "v_x"; set key top right; set yrange [-0.6:0.95]
plot res.'/profile.tsv' u 1:4:5 w yerrorbars ls OURS ps 1.0 t "this package, dt = 0.005", \
     res.'/profile_dt0.01.tsv' u 1:4:5 w yerrorbars pt 6 ps 2.0 lw 2 lc rgb '#6a8fd0' t "this package, dt = 0.01", \
     0 w l lc rgb "gray" notitle
set ylabel "number density"; set autoscale y; set offsets 0, 0, graph 0.5, graph 0.3; set key top right
plot res.'/profile.tsv' u 1:2:3 w yerrorbars ls OURS ps 0.8 t "this package, dt = 0.005", 3 w l dt 2 lc rgb "black" t "n = 3"
set autoscale; set offsets 0, 0, graph 0.35, graph 0.1; set xrange [0.5:3.5]; set xtics ("dt = 0.005" 1, "dt = 0.01" 2, "paper" 3)
set xlabel ""; set ylabel "viscosity mu"
set key top left
plot '+' u (1):(S("mu", 2)):(S("mu", 3)) every ::0::0 w yerrorbars ls OURS t "this package", \
     '+' u (2):(S("mu_dt0.01", 2)):(S("mu_dt0.01", 3)) every ::0::0 w yerrorbars ls OURS notitle, \
     PAPER_POINTS("^mu$") u (3):2:3:4 w yerrorbars ls PAPER t "paper, ± its band"
unset multiplot

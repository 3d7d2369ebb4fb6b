# Fig. 6 of Phan-Thien et al. 2016: radial conservative field of the 4-particle
# cylinder, fluid density map (10 x 10 bins per unit area) and g(q) about the
# centre (eq. 48).
load '../../plot-style.gp'
set terminal @PNG size 2700,840
set output out.'/cylinder-'.tier.'.png'
set multiplot layout 1,3 title "4-particle cylinder in the m = 0 fluid, no flow (tier: ".tier.")"
set view map; set size ratio -1; unset key
set xrange [0:6]; set yrange [0:6]; set xlabel "x"; set ylabel "y"
set title "radial repulsive force on a fluid particle"
set palette rgb 33,13,10
splot res.'/force_map.tsv' u 1:2:3 skip 1 w pm3d
set title "fluid number density"
splot res.'/density_map.tsv' u 1:2:3 skip 1 w pm3d
unset view; set size noratio; set autoscale; set key bottom right font ",15"
set title "g(q) about the centre (eq. 48, dq = 0.01)"
set xlabel "q"; set ylabel "g(q)"; set logscale y; set yrange [1e-4:3]; set xrange [0:2]
a = system("awk -F'\t' '$1==\"exclusion_radius\"{print $2}' ".res."/summary.tsv") + 0
ase = system("awk -F'\t' '$1==\"exclusion_radius\"{print $3}' ".res."/summary.tsv") + 0
set arrow from a, 1e-4 to a, 3 nohead dt 2
plot res.'/around.tsv' u 1:($2 > 0 ? $2 : 1e-9) w l lw 2 t "this package", \
     1e-3 w l dt 3 t "g = 0.001", \
     '+' u (a):(1e-3):(a - ase):(a + ase) every ::0::0 w xerrorbars ls OURS t "exclusion radius, ours", \
     PAPER_POINTS("^exclusion_radius$") u 2:(2.5e-3):3:4 w xerrorbars ls PAPER t "paper a ≈ 0.25, the band"
unset multiplot

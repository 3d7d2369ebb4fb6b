# Figs 10-11 of Phan-Thien et al. 2016: radial conservative field of a 3-particle
# spring colloid, the solvent RDF, the solvent distribution about the colloid centre
# (eq. 48) and the MSDs of solvent and colloid (eq. 52).
set terminal pngcairo size 1200,900 font ",10"
set output out.'/colloid-structure-'.tier.'.png'
set datafile separator "\t"
set multiplot layout 2,2 title "Massless spring colloid (3 particles, H = 1000) in the m = 0 solvent (tier: ".tier.")"
g(q) = system("awk -F'\t' '$1==\"".q."\"{print $2}' ".res."/summary.tsv") + 0
set view map; set size ratio -1; unset key
set xrange [2:4]; set yrange [2:4]; set xlabel "x"; set ylabel "y"
set title "Fig. 10: radial repulsive force of the colloid's particles"
set palette rgb 33,13,10
splot res.'/force_map.tsv' u 1:2:3 skip 1 w pm3d
unset view; set size noratio; set autoscale; set key top left
set title "Fig. 11 (top): solvent RDF"
set xlabel "r"; set ylabel "g(r)"; set logscale y; set yrange [1e-4:3]; set xrange [0:1]
plot res.'/rdf.tsv' u 1:($2 > 0 ? $2 : 1e-9) skip 1 w l lw 2 t "solvent-solvent", 1e-3 w l dt 3 t "g = 0.001"
set title "Fig. 11 (bottom): solvent about the colloid centre (eq. 48)"
set xlabel "q"; set ylabel "g(q)"; set xrange [0:2]
a = g("colloid_radius")
set arrow 1 from a, 1e-4 to a, 3 nohead dt 2
plot res.'/colloid_around.tsv' u 1:($2 > 0 ? $2 : 1e-9) skip 1 w l lw 2 t sprintf("this package, a = %.2f", a), \
     1e-3 w l dt 3 t "g = 0.001", '+' u (0.2):(1e-4) w p pt 7 ps 1.5 t "paper: a = 0.2"
unset arrow 1; unset logscale y; set autoscale
set title "MSD (eq. 52)"; set xlabel "t"; set ylabel "MSD"; set key top left
ds = g("D_solvent"); dc = g("D_colloid")
plot res.'/msd.tsv' u 1:2:3 skip 2 w yerrorlines t sprintf("solvent, D = %.3f", ds), \
     res.'/colloid_msd.tsv' u 1:2:3 skip 2 w yerrorlines t sprintf("colloid, D = %.3f", dc), \
     4 * 0.095 * x w l dt 2 t "paper D = 0.095", 4 * 0.055 * x w l dt 3 t "paper D = 0.055"
unset multiplot

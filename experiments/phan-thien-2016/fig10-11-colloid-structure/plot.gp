# Figs 10-11 of Phan-Thien et al. 2016: radial conservative field of a 3-particle
# spring colloid, the solvent RDF, the solvent distribution about the colloid centre
# (eq. 48) and the MSDs of solvent and colloid (eq. 52).
load '../../plot-style.gp'
set terminal @PNG size 2400,1800
set output out.'/colloid-structure-'.tier.'.png'
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
set xlabel "q"; set ylabel "g(q)"; set xrange [0:2]; set key bottom right
a = g("colloid_radius")
set arrow 1 from a, 1e-4 to a, 3 nohead dt 2
gs(q) = system("awk -F'\t' '$1==\"".q."\"{print $3}' ".res."/summary.tsv") + 0
ase = gs("colloid_radius")
plot res.'/colloid_around.tsv' u 1:($2 > 0 ? $2 : 1e-9) skip 1 w l lw 2 t sprintf("this package, a = %.2f", a), \
     1e-3 w l dt 3 t "g = 0.001", \
     '+' u (a):(1e-3):(a - ase):(a + ase) every ::0::0 w xerrorbars ls OURS t "colloid radius, ours", \
     PAPER_POINTS("^colloid_radius$") u 2:(2.5e-3):3:4 w xerrorbars ls PAPER t "paper a ≈ 0.2, the band"
unset arrow 1; unset logscale y; set autoscale
set title "MSD (eq. 52)"; set xlabel "t"; set ylabel "MSD"; set key top left
ds = g("D_solvent"); dc = g("D_colloid")
# the paper's D and its band as 4 D t (eq. 52), a shaded wedge each
slo = PAPER_AT("^D_solvent$", 3); shi = PAPER_AT("^D_solvent$", 4)
clo = PAPER_AT("^D_colloid$", 3); chi = PAPER_AT("^D_colloid$", 4)
stats res.'/msd.tsv' u 1 skip 2 nooutput; set xrange [0:STATS_max]
plot '+' u 1:(4 * slo * $1):(4 * shi * $1) w filledcurves fs transparent solid 0.18 noborder lc rgb '#c62828' t "paper D = 0.095, the band", \
     '+' u 1:(4 * clo * $1):(4 * chi * $1) w filledcurves fs transparent solid 0.18 noborder lc rgb '#e08000' t "paper D = 0.055, the band", \
     res.'/msd.tsv' u 1:2:3 skip 2 w yerrorlines ls OURS t sprintf("solvent, D = %.3f", ds), \
     res.'/colloid_msd.tsv' u 1:2:3 skip 2 w yerrorlines pt 5 lc rgb '#6a3d9a' t sprintf("colloid, D = %.3f", dc)
unset multiplot

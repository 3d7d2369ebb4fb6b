# Pan et al. 2008, eqs 16-17: colloid MSD / 6t in the 10^3 box, and D in three periodic boxes against
# 1/L (Yeh-Hummer), each against the paper's D with its band (bands.tsv).
load '../../plot-style.gp'
S(f, q, c) = real(system("awk -F'\t' '$1==\"".q."\"{print $".c."}' ".res."/".f))
pD = PAPER_AT("^D_colloid$", 2); pDlo = PAPER_AT("^D_colloid$", 3); pDhi = PAPER_AT("^D_colloid$", 4)
set terminal @PNG size 1400,960
set output out.'/msd-'.tier.'.png'
set title "Colloid diffusion, MSD / 6t, 10^3 box, 27 colloids (tier: ".tier.")"
set xlabel "t"; set ylabel "MSD / 6t"; set key bottom right
stats res.'/msd.tsv' u 1 nooutput; set xrange [0:STATS_max]
plot '+' u 1:(pDlo):(pDhi) w filledcurves fs transparent solid 0.15 noborder lc rgb '#c62828' t "the paper's D, ± its band", \
     pD w l ls PAPER t sprintf("paper: D = %g", pD), \
     res.'/msd.tsv' u 1:4:5 w yerrorbars ls OURS ps 0.8 t "this package"

# D(L) in the three boxes against 1/L, the weighted line extrapolated to 1/L = 0 (Yeh-Hummer)
set output out.'/d-of-L-'.tier.'.png'
set title "Colloid D in periodic boxes L = 6, 8, 12 against 1/L (tier: ".tier.")"
set xlabel "1 / L"; set ylabel "D"; set key rmargin top; set xrange [-0.01:0.18]; set autoscale y; set offsets 0, 0, graph 0.05, graph 0.05
set terminal @PNG size 2200,960
d0 = S("fit-d-of-L.tsv", "value_at_centre", 2); s1 = S("fit-d-of-L.tsv", "slope", 2)
cyh = S("summary.tsv", "yeh_hummer_coefficient", 2)
plot res.'/d-of-L.tsv' u 2:4:5 skip 1 w yerrorbars ls OURS t "this package, D(L)", \
     '+' u (0.1):(S("summary.tsv", "D_colloid", 2)):(S("summary.tsv", "D_colloid", 3)) every ::0::0 w yerrorbars pt 5 ps 1.6 lw 2 lc rgb '#1f4e9c' t "this package, D in the 10^3 box (27 colloids)", \
     '+' u (0):(S("summary.tsv", "D_colloid_extrapolated", 2)):(S("summary.tsv", "D_colloid_extrapolated", 3)) every ::0::0 w yerrorbars pt 9 ps 2 lw 2 lc rgb '#1f4e9c' t "this package, extrapolated D_{inf}", \
     PAPER_POINTS("^D_colloid$") u (0.1 + 0.004):2:3:4 w yerrorbars ls PAPER t "paper, ± its tolerance (the band), 10^3 box", \
     PAPER_POINTS("^D_colloid_extrapolated$") u (0.004):2:3:4 w yerrorbars ls PAPER t "paper's D read as D_{inf}, ± the band", \
     [0:0.17] d0 + s1 * x w l lw 2 lc rgb '#1f4e9c' t "weighted fit, extrapolated to 1/L = 0", \
     [0:0.17] d0 - cyh * x w l dt 3 lw 2 lc rgb 'black' t "Yeh-Hummer slope (measured {/Symbol h}) through the fit's D_{inf}"

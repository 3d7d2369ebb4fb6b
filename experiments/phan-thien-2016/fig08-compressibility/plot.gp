# Fig. 8 of Phan-Thien et al. 2016: eq. 49 density residual and mean |div u|
# against the body force P, m = 0 against m = 1.
# one panel per row, each the column's width (a row of three shrank each to a third of it)
load '../../plot-style.gp'
set terminal @PNG size 1800,3000
set output out.'/compressibility-'.tier.'.png'
set multiplot layout 4,1 title "Flow past the cylinder array: compressibility, m = 0 vs m = 1 (tier: ".tier.")"
set xlabel "body force P"; set key top left
set ylabel "eq. 49 residual of the time-averaged density"
plot res.'/fields.tsv' u ($2 == 0 ? $1 : 1/0):3:4 skip 1 w yerrorlines pt 7 t "m = 0", \
     ''              u ($2 == 1 ? $1 : 1/0):3:4 skip 1 w yerrorlines pt 5 t "m = 1"
set ylabel "mean |div u| of the time-averaged velocity"
plot res.'/fields.tsv' u ($2 == 0 ? $1 : 1/0):5:6 skip 1 w yerrorlines pt 7 t "m = 0", \
     ''              u ($2 == 1 ? $1 : 1/0):5:6 skip 1 w yerrorlines pt 5 t "m = 1"
set ylabel "Mach number U / c_T of the m = 1 flow"; set key top left
plot res.'/mach.tsv' u 1:2:3 skip 1 w yerrorlines pt 5 t "m = 1", 1 w l dt 2 lc rgb "gray" t "Ma = 1"
# the claims: the growths from P = 0.1 to 1 beside the paper's and their bands (bands.tsv)
Q = "residual_growth_m0 divu_growth_m0 residual_growth_ratio_m1_m0 divu_growth_ratio_m1_m0"
S(q, c) = real(system("awk -F'\t' '$1 == \"".q."\" { print $".c." }' ".res."/summary.tsv"))
set xtics ("residual, m = 0" 1, "div u, m = 0" 2, "residual, m = 1 over m = 0" 3, "div u, m = 1 over m = 0" 4)
set xrange [0.5:4.7]; set yrange [0:*]; set offsets 0, 0, graph 0.12, 0; set xlabel "growth from P = 0.1 to P = 1"; set ylabel "growth factor"; set key top center horizontal
plot for [i = 1:4] '+' u (i):(S(word(Q, i), 2)):(S(word(Q, i), 3)) every ::0::0 w yerrorbars ls OURS t (i == 1 ? "this package" : ""), \
     for [i = 1:4] PAPER_POINTS("^".word(Q, i)."$") u (i + 0.15):2:3:4 w yerrorbars ls PAPER t (i == 1 ? PAPER_TITLE : "")
unset multiplot

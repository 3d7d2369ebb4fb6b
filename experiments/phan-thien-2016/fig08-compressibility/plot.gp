# Fig. 8 of Phan-Thien et al. 2016: eq. 49 density residual and mean |div u|
# against the body force P, m = 0 against m = 1.
# one panel per row, each the column's width (a row of three shrank each to a third of it)
set terminal pngcairo size 900,1150 font ",10"
set output out.'/compressibility-'.tier.'.png'
set datafile separator "\t"
set multiplot layout 3,1 title "Flow past the cylinder array: compressibility, m = 0 vs m = 1 (tier: ".tier.")"
set xlabel "body force P"; set key top left
set ylabel "eq. 49 residual of the time-averaged density"
plot res.'/fields.tsv' u ($2 == 0 ? $1 : 1/0):3:4 skip 1 w yerrorlines pt 7 t "m = 0", \
     ''              u ($2 == 1 ? $1 : 1/0):3:4 skip 1 w yerrorlines pt 5 t "m = 1"
set ylabel "mean |div u| of the time-averaged velocity"
plot res.'/fields.tsv' u ($2 == 0 ? $1 : 1/0):5:6 skip 1 w yerrorlines pt 7 t "m = 0", \
     ''              u ($2 == 1 ? $1 : 1/0):5:6 skip 1 w yerrorlines pt 5 t "m = 1"
set ylabel "Mach number U / c_T of the m = 1 flow"; set key top left
plot res.'/mach.tsv' u 1:2:3 skip 1 w yerrorlines pt 5 t "m = 1", 1 w l dt 2 lc rgb "gray" t "Ma = 1"
unset multiplot

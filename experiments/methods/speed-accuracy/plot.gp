# The speed-accuracy trade: temperature error against dt and against CPU cost
# (Groot-Warren fluid, mai-duy-2019 solvent, pan-2008 rotating fluid; lambda = 0.5
# and 0.65), and the m = 0 Couette viscosity against the solver tolerance.
load '../../plot-style.gp'
set terminal @PNG size 2200,1640
set output out.'/speed-accuracy-'.tier.'.png'
set datafile missing "nan"
f = res.'/ladder-dt.tsv'
sel(fl, l, col) = (strcol(1) eq fl && abs($2 - l) < 1e-9) ? column(col) : 1/0
set multiplot layout 2,2 title "Speed against accuracy (tier: ".tier.")"
set key top left font ",16"
set xlabel "dt"; set ylabel "kinetic temperature T / kBT - 1"
set grid
plot 0 lc rgb "gray" notitle, \
     f u 3:(sel("gw",0.5,4)-1):5 w yerrorlines pt 7 lc 1 t "Groot-Warren fluid, lambda 0.5", \
     f u 3:(sel("gw",0.65,4)-1):5 w yerrorlines pt 6 dt 2 lc 1 t "Groot-Warren fluid, lambda 0.65", \
     f u 3:(sel("maiduy",0.5,4)-1):5 w yerrorlines pt 7 lc 2 t "mai-duy solvent, lambda 0.5", \
     f u 3:(sel("maiduy",0.65,4)-1):5 w yerrorlines pt 6 dt 2 lc 2 t "mai-duy solvent, lambda 0.65", \
     f u 3:(sel("pan",0.5,4)-1):5 w yerrorlines pt 7 lc 3 t "pan fluid (rotating), lambda 0.5", \
     f u 3:(sel("pan",0.5,6)-1):7 w yerrorlines pt 4 lc 3 t "pan fluid, rotational T"
set logscale xy; set format y "10^{%T}"
set xlabel "CPU s per 1000 particles per time unit (1 thread)"; set ylabel "|T / kBT - 1|"
set key top right font ",16"
plot f u (sel("gw",0.5,10)):(abs($4-1)) w lp pt 7 lc 1 t "GW fluid, lambda 0.5", \
     f u (sel("gw",0.65,10)):(abs($4-1)) w lp pt 6 dt 2 lc 1 t "GW fluid, lambda 0.65", \
     f u (sel("maiduy",0.5,10)):(abs($4-1)) w lp pt 7 lc 2 t "mai-duy, lambda 0.5", \
     f u (sel("maiduy",0.65,10)):(abs($4-1)) w lp pt 6 dt 2 lc 2 t "mai-duy, lambda 0.65", \
     f u (sel("pan",0.5,10)):(abs($4-1)) w lp pt 7 lc 3 t "pan, lambda 0.5", \
     f u 10:($5) w p pt 1 lc rgb "gray" t "1 stderr of T"
g = res.'/ladder-tolerance.tsv'
unset logscale y; set format y "%g"
set xlabel "CPU seconds per step (assembly + solve)"; set ylabel "(eta - eta_{fig03 paper}) / eta_{fig03 paper}"
set key top right
plot 0 lc rgb "gray" notitle, \
     g u (strcol(1) eq "pcg" ? $8 : 1/0):5:6 w yerrorlines pt 7 t "PCG (tolerance 1e-1 ... 1e-7)", \
     g u (strcol(1) eq "scheme2_consistent" ? $8 : 1/0):5:6 w yerrorlines pt 5 t "consistent Scheme 2"
set logscale y; set format y "10^{%T}"; set format x "10^{%T}"
set xlabel "eq. 27 tolerance"; set ylabel "true relative error of v per step"
set key top left
plot g u (strcol(1) eq "pcg" ? $2 : 1/0):9 w lp pt 7 t "PCG", \
     g u (strcol(1) eq "scheme2_consistent" ? $2 : 1/0):9 w lp pt 5 t "consistent Scheme 2", x lc rgb "gray" dt 2 t "error = tolerance"
unset multiplot

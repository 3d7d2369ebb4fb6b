# Issue 38's estimators for pan-2008. Left: the twins (correlated sampling): the tiny twin's
# decorrelation (rms of the difference over that of two independent runs) and the full twin's
# response over its steady value, against the time since the branch, drag and torque. Middle: the
# rotation ladder, torque over eq. 18 against Omega. Right: the fixed sphere's drag coefficient over
# Stokes against the box, with Hasimoto's periodic array.
load '../../plot-style.gp'
set terminal @PNG size 2700,1150
set output out.'/estimators-'.tier.'.png'
set multiplot layout 1,3 title sprintf("pan-2008 estimators (tier: %s)", tier)
set xlabel "time since the branch"; set ylabel "twins"; set key below; set xrange [0:6]; set yrange [-0.2:2]
plot res.'/twin_drag.tsv' u 1:5 skip 1 w lp pt 7 ps 0.5 t "drag: tiny twin's decorrelation", \
     res.'/twin_rot.tsv' u 1:5 skip 1 w lp pt 5 ps 0.5 t "torque (hot start): tiny twin's decorrelation", \
     res.'/twin_drag.tsv' u 1:4 skip 1 w lp pt 6 ps 0.5 t "drag: response / steady", \
     res.'/twin_rot.tsv' u 1:4 skip 1 w lp pt 4 ps 0.5 t "torque: response / steady", \
     1 w l dt 2 lc rgb "gray" notitle
set xlabel "|Omega|"; set ylabel "torque / eq. 18 (paper mu, R)"; set key below; set xrange [0:4.5]; set autoscale y
plot res.'/ladder.tsv' u (-$1):4:5 skip 1 w yerrorbars ls OURS t "fixed sphere, gamma^C_cf = 0, gamma^S_cf = 5.5", \
     1 w l dt 2 t "eq. 18", 1.05 w l dt 3 lc rgb "gray" t "band edges", 0.95 w l dt 3 lc rgb "gray" notitle
set xlabel "box edge L"; set ylabel "drag / (6 pi mu R u)"; set key below; set xrange [4:12]; set autoscale y
K(L) = 1 / (1 - 1.7601 * (4 * pi * 0.2737**3 / (3 * L**3))**(1./3) + 4 * pi * 0.2737**3 / (3 * L**3))
plot res.'/hold.tsv' u 1:5:6 skip 1 w yerrorbars ls OURS t "fixed sphere, held u (0.3, 0.15)", \
     K(x) w l dt 2 t "Hasimoto, simple cubic array", 1 w l dt 3 t "eq. 19"
unset multiplot

# s and gamma against the imposed viscosity at Sc = 500 (eqs 14-15, 18-19).
load '../../plot-style.gp'
set terminal @PNG size 1800,840
set output out.'/s-gamma-'.tier.'.png'
set key top right
set multiplot layout 1,2 title "Imposed eta at Sc = 500, n = 4, rc = 1.5 (Mai-Duy et al. 2019, eqs 14-21)"
set xlabel "eta"; set ylabel "s"
plot res.'/curves.tsv' u 1:2 w l lw 2 t "3D, eq. 14", '' u 1:4 w l lw 2 dt 2 t "2D, eq. 18", \
     '+' u (30):(0.42) every ::0::0 w p pt 7 ps 3 t "paper: eta = 30, s = 0.42"
set ylabel "gamma"; set logscale y
plot res.'/curves.tsv' u 1:3 w l lw 2 t "3D, eq. 15", '' u 1:5 w l lw 2 dt 2 t "2D, eq. 19", \
     '+' u (30):(6.97) every ::0::0 w p pt 7 ps 3 t "paper: eta = 30, gamma = 6.97"
unset multiplot

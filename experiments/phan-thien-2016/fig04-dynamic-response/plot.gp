# Start-up of the Couette profile, m = 1 (top) and m = 0 (bottom), at t = 2, 4, ..., 20
# (Phan-Thien et al. 2016, Fig. 4), and the growth of the projection on the steady profile.
load '../../plot-style.gp'
set terminal @PNG size 2400,840
set output out.'/startup-'.tier.'.png'
set multiplot layout 1,3 title "Start-up from rest, walls at -10 and +10 from t = 0 (tier: ".tier.")"
set xlabel "y"; set ylabel "v_x"; set yrange [-11:11]; set key top left font ",14"
set title "m = 1"
plot for [k=2:11] res.'/profiles_m1.tsv' u 1:k w lp pt 7 ps 0.8 t columnhead(k), '' u 1:12 w l lw 2 lc rgb "black" t "steady"
set title "m = 0"
plot for [k=2:11] res.'/profiles_m0.tsv' u 1:k w lp pt 7 ps 0.8 t columnhead(k), '' u 1:12 w l lw 2 lc rgb "black" t "steady"
set title "growth"; set xlabel "t"; set ylabel "projection on the steady profile"; set yrange [-0.2:1.3]; set logscale x; set xrange [0.01:40]
plot res.'/growth_m1.tsv' u 1:2 w l t "m = 1", res.'/growth_m0.tsv' u 1:2 w l t "m = 0", 0.9 w l dt 2 lc rgb "gray" t "90 %"
unset multiplot

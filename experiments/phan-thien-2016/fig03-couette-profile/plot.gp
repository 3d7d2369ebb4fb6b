# Density and x velocity across the m = 0 Couette channel (Phan-Thien et al. 2016, Fig. 3).
load '../../plot-style.gp'
set terminal @PNG size 2000,840
set output out.'/profile-'.tier.'.png'
set multiplot layout 1,2 title "m = 0 Couette channel, walls at -10 and +10 (tier: ".tier.")"
set xlabel "y"; set xrange [0:12]; set key top left font ",16"
set ylabel "number density"; set yrange [0:6]
plot res.'/profile.tsv' u 1:2:3 w yerr t "PCG (A v = f)", res.'/profile_scheme2.tsv' u 1:2:3 w yerr t "Scheme 2 (published)", 4 w l dt 2 lc rgb "gray" t "n = 4"
set ylabel "v_x"; set yrange [-12:12]
g = 0; c = 0
plot res.'/profile.tsv' u 1:4:5 w yerr t "PCG (A v = f)", res.'/profile_scheme2.tsv' u 1:4:5 w yerr t "Scheme 2 (published)", \
     (x < 1 ? -10 : (x > 11 ? 10 : 1/0)) w l lc rgb "black" t "wall velocity"
unset multiplot

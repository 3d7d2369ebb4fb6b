# m -> 0 limit (left) and the m = 0 time-step scan (right) in the Couette channel.
load '../../plot-style.gp'
set terminal @PNG size 2000,940
set output out.'/m-limit-dt-'.tier.'.png'
set multiplot layout 1,2 title "m -> 0 limit and the m = 0 time step (tier: ".tier.")"
set logscale x; set xlabel "m (inertial DPD, dt = m/30)"; set ylabel "bulk shear rate"; set key outside top center horizontal font ",18"; set tmargin 4   # above the axes: clear of the data
stats res.'/summary.tsv' u (strcol(1) eq "shear_rate_m0" ? $2 : 1/0) nooutput name "M0"
plot res.'/m-limit.tsv' u 1:3:4 skip 1 w yerr pt 7 t "inertial", M0_max w l dt 2 t "m = 0 (PCG)"
set xlabel "dt (m = 0)"; set ylabel "viscosity from the wall force"; set y2label "bulk density max. deviation"; set y2tics; set ytics nomirror
plot res.'/dt-scan.tsv' u 1:4:5 skip 1 w yerr pt 7 t "eta", '' u 1:6 skip 1 axes x1y2 w lp pt 6 t "density deviation"
unset multiplot

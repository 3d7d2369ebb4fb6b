# Temperature and viscosity of the mai-duy-2019 solvent against the time step.
load '../../plot-style.gp'
set terminal @PNG size 1800,840
set output out.'/dt-scan-'.tier.'.png'
set multiplot layout 1,2 title "Groot-Warren velocity Verlet (lambda = 0.5), solvent of eq. 29 under shear (tier: ".tier.")"
set xlabel "dt"; set ylabel "kinetic temperature"; set key top left
plot res.'/dt-scan.tsv' u 1:2:3 w yerrorlines pt 7 t "measured", 1.01 w l dt 2 lc rgb "gray" t "+-1 %", 0.99 w l dt 2 lc rgb "gray" not
set ylabel "eta = <T_xy> / rate"
plot res.'/dt-scan.tsv' u 1:4:5 w yerrorlines pt 7 t "measured", 29.08 w l dt 2 t "paper, a = 3.53 (29.08)"
unset multiplot

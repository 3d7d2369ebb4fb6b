# Pan et al. 2008, Fig. 1: torque on a fixed colloid spinning at Omega = -0.4 (paper tier: -2, the
# stronger drive of issue 38; run.sh).
set terminal pngcairo size 900,420 font ",10"
set output out.'/torque-'.tier.'.png'
set datafile separator "\t"
OM = (tier eq 'paper') ? 2.0 : 0.4
T18 = 8*pi*3.6388*OM*0.2737**3
set multiplot layout 1,2 title sprintf("Torque on a colloid spinning at Omega = -%.1f, 10^3 box (tier: %s)", OM, tier)
set xlabel "gamma^S_{cf} (gamma^C_{cf} = 0)"; set ylabel "torque T_z"; set key top left
set xrange [0:10]; set yrange [0:*]
plot res.'/torque.tsv' u ($1 == 0 ? $2 : 1/0):3:4 w yerrorbars pt 7 t "this package", \
     T18 w l dt 2 t "eq. 18, paper mu and R"
set xlabel "gamma^C_{cf} (gamma^S_{cf} = 5.5)"
set xrange [-0.5:8]
plot res.'/torque.tsv' u ($2 == 5.5 ? $1 : 1/0):3:4 w yerrorbars pt 7 t "this package", \
     T18 w l dt 2 t "eq. 18, paper mu and R"
unset multiplot

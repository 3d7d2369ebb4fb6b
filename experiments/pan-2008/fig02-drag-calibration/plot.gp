# Pan et al. 2008, Fig. 2: superficial velocity past a fixed colloid against gamma^C_cf.
set terminal pngcairo size 700,480 font ",10"
set output out.'/superficial-'.tier.'.png'
set datafile separator "\t"
mu = 3.6388; R = 0.2737; F = 3000*0.001877; phi = 4*pi*R**3/3/1000.
u19 = F/(6*pi*mu*R); uH = u19*(1 - 1.7601*phi**(1./3) + phi - 1.5593*phi**2)
set title "Superficial velocity past one fixed colloid, 10^3 box, gamma^S_{cf} = 5.5 (tier: ".tier.")"
set xlabel "gamma^C_{cf}"; set ylabel "superficial velocity u (eq. 20)"; set key top right
set xrange [-0.5:7.5]; set yrange [0.2:0.45]
plot res.'/superficial.tsv' u 1:2:3 w yerrorbars pt 7 t "this package", \
     '-' u 1:2 w p pt 6 ps 1.5 t "paper (gamma^C_{cf} = 3.5)", \
     u19 w l dt 2 t "eq. 19 (paper mu, R)", uH w l dt 3 t "Hasimoto, simple cubic array"
3.5	0.2986
e

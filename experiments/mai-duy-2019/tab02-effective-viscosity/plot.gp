# Table 2 of Mai-Duy et al. 2019 (a = 3.53): effective k and eta by the TCAF construction against
# phi, beside the paper's values; and eta(k) of the free and constrained systems of each phi.
load '../../plot-style.gp'
set terminal @PNG size 2000,1120 noenhanced
set output out.'/effective-viscosity-'.tier.'.png'
set multiplot layout 1,2 title "Table 2: TCAF effective k and eta, a = 3.53 (tier: ".tier.")"
# the legends above the axes, clear of the data (five series on the left, one column)
set xlabel "phi"; set ylabel "eta_eff"; set key outside top center vertical maxrows 5 Left reverse font ",18"; set tmargin 7; set xrange [0:0.52]
plot 'paper-table2.tsv' u 2:5 w l lc rgb "#c62828" dt 2 notitle, \
     PAPER_POINTS("^eta_eff_phi") u ($1 + 0.006):2:3:4 w yerrorbars ls PAPER t "Table 2, ".PAPER_TITLE, \
     res.'/table2_data.tsv' u 2:7:8 w yerrorbars ls OURS t "constrained, time integral: eta_eff", \
     res.'/table2_data.tsv' u 2:17:18 w yerrorbars pt 9 lc 4 t "constrained, two-mode slow mode", \
     res.'/table2_data.tsv' u 2:13:14 w yerrorbars pt 4 lc 7 t "constrained, eq. 28 amplitude 1 (literal fit)", \
     res.'/table2_data.tsv' u 2:9:10 w yerrorbars pt 5 lc 1 t "free system, eta(k -> 0)"
set ylabel "k_eff"
plot 'paper-table2.tsv' u 2:3 w l lc rgb "#c62828" dt 2 notitle, \
     PAPER_POINTS("^k_eff_phi") u ($1 + 0.006):2:3:4 w yerrorbars ls PAPER t "Table 2, ".PAPER_TITLE, \
     res.'/table2_data.tsv' u 2:3:4 w yerrorbars ls OURS t "k_eff (nan: no crossing)"
unset multiplot

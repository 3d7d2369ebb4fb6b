# Table 2 of Mai-Duy et al. 2019 (a = 3.53): effective k and eta by the TCAF construction against
# phi, beside the paper's values; and eta(k) of the free and constrained systems of each phi.
set terminal pngcairo size 1000,440 font ",10" noenhanced
set output out.'/effective-viscosity-'.tier.'.png'
set datafile separator "\t"
set multiplot layout 1,2 title "Table 2: TCAF effective k and eta, a = 3.53 (tier: ".tier.")"
set xlabel "phi"; set ylabel "eta_eff"; set key bottom left; set xrange [0:0.52]
plot 'paper-table2.tsv' u 2:5 w lp pt 6 lc rgb "black" t "paper, eta_eff", \
     res.'/table2_data.tsv' u 2:7:8 w yerrorbars pt 7 lc 2 t "constrained eta(k -> 0) = eta_eff (integral)", \
     res.'/table2_data.tsv' u 2:17:18 w yerrorbars pt 9 lc 4 t "constrained, two-mode slow mode", \
     res.'/table2_data.tsv' u 2:13:14 w yerrorbars pt 4 lc 7 t "constrained, eq. 28 amplitude 1 (literal)", \
     res.'/table2_data.tsv' u 2:9:10 w yerrorbars pt 5 lc 1 t "free eta(k -> 0)"
set ylabel "k_eff"; set key top left
plot 'paper-table2.tsv' u 2:3 w lp pt 6 lc rgb "black" t "paper, k_eff", \
     res.'/table2_data.tsv' u 2:3:4 w yerrorbars pt 7 lc 2 t "k_eff (nan: no crossing)"
unset multiplot

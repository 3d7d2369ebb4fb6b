# Effective wavelength of the solvent against phi (Mai-Duy et al. 2019, Table 1).
set terminal pngcairo size 700,480 font ",10"
set output out.'/wavelengths-'.tier.'.png'
set datafile separator "\t"
set title "Effective wavelength against volume fraction (tier: ".tier.")"
set xlabel "phi"; set ylabel "lambda"; set key top right; set logscale y
# lambda_tcaf.tsv: nan where the phi was not run or the free eta(k) has no crossing (not drawn)
plot res.'/table1.tsv' skip 1 u 2:3 w lp pt 7 t "sphere, eq. 32 (this package)", \
     '' skip 1 u 2:4 w p pt 6 ps 1.8 t "sphere, paper", \
     '' skip 1 u 2:5 w lp pt 5 t "cube, eq. 31 (this package)", \
     '' skip 1 u 2:6 w p pt 4 ps 1.8 t "cube, paper", \
     '' skip 1 u 2:8 w lp pt 9 dt 2 t "TCAF, paper", \
     res.'/lambda_tcaf.tsv' skip 1 u 1:2:3 w yerrorbars pt 11 ps 1.5 lc rgb "red" t "TCAF (this package; none where no crossing)"

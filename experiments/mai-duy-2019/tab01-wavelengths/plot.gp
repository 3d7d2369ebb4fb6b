# Effective wavelength of the solvent against phi (Mai-Duy et al. 2019, Table 1).
load '../../plot-style.gp'
set terminal @PNG size 1400,960
set output out.'/wavelengths-'.tier.'.png'
set title "Effective wavelength against volume fraction (tier: ".tier.")"
set xlabel "phi"; set ylabel "lambda"; set key top right; set logscale y
# lambda_tcaf.tsv: nan where the phi was not run or the free eta(k) has no crossing (not drawn)
plot res.'/table1.tsv' skip 1 u 2:3 w lp pt 7 t "sphere, eq. 32 (this package)", \
     '' skip 1 u 2:4 w p pt 6 ps 3.6 t "sphere, paper", \
     '' skip 1 u 2:5 w lp pt 5 t "cube, eq. 31 (this package)", \
     '' skip 1 u 2:6 w p pt 4 ps 3.6 t "cube, paper", \
     PAPER_POINTS("^lambda_tcaf_phi") u ($1 + 0.008):2:3:4 w yerrorbars ls PAPER t "TCAF, ".PAPER_TITLE, \
     res.'/lambda_tcaf.tsv' skip 1 u 1:2:3 w yerrorbars ls OURS t "TCAF (this package; none where no crossing)"

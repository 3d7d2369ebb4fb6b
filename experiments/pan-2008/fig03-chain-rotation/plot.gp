# Pan et al. 2008, Fig. 3: torque shape factor of a chain of N touching spheres spinning about its
# axis; the paper's single-sphere value and its band from bands.tsv.
load '../../plot-style.gp'
set terminal @PNG size 1400,960
set output out.'/chain-'.tier.'.png'
set title "Chain of N touching spheres spinning about its axis, 10^3 box (tier: ".tier.")"
set xlabel "N"; set ylabel "T_s = -T / (8 pi mu Omega N R^3) (eq. 24)"; set key top right
set xrange [0.5:8.5]; set autoscale y; set offsets 0, 0, graph 0.35, graph 0.05   # room above the data for the key
plot PAPER_POINTS("^Ts_N") u ($1 + 0.2):2:3:4 w yerrorbars ls PAPER t PAPER_TITLE, \
     res.'/shape_factor.tsv' u 1:2:3 skip 1 w yerrorbars ls OURS t "this package", \
     1 w l dt 2 lw 2 lc rgb 'black' t "single sphere (eq. 18)"

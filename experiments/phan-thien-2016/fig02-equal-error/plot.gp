# Iterations and CPU time per step against the true relative error reached, per solver
# (m = 0 Couette channel of Phan-Thien et al. 2016, Fig. 2 set-up; ladder of eq. 27 tolerances).
load '../../plot-style.gp'
set terminal @PNG size 2000,840
set output out.'/equal-error-'.tier.'.png'
set multiplot layout 1,2 title "Solvers at equal true error (tier: ".tier."; published Scheme 2 against its own fixed point)"
set logscale xy; set format x "10^{%T}"; set xlabel "true relative error per step"; set key top right font ",16"
set arrow 1 from 1e-6, graph 0 to 1e-6, graph 1 nohead dt 2 lc rgb "gray"
set ylabel "iterations per step"
plot for [s in "scheme1 scheme2_paper scheme2_consistent pcg pcg_2level"] res.'/ladder.tsv' u (strcol(1) eq s ? $5 : 1/0):3 w lp pt 7 t s
set ylabel "CPU seconds per step (assembly + solve)"
plot for [s in "scheme1 scheme2_paper scheme2_consistent pcg pcg_2level"] res.'/ladder.tsv' u (strcol(1) eq s ? $5 : 1/0):6 w lp pt 7 t s
unset multiplot

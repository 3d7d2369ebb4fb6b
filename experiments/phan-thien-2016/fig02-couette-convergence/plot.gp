# Iterations per step of the m = 0 Couette channel (Phan-Thien et al. 2016, Fig. 2).
set terminal pngcairo size 900,420 font ",10"
set output out.'/iterations-'.tier.'.png'
set datafile separator "\t"
set multiplot layout 1,2 title "m = 0 Couette channel, tolerance 1e-7 on eq. 27 (tier: ".tier.")"
set xlabel "step"; set ylabel "iterations per step"; set logscale y; set format y "10^{%T}"; set yrange [10:30000]; set key top right maxrows 3 font ",8"
plot res.'/solver_scheme1.tsv' u 1:2 w l t "Scheme 1", res.'/solver_scheme2_paper.tsv' u 1:2 w l t "Scheme 2 (published)", \
     res.'/solver_scheme2_consistent.tsv' u 1:2 w l t "Scheme 2 (consistent)", res.'/solver_pcg.tsv' u 1:2 w l t "PCG", \
     2100 w l dt 2 lc rgb "gray" t "paper: 2100, 450", 450 w l dt 2 lc rgb "gray" not
set ylabel "true relative error"; set yrange [1e-8:100]; set key top right font ",8"
plot res.'/solver_scheme1.tsv' u 1:5 w l t "Scheme 1", res.'/solver_scheme2_paper.tsv' u 1:5 w l t "Scheme 2 (published)", \
     res.'/solver_scheme2_consistent.tsv' u 1:5 w l t "Scheme 2 (consistent)", res.'/solver_pcg.tsv' u 1:5 w l t "PCG"
unset multiplot

# Iterations per step of the m = 0 Couette channel (Phan-Thien et al. 2016, Fig. 2).
load '../../plot-style.gp'
set terminal @PNG size 1800,840
set output out.'/iterations-'.tier.'.png'
set multiplot layout 1,2 title "m = 0 Couette channel, tolerance 1e-7 on eq. 27 (tier: ".tier.")"
set xlabel "step"; set ylabel "iterations per step"; set logscale y; set format y "10^{%T}"; set yrange [10:100000]; set key top left maxrows 3 font ",15"
# the paper's iteration counts and their bands (bands.tsv), shaded across the run
stats res.'/solver_pcg.tsv' u 1 nooutput; set xrange [STATS_min:STATS_max]
plot '+' u 1:(PAPER_AT("^iterations_scheme1$", 3)):(PAPER_AT("^iterations_scheme1$", 4)) w filledcurves fs transparent solid 0.15 noborder lc rgb '#c62828' t "paper ≈ 2100, band", \
     '+' u 1:(PAPER_AT("^iterations_scheme2$", 3)):(PAPER_AT("^iterations_scheme2$", 4)) w filledcurves fs transparent solid 0.15 noborder lc rgb '#e08000' t "paper ≈ 450, band", \
     res.'/solver_scheme1.tsv' u 1:2 w l lc 1 t "Scheme 1", res.'/solver_scheme2_paper.tsv' u 1:2 w l lc 2 t "Scheme 2 (published)", \
     res.'/solver_scheme2_consistent.tsv' u 1:2 w l lc 3 t "Scheme 2 (consistent)", res.'/solver_pcg.tsv' u 1:2 w l lc 4 t "PCG"
set ylabel "true relative error"; set yrange [1e-8:100]; set key top right font ",16"
plot res.'/solver_scheme1.tsv' u 1:5 w l t "Scheme 1", res.'/solver_scheme2_paper.tsv' u 1:5 w l t "Scheme 2 (published)", \
     res.'/solver_scheme2_consistent.tsv' u 1:5 w l t "Scheme 2 (consistent)", res.'/solver_pcg.tsv' u 1:5 w l t "PCG"
unset multiplot

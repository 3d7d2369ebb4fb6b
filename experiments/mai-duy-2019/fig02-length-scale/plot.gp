# eta(k) of the free and the spring-constrained system at one phi (Mai-Duy et al. 2019, Fig. 2).
load '../../plot-style.gp'
set terminal @PNG size 1400,960
set output out.'/length-scale-'.tier.'.png'
stats res.'/summary.tsv' u (strcol(1) eq "eta_k0_constrained" ? $2 : NaN) nooutput
ec = STATS_max
stats res.'/summary.tsv' u (strcol(1) eq "phi" ? $2 : NaN) nooutput
phi = STATS_max
set title sprintf("eta(k), free and spring-constrained, phi = %.4f (tier: %s)", phi, tier)
set xlabel "k"; set ylabel "eta(k)"; set key top right; set xrange [0:*]
plot res.'/tcaf_eta_free.tsv' u 1:4:5 w yerrorlines pt 7 t "free system", \
     res.'/tcaf_eta_free.tsv' u 1:10 w l dt 2 lc 1 t "free: k -> 0 fit", \
     res.'/tcaf_eta_constrained.tsv' u 1:4:5 w yerrorlines pt 5 t "constrained (springs)", \
     res.'/tcaf_eta_constrained.tsv' u 1:10 w l dt 2 lc 2 t "constrained: k -> 0 fit", \
     res.'/tcaf_eta_constrained_bodies.tsv' u 1:4:5 w yerrorlines pt 9 t "constrained, bodies' momentum in J", \
     ec w l lc rgb "black" dt 3 t sprintf("constrained eta(k -> 0) = %.2f", ec)

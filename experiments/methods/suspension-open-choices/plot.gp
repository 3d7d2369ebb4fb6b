# eta_r(phi = 0.49) under each open choice, a = 3.53 and 6.50, beside the paper's values (Figs 4-5).
load '../../plot-style.gp'
set terminal @PNG size 1520,960
set output out.'/eta-r-choices-'.tier.'.png'
set title sprintf("eta_r(phi = 0.49) against the open choices (tier: %s)", tier)
set ylabel "eta_r"; set xtics rotate by -30; set key top left; set offsets 0.5, 0.5, 0, 0
# rows come in pairs, a = 3.53 then a = 6.50, one pair per choice
plot res.'/eta_r.tsv' u 0:4:5:xtic(1) every 2 skip 1 w yerrorbars pt 5 lc 2 t "a = 3.53", \
     res.'/eta_r.tsv' u ($0 + 0.1):4:5 every 2::1 skip 1 w yerrorbars pt 7 lc 1 t "a = 6.50", \
     5.17 w l dt 2 lc 2 t "paper, a = 3.53", 6.69 w l dt 2 lc 1 t "paper, a = 6.50"

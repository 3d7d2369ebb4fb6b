# Pan et al. 2008, Fig. 2: superficial velocity past a fixed colloid against gamma^C_cf; eq. 19 and
# Hasimoto's array from summary.tsv, the paper's point and its band from bands.tsv.
load '../../plot-style.gp'
set terminal @PNG size 1400,960
set output out.'/superficial-'.tier.'.png'
S(q) = real(system("awk -F'\t' '$1==\"".q."\"{print $2}' ".res."/summary.tsv"))
u19 = S("u_eq19"); uH = S("u_hasimoto")
set title "Superficial velocity past one fixed colloid, 10^3 box, gamma^S_{cf} = 5.5 (tier: ".tier.")"
set xlabel "gamma^C_{cf}"; set ylabel "superficial velocity u (eq. 20)"; set key top right
set xrange [-0.5:7.5]; set autoscale y; set offsets 0, 0, graph 0.35, graph 0.05   # room above the data for the key
plot PAPER_POINTS("^u_gC") u ($1 + 0.15):2:3:4 w yerrorbars ls PAPER t PAPER_TITLE, \
     res.'/superficial.tsv' u 1:2:3 skip 1 w yerrorbars ls OURS t "this package", \
     u19 w l dt 2 lw 2 lc rgb 'black' t "eq. 19 (paper mu, R)", uH w l dt 3 lw 2 lc rgb 'black' t "Hasimoto, simple cubic array"

# Pan et al. 2008, Fig. 1: torque on a fixed colloid spinning at Omega = -0.4 (paper tier: -2, the
# stronger drive of issue 38; run.sh), against gamma^S_cf and gamma^C_cf; eq. 18 from summary.tsv, the
# paper's torque at the calibrated point (its ratio to eq. 18) and the band of the slope in gamma^C_cf
# from bands.tsv.
load '../../plot-style.gp'
set terminal @PNG size 2400,960
set output out.'/torque-'.tier.'.png'
S(q, c) = real(system("awk -F'\t' '$1==\"".q."\"{print $".c."}' ".res."/summary.tsv"))
T18 = S("torque_eq18", 2)
OM = (tier eq 'paper') ? 2.0 : 0.4           # |Omega| of the tier's runs (run.sh)
set multiplot layout 1,2 title sprintf("Torque on a colloid spinning at Omega = -%.1f, 10^3 box (tier: %s)", OM, tier)
set xlabel "gamma^S_{cf} (gamma^C_{cf} = 0)"; set ylabel "torque T_z"; set key bottom right
set xrange [0:10]; set yrange [0:*]
plot PAPER_POINTS("^torque_ratio_gS") u ($1 + 0.3):($2 * T18):($3 * T18):($4 * T18) w yerrorbars ls PAPER \
         t sprintf("paper at 5.5 (%g x eq. 18), ± the band", PAPER_AT("^torque_ratio_gS", 2)), \
     res.'/torque.tsv' u ($1 == 0 ? $2 : 1/0):3:4 w yerrorbars ls OURS t "this package", \
     T18 w l dt 2 lw 2 lc rgb 'black' t "eq. 18, paper mu and R"
# the claim: no dependence on gamma^C_cf, slope within the band (per unit gamma^C_cf at Omega = -0.4,
# here at the tier's Omega), drawn as a fan from our gamma^C_cf = 0 point
set xlabel "gamma^C_{cf} (gamma^S_{cf} = 5.5)"
set xrange [-0.5:8]; set yrange [0:*]
T0 = S("torque_gC0.0_gS5.5", 2)
slo = PAPER_AT("^torque_slope_gC$", 3) * OM / 0.4; shi = PAPER_AT("^torque_slope_gC$", 4) * OM / 0.4
plot '+' u 1:(T0 + slo * x):(T0 + shi * x) w filledcurves fs transparent solid 0.15 noborder lc rgb '#c62828' t "paper: no dependence, slope ± its band", \
     res.'/torque.tsv' u ($2 == 5.5 ? $1 : 1/0):3:4 w yerrorbars ls OURS t "this package", \
     T18 w l dt 2 lw 2 lc rgb 'black' t "eq. 18, paper mu and R"
unset multiplot

# Centre of mass of the m = 0 fluid, Scheme 1 against the published Scheme 2
# (Phan-Thien et al. 2016, section 3): seed 1 of each.
load '../../plot-style.gp'
set terminal @PNG size 2400,840
set output out.'/com-'.tier.'.png'
set multiplot layout 1,3 title "Fluid centre of mass, dt = 0.005 (tier: ".tier.")"
set xlabel "t"; set key top right font ",16"
set ylabel "COM velocity (Scheme 1)"
plot res.'/com_scheme1.tsv' u 1:2 w l t "V_x", '' u 1:3 w l t "V_y", 15 w l dt 2 lc rgb "gray" t "paper: +-15 (x), +-8 (y)", -15 w l dt 2 lc rgb "gray" not, 8 w l dt 3 lc rgb "gray" not, -8 w l dt 3 lc rgb "gray" not
set ylabel "COM displacement (Scheme 1)"
plot res.'/com_scheme1.tsv' u 1:4 w l t "x_c", '' u 1:5 w l t "y_c", 1.2 w l dt 2 lc rgb "gray" t "paper: -0.6 < x_c < 1.2", -0.6 w l dt 2 lc rgb "gray" not
set ylabel "|COM velocity|, |displacement| (Scheme 2)"; set logscale y; set format y "10^{%T}"; set yrange [1e-14:1e-5]
plot res.'/com_scheme2.tsv' u 1:(sqrt($2**2+$3**2)) w l t "|V_c|", '' u 1:(sqrt($4**2+$5**2)) w l t "|R_c - R_c(0)|", \
     1e-8/400*sqrt(2) w l dt 2 lc rgb "gray" t "paper: sum v < 1e-8", 1.414e-10 w l dt 3 lc rgb "gray" t "paper: |x_c|,|y_c| < 1e-10"
unset multiplot

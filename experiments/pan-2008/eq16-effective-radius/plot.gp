# Pan et al. 2008, eqs 16-17: colloid MSD / 6t.
set terminal pngcairo size 600,420 font ",10"
set output out.'/msd-'.tier.'.png'
set datafile separator "\t"
set title "Colloid diffusion, MSD / 6t, 10^3 box, 27 colloids (tier: ".tier.")"
set xlabel "t"; set ylabel "MSD / 6t"; set key top right
plot res.'/msd.tsv' u 1:4:5 w yerrorbars pt 7 ps 0.5 t "this package", 0.0533 w l dt 2 t "paper D = 0.0533"

# D(L) in the three boxes against 1/L, the weighted line extrapolated to 1/L = 0 (Yeh-Hummer)
set output out.'/d-of-L-'.tier.'.png'
set title "Colloid D in periodic boxes L = 6, 8, 12 against 1/L (tier: ".tier.")"
set xlabel "1 / L"; set ylabel "D"; set key top right; set xrange [0:0.18]
d0 = real(system("awk -F'\t' '$1==\"value_at_centre\"{print $2}' ".res."/fit-d-of-L.tsv"))
s1 = real(system("awk -F'\t' '$1==\"slope\"{print $2}' ".res."/fit-d-of-L.tsv"))
cyh = real(system("awk -F'\t' '$1==\"yeh_hummer_coefficient\"{print $2}' ".res."/summary.tsv"))
plot res.'/d-of-L.tsv' u 2:4:5 w yerrorbars pt 7 ps 0.8 t "this package, D(L)", \
     d0 + s1 * x w l t "weighted fit, extrapolated to 1/L = 0", \
     d0 - cyh * x w l dt 3 t "Yeh-Hummer slope (measured {/Symbol h}) through the fit's D_{inf}", \
     0.0533 w l dt 2 t "paper D = 0.0533"

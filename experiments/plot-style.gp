# plot-style.gp -- the one plot style of experiments/*/*/plot.gp, loaded first by each
# (`load '../../plot-style.gp'`; gnuplot runs in experiments/PAPER/EXP with res, out, tier set by
# experiments.mk). Issue 40: a figure a reviewer reads at a page's width, with the paper's values and
# their tolerance drawn beside ours with error bars.
#   set terminal @PNG size W, H      a PNG at twice the pixel size of the layout W/2 x H/2 (pngcairo,
#                                    fonts and lines scaled alike): sharp at full width and on print;
#                                    @PNG_BARE ... font 'Sans,N' for another font size
#   ... ls OURS                      our values: filled circles with error bars, blue
#   ... ls PAPER                     the paper's: open red squares, the bar its band (the tolerance)
#   PAPER_POINTS(re)                 the paper's numbers of the claim rows of bands.tsv whose quantity
#                                    matches the awk regular expression re, at this tier (else the
#                                    paper tier): "x value lo hi quantity", x the number that follows
#                                    the match in the quantity name (0.19 for ^eta_r_original_phi on
#                                    eta_r_original_phi0.19), the value the paper's printed number (else
#                                    the band's centre), lo and hi the band (an open side at the value);
#                                    PAPER_AT(re, 2 | 3 | 4) that value, lo or hi of the first such row
PNG_BARE = "pngcairo enhanced linewidth 2"
PNG = PNG_BARE." font 'Sans,20'"
OURS = 100; PAPER = 101
set style line OURS pt 7 ps 1.6 lw 2 lc rgb '#1f4e9c'
set style line PAPER pt 4 ps 2.6 lw 3 lc rgb '#c62828'
# (line styles, not macros: gnuplot expands no macro after an apostrophe in a title on the same line)
PAPER_TITLE = "paper, ± its tolerance (the band)"
set datafile separator "\t"
set key opaque box lc rgb "#bbbbbb" Left reverse samplen 2 spacing 1.1
set grid lc rgb "#e0e0e0"
set border lw 1.5
set pointsize 2
PAPER_CMD(re) = sprintf("awk -F'\\t' -v re='%s' -v tier='%s' -f ../../../tools/lib/paper-points.awk bands.tsv", re, tier)
PAPER_POINTS(re) = "< ".PAPER_CMD(re)
# one number of the first such row: PAPER_AT(re, 2) its value, 3 the band's lower edge, 4 the upper
PAPER_AT(re, col) = real(system(PAPER_CMD(re)." | awk -F'\\t' 'NR == 1 { print $".col." }'"))

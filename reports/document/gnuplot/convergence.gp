# The final position error against dt on the spring: each method's errors (points), its
# least-squares line over the fitted window (solid) and slopes 1, 2 and 4 for reference (grey,
# dashed, each labelled with its order at its left end); a panel per family, every panel on the
# same axes, at most six labelled decades an axis.
# Variables set by steplab report: datadir, outfile, format (png|svg|pdf), the panels npanel, panel1..,
# ptitle1..; styles.gp: each method's style.
ncol = npanel <= 3 ? npanel : npanel == 4 ? 2 : 3
nrow = (npanel + ncol - 1) / ncol
load "styles.gp"  # each method's style, the terminal and the fonts
eval terminal(350 * nrow + 60, 4.4 * nrow + 0.6)
set output outfile
set grid lc rgb "#dddddd"
set key below horizontal samplen 1.5 spacing 0.9 font kfont noenhanced  # method names have underscores
set logscale xy
set format xy "10^{%L}"
# the same ranges in every panel: over every method's errors
emin = 1e300; emax = 0; dmin = 1e300; dmax = 0
do for [f=1:npanel] {
  do for [m in value("panel".f)] {
    stats datadir."/conv_".m.".dat" using 1:2 nooutput
    dmin = STATS_min_x < dmin ? STATS_min_x : dmin; dmax = STATS_max_x > dmax ? STATS_max_x : dmax
    emin = STATS_min_y > 0 && STATS_min_y < emin ? STATS_min_y : emin; emax = STATS_max_y > emax ? STATS_max_y : emax
  }
}
eval axis_tics("x", dmin / 1.5, dmax * 1.5, 1)
eval axis_tics("y", emin / 10, emax * 10, 1)
set xlabel "dt (s)"
set ylabel "error at t_{end} (m)"
set multiplot layout nrow,ncol
do for [f=1:npanel] {
  ms = value("panel".f)
  set title value("ptitle".f) noenhanced
  plot for [m in ms] datadir."/conv_".m.".dat" using 1:2 with points lt mlt(m) title m, \
       for [m in ms] datadir."/fit_".m.".dat" using 1:2 with lines lt mlt(m) dt 1 lw 2 notitle, \
       for [p=0:2] datadir."/reference_slopes.dat" index p using 1:2 with lines dt 2 lw 1 lc rgb "#888888" notitle, \
       for [p=0:2] datadir."/reference_slopes.dat" index p every ::0::0 using 1:2:("order ".word("1 2 4", p + 1)) \
           with labels right offset -0.3, 0 font kfont tc rgb "#555555" notitle
}
unset multiplot

# The undamped bounce: E/E0 after the last bounce against dt, a panel per family (the methods of
# the collision study), every panel on the same axes.
# Variables set by steplab report: datadir, outfile, format (png|svg|pdf), the panels npanel, panel1..,
# ptitle1..; styles.gp: each method's style.
ncol = npanel <= 3 ? npanel : npanel == 4 ? 2 : 3
nrow = (npanel + ncol - 1) / ncol
load "styles.gp"  # each method's style, the terminal and the fonts
eval terminal(330 * nrow + 60, 4.0 * nrow + 0.6)
set output outfile
set grid lc rgb "#dddddd"
set key below horizontal samplen 1.5 spacing 0.9 font kfont noenhanced  # method names have underscores
set logscale x
rmin = 1e300; rmax = -1e300
do for [f=1:npanel] {
  do for [m in value("panel".f)] {
    stats datadir."/bounce_".m.".dat" using 2 nooutput
    rmin = STATS_min < rmin ? STATS_min : rmin; rmax = STATS_max > rmax ? STATS_max : rmax
  }
}
pad = (rmax - rmin) * 0.1 + 1e-3
set yrange [rmin - pad : rmax + pad]
set xlabel "dt (s)"
set ylabel "E/E0 after the last bounce"
set multiplot layout nrow,ncol
do for [f=1:npanel] {
  ms = value("panel".f)
  set title value("ptitle".f) noenhanced
  plot for [m in ms] datadir."/bounce_".m.".dat" using 1:2 with linespoints lt mlt(m) title m
}
unset multiplot

# Stable for how long: an invariant's largest relative error up to t against t in periods, log-log,
# each method a line through its samples (a run that blew up ends where it did); a panel per
# family (the full report) or one panel (the hand-in), every panel on the same axes.
# Variables set by steplab report: datadir, outfile, format (png|svg|pdf), prefix (the data files'
# names up to the method's: lt_<scene>_), col (the column drawn: 2 the energy), ylab, the panels
# npanel, panel1.., ptitle1..; styles.gp: each method's style.
ncol = npanel <= 3 ? npanel : npanel == 4 ? 2 : 3
nrow = (npanel + ncol - 1) / ncol
load "styles.gp"  # each method's style, the terminal and the fonts
eval terminal(300 * nrow + 80, 3.8 * nrow + 0.9)
set output outfile
set grid lc rgb "#dddddd"
set key below horizontal samplen 1.5 spacing 0.9 font kfont noenhanced  # method names have underscores
set logscale xy
set format xy "10^{%L}"
# the same ranges in every panel: over every method's errors above zero
emin = 1e300; emax = 0; tmax = 1
do for [f=1:npanel] {
  do for [m in value("panel".f)] {
    stats datadir."/".prefix.m.".dat" using 1:(column(col) > 0 ? column(col) : NaN) nooutput
    tmax = STATS_max_x > tmax ? STATS_max_x : tmax
    emin = STATS_min_y < emin ? STATS_min_y : emin; emax = STATS_max_y > emax ? STATS_max_y : emax
  }
}
set xrange [0.8 : tmax * 1.25]
# capped at 100: a run whose error passes it has lost its orbit (or blown up), and its line leaves
# the panel there instead of flattening every other
set yrange [emin / 10 : (emax * 10 < 100 ? emax * 10 : 100)]
set xlabel "t (periods)"
set ylabel ylab
set multiplot layout nrow,ncol
do for [f=1:npanel] {
  ms = value("panel".f)
  set title value("ptitle".f) noenhanced
  plot for [m in ms] datadir."/".prefix.m.".dat" using 1:(column(col) > 0 ? column(col) : NaN) with linespoints lt mlt(m) ps 0.5 title m
}
unset multiplot

# Figure 9: the undamped bounce: energy ratio after the last bounce against dt, one panel per
# family (the methods of the collision study: numeric), all on the same axes.
# Variables set by steplab report: datadir, outfile, format (png|pdf), methods, numeric, springdts, largedt;
# styles.gp (written beside this script): each method's style, the panels npanel, panel1.., ptitle1..
if (format eq "png") { set terminal pngcairo enhanced size 1100,760 font ",11" } else { set terminal pdfcairo enhanced size 16cm,11cm font ",7" }
set output outfile
load "styles.gp"
set grid lc rgb "#dddddd"
set key top left samplen 3 noenhanced  # method names have underscores
set logscale x
rmin = 1e300; rmax = -1e300
do for [m in numeric] {
  stats datadir."/bounce_".m.".dat" using 2 nooutput
  rmin = STATS_min < rmin ? STATS_min : rmin; rmax = STATS_max > rmax ? STATS_max : rmax
}
pad = (rmax - rmin) * 0.1 + 1e-3
set yrange [rmin - pad : rmax + pad]
set multiplot layout 2,3
do for [f=1:npanel] {
  ms = ""
  do for [m in value("panel".f)] { if (in_list(m, numeric)) { ms = ms." ".m } }
  set title value("ptitle".f) noenhanced
  set xlabel (f > 3 || f + 3 > npanel ? "dt (s)" : "")
  set ylabel (f % 3 == 1 ? "E / E0 after the last bounce" : "")
  if (words(ms) > 0) {
    plot for [m in ms] datadir."/bounce_".m.".dat" using 1:2 with linespoints lt mlt(m) title m
  } else { set multiplot next }
}
unset multiplot

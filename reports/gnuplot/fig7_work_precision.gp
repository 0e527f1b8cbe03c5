# Figure 7: work-precision on the spring: final position error against measured run time, one
# panel per family, all on the same axes.
# Variables set by steplab report: datadir, outfile, format (png|pdf), methods, numeric, springdts, largedt;
# styles.gp (written beside this script): each method's style, the family panels nfam, fam1.., famname1..
if (format eq "png") { set terminal pngcairo enhanced size 1100,760 font ",11" } else { set terminal pdfcairo enhanced size 16cm,11cm font ",7" }
set output outfile
load "styles.gp"
set grid lc rgb "#dddddd"
set key top right samplen 3 noenhanced  # method names have underscores
set logscale xy
set format xy "10^{%L}"
emin = 1e300; emax = 0; tmin = 1e300; tmax = 0
do for [f=1:nfam] {
  do for [m in value("fam".f)] {
    stats datadir."/conv_".m.".dat" using 3:2 nooutput
    tmin = STATS_min_x < tmin ? STATS_min_x : tmin; tmax = STATS_max_x > tmax ? STATS_max_x : tmax
    emin = STATS_min_y > 0 && STATS_min_y < emin ? STATS_min_y : emin; emax = STATS_max_y > emax ? STATS_max_y : emax
  }
}
set xrange [tmin / 1.5 : tmax * 1.5]
set yrange [emin / 10 : emax * 10]
set multiplot layout 2,3
do for [f=1:nfam] {
  ms = value("fam".f)
  set title value("famname".f) noenhanced
  set xlabel (f > 3 || f + 3 > nfam ? "run time (s)" : "")
  set ylabel (f % 3 == 1 ? "error at t_{end} (m)" : "")
  plot for [m in ms] datadir."/conv_".m.".dat" using 3:2 with linespoints lt mlt(m) title m
}
unset multiplot

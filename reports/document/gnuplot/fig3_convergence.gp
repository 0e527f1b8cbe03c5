# Figure 3: final position error against dt on the spring, fitted slopes and reference slopes,
# one panel per family, all on the same axes.
# Variables set by steplab report: datadir, outfile, format (png|pdf), methods, numeric, springdts, largedt;
# styles.gp (written beside this script): each method's style, the panels npanel, panel1.., ptitle1..
if (format eq "png") { set terminal pngcairo enhanced size 1100,760 font ",11" } else { set terminal pdfcairo enhanced size 16cm,11cm font ",7" }
set output outfile
load "styles.gp"
set grid lc rgb "#dddddd"
set key top left samplen 3 noenhanced  # method names have underscores
set logscale xy
set format xy "10^{%L}"
# the same ranges in every panel: over every method's errors (and the reference slopes)
emin = 1e300; emax = 0; dmin = 1e300; dmax = 0
do for [f=1:npanel] {
  do for [m in value("panel".f)] {
    stats datadir."/conv_".m.".dat" using 1:2 nooutput
    dmin = STATS_min_x < dmin ? STATS_min_x : dmin; dmax = STATS_max_x > dmax ? STATS_max_x : dmax
    emin = STATS_min_y > 0 && STATS_min_y < emin ? STATS_min_y : emin; emax = STATS_max_y > emax ? STATS_max_y : emax
  }
}
set xrange [dmin / 1.5 : dmax * 1.5]
set yrange [emin / 10 : emax * 1e3]  # room for the key above the largest errors
set multiplot layout 2,3
do for [f=1:npanel] {
  ms = value("panel".f)
  set title value("ptitle".f) noenhanced
  set xlabel (f > 3 || f + 3 > npanel ? "dt (s)" : "")
  set ylabel (f % 3 == 1 ? "error at t_{end} (m)" : "")
  plot for [m in ms] datadir."/conv_".m.".dat" using 1:2 with points lt mlt(m) title m, \
       for [m in ms] datadir."/fit_".m.".dat" using 1:2 with lines lt mlt(m) dt 1 lw 2 notitle, \
       for [p=0:2] datadir."/reference_slopes.dat" index p using 1:2 with lines dt 2 lw 1 lc rgb "#888888" title (p == 0 ? "slopes 1, 2, 4" : "")
}
unset multiplot

# Figure 7: work-precision on the spring (left column) and the stiff chain (right column): the
# largest position error along a run against its cost (run time, or evaluations where the report
# is not timed); a row per family, the adaptive solvers (steplab's dopri5, Boost.Odeint's, CVODE's
# BDF) in the last; common axes down each column.
# Variables set by steplab report: datadir, outfile, format (png|pdf), xcol (3: seconds,
# 4: evaluations), xname, scene1/scene2 and their ranges xlo1, xhi1, ylo1, yhi1, ...;
# the panels npanel, panel1.., ptitle1.. (a family's methods, the adaptive solvers: a row each);
# styles.gp (written beside this script): each method's style.
load "styles.gp"
nrow = npanel
if (format eq "png") { set terminal pngcairo enhanced size 1000,280 * nrow font ",10" } else { eval sprintf("set terminal pdfcairo enhanced size 16cm,%.1fcm font ',6.5'", 3.4 * nrow) }
set output outfile
set grid lc rgb "#dddddd"
set key top right samplen 2.5 spacing 0.9 noenhanced  # method names have underscores
set logscale xy
set format xy "10^{%L}"
set multiplot layout nrow,2
do for [r=1:nrow] {
  ms = value("panel".r)
  do for [k=1:2] {
    set xrange [value("xlo".k) : value("xhi".k)]
    set yrange [value("ylo".k) : value("yhi".k)]
    set title value("ptitle".r).", ".value("scene".k) noenhanced
    set xlabel (r == nrow ? xname : "")
    set ylabel (k == 1 ? "largest error (m)" : "")
    plot for [m in ms] datadir."/wp_".value("scene".k)."_".m.".dat" using xcol:2 with linespoints lt mlt(m) title m
  }
}
unset multiplot

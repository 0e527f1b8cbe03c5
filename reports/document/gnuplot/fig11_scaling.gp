# Figure 11: the rope of N masses: each solver's whole-run cost at the target error against N,
# a panel per family and one for the adaptive solvers; in the last panel the explicit methods'
# stable step dt* against N (points) beside its 1/N prediction from the smallest N (dashed).
# Variables set by steplab report: datadir, outfile, format (png|pdf), costname, limited (the
# explicit methods with a finite dt* at every N), the panels npanel, panel1.., ptitle1.. (a family's
# methods, or the adaptive solvers, each with a cost at some N);
# styles.gp (written beside this script): each method's style.
load "styles.gp"
nrow = (npanel + 3) / 3
if (format eq "png") { set terminal pngcairo enhanced size 1100,330 * nrow font ",10" } else { eval sprintf("set terminal pdfcairo enhanced size 16cm,%.1fcm font ',6.5'", 4.2 * nrow) }
set output outfile
set grid lc rgb "#dddddd"
set key top left samplen 2.5 spacing 0.9 noenhanced  # method names have underscores
set logscale xy
set format y "10^{%L}"
set multiplot layout nrow,3
do for [f=1:npanel] {
  ms = value("panel".f)
  set title value("ptitle".f) noenhanced
  set xlabel "masses N"
  set ylabel costname
  plot for [m in ms] datadir."/scaling_".m.".dat" using 1:2 with linespoints lt mlt(m) title m
}
set title "explicit methods: dt* against N"
set key bottom left
set ylabel "dt* (s)"
if (words(limited) > 0) {
  plot for [m in limited] datadir."/scaling_".m.".dat" using 1:($4 > 0 && $4 < 1e300 ? $4 : 1/0) with points lt mlt(m) title m, \
       for [m in limited] datadir."/scaling_".m.".dat" using 1:($5 > 0 && $5 < 1e300 ? $5 : 1/0) with lines lt mlt(m) dt 2 notitle
} else {  # none among the report's methods: an empty panel that says so
  unset logscale
  set xrange [0:1]; set yrange [0:1]; unset xtics; unset ytics
  set label 1 "no explicit method of this report" at graph 0.5, 0.5 center
  plot -1 notitle
  unset label 1
}
unset multiplot

# A scene of run-time size refined: each solver's whole-run cost at the target error against the
# number of masses N, a panel per family and one for the adaptive solvers.
# Variables set by steplab report: datadir, outfile, format (png|svg|pdf), costname, the panels npanel,
# panel1.., ptitle1.. (each a family's methods, or the adaptive solvers, with a cost at some N);
# styles.gp: each solver's style.
ncol = npanel <= 3 ? npanel : npanel == 4 ? 2 : 3
nrow = (npanel + ncol - 1) / ncol
load "styles.gp"  # each method's style, the terminal and the fonts
eval terminal(340 * nrow + 60, 4.2 * nrow + 0.6)
set output outfile
set grid lc rgb "#dddddd"
set key below horizontal samplen 1.5 spacing 0.9 font kfont noenhanced  # solver names have underscores
set logscale xy
set format y "10^{%L}"
set xlabel "masses N"
set ylabel costname
# drawn twice: into a table for the ranges gnuplot picks, then with at most six ticks an axis
do for [pass=1:2] {
  if (pass == 1) { set table $ranges } else { set multiplot layout nrow,ncol }
  do for [f=1:npanel] {
    ms = value("panel".f)
    set title value("ptitle".f) noenhanced
    if (pass == 2) { eval tics("x", f, 1); eval tics("y", f, 1) }
    plot for [m in ms] datadir."/scaling_".m.".dat" using 1:2 with linespoints lt mlt(m) title m
    if (pass == 1) { eval keep_ranges(f) }
  }
  if (pass == 1) { unset table; set autoscale }
}
unset multiplot

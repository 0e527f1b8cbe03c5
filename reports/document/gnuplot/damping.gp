# The energy growth rate against damping at the sheet's large step: measured (points) on the
# predicted curves 2 ln(rho) / h from each method's step map (lines), a panel per family.
# Variables set by steplab report: datadir, outfile, format (png|svg|pdf), largedt, the panels npanel,
# panel1.., ptitle1..; styles.gp: each method's style.
ncol = npanel <= 3 ? npanel : npanel == 4 ? 2 : 3
nrow = (npanel + ncol - 1) / ncol
load "styles.gp"  # each method's style, the terminal and the fonts
eval terminal(336 * nrow + 60, 4.2 * nrow + 0.6)
set output outfile
set grid lc rgb "#dddddd"
set key below horizontal samplen 1.5 spacing 0.9 font kfont noenhanced  # method names have underscores
set xlabel "damping (kg/s)"
set ylabel "d ln E / dt (1/s)"
# drawn twice: into a table for the ranges gnuplot picks, then with at most six ticks an axis
do for [pass=1:2] {
  if (pass == 1) { set table $ranges } else { set multiplot layout nrow, ncol }
  do for [f=1:npanel] {
    ms = value("panel".f)
    set title value("ptitle".f) noenhanced
    if (pass == 2) { eval tics("x", f, 0); eval tics("y", f, 0) }
    plot for [m in ms] datadir."/predicted_".m.".dat" using 1:2 with lines lt mlt(m) notitle, \
         for [m in ms] datadir."/sweep_".m.".dat" using 1:2 with points lt mlt(m) title m
    if (pass == 1) { eval keep_ranges(f) }
  }
  if (pass == 1) { unset table; set autoscale }
}
unset multiplot

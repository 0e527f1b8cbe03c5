# The edge of stability over (dt, damping) on the spring, a panel per family: for each method the
# measured dt* of each damping's row of runs (points), the predicted one (a line) and where a row
# is stable again beyond it (open points).
# Variables set by steplab report: datadir, outfile, format (png|svg|pdf), dtmin and dtmax (the map's
# steps), the panels npanel, panel1.., ptitle1..; styles.gp: each method's style.
ncol = npanel <= 3 ? npanel : npanel == 4 ? 2 : 3
nrow = (npanel + ncol - 1) / ncol
load "styles.gp"  # each method's style, the terminal and the fonts
eval terminal(350 * nrow + 60, 4.4 * nrow + 0.6)
set output outfile
set grid lc rgb "#dddddd"
set key below horizontal samplen 1.5 spacing 0.9 font kfont noenhanced  # method names have underscores
set logscale x
set xrange [dtmin:dtmax]
set xlabel "dt (s)"
set ylabel "damping (kg/s)"
# drawn twice: into a table for the damping range gnuplot picks, then with at most six ticks on it
do for [pass=1:2] {
  if (pass == 1) { set table $ranges } else { set multiplot layout nrow, ncol }
  do for [f=1:npanel] {
    ms = value("panel".f)
    set title value("ptitle".f) noenhanced
    if (pass == 2) { eval tics("y", f, 0) }
    plot for [m in ms] datadir."/edge_".m.".dat" index 0 using 3:1 with lines lt mlt(m) dt 1 lw 1.5 notitle, \
         for [m in ms] datadir."/edge_".m.".dat" index 0 using 2:1 with points lt mlt(m) ps 0.5 title m, \
         for [m in ms] datadir."/edge_".m.".dat" index 1 using 2:1 with points lt mlt(m) pt 6 ps 0.6 notitle, \
         keyentry with points pt 6 ps 0.6 lc rgb "black" title "stable again"
    if (pass == 1) { eval keep_ranges(f) }
  }
  if (pass == 1) { unset table; set autoscale y }
}
unset multiplot

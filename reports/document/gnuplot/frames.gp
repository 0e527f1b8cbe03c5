# At a frame budget: the largest position error over the frames against the cost a frame (time,
# or spring visits where the report is not timed), each method a line through its splits of the
# budget (substeps x sweeps or CG iterations), the stable ones only.
# Variables set by steplab report: datadir, outfile, format (png|svg|pdf), xcol (3: seconds a frame,
# 4: spring visits a frame), xname, the panel panel1 (the methods) and ptitle1; styles.gp: each
# method's style.
load "styles.gp"  # each method's style, the terminal and the fonts
eval terminal(520, 8)
set output outfile
set grid lc rgb "#dddddd"
set key outside right vertical samplen 1.5 spacing 0.9 font kfont noenhanced  # method names have underscores
set logscale xy
set format xy "10^{%L}"
set xlabel xname
set ylabel "largest error over the frames"
set title ptitle1 noenhanced
ms = panel1
# drawn twice: into a table for the ranges gnuplot picks, then with at most six ticks an axis
do for [pass=1:2] {
  if (pass == 1) { set table $ranges } else { eval tics("x", 1, 1); eval tics("y", 1, 1) }
  plot for [m in ms] datadir."/frames_".m.".dat" using xcol:5 with linespoints lt mlt(m) title m
  if (pass == 1) { unset table; eval keep_ranges(1) }
}

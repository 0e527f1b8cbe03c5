# The undamped spring over a long run at the sheet's large step: E/E0 - 1 against time, linear
# axis, a panel per family (the methods whose energy stays bounded or drifts; those that blow up
# are left out). Markers every nth sample, staggered between methods.
# Variables set by steplab report: datadir, outfile, format (png|svg|pdf), largedt, reach (the y range
# is -reach .. reach), the panels npanel, panel1.., ptitle1..; styles.gp: each method's style.
ncol = npanel <= 3 ? npanel : npanel == 4 ? 2 : 3
nrow = (npanel + ncol - 1) / ncol
load "styles.gp"  # each method's style, the terminal and the fonts
eval terminal(322 * nrow + 60, 4.0 * nrow + 0.6)
set output outfile
set grid lc rgb "#dddddd"
set key below horizontal samplen 1.5 spacing 0.9 font kfont noenhanced  # method names have underscores
eval axis_tics("y", -reach, reach, 0)
set format y "%.2g"
set multiplot layout nrow, ncol
do for [f=1:npanel] {
  ms = value("panel".f)
  stats datadir."/energy_".word(ms, 1).".dat" using 1 nooutput
  nth = STATS_records > 20 ? int(STATS_records / 10) : 1
  set title value("ptitle".f) noenhanced
  set xlabel "t (s)"
  set ylabel "E/E0 - 1"
  plot for [j=1:words(ms)] datadir."/energy_".word(ms, j).".dat" using 1:2 with lines lt mlt(word(ms, j)) notitle, \
       for [j=1:words(ms)] datadir."/energy_".word(ms, j).".dat" using 1:2 every nth::((j - 1) * nth / words(ms)) with points lt mlt(word(ms, j)) notitle, \
       for [j=1:words(ms)] keyentry with linespoints lt mlt(word(ms, j)) title word(ms, j)
}
unset multiplot

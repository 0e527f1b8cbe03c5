# The cannon ball's path per method beside the exact parabola (the sheet's figure 1), a panel per
# family. Markers every nth sample, staggered between methods so that they do not hide each other.
# Variables set by steplab report: datadir, outfile, format (png|svg|pdf), the panels npanel, panel1..,
# ptitle1..; styles.gp: each method's style.
ncol = npanel <= 3 ? npanel : npanel == 4 ? 2 : 3
nrow = (npanel + ncol - 1) / ncol
load "styles.gp"  # each method's style, the terminal and the fonts
eval terminal(330 * nrow + 60, 4.2 * nrow + 0.6)
set output outfile
set grid lc rgb "#dddddd"
set key below horizontal samplen 1.5 spacing 0.9 font kfont noenhanced  # method names have underscores
set xlabel "x (m)"
set ylabel "y (m)"
# At most about four x labels a panel (a 5 cm panel holds four "1000"s): the tick step 1, 2 or 5
# times a power of ten.
stats datadir."/cannon_exact.dat" using 1 nooutput
span = STATS_max - STATS_min > 0 ? STATS_max - STATS_min : 1
decade = 10**floor(log10(span / 4))
xstep = (span / decade <= 4 ? 1 : span / decade <= 8 ? 2 : 5) * decade
set xtics xstep
# drawn twice: into a table for the height's range gnuplot picks, then with at most six ticks on it
do for [pass=1:2] {
  if (pass == 1) { set table $ranges } else { set multiplot layout nrow,ncol }
  do for [f=1:npanel] {
    ms = value("panel".f)
    stats datadir."/cannon_".word(ms, 1).".dat" using 1 nooutput
    nth = STATS_records > 20 ? int(STATS_records / 10) : 1
    set title value("ptitle".f) noenhanced
    if (pass == 2) { eval tics("y", f, 0) }
    plot datadir."/cannon_exact.dat" using 1:2 with lines dt 1 lw 4 lc rgb "#bbbbbb" title "exact", \
         for [j=1:words(ms)] datadir."/cannon_".word(ms, j).".dat" using 1:2 with lines lt mlt(word(ms, j)) notitle, \
         for [j=1:words(ms)] datadir."/cannon_".word(ms, j).".dat" using 1:2 every nth::((j - 1) * nth / words(ms)) with points lt mlt(word(ms, j)) notitle, \
         for [j=1:words(ms)] keyentry with linespoints lt mlt(word(ms, j)) title word(ms, j)
    if (pass == 1) { eval keep_ranges(f) }
  }
  if (pass == 1) { unset table; set autoscale y }
}
unset multiplot

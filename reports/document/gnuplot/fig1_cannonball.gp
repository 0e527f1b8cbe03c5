# Figure 1: the cannon ball's path per method beside the exact parabola (the sheet's figure 1),
# one panel per family. Markers every nth sample, staggered between methods so that they do not
# hide each other.
# Variables set by steplab report: datadir, outfile, format (png|pdf), methods, numeric, springdts, largedt;
# styles.gp (written beside this script): each method's style, the panels npanel, panel1.., ptitle1..
if (format eq "png") { set terminal pngcairo enhanced size 1100,680 font ",11" } else { set terminal pdfcairo enhanced size 16cm,9.6cm font ",7" }
set output outfile
load "styles.gp"
set grid lc rgb "#dddddd"
set key bottom center samplen 3 noenhanced  # method names have underscores
set xlabel "x (m)"
set ylabel "y (m)"
set multiplot layout 2,3
do for [f=1:npanel] {
  ms = value("panel".f)
  stats datadir."/cannon_".word(ms, 1).".dat" using 1 nooutput
  nth = STATS_records > 20 ? int(STATS_records / 10) : 1
  set title value("ptitle".f) noenhanced
  plot datadir."/cannon_exact.dat" using 1:2 with lines lw 4 lc rgb "#bbbbbb" title "exact", \
       for [j=1:words(ms)] datadir."/cannon_".word(ms, j).".dat" using 1:2 with lines lt mlt(word(ms, j)) notitle, \
       for [j=1:words(ms)] datadir."/cannon_".word(ms, j).".dat" using 1:2 every nth::((j - 1) * nth / words(ms)) with points lt mlt(word(ms, j)) notitle, \
       for [j=1:words(ms)] keyentry with linespoints lt mlt(word(ms, j)) title word(ms, j)
}
unset multiplot

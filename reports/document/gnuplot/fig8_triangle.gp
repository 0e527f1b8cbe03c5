# Figure 8: the falling triangle: height of its centre against time, per method, one panel per
# family (the methods of the collision study: numeric).
# Variables set by steplab report: datadir, outfile, format (png|pdf), methods, numeric, springdts, largedt;
# styles.gp (written beside this script): each method's style, the panels npanel, panel1.., ptitle1..
if (format eq "png") { set terminal pngcairo enhanced size 1100,760 font ",11" } else { set terminal pdfcairo enhanced size 16cm,11cm font ",7" }
set output outfile
load "styles.gp"
set grid lc rgb "#dddddd"
set key top right samplen 3 noenhanced  # method names have underscores
set multiplot layout 2,3
do for [f=1:npanel] {
  ms = ""
  do for [m in value("panel".f)] { if (in_list(m, numeric)) { ms = ms." ".m } }
  set title value("ptitle".f) noenhanced
  set xlabel (f > 3 || f + 3 > npanel ? "t (s)" : "")
  set ylabel (f % 3 == 1 ? "centre height (m)" : "")
  if (words(ms) > 0) {
    stats datadir."/triangle_".word(ms, 1).".dat" using 1 nooutput
    nth = STATS_records > 20 ? int(STATS_records / 10) : 1
    plot for [j=1:words(ms)] datadir."/triangle_".word(ms, j).".dat" using 1:2 with lines lt mlt(word(ms, j)) lw 1.2 notitle, \
       for [j=1:words(ms)] datadir."/triangle_".word(ms, j).".dat" using 1:2 every nth::((j - 1) * nth / words(ms)) with points lt mlt(word(ms, j)) notitle, \
       for [j=1:words(ms)] keyentry with linespoints lt mlt(word(ms, j)) lw 1.2 title word(ms, j)
  } else { set multiplot next }
}
unset multiplot

# Figure 4: energy ratio against time without damping at the large step, log scale, one panel per
# family.
# Variables set by steplab report: datadir, outfile, format (png|pdf), methods, numeric, springdts, largedt;
# styles.gp (written beside this script): each method's style, the panels npanel, panel1.., ptitle1..
if (format eq "png") { set terminal pngcairo enhanced size 1100,760 font ",11" } else { set terminal pdfcairo enhanced size 16cm,11cm font ",7" }
set output outfile
load "styles.gp"
set grid lc rgb "#dddddd"
set key top left samplen 3 noenhanced  # method names have underscores
set offsets graph 0, graph 0, graph 0.35, graph 0  # room for the key above the curves
set logscale y
set format y "10^{%L}"
set multiplot layout 2,3
do for [f=1:npanel] {
  ms = value("panel".f)
  stats datadir."/energy_".word(ms, 1).".dat" using 1 nooutput
  nth = STATS_records > 20 ? int(STATS_records / 10) : 1
  set title value("ptitle".f).", damping 0, dt = ".largedt noenhanced
  set xlabel (f > 3 || f + 3 > npanel ? "t (s)" : "")
  set ylabel (f % 3 == 1 ? "E / E0" : "")
  plot for [j=1:words(ms)] datadir."/energy_".word(ms, j).".dat" using 1:2 with lines lt mlt(word(ms, j)) notitle, \
       for [j=1:words(ms)] datadir."/energy_".word(ms, j).".dat" using 1:2 every nth::((j - 1) * nth / words(ms)) with points lt mlt(word(ms, j)) notitle, \
       for [j=1:words(ms)] keyentry with linespoints lt mlt(word(ms, j)) title word(ms, j)
}
unset multiplot

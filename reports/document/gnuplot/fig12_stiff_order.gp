# Figure 12: the fitted order of the largest position error against the stiffness of the stiffened
# scene (the mass pulled to a moving target), a panel per family, each fit's bound as an error
# bar; dashed, each method's theory: its order p at the left, its stiff-limit order at the right
# (analysis/order_reduction.hpp). A method stable only at low stiffness has points only there.
# Variables set by steplab report: datadir, outfile, format (png|pdf), kmin and kmax (the x range);
# styles.gp (written beside this script): each method's style, the panels npanel, panel1.., ptitle1..
if (format eq "png") { set terminal pngcairo enhanced size 1100,620 font ",11" } else { set terminal pdfcairo enhanced size 16cm,9.5cm font ",7" }
set output outfile
load "styles.gp"
set grid lc rgb "#dddddd"
set key top right samplen 3 noenhanced  # method names have underscores
set logscale x
set format x "10^{%L}"
set xrange [kmin : kmax]
set yrange [0 : 6.5]
set multiplot layout 2,3
do for [f=1:npanel] {
  ms = value("panel".f)
  set title value("ptitle".f) noenhanced
  set xlabel (f > 3 || f + 3 > npanel ? "stiffness k" : "")
  set ylabel (f % 3 == 1 ? "fitted order" : "")
  plot for [m in ms] datadir."/stiff_".m.".dat" using 1:2:3:4 with yerrorlines lt mlt(m) title m, \
       for [m in ms] datadir."/stiff_theory_".m.".dat" index 0 using 1:2 with lines lt mlt(m) dt 2 lw 2 notitle, \
       for [m in ms] datadir."/stiff_theory_".m.".dat" index 1 using 1:2 with lines lt mlt(m) dt 2 lw 2 notitle
}
unset multiplot

# The fitted order of the largest position error against the stiffness of the stiffened scene (the
# mass pulled to a moving target), a panel per family, each fit's bound as an error bar; dashed,
# each method's theory: its order p at the left, its stiff-limit order at the right
# (analysis/studies/order_reduction.hpp). A method stable only at low stiffness has points only there.
# Variables set by steplab report: datadir, outfile, format (png|svg|pdf), kmin and kmax (the x
# range), the panels npanel, panel1.., ptitle1..; styles.gp: each method's style.
ncol = npanel <= 3 ? npanel : npanel == 4 ? 2 : 3
nrow = (npanel + ncol - 1) / ncol
load "styles.gp"  # each method's style, the terminal and the fonts
eval terminal(330 * nrow + 60, 4.2 * nrow + 0.6)
set output outfile
set grid lc rgb "#dddddd"
set key below horizontal samplen 1.5 spacing 0.9 font kfont noenhanced  # method names have underscores
set logscale x
set format x "10^{%L}"
eval axis_tics("x", kmin, kmax, 1)
set yrange [0 : 6.5]
set ytics 2
set mytics 2
set xlabel "stiffness k"
set ylabel "fitted order"
set multiplot layout nrow,ncol
do for [f=1:npanel] {
  ms = value("panel".f)
  set title value("ptitle".f) noenhanced
  plot for [m in ms] datadir."/stiff_".m.".dat" using 1:2:3:4 with yerrorlines lt mlt(m) title m, \
       for [m in ms] datadir."/stiff_theory_".m.".dat" index 0 using 1:2 with lines lt mlt(m) dt 2 lw 2 notitle, \
       for [m in ms] datadir."/stiff_theory_".m.".dat" index 1 using 1:2 with lines lt mlt(m) dt 2 lw 2 notitle
}
unset multiplot

# Figure 5: energy growth rate against damping at the large step: measured (points) on the
# predicted curves 2 ln(rho) / h (lines), one panel per family.
# Variables set by steplab report: datadir, outfile, format (png|pdf), methods, numeric, springdts, largedt;
# styles.gp (written beside this script): each method's style, the panels npanel, panel1.., ptitle1..
if (format eq "png") { set terminal pngcairo enhanced size 1100,760 font ",11" } else { set terminal pdfcairo enhanced size 16cm,11cm font ",7" }
set output outfile
load "styles.gp"
set grid lc rgb "#dddddd"
set key top right samplen 3 noenhanced  # method names have underscores
set multiplot layout 2,3
do for [f=1:npanel] {
  ms = value("panel".f)
  set title value("ptitle".f).", dt = ".largedt noenhanced
  set xlabel (f > 3 || f + 3 > npanel ? "damping gamma (kg/s)" : "")
  set ylabel (f % 3 == 1 ? "d ln E / dt (1/s)" : "")
  plot for [m in ms] datadir."/predicted_".m.".dat" using 1:2 with lines lt mlt(m) notitle, \
       for [m in ms] datadir."/sweep_".m.".dat" using 1:2 with points lt mlt(m) title m
}
unset multiplot

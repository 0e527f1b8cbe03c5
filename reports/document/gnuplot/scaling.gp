# A scene of run-time size refined: each solver's whole-run cost at the target error against the
# number of masses N, a panel per family and one for the adaptive solvers.
# Variables set by steplab report: datadir, outfile, format (png|pdf), costname, the panels npanel,
# panel1.., ptitle1.. (each a family's methods, or the adaptive solvers, with a cost at some N);
# styles.gp: each solver's style.
ncol = npanel <= 3 ? npanel : npanel == 4 ? 2 : 3
nrow = (npanel + ncol - 1) / ncol
if (format eq "png") { set terminal pngcairo enhanced size 1100,340 * nrow + 60 font ",12" } else { eval sprintf("set terminal pdfcairo enhanced size 16cm,%.1fcm font ',10'", 4.2 * nrow + 0.6) }
set output outfile
kfont = format eq "png" ? ",11" : ",8"  # the keys and labels: 8 pt at print size
load "styles.gp"
set grid lc rgb "#dddddd"
set key below horizontal samplen 1.5 spacing 0.9 font kfont noenhanced  # solver names have underscores
set logscale xy
set format y "10^{%L}"
set xlabel "masses N"
set ylabel costname
set multiplot layout nrow,ncol
do for [f=1:npanel] {
  ms = value("panel".f)
  set title value("ptitle".f) noenhanced
  plot for [m in ms] datadir."/scaling_".m.".dat" using 1:2 with linespoints lt mlt(m) title m
}
unset multiplot

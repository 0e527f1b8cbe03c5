# Work against precision: the largest position error along a run against its cost (run time, or
# force evaluations where the report is not timed), a row per scene (the spring, the stiff chain)
# with common axes along it; its panels: the explicit fixed-step methods, the implicit ones, the
# adaptive solvers (steplab's dopri5, Boost.Odeint's, CVODE's set-ups).
# Variables set by steplab report: datadir, outfile, format (png|pdf), xcol (3: seconds, 4: force
# evaluations), xname, the panels npanel, panel1.., ptitle1.., and per panel k its scene pscenek
# and ranges xlok, xhik, ylok, yhik; styles.gp: each solver's style.
ncol = npanel <= 3 ? npanel : npanel == 4 ? 2 : 3
nrow = (npanel + ncol - 1) / ncol
if (format eq "png") { set terminal pngcairo enhanced size 1100,360 * nrow + 60 font ",12" } else { eval sprintf("set terminal pdfcairo enhanced size 16cm,%.1fcm font ',10'", 4.6 * nrow + 0.6) }
set output outfile
kfont = format eq "png" ? ",11" : ",8"  # the keys and labels: 8 pt at print size
load "styles.gp"
set grid lc rgb "#dddddd"
set key below horizontal samplen 1.5 spacing 0.9 font kfont noenhanced  # solver names have underscores
set logscale xy
set format xy "10^{%L}"
set xlabel xname
set ylabel "largest error (m)"
set multiplot layout nrow,ncol
do for [k=1:npanel] {
  ms = value("panel".k)
  set xrange [value("xlo".k) : value("xhi".k)]
  set yrange [value("ylo".k) : value("yhi".k)]
  set title value("ptitle".k) noenhanced
  plot for [m in ms] datadir."/wp_".value("pscene".k)."_".m.".dat" using xcol:2 with linespoints lt mlt(m) title m
}
unset multiplot

# Work against precision: the largest position error along a run against its cost (run time, or
# force evaluations where the report is not timed), a row per scene (the spring, the stiff chain)
# with common axes along it; its panels: the explicit fixed-step methods, the implicit ones, the
# adaptive solvers (steplab's dopri5, Boost.Odeint's, CVODE's set-ups).
# Variables set by steplab report: datadir, outfile, format (png|svg|pdf), xcol (3: seconds, 4: force
# evaluations), xname, the panels npanel, panel1.., ptitle1.., and per panel k its scene pscenek
# and ranges xlok, xhik, ylok, yhik; styles.gp: each solver's style.
ncol = npanel <= 3 ? npanel : npanel == 4 ? 2 : 3
nrow = (npanel + ncol - 1) / ncol
load "styles.gp"  # each method's style, the terminal and the fonts
eval terminal(360 * nrow + 60, 4.6 * nrow + 0.6)
set output outfile
set grid lc rgb "#dddddd"
set key below horizontal samplen 1.5 spacing 0.9 font kfont noenhanced  # solver names have underscores
set logscale xy
set format xy "10^{%L}"
set xlabel xname
set ylabel "largest error (m)"
set multiplot layout nrow,ncol
do for [k=1:npanel] {
  ms = value("panel".k)
  eval axis_tics("x", value("xlo".k), value("xhi".k), 1)
  eval axis_tics("y", value("ylo".k), value("yhi".k), 1)
  set title value("ptitle".k) noenhanced
  plot for [m in ms] datadir."/wp_".value("pscene".k)."_".m.".dat" using xcol:2 with linespoints lt mlt(m) title m
}
unset multiplot

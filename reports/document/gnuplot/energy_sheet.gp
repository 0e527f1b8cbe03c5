# E/E0 of the sheet's methods at its large step over a long run, on a log axis, beside the exact
# flow's (grey): undamped (left; the exact E/E0 is 1) and at the spring's damping (right).
# Variables set by steplab report: datadir, outfile, format (png|svg|pdf), largedt, the panels
# npanel (2), panel1, panel2 (the same methods), ptitle1, ptitle2; styles.gp: each method's style.
load "styles.gp"  # each method's style, the terminal and the fonts
eval terminal(330, 5.0)
set output outfile
set grid lc rgb "#dddddd"
set key at screen 0.995, 0.55 right center vertical Left reverse samplen 2 font kfont noenhanced  # right of both panels
set logscale y
set format y "10^{%T}"
set xlabel "t (s)"
set ylabel "E/E0"
ms = panel1
files = "sheet_ sheet_damped_"
# One y range for both panels, its decades labelled at most six times.
lo = 1; hi = 1
do for [f=1:2] {
  do for [m in ms] {
    stats datadir."/".word(files, f).m.".dat" using 2 nooutput
    lo = STATS_min < lo ? STATS_min : lo; hi = STATS_max > hi ? STATS_max : hi
  }
  stats datadir."/sheet_exact.dat" using (column(f + 1)) nooutput
  lo = STATS_min < lo ? STATS_min : lo
}
dlo = floor(log10(lo)); dhi = ceil(log10(hi))
dlo = dhi - dlo < 2 ? dlo - 1 : dlo; dhi = dhi - dlo < 2 ? dhi + 1 : dhi
set yrange [10**dlo : 10**dhi]
set ytics 10**ceil((dhi - dlo) / 5.0)
set mytics 1
set multiplot layout 1, 2 margins 0.08, 0.8, 0.17, 0.88 spacing 0.1, 0
do for [f=1:2] {
  set title value("ptitle".f) noenhanced
  stats datadir."/".word(files, f).word(ms, 1).".dat" using 1 nooutput
  nth = STATS_records > 20 ? int(STATS_records / 10) : 1
  if (f == 1) { set key } else { unset key }
  plot datadir."/sheet_exact.dat" using 1:(column(f + 1)) with lines dt 1 lw 4 lc rgb "#bbbbbb" title "exact", \
       for [j=1:words(ms)] datadir."/".word(files, f).word(ms, j).".dat" using 1:2 with lines lt mlt(word(ms, j)) lw 1.2 notitle, \
       for [j=1:words(ms)] datadir."/".word(files, f).word(ms, j).".dat" using 1:2 every nth::((j - 1) * nth / words(ms)) with points lt mlt(word(ms, j)) notitle, \
       for [j=1:words(ms)] keyentry with linespoints lt mlt(word(ms, j)) lw 1.2 title word(ms, j)
}
unset multiplot

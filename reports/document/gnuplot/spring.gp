# The spring's height y(t) per method against the exact solution: a column per family, a row per
# step (a row per family and a column per step where there are more than three families).
# Variables set by steplab report: datadir, outfile, format (png|svg|pdf), springdts (the steps), the
# panels npanel, panel1.., ptitle1..; styles.gp: each method's style.
n = words(springdts)
load "styles.gp"  # each method's style, the terminal and the fonts
wide = npanel <= 3  # families across
rows = wide ? n : npanel
cols = wide ? npanel : n
keycm = 1.8  # the keys' band under the panels, when families are across
eval terminal(190 * rows + 90, 2.8 * rows + (wide ? keycm : 0.6))
set output outfile
set grid lc rgb "#dddddd"
set ylabel "y (m)"
bottom = wide ? keycm / (2.8 * rows + keycm) : 0.08
if (wide) {
  set multiplot layout rows, cols margins 0.07, 0.98, bottom + 0.06, 0.94 spacing 0.07, 0.12
} else {
  set multiplot layout rows, cols
}
do for [cell=1:rows * cols] {
  r = (cell - 1) / cols + 1
  c = (cell - 1) % cols + 1
  f = wide ? c : r
  k = wide ? r : c
  ms = value("panel".f)
  set xlabel (r == rows ? "t (s)" : "")
  if (wide && r == rows) {  # under each family's column, its methods
    set key at screen 0.07 + (c - 0.5) * 0.91 / cols, 0.005 center bottom vertical Left reverse samplen 2 font kfont noenhanced
  } else {
    if (!wide && k == n) { set key outside right top vertical samplen 2 font kfont noenhanced } else { unset key }
  }
  set title value("ptitle".f).", dt = ".word(springdts, k) noenhanced
  stats datadir."/spring".(k-1)."_".word(ms, 1).".dat" using 1 nooutput
  nth = STATS_records > 20 ? int(STATS_records / 12) : 1
  span = 0  # at most six labels on y: a step of 1, 2 or 5 m
  do for [m in ms] {
    stats datadir."/spring".(k-1)."_".m.".dat" using 2 nooutput
    span = STATS_max - STATS_min > span ? STATS_max - STATS_min : span
  }
  ystep = span <= 5 ? 1 : span <= 10 ? 2 : 5
  set ytics ystep
  plot datadir."/spring_exact.dat" using 1:2 with lines dt 1 lw 4 lc rgb "#bbbbbb" title "exact", \
       for [j=1:words(ms)] datadir."/spring".(k-1)."_".word(ms, j).".dat" using 1:2 with lines lt mlt(word(ms, j)) lw 1.2 notitle, \
       for [j=1:words(ms)] datadir."/spring".(k-1)."_".word(ms, j).".dat" using 1:2 every nth::((j - 1) * nth / words(ms)) with points lt mlt(word(ms, j)) notitle, \
       for [j=1:words(ms)] keyentry with linespoints lt mlt(word(ms, j)) lw 1.2 title word(ms, j)
}
unset multiplot

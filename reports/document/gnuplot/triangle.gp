# The falling triangle with the sheet's methods: its lowest corner's height against the ground
# (y = -1, grey; left) and E/E0 (right) over t.
# Variables set by steplab report: datadir, outfile, format (png|svg|pdf), the panels npanel (2),
# panel1, panel2 (the same methods), ptitle1, ptitle2; styles.gp: each method's style.
load "styles.gp"  # each method's style, the terminal and the fonts
eval terminal(330, 5.0)
set output outfile
set grid lc rgb "#dddddd"
set key at screen 0.995, 0.55 right center vertical Left reverse samplen 2 font kfont noenhanced  # right of both panels
set xlabel "t (s)"
ms = panel1
stats datadir."/triangle_".word(ms, 1).".dat" using 1 nooutput
nth = STATS_records > 20 ? int(STATS_records / 10) : 1
set multiplot layout 1, 2 margins 0.08, 0.8, 0.17, 0.88 spacing 0.1, 0
set title ptitle1 noenhanced
set ylabel "lowest corner y (m)"
set yrange [-1.25:-0.25]
set ytics 0.25
plot -1 with lines dt 1 lw 4 lc rgb "#bbbbbb" title "ground", \
     for [j=1:words(ms)] datadir."/triangle_".word(ms, j).".dat" using 1:2 with lines lt mlt(word(ms, j)) lw 1.2 notitle, \
     for [j=1:words(ms)] datadir."/triangle_".word(ms, j).".dat" using 1:2 every nth::((j - 1) * nth / words(ms)) with points lt mlt(word(ms, j)) notitle, \
     for [j=1:words(ms)] keyentry with linespoints lt mlt(word(ms, j)) lw 1.2 title word(ms, j)
unset key
set title ptitle2 noenhanced
set ylabel "E/E0"
set autoscale y
# E/E0's range: every method's, for at most six ticks on it
elo = 1e300; ehi = -1e300
do for [m in ms] {
  stats datadir."/triangle_".m.".dat" using 3 nooutput
  elo = STATS_min < elo ? STATS_min : elo; ehi = STATS_max > ehi ? STATS_max : ehi
}
eval span_tics("y", elo, ehi)
plot for [j=1:words(ms)] datadir."/triangle_".word(ms, j).".dat" using 1:3 with lines lt mlt(word(ms, j)) lw 1.2 notitle, \
     for [j=1:words(ms)] datadir."/triangle_".word(ms, j).".dat" using 1:3 every nth::((j - 1) * nth / words(ms)) with points lt mlt(word(ms, j)) notitle
unset multiplot

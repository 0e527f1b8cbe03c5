# The cloth at a frame budget, seen from the side: the middle column of masses (y across from the
# pinned edge, z up, in metres, on equal axes) at three frames, the reference in black and each
# family's cheapest stable set-up in its method's style.
# Variables set by steplab report: datadir, outfile, format (png|svg|pdf), the panels npanel (3),
# panel1.. (the same methods), ptitle1.. (the frames' times); styles.gp: each method's style.
load "styles.gp"  # each method's style, the terminal and the fonts
eval terminal(300, 4.6)
set output outfile
set grid lc rgb "#dddddd"
set key at graph 0.02, 0.97 left top vertical Left reverse samplen 2 spacing 0.9 font kfont noenhanced  # in the first panel's empty half; method names have underscores
ms = panel1
# one range for every panel, over every curve and frame: the sheet's size is the same in each
ylo = 1e300; yhi = -1e300; zlo = 1e300; zhi = -1e300
do for [f in "reference ".ms] {
  stats datadir."/profile_".f.".dat" using 1:2 nooutput
  ylo = STATS_min_x < ylo ? STATS_min_x : ylo; yhi = STATS_max_x > yhi ? STATS_max_x : yhi
  zlo = STATS_min_y < zlo ? STATS_min_y : zlo; zhi = STATS_max_y > zhi ? STATS_max_y : zhi
}
eval span_tics("x", ylo, yhi)
eval span_tics("y", zlo, zhi)
set size ratio -1
set xlabel "y (m)"
set ylabel "z (m)"
set multiplot layout 1, npanel margins 0.07, 0.98, 0.2, 0.9 spacing 0.06, 0
do for [p=1:npanel] {
  set title value("ptitle".p) noenhanced
  if (p > 1) { unset ylabel; set format y "" } else { set format y "%g" }
  if (p > 1) { unset key }
  plot datadir."/profile_reference.dat" index (p - 1) using 1:2 with lines lw 3 lc rgb "black" title "reference", \
       for [m in ms] datadir."/profile_".m.".dat" index (p - 1) using 1:2 with linespoints lt mlt(m) title m
}
unset multiplot

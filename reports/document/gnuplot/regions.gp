# Stability regions in z = h lambda, a panel per family with a scalar stability function: each
# method's region (|R(z)| <= 1, or the root condition) lightly filled in its colour, so that nested
# regions show (every other grid point: the translucent images are most of the figure's drawing
# time, four times less so), and its edge drawn in its colour and dash (gnuplot's contour of the region's 0/1
# grid at 1/2, taken into a datablock first); the spring's eigenvalue ray (red, crosses) and, per
# method, where it leaves the region at the predicted dt* and where it enters it again (points).
# Variables set by steplab report: datadir, outfile, format (png|svg|pdf), the panels npanel,
# panel1.. (methods), ptitle1.. (family), and rgb_<method> (its colour as 0xRRGGBB).
load "styles.gp"  # each method's style, the terminal and the fonts
# the ray's far end (before the ranges, which stats would keep to), for its crosses
stats datadir."/ray.dat" every ::1::1 using 1 nooutput
rx = STATS_min
stats datadir."/ray.dat" every ::1::1 using 2 nooutput
ry = STATS_min
eval terminal(950, 11.5)
set output outfile
unset colorbox
set xrange [-7:3]
set yrange [-5:5]
set size ratio -1
set xtics 2
set ytics 2
set grid front lc rgb "#bbbbbb"
set xlabel "Re z"
set ylabel "Im z"
set key outside right top vertical samplen 1.5 font kfont noenhanced
red(c) = int(c / 65536) % 256
green(c) = int(c / 256) % 256
blue(c) = c % 256
# each region's edge: its contour at 1/2 into the datablock $edge_<method>
set contour base
set cntrparam levels discrete 0.5
unset surface
do for [f=1:npanel] {
  do for [m in value("panel".f)] {
    eval sprintf("set table $edge_%s", m)
    splot datadir."/region_".m.".dat" using 1:2:3 with lines notitle
    unset table
  }
}
unset contour
set surface
set multiplot layout 2,2
do for [f=1:npanel] {
  ms = value("panel".f)
  set title value("ptitle".f) noenhanced
  plot for [m in ms] datadir."/region_".m.".dat" using 1:2:(red(value("rgb_".m))):(green(value("rgb_".m))):(blue(value("rgb_".m))):($3 * 40) every 2:2 with rgbalpha notitle, \
       for [m in ms] "$edge_".m using 1:2 with lines lt mlt(m) lw 2 title m, \
       [t=0:1:0.02] '+' using (t * rx):(t * ry) with linespoints dt 1 lw 2 pt 2 ps 0.5 pi 4 lc rgb "#C0392B" title "spring's ray", \
       for [m in ms] datadir."/mark_".m.".dat" using 1:2 with points pt 7 ps 0.9 lc rgb sprintf("#%06X", value("rgb_".m)) notitle, \
       for [m in ms] datadir."/mark_".m.".dat" using 1:2 with points pt 6 ps 0.9 lc rgb "black" notitle
}
unset multiplot

# Stability regions in z = h lambda, a panel per family with a scalar stability function: each
# method's region (|R(z)| <= 1, or the root condition) filled in its colour, translucent so that
# nested regions show; the spring's eigenvalue ray (red) and, per method, where it leaves the
# region at the predicted dt* and where it enters it again (points).
# Variables set by steplab report: datadir, outfile, format (png|svg|pdf), the panels npanel,
# panel1.. (methods), ptitle1.. (family), and rgb_<method> (its colour as 0xRRGGBB).
load "styles.gp"  # each method's style, the terminal and the fonts
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
set multiplot layout 2,2
do for [f=1:npanel] {
  ms = value("panel".f)
  set title value("ptitle".f) noenhanced
  plot for [m in ms] datadir."/region_".m.".dat" using 1:2:(red(value("rgb_".m))):(green(value("rgb_".m))):(blue(value("rgb_".m))):($3 * 70) with rgbalpha notitle, \
       for [m in ms] keyentry with boxes fs solid 0.5 lc rgb sprintf("#%06X", value("rgb_".m)) title m, \
       datadir."/ray.dat" using 1:2 with lines lw 2 lc rgb "#C0392B" title "spring's ray", \
       for [m in ms] datadir."/mark_".m.".dat" using 1:2 with points pt 7 ps 0.9 lc rgb sprintf("#%06X", value("rgb_".m)) notitle, \
       for [m in ms] datadir."/mark_".m.".dat" using 1:2 with points pt 6 ps 0.9 lc rgb "black" notitle
}
unset multiplot

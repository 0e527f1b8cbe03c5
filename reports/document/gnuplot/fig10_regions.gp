# Figure 10: stability regions in the complex plane z = h lambda, one panel per method with a
# scalar stability function (shaded: stable), the spring's eigenvalue ray and dt* on it.
# Variables set by steplab report: datadir, outfile, format (png|pdf), methods, numeric, springdts, largedt,
# and for this figure regions (the methods drawn).
if (format eq "png") { set terminal pngcairo enhanced size 1100,850 font ",11" } else { set terminal pdfcairo enhanced size 16cm,12.4cm font ",7" }
set output outfile
unset key
set palette defined (0 "#f4f4f4", 1 "#8fb3e0")
unset colorbox
set cbrange [0:1]
set xrange [-7:3]
set yrange [-5:5]
set size ratio -1
set xtics 2
set ytics 2
set grid front lc rgb "#bbbbbb"
n = words(regions)
set multiplot layout 3,(n+2)/3
do for [i=1:n] {
  m = word(regions, i)
  set title m noenhanced
  plot datadir."/region_".m.".dat" using 1:2:3 with image, \
       datadir."/ray.dat" using 1:2 with lines lw 1.5 dt 2 lc rgb "black", \
       datadir."/mark_".m.".dat" using 1:2 with points pt 7 ps 0.8 lc rgb "#c0392b"
}
unset multiplot

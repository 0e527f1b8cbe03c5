# Figure 6: stability maps per method over (dt, damping): measured stable (dark) or not
# (light), and the predicted boundary dt* (black line).
# Variables set by steplab report: datadir, outfile, format (png|pdf), methods, numeric, springdts, largedt.
if (format eq "png") { set terminal pngcairo enhanced size 1100,680 font ",12" } else { set terminal pdfcairo enhanced size 16cm,9.6cm font ",8" }
set output outfile
set grid lc rgb "#dddddd"
set key outside right top samplen 2 noenhanced  # method names have underscores
unset key
# x is log10(dt): an image needs a uniform grid
set xtics ("0.001" -3, "0.01" -2, "0.1" -1, "1" 0, "10" 1, "100" 2)
set palette defined (0 "#f6d5d5", 1 "#3b6fb6")
unset colorbox
set cbrange [0:1]
set autoscale xfix
set autoscale yfix
n = words(methods)
set multiplot layout 2,(n+1)/2
do for [i=1:n] {
  m = word(methods, i)
  set title m noenhanced
  set xlabel "dt"
  set ylabel "damping"
  plot datadir."/map_".m.".dat" using (log10($1)):2:3 with image, \
       datadir."/boundary_".m.".dat" using (log10($1)):2 with lines lw 2 lc rgb "black"
}
unset multiplot

# Figure 8: the falling triangle: height of its centre against time, per method.
# Variables set by steplab report: datadir, outfile, format (png|pdf), methods, numeric, springdts, largedt.
if (format eq "png") { set terminal pngcairo enhanced size 1100,680 font ",12" } else { set terminal pdfcairo enhanced size 16cm,9.6cm font ",8" }
set output outfile
set grid lc rgb "#dddddd"
set key outside right top samplen 2 noenhanced  # method names have underscores
set xlabel "t (s)"
set ylabel "centre height (m)"
plot for [m in numeric] datadir."/triangle_".m.".dat" using 1:2 with lines lw 1.2 title m

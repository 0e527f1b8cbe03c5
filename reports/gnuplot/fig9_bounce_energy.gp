# Figure 9: the undamped bounce: energy ratio after the last bounce against dt.
# Variables set by steplab report: datadir, outfile, format (png|pdf), methods, numeric, springdts, largedt.
if (format eq "png") { set terminal pngcairo enhanced size 1100,680 font ",12" } else { set terminal pdfcairo enhanced size 16cm,9.6cm font ",8" }
set output outfile
set grid lc rgb "#dddddd"
set key outside right top samplen 2 noenhanced  # method names have underscores
set logscale x
set xlabel "dt (s)"
set ylabel "E / E0 after the last bounce"
plot for [m in numeric] datadir."/bounce_".m.".dat" using 1:2 with linespoints pt 7 lw 1.5 title m

# Figure 7: work-precision on the spring: final position error against measured run time.
# Variables set by steplab report: datadir, outfile, format (png|pdf), methods, numeric, springdts, largedt.
if (format eq "png") { set terminal pngcairo enhanced size 1100,680 font ",12" } else { set terminal pdfcairo enhanced size 16cm,9.6cm font ",8" }
set output outfile
set grid lc rgb "#dddddd"
set key outside right top samplen 2 noenhanced  # method names have underscores
set logscale xy
set format xy "10^{%L}"
set xlabel "run time (s)"
set ylabel "error at t_end (m)"
plot for [m in methods] datadir."/conv_".m.".dat" using 3:2 with linespoints pt 7 ps 0.6 lw 1.2 title m

# Figure 4: energy ratio against time without damping at the large step, log scale.
# Variables set by steplab report: datadir, outfile, format (png|pdf), methods, numeric, springdts, largedt.
if (format eq "png") { set terminal pngcairo enhanced size 1100,680 font ",12" } else { set terminal pdfcairo enhanced size 16cm,9.6cm font ",8" }
set output outfile
set grid lc rgb "#dddddd"
set key outside right top samplen 2 noenhanced  # method names have underscores
set logscale y
set format y "10^{%L}"
set xlabel "t (s)"
set ylabel "E / E0"
set title "damping 0, dt = ".largedt
plot for [m in methods] datadir."/energy_".m.".dat" using 1:2 with lines lw 1.5 title m

# Figure 1: the cannon ball's path per method beside the exact parabola (the sheet's figure 1).
# Variables set by steplab report: datadir, outfile, format (png|pdf), methods, numeric, springdts, largedt.
if (format eq "png") { set terminal pngcairo enhanced size 1100,680 font ",12" } else { set terminal pdfcairo enhanced size 16cm,9.6cm font ",8" }
set output outfile
set grid lc rgb "#dddddd"
set key outside right top samplen 2 noenhanced  # method names have underscores
set xlabel "x (m)"
set ylabel "y (m)"
plot datadir."/cannon_exact.dat" using 1:2 with lines lw 4 lc rgb "#bbbbbb" title "exact", \
     for [m in methods] datadir."/cannon_".m.".dat" using 1:2 with lines lw 1.5 title m

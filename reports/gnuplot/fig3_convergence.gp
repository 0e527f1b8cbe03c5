# Figure 3: final position error against dt on the spring, fitted slopes and reference slopes.
# Variables set by steplab report: datadir, outfile, format (png|pdf), methods, numeric, springdts, largedt.
if (format eq "png") { set terminal pngcairo enhanced size 1100,680 font ",12" } else { set terminal pdfcairo enhanced size 16cm,9.6cm font ",8" }
set output outfile
set grid lc rgb "#dddddd"
set key outside right top samplen 2 noenhanced  # method names have underscores
set logscale xy
set format xy "10^{%L}"
set xlabel "dt (s)"
set ylabel "error at t_end (m)"
plot for [i=1:words(methods)] datadir."/conv_".word(methods,i).".dat" using 1:2 with points pt 7 ps 0.8 lc i title word(methods,i), \
     for [i=1:words(methods)] datadir."/fit_".word(methods,i).".dat" using 1:2 with lines lw 2 lc i notitle, \
     for [p=0:2] datadir."/reference_slopes.dat" index p using 1:2 with lines dt 2 lc rgb "#888888" title (p == 0 ? "slopes 1, 2, 4" : "")

# Figure 5: energy growth rate against damping at the large step: measured (points) on the
# predicted curves 2 ln(rho) / h (lines).
# Variables set by steplab report: datadir, outfile, format (png|pdf), methods, numeric, springdts, largedt.
if (format eq "png") { set terminal pngcairo enhanced size 1100,680 font ",12" } else { set terminal pdfcairo enhanced size 16cm,9.6cm font ",8" }
set output outfile
set grid lc rgb "#dddddd"
set key outside right top samplen 2 noenhanced  # method names have underscores
set xlabel "damping gamma (kg/s)"
set ylabel "d ln E / dt (1/s)"
set title "dt = ".largedt
plot for [i=1:words(methods)] datadir."/predicted_".word(methods,i).".dat" using 1:2 with lines lw 1.5 lc i notitle, \
     for [i=1:words(methods)] datadir."/sweep_".word(methods,i).".dat" using 1:2 with points pt 7 ps 0.9 lc i title word(methods,i)

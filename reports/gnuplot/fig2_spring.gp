# Figure 2: the spring's height y(t) per method against the exact solution, one panel per step.
# Variables set by steplab report: datadir, outfile, format (png|pdf), methods, numeric, springdts, largedt.
if (format eq "png") { set terminal pngcairo enhanced size 1100,680 font ",12" } else { set terminal pdfcairo enhanced size 16cm,9.6cm font ",8" }
set output outfile
set grid lc rgb "#dddddd"
set key outside right top samplen 2 noenhanced  # method names have underscores
n = words(springdts)
set multiplot layout n,1
set ylabel "y (m)"
do for [k=1:n] {
  if (k == n) { set xlabel "t (s)" } else { unset xlabel }
  set title "dt = ".word(springdts, k) noenhanced
  plot datadir."/spring_exact.dat" using 1:2 with lines lw 4 lc rgb "#bbbbbb" title "exact", \
       for [m in methods] datadir."/spring".(k-1)."_".m.".dat" using 1:2 with lines lw 1.2 title m
}
unset multiplot

# Figure 13: the crossover map on the first scene of run-time size: a panel per target error, a
# cell per (masses N, stiffness) coloured by the group of its cheapest solver and labelled with
# it and its margin over the next cheapest.
# Variables set by steplab report: datadir, outfile, format (png|pdf), ntargets, xlabels and
# ylabels (the masses and stiffnesses, words), ylab (the stiffness parameter's name), tt1 .. (the
# panels' titles).
if (format eq "png") { set terminal pngcairo enhanced size 1100,440 font ",10" } else { set terminal pdfcairo enhanced size 16cm,7.5cm font ',6.5' }
set output outfile
set multiplot layout 1,ntargets
nx = words(xlabels)
ny = words(ylabels)
set xrange [-0.5:nx - 0.5]
set yrange [-0.5:ny - 0.5]
set xtics ()
set ytics ()
do for [i=1:nx] { set xtics add (word(xlabels, i) i - 1) }
do for [i=1:ny] { set ytics add (word(ylabels, i) i - 1) }
set tics scale 0
set xlabel "masses N"
set ylabel ylab
unset key
do for [t=1:ntargets] {
  set title value("tt".t) noenhanced
  plot datadir."/scaling_map.dat" index (t - 1) using 1:2:(0.49):(0.49):3 with boxxyerror fs solid 0.85 noborder lc rgb variable, \
       '' index (t - 1) using 1:($2 + 0.12):4 with labels font ",7" noenhanced, \
       '' index (t - 1) using 1:($2 - 0.15):5 with labels font ",7" noenhanced
}
unset multiplot

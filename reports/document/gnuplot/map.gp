# The crossover map on the first scene of run-time size: a panel per target error, a cell per
# (masses N, stiffness) coloured by the group of its cheapest solver and labelled with it and its
# margin over the next cheapest; a tie (a margin within the timing's noise) white, both named.
# Variables set by steplab report: datadir, outfile, format (png|svg|pdf), ntargets, xlabels and
# ylabels (the masses and stiffnesses, words), ylab (the stiffness parameter's name), tt1 .. (the
# panels' titles).
load "styles.gp"  # each method's style, the terminal and the fonts
eval terminal(330 * ntargets, 5.2 * ntargets)
set output outfile
set multiplot layout ntargets,1
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
  plot datadir."/map.dat" index (t - 1) using 1:2:(0.49):(0.49):3 with boxxyerror fs solid 0.85 border lc rgb "#bbbbbb" lc rgb variable, \
       '' index (t - 1) using 1:($2 + 0.13):4 with labels font kfont noenhanced, \
       '' index (t - 1) using 1:($2 - 0.15):5 with labels font kfont noenhanced
}
unset multiplot

# Figure 6: stability maps per method over (dt, damping), one row per family: measured stable
# (dark) or not (light), and the predicted boundary dt* (black line).
# Variables set by steplab report: datadir, outfile, format (png|pdf), methods, numeric, springdts, largedt,
# styles.gp (written beside this script): the panels npanel, panel1.. (its methods), ptitle1.. (its title).
if (format eq "png") { set terminal pngcairo enhanced size 1100,1300 font ",11" } else { set terminal pdfcairo enhanced size 16cm,19cm font ",7" }
set output outfile
load "styles.gp"
unset key
# x is log10(dt): an image needs a uniform grid
set xtics ("0.01" -2, "0.1" -1, "1" 0, "10" 1)
set palette defined (0 "#f6d5d5", 1 "#3b6fb6")
unset colorbox
set cbrange [0:1]
set autoscale xfix
set autoscale yfix
set multiplot
cols = 4
w = 1.0 / cols
h = 0.96 / npanel
do for [r=1:npanel] {
  row = value("panel".r)
  do for [c=1:words(row)] {
    m = word(row, c)
    set origin (c - 1) * w, 0.96 - r * h
    set size w, h
    set title (c == 1 ? value("ptitle".r).": ".m : m) noenhanced
    set xlabel (r == npanel ? "dt" : "")
    set ylabel (c == 1 ? "damping" : "")
    plot datadir."/map_".m.".dat" using (log10($1)):2:3 with image, \
         datadir."/boundary_".m.".dat" using (log10($1)):2 with lines lw 2 lc rgb "black"
  }
}
unset multiplot

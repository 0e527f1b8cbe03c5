# The spring's height y(t) per method against the exact solution: a row per family, a column per
# step.
# Variables set by steplab report: datadir, outfile, format (png|svg|pdf), springdts (the steps), the
# panels npanel, panel1.., ptitle1..; styles.gp: each method's style.
n = words(springdts)
load "styles.gp"  # each method's style, the terminal and the fonts
eval terminal(260 * npanel + 60, 3.9 * npanel + 0.6)
set output outfile
set grid lc rgb "#dddddd"
set key outside right top vertical samplen 2 noenhanced  # method names have underscores
set ylabel "y (m)"
set multiplot layout npanel,n
do for [f=1:npanel] {
  ms = value("panel".f)
  do for [k=1:n] {
    set xlabel (f == npanel ? "t (s)" : "")
    if (k == n) { set key } else { unset key }
    set title value("ptitle".f).", dt = ".word(springdts, k) noenhanced
    stats datadir."/spring".(k-1)."_".word(ms, 1).".dat" using 1 nooutput
    nth = STATS_records > 20 ? int(STATS_records / 12) : 1
    plot datadir."/spring_exact.dat" using 1:2 with lines lw 4 lc rgb "#bbbbbb" title "exact", \
         for [j=1:words(ms)] datadir."/spring".(k-1)."_".word(ms, j).".dat" using 1:2 with lines lt mlt(word(ms, j)) lw 1.2 notitle, \
         for [j=1:words(ms)] datadir."/spring".(k-1)."_".word(ms, j).".dat" using 1:2 every nth::((j - 1) * nth / words(ms)) with points lt mlt(word(ms, j)) notitle, \
         for [j=1:words(ms)] keyentry with linespoints lt mlt(word(ms, j)) lw 1.2 title word(ms, j)
  }
}
unset multiplot

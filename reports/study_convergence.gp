# Convergence plot of a study (studies/study_convergence.cpp): error against elements or
# unknowns on log-log axes, one curve per combination, with reference slopes.
# Variables: files, titles (word lists), xcol (1 elements, 2 unknowns), xlabel, ylabel,
# plottitle, outbase, refx, refy (anchor of the reference slopes).
set terminal pngcairo size 1000,650 enhanced font ",10"
set output outbase.'.png'
set logscale xy
set format y "10^{%L}"
set xlabel xlabel
set ylabel ylabel
set title plottitle noenhanced
set key outside right top noenhanced font ",9"
set grid
# Keep extreme points off the frame.
set offsets graph 0.05, graph 0.05, graph 0.05, graph 0.05
n = words(files)
xc = int(xcol + 0)
rx = refx + 0.0
ry = refy + 0.0
ref2(x) = ry * (x / rx)**-2
ref4(x) = ry * (x / rx)**-4
plot for [i=1:n] word(files, i) using (column(xc)):4 with linespoints lw 1.5 pt (i % 13 + 1) \
       lc i title word(titles, i), \
     ref2(x) with lines dt 2 lw 2 lc rgb "black" title "slope -2 (reference)", \
     ref4(x) with lines dt 3 lw 2 lc rgb "gray40" title "slope -4 (reference)"
# The same figure as SVG, for the HTML report.
set terminal svg size 1000,650 dynamic enhanced font ",10"
set output outbase.'.svg'
replot
unset output

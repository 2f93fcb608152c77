# Speed vs accuracy (benches/study_speed.cpp): error against in-process wall time (median of
# repeats), one curve per combination (its meshes/orders), the Pareto front across combinations.
# Variables: files, titles (word lists), front (data file of the front), plottitle, ylabel, outbase.
set terminal pngcairo size 1000,650 enhanced font ",10"
set output outbase.'.png'
set logscale xy
set format y "10^{%L}"
set format x "10^{%L}"
set xlabel "in-process wall time to solution, median of repeats [s]"
set ylabel ylabel
set title plottitle noenhanced
set key outside right top noenhanced font ",9"
set grid
# Keep extreme points off the frame.
set offsets graph 0.05, graph 0.05, graph 0.05, graph 0.05
n = words(files)
plot for [i=1:n] word(files, i) using 3:4 with linespoints lw 1.2 pt (i % 13 + 1) lc i \
       title word(titles, i), \
     front using 1:2 with steps lw 3 lc rgb "black" title "Pareto front (all combinations)", \
     front using 1:2 with points pt 7 ps 1.6 lc rgb "black" notitle
# The same figure as SVG, for the HTML report.
set terminal svg size 1000,650 dynamic enhanced font ",10"
set output outbase.'.svg'
replot
unset output

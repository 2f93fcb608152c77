# Joined-beam frequency convergence (studies/study_joined_beam_modal.cpp): the largest relative
# frequency error over the five lowest modes against elements per member (h-refinement) or
# unknowns (h and p), log-log, with reference slopes anchored at the first point of the first file.
# Variables: files, titles (word lists), xcol (1 elements, 2 unknowns), xlabel, plottitle, outbase.
set terminal pngcairo size 1000,650 enhanced font ",10"
set output outbase.'.png'
set logscale xy
set format y "10^{%L}"
set xlabel xlabel
set ylabel "max_k |f_k − f_{k,R}| / f_{k,R} [-]"
set title plottitle noenhanced
set key outside right top noenhanced font ",9"
set grid
set yrange [1e-13:*]
n = words(files)
xc = int(xcol + 0)
stats word(files, 1) using (column(xc)):4 nooutput
rx = STATS_min_x
ry = STATS_max_y
ref2(x) = ry * (x / rx)**-2
ref4(x) = ry * (x / rx)**-4
ref8(x) = ry * (x / rx)**-8
plot for [i=1:n] word(files, i) using (column(xc)):4 with linespoints lw 1.5 pt (i % 13 + 1) \
       lc i title word(titles, i), \
     ref2(x) with lines dt 2 lw 2 lc rgb "black" title "slope -2 (reference)", \
     ref4(x) with lines dt 3 lw 2 lc rgb "gray40" title "slope -4 (reference)", \
     ref8(x) with lines dt 4 lw 2 lc rgb "gray60" title "slope -8 (reference)"
# The same figure as SVG, for the HTML report.
set terminal svg size 1000,650 dynamic enhanced font ",10"
set output outbase.'.svg'
replot
unset output

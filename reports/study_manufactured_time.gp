# Time (or space) convergence against the manufactured motion (cases/runner/
# study_manufactured_time.cpp): error against the step size (or elements) on log-log axes, one
# curve per combination, with a reference slope.
# Variables: files, titles (word lists), xcol, ycol (columns of the data files), xlabel, ylabel,
# plottitle, outbase, refx, refy (anchor of the reference slope), slope (its order; the
# reference line is refy (x/refx)^slope — positive for Δt, negative for elements).
set terminal pngcairo size 1000,650 enhanced font ",10"
set output outbase.'.png'
set logscale xy
set format y "10^{%L}"
set xlabel xlabel
set ylabel ylabel
set title plottitle noenhanced
set key outside right top noenhanced font ",9"
set grid
n = words(files)
xc = int(xcol + 0)
yc = int(ycol + 0)
rx = refx + 0.0
ry = refy + 0.0
sl = slope + 0.0
ref(x) = ry * (x / rx)**sl
plot for [i=1:n] word(files, i) using (column(xc)):(column(yc)) with linespoints lw 1.5 \
       pt (i % 13 + 1) lc i title word(titles, i), \
     ref(x) with lines dt 2 lw 2 lc rgb "black" title sprintf("slope %g (reference)", sl)

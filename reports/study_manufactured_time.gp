# Time (or space) convergence against the manufactured motion
# (studies/study_manufactured_time.cpp): error against the step size (or elements) on log-log axes, one
# curve per combination, with a reference slope.
# Variables: files, titles (word lists), xcol, ycol (columns of the data files), xlabel, ylabel,
# plottitle, outbase, refx, refy (anchor of the reference slope), slope (its order; the
# reference line is refy (x/refx)^slope — positive for Δt, negative for elements).
# Several combinations give the same errors to plotting accuracy (the displacement
# parameterizations at one ρ∞): each curve has its own open marker, each smaller than the one
# before in a cycle, so coinciding curves show as nested markers. The axis ranges are padded
# (no point on the frame) and the key is below the plot, where it hides no curve.
n = words(files)
xc = int(xcol + 0)
yc = int(ycol + 0)
xmin = 1e300; xmax = -1e300; ymin = 1e300; ymax = -1e300
do for [i=1:n] {
    stats word(files, i) using xc:yc nooutput
    if (STATS_records > 0) {
        xmin = (STATS_min_x < xmin) ? STATS_min_x : xmin
        xmax = (STATS_max_x > xmax) ? STATS_max_x : xmax
        ymin = (STATS_min_y < ymin) ? STATS_min_y : ymin
        ymax = (STATS_max_y > ymax) ? STATS_max_y : ymax
    }
}
padx = 10**(0.08 * (log10(xmax / xmin) > 1 ? log10(xmax / xmin) : 1))
pady = 10**(0.06 * (log10(ymax / ymin) > 1 ? log10(ymax / ymin) : 1))
rows = int((n + 1) / 2) + 1
set terminal pngcairo size 900, 560 + 16 * rows enhanced font ",10"
set output outbase.'.png'
set logscale xy
set format y "10^{%L}"
set xrange [xmin / padx:xmax * padx]
set yrange [ymin / pady:ymax * pady]
set xlabel xlabel
set ylabel ylabel
set title plottitle noenhanced
set key outside below center Left reverse noenhanced font ",9" maxrows rows
set grid
rx = refx + 0.0
ry = refy + 0.0
sl = slope + 0.0
ref(x) = ry * (x / rx)**sl
colour(k) = word("#1f77b4 #d62728 #2ca02c #9467bd #ff7f0e #17becf #8c564b #e377c2 #000000 #7f7f7f", (k - 1) % 10 + 1)
mark_shape(k) = word("6 4 8 12 10 14 2 1 3", (k - 1) % 9 + 1) + 0
mark_size(k) = 2.4 - 0.4 * ((k - 1) % 5)
dash(k) = (k - 1) % 5 + 1
plot for [i=1:n] word(files, i) using (column(xc)):(column(yc)) with linespoints lw 1.2 \
       dt dash(i) pt (mark_shape(i)) ps (mark_size(i)) lc rgb colour(i) title word(titles, i), \
     ref(x) with lines dt 2 lw 2 lc rgb "black" title sprintf("slope %g (reference)", sl)
# The same figure as SVG, for the HTML report.
set terminal svg size 900, 560 + 16 * rows dynamic enhanced font ",10"
set output outbase.'.svg'
replot
unset output

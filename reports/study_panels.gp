# Multi-panel line plot of the studies (studies/study_plot.cpp): curves grouped into panels
# (e.g. one per discretization, the parameterizations inside), so that curves which coincide are
# not hidden behind each other: inside a panel each curve has its own open marker shape, drawn
# smaller than the one before (coinciding points show as nested markers), and its own colour and
# dash. All panels share the axis ranges (computed from every file, padded so that no point sits
# on the frame). Keys go below each panel.
# Variables: files, titles, groups (panel number per file, 1-based), panels (panel titles, '_' for
# spaces), layout ("rows,cols"), xcol, ycol, xlabel, ylabel, plottitle, outbase, logx, logy
# ('1' for a log axis). Optional: hline/hlabel (a horizontal reference line), failed (file of
# "x panel" rows: runs without a result, drawn as red crosses on the panel's top edge, never
# joined to the curves), extra/extratitle (a file of x y drawn in every panel, e.g. the Pareto
# front), slopes ("x0 y0": reference slopes −2 and −4 through that point).
if (!exists("hline")) { hline = '' }
if (!exists("hlabel")) { hlabel = '' }
if (!exists("failed")) { failed = '' }
if (!exists("extra")) { extra = '' }
if (!exists("extratitle")) { extratitle = '' }
if (!exists("slopes")) { slopes = '' }
spaces(s) = (strstrt(s, "_") == 0) ? s : s[1:strstrt(s, "_") - 1]." ".spaces(s[strstrt(s, "_") + 1:])
n = words(files)
np = words(panels)
rows = int(word(system("echo ".layout." | tr , ' '"), 1))
cols = int(word(system("echo ".layout." | tr , ' '"), 2))
xc = int(xcol + 0)
yc = int(ycol + 0)
lx = (logx eq '1')
ly = (logy eq '1')

# Shared ranges over every file (and the reference line), padded.
xmin = 1e300; xmax = -1e300; ymin = 1e300; ymax = -1e300
do for [i=1:n] {
    # A file with no valid point (every run of its curve failed) leaves STATS_* undefined.
    undefine STATS_*
    stats word(files, i) using xc:yc nooutput
    if (exists("STATS_records") && STATS_records > 0) {
        xmin = (STATS_min_x < xmin) ? STATS_min_x : xmin
        xmax = (STATS_max_x > xmax) ? STATS_max_x : xmax
        ymin = (STATS_min_y < ymin) ? STATS_min_y : ymin
        ymax = (STATS_max_y > ymax) ? STATS_max_y : ymax
    }
}
if (extra ne '') {
    stats extra using 1:2 nooutput
    ymin = (STATS_min_y < ymin) ? STATS_min_y : ymin
    ymax = (STATS_max_y > ymax) ? STATS_max_y : ymax
}
if (hline ne '') {
    hy = hline + 0.0
    ymin = (hy < ymin) ? hy : ymin
    ymax = (hy > ymax) ? hy : ymax
}
if (failed ne '') {
    stats failed using 1 nooutput
    xmin = (STATS_min < xmin) ? STATS_min : xmin
    xmax = (STATS_max > xmax) ? STATS_max : xmax
}
pad(lo, hi, islog, side) = islog ? \
    (side < 0 ? lo / 10**(0.06 * (log10(hi / lo) > 1 ? log10(hi / lo) : 1)) \
              : hi * 10**(0.06 * (log10(hi / lo) > 1 ? log10(hi / lo) : 1))) : \
    (side < 0 ? lo - 0.06 * (hi > lo ? hi - lo : (abs(lo) > 0 ? abs(lo) : 1)) \
              : hi + 0.06 * (hi > lo ? hi - lo : (abs(hi) > 0 ? abs(hi) : 1)))
x0 = pad(xmin, xmax, lx, -1); x1 = pad(xmin, xmax, lx, 1)
y0 = pad(ymin, ymax, ly, -1); y1 = pad(ymin, ymax, ly, 1)
# The failed runs' row: just under the top of the frame.
yfail = ly ? y1 / 10**(0.03 * log10(y1 / y0)) : y1 - 0.03 * (y1 - y0)

# The PNG for the Markdown report, the SVG for the HTML one.
do for [fmt in "pngcairo svg"] {
    if (fmt eq "svg") { set terminal svg size 420 * cols + 120, 430 * rows + 60 dynamic enhanced font ",9"; set output outbase.'.svg' } \
    else { set terminal pngcairo size 420 * cols + 120, 430 * rows + 60 enhanced font ",9"; set output outbase.'.png' }
    if (lx) { set logscale x; set format x "10^{%L}" }
    if (ly) { set logscale y; set format y "10^{%L}" }
    set xrange [x0:x1]
    set yrange [y0:y1]
    set xlabel xlabel noenhanced
    set ylabel ylabel
    set grid
    set key outside below left Left reverse noenhanced font ",8" maxrows 6 height 1.5
    hy = (hline ne '') ? hline + 0.0 : NaN
    sx = (slopes ne '') ? word(slopes, 1) + 0.0 : 1.0
    sy = (slopes ne '') ? word(slopes, 2) + 0.0 : NaN
    extrafile = (extra ne '') ? extra : '/dev/null'
    failedfile = (failed ne '') ? failed : '/dev/null'
    # Marker of the k-th curve of a panel: open shapes, each smaller than the last.
    colour(k) = word("#1f77b4 #d62728 #2ca02c #9467bd #ff7f0e #17becf #8c564b #e377c2 #000000 #7f7f7f", (k - 1) % 10 + 1)
    mark_shape(k) = word("6 4 8 12 10 14 2 1 3", (k - 1) % 9 + 1) + 0
    mark_size(k) = 2.4 - 0.4 * ((k - 1) % 5)
    dash(k) = (k - 1) % 5 + 1
    set multiplot layout rows, cols title plottitle noenhanced font ",11"
    do for [p=1:np] {
        set title spaces(word(panels, p)) noenhanced
        # Files of this panel: their order inside it picks marker, size, colour and dash.
        members = ''
        do for [i=1:n] { if (int(word(groups, i)) == p) { members = members.' '.i } }
        m = words(members)
        # The failure marker's key entry only where this panel has failures.
        nfail = 0
        if (failed ne '') {
            nfail = int(system(sprintf("awk '!/^#/ && $2 == %d' %s | wc -l", p, failed)))
        }
        plot for [j=1:m] word(files, int(word(members, j))) using xc:yc \
                 with linespoints lw 1.2 dt dash(j) pt (mark_shape(j)) ps (mark_size(j)) lc rgb colour(j) \
                 title word(titles, int(word(members, j))), \
             hy with lines dt 2 lw 1.5 lc rgb "black" \
                 title (hline ne '' ? hlabel : ''), \
             sy * (x / sx)**-2 with lines dt 2 lw 1.5 lc rgb "gray30" \
                 title (slopes ne '' ? 'slope -2' : ''), \
             sy * (x / sx)**-4 with lines dt 3 lw 1.5 lc rgb "gray50" \
                 title (slopes ne '' ? 'slope -4' : ''), \
             extrafile using 1:2 with steps lw 2.5 lc rgb "black" \
                 title (extra ne '' ? extratitle : ''), \
             failedfile using 1:($2 == p ? yfail : NaN) with points \
                 pt 2 ps 1.8 lw 2 lc rgb "red" title (nfail > 0 ? 'failed: no result' : '')
    }
    unset multiplot
    unset output
}

# Tip displacement of the moment-loaded cantilever (seed 002 Example 1, L = 12 in) against the
# load factor λ, every combination over the exact solution, and below it every combination's
# tip error against the exact solution: on the displacement plot the combinations coincide to
# plotting accuracy, so each has its own open marker, drawn smaller than the one before (they
# show as nested markers), and the error panel separates them.
# Variables: files (space-separated data files: λ u1 u3 iterations), outbase (output path without
# extension). Writes outbase.png and outbase.svg.
L = 12.0
rho(l) = L / (l * pi)
u1(l) = l == 0 ? 0 : rho(l) * sin(l * pi) - L
u3(l) = l == 0 ? 0 : rho(l) * (1 - cos(l * pi))
err(l, a, b) = sqrt((a - u1(l))**2 + (b - u3(l))**2) / L
label(f) = system(sprintf("basename %s .dat | sed 's/^rollup_//'", f))
n = words(files)
lmax = 0
do for [i=1:n] {
    stats word(files, i) using 1 nooutput
    lmax = (STATS_max > lmax) ? STATS_max : lmax
}
colour(k) = word("#1f77b4 #d62728 #2ca02c #9467bd #ff7f0e #17becf #8c564b #e377c2 #000000 #7f7f7f", (k - 1) % 10 + 1)
mark_shape(k) = word("6 4 8 12 10 14 2 1 3", (k - 1) % 9 + 1) + 0
mark_size(k) = 2.6 - 0.28 * ((k - 1) % 8)
set grid
set samples 400
set xrange [0:lmax * 1.04]
set key outside right top noenhanced font ",9"
do for [fmt in "pngcairo svg"] {
    if (fmt eq "svg") { set terminal svg size 1100,900 dynamic; set output outbase.".svg" } \
    else { set terminal pngcairo size 1100,900; set output outbase.".png" }
    set multiplot layout 2,1 title "Cantilever roll-up: tip displacement vs load factor (exact: lines)"
    set lmargin 12
    set rmargin 36
    set xlabel "load factor λ [-] (tip moment λ·πEI/L)"
    set ylabel "tip displacement [in]"
    set yrange [-16:10]
    unset logscale y
    set format y "%g"
    plot u1(x) w l lw 2 lc rgb "gray40" t "exact u1", \
         u3(x) w l lw 2 lc rgb "gray70" t "exact u3", \
         for [i=1:n] word(files, i) u 1:2 w p pt mark_shape(i) ps mark_size(i) lw 1.5 lc rgb colour(i) t label(word(files, i)), \
         for [i=1:n] word(files, i) u 1:3 w p pt mark_shape(i) ps mark_size(i) lw 1.5 lc rgb colour(i) notitle
    set ylabel "tip error ‖u - u_{exact}‖/L [-]"
    set logscale y
    set format y "10^{%L}"
    set yrange [*:*]
    set offsets 0, 0, graph 0.08, graph 0.08
    plot for [i=1:n] word(files, i) u 1:(err($1, $2, $3)) w lp lw 1.2 pt mark_shape(i) \
             ps mark_size(i) lc rgb colour(i) t label(word(files, i))
    set offsets 0, 0, 0, 0
    unset multiplot
    unset output
}

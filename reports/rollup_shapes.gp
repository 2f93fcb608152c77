# Deformed shapes of the moment-loaded cantilever (seed 002 Fig. 3, L = 12 in) for each reported
# load factor λ: the computed nodes (points) over the exact circular arcs of radius L/(λπ) (lines).
# Variables: datafile (blocks separated by two blank lines, one per λ: x z, with a "# lambda"
# comment line first), lambdas (space-separated λ values in block order), outbase.
L = 12.0
set key outside right
set grid
set size ratio -1
set xlabel "x [in]"
set ylabel "z [in]"
set title "Cantilever roll-up: deformed shapes for several λ (exact arcs: lines)"
set parametric
set trange [0:1]
nl = words(lambdas)
lam(i) = real(word(lambdas, i))
# Exact centre line at arc fraction t: x = ρ sin(λπ t), z = ρ (1 − cos(λπ t)), ρ = L/(λπ).
ex(i, t) = L / (lam(i) * pi) * sin(lam(i) * pi * t)
ez(i, t) = L / (lam(i) * pi) * (1 - cos(lam(i) * pi * t))
do for [fmt in "pngcairo svg"] {
    if (fmt eq "svg") { set terminal svg size 900,700 dynamic; set output outbase.".svg" } \
    else { set terminal pngcairo size 900,700; set output outbase.".png" }
    plot for [i=1:nl] ex(i, t), ez(i, t) w l lw 1.5 lc i notitle, \
         for [i=1:nl] datafile index (i-1) u 1:2 w p pt 7 ps 0.6 lc i t sprintf("λ = %s", word(lambdas, i))
    unset output
}

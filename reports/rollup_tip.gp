# Tip displacement of the moment-loaded cantilever (seed 002 Example 1, L = 12 in) against the
# load factor λ, every combination (points) over the exact solution (lines).
# Variables: files (space-separated data files: λ u1 u3 iterations), outbase (output path without
# extension). Writes outbase.png and outbase.svg.
L = 12.0
rho(l) = L / (l * pi)
u1(l) = l == 0 ? 0 : rho(l) * sin(l * pi) - L
u3(l) = l == 0 ? 0 : rho(l) * (1 - cos(l * pi))
label(f) = system(sprintf("basename %s .dat | sed 's/^rollup_//'", f))
set key outside right
set grid
set xlabel "load factor λ (tip moment λ·πEI/L)"
set ylabel "tip displacement [in]"
set title "Cantilever roll-up: tip displacement vs load factor (exact: lines)"
set samples 400
do for [fmt in "pngcairo svg"] {
    if (fmt eq "svg") { set terminal svg size 1000,600 dynamic; set output outbase.".svg" } \
    else { set terminal pngcairo size 1000,600; set output outbase.".png" }
    plot [0:*] u1(x) w l lw 2 lc rgb "gray40" t "exact u1", \
         u3(x) w l lw 2 lc rgb "gray70" t "exact u3", \
         for [f in files] f u 1:2 w p pt 7 ps 0.8 t label(f)." u1", \
         for [f in files] f u 1:3 w p pt 6 ps 0.8 t label(f)." u3"
    unset output
}

# The effectivity study (studies/study_effectivity.cpp): estimated / true error against the
# refinement, one panel per strategy (p+1: the order on a fixed mesh; h/2, h/4 and 2h, 4h:
# elements per member), the band [0.5, 2] where asymptotic rows must lie shaded. Filled circles:
# asymptotic rows (the true errors show the regime); open circles: the others.
# Variables: pfile, hfile, cfile (rows "x effectivity asymptotic(0/1)"), plottitle, outbase.
do for [fmt in "pngcairo svg"] {
    if (fmt eq "svg") { set terminal svg size 1500,500 dynamic enhanced font ",10"; set output outbase.'.svg' } \
    else { set terminal pngcairo size 1500,500 enhanced font ",10"; set output outbase.'.png' }
    set multiplot layout 1, 3 title plottitle noenhanced font ",11"
    set logscale y
    set format y "%g"
    set ylabel "effectivity (estimated / true error) [-]"
    set grid
    set key top right font ",9"
    set object 1 rectangle from graph 0, first 0.5 to graph 1, first 2.0 behind \
        fillcolor rgb "#2ca02c" fillstyle transparent solid 0.2 noborder
    do for [panel=1:3] {
        file = (panel == 1) ? pfile : (panel == 2) ? hfile : cfile
        if (panel == 1) {
            unset logscale x
            set format x "%g"
            set xlabel "order p (2 or 4 elements per member) [-]"
            set title "displacement formulation: p+1 (p+2 decay check)"
            set xrange [*:*]
        } else {
            set logscale x 2
            set format x "%g"
            set xlabel "elements per member [-]"
            set title (panel == 2) ? "mixed formulation: h/2, h/4 (observed order)" \
                                   : "mixed formulation: 2h, 4h (coarser companions)"
        }
        set offsets graph 0.05, graph 0.05, 0, 0
        plot 0.5 with lines dt 2 lw 1.5 lc rgb "#2ca02c" title "band [0.5, 2]", \
             2.0 with lines dt 2 lw 1.5 lc rgb "#2ca02c" notitle, \
             file using 1:($3 == 1 ? $2 : NaN) with points pt 7 ps 0.9 lc rgb "#1f77b4" \
                 title "asymptotic", \
             file using 1:($3 == 0 ? $2 : NaN) with points pt 6 ps 0.9 lc rgb "#d62728" \
                 title "not asymptotic"
    }
    unset multiplot
    unset output
}

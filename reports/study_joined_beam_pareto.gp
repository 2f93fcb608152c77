# Joined-beam dynamic speed vs accuracy (cases/runner/study_joined_beam_dynamics.cpp): time error of
# the joint history against CPU time, one curve per combination and integrator (its Δt or IDA
# tolerances), and the Pareto front across all runs.
# Variables: files, titles (word lists), front (data file of the front), plottitle, outbase.
set terminal pngcairo size 1000,650 enhanced font ",10"
set output outbase.'.png'
set logscale xy
set format y "10^{%L}"
set xlabel "thread CPU time of the run, median of repeats [s]"
set ylabel "max_t ‖Δu_{joint}‖ / max_t ‖u_{joint}‖ (same-mesh reference) [-]"
set title plottitle noenhanced
set key outside right top noenhanced font ",9"
set grid
n = words(files)
plot for [i=1:n] word(files, i) using 3:4 with linespoints lw 1.2 pt (i % 13 + 1) lc i \
       title word(titles, i), \
     front using 1:2 with steps lw 3 lc rgb "black" title "Pareto front (all runs)", \
     front using 1:2 with points pt 7 ps 1.6 lc rgb "black" notitle

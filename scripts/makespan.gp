# The predicted make-span of `mpirun -np N rotbeam ...` against the ranks, for two jobs
# (docs/distributed-runs.md, "Scaling"): each job's table as scripts/makespan.py prints it, the
# simulated make-span and the longest unit, which bounds it. Variables: table1, title1, table2,
# title2, output (an SVG file).
set terminal svg size 800,500 dynamic enhanced font ",11"
set output output
set logscale xy
set xlabel "ranks (one thread each)"
set ylabel "make-span [s]"
set key top right noenhanced
set grid
plot table1 using 1:2 with linespoints lw 2 pt 7 lc 1 title title1, \
     table1 using 1:4 with lines dt 2 lw 1.5 lc 1 title title1.": longest unit", \
     table2 using 1:2 with linespoints lw 2 pt 5 lc 2 title title2, \
     table2 using 1:4 with lines dt 2 lw 1.5 lc 2 title title2.": longest unit"

# Seed 002 Figs. 6–7: joint displacement of the joined beam against time, dead (blue) and
# follower (red) joint force. The combinations agree to plotting accuracy, so the three history
# panels draw one combination per load (the first listed) and the bottom panel shows every other
# combination's distance from it, max over [0, t] of ‖u_joint − u_joint(first)‖, on a log axis:
# no curve is hidden behind another.
# Variables: dead, follower (space-separated data files: t ux uy uz rx ry rz ...; "?" missing),
# outbase (output path without extension). Writes outbase.png and outbase.svg.
set datafile missing "?"
label(f) = system(sprintf("basename %s .dat | sed 's/^joined_[a-z]*_//; s/-/\\//'", f))
columns(f) = int(system(sprintf("awk '!/^#/{print NF; exit}' %s", f)))
set grid
set key outside right top font ",9" noenhanced
set xlabel "time t [s]"
set lmargin 12
set rmargin 40
dead_colour = "#1f5fb4"
follower_colour = "#d62728"
colour(k) = word("#1f77b4 #2ca02c #9467bd #ff7f0e #17becf #8c564b #e377c2 #000000 #7f7f7f #bcbd22", (k - 1) % 10 + 1)
mark_shape(k) = word("6 4 8 12 10 14 2 1 3", (k - 1) % 9 + 1) + 0
mark_size(k) = 1.8 - 0.25 * ((k - 1) % 6)
dref = words(dead) > 0 ? word(dead, 1) : ''
fref = words(follower) > 0 ? word(follower, 1) : ''
nd = words(dead)
nf = words(follower)
ncd = nd > 0 ? columns(dref) : 0
ncf = nf > 0 ? columns(fref) : 0
# Distance of the joint from the reference combination's at the same time (NaN if the rows'
# times differ, and at t = 0 where both are exactly at rest).
dist(nc) = (column(1) == column(nc + 1) && column(1) > 0) ? \
    sqrt((column(2) - column(nc + 2))**2 + (column(3) - column(nc + 3))**2 + \
         (column(4) - column(nc + 4))**2) : NaN
do for [fmt in "pngcairo svg"] {
    if (fmt eq "svg") { set terminal svg size 1100,1400 dynamic; set output outbase.".svg" } \
    else { set terminal pngcairo size 1100,1400; set output outbase.".png" }
    set multiplot layout 4,1 title "Joined beam, joint force F_z = 1e5 sin(20 t) N from rest: dead (blue) vs follower (red)"
    unset logscale y
    set format y "%g"
    set offsets 0, 0, graph 0.05, graph 0.05
    set ylabel "joint u_z [m] (vertical)"
    plot [0:2] (nd > 0 ? dref : '/dev/null') u 1:4 w l lw 1.2 lc rgb dead_colour t "dead ".label(dref), \
               (nf > 0 ? fref : '/dev/null') u 1:4 w l lw 1.2 lc rgb follower_colour t "follower ".label(fref)
    set ylabel "joint u_z [m], first 0.6 s"
    plot [0:0.6] (nd > 0 ? dref : '/dev/null') u 1:4 w l lw 1.5 lc rgb dead_colour t "dead ".label(dref), \
                 (nf > 0 ? fref : '/dev/null') u 1:4 w l lw 1.5 lc rgb follower_colour t "follower ".label(fref)
    set ylabel "joint u_x [m] (in plane)"
    plot [0:2] (nd > 0 ? dref : '/dev/null') u 1:2 w l lw 1.2 lc rgb dead_colour t "dead ".label(dref), \
               (nf > 0 ? fref : '/dev/null') u 1:2 w l lw 1.2 lc rgb follower_colour t "follower ".label(fref)
    set ylabel "max over [0, t] of the distance [m]" noenhanced
    set title "every other combination: joint distance from ".label(nd > 0 ? dref : fref) noenhanced
    set logscale y
    set format y "10^{%L}"
    set offsets 0, 0, 0, 0
    set yrange [1e-12:*]
    # Running maximum over [0, t] of the distance: a monotone envelope per combination (the
    # distance itself oscillates with the response and the curves would cover each other).
    plot [0:2] for [i=2:(nd > 1 ? nd : 1)] sprintf("< paste %s %s", dref, word(dead, i)) \
                   u 1:($0 == 0 ? (m = 0) : 0, d = dist(ncd), m = (d == d && d > m) ? d : m, m) \
                   w lp lw 1.5 dt 1 pi 150 pt mark_shape(i - 1) ps mark_size(i - 1) \
                   lc rgb colour(i - 1) t "dead ".label(word(dead, i)), \
               for [i=2:(nf > 1 ? nf : 1)] sprintf("< paste %s %s", fref, word(follower, i)) \
                   u 1:($0 == 0 ? (m = 0) : 0, d = dist(ncf), m = (d == d && d > m) ? d : m, m) \
                   w lp lw 1.5 dt 2 pi 150 pt mark_shape(i - 1) ps mark_size(i - 1) \
                   lc rgb colour(i - 1) t "follower ".label(word(follower, i))
    set yrange [*:*]
    unset title
    unset multiplot
    unset output
}

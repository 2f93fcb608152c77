# Seed 002 Figs. 6–7: joint displacement of the joined beam against time, dead (blue) and
# follower (red) joint force, one curve per combination that ran (dash type by combination).
# Variables: dead, follower (space-separated data files: t ux uy uz rx ry rz ...; "?" missing),
# outbase (output path without extension). Writes outbase.png and outbase.svg.
set datafile missing "?"
label(f) = system(sprintf("basename %s .dat | sed 's/^joined_[a-z]*_//; s/-/\\//'", f))
set grid
set key outside right top font ",9"
set xlabel "time t [s]"
set lmargin 12
set rmargin 34
dead_colour = "#1f5fb4"
follower_colour = "#d62728"
do for [fmt in "pngcairo svg"] {
    if (fmt eq "svg") { set terminal svg size 1100,1000 dynamic; set output outbase.".svg" } \
    else { set terminal pngcairo size 1100,1000; set output outbase.".png" }
    set multiplot layout 3,1 title "Joined beam, joint force F_z = 1e5 sin(20 t) N from rest: dead (blue) vs follower (red)"
    set ylabel "joint u_z [m] (vertical)"
    plot [0:2] for [i=1:words(dead)] word(dead, i) u 1:4 w l lw 1.2 lc rgb dead_colour dt i t "dead ".label(word(dead, i)), \
               for [i=1:words(follower)] word(follower, i) u 1:4 w l lw 1.2 lc rgb follower_colour dt i t "follower ".label(word(follower, i))
    set ylabel "joint u_z [m], first 0.6 s"
    plot [0:0.6] for [i=1:words(dead)] word(dead, i) u 1:4 w l lw 1.5 lc rgb dead_colour dt i t "dead ".label(word(dead, i)), \
                 for [i=1:words(follower)] word(follower, i) u 1:4 w l lw 1.5 lc rgb follower_colour dt i t "follower ".label(word(follower, i))
    set ylabel "joint u_x [m] (in plane)"
    plot [0:2] for [i=1:words(dead)] word(dead, i) u 1:2 w l lw 1.2 lc rgb dead_colour dt i t "dead ".label(word(dead, i)), \
               for [i=1:words(follower)] word(follower, i) u 1:2 w l lw 1.2 lc rgb follower_colour dt i t "follower ".label(word(follower, i))
    unset multiplot
    unset output
}

# Seed 002 Figs. 10–11: the MH-104 blade under a dead tip force 1e5 sin(20 t) N. Fig. 10 (outbase
# -tip): tip displacement and rotation vector; Fig. 11 (outbase-root): root reaction force and
# moment. Components by colour (x, y, z), combinations by dash type.
# Variables: files (space-separated data files: t ux uy uz rx ry rz Fx Fy Fz Mx My Mz; "?"
# missing), outbase (output path prefix). Writes outbase-tip/-root .png and .svg.
set datafile missing "?"
label(f) = system(sprintf("basename %s .dat | sed 's/^blade_//; s/-/\\//'", f))
comp(k) = word("x y z", k)
set grid
set key outside right top
set xlabel "time t [s]"
do for [part in "tip root"] {
    do for [fmt in "pngcairo svg"] {
        if (fmt eq "svg") { set terminal svg size 1100,800 dynamic; set output outbase."-".part.".svg" } \
        else { set terminal pngcairo size 1100,800; set output outbase."-".part.".png" }
        if (part eq "tip") {
            set multiplot layout 2,1 title "Blade MH-104 (Fig. 10): tip displacement and rotation, dead tip force F_z = 1e5 sin(20 t) N"
            c1 = 2; c2 = 5; y1 = "tip displacement [m]"; y2 = "tip rotation vector [rad]"; s1 = "u"; s2 = "r"
        } else {
            set multiplot layout 2,1 title "Blade MH-104 (Fig. 11): root reaction force and moment (global frame)"
            c1 = 8; c2 = 11; y1 = "root force [N]"; y2 = "root moment [N·m]"; s1 = "F"; s2 = "M"
        }
        set ylabel y1
        plot [0:2] for [i=1:words(files)] for [k=1:3] word(files, i) u 1:(column(c1 + k - 1)) w l lw 1.5 lc k dt i t s1."_".comp(k)." ".label(word(files, i))
        set ylabel y2
        plot [0:2] for [i=1:words(files)] for [k=1:3] word(files, i) u 1:(column(c2 + k - 1)) w l lw 1.5 lc k dt i t s2."_".comp(k)." ".label(word(files, i))
        unset multiplot
        unset output
    }
}

# Rotation study: smallest singular value of the material tangent H_m of each parameterization
# against the rotation angle (0 … 4π). Variables: datafile (columns: angle, then per
# parameterization σ_min and round-trip error; header line names them), outbase.
set grid
set datafile missing "?"
set key outside right
set xlabel "rotation angle φ [rad]"
set xtics ("0" 0, "π" pi, "2π" 2*pi, "3π" 3*pi, "4π" 4*pi)
do for [fmt in "pngcairo svg"] {
    if (fmt eq "svg") { set terminal svg size 1000,800 dynamic; set output outbase.".svg" } \
    else { set terminal pngcairo size 1000,800; set output outbase.".png" }
    set multiplot layout 2,1 title "Where each parameterization becomes singular"
    set ylabel "σ_{min}(H_m) [-]"
    set logscale y
    stats datafile nooutput
    ncols = STATS_columns
    plot for [c=2:ncols:2] datafile u 1:c w l lw 2 t columnheader(c)
    set ylabel "round-trip error ‖ψ → p → ψ‖ [rad]"
    plot for [c=3:ncols:2] datafile u 1:(column(c) > 0 ? column(c) : 1e-17) w l lw 2 t columnheader(c)
    unset multiplot
    unset logscale y
    unset output
}

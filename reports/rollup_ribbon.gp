# The roll-up (moment-loaded cantilever, L = 12 in) in 3D: the ribbon x ± h d2 spanned by the
# sections' second director at several load factors λ, from the node frames of `run --vtk`.
# Variables: datafile (one block per λ, separated by two blank lines: the ribbon's two edges as
# two scans of x y z, separated by one blank line), lambdas (λ values in block order), outbase.
set view 65, 35, 1, 1
set yrange [-3:3]
set ytics 1
set view equal xyz
set xyplane 0
set grid
set xlabel "x [in]"
set ylabel "y [in]"
set zlabel "z [in]" rotate parallel
set key outside right
set title "Cantilever roll-up: ribbon of the section frames for several λ"
set hidden3d
nl = words(lambdas)
do for [fmt in "pngcairo svg"] {
    if (fmt eq "svg") { set terminal svg size 900,700 dynamic; set output outbase.".svg" } \
    else { set terminal pngcairo size 900,700; set output outbase.".png" }
    splot for [i=1:nl] datafile index (i-1) u 1:2:3 w l lw 1 lc i t sprintf("λ = %s", word(lambdas, i))
    unset output
}

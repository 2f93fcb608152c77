# Generic line plot of the studies (studies/study_*.cpp): one curve per data file.
# Variables: files, titles (word lists), xcol, ycol, xlabel, ylabel, plottitle, outbase,
# logx, logy ('1' for a log axis), hline (optional: a horizontal reference line at this y,
# labelled hlabel).
set terminal pngcairo size 1000,600 enhanced font ",10"
set output outbase.'.png'
if (logx eq '1') { set logscale x; set format x "10^{%L}" }
if (logy eq '1') { set logscale y; set format y "10^{%L}" }
set xlabel xlabel
set ylabel ylabel
set title plottitle noenhanced
set key outside right top noenhanced font ",9"
set grid
# Keep extreme points off the frame.
set offsets graph 0.05, graph 0.05, graph 0.05, graph 0.05
n = words(files)
xc = int(xcol + 0)
yc = int(ycol + 0)
if (!exists("hline")) { hline = '' }
if (!exists("hlabel")) { hlabel = '' }
if (hline eq '') {
    plot for [i=1:n] word(files, i) using xc:yc with linespoints lw 1.5 pt (i % 13 + 1) lc i \
         title word(titles, i)
} else {
    hy = hline + 0.0
    plot for [i=1:n] word(files, i) using xc:yc with linespoints lw 1.5 pt (i % 13 + 1) lc i \
         title word(titles, i), hy with lines dt 2 lw 2 lc rgb "black" title hlabel
}
# The same figure as SVG, for the HTML report.
set terminal svg size 1000,600 dynamic enhanced font ",10"
set output outbase.'.svg'
replot
unset output

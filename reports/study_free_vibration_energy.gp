# Energy of the undamped free vibration over many periods (studies/study_free_vibration_time.cpp):
# window means of (E − E0)/E0 against the period count, one curve per scheme. Top: every scheme
# (the dissipative ones, generalized-α ρ∞ < 1 and Radau IIA, lose energy and set the scale);
# bottom: the schemes without numerical dissipation alone, on their own scale.
# Variables: files, titles (word lists), outbase.
n = words(files)
colour(k) = word("#1f77b4 #d62728 #2ca02c #9467bd #ff7f0e #17becf #8c564b #e377c2", (k - 1) % 8 + 1)
dissipative(k) = strstrt(word(titles, k), "ga0.") > 0 || strstrt(word(titles, k), "radau") > 0
set terminal pngcairo size 900, 900 enhanced font ",10"
set output outbase.'.png'
set multiplot layout 2, 1
set xlabel "periods of the first mode [-]"
set ylabel "(E − E0)/E0, mean over 10 periods [-]"
set format y "%.1e"
set key outside right top noenhanced font ",9"
set grid
set title "Free vibration: energy, every scheme" noenhanced
plot for [i=1:n] word(files, i) using 1:2 with lines lw 1.5 lc rgb colour(i) title word(titles, i)
set title "Free vibration: energy, schemes without numerical dissipation" noenhanced
plot for [i=1:n] word(files, i) using 1:(dissipative(i) ? NaN : $2) with lines lw 1.5 \
       lc rgb colour(i) title (dissipative(i) ? "" : word(titles, i))
unset multiplot
# The same figure as SVG, for the HTML report.
set terminal svg size 900, 900 dynamic enhanced font ",10"
set output outbase.'.svg'
set multiplot layout 2, 1
set title "Free vibration: energy, every scheme" noenhanced
plot for [i=1:n] word(files, i) using 1:2 with lines lw 1.5 lc rgb colour(i) title word(titles, i)
set title "Free vibration: energy, schemes without numerical dissipation" noenhanced
plot for [i=1:n] word(files, i) using 1:(dissipative(i) ? NaN : $2) with lines lw 1.5 \
       lc rgb colour(i) title (dissipative(i) ? "" : word(titles, i))
unset multiplot
unset output

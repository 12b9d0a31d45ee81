# out/damped.png: damped swing (eqs. 46-48), ε = 1. Left: the correct verdict
# |S₁| < 2 cosh ε (multipliers of x inside the unit circle); right: the paper's
# |S₁| ≤ 2, only sufficient. Needs out/damped_chart.dat (columns stable and stable_paper).
# Parameters: file (the chart), out (the image).
load 'plots/columns.gp'
if (!exists("file")) file = 'out/damped_chart.dat'
if (!exists("out")) out = 'out/damped.png'
set encoding utf8
set terminal pngcairo size 1500,650 font "Sans,11"
set output out
pi2 = pi**2
set palette defined (0 "#f3efe6", 1 "#23406e")
set cbrange [0:1]
unset colorbox
set xrange [0:9.8]
set yrange [-2:12]
set xlabel "α = aπ²/ρ"
set ylabel "β = gπ²/(ρω²)"
set arrow 1 from 0,0 to 9.8,0 nohead dt 2 lw 1.2 lc "#888888" front
set arrow 2 from 0,pi2 to 9.8,pi2 nohead dt 2 lw 1.2 lc "#888888" front
set style textbox opaque fc "white" noborder margins 1,1
set label 1 "β = π²  (r_0 = 0)" at 0.15,pi2+0.4 front boxed font ",9" tc "#555555"
set label 3 "β = 0  (g = 0)" at 0.15,0.4 front boxed font ",9" tc "#555555"
set key at graph 0.01, graph 0.80 left top Left reverse box opaque samplen 2 font ",10"
set multiplot layout 1,2 title "Damped swing, ε = κπ/ω = 1 (exact S₁; dark = asymptotically stable)" font ",13"
set title "correct: |S₁| < 2 cosh ε"
plot named(file) using 'alpha':'beta':'stable' with image notitle, \
     keyentry with boxes fs solid 1.0 border lc "#555555" fc "#23406e" title "asymptotically stable: |S₁| < 2 cosh ε", \
     keyentry with boxes fs solid 1.0 border lc "#555555" fc "#f3efe6" title "unstable"
set title "the paper: |S₁| ≤ 2, only sufficient: part of the stable region shown unstable"
plot named(file) using 'alpha':'beta':'stable_paper' with image notitle, \
     keyentry with boxes fs solid 1.0 border lc "#555555" fc "#23406e" title "stable by the paper: |S₁| ≤ 2", \
     keyentry with boxes fs solid 1.0 border lc "#555555" fc "#f3efe6" title "not stable by the paper"
unset multiplot

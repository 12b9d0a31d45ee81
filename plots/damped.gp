# A damped chart (eqs. (46)-(48)) by both criteria: left the correct verdict |S1| < 2 cosh eps
# (the multipliers of x inside the unit circle), right the paper's |S1| <= 2, only
# sufficient. out/damped.png of `make run` is the chart at eps = 1.
# Call from any directory (default: the file `make run` writes into out/ here):
#   gnuplot -e "file='my_chart.dat'; out='x.png'" PATH/plots/damped.gp
# Parameters: file (a chart with damping: columns stable and stable_paper), out (the image).
# From the header: the ranges (alpha, beta), the damping (&scene epsilon, or &physical kappa),
# the method.
load system("dirname '".ARG0."'")."/columns.gp"
if (!exists("file")) file = 'out/damped_chart.dat'
if (!exists("out")) out = 'out/damped.png'
set encoding utf8
set terminal pngcairo size 1500,650 font "Sans,11"
set output out
pi2 = pi**2
x_min = low(file, 'alpha'); x_max = high(file, 'alpha')
y_min = low(file, 'beta'); y_max = high(file, 'beta')
set palette defined (0 "#f3efe6", 1 "#23406e")
set cbrange [0:1]
unset colorbox
set xrange [x_min:x_max]
set yrange [y_min:y_max]
set xlabel "α = aπ²/ρ"
set ylabel "β = gπ²/(ρω²)"
set style textbox opaque fc "white" noborder margins 1,1
array levels[2] = [0, pi2]
array names[2] = ["β = 0  (g = 0)", "β = π²  (r_0 = 0)"]
do for [k = 1:2] {
   if (levels[k] > y_min && levels[k] < y_max) {
      set arrow k from x_min, levels[k] to x_max, levels[k] nohead dt 2 lw 1.2 lc "#888888" front
      set label k names[k] at graph 0.015, first levels[k] + 0.03*(y_max - y_min) front boxed font ",9" tc "#555555"
   }
}
kappa = scene_value(file, 'kappa')
damping = kappa ne '' ? sprintf("κ = %s 1/s (ε = κπ/ω)", kappa) : sprintf("ε = κπ/ω = %s", scene_value(file, 'epsilon'))
set key at graph 0.01, graph 0.80 left top Left reverse box opaque samplen 2 font ",10"
set multiplot layout 1,2 title sprintf("Damped swing, %s; %s, S₁ of the χ equation (dark = asymptotically stable)", \
   damping, method_title(file)) font ",13" noenhanced
set title "correct: |S₁| < 2 cosh ε"
plot named(file) using 'alpha':'beta':'stable' with image notitle, \
     keyentry with boxes fs solid 1.0 border lc "#555555" fc "#23406e" title "asymptotically stable: |S₁| < 2 cosh ε", \
     keyentry with boxes fs solid 1.0 border lc "#555555" fc "#f3efe6" title "unstable"
set title "the paper: |S₁| ≤ 2, only sufficient: part of the stable region shown unstable"
plot named(file) using 'alpha':'beta':'stable_paper' with image notitle, \
     keyentry with boxes fs solid 1.0 border lc "#555555" fc "#23406e" title "stable by the paper: |S₁| ≤ 2", \
     keyentry with boxes fs solid 1.0 border lc "#555555" fc "#f3efe6" title "not stable by the paper"
unset multiplot

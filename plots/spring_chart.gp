# The stability of a real spring over bounce amplitude a [m] and frequency omega = sqrt(k/m)
# [rad/s], a chart of &physical a_min ... omega_max (out/spring_chart.png of `make run`):
# left the verdict, right the growth rate of the swing per second (mu_per_s) where it is
# unstable; a dashed line at the omega of one spring with a cross at its critical amplitudes.
# Call from any directory (defaults: the files `make run` writes into out/ here):
#   gnuplot -e "file='my_chart.dat'; critical='my_boundaries.dat'; out='x.png'" PATH/plots/spring_chart.gp
# Parameters: file (a chart over (a, omega)), critical (the critical amplitudes of one
# spring, task boundaries with &physical; optional: left out when it cannot be read), out.
# From the headers: the ranges of a and omega, r0 and g (the title), the spring of
# `critical` (k and m, or omega: where its line goes and what its key says).
load system("dirname '".ARG0."'")."/columns.gp"
if (!exists("file")) file = 'out/spring_chart.dat'
if (!exists("critical")) critical = 'out/spring_boundaries.dat'
if (!exists("out")) out = 'out/spring_chart.png'
set encoding utf8
set terminal pngcairo size 1500,650 font "Sans,11"
set output out
a_min = low(file, 'a'); a_max = high(file, 'a')
set xlabel "bounce amplitude a [m]"
set ylabel "ω = √(k/m) [rad/s]"
set xrange [a_min:a_max]
set yrange [low(file, 'omega'):high(file, 'omega')]
has_spring = readable(critical)
if (has_spring) {
   k = scene_value(critical, 'k'); m = scene_value(critical, 'm')
   spring_omega = k ne '' ? sqrt(real(k)/real(m)) : real(scene_value(critical, 'omega'))
   spring = k ne '' ? sprintf("k = %s N/m, m = %s kg", k, m) : sprintf("ω = %s rad/s", scene_value(critical, 'omega'))
   set arrow 1 from a_min, spring_omega to a_max, spring_omega nohead dt 2 lw 1.5 lc "black" front
   spring_plot = sprintf(", named('%s') using 'a':(%.17g) with points pt 2 ps 2.5 lw 2 lc '#d73027' title '%s: critical a'", \
      critical, spring_omega, spring)
} else {
   spring_plot = ''
}
set key at graph 0.98, graph 0.98 right top box opaque samplen 2 font ",10"
set multiplot layout 1,2 title sprintf("A spring of natural length r0 = %s m (g = %s m/s²): stability of the vertical bounce", \
   scene_value(file, 'r0'), scene_value(file, 'g')) font ",13"
set title "verdict (dark = stable swing)"
set palette defined (0 "#f3efe6", 1 "#23406e")
set cbrange [0:1]
unset colorbox
plot named(file) using 'a':'omega':'stable' with image notitle, \
     keyentry with boxes fs solid 1.0 border lc "#555555" fc "#23406e" title "stable", \
     keyentry with boxes fs solid 1.0 border lc "#555555" fc "#f3efe6" title "unstable" @spring_plot
set title "growth rate of the swing μω/π [1/s] (0 where stable)"
set palette defined (0 "#fbfbf4", 0.1 "#fde8a0", 0.35 "#f39a3d", 0.7 "#c4312b", 1 "#4a0c16")
set cbrange [0:high(file, 'mu_per_s')]
set colorbox
set cblabel "growth rate [1/s]" noenhanced
unset key
plot named(file) using 'a':'omega':(column('mu_per_s') > 0 ? column('mu_per_s') : 0) with image notitle
unset multiplot

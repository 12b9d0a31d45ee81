# out/spring_chart.png: the stability of a real spring (natural length 0.30 m, g = 9.81) over
# bounce amplitude a [m] and frequency omega = sqrt(k/m) [rad/s]: left the verdict, right the
# growth rate of the swing per second (mu_per_s) where it is unstable. The dashed line is the
# spring k = 25 N/m, m = 0.25 kg (omega = 10 rad/s), the cross its critical amplitude.
# Needs out/spring_chart.dat (scene spring_chart.nml) and out/spring_boundaries.dat (scene
# spring_boundaries.nml). Parameters: file (the chart), critical (the critical amplitudes of
# one spring), spring_omega (its omega), out (the image).
load 'plots/columns.gp'
if (!exists("file")) file = 'out/spring_chart.dat'
if (!exists("critical")) critical = 'out/spring_boundaries.dat'
if (!exists("spring_omega")) spring_omega = 10.0
if (!exists("out")) out = 'out/spring_chart.png'
set encoding utf8
set terminal pngcairo size 1500,650 font "Sans,11"
set output out
set xlabel "bounce amplitude a [m]"
set ylabel "ω = √(k/m) [rad/s]"
set xrange [0:0.3]
set yrange [6:20]
set arrow 1 from 0,spring_omega to 0.3,spring_omega nohead dt 2 lw 1.5 lc "black" front
set key at graph 0.98, graph 0.98 right top box opaque samplen 2 font ",10"
set multiplot layout 1,2 title "A spring of natural length 0.30 m: stability of the vertical bounce (r0, g fixed)" font ",13"
set title "verdict (dark = stable swing)"
set palette defined (0 "#f3efe6", 1 "#23406e")
set cbrange [0:1]
unset colorbox
plot named(file) using 'a':'omega':'stable' with image notitle, \
     keyentry with boxes fs solid 1.0 border lc "#555555" fc "#23406e" title "stable", \
     keyentry with boxes fs solid 1.0 border lc "#555555" fc "#f3efe6" title "unstable", \
     named(critical) using 'a':(spring_omega) with points pt 2 ps 2.5 lw 2 lc "#d73027" \
        title "k = 25 N/m, m = 0.25 kg: critical a"
set title "growth rate of the swing μω/π [1/s] (0 where stable)"
set palette defined (0 "#fbfbf4", 0.1 "#fde8a0", 0.35 "#f39a3d", 0.7 "#c4312b", 1 "#4a0c16")
set autoscale cb
set colorbox
set cblabel "growth rate [1/s]" noenhanced
unset key
plot named(file) using 'a':'omega':(column('mu_per_s') > 0 ? column('mu_per_s') : 0) with image notitle
unset multiplot

# out/onset.png from out/onset_law.dat (fpm run --example onset_law; make run does both):
# the onset law of the swing. Points: observed radial periods until |phi| first exceeds 0.1;
# solid lines: the law n* = ln(0.1/phi0)/ln(lambda_max), lambda_max from the core; dashed: the onset
# of the full linear solution (n_linear).
set encoding utf8
set terminal pngcairo size 900,600 font "Sans,11"
set output 'out/onset.png'
set logscale x
set format x "10^{%L}"
set xrange [1e-21:1e-1]
set xlabel "φ(0) [rad]"
set ylabel "radial periods until |φ| > 0.1"
set grid lc "#dddddd"
set key top right box opaque
set title "Onset of the swing: observed (points), ln(0.1/φ0)/ln λ_{max} (solid), the linear solution (dashed)"
file = 'out/onset_law.dat'
plot file using ($1 == 2 ? $4 : 1/0):7 with points pt 7 ps 1.3 lc "#23406e" title "(b) α=3.70, β=2.47", \
     file using ($1 == 2 ? $4 : 1/0):6 with lines lw 1.5 lc "#23406e" notitle, \
     file using ($1 == 5 ? $4 : 1/0):7 with points pt 5 ps 1.3 lc "#d55e00" title "(e) α=7.88, β=3.95", \
     file using ($1 == 5 ? $4 : 1/0):6 with lines lw 1.5 lc "#d55e00" notitle, \
     file using ($1 == 7 ? $4 : 1/0):7 with points pt 9 ps 1.5 lc "#009e73" title "(g) α=7.48, β=2.47", \
     file using ($1 == 7 ? $4 : 1/0):6 with lines lw 1.5 lc "#009e73" notitle, \
     file using ($1 == 2 ? $4 : 1/0):12 with lines dt 2 lw 1.5 lc "#23406e" notitle, \
     file using ($1 == 5 ? $4 : 1/0):12 with lines dt 2 lw 1.5 lc "#d55e00" notitle, \
     file using ($1 == 7 ? $4 : 1/0):12 with lines dt 2 lw 1.5 lc "#009e73" notitle

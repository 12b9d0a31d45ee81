# out/area.png: where the paper's eq. (37) chart is wrong inside the physical domain
# (left), and the misclassified length in beta at each alpha for every approximate chart
# (right). Needs out/area_map.dat, out/area_length.dat (make area).
set encoding utf8
set terminal pngcairo size 1500,650 font "Sans,11"
set output 'out/area.png'
pi2 = pi**2
set multiplot layout 1,2 title "Misclassified regions of the approximate charts over 0 ≤ α < π², 0 < β < π²" font ",13"
# classes of out/area_map.dat: 0 both stable, 1 both unstable, 2 exact stable but eq. (37) unstable,
# 3 exact unstable but eq. (37) stable
set palette defined (0 "#9fb4d6", 1 "#f3efe6", 2 "#d7301f", 3 "#fdae61")
set cbrange [0:3]
unset colorbox
set xrange [0:pi2]
set yrange [0:pi2]
set xlabel "α"
set ylabel "β"
set key at graph 0.98, graph 0.98 right top box opaque samplen 2 font ",10"
set title "eq. (37) against the exact chart"
plot 'out/area_map.dat' using 1:2:3 with image notitle, \
     keyentry with boxes fs solid 1.0 lc "#555555" fc "#9fb4d6" title "stable (both)", \
     keyentry with boxes fs solid 1.0 lc "#555555" fc "#f3efe6" title "unstable (both)", \
     keyentry with boxes fs solid 1.0 lc "#555555" fc "#d7301f" title "eq. (37) unstable, exact stable", \
     keyentry with boxes fs solid 1.0 lc "#555555" fc "#fdae61" title "eq. (37) stable, exact unstable"
set title "misclassified length in β at each α"
set logscale y
set yrange [1e-6:10]
set format y "10^{%L}"
set ylabel "|U_{exact} Δ U_{approx}| ∩ (0, π²)"
set key at graph 0.02, graph 0.98 left top Left reverse box opaque samplen 2 font ",9"
plot 'out/area_length.dat' using 1:($2 > 0 ? $2 : 1/0) with lines lw 2.5 lc "black" title "eq. (37), 2 pieces", \
     '' using 1:($3 > 0 ? $3 : 1/0) with lines lw 1.5 lc "#b2182b" title "endpoint N = 4", \
     '' using 1:($4 > 0 ? $4 : 1/0) with lines lw 1.5 lc "#ef8a62" title "endpoint N = 8", \
     '' using 1:($5 > 0 ? $5 : 1/0) with lines lw 1.5 lc "#fddbc7" title "endpoint N = 16", \
     '' using 1:($6 > 0 ? $6 : 1/0) with lines lw 1.5 lc "#999999" title "endpoint N = 64", \
     '' using 1:($7 > 0 ? $7 : 1/0) with lines lw 1.5 dt 2 lc "#2166ac" title "midpoint N = 4", \
     '' using 1:($8 > 0 ? $8 : 1/0) with lines lw 1.5 dt 2 lc "#67a9cf" title "midpoint N = 8", \
     '' using 1:($9 > 0 ? $9 : 1/0) with lines lw 1.5 dt 2 lc "#1b7837" title "midpoint N = 16", \
     '' using 1:($10 > 0 ? $10 : 1/0) with lines lw 1.5 dt 2 lc "#762a83" title "midpoint N = 64"
unset multiplot

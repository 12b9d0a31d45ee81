# Where the approximate charts are wrong inside the physical domain (make area: the program
# hillstab_area writes out/area_map.dat and out/area_length.dat where it runs; this draws
# out/area.png): left the paper's eq. (37) chart against the exact one, cell by cell; right
# the misclassified length in beta at each alpha, one line per approximate chart.
# Call from any directory (defaults: the files `make area` writes into out/ here):
#   gnuplot -e "map='area_map.dat'; length='area_length.dat'; out='x.png'" PATH/plots/area.gp
# Parameters: map (columns alpha beta class), length (columns alpha, then one per chart),
# out. From the files: the ranges, the size of the map (its header), the charts (the column
# names of length: paper, endpoint4, midpoint16, ...).
load system("dirname '".ARG0."'")."/columns.gp"
if (!exists("map")) map = 'out/area_map.dat'
if (!exists("length")) length = 'out/area_length.dat'
if (!exists("out")) out = 'out/area.png'
set encoding utf8
set terminal pngcairo size 1500,650 font "Sans,11"
set output out
set multiplot layout 1,2 title "Misclassified regions of the approximate charts over 0 ≤ α < π², 0 < β < π²" font ",13"
# classes of the map: 0 both stable, 1 both unstable, 2 exact stable but eq. (37) unstable,
# 3 exact unstable but eq. (37) stable
set palette defined (0 "#9fb4d6", 1 "#f3efe6", 2 "#d7301f", 3 "#fdae61")
set cbrange [0:3]
unset colorbox
set xrange [low(map, 'alpha'):high(map, 'alpha')]
set yrange [low(map, 'beta'):high(map, 'beta')]
set xlabel "α"
set ylabel "β"
set key at graph 0.98, graph 0.98 right top box opaque samplen 2 font ",10"
set title "eq. (37) against the exact chart (".system("sed -n 's/.* on \\(.*\\) cell centres.*/\\1/p' '".map."' | head -n 1")." cells)"
plot named(map) using 'alpha':'beta':'class' with image notitle, \
     keyentry with boxes fs solid 1.0 lc "#555555" fc "#9fb4d6" title "stable (both)", \
     keyentry with boxes fs solid 1.0 lc "#555555" fc "#f3efe6" title "unstable (both)", \
     keyentry with boxes fs solid 1.0 lc "#555555" fc "#d7301f" title "eq. (37) unstable, exact stable", \
     keyentry with boxes fs solid 1.0 lc "#555555" fc "#fdae61" title "eq. (37) stable, exact unstable"
set title "misclassified length in β at each α"
set xrange [low(length, 'alpha'):high(length, 'alpha')]
set logscale y
set yrange [1e-6:10]
set format y "10^{%L}"
set ylabel "|U_{exact} Δ U_{approx}| ∩ (0, π²)"
set key at graph 0.02, graph 0.98 left top Left reverse box opaque samplen 2 font ",9"
charts = column_names(length)
array colours[8] = ["#b2182b", "#ef8a62", "#fddbc7", "#999999", "#2166ac", "#67a9cf", "#1b7837", "#762a83"]
chart_title(name) = name eq 'paper' ? "eq. (37), 2 pieces" : \
   system(sprintf("echo '%s' | sed 's/^\\([a-z]*\\)\\([0-9]*\\)$/\\1 N = \\2/'", name))
dash(i) = strstrt(word(charts, i), 'midpoint') == 1 ? 2 : 1
plot for [i = 2:words(charts)] named(length) using 'alpha':(column(word(charts, i)) > 0 ? column(word(charts, i)) : 1/0) \
        with lines lw (word(charts, i) eq 'paper' ? 2.5 : 1.5) dt dash(i) \
        lc rgb (word(charts, i) eq 'paper' ? "black" : colours[(i - 3)%8 + 1]) title chart_title(word(charts, i))
unset multiplot

# out/boundaries.png: the exact stability chart of the elastic model with its transition
# curves by Hill's method drawn as lines (S = +2 blue, S = -2 orange; dashed: a tongue of
# zero width, both curves of that order coincide). Needs out/boundaries_chart_chart.dat and
# out/boundaries_exact_boundaries.dat (scenes boundaries_chart.nml, boundaries_exact.nml).
# Parameters (gnuplot -e "file='...'; curves='...'; out='...'"): file, the chart; curves, the
# boundaries file; out, the image.
load 'plots/columns.gp'
if (!exists("file")) file = 'out/boundaries_chart_chart.dat'
if (!exists("curves")) curves = 'out/boundaries_exact_boundaries.dat'
if (!exists("out")) out = 'out/boundaries.png'
set encoding utf8
set terminal pngcairo size 1000,800 font "Sans,11"
set output out
pi2 = pi**2
set palette defined (0 "#f3efe6", 1 "#9fb4d6")
set cbrange [0:1]
unset colorbox
set xrange [0:9.8]
set yrange [-2:40]
set xlabel "α = aπ²/ρ"
set ylabel "β = gπ²/(ρω²)"
set key at graph 0.02, graph 0.98 left top Left reverse box opaque samplen 3 font ",10"
set title "Exact chart (light blue = stable) and its transition curves by Hill's method"
plot named(file) using 'alpha':'beta':'stable' with image notitle, \
     named(curves) using 'alpha':(column('kind') > 0 && column('coexist') == 0 ? column('beta') : 1/0) with lines lw 2 lc "#1f4e9c" title "S = +2, a_n, b_n (periodic)", \
     named(curves) using 'alpha':(column('kind') > 0 && column('coexist') == 1 ? column('beta') : 1/0) with lines lw 2 dt 2 lc "#1f4e9c" title "S = +2, a_n = b_n: zero-width tongue", \
     named(curves) using 'alpha':(column('kind') < 0 && column('coexist') == 0 ? column('beta') : 1/0) with lines lw 2 lc "#d9730d" title "S = −2, a_n, b_n (antiperiodic; open tongues)"

# A chart (dark = stable) with transition curves drawn over it: out/fig3_boundaries.png of
# `make run` is the paper's Fig. 3 redrawn, its eq. (37) chart with the exact transition
# curves by Hill's method and the curves of eq. (37) itself (roots of S = +-2 by Brent).
# Call from any directory (defaults: the files `make run` writes into out/ here):
#   gnuplot -e "file='a_chart.dat'; curves='b_boundaries.dat'; paper_curves='c_boundaries.dat'; points='d_points.dat'; out='x.png'" PATH/plots/fig3_boundaries.gp
# Parameters: file (a chart), curves (a boundaries file drawn as lines, S = +2 and S = -2),
# paper_curves (a second boundaries file drawn as dots; optional), points (optional), out.
# From the headers: the ranges (file's alpha, beta), the methods (title, key), the points'
# labels (the third column of the file their `&points file` names, when readable).
load system("dirname '".ARG0."'")."/columns.gp"
if (!exists("file")) file = 'out/default_paper_chart.dat'
if (!exists("curves")) curves = 'out/boundaries_exact_boundaries.dat'
if (!exists("paper_curves")) paper_curves = 'out/boundaries_paper_boundaries.dat'
if (!exists("points")) points = 'out/fig4_points.dat'
if (!exists("out")) out = 'out/fig3_boundaries.png'
set encoding utf8
set terminal pngcairo size 1000,780 font "Sans,11"
set output out
set palette defined (0 "#f3efe6", 1 "#23406e")
set cbrange [0:1]
unset colorbox
set xrange [low(file, 'alpha'):high(file, 'alpha')]
set yrange [low(file, 'beta'):high(file, 'beta')]
set xlabel "α = aπ²/ρ"
set ylabel "β = gπ²/(ρω²)"
set key at graph 0.98, graph 0.98 right top box opaque samplen 3 font ",10" noenhanced
extra = ''
if (readable(paper_curves)) {
   extra = sprintf(", named('%s') using 'alpha':'beta' with points pt 7 ps 0.25 lc '#9a9a9a' title \"S = ±2, %s\"", \
      paper_curves, method_name(paper_curves))
}
if (readable(points)) {
   labels = points_labels(points)
   extra = extra . sprintf(", named('%s') using 'alpha':'beta' with points pt 7 ps 1.3 lc 'black' title 'points'", points) . \
      (labels eq '' ? '' : sprintf(", '%s' using 1:2:3 with labels offset 1.4,0.6 font ',10' tc 'black' notitle", labels))
}
set title sprintf("The chart of method %s (dark = stable) with the transition curves by %s", method_name(file), \
   method_name(curves)) noenhanced
plot file using col(file, 'alpha'):col(file, 'beta'):col(file, 'stable') with image notitle, \
     named(curves) using 'alpha':(column('kind') > 0 ? column('beta') : 1/0) with lines lw 2.5 lc "#f2b134" \
        title "S = +2, ".method_name(curves), \
     named(curves) using 'alpha':(column('kind') < 0 ? column('beta') : 1/0) with lines lw 2.5 lc "#e8553e" \
        title "S = −2, ".method_name(curves) @extra

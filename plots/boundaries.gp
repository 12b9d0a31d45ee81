# A stability chart with its transition curves drawn as lines (S = +2 blue, S = -2 orange;
# dashed: a tongue of zero width, both curves of that order coincide): out/boundaries.png
# of `make run`, the exact chart of the elastic model and the curves by Hill's method.
# Call from any directory (defaults: the files `make run` writes into out/ here):
#   gnuplot -e "file='a_chart.dat'; curves='b_boundaries.dat'; out='x.png'" PATH/plots/boundaries.gp
# Parameters: file (a chart), curves (a boundaries file with the columns kind and coexist,
# task boundaries by an exact method), out (the image).
# From the headers: the ranges (the chart's alpha, beta), the methods and the model (title,
# axis labels).
load system("dirname '".ARG0."'")."/columns.gp"
if (!exists("file")) file = 'out/boundaries_chart_chart.dat'
if (!exists("curves")) curves = 'out/boundaries_exact_boundaries.dat'
if (!exists("out")) out = 'out/boundaries.png'
set encoding utf8
set terminal pngcairo size 1000,800 font "Sans,11"
set output out
set palette defined (0 "#f3efe6", 1 "#9fb4d6")
set cbrange [0:1]
unset colorbox
set xrange [low(file, 'alpha'):high(file, 'alpha')]
set yrange [low(file, 'beta'):high(file, 'beta')]
# the axes: the pendulum's physical meaning (both bounces), or Strutt's (drive strength, mean stiffness)
if (scene_value(file, 'model') eq 'elastic' || scene_value(file, 'model') eq 'modulated') {
   set xlabel "α = aπ²/ρ"
   set ylabel "β = gπ²/(ρω²)"
} else {
   set xlabel "α  (drive strength)"
   set ylabel "β  (mean stiffness)"
}
set key at graph 0.02, graph 0.98 left top Left reverse box opaque samplen 3 font ",10"
curves_by_ = method_name(curves)
if (strstrt(curves_by_, 'every curve by ') == 1) curves_by_ = curves_by_[16:*]
set title sprintf("Model %s: %s (light blue = stable)\ntransition curves by %s", \
   scene_value(file, 'model'), method_title(file), curves_by_) noenhanced
plot named(file) using 'alpha':'beta':'stable' with image notitle, \
     named(curves) using 'alpha':(column('kind') > 0 && column('coexist') == 0 ? column('beta') : 1/0) with lines lw 2 lc "#1f4e9c" title "S = +2, a_n, b_n (periodic)", \
     named(curves) using 'alpha':(column('kind') > 0 && column('coexist') == 1 ? column('beta') : 1/0) with lines lw 2 dt 2 lc "#1f4e9c" title "S = +2, a_n = b_n: zero-width tongue", \
     named(curves) using 'alpha':(column('kind') < 0 && column('coexist') == 0 ? column('beta') : 1/0) with lines lw 2 lc "#d9730d" title "S = −2, a_n, b_n (antiperiodic; open tongues)"

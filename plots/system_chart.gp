# A stability chart of a system of Hill equations (task chart, &scene model = 'system'): left
# the verdict by kind (parametric at +1, at -1, combination resonance, marginal), right the
# largest Floquet exponent mu. out/system_pendula.png of `make run` is the two coupled
# pendula on a shaken support (data/scenes/system_pendula.nml); a system in first-order form
# (&equations state) is titled by its states.
# Call from any directory (default: the file `make run` writes into out/ here):
#   gnuplot -e "file='my_chart.dat'; out='x.png'" PATH/plots/system_chart.gp
# Parameters: file (a system chart with columns alpha, beta, stable, kind, mu), out (the image).
# From the header: the ranges, the number of degrees of freedom and the method.
load system("dirname '".ARG0."'")."/columns.gp"
if (!exists("file")) file = 'out/system_pendula_chart.dat'
if (!exists("out")) out = 'out/system_pendula.png'
set encoding utf8
set terminal pngcairo size 1500,650 font "Sans,11"
set output out
# the first two columns are the axes (alpha and beta, or an equations system's parameters)
x_name = word(column_names(file), 1)
y_name = word(column_names(file), 2)
set xrange [low(file, x_name):high(file, x_name)]
set yrange [low(file, y_name):high(file, y_name)]
# an equations system (model 'equations') names its axes' parameters in &equations alpha, beta
x_axis = scene_value(file, 'alpha')
y_axis = scene_value(file, 'beta')
if (x_axis ne '') { set xlabel x_axis noenhanced } else { set xlabel "α (drive)" }
if (y_axis ne '') { set ylabel y_axis noenhanced } else { set ylabel "β" }
# the verdict's colour: 0 stable, 1 at +1, 2 at -1, 3 combination, 4 damped, 5 marginal
shade(s, k) = s < 0 ? 5 : (s == 1 ? (k == 4 ? 4 : 0) : k)
set palette defined (0 "#f3efe6", 1 "#d9730d", 2 "#1f4e9c", 3 "#b0208a", 4 "#9fc8a0", 5 "#222222")
set cbrange [-0.5:5.5]
set palette maxcolors 6
set cbtics ("stable" 0, "unstable at +1" 1, "unstable at −1" 2, "combination" 3, "damped, stable" 4, \
   "marginal" 5) font ",9"
# a system in first-order form (&equations state) has n states
system_title = sprintf("System of Hill equations, n = %d", int(real(scene_value(file, 'n'))))
if (scene_value(file, 'state') ne '') { \
   system_title = sprintf("First-order system y' = A(t) y, %d states", int(real(scene_value(file, 'n')))) }
set multiplot layout 1,2 title sprintf("%s; %s", system_title, method_title(file)) font ",11" noenhanced
set title "verdict from the multipliers, by kind"
plot named(file) using 1:2:(shade(column('stable'), column('kind'))) with image notitle
set title "largest Floquet exponent μ = ln|λ|max / P"
set palette defined (0 "#ffffff", 0.2 "#f6d28b", 0.6 "#d9730d", 1 "#5a1a00")
set palette maxcolors 0
set cbrange [0:*]
set cbtics auto font ",9"
plot named(file) using 1:2:'mu' with image notitle
unset multiplot

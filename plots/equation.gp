# A chart of an equation written in physical time (&scene model = 'equation'): the
# stability verdict over the equation's own two parameters, the axes named after them, and
# an optional curve over it. out/kapitza.png of `make run` is the damped Kapitza pendulum
# over (drive frequency w, pivot amplitude A) with the classical stabilisation threshold
# A w = sqrt(2 g l) drawn over it.
# Call from any directory (default: the file `make run` writes into out/ here):
#   gnuplot -e "file='my_chart.dat'; out='x.png'" PATH/plots/equation.gp
# Parameters: file (a chart of an equation), out (the image); optional curve (a gnuplot
# expression of x, drawn as y = curve(x), e.g. "sqrt(2*9.81*0.2)/x") and curve_title.
# From the header: the two axes (the first two columns), the equation, the parameters and
# the method.
load system("dirname '".ARG0."'")."/columns.gp"
if (!exists("file")) file = 'out/kapitza_chart.dat'
if (!exists("out")) out = 'out/kapitza.png'
if (!exists("curve")) curve = ''
if (!exists("curve_title")) curve_title = curve
set encoding utf8
set terminal pngcairo size 1000,720 font "Sans,11"
set output out
names_ = column_names(file)
x_name = word(names_, 1)
y_name = word(names_, 2)
stable_column = col(file, 'stable')
set xrange [low(file, x_name):high(file, x_name)]
set yrange [low(file, y_name):high(file, y_name)]
set xlabel x_name noenhanced
set ylabel y_name noenhanced
set palette defined (0 "#f3efe6", 0.5 "#c9a227", 1 "#23406e")
set cbrange [0:1]
unset colorbox
set title sprintf("m x'' + c x' + k(t) x = 0, k(t) = %s, m = %s, c = %s\n%s (dark = stable)", \
   scene_value(file, 'stiffness'), scene_value(file, 'mass'), scene_value(file, 'damping'), method_title(file)) \
   font ",11" noenhanced
set key at graph 0.98, graph 0.97 right top box opaque samplen 2 font ",10" noenhanced
if (curve ne '') {
   eval sprintf("f_curve(x) = %s", curve)
   plot file using 1:2:stable_column with image notitle, \
        f_curve(x) with lines lw 2 dt 2 lc "#c0392b" title curve_title, \
        keyentry with boxes fs solid 1.0 border lc "#555555" fc "#23406e" title "stable", \
        keyentry with boxes fs solid 1.0 border lc "#555555" fc "#f3efe6" title "unstable"
} else {
   plot file using 1:2:stable_column with image notitle, \
        keyentry with boxes fs solid 1.0 border lc "#555555" fc "#23406e" title "stable", \
        keyentry with boxes fs solid 1.0 border lc "#555555" fc "#f3efe6" title "unstable"
}

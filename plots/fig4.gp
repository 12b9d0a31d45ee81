# phi(t) of the nonlinear pendulum (task series), one panel per file: out/fig4.png of
# `make run` is the paper's Fig. 4 redrawn, cases (a)-(h) over 50 radial periods.
# Call from any directory (defaults: the files `make run` writes into out/ here):
#   gnuplot -e "files='run_%s_series.dat'; cases='1 2 3'; out='x.png'" PATH/plots/fig4.gp
# Parameters: files (a sprintf pattern of the series files, %s = each word of cases),
# cases (default "a b c d e f g h"), out (the image). From each header: alpha, beta, the
# start angle (phi0 or phi0_degrees), the radial periods and the tolerance (titles).
load system("dirname '".ARG0."'")."/columns.gp"
if (!exists("files")) files = 'out/fig4%s_series.dat'
if (!exists("cases")) cases = "a b c d e f g h"
if (!exists("out")) out = 'out/fig4.png'
n = words(cases)
rows = (n + 1)/2
set encoding utf8
set terminal pngcairo size 1200,(50 + 310*rows) font "Sans,10"
set output out
first = sprintf(files, word(cases, 1))
set multiplot layout rows,(n > 1 ? 2 : 1) title sprintf("The elastic pendulum (task series): φ(t), %s radial periods, DOP853 at %s", \
   scene_value(first, 'periods'), scene_value(first, 'tolerance'))
set xlabel "t [s]"
set ylabel "φ [rad]"
set grid lc "#dddddd"
set autoscale xfix
unset key
do for [i = 1:n] {
   f = sprintf(files, word(cases, i))
   set title sprintf("(%s) α = %s, β = %s, φ(0) = %s", word(cases, i), scene_value(f, 'alpha'), scene_value(f, 'beta'), \
      start_angle(f))
   plot named(f) using 't':'phi' with lines lw 1 lc "#23406e" notitle
}
unset multiplot

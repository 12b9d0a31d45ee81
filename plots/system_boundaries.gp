# The transition curves of a system of Hill equations (task boundaries, &scene model =
# 'system') over its chart: Hill's method's curves of a multiplier at +1 and at -1 and the
# edges of the combination tongues (root-finding on Broucke's discriminant), on the verdict of
# the chart. out/system_pendula_boundaries.png of `make run` (data/scenes/system_pendula*.nml).
# Call from any directory (defaults: the files `make run` writes into out/ here):
#   gnuplot -e "file='my_chart.dat'; curves='my_boundaries.dat'; out='x.png'" PATH/plots/system_boundaries.gp
# Parameters: file (a system chart: alpha, beta, stable, kind), curves (a system boundaries
# file: alpha, beta, kind, status), out (the image). From the headers: the ranges, n, the method.
load system("dirname '".ARG0."'")."/columns.gp"
if (!exists("file")) file = 'out/system_pendula_chart.dat'
if (!exists("curves")) curves = 'out/system_pendula_boundaries.dat'
if (!exists("out")) out = 'out/system_pendula_boundaries.png'
set encoding utf8
set terminal pngcairo size 1000,760 font "Sans,11"
set output out
set xrange [low(file, 'alpha'):high(file, 'alpha')]
set yrange [low(file, 'beta'):high(file, 'beta')]
set xlabel "α (drive)"
set ylabel "β"
set palette defined (0 "#f6f3ec", 1 "#d8d2c4")
set cbrange [0:1]
unset colorbox
set key outside below horizontal samplen 2 font ",10"
set title sprintf("Transition curves of a system, n = %d: Hill's method (+1, −1) and combination edges", \
   int(real(scene_value(curves, 'n')))) font ",12" noenhanced
plot named(file) using 'alpha':'beta':(column('stable') == 1 ? 0 : 1) with image notitle, \
     named(curves) using 'alpha':(column('kind') == 1 ? column('beta') : 1/0) with points pt 7 ps 0.45 lc "#d9730d" \
        title "multiplier at +1", \
     named(curves) using 'alpha':(column('kind') == 2 ? column('beta') : 1/0) with points pt 7 ps 0.45 lc "#1f4e9c" \
        title "multiplier at −1", \
     named(curves) using 'alpha':(column('kind') == 3 ? column('beta') : 1/0) with points pt 7 ps 0.45 lc "#b0208a" \
        title "combination tongue (Krein collision)", \
     named(curves) using 'alpha':(column('status') != 0 ? column('beta') : 1/0) with points pt 6 ps 1.2 lc "black" \
        title "not confirmed"

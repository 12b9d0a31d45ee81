# The Strutt diagram (Mathieu model q = beta - nu cos(pi tau)): transition curves by Hill's
# method as lines, GSL's (pi^2/4) a_n, b_n(2 nu/pi^2) as points over them (out/strutt.png of
# `make run`).
# Call from any directory (default: the file `make run` writes into out/ here):
#   gnuplot -e "file='my_boundaries.dat'; out='x.png'" PATH/plots/strutt.gp
# Parameters: file (a boundaries file of the Mathieu model by an exact method: columns
# branch, gsl_ok, beta_gsl), out (the image). From the header: the ranges (&chart alpha_min
# ... beta_max of the run).
load system("dirname '".ARG0."'")."/columns.gp"
if (!exists("file")) file = 'out/boundaries_mathieu_boundaries.dat'
if (!exists("out")) out = 'out/strutt.png'
set encoding utf8
set terminal pngcairo size 1000,780 font "Sans,11"
set output out
set xrange [low(file, 'alpha'):high(file, 'alpha')]
set yrange [low(file, 'beta'):high(file, 'beta')]
set xlabel "ν  (q = β − ν cos πτ;  Mathieu q = 2ν/π²)"
set ylabel "β  (Mathieu a = 4β/π²)"
set key at graph 0.02, graph 0.98 left top Left reverse box opaque samplen 3 font ",10"
set title "Strutt diagram: Hill's method (lines) and GSL's a_n, b_n (points)"
plot named(file) using 'alpha':(column('branch') == 1 ? column('beta') : 1/0) with lines lw 2 lc "#1f4e9c" title "a_n by Hill's method", \
     named(file) using 'alpha':(column('branch') == 2 ? column('beta') : 1/0) with lines lw 2 lc "#d9730d" title "b_n by Hill's method", \
     named(file) every 6 using 'alpha':(column('gsl_ok') == 1 ? column('beta_gsl') : 1/0) with points pt 6 ps 0.8 lc "black" title "GSL gsl\\_sf\\_mathieu\\_a/b"

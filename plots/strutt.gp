# out/strutt.png: the Strutt diagram (Mathieu model q = beta - nu cos(pi tau)): transition
# curves by Hill's method as lines, GSL's (pi^2/4) a_n, b_n(2 nu/pi^2) as points over them.
# Needs out/boundaries_mathieu_boundaries.dat (scene boundaries_mathieu.nml).
set encoding utf8
set terminal pngcairo size 1000,780 font "Sans,11"
set output 'out/strutt.png'
set xrange [0:40]
set yrange [-20:60]
set xlabel "ν  (q = β − ν cos πτ;  Mathieu q = 2ν/π²)"
set ylabel "β  (Mathieu a = 4β/π²)"
set key at graph 0.02, graph 0.98 left top Left reverse box opaque samplen 3 font ",10"
set title "Strutt diagram: Hill's method (lines) and GSL's a_n, b_n (points)"
# columns: alpha beta kind order branch curve coexist status check beta_error modes beta_gsl gsl_ok
plot 'out/boundaries_mathieu_boundaries.dat' using 1:($5 == 1 ? $2 : 1/0) with lines lw 2 lc "#1f4e9c" title "a_n by Hill's method", \
     '' using 1:($5 == 2 ? $2 : 1/0) with lines lw 2 lc "#d9730d" title "b_n by Hill's method", \
     '' every 6 using 1:($13 == 1 ? $12 : 1/0) with points pt 6 ps 0.8 lc "black" title "GSL gsl\\_sf\\_mathieu\\_a/b"

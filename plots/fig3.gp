# A chart (filled, dark = stable) with the boundary |S| = 2 of a second chart drawn over
# it, and points marked: out/fig3.png of `make run` is the paper's Fig. 3 redrawn, its
# eq. (37) chart with the exact boundary and the Fig. 4 points.
# Call from any directory (defaults: the files `make run` writes into out/ here):
#   gnuplot -e "file='a_chart.dat'; exact='b_chart.dat'; points='c_points.dat'; out='x.png'" PATH/plots/fig3.gp
# Parameters: file (the filled chart), exact (the chart whose |S| = 2 is drawn: a contour of
# its log10_abs_S), points (optional: left out when it cannot be read), out (the image).
# From the headers: the ranges (file's alpha, beta), each chart's method (title, key), the
# points' labels (the third column of the file their `&points file` names, when readable).
load system("dirname '".ARG0."'")."/columns.gp"
if (!exists("file")) file = 'out/default_paper_chart.dat'
if (!exists("exact")) exact = 'out/default_exact_chart.dat'
if (!exists("points")) points = 'out/fig4_points.dat'
if (!exists("out")) out = 'out/fig3.png'
set encoding utf8
set terminal pngcairo size 900,720 font "Sans,11"
set output out
pi2 = pi**2
x_min = low(file, 'alpha'); x_max = high(file, 'alpha')
y_min = low(file, 'beta'); y_max = high(file, 'beta')

# the boundary: contour log10|S| = log10 2 of the second chart
set contour base
set cntrparam levels discrete log10(2.0)
unset surface
set view map
set table $boundary
splot exact using col(exact, 'alpha'):col(exact, 'beta'):col(exact, 'log10_abs_S') with lines notitle
unset table
unset contour

set palette defined (0 "#f3efe6", 1 "#23406e")
set cbrange [0:1]
unset colorbox
set xrange [x_min:x_max]
set yrange [y_min:y_max]
set xlabel "α = aπ²/ρ"
set ylabel "β = gπ²/(ρω²)"
set key at graph 0.02, graph 0.80 left top Left reverse box opaque samplen 2 font ",10"
set style textbox opaque fc "white" noborder margins 1,1
if (pi2/4 > y_min && pi2/4 < y_max) {
   set arrow 1 from x_min, pi2/4 to x_max, pi2/4 nohead dt 3 lw 1.2 lc "#c05020" front
}
points_plot = ''
if (readable(points)) {
   labels = points_labels(points)
   points_plot = sprintf(", named('%s') using 'alpha':'beta' with points pt 7 ps 1.3 lc 'black' title 'points'", points) . \
      (labels eq '' ? '' : sprintf(", '%s' using 1:2:3 with labels offset 1.4,0.6 boxed font ',10' tc 'black' notitle", labels))
}
set title sprintf("The chart of method %s (dark = stable) and the boundary |S| = 2 of method %s", method_name(file), \
   method_name(exact)) noenhanced
plot file using col(file, 'alpha'):col(file, 'beta'):col(file, 'stable') with image notitle, \
     keyentry with boxes fs solid 1.0 border lc "#555555" fc "#23406e" title "stable", \
     keyentry with boxes fs solid 1.0 border lc "#555555" fc "#f3efe6" title "unstable", \
     $boundary using 1:2 with lines lw 2 lc "#e08000" title "|S| = 2, ".method_title(exact) @points_plot

# out/fig3.png: the paper's Fig. 3 redrawn: its eq. (37) chart (filled, dark =
# stable) with the exact boundary |S| = 2 drawn over it, and the Fig. 4 points.
# Needs out/default_paper_chart.dat, out/default_exact_chart.dat, out/fig4_points.dat.
# Parameters: file (the eq. (37) chart), exact (the exact chart), points, out.
load 'plots/columns.gp'
if (!exists("file")) file = 'out/default_paper_chart.dat'
if (!exists("exact")) exact = 'out/default_exact_chart.dat'
if (!exists("points")) points = 'out/fig4_points.dat'
if (!exists("out")) out = 'out/fig3.png'
set encoding utf8
set terminal pngcairo size 900,720 font "Sans,11"
set output out
pi2 = pi**2

# the exact boundary: contour log10|S| = log10 2 of the exact chart
set contour base
set cntrparam levels discrete log10(2.0)
unset surface
set view map
set table $boundary
splot named(exact) using 'alpha':'beta':'log10_abs_S' with lines notitle
unset table
unset contour

set palette defined (0 "#f3efe6", 1 "#23406e")
set cbrange [0:1]
unset colorbox
set xrange [0:9.8]
set yrange [-2:12]
set xlabel "α = aπ²/ρ"
set ylabel "β = gπ²/(ρω²)"
set key at graph 0.02, graph 0.80 left top Left reverse box opaque samplen 2 font ",10"
set style textbox opaque fc "white" noborder margins 1,1
set arrow 1 from 0,pi2/4 to 9.8,pi2/4 nohead dt 3 lw 1.2 lc "#c05020" front
set title "Fig. 3: the paper's eq. (37) chart (dark = stable) and the exact boundary |S| = 2"
plot named(file) using 'alpha':'beta':'stable' with image notitle, \
     keyentry with boxes fs solid 1.0 border lc "#555555" fc "#23406e" title "stable by eq. (37)", \
     keyentry with boxes fs solid 1.0 border lc "#555555" fc "#f3efe6" title "unstable by eq. (37)", \
     $boundary using 1:2 with lines lw 2 lc "#e08000" title "exact |S| = 2", \
     named(points) using 'alpha':'beta' with points pt 7 ps 1.3 lc "black" title "Fig. 4 points", \
     'data/points/fig4.dat' using 1:2:3 with labels offset 1.4,0.6 boxed font ",10" tc "black" notitle

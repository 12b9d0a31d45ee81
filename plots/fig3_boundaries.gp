# out/fig3_boundaries.png: the paper's Fig. 3 redrawn: its eq. (37) chart (dark = stable)
# with the exact transition curves by Hill's method over it, and the curves of eq. (37)
# itself (roots of S = +-2 by Brent). Needs out/default_paper_chart.dat,
# out/boundaries_exact_boundaries.dat, out/boundaries_paper_boundaries.dat, out/fig4_points.dat.
# Parameters: file (the eq. (37) chart), curves (exact), paper_curves, points, out.
load 'plots/columns.gp'
if (!exists("file")) file = 'out/default_paper_chart.dat'
if (!exists("curves")) curves = 'out/boundaries_exact_boundaries.dat'
if (!exists("paper_curves")) paper_curves = 'out/boundaries_paper_boundaries.dat'
if (!exists("points")) points = 'out/fig4_points.dat'
if (!exists("out")) out = 'out/fig3_boundaries.png'
set encoding utf8
set terminal pngcairo size 1000,780 font "Sans,11"
set output out
pi2 = pi**2
set palette defined (0 "#f3efe6", 1 "#23406e")
set cbrange [0:1]
unset colorbox
set xrange [0:9.8]
set yrange [-2:12]
set xlabel "α = aπ²/ρ"
set ylabel "β = gπ²/(ρω²)"
set key at graph 0.98, graph 0.98 right top box opaque samplen 3 font ",10"
set title "Fig. 3 redrawn: eq. (37) chart (dark = stable) with the exact transition curves"
plot named(file) using 'alpha':'beta':'stable' with image notitle, \
     named(paper_curves) using 'alpha':'beta' with points pt 7 ps 0.25 lc "#9a9a9a" title "eq. (37): S = ±2", \
     named(curves) using 'alpha':(column('kind') > 0 ? column('beta') : 1/0) with lines lw 2.5 lc "#f2b134" title "exact S = +2 (Hill's method)", \
     named(curves) using 'alpha':(column('kind') < 0 ? column('beta') : 1/0) with lines lw 2.5 lc "#e8553e" title "exact S = −2 (Hill's method)", \
     named(points) using 'alpha':'beta' with points pt 7 ps 1.3 lc "black" title "Fig. 4 points", \
     'data/points/fig4.dat' using 1:2:3 with labels offset 1.4,0.6 font ",10" tc "black" notitle

# out/fig3_boundaries.png: the paper's Fig. 3 redrawn: its eq. (37) chart (dark = stable)
# with the exact transition curves by Hill's method over it, and the curves of eq. (37)
# itself (roots of S = +-2 by Brent). Needs out/default_paper_chart.dat,
# out/boundaries_exact_boundaries.dat, out/boundaries_paper_boundaries.dat, out/fig4_points.dat.
set encoding utf8
set terminal pngcairo size 1000,780 font "Sans,11"
set output 'out/fig3_boundaries.png'
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
plot 'out/default_paper_chart.dat' using 1:2:4 with image notitle, \
     'out/boundaries_paper_boundaries.dat' using 1:2 with points pt 7 ps 0.25 lc "#9a9a9a" title "eq. (37): S = ±2", \
     'out/boundaries_exact_boundaries.dat' using 1:($3 > 0 ? $2 : 1/0) with lines lw 2.5 lc "#f2b134" title "exact S = +2 (Hill's method)", \
     '' using 1:($3 < 0 ? $2 : 1/0) with lines lw 2.5 lc "#e8553e" title "exact S = −2 (Hill's method)", \
     'out/fig4_points.dat' using 1:2 with points pt 7 ps 1.3 lc "black" title "Fig. 4 points", \
     'data/points/fig4.dat' using 1:2:3 with labels offset 1.4,0.6 font ",10" tc "black" notitle

# out/fig2.png: the paper's Fig. 2: Q(τ) of eq. (25) at β = 6 and the 2-piece
# coefficient of eq. (28) (thin steps) used by eq. (37).
# Needs out/fig2_coefficient.dat (columns: tau, then Q and Qseg for α = 4, 6, 7.5, 8, 9, 9.7).
set encoding utf8
set terminal pngcairo size 1300,560 font "Sans,11"
set output 'out/fig2.png'
set xlabel "τ = ωt/π"
set ylabel "Q(τ)"
set xrange [0:4]
set key bottom right box opaque font ",10"
set grid lc "#dddddd"
set multiplot layout 1,2 title "Fig. 2: Q(τ) at β = 6 and its 2-piece version of eq. (28) (thin)" font ",13"

set title "(a) α = 4, 6, 7.5"
plot 'out/fig2_coefficient.dat' using 1:2 with lines lw 2 dt 3 lc "#1b9e77" title "α = 4", \
     '' using 1:3 with lines lw 1 dt 3 lc "#1b9e77" notitle, \
     '' using 1:4 with lines lw 2 lc "#d95f02" title "α = 6", \
     '' using 1:5 with lines lw 1 lc "#d95f02" notitle, \
     '' using 1:6 with lines lw 2 dt 2 lc "#7570b3" title "α = 7.5", \
     '' using 1:7 with lines lw 1 dt 2 lc "#7570b3" notitle

set title "(b) α = 8, 9, 9.7 (α → π²: a deep narrow dip at τ = 0, 2, ...)"
plot 'out/fig2_coefficient.dat' using 1:8 with lines lw 2 dt 3 lc "#1b9e77" title "α = 8", \
     '' using 1:9 with lines lw 1 dt 3 lc "#1b9e77" notitle, \
     '' using 1:10 with lines lw 2 lc "#d95f02" title "α = 9", \
     '' using 1:11 with lines lw 1 lc "#d95f02" notitle, \
     '' using 1:12 with lines lw 2 dt 2 lc "#7570b3" title "α = 9.7", \
     '' using 1:13 with lines lw 1 dt 2 lc "#7570b3" notitle
unset multiplot

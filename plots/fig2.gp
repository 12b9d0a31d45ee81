# out/fig2.png: the paper's Fig. 2: Q(τ) of eq. (25) at β = 6 and the 2-piece
# coefficient of eq. (28) (thin steps) used by eq. (37).
# Needs out/fig2_coefficient.dat (columns: tau, then Q and Qseg for α = 4, 6, 7.5, 8, 9, 9.7).
# Parameters: file (the coefficient file), out (the image).
load 'plots/columns.gp'
if (!exists("file")) file = 'out/fig2_coefficient.dat'
if (!exists("out")) out = 'out/fig2.png'
set encoding utf8
set terminal pngcairo size 1300,560 font "Sans,11"
set output out
set xlabel "τ = ωt/π"
set ylabel "Q(τ)"
set xrange [0:4]
set key bottom right box opaque font ",10"
set grid lc "#dddddd"
set multiplot layout 1,2 title "Fig. 2: Q(τ) at β = 6 and its 2-piece version of eq. (28) (thin)" font ",13"

set title "(a) α = 4, 6, 7.5"
plot named(file) using 'tau':'Q(4.0)' with lines lw 2 dt 3 lc "#1b9e77" title "α = 4", \
     named(file) using 'tau':'Qseg(4.0)' with lines lw 1 dt 3 lc "#1b9e77" notitle, \
     named(file) using 'tau':'Q(6.0)' with lines lw 2 lc "#d95f02" title "α = 6", \
     named(file) using 'tau':'Qseg(6.0)' with lines lw 1 lc "#d95f02" notitle, \
     named(file) using 'tau':'Q(7.5)' with lines lw 2 dt 2 lc "#7570b3" title "α = 7.5", \
     named(file) using 'tau':'Qseg(7.5)' with lines lw 1 dt 2 lc "#7570b3" notitle

set title "(b) α = 8, 9, 9.7 (α → π²: a deep narrow dip at τ = 0, 2, ...)"
plot named(file) using 'tau':'Q(8.0)' with lines lw 2 dt 3 lc "#1b9e77" title "α = 8", \
     named(file) using 'tau':'Qseg(8.0)' with lines lw 1 dt 3 lc "#1b9e77" notitle, \
     named(file) using 'tau':'Q(9.0)' with lines lw 2 lc "#d95f02" title "α = 9", \
     named(file) using 'tau':'Qseg(9.0)' with lines lw 1 lc "#d95f02" notitle, \
     named(file) using 'tau':'Q(9.7)' with lines lw 2 dt 2 lc "#7570b3" title "α = 9.7", \
     named(file) using 'tau':'Qseg(9.7)' with lines lw 1 dt 2 lc "#7570b3" notitle
unset multiplot

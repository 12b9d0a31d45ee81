# out/fig4.png: the paper's Fig. 4 redrawn from the nonlinear pendulum (task series):
# phi(t) over 50 radial periods for the cases (a)-(h). Run from the repository root
# after the scenes data/scenes/fig4[a-h].nml (`make run` does both).
# Parameters: files (a sprintf pattern of the eight series files, %s = a ... h), out.
load 'plots/columns.gp'
if (!exists("files")) files = 'out/fig4%s_series.dat'
if (!exists("out")) out = 'out/fig4.png'
set encoding utf8
set terminal pngcairo size 1200,1300 font "Sans,10"
set output out
set multiplot layout 4,2 title "Fig. 4: the elastic pendulum from φ(0) = 0.017 rad ((f), (h): 1e-20), 50 radial periods, DOP853 at 1e-10"
set xlabel "t [s]"
set ylabel "φ [rad]"
set grid lc "#dddddd"
unset key
cases = "a b c d e f g h"
labels = "'(a) α=1.48, β=2.47' '(b) α=3.70, β=2.47' '(c) α=2.57, β=1.29 (stable)' '(d) α=5.0, β=0.76 (stable)' '(e) α=7.88, β=3.95' '(f) as (e), φ(0)=1e-20' '(g) α=7.48, β=2.47' '(h) as (g), φ(0)=1e-20'"
do for [i=1:8] {
   c = word(cases, i)
   set title word(labels, i)
   plot named(sprintf(files, c)) using 't':'phi' with lines lw 1 lc "#23406e" notitle
}
unset multiplot

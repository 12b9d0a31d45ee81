# build/bench/system_cost.png from build/bench/system_cost.dat (make bench-system): the cost of
# a chart point of a system of n Hill equations (chains of n driven oscillators, method auto
# at 1e-10) against n, log-log: microseconds per point and per Magnus step, with the n³ slope
# of the dense 2n × 2n products for comparison.
# Call from any directory:
#   gnuplot -e "file='system_cost.dat'; out='x.png'" PATH/plots/bench_system.gp
if (!exists("file")) file = 'build/bench/system_cost.dat'
if (!exists("out")) out = 'build/bench/system_cost.png'
set encoding utf8
set terminal pngcairo size 800,560 font "Sans,10"
set output out
set logscale xy
set xrange [0.8:25]
set xlabel "degrees of freedom n"
set ylabel "microseconds"
set key top left
set grid
set title "systems of Hill equations: cost of a chart point against n (Magnus-6, tolerance 1e-10)"
# columns: n us_per_point steps_per_point us_per_step failures
stats file using 1:4 nooutput
n_last = STATS_max_x
step_last = STATS_max_y
plot file using 1:2 with linespoints pt 7 title "per point", \
     file using 1:4 with linespoints pt 5 title "per step", \
     step_last*(x/n_last)**3 with lines dt 2 lc rgb "gray" title "∝ n³"

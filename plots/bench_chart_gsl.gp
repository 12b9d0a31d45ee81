# out/bench_chart_gsl.png from out/bench_chart_gsl.dat (make bench, scripts/bench_chart.py): the
# 300 x 300 chart, time of a whole run against the worst error of S at the 40 reference points
# of data/reference/chart_set.dat. The plain C GSL program (rk8pd, one thread) at its seven
# tolerances as a line; hillstab (auto, two threads) as points for the full chart (text at
# tolerances 1e-8, 1e-10 and 1e-12; binary and text on disk at 1e-10) and as horizontal lines for the charts that need no S (verdict,
# growth), whose time does not depend on an error of S.
# Call from any directory (defaults: the files `make bench` writes into out/ here):
#   gnuplot -e "file='x_chart_gsl.dat'; out='x.png'" PATH/plots/bench_chart_gsl.gp
# Parameters: file (scripts/bench_chart.py --out), out (the image). From the file: the size
# of the chart (its first header line), the range of the times. (The errors are measured
# at the reference points of a 300 x 300 chart only: a file of another size has none.)
if (!exists("file")) file = 'out/bench_chart_gsl.dat'
if (!exists("out")) out = 'out/bench_chart_gsl.png'
set encoding utf8
set terminal pngcairo size 900,620 font "Sans,10"
set output out
set logscale xy
stats file using 4 nooutput
set yrange [STATS_min/2:STATS_max*2]
set format x "10^{%L}"
set xlabel "worst |S − S_{ref}|/max(1, |S_{ref}|) at 40 chart points"
set ylabel "seconds, whole run"
set key top right
set grid
size = system("sed -n '1s/.*: \\([0-9]* x [0-9]*\\) chart.*/\\1/p' '".file."'")
set title size." chart: hillstab against the plain C GSL program"
# the rows of one program and run, by the words of the run column
is(prog, word) = (strcol(1) eq prog && strstrt(strcol(2), word) > 0)
plot file using (strcol(1) eq "gsl" ? $5 : 1/0):4 with linespoints pt 7 lw 2 lc "#b2182b" \
        title "GSL rk8pd, 1 thread (tolerance 1e-8 … 1e-14)", \
     '' using (is("hillstab", "full chart, text") && !is("hillstab", "disk") ? $5 : 1/0):4 \
        with points pt 5 ps 1.6 lc "#2166ac" title "hillstab full chart, text (tmpfs; tolerance 1e-8, 1e-10, 1e-12)", \
     '' using (is("hillstab", "binary") ? $5 : 1/0):4 with points pt 4 ps 1.6 lw 2 lc "#2166ac" \
        title "hillstab full chart, binary", \
     '' using (is("hillstab", "full chart, text, on disk") ? $5 : 1/0):4 with points pt 6 ps 1.6 lw 2 \
        lc "#2166ac" title "hillstab full chart, text, on disk", \
     '' using (5e-14):(is("hillstab", "verdict chart (") ? $4 : 1/0):(1e-7):(0) with vectors nohead dt 2 lw 2 \
        lc "#1b7837" title "hillstab verdict chart (no S)", \
     '' using (5e-14):(is("hillstab", "growth") ? $4 : 1/0):(1e-7):(0) with vectors nohead dt 3 lw 2 \
        lc "#762a83" title "hillstab growth chart (mu)"

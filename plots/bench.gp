# Work-precision figure from out/bench_work_precision.dat (make bench):
# max error in S over the sample against time per point, one curve per method.
set terminal pngcairo size 1200,520 enhanced font ",11"
set output "out/bench.png"
set multiplot layout 1,2 title "hillstab: speed against error (error scaled by max(1,|S|), sample incl. alpha = 9.8)"
set logscale xy
set format x "10^{%L}"
set format y "10^{%L}"
set grid
set key top right font ",9"
# one colour per method (nine of them: gnuplot's default cycle has eight)
array colours[9] = ["#9400d3", "#009e73", "#56b4e9", "#e69f00", "#f0e442", "#0072b2", "#d55e00", "#000000", "#cc79a7"]
set ylabel "max error in S"
file = "out/bench_work_precision.dat"
load "out/bench_methods.gp"
nblocks = words(names)
set xlabel "time per point [s]"
plot for [i=0:nblocks-1] file index i using 3:($4 > 0 ? $4 : 1e-17) with linespoints pt 7 ps 0.6 \
     lc rgb colours[i+1] lw (word(names, i+1) eq "auto-rows" ? 2.5 : 1) title word(names, i+1)
set xlabel "Q evaluations per point"
plot for [i=0:nblocks-1] file index i using 6:($4 > 0 ? $4 : 1e-17) with linespoints pt 7 ps 0.6 \
     lc rgb colours[i+1] lw (word(names, i+1) eq "auto-rows" ? 2.5 : 1) title word(names, i+1)
unset multiplot

# Work-precision figure of hillstab_bench (make bench writes out/bench_work_precision.dat and
# out/bench_methods.gp, the methods' names, and draws out/bench.png): the largest error of S
# over the sample against the time per point and against the evaluations of Q per point, one
# curve per method (one gnuplot index each).
# Call from any directory (defaults: the files `make bench` writes into out/ here):
#   gnuplot -e "file='x_work_precision.dat'; out='x.png'" PATH/plots/bench.gp
# Parameters: file (hillstab_bench --out X writes X_work_precision.dat and, beside it,
# X_methods.gp, read from there), out (the image). From the file's header: the sample.
if (!exists("file")) file = 'out/bench_work_precision.dat'
if (!exists("out")) out = 'out/bench.png'
set terminal pngcairo size 1200,520 enhanced font ",11"
set output out
sample = system("sed -n 's/^# sample: //p' '".file."' | head -n 1")
set multiplot layout 1,2 title "hillstab: speed against error (error scaled by max(1,|S|)); sample: ".sample noenhanced
set logscale xy
set format x "10^{%L}"
set format y "10^{%L}"
set grid
set key top right font ",9"
# one colour per method (nine of them: gnuplot's default cycle has eight)
array colours[9] = ["#9400d3", "#009e73", "#56b4e9", "#e69f00", "#f0e442", "#0072b2", "#d55e00", "#000000", "#cc79a7"]
set ylabel "max error in S"
load file[1:strstrt(file, '_work_precision.dat') - 1].'_methods.gp'
nblocks = words(names)
set xlabel "time per point [s]"
plot for [i=0:nblocks-1] file index i using 3:($4 > 0 ? $4 : 1e-17) with linespoints pt 7 ps 0.6 \
     lc rgb colours[i+1] lw (word(names, i+1) eq "auto-rows" ? 2.5 : 1) title word(names, i+1)
set xlabel "Q evaluations per point"
plot for [i=0:nblocks-1] file index i using 6:($4 > 0 ? $4 : 1e-17) with linespoints pt 7 ps 0.6 \
     lc rgb colours[i+1] lw (word(names, i+1) eq "auto-rows" ? 2.5 : 1) title word(names, i+1)
unset multiplot

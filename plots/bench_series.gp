# out/bench_series.png from out/bench_series.dat (make bench): the nonlinear pendulum of
# Fig. 4 (e) by hillstab's DOPRI5, DOP853, PD87 (the Prince-Dormand 8(7) pair of GSL's
# rk8pd, in hillstab's integrator) and VERN98 (Verner's 9(8) pair) and by GSL's rk8pd.
# Columns: error of the state after 10 radial periods (the motion is chaotic, so the state
# after 100 periods cannot be converged); energy error after 100 periods; the largest
# energy error at the step ends over those 100 periods (same runs). Top row against the
# time per run, bottom row against the f-evaluations per run.
# Call from any directory (defaults: the files `make bench` writes into out/ here):
#   gnuplot -e "file='x_series.dat'; out='x.png'" PATH/plots/bench_series.gp
# Parameters: file (hillstab_bench_series --out X writes X_series.dat), out (the image).
# From the file: its methods (one block each, the first column) and their tolerances.
if (!exists("file")) file = 'out/bench_series.dat'
if (!exists("out")) out = 'out/bench_series.png'
set terminal pngcairo size 1650,1000 enhanced font ",11"
set output out
methods = system("awk '!/^#/ && NF && !seen[$1]++ {printf \"%s \", toupper($1)}' '".file."'")
tolerances = system("awk '!/^#/ && NF {print $2 + 0}' '".file."' | sort -g | sed -n '1p;$p' | tr '\\n' ' '")
set multiplot layout 2,3 title sprintf("nonlinear pendulum, Fig. 4 (e): speed against error (tolerances %s ... %s)", \
   word(tolerances, 2), word(tolerances, 1))
set logscale xy
set format x "10^{%L}"
set format y "10^{%L}"
set grid
set key bottom left font ",10"
names = methods
array colours[5] = ["#56b4e9", "#d55e00", "#009e73", "#cc79a7", "#000000"]
array ylabels[3] = ["state error after 10 periods (scaled by rho, rho omega)", \
                    "|E(100 T) - E(0)| / E_{scale}", \
                    "max over the steps of |E - E(0)| / E_{scale}, 100 periods"]
# row 1: error against time (columns 3, 6, 9); row 2: against f-evaluations (5, 8, 11)
do for [row=1:2] {
   set xlabel (row == 1 ? "time per run [s]" : "f-evaluations per run")
   do for [m=1:3] {
      set ylabel ylabels[m]
      x = (row == 1 ? 3*m : 3*m + 2)
      plot for [i=0:words(names) - 1] file index i using x:(column(3*m + 1)) with linespoints pt 7 ps 0.7 \
         lc rgb colours[i%5 + 1] lw 1.5 title word(names, i+1)
   }
}
unset multiplot

# Poincare sections (phi = 0 crossed with phi' > 0: r, r') of the nonlinear pendulum, two
# files side by side, one colour per orbit: out/poincare.png of `make run` is a stable chart
# point, the paper's Fig. 4 (c), beside a point inside an instability tongue, Fig. 4 (g).
# Call from any directory (defaults: the files `make run` writes into out/ here):
#   gnuplot -e "file='a_poincare.dat'; chaotic='b_poincare.dat'; out='x.png'" PATH/plots/poincare.gp
# Parameters: file and chaotic (two poincare files: left and right), out (the image).
# From the headers: alpha and beta (titles), the start angles of &poincare phi0s (keys),
# the radial periods. The blocks are read with index, so the columns are found by col().
load system("dirname '".ARG0."'")."/columns.gp"
if (!exists("file")) file = 'out/poincare_regular_poincare.dat'
if (!exists("chaotic")) chaotic = 'out/poincare_chaotic_poincare.dat'
if (!exists("out")) out = 'out/poincare.png'
set encoding utf8
set terminal pngcairo size 1400,640 font "Sans,11"
set output out
set xlabel "r  [m]  at φ = 0"
set ylabel "r'  [m/s]"
set key outside right top Left reverse samplen 1 font ",10"
set multiplot layout 1,2 title sprintf("Poincaré sections of the elastic pendulum (φ = 0, φ' > 0), %s radial periods per orbit", \
   scene_value(file, 'periods')) font ",13"
do for [f in file.' '.chaotic] {
   r = col(f, 'r'); rdot = col(f, 'r_dot')
   angles = system("echo '".scene_value(f, 'phi0s')."' | tr -d ,")
   set title sprintf("α = %s, β = %s", scene_value(f, 'alpha'), scene_value(f, 'beta'))
   plot for [k = 0:words(angles) - 1] f index k using (column(r)):(column(rdot)) with points pt 7 ps 0.25 \
        title sprintf("φ0 = %s", word(angles, k + 1))
}
unset multiplot

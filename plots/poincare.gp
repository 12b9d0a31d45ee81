# out/poincare.png: Poincare sections (phi = 0 crossed with phi' > 0: r, r') of the
# nonlinear pendulum at a stable chart point, the paper's Fig. 4 (c), and inside an
# instability tongue, Fig. 4 (g); in each panel all orbits share one energy (the
# phi0 = 0.017 start). Needs out/poincare_regular_poincare.dat and
# out/poincare_chaotic_poincare.dat (scenes poincare_regular.nml, poincare_chaotic.nml).
# Run from the repository root: gnuplot plots/poincare.gp
# Parameters: file (the regular sections), chaotic (the chaotic ones), out. The blocks are
# read with index, so the columns are found by col() (plots/columns.gp).
load 'plots/columns.gp'
if (!exists("file")) file = 'out/poincare_regular_poincare.dat'
if (!exists("chaotic")) chaotic = 'out/poincare_chaotic_poincare.dat'
if (!exists("out")) out = 'out/poincare.png'
set encoding utf8
set terminal pngcairo size 1400,640 font "Sans,11"
set output out
r_file = col(file, 'r'); rdot_file = col(file, 'r_dot')
r_chaotic = col(chaotic, 'r'); rdot_chaotic = col(chaotic, 'r_dot')
set xlabel "r  [m]  at φ = 0"
set ylabel "r'  [m/s]"
set key outside right top Left reverse samplen 1 font ",10"
set multiplot layout 1,2 title "Poincaré sections of the elastic pendulum (φ = 0, φ' > 0), 2000 radial periods per orbit" font ",13"
set title "Fig. 4 (c): α = 2.57, β = 1.29 (chart: stable) — closed curves: regular"
plot for [k=0:5] file index k using (column(r_file)):(column(rdot_file)) with points pt 7 ps 0.25 \
     title sprintf("φ0 = %s", word("0.017 0.1 0.2 0.3 0.45 0.6", k + 1))
set title "Fig. 4 (g): α = 7.48, β = 2.47 (chart: unstable) — scattered: chaotic"
plot for [k=0:3] chaotic index k using (column(r_chaotic)):(column(rdot_chaotic)) with points pt 7 ps 0.25 \
     title sprintf("φ0 = %s", word("0.017 0.3 0.6 0.9", k + 1))
unset multiplot

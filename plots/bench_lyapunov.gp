# out/bench_lyapunov.png from out/bench_lyapunov.dat and out/bench_lyapunov_map.dat
# (make bench-lyapunov): the chaos map of the physical domain from phi(0) = 0.017 at rest.
# Top: the 40 x 40 benchmark map - the 3000-period reference verdict, hillstab's verdict
# (MEGNO, default options) with the points where it differs from a clear reference marked,
# and the work per point: the plain C GSL program's f-evaluations (rk8pd) over hillstab's
# (force evaluations of the symplectic tangent map, f-evaluations where DOP853 ran).
# Bottom: MEGNO <Y> over the 400 x 400 map at 1000 periods (hillstab, defaults; every
# point when make bench-lyapunov ran with BENCH_ESTIMATE_STRIDE=1, else a sample) and the
# radial periods each point needed before its verdict was certain.
# Call from any directory (defaults: the files `make bench-lyapunov` writes into out/ here):
#   gnuplot -e "file='bench_lyapunov.dat'; map='bench_lyapunov_map.dat'; out='x.png'" PATH/plots/bench_lyapunov.gp
# Parameters: file (hillstab_bench_lyapunov map), map (hillstab_bench_lyapunov estimate),
# out (the image). From the files' first header lines: the size of each map, its radial
# periods and the start angle (titles).
if (!exists("file")) file = 'out/bench_lyapunov.dat'
if (!exists("map")) map = 'out/bench_lyapunov_map.dat'
if (!exists("out")) out = 'out/bench_lyapunov.png'
set encoding utf8
set terminal pngcairo size 1650,1050 font "Sans,10"
set output out
set xrange [0:pi**2]
set yrange [0:pi**2]
set xlabel "α = aπ²/ρ"
set ylabel "β = gπ²/(ρω²)"
set size ratio -1
# "N x N" and "P radial periods" and "phi0 = X" of a file's first line
first_line(f, pattern) = system(sprintf("sed -n '1s/.*[ :]\\(%s\\).*/\\1/p' '%s'", pattern, f))
set multiplot layout 2,3 title sprintf("chaos map of the elastic pendulum from φ(0) = %s rad: verdicts, MEGNO and work per point", \
   first_line(file, 'phi0 = [0-9.e+-]*')[8:]) font ",13"

set title sprintf("%s map, reference (DOP853): regular, not clear, chaotic", first_line(file, '[0-9]* x [0-9]*'))
set palette defined (0 "#dfe7f2", 0.5 "#f6c85f", 1 "#b2182b")
set cbrange [0:1]
unset colorbox
plot file using 1:2:3 with image notitle

set title sprintf("hillstab (%s, MEGNO): ○ differs from a clear reference", first_line(file, '[0-9]* radial periods'))
plot file using 1:2:5 with image notitle, \
     '' using 1:(($3 != 0.5 && $5 != $3) ? $2 : 1/0) with points pt 6 ps 1.5 lw 2 lc "black" notitle

set title "evaluations per point, plain C GSL over hillstab"
set logscale cb
set cbrange [1:100]
set colorbox
set cblabel "ratio"
set palette defined (0 "#f7fcf5", 0.4 "#74c476", 0.7 "#238b45", 1 "#00441b")
plot file using 1:2:($14/$11) with image notitle
unset logscale cb

set title sprintf("MEGNO ⟨Y⟩ at the end (%s map, %s)", first_line(map, '[0-9]* x [0-9]*'), \
   first_line(map, '[0-9]* radial periods'))
set logscale cb
set cbrange [0.5:1000]
set cblabel "⟨Y⟩"
set palette defined (0 "#fbfbf4", 0.25 "#fde8a0", 0.5 "#f39a3d", 0.75 "#c4312b", 1 "#4a0c16")
plot map using 1:2:($4 < 0.5 ? 0.5 : $4) with points pt 5 ps 0.3 lc palette notitle
unset logscale cb

set title "radial periods integrated (early stop once chaos is certain)"
set cbrange [0:real(word(first_line(map, '[0-9]* radial periods'), 1))]
set cblabel "periods"
set palette defined (0 "#084081", 0.5 "#7bccc4", 1 "#f7fcf0")
plot map using 1:2:6 with points pt 5 ps 0.3 lc palette notitle

set title "integrator per point: symplectic (light), DOP853 (dark)"
unset colorbox
set palette defined (1 "#e0ecf4", 2 "#4d004b")
set cbrange [1:2]
plot map using 1:2:7 with points pt 5 ps 0.3 lc palette notitle
unset multiplot

# out/lyapunov.png: the largest Lyapunov exponent of the nonlinear pendulum over the
# physical domain (each point started at phi0 = 0.017 at rest, 300 radial periods), with
# the exact transition curves S = +-2 of the chart drawn over it; beside it the verdicts:
# chart stable or unstable, orbit regular or chaotic (the file's chaotic column: MEGNO, with
# the rule in the file's header; undecided points in grey). Chaotic points stop as soon as
# their verdict is certain, so their exponent is over fewer periods (the periods column).
# Needs out/lyapunov_map_lyapunov.dat and out/boundaries_exact_boundaries.dat (scenes
# lyapunov_map.nml, boundaries_exact.nml). Run from the repository root.
set encoding utf8
set terminal pngcairo size 1500,680 font "Sans,11"
set output 'out/lyapunov.png'
pi2 = pi**2
set xrange [0.05:9.8]
set yrange [0.1:9.75]
set xlabel "α = aπ²/ρ"
set ylabel "β = gπ²/(ρω²)"
set multiplot layout 1,2 title "Elastic pendulum from φ(0) = 0.017 rad: chaos indicators over up to 300 radial periods" font ",13"

set title "exponent per radial period, with the chart's exact transition curves (S = ±2)"
set palette defined (0 "#fbfbf4", 0.06 "#fde8a0", 0.2 "#f39a3d", 0.5 "#c4312b", 1 "#4a0c16")
set cbrange [0:0.5]
set cblabel "λ (per radial period)"
set key at graph 0.02, graph 0.98 left top Left reverse box opaque samplen 2 font ",9"
plot 'out/lyapunov_map_lyapunov.dat' using 1:2:($3 < 0 ? 0 : $3) with image notitle, \
     'out/boundaries_exact_boundaries.dat' using 1:($3 > 0 ? $2 : 1/0) with lines lw 1.5 lc "#1f4e9c" title "S = +2", \
     '' using 1:($3 < 0 ? $2 : 1/0) with lines lw 1.5 lc "#2a9d8f" title "S = −2"

set title "verdicts: the chart's (linear) and the orbit's (MEGNO)"
unset colorbox
set palette defined (0 "#dfe7f2", 1 "#7a5195", 2 "#f6c85f", 3 "#b2182b", 4 "#9a9a9a")
set cbrange [0:4]
verdict(stable, chaotic) = chaotic == 0.5 ? 4 : (stable >= 0.5 ? 0 : 2) + (chaotic > 0.5 ? 1 : 0)
plot 'out/lyapunov_map_lyapunov.dat' using 1:2:(verdict($5, $10)) with image notitle, \
     'out/boundaries_exact_boundaries.dat' using 1:2 with lines lw 1 lc "#555555" notitle, \
     keyentry with boxes fs solid 1.0 fc "#dfe7f2" title "chart stable, orbit regular", \
     keyentry with boxes fs solid 1.0 fc "#7a5195" title "chart stable, orbit chaotic", \
     keyentry with boxes fs solid 1.0 fc "#f6c85f" title "chart unstable, orbit regular", \
     keyentry with boxes fs solid 1.0 fc "#b2182b" title "chart unstable, orbit chaotic", \
     keyentry with boxes fs solid 1.0 fc "#9a9a9a" title "orbit undecided"
unset multiplot

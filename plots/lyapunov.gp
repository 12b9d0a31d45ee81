# A Lyapunov map of the nonlinear pendulum (task lyapunov) with the transition curves S = +-2
# of the chart drawn over it, beside the verdicts: chart stable or unstable, orbit regular
# or chaotic (the file's chaotic column, by the rule its header states; undecided points in
# grey). out/lyapunov.png of `make run` is the physical domain from phi0 = 0.017 at rest.
# Chaotic points stop as soon as their verdict is certain, so their exponent is over fewer
# periods (the periods column).
# Call from any directory (defaults: the files `make run` writes into out/ here):
#   gnuplot -e "file='my_lyapunov.dat'; curves='my_boundaries.dat'; out='x.png'" PATH/plots/lyapunov.gp
# Parameters: file (a lyapunov map over &chart), curves (a boundaries file; optional: left
# out when it cannot be read), out (the image). From the header: the ranges (alpha, beta),
# the start angle and the radial periods (title).
load system("dirname '".ARG0."'")."/columns.gp"
if (!exists("file")) file = 'out/lyapunov_map_lyapunov.dat'
if (!exists("curves")) curves = 'out/boundaries_exact_boundaries.dat'
if (!exists("out")) out = 'out/lyapunov.png'
set encoding utf8
set terminal pngcairo size 1500,680 font "Sans,11"
set output out
set xrange [low(file, 'alpha'):high(file, 'alpha')]
set yrange [low(file, 'beta'):high(file, 'beta')]
set xlabel "α = aπ²/ρ"
set ylabel "β = gπ²/(ρω²)"
has_curves = readable(curves)
curve_plots = !has_curves ? '' : \
   sprintf(", named('%s') using 'alpha':(column('kind') > 0 ? column('beta') : 1/0) with lines lw 1.5 lc '#1f4e9c' title 'S = +2'", curves) . \
   sprintf(", named('%s') using 'alpha':(column('kind') < 0 ? column('beta') : 1/0) with lines lw 1.5 lc '#2a9d8f' title 'S = −2'", curves)
curve_lines = !has_curves ? '' : sprintf(", named('%s') using 'alpha':'beta' with lines lw 1 lc '#555555' notitle", curves)
set multiplot layout 1,2 title sprintf("Elastic pendulum from φ(0) = %s: chaos indicators over up to %s radial periods", \
   start_angle(file), scene_value(file, 'periods')) font ",13"

set title "exponent per radial period".(has_curves ? ", with the chart's transition curves (S = ±2)" : "")
set palette defined (0 "#fbfbf4", 0.06 "#fde8a0", 0.2 "#f39a3d", 0.5 "#c4312b", 1 "#4a0c16")
set cbrange [0:0.5]
set cblabel "λ (per radial period)"
set key at graph 0.02, graph 0.98 left top Left reverse box opaque samplen 2 font ",9"
plot named(file) using 'alpha':'beta':(column('lyapunov') < 0 ? 0 : column('lyapunov')) with image notitle @curve_plots

set title "verdicts: the chart's (linear) and the orbit's (MEGNO)"
unset colorbox
set palette defined (0 "#dfe7f2", 1 "#7a5195", 2 "#f6c85f", 3 "#b2182b", 4 "#9a9a9a")
set cbrange [0:4]
verdict(stable, chaotic) = chaotic == 0.5 ? 4 : (stable >= 0.5 ? 0 : 2) + (chaotic > 0.5 ? 1 : 0)
plot named(file) using 'alpha':'beta':(verdict(column('stable'), column('chaotic'))) with image notitle @curve_lines, \
     keyentry with boxes fs solid 1.0 fc "#dfe7f2" title "chart stable, orbit regular", \
     keyentry with boxes fs solid 1.0 fc "#7a5195" title "chart stable, orbit chaotic", \
     keyentry with boxes fs solid 1.0 fc "#f6c85f" title "chart unstable, orbit regular", \
     keyentry with boxes fs solid 1.0 fc "#b2182b" title "chart unstable, orbit chaotic", \
     keyentry with boxes fs solid 1.0 fc "#9a9a9a" title "orbit undecided"
unset multiplot

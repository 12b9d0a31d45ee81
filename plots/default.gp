# out/default.png: the exact stability chart of the elastic pendulum beside the
# paper's 2-piece chart of eq. (37), with the paper's Fig. 4 points.
# Run from the repository root after the default scenes: gnuplot plots/default.gp
# Parameters: file (the exact chart), paper (the eq. (37) chart), points (the Fig. 4 points
# file written by hillstab), out (the image).
load 'plots/columns.gp'
if (!exists("file")) file = 'out/default_exact_chart.dat'
if (!exists("paper")) paper = 'out/default_paper_chart.dat'
if (!exists("points")) points = 'out/fig4_points.dat'
if (!exists("out")) out = 'out/default.png'
set encoding utf8
set terminal pngcairo size 1500,650 font "Sans,11"
set output out
pi2 = pi**2

set palette defined (0 "#f3efe6", 1 "#23406e")
set cbrange [0:1]
unset colorbox
set xrange [0:9.8]
set yrange [-2:12]
set xlabel "α = aπ²/ρ   (bounce amplitude a, equilibrium length ρ)"
set ylabel "β = gπ²/(ρω²)"
set key at graph 0.01, graph 0.83 left top Left reverse box opaque samplen 2 font ",10"
# physical domain 0 < β < π²; β = π²/4 is the 4/3 pendulum (parametric resonance)
set arrow 1 from 0,0 to 9.8,0 nohead dt 2 lw 1.2 lc "#888888" front
set arrow 2 from 0,pi2 to 9.8,pi2 nohead dt 2 lw 1.2 lc "#888888" front
set arrow 3 from 0,pi2/4 to 9.8,pi2/4 nohead dt 3 lw 1.2 lc "#c05020" front
set style textbox opaque fc "white" noborder margins 1,1
set label 1 "β = π²  (r_0 = 0)" at 0.15,pi2+0.4 front boxed font ",9" tc "#555555"
set label 2 "β = π²/4  (4/3 pendulum)" at 0.15,pi2/4+0.4 front boxed font ",9" tc "#c05020"
set label 3 "β = 0" at 0.15,0.4 front boxed font ",9" tc "#555555"

set multiplot layout 1,2 title "Elastic pendulum: stability of a small swing about the vertical bounce  (dark = stable)" font ",13"

# point labels up and to the right, except (a), which would sit under the β = π²/4 box
label_dy(name) = name eq "(a)" ? -0.45 : 0.35
set title "exact monodromy (method auto)"
plot named(file) using 'alpha':'beta':'stable' with image notitle, \
     named(points) using 'alpha':'beta':(column('stable') > 0.5 ? 0x1a9850 : 0xd73027) with points pt 7 ps 1.4 lc rgb variable notitle, \
     'data/points/fig4.dat' using ($1 + 0.12):($2 + label_dy(strcol(3))):3 with labels left boxed font ",10" tc "black" notitle, \
     keyentry with boxes fs solid 1.0 border lc "#555555" fc "#23406e" title "stable chart region", \
     keyentry with boxes fs solid 1.0 border lc "#555555" fc "#f3efe6" title "unstable chart region", \
     keyentry with points pt 7 ps 1.4 lc "#1a9850" title "Fig. 4 point, stable (exact)", \
     keyentry with points pt 7 ps 1.4 lc "#d73027" title "Fig. 4 point, unstable (exact)"

set title "the paper's eq. (37): Q in two constant pieces"
plot named(paper) using 'alpha':'beta':'stable' with image notitle, \
     named(points) using 'alpha':'beta':(column('stable') > 0.5 ? 0x1a9850 : 0xd73027) with points pt 7 ps 1.4 lc rgb variable notitle, \
     'data/points/fig4.dat' using ($1 + 0.12):($2 + label_dy(strcol(3))):3 with labels left boxed font ",10" tc "black" notitle, \
     keyentry with boxes fs solid 1.0 border lc "#555555" fc "#23406e" title "stable by eq. (37)", \
     keyentry with boxes fs solid 1.0 border lc "#555555" fc "#f3efe6" title "unstable by eq. (37)", \
     keyentry with points pt 7 ps 1.4 lc "#1a9850" title "Fig. 4 point, stable (exact)", \
     keyentry with points pt 7 ps 1.4 lc "#d73027" title "Fig. 4 point, unstable (exact)"
unset multiplot

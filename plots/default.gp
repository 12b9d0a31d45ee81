# Two stability charts side by side, with points marked: out/default.png of `make run` is the
# exact chart of the elastic pendulum beside the paper's 2-piece chart of eq. (37), with
# the paper's Fig. 4 points.
# Call from any directory (defaults: the files `make run` writes into out/ here):
#   gnuplot -e "file='a_chart.dat'; paper='b_chart.dat'; points='c_points.dat'; out='x.png'" PATH/plots/default.gp
# Parameters: file (a chart), paper (a second chart, e.g. by method formula), points (a
# points file; optional: left out when it cannot be read), out (the image).
# From the headers: the axes' ranges (the charts' alpha, beta), the model and each chart's
# method (titles); the points' labels come from the third column of the file their
# header's `&points file` names, when it can be read (from here, else from the repository).
# The lines beta = 0, pi^2/4, pi^2 (the physical domain) are drawn for the elastic model.
load system("dirname '".ARG0."'")."/columns.gp"
if (!exists("file")) file = 'out/default_exact_chart.dat'
if (!exists("paper")) paper = 'out/default_paper_chart.dat'
if (!exists("points")) points = 'out/fig4_points.dat'
if (!exists("out")) out = 'out/default.png'
set encoding utf8
set terminal pngcairo size 1500,650 font "Sans,11"
set output out
pi2 = pi**2
model = header_line(file, 'model')
elastic = strstrt(model, 'elastic') == 1
x_min = low(file, 'alpha'); x_max = high(file, 'alpha')
y_min = low(file, 'beta'); y_max = high(file, 'beta')

set palette defined (0 "#f3efe6", 1 "#23406e")
set cbrange [0:1]
unset colorbox
set xrange [x_min:x_max]
set yrange [y_min:y_max]
set xlabel elastic ? "α = aπ²/ρ   (bounce amplitude a, equilibrium length ρ)" : "α"
set ylabel elastic ? "β = gπ²/(ρω²)" : "β"
set key at graph 0.01, graph 0.83 left top Left reverse box opaque samplen 2 font ",10"
set style textbox opaque fc "white" noborder margins 1,1
if (elastic) {
   # physical domain 0 < β < π²; β = π²/4 is the 4/3 pendulum (parametric resonance)
   array levels[3] = [0, pi2/4, pi2]
   array names[3] = ["β = 0", "β = π²/4  (4/3 pendulum)", "β = π²  (r_0 = 0)"]
   do for [k = 1:3] {
      if (levels[k] > y_min && levels[k] < y_max) {
         dash = k == 2 ? 3 : 2
         set arrow k from x_min, levels[k] to x_max, levels[k] nohead dt dash lw 1.2 \
            lc rgb (k == 2 ? "#c05020" : "#888888") front
         set label k names[k] at graph 0.015, first levels[k] + 0.03*(y_max - y_min) front boxed font ",9" \
            tc rgb (k == 2 ? "#c05020" : "#555555")
      }
   }
}

has_points = readable(points)
labels = has_points ? points_labels(points) : ''
points_method = has_points ? header_line(points, 'method') : ''
# a point's label up and to the right, except (a), which would sit under the β = π²/4 box
label_dy(name) = (name eq "(a)" ? -0.032 : 0.025)*(y_max - y_min)
point_plots = !has_points ? '' : \
   sprintf(", named('%s') using 'alpha':'beta':(column('stable') > 0.5 ? 0x1a9850 : 0xd73027) with points pt 7 ps 1.4 lc rgb variable notitle", points) . \
   (labels eq '' ? '' : sprintf(", '%s' using ($1 + 0.012*(x_max - x_min)):($2 + label_dy(strcol(3))):3 with labels left boxed font ',10' tc 'black' notitle", labels)) . \
   sprintf(", keyentry with points pt 7 ps 1.4 lc '#1a9850' title 'point, stable (%s)', keyentry with points pt 7 ps 1.4 lc '#d73027' title 'point, unstable (%s)'", points_method, points_method)

set multiplot layout 1,2 title "Stability of a small swing about the vertical bounce (dark = stable); model ".greek(model) font ",13" noenhanced
set title method_title(file) noenhanced
# the charts read directly, by column numbers (big files: no pipe)
plot file using col(file, 'alpha'):col(file, 'beta'):col(file, 'stable') with image notitle, \
     keyentry with boxes fs solid 1.0 border lc "#555555" fc "#23406e" title "stable chart region", \
     keyentry with boxes fs solid 1.0 border lc "#555555" fc "#f3efe6" title "unstable chart region" @point_plots
set title method_title(paper) noenhanced
plot paper using col(paper, 'alpha'):col(paper, 'beta'):col(paper, 'stable') with image notitle, \
     keyentry with boxes fs solid 1.0 border lc "#555555" fc "#23406e" title "stable by this method", \
     keyentry with boxes fs solid 1.0 border lc "#555555" fc "#f3efe6" title "unstable by this method" @point_plots
unset multiplot

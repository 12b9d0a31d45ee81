# The resonance regions of a driven problem (task regions) over its stability chart (task
# chart of the same problem and ranges): the chart's verdict as the background, each region's
# tip (the least drive at which it opens) as a point labelled with its resonance (2ω1/1: the
# simple resonance Ω = 2ω1; (ω1+ω2)/1: the sum resonance), and its width at the top drive as a
# bar, and, when an edges file (task edges) is given, each region's boundary traced from its
# tip (solid where checked a stability boundary; overlaps of two regions dotted). Regions
# closed up to the top drive, not confirmed, and difference regions of equal signature are
# left out; a stretch of the top drive unstable outside every region is drawn as a bar.
# out/column_regions.png of `make run` is Bolotin's damped column of three modes
# (data/scenes/column_regions.nml and column_edges.nml over column_equations.nml's chart).
# Call from any directory (default: the files `make run` writes into out/ here):
#   gnuplot -e "chart='my_chart.dat'; regions='my_regions.dat'; edges='my_edges.dat'; out='x.png'" PATH/plots/regions.gp
# Parameters: chart (a chart with the axes as its first two columns and a column stable),
# regions (the regions file; its frequency and drive columns are named after the chart's
# axes), edges (the edges file of the same problem and ranges, or '' for none), out (the
# image).
load system("dirname '".ARG0."'")."/columns.gp"
if (!exists("chart")) chart = 'out/column_equations_chart.dat'
if (!exists("regions")) regions = 'out/column_regions.dat'
if (!exists("edges")) edges = 'out/column_edges.dat'
if (!exists("out")) out = 'out/column_regions.png'
set encoding utf8
set terminal pngcairo size 1000,700 font "Sans,11"
set output out
x_name = word(column_names(chart), 1)
y_name = word(column_names(chart), 2)
f_name = word(column_names(regions), 6)
d_name = word(column_names(regions), 8)
set xrange [low(chart, x_name):high(chart, x_name)]
set yrange [low(chart, y_name):high(chart, y_name)]
set xlabel x_name noenhanced
set ylabel y_name noenhanced
set title sprintf("Resonance regions and their tips (frequency %s, drive %s); %s", f_name, d_name, \
   method_title(regions)) noenhanced
set palette defined (0 "#c9552f", 1 "#f3efe6")
set cbrange [0:1]
unset colorbox
shown(s) = (s == 1 || s == 2 || s == 5 || s == 6) ? 0 : 1
bar(s) = (s == 1 || s == 2 || s == 5) ? 0 : 1
label(k, o, i, j) = k == 1 ? sprintf("2ω%d/%d", i, o) : (k == 2 ? sprintf("(ω%d+ω%d)/%d", i, j, o) : \
   sprintf("(ω%d−ω%d)/%d", j, i, o))
top = high(chart, d_name)
# the edges file, when there is one: a list of one name or none
edge_files = (edges ne '' && readable(edges)) ? edges : ''
# the tip and the top edges in the chart's axes (the frequency on x or on y)
tip_x(f, d) = f_name eq x_name ? f : d
tip_y(f, d) = f_name eq x_name ? d : f
plot named(chart) using 1:2:(column('stable') > 0 ? 1 : 0) with image notitle, \
   named(regions) using (bar(column('status')) && column('edge_high') > column('edge_low') ? \
      tip_x(column('edge_low'), top) : NaN):(tip_y(column('edge_low'), top)): \
      (f_name eq x_name ? column('edge_high') - column('edge_low') : 0): \
      (f_name eq x_name ? 0 : column('edge_high') - column('edge_low')) \
      with vectors nohead lw 3 lc rgb "#1f4e9c" title "width at the top drive", \
   named(regions) using (shown(column('status')) ? tip_x(column(f_name), column(d_name)) : NaN): \
      (tip_y(column(f_name), column(d_name))) with points pt 7 ps 1.4 lc rgb "#111111" title "tip", \
   named(regions) using (shown(column('status')) ? tip_x(column(f_name), column(d_name)) : NaN): \
      (tip_y(column(f_name), column(d_name))): \
      (label(column('kind'), column('order'), column('mode_i'), column('mode_j'))) \
      with labels offset 0,1 font ",10" notitle, \
   for [e in edge_files] named(e) using \
      (column('status') == 0 || column('status') == 4 ? tip_x(column(f_name), column(d_name)) : NaN): \
      (tip_y(column(f_name), column(d_name))) with lines lw 2 lc rgb "#111111" title "boundary (task edges)", \
   for [e in edge_files] named(e) using \
      (column('status') == 1 ? tip_x(column(f_name), column(d_name)) : NaN): \
      (tip_y(column(f_name), column(d_name))) with points pt 7 ps 0.4 lc rgb "#7a7a7a" title "overlap of two regions"

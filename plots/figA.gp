# Three charts of the Mathieu equation q(tau) = beta - nu cos(pi tau) (eq. (A1)), the paper's
# Appendix A figures of `make run`:
#   out/figA1.png  the paper's 2-piece trace (A3) alone (Fig. A1),
#   out/figA3.png  (A3) with the exact Strutt diagram boundary over it (Fig. A3),
#   out/figA4.png  4 averaged pieces, the paper's (A18), with the exact boundary (Fig. A4).
# Call from any directory (defaults: the files `make run` writes into out/ here):
#   gnuplot -e "exact='a_chart.dat'; formula='b_chart.dat'; segments4='c_chart.dat'; out='x%s.png'" PATH/plots/figA.gp
# Parameters: exact (the chart whose boundary |S| = 2 is drawn: a contour of its
# log10_abs_S), formula and segments4 (two charts drawn filled), out (a sprintf pattern of
# the images, %s = 1, 3, 4). From the headers: the ranges (formula's alpha, beta), the
# model and each chart's method (titles).
load system("dirname '".ARG0."'")."/columns.gp"
if (!exists("exact")) exact = 'out/figA_exact_chart.dat'
if (!exists("formula")) formula = 'out/figA_formula_chart.dat'
if (!exists("segments4")) segments4 = 'out/figA_segments4_chart.dat'
if (!exists("out")) out = 'out/figA%s.png'
set encoding utf8
mathieu = strstrt(header_line(formula, 'model'), 'mathieu') == 1

set contour base
set cntrparam levels discrete log10(2.0)
unset surface
set view map
set table $strutt
splot named(exact) using 'alpha':'beta':'log10_abs_S' with lines notitle
unset table
unset contour

set terminal pngcairo size 800,680 font "Sans,11"
set palette defined (0 "#f3efe6", 1 "#23406e")
set cbrange [0:1]
unset colorbox
set xrange [low(formula, 'alpha'):high(formula, 'alpha')]
set yrange [low(formula, 'beta'):high(formula, 'beta')]
set xlabel mathieu ? "ν  (q = β − ν cos πτ)" : "α"
set ylabel "β"
set key at graph 0.02, graph 0.97 left top Left reverse box opaque samplen 2 font ",10"
# colour key of the chart (the image itself has no legend entry)
key_stable = 'keyentry with boxes fs solid 1.0 border lc "#555555" fc "#23406e" title "stable"'
key_unstable = 'keyentry with boxes fs solid 1.0 border lc "#555555" fc "#f3efe6" title "unstable"'
model = scene_value(formula, 'model')

set output sprintf(out, '1')
set title sprintf("Model %s, method %s (dark = stable)", model, method_name(formula)) noenhanced
plot named(formula) using 'alpha':'beta':'stable' with image notitle, @key_stable, @key_unstable

set output sprintf(out, '3')
set title sprintf("Model %s, method %s, against |S| = 2 of method %s", model, method_name(formula), method_name(exact)) \
   noenhanced
plot named(formula) using 'alpha':'beta':'stable' with image notitle, @key_stable, @key_unstable, \
     $strutt using 1:2 with lines lw 2 lc "#e08000" title "|S| = 2, ".method_name(exact)

set output sprintf(out, '4')
set title sprintf("Model %s, %s, against |S| = 2 of method %s", model, method_title(segments4), method_name(exact)) \
   noenhanced
plot named(segments4) using 'alpha':'beta':'stable' with image notitle, @key_stable, @key_unstable, \
     $strutt using 1:2 with lines lw 2 lc "#e08000" title "|S| = 2, ".method_name(exact)

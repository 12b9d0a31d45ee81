# Appendix A figures for the Mathieu equation q(τ) = β − ν cos πτ (eq. A1):
#   out/figA1.png  the paper's 2-piece trace (A3) alone (Fig. A1),
#   out/figA3.png  (A3) with the exact Strutt diagram boundary over it (Fig. A3),
#   out/figA4.png  4 averaged pieces, the paper's (A18), with the exact boundary (Fig. A4).
# Needs out/figA_formula_chart.dat, out/figA_segments4_chart.dat, out/figA_exact_chart.dat.
# Parameters: exact, formula, segments4 (the three charts); out (a sprintf pattern of the
# images, %s = 1, 3, 4).
load 'plots/columns.gp'
if (!exists("exact")) exact = 'out/figA_exact_chart.dat'
if (!exists("formula")) formula = 'out/figA_formula_chart.dat'
if (!exists("segments4")) segments4 = 'out/figA_segments4_chart.dat'
if (!exists("out")) out = 'out/figA%s.png'
set encoding utf8
pi2 = pi**2

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
set xrange [0:10]
set yrange [-2:12]
set xlabel "ν  (q = β − ν cos πτ)"
set ylabel "β"
set key at graph 0.02, graph 0.97 left top Left reverse box opaque samplen 2 font ",10"
# colour key of the chart (the image itself has no legend entry)
key_stable = 'keyentry with boxes fs solid 1.0 border lc "#555555" fc "#23406e" title "stable"'
key_unstable = 'keyentry with boxes fs solid 1.0 border lc "#555555" fc "#f3efe6" title "unstable"'

set output sprintf(out, '1')
set title "Fig. A1: Mathieu, 2-piece trace (A3)  (dark = stable)"
plot named(formula) using 'alpha':'beta':'stable' with image notitle, @key_stable, @key_unstable

set output sprintf(out, '3')
set title "Fig. A3: (A3), 2 pieces, against the exact Strutt diagram"
plot named(formula) using 'alpha':'beta':'stable' with image notitle, @key_stable, @key_unstable, \
     $strutt using 1:2 with lines lw 2 lc "#e08000" title "exact |S| = 2"

set output sprintf(out, '4')
set title "Fig. A4: 4 averaged pieces (A18) against the exact Strutt diagram"
plot named(segments4) using 'alpha':'beta':'stable' with image notitle, @key_stable, @key_unstable, \
     $strutt using 1:2 with lines lw 2 lc "#e08000" title "exact |S| = 2"

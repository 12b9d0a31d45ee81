# The onset law of the swing, from the library example onset_law (`fpm run --example
# onset_law` writes out/onset_law.dat where it runs; `make run` draws out/onset.png): per
# case, points: the observed radial periods until |phi| first exceeds 0.1; solid: the law
# n* = ln(0.1/phi0)/ln(lambda_max), lambda_max from the core; dashed: the onset of the full
# linear solution (n_linear).
# Call from any directory (defaults: the files `make run` writes into out/ here):
#   gnuplot -e "file='onset_law.dat'; out='x.png'" PATH/plots/onset.gp
# Parameters: file, out. From the file: its cases (column case, each with its alpha and
# beta) and the range of phi0; the columns by the names of its '# columns:' line.
load system("dirname '".ARG0."'")."/columns.gp"
if (!exists("file")) file = 'out/onset_law.dat'
if (!exists("out")) out = 'out/onset.png'
set encoding utf8
set terminal pngcairo size 900,600 font "Sans,11"
set output out
set logscale x
set format x "10^{%L}"
set xrange [low(file, 'phi0')/10:high(file, 'phi0')*10]
set xlabel "φ(0) [rad]"
set ylabel "radial periods until |φ| > 0.1"
set grid lc "#dddddd"
set key top right box opaque
set title "Onset of the swing: observed (points), ln(0.1/φ0)/ln λ_{max} (solid), the linear solution (dashed)"
cases = values(file, 'case')
c_case = col(file, 'case'); c_alpha = col(file, 'alpha'); c_beta = col(file, 'beta')
where(k) = sprintf("α = %s, β = %s", \
   system(sprintf("awk '!/^#/ && $%d == %s {print $%d; exit}' '%s'", c_case, word(cases, k), c_alpha, file)), \
   system(sprintf("awk '!/^#/ && $%d == %s {print $%d; exit}' '%s'", c_case, word(cases, k), c_beta, file)))
array colours[3] = ["#23406e", "#d55e00", "#009e73"]
array shapes[3] = [7, 5, 9]
is(k) = column(c_case) == real(word(cases, k))
plot for [k = 1:words(cases)] named(file) using (is(k) ? column('phi0') : 1/0):'n_observed' with points \
        pt shapes[(k - 1)%3 + 1] ps 1.3 lc rgb colours[(k - 1)%3 + 1] title sprintf("case %s: %s", word(cases, k), where(k)), \
     for [k = 1:words(cases)] named(file) using (is(k) ? column('phi0') : 1/0):'n_predicted' with lines lw 1.5 \
        lc rgb colours[(k - 1)%3 + 1] notitle, \
     for [k = 1:words(cases)] named(file) using (is(k) ? column('phi0') : 1/0):'n_linear' with lines dt 2 lw 1.5 \
        lc rgb colours[(k - 1)%3 + 1] notitle

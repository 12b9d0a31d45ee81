# Q(tau) and its N-piece version, one pair of columns per alpha of task coefficient: the
# paper's Fig. 2 (Q of eq. (25) at beta = 6 and the 2-piece coefficient of eq. (28), thin
# steps) is out/fig2.png of `make run`.
# Call from any directory (default: the file `make run` writes into out/ here):
#   gnuplot -e "file='my_coefficient.dat'; out='x.png'" PATH/plots/fig2.gp
# Parameters: file (a coefficient file: tau, then Q(alpha) and Qseg(alpha) for each alpha),
# out (the image). From the header and the column names: the alphas (the first half on the
# left, the rest on the right), beta, the pieces and their sampling, the range of tau.
load system("dirname '".ARG0."'")."/columns.gp"
if (!exists("file")) file = 'out/fig2_coefficient.dat'
if (!exists("out")) out = 'out/fig2.png'
set encoding utf8
set terminal pngcairo size 1300,560 font "Sans,11"
set output out
names = column_names(file)
alphas = ''
do for [i = 1:words(names)] {
   if (strstrt(word(names, i), 'Q(') == 1) { alphas = alphas.' '.word(names, i)[3:strlen(word(names, i)) - 1] }
}
n = words(alphas)
half = (n + 1)/2
panels = n > 1 ? 2 : 1
array colours[3] = ["#1b9e77", "#d95f02", "#7570b3"]
array dashes[3] = [3, 1, 2]
set xlabel "τ = ωt/π"
set ylabel "Q(τ)"
set xrange [low(file, 'tau'):high(file, 'tau')]
set key bottom right box opaque font ",10"
set grid lc "#dddddd"
set multiplot layout 1,panels title sprintf("Q(τ) at β = %s and its %s-piece version (%s sampling, thin)", \
   scene_value(file, 'beta'), scene_value(file, 'n_segments'), scene_value(file, 'sampling')) font ",13"
do for [panel = 1:panels] {
   first = panel == 1 ? 1 : half + 1
   last = panel == 1 ? half : n
   set title sprintf("(%s) α = %s", panel == 1 ? "a" : "b", \
      system(sprintf("echo '%s' | cut -d' ' -f%d-%d | sed 's/ /, /g'", alphas[2:], first, last)))
   plot for [i = first:last] named(file) using 'tau':(column('Q('.word(alphas, i).')')) with lines lw 2 \
           dt dashes[(i - first)%3 + 1] lc rgb colours[(i - first)%3 + 1] title "α = ".word(alphas, i), \
        for [i = first:last] named(file) using 'tau':(column('Qseg('.word(alphas, i).')')) with lines lw 1 \
           dt dashes[(i - first)%3 + 1] lc rgb colours[(i - first)%3 + 1] notitle
}
unset multiplot

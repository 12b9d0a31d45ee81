# Helpers of the shipped plots, loaded by each of them from its own folder:
#   load system("dirname '".ARG0."'")."/columns.gp"
# so that a plot runs from any directory. hillstab's files carry their column names on the
# '# columns:' line only (every other line not starting with '#' is numbers, for numpy and
# awk), and their header holds the scene that made them; the plots take names, ranges,
# titles and labels from there (plots/header.awk reads them), not from the shipped scenes.
#   plots              the folder of the plots (for plots/header.awk and the repository's
#                      data/, e.g. the labels of the paper's Fig. 4 points)
#   named(f)           the data of file f with its column names as the first line, so that
#                      `plot named(f) using 'alpha':'beta':'stable'` and column('mu') work
#                      (a gnuplot pipe through sed; blank lines, and so alpha blocks, are kept)
#   col(f, name)       the number of column `name` in file f (0 when it has none), for
#                      `plot f index k using (column(col(f, 'r'))):...`, where a header in the
#                      first block only would not reach the later blocks, and for big files:
#                      `a = col(f, 'alpha'); ...; plot f using a:b:s` reads f directly, without
#                      named()'s pipe (a 600 x 600 chart in 2.3 s instead of 3.8 s)
#   scene_value(f, v)  the value of variable v in the effective scene of f's header ("" when
#                      no group gives it), e.g. scene_value(f, 'epsilon'), scene_value(f, 'r0')
#   header_line(f, k)  the text of f's header line '# k: ...', e.g. header_line(f, 'model'),
#                      header_line(f, 'spring'), header_line(f, 'method')
#   low(f, name), high(f, name)   the smallest and largest value of column `name` of f (a
#                      degenerate range widened by 0.5), for `set xrange [low(f, 'alpha'):high(f, 'alpha')]`
#   values(f, name)    the distinct values of column `name`, blank-separated (for word())
#   readable(f)        1 when file f can be read, else 0
#   points_labels(f)   for a points file f: the file its header's `&points file` names, when it
#                      can be read (from here, else from the repository) and has a third column
#                      (labels, as data/points/fig4.dat); else ""
#   method_title(f)    "method " and f's header line 'method', e.g. "method auto, tolerance 1.0e-10"
#                      (method formula said to be the paper's 2-piece closed form)
#   method_name(f)     that line up to its first ',' or ' (': "auto", "formula", "Hill's method"
#   start_angle(f)     the pendulum's start angle of &series: "0.017 rad" (phi0) or "1.0°" (phi0_degrees)
#   greek(text)        text with alpha, beta, ... pi, tau, omega, rho, phi written as Greek letters
# Every plot takes its data files and image as parameters, with the files `make run` writes
# into out/ (relative to the current directory) as defaults:
#   gnuplot -e "file='x_chart.dat'; out='x.png'" /path/to/hillstab/plots/damped.gp
plots = system("dirname '".ARG0."'")
header_awk(f, get, key) = system(sprintf("awk -v get=%s -v key='%s' -f '%s/header.awk' '%s'", get, key, plots, f))
named(f) = "< sed -e 's/^# columns: //' -e '/^#/d' '".f."'"
column_names(f) = system("sed -n 's/^# columns: //p' '".f."' | head -n 1")
col(f, name) = (names_ = column_names(f), sum [i_ = 1:words(names_)] (word(names_, i_) eq name ? i_ : 0))
scene_value(f, v) = header_awk(f, 'scene', v)
header_line(f, k) = header_awk(f, 'line', k)
low(f, name) = real(word(header_awk(f, 'range', name), 1))
high(f, name) = real(word(header_awk(f, 'range', name), 2))
values(f, name) = header_awk(f, 'values', name)
readable(f) = int(system("test -r '".f."' && echo 1 || echo 0"))
greek(text) = system(sprintf("echo '%s' | sed -e 's/alpha/α/g; s/beta/β/g; s/epsilon/ε/g; s/kappa/κ/g; s/omega/ω/g; s/\\bpi\\b/π/g; s/\\btau\\b/τ/g; s/\\brho\\b/ρ/g; s/\\bphi/φ/g; s/\\^2/²/g; s/sqrt/√/g'", text))
labels_at_(p_) = p_ eq '' ? '' : readable(p_) ? p_ : readable(plots.'/../'.p_) ? plots.'/../'.p_ : ''
has_labels_(p_) = p_ ne '' && system("awk '!/^#/ && NF >= 3' '".p_."' | head -n 1") ne ''
points_labels(f) = (q_ = labels_at_(scene_value(f, 'file')), has_labels_(q_) ? q_ : '')
method_title(f) = (m_ = header_line(f, 'method'), "method ".m_.(m_ eq 'formula' ? ": the paper's closed form, Q in two pieces" : ''))
method_name(f) = (m_ = header_line(f, 'method'), i_ = strstrt(m_.' (', ' ('), j_ = strstrt(m_.',', ','), \
   m_[1:(i_ < j_ ? i_ : j_) - 1])
start_angle(f) = (a_ = scene_value(f, 'phi0'), a_ ne '' ? a_.' rad' : scene_value(f, 'phi0_degrees').'°')

# Columns by name for hillstab's files, which carry their names on the '# columns:' line
# only (every other line not starting with '#' is numbers, for numpy.loadtxt and awk).
#   named(f)           the data of file f with its column names as the first line, so that
#                      `plot named(f) using 'alpha':'beta':'stable'` and column('mu') work
#                      (a gnuplot pipe through sed; blank lines, and so α blocks, are kept)
#   col(f, name)       the number of column `name` in file f (0 when it has none), for
#                      `plot f index k using (column(col(f, 'r'))):...`, where a header in the
#                      first block only would not reach the later blocks
# Every plot takes its data file and image as parameters with the shipped files as defaults:
#   gnuplot -e "file='x_chart.dat'; out='x.png'" plots/chart.gp
named(f) = "< sed -e 's/^# columns: //' -e '/^#/d' '".f."'"
column_names(f) = system("sed -n 's/^# columns: //p' '".f."' | head -n 1")
col(f, name) = (names_ = column_names(f), sum [i_ = 1:words(names_)] (word(names_, i_) eq name ? i_ : 0))

#!/usr/bin/env bash
# `make run`: build hillstab, run the scenes of data/scenes (the default chart
# pair first), draw the figures with gnuplot, and say where the files are.
#   out/default.png  the exact chart beside the paper's eq. (37) chart
#   out/fig4.png     the nonlinear pendulum of the paper's Fig. 4, cases (a)-(h)
#   out/onset.png    the onset law of the swing (out/onset_law.dat)
#   out/fig2.png, out/fig3.png, out/figA1.png, out/figA3.png, out/figA4.png, out/damped.png,
#   out/boundaries.png, out/fig3_boundaries.png, out/strutt.png (transition curves)
#   out/lyapunov.png (Lyapunov map), out/poincare.png (Poincare sections)
#   out/own_pivot.png, out/own_sampled.png, out/meissner.png, out/modulated.png (other Hill equations)
#   out/kapitza.png, out/column_equations.png, out/feedback.png (equations in physical time over their
#   own parameters; the last a first-order system y' = A(t) y)
#   out/system_pendula.png, out/system_pendula_boundaries.png, out/system_column.png, out/system_chain.png
#   (systems of Hill equations)
# HILLSTAB_SCENES=DIR runs the scenes of DIR instead (same names expected).
set -euo pipefail
cd "$(dirname "$0")/.."

scenes_dir=${HILLSTAB_SCENES:-data/scenes}
scenes=(default_exact default_paper fig4_points fig2_coefficient
        figA_mathieu_formula figA_mathieu_segments4 figA_mathieu_exact damped spring_physical
        spring_amplitudes spring_boundaries spring_series spring_chart
        fig4a fig4b fig4c fig4d fig4e fig4f fig4g fig4h
        boundaries_chart boundaries_exact boundaries_paper boundaries_mathieu
        lyapunov_map lyapunov_fig4 poincare_regular poincare_chaotic
        own_pivot_chart own_pivot_boundaries own_sampled_chart own_sampled_boundaries
        meissner_chart meissner_boundaries modulated_chart modulated_boundaries kapitza_chart column_equations column_regions column_edges
        feedback_first_order
        system_pendula system_pendula_boundaries system_column system_chain)
plots=(default fig2 fig3 figA damped fig4 boundaries fig3_boundaries strutt lyapunov poincare spring_chart system_chart
       system_boundaries)

command -v gnuplot >/dev/null 2>&1 || { echo "run_default: gnuplot not found (run scripts/setup.sh)" >&2; exit 1; }

mkdir -p out
paths=()
for scene in "${scenes[@]}"; do
   paths+=("$scenes_dir/$scene.nml")
done

# every line a program prints is text: its stdout and stderr are shown as they come and
# kept, then checked to decode as UTF-8 with no control characters but tab, carriage
# return (progress) and escape (a list-directed or raw write of a number is not text)
logs=$(mktemp -d)
trap 'rm -rf "$logs"' EXIT
text_only() {   # name command...: run, show and check its output
   local name=$1
   shift
   local status=0
   "$@" > >(tee "$logs/$name.out") 2> >(tee "$logs/$name.err" >&2) || status=$?
   wait
   for stream in out err; do
      python3 - "$logs/$name.$stream" "$name" "$stream" <<'PY' || exit 1
import sys
data = open(sys.argv[1], "rb").read()
try:
    text = data.decode("utf-8")
except UnicodeDecodeError as e:
    sys.exit("run_default: %s wrote bytes that are not UTF-8 text on std%s (at byte %d)" % (sys.argv[2], sys.argv[3], e.start))
bad = [c for c in text if ord(c) < 32 and c not in "\t\n\r\x1b" or ord(c) == 127]
if bad:
    sys.exit("run_default: %s wrote control characters on std%s: %r" % (sys.argv[2], sys.argv[3], bad[:5]))
PY
   done
   return $status
}

start=$(date +%s)
flags=$(bash scripts/release_flags.sh)
link=$(bash scripts/release_link_flags.sh)
text_only hillstab bash scripts/fpm.sh run --profile release --flag "$flags" --link-flag "$link" hillstab -- "${paths[@]}"
# the onset law of the swing (a library example writing out/onset_law.dat)
text_only onset_law bash scripts/fpm.sh run --profile release --flag "$flags" --link-flag "$link" --example onset_law
plots+=(onset)
for plot in "${plots[@]}"; do
   gnuplot "plots/$plot.gp"
done
# Hill equations of other coefficients: each chart under its transition curves
for pair in own_pivot own_sampled meissner modulated; do
   gnuplot -e "file='out/${pair}_chart_chart.dat'; curves='out/${pair}_boundaries_boundaries.dat'; out='out/$pair.png'" \
      plots/boundaries.gp
done
# an equation in physical time: the Kapitza pendulum with its classical threshold A w = sqrt(2 g l)
gnuplot -e "curve='sqrt(2*9.81*0.2)/x'; curve_title='A w = sqrt(2 g l)'" plots/equation.gp
# systems of Hill equations: Mettler's column and the chain of 10 (the pendula pair is the default)
for system in column chain; do
   gnuplot -e "file='out/system_${system}_chart.dat'; out='out/system_$system.png'" plots/system_chart.gp
done
# a system written in physical time: Bolotin's damped column over (Om, P1)
gnuplot -e "file='out/column_equations_chart.dat'; out='out/column_equations.png'" plots/system_chart.gp
# a first-order system y' = A(t) y of three states: a feedback gain modulated in time
gnuplot -e "file='out/feedback_chart.dat'; out='out/feedback.png'" plots/system_chart.gp
# its resonance regions: every tip, width and boundary over that chart
gnuplot plots/regions.gp
seconds=$(( $(date +%s) - start ))

echo
echo "hillstab: scenes run and figures drawn in ${seconds} s"
echo "  default figure (exact chart beside the paper's): out/default.png"
echo "  other figures: $(cd out && ls fig*.png damped.png boundaries.png strutt.png onset.png lyapunov.png poincare.png spring_chart.png own_pivot.png own_sampled.png meissner.png modulated.png kapitza.png column_equations.png feedback.png column_regions.png system_pendula.png system_pendula_boundaries.png system_column.png system_chain.png | sed 's|^|out/|' | tr '\n' ' ')"
echo "  data (gnuplot-ready, header = scene to repeat the run): out/*.dat"

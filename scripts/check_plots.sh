#!/usr/bin/env bash
# Every shipped plot on files it has never seen (make check-plots; .ci/run): in a temporary
# directory, outside the repository, hillstab runs scenes other than the shipped ones (another
# spring, other ranges, grids, start angles, damping and sections), the library example
# onset_law, hillstab_area --quick and the benchmarks in their quick forms write their files;
# then each plots/*.gp runs there, called by its path, on those files. A plot passes when
# gnuplot exits 0, prints nothing (no warning) and writes a PNG. A plot without a case here
# fails the check, so that a new plot comes with one.
#   bash scripts/check_plots.sh            (builds fpm's release profile without -march=native)
#   HILLSTAB_PLOTS_KEEP=DIR bash scripts/check_plots.sh   also copy the images into DIR
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
command -v gnuplot >/dev/null 2>&1 || { echo "check_plots: gnuplot not found (bash scripts/setup.sh plot)" >&2; exit 1; }
mkdir -p build
profile=(--profile release --flag "")
bash scripts/fpm.sh build "${profile[@]}" >build/check_plots.log 2>&1 \
   || { cat build/check_plots.log >&2; echo "check_plots: build failed" >&2; exit 1; }
program() {
   local path
   path=$(bash scripts/fpm.sh run "${profile[@]}" --runner echo "$@" 2>/dev/null | tail -1)
   case "$path" in /*) ;; *) path=$root/$path ;; esac
   [ -x "$path" ] || { echo "check_plots: $* not built" >&2; exit 1; }
   echo "$path"
}
hillstab=$(program hillstab)
area=$(program hillstab_area)
bench=$(program hillstab_bench)
bench_series=$(program hillstab_bench_series)
bench_lyapunov=$(program hillstab_bench_lyapunov)
bench_system=$(program hillstab_bench_system)
chaos_reference=$(program hillstab_chaos_reference)
onset_law=$(program --example onset_law)

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
trap '[ -f made.log ] && tail -n 20 made.log >&2; echo "check_plots: making the files failed (line $LINENO)" >&2' ERR
cd "$work"
mkdir -p out
start=$(date +%s)

# the scenes: not the shipped ones, in other ranges
cat > pts.dat <<'EOF'
# alpha beta label
1.0  1.0  (p)
3.0  4.5  (q)
5.5  2.0  (r)
EOF
grid="alpha_min = 0.5, alpha_max = 6.0, n_alpha = 70, beta_min = -1.0, beta_max = 8.0, n_beta = 60"
scene() { local name=$1; shift; printf '%s\n' "$@" > "$name.nml"; }
scene exact "&scene task = 'chart', method = 'auto', tolerance = 1e-9, output = 'other_exact' /" "&chart $grid /"
scene paper "&scene task = 'chart', method = 'segments', n_segments = 3, sampling = 'midpoint', output = 'other_paper' /" \
   "&chart $grid /"
scene points "&scene task = 'points', method = 'magnus6', output = 'other' /" "&points file = 'pts.dat' /"
scene coefficient "&scene task = 'coefficient', n_segments = 4, sampling = 'average', output = 'other' /" \
   "&coefficient alphas = 2.0, 5.0, 8.5, beta = 3.0, n_tau = 201, tau_min = -1.0, tau_max = 3.0 /"
scene damped "&scene task = 'chart', epsilon = 0.4, output = 'other_damped' /" "&chart $grid /"
scene curves "&scene task = 'boundaries', output = 'other_exact' /" "&chart $grid /"
scene curves_paper "&scene task = 'boundaries', method = 'formula', output = 'other_paper' /" \
   "&chart alpha_min = 0.5, alpha_max = 6.0, n_alpha = 40, beta_min = -1.0, beta_max = 8.0, n_beta = 400 /"
mathieu="alpha_min = 0.0, alpha_max = 8.0, n_alpha = 50, beta_min = -1.0, beta_max = 10.0, n_beta = 50"
scene m_exact "&scene task = 'chart', model = 'mathieu', output = 'm_exact' /" "&chart $mathieu /"
scene m_formula "&scene task = 'chart', model = 'mathieu', method = 'formula', output = 'm_formula' /" "&chart $mathieu /"
scene m_segments "&scene task = 'chart', model = 'mathieu', method = 'segments', n_segments = 6, sampling = 'average', \
output = 'm_segments' /" "&chart $mathieu /"
scene m_curves "&scene task = 'boundaries', model = 'mathieu', output = 'm' /" \
   "&chart alpha_min = 0.0, alpha_max = 15.0, n_alpha = 60, beta_min = -5.0, beta_max = 25.0, n_beta = 60 /"
scene swing_1 "&scene task = 'series', output = 'swing_1' /" "&series alpha = 2.0, beta = 1.6, phi0_degrees = 5, periods = 8 /"
scene swing_2 "&scene task = 'series', output = 'swing_2' /" "&series alpha = 6.5, beta = 3.3, phi0 = 0.05, periods = 8 /"
scene swing_3 "&scene task = 'series', tolerance = 1e-9, output = 'swing_3' /" \
   "&series alpha = 4.0, beta = 2.2, phi0 = 1e-6, periods = 12, r0 = 0.25 /"
scene map "&scene task = 'lyapunov', output = 'other' /" "&series phi0_degrees = 2, periods = 20 /" \
   "&chart alpha_min = 1.0, alpha_max = 8.0, n_alpha = 12, beta_min = 0.5, beta_max = 6.0, n_beta = 10 /"
scene section_1 "&scene task = 'poincare', output = 'section_1' /" "&series alpha = 3.0, beta = 1.1, periods = 60 /" \
   "&poincare phi0s = 0.02, 0.2, 0.4 /"
scene section_2 "&scene task = 'poincare', output = 'section_2' /" "&series alpha = 7.0, beta = 2.6, periods = 60 /" \
   "&poincare phi0s = 0.02, 0.5 /"
# a lab spring: k = 40 N/m, m = 0.5 kg, r0 = 0.25 m (omega = 8.94 rad/s)
scene spring "&scene task = 'chart', output = 'lab' /" \
   "&physical g = 9.81, r0 = 0.25, a_min = 0.0, a_max = 0.2, n_a = 41, omega_min = 7.0, omega_max = 12.0, n_omega = 31 /"
scene spring_critical "&scene task = 'boundaries', output = 'lab' /" "&physical k = 40, m = 0.5, g = 9.81, r0 = 0.25 /"
# a system of two equations, other than the shipped ones: unequal masses, gyroscopic coupling
pair="&system n = 2, mass = 1, 0, 0, 0.5, b = 1.5, -0.5, -0.5, 1.2, gyroscopic = 0, 0.1, -0.1, 0, cos = -1, -0.2, -0.2, -0.6 /"
sgrid="alpha_min = 0.0, alpha_max = 1.0, n_alpha = 30, beta_min = 0.2, beta_max = 2.5, n_beta = 50"
scene sys_chart "&scene task = 'chart', model = 'system', tolerance = 1e-8, output = 'sys' /" "$pair" "&chart $sgrid /"
scene sys_curves "&scene task = 'boundaries', model = 'system', tolerance = 1e-8, output = 'sys' /" "$pair" \
   "&chart $sgrid /"
# an equation in physical time, other than the shipped Kapitza pendulum: a mass, damping, a sine term
scene eq_chart "&scene task = 'chart', model = 'equation', tolerance = 1e-8, output = 'eq' /" \
   "&equation parameters = 'm = 2.5, c = 0.3, k0 = 40, k1 = 0, W = 10', stiffness = 'k0 + k1*cos(W*t) + 5*sin(2*W*t)', \
mass = 'm', damping = 'c', frequency = 'W', alpha = 'W', beta = 'k1' /" \
   "&chart alpha_min = 2.0, alpha_max = 30.0, n_alpha = 30, beta_min = 0.0, beta_max = 80.0, n_beta = 30 /"
# its resonance regions over the same ranges
scene eq_regions "&scene task = 'regions', model = 'equation', tolerance = 1e-8, output = 'eq' /" \
   "&equation parameters = 'm = 2.5, c = 0.3, k0 = 40, k1 = 0, W = 10', stiffness = 'k0 + k1*cos(W*t) + 5*sin(2*W*t)', \
mass = 'm', damping = 'c', frequency = 'W', alpha = 'W', beta = 'k1' /" \
   "&chart alpha_min = 2.0, alpha_max = 30.0, n_alpha = 30, beta_min = 0.0, beta_max = 80.0, n_beta = 30 /" \
   "&regions order = 2 /"
# and their boundaries from each tip
scene eq_edges "&scene task = 'edges', model = 'equation', tolerance = 1e-8, output = 'eq' /" \
   "&equation parameters = 'm = 2.5, c = 0.3, k0 = 40, k1 = 0, W = 10', stiffness = 'k0 + k1*cos(W*t) + 5*sin(2*W*t)', \
mass = 'm', damping = 'c', frequency = 'W', alpha = 'W', beta = 'k1' /" \
   "&chart alpha_min = 2.0, alpha_max = 30.0, n_alpha = 30, beta_min = 0.0, beta_max = 80.0, n_beta = 30 /" \
   "&regions order = 2 /" "&edges levels = 8 /"
OMP_NUM_THREADS=2 "$hillstab" --quiet exact.nml paper.nml points.nml coefficient.nml damped.nml curves.nml \
   curves_paper.nml m_exact.nml m_formula.nml m_segments.nml m_curves.nml swing_1.nml swing_2.nml swing_3.nml map.nml \
   section_1.nml section_2.nml spring.nml spring_critical.nml sys_chart.nml sys_curves.nml eq_chart.nml eq_regions.nml \
   eq_edges.nml
# the programs' own reports go to made.log
"$onset_law" out/onset_law.dat >made.log 2>&1
"$area" --quick >>made.log 2>&1
"$bench" --quick --out quick >>made.log 2>&1
"$bench_series" --quick --out quick >>made.log 2>&1
"$bench_system" --n 4 --cost-n 2 --rounds 1 --no-gsl >>made.log 2>&1
cc -O2 "$root/bench/chart_gsl.c" -o chart_gsl -lgsl -lgslcblas -lm
cc -O2 "$root/bench/lyapunov_gsl.c" -o lyapunov_gsl -lgsl -lgslcblas -lm
# the chart benchmark reads its reference points from the repository (data/reference/)
(cd "$root" && python3 scripts/bench_chart.py "$hillstab" "$work/chart_gsl" --rounds 1 --disk "$work" \
   --scratch "$work" --out "$work/quick_chart_gsl.dat" >>"$work/made.log" 2>&1) \
   || { cat made.log >&2; echo "check_plots: scripts/bench_chart.py failed" >&2; exit 1; }
"$chaos_reference" grid 5 1000 1e-8 lyapunov_reference.dat >>made.log 2>&1
"$bench_lyapunov" map 5 30 1 lyapunov_reference.dat ./lyapunov_gsl >>made.log 2>&1
"$bench_lyapunov" estimate 20 30 7 >>made.log 2>&1
made=$(( $(date +%s) - start ))

# each plot: its parameters on these files
parameters() {
   case "$1" in
      area) echo "map='out/area_map.dat'; length='out/area_length.dat'" ;;
      bench) echo "file='quick_work_precision.dat'" ;;
      bench_chart_gsl) echo "file='quick_chart_gsl.dat'" ;;
      bench_lyapunov) echo "file='out/bench_lyapunov.dat'; map='out/bench_lyapunov_map.dat'" ;;
      bench_series) echo "file='quick_series.dat'" ;;
      bench_system) echo "file='build/bench/system_cost.dat'" ;;
      boundaries) echo "file='other_exact_chart.dat'; curves='other_exact_boundaries.dat'" ;;
      damped) echo "file='other_damped_chart.dat'" ;;
      equation) echo "file='eq_chart.dat'; curve='2*x'; curve_title='k1 = 2 W'" ;;
      default) echo "file='other_exact_chart.dat'; paper='other_paper_chart.dat'; points='other_points.dat'" ;;
      fig2) echo "file='other_coefficient.dat'" ;;
      fig3) echo "file='other_paper_chart.dat'; exact='other_exact_chart.dat'; points='other_points.dat'" ;;
      fig3_boundaries) echo "file='other_paper_chart.dat'; curves='other_exact_boundaries.dat'; \
paper_curves='other_paper_boundaries.dat'; points='other_points.dat'" ;;
      fig4) echo "files='swing_%s_series.dat'; cases='1 2 3'" ;;
      figA) echo "exact='m_exact_chart.dat'; formula='m_formula_chart.dat'; segments4='m_segments_chart.dat'; out='figA%s.png'" ;;
      lyapunov) echo "file='other_lyapunov.dat'; curves='other_exact_boundaries.dat'" ;;
      onset) echo "file='out/onset_law.dat'" ;;
      regions) echo "chart='eq_chart.dat'; regions='eq_regions.dat'; edges='eq_edges.dat'" ;;
      poincare) echo "file='section_1_poincare.dat'; chaotic='section_2_poincare.dat'" ;;
      spring_chart) echo "file='lab_chart.dat'; critical='lab_boundaries.dat'" ;;
      strutt) echo "file='m_boundaries.dat'" ;;
      system_chart) echo "file='sys_chart.dat'" ;;
      system_boundaries) echo "file='sys_chart.dat'; curves='sys_boundaries.dat'" ;;
      *) return 1 ;;
   esac
}

failed=0
count=0
for script in "$root"/plots/*.gp; do
   name=$(basename "$script" .gp)
   [ "$name" = columns ] && continue   # the helpers the plots load
   count=$((count + 1))
   if ! given=$(parameters "$name"); then
      echo "check_plots: FAILED: plots/$name.gp has no case in scripts/check_plots.sh" >&2
      failed=1
      continue
   fi
   case "$given" in
      *"out='figA%s.png'"*) images="figA1.png figA3.png figA4.png" ;;
      *) images="$name.png"; given="$given; out='$name.png'" ;;
   esac
   status=0
   gnuplot -e "$given" "$script" > "$name.log" 2>&1 || status=$?
   problem=""
   [ "$status" = 0 ] || problem="gnuplot exit status $status"
   [ -s "$name.log" ] && problem="${problem:+$problem; }gnuplot printed: $(head -c 600 "$name.log")"
   for image in $images; do
      [ "$(head -c 8 "$image" 2>/dev/null | od -An -tx1 | tr -d ' \n')" = 89504e470d0a1a0a ] \
         || problem="${problem:+$problem; }no PNG $image"
   done
   if [ -n "$problem" ]; then
      echo "check_plots: FAILED: plots/$name.gp: $problem" >&2
      failed=1
   fi
   if [ -n "${HILLSTAB_PLOTS_KEEP:-}" ]; then
      mkdir -p "$HILLSTAB_PLOTS_KEEP" && for image in $images; do [ -f "$image" ] && cp "$image" "$HILLSTAB_PLOTS_KEEP/"; done
   fi
done
seconds=$(( $(date +%s) - start ))
if [ "$failed" != 0 ]; then
   echo "check_plots: some plots failed (above)" >&2
   exit 1
fi
echo "check_plots: $count plots run from $work on files of other scenes, each a PNG and no word from gnuplot (files made in ${made} s, all in ${seconds} s)"

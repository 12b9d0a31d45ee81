#!/usr/bin/env bash
# `make bench-output`: size and write time of a large chart file in each output layout,
# side by side in one run. A 1000 x 1000 chart (alpha in [0, 9.86], beta in [-50, 50]) is
# written as text with every column, with 'alpha beta stable mu' (the growth: exact where
# |S| < 2, S elsewhere) and with 'alpha beta stable' (the verdicts only), and the same three
# as binary float64 records; each run twice, the faster kept. Method formula (the paper's
# closed form, ~0.1 us a point) makes the output dominate the run time; method auto
# (exact, tolerance 1e-10) shows what the layout changes in a real run.
# Writes out/bench_output.dat (gnuplot-ready) and prints the table.
set -euo pipefail
cd "$(dirname "$0")/.."
n=${HILLSTAB_BENCH_N:-1000}
work=$(mktemp -d "${TMPDIR:-/tmp}/hillstab_bench_output.XXXXXX")
trap 'rm -rf "$work"' EXIT
flags=$(bash scripts/release_flags.sh)
link=$(bash scripts/release_link_flags.sh)
bash scripts/fpm.sh build --profile release --flag "$flags" --link-flag "$link" >/dev/null
exe=$(bash scripts/fpm.sh run --profile release --flag "$flags" --link-flag "$link" --runner echo hillstab 2>/dev/null | tail -1)
mkdir -p out
result=out/bench_output.dat
{
   echo "# hillstab make bench-output: one ${n} x ${n} chart in each output layout (the faster of 2 runs)"
   echo "# threads: ${OMP_NUM_THREADS:-all}; bytes_per_point = size/points; seconds: wall time of the whole run"
   echo "# columns: method layout columns bytes bytes_per_point seconds"
} > "$result.part"
printf '%-8s %-7s %-28s %14s %10s %9s\n' method format columns bytes "B/point" seconds
for method in formula auto; do
   for format in text binary; do
      for columns in "" "alpha beta stable mu" "alpha beta stable"; do
         scene=$work/scene.nml
         cat > "$scene" <<NML
&scene method = '$method', tolerance = 1e-10, output = '$work/run', format = '$format', columns = '$columns' /
&chart alpha_min = 0, alpha_max = 9.86, n_alpha = $n, beta_min = -50, beta_max = 50, n_beta = $n /
NML
         best=""
         for repeat in 1 2; do
            start=$(date +%s.%N)
            "$exe" --quiet "$scene"
            end=$(date +%s.%N)
            t=$(awk -v a="$start" -v b="$end" 'BEGIN { printf "%.3f", b - a }')
            if [ -z "$best" ] || awk -v t="$t" -v b="$best" 'BEGIN { exit !(t < b) }'; then best=$t; fi
         done
         file=$work/run_chart.dat
         [ "$format" = binary ] && file=$work/run_chart.bin
         bytes=$(stat -c %s "$file")
         per=$(awk -v b="$bytes" -v n="$n" 'BEGIN { printf "%.1f", b / (n * n) }')
         label=${columns:-all}
         printf '%-8s %-7s %-28s %14s %10s %9.2f\n' "$method" "$format" "$label" "$bytes" "$per" "$best"
         printf '%s %s "%s" %s %s %.3f\n' "$method" "$format" "$label" "$bytes" "$per" "$best" >> "$result.part"
         rm -f "$file"
      done
   done
done
mv "$result.part" "$result"
echo "wrote $result"

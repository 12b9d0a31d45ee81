#!/usr/bin/env bash
# Instructions of a 300 x 300 chart (alpha in [0, 9.8], beta in [-2, 12], method auto,
# tolerance 1e-10) counted by callgrind on one thread, generic build (no -march=native), for
# two versions of hillstab side by side: the working tree and BASE (a commit, default the
# one before the chart work of issue 22). Counts do not depend on the load of the machine.
#
#   bash scripts/bench_instructions.sh [BASE]
#
# Runs per version: the full chart as text, the same as binary (so text output costs the
# difference), the verdict chart (columns 'alpha beta stable') and a 1 x 1 chart (the fixed
# cost of a run: start, scene, header, file), and a Lyapunov map (8 x 8, 200 periods). Prints the table and writes
# out/bench_instructions.dat. Needs valgrind (scripts/setup.sh valgrind); takes a few minutes.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
base=${1:-a5be02a}
bash scripts/setup.sh valgrind >/dev/null
work=$(mktemp -d "${TMPDIR:-/tmp}/hillstab_instructions.XXXXXX")
trap 'git -C "$root" worktree remove --force "$work/base" >/dev/null 2>&1 || true; rm -rf "$work"' EXIT
git worktree add --detach "$work/base" "$base" >/dev/null 2>&1

# the program of a tree, built with fpm's release profile and no extra flags
program_of() {
   (cd "$1" && bash scripts/fpm.sh build --profile release --flag "" >/dev/null 2>&1 &&
    bash scripts/fpm.sh run --profile release --flag "" --runner echo hillstab 2>/dev/null | tail -1)
}
new=$root/$(program_of "$root")
old=$work/base/$(program_of "$work/base")

scene() {   # name n columns format
   local extra=""
   [ -n "$3" ] && extra=", columns = '$3'"
   [ "$4" = binary ] && extra="$extra, format = 'binary'"
   cat > "$work/$1.nml" <<NML
&scene task = 'chart', method = 'auto', tolerance = 1e-10, output = '$work/$1'$extra /
&chart alpha_min = 0, alpha_max = 9.8, n_alpha = $2, beta_min = -2, beta_max = 12, n_beta = $2 /
NML
}
scene full 300 "" text
scene binary 300 "" binary
scene verdict 300 "alpha beta stable" text
scene tiny 1 "" text
# a Lyapunov map (the pendulum's tangent dynamics, not the chart's kernel): 8 x 8 points, 200 periods
cat > "$work/lyapunov.nml" <<NML
&scene task = 'lyapunov', output = '$work/lyapunov' /
&series periods = 200 /
&chart alpha_min = 0.5, alpha_max = 9, n_alpha = 8, beta_min = 0.5, beta_max = 9, n_beta = 8 /
NML

count() {   # program scene [options]
   local exe=$1 name=$2
   shift 2
   # a new file each time: the two versions write the same path, and a run that replaces a
   # file counts more instructions than one that writes it anew
   rm -f "$work/$name"_*.dat
   OMP_NUM_THREADS=1 valgrind --tool=callgrind --callgrind-out-file="$work/cg.out" "$exe" --quiet "$@" \
      "$work/$name.nml" 2>&1 | sed -n 's/.*Collected : \([0-9]*\).*/\1/p'
}
mkdir -p out
result=out/bench_instructions.dat
{
   echo "# hillstab instructions (callgrind, 1 thread, generic build) of a 300 x 300 auto chart at 1e-10 and a lyapunov map"
   echo "# versions: $(git -C "$work/base" log -1 --format='%h') (before) and the working tree (after)"
   echo "# text output = full text - full binary; compute = full binary - 1 x 1 chart"
   echo "# columns: run before after"
} > "$result.part"
printf '%-28s %16s %16s %8s\n' run before after ratio
for run in tiny full binary verdict lyapunov; do
   # the new program keeps a checkpoint of runs longer than its interval (seconds under
   # valgrind): an interval no run reaches, so that the count is that of a normal run
   b=$(count "$old" "$run")
   a=$(count "$new" "$run" --checkpoint-interval 1000000)
   eval "before_$run=$b after_$run=$a"
   printf '%-28s %16s %16s %8.2f\n' "$run" "$b" "$a" "$(awk -v a="$a" -v b="$b" 'BEGIN { print b / a }')"
   echo "$run $b $a" >> "$result.part"
done
for derived in text compute; do
   if [ "$derived" = text ]; then
      b=$((before_full - before_binary)); a=$((after_full - after_binary))
   else
      b=$((before_binary - before_tiny)); a=$((after_binary - after_tiny))
   fi
   printf '%-28s %16s %16s %8.2f\n' "$derived" "$b" "$a" "$(awk -v a="$a" -v b="$b" 'BEGIN { print b / a }')"
   echo "$derived $b $a" >> "$result.part"
done
mv "$result.part" "$result"
echo "wrote $result"

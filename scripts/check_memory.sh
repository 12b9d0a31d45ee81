#!/usr/bin/env bash
# valgrind memcheck on small scenes of every task and of the models with data (and a physical, binary points scene, a binary
# chart over &physical amplitudes and frequencies, a binary chart resumed from its checkpoint, a chart updating its
# checkpoint after every row, and a chart resumed from the checkpoint a write error left): no invalid access, no use
# of uninitialised values, no definite leak (--error-exitcode makes any of them fail).
# usage: scripts/check_memory.sh BUILD/app/hillstab
set -euo pipefail
hillstab=$(readlink -f "$1")
root=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp -r "$root/data" "$work/data"
cd "$work"
cat > chart.nml <<'NML'
&scene task='chart', method='auto', output='m_auto' /
&chart alpha_min=0, alpha_max=9.5, n_alpha=3, beta_min=-2, beta_max=12, n_beta=5 /
NML
cat > chart_segments.nml <<'NML'
&scene task='chart', method='segments', n_segments=4, epsilon=0.2, output='m_seg' /
&chart n_alpha=3, n_beta=4 /
NML
cat > points.nml <<'NML'
&scene task='points', method='magnus6', output='m_points' /
&points file='data/points/fig4.dat' /
NML
cat > coefficient.nml <<'NML'
&scene task='coefficient', output='m_coef' /
&coefficient n_tau=21 /
NML
cat > series.nml <<'NML'
&scene task='series', output='m_series' /
&series alpha=1.48, beta=2.47, phi0=0.017, periods=2, samples_per_period=10, r0=0.1, g=9.81 /
NML
cat > boundaries.nml <<'NML'
&scene task='boundaries', model='mathieu', output='m_bound' /
&chart alpha_min=0, alpha_max=10, n_alpha=3, beta_min=-5, beta_max=20 /
NML
cat > lyapunov.nml <<'NML'
&scene task='lyapunov', output='m_lyap' /
&series periods=3 /
&chart n_alpha=2, n_beta=2 /
NML
cat > poincare.nml <<'NML'
&scene task='poincare', output='m_poinc' /
&series periods=5 /
&poincare phi0s=0.05, 0.1 /
NML
cat > physical.nml <<'NML'
&scene task='points', output='m_phys', format='binary' /
&physical omega=10, r0=0.3, a=0.01, 0.05, kappa=0.1 /
NML
cat > checkpoint.nml <<'NML'
&scene task='chart', method='magnus4', output='m_checkpoint' /
&chart n_alpha=4, n_beta=6 /
NML
cat > resume.nml <<'NML'
&scene task='chart', method='formula', output='m_resume' /
&chart n_alpha=6, n_beta=40 /
NML
# stop_at_limit SCENE KIB CHECKPOINT: run SCENE under a file-size limit of KIB KiB (bash counts ulimit -f in
# 1024-byte blocks); it must stop with exit 2 and leave CHECKPOINT for the resumed run
stop_at_limit() {
   local code
   set +e
   (ulimit -f "$2"; "$hillstab" --quiet --checkpoint-interval 0 "$1" 2>/dev/null)
   code=$?
   set -e
   if [ "$code" -ne 2 ] || [ ! -f "$3/state" ]; then
      echo "check-memory: $1 under a file-size limit exited $code and left no checkpoint" >&2
      exit 1
   fi
}
# a checkpoint for the resumed run: the first run stops at 20 KiB
stop_at_limit resume.nml 20 m_resume_chart.dat.checkpoint
# the same for a binary chart (its records' bytes in the checkpoint), stopped at 12 KiB
cat > resume_binary.nml <<'NML'
&scene task='chart', method='formula', format='binary', output='m_resume_binary' /
&chart n_alpha=6, n_beta=40 /
NML
stop_at_limit resume_binary.nml 12 m_resume_binary_chart.bin.checkpoint
# a chart over &physical amplitudes and frequencies, in binary (a unit an amplitude)
cat > physical_chart.nml <<'NML'
&scene task='chart', format='binary', output='m_phys_chart' /
&physical g=9.81, r0=0.3, kappa=0.1, a_min=0, a_max=0.2, n_a=3, omega_min=6, omega_max=12, n_omega=4 /
NML
cat > fourier.nml <<'NML'
&scene task='chart', model='fourier', method='auto', output='m_fourier' /
&chart alpha_min=0, alpha_max=4, n_alpha=3, beta_min=-2, beta_max=12, n_beta=4 /
&fourier cos=0.5, 0, 0.25, sin=0, 0.3 /
NML
printf '%s\n' 1 0.8 0.2 -0.5 -1 -0.4 0.3 0.9 >samples.dat
cat > sampled.nml <<'NML'
&scene task='boundaries', model='sampled', output='m_sampled' /
&chart alpha_min=0, alpha_max=3, n_alpha=3, beta_min=-2, beta_max=12 /
&sampled file='samples.dat' /
NML
cat > meissner.nml <<'NML'
&scene task='chart', model='meissner', method='magnus6', epsilon=0.1, output='m_meissner' /
&chart alpha_min=0.5, alpha_max=3, n_alpha=3, beta_min=-1, beta_max=5, n_beta=3 /
NML
cat > modulated.nml <<'NML'
&scene task='boundaries', model='modulated', tolerance=1e-8, output='m_modulated' /
&chart alpha_min=0.5, alpha_max=3, n_alpha=2, beta_min=0, beta_max=6 /
NML
cat > bad.nml <<'NML'
&scene task='chart', output='m_bad' /
&chart beta_max = -, /
NML
status=0
for scene in chart chart_segments points coefficient series boundaries lyapunov poincare physical checkpoint resume \
   resume_binary physical_chart fourier sampled meissner modulated bad; do
   log="$work/$scene.valgrind"
   options=--quiet
   case $scene in
   checkpoint) options="--quiet --checkpoint-interval 0" ;;
   resume | resume_binary) options="--quiet --resume" ;;
   esac
   set +e
   # shellcheck disable=SC2086
   OMP_NUM_THREADS=2 valgrind --quiet --error-exitcode=99 --leak-check=full --show-leak-kinds=definite \
      --errors-for-leak-kinds=definite --log-file="$log" "$hillstab" $options "$scene.nml" 2>"$work/$scene.stderr"
   code=$?
   set -e
   if [ "$code" -eq 99 ] || [ -s "$log" ]; then
      echo "check-memory: $scene: valgrind reports errors:" >&2
      sed 's/^/   /' "$log" >&2
      status=1
   elif [ "$scene" = bad ] && [ "$code" -ne 2 ]; then
      echo "check-memory: bad scene exited $code, expected 2" >&2
      status=1
   elif [ "$scene" != bad ] && [ "$code" -ne 0 ]; then
      echo "check-memory: $scene exited $code" >&2
      status=1
   elif [ "$scene" = resume ] && { ! grep -q resuming "$work/$scene.stderr" || [ -e m_resume_chart.dat.checkpoint ]; }; then
      echo "check-memory: the resumed run did not resume, or left its checkpoint" >&2
      status=1
   elif [ "$scene" = resume_binary ] && { ! grep -q resuming "$work/$scene.stderr" ||
      [ -e m_resume_binary_chart.bin.checkpoint ]; }; then
      echo "check-memory: the resumed run did not resume, or left its checkpoint" >&2
      status=1
   else
      echo "check-memory: $scene: clean (exit $code)"
   fi
done
exit $status

#!/usr/bin/env bash
# Tests of hillstab_mpi (run by `make test-mpi` and CI): builds hillstab and hillstab_mpi
# with CMake (-DHILLSTAB_MPI=ON), then checks against the single-process program:
#  - np = 1, 2, 3 write the same file as hillstab (charts with many and few rows, damped,
#    a points list, a Lyapunov map, a non-distributed task, a system's chart and points, a system of one
#    equation's chart; binary charts and points lists, scalar and system; a chart over &physical
#    amplitudes and frequencies, text and binary);
#  - bad input (unknown variable, unwritable output) gives exit 2 on every rank, no hang,
#    no file; a failing point is written as hillstab writes it (status 2, placeholders),
#    with hillstab's message and exit 3 on every rank;
#  - faults: ranks reading different scenes (exit 2, no file); SIGTERM to rank 0 and to
#    mpirun, kill -9 of a worker, a file-size limit: no hang, no temporary file, the old
#    output kept;
#  - resume: a chart (text and binary) and a Lyapunov map killed with SIGKILL (rank 0) early, midway and late,
#    resumed with another number of ranks or by hillstab (and a hillstab run resumed by
#    hillstab_mpi): the file of an uninterrupted run, no checkpoint, no temporary file left;
#    a checkpoint of another scene refused (exit 2 on every rank, one message); --resume
#    without a checkpoint; SIGTERM to mpirun keeps the checkpoint and says how to resume;
#  - options: --version, --help, an unknown option.
# Every check that stops a run waits first for rank 0 to pause at a chosen unit (the test
# hook HILLSTAB_TEST_PAUSE_AFTER_UNITS, passed on with mpirun -x), so that the signal lands
# mid-run on any machine; a run that ends first fails as "precondition not reached".
# Prints one line per check and a closing `N passed, M failed`; exits 1 on a failure.
set -uo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup_mpi.sh
build=build/cmake_mpi
mkdir -p build
cmake -S . -B "$build" -DHILLSTAB_MPI=ON -DCMAKE_BUILD_TYPE=Release >"$build.log" 2>&1 \
   && cmake --build "$build" -j 2 >>"$build.log" 2>&1 \
   || { cat "$build.log"; echo "test_mpi: build failed"; exit 1; }
serial=$PWD/$build/hillstab
mpi=$PWD/$build/hillstab_mpi
# root in containers and CI; more ranks than cores on small machines
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1
export OMP_NUM_THREADS=1
run_mpi() { timeout 300 mpirun --oversubscribe -np "$@"; }

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
passed=0
failed=0
pass() { echo "  PASS mpi/$1"; passed=$((passed + 1)); }
fail() { echo "  FAIL mpi/$1"; failed=$((failed + 1)); }
check() { if eval "$2"; then pass "$1"; else fail "$1"; fi; }

# every rank's exit status, one file per rank
rank_statuses() {
   local np=$1 dir=$2
   shift 2
   rm -rf "$dir"
   mkdir -p "$dir"
   run_mpi "$np" sh -c '"$0" "$@" 2>>"'"$dir"'/stderr.$OMPI_COMM_WORLD_RANK"; echo $? > "'"$dir"'/rc.$OMPI_COMM_WORLD_RANK"' \
      "$mpi" "$@" >/dev/null 2>&1
   echo $? >"$dir/mpirun_rc"
}
all_ranks() { # all_ranks DIR NP STATUS: every rank exited with STATUS
   local k
   for ((k = 0; k < $2; k++)); do
      [ -f "$1/rc.$k" ] && [ "$(cat "$1/rc.$k")" = "$3" ] || return 1
   done
}

echo "# suite mpi"
printf '%s\n' "&scene task='chart', output='$work/many' /" \
   "&chart alpha_min=0, alpha_max=9.8, n_alpha=37, beta_min=-2, beta_max=12, n_beta=53 /" >"$work/many.nml"
printf '%s\n' "&scene task='chart', epsilon=0.3, output='$work/few' /" \
   "&chart alpha_min=4, alpha_max=9.7, n_alpha=3, beta_min=-2, beta_max=12, n_beta=401 /" >"$work/few.nml"
awk 'BEGIN { for (k = 0; k < 97; k++) printf "%.4f %.4f\n", 9.8 * k / 97, 12 - 14 * ((7 * k) % 31) / 31 }' \
   >"$work/points.dat"
printf '%s\n' "&scene task='points', method='magnus6', output='$work/pts' /" \
   "&points file='$work/points.dat' /" >"$work/pts.nml"
printf '%s\n' "&scene task='coefficient', output='$work/coef' /" "&coefficient /" >"$work/coef.nml"
printf '%s\n' "&scene task='lyapunov', output='$work/lyap' /" "&series phi0=0.017, periods=40 /" \
   "&chart alpha_min=0.5, alpha_max=9.5, n_alpha=7, beta_min=0.5, beta_max=9.5, n_beta=9 /" >"$work/lyap.nml"
# a system (2 DOF, damped, a gyroscopic term): a chart of many rows, and points in several units
sysgroup="&system n = 2, b = 1.0, 0.0, 0.0, 16.0, cos = -1.0, -0.6, -0.6, -4.0, sin = 0.0, 0.3, 0.3, 0.5, gyroscopic = 0.0, 0.2, -0.2, 0.0 /"
printf '%s\n' "&scene task='chart', model='system', epsilon=0.02, output='$work/sys' /" "$sysgroup" \
   "&chart alpha_min=0, alpha_max=1.2, n_alpha=23, beta_min=0, beta_max=3, n_beta=31 /" >"$work/sys.nml"
awk 'BEGIN { for (k = 0; k < 200; k++) printf "%.4f %.4f\n", 1.2 * ((7 * k) % 23) / 23, 3 * k / 200 }' >"$work/syspoints.dat"
printf '%s\n' "&scene task='points', model='system', method='rk', tolerance=1e-9, output='$work/syspts' /" "$sysgroup" \
   "&points file='$work/syspoints.dat' /" >"$work/syspts.nml"
# a system of one equation (the Kapitza pendulum written as &equations n = 1): the scalar path, spread too
printf '%s\n' "&scene task='chart', model='equations', output='$work/one' /" \
   "&equations n = 1, parameters = 'g = 9.81, l = 0.2, kappa = 0.2, A = 0.005, w = 314.16', stiffness = '-g/l + A*w^2/l*cos(w*t)', damping = 'kappa', frequency = 'w', alpha = 'w', beta = 'A' /" \
   "&chart alpha_min=60, alpha_max=700, n_alpha=19, beta_min=0, beta_max=0.1, n_beta=27 /" >"$work/one.nml"
# the same in binary (format = 'binary': the records of every unit, in order)
printf '%s\n' "&scene task='chart', format='binary', output='$work/bmany' /" \
   "&chart alpha_min=0, alpha_max=9.8, n_alpha=37, beta_min=-2, beta_max=12, n_beta=53 /" >"$work/bmany.nml"
printf '%s\n' "&scene task='chart', epsilon=0.3, format='binary', columns='alpha beta stable', output='$work/bfew' /" \
   "&chart alpha_min=4, alpha_max=9.7, n_alpha=3, beta_min=-2, beta_max=12, n_beta=401 /" >"$work/bfew.nml"
printf '%s\n' "&scene task='points', method='magnus6', format='binary', output='$work/bpts' /" \
   "&points file='$work/points.dat' /" >"$work/bpts.nml"
printf '%s\n' "&scene task='chart', model='system', epsilon=0.02, format='binary', output='$work/bsys' /" "$sysgroup" \
   "&chart alpha_min=0, alpha_max=1.2, n_alpha=23, beta_min=0, beta_max=3, n_beta=31 /" >"$work/bsys.nml"
printf '%s\n' "&scene task='points', model='system', method='rk', tolerance=1e-9, format='binary', output='$work/bsyspts' /" \
   "$sysgroup" "&points file='$work/syspoints.dat' /" >"$work/bsyspts.nml"
# a chart over &physical amplitudes and frequencies (a row an amplitude), text and binary
printf '%s\n' "&scene task='chart', output='$work/phys' /" \
   "&physical g = 9.81, r0 = 0.3, kappa = 0.1, a_min = 0.0, a_max = 0.2, n_a = 17, omega_min = 6, omega_max = 12, n_omega = 41 /" \
   >"$work/phys.nml"
sed "s/output=/format='binary', output=/; s#/phys'#/bphys'#" "$work/phys.nml" >"$work/bphys.nml"
for name in many:chart few:chart pts:points coef:coefficient lyap:lyapunov sys:chart syspts:points one:chart \
   bmany:chart:bin bfew:chart:bin bpts:points:bin bsys:chart:bin bsyspts:points:bin phys:chart bphys:chart:bin; do
   IFS=: read -r scene task ext <<<"$name"
   file="$work/${scene}_${task}.${ext:-dat}"
   "$serial" -q "$work/$scene.nml" && mv "$file" "$work/$scene.serial"
   for np in 1 2 3; do
      rm -f "$file"
      run_mpi "$np" "$mpi" -q "$work/$scene.nml"
      rc=$?
      check "${scene}_np${np}_same_file" '[ $rc -eq 0 ] && cmp -s "$file" "$work/$scene.serial" && { [ -z "$ext" ] || grep -aq "format: binary" "$file"; }'
   done
done
# the data lines alone are identical too (the header is, since the scene file is the same)
check "data_lines" 'cmp -s <(grep -v "^#" "$work/many_chart.dat") <(grep -v "^#" "$work/many.serial") && [ $(grep -vc "^#" "$work/many.serial") -eq $((37 * 53 + 36)) ]'

# bad input: every rank exits 2, nothing written
printf '%s\n' "&scene task='chart', output='$work/bad' /" "&chart n_alpah=3 /" >"$work/bad.nml"
for np in 1 3; do
   rank_statuses "$np" "$work/st" "$work/bad.nml"
   check "bad_scene_np${np}_exit2_every_rank" 'all_ranks "$work/st" $np 2 && [ ! -e "$work/bad_chart.dat" ]'
   check "bad_scene_np${np}_one_message" '[ $(cat "$work"/st/stderr.* | grep -c "n_alpah") -eq 1 ]'
done
# (a missing directory is created; under a regular file none can be)
printf '%s\n' "&scene task='chart', output='$work/bad.nml/dir/x' /" "&chart n_alpha=3, n_beta=3 /" >"$work/nodir.nml"
rank_statuses 3 "$work/st" "$work/nodir.nml"
check "unwritable_output_exit2_every_rank" 'all_ranks "$work/st" 3 2'
rank_statuses 2 "$work/st" "$work/missing.nml"
check "missing_scene_exit2_every_rank" 'all_ranks "$work/st" 2 2'

# a failing point (method auto at alpha = 9.8696, beta = 1e13: no digit of S reliable): as hillstab, the file is
# written with the point's status and placeholders, every rank exits 3, the message is hillstab's
awk 'BEGIN { for (k = 0; k < 40; k++) print (k == 23 ? 9.8696 : 1 + k / 10), (k == 23 ? 1e13 : 2.0) }' >"$work/fail.dat"
printf '%s\n' "&scene task='points', method='auto', output='$work/fail' /" "&points file='$work/fail.dat' /" \
   >"$work/fail.nml"
"$serial" -q "$work/fail.nml" 2>"$work/fail.serial_message"
serial_rc=$?
mv "$work/fail_points.dat" "$work/fail.serial"
for np in 1 2 3; do
   rm -f "$work/fail_points.dat"
   rank_statuses "$np" "$work/st" -q "$work/fail.nml"
   check "failing_point_np${np}_exit3_every_rank" '[ $serial_rc -eq 3 ] && all_ranks "$work/st" $np 3'
   check "failing_point_np${np}_message" \
      '[ "$(cat "$work"/st/stderr.*)" = "$(sed "s/^hillstab:/hillstab_mpi:/" "$work/fail.serial_message")" ]'
   check "failing_point_np${np}_same_file" 'cmp -s "$work/fail_points.dat" "$work/fail.serial"'
done
# a chart whose first point fails: status and file as hillstab's
printf '%s\n' "&scene task='chart', output='$work/fail' /" \
   "&chart alpha_min=3, alpha_max=3, n_alpha=2, beta_min=2, beta_max=1e13, n_beta=3 /" >"$work/fail_chart.nml"
"$serial" -q "$work/fail_chart.nml" 2>/dev/null
serial_rc=$?
mv "$work/fail_chart.dat" "$work/fail_chart.serial"
rank_statuses 3 "$work/st" -q "$work/fail_chart.nml"
check "failing_chart_np3_as_serial" 'all_ranks "$work/st" 3 $serial_rc && cmp -s "$work/fail_chart.dat" "$work/fail_chart.serial"'
check "no_temporary_files" '[ -z "$(ls "$work" | grep part)" ]'

# faults: ranks that read different scenes; signals; a killed worker; a file-size limit.
# Each: no temporary file, the old output kept, no hang (every mpirun under timeout).
mkdir -p "$work/A" "$work/B"
printf '%s\n' "&scene method='formula', output='out' /" "&chart n_alpha=10, n_beta=20 /" >"$work/A/s.nml"
printf '%s\n' "&scene method='formula', output='out' /" "&chart n_alpha=10, n_beta=20, beta_max=8 /" \
   >"$work/B/s.nml"
timeout 120 mpirun --oversubscribe -np 1 --wdir "$work/A" "$mpi" -q s.nml : -np 2 --wdir "$work/B" "$mpi" -q s.nml \
   >/dev/null 2>"$work/mismatch.err"
mismatch_rc=$?
check "mismatched_scenes_exit2_no_file" '[ $mismatch_rc = 2 ] && [ ! -e "$work/A/out_chart.dat" ] && [ ! -e "$work/B/out_chart.dat" ] && grep -q "ranks read different scenes" "$work/mismatch.err"'
printf '%s\n' "&scene method='magnus6', tolerance=1e-12, output='$work/sig' /" \
   "&chart n_alpha=1500, n_beta=1500 /" >"$work/sig.nml"
# interrupt a long chart: SIGTERM to rank 0, to mpirun, kill -9 of a worker; rank 0 waits
# after the chart's first row (the test hook HILLSTAB_TEST_PAUSE_AFTER_UNITS), so that the
# signal lands mid-run whatever the machine's speed
for how in rank0_term mpirun_term worker_kill; do
   echo old >"$work/sig_chart.dat"
   HILLSTAB_TEST_PAUSE_AFTER_UNITS=1 timeout 120 mpirun --oversubscribe -x HILLSTAB_TEST_PAUSE_AFTER_UNITS -np 2 \
      "$mpi" -q "$work/sig.nml" >/dev/null 2>"$work/sig.err" &
   launcher=$!
   for _ in $(seq 1200); do
      grep -q "test hook: paused" "$work/sig.err" 2>/dev/null && break
      kill -0 "$launcher" 2>/dev/null || break
      sleep 0.1
   done
   if ! grep -q "test hook: paused" "$work/sig.err" 2>/dev/null; then
      kill -KILL "$launcher" 2>/dev/null
      wait "$launcher"
      echo "    $how: precondition not reached: the run ended (or ran two minutes) before rank 0 paused after its first row; nothing was tested"
      fail "${how}_no_temporary_file_old_kept"
      continue
   fi
   ranks=$(pgrep -f "^$mpi -q $work/sig.nml" | sort -n)
   rank0=$(echo "$ranks" | sed -n 1p)
   worker=$(echo "$ranks" | sed -n 2p)
   case $how in
   rank0_term) kill -TERM "$rank0" ;;
   mpirun_term) pkill -TERM -f "^mpirun --oversubscribe -x HILLSTAB_TEST_PAUSE_AFTER_UNITS -np 2 $mpi -q $work/sig.nml" ;;
   worker_kill) kill -KILL "$worker" ;;
   esac
   wait "$launcher"
   rc=$?
   sleep 0.5
   [ -n "$(ls "$work" | grep sig_chart.dat.part)" ] && echo "    $how: left $(ls "$work" | grep sig_chart.dat.part), exit $rc"
   check "${how}_no_temporary_file_old_kept" '[ -z "$(ls "$work" | grep sig_chart.dat.part)" ] && [ "$(cat "$work/sig_chart.dat")" = old ] && [ $rc != 0 ] && [ $rc != 124 ]'
done
printf '%s\n' "&scene method='formula', output='$work/big' /" "&chart n_alpha=300, n_beta=300 /" >"$work/big.nml"
echo old >"$work/big_chart.dat"
timeout 120 mpirun --oversubscribe -np 2 bash -c "ulimit -f 100; exec \"$mpi\" -q \"$work/big.nml\"" >/dev/null \
   2>"$work/big.err"
big_rc=$?
check "file_size_limit_message_no_hang" '[ $big_rc = 2 ] && grep -q "File too large" "$work/big.err" && [ "$(cat "$work/big_chart.dat")" = old ] && [ -z "$(ls "$work" | grep big_chart.dat.part)" ]'

# resume: runs killed with SIGKILL once their checkpoint (updated after every unit) holds
# UNITS units, then resumed; the file must be the uninterrupted one
printf '%s\n' "&scene task='chart', method='magnus6', tolerance=1e-12, output='$work/rc' /" \
   "&chart alpha_min=0, alpha_max=9.8, n_alpha=24, beta_min=-2, beta_max=12, n_beta=300 /" >"$work/rc.nml"
printf '%s\n' "&scene task='chart', method='magnus6', tolerance=1e-12, format='binary', output='$work/rb' /" \
   "&chart alpha_min=0, alpha_max=9.8, n_alpha=24, beta_min=-2, beta_max=12, n_beta=300 /" >"$work/rb.nml"
printf '%s\n' "&scene task='lyapunov', output='$work/rl' /" "&series phi0=0.017, periods=250 /" \
   "&lyapunov lanes=1, early_stop=.false. /" \
   "&chart alpha_min=0.5, alpha_max=9.5, n_alpha=8, beta_min=0.5, beta_max=9.5, n_beta=25 /" >"$work/rl.nml"
"$serial" -q "$work/rc.nml" 2>/dev/null && mv "$work/rc_chart.dat" "$work/rc.serial"
"$serial" -q "$work/rb.nml" 2>/dev/null && mv "$work/rb_chart.bin" "$work/rb.serial"
"$serial" -q "$work/rl.nml" 2>/dev/null && mv "$work/rl_lyapunov.dat" "$work/rl.serial"
# stop_at SCENE TASK UNITS SIGNAL WHO [EXT]: run SCENE (its file's extension EXT, dat by default) (WHO: mpi or mpirun, 2 ranks; serial) with
# the test hook HILLSTAB_TEST_PAUSE_AFTER_UNITS=UNITS (the writer waits once the checkpoint
# records UNITS units) and send SIGNAL to rank 0 (WHO mpi), to mpirun (WHO mpirun) or to
# hillstab once the checkpoint holds UNITS units; sets rc and ck, and reached (1: the signal
# was sent while the run went on; 0: the run ended or ran two minutes first, said on stdout)
stop_at() {
   local scene=$1 task=$2 units=$3 sig=$4 who=$5 ext=${6:-dat} pid n u target
   ck="$work/${scene}_${task}.$ext.checkpoint"
   rm -rf "$ck" "$work/${scene}_${task}.$ext"
   export HILLSTAB_TEST_PAUSE_AFTER_UNITS=$units
   if [ "$who" != serial ]; then
      timeout 120 mpirun --oversubscribe -x HILLSTAB_TEST_PAUSE_AFTER_UNITS -np 2 "$mpi" -q --checkpoint-interval 0 \
         "$work/$scene.nml" >/dev/null 2>"$work/stop.err" &
   else
      timeout 120 "$serial" -q --checkpoint-interval 0 "$work/$scene.nml" >/dev/null 2>"$work/stop.err" &
   fi
   pid=$!
   unset HILLSTAB_TEST_PAUSE_AFTER_UNITS
   n=0
   reached=0
   while kill -0 "$pid" 2>/dev/null; do
      u=$(sed -n 's/^units = \([0-9]*\) .*/\1/p' "$ck/state" 2>/dev/null)
      if [ "${u:-0}" -ge "$units" ]; then
         if [ "$who" = mpi ]; then
            target=$(pgrep -f "^$mpi -q --checkpoint-interval 0 $work/$scene.nml" | sort -n | head -1)
         elif [ "$who" = mpirun ]; then
            target=$(pgrep -f "^mpirun --oversubscribe -x HILLSTAB_TEST_PAUSE_AFTER_UNITS -np 2 $mpi -q --checkpoint-interval 0 $work/$scene.nml")
         else
            target=$(pgrep -f "^$serial -q --checkpoint-interval 0 $work/$scene.nml")
         fi
         kill -"$sig" $target
         reached=1
         break
      fi
      n=$((n + 1))
      [ $n -ge 12000 ] && break
      sleep 0.01
   done
   [ $reached = 1 ] || kill -KILL "$pid" 2>/dev/null
   { wait "$pid"; } 2>/dev/null
   rc=$?
   [ $reached = 1 ] || echo "    precondition not reached: $scene ($who) ended with status $rc (or ran two minutes) before its checkpoint recorded $units units, so the signal could not land mid-run; nothing was tested"
}
# resume_by SCENE TASK HOW: --resume by HOW (np2, np3: hillstab_mpi; serial); sets rc
resume_by() {
   case $3 in
   np*) run_mpi "${3#np}" "$mpi" -q --resume "$work/$1.nml" 2>"$work/resume.err" ;;
   serial) "$serial" -q --resume "$work/$1.nml" 2>"$work/resume.err" ;;
   esac
   rc=$?
}
for case in rc:chart:2:mpi:np3 rc:chart:12:mpi:serial rc:chart:20:mpi:np2 rc:chart:10:serial:np2 \
   rl:lyapunov:2:mpi:np2 rl:lyapunov:8:mpi:serial rl:lyapunov:12:mpi:np3 \
   rb:chart:3:mpi:np3:bin rb:chart:11:mpi:serial:bin rb:chart:17:serial:np2:bin; do
   IFS=: read -r scene task units who how ext <<<"$case"
   ext=${ext:-dat}
   name="resume_${task}_${who}_killed_after_${units}_by_$how"
   [ "$ext" = dat ] || name="resume_binary_${task}_${who}_killed_after_${units}_by_$how"
   stop_at "$scene" "$task" "$units" KILL "$who" "$ext"
   if [ $reached = 0 ]; then
      fail "${name}_killed_with_checkpoint"
      continue
   fi
   done_units=$(sed -n 's/^units = \([0-9]*\) .*/\1/p' "$ck/state" 2>/dev/null)
   bytes=$(sed -n 's/^bytes = //p' "$ck/state" 2>/dev/null)
   check "${name}_killed_with_checkpoint" '[ $rc != 0 ] && [ $rc != 124 ] && [ "${done_units:-0}" -ge $units ] && [ "${bytes:-0}" -le $(stat -c %s "$ck/data") ] && [ ! -e "$work/${scene}_${task}.$ext" ]'
   resume_by "$scene" "$task" "$how"
   check "${name}_same_file" '[ $rc = 0 ] && cmp -s "$work/${scene}_${task}.$ext" "$work/$scene.serial" && grep -q "resuming" "$work/resume.err"'
   check "${name}_nothing_left" '[ ! -e "$ck" ] && [ -z "$(ls "$work" | grep "${scene}_${task}.$ext.part")" ]'
done
# a checkpoint of another scene: exit 2 on every rank, one message naming the variable
# (beside the note on a temporary file the killed rank 0 may have left, which the run removes)
stop_at rc chart 3 KILL mpi
sed 's/n_beta=300/n_beta=301/' "$work/rc.nml" >"$work/rc_other.nml"
rank_statuses 3 "$work/st" -q --resume "$work/rc_other.nml"
check "resume_other_scene_exit2_every_rank" '[ $reached = 1 ] && all_ranks "$work/st" 3 2 && [ -d "$ck" ] && [ ! -e "$work/rc_chart.dat" ]'
check "resume_other_scene_one_message" '[ "$(cat "$work"/st/stderr.* | grep -c "&chart: n_beta: 301 in this scene, 300 in the checkpoint")" = 1 ] && [ "$(cat "$work"/st/stderr.* | grep -v ": removed .*a temporary file of" | wc -l)" = 1 ]'
# without --resume: discarded with one note, the whole file
rank_statuses 2 "$work/st" -q "$work/rc.nml"
check "no_resume_discards_with_a_note" 'all_ranks "$work/st" 2 0 && [ "$(cat "$work"/st/stderr.* | grep -c "discarded the checkpoint")" = 1 ] && [ ! -e "$ck" ] && cmp -s "$work/rc_chart.dat" "$work/rc.serial"'
# --resume without a checkpoint: starts afresh, says so once
rm -f "$work/rl_lyapunov.dat"
rank_statuses 3 "$work/st" -q --resume "$work/rl.nml"
check "resume_without_checkpoint" 'all_ranks "$work/st" 3 0 && [ "$(cat "$work"/st/stderr.* | grep -c "no checkpoint of .*starting afresh")" = 1 ] && cmp -s "$work/rl_lyapunov.dat" "$work/rl.serial"'
# SIGTERM to rank 0: the checkpoint is kept, rank 0 says how to resume, no temporary file;
# to mpirun: the same on the disk (mpirun need not pass on what rank 0 prints as it ends)
stop_at rc chart 4 TERM mpi
check "sigterm_rank0_keeps_checkpoint" '[ $reached = 1 ] && [ $rc != 0 ] && [ $rc != 124 ] && [ -f "$ck/state" ] && [ -z "$(ls "$work" | grep rc_chart.dat.part)" ] && grep -q "stopped by signal 15; the checkpoint .* keeps .*hillstab_mpi --resume $work/rc.nml" "$work/stop.err"'
resume_by rc chart np2
check "sigterm_rank0_then_resumed" '[ $rc = 0 ] && cmp -s "$work/rc_chart.dat" "$work/rc.serial" && [ ! -e "$ck" ]'
# (mpirun acts on SIGTERM about a second later, while rank 0 waits in the test hook; a
# temporary file mpirun's SIGKILL may leave is removed by the resumed run)
stop_at rc chart 4 TERM mpirun
check "sigterm_mpirun_keeps_checkpoint" '[ $reached = 1 ] && [ $rc != 0 ] && [ $rc != 124 ] && [ -f "$ck/state" ] && [ ! -e "$work/rc_chart.dat" ]'
resume_by rc chart np3
check "sigterm_mpirun_then_resumed" '[ $rc = 0 ] && cmp -s "$work/rc_chart.dat" "$work/rc.serial" && [ ! -e "$ck" ] && [ -z "$(ls "$work" | grep rc_chart.dat.part)" ]'

# options
check "version" '[ "$(run_mpi 2 "$mpi" --version)" = "$("$serial" --version | sed s/hillstab/hillstab_mpi/)" ]'
help_text=$(run_mpi 2 "$mpi" --help)
check "help" '[[ "$help_text" == *"usage: mpirun"* ]]'
rank_statuses 2 "$work/st" --frobnicate
check "unknown_option_exit2_every_rank" 'all_ranks "$work/st" 2 2'

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]

!> Tests of checkpoints and `--resume` (hillstab_batch_output_checkpoint, hillstab_batch_run_units): the
!> hillstab program (built beside this test program) is killed with SIGKILL early, midway and
!> late in a chart (text and binary) and a Lyapunov map, and `--resume` must then write the file an
!> uninterrupted run writes, byte for byte, computing only what is missing, and leave no
!> checkpoint and no temporary file; SIGTERM keeps the checkpoint and says how to resume; a
!> checkpoint of another scene is refused (exit 2) naming the difference; `--resume` without
!> a checkpoint starts afresh and says so; a run without `--resume` discards one with a
!> note; anything planted at the checkpoint's name (symbolic links, a hard link, a
!> directory open to others) is refused and left untouched, as is a checkpoint whose `data`
!> or `state` is a FIFO (never opened: no hang), a directory or a symbolic link; a second run
!> is refused while the first writes; a write error keeps the checkpoint and a resumed run
!> completes the file (text and binary); a checkpoint of another kind of problem (a scalar chart's under a
!> system scene, a state recording a system chart under the scalar scene) is never resumed.
module test_checkpoint
   use hillstab_core_kinds, only: wp, int64
   use hillstab_core_error, only: error_t, err_io, err_input
   use hillstab_core_text, only: integer_text
   use hillstab_batch_run_scenes, only: run_scene_file
   use hillstab_batch_output_checkpoint, only: checkpoint_options_t, checkpoint_directory, scene_difference
   use hillstab_batch_output_digest, only: text_digest
   use hillstab_batch_run_cli, only: exit_status
   use hillstab_fault_injection, only: limit_file_size, lift_file_size_limit
   use hillstab_testing
   use hillstab_test_scratch, only: padded, scratch_prefix, write_file, read_lines, file_exists, delete_file, contains_text, &
      any_temp_file, program_path
   implicit none
   private
   public :: collect_checkpoint

   !> A scene run by the program, its output and the file of an uninterrupted run.
   type :: fixture_t
      character(len=:), allocatable :: scene      !! the scene file
      character(len=:), allocatable :: output     !! the file it writes
      character(len=:), allocatable :: reference  !! that file from an uninterrupted run
      integer :: n_units = 0                      !! units of a serial run
      logical :: ready = .false.                  !! made (the reference written)
   end type fixture_t

   type(fixture_t), save :: chart, map, system_chart, system_points
   !> The status of `stop_program` when the run did not reach the units it was to be stopped at.
   integer, parameter :: not_reached = 250

contains

   function collect_checkpoint() result(suite)
      type(testsuite_t) :: suite
      suite = new_testsuite("checkpoint", [ &
         new_unittest("chart_resumed_after_kill", chart_resumed_after_kill), &
         new_unittest("lyapunov_resumed_after_kill", lyapunov_resumed_after_kill), &
         new_unittest("system_resumed_after_kill", system_resumed_after_kill), &
         new_unittest("sigterm_keeps_checkpoint", sigterm_keeps_checkpoint), &
         new_unittest("damaged_checkpoint_refused", damaged_checkpoint_refused), &
         new_unittest("probe_digit_flip_refused", probe_digit_flip_refused), &
         new_unittest("killed_before_checkpoint", killed_before_checkpoint), &
         new_unittest("other_scene_refused", other_scene_refused), &
         new_unittest("resume_without_checkpoint", resume_without_checkpoint), &
         new_unittest("discarded_without_resume", discarded_without_resume), &
         new_unittest("planted_links_not_followed", planted_links_not_followed), &
         new_unittest("second_run_refused", second_run_refused), &
         new_unittest("write_error_keeps_checkpoint", write_error_keeps_checkpoint), &
         new_unittest("binary_resumed_after_kill", binary_resumed_after_kill), &
         new_unittest("binary_write_error_resumed", binary_write_error_resumed), &
         new_unittest("scene_differences", scene_differences), &
         new_unittest("long_output_names", long_output_names), &
         new_unittest("planted_members_kept", planted_members_kept), &
         new_unittest("other_problem_kind", other_problem_kind)])
   end function collect_checkpoint

   !> Run a shell command; its exit status.
   integer function shell(command) result(status)
      character(len=*), intent(in) :: command
      integer :: exit_code
      call execute_command_line(command, exitstat=exit_code)
      status = exit_code
   end function shell

   !> Run the program with `arguments` (OMP_NUM_THREADS=`threads`), stderr to `err`; its
   !> exit status.
   integer function run_program(arguments, err, threads) result(status)
      character(len=*), intent(in) :: arguments, err
      integer, intent(in) :: threads
      character(len=8) :: text
      write (text, '(i0)') threads
      status = shell("OMP_NUM_THREADS="//trim(text)//" '"//program_path()//"' "//arguments//" 2>'"//err//"'")
   end function run_program

   !> Start the program on one thread with `arguments` and the test hook
   !> HILLSTAB_TEST_PAUSE_AFTER_UNITS=`units` (it waits once unit `units` is written and,
   !> with --checkpoint-interval 0, recorded), and once the checkpoint's state `state`
   !> records at least `units` units, send it `signal` (KILL, TERM): the signal lands
   !> mid-run whatever the machine's speed. The program's exit status as the shell sees it
   !> (137 killed, 143 after SIGTERM); `not_reached` when the run ended, or ran two minutes,
   !> without its checkpoint recording `units` units (no signal was sent: see `reached`).
   integer function stop_program(arguments, state, units, signal, err) result(status)
      character(len=*), intent(in) :: arguments, state, signal, err
      integer, intent(in) :: units
      character(len=:), allocatable :: script
      character(len=8) :: text
      script = scratch_prefix("stop.sh")
      call write_file(script, [character(len=120) :: &
         'units=$1; sig=$2; state=$3; err=$4; shift 4', &
         'HILLSTAB_TEST_PAUSE_AFTER_UNITS=$units OMP_NUM_THREADS=1 "$@" 2>"$err" &', &
         'pid=$!; n=0; sent=0; exec 2>/dev/null', &
         'while kill -0 $pid 2>/dev/null; do', &
         '   u=$(sed -n "s/^units = \([0-9]*\) .*/\1/p" "$state" 2>/dev/null)', &
         '   if [ "${u:-0}" -ge "$units" ]; then kill -"$sig" $pid; sent=1; break; fi', &
         '   n=$((n + 1)); if [ $n -ge 12000 ]; then kill -KILL $pid; break; fi', &
         '   sleep 0.01', &
         'done', &
         '{ wait $pid; status=$?; } 2>/dev/null', &
         '[ $sent = 1 ] && exit $status', &
         'echo "test: the run ended with status $status, its checkpoint holding ${u:-no} units" >>"$err"', &
         'exit 250'])
      write (text, '(i0)') units
      status = shell("bash '"//script//"' "//trim(text)//" "//signal//" '"//state//"' '"//err//"' '"// &
                     program_path()//"' "//arguments)
      call delete_file(script)
   end function stop_program

   !> Whether `stop_program` or `kill_when` reached its precondition (`condition`: what the
   !> signal waited for); when not, a failed check that says so.
   logical function reached(ctx, status, condition, label)
      type(test_context_t), intent(inout) :: ctx
      integer, intent(in) :: status  !! of stop_program or kill_when
      character(len=*), intent(in) :: condition  !! "its checkpoint recorded 5 units"
      character(len=*), intent(in) :: label
      reached = status /= not_reached
      if (.not. reached) call check(ctx, .false., label//": precondition not reached: the run ended (or ran two "// &
         "minutes) before "//condition//", so the signal could not land mid-run; nothing was tested")
   end function reached

   !> "its checkpoint recorded 5 units".
   function units_text(units) result(text)
      integer, intent(in) :: units
      character(len=:), allocatable :: text
      text = "its checkpoint recorded "//integer_text(units)//" units"
   end function units_text

   !> The units done and the bytes a checkpoint's state records (-1 when it has none).
   subroutine state_of(directory, units, bytes)
      character(len=*), intent(in) :: directory
      integer, intent(out) :: units
      integer(int64), intent(out) :: bytes
      character(len=1024), allocatable :: lines(:)
      integer :: k, ios
      units = -1
      bytes = -1
      lines = read_lines(directory//"/state")
      do k = 1, size(lines)
         if (lines(k)(1:8) == "units = ") read (lines(k)(9:), *, iostat=ios) units
         if (lines(k)(1:8) == "bytes = ") read (lines(k)(9:), *, iostat=ios) bytes
      end do
   end subroutine state_of

   !> Bytes of a file (-1 when missing).
   function size_of(path) result(bytes)
      character(len=*), intent(in) :: path
      integer(int64) :: bytes
      logical :: exists
      inquire (file=path, exist=exists, size=bytes)
      if (.not. exists) bytes = -1
   end function size_of

   !> Whether two files are byte for byte the same.
   logical function same_file(a, b)
      character(len=*), intent(in) :: a, b
      same_file = shell("cmp -s '"//a//"' '"//b//"'") == 0
   end function same_file

   !> Whether a file's text contains `part`.
   logical function file_says(path, part)
      character(len=*), intent(in) :: path, part
      character(len=1024), allocatable :: lines(:)
      integer :: k
      file_says = .false.
      lines = read_lines(path)
      do k = 1, size(lines)
         if (index(lines(k), part) > 0) file_says = .true.
      end do
   end function file_says

   !> Whether a directory exists.
   logical function directory_exists(path)
      character(len=*), intent(in) :: path
      directory_exists = shell("test -d '"//path//"'") == 0
   end function directory_exists

   !> Write `lines` as the scene of `f`, run it uninterrupted, keep its file as the reference
   !> (`extension` of the file: ".dat" by default).
   subroutine make_fixture(f, name, lines, task, n_units, extension)
      type(fixture_t), intent(inout) :: f
      character(len=*), intent(in) :: name, lines(:), task
      integer, intent(in) :: n_units
      character(len=*), intent(in), optional :: extension
      integer :: status
      if (f%ready) return
      f%scene = scratch_prefix(name)//".nml"
      f%output = scratch_prefix(name)//"_"//task//".dat"
      if (present(extension)) f%output = scratch_prefix(name)//"_"//task//extension
      f%reference = scratch_prefix(name)//".reference"
      f%n_units = n_units
      call write_file(f%scene, lines)
      status = run_program("--quiet '"//f%scene//"'", scratch_prefix(name)//".err", 2)
      status = shell("mv '"//f%output//"' '"//f%reference//"'")
      f%ready = status == 0
   end subroutine make_fixture

   !> Delete the files of a fixture (each test leaves nothing behind; the next makes it again).
   subroutine release_fixture(f)
      type(fixture_t), intent(inout) :: f
      if (.not. allocated(f%scene)) return
      call delete_file(f%scene)
      call delete_file(f%reference)
      call delete_file(f%scene(:len(f%scene) - 4)//".err")
      call delete_file(f%output)
      f%ready = .false.
   end subroutine release_fixture

   !> A chart of 24 rows of 300 points by magnus6 at 1e-12 (20 to 50 ms a row here).
   subroutine chart_fixture()
      call make_fixture(chart, "ck_chart", [ &
         padded("&scene task='chart', method='magnus6', tolerance=1e-12, output='"//scratch_prefix("ck_chart")//"' /"), &
         padded("&chart alpha_min=0, alpha_max=9.8, n_alpha=24, beta_min=-2, beta_max=12, n_beta=300 /")], "chart", 24)
   end subroutine chart_fixture

   !> A Lyapunov map of 8 x 25 points, one a batch, 150 periods each: 13 units of 16 points.
   subroutine map_fixture()
      call make_fixture(map, "ck_map", [ &
         padded("&scene task='lyapunov', output='"//scratch_prefix("ck_map")//"' /"), &
         padded("&series phi0=0.017, periods=150 /"), &
         padded("&lyapunov lanes=1, early_stop=.false. /"), &
         padded("&chart alpha_min=0.5, alpha_max=9.5, n_alpha=8, beta_min=0.5, beta_max=9.5, n_beta=25 /")], &
         "lyapunov", 13)
   end subroutine map_fixture

   !> Kill the run of `f` with SIGKILL once `units` units are in its checkpoint, check what
   !> the checkpoint holds, optionally add bytes a killed write could leave after the recorded
   !> ones (cut on resume), and resume it (on two threads): the file of the uninterrupted
   !> run, no checkpoint, no temporary file.
   subroutine kill_and_resume(ctx, f, units, garbage)
      type(test_context_t), intent(inout) :: ctx
      type(fixture_t), intent(in) :: f
      integer, intent(in) :: units
      logical, intent(in) :: garbage
      character(len=:), allocatable :: directory, err, label
      character(len=8) :: text
      integer(int64) :: bytes
      integer :: status, done
      write (text, '(i0)') units
      label = f%output//" killed after "//trim(text)//" units"
      directory = checkpoint_directory(f%output)
      err = scratch_prefix("ck.err")
      status = stop_program("--quiet --checkpoint-interval 0 '"//f%scene//"'", directory//"/state", units, "KILL", err)
      if (.not. reached(ctx, status, units_text(units), label)) then
         ! what the run that ended wrote must not fail the next check of the caller
         call delete_file(f%output)
         status = shell("rm -rf '"//directory//"'")
         return
      end if
      call check(ctx, status == 137, label//": killed while it ran (status "//integer_text(status)//")")
      call state_of(directory, done, bytes)
      call check(ctx, done >= units .and. done < f%n_units, label//": the checkpoint records "//integer_text(done)// &
                 " units")
      call check(ctx, bytes > 0 .and. bytes <= size_of(directory//"/data"), label// &
                 ": the state claims no more bytes than the data hold")
      call check(ctx, .not. file_exists(f%output), label//": no output file")
      if (garbage) then
         ! a partial row after the recorded bytes, as a write the kill cut short leaves
         status = shell("printf '1.0 2.0 partial row' >> '"//directory//"/data'")
         call check(ctx, status == 0 .and. size_of(directory//"/data") > bytes, label//": bytes added")
      end if
      status = run_program("--quiet --resume '"//f%scene//"'", err, 2)
      call check(ctx, status == 0, label//": the resumed run succeeds (status "//integer_text(status)//")")
      call check(ctx, file_says(err, "resuming"), label//": it says it resumes")
      call check(ctx, same_file(f%output, f%reference), label//": the file of an uninterrupted run")
      call check(ctx, .not. directory_exists(directory), label//": the checkpoint is removed")
      call check(ctx, .not. any_temp_file(f%output), label//": no temporary file")
      call delete_file(f%output)
      call delete_file(err)
   end subroutine kill_and_resume

   !> SIGKILL after 1, 12 and 20 of 24 rows (the middle one with a partial row after the
   !> recorded bytes, which the resumed run cuts).
   subroutine chart_resumed_after_kill(ctx)
      type(test_context_t), intent(inout) :: ctx
      call chart_fixture()
      call check(ctx, chart%ready, "the uninterrupted chart ran: "//program_path())
      if (.not. chart%ready) return
      call kill_and_resume(ctx, chart, 1, .false.)
      call kill_and_resume(ctx, chart, 12, .true.)
      call kill_and_resume(ctx, chart, 20, .false.)
      call release_fixture(chart)
   end subroutine chart_resumed_after_kill

   !> A system's chart (16 rows of 200 points, damped, a gyroscopic term) and points list (320
   !> points: 5 units of 64) killed after 1, 8 and 14 rows and after 2 units, resumed: the
   !> files of the uninterrupted runs.
   subroutine system_resumed_after_kill(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=240) :: group(2)
      character(len=:), allocatable :: points
      group = [padded("&system n = 2, b = 1.0, 0.0, 0.0, 16.0, cos = -1.0, -0.6, -0.6, -4.0, sin = 0.0, 0.3, 0.3, 0.5,"), &
               padded("   gyroscopic = 0.0, 0.2, -0.2, 0.0 /")]
      call make_fixture(system_chart, "ck_sys", [ &
         padded("&scene model='system', method='magnus6', tolerance=1e-10, epsilon=0.02, output='"// &
                scratch_prefix("ck_sys")//"' /"), group, &
         padded("&chart alpha_min=0, alpha_max=1.2, n_alpha=16, beta_min=0, beta_max=3, n_beta=200 /")], "chart", 16)
      call check(ctx, system_chart%ready, "the uninterrupted system chart ran: "//program_path())
      if (system_chart%ready) then
         call kill_and_resume(ctx, system_chart, 1, .false.)
         call kill_and_resume(ctx, system_chart, 8, .true.)
         call kill_and_resume(ctx, system_chart, 14, .false.)
      end if
      call release_fixture(system_chart)
      points = system_points_file("ck_sys_points")
      call make_fixture(system_points, "ck_sys_pts", [ &
         padded("&scene task='points', model='system', method='rk', tolerance=1e-9, output='"// &
                scratch_prefix("ck_sys_pts")//"' /"), group, padded("&points file='"//points//"' /")], "points", 5)
      call check(ctx, system_points%ready, "the uninterrupted system points ran")
      if (system_points%ready) call kill_and_resume(ctx, system_points, 2, .true.)
      call release_fixture(system_points)
      call delete_file(points)
   end subroutine system_resumed_after_kill

   !> A points file of 320 points over a system's (α, β) (5 units of 64), its path.
   function system_points_file(name) result(path)
      character(len=*), intent(in) :: name  !! the scratch name
      character(len=:), allocatable :: path
      character(len=40) :: lines(320)
      integer :: k
      path = scratch_prefix(name)//".dat"
      do k = 1, size(lines)
         write (lines(k), '(f8.4,1x,f8.4)') 1.2_wp*mod(7*k, 23)/23.0_wp, 3.0_wp*(k - 1)/size(lines)
      end do
      call write_file(path, lines)
   end function system_points_file

   !> SIGKILL after 1, 6 and 11 of 13 units of a Lyapunov map.
   subroutine lyapunov_resumed_after_kill(ctx)
      type(test_context_t), intent(inout) :: ctx
      call map_fixture()
      call check(ctx, map%ready, "the uninterrupted map ran: "//program_path())
      if (.not. map%ready) return
      call kill_and_resume(ctx, map, 1, .false.)
      call kill_and_resume(ctx, map, 6, .true.)
      call kill_and_resume(ctx, map, 11, .false.)
      call release_fixture(map)
   end subroutine lyapunov_resumed_after_kill

   !> A checkpoint damaged after its run was killed (10 of 24 rows): a digit changed in a
   !> recorded row, a new line planted in one, the scene in the header of `data` edited, the
   !> state's byte count (less and more), unit count (less and more) and failed-point count
   !> edited, `data` cut short, the state cut short. Each: `--resume` refuses it, exit 2,
   !> naming the checkpoint and the damage, no output file, the checkpoint kept as it was;
   !> a run without `--resume` discards it with a note and writes the uninterrupted file.
   subroutine damaged_checkpoint_refused(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=:), allocatable :: directory, err, saved, row
      character(len=200) :: damages(10), labels(10)
      integer :: status, k
      call chart_fixture()
      if (.not. chart%ready) return
      directory = checkpoint_directory(chart%output)
      saved = directory//".saved"
      err = scratch_prefix("ck_damaged.err")
      status = stop_program("--quiet --checkpoint-interval 0 '"//chart%scene//"'", directory//"/state", 10, "KILL", err)
      if (.not. reached(ctx, status, units_text(10), "SIGKILL after 10 rows")) return
      status = shell("rm -rf '"//saved//"' && cp -a '"//directory//"' '"//saved//"'")
      ! the fifth data line of `data` (a recorded row: 10 rows of 300 lines are recorded)
      row = "$(($(grep -n -m1 -v '^#' data | cut -d: -f1) + 4))"
      labels = [character(len=200) :: "a digit of a recorded row", "a new line planted in a recorded row", &
                "the scene in the header of data", "the byte count less", "the byte count more", &
                "the unit count less", "the unit count more", "the failed-point count", "data cut short", &
                "the state cut short"]
      damages = [character(len=200) :: &
         "sed -i -E """//row//"{s/0e/1e/;t;s/[1-9]e/0e/}"" data", &
         "sed -i """//row//"s/ /\n/"" data", &
         "sed -i '0,/n_beta = 300/s//n_beta = 301/' data", &
         "sed -i -E 's/^bytes = ([0-9]+)$/echo bytes = $((\1 - 1))/e' state", &
         "sed -i -E 's/^bytes = ([0-9]+)$/echo bytes = $((\1 + 20))/e' state", &
         "sed -i 's/^units = 10 /units = 9 /' state", &
         "sed -i 's/^units = 10 /units = 11 /' state", &
         "sed -i 's/^failed = 0 0/failed = 1 5/' state", &
         "truncate -s -100 data", &
         "truncate -s -30 state"]
      do k = 1, size(damages)
         status = shell("rm -rf '"//directory//"' && cp -a '"//saved//"' '"//directory//"' && cd '"//directory// &
                        "' && "//trim(damages(k)))
         call check(ctx, status == 0 .and. shell("diff -rq '"//saved//"' '"//directory//"' >/dev/null") /= 0, &
                    trim(labels(k))//": damaged")
         status = run_program("--quiet --resume '"//chart%scene//"'", err, 2)
         call check(ctx, status == 2, trim(labels(k))//": refused, exit 2 (status "//integer_text(status)//")")
         call check(ctx, file_says(err, "'"//directory//"'") .and. file_says(err, "damaged") .and. &
                    file_says(err, "not resumed"), trim(labels(k))//": names the checkpoint and the damage")
         call check(ctx, .not. file_exists(chart%output) .and. .not. any_temp_file(chart%output), &
                    trim(labels(k))//": no output file, no temporary file")
         call check(ctx, directory_exists(directory), trim(labels(k))//": the checkpoint is kept")
      end do
      status = run_program("--quiet '"//chart%scene//"'", err, 2)
      call check(ctx, status == 0 .and. same_file(chart%output, chart%reference), &
                 "without --resume: the uninterrupted file")
      call check(ctx, file_says(err, "discarded the damaged checkpoint '"//directory//"'"), "with a note")
      call check(ctx, .not. directory_exists(directory), "the checkpoint is gone")
      status = shell("rm -rf '"//saved//"'")
      call delete_file(chart%output)
      call delete_file(err)
   end subroutine damaged_checkpoint_refused

   !> The reproducer of a fault probe: a 200 x 200 magnus6 chart at 1e-12 with
   !> --checkpoint-interval 0, killed with SIGKILL mid-run (here once 20 rows are recorded),
   !> one digit of a finished row flipped in `data`: `--resume` refuses it (exit 2) instead of
   !> writing a file with one data line that differs.
   subroutine probe_digit_flip_refused(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=:), allocatable :: prefix, scene, output, directory, err
      integer :: status
      prefix = scratch_prefix("ck_probe")
      scene = prefix//".nml"
      output = prefix//"_chart.dat"
      directory = checkpoint_directory(output)
      err = prefix//".err"
      call write_file(scene, [padded("&scene method='magnus6', tolerance=1e-12, output='"//prefix//"' /"), &
                              padded("&chart n_alpha=200, n_beta=200 /")])
      status = stop_program("--quiet --checkpoint-interval 0 '"//scene//"'", directory//"/state", 20, "KILL", err)
      if (.not. reached(ctx, status, units_text(20), "SIGKILL after 20 rows")) return
      status = shell("cd '"//directory//"' && cp data data.before && n=$(($(grep -n -m1 -v '^#' data | cut -d: -f1) "// &
                     "+ 1000)) && sed -i -E ""${n}{s/0e/1e/;t;s/[1-9]e/0e/}"" data && ! cmp -s data data.before && "// &
                     "rm data.before")
      call check(ctx, status == 0, "a digit of row 6 flipped")
      status = run_program("--quiet --resume '"//scene//"'", err, 2)
      call check(ctx, status == 2, "refused, exit 2 (status "//integer_text(status)//")")
      call check(ctx, file_says(err, "checkpoint '"//directory//"'") .and. file_says(err, "damaged"), &
                 "the message names the checkpoint and the damage")
      call check(ctx, .not. file_exists(output) .and. .not. any_temp_file(output), "no output, no temporary file")
      status = shell("rm -rf '"//directory//"'")
      call delete_file(scene)
      call delete_file(err)
   end subroutine probe_digit_flip_refused

   !> Run the program with `arguments` (and `environment`, assignments before it) and send it
   !> SIGKILL once a file `<output>.part??????` exists and, when `mark` is given, its stderr
   !> `err` holds `mark`: 137, or `not_reached` when the run ended (or ran two minutes) first.
   integer function kill_when(environment, arguments, output, mark, err) result(status)
      character(len=*), intent(in) :: environment, arguments, output, mark, err
      character(len=:), allocatable :: script
      script = scratch_prefix("kill_when.sh")
      call write_file(script, [character(len=160) :: &
         'output=$1; mark=$2; err=$3; shift 3', &
         'env "$@" 2>"$err" &', &
         'pid=$!; n=0; exec 2>/dev/null', &
         'while kill -0 $pid; do', &
         '   set -- "$output".part??????', &
         '   if [ -e "$1" ] && { [ -z "$mark" ] || grep -q "$mark" "$err"; }; then kill -KILL $pid; wait $pid; exit $?; fi', &
         '   n=$((n + 1)); if [ $n -ge 12000 ]; then kill -KILL $pid; break; fi', &
         '   sleep 0.01', &
         'done', &
         'wait $pid; echo "test: the run ended with status $? before it could be killed" >>"$err"', &
         'exit 250'])
      status = shell("bash '"//script//"' '"//output//"' '"//mark//"' '"//err//"' "//environment//" '"// &
                     program_path()//"' "//arguments)
      call delete_file(script)
   end function kill_when

   !> SIGKILL before the first checkpoint leaves the temporary output (nothing else can
   !> remove it); the next run of the same output removes it, says so, and writes its file:
   !> a chart stopped after its first row (the test hook, the default checkpoint interval)
   !> and a boundaries run stopped in its first block of Hill's matrix (alpha = 1, beta up
   !> to 1e6: a block of a minute or more), each followed by a run without `--resume`.
   subroutine killed_before_checkpoint(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=:), allocatable :: err, prefix, scene, output
      integer :: status
      call chart_fixture()
      if (.not. chart%ready) return
      err = scratch_prefix("ck_early.err")
      status = kill_when("HILLSTAB_TEST_PAUSE_AFTER_UNITS=1 OMP_NUM_THREADS=1", "--quiet '"//chart%scene//"'", &
                         chart%output, "test hook: paused", err)
      if (reached(ctx, status, "it paused after its first row", "chart")) then
         call check(ctx, status == 137, "chart: killed (status "//integer_text(status)//")")
         call check(ctx, any_temp_file(chart%output), "chart: its temporary file is left")
         status = shell("rm -rf '"//checkpoint_directory(chart%output)//"'")
         status = run_program("--quiet '"//chart%scene//"'", err, 2)
         call check(ctx, status == 0 .and. same_file(chart%output, chart%reference), "chart: the next run writes its file")
         call check(ctx, file_says(err, "removed '"//chart%output//".part"), "chart: and says it removed the old one")
         call check(ctx, .not. any_temp_file(chart%output), "chart: no temporary file")
      end if
      call delete_file(chart%output)
      call release_fixture(chart)
      prefix = scratch_prefix("ck_bnd")
      scene = prefix//".nml"
      output = prefix//"_boundaries.dat"
      call write_file(scene, [padded("&scene task='boundaries', output='"//prefix//"' /"), &
                              padded("&chart alpha_min=1, alpha_max=1, n_alpha=1, beta_min=0, beta_max=1e6 /")])
      status = kill_when("OMP_NUM_THREADS=1", "--quiet '"//scene//"'", output, "", err)
      if (reached(ctx, status, "its temporary file appeared", "boundaries")) then
         call check(ctx, status == 137 .and. any_temp_file(output), "boundaries: killed, its temporary file left")
         call write_file(scene, [padded("&scene task='boundaries', method='formula', output='"//prefix//"' /"), &
                                 padded("&chart n_alpha=3 /")])
         status = run_program("--quiet --resume '"//scene//"'", err, 2)
         call check(ctx, status == 0 .and. file_exists(output), "boundaries: the next run (--resume) writes its file")
         call check(ctx, file_says(err, "removed '"//output//".part"), "boundaries: and says it removed the old one")
         call check(ctx, .not. any_temp_file(output), "boundaries: no temporary file")
      end if
      call delete_file(output)
      call delete_file(scene)
      call delete_file(err)
   end subroutine killed_before_checkpoint

   !> SIGTERM: exit 143, the temporary file removed, the checkpoint kept, a message saying
   !> how to resume; the resumed run writes the uninterrupted file.
   subroutine sigterm_keeps_checkpoint(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=:), allocatable :: directory, err
      integer(int64) :: bytes
      integer :: status, done
      call chart_fixture()
      if (.not. chart%ready) return
      directory = checkpoint_directory(chart%output)
      err = scratch_prefix("ck_term.err")
      status = stop_program("--quiet --checkpoint-interval 0 '"//chart%scene//"'", directory//"/state", 5, "TERM", err)
      if (.not. reached(ctx, status, units_text(5), "SIGTERM after 5 units")) return
      call check(ctx, status == 143, "exit 143 (status "//integer_text(status)//")")
      call check(ctx, file_says(err, "stopped by signal 15"), "says which signal")
      call check(ctx, file_says(err, "hillstab --resume "//chart%scene), "says how to resume")
      call check(ctx, file_says(err, "the checkpoint '"//directory//"' keeps"), "names the checkpoint")
      call check(ctx, .not. any_temp_file(chart%output), "no temporary file")
      call check(ctx, .not. file_exists(chart%output), "no output file")
      call state_of(directory, done, bytes)
      call check(ctx, done >= 5 .and. bytes <= size_of(directory//"/data"), "the checkpoint is kept")
      status = run_program("--quiet --resume '"//chart%scene//"'", err, 2)
      call check(ctx, status == 0 .and. same_file(chart%output, chart%reference), "resumed: the uninterrupted file")
      call check(ctx, .not. directory_exists(directory), "the checkpoint is removed")
      call delete_file(err)
      call release_fixture(chart)
   end subroutine sigterm_keeps_checkpoint

   !> A checkpoint of another effective scene (a variable of &chart, of &scene) is refused
   !> with exit 2 naming group and variable, and left as it was.
   subroutine other_scene_refused(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=:), allocatable :: directory, err, other
      character(len=1024), allocatable :: before(:), after(:)
      integer :: status
      call chart_fixture()
      if (.not. chart%ready) return
      directory = checkpoint_directory(chart%output)
      err = scratch_prefix("ck_other.err")
      other = scratch_prefix("ck_other.nml")
      status = stop_program("--quiet --checkpoint-interval 0 '"//chart%scene//"'", directory//"/state", 2, "KILL", err)
      if (.not. reached(ctx, status, units_text(2), "SIGKILL after 2 units")) return
      before = read_lines(directory//"/state")
      call write_file(other, [ &
         padded("&scene task='chart', method='magnus6', tolerance=1e-12, output='"//scratch_prefix("ck_chart")//"' /"), &
         padded("&chart alpha_min=0, alpha_max=9.8, n_alpha=24, beta_min=-2, beta_max=12, n_beta=301 /")])
      status = run_program("--quiet --resume '"//other//"'", err, 1)
      call check(ctx, status == 2, "another grid: exit 2 (status "//integer_text(status)//")")
      call check(ctx, file_says(err, other//": &chart: n_beta: 301 in this scene, 300 in the checkpoint"), &
                 "names group, variable and values")
      call write_file(other, [ &
         padded("&scene task='chart', method='magnus4', tolerance=1e-12, output='"//scratch_prefix("ck_chart")//"' /"), &
         padded("&chart alpha_min=0, alpha_max=9.8, n_alpha=24, beta_min=-2, beta_max=12, n_beta=300 /")])
      status = run_program("--quiet --resume '"//other//"'", err, 1)
      call check(ctx, status == 2, "another method: exit 2")
      call check(ctx, file_says(err, "&scene: method: 'magnus4' in this scene, 'magnus6' in the checkpoint"), &
                 "names the method")
      after = read_lines(directory//"/state")
      call check(ctx, size(after) == size(before) .and. size(before) > 5, "the checkpoint is kept")
      if (size(after) == size(before)) call check(ctx, all(after == before), "unchanged")
      call check(ctx, .not. file_exists(chart%output), "no output file")
      ! the same scene resumes it
      status = run_program("--quiet --resume '"//chart%scene//"'", err, 2)
      call check(ctx, status == 0 .and. same_file(chart%output, chart%reference), "the scene of the checkpoint resumes")
      call delete_file(other)
      call delete_file(err)
      call release_fixture(chart)
   end subroutine other_scene_refused

   !> `--resume` without a checkpoint: a fresh run that says so, the same file.
   subroutine resume_without_checkpoint(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=:), allocatable :: err
      integer :: status
      call map_fixture()
      if (.not. map%ready) return
      err = scratch_prefix("ck_fresh.err")
      call check(ctx, .not. directory_exists(checkpoint_directory(map%output)), "no checkpoint before")
      status = run_program("--quiet --resume '"//map%scene//"'", err, 2)
      call check(ctx, status == 0, "exit 0")
      call check(ctx, file_says(err, "no checkpoint of "//map%output) .and. file_says(err, "starting afresh"), &
                 "says it starts afresh")
      call check(ctx, same_file(map%output, map%reference), "the same file")
      call check(ctx, .not. directory_exists(checkpoint_directory(map%output)), "no checkpoint after")
      call delete_file(err)
      call release_fixture(map)
   end subroutine resume_without_checkpoint

   !> A run without `--resume` discards a checkpoint (and the temporary file its killed run
   !> left) with a note, and writes the whole file.
   subroutine discarded_without_resume(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=:), allocatable :: directory, err
      integer :: status
      call map_fixture()
      if (.not. map%ready) return
      directory = checkpoint_directory(map%output)
      err = scratch_prefix("ck_discard.err")
      status = stop_program("--quiet --checkpoint-interval 0 '"//map%scene//"'", directory//"/state", 3, "KILL", err)
      if (.not. reached(ctx, status, units_text(3), "SIGKILL after 3 units")) return
      call check(ctx, status == 137 .and. directory_exists(directory), "a checkpoint is left")
      call check(ctx, any_temp_file(map%output), "and the killed run's temporary file")
      status = run_program("--quiet '"//map%scene//"'", err, 2)
      call check(ctx, status == 0, "exit 0")
      call check(ctx, file_says(err, "discarded the checkpoint '"//directory//"'"), "says it discarded it")
      call check(ctx, same_file(map%output, map%reference), "the whole file")
      call check(ctx, .not. directory_exists(directory), "the checkpoint is gone")
      call check(ctx, .not. any_temp_file(map%output), "so is the temporary file")
      call delete_file(err)
      call release_fixture(map)
   end subroutine discarded_without_resume

   !> At the checkpoint's name: a symbolic link to a directory and to a file, a hard link of
   !> a file, a directory other users may write: refused (exit 2) naming it, with and without
   !> `--resume`, nothing followed, written or removed, no output.
   subroutine planted_links_not_followed(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=:), allocatable :: prefix, scene, output, directory, victim
      character(len=1024), allocatable :: lines(:)
      type(error_t), allocatable :: error
      integer :: status, round
      logical :: resume
      prefix = scratch_prefix("ck_planted")
      scene = prefix//".nml"
      output = prefix//"_chart.dat"
      directory = checkpoint_directory(output)
      victim = prefix//"_victim"
      call write_file(scene, [padded("&scene method='formula', output='"//prefix//"' /"), &
                              padded("&chart n_alpha=3, n_beta=4 /")])
      do round = 1, 8
         resume = round > 4
         status = shell("rm -rf '"//victim//"' '"//directory//"'; mkdir -p '"//victim//"'; echo precious > '"// &
                        victim//"/state'; echo precious > '"//victim//"/file'")
         select case (mod(round - 1, 4))
         case (0)
            status = shell("ln -s '"//victim(index(victim, "/", back=.true.) + 1:)//"' '"//directory//"'")
         case (1)
            status = shell("ln -s '"//victim(index(victim, "/", back=.true.) + 1:)//"/file' '"//directory//"'")
         case (2)
            status = shell("ln '"//victim//"/file' '"//directory//"'")
         case (3)
            status = shell("mkdir -m 0777 '"//directory//"'; echo precious > '"//directory//"/state'")
         end select
         call run_scene_file(scene, .true., error, options=checkpoint_options_t(resume=resume, interval=0.0_wp))
         call check(ctx, allocated(error), "refused, round "//integer_text(round))
         if (allocated(error)) then
            call check(ctx, exit_status(error) == 2, "exit 2: "//error%message)
            call check(ctx, contains_text(error%message, scene//": &scene: output: cannot keep the checkpoint '"// &
                       directory//"'"), "names the checkpoint: "//error%message)
         end if
         lines = read_lines(victim//"/file")
         call check(ctx, size(lines) == 1 .and. lines(1) == "precious", "the victim's file untouched")
         lines = read_lines(victim//"/state")
         call check(ctx, size(lines) == 1 .and. lines(1) == "precious", "the victim's directory untouched")
         call check(ctx, shell("test -L '"//directory//"' || test -e '"//directory//"'") == 0, "the planted name kept")
         call check(ctx, .not. file_exists(output) .and. .not. any_temp_file(output), "no output, no temporary file")
      end do
      status = shell("rm -rf '"//victim//"' '"//directory//"'")
      call delete_file(scene)
   end subroutine planted_links_not_followed

   !> A checkpoint (mode 0700, a `data` of 3 lines) whose `data` or `state` is a FIFO (whose
   !> open blocks until a writer comes), a directory or a symbolic link: refused with and
   !> without `--resume` within 60 s (exit 2, not 124 of `timeout`), one line naming the
   !> member, the checkpoint kept as it was (its `data` intact), no output; a system scene
   !> of the same output likewise.
   subroutine planted_members_kept(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=:), allocatable :: prefix, scene, system, output, directory, err, member, plant, label
      character(len=1024), allocatable :: lines(:)
      integer :: status, round, which
      logical :: resume
      prefix = scratch_prefix("ck_members")
      scene = prefix//".nml"
      system = prefix//"_system.nml"
      output = prefix//"_chart.dat"
      directory = checkpoint_directory(output)
      err = prefix//".err"
      call write_file(scene, [padded("&scene method='formula', output='"//prefix//"' /"), &
                              padded("&chart n_alpha=3, n_beta=4 /")])
      call write_file(system, [padded("&scene model='system', method='magnus4', tolerance=1e-6, output='"// &
                                      prefix//"' /"), padded("&system n = 1, cos = 1 /"), &
                               padded("&chart n_alpha=2, n_beta=2 /")])
      do round = 1, 16
         resume = mod(round - 1, 2) == 1
         which = (round - 1)/2
         member = trim(merge("data ", "state", mod(which, 2) == 0))
         ! a FIFO, a directory, a symbolic link, and a FIFO under the system scene
         select case (which/2)
         case (0, 3)
            plant = "mkfifo '"//directory//"/"//member//"'"
         case (1)
            plant = "mkdir '"//directory//"/"//member//"'; echo precious > '"//directory//"/"//member//"/x'"
         case default
            plant = "ln -s data2 '"//directory//"/"//member//"'"
         end select
         status = shell("rm -rf '"//directory//"'; mkdir -m 0700 '"//directory//"' && printf '# a\n# b\n1 2\n' > '"// &
                        directory//"/data2' && cp '"//directory//"/data2' '"//directory//"/data' && "// &
                        "printf 'hillstab checkpoint 3\n' > '"//directory//"/state' && rm '"//directory//"/"// &
                        member//"' && "//plant)
         label = member//" "//plant(:index(plant, " ") - 1)//merge(" --resume", "         ", resume)
         if (round > 12) label = label//" (system scene)"
         if (round > 12) then
            status = shell("timeout 60 '"//program_path()//"' --quiet"//merge(" --resume", "         ", resume)// &
                           " '"//system//"' 2>'"//err//"'")
         else
            status = shell("timeout 60 '"//program_path()//"' --quiet"//merge(" --resume", "         ", resume)// &
                           " '"//scene//"' 2>'"//err//"'")
         end if
         call check(ctx, status == 2, label//": exit 2 (status "//integer_text(status)//", 124: it hung)")
         lines = read_lines(err)
         call check(ctx, size(lines) == 1, label//": one line")
         if (size(lines) == 1) call check(ctx, index(lines(1), "&scene: output: cannot use the checkpoint '"// &
                                          directory//"': its "//member//" '"//directory//"/"//member//"' is ") > 0 &
                                          .and. index(lines(1), "kept as it is") > 0, label//": "//trim(lines(1)))
         call check(ctx, shell("test -e '"//directory//"/"//member//"' -o -L '"//directory//"/"//member//"'") == 0, &
                    label//": the member kept")
         if (member == "state") then
            call check(ctx, same_file(directory//"/data", directory//"/data2"), label//": data intact")
         else
            lines = read_lines(directory//"/state")
            call check(ctx, size(lines) == 1, label//": state intact")
            if (size(lines) == 1) call check(ctx, lines(1) == "hillstab checkpoint 3", label//": state intact")
         end if
         call check(ctx, .not. file_exists(output) .and. .not. any_temp_file(output), label//": no output")
      end do
      status = shell("rm -rf '"//directory//"'")
      call delete_file(scene)
      call delete_file(system)
      call delete_file(err)
   end subroutine planted_members_kept

   !> Checkpoints across kinds of problem: the chart killed after 3 rows leaves a scalar
   !> chart's checkpoint; a system scene of the same output refuses it under `--resume`
   !> (exit 2, naming &scene model and both kinds, the checkpoint kept) and discards it
   !> without (a note; its file written); the scalar `--resume` then starts afresh and
   !> writes the uninterrupted file. A state recording another kind (a system chart, its
   !> checksum recomputed) is refused by the scalar scene's `--resume`, naming both kinds.
   subroutine other_problem_kind(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=:), allocatable :: directory, err, system, text, head
      character(len=1024), allocatable :: before(:), after(:)
      integer :: status, unit, at, last
      integer(int64) :: bytes
      call chart_fixture()
      if (.not. chart%ready) return
      directory = checkpoint_directory(chart%output)
      err = scratch_prefix("ck_kind.err")
      system = scratch_prefix("ck_kind.nml")
      call write_file(system, [padded("&scene model='system', method='magnus4', tolerance=1e-6, output='"// &
                                      scratch_prefix("ck_chart")//"' /"), padded("&system n = 1, cos = 1 /"), &
                               padded("&chart n_alpha=2, n_beta=2 /")])
      status = stop_program("--quiet --checkpoint-interval 0 '"//chart%scene//"'", directory//"/state", 3, "KILL", err)
      if (.not. reached(ctx, status, units_text(3), "SIGKILL after 3 units")) return
      before = read_lines(directory//"/state")
      call check(ctx, any(before == "problem = scalar chart"), "the state records the kind: scalar chart")
      status = run_program("--quiet --resume '"//system//"'", err, 1)
      call check(ctx, status == 2, "system --resume: exit 2 (status "//integer_text(status)//")")
      call check(ctx, file_says(err, system//": &scene: model: the checkpoint is of a scalar chart, this scene is a "// &
                 "system chart (checkpoint '"//directory//"'): it is not resumed"), "names &scene model and both kinds")
      after = read_lines(directory//"/state")
      call check(ctx, size(after) == size(before), "the checkpoint is kept")
      if (size(after) == size(before)) call check(ctx, all(after == before), "unchanged")
      call check(ctx, .not. file_exists(chart%output), "no output file")
      status = run_program("--quiet '"//system//"'", err, 1)
      call check(ctx, status == 0, "system without --resume: exit 0 (status "//integer_text(status)//")")
      call check(ctx, file_says(err, "discarded the checkpoint '"//directory//"' of an earlier run"), &
                 "says it discarded it")
      call check(ctx, .not. directory_exists(directory) .and. .not. any_temp_file(chart%output), &
                 "no checkpoint, no temporary file")
      call check(ctx, file_exists(chart%output), "the system chart written")
      status = run_program("--quiet --resume '"//chart%scene//"'", err, 2)
      call check(ctx, status == 0 .and. file_says(err, "no checkpoint of "//chart%output), &
                 "the scalar --resume starts afresh")
      call check(ctx, same_file(chart%output, chart%reference), "and writes the uninterrupted file")
      call delete_file(chart%output)
      ! a state that records another kind, its checksum recomputed
      status = stop_program("--quiet --checkpoint-interval 0 '"//chart%scene//"'", directory//"/state", 3, "KILL", err)
      if (.not. reached(ctx, status, units_text(3), "SIGKILL after 3 units")) return
      inquire (file=directory//"/state", size=bytes)
      allocate (character(len=bytes) :: text)
      open (newunit=unit, file=directory//"/state", access="stream", form="unformatted", status="old")
      read (unit) text
      close (unit)
      at = index(text, "problem = scalar chart")
      last = index(text(:len(text) - 1), new_line("a"), back=.true.)
      call check(ctx, at > 0 .and. last > at, "the state has its kind and a checksum line")
      if (at == 0 .or. last <= at) return
      head = text(:at - 1)//"problem = system chart"//text(at + len("problem = scalar chart"):last)
      text = head//"check = "//text_digest(head)//new_line("a")
      open (newunit=unit, file=directory//"/state", access="stream", form="unformatted", status="replace")
      write (unit) text
      close (unit)
      status = run_program("--quiet --resume '"//chart%scene//"'", err, 1)
      call check(ctx, status == 2, "scalar --resume of a system chart's state: exit 2 (status "//integer_text(status)//")")
      call check(ctx, file_says(err, chart%scene//": &scene: model: the checkpoint is of a system chart, this scene "// &
                 "is a scalar chart (checkpoint '"//directory//"'): it is not resumed"), "names both kinds")
      call check(ctx, directory_exists(directory) .and. .not. file_exists(chart%output), "kept, no output")
      status = shell("rm -rf '"//directory//"'")
      call delete_file(system)
      call delete_file(err)
      call release_fixture(chart)
   end subroutine other_problem_kind

   !> While a run writes its output, a second run of the same output (with or without
   !> `--resume`) is refused (exit 2) and changes nothing: once the first keeps a checkpoint
   !> (interval 0: from its start), and before it has made one (the default interval).
   subroutine second_run_refused(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=:), allocatable :: directory, err, script, interval
      integer :: status, round
      call chart_fixture()
      if (.not. chart%ready) return
      directory = checkpoint_directory(chart%output)
      err = scratch_prefix("ck_second.err")
      script = scratch_prefix("second.sh")
      ! the first run waits after its first row (the test hook) while the others start
      call write_file(script, [character(len=200) :: &
         'HILLSTAB_TEST_PAUSE_AFTER_UNITS=1 OMP_NUM_THREADS=1 "$1" --quiet "${@:5}" "$2" 2>"$4.first" &', &
         'pid=$!; n=0', &
         'until grep -q "test hook: paused" "$4.first" 2>/dev/null || ! kill -0 $pid 2>/dev/null; do', &
         '   n=$((n + 1)); if [ $n -ge 12000 ]; then break; fi; sleep 0.01', &
         'done', &
         'if ! grep -q "test hook: paused" "$4.first"; then kill -KILL $pid; wait $pid; rm -f "$4.first"; exit 250; fi', &
         '"$1" --quiet "$2" 2>"$4"; first=$?', &
         '"$1" --quiet --resume "$2" 2>>"$4"; second=$?', &
         'kill -TERM $pid; wait $pid; rm -f "$4.first"', &
         '[ $first = 2 ] && [ $second = 2 ]'])
      do round = 1, 2
         interval = merge("--checkpoint-interval 0", "                       ", round == 1)
         status = shell("bash '"//script//"' '"//program_path()//"' '"//chart%scene//"' '"//directory//"' '"// &
                        err//"' "//trim(interval))
         if (.not. reached(ctx, status, "it paused after its first row", "round "//integer_text(round))) exit
         call check(ctx, status == 0, "both refused with exit 2, round "//integer_text(round))
         call check(ctx, file_says(err, "is in use by another run"), "says why, round "//integer_text(round))
         call check(ctx, .not. file_exists(chart%output), "no output file")
         call check(ctx, .not. any_temp_file(chart%output), "no temporary file left")
         status = shell("rm -rf '"//directory//"'")
      end do
      call delete_file(script)
      call delete_file(err)
      call release_fixture(chart)
   end subroutine second_run_refused

   !> A points run that hits a file-size limit fails (exit 2) keeping its checkpoint and
   !> saying so; resumed without the limit it writes the uninterrupted file. A changed
   !> points file is then refused, naming `&points file`.
   subroutine write_error_keeps_checkpoint(ctx)
      type(test_context_t), intent(inout) :: ctx
      call limit_then_resume(ctx, .false.)
   end subroutine write_error_keeps_checkpoint

   !> The same in binary: 400 points, 35 kB of records, stopped at 30 kB.
   subroutine binary_write_error_resumed(ctx)
      type(test_context_t), intent(inout) :: ctx
      call limit_then_resume(ctx, .true.)
   end subroutine binary_write_error_resumed

   !> A points run of 400 points (text or binary, both above 30 kB) under a file-size limit
   !> of 30 kB, then resumed without it, then under the limit again and resumed with other
   !> points.
   subroutine limit_then_resume(ctx, binary)
      type(test_context_t), intent(inout) :: ctx
      logical, intent(in) :: binary  !! format = 'binary'
      character(len=:), allocatable :: prefix, scene, points, output, directory, reference
      character(len=40) :: lines(400)
      type(error_t), allocatable :: error
      integer(int64) :: bytes
      integer :: k, done, status
      prefix = scratch_prefix(merge("ck_points", "ck_binary", .not. binary))
      scene = prefix//".nml"
      points = prefix//".dat"
      output = prefix//"_points"//merge(".dat", ".bin", .not. binary)
      reference = prefix//".reference"
      directory = checkpoint_directory(output)
      do k = 1, size(lines)
         write (lines(k), '(f8.4,1x,f8.4)') 9.8_wp*(k - 1)/size(lines), 12.0_wp - 14.0_wp*mod(7*k, 31)/31.0_wp
      end do
      call write_file(points, lines)
      call write_file(scene, [padded("&scene task='points', method='magnus6', format='"// &
                                     trim(merge("text  ", "binary", .not. binary))//"', output='"//prefix//"' /"), &
                              padded("&points file='"//points//"' /")])
      call run_scene_file(scene, .true., error)
      call check(ctx, .not. allocated(error), "the uninterrupted run")
      call check(ctx, size_of(output) > 35000_int64, "its file: "//integer_text(size_of(output))//" bytes")
      status = shell("mv '"//output//"' '"//reference//"'")
      call limit_file_size(30000_int64)
      call run_scene_file(scene, .true., error, options=checkpoint_options_t(interval=0.0_wp, command="RESUME"))
      call lift_file_size_limit()
      call check(ctx, allocated(error), "the write error stops the run")
      if (allocated(error)) then
         call check(ctx, error%code == err_io .and. contains_text(error%message, "File too large"), error%message)
         call check(ctx, contains_text(error%message, "the checkpoint '"//directory//"' keeps") .and. &
                    contains_text(error%message, "`RESUME` continues the run"), "says the checkpoint is kept")
      end if
      call state_of(directory, done, bytes)
      call check(ctx, done > 0 .and. bytes <= 30000_int64, "the checkpoint holds the units written: "// &
                 integer_text(done))
      call check(ctx, .not. file_exists(output) .and. .not. any_temp_file(output), "no output, no temporary file")
      call run_scene_file(scene, .true., error, options=checkpoint_options_t(resume=.true.))
      call check(ctx, .not. allocated(error), "resumed without the limit")
      call check(ctx, same_file(output, reference), "the file of the uninterrupted run")
      if (.not. same_file(output, reference) .and. .not. binary) status = shell("diff '"//output//"' '"//reference//"' | head -20")
      call check(ctx, .not. directory_exists(directory), "the checkpoint is removed")
      ! a checkpoint of the same scene with other points
      call limit_file_size(30000_int64)
      call run_scene_file(scene, .true., error, options=checkpoint_options_t(interval=0.0_wp))
      call lift_file_size_limit()
      lines(7) = "1.2345 2.3456"
      call write_file(points, lines)
      call run_scene_file(scene, .true., error, options=checkpoint_options_t(resume=.true.))
      call check(ctx, allocated(error), "other points are refused")
      if (allocated(error)) then
         call check(ctx, error%code == err_input, "bad input (exit 2)")
         call check(ctx, contains_text(error%message, scene//": &points: file: the points differ"), error%message)
      end if
      call check(ctx, directory_exists(directory), "and their checkpoint kept")
      status = shell("rm -rf '"//directory//"'")
      call delete_file(output)
      call delete_file(reference)
      call delete_file(points)
      call delete_file(scene)
   end subroutine limit_then_resume

   !> Binary files keep checkpoints as text files do: a chart (24 rows of 300 points) killed
   !> after 1, 12 (with a partial record after the recorded bytes) and 20 rows, a chart over
   !> `&physical` amplitudes and frequencies (12 rows of 150) killed after 5, and a system's
   !> points list (320 points, 5 units of 64) killed after 2 units, resumed: the files of the
   !> uninterrupted runs, byte for byte.
   subroutine binary_resumed_after_kill(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(fixture_t) :: binary_chart, binary_points
      character(len=:), allocatable :: points
      call make_fixture(binary_chart, "ck_bin", [ &
         padded("&scene task='chart', method='magnus6', tolerance=1e-12, format='binary', output='"// &
                scratch_prefix("ck_bin")//"' /"), &
         padded("&chart alpha_min=0, alpha_max=9.8, n_alpha=24, beta_min=-2, beta_max=12, n_beta=300 /")], "chart", 24, &
         ".bin")
      call check(ctx, binary_chart%ready, "the uninterrupted binary chart ran: "//program_path())
      if (binary_chart%ready) then
         call check(ctx, shell("grep -q 'format: binary' '"//binary_chart%reference//"'") == 0, "a binary file")
         call kill_and_resume(ctx, binary_chart, 1, .false.)
         call kill_and_resume(ctx, binary_chart, 12, .true.)
         call kill_and_resume(ctx, binary_chart, 20, .false.)
      end if
      call release_fixture(binary_chart)
      ! a chart over &physical amplitudes and frequencies, a row an amplitude
      call make_fixture(binary_chart, "ck_phys", [ &
         padded("&scene task='chart', method='magnus6', tolerance=1e-12, format='binary', output='"// &
                scratch_prefix("ck_phys")//"' /"), &
         padded("&physical g = 9.81, r0 = 0.3, kappa = 0.1, a_min = 0.0, a_max = 0.2, n_a = 12, omega_min = 6, "// &
                "omega_max = 12, n_omega = 150 /")], "chart", 12, ".bin")
      call check(ctx, binary_chart%ready, "the uninterrupted chart over &physical ran")
      if (binary_chart%ready) call kill_and_resume(ctx, binary_chart, 5, .true.)
      call release_fixture(binary_chart)
      points = system_points_file("ck_bin_points")
      call make_fixture(binary_points, "ck_bin_pts", [ &
         padded("&scene task='points', model='system', method='rk', tolerance=1e-9, format='binary', output='"// &
                scratch_prefix("ck_bin_pts")//"' /"), &
         padded("&system n = 2, b = 1.0, 0.0, 0.0, 16.0, cos = -1.0, -0.6, -0.6, -4.0, sin = 0.0, 0.3, 0.3, 0.5 /"), &
         padded("&points file='"//points//"' /")], "points", 5, ".bin")
      call check(ctx, binary_points%ready, "the uninterrupted binary system points ran")
      if (binary_points%ready) call kill_and_resume(ctx, binary_points, 2, .true.)
      call release_fixture(binary_points)
      call delete_file(points)
   end subroutine binary_resumed_after_kill

   !> The first difference between two effective scenes, by group and variable.
   subroutine scene_differences(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=80) :: a(2), b(2)
      character(len=80) :: c(3)
      a = [character(len=80) :: "&scene task = 'chart', columns = 'alpha, beta', epsilon = 0.0 /", &
           "&chart n_alpha = 3, n_beta = 4 /"]
      b = a
      call check(ctx, scene_difference(a, b) == "", "the same scene")
      b(2) = "&chart n_alpha = 3, n_beta = 5 /"
      call check(ctx, scene_difference(a, b) == "&chart: n_beta: 5 in this scene, 4 in the checkpoint", &
                 scene_difference(a, b))
      b = a
      b(1) = "&scene task = 'chart', columns = 'alpha, S', epsilon = 0.0 /"
      call check(ctx, scene_difference(a, b) == "&scene: columns: 'alpha, S' in this scene, 'alpha, beta' in the "// &
                 "checkpoint", "a quoted comma: "//scene_difference(a, b))
      c = [character(len=80) :: a(1), "&physical r0 = 1.0 /", a(2)]
      call check(ctx, scene_difference(a, c) == "&physical: this scene has the group, the checkpoint's scene has not", &
                 scene_difference(a, c))
      call check(ctx, scene_difference(c, a) == "&physical: the checkpoint's scene has the group, this scene has not", &
                 scene_difference(c, a))
   end subroutine scene_differences

   !> The checkpoint of an output name of 255 bytes fits in a file name, and different long
   !> names get different checkpoints.
   subroutine long_output_names(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=:), allocatable :: a, b, da, db
      a = "out/"//repeat("a", 250)//"1.dat"
      b = "out/"//repeat("a", 250)//"2.dat"
      da = checkpoint_directory(a)
      db = checkpoint_directory(b)
      call check(ctx, len(da) - 4 <= 255 .and. len(db) - 4 <= 255, "fits: "//da)
      call check(ctx, da /= db, "distinct")
      call check(ctx, checkpoint_directory("out/x_chart.dat") == "out/x_chart.dat.checkpoint", "the plain name")
   end subroutine long_output_names
end module test_checkpoint

!> Tests of the atomic output writer (hillstab_batch_output_file): under a file-size limit every
!> task's writer fails with the path and the cause and leaves the old file and no
!> temporary file; a directory in the place of the output file is refused before any
!> work; a committed file holds exactly what was written (every line compared); the progress
!> line's rate, whole from 10 up and with two significant digits below.
module test_output
   use hillstab_core_kinds, only: wp, int64
   use hillstab_core_error, only: error_t, err_io, err_input
   use hillstab_core_text, only: integer_text
   use hillstab_batch_run_cli, only: exit_status
   use hillstab_batch_output_file, only: output_file_t, open_output, write_text, commit_output, discard_output
   use hillstab_batch_run_scenes, only: run_scene_file
   use hillstab_batch_output_progress, only: rate_text
   use hillstab_testing
   use hillstab_fault_injection, only: check_writer_under_limit, limit_file_size, lift_file_size_limit, &
      limit_address_space, lift_address_space_limit
   use hillstab_test_scratch, only: padded, scratch_prefix, write_file, read_lines, file_exists, delete_file, contains_text, &
      any_temp_file, program_path
   use hillstab_batch_output_checkpoint, only: checkpoint_options_t
   use hillstab_ffi_libc, only: c_fopen, c_fclose, c_string, lock_state, lock_taken
   use, intrinsic :: iso_c_binding, only: c_ptr, c_int, c_associated
   implicit none
   private
   public :: collect_output

contains

   function collect_output() result(suite)
      type(testsuite_t) :: suite
      suite = new_testsuite("output", [ &
         new_unittest("commit_writes_all", commit_writes_all), &
         new_unittest("failed_write_keeps_old_file", failed_write_keeps_old_file), &
         new_unittest("chart_writer_file_limit", chart_writer_file_limit), &
         new_unittest("points_writer_file_limit", points_writer_file_limit), &
         new_unittest("coefficient_writer_file_limit", coefficient_writer_file_limit), &
         new_unittest("directory_output_refused", directory_output_refused), &
         new_unittest("output_larger_than_free_space", output_larger_than_free_space), &
         new_unittest("buffers_larger_than_memory", buffers_larger_than_memory), &
         new_unittest("every_task_memory_estimate", every_task_memory_estimate), &
         new_unittest("address_space_too_small_to_start", address_space_too_small_to_start), &
         new_unittest("probe_memory_reproducers", probe_memory_reproducers), &
         new_unittest("system_memory_reproducers", system_memory_reproducers), &
         new_unittest("stale_temporary_removed", stale_temporary_removed), &
         new_unittest("busy_temporary_refused", busy_temporary_refused), &
         new_unittest("progress_rate_text", progress_rate_text)])
   end function collect_output

   subroutine commit_writes_all(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(output_file_t) :: file
      type(error_t), allocatable :: error
      character(len=1024), allocatable :: lines(:)
      character(len=:), allocatable :: path
      integer :: k
      path = scratch_prefix("commit")//".dat"
      call open_output(file, path, error)
      call check(ctx, .not. allocated(error), "open")
      if (allocated(error)) return
      do k = 1, 3000
         call write_text(file, repeat("x", mod(k, 97))//"|", error)
         if (allocated(error)) exit
      end do
      call check(ctx, .not. allocated(error), "writes")
      call commit_output(file, error)
      call check(ctx, .not. allocated(error), "commit")
      lines = read_lines(path)
      call check(ctx, size(lines) == 3000, "every line")
      if (size(lines) == 3000) then
         do k = 1, 3000
            if (trim(lines(k)) /= repeat("x", mod(k, 97))//"|") exit
         end do
         call check(ctx, k > 3000, "each line as written")
      end if
      call delete_file(path)
   end subroutine commit_writes_all

   !> The writer itself: a write beyond the limit fails, so does commit; the old file stays.
   subroutine failed_write_keeps_old_file(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(output_file_t) :: file
      type(error_t), allocatable :: error, commit_error
      character(len=1024), allocatable :: lines(:)
      character(len=:), allocatable :: path
      integer :: k
      logical :: failed
      path = scratch_prefix("limited")//".dat"
      call write_file(path, ["old"])
      call open_output(file, path, error)
      call check(ctx, .not. allocated(error), "open")
      if (allocated(error)) return
      call limit_file_size(10000_int64)
      failed = .false.
      do k = 1, 1000
         call write_text(file, repeat("y", 99), error)
         if (allocated(error)) failed = .true.
      end do
      call commit_output(file, commit_error)
      call lift_file_size_limit()
      call check(ctx, failed, "a write past the limit reports an error")
      call check(ctx, allocated(commit_error), "commit refuses an incomplete file")
      if (allocated(commit_error)) then
         call check(ctx, commit_error%code == err_io, "i/o error")
         call check(ctx, contains_text(commit_error%message, path), "names the path: "//commit_error%message)
      end if
      lines = read_lines(path)
      call check(ctx, size(lines) == 1, "old file kept")
      if (size(lines) == 1) call check(ctx, lines(1) == "old", "old file unchanged")
      call check(ctx, .not. file_exists(file%temp_path), "temporary file removed")
      call delete_file(path)
   end subroutine failed_write_keeps_old_file

   subroutine chart_writer_file_limit(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=:), allocatable :: out, scene
      out = scratch_prefix("limchart")
      scene = out//".nml"
      call write_file(scene, [padded("&scene method = 'formula', output = '"//out//"' /"), &
                              padded("&chart n_alpha = 40, n_beta = 40 /")])
      call check_writer_under_limit(ctx, scene, out//"_chart.dat", 8192_int64)
      call delete_file(scene)
   end subroutine chart_writer_file_limit

   subroutine points_writer_file_limit(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=:), allocatable :: out, scene, points
      character(len=40) :: lines(200)
      integer :: k
      out = scratch_prefix("limpts")
      scene = out//".nml"
      points = out//"_in.dat"
      do k = 1, size(lines)
         write (lines(k), '(f6.3,1x,f6.3)') 0.04*k, 0.05*k
      end do
      call write_file(points, lines)
      call write_file(scene, [padded("&scene task = 'points', method = 'formula', output = '"//out//"' /"), &
                              padded("&points file = '"//points//"' /")])
      call check_writer_under_limit(ctx, scene, out//"_points.dat", 8192_int64)
      call delete_file(scene)
      call delete_file(points)
   end subroutine points_writer_file_limit

   subroutine coefficient_writer_file_limit(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=:), allocatable :: out, scene
      out = scratch_prefix("limcoef")
      scene = out//".nml"
      call write_file(scene, [padded("&scene task = 'coefficient', output = '"//out//"' /"), &
                              padded("&coefficient n_tau = 400 /")])
      call check_writer_under_limit(ctx, scene, out//"_coefficient.dat", 8192_int64)
      call delete_file(scene)
   end subroutine coefficient_writer_file_limit

   !> An output path taken by a directory fails before any computing, naming `output`.
   subroutine directory_output_refused(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(error_t), allocatable :: error
      character(len=:), allocatable :: out, scene
      integer :: stat
      out = scratch_prefix("dirout")
      scene = out//".nml"
      call execute_command_line("mkdir -p "//out//"_chart.dat", exitstat=stat)
      call write_file(scene, [padded("&scene method = 'formula', output = '"//out//"' /"), &
                              padded("&chart n_alpha = 3, n_beta = 3 /")])
      call run_scene_file(scene, .true., error)
      call check(ctx, allocated(error), "a directory as output file is an error")
      if (allocated(error)) then
         call check(ctx, error%code == err_io, "i/o error")
         call check(ctx, contains_text(error%message, scene//": &scene: output: "), "names output: "//error%message)
         call check(ctx, contains_text(error%message, "directory"), "says why: "//error%message)
      end if
      call execute_command_line("rmdir "//out//"_chart.dat", exitstat=stat)
      call delete_file(scene)
   end subroutine directory_output_refused
   !> A chart whose file cannot fit on the file system is refused before any work,
   !> naming n_alpha and n_beta (10^16 points: no disk holds 10^18 bytes).
   subroutine output_larger_than_free_space(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(error_t), allocatable :: error
      character(len=:), allocatable :: out, scene
      out = scratch_prefix("huge")
      scene = out//".nml"
      call write_file(scene, [padded("&scene method = 'formula', output = '"//out//"' /"), &
                              padded("&chart n_alpha = 100000000, n_beta = 100000000 /")])
      call run_scene_file(scene, .true., error)
      call check(ctx, allocated(error), "a chart larger than the free space is refused")
      if (allocated(error)) then
         call check(ctx, contains_text(error%message, scene//": &chart: n_alpha, n_beta: "), "names the variables: "// &
                    error%message)
         call check(ctx, contains_text(error%message, "free"), "says why: "//error%message)
      end if
      call check(ctx, .not. file_exists(out//"_chart.dat"), "no file")
      call delete_file(scene)
   end subroutine output_larger_than_free_space

   !> Under an address-space limit 400 MB above the process's size, a 1 x 2000000 chart
   !> (about 1 GB of row buffers) is refused before any work, naming the variables and
   !> the limit, with no file; the same scene at 1 x 20000 still runs under the limit.
   subroutine buffers_larger_than_memory(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(error_t), allocatable :: error
      character(len=:), allocatable :: out, scene
      out = scratch_prefix("memory")
      scene = out//".nml"
      call write_file(scene, [padded("&scene method = 'formula', output = '"//out//"' /"), &
                              padded("&chart n_alpha = 1, n_beta = 2000000 /")])
      call limit_address_space(400000000_int64)
      call run_scene_file(scene, .true., error)
      call lift_address_space_limit()
      call check(ctx, allocated(error), "buffers larger than the memory left are refused")
      if (allocated(error)) then
         call check(ctx, error%code == err_input, "bad input (exit 2): "//error%message)
         call check(ctx, contains_text(error%message, scene//": &chart: n_alpha, n_beta: "), "names the variables: "// &
                    error%message)
         call check(ctx, contains_text(error%message, "ulimit -v"), "says which limit: "//error%message)
      end if
      call check(ctx, .not. file_exists(out//"_chart.dat"), "no file")
      call write_file(scene, [padded("&scene method = 'formula', output = '"//out//"' /"), &
                              padded("&chart n_alpha = 1, n_beta = 20000 /")])
      call limit_address_space(400000000_int64)
      call run_scene_file(scene, .true., error)
      call lift_address_space_limit()
      call check(ctx, .not. allocated(error), "a small chart runs under the limit")
      call check(ctx, file_exists(out//"_chart.dat"), "and writes its file")
      call delete_file(out//"_chart.dat")
      call delete_file(scene)
   end subroutine buffers_larger_than_memory
   !> Under an address-space limit, the memory estimate of each task refuses a scene whose
   !> buffers would not fit, before any work, naming the variables that set them and the
   !> limit (exit 2), with no file and no temporary file: boundaries over 10^6 alphas (about
   !> 2.4 GB under a limit 200 MB above the process), poincare over 10^6 periods (about
   !> 340 MB under 100 MB), lyapunov over 400 x 400 points in 256 lanes (about 90 MB
   !> on two threads, under 30 MB), coefficient of 64 curves of 10^5 pieces (51 MB under
   !> 20 MB); each task's small scene still runs under the same limit. (series streams its
   !> rows: `address_space_too_small_to_start`.)
   subroutine every_task_memory_estimate(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(error_t), allocatable :: error
      character(len=:), allocatable :: out, scene, output, names
      character(len=800) :: big(2, 4), small(2, 4)
      character(len=16) :: tasks(4)
      integer(int64) :: extra(4)
      character(len=:), allocatable :: alphas
      integer :: k, j, round
      out = scratch_prefix("memory_task")
      alphas = "1.0"
      do j = 2, 64
         alphas = alphas//", "//integer_text(j)//".0e-2"
      end do
      tasks = [character(len=16) :: "boundaries", "poincare", "lyapunov", "coefficient"]
      extra = [200000000_int64, 100000000_int64, 30000000_int64, 20000000_int64]
      big(:, 1) = [character(len=800) :: "&scene task='boundaries', output='"//out//"' /", "&chart n_alpha=1000000 /"]
      small(:, 1) = [character(len=800) :: "&scene task='boundaries', output='"//out//"' /", "&chart n_alpha=3 /"]
      big(:, 2) = [character(len=800) :: "&scene task='poincare', output='"//out//"' /", "&series periods=1000000 /"]
      small(:, 2) = [character(len=800) :: "&scene task='poincare', output='"//out//"' /", "&series periods=3 /"]
      big(:, 3) = [character(len=800) :: "&scene task='lyapunov', output='"//out//"' /", &
                   "&lyapunov lanes=256 / &series periods=2 / &chart n_alpha=400, n_beta=400 /"]
      small(:, 3) = [character(len=800) :: "&scene task='lyapunov', output='"//out//"' /", &
                     "&lyapunov lanes=256 / &series periods=2 / &chart n_alpha=3, n_beta=3 /"]
      big(:, 4) = [character(len=800) :: "&scene task='coefficient', method='segments', n_segments=100000, output='"// &
                   out//"' /", "&coefficient alphas="//alphas//", n_tau=5 /"]
      small(:, 4) = [character(len=800) :: "&scene task='coefficient', method='segments', n_segments=1000, output='"// &
                     out//"' /", "&coefficient alphas="//alphas//", n_tau=5 /"]
      scene = out//".nml"
      do k = 1, size(tasks)
         output = out//"_"//trim(tasks(k))//".dat"
         do round = 1, 2
            if (round == 1) then
               call write_file(scene, big(:, k))
            else
               call write_file(scene, small(:, k))
            end if
            call limit_address_space(extra(k))
            call run_scene_file(scene, .true., error)
            call lift_address_space_limit()
            if (round == 2) then
               call check(ctx, .not. allocated(error), trim(tasks(k))//": the small scene runs under the limit")
               call check(ctx, file_exists(output), trim(tasks(k))//": and writes its file")
               call delete_file(output)
               cycle
            end if
            call check(ctx, allocated(error), trim(tasks(k))//": refused")
            if (allocated(error)) then
               call check(ctx, exit_status(error) == 2, trim(tasks(k))//": exit 2: "//error%message)
               names = merge("&chart: n_alpha   ", "&series: periods  ", k == 1)
               if (k == 3) names = "&lyapunov: lanes"
               if (k == 4) names = "&scene: n_segments"
               call check(ctx, contains_text(error%message, scene//": "//trim(names)) .or. &
                          contains_text(error%message, trim(names)), trim(tasks(k))//": names "//trim(names)//": "// &
                          error%message)
               call check(ctx, contains_text(error%message, "ulimit -v"), trim(tasks(k))//": names the limit")
            end if
            call check(ctx, .not. file_exists(output) .and. .not. any_temp_file(output), &
                       trim(tasks(k))//": no file, no temporary file")
         end do
      end do
      call delete_file(scene)
   end subroutine every_task_memory_estimate

   !> The program under an address-space limit too small for any run (`ulimit -v 32000`:
   !> about 12 MB above what it holds at its start): a series scene (whose rows stream, so
   !> that nothing in the scene sets its memory) and a chart are refused at once with
   !> hillstab's own message naming the limit (exit 2), not the OpenMP runtime's or a
   !> backtrace; no file, no temporary file. Not under AddressSanitizer (its shadow memory
   !> needs an unlimited address space).
   subroutine address_space_too_small_to_start(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=:), allocatable :: out, err
      character(len=1024), allocatable :: lines(:)
      character(len=16) :: asan
      integer :: status, length, k
      call get_environment_variable("ASAN_OPTIONS", asan, length, status)
      if (status == 0) then
         call check(ctx, .true., "skipped under AddressSanitizer")
         return
      end if
      out = scratch_prefix("start")
      err = out//".err"
      call write_file(out//"_s.nml", [padded("&scene task='series', output='"//out//"' /"), &
                                      padded("&series periods=2 /")])
      call write_file(out//"_c.nml", [padded("&scene method='formula', output='"//out//"' /"), &
                                      padded("&chart n_alpha=5, n_beta=5 /")])
      do k = 1, 2
         call execute_command_line("ulimit -v 32000; OMP_NUM_THREADS="//achar(iachar("0") + k)//" '"// &
                                   program_path()//"' --quiet '"//out//"_s.nml' '"//out//"_c.nml' 2>'"//err//"'", &
                                   exitstat=status)
         call check(ctx, status == 2, integer_text(k)//" thread(s): exit 2 (status "//integer_text(status)//")")
         lines = read_lines(err)
         call check(ctx, size(lines) == 1, integer_text(k)//" thread(s): one message line")
         if (size(lines) == 1) call check(ctx, index(lines(1), "hillstab: the address-space limit (ulimit -v) "// &
                                          "leaves this process") == 1, trim(lines(1)))
         call check(ctx, .not. file_exists(out//"_series.dat") .and. .not. any_temp_file(out//"_series.dat") .and. &
                    .not. file_exists(out//"_chart.dat") .and. .not. any_temp_file(out//"_chart.dat"), &
                    "no file, no temporary file")
      end do
      call delete_file(out//"_s.nml")
      call delete_file(out//"_c.nml")
      call delete_file(err)
   end subroutine address_space_too_small_to_start

   !> The reproducers of a fault probe, which ended with "Error allocating 54400000000
   !> bytes", a backtrace, exit 1 and a temporary file left: boundaries over
   !> `n_alpha = 100000000` (here under an address-space limit 200 GB above the process, so
   !> that no machine runs it), boundaries over 10^6 alphas under `ulimit -v 300000` and
   !> poincare over 10^6 periods under `ulimit -v 200000` (the program, as the probe ran it;
   !> not under AddressSanitizer). Each: exit 2, one message naming the variable, no file.
   subroutine probe_memory_reproducers(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(error_t), allocatable :: error
      character(len=:), allocatable :: out, err
      character(len=1024), allocatable :: lines(:)
      character(len=16) :: asan
      integer :: status, length
      out = scratch_prefix("probe_memory")
      err = out//".err"
      call write_file(out//"_b8.nml", [padded("&scene task='boundaries', output='"//out//"' /"), &
                                       padded("&chart n_alpha=100000000 /")])
      call limit_address_space(200000000000_int64)
      call run_scene_file(out//"_b8.nml", .true., error)
      call lift_address_space_limit()
      call check(ctx, allocated(error), "n_alpha = 1e8: refused")
      if (allocated(error)) then
         call check(ctx, exit_status(error) == 2 .and. contains_text(error%message, out//"_b8.nml: &chart: n_alpha"), &
                    "exit 2 naming n_alpha: "//error%message)
      end if
      call check(ctx, .not. file_exists(out//"_boundaries.dat") .and. .not. any_temp_file(out//"_boundaries.dat"), &
                 "n_alpha = 1e8: no file, no temporary file")
      call delete_file(out//"_b8.nml")
      call get_environment_variable("ASAN_OPTIONS", asan, length, status)
      if (status == 0) return
      call write_file(out//"_b6.nml", [padded("&scene task='boundaries', output='"//out//"' /"), &
                                       padded("&chart n_alpha=1000000 /")])
      call write_file(out//"_p6.nml", [padded("&scene task='poincare', output='"//out//"' /"), &
                                       padded("&series periods=1000000 /")])
      call probe("300000", out//"_b6.nml", out//"_boundaries.dat", "&chart: n_alpha")
      call probe("200000", out//"_p6.nml", out//"_poincare.dat", "&series: periods")
      call delete_file(out//"_b6.nml")
      call delete_file(out//"_p6.nml")
      call delete_file(err)
   contains
      subroutine probe(limit, scene, output, names)
         character(len=*), intent(in) :: limit, scene, output, names
         call execute_command_line("ulimit -v "//limit//"; '"//program_path()//"' --quiet '"//scene//"' 2>'"// &
                                   err//"'", exitstat=status)
         call check(ctx, status == 2, scene//" under ulimit -v "//limit//": exit 2 (status "//integer_text(status)//")")
         lines = read_lines(err)
         call check(ctx, size(lines) == 1, scene//": one message line")
         if (size(lines) == 1) call check(ctx, index(lines(1), "hillstab: "//scene//": "//names) == 1 .and. &
                                          index(lines(1), "ulimit -v") > 0, trim(lines(1)))
         call check(ctx, .not. file_exists(output) .and. .not. any_temp_file(output), scene//": no file, no temporary file")
      end subroutine probe
   end subroutine probe_memory_reproducers

   !> The memory reproducers of system scenes, which ended with "Error allocating
   !> 204800000000 bytes", a backtrace, exit 1 and a temporary file left: a chart of
   !> 1 x 10^8 points and the boundaries over 10^8 β samples (in the process, under an
   !> address-space limit 200 GB above it, so that no machine runs them), and the chart of
   !> 1 x 2000000 under `ulimit -v 300000` (the program, not under AddressSanitizer). Each:
   !> exit 2, one message naming &chart n_alpha, n_beta and the memory, no file; a chart of
   !> 1 x 2000 still runs under the same `ulimit -v`.
   subroutine system_memory_reproducers(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(error_t), allocatable :: error
      character(len=:), allocatable :: out, err, system
      character(len=1024), allocatable :: lines(:)
      character(len=16) :: asan
      character(len=10) :: tasks(2)
      integer :: status, length, k
      out = scratch_prefix("system_memory")
      err = out//".err"
      system = "&system n = 2, mass = 1.0, 0.0, 0.0, 0.25, b = 2.0, -1.0, -1.0, 1.5, cos = -1.0, 0.0, 0.0, -0.5 /"
      tasks = [character(len=10) :: "chart", "boundaries"]
      do k = 1, 2
         call write_file(out//"_8.nml", [padded("&scene model='system', task='"//trim(tasks(k))//"', output='"// &
                                                out//"' /"), padded(system), padded("&chart n_alpha=1, n_beta=100000000 /")])
         call limit_address_space(200000000000_int64)
         call run_scene_file(out//"_8.nml", .true., error)
         call lift_address_space_limit()
         call check(ctx, allocated(error), trim(tasks(k))//" 1 x 1e8: refused")
         if (allocated(error)) then
            call check(ctx, exit_status(error) == 2 .and. &
                       contains_text(error%message, out//"_8.nml: &chart: n_alpha, n_beta: 1 x 100000000 points would "// &
                                     "need about") .and. contains_text(error%message, "of memory, more than"), &
                       trim(tasks(k))//": exit 2 naming n_beta and the memory: "//error%message)
         end if
         call check(ctx, .not. file_exists(out//"_"//trim(tasks(k))//".dat") .and. &
                    .not. any_temp_file(out//"_"//trim(tasks(k))//".dat"), trim(tasks(k))//": no file, no temporary file")
      end do
      call delete_file(out//"_8.nml")
      call get_environment_variable("ASAN_OPTIONS", asan, length, status)
      if (status == 0) return
      call write_file(out//"_2m.nml", [padded("&scene model='system', output='"//out//"' /"), padded(system), &
                                       padded("&chart n_alpha=1, n_beta=2000000 /")])
      call execute_command_line("ulimit -v 300000; '"//program_path()//"' --quiet '"//out//"_2m.nml' 2>'"// &
                                err//"'", exitstat=status)
      call check(ctx, status == 2, "1 x 2000000 under ulimit -v 300000: exit 2 (status "//integer_text(status)//")")
      lines = read_lines(err)
      call check(ctx, size(lines) == 1, "one message line")
      if (size(lines) == 1) call check(ctx, index(lines(1), "hillstab: "//out//"_2m.nml: &chart: n_alpha, n_beta: "// &
                                       "1 x 2000000 points would need about") == 1 .and. index(lines(1), "ulimit -v") > 0, &
                                       trim(lines(1)))
      call check(ctx, .not. file_exists(out//"_chart.dat") .and. .not. any_temp_file(out//"_chart.dat"), &
                 "1 x 2000000: no file, no temporary file")
      call write_file(out//"_2m.nml", [padded("&scene model='system', method='magnus4', tolerance=1e-6, output='"// &
                                              out//"' /"), padded(system), padded("&chart n_alpha=1, n_beta=2000 /")])
      call execute_command_line("ulimit -v 300000; '"//program_path()//"' --quiet '"//out//"_2m.nml' 2>'"// &
                                err//"'", exitstat=status)
      call check(ctx, status == 0, "1 x 2000 under ulimit -v 300000: runs (status "//integer_text(status)//")")
      call check(ctx, file_exists(out//"_chart.dat"), "and writes its file")
      call delete_file(out//"_chart.dat")
      call delete_file(out//"_2m.nml")
      call delete_file(err)
   end subroutine system_memory_reproducers

   !> A small scene of every task (chart in text and in binary, points, lyapunov,
   !> coefficient, series, boundaries, poincare) writing `<prefix>k_<task>.<ext>`: its
   !> scene file and its output.
   subroutine every_task(prefix, k, scene, output)
      character(len=*), intent(in) :: prefix
      integer, intent(in) :: k  !! 1 … 8
      character(len=:), allocatable, intent(out) :: scene, output
      character(len=:), allocatable :: out
      character(len=:), allocatable :: lines(:)
      out = prefix//achar(iachar("0") + k)
      scene = out//".nml"
      select case (k)
      case (1)
         lines = [padded("&scene method='formula', output='"//out//"' /"), padded("&chart n_alpha=3, n_beta=4 /")]
         output = out//"_chart.dat"
      case (2)
         lines = [padded("&scene method='formula', format='binary', output='"//out//"' /"), &
                  padded("&chart n_alpha=3, n_beta=4 /")]
         output = out//"_chart.bin"
      case (3)
         call write_file(out//"_pts.txt", ["1.0 2.0", "3.0 4.0"])
         lines = [padded("&scene task='points', method='formula', output='"//out//"' /"), &
                  padded("&points file='"//out//"_pts.txt' /")]
         output = out//"_points.dat"
      case (4)
         lines = [padded("&scene task='lyapunov', output='"//out//"' /"), padded("&series phi0=0.017, periods=2 /"), &
                  padded("&chart n_alpha=2, n_beta=2 /")]
         output = out//"_lyapunov.dat"
      case (5)
         lines = [padded("&scene task='coefficient', output='"//out//"' /"), padded("&coefficient n_tau=5 /")]
         output = out//"_coefficient.dat"
      case (6)
         lines = [padded("&scene task='series', output='"//out//"' /"), &
                  padded("&series periods=1, samples_per_period=5 /")]
         output = out//"_series.dat"
      case (7)
         lines = [padded("&scene task='boundaries', method='formula', output='"//out//"' /"), &
                  padded("&chart n_alpha=3 /")]
         output = out//"_boundaries.dat"
      case default
         lines = [padded("&scene task='poincare', output='"//out//"' /"), padded("&series periods=2 /")]
         output = out//"_poincare.dat"
      end select
      call write_file(scene, lines)
   end subroutine every_task

   !> A temporary file a killed run of each task's output left (named as the writer names
   !> them, nobody holding its lock) is removed by the next run of that output, with or
   !> without `--resume`, and the run writes its file.
   subroutine stale_temporary_removed(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(error_t), allocatable :: error
      character(len=:), allocatable :: scene, output
      integer :: k, round
      do round = 1, 2
         do k = 1, 8
            call every_task(scratch_prefix("stale"), k, scene, output)
            call write_file(output//".partAb12Cd", ["a row of a killed run"])
            call write_file(output//".partZz99zz", ["another"])
            call run_scene_file(scene, .true., error, options=checkpoint_options_t(resume=round == 2))
            call check(ctx, .not. allocated(error), "task "//integer_text(k)//" runs")
            call check(ctx, file_exists(output), "and writes "//output)
            call check(ctx, .not. any_temp_file(output), "task "//integer_text(k)//", round "// &
                       integer_text(round)//": the stale temporary files are removed")
            call delete_file(output)
            call delete_file(scene)
         end do
      end do
      call delete_file(scratch_prefix("stale")//"3_pts.txt")
   end subroutine stale_temporary_removed

   !> A temporary file of the output whose lock is held (another run writing it): every
   !> task refuses the run (exit 2, "in use by another run"), writes nothing and leaves
   !> that file alone.
   subroutine busy_temporary_refused(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(error_t), allocatable :: error
      character(len=:), allocatable :: scene, output
      type(c_ptr) :: held
      integer(c_int) :: status
      integer :: k
      do k = 1, 8
         call every_task(scratch_prefix("busy"), k, scene, output)
         call write_file(output//".partAb12Cd", ["a row of a running run"])
         held = c_fopen(c_string(output//".partAb12Cd"), c_string("r"))
         call check(ctx, c_associated(held), "opened")
         if (.not. c_associated(held)) cycle
         call check(ctx, lock_state(held) == lock_taken, "its lock held here")
         call run_scene_file(scene, .true., error)
         call check(ctx, allocated(error), "task "//integer_text(k)//": refused")
         if (allocated(error)) then
            call check(ctx, exit_status(error) == 2, "exit 2: "//error%message)
            call check(ctx, contains_text(error%message, scene//": &scene: output: ") .and. &
                       contains_text(error%message, "in use by another run"), "says why: "//error%message)
         end if
         call check(ctx, .not. file_exists(output), "no output")
         call check(ctx, file_exists(output//".partAb12Cd"), "the other run's file is kept")
         status = c_fclose(held)
         call delete_file(output//".partAb12Cd")
         call check(ctx, .not. any_temp_file(output), "no temporary file of its own left")
         call delete_file(scene)
      end do
      call delete_file(scratch_prefix("busy")//"3_pts.txt")
   end subroutine busy_temporary_refused

   !> The rate of the progress line: a unit taking half a minute (a block of Hill's matrix near
   !> alpha = pi^2) showed as "0 Hill blocks/s".
   subroutine progress_rate_text(ctx)
      type(test_context_t), intent(inout) :: ctx
      call check(ctx, rate_text(1234.4_wp) == "1234", "1234.4: "//rate_text(1234.4_wp))
      call check(ctx, rate_text(9.6_wp) == "10", "9.6: "//rate_text(9.6_wp))
      call check(ctx, rate_text(3.74_wp) == "3.7", "3.74: "//rate_text(3.74_wp))
      call check(ctx, rate_text(0.5_wp) == "0.50", "0.5: "//rate_text(0.5_wp))
      call check(ctx, rate_text(0.0357_wp) == "0.036", "0.0357: "//rate_text(0.0357_wp))
      call check(ctx, rate_text(2.0e-5_wp) == "0.000020", "2e-5: "//rate_text(2.0e-5_wp))
      call check(ctx, rate_text(0.0_wp) == "0", "0: "//rate_text(0.0_wp))
   end subroutine progress_rate_text

end module test_output

!> Tests of the unit-by-unit driver that writes every chart and points file (scalar and
!> system, text and binary) in the serial program and the MPI program: its threaded run
!> (`run_batch`: units in a window, written as soon as they are next) writes the bytes of
!> the units computed one at a time last to first and written in order, for charts with
!> few and many rows and for points lists; the rows' values equal each point computed alone
!> (a scalar point by `monodromy_trace`, not the row's lanes and meshes; a system's by
!> `system_values`, not the row's shared nodes); binary records equal the text file's
!> numbers; the units cover every point once; a failing point is written with its status
!> and placeholders and reported, exit 3; a task whose points are independent has no loop of
!> its own; exit statuses.
module test_batch
   use hillstab_core_kinds, only: wp, int64
   use hillstab_core_text, only: integer_text, real_text
   use hillstab_hill_model, only: hill_point_t
   use hillstab_hill_units, only: physical_t, physical_epsilon
   use hillstab_hill_transfer, only: trace_t
   use hillstab_hill_system, only: system_form_t, prepare_system
   use hillstab_integrate_monodromy, only: monodromy_trace
   use hillstab_integrate_system, only: system_method_t
   use hillstab_batch_tasks_system_values, only: system_values
   use hillstab_batch_tasks_floquet_columns, only: n_fixed
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   use hillstab_core_error, only: error_t, err_input, err_io, err_integration, err_invalid_parameter, err_points_failed
   use hillstab_batch_scene_physical, only: pendulum_task_t
   use hillstab_batch_scene_types, only: scene_t
   use hillstab_batch_run_read, only: read_scene
   use hillstab_batch_run_scenes, only: output_path
   use hillstab_batch_run_units, only: batch_t, batch_result_t, batch_plan, batch_unit_range, batch_compute, batch_open, &
      batch_write, batch_commit, batch_discard, run_batch
   use hillstab_batch_run_cli, only: exit_status
   use hillstab_batch_tasks_points, only: points_task_t
   use hillstab_batch_run_threads, only: place_threads, placement_by_openmp, allowed_cpus, bind_thread
   !$ use omp_lib, only: omp_get_max_threads, omp_get_thread_num
   use hillstab_testing
   use hillstab_test_scratch, only: padded, scratch_prefix, write_file, read_lines, file_exists, delete_file, contains_text
   implicit none
   private
   public :: collect_batch

contains

   function collect_batch() result(suite)
      type(testsuite_t) :: suite
      suite = new_testsuite("batch", [ &
         new_unittest("chart_equals_serial", chart_equals_serial), &
         new_unittest("points_equal_serial", points_equal_serial), &
         new_unittest("system_chart_equals_serial", system_chart_equals_serial), &
         new_unittest("system_points_equal_serial", system_points_equal_serial), &
         new_unittest("binary_equals_serial", binary_equals_serial), &
         new_unittest("no_loop_of_its_own", no_loop_of_its_own), &
         new_unittest("units_cover_points", units_cover_points), &
         new_unittest("failing_point", failing_point), &
         new_unittest("exit_statuses", exit_statuses), &
         new_unittest("threads_bound", threads_bound)])
   end function collect_batch

   !> Read a scene written from `lines`.
   subroutine scene_from(name, lines, scene)
      character(len=*), intent(in) :: name, lines(:)
      type(scene_t), intent(out) :: scene
      type(error_t), allocatable :: error
      character(len=:), allocatable :: path
      path = scratch_prefix(name)//".nml"
      call write_file(path, lines)
      call read_scene(path, scene, error)
      call delete_file(path)
      if (allocated(error)) error stop "test_batch: bad test scene"
   end subroutine scene_from

   !> Lines of a file that are not comments, and the number of comment lines.
   subroutine data_lines(path, lines, n_header)
      character(len=*), intent(in) :: path
      character(len=1024), allocatable, intent(out) :: lines(:)
      integer, intent(out) :: n_header
      character(len=1024), allocatable :: all(:)
      all = read_lines(path)
      n_header = count(all(:)(1:1) == "#")
      lines = pack(all, all(:)(1:1) /= "#")
   end subroutine data_lines

   !> Run `scene` twice through the driver: its units computed one at a time last to first
   !> (as for three workers) and written in order, and `run_batch` (threads, a window of
   !> units); the two files must hold the same bytes (the header names its own file). With
   !> `n_lines`, the text file must hold that many data lines (blank lines between α blocks
   !> included). The threaded run's file is kept as `written` for the value checks.
   subroutine compare_runs(ctx, scene, label, written, n_lines)
      type(test_context_t), intent(inout) :: ctx
      type(scene_t), intent(in) :: scene
      character(len=*), intent(in) :: label
      character(len=:), allocatable, intent(out) :: written  !! the threaded run's file
      integer, intent(in), optional :: n_lines
      type(scene_t) :: reversed, batched
      type(batch_t) :: batch
      type(batch_result_t), allocatable :: results(:)
      type(error_t), allocatable :: error
      character(len=:), allocatable :: a, b
      character(len=1024), allocatable :: data(:)
      integer :: unit, n_header
      reversed = scene
      reversed%output = scene%output//"_rev"
      batched = scene
      batched%output = scene%output//"_bat"
      call batch_plan(reversed, 3, batch)
      allocate (results(batch%n_units))
      do unit = batch%n_units, 1, -1
         call batch_compute(batch, unit, results(unit))
      end do
      call batch_open(batch, .true., error)
      do unit = 1, batch%n_units
         if (allocated(error)) exit
         call batch_write(batch, results(unit), error)
      end do
      if (allocated(error)) then
         call batch_discard(batch)
      else
         call batch_commit(batch, error)
      end if
      call check(ctx, .not. allocated(error), label//": units last to first")
      call run_batch(batched, .true., error)
      call check(ctx, .not. allocated(error), label//": threaded run")
      a = file_bytes(output_path(reversed))
      b = file_bytes(output_path(batched))
      call check(ctx, len(b) > 200, label//": a file")
      call check(ctx, replace_text(a, reversed%output, batched%output) == b, label//": the same bytes")
      if (present(n_lines)) then
         call data_lines(output_path(batched), data, n_header)
         call check(ctx, size(data) == n_lines .and. n_header > 3, label//": "//integer_text(size(data))// &
                    " data lines, "//integer_text(n_lines)//" expected")
      end if
      call delete_file(output_path(reversed))
      written = output_path(batched)
   end subroutine compare_runs

   !> The numbers of a text file's column `name` (header "# columns:"), blank lines skipped;
   !> empty when the file has no such column.
   subroutine column_of(path, name, values)
      character(len=*), intent(in) :: path, name
      real(wp), allocatable, intent(out) :: values(:)
      character(len=1024), allocatable :: all(:), data(:)
      character(len=64) :: words(40)
      integer :: k, position, n_header, ios
      all = read_lines(path)
      allocate (values(0))
      position = 0
      do k = 1, size(all)
         if (index(all(k), "# columns: ") == 1) then
            words = ""
            read (all(k)(12:), *, iostat=ios) words
            position = findloc(words, name, dim=1)
         end if
      end do
      if (position == 0) return
      call data_lines(path, data, n_header)
      data = pack(data, len_trim(data) > 0)
      deallocate (values)
      allocate (values(size(data)))
      do k = 1, size(data)
         block
            character(len=64) :: fields(position)
            read (data(k), *, iostat=ios) fields
            values(k) = ieee_quiet()
            if (ios == 0) read (fields(position), *, iostat=ios) values(k)
         end block
      end do
   end subroutine column_of

   !> A quiet NaN (a value no column holds when it is read).
   real(wp) function ieee_quiet()
      ieee_quiet = ieee_value(1.0_wp, ieee_quiet_nan)
   end function ieee_quiet

   !> The trace of a file's points against each computed alone, within `relative` of
   !> max(1, |trace|), at up to 40 points spread over the file: a scalar scene's S by
   !> `monodromy_trace` (one point: not the row's lanes, meshes and chunks; over `&physical`
   !> the pendulum's ε at each ω), a system's trace by `system_values` (not the row's
   !> shared nodes).
   subroutine check_alone(ctx, scene, path, relative, label)
      type(test_context_t), intent(inout) :: ctx
      type(scene_t), intent(in) :: scene
      character(len=*), intent(in) :: path, label
      real(wp), intent(in) :: relative
      real(wp), allocatable :: alpha(:), beta(:), written(:), omega(:), v(:)
      type(trace_t) :: tr
      type(system_form_t) :: form
      type(error_t), allocatable :: error
      type(physical_t) :: p
      character(len=:), allocatable :: message, name
      logical :: system, failed
      real(wp) :: worst, epsilon, value
      integer :: k, step, n, compared
      system = .not. allocated(scene%model)
      name = merge("trace", "S    ", system)
      call column_of(path, "alpha", alpha)
      call column_of(path, "beta", beta)
      call column_of(path, trim(name), written)
      call column_of(path, "omega", omega)
      n = size(written)
      call check(ctx, n > 0 .and. size(alpha) == n .and. size(beta) == n, label//": alpha, beta and "//trim(name)// &
                 " read")
      if (n == 0 .or. size(alpha) /= n .or. size(beta) /= n) return
      if (system) then
         call prepare_system(scene%system, scene%epsilon, form, error)
         call check(ctx, .not. allocated(error), label//": the system prepared")
         if (allocated(error)) return
         allocate (v(n_fixed + form%n))
      end if
      compared = 0
      step = max(1, n/40)
      worst = 0.0_wp
      do k = 1, n, step
         if (system) then
            call system_values(scene%system, form, system_method_t(scene%method%kind, scene%method%tolerance), &
                               alpha(k), beta(k), v, failed, message)
            value = v(3)
         else
            epsilon = scene%model%point_damping(alpha(k), scene%epsilon)
            if (size(omega) == n) then
               select type (task => scene%task)
               class is (pendulum_task_t)
                  p = task%physical%pendulum
               end select
               p%omega = omega(k)
               epsilon = physical_epsilon(p)
            end if
            call monodromy_trace(scene%model, hill_point_t(alpha(k), beta(k), epsilon), scene%method, tr, error)
            failed = allocated(error)
            value = tr%value
         end if
         if (failed) cycle
         compared = compared + 1
         worst = max(worst, abs(value - written(k))/max(1.0_wp, abs(value)))
      end do
      call check(ctx, compared >= min(n, 20), label//": "//integer_text(compared)//" points compared")
      call check(ctx, worst <= relative, label//": "//trim(name)//" as each point alone, worst "//real_text(worst))
   end subroutine check_alone

   !> Charts with few rows (chunks of a row in parallel) and many rows (rows in parallel),
   !> damped, by segments, over `&physical` amplitudes and frequencies (a row an amplitude),
   !> on log axes: the driver's files, and S as each point alone.
   subroutine chart_equals_serial(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(scene_t) :: scene
      character(len=:), allocatable :: written
      call scene_from("batch_few", [padded("&scene task='chart', output='"//scratch_prefix("few")//"' /"), &
         padded("&chart alpha_min=3, alpha_max=9.8, n_alpha=2, beta_min=-2, beta_max=12, n_beta=301 /")], scene)
      call compare_runs(ctx, scene, "chart, 2 rows", written, 2*301 + 1)
      call check_alone(ctx, scene, written, 1.0e-8_wp, "chart, 2 rows")
      call delete_file(written)
      call scene_from("batch_many", [padded("&scene task='chart', epsilon=0.2, output='"//scratch_prefix("many")//"' /"), &
         padded("&chart alpha_min=0, alpha_max=9.8, n_alpha=40, beta_min=-2, beta_max=12, n_beta=41 /")], scene)
      call compare_runs(ctx, scene, "damped chart, 40 rows", written, 40*41 + 39)
      call check_alone(ctx, scene, written, 1.0e-8_wp, "damped chart, 40 rows")
      call delete_file(written)
      call scene_from("batch_seg", [padded("&scene task='chart', method='segments', n_segments=8, output='"// &
         scratch_prefix("seg")//"' /"), &
         padded("&chart alpha_min=0, alpha_max=9, n_alpha=17, beta_min=-2, beta_max=12, n_beta=1 /")], scene)
      call compare_runs(ctx, scene, "segments chart, one column", written, 17 + 16)
      call check_alone(ctx, scene, written, 1.0e-12_wp, "segments chart, one column")
      call delete_file(written)
      call scene_from("batch_phys", [padded("&scene task='chart', output='"//scratch_prefix("phys")// &
         "' /"), padded("&physical g = 9.81, r0 = 0.3, kappa = 0.1, a_min = 0.0, a_max = 0.2, n_a = 13, "// &
         "omega_min = 6, omega_max = 12, n_omega = 29 /")], scene)
      call compare_runs(ctx, scene, "chart over &physical, 13 amplitudes", written, 13*29 + 12)
      call check_alone(ctx, scene, written, 1.0e-8_wp, "chart over &physical, 13 amplitudes")
      call delete_file(written)
      call scene_from("batch_log", [padded("&scene task='chart', output='"//scratch_prefix("log")//"' /"), &
         padded("&chart alpha_min=0.01, alpha_max=9.8, n_alpha=9, alpha_scale='log', beta_min=0.01, beta_max=100, "// &
                "n_beta=37, beta_scale='log' /")], scene)
      call compare_runs(ctx, scene, "log chart, 9 rows", written, 9*37 + 8)
      call check_alone(ctx, scene, written, 1.0e-8_wp, "log chart, 9 rows")
      call delete_file(written)
   end subroutine chart_equals_serial

   !> A points list longer than a unit: the driver's files, and S as each point alone.
   subroutine points_equal_serial(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(scene_t) :: scene
      character(len=:), allocatable :: points, written
      character(len=40) :: lines(150)
      integer :: k
      points = scratch_prefix("batch_points")//".dat"
      do k = 1, size(lines)
         write (lines(k), '(f8.4,1x,f8.4)') 9.8_wp*(k - 1)/size(lines), 12.0_wp - 14.0_wp*mod(7*k, 31)/31.0_wp
      end do
      call write_file(points, lines)
      call scene_from("batch_pts", [padded("&scene task='points', output='"//scratch_prefix("pts")//"' /"), &
         padded("&points file='"//points//"' /")], scene)
      call compare_runs(ctx, scene, "points", written, 150)
      call check_alone(ctx, scene, written, 1.0e-8_wp, "points")
      call delete_file(written)
      call delete_file(points)
   end subroutine points_equal_serial

   !> `&system` of a damped 2-DOF system with a sine drive and a gyroscopic term (Mettler's
   !> column's matrices, coupled further).
   function system_group() result(lines)
      character(len=len(padded(""))), allocatable :: lines(:)
      lines = [padded("&system n = 2, b = 1.0, 0.0, 0.0, 16.0, cos = -1.0, -0.6, -0.6, -4.0,"), &
               padded("   sin = 0.0, 0.3, 0.3, 0.5, gyroscopic = 0.0, 0.2, -0.2, 0.0 /")]
   end function system_group

   !> A system chart (a unit a row, on threads as soon as there are two), damped and not,
   !> with few rows and many, on log axes: the driver's files, and the trace as each point
   !> alone (the row shares its nodes).
   subroutine system_chart_equals_serial(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(scene_t) :: scene
      character(len=:), allocatable :: written
      call scene_from("batch_sys_few", [padded("&scene task='chart', model='system', output='"// &
         scratch_prefix("sys_few")//"' /"), system_group(), &
         padded("&chart alpha_min=0, alpha_max=1.2, n_alpha=3, beta_min=0, beta_max=3, n_beta=41 /")], scene)
      call compare_runs(ctx, scene, "system chart, 3 rows", written, 3*41 + 2)
      call check_alone(ctx, scene, written, 1.0e-8_wp, "system chart, 3 rows")
      call delete_file(written)
      call scene_from("batch_sys_many", [padded("&scene task='chart', model='system', epsilon=0.05, "// &
         "method='magnus4', tolerance=1e-9, columns='alpha beta stable kind mu mu_2 status', output='"// &
         scratch_prefix("sys_many")//"' /"), system_group(), &
         padded("&chart alpha_min=0, alpha_max=1.2, n_alpha=19, beta_min=0, beta_max=3, n_beta=13 /")], scene)
      call compare_runs(ctx, scene, "damped system chart, 19 rows", written, 19*13 + 18)
      call delete_file(written)
      call scene_from("batch_sys_log", [padded("&scene task='chart', model='system', output='"// &
         scratch_prefix("sys_log")//"' /"), system_group(), &
         padded("&chart alpha_min=0.01, alpha_max=1.2, n_alpha=11, alpha_scale='log', beta_min=0.05, beta_max=3, "// &
                "n_beta=13, beta_scale='log' /")], scene)
      call compare_runs(ctx, scene, "log system chart, 11 rows", written, 11*13 + 10)
      call check_alone(ctx, scene, written, 1.0e-8_wp, "log system chart, 11 rows")
      call delete_file(written)
   end subroutine system_chart_equals_serial

   !> A system points list longer than a unit: the driver's files. Each point is computed
   !> alone: the list at one α in reverse order gives every line of the list in order (a
   !> point's line does not depend on its neighbours, which share an α and would share
   !> nodes along a chart row).
   subroutine system_points_equal_serial(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(scene_t) :: scene
      type(error_t), allocatable :: error
      character(len=:), allocatable :: points, written
      character(len=40) :: lines(150)
      character(len=1024), allocatable :: forward(:), backward(:)
      integer :: k, n_header
      points = scratch_prefix("batch_sys_points")//".dat"
      do k = 1, size(lines)
         write (lines(k), '(f8.4,1x,f8.4)') 1.2_wp*mod(3*k, 17)/17.0_wp, 3.0_wp*(k - 1)/size(lines)
      end do
      call write_file(points, lines)
      call scene_from("batch_sys_pts", [padded("&scene task='points', model='system', output='"// &
         scratch_prefix("sys_pts")//"' /"), system_group(), padded("&points file='"//points//"' /")], scene)
      call compare_runs(ctx, scene, "system points", written, 150)
      call delete_file(written)
      do k = 1, size(lines)
         write (lines(k), '(f8.4,1x,f8.4)') 0.7_wp, 3.0_wp*(k - 1)/size(lines)
      end do
      call write_file(points, lines)
      call scene_from("batch_sys_pts", [padded("&scene task='points', model='system', output='"// &
         scratch_prefix("sys_fwd")//"' /"), system_group(), padded("&points file='"//points//"' /")], scene)
      call run_batch(scene, .true., error)
      call check(ctx, .not. allocated(error), "the list in order")
      call data_lines(output_path(scene), forward, n_header)
      call delete_file(output_path(scene))
      call write_file(points, lines(size(lines):1:-1))
      call scene_from("batch_sys_pts", [padded("&scene task='points', model='system', output='"// &
         scratch_prefix("sys_bwd")//"' /"), system_group(), padded("&points file='"//points//"' /")], scene)
      call run_batch(scene, .true., error)
      call check(ctx, .not. allocated(error), "the list reversed")
      call data_lines(output_path(scene), backward, n_header)
      call delete_file(output_path(scene))
      call check(ctx, size(forward) == size(lines) .and. size(backward) == size(lines), "a line a point")
      if (size(forward) == size(backward)) call check(ctx, all(forward == backward(size(backward):1:-1)), &
                                                      "each point's line whatever its neighbours")
      call delete_file(points)
   end subroutine system_points_equal_serial

   !> A task whose points are independent has no loop of its own: its `run` says it runs
   !> unit by unit (err_input) and writes nothing; the scene runner writes its file.
   subroutine no_loop_of_its_own(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(scene_t) :: scene
      type(error_t), allocatable :: error
      call scene_from("batch_own", [padded("&scene task='chart', method='formula', output='"// &
         scratch_prefix("own")//"' /"), padded("&chart n_alpha=3, n_beta=4 /")], scene)
      call scene%task%run(scene, .true., error)
      call check(ctx, allocated(error), "refused")
      if (allocated(error)) call check(ctx, error%code == err_input .and. contains_text(error%message, &
         "&scene: task: task 'chart' runs unit by unit"), error%message)
      call check(ctx, .not. file_exists(output_path(scene)), "no file")
   end subroutine no_loop_of_its_own

   !> Binary files: the driver's threaded run writes the bytes of the units computed last to
   !> first (`compare_runs`), and its records are the text file's numbers, point by point
   !> (alpha and beta exactly: their 17 digits give the double back; every other column to
   !> its digits, at least 4): scalar charts with few rows and many, every column and the
   !> verdict only, damped, over `&physical`; a points list; a system's chart, damped and not, and points
   !> list. The records after the header are as many as the points times the columns.
   subroutine binary_equals_serial(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=:), allocatable :: points, system_points
      character(len=40) :: lines(150)
      integer :: k
      call compare_binary(ctx, "bfew", [padded("&scene task='chart', FORMAT output='OUT' /"), &
         padded("&chart alpha_min=3, alpha_max=9.8, n_alpha=2, beta_min=-2, beta_max=12, n_beta=301 /")], &
         "binary chart, 2 rows")
      call compare_binary(ctx, "bmany", [padded("&scene task='chart', epsilon=0.2, FORMAT output='OUT' /"), &
         padded("&chart alpha_min=0, alpha_max=9.8, n_alpha=40, beta_min=-2, beta_max=12, n_beta=41 /")], &
         "damped binary chart, 40 rows")
      call compare_binary(ctx, "bphys", [padded("&scene task='chart', FORMAT output='OUT' /"), &
         padded("&physical g = 9.81, r0 = 0.3, a_min = 0.0, a_max = 0.2, n_a = 11, omega_min = 6, omega_max = 12, "// &
                "n_omega = 23 /")], "binary chart over &physical, 11 amplitudes")
      call compare_binary(ctx, "bverdict", [padded("&scene task='chart', columns='alpha beta stable', FORMAT "// &
         "output='OUT' /"), padded("&chart alpha_min=0, alpha_max=9.8, n_alpha=40, beta_min=-2, beta_max=12, "// &
         "n_beta=37 /")], "binary verdict chart, 40 rows")
      points = scratch_prefix("bin_points")//".dat"
      system_points = scratch_prefix("bin_sys_points")//".dat"
      do k = 1, size(lines)
         write (lines(k), '(f8.4,1x,f8.4)') 9.8_wp*(k - 1)/size(lines), 12.0_wp - 14.0_wp*mod(7*k, 31)/31.0_wp
      end do
      call write_file(points, lines)
      call compare_binary(ctx, "bpts", [padded("&scene task='points', FORMAT output='OUT' /"), &
         padded("&points file='"//points//"' /")], "binary points")
      call compare_binary(ctx, "bsys_few", [padded("&scene task='chart', model='system', FORMAT output='OUT' /"), &
         system_group(), padded("&chart alpha_min=0, alpha_max=1.2, n_alpha=3, beta_min=0, beta_max=3, n_beta=41 /")], &
         "binary system chart, 3 rows")
      call compare_binary(ctx, "bsys_many", [padded("&scene task='chart', model='system', epsilon=0.05, "// &
         "method='magnus4', tolerance=1e-9, columns='alpha beta stable kind mu mu_2 status', FORMAT output='OUT' /"), &
         system_group(), padded("&chart alpha_min=0, alpha_max=1.2, n_alpha=19, beta_min=0, beta_max=3, n_beta=13 /")], &
         "damped binary system chart, 19 rows")
      do k = 1, size(lines)
         write (lines(k), '(f8.4,1x,f8.4)') 1.2_wp*mod(3*k, 17)/17.0_wp, 3.0_wp*(k - 1)/size(lines)
      end do
      call write_file(system_points, lines)
      call compare_binary(ctx, "bsys_pts", [padded("&scene task='points', model='system', FORMAT output='OUT' /"), &
         system_group(), padded("&points file='"//system_points//"' /")], "binary system points")
      call delete_file(points)
      call delete_file(system_points)
   end subroutine binary_equals_serial

   !> The scene `lines` (FORMAT and OUT replaced) written in binary through the driver
   !> (`compare_runs`) and as text: the records equal the text file's numbers.
   subroutine compare_binary(ctx, name, lines, label)
      type(test_context_t), intent(inout) :: ctx
      character(len=*), intent(in) :: name, lines(:), label
      type(scene_t) :: binary, text
      type(error_t), allocatable :: error
      character(len=:), allocatable :: b, written
      character(len=len(lines)) :: edited(size(lines))
      real(wp), allocatable :: records(:, :), column(:)
      character(len=64) :: names(40)
      integer(int64) :: skip, n_columns, n_points
      integer :: at, ios, k, c
      logical :: same
      do k = 1, size(lines)
         edited(k) = replace_text(replace_text(lines(k), "FORMAT", "format='binary',"), "OUT", scratch_prefix(name))
      end do
      call scene_from(name, edited, binary)
      call compare_runs(ctx, binary, label, written)
      b = file_bytes(written)
      call check(ctx, index(b, "format: binary: after the first ") > 0, label//": a binary file")
      skip = -1
      n_columns = -1
      at = index(b, "format: binary: after the first ")
      if (at > 0) read (b(at + 32:), *, iostat=ios) skip
      at = index(b, " records of ")
      if (at > 0) read (b(at + 12:), *, iostat=ios) n_columns
      n_points = binary%task%point_count()
      call check(ctx, skip > 0 .and. n_columns > 2 .and. len(b, int64) - skip == 8*n_columns*n_points, &
                 label//": the records of every point after the header")
      call delete_file(written)
      if (.not. (skip > 0 .and. n_columns > 2 .and. len(b, int64) - skip == 8*n_columns*n_points)) return
      allocate (records(n_columns, n_points))
      records = reshape(transfer(b(skip + 1:), 1.0_wp, int(n_columns*n_points)), [n_columns, n_points])
      ! the same scene as text
      do k = 1, size(lines)
         edited(k) = replace_text(replace_text(lines(k), "FORMAT", ""), "OUT", scratch_prefix(name//"_txt"))
      end do
      call scene_from(name//"_txt", edited, text)
      call run_batch(text, .true., error)
      call check(ctx, .not. allocated(error), label//": as text")
      if (allocated(error)) return
      names = ""
      at = index(b, "# columns: ")
      read (b(at + 11:index(b(at:), new_line("a")) + at - 2), *, iostat=ios) names(:n_columns)
      same = .true.
      do c = 1, int(n_columns)
         call column_of(output_path(text), trim(names(c)), column)
         if (size(column) /= n_points) then
            same = .false.
            cycle
         end if
         if (names(c) == "alpha" .or. names(c) == "beta") then
            same = same .and. all(column == records(c, :))
         else
            same = same .and. all(abs(column - records(c, :)) <= 1.0e-3_wp*abs(records(c, :)) .or. &
                                  (column /= column .and. records(c, :) /= records(c, :)))
         end if
      end do
      call check(ctx, same, label//": the records are the text's numbers, column by column")
      call delete_file(output_path(text))
   end subroutine compare_binary

   !> A file's bytes ("" when it cannot be read).
   function file_bytes(path) result(bytes)
      character(len=*), intent(in) :: path
      character(len=:), allocatable :: bytes
      integer(int64) :: n
      integer :: unit, ios
      logical :: exists
      inquire (file=path, exist=exists, size=n)
      if (.not. exists .or. n <= 0) then
         bytes = ""
         return
      end if
      allocate (character(len=n) :: bytes)
      open (newunit=unit, file=path, access="stream", form="unformatted", action="read", status="old", iostat=ios)
      if (ios /= 0) then
         bytes = ""
         return
      end if
      read (unit, iostat=ios) bytes
      if (ios /= 0) bytes = ""
      close (unit)
   end function file_bytes

   !> The ranges of the units of a points list tile 1 … n without gaps or overlaps,
   !> for any number of workers; a chart has one unit per row.
   subroutine units_cover_points(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(scene_t) :: scene
      type(batch_t) :: batch
      integer(int64) :: first, last, next
      integer :: unit, workers, n
      logical :: tiled
      character(len=:), allocatable :: points
      call scene_from("batch_cover", [padded("&scene task='chart' /"), &
         padded("&chart n_alpha=7, n_beta=5 /")], scene)
      call batch_plan(scene, 4, batch)
      call check(ctx, batch%n_units == 7 .and. batch%unit_size == 5 .and. batch%n_points == 35, "chart: rows")
      points = scratch_prefix("batch_cover")//".dat"
      call write_file(points, ["1.0 2.0"])
      call scene_from("batch_cover", [padded("&scene task='points' /"), padded("&points file='"//points//"' /")], &
         scene)
      call delete_file(points)
      do n = 1, 2000, 37
         select type (task => scene%task)
         type is (points_task_t)
            deallocate (task%points)
            allocate (task%points(2, n))
            task%points = 1.0_wp
         end select
         do workers = 1, 9, 4
            call batch_plan(scene, workers, batch)
            next = 1
            tiled = .true.
            do unit = 1, batch%n_units
               call batch_unit_range(batch, unit, first, last)
               tiled = tiled .and. first == next .and. last >= first
               next = last + 1
            end do
            call check(ctx, tiled .and. next == n + 1 .and. batch%unit_size <= 64, "points tiled")
         end do
      end do
   end subroutine units_cover_points

   !> A point where the method fails (method auto at beta = 1e13) is written with its status
   !> and placeholders, the others with theirs, and the run reports err_points_failed (exit 3)
   !> naming the point.
   subroutine failing_point(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(scene_t) :: scene
      type(error_t), allocatable :: error
      character(len=:), allocatable :: points
      real(wp), allocatable :: status(:), s(:)
      points = scratch_prefix("batch_fail")//".dat"
      ! beta = 1e13 with 1 - alpha/pi^2 = 3e-7: no mesh of auto or of adaptive Magnus-6 leaves a digit of S
      ! (round-off level 9e293): a real failure
      call write_file(points, [character(len=20) :: "1.0 2.0", "2.0 3.0", "9.8696 1e13", "4.0 2.0"])
      call scene_from("batch_fail", [padded("&scene task='points', method='auto', output='"// &
         scratch_prefix("fail")//"' /"), padded("&points file='"//points//"' /")], scene)
      call run_batch(scene, .true., error)
      call check(ctx, allocated(error), "the run reports the failure")
      if (allocated(error)) then
         call check(ctx, error%code == err_points_failed, "err_points_failed")
         call check(ctx, contains_text(error%message, "failed at 1 of 4 point(s), written with status 2"), &
            "counts it: "//error%message)
         call check(ctx, contains_text(error%message, "beta = 10000000000000.0"), "names the point")
         call check(ctx, exit_status(error) == 3, "exit status 3")
      end if
      call column_of(output_path(scene), "status", status)
      call column_of(output_path(scene), "S", s)
      call check(ctx, size(status) == 4 .and. size(s) == 4, "all points written")
      if (size(status) == 4 .and. size(s) == 4) then
         call check(ctx, all(status == [0.0_wp, 0.0_wp, 2.0_wp, 0.0_wp]), "status 2 on the failed point alone")
         call check(ctx, s(3) == 0.0_wp .and. all(abs(s([1, 2, 4])) > 0.0_wp), "its placeholder, the others' S")
      end if
      call delete_file(output_path(scene))
      call delete_file(points)
   end subroutine failing_point

   !> `text` with every `part` replaced by `by`.
   pure function replace_text(text, part, by) result(out)
      character(len=*), intent(in) :: text, part, by
      character(len=:), allocatable :: out
      integer :: k
      out = text
      k = index(out, part)
      do while (k > 0)
         out = out(:k - 1)//by//out(k + len(part):)
         k = index(out, part)
      end do
   end function replace_text

   subroutine exit_statuses(ctx)
      type(test_context_t), intent(inout) :: ctx
      call check(ctx, exit_status(error_t(err_input, "x")) == 2, "bad input: 2")
      call check(ctx, exit_status(error_t(err_io, "x")) == 2, "unwritable: 2")
      call check(ctx, exit_status(error_t(err_invalid_parameter, "x")) == 2, "invalid parameter: 2")
      call check(ctx, exit_status(error_t(err_integration, "x")) == 1, "computation: 1")
      call check(ctx, exit_status(error_t(err_points_failed, "x")) == 3, "points failed: 3")
   end subroutine exit_statuses
   !> place_threads: with several threads, CPUs enough and no OpenMP placement chosen, every
   !> thread of a team runs on one CPU of its own, among those the process could use; else
   !> nothing is bound. A second call does nothing.
   subroutine threads_bound(ctx)
      type(test_context_t), intent(inout) :: ctx
      integer, allocatable :: before(:), mine(:)
      integer :: n, t, own(0:255), counts(0:255)
      logical :: bound
      call allowed_cpus(before)
      n = 1
      !$ n = omp_get_max_threads()
      call place_threads()
      call place_threads(bound)
      call check(ctx, .not. bound, "a second call binds nothing")
      if (n < 2 .or. n > 256 .or. size(before) < n .or. placement_by_openmp()) then
         call allowed_cpus(mine)
         call check(ctx, size(mine) == size(before), "nothing bound: the CPUs as before")
         write (*, '(4x,a)') "threads_bound: one thread, too few CPUs or OpenMP's placement set: nothing to bind"
         return
      end if
      own = -1
      counts = 0
      !$omp parallel num_threads(n) default(shared) private(t, mine)
      t = 0
      !$ t = omp_get_thread_num()
      call allowed_cpus(mine)
      counts(t) = size(mine)
      if (size(mine) == 1) own(t) = mine(1)
      !$omp end parallel
      call check(ctx, all(counts(0:n - 1) == 1), "every thread on one CPU")
      do t = 0, n - 1
         call check(ctx, any(before == own(t)), "a CPU the process could use")
         call check(ctx, count(own(0:n - 1) == own(t)) == 1, "a CPU of its own")
      end do
      ! the threads freed again, so that the suites after this one (and the programs they
      ! start, which inherit the mask) run as a fresh process would
      !$omp parallel num_threads(n) default(shared) private(bound)
      call bind_thread(before, bound)
      !$omp end parallel
      call allowed_cpus(mine)
      call check(ctx, size(mine) == size(before), "the CPUs as before, afterwards")
   end subroutine threads_bound
end module test_batch

!> Tests of the unit-by-unit driver shared with the MPI program and the serial program's
!> text runs: its file equals the one the task's own loop writes (same data lines, same
!> header apart from the output name) for charts
!> with few and many rows and for points lists, also when the units are computed in
!> reverse order and written in order; binary files (charts, points, a system's chart and
!> points) byte for byte those of the task's own loop; the units cover every point once; a failing
!> point is written with its status and reported with the serial message; exit statuses.
module test_batch
   use hillstab_core_kinds, only: wp, int64
   use hillstab_core_error, only: error_t, err_input, err_io, err_integration, err_invalid_parameter, err_points_failed
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
         new_unittest("system_units_in_any_order", system_units_in_any_order), &
         new_unittest("binary_equals_serial", binary_equals_serial), &
         new_unittest("units_in_any_order", units_in_any_order), &
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

   !> Run `scene` by its task's own loop and through run_batch; compare the two files.
   subroutine compare_with_serial(ctx, scene, label)
      type(test_context_t), intent(inout) :: ctx
      type(scene_t), intent(in) :: scene
      character(len=*), intent(in) :: label
      type(scene_t) :: serial, batched
      type(error_t), allocatable :: error
      character(len=1024), allocatable :: a(:), b(:)
      integer :: na, nb
      serial = scene
      serial%output = scene%output//"_serial"
      batched = scene
      batched%output = scene%output//"_batch"
      call serial%task%run(serial, .true., error)
      call check(ctx, .not. allocated(error), label//": serial run")
      call run_batch(batched, .true., error)
      call check(ctx, .not. allocated(error), label//": batch run")
      call data_lines(output_path(serial), a, na)
      call data_lines(output_path(batched), b, nb)
      call check(ctx, na == nb .and. na > 3, label//": same header length")
      call check(ctx, size(a) == size(b) .and. size(a) > 0, label//": same number of data lines")
      if (size(a) == size(b)) call check(ctx, all(a == b), label//": identical data lines")
      call delete_file(output_path(serial))
      call delete_file(output_path(batched))
   end subroutine compare_with_serial

   !> Charts with few rows (chunks of a row in parallel) and many rows (rows in parallel).
   subroutine chart_equals_serial(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(scene_t) :: scene
      call scene_from("batch_few", [padded("&scene task='chart', output='"//scratch_prefix("few")//"' /"), &
         padded("&chart alpha_min=3, alpha_max=9.8, n_alpha=2, beta_min=-2, beta_max=12, n_beta=301 /")], scene)
      call compare_with_serial(ctx, scene, "chart, 2 rows")
      call scene_from("batch_many", [padded("&scene task='chart', epsilon=0.2, output='"//scratch_prefix("many")//"' /"), &
         padded("&chart alpha_min=0, alpha_max=9.8, n_alpha=40, beta_min=-2, beta_max=12, n_beta=41 /")], scene)
      call compare_with_serial(ctx, scene, "damped chart, 40 rows")
      call scene_from("batch_seg", [padded("&scene task='chart', method='segments', n_segments=8, output='"// &
         scratch_prefix("seg")//"' /"), &
         padded("&chart alpha_min=0, alpha_max=9, n_alpha=17, beta_min=-2, beta_max=12, n_beta=1 /")], scene)
      call compare_with_serial(ctx, scene, "segments chart, one column")
      call scene_from("batch_log", [padded("&scene task='chart', output='"//scratch_prefix("log")//"' /"), &
         padded("&chart alpha_min=0.01, alpha_max=9.8, n_alpha=9, alpha_scale='log', beta_min=0.01, beta_max=100, "// &
                "n_beta=37, beta_scale='log' /")], scene)
      call compare_with_serial(ctx, scene, "log chart, 9 rows")
   end subroutine chart_equals_serial

   subroutine points_equal_serial(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(scene_t) :: scene
      character(len=:), allocatable :: points
      character(len=40) :: lines(150)
      integer :: k
      points = scratch_prefix("batch_points")//".dat"
      do k = 1, size(lines)
         write (lines(k), '(f8.4,1x,f8.4)') 9.8_wp*(k - 1)/size(lines), 12.0_wp - 14.0_wp*mod(7*k, 31)/31.0_wp
      end do
      call write_file(points, lines)
      call scene_from("batch_pts", [padded("&scene task='points', output='"//scratch_prefix("pts")//"' /"), &
         padded("&points file='"//points//"' /")], scene)
      call compare_with_serial(ctx, scene, "points")
      call delete_file(points)
   end subroutine points_equal_serial

   !> `&system` of a damped 2-DOF system with a sine drive and a gyroscopic term (Mettler's
   !> column's matrices, coupled further).
   function system_group() result(lines)
      character(len=len(padded(""))), allocatable :: lines(:)
      lines = [padded("&system n = 2, b = 1.0, 0.0, 0.0, 16.0, cos = -1.0, -0.6, -0.6, -4.0,"), &
               padded("   sin = 0.0, 0.3, 0.3, 0.5, gyroscopic = 0.0, 0.2, -0.2, 0.0 /")]
   end function system_group

   !> A system chart: its task's own loop (blocks of rows) and the driver's units (a row each,
   !> on threads as soon as there are two) write the same data lines, damped and not, with
   !> few rows and many.
   subroutine system_chart_equals_serial(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(scene_t) :: scene
      call scene_from("batch_sys_few", [padded("&scene task='chart', model='system', output='"// &
         scratch_prefix("sys_few")//"' /"), system_group(), &
         padded("&chart alpha_min=0, alpha_max=1.2, n_alpha=3, beta_min=0, beta_max=3, n_beta=41 /")], scene)
      call compare_with_serial(ctx, scene, "system chart, 3 rows")
      call scene_from("batch_sys_many", [padded("&scene task='chart', model='system', epsilon=0.05, "// &
         "method='magnus4', tolerance=1e-9, columns='alpha beta stable kind mu mu_2 status', output='"// &
         scratch_prefix("sys_many")//"' /"), system_group(), &
         padded("&chart alpha_min=0, alpha_max=1.2, n_alpha=19, beta_min=0, beta_max=3, n_beta=13 /")], scene)
      call compare_with_serial(ctx, scene, "damped system chart, 19 rows")
      call scene_from("batch_sys_log", [padded("&scene task='chart', model='system', output='"// &
         scratch_prefix("sys_log")//"' /"), system_group(), &
         padded("&chart alpha_min=0.01, alpha_max=1.2, n_alpha=11, alpha_scale='log', beta_min=0.05, beta_max=3, "// &
                "n_beta=13, beta_scale='log' /")], scene)
      call compare_with_serial(ctx, scene, "log system chart, 11 rows")
   end subroutine system_chart_equals_serial

   !> A system points list longer than a unit: the same lines from the task's own loop
   !> and from the driver. Each point is computed alone: the list at one α in reverse order
   !> gives every line of the list in order (a point's line does not depend on its
   !> neighbours, which share an α and would share nodes along a chart row).
   subroutine system_points_equal_serial(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(scene_t) :: scene
      type(error_t), allocatable :: error
      character(len=:), allocatable :: points
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
      call compare_with_serial(ctx, scene, "system points")
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

   !> A system chart's units computed last to first for three workers, then written in
   !> order, give the file of the task's own loop.
   subroutine system_units_in_any_order(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(scene_t) :: scene, serial
      type(batch_t) :: batch
      type(batch_result_t), allocatable :: results(:)
      type(error_t), allocatable :: error
      character(len=1024), allocatable :: a(:), b(:)
      integer :: unit, na, nb
      call scene_from("batch_sys_rev", [padded("&scene task='chart', model='system', output='"// &
         scratch_prefix("sys_rev")//"' /"), system_group(), &
         padded("&chart alpha_min=0.1, alpha_max=1.1, n_alpha=5, beta_min=0.2, beta_max=2.8, n_beta=7 /")], scene)
      serial = scene
      serial%output = scene%output//"_serial"
      call serial%task%run(serial, .true., error)
      call check(ctx, .not. allocated(error), "serial run")
      call batch_plan(scene, 3, batch)
      call check(ctx, batch%n_units == 5 .and. batch%unit_size == 7, "a unit per row")
      allocate (results(batch%n_units))
      do unit = batch%n_units, 1, -1
         call batch_compute(batch, unit, results(unit))
      end do
      call batch_open(batch, .true., error)
      call check(ctx, .not. allocated(error), "open")
      do unit = 1, batch%n_units
         call batch_write(batch, results(unit), error)
         if (allocated(error)) exit
      end do
      call batch_commit(batch, error)
      call check(ctx, .not. allocated(error), "write and commit")
      call data_lines(output_path(serial), a, na)
      call data_lines(output_path(scene), b, nb)
      call check(ctx, na == nb, "same header length")
      call check(ctx, size(a) == size(b) .and. size(a) == 5*7 + 4, "5 blocks of 7 lines and 4 blank lines")
      if (size(a) == size(b)) call check(ctx, all(a == b), "identical data lines")
      call delete_file(output_path(serial))
      call delete_file(output_path(scene))
   end subroutine system_units_in_any_order

   !> Units computed last to first, then written first to last, give the serial file.
   subroutine units_in_any_order(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(scene_t) :: scene, serial
      type(batch_t) :: batch
      type(batch_result_t), allocatable :: results(:)
      type(error_t), allocatable :: error
      character(len=1024), allocatable :: a(:), b(:)
      integer :: unit, na, nb
      call scene_from("batch_rev", [padded("&scene task='chart', output='"//scratch_prefix("rev")//"' /"), &
         padded("&chart alpha_min=1, alpha_max=9.5, n_alpha=9, beta_min=-1, beta_max=10, n_beta=23 /")], scene)
      serial = scene
      serial%output = scene%output//"_serial"
      call serial%task%run(serial, .true., error)
      call check(ctx, .not. allocated(error), "serial run")
      call batch_plan(scene, 3, batch)
      allocate (results(batch%n_units))
      do unit = batch%n_units, 1, -1
         call batch_compute(batch, unit, results(unit))
      end do
      call batch_open(batch, .true., error)
      call check(ctx, .not. allocated(error), "open")
      do unit = 1, batch%n_units
         call batch_write(batch, results(unit), error)
         if (allocated(error)) exit
      end do
      call check(ctx, .not. allocated(error), "write")
      call batch_commit(batch, error)
      call check(ctx, .not. allocated(error), "commit")
      call data_lines(output_path(serial), a, na)
      call data_lines(output_path(scene), b, nb)
      call check(ctx, size(a) == size(b) .and. size(a) == 9*23 + 8, "9 blocks of 23 lines and 8 blank lines")
      if (size(a) == size(b)) call check(ctx, all(a == b), "identical data lines")
      call delete_file(output_path(serial))
      call delete_file(output_path(scene))
   end subroutine units_in_any_order

   !> Binary files written by the driver are those of the task's own loop byte for byte
   !> (the header names its own file): scalar charts with few rows (chunks of a row in
   !> parallel) and many (rows in parallel), with every column and with the verdict only, a
   !> damped one; a points list; a system's chart, damped and not, and points list; and the
   !> units of a scalar and a system chart computed last to first, written in order. The
   !> records after the header are as many as the points times the columns.
   subroutine binary_equals_serial(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(scene_t) :: scene
      character(len=:), allocatable :: points, system_points
      character(len=40) :: lines(150)
      integer :: k
      call scene_from("bin_few", [padded("&scene task='chart', format='binary', output='"//scratch_prefix("bfew")// &
         "' /"), padded("&chart alpha_min=3, alpha_max=9.8, n_alpha=2, beta_min=-2, beta_max=12, n_beta=301 /")], scene)
      call compare_binary(ctx, scene, "binary chart, 2 rows", .false.)
      call scene_from("bin_many", [padded("&scene task='chart', epsilon=0.2, format='binary', output='"// &
         scratch_prefix("bmany")//"' /"), &
         padded("&chart alpha_min=0, alpha_max=9.8, n_alpha=40, beta_min=-2, beta_max=12, n_beta=41 /")], scene)
      call compare_binary(ctx, scene, "damped binary chart, 40 rows", .false.)
      call scene_from("bin_verdict", [padded("&scene task='chart', format='binary', columns='alpha beta stable', "// &
         "output='"//scratch_prefix("bverdict")//"' /"), &
         padded("&chart alpha_min=0, alpha_max=9.8, n_alpha=40, beta_min=-2, beta_max=12, n_beta=37 /")], scene)
      call compare_binary(ctx, scene, "binary verdict chart, 40 rows", .false.)
      call scene_from("bin_rev", [padded("&scene task='chart', format='binary', output='"//scratch_prefix("brev")// &
         "' /"), padded("&chart alpha_min=1, alpha_max=9.5, n_alpha=9, beta_min=-1, beta_max=10, n_beta=23 /")], scene)
      call compare_binary(ctx, scene, "binary chart, units last to first", .true.)
      points = scratch_prefix("bin_points")//".dat"
      system_points = scratch_prefix("bin_sys_points")//".dat"
      do k = 1, size(lines)
         write (lines(k), '(f8.4,1x,f8.4)') 9.8_wp*(k - 1)/size(lines), 12.0_wp - 14.0_wp*mod(7*k, 31)/31.0_wp
      end do
      call write_file(points, lines)
      call scene_from("bin_pts", [padded("&scene task='points', format='binary', output='"//scratch_prefix("bpts")// &
         "' /"), padded("&points file='"//points//"' /")], scene)
      call compare_binary(ctx, scene, "binary points", .false.)
      call scene_from("bin_sys_few", [padded("&scene task='chart', model='system', format='binary', output='"// &
         scratch_prefix("bsys_few")//"' /"), system_group(), &
         padded("&chart alpha_min=0, alpha_max=1.2, n_alpha=3, beta_min=0, beta_max=3, n_beta=41 /")], scene)
      call compare_binary(ctx, scene, "binary system chart, 3 rows", .false.)
      call scene_from("bin_sys_many", [padded("&scene task='chart', model='system', epsilon=0.05, format='binary', "// &
         "method='magnus4', tolerance=1e-9, columns='alpha beta stable kind mu mu_2 status', output='"// &
         scratch_prefix("bsys_many")//"' /"), system_group(), &
         padded("&chart alpha_min=0, alpha_max=1.2, n_alpha=19, beta_min=0, beta_max=3, n_beta=13 /")], scene)
      call compare_binary(ctx, scene, "damped binary system chart, 19 rows", .false.)
      call scene_from("bin_sys_rev", [padded("&scene task='chart', model='system', format='binary', output='"// &
         scratch_prefix("bsys_rev")//"' /"), system_group(), &
         padded("&chart alpha_min=0.1, alpha_max=1.1, n_alpha=5, beta_min=0.2, beta_max=2.8, n_beta=7 /")], scene)
      call compare_binary(ctx, scene, "binary system chart, units last to first", .true.)
      do k = 1, size(lines)
         write (lines(k), '(f8.4,1x,f8.4)') 1.2_wp*mod(3*k, 17)/17.0_wp, 3.0_wp*(k - 1)/size(lines)
      end do
      call write_file(system_points, lines)
      call scene_from("bin_sys_pts", [padded("&scene task='points', model='system', format='binary', output='"// &
         scratch_prefix("bsys_pts")//"' /"), system_group(), padded("&points file='"//system_points//"' /")], scene)
      call compare_binary(ctx, scene, "binary system points", .false.)
      call delete_file(points)
      call delete_file(system_points)
   end subroutine binary_equals_serial

   !> Run the binary `scene` by its task's own loop and by the driver (`reverse`: units
   !> computed last to first for three workers, then written in order); compare the files.
   subroutine compare_binary(ctx, scene, label, reverse)
      type(test_context_t), intent(inout) :: ctx
      type(scene_t), intent(in) :: scene
      character(len=*), intent(in) :: label
      logical, intent(in) :: reverse
      type(scene_t) :: serial, batched
      type(batch_t) :: batch
      type(batch_result_t), allocatable :: results(:)
      type(error_t), allocatable :: error
      character(len=:), allocatable :: a, b
      integer(int64) :: skip, n_columns
      integer :: unit, at, ios
      serial = scene
      serial%output = scene%output//"_own"
      batched = scene
      batched%output = scene%output//"_bat"
      call serial%task%run(serial, .true., error)
      call check(ctx, .not. allocated(error), label//": the task's own loop")
      if (reverse) then
         call batch_plan(batched, 3, batch)
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
      else
         call run_batch(batched, .true., error)
      end if
      call check(ctx, .not. allocated(error), label//": the driver")
      a = file_bytes(output_path(serial))
      b = file_bytes(output_path(batched))
      call check(ctx, len(b) > 0 .and. index(b, "format: binary: after the first ") > 0, label//": a binary file")
      call check(ctx, replace_text(a, serial%output, batched%output) == b, label//": the same bytes")
      ! the records: points x columns float64 after the header's bytes
      skip = -1
      n_columns = -1
      at = index(b, "format: binary: after the first ")
      if (at > 0) read (b(at + 32:), *, iostat=ios) skip
      at = index(b, " records of ")
      if (at > 0) read (b(at + 12:), *, iostat=ios) n_columns
      call check(ctx, skip > 0 .and. n_columns > 2 .and. len(b, int64) - skip == 8*n_columns*scene%task%point_count(), &
                 label//": "//"the records of every point after the header")
      call delete_file(output_path(serial))
      call delete_file(output_path(batched))
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
   !> and placeholders as in the serial run (same data lines), and the run reports
   !> err_points_failed with the serial message.
   subroutine failing_point(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(scene_t) :: scene, serial
      type(error_t), allocatable :: error, serial_error
      character(len=:), allocatable :: points
      character(len=1024), allocatable :: a(:), b(:)
      integer :: na, nb
      points = scratch_prefix("batch_fail")//".dat"
      ! beta = 1e13 with 1 - alpha/pi^2 = 3e-7: no mesh of auto or of adaptive Magnus-6 leaves a digit of S
      ! (round-off level 9e293): a real failure
      call write_file(points, [character(len=20) :: "1.0 2.0", "2.0 3.0", "9.8696 1e13", "4.0 2.0"])
      call scene_from("batch_fail", [padded("&scene task='points', method='auto', output='"// &
         scratch_prefix("fail")//"' /"), padded("&points file='"//points//"' /")], scene)
      serial = scene
      serial%output = scene%output//"_serial"
      call serial%task%run(serial, .true., serial_error)
      call run_batch(scene, .true., error)
      call check(ctx, allocated(error) .and. allocated(serial_error), "both runs report the failure")
      if (allocated(error) .and. allocated(serial_error)) then
         call check(ctx, error%code == err_points_failed .and. error%code == serial_error%code, "err_points_failed")
         call check(ctx, contains_text(error%message, "beta = 10000000000000.0"), "names the point")
         call check(ctx, error%message == replace_text(serial_error%message, "_serial", ""), "the serial message")
         call check(ctx, exit_status(error) == 3, "exit status 3")
      end if
      call data_lines(output_path(serial), a, na)
      call data_lines(output_path(scene), b, nb)
      call check(ctx, size(a) == 4 .and. size(b) == 4, "all points written")
      if (size(a) == size(b)) call check(ctx, all(a == b), "identical data lines")
      call delete_file(output_path(serial))
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

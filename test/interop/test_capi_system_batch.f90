!> Tests of the C entry points that compute many points of a system at once
!> (hillstab_interop_capi_system_batch), called from Fortran as C calls them: the values of
!> `hillstab_system_points` equal `hillstab_system_floquet` point by point (damping per
!> point, threads), both entry points equal the data lines of tasks `points` and `chart`
!> to the bit, the column names are the files', and bad input is refused naming the
!> argument and the point, the outputs untouched. The same for an equations system
!> (`hillstab_system_new_named("equations")`, its texts by `hillstab_system_set_text`):
!> Bolotin's column of docs/guide/your-problem.md, its damping prepared at each point's α,
!> against the files of tasks `points` and `chart` to the bit, and its bad input (an
!> unknown kind or variable, a text it refuses, ε ≠ 0) named.
module test_capi_system_batch
   use, intrinsic :: iso_c_binding, only: c_int, c_double, c_char, c_size_t, c_null_char, c_ptr, c_null_ptr, &
      c_associated, c_loc
   use hillstab_core_kinds, only: wp
   use hillstab_core_error, only: error_t, err_invalid_parameter, err_input
   use hillstab_core_text, only: integer_text
   use hillstab_interop_capi, only: hillstab_c_last_error
   use hillstab_interop_capi_system, only: hillstab_c_system_new, hillstab_c_system_free, hillstab_c_system_set, &
      hillstab_c_system_check, hillstab_c_system_floquet, hillstab_c_system_new_named, hillstab_c_system_set_text, &
      hillstab_c_system_monodromy, hillstab_c_system_dof
   use hillstab_interop_capi_system_batch
   use hillstab_batch_run_scenes, only: run_scene_file
   use hillstab_test_scratch, only: padded, scratch_prefix, write_file, read_lines, delete_file
   use hillstab_testing
   implicit none
   private
   public :: collect_capi_system_batch

   !> The system of the tests: damped, a sine drive and a gyroscopic term, as `&system` and as set calls.
   character(len=*), parameter :: group = "&system n = 2, mass = 1.0, 0.0, 0.0, 0.64, b = 1.1, -0.1, -0.1, 0.9, "// &
                                          "damping = 0.02, 0.0, 0.0, 0.01, gyroscopic = 0.0, 0.3, -0.3, 0.0, "// &
                                          "cos = -1.0, -0.2, -0.2, -0.8, sin = 0.0, 0.1, 0.1, 0.3 /"
   !> Bolotin's column (docs/guide/your-problem.md, data/scenes/column_equations.nml) as `&equations`.
   character(len=*), parameter :: column_group = "&equations n = 3, parameters = 'P0 = 0.3, P1 = 0, Om = 2, "// &
      "zeta = 0.01', matrices = 'W = [1, 0, 0; 0, 16, 0; 0, 0, 81], S = [1, 0.3, 0.1; 0.3, 4, 0.4; 0.1, 0.4, 9], "// &
      "Z = [1, 0, 0; 0, 4, 0; 0, 0, 9]', stiffness = 'W - (P0 + P1*cos(Om*t))*S', damping = '2*zeta*Z', "// &
      "frequency = 'Om', alpha = 'Om', beta = 'P1' /"

contains

   function collect_capi_system_batch() result(suite)
      type(testsuite_t) :: suite
      suite = new_testsuite("capi_system_batch", [ &
         new_unittest("points_match_one_by_one", points_match_one_by_one), &
         new_unittest("equal_task_files", equal_task_files), &
         new_unittest("log_chart_equals_task_file", log_chart_equals_task_file), &
         new_unittest("bad_input_named", bad_input_named), &
         new_unittest("equations_equal_task_files", equations_equal_task_files), &
         new_unittest("equations_bad_input_named", equations_bad_input_named)])
   end function collect_capi_system_batch

   function last_message() result(text)
      character(len=:), allocatable :: text
      character(kind=c_char) :: buffer(1024)
      integer(c_int) :: code
      integer :: i
      code = hillstab_c_last_error(buffer, size(buffer, kind=c_size_t))
      text = ""
      do i = 1, size(buffer)
         if (buffer(i) == c_null_char) exit
         text = text//buffer(i)
      end do
   end function last_message

   integer(c_int) function set(system, name, values) result(status)
      type(c_ptr), intent(in) :: system
      character(len=*), intent(in) :: name
      real(c_double), intent(in), target, contiguous :: values(:)
      character(kind=c_char), target :: chars(len(name) + 1)
      integer :: i
      do i = 1, len(name)
         chars(i) = name(i:i)
      end do
      chars(len(name) + 1) = c_null_char
      status = hillstab_c_system_set(system, c_loc(chars), c_loc(values), size(values, kind=c_size_t))
   end function set

   integer(c_int) function set_text(system, name, text) result(status)
      type(c_ptr), intent(in) :: system
      character(len=*), intent(in) :: name, text
      character(kind=c_char), target :: chars(len(name) + 1), value(len(text) + 1)
      call to_c(name, chars)
      call to_c(text, value)
      status = hillstab_c_system_set_text(system, c_loc(chars), c_loc(value))
   end function set_text

   !> A NUL-terminated copy of `text`.
   subroutine to_c(text, chars)
      character(len=*), intent(in) :: text
      character(kind=c_char), intent(out) :: chars(:)
      integer :: i
      do i = 1, len(text)
         chars(i) = text(i:i)
      end do
      chars(len(text) + 1) = c_null_char
   end subroutine to_c

   !> A new system of kind `name` (c_null_ptr when refused).
   function new_named(name) result(system)
      character(len=*), intent(in) :: name
      type(c_ptr), target :: system
      character(kind=c_char), target :: chars(len(name) + 1)
      integer(c_int) :: code
      system = c_null_ptr
      call to_c(name, chars)
      code = hillstab_c_system_new_named(c_loc(chars), c_loc(system))
      if (code /= 0) system = c_null_ptr
   end function new_named

   !> Bolotin's column of `column_group` through the C API.
   function c_column(ctx) result(system)
      type(test_context_t), intent(inout) :: ctx
      type(c_ptr) :: system
      system = new_named("equations")
      call check(ctx, c_associated(system), "new_named equations: "//last_message())
      call check(ctx, set(system, "n", [3.0_wp]) == 0, "set n: "//last_message())
      call check(ctx, set_text(system, "parameters", "P0 = 0.3, P1 = 0, Om = 2, zeta = 0.01") == 0, "parameters")
      call check(ctx, set_text(system, "matrices", "W = [1, 0, 0; 0, 16, 0; 0, 0, 81], S = [1, 0.3, 0.1; 0.3, 4, "// &
                 "0.4; 0.1, 0.4, 9], Z = [1, 0, 0; 0, 4, 0; 0, 0, 9]") == 0, "matrices")
      call check(ctx, set_text(system, "stiffness", "W - (P0 + P1*cos(Om*t))*S") == 0, "stiffness")
      call check(ctx, set_text(system, "damping", "2*zeta*Z") == 0, "damping")
      call check(ctx, set_text(system, "frequency", "Om") == 0, "frequency")
      call check(ctx, set_text(system, "alpha", "Om") == 0, "alpha")
      call check(ctx, set_text(system, "beta", "P1") == 0, "beta")
      call check(ctx, hillstab_c_system_check(system) == 0, "check: "//last_message())
   end function c_column

   !> A scene line of up to 600 characters (the column's group is longer than `padded`'s).
   pure function long_line(text) result(line)
      character(len=*), intent(in) :: text
      character(len=600) :: line
      line = text
   end function long_line

   !> The system of `group` through the C API.
   function c_system(ctx) result(system)
      type(test_context_t), intent(inout) :: ctx
      type(c_ptr), target :: system
      system = c_null_ptr
      call check(ctx, hillstab_c_system_new(c_loc(system)) == 0 .and. c_associated(system), "new")
      call check(ctx, set(system, "n", [2.0_wp]) == 0, "set n")
      call check(ctx, set(system, "mass", [1.0_wp, 0.0_wp, 0.0_wp, 0.64_wp]) == 0, "set mass")
      call check(ctx, set(system, "b", [1.1_wp, -0.1_wp, -0.1_wp, 0.9_wp]) == 0, "set b")
      call check(ctx, set(system, "damping", [0.02_wp, 0.0_wp, 0.0_wp, 0.01_wp]) == 0, "set damping")
      call check(ctx, set(system, "gyroscopic", [0.0_wp, 0.3_wp, -0.3_wp, 0.0_wp]) == 0, "set gyroscopic")
      call check(ctx, set(system, "cos", [-1.0_wp, -0.2_wp, -0.2_wp, -0.8_wp]) == 0, "set cos")
      call check(ctx, set(system, "sin", [0.0_wp, 0.1_wp, 0.1_wp, 0.3_wp]) == 0, "set sin")
      call check(ctx, hillstab_c_system_check(system) == 0, "check: "//last_message())
   end function c_system

   !> The name of column k (from 0).
   function column_name(system, k) result(name)
      type(c_ptr), intent(in) :: system
      integer, intent(in) :: k
      character(len=:), allocatable :: name
      character(kind=c_char) :: buffer(64)
      integer :: i
      name = ""
      if (hillstab_c_system_column_name(system, int(k, c_int), buffer, size(buffer, kind=c_size_t)) /= 0) return
      do i = 1, size(buffer)
         if (buffer(i) == c_null_char) exit
         name = name//buffer(i)
      end do
   end function column_name

   !> 48 points at one α and at others, damping 0 and 0.05 mixed, by auto and rk on two
   !> threads: every value equals one `hillstab_system_floquet` call at the point.
   subroutine points_match_one_by_one(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(c_ptr) :: system
      integer, parameter :: n = 48
      real(c_double), target :: alpha(n), beta(n), epsilon(n), values(16, n)
      real(c_double), target :: re(4), im(4), scale, exponents(2), trace, a2, defect, estimate
      integer(c_int), target :: status(n), verdict, kind, status1, count
      integer, parameter :: methods(2) = [0, 5]
      integer :: j, m
      character(len=60) :: where
      system = c_system(ctx)
      call check(ctx, hillstab_c_system_column_count(system, c_loc(count)) == 0 .and. count == 16, "16 columns")
      call check(ctx, column_name(system, 0) == "alpha" .and. column_name(system, 10) == "mu_1" .and. &
                 column_name(system, 15) == "steps", "column names: "//column_name(system, 10))
      do j = 1, n
         alpha(j) = merge(0.9_wp, 0.05_wp*j, j <= n/2)
         beta(j) = 0.1_wp + 0.06_wp*mod(7*j, n)
         epsilon(j) = merge(0.0_wp, 0.05_wp, mod(j, 3) == 0)
      end do
      do m = 1, size(methods)
         call check(ctx, hillstab_c_system_points(system, int(n, c_size_t), alpha, beta, epsilon, int(methods(m), &
                    c_int), 1.0e-10_c_double, 2_c_int, c_loc(values), c_loc(status)) == 0, "points: "//last_message())
         do j = 1, n
            write (where, '(a, i0, a, i0)') "method ", methods(m), ", point ", j
            call check(ctx, hillstab_c_system_floquet(system, alpha(j), beta(j), epsilon(j), int(methods(m), c_int), &
                       1.0e-10_c_double, c_loc(re), c_loc(im), c_loc(scale), c_loc(exponents), c_loc(verdict), &
                       c_loc(kind), c_loc(trace), c_loc(a2), c_loc(defect), c_loc(estimate), c_loc(status1)) == 0, &
                       trim(where)//": floquet")
            call check(ctx, values(1, j) == alpha(j) .and. values(2, j) == beta(j), trim(where)//": alpha, beta")
            call check(ctx, values(3, j) == trace .and. values(4, j) == a2, trim(where)//": trace, a2")
            call check(ctx, nint(values(6, j)) == verdict .and. nint(values(7, j)) == kind, &
                       trim(where)//": verdict and kind")
            call check(ctx, all(values(11:12, j) == exponents), trim(where)//": exponents")
            call check(ctx, values(13, j) == defect .and. values(14, j) == estimate, trim(where)//": defect, estimate")
            call check(ctx, nint(values(15, j)) == status1 .and. status(j) == status1, trim(where)//": status")
         end do
      end do
      call hillstab_c_system_free(system)
   end subroutine points_match_one_by_one

   !> The numbers of a file's data lines (blank lines skipped).
   function numbers(path, n_columns) result(rows)
      character(len=*), intent(in) :: path
      integer, intent(in) :: n_columns
      real(wp), allocatable :: rows(:, :)
      character(len=1024), allocatable :: lines(:)
      integer :: k, n, ios
      lines = read_lines(path)
      allocate (rows(n_columns, size(lines)))
      n = 0
      do k = 1, size(lines)
         if (lines(k)(1:1) == "#" .or. len_trim(lines(k)) == 0) cycle
         n = n + 1
         read (lines(k), *, iostat=ios) rows(:, n)
         if (ios /= 0) rows(:, n) = huge(1.0_wp)
      end do
      rows = rows(:, :n)
   end function numbers

   !> hillstab_system_points against task points' file and hillstab_system_chart against task
   !> chart's: every number of every line, bit for bit (17 significant digits round-trip).
   subroutine equal_task_files(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(c_ptr) :: system
      type(error_t), allocatable :: error
      character(len=:), allocatable :: out, scene, points, written
      character(len=40) :: lines(30)
      real(c_double), target :: alpha(30), beta(30), epsilon(30), values(16, 30), a(5), b(7), grid(16, 7, 5)
      integer(c_int), target :: status(30), grid_status(7, 5)
      real(wp), allocatable :: file(:, :)
      integer :: j
      system = c_system(ctx)
      points = scratch_prefix("capi_sys_input")//".dat"
      do j = 1, size(lines)
         alpha(j) = 0.7_wp
         beta(j) = 0.2_wp + 0.1_wp*j
         epsilon(j) = 0.03_wp
         write (lines(j), '(f8.4, 1x, f8.4)') alpha(j), beta(j)
         read (lines(j), *) alpha(j), beta(j)
      end do
      call write_file(points, lines)
      out = scratch_prefix("capi_sys")
      scene = out//".nml"
      call write_file(scene, [padded("&scene task = 'points', model = 'system', method = 'magnus4', tolerance = 1e-9, "// &
                              "epsilon = 0.03, output = '"//out//"' /"), padded(group), &
                              padded("&points file = '"//points//"' /")])
      call run_scene_file(scene, .true., error, written)
      call check(ctx, .not. allocated(error), "task points runs")
      if (allocated(error)) return
      file = numbers(written, 16)
      call delete_file(written)
      call check(ctx, hillstab_c_system_points(system, 30_c_size_t, alpha, beta, epsilon, 3_c_int, 1.0e-9_c_double, &
                 0_c_int, c_loc(values), c_loc(status)) == 0, "points: "//last_message())
      call check(ctx, size(file, 2) == 30, "30 lines")
      if (size(file, 2) == 30) call check(ctx, all(file == values), "the points file's numbers")
      call write_file(scene, [padded("&scene task = 'chart', model = 'system', method = 'auto', tolerance = 1e-10, "// &
                              "epsilon = 0.03, output = '"//out//"' /"), padded(group), &
                              padded("&chart alpha_min = 0.1, alpha_max = 1.3, n_alpha = 5, beta_min = 0.2, "// &
                                     "beta_max = 2.6, n_beta = 7 /")])
      call run_scene_file(scene, .true., error, written)
      call check(ctx, .not. allocated(error), "task chart runs")
      if (allocated(error)) return
      file = numbers(written, 16)
      call delete_file(written)
      call check(ctx, hillstab_c_system_chart(system, 0.1_c_double, 1.3_c_double, 5_c_size_t, 0.2_c_double, &
                 2.6_c_double, 7_c_size_t, 0.03_c_double, 0_c_int, 1.0e-10_c_double, 2_c_int, c_loc(a), c_loc(b), &
                 c_loc(grid), c_loc(grid_status)) == 0, "chart: "//last_message())
      call check(ctx, size(file, 2) == 35, "35 lines")
      if (size(file, 2) == 35) call check(ctx, all(file == reshape(grid, [16, 35])), "the chart file's numbers")
      call check(ctx, a(1) == 0.1_wp .and. a(5) == 1.3_wp .and. b(1) == 0.2_wp .and. b(7) == 2.6_wp, "the axes")
      call delete_file(scene)
      call delete_file(points)
      call hillstab_c_system_free(system)
   end subroutine equal_task_files

   !> `hillstab_system_chart_scaled` over log axes against task chart with `alpha_scale`,
   !> `beta_scale` = 'log': every number of every line to the bit; linear scales are
   !> `hillstab_system_chart`; a log axis from 0 or an unknown scale refused by name.
   subroutine log_chart_equals_task_file(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(c_ptr) :: system
      type(error_t), allocatable :: error
      character(len=:), allocatable :: out, scene, written, message
      real(c_double), target :: a(5), b(7), grid(16, 7, 5), a2(5), b2(7), grid2(16, 7, 5)
      integer(c_int), target :: grid_status(7, 5), grid_status2(7, 5)
      real(wp), allocatable :: file(:, :)
      system = c_system(ctx)
      out = scratch_prefix("capi_sys_log")
      scene = out//".nml"
      call write_file(scene, [padded("&scene task = 'chart', model = 'system', method = 'auto', tolerance = 1e-10, "// &
                              "epsilon = 0.03, output = '"//out//"' /"), padded(group), &
                              padded("&chart alpha_min = 0.01, alpha_max = 1.3, n_alpha = 5, alpha_scale = 'log', "// &
                                     "beta_min = 0.02, beta_max = 2.6, n_beta = 7, beta_scale = 'log' /")])
      call run_scene_file(scene, .true., error, written)
      call check(ctx, .not. allocated(error), "task chart runs")
      if (allocated(error)) return
      file = numbers(written, 16)
      call delete_file(written)
      call delete_file(scene)
      call check(ctx, hillstab_c_system_chart_scaled(system, 0.01_c_double, 1.3_c_double, 5_c_size_t, 1_c_int, &
                 0.02_c_double, 2.6_c_double, 7_c_size_t, 1_c_int, 0.03_c_double, 0_c_int, 1.0e-10_c_double, 2_c_int, &
                 c_loc(a), c_loc(b), c_loc(grid), c_loc(grid_status)) == 0, "log chart: "//last_message())
      call check(ctx, size(file, 2) == 35, "35 lines")
      if (size(file, 2) == 35) call check(ctx, all(file == reshape(grid, [16, 35])), "the chart file's numbers")
      call check(ctx, a(1) == 0.01_wp .and. a(5) == 1.3_wp .and. b(1) == 0.02_wp .and. b(7) == 2.6_wp, "the ends")
      call check(ctx, all(a(2:) > a(:4)) .and. abs(a(3)/a(2) - a(2)/a(1)) < 1.0e-14_wp, "a geometric alpha axis")
      call check(ctx, hillstab_c_system_chart_scaled(system, 0.1_c_double, 1.3_c_double, 5_c_size_t, 0_c_int, &
                 0.2_c_double, 2.6_c_double, 7_c_size_t, 0_c_int, 0.03_c_double, 0_c_int, 1.0e-10_c_double, 2_c_int, &
                 c_loc(a), c_loc(b), c_loc(grid), c_loc(grid_status)) == 0, "linear: "//last_message())
      call check(ctx, hillstab_c_system_chart(system, 0.1_c_double, 1.3_c_double, 5_c_size_t, 0.2_c_double, &
                 2.6_c_double, 7_c_size_t, 0.03_c_double, 0_c_int, 1.0e-10_c_double, 2_c_int, c_loc(a2), c_loc(b2), &
                 c_loc(grid2), c_loc(grid_status2)) == 0, "hillstab_system_chart: "//last_message())
      call check(ctx, all(a == a2) .and. all(b == b2) .and. all(grid == grid2) .and. all(grid_status == grid_status2), &
                 "linear scales: hillstab_system_chart to the bit")
      grid = 7.0_wp
      call check(ctx, hillstab_c_system_chart_scaled(system, 0.0_c_double, 1.3_c_double, 5_c_size_t, 1_c_int, &
                 0.2_c_double, 2.6_c_double, 7_c_size_t, 0_c_int, 0.0_c_double, 0_c_int, 1.0e-10_c_double, 0_c_int, &
                 c_loc(a), c_loc(b), c_loc(grid), c_loc(grid_status)) == err_invalid_parameter, "log alpha from 0")
      message = last_message()
      call check(ctx, index(message, "hillstab_system_chart_scaled: a log alpha axis needs") == 1, message)
      call check(ctx, hillstab_c_system_chart_scaled(system, 0.1_c_double, 1.3_c_double, 5_c_size_t, 0_c_int, &
                 0.2_c_double, 2.6_c_double, 7_c_size_t, -1_c_int, 0.0_c_double, 0_c_int, 1.0e-10_c_double, 0_c_int, &
                 c_loc(a), c_loc(b), c_loc(grid), c_loc(grid_status)) == err_invalid_parameter, "scale -1")
      message = last_message()
      call check(ctx, index(message, "hillstab_system_chart_scaled: beta_scale must be 0 (linear) or 1 (log)") == 1, &
                 message)
      call check(ctx, all(grid == 7.0_wp), "the chart untouched")
      call hillstab_c_system_free(system)
   end subroutine log_chart_equals_task_file

   !> Bad input: the argument and the point named, nothing written.
   subroutine bad_input_named(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(c_ptr) :: system
      real(c_double), target :: alpha(3), beta(3), epsilon(3), values(16, 3), a(2), b(2), grid(16, 2, 2)
      integer(c_int), target :: status(3), grid_status(2, 2)
      system = c_system(ctx)
      alpha = [0.1_wp, 0.2_wp, 0.3_wp]
      beta = 1.0_wp
      epsilon = [0.0_wp, 0.0_wp, -0.1_wp]
      values = 7.0_wp
      call refused(hillstab_c_system_points(system, 3_c_size_t, alpha, beta, epsilon, 0_c_int, 1.0e-10_c_double, &
                   0_c_int, c_loc(values), c_loc(status)), "hillstab_system_points: epsilon: point 2: must be finite "// &
                   "and >= 0, got -0.1", "negative epsilon")
      epsilon = 0.0_wp
      call refused(hillstab_c_system_points(system, 3_c_size_t, alpha, beta, epsilon, 0_c_int, 1.0e-10_c_double, &
                   0_c_int, c_null_ptr, c_loc(status)), "hillstab_system_points: values: a null pointer", "null values")
      call refused(hillstab_c_system_points(system, 3_c_size_t, alpha, beta, epsilon, 7_c_int, 1.0e-10_c_double, &
                   0_c_int, c_loc(values), c_loc(status)), "hillstab_system_points: method:", "unknown method")
      call refused(hillstab_c_system_points(system, 3_c_size_t, alpha, beta, epsilon, 0_c_int, 1.0e-10_c_double, &
                   -1_c_int, c_loc(values), c_loc(status)), "hillstab_system_points: threads:", "negative threads")
      call refused(hillstab_c_system_points(c_null_ptr, 3_c_size_t, alpha, beta, epsilon, 0_c_int, 1.0e-10_c_double, &
                   0_c_int, c_loc(values), c_loc(status)), "hillstab_system_points: system:", "null system")
      call check(ctx, all(values == 7.0_wp), "the values untouched")
      grid = 7.0_wp
      call refused(hillstab_c_system_chart(system, 0.0_c_double, 1.0_c_double, 2_c_size_t, 0.0_c_double, &
                   1.0_c_double, huge(1_c_size_t), 0.0_c_double, 0_c_int, 1.0e-10_c_double, 0_c_int, c_loc(a), &
                   c_loc(b), c_loc(grid), c_loc(grid_status)), "hillstab_system_chart: n_beta =", "n_beta too large")
      call refused(hillstab_c_system_chart(system, 0.0_c_double, 1.0_c_double, 2_c_size_t, 0.0_c_double, &
                   1.0_c_double, 2_c_size_t, -1.0_c_double, 0_c_int, 1.0e-10_c_double, 0_c_int, c_loc(a), &
                   c_loc(b), c_loc(grid), c_loc(grid_status)), "hillstab_system_chart: epsilon: the grid:", &
                   "negative epsilon")
      call check(ctx, all(grid == 7.0_wp), "the chart untouched")
      call hillstab_c_system_free(system)
   contains
      subroutine refused(code, part, what)
         integer(c_int), intent(in) :: code
         character(len=*), intent(in) :: part, what
         character(len=:), allocatable :: message
         message = last_message()
         call check(ctx, code == err_invalid_parameter, what//": status "//integer_text(int(code)))
         call check(ctx, index(message, part) == 1, what//": the message '"//message//"' starts with '"//part//"'")
      end subroutine refused
   end subroutine bad_input_named

   !> Bolotin's column through the C API against tasks `points` (8 points near the principal,
   !> combination and second-order regions and off them, auto and magnus4) and `chart` (4 × 5
   !> over (Om, P1)): every number of every line to the bit. `hillstab_system_floquet` at each
   !> point equals the points' values to the bit, and `hillstab_system_monodromy` keeps
   !> Liouville's det Φ = exp(−T tr C), T = 2π/Om, at the point's own Om (the damping
   !> prepared at the point, not at the parameters' Om = 2).
   subroutine equations_equal_task_files(ctx)
      type(test_context_t), intent(inout) :: ctx
      integer, parameter :: n = 8, width = 17
      real(wp), parameter :: pi = acos(-1.0_wp)
      type(c_ptr) :: system
      type(error_t), allocatable :: error
      character(len=:), allocatable :: out, scene, points, written
      character(len=40) :: lines(n)
      character(len=8), parameter :: methods(2) = [character(len=8) :: "auto", "magnus4"]
      integer, parameter :: codes(2) = [0, 3]
      real(c_double), target :: alpha(n), beta(n), epsilon(n), values(width, n), a(4), b(5), grid(width, 5, 4)
      real(c_double), target :: re(6), im(6), scale, exponents(3), trace, a2, defect, estimate, phi(36)
      integer(c_int), target :: status(n), grid_status(5, 4), verdict, kind, status1, dof, count
      real(wp), allocatable :: file(:, :)
      complex(wp) :: product
      integer :: j, m
      character(len=60) :: where
      system = c_column(ctx)
      call check(ctx, hillstab_c_system_dof(system, c_loc(dof)) == 0 .and. dof == 3, "n = 3")
      call check(ctx, hillstab_c_system_column_count(system, c_loc(count)) == 0 .and. count == width, "17 columns")
      alpha = [1.6726_wp, 1.6_wp, 4.68_wp, 10.0_wp, 0.84_wp, 7.69_wp, 2.34_wp, 17.7_wp]
      beta = [0.0_wp, 0.4_wp, 0.3_wp, 0.0_wp, 0.8_wp, 0.5_wp, 1.0_wp, 0.2_wp]
      epsilon = 0.0_wp
      points = scratch_prefix("capi_eqs_input")//".dat"
      do j = 1, n
         write (lines(j), '(f8.4, 1x, f8.4)') alpha(j), beta(j)
         read (lines(j), *) alpha(j), beta(j)
      end do
      call write_file(points, lines)
      out = scratch_prefix("capi_eqs")
      scene = out//".nml"
      do m = 1, size(methods)
         call write_file(scene, [long_line("&scene task = 'points', model = 'equations', method = '"// &
                                        trim(methods(m))//"', tolerance = 1e-10, output = '"//out//"' /"), &
                                 long_line(column_group), long_line("&points file = '"//points//"' /")])
         call run_scene_file(scene, .true., error, written)
         call check(ctx, .not. allocated(error), "task points runs ("//trim(methods(m))//")")
         if (allocated(error)) then
            call check(ctx, .false., error%message)
            return
         end if
         file = numbers(written, width)
         call delete_file(written)
         values = 7.0_wp
         call check(ctx, hillstab_c_system_points(system, int(n, c_size_t), alpha, beta, epsilon, int(codes(m), &
                    c_int), 1.0e-10_c_double, 2_c_int, c_loc(values), c_loc(status)) == 0, "points: "//last_message())
         call check(ctx, size(file, 2) == n, "8 lines")
         if (size(file, 2) == n) call check(ctx, all(file == values), "the points file's numbers, "//trim(methods(m)))
         call check(ctx, all(status == 0), "status 0, "//trim(methods(m)))
         do j = 1, n
            write (where, '(a, a, a, i0)') "equations, ", trim(methods(m)), ", point ", j
            call check(ctx, hillstab_c_system_floquet(system, alpha(j), beta(j), 0.0_c_double, int(codes(m), c_int), &
                       1.0e-10_c_double, c_loc(re), c_loc(im), c_loc(scale), c_loc(exponents), c_loc(verdict), &
                       c_loc(kind), c_loc(trace), c_loc(a2), c_loc(defect), c_loc(estimate), c_loc(status1)) == 0, &
                       trim(where)//": floquet "//last_message())
            call check(ctx, values(3, j) == trace .and. values(4, j) == a2, trim(where)//": trace, a2")
            call check(ctx, nint(values(6, j)) == verdict .and. nint(values(7, j)) == kind, &
                       trim(where)//": verdict and kind")
            call check(ctx, all(values(11:13, j) == exponents), trim(where)//": exponents")
            call check(ctx, values(14, j) == defect .and. values(15, j) == estimate, trim(where)//": defect, estimate")
            call check(ctx, nint(values(16, j)) == status1, trim(where)//": status")
            ! Liouville: the product of the multipliers is det Φ = exp(−T tr C), tr C = 2 ζ (1 + 4 + 9)
            product = product_of(cmplx(re, im, wp))*exp(scale*6.0_wp)
            call check(ctx, abs(product/exp(-2.0_wp*pi/alpha(j)*0.28_wp) - 1.0_wp) <= 1.0e-6_wp, trim(where)// &
                       ": det Phi = exp(-T tr C) at the point's Om")
         end do
      end do
      call check(ctx, hillstab_c_system_monodromy(system, 10.0_c_double, 0.0_c_double, 0.0_c_double, 0_c_int, &
                 1.0e-10_c_double, c_loc(phi), c_loc(scale), c_loc(estimate), c_loc(status1)) == 0, &
                 "monodromy: "//last_message())
      call check(ctx, abs(determinant(reshape(phi, [6, 6]))*exp(6.0_wp*scale)/exp(-2.0_wp*pi/10.0_wp*0.28_wp) - &
                          1.0_wp) <= 1.0e-6_wp, &
                 "monodromy: det Phi = exp(-T tr C) at Om = 10")
      call write_file(scene, [long_line("&scene task = 'chart', model = 'equations', method = 'auto', "// &
                                     "tolerance = 1e-10, output = '"//out//"' /"), long_line(column_group), &
                              long_line("&chart alpha_min = 1.2, alpha_max = 2.1, n_alpha = 4, beta_min = 0.0, "// &
                                     "beta_max = 1.2, n_beta = 5 /")])
      call run_scene_file(scene, .true., error, written)
      call check(ctx, .not. allocated(error), "task chart runs")
      if (allocated(error)) return
      file = numbers(written, width)
      call delete_file(written)
      call check(ctx, hillstab_c_system_chart(system, 1.2_c_double, 2.1_c_double, 4_c_size_t, 0.0_c_double, &
                 1.2_c_double, 5_c_size_t, 0.0_c_double, 0_c_int, 1.0e-10_c_double, 2_c_int, c_loc(a), c_loc(b), &
                 c_loc(grid), c_loc(grid_status)) == 0, "chart: "//last_message())
      call check(ctx, size(file, 2) == 20, "20 lines")
      if (size(file, 2) == 20) call check(ctx, all(file == reshape(grid, [width, 20])), "the chart file's numbers")
      call check(ctx, a(1) == 1.2_wp .and. a(4) == 2.1_wp .and. b(1) == 0.0_wp .and. b(5) == 1.2_wp, "the axes")
      call check(ctx, any(nint(grid(6, :, :)) == 0) .and. any(nint(grid(6, :, :)) == 1), "stable and unstable points")
      call delete_file(scene)
      call delete_file(points)
      call hillstab_c_system_free(system)
   contains
      pure complex(wp) function product_of(z)
         complex(wp), intent(in) :: z(:)
         integer :: i
         product_of = (1.0_wp, 0.0_wp)
         do i = 1, size(z)
            product_of = product_of*z(i)
         end do
      end function product_of
      !> det by Gaussian elimination with partial pivoting (the matrix row-major: its transpose has the same det)
      function determinant(matrix) result(det)
         real(wp), intent(in) :: matrix(:, :)
         real(wp) :: det, a(size(matrix, 1), size(matrix, 1)), row(size(matrix, 1))
         integer :: i, k, p
         a = matrix
         det = 1.0_wp
         do k = 1, size(a, 1)
            p = k - 1 + maxloc(abs(a(k:, k)), dim=1)
            if (p /= k) then
               row = a(k, :)
               a(k, :) = a(p, :)
               a(p, :) = row
               det = -det
            end if
            det = det*a(k, k)
            do i = k + 1, size(a, 1)
               a(i, k:) = a(i, k:) - a(i, k)/a(k, k)*a(k, k:)
            end do
         end do
      end function determinant
   end subroutine equations_equal_task_files

   !> An equations system's bad input, named: an unknown kind, an unknown variable (set and
   !> set_text), numbers for a text, a text for a matrix system, a text the system refuses
   !> (hillstab_system_check and every computation name the variable; set right again, the
   !> system is whole), ε ≠ 0 (floquet, points, chart, and the command line's &scene).
   subroutine equations_bad_input_named(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(c_ptr) :: system, matrix
      type(error_t), allocatable :: error
      character(len=:), allocatable :: out, scene, written
      real(c_double), target :: alpha(2), beta(2), epsilon(2), values(17, 2), a(2), b(2), grid(17, 2, 2)
      real(c_double), target :: re(6), im(6), scale, exponents(3), trace, a2, defect, estimate
      integer(c_int), target :: status(2), grid_status(2, 2), verdict, kind, status1
      system = new_named("bogus")
      call check(ctx, .not. c_associated(system), "an unknown kind is refused")
      call check(ctx, index(last_message(), "hillstab_system_new_named: name: unknown system 'bogus'") == 1, &
                 "the kind named: "//last_message())
      matrix = new_named("System")
      call check(ctx, c_associated(matrix), "'System' (any case) is the matrix system")
      call refused(set_text(matrix, "stiffness", "W"), "hillstab_system_set_text: the system model has no text "// &
                   "variable 'stiffness'", "a text for a matrix system")
      call hillstab_c_system_free(matrix)
      system = c_column(ctx)
      call refused(set_text(system, "stifness", "W"), "hillstab_system_set_text: the equations system has no "// &
                   "variable 'stifness'", "an unknown variable")
      call refused(set(system, "stiffness", [1.0_wp]), "hillstab_system_set: the equations system has no "// &
                   "numeric variable 'stiffness'", "numbers for a text")
      call refused(set(system, "n", [2.5_wp]), "hillstab_system_set: n: ", "n not an integer")
      call check(ctx, hillstab_c_system_check(system) == 0, "the system unchanged by the refusals: "//last_message())
      ! a text the system refuses: taken by set_text, named by check and by every computation
      call check(ctx, set_text(system, "matrices", "W = [1, 0, 0; 0, 16, 0; 0, 0, 81], S = [1, 0.3, 0.1; 0.3, 4; "// &
                 "0.1, 0.4, 9], Z = [1, 0, 0; 0, 4, 0; 0, 0, 9]") == 0, "a text set")
      call refused(hillstab_c_system_check(system), "hillstab_system_check: matrices: S, row 2 has 2 entries, "// &
                   "n = 3 are needed", "a matrix row short")
      alpha = [2.0_wp, 3.0_wp]
      beta = [0.1_wp, 0.2_wp]
      epsilon = 0.0_wp
      values = 7.0_wp
      call refused(hillstab_c_system_points(system, 2_c_size_t, alpha, beta, epsilon, 0_c_int, 1.0e-10_c_double, &
                   0_c_int, c_loc(values), c_loc(status)), "hillstab_system_points: matrices: S, row 2", &
                   "points on a refused text")
      call refused(hillstab_c_system_floquet(system, 2.0_c_double, 0.1_c_double, 0.0_c_double, 0_c_int, &
                   1.0e-10_c_double, c_loc(re), c_loc(im), c_loc(scale), c_loc(exponents), c_loc(verdict), &
                   c_loc(kind), c_loc(trace), c_loc(a2), c_loc(defect), c_loc(estimate), c_loc(status1)), &
                   "hillstab_system_floquet: matrices: S, row 2", "floquet on a refused text")
      call check(ctx, set_text(system, "matrices", "W = [1, 0, 0; 0, 16, 0; 0, 0, 81], S = [1, 0.3, 0.1; 0.3, 4, "// &
                 "0.4; 0.1, 0.4, 9], Z = [1, 0, 0; 0, 4, 0; 0, 0, 9]") == 0, "the text set right")
      call check(ctx, hillstab_c_system_check(system) == 0, "whole again: "//last_message())
      call check(ctx, set_text(system, "alpha", "Omega") == 0, "set_text takes the name; check judges it")
      call refused(hillstab_c_system_check(system), "hillstab_system_check: alpha: 'Omega'", "an axis no parameter")
      call check(ctx, set_text(system, "alpha", "Om") == 0 .and. hillstab_c_system_check(system) == 0, "alpha again")
      ! the damping is the system's own
      call refused(hillstab_c_system_floquet(system, 2.0_c_double, 0.1_c_double, 0.1_c_double, 0_c_int, &
                   1.0e-10_c_double, c_loc(re), c_loc(im), c_loc(scale), c_loc(exponents), c_loc(verdict), &
                   c_loc(kind), c_loc(trace), c_loc(a2), c_loc(defect), c_loc(estimate), c_loc(status1)), &
                   "hillstab_system_floquet: epsilon: the equations system carries its own damping", &
                   "floquet with epsilon")
      epsilon = [0.0_wp, 0.05_wp]
      call refused(hillstab_c_system_points(system, 2_c_size_t, alpha, beta, epsilon, 0_c_int, 1.0e-10_c_double, &
                   0_c_int, c_loc(values), c_loc(status)), "hillstab_system_points: epsilon: point 1: the equations "// &
                   "system carries its own damping", "points with epsilon")
      call check(ctx, all(values == 7.0_wp), "the values untouched")
      grid = 7.0_wp
      call refused(hillstab_c_system_chart(system, 1.0_c_double, 2.0_c_double, 2_c_size_t, 0.0_c_double, &
                   1.0_c_double, 2_c_size_t, 0.01_c_double, 0_c_int, 1.0e-10_c_double, 0_c_int, c_loc(a), &
                   c_loc(b), c_loc(grid), c_loc(grid_status)), "hillstab_system_chart: epsilon: the grid: the "// &
                   "equations system carries its own damping", "chart with epsilon")
      call check(ctx, all(grid == 7.0_wp), "the chart untouched")
      call refused(hillstab_c_system_chart(system, -1.0_c_double, 2.0_c_double, 2_c_size_t, 0.0_c_double, &
                   1.0_c_double, 2_c_size_t, 0.0_c_double, 0_c_int, 1.0e-10_c_double, 0_c_int, c_loc(a), &
                   c_loc(b), c_loc(grid), c_loc(grid_status)), "hillstab_system_chart: the grid (alpha = -1", &
                   "a frequency <= 0")
      call hillstab_c_system_free(system)
      ! the command line refuses it alike
      out = scratch_prefix("capi_eqs_eps")
      scene = out//".nml"
      call write_file(scene, [long_line("&scene task = 'chart', model = 'equations', epsilon = 0.1, output = '"// &
                                     out//"' /"), long_line(column_group), &
                              long_line("&chart alpha_min = 1.0, alpha_max = 2.0, n_alpha = 2, beta_min = 0.0, "// &
                                     "beta_max = 1.0, n_beta = 2 /")])
      call run_scene_file(scene, .true., error, written)
      call check(ctx, allocated(error), "the command line refuses epsilon")
      if (allocated(error)) then
         call check(ctx, error%code == err_input .and. index(error%message, "&scene: epsilon: the equations system "// &
                    "carries its own damping") > 0, "named: "//error%message)
      end if
      call delete_file(scene)
   contains
      subroutine refused(code, part, what)
         integer(c_int), intent(in) :: code
         character(len=*), intent(in) :: part, what
         character(len=:), allocatable :: message
         message = last_message()
         call check(ctx, code == err_invalid_parameter, what//": status "//integer_text(int(code)))
         call check(ctx, index(message, part) == 1, what//": the message '"//message//"' starts with '"//part//"'")
      end subroutine refused
   end subroutine equations_bad_input_named
end module test_capi_system_batch

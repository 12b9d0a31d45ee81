!> Tests of the tasks on a system scene (`&scene model = 'system'`) through `run_scene_file`,
!> reading the files back: a one-equation system's chart against the Mathieu model's chart
!> (the same Q = β − α cos πτ), the columns and their selection, a repeated run from the
!> header, the points task, the coefficient task against K(τ) in closed form, a matrix given
!> as a file of rows, a binary chart of chosen columns against the text one, and one equation
!> of `&equations` on method auto (the scalar path) against the same chart on magnus6.
module test_task_system
   use hillstab_core_kinds, only: wp, pi, int64
   use hillstab_core_error, only: error_t, err_points_failed
   use hillstab_hill_system_floquet, only: kind_minus_one, kind_plus_one, kind_combination
   use hillstab_test_scratch, only: padded, scratch_prefix, write_file, read_lines, delete_file, contains_text
   use hillstab_test_files, only: run_text_scene, check_rerun
   use hillstab_batch_scene_types, only: scene_t
   use hillstab_batch_run_read, only: read_scene
   use hillstab_batch_run_scenes, only: run_scene_file
   use hillstab_testing
   implicit none
   private
   public :: collect_task_system

contains

   function collect_task_system() result(suite)
      type(testsuite_t) :: suite
      suite = new_testsuite("task_system", [ &
         new_unittest("one_equation_is_mathieu_chart", one_equation_is_mathieu_chart), &
         new_unittest("pendula_columns_and_rerun", pendula_columns_and_rerun), &
         new_unittest("points_and_verdict_columns", points_and_verdict_columns), &
         new_unittest("coefficient_closed_form", coefficient_closed_form), &
         new_unittest("matrix_from_file", matrix_from_file), &
         new_unittest("binary_chosen_columns", binary_chosen_columns), &
         new_unittest("estimates_bound_files", estimates_bound_files), &
         new_unittest("one_equation_scalar_path", one_equation_scalar_path)])
   end function collect_task_system

   !> The free-space check refuses a run whose task's estimate of its file exceeds the room
   !> left: the estimates of a system's chart and points files, text and binary, all columns
   !> and a few, bound the files written (and by no more than the header's allowance and a
   !> line's width a point).
   subroutine estimates_bound_files(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=*), parameter :: group = "&system n = 3, b = 1.0, 0.0, 0.0, 0.0, 2.0, 0.0, 0.0, 0.0, 3.0, "// &
                                             "cos = -1.0, -0.3, 0.0, -0.3, -1.0, -0.3, 0.0, -0.3, -1.0 /"
      character(len=:), allocatable :: out, path, points, formats(:), columns(:)
      character(len=40) :: lines(70)
      type(scene_t) :: scene
      type(error_t), allocatable :: error
      integer(int64) :: estimate, bytes
      integer :: f, c, t, k, n_points
      points = scratch_prefix("sys_est_input")//".dat"
      do k = 1, size(lines)
         write (lines(k), '(f8.4,1x,f8.4)') 0.01_wp*k, 0.5_wp + 0.02_wp*k
      end do
      call write_file(points, lines)
      formats = [character(len=6) :: "text", "binary"]
      columns = [character(len=40) :: "", "alpha beta stable mu_3 status"]
      do t = 1, 2
         do f = 1, 2
            do c = 1, 2
               out = scratch_prefix("sys_est")
               path = out//".nml"
               if (t == 1) then
                  call write_file(path, [padded("&scene model = 'system', format = '"//trim(formats(f))// &
                     "', columns = '"//trim(columns(c))//"', output = '"//out//"' /"), padded(group), &
                     padded("&chart alpha_min = 0, alpha_max = 1, n_alpha = 9, beta_min = 0.5, beta_max = 2, "// &
                            "n_beta = 31 /")])
                  n_points = 9*31
               else
                  call write_file(path, [padded("&scene task = 'points', model = 'system', format = '"// &
                     trim(formats(f))//"', columns = '"//trim(columns(c))//"', output = '"//out//"' /"), &
                     padded(group), padded("&points file = '"//points//"' /")])
                  n_points = size(lines)
               end if
               call read_scene(path, scene, error)
               if (allocated(error)) then
                  call check(ctx, .false., "the scene reads: "//error%message)
                  return
               end if
               estimate = scene%task%estimated_bytes(scene)
               call run_scene_file(path, .true., error)
               call check(ctx, .not. allocated(error), "the scene runs")
               inquire (file=out//"_"//scene%task%name//merge(".dat", ".bin", f == 1), size=bytes)
               call check(ctx, bytes > 0 .and. bytes <= estimate, trim(formats(f))//" "//scene%task%name// &
                          " '"//trim(columns(c))//"': the estimate bounds the file")
               call check(ctx, estimate <= 1000000_int64 + bytes + int(n_points, int64)*30*20, &
                          "and is not far above it")
               call delete_file(out//"_"//scene%task%name//merge(".dat", ".bin", f == 1))
               call delete_file(path)
            end do
         end do
      end do
      call delete_file(points)
   end subroutine estimates_bound_files

   !> The numbers of the data lines (blank lines skipped).
   subroutine numbers(lines, n_columns, rows)
      character(len=*), intent(in) :: lines(:)
      integer, intent(in) :: n_columns
      real(wp), allocatable, intent(out) :: rows(:, :)
      integer :: k, n, ios
      allocate (rows(n_columns, size(lines)))
      n = 0
      do k = 1, size(lines)
         if (lines(k)(1:1) == "#" .or. len_trim(lines(k)) == 0) cycle
         n = n + 1
         read (lines(k), *, iostat=ios) rows(:, n)
         if (ios /= 0) rows(:, n) = huge(1.0_wp)
      end do
      rows = rows(:, :n)
   end subroutine numbers

   !> n = 1, B = 1, K₁ᶜ = −1 is the Mathieu equation: trace = S and the same verdicts (where
   !> decided) as the Mathieu model's chart.
   subroutine one_equation_is_mathieu_chart(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(error_t), allocatable :: error
      character(len=:), allocatable :: written, scalar_file, out
      character(len=1024), allocatable :: lines(:)
      real(wp), allocatable :: sys(:, :), ref(:, :)
      character(len=*), parameter :: grid = "&chart alpha_min = 0, alpha_max = 6, n_alpha = 7, beta_min = -1, "// &
                                            "beta_max = 9, n_beta = 21 /"
      integer :: k
      out = scratch_prefix("sys1")
      call run_text_scene("sys1", [padded("&scene model = 'system', columns = 'alpha beta trace stable kind "// &
                                          "status', output = '"//out//"' /"), &
                                   padded("&system n = 1, cos = -1 /"), padded(grid)], error, written)
      call check(ctx, .not. allocated(error), "system chart runs")
      if (allocated(error)) return
      lines = read_lines(written)
      call numbers(lines, 6, sys)
      call delete_file(written)
      out = scratch_prefix("mat1")
      call run_text_scene("mat1", [padded("&scene model = 'mathieu', columns = 'alpha beta S stable', "// &
                                          "tolerance = 1e-12, output = '"//out//"' /"), padded(grid)], error, scalar_file)
      call check(ctx, .not. allocated(error), "mathieu chart runs")
      if (allocated(error)) return
      lines = read_lines(scalar_file)
      call numbers(lines, 4, ref)
      call delete_file(scalar_file)
      call check(ctx, size(sys, 2) == 147 .and. size(ref, 2) == 147, "7 x 21 points each")
      if (size(sys, 2) /= size(ref, 2)) return
      do k = 1, size(sys, 2)
         call check(ctx, sys(3, k), ref(3, k), abs=4.0e-10_wp*max(1.0_wp, abs(ref(3, k))), message="trace = S")
         call check(ctx, sys(6, k) == 0.0_wp, "status 0")
         if (abs(abs(ref(3, k)) - 2.0_wp) > 1.0e-6_wp) then
            call check(ctx, sys(4, k) == ref(4, k), "the verdict where the margin is clear")
            if (ref(4, k) == 0.0_wp) call check(ctx, nint(sys(5, k)) == merge(kind_plus_one, kind_minus_one, &
                                                                           ref(3, k) > 0.0_wp), "kind +1 / -1")
         end if
      end do
   end subroutine one_equation_is_mathieu_chart

   !> The pendula pair: every column, its header (effective &system, one columns line), the
   !> combination kind inside the ω₁ + ω₂ = π tongue, and the file repeated from its header.
   subroutine pendula_columns_and_rerun(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(error_t), allocatable :: error
      character(len=:), allocatable :: written, out, again
      character(len=1024), allocatable :: lines(:)
      real(wp), allocatable :: rows(:, :)
      logical :: ok
      integer :: k, combination
      out = scratch_prefix("pair")
      call run_text_scene("pair", [padded("&scene model = 'system', output = '"//out//"' /"), &
                                   padded("&system n = 2, mass = 1, 0, 0, 0.25, b = 2, -1, -1, 1.5, cos = -1, 0, 0, -0.5 /"), &
                                   padded("&chart alpha_min = 0.5, alpha_max = 1.0, n_alpha = 3, beta_min = 0.6, "// &
                                          "beta_max = 0.85, n_beta = 11 /")], error, written)
      call check(ctx, .not. allocated(error), "pair chart runs")
      if (allocated(error)) return
      lines = read_lines(written)
      call check(ctx, count(index(lines, "# columns: alpha beta trace a2 overflow stable kind lambda_max mu "// &
                                  "argument mu_1 mu_2 defect error_estimate status steps") == 1) == 1, "one columns line")
      call check(ctx, any(index(lines, "# &system n = 2, mass = 1.0, 0.0, 0.0, 0.25") == 1), "effective &system, n whole")
      call numbers(lines, 16, rows)
      call check(ctx, size(rows, 2) == 33, "3 x 11 rows")
      combination = 0
      do k = 1, size(rows, 2)
         call check(ctx, rows(15, k) == 0.0_wp, "status 0")
         call check(ctx, rows(14, k) <= 1.0e-10_wp, "error estimate within the tolerance")
         call check(ctx, abs(rows(13, k)) <= 1.0e-9_wp, "symplectic defect")
         call check(ctx, rows(9, k), max(rows(11, k), rows(12, k)), abs=1.0e-15_wp, message="mu = mu_1")
         if (nint(rows(7, k)) == kind_combination) combination = combination + 1
      end do
      call check(ctx, combination >= 3, "the combination tongue near beta = 0.72")
      call check_rerun(ctx, written, lines, again, ok)
      call delete_file(written)
      if (ok) call delete_file(again)
   end subroutine pendula_columns_and_rerun

   !> Points at a file's (α, β), in file order, with the verdict columns only.
   subroutine points_and_verdict_columns(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(error_t), allocatable :: error
      character(len=:), allocatable :: written, out, pts
      character(len=1024), allocatable :: lines(:)
      real(wp), allocatable :: rows(:, :)
      out = scratch_prefix("syspts")
      pts = out//"_in.dat"
      call write_file(pts, [padded("# alpha beta"), padded("0.5 2.1"), padded("1.0 0.72"), padded("0.2 1.2")])
      call run_text_scene("syspts", [padded("&scene task = 'points', model = 'system', columns = 'alpha beta "// &
                                            "stable kind status', output = '"//out//"' /"), &
                                     padded("&system n = 2, mass = 1, 0, 0, 0.25, b = 2, -1, -1, 1.5, cos = -1, 0, 0, "// &
                                            "-0.5 /"), padded("&points file = '"//pts//"' /")], error, written)
      call check(ctx, .not. allocated(error), "points run")
      if (allocated(error)) return
      lines = read_lines(written)
      call numbers(lines, 5, rows)
      call check(ctx, size(rows, 2) == 3, "three points")
      if (size(rows, 2) /= 3) return
      call check(ctx, nint(rows(3, 1)) == 0 .and. nint(rows(4, 1)) == kind_minus_one, "simple tongue at beta = 2.1")
      call check(ctx, nint(rows(3, 2)) == 0 .and. nint(rows(4, 2)) == kind_combination, "combination at 0.72")
      call check(ctx, nint(rows(3, 3)) == 1 .and. nint(rows(4, 3)) == 0, "stable between the tongues")
      call delete_file(written)
      call delete_file(pts)
   end subroutine points_and_verdict_columns

   !> K(τ) = K0 + β B + α (K₁ᶜ cos πτ + K₁ˢ sin πτ) entry by entry.
   subroutine coefficient_closed_form(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(error_t), allocatable :: error
      character(len=:), allocatable :: written, out
      character(len=1024), allocatable :: lines(:)
      real(wp), allocatable :: rows(:, :)
      real(wp) :: a, t, expected(4)
      integer :: k
      out = scratch_prefix("syscoef")
      call run_text_scene("syscoef", [padded("&scene task = 'coefficient', model = 'system', output = '"//out//"' /"), &
                                      padded("&system n = 2, k0 = 1, 2, 2, 3, b = 1, 0, 0, 2, cos = 0.5, 0, 0, 1, "// &
                                             "sin = 0, 1, 1, 0 /"), &
                                      padded("&coefficient alphas = 0.5, 2.0, beta = 1.5, n_tau = 9 /")], error, written)
      call check(ctx, .not. allocated(error), "coefficient runs")
      if (allocated(error)) return
      lines = read_lines(written)
      call numbers(lines, 6, rows)
      call check(ctx, size(rows, 2) == 18, "two blocks of 9")
      do k = 1, size(rows, 2)
         a = rows(1, k)
         t = rows(2, k)
         expected = [1.0_wp + 1.5_wp + a*0.5_wp*cos(pi*t), 2.0_wp + a*sin(pi*t), 2.0_wp + a*sin(pi*t), &
                     3.0_wp + 3.0_wp + a*cos(pi*t)]
         call check(ctx, rows(3, k), expected(1), abs=1.0e-14_wp, message="k_1_1")
         call check(ctx, rows(4, k), expected(2), abs=1.0e-14_wp, message="k_1_2")
         call check(ctx, rows(5, k), expected(3), abs=1.0e-14_wp, message="k_2_1")
         call check(ctx, rows(6, k), expected(4), abs=1.0e-14_wp, message="k_2_2")
      end do
      call delete_file(written)
   end subroutine coefficient_closed_form

   !> A matrix as a quoted file of its rows (comments, a blank line, closing commas) gives
   !> the file of the same matrix as a list.
   subroutine matrix_from_file(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(error_t), allocatable :: error
      character(len=:), allocatable :: first, second, out, matrix
      character(len=1024), allocatable :: a(:), b(:)
      integer :: k
      out = scratch_prefix("sysfile")
      matrix = out//"_mass.dat"
      call write_file(matrix, [padded("# the mass matrix"), padded("1.0,  0.0,"), padded(""), padded("0.0  0.25  # m2")])
      call run_text_scene("sysfile", [padded("&scene model = 'system', columns = 'alpha beta trace a2', output = '"// &
                                             out//"_a' /"), padded("&system n = 2, mass = '"//matrix//"', b = 2, -1, "// &
                                             "-1, 1.5, cos = -1, 0, 0, -0.5 /"), padded("&chart n_alpha = 2, "// &
                                             "alpha_max = 1, n_beta = 5, beta_min = 0, beta_max = 2 /")], error, first)
      call check(ctx, .not. allocated(error), "mass from a file")
      if (allocated(error)) return
      call run_text_scene("syslist", [padded("&scene model = 'system', columns = 'alpha beta trace a2', output = '"// &
                                             out//"_b' /"), padded("&system n = 2, mass = 1, 0, 0, 0.25, b = 2, -1, "// &
                                             "-1, 1.5, cos = -1, 0, 0, -0.5 /"), padded("&chart n_alpha = 2, "// &
                                             "alpha_max = 1, n_beta = 5, beta_min = 0, beta_max = 2 /")], error, second)
      call check(ctx, .not. allocated(error), "mass as a list")
      if (allocated(error)) return
      a = read_lines(first)
      b = read_lines(second)
      call check(ctx, any(index(a, "mass = 1.0, 0.0, 0.0, 0.25") > 0), "the header gives the file's numbers")
      do k = 1, min(size(a), size(b))
         if (a(k)(1:1) == "#") cycle
         call check(ctx, a(k) == b(k), "the same data lines")
      end do
      call delete_file(first)
      call delete_file(second)
      call delete_file(matrix)
   end subroutine matrix_from_file

   !> A binary chart of the columns `alpha beta stable kind`: after its header exactly those
   !> four float64 values a point (the records the header's `# columns:` line names), equal
   !> to the text chart's numbers.
   subroutine binary_chosen_columns(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(error_t), allocatable :: error
      character(len=:), allocatable :: written, out, raw
      character(len=1024), allocatable :: lines(:)
      real(wp), allocatable :: rows(:, :), records(:, :)
      integer(int64) :: bytes
      integer :: unit, start, at, k
      character(len=*), parameter :: system = "&system n = 2, mass = 1, 0, 0, 0.25, b = 2, -1, -1, 1.5, "// &
                                              "cos = -1, 0, 0, -0.5 /"
      character(len=*), parameter :: grid = "&chart alpha_min = 0.5, alpha_max = 1.0, n_alpha = 2, beta_min = 0.6, "// &
                                            "beta_max = 2.2, n_beta = 3 /"
      out = scratch_prefix("sysbin")
      call run_text_scene("sysbin", [padded("&scene model = 'system', columns = 'alpha beta stable kind', output = '"// &
                                            out//"' /"), padded(system), padded(grid)], error, written)
      call check(ctx, .not. allocated(error), "text chart runs")
      if (allocated(error)) return
      lines = read_lines(written)
      call numbers(lines, 4, rows)
      call delete_file(written)
      call run_text_scene("sysbin", [padded("&scene model = 'system', format = 'binary', columns = 'alpha beta "// &
                                            "stable kind', output = '"//out//"' /"), padded(system), padded(grid)], &
                          error, written)
      call check(ctx, .not. allocated(error), "binary chart runs")
      if (allocated(error)) return
      inquire (file=written, size=bytes)
      allocate (character(len=bytes) :: raw)
      open (newunit=unit, file=written, access="stream", form="unformatted", status="old", action="read")
      read (unit) raw
      close (unit)
      at = index(raw, new_line("a")//"# columns: alpha beta stable kind"//new_line("a"))
      call check(ctx, at > 0, "the header's columns line")
      if (at == 0) return
      start = at + len("# columns: alpha beta stable kind") + 2
      call check(ctx, len(raw) - start + 1 == 6*4*8, "4 values of 6 points after the header")
      if (len(raw) - start + 1 /= 6*4*8) return
      allocate (records(4, 6))
      records = reshape(transfer(raw(start:), 1.0_wp, 24), [4, 6])
      do k = 1, 6
         call check(ctx, all(records(:, k) == rows(:, k)), "point's values as in the text file")
      end do
      call delete_file(written)
   end subroutine binary_chosen_columns
   !> One damped equation written as a system (`&equations n = 1`, its mass and stiffness
   !> through 1 × 1 matrices): on method auto it takes the scalar path (the header says so),
   !> and its chart agrees with the system method magnus6's on the same grid: the trace, μ
   !> and the argument within the tolerances, a₂ = det Φ = exp(−εP) in closed form, the same
   !> verdict and kind wherever magnus6 decides; the points task gives the chart's values.
   subroutine one_equation_scalar_path(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=*), parameter :: equations = "&equations n = 1, parameters = 'P0 = 0.3, P1 = 0, Om = 2, "// &
         "zeta = 0.02', matrices = 'W = [1.5], S = [0.7], Mm = [2]', mass = 'Mm', stiffness = "// &
         "'W - (P0 + P1*cos(Om*t))*S', damping = '2*zeta*Mm', frequency = 'Om', alpha = 'Om', beta = 'P1' /"
      character(len=*), parameter :: grid = "&chart alpha_min = 0.5, alpha_max = 4, n_alpha = 8, beta_min = 0, "// &
                                            "beta_max = 2.5, n_beta = 25 /"
      type(error_t), allocatable :: error
      character(len=:), allocatable :: written, out, points_path
      character(len=1024), allocatable :: lines(:)
      character(len=60) :: point_lines(5)
      real(wp), allocatable :: fast(:, :), slow(:, :), listed(:, :)
      real(wp) :: epsilon
      integer :: k, j, decided, unstable
      out = scratch_prefix("one_fast")
      call run_text_scene("one_fast", [padded("&scene model = 'equations', method = 'auto', tolerance = 1e-10, "// &
                                              "output = '"//out//"' /"), padded(equations), padded(grid)], error, written)
      call check(ctx, .not. allocated(error), "auto chart runs")
      if (allocated(error)) return
      lines = read_lines(written)
      call check(ctx, any(index(lines, "# method: auto on the scalar form") == 1), "the header names the scalar path")
      call numbers(lines, 15, fast)
      call delete_file(written)
      out = scratch_prefix("one_slow")
      call run_text_scene("one_slow", [padded("&scene model = 'equations', method = 'magnus6', tolerance = 1e-11, "// &
                                              "output = '"//out//"' /"), padded(equations), padded(grid)], error, written)
      call check(ctx, .not. allocated(error), "magnus6 chart runs")
      if (allocated(error)) return
      lines = read_lines(written)
      call check(ctx, .not. any(index(lines, "scalar form") > 0), "magnus6 takes the system path")
      call numbers(lines, 15, slow)
      call delete_file(written)
      call check(ctx, size(fast, 2) == 200 .and. size(slow, 2) == 200, "8 x 25 points each")
      if (size(fast, 2) /= size(slow, 2)) return
      decided = 0
      unstable = 0
      do k = 1, size(fast, 2)
         ! eps = pi c/(m Om) = 2 pi zeta/Om, P = 2: det Phi = exp(-2 eps)
         epsilon = 2.0_wp*pi*0.02_wp/fast(1, k)
         call check(ctx, fast(14, k) == 0.0_wp .and. slow(14, k) == 0.0_wp, "status 0")
         call check(ctx, fast(3, k), slow(3, k), abs=1.0e-8_wp*max(1.0_wp, abs(slow(3, k))), message="trace")
         call check(ctx, fast(4, k), exp(-2.0_wp*epsilon), rel=1.0e-13_wp, message="a2 = exp(-eps P)")
         call check(ctx, slow(4, k), exp(-2.0_wp*epsilon), rel=1.0e-9_wp, message="magnus6's a2 too")
         call check(ctx, fast(9, k), slow(9, k), abs=1.0e-9_wp, message="mu")
         call check(ctx, fast(11, k), slow(11, k), abs=1.0e-9_wp, message="mu_1")
         call check(ctx, fast(12, k) == 0.0_wp, "no defect by construction")
         if (abs(fast(10, k) - slow(10, k)) > 1.0e-6_wp) &
            call check(ctx, abs(abs(fast(10, k) - slow(10, k)) - 1.0_wp) < 1.0e-6_wp .or. fast(8, k) < 1.0_wp, &
                       "the argument where the multipliers differ in modulus")
         if (slow(6, k) >= 0.0_wp) then
            decided = decided + 1
            call check(ctx, fast(6, k) == slow(6, k) .and. fast(7, k) == slow(7, k), "verdict and kind")
            if (slow(6, k) == 0.0_wp) unstable = unstable + 1
         end if
      end do
      call check(ctx, decided >= 190 .and. unstable >= 10 .and. decided - unstable >= 10, &
                 "both verdicts in the sample, nearly every point decided")
      ! the points task on five of the chart's points: the chart's values
      do j = 1, 5
         k = 37*j
         write (point_lines(j), '(es24.16, 1x, es24.16)') fast(1, k), fast(2, k)
      end do
      points_path = scratch_prefix("one_points_in")//".dat"
      call write_file(points_path, point_lines)
      out = scratch_prefix("one_points")
      call run_text_scene("one_points", [padded("&scene task = 'points', model = 'equations', method = 'auto', "// &
                                                "tolerance = 1e-10, output = '"//out//"' /"), padded(equations), &
                                         padded("&points file = '"//points_path//"' /")], error, written)
      call check(ctx, .not. allocated(error), "points run")
      if (allocated(error)) return
      lines = read_lines(written)
      call numbers(lines, 15, listed)
      call delete_file(written)
      call delete_file(points_path)
      call check(ctx, size(listed, 2) == 5, "5 points")
      if (size(listed, 2) /= 5) return
      do j = 1, 5
         call check(ctx, listed(3, j), fast(3, 37*j), abs=1.0e-9_wp*max(1.0_wp, abs(fast(3, 37*j))), &
                    message="a point's trace is the chart's")
         call check(ctx, listed(6, j) == fast(6, 37*j), "and its verdict")
      end do
   end subroutine one_equation_scalar_path

end module test_task_system

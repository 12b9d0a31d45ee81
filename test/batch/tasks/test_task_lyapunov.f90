!> Tests of the lyapunov task (hillstab_batch_tasks_lyapunov) through `run_scene_file`, reading
!> the file back: layout (header with the effective scene, one `# columns:` line, α
!> blocks); with `integrator = 'dop853'` and no early stop each value against the library
!> called directly (lyapunov_largest, Benettin by DOP853), and the linear columns against
!> the points task of the core at the same points; the default integrator (symplectic
!> tangent map, early stop) against that run: the same verdicts, the exponents of regular
!> orbits within their spread; lanes do not change the lines; the same values over
!> `&points`; repeating the run from its output; the distributed driver
!> (hillstab_batch_run_units) writing the same file; bad input naming file, group and variable.
module test_task_lyapunov
   use hillstab_core_kinds, only: wp, pi2
   use hillstab_core_error, only: error_t, err_input
   use hillstab_batch_scene_types, only: scene_t
   use hillstab_batch_run_read, only: read_scene
   use hillstab_batch_run_scenes, only: run_scene_file, output_path
   use hillstab_batch_run_units, only: run_batch
   use hillstab_pendulum_equations, only: pendulum_t, pendulum_from_chart, pendulum_initial_state
   use hillstab_pendulum_lyapunov, only: lyapunov_t, lyapunov_largest
   use hillstab_testing
   use hillstab_test_files, only: run_text_scene
   use hillstab_test_scratch, only: padded, scratch_prefix, write_file, read_lines, file_exists, delete_file, contains_text
   implicit none
   private
   public :: collect_task_lyapunov

contains

   function collect_task_lyapunov() result(suite)
      type(testsuite_t) :: suite
      suite = new_testsuite("task_lyapunov", [ &
         new_unittest("grid_layout_and_values", grid_layout_and_values), &
         new_unittest("default_integrator_same_verdicts", default_integrator_same_verdicts), &
         new_unittest("lanes_do_not_change_lines", lanes_do_not_change_lines), &
         new_unittest("points_same_values", points_same_values), &
         new_unittest("over_a_spring", over_a_spring), &
         new_unittest("repeat_and_distributed", repeat_and_distributed), &
         new_unittest("bad_input", bad_input)])
   end function collect_task_lyapunov

   !> The numeric rows of a file (n_columns numbers each), and the blank lines.
   subroutine rows_of(path, n_columns, rows, n_blank, columns)
      character(len=*), intent(in) :: path
      integer, intent(in) :: n_columns
      real(wp), allocatable, intent(out) :: rows(:, :)
      integer, intent(out) :: n_blank
      character(len=:), allocatable, intent(out) :: columns
      character(len=1024), allocatable :: lines(:)
      integer :: k, n, ios
      lines = read_lines(path)
      allocate (rows(n_columns, size(lines)))
      n = 0
      n_blank = 0
      columns = ""
      do k = 1, size(lines)
         if (lines(k)(1:11) == "# columns: ") columns = trim(lines(k)(12:))
         if (lines(k)(1:1) == "#") cycle
         if (len_trim(lines(k)) == 0) then
            n_blank = n_blank + 1
            cycle
         end if
         n = n + 1
         read (lines(k), *, iostat=ios) rows(:, n)
         if (ios /= 0) rows(:, n) = -huge(1.0_wp)
      end do
      rows = rows(:, :n)
   end subroutine rows_of

   !> A 3 × 2 grid at 60 periods by DOP853 without early stop: 6 lines in 3 blocks; each
   !> exponent, spread, max |φ| and energy drift equal lyapunov_largest's; λ_max and stable
   !> equal the points task's; MEGNO below 3 on the regular orbit (c), above 3.5 on (g).
   subroutine grid_layout_and_values(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(error_t), allocatable :: error
      character(len=:), allocatable :: written, columns, chart_written
      real(wp), allocatable :: rows(:, :), core(:, :)
      integer :: n_blank, k, n_core_blank
      type(pendulum_t) :: p
      type(lyapunov_t) :: reference
      character(len=60) :: points(6)
      call run_text_scene("lyap_grid", [padded("&scene task='lyapunov', tolerance=1e-10, output='"// &
         scratch_prefix("lyap_grid")//"' /"), padded("&series phi0=0.017, periods=60, r0=0.2, g=9.81 /"), &
         padded("&lyapunov integrator='dop853', early_stop=.false. /"), &
         padded("&chart alpha_min=2.57, alpha_max=7.48, n_alpha=3, beta_min=1.29, beta_max=2.47, n_beta=2 /")], &
         error, written)
      call check(ctx, .not. allocated(error), "runs")
      if (allocated(error)) return
      call rows_of(written, 17, rows, n_blank, columns)
      call check(ctx, columns == "alpha beta lyapunov spread lyapunov_error stable lambda_max log_lambda_max max_abs_phi "// &
         "energy_drift chaotic megno fli energy_error integrator periods status", "columns")
      call check(ctx, size(rows, 2) == 6 .and. n_blank == 2, "6 lines in 3 blocks")
      if (size(rows, 2) /= 6) return
      call check(ctx, all(rows(17, :) == 0.0_wp) .and. all(rows(16, :) == 60.0_wp), "status 0, 60 periods")
      call check(ctx, all(rows(15, :) == 2.0_wp), "integrator 2 (DOP853)")
      call check(ctx, rows(12, 1) < 3.0_wp .and. rows(12, 6) > 3.5_wp, "megno below 3 at (c), above 3.5 at (g)")
      call check(ctx, rows(11, 1) == 0.0_wp .and. rows(11, 6) == 1.0_wp, "(c) regular, (g) chaotic")
      call check(ctx, all(rows(13, :) >= 0.0_wp) .and. all(rows(14, :) >= rows(10, :)), "fli >= 0, energy_error >= drift")
      do k = 1, 6
         call pendulum_from_chart(rows(1, k), rows(2, k), 0.0_wp, 0.2_wp, 9.81_wp, p, error)
         call lyapunov_largest(p, pendulum_initial_state(p, 0.017_wp), 60, 1.0e-10_wp, reference, error)
         call check(ctx, rows(3, k), reference%exponent, rel=1.0e-9_wp, abs=1.0e-12_wp)
         call check(ctx, rows(4, k), reference%spread, rel=1.0e-2_wp, abs=1.0e-12_wp)
         call check(ctx, rows(5, k), reference%exponent_error, rel=1.0e-2_wp, abs=1.0e-12_wp)
         call check(ctx, rows(9, k), reference%max_abs_phi, rel=1.0e-5_wp)
         call check(ctx, abs(rows(8, k) - log(rows(7, k))) < 1.0e-8_wp*max(1.0_wp, rows(8, k)), &
            "log_lambda_max = ln lambda_max")
         write (points(k), '(2es24.16)') rows(1, k), rows(2, k)
      end do
      ! the linear columns against the core's points task at the same points
      call write_file(scratch_prefix("lyap_core")//".dat", points)
      call run_text_scene("lyap_core", [padded("&scene task='points', output='"//scratch_prefix("lyap_core")//"' /"), &
         padded("&points file='"//scratch_prefix("lyap_core")//".dat' /")], error, chart_written)
      call check(ctx, .not. allocated(error), "core runs")
      if (.not. allocated(error)) then
         call rows_of(chart_written, 5, core, n_core_blank, columns)
         do k = 1, 6
            call check(ctx, rows(6, k) == core(4, k), "stable as the chart")
            call check(ctx, rows(7, k), core(5, k), rel=1.0e-9_wp)
         end do
         call delete_file(chart_written)
      end if
      ! case (g) is chaotic, case (c) regular
      call check(ctx, rows(3, 6) > 0.1_wp .and. rows(3, 1) < 0.1_wp, "(7.48, 2.47) above (2.57, 1.29)")
      call delete_file(scratch_prefix("lyap_core")//".dat")
      call delete_file(written)
   end subroutine grid_layout_and_values

   !> The default integrator (auto: the symplectic tangent map, early stop) over a 4 × 3 grid
   !> of the physical domain at 300 periods against DOP853 without early stop: the same
   !> verdict at every point; on the points both call regular, the exponents agree within
   !> the larger spread; the symplectic map ran at most points, with energy errors below
   !> the tolerance; chaotic points stopped early.
   subroutine default_integrator_same_verdicts(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(error_t), allocatable :: error
      character(len=:), allocatable :: fast, slow, columns
      real(wp), allocatable :: a(:, :), b(:, :)
      integer :: na, nb, k
      character(len=*), parameter :: grid = "&chart alpha_min=1.5, alpha_max=8.5, n_alpha=4, beta_min=1, "// &
         "beta_max=6, n_beta=3 /"
      call run_text_scene("lyap_auto", [padded("&scene task='lyapunov', output='"//scratch_prefix("lyap_auto")// &
         "' /"), padded("&series periods=300 /"), padded(grid)], error, fast)
      call check(ctx, .not. allocated(error), "auto runs")
      if (allocated(error)) return
      call run_text_scene("lyap_dop", [padded("&scene task='lyapunov', output='"//scratch_prefix("lyap_dop")// &
         "' /"), padded("&series periods=300 /"), padded("&lyapunov integrator='dop853', early_stop=.false. /"), &
         padded(grid)], error, slow)
      call check(ctx, .not. allocated(error), "dop853 runs")
      if (allocated(error)) return
      call rows_of(fast, 17, a, na, columns)
      call rows_of(slow, 17, b, nb, columns)
      call check(ctx, size(a, 2) == 12 .and. size(b, 2) == 12, "12 lines each")
      if (size(a, 2) /= 12 .or. size(b, 2) /= 12) return
      call check(ctx, all(a(11, :) == b(11, :)), "same verdicts")
      call check(ctx, count(a(15, :) == 1.0_wp) >= 9, "symplectic at most points")
      call check(ctx, all(a(14, :) <= 1.0e-6_wp .or. a(15, :) == 2.0_wp), "energy errors within the tolerance")
      call check(ctx, any(a(11, :) == 1.0_wp) .and. any(a(11, :) == 0.0_wp), "both kinds of orbit")
      do k = 1, 12
         if (a(11, k) == 0.0_wp .and. b(11, k) == 0.0_wp) then
            call check(ctx, abs(a(3, k) - b(3, k)) <= max(a(4, k), b(4, k)), "regular: exponents within the spread")
            call check(ctx, a(16, k) == 300.0_wp, "regular: the full periods")
         else if (a(11, k) == 1.0_wp) then
            call check(ctx, a(16, k) < 300.0_wp, "chaotic: stopped early")
         end if
         call check(ctx, a(6, k) == b(6, k) .and. a(7, k) == b(7, k), "the same linear columns")
      end do
      call delete_file(fast)
      call delete_file(slow)
   end subroutine default_integrator_same_verdicts

   !> One lane or sixteen: the same lines (each lane's arithmetic is its own).
   subroutine lanes_do_not_change_lines(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(error_t), allocatable :: error
      character(len=:), allocatable :: one, many
      character(len=1024), allocatable :: a(:), b(:)
      character(len=*), parameter :: grid = "&chart alpha_min=2, alpha_max=9, n_alpha=5, beta_min=1, "// &
         "beta_max=8, n_beta=4 /"
      call run_text_scene("lyap_one", [padded("&scene task='lyapunov', output='"//scratch_prefix("lyap_lanes")// &
         "' /"), padded("&series periods=40 /"), padded("&lyapunov lanes=1 /"), padded(grid)], error, one)
      call check(ctx, .not. allocated(error), "one lane runs")
      if (allocated(error)) return
      a = read_lines(one)
      call delete_file(one)
      call run_text_scene("lyap_many", [padded("&scene task='lyapunov', output='"//scratch_prefix("lyap_lanes")// &
         "' /"), padded("&series periods=40 /"), padded("&lyapunov lanes=16 /"), padded(grid)], error, many)
      call check(ctx, .not. allocated(error), "16 lanes run")
      if (allocated(error)) return
      b = read_lines(many)
      call delete_file(many)
      call check(ctx, size(a) == size(b), "same length")
      ! the scene file line and the &lyapunov line differ
      if (size(a) == size(b)) call check(ctx, count(a /= b) == 2, "only the scene lines differ")
   end subroutine lanes_do_not_change_lines

   !> Over the amplitudes and frequencies of `&physical` (3 x 2, r0 = 0.3 m): blocks of
   !> constant a; a, omega as given; alpha = a pi^2/rho with rho = r0 + g/omega^2, beta =
   !> g pi^2/(rho omega^2); lyapunov_per_s = lyapunov omega/(2 pi); every indicator equal
   !> to a run over `&points` at the same (alpha, beta) with r0, g in `&series`; the file
   !> repeats its run; the spring and `&chart` (or r0 in `&series`) together refused.
   subroutine over_a_spring(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(error_t), allocatable :: error
      character(len=:), allocatable :: spring, list, columns, copy, again
      real(wp), allocatable :: a(:, :), b(:, :)
      character(len=60) :: points(6)
      real(wp), parameter :: g = 9.80665_wp, r0 = 0.3_wp, pi = acos(-1.0_wp)
      real(wp) :: rho, amplitude, omega
      integer :: na, nb, k, i, j
      character(len=1024), allocatable :: first(:), second(:)
      call run_text_scene("lyap_spring", [padded("&scene task='lyapunov', output='"// &
         scratch_prefix("lyap_spring")//"' /"), padded("&series periods=40 /"), &
         padded("&physical r0=0.3, a_min=0.002, a_max=0.05, n_a=3, omega_min=8, omega_max=12, n_omega=2 /")], &
         error, spring)
      call check(ctx, .not. allocated(error), "runs")
      if (allocated(error)) return
      call rows_of(spring, 20, a, na, columns)
      call check(ctx, columns == "alpha beta a omega lyapunov lyapunov_per_s spread lyapunov_error stable lambda_max "// &
         "log_lambda_max max_abs_phi energy_drift chaotic megno fli energy_error integrator periods status", "columns")
      call check(ctx, size(a, 2) == 6 .and. na == 2, "6 lines in 3 blocks of constant a")
      if (size(a, 2) /= 6) return
      do k = 1, 6
         i = (k - 1)/2 + 1
         j = mod(k - 1, 2) + 1
         amplitude = 0.002_wp + (i - 1)*0.024_wp
         omega = 8.0_wp + (j - 1)*4.0_wp
         rho = r0 + g/omega**2
         call check(ctx, a(3, k), amplitude, rel=1.0e-15_wp)
         call check(ctx, a(4, k), omega, rel=1.0e-15_wp)
         call check(ctx, a(1, k), amplitude*pi**2/rho, rel=1.0e-14_wp)
         call check(ctx, a(2, k), g*pi**2/(rho*omega**2), rel=1.0e-14_wp)
         call check(ctx, a(6, k), a(5, k)*omega/(2.0_wp*pi), rel=1.0e-9_wp, abs=1.0e-12_wp)
         write (points(k), '(2es24.16e3)') a(1, k), a(2, k)
      end do
      call write_file(scratch_prefix("lyap_spring_pts")//".dat", points)
      call run_text_scene("lyap_spring_pts", [padded("&scene task='lyapunov', output='"// &
         scratch_prefix("lyap_spring_pts")//"' /"), padded("&series periods=40, r0=0.3, g=9.80665 /"), &
         padded("&lyapunov over='points' /"), padded("&points file='"//scratch_prefix("lyap_spring_pts")//".dat' /")], &
         error, list)
      call check(ctx, .not. allocated(error), "the points run")
      if (.not. allocated(error)) then
         call rows_of(list, 17, b, nb, columns)
         if (size(b, 2) == 6) then
            ! the shared columns: the spring's file has a, omega (3, 4) and lyapunov_per_s (6) more
            call check(ctx, all(a([1, 2, 5], :) == b([1, 2, 3], :)) .and. all(a(7:20, :) == b(4:17, :)), &
               "every indicator as over &points")
         else
            call check(ctx, .false., "6 lines over &points")
         end if
         call delete_file(list)
      end if
      ! the file repeats its run
      first = read_lines(spring)
      copy = scratch_prefix("lyap_spring_copy")//".dat"
      call write_file(copy, first)
      call delete_file(spring)
      call run_scene_file(copy, .true., error, again)
      call check(ctx, .not. allocated(error), "repeats from its output")
      if (.not. allocated(error)) then
         second = read_lines(again)
         call check(ctx, size(first) == size(second), "same length")
         if (size(first) == size(second)) call check(ctx, count(first /= second) == 1, "only the scene file line differs")
         call delete_file(again)
      end if
      call delete_file(copy)
      call delete_file(scratch_prefix("lyap_spring_pts")//".dat")
      ! the spring and the dimensionless grid together
      call run_text_scene("lyap_spring_bad", [padded("&scene task='lyapunov', output='"// &
         scratch_prefix("lyap_spring_bad")//"' /"), padded("&series periods=40, r0=0.1 /"), &
         padded("&physical r0=0.3, a_min=0.002, a_max=0.05, n_a=3, omega=10 /")], error, list)
      call check(ctx, allocated(error), "r0 in &series with &physical refused")
      if (allocated(error)) call check(ctx, contains_text(error%message, "&series: r0:"), "names &series r0: "// &
         error%message)
      call run_text_scene("lyap_spring_bad", [padded("&scene task='lyapunov', output='"// &
         scratch_prefix("lyap_spring_bad")//"' /"), padded("&series periods=40 /"), padded("&chart /"), &
         padded("&physical r0=0.3, a_min=0.002, a_max=0.05, n_a=3, omega=10 /")], error, list)
      call check(ctx, allocated(error), "&chart with &physical refused")
      if (allocated(error)) call check(ctx, contains_text(error%message, "&chart:"), "names &chart: "//error%message)
      call check(ctx, .not. file_exists(scratch_prefix("lyap_spring_bad")//"_lyapunov.dat"), "no file")
   end subroutine over_a_spring

   !> Over `&points`: the lines of the same points as the grid's (no blank lines).
   subroutine points_same_values(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(error_t), allocatable :: error
      character(len=:), allocatable :: grid, list, columns
      real(wp), allocatable :: a(:, :), b(:, :)
      integer :: na, nb
      call run_text_scene("lyap_g", [padded("&scene task='lyapunov', output='"//scratch_prefix("lyap_g")//"' /"), &
         padded("&series periods=30 /"), &
         padded("&chart alpha_min=3.7, alpha_max=7.48, n_alpha=2, beta_min=2.47, beta_max=2.47, n_beta=1 /")], &
         error, grid)
      call write_file(scratch_prefix("lyap_p")//".dat", [character(len=20) :: "3.7 2.47", "7.48 2.47"])
      call run_text_scene("lyap_p", [padded("&scene task='lyapunov', output='"//scratch_prefix("lyap_p")//"' /"), &
         padded("&series periods=30 /"), padded("&lyapunov over='points' /"), &
         padded("&points file='"//scratch_prefix("lyap_p")//".dat' /")], error, list)
      call check(ctx, .not. allocated(error), "runs")
      if (allocated(error)) return
      call rows_of(grid, 17, a, na, columns)
      call rows_of(list, 17, b, nb, columns)
      call check(ctx, size(a, 2) == 2 .and. size(b, 2) == 2 .and. nb == 0, "two lines each")
      if (size(a, 2) == 2 .and. size(b, 2) == 2) call check(ctx, all(a == b), "same values")
      call delete_file(grid)
      call delete_file(list)
      call delete_file(scratch_prefix("lyap_p")//".dat")
   end subroutine points_same_values

   !> Giving the output file back as a scene repeats the run (identical file apart from
   !> the scene file line); run_batch (the MPI driver's serial path) writes the same lines.
   subroutine repeat_and_distributed(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(error_t), allocatable :: error
      type(scene_t) :: scene
      character(len=:), allocatable :: written, again
      character(len=1024), allocatable :: a(:), b(:), c(:)
      character(len=:), allocatable :: copy
      call run_text_scene("lyap_rep", [padded("&scene task='lyapunov', output='"//scratch_prefix("lyap_rep")//"' /"), &
         padded("&series periods=20 /"), &
         padded("&chart alpha_min=1, alpha_max=9, n_alpha=4, beta_min=0.5, beta_max=9, n_beta=3 /")], error, written)
      call check(ctx, .not. allocated(error), "runs")
      if (allocated(error)) return
      a = read_lines(written)
      copy = scratch_prefix("lyap_rep_copy")//".dat"
      call write_file(copy, a)
      call delete_file(written)
      call run_scene_file(copy, .true., error, again)
      call check(ctx, .not. allocated(error) .and. again == written, "repeats from its output")
      b = read_lines(written)
      call check(ctx, size(a) == size(b), "same length")
      if (size(a) == size(b)) call check(ctx, count(a /= b) == 1, "only the scene file line differs")
      call read_scene(copy, scene, error)
      call check(ctx, .not. allocated(error), "its output reads as a scene")
      if (allocated(error)) return
      scene%output = scene%output//"_batch"
      call run_batch(scene, .true., error)
      call check(ctx, .not. allocated(error), "batch runs")
      c = read_lines(output_path(scene))
      call check(ctx, size(c) == size(b), "batch: same length")
      if (size(c) == size(b)) call check(ctx, count(c /= b) == 1, "batch: only the output name differs")
      call delete_file(output_path(scene))
      call delete_file(written)
      call delete_file(copy)
   end subroutine repeat_and_distributed

   subroutine bad_input(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(error_t), allocatable :: error
      character(len=:), allocatable :: written
      call run_text_scene("lyap_bad", [padded("&scene task='lyapunov', output='"//scratch_prefix("lyap_bad")//"' /"), &
         padded("&series periods=20 /"), padded("&chart beta_min=0, beta_max=5 /")], error, written)
      call check(ctx, allocated(error), "beta_min = 0 refused")
      if (allocated(error)) call check(ctx, error%code == err_input .and. contains_text(error%message, "&chart") .and. &
         contains_text(error%message, "beta_min"), "names &chart beta_min: "//error%message)
      call run_text_scene("lyap_bad", [padded("&scene task='lyapunov', output='"//scratch_prefix("lyap_bad")//"' /"), &
         padded("&series periods=20 /"), padded("&lyapunov over='grid' /"), padded("&chart /")], error, written)
      call check(ctx, allocated(error), "over = 'grid' refused")
      if (allocated(error)) call check(ctx, contains_text(error%message, "&lyapunov") .and. &
         contains_text(error%message, "over"), "names &lyapunov over: "//error%message)
      call run_text_scene("lyap_bad", [padded("&scene task='lyapunov', output='"//scratch_prefix("lyap_bad")//"' /"), &
         padded("&series periods=0 /"), padded("&chart beta_min=1 /")], error, written)
      call check(ctx, allocated(error), "periods = 0 refused")
      if (allocated(error)) call check(ctx, contains_text(error%message, "periods"), "names periods")
      call bad_lyapunov("integrator='rk4'", "integrator")
      call bad_lyapunov("scheme='euler'", "scheme")
      call bad_lyapunov("lanes=0", "lanes")
      call bad_lyapunov("megno_regular=3.0, megno_chaotic=2.5", "megno_chaotic")
      call bad_lyapunov("megno_stop=3.0", "megno_stop")
      call bad_lyapunov("energy_tolerance=0", "energy_tolerance")
      call bad_lyapunov("steps_per_period=2", "steps_per_period")
      call bad_lyapunov("min_periods=0", "min_periods")
      call run_text_scene("lyap_bad", [padded("&scene task='lyapunov', epsilon=0.01, output='"// &
         scratch_prefix("lyap_bad")//"' /"), padded("&series periods=20 /"), &
         padded("&lyapunov integrator='symplectic' /"), padded("&chart /")], error, written)
      call check(ctx, allocated(error), "symplectic with damping refused")
      if (allocated(error)) call check(ctx, contains_text(error%message, "integrator") .and. &
         contains_text(error%message, "epsilon"), "names integrator and epsilon: "//error%message)
      call check(ctx, .not. file_exists(scratch_prefix("lyap_bad")//"_lyapunov.dat"), "no file")
   contains
      subroutine bad_lyapunov(settings, variable)
         character(len=*), intent(in) :: settings, variable
         call run_text_scene("lyap_bad", [padded("&scene task='lyapunov', output='"//scratch_prefix("lyap_bad")// &
            "' /"), padded("&series periods=20 /"), padded("&lyapunov "//settings//" /"), padded("&chart /")], &
            error, written)
         call check(ctx, allocated(error), settings//" refused")
         if (allocated(error)) call check(ctx, error%code == err_input .and. contains_text(error%message, &
            "&lyapunov") .and. contains_text(error%message, variable//":"), "names &lyapunov "//variable//": "// &
            error%message)
      end subroutine bad_lyapunov
   end subroutine bad_input
end module test_task_lyapunov

!> Tests of the lyapunov task (hillstab_batch_task_lyapunov) through `run_scene_file`, reading
!> the file back: layout (header with the effective scene, one `# columns:` line, α
!> blocks), each value against the library called directly (lyapunov_largest) and the
!> linear columns against the points task of the core at the same points; the same
!> values over `&points`; repeating the run from its output; the distributed driver
!> (hillstab_batch_units) writing the same file; bad input naming file, group and variable.
module test_task_lyapunov
   use hillstab_core_kinds, only: wp, pi2
   use hillstab_core_error, only: error_t, err_input
   use hillstab_batch_scene, only: scene_t
   use hillstab_batch_scene_read, only: read_scene
   use hillstab_batch_tasks, only: run_scene_file, output_path
   use hillstab_batch_units, only: run_batch
   use hillstab_pendulum_equations, only: pendulum_t, pendulum_from_chart, pendulum_initial_state
   use hillstab_pendulum_lyapunov, only: lyapunov_t, lyapunov_largest
   use hillstab_testing
   use hillstab_test_files, only: run_text_scene
   use test_scene, only: padded, scratch_prefix, write_file, read_lines, file_exists, delete_file, contains_text
   implicit none
   private
   public :: collect_task_lyapunov

contains

   function collect_task_lyapunov() result(suite)
      type(testsuite_t) :: suite
      suite = new_testsuite("task_lyapunov", [ &
         new_unittest("grid_layout_and_values", grid_layout_and_values), &
         new_unittest("points_same_values", points_same_values), &
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

   !> A 3 × 2 grid at 60 periods: 6 lines in 3 blocks; each exponent, spread, max |φ|
   !> and energy drift equal lyapunov_largest's; λ_max and stable equal the points task's.
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
         padded("&chart alpha_min=2.57, alpha_max=7.48, n_alpha=3, beta_min=1.29, beta_max=2.47, n_beta=2 /")], &
         error, written)
      call check(ctx, .not. allocated(error), "runs")
      if (allocated(error)) return
      call rows_of(written, 11, rows, n_blank, columns)
      call check(ctx, columns == "alpha beta lyapunov spread stable lambda_max log_lambda_max max_abs_phi "// &
         "energy_drift periods status", "columns")
      call check(ctx, size(rows, 2) == 6 .and. n_blank == 2, "6 lines in 3 blocks")
      if (size(rows, 2) /= 6) return
      call check(ctx, all(rows(11, :) == 0.0_wp) .and. all(rows(10, :) == 60.0_wp), "status 0, 60 periods")
      do k = 1, 6
         call pendulum_from_chart(rows(1, k), rows(2, k), 0.0_wp, 0.2_wp, 9.81_wp, p, error)
         call lyapunov_largest(p, pendulum_initial_state(p, 0.017_wp), 60, 1.0e-10_wp, reference, error)
         call check(ctx, rows(3, k), reference%exponent, rel=1.0e-9_wp, abs=1.0e-12_wp)
         call check(ctx, rows(4, k), reference%spread, rel=1.0e-2_wp, abs=1.0e-12_wp)
         call check(ctx, rows(8, k), reference%max_abs_phi, rel=1.0e-5_wp)
         call check(ctx, abs(rows(7, k) - log(rows(6, k))) < 1.0e-8_wp*max(1.0_wp, rows(7, k)), &
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
            call check(ctx, rows(5, k) == core(4, k), "stable as the chart")
            call check(ctx, rows(6, k), core(5, k), rel=1.0e-9_wp)
         end do
         call delete_file(chart_written)
      end if
      ! case (g) is chaotic, case (c) regular
      call check(ctx, rows(3, 6) > 0.1_wp .and. rows(3, 1) < 0.1_wp, "(7.48, 2.47) above (2.57, 1.29)")
      call delete_file(scratch_prefix("lyap_core")//".dat")
      call delete_file(written)
   end subroutine grid_layout_and_values

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
      call rows_of(grid, 11, a, na, columns)
      call rows_of(list, 11, b, nb, columns)
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
      call check(ctx, .not. file_exists(scratch_prefix("lyap_bad")//"_lyapunov.dat"), "no file")
   end subroutine bad_input
end module test_task_lyapunov

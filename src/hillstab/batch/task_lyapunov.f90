!> Task `lyapunov`: the largest Lyapunov exponent of the nonlinear pendulum
!> (hillstab_pendulum_lyapunov) over the (α, β) grid of `&chart` or at the points of `&points`
!> (`&lyapunov over`), each point started as `&series` says (φ0, velocities, r0, g) and
!> integrated for `&series periods` radial periods at the `&scene tolerance`. Beside the
!> exponent: its error indication, the chart's linear verdict at the point (the core's
!> stable, λ_max and ln λ_max by the `&scene method`), the largest |φ| reached and the
!> energy drift. One line per point, blocks of constant α separated by a blank line
!> (a grid), or in the points' order.
!>
!> Points are independent: the serial task computes them in parallel (OpenMP, dynamic
!> schedule: chaotic and near-π² points cost more) in units of consecutive points and
!> writes the units in order; the MPI program (hillstab_batch_units) computes the same units
!> on several ranks with `lyapunov_lines` and writes the same file.
module hillstab_batch_task_lyapunov
   use hillstab_core_kinds, only: wp, int64, version_string
   use hillstab_core_error, only: error_t, set_error, err_accuracy, err_points_failed
   use hillstab_core_status, only: status_ok, status_roundoff, status_failed
   use hillstab_hill_coefficient, only: hill_model_t, model_elastic
   use hillstab_hill_transfer, only: trace_t
   use hillstab_hill_floquet, only: floquet_t, floquet_from_trace, largest_multiplier_modulus
   use hillstab_integrate_monodromy, only: monodromy_trace, method_name
   use hillstab_pendulum_equations, only: pendulum_t, pendulum_from_chart, pendulum_initial_state
   use hillstab_pendulum_lyapunov, only: lyapunov_t, lyapunov_largest
   use hillstab_batch_scene, only: scene_t, scene_header, grid_point, real_text, integer_text, output_path
   use hillstab_batch_output, only: output_file_t, open_output, finish_output, write_header, write_text, joined_lines
   use hillstab_core_text, only: put_es, put_integer
   use, intrinsic :: iso_fortran_env, only: error_unit
   implicit none
   private
   public :: run_lyapunov, lyapunov_header, lyapunov_columns, lyapunov_lines, lyapunov_point_count, &
      lyapunov_point, lyapunov_line_length, lyapunov_failure_error, lyapunov_unit_size

   !> Characters in one line of the file.
   integer, parameter :: lyapunov_line_length = 240
   !> Points per unit of work in the serial task (written as one block).
   integer, parameter :: lyapunov_unit_size = 64

contains

   !> Column names of `<output>_lyapunov.dat`.
   pure function lyapunov_columns() result(names)
      character(len=:), allocatable :: names
      names = "alpha beta lyapunov spread stable lambda_max log_lambda_max max_abs_phi energy_drift periods status"
   end function lyapunov_columns

   !> Number of points of the scene (grid or list).
   pure integer(int64) function lyapunov_point_count(scene) result(n)
      type(scene_t), intent(in) :: scene  !! a lyapunov scene
      if (scene%lyapunov_points) then
         n = size(scene%points, 2)
      else
         n = int(scene%chart%n_alpha, int64)*scene%chart%n_beta
      end if
   end function lyapunov_point_count

   !> (α, β) of point k (a grid numbered row by row, α outer), and whether it starts a new
   !> α block after the first (a blank line goes before it).
   pure subroutine lyapunov_point(scene, k, alpha, beta, new_block)
      type(scene_t), intent(in) :: scene  !! a lyapunov scene
      integer(int64), intent(in) :: k     !! point index, 1 … lyapunov_point_count(scene)
      real(wp), intent(out) :: alpha      !! α of the point
      real(wp), intent(out) :: beta       !! β of the point
      logical, intent(out) :: new_block   !! a blank line goes before it
      real(wp) :: point(2)
      if (scene%lyapunov_points) then
         alpha = scene%points(1, k)
         beta = scene%points(2, k)
         new_block = .false.
      else
         point = grid_point(scene%chart, k)
         alpha = point(1)
         beta = point(2)
         ! the first β of a row after the first row
         new_block = mod(k - 1, int(scene%chart%n_beta, int64)) == 0 .and. k > scene%chart%n_beta
      end if
   end subroutine lyapunov_point

   !> Header lines: version, the effective scene, what the columns mean.
   function lyapunov_header(scene) result(lines)
      type(scene_t), intent(in) :: scene  !! a lyapunov scene
      character(len=:), allocatable :: lines(:)
      character(len=240) :: text(16)
      integer :: n
      n = 0
      n = n + 1; text(n) = "each point: the pendulum at (alpha, beta) with r0, g of &series, started at phi0 (eq. (38)), "// &
         integer_text(scene%series%periods)//" radial periods by DOP853 at tolerance "// &
         real_text(scene%method%tolerance)
      n = n + 1; text(n) = "lyapunov: largest Lyapunov exponent per radial period (Benettin: one tangent vector, "// &
         "renormalised every period)"
      n = n + 1; text(n) = "spread: max - min of the running estimate over the last half of the periods "// &
         "(error indication; a regular orbit decays like ln n/n)"
      n = n + 1; text(n) = "stable, lambda_max: the chart's linear verdict for the swing about the bounce (method "// &
         method_name(scene%method%kind)//"; stable 0.5: marginal, as in charts), log_lambda_max = ln(lambda_max) per "// &
         "radial period (compare lyapunov)"
      n = n + 1; text(n) = "max_abs_phi: largest |phi| [rad] at the integrator's steps; energy_drift: |E(end) - E(0)| "// &
         "over the sum of the energy terms' magnitudes"
      n = n + 1; text(n) = "status: 0 ok; 1 the chart's value only round-off limited; 2 failed (lyapunov = 0, spread = "// &
         "-1, stable = -1, lambda_max = -1, log_lambda_max = 0, max_abs_phi = -1, energy_drift = -1: placeholders)"
      n = n + 1; text(n) = "periods: radial periods integrated (fewer than asked only on a failed point)"
      if (scene%epsilon > 0.0_wp) then
         n = n + 1; text(n) = "damping epsilon = "//real_text(scene%epsilon)//": stable is |S1| < 2 cosh(epsilon), "// &
            "lambda_max includes exp(-epsilon)"
      end if
      lines = scene_header(scene, "hillstab "//version_string//": largest Lyapunov exponent of the nonlinear "// &
                           "elastic pendulum", text(:n))
   end function lyapunov_header

   !> The line of one point and its status.
   subroutine lyapunov_point_line(scene, alpha, beta, line, status)
      type(scene_t), intent(in) :: scene
      real(wp), intent(in) :: alpha, beta
      character(len=lyapunov_line_length), intent(out) :: line
      integer, intent(out) :: status
      type(pendulum_t) :: p
      type(lyapunov_t) :: result
      type(error_t), allocatable :: error
      type(trace_t) :: tr
      type(floquet_t) :: f
      real(wp) :: lambda_max
      integer :: pos, stable
      status = status_ok
      call pendulum_from_chart(alpha, beta, scene%epsilon, scene%series%r0, scene%series%g, p, error)
      if (.not. allocated(error)) then
         call lyapunov_largest(p, pendulum_initial_state(p, scene%series%phi0, scene%series%vx0, scene%series%vz0), &
            scene%series%periods, scene%method%tolerance, result, error)
      end if
      if (allocated(error)) then
         status = status_failed
         line = failed_line(alpha, beta, result%periods)
         return
      end if
      call monodromy_trace(hill_model_t(model_elastic, alpha, beta, scene%epsilon), scene%method, tr, error)
      if (allocated(error)) then
         if (error%code /= err_accuracy) then
            status = status_failed
            line = failed_line(alpha, beta, result%periods)
            return
         end if
         status = status_roundoff
      end if
      f = floquet_from_trace(tr, scene%epsilon)
      lambda_max = min(largest_multiplier_modulus(f), 1.0e300_wp)
      stable = merge(1, 0, f%stable)
      pos = 0
      call put_es(line, pos, alpha, 16)
      call blank()
      call put_es(line, pos, beta, 16)
      call blank()
      call put_es(line, pos, result%exponent, 10)
      call blank()
      call put_es(line, pos, result%spread, 3)
      if (f%marginal) then
         ! |S| within its error bound of the threshold: as the chart writes it
         line(pos + 1:pos + 4) = " 0.5"
         pos = pos + 4
      else
         line(pos + 1:pos + 2) = " "//achar(iachar("0") + stable)
         pos = pos + 2
      end if
      call blank()
      call put_es(line, pos, lambda_max, 10)
      call blank()
      call put_es(line, pos, f%exponent*2.0_wp + 0.0_wp, 10)
      call blank()
      call put_es(line, pos, result%max_abs_phi, 6)
      call blank()
      call put_es(line, pos, result%energy_drift, 3)
      ! put_integer, not integer_text: this runs in the parallel loop (see put_integer)
      call blank()
      call put_integer(line, pos, result%periods)
      line(pos + 1:) = " "//achar(iachar("0") + status)
   contains
      subroutine blank()
         line(pos + 1:pos + 1) = " "
         pos = pos + 1
      end subroutine blank
   end subroutine lyapunov_point_line

   !> Placeholder line of a failed point (values outside every column's range).
   function failed_line(alpha, beta, periods) result(line)
      real(wp), intent(in) :: alpha, beta
      integer, intent(in) :: periods  !! periods integrated before the failure
      character(len=lyapunov_line_length) :: line
      character(len=*), parameter :: placeholders = " 0 -1 -1 -1 0 -1 -1 "
      integer :: pos
      pos = 0
      call put_es(line, pos, alpha, 16)
      line(pos + 1:pos + 1) = " "
      pos = pos + 1
      call put_es(line, pos, beta, 16)
      line(pos + 1:pos + len(placeholders)) = placeholders
      pos = pos + len(placeholders)
      call put_integer(line, pos, periods)  ! not integer_text: runs in the parallel loop
      line(pos + 1:) = " "//achar(iachar("0") + status_failed)
   end function failed_line

   !> Lines and statuses of the points first … last (in parallel), and the text the file
   !> holds for them: the lines joined, a blank line before each new α block.
   subroutine lyapunov_lines(scene, first, last, text, statuses)
      type(scene_t), intent(in) :: scene  !! a lyapunov scene
      integer(int64), intent(in) :: first, last  !! range of point indices
      character(len=:), allocatable, intent(out) :: text  !! without the final new line
      integer, intent(out) :: statuses(first:last)       !! per point
      character(len=lyapunov_line_length), allocatable :: lines(:)
      logical, allocatable :: new_block(:)
      real(wp) :: alpha, beta
      integer(int64) :: k
      allocate (lines(first:last), new_block(first:last))
      !$omp parallel do schedule(dynamic) default(shared) private(k, alpha, beta)
      do k = first, last
         call lyapunov_point(scene, k, alpha, beta, new_block(k))
         call lyapunov_point_line(scene, alpha, beta, lines(k), statuses(k))
      end do
      !$omp end parallel do
      text = joined_lines(lines, .false., new_block)
   end subroutine lyapunov_lines

   !> err_points_failed naming the first failed point, after the file has been written.
   subroutine lyapunov_failure_error(scene, n_failed, first, error)
      type(scene_t), intent(in) :: scene  !! a lyapunov scene
      integer(int64), intent(in) :: n_failed  !! failed points written
      real(wp), intent(in) :: first(2)  !! α, β of the first failed point
      type(error_t), allocatable, intent(out) :: error  !! err_points_failed when n_failed > 0
      if (n_failed == 0) return
      call set_error(error, err_points_failed, scene%source//": &series: the pendulum could not be integrated at "// &
         integer_text(n_failed)//" of "//integer_text(lyapunov_point_count(scene))//" point(s), written with "// &
         "status 2 and placeholders to "//output_path(scene)// &
         "; first at alpha = "//real_text(first(1))//", beta = "//real_text(first(2)))
   end subroutine lyapunov_failure_error

   !> The lyapunov task, in this process: units of `lyapunov_unit_size` points computed
   !> in parallel and written in order.
   subroutine run_lyapunov(scene, quiet, error)
      type(scene_t), intent(in) :: scene  !! a validated lyapunov scene
      logical, intent(in) :: quiet  !! no progress on stderr
      !> err_io (unwritable output), err_points_failed (written, some points failed)
      type(error_t), allocatable, intent(out) :: error
      type(output_file_t) :: file
      character(len=:), allocatable :: text
      integer, allocatable :: statuses(:)
      integer(int64) :: n, first, last, n_failed, j
      real(wp) :: first_failed(2), alpha, beta
      logical :: new_block
      integer(int64) :: clock_start, clock_now, ticks
      n = lyapunov_point_count(scene)
      call open_output(file, output_path(scene), error, context=scene%source//": &scene: output: ")
      if (allocated(error)) return
      call write_header(file, lyapunov_header(scene), lyapunov_columns(), error)
      n_failed = 0
      call system_clock(clock_start, ticks)
      first = 1
      do while (first <= n .and. .not. allocated(error))
         last = min(n, first + lyapunov_unit_size - 1)
         allocate (statuses(first:last))
         call lyapunov_lines(scene, first, last, text, statuses)
         call write_text(file, text, error)
         if (any(statuses == status_failed)) then
            j = first + findloc(statuses, status_failed, dim=1) - 1
            if (n_failed == 0) then
               call lyapunov_point(scene, j, alpha, beta, new_block)
               first_failed = [alpha, beta]
            end if
            n_failed = n_failed + count(statuses == status_failed)
         end if
         deallocate (statuses)
         if (.not. quiet) then
            call system_clock(clock_now)
            if (real(clock_now - clock_start, wp)/ticks > 5.0_wp .and. last < n) then
               write (error_unit, '(a,i0,a,i0,a)') "hillstab: lyapunov: ", last, " of ", n, " points"
               clock_start = clock_now
            end if
         end if
         first = last + 1
      end do
      call finish_output(file, error)
      if (allocated(error)) return
      call lyapunov_failure_error(scene, n_failed, first_failed, error)
   end subroutine run_lyapunov
end module hillstab_batch_task_lyapunov

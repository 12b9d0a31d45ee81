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
   use hillstab_core_kinds, only: wp, int64, pi2, version_string
   use hillstab_core_error, only: error_t, set_error, err_accuracy, err_points_failed
   use hillstab_core_status, only: status_ok, status_roundoff, status_failed
   use hillstab_core_text, only: real_text, integer_text
   use hillstab_hill_models, only: hill_model_t
   use hillstab_hill_transfer, only: trace_t
   use hillstab_hill_floquet, only: floquet_t, floquet_from_trace, largest_multiplier_modulus
   use hillstab_integrate_monodromy, only: monodromy_trace, method_name
   use hillstab_pendulum_equations, only: pendulum_t, pendulum_from_chart, pendulum_initial_state
   use hillstab_pendulum_lyapunov, only: lyapunov_t, lyapunov_largest
   use hillstab_batch_scene, only: scene_t, task_t, scene_header, output_path, open_scene_output
   use hillstab_batch_scene_file, only: scene_file_t, fail
   use hillstab_batch_scene_checks, only: min_pendulum_beta
   use hillstab_batch_declaration, only: new_group, group_t, group_reader_t, variable, var_name, begin_group, next_item, end_group
   use hillstab_batch_group_chart, only: chart_grid_t, chart_group, read_chart_group, grid_point
   use hillstab_batch_group_points, only: points_group, read_points_group
   use hillstab_batch_group_series, only: series_plan_t, series_group, read_series_group
   use hillstab_batch_columns, only: column_t, style_e17, style_e11, style_e7, style_e4, style_flag, style_integer, &
      columns_text, put_row, all_columns, failed_row
   use hillstab_batch_chart_columns, only: header_bytes, text_row_bytes
   use hillstab_batch_output, only: output_file_t, finish_output, write_header, write_text, joined_lines
   use hillstab_batch_progress, only: progress_t, progress_begin, progress_update, progress_end
   implicit none
   private
   public :: lyapunov_task_t, lyapunov_task, lyapunov_group

   !> Characters in one line of the file.
   integer, parameter :: lyapunov_line_length = 240
   !> Points per unit of work in the serial task (written as one block).
   integer, parameter :: lyapunov_unit_size = 64
   !> The columns, by index.
   integer, parameter :: col_alpha = 1, col_beta = 2, col_lyapunov = 3, col_spread = 4, col_stable = 5, &
      col_lambda_max = 6, col_log_lambda_max = 7, col_max_abs_phi = 8, col_energy_drift = 9, col_periods = 10, &
      col_status = 11, n_columns = 11

   !> The lyapunov task: the pendulum of `&series` over a grid or a list of points.
   type, extends(task_t) :: lyapunov_task_t
      type(series_plan_t) :: series           !! the pendulum's start, r0, g and periods
      logical :: over_points = .false.        !! over `&points` instead of `&chart`
      type(chart_grid_t) :: grid              !! `&chart`
      character(len=:), allocatable :: file   !! `&points file`
      real(wp), allocatable :: points(:, :)   !! (2, n) α, β of `&points`
      type(column_t), allocatable :: table(:)  !! the columns of the file
   contains
      procedure :: read => lyapunov_read
      procedure :: run => lyapunov_run
      procedure :: declarations => lyapunov_declarations
      procedure :: template_alternatives => lyapunov_template_alternatives
      procedure :: estimated_bytes => lyapunov_estimated_bytes
      procedure :: size_variables => lyapunov_size_variables
      procedure :: point_count => lyapunov_point_count
      procedure :: unit_size => lyapunov_unit_size_of
      procedure :: unit_text => lyapunov_unit_text
      procedure :: open_units => lyapunov_open_units
      procedure :: finish_units => lyapunov_finish_units
      procedure :: point_of => lyapunov_point_of
   end type lyapunov_task_t

contains

   !> `&series`, `&lyapunov`, `&chart` (the physical domain).
   function lyapunov_declarations(self) result(groups)
      class(lyapunov_task_t), intent(in) :: self  !! the task
      type(group_t), allocatable :: groups(:)
      allocate (groups(3))
      groups(1) = series_group()
      groups(2) = lyapunov_group()
      groups(3) = lyapunov_chart_group()
   end function lyapunov_declarations

   !> `&points`, the alternative to `&chart` with over = 'points'.
   subroutine lyapunov_template_alternatives(self, groups, notes)
      class(lyapunov_task_t), intent(in) :: self  !! the task
      type(group_t), allocatable, intent(out) :: groups(:)  !! the groups, commented out in templates
      character(len=80), allocatable, intent(out) :: notes(:)  !! one comment line per group
      allocate (groups(1), notes(1))
      groups(1) = points_group()
      groups(1)%variables(1)%help = "one 'alpha beta' pair per line, 0 < beta < pi^2"
      notes(1) = "with over = 'points': the points of a file instead of the grid"
   end subroutine lyapunov_template_alternatives

   !> The variables that set the size of the file.
   function lyapunov_size_variables(self) result(text)
      class(lyapunov_task_t), intent(in) :: self  !! the task
      character(len=:), allocatable :: text
      text = "&chart: n_alpha, n_beta: "//integer_text(self%grid%n_alpha)//" x "//integer_text(self%grid%n_beta)// &
             " points"
   end function lyapunov_size_variables

   !> A lyapunov task before its scene is read.
   function lyapunov_task() result(task)
      type(lyapunov_task_t) :: task
      task%name = "lyapunov"
      task%takes_physical = .false.
   end function lyapunov_task

   !> The declaration of `&lyapunov`.
   function lyapunov_group() result(group)
      type(group_t) :: group
      group = new_group("lyapunov", "what the map runs over")
      call group%add("over", var_name, "'chart'", "chart: the grid of &chart (0 < beta < pi^2) | points: the points "// &
         ""// &
         "of &points")
   end function lyapunov_group

   !> The default grid of the task: the physical domain 0 <= alpha < pi^2, 0 < beta < pi^2
   !> (the pendulum exists only there), 100 x 100.
   function lyapunov_chart_group() result(group)
      type(group_t) :: group
      group = chart_group()
      group = group%with_default("n_alpha", "100")
      group = group%with_default("beta_min", "0.1")
      group = group%with_default("beta_max", "9.8")
      group = group%with_default("n_beta", "100")
   end function lyapunov_chart_group

   !> `&series`, `&lyapunov` (optional), then `&chart` or `&points`.
   subroutine lyapunov_read(self, file, scene, error)
      class(lyapunov_task_t), intent(inout) :: self  !! the task, its groups filled in
      type(scene_file_t), intent(in) :: file      !! the scene file
      type(scene_t), intent(in) :: scene          !! the `&scene` settings
      type(error_t), allocatable, intent(out) :: error  !! err_input naming file, group and variable
      type(group_t) :: group
      character(len=65536) :: over
      namelist /lyapunov/ over
      type(group_reader_t) :: reader
      allocate (self%groups(3))
      call read_series_group(file, series_group(), scene%model, scene%physical, self%series, self%groups(1), error)
      if (allocated(error)) return
      group = lyapunov_group()
      call begin_group(reader, file, group, optional=.true.)
      read (reader%defaults, nml=lyapunov, iostat=reader%defaults_status, iomsg=reader%defaults_msg)
      if (reader%from_file) read (file%unit, nml=lyapunov, iostat=reader%ios, iomsg=reader%msg)
      do while (next_item(reader, file, group))
         read (reader%record, nml=lyapunov, iostat=reader%stat, iomsg=reader%message)
      end do
      write (reader%echo, nml=lyapunov, delim="apostrophe", iostat=reader%echo_status)
      call end_group(reader, file, group, self%groups(2), error)
      if (allocated(error)) return
      select case (self%groups(2)%text("over"))
      case ("'chart'"); self%over_points = .false.
      case ("'points'"); self%over_points = .true.
      case default
         call fail(error, file%path, group%name, "over", "unknown value '"//trim(over)//"' (expected chart or points)")
         return
      end select
      if (self%over_points) then
         call read_points_group(file, points_group(), scene%model, self%file, self%points, self%groups(3), error)
      else
         call read_chart_group(file, lyapunov_chart_group(), scene%model, self%grid, self%groups(3), error)
      end if
      if (allocated(error)) return
      call check_lyapunov_domain(self, file%path, error)
      self%table = lyapunov_columns()
   end subroutine lyapunov_read

   !> The lyapunov task integrates the pendulum: every point must lie in the physical
   !> domain 0 <= alpha < pi^2, 0 < beta < pi^2.
   subroutine check_lyapunov_domain(self, source, error)
      class(lyapunov_task_t), intent(in) :: self
      character(len=*), intent(in) :: source
      type(error_t), allocatable, intent(out) :: error
      character(len=*), parameter :: why = " (the lyapunov task simulates the pendulum: 0 < beta < pi**2 = "
      integer :: k
      if (self%over_points) then
         do k = 1, size(self%points, 2)
            if (self%points(2, k) <= 0.0_wp .or. self%points(2, k) >= pi2) then
               call fail(error, source, "points", "file", "point "//integer_text(k)//" of "// &
                  self%file//" has beta = "//real_text(self%points(2, k))//" outside the physical domain"// &
                  why//real_text(pi2)//")")
               return
            end if
            if (self%points(2, k) < min_pendulum_beta) then
               call fail(error, source, "points", "file", "point "//integer_text(k)//" of "// &
                  self%file//" has beta = "//real_text(self%points(2, k))//", below "// &
                  real_text(min_pendulum_beta)//" (smaller values make the pendulum's time scales overflow)")
               return
            end if
         end do
      else if (self%grid%beta_min <= 0.0_wp) then
         call fail(error, source, "chart", "beta_min", "must be > 0"//why//real_text(pi2)//"), got "// &
            real_text(self%grid%beta_min))
      else if (self%grid%beta_min < min_pendulum_beta) then
         call fail(error, source, "chart", "beta_min", "must be >= "//real_text(min_pendulum_beta)// &
            " (smaller values make the pendulum's time scales overflow), got "//real_text(self%grid%beta_min))
      else if (self%grid%beta_max >= pi2) then
         call fail(error, source, "chart", "beta_max", "must be < pi**2"//why//real_text(pi2)//"), got "// &
            real_text(self%grid%beta_max))
      end if
   end subroutine check_lyapunov_domain

   !> The columns of `<output>_lyapunov.dat`.
   function lyapunov_columns() result(table)
      type(column_t) :: table(n_columns)
      table(col_alpha) = column_t("alpha", "", "alpha of the point", style_e17, 0.0_wp, .true.)
      table(col_beta) = column_t("beta", "", "beta of the point", style_e17, 0.0_wp, .true.)
      table(col_lyapunov) = column_t("lyapunov", "", "largest Lyapunov exponent per radial period (Benettin: one "// &
         "tangent vector, renormalised every period)", style_e11, 0.0_wp)
      table(col_spread) = column_t("spread", "", "max - min of the running estimate over the last half of the "// &
         "periods (error indication; a regular orbit decays like ln n/n)", style_e4, -1.0_wp)
      table(col_stable) = column_t("stable", "", "the chart's linear verdict for the swing about the bounce "// &
         "(0.5: marginal, as in charts)", style_flag, -1.0_wp)
      table(col_lambda_max) = column_t("lambda_max", "", "largest |multiplier| of the linearised swing per radial "// &
         "period", style_e11, -1.0_wp)
      table(col_log_lambda_max) = column_t("log_lambda_max", "", "ln(lambda_max) per radial period (compare "// &
         "lyapunov)", style_e11, 0.0_wp)
      table(col_max_abs_phi) = column_t("max_abs_phi", "rad", "largest |phi| at the integrator's steps", style_e7, &
         -1.0_wp)
      table(col_energy_drift) = column_t("energy_drift", "", "|E(end) - E(0)| over the sum of the energy terms' "// &
         "magnitudes", style_e4, -1.0_wp)
      table(col_periods) = column_t("periods", "", "radial periods integrated (fewer than asked only on a failed "// &
         "point)", style_integer, 0.0_wp, .true.)
      table(col_status) = column_t("status", "", "0 ok; 1 the chart's value only round-off limited; 2 failed "// &
         "(placeholders)", style_flag, real(status_failed, wp))
   end function lyapunov_columns

   !> As a chart of the same grid (or points).
   pure function lyapunov_estimated_bytes(self, scene) result(bytes)
      class(lyapunov_task_t), intent(in) :: self  !! the task
      type(scene_t), intent(in) :: scene  !! its scene
      integer(int64) :: bytes
      if (self%over_points) then
         bytes = 0
      else
         bytes = header_bytes + int(self%grid%n_alpha, int64)*int(self%grid%n_beta, int64)*text_row_bytes + &
                 int(self%grid%n_alpha, int64)
      end if
   end function lyapunov_estimated_bytes

   !> Number of points of the scene (grid or list).
   pure function lyapunov_point_count(self) result(n)
      class(lyapunov_task_t), intent(in) :: self  !! the task
      integer(int64) :: n
      if (self%over_points) then
         n = size(self%points, 2)
      else
         n = int(self%grid%n_alpha, int64)*self%grid%n_beta
      end if
   end function lyapunov_point_count

   !> A point is hundreds of radial periods (~10 ms to 1 s): small units balance well.
   pure integer function lyapunov_unit_size_of(self, n_workers) result(size)
      class(lyapunov_task_t), intent(in) :: self  !! the task
      integer, intent(in) :: n_workers   !! processes computing units
      size = int(max(1_int64, min(16_int64, self%point_count()/(32*max(1, n_workers)))))
   end function lyapunov_unit_size_of

   !> (α, β) of point k.
   pure function lyapunov_point_of(self, k) result(point)
      class(lyapunov_task_t), intent(in) :: self  !! the task
      integer(int64), intent(in) :: k  !! the point
      real(wp) :: point(2)
      if (self%over_points) then
         point = self%points(:, k)
      else
         point = grid_point(self%grid, k)
      end if
   end function lyapunov_point_of

   !> Whether point k starts a new α block after the first (a blank line goes before it).
   pure logical function new_block(self, k)
      class(lyapunov_task_t), intent(in) :: self
      integer(int64), intent(in) :: k
      new_block = .false.
      if (self%over_points) return
      new_block = mod(k - 1, int(self%grid%n_beta, int64)) == 0 .and. k > self%grid%n_beta
   end function new_block

   !> Header lines: version, the effective scene, what the columns mean.
   function lyapunov_header(self, scene) result(lines)
      class(lyapunov_task_t), intent(in) :: self  !! the task
      type(scene_t), intent(in) :: scene  !! its scene
      character(len=:), allocatable :: lines(:)
      character(len=240) :: text(16)
      integer :: n
      n = 0
      n = n + 1; text(n) = "each point: the pendulum at (alpha, beta) with r0, g of &series, started at phi0 (eq. (38)), "// &
         integer_text(self%series%periods)//" radial periods by DOP853 at tolerance "// &
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
   subroutine lyapunov_point_line(self, scene, alpha, beta, line, status)
      class(lyapunov_task_t), intent(in) :: self
      type(scene_t), intent(in) :: scene
      real(wp), intent(in) :: alpha, beta
      character(len=lyapunov_line_length), intent(out) :: line
      integer, intent(out) :: status
      type(pendulum_t) :: p
      type(lyapunov_t) :: result
      type(error_t), allocatable :: error
      type(trace_t) :: tr
      type(floquet_t) :: f
      real(wp) :: v(n_columns)
      integer :: pos
      status = status_ok
      v = 0.0_wp
      v(col_alpha) = alpha
      v(col_beta) = beta
      call pendulum_from_chart(alpha, beta, scene%epsilon, self%series%r0, self%series%g, p, error)
      if (.not. allocated(error)) then
         call lyapunov_largest(p, pendulum_initial_state(p, self%series%phi0, self%series%vx0, self%series%vz0), &
            self%series%periods, scene%method%tolerance, result, error)
      end if
      if (.not. allocated(error)) then
         call monodromy_trace(hill_model_t(scene%model, alpha, beta, scene%epsilon), scene%method, tr, error)
         if (allocated(error)) then
            if (error%code == err_accuracy) then
               deallocate (error)
               status = status_roundoff
            end if
         end if
      end if
      v(col_periods) = real(result%periods, wp)
      if (allocated(error)) then
         status = status_failed
         call failed_row(self%table, v)
      else
         f = floquet_from_trace(tr, scene%epsilon)
         v(col_lyapunov) = result%exponent
         v(col_spread) = result%spread
         v(col_stable) = merge(1.0_wp, 0.0_wp, f%stable)
         ! |S| within its error bound of the threshold: as the chart writes it
         if (f%marginal) v(col_stable) = 0.5_wp
         v(col_lambda_max) = min(largest_multiplier_modulus(f), 1.0e300_wp)
         v(col_log_lambda_max) = f%exponent*2.0_wp + 0.0_wp
         v(col_max_abs_phi) = result%max_abs_phi
         v(col_energy_drift) = result%energy_drift
         v(col_status) = real(status, wp)
      end if
      pos = 0
      call put_row(self%table, all_columns(self%table), v, line, pos)
      line(pos + 1:) = ""
   end subroutine lyapunov_point_line

   !> Lines and statuses of the points first … last (in parallel), and the text the file
   !> holds for them: the lines joined, a blank line before each new α block.
   subroutine lyapunov_lines(self, scene, first, last, text, statuses)
      class(lyapunov_task_t), intent(in) :: self  !! the task
      type(scene_t), intent(in) :: scene  !! its scene
      integer(int64), intent(in) :: first, last  !! range of point indices
      character(len=:), allocatable, intent(out) :: text  !! without the final new line
      integer, intent(out) :: statuses(first:last)       !! per point
      character(len=lyapunov_line_length), allocatable :: lines(:)
      logical, allocatable :: breaks(:)
      real(wp) :: point(2)
      integer(int64) :: k
      allocate (lines(first:last), breaks(first:last))
      !$omp parallel do schedule(dynamic) default(shared) private(k, point)
      do k = first, last
         point = self%point_of(k)
         breaks(k) = new_block(self, k)
         call lyapunov_point_line(self, scene, point(1), point(2), lines(k), statuses(k))
      end do
      !$omp end parallel do
      text = joined_lines(lines, .false., breaks)
   end subroutine lyapunov_lines

   !> err_points_failed naming the first failed point, after the file has been written.
   subroutine lyapunov_failure_error(self, scene, n_failed, first, error)
      class(lyapunov_task_t), intent(in) :: self  !! the task
      type(scene_t), intent(in) :: scene  !! its scene
      integer(int64), intent(in) :: n_failed  !! failed points written
      real(wp), intent(in) :: first(2)  !! α, β of the first failed point
      type(error_t), allocatable, intent(out) :: error  !! err_points_failed when n_failed > 0
      if (n_failed == 0) return
      call set_error(error, err_points_failed, scene%source//": &series: the pendulum could not be integrated at "// &
         integer_text(n_failed)//" of "//integer_text(self%point_count())//" point(s), written with "// &
         "status 2 and placeholders to "//output_path(scene)// &
         "; first at alpha = "//real_text(first(1))//", beta = "//real_text(first(2)))
   end subroutine lyapunov_failure_error

   !> The lyapunov task, in this process: units of `lyapunov_unit_size` points computed
   !> in parallel and written in order.
   subroutine lyapunov_run(self, scene, quiet, error)
      class(lyapunov_task_t), intent(in) :: self  !! the task
      type(scene_t), intent(in) :: scene  !! a validated lyapunov scene
      logical, intent(in) :: quiet  !! no progress on stderr
      !> err_io (unwritable output), err_points_failed (written, some points failed)
      type(error_t), allocatable, intent(out) :: error
      type(output_file_t) :: file
      character(len=:), allocatable :: text
      integer, allocatable :: statuses(:)
      integer(int64) :: n, first, last, n_failed, j
      real(wp) :: first_failed(2)
      type(progress_t) :: progress
      n = self%point_count()
      call open_scene_output(scene, file, error)
      if (allocated(error)) return
      call write_header(file, lyapunov_header(self, scene), columns_text(self%table, all_columns(self%table)), error)
      n_failed = 0
      call progress_begin(progress, n, quiet)
      first = 1
      do while (first <= n .and. .not. allocated(error))
         last = min(n, first + lyapunov_unit_size - 1)
         allocate (statuses(first:last))
         call lyapunov_lines(self, scene, first, last, text, statuses)
         call write_text(file, text, error)
         if (any(statuses == status_failed)) then
            j = first + findloc(statuses, status_failed, dim=1) - 1
            if (n_failed == 0) then
               first_failed = self%point_of(j)
            end if
            n_failed = n_failed + count(statuses == status_failed)
         end if
         deallocate (statuses)
         call progress_update(progress, last)
         first = last + 1
      end do
      call progress_end(progress)
      call finish_output(file, error)
      if (allocated(error)) return
      call lyapunov_failure_error(self, scene, n_failed, first_failed, error)
   end subroutine lyapunov_run

   !> The lines of the points `first` … `last`, as `lyapunov_run` writes them.
   subroutine lyapunov_unit_text(self, scene, unit, first, last, text, statuses)
      class(lyapunov_task_t), intent(in) :: self  !! the task
      type(scene_t), intent(in) :: scene  !! its scene
      integer, intent(in) :: unit  !! the unit
      integer(int64), intent(in) :: first, last  !! its points
      character(len=:), allocatable, intent(out) :: text  !! the lines, no final new line
      integer, intent(out) :: statuses(first:last)  !! per point
      call lyapunov_lines(self, scene, first, last, text, statuses)
   end subroutine lyapunov_unit_text

   !> The header of `lyapunov_run`.
   subroutine lyapunov_open_units(self, scene, file, error)
      class(lyapunov_task_t), intent(in) :: self  !! the task
      type(scene_t), intent(in) :: scene  !! its scene
      type(output_file_t), intent(inout) :: file  !! the open output file
      type(error_t), allocatable, intent(out) :: error  !! why the file cannot be written
      call write_header(file, lyapunov_header(self, scene), columns_text(self%table, all_columns(self%table)), error)
   end subroutine lyapunov_open_units

   !> As after `lyapunov_run`: the error naming the first failed point.
   subroutine lyapunov_finish_units(self, scene, n_points, n_failed, first_failed, n_inaccurate, first_inaccurate, error)
      class(lyapunov_task_t), intent(in) :: self  !! the task
      type(scene_t), intent(in) :: scene  !! its scene
      integer(int64), intent(in) :: n_points  !! all points
      integer(int64), intent(in) :: n_failed  !! failed points written
      real(wp), intent(in) :: first_failed(2)  !! (α, β) of the first of them
      integer(int64), intent(in) :: n_inaccurate  !! round-off limited points written
      real(wp), intent(in) :: first_inaccurate(2)  !! (α, β) of the first of them
      type(error_t), allocatable, intent(out) :: error  !! err_points_failed when points failed
      call lyapunov_failure_error(self, scene, n_failed, first_failed, error)
   end subroutine lyapunov_finish_units
end module hillstab_batch_task_lyapunov

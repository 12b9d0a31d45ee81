!> Task `lyapunov`: chaos indicators of the nonlinear pendulum (hillstab_pendulum_chaos)
!> over the (α, β) grid of `&chart` or at the points of `&points` (`&lyapunov over`), each
!> point started as `&series` says (φ0, velocities, r0, g) and integrated for up to
!> `&series periods` radial periods: the finite-time Lyapunov exponent and its spread,
!> MEGNO, the FLI and the verdict (chaotic 1, regular 0, undecided 0.5), by the integrator
!> of `&lyapunov` (auto: a symplectic tangent map where it holds the energy tolerance,
!> DOP853 at the `&scene tolerance` otherwise and with damping); a point stops as soon as
!> its verdict is certain unless `early_stop = .false.`. Beside them: the chart's linear
!> verdict at the point (the core's stable, λ_max and ln λ_max by the `&scene method`), the
!> largest |φ| reached and the energy errors. One line per point, blocks of constant α
!> separated by a blank line (a grid), or in the points' order.
!>
!> Points are independent: the task runs in units of whole batches of `lanes` consecutive
!> points advanced together (`lyapunov_lines`, the batches of a unit in parallel, dynamic
!> schedule), which the unit driver (hillstab_batch_run_units) computes on OpenMP threads
!> or over MPI ranks and writes in order into the same file. Batches start at fixed point indices (1, 1 + lanes, …), so that a point's
!> companions, and its line, do not depend on how the units are cut.
module hillstab_batch_tasks_lyapunov
   use hillstab_core_kinds, only: wp, int64, pi, pi2, version_string
   use hillstab_core_error, only: error_t, set_error, err_accuracy, err_points_failed
   use hillstab_core_status, only: status_ok, status_roundoff, status_failed
   use hillstab_core_text, only: real_text, integer_text, lower_case
   use hillstab_hill_model, only: hill_point_t
   use hillstab_hill_transfer, only: trace_t
   use hillstab_hill_floquet, only: floquet_t, floquet_from_trace, largest_multiplier_modulus
   use hillstab_integrate_monodromy, only: monodromy_trace, method_name
   use hillstab_pendulum_equations, only: pendulum_t, pendulum_from_chart, pendulum_initial_state
   use hillstab_pendulum_symplectic, only: symplectic_scheme_id, symplectic_scheme_name, symplectic_scheme_count
   use hillstab_pendulum_chaos, only: chaos_options_t, chaos_t, chaos_indicators_batch, chaos_integrator_id, &
      chaos_integrator_name, chaos_method_text, chaos_verdict_rule, chaos_symplectic
   use hillstab_batch_scene_types, only: scene_t, task_t, scene_header, output_path
   use hillstab_batch_scene_physical, only: physical_summary, pendulum_task_t
   use hillstab_batch_scene_file, only: scene_file_t, fail, group_present, read_len
   use hillstab_hill_units, only: physical_t, physical_alpha, physical_beta, physical_epsilon
   use hillstab_batch_scene_checks, only: min_pendulum_beta
   use hillstab_batch_scene_declaration, only: new_group, group_t, group_values_t, group_reader_t, var_name, &
      var_integer, var_real, var_logical, begin_group, next_item, end_group
   use hillstab_batch_scene_group_chart, only: chart_grid_t, chart_group, read_chart_group, grid_point, grid_size_text
   use hillstab_batch_scene_group_points, only: points_group, read_points_group
   use hillstab_batch_scene_group_series, only: series_plan_t, series_group, read_series_group, start_angle_text
   use hillstab_batch_output_columns, only: column_t, style_e17, style_e11, style_e7, style_e4, style_flag, &
      style_integer, columns_text, put_row, failed_row
   use hillstab_batch_tasks_chart_columns, only: header_bytes, text_row_bytes
   use hillstab_batch_output_file, only: output_file_t, write_header, join_lines
   use hillstab_core_parallel, only: max_threads
   implicit none
   private
   public :: lyapunov_task_t, lyapunov_task, lyapunov_group

   !> Characters in one line of the file.
   integer, parameter :: lyapunov_line_length = 320
   !> Most lanes a scene may ask for.
   integer, parameter :: max_lanes = 256
   !> The columns, by index.
   integer, parameter :: col_alpha = 1, col_beta = 2, col_lyapunov = 3, col_spread = 4, col_stable = 5, &
      col_lambda_max = 6, col_log_lambda_max = 7, col_max_abs_phi = 8, col_energy_drift = 9, col_chaotic = 10, &
      col_megno = 11, col_fli = 12, col_energy_error = 13, col_integrator = 14, col_periods = 15, col_status = 16, &
      col_a = 17, col_omega = 18, col_lyapunov_per_s = 19, col_lyapunov_error = 20, n_columns = 20
   !> The columns of a file over (α, β), and over the amplitudes and frequencies of
   !> `&physical` (a, ω and the exponent per second beside α, β and the exponent).
   integer, parameter :: chart_ids(17) = [col_alpha, col_beta, col_lyapunov, col_spread, col_lyapunov_error, &
      col_stable, col_lambda_max, col_log_lambda_max, col_max_abs_phi, col_energy_drift, col_chaotic, col_megno, &
      col_fli, col_energy_error, col_integrator, col_periods, col_status]
   integer, parameter :: physical_ids(20) = [col_alpha, col_beta, col_a, col_omega, col_lyapunov, &
      col_lyapunov_per_s, col_spread, col_lyapunov_error, col_stable, col_lambda_max, col_log_lambda_max, &
      col_max_abs_phi, col_energy_drift, col_chaotic, col_megno, col_fli, col_energy_error, col_integrator, col_periods, &
      col_status]

   !> The lyapunov task: the pendulum of `&series` over a grid or a list of points.
   type, extends(pendulum_task_t) :: lyapunov_task_t
      type(series_plan_t) :: series           !! the pendulum's start, r0, g and periods
      logical :: over_points = .false.        !! over `&points` instead of `&chart`
      type(chart_grid_t) :: grid              !! `&chart`
      character(len=:), allocatable :: file   !! `&points file`
      real(wp), allocatable :: points(:, :)   !! (2, n) α, β of `&points`
      type(column_t), allocatable :: table(:)  !! the columns of the file
      type(chaos_options_t) :: chaos          !! integrator and indicators of `&lyapunov`
      !> over the amplitudes (and frequencies) of `&physical`: a grid of n_a x n_omega
      !> points in blocks of constant a, or the amplitudes at one omega
      logical :: over_physical = .false.
      type(physical_t) :: spring              !! `&physical` r0, g, kappa (a, omega per point)
      real(wp), allocatable :: amplitudes(:)  !! a [m]
      real(wp), allocatable :: omegas(:)      !! omega [rad/s] (one value without a range)
      integer, allocatable :: ids(:)          !! the columns written
   contains
      procedure :: read => lyapunov_read
      procedure :: declarations => lyapunov_declarations
      procedure :: template_alternatives => lyapunov_template_alternatives
      procedure :: estimated_bytes => lyapunov_estimated_bytes
      procedure :: size_variables => lyapunov_size_variables
      procedure :: memory_bytes => lyapunov_memory_bytes
      procedure :: memory_variables => lyapunov_memory_variables
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
      text = grid_size_text(self%grid, self%over_physical)
   end function lyapunov_size_variables

   !> An upper estimate of the memory of a run by the unit driver (hillstab_batch_run_units
   !> `run_batch`: 16 units a thread held for writing, one a thread at work): each unit's
   !> lines and their joined text, and each lane's orbit at work.
   function lyapunov_memory_bytes(self, scene) result(bytes)
      class(lyapunov_task_t), intent(in) :: self  !! the task
      type(scene_t), intent(in) :: scene  !! its scene
      integer(int64) :: bytes
      integer(int64) :: units, points
      units = 17*int(max_threads(), int64)
      points = min(self%point_count(), units*self%unit_size(1))
      bytes = points*(2*lyapunov_line_length + 8) + int(max_threads(), int64)*self%chaos%lanes*4096
   end function lyapunov_memory_bytes

   !> What sets the memory of a run: the points (a unit is up to 16 batches of lanes) and the lanes.
   function lyapunov_memory_variables(self) result(text)
      class(lyapunov_task_t), intent(in) :: self  !! the task
      character(len=:), allocatable :: text
      text = self%size_variables()//" and &lyapunov: lanes: "//integer_text(self%chaos%lanes)
   end function lyapunov_memory_variables

   !> A lyapunov task before its scene is read.
   function lyapunov_task() result(task)
      type(lyapunov_task_t) :: task
      task%name = "lyapunov"
      task%physical_use%takes_amplitudes = .true.
      task%physical_use%takes_omega_range = .true.
      task%physical_use%amplitudes_replace = "&chart (or &points), and r0, g from &series"
   end function lyapunov_task

   !> The declaration of `&lyapunov`.
   function lyapunov_group() result(group)
      type(group_t) :: group
      type(chaos_options_t) :: defaults
      group = new_group("lyapunov", "what the map runs over, the integrator and the chaos indicators")
      call group%add("over", var_name, "'chart'", "chart: the grid of &chart (0 < beta < pi^2) | points: the points "// &
         "of &points")
      call group%add("integrator", var_name, "'"//chaos_integrator_name(defaults%integrator)//"'", "auto: "// &
         "symplectic where it holds energy_tolerance, else DOP853 | symplectic (undamped only) | dop853")
      call group%add("scheme", var_name, "'"//symplectic_scheme_name(defaults%scheme)//"'", "symplectic scheme: "// &
         "leapfrog | yoshida4 | yoshida6 | blanes_moan4 | blanes_moan6 | mclachlan8")
      call group%add("steps_per_period", var_integer, integer_text(defaults%steps_per_period), "symplectic steps "// &
         "per radial period, >= 4; 0: from each orbit's closest pass to the pivot")
      call group%add("energy_tolerance", var_real, real_text(defaults%energy_tolerance), "largest relative energy "// &
         "error of a symplectic run, in (0, 0.1]; beyond it the steps double, then (auto) DOP853")
      call group%add("early_stop", var_logical, ".true.", "stop a point as soon as its verdict is certain")
      call group%add("megno_chaotic", var_real, real_text(defaults%megno_chaotic), "MEGNO above this at the "// &
         "end: chaotic (1)")
      call group%add("megno_regular", var_real, real_text(defaults%megno_regular), "MEGNO below this at the "// &
         "end: regular (0); between the two: undecided (0.5)")
      call group%add("megno_stop", var_real, real_text(defaults%megno_stop), "early stop as chaotic once MEGNO "// &
         "exceeds this plus the start's transient allowance, >= megno_chaotic")
      call group%add("min_periods", var_integer, integer_text(defaults%min_periods), "no early stop before this "// &
         "many radial periods, >= 1")
      call group%add("lanes", var_integer, integer_text(defaults%lanes), "points advanced together, 1 ... "// &
         integer_text(max_lanes))
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
      character(len=read_len) :: over, integrator, scheme
      integer :: steps_per_period, min_periods, lanes
      real(wp) :: energy_tolerance, megno_chaotic, megno_regular, megno_stop
      logical :: early_stop
      namelist /lyapunov/ over, integrator, scheme, steps_per_period, energy_tolerance, early_stop, megno_chaotic, &
         megno_regular, megno_stop, min_periods, lanes
      type(group_reader_t) :: reader
      type(group_values_t), allocatable :: kept(:)
      character(len=*), parameter :: spring_variables(4) = ["alpha", "beta ", "r0   ", "g    "]
      integer :: j
      allocate (self%groups(3))
      ! with &physical the spring comes from there: &series gives the start and the periods
      call read_series_group(file, series_group(), scene%model, self%series, self%groups(1), error, &
         samples=.false., warnings=self%warnings)
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
      call chaos_settings(error)
      if (allocated(error)) return
      self%table = lyapunov_columns()
      self%ids = chart_ids
      if (self%physical%given) then
         call physical_settings(error)
         if (allocated(error)) return
         self%ids = physical_ids
         ! the effective scene: &series without the spring, &lyapunov without over, no
         ! &chart or &points (given back as a scene, the file repeats its run)
         do j = 1, size(spring_variables)
            call self%groups(1)%hide(trim(spring_variables(j)))
         end do
         call self%groups(2)%hide("over")
         allocate (kept(2))
         kept(1) = self%groups(1)
         kept(2) = self%groups(2)
         call move_alloc(kept, self%groups)
         return
      end if
      if (self%over_points) then
         call read_points_group(file, points_group(), scene%model, self%file, self%points, self%groups(3), error)
      else
         call read_chart_group(file, lyapunov_chart_group(), scene%model, self%grid, self%groups(3), error)
      end if
      if (allocated(error)) return
      call check_lyapunov_domain(self, file%path, error)
   contains
      !> Over `&physical`: the amplitudes (and frequencies), r0, g, kappa from there; `&series`
      !> gives the start and the periods only; no `&chart` or `&points`.
      subroutine physical_settings(error)
         type(error_t), allocatable, intent(out) :: error
         integer :: j
         real(wp) :: beta_low
         ! (alpha and beta of &series are unused by this task in any case)
         do j = 3, size(spring_variables)
            if (self%groups(1)%given(trim(spring_variables(j)))) then
               call fail(error, file%path, "series", trim(spring_variables(j)), "with &physical the points come "// &
                  "from its amplitudes and frequencies and r0, g from &physical: leave "//trim(spring_variables(j))// &
                  " out of &series")
               return
            end if
         end do
         if (self%over_points) then
            call fail(error, file%path, "lyapunov", "over", "with &physical the map runs over its amplitudes "// &
               "(and frequencies), not over &points: leave over = 'points' out")
            return
         end if
         if (group_present(file%unit, "chart") .or. group_present(file%unit, "points")) then
            call fail(error, file%path, trim(merge("chart ", "points", group_present(file%unit, "chart"))), "alpha_min", &
               "the map runs either over &physical (a, omega) or over &chart / &points, not both")
            if (.not. group_present(file%unit, "chart")) error%message = file%path//": &points: file: the map "// &
               "runs either over &physical (a, omega) or over &chart / &points, not both"
            return
         end if
         if (size(self%physical%amplitudes) == 0) then
            call fail(error, file%path, "physical", "a_min", "the map over &physical needs the amplitudes: "// &
               "a_min, a_max, n_a (or the list a) with r0")
            return
         end if
         self%over_physical = .true.
         self%spring = self%physical%pendulum
         self%amplitudes = self%physical%amplitudes
         if (size(self%physical%omegas) > 0) then
            self%omegas = self%physical%omegas
         else
            self%omegas = [self%physical%pendulum%omega]
         end if
         self%over_points = .false.
         self%grid%n_alpha = size(self%amplitudes)
         self%grid%n_beta = size(self%omegas)
         ! beta = g pi^2/(rho omega^2) falls with omega: its smallest value at the largest omega
         beta_low = huge(1.0_wp)
         do j = 1, size(self%omegas)
            self%spring%omega = self%omegas(j)
            beta_low = min(beta_low, physical_beta(self%spring))
         end do
         self%spring%omega = self%omegas(1)
         if (beta_low < min_pendulum_beta) then
            call fail(error, file%path, "physical", trim(merge("omega_max", "omega    ", size(self%physical%omegas) > 0)), &
               "gives beta = "//real_text(beta_low)//", below "//real_text(min_pendulum_beta)// &
               " (the pendulum's time scales overflow there)")
         end if
      end subroutine physical_settings

      !> The options of hillstab_pendulum_chaos from the group, checked.
      subroutine chaos_settings(error)
         type(error_t), allocatable, intent(out) :: error
         self%chaos%integrator = chaos_integrator_id(lower_case(trim(adjustl(integrator))))
         self%chaos%scheme = symplectic_scheme_id(lower_case(trim(adjustl(scheme))))
         if (self%chaos%integrator < 0) then
            call fail(error, file%path, group%name, "integrator", "unknown value '"//trim(integrator)// &
               "' (expected auto, symplectic or dop853)")
         else if (self%chaos%scheme < 1 .or. self%chaos%scheme > symplectic_scheme_count) then
            call fail(error, file%path, group%name, "scheme", "unknown value '"//trim(scheme)// &
               "' (expected leapfrog, yoshida4, yoshida6, blanes_moan4, blanes_moan6 or mclachlan8)")
         else if (self%chaos%integrator == chaos_symplectic .and. scene%epsilon > 0.0_wp) then
            call fail(error, file%path, group%name, "integrator", "'symplectic' needs an undamped pendulum, but "// &
               "&scene epsilon = "//real_text(scene%epsilon)//" (use auto or dop853)")
         else if (steps_per_period /= 0 .and. (steps_per_period < 4 .or. steps_per_period > 1000000)) then
            call fail(error, file%path, group%name, "steps_per_period", "must be 0 or lie in [4, 1e6], got "// &
               integer_text(steps_per_period))
         else if (.not. (energy_tolerance > 0.0_wp .and. energy_tolerance <= 0.1_wp)) then
            call fail(error, file%path, group%name, "energy_tolerance", "must lie in (0, 0.1], got "// &
               real_text(energy_tolerance))
         else if (.not. (megno_regular > 0.0_wp .and. megno_regular < 1.0e6_wp)) then
            call fail(error, file%path, group%name, "megno_regular", "must lie in (0, 1e6), got "// &
               real_text(megno_regular))
         else if (.not. (megno_chaotic >= megno_regular .and. megno_chaotic < 1.0e6_wp)) then
            call fail(error, file%path, group%name, "megno_chaotic", "must lie in [megno_regular = "// &
               real_text(megno_regular)//", 1e6), got "//real_text(megno_chaotic))
         else if (.not. (megno_stop >= megno_chaotic .and. megno_stop < 1.0e6_wp)) then
            call fail(error, file%path, group%name, "megno_stop", "must lie in [megno_chaotic = "// &
               real_text(megno_chaotic)//", 1e6), got "//real_text(megno_stop))
         else if (min_periods < 1) then
            call fail(error, file%path, group%name, "min_periods", "must be >= 1, got "//integer_text(min_periods))
         else if (lanes < 1 .or. lanes > max_lanes) then
            call fail(error, file%path, group%name, "lanes", "must lie in [1, "//integer_text(max_lanes)// &
               "], got "//integer_text(lanes))
         end if
         if (allocated(error)) return
         self%chaos%steps_per_period = steps_per_period
         self%chaos%energy_tolerance = energy_tolerance
         self%chaos%early_stop = early_stop
         self%chaos%megno_chaotic = megno_chaotic
         self%chaos%megno_regular = megno_regular
         self%chaos%megno_stop = megno_stop
         self%chaos%min_periods = min_periods
         self%chaos%lanes = lanes
      end subroutine chaos_settings
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
      table(col_lyapunov) = column_t("lyapunov", "", "finite-time largest Lyapunov exponent per radial period "// &
         "over the periods integrated (Benettin: one tangent vector, renormalised every period)", style_e11, 0.0_wp)
      table(col_spread) = column_t("spread", "", "max - min of the running estimate over the last half of the "// &
         "periods (how far it still moves, not an error bar; a regular orbit decays like ln n/n)", style_e4, -1.0_wp)
      table(col_lyapunov_error) = column_t("lyapunov_error", "", "error bar of lyapunov: 95% half-width by batch "// &
         "means of the per-period growths (min(5, periods) batches, Student's t); covers the scatter of runs from "// &
         "starts 1e-12 apart", style_e4, -1.0_wp)
      table(col_stable) = column_t("stable", "", "the chart's linear verdict for the swing about the bounce "// &
         "(0.5: marginal, as in charts)", style_flag, -1.0_wp)
      table(col_lambda_max) = column_t("lambda_max", "", "largest |multiplier| of the linearised swing per radial "// &
         "period", style_e11, -1.0_wp)
      table(col_log_lambda_max) = column_t("log_lambda_max", "", "ln(lambda_max) per radial period (compare "// &
         "lyapunov)", style_e11, 0.0_wp)
      table(col_max_abs_phi) = column_t("max_abs_phi", "rad", "largest |phi| at the integrator's steps", style_e7, &
         -1.0_wp)
      table(col_energy_drift) = column_t("energy_drift", "", "|E(end) - E(0)| over the sum of the energy terms' "// &
         "magnitudes at the start", style_e4, -1.0_wp)
      table(col_chaotic) = column_t("chaotic", "", "verdict: 1 chaotic, 0 regular, 0.5 undecided (the rule in "// &
         "the header)", style_flag, -1.0_wp)
      table(col_megno) = column_t("megno", "", "MEGNO <Y> at the end: -> 2 on quasi-periodic orbits, -> 0 on "// &
         "stable periodic ones, ~ lyapunov t/2 on chaotic ones (t in radial periods)", style_e7, 0.0_wp)
      table(col_fli) = column_t("fli", "", "fast Lyapunov indicator: largest ln|delta| at the period ends, "// &
         "|delta(0)| = 1", style_e7, 0.0_wp)
      table(col_energy_error) = column_t("energy_error", "", "largest |E - E(0)| at the integrator's steps, on "// &
         "the scale of energy_drift", style_e4, -1.0_wp)
      table(col_integrator) = column_t("integrator", "", "the integrator that ran: 1 symplectic tangent map, "// &
         "2 DOP853", style_integer, 0.0_wp)
      table(col_periods) = column_t("periods", "", "radial periods integrated (fewer than asked when the "// &
         "verdict was certain early, or on a failed point)", style_integer, 0.0_wp, .true.)
      table(col_status) = column_t("status", "", "0 ok; 1 the chart's value only round-off limited; 2 failed "// &
         "(placeholders)", style_flag, real(status_failed, wp))
      table(col_a) = column_t("a", "m", "bounce amplitude of &physical (alpha = a pi^2/rho)", style_e17, 0.0_wp, &
         .true.)
      table(col_omega) = column_t("omega", "rad/s", "radial angular frequency of &physical (beta = g pi^2/(rho "// &
         "omega^2))", style_e17, 0.0_wp, .true.)
      table(col_lyapunov_per_s) = column_t("lyapunov_per_s", "1/s", "lyapunov per second: lyapunov omega/(2 pi)", &
         style_e11, 0.0_wp)
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

   !> A point is up to thousands of radial periods (~1 ms to 1 s; points whose verdict is
   !> certain early cost far less): units of whole batches of lanes, 1 to 16 batches, about
   !> 8 units per worker at least.
   pure integer function lyapunov_unit_size_of(self, n_workers) result(size)
      class(lyapunov_task_t), intent(in) :: self  !! the task
      integer, intent(in) :: n_workers   !! processes computing units
      integer(int64) :: batches
      batches = (self%point_count() + self%chaos%lanes - 1)/self%chaos%lanes
      size = self%chaos%lanes*int(max(1_int64, min(16_int64, batches/(8*max(1, n_workers)))))
   end function lyapunov_unit_size_of

   !> (α, β) of point k.
   pure function lyapunov_point_of(self, scene, k) result(point)
      class(lyapunov_task_t), intent(in) :: self  !! the task
      type(scene_t), intent(in) :: scene  !! its scene
      integer(int64), intent(in) :: k  !! the point
      real(wp) :: point(2)
      type(physical_t) :: p
      if (self%over_physical) then
         p = spring_at(self, k)
         point = [physical_alpha(p), physical_beta(p)]
      else if (self%over_points) then
         point = self%points(:, k)
      else
         point = grid_point(self%grid, k)
      end if
   end function lyapunov_point_of

   !> The spring of point k of a map over `&physical`: a of its block, omega within it.
   pure function spring_at(self, k) result(p)
      class(lyapunov_task_t), intent(in) :: self
      integer(int64), intent(in) :: k
      type(physical_t) :: p
      integer(int64) :: n_omega
      n_omega = size(self%omegas, kind=int64)
      p = self%spring
      p%a = self%amplitudes((k - 1)/n_omega + 1)
      p%omega = self%omegas(mod(k - 1, n_omega) + 1)
   end function spring_at

   !> Whether point k starts a new α block after the first (a blank line goes before it).
   pure logical function new_block(self, k)
      class(lyapunov_task_t), intent(in) :: self
      integer(int64), intent(in) :: k
      new_block = .false.
      if (self%over_points) return
      ! amplitudes at one omega: a list, not a grid
      if (self%over_physical) then
         if (size(self%omegas) == 1) return
      end if
      new_block = mod(k - 1, int(self%grid%n_beta, int64)) == 0 .and. k > self%grid%n_beta
   end function new_block

   !> Header lines: version, the effective scene, the integrator, the verdict's rule, what
   !> the columns mean.
   function lyapunov_header(self, scene) result(lines)
      class(lyapunov_task_t), intent(in) :: self  !! the task
      type(scene_t), intent(in) :: scene  !! its scene
      character(len=:), allocatable :: lines(:)
      character(len=400) :: text(26)
      character(len=:), allocatable :: spring(:)
      integer :: n, j
      n = 0
      if (self%over_physical) then
         n = n + 1; text(n) = "each point: the spring of &physical at its amplitude a and frequency omega (alpha = a "// &
            "pi^2/rho, beta = g pi^2/(rho omega^2), epsilon = kappa pi/omega), started at phi0 of &series (eq. (38)) "// &
            "= "//start_angle_text(self%series%phi0)//", "//integer_text(self%series%periods)//" radial periods"
      else
         n = n + 1; text(n) = "each point: the pendulum at (alpha, beta) with r0, g of &series, started at phi0 "// &
            "(eq. (38)) = "//start_angle_text(self%series%phi0)//", "//integer_text(self%series%periods)// &
            " radial periods"
      end if
      if (self%chaos%early_stop) text(n) = trim(text(n))//" at most, stopped as soon as the verdict is certain"
      n = n + 1; text(n) = chaos_method_text(self%chaos, scene%method%tolerance)
      n = n + 1; text(n) = chaos_verdict_rule(self%chaos)
      n = n + 1; text(n) = "lyapunov: finite-time largest Lyapunov exponent per radial period (Benettin: one tangent "// &
         "vector, renormalised every period)"
      n = n + 1; text(n) = "spread: max - min of the running estimate over the last half of the periods "// &
         "(how far it still moves; not an error bar)"
      n = n + 1; text(n) = "lyapunov_error: 95% half-width of lyapunov by batch means: the periods' growths "// &
         "ln(|delta(k)|/|delta(k-1)|) in B = min(5, periods) consecutive batches, the standard error of their "// &
         "mean times Student's t (B - 1)"
      n = n + 1; text(n) = "lyapunov_error covers the scatter of lyapunov between runs from starts 1e-12 apart "// &
         "(chaotic orbits), is ~ sqrt(B) t/periods on regular ones and wider on points stopped early (fewer periods)"
      n = n + 1; text(n) = "megno: MEGNO <Y> -> 2 quasi-periodic, -> 0 stable periodic, ~ lyapunov t/2 chaotic; fli: "// &
         "largest ln|delta| at the period ends (|delta(0)| = 1)"
      n = n + 1; text(n) = "stable, lambda_max: the chart's linear verdict for the swing about the bounce (method "// &
         method_name(scene%method%kind)//"; stable 0.5: marginal, as in charts), log_lambda_max = ln(lambda_max) per "// &
         "radial period (compare lyapunov)"
      n = n + 1; text(n) = "max_abs_phi: largest |phi| [rad] at the integrator's steps; energy_drift, energy_error: "// &
         "|E - E(0)| at the end, largest at the steps, over the energy terms' magnitudes at t = 0"
      n = n + 1; text(n) = "integrator: 1 symplectic tangent map, 2 DOP853; periods: radial periods integrated (fewer "// &
         "than asked when the verdict was certain early)"
      n = n + 1; text(n) = "status: 0 ok; 1 the chart's value only round-off limited; 2 failed (placeholders, below)"
      n = n + 1; text(n) = "failed rows: "//placeholders_text(self%table, self%ids)
      if (self%over_physical) then
         spring = physical_summary(self%physical, scene%epsilon)
         do j = 1, size(spring)
            n = n + 1; text(n) = spring(j)
         end do
         n = n + 1; text(n) = "a [m], omega [rad/s]: the point's spring; lyapunov_per_s [1/s] = lyapunov omega/(2 pi), "// &
            "the exponent per second"
      end if
      if (scene%epsilon > 0.0_wp) then
         n = n + 1; text(n) = "damping epsilon = "//real_text(scene%epsilon)//": stable is |S1| < 2 cosh(epsilon), "// &
            "lambda_max includes exp(-epsilon); DOP853 at every point; energy_drift is the energy lost"
      end if
      lines = scene_header(scene, "hillstab "//version_string//": chaos indicators of the nonlinear "// &
                           "elastic pendulum", text(:n))
   end function lyapunov_header

   !> "lyapunov = 0, spread = -1, ...": the placeholders of a failed row, in the columns' styles.
   function placeholders_text(table, ids) result(text)
      type(column_t), intent(in) :: table(:)
      integer, intent(in) :: ids(:)  !! the columns written
      character(len=:), allocatable :: text
      character(len=48) :: field
      integer :: i, k, pos
      text = ""
      do i = 1, size(ids)
         k = ids(i)
         if (table(k)%keep_on_failure .or. k == col_status) cycle
         pos = 0
         call put_row(table(k:k), [1], [table(k)%placeholder], field, pos)
         if (len(text) > 0) text = text//", "
         text = text//table(k)%name//" = "//trim(adjustl(field(:pos)))
      end do
   end function placeholders_text

   !> The lines and statuses of the points lo … hi, one batch: the orbits advanced together
   !> by chaos_indicators_batch, then each point's linear verdict.
   subroutine lyapunov_batch(self, scene, lo, hi, lines, statuses)
      class(lyapunov_task_t), intent(in) :: self
      type(scene_t), intent(in) :: scene
      integer(int64), intent(in) :: lo, hi
      character(len=lyapunov_line_length), intent(out) :: lines(lo:hi)
      integer, intent(out) :: statuses(lo:hi)
      type(pendulum_t) :: pendula(hi - lo + 1)
      real(wp) :: y0(4, hi - lo + 1), point(2, hi - lo + 1)
      type(chaos_t), allocatable :: results(:)
      integer :: slot(hi - lo + 1)
      real(wp) :: epsilons(hi - lo + 1)
      type(physical_t) :: spring
      type(error_t), allocatable :: error
      integer :: m, j
      integer(int64) :: k
      m = 0
      do k = lo, hi
         j = int(k - lo) + 1
         point(:, j) = self%point_of(scene, k)
         slot(j) = 0
         if (self%over_physical) then
            spring = spring_at(self, k)
            epsilons(j) = physical_epsilon(spring)
            call pendulum_from_chart(point(1, j), point(2, j), epsilons(j), spring%r0, spring%g, pendula(m + 1), error)
         else
            epsilons(j) = scene%epsilon
            call pendulum_from_chart(point(1, j), point(2, j), scene%epsilon, self%series%r0, self%series%g, &
               pendula(m + 1), error)
         end if
         if (allocated(error)) then
            deallocate (error)
            cycle
         end if
         m = m + 1
         slot(j) = m
         y0(:, m) = pendulum_initial_state(pendula(m), self%series%phi0, self%series%vx0, self%series%vz0)
      end do
      allocate (results(m))
      if (m > 0) call chaos_indicators_batch(pendula(:m), y0(:, :m), self%series%periods, scene%method%tolerance, &
                                             self%chaos, results)
      do k = lo, hi
         j = int(k - lo) + 1
         if (self%over_physical) then
            spring = spring_at(self, k)
         else
            spring = physical_t()
         end if
         if (slot(j) == 0) then
            call point_line(self, scene, point(:, j), epsilons(j), spring, chaos_t(), .false., lines(k), statuses(k))
         else
            call point_line(self, scene, point(:, j), epsilons(j), spring, results(slot(j)), .true., lines(k), &
               statuses(k))
         end if
      end do
   end subroutine lyapunov_batch

   !> The line of one point from its orbit's indicators (`integrated` false: the pendulum
   !> could not be set up), with the chart's linear verdict; its status.
   subroutine point_line(self, scene, point, epsilon, spring, result, integrated, line, status)
      class(lyapunov_task_t), intent(in) :: self
      type(scene_t), intent(in) :: scene
      real(wp), intent(in) :: point(2)
      real(wp), intent(in) :: epsilon  !! the point's damping
      type(physical_t), intent(in) :: spring  !! over `&physical`: the point's a and omega
      type(chaos_t), intent(in) :: result
      logical, intent(in) :: integrated
      character(len=lyapunov_line_length), intent(out) :: line
      integer, intent(out) :: status
      type(error_t), allocatable :: error
      type(trace_t) :: tr
      type(floquet_t) :: f
      real(wp) :: v(n_columns)
      integer :: pos
      logical :: failed
      status = status_ok
      v = 0.0_wp
      v(col_alpha) = point(1)
      v(col_beta) = point(2)
      failed = .not. integrated
      if (.not. failed) failed = allocated(result%error)
      if (.not. failed) then
         call monodromy_trace(scene%model, hill_point_t(point(1), point(2), epsilon), scene%method, tr, error)
         if (allocated(error)) then
            if (error%code == err_accuracy) then
               deallocate (error)
               status = status_roundoff
            else
               failed = .true.
            end if
         end if
      end if
      v(col_periods) = real(result%periods, wp)
      v(col_a) = spring%a
      v(col_omega) = spring%omega
      if (failed) then
         status = status_failed
         call failed_row(self%table, v)
      else
         f = floquet_from_trace(tr, epsilon)
         v(col_lyapunov) = result%lyapunov
         v(col_lyapunov_per_s) = result%lyapunov*spring%omega/(2.0_wp*pi)
         v(col_spread) = result%spread
         v(col_lyapunov_error) = result%lyapunov_error
         v(col_stable) = merge(1.0_wp, 0.0_wp, f%stable)
         ! |S| within its error bound of the threshold: as the chart writes it
         if (f%marginal) v(col_stable) = 0.5_wp
         v(col_lambda_max) = min(largest_multiplier_modulus(f), 1.0e300_wp)
         v(col_log_lambda_max) = f%exponent*2.0_wp + 0.0_wp
         v(col_max_abs_phi) = result%max_abs_phi
         v(col_energy_drift) = result%energy_drift
         v(col_chaotic) = result%chaotic
         v(col_megno) = result%megno
         v(col_fli) = result%fli
         v(col_energy_error) = result%energy_error
         v(col_integrator) = real(merge(1, 2, result%integrator == chaos_symplectic), wp)
         v(col_status) = real(status, wp)
      end if
      pos = 0
      call put_row(self%table, self%ids, v, line, pos)
      line(pos + 1:) = ""
   end subroutine point_line

   !> Lines and statuses of the points first … last, and the text the file holds for them:
   !> the lines joined, a blank line before each new α block. The points go in batches of
   !> `lanes` that start at fixed indices (1, 1 + lanes, …), the batches in parallel.
   subroutine lyapunov_lines(self, scene, first, last, text, statuses)
      class(lyapunov_task_t), intent(in) :: self  !! the task
      type(scene_t), intent(in) :: scene  !! its scene
      integer(int64), intent(in) :: first, last  !! range of point indices
      character(len=:), allocatable, intent(out) :: text  !! without the final new line
      integer, intent(out) :: statuses(first:last)       !! per point
      character(len=lyapunov_line_length), allocatable :: lines(:)
      logical, allocatable :: breaks(:)
      integer(int64) :: k, b, lanes, lo, hi
      allocate (lines(first:last), breaks(first:last))
      lanes = self%chaos%lanes
      do k = first, last
         breaks(k) = new_block(self, k)
      end do
      !$omp parallel do schedule(dynamic) default(shared) private(b, lo, hi)
      do b = (first - 1)/lanes, (last - 1)/lanes
         lo = max(first, b*lanes + 1)
         hi = min(last, (b + 1)*lanes)
         call lyapunov_batch(self, scene, lo, hi, lines(lo:hi), statuses(lo:hi))
      end do
      !$omp end parallel do
      call join_lines(lines, .false., text, breaks)
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

   !> The lines of the points `first` … `last`, as the file holds them (the unit driver,
   !> hillstab_batch_run_units, writes them in order, on threads or over MPI ranks).
   subroutine lyapunov_unit_text(self, scene, unit, first, last, text, statuses)
      class(lyapunov_task_t), intent(in) :: self  !! the task
      type(scene_t), intent(in) :: scene  !! its scene
      integer, intent(in) :: unit  !! the unit
      integer(int64), intent(in) :: first, last  !! its points
      character(len=:), allocatable, intent(out) :: text  !! the lines, no final new line
      integer, intent(out) :: statuses(first:last)  !! per point
      call lyapunov_lines(self, scene, first, last, text, statuses)
   end subroutine lyapunov_unit_text

   !> The header of a lyapunov file.
   subroutine lyapunov_open_units(self, scene, file, error)
      class(lyapunov_task_t), intent(in) :: self  !! the task
      type(scene_t), intent(in) :: scene  !! its scene
      type(output_file_t), intent(inout) :: file  !! the open output file
      type(error_t), allocatable, intent(out) :: error  !! why the file cannot be written
      call write_header(file, lyapunov_header(self, scene), columns_text(self%table, self%ids), error)
   end subroutine lyapunov_open_units

   !> After the units: the error naming the first failed point.
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
end module hillstab_batch_tasks_lyapunov

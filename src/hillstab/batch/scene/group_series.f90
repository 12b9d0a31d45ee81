!> The `&series` group: the nonlinear pendulum at (α, β) with its natural length and
!> gravity, its start (eq. (38) plus optional velocities) and the sampling. Read by the
!> series, lyapunov and poincare tasks.
!>
!>```fortran
!> type(series_plan_t) :: plan
!> plan = series_plan_t(1.48_wp, 2.47_wp, 0.017_wp, 50, 100, 0.1_wp, 9.81_wp, 0.0_wp, 0.0_wp)
!>```
module hillstab_batch_scene_group_series
   use hillstab_core_kinds, only: wp, int64, pi, pi2
   use hillstab_core_error, only: error_t
   use hillstab_core_text, only: real_text, integer_text
   use hillstab_hill_model, only: hill_model_t
   use hillstab_hill_model_pendulum, only: is_elastic_pendulum
   use hillstab_batch_scene_file, only: scene_file_t, fail
   use hillstab_batch_scene_declaration, only: new_group, group_t, group_values_t, group_reader_t, variable, var_real, &
      var_integer, &
      begin_group, next_item, end_group
   use hillstab_batch_scene_checks, only: require_finite, min_pendulum_beta, longest_spring, slowest_omega
   use hillstab_batch_scene_types, only: add_warning
   implicit none
   private
   public :: series_plan_t, series_group, read_series_group, max_series_lines, start_angle_text

   !> A series scene writing more data lines than this is refused.
   integer(int64), parameter :: max_series_lines = 100000000_int64

   !> The pendulum of `&series`: (α, β) from eq. (38), sampled `samples_per_period` times
   !> per radial period.
   type :: series_plan_t
      real(wp) :: alpha = 0.0_wp             !! α, in [0, π²)
      real(wp) :: beta = 0.0_wp              !! β, in (0, π²)
      real(wp) :: phi0 = 0.0_wp              !! initial angle [rad]
      integer :: periods = 1                 !! radial periods to simulate (with `duration`: 0)
      integer :: samples_per_period = 1      !! output rows per radial period
      real(wp) :: r0 = 0.0_wp                !! natural length [m]
      real(wp) :: g = 0.0_wp                 !! gravity [m/s²]
      real(wp) :: vx0 = 0.0_wp               !! initial horizontal velocity [m/s]
      real(wp) :: vz0 = 0.0_wp               !! initial downward velocity [m/s]
      !> the length of the run in seconds (`&series duration`); 0 when given as `periods`
      real(wp) :: duration = 0.0_wp
   end type series_plan_t

contains

   !> The declaration of `&series` (defaults: the paper's Fig. 4 (a)).
   function series_group() result(group)
      type(group_t) :: group
      group = new_group("series", "the nonlinear pendulum and its start (eq. (38))")
      call group%add("alpha", var_real, "1.48", "alpha = a pi^2/rho, 0 <= alpha < pi^2")
      call group%add("beta", var_real, "2.47", "beta = g pi^2/(rho omega^2), 0 < beta < pi^2 (physical domain)")
      call group%add("phi0", var_real, "0.017", "initial angle from the downward vertical, rad (0: pure bounce)")
      call group%add("phi0_degrees", var_real, "", "instead of phi0, the initial angle in degrees", example="1.0")
      call group%add("periods", var_integer, "50", "radial periods T = 2 pi/omega to simulate, >= 1")
      call group%add("duration", var_real, "", "series: instead of periods, the length of the run in seconds "// &
         "(> 0; rows at t = j T/samples_per_period <= duration)", example="30.0")
      call group%add("samples_per_period", var_integer, "100", "output rows per radial period, >= 1; "// &
         "periods*samples_per_period + 1 <= 1e8")
      call group%add("r0", var_real, "0.1", "natural length of the spring, m; > 0")
      call group%add("g", var_real, "9.81", "gravity, m/s^2; > 0")
      call group%add("vx0", var_real, "0.0", "initial horizontal velocity, m/s")
      call group%add("vz0", var_real, "0.0", "initial downward velocity, m/s")
   end function series_group

   !> Read and check `&series`. The pendulum is the elastic one given in dimensionless
   !> units here, so a scene of another model is refused.
   subroutine read_series_group(file, group, model, plan, values, error, samples, takes_duration, warnings)
      type(scene_file_t), intent(in) :: file  !! the scene file
      type(group_t), intent(in) :: group      !! the declaration (`series_group`)
      class(hill_model_t), intent(in) :: model  !! the model of `&scene`
      type(series_plan_t), intent(out) :: plan  !! the pendulum and its sampling
      type(group_values_t), intent(out) :: values  !! the effective values
      type(error_t), allocatable, intent(out) :: error  !! err_input naming file, group and variable
      !> the task writes the samples (series; default): periods * samples_per_period lines
      !> are bounded; else (lyapunov, poincare) periods alone
      logical, intent(in), optional :: samples
      !> the task takes `duration` (seconds) instead of `periods` (default: no)
      logical, intent(in), optional :: takes_duration
      !> warnings, one a line, to which a spring longer than 100 m (`r0` or ρ) or an ω below
      !> 1e-3 rad/s adds one (`task_t%warnings`)
      character(len=:), allocatable, intent(inout), optional :: warnings
      real(wp) :: alpha, beta, phi0, phi0_degrees, duration, r0, g, vx0, vz0, rho, omega
      logical :: samples_written
      integer :: periods, samples_per_period
      character(len=:), allocatable :: angle
      namelist /series/ alpha, beta, phi0, phi0_degrees, periods, duration, samples_per_period, r0, g, vx0, vz0
      logical :: durations
      type(group_reader_t) :: reader
      samples_written = .true.
      if (present(samples)) samples_written = samples
      call begin_group(reader, file, group)
      read (reader%defaults, nml=series, iostat=reader%defaults_status, iomsg=reader%defaults_msg)
      if (reader%from_file) read (file%unit, nml=series, iostat=reader%ios, iomsg=reader%msg)
      do while (next_item(reader, file, group))
         read (reader%record, nml=series, iostat=reader%stat, iomsg=reader%message)
      end do
      write (reader%echo, nml=series, delim="apostrophe", iostat=reader%echo_status)
      call end_group(reader, file, group, values, error)
      if (allocated(error)) return
      call finite("alpha", alpha)
      call finite("beta", beta)
      call finite("phi0", phi0)
      call finite("phi0_degrees", phi0_degrees)
      call finite("r0", r0)
      call finite("g", g)
      call finite("vx0", vx0)
      call finite("vz0", vz0)
      call finite("duration", duration)
      if (allocated(error)) return
      ! the start angle in radians or in degrees, not both
      angle = "phi0"
      if (values%given("phi0_degrees")) then
         if (values%given("phi0")) then
            call fail(error, file%path, group%name, "phi0_degrees", "give the initial angle either as phi0 "// &
               "(radians) or as phi0_degrees (degrees), not both")
            return
         end if
         angle = "phi0_degrees"
         phi0 = phi0_degrees*(pi/180.0_wp)
         call values%hide("phi0")
      end if
      durations = .false.
      if (present(takes_duration)) durations = takes_duration
      if (values%given("duration")) then
         if (.not. durations) then
            call fail(error, file%path, group%name, "duration", "this task counts radial periods: give periods")
         else if (values%given("periods")) then
            call fail(error, file%path, group%name, "duration", "give the length of the run either as periods "// &
               "(radial periods) or as duration (seconds), not both")
         else if (.not. duration > 0.0_wp) then
            call fail(error, file%path, group%name, "duration", "must be > 0 (seconds), got "//real_text(duration))
         end if
         if (allocated(error)) return
         periods = 1   ! checked below as a count; the rows follow from duration (task series)
      end if
      if (.not. is_elastic_pendulum(model)) then
         call fail(error, file%path, "scene", "model", "the pendulum tasks simulate the elastic pendulum: model '"// &
            model%name()//"' is not it")
      else if (alpha < 0.0_wp .or. alpha >= pi2) then
         call fail(error, file%path, group%name, "alpha", "must lie in [0, pi**2 = "//real_text(pi2)// &
            ") (amplitude a < rho), got "//real_text(alpha))
      else if (beta <= 0.0_wp .or. beta >= pi2) then
         call fail(error, file%path, group%name, "beta", "must lie in (0, pi**2 = "//real_text(pi2)// &
            "), the physical domain (r0 > 0), got "//real_text(beta))
      else if (beta < min_pendulum_beta) then
         call fail(error, file%path, group%name, "beta", "must be >= 1.0e-8 (smaller values make the "// &
            "pendulum's time scales overflow), got "//real_text(beta))
      else if (periods < 1) then
         call fail(error, file%path, group%name, "periods", "must be >= 1, got "//integer_text(periods))
      else if (samples_per_period < 1) then
         call fail(error, file%path, group%name, "samples_per_period", "must be >= 1, got "// &
            integer_text(samples_per_period))
      else if (.not. r0 > 0.0_wp) then
         call fail(error, file%path, group%name, "r0", "the natural length must be > 0, got "//real_text(r0))
      else if (.not. g > 0.0_wp) then
         call fail(error, file%path, group%name, "g", "gravity must be > 0, got "//real_text(g))
      else if (phi0 /= 0.0_wp .and. (abs(phi0) < 1.0e-300_wp .or. abs(phi0) > 1.0e3_wp)) then
         call fail(error, file%path, group%name, angle, "must be 0 or lie in [1e-300, 1e3] rad in magnitude, got "// &
            start_angle_text(phi0))
      else if (r0 < 1.0e-50_wp .or. r0 > 1.0e50_wp .or. g < 1.0e-50_wp .or. g > 1.0e50_wp) then
         call fail(error, file%path, group%name, merge("r0", "g ", r0 < 1.0e-50_wp .or. r0 > 1.0e50_wp), &
            "must lie in [1e-50, 1e50]")
      else if (max(abs(vx0), abs(vz0)) > 1.0e50_wp) then
         call fail(error, file%path, group%name, merge("vx0", "vz0", abs(vx0) > 1.0e50_wp), "must lie in [-1e50, 1e50]")
      else if (samples_written .and. int(periods, int64)*samples_per_period + 1 > max_series_lines) then
         call fail(error, file%path, group%name, "periods", "periods * samples_per_period + 1 = "// &
            integer_text(int(periods, int64)*samples_per_period + 1)// &
            " data lines exceed the limit of 1e8; lower periods or samples_per_period")
      else if (.not. samples_written .and. periods > max_series_lines) then
         call fail(error, file%path, group%name, "periods", "must be at most 1e8 radial periods, got "// &
            integer_text(periods))
      end if
      if (allocated(error)) return
      if (present(warnings) .and. values%given("r0")) then
         ! the loaded length and the radial frequency of this (alpha, beta): eqs. (4), (24)
         rho = r0/(1.0_wp - beta/pi2)
         omega = sqrt(g*pi2/(rho*beta))
         if (rho > longest_spring) then
            call add_warning(warnings, file%path//": &"//group%name//": r0: a spring longer than "// &
               real_text(longest_spring)//" m: r0 = "//real_text(r0)//" m, rho = r0/(1 - beta/pi^2) = "// &
               real_text(rho)//" m (lengths are in metres: 25 cm is r0 = 0.25)")
         end if
         if (omega < slowest_omega) then
            call add_warning(warnings, file%path//": &"//group%name//": r0: omega = sqrt(g pi^2/(rho beta)) = "// &
               real_text(omega)//" rad/s is below "//real_text(slowest_omega)//" rad/s (r0 = "//real_text(r0)// &
               " m, g = "//real_text(g)//" m/s^2: lengths in metres?)")
         end if
      end if
      if (values%given("duration")) then
         periods = 0
         call values%hide("periods")
      else
         duration = 0.0_wp
      end if
      plan = series_plan_t(alpha=alpha, beta=beta, phi0=phi0, periods=periods, samples_per_period=samples_per_period, &
         r0=r0, g=g, vx0=vx0, vz0=vz0, duration=duration)
   contains
      subroutine finite(name, x)
         character(len=*), intent(in) :: name
         real(wp), intent(in) :: x
         if (.not. allocated(error)) call require_finite(file%path, group%name, name, x, error)
      end subroutine finite
   end subroutine read_series_group

   !> The start angle in both units, for headers and messages: "0.017 rad = 0.974... degrees".
   function start_angle_text(phi0) result(text)
      real(wp), intent(in) :: phi0  !! the angle [rad]
      character(len=:), allocatable :: text
      text = real_text(phi0)//" rad = "//real_text(phi0*(180.0_wp/pi))//" degrees"
   end function start_angle_text
end module hillstab_batch_scene_group_series

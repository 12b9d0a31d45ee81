!> The series task: the nonlinear (optionally damped) elastic pendulum at (α, β) from
!> eq. (38), integrated by DOP853 and sampled from its 7th-order dense output at exactly
!> t = j T / samples_per_period, written as `<output>_series.dat` with columns
!> `t r phi x z E vx vz`. The header carries the effective scene (a repeatable run) and a
!> summary: max |φ|, energy drift, integrator work, λ_max of the linearised swing from
!> the core, and the predicted and observed onset of the swing.
!>
!> The run integrates twice, identically: the first pass measures the summary, which
!> belongs in the header, the second writes the samples (rows go straight to the file,
!> so memory does not grow with the length of the run). Only the first pass watches
!> (max |φ| on 16 dense points per step, energy, onset); the second only samples.
!>
!>```fortran
!> type(scene_t) :: scene
!> type(error_t), allocatable :: error
!> call read_scene("data/scenes/fig4a.nml", scene, error)
!> if (.not. allocated(error)) call run_series(scene, error)
!>```
module hillstab_batch_tasks_series
   use hillstab_core_kinds, only: wp, int64, pi2, version_string
   use hillstab_batch_output_progress, only: progress_t, progress_begin, progress_update, progress_end
   use hillstab_core_error, only: error_t, set_error, err_input, err_accuracy, err_invalid_parameter
   use hillstab_core_status, only: status_ok, status_roundoff, status_failed, status_name
   use hillstab_core_stats, only: work_stats_t
   use hillstab_hill_model, only: hill_model_t, hill_point_t, model_description
   use hillstab_hill_transfer, only: trace_t
   use hillstab_hill_floquet, only: floquet_t, floquet_from_trace, largest_multiplier_modulus
   use hillstab_integrate_monodromy, only: monodromy_trace, method_name
   use hillstab_integrate_rk, only: rk_step_t, rk_dense_value
   use hillstab_pendulum_equations, only: pendulum_t, pendulum_system_t, pendulum_from_chart, pendulum_initial_state, &
      pendulum_angle, pendulum_energy, pendulum_radius, px, pz, pvx, pvz
   use hillstab_pendulum_analysis, only: pendulum_watch_t, pendulum_integrate, onset_periods, default_phi_sat, &
      linear_onset_periods
   use hillstab_batch_scene_types, only: scene_t, task_t, scene_header, output_path, open_scene_output
   use hillstab_batch_scene_physical, only: physical_summary, physical_scene_t, pendulum_task_t
   use hillstab_batch_scene_declaration, only: group_t
   use hillstab_batch_scene_file, only: scene_file_t, fail
   use hillstab_batch_scene_checks, only: min_pendulum_beta
   use hillstab_hill_units, only: physical_t, physical_alpha, physical_beta
   use hillstab_batch_scene_group_series, only: series_plan_t, series_group, read_series_group, max_series_lines, &
      start_angle_text
   use hillstab_batch_output_columns, only: column_t, style_e17, columns_text, put_row, all_columns
   use hillstab_core_text, only: put_es, real_text, integer_text
   use hillstab_batch_output_file, only: output_file_t, finish_output, discard_output, write_header, write_text
   implicit none
   private
   public :: series_task_t, series_task, series_summary_t, series_summary

   !> The series task and its pendulum (`&series`).
   type, extends(pendulum_task_t) :: series_task_t
      type(series_plan_t) :: plan  !! the pendulum, its start and the sampling
      !> the last sample index j (t_j = j T/samples_per_period): periods × samples_per_period,
      !> or the last t_j <= duration
      integer(int64) :: n_samples = 0
   contains
      procedure :: read => series_read
      procedure :: run => series_run
      procedure :: declarations => series_declarations
   end type series_task_t

   !> What the header reports about a run.
   type :: series_summary_t
      type(pendulum_t) :: pendulum               !! parameters and derived quantities
      real(wp) :: max_abs_phi = 0.0_wp           !! largest |φ| [rad]
      real(wp) :: time_of_max_phi = 0.0_wp       !! where [s]
      real(wp) :: energy_drift = 0.0_wp          !! max |E − E(0)| / energy scale over the written rows
      real(wp) :: energy_drift_steps = 0.0_wp    !! the same over the integrator's step ends
      real(wp) :: energy_start = 0.0_wp          !! E(0) [J/kg]
      real(wp) :: energy_scale = 0.0_wp          !! ½|v|² + ½ω²(r − r0)² + g|z| at t = 0 [J/kg]
      real(wp) :: energy_end = 0.0_wp            !! E at the end [J/kg]
      integer(int64) :: energy_increases = 0     !! steps over which E rose beyond round-off
      type(work_stats_t) :: work                 !! steps, rejections, f-evaluations (one pass)
      real(wp) :: trace = 0.0_wp                 !! S of the core at (α, β, ε)
      real(wp) :: lambda_max = -1.0_wp           !! largest multiplier modulus of x per radial period
      logical :: stable = .false.                !! the chart's verdict
      integer :: status = status_failed          !! of the core's λ_max (hillstab_core_status)
      !> first |φ| = φ_sat of the linear swing from the start (`linear_onset_periods`; damped:
      !> the multiplier law) [periods]; −1: no onset expected
      real(wp) :: onset_predicted = -1.0_wp
      !> first |φ| = 2 φ_sat of the linear swing: the late end of the predicted interval of the
      !> onset (the nonlinear swing falls behind the linear one) [periods]; −1: none
      real(wp) :: onset_late = -1.0_wp
      real(wp) :: onset_law = -1.0_wp            !! n* = ln(φ_sat/|φ0|)/ln λ_max [periods]; −1: none
      real(wp) :: onset_observed = -1.0_wp       !! first |φ| > φ_sat [periods]; −1: not within the run
   end type series_summary_t

   !> The pendulum of the writing pass: writes the samples (the first pass has watched).
   type, extends(pendulum_system_t) :: series_writer_t
      type(output_file_t) :: file                !! the open output file
      type(column_t), allocatable :: table(:)    !! the columns
      integer(int64) :: next = 0                 !! index j of the next sample
      integer(int64) :: n_samples = 0            !! last index (periods × samples_per_period)
      integer :: samples_per_period = 1
      type(error_t), allocatable :: error        !! a write failure (the integration then stops)
      type(progress_t) :: progress               !! rows written, on stderr
   contains
      procedure :: observe => write_samples
   end type series_writer_t

contains

   !> `&series`.
   function series_declarations(self) result(groups)
      class(series_task_t), intent(in) :: self  !! the task
      type(group_t), allocatable :: groups(:)
      allocate (groups(1))
      groups(1) = series_group()
   end function series_declarations

   !> A series task before its scene is read.
   function series_task() result(task)
      type(series_task_t) :: task
      task%name = "series"
      task%physical_use%takes_amplitudes = .true.
      task%physical_use%takes_spring = .true.
      task%physical_use%single_amplitude = .true.
      task%physical_use%amplitudes_replace = "alpha, beta, r0 and g from &series"
   end function series_task

   !> `&series`.
   subroutine series_read(self, file, scene, error)
      class(series_task_t), intent(inout) :: self  !! the task, its pendulum filled in
      type(scene_file_t), intent(in) :: file      !! the scene file
      type(scene_t), intent(in) :: scene          !! the `&scene` settings
      type(error_t), allocatable, intent(out) :: error  !! err_input naming file, group and variable
      type(pendulum_t) :: p
      type(error_t), allocatable :: cause
      character(len=5), parameter :: replaced(4) = ["alpha", "beta ", "r0   ", "g    "]
      real(wp) :: spacing
      integer :: k
      allocate (self%groups(1))
      call read_series_group(file, series_group(), scene%model, self%plan, self%groups(1), error, &
                             takes_duration=.true., warnings=self%warnings)
      if (allocated(error)) return
      if (self%physical%given) then
         ! the pendulum of &physical (omega or k, m; r0; g; kappa; one amplitude a)
         do k = 1, size(replaced)
            if (self%groups(1)%given(trim(replaced(k)))) then
               call fail(error, file%path, "series", trim(replaced(k)), "the pendulum comes either from &series "// &
                  "alpha, beta, r0, g or from &physical (omega or k, m; r0; g; a), not both: &series "// &
                  trim(replaced(k))//" with &physical")
               return
            end if
         end do
         if (size(self%physical%amplitudes) /= 1) then
            call fail(error, file%path, "physical", "a", "task series simulates one bounce amplitude: give one a "// &
               "(m) with r0, got "//integer_text(size(self%physical%amplitudes)))
            return
         end if
         if (.not. self%physical%pendulum%g > 0.0_wp) then
            call fail(error, file%path, "physical", "g", "the series task needs gravity g > 0")
            return
         end if
         self%plan%alpha = physical_alpha(physical_t(r0=self%physical%pendulum%r0, g=self%physical%pendulum%g, &
                                                     omega=self%physical%pendulum%omega, a=self%physical%amplitudes(1)))
         self%plan%beta = physical_beta(self%physical%pendulum)
         self%plan%r0 = self%physical%pendulum%r0
         self%plan%g = self%physical%pendulum%g
         if (self%plan%beta < min_pendulum_beta .or. self%plan%beta >= pi2) then
            call fail(error, file%path, "physical", "r0", "beta = g pi^2/(rho omega^2) = "// &
               real_text(self%plan%beta)//" must lie in [1e-8, pi^2) for the series task")
            return
         end if
         do k = 1, size(replaced)
            call self%groups(1)%hide(trim(replaced(k)))
         end do
      end if
      call pendulum_from_chart(self%plan%alpha, self%plan%beta, scene%epsilon, self%plan%r0, self%plan%g, p, cause)
      if (allocated(cause)) then
         call fail(error, file%path, "series", "alpha", cause%message)
         return
      end if
      if (self%plan%duration > 0.0_wp) then
         ! the last sample time t_j = j T/samples_per_period (the expression of the run) <= duration
         spacing = p%period/real(self%plan%samples_per_period, wp)
         if (self%plan%duration/spacing + 2.0_wp > real(max_series_lines, wp)) then
            call fail(error, file%path, "series", "duration", real_text(self%plan%duration)//" s at "// &
               real_text(spacing)//" s a row exceeds the limit of 1e8 data lines; lower duration or "// &
               "samples_per_period")
            return
         end if
         self%n_samples = int(self%plan%duration/spacing, int64)
         do while (sample_time(p, self%n_samples + 1, self%plan%samples_per_period) <= self%plan%duration)
            self%n_samples = self%n_samples + 1
         end do
         do while (self%n_samples > 0)
            if (sample_time(p, self%n_samples, self%plan%samples_per_period) <= self%plan%duration) exit
            self%n_samples = self%n_samples - 1
         end do
         if (self%n_samples < 1) then
            call fail(error, file%path, "series", "duration", "must be at least one sample spacing T/"// &
               "samples_per_period = "//real_text(spacing)//" s, got "//real_text(self%plan%duration))
            return
         end if
      else
         self%n_samples = int(self%plan%periods, int64)*self%plan%samples_per_period
      end if
   end subroutine series_read

   !> The columns of a series file.
   function series_columns() result(table)
      type(column_t), allocatable :: table(:)
      allocate (table(8))
      table(1) = column_t("t", "s", "time", style_e17)
      table(2) = column_t("r", "m", "length of the spring", style_e17)
      table(3) = column_t("phi", "rad", "angle from the downward vertical", style_e17)
      table(4) = column_t("x", "m", "horizontal position", style_e17)
      table(5) = column_t("z", "m", "downward position", style_e17)
      table(6) = column_t("E", "J/kg", "energy per unit mass, eq. (3)", style_e17)
      table(7) = column_t("vx", "m/s", "horizontal velocity", style_e17)
      table(8) = column_t("vz", "m/s", "downward velocity", style_e17)
   end function series_columns

   !> Run the series task of a validated scene: `<output>_series.dat`, or an error and no file.
   subroutine series_run(self, scene, quiet, error)
      class(series_task_t), intent(in) :: self  !! the task
      type(scene_t), intent(in) :: scene  !! its scene
      logical, intent(in) :: quiet  !! no progress on stderr (the rows of the writing pass)
      type(error_t), allocatable, intent(out) :: error  !! what failed; unallocated on success
      type(series_summary_t) :: summary
      type(series_writer_t) :: writer
      type(work_stats_t) :: stats
      real(wp) :: y(4)

      call series_summary(scene, self%plan, self%n_samples, summary, error)
      if (allocated(error)) return

      call open_scene_output(scene, writer%file, error)
      if (allocated(error)) return
      writer%table = series_columns()
      call write_header(writer%file, series_header(scene, self%physical, self%plan, self%n_samples, summary), &
                        columns_text(writer%table, all_columns(writer%table)), error)
      if (allocated(error)) then
         call discard_output(writer%file)
         return
      end if
      writer%pendulum = summary%pendulum
      writer%n_samples = self%n_samples
      writer%samples_per_period = self%plan%samples_per_period
      y = initial_state(self%plan, summary%pendulum)
      call progress_begin(writer%progress, writer%n_samples + 1, quiet, "rows")
      call pendulum_integrate(writer, y, sample_time(writer%pendulum, writer%n_samples, writer%samples_per_period), &
                              scene%method%tolerance, stats, error)
      if (.not. allocated(error) .and. allocated(writer%error)) call move_alloc(writer%error, error)
      if (.not. allocated(error) .and. writer%next <= writer%n_samples) then
         call set_error(error, err_input, "series: the integration ended before the last sample")
      end if
      call progress_end(writer%progress)
      if (allocated(error)) error%message = scene%source//": "//error%message
      call finish_output(writer%file, error)
   end subroutine series_run

   !> The first pass: integrate without writing and measure what the header reports.
   subroutine series_summary(scene, plan, n_samples, summary, error)
      type(scene_t), intent(in) :: scene           !! task = series
      type(series_plan_t), intent(in) :: plan      !! its pendulum
      integer(int64), intent(in) :: n_samples      !! the last sample index
      type(series_summary_t), intent(out) :: summary  !! what the header reports: energy drift, angles, onset, work
      type(error_t), allocatable, intent(out) :: error  !! integration failure; unallocated on success
      type(pendulum_watch_t) :: watch
      type(trace_t) :: tr
      type(floquet_t) :: f
      type(error_t), allocatable :: cause
      real(wp) :: y(4), t_end
         call pendulum_from_chart(plan%alpha, plan%beta, scene%epsilon, plan%r0, plan%g, summary%pendulum, cause)
         if (allocated(cause)) then
            call set_error(error, err_input, scene%source//": &series: "//cause%message)
            return
         end if
         ! λ_max of the linearised swing from the core (the chart's method and tolerance)
         call monodromy_trace(scene%model, hill_point_t(plan%alpha, plan%beta, scene%epsilon), scene%method, &
                              tr, cause)
         summary%status = status_ok
         if (allocated(cause)) then
            summary%status = merge(status_roundoff, status_failed, cause%code == err_accuracy)
            deallocate (cause)
         end if
         if (summary%status /= status_failed) then
            f = floquet_from_trace(tr, scene%epsilon)
            summary%trace = tr%value
            summary%lambda_max = largest_multiplier_modulus(f)
            summary%stable = f%stable
            summary%onset_law = onset_periods(plan%phi0, default_phi_sat, summary%lambda_max)
            summary%onset_predicted = summary%onset_law
            if (scene%epsilon == 0.0_wp .and. summary%onset_law >= 0.0_wp) then
               summary%onset_predicted = linear_onset_periods(plan%alpha, plan%beta, plan%phi0, default_phi_sat)
               summary%onset_late = linear_onset_periods(plan%alpha, plan%beta, plan%phi0, 2.0_wp*default_phi_sat)
            end if
         end if

         watch%pendulum = summary%pendulum
         ! the rows the second pass writes: their energies are what the user reads
         watch%samples_per_period = plan%samples_per_period
         watch%n_samples = n_samples
         y = initial_state(plan, summary%pendulum)
         t_end = sample_time(summary%pendulum, n_samples, plan%samples_per_period)
         call pendulum_integrate(watch, y, t_end, scene%method%tolerance, summary%work, cause)
         if (allocated(cause)) then
            call set_error(error, cause%code, scene%source//": series: "//cause%message)
            return
         end if
         summary%max_abs_phi = watch%max_abs_phi
         summary%time_of_max_phi = watch%time_of_max_phi
         summary%energy_start = watch%energy_start
         summary%energy_scale = watch%energy_scale
         summary%energy_end = watch%energy_last
         summary%energy_drift = watch%max_sample_energy_error/watch%energy_scale
         summary%energy_drift_steps = watch%max_energy_error/watch%energy_scale
         summary%energy_increases = watch%energy_increases
         if (watch%onset_time >= 0.0_wp) summary%onset_observed = watch%onset_time/summary%pendulum%period
   end subroutine series_summary

   !> Initial state of the scene (eq. (38) plus the optional velocities).
   pure function initial_state(plan, p) result(y)
      type(series_plan_t), intent(in) :: plan
      type(pendulum_t), intent(in) :: p
      real(wp) :: y(4)
      y = pendulum_initial_state(p, plan%phi0, plan%vx0, plan%vz0)
   end function initial_state

   !> t_j = j T / samples_per_period, computed afresh for every j (no accumulated round-off).
   pure real(wp) function sample_time(p, j, samples_per_period) result(t)
      type(pendulum_t), intent(in) :: p
      integer(int64), intent(in) :: j
      integer, intent(in) :: samples_per_period
      t = real(j, wp)*p%period/real(samples_per_period, wp)
   end function sample_time

   !> Observer of the writing pass: every sample time in (t_old, t] from the dense output
   !> (the initial point at index 0).
   subroutine write_samples(self, step, stop)
      class(series_writer_t), intent(inout) :: self
      type(rk_step_t), intent(in) :: step
      logical, intent(inout) :: stop
      real(wp) :: ts, y(4)
      character(len=8*25) :: line
      integer :: pos
      real(wp) :: values(8)
      do while (self%next <= self%n_samples)
         ts = sample_time(self%pendulum, self%next, self%samples_per_period)
         ! the last step ends exactly on the last sample time (the same expression)
         if (ts > step%t) exit
         if (ts == step%t) then
            y = step%y
         else
            y = rk_dense_value(step, ts)
         end if
         values = [ts, pendulum_radius(y), pendulum_angle(y), y(px), y(pz), pendulum_energy(self%pendulum, y), &
                   y(pvx), y(pvz)]
         pos = 0
         call put_row(self%table, all_columns(self%table), values, line, pos)
         call write_text(self%file, trim(adjustl(line(1:pos))), self%error)
         if (allocated(self%error)) then
            stop = .true.
            return
         end if
         self%next = self%next + 1
      end do
      call progress_update(self%progress, self%next)
   end subroutine write_samples

   !> Header: version, scene (repeatable), the pendulum, the method, the summary, the columns.
   function series_header(scene, physical, plan, n_samples, s) result(lines)
      type(scene_t), intent(in) :: scene
      type(physical_scene_t), intent(in) :: physical  !! the task's `&physical`
      type(series_plan_t), intent(in) :: plan
      integer(int64), intent(in) :: n_samples
      type(series_summary_t), intent(in) :: s
      character(len=:), allocatable :: lines(:)
      character(len=400) :: extra(30)
      character(len=:), allocatable :: spring(:)
      integer :: n, k
      n = 0
      if (physical%given) then
         spring = physical_summary(physical, scene%epsilon)
         do k = 1, size(spring)
            n = n + 1; extra(n) = spring(k)
         end do
         n = n + 1; extra(n) = "the pendulum of &physical: alpha = a pi^2/rho = "//real_text(plan%alpha)// &
            ", beta = "//real_text(plan%beta)//" (eq. (24))"
      end if
      associate (p => s%pendulum)
         n = n + 1; extra(n) = "model: x'' = -omega^2 (1 - r0/r) x - kappa x', z'' = -omega^2 (1 - r0/r) z + g - kappa z'"// &
            " (x horizontal, z downward from the pivot, r = sqrt(x^2 + z^2), phi = atan2(x, z))"
         n = n + 1; extra(n) = "pendulum: rho = "//real_text(p%rho)//" m, omega = "//real_text(p%omega)// &
            " 1/s, a = "//real_text(p%a)//" m, T = "//real_text(p%period)//" s, kappa = epsilon omega/pi = "// &
            real_text(p%kappa)//" 1/s"
         n = n + 1; extra(n) = "start (eq. (38)): r(0) = rho - a = "//real_text(p%rho - p%a)//" m, phi(0) = phi0 = "// &
            start_angle_text(plan%phi0)//", velocities vx0, vz0"
      end associate
      n = n + 1; extra(n) = "integrator: DOP853, relative tolerance "//real_text(scene%method%tolerance)// &
         "; absolute tolerances rtol*rho on z, rtol*(initial swing) on x (relative accuracy in a tiny swing)"
      n = n + 1; extra(n) = "samples: 7th-order dense output at t = j T / samples_per_period, j = 0 .. "// &
         integer_text(n_samples)//" (the step size is not forced onto them); last row t = "// &
         real_text(sample_time(s%pendulum, n_samples, plan%samples_per_period))//" s"
      n = n + 1; extra(n) = "summary: max |phi| = "//fmt(s%max_abs_phi)//" rad at t = "//fmt(s%time_of_max_phi)// &
         " s (16 dense points per step)"
      n = n + 1; extra(n) = "summary: energy E(0) = "//fmt(s%energy_start)//" J/kg, E(end) = "//fmt(s%energy_end)// &
         " J/kg, "//merge("change", "drift ", scene%epsilon > 0.0_wp)//" max|E - E(0)|/E_scale = "// &
         fmt(s%energy_drift)//" over the written rows ("//fmt(s%energy_drift_steps)//" over the integrator's "// &
         "step ends)"//merge(" (damped: the dissipated energy, not an error)", &
         "                                              ", scene%epsilon > 0.0_wp)
      n = n + 1; extra(n) = "summary: E_scale = "//fmt(s%energy_scale)// &
         " J/kg (1/2 |v|^2 + 1/2 omega^2 (r - r0)^2 + g |z| at t = 0; E itself may be near 0)"
      if (scene%epsilon > 0.0_wp) then
         n = n + 1; extra(n) = "summary: damped: steps over which E rose beyond round-off: "// &
            integer_text(s%energy_increases)//" (0: E decreases monotonically)"
      end if
      n = n + 1; extra(n) = "summary: accepted steps "//integer_text(s%work%n_steps)// &
         ", rejected "//integer_text(s%work%n_rejected)//", f-evaluations "// &
         integer_text(s%work%n_evaluations)//" (one pass)"
      if (s%status == status_failed) then
         n = n + 1; extra(n) = "summary: lambda_max: status 2 (failed): the core could not compute S here"
      else
         n = n + 1; extra(n) = "summary: core ("//method_name(scene%method%kind)//"): S = "//fmt(s%trace)// &
            ", lambda_max = "//fmt(s%lambda_max)//" per radial period (largest |multiplier| of the linearised"// &
            " swing), chart verdict "//merge("stable  ", "unstable", s%stable)//", status "// &
            integer_text(s%status)//" ("//status_name(s%status)//")"
      end if
      if (scene%epsilon == 0.0_wp) then
         n = n + 1; extra(n) = "summary: onset (|phi| > "//real_text(default_phi_sat)//"): predicted n* = "// &
            "first |x|/r = sin(0.1) of the linear swing x = r(0) sin(phi0) u(t) = "// &
            periods_text(s%onset_predicted, "never (no growth or phi0 = 0)")// &
            ", observed "//periods_text(s%onset_observed, "not within the run")
         if (s%onset_predicted > 0.0_wp) then
            n = n + 1; extra(n) = "summary: onset expected in [n*, n2] = ["//fmt(s%onset_predicted)//", "// &
               late_text(s%onset_late)//"] periods, n2 the "// &
               "first |x|/r = sin(0.2) of the linear swing (the nonlinear swing falls behind it near 0.1; "// &
               "measured: every observed onset inside for lambda_max = 1.13 ... 44; at lambda_max <= 1.1 the "// &
               "swing may saturate below 0.1, no onset)"
         end if
      else
         n = n + 1; extra(n) = "summary: onset (|phi| > "//real_text(default_phi_sat)//"): predicted n* = "// &
            "ln(0.1/|phi0|)/ln(lambda_max) (damped) = "//periods_text(s%onset_predicted, &
            "never (no growth or phi0 = 0)")//", observed "//periods_text(s%onset_observed, "not within the run")
      end if
      n = n + 1; extra(n) = "summary: onset law (the multiplier alone): n* = ln(0.1/|phi0|)/ln(lambda_max) = "// &
         periods_text(s%onset_law, "never (no growth or phi0 = 0)")// &
         "; u: the even solution of the Hill equation x'' + Q x = 0 about the bounce, tau = omega t/pi"
      n = n + 1; extra(n) = "units: t [s], r [m], phi [rad], x, z [m], E [J/kg], vx, vz [m/s]"
      lines = scene_header(scene, "hillstab "//version_string//": the nonlinear elastic pendulum (task series)", extra(:n))
   contains
      function fmt(x) result(text)
         real(wp), intent(in) :: x
         character(len=:), allocatable :: text
         character(len=32) :: buffer
         integer :: pos
         pos = 0
         call put_es(buffer, pos, x, 10)
         text = trim(adjustl(buffer(1:pos)))
      end function fmt
      function late_text(n_periods) result(text)
         real(wp), intent(in) :: n_periods
         character(len=:), allocatable :: text
         if (n_periods < 0.0_wp) then
            text = "never"
         else
            text = fmt(n_periods)
         end if
      end function late_text
      function periods_text(n_periods, none) result(text)
         real(wp), intent(in) :: n_periods
         character(len=*), intent(in) :: none
         character(len=:), allocatable :: text
         if (n_periods < 0.0_wp) then
            text = none
         else
            text = fmt(n_periods)//" periods (t = "//fmt(n_periods*s%pendulum%period)//" s)"
         end if
      end function periods_text
   end function series_header
end module hillstab_batch_tasks_series

!> Speed against error for the nonlinear pendulum of the paper's Fig. 4 (e) (α = 7.88,
!> β = 3.95, φ0 = 0.017, r0 = 0.1 m, g = 9.81 m/s²) by hillstab's DOPRI5, DOP853, PD87
!> (the Prince–Dormand 8(7) pair of GSL's rk8pd, in hillstab's integrator) and VERN98
!> (Verner's 9(8) pair) and by GSL's rk8pd, several tolerances each. All five integrate the
!> same equations (`pendulum_rhs`) with the same absolute tolerances (`pendulum_atol`).
!>
!> The motion of (e) is chaotic: two converged integrations (DOP853 and rk8pd at 1e-15)
!> part by a factor of about 10 every 2.5 radial periods and disagree at O(1) after 100.
!> So the state is compared with the reference after 10 periods (where the two references
!> agree to ~2e-13), and the 100-period run is judged by its energy error, which chaos does
!> not amplify, in two ways: at the end, |E(100 T) − E(0)|/E_scale, and as the largest
!> |E − E(0)|/E_scale at the ends of the steps (the drift along the run; same runs, same
!> times, the errors from untimed runs that watch every step). The end value is one sample
!> of a signed, oscillating quantity: rk8pd's at 1e-12 is 25 times below its largest value
!> along the run, a chance near-zero that makes equal-error comparisons jump there.
!>
!> Usage: hillstab_bench_series [--quick] [--periods N] [--out PREFIX]
!> Writes PREFIX_series.dat (default PREFIX = out/bench): method, tolerance, then for the
!> state run, the energy run and the drift the seconds per run, the error and the f-evaluations;
!> prints the tables (with the time per f-evaluation) and, for each hillstab run, its time
!> and its f-evaluations over GSL's at equal error. GSL also runs at two looser tolerances
!> so that its curve covers the errors of hillstab's loosest runs. Times are wall-clock,
!> the fastest of interleaved repeated runs, measured side by side in one run; compare
!> them as ratios.
program hillstab_bench_series
   use, intrinsic :: iso_fortran_env, only: output_unit, error_unit, int64
   use hillstab_core_kinds, only: wp
   use hillstab_core_error, only: error_t
   use hillstab_core_stats, only: work_stats_t
   use hillstab_integrate_rk, only: rk_options_t, rk_integrate, rk_dop853, rk_dopri5, rk_pd87, rk_vern98
   use hillstab_pendulum_equations, only: pendulum_t, pendulum_system_t, pendulum_from_chart, pendulum_initial_state, &
      pendulum_atol, pendulum_energy, pendulum_energy_scale
   use hillstab_pendulum_gsl, only: pendulum_gsl
   use hillstab_pendulum_analysis, only: pendulum_watch_t
   implicit none

   integer :: n_periods = 10          !! the state run
   integer, parameter :: energy_periods = 100
   integer, parameter :: method_gsl = 5
   !> hillstab's integrators, in the order of `names`
   integer, parameter :: hillstab_methods(4) = [rk_dopri5, rk_dop853, rk_pd87, rk_vern98]
   !> GSL also runs at these looser tolerances (alone), so that its curve reaches the
   !> errors of hillstab's loosest runs and every one of those has a GSL time to compare with
   real(wp), parameter :: gsl_looser(2) = [1.0e-3_wp, 1.0e-4_wp]
   character(len=*), parameter :: names(5) = [character(len=6) :: "dopri5", "dop853", "pd87", "vern98", "rk8pd"]
   real(wp), allocatable :: tolerances(:)
   type(pendulum_system_t) :: system
   type(error_t), allocatable :: error
   real(wp) :: y0(4), reference(4), check_state(4), t_end
   real(wp), allocatable :: table_err(:, :, :), table_time(:, :, :)
   integer(int64), allocatable :: table_evals(:, :, :)
   ! GSL's whole curve: the looser tolerances, then those of the table
   real(wp), allocatable :: gsl_err(:, :), gsl_time(:, :), gsl_evals(:, :)
   integer :: measure
   character(len=256) :: prefix, arg
   logical :: quick
   integer :: i, j, m, unit, ios
   type(work_stats_t) :: stats

   prefix = "out/bench"
   quick = .false.
   i = 1
   do while (i <= command_argument_count())
      call get_command_argument(i, arg)
      select case (trim(arg))
      case ("--quick"); quick = .true.
      case ("--periods")
         i = i + 1
         call get_command_argument(i, arg)
         read (arg, *) n_periods
      case ("--out")
         i = i + 1
         call get_command_argument(i, prefix)
      case default
         write (error_unit, '(a)') "usage: hillstab_bench_series [--quick] [--periods N] [--out PREFIX]"
         error stop 2
      end select
      i = i + 1
   end do
   if (quick) then
      tolerances = [1.0e-6_wp, 1.0e-9_wp, 1.0e-12_wp]
   else
      tolerances = [1.0e-5_wp, 1.0e-6_wp, 1.0e-7_wp, 1.0e-8_wp, 1.0e-9_wp, 1.0e-10_wp, 1.0e-11_wp, 1.0e-12_wp, &
                    1.0e-13_wp]
   end if

   call pendulum_from_chart(7.88_wp, 3.95_wp, 0.0_wp, 0.1_wp, 9.81_wp, system%pendulum, error)
   if (allocated(error)) error stop "bench_series: invalid pendulum"
   y0 = pendulum_initial_state(system%pendulum, 0.017_wp)
   t_end = n_periods*system%pendulum%period

   ! reference: DOP853 at 1e-15; its distance to GSL rk8pd at 1e-15 says how good it is
   reference = y0
   call run_dop(system, rk_dop853, 1.0e-15_wp, reference, stats)
   check_state = y0
   call pendulum_gsl(system%pendulum, check_state, t_end, 1.0e-15_wp, stats, error)
   if (allocated(error)) error stop "bench_series: GSL reference failed"
   write (output_unit, '(a,i0,a)') "# Fig. 4 (e), phi0 = 0.017: reference state after ", n_periods, " radial periods"
   write (output_unit, '(a,es10.3)') "# reference DOP853 1e-15 vs GSL rk8pd 1e-15: scaled difference ", &
      scaled_error(check_state)

   allocate (table_err(size(tolerances), method_gsl, 3), table_time(size(tolerances), method_gsl, 3), &
             table_evals(size(tolerances), method_gsl, 3))
   allocate (gsl_err(size(gsl_looser) + size(tolerances), 3), gsl_time(size(gsl_looser) + size(tolerances), 3), &
             gsl_evals(size(gsl_looser) + size(tolerances), 3))
   do measure = 1, 3
      if (measure == 1) then
         write (output_unit, '(a,i0,a)') "# state after ", n_periods, " periods: method tolerance seconds error f-evals"
      else if (measure == 2) then
         t_end = energy_periods*system%pendulum%period
         write (output_unit, '(a,i0,a)') "# energy after ", energy_periods, &
            " periods: method tolerance seconds error f-evals"
      else
         write (output_unit, '(a,i0,a)') "# largest energy error at step ends over ", energy_periods, &
            " periods: method tolerance seconds error f-evals"
      end if
      if (measure < 3) then
         do j = 1, size(tolerances)
            call time_interleaved(tolerances(j), measure, j)
         end do
         do j = 1, size(gsl_looser)
            call time_gsl_alone(gsl_looser(j), measure, j)
         end do
      else
         ! the runs of measure 2, judged along the way: times and evaluations are theirs, the
         ! errors come from untimed runs that watch every step (the same steps)
         table_time(:, :, 3) = table_time(:, :, 2)
         table_evals(:, :, 3) = table_evals(:, :, 2)
         gsl_time(:, 3) = gsl_time(:, 2)
         gsl_evals(:, 3) = gsl_evals(:, 2)
         do j = 1, size(tolerances)
            do m = 1, method_gsl
               table_err(j, m, 3) = watched_drift(m, tolerances(j))
            end do
         end do
         do j = 1, size(gsl_looser)
            gsl_err(j, 3) = watched_drift(method_gsl, gsl_looser(j))
         end do
      end if
      gsl_err(size(gsl_looser) + 1:, measure) = table_err(:, method_gsl, measure)
      gsl_time(size(gsl_looser) + 1:, measure) = table_time(:, method_gsl, measure)
      gsl_evals(size(gsl_looser) + 1:, measure) = real(table_evals(:, method_gsl, measure), wp)
      write (output_unit, '(a)') "# (ns/eval: time per f-evaluation)"
      do m = 1, method_gsl
         if (m == method_gsl) then
            do j = 1, size(gsl_looser)
               write (output_unit, '(a8,es11.2,es12.4,es12.4,i12,f9.1,a)') names(m), gsl_looser(j), &
                  gsl_time(j, measure), gsl_err(j, measure), nint(gsl_evals(j, measure), int64), &
                  1.0e9_wp*gsl_time(j, measure)/gsl_evals(j, measure), " ns/eval"
            end do
         end if
         do j = 1, size(tolerances)
            write (output_unit, '(a8,es11.2,es12.4,es12.4,i12,f9.1,a)') names(m), tolerances(j), &
               table_time(j, m, measure), table_err(j, m, measure), table_evals(j, m, measure), &
               1.0e9_wp*table_time(j, m, measure)/real(table_evals(j, m, measure), wp), " ns/eval"
         end do
      end do
      ! time and f-evaluations of each hillstab integrator divided by GSL's at the same
      ! error (GSL's log-time and log-evaluations interpolated in log-error); > 1 means
      ! slower (more evaluations) than GSL
      write (output_unit, '(a)') "# time and f-evaluation ratios to GSL rk8pd at equal error "// &
         "(< 1: faster, fewer; -1: outside GSL's range)"
      do m = 1, size(hillstab_methods)
         do j = 1, size(tolerances)
            write (output_unit, '(a8,es11.2,a,es10.3,a,f7.3,a,f7.3)') names(m), tolerances(j), " error ", &
               table_err(j, m, measure), ": time ratio ", &
               ratio_to_gsl(measure, table_err(j, m, measure), table_time(j, m, measure), gsl_time(:, measure)), &
               "  f-evaluation ratio ", ratio_to_gsl(measure, table_err(j, m, measure), &
               real(table_evals(j, m, measure), wp), gsl_evals(:, measure))
         end do
      end do
   end do

   open (newunit=unit, file=trim(prefix)//"_series.dat", status="replace", action="write", iostat=ios)
   if (ios /= 0) error stop "bench_series: cannot write the data file"
   write (unit, '(a,i0,a,i0,a)') "# hillstab_bench_series: Fig. 4 (e); state error after ", n_periods, &
      " radial periods = max(|dx|, |dz|)/rho, max(|dvx|, |dvz|)/(rho omega) against DOP853 at 1e-15; "// &
      "energy error after ", energy_periods, " periods = |E - E(0)|/E_scale; drift = largest |E - E(0)|/E_scale "// &
      "at the step ends over those periods (same runs)"
   write (unit, '(a)') "# one block per method (dopri5, dop853, pd87, vern98, rk8pd), blocks separated by two "// &
      "blank lines"
   write (unit, '(a)') "# columns: method tolerance seconds_state error_state evaluations_state "// &
      "seconds_energy error_energy evaluations_energy seconds_drift error_drift evaluations_drift"
   do m = 1, method_gsl
      if (m == method_gsl) then
         do j = 1, size(gsl_looser)
            write (unit, '(a,1x,es11.3,9(1x,es12.5))') trim(names(m)), gsl_looser(j), &
               (gsl_time(j, measure), gsl_err(j, measure), gsl_evals(j, measure), measure = 1, 3)
         end do
      end if
      do j = 1, size(tolerances)
         write (unit, '(a,1x,es11.3,9(1x,es12.5))') trim(names(m)), tolerances(j), &
            (table_time(j, m, measure), table_err(j, m, measure), real(table_evals(j, m, measure), wp), measure = 1, 3)
      end do
      write (unit, '(a)') ""
      write (unit, '(a)') ""
   end do
   close (unit)

contains

   !> One run of hillstab's integrator `method` at `tolerance` from t = 0 to t_end: the
   !> benchmark's pendulum, or one that watches its steps (`watched_drift`).
   subroutine run_dop(integrated, method, tolerance, y, work)
      class(pendulum_system_t), intent(inout) :: integrated
      integer, intent(in) :: method
      real(wp), intent(in) :: tolerance
      real(wp), intent(inout) :: y(4)
      type(work_stats_t), intent(out) :: work
      type(rk_options_t) :: options
      real(wp) :: t
      options = rk_options_t(method=method, rtol=tolerance, atol=tolerance, max_steps=huge(1))
      options%atol_components = pendulum_atol(integrated%pendulum, y, tolerance)
      t = 0.0_wp
      call rk_integrate(integrated, t, t_end, y, options, work, error)
      if (allocated(error)) error stop "bench_series: hillstab integration failed"
   end subroutine run_dop

   !> max(|Δx|, |Δz|)/ρ and max(|Δx'|, |Δz'|)/(ρω) against the reference, the larger.
   real(wp) function scaled_error(y) result(e)
      real(wp), intent(in) :: y(4)
      associate (p => system%pendulum)
         e = max(maxval(abs(y(1:2) - reference(1:2)))/p%rho, maxval(abs(y(3:4) - reference(3:4)))/(p%rho*p%omega))
      end associate
   end function scaled_error

   !> The error of a run ending in y: the scaled state error (measure 1) or the energy
   !> error at the end, |E(y) − E(y0)|/E_scale (measure 2).
   real(wp) function run_error(measure, y) result(e)
      integer, intent(in) :: measure
      real(wp), intent(in) :: y(4)
      if (measure == 1) then
         e = scaled_error(y)
      else
         e = abs(pendulum_energy(system%pendulum, y) - pendulum_energy(system%pendulum, y0)) &
             /pendulum_energy_scale(system%pendulum, y0)
      end if
   end function run_error

   !> Time the five integrators at one tolerance, interleaved (one run of each per round,
   !> so all see the same load), and keep each one's fastest run: the time of a run that
   !> other processes did not interrupt. At least 5 rounds, then until 1.5 s or 300 rounds.
   subroutine time_interleaved(tolerance, measure, j)
      real(wp), intent(in) :: tolerance
      integer, intent(in) :: measure, j
      integer(int64) :: t0, t1, rate, start
      integer :: rounds, method
      real(wp) :: y(4)
      type(work_stats_t) :: work
      table_time(j, :, measure) = huge(1.0_wp)
      rounds = 0
      call system_clock(start, rate)
      do
         do method = 1, method_gsl
            y = y0
            call system_clock(t0)
            if (method == method_gsl) then
               call pendulum_gsl(system%pendulum, y, t_end, tolerance, work, error)
               if (allocated(error)) error stop "bench_series: GSL failed"
            else
               call run_dop(system, hillstab_methods(method), tolerance, y, work)
            end if
            call system_clock(t1)
            table_time(j, method, measure) = min(table_time(j, method, measure), real(t1 - t0, wp)/rate)
            table_evals(j, method, measure) = work%n_evaluations
            table_err(j, method, measure) = run_error(measure, y)
         end do
         rounds = rounds + 1
         if (quick .and. rounds >= 2) exit
         if (rounds >= 5 .and. (real(t1 - start, wp)/rate > 1.5_wp .or. rounds >= 300)) exit
      end do
   end subroutine time_interleaved

   !> The largest energy error at the ends of the steps of one (untimed) run.
   real(wp) function watched_drift(method, tolerance) result(drift)
      integer, intent(in) :: method
      real(wp), intent(in) :: tolerance
      type(pendulum_watch_t) :: watched  ! its observer keeps the largest |E − E(0)| at the step ends
      type(work_stats_t) :: work
      real(wp) :: y(4)
      y = y0
      if (method == method_gsl) then
         call pendulum_gsl(system%pendulum, y, t_end, tolerance, work, error, energy_drift=drift)
         if (allocated(error)) error stop "bench_series: GSL failed"
         return
      end if
      watched%pendulum = system%pendulum
      call run_dop(watched, hillstab_methods(method), tolerance, y, work)
      drift = watched%max_energy_error/watched%energy_scale
   end function watched_drift

   !> Time the GSL run alone at a tolerance looser than the table's (fastest of at least
   !> 5 runs, then until 1.5 s or 300 runs), into row j of GSL's curve.
   subroutine time_gsl_alone(tolerance, measure, j)
      real(wp), intent(in) :: tolerance
      integer, intent(in) :: measure, j
      integer(int64) :: t0, t1, rate, start
      integer :: rounds
      real(wp) :: y(4)
      type(work_stats_t) :: work
      gsl_time(j, measure) = huge(1.0_wp)
      rounds = 0
      call system_clock(start, rate)
      do
         y = y0
         call system_clock(t0)
         call pendulum_gsl(system%pendulum, y, t_end, tolerance, work, error)
         if (allocated(error)) error stop "bench_series: GSL failed"
         call system_clock(t1)
         gsl_time(j, measure) = min(gsl_time(j, measure), real(t1 - t0, wp)/rate)
         gsl_evals(j, measure) = real(work%n_evaluations, wp)
         gsl_err(j, measure) = run_error(measure, y)
         rounds = rounds + 1
         if (quick .and. rounds >= 2) exit
         if (rounds >= 5 .and. (real(t1 - start, wp)/rate > 1.5_wp .or. rounds >= 300)) exit
      end do
   end subroutine time_gsl_alone

   !> This integrator's cost (time or f-evaluations) over GSL's at the same error: GSL's
   !> log-cost interpolated in log-error between neighbouring points of its curve.
   real(wp) function ratio_to_gsl(measure, e, cost, gsl_cost) result(r)
      integer, intent(in) :: measure
      real(wp), intent(in) :: e, cost
      real(wp), intent(in) :: gsl_cost(:)  !! GSL's cost along its curve (gsl_err)
      real(wp) :: le(size(gsl_cost)), lc(size(gsl_cost)), w
      integer :: k
      le = log(gsl_err(:, measure))
      lc = log(gsl_cost)
      r = -1.0_wp
      do k = 1, size(gsl_cost) - 1
         if ((log(e) - le(k))*(log(e) - le(k + 1)) <= 0.0_wp .and. le(k) /= le(k + 1)) then
            w = (log(e) - le(k))/(le(k + 1) - le(k))
            r = cost/exp(lc(k) + w*(lc(k + 1) - lc(k)))
            return
         end if
      end do
   end function ratio_to_gsl
end program hillstab_bench_series

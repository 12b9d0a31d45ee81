!> Chaos indicators of the nonlinear pendulum: the finite-time Lyapunov exponent, MEGNO
!> and the FLI from one tangent vector, a verdict (chaotic, regular or undecided), and
!> early stopping once the verdict is certain. One entry point for one orbit
!> (`chaos_indicators`) and one for many (`chaos_indicators_batch`, orbits in lanes).
!>
!> Integrators (`chaos_options_t%integrator`):
!> - symplectic: without damping the pendulum is Hamiltonian with a separable H, and a
!>   fixed-step symplectic scheme with its tangent map (hillstab_pendulum_symplectic)
!>   advances the orbit and the tangent vector at a few force evaluations per step, its
!>   energy error bounded. The step per orbit comes from what the orbit needs
!>   (`chaos_steps_per_period`); the energy error is watched at every step, and a run
!>   whose error exceeds `energy_tolerance` is repeated with twice the steps, up to
!>   `max_steps_per_period`.
!> - dop853: the trajectory and the variational equations v' = J(y) v by DOP853 at the
!>   given tolerance, restarted every radial period as `lyapunov_largest` does (with
!>   early stopping off, the same exponent to the bit).
!> - auto (default): symplectic where that holds the energy tolerance within
!>   `max_steps_per_period`, DOP853 otherwise (close passes to the pivot, α → π²) and
!>   always with damping (ε > 0: not Hamiltonian).
!>
!> Indicators, all from the tangent vector δ with ‖δ‖² = δx² + δz² + (δx'² + δz'²)/ω²,
!> renormalised at the end of every radial period, and t in radial periods:
!> - `lyapunov`: λ_n = (1/n) Σ ln(‖δ(k)‖/‖δ(k−1)‖) (Benettin), per radial period;
!>   `spread`: max − min of λ_m over m ∈ [⌈n/2⌉, n] (as `lyapunov_largest`), how far it
!>   still moves; `lyapunov_error`: the error bar of λ_n by batch means of the growths
!>   (`lyapunov_error_bar`: 95 % half-width, B = min(5, n) batches, Student's t).
!> - `megno`: ⟨Y⟩(t) = (1/t) ∫₀ᵗ Y ds with Y(t) = (2/t) ∫₀ᵗ s (δ̇·δ)/(δ·δ) ds
!>   (Cincotta & Simó, A&AS 147 (2000) 205, eq. (2)–(3)), from the same tangent vector
!>   at no extra integration: on the symplectic scheme by the trapezoidal rule over its
!>   equal steps with δ̇ from the variational equations (hillstab_pendulum_chaos_track);
!>   on DOP853 from ln‖δ‖ by Gauss–Legendre on each step (`watch_step` says why).
!>   ⟨Y⟩ → 2 on quasi-periodic orbits, → 0 on stable periodic ones, ≈ λt/2 on chaotic ones.
!> - `fli`: max over the period ends of ln‖δ‖ (Froeschlé, Lega & Gonczi, Celest. Mech.
!>   Dyn. Astron. 67 (1997) 41), with ‖δ(0)‖ = 1.
!> - `chaotic`: the verdict of `chaos_verdict` (see there for the rule and thresholds).
!>
!> Pure numerics: no I/O, no module state, errors through error_t; threads may run
!> independent orbits or batches.
!>
!>```fortran
!> type(pendulum_t) :: p
!> type(chaos_t) :: result
!> type(error_t), allocatable :: error
!> call pendulum_from_chart(7.48_wp, 2.47_wp, 0.0_wp, 0.1_wp, 9.81_wp, p, error)
!> call chaos_indicators(p, pendulum_initial_state(p, 0.017_wp), 1000, 1.0e-10_wp, chaos_options_t(), result, error)
!> print *, result%chaotic, result%megno, result%lyapunov, result%periods
!>```
module hillstab_pendulum_chaos
   use hillstab_core_kinds, only: wp, int64
   use hillstab_core_error, only: error_t, set_error, err_invalid_parameter, err_integration, err_accuracy
   use hillstab_core_stats, only: work_stats_t, add_work
   use hillstab_integrate_rk, only: rk_step_t, rk_options_t, rk_integrate, rk_dop853, rk_dense_value
   use hillstab_pendulum_lyapunov, only: tangent_norm, lyapunov_error_bar
   use hillstab_pendulum_equations, only: pendulum_t, pendulum_tangent_t, pendulum_atol, pendulum_energy, &
      pendulum_radius, px, pz
   use hillstab_pendulum_symplectic, only: symplectic_scheme_t, symplectic_scheme, symplectic_scheme_count, &
      symplectic_scheme_name, tangent_lanes_t, lanes_allocate, lanes_load, lanes_step, lanes_state
   use hillstab_pendulum_chaos_track, only: chaos_options_t, chaos_verdict, chaos_verdict_rule, chaos_auto, &
      chaos_symplectic, chaos_dop853, chaos_transient_allowance, track_t, track_allocate, track_start, &
      track_period_end, track_move, sample_lanes, track_finish, track_refine
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   implicit none
   private
   public :: chaos_options_t, chaos_t, chaos_indicators, chaos_indicators_batch, chaos_verdict, chaos_transient_allowance, &
      chaos_steps_per_period, chaos_integrator_name, chaos_integrator_id, chaos_method_text, chaos_verdict_rule
   public :: chaos_auto, chaos_symplectic, chaos_dop853


   !> Result of `chaos_indicators` for one orbit.
   type :: chaos_t
      integer :: periods = 0           !! radial periods integrated (fewer than asked: stopped early or failed)
      real(wp) :: lyapunov = 0.0_wp    !! λ_n: finite-time largest Lyapunov exponent per radial period
      real(wp) :: spread = 0.0_wp      !! max − min of λ_m over m ∈ [⌈n/2⌉, n]
      !> error bar of λ_n: 95 % half-width by batch means of the growths (`lyapunov_error_bar`)
      real(wp) :: lyapunov_error = 0.0_wp
      real(wp) :: megno = 0.0_wp       !! ⟨Y⟩ at the end
      real(wp) :: fli = 0.0_wp         !! fast Lyapunov indicator: max ln‖δ‖ at the period ends
      real(wp) :: chaotic = 0.5_wp     !! verdict: 1 chaotic, 0 regular, 0.5 undecided
      logical :: stopped_early = .false.  !! the verdict was certain before the periods asked
      real(wp) :: max_abs_phi = 0.0_wp !! largest |φ| [rad] at the integrator's steps
      !> |E(end) − E(0)| over the sum of the energy terms' magnitudes at t = 0 (ε = 0)
      real(wp) :: energy_drift = 0.0_wp
      !> largest |E − E(0)| at the steps, on the same scale (ε = 0)
      real(wp) :: energy_error = 0.0_wp
      integer :: integrator = chaos_auto   !! the integrator that ran: chaos_symplectic or chaos_dop853
      integer :: scheme = 0                !! the symplectic scheme (0 when DOP853 ran)
      integer :: steps_per_period = 0      !! of the symplectic run (0 when DOP853 ran)
      integer :: attempts = 0              !! symplectic runs made (> 1: step refined after an energy error)
      !> steps and evaluations of all runs: force evaluations (symplectic; each gives the
      !> force and the Hessian) plus f-evaluations of the 8-D system (DOP853)
      type(work_stats_t) :: stats
      real(wp) :: final_state(4) = 0.0_wp  !! (x, z, x', z') at the end
      type(error_t), allocatable :: error  !! allocated when the orbit could not be computed
   end type chaos_t

   !> The tangent system of DOP853 with the bookkeeping of one orbit in its observer.
   type, extends(pendulum_tangent_t) :: watched_tangent_t
      type(track_t) :: track  !! one lane
      real(wp) :: integral_l = 0.0_wp      !! ∫₀ᵗ L ds, L = ln‖δ‖ (t in radial periods)
      real(wp) :: integral_l_log = 0.0_wp  !! ∫₀ᵗ L ln s ds
   contains
      procedure :: observe => watch_step
   end type watched_tangent_t

contains

   !> Name of an integrator choice ("auto", "symplectic", "dop853"; "" when unknown).
   pure function chaos_integrator_name(integrator) result(name)
      integer, intent(in) :: integrator  !! chaos_auto, chaos_symplectic or chaos_dop853
      character(len=:), allocatable :: name
      select case (integrator)
      case (chaos_auto); name = "auto"
      case (chaos_symplectic); name = "symplectic"
      case (chaos_dop853); name = "dop853"
      case default; name = ""
      end select
   end function chaos_integrator_name

   !> The integrator choice named `name` ("auto", "symplectic", "dop853"; −1 when unknown),
   !> for readers of scene variables.
   pure integer function chaos_integrator_id(name) result(id)
      character(len=*), intent(in) :: name  !! an integrator's name
      do id = chaos_auto, chaos_dop853
         if (chaos_integrator_name(id) == trim(name)) return
      end do
      id = -1
   end function chaos_integrator_id

   !> What `options` integrate with, in words (for file headers; under 240 characters):
   !> the integrator, the symplectic scheme and its step rule, the energy check and the
   !> fallback.
   function chaos_method_text(options, tolerance) result(text)
      type(chaos_options_t), intent(in) :: options  !! the options
      real(wp), intent(in) :: tolerance             !! the tolerance given to DOP853
      character(len=:), allocatable :: text         !! one line
      character(len=400) :: buffer
      character(len=80) :: steps
      if (options%steps_per_period > 0) then
         write (steps, '(i0,a)') options%steps_per_period, " steps per period"
      else
         write (steps, '(f0.1,a)') options%base_steps, " x max(1, r0/r_lo - 1)^(3/4) steps per period"
      end if
      select case (options%integrator)
      case (chaos_dop853)
         write (buffer, '(a,es7.1,a)') "integrator dop853: DOP853 on the orbit and the variational equations at ", &
            tolerance, ", restarted every radial period"
      case default
         write (buffer, '(a,a,a,a,a,es7.1,a,i0,a)') "integrator ", chaos_integrator_name(options%integrator), &
            ": symplectic "//symplectic_scheme_name(options%scheme)//" + tangent map, ", trim(steps), &
            ", energy error < ", options%energy_tolerance, " (else doubled steps, up to ", &
            options%max_steps_per_period, ")"
         if (options%integrator == chaos_auto) then
            write (buffer, '(a,es7.1,a)') trim(buffer)//"; else DOP853 at ", tolerance, " (and near the pivot, "// &
               "with damping)"
         end if
      end select
      text = trim(buffer)
   end function chaos_method_text

   !> Steps per radial period of the symplectic scheme for the orbit from y0: what the
   !> fastest motion it can reach needs. Energy bounds the orbit to r ≥ r_lo, the smaller
   !> root of ½ω²(r − r0)² − g r = E (the potential's minimum over the circle of radius
   !> r; for a start at rest near the axis, r_lo is the bounce's ρ − a). Near the pivot
   !> the tangential stiffness |∇²V| = ω²(r0/r − 1) exceeds the radial ω², so
   !>
   !>   N = ⌈base_steps · max(1, r0/r_lo − 1)^(3/4)⌉   (at most 1e9).
   !>
   !> The square root of max(1, r0/r_lo − 1) is the fastest local frequency over ω; the
   !> power 3/2 on it comes from energy errors measured at fixed N over the physical
   !> domain (at N = 16 the error of the order-6 scheme grew about like (r0/r_lo)⁵, not
   !> like the (r0/r_lo)³ of the frequency alone: the close pass is also a fast pass).
   !> The energy error is checked along the orbit anyway (`chaos_indicators`), so the rule
   !> only has to be a good first guess. 0 when the energy reaches the pivot (r_lo ≤ 0):
   !> no fixed step is safe there.
   pure integer function chaos_steps_per_period(p, y0, options) result(n)
      type(pendulum_t), intent(in) :: p              !! the pendulum
      real(wp), intent(in) :: y0(4)                  !! the start (x, z, x', z')
      type(chaos_options_t), intent(in) :: options   !! base_steps, max_steps_per_period
      real(wp) :: e, w2, root, r_lo, ratio
      if (options%steps_per_period > 0) then
         n = options%steps_per_period
         return
      end if
      w2 = p%omega**2
      e = pendulum_energy(p, y0)
      ! r_lo = ρ − √(ρ² − r0² + 2E/ω²) written without cancellation
      root = p%rho**2 - p%r0**2 + 2.0_wp*e/w2
      if (root < 0.0_wp) root = 0.0_wp
      r_lo = (p%r0**2 - 2.0_wp*e/w2)/(p%rho + sqrt(root))
      if (.not. (r_lo > 0.0_wp)) then
         n = 0
         return
      end if
      ratio = max(1.0_wp, p%r0/r_lo - 1.0_wp)
      n = ceiling(min(options%base_steps*ratio**0.75_wp, 1.0e9_wp))
   end function chaos_steps_per_period

   !> Chaos indicators of one orbit over `periods` radial periods from y0 (see the module
   !> description); the one-orbit form of `chaos_indicators_batch`.
   subroutine chaos_indicators(p, y0, periods, tolerance, options, result, error)
      type(pendulum_t), intent(in) :: p                !! the pendulum
      real(wp), intent(in) :: y0(4)                    !! initial state (x, z, x', z')
      integer, intent(in) :: periods                   !! radial periods N ≥ 1 (fewer if stopped early)
      real(wp), intent(in) :: tolerance                !! relative tolerance of DOP853 (> 0)
      type(chaos_options_t), intent(in) :: options     !! integrator, thresholds, early stop
      type(chaos_t), intent(out) :: result             !! indicators, verdict, work
      type(error_t), allocatable, intent(out) :: error !! invalid arguments; integration failure
      type(chaos_t) :: results(1)
      type(chaos_options_t) :: one_lane
      one_lane = options
      one_lane%lanes = 1
      call chaos_indicators_batch([p], reshape(y0, [4, 1]), periods, tolerance, one_lane, results)
      result = results(1)
      if (allocated(result%error)) error = result%error
   end subroutine chaos_indicators

   !> Chaos indicators of many orbits: `pendula(k)` from `y0(:, k)`, each over `periods`
   !> radial periods. Orbits on the symplectic scheme run `options%lanes` at a time in
   !> lanes, a finished lane taking the next orbit; every orbit's result is what
   !> `chaos_indicators` gives for it alone. An orbit that fails has its error in
   !> `results(k)%error` and the others are computed.
   subroutine chaos_indicators_batch(pendula, y0, periods, tolerance, options, results)
      type(pendulum_t), intent(in) :: pendula(:)      !! the pendula
      real(wp), intent(in) :: y0(:, :)                !! (4, size(pendula)): initial states
      integer, intent(in) :: periods                  !! radial periods N ≥ 1
      real(wp), intent(in) :: tolerance               !! relative tolerance of DOP853 (> 0)
      type(chaos_options_t), intent(in) :: options    !! integrator, thresholds, early stop, lanes
      type(chaos_t), intent(out) :: results(:)        !! one per orbit
      type(error_t), allocatable :: error
      logical, allocatable :: symplectic(:)
      integer, allocatable :: steps(:)
      integer :: k, n
      n = size(pendula)
      call check_options(options, periods, tolerance, error)
      if (.not. allocated(error) .and. (size(y0, 1) /= 4 .or. size(y0, 2) /= n .or. size(results) /= n)) &
         call set_error(error, err_invalid_parameter, "chaos_indicators_batch: y0 must be (4, n) and results (n)")
      if (allocated(error)) then
         do k = 1, size(results)
            results(k)%error = error
         end do
         return
      end if
      allocate (symplectic(n), steps(n))
      do k = 1, n
         symplectic(k) = .false.
         steps(k) = 0
         if (.not. all(ieee_is_finite(y0(:, k)))) then
            call set_error(results(k)%error, err_invalid_parameter, "chaos_indicators: non-finite initial state")
         else if (pendulum_radius(y0(:, k)) <= 0.0_wp) then
            call set_error(results(k)%error, err_invalid_parameter, "chaos_indicators: the start is at the pivot")
         else if (pendula(k)%kappa > 0.0_wp .and. options%integrator == chaos_symplectic) then
            call set_error(results(k)%error, err_invalid_parameter, &
               "chaos_indicators: the symplectic integrator needs epsilon = 0 (the damped pendulum is not Hamiltonian)")
         else if (options%integrator /= chaos_dop853 .and. pendula(k)%kappa == 0.0_wp) then
            ! auto: DOP853 where the rule asks for more than max_steps_per_period; symplectic:
            ! at most max_steps_per_period (the energy check then decides)
            steps(k) = chaos_steps_per_period(pendula(k), y0(:, k), options)
            if (options%integrator == chaos_symplectic) steps(k) = min(steps(k), options%max_steps_per_period)
            symplectic(k) = steps(k) > 0 .and. steps(k) <= options%max_steps_per_period
            if (options%integrator == chaos_symplectic .and. .not. symplectic(k)) &
               call set_error(results(k)%error, err_invalid_parameter, "chaos_indicators: the energy reaches the "// &
                  "pivot; no fixed step can be chosen (use integrator auto or dop853)")
         end if
      end do
      if (any(symplectic)) call run_lanes(pendula, y0, periods, options, symplectic, steps, results)
      ! DOP853: the damped orbits, those no fixed step suits and those the lanes gave up
      do k = 1, n
         if (allocated(results(k)%error)) cycle
         if (symplectic(k) .and. results(k)%integrator == chaos_symplectic) cycle
         call run_dop853(pendula(k), y0(:, k), periods, tolerance, options, results(k))
      end do
   end subroutine chaos_indicators_batch

   !> Arguments common to all orbits.
   pure subroutine check_options(options, periods, tolerance, error)
      type(chaos_options_t), intent(in) :: options
      integer, intent(in) :: periods
      real(wp), intent(in) :: tolerance
      type(error_t), allocatable, intent(out) :: error
      if (periods < 1) then
         call set_error(error, err_invalid_parameter, "chaos_indicators: periods must be >= 1")
      else if (.not. (ieee_is_finite(tolerance) .and. tolerance > 0.0_wp)) then
         call set_error(error, err_invalid_parameter, "chaos_indicators: tolerance must be > 0")
      else if (options%integrator < chaos_auto .or. options%integrator > chaos_dop853) then
         call set_error(error, err_invalid_parameter, "chaos_indicators: unknown integrator")
      else if (options%scheme < 1 .or. options%scheme > symplectic_scheme_count) then
         call set_error(error, err_invalid_parameter, "chaos_indicators: unknown symplectic scheme")
      else if (options%steps_per_period < 0 .or. options%max_steps_per_period < 4 .or. &
               .not. (options%base_steps >= 1.0_wp .and. options%base_steps <= 1.0e6_wp)) then
         call set_error(error, err_invalid_parameter, "chaos_indicators: steps_per_period must be >= 0, "// &
            "max_steps_per_period >= 4 and base_steps in [1, 1e6]")
      else if (.not. (options%energy_tolerance > 0.0_wp .and. ieee_is_finite(options%energy_tolerance))) then
         call set_error(error, err_invalid_parameter, "chaos_indicators: energy_tolerance must be > 0")
      else if (.not. (all(ieee_is_finite([options%megno_chaotic, options%megno_regular, options%megno_stop])) .and. &
                      options%megno_regular <= options%megno_chaotic)) then
         call set_error(error, err_invalid_parameter, "chaos_indicators: the MEGNO thresholds must be finite "// &
            "with megno_regular <= megno_chaotic")
      else if (options%min_periods < 1 .or. options%lanes < 1) then
         call set_error(error, err_invalid_parameter, "chaos_indicators: min_periods and lanes must be >= 1")
      end if
   end subroutine check_options

   !> The result of lane k (its orbit ended with state y).
   subroutine track_result(track, k, p, y, periods, options, result)
      type(track_t), intent(in) :: track
      integer, intent(in) :: k, periods
      type(pendulum_t), intent(in) :: p
      real(wp), intent(in) :: y(4)
      type(chaos_options_t), intent(in) :: options
      type(chaos_t), intent(inout) :: result
      real(wp) :: sum_log, running, low, high
      logical :: certain
      integer :: n, m, half
      n = track%done(k)
      result%periods = n
      sum_log = 0.0_wp
      low = huge(1.0_wp)
      high = -huge(1.0_wp)
      half = (n + 1)/2
      ! λ_m summed in the order of `lyapunov_largest` (the same bits on the same growths)
      do m = 1, n
         sum_log = sum_log + track%growth(m, k)
         running = sum_log/m
         if (m >= half) then
            low = min(low, running)
            high = max(high, running)
         end if
      end do
      result%lyapunov = sum_log/n
      result%spread = high - low
      result%lyapunov_error = lyapunov_error_bar(track%growth(:n, k))
      result%megno = track%megno(n, k)
      result%fli = track%fli(k)
      call chaos_verdict(options, n, periods, track%megno(n, k), track%megno((n + 1)/2, k), track%allowance(k), &
         result%chaotic, certain)
      result%stopped_early = n < periods
      result%max_abs_phi = 2.0_wp*atan2(track%swing_x(k), track%swing_w(k))
      result%energy_drift = abs(pendulum_energy(p, y) - track%e0(k))/track%scale(k)
      result%energy_error = track%de(k)/track%scale(k)
      result%final_state = y
      result%attempts = track%attempts(k)
   end subroutine track_result

   ! ---------------------------------------------------------------------------------
   ! Symplectic lanes
   ! ---------------------------------------------------------------------------------

   !> The orbits with `selected(k)` on the symplectic scheme, `options%lanes` at a time.
   !> An orbit whose energy error exceeds the tolerance is restarted with twice the steps;
   !> beyond max_steps_per_period it is left to DOP853 (auto; results(k)%integrator stays
   !> chaos_auto) or fails with err_accuracy (symplectic).
   subroutine run_lanes(pendula, y0, periods, options, selected, steps, results)
      type(pendulum_t), intent(in) :: pendula(:)
      real(wp), intent(in) :: y0(:, :)
      integer, intent(in) :: periods
      type(chaos_options_t), intent(in) :: options
      logical, intent(in) :: selected(:)
      integer, intent(in) :: steps(:)  !! first steps per radial period of each selected orbit
      type(chaos_t), intent(inout) :: results(:)
      type(tangent_lanes_t) :: lanes
      type(track_t) :: track
      integer :: capacity
      capacity = min(options%lanes, count(selected))
      call lanes_allocate(lanes, capacity)
      call track_allocate(track, capacity, periods)
      call drive_lanes(pendula, y0, periods, options, selected, steps, results, lanes, track)
   end subroutine run_lanes

   !> The loop of `run_lanes` over allocated lanes and track (dummy arguments, not
   !> locals: the compiler vectorises the loops over them only then).
   subroutine drive_lanes(pendula, y0, periods, options, selected, steps, results, lanes, track)
      type(pendulum_t), intent(in) :: pendula(:)
      real(wp), intent(in) :: y0(:, :)
      integer, intent(in) :: periods
      type(chaos_options_t), intent(in) :: options
      logical, intent(in) :: selected(:)
      integer, intent(in) :: steps(:)
      type(chaos_t), intent(inout) :: results(:)
      type(tangent_lanes_t), intent(inout) :: lanes
      type(track_t), intent(inout) :: track
      type(symplectic_scheme_t) :: scheme
      real(wp), parameter :: d0(4) = 0.5_wp*[1.0_wp, 1.0_wp, 1.0_wp, 1.0_wp]
      real(wp) :: norm, y(4), d(4)
      integer :: capacity, next, l, n, action, k
      scheme = symplectic_scheme(options%scheme)
      capacity = size(lanes%x)
      next = 0
      n = 0
      ! fill the lanes
      do l = 1, capacity
         call take_next(lanes, track, l)
      end do
      n = lanes%n
      do while (n > 0)
         call lanes_step(scheme, lanes)
         call sample_lanes(lanes, track)
         if (.not. any(track%step(1:n) == track%steps(1:n))) cycle
         ! period ends, lane by lane
         l = 1
         do while (l <= n)
            if (track%step(l) /= track%steps(l)) then
               l = l + 1
               cycle
            end if
            k = track%point(l)
            norm = tangent_norm(pendula(k), [lanes%dx(l), lanes%dz(l), lanes%dvx(l), lanes%dvz(l)])
            if (.not. (norm > 0.0_wp .and. ieee_is_finite(norm) .and. ieee_is_finite(track%i2(l)))) then
               call lanes_state(lanes, l, y, d)
               results(k)%periods = track%done(l)
               call set_error(results(k)%error, err_integration, "chaos_indicators: tangent vector lost (zero or "// &
                  "not finite) on the symplectic scheme")
               call release(lanes, track, l)
               cycle
            end if
            lanes%dx(l) = lanes%dx(l)/norm
            lanes%dz(l) = lanes%dz(l)/norm
            lanes%dvx(l) = lanes%dvx(l)/norm
            lanes%dvz(l) = lanes%dvz(l)/norm
            call track_period_end(track, l, norm, periods, options, action)
            if (track%de(l) > options%energy_tolerance*track%scale(l)) action = track_refine
            select case (action)
            case (track_finish)
               call lanes_state(lanes, l, y, d)
               call track_result(track, l, pendula(k), y, periods, options, results(k))
               results(k)%integrator = chaos_symplectic
               results(k)%scheme = options%scheme
               results(k)%steps_per_period = track%steps(l)
               results(k)%stats%n_steps = results(k)%stats%n_steps + int(track%done(l), int64)*track%steps(l)
               results(k)%stats%n_evaluations = track%evaluations(l) + 1_int64 + &
                                                int(track%done(l), int64)*track%steps(l)*scheme%stages
               call release(lanes, track, l)
            case (track_refine)
               track%evaluations(l) = track%evaluations(l) + 1_int64 + &
                                      int(track%done(l), int64)*track%steps(l)*scheme%stages
               results(k)%stats%n_steps = results(k)%stats%n_steps + int(track%done(l), int64)*track%steps(l)
               if (2*track%steps(l) <= options%max_steps_per_period) then
                  call start(lanes, track, l, k, 2*track%steps(l))
                  l = l + 1
               else
                  ! left to DOP853 (auto) with the work done so far counted
                  results(k)%attempts = track%attempts(l)
                  results(k)%stats%n_evaluations = track%evaluations(l)
                  if (options%integrator == chaos_symplectic) then
                     call lanes_state(lanes, l, y, d)
                     call track_result(track, l, pendula(k), y, periods, options, results(k))
                     results(k)%integrator = chaos_symplectic
                     results(k)%scheme = options%scheme
                     results(k)%steps_per_period = track%steps(l)
                     call set_error(results(k)%error, err_accuracy, "chaos_indicators: the energy error exceeds "// &
                        "energy_tolerance at max_steps_per_period steps per radial period")
                  end if
                  call release(lanes, track, l)
               end if
            case default
               l = l + 1
            end select
         end do
      end do

   contains

      !> Put the next selected orbit into lane l (or leave it empty).
      subroutine take_next(lanes, track, l)
         type(tangent_lanes_t), intent(inout) :: lanes
         type(track_t), intent(inout) :: track
         integer, intent(in) :: l
         do while (next < size(pendula))
            next = next + 1
            if (.not. selected(next)) cycle
            track%attempts(l) = 0
            track%evaluations(l) = 0
            call start(lanes, track, l, next, steps(next))
            return
         end do
         track%point(l) = 0
      end subroutine take_next

      !> (Re)start orbit k in lane l with `steps` steps per radial period. (The lanes and
      !> the track are passed, not host-associated: the loops over them in run_lanes are
      !> then vectorised.)
      subroutine start(lanes, track, l, k, steps)
         type(tangent_lanes_t), intent(inout) :: lanes
         type(track_t), intent(inout) :: track
         integer, intent(in) :: l, k, steps
         real(wp) :: d_start(4)
         d_start = d0*[1.0_wp, 1.0_wp, pendula(k)%omega, pendula(k)%omega]
         call lanes_load(lanes, l, pendula(k), y0(:, k), d_start, pendula(k)%period/steps)
         call track_start(track, l, k, pendula(k), y0(:, k), d_start, steps)
      end subroutine start

      !> Lane l is free: the next orbit takes it, or the last lane in use moves into it.
      subroutine release(lanes, track, l)
         type(tangent_lanes_t), intent(inout) :: lanes
         type(track_t), intent(inout) :: track
         integer, intent(in) :: l
         real(wp) :: y_last(4), d_last(4)
         integer :: last
         call take_next(lanes, track, l)
         if (track%point(l) /= 0) return
         last = n
         if (last /= l) then
            call lanes_state(lanes, last, y_last, d_last)
            call lanes_load(lanes, l, pendula(track%point(last)), y_last, d_last, lanes%h(last))
            call track_move(track, last, l)
         end if
         n = n - 1
         lanes%n = n
      end subroutine release
   end subroutine drive_lanes


   ! ---------------------------------------------------------------------------------
   ! DOP853
   ! ---------------------------------------------------------------------------------

   !> One orbit by DOP853 on the trajectory and the variational equations, one
   !> rk_integrate call per radial period starting with the step predicted at the end
   !> of the previous one, with the tolerances of `lyapunov_largest`.
   subroutine run_dop853(p, y0, periods, tolerance, options, result)
      type(pendulum_t), intent(in) :: p
      real(wp), intent(in) :: y0(4)
      integer, intent(in) :: periods
      real(wp), intent(in) :: tolerance
      type(chaos_options_t), intent(in) :: options
      type(chaos_t), intent(inout) :: result
      type(watched_tangent_t) :: system
      type(rk_options_t) :: rk
      type(work_stats_t) :: part
      type(error_t), allocatable :: error
      real(wp) :: y(8), t, h_next, norm
      integer :: n, action, attempts
      character(len=120) :: text
      system%pendulum = p
      attempts = result%attempts
      call track_allocate(system%track, 1, periods)
      y(1:4) = y0
      y(5:8) = 0.5_wp*[1.0_wp, 1.0_wp, p%omega, p%omega]
      call track_start(system%track, 1, 1, p, y0, y(5:8), 1)
      rk = rk_options_t(method=rk_dop853, rtol=tolerance, atol=tolerance, max_steps=1000000)
      rk%atol_components = [pendulum_atol(p, y0, tolerance), tolerance*[1.0_wp, 1.0_wp, p%omega, p%omega]]
      t = 0.0_wp
      h_next = 0.0_wp
      do n = 1, periods
         rk%h_initial = h_next
         call rk_integrate(system, t, n*p%period, y, rk, part, error, h_next=h_next)
         call add_work(result%stats, part)
         if (allocated(error)) then
            write (text, '(a,i0,a)') "chaos_indicators: DOP853: radial period ", n, ": "
            call set_error(result%error, error%code, trim(text)//" "//error%message)
            result%periods = n - 1
            return
         end if
         norm = tangent_norm(p, y(5:8))
         if (.not. (norm > 0.0_wp .and. ieee_is_finite(norm) .and. ieee_is_finite(system%track%i2(1)))) then
            write (text, '(a,i0)') "chaos_indicators: tangent vector lost (zero or not finite) in radial period ", n
            call set_error(result%error, err_integration, trim(text))
            result%periods = n - 1
            return
         end if
         y(5:8) = y(5:8)/norm
         call track_period_end(system%track, 1, norm, periods, options, action)
         if (action == track_finish) exit
      end do
      call track_result(system%track, 1, p, y(1:4), periods, options, result)
      result%integrator = chaos_dop853
      result%scheme = 0
      result%steps_per_period = 0
      result%attempts = attempts
   end subroutine run_dop853

   !> The observer: per accepted step the samples of the lanes (energy, largest angle)
   !> and MEGNO. The steps of DOP853 are not uniform, and the trapezoidal rule on
   !> s (δ̇·δ)/(δ·δ) over them (as the lanes do over their equal steps) would leave an error
   !> that grows with t where the steps shrink and grow in step with the oscillation of
   !> δ̇·δ. So here MEGNO is taken in the equivalent form
   !>
   !>   ⟨Y⟩(t) = (2/t) [A(t) (1 − ln t) + B(t)],   A = ∫₀ᵗ L ds,   B = ∫₀ᵗ L ln s ds,
   !>
   !> (Y(s) = 2(L(s) − A(s)/s) integrated by parts), L = ln‖δ‖ with the renormalisations
   !> added back, and A and B by 2-point Gauss–Legendre on every step with δ from the step's
   !> cubic Hermite interpolant: an error of order h⁴ per unit time, which stays small.
   subroutine watch_step(self, step, stop)
      class(watched_tangent_t), intent(inout) :: self
      type(rk_step_t), intent(in) :: step
      logical, intent(inout) :: stop
      real(wp), parameter :: gauss_offset = 0.5_wp/sqrt(3.0_wp)  ! nodes 1/2 ∓ √3/6 on [0, 1]
      real(wp) :: t, t_old, dt, s, level, ax, az, r, node(8)
      integer :: j
      if (step%index == 0) return
      associate (track => self%track, y => step%y)
         t = step%t/track%period(1)
         t_old = step%t_old/track%period(1)
         dt = t - t_old
         track%t(1) = t
         track%de(1) = max(track%de(1), abs(pendulum_energy(self%pendulum, y(1:4)) - track%e0(1)))
         r = pendulum_radius(y)
         ax = abs(y(px))
         az = r + y(pz)
         if (ax*track%swing_w(1) > track%swing_x(1)*az) then
            track%swing_x(1) = ax
            track%swing_w(1) = az
         end if
         do j = -1, 1, 2
            s = t_old + dt*(0.5_wp + j*gauss_offset)
            node = rk_dense_value(step, s*track%period(1))
            level = track%level(1) + log(tangent_norm(self%pendulum, node(5:8)))
            self%integral_l = self%integral_l + 0.5_wp*dt*level
            self%integral_l_log = self%integral_l_log + 0.5_wp*dt*level*log(s)
         end do
         ! I₂ = t ⟨Y⟩, as the lanes keep it
         track%i2(1) = 2.0_wp*(self%integral_l*(1.0_wp - log(t)) + self%integral_l_log)
      end associate
   end subroutine watch_step
end module hillstab_pendulum_chaos

!> Adaptive embedded Runge–Kutta integrators for first-order systems y' = f(t, y):
!> Dormand–Prince 5(4) (DOPRI5), Dormand–Prince 8(5,3) (DOP853), Prince–Dormand 8(7)
!> (PD87, the pair of GSL's rk8pd) and Verner's most efficient 9(8) pair (VERN98), the last
!> two without continuous extension of their own, with Hairer's error norm, PI step-size
!> control, initial step guess and continuous (dense) output,
!> plus a fixed-step mode without error control for convergence studies.
!>
!> The step control, error norms and dense output follow E. Hairer, S. P. Nørsett,
!> G. Wanner, *Solving Ordinary Differential Equations I*, 2nd ed., Springer 1993,
!> §II.4–II.6 and §IV.2, as implemented in Hairer's codes dopri5.f and dop853.f
!> (versions of 1996). The pairs' coefficients and their provenance are in
!> hillstab_integrate_rk_tableaux, their one-step kernels in hillstab_integrate_rk_stages;
!> this module is the driver: arguments, step control, accepted steps, dense output and
!> the observer, with the state of one integration in a `rk_driver_t`.
!>
!> The system is an extension of the abstract type `rk_system_t`: its components carry
!> the parameters, its deferred binding `rhs` computes f, and its binding `observe`
!> (a no-op unless overridden) sees the initial point and every accepted step with its
!> continuous extension (`rk_dense_value`) and may stop the integration. No procedure
!> is passed as an argument, so callers need no internal procedures (gfortran would
!> build trampolines for those and the program would need an executable stack). The
!> module has no state: independent integrations may run in parallel threads.
!>
!>```fortran
!> type, extends(rk_system_t) :: oscillator_t
!>    real(wp) :: omega = 1.0_wp
!> contains
!>    procedure :: rhs => oscillator_rhs
!> end type oscillator_t
!> ...
!> type(oscillator_t) :: oscillator
!> type(rk_options_t) :: options
!> type(error_t), allocatable :: error
!> real(wp) :: t, y(2), t_out(3), y_out(2, 3)
!> t = 0.0_wp; y = [1.0_wp, 0.0_wp]; t_out = [0.5_wp, 1.0_wp, 2.0_wp]
!> options = rk_options_t(method=rk_dop853, rtol=1.0e-10_wp, atol=1.0e-10_wp)
!> call rk_integrate(oscillator, t, 2.0_wp, y, options, error=error, t_out=t_out, y_out=y_out)
!> ...
!> subroutine oscillator_rhs(self, t, y, dydt)
!>    class(oscillator_t), intent(inout) :: self
!>    real(wp), intent(in) :: t, y(:)
!>    real(wp), intent(out) :: dydt(:)
!>    dydt = [y(2), -self%omega**2*y(1)]
!> end subroutine oscillator_rhs
!>```
module hillstab_integrate_rk
   use hillstab_core_kinds, only: wp
   use hillstab_core_error, only: error_t, set_error, err_invalid_parameter, err_integration
   use hillstab_core_stats, only: work_stats_t
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use hillstab_integrate_rk_tableaux, only: rk_dopri5, rk_dop853, rk_pd87, rk_vern98, rk_pair_t, rk_pairs, &
      rk_method_name, rk_method_order, rk_beta_limit, rk_vern98_tableau
   use hillstab_integrate_rk_stages, only: rk_system_t, rk_rhs, rk_observe, rk_step_t, rk_stages_t, rk_stages_start, &
      rk_trial_step, rk_evaluate, rk_evaluate_new_point, rk_dense_extension, rk_accept_step
   implicit none
   private
   public :: rk_system_t, rk_rhs, rk_observe, rk_options_t, rk_step_t, rk_integrate, rk_dense_value
   public :: rk_beta_limit
   public :: rk_dopri5, rk_dop853, rk_pd87, rk_vern98, rk_method_name, rk_method_order, rk_vern98_tableau

   !> Options of `rk_integrate`. Zero (or negative) values of the step-control
   !> parameters select the defaults of Hairer's codes for the chosen method.
   type :: rk_options_t
      integer :: method = rk_dop853       !! rk_dopri5, rk_dop853, rk_pd87 or rk_vern98
      real(wp) :: rtol = 1.0e-10_wp       !! relative tolerance (≥ 0)
      real(wp) :: atol = 1.0e-10_wp       !! absolute tolerance (> 0)
      real(wp), allocatable :: atol_components(:)  !! per-component absolute tolerances (all > 0,
                                          !! size of the state); when allocated they replace
                                          !! `atol` (Hairer's ITOL = 1)
      real(wp) :: h_initial = 0.0_wp      !! first step; 0 → Hairer's initial guess (hinit)
      real(wp) :: h_max = 0.0_wp          !! largest |h|; 0 → |t_end − t|
      integer :: max_steps = 100000       !! attempted steps (accepted + rejected) before failing
      integer :: fixed_steps = 0          !! > 0: this many equal steps, no error control
      real(wp) :: safety = 0.9_wp         !! safety factor of the step prediction
      real(wp) :: beta = -1.0_wp          !! PI (Lund) stabilisation; < 0 → 0.04 (DOPRI5), 0 (others);
                                          !! must lie below `rk_beta_limit` (0.114 DOPRI5,
                                          !! 0.104 DOP853/PD87, 0.093 VERN98)
      real(wp) :: fac_min = 0.0_wp        !! smallest h_new/h; 0 → 0.2 (DOPRI5), 0.333 (others)
      real(wp) :: fac_max = 0.0_wp        !! largest h_new/h; 0 → 10 (DOPRI5), 6 (others)
      logical :: dense_output = .false.   !! build DOP853's 7th-order interpolant every step
                                          !! (3 more evaluations); implied by `t_out`;
                                          !! refused by rk_pd87 and rk_vern98
   end type rk_options_t

   !> Unit round-off used in the step-size underflow test (Hairer's UROUND).
   real(wp), parameter :: unit_roundoff = epsilon(1.0_wp)

   !> Step-control parameters resolved from the options and the method defaults.
   type :: controller_t
      real(wp) :: safety, beta, fac_min, fac_max, exponent, h_max
      real(wp) :: fac_old = 1.0e-4_wp   !! previous accepted error (Hairer's FACOLD)
   end type controller_t

   !> The state of one integration by `rk_integrate`, handed to the driver's procedures
   !> (which once were internal procedures sharing the host's variables): the pair, the
   !> stage workspace the kernels of hillstab_integrate_rk_stages work in, the accepted
   !> step the observer sees, the step control, the work done and the next output.
   type :: rk_driver_t
      type(rk_pair_t) :: pair              ! what the driver needs to know of the method
      integer :: method = rk_dop853        ! the method code
      integer :: n = 0                     ! components of the state
      real(wp) :: t_end = 0.0_wp           ! end of the interval
      real(wp) :: direction = 1.0_wp       ! sign(t_end − t)
      real(wp) :: span = 0.0_wp            ! |t_end − t|
      type(rk_stages_t) :: stages          ! stage array, its views, tolerances, f-evaluations
      type(rk_step_t) :: step              ! the last accepted step, as the observer sees it
      type(controller_t) :: control        ! resolved step-control parameters
      type(work_stats_t) :: work           ! steps and rejections (evaluations: in `stages`)
      integer :: next_out = 1              ! next entry of t_out to fill
      logical :: stop = .false.            ! the observer asked to stop
      logical :: want_dense = .false.      ! the 7th-order extension of DOP853 is built
   end type rk_driver_t

contains

   !> The continuous extension of `step` at time t (t in [t_old, t]; mild
   !> extrapolation is allowed but not accurate). `step` must come from rk_integrate
   !> (its arrays are allocated there). Hairer's CONTD5/CONTD8 form:
   !> y = d0 + s(d1 + s'(d2 + s(d3 + s'(d4 + s(d5 + s'(d6 + s d7)))))), s = (t − t_old)/h, s' = 1 − s.
   pure function rk_dense_value(step, t) result(y)
      type(rk_step_t), intent(in) :: step  !! an accepted step with its dense coefficients
      real(wp), intent(in) :: t            !! where to evaluate
      real(wp) :: y(size(step%y))
      real(wp) :: s, s1
      if (t == step%t .or. step%h == 0.0_wp) then
         y = step%y
         return
      end if
      s = (t - step%t_old)/step%h
      s1 = 1.0_wp - s
      associate (d => step%dense)
         y = d(:, 0) + s*(d(:, 1) + s1*(d(:, 2) + s*(d(:, 3) + s1*(d(:, 4) &
             + s*(d(:, 5) + s1*(d(:, 6) + s*d(:, 7)))))))
      end associate
   end function rk_dense_value

   !> Integrate y' = f(t, y) from t to t_end.
   !>
   !> Adaptive mode (default): local error per step kept below rtol·|y| + atol in
   !> Hairer's norm; fixed-step mode (`options%fixed_steps` = N > 0): N equal steps,
   !> no error control. On return t is where the integration ended (t_end unless an
   !> observer stopped it or it failed) and y the state there. On failure `error` is
   !> allocated (code err_integration or err_invalid_parameter) and t, y hold the last
   !> accepted point, never a non-finite value.
   subroutine rk_integrate(system, t, t_end, y, options, stats, error, t_out, y_out, h_next)
      class(rk_system_t), intent(inout) :: system  !! right-hand side, its data and its observer
      real(wp), intent(inout) :: t             !! start in, end reached out
      real(wp), intent(in) :: t_end            !! end of the interval (t_end < t integrates backwards)
      real(wp), intent(inout) :: y(:)          !! initial state in, final state out
      type(rk_options_t), intent(in) :: options  !! method, tolerances, step control
      type(work_stats_t), intent(out), optional :: stats  !! accepted steps, rejected steps (including
                                                          !! those of the first step, which Hairer's
                                                          !! codes do not count), f-evaluations
      type(error_t), allocatable, intent(out) :: error    !! allocated on failure
      real(wp), intent(in), optional :: t_out(:)  !! output times, monotone from t towards t_end
      real(wp), intent(out), optional :: y_out(:, :)  !! (size(y), size(t_out)) dense output there
      real(wp), intent(out), optional :: h_next  !! predicted next step (to resume an integration)
      ! t_out and y_out go on to the driver as ordinary arrays, empty when absent: gfortran 12
      ! builds the descriptor of an absent optional array passed on to another optional dummy
      ! from strides it set only when the array is present (offset = -stride1 - stride2 on
      ! stale registers; the descriptor is then discarded, but UBSan reports the overflow:
      ! scripts/sanitize/absent_optional.f90 shows it)
      real(wp) :: no_times(0), no_states(0, 0)

      if (present(h_next)) h_next = 0.0_wp
      call check_arguments(t, t_end, y, options, present(t_out), present(y_out), error)
      if (.not. allocated(error) .and. present(t_out) .and. present(y_out)) &
         call check_outputs(t, t_end, size(y), t_out, y_out, error)
      if (allocated(error)) then
         if (present(stats)) stats = work_stats_t()
         return
      end if
      if (present(t_out) .and. present(y_out)) then
         call integrate_outputs(system, t, t_end, y, options, .true., t_out, y_out, error, stats, h_next)
      else
         call integrate_outputs(system, t, t_end, y, options, .false., no_times, no_states, error, stats, h_next)
      end if
   end subroutine rk_integrate

   !> `rk_integrate` once its arguments are checked; `outputs` tells whether the caller gave
   !> t_out and y_out (else both are empty).
   subroutine integrate_outputs(system, t, t_end, y, options, outputs, t_out, y_out, error, stats, h_next)
      class(rk_system_t), intent(inout) :: system
      real(wp), intent(inout) :: t
      real(wp), intent(in) :: t_end
      real(wp), intent(inout) :: y(:)
      type(rk_options_t), intent(in) :: options
      logical, intent(in) :: outputs
      real(wp), intent(in) :: t_out(:)
      real(wp), intent(inout) :: y_out(:, :)
      type(error_t), allocatable, intent(inout) :: error
      type(work_stats_t), intent(out), optional :: stats
      real(wp), intent(inout), optional :: h_next
      type(rk_driver_t), target :: d
      call start_driver(d, t, t_end, y, options, outputs .or. options%dense_output)
      call fill_outputs(d, t_out, y_out)
      if (t == t_end) then
         call finish(d, t, y, stats)
         return
      end if

      call rk_evaluate(d%stages, system, t, y, d%stages%k(:, 1))
      if (.not. d%stages%finite) then
         call fail_non_finite(d, t, "initial state", error)
         call finish(d, t, y, stats)
         return
      end if

      call system%observe(d%step, d%stop)
      if (.not. d%stop) then
         if (options%fixed_steps > 0) then
            call integrate_fixed(d, system, t, options, error, t_out, y_out, h_next)
         else
            call integrate_adaptive(d, system, options, error, t_out, y_out, h_next)
         end if
      end if
      call finish(d, t, y, stats)
   end subroutine integrate_outputs

   !> The arguments of `rk_integrate` checked: err_invalid_parameter naming the first bad one.
   !> (The shapes and values of t_out and y_out, when both are given, by `check_outputs`.)
   subroutine check_arguments(t, t_end, y, options, has_t_out, has_y_out, error)
      real(wp), intent(in) :: t, t_end, y(:)
      type(rk_options_t), intent(in) :: options
      logical, intent(in) :: has_t_out, has_y_out
      type(error_t), allocatable, intent(out) :: error
      character(len=160) :: message
      integer :: n
      n = size(y)
      if (options%method < 1 .or. options%method > size(rk_pairs)) then
         call set_error(error, err_invalid_parameter, "rk_integrate: unknown method")
      else if (rk_pairs(options%method)%dense_order == 0 .and. (has_t_out .or. options%dense_output)) then
         call set_error(error, err_invalid_parameter, "rk_integrate: "//rk_method_name(options%method)// &
            " has no continuous extension of its order; use dop853 for t_out or dense_output")
      else if (n < 1) then
         call set_error(error, err_invalid_parameter, "rk_integrate: empty state vector")
      else if (.not. (ieee_is_finite(t) .and. ieee_is_finite(t_end))) then
         call set_error(error, err_invalid_parameter, "rk_integrate: t and t_end must be finite")
      else if (.not. all(ieee_is_finite(y))) then
         call set_error(error, err_invalid_parameter, "rk_integrate: non-finite initial state")
      else if (.not. all(ieee_is_finite([options%rtol, options%atol, options%h_initial, options%h_max, &
                                         options%safety, options%beta, options%fac_min, options%fac_max]))) then
         call set_error(error, err_invalid_parameter, "rk_integrate: non-finite option")
      else if (options%fixed_steps < 0) then
         call set_error(error, err_invalid_parameter, "rk_integrate: fixed_steps must be >= 0")
      else if (options%fixed_steps == 0 .and. (options%rtol < 0.0_wp .or. options%atol <= 0.0_wp)) then
         call set_error(error, err_invalid_parameter, "rk_integrate: need rtol >= 0 and atol > 0")
      else if (.not. atol_components_valid(options, n)) then
         call set_error(error, err_invalid_parameter, &
            "rk_integrate: atol_components must have the size of y, be finite and > 0")
      else if (options%max_steps < 1) then
         call set_error(error, err_invalid_parameter, "rk_integrate: max_steps must be >= 1")
      else if (options%safety <= 1.0e-4_wp .or. options%safety >= 1.0_wp) then
         call set_error(error, err_invalid_parameter, "rk_integrate: safety must lie in (1e-4, 1)")
      else if (options%beta >= rk_beta_limit(options%method)) then
         write (message, '(a,es10.3,a,f6.4,a)') "rk_integrate: beta = ", options%beta, " must be < ", &
            rk_beta_limit(options%method), " for "//rk_method_name(options%method)// &
            " (above it the step control drives the error towards zero and the steps collapse)"
         call set_error(error, err_invalid_parameter, trim(message))
      else if (options%h_max < 0.0_wp) then
         call set_error(error, err_invalid_parameter, "rk_integrate: h_max must be >= 0")
      else if (options%fac_min > 1.0_wp .or. (options%fac_max > 0.0_wp .and. options%fac_max < 1.0_wp)) then
         call set_error(error, err_invalid_parameter, "rk_integrate: need fac_min <= 1 <= fac_max")
      else if (has_t_out .neqv. has_y_out) then
         call set_error(error, err_invalid_parameter, "rk_integrate: t_out and y_out go together")
      end if
   end subroutine check_arguments

   !> The output times and their array checked: err_invalid_parameter naming the first fault.
   subroutine check_outputs(t, t_end, n, t_out, y_out, error)
      real(wp), intent(in) :: t, t_end
      integer, intent(in) :: n
      real(wp), intent(in) :: t_out(:), y_out(:, :)
      type(error_t), allocatable, intent(inout) :: error
      if (size(y_out, 1) /= n .or. size(y_out, 2) /= size(t_out)) then
         call set_error(error, err_invalid_parameter, "rk_integrate: y_out must be (size(y), size(t_out))")
      else if (.not. all(ieee_is_finite(t_out))) then
         call set_error(error, err_invalid_parameter, "rk_integrate: non-finite output time")
      else if (.not. outputs_ordered(t, t_end, t_out)) then
         call set_error(error, err_invalid_parameter, &
            "rk_integrate: t_out must be monotone from t towards t_end and lie in between")
      end if
   end subroutine check_outputs

   logical function atol_components_valid(options, n) result(valid)
      type(rk_options_t), intent(in) :: options
      integer, intent(in) :: n
      valid = .true.
      if (.not. allocated(options%atol_components)) return
      valid = size(options%atol_components) == n
      if (valid) valid = all(ieee_is_finite(options%atol_components)) .and. all(options%atol_components > 0.0_wp)
   end function atol_components_valid

   logical function outputs_ordered(t, t_end, t_out)
      real(wp), intent(in) :: t, t_end, t_out(:)
      real(wp) :: dir, previous
      integer :: j
      dir = sign(1.0_wp, t_end - t)
      previous = t
      outputs_ordered = .true.
      do j = 1, size(t_out)
         if ((t_out(j) - previous)*dir < 0.0_wp .or. (t_out(j) - t_end)*dir > 0.0_wp) then
            outputs_ordered = .false.
            return
         end if
         previous = t_out(j)
      end do
   end function outputs_ordered

   !> The driver at (t, y): the pair's row, the stage workspace (tolerances, stage array and
   !> its pointer views), the step record of the initial point.
   subroutine start_driver(d, t, t_end, y, options, want_dense)
      type(rk_driver_t), intent(inout), target :: d
      real(wp), intent(in) :: t, t_end, y(:)
      type(rk_options_t), intent(in) :: options
      logical, intent(in) :: want_dense
      real(wp), allocatable :: atol(:)
      d%method = options%method
      d%pair = rk_pairs(options%method)
      d%n = size(y)
      if (allocated(options%atol_components)) then
         atol = options%atol_components
      else
         allocate (atol(d%n), source=options%atol)
      end if
      call rk_stages_start(d%stages, options%method, d%n, d%pair%columns, atol, options%rtol)
      d%want_dense = want_dense
      d%work = work_stats_t()
      allocate (d%step%y(d%n), d%step%dense(d%n, 0:7))
      d%step%method = options%method
      d%step%dense = 0.0_wp
      d%step%t_old = t; d%step%t = t; d%step%h = 0.0_wp; d%step%y = y
      d%t_end = t_end
      d%direction = sign(1.0_wp, t_end - t)
      d%span = abs(t_end - t)
      d%next_out = 1
      d%stop = .false.
   end subroutine start_driver

   !> t, y and the work counted where the integration ended.
   subroutine finish(d, t, y, stats)
      type(rk_driver_t), intent(in) :: d
      real(wp), intent(inout) :: t, y(:)
      type(work_stats_t), intent(out), optional :: stats
      t = d%step%t
      y = d%step%y
      if (present(stats)) then
         stats = d%work
         stats%n_evaluations = d%stages%n_evaluations
      end if
   end subroutine finish

   subroutine fail_non_finite(d, tau, where, error)
      type(rk_driver_t), intent(in) :: d
      real(wp), intent(in) :: tau
      character(len=*), intent(in) :: where
      type(error_t), allocatable, intent(out) :: error
      character(len=160) :: message
      write (message, '(a,es24.16,a)') "rk_integrate: non-finite derivative at t = ", tau, " ("//where//")"
      call set_error(error, err_integration, trim(message))
   end subroutine fail_non_finite

   !> Fill the outputs up to the current step (dense output on [t_old, t]).
   subroutine fill_outputs(d, t_out, y_out)
      type(rk_driver_t), intent(inout) :: d
      real(wp), intent(in) :: t_out(:)
      real(wp), intent(inout) :: y_out(:, :)
      do while (d%next_out <= size(t_out))
         if ((t_out(d%next_out) - d%step%t)*d%direction > 0.0_wp) exit
         if (t_out(d%next_out) == d%step%t) then
            y_out(:, d%next_out) = d%step%y
         else
            y_out(:, d%next_out) = rk_dense_value(d%step, t_out(d%next_out))
         end if
         d%next_out = d%next_out + 1
      end do
   end subroutine fill_outputs

   !> Hairer's HINIT: h such that h^order · max(‖f0‖, ‖f'‖) ≈ 0.01, using one Euler step
   !> from the initial point (d%step).
   real(wp) function initial_step(d, system, options, order) result(h_guess)
      type(rk_driver_t), intent(inout), target :: d
      class(rk_system_t), intent(inout) :: system
      type(rk_options_t), intent(in) :: options
      integer, intent(in) :: order
      real(wp) :: sk(d%n), dnf, dny, der2, der12, h0, h1
      associate (y => d%step%y, t => d%step%t, k => d%stages%k)
         sk = d%stages%atol + options%rtol*abs(y)
         dnf = sum((k(:, 1)/sk)**2)
         dny = sum((y/sk)**2)
         if (dnf <= 1.0e-10_wp .or. dny <= 1.0e-10_wp) then
            h0 = 1.0e-6_wp
         else
            h0 = sqrt(dny/dnf)*0.01_wp
         end if
         h0 = min(h0, d%control%h_max)
         d%stages%y_stage = y + d%direction*h0*k(:, 1)
         call rk_evaluate(d%stages, system, t + d%direction*h0, d%stages%y_stage, k(:, 2))
         if (.not. d%stages%finite) then
            h_guess = 1.0e-6_wp*d%span   ! the first real step will meet the problem and report it
            return
         end if
         der2 = sqrt(sum(((k(:, 2) - k(:, 1))/sk)**2))/h0
         der12 = max(der2, sqrt(dnf))
         if (der12 <= 1.0e-15_wp) then
            h1 = max(1.0e-6_wp, h0*1.0e-3_wp)
         else
            h1 = (0.01_wp/der12)**(1.0_wp/order)
         end if
         h_guess = min(100.0_wp*h0, h1, d%control%h_max)
      end associate
   end function initial_step

   !> `fixed_steps` equal steps from t0 to t_end, no error control.
   subroutine integrate_fixed(d, system, t0, options, error, t_out, y_out, h_next)
      type(rk_driver_t), intent(inout), target :: d
      class(rk_system_t), intent(inout) :: system
      real(wp), intent(in) :: t0
      type(rk_options_t), intent(in) :: options
      type(error_t), allocatable, intent(inout) :: error
      real(wp), intent(in) :: t_out(:)        !! output times (empty: none)
      real(wp), intent(inout) :: y_out(:, :)
      real(wp), intent(inout), optional :: h_next
      real(wp) :: h, err
      integer :: i
      h = (d%t_end - t0)/options%fixed_steps
      do i = 1, options%fixed_steps
         call rk_trial_step(d%stages, system, d%step, h, .false., err)
         if (.not. d%stages%finite) then
            call fail_non_finite(d, d%step%t, "fixed step", error)
            return
         end if
         call complete_step(d, system, merge(d%t_end, t0 + i*h, i == options%fixed_steps), error)
         if (allocated(error)) return
         if (size(t_out) > 0) call fill_outputs(d, t_out, y_out)
         call system%observe(d%step, d%stop)
         if (d%stop) exit
      end do
      if (present(h_next)) h_next = h
   end subroutine integrate_fixed

   !> Steps under Hairer's error control (PI control, step rejection) from d%step to t_end.
   subroutine integrate_adaptive(d, system, options, error, t_out, y_out, h_next)
      type(rk_driver_t), intent(inout), target :: d
      class(rk_system_t), intent(inout) :: system
      type(rk_options_t), intent(in) :: options
      type(error_t), allocatable, intent(inout) :: error
      real(wp), intent(in) :: t_out(:)        !! output times (empty: none)
      real(wp), intent(inout) :: y_out(:, :)
      real(wp), intent(inout), optional :: h_next
      real(wp) :: h, h_new, err, fac11, fac, direction, t_end
      type(controller_t) :: control
      integer :: order, attempts
      logical :: last, rejected_before
      character(len=160) :: message
      order = d%pair%order
      ! Hairer's defaults of the pair, unless set; the error estimate is of order p − 1
      ! (local error ~ h^p, p the propagating order): h ∝ err^(-1/p), PI-stabilised
      ! (the loop works on local copies of the control and the interval: they stay in
      ! registers across the calls, where components of the driver, a target, are reloaded)
      direction = d%direction
      t_end = d%t_end
      control%safety = options%safety
      control%beta = merge(options%beta, d%pair%beta, options%beta >= 0.0_wp)
      control%fac_min = merge(options%fac_min, d%pair%fac_min, options%fac_min > 0.0_wp)
      control%fac_max = merge(options%fac_max, d%pair%fac_max, options%fac_max > 0.0_wp)
      control%exponent = 1.0_wp/order - d%pair%pi_weight*control%beta
      control%h_max = merge(options%h_max, d%span, options%h_max > 0.0_wp)
      control%fac_old = 1.0e-4_wp
      d%control = control

      if (options%h_initial /= 0.0_wp) then
         h = min(abs(options%h_initial), control%h_max)
      else
         h = initial_step(d, system, options, order)
      end if
      h = direction*h
      rejected_before = .false.
      last = .false.
      attempts = 0
      do
         if (attempts >= options%max_steps) then
            write (message, '(a,i0,a,es24.16)') "rk_integrate: more than max_steps = ", options%max_steps, &
               " steps needed; stopped at t = ", d%step%t
            call set_error(error, err_integration, trim(message))
            return
         end if
         if (0.1_wp*abs(h) <= abs(d%step%t)*unit_roundoff .or. abs(h) < tiny(1.0_wp)) then
            write (message, '(a,es10.3,a,es24.16)') "rk_integrate: step size underflow, h = ", h, &
               " at t = ", d%step%t
            call set_error(error, err_integration, trim(message))
            return
         end if
         if ((d%step%t + 1.01_wp*h - t_end)*direction > 0.0_wp) then
            h = t_end - d%step%t
            last = .true.
         else
            ! make t + h exact, so that the solution is advanced by exactly the time that
            ! t moves: otherwise each step's rounding of t is a jump of the coefficient
            ! (a phase error √q·ulp(t) per step, a random walk of 1e-12 in S over the
            ! ~1e4 steps of β = 1e5)
            h = (d%step%t + h) - d%step%t
         end if
         attempts = attempts + 1

         call rk_trial_step(d%stages, system, d%step, h, .true., err)
         if (.not. d%stages%finite) then
            call fail_non_finite(d, d%step%t, "trial step", error)
            return
         end if

         if (control%exponent == 0.125_wp) then
            fac11 = sqrt(sqrt(sqrt(err)))  ! DOP853's err^(1/8) without a pow call
         else
            fac11 = err**control%exponent
         end if
         ! Lund stabilisation (PI control): divide by the previous error to the power beta
         fac = fac11
         if (control%beta /= 0.0_wp) fac = fac11/control%fac_old**control%beta
         fac = max(1.0_wp/control%fac_max, min(1.0_wp/control%fac_min, fac/control%safety))
         h_new = h/fac
         if (err <= 1.0_wp) then
            control%fac_old = max(err, 1.0e-4_wp)
            call complete_step(d, system, merge(t_end, d%step%t + h, last), error)
            if (allocated(error)) return
            if (size(t_out) > 0) call fill_outputs(d, t_out, y_out)
            call system%observe(d%step, d%stop)
            if (last .or. d%stop) exit
            if (abs(h_new) > control%h_max) h_new = direction*control%h_max
            if (rejected_before) h_new = direction*min(abs(h_new), abs(h))
            rejected_before = .false.
         else
            h_new = h/min(1.0_wp/control%fac_min, fac11/control%safety)
            rejected_before = .true.
            last = .false.
            d%work%n_rejected = d%work%n_rejected + 1
         end if
         h = h_new
      end do
      if (present(h_next)) h_next = direction*min(abs(h_new), control%h_max)
      d%control = control
   end subroutine integrate_adaptive

   !> After a successful attempt: f at the new point (DOP853, PD87, VERN98; DOPRI5 has it),
   !> the dense output and the step recorded (which moves f(new) into the first column for
   !> the next step); the callers then serve the outputs and call the observer.
   subroutine complete_step(d, system, t_new, error)
      type(rk_driver_t), intent(inout), target :: d
      class(rk_system_t), intent(inout) :: system
      real(wp), intent(in) :: t_new
      type(error_t), allocatable, intent(inout) :: error
      real(wp) :: hh
      integer :: j_new
      hh = t_new - d%step%t
      j_new = d%pair%new_column
      if (.not. d%pair%fsal) then
         ! f at the new point, in the column after the stages (DOP853 13, PD87 14, VERN98 17;
         ! DOPRI5's last stage is f there: FSAL)
         call rk_evaluate_new_point(d%stages, system, t_new, j_new)
         if (.not. d%stages%finite) then
            call fail_non_finite(d, t_new, "end of accepted step", error)
            return
         end if
         if (d%want_dense) then  ! DOP853 only: the others refuse dense output (DOPRI5 has its own)
            call rk_dense_extension(d%stages, system, d%step, hh)
            if (.not. d%stages%finite) then
               call fail_non_finite(d, d%step%t, "dense output stage", error)
               return
            end if
         end if
      end if
      ! the Hermite part (DOPRI5: with Shampine's 4th-order term), the step recorded
      call rk_accept_step(d%stages, d%step, t_new, j_new)
      if (d%want_dense) d%step%dense_order = d%pair%dense_order
      d%work%n_steps = d%work%n_steps + 1
   end subroutine complete_step
end module hillstab_integrate_rk

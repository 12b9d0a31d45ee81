!> Tests of the Runge–Kutta integrators (hillstab_integrate_rk) and of the half-period RK
!> monodromy (hillstab_integrate_monodromy_rk), each against an independent reference:
!> closed-form solutions (harmonic oscillator, constant Hill coefficient, Meissner),
!> Hairer's published DOPRI5 run on the Arenstorf orbit, a full-period integration,
!> the converged segmented product, and the RK4 test reference; PD8(7) against single
!> steps of GSL's rk8pd (the same tableau), its order, and against DOP853 on the pendulum;
!> Verner's 9(8) pair against its order conditions, a limit cycle in closed form and
!> DOP853 on the pendulum.
module test_rk
   use, intrinsic :: iso_c_binding, only: c_int, c_double, c_size_t, c_ptr, c_null_ptr, c_null_funptr, &
      c_loc, c_funloc, c_f_pointer, c_associated, c_funptr
   use hillstab_core_kinds, only: wp, pi, pi2
   use hillstab_core_error, only: error_t, err_integration, err_invalid_parameter
   use hillstab_core_stats, only: work_stats_t
   use hillstab_hill_coefficient, only: sampling_average
   use hillstab_hill_transfer, only: scaled_matrix_t, trace_t, matrix_of, determinant
   use hillstab_integrate_monodromy, only: trace_segmented, monodromy_trace, method_t, method_rk
   use hillstab_integrate_rk
   use hillstab_integrate_monodromy_rk
   use hillstab_test_reference, only: rk4_monodromy, value_of
   use hillstab_ffi_gsl, only: gsl_odeiv2_system, gsl_odeiv2_step_rk8pd, gsl_set_error_handler_off
   use hillstab_pendulum_equations, only: pendulum_system_t, pendulum_initial_state, pendulum_atol
   use hillstab_test_pendulum, only: pendulum_at
   use hillstab_pendulum_analysis, only: pendulum_watch_t
   use hillstab_testing
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite, ieee_value, ieee_positive_inf, ieee_quiet_nan
   use hillstab_hill_model, only: hill_model_t, hill_point_t, hill_coefficient
   use hillstab_hill_model_elastic, only: elastic_model_t
   use hillstab_hill_model_mathieu, only: mathieu_model_t
   use hillstab_test_models, only: model_of_code
   implicit none
   private
   public :: collect_rk

   !> Arenstorf orbit (Hairer, Nørsett & Wanner I, §II.0).
   real(wp), parameter :: arenstorf_mu = 0.012277471_wp
   real(wp), parameter :: arenstorf_period = 17.0652165601579625588917206249_wp
   real(wp), parameter :: arenstorf_start(4) = [0.994_wp, 0.0_wp, 0.0_wp, -2.00158510637908252240537862224_wp]

   !> x'' = −x as (x, x').
   type, extends(rk_system_t) :: oscillator_t
   contains
      procedure :: rhs => oscillator
   end type oscillator_t

   !> The oscillator with an observer that records the largest dense-output error at
   !> the midpoint of every step.
   type, extends(oscillator_t) :: midpoint_oscillator_t
      real(wp) :: worst = 0.0_wp
   contains
      procedure :: observe => at_midpoint
   end type midpoint_oscillator_t

   !> The oscillator with an observer that counts its calls and stops after 3 steps.
   type, extends(oscillator_t) :: stopping_oscillator_t
      integer :: seen = 0
   contains
      procedure :: observe => stop_after_three
   end type stopping_oscillator_t

   !> The oscillator whose derivative turns infinite for t > 1/2.
   type, extends(rk_system_t) :: infinite_after_half_t
   contains
      procedure :: rhs => infinite_after_half
   end type infinite_after_half_t

   !> y' = y², which blows up at t = 1 from y(0) = 1.
   type, extends(rk_system_t) :: blow_up_t
   contains
      procedure :: rhs => blow_up
   end type blow_up_t

   !> The restricted three-body problem of the Arenstorf orbit.
   type, extends(rk_system_t) :: three_body_t
   contains
      procedure :: rhs => three_body
   end type three_body_t

   !> y' = J y + (1 − |y|²) y in the plane (J: rotation by π/2): from radius r0 the
   !> solution spirals onto the unit circle, r(t) = (1 + (r0⁻² − 1) e^(−2t))^(−1/2), angle t.
   type, extends(rk_system_t) :: limit_cycle_t
   contains
      procedure :: rhs => limit_cycle
   end type limit_cycle_t

   !> Two solutions (u, u', v, v') of x'' + q(τ) x = 0.
   type, extends(rk_system_t) :: hill_pair_t
      class(hill_model_t), pointer :: model => null()
      type(hill_point_t) :: point
   contains
      procedure :: rhs => hill_pair
   end type hill_pair_t

   !> Two solutions of y'' + r s(t) y = 0, s = +1 on [0, 1), −1 on [1, 2) (piece = 0),
   !> or s = +1 throughout (piece = 1), or s = −1 throughout (piece = 2).
   type, extends(rk_system_t) :: meissner_t
      real(wp) :: r = 1.0_wp
      integer :: piece = 0
   contains
      procedure :: rhs => meissner
   end type meissner_t

   !> y' = y² cos t: from y(0) = 1/2, y = 1/(2 − sin t) (nonlinear and time-dependent).
   type, extends(rk_system_t) :: riccati_t
   contains
      procedure :: rhs => riccati
   end type riccati_t

   !> y' = t y²: from y(0) = y0, y = 1/(1/y0 − t²/2). f(−t, y) = −f(t, y), so integrating
   !> backwards from 0 to −T is the forward integration from 0 to T mirrored, bit for bit (every
   !> product with a negated t or h is the exact negation), while a stage at a wrong time
   !> (t + c|h| instead of t + c h) breaks the mirror.
   type, extends(rk_system_t) :: odd_in_time_t
   contains
      procedure :: rhs => odd_in_time
   end type odd_in_time_t

   !> The oscillator whose derivative is +Inf at its evaluation number `fail_at`.
   type, extends(oscillator_t) :: failing_at_t
      integer :: calls = 0
      integer :: fail_at = 0
   contains
      procedure :: rhs => fail_at_count
   end type failing_at_t

   !> The oscillator with an observer that checks what each accepted step hands over
   !> (pair, cubic Hermite interpolant with zero higher coefficients, contiguous steps)
   !> and stops after 3 steps.
   type, extends(oscillator_t) :: hermite_watch_t
      integer :: method = 0
      integer :: seen = 0
      logical :: consistent = .true.
      real(wp) :: t_previous = 0.0_wp
   contains
      procedure :: observe => watch_hermite
   end type hermite_watch_t

   !> Any rk_system_t seen by GSL: handed to `gsl_system_rhs` through the params pointer.
   type :: gsl_context_t
      class(rk_system_t), pointer :: system => null()
      integer :: n = 0
   end type gsl_context_t

   interface
      !> gsl_odeiv2_step_alloc: a stepper of the given type for dim equations.
      function gsl_odeiv2_step_alloc(step_type, dim) bind(C, name="gsl_odeiv2_step_alloc") result(step)
         import :: c_ptr, c_size_t
         type(c_ptr), value :: step_type     !! e.g. gsl_odeiv2_step_rk8pd
         integer(c_size_t), value :: dim     !! number of equations
         type(c_ptr) :: step
      end function gsl_odeiv2_step_alloc

      !> gsl_odeiv2_step_apply: one step of size h from (t, y); y is advanced, yerr gets
      !> the stepper's error estimate. Null dydt_in: f(t, y) is evaluated by the stepper.
      function gsl_odeiv2_step_apply(step, t, h, y, yerr, dydt_in, dydt_out, sys) &
         bind(C, name="gsl_odeiv2_step_apply") result(status)
         import :: c_ptr, c_double, c_int, gsl_odeiv2_system
         type(c_ptr), value :: step              !! the stepper
         real(c_double), value :: t              !! start of the step
         real(c_double), value :: h              !! step size
         real(c_double), intent(inout) :: y(*)   !! state at t in, at t + h out
         real(c_double), intent(out) :: yerr(*)  !! estimated local error of each component
         type(c_ptr), value :: dydt_in           !! f(t, y) if known, or null
         type(c_ptr), value :: dydt_out          !! f(t + h, y(t + h)) out, or null
         type(gsl_odeiv2_system), intent(in) :: sys  !! the system
         integer(c_int) :: status
      end function gsl_odeiv2_step_apply

      !> gsl_odeiv2_step_free.
      subroutine gsl_odeiv2_step_free(step) bind(C, name="gsl_odeiv2_step_free")
         import :: c_ptr
         type(c_ptr), value :: step  !! the stepper
      end subroutine gsl_odeiv2_step_free
   end interface

contains

   function collect_rk() result(suite)
      type(testsuite_t) :: suite
      suite = new_testsuite("rk", [ &
         new_unittest("order_oscillator", order_oscillator), &
         new_unittest("order_constant_hill", order_constant_hill), &
         new_unittest("order_meissner", order_meissner), &
         new_unittest("arenstorf_dopri5_hairer", arenstorf_dopri5_hairer), &
         new_unittest("arenstorf_dop853", arenstorf_dop853), &
         new_unittest("dense_output", dense_output), &
         new_unittest("dense_order", dense_order), &
         new_unittest("backward_and_observer", backward_and_observer), &
         new_unittest("output_arguments", output_arguments), &
         new_unittest("error_paths", error_paths), &
         new_unittest("tiny_state_relative", tiny_state_relative), &
         new_unittest("half_equals_full_period", half_equals_full_period), &
         new_unittest("trace_vs_references", trace_vs_references), &
         new_unittest("unit_determinant", unit_determinant), &
         new_unittest("hard_cases", hard_cases), &
         new_unittest("dispatch_and_work", dispatch_and_work), &
         new_unittest("pd87_step_equals_gsl", pd87_step_equals_gsl), &
         new_unittest("pd87_order", pd87_order), &
         new_unittest("pd87_pendulum", pd87_pendulum), &
         new_unittest("pd87_refusals", pd87_refusals), &
         new_unittest("pd87_work", pd87_work), &
         new_unittest("vern98_tableau", vern98_tableau), &
         new_unittest("vern98_order", vern98_order), &
         new_unittest("vern98_pendulum", vern98_pendulum), &
         new_unittest("backward_mirror", backward_mirror), &
         new_unittest("new_pairs_observer", new_pairs_observer), &
         new_unittest("new_pairs_non_finite", new_pairs_non_finite), &
         new_unittest("new_pairs_max_steps", new_pairs_max_steps)])
   end function collect_rk

   ! ----------------------------------------------------------------------------------
   ! helpers
   ! ----------------------------------------------------------------------------------

   subroutine oscillator(self, t, y, dydt)
      class(oscillator_t), intent(inout) :: self
      real(wp), intent(in) :: t, y(:)
      real(wp), intent(out) :: dydt(:)
      dydt(1) = y(2)
      dydt(2) = -y(1)
   end subroutine oscillator

   subroutine at_midpoint(self, step, stop)
      class(midpoint_oscillator_t), intent(inout) :: self
      type(rk_step_t), intent(in) :: step
      logical, intent(inout) :: stop
      real(wp) :: tm, ym(2)
      if (step%index == 0) return
      tm = step%t_old + 0.5_wp*step%h
      ym = rk_dense_value(step, tm)
      self%worst = max(self%worst, abs(ym(1) - cos(tm)) + abs(ym(2) + sin(tm)))
   end subroutine at_midpoint

   subroutine stop_after_three(self, step, stop)
      class(stopping_oscillator_t), intent(inout) :: self
      type(rk_step_t), intent(in) :: step
      logical, intent(inout) :: stop
      self%seen = self%seen + 1
      stop = step%index >= 3
   end subroutine stop_after_three

   subroutine infinite_after_half(self, t, y, dydt)
      class(infinite_after_half_t), intent(inout) :: self
      real(wp), intent(in) :: t, y(:)
      real(wp), intent(out) :: dydt(:)
      dydt = [y(2), -y(1)]
      if (t > 0.5_wp) dydt(2) = ieee_value(1.0_wp, ieee_positive_inf)
   end subroutine infinite_after_half

   subroutine blow_up(self, t, y, dydt)
      class(blow_up_t), intent(inout) :: self
      real(wp), intent(in) :: t, y(:)
      real(wp), intent(out) :: dydt(:)
      dydt = y**2
   end subroutine blow_up

   subroutine three_body(self, t, y, dydt)
      class(three_body_t), intent(inout) :: self
      real(wp), intent(in) :: t, y(:)
      real(wp), intent(out) :: dydt(:)
      real(wp) :: d1, d2, mu1
      mu1 = 1.0_wp - arenstorf_mu
      d1 = ((y(1) + arenstorf_mu)**2 + y(2)**2)**1.5_wp
      d2 = ((y(1) - mu1)**2 + y(2)**2)**1.5_wp
      dydt(1) = y(3)
      dydt(2) = y(4)
      dydt(3) = y(1) + 2.0_wp*y(4) - mu1*(y(1) + arenstorf_mu)/d1 - arenstorf_mu*(y(1) - mu1)/d2
      dydt(4) = y(2) - 2.0_wp*y(3) - mu1*y(2)/d1 - arenstorf_mu*y(2)/d2
   end subroutine three_body

   subroutine limit_cycle(self, t, y, dydt)
      class(limit_cycle_t), intent(inout) :: self
      real(wp), intent(in) :: t, y(:)
      real(wp), intent(out) :: dydt(:)
      real(wp) :: s
      s = 1.0_wp - y(1)**2 - y(2)**2
      dydt(1) = -y(2) + s*y(1)
      dydt(2) = y(1) + s*y(2)
   end subroutine limit_cycle

   subroutine hill_pair(self, t, y, dydt)
      class(hill_pair_t), intent(inout) :: self
      real(wp), intent(in) :: t, y(:)
      real(wp), intent(out) :: dydt(:)
      real(wp) :: q
      q = hill_coefficient(self%model, self%point, t)
      dydt = [y(2), -q*y(1), y(4), -q*y(3)]
   end subroutine hill_pair

   subroutine meissner(self, t, y, dydt)
      class(meissner_t), intent(inout) :: self
      real(wp), intent(in) :: t, y(:)
      real(wp), intent(out) :: dydt(:)
      real(wp) :: q
      select case (self%piece)
      case (1); q = self%r
      case (2); q = -self%r
      case default; q = merge(self%r, -self%r, t < 1.0_wp)
      end select
      dydt = [y(2), -q*y(1), y(4), -q*y(3)]
   end subroutine meissner

   !> Error at t = 10 of the harmonic oscillator in fixed-step mode.
   real(wp) function oscillator_error(method, n_steps) result(err)
      integer, intent(in) :: method, n_steps
      real(wp) :: t, y(2)
      type(error_t), allocatable :: error
      type(oscillator_t) :: osc
      t = 0.0_wp
      y = [1.0_wp, 0.0_wp]
      call rk_integrate(osc, t, 10.0_wp, y, rk_options_t(method=method, fixed_steps=n_steps), error=error)
      err = norm2(y - [cos(10.0_wp), -sin(10.0_wp)])
      if (allocated(error)) err = huge(1.0_wp)
   end function oscillator_error

   !> S = 2(u v' + u' v) of x'' + q(τ) x = 0 from the even/odd solutions on [0, 1]
   !> integrated in fixed-step mode (the half-period identity, independent of monodromy_rk).
   real(wp) function fixed_step_trace(model, point, method, n_steps) result(s)
      class(hill_model_t), intent(in), target :: model  !! the model
      type(hill_point_t), intent(in) :: point   !! α, β, ε
      integer, intent(in) :: method, n_steps
      real(wp) :: t, y(4)
      type(error_t), allocatable :: error
      type(hill_pair_t) :: pair
      t = 0.0_wp
      y = [1.0_wp, 0.0_wp, 0.0_wp, 1.0_wp]
      pair%model => model
      pair%point = point
      call rk_integrate(pair, t, 1.0_wp, y, rk_options_t(method=method, fixed_steps=n_steps), &
                        error=error)
      s = 2.0_wp*(y(1)*y(4) + y(2)*y(3))
      if (allocated(error)) s = huge(1.0_wp)
   end function fixed_step_trace

   subroutine riccati(self, t, y, dydt)
      class(riccati_t), intent(inout) :: self
      real(wp), intent(in) :: t, y(:)
      real(wp), intent(out) :: dydt(:)
      dydt(1) = y(1)**2*cos(t)
   end subroutine riccati

   subroutine odd_in_time(self, t, y, dydt)
      class(odd_in_time_t), intent(inout) :: self
      real(wp), intent(in) :: t, y(:)
      real(wp), intent(out) :: dydt(:)
      dydt(1) = t*y(1)**2
   end subroutine odd_in_time

   subroutine fail_at_count(self, t, y, dydt)
      class(failing_at_t), intent(inout) :: self
      real(wp), intent(in) :: t, y(:)
      real(wp), intent(out) :: dydt(:)
      self%calls = self%calls + 1
      dydt(1) = y(2)
      dydt(2) = -y(1)
      if (self%calls == self%fail_at) dydt(2) = ieee_value(1.0_wp, ieee_positive_inf)
   end subroutine fail_at_count

   subroutine watch_hermite(self, step, stop)
      class(hermite_watch_t), intent(inout) :: self
      type(rk_step_t), intent(in) :: step
      logical, intent(inout) :: stop
      self%seen = self%seen + 1
      self%consistent = self%consistent .and. step%method == self%method .and. step%index == self%seen - 1
      if (step%index > 0) then
         self%consistent = self%consistent .and. step%dense_order == 3 .and. all(step%dense(:, 4:7) == 0.0_wp) &
            .and. step%t_old == self%t_previous .and. step%h == step%t - step%t_old
      end if
      self%t_previous = step%t
      stop = step%index >= 3
   end subroutine watch_hermite

   !> GSL's right-hand side for any rk_system_t: the system comes through `params`.
   function gsl_system_rhs(t, y, dydt, params) bind(C) result(status)
      real(c_double), value :: t
      type(c_ptr), value :: y, dydt, params
      integer(c_int) :: status
      type(gsl_context_t), pointer :: context
      real(c_double), pointer :: state(:), derivative(:)
      call c_f_pointer(params, context)
      call c_f_pointer(y, state, [context%n])
      call c_f_pointer(dydt, derivative, [context%n])
      call context%system%rhs(t, state, derivative)
      status = 0_c_int
   end function gsl_system_rhs

   !> Observed order log2(e(N)/e(2N)) compared with `expected`.
   subroutine check_order(ctx, e1, e2, expected, label)
      type(test_context_t), intent(inout) :: ctx
      real(wp), intent(in) :: e1, e2
      real(wp), intent(in) :: expected
      character(len=*), intent(in) :: label
      real(wp) :: order
      order = log(e1/e2)/log(2.0_wp)
      write (*, '(4x,a,a,f6.2)') label, ": observed order ", order
      call check(ctx, order, expected, abs=0.3_wp, message=label)
   end subroutine check_order

   ! ----------------------------------------------------------------------------------
   ! integrator
   ! ----------------------------------------------------------------------------------

   !> Fixed-step convergence on x'' = −x (closed form cos, −sin) at t = 10.
   subroutine order_oscillator(ctx)
      type(test_context_t), intent(inout) :: ctx
      call check_order(ctx, oscillator_error(rk_dop853, 20), oscillator_error(rk_dop853, 40), 8.0_wp, &
         "dop853 oscillator N=20,40")
      call check_order(ctx, oscillator_error(rk_dopri5, 80), oscillator_error(rk_dopri5, 160), 5.0_wp, &
         "dopri5 oscillator N=80,160")
   end subroutine order_oscillator

   !> Fixed-step convergence on the α = 0 Hill equation: S = 2 cos(2√β). For constant q the
   !> trace error is an amplitude part (∝ cos 2√β) plus a phase part (∝ sin 2√β); the
   !> leading (h^p) term of DOPRI5 is an amplitude error and that of DOP853 a phase error,
   !> so β is chosen where the matching factor is near 1 (β = 10: cos ≈ 1; β = 30: sin ≈ 1).
   subroutine order_constant_hill(ctx)
      type(test_context_t), intent(inout) :: ctx
      class(hill_model_t), pointer :: model => null()
      type(hill_point_t) :: point
      real(wp) :: exact
      model => model_of_code(1)
      point = hill_point_t(0.0_wp, 30.0_wp, 0.0_wp)
      exact = 2.0_wp*cos(2.0_wp*sqrt(30.0_wp))
      call check_order(ctx, abs(fixed_step_trace(model, point, rk_dop853, 8) - exact), &
         abs(fixed_step_trace(model, point, rk_dop853, 16) - exact), 8.0_wp, "dop853 alpha=0 beta=30 N=8,16")
      call check(ctx, fixed_step_trace(model, point, rk_dop853, 200), exact, abs=1.0e-13_wp, message="dop853 N=200")
      model => model_of_code(1)
      point = hill_point_t(0.0_wp, 10.0_wp, 0.0_wp)
      exact = 2.0_wp*cos(2.0_wp*sqrt(10.0_wp))
      call check_order(ctx, abs(fixed_step_trace(model, point, rk_dopri5, 32) - exact), &
         abs(fixed_step_trace(model, point, rk_dopri5, 64) - exact), 5.0_wp, "dopri5 alpha=0 beta=10 N=32,64")
      ! β < 0: S = 2 cosh(2√|β|)
      model => model_of_code(1)
      point = hill_point_t(0.0_wp, -10.0_wp, 0.0_wp)
      exact = 2.0_wp*cosh(2.0_wp*sqrt(10.0_wp))
      call check(ctx, fixed_step_trace(model, point, rk_dop853, 200), exact, rel=1.0e-13_wp, message="beta < 0")
   end subroutine order_constant_hill

   !> Meissner: y'' + r s(t) y = 0, s = +1 on [0, 1), −1 on [1, 2), trace 2 cos√r cosh√r.
   !> The step grid is aligned with the jump: the integration restarts at t = 1, with
   !> n steps on the first piece and 2n on the second. (With equal steps the leading
   !> DOPRI5 error, z⁶/3600 per step, scales the two pieces by −Nθ⁶/3600 and +Nθ⁶/3600
   !> and cancels exactly in the trace, which then converges at order 6.)
   subroutine order_meissner(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp) :: r, exact, s, t, y(4), e(2)
      type(error_t), allocatable :: error
      type(work_stats_t) :: stats
      integer :: method, k, n
      do method = rk_dopri5, rk_dop853
         ! r chosen so that the asymptotic regime starts early (for DOPRI5 sin √r ≈ 0 damps
         ! its h⁶ phase term, which at r = 20 still competes with h⁵ at n = 64)
         r = merge(9.0_wp, 20.0_wp, method == rk_dopri5)
         exact = 2.0_wp*cos(sqrt(r))*cosh(sqrt(r))
         do k = 1, 2
            n = merge(32, 8, method == rk_dopri5)*k
            e(k) = abs(meissner_trace(rk_options_t(method=method, fixed_steps=n), .true.) - exact)
         end do
         call check_order(ctx, e(1), e(2), real(rk_method_order(method), wp), &
            "meissner "//rk_method_name(method))
      end do
      ! adaptive, in one call straight through the jump: rejections locate it
      s = meissner_trace(rk_options_t(method=rk_dop853, rtol=1.0e-12_wp, atol=1.0e-12_wp), .false.)
      write (*, '(4x,a,es10.2,a,i0,a,i0)') "meissner adaptive through the jump: error ", abs(s - exact), &
         ", evaluations ", stats%n_evaluations, ", rejected ", stats%n_rejected
      call check(ctx, s, exact, rel=1.0e-9_wp, message="adaptive dop853 across the jump")
      call check(ctx, stats%n_rejected > 0, "the jump causes rejections")
   contains
      real(wp) function meissner_trace(options, restart) result(trace)
         type(rk_options_t), intent(in) :: options
         logical, intent(in) :: restart
         type(meissner_t) :: piecewise
         t = 0.0_wp
         y = [1.0_wp, 0.0_wp, 0.0_wp, 1.0_wp]
         if (restart) then
            piecewise = meissner_t(r=r, piece=1)
            call rk_integrate(piecewise, t, 1.0_wp, y, options, stats, error)
            call check(ctx, .not. allocated(error), "first half")
            piecewise = meissner_t(r=r, piece=2)
            call rk_integrate(piecewise, t, 2.0_wp, y, rk_options_t(method=options%method, &
                              fixed_steps=2*options%fixed_steps), stats, error)
         else
            piecewise = meissner_t(r=r)
            call rk_integrate(piecewise, t, 2.0_wp, y, options, stats, error)
         end if
         call check(ctx, .not. allocated(error), "meissner integration")
         trace = y(1) + y(4)
      end function meissner_trace
   end subroutine order_meissner

   !> DOPRI5 at rtol = atol = 1e-7 reproduces Hairer's dr_dopri5 run (published output:
   !> Y(XEND) = (0.9940021016, 0.8911185692e-5), fcn = 1442, accpt = 216, rejct = 22, where
   !> Hairer does not count the 2 rejections of the very first step).
   subroutine arenstorf_dopri5_hairer(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp) :: t, y(4), t_out(1), y_out(4, 1)
      type(work_stats_t) :: stats
      type(error_t), allocatable :: error
      type(three_body_t) :: body
      t = 0.0_wp
      y = arenstorf_start
      t_out = [2.0_wp]
      call rk_integrate(body, t, arenstorf_period, y, rk_options_t(method=rk_dopri5, rtol=1.0e-7_wp, &
                        atol=1.0e-7_wp), stats, error, t_out=t_out, y_out=y_out)
      call check(ctx, .not. allocated(error), "integration succeeds")
      write (*, '(4x,a,i0,a,i0,a,i0,a)') "arenstorf dopri5 tol 1e-7: f-evals ", stats%n_evaluations, &
         ", accepted ", stats%n_steps, ", rejected ", stats%n_rejected, " (Hairer: 1442, 216, 22+2)"
      call check(ctx, t, arenstorf_period, rel=0.0_wp, message="reaches the end")
      call check(ctx, y(1), 0.9940021016_wp, abs=2.0e-10_wp, message="Hairer's y1(T)")
      call check(ctx, y(2), 0.8911185692e-5_wp, abs=2.0e-10_wp, message="Hairer's y2(T)")
      ! Hairer's dense output at x = 2: (-0.5798781411, 0.6090775251)
      call check(ctx, y_out(1, 1), -0.5798781411_wp, abs=2.0e-10_wp, message="Hairer's y1(2)")
      call check(ctx, y_out(2, 1), 0.6090775251_wp, abs=2.0e-10_wp, message="Hairer's y2(2)")
      call check(ctx, real(stats%n_evaluations, wp), 1442.0_wp, abs=12.0_wp, message="f-evaluations")
      call check(ctx, real(stats%n_steps, wp), 216.0_wp, abs=2.0_wp, message="accepted steps")
   end subroutine arenstorf_dopri5_hairer

   !> One period of the Arenstorf orbit with DOP853 at rtol = atol = 1e-10 returns to the
   !> start. The position error is a small multiple of the tolerance; the velocity error
   !> is ~150× the position error, because the orbit ends next to the moon where the
   !> acceleration is ~300 and any phase error δt shows up as 300 δt in the velocity.
   subroutine arenstorf_dop853(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp) :: t, y(4), err_tight, err_loose
      type(work_stats_t) :: stats
      type(error_t), allocatable :: error
      integer :: k
      real(wp) :: tol(2) = [1.0e-10_wp, 1.0e-12_wp], err(2)
      type(three_body_t) :: body
      do k = 1, 2
         t = 0.0_wp
         y = arenstorf_start
         call rk_integrate(body, t, arenstorf_period, y, rk_options_t(method=rk_dop853, rtol=tol(k), &
                           atol=tol(k)), stats, error)
         call check(ctx, .not. allocated(error), "integration succeeds")
         err(k) = norm2(y(1:2) - arenstorf_start(1:2))
         write (*, '(4x,a,es8.1,a,es10.3,a,es10.3,a,i0,a,i0,a,i0)') "arenstorf dop853 tol ", tol(k), &
            ": position error ", err(k), ", velocity error ", norm2(y(3:4) - arenstorf_start(3:4)), &
            ", f-evals ", stats%n_evaluations, ", accepted ", stats%n_steps, ", rejected ", stats%n_rejected
         call check(ctx, err(k) < 100.0_wp*tol(k), "position error within 100 tol")
         call check(ctx, norm2(y(3:4) - arenstorf_start(3:4)) < 1.0e5_wp*tol(k), "velocity error within 1e5 tol")
      end do
      err_loose = err(1); err_tight = err(2)
      call check(ctx, err_tight < err_loose/10.0_wp, "error decreases with the tolerance")
   end subroutine arenstorf_dop853

   !> Dense output between steps against the closed form, with few large steps.
   subroutine dense_output(ctx)
      type(test_context_t), intent(inout) :: ctx
      integer, parameter :: n_out = 201
      real(wp) :: t, y(2), t_out(n_out), y_out(2, n_out), worst
      real(wp) :: tol(2) = [1.0e-6_wp, 1.0e-10_wp]
      type(work_stats_t) :: stats
      type(error_t), allocatable :: error
      integer :: method, j, k
      type(oscillator_t) :: osc
      do k = 1, n_out
         t_out(k) = 10.0_wp*(k - 1)/(n_out - 1)
      end do
      do method = rk_dopri5, rk_dop853
         do j = 1, 2
            t = 0.0_wp
            y = [1.0_wp, 0.0_wp]
            call rk_integrate(osc, t, 10.0_wp, y, rk_options_t(method=method, rtol=tol(j), atol=tol(j)), &
                              stats, error, t_out=t_out, y_out=y_out)
            call check(ctx, .not. allocated(error), "integration succeeds")
            worst = maxval(abs(y_out(1, :) - cos(t_out))) + maxval(abs(y_out(2, :) + sin(t_out)))
            write (*, '(4x,a,a,es8.1,a,es10.3,a,i0,a)') rk_method_name(method), " dense output tol ", tol(j), &
               ": max error ", worst, " (", stats%n_steps, " steps)"
            call check(ctx, worst < 20.0_wp*tol(j), "dense output within 20 tol")
            call check(ctx, y_out(1, n_out) == y(1) .and. y_out(2, n_out) == y(2), "last output = final state")
            call check(ctx, y_out(1, 1) == 1.0_wp .and. y_out(2, 1) == 0.0_wp, "first output = initial state")
         end do
      end do
   end subroutine dense_output

   !> Largest error (|Δx| + |Δx'|) of the observer's interpolant at the step midpoints of
   !> `n_steps` fixed steps of the oscillator over [0, 10] (with or without dense output).
   real(wp) function midpoint_error(ctx, method, dense, n_steps) result(err)
      type(test_context_t), intent(inout) :: ctx
      integer, intent(in) :: method, n_steps
      logical, intent(in) :: dense
      real(wp) :: t, y(2)
      type(error_t), allocatable :: error
      type(midpoint_oscillator_t) :: system
      t = 0.0_wp
      y = [1.0_wp, 0.0_wp]
      call rk_integrate(system, t, 10.0_wp, y, rk_options_t(method=method, fixed_steps=n_steps, &
                        dense_output=dense), error=error)
      call check(ctx, .not. allocated(error), rk_method_name(method)//" midpoint run succeeds")
      err = system%worst
   end function midpoint_error

   !> Order of the continuous extensions: error at step midpoints in fixed-step mode,
   !> through the observer's interpolant (7 for DOP853 with dense output, 3 for its
   !> Hermite fallback, 4 for DOPRI5; the midpoint error converges at the interpolant
   !> order + 1 or at the method order, whichever is lower).
   subroutine dense_order(ctx)
      type(test_context_t), intent(inout) :: ctx
      call check_order(ctx, midpoint_error(ctx, rk_dop853, .true., 10), midpoint_error(ctx, rk_dop853, .true., 20), &
         8.0_wp, "dop853 dense midpoints")
      call check_order(ctx, midpoint_error(ctx, rk_dop853, .false., 40), midpoint_error(ctx, rk_dop853, .false., 80), &
         4.0_wp, "dop853 hermite midpoints")
      call check_order(ctx, midpoint_error(ctx, rk_dopri5, .true., 40), midpoint_error(ctx, rk_dopri5, .true., 80), &
         5.0_wp, "dopri5 dense midpoints")
   end subroutine dense_order

   !> Backward integration returns to the start; the observer sees every step and
   !> can stop the integration early.
   subroutine backward_and_observer(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp) :: t, y(2), t_out(3), y_out(2, 3)
      type(work_stats_t) :: stats
      type(error_t), allocatable :: error
      type(stopping_oscillator_t) :: stopping
      type(oscillator_t) :: osc
      t = 5.0_wp
      y = [cos(5.0_wp), -sin(5.0_wp)]
      t_out = [4.0_wp, 2.5_wp, 0.0_wp]
      call rk_integrate(osc, t, 0.0_wp, y, rk_options_t(rtol=1.0e-12_wp, atol=1.0e-12_wp), stats, error, &
                        t_out=t_out, y_out=y_out)
      call check(ctx, .not. allocated(error), "backward integration succeeds")
      call check(ctx, t, 0.0_wp, abs=0.0_wp, message="reaches t_end")
      call check(ctx, y(1), 1.0_wp, abs=1.0e-10_wp, message="backward y1")
      call check(ctx, y(2), 0.0_wp, abs=1.0e-10_wp, message="backward y2")
      call check(ctx, y_out(1, 2), cos(2.5_wp), abs=1.0e-10_wp, message="backward dense output")
      t = 0.0_wp
      y = [1.0_wp, 0.0_wp]
      call rk_integrate(stopping, t, 10.0_wp, y, rk_options_t(rtol=1.0e-8_wp, atol=1.0e-8_wp), stats, error)
      call check(ctx, .not. allocated(error), "stopping is not an error")
      call check(ctx, stopping%seen == 4 .and. stats%n_steps == 3, "observer called at start and after 3 steps")
      call check(ctx, t > 0.0_wp .and. t < 10.0_wp, "stopped inside the interval")
      call check(ctx, y(1), cos(t), abs=1.0e-7_wp, message="state at the stop")
      ! t_out rejected when out of order
      call rk_integrate(osc, t, 10.0_wp, y, rk_options_t(), stats, error, t_out=[9.0_wp, 8.0_wp], &
                        y_out=y_out(:, 1:2))
      call check(ctx, allocated(error), "unordered t_out rejected")
   end subroutine backward_and_observer

   !> t_out and y_out: checked as before they went on to the driver as ordinary arrays (empty
   !> when absent), and the same steps with and without them (fixed and adaptive).
   subroutine output_arguments(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp) :: t, y(2), y_plain(2), t_out(3), y_out(2, 3), y_wide(2, 4), h_plain, h_out
      type(work_stats_t) :: stats, stats_plain
      type(error_t), allocatable :: error
      type(oscillator_t) :: osc
      type(rk_options_t) :: options
      integer :: k
      t_out = [0.5_wp, 1.0_wp, 2.0_wp]
      do k = 1, 2
         options = rk_options_t(rtol=1.0e-10_wp, atol=1.0e-10_wp)
         if (k == 2) options%fixed_steps = 40
         t = 0.0_wp
         y_plain = [1.0_wp, 0.0_wp]
         call rk_integrate(osc, t, 2.0_wp, y_plain, options, stats_plain, error, h_next=h_plain)
         call check(ctx, .not. allocated(error), "without outputs")
         t = 0.0_wp
         y = [1.0_wp, 0.0_wp]
         y_out = -7.0_wp
         call rk_integrate(osc, t, 2.0_wp, y, options, stats, error, t_out=t_out, y_out=y_out, h_next=h_out)
         call check(ctx, .not. allocated(error), "with outputs")
         call check(ctx, all(y == y_plain) .and. h_out == h_plain .and. stats%n_steps == stats_plain%n_steps, &
                    "the same steps with and without outputs")
         call check(ctx, y_out(1, 3), y(1), abs=0.0_wp, message="the last output time is t_end")
         call check(ctx, y_out(1, 1), cos(0.5_wp), abs=merge(1.0e-8_wp, 1.0e-6_wp, k == 1), &
                    message="dense output at t = 0.5")
         call check(ctx, y_out(2, 2), -sin(1.0_wp), abs=merge(1.0e-8_wp, 1.0e-6_wp, k == 1), &
                    message="dense output at t = 1")
      end do
      t = 0.0_wp
      y = [1.0_wp, 0.0_wp]
      call rk_integrate(osc, t, 2.0_wp, y, rk_options_t(), stats, error, t_out=t_out)
      call check(ctx, has_message(error, "t_out and y_out go together"), "t_out without y_out")
      call check(ctx, t == 0.0_wp .and. stats%n_steps == 0, "nothing integrated")
      call rk_integrate(osc, t, 2.0_wp, y, rk_options_t(), stats, error, y_out=y_out)
      call check(ctx, has_message(error, "t_out and y_out go together"), "y_out without t_out")
      call rk_integrate(osc, t, 2.0_wp, y, rk_options_t(), stats, error, t_out=t_out, y_out=y_wide)
      call check(ctx, has_message(error, "y_out must be (size(y), size(t_out))"), "y_out of the wrong shape")
      call rk_integrate(osc, t, 2.0_wp, y, rk_options_t(), stats, error, t_out=[0.5_wp, ieee_value(1.0_wp, &
                        ieee_quiet_nan), 1.0_wp], y_out=y_out)
      call check(ctx, has_message(error, "non-finite output time"), "NaN output time")
      call rk_integrate(osc, t, 2.0_wp, y, rk_options_t(), stats, error, t_out=[0.5_wp, 1.0_wp, 3.0_wp], y_out=y_out)
      call check(ctx, has_message(error, "monotone from t towards t_end"), "output time beyond t_end")
      ! an unknown method still comes first (the order of the checks kept)
      call rk_integrate(osc, t, 2.0_wp, y, rk_options_t(method=99), stats, error, t_out=t_out)
      call check(ctx, has_message(error, "unknown method"), "the method before the outputs")
   contains
      logical function has_message(error, text)
         type(error_t), allocatable, intent(in) :: error
         character(len=*), intent(in) :: text
         has_message = .false.
         if (allocated(error)) has_message = error%code == err_invalid_parameter .and. &
                                             index(error%message, text) > 0
      end function has_message
   end subroutine output_arguments

   !> Failures are reported through error_t and leave a finite state behind.
   subroutine error_paths(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp) :: t, y(4)
      type(work_stats_t) :: stats
      type(error_t), allocatable :: error
      ! too many steps
      type(blow_up_t) :: explosive
      type(infinite_after_half_t) :: infinite
      type(oscillator_t) :: osc
      type(three_body_t) :: body
      t = 0.0_wp
      y = arenstorf_start
      call rk_integrate(body, t, arenstorf_period, y, rk_options_t(rtol=1.0e-10_wp, atol=1.0e-10_wp, &
                        max_steps=20), stats, error)
      call check(ctx, allocated(error), "max_steps: error")
      if (allocated(error)) then
         call check(ctx, error%code == err_integration .and. index(error%message, "max_steps") > 0, &
            "max_steps: code and message")
      end if
      call check(ctx, all(ieee_is_finite(y)) .and. t > 0.0_wp .and. t < arenstorf_period, "max_steps: state kept")
      ! non-finite derivative
      t = 0.0_wp
      y(1:2) = [1.0_wp, 0.0_wp]
      call rk_integrate(infinite, t, 1.0_wp, y(1:2), rk_options_t(), stats, error)
      call check(ctx, allocated(error), "non-finite: error")
      if (allocated(error)) then
         call check(ctx, error%code == err_integration .and. index(error%message, "non-finite") > 0, &
            "non-finite: code and message")
      end if
      call check(ctx, all(ieee_is_finite(y(1:2))) .and. t <= 0.5_wp, "non-finite: last good state kept")
      ! the same in fixed-step mode
      t = 0.0_wp
      y(1:2) = [1.0_wp, 0.0_wp]
      call rk_integrate(infinite, t, 1.0_wp, y(1:2), rk_options_t(method=rk_dopri5, fixed_steps=10), &
                        stats, error)
      call check(ctx, allocated(error) .and. all(ieee_is_finite(y(1:2))), "non-finite fixed-step: error")
      ! step-size underflow: y' = y², y(0) = 1 blows up at t = 1
      t = 0.0_wp
      y(1:1) = [1.0_wp]
      call rk_integrate(explosive, t, 2.0_wp, y(1:1), rk_options_t(rtol=1.0e-8_wp, atol=1.0e-8_wp), stats, error)
      call check(ctx, allocated(error), "blow-up: error")
      if (allocated(error)) then
         write (*, '(4x,a)') "blow-up: "//error%message
         call check(ctx, error%code == err_integration .and. index(error%message, "underflow") > 0, &
            "blow-up: step size underflow")
      end if
      call check(ctx, ieee_is_finite(y(1)) .and. abs(t - 1.0_wp) < 1.0e-6_wp, "blow-up: stopped at t = 1")
      ! invalid options
      t = 0.0_wp
      y(1:2) = [1.0_wp, 0.0_wp]
      call rk_integrate(osc, t, 1.0_wp, y(1:2), rk_options_t(atol=0.0_wp), stats, error)
      call check(ctx, allocated(error), "atol = 0 rejected")
      if (allocated(error)) call check(ctx, error%code == err_invalid_parameter, "atol = 0: code")
      call rk_integrate(osc, t, 1.0_wp, y(1:2), rk_options_t(method=7), stats, error)
      call check(ctx, allocated(error), "unknown method rejected")
      ! PI parameter beyond the controller's stable range: refused (above it the steady-state
      ! error of the controller leaves (0, 1), measured: vern98 with beta = 0.17 took 858 000
      ! steps for 100 periods of the pendulum at 1e-9); just below it, an ordinary integration
      call check_beta(rk_dop853, 0.105_wp, .false.)
      call check_beta(rk_dop853, 0.1_wp, .true.)
      call check_beta(rk_pd87, 0.105_wp, .false.)
      call check_beta(rk_vern98, 0.093_wp, .false.)
      call check_beta(rk_vern98, 0.09_wp, .true.)
      call check_beta(rk_dopri5, 0.115_wp, .false.)
      call check_beta(rk_dopri5, 0.11_wp, .true.)
   contains
      subroutine check_beta(method, beta, accepted)
         integer, intent(in) :: method
         real(wp), intent(in) :: beta
         logical, intent(in) :: accepted
         character(len=64) :: label
         t = 0.0_wp
         y(1:2) = [1.0_wp, 0.0_wp]
         write (label, '(a,a,f6.3)') rk_method_name(method), " beta =", beta
         call rk_integrate(osc, t, 10.0_wp, y(1:2), rk_options_t(method=method, rtol=1.0e-9_wp, atol=1.0e-9_wp, &
                           beta=beta), stats, error)
         if (accepted) then
            call check(ctx, .not. allocated(error), trim(label)//": accepted")
            ! the oscillator's closed form (cos t, −sin t) at t = 10 within 10·tol (measured
            ! 1.1e-13, 2.0e-14, 4.3e-13 for dop853, vern98, dopri5: so close to the limit the
            ! controller settles at errors far below 1 and over-resolves)
            call check(ctx, y(1), cos(10.0_wp), abs=1.0e-8_wp, message=trim(label)//": x(10)")
         else
            call check(ctx, allocated(error), trim(label)//": refused")
            if (allocated(error)) call check(ctx, error%code == err_invalid_parameter .and. &
               index(error%message, "beta") > 0, trim(label)//": code and message")
            call check(ctx, t == 0.0_wp .and. y(1) == 1.0_wp, trim(label)//": state untouched")
         end if
      end subroutine check_beta
   end subroutine error_paths

   !> A state of size 1e-20 keeps its relative accuracy when the per-component absolute
   !> tolerances are scaled with it; a fixed atol = 1e-10 drowns it (the closed form
   !> 1e-20 (cos t, −sin t) is the reference).
   subroutine tiny_state_relative(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp), parameter :: amplitude = 1.0e-20_wp
      real(wp) :: t, y(2), exact(2), rel_scaled, rel_fixed
      type(oscillator_t) :: osc
      type(work_stats_t) :: stats
      type(error_t), allocatable :: error
      type(rk_options_t) :: options
      exact = amplitude*[cos(20.0_wp), -sin(20.0_wp)]
      options = rk_options_t(rtol=1.0e-10_wp, atol=1.0e-10_wp)
      options%atol_components = [1.0e-10_wp*amplitude, 1.0e-10_wp*amplitude]
      t = 0.0_wp
      y = [amplitude, 0.0_wp]
      call rk_integrate(osc, t, 20.0_wp, y, options, stats, error)
      call check(ctx, .not. allocated(error), "scaled atol: integration succeeds")
      rel_scaled = norm2(y - exact)/amplitude
      t = 0.0_wp
      y = [amplitude, 0.0_wp]
      call rk_integrate(osc, t, 20.0_wp, y, rk_options_t(rtol=1.0e-10_wp, atol=1.0e-10_wp), error=error)
      call check(ctx, .not. allocated(error), "fixed atol: integration succeeds")
      rel_fixed = norm2(y - exact)/amplitude
      write (*, '(4x,a,es10.3,a,es10.3)') "x ~ 1e-20: relative error with scaled atol ", rel_scaled, &
         ", with atol = 1e-10 ", rel_fixed
      call check(ctx, rel_scaled < 1.0e-8_wp, "scaled atol keeps relative accuracy")
      call check(ctx, rel_fixed > 1.0e-3_wp, "a fixed atol drowns the tiny state (the trap this option avoids)")
      ! invalid component tolerances
      options%atol_components = [1.0e-10_wp, 0.0_wp]
      call rk_integrate(osc, t, 21.0_wp, y, options, stats, error)
      call check(ctx, allocated(error), "atol_components = 0 rejected")
      options%atol_components = [1.0e-10_wp]
      call rk_integrate(osc, t, 21.0_wp, y, options, stats, error)
      call check(ctx, allocated(error), "atol_components of the wrong size rejected")
   end subroutine tiny_state_relative

   ! ----------------------------------------------------------------------------------
   ! Hill monodromy
   ! ----------------------------------------------------------------------------------

   !> The half-period identity M = [[uv'+u'v, 2vv'], [2uu', uv'+u'v]] against a direct
   !> integration of the fundamental matrix over the full period [0, 2].
   subroutine half_equals_full_period(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp) :: alphas(3) = [1.48_wp, 5.0_wp, 9.0_wp], betas(3) = [2.47_wp, -3.0_wp, 12.0_wp]
      real(wp) :: half(2, 2), full(2, 2), t, y(4)
      class(hill_model_t), pointer :: model => null()
      type(hill_point_t) :: point
      type(scaled_matrix_t) :: m
      type(work_stats_t) :: stats
      type(error_t), allocatable :: error
      integer :: i, k
      type(hill_pair_t) :: pair
      do i = 1, size(alphas)
         do k = 1, 2   ! the elastic and the Mathieu model
            model => model_of_code(k)
            point = hill_point_t(alphas(i), betas(i), 0.0_wp)
            call monodromy_rk(model, point, 1.0e-12_wp, m, stats, error)
            call check(ctx, .not. allocated(error), "monodromy_rk succeeds")
            half = matrix_of(m)
            t = 0.0_wp
            y = [1.0_wp, 0.0_wp, 0.0_wp, 1.0_wp]
            pair%model => model
            pair%point = point
            call rk_integrate(pair, t, 2.0_wp, y, rk_options_t(rtol=1.0e-13_wp, atol=1.0e-13_wp), error=error)
            call check(ctx, .not. allocated(error), "full-period integration succeeds")
            full = reshape(y, [2, 2])
            call check(ctx, maxval(abs(half - full)) < 1.0e-10_wp*max(1.0_wp, maxval(abs(full))), &
               "half-period M = full-period M")
         end do
      end do
   end subroutine half_equals_full_period

   !> S by trace_rk against the segmented product with exact averages, Richardson-
   !> extrapolated from N = 2^15 and 2^16 pieces (second order), and the RK4 reference.
   subroutine trace_vs_references(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp) :: alphas(4) = [0.5_wp, 3.7_wp, 7.88_wp, 9.8_wp], betas(3) = [0.76_wp, 2.47_wp, 3.95_wp]
      real(wp) :: coarse, fine, reference, m4(2, 2), scale_s
      class(hill_model_t), pointer :: model => null()
      type(hill_point_t) :: point
      type(trace_t) :: tr
      type(error_t), allocatable :: error
      integer :: i, j, method
      character(len=64) :: label
      do i = 1, size(alphas)
         do j = 1, size(betas)
            model => model_of_code(1)
            point = hill_point_t(alphas(i), betas(j), 0.0_wp)
            coarse = value_of(trace_segmented(model, point, 2**15, sampling_average))
            fine = value_of(trace_segmented(model, point, 2**16, sampling_average))
            reference = (4.0_wp*fine - coarse)/3.0_wp
            scale_s = max(1.0_wp, abs(reference))
            write (label, '(a,f5.2,a,f5.2)') "alpha=", alphas(i), " beta=", betas(j)
            do method = rk_dopri5, rk_dop853
               call trace_rk(model, point, 1.0e-10_wp, tr, error, method=method)
               call check(ctx, .not. allocated(error), "trace_rk succeeds")
               ! the reference itself is good to ~1e-12 relative (difference to a 1e-15 run)
               call check(ctx, tr%value, reference, abs=1.0e-10_wp*scale_s, &
                  message=trim(label)//" vs segmented "//rk_method_name(method))
            end do
            if (alphas(i) < 9.0_wp) then
               m4 = rk4_monodromy(model, point, 0.0_wp, 4000)
               call check(ctx, tr%value, m4(1, 1) + m4(2, 2), abs=1.0e-8_wp*scale_s, message=trim(label)//" vs rk4")
            end if
         end do
      end do
   end subroutine trace_vs_references

   !> det M = (u v' − u' v)² = 1.
   subroutine unit_determinant(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp) :: alphas(4) = [0.0_wp, 4.0_wp, 8.0_wp, 9.8_wp], betas(4) = [-2.0_wp, 2.47_wp, 6.0_wp, 12.0_wp]
      type(scaled_matrix_t) :: m
      type(work_stats_t) :: stats
      type(error_t), allocatable :: error
      real(wp) :: plain(2, 2)
      integer :: i, j
      do i = 1, size(alphas)
         do j = 1, size(betas)
            call monodromy_rk(elastic_model_t(), hill_point_t(alphas(i), betas(j), 0.0_wp), 1.0e-12_wp, m, stats, error)
            call check(ctx, .not. allocated(error), "monodromy_rk succeeds")
            plain = matrix_of(m)
            ! the determinant of a matrix with entries ~E is known to ~E² · 1e-16
            call check(ctx, determinant(plain), 1.0_wp, abs=1.0e-12_wp*max(1.0_wp, maxval(abs(plain))**2*1.0e-3_wp))
         end do
      end do
   end subroutine unit_determinant

   !> α = 9.8 with β = −50, 400 and −400: finite, consistent with the segmented product;
   !> a coefficient so negative that S overflows is rescaled, not NaN.
   subroutine hard_cases(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp) :: betas(3) = [-50.0_wp, 400.0_wp, -400.0_wp], coarse, fine, reference
      class(hill_model_t), pointer :: model => null()
      type(hill_point_t) :: point
      type(trace_t) :: tr, segmented
      type(work_stats_t) :: stats
      type(error_t), allocatable :: error
      integer :: j
      do j = 1, size(betas)
         model => model_of_code(1)
         point = hill_point_t(9.8_wp, betas(j), 0.0_wp)
         call trace_rk(model, point, 1.0e-10_wp, tr, error, stats)
         call check(ctx, .not. allocated(error), "trace_rk succeeds")
         call check(ctx, ieee_is_finite(tr%value) .and. ieee_is_finite(tr%log_abs) .and. .not. tr%overflow, "finite")
         coarse = value_of(trace_segmented(model, point, 2**15, sampling_average))
         fine = value_of(trace_segmented(model, point, 2**16, sampling_average))
         reference = (4.0_wp*fine - coarse)/3.0_wp
         write (*, '(4x,a,f7.1,a,es22.14,a,es9.2,a,i0)') "alpha=9.8 beta=", betas(j), ": S = ", tr%value, &
            ", rel. diff to segmented ", abs(tr%value - reference)/max(1.0_wp, abs(reference)), &
            ", Q evaluations ", stats%n_evaluations
         call check(ctx, tr%value, reference, abs=1.0e-9_wp*max(1.0_wp, abs(reference)), message="vs segmented")
      end do
      ! S ~ e^2000: the pairs are rescaled on the way and the trace is flagged as overflowing
      model => model_of_code(1)
      point = hill_point_t(9.86_wp, -1.0e5_wp, 0.0_wp)
      call trace_rk(model, point, 1.0e-8_wp, tr, error, stats)
      call check(ctx, .not. allocated(error), "extreme case succeeds")
      segmented = trace_segmented(model, point, 2**16, sampling_average)
      write (*, '(4x,a,es12.5,a,es12.5,a,i0)') "alpha=9.86 beta=-1e5: ln S = ", tr%log_abs, " (segmented ", &
         segmented%log_abs, "), Q evaluations ", stats%n_evaluations
      call check(ctx, tr%overflow .and. ieee_is_finite(tr%log_abs), "overflow flagged, log finite")
      call check(ctx, tr%log_abs, segmented%log_abs, rel=1.0e-6_wp, message="ln S vs segmented")
   end subroutine hard_cases

   !> monodromy_trace dispatches method_rk; evaluation counts at tolerance 1e-10.
   subroutine dispatch_and_work(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp) :: points(2, 5)
      class(hill_model_t), pointer :: model => null()
      type(hill_point_t) :: point
      type(trace_t) :: tr, direct
      type(work_stats_t) :: stats
      type(error_t), allocatable :: error
      integer :: i
      points = reshape([1.48_wp, 2.47_wp, 3.7_wp, 2.47_wp, 7.88_wp, 3.95_wp, 9.8_wp, 2.47_wp, 9.8_wp, pi2/4], [2, 5])
      do i = 1, size(points, 2)
         model => model_of_code(1)
         point = hill_point_t(points(1, i), points(2, i), 0.0_wp)
         call monodromy_trace(model, point, method_t(method_rk, tolerance=1.0e-10_wp), tr, error)
         call check(ctx, .not. allocated(error), "method_rk available")
         call trace_rk(model, point, 1.0e-10_wp, direct, error, stats)
         call check(ctx, tr%value == direct%value, "dispatcher = trace_rk")
         call check(ctx, stats%n_evaluations > 0 .and. stats%n_steps > 0, "work counted")
         write (*, '(4x,a,f5.2,a,f5.2,a,es20.12,a,i0,a,i0,a,i0)') "alpha=", points(1, i), " beta=", points(2, i), &
            ": S = ", tr%value, ", Q evaluations ", stats%n_evaluations, ", steps ", stats%n_steps, &
            ", rejected ", stats%n_rejected
      end do
      ! damping: the χ equation carries −ε²/4
      model => model_of_code(2)
      point = hill_point_t(1.0_wp, 2.0_wp, 0.6_wp)
      call trace_rk(model, point, 1.0e-10_wp, tr, error)
      direct = trace_segmented(model, point, 2**15, sampling_average)
      call check(ctx, tr%value, direct%value, abs=1.0e-8_wp, message="damped mathieu vs segmented")
      call trace_rk(elastic_model_t(), hill_point_t(10.0_wp, 1.0_wp, 0.0_wp), 1.0e-10_wp, tr, error)
      call check(ctx, allocated(error), "alpha > pi**2 rejected")
      call trace_rk(model, point, 0.0_wp, tr, error)
      call check(ctx, allocated(error), "tolerance 0 rejected")
      call trace_rk(model, point, 1.0e-10_wp, tr, error, method=9)
      call check(ctx, allocated(error), "unknown method rejected")
   end subroutine dispatch_and_work

   ! ----------------------------------------------------------------------------------
   ! Prince–Dormand 8(7)
   ! ----------------------------------------------------------------------------------

   !> One fixed step of PD8(7) equals one step of GSL's rk8pd (the same tableau, with the
   !> stage sums in the same order; bit for bit without FMA contraction) from the same state
   !> with the same h, on the pendulum,
   !> the Arenstorf problem and a time-dependent Hill pair (which sees the nodes c_i).
   !> hillstab's error norm equals the RMS of GSL's yerr: with rtol = 0 and atol just above
   !> it the first step is accepted, just below it rejected.
   subroutine pd87_step_equals_gsl(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(pendulum_system_t), target :: pendulum
      type(three_body_t), target :: body
      type(hill_pair_t), target :: pair
      type(c_funptr) :: previous
      previous = gsl_set_error_handler_off()
      pendulum%pendulum = pendulum_at(7.88_wp, 3.95_wp)
      call compare(pendulum, 0.0_wp, pendulum%pendulum%period/8, pendulum_initial_state(pendulum%pendulum, 0.3_wp), &
         "pendulum (e) phi0=0.3")
      call compare(body, 0.0_wp, 0.01_wp, arenstorf_start, "arenstorf")
      pair%model => model_of_code(1)
      pair%point = hill_point_t(7.88_wp, 3.95_wp, 0.0_wp)
      call compare(pair, 0.3_wp, 0.2_wp, [1.0_wp, 0.0_wp, 0.0_wp, 1.0_wp], "hill pair alpha=7.88 beta=3.95")
   contains
      subroutine compare(system, t0, h, y0, label)
         class(rk_system_t), intent(inout), target :: system
         real(wp), intent(in) :: t0, h, y0(:)
         character(len=*), intent(in) :: label
         type(gsl_context_t), target :: context
         type(gsl_odeiv2_system) :: gsl_system
         type(c_ptr) :: stepper
         type(work_stats_t) :: stats
         type(error_t), allocatable :: error
         type(rk_options_t) :: options
         real(wp) :: t, t_end, hh, y(size(y0)), y_gsl(size(y0)), y_err(size(y0)), rel, ulps, rms
         integer(c_int) :: status
         integer :: n, i
         n = size(y0)
         t_end = t0 + h
         hh = t_end - t0   ! the step rk_integrate takes
         t = t0
         y = y0
         call rk_integrate(system, t, t_end, y, rk_options_t(method=rk_pd87, fixed_steps=1), stats, error)
         call check(ctx, .not. allocated(error), label//": hillstab step")
         call check(ctx, stats%n_evaluations == 14, label//": 13 stages + f at the new point")
         context%system => system
         context%n = n
         gsl_system = gsl_odeiv2_system(c_funloc(gsl_system_rhs), c_null_funptr, int(n, c_size_t), c_loc(context))
         stepper = gsl_odeiv2_step_alloc(gsl_odeiv2_step_rk8pd, int(n, c_size_t))
         call check(ctx, c_associated(stepper), label//": GSL stepper allocated")
         if (.not. c_associated(stepper)) return
         y_gsl = y0
         status = gsl_odeiv2_step_apply(stepper, t0, hh, y_gsl, y_err, c_null_ptr, c_null_ptr, gsl_system)
         call gsl_odeiv2_step_free(stepper)
         call check(ctx, status == 0, label//": GSL step")
         rel = 0.0_wp
         ulps = 0.0_wp
         do i = 1, n
            rel = max(rel, abs(y(i) - y_gsl(i))/max(abs(y0(i)), abs(y_gsl(i))))
            ulps = max(ulps, abs(y(i) - y_gsl(i))/spacing(max(abs(y0(i)), abs(y_gsl(i)))))
         end do
         rms = sqrt(sum(y_err**2)/n)
         write (*, '(4x,a,a,es9.2,a,es8.1,a,es9.2)') label, ": |pd87 - gsl rk8pd| relative ", rel, &
            " (", ulps, " ulps), rms of GSL's yerr ", rms
         ! bit for bit where a*b + c is not contracted into fused multiply-adds (the default
         ! and debug builds: measured 0 ulps); with FMA contraction (the release build with
         ! -march=native) the stage sums round differently: measured up to 8 ulps (Arenstorf)
         call check(ctx, ulps <= 16.0_wp, label//": one step equals GSL's rk8pd (to FMA rounding)")
         ! the error estimate: accepted at atol = rms(yerr)·(1 + 1e-6), rejected at (1 − 1e-6).
         ! Measured: the decision flips within 1e-11 (pendulum), 1e-13 (Arenstorf) and 1e-9
         ! (Hill pair, whose yerr of 6e-8 is GSL's difference of two sums ~1: cancellation)
         do i = 1, 2
            options = rk_options_t(method=rk_pd87, rtol=0.0_wp, h_initial=hh, max_steps=2)
            options%atol_components = spread(rms*merge(1.0_wp + 1.0e-6_wp, 1.0_wp - 1.0e-6_wp, i == 1), 1, n)
            t = t0
            y = y0
            call rk_integrate(system, t, t_end, y, options, stats, error)
            if (i == 1) then
               call check(ctx, .not. allocated(error) .and. stats%n_rejected == 0 .and. stats%n_steps == 1, &
                  label//": accepted with atol just above GSL's rms yerr")
            else
               call check(ctx, stats%n_rejected >= 1, label//": rejected with atol just below GSL's rms yerr")
            end if
         end do
      end subroutine compare
   end subroutine pd87_step_equals_gsl

   !> Fixed-step convergence at order 8 on y' = y² cos t, y(0) = 1/2, y = 1/(2 − sin t) on
   !> [0, 20] (nonlinear and time-dependent, so the nodes c_i matter). PD8(7) was built for a
   !> small principal error, so the h⁹ term still shows at these steps: measured orders 8.35
   !> (N = 80, 160) and 8.25 (N = 120, 240), errors 9.1e-11 … 1.0e-14, falling towards 8;
   !> the bounds [7.7, 8.7] leave that margin. (The oscillator is no test of order 8 here:
   !> on linear problems b·A⁸·1 · 9! = 0.9987, so the h⁹ term is 1.3e-3 of its Taylor size
   !> and the h¹⁰ term dominates until round-off: 8.9 at N = 20, 40.)
   subroutine pd87_order(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp) :: order
      integer :: n
      do n = 80, 120, 40
         order = log(riccati_error(n)/riccati_error(2*n))/log(2.0_wp)
         write (*, '(4x,a,i0,a,i0,a,f6.2,a,es9.2)') "pd87 y'=y^2 cos t N=", n, ",", 2*n, ": observed order ", &
            order, ", error ", riccati_error(2*n)
         call check(ctx, order >= 7.7_wp .and. order <= 8.7_wp, "pd87 order 8")
      end do
   contains
      real(wp) function riccati_error(n_steps) result(err)
         integer, intent(in) :: n_steps
         type(riccati_t) :: problem
         type(error_t), allocatable :: error
         real(wp) :: t, y(1)
         t = 0.0_wp
         y = 0.5_wp
         call rk_integrate(problem, t, 20.0_wp, y, rk_options_t(method=rk_pd87, fixed_steps=n_steps), error=error)
         call check(ctx, .not. allocated(error), "riccati integration")
         err = abs(y(1) - 1.0_wp/(2.0_wp - sin(20.0_wp)))
      end function riccati_error
   end subroutine pd87_order

   !> The pendulum of Fig. 4 (e) (α = 7.88, β = 3.95, φ0 = 0.017; the swing grows to 0.65 rad)
   !> over 10 radial periods by PD8(7) at rtol = 1e-10 and 1e-12 against DOP853 at 1e-14, the
   !> error in units of (ρ, ρ, ρω, ρω). Measured: 1.9e-9 and 1.4e-11 (14–19 rtol; DOP853 at the
   !> same rtol: 2.8e-9 and 2.4e-11); the reference is good to ~6e-13 (PD8(7) at 1e-14 differs
   !> by that), so the bound 50 rtol holds with a margin of about 3. The energy drift of PD8(7)
   !> at 1e-12 over 50 periods, relative to the energy scale: measured 3.0e-12, bound 1e-10.
   subroutine pd87_pendulum(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(pendulum_watch_t) :: system  ! its observer keeps the largest energy error at the step ends
      type(rk_options_t) :: options
      type(work_stats_t) :: stats
      type(error_t), allocatable :: error
      real(wp) :: t, y0(4), reference(4), y(4), scale(4), err, drift
      real(wp) :: rtols(2) = [1.0e-10_wp, 1.0e-12_wp]
      integer :: k
      system%pendulum = pendulum_at(7.88_wp, 3.95_wp)
      associate (p => system%pendulum)
         y0 = pendulum_initial_state(p, 0.017_wp)
         scale = [p%rho, p%rho, p%rho*p%omega, p%rho*p%omega]
         options = rk_options_t(method=rk_dop853, rtol=1.0e-14_wp, max_steps=10**6)
         options%atol_components = pendulum_atol(p, y0, 1.0e-14_wp)
         t = 0.0_wp
         reference = y0
         call rk_integrate(system, t, 10*p%period, reference, options, stats, error)
         call check(ctx, .not. allocated(error), "dop853 reference")
         do k = 1, 2
            options = rk_options_t(method=rk_pd87, rtol=rtols(k), max_steps=10**6)
            options%atol_components = pendulum_atol(p, y0, rtols(k))
            t = 0.0_wp
            y = y0
            call rk_integrate(system, t, 10*p%period, y, options, stats, error)
            call check(ctx, .not. allocated(error), "pd87 integration")
            err = maxval(abs(y - reference)/scale)
            write (*, '(4x,a,es8.1,a,es10.3,a,f8.4,a,i0,a,i0,a,i0)') "pendulum (e) 10 periods pd87 rtol ", rtols(k), &
               ": error/(rho, rho omega) ", err, ", phi ", atan2(y(1), y(2)), ", f-evals ", stats%n_evaluations, &
               ", accepted ", stats%n_steps, ", rejected ", stats%n_rejected
            call check(ctx, err < 50.0_wp*rtols(k), "pd87 vs dop853 at 1e-14 within 50 rtol")
         end do
         options = rk_options_t(method=rk_pd87, rtol=1.0e-12_wp, max_steps=10**6)
         options%atol_components = pendulum_atol(p, y0, 1.0e-12_wp)
         t = 0.0_wp
         y = y0
         call rk_integrate(system, t, 50*p%period, y, options, stats, error)
         call check(ctx, .not. allocated(error), "pd87 50 periods")
         drift = system%max_energy_error/system%energy_scale
         write (*, '(4x,a,es10.3,a,i0)') "pendulum (e) pd87 rtol 1e-12: max energy drift over 50 periods ", drift, &
            ", steps ", stats%n_steps
         call check(ctx, drift < 1.0e-10_wp, "energy drift < 1e-10")
      end associate
   end subroutine pd87_pendulum

   !> PD8(7) has no continuous extension: t_out and dense_output are refused (state
   !> untouched); observers get the cubic Hermite interpolant (order 3: the midpoint error
   !> converges at order 4). Name and order.
   subroutine pd87_refusals(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(oscillator_t) :: osc
      type(work_stats_t) :: stats
      type(error_t), allocatable :: error
      real(wp) :: t, y(2), y_out(2, 1)
      integer :: k
      do k = 1, 2
         t = 0.0_wp
         y = [1.0_wp, 0.0_wp]
         if (k == 1) then
            call rk_integrate(osc, t, 1.0_wp, y, rk_options_t(method=rk_pd87), stats, error, t_out=[0.5_wp], &
                              y_out=y_out)
         else
            call rk_integrate(osc, t, 1.0_wp, y, rk_options_t(method=rk_pd87, dense_output=.true.), stats, error)
         end if
         call check(ctx, allocated(error), "pd87 refuses "//merge("t_out       ", "dense_output", k == 1))
         if (allocated(error)) call check(ctx, error%code == err_invalid_parameter, "refusal code")
         call check(ctx, t == 0.0_wp .and. y(1) == 1.0_wp .and. y(2) == 0.0_wp, "state unchanged")
         call check(ctx, stats%n_evaluations == 0, "nothing evaluated")
      end do
      call check(ctx, rk_method_name(rk_pd87) == "pd87", "name")
      call check(ctx, rk_method_order(rk_pd87) == 8, "order")
      call check_order(ctx, midpoint_error(ctx, rk_pd87, .false., 40), midpoint_error(ctx, rk_pd87, .false., 80), &
         4.0_wp, "pd87 hermite midpoints")
   end subroutine pd87_refusals

   !> Evaluation counts: 13 per accepted step (12 stages after k1, then f at the new point),
   !> 12 per rejected one, plus f(y0) and, without h_initial, the one evaluation of the
   !> initial step guess. Exactly, on the Arenstorf orbit (which has rejections), which
   !> also returns to its start.
   subroutine pd87_work(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(three_body_t) :: body
      type(work_stats_t) :: stats
      type(error_t), allocatable :: error
      real(wp) :: t, y(4)
      integer :: k
      do k = 1, 2
         t = 0.0_wp
         y = arenstorf_start
         call rk_integrate(body, t, arenstorf_period, y, rk_options_t(method=rk_pd87, rtol=1.0e-10_wp, &
                           atol=1.0e-10_wp, h_initial=merge(0.0_wp, 1.0e-3_wp, k == 1)), stats, error)
         call check(ctx, .not. allocated(error), "integration succeeds")
         write (*, '(4x,a,a,a,es10.3,a,i0,a,i0,a,i0)') "arenstorf pd87 tol 1e-10", merge(" (hinit)  ", " h0 = 1e-3", &
            k == 1), ": position error ", norm2(y(1:2) - arenstorf_start(1:2)), ", f-evals ", stats%n_evaluations, &
            ", accepted ", stats%n_steps, ", rejected ", stats%n_rejected
         call check(ctx, norm2(y(1:2) - arenstorf_start(1:2)) < 100.0_wp*1.0e-10_wp, "position error within 100 tol")
         call check(ctx, stats%n_rejected > 0, "there are rejections")
         call check(ctx, stats%n_evaluations == 13*stats%n_steps + 12*stats%n_rejected + merge(2, 1, k == 1), &
            "evaluations = 13 accepted + 12 rejected + initial")
      end do
      t = 0.0_wp
      y = arenstorf_start
      call rk_integrate(body, t, 1.0_wp, y, rk_options_t(method=rk_pd87, fixed_steps=50), stats, error)
      call check(ctx, stats%n_evaluations == 1 + 13*50 .and. stats%n_steps == 50, "fixed steps: 1 + 13 per step")
   end subroutine pd87_work

   ! ----------------------------------------------------------------------------------
   ! Verner's 9(8) pair
   ! ----------------------------------------------------------------------------------

   !> The tableau of rk_vern98 as the integrator holds it, against its defining
   !> conditions: row sums Σ_j a_ij = c_i (every stage), quadrature Σ b_i c_i^(q−1) = 1/q
   !> for q = 1…9 (9th-order weights) and q = 1…8 (8th-order weights), which must fail at
   !> q = 9 (a genuinely lower-order embedded formula). Residuals are compared with the
   !> rounding of the double-precision coefficients (a few ulp of Σ|terms|); a wrong or
   !> truncated digit anywhere in a row or weight shows up far above that.
   subroutine vern98_tableau(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp) :: c(16), a(16, 16), b(16), bh(16), residual, worst_row, worst_b, worst_bh
      integer :: i, q
      character(len=40) :: label
      call rk_vern98_tableau(c, a, b, bh)
      call check(ctx, rk_method_order(rk_vern98) == 9 .and. rk_method_name(rk_vern98) == "vern98", &
         "vern98: name and order")
      call check(ctx, all([(all(a(i, i:) == 0.0_wp), i = 1, 16)]), "explicit: a(i, j) = 0 for j >= i")
      worst_row = 0.0_wp
      do i = 2, 16
         residual = abs(sum(a(i, :)) - c(i))
         worst_row = max(worst_row, residual)
         write (label, '(a,i0)') "row sum = c, stage ", i
         call check(ctx, residual <= 4.0_wp*epsilon(1.0_wp)*sum(abs(a(i, :))), trim(label))
      end do
      worst_b = 0.0_wp
      worst_bh = 0.0_wp
      do q = 1, 9
         residual = abs(sum(b*c**(q - 1)) - 1.0_wp/q)
         worst_b = max(worst_b, residual)
         write (label, '(a,i0)') "9th-order quadrature q = ", q
         call check(ctx, residual <= 4.0_wp*epsilon(1.0_wp)*sum(abs(b*c**(q - 1))), trim(label))
         residual = abs(sum(bh*c**(q - 1)) - 1.0_wp/q)
         if (q <= 8) then
            worst_bh = max(worst_bh, residual)
            write (label, '(a,i0)') "8th-order quadrature q = ", q
            call check(ctx, residual <= 4.0_wp*epsilon(1.0_wp)*sum(abs(bh*c**(q - 1))), trim(label))
         else
            write (*, '(4x,a,es10.2)') "vern98 8th-order weights at q = 9: residual ", residual
            call check(ctx, residual > 1.0e-7_wp, "8th-order weights are not 9th-order")
         end if
      end do
      write (*, '(4x,a,es10.2,a,es10.2,a,es10.2)') "vern98 largest residuals: row sums ", worst_row, &
         ", quadrature b ", worst_b, ", quadrature b^ ", worst_bh
   end subroutine vern98_tableau

   !> Observed order of rk_vern98 with fixed steps on a smooth nonlinear problem with a
   !> closed-form solution: the planar limit cycle y' = J y + (1 − |y|²) y from r0 = 2 to
   !> t = 2 (errors 1e-8 … 3e-14, above round-off). Error ratio 2^9 when halving h; the
   !> observed order approaches 9 from above (9.4, 9.2, 9.1 from N = 8 on). Also the
   !> work of a fixed step: 15 evaluations (stage 16 only serves the error estimate).
   subroutine vern98_order(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp) :: e(3)
      type(work_stats_t) :: stats
      integer :: k
      do k = 1, 3
         e(k) = cycle_error(16*2**(k - 1))
      end do
      write (*, '(4x,a,3es10.2)') "vern98 limit cycle, N = 16, 32, 64: errors ", e
      call check_order(ctx, e(1), e(2), 9.0_wp, "vern98 limit cycle N=16,32")
      call check_order(ctx, e(2), e(3), 9.0_wp, "vern98 limit cycle N=32,64")
      call check(ctx, stats%n_evaluations == 1 + 15*64, "fixed steps: 15 evaluations per step")
   contains
      real(wp) function cycle_error(n_steps) result(err)
         integer, intent(in) :: n_steps
         real(wp), parameter :: r0 = 2.0_wp, t_end = 2.0_wp
         real(wp) :: t, y(2), r
         type(error_t), allocatable :: error
         type(limit_cycle_t) :: spiral
         y = [r0, 0.0_wp]
         t = 0.0_wp
         call rk_integrate(spiral, t, t_end, y, rk_options_t(method=rk_vern98, fixed_steps=n_steps), stats, error)
         r = 1.0_wp/sqrt(1.0_wp + (1.0_wp/r0**2 - 1.0_wp)*exp(-2.0_wp*t_end))
         err = norm2(y - r*[cos(t_end), sin(t_end)])
         if (allocated(error)) err = huge(1.0_wp)
      end function cycle_error
   end subroutine vern98_order

   !> The nonlinear pendulum of Fig. 4 (e) (α = 7.88, β = 3.95, φ0 = 0.017) over 10 radial
   !> periods by rk_vern98 at rtol 1e-10 and 1e-12 (atol from pendulum_atol) against DOP853
   !> at 1e-14; the state error scaled by ρ and ρω, within 50 rtol as for PD8(7) (measured
   !> 1.1e-9 and 1.8e-11). Also: the evaluation count of a pair
   !> that is not FSAL (16 per accepted step, 15 per rejected one, 2 to start), and the
   !> refusal of dense output, which the pair does not have.
   subroutine vern98_pendulum(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(pendulum_system_t) :: system
      real(wp) :: y0(4), reference(4), y(4), t, t_end, errors(2), y_out(4, 1)
      real(wp), parameter :: tolerances(2) = [1.0e-10_wp, 1.0e-12_wp], bounds(2) = [5.0e-9_wp, 5.0e-11_wp]
      type(work_stats_t) :: stats
      type(error_t), allocatable :: error
      type(rk_options_t) :: options
      integer :: k
      system%pendulum = pendulum_at(7.88_wp, 3.95_wp, 0.0_wp)
      y0 = pendulum_initial_state(system%pendulum, 0.017_wp)
      t_end = 10*system%pendulum%period
      reference = y0
      call run(rk_dop853, 1.0e-14_wp, reference)
      do k = 1, 2
         y = y0
         call run(rk_vern98, tolerances(k), y)
         call check(ctx, .not. allocated(error), "vern98 pendulum integration succeeds")
         associate (p => system%pendulum)
            errors(k) = max(maxval(abs(y(1:2) - reference(1:2)))/p%rho, &
                            maxval(abs(y(3:4) - reference(3:4)))/(p%rho*p%omega))
         end associate
         write (*, '(4x,a,es8.1,a,es10.3,a,i0,a,i0,a,i0)') "vern98 pendulum (e), 10 periods, rtol ", tolerances(k), &
            ": scaled error vs dop853 1e-14 ", errors(k), ", f-evals ", stats%n_evaluations, ", accepted ", &
            stats%n_steps, ", rejected ", stats%n_rejected
         call check(ctx, errors(k) < bounds(k), "vern98 pendulum error within bound")
         call check(ctx, stats%n_evaluations == 2 + 16*stats%n_steps + 15*stats%n_rejected, &
            "vern98 evaluations: 2 + 16 per accepted + 15 per rejected step")
      end do
      call check(ctx, errors(2) < errors(1)/10.0_wp, "error decreases with the tolerance")
      ! no continuous extension of its own: t_out and dense_output are refused
      y = y0
      t = 0.0_wp
      call rk_integrate(system, t, t_end, y, rk_options_t(method=rk_vern98), stats, error, t_out=[t_end], &
                        y_out=y_out)
      call check(ctx, allocated(error), "vern98 t_out refused")
      if (allocated(error)) call check(ctx, error%code == err_invalid_parameter, "vern98 t_out: code")
      call rk_integrate(system, t, t_end, y, rk_options_t(method=rk_vern98, dense_output=.true.), stats, error)
      call check(ctx, allocated(error), "vern98 dense_output refused")
   contains
      subroutine run(method, tolerance, state)
         integer, intent(in) :: method
         real(wp), intent(in) :: tolerance
         real(wp), intent(inout) :: state(4)
         options = rk_options_t(method=method, rtol=tolerance, atol=tolerance, max_steps=10**6)
         options%atol_components = pendulum_atol(system%pendulum, state, tolerance)
         t = 0.0_wp
         call rk_integrate(system, t, t_end, state, options, stats, error)
      end subroutine run
   end subroutine vern98_pendulum

   ! ----------------------------------------------------------------------------------
   ! the plumbing of the four pairs: direction, observer, failures, step limit
   ! ----------------------------------------------------------------------------------

   !> Backward integration of every pair, adaptive and fixed-step, on y' = t y² (time-
   !> dependent, odd in t): from y(0) = 0.1 to t = −3 it must equal the forward run to
   !> t = 3 bit for bit (state, steps, rejections, evaluations, h_next mirrored), and the
   !> forward run must meet the closed form 1/(10 − t²/2).
   subroutine backward_mirror(ctx)
      type(test_context_t), intent(inout) :: ctx
      integer, parameter :: methods(4) = [rk_dopri5, rk_dop853, rk_pd87, rk_vern98]
      real(wp), parameter :: y0 = 0.1_wp, t_span = 3.0_wp
      ! errors at t = 3 (y = 0.18), measured: adaptive at 1e-10 1.9e-10 (DOPRI5), 1.5e-11,
      ! 4.4e-11, 5.2e-12; 20 fixed steps 5.6e-10 (DOPRI5), 1.3e-14, 5.8e-15, 6e-17
      real(wp), parameter :: bounds(4, 2) = reshape([5.0e-10_wp, 5.0e-11_wp, 1.0e-10_wp, 2.0e-11_wp, &
                                                     2.0e-9_wp, 5.0e-14_wp, 2.0e-14_wp, 1.0e-15_wp], [4, 2])
      type(odd_in_time_t) :: problem
      type(work_stats_t) :: stats(2)
      type(error_t), allocatable :: error
      real(wp) :: t(2), y(1, 2), h_next(2), exact
      integer :: m, mode, direction
      character(len=40) :: label
      exact = 1.0_wp/(1.0_wp/y0 - 0.5_wp*t_span**2)
      do m = 1, size(methods)
         do mode = 1, 2
            write (label, '(a,a)') rk_method_name(methods(m)), merge(" adaptive", " fixed   ", mode == 1)
            do direction = 1, 2
               t(direction) = 0.0_wp
               y(:, direction) = y0
               call rk_integrate(problem, t(direction), merge(t_span, -t_span, direction == 1), y(:, direction), &
                                 rk_options_t(method=methods(m), rtol=1.0e-10_wp, atol=1.0e-10_wp, &
                                              fixed_steps=merge(0, 20, mode == 1)), stats(direction), error, &
                                 h_next=h_next(direction))
               call check(ctx, .not. allocated(error), trim(label)//": integration succeeds")
            end do
            write (*, '(4x,a,a,es10.3,a,i0,a,i0)') trim(label), ": y' = t y^2, error at t = 3 ", &
               abs(y(1, 1) - exact), ", steps ", stats(1)%n_steps, ", rejected ", stats(1)%n_rejected
            call check(ctx, t(1) == t_span .and. t(2) == -t_span, trim(label)//": both reach t_end")
            call check(ctx, y(1, 2) == y(1, 1), trim(label)//": backward = forward mirrored, bit for bit")
            call check(ctx, stats(2)%n_steps == stats(1)%n_steps .and. stats(2)%n_rejected == stats(1)%n_rejected &
               .and. stats(2)%n_evaluations == stats(1)%n_evaluations, trim(label)//": the same work")
            call check(ctx, h_next(1) > 0.0_wp .and. h_next(2) == -h_next(1), trim(label)//": h_next mirrored")
            call check(ctx, y(1, 1), exact, abs=bounds(m, mode), message=trim(label)//": closed form")
         end do
      end do
   end subroutine backward_mirror

   !> The observer with PD8(7) and VERN98, adaptive and fixed-step: each accepted step comes
   !> with its pair, the cubic Hermite interpolant (dense_order 3, coefficients 4–7 zero),
   !> contiguous intervals; stopping after 3 steps ends the integration there, no error, the
   !> state at the stop on the closed form (cos t, −sin t) and the work of exactly 3 steps.
   !> VERN98's Hermite interpolant converges at order 4 at the step midpoints.
   subroutine new_pairs_observer(ctx)
      type(test_context_t), intent(inout) :: ctx
      integer, parameter :: methods(2) = [rk_pd87, rk_vern98], per_step(2) = [13, 16], per_fixed(2) = [13, 15]
      type(hermite_watch_t) :: watch
      type(work_stats_t) :: stats
      type(error_t), allocatable :: error
      real(wp) :: t, y(2), h_next
      integer :: m, mode
      character(len=40) :: label
      do m = 1, size(methods)
         do mode = 1, 2
            write (label, '(a,a)') rk_method_name(methods(m)), merge(" adaptive", " fixed   ", mode == 1)
            watch = hermite_watch_t(method=methods(m))
            t = 0.0_wp
            y = [1.0_wp, 0.0_wp]
            call rk_integrate(watch, t, 10.0_wp, y, rk_options_t(method=methods(m), rtol=1.0e-10_wp, &
                              atol=1.0e-10_wp, h_initial=0.1_wp, fixed_steps=merge(0, 40, mode == 1)), stats, error, &
                              h_next=h_next)
            call check(ctx, .not. allocated(error), trim(label)//": stopping is not an error")
            call check(ctx, watch%consistent, trim(label)//": pair, Hermite interpolant, contiguous steps")
            call check(ctx, watch%seen == 4 .and. stats%n_steps == 3, trim(label)//": stopped after 3 steps")
            call check(ctx, t == watch%t_previous .and. t > 0.0_wp .and. t < 10.0_wp, trim(label)//": t at the stop")
            call check(ctx, y(1), cos(t), abs=1.0e-9_wp, message=trim(label)//": x at the stop")
            call check(ctx, y(2), -sin(t), abs=1.0e-9_wp, message=trim(label)//": x' at the stop")
            ! a stopped run can be resumed: h_next is the next step (the fixed step, in fixed mode)
            call check(ctx, merge(h_next > 0.0_wp, h_next == 10.0_wp/40, mode == 1), &
               trim(label)//": h_next at the stop")
            if (mode == 1) then
               call check(ctx, stats%n_evaluations == 1 + per_step(m)*3 + (per_step(m) - 1)*stats%n_rejected, &
                  trim(label)//": evaluations of 3 steps")
            else
               call check(ctx, t == 3*(10.0_wp/40) .and. stats%n_evaluations == 1 + per_fixed(m)*3, &
                  trim(label)//": 3 fixed steps and their evaluations")
            end if
         end do
      end do
      call check_order(ctx, midpoint_error(ctx, rk_vern98, .false., 40), midpoint_error(ctx, rk_vern98, .false., 80), &
         4.0_wp, "vern98 hermite midpoints")
   end subroutine new_pairs_observer

   !> A non-finite derivative at any evaluation of PD8(7) and VERN98 (adaptive and
   !> fixed-step) is caught at that evaluation: the integration stops with err_integration
   !> and a message naming where, no further evaluation, t and y at the last accepted point.
   !> Every evaluation of the first step is tried (f(y0), each stage, f at the new point),
   !> then one stage of the second step.
   subroutine new_pairs_non_finite(ctx)
      type(test_context_t), intent(inout) :: ctx
      integer, parameter :: methods(2) = [rk_pd87, rk_vern98]
      ! evaluations of the first step, h_initial given: f(y0), the stages, f at the new
      ! point (VERN98's fixed steps skip stage 16)
      integer, parameter :: first_step(2, 2) = reshape([14, 17, 14, 16], [2, 2])
      type(failing_at_t) :: system
      type(work_stats_t) :: stats
      type(error_t), allocatable :: error
      real(wp) :: t, y(2)
      integer :: m, mode, j, n_first
      logical :: caught, where_named, state_kept
      character(len=40) :: label, where
      do m = 1, size(methods)
         do mode = 1, 2
            write (label, '(a,a)') rk_method_name(methods(m)), merge(" adaptive", " fixed   ", mode == 1)
            n_first = first_step(m, mode)
            caught = .true.
            where_named = .true.
            state_kept = .true.
            do j = 1, n_first + 5
               system = failing_at_t(fail_at=j)
               t = 0.0_wp
               y = [1.0_wp, 0.0_wp]
               call rk_integrate(system, t, 1.0_wp, y, rk_options_t(method=methods(m), rtol=1.0e-10_wp, &
                                 atol=1.0e-10_wp, h_initial=0.1_wp, fixed_steps=merge(0, 10, mode == 1)), stats, error)
               if (j == 1) then
                  where = "initial state"
               else if (j == n_first) then
                  where = "end of accepted step"
               else
                  where = merge("trial step", "fixed step", mode == 1)
               end if
               caught = caught .and. allocated(error) .and. system%calls == j .and. stats%n_evaluations == j
               if (.not. allocated(error)) cycle
               where_named = where_named .and. error%code == err_integration .and. &
                  index(error%message, "non-finite") > 0 .and. index(error%message, trim(where)) > 0
               if (j <= n_first) then
                  state_kept = state_kept .and. t == 0.0_wp .and. all(y == [1.0_wp, 0.0_wp]) .and. stats%n_steps == 0
               else
                  state_kept = state_kept .and. t > 0.0_wp .and. stats%n_steps == 1 .and. &
                     abs(y(1) - cos(t)) < 1.0e-9_wp
               end if
            end do
            call check(ctx, caught, trim(label)//": caught at the failing evaluation, none after")
            call check(ctx, where_named, trim(label)//": err_integration naming where")
            call check(ctx, state_kept, trim(label)//": t and y at the last accepted point")
         end do
      end do
   end subroutine new_pairs_non_finite

   !> max_steps with PD8(7) and VERN98: the Arenstorf orbit at 1e-10 with 20 attempts
   !> stops with err_integration after exactly 20 attempted steps, inside the interval,
   !> at a finite state.
   subroutine new_pairs_max_steps(ctx)
      type(test_context_t), intent(inout) :: ctx
      integer, parameter :: methods(2) = [rk_pd87, rk_vern98]
      type(three_body_t) :: body
      type(work_stats_t) :: stats
      type(error_t), allocatable :: error
      real(wp) :: t, y(4)
      integer :: m
      do m = 1, size(methods)
         t = 0.0_wp
         y = arenstorf_start
         call rk_integrate(body, t, arenstorf_period, y, rk_options_t(method=methods(m), rtol=1.0e-10_wp, &
                           atol=1.0e-10_wp, max_steps=20), stats, error)
         call check(ctx, allocated(error), rk_method_name(methods(m))//" max_steps: error")
         if (allocated(error)) call check(ctx, error%code == err_integration .and. &
            index(error%message, "max_steps") > 0, rk_method_name(methods(m))//" max_steps: code and message")
         call check(ctx, stats%n_steps + stats%n_rejected == 20, rk_method_name(methods(m))//" max_steps: 20 attempts")
         call check(ctx, all(ieee_is_finite(y)) .and. t > 0.0_wp .and. t < arenstorf_period, &
            rk_method_name(methods(m))//" max_steps: state kept")
      end do
   end subroutine new_pairs_max_steps
end module test_rk

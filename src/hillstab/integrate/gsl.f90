!> hillstab's own `bind(C)` bindings to the few GSL routines it uses, and two
!> references built on them:
!>
!> - Mathieu characteristic values a_n(q), b_n(q) (`gsl_sf_mathieu_a_e/_b_e`) and
!>   the transition curves of the paper's Mathieu form q(τ) = β − ν cos πτ (A1):
!>   with z = πτ/2 it is y'' + (a − 2q cos 2z) y = 0, a = 4β/π², q = 2ν/π², so the
!>   curves are β = (π²/4) a_n(2ν/π²) and β = (π²/4) b_n(2ν/π²) (BRIEF §5);
!> - the one-period monodromy of the χ equation (47) by GSL's odeiv2 driver with
!>   the Prince–Dormand 8(7) pair `rk8pd`, using the even symmetry of Q: the even
!>   and odd solutions u, v are integrated on [0, 1] only (BRIEF §4).
!>
!> GSL's default error handler aborts the program; every entry point here first
!> switches it off (`gsl_set_error_handler_off`) and checks status codes, which it
!> reports through `error_t`. No module variable holds state: the right-hand side
!> receives the model and its evaluation counter through GSL's `params` pointer, so
!> the routines may be called from several OpenMP threads at once. (The handler
!> switch writes one GSL global; every thread writes the same value, null.)
!>
!> Accuracy of the monodromy: GSL's control keeps each step's error in every
!> component below eps·(1 + |y_i|). The error in S, relative to max(1, |S|), came out
!> at 0.1–0.3·κ·eps, where κ compares the size the solutions reach inside the period
!> with S; κ ≲ 5 over most of the chart but reaches ~3e3 at α → π², β → 0 (e.g.
!> α = 9.8, β = 0, where S = 2). A local epsilon therefore does not bound the error of
!> S: `monodromy_gsl` integrates with eps = tolerance·gsl_tolerance_factor, then eps
!> divided by max(10, κ/2), then by 10, until two successive traces agree to the
!> tolerance (hillstab_integrate_refine), and reports round-off limited (err_accuracy) where eps
!> reaches its floor 1e-15 or GSL's control cannot meet it (GSL_FAILURE). The driver's
!> loop is run here (`integrate_pair`) so that every step is exact in time (GSL advances
!> t by a rounded t + h; over the 1e4 steps at |β| ~ 1e5 that cost up to 3e-12 in S),
!> and the solutions are rescaled by powers of two. Measured against the 50-digit
!> references of data/reference/ (README, *Accuracy*).
!>
!>```fortran
!> type(trace_t) :: tr
!> type(work_stats_t) :: stats
!> type(error_t), allocatable :: error
!> call trace_gsl(hill_model_t(model_elastic, 9.8_wp, 2.47_wp, 0.0_wp), 1.0e-12_wp, tr, stats, error)
!>```
module hillstab_integrate_gsl
   use, intrinsic :: iso_c_binding, only: c_int, c_double, c_size_t, c_long, c_ptr, c_funptr, &
      c_null_funptr, c_loc, c_funloc, c_f_pointer, c_associated
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use hillstab_core_kinds, only: wp, int64, pi2, log_huge
   use hillstab_core_error, only: error_t, set_error, err_invalid_parameter, err_integration, err_accuracy
   use hillstab_integrate_refine, only: refinement_t, start_refinement, refine, refine_more, refine_roundoff, &
      roundoff_level, propagator_condition, trace_distance, first_step_factor, next_local_tolerance
   use hillstab_core_stats, only: work_stats_t, add_work
   use hillstab_hill_coefficient, only: hill_model_t, hill_coefficient, check_model, phase_bound
   use hillstab_hill_transfer, only: scaled_matrix_t, normalize_scaled, trace_t, trace_of, monodromy_from_half_period
   implicit none
   private
   public :: mathieu_a, mathieu_b, mathieu_transition_beta, mathieu_kind_a, mathieu_kind_b, &
      mathieu_max_order
   public :: monodromy_gsl, trace_gsl, monodromy_gsl_full_period, gsl_tolerance_factor
   public :: gsl_odeiv2_step_rk8pd
   ! the odeiv2 driver, for other systems integrated by rk8pd (hillstab_pendulum_gsl_lyapunov)
   public :: gsl_odeiv2_system, gsl_odeiv2_driver_alloc_scaled_new, gsl_odeiv2_driver_set_nmax, &
      gsl_odeiv2_driver_apply, gsl_odeiv2_driver_free, gsl_set_error_handler_off, gsl_rk8pd_scaled_driver, &
      gsl_odeiv2_driver_view, gsl_odeiv2_evolve_apply
   ! the status codes the drivers of hillstab_pendulum_gsl and hillstab_pendulum_gsl_lyapunov read and set
   public :: gsl_success, gsl_ebadfunc, gsl_emaxiter

   !> Curves of the even Mathieu functions ce_n: a_n(q), n ≥ 0.
   integer, parameter :: mathieu_kind_a = 1
   !> Curves of the odd Mathieu functions se_n: b_n(q), n ≥ 1.
   integer, parameter :: mathieu_kind_b = 2
   !> Largest order accepted. GSL's initial guess switches to n² at order 70 and
   !> its root search then converges to wrong values at large q (a known upstream
   !> bug); orders up to 60 keep a margin. (GSL's continued fractions also stop at
   !> 50 terms, so accuracy degrades for |q| of order 1e3 and beyond; hillstab's
   !> Mathieu charts need |q| = 2|ν|/π² of order 1.)
   integer, parameter :: mathieu_max_order = 60

   !> epsabs = epsrel = tolerance·gsl_tolerance_factor in GSL's control
   !> D_i = epsabs + epsrel |y_i| for the first pass of `monodromy_gsl` (the only one of
   !> `monodromy_gsl_full_period`). Measured: the error in S relative to max(1, |S|)
   !> is about 0.1–0.3·κ·epsilon, κ the condition of `half_period_monodromy`
   !> (κ ≲ 5 over most of the chart), so the second pass usually confirms the first.
   real(wp), parameter :: gsl_tolerance_factor = 0.5_wp
   !> GSL cannot meet a relative local error below a few ulps: the control's
   !> epsilon is never set below this.
   real(wp), parameter :: smallest_gsl_epsilon = 1.0e-15_wp
   !> Step limit per call of the driver (GSL_EMAXITER beyond).
   integer(c_long), parameter :: max_steps = 1000000_c_long
   !> Largest growth (natural log) of a solution allowed within one integration
   !> chunk before it is renormalized.
   real(wp), parameter :: chunk_log_growth = 200.0_wp

   !> Status GSL_SUCCESS.
   integer(c_int), parameter :: gsl_success = 0
   !> Status GSL_FAILURE, returned when the step control cannot meet its epsilon even at the smallest step
   !> (rounding noise in the step's error estimate exceeds it).
   integer(c_int), parameter :: gsl_failure = -1
   !> `monodromy_gsl`: at most this many values of S per point.
   integer, parameter :: max_ladder_runs = 8
   !> Status GSL_EBADFUNC: the right-hand side returned a non-finite value (set by the
   !> right-hand sides here, read by GSL as a failed evaluation).
   integer(c_int), parameter :: gsl_ebadfunc = 9
   !> Status GSL_EMAXITER: more steps than the driver's limit (here: more than `max_steps`
   !> steps in one stretch).
   integer(c_int), parameter :: gsl_emaxiter = 11

   !> gsl_sf_result: value and GSL's error estimate.
   type, bind(C) :: gsl_sf_result
      real(c_double) :: val
      real(c_double) :: err
   end type gsl_sf_result

   !> gsl_odeiv2_system.
   type, bind(C) :: gsl_odeiv2_system
      type(c_funptr) :: function      !! int f(double t, const double y[], double dydt[], void *params)
      type(c_funptr) :: jacobian      !! unused by explicit steppers: null
      integer(c_size_t) :: dimension  !! number of equations
      type(c_ptr) :: params  !! context handed to the right-hand side
   end type gsl_odeiv2_system

   !> The public layout of struct gsl_odeiv2_driver_struct (gsl_odeiv2.h): its stepper,
   !> control and evolve objects and its step, for loops that run GSL's evolve themselves.
   type, bind(C) :: gsl_odeiv2_driver_view
      type(c_ptr) :: sys      !! the gsl_odeiv2_system
      type(c_ptr) :: step     !! the stepper
      type(c_ptr) :: control  !! the step-size control
      type(c_ptr) :: evolve   !! the evolve object
      real(c_double) :: h     !! the next step proposed
      real(c_double) :: hmin  !! smallest step allowed
      real(c_double) :: hmax  !! largest step allowed
      integer(c_long) :: n, nmax   !! unsigned long in C
   end type gsl_odeiv2_driver_view

   !> The public layout of struct gsl_odeiv2_evolve_struct: `count` counts every
   !> attempted step (accepted or not), `failed_steps` the rejected ones.
   type, bind(C) :: gsl_odeiv2_evolve_view
      integer(c_size_t) :: dimension
      type(c_ptr) :: y0, yerr, dydt_in, dydt_out
      real(c_double) :: last_step
      integer(c_long) :: count, failed_steps
   end type gsl_odeiv2_evolve_view

   !> What the right-hand side needs: the model, and a counter of its calls.
   type :: rhs_context_t
      type(hill_model_t) :: model
      integer(int64) :: n_evaluations = 0
      !> GSL's t minus the time the solution has been advanced by (Σ h of the accepted
      !> steps): q is evaluated at t − lag (see `integrate_pair`)
      real(wp) :: lag = 0.0_wp
      real(wp) :: peak(2) = 0.0_wp  !! largest |u|, |u'| and |v|, |v'| seen by the right-hand side
      real(wp) :: terms(3) = 0.0_wp !! largest u², v'², |v u'| (the scaled condition, within a chunk)
   end type rhs_context_t

   !> `const gsl_odeiv2_step_type *gsl_odeiv2_step_rk8pd`, a global of libgsl.
   !> It must be public: gfortran gives private module variables hidden
   !> visibility, even with BIND(C), and the linker then allocates a hidden, null
   !> copy instead of referring to libgsl's (GSL segfaults on it).
   !> `protected`: nothing in hillstab may assign it.
   type(c_ptr), bind(C, name="gsl_odeiv2_step_rk8pd"), protected :: gsl_odeiv2_step_rk8pd

   interface
      !> Turn GSL's abort-on-error handler off (errors come back as status codes); returns the previous handler.
      function gsl_set_error_handler_off() bind(C, name="gsl_set_error_handler_off") result(previous)
         import :: c_funptr
         type(c_funptr) :: previous
      end function gsl_set_error_handler_off

      function gsl_sf_mathieu_a_e(order, qq, result) bind(C, name="gsl_sf_mathieu_a_e") result(status)
         import :: c_int, c_double, gsl_sf_result
         integer(c_int), value :: order
         real(c_double), value :: qq
         type(gsl_sf_result), intent(out) :: result
         integer(c_int) :: status
      end function gsl_sf_mathieu_a_e

      function gsl_sf_mathieu_b_e(order, qq, result) bind(C, name="gsl_sf_mathieu_b_e") result(status)
         import :: c_int, c_double, gsl_sf_result
         integer(c_int), value :: order
         real(c_double), value :: qq
         type(gsl_sf_result), intent(out) :: result
         integer(c_int) :: status
      end function gsl_sf_mathieu_b_e

      function gsl_odeiv2_driver_alloc_y_new(sys, step_type, hstart, epsabs, epsrel) &
         bind(C, name="gsl_odeiv2_driver_alloc_y_new") result(driver)
         import :: c_ptr, c_double, gsl_odeiv2_system
         type(gsl_odeiv2_system), intent(in) :: sys
         type(c_ptr), value :: step_type
         real(c_double), value :: hstart, epsabs, epsrel
         type(c_ptr) :: driver
      end function gsl_odeiv2_driver_alloc_y_new

      !> Driver with GSL's scaled control: the error of component i is kept below
      !> epsabs·scale_abs(i) + epsrel·(a_y |y_i| + a_dydt h |y_i'|) (the array is copied).
      function gsl_odeiv2_driver_alloc_scaled_new(sys, step_type, hstart, epsabs, epsrel, a_y, a_dydt, scale_abs) &
         bind(C, name="gsl_odeiv2_driver_alloc_scaled_new") result(driver)
         import :: c_ptr, c_double, gsl_odeiv2_system
         type(gsl_odeiv2_system), intent(in) :: sys  !! the system (function, dimension, params)
         type(c_ptr), value :: step_type  !! the stepper, e.g. gsl_odeiv2_step_rk8pd
         !> first step; absolute and relative tolerance; weights of y and h y'
         real(c_double), value :: hstart, epsabs, epsrel, a_y, a_dydt
         real(c_double), intent(in) :: scale_abs(*)  !! per-component scale of epsabs
         type(c_ptr) :: driver
      end function gsl_odeiv2_driver_alloc_scaled_new

      !> One step of the evolution (with GSL's internal retries on rejection).
      function gsl_odeiv2_evolve_apply(evolve, control, step, system, t, t1, h, y) &
         bind(C, name="gsl_odeiv2_evolve_apply") result(status)
         import :: c_ptr, c_double, c_int
         type(c_ptr), value :: evolve   !! the evolve object (its step counters)
         type(c_ptr), value :: control  !! the step-size control
         type(c_ptr), value :: step     !! the stepper
         type(c_ptr), value :: system   !! the gsl_odeiv2_system
         real(c_double), intent(inout) :: t  !! time, advanced by the accepted step
         real(c_double), value :: t1         !! do not step past t1
         real(c_double), intent(inout) :: h  !! proposed step in, next proposal out
         real(c_double), intent(inout) :: y(*)  !! state at t, advanced
         integer(c_int) :: status
      end function gsl_odeiv2_evolve_apply

      !> Limit the number of steps of one gsl_odeiv2_driver_apply call.
      function gsl_odeiv2_driver_set_nmax(driver, nmax) bind(C, name="gsl_odeiv2_driver_set_nmax") result(status)
         import :: c_ptr, c_long, c_int
         type(c_ptr), value :: driver  !! the driver
         integer(c_long), value :: nmax  !! largest number of steps per apply (0: no limit)
         integer(c_int) :: status
      end function gsl_odeiv2_driver_set_nmax

      !> Integrate from t to t1 (GSL_SUCCESS = 0, else a GSL error code).
      function gsl_odeiv2_driver_apply(driver, t, t1, y) bind(C, name="gsl_odeiv2_driver_apply") result(status)
         import :: c_ptr, c_double, c_int
         type(c_ptr), value :: driver  !! the driver
         real(c_double), intent(inout) :: t  !! time, advanced to t1
         real(c_double), value :: t1  !! end time
         real(c_double), intent(inout) :: y(*)  !! state at t, advanced
         integer(c_int) :: status
      end function gsl_odeiv2_driver_apply

      !> Free a driver.
      subroutine gsl_odeiv2_driver_free(driver) bind(C, name="gsl_odeiv2_driver_free")
         import :: c_ptr
         type(c_ptr), value :: driver  !! the driver
      end subroutine gsl_odeiv2_driver_free

      function gsl_odeiv2_driver_reset(driver) bind(C, name="gsl_odeiv2_driver_reset") result(status)
         import :: c_ptr, c_int
         type(c_ptr), value :: driver
         integer(c_int) :: status
      end function gsl_odeiv2_driver_reset
   end interface

contains

   !> Characteristic value a_n(q) of the even Mathieu functions (GSL).
   subroutine mathieu_a(n, q, value, error)
      integer, intent(in) :: n             !! order, 0 ≤ n ≤ mathieu_max_order
      real(wp), intent(in) :: q            !! Mathieu parameter (any sign)
      real(wp), intent(out) :: value       !! a_n(q)
      type(error_t), allocatable, intent(out) :: error  !! GSL failure; unallocated on success
      call mathieu_characteristic(mathieu_kind_a, n, q, value, error)
   end subroutine mathieu_a

   !> Characteristic value b_n(q) of the odd Mathieu functions (GSL).
   subroutine mathieu_b(n, q, value, error)
      integer, intent(in) :: n             !! order, 1 ≤ n ≤ mathieu_max_order
      real(wp), intent(in) :: q            !! Mathieu parameter (any sign)
      real(wp), intent(out) :: value       !! b_n(q)
      type(error_t), allocatable, intent(out) :: error  !! GSL failure; unallocated on success
      call mathieu_characteristic(mathieu_kind_b, n, q, value, error)
   end subroutine mathieu_b

   !> β on the n-th transition curve of q(τ) = β − ν cos πτ: (π²/4) a_n(2ν/π²)
   !> (kind a) or (π²/4) b_n(2ν/π²) (kind b). On it the trace is +2 for even n
   !> (2-periodic solution) and −2 for odd n (antiperiodic).
   subroutine mathieu_transition_beta(kind, n, nu, beta, error)
      integer, intent(in) :: kind          !! mathieu_kind_a or mathieu_kind_b
      integer, intent(in) :: n             !! order of the curve
      real(wp), intent(in) :: nu           !! ν, the amplitude of the cosine
      real(wp), intent(out) :: beta        !! β on the curve
      type(error_t), allocatable, intent(out) :: error  !! GSL failure or bad kind; unallocated on success
      real(wp) :: a
      call mathieu_characteristic(kind, n, 2.0_wp*nu/pi2, a, error)
      beta = 0.25_wp*pi2*a
   end subroutine mathieu_transition_beta

   subroutine mathieu_characteristic(kind, n, q, value, error)
      integer, intent(in) :: kind, n
      real(wp), intent(in) :: q
      real(wp), intent(out) :: value
      type(error_t), allocatable, intent(out) :: error
      type(gsl_sf_result) :: result
      type(c_funptr) :: previous
      integer(c_int) :: status
      integer :: lowest
      character(len=120) :: buf
      value = 0.0_wp
      if (kind /= mathieu_kind_a .and. kind /= mathieu_kind_b) then
         call set_error(error, err_invalid_parameter, "Mathieu kind must be mathieu_kind_a or mathieu_kind_b")
         return
      end if
      lowest = merge(0, 1, kind == mathieu_kind_a)
      if (n < lowest .or. n > mathieu_max_order) then
         write (buf, '(a,a,a,i0,a,i0,a,i0)') "Mathieu order of ", trim(kind_letter(kind)), "_n must be in ", &
            lowest, "..", mathieu_max_order, " (GSL is unreliable beyond), got n = ", n
         call set_error(error, err_invalid_parameter, trim(buf))
         return
      end if
      if (.not. ieee_is_finite(q)) then
         call set_error(error, err_invalid_parameter, "Mathieu parameter q must be finite")
         return
      end if
      previous = gsl_set_error_handler_off()
      result = gsl_sf_result(0.0_c_double, 0.0_c_double)
      if (kind == mathieu_kind_a) then
         status = gsl_sf_mathieu_a_e(int(n, c_int), real(q, c_double), result)
      else
         status = gsl_sf_mathieu_b_e(int(n, c_int), real(q, c_double), result)
      end if
      if (status /= gsl_success .or. .not. (ieee_is_finite(result%val) .and. ieee_is_finite(result%err))) then
         write (buf, '(a,a,a,i0,a,es12.5,a,i0)') "GSL failed to compute Mathieu ", trim(kind_letter(kind)), "_", &
            n, "(q) at q = ", q, ", status ", status
         call set_error(error, err_integration, trim(buf))
         return
      end if
      value = result%val
   end subroutine mathieu_characteristic

   pure function kind_letter(kind) result(letter)
      integer, intent(in) :: kind
      character(len=1) :: letter
      letter = merge("a", "b", kind == mathieu_kind_a)
   end function kind_letter

   !> Right-hand side of the χ equation for the 4-vector y = (u, u', v, v') of two
   !> solutions, in GSL's calling convention. Non-finite values stop the driver.
   function hill_rhs(t, y, dydt, params) bind(C) result(status)
      real(c_double), value :: t
      real(c_double), intent(in) :: y(4)
      real(c_double), intent(out) :: dydt(4)
      type(c_ptr), value :: params
      integer(c_int) :: status
      type(rhs_context_t), pointer :: context
      real(wp) :: q
      call c_f_pointer(params, context)
      context%n_evaluations = context%n_evaluations + 1
      context%peak(1) = max(context%peak(1), abs(y(1)), abs(y(2)))
      context%peak(2) = max(context%peak(2), abs(y(3)), abs(y(4)))
      context%terms = max(context%terms, [y(1)*y(1), y(4)*y(4), abs(y(3)*y(2))])
      q = hill_coefficient(context%model, t - context%lag)
      dydt(1) = y(2)
      dydt(2) = -q*y(1)
      dydt(3) = y(4)
      dydt(4) = -q*y(3)
      status = gsl_success
      if (.not. all(ieee_is_finite(dydt))) status = gsl_ebadfunc
   end function hill_rhs

   !> Integrate the two solutions y = (u, u', v, v') of the χ equation from τ = 0,
   !> y(0) = (1, 0, 0, 1), to `t_end` with GSL's control epsilon `eps`,
   !> renormalizing each solution between chunks short enough that it cannot
   !> overflow. On return the solutions are exp(log_scale(j)) times the columns of y.
   subroutine integrate_pair(model, t_end, eps, y, log_scale, log_peak, stats, error, log_condition_peak)
      type(hill_model_t), intent(in) :: model
      real(wp), intent(in) :: t_end          !! end of the integration, > 0
      real(wp), intent(in) :: eps            !! epsabs = epsrel of GSL's y-control
      real(wp), intent(out) :: y(2, 2)       !! (scaled) u, u' and v, v' at t_end
      real(wp), intent(out) :: log_scale(2)  !! ln of the scale factor of each column
      real(wp), intent(out) :: log_peak(2)   !! ln of the largest |component| of each solution on the way
      type(work_stats_t), intent(out) :: stats
      !> err_accuracy when GSL's control cannot meet `eps` (GSL_FAILURE), err_integration otherwise
      type(error_t), allocatable, intent(out) :: error
      !> ln of the largest scaled condition u² + v'² + 2|v u'| along the way
      real(wp), intent(out), optional :: log_condition_peak
      type(rhs_context_t), target :: context
      type(gsl_odeiv2_system), target :: system
      type(gsl_odeiv2_driver_view), pointer :: driver_view
      type(gsl_odeiv2_evolve_view), pointer :: evolve_view
      type(c_ptr) :: driver
      type(c_funptr) :: previous
      real(c_double) :: state(4), t
      real(wp) :: growth_rate, magnitude, condition_peak
      integer(c_int) :: status
      integer :: n_chunks, chunk, j, e, exponents(2)
      integer(int64) :: n_accepted, n_rejected
      character(len=200) :: buf

      y = reshape([1.0_wp, 0.0_wp, 0.0_wp, 1.0_wp], [2, 2])
      log_scale = 0.0_wp
      exponents = 0
      n_accepted = 0
      n_rejected = 0
      log_peak = 0.0_wp
      stats = work_stats_t()
      previous = gsl_set_error_handler_off()

      ! With c² = max(1, max|q|) the energy c²w² + w'² of any solution grows at most
      ! like exp(2c τ), and q is monotone in cos πτ, so its extremes on [0, 1] are at
      ! τ = 0 and 1: chunks of length ≤ chunk_log_growth/c keep u, v finite.
      growth_rate = sqrt(max(1.0_wp, abs(hill_coefficient(model, 0.0_wp)), abs(hill_coefficient(model, 1.0_wp))))
      n_chunks = max(1, ceiling(growth_rate*t_end/chunk_log_growth))

      context%model = model
      context%n_evaluations = 0
      context%peak = 0.0_wp
      system = gsl_odeiv2_system(c_funloc(hill_rhs), c_null_funptr, 4_c_size_t, c_loc(context))
      driver = gsl_odeiv2_driver_alloc_y_new(system, gsl_odeiv2_step_rk8pd, &
                                             real(0.1_wp/growth_rate, c_double), real(eps, c_double), real(eps, c_double))
      if (.not. c_associated(driver)) then
         call set_error(error, err_integration, "GSL could not allocate the odeiv2 driver")
         return
      end if
      status = gsl_odeiv2_driver_set_nmax(driver, max_steps)

      call c_f_pointer(driver, driver_view)
      call c_f_pointer(driver_view%evolve, evolve_view)
      state = [1.0_c_double, 0.0_c_double, 0.0_c_double, 1.0_c_double]
      t = 0.0_c_double
      context%lag = 0.0_wp
      condition_peak = 0.0_wp
      do chunk = 1, n_chunks
         context%terms = 0.0_wp
         call advance_to(t_end*chunk/n_chunks)
         if (status == gsl_success .and. .not. all(ieee_is_finite(state))) status = gsl_ebadfunc
         if (status /= gsl_success) exit
         condition_peak = max(condition_peak, log(max(context%terms(1), tiny(1.0_wp))) + 2.0_wp*log_scale(1), &
                              log(max(context%terms(2), tiny(1.0_wp))) + 2.0_wp*log_scale(2), &
                              log(max(context%terms(3), tiny(1.0_wp))) + log_scale(1) + log_scale(2))
         do j = 1, 2
            if (context%peak(j) > 0.0_wp) log_peak(j) = max(log_peak(j), log(context%peak(j)) + log_scale(j))
            context%peak(j) = 0.0_wp
            magnitude = max(abs(state(2*j - 1)), abs(state(2*j)))
            if (n_chunks > 1 .and. magnitude > 0.0_wp) then
               ! by a power of two (exact), the exponents counted as integers: a logarithm
               ! added per chunk rounds each time, and at β = −1e6 (ln|S| ≈ 5000, ~25
               ! chunks) those roundings put S off by 5e-12
               e = exponent(magnitude)
               state(2*j - 1:2*j) = scale(state(2*j - 1:2*j), -e)
               exponents(j) = exponents(j) + e
               log_scale(j) = exponents(j)*log(2.0_wp)
            end if
         end do
         ! without a reset of the driver's evolution and stepper objects the next
         ! driver_apply after a renormalization fails at once with GSL_FAILURE (the step
         ! size collapses to 1e-17: the objects' state from before no longer matches y).
         ! This was rk8pd's status -1 at |beta| >= 1e4 and beta << 0 near alpha -> pi^2.
         if (n_chunks > 1) status = gsl_odeiv2_driver_reset(driver)
         if (status /= gsl_success) exit
      end do
      if (present(log_condition_peak)) log_condition_peak = condition_peak

      ! (counted here: the evolve object's counters restart at each driver reset)
      stats%n_steps = n_accepted
      stats%n_rejected = n_rejected
      stats%n_evaluations = context%n_evaluations
      call gsl_odeiv2_driver_free(driver)

      if (status /= gsl_success) then
         write (buf, '(a,i0,a,es12.5,a,es12.5,a,es12.5,a,es9.2,a)') "GSL rk8pd failed with status ", status, &
            " at tau = ", t, " (alpha = ", model%alpha, ", beta = ", model%beta, ", eps = ", eps, ")"
         if (status == gsl_failure) then
            call set_error(error, err_accuracy, trim(buf))
         else
            call set_error(error, err_integration, trim(buf))
         end if
         return
      end if
      y = reshape(real(state, wp), [2, 2])

   contains

      !> gsl_odeiv2_driver_apply's loop, with one change: each step h is made exact
      !> (t + h representable, h = (t + h) − t) before the step, and where GSL's retries
      !> after a rejection still leave t + h rounded, the difference is kept in
      !> context%lag and q is evaluated at t − lag. GSL advances the solution by h but
      !> t by fl(t + h); each rounding is a jump of the coefficient by up to ulp(t)/2,
      !> a phase error of √|q|·ulp(t)/2, and over the ~1e4 steps at |β| ~ 1e5 these
      !> added up to errors of 1e-12 to 3e-12 in S, above a tolerance of 1e-12.
      subroutine advance_to(t_goal)
         real(wp), intent(in) :: t_goal  !! the time the solution is to reach
         real(c_double) :: t_start, target, h_exact
         integer(c_long) :: n, failed_before
         ! GSL's t runs ahead of the solution's time by `lag`
         target = real(t_goal + context%lag, c_double)
         n = 0
         status = gsl_success
         do while (t < target)
            if (n >= max_steps) then
               status = gsl_emaxiter
               return
            end if
            if (t + driver_view%h < target) then
               ! (a step below half an ulp of t would round to 0: left to GSL, which fails on it)
               h_exact = (t + driver_view%h) - t
               if (h_exact > 0.0_c_double) driver_view%h = h_exact
            end if
            t_start = t
            failed_before = evolve_view%failed_steps
            status = gsl_odeiv2_evolve_apply(driver_view%evolve, driver_view%control, driver_view%step, &
                                             driver_view%sys, t, target, driver_view%h, state)
            n_rejected = n_rejected + (evolve_view%failed_steps - failed_before)
            if (status /= gsl_success) return
            context%lag = context%lag + ((t - t_start) - evolve_view%last_step)
            n = n + 1
            n_accepted = n_accepted + 1
         end do
      end subroutine advance_to
   end subroutine integrate_pair

   !> Monodromy from the half period with GSL epsilon `eps`; `log_condition` is
   !> ln κ, κ = max|u-solution|·max|v-solution| over [0, 1] / max(1, |S|); `log_peak` the
   !> ln of the largest scaled condition of the propagator (`propagator_condition`).
   subroutine half_period_monodromy(model, eps, m, log_condition, stats, error, log_peak)
      type(hill_model_t), intent(in) :: model
      real(wp), intent(in) :: eps
      type(scaled_matrix_t), intent(out) :: m
      real(wp), intent(out) :: log_condition
      type(work_stats_t), intent(out) :: stats
      type(error_t), allocatable, intent(out) :: error
      real(wp), intent(out), optional :: log_peak
      real(wp) :: y(2, 2), log_scale(2), log_peaks(2), condition_peak
      type(trace_t) :: tr
      log_condition = 0.0_wp
      call integrate_pair(model, 1.0_wp, eps, y, log_scale, log_peaks, stats, error, condition_peak)
      if (present(log_peak)) log_peak = condition_peak
      if (allocated(error)) return
      m = monodromy_from_half_period(y, log_scale(1), log_scale(2))
      tr = trace_of(m)
      log_condition = sum(log_peaks) - max(0.0_wp, tr%log_abs)
   end subroutine half_period_monodromy

   !> One-period monodromy of the χ equation from the half period: with u, v the
   !> even and odd solutions at τ = 1 (u v' − u' v = 1),
   !> M = [[u v' + u' v, 2 v v'], [2 u u', u v' + u' v]], S = 2 (u v' + u' v).
   !>
   !> `tolerance` is the target error on S relative to max(1, |S|), with a global error
   !> control (hillstab_integrate_refine): the half period is integrated with GSL's control epsilon
   !> tolerance·gsl_tolerance_factor, then smaller (first by the condition of the
   !> propagator, then tenfold) until two successive traces agree to the tolerance; the
   !> finer monodromy is returned and their difference is the error estimate. When the
   !> epsilon reaches its floor, GSL's control cannot meet it (GSL_FAILURE: rounding
   !> noise), or the traces differ by rounding noise only, the finest monodromy comes back
   !> with err_accuracy (round-off limited) and its estimate. `stats` counts every pass.
   subroutine monodromy_gsl(model, tolerance, m, stats, error, error_estimate)
      type(hill_model_t), intent(in) :: model  !! the Hill equation: model kind, alpha, beta, damping epsilon
      real(wp), intent(in) :: tolerance         !! target error on S, scaled by max(1, |S|)
      type(scaled_matrix_t), intent(out) :: m   !! monodromy over [0, 2]
      type(work_stats_t), intent(out) :: stats  !! rk8pd steps, rejections, Q evaluations
      !> GSL failure; err_accuracy when round-off limited (`m` then holds the best value)
      type(error_t), allocatable, intent(out) :: error
      real(wp), intent(out), optional :: error_estimate  !! estimated |ΔS|/max(1, |S|)
      type(work_stats_t) :: part
      type(scaled_matrix_t) :: trial, best
      type(refinement_t) :: ladder
      type(trace_t) :: tr
      type(error_t), allocatable :: run_error
      real(wp) :: log_condition, eps, log_peak, estimate, noise, phase
      integer :: run, loosening
      character(len=200) :: buffer
      stats = work_stats_t()
      if (present(error_estimate)) error_estimate = -1.0_wp
      call check_model(model, error)
      if (allocated(error)) return
      call check_tolerance(tolerance, error)
      if (allocated(error)) return
      call start_refinement(ladder, tolerance)
      eps = max(gsl_epsilon(tolerance, 0.0_wp), 10.0_wp*smallest_gsl_epsilon)
      ! the first pass: loosen the epsilon while GSL's control cannot meet it at all
      do loosening = 1, 6
         call half_period_monodromy(model, eps, best, log_condition, part, run_error, log_peak)
         call add_work(stats, part)
         if (.not. allocated(run_error)) exit
         if (run_error%code /= err_accuracy .or. eps > 1.0e-6_wp) then
            call move_alloc(run_error, error)
            return
         end if
         eps = 100.0_wp*eps
      end do
      if (allocated(run_error)) then
         call move_alloc(run_error, error)
         return
      end if
      tr = trace_of(best)
      phase = phase_bound(model)
      call refine(ladder, tr, .false., roundoff_level(log_peak, tr%log_abs, int(part%n_steps), phase))
      estimate = -1.0_wp
      do run = 2, max_ladder_runs
         ! the first step down also divides by the condition κ of the first pass: where the
         ! solutions grow far beyond S inside the period (α → π², β → 0) the first pass's
         ! error is κ times its epsilon and two loose passes can agree on a wrong value
         eps = next_local_tolerance(eps, merge(first_step_factor(log_peak, tr%log_abs), 10.0_wp, run == 2), &
                                    smallest_gsl_epsilon)
         call half_period_monodromy(model, eps, trial, log_condition, part, run_error, log_peak)
         call add_work(stats, part)
         if (allocated(run_error)) then
            if (run_error%code /= err_accuracy) then
               call move_alloc(run_error, error)
               return
            end if
            ! GSL cannot reach this epsilon: the previous pass is the best available
            if (ladder%n_values >= 2) then
               estimate = ladder%difference
            else
               ! only one value so far: compare it with a pass ten times looser
               call half_period_monodromy(model, 100.0_wp*eps, trial, log_condition, part, run_error, log_peak)
               call add_work(stats, part)
               if (allocated(run_error)) then
                  call move_alloc(run_error, error)
                  return
               end if
               estimate = trace_distance(trace_of(best), trace_of(trial))
            end if
            tr = trace_of(best)
            estimate = max(estimate, roundoff_level(log_peak, tr%log_abs, int(part%n_steps), phase))
            exit
         end if
         tr = trace_of(trial)
         noise = roundoff_level(log_peak, tr%log_abs, int(part%n_steps), phase)
         call refine(ladder, tr, eps <= 1.001_wp*smallest_gsl_epsilon .or. run == max_ladder_runs, noise, &
                     near_floor=eps <= 1.0e3_wp*smallest_gsl_epsilon)
         best = trial
         if (ladder%verdict /= refine_more) then
            estimate = tr%error_estimate
            exit
         end if
      end do
      m = best
      if (present(error_estimate)) error_estimate = estimate
      if (estimate > tolerance .or. ladder%verdict == refine_roundoff) then
         write (buffer, '(a,es9.2,a,es9.2,a)') "gsl: the tolerance ", tolerance, &
            " is below what rk8pd reaches here (estimated error ", estimate, "); best value returned"
         call set_error(error, err_accuracy, trim(buffer))
      end if
   end subroutine monodromy_gsl

   !> Trace S of `monodromy_gsl`, with its error estimate; on err_accuracy (round-off
   !> limited) the best value is still returned.
   subroutine trace_gsl(model, tolerance, tr, stats, error)
      type(hill_model_t), intent(in) :: model  !! the Hill equation: model kind, alpha, beta, damping epsilon
      real(wp), intent(in) :: tolerance         !! target error on S, scaled by max(1, |S|)
      type(trace_t), intent(out) :: tr          !! S and its error estimate
      type(work_stats_t), intent(out) :: stats  !! rk8pd steps, rejections, Q evaluations
      !> GSL failure; err_accuracy when round-off limited (`tr` then holds the best value)
      type(error_t), allocatable, intent(out) :: error
      type(scaled_matrix_t) :: m
      real(wp) :: estimate
      call monodromy_gsl(model, tolerance, m, stats, error, estimate)
      if (allocated(error)) then
         if (error%code /= err_accuracy) return
      end if
      tr = trace_of(m)
      tr%error_estimate = estimate
   end subroutine trace_gsl

   !> Monodromy by direct rk8pd integration over the whole period [0, 2], without
   !> the symmetry (GSL epsilon tolerance·gsl_tolerance_factor, no rerun): a check
   !> of `monodromy_gsl`, at twice the work.
   subroutine monodromy_gsl_full_period(model, tolerance, m, stats, error)
      type(hill_model_t), intent(in) :: model  !! the Hill equation: model kind, alpha, beta, damping epsilon
      real(wp), intent(in) :: tolerance         !! sets GSL's control epsilon
      type(scaled_matrix_t), intent(out) :: m   !! monodromy over [0, 2]
      type(work_stats_t), intent(out) :: stats  !! rk8pd steps, rejections, Q evaluations
      type(error_t), allocatable, intent(out) :: error  !! GSL failure; unallocated on success
      real(wp) :: y(2, 2), log_scale(2), log_peak(2), top
      stats = work_stats_t()
      call check_model(model, error)
      if (allocated(error)) return
      call check_tolerance(tolerance, error)
      if (allocated(error)) return
      call integrate_pair(model, 2.0_wp, gsl_epsilon(tolerance, 0.0_wp), y, log_scale, log_peak, stats, error)
      if (allocated(error)) return
      top = maxval(log_scale)
      m%m(:, 1) = y(:, 1)*exp(max(log_scale(1) - top, -log_huge))
      m%m(:, 2) = y(:, 2)*exp(max(log_scale(2) - top, -log_huge))
      m%log_scale = top
      call normalize_scaled(m)
   end subroutine monodromy_gsl_full_period

   !> GSL control epsilon for a target tolerance and a condition ln κ, floored.
   pure real(wp) function gsl_epsilon(tolerance, log_condition) result(eps)
      real(wp), intent(in) :: tolerance, log_condition
      eps = max(smallest_gsl_epsilon, tolerance*gsl_tolerance_factor*exp(-min(log_condition, 100.0_wp)))
   end function gsl_epsilon

   !> A GSL odeiv2 driver with the rk8pd stepper and GSL's scaled error control set up
   !> like hillstab's: the error of component i is kept below rtol·(scale_abs(i) + |y_i|)
   !> (absolute part rtol·scale_abs(i), relative part rtol·|y_i|), with GSL's error
   !> handler switched off so that failures come back as status codes. The driver keeps
   !> the address of `system`, which must outlive it. A null pointer when GSL cannot
   !> allocate it; free it with `gsl_odeiv2_driver_free`.
   function gsl_rk8pd_scaled_driver(system, h_start, rtol, scale_abs, step_limit) result(driver)
      type(gsl_odeiv2_system), intent(in), target :: system  !! the system (kept by the driver)
      real(wp), intent(in) :: h_start              !! first trial step
      real(wp), intent(in) :: rtol                 !! relative tolerance (> 0)
      real(c_double), intent(in) :: scale_abs(:)   !! absolute tolerances over rtol, per component
      integer(c_long), intent(in) :: step_limit    !! most steps per gsl_odeiv2_driver_apply call
      type(c_ptr) :: driver                        !! the driver, or a null pointer
      type(c_funptr) :: previous
      integer(c_int) :: status
      previous = gsl_set_error_handler_off()
      driver = gsl_odeiv2_driver_alloc_scaled_new(system, gsl_odeiv2_step_rk8pd, real(h_start, c_double), &
         real(rtol, c_double), real(rtol, c_double), 1.0_c_double, 0.0_c_double, scale_abs)
      if (c_associated(driver)) status = gsl_odeiv2_driver_set_nmax(driver, step_limit)
   end function gsl_rk8pd_scaled_driver

   subroutine check_tolerance(tolerance, error)
      real(wp), intent(in) :: tolerance
      type(error_t), allocatable, intent(out) :: error
      character(len=80) :: buf
      ! ieee_is_finite first: an ordered comparison with NaN raises 'invalid'
      if (.not. ieee_is_finite(tolerance)) then
         call set_error(error, err_invalid_parameter, "GSL monodromy tolerance must be finite")
      else if (.not. (tolerance > 0.0_wp .and. tolerance < 1.0_wp)) then
         write (buf, '(a,es12.5)') "GSL monodromy tolerance must be in (0, 1), got ", tolerance
         call set_error(error, err_invalid_parameter, trim(buf))
      end if
   end subroutine check_tolerance
end module hillstab_integrate_gsl

!> The one-period monodromy of the χ equation (47) by GSL's odeiv2 stepper with the
!> Prince–Dormand 8(7) pair `rk8pd` (method `gsl`), using the even symmetry of Q: the
!> even and odd solutions u, v are integrated on [0, 1] only (Floquet theory: S = 2(u v' + u' v)). The bindings
!> are those of `hillstab_ffi_gsl`.
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
!> tolerance and their difference has contracted to at most half the one before
!> (hillstab_integrate_refine `refine`, `contraction`: rk8pd's global error need not
!> follow its epsilon, so two agreeing values alone do not bound it), and reports round-off limited (err_accuracy) where eps
!> reaches its floor 1e-15 or GSL's control cannot meet it (GSL_FAILURE). The driver's
!> loop is run here (`integrate_pair`) so that every step is exact in time (GSL advances
!> t by a rounded t + h; over the 1e4 steps at |β| ~ 1e5 that cost up to 3e-12 in S),
!> and the solutions are rescaled by powers of two. Measured against the 50-digit
!> references of data/reference/ (guide page *Methods and accuracy*).
!>
!>```fortran
!> type(trace_t) :: tr
!> type(work_stats_t) :: stats
!> type(error_t), allocatable :: error
!> call trace_gsl(elastic_model_t(), hill_point_t(9.8_wp, 2.47_wp, 0.0_wp), 1.0e-12_wp, tr, stats, error)
!>```
module hillstab_integrate_monodromy_gsl
   use, intrinsic :: iso_c_binding, only: c_int, c_double, c_size_t, c_long, c_ptr, c_funptr, &
      c_null_funptr, c_loc, c_funloc, c_f_pointer, c_associated
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use hillstab_core_kinds, only: wp, int64, log_huge
   use hillstab_core_error, only: error_t, set_error, err_invalid_parameter, err_integration, err_accuracy
   use hillstab_integrate_refine, only: refinement_t, start_refinement, refine, refine_more, refine_roundoff, &
      roundoff_level, propagator_condition, trace_distance, first_step_factor, next_local_tolerance, sensitivity_t, &
      accumulate_sensitivity, coefficient_level, rk_rounding
   use hillstab_core_stats, only: work_stats_t, add_work
   use hillstab_hill_model, only: hill_model_t, hill_point_t, hill_window_t, hill_coefficient_before, check_point, &
      model_split, model_coefficient_range, window_piece_end
   use hillstab_hill_coefficient, only: phase_bound
   use hillstab_hill_transfer, only: scaled_matrix_t, normalize_scaled, trace_t, trace_of, monodromy_from_window
   use hillstab_ffi_gsl, only: gsl_odeiv2_system, gsl_odeiv2_driver_view, gsl_odeiv2_evolve_view, gsl_odeiv2_step_rk8pd, &
      gsl_set_error_handler_off, gsl_odeiv2_driver_alloc_y_new, gsl_odeiv2_evolve_apply, gsl_odeiv2_driver_set_nmax, &
      gsl_odeiv2_driver_free, gsl_odeiv2_driver_reset, gsl_success, gsl_failure, gsl_ebadfunc, gsl_emaxiter
   implicit none
   private
   public :: monodromy_gsl, trace_gsl, monodromy_gsl_full_period, gsl_tolerance_factor

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

   !> `monodromy_gsl`: at most this many values of S per point.
   integer, parameter :: max_ladder_runs = 8

   !> What the right-hand side needs: the model, and a counter of its calls.
   type :: rhs_context_t
      class(hill_model_t), allocatable :: model  !! the model (a copy: GSL reaches it through a C pointer)
      type(hill_point_t) :: point                !! α, β, ε
      !> the jump of q that ends the current piece (huge: none): q from the left there
      real(wp) :: jump = huge(1.0_wp)
      integer(int64) :: n_evaluations = 0
      !> GSL's t minus the time the solution has been advanced by (Σ h of the accepted
      !> steps): q is evaluated at t − lag (see `integrate_pair`)
      real(wp) :: lag = 0.0_wp
      real(wp) :: peak(2) = 0.0_wp  !! largest |u|, |u'| and |v|, |v'| seen by the right-hand side
      real(wp) :: terms(3) = 0.0_wp !! largest u², v'², |v u'| (the scaled condition, within a chunk)
   end type rhs_context_t

contains

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
      q = hill_coefficient_before(context%model, context%point, t - context%lag, context%jump)
      dydt(1) = y(2)
      dydt(2) = -q*y(1)
      dydt(3) = y(4)
      dydt(4) = -q*y(3)
      status = gsl_success
      if (.not. all(ieee_is_finite(dydt))) status = gsl_ebadfunc
   end function hill_rhs

   !> Integrate the two solutions y = (u, u', v, v') of the χ equation over the window
   !> (from its start, y = (1, 0, 0, 1), over `length`; the driver restarts at each jump of q
   !> inside it) with GSL's control epsilon `eps`, renormalizing each solution between
   !> chunks short enough that it cannot overflow. On return the solutions are
   !> exp(log_scale(j)) times the columns of y.
   subroutine integrate_pair(model, point, window, eps, y, log_scale, log_peak, stats, error, log_condition_peak, &
                             sensitivity)
      class(hill_model_t), intent(in) :: model  !! the model
      type(hill_point_t), intent(in) :: point   !! α, β, ε
      type(hill_window_t), intent(in) :: window  !! where to integrate (its length > 0)
      real(wp), intent(in) :: eps            !! epsabs = epsrel of GSL's y-control
      real(wp), intent(out) :: y(2, 2)       !! (scaled) u, u' and v, v' at t_end
      real(wp), intent(out) :: log_scale(2)  !! ln of the scale factor of each column
      real(wp), intent(out) :: log_peak(2)   !! ln of the largest |component| of each solution on the way
      type(work_stats_t), intent(out) :: stats
      !> err_accuracy when GSL's control cannot meet `eps` (GSL_FAILURE), err_integration otherwise
      type(error_t), allocatable, intent(out) :: error
      !> ln of the largest scaled condition u² + v'² + 2|v u'| along the way
      real(wp), intent(out), optional :: log_condition_peak
      !> the integrals for the rounding of q (hillstab_integrate_refine `coefficient_level`;
      !> one more evaluation of q per step)
      type(sensitivity_t), intent(out), optional :: sensitivity
      type(rhs_context_t), target :: context
      type(sensitivity_t) :: integrals
      real(wp) :: c0, c1, top
      type(gsl_odeiv2_system), target :: system
      type(gsl_odeiv2_driver_view), pointer :: driver_view
      type(gsl_odeiv2_evolve_view), pointer :: evolve_view
      type(c_ptr) :: driver
      type(c_funptr) :: previous
      real(c_double) :: state(4), t
      real(wp) :: growth_rate, magnitude, condition_peak, q_min, q_max, piece_start, piece_end, jump
      integer(c_int) :: status
      integer :: n_chunks, chunk, j, e, exponents(2), piece
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
      call model_split(model, point%alpha, point%beta, point%epsilon, c0, c1)

      ! With c² = max(1, max|q|) the energy c²w² + w'² of any solution grows at most
      ! like exp(2c τ), and |q| is bounded by the model's range of q: chunks of length
      ! ≤ chunk_log_growth/c keep u, v finite.
      call model_coefficient_range(model, point, q_min, q_max)
      growth_rate = sqrt(max(1.0_wp, abs(q_min), abs(q_max)))

      allocate (context%model, source=model)
      context%point = point
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
      t = real(window%start, c_double)
      context%lag = 0.0_wp
      condition_peak = 0.0_wp
      piece_start = window%start
      do piece = 1, window%n_breaks + 1
      call window_piece_end(window, piece, piece_end, jump)
      context%jump = jump
      if (piece > 1) then
         ! across a jump of q: GSL's t made the piece's start exactly (no lag), the driver's
         ! step and its FSAL state reset
         context%lag = real(t, wp) - piece_start
         status = gsl_odeiv2_driver_reset(driver)
      end if
      n_chunks = max(1, ceiling(growth_rate*(piece_end - piece_start)/chunk_log_growth))
      do chunk = 1, n_chunks
         context%terms = 0.0_wp
         call advance_to(piece_start + (piece_end - piece_start)*chunk/n_chunks)
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
      if (status /= gsl_success) exit
      piece_start = piece_end
      end do
      if (present(log_condition_peak)) log_condition_peak = condition_peak
      if (present(sensitivity)) sensitivity = integrals

      ! (counted here: the evolve object's counters restart at each driver reset)
      stats%n_steps = n_accepted
      stats%n_rejected = n_rejected
      stats%n_evaluations = context%n_evaluations
      call gsl_odeiv2_driver_free(driver)

      if (status /= gsl_success) then
         write (buf, '(a,i0,a,es12.5,a,es12.5,a,es12.5,a,es9.2,a)') "GSL rk8pd failed with status ", status, &
            " at tau = ", t, " (alpha = ", point%alpha, ", beta = ", point%beta, ", eps = ", eps, ")"
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
         real(wp) :: lag_before
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
            lag_before = context%lag
            failed_before = evolve_view%failed_steps
            status = gsl_odeiv2_evolve_apply(driver_view%evolve, driver_view%control, driver_view%step, &
                                             driver_view%sys, t, target, driver_view%h, state)
            n_rejected = n_rejected + (evolve_view%failed_steps - failed_before)
            if (status /= gsl_success) return
            context%lag = context%lag + ((t - t_start) - evolve_view%last_step)
            if (present(sensitivity)) then
               ! the sensitivity integrals, u and v brought to their common scale, q − c₀ at mid-step
               top = max(log_scale(1), log_scale(2))
               call accumulate_sensitivity(integrals, state(1)*exp(log_scale(1) - top), state(3)*exp(log_scale(2) - top), &
                                           top, real(evolve_view%last_step, wp), &
                                           hill_coefficient_before(model, point, &
                                              t_start - lag_before + 0.5_wp*evolve_view%last_step, context%jump) - c0)
               context%n_evaluations = context%n_evaluations + 1
            end if
            n = n + 1
            n_accepted = n_accepted + 1
         end do
      end subroutine advance_to
   end subroutine integrate_pair

   !> Monodromy from the model's window (half a period of an even q, or the period) with GSL
   !> epsilon `eps`; `log_condition` is ln κ, κ = max|u-solution|·max|v-solution| over the
   !> window / max(1, |S|); `log_peak` the
   !> ln of the largest scaled condition of the propagator (`propagator_condition`).
   subroutine half_period_monodromy(model, point, eps, m, log_condition, stats, error, log_peak, coefficient_noise)
      class(hill_model_t), intent(in) :: model  !! the model
      type(hill_point_t), intent(in) :: point   !! α, β, ε
      real(wp), intent(in) :: eps
      type(scaled_matrix_t), intent(out) :: m
      real(wp), intent(out) :: log_condition
      type(work_stats_t), intent(out) :: stats
      type(error_t), allocatable, intent(out) :: error
      real(wp), intent(out), optional :: log_peak
      !> the round-off of S from the rounding of q (`coefficient_level`)
      real(wp), intent(out), optional :: coefficient_noise
      real(wp) :: y(2, 2), log_scale(2), log_peaks(2), condition_peak, c0, c1
      type(trace_t) :: tr
      type(sensitivity_t) :: sensitivity
      type(hill_window_t) :: window
      log_condition = 0.0_wp
      if (present(coefficient_noise)) coefficient_noise = 0.0_wp
      window = model%window(point%alpha)
      call integrate_pair(model, point, window, eps, y, log_scale, log_peaks, stats, error, condition_peak, sensitivity)
      if (present(log_peak)) log_peak = condition_peak
      if (allocated(error)) return
      m = monodromy_from_window(y, log_scale(1), log_scale(2), window%half)
      tr = trace_of(m)
      log_condition = sum(log_peaks) - max(0.0_wp, tr%log_abs)
      if (present(coefficient_noise)) then
         call model_split(model, point%alpha, point%beta, point%epsilon, c0, c1)
         coefficient_noise = coefficient_level(sensitivity, c0, m, tr%log_abs, window%half)
      end if
   end subroutine half_period_monodromy

   !> One-period monodromy of the χ equation from the half period: with u, v the
   !> even and odd solutions at τ = 1 (u v' − u' v = 1),
   !> M = [[u v' + u' v, 2 v v'], [2 u u', u v' + u' v]], S = 2 (u v' + u' v).
   !>
   !> `tolerance` is the target error on S relative to max(1, |S|), with a global error
   !> control (hillstab_integrate_refine): the half period is integrated with GSL's control epsilon
   !> tolerance·gsl_tolerance_factor, then smaller (first by the condition of the
   !> propagator, then tenfold) until two successive traces agree to the tolerance with a
   !> difference at most half the one before (or at the round-off level); the finer monodromy is returned and their difference is the error estimate. When the
   !> epsilon reaches its floor, GSL's control cannot meet it (GSL_FAILURE: rounding
   !> noise), or the traces differ by rounding noise only, the finest monodromy comes back
   !> with err_accuracy (round-off limited) and its estimate. `stats` counts every pass.
   subroutine monodromy_gsl(model, point, tolerance, m, stats, error, error_estimate)
      class(hill_model_t), intent(in) :: model  !! the model
      type(hill_point_t), intent(in) :: point   !! α, β, ε
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
      real(wp) :: log_condition, eps, log_peak, estimate, noise, phase, coefficient_noise, last_coefficient_noise
      logical :: half  ! the model's window is half a period (`roundoff_level`)
      type(hill_window_t) :: window
      integer :: run, loosening
      character(len=200) :: buffer
      stats = work_stats_t()
      if (present(error_estimate)) error_estimate = -1.0_wp
      call check_point(model, point, error)
      if (allocated(error)) return
      call check_tolerance(tolerance, error)
      if (allocated(error)) return
      call start_refinement(ladder, tolerance)
      eps = max(gsl_epsilon(tolerance, 0.0_wp), 10.0_wp*smallest_gsl_epsilon)
      ! the first pass: loosen the epsilon while GSL's control cannot meet it at all
      do loosening = 1, 6
         call half_period_monodromy(model, point, eps, best, log_condition, part, run_error, log_peak, coefficient_noise)
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
      phase = phase_bound(model, point)
      window = model%window(point%alpha)
      half = window%half
      call refine(ladder, tr, .false., roundoff_level(log_peak, tr%log_abs, int(part%n_steps), phase, rk_rounding, half) &
                  + coefficient_noise)
      last_coefficient_noise = coefficient_noise
      estimate = -1.0_wp
      do run = 2, max_ladder_runs
         ! the first step down also divides by the condition κ of the first pass: where the
         ! solutions grow far beyond S inside the period (α → π², β → 0) the first pass's
         ! error is κ times its epsilon and two loose passes can agree on a wrong value
         eps = next_local_tolerance(eps, merge(first_step_factor(log_peak, tr%log_abs), 10.0_wp, run == 2), &
                                    smallest_gsl_epsilon)
         call half_period_monodromy(model, point, eps, trial, log_condition, part, run_error, log_peak, coefficient_noise)
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
               call half_period_monodromy(model, point, 100.0_wp*eps, trial, log_condition, part, run_error, log_peak)
               call add_work(stats, part)
               if (allocated(run_error)) then
                  call move_alloc(run_error, error)
                  return
               end if
               estimate = trace_distance(trace_of(best), trace_of(trial))
            end if
            tr = trace_of(best)
            estimate = max(estimate, roundoff_level(log_peak, tr%log_abs, int(part%n_steps), phase, rk_rounding, half) &
                                     + last_coefficient_noise)
            exit
         end if
         tr = trace_of(trial)
         noise = roundoff_level(log_peak, tr%log_abs, int(part%n_steps), phase, rk_rounding, half) + coefficient_noise
         last_coefficient_noise = coefficient_noise
         call refine(ladder, tr, eps <= 1.001_wp*smallest_gsl_epsilon .or. run == max_ladder_runs, noise, &
                     near_floor=eps <= 1.0e3_wp*smallest_gsl_epsilon, contraction=.true.)
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
   subroutine trace_gsl(model, point, tolerance, tr, stats, error)
      class(hill_model_t), intent(in) :: model  !! the model
      type(hill_point_t), intent(in) :: point   !! α, β, ε
      real(wp), intent(in) :: tolerance         !! target error on S, scaled by max(1, |S|)
      type(trace_t), intent(out) :: tr          !! S and its error estimate
      type(work_stats_t), intent(out) :: stats  !! rk8pd steps, rejections, Q evaluations
      !> GSL failure; err_accuracy when round-off limited (`tr` then holds the best value)
      type(error_t), allocatable, intent(out) :: error
      type(scaled_matrix_t) :: m
      real(wp) :: estimate
      call monodromy_gsl(model, point, tolerance, m, stats, error, estimate)
      if (allocated(error)) then
         if (error%code /= err_accuracy) return
      end if
      tr = trace_of(m)
      tr%error_estimate = estimate
   end subroutine trace_gsl

   !> Monodromy by direct rk8pd integration over the whole period [0, P] (the jumps of q
   !> kept), without the symmetry (GSL epsilon tolerance·gsl_tolerance_factor, no rerun): a
   !> check of `monodromy_gsl`, at twice the work.
   subroutine monodromy_gsl_full_period(model, point, tolerance, m, stats, error)
      class(hill_model_t), intent(in) :: model  !! the model
      type(hill_point_t), intent(in) :: point   !! α, β, ε
      real(wp), intent(in) :: tolerance         !! sets GSL's control epsilon
      type(scaled_matrix_t), intent(out) :: m   !! monodromy over [0, 2]
      type(work_stats_t), intent(out) :: stats  !! rk8pd steps, rejections, Q evaluations
      type(error_t), allocatable, intent(out) :: error  !! GSL failure; unallocated on success
      real(wp) :: y(2, 2), log_scale(2), log_peak(2)
      stats = work_stats_t()
      call check_point(model, point, error)
      if (allocated(error)) return
      call check_tolerance(tolerance, error)
      if (allocated(error)) return
      call integrate_pair(model, point, period_window(model, point), gsl_epsilon(tolerance, 0.0_wp), y, log_scale, &
                          log_peak, stats, error)
      if (allocated(error)) return
      m = monodromy_from_window(y, log_scale(1), log_scale(2), .false.)
   end subroutine monodromy_gsl_full_period

   !> The whole period [0, P] as a window, with the jumps of q in it (from the model's own
   !> window: its jumps, and their mirror images about its start when it is half a period).
   pure function period_window(model, point) result(window)
      class(hill_model_t), intent(in) :: model  !! the model
      type(hill_point_t), intent(in) :: point   !! α, β, ε
      type(hill_window_t) :: window
      type(hill_window_t) :: own
      real(wp) :: period, jumps(2*size(own%breaks) + 2), t
      integer :: k, n, i
      own = model%window(point%alpha)
      period = model%period()
      n = 0
      do k = 1, own%n_breaks
         n = n + 1; jumps(n) = own%breaks(k)
         if (own%half) then
            n = n + 1; jumps(n) = 2.0_wp*own%start - own%breaks(k)
         end if
      end do
      ! the window's ends are not among its jumps: where q has jumps at all, they are taken
      ! as jumps too (a restart where q is continuous costs a few steps, nothing more)
      if (own%n_breaks > 0) then
         n = n + 1; jumps(n) = own%start
         n = n + 1; jumps(n) = own%start + own%length
      end if
      window = hill_window_t(start=0.0_wp, length=period, half=.false.)
      do k = 1, n
         t = modulo(jumps(k), period)
         if (t <= 0.0_wp .or. t >= period) cycle
         if (any(window%breaks(1:window%n_breaks) == t)) cycle
         if (window%n_breaks == size(window%breaks)) exit
         ! insertion in ascending order
         i = window%n_breaks
         do while (i > 0)
            if (window%breaks(i) < t) exit
            window%breaks(i + 1) = window%breaks(i)
            i = i - 1
         end do
         window%breaks(i + 1) = t
         window%n_breaks = window%n_breaks + 1
      end do
   end function period_window

   !> GSL control epsilon for a target tolerance and a condition ln κ, floored.
   pure real(wp) function gsl_epsilon(tolerance, log_condition) result(eps)
      real(wp), intent(in) :: tolerance, log_condition
      eps = max(smallest_gsl_epsilon, tolerance*gsl_tolerance_factor*exp(-min(log_condition, 100.0_wp)))
   end function gsl_epsilon

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
end module hillstab_integrate_monodromy_gsl

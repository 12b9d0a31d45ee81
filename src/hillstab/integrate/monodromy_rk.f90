!> Monodromy of the χ equation χ'' + q(τ) χ = 0 (q of the model, eq. (47)) by
!> hillstab's adaptive Runge–Kutta integrator, over half a period.
!>
!> q is even and 2-periodic, so with the even and odd fundamental solutions u
!> (u(0) = 1, u'(0) = 0) and v (v(0) = 0, v'(0) = 1) on [0, 1] the one-period monodromy is
!> M = R Φ(1)⁻¹ R Φ(1), R = diag(1, −1), Φ = [[u, v], [u', v']], that is
!>
!>   M = [[u v' + u' v, 2 v v'], [2 u u', u v' + u' v]] at τ = 1,  S = 2 (u v' + u' v),
!>
!> and det M = (u v' − u' v)² = W² = 1 (Floquet theory of the Hill equation). Only [0, 1] is integrated.
!>
!> Strongly negative q (β ≪ 0, α → π²) makes u, v grow like e^{∫√|q|}; the
!> integration stops whenever a pair exceeds 2^200, rescales it by a power of two
!> (exact) and resumes, so the result is a `scaled_matrix_t` that cannot overflow.
!>
!>```fortran
!> type(trace_t) :: tr
!> type(error_t), allocatable :: error
!> call trace_rk(elastic_model_t(), hill_point_t(9.8_wp, 2.47_wp, 0.0_wp), 1.0e-10_wp, tr, error)
!>```
module hillstab_integrate_monodromy_rk
   use hillstab_core_kinds, only: wp, int64
   use hillstab_core_error, only: error_t, set_error, err_invalid_parameter, err_integration, err_accuracy
   use hillstab_integrate_refine, only: refinement_t, start_refinement, refine, refine_more, refine_roundoff, &
      roundoff_level, propagator_condition, first_step_factor, next_local_tolerance, sensitivity_t, &
      accumulate_sensitivity, coefficient_level, rk_rounding
   use hillstab_core_stats, only: work_stats_t, add_work
   use hillstab_hill_model, only: hill_model_t, hill_point_t, hill_window_t, hill_coefficient_before, check_point, &
      model_split, window_piece_end
   use hillstab_hill_coefficient, only: phase_bound
   use hillstab_hill_transfer, only: scaled_matrix_t, normalize_scaled, trace_t, trace_of, monodromy_from_window
   use hillstab_integrate_rk, only: rk_system_t, rk_options_t, rk_step_t, rk_integrate, rk_dopri5, rk_dop853
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   implicit none
   private
   public :: monodromy_rk, trace_rk, rk_tolerances

   !> rtol = atol = tolerance × this factor for DOP853. Measured over α ∈ {0, 2, 5, 9, 9.8},
   !> β ∈ {−50, 1, 2.47, 6, 400}, tolerance 1e-6…1e-13: the error of S divided by
   !> max(1, |S|) is at most 0.93 × (10·rtol) and typically 0.05–0.3 × (10·rtol), so 0.05
   !> keeps it below about half the requested tolerance.
   real(wp), parameter :: dop853_tolerance_factor = 0.05_wp
   !> The same for DOPRI5 (measured error of S at most 0.6 × (50·rtol) on the same grid).
   real(wp), parameter :: dopri5_tolerance_factor = 0.02_wp
   !> Local tolerances are not taken below this (round-off floor of the pairs).
   real(wp), parameter :: tolerance_floor = 1.0e-15_wp
   !> `trace_rk`: the first local tolerance of its ladder is tolerance × this factor (twice
   !> the calibrated `dop853_tolerance_factor`, so that the first difference usually meets
   !> the tolerance), each further one ten times smaller.
   real(wp), parameter :: ladder_start_factor = 2.0_wp
   !> `trace_rk`: at most this many values of S per point.
   integer, parameter :: max_ladder_runs = 8
   !> A solution pair is rescaled when its largest component passes 2^200.
   integer, parameter :: rescale_exponent = 200

   !> The even and odd solutions (u, u', v, v') of χ'' + q(τ) χ = 0 as one RK system; the
   !> observer stops the integration before either pair can overflow.
   type, extends(rk_system_t) :: even_odd_pair_t
      class(hill_model_t), allocatable :: model  !! the model
      type(hill_point_t) :: point                !! α, β, ε
      !> the jump of q that ends the current piece of the window (huge: none): q is taken
      !> from the left there (`hill_coefficient_before`)
      real(wp) :: jump = huge(1.0_wp)
      !> largest u², v'², |v u'| of the current (unrescaled) stretch, for the condition
      real(wp) :: peak_terms(3) = 0.0_wp
      !> ln of the scales of the u and v pairs of the current stretch, the constant c₀ of q
      real(wp) :: log_u = 0.0_wp, log_v = 0.0_wp, c0 = 0.0_wp
      !> the integrals for the rounding of q (hillstab_integrate_refine `coefficient_level`)
      type(sensitivity_t) :: sensitivity
      !> Q evaluations made for them (one per step)
      integer(int64) :: n_extra = 0
   contains
      procedure :: rhs => even_odd_rhs
      procedure :: observe => watch_growth
   end type even_odd_pair_t

contains

   !> Local tolerances rtol = atol used for a target error `tolerance` on S.
   pure real(wp) function rk_tolerances(tolerance, method) result(local)
      real(wp), intent(in) :: tolerance  !! target error on S, scaled by max(1, |S|)
      integer, intent(in) :: method      !! rk_dopri5 or rk_dop853
      if (method == rk_dopri5) then
         local = max(tolerance*dopri5_tolerance_factor, tolerance_floor)
      else
         local = max(tolerance*dop853_tolerance_factor, tolerance_floor)
      end if
   end function rk_tolerances

   !> One-period monodromy M of the χ equation from the solutions u, v (u(start) = 1, u' = 0;
   !> v(start) = 0, v' = 1) over the model's window: the even and odd solutions on half a
   !> period where Q is even about the start, the fundamental matrix over the period else; the
   !> integration restarts at each jump of Q inside the window.
   subroutine monodromy_rk(model, point, tolerance, m, stats, error, method, local_tolerance, log_peak, coefficient_noise)
      class(hill_model_t), intent(in) :: model  !! the model
      type(hill_point_t), intent(in) :: point   !! α, β, ε
      real(wp), intent(in) :: tolerance        !! target error on S, scaled by max(1, |S|)
      type(scaled_matrix_t), intent(out) :: m  !! M = e^{log_scale} m
      type(work_stats_t), intent(out) :: stats !! steps, rejections, Q evaluations
      type(error_t), allocatable, intent(out) :: error  !! integration failure; unallocated on success
      integer, intent(in), optional :: method  !! rk_dop853 (default) or rk_dopri5
      !> rtol = atol of the pair (floored at 1e-15), instead of the calibrated
      !> `rk_tolerances(tolerance, method)`
      real(wp), intent(in), optional :: local_tolerance
      !> ln of the largest scaled condition of the half-period propagator along the way
      !> (`propagator_condition`), for the round-off level of S
      real(wp), intent(out), optional :: log_peak
      !> the round-off of S from the rounding of q (`coefficient_level`)
      real(wp), intent(out), optional :: coefficient_noise
      type(rk_options_t) :: options
      type(trace_t) :: tr
      real(wp) :: c1
      type(even_odd_pair_t) :: pair
      type(work_stats_t) :: part
      real(wp) :: t, y(4), h_next, log_u, log_v, peak, piece_end, window_end
      type(hill_window_t) :: window
      integer :: e, e_u, e_v, piece
      character(len=80) :: buffer

      stats = work_stats_t()
      m = scaled_matrix_t()
      call check_point(model, point, error)
      if (allocated(error)) return
      if (.not. (ieee_is_finite(tolerance) .and. tolerance > 0.0_wp)) then
         write (buffer, '(es12.4)') tolerance
         call set_error(error, err_invalid_parameter, "monodromy_rk: tolerance must be > 0, got "// &
            trim(adjustl(buffer)))
         return
      end if
      options%method = rk_dop853
      if (present(method)) options%method = method
      if (options%method /= rk_dop853 .and. options%method /= rk_dopri5) then
         call set_error(error, err_invalid_parameter, "monodromy_rk: unknown Runge-Kutta method")
         return
      end if
      options%rtol = rk_tolerances(tolerance, options%method)
      if (present(local_tolerance)) options%rtol = max(local_tolerance, tolerance_floor)
      options%atol = options%rtol
      options%max_steps = 1000000
      allocate (pair%model, source=model)
      pair%point = point
      call model_split(model, point%alpha, point%beta, point%epsilon, pair%c0, c1)

      ! y = (u, u', v, v') with the even and odd initial values
      y = [1.0_wp, 0.0_wp, 0.0_wp, 1.0_wp]
      window = model%window(point%alpha)
      window_end = window%start + window%length
      t = window%start
      log_u = 0.0_wp
      log_v = 0.0_wp
      e_u = 0
      e_v = 0
      peak = 0.0_wp
      piece = 1
      do
         call window_piece_end(window, piece, piece_end, pair%jump)
         pair%peak_terms = 0.0_wp
         pair%log_u = log_u
         pair%log_v = log_v
         call rk_integrate(pair, t, piece_end, y, options, part, error, h_next=h_next)
         call add_work(stats, part)
         if (allocated(error)) then
            error%message = "monodromy_rk: "//error%message
            return
         end if
         ! fold this stretch's peak in, with the scales of its pairs (as logarithms)
         peak = max(peak, log_or_floor(pair%peak_terms(1)) + 2.0_wp*log_u, &
                    log_or_floor(pair%peak_terms(2)) + 2.0_wp*log_v, &
                    log_or_floor(pair%peak_terms(3)) + log_u + log_v)
         if (t == window_end) exit
         if (t == piece_end) then
            ! a jump of q: the next piece starts with the pair's own first step
            piece = piece + 1
            options%h_initial = 0.0_wp
            cycle
         end if
         ! stopped by watch_growth: rescale each pair by a power of two and resume
         ! (the exponents are counted as integers: a logarithm added at each rescaling
         ! would round each time)
         e = exponent(maxval(abs(y(1:2))))
         y(1:2) = scale(y(1:2), -e)
         e_u = e_u + e
         log_u = e_u*log(2.0_wp)
         e = exponent(maxval(abs(y(3:4))))
         y(3:4) = scale(y(3:4), -e)
         e_v = e_v + e
         log_v = e_v*log(2.0_wp)
         options%h_initial = abs(h_next)
      end do

      if (present(log_peak)) log_peak = max(peak, log(propagator_condition(1.0_wp, 0.0_wp, 0.0_wp, 1.0_wp)))
      stats%n_evaluations = stats%n_evaluations + pair%n_extra
      m = monodromy_from_window(reshape(y, [2, 2]), log_u, log_v, window%half)
      if (present(coefficient_noise)) then
         tr = trace_of(m)
         coefficient_noise = coefficient_level(pair%sensitivity, pair%c0, m, tr%log_abs, window%half)
      end if
      if (.not. (all(ieee_is_finite(m%m)) .and. ieee_is_finite(m%log_scale))) then
         call set_error(error, err_integration, "monodromy_rk: non-finite monodromy")
         m = scaled_matrix_t()
      end if
   end subroutine monodromy_rk

   !> Trace S of the one-period monodromy of the χ equation by `monodromy_rk`, with a
   !> global error control (hillstab_integrate_refine): S at local tolerances ℓ, ℓ/10, … (ℓ =
   !> 2·rk_tolerances(tolerance)) until two successive values agree to `tolerance`; the
   !> finer one is returned with their difference as `tr%error_estimate`. When the local
   !> tolerance reaches its floor, or the values differ only by rounding noise, the finest
   !> value comes back with err_accuracy (round-off limited) and its estimate.
   subroutine trace_rk(model, point, tolerance, tr, error, stats, method)
      class(hill_model_t), intent(in) :: model  !! the model
      type(hill_point_t), intent(in) :: point   !! α, β, ε
      real(wp), intent(in) :: tolerance        !! target error on S, scaled by max(1, |S|)
      type(trace_t), intent(out) :: tr         !! S, flagged if it overflows; its error estimate
      !> integration failure; err_accuracy when round-off limited (`tr` then holds the best value)
      type(error_t), allocatable, intent(out) :: error
      type(work_stats_t), intent(out), optional :: stats  !! steps, rejections, Q evaluations of all runs
      integer, intent(in), optional :: method  !! rk_dop853 (default) or rk_dopri5
      type(scaled_matrix_t) :: m
      type(work_stats_t) :: work, part
      type(refinement_t) :: ladder
      real(wp) :: local, log_peak, phase, coefficient_noise
      logical :: half  ! the model's window is half a period (`roundoff_level`)
      type(hill_window_t) :: window
      integer :: run, kind
      character(len=160) :: buffer
      kind = rk_dop853
      if (present(method)) kind = method
      work = work_stats_t()
      tr = trace_t()
      call start_refinement(ladder, tolerance)
      local = max(ladder_start_factor*rk_tolerances(tolerance, kind), 10.0_wp*tolerance_floor)
      do run = 1, max_ladder_runs
         call monodromy_rk(model, point, tolerance, m, part, error, method, local_tolerance=local, log_peak=log_peak, &
                           coefficient_noise=coefficient_noise)
         call add_work(work, part)
         if (allocated(error)) exit
         if (run == 1) then
            phase = phase_bound(model, point)   ! (the model is known valid from here)
            window = model%window(point%alpha)
            half = window%half
         end if
         tr = trace_of(m)
         call refine(ladder, tr, at_floor=local <= 1.001_wp*tolerance_floor .or. run == max_ladder_runs, &
                     noise=roundoff_level(log_peak, tr%log_abs, int(part%n_steps), phase, rk_rounding, half) &
                           + coefficient_noise, &
                     near_floor=local <= 1.0e3_wp*tolerance_floor)
         if (ladder%verdict /= refine_more) exit
         ! the first step down also divides by the propagator's condition (`first_step_factor`)
         local = next_local_tolerance(local, merge(first_step_factor(log_peak, tr%log_abs), 10.0_wp, run == 1), &
                                      tolerance_floor)
      end do
      if (present(stats)) stats = work
      if (allocated(error)) then
         tr = trace_t()
         return
      end if
      if (ladder%verdict == refine_roundoff) then
         write (buffer, '(a,es9.2,a,es9.2,a)') "rk: the tolerance ", tolerance, &
            " is below what DOP853 reaches here (estimated error ", tr%error_estimate, "); best value returned"
         call set_error(error, err_accuracy, trim(buffer))
      end if
   end subroutine trace_rk

   !> χ'' = −q χ for both solutions: one evaluation of q per call.
   subroutine even_odd_rhs(self, t, y, dydt)
      class(even_odd_pair_t), intent(inout) :: self
      real(wp), intent(in) :: t, y(:)
      real(wp), intent(out) :: dydt(:)
      real(wp) :: q
      q = hill_coefficient_before(self%model, self%point, t, self%jump)
      dydt(1) = y(2)
      dydt(2) = -q*y(1)
      dydt(3) = y(4)
      dydt(4) = -q*y(3)
   end subroutine even_odd_rhs

   !> ln x, or a very negative number for x = 0.
   pure real(wp) function log_or_floor(x)
      real(wp), intent(in) :: x
      log_or_floor = -huge(1.0_wp)
      if (x > 0.0_wp) log_or_floor = log(x)
   end function log_or_floor

   !> Record the condition terms; stop before the solutions can overflow, so they can be rescaled.
   subroutine watch_growth(self, step, stop)
      class(even_odd_pair_t), intent(inout) :: self
      type(rk_step_t), intent(in) :: step
      logical, intent(inout) :: stop
      real(wp) :: top
      self%peak_terms = max(self%peak_terms, [step%y(1)**2, step%y(4)**2, abs(step%y(3)*step%y(2))])
      if (step%index > 0) then
         ! the sensitivity integrals, u and v brought to their common scale, q − c₀ at mid-step
         top = max(self%log_u, self%log_v)
         call accumulate_sensitivity(self%sensitivity, step%y(1)*exp(self%log_u - top), &
                                     step%y(3)*exp(self%log_v - top), top, step%h, &
                                     hill_coefficient_before(self%model, self%point, step%t_old + 0.5_wp*step%h, &
                                                             self%jump) - self%c0)
         self%n_extra = self%n_extra + 1
      end if
      if (step%t < 1.0_wp) then
         stop = exponent(maxval(abs(step%y(1:2)))) > rescale_exponent &
                .or. exponent(maxval(abs(step%y(3:4)))) > rescale_exponent
      end if
   end subroutine watch_growth
end module hillstab_integrate_monodromy_rk

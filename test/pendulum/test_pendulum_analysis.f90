!> Tests of hillstab_pendulum_analysis: the multipliers of the 4×4 variational monodromy
!> along the bounce (dgeev) against the core's S (GSL rk8pd on the Hill equation) at
!> stable and unstable points up to α = 9.5; the onset law (observed onsets against a
!> run at a 1000× tighter tolerance, and their spacing against ln(φ ratio)/ln λ_max);
!> and that φ0 = 0 never starts.
module test_pendulum_analysis
   use hillstab_core_kinds, only: wp, pi2
   use hillstab_core_error, only: error_t
   use hillstab_core_stats, only: work_stats_t
   use hillstab_hill_transfer, only: trace_t
   use hillstab_hill_floquet, only: floquet_from_trace, largest_multiplier_modulus
   use hillstab_integrate_monodromy, only: monodromy_trace, method_t, method_gsl
   use hillstab_pendulum_equations
   use hillstab_pendulum_analysis
   use hillstab_testing
   use hillstab_test_pendulum, only: pendulum_at
   use hillstab_hill_model, only: hill_point_t
   use hillstab_hill_model_elastic, only: elastic_model_t
   implicit none
   private
   public :: collect_pendulum_analysis

contains

   function collect_pendulum_analysis() result(suite)
      type(testsuite_t) :: suite
      suite = new_testsuite("pendulum_analysis", [ &
         new_unittest("multipliers_vs_core", multipliers_vs_core), &
         new_unittest("onset_periods_formula", onset_periods_formula), &
         new_unittest("onset_accurate_at_1e-20", onset_accurate), &
         new_unittest("onset_law_spacing", onset_law_spacing), &
         new_unittest("linear_onset_prediction", linear_onset_prediction), &
         new_unittest("onset_interval_weak_to_strong", onset_interval), &
         new_unittest("zero_angle_never_starts", zero_angle_never_starts)])
   end function collect_pendulum_analysis

   !> λ_max of the Hill equation at (α, β, ε) from the core (GSL rk8pd, 1e-13).
   real(wp) function core_lambda(alpha, beta, epsilon) result(lambda)
      real(wp), intent(in) :: alpha, beta, epsilon
      type(trace_t) :: tr
      type(error_t), allocatable :: error
      call monodromy_trace(elastic_model_t(), hill_point_t(alpha, beta, epsilon), method_t(method_gsl, &
                           tolerance=1.0e-13_wp), tr, error)
      lambda = largest_multiplier_modulus(floquet_from_trace(tr, epsilon))
   end function core_lambda

   !> First time |φ| > 0.1 [radial periods] from phi0 within `periods` periods (−1: never).
   real(wp) function observed_onset(alpha, beta, phi0, rtol, periods) result(n)
      real(wp), intent(in) :: alpha, beta, phi0, rtol
      integer, intent(in) :: periods
      type(pendulum_watch_t) :: watch
      type(work_stats_t) :: stats
      type(error_t), allocatable :: error
      real(wp) :: y(4)
      watch%pendulum = pendulum_at(alpha, beta, 0.0_wp)
      watch%stop_at_onset = .true.
      y = pendulum_initial_state(watch%pendulum, phi0)
      call pendulum_integrate(watch, y, periods*watch%pendulum%period, rtol, stats, error)
      n = -2.0_wp
      if (allocated(error)) return
      n = -1.0_wp
      if (watch%onset_time >= 0.0_wp) n = watch%onset_time/watch%pendulum%period
   end function observed_onset

   !> Multipliers of the 4×4 monodromy: the radial pair is {1, 1}, the swing pair has
   !> product 1 and sum S of the core (to 1e-10 relative; measured 2.5e-13, and |radial − 1|
   !> at most 2.1e-13), at 6+ points, stable and unstable, including α = 9.5.
   subroutine multipliers_vs_core(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp) :: points(2, 8)
      type(bounce_multipliers_t) :: mult
      type(work_stats_t) :: stats
      type(error_t), allocatable :: error
      type(trace_t) :: core
      integer :: i
      character(len=64) :: label
      points = reshape([1.48_wp, 2.47_wp, 3.7_wp, 2.47_wp, 2.57_wp, 1.29_wp, 5.0_wp, 0.76_wp, &
                        7.88_wp, 3.95_wp, 7.48_wp, 2.47_wp, 9.5_wp, 2.47_wp, 9.5_wp, 6.0_wp], [2, 8])
      do i = 1, size(points, 2)
         write (label, '(a,f5.2,a,f5.2)') "alpha=", points(1, i), " beta=", points(2, i)
         call bounce_multipliers(pendulum_at(points(1, i), points(2, i), 0.0_wp), 1.0e-13_wp, mult, stats, error)
         call check(ctx, .not. allocated(error), trim(label)//": multipliers computed")
         if (allocated(error)) cycle
         call monodromy_trace(elastic_model_t(), hill_point_t(points(1, i), points(2, i), 0.0_wp), &
                              method_t(method_gsl, tolerance=1.0e-13_wp), core, error)
         write (*, '(4x,a,a,es22.14,a,es22.14,a,2es10.2)') trim(label), ": lambda1 + lambda2 = ", mult%swing_sum, &
            ", core S = ", core%value, ", |radial - 1| = ", abs(mult%radial - 1.0_wp)
         call check(ctx, mult%swing_sum, core%value, abs=1.0e-10_wp*max(1.0_wp, abs(core%value)), &
            message=trim(label)//": swing multipliers sum to S")
         call check(ctx, maxval(abs(mult%radial - 1.0_wp)) < 1.0e-10_wp, trim(label)//": radial multipliers {1, 1}")
         call check(ctx, abs(mult%swing(1)*mult%swing(2) - 1.0_wp) < 1.0e-8_wp, trim(label)//": det of the swing = 1")
      end do
      ! damped: the radial pair decays by e^(-eps) per period (κT/2 = ε); the swing block
      ! is then taken along the decaying bounce, which is not the chart's periodic orbit
      call bounce_multipliers(pendulum_at(3.7_wp, 2.47_wp, 0.3_wp), 1.0e-13_wp, mult, stats, error)
      call check(ctx, .not. allocated(error), "damped multipliers computed")
      call check(ctx, maxval(abs(mult%radial)), exp(-0.3_wp), rel=1.0e-8_wp, message="damped radial |lambda| = e^-eps")
   end subroutine multipliers_vs_core

   subroutine onset_periods_formula(ctx)
      type(test_context_t), intent(inout) :: ctx
      call check(ctx, onset_periods(1.0e-20_wp, 0.1_wp, 10.0_wp), 19.0_wp, rel=1.0e-14_wp, message="1e-20 -> 19")
      call check(ctx, onset_periods(-1.0e-5_wp, 0.1_wp, exp(1.0_wp)), log(1.0e4_wp), rel=1.0e-14_wp, &
         message="negative phi0")
      call check(ctx, onset_periods(0.0_wp, 0.1_wp, 10.0_wp), -1.0_wp, abs=0.0_wp, message="phi0 = 0: never")
      call check(ctx, onset_periods(1.0e-3_wp, 0.1_wp, 1.0_wp), -1.0_wp, abs=0.0_wp, message="stable: never")
      call check(ctx, onset_periods(0.2_wp, 0.1_wp, 3.0_wp), 0.0_wp, abs=0.0_wp, message="already above")
   end subroutine onset_periods_formula

   !> The observed onset at φ0 = 1e-20 (the linear phase spans 18+ periods) at tolerance
   !> 1e-10 agrees with a run at 1e-13 to 1e-8 relative (measured at most 7e-11; cases (e),
   !> (g), (b)).
   subroutine onset_accurate(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp) :: cases(2, 3), loose, tight
      integer :: i
      cases = reshape([7.88_wp, 3.95_wp, 7.48_wp, 2.47_wp, 3.7_wp, 2.47_wp], [2, 3])
      do i = 1, 3
         loose = observed_onset(cases(1, i), cases(2, i), 1.0e-20_wp, 1.0e-10_wp, 200)
         tight = observed_onset(cases(1, i), cases(2, i), 1.0e-20_wp, 1.0e-13_wp, 200)
         write (*, '(4x,a,f5.2,a,f5.2,a,f12.8,a,f12.8,a,es9.2)') "alpha=", cases(1, i), " beta=", cases(2, i), &
            ": onset from 1e-20 at ", loose, " periods (tol 1e-10), ", tight, " (tol 1e-13), rel. diff ", &
            abs(loose - tight)/tight
         call check(ctx, tight > 10.0_wp, "onset reached after the linear phase")
         call check(ctx, loose, tight, rel=1.0e-8_wp, message="onset accurate to 1e-8")
      end do
   end subroutine onset_accurate

   !> In the linear phase the swing from φ0/10^10 is the swing from φ0 scaled by 10^-10,
   !> so the onset comes ln(1e10)/ln λ_max periods later, to within one radial period: the
   !> threshold is crossed near a peak of |φ|, and in the parametric resonance the peaks
   !> come once per radial period. λ_max from the core.
   subroutine onset_law_spacing(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp) :: cases(2, 3), lambda, spacing, predicted
      integer :: i
      cases = reshape([7.88_wp, 3.95_wp, 7.48_wp, 2.47_wp, 3.7_wp, 2.47_wp], [2, 3])
      do i = 1, 3
         lambda = core_lambda(cases(1, i), cases(2, i), 0.0_wp)
         spacing = observed_onset(cases(1, i), cases(2, i), 1.0e-20_wp, 1.0e-10_wp, 200) &
                   - observed_onset(cases(1, i), cases(2, i), 1.0e-10_wp, 1.0e-10_wp, 200)
         predicted = log(1.0e10_wp)/log(lambda)
         write (*, '(4x,a,f5.2,a,f5.2,a,f10.5,a,f10.5,a)') "alpha=", cases(1, i), " beta=", cases(2, i), &
            ": onset(1e-20) - onset(1e-10) = ", spacing, " periods, ln(1e10)/ln(lambda_max) = ", predicted, &
            " periods"
         call check(ctx, spacing, predicted, abs=1.0_wp, message="onset spacing follows the law")
      end do
   end subroutine onset_law_spacing

   !> The onset from the full linear solution (`linear_onset_periods`) against the observed
   !> onset of the nonlinear pendulum (DOP853 at 1e-10, the first |φ| > 0.1 on the dense
   !> output): within 0.1 radial period for φ0 = 1e-6 … 1e-20 at the paper's (b), (e), (g)
   !> and at two more unstable points of the physical domain; the multiplier law alone is
   !> 0.2–1.1 periods early there. φ0 = 0 and a stable point: never.
   subroutine linear_onset_prediction(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp), parameter :: cases(2, 5) = reshape([3.7_wp, 2.47_wp, 7.88_wp, 3.95_wp, 7.48_wp, 2.47_wp, &
                                                    5.0_wp, 2.47_wp, 9.0_wp, 1.5_wp], [2, 5])
      real(wp), parameter :: phi0s(4) = [1.0e-6_wp, 1.0e-10_wp, 1.0e-15_wp, 1.0e-20_wp]
      real(wp) :: predicted, observed, worst
      integer :: i, j
      do i = 1, size(cases, 2)
         worst = 0.0_wp
         do j = 1, size(phi0s)
            predicted = linear_onset_periods(cases(1, i), cases(2, i), phi0s(j), default_phi_sat)
            observed = observed_onset(cases(1, i), cases(2, i), phi0s(j), 1.0e-10_wp, 200)
            call check(ctx, observed > 0.0_wp, "onset observed within 200 periods")
            call check(ctx, predicted, observed, abs=0.1_wp, message="linear prediction within 0.1 period")
            worst = max(worst, abs(predicted - observed))
         end do
         write (*, '(4x,a,f5.2,a,f5.2,a,f7.4,a)') "alpha=", cases(1, i), " beta=", cases(2, i), &
            ": |predicted - observed| <= ", worst, " periods (phi0 = 1e-6 ... 1e-20)"
      end do
      call check(ctx, linear_onset_periods(7.88_wp, 3.95_wp, 0.0_wp, default_phi_sat), -1.0_wp, abs=0.0_wp, &
                 message="phi0 = 0: never")
      call check(ctx, linear_onset_periods(2.57_wp, 1.29_wp, 1.0e-5_wp, default_phi_sat), -1.0_wp, abs=0.0_wp, &
                 message="stable (c): never")
   end subroutine linear_onset_prediction

   !> The predicted interval of the onset, [first |φ| = 0.1, first |φ| = 0.2] of the linear
   !> swing (`linear_onset_periods` at φ_sat and 2 φ_sat), contains the observed onset from
   !> weak growth (λ_max = 1.13 per period, where the nonlinear swing falls four periods
   !> behind the linear one) to strong (λ_max = 44), at φ0 = 1e-10 (the points where the
   !> crossing once moved by a period or by a peak among them); at λ_max = 1.10 the swing
   !> saturates below 0.1 and never gets there (3000 periods).
   subroutine onset_interval(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp), parameter :: cases(3, 9) = reshape([ &
         0.6_wp, 2.35_wp, 1.0e-10_wp, 2.1821108452452718_wp, 3.2087214047188071_wp, 1.0e-10_wp, &
         1.0_wp, 2.4674_wp, 1.0e-10_wp, 2.0_wp, 2.4674_wp, 1.0e-10_wp, 4.4_wp, 3.1_wp, 1.0e-9_wp, &
         4.0_wp, 2.4674_wp, 1.0e-15_wp, 6.0_wp, 2.4674_wp, 1.0e-10_wp, 7.0_wp, 3.0_wp, 1.0e-10_wp, &
         9.0_wp, 2.4674_wp, 1.0e-10_wp], [3, 9])
      real(wp) :: low, high, observed, lambda
      character(len=160) :: where
      integer :: i
      do i = 1, size(cases, 2)
         low = linear_onset_periods(cases(1, i), cases(2, i), cases(3, i), default_phi_sat)
         high = linear_onset_periods(cases(1, i), cases(2, i), cases(3, i), 2.0_wp*default_phi_sat)
         observed = observed_onset(cases(1, i), cases(2, i), cases(3, i), 1.0e-10_wp, 400)
         lambda = core_lambda(cases(1, i), cases(2, i), 0.0_wp)
         write (where, '(a,f6.3,a,f6.3,a,es8.1,a,f7.3,a,f9.3,a,f9.3,a,f9.3)') "alpha=", cases(1, i), " beta=", &
            cases(2, i), " phi0=", cases(3, i), " lambda_max=", lambda, ": [", low, ",", high, "], observed ", observed
         write (*, '(4x,a)') trim(where)
         call check(ctx, observed > 0.0_wp .and. low > 0.0_wp .and. high > low, trim(where)//": all found")
         call check(ctx, observed >= low - 0.01_wp .and. observed <= high, trim(where)//": observed in the interval")
      end do
      call check(ctx, observed_onset(0.4_wp, 2.4674_wp, 1.0e-5_wp, 1.0e-10_wp, 3000), -1.0_wp, abs=0.0_wp, &
                 message="lambda_max = 1.10: saturates below 0.1 (no onset in 3000 periods)")
   end subroutine onset_interval

   !> φ0 = 0: the bounce is an exact solution, x stays 0 and the swing never starts.
   subroutine zero_angle_never_starts(ctx)
      type(test_context_t), intent(inout) :: ctx
      call check(ctx, observed_onset(7.88_wp, 3.95_wp, 0.0_wp, 1.0e-10_wp, 100), -1.0_wp, abs=0.0_wp, &
         message="no onset from phi0 = 0 in 100 periods")
   end subroutine zero_angle_never_starts

end module test_pendulum_analysis

!> Tests of the largest Lyapunov exponent (hillstab_pendulum_lyapunov) against independent
!> references: while the swing is tiny (φ0 = 1e-12) the tangent vector grows per radial
!> period by the chart's largest Floquet multiplier λ_max, computed by the core (method
!> auto on the Hill equation); on the paper's regular cases (c) and (d) the estimate
!> decays like ln n / n; on case (g) it settles at a clearly positive value; the
!> running estimate and spread are consistent; the exponent does not depend on the
!> integrator (DOP853 against DOPRI5) or the tolerance beyond its error indication;
!> the error bar (batch means) covers the scatter of runs from starts 1e-12 apart at a
!> chaotic point and is small on a regular orbit; bad arguments are refused.
module test_lyapunov
   use hillstab_core_kinds, only: wp
   use hillstab_core_error, only: error_t, err_invalid_parameter
   use hillstab_hill_transfer, only: trace_t
   use hillstab_hill_floquet, only: floquet_t, floquet_from_trace, largest_multiplier_modulus
   use hillstab_integrate_monodromy, only: monodromy_trace, method_t, method_auto
   use hillstab_integrate_rk, only: rk_dopri5
   use hillstab_pendulum_equations, only: pendulum_t, pendulum_initial_state
   use hillstab_pendulum_lyapunov
   use hillstab_pendulum_gsl_lyapunov, only: lyapunov_largest_gsl
   use hillstab_testing
   use hillstab_test_pendulum, only: pendulum_at
   use hillstab_pendulum_chaos, only: chaos_t, chaos_options_t, chaos_indicators
   use hillstab_hill_model, only: hill_point_t
   use hillstab_hill_model_elastic, only: elastic_model_t
   implicit none
   private
   public :: collect_lyapunov

contains

   function collect_lyapunov() result(suite)
      type(testsuite_t) :: suite
      suite = new_testsuite("lyapunov", [ &
         new_unittest("linear_phase_grows_like_floquet", linear_phase_grows_like_floquet), &
         new_unittest("regular_cases_decay", regular_cases_decay), &
         new_unittest("chaotic_case_positive", chaotic_case_positive), &
         new_unittest("running_estimate_consistent", running_estimate_consistent), &
         new_unittest("integrator_independent", integrator_independent), &
         new_unittest("error_bar_formula", error_bar_formula), &
         new_unittest("error_bar_covers_scatter", error_bar_covers_scatter), &
         new_unittest("error_bar_regular_and_early_stop", error_bar_regular_and_early_stop), &
         new_unittest("damped_bounce", damped_bounce), &
         new_unittest("gsl_rk8pd_agrees", gsl_rk8pd_agrees), &
         new_unittest("bad_arguments", bad_arguments)])
   end function collect_lyapunov

   !> ln λ_max of the chart at (α, β, ε) by the core.
   real(wp) function chart_log_lambda(alpha, beta, epsilon)
      real(wp), intent(in) :: alpha, beta, epsilon
      type(trace_t) :: tr
      type(floquet_t) :: f
      type(error_t), allocatable :: error
      call monodromy_trace(elastic_model_t(), hill_point_t(alpha, beta, epsilon), method_t(method_auto, tolerance=1.0e-13_wp), &
         tr, error)
      if (allocated(error)) error stop "test_lyapunov: core failed"
      f = floquet_from_trace(tr, epsilon)
      chart_log_lambda = log(largest_multiplier_modulus(f))
   end function chart_log_lambda

   !> φ0 = 1e-12: once the tangent vector has turned into the growing Floquet direction
   !> its growth per radial period is the chart's ln λ_max, period after period, until
   !> the swing reaches a few percent. Cases (b), (g) and (e) of the paper and a point
   !> in the first tongue (λ_max = 1.27: the other multiplier fades slowly, so later
   !> periods). Undamped only: with damping the radial motion decays too, and the orbit
   !> is no longer the bounce whose swing the chart describes.
   subroutine linear_phase_grows_like_floquet(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp), parameter :: points(3, 4) = reshape([3.70_wp, 2.47_wp, 0.0_wp, 7.48_wp, 2.47_wp, 0.0_wp, &
         7.88_wp, 3.95_wp, 0.0_wp, 1.0_wp, 2.4674_wp, 0.0_wp], [3, 4])
      integer, parameter :: from(4) = [10, 5, 5, 45], to(4) = [16, 8, 8, 55]
      type(lyapunov_t) :: result
      type(error_t), allocatable :: error
      real(wp) :: reference, worst
      character(len=60) :: label
      integer :: k
      do k = 1, size(points, 2)
         write (label, '(a,3f6.2)') "alpha, beta, epsilon", points(:, k)
         call lyapunov_largest(pendulum_at(points(1, k), points(2, k), points(3, k)), &
            pendulum_initial_state(pendulum_at(points(1, k), points(2, k), points(3, k)), 1.0e-12_wp), to(k), 1.0e-12_wp, &
            result, error)
         call check(ctx, .not. allocated(error), "integrated: "//trim(label))
         if (allocated(error)) cycle
         reference = chart_log_lambda(points(1, k), points(2, k), points(3, k))
         worst = maxval(abs(result%log_growth(from(k):to(k)) - reference))
         call check(ctx, worst <= 1.0e-7_wp*max(1.0_wp, abs(reference)), "growth per period = ln lambda_max: "// &
            trim(label))
         call check(ctx, reference > 0.2_wp, "a growing case: "//trim(label))
         write (*, '(4x,a,a,f12.8,a,es9.2)') trim(label), ": ln lambda_max ", reference, ", worst difference ", worst
      end do
   end subroutine linear_phase_grows_like_floquet

   !> Cases (c) and (d) (stable, φ0 = 0.017): λ_n n / ln n stays bounded (between 0.05
   !> and 2 from n = 100 to 2000: λ_n → 0 like ln n / n) and λ_2000 is well below λ_200.
   subroutine regular_cases_decay(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp), parameter :: cases(2, 2) = reshape([2.57_wp, 1.29_wp, 5.0_wp, 0.76_wp], [2, 2])
      type(lyapunov_t) :: result
      type(error_t), allocatable :: error
      real(wp) :: ratio(4)
      integer, parameter :: at(4) = [100, 300, 1000, 2000]
      integer :: k
      do k = 1, 2
         call lyapunov_largest(pendulum_at(cases(1, k), cases(2, k), 0.0_wp), &
            pendulum_initial_state(pendulum_at(cases(1, k), cases(2, k), 0.0_wp), 0.017_wp), 2000, 1.0e-10_wp, result, error)
         call check(ctx, .not. allocated(error), "integrated")
         if (allocated(error)) cycle
         ratio = result%running(at)*at/log(real(at, wp))
         call check(ctx, all(ratio > 0.05_wp .and. ratio < 2.0_wp), "lambda_n n / ln n bounded")
         call check(ctx, result%running(2000) < 0.25_wp*result%running(200), "lambda_2000 < lambda_200/4")
         call check(ctx, result%max_abs_phi < 0.05_wp, "the swing stays small")
         write (*, '(4x,a,2f5.2,a,4f7.3,a,es10.3)') "case", cases(:, k), ": lambda_n n/ln n at n = 100, 300, 1000, 2000:", &
            ratio, "; lambda_2000 = ", result%exponent
      end do
   end subroutine regular_cases_decay

   !> Case (g) (7.48, 2.47), φ0 = 0.017: λ ≈ 0.3 per radial period, well above the
   !> ln n / n of a regular orbit and above its own spread.
   subroutine chaotic_case_positive(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(lyapunov_t) :: result
      type(error_t), allocatable :: error
      call lyapunov_largest(pendulum_at(7.48_wp, 2.47_wp, 0.0_wp), pendulum_initial_state(pendulum_at(7.48_wp, 2.47_wp, 0.0_wp), &
         0.017_wp), 1000, 1.0e-10_wp, result, error)
      call check(ctx, .not. allocated(error), "integrated")
      if (allocated(error)) return
      call check(ctx, result%exponent > 0.15_wp, "clearly positive")
      call check(ctx, result%exponent > 20.0_wp*log(1000.0_wp)/1000.0_wp, "far above ln n / n")
      call check(ctx, result%spread < 0.5_wp*result%exponent, "spread below half the value")
      call check(ctx, result%max_abs_phi > 1.0_wp, "large swings")
      write (*, '(4x,a,f8.4,a,f8.4,a,f7.3)') "case (g): lambda = ", result%exponent, ", spread ", result%spread, &
         ", max |phi| ", result%max_abs_phi
   end subroutine chaotic_case_positive

   !> The running estimate is the mean of the growths; the spread is its range over
   !> the second half; energy is kept.
   subroutine running_estimate_consistent(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(lyapunov_t) :: result
      type(error_t), allocatable :: error
      integer :: n
      call lyapunov_largest(pendulum_at(3.70_wp, 2.47_wp, 0.0_wp), pendulum_initial_state(pendulum_at(3.70_wp, 2.47_wp, 0.0_wp), &
         0.017_wp), 101, 1.0e-10_wp, result, error)
      call check(ctx, .not. allocated(error) .and. result%periods == 101, "integrated")
      if (allocated(error)) return
      do n = 1, 101, 25
         call check(ctx, result%running(n), sum(result%log_growth(:n))/n, abs=1.0e-14_wp, rel=1.0e-12_wp)
      end do
      call check(ctx, result%spread, maxval(result%running(51:)) - minval(result%running(51:)), abs=0.0_wp, &
         rel=1.0e-15_wp)
      call check(ctx, result%exponent == result%running(101), "exponent = last running value")
      call check(ctx, result%energy_drift < 1.0e-8_wp, "energy kept")
   end subroutine running_estimate_consistent

   !> DOP853 and DOPRI5, tolerances 1e-9 and 1e-11: on a regular case the exponents
   !> agree closely; on the chaotic case (g) the orbits part after some periods (that is
   !> chaos) but the exponents agree within their error indications.
   subroutine integrator_independent(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(lyapunov_t) :: a, b
      type(error_t), allocatable :: error
      type(pendulum_t) :: p
      p = pendulum_at(2.57_wp, 1.29_wp, 0.0_wp)
      call lyapunov_largest(p, pendulum_initial_state(p, 0.017_wp), 200, 1.0e-11_wp, a, error)
      call lyapunov_largest(p, pendulum_initial_state(p, 0.017_wp), 200, 1.0e-9_wp, b, error, method=rk_dopri5)
      call check(ctx, .not. allocated(error), "integrated")
      ! measured difference 9.1e-9 (exponent 9.2e-3)
      call check(ctx, a%exponent, b%exponent, abs=1.0e-7_wp, rel=0.0_wp)
      p = pendulum_at(7.48_wp, 2.47_wp, 0.0_wp)
      call lyapunov_largest(p, pendulum_initial_state(p, 0.017_wp), 600, 1.0e-11_wp, a, error)
      call lyapunov_largest(p, pendulum_initial_state(p, 0.017_wp), 600, 1.0e-9_wp, b, error, method=rk_dopri5)
      call check(ctx, .not. allocated(error), "integrated")
      call check(ctx, abs(a%exponent - b%exponent) <= 2.0_wp*(a%spread + b%spread), "chaotic: within the spreads")
      write (*, '(4x,a,2f8.4,a,2f8.4)') "case (g): dop853 1e-11 / dopri5 1e-9: ", a%exponent, b%exponent, &
         ", spreads ", a%spread, b%spread
   end subroutine integrator_independent

   !> The batch-means bar against the formula written out: 10 growths in 5 batches of 2,
   !> batch means m_b, bar = t(0.975, 4) · s_m/√5 with s_m their standard deviation; one
   !> growth: the bar is its magnitude; equal growths: no scatter, bar 0; 7 growths in
   !> batches of 1, 1, 2, 1, 2 (⌊bN/B⌋ boundaries): weighted by length.
   subroutine error_bar_formula(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp) :: g(10), m(5), s, w(5), mean7
      integer :: b
      g = [0.3_wp, 0.5_wp, -0.1_wp, 0.9_wp, 0.4_wp, 0.2_wp, 1.1_wp, 0.7_wp, 0.0_wp, 0.6_wp]
      do b = 1, 5
         m(b) = 0.5_wp*(g(2*b - 1) + g(2*b))
      end do
      s = sqrt(sum((m - sum(m)/5)**2)/4)
      call check(ctx, lyapunov_error_bar(g), 2.776_wp*s/sqrt(5.0_wp), rel=1.0e-14_wp)
      call check(ctx, lyapunov_error_bar(g(2:2)), 0.5_wp, rel=0.0_wp)
      call check(ctx, lyapunov_error_bar([0.25_wp, 0.25_wp, 0.25_wp, 0.25_wp]), 0.0_wp, abs=1.0e-15_wp)
      ! N = 7, B = 5: batches end at 1, 2, 4, 5, 7
      m = [g(1), g(2), 0.5_wp*(g(3) + g(4)), g(5), 0.5_wp*(g(6) + g(7))]
      w = [1.0_wp, 1.0_wp, 2.0_wp, 1.0_wp, 2.0_wp]/7
      mean7 = sum(g(:7))/7
      call check(ctx, lyapunov_error_bar(g(:7)), 2.776_wp*sqrt(5.0_wp/4*sum((w*(m - mean7))**2)), rel=1.0e-14_wp)
      ! two batches at most: t(0.975, 1) = 12.706 on the two halves
      call check(ctx, lyapunov_error_bar(g, batches=2), 12.706_wp*abs(sum(g(1:5))/5 - sum(g(6:10))/5)/2, &
         rel=1.0e-14_wp)
   end subroutine error_bar_formula

   !> The chaotic point (8.3, 5.2), φ0 = 0.017, 400 periods: 9 runs with φ0 changed by
   !> k·1e-12 relative (k = 0 … 8, DOP853 at 1e-10) and the unchanged start at tolerance 1e-11. Runs part
   !> after ~75 periods, and their exponents scatter (measured 0.27–0.46) several times
   !> the spread (≤ 0.09). Each run's distance from the runs' mean is within 1.5 of its
   !> own bar (measured ≤ 1.06; over 100 such runs 94 lie within 1 bar, all within
   !> 1.6), and the mean bar lies within a factor 2 of twice the runs' standard
   !> deviation (measured 0.14 against 0.096): the bar neither misses nor swamps the
   !> scatter, while the spread misses it.
   subroutine error_bar_covers_scatter(ctx)
      type(test_context_t), intent(inout) :: ctx
      integer, parameter :: runs = 10
      type(lyapunov_t) :: result
      type(error_t), allocatable :: error
      type(pendulum_t) :: p
      real(wp) :: lambda(runs), bar(runs), spread(runs), mean, sd, tol
      integer :: k
      p = pendulum_at(8.3_wp, 5.2_wp, 0.0_wp)
      do k = 1, runs
         tol = merge(1.0e-11_wp, 1.0e-10_wp, k == runs)
         call lyapunov_largest(p, pendulum_initial_state(p, 0.017_wp*(1.0_wp + 1.0e-12_wp*merge(0, k - 1, k == runs))), &
            400, tol, result, error)
         call check(ctx, .not. allocated(error), "integrated")
         if (allocated(error)) return
         lambda(k) = result%exponent
         bar(k) = result%exponent_error
         spread(k) = result%spread
      end do
      mean = sum(lambda)/runs
      sd = sqrt(sum((lambda - mean)**2)/(runs - 1))
      call check(ctx, all(abs(lambda - mean) <= 1.5_wp*bar), "each run within 1.5 bars of the mean")
      call check(ctx, sum(bar)/runs >= 0.5_wp*2.0_wp*sd .and. sum(bar)/runs <= 2.0_wp*2.0_wp*sd, &
         "mean bar within a factor 2 of 2 sd")
      call check(ctx, maxval(lambda) - minval(lambda) > 1.5_wp*maxval(spread), "the spread misses the scatter")
      write (*, '(4x,a,2f7.3,a,f7.3,a,f7.3,a,f7.3,a,f7.3)') "(8.3, 5.2): lambda in", minval(lambda), maxval(lambda), &
         ", sd", sd, ", mean bar", sum(bar)/runs, ", max |dev|/bar", maxval(abs(lambda - mean)/bar), &
         ", max spread", maxval(spread)
   end subroutine error_bar_covers_scatter

   !> The regular case (c) (2.57, 1.29), 400 periods: the bar is below ln n / n (measured
   !> 0.0049 against 0.015). The chaotic point (8.3, 5.2) by chaos_indicators with early
   !> stopping: fewer periods (measured 42), a wider bar (measured 0.36), which covers the
   !> distance of the early exponent from the mean of 400-period runs from starts 1e-12
   !> apart (measured 0.10).
   subroutine error_bar_regular_and_early_stop(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(lyapunov_t) :: result
      type(chaos_t) :: early
      type(error_t), allocatable :: error
      type(pendulum_t) :: p
      real(wp) :: long_mean, regular_bar
      integer :: k
      p = pendulum_at(2.57_wp, 1.29_wp, 0.0_wp)
      call lyapunov_largest(p, pendulum_initial_state(p, 0.017_wp), 400, 1.0e-10_wp, result, error)
      call check(ctx, .not. allocated(error), "integrated")
      if (allocated(error)) return
      call check(ctx, result%exponent_error > 0.0_wp .and. result%exponent_error < log(400.0_wp)/400, &
         "regular: bar below ln n/n")
      regular_bar = result%exponent_error
      p = pendulum_at(8.3_wp, 5.2_wp, 0.0_wp)
      call chaos_indicators(p, pendulum_initial_state(p, 0.017_wp), 400, 1.0e-10_wp, chaos_options_t(), early, error)
      call check(ctx, .not. allocated(error), "chaos indicators")
      if (allocated(error)) return
      long_mean = 0.0_wp
      do k = 1, 4
         call lyapunov_largest(p, pendulum_initial_state(p, 0.017_wp*(1.0_wp + 1.0e-12_wp*k)), 400, 1.0e-10_wp, &
            result, error)
         long_mean = long_mean + result%exponent/4
      end do
      call check(ctx, early%periods < 400, "stopped early")
      call check(ctx, abs(early%lyapunov - long_mean) <= early%lyapunov_error, "early bar covers the long runs' mean")
      write (*, '(4x,a,es10.3,a,i0,a,f7.3,a,f7.3,a,f7.3)') "(c): bar", regular_bar, &
         "; (8.3, 5.2) early: periods ", early%periods, ", lambda", early%lyapunov, ", bar", early%lyapunov_error, &
         ", 400-period mean", long_mean
   end subroutine error_bar_regular_and_early_stop

   !> With damping and a stable chart point, the swing and the radial motion decay: the
   !> exponent tends to −ε per radial period (the damped radial oscillator's multipliers
   !> have modulus e^{−κT/2} = e^{−ε}, and so do those of the small damped swing about
   !> r = ρ). The growth of single periods oscillates (the tangent vector turns within the
   !> decaying modes); its mean over 400 periods is −ε to within 1e-3 (measured 1.4e-4).
   subroutine damped_bounce(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(lyapunov_t) :: result
      type(error_t), allocatable :: error
      type(pendulum_t) :: p
      p = pendulum_at(2.57_wp, 1.29_wp, 0.4_wp)
      call lyapunov_largest(p, pendulum_initial_state(p, 0.017_wp), 400, 1.0e-11_wp, result, error)
      call check(ctx, .not. allocated(error), "integrated")
      call check(ctx, result%exponent, -0.4_wp, abs=1.0e-3_wp, rel=0.0_wp)
   end subroutine damped_bounce

   !> GSL rk8pd driving the same equations: the same exponent on the regular case (c)
   !> and the chart's growth in the linear phase of case (g).
   subroutine gsl_rk8pd_agrees(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(lyapunov_t) :: a, b
      type(error_t), allocatable :: error
      type(pendulum_t) :: p
      p = pendulum_at(2.57_wp, 1.29_wp, 0.0_wp)
      call lyapunov_largest(p, pendulum_initial_state(p, 0.017_wp), 300, 1.0e-11_wp, a, error)
      call lyapunov_largest_gsl(p, pendulum_initial_state(p, 0.017_wp), 300, 1.0e-11_wp, b, error)
      call check(ctx, .not. allocated(error), "integrated")
      ! measured difference 3e-11 (exponent 6.8e-3)
      call check(ctx, b%exponent, a%exponent, abs=1.0e-9_wp, rel=0.0_wp)
      call check(ctx, b%energy_drift < 1.0e-8_wp, "energy kept")
      write (*, '(4x,a,es10.3,a,es10.3)') "case (c), 300 periods: dop853 - rk8pd ", a%exponent - b%exponent, &
         ", dop853 ", a%exponent
      p = pendulum_at(7.48_wp, 2.47_wp, 0.0_wp)
      call lyapunov_largest_gsl(p, pendulum_initial_state(p, 1.0e-12_wp), 8, 1.0e-12_wp, b, error)
      call check(ctx, .not. allocated(error), "integrated")
      call check(ctx, maxval(abs(b%log_growth(5:8) - chart_log_lambda(7.48_wp, 2.47_wp, 0.0_wp))) < 1.0e-7_wp, &
         "linear phase: ln lambda_max")
   end subroutine gsl_rk8pd_agrees

   subroutine bad_arguments(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(lyapunov_t) :: result
      type(error_t), allocatable :: error
      type(pendulum_t) :: p
      p = pendulum_at(2.57_wp, 1.29_wp, 0.0_wp)
      call lyapunov_largest(p, pendulum_initial_state(p, 0.017_wp), 0, 1.0e-10_wp, result, error)
      call check(ctx, allocated(error), "periods = 0")
      call lyapunov_largest(p, pendulum_initial_state(p, 0.017_wp), 5, 0.0_wp, result, error)
      call check(ctx, allocated(error), "rtol = 0")
      call lyapunov_largest(p, pendulum_initial_state(p, 0.017_wp), 5, 1.0e-10_wp, result, error, method=7)
      call check(ctx, allocated(error), "unknown method")
      if (allocated(error)) call check(ctx, error%code == err_invalid_parameter, "invalid parameter")
   end subroutine bad_arguments
end module test_lyapunov

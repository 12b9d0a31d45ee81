!> Tests of the Floquet layer: Vieta relations of the multipliers, exponents,
!> overflowed traces, and the damped stability criterion |S₁| < 2 cosh ε.
module test_floquet
   use hillstab_core_kinds, only: wp, pi
   use hillstab_hill_transfer, only: trace_t
   use hillstab_hill_floquet
   use hillstab_testing
   implicit none
   private
   public :: collect_floquet

contains

   function collect_floquet() result(suite)
      type(testsuite_t) :: suite
      suite = new_testsuite("floquet", [ &
         new_unittest("vieta_relations", vieta_relations), &
         new_unittest("exponent_and_rotation", exponent_and_rotation), &
         new_unittest("overflowed_trace", overflowed_trace), &
         new_unittest("damped_criterion", damped_criterion), &
         new_unittest("marginal_verdicts", marginal_verdicts), &
         new_unittest("longer_period", longer_period), &
         new_unittest("in_place_is_the_result", in_place_is_the_result)])
   end function collect_floquet

   !> λ₁ + λ₂ = e^{−ε} S and λ₁ λ₂ = e^{−2ε} for the multipliers of x.
   subroutine vieta_relations(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp) :: traces(7) = [-1.0e6_wp, -3.0_wp, -1.999_wp, 0.5_wp, 1.0_wp, 2.5_wp, 40.0_wp]
      real(wp) :: eps(3) = [0.0_wp, 0.3_wp, 2.0_wp]
      type(floquet_t) :: f
      complex(wp) :: lam(2)
      integer :: i, k
      do k = 1, size(eps)
         do i = 1, size(traces)
            f = floquet_from_value(traces(i), eps(k))
            lam = multipliers(f)
            call check(ctx, real(lam(1) + lam(2), wp), exp(-eps(k))*traces(i), rel=1.0e-12_wp, abs=1.0e-14_wp)
            call check(ctx, aimag(lam(1) + lam(2)), 0.0_wp, abs=1.0e-14_wp)
            call check(ctx, real(lam(1)*lam(2), wp), exp(-2*eps(k)), rel=1.0e-10_wp)
            call check(ctx, abs(lam(1)) >= abs(lam(2)) - 1.0e-15_wp, "largest first")
         end do
      end do
   end subroutine vieta_relations

   subroutine exponent_and_rotation(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(floquet_t) :: f
      f = floquet_from_value(2.0_wp*cos(0.3_wp), 0.0_wp)
      call check(ctx, f%rotation, 0.3_wp, rel=1.0e-13_wp)
      call check(ctx, f%exponent, 0.0_wp, abs=0.0_wp)
      call check(ctx, f%stable .and. f%stable_paper, "|S| < 2 stable")
      f = floquet_from_value(-2.0_wp*cosh(0.8_wp), 0.0_wp)
      call check(ctx, f%exponent, 0.4_wp, rel=1.0e-13_wp)
      call check(ctx, f%argument(1), pi, rel=1.0e-15_wp)
      call check(ctx, .not. f%stable, "S < -2 unstable")
      call check(ctx, largest_multiplier_modulus(f), exp(0.8_wp), rel=1.0e-13_wp)
   end subroutine exponent_and_rotation

   subroutine overflowed_trace(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(floquet_t) :: f
      f = floquet_from_trace(trace_t(huge(1.0_wp), 1500.0_wp, .true.), 0.0_wp)
      call check(ctx, f%exponent, 750.0_wp, rel=1.0e-14_wp)
      call check(ctx, f%log_modulus(2), -1500.0_wp, rel=1.0e-14_wp)
      call check(ctx, largest_multiplier_modulus(f) == huge(1.0_wp), "modulus clamped")
      call check(ctx, .not. (f%stable .or. f%stable_paper), "overflow is unstable")
      f = floquet_from_trace(trace_t(huge(1.0_wp), 1500.0_wp, .true.), 2000.0_wp)
      call check(ctx, f%stable, "damping stronger than growth is stable")
   end subroutine overflowed_trace

   !> With ε > 0 the verdict is |S₁| < 2 cosh ε; the paper's |S₁| ≤ 2 is kept apart.
   subroutine damped_criterion(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(floquet_t) :: f
      f = floquet_from_value(2.5_wp, 1.0_wp)          ! 2 cosh 1 = 3.086
      call check(ctx, f%stable, "2.5 < 2 cosh 1 stable")
      call check(ctx, .not. f%stable_paper, "paper says unstable")
      call check(ctx, f%exponent, 0.5_wp*(acosh(1.25_wp) - 1.0_wp), rel=1.0e-13_wp)
      f = floquet_from_value(-3.2_wp, 1.0_wp)
      call check(ctx, .not. f%stable, "3.2 > 2 cosh 1 unstable")
      f = floquet_from_value(1.0_wp, 0.5_wp)
      call check(ctx, f%exponent, -0.25_wp, rel=1.0e-15_wp)
   end subroutine damped_criterion
   !> Marginal: |S| within max(estimate, tolerance) max(1, |S|) of 2 cosh ε; never without an
   !> estimate (formula, segments) or on overflow.
   subroutine marginal_verdicts(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(floquet_t) :: f
      ! alpha = 9.86, beta = 0 at tolerance 1e-12: S = 2.0000000004 with an estimate 1e-9
      f = floquet_from_trace(trace_t(2.0000000004_wp, log(2.0000000004_wp), .false., 1.0e-9_wp), 0.0_wp, 1.0e-12_wp)
      call check(ctx, f%marginal .and. .not. f%stable, "S = 2 + 4e-10, estimate 1e-9: marginal")
      f = floquet_from_trace(trace_t(-1.9999999996_wp, log(1.9999999996_wp), .false., 1.0e-9_wp), 0.0_wp)
      call check(ctx, f%marginal .and. f%stable, "S = -2 + 4e-10: marginal")
      f = floquet_from_trace(trace_t(2.0000001_wp, log(2.0000001_wp), .false., 1.0e-9_wp), 0.0_wp, 1.0e-12_wp)
      call check(ctx, .not. f%marginal .and. .not. f%stable, "S = 2 + 1e-7: decided")
      ! the tolerance widens the bound when the estimate is smaller
      f = floquet_from_trace(trace_t(1.9999999999995_wp, log(1.9999999999995_wp), .false., 1.0e-14_wp), 0.0_wp, &
                             1.0e-12_wp)
      call check(ctx, f%marginal, "within the tolerance of 2")
      f = floquet_from_trace(trace_t(1.9999999999995_wp, log(1.9999999999995_wp), .false., 1.0e-14_wp), 0.0_wp)
      call check(ctx, .not. f%marginal, "beyond the estimate alone")
      f = floquet_from_trace(trace_t(2.0000000004_wp, log(2.0000000004_wp), .false., -1.0_wp), 0.0_wp, 1.0e-8_wp)
      call check(ctx, .not. f%marginal, "no estimate: never marginal")
      ! damped: the threshold is 2 cosh(epsilon)
      f = floquet_from_trace(trace_t(2.0_wp*cosh(0.5_wp) + 1.0e-11_wp, log(2.0_wp*cosh(0.5_wp)), .false., 1.0e-10_wp), &
                             0.5_wp)
      call check(ctx, f%marginal, "damped threshold 2 cosh(eps)")
      f = floquet_from_trace(trace_t(2.0_wp + 1.0e-11_wp, log(2.0_wp), .false., 1.0e-10_wp), 0.5_wp)
      call check(ctx, .not. f%marginal .and. f%stable, "damped: |S1| = 2 is well inside")
      f = floquet_from_trace(trace_t(huge(1.0_wp), 1500.0_wp, .true., 1.0e-10_wp), 0.0_wp)
      call check(ctx, .not. f%marginal, "overflow: not marginal")
   end subroutine marginal_verdicts
   !> A period P = 4: the multipliers of x are those of χ times e^{−εP/2}, the exponent is
   !> ln|λ_max|/P, and the damped threshold is 2 cosh(εP/2); P = 2 given explicitly is the default.
   subroutine longer_period(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(floquet_t) :: f, g
      real(wp) :: s, eps, growth
      integer :: i
      do i = 0, 30
         s = -6.0_wp + 0.4_wp*i
         eps = 0.02_wp*mod(i, 4)
         f = floquet_from_value(s, 0.0_wp)
         f = floquet_from_trace(f%trace, eps, period=4.0_wp)
         if (abs(s) >= 2.0_wp) then
            growth = log(0.5_wp*(abs(s) + sqrt(s*s - 4.0_wp)))
         else
            growth = 0.0_wp
         end if
         call check_close(ctx, f%log_modulus(1), growth - 2.0_wp*eps, abs=1.0e-13_wp, message="ln|lambda_max|")
         call check_close(ctx, f%exponent, (growth - 2.0_wp*eps)/4.0_wp, abs=1.0e-13_wp, message="exponent")
         call check(ctx, f%stable .eqv. (abs(s) < 2.0_wp*cosh(2.0_wp*eps)), "stable by 2 cosh(eps P/2)")
         g = floquet_from_trace(f%trace, eps, period=2.0_wp)
         f = floquet_from_trace(f%trace, eps)
         call check(ctx, f%exponent == g%exponent .and. (f%stable .eqv. g%stable), "period 2 is the default")
      end do
      call check(ctx, period_damping(0.3_wp, 2.0_wp) == 0.3_wp, "period_damping at P = 2 is epsilon exactly")
   end subroutine longer_period
   !> `set_from_trace` into a result that held another point's analysis gives, field by field,
   !> what `floquet_from_trace` (and, verdicts only, `floquet_verdict`) returns: nothing of the
   !> other point is left. Traces on both sides of ±2, overflowed, with and without damping and
   !> an error estimate, periods 2 and 4.
   subroutine in_place_is_the_result(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(trace_t) :: traces(5)
      real(wp), parameter :: eps(2) = [0.0_wp, 0.35_wp], periods(2) = [2.0_wp, 4.0_wp]
      type(floquet_t) :: f, g
      integer :: i, k, p, w
      logical :: only
      character(len=:), allocatable :: where
      traces(1) = trace_t(value=0.3_wp, log_abs=log(0.3_wp), error_estimate=1.0e-12_wp)
      traces(2) = trace_t(value=-2.7_wp, log_abs=log(2.7_wp))
      traces(3) = trace_t(value=huge(1.0_wp), log_abs=900.0_wp, overflow=.true.)
      traces(4) = trace_t(value=2.0_wp + 1.0e-13_wp, log_abs=log(2.0_wp), error_estimate=1.0e-11_wp)
      traces(5) = trace_t(value=-1.9_wp, log_abs=log(1.9_wp), error_estimate=2.0_wp)
      do w = 0, 1
         only = w == 1
         do p = 1, size(periods)
            do k = 1, size(eps)
               do i = 1, size(traces)
                  where = "trace "//achar(48 + i)//", eps "//achar(48 + k)//", period "//achar(48 + p)// &
                          merge(", verdicts", "          ", only)
                  ! f holds another point's analysis first
                  f = floquet_from_trace(traces(1 + mod(i, size(traces))), eps(3 - k), 1.0e-9_wp, periods(3 - p))
                  call set_from_trace(f, traces(i), eps(k), 1.0e-10_wp, periods(p), only)
                  if (only) then
                     g = floquet_verdict(traces(i), eps(k), 1.0e-10_wp, periods(p))
                  else
                     g = floquet_from_trace(traces(i), eps(k), 1.0e-10_wp, periods(p))
                  end if
                  call check(ctx, f%n == g%n .and. f%verdict == g%verdict .and. f%kind == g%kind, &
                             where//": n, verdict, kind")
                  call check(ctx, (f%stable .eqv. g%stable) .and. (f%stable_paper .eqv. g%stable_paper) .and. &
                             (f%marginal .eqv. g%marginal), where//": flags")
                  call check(ctx, all(f%log_modulus == g%log_modulus) .and. all(f%argument == g%argument) .and. &
                             f%rotation == g%rotation .and. f%exponent == g%exponent, where//": multipliers")
                  call check(ctx, f%trace%value == g%trace%value .and. f%trace%log_abs == g%trace%log_abs .and. &
                             f%epsilon == g%epsilon .and. f%period == g%period, where//": trace, eps, period")
               end do
            end do
         end do
      end do
      ! the kinds the traces reach, against their definitions
      f = floquet_from_trace(traces(2), 0.0_wp)
      call check(ctx, f%verdict == verdict_unstable .and. f%kind == kind_minus_one, "S = -2.7: unstable at -1")
      f = floquet_from_trace(traces(3), 0.0_wp)
      call check(ctx, f%verdict == verdict_unstable .and. f%kind == kind_plus_one, "S overflowed: unstable at +1")
      f = floquet_from_trace(traces(1), 0.35_wp)
      call check(ctx, f%verdict == verdict_stable .and. f%kind == kind_damped, "S = 0.3 damped: damped")
      f = floquet_from_trace(traces(1), 0.0_wp)
      call check(ctx, f%verdict == verdict_stable .and. f%kind == kind_stable, "S = 0.3: stable")
      f = floquet_from_trace(traces(4), 0.0_wp, 1.0e-10_wp)
      call check(ctx, f%verdict == verdict_marginal .and. f%kind == kind_undecided .and. f%marginal, &
                 "S = 2 + 1e-13 with an estimate 1e-11: marginal, undecided")
   end subroutine in_place_is_the_result

end module test_floquet

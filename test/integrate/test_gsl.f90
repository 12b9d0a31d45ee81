!> Tests of the GSL-based references (hillstab_hill_mathieu, hillstab_integrate_monodromy_gsl):
!> published Mathieu characteristic values, transition curves checked as transitions (S = ±2) by two independent
!> monodromies, the α = 0 closed form, the half-period identity against a
!> full-period integration, det M = 1, agreement with Richardson-extrapolated
!> segmentation, the error-versus-tolerance contract, bad input, and
!> thread safety under OpenMP.
module test_gsl
   use hillstab_core_kinds, only: wp, pi2
   use hillstab_core_error, only: error_t, err_invalid_parameter
   use hillstab_core_stats, only: work_stats_t
   use hillstab_hill_coefficient
   use hillstab_hill_transfer, only: trace_t, scaled_matrix_t, matrix_of
   use hillstab_integrate_monodromy, only: trace_segmented, method_t, method_gsl, monodromy_trace
   use hillstab_integrate_monodromy_gsl
   use hillstab_hill_mathieu
   use hillstab_testing
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_positive_inf, ieee_quiet_nan
   use hillstab_hill_model, only: hill_model_t, hill_point_t
   use hillstab_hill_model_elastic, only: elastic_model_t
   use hillstab_hill_model_mathieu, only: mathieu_model_t
   use hillstab_hill_models, only: model_from_code
   use hillstab_test_models, only: model_of_code
   implicit none
   private
   public :: collect_gsl

contains

   function collect_gsl() result(suite)
      type(testsuite_t) :: suite
      suite = new_testsuite("gsl", [ &
         new_unittest("mathieu_published", mathieu_published), &
         new_unittest("mathieu_negative_q", mathieu_negative_q), &
         new_unittest("transition_curves", transition_curves), &
         new_unittest("alpha_zero", alpha_zero), &
         new_unittest("half_period_identity", half_period_identity), &
         new_unittest("segmented_agreement", segmented_agreement), &
         new_unittest("tolerance_contract", tolerance_contract), &
         new_unittest("work_counted", work_counted), &
         new_unittest("bad_input", bad_input), &
         new_unittest("method_dispatch", method_dispatch), &
         new_unittest("openmp_threads", openmp_threads)])
   end function collect_gsl

   !> Characteristic values published to 12 decimals (GSL, SciPy and a
   !> tridiagonal solve agree to ~1e-13).
   subroutine mathieu_published(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp) :: value
      type(error_t), allocatable :: error
      call mathieu_a(0, 1.0_wp, value, error)
      call check(ctx, value, -0.455138604107_wp, abs=1.0e-11_wp, message="a0(1)")
      call mathieu_b(1, 1.0_wp, value, error)
      call check(ctx, value, -0.110248816992_wp, abs=1.0e-11_wp, message="b1(1)")
      call mathieu_a(1, 1.0_wp, value, error)
      call check(ctx, value, 1.859108072514_wp, abs=1.0e-11_wp, message="a1(1)")
      call mathieu_b(2, 1.0_wp, value, error)
      call check(ctx, value, 3.917024772998_wp, abs=1.0e-11_wp, message="b2(1)")
      call mathieu_a(0, 10.0_wp, value, error)
      call check(ctx, value, -13.936979956659_wp, abs=1.0e-11_wp, message="a0(10)")
      call mathieu_b(1, 10.0_wp, value, error)
      call check(ctx, value, -13.936552479250_wp, abs=1.0e-11_wp, message="b1(10)")
      call mathieu_a(0, 25.0_wp, value, error)
      call check(ctx, value, -40.256779546567_wp, abs=1.0e-11_wp, message="a0(25)")
      call mathieu_a(1, 25.0_wp, value, error)
      call check(ctx, value, -21.314899690666_wp, abs=1.0e-11_wp, message="a1(25)")
      call check(ctx, .not. allocated(error), "no error on valid input")
      ! q = 0: a_n = b_n = n²
      call mathieu_b(7, 0.0_wp, value, error)
      call check(ctx, value, 49.0_wp, abs=1.0e-14_wp, message="b7(0)")
   end subroutine mathieu_published

   !> A&S 20.8.3: a_{2k}(−q) = a_{2k}(q), a_{2k+1}(−q) = b_{2k+1}(q).
   subroutine mathieu_negative_q(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp) :: plus, minus
      type(error_t), allocatable :: error
      call mathieu_a(2, 3.0_wp, plus, error)
      call mathieu_a(2, -3.0_wp, minus, error)
      call check(ctx, minus, plus, rel=1.0e-13_wp)
      call mathieu_b(3, 3.0_wp, plus, error)
      call mathieu_a(3, -3.0_wp, minus, error)
      call check(ctx, minus, plus, rel=1.0e-13_wp)
   end subroutine mathieu_negative_q

   !> On β = (π²/4) a_n(2ν/π²) and (π²/4) b_n(2ν/π²) the Mathieu model has
   !> S = +2 (n even) or −2 (n odd), by GSL rk8pd and by average segmentation
   !> (Richardson on N, 2N).
   subroutine transition_curves(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp), parameter :: nus(3) = [0.5_wp, 3.0_wp, 8.0_wp]
      real(wp) :: beta, expected, richardson
      type(trace_t) :: tr, coarse, fine
      type(work_stats_t) :: stats
      type(error_t), allocatable :: error
      class(hill_model_t), pointer :: model
      type(hill_point_t) :: point
      integer :: n, i, kind
      character(len=60) :: label
      do kind = mathieu_kind_a, mathieu_kind_b
         do n = merge(0, 1, kind == mathieu_kind_a), 3
            do i = 1, size(nus)
               write (label, '(a,i0,a,i0,a,f4.1)') "kind ", kind, " n = ", n, " nu = ", nus(i)
               call mathieu_transition_beta(kind, n, nus(i), beta, error)
               call check(ctx, .not. allocated(error), "transition beta "//trim(label))
               if (allocated(error)) cycle
               expected = merge(2.0_wp, -2.0_wp, mod(n, 2) == 0)
               model => model_of_code(2)
               point = hill_point_t(nus(i), beta, 0.0_wp)
               call trace_gsl(model, point, 1.0e-13_wp, tr, stats, error)
               call check(ctx, tr%value, expected, abs=1.0e-10_wp, message="gsl "//trim(label))
               coarse = trace_segmented(model, point, 2048, sampling_average)
               fine = trace_segmented(model, point, 4096, sampling_average)
               richardson = (4.0_wp*fine%value - coarse%value)/3.0_wp
               call check(ctx, richardson, expected, abs=1.0e-9_wp, message="segments "//trim(label))
            end do
         end do
      end do
   end subroutine transition_curves

   !> α = 0, q ≡ β: S = 2 cos(2√β), or 2 cosh(2√−β) for β < 0.
   subroutine alpha_zero(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp), parameter :: betas(8) = [-30.0_wp, -4.0_wp, -0.5_wp, 0.0_wp, 0.5_wp, 2.47_wp, 9.0_wp, 40.0_wp]
      real(wp) :: exact
      type(trace_t) :: tr
      type(work_stats_t) :: stats
      type(error_t), allocatable :: error
      integer :: i, kind
      class(hill_model_t), pointer :: kind_model
      do kind = 1, 2   ! the elastic and the Mathieu model
         kind_model => model_of_code(kind)
         do i = 1, size(betas)
            if (betas(i) >= 0.0_wp) then
               exact = 2.0_wp*cos(2.0_wp*sqrt(betas(i)))
            else
               exact = 2.0_wp*cosh(2.0_wp*sqrt(-betas(i)))
            end if
            call trace_gsl(kind_model, hill_point_t(0.0_wp, betas(i), 0.0_wp), 1.0e-12_wp, tr, stats, error)
            call check(ctx, tr%value, exact, abs=1.0e-12_wp*max(1.0_wp, abs(exact)))
         end do
      end do
   end subroutine alpha_zero

   !> The half-period monodromy equals the direct full-period integration, and
   !> det M = 1 (relative to the size of the products it cancels).
   subroutine half_period_identity(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp), parameter :: points(3, 6) = reshape([ &
         1.0_wp, 1.48_wp, 2.47_wp, 1.0_wp, 5.0_wp, 0.76_wp, 1.0_wp, 9.8_wp, 2.47_wp, &
         1.0_wp, 9.0_wp, -3.0_wp, 2.0_wp, 6.0_wp, 1.5_wp, 2.0_wp, 12.0_wp, -5.0_wp], [3, 6])
      type(scaled_matrix_t) :: half, full
      type(work_stats_t) :: stats
      type(error_t), allocatable :: error
      class(hill_model_t), pointer :: model
      type(hill_point_t) :: point
      real(wp) :: a(2, 2), b(2, 2), size_a
      integer :: p, i, j
      do p = 1, size(points, 2)
         model => model_of_code(nint(points(1, p)))
         point = hill_point_t(points(2, p), points(3, p), 0.0_wp)
         call monodromy_gsl(model, point, 1.0e-13_wp, half, stats, error)
         call monodromy_gsl_full_period(model, point, 1.0e-14_wp, full, stats, error)
         call check(ctx, .not. allocated(error), "integrations succeed")
         a = matrix_of(half)
         b = matrix_of(full)
         size_a = maxval(abs(a))
         do j = 1, 2
            do i = 1, 2
               call check(ctx, a(i, j), b(i, j), abs=1.0e-11_wp*size_a, message="entry of M")
            end do
         end do
         call check(ctx, a(1, 1)*a(2, 2) - a(1, 2)*a(2, 1), 1.0_wp, &
                    abs=1.0e-11_wp*max(1.0_wp, abs(a(1, 1)*a(2, 2)) + abs(a(1, 2)*a(2, 1))), message="det M")
      end do
   end subroutine half_period_identity

   !> Agreement with average segmentation extrapolated in N (second order:
   !> (4 S_2N − S_N)/3) at elastic points including α = 9.8.
   subroutine segmented_agreement(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp), parameter :: points(2, 5) = reshape([1.48_wp, 2.47_wp, 3.7_wp, 2.47_wp, 7.88_wp, 3.95_wp, &
                                                      9.8_wp, 2.47_wp, 9.8_wp, 12.0_wp], [2, 5])
      type(trace_t) :: tr, coarse, fine
      type(work_stats_t) :: stats
      type(error_t), allocatable :: error
      class(hill_model_t), pointer :: model
      type(hill_point_t) :: point
      real(wp) :: richardson
      integer :: p
      do p = 1, size(points, 2)
         model => model_of_code(1)
         point = hill_point_t(points(1, p), points(2, p), 0.0_wp)
         call trace_gsl(model, point, 1.0e-12_wp, tr, stats, error)
         coarse = trace_segmented(model, point, 4096, sampling_average)
         fine = trace_segmented(model, point, 8192, sampling_average)
         richardson = (4.0_wp*fine%value - coarse%value)/3.0_wp
         call check(ctx, tr%value, richardson, rel=1.0e-9_wp, abs=1.0e-9_wp)
      end do
   end subroutine segmented_agreement

   !> The error in S relative to max(1, |S|) stays below the tolerance: references
   !> from a quadruple-precision RK4 integration (40000 steps, Richardson-corrected)
   !> of the same double-precision parameters. At (9.8, 0) the solutions grow to
   !> ~450 inside the period while S = 2 (κ ≈ 3e3): below tolerance ≈ 1e-11 the
   !> floored GSL epsilon (1e-15) limits the error to ~2e-11.
   subroutine tolerance_contract(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp), parameter :: points(2, 5) = reshape([1.48_wp, 2.47_wp, 5.0_wp, 0.76_wp, 9.8_wp, 2.47_wp, &
                                                      9.8_wp, 0.0_wp, 9.0_wp, -3.0_wp], [2, 5])
      real(wp), parameter :: exact(5) = [-2.128236800477150725_wp, -1.619483096523446508_wp, &
                                         -1266.801968666852957_wp, 1.999999999999999987_wp, 565.9470211143013849_wp]
      real(wp), parameter :: tolerances(4) = [1.0e-6_wp, 1.0e-8_wp, 1.0e-10_wp, 1.0e-12_wp]
      type(trace_t) :: tr
      type(work_stats_t) :: stats
      type(error_t), allocatable :: error
      real(wp) :: bound
      integer :: p, k
      do p = 1, size(points, 2)
         do k = 1, size(tolerances)
            call trace_gsl(elastic_model_t(), hill_point_t(points(1, p), points(2, p), 0.0_wp), tolerances(k), &
                           tr, stats, error)
            bound = tolerances(k)*max(1.0_wp, abs(exact(p)))
            if (p == 4) bound = max(bound, 5.0e-11_wp)  ! the double-precision floor at κ ≈ 3e3
            call check(ctx, tr%value, exact(p), abs=bound)
         end do
      end do
   end subroutine tolerance_contract

   !> Work counters: rk8pd makes 13 stage evaluations per attempted step, one of
   !> them reused (FSAL-like dydt_in), plus one per accepted step for the sensitivity
   !> integrals of the round-off level, and tighter tolerances cost more.
   subroutine work_counted(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(trace_t) :: tr
      type(work_stats_t) :: loose, tight
      type(error_t), allocatable :: error
      class(hill_model_t), pointer :: model
      type(hill_point_t) :: point
      model => model_of_code(1)
      point = hill_point_t(7.88_wp, 3.95_wp, 0.0_wp)
      call trace_gsl(model, point, 1.0e-6_wp, tr, loose, error)
      call trace_gsl(model, point, 1.0e-13_wp, tr, tight, error)
      call check(ctx, loose%n_steps > 0 .and. loose%n_rejected >= 0, "steps counted")
      ! 13 per step (12 per retry) and one per accepted step for the sensitivity integrals
      call check(ctx, loose%n_evaluations >= 12*(loose%n_steps + loose%n_rejected) + loose%n_steps .and. &
                 loose%n_evaluations <= 15*(loose%n_steps + loose%n_rejected) + 1, "about 14 evaluations per step")
      call check(ctx, tight%n_evaluations > loose%n_evaluations, "tighter tolerance costs more")
   end subroutine work_counted

   subroutine bad_input(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp) :: value
      type(trace_t) :: tr
      type(work_stats_t) :: stats
      type(error_t), allocatable :: error
      call mathieu_a(-1, 1.0_wp, value, error)
      call check(ctx, allocated(error), "a_n with n < 0")
      call mathieu_a(mathieu_max_order + 1, 1.0_wp, value, error)
      call check(ctx, allocated(error), "a_n with n too large")
      if (allocated(error)) call check(ctx, error%code == err_invalid_parameter, "code")
      call mathieu_b(0, 1.0_wp, value, error)
      call check(ctx, allocated(error), "b_0")
      call mathieu_b(500, 1.0_wp, value, error)
      call check(ctx, allocated(error), "b_500")
      call mathieu_transition_beta(3, 1, 1.0_wp, value, error)
      call check(ctx, allocated(error), "unknown kind")
      call mathieu_a(mathieu_max_order, 1.0_wp, value, error)
      call check(ctx, .not. allocated(error), "largest order accepted")
      call trace_gsl(elastic_model_t(), hill_point_t(1.0_wp, 2.0_wp, 0.0_wp), 0.0_wp, tr, stats, error)
      call check(ctx, allocated(error), "zero tolerance")
      call trace_gsl(elastic_model_t(), hill_point_t(1.0_wp, 2.0_wp, 0.0_wp), ieee_value(1.0_wp, ieee_positive_inf), tr, &
         stats, error)
      call check(ctx, allocated(error), "infinite tolerance")
      call trace_gsl(elastic_model_t(), hill_point_t(1.0_wp, 2.0_wp, 0.0_wp), ieee_value(1.0_wp, ieee_quiet_nan), tr, stats, error)
      call check(ctx, allocated(error), "NaN tolerance")
      call trace_gsl(elastic_model_t(), hill_point_t(pi2, 2.0_wp, 0.0_wp), 1.0e-8_wp, tr, stats, error)
      call check(ctx, allocated(error), "alpha = pi**2")
   end subroutine bad_input

   subroutine method_dispatch(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(trace_t) :: direct, dispatched
      type(work_stats_t) :: stats
      type(error_t), allocatable :: error
      class(hill_model_t), pointer :: model
      type(hill_point_t) :: point
      model => model_of_code(1)
      point = hill_point_t(5.0_wp, 1.6_wp, 0.4_wp)
      call trace_gsl(model, point, 1.0e-11_wp, direct, stats, error)
      call monodromy_trace(model, point, method_t(kind=method_gsl, tolerance=1.0e-11_wp), dispatched, error)
      call check(ctx, .not. allocated(error), "dispatch succeeds")
      call check(ctx, dispatched%value, direct%value, abs=0.0_wp, message="same trace")
   end subroutine method_dispatch

   !> No shared state: the same traces from several OpenMP threads at once.
   subroutine openmp_threads(ctx)
      type(test_context_t), intent(inout) :: ctx
      integer, parameter :: n = 24
      real(wp) :: serial(n), parallel(n)
      logical :: failed(n)
      integer :: i
      failed = .false.
      do i = 1, n
         serial(i) = trace_at(i, failed(i))
      end do
      !$omp parallel do schedule(static, 1)
      do i = 1, n
         parallel(i) = trace_at(i, failed(i))
      end do
      !$omp end parallel do
      call check(ctx, .not. any(failed), "no errors")
      do i = 1, n
         call check(ctx, parallel(i), serial(i), abs=0.0_wp)
      end do
   contains
      real(wp) function trace_at(k, bad) result(s)
         integer, intent(in) :: k
         logical, intent(inout) :: bad
         type(trace_t) :: tr
         type(work_stats_t) :: stats
         type(error_t), allocatable :: error
         call trace_gsl(elastic_model_t(), hill_point_t(0.4_wp*k, 0.5_wp*k, 0.0_wp), 1.0e-11_wp, tr, stats, error)
         bad = bad .or. allocated(error)
         s = tr%value
      end function trace_at
   end subroutine openmp_threads
end module test_gsl

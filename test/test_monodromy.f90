!> Tests of the segmented monodromy against an independent fine-step RK4
!> integration: unit determinant, second-order convergence of midpoint and
!> average sampling, the 4/3 pendulum resonance, the damped criterion, and
!> finite results in the hard cases.
module test_monodromy
   use hillstab_kinds, only: wp, pi2
   use hillstab_error, only: error_t
   use hillstab_coefficient
   use hillstab_transfer
   use hillstab_floquet
   use hillstab_monodromy
   use test_reference, only: rk4_monodromy, value_of
   use hillstab_testing
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   implicit none
   private
   public :: collect_monodromy

contains

   function collect_monodromy() result(suite)
      type(testsuite_t) :: suite
      suite = new_testsuite("monodromy", [ &
         new_unittest("unit_determinant", unit_determinant), &
         new_unittest("damped_determinant", damped_determinant), &
         new_unittest("second_order_convergence", second_order_convergence), &
         new_unittest("resonance_four_thirds", resonance_four_thirds), &
         new_unittest("damped_stable_beyond_paper", damped_stable_beyond_paper), &
         new_unittest("hard_cases_finite", hard_cases_finite), &
         new_unittest("method_dispatch", method_dispatch)])
   end function collect_monodromy

   subroutine unit_determinant(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp) :: alphas(4) = [0.0_wp, 4.0_wp, 8.0_wp, 9.8_wp], betas(4) = [-2.0_wp, 2.47_wp, 6.0_wp, 12.0_wp]
      integer :: i, j, s
      real(wp) :: m(2, 2)
      do i = 1, 4
         do j = 1, 4
            do s = sampling_endpoint, sampling_average
               m = matrix_of(monodromy_segmented(hill_model_t(model_elastic, alphas(i), betas(j), 0.0_wp), 64, s))
               call check(ctx, determinant(m), 1.0_wp, rel=1.0e-12_wp*max(1.0_wp, maxval(abs(m))**2*1.0e-2_wp))
            end do
         end do
      end do
   end subroutine unit_determinant

   !> The damped swing x'' + εx' + Qx = 0 over one period: det M_x = e^{−2ε}
   !> (Liouville) and tr M_x = e^{−ε} S₁, checked by direct RK4 integration.
   subroutine damped_determinant(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp) :: eps(3) = [0.2_wp, 1.0_wp, 3.0_wp], mx(2, 2), ref(2, 2)
      type(hill_model_t) :: chi, bare
      integer :: k
      do k = 1, size(eps)
         chi = hill_model_t(model_elastic, 5.0_wp, 1.6_wp, eps(k))
         bare = chi; bare%epsilon = 0.0_wp
         ref = rk4_monodromy(bare, eps(k), 20000)
         call check(ctx, determinant(ref), exp(-2*eps(k)), rel=1.0e-10_wp)
         mx = matrix_of(swing_monodromy(monodromy_segmented(chi, 8192, sampling_average), eps(k)))
         call check(ctx, determinant(mx), exp(-2*eps(k)), rel=1.0e-12_wp)
         call check(ctx, mx(1, 1) + mx(2, 2), ref(1, 1) + ref(2, 2), rel=1.0e-6_wp, abs=1.0e-6_wp)
         call check(ctx, mx(2, 1), ref(2, 1), rel=1.0e-6_wp, abs=1.0e-6_wp)
      end do
   end subroutine damped_determinant

   !> Midpoint and average sampling are second order as N doubles.
   subroutine second_order_convergence(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp) :: alphas(2) = [2.0_wp, 5.0_wp], betas(2) = [2.47_wp, 6.0_wp], exact, e1, e2, order
      integer :: i, j, s, n
      type(hill_model_t) :: model
      character(len=80) :: label
      do i = 1, 2
         do j = 1, 2
            model = hill_model_t(model_elastic, alphas(i), betas(j), 0.0_wp)
            ref: block
               real(wp) :: m(2, 2)
               m = rk4_monodromy(model, 0.0_wp, 20000)
               exact = m(1, 1) + m(2, 2)
            end block ref
            do s = sampling_midpoint, sampling_average
               do n = 32, 256, 224
                  e1 = abs(value_of(trace_segmented(model, n, s)) - exact)
                  e2 = abs(value_of(trace_segmented(model, 2*n, s)) - exact)
                  order = log(e1/e2)/log(2.0_wp)
                  write (label, '(a,f4.1,a,f5.2,a,a,a,i0)') "alpha=", alphas(i), " beta=", betas(j), " ", &
                     sampling_name(s), " N=", n
                  call check(ctx, order, 2.0_wp, abs=0.1_wp, message=trim(label))
               end do
            end do
         end do
      end do
   end subroutine second_order_convergence

   !> β = π²/4 (the 4/3 pendulum) lies in the antiperiodic tongue for every α.
   subroutine resonance_four_thirds(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp) :: alphas(5) = [0.1_wp, 1.0_wp, 4.0_wp, 8.0_wp, 9.5_wp], m(2, 2)
      type(hill_model_t) :: model
      type(floquet_t) :: f
      integer :: i
      do i = 1, size(alphas)
         model = hill_model_t(model_elastic, alphas(i), pi2/4, 0.0_wp)
         f = floquet_from_trace(trace_segmented(model, 4096, sampling_average), 0.0_wp)
         call check(ctx, .not. f%stable, "segmented unstable")
         call check(ctx, f%trace%value < -2.0_wp, "antiperiodic: S < -2")
         m = rk4_monodromy(model, 0.0_wp, 40000)
         call check(ctx, f%trace%value, m(1, 1) + m(2, 2), rel=1.0e-5_wp)
      end do
   end subroutine resonance_four_thirds

   !> ε = 1, α = 5, β = 1.6: |S₁| > 2 yet the swing decays (|S₁| < 2 cosh 1), confirmed
   !> by the spectral radius of the directly integrated damped monodromy.
   subroutine damped_stable_beyond_paper(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(hill_model_t) :: chi, bare
      type(floquet_t) :: f
      real(wp) :: m(2, 2), tr, det, radius
      chi = hill_model_t(model_elastic, 5.0_wp, 1.6_wp, 1.0_wp)
      f = floquet_from_trace(trace_segmented(chi, 8192, sampling_average), chi%epsilon)
      call check(ctx, abs(f%trace%value) > 2.0_wp, "|S1| > 2")
      call check(ctx, f%stable, "stable by |S1| < 2 cosh eps")
      call check(ctx, .not. f%stable_paper, "paper's criterion says unstable")
      bare = chi; bare%epsilon = 0.0_wp
      m = rk4_monodromy(bare, 1.0_wp, 20000)
      tr = m(1, 1) + m(2, 2); det = determinant(m)
      radius = (abs(tr) + sqrt(max(tr**2 - 4*det, 0.0_wp)))/2
      if (tr**2 < 4*det) radius = sqrt(det)
      call check(ctx, radius < 1.0_wp, "integrated damped swing decays")
      call check(ctx, log(radius), f%log_modulus(1), rel=1.0e-5_wp)
   end subroutine damped_stable_beyond_paper

   subroutine hard_cases_finite(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp) :: alphas(3) = [9.8_wp, 9.86_wp, 9.8696_wp], betas(4) = [-400.0_wp, 0.0_wp, 3.95_wp, 1.0e4_wp]
      type(floquet_t) :: f
      type(trace_t) :: tr
      integer :: i, j, s
      do i = 1, 3
         do j = 1, 4
            do s = sampling_endpoint, sampling_average
               tr = trace_segmented(hill_model_t(model_elastic, alphas(i), betas(j), 0.0_wp), 512, s)
               f = floquet_from_trace(tr, 0.0_wp)
               call check(ctx, ieee_is_finite(tr%value) .and. ieee_is_finite(tr%log_abs) .and. &
                  ieee_is_finite(f%exponent), "finite")
            end do
            tr = trace_segmented(hill_model_t(model_elastic, alphas(i), betas(j), 0.0_wp), 2, sampling_endpoint)
            call check(ctx, ieee_is_finite(tr%value) .and. ieee_is_finite(tr%log_abs), "finite eq. (37)")
         end do
      end do
      ! q = 0 pieces: β = α makes the first endpoint piece exactly zero
      tr = trace_segmented(hill_model_t(model_elastic, 5.0_wp, 5.0_wp, 0.0_wp), 2, sampling_endpoint)
      call check(ctx, ieee_is_finite(tr%value), "zero piece finite")
      ! extreme negative coefficient: the trace overflows and is flagged, exponent finite
      tr = trace_segmented(hill_model_t(model_elastic, 9.86_wp, -1.0e6_wp, 0.0_wp), 256, sampling_average)
      f = floquet_from_trace(tr, 0.0_wp)
      call check(ctx, tr%overflow .and. ieee_is_finite(f%exponent) .and. f%exponent > 300.0_wp, "overflow flagged")
   end subroutine hard_cases_finite

   subroutine method_dispatch(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(hill_model_t) :: model
      type(trace_t) :: tr
      type(error_t), allocatable :: error
      model = hill_model_t(model_elastic, 3.7_wp, 2.47_wp, 0.0_wp)
      call monodromy_trace(model, method_t(method_formula), tr, error)
      call check(ctx, .not. allocated(error), "formula works")
      call check(ctx, tr%value, value_of(trace_segmented(model, 2, sampling_endpoint)), rel=1.0e-12_wp)
      call monodromy_trace(model, method_t(method_segments, 0, sampling_average), tr, error)
      call check(ctx, allocated(error), "n_segments = 0 rejected")
      call monodromy_trace(hill_model_t(model_elastic, 10.0_wp, 1.0_wp, 0.0_wp), method_t(method_formula), tr, error)
      call check(ctx, allocated(error), "alpha > pi**2 rejected")
      call check(ctx, method_from_name("magnus6") == method_magnus6 .and. method_from_name("x") == -1, "names")
   end subroutine method_dispatch
end module test_monodromy

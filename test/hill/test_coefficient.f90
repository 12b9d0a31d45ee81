!> Tests of the Hill coefficient: the two forms of eq. (25), eq. (28), the
!> closed-form segment averages (against quadrature) and parameter validation.
module test_coefficient
   use hillstab_core_kinds, only: wp, pi, pi2
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   use hillstab_core_error, only: error_t
   use hillstab_hill_coefficient
   use hillstab_testing
   use hillstab_hill_model, only: hill_model_t, hill_point_t, hill_coefficient, segment_average, check_point
   use hillstab_hill_model_elastic, only: elastic_model_t
   use hillstab_hill_model_mathieu, only: mathieu_model_t
   use hillstab_test_models, only: model_of_code
   implicit none
   !> Quadruple precision for the independent quadrature of the segment averages.
   integer, parameter :: qp = selected_real_kind(30)
   private
   public :: collect_coefficient

contains

   function collect_coefficient() result(suite)
      type(testsuite_t) :: suite
      suite = new_testsuite("coefficient", [ &
         new_unittest("two_forms_of_eq25", two_forms_of_eq25), &
         new_unittest("endpoints_are_eq28", endpoints_are_eq28), &
         new_unittest("even_and_periodic", even_and_periodic), &
         new_unittest("isotropic_beta_pi2", isotropic_beta_pi2), &
         new_unittest("average_matches_quadrature", average_matches_quadrature), &
         new_unittest("average_near_pi2_quad_precision", average_near_pi2_quad_precision), &
         new_unittest("mathieu_and_damping", mathieu_and_damping), &
         new_unittest("validation", validation)])
   end function collect_coefficient

   subroutine two_forms_of_eq25(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp) :: alphas(5) = [0.0_wp, 1.48_wp, 5.0_wp, 8.0_wp, 9.5_wp], tau, direct
      integer :: i, j
      class(hill_model_t), pointer :: m_model
      type(hill_point_t) :: m
      do i = 1, size(alphas)
         do j = 0, 20
            tau = 0.1_wp*j
            m_model => model_of_code(1)
            m = hill_point_t(alphas(i), 2.47_wp, 0.0_wp)
            direct = (m%beta - m%alpha*cos(pi*tau))/(1.0_wp - m%alpha/pi2*cos(pi*tau))
            call check(ctx, hill_coefficient(m_model, m, tau), direct, rel=1.0e-11_wp, abs=1.0e-12_wp)
         end do
      end do
   end subroutine two_forms_of_eq25

   subroutine endpoints_are_eq28(ctx)
      type(test_context_t), intent(inout) :: ctx
      class(hill_model_t), pointer :: m_model
      type(hill_point_t) :: m
      real(wp) :: q(2)
      m_model => model_of_code(1)
      m = hill_point_t(9.86_wp, 3.95_wp, 0.0_wp)
      call segment_coefficients(m_model, m, 2, sampling_endpoint, q)
      call check(ctx, q(1), (m%beta - m%alpha)/(1.0_wp - m%alpha/pi2), rel=1.0e-10_wp)
      call check(ctx, q(2), (m%beta + m%alpha)/(1.0_wp + m%alpha/pi2), rel=1.0e-14_wp)
   end subroutine endpoints_are_eq28

   subroutine even_and_periodic(ctx)
      type(test_context_t), intent(inout) :: ctx
      class(hill_model_t), pointer :: m_model
      type(hill_point_t) :: m
      integer :: j
      m_model => model_of_code(1)
      m = hill_point_t(7.5_wp, 6.0_wp, 0.3_wp)
      do j = 1, 9
         call check(ctx, hill_coefficient(m_model, m, -0.21_wp*j), hill_coefficient(m_model, m, 0.21_wp*j), rel=1.0e-13_wp)
         call check(ctx, hill_coefficient(m_model, m, 0.21_wp*j + 2.0_wp), hill_coefficient(m_model, m, 0.21_wp*j), rel=1.0e-12_wp)
      end do
   end subroutine even_and_periodic

   subroutine isotropic_beta_pi2(ctx)
      type(test_context_t), intent(inout) :: ctx
      class(hill_model_t), pointer :: m_model
      type(hill_point_t) :: m
      real(wp) :: q(7)
      m_model => model_of_code(1)
      m = hill_point_t(9.8_wp, pi2, 0.0_wp)
      call check(ctx, hill_coefficient(m_model, m, 0.0_wp), pi2, rel=1.0e-15_wp)
      call segment_coefficients(m_model, m, 7, sampling_average, q)
      call check(ctx, maxval(abs(q - pi2)), 0.0_wp, abs=1.0e-13_wp)
   end subroutine isotropic_beta_pi2

   !> Composite Gauss–Legendre (5 points) on many panels, the independent reference.
   real(wp) function quadrature_mean(m_model, m, a, b) result(mean)
      class(hill_model_t), intent(in) :: m_model
      type(hill_point_t), intent(in) :: m
      real(wp), intent(in) :: a, b
      real(wp), parameter :: x(5) = [-0.9061798459386640_wp, -0.5384693101056831_wp, 0.0_wp, &
                                     0.5384693101056831_wp, 0.9061798459386640_wp]
      real(wp), parameter :: w(5) = [0.2369268850561891_wp, 0.4786286704993665_wp, 0.5688888888888889_wp, &
                                     0.4786286704993665_wp, 0.2369268850561891_wp]
      integer, parameter :: panels = 4000
      real(wp) :: h, c, s
      integer :: i
      h = (b - a)/panels
      s = 0.0_wp
      do i = 1, panels
         c = a + (i - 0.5_wp)*h
         s = s + 0.5_wp*h*sum(w*hill_coefficient(m_model, m, c + 0.5_wp*h*x))
      end do
      mean = s/(b - a)
   end function quadrature_mean

   subroutine average_matches_quadrature(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp) :: alphas(4) = [0.5_wp, 4.0_wp, 9.0_wp, 9.8_wp]
      real(wp) :: ends(2, 5)
      class(hill_model_t), pointer :: m_model
      type(hill_point_t) :: m
      integer :: i, j
      ends = reshape([0.0_wp, 1.0_wp, 1.0_wp, 2.0_wp, 0.0_wp, 0.125_wp, 0.3_wp, 1.7_wp, 1.9_wp, 2.0_wp], [2, 5])
      do i = 1, size(alphas)
         m_model => model_of_code(1)
         m = hill_point_t(alphas(i), 2.47_wp, 0.0_wp)
         do j = 1, 5
            call check(ctx, segment_average(m_model, m, ends(1, j), ends(2, j)), &
               quadrature_mean(m_model, m, ends(1, j), ends(2, j)), rel=1.0e-11_wp, abs=1.0e-11_wp)
         end do
         ! the mean over a whole period: π² + (β − π²)/√(1 − k²)
         call check(ctx, segment_average(m_model, m, 0.0_wp, 2.0_wp), &
            pi2 + (m%beta - pi2)/sqrt(1.0_wp - (m%alpha/pi2)**2), rel=1.0e-13_wp)
      end do
   end subroutine average_matches_quadrature

   !> 1/(1 − k cos θ) in quadruple precision, with 1 − k cos θ = (1 − k) + 2k sin²(θ/2).
   pure real(qp) function inverse_cos_qp(k, one_minus_k, theta) result(f)
      real(qp), intent(in) :: k, one_minus_k, theta
      f = 1.0_qp/(one_minus_k + 2.0_qp*k*sin(0.5_qp*theta)**2)
   end function inverse_cos_qp

   !> 5-point Gauss–Legendre on [a, b] in quadruple precision.
   pure real(qp) function gauss5_qp(k, one_minus_k, a, b) result(s)
      real(qp), intent(in) :: k, one_minus_k, a, b
      real(qp), parameter :: x(5) = [-0.906179845938663992797626878299392965_qp, -0.538469310105683091036314420700208805_qp, &
                                     0.0_qp, 0.538469310105683091036314420700208805_qp, 0.906179845938663992797626878299392965_qp]
      real(qp), parameter :: w(5) = [0.236926885056189087514264040719917363_qp, 0.478628670499366468041291514835638192_qp, &
                                     0.568888888888888888888888888888888889_qp, 0.478628670499366468041291514835638192_qp, &
                                     0.236926885056189087514264040719917363_qp]
      integer :: i
      s = 0.0_qp
      do i = 1, 5
         s = s + w(i)*inverse_cos_qp(k, one_minus_k, 0.5_qp*(a + b) + 0.5_qp*(b - a)*x(i))
      end do
      s = 0.5_qp*(b - a)*s
   end function gauss5_qp

   !> ∫ₐᵇ 1/(1 − k cos θ) dθ by adaptive bisection of 5-point Gauss–Legendre panels until
   !> the two halves agree with the whole to 1e-26 of it (quadruple precision throughout).
   recursive function adaptive_qp(k, one_minus_k, a, b, whole, depth) result(s)
      real(qp), intent(in) :: k, one_minus_k, a, b, whole
      integer, intent(in) :: depth
      real(qp) :: s, m, left, right
      m = 0.5_qp*(a + b)
      left = gauss5_qp(k, one_minus_k, a, m)
      right = gauss5_qp(k, one_minus_k, m, b)
      if (abs(left + right - whole) <= 1.0e-26_qp*abs(left + right) .or. depth > 60) then
         s = left + right
      else
         s = adaptive_qp(k, one_minus_k, a, m, left, depth + 1) + adaptive_qp(k, one_minus_k, m, b, right, depth + 1)
      end if
   end function adaptive_qp

   !> The closed-form segment averages near α → π² (down to π² − 8e-6, where 1 − α/π² =
   !> 8.1e-7) and at β = −19735, against an independent quadrature of 1/(1 − k cos πτ) in
   !> quadruple precision (k and 1 − k from the double α in quadruple precision): the
   !> 4-, 2- and 1-piece segmentations of the period and some others, to 2e-14 relative.
   subroutine average_near_pi2_quad_precision(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp), parameter :: alphas(4) = [9.0_wp, 9.8_wp, 9.869_wp, pi2 - 8.0e-6_wp]
      real(wp), parameter :: ends(2, 9) = reshape([0.0_wp, 0.5_wp, 0.5_wp, 1.0_wp, 1.0_wp, 1.5_wp, 1.5_wp, 2.0_wp, &
                                                   0.0_wp, 1.0_wp, 1.0_wp, 2.0_wp, 0.0_wp, 2.0_wp, 0.001_wp, 0.003_wp, &
                                                   0.3_wp, 0.31_wp], [2, 9])
      real(wp), parameter :: beta = -19735.0_wp
      real(qp) :: k, one_minus_k, a, b, integral, reference
      class(hill_model_t), pointer :: m_model
      type(hill_point_t) :: m
      integer :: i, j
      do i = 1, size(alphas)
         m_model => model_of_code(1)
         m = hill_point_t(alphas(i), beta, 0.0_wp)
         k = real(alphas(i), qp)/(acos(-1.0_qp)**2)
         one_minus_k = (acos(-1.0_qp)**2 - real(alphas(i), qp))/(acos(-1.0_qp)**2)
         do j = 1, size(ends, 2)
            a = acos(-1.0_qp)*real(ends(1, j), qp)
            b = acos(-1.0_qp)*real(ends(2, j), qp)
            integral = adaptive_qp(k, one_minus_k, a, b, gauss5_qp(k, one_minus_k, a, b), 0)
            reference = acos(-1.0_qp)**2 + (real(beta, qp) - acos(-1.0_qp)**2)*integral/(b - a)
            call check(ctx, segment_average(m_model, m, ends(1, j), ends(2, j)), real(reference, wp), rel=2.0e-14_wp, &
                       message="segment average against quadruple-precision quadrature")
         end do
      end do
   end subroutine average_near_pi2_quad_precision

   subroutine mathieu_and_damping(ctx)
      type(test_context_t), intent(inout) :: ctx
      class(hill_model_t), pointer :: m_model
      type(hill_point_t) :: m
      type(hill_point_t) :: undamped
      m_model => model_of_code(2)
      m = hill_point_t(12.0_wp, 3.0_wp, 2.0_wp)
      call check(ctx, hill_coefficient(m_model, m, 1.0_wp/3.0_wp), 3.0_wp - 12.0_wp*0.5_wp - 1.0_wp, rel=1.0e-14_wp)
      call check(ctx, segment_average(m_model, m, 0.2_wp, 0.9_wp), quadrature_mean(m_model, m, 0.2_wp, 0.9_wp), rel=1.0e-12_wp)
      m_model => model_of_code(1)
      m = hill_point_t(6.0_wp, 3.0_wp, 1.5_wp)
      undamped = m; undamped%epsilon = 0.0_wp
      call check(ctx, hill_coefficient(m_model, m, 0.7_wp), hill_coefficient(m_model, undamped, &
         0.7_wp) - 1.5_wp**2/4, rel=1.0e-14_wp)
   end subroutine mathieu_and_damping

   subroutine validation(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(error_t), allocatable :: error
      real(wp) :: nan
      call check_point(elastic_model_t(), hill_point_t(pi2, 1.0_wp, 0.0_wp), error)
      call check(ctx, allocated(error), "alpha = pi**2 rejected")
      call check_point(elastic_model_t(), hill_point_t(-0.1_wp, 1.0_wp, 0.0_wp), error)
      call check(ctx, allocated(error), "alpha < 0 rejected")
      call check_point(elastic_model_t(), hill_point_t(1.0_wp, 1.0_wp, -1.0_wp), error)
      call check(ctx, allocated(error), "epsilon < 0 rejected")
      nan = ieee_value(nan, ieee_quiet_nan)
      call check_point(elastic_model_t(), hill_point_t(1.0_wp, nan, 0.0_wp), error)
      call check(ctx, allocated(error), "NaN rejected")
      call check_point(elastic_model_t(), hill_point_t(9.86_wp, -400.0_wp, 3.0_wp), error)
      call check(ctx, .not. allocated(error), "alpha = 9.86 accepted")
      call check_point(mathieu_model_t(), hill_point_t(25.0_wp, 1.0_wp, 0.0_wp), error)
      call check(ctx, .not. allocated(error), "mathieu nu > pi**2 accepted")
   end subroutine validation
end module test_coefficient

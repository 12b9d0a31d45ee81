!> Tests of the Hill coefficient: the two forms of eq. (25), eq. (28), the
!> closed-form segment averages (against quadrature) and parameter validation.
module test_coefficient
   use hillstab_core_kinds, only: wp, pi, pi2
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   use hillstab_core_error, only: error_t
   use hillstab_hill_coefficient
   use hillstab_testing
   implicit none
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
         new_unittest("mathieu_and_damping", mathieu_and_damping), &
         new_unittest("validation", validation)])
   end function collect_coefficient

   subroutine two_forms_of_eq25(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp) :: alphas(5) = [0.0_wp, 1.48_wp, 5.0_wp, 8.0_wp, 9.5_wp], tau, direct
      integer :: i, j
      type(hill_model_t) :: m
      do i = 1, size(alphas)
         do j = 0, 20
            tau = 0.1_wp*j
            m = hill_model_t(model_elastic, alphas(i), 2.47_wp, 0.0_wp)
            direct = (m%beta - m%alpha*cos(pi*tau))/(1.0_wp - m%alpha/pi2*cos(pi*tau))
            call check(ctx, hill_coefficient(m, tau), direct, rel=1.0e-11_wp, abs=1.0e-12_wp)
         end do
      end do
   end subroutine two_forms_of_eq25

   subroutine endpoints_are_eq28(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(hill_model_t) :: m
      real(wp) :: q(2)
      m = hill_model_t(model_elastic, 9.86_wp, 3.95_wp, 0.0_wp)
      call segment_coefficients(m, 2, sampling_endpoint, q)
      call check(ctx, q(1), (m%beta - m%alpha)/(1.0_wp - m%alpha/pi2), rel=1.0e-10_wp)
      call check(ctx, q(2), (m%beta + m%alpha)/(1.0_wp + m%alpha/pi2), rel=1.0e-14_wp)
   end subroutine endpoints_are_eq28

   subroutine even_and_periodic(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(hill_model_t) :: m
      integer :: j
      m = hill_model_t(model_elastic, 7.5_wp, 6.0_wp, 0.3_wp)
      do j = 1, 9
         call check(ctx, hill_coefficient(m, -0.21_wp*j), hill_coefficient(m, 0.21_wp*j), rel=1.0e-13_wp)
         call check(ctx, hill_coefficient(m, 0.21_wp*j + 2.0_wp), hill_coefficient(m, 0.21_wp*j), rel=1.0e-12_wp)
      end do
   end subroutine even_and_periodic

   subroutine isotropic_beta_pi2(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(hill_model_t) :: m
      real(wp) :: q(7)
      m = hill_model_t(model_elastic, 9.8_wp, pi2, 0.0_wp)
      call check(ctx, hill_coefficient(m, 0.0_wp), pi2, rel=1.0e-15_wp)
      call segment_coefficients(m, 7, sampling_average, q)
      call check(ctx, maxval(abs(q - pi2)), 0.0_wp, abs=1.0e-13_wp)
   end subroutine isotropic_beta_pi2

   !> Composite Gauss–Legendre (5 points) on many panels, the independent reference.
   real(wp) function quadrature_mean(m, a, b) result(mean)
      type(hill_model_t), intent(in) :: m
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
         s = s + 0.5_wp*h*sum(w*hill_coefficient(m, c + 0.5_wp*h*x))
      end do
      mean = s/(b - a)
   end function quadrature_mean

   subroutine average_matches_quadrature(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp) :: alphas(4) = [0.5_wp, 4.0_wp, 9.0_wp, 9.8_wp]
      real(wp) :: ends(2, 5)
      type(hill_model_t) :: m
      integer :: i, j
      ends = reshape([0.0_wp, 1.0_wp, 1.0_wp, 2.0_wp, 0.0_wp, 0.125_wp, 0.3_wp, 1.7_wp, 1.9_wp, 2.0_wp], [2, 5])
      do i = 1, size(alphas)
         m = hill_model_t(model_elastic, alphas(i), 2.47_wp, 0.0_wp)
         do j = 1, 5
            call check(ctx, segment_average(m, ends(1, j), ends(2, j)), &
               quadrature_mean(m, ends(1, j), ends(2, j)), rel=1.0e-11_wp, abs=1.0e-11_wp)
         end do
         ! the mean over a whole period: π² + (β − π²)/√(1 − k²)
         call check(ctx, segment_average(m, 0.0_wp, 2.0_wp), &
            pi2 + (m%beta - pi2)/sqrt(1.0_wp - (m%alpha/pi2)**2), rel=1.0e-13_wp)
      end do
   end subroutine average_matches_quadrature

   subroutine mathieu_and_damping(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(hill_model_t) :: m, undamped
      m = hill_model_t(model_mathieu, 12.0_wp, 3.0_wp, 2.0_wp)
      call check(ctx, hill_coefficient(m, 1.0_wp/3.0_wp), 3.0_wp - 12.0_wp*0.5_wp - 1.0_wp, rel=1.0e-14_wp)
      call check(ctx, segment_average(m, 0.2_wp, 0.9_wp), quadrature_mean(m, 0.2_wp, 0.9_wp), rel=1.0e-12_wp)
      m = hill_model_t(model_elastic, 6.0_wp, 3.0_wp, 1.5_wp)
      undamped = m; undamped%epsilon = 0.0_wp
      call check(ctx, hill_coefficient(m, 0.7_wp), hill_coefficient(undamped, 0.7_wp) - 1.5_wp**2/4, rel=1.0e-14_wp)
   end subroutine mathieu_and_damping

   subroutine validation(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(error_t), allocatable :: error
      real(wp) :: nan
      call check_model(hill_model_t(model_elastic, pi2, 1.0_wp, 0.0_wp), error)
      call check(ctx, allocated(error), "alpha = pi**2 rejected")
      call check_model(hill_model_t(model_elastic, -0.1_wp, 1.0_wp, 0.0_wp), error)
      call check(ctx, allocated(error), "alpha < 0 rejected")
      call check_model(hill_model_t(model_elastic, 1.0_wp, 1.0_wp, -1.0_wp), error)
      call check(ctx, allocated(error), "epsilon < 0 rejected")
      nan = ieee_value(nan, ieee_quiet_nan)
      call check_model(hill_model_t(model_elastic, 1.0_wp, nan, 0.0_wp), error)
      call check(ctx, allocated(error), "NaN rejected")
      call check_model(hill_model_t(model_elastic, 9.86_wp, -400.0_wp, 3.0_wp), error)
      call check(ctx, .not. allocated(error), "alpha = 9.86 accepted")
      call check_model(hill_model_t(model_mathieu, 25.0_wp, 1.0_wp, 0.0_wp), error)
      call check(ctx, .not. allocated(error), "mathieu nu > pi**2 accepted")
   end subroutine validation
end module test_coefficient

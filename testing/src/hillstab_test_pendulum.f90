!> The test suites' pendulum: given chart parameters, r0 = 0.1 m and g = 9.81 m/s².
module hillstab_test_pendulum
   use hillstab_core_kinds, only: wp
   use hillstab_core_error, only: error_t
   use hillstab_pendulum_equations, only: pendulum_t, pendulum_from_chart
   implicit none
   private
   public :: pendulum_at

contains

   !> The pendulum at (α, β, ε) with r0 = 0.1 m, g = 9.81 m/s²; stops the test program
   !> if the parameters are refused (the suites only ask for valid ones).
   function pendulum_at(alpha, beta, epsilon) result(p)
      real(wp), intent(in) :: alpha, beta  !! chart parameters
      real(wp), intent(in), optional :: epsilon  !! damping (default 0)
      type(pendulum_t) :: p
      type(error_t), allocatable :: error
      real(wp) :: eps
      eps = 0.0_wp
      if (present(epsilon)) eps = epsilon
      call pendulum_from_chart(alpha, beta, eps, 0.1_wp, 9.81_wp, p, error)
      if (allocated(error)) error stop "test suites: valid pendulum parameters refused: "//error%message
   end function pendulum_at
end module hillstab_test_pendulum

!> The Arenstorf orbit (restricted three-body problem; Hairer, Nørsett & Wanner,
!> Solving ODEs I, §II.0): one period with DOPRI5 and DOP853 at several tolerances,
!> printing the return error and the work. Hairer's dr_dopri5 driver reports, at
!> rtol = atol = 1e-7 with dense output, fcn = 1442, step = 240, accpt = 216, rejct = 22
!> (its fcn counts 2 for the initial guess and 6 per attempted step).
module arenstorf_system
   use hillstab_core_kinds, only: wp
   use hillstab_integrate_rk, only: rk_system_t
   implicit none
   private
   public :: three_body_t

   !> The restricted three-body problem with mass ratio `mu`.
   type, extends(rk_system_t) :: three_body_t
      real(wp) :: mu = 0.012277471_wp  !! mass ratio moon/(earth + moon)
   contains
      procedure :: rhs => three_body
   end type three_body_t

contains

   !> Equations of motion in the rotating frame, Hairer's (0.1).
   subroutine three_body(self, t, y, dydt)
      class(three_body_t), intent(inout) :: self
      real(wp), intent(in) :: t, y(:)
      real(wp), intent(out) :: dydt(:)
      real(wp) :: d1, d2
      associate (mu => self%mu)
         d1 = ((y(1) + mu)**2 + y(2)**2)**1.5_wp
         d2 = ((y(1) - (1.0_wp - mu))**2 + y(2)**2)**1.5_wp
         dydt(1) = y(3)
         dydt(2) = y(4)
         dydt(3) = y(1) + 2.0_wp*y(4) - (1.0_wp - mu)*(y(1) + mu)/d1 - mu*(y(1) - (1.0_wp - mu))/d2
         dydt(4) = y(2) - 2.0_wp*y(3) - (1.0_wp - mu)*y(2)/d1 - mu*y(2)/d2
      end associate
   end subroutine three_body
end module arenstorf_system

program arenstorf
   use hillstab_core_kinds, only: wp
   use hillstab_core_error, only: error_t
   use hillstab_core_stats, only: work_stats_t
   use hillstab_integrate_rk, only: rk_options_t, rk_integrate, rk_dopri5, rk_dop853, rk_method_name
   use arenstorf_system, only: three_body_t
   implicit none
   real(wp), parameter :: period = 17.0652165601579625588917206249_wp
   real(wp), parameter :: y_start(4) = [0.994_wp, 0.0_wp, 0.0_wp, -2.00158510637908252240537862224_wp]
   real(wp) :: tolerances(4) = [1.0e-7_wp, 1.0e-10_wp, 1.0e-12_wp, 1.0e-14_wp]
   integer :: methods(2) = [rk_dopri5, rk_dop853], i, j
   real(wp) :: t, y(4), t_out(9), y_out(4, 9)
   type(work_stats_t) :: stats
   type(error_t), allocatable :: error
   type(three_body_t) :: three_body

   t_out = [(2.0_wp*j, j=1, 8), period]
   write (*, '(a)') "# method   tol    position err   f-evals  accepted  rejected"
   do i = 1, size(methods)
      do j = 1, size(tolerances)
         t = 0.0_wp
         y = y_start
         call rk_integrate(three_body, t, period, y, &
                           rk_options_t(method=methods(i), rtol=tolerances(j), atol=tolerances(j)), &
                           stats, error, t_out=t_out, y_out=y_out)
         if (allocated(error)) then
            write (*, '(a)') error%message
            cycle
         end if
         write (*, '(a8,es9.1,es14.3,3i10)') rk_method_name(methods(i)), tolerances(j), &
            norm2(y(1:2) - y_start(1:2)), stats%n_evaluations, stats%n_steps, stats%n_rejected
      end do
   end do

end program arenstorf

!> Test-only reference: the one-period monodromy of x'' + ε x' + q(τ) x = 0 by the
!> classical fixed-step Runge–Kutta 4 on the 2×2 matrix equation. It shares no
!> code with the library's transfer matrices, so it is an independent check.
module hillstab_test_reference
   use hillstab_core_kinds, only: wp
   use hillstab_hill_transfer, only: trace_t
   use hillstab_hill_model, only: hill_model_t, hill_point_t, hill_coefficient
   implicit none
   private
   public :: rk4_monodromy, value_of

contains

   !> The value of a trace (a function result cannot be followed by %component).
   pure real(wp) function value_of(tr)
      type(trace_t), intent(in) :: tr
      value_of = tr%value
   end function value_of

   !> Monodromy over one period [0, P] with `n_steps` RK4 steps; `drag` is the ε of the x' term.
   function rk4_monodromy(model, point, drag, n_steps) result(m)
      class(hill_model_t), intent(in) :: model  !! the model
      type(hill_point_t), intent(in) :: point   !! α, β, ε
      real(wp), intent(in) :: drag
      integer, intent(in) :: n_steps
      real(wp) :: m(2, 2)
      real(wp) :: h, t, k1(2, 2), k2(2, 2), k3(2, 2), k4(2, 2)
      integer :: i
      h = model%period()/n_steps
      m = reshape([1.0_wp, 0.0_wp, 0.0_wp, 1.0_wp], [2, 2])
      do i = 0, n_steps - 1
         t = i*h
         k1 = rhs(t, m)
         k2 = rhs(t + 0.5_wp*h, m + 0.5_wp*h*k1)
         k3 = rhs(t + 0.5_wp*h, m + 0.5_wp*h*k2)
         k4 = rhs(t + h, m + h*k3)
         m = m + h/6.0_wp*(k1 + 2.0_wp*k2 + 2.0_wp*k3 + k4)
      end do
   contains
      function rhs(tau, y) result(dy)
         real(wp), intent(in) :: tau, y(2, 2)
         real(wp) :: dy(2, 2), q
         q = hill_coefficient(model, point, tau)
         dy(1, :) = y(2, :)
         dy(2, :) = -q*y(1, :) - drag*y(2, :)
      end function rhs
   end function rk4_monodromy
end module hillstab_test_reference

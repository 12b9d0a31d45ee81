!> Test-only reference: the one-period monodromy of x'' + ε x' + q(τ) x = 0 by the
!> classical fixed-step Runge–Kutta 4 on the 2×2 matrix equation. It shares no
!> code with the library's transfer matrices, so it is an independent check.
module hillstab_test_reference
   use hillstab_core_kinds, only: wp
   use hillstab_hill_transfer, only: trace_t
   use hillstab_hill_model, only: hill_model_t, hill_point_t, hill_coefficient
   use hillstab_core_error, only: error_t, err_accuracy
   use hillstab_integrate_monodromy, only: method_t, monodromy_trace, monodromy_trace_batch, method_auto, &
      method_magnus6
   implicit none
   private
   public :: rk4_monodromy, value_of, auto_row_errors

contains

   !> One chart row (α, the β values) by method auto at `tolerance` as the chart task computes
   !> it (`monodromy_trace_batch`: meshes shared over the row), each point against magnus6 at
   !> 1e-12 (round-off limited references kept, failed points skipped): the largest error
   !> relative to max(1, |S|) over the tolerance goes into `worst`, the points compared into
   !> `n_checked`.
   subroutine auto_row_errors(model, alpha, betas, tolerance, worst, n_checked, epsilon)
      class(hill_model_t), intent(in) :: model  !! the model
      real(wp), intent(in) :: alpha             !! α of the row
      real(wp), intent(in) :: betas(:)          !! its β values
      real(wp), intent(in) :: tolerance         !! auto's tolerance
      real(wp), intent(inout) :: worst          !! largest error/tolerance so far
      integer, intent(inout) :: n_checked       !! points compared so far
      real(wp), intent(in), optional :: epsilon  !! the row's damping (default 0)
      type(trace_t) :: row(size(betas)), reference
      logical :: failed(size(betas))
      type(error_t), allocatable :: error
      real(wp) :: damping
      integer :: k
      damping = 0.0_wp
      if (present(epsilon)) damping = epsilon
      call monodromy_trace_batch(model, hill_point_t(alpha, 0.0_wp, damping), betas, &
                                 method_t(method_auto, tolerance=tolerance), row, failed, error)
      if (allocated(error)) deallocate (error)
      do k = 1, size(betas)
         if (failed(k)) cycle
         call monodromy_trace(model, hill_point_t(alpha, betas(k), damping), &
                              method_t(method_magnus6, tolerance=1.0e-12_wp), reference, error)
         if (allocated(error)) then
            if (error%code /= err_accuracy) cycle
            deallocate (error)
         end if
         worst = max(worst, abs(row(k)%value - reference%value)/max(1.0_wp, abs(reference%value))/tolerance)
         n_checked = n_checked + 1
      end do
   end subroutine auto_row_errors

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

!> Any scalar model x'' + Q(τ) x = 0 (hillstab_hill_model) as a system of one equation:
!> M = 1, K = Q(τ; α, 0) + β (Q(τ; α, 1) − Q(τ; α, 0)) (every model's Q is affine in β),
!> the damping ε of the scene as C = ε. The system methods then reproduce the scalar
!> methods' trace S at every tolerance (the tests hold them to it), and a decoupled system
!> can be checked equation by equation.
!>
!>```fortran
!> type(scalar_system_t) :: one
!> allocate (one%model, source=elastic_model_t())
!>```
module hillstab_hill_system_scalar
   use hillstab_core_kinds, only: wp
   use hillstab_hill_model, only: hill_model_t, hill_window_t
   use hillstab_hill_system, only: hill_system_t
   implicit none
   private
   public :: scalar_system_t

   !> A scalar model seen as a system with n = 1.
   type, extends(hill_system_t) :: scalar_system_t
      class(hill_model_t), allocatable :: model  !! the scalar model
   contains
      procedure :: name => scalar_name
      procedure :: formula => scalar_formula
      procedure :: dof => scalar_dof
      procedure :: mass => scalar_mass
      procedure :: stiffness => scalar_stiffness
      procedure :: period => scalar_period
      procedure :: even => scalar_even
      procedure :: alpha_domain => scalar_alpha_domain
      procedure :: alpha_valid => scalar_alpha_valid
      procedure :: scalar_model => scalar_own_model
   end type scalar_system_t

contains

   pure function scalar_name(self) result(text)
      class(scalar_system_t), intent(in) :: self  !! the system
      character(len=:), allocatable :: text
      text = self%model%name()
   end function scalar_name

   pure function scalar_formula(self) result(text)
      class(scalar_system_t), intent(in) :: self  !! the system
      character(len=:), allocatable :: text
      text = self%model%formula()
   end function scalar_formula

   pure integer function scalar_dof(self)
      class(scalar_system_t), intent(in) :: self  !! the system
      scalar_dof = 1
   end function scalar_dof

   pure subroutine scalar_mass(self, a)
      class(scalar_system_t), intent(in) :: self  !! the system
      real(wp), intent(out) :: a(:, :)           !! M = 1
      a = 1.0_wp
   end subroutine scalar_mass

   !> p = Q(τ; α, 0), b = Q(τ; α, 1) − Q(τ; α, 0).
   pure subroutine scalar_stiffness(self, alpha, tau, p, b)
      class(scalar_system_t), intent(in) :: self  !! the system
      real(wp), intent(in) :: alpha, tau         !! α and τ
      real(wp), intent(out) :: p(:, :), b(:, :)  !! the parts of K
      p = self%model%coefficient(alpha, 0.0_wp, tau)
      b = self%model%coefficient(alpha, 1.0_wp, tau) - p(1, 1)
   end subroutine scalar_stiffness

   !> The model itself, when its damping is the scene's (as the system's C = ε is).
   subroutine scalar_own_model(self, model)
      class(scalar_system_t), intent(in) :: self  !! the system
      class(hill_model_t), allocatable, intent(out) :: model  !! the model, or unallocated
      if (self%model%takes_scene_damping()) allocate (model, source=self%model)
   end subroutine scalar_own_model

   pure real(wp) function scalar_period(self) result(period)
      class(scalar_system_t), intent(in) :: self  !! the system
      period = self%model%period()
   end function scalar_period

   !> Even about τ = 0 when the model's window is half a period from 0 without jumps.
   pure logical function scalar_even(self)
      class(scalar_system_t), intent(in) :: self  !! the system
      type(hill_window_t) :: window
      window = self%model%window(0.0_wp)
      scalar_even = window%half .and. window%start == 0.0_wp .and. window%n_breaks == 0
   end function scalar_even

   pure function scalar_alpha_domain(self) result(text)
      class(scalar_system_t), intent(in) :: self  !! the system
      character(len=:), allocatable :: text
      text = self%model%alpha_domain()
   end function scalar_alpha_domain

   elemental logical function scalar_alpha_valid(self, alpha) result(valid)
      class(scalar_system_t), intent(in) :: self  !! the system
      real(wp), intent(in) :: alpha              !! α
      valid = self%model%alpha_valid(alpha)
   end function scalar_alpha_valid
end module hillstab_hill_system_scalar

!> The models that are forms of the elastic pendulum: what a pendulum given in SI units
!> (a scene's `&physical`) means for them, kept out of the abstract `hill_model_t`.
!>
!> `pendulum_model_t` extends `hill_model_t` with the pendulum's three questions: the
!> model's α of a pendulum in physical units (α = aπ²/ρ, eq. (24), unless the model says
!> otherwise: the Mathieu form takes ν of eq. (21)), what that α means in a header, and
!> whether the model is the elastic pendulum itself (its physical domain a < ρ and its
!> nonlinear motion, which tasks series and lyapunov simulate). The elastic and Mathieu
!> models extend it; every other model is a Hill equation of its own.
!>
!> The functions `pendulum_alpha`, `pendulum_note` and `is_elastic_pendulum` ask any
!> `class(hill_model_t)`: a model that is not a form of the pendulum takes α = aπ²/ρ, no
!> note and is not the pendulum, so that a scene may still give its α and β through
!> `&physical` as the pendulum's.
!>
!>```fortran
!> type(mathieu_model_t) :: mathieu
!> print *, pendulum_alpha(mathieu, physical_t(r0=0.8_wp, g=9.81_wp, omega=6.0_wp, a=0.3_wp))
!>```
module hillstab_hill_model_pendulum
   use hillstab_core_kinds, only: wp
   use hillstab_hill_units, only: physical_t, physical_alpha
   use hillstab_hill_model, only: hill_model_t
   implicit none
   private
   public :: pendulum_model_t, pendulum_alpha, pendulum_note, is_elastic_pendulum

   !> A model that is a form of the elastic pendulum (hillstab_hill_model): the defaults are
   !> α = aπ²/ρ, no note, not the pendulum itself.
   type, abstract, extends(hill_model_t) :: pendulum_model_t
   contains
      !> the model's α of a pendulum in physical units
      procedure :: physical_alpha => pendulum_model_alpha
      !> what that α means, for headers ("" when it is aπ²/ρ)
      procedure :: physical_note => no_physical_note
      !> the model is the elastic pendulum itself (physical domain, nonlinear simulation)
      procedure :: is_pendulum => not_the_pendulum
   end type pendulum_model_t

contains

   !> α = aπ²/ρ, eq. (24).
   elemental real(wp) function pendulum_model_alpha(self, p) result(alpha)
      class(pendulum_model_t), intent(in) :: self  !! the model
      type(physical_t), intent(in) :: p            !! the pendulum (ω > 0, ρ > 0)
      alpha = physical_alpha(p)
   end function pendulum_model_alpha

   !> "": α is aπ²/ρ.
   pure function no_physical_note(self) result(text)
      class(pendulum_model_t), intent(in) :: self  !! the model
      character(len=:), allocatable :: text
      text = ""
   end function no_physical_note

   !> Not the elastic pendulum itself unless the model says so.
   elemental logical function not_the_pendulum(self)
      class(pendulum_model_t), intent(in) :: self  !! the model
      not_the_pendulum = .false.
   end function not_the_pendulum

   !> The α of any model for a pendulum given in physical units: the model's own when it is a
   !> form of the pendulum, aπ²/ρ (eq. (24)) otherwise.
   pure real(wp) function pendulum_alpha(model, p) result(alpha)
      class(hill_model_t), intent(in) :: model  !! the model
      type(physical_t), intent(in) :: p         !! the pendulum (ω > 0, ρ > 0)
      select type (model)
      class is (pendulum_model_t)
         alpha = model%physical_alpha(p)
      class default
         alpha = physical_alpha(p)
      end select
   end function pendulum_alpha

   !> What α from physical units means for any model, for headers ("" when it is aπ²/ρ).
   pure function pendulum_note(model) result(text)
      class(hill_model_t), intent(in) :: model  !! the model
      character(len=:), allocatable :: text
      select type (model)
      class is (pendulum_model_t)
         text = model%physical_note()
      class default
         text = ""
      end select
   end function pendulum_note

   !> Whether any model is the elastic pendulum itself: its physical domain (a `physical`
   !> column), its nonlinear simulation and α = aπ²/ρ.
   pure logical function is_elastic_pendulum(model) result(is_it)
      class(hill_model_t), intent(in) :: model  !! the model
      select type (model)
      class is (pendulum_model_t)
         is_it = model%is_pendulum()
      class default
         is_it = .false.
      end select
   end function is_elastic_pendulum

end module hillstab_hill_model_pendulum

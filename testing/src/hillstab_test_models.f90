!> The models of the registry by their codes, for the suites that loop over models or read
!> a model code from a reference table: one instance of each, made on first use and kept,
!> handed out as pointers (no copies of polymorphic values, nothing to free). The models
!> that carry data get a fixed example: the fourier model f = 0.5 cos πτ + 0.25 cos 3πτ +
!> 0.3 sin 2πτ (not even: sine terms), the sampled model 12 samples of cos πτ − 0.4 sin 2πτ,
!> the equation 1.5 x'' + (b − a cos πt + 0.3 a sin 2πt) x = 0 (Ω = π, axes a and b).
module hillstab_test_models
   use hillstab_hill_model, only: hill_model_t
   use hillstab_hill_models, only: model_from_code, model_count
   use hillstab_core_kinds, only: wp, pi
   use hillstab_core_error, only: error_t
   implicit none
   private
   public :: model_of_code

   !> One registered model.
   type :: kept_model_t
      class(hill_model_t), allocatable :: model
   end type kept_model_t

   type(kept_model_t), target, save :: kept(model_count)

contains

   !> The model of a registry code (1 elastic, 2 Mathieu, …); null for an unknown code.
   function model_of_code(code) result(model)
      integer, intent(in) :: code  !! the registry's code
      class(hill_model_t), pointer :: model
      type(error_t), allocatable :: error
      model => null()
      if (code < 1 .or. code > model_count) return
      if (.not. allocated(kept(code)%model)) then
         call model_from_code(code, kept(code)%model, error)
         call example_data(kept(code)%model)
      end if
      model => kept(code)%model
   end function model_of_code
   !> The example data of a model that carries data (see the module doc).
   subroutine example_data(model)
      class(hill_model_t), intent(inout) :: model  !! a model of the registry
      type(error_t), allocatable :: error
      real(wp) :: samples(12)
      integer :: j
      select case (model%name())
      case ("fourier")
         call model%set_values("cos", [0.5_wp, 0.0_wp, 0.25_wp], error)
         call model%set_values("sin", [0.0_wp, 0.3_wp], error)
      case ("sampled")
         do j = 0, 11
            samples(j + 1) = cos(pi*j/6.0_wp) - 0.4_wp*sin(2.0_wp*pi*j/6.0_wp)
         end do
         call model%set_values("samples", samples, error)
      case ("equation")
         call model%set_text("parameters", "a = 1, b = 1", error)
         call model%set_text("stiffness", "b - a*cos(pi*t) + 0.3*a*sin(2*pi*t)", error)
         call model%set_text("mass", "1.5", error)
         call model%set_text("frequency", "pi", error)
         call model%set_text("alpha", "a", error)
         call model%set_text("beta", "b", error)
      end select
   end subroutine example_data
end module hillstab_test_models

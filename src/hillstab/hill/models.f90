!> The models of Q a scene, a C program or a FORTRAN 77 program can name, in one place:
!> each registered model has a name, a code (its row: the C API's HILLSTAB_MODEL_* and the
!> F77 MODEL codes, which test suite codes checks against this table) and a module whose
!> type extends `hill_model_t` (hillstab_hill_model). A new model is its module plus one
!> row here (its name in `model_names` and its `case` in `new_model`); the scene reader,
!> the templates, the C and F77 entry points and the docs' list of models find it here.
!>
!> Models:
!> - `elastic` (1): Q(τ) = (β − α cos πτ)/(1 − (α/π²) cos πτ), paper eq. (25);
!> - `mathieu` (2): q(τ) = β − α cos πτ, the paper's Mathieu form (A1) with α playing ν;
!> - `meissner` (3): Q(τ) = β ± α on the two halves of the period, Meissner's square wave;
!> - `fourier` (4): Q(τ) = β + α f(τ), f a Fourier series given in the scene (`&fourier`);
!> - `sampled` (5): Q(τ) = β + α f(τ), f interpolating samples of one period (`&sampled`);
!> - `modulated` (6): Q(τ) = (β + k m'')/(1 − k m), m = cos πτ cos(πτ/2), the swing about the
!>   modulated bounce r = ρ − a cos ωt cos(ωt/2);
!> - `equation` (7): m x'' + c x' + k(t) x = 0 in physical time with named parameters
!>   (`&equation`), any two of them the chart's axes.
!>
!>```fortran
!> class(hill_model_t), allocatable :: model
!> type(error_t), allocatable :: error
!> call new_model("mathieu", model, error)
!> print *, model_description(model)
!>```
module hillstab_hill_models
   use hillstab_core_error, only: error_t, set_error, err_invalid_parameter
   use hillstab_core_text, only: name_position, alternatives_text, integer_text
   use hillstab_hill_model, only: hill_model_t
   use hillstab_hill_model_elastic, only: elastic_model_t
   use hillstab_hill_model_mathieu, only: mathieu_model_t
   use hillstab_hill_model_meissner, only: meissner_model_t
   use hillstab_hill_model_fourier, only: fourier_model_t
   use hillstab_hill_model_sampled, only: sampled_model_t
   use hillstab_hill_model_modulated, only: modulated_model_t
   use hillstab_hill_model_equation, only: equation_model_t
   implicit none
   private
   public :: model_names, model_count, new_model, model_from_code, model_code, model_names_text

   !> The registered models' names, in the order of their codes (code = position).
   character(len=*), parameter :: model_names(7) = [character(len=16) :: "elastic", "mathieu", "meissner", "fourier", &
      "sampled", "modulated", "equation"]
   !> Number of models; their codes are 1 … model_count.
   integer, parameter :: model_count = size(model_names)

contains

   !> A model of the given name (any case, blanks trimmed), with its data at their defaults;
   !> err_invalid_parameter naming the known models when there is none.
   subroutine new_model(name, model, error)
      character(len=*), intent(in) :: name  !! a model name
      class(hill_model_t), allocatable, intent(out) :: model  !! the model
      type(error_t), allocatable, intent(out) :: error  !! unknown name
      integer :: code
      code = name_position(name, model_names)
      if (code == 0) then
         call set_error(error, err_invalid_parameter, "unknown model '"//trim(adjustl(name))//"' (expected "// &
            model_names_text()//")")
         return
      end if
      call model_from_code(code, model, error)
   end subroutine new_model

   !> The model of a code (the C API's HILLSTAB_MODEL_*, the F77 MODEL codes);
   !> err_invalid_parameter for any other code.
   subroutine model_from_code(code, model, error)
      integer, intent(in) :: code  !! 1 … model_count
      class(hill_model_t), allocatable, intent(out) :: model  !! the model
      type(error_t), allocatable, intent(out) :: error  !! unknown code
      select case (code)
      case (1); allocate (model, source=elastic_model_t())
      case (2); allocate (model, source=mathieu_model_t())
      case (3); allocate (model, source=meissner_model_t())
      case (4); allocate (model, source=fourier_model_t())
      case (5); allocate (model, source=sampled_model_t())
      case (6); allocate (model, source=modulated_model_t())
      case (7); allocate (model, source=equation_model_t())
      case default
         call set_error(error, err_invalid_parameter, "unknown model code "//integer_text(code)//" (expected 1 to "// &
            integer_text(model_count)//")")
      end select
   end subroutine model_from_code

   !> The code of a model (its row), 0 for a model not registered here.
   pure integer function model_code(model) result(code)
      class(hill_model_t), intent(in) :: model  !! a model
      code = name_position(model%name(), model_names)
   end function model_code

   !> The model names as a choice for messages: "elastic or mathieu".
   pure function model_names_text() result(text)
      character(len=:), allocatable :: text
      text = alternatives_text(model_names)
   end function model_names_text
end module hillstab_hill_models

!> The models of the registry by their codes, for the suites that loop over models or read
!> a model code from a reference table: one instance of each, made on first use and kept,
!> handed out as pointers (no copies of polymorphic values, nothing to free).
module hillstab_test_models
   use hillstab_hill_model, only: hill_model_t
   use hillstab_hill_models, only: model_from_code, model_count
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
      if (.not. allocated(kept(code)%model)) call model_from_code(code, kept(code)%model, error)
      model => kept(code)%model
   end function model_of_code
end module hillstab_test_models

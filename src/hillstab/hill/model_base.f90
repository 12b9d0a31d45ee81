!> What every model object shares, scalar (`hill_model_t`, one Hill equation) or system
!> (`hill_system_t`, n coupled ones): its name and formula as headers state them, and the
!> variables that a model carrying data takes from its scene group `&<name>`, from the C API
!> or from Python (`variables`, `set_values`, `check_values`). The scene reader's group of a
!> model (hillstab_batch_scene_group_model) reads any `model_base_t` from these bindings
!> alone.
!>
!>```fortran
!> class(model_base_t), allocatable :: model
!> print '(a)', model%name()//": "//model%formula()
!>```
module hillstab_hill_model_base
   use hillstab_core_kinds, only: wp
   use hillstab_core_error, only: error_t, set_error, err_invalid_parameter
   implicit none
   private
   public :: model_base_t, model_variable_t, model_variable_real, model_variable_list, model_variable_file, &
      model_variable_text

   !> A model variable holding one number.
   integer, parameter :: model_variable_real = 1
   !> A model variable holding a list of numbers (up to `max_count`).
   integer, parameter :: model_variable_list = 2
   !> A model variable naming a file of numbers (one or more per line, `#` comments), read by
   !> the scene reader and handed to the model as the list of its numbers, row by row.
   integer, parameter :: model_variable_file = 3
   !> A model variable holding a text (an expression, a list of named parameters), quoted in
   !> a scene, handed to the model by `set_text`.
   integer, parameter :: model_variable_text = 4

   !> One variable of a model that carries data (Fourier coefficients, samples, matrices): what
   !> its scene group (named after the model), its template and the C API's
   !> `hillstab_model_set` know of it.
   type :: model_variable_t
      character(len=32) :: name = ""                !! the variable's name
      integer :: kind = model_variable_list          !! model_variable_real, _list or _file
      integer :: max_count = 1                       !! most numbers it takes
      character(len=64) :: default = ""             !! its default as scene text ("" = none)
      character(len=240) :: help = ""               !! what it means, for templates and docs
      logical :: whole = .false.                     !! a whole number (a count): echoed without a decimal point
   end type model_variable_t

   !> A model object: a name, a formula and, for a model that carries data, its variables.
   type, abstract :: model_base_t
   contains
      !> the name a scene gives in `&scene model` (lower case)
      procedure(base_text), deferred :: name
      !> the coefficient as output headers state it, after "model: <name>, "
      procedure(base_text), deferred :: formula
      procedure :: variables => no_variables
      procedure :: set_values => no_values
      procedure :: set_text => no_text
      procedure :: check_values => values_complete
      procedure :: axis_name => greek_axis_name
   end type model_base_t

   abstract interface
      !> A text of the model.
      pure function base_text(self) result(text)
         import :: model_base_t
         class(model_base_t), intent(in) :: self  !! the model
         character(len=:), allocatable :: text
      end function base_text
   end interface

contains

   !> The variables of a model that carries data: none unless the model has them.
   pure function no_variables(self) result(variables)
      class(model_base_t), intent(in) :: self  !! the model
      type(model_variable_t), allocatable :: variables(:)
      allocate (variables(0))
   end function no_variables

   !> Set a variable of the model (`variables`) to the given numbers: err_invalid_parameter
   !> unless the model has such a variable.
   pure subroutine no_values(self, name, values, error)
      class(model_base_t), intent(inout) :: self  !! the model
      character(len=*), intent(in) :: name        !! the variable
      real(wp), intent(in) :: values(:)           !! its numbers
      !> err_invalid_parameter naming the model and the variable; unallocated when set
      type(error_t), allocatable, intent(out) :: error
      call set_error(error, err_invalid_parameter, "the "//self%name()//" model has no variable '"//trim(name)//"'")
   end subroutine no_values

   !> Set a text variable of the model (`model_variable_text`): err_invalid_parameter unless
   !> the model has such a variable.
   pure subroutine no_text(self, name, text, error)
      class(model_base_t), intent(inout) :: self  !! the model
      character(len=*), intent(in) :: name        !! the variable
      character(len=*), intent(in) :: text        !! its text, unquoted
      !> err_invalid_parameter naming the model and the variable; unallocated when set
      type(error_t), allocatable, intent(out) :: error
      call set_error(error, err_invalid_parameter, "the "//self%name()//" model has no text variable '"// &
         trim(name)//"'")
   end subroutine no_text

   !> The name of the chart's axis k (1: α, the rows; 2: β) as files name its column:
   !> "alpha" and "beta" unless the model's axes are parameters of its own.
   pure function greek_axis_name(self, k) result(name)
      class(model_base_t), intent(in) :: self  !! the model
      integer, intent(in) :: k                 !! 1 or 2
      character(len=:), allocatable :: name
      name = trim(merge("alpha", "beta ", k == 1))
   end function greek_axis_name

   !> After its variables are set: whether the model is complete and consistent (every
   !> model without variables is).
   pure subroutine values_complete(self, error)
      class(model_base_t), intent(in) :: self  !! the model
      !> err_invalid_parameter naming what is missing or wrong; unallocated when complete
      type(error_t), allocatable, intent(out) :: error
   end subroutine values_complete
end module hillstab_hill_model_base

!> Error reporting for library code: procedures never stop the program, they
!> allocate an `error_t` with a code and a message and return.
!>
!>```fortran
!> type(error_t), allocatable :: error
!> call check_model(model, error)
!> if (allocated(error)) print '(a)', error%message
!>```
module hillstab_core_error
   implicit none
   private
   public :: error_t, set_error, error_code_name
   public :: err_invalid_parameter, err_overflow, err_integration, err_io, err_input, err_singular, err_accuracy, &
      err_points_failed

   !> A parameter is outside the domain where the quantity is defined.
   integer, parameter :: err_invalid_parameter = 1
   !> A result does not fit in real(wp).
   integer, parameter :: err_overflow = 2
   !> A numerical integration failed (step underflow, too many steps, non-finite state).
   integer, parameter :: err_integration = 3
   !> A file could not be read or written.
   integer, parameter :: err_io = 4
   !> User input (scene, namelist, command line) is invalid.
   integer, parameter :: err_input = 5
   !> A linear-algebra problem is singular or did not converge.
   integer, parameter :: err_singular = 6
   !> The requested accuracy is below what double precision allows for this problem;
   !> the best value is returned with this error.
   integer, parameter :: err_accuracy = 7
   !> A task wrote its file, but some of its points could not be computed (they carry
   !> status_failed of hillstab_core_status); the message counts them and names the first.
   integer, parameter :: err_points_failed = 8

   !> Error descriptor: a code from the `err_*` constants and a readable message.
   type :: error_t
      integer :: code = 0               !! one of the err_* constants
      character(len=:), allocatable :: message  !! what went wrong, with the offending value
   end type error_t

contains

   !> Allocate `error` with `code` and `message`.
   pure subroutine set_error(error, code, message)
      type(error_t), allocatable, intent(out) :: error  !! the error to create
      integer, intent(in) :: code                        !! one of the err_* constants
      character(len=*), intent(in) :: message            !! what went wrong
      allocate (error)
      error%code = code
      error%message = message
   end subroutine set_error

   !> Short name of an error code, for messages.
   pure function error_code_name(code) result(name)
      integer, intent(in) :: code  !! one of the err_* constants
      character(len=:), allocatable :: name
      select case (code)
      case (err_invalid_parameter); name = "invalid parameter"
      case (err_overflow); name = "overflow"
      case (err_integration); name = "integration failure"
      case (err_io); name = "i/o error"
      case (err_input); name = "invalid input"
      case (err_singular); name = "singular problem"
      case (err_accuracy); name = "accuracy not reached"
      case (err_points_failed); name = "some points failed"
      case default; name = "error"
      end select
   end function error_code_name
end module hillstab_core_error

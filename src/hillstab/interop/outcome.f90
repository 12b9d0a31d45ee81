!> The outcome of the most recent call of a C or old-style entry point, kept per
!> thread, so that callers without an `error_t` (C, FORTRAN 77) can read the same
!> message a Fortran caller gets (`hillstab_last_error` in C, `HSERRM` in Fortran).
!>
!> The storage is OpenMP `threadprivate`, which gfortran keeps in thread-local
!> storage: threads made by OpenMP, by POSIX threads or by any other runtime each
!> see the outcome of their own last call.
!>
!>```fortran
!> call record_outcome(error)   ! at the end of every entry point
!> call get_last_error(code, text)
!>```
module hillstab_interop_outcome
   use hillstab_core_error, only: error_t
   implicit none
   private
   public :: record_outcome, get_last_error, last_error_length

   !> Longest message kept; longer messages are cut.
   integer, parameter :: last_error_length = 1024

   integer, save :: code = 0
   integer, save :: length = 0
   character(len=last_error_length), save :: message = ""
   !$omp threadprivate(code, length, message)

contains

   !> Keep the outcome of an entry point call in this thread: the code and message of
   !> `error` when it is allocated, success (code 0, empty message) otherwise.
   subroutine record_outcome(error)
      type(error_t), allocatable, intent(in) :: error  !! the call's error, unallocated on success
      if (allocated(error)) then
         code = error%code
         length = 0
         if (allocated(error%message)) then
            length = min(len(error%message), last_error_length)
            message = error%message(1:length)
         end if
      else
         code = 0
         length = 0
         message = ""
      end if
   end subroutine record_outcome

   !> Code and message of the most recent entry point call in this thread (0 and ""
   !> when it succeeded).
   subroutine get_last_error(error_code, error_message)
      integer, intent(out) :: error_code                              !! the call's error code
      character(len=:), allocatable, intent(out) :: error_message     !! its message
      error_code = code
      error_message = message(1:length)
   end subroutine get_last_error
end module hillstab_interop_outcome

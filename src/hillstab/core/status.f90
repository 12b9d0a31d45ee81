!> Per-point status codes written in the `status` column of every output with a value
!> per point (chart, points, boundaries, series summaries, Lyapunov maps), and the exit
!> status of a run that completed with some failed points.
!>
!>```fortran
!> use hillstab_core_status
!> print '(i0, 1x, a)', status_roundoff, status_name(status_roundoff)
!>```
module hillstab_core_status
   implicit none
   private
   public :: status_ok, status_roundoff, status_failed, status_name, exit_points_failed

   !> The value meets the requested tolerance.
   integer, parameter :: status_ok = 0
   !> The tolerance lies below what double precision allows at this point: the value is
   !> the best one available and the error column holds its estimated error.
   integer, parameter :: status_roundoff = 1
   !> No value could be computed at this point: its numeric columns are placeholders.
   integer, parameter :: status_failed = 2
   !> Exit status of a run that wrote its file but in which some points failed.
   integer, parameter :: exit_points_failed = 3

contains

   !> Short name of a status code, for headers and messages.
   pure function status_name(status) result(name)
      integer, intent(in) :: status  !! one of the status_* constants
      character(len=:), allocatable :: name
      select case (status)
      case (status_ok); name = "ok"
      case (status_roundoff); name = "round-off limited"
      case (status_failed); name = "failed"
      case default; name = "unknown"
      end select
   end function status_name
end module hillstab_core_status

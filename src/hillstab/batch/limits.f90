!> Resource limits checked before any work: the estimated size of a task's output file
!> against the free space of the file system that will hold it (statvfs), so that a
!> chart of 10^10 points is refused at once, naming the scene variables, instead of
!> filling the disk for hours.
!>
!>```fortran
!> call check_output_room(scene, output_path, error)
!>```
module hillstab_batch_limits
   use hillstab_core_kinds, only: wp, int64
   use hillstab_core_error, only: error_t, set_error, err_input
   use hillstab_batch_scene, only: scene_t
   use hillstab_ffi_libc, only: statvfs_t, c_statvfs, c_string
   implicit none
   private
   public :: check_output_room, free_bytes

contains

   !> Bytes available to this process on the file system holding `path` (a file that
   !> may not exist yet: its directory is asked); `known` false when that fails.
   subroutine free_bytes(path, bytes, known)
      character(len=*), intent(in) :: path  !! a file path
      integer(int64), intent(out) :: bytes  !! free bytes (0 when unknown)
      logical, intent(out) :: known         !! statvfs succeeded
      type(statvfs_t) :: info
      character(len=:), allocatable :: dir
      integer :: slash
      slash = index(path, "/", back=.true.)
      if (slash == 0) then
         dir = "."
      else if (slash == 1) then
         dir = "/"
      else
         dir = path(:slash - 1)
      end if
      bytes = 0
      known = c_statvfs(c_string(dir), info) == 0
      if (known) bytes = int(info%bavail, int64)*int(info%frsize, int64)
   end subroutine free_bytes

   !> Refuse a scene whose output would not fit in the free space where it goes, naming the
   !> variables that set its size.
   subroutine check_output_room(scene, path, error)
      type(scene_t), intent(in) :: scene  !! a validated scene
      character(len=*), intent(in) :: path  !! its output file
      type(error_t), allocatable, intent(out) :: error  !! err_input when it would not fit
      integer(int64) :: need, free
      logical :: known
      need = scene%task%estimated_bytes(scene)
      if (need == 0) return
      call free_bytes(path, free, known)
      if (.not. known .or. need <= free) return
      call set_error(error, err_input, scene%source//": "//scene%task%size_variables()//" would write about "// &
         size_text(need)//" to '"//path//"', more than the "//size_text(free)//" free there")
   end subroutine check_output_room

   !> Bytes as "12 MB" style text (decimal units).
   pure function size_text(bytes) result(text)
      integer(int64), intent(in) :: bytes
      character(len=:), allocatable :: text
      character(len=*), parameter :: units(5) = ["B ", "kB", "MB", "GB", "TB"]
      real(wp) :: x
      integer :: k
      character(len=24) :: buffer
      x = real(bytes, wp)
      k = 1
      do while (x >= 1000.0_wp .and. k < size(units))
         x = x/1000.0_wp
         k = k + 1
      end do
      write (buffer, '(f0.1)') x
      text = trim(buffer)//" "//trim(units(k))
   end function size_text
end module hillstab_batch_limits

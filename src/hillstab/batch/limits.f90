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
   use hillstab_batch_scene, only: scene_t, task_chart, task_points, task_coefficient, task_lyapunov
   use hillstab_core_text, only: integer_text
   use, intrinsic :: iso_c_binding, only: c_int, c_long, c_char, c_null_char
   implicit none
   private
   public :: check_output_room, free_bytes, estimated_output_bytes

   !> Bytes of one chart or points row written as text (an upper bound) and as binary.
   integer(int64), parameter :: text_row_bytes = 161, binary_row_bytes = 8*16
   !> Bytes of a header (an upper bound).
   integer(int64), parameter :: header_bytes = 16384

   !> struct statvfs on 64-bit Linux.
   type, bind(C) :: statvfs_t
      integer(c_long) :: bsize, frsize, blocks, bfree, bavail, files, ffree, favail, fsid, flag, namemax
      integer(c_int) :: spare(6)
   end type statvfs_t

   interface
      function c_statvfs(path, info) bind(C, name="statvfs") result(status)
         import :: c_char, c_int, statvfs_t
         character(kind=c_char), intent(in) :: path(*)
         type(statvfs_t), intent(out) :: info
         integer(c_int) :: status
      end function c_statvfs
   end interface

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
      known = c_statvfs(dir//c_null_char, info) == 0
      if (known) bytes = int(info%bavail, int64)*int(info%frsize, int64)
   end subroutine free_bytes

   !> An upper estimate of the bytes a scene's output file takes (0 for tasks not estimated
   !> here: they bound their own output).
   pure function estimated_output_bytes(scene) result(bytes)
      type(scene_t), intent(in) :: scene  !! a validated scene
      integer(int64) :: bytes
      integer(int64) :: row
      row = merge(binary_row_bytes, text_row_bytes, scene%binary)
      select case (scene%task)
      case (task_chart, task_lyapunov)
         bytes = header_bytes + int(scene%chart%n_alpha, int64)*int(scene%chart%n_beta, int64)*row + &
                 int(scene%chart%n_alpha, int64)
      case (task_points)
         bytes = 0
         if (allocated(scene%points)) bytes = header_bytes + int(size(scene%points, 2), int64)*row
      case (task_coefficient)
         bytes = header_bytes + int(scene%coefficient%n_tau, int64)*25_int64* &
                 (1_int64 + 2_int64*size(scene%coefficient%alphas))
      case default
         bytes = 0
      end select
   end function estimated_output_bytes

   !> Refuse a scene whose output would not fit in the free space where it goes, naming the
   !> variables that set its size.
   subroutine check_output_room(scene, path, error)
      type(scene_t), intent(in) :: scene  !! a validated scene
      character(len=*), intent(in) :: path  !! its output file
      type(error_t), allocatable, intent(out) :: error  !! err_input when it would not fit
      integer(int64) :: need, free
      logical :: known
      character(len=:), allocatable :: where
      need = estimated_output_bytes(scene)
      if (need == 0) return
      call free_bytes(path, free, known)
      if (.not. known .or. need <= free) return
      select case (scene%task)
      case (task_chart, task_lyapunov)
         where = "&chart: n_alpha, n_beta: "//integer_text(scene%chart%n_alpha)//" x "// &
                 integer_text(scene%chart%n_beta)//" points"
      case (task_points)
         where = "&points: file: "//integer_text(size(scene%points, 2))//" points"
      case default
         where = "&coefficient: n_tau: "//integer_text(scene%coefficient%n_tau)//" rows"
      end select
      call set_error(error, err_input, scene%source//": "//where//" would write about "//size_text(need)// &
         " to '"//path//"', more than the "//size_text(free)//" free there")
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

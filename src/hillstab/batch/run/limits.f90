!> Resource limits checked before any work: the estimated size of a task's output file
!> against the free space of the file system that will hold it (statvfs), so that a
!> chart of 10^10 points is refused at once, naming the scene variables, instead of
!> filling the disk for hours; and the memory its buffers need against what the process
!> may still take (its address-space limit, RLIMIT_AS, less what it holds) and what the
!> machine has (MemAvailable plus free swap), so that a scene that would fail to allocate
!> is refused with a message instead of aborting.
!>
!>```fortran
!> call check_output_room(scene, output_path, error)
!>```
module hillstab_batch_run_limits
   use hillstab_core_kinds, only: wp, int64
   use hillstab_core_error, only: error_t, set_error, err_input
   use hillstab_batch_scene_types, only: scene_t
   use hillstab_ffi_libc, only: statvfs_t, c_statvfs, c_string, c_getrlimit, rlimit_t, rlimit_as, c_getpagesize
   use, intrinsic :: iso_c_binding, only: c_int
   implicit none
   private
   public :: check_output_room, free_bytes, check_memory_room, available_memory

   !> Needs below this are not checked (the program itself, its stack and libraries).
   integer(int64), parameter :: small_need = 64_int64*1024*1024

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

   !> Refuse a scene whose buffers would not fit in the memory the process may take.
   subroutine check_memory_room(scene, error)
      type(scene_t), intent(in) :: scene  !! a validated scene
      type(error_t), allocatable, intent(out) :: error  !! err_input when they would not fit
      integer(int64) :: need, free
      character(len=:), allocatable :: what
      need = scene%task%memory_bytes(scene)
      if (need < small_need) return
      call available_memory(free, what)
      if (free < 0 .or. need <= free) return
      call set_error(error, err_input, scene%source//": "//scene%task%size_variables()//" would need about "// &
         size_text(need)//" of memory, more than the "//size_text(free)//" "//what)
   end subroutine check_memory_room

   !> Bytes this process may still allocate: the smaller of what its address-space limit
   !> leaves (RLIMIT_AS less the current size, /proc/self/statm) and what the machine has
   !> (MemAvailable plus SwapFree, /proc/meminfo); −1 when neither is known. `what` says
   !> which bound it is.
   subroutine available_memory(bytes, what)
      integer(int64), intent(out) :: bytes  !! −1: unknown
      character(len=:), allocatable, intent(out) :: what  !! "the address-space limit leaves" ...
      type(rlimit_t) :: limit
      integer(int64) :: size_pages, machine, leaves
      integer :: unit, ios
      character(len=256) :: line
      bytes = -1
      what = ""
      machine = -1
      open (newunit=unit, file="/proc/meminfo", action="read", status="old", iostat=ios)
      if (ios == 0) then
         machine = 0
         do
            read (unit, '(a)', iostat=ios) line
            if (ios /= 0) exit
            if (index(line, "MemAvailable:") == 1 .or. index(line, "SwapFree:") == 1) &
               machine = machine + 1024*kilobytes(line)
         end do
         close (unit)
         if (machine > 0) then
            bytes = machine
            what = "available on this machine (MemAvailable + SwapFree)"
         end if
      end if
      if (c_getrlimit(rlimit_as, limit) == 0 .and. limit%cur > 0) then
         size_pages = 0
         open (newunit=unit, file="/proc/self/statm", action="read", status="old", iostat=ios)
         if (ios == 0) then
            read (unit, *, iostat=ios) size_pages
            close (unit)
         end if
         leaves = max(0_int64, int(limit%cur, int64) - size_pages*int(c_getpagesize(), int64))
         if (bytes < 0 .or. leaves < bytes) then
            bytes = leaves
            what = "that the address-space limit (ulimit -v) leaves this process"
         end if
      end if
   contains
      integer(int64) function kilobytes(text)
         character(len=*), intent(in) :: text
         integer :: colon, status
         colon = index(text, ":")
         read (text(colon + 1:), *, iostat=status) kilobytes
         if (status /= 0) kilobytes = 0
      end function kilobytes
   end subroutine available_memory

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
end module hillstab_batch_run_limits

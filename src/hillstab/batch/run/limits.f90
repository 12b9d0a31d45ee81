!> Resource limits checked before any work: the estimated size of a task's output file
!> against the free space of the file system that will hold it (statvfs), so that a
!> chart of 10^10 points is refused at once, naming the scene variables, instead of
!> filling the disk for hours; and the memory its buffers need against what the process
!> may still take (its address-space limit, RLIMIT_AS, less what it holds) and what the
!> machine has (MemAvailable plus free swap), so that a scene that would fail to allocate
!> is refused with a message instead of aborting. Every task estimates its memory
!> (hillstab_batch_scene_types `memory_bytes`); `check_start_memory` refuses at once,
!> before the first thread is made, a process whose address-space limit cannot hold what any
!> run needs (`run_margin`) and its threads' stacks.
!>
!>```fortran
!> call check_output_room(scene, output_path, error)
!>```
module hillstab_batch_run_limits
   use hillstab_core_kinds, only: wp, int64
   use hillstab_core_error, only: error_t, set_error, err_input
   use hillstab_batch_scene_types, only: scene_t
   use hillstab_ffi_libc, only: statvfs_t, c_statvfs, c_string, c_getrlimit, rlimit_t, rlimit_as, rlimit_stack, &
      c_getpagesize
   use hillstab_core_text, only: integer_text
   use, intrinsic :: iso_c_binding, only: c_int
   implicit none
   private
   public :: check_output_room, free_bytes, check_memory_room, available_memory, check_start_memory, size_text

   !> What any run needs after its start besides its threads' stacks: the runtime's buffers,
   !> the scene and its texts (measured: a 5 x 5 chart on one thread runs under `ulimit -v`
   !> 37 MB and fails under 36 MB; the program and its libraries hold 20.4 MB at its start).
   integer(int64), parameter :: run_margin = 16_int64*1024*1024
   !> Task estimates below this are not checked: the heap the run has taken by then holds
   !> that much to spare (the allocator asks for 16 MiB more at a time, hillstab_batch_run_cli).
   integer(int64), parameter :: small_need = 8_int64*1024*1024
   !> The stack of a thread when neither OMP_STACKSIZE nor a finite `ulimit -s` says (glibc's
   !> default on 64-bit Linux).
   integer(int64), parameter :: default_stack = 8_int64*1024*1024

contains

   !> Bytes available to this process on the file system holding `path` (a file that
   !> may not exist yet: its directory is asked); `known` false when that fails.
   subroutine free_bytes(path, bytes, known)
      character(len=*), intent(in) :: path  !! a file path
      integer(int64), intent(out) :: bytes  !! free bytes (0 when unknown)
      logical, intent(out) :: known         !! statvfs succeeded and the file system has blocks
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
      ! a file system of no blocks at all (/proc, /sys) says nothing of its room
      known = c_statvfs(c_string(dir), info) == 0
      if (known) known = info%blocks > 0
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
      ! (a file system that reports no blocks at all, /proc, /sys, says nothing of its room:
      ! the write itself will say what is wrong)
      if (.not. known .or. need <= free) return
      call set_error(error, err_input, scene%source//": "//scene%task%size_variables()//" would write about "// &
         size_text(need)//" to '"//path//"', more than the "//size_text(free)//" free there")
   end subroutine check_output_room

   !> Refuse a scene whose buffers (its task's estimate, `memory_bytes`) would not fit in the
   !> memory the process may take, naming the variables that set them.
   subroutine check_memory_room(scene, error)
      type(scene_t), intent(in) :: scene  !! a validated scene
      type(error_t), allocatable, intent(out) :: error  !! err_input when they would not fit
      integer(int64) :: need, free
      character(len=:), allocatable :: what
      need = scene%task%memory_bytes(scene)
      if (need < small_need) return
      call available_memory(free, what)
      if (free < 0 .or. need <= free) return
      call set_error(error, err_input, scene%source//": "//scene%task%memory_variables()//" would need about "// &
         size_text(need)//" of memory, more than the "//size_text(free)//" "//what)
   end subroutine check_memory_room

   !> Before the first thread is made: when the address-space limit (`ulimit -v`) leaves
   !> this process less than its threads' stacks and the margin of a run need, `message`
   !> says so (else it is empty): an OpenMP runtime that cannot make its threads stops the
   !> program with a line of its own.
   subroutine check_start_memory(threads, message)
      integer, intent(in) :: threads  !! the threads a run will make (besides the first)
      character(len=:), allocatable, intent(out) :: message  !! "" when the limit leaves enough
      integer(int64) :: free, need
      character(len=:), allocatable :: what
      message = ""
      call address_space_left(free)
      if (free < 0) return
      need = run_margin + int(max(threads, 0), int64)*thread_stack()
      if (need <= free) return
      message = "the address-space limit (ulimit -v) leaves this process "//size_text(free)//", less than the "// &
         "about "//size_text(need)//" a run needs (the runtime"
      if (threads > 0) then
         message = message//" and "//integer_text(threads)//" more threads' stacks of "//size_text(thread_stack())// &
            " each): raise the limit, or set OMP_NUM_THREADS=1"
      else
         message = message//"): raise the limit"
      end if
   end subroutine check_start_memory

   !> The stack of a new thread: OMP_STACKSIZE (a number with B, K, M or G; K when none),
   !> else the soft `ulimit -s`, else glibc's default.
   function thread_stack() result(bytes)
      integer(int64) :: bytes
      type(rlimit_t) :: limit
      character(len=32) :: text
      integer :: length, status, ios
      integer(int64) :: scale, value
      bytes = default_stack
      call get_environment_variable("OMP_STACKSIZE", text, length, status)
      if (status == 0 .and. length > 0) then
         text = adjustl(text(:length))
         length = len_trim(text)
         scale = 1024
         select case (text(length:length))
         case ("B", "b")
            scale = 1
         case ("K", "k")
            scale = 1024
         case ("M", "m")
            scale = 1024**2
         case ("G", "g")
            scale = 1024**3
         end select
         if (verify(text(length:length), "0123456789") /= 0) length = length - 1
         read (text(:length), *, iostat=ios) value
         if (ios == 0 .and. length > 0 .and. value > 0) then
            bytes = value*scale
            return
         end if
      end if
      if (c_getrlimit(rlimit_stack, limit) == 0 .and. limit%cur > 0) bytes = int(limit%cur, int64)
   end function thread_stack

   !> What the address-space limit leaves this process (−1: no limit, or unknown).
   subroutine address_space_left(bytes)
      integer(int64), intent(out) :: bytes
      type(rlimit_t) :: limit
      integer(int64) :: size_pages
      integer :: unit, ios
      bytes = -1
      if (c_getrlimit(rlimit_as, limit) /= 0 .or. limit%cur <= 0) return
      size_pages = 0
      open (newunit=unit, file="/proc/self/statm", action="read", status="old", iostat=ios)
      if (ios == 0) then
         read (unit, *, iostat=ios) size_pages
         close (unit)
      end if
      bytes = max(0_int64, int(limit%cur, int64) - size_pages*int(c_getpagesize(), int64))
   end subroutine address_space_left

   !> Bytes this process may still allocate: the smaller of what its address-space limit
   !> leaves (RLIMIT_AS less the current size, /proc/self/statm) and what the machine has
   !> (MemAvailable plus SwapFree, /proc/meminfo); −1 when neither is known. `what` says
   !> which bound it is.
   subroutine available_memory(bytes, what)
      integer(int64), intent(out) :: bytes  !! −1: unknown
      character(len=:), allocatable, intent(out) :: what  !! "the address-space limit leaves" ...
      integer(int64) :: machine, leaves
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
      call address_space_left(leaves)
      if (leaves >= 0) then
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

   !> Bytes as "12.0 MB" style text (decimal units; "0 B", "512 B" below a kilobyte).
   pure function size_text(bytes) result(text)
      integer(int64), intent(in) :: bytes  !! a size
      character(len=:), allocatable :: text
      character(len=*), parameter :: units(5) = ["B ", "kB", "MB", "GB", "TB"]
      real(wp) :: x
      integer :: k
      character(len=24) :: buffer
      if (bytes < 1000) then
         write (buffer, '(i0)') bytes
         text = trim(buffer)//" B"
         return
      end if
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

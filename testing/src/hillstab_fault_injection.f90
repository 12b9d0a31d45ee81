!> Fault injection for tests: a file-size limit on the test process (RLIMIT_FSIZE with
!> SIGXFSZ ignored), under which a write that crosses the limit fails with EFBIG the
!> way a write to a full file system fails with ENOSPC. Every task's writer is tested
!> with it (`check_writer_under_limit`): the run must fail with an i/o error naming the
!> output path and the cause, keep the old file, and leave no temporary file.
!>
!>```fortran
!> call limit_file_size(4096_int64)
!> call run_scene_file(path, .true., error)
!> call lift_file_size_limit()
!>```
module hillstab_fault_injection
   use hillstab_core_kinds, only: int64
   use hillstab_core_error, only: error_t, err_io
   use hillstab_batch_run_scenes, only: run_scene_file
   use hillstab_testing, only: test_context_t, check
   use hillstab_test_scratch, only: write_file, any_temp_file
   use, intrinsic :: iso_c_binding, only: c_int, c_long, c_funptr, c_intptr_t, c_null_funptr
   implicit none
   private
   public :: limit_file_size, lift_file_size_limit, check_writer_under_limit, limit_address_space, &
      lift_address_space_limit
   integer(c_int), parameter :: rlimit_as = 9     ! RLIMIT_AS (Linux)

   integer(c_int), parameter :: rlimit_fsize = 1  ! RLIMIT_FSIZE (Linux)
   integer(c_int), parameter :: sigxfsz = 25      ! SIGXFSZ (Linux)

   type, bind(C) :: rlimit_t
      integer(c_long) :: current
      integer(c_long) :: maximum
   end type rlimit_t

   type(rlimit_t), save :: saved_limit
   type(rlimit_t), save :: saved_as
   type(c_funptr), save :: saved_handler = c_null_funptr
   logical, save :: active = .false.

   interface
      function c_getrlimit(resource, limit) bind(C, name="getrlimit") result(status)
         import :: c_int, rlimit_t
         integer(c_int), value :: resource
         type(rlimit_t), intent(out) :: limit
         integer(c_int) :: status
      end function c_getrlimit
      function c_setrlimit(resource, limit) bind(C, name="setrlimit") result(status)
         import :: c_int, rlimit_t
         integer(c_int), value :: resource
         type(rlimit_t), intent(in) :: limit
         integer(c_int) :: status
      end function c_setrlimit
      function c_signal(signum, handler) bind(C, name="signal") result(previous)
         import :: c_int, c_funptr
         integer(c_int), value :: signum
         type(c_funptr), value :: handler
         type(c_funptr) :: previous
      end function c_signal
   end interface

contains

   !> Limit the address space of this process to its current size plus `extra` bytes
   !> (allocations beyond fail, as on a machine short of memory).
   subroutine limit_address_space(extra)
      integer(int64), intent(in) :: extra
      type(rlimit_t) :: limit
      integer(int64) :: pages
      integer :: unit, ios
      integer(c_int) :: status
      status = c_getrlimit(rlimit_as, saved_as)
      pages = 0
      open (newunit=unit, file="/proc/self/statm", action="read", status="old", iostat=ios)
      if (ios == 0) read (unit, *, iostat=ios) pages
      if (ios == 0) close (unit)
      limit%current = int(pages*4096_int64 + extra, c_long)
      limit%maximum = saved_as%maximum
      status = c_setrlimit(rlimit_as, limit)
   end subroutine limit_address_space

   !> Restore the address-space limit in place before `limit_address_space`.
   subroutine lift_address_space_limit()
      integer(c_int) :: status
      status = c_setrlimit(rlimit_as, saved_as)
   end subroutine lift_address_space_limit

   !> Limit the size of files this process writes to `bytes`; crossing it makes the
   !> write fail (EFBIG) instead of killing the process. Print nothing until lifted.
   subroutine limit_file_size(bytes)
      integer(int64), intent(in) :: bytes
      type(rlimit_t) :: limit
      type(c_funptr) :: ignore
      integer(c_int) :: status
      if (active) call lift_file_size_limit()
      status = c_getrlimit(rlimit_fsize, saved_limit)
      ignore = transfer(1_c_intptr_t, ignore)  ! SIG_IGN
      saved_handler = c_signal(sigxfsz, ignore)
      limit%current = int(bytes, c_long)
      limit%maximum = saved_limit%maximum
      status = c_setrlimit(rlimit_fsize, limit)
      active = .true.
   end subroutine limit_file_size

   !> Restore the limit and the SIGXFSZ handler in place before `limit_file_size`.
   subroutine lift_file_size_limit()
      integer(c_int) :: status
      type(c_funptr) :: previous
      if (.not. active) return
      status = c_setrlimit(rlimit_fsize, saved_limit)
      previous = c_signal(sigxfsz, saved_handler)
      active = .false.
   end subroutine lift_file_size_limit

   !> Run the scene file `scene` under a file-size limit of `bytes` (smaller than its output)
   !> and check that the writer of `output` fails cleanly: an i/o error naming `output`
   !> and the cause after the scene (`<scene>: &scene: output: `), `output` still holding its
   !> one line `sentinel`, no temporary file `output.part??????` left.
   subroutine check_writer_under_limit(ctx, scene, output, bytes)
      type(test_context_t), intent(inout) :: ctx
      character(len=*), intent(in) :: scene   !! scene file (written beforehand)
      character(len=*), intent(in) :: output  !! the path its task writes
      integer(int64), intent(in) :: bytes     !! the limit
      type(error_t), allocatable :: error
      character(len=64) :: line
      integer :: unit, ios
      call write_file(output, ["sentinel"])
      call limit_file_size(bytes)
      call run_scene_file(scene, .true., error)
      call lift_file_size_limit()
      call check(ctx, allocated(error), "a run over the file-size limit fails: "//output)
      if (allocated(error)) then
         call check(ctx, error%code == err_io, "i/o error code: "//error%message)
         call check(ctx, index(error%message, "'"//output//"'") > 0, "names the path: "//error%message)
         call check(ctx, index(error%message, scene//": &scene: output: ") == 1, "names the scene: "//error%message)
         call check(ctx, index(error%message, "File too large") > 0, "names the cause: "//error%message)
      end if
      open (newunit=unit, file=output, status="old", action="read", iostat=ios)
      call check(ctx, ios == 0, "the old file is still there: "//output)
      if (ios == 0) then
         read (unit, '(a)', iostat=ios) line
         call check(ctx, ios == 0 .and. line == "sentinel", "the old file is unchanged: "//output)
         read (unit, '(a)', iostat=ios) line
         call check(ctx, ios /= 0, "the old file has one line: "//output)
         close (unit, status="delete")
      end if
      call check(ctx, .not. any_temp_file(output), "no temporary file left: "//output)
   end subroutine check_writer_under_limit

end module hillstab_fault_injection

!> Test helper: run a scene with its progress reports captured. HILLSTAB_PROGRESS=always
!> makes every progress update a line on stderr; stderr (file descriptor 2) is pointed at a
!> scratch file for the run and restored after it; the lines starting "hillstab: " and
!> holding "% (" are the progress lines.
!>
!>```fortran
!> call run_with_progress(path, progress, error, written)
!>```
module hillstab_test_progress
   use hillstab_core_error, only: error_t
   use hillstab_batch_run_scenes, only: run_scene_file
   use hillstab_test_scratch, only: scratch_prefix, read_lines, delete_file
   use, intrinsic :: iso_fortran_env, only: error_unit
   use, intrinsic :: iso_c_binding, only: c_int, c_char, c_null_char
   implicit none
   private
   public :: run_with_progress, progress_numbers

   interface
      function c_dup(fd) bind(C, name="dup") result(copy)
         import :: c_int
         integer(c_int), value :: fd
         integer(c_int) :: copy
      end function c_dup
      function c_dup2(fd, target) bind(C, name="dup2") result(status)
         import :: c_int
         integer(c_int), value :: fd, target
         integer(c_int) :: status
      end function c_dup2
      function c_creat(path, mode) bind(C, name="creat") result(fd)
         import :: c_int, c_char
         character(kind=c_char), intent(in) :: path(*)
         integer(c_int), value :: mode
         integer(c_int) :: fd
      end function c_creat
      function c_close(fd) bind(C, name="close") result(status)
         import :: c_int
         integer(c_int), value :: fd
         integer(c_int) :: status
      end function c_close
      function c_setenv(name, value, overwrite) bind(C, name="setenv") result(status)
         import :: c_int, c_char
         character(kind=c_char), intent(in) :: name(*), value(*)
         integer(c_int), value :: overwrite
         integer(c_int) :: status
      end function c_setenv
      function c_unsetenv(name) bind(C, name="unsetenv") result(status)
         import :: c_int, c_char
         character(kind=c_char), intent(in) :: name(*)
         integer(c_int) :: status
      end function c_unsetenv
   end interface

contains

   !> Run the scene file `path` (not quiet) with HILLSTAB_PROGRESS=always and stderr in a
   !> scratch file; `progress` holds the progress lines written, in order.
   subroutine run_with_progress(path, progress, error, written)
      character(len=*), intent(in) :: path  !! the scene file
      character(len=1024), allocatable, intent(out) :: progress(:)  !! its progress lines
      type(error_t), allocatable, intent(out) :: error  !! the run's error
      character(len=:), allocatable, intent(out) :: written  !! the file written
      character(len=:), allocatable :: captured
      character(len=1024), allocatable :: lines(:)
      integer(c_int) :: saved, fd, status
      integer :: k, n
      captured = scratch_prefix("progress")//".err"
      status = c_setenv("HILLSTAB_PROGRESS"//c_null_char, "always"//c_null_char, 1_c_int)
      flush (error_unit)
      saved = c_dup(2_c_int)
      fd = c_creat(captured//c_null_char, int(o'600', c_int))
      status = c_dup2(fd, 2_c_int)
      status = c_close(fd)
      call run_scene_file(path, .false., error, written)
      flush (error_unit)
      status = c_dup2(saved, 2_c_int)
      status = c_close(saved)
      status = c_unsetenv("HILLSTAB_PROGRESS"//c_null_char)
      lines = read_lines(captured)
      call delete_file(captured)
      allocate (progress(size(lines)))
      n = 0
      do k = 1, size(lines)
         if (index(lines(k), "hillstab: ") == 1 .and. index(lines(k), "% (") > 0) then
            n = n + 1
            progress(n) = lines(k)
         end if
      end do
      progress = progress(:n)
   end subroutine run_with_progress

   !> The numbers of a progress line "hillstab: 42.0% (21 of 50 points, ...)": the percentage,
   !> done, total and what is counted (`ok` false when the line is not of that form).
   subroutine progress_numbers(line, percent, done, total, label, ok)
      character(len=*), intent(in) :: line  !! a progress line
      real, intent(out) :: percent  !! its percentage
      integer, intent(out) :: done, total  !! units done, of total
      character(len=:), allocatable, intent(out) :: label  !! what is counted ("points", "rows", ...)
      logical, intent(out) :: ok  !! the line has the form
      integer :: open_at, of_at, comma_at, ios, blank_at
      ok = .false.
      percent = 0.0; done = 0; total = 0; label = ""
      open_at = index(line, "% (")
      of_at = index(line, " of ")
      comma_at = index(line, ",")
      if (open_at == 0 .or. of_at < open_at .or. comma_at < of_at) return
      read (line(len("hillstab: ") + 1:open_at - 1), *, iostat=ios) percent
      if (ios /= 0) return
      read (line(open_at + 3:of_at - 1), *, iostat=ios) done
      if (ios /= 0) return
      blank_at = of_at + 3 + index(line(of_at + 4:comma_at - 1), " ")
      read (line(of_at + 4:blank_at - 1), *, iostat=ios) total
      if (ios /= 0) return
      label = line(blank_at + 1:comma_at - 1)
      ok = .true.
   end subroutine progress_numbers
end module hillstab_test_progress

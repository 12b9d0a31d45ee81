!> Scratch files of the tests: unique names under build/ for this process, writing and
!> reading text files line by line, a look for the output writer's temporary files, and
!> the hillstab program of the build under test.
module hillstab_test_scratch
   use hillstab_core_text, only: read_text_line
   use, intrinsic :: iso_c_binding, only: c_int
   implicit none
   private
   public :: scratch_prefix, write_file, read_lines, file_exists, delete_file, contains_text, padded, any_temp_file, &
      program_path
   public :: c_getpid

   interface
      function c_getpid() bind(C, name="getpid") result(pid)
         import :: c_int
         integer(c_int) :: pid
      end function c_getpid
   end interface

contains

   !> A unique scratch path prefix under build/ for this process and test.
   function scratch_prefix(name) result(prefix)
      character(len=*), intent(in) :: name
      character(len=:), allocatable :: prefix
      character(len=16) :: pid
      write (pid, '(i0)') c_getpid()
      prefix = "build/hillstab_test_"//trim(pid)//"_"//name
   end function scratch_prefix

   !> The hillstab program of this build: `<build>/app/hillstab` beside `<build>/test/…`.
   function program_path() result(path)
      character(len=:), allocatable :: path
      character(len=4096) :: self
      integer :: at
      call get_command_argument(0, self)
      at = index(self, "/test/", back=.true.)
      if (at == 0) then
         path = "hillstab"
      else
         path = self(:at)//"app/hillstab"
      end if
   end function program_path

   !> Whether a temporary file of the writer for `output` (`<output>.part??????`) exists.
   logical function any_temp_file(output)
      character(len=*), intent(in) :: output  !! the final name
      integer :: status
      call execute_command_line("set -- '"//output//"'.part??????; test -e ""$1""", exitstat=status)
      any_temp_file = status == 0
   end function any_temp_file

   subroutine write_file(path, lines)
      character(len=*), intent(in) :: path
      character(len=*), intent(in) :: lines(:)
      integer :: unit, k
      open (newunit=unit, file=path, status="replace", action="write")
      do k = 1, size(lines)
         write (unit, '(a)') trim(lines(k))
      end do
      close (unit)
   end subroutine write_file

   !> All lines of a text file (empty array when it does not exist).
   function read_lines(path) result(lines)
      character(len=*), intent(in) :: path
      character(len=1024), allocatable :: lines(:)
      character(len=1024), allocatable :: grown(:)
      character(len=:), allocatable :: line
      integer :: unit, ios, n
      allocate (lines(0))
      open (newunit=unit, file=path, status="old", action="read", iostat=ios)
      if (ios /= 0) return
      ! Capacity doubles, so reading n lines copies O(n) lines, not O(n**2).
      deallocate (lines)
      allocate (lines(64))
      n = 0
      do
         call read_text_line(unit, line, ios)
         if (ios /= 0) exit
         if (n == size(lines)) then
            allocate (grown(2*size(lines)))
            grown(1:n) = lines(1:n)
            call move_alloc(grown, lines)
         end if
         n = n + 1
         lines(n) = line
      end do
      close (unit)
      lines = lines(1:n)
   end function read_lines

   logical function file_exists(path)
      character(len=*), intent(in) :: path
      inquire (file=path, exist=file_exists)
   end function file_exists

   subroutine delete_file(path)
      character(len=*), intent(in) :: path
      integer :: unit, ios
      open (newunit=unit, file=path, status="old", iostat=ios)
      if (ios == 0) close (unit, status="delete")
   end subroutine delete_file

   !> A line padded to a fixed length, so that array constructors of lines built
   !> from variables have elements of equal length.
   pure function padded(text) result(line)
      character(len=*), intent(in) :: text
      character(len=240) :: line
      line = text
   end function padded

   logical function contains_text(text, part)
      character(len=*), intent(in) :: text, part
      contains_text = index(text, part) > 0
   end function contains_text
end module hillstab_test_scratch

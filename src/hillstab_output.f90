!> Gnuplot-ready output files: a `#` header, one `# columns:` line, numeric columns.
!>
!> Files appear complete or not at all: rows go to `<path>.part<pid>`, which is
!> renamed onto `<path>` only by `commit_output`, and only when every write, the
!> flush to the disk and the close succeeded; otherwise the temporary file is deleted,
!> `<path>` keeps what it had and the error names the path and the cause (a full file
!> system, a file-size limit). `discard_output` deletes the temporary file.
!> An existing file at `<path>` is never opened, so a failed run leaves it untouched.
!> Writes go through C stdio so that every failure is seen with its errno (gfortran's
!> buffered formatted writes can lose ENOSPC). While written, the temporary file is
!> registered with hillstab_signals for removal on an interrupt.
!> This module formats numbers and moves files; it knows nothing of integrators.
!>
!>```fortran
!> type(output_file_t) :: file
!> type(error_t), allocatable :: error
!> call open_output(file, "out/run_chart.dat", error)
!> call write_header(file, ["hillstab 0.1.0"], "alpha beta S", error)
!> call write_text(file, "1.0 2.0 3.0", error)
!> call commit_output(file, error)
!>```
module hillstab_output
   use hillstab_kinds, only: wp, int64
   use hillstab_error, only: error_t, set_error, err_io
   use hillstab_floquet, only: floquet_t, largest_multiplier_modulus
   use hillstab_format, only: put_es
   use hillstab_signals, only: watch_temp_file, forget_temp_file
   use, intrinsic :: iso_c_binding, only: c_int, c_char, c_null_char, c_ptr, c_null_ptr, c_associated, &
      c_size_t, c_f_pointer
   implicit none
   private
   public :: output_file_t, open_output, commit_output, discard_output, write_header, write_text
   public :: chart_columns, chart_line, failed_chart_line, chart_line_length, clamp_magnitude, log10_floor, &
      real_columns, failed_log10_abs_s
   public :: remove_file, is_directory

   !> Magnitudes beyond this are written as ±clamp_magnitude with the overflow flag set.
   real(wp), parameter :: clamp_magnitude = 1.0e300_wp
   !> log10|S| is written as at least this (only S = 0 exactly reaches it).
   real(wp), parameter :: log10_floor = -300.0_wp
   !> The `stable` column of a marginal point (|S| within its error bound of the threshold):
   !> neither 1 nor 0, half-way in a [0, 1] colour scale.
   character(len=*), parameter :: marginal_text = " 0.5"
   !> log10_abs_S of a failed point: below `log10_floor`, so never a value.
   real(wp), parameter :: failed_log10_abs_s = -999.0_wp
   !> Characters in one chart line (see `chart_line`).
   integer, parameter :: chart_line_length = 200

   !> An output file being written under a temporary name.
   type :: output_file_t
      type(c_ptr) :: stream = c_null_ptr             !! C stream of the temporary file
      character(len=:), allocatable :: path          !! final name
      character(len=:), allocatable :: temp_path     !! name while being written
      character(len=:), allocatable :: failure       !! first write failure (the file is then incomplete)
      integer(int64) :: bytes = 0                    !! bytes written so far
      integer :: slot = 0                            !! hillstab_signals handle
   end type output_file_t

   interface
      function c_rename(old, new) bind(C, name="rename") result(status)
         import :: c_int, c_char
         character(kind=c_char), intent(in) :: old(*), new(*)
         integer(c_int) :: status
      end function c_rename
      function c_remove(path) bind(C, name="remove") result(status)
         import :: c_int, c_char
         character(kind=c_char), intent(in) :: path(*)
         integer(c_int) :: status
      end function c_remove
      function c_getpid() bind(C, name="getpid") result(pid)
         import :: c_int
         integer(c_int) :: pid
      end function c_getpid
      function c_fopen(path, mode) bind(C, name="fopen") result(stream)
         import :: c_char, c_ptr
         character(kind=c_char), intent(in) :: path(*), mode(*)
         type(c_ptr) :: stream
      end function c_fopen
      function c_fwrite(buffer, size, count, stream) bind(C, name="fwrite") result(written)
         import :: c_char, c_size_t, c_ptr
         character(kind=c_char), intent(in) :: buffer(*)
         integer(c_size_t), value :: size, count
         type(c_ptr), value :: stream
         integer(c_size_t) :: written
      end function c_fwrite
      function c_fflush(stream) bind(C, name="fflush") result(status)
         import :: c_int, c_ptr
         type(c_ptr), value :: stream
         integer(c_int) :: status
      end function c_fflush
      function c_fclose(stream) bind(C, name="fclose") result(status)
         import :: c_int, c_ptr
         type(c_ptr), value :: stream
         integer(c_int) :: status
      end function c_fclose
      function c_fileno(stream) bind(C, name="fileno") result(fd)
         import :: c_int, c_ptr
         type(c_ptr), value :: stream
         integer(c_int) :: fd
      end function c_fileno
      function c_fsync(fd) bind(C, name="fsync") result(status)
         import :: c_int
         integer(c_int), value :: fd
         integer(c_int) :: status
      end function c_fsync
      function c_errno_location() bind(C, name="__errno_location") result(where)
         import :: c_ptr
         type(c_ptr) :: where
      end function c_errno_location
      function c_strerror(code) bind(C, name="strerror") result(text)
         import :: c_int, c_ptr
         integer(c_int), value :: code
         type(c_ptr) :: text
      end function c_strerror
   end interface

contains

   !> Open `<path>.part<pid>` for writing; fails (err_io) when the place is not writable
   !> or `path` is a directory.
   subroutine open_output(file, path, error)
      type(output_file_t), intent(out) :: file  !! the open temporary file
      character(len=*), intent(in) :: path  !! final file name
      type(error_t), allocatable, intent(out) :: error  !! err_io when the place is not writable
      character(len=24) :: pid
      write (pid, '(i0)') c_getpid()
      file%path = path
      file%temp_path = path//".part"//trim(pid)
      if (is_directory(path)) then
         call set_error(error, err_io, "cannot write '"//path//"': it is a directory")
         return
      end if
      call set_errno(0)
      file%stream = c_fopen(c_string(file%temp_path), c_string("w"))
      if (.not. c_associated(file%stream)) then
         call set_error(error, err_io, "cannot write '"//path//"': "//errno_text())
         return
      end if
      call watch_temp_file(file%temp_path, file%slot)
   end subroutine open_output

   !> Flush the temporary file to the disk, close it and rename it onto the final name;
   !> after any failure (now or in an earlier write) the temporary file is deleted.
   subroutine commit_output(file, error)
      type(output_file_t), intent(inout) :: file  !! the file written
      type(error_t), allocatable, intent(out) :: error  !! err_io when a write, the flush, close or rename failed
      character(len=:), allocatable :: cause
      if (.not. c_associated(file%stream)) then
         call set_error(error, err_io, "cannot finish '"//file%path//"': the file is not open")
         return
      end if
      if (allocated(file%failure)) cause = file%failure
      call set_errno(0)
      if (c_fflush(file%stream) /= 0) then
         if (.not. allocated(cause)) cause = errno_text()
      else if (c_fsync(c_fileno(file%stream)) /= 0) then
         if (.not. allocated(cause)) cause = errno_text()
      end if
      call set_errno(0)
      if (c_fclose(file%stream) /= 0) then
         if (.not. allocated(cause)) cause = errno_text()
      end if
      file%stream = c_null_ptr
      if (allocated(cause)) then
         call remove_file(file%temp_path)
         call forget_temp_file(file%slot)
         call set_error(error, err_io, "cannot write '"//file%path//"': "//cause// &
            " (the file is left as it was)")
         return
      end if
      call set_errno(0)
      if (c_rename(c_string(file%temp_path), c_string(file%path)) /= 0) then
         cause = errno_text()
         call remove_file(file%temp_path)
         call set_error(error, err_io, "cannot rename '"//file%temp_path//"' to '"//file%path//"': "//cause)
      end if
      call forget_temp_file(file%slot)
   end subroutine commit_output

   !> Close and delete the temporary file; the final name is left as it was.
   subroutine discard_output(file)
      type(output_file_t), intent(inout) :: file  !! the file to abandon
      integer(c_int) :: status
      if (c_associated(file%stream)) status = c_fclose(file%stream)
      file%stream = c_null_ptr
      if (allocated(file%temp_path)) call remove_file(file%temp_path)
      call forget_temp_file(file%slot)
   end subroutine discard_output

   !> Delete a file if it exists (no error if it does not).
   subroutine remove_file(path)
      character(len=*), intent(in) :: path  !! the file
      integer(c_int) :: status
      status = c_remove(c_string(path))
   end subroutine remove_file

   !> Whether `path` names an existing directory.
   logical function is_directory(path)
      character(len=*), intent(in) :: path  !! any path
      if (len(path) == 0) then
         is_directory = .false.
         return
      end if
      inquire (file=path//"/.", exist=is_directory)
   end function is_directory

   !> Write the header: each of `lines` after "# ", then "# columns: <columns>".
   subroutine write_header(file, lines, columns, error)
      type(output_file_t), intent(inout) :: file  !! the open output file
      character(len=*), intent(in) :: lines(:)  !! header text, one entry a line
      character(len=*), intent(in) :: columns   !! blank-separated column names
      type(error_t), allocatable, intent(out) :: error  !! err_io when writing fails
      integer :: k
      do k = 1, size(lines)
         call write_text(file, "# "//trim(lines(k)), error)
         if (allocated(error)) return
      end do
      call write_text(file, "# columns: "//columns, error)
   end subroutine write_header

   !> Write one line of text (a newline is added). After a failed write the file is
   !> incomplete: this and every later write report the failure, and commit_output
   !> deletes the file.
   subroutine write_text(file, line, error)
      type(output_file_t), intent(inout) :: file  !! the open output file
      character(len=*), intent(in) :: line  !! the line, without its new line
      type(error_t), allocatable, intent(out) :: error  !! err_io when writing fails
      integer(c_size_t) :: written
      if (.not. allocated(file%failure)) then
         if (.not. c_associated(file%stream)) then
            file%failure = "the file is not open"
         else
            call set_errno(0)
            written = c_fwrite(line//new_line("a"), 1_c_size_t, int(len(line) + 1, c_size_t), file%stream)
            if (written /= int(len(line) + 1, c_size_t)) then
               file%failure = errno_text()
            else
               file%bytes = file%bytes + len(line) + 1
            end if
         end if
      end if
      if (allocated(file%failure)) call set_error(error, err_io, "cannot write '"//file%path//"': "// &
         file%failure//" (the file is left as it was)")
   end subroutine write_text

   !> Column names of chart and points files; `physical` only for the elastic model,
   !> `stable_paper` only with damping, `mu_per_s` only when ω is known.
   pure function chart_columns(damped, elastic, per_second) result(names)
      logical, intent(in) :: damped  !! ε > 0
      logical, intent(in), optional :: elastic     !! the elastic model (default): the `physical` column
      logical, intent(in), optional :: per_second  !! the scene knows ω: the `mu_per_s` column
      character(len=:), allocatable :: names
      names = "alpha beta S stable lambda_max mu log10_abs_S overflow"
      if (optional_true(elastic, .true.)) names = names//" physical"
      if (damped) names = names//" stable_paper"
      if (optional_true(per_second, .false.)) names = names//" mu_per_s"
      names = names//" error_estimate status"
   end function chart_columns

   pure logical function optional_true(flag, default)
      logical, intent(in), optional :: flag
      logical, intent(in) :: default
      optional_true = default
      if (present(flag)) optional_true = flag
   end function optional_true

   !> One chart row: alpha beta S stable lambda_max mu log10_abs_S overflow [physical] [stable_paper]
   !> [mu_per_s] error_estimate status, as named by `chart_columns`. |S| > 1e300 is written as ±1e300 with overflow = 1 (log10_abs_S
   !> stays exact); lambda_max is clamped the same way; flags are 1 or 0; error_estimate is
   !> the method's estimate of |ΔS|/max(1, |S|) (−1 when the method gives none); status is
   !> a code of hillstab_status (status_ok or status_roundoff here, see `failed_chart_line`).
   pure function chart_line(alpha, beta, f, damped, physical, status, alpha_text, beta_text, elastic, per_second) &
      result(line)
      real(wp), intent(in) :: alpha, beta  !! the grid point
      type(floquet_t), intent(in) :: f  !! Floquet data of the point
      logical, intent(in) :: damped     !! write the stable_paper column
      logical, intent(in) :: physical   !! (α, β) inside the physical domain
      integer, intent(in) :: status     !! per-point status code (hillstab_status)
      !> format_es(alpha, 16), format_es(beta, 16) when already at hand (a chart formats
      !> each grid value once, not once per point)
      character(len=23), intent(in), optional :: alpha_text, beta_text
      logical, intent(in), optional :: elastic  !! write the `physical` column (default: yes)
      !> ω/π (1/s per unit τ) when the scene knows ω: write the `mu_per_s` column μ ω/π
      real(wp), intent(in), optional :: per_second
      character(len=chart_line_length) :: line
      real(wp) :: s, lambda_max, log10_abs_s, mu, estimate
      logical :: overflow
      integer :: pos
      s = f%trace%value
      overflow = f%trace%overflow .or. abs(s) > clamp_magnitude
      if (overflow) s = sign(clamp_magnitude, s)
      lambda_max = min(largest_multiplier_modulus(f), clamp_magnitude)
      log10_abs_s = max(f%trace%log_abs/log(10.0_wp), log10_floor)
      mu = f%exponent + 0.0_wp  ! no "-0.0" in the file
      estimate = f%trace%error_estimate
      if (estimate < 0.0_wp) estimate = -1.0_wp
      ! hand formatting (hillstab_format): Fortran's formatted write would cost more than
      ! computing the point with method auto
      call put_point(line, pos, alpha, beta, alpha_text, beta_text)
      call put_es(line, pos, s, 16)
      if (f%marginal) then
         call put_text(line, pos, marginal_text)
      else
         call put_flag(line, pos, f%stable)
      end if
      call put_blank(line, pos)
      call put_es(line, pos, lambda_max, 10)
      call put_blank(line, pos)
      call put_es(line, pos, mu, 10)
      call put_blank(line, pos)
      call put_es(line, pos, log10_abs_s, 10)
      call put_flag(line, pos, overflow)
      if (optional_true(elastic, .true.)) call put_flag(line, pos, physical)
      if (damped) call put_flag(line, pos, f%stable_paper)
      if (present(per_second)) then
         call put_blank(line, pos)
         call put_es(line, pos, mu*per_second + 0.0_wp, 10)
      end if
      call put_blank(line, pos)
      call put_es(line, pos, min(estimate, clamp_magnitude), 3)
      call put_status(line, pos, status)
      line(pos + 1:) = ""
   end function chart_line

   !> The chart row of a point where no value could be computed: alpha beta, then
   !> placeholders outside the range of every column that has one (stable, overflow and
   !> stable_paper −1, lambda_max −1, log10_abs_S −999, error_estimate −1), S = 0 and
   !> mu = 0 (and mu_per_s = 0), physical as for any point, and status = `status` (status_failed).
   pure function failed_chart_line(alpha, beta, damped, physical, status, alpha_text, beta_text, elastic, &
                                   per_second) result(line)
      real(wp), intent(in) :: alpha, beta  !! the grid point
      logical, intent(in) :: damped     !! write the stable_paper column
      logical, intent(in) :: physical   !! (α, β) inside the physical domain
      integer, intent(in) :: status     !! per-point status code (status_failed)
      character(len=23), intent(in), optional :: alpha_text, beta_text  !! as for `chart_line`
      logical, intent(in), optional :: elastic      !! as for `chart_line`
      real(wp), intent(in), optional :: per_second  !! as for `chart_line`
      character(len=chart_line_length) :: line
      integer :: pos
      call put_point(line, pos, alpha, beta, alpha_text, beta_text)
      call put_es(line, pos, 0.0_wp, 16)
      call put_text(line, pos, " -1 ")
      call put_es(line, pos, -1.0_wp, 10)
      call put_blank(line, pos)
      call put_es(line, pos, 0.0_wp, 10)
      call put_blank(line, pos)
      call put_es(line, pos, failed_log10_abs_s, 10)
      call put_text(line, pos, " -1")
      if (optional_true(elastic, .true.)) call put_flag(line, pos, physical)
      if (damped) call put_text(line, pos, " -1")
      if (present(per_second)) then
         call put_blank(line, pos)
         call put_es(line, pos, 0.0_wp, 10)
      end if
      call put_blank(line, pos)
      call put_es(line, pos, -1.0_wp, 3)
      call put_status(line, pos, status)
      line(pos + 1:) = ""
   end function failed_chart_line

   !> "alpha beta " at the start of a chart line.
   pure subroutine put_point(line, pos, alpha, beta, alpha_text, beta_text)
      character(len=*), intent(inout) :: line
      integer, intent(out) :: pos
      real(wp), intent(in) :: alpha, beta
      character(len=23), intent(in), optional :: alpha_text, beta_text
      pos = 0
      if (present(alpha_text)) then
         line(1:23) = alpha_text
         pos = 23
      else
         call put_es(line, pos, alpha, 16)
      end if
      call put_blank(line, pos)
      if (present(beta_text)) then
         line(pos + 1:pos + 23) = beta_text
         pos = pos + 23
      else
         call put_es(line, pos, beta, 16)
      end if
      call put_blank(line, pos)
   end subroutine put_point

   !> Reals written in full precision, separated by one blank.
   pure function real_columns(values) result(line)
      real(wp), intent(in) :: values(:)  !! the values, finite
      character(len=25*size(values)) :: line
      write (line, '(*(es24.16e3,:,1x))') values
   end function real_columns

   !> Append one blank.
   pure subroutine put_blank(line, pos)
      character(len=*), intent(inout) :: line
      integer, intent(inout) :: pos
      line(pos + 1:pos + 1) = " "
      pos = pos + 1
   end subroutine put_blank

   !> Append a short piece of text.
   pure subroutine put_text(line, pos, text)
      character(len=*), intent(inout) :: line
      integer, intent(inout) :: pos
      character(len=*), intent(in) :: text
      line(pos + 1:pos + len(text)) = text
      pos = pos + len(text)
   end subroutine put_text

   !> Append " <status>" (a code of hillstab_status, 0 … 9).
   pure subroutine put_status(line, pos, status)
      character(len=*), intent(inout) :: line
      integer, intent(inout) :: pos
      integer, intent(in) :: status
      line(pos + 1:pos + 2) = " "//achar(iachar("0") + max(0, min(9, status)))
      pos = pos + 2
   end subroutine put_status

   !> Append " 1" or " 0".
   pure subroutine put_flag(line, pos, condition)
      character(len=*), intent(inout) :: line
      integer, intent(inout) :: pos
      logical, intent(in) :: condition
      line(pos + 1:pos + 2) = " 0"
      if (condition) line(pos + 2:pos + 2) = "1"
      pos = pos + 2
   end subroutine put_flag

   elemental integer function flag(condition)
      logical, intent(in) :: condition
      flag = merge(1, 0, condition)
   end function flag

   !> The message of the current errno ("unknown cause" when errno is 0).
   function errno_text() result(text)
      character(len=:), allocatable :: text
      integer(c_int), pointer :: code
      character(kind=c_char), pointer :: chars(:)
      integer :: n
      call c_f_pointer(c_errno_location(), code)
      if (code == 0) then
         text = "unknown cause"
         return
      end if
      call c_f_pointer(c_strerror(code), chars, [1024])
      n = 0
      do while (n < 1024)
         if (chars(n + 1) == c_null_char) exit
         n = n + 1
      end do
      allocate (character(len=n) :: text)
      text = transfer(chars(:n), text)
   end function errno_text

   subroutine set_errno(value)
      integer, intent(in) :: value
      integer(c_int), pointer :: code
      call c_f_pointer(c_errno_location(), code)
      code = int(value, c_int)
   end subroutine set_errno

   pure function c_string(text) result(c)
      character(len=*), intent(in) :: text
      character(kind=c_char) :: c(len(text) + 1)
      integer :: i
      do i = 1, len(text)
         c(i) = text(i:i)
      end do
      c(len(text) + 1) = c_null_char
   end function c_string
end module hillstab_output

!> Gnuplot-ready output files: a `#` header, one `# columns:` line, numeric columns.
!>
!> Files appear complete or not at all: rows go to `<path>.part<pid>`, which is
!> renamed onto `<path>` only by `commit_output`; `discard_output` deletes it.
!> An existing file at `<path>` is never opened, so a failed run leaves it untouched.
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
   use hillstab_kinds, only: wp
   use hillstab_error, only: error_t, set_error, err_io
   use hillstab_floquet, only: floquet_t, largest_multiplier_modulus
   use hillstab_format, only: put_es
   use, intrinsic :: iso_c_binding, only: c_int, c_char, c_null_char
   implicit none
   private
   public :: output_file_t, open_output, commit_output, discard_output, write_header, write_text
   public :: chart_columns, chart_line, failed_chart_line, chart_line_length, clamp_magnitude, log10_floor, &
      real_columns, failed_log10_abs_s
   public :: remove_file

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
      integer :: unit = -1                           !! Fortran unit of the temporary file
      character(len=:), allocatable :: path          !! final name
      character(len=:), allocatable :: temp_path     !! name while being written
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
   end interface

contains

   !> Open `<path>.part<pid>` for writing; fails (err_io) when the place is not writable.
   subroutine open_output(file, path, error)
      type(output_file_t), intent(out) :: file  !! the open temporary file
      character(len=*), intent(in) :: path  !! final file name
      type(error_t), allocatable, intent(out) :: error  !! err_io when the place is not writable
      integer :: ios
      character(len=512) :: msg
      character(len=24) :: pid
      write (pid, '(i0)') c_getpid()
      file%path = path
      file%temp_path = path//".part"//trim(pid)
      open (newunit=file%unit, file=file%temp_path, status="replace", action="write", form="formatted", &
            iostat=ios, iomsg=msg)
      if (ios /= 0) then
         file%unit = -1
         call set_error(error, err_io, "cannot write '"//path//"': "//trim(msg))
      end if
   end subroutine open_output

   !> Close the temporary file and rename it onto the final name.
   subroutine commit_output(file, error)
      type(output_file_t), intent(inout) :: file  !! the file written
      type(error_t), allocatable, intent(out) :: error  !! err_io when closing or renaming fails
      integer :: ios
      character(len=512) :: msg
      close (file%unit, iostat=ios, iomsg=msg)
      file%unit = -1
      if (ios /= 0) then
         call remove_file(file%temp_path)
         call set_error(error, err_io, "cannot finish '"//file%path//"': "//trim(msg))
         return
      end if
      if (c_rename(c_string(file%temp_path), c_string(file%path)) /= 0) then
         call remove_file(file%temp_path)
         call set_error(error, err_io, "cannot rename '"//file%temp_path//"' to '"//file%path//"'")
      end if
   end subroutine commit_output

   !> Close and delete the temporary file; the final name is left as it was.
   subroutine discard_output(file)
      type(output_file_t), intent(inout) :: file  !! the file to abandon
      integer :: ios
      if (file%unit /= -1) close (file%unit, status="delete", iostat=ios)
      file%unit = -1
      if (allocated(file%temp_path)) call remove_file(file%temp_path)
   end subroutine discard_output

   !> Delete a file if it exists (no error if it does not).
   subroutine remove_file(path)
      character(len=*), intent(in) :: path  !! the file
      integer(c_int) :: status
      status = c_remove(c_string(path))
   end subroutine remove_file

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

   !> Write one line of text.
   subroutine write_text(file, line, error)
      type(output_file_t), intent(inout) :: file  !! the open output file
      character(len=*), intent(in) :: line  !! the line, without its new line
      type(error_t), allocatable, intent(out) :: error  !! err_io when writing fails
      integer :: ios
      character(len=512) :: msg
      write (file%unit, '(a)', iostat=ios, iomsg=msg) line
      if (ios /= 0) call set_error(error, err_io, "cannot write '"//file%path//"': "//trim(msg))
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

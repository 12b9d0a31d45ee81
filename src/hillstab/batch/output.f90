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
!> registered with hillstab_batch_signals for removal on an interrupt.
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
module hillstab_batch_output
   use hillstab_core_kinds, only: wp, int64
   use hillstab_core_error, only: error_t, set_error, err_io
   use hillstab_hill_floquet, only: floquet_t, largest_multiplier_modulus
   use hillstab_core_text, only: put_es, integer_text, lower_case
   use hillstab_batch_signals, only: watch_temp_file, forget_temp_file
   use, intrinsic :: iso_c_binding, only: c_int, c_char, c_null_char, c_ptr, c_null_ptr, c_associated, &
      c_size_t, c_f_pointer, c_loc
   implicit none
   private
   public :: output_file_t, open_output, commit_output, discard_output, finish_output, write_header, write_text
   public :: n_chart_columns, chart_column_names, chart_values, failed_chart_values, chart_text
   public :: chart_columns_text, default_chart_columns, find_chart_columns, write_records
   public :: chart_line_length, clamp_magnitude, log10_floor, real_columns, failed_log10_abs_s
   public :: remove_file, is_directory, joined_lines

   !> Magnitudes beyond this are written as ±clamp_magnitude with the overflow flag set.
   real(wp), parameter :: clamp_magnitude = 1.0e300_wp
   !> log10|S| is written as at least this (only S = 0 exactly reaches it).
   real(wp), parameter :: log10_floor = -300.0_wp
   !> log10_abs_S of a failed point: below `log10_floor`, so never a value.
   real(wp), parameter :: failed_log10_abs_s = -999.0_wp
   !> Number of columns a chart or points file can hold (`chart_column_names`).
   integer, parameter :: n_chart_columns = 13
   !> Characters in one chart line (see `chart_text`).
   integer, parameter :: chart_line_length = 200

   !> An output file being written under a temporary name.
   type :: output_file_t
      type(c_ptr) :: stream = c_null_ptr             !! C stream of the temporary file
      character(len=:), allocatable :: path          !! final name
      character(len=:), allocatable :: temp_path     !! name while being written
      character(len=:), allocatable :: failure       !! first write failure (the file is then incomplete)
      integer(int64) :: bytes = 0                    !! bytes written so far
      integer :: slot = 0                            !! hillstab_batch_signals handle
      logical :: binary = .false.                    !! stream file: text header, then raw records
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
      function c_fwrite_raw(buffer, size, count, stream) bind(C, name="fwrite") result(written)
         import :: c_ptr, c_size_t
         type(c_ptr), value :: buffer
         integer(c_size_t), value :: size, count
         type(c_ptr), value :: stream
         integer(c_size_t) :: written
      end function c_fwrite_raw
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
   !> or `path` is a directory. With `binary`, the file is a byte stream: text lines
   !> (`write_text`, `write_header`) and then raw records (`write_records`).
   subroutine open_output(file, path, error, binary, context)
      type(output_file_t), intent(out) :: file  !! the open temporary file
      character(len=*), intent(in) :: path  !! final file name
      type(error_t), allocatable, intent(out) :: error  !! err_io when the place is not writable
      logical, intent(in), optional :: binary  !! a byte stream (default: a text file)
      !> put before the error message: what named the path (a task: "<scene>: &scene: output: ")
      character(len=*), intent(in), optional :: context
      character(len=24) :: pid
      character(len=:), allocatable :: prefix
      prefix = ""
      if (present(context)) prefix = context
      write (pid, '(i0)') c_getpid()
      file%path = path
      file%temp_path = path//".part"//trim(pid)
      if (present(binary)) file%binary = binary
      if (is_directory(path)) then
         call set_error(error, err_io, prefix//"cannot write '"//path//"': it is a directory")
         return
      end if
      call set_errno(0)
      file%stream = c_fopen(c_string(file%temp_path), c_string("w"))
      if (.not. c_associated(file%stream)) then
         call set_error(error, err_io, prefix//"cannot write '"//path//"': "//errno_text())
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

   !> End the writing of a file: commit it when `error` is unallocated (a failure to
   !> commit comes back in `error`), else discard it and keep `error`.
   subroutine finish_output(file, error)
      type(output_file_t), intent(inout) :: file  !! the file written
      !> in: the first failure while writing, if any; out: that one, or the commit's
      type(error_t), allocatable, intent(inout) :: error
      if (allocated(error)) then
         call discard_output(file)
      else
         call commit_output(file, error)
      end if
   end subroutine finish_output

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
   !> Text files with `names_line`: then one uncommented line of the column names, which
   !> gnuplot takes as column headers (`using 'alpha':'mu'`) and pandas as the header
   !> (`read_csv(path, comment='#', sep=r'\s+')`). Binary files (`records` given): the header
   !> also says where the data start and how gnuplot and numpy read them.
   subroutine write_header(file, lines, columns, error, names_line, records)
      type(output_file_t), intent(inout) :: file  !! the open output file
      character(len=*), intent(in) :: lines(:)  !! header text, one entry a line
      character(len=*), intent(in) :: columns   !! blank-separated column names
      type(error_t), allocatable, intent(out) :: error  !! err_io when writing fails
      logical, intent(in), optional :: names_line  !! text: a line of column names after the header
      !> binary: (records per block, blocks), e.g. (n_beta, n_alpha) of a chart
      integer, intent(in), optional :: records(2)
      character(len=:), allocatable :: layout(:)
      character(len=*), parameter :: mark = "@SKIP@@@@@"  ! 10 characters, replaced by the byte count
      character(len=10) :: skip_text
      integer :: k, n_columns, total
      if (file%binary .and. present(records)) then
         n_columns = 1
         do k = 1, len_trim(columns)
            if (columns(k:k) == " ") n_columns = n_columns + 1
         end do
         layout = [character(len=400 + len(file%path)) :: &
            "format: binary: after the first "//mark//" bytes (this header) come "// &
            integer_text(records(1))//" x "//integer_text(records(2))//" records of "//integer_text(n_columns)// &
            " float64 (native byte order, little-endian on x86-64 and ARM), the columns below, point by point "// &
            "in the order of the text format", &
            "gnuplot: plot '"//file%path//"' binary skip="//mark//" format='%"//integer_text(n_columns)// &
            "float64' record=("//integer_text(records(1))//","//integer_text(records(2))// &
            ") using 1:2:N with image (N: a column number, from 1 in the columns line)", &
            "numpy: numpy.fromfile('"//file%path//"', dtype='<f8', offset="//mark//").reshape(-1, "// &
            integer_text(n_columns)//")"]
         total = len("# columns: "//columns) + 1
         do k = 1, size(lines)
            total = total + len_trim(lines(k)) + 3
         end do
         do k = 1, size(layout)
            total = total + len_trim(layout(k)) + 3
         end do
         write (skip_text, '(i0)') total
         do k = 1, size(layout)
            layout(k) = replaced(layout(k), mark, skip_text)
         end do
         do k = 1, size(lines)
            call write_text(file, "# "//trim(lines(k)), error)
            if (allocated(error)) return
         end do
         do k = 1, size(layout)
            call write_text(file, "# "//trim(layout(k)), error)
            if (allocated(error)) return
         end do
         call write_text(file, "# columns: "//columns, error)
         return
      end if
      do k = 1, size(lines)
         call write_text(file, "# "//trim(lines(k)), error)
         if (allocated(error)) return
      end do
      call write_text(file, "# columns: "//columns, error)
      if (allocated(error)) return
      if (present(names_line)) then
         if (names_line) call write_text(file, columns, error)
      end if
   contains
      !> `text` with every `key` replaced by `value` (same length: the line keeps its length).
      pure function replaced(text, key, value) result(out)
         character(len=*), intent(in) :: text, key
         character(len=len(key)), intent(in) :: value
         character(len=len(text)) :: out
         integer :: at
         out = text
         do
            at = index(out, key)
            if (at == 0) exit
            out(at:at + len(key) - 1) = value
         end do
      end function replaced
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

   !> `lines` (each trimmed) joined by new lines, after a leading new line if `separate`,
   !> without a final one: a block of rows written by one `write_text` (one write per line
   !> would cost more than a chart point of method auto). With `breaks`, one more new line
   !> (a blank line: a new gnuplot block) before each line j where breaks(j).
   pure function joined_lines(lines, separate, breaks) result(text)
      character(len=*), intent(in) :: lines(:)  !! the rows
      logical, intent(in) :: separate  !! start with a new line (a blank line before the block)
      logical, intent(in), optional :: breaks(:)  !! a blank line before line j (size of lines)
      character(len=:), allocatable :: text
      integer :: j, n, pos, total
      total = merge(1, 0, separate) + max(size(lines) - 1, 0)
      if (present(breaks)) total = total + count(breaks)
      do j = 1, size(lines)
         total = total + len_trim(lines(j))
      end do
      allocate (character(len=total) :: text)
      pos = 0
      if (separate) then
         text(1:1) = new_line("a")
         pos = 1
      end if
      do j = 1, size(lines)
         if (j > 1) then
            text(pos + 1:pos + 1) = new_line("a")
            pos = pos + 1
         end if
         if (present(breaks)) then
            if (breaks(j)) then
               text(pos + 1:pos + 1) = new_line("a")
               pos = pos + 1
            end if
         end if
         n = len_trim(lines(j))
         text(pos + 1:pos + n) = lines(j)(1:n)
         pos = pos + n
      end do
   end function joined_lines

   !> Write records of reals as raw float64 (binary files only), column-major: one
   !> record per column of `values`.
   subroutine write_records(file, values, error)
      type(output_file_t), intent(inout) :: file  !! the open binary file
      real(wp), intent(in) :: values(:, :)  !! (columns, records)
      type(error_t), allocatable, intent(out) :: error  !! err_io when writing fails
      real(wp), allocatable, target :: copy(:, :)
      integer(c_size_t) :: n, written
      if (.not. allocated(file%failure)) then
         if (.not. c_associated(file%stream)) then
            file%failure = "the file is not open"
         else if (size(values) > 0) then
            copy = values  ! contiguous
            n = int(size(copy), c_size_t)
            call set_errno(0)
            written = c_fwrite_raw(c_loc(copy), int(storage_size(copy)/8, c_size_t), n, file%stream)
            if (written /= n) then
               file%failure = errno_text()
            else
               file%bytes = file%bytes + int(n, int64)*(storage_size(copy)/8)
            end if
         end if
      end if
      if (allocated(file%failure)) call set_error(error, err_io, "cannot write '"//file%path//"': "// &
         file%failure//" (the file is left as it was)")
   end subroutine write_records

   !> Every column a chart or points file can hold, in file order (`default_chart_columns`
   !> picks those of a scene, `find_chart_columns` those a scene names).
   pure function chart_column_names() result(names)
      character(len=14) :: names(n_chart_columns)
      names = [character(len=14) :: "alpha", "beta", "S", "stable", "lambda_max", "mu", "log10_abs_S", "overflow", &
               "physical", "stable_paper", "mu_per_s", "error_estimate", "status"]
   end function chart_column_names

   !> Indices (into `chart_column_names`) of the columns a chart of this kind offers:
   !> `physical` for the elastic model, `stable_paper` with damping, `mu_per_s` when ω is known.
   pure function default_chart_columns(damped, elastic, per_second) result(ids)
      logical, intent(in) :: damped      !! ε > 0
      logical, intent(in) :: elastic     !! the elastic model
      logical, intent(in) :: per_second  !! the scene knows ω
      integer, allocatable :: ids(:)
      ids = [1, 2, 3, 4, 5, 6, 7, 8]
      if (elastic) ids = [ids, 9]
      if (damped) ids = [ids, 10]
      if (per_second) ids = [ids, 11]
      ids = [ids, 12, 13]
   end function default_chart_columns

   !> The columns named in `text` (blank- or comma-separated, case-insensitive), in the
   !> order given, each one of `available`; `bad` names the first that is not ("" when all are).
   pure subroutine find_chart_columns(text, available, ids, bad)
      character(len=*), intent(in) :: text  !! the names, as in `&scene columns`
      integer, intent(in) :: available(:)  !! indices offered (`default_chart_columns`)
      integer, allocatable, intent(out) :: ids(:)  !! indices of the names found, in order
      character(len=:), allocatable, intent(out) :: bad  !! the first unknown or repeated name, or ""
      character(len=14) :: names(n_chart_columns)
      character(len=:), allocatable :: word
      integer :: i, j, k, found
      names = chart_column_names()
      allocate (ids(0))
      bad = ""
      i = 1
      do while (i <= len(text))
         if (index(" ,", text(i:i)) > 0) then
            i = i + 1
            cycle
         end if
         j = i
         do while (j < len(text))
            if (index(" ,", text(j + 1:j + 1)) > 0) exit
            j = j + 1
         end do
         word = lower_case(text(i:j))
         found = 0
         do k = 1, size(available)
            if (lower_case(trim(names(available(k)))) == word) found = available(k)
         end do
         if (found == 0 .or. any(ids == found)) then
            bad = text(i:j)
            return
         end if
         ids = [ids, found]
         i = j + 1
      end do
   end subroutine find_chart_columns

   !> Column names joined by blanks.
   pure function chart_columns_text(ids) result(text)
      integer, intent(in) :: ids(:)  !! indices into `chart_column_names`
      character(len=:), allocatable :: text
      character(len=14) :: names(n_chart_columns)
      integer :: k
      names = chart_column_names()
      text = ""
      do k = 1, size(ids)
         if (k > 1) text = text//" "
         text = text//trim(names(ids(k)))
      end do
   end function chart_columns_text

   !> The value of every column (`chart_column_names` order) at one computed point: S and
   !> lambda_max clamped to ±1e300, flags 1 or 0, stable 0.5 when marginal, mu_per_s = μ ω/π
   !> (0 without `per_second`), error_estimate −1 when the method gives none.
   pure function chart_values(alpha, beta, f, physical, status, per_second) result(v)
      real(wp), intent(in) :: alpha, beta  !! the grid point
      type(floquet_t), intent(in) :: f  !! Floquet data of the point
      logical, intent(in) :: physical   !! (α, β) inside the physical domain
      integer, intent(in) :: status     !! per-point status code (hillstab_core_status)
      real(wp), intent(in), optional :: per_second  !! ω/π
      real(wp) :: v(n_chart_columns)
      real(wp) :: s, estimate
      logical :: overflow
      s = f%trace%value
      overflow = f%trace%overflow .or. abs(s) > clamp_magnitude
      if (overflow) s = sign(clamp_magnitude, s)
      estimate = f%trace%error_estimate
      if (estimate < 0.0_wp) estimate = -1.0_wp
      v(1) = alpha
      v(2) = beta
      v(3) = s
      v(4) = merge(1.0_wp, 0.0_wp, f%stable)
      if (f%marginal) v(4) = 0.5_wp
      v(5) = min(largest_multiplier_modulus(f), clamp_magnitude)
      v(6) = f%exponent + 0.0_wp  ! no "-0.0" in the file
      v(7) = max(f%trace%log_abs/log(10.0_wp), log10_floor)
      v(8) = merge(1.0_wp, 0.0_wp, overflow)
      v(9) = merge(1.0_wp, 0.0_wp, physical)
      v(10) = merge(1.0_wp, 0.0_wp, f%stable_paper)
      v(11) = 0.0_wp
      if (present(per_second)) v(11) = v(6)*per_second + 0.0_wp
      v(12) = min(estimate, clamp_magnitude)
      v(13) = real(status, wp)
   end function chart_values

   !> The columns of a point where no value could be computed: alpha beta, then
   !> placeholders outside the range of every column that has one (stable, overflow and
   !> stable_paper −1, lambda_max −1, log10_abs_S −999, error_estimate −1), S = mu =
   !> mu_per_s = 0, physical as for any point, and status = `status` (status_failed).
   pure function failed_chart_values(alpha, beta, physical, status) result(v)
      real(wp), intent(in) :: alpha, beta  !! the grid point
      logical, intent(in) :: physical   !! (α, β) inside the physical domain
      integer, intent(in) :: status     !! per-point status code (status_failed)
      real(wp) :: v(n_chart_columns)
      v = [alpha, beta, 0.0_wp, -1.0_wp, -1.0_wp, 0.0_wp, failed_log10_abs_s, -1.0_wp, &
           merge(1.0_wp, 0.0_wp, physical), -1.0_wp, 0.0_wp, -1.0_wp, real(status, wp)]
   end function failed_chart_values

   !> One text line of the columns `ids` of a point's values `v` (from `chart_values`):
   !> alpha, beta, S with 17 significant digits, lambda_max, mu, log10_abs_S, mu_per_s with 11,
   !> error_estimate with 4, flags and status as integers (stable 0.5 when marginal).
   pure function chart_text(ids, v, alpha_text, beta_text) result(line)
      integer, intent(in) :: ids(:)  !! the columns to write (indices into `chart_column_names`)
      real(wp), intent(in) :: v(n_chart_columns)  !! every column's value (`chart_values`)
      !> format_es(alpha, 16), format_es(beta, 16) when already at hand (a chart formats
      !> each grid value once, not once per point)
      character(len=23), intent(in), optional :: alpha_text, beta_text
      character(len=chart_line_length) :: line
      integer :: k, pos
      ! hand formatting (hillstab_core_text): Fortran's formatted write would cost more than
      ! computing the point with method auto
      pos = 0
      do k = 1, size(ids)
         if (k > 1) call put_blank(line, pos)
         select case (ids(k))
         case (1)
            if (present(alpha_text)) then
               call put_text(line, pos, alpha_text)
            else
               call put_es(line, pos, v(1), 16)
            end if
         case (2)
            if (present(beta_text)) then
               call put_text(line, pos, beta_text)
            else
               call put_es(line, pos, v(2), 16)
            end if
         case (3)
            call put_es(line, pos, v(3), 16)
         case (5, 6, 7, 11)
            call put_es(line, pos, v(ids(k)), 10)
         case (12)
            call put_es(line, pos, v(12), 3)
         case default  ! flags and status: small integers, or 0.5 (marginal)
            if (v(ids(k)) == 0.5_wp) then
               call put_text(line, pos, "0.5")
            else if (v(ids(k)) < 0.0_wp) then
               call put_text(line, pos, "-"//achar(iachar("0") + min(9, nint(-v(ids(k))))))
            else
               call put_text(line, pos, achar(iachar("0") + min(9, nint(v(ids(k))))))
            end if
         end select
      end do
      line(pos + 1:) = ""
   end function chart_text

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
end module hillstab_batch_output

!> Gnuplot-ready output files: a `#` header, one `# columns:` line, numeric columns.
!>
!> Files appear complete or not at all: rows go to a new temporary file in the output's
!> directory, `<name>.partXXXXXX` (the suffix unpredictable, the file created exclusively
!> by mkstemp: nothing someone placed at that name, a symbolic or hard link included, is
!> ever opened; the name shortened so that it fits wherever the final name does), which is
!> renamed onto `<path>` only by `commit_output`, and only when every write, the
!> flush to the disk and the close succeeded; otherwise the temporary file is deleted,
!> `<path>` keeps what it had and the error names the path and the cause (a full file
!> system, a file-size limit). `discard_output` deletes the temporary file.
!> An existing file at `<path>` is never opened, so a failed run leaves it untouched.
!> Writes go through C stdio so that every failure is seen with its errno (gfortran's
!> buffered formatted writes can lose ENOSPC). While written, the temporary file is
!> registered with hillstab_batch_output_signals for removal on an interrupt.
!>
!> A long run keeps a checkpoint of its partial file (hillstab_batch_output_checkpoint): `sync_output`
!> puts what was written on the disk, `lock_output` marks the file as in use, and
!> `resume_output` continues a partial file: cut to its valid length, it is written on under
!> a new temporary name (a hard link made exclusively, with an unpredictable suffix, as
!> mkstemp names) and renamed onto `<path>` by `commit_output` like a new one.
!> This module moves bytes and files; what the columns mean is the tasks' (their column
!> tables, hillstab_batch_output_columns); it knows nothing of integrators.
!>
!>```fortran
!> type(output_file_t) :: file
!> type(error_t), allocatable :: error
!> call open_output(file, "out/run_chart.dat", error)
!> call write_header(file, ["hillstab 0.1.0"], "alpha beta S", error)
!> call write_text(file, "1.0 2.0 3.0", error)
!> call commit_output(file, error)
!>```
module hillstab_batch_output_file
   use hillstab_core_kinds, only: int64
   use hillstab_core_error, only: error_t, set_error, err_io
   use hillstab_core_text, only: integer_text
   use hillstab_ffi_libc, only: c_mkdir, c_rename, c_mkstemp, c_fdopen, c_fchmod, c_umask, c_close, c_fwrite, c_fwrite_raw, &
      c_fflush, c_fclose, c_fileno, c_fsync, errno_text, set_errno, c_string, remove_file, is_directory, c_fopen, &
      c_fstat, stat_t, file_type, file_type_regular, c_ftruncate, c_fseek, seek_end, try_lock, name_max, &
      errno_value, errno_exists, c_link, c_getrandom, c_getpid, c_lstat, c_unlink, c_geteuid, names_with_prefix, &
      lock_state, lock_taken, lock_busy, lock_unknown
   use hillstab_batch_output_signals, only: watch_temp_file, forget_temp_file, begin_commit
   use hillstab_batch_output_digest, only: digest_t, digest_update, digest_value
   use hillstab_core_kinds, only: wp
   use, intrinsic :: iso_c_binding, only: c_int, c_char, c_null_char, c_ptr, c_null_ptr, c_associated, c_size_t, c_loc, &
      c_long
   use, intrinsic :: iso_fortran_env, only: error_unit
   implicit none
   private
   public :: output_file_t, open_output, commit_output, discard_output, finish_output, write_header, write_text
   public :: write_records, write_bytes, record_bytes, joined_lines, join_lines, sync_output, lock_output, &
      resume_output, temporary_prefix, &
      digest_written, &
      claim_output

   !> The characters of the suffix of a temporary name (mkstemp's and `random_suffix`'s).
   character(len=*), parameter :: suffix_alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789"

   !> An output file being written under a temporary name.
   type :: output_file_t
      type(c_ptr) :: stream = c_null_ptr             !! C stream of the temporary file
      character(len=:), allocatable :: path          !! final name
      character(len=:), allocatable :: temp_path     !! name while being written
      character(len=:), allocatable :: failure       !! first write failure (the file is then incomplete)
      integer(int64) :: bytes = 0                    !! bytes written so far
      integer :: slot = 0                            !! hillstab_batch_output_signals handle
      logical :: binary = .false.                    !! stream file: text header, then raw records
      !> keep the checksum of every byte written (a run that keeps a checkpoint);
      !> it is brought up to date from the file when a checkpoint needs it (`digest_written`),
      !> so that a run that never makes one never reads its bytes twice
      logical :: digesting = .false.
      type(digest_t) :: digest                       !! the checksum of the first `digested` bytes
      integer(int64) :: digested = 0                 !! how many bytes `digest` covers
   end type output_file_t

contains

   !> Create the temporary file of `path` for writing; fails (err_io) when the place is not
   !> writable or `path` is a directory. With `binary`, the file is a byte stream: text lines
   !> (`write_text`, `write_header`) and then raw records (`write_records`).
   subroutine open_output(file, path, error, binary, context)
      type(output_file_t), intent(out) :: file  !! the open temporary file
      character(len=*), intent(in) :: path  !! final file name
      type(error_t), allocatable, intent(out) :: error  !! err_io when the place is not writable
      logical, intent(in), optional :: binary  !! a byte stream (default: a text file)
      !> put before the error message: what named the path (a task: "<scene>: &scene: output: ")
      character(len=*), intent(in), optional :: context
      character(len=:), allocatable :: prefix, name
      character(kind=c_char), allocatable :: template(:)
      integer(c_int) :: fd, mask, status
      integer :: k, attempt
      prefix = ""
      if (present(context)) prefix = context
      file%path = path
      if (present(binary)) file%binary = binary
      if (is_directory(path)) then
         call set_error(error, err_io, prefix//"cannot write '"//path//"': it is a directory")
         return
      end if
      if (len(path) - index(path, "/", back=.true.) > name_max) then
         call set_error(error, err_io, prefix//"cannot write '"//path//"': File name too long (its last "// &
            "component has "//integer_text(len(path) - index(path, "/", back=.true.))//" bytes, at most "// &
            integer_text(name_max)//")")
         return
      end if
      ! the output's directory is made when missing (each missing component, as mkdir -p)
      call make_directories(path, prefix, error)
      if (allocated(error)) return
      name = temporary_template(path)
      allocate (template(len(name) + 1))
      do attempt = 1, 8
         do k = 1, len(name)
            template(k) = name(k:k)
         end do
         template(len(name) + 1) = c_null_char
         call set_errno(0)
         fd = c_mkstemp(template)
         if (fd < 0) then
            call set_error(error, err_io, prefix//"cannot write '"//path//"': "//errno_text())
            return
         end if
         if (allocated(file%temp_path)) deallocate (file%temp_path)
         allocate (character(len=size(template) - 1) :: file%temp_path)
         do k = 1, size(template) - 1
            file%temp_path(k:k) = template(k)
         end do
         call watch_temp_file(file%temp_path, file%slot)
         ! mkstemp creates the file 0600; the output gets the mode a new file would get
         mask = c_umask(int(o'022', c_int))
         status = c_umask(mask)
         status = c_fchmod(fd, iand(int(o'666', c_int), not(mask)))
         call set_errno(0)
         file%stream = c_fdopen(fd, c_string("w"))
         if (.not. c_associated(file%stream)) then
            call set_error(error, err_io, prefix//"cannot write '"//path//"': "//errno_text())
            status = c_close(fd)
            call remove_file(file%temp_path)
            call forget_temp_file(file%slot)
            return
         end if
         ! the writer's lock, held until the file is closed or the process ends: a later run
         ! of the same output sees the file in use, and one that finds it free knows that its
         ! writer is gone (`claim_output`)
         if (lock_state(file%stream) /= lock_busy .and. still_named(file)) exit
         ! another run's claim took the new file for a stale one in the instant before the
         ! lock (that run removes it): another name
         status = c_fclose(file%stream)
         file%stream = c_null_ptr
         call forget_temp_file(file%slot)
         if (attempt == 8) then
            call set_error(error, err_io, prefix//"cannot write '"//path//"': its temporary files are removed as "// &
               "soon as they are made (another run of the same output?)")
            return
         end if
      end do
      ! the temporary files other runs of this output left: those of a run that is gone are
      ! removed, one that is being written means another run writes the output (refused)
      call claim_output(path, error, prefix, own=file%temp_path)
      if (allocated(error)) call discard_output(file)
   end subroutine open_output

   !> Whether the temporary name of `file` still names its open file.
   logical function still_named(file)
      type(output_file_t), intent(in) :: file
      type(stat_t) :: named, opened
      still_named = .false.
      if (c_lstat(c_string(file%temp_path), named) /= 0) return
      if (c_fstat(c_fileno(file%stream), opened) /= 0) return
      still_named = named%dev == opened%dev .and. named%ino == opened%ino
   end function still_named

   !> Before writing `path`: look at the temporary files of `path` beside it (named as
   !> `open_output` names them, `own` aside). Each is locked by its writer while that writer
   !> runs (`open_output`, `resume_output`): one whose lock is free was left by a run that
   !> stopped without removing it (SIGKILL, a lost node, a power cut) and is removed, with a
   !> note on stderr; one whose lock is held belongs to another run writing the same output,
   !> and the output is refused (err_io, "in use by another run"). Files of another user, not
   !> regular files, and files on a file system without locks are left alone.
   subroutine claim_output(path, error, context, own, program)
      character(len=*), intent(in) :: path  !! the output file
      type(error_t), allocatable, intent(out) :: error  !! err_io: another run writes `path`
      character(len=*), intent(in), optional :: context  !! put before the error message
      character(len=*), intent(in), optional :: own  !! this run's own temporary file
      character(len=*), intent(in), optional :: program  !! the name before the note (default "hillstab")
      character(len=:), allocatable :: prefix, directory, head, names(:), candidate, name
      type(stat_t) :: named, opened
      type(c_ptr) :: stream
      integer(c_int) :: status
      integer :: k, slash, state
      prefix = ""
      if (present(context)) prefix = context
      name = "hillstab"
      if (present(program)) name = program
      head = temporary_prefix(path)
      slash = index(head, "/", back=.true.)
      if (slash == 0) then
         directory = "."
      else if (slash == 1) then
         directory = "/"
      else
         directory = head(:slash - 1)
      end if
      call names_with_prefix(directory, head(slash + 1:), 6, names)
      do k = 1, size(names)
         candidate = head(:slash)//names(k)
         if (present(own)) then
            if (candidate == own) cycle
         end if
         if (verify(names(k)(len(names(k)) - 5:), suffix_alphabet) /= 0) cycle
         if (c_lstat(c_string(candidate), named) /= 0) cycle
         if (iand(named%mode, file_type) /= file_type_regular .or. named%uid /= c_geteuid()) cycle
         stream = c_fopen(c_string(candidate), c_string("r"))
         if (.not. c_associated(stream)) cycle
         state = lock_unknown
         if (c_fstat(c_fileno(stream), opened) == 0) then
            if (opened%dev == named%dev .and. opened%ino == named%ino) state = lock_state(stream)
         end if
         if (state == lock_taken) then
            ! no writer: remove the name while holding its lock, then let the lock go
            status = c_unlink(c_string(candidate))
            if (status == 0) write (error_unit, '(a)') name//": removed '"//candidate//"', a temporary file of "// &
               path//" that a stopped run left (its writer is gone)"
         end if
         status = c_fclose(stream)
         if (state == lock_busy) then
            call set_error(error, err_io, prefix//"cannot write '"//path//"': it is in use by another run (its "// &
               "temporary file '"//candidate//"' is being written): wait until that run ends, or stop it")
            return
         end if
      end do
   end subroutine claim_output

   !> Make the missing directories of the path of a file (its components before the last
   !> '/'), as `mkdir -p` with mode 0777 before the umask.
   subroutine make_directories(path, prefix, error)
      character(len=*), intent(in) :: path    !! the file
      character(len=*), intent(in) :: prefix  !! put before an error message
      type(error_t), allocatable, intent(out) :: error  !! err_io naming the directory that cannot be made
      integer :: k
      integer(c_int) :: status
      do k = 2, len(path)
         if (path(k:k) /= "/") cycle
         if (path(k - 1:k - 1) == "/") cycle
         if (is_directory(path(:k - 1))) cycle
         call set_errno(0)
         status = c_mkdir(c_string(path(:k - 1)), int(o'777', c_int))
         if (status /= 0 .and. .not. is_directory(path(:k - 1))) then
            call set_error(error, err_io, prefix//"cannot write '"//path//"': cannot make the directory '"// &
               path(:k - 1)//"': "//errno_text())
            return
         end if
      end do
   end subroutine make_directories

   !> The mkstemp template of the temporary file of `path`: `<dir>/<name>.partXXXXXX`, the
   !> name cut to at most 244 bytes so that the whole fits in the 255 bytes of a file name.
   pure function temporary_template(path) result(template)
      character(len=*), intent(in) :: path  !! final file name
      character(len=:), allocatable :: template
      integer, parameter :: suffix = len(".partXXXXXX")
      integer :: slash, n
      slash = index(path, "/", back=.true.)
      n = min(len(path) - slash, name_max - suffix)
      template = path(:slash + n)//".partXXXXXX"
   end function temporary_template

   !> The temporary names of `path` before their six unpredictable characters
   !> (`<dir>/<name>.part`, the name cut as `open_output` cuts it).
   pure function temporary_prefix(path) result(prefix)
      character(len=*), intent(in) :: path  !! final file name
      character(len=:), allocatable :: prefix
      character(len=:), allocatable :: template
      template = temporary_template(path)
      prefix = template(:len(template) - 6)
   end function temporary_prefix

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
      ! a signal from here on is held until the program has reported this file
      call begin_commit()
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
      ! the line and its new line in two writes to the buffered stream (line//new_line
      ! would copy a chart's whole block of rows)
      call write_bytes(file, line, error)
      if (.not. allocated(error)) call write_bytes(file, new_line("a"), error)
   end subroutine write_text

   !> `lines` (each trimmed, or cut at `lengths`) joined by new lines, after a leading new
   !> line if `separate`, without a final one: a block of rows written by one `write_text`
   !> (one write per line would cost more than a chart point of method auto). With
   !> `breaks`, one more new line (a blank line: a new gnuplot block) before each line j
   !> where breaks(j). On OpenMP threads call `join_lines` instead: gfortran 12 keeps the
   !> length of a deferred-length function result in a static variable of the caller, so
   !> concurrent calls of this function can return texts of the wrong length.
   pure function joined_lines(lines, separate, breaks, lengths) result(text)
      character(len=*), intent(in) :: lines(:)  !! the rows
      logical, intent(in) :: separate  !! start with a new line (a blank line before the block)
      logical, intent(in), optional :: breaks(:)  !! a blank line before line j (size of lines)
      !> the length of each row (its text is lines(j)(1:lengths(j))); default len_trim
      integer, intent(in), optional :: lengths(:)
      character(len=:), allocatable :: text
      call join_lines(lines, separate, text, breaks, lengths)
   end function joined_lines

   !> `joined_lines` as a subroutine, safe on concurrent OpenMP threads (the text is an
   !> argument, not a function result): the unit texts of the tasks are joined with it.
   pure subroutine join_lines(lines, separate, text, breaks, lengths)
      character(len=*), intent(in) :: lines(:)  !! the rows
      logical, intent(in) :: separate  !! start with a new line (a blank line before the block)
      character(len=:), allocatable, intent(out) :: text  !! the rows joined, no final new line
      logical, intent(in), optional :: breaks(:)  !! a blank line before line j (size of lines)
      !> the length of each row (its text is lines(j)(1:lengths(j))); default len_trim
      integer, intent(in), optional :: lengths(:)
      integer :: j, n, pos, total
      total = merge(1, 0, separate) + max(size(lines) - 1, 0)
      if (present(breaks)) total = total + count(breaks)
      if (present(lengths)) then
         total = total + sum(lengths)
      else
         do j = 1, size(lines)
            total = total + len_trim(lines(j))
         end do
      end if
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
         if (present(lengths)) then
            n = lengths(j)
         else
            n = len_trim(lines(j))
         end if
         text(pos + 1:pos + n) = lines(j)(1:n)
         pos = pos + n
      end do
   end subroutine join_lines

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
   !> Write bytes as they are (no new line added): the records of a unit of work made by
   !> `record_bytes` elsewhere (another thread, another MPI rank), in a binary file.
   subroutine write_bytes(file, bytes, error)
      type(output_file_t), intent(inout) :: file  !! the open output file
      character(len=*), intent(in) :: bytes  !! the bytes
      type(error_t), allocatable, intent(out) :: error  !! err_io when writing fails
      integer(c_size_t) :: written
      if (.not. allocated(file%failure)) then
         if (.not. c_associated(file%stream)) then
            file%failure = "the file is not open"
         else if (len(bytes) > 0) then
            call set_errno(0)
            written = c_fwrite(bytes, 1_c_size_t, int(len(bytes), c_size_t), file%stream)
            if (written /= int(len(bytes), c_size_t)) then
               file%failure = errno_text()
            else
               file%bytes = file%bytes + len(bytes)
            end if
         end if
      end if
      if (allocated(file%failure)) call set_error(error, err_io, "cannot write '"//file%path//"': "// &
         file%failure//" (the file is left as it was)")
   end subroutine write_bytes

   !> The bytes `write_records` writes for `values` (float64 in native order, column-major),
   !> held in a character string: a unit's records travel as its text does.
   pure subroutine record_bytes(values, bytes)
      real(wp), intent(in) :: values(:, :)  !! (columns, records)
      character(len=:), allocatable, intent(out) :: bytes  !! 8 size(values) bytes
      allocate (character(len=(storage_size(values)/8)*size(values)) :: bytes)
      if (size(values) > 0) bytes = transfer(values, bytes)
   end subroutine record_bytes

   !> Put everything written so far on the disk (flush and fsync): afterwards `file%bytes`
   !> bytes are durable. A failure makes the file incomplete, as a failed write does.
   subroutine sync_output(file, error)
      type(output_file_t), intent(inout) :: file  !! the open output file
      type(error_t), allocatable, intent(out) :: error  !! err_io when the flush or fsync failed
      if (.not. allocated(file%failure)) then
         if (.not. c_associated(file%stream)) then
            file%failure = "the file is not open"
         else
            call set_errno(0)
            if (c_fflush(file%stream) /= 0) then
               file%failure = errno_text()
            else if (c_fsync(c_fileno(file%stream)) /= 0) then
               file%failure = errno_text()
            end if
         end if
      end if
      if (allocated(file%failure)) call set_error(error, err_io, "cannot write '"//file%path//"': "// &
         file%failure//" (the file is left as it was)")
   end subroutine sync_output

   !> Take an exclusive advisory lock (flock) on the open file, released when the file is
   !> closed or the process ends; `.false.` also when the file system has no locks.
   !> `busy`: another process holds the lock.
   function lock_output(file) result(busy)
      type(output_file_t), intent(in) :: file  !! the open output file
      logical :: busy
      busy = .false.
      if (c_associated(file%stream)) busy = try_lock(file%stream)
   end function lock_output

   !> Continue the partial output `data_path` of `path` (a file in a directory only this
   !> user can write, which nothing else has open: `lock_output`): with `digest`, its first
   !> `bytes` bytes must have that checksum (hillstab_batch_output_digest), else it is left
   !> as it is and `damaged` is set; it is cut to its first `bytes` bytes, given a new
   !> temporary name beside `path` (a hard link made exclusively, with an unpredictable
   !> suffix: a name someone placed is never written through) and opened for appending, with
   !> `file%bytes` = `bytes` (and, with `digest`, its checksum kept on from there).
   !> `commit_output` then renames it onto `path`, `discard_output` removes only the
   !> temporary name. On failure nothing is changed but the length of the partial file when
   !> the cut was made.
   subroutine resume_output(file, path, data_path, bytes, error, context, digest, damaged)
      type(output_file_t), intent(out) :: file  !! the file, open for writing on
      character(len=*), intent(in) :: path  !! final file name
      character(len=*), intent(in) :: data_path  !! the partial file
      integer(int64), intent(in) :: bytes  !! its valid length
      !> err_io naming the partial file and the cause (another run holds its lock: in use)
      type(error_t), allocatable, intent(out) :: error
      !> put before the error message: what named the path
      character(len=*), intent(in), optional :: context
      !> the checksum (`digest_value`) the first `bytes` bytes must have
      integer(int64), intent(in), optional :: digest(2)
      !> the file is shorter than `bytes`, or its bytes do not have the checksum `digest`
      logical, intent(out), optional :: damaged
      character(len=:), allocatable :: prefix, template, why
      type(stat_t) :: info
      integer(c_int) :: status
      integer :: attempt
      prefix = ""
      if (present(context)) prefix = context
      if (present(damaged)) damaged = .false.
      file%path = path
      call set_errno(0)
      file%stream = c_fopen(c_string(data_path), c_string("r+"))
      if (.not. c_associated(file%stream)) then
         call set_error(error, err_io, prefix//"cannot resume '"//path//"': cannot open '"//data_path//"': "// &
            errno_text())
         return
      end if
      if (c_fstat(c_fileno(file%stream), info) /= 0) then
         call fail_resume(errno_text())
         return
      end if
      if (iand(info%mode, file_type) /= file_type_regular) then
         call fail_resume("not a regular file")
         return
      end if
      if (lock_output(file)) then
         call fail_resume("another run is writing it (it holds the file's lock)")
         return
      end if
      if (int(info%size, int64) < bytes) then
         if (present(damaged)) damaged = .true.
         call fail_resume("it holds "//integer_text(int(info%size, int64))//" bytes, fewer than the "// &
            integer_text(bytes)//" its checkpoint records (damaged)")
         return
      end if
      if (present(digest)) then
         file%digesting = .true.
         call digest_file(data_path, bytes, file%digest, why)
         file%digested = bytes
         if (allocated(why)) then
            call fail_resume(why)
            return
         end if
         if (any(digest_value(file%digest) /= digest)) then
            if (present(damaged)) damaged = .true.
            call fail_resume("its first "//integer_text(bytes)//" bytes do not have the checksum its checkpoint "// &
               "records (damaged: a byte changed, added or removed since)")
            return
         end if
      end if
      call set_errno(0)
      if (c_ftruncate(c_fileno(file%stream), int(bytes, c_long)) /= 0) then
         call fail_resume(errno_text())
         return
      end if
      if (c_fseek(file%stream, 0_c_long, seek_end) /= 0) then
         call fail_resume(errno_text())
         return
      end if
      template = temporary_prefix(path)
      do attempt = 1, 100
         file%temp_path = template//random_suffix(6)
         call set_errno(0)
         if (c_link(c_string(data_path), c_string(file%temp_path)) == 0) exit
         if (errno_value() /= errno_exists .or. attempt == 100) then
            call fail_resume("cannot give it a temporary name beside '"//path//"': "//errno_text())
            deallocate (file%temp_path)
            return
         end if
      end do
      call watch_temp_file(file%temp_path, file%slot)
      file%bytes = bytes
   contains
      !> Close the partial file and say why it cannot be continued.
      subroutine fail_resume(cause)
         character(len=*), intent(in) :: cause
         status = c_fclose(file%stream)
         file%stream = c_null_ptr
         call set_error(error, err_io, prefix//"cannot resume '"//path//"' from '"//data_path//"': "//cause)
      end subroutine fail_resume
   end subroutine resume_output

   !> Bring the checksum of a digesting file up to its `bytes` bytes, reading what was
   !> written since the last call back from the file (call after `sync_output`, so that every
   !> byte is in it): what a checkpoint records. `cause` says why the file could not be read.
   subroutine digest_written(file, cause)
      type(output_file_t), intent(inout) :: file  !! the file being written
      character(len=:), allocatable, intent(out) :: cause  !! why its bytes could not be read
      if (.not. file%digesting .or. file%digested >= file%bytes) return
      call digest_range(file%temp_path, file%digested, file%bytes, file%digest, cause)
      if (.not. allocated(cause)) file%digested = file%bytes
   end subroutine digest_written

   !> The checksum of the first `bytes` bytes of the file `path` (read in pieces of 1 MiB);
   !> `cause` says why it could not be read.
   subroutine digest_file(path, bytes, digest, cause)
      character(len=*), intent(in) :: path
      integer(int64), intent(in) :: bytes
      type(digest_t), intent(out) :: digest
      character(len=:), allocatable, intent(out) :: cause
      call digest_range(path, 0_int64, bytes, digest, cause)
   end subroutine digest_file

   !> Feed the bytes first + 1 … bytes of the file `path` to `digest`.
   subroutine digest_range(path, first, bytes, digest, cause)
      character(len=*), intent(in) :: path
      integer(int64), intent(in) :: first, bytes
      type(digest_t), intent(inout) :: digest
      character(len=:), allocatable, intent(out) :: cause
      integer, parameter :: piece = 1048576
      character(len=:), allocatable :: buffer
      character(len=256) :: message
      integer(int64) :: at, n
      integer :: unit, ios
      open (newunit=unit, file=path, access="stream", form="unformatted", action="read", status="old", iostat=ios, &
            iomsg=message)
      if (ios /= 0) then
         cause = "cannot read it: "//trim(message)
         return
      end if
      allocate (character(len=int(min(int(piece, int64), max(bytes - first, 1_int64)))) :: buffer)
      at = first
      do while (at < bytes)
         n = min(int(len(buffer), int64), bytes - at)
         read (unit, pos=at + 1, iostat=ios, iomsg=message) buffer(:n)
         if (ios /= 0) then
            cause = "cannot read it: "//trim(message)
            exit
         end if
         call digest_update(digest, buffer(:n))
         at = at + n
      end do
      close (unit)
   end subroutine digest_range

   !> `n` characters from [A-Za-z0-9], unpredictable (getrandom; the clock and the process
   !> id should it fail, when a name taken only costs another try).
   function random_suffix(n) result(text)
      integer, intent(in) :: n  !! the length
      character(len=n) :: text
      character(len=*), parameter :: alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789"
      character(kind=c_char) :: bytes(n)
      integer(int64) :: clock, mix
      integer :: k, code
      if (c_getrandom(bytes, int(n, c_size_t), 0_c_int) /= int(n, c_long)) then
         call system_clock(clock)
         mix = ieor(clock, ishft(int(c_getpid(), int64), 32)) + 1
         do k = 1, n
            ! xorshift64
            mix = ieor(mix, ishft(mix, 13))
            mix = ieor(mix, ishft(mix, -7))
            mix = ieor(mix, ishft(mix, 17))
            bytes(k) = achar(int(iand(ishft(mix, -24), 255_int64)))
         end do
      end if
      do k = 1, n
         code = mod(modulo(iachar(bytes(k)), 256), len(alphabet)) + 1
         text(k:k) = alphabet(code:code)
      end do
   end function random_suffix
end module hillstab_batch_output_file

!> Checkpoints of long runs: what a chart, points or lyapunov run has written so far, kept
!> on the disk beside its output so that `hillstab --resume` continues the run after an
!> interruption (a batch system's wall-time limit, a failed node, SIGKILL) and writes the same
!> file as an uninterrupted run. hillstab_batch_run_units decides when (every few seconds of
!> progress, at unit boundaries); this module keeps the files.
!>
!> The checkpoint of the output `<path>` is the directory `<path>.checkpoint`, made with
!> mkdir and mode 0700 (mkdir never follows nor reuses a name someone placed, and nobody else
!> can put a name inside). In it:
!>
!> - `data`: a hard link of the run's temporary output `<path>.partXXXXXX` — the header and
!>   the units written so far. Nothing is written twice: the checkpoint is the partial output
!>   itself, kept by a second name when a signal removes the temporary one.
!> - `state`: text, `key = value` lines: the program version, the problem kind (`problem =
!>   scalar chart`, `system points`: --resume continues only a checkpoint of its own kind),
!>   the output, the temporary name, a fingerprint of the effective scene and its points (hillstab_batch_run_units
!>   `scene_fingerprint`), the effective scene's namelist lines, the units (size, count,
!>   done), the bytes of `data` they fill and their checksum (hillstab_batch_output_digest), and the
!>   counts and first indices of failed and round-off limited points (so that the resumed run
!>   reports what an uninterrupted one reports); its last line, `check = …`, is the checksum
!>   of the lines before it.
!>
!> Nothing is trusted unread: `find_checkpoint` recomputes the state's checksum and checks
!> that its numbers agree with one another (a state that fails is damaged: `--resume`
!> refuses it, naming the checkpoint, and keeps it), and the resumed run recomputes the
!> checksum of the recorded bytes of `data` before it writes a byte (hillstab_batch_output_file
!> `resume_output`). A changed digit, a planted or removed line, an edited header, a byte
!> count, unit count or failed-point count edited in the state: each is refused, never
!> continued into a file that differs from the one an uninterrupted run writes.
!>
!> Order of writes: `data` is flushed and fsynced, then the new state goes to `state.new`, is
!> fsynced and renamed onto `state`, then the directory is fsynced. So the state never claims
!> more bytes than are on the disk; bytes beyond it (a unit written after the last update, a
!> partial write) are cut on resume. Anything at the checkpoint's name that is not a
!> directory of this user closed to others (a symbolic link, a file, a hard link, another
!> user's directory) is refused, never followed, written or removed; so is a checkpoint whose
!> `data` or `state` is not a regular file (a FIFO, whose open would block; a directory; a
!> symbolic link): it is kept as it is, never opened. A run holds an advisory
!> lock (flock) on `data`: a second run of the same output is refused while the first runs.
!>
!>```fortran
!> type(checkpoint_state_t) :: state
!> type(error_t), allocatable :: error
!> character(len=:), allocatable :: reason
!> integer :: kind
!> call find_checkpoint(checkpoint_directory("out/map_lyapunov.dat"), kind, state, reason, error)
!> if (kind == checkpoint_usable) print '(a)', "units done: ", state%units_done
!>```
module hillstab_batch_output_checkpoint
   use hillstab_core_kinds, only: wp, int64
   use hillstab_core_error, only: error_t, set_error, err_io
   use hillstab_core_text, only: integer_text
   use hillstab_batch_output_digest, only: text_digest
   use hillstab_ffi_libc, only: c_lstat, c_fstat, stat_t, c_mkdir, c_link, c_rmdir, c_unlink, c_rename, c_geteuid, &
      c_fopen, c_fclose, c_fwrite, c_fflush, c_fsync, c_fileno, try_lock, name_max, &
      file_type, file_type_directory, file_type_link, file_type_regular, errno_text, errno_value, set_errno, &
      errno_no_entry, c_string, is_special_file
   use, intrinsic :: iso_c_binding, only: c_int, c_ptr, c_size_t, c_associated
   use, intrinsic :: iso_fortran_env, only: error_unit
   implicit none
   private
   public :: checkpoint_options_t, checkpoint_state_t, checkpoint_directory, checkpoint_data, find_checkpoint, &
      make_checkpoint, save_checkpoint_state, remove_checkpoint, remove_stale_temporary, scene_difference, &
      checkpoint_note, scene_lines, fnv1a_step
   public :: checkpoint_usable, checkpoint_incomplete, checkpoint_damaged

   !> Seconds between two updates of a checkpoint by default.
   real(wp), parameter :: default_interval = 3.0_wp
   !> What `find_checkpoint` found: nothing at the name
   integer, parameter :: checkpoint_none = 0
   !> a checkpoint with its data and a readable state
   integer, parameter :: checkpoint_usable = 1
   !> a checkpoint directory without data or without a readable state (its run stopped
   !> while making it, or an older version wrote it); discarded, never resumed
   integer, parameter :: checkpoint_incomplete = 2
   !> a checkpoint whose state fails its checksum or contradicts itself (damaged since it was
   !> written); `--resume` refuses it, a run without discards it
   integer, parameter :: checkpoint_damaged = 3
   !> The first line of a state file.
   character(len=*), parameter :: state_format = "hillstab checkpoint 3"
   !> Longest state file read (the effective scene's lines are at most 1 MiB).
   integer, parameter :: max_state_bytes = 4194304
   !> Suffix of a checkpoint directory.
   character(len=*), parameter :: suffix = ".checkpoint"

   !> How a run treats checkpoints (the command line's `--resume`, `--checkpoint-interval`).
   type :: checkpoint_options_t
      logical :: resume = .false.  !! continue from an existing checkpoint (else discard it)
      real(wp) :: interval = default_interval  !! seconds between updates (0: after every unit)
      character(len=:), allocatable :: program  !! the program's name, before its notes ("hillstab")
      !> how to resume the run, for messages ("hillstab --resume scene.nml")
      character(len=:), allocatable :: command
   end type checkpoint_options_t

   !> What a checkpoint records: which run, how far it got.
   type :: checkpoint_state_t
      character(len=:), allocatable :: version    !! version of the program that wrote it
      !> the kind of problem and the task ("scalar chart", "system points"): --resume continues
      !> only a checkpoint of the run's own kind
      character(len=:), allocatable :: problem
      character(len=:), allocatable :: output     !! the output file
      character(len=:), allocatable :: temporary  !! the temporary name of the data (left by SIGKILL)
      integer(int64) :: fingerprint(2) = 0        !! of the effective scene and its points
      integer(int64) :: n_points = 0              !! points of the run
      integer :: unit_size = 0                    !! points per unit
      integer :: n_units = 0                      !! units of the run
      integer :: units_done = 0                   !! units 1 … units_done are in the data
      integer(int64) :: bytes = 0                 !! bytes of the data they fill (with the header)
      integer(int64) :: digest(2) = 0             !! the checksum of those bytes (hillstab_batch_output_digest)
      integer(int64) :: n_inaccurate = 0          !! round-off limited points among them
      integer(int64) :: first_inaccurate = 0      !! index of the first of them (0: none)
      integer(int64) :: n_failed = 0              !! failed points among them
      integer(int64) :: first_failed = 0          !! index of the first of them (0: none)
      !> the effective scene's namelist lines, each ended by a new line (one string: gfortran 12
      !> copies a deferred-length array component wrongly in intrinsic assignment)
      character(len=:), allocatable :: scene
   end type checkpoint_state_t

contains

   !> The checkpoint directory of the output `path`: `<path>.checkpoint`; a name too long for
   !> that is cut and completed by a hash of the whole, so that it fits where `path` fits.
   function checkpoint_directory(path) result(directory)
      character(len=*), intent(in) :: path  !! the output file
      character(len=:), allocatable :: directory
      integer :: slash, n
      slash = index(path, "/", back=.true.)
      n = len(path) - slash
      if (n + len(suffix) <= name_max) then
         directory = path//suffix
      else
         directory = path(:slash + name_max - len(suffix) - 9)//"-"//hash_text(path)//suffix
      end if
   end function checkpoint_directory

   !> The data file of a checkpoint directory.
   pure function checkpoint_data(directory) result(path)
      character(len=*), intent(in) :: directory  !! the checkpoint directory
      character(len=:), allocatable :: path
      path = directory//"/data"
   end function checkpoint_data

   !> Eight hexadecimal digits of a 32-bit FNV-1a hash of `text`.
   function hash_text(text) result(hex)
      character(len=*), intent(in) :: text
      character(len=8) :: hex
      character(len=*), parameter :: digits = "0123456789abcdef"
      integer(int64) :: hash
      integer :: k
      hash = 2166136261_int64
      do k = 1, len(text)
         hash = fnv1a_step(hash, int(iachar(text(k:k)), int64))
      end do
      do k = 8, 1, -1
         hex(k:k) = digits(int(mod(hash, 16_int64)) + 1:int(mod(hash, 16_int64)) + 1)
         hash = hash/16
      end do
   end function hash_text

   !> One step of the 32-bit FNV-1a hash: `value` mixed into `hash`.
   elemental integer(int64) function fnv1a_step(hash, value) result(next)
      integer(int64), intent(in) :: hash   !! the hash so far, in [0, 2^32)
      integer(int64), intent(in) :: value  !! the next byte or word, in [0, 2^32)
      next = mod(ieor(hash, value)*16777619_int64, 4294967296_int64)
   end function fnv1a_step

   !> What is at the checkpoint name `directory`: nothing, a usable checkpoint (`state`
   !> read), an incomplete one or a damaged one (`reason` says what it lacks or what is
   !> wrong). `error` (err_io) when
   !> something else is in the way — a symbolic link, a file, a directory of another user
   !> or open to others (never followed nor removed), a checkpoint whose `data` or `state`
   !> is not a regular file (never opened: a FIFO would block the open; kept as it is) —
   !> or when another run holds the checkpoint's lock.
   subroutine find_checkpoint(directory, kind, state, reason, error)
      character(len=*), intent(in) :: directory  !! the checkpoint directory (`checkpoint_directory`)
      !> checkpoint_none, checkpoint_usable, checkpoint_incomplete or checkpoint_damaged
      integer, intent(out) :: kind
      type(checkpoint_state_t), intent(out) :: state  !! a usable checkpoint's state
      character(len=:), allocatable, intent(out) :: reason  !! why a checkpoint is incomplete or damaged
      !> err_io: "cannot keep the checkpoint '…': <why>" (the caller names the scene)
      type(error_t), allocatable, intent(out) :: error
      type(stat_t) :: info
      type(c_ptr) :: stream
      integer(c_int) :: status
      logical :: busy
      kind = checkpoint_none
      reason = ""
      ! nothing there (or no way there: the output's own checks name the cause)
      if (c_lstat(c_string(directory), info) /= 0) return
      if (iand(info%mode, file_type) == file_type_link) then
         call in_the_way("it is a symbolic link (not followed)")
         return
      else if (iand(info%mode, file_type) /= file_type_directory) then
         if (iand(info%mode, file_type) == file_type_regular) then
            call in_the_way("it is a file, not a directory hillstab made (not opened)")
         else
            call in_the_way("it is not a directory hillstab made (not opened)")
         end if
         return
      else if (info%uid /= c_geteuid()) then
         call in_the_way("it belongs to another user (uid "//integer_text(int(info%uid))//")")
         return
      else if (iand(info%mode, int(o'077', c_int)) /= 0) then
         call in_the_way("other users may write or read it (mode "//octal_text(iand(info%mode, int(o'7777', c_int)))// &
            "), so it is not one hillstab made")
         return
      end if
      ! neither member is opened unless it is a regular file
      call check_member(checkpoint_data(directory), "data")
      if (.not. allocated(error)) call check_member(directory//"/state", "state")
      if (allocated(error)) return
      kind = checkpoint_incomplete
      call set_errno(0)
      stream = c_fopen(c_string(checkpoint_data(directory)), c_string("r"))
      if (.not. c_associated(stream)) then
         reason = "it has no data ("//errno_text()//")"
         return
      end if
      busy = try_lock(stream)
      status = c_fstat(c_fileno(stream), info)
      status = c_fclose(stream)
      if (busy) then
         call set_error(error, err_io, "the checkpoint '"//directory//"' is in use by another run (it holds the "// &
            "checkpoint's lock): wait until that run ends, or stop it")
         return
      end if
      if (iand(info%mode, file_type) /= file_type_regular) then
         reason = "its data is not a regular file"
         return
      end if
      kind = read_state(directory, state, reason)
   contains
      subroutine in_the_way(why)
         character(len=*), intent(in) :: why
         call set_error(error, err_io, "cannot keep the checkpoint '"//directory//"': "//why// &
            "; remove it, or choose another output")
      end subroutine in_the_way
      !> A member that exists and is not a regular file: refused, the checkpoint kept.
      subroutine check_member(path, name)
         character(len=*), intent(in) :: path, name
         type(stat_t) :: member
         character(len=:), allocatable :: what
         if (c_lstat(c_string(path), member) /= 0) return
         if (iand(member%mode, file_type) == file_type_regular) return
         if (iand(member%mode, file_type) == file_type_link) then
            what = "a symbolic link (not followed)"
         else if (iand(member%mode, file_type) == file_type_directory) then
            what = "a directory"
         else if (is_special_file(path)) then
            what = "not a regular file (a FIFO, device or socket; not opened)"
         else
            what = "not a regular file"
         end if
         call set_error(error, err_io, "cannot use the checkpoint '"//directory//"': its "//name//" '"//path// &
            "' is "//what//", not a file hillstab made; the checkpoint is kept as it is: remove it, or "// &
            "choose another output")
      end subroutine check_member
   end subroutine find_checkpoint

   !> Permission bits as four octal digits.
   pure function octal_text(mode) result(text)
      integer(c_int), intent(in) :: mode
      character(len=4) :: text
      integer :: k, m
      m = int(mode)
      do k = 4, 1, -1
         text(k:k) = achar(iachar("0") + mod(m, 8))
         m = m/8
      end do
   end function octal_text

   !> Read the state file of a checkpoint: checkpoint_usable, or checkpoint_incomplete
   !> (missing, of another format) or checkpoint_damaged (its checksum fails, a line cannot be
   !> read, its numbers contradict one another) with `reason`.
   function read_state(directory, state, reason) result(kind)
      character(len=*), intent(in) :: directory
      type(checkpoint_state_t), intent(inout) :: state
      character(len=:), allocatable, intent(inout) :: reason
      integer :: kind
      character(len=:), allocatable :: text, line, key, value, collected
      character(len=*), parameter :: check_key = "check = "
      integer :: ios, at, n_scene, start, end_of_line, last
      logical :: have(10), exists
      integer(int64) :: size
      kind = checkpoint_incomplete
      inquire (file=directory//"/state", exist=exists, size=size)
      if (.not. exists) then
         reason = "it has no state (its run stopped before the first checkpoint was complete)"
         return
      end if
      if (size > max_state_bytes .or. size < 0) then
         kind = checkpoint_damaged
         reason = "its state is damaged ("//integer_text(size)//" bytes, more than a state holds)"
         return
      end if
      call read_whole(directory//"/state", int(size), text, ios)
      if (ios /= 0) then
         reason = "its state cannot be read"
         return
      end if
      if (index(text, state_format//new_line("a")) /= 1) then
         reason = "its state is not one this version reads"
         return
      end if
      kind = checkpoint_damaged
      ! the last line is the checksum of the text before it
      last = index(text(:max(len(text) - 1, 0)), new_line("a"), back=.true.)
      if (len(text) < 2 .or. text(len(text):) /= new_line("a") .or. last == 0) then
         reason = "its state is damaged (cut short)"
         return
      end if
      if (text(last + 1:len(text) - 1) /= check_key//text_digest(text(:last))) then
         reason = "its state is damaged (it does not match the checksum of its last line)"
         return
      end if
      have = .false.
      collected = ""
      n_scene = 0
      ios = 0
      start = len(state_format) + 2
      do while (start <= last)
         end_of_line = start + index(text(start:last), new_line("a")) - 2
         line = text(start:end_of_line)
         start = end_of_line + 2
         if (len(line) == 0) cycle
         if (line(1:1) == "#") cycle
         at = index(line, " = ")
         if (at == 0) then
            ios = 1
            exit
         end if
         key = line(:at - 1)
         value = line(at + 3:)
         select case (key)
         case ("version")
            state%version = value
            have(1) = .true.
         case ("problem")
            state%problem = value
            have(10) = .true.
         case ("output")
            state%output = value
            have(2) = .true.
         case ("temporary")
            state%temporary = value
         case ("fingerprint")
            read (value, *, iostat=ios) state%fingerprint
            have(3) = .true.
         case ("points")
            read (value, *, iostat=ios) state%n_points
            have(4) = .true.
         case ("units")
            read (value, *, iostat=ios) state%units_done, state%n_units, state%unit_size
            have(5) = .true.
         case ("bytes")
            read (value, *, iostat=ios) state%bytes
            have(6) = .true.
         case ("inaccurate")
            read (value, *, iostat=ios) state%n_inaccurate, state%first_inaccurate
            have(7) = .true.
         case ("failed")
            read (value, *, iostat=ios) state%n_failed, state%first_failed
            have(8) = .true.
         case ("digest")
            read (value, *, iostat=ios) state%digest
            have(9) = .true.
         case ("scene")
            collected = collected//value//new_line("a")
            n_scene = n_scene + 1
         case default
            ios = 1
         end select
         if (ios /= 0) exit
      end do
      if (ios /= 0 .or. .not. all(have) .or. n_scene == 0) then
         reason = "its state is damaged (a line cannot be read)"
         return
      end if
      reason = inconsistency(state)
      if (len(reason) > 0) then
         reason = "its state is damaged ("//reason//")"
         return
      end if
      state%scene = collected
      kind = checkpoint_usable
   end function read_state

   !> What in a state contradicts the rest ("" when nothing): the units and points, the
   !> points done against the counts and first indices of failed and inaccurate points.
   pure function inconsistency(state) result(text)
      type(checkpoint_state_t), intent(in) :: state
      character(len=:), allocatable :: text
      integer(int64) :: done
      text = ""
      if (state%unit_size < 1 .or. state%n_units < 1 .or. state%n_points < 1 .or. state%bytes < 1) then
         text = "units, points or bytes below 1"
      else if (state%units_done < 0 .or. state%units_done > state%n_units) then
         text = "units done outside 0 ... units"
      else if (int(state%n_units, int64) /= (state%n_points + state%unit_size - 1)/state%unit_size) then
         text = "the units do not tile the points"
      else if (any(state%digest < 0) .or. any(state%digest > 4294967295_int64)) then
         text = "a checksum out of range"
      end if
      if (len(text) > 0) return
      done = min(state%n_points, int(state%units_done, int64)*state%unit_size)
      if (state%n_failed < 0 .or. state%n_failed > done .or. (state%n_failed > 0 .neqv. state%first_failed > 0) &
          .or. state%first_failed < 0 .or. state%first_failed > done) then
         text = "failed points that the points done cannot hold"
      else if (state%n_inaccurate < 0 .or. state%n_inaccurate > done .or. (state%n_inaccurate > 0 .neqv. &
               state%first_inaccurate > 0) .or. state%first_inaccurate < 0 .or. state%first_inaccurate > done) then
         text = "round-off limited points that the points done cannot hold"
      end if
   end function inconsistency

   !> The `size` bytes of the file `path` as one string; `ios` /= 0 when it cannot be read.
   subroutine read_whole(path, size, text, ios)
      character(len=*), intent(in) :: path
      integer, intent(in) :: size
      character(len=:), allocatable, intent(out) :: text
      integer, intent(out) :: ios
      integer :: unit
      allocate (character(len=size) :: text)
      open (newunit=unit, file=path, access="stream", form="unformatted", action="read", status="old", iostat=ios)
      if (ios /= 0) return
      if (size > 0) read (unit, iostat=ios) text
      close (unit)
   end subroutine read_whole

   !> The lines of a text whose every line ends with a new line, as an array.
   pure function scene_lines(text) result(lines)
      character(len=*), intent(in) :: text  !! lines, each ended by a new line
      character(len=:), allocatable :: lines(:)
      integer :: k, n, start, at, width
      n = count([(text(k:k) == new_line("a"), k=1, len(text))])
      width = 0
      start = 1
      do k = 1, n
         at = start + index(text(start:), new_line("a")) - 1
         width = max(width, at - start)
         start = at + 1
      end do
      allocate (character(len=width) :: lines(n))
      start = 1
      do k = 1, n
         at = start + index(text(start:), new_line("a")) - 1
         lines(k) = text(start:at - 1)
         start = at + 1
      end do
   end function scene_lines

   !> Write `state` durably: to `state.new`, fsynced, renamed onto `state`, the directory
   !> fsynced (the caller has put the data it describes on the disk first).
   subroutine save_checkpoint_state(directory, state, error)
      character(len=*), intent(in) :: directory  !! the checkpoint directory
      type(checkpoint_state_t), intent(in) :: state  !! what it records
      type(error_t), allocatable, intent(out) :: error  !! err_io naming the file and the cause
      character(len=:), allocatable :: text, cause
      type(c_ptr) :: stream
      integer(c_size_t) :: written
      integer(c_int) :: status
      integer :: start, at
      text = state_format//new_line("a")// &
         "# the progress of an interrupted run, read by --resume; remove this directory to discard it"// &
         new_line("a")// &
         "version = "//state%version//new_line("a")// &
         "problem = "//state%problem//new_line("a")// &
         "output = "//state%output//new_line("a")// &
         "temporary = "//state%temporary//new_line("a")// &
         "fingerprint = "//integer_text(state%fingerprint(1))//" "//integer_text(state%fingerprint(2))//new_line("a")// &
         "points = "//integer_text(state%n_points)//new_line("a")// &
         "units = "//integer_text(state%units_done)//" "//integer_text(state%n_units)//" "// &
         integer_text(state%unit_size)//new_line("a")// &
         "bytes = "//integer_text(state%bytes)//new_line("a")// &
         "digest = "//integer_text(state%digest(1))//" "//integer_text(state%digest(2))//new_line("a")// &
         "inaccurate = "//integer_text(state%n_inaccurate)//" "//integer_text(state%first_inaccurate)//new_line("a")// &
         "failed = "//integer_text(state%n_failed)//" "//integer_text(state%first_failed)//new_line("a")
      start = 1
      do while (start <= len(state%scene))
         at = start + index(state%scene(start:), new_line("a")) - 1
         if (at < start) at = len(state%scene) + 1
         text = text//"scene = "//state%scene(start:at - 1)//new_line("a")
         start = at + 1
      end do
      text = text//"check = "//text_digest(text)//new_line("a")
      call set_errno(0)
      stream = c_fopen(c_string(directory//"/state.new"), c_string("w"))
      if (.not. c_associated(stream)) then
         call set_error(error, err_io, "cannot write '"//directory//"/state.new': "//errno_text())
         return
      end if
      written = c_fwrite(text, 1_c_size_t, int(len(text), c_size_t), stream)
      if (written /= int(len(text), c_size_t)) then
         cause = errno_text()
      else if (c_fflush(stream) /= 0) then
         cause = errno_text()
      else if (c_fsync(c_fileno(stream)) /= 0) then
         cause = errno_text()
      end if
      call set_errno(0)
      status = c_fclose(stream)
      if (status /= 0 .and. .not. allocated(cause)) cause = errno_text()
      if (.not. allocated(cause)) then
         if (c_rename(c_string(directory//"/state.new"), c_string(directory//"/state")) /= 0) cause = errno_text()
      end if
      if (allocated(cause)) then
         status = c_unlink(c_string(directory//"/state.new"))
         call set_error(error, err_io, "cannot write '"//directory//"/state': "//cause)
         return
      end if
      call sync_directory(directory)
   end subroutine save_checkpoint_state

   !> fsync a directory, so that the names made or renamed in it are on the disk.
   subroutine sync_directory(directory)
      character(len=*), intent(in) :: directory
      type(c_ptr) :: stream
      integer(c_int) :: status
      stream = c_fopen(c_string(directory), c_string("r"))
      if (.not. c_associated(stream)) return
      status = c_fsync(c_fileno(stream))
      status = c_fclose(stream)
   end subroutine sync_directory

   !> The directory of a path ("." when it has none).
   pure function directory_of(path) result(directory)
      character(len=*), intent(in) :: path
      character(len=:), allocatable :: directory
      integer :: slash
      slash = index(path, "/", back=.true.)
      if (slash == 0) then
         directory = "."
      else if (slash == 1) then
         directory = "/"
      else
         directory = path(:slash - 1)
      end if
   end function directory_of

   !> Make the checkpoint `directory` (mode 0700, exclusively) holding `temporary` (the
   !> run's temporary output, its data written up to `state%bytes` and on the disk) as `data`
   !> and `state`. On failure nothing is left.
   subroutine make_checkpoint(directory, temporary, state, error)
      character(len=*), intent(in) :: directory  !! the checkpoint directory to make
      character(len=*), intent(in) :: temporary  !! the temporary output file
      type(checkpoint_state_t), intent(in) :: state  !! what it records
      type(error_t), allocatable, intent(out) :: error  !! err_io naming what failed and why
      integer(c_int) :: status
      call set_errno(0)
      if (c_mkdir(c_string(directory), int(o'700', c_int)) /= 0) then
         call set_error(error, err_io, "cannot make the checkpoint '"//directory//"': "//errno_text())
         return
      end if
      call set_errno(0)
      if (c_link(c_string(temporary), c_string(checkpoint_data(directory))) /= 0) then
         call set_error(error, err_io, "cannot keep a checkpoint in '"//directory//"': cannot link '"//temporary// &
            "' there: "//errno_text())
         status = c_rmdir(c_string(directory))
         return
      end if
      call save_checkpoint_state(directory, state, error)
      if (allocated(error)) then
         status = c_unlink(c_string(checkpoint_data(directory)))
         status = c_rmdir(c_string(directory))
         return
      end if
      call sync_directory(directory_of(directory))
   end subroutine make_checkpoint

   !> Remove a checkpoint this user's run made (the state first: a crash in between leaves
   !> an incomplete checkpoint, never a state without its data).
   subroutine remove_checkpoint(directory, error)
      character(len=*), intent(in) :: directory  !! the checkpoint directory
      type(error_t), allocatable, intent(out) :: error  !! err_io when the directory cannot be removed
      integer(c_int) :: status
      status = c_unlink(c_string(directory//"/state"))
      status = c_unlink(c_string(directory//"/state.new"))
      status = c_unlink(c_string(checkpoint_data(directory)))
      call set_errno(0)
      if (c_rmdir(c_string(directory)) /= 0) then
         if (errno_value() /= errno_no_entry) then
            call set_error(error, err_io, "cannot remove the checkpoint '"//directory//"': "//errno_text())
            return
         end if
      end if
      call sync_directory(directory_of(directory))
   end subroutine remove_checkpoint

   !> Remove the temporary output a killed run left (the state's `temporary`), when it is
   !> still a name of the checkpoint's data beside the output, named as the writer names its
   !> temporary files (`prefix` and six characters); anything else is left alone.
   subroutine remove_stale_temporary(directory, state, prefix)
      character(len=*), intent(in) :: directory  !! the checkpoint directory
      type(checkpoint_state_t), intent(in) :: state  !! its state
      character(len=*), intent(in) :: prefix  !! the temporary names of the output before their suffix
      type(stat_t) :: stale, data
      integer(c_int) :: status
      if (.not. allocated(state%temporary)) return
      if (len(state%temporary) /= len(prefix) + 6) return
      if (state%temporary(:len(prefix)) /= prefix) return
      if (c_lstat(c_string(state%temporary), stale) /= 0) return
      if (c_lstat(c_string(checkpoint_data(directory)), data) /= 0) return
      if (iand(stale%mode, file_type) /= file_type_regular) return
      if (stale%dev /= data%dev .or. stale%ino /= data%ino) return
      status = c_unlink(c_string(state%temporary))
   end subroutine remove_stale_temporary

   !> How the effective scene `lines` differs from a checkpoint's `saved` lines, as
   !> "&group: variable: <value> in this scene, <value> in the checkpoint" for the first
   !> difference; "" when they are the same.
   function scene_difference(saved, lines) result(text)
      character(len=*), intent(in) :: saved(:)  !! the checkpoint's scene
      character(len=*), intent(in) :: lines(:)  !! this run's scene
      character(len=:), allocatable :: text
      character(len=:), allocatable :: names(:), values(:), old_names(:), old_values(:)
      integer :: i, j, k
      text = ""
      do i = 1, size(lines)
         j = group_index(saved, group_name(lines(i)))
         if (j == 0) then
            text = group_name(lines(i))//": this scene has the group, the checkpoint's scene has not"
            return
         end if
         if (trim(saved(j)) == trim(lines(i))) cycle
         call scene_items(lines(i), names, values)
         call scene_items(saved(j), old_names, old_values)
         do k = 1, min(size(names), size(old_names))
            if (names(k) /= old_names(k)) exit
            if (values(k) /= old_values(k)) then
               text = group_name(lines(i))//": "//trim(names(k))//": "//trim(values(k))//" in this scene, "// &
                  trim(old_values(k))//" in the checkpoint"
               return
            end if
         end do
         text = group_name(lines(i))//": '"//trim(lines(i))//"' in this scene, '"//trim(saved(j))//"' in the checkpoint"
         return
      end do
      do j = 1, size(saved)
         if (group_index(lines, group_name(saved(j))) == 0) then
            text = group_name(saved(j))//": the checkpoint's scene has the group, this scene has not"
            return
         end if
      end do
   end function scene_difference

   !> "&chart" of "&chart alpha_min = 0.0, … /".
   pure function group_name(line) result(name)
      character(len=*), intent(in) :: line
      character(len=:), allocatable :: name
      integer :: blank
      blank = index(trim(line), " ")
      if (blank == 0) then
         name = trim(line)
      else
         name = line(:blank - 1)
      end if
   end function group_name

   !> The index of the line of group `name` (0: none).
   pure integer function group_index(lines, name)
      character(len=*), intent(in) :: lines(:)
      character(len=*), intent(in) :: name
      integer :: k
      group_index = 0
      do k = 1, size(lines)
         if (group_name(lines(k)) == name) then
            group_index = k
            return
         end if
      end do
   end function group_index

   !> The items `name = value` of a namelist line "&group a = 1, b = 'x, y' /" (commas within
   !> quotes kept).
   pure subroutine scene_items(line, names, values)
      character(len=*), intent(in) :: line
      character(len=:), allocatable, intent(out) :: names(:), values(:)
      character(len=:), allocatable :: body, item
      integer :: k, n, start, at, pass
      logical :: quoted
      body = trim(line)
      k = index(body, " ")
      if (k == 0) then
         allocate (character(len=1) :: names(0), values(0))
         return
      end if
      body = body(k + 1:)
      if (len(body) >= 2) then
         if (body(len(body) - 1:) == " /") body = body(:len(body) - 2)
      end if
      ! pass 1 counts the items, pass 2 stores them
      do pass = 1, 2
         n = 0
         start = 1
         quoted = .false.
         do k = 1, len(body) + 1
            if (k <= len(body)) then
               if (body(k:k) == "'") quoted = .not. quoted
               if (quoted .or. body(k:k) /= ",") cycle
            end if
            n = n + 1
            if (pass == 2) then
               item = trim(adjustl(body(start:k - 1)))
               at = index(item, " = ")
               if (at == 0) then
                  names(n) = item
                  values(n) = ""
               else
                  names(n) = item(:at - 1)
                  values(n) = item(at + 3:)
               end if
            end if
            start = k + 1
         end do
         if (pass == 1) allocate (character(len=len(body)) :: names(n), values(n))
      end do
   end subroutine scene_items

   !> Print "<program>: <text>" on stderr.
   subroutine checkpoint_note(options, text)
      type(checkpoint_options_t), intent(in) :: options  !! the program's name
      character(len=*), intent(in) :: text  !! the note
      character(len=:), allocatable :: program
      program = "hillstab"
      if (allocated(options%program)) program = options%program
      write (error_unit, '(a)') program//": "//text
      flush (error_unit)
   end subroutine checkpoint_note
end module hillstab_batch_output_checkpoint

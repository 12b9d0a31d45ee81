!> Temporary files that must not outlive an interrupted run.
!>
!> The output writer registers each temporary file while it is being written
!> (`watch_temp_file`) and forgets it once renamed or deleted (`forget_temp_file`).
!> A program that calls `install_signal_cleanup` (the hillstab command line does;
!> library code never installs handlers in its caller's process) then removes the
!> registered files on SIGINT, SIGTERM and SIGHUP and exits with status 128 + signal.
!> SIGXFSZ (a file-size limit) is ignored instead, so the write that crosses the
!> limit fails with EFBIG and the writer reports it and deletes its temporary file.
!>
!> The outcome reported is the outcome on disk: from just before a finished file is
!> renamed onto its name (`begin_commit`) until the program has reported that scene
!> (`settle_signals`), a signal is held, not acted on; `settle_signals` then says that it
!> arrived after the file was written, and the program stops there with the status of
!> what it wrote (the scenes after it not run: 128 + signal).
!>
!> A run that keeps a checkpoint (hillstab_batch_output_checkpoint) registers a note
!> (`set_interrupt_note`): the handler prints it on stderr, with the signal's number, before
!> it exits, saying that the checkpoint is kept and how to resume the run.
!>
!> The handler touches only fixed character buffers and calls `unlink`, `write` and
!> `_exit`, all async-signal-safe.
!>
!>```fortran
!> call install_signal_cleanup()
!>```
module hillstab_batch_output_signals
   use hillstab_ffi_libc, only: c_signal, c_unlink, c_exit_now, c_write
   use, intrinsic :: iso_c_binding, only: c_int, c_char, c_null_char, c_funptr, c_funloc, c_intptr_t, c_size_t, c_long
   implicit none
   private
   public :: install_signal_cleanup, watch_temp_file, forget_temp_file, max_watched_path, begin_commit, &
      settle_signals, set_interrupt_note, clear_interrupt_note
   public :: signal_hangup, signal_interrupt, signal_terminate, signal_file_size

   integer, parameter :: signal_hangup = 1      !! SIGHUP (Linux)
   integer, parameter :: signal_interrupt = 2   !! SIGINT
   integer, parameter :: signal_terminate = 15  !! SIGTERM
   integer, parameter :: signal_file_size = 25  !! SIGXFSZ (Linux)
   !> Longest path that can be watched (longer paths are not removed on a signal).
   integer, parameter :: max_watched_path = 4096
   !> Number of temporary files watched at the same time.
   integer, parameter :: n_slots = 8

   !> Watched paths, NUL-terminated; a slot is free when its first character is NUL.
   character(kind=c_char), volatile, save :: watched(max_watched_path + 1, n_slots) = c_null_char
   !> 1 while a file is being committed and reported: signals are held
   integer(c_int), volatile, save :: holding = 0
   !> the signal held (0: none)
   integer(c_int), volatile, save :: held = 0
   !> Longest part of an interrupt note.
   integer, parameter :: max_note = 8192
   !> The interrupt note: its text before the signal's number and after it
   character(kind=c_char), volatile, save :: note_head(max_note) = c_null_char
   character(kind=c_char), volatile, save :: note_tail(max_note) = c_null_char
   !> the lengths of the two parts (0: no note)
   integer(c_size_t), volatile, save :: head_length = 0, tail_length = 0


contains

   !> Remove watched temporary files on SIGINT, SIGTERM, SIGHUP (then exit 128 + signal);
   !> ignore SIGXFSZ so that exceeding a file-size limit is a write error the writer handles.
   subroutine install_signal_cleanup()
      type(c_funptr) :: previous
      type(c_funptr) :: ignore
      ignore = transfer(1_c_intptr_t, ignore)  ! SIG_IGN
      previous = c_signal(int(signal_hangup, c_int), c_funloc(on_signal))
      previous = c_signal(int(signal_interrupt, c_int), c_funloc(on_signal))
      previous = c_signal(int(signal_terminate, c_int), c_funloc(on_signal))
      previous = c_signal(int(signal_file_size, c_int), ignore)
   end subroutine install_signal_cleanup

   !> Register `path` for removal on a signal; `slot` (0: none free or path too long)
   !> is given back to `forget_temp_file`.
   subroutine watch_temp_file(path, slot)
      character(len=*), intent(in) :: path  !! the temporary file
      integer, intent(out) :: slot          !! handle for forget_temp_file
      integer :: k, i
      slot = 0
      if (len(path) == 0 .or. len(path) > max_watched_path) return
      do k = 1, n_slots
         if (watched(1, k) == c_null_char) then
            slot = k
            exit
         end if
      end do
      if (slot == 0) return
      ! the first character last: the handler sees either a free slot or a whole path
      do i = 2, len(path)
         watched(i, slot) = path(i:i)
      end do
      watched(len(path) + 1, slot) = c_null_char
      watched(1, slot) = path(1:1)
   end subroutine watch_temp_file

   !> Stop watching the file of `slot` (0 is ignored).
   subroutine forget_temp_file(slot)
      integer, intent(in) :: slot  !! the slot returned by watch_temp_file
      if (slot < 1 .or. slot > n_slots) return
      watched(1, slot) = c_null_char
   end subroutine forget_temp_file

   !> Print `head`, the signal's number and `tail` (then a new line) on stderr when a signal
   !> ends the run; parts longer than 8192 bytes are cut.
   subroutine set_interrupt_note(head, tail)
      character(len=*), intent(in) :: head  !! the text before the number ("hillstab: stopped by signal ")
      character(len=*), intent(in) :: tail  !! the text after it
      integer :: i
      ! disabled while the buffers change: the handler sees no note or a whole one
      head_length = 0
      tail_length = 0
      do i = 1, min(len(head), max_note)
         note_head(i) = head(i:i)
      end do
      do i = 1, min(len(tail), max_note - 1)
         note_tail(i) = tail(i:i)
      end do
      note_tail(min(len(tail), max_note - 1) + 1) = new_line("a")
      tail_length = int(min(len(tail), max_note - 1) + 1, c_size_t)
      head_length = int(min(len(head), max_note), c_size_t)
   end subroutine set_interrupt_note

   !> No note on a signal any more.
   subroutine clear_interrupt_note()
      head_length = 0
      tail_length = 0
   end subroutine clear_interrupt_note

   !> From now until `settle_signals`, hold SIGINT, SIGTERM, SIGHUP instead of acting on
   !> them: a file is about to take its final name.
   subroutine begin_commit()
      holding = 1
   end subroutine begin_commit

   !> End the hold of `begin_commit`; the signal that arrived meanwhile (0: none), which
   !> the caller acts on now that what is on disk has been reported. With `keep_holding`
   !> (the last scene reported, the program about to exit with the status of what it
   !> wrote) signals stay held until the exit: one arriving in between must not turn a
   !> finished run into an interrupted one.
   integer function settle_signals(keep_holding) result(signum)
      logical, intent(in), optional :: keep_holding  !! hold signals until the process exits
      logical :: keep
      keep = .false.
      if (present(keep_holding)) keep = keep_holding
      if (.not. keep) holding = 0
      signum = int(held)
      held = 0
   end function settle_signals

   !> Signal handler: unlink every watched file, exit 128 + signal (while a commit is in
   !> progress: hold the signal for `settle_signals`).
   subroutine on_signal(signum) bind(C)
      integer(c_int), value :: signum
      integer :: k, n, m
      integer(c_int) :: status
      integer(c_long) :: written
      character(kind=c_char) :: digits(4)
      if (holding /= 0) then
         if (held == 0) held = signum
         return
      end if
      do k = 1, n_slots
         if (watched(1, k) /= c_null_char) status = c_unlink(watched(:, k))
      end do
      if (head_length > 0) then
         n = 0
         m = int(signum)
         do
            n = n + 1
            digits(n) = achar(iachar("0") + mod(m, 10))
            m = m/10
            if (m == 0 .or. n == size(digits)) exit
         end do
         digits(:n) = digits(n:1:-1)
         written = c_write(2_c_int, note_head, head_length)
         written = c_write(2_c_int, digits, int(n, c_size_t))
         written = c_write(2_c_int, note_tail, tail_length)
      end if
      call c_exit_now(128_c_int + signum)
   end subroutine on_signal
end module hillstab_batch_output_signals

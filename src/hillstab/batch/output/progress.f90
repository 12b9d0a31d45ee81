!> Progress on stderr for runs longer than about a second: percentage, points, rate and
!> time left, redrawn in place on a terminal, a line every 5 s otherwise.
!>
!> The environment variable HILLSTAB_PROGRESS=always reports every update that advances the
!> count at once, a line each (not redrawn), whether or not stderr is a terminal and however
!> short the run: for tests of what a task counts, and for logs that should show each step.
!>
!>```fortran
!> type(progress_t) :: progress
!> call progress_begin(progress, 1000_int64, quiet=.false.)
!> call progress_update(progress, 500_int64)   ! or, one point at a time: call progress_step(progress)
!> call progress_end(progress)
!>```
module hillstab_batch_output_progress
   use hillstab_core_kinds, only: wp, int64
   use hillstab_ffi_libc, only: c_isatty
   use, intrinsic :: iso_fortran_env, only: error_unit
   use, intrinsic :: iso_c_binding, only: c_int
   implicit none
   private
   public :: progress_t, progress_begin, progress_update, progress_step, progress_beat, progress_end, rate_text

   !> Progress on stderr for runs longer than about a second.
   type :: progress_t
      logical :: enabled = .false.      !! not quiet
      logical :: shown = .false.        !! something has been printed
      logical :: terminal = .false.     !! stderr is a terminal: redraw one line
      logical :: always = .false.       !! HILLSTAB_PROGRESS=always: every advance, a line each
      integer(int64) :: reported = -1   !! points done at the last report
      integer(int64) :: done = 0        !! points counted by `progress_step`
      integer(int64) :: total = 0       !! points to compute
      integer(int64) :: before = 0      !! points done before this run (a resumed run)
      integer(int64) :: start = 0       !! clock at the start
      integer(int64) :: last = 0        !! clock at the last report
      integer(int64) :: ticks = 1       !! clock ticks per second
      character(len=16) :: label = "points"  !! what is counted: points, rows, alphas, orbits
   end type progress_t

contains

   !> Start reporting the progress of a run of `total` points (nothing when quiet); a
   !> resumed run gives the points an earlier run did (`before`): the rate and the time left
   !> count only this run's.
   subroutine progress_begin(progress, total, quiet, label, before)
      type(progress_t), intent(out) :: progress  !! the progress state
      integer(int64), intent(in) :: total  !! points to compute
      logical, intent(in) :: quiet  !! no progress on stderr
      character(len=*), intent(in), optional :: label  !! what is counted (default "points")
      integer(int64), intent(in), optional :: before  !! points already done (default 0)
      progress%enabled = .not. quiet
      if (present(label)) progress%label = label
      if (present(before)) progress%before = before
      progress%total = total
      call system_clock(progress%start, progress%ticks)
      progress%last = progress%start
      if (progress%enabled) then
         progress%always = progress_always()
         progress%terminal = c_isatty(2_c_int) == 1 .and. .not. progress%always
      end if
   end subroutine progress_begin

   !> Whether HILLSTAB_PROGRESS is `always`.
   logical function progress_always()
      character(len=16) :: value
      integer :: length, status
      call get_environment_variable("HILLSTAB_PROGRESS", value, length, status)
      progress_always = status == 0 .and. value == "always"
   end function progress_always

   !> Report `done` of `total` points: percentage, rate and time left, once the run
   !> has taken a second; redrawn in place on a terminal, a line every 5 s otherwise.
   subroutine progress_update(progress, done)
      type(progress_t), intent(inout) :: progress  !! the progress state
      integer(int64), intent(in) :: done  !! points computed so far
      integer(int64) :: now
      real(wp) :: elapsed, since_last, rate, left, interval
      character(len=160) :: text
      character(len=12) :: left_text
      if (.not. progress%enabled .or. progress%total <= 0) return
      call system_clock(now)
      elapsed = real(now - progress%start, wp)/progress%ticks
      since_last = real(now - progress%last, wp)/progress%ticks
      if (progress%always) then
         if (done == progress%reported) return
      else
         if (elapsed < 1.0_wp) return
         interval = merge(0.25_wp, 5.0_wp, progress%terminal)
         if (progress%shown .and. since_last < interval .and. done < progress%total) return
      end if
      ! (at least a microsecond: HILLSTAB_PROGRESS=always reports from the start); a resumed
      ! run counts only the points it computed itself
      rate = real(done - progress%before, wp)/max(elapsed, 1.0e-6_wp)
      if (done > progress%before) then
         left = real(progress%total - done, wp)/rate
         write (left_text, '(f12.1)') min(left, 1.0e9_wp)
      else
         left_text = "?"   ! nothing done yet: no rate (and no division by zero in a trapping build)
      end if
      write (text, '(a,f5.1,a,i0,a,i0,a)') "hillstab: ", 100.0_wp*done/progress%total, "% (", &
         done, " of ", progress%total, " "//trim(progress%label)//", "//rate_text(rate)//" "// &
         trim(progress%label)//"/s, "
      text = trim(text)//" "//trim(adjustl(left_text))//" s left)"
      if (progress%terminal) then
         write (error_unit, '(a)', advance="no") achar(13)//trim(text)//"   "
      else
         write (error_unit, '(a)') trim(text)
      end if
      flush (error_unit)
      progress%shown = .true.
      progress%last = now
      progress%reported = done
   end subroutine progress_update

   !> One more point done, from any thread of a parallel loop: counted and reported
   !> (`progress_update`) under one lock.
   subroutine progress_step(progress)
      type(progress_t), intent(inout) :: progress  !! the progress state
      !$omp critical (hillstab_progress_step)
      progress%done = progress%done + 1
      call progress_update(progress, progress%done)
      !$omp end critical (hillstab_progress_step)
   end subroutine progress_step

   !> Nothing more done, but time has passed: the line again when it is due (every 5 s off a
   !> terminal), its rate and time left as of now. A thread that watches a long unit (a
   !> block of Hill's matrix that takes a minute) calls it while the others compute, so that
   !> the line keeps its pace; safe beside `progress_step` on other threads.
   subroutine progress_beat(progress)
      type(progress_t), intent(inout) :: progress  !! the progress state
      !$omp critical (hillstab_progress_step)
      ! (the last step has reported the end)
      if (progress%done < progress%total) call progress_update(progress, progress%done)
      !$omp end critical (hillstab_progress_step)
   end subroutine progress_beat

   !> A rate as a whole number from 10 up, with two significant digits below (a unit that
   !> takes many seconds, as a block of Hill's matrix near alpha = pi^2: "0.036").
   function rate_text(rate) result(text)
      real(wp), intent(in) :: rate  !! units per second, >= 0
      character(len=:), allocatable :: text
      character(len=32) :: buffer, form
      integer :: decimals
      if (rate >= 9.5_wp) then
         write (buffer, '(i0)') nint(rate, int64)
      else if (rate < 1.0e-6_wp) then
         buffer = "0"
      else
         decimals = min(7, max(1, 1 - floor(log10(rate))))
         write (form, '(a,i0,a)') "(f0.", decimals, ")"
         write (buffer, form) rate
         if (buffer(1:1) == ".") buffer = "0"//buffer
      end if
      text = trim(buffer)
   end function rate_text

   !> End the progress display (a final new line on a terminal).
   subroutine progress_end(progress)
      type(progress_t), intent(in) :: progress  !! the progress state
      if (progress%shown .and. progress%terminal) write (error_unit, '(a)') ""
   end subroutine progress_end
end module hillstab_batch_output_progress

!> The work of a chart, points or lyapunov scene cut into independent units, for drivers that
!> compute units in any order, anywhere (the MPI program `hillstab_mpi`), and write them
!> in order into the same file as the serial task.
!>
!> The task says how (its unit bindings, hillstab_batch_scene `task_t`): a chart's unit is
!> one row (one α, all β), computed by the chart task's own row routine, so the data lines
!> are those of a serial run; points and lyapunov scenes are cut into runs of consecutive
!> points. A unit's result is its text (the lines as the serial task writes
!> them, with the blank line that separates α blocks) and a status per point
!> (hillstab_core_status). Only `batch_open` / `batch_write` / `batch_commit` touch the file,
!> through hillstab_batch_output, so the file appears whole or not at all. As in the serial
!> tasks, a failed point is written with its status and placeholders, and `batch_commit`
!> returns err_points_failed (exit status 3) naming the first.
!>
!>```fortran
!> type(batch_t) :: batch
!> type(batch_result_t) :: result
!> type(error_t), allocatable :: error
!> integer :: unit
!> call batch_plan(scene, 1, batch)
!> call batch_open(batch, .true., error)
!> do unit = 1, batch%n_units
!>    call batch_compute(batch, unit, result)
!>    call batch_write(batch, result, error)
!>    if (allocated(error)) exit
!> end do
!> if (allocated(error)) then
!>    call batch_discard(batch)
!> else
!>    call batch_commit(batch, error)   ! err_points_failed: written, with failed points
!> end if
!>```
module hillstab_batch_units
   use hillstab_core_kinds, only: wp, int64
   use, intrinsic :: iso_fortran_env, only: int32
   use hillstab_core_error, only: error_t, set_error, err_input
   use hillstab_core_status, only: status_roundoff, status_failed
   use hillstab_batch_scene, only: scene_t, task_t, open_scene_output, scene_namelist
   use hillstab_batch_output, only: output_file_t, write_text, commit_output, discard_output
   use hillstab_batch_progress, only: progress_t, progress_begin, progress_update, progress_end
   implicit none
   private
   public :: batch_t, batch_result_t, batch_distributable, batch_plan, batch_unit_range, batch_compute, &
      batch_open, batch_write, batch_commit, batch_discard, run_batch, scene_fingerprint

   !> A scene's work cut into units, and the state of its output file.
   type :: batch_t
      type(scene_t) :: scene                 !! the scene, its task prepared for units
      integer :: n_units = 0                 !! units to compute, numbered 1 … n_units
      integer :: unit_size = 1               !! points per unit (a chart: n_beta, one row)
      integer(int64) :: n_points = 0         !! points in the scene
      type(output_file_t) :: file            !! the output being written
      type(progress_t) :: progress           !! progress on stderr
      integer(int64) :: done = 0             !! points written so far
      integer(int64) :: n_inaccurate = 0     !! round-off limited points written so far
      real(wp) :: first_inaccurate(2) = 0.0_wp  !! (α, β) of the first of them
      integer(int64) :: n_failed = 0         !! failed points written so far
      real(wp) :: first_failed(2) = 0.0_wp   !! (α, β) of the first of them
   end type batch_t

   !> The computed text of one unit.
   type :: batch_result_t
      integer :: unit = 0                    !! which unit
      !> the unit's lines exactly as the file holds them, without the final new line
      character(len=:), allocatable :: text
      integer, allocatable :: status(:)      !! per point: status_ok, status_roundoff or status_failed
   end type batch_result_t

contains

   !> Whether a scene's task can be cut into units (its points are independent).
   pure logical function batch_distributable(scene)
      type(scene_t), intent(in) :: scene  !! a validated scene
      batch_distributable = scene%task%point_count() > 0
   end function batch_distributable

   !> Cut the work of `scene` into units for `n_workers` computing processes, as its task
   !> says (a chart by rows; a points list or a Lyapunov map in runs of consecutive points,
   !> small enough to balance points of very different cost).
   subroutine batch_plan(scene, n_workers, batch)
      type(scene_t), intent(in) :: scene  !! a distributable scene
      integer, intent(in) :: n_workers    !! processes that will compute units (≥ 1)
      type(batch_t), intent(out) :: batch  !! the units and the output file state
      class(task_t), allocatable :: task
      batch%scene = scene
      batch%n_points = scene%task%point_count()
      batch%unit_size = scene%task%unit_size(n_workers)
      batch%n_units = int((batch%n_points + batch%unit_size - 1)/batch%unit_size)
      ! what every unit shares, made once (the task is prepared apart from the scene holding it)
      allocate (task, source=scene%task)
      call task%prepare_units(scene)
      call move_alloc(task, batch%scene%task)
   end subroutine batch_plan

   !> Two 32-bit FNV-1a hashes (different offset bases) of what a run computes: the
   !> effective scene's namelist lines and, for a distributable scene, every point's
   !> (α, β). Processes that read the same scene and points get the same pair; a scene
   !> or points file that differs between them (another working directory, a file edited
   !> between the starts) gives another pair.
   function scene_fingerprint(scene) result(hash)
      type(scene_t), intent(in) :: scene  !! a scene as read
      integer(int64) :: hash(2)
      integer(int64), parameter :: prime = 16777619_int64, modulus = 4294967296_int64
      character(len=:), allocatable :: lines(:)
      integer(int32) :: words(4)
      real(wp) :: point(2)
      integer(int64) :: k
      integer :: i, j
      hash = [2166136261_int64, 84696351_int64]
      lines = scene_namelist(scene)
      do i = 1, size(lines)
         do j = 1, len_trim(lines(i))
            call mix(int(iachar(lines(i)(j:j)), int64))
         end do
         call mix(10_int64)
      end do
      if (batch_distributable(scene)) then
         do k = 1, scene%task%point_count()
            point = scene%task%point_of(k)
            words = transfer(point, words)
            do j = 1, 4
               call mix(int(words(j), int64) + 2147483648_int64)
            end do
         end do
      end if
   contains
      pure subroutine mix(value)
         integer(int64), intent(in) :: value  !! in [0, 2^32)
         hash = mod(ieor(hash, value)*prime, modulus)
      end subroutine mix
   end function scene_fingerprint

   !> The points of `unit`, as indices first … last in the scene's order (a chart's
   !> points numbered row by row).
   pure subroutine batch_unit_range(batch, unit, first, last)
      type(batch_t), intent(in) :: batch  !! the planned work
      integer, intent(in) :: unit  !! 1 ... batch%n_units
      integer(int64), intent(out) :: first, last  !! first and last point index of the unit
      first = int(unit - 1, int64)*batch%unit_size + 1
      last = min(batch%n_points, int(unit, int64)*batch%unit_size)
   end subroutine batch_unit_range

   !> Compute one unit. Pure computation: no file is touched, so any process can do it.
   subroutine batch_compute(batch, unit, result)
      type(batch_t), intent(in) :: batch  !! the planned work
      integer, intent(in) :: unit  !! 1 … batch%n_units
      type(batch_result_t), intent(out) :: result  !! the unit's lines and point statuses
      integer(int64) :: first, last
      call batch_unit_range(batch, unit, first, last)
      allocate (result%status(first:last))
      result%unit = unit
      call batch%scene%task%unit_text(batch%scene, unit, first, last, result%text, result%status)
   end subroutine batch_compute

   !> Open the output file of the scene and write its header (an unwritable path fails
   !> here, before anything is computed).
   subroutine batch_open(batch, quiet, error)
      type(batch_t), intent(inout) :: batch  !! the planned work; its output file is opened
      logical, intent(in) :: quiet  !! no progress on stderr
      type(error_t), allocatable, intent(out) :: error  !! failure description; unallocated on success
      if (batch%scene%binary) then
         call set_error(error, err_input, batch%scene%source//": &scene: format: 'binary' is written by the "// &
            "hillstab program, not by the unit-by-unit driver: use format = 'text'")
         return
      end if
      call open_scene_output(batch%scene, batch%file, error)
      if (allocated(error)) return
      call batch%scene%task%open_units(batch%scene, batch%file, error)
      if (allocated(error)) then
         call discard_output(batch%file)
         return
      end if
      batch%done = 0
      batch%n_inaccurate = 0
      batch%n_failed = 0
      call progress_begin(batch%progress, batch%n_points, quiet)
   end subroutine batch_open

   !> Append a unit's text to the file and count its round-off limited and failed
   !> points; units must come in order 1, 2, …. An error (the file cannot be written)
   !> means the file must be discarded.
   subroutine batch_write(batch, result, error)
      type(batch_t), intent(inout) :: batch  !! the planned work with its open output file
      type(batch_result_t), intent(in) :: result  !! the next unit's result, in unit order
      type(error_t), allocatable, intent(out) :: error  !! the file cannot be written; unallocated on success
      integer(int64) :: first, last
      integer :: j
      call batch_unit_range(batch, result%unit, first, last)
      call write_text(batch%file, result%text, error)
      if (allocated(error)) return
      if (any(result%status == status_roundoff)) then
         j = findloc(result%status, status_roundoff, dim=1)
         if (batch%n_inaccurate == 0) batch%first_inaccurate = batch%scene%task%point_of(first + j - 1)
         batch%n_inaccurate = batch%n_inaccurate + count(result%status == status_roundoff)
      end if
      if (any(result%status == status_failed)) then
         j = findloc(result%status, status_failed, dim=1)
         if (batch%n_failed == 0) batch%first_failed = batch%scene%task%point_of(first + j - 1)
         batch%n_failed = batch%n_failed + count(result%status == status_failed)
      end if
      batch%done = last
      call progress_update(batch%progress, batch%done)
   end subroutine batch_write

   !> Finish the file (rename it onto its name); then the task's warnings, and with failed
   !> points `error` is err_points_failed naming the first (as after a serial run).
   subroutine batch_commit(batch, error)
      type(batch_t), intent(inout) :: batch  !! the planned work with every unit written
      !> err_points_failed naming the first failed point, or a rename failure
      type(error_t), allocatable, intent(out) :: error
      call progress_end(batch%progress)
      call commit_output(batch%file, error)
      if (allocated(error)) return
      call batch%scene%task%finish_units(batch%scene, batch%n_points, batch%n_failed, batch%first_failed, &
                                         batch%n_inaccurate, batch%first_inaccurate, error)
   end subroutine batch_commit

   !> Abandon the file: the temporary file is deleted, the final name left as it was.
   subroutine batch_discard(batch)
      type(batch_t), intent(inout) :: batch  !! the planned work whose file is abandoned
      call progress_end(batch%progress)
      call discard_output(batch%file)
   end subroutine batch_discard

   !> Run a distributable scene unit by unit in this process: the reference order of
   !> work of a distributed run, and what such a run does with one process.
   subroutine run_batch(scene, quiet, error)
      type(scene_t), intent(in) :: scene  !! a validated chart or points scene
      logical, intent(in) :: quiet  !! no progress on stderr
      type(error_t), allocatable, intent(out) :: error  !! what failed (err_points_failed: written with failed points)
      type(batch_t) :: batch
      type(batch_result_t) :: result
      integer :: unit
      call batch_plan(scene, 1, batch)
      call batch_open(batch, quiet, error)
      if (allocated(error)) return
      do unit = 1, batch%n_units
         call batch_compute(batch, unit, result)
         call batch_write(batch, result, error)
         if (allocated(error)) exit
      end do
      if (allocated(error)) then
         call batch_discard(batch)
      else
         call batch_commit(batch, error)
      end if
   end subroutine run_batch
end module hillstab_batch_units

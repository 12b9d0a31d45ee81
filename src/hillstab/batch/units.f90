!> The work of a chart or points scene cut into independent units, for drivers that
!> compute units in any order, anywhere (the MPI program `hillstab_mpi`), and write them
!> in order into the same file as the serial task.
!>
!> A chart's unit is one row (one α, all β), computed by the chart task's own row routine,
!> so the data lines are those of a serial run; a points scene is cut into runs of
!> consecutive points. A unit's result is its text (the lines as the serial task writes
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
   use hillstab_core_error, only: error_t, set_error, err_input, err_io, err_invalid_parameter, err_points_failed
   use hillstab_core_status, only: status_roundoff, status_failed, exit_points_failed
   use hillstab_hill_coefficient, only: in_physical_domain
   use hillstab_batch_scene, only: scene_t, task_chart, task_points, task_lyapunov, grid_point
   use hillstab_batch_task_lyapunov, only: lyapunov_lines, lyapunov_header, lyapunov_columns, lyapunov_point_count, &
      lyapunov_point, lyapunov_failure_error
   use hillstab_hill_coefficient, only: model_elastic
   use hillstab_batch_output, only: output_file_t, write_header, write_text, commit_output, discard_output, &
      chart_columns_text, chart_line_length, joined_lines
   use hillstab_batch_tasks, only: scene_columns, chart_betas, chart_row, compute_points, chart_header, open_scene_output, &
      check_method_runs, &
      warn_inaccurate, failed_points_error, progress_t, progress_begin, progress_update, progress_end
   implicit none
   private
   public :: batch_t, batch_result_t, batch_distributable, batch_plan, batch_unit_range, batch_compute, &
      batch_open, batch_write, batch_commit, batch_discard, run_batch, exit_status

   !> A scene's work cut into units, and the state of its output file.
   type :: batch_t
      type(scene_t) :: scene                 !! the scene (chart or points)
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
      !> a chart: what every row shares, made once by `batch_plan` (`chart_betas`, `scene_columns`)
      real(wp), allocatable :: betas(:)
      character(len=23), allocatable :: beta_texts(:)  !! a chart: format_es(betas, 16)
      integer, allocatable :: ids(:)         !! a chart: the columns written
   end type batch_t

   !> The computed text of one unit.
   type :: batch_result_t
      integer :: unit = 0                    !! which unit
      !> the unit's lines exactly as the file holds them, without the final new line
      character(len=:), allocatable :: text
      integer, allocatable :: status(:)      !! per point: status_ok, status_roundoff or status_failed
   end type batch_result_t

contains

   !> Whether a scene's task can be cut into units (chart and points).
   pure logical function batch_distributable(scene)
      type(scene_t), intent(in) :: scene  !! a validated scene
      batch_distributable = scene%task == task_chart .or. scene%task == task_points .or. scene%task == task_lyapunov
   end function batch_distributable

   !> Cut the work of `scene` into units for `n_workers` computing processes: a chart
   !> by rows; a points list in runs of consecutive points, small enough (about 16 units
   !> a worker, at most 64 points) to balance points of very different cost.
   subroutine batch_plan(scene, n_workers, batch)
      type(scene_t), intent(in) :: scene  !! a chart or points scene
      integer, intent(in) :: n_workers    !! processes that will compute units (≥ 1)
      type(batch_t), intent(out) :: batch  !! the units and the output file state
      integer :: n
      type(error_t), allocatable :: error
      batch%scene = scene
      select case (scene%task)
      case (task_chart)
         batch%unit_size = scene%chart%n_beta
         batch%n_units = scene%chart%n_alpha
         batch%n_points = int(scene%chart%n_alpha, int64)*scene%chart%n_beta
         call chart_betas(scene, batch%betas, batch%beta_texts)
         call scene_columns(scene, batch%ids, error)
         ! a bad &scene columns is reported by batch_open; chart_row then falls back on its own
         if (allocated(error) .and. allocated(batch%ids)) deallocate (batch%ids)
      case (task_points)
         n = size(scene%points, 2)
         batch%n_points = n
         batch%unit_size = max(1, min(64, n/(16*max(1, n_workers))))
         batch%n_units = (n + batch%unit_size - 1)/batch%unit_size
      case (task_lyapunov)
         ! a point is hundreds of radial periods (~10 ms to 1 s): small units balance well
         batch%n_points = lyapunov_point_count(scene)
         batch%unit_size = int(max(1_int64, min(16_int64, batch%n_points/(32*max(1, n_workers)))))
         batch%n_units = int((batch%n_points + batch%unit_size - 1)/batch%unit_size)
      end select
   end subroutine batch_plan

   !> The points of `unit`, as indices first … last in the scene's order (a chart's
   !> points numbered row by row).
   pure subroutine batch_unit_range(batch, unit, first, last)
      type(batch_t), intent(in) :: batch  !! the planned work
      integer, intent(in) :: unit  !! 1 ... batch%n_units
      integer(int64), intent(out) :: first, last  !! first and last point index of the unit
      first = int(unit - 1, int64)*batch%unit_size + 1
      last = min(batch%n_points, int(unit, int64)*batch%unit_size)
   end subroutine batch_unit_range

   !> (α, β) of point `k` of the scene.
   pure function point_of(batch, k) result(point)
      type(batch_t), intent(in) :: batch
      integer(int64), intent(in) :: k
      real(wp) :: point(2)
      logical :: new_block
      if (batch%scene%task == task_lyapunov) then
         call lyapunov_point(batch%scene, k, point(1), point(2), new_block)
      else if (batch%scene%task == task_chart) then
         point = grid_point(batch%scene%chart, k)
      else
         point = batch%scene%points(:, k)
      end if
   end function point_of

   !> Compute one unit. Pure computation: no file is touched, so any process can do it.
   subroutine batch_compute(batch, unit, result)
      type(batch_t), intent(in) :: batch  !! the planned work
      integer, intent(in) :: unit  !! 1 … batch%n_units
      type(batch_result_t), intent(out) :: result  !! the unit's lines and point statuses
      character(len=chart_line_length), allocatable :: lines(:)
      integer(int64) :: first, last
      call batch_unit_range(batch, unit, first, last)
      allocate (result%status(first:last))
      result%unit = unit
      if (batch%scene%task == task_lyapunov) then
         ! the task's own lines and blank lines between α blocks
         call lyapunov_lines(batch%scene, first, last, result%text, result%status)
         return
      end if
      allocate (lines(first:last))
      select case (batch%scene%task)
      case (task_chart)
         ! (batch%ids unallocated is an absent optional argument: chart_row then makes its own)
         call chart_row(batch%scene, unit, lines, result%status, batch%betas, batch%beta_texts, batch%ids)
      case (task_points)
         call compute_points(batch%scene, int(first), int(last), lines, result%status)
      end select
      ! a chart's rows are blocks of constant α separated by one blank line
      result%text = joined_lines(lines, batch%scene%task == task_chart .and. unit > 1)
   end subroutine batch_compute

   !> Open the output file of the scene and write its header (an unwritable path fails
   !> here, before anything is computed).
   subroutine batch_open(batch, quiet, error)
      type(batch_t), intent(inout) :: batch  !! the planned work; its output file is opened
      logical, intent(in) :: quiet  !! no progress on stderr
      type(error_t), allocatable, intent(out) :: error  !! failure description; unallocated on success
      logical :: outside
      type(scene_t) :: s
      integer, allocatable :: ids(:)
      s = batch%scene
      if (s%binary) then
         call set_error(error, err_input, s%source//": &scene: format: 'binary' is written by the hillstab "// &
            "program, not by the unit-by-unit driver: use format = 'text'")
         return
      end if
      call scene_columns(s, ids, error)
      if (allocated(error)) return
      call open_scene_output(s, batch%file, error)
      if (allocated(error)) return
      if (s%task == task_lyapunov) then
         call write_header(batch%file, lyapunov_header(s), lyapunov_columns(), error)
         if (allocated(error)) then
            call discard_output(batch%file)
            return
         end if
         call begin()
         return
      end if
      if (s%task == task_chart) then
         call check_method_runs(s, error)
         if (allocated(error)) then
            call discard_output(batch%file)
            return
         end if
         outside = .not. (in_physical_domain(s%chart%alpha_min, s%chart%beta_min) .and. &
                          in_physical_domain(s%chart%alpha_max, s%chart%beta_max))
      else
         outside = .not. all(in_physical_domain(s%points(1, :), s%points(2, :)))
      end if
      call write_header(batch%file, chart_header(s, outside), chart_columns_text(ids), error, &
                        names_line=s%names_line)
      if (allocated(error)) then
         call discard_output(batch%file)
         return
      end if
      call begin()
   contains
      subroutine begin()
         batch%done = 0
         batch%n_inaccurate = 0
         batch%n_failed = 0
         call progress_begin(batch%progress, batch%n_points, quiet)
      end subroutine begin
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
         if (batch%n_inaccurate == 0) batch%first_inaccurate = point_of(batch, first + j - 1)
         batch%n_inaccurate = batch%n_inaccurate + count(result%status == status_roundoff)
      end if
      if (any(result%status == status_failed)) then
         j = findloc(result%status, status_failed, dim=1)
         if (batch%n_failed == 0) batch%first_failed = point_of(batch, first + j - 1)
         batch%n_failed = batch%n_failed + count(result%status == status_failed)
      end if
      batch%done = last
      call progress_update(batch%progress, batch%done)
   end subroutine batch_write

   !> Finish the file (rename it onto its name) and warn about round-off limited points.
   !> With failed points the file is written and `error` is err_points_failed, naming the
   !> first (computed again here, so the message is that of a serial run).
   subroutine batch_commit(batch, error)
      type(batch_t), intent(inout) :: batch  !! the planned work with every unit written
      !> err_points_failed naming the first failed point, or a rename failure
      type(error_t), allocatable, intent(out) :: error
      call progress_end(batch%progress)
      call commit_output(batch%file, error)
      if (allocated(error)) return
      if (batch%scene%task == task_lyapunov) then
         call lyapunov_failure_error(batch%scene, batch%n_failed, batch%first_failed, error)
         return
      end if
      call warn_inaccurate(batch%scene, batch%n_inaccurate, batch%first_inaccurate)
      call failed_points_error(batch%scene, batch%n_failed, batch%n_points, batch%first_failed, error)
   end subroutine batch_commit

   !> Abandon the file: the temporary file is deleted, the final name left as it was.
   subroutine batch_discard(batch)
      type(batch_t), intent(inout) :: batch  !! the planned work whose file is abandoned
      call progress_end(batch%progress)
      call discard_output(batch%file)
   end subroutine batch_discard

   !> Run a chart or points scene unit by unit in this process: the reference order of
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

   !> The exit status of a run that ended with `error`: 2 for bad input (scene, points
   !> file, output path), 3 when the file was written but some points failed
   !> (err_points_failed), 1 when a computation failed otherwise.
   pure integer function exit_status(error)
      type(error_t), intent(in) :: error  !! the error a run ended with
      select case (error%code)
      case (err_input, err_io, err_invalid_parameter)
         exit_status = 2
      case (err_points_failed)
         exit_status = exit_points_failed
      case default
         exit_status = 1
      end select
   end function exit_status
end module hillstab_batch_units

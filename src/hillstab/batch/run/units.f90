!> The work of a chart, points or lyapunov scene cut into independent units, for drivers that
!> compute units in any order, anywhere (`run_batch` on OpenMP threads in the serial
!> program, the MPI program `hillstab_mpi` over ranks), and write them in order into the
!> same file.
!>
!> The task says how (its unit bindings, hillstab_batch_scene_types `task_t`): a chart's unit is
!> one row (one α, all β), computed by the chart task's row routine, so the data lines do
!> not depend on who computed them; points and lyapunov scenes are cut into runs of
!> consecutive points. A unit's result is its text (the lines as the file holds
!> them, with the blank line that separates α blocks; in a binary file, its records' bytes,
!> hillstab_batch_output_file `record_bytes`) and a status per point
!> (hillstab_core_status). Only `batch_open` / `batch_write` / `batch_commit` touch the file,
!> through hillstab_batch_output_file, so the file appears whole or not at all. As in every
!> task, a failed point is written with its status and placeholders, and `batch_commit`
!> returns err_points_failed (exit status 3) naming the first.
!>
!> Long runs keep a checkpoint (hillstab_batch_output_checkpoint) when `batch_open` is given
!> options: every `interval` seconds of progress (3 by default), at a unit boundary,
!> `batch_write` puts the file written so far on the disk and records how many units it
!> holds; the first such update makes the checkpoint, so runs shorter than the interval
!> leave none. `batch_open` with `resume` continues from a checkpoint of the same
!> effective scene and points (units before `first_unit` are not computed again: the file
!> is the one an uninterrupted run writes), refuses one of another scene (err_input, naming
!> the first difference), and without `resume` discards one with a note. `batch_commit`
!> removes the checkpoint with the finished file; `batch_discard` and signals keep it.
!> `run_batch` computes units on OpenMP threads (16 a thread held at once) and writes each as soon as it is next in order, so a checkpoint follows
!> the run unit by unit, in the serial program and in `hillstab_mpi` alike.
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
module hillstab_batch_run_units
   use hillstab_core_kinds, only: wp, int64, version_string
   use, intrinsic :: iso_fortran_env, only: int32
   use hillstab_core_error, only: error_t, set_error, err_input
   use hillstab_core_status, only: status_roundoff, status_failed
   use hillstab_core_text, only: integer_text
   use hillstab_batch_scene_types, only: scene_t, task_t, open_scene_output, scene_namelist, output_path
   use hillstab_batch_output_file, only: output_file_t, write_text, write_bytes, commit_output, discard_output, &
      sync_output, lock_output, &
      resume_output, temporary_prefix, joined_lines, claim_output, digest_written
   use hillstab_batch_output_progress, only: progress_t, progress_begin, progress_update, progress_end
   use hillstab_batch_output_checkpoint, only: checkpoint_options_t, checkpoint_state_t, checkpoint_directory, checkpoint_data, &
      find_checkpoint, make_checkpoint, save_checkpoint_state, remove_checkpoint, remove_stale_temporary, &
      scene_difference, checkpoint_note, checkpoint_usable, checkpoint_incomplete, checkpoint_damaged, scene_lines, &
      fnv1a_step
   use hillstab_batch_output_digest, only: digest_value
   use hillstab_core_parallel, only: max_threads
   use hillstab_batch_output_signals, only: set_interrupt_note, clear_interrupt_note
   use hillstab_ffi_libc, only: c_nanosleep, timespec_t
   use, intrinsic :: iso_c_binding, only: c_int, c_long
   !$ use omp_lib, only: omp_init_lock, omp_destroy_lock, omp_test_lock, omp_unset_lock
   implicit none
   private
   !> Kind of the writer's lock of `run_batch`: OpenMP's lock kind (4 in gfortran; checked
   !> at compile time by the calls taking it); unused without OpenMP.
   integer, parameter :: lock_kind = int32
   public :: batch_t, batch_result_t, batch_distributable, batch_plan, batch_set_unit_size, batch_unit_range, &
      batch_compute, batch_open, batch_write, batch_commit, batch_discard, run_batch, scene_fingerprint, max_threads, &
      problem_kind, settle_checkpoint

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
      integer :: first_unit = 1              !! the first unit to compute (after those of a resumed checkpoint)
      type(checkpoint_options_t) :: options  !! how this run keeps its checkpoint
      logical :: checkpointing = .false.     !! this run keeps a checkpoint
      logical :: checkpoint_made = .false.   !! it exists on the disk (made, or resumed)
      logical :: fingerprinted = .false.     !! state%fingerprint is made (`fingerprint_run`)
      character(len=:), allocatable :: checkpoint  !! its directory
      type(checkpoint_state_t) :: state      !! what it records (as of its last update)
      integer(int64) :: checkpoint_clock = 0  !! system_clock at its last update (or the start)
      !> the test hook's unit (`pause_hook`): the writer waits once this unit is written (0: never)
      integer :: pause_after = 0
   end type batch_t

   !> The environment variable of the test hook (`pause_hook`).
   character(len=*), parameter :: pause_variable = "HILLSTAB_TEST_PAUSE_AFTER_UNITS"
   !> Longest wait of the test hook [s].
   integer, parameter :: pause_seconds = 60

   !> The computed text of one unit.
   type :: batch_result_t
      integer :: unit = 0                    !! which unit
      !> the unit's lines exactly as the file holds them, without the final new line (a
      !> binary file: its records' bytes, written as they are)
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
      call batch_set_unit_size(batch, scene%task%unit_size(n_workers))
      ! what every unit shares, made once (the task is prepared apart from the scene holding it)
      allocate (task, source=scene%task)
      call task%prepare_units(scene)
      call move_alloc(task, batch%scene%task)
   end subroutine batch_plan

   !> Cut a planned batch's points into units of `unit_size` points instead (a resumed
   !> checkpoint's cut; only a chart's must be its rows' n_beta, the other files do not
   !> depend on the cut).
   pure subroutine batch_set_unit_size(batch, unit_size)
      type(batch_t), intent(inout) :: batch  !! a planned batch
      integer, intent(in) :: unit_size  !! points per unit (≥ 1)
      batch%unit_size = unit_size
      batch%n_units = int((batch%n_points + batch%unit_size - 1)/batch%unit_size)
   end subroutine batch_set_unit_size

   !> Two 32-bit FNV-1a hashes (different offset bases) of what a run computes: the
   !> effective scene's namelist lines and, for a distributable scene, every point's
   !> (α, β). Processes that read the same scene and points get the same pair; a scene
   !> or points file that differs between them (another working directory, a file edited
   !> between the starts) gives another pair.
   function scene_fingerprint(scene) result(hash)
      type(scene_t), intent(in) :: scene  !! a scene as read
      integer(int64) :: hash(2)
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
            point = scene%task%point_of(scene, k)
            words = transfer(point, words)
            do j = 1, 4
               call mix(int(words(j), int64) + 2147483648_int64)
            end do
         end do
      end if
   contains
      pure subroutine mix(value)
         integer(int64), intent(in) :: value  !! in [0, 2^32)
         hash = fnv1a_step(hash, value)
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
   !> here, before anything is computed). With `options`, the run keeps a checkpoint, and
   !> what is at the checkpoint's name is dealt with first: with `resume`, a checkpoint of
   !> the same effective scene and points is continued (the file reopened after its last
   !> recorded unit, `first_unit` the next), one of another scene is refused (err_input
   !> naming the first difference); without, a checkpoint is discarded with a note. Anything
   !> else at the name (a symbolic link, a file, a directory open to others) is refused
   !> (err_io), as is a checkpoint another run is writing.
   subroutine batch_open(batch, quiet, error, options)
      type(batch_t), intent(inout) :: batch  !! the planned work; its output file is opened
      logical, intent(in) :: quiet  !! no progress on stderr
      type(error_t), allocatable, intent(out) :: error  !! failure description; unallocated on success
      type(checkpoint_options_t), intent(in), optional :: options  !! keep a checkpoint, and how
      type(checkpoint_state_t) :: saved
      character(len=:), allocatable :: reason
      integer :: kind
      logical :: resumed
      integer(int64) :: rate
      batch%done = 0
      batch%n_inaccurate = 0
      batch%n_failed = 0
      batch%first_unit = 1
      batch%checkpoint_made = .false.
      batch%checkpointing = present(options)
      batch%pause_after = pause_hook()
      resumed = .false.
      if (batch%checkpointing) then
         batch%options = options
         if (.not. allocated(batch%options%program)) batch%options%program = "hillstab"
         if (.not. allocated(batch%options%command)) batch%options%command = batch%options%program//" --resume SCENE"
         batch%checkpoint = checkpoint_directory(output_path(batch%scene))
         ! temporary files of this output that stopped runs left are removed first (also when
         ! the checkpoint is then refused); one being written means another run (refused)
         call claim_output(output_path(batch%scene), error, batch%scene%source//": &scene: output: ", &
                           program=batch%options%program)
         if (allocated(error)) return
         call find_checkpoint(batch%checkpoint, kind, saved, reason, error)
         if (allocated(error)) then
            error%message = batch%scene%source//": &scene: output: "//error%message
            return
         end if
         call describe_run(batch)
         select case (kind)
         case (checkpoint_usable)
            if (options%resume) then
               call resume_batch(batch, saved, error)
               if (allocated(error)) return
               resumed = .true.
            else
               call discard_checkpoint(batch, saved, error)
               if (allocated(error)) return
               call checkpoint_note(batch%options, "discarded the checkpoint '"//batch%checkpoint//"' of an "// &
                  "earlier run ("//progress_text(saved)//"): without --resume the run starts afresh")
            end if
         case (checkpoint_damaged)
            if (options%resume) then
               call set_error(error, err_input, batch%scene%source//": &scene: output: the checkpoint '"// &
                  batch%checkpoint//"' cannot be resumed: "//reason//"; it is not resumed and kept as it is: "// &
                  "run without --resume to discard it and start afresh")
               return
            end if
            call discard_checkpoint(batch, saved, error)
            if (allocated(error)) return
            call checkpoint_note(batch%options, "discarded the damaged checkpoint '"//batch%checkpoint// &
               "' of an earlier run: "//reason//"; without --resume the run starts afresh")
         case (checkpoint_incomplete)
            call discard_checkpoint(batch, saved, error)
            if (allocated(error)) return
            if (options%resume) then
               call checkpoint_note(batch%options, "the checkpoint '"//batch%checkpoint//"' cannot be resumed: "// &
                  reason//"; discarded it, starting afresh")
            else
               call checkpoint_note(batch%options, "discarded the incomplete checkpoint '"//batch%checkpoint// &
                  "' of an earlier run ("//reason//")")
            end if
         case default
            if (options%resume) call checkpoint_note(batch%options, "no checkpoint of "//output_path(batch%scene)// &
               " ('"//batch%checkpoint//"' does not exist): starting afresh")
         end select
      end if
      if (.not. resumed) then
         call open_scene_output(batch%scene, batch%file, error)
         if (allocated(error)) return
         ! a checkpoint records the checksum of every byte of its data, the header included
         batch%file%digesting = batch%checkpointing
         call batch%scene%task%open_units(batch%scene, batch%file, error)
         if (allocated(error)) then
            call discard_output(batch%file)
            return
         end if
      end if
      call progress_begin(batch%progress, batch%n_points, quiet, before=batch%done)
      call system_clock(batch%checkpoint_clock, rate)
      ! with no interval, the checkpoint is made at once (the header alone)
      if (batch%checkpointing .and. .not. batch%checkpoint_made) then
         if (batch%options%interval <= 0.0_wp) call update_checkpoint(batch, error)
      end if
      if (allocated(error)) call batch_discard(batch)
   end subroutine batch_open

   !> What this run would record in its checkpoint before any unit: the program, the output,
   !> the effective scene, its points' fingerprint, the units.
   subroutine describe_run(batch)
      type(batch_t), intent(inout) :: batch
      batch%state = checkpoint_state_t()
      batch%state%version = version_string
      batch%state%problem = problem_kind(batch%scene)
      batch%state%output = output_path(batch%scene)
      batch%state%temporary = ""
      ! the fingerprint is made when a checkpoint is compared or first written
      ! (`fingerprint_run`): it reads every point (a chart's grid, a points file), and most
      ! runs end before they make a checkpoint
      batch%state%fingerprint = 0
      batch%fingerprinted = .false.
      batch%state%n_points = batch%n_points
      batch%state%unit_size = batch%unit_size
      batch%state%n_units = batch%n_units
      batch%state%scene = joined_lines(scene_namelist(batch%scene), .false.)//new_line("a")
   end subroutine describe_run

   !> The fingerprint of the run's scene and points in its state, made once.
   subroutine fingerprint_run(batch)
      type(batch_t), intent(inout) :: batch
      if (batch%fingerprinted) return
      batch%state%fingerprint = scene_fingerprint(batch%scene)
      batch%fingerprinted = .true.
   end subroutine fingerprint_run

   !> "37 of 400 units, 14800 of 160000 points done".
   function progress_text(state) result(text)
      type(checkpoint_state_t), intent(in) :: state
      character(len=:), allocatable :: text
      text = integer_text(min(state%n_points, int(state%units_done, int64)*state%unit_size))//" of "// &
         integer_text(state%n_points)//" points done"
   end function progress_text

   !> Remove a checkpoint found at the start (and the temporary output its killed run left).
   subroutine discard_checkpoint(batch, saved, error)
      type(batch_t), intent(inout) :: batch
      type(checkpoint_state_t), intent(in) :: saved
      type(error_t), allocatable, intent(out) :: error
      call remove_stale_temporary(batch%checkpoint, saved, temporary_prefix(output_path(batch%scene)))
      call remove_checkpoint(batch%checkpoint, error)
      if (allocated(error)) error%message = batch%scene%source//": &scene: output: "//error%message
   end subroutine discard_checkpoint

   !> Continue from the checkpoint `saved` when it is one of this run (same version, output,
   !> effective scene and points): the file is reopened after its last recorded unit.
   subroutine resume_batch(batch, saved, error)
      type(batch_t), intent(inout) :: batch
      type(checkpoint_state_t), intent(in) :: saved
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: difference, refusal, source
      logical :: damaged
      source = batch%scene%source
      refusal = " (checkpoint '"//batch%checkpoint//"'): it is not resumed; run without --resume to discard it "// &
         "and start afresh"
      if (saved%version /= version_string) then
         call set_error(error, err_input, source//": the checkpoint was written by hillstab "//saved%version// &
            ", this is "//version_string//", whose lines may differ"//refusal)
         return
      end if
      if (saved%problem /= batch%state%problem) then
         call set_error(error, err_input, source//": &scene: model: the checkpoint is of a "//saved%problem// &
            ", this scene is a "//batch%state%problem//refusal)
         return
      end if
      if (saved%output /= batch%state%output) then
         call set_error(error, err_input, source//": &scene: output: the checkpoint is of the output '"// &
            saved%output//"'"//refusal)
         return
      end if
      difference = scene_difference(scene_lines(saved%scene), scene_lines(batch%state%scene))
      if (len(difference) > 0) then
         call set_error(error, err_input, source//": "//difference//refusal)
         return
      end if
      call fingerprint_run(batch)
      if (any(saved%fingerprint /= batch%state%fingerprint) .or. saved%n_points /= batch%n_points) then
         if (index(new_line("a")//batch%state%scene, new_line("a")//"&points ") > 0) then
            call set_error(error, err_input, source//": &points: file: the points differ from those of the "// &
               "checkpoint (the file changed since)"//refusal)
         else
            call set_error(error, err_input, source//": the points differ from those of the checkpoint"//refusal)
         end if
         return
      end if
      ! the units of the checkpoint (the file does not depend on the cut, a chart's is its rows)
      call batch_set_unit_size(batch, saved%unit_size)
      if (batch%n_units /= saved%n_units) then
         call set_error(error, err_input, source//": the checkpoint's units do not tile the points"//refusal)
         return
      end if
      call remove_stale_temporary(batch%checkpoint, saved, temporary_prefix(batch%state%output))
      ! the recorded bytes must have the recorded checksum: nothing damaged goes on
      call resume_output(batch%file, batch%state%output, checkpoint_data(batch%checkpoint), saved%bytes, error, &
         context=source//": &scene: output: ", digest=saved%digest, damaged=damaged)
      if (allocated(error)) then
         if (damaged) error%message = error%message//"; the checkpoint '"//batch%checkpoint//"' is not resumed "// &
            "and kept as it is: run without --resume to discard it and start afresh"
         return
      end if
      batch%first_unit = saved%units_done + 1
      batch%done = min(batch%n_points, int(saved%units_done, int64)*batch%unit_size)
      batch%n_inaccurate = saved%n_inaccurate
      if (saved%first_inaccurate > 0) batch%first_inaccurate = batch%scene%task%point_of(batch%scene, saved%first_inaccurate)
      batch%n_failed = saved%n_failed
      if (saved%first_failed > 0) batch%first_failed = batch%scene%task%point_of(batch%scene, saved%first_failed)
      batch%state = saved
      batch%state%temporary = batch%file%temp_path
      batch%checkpoint_made = .true.
      ! the state names the new temporary file at once (a kill now leaves nothing unknown)
      call save_checkpoint_state(batch%checkpoint, batch%state, error)
      if (allocated(error)) then
         call discard_output(batch%file)
         error%message = source//": &scene: output: "//error%message
         return
      end if
      call set_resume_note(batch)
      call checkpoint_note(batch%options, "resuming "//batch%state%output//" from its checkpoint '"// &
         batch%checkpoint//"': "//progress_text(saved)//", "//integer_text(batch%n_points - batch%done)// &
         " to compute")
   end subroutine resume_batch

   !> What a signal prints from now on: the checkpoint is kept, and how to resume.
   subroutine set_resume_note(batch)
      type(batch_t), intent(in) :: batch
      character(len=:), allocatable :: head
      head = batch%options%program//": stopped by signal "
      ! on a terminal the progress line has no new line yet
      if (batch%progress%terminal) head = new_line("a")//head
      call set_interrupt_note(head, "; "//kept_text(batch))
   end subroutine set_resume_note

   !> "the checkpoint '…' keeps … points: `hillstab --resume s.nml` continues the run".
   function kept_text(batch) result(text)
      type(batch_t), intent(in) :: batch
      character(len=:), allocatable :: text
      text = "the checkpoint '"//batch%checkpoint//"' keeps "// &
         integer_text(min(batch%n_points, int(batch%state%units_done, int64)*batch%unit_size))//" of "// &
         integer_text(batch%n_points)//" points: `"//batch%options%command//"` continues the run"
   end function kept_text

   !> Put the file written so far on the disk and record it in the checkpoint (made on the
   !> first call). A failure to sync is the file's write error (`error`); a checkpoint that
   !> cannot be made or updated only costs the protection: a note, and the run goes on.
   subroutine update_checkpoint(batch, error)
      type(batch_t), intent(inout) :: batch
      type(error_t), allocatable, intent(inout) :: error
      type(error_t), allocatable :: cause
      character(len=:), allocatable :: why
      logical :: busy
      call sync_output(batch%file, error)
      if (allocated(error)) return
      call digest_written(batch%file, why)
      if (allocated(why)) then
         call checkpoint_note(batch%options, "cannot read back '"//batch%file%temp_path//"' for the checkpoint's "// &
                              "checksum: "//why//"; the run goes on without a checkpoint")
         batch%checkpointing = .false.
         return
      end if
      batch%state%units_done = int((batch%done + batch%unit_size - 1)/batch%unit_size)
      batch%state%bytes = batch%file%bytes
      batch%state%digest = digest_value(batch%file%digest)
      batch%state%n_inaccurate = batch%n_inaccurate
      batch%state%n_failed = batch%n_failed
      batch%state%temporary = batch%file%temp_path
      if (.not. batch%checkpoint_made) then
         call fingerprint_run(batch)
         busy = lock_output(batch%file)
         call make_checkpoint(batch%checkpoint, batch%file%temp_path, batch%state, cause)
         if (allocated(cause)) then
            call checkpoint_note(batch%options, cause%message//"; the run goes on without a checkpoint")
            batch%checkpointing = .false.
            return
         end if
         batch%checkpoint_made = .true.
      else
         call save_checkpoint_state(batch%checkpoint, batch%state, cause)
         if (allocated(cause)) then
            call checkpoint_note(batch%options, cause%message//"; the checkpoint keeps its last update, the "// &
               "run goes on without updating it")
            batch%checkpointing = .false.
            return
         end if
      end if
      call set_resume_note(batch)
   end subroutine update_checkpoint

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
      if (batch%scene%binary) then
         call write_bytes(batch%file, result%text, error)
      else
         call write_text(batch%file, result%text, error)
      end if
      if (allocated(error)) return
      if (any(result%status == status_roundoff)) then
         j = findloc(result%status, status_roundoff, dim=1)
         if (batch%n_inaccurate == 0) then
            batch%first_inaccurate = batch%scene%task%point_of(batch%scene, first + j - 1)
            batch%state%first_inaccurate = first + j - 1
         end if
         batch%n_inaccurate = batch%n_inaccurate + count(result%status == status_roundoff)
      end if
      if (any(result%status == status_failed)) then
         j = findloc(result%status, status_failed, dim=1)
         if (batch%n_failed == 0) then
            batch%first_failed = batch%scene%task%point_of(batch%scene, first + j - 1)
            batch%state%first_failed = first + j - 1
         end if
         batch%n_failed = batch%n_failed + count(result%status == status_failed)
      end if
      batch%done = last
      call progress_update(batch%progress, batch%done)
      if (batch%checkpointing) then
         if (checkpoint_due(batch)) call update_checkpoint(batch, error)
      end if
      if (batch%pause_after > 0 .and. result%unit >= batch%pause_after .and. .not. allocated(error)) &
         call test_pause(batch, result%unit)
   end subroutine batch_write

   !> The test hook: the unit after which the writer of a batch waits, from the environment
   !> variable HILLSTAB_TEST_PAUSE_AFTER_UNITS (read once, when the batch opens; 0 when it is
   !> unset or not a positive whole number). Only the tests set it: a test that kills a
   !> run (SIGKILL, SIGTERM, a killed MPI rank) waits for the pause, so that its signal lands
   !> mid-run however fast the machine is.
   integer function pause_hook() result(unit)
      character(len=16) :: text
      integer :: length, status, ios
      unit = 0
      call get_environment_variable(pause_variable, text, length, status)
      if (status /= 0 .or. length == 0) return
      if (verify(text(:length), "0123456789") /= 0) return
      read (text(:length), *, iostat=ios) unit
      if (ios /= 0 .or. unit < 0) unit = 0
   end function pause_hook

   !> The test hook's wait: the units 1 … `unit` are written (and, with the checkpoint
   !> interval 0, recorded in the checkpoint); say so on stderr and sleep, at most a minute,
   !> then go on. Once per run.
   subroutine test_pause(batch, unit)
      type(batch_t), intent(inout) :: batch
      integer, intent(in) :: unit
      integer :: k
      batch%pause_after = 0
      call checkpoint_note(batch%options, "test hook: paused after unit "//integer_text(unit)//" of "// &
         integer_text(batch%n_units)//" ("//pause_variable//")")
      do k = 1, 20*pause_seconds
         call pause_for(50000000_c_long)
      end do
   end subroutine test_pause

   !> Whether the checkpoint's interval has passed since its last update.
   logical function checkpoint_due(batch)
      type(batch_t), intent(inout) :: batch
      integer(int64) :: now, rate
      call system_clock(now, rate)
      checkpoint_due = real(now - batch%checkpoint_clock, wp) >= batch%options%interval*real(rate, wp)
      if (checkpoint_due) batch%checkpoint_clock = now
   end function checkpoint_due

   !> Finish the file (rename it onto its name) and remove its checkpoint; then the task's
   !> warnings, and with failed points `error` is err_points_failed naming the first (as
   !> after a serial run). A file that cannot be finished keeps its checkpoint.
   subroutine batch_commit(batch, error)
      type(batch_t), intent(inout) :: batch  !! the planned work with every unit written
      !> err_points_failed naming the first failed point, or a rename failure
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: cause
      call progress_end(batch%progress)
      call commit_output(batch%file, error)
      if (batch%checkpoint_made) then
         call clear_interrupt_note()
         if (allocated(error)) then
            error%message = error%message//"; "//kept_text(batch)
            return
         end if
         call remove_checkpoint(batch%checkpoint, cause)
         if (allocated(cause)) call checkpoint_note(batch%options, cause%message)
         batch%checkpoint_made = .false.
      end if
      if (allocated(error)) return
      call batch%scene%task%finish_units(batch%scene, batch%n_points, batch%n_failed, batch%first_failed, &
                                         batch%n_inaccurate, batch%first_inaccurate, error)
   end subroutine batch_commit

   !> Abandon the file: the temporary file is deleted, the final name left as it was. A
   !> checkpoint is kept; `error` (the failure that stopped the run) then says where and
   !> how to resume.
   subroutine batch_discard(batch, error)
      type(batch_t), intent(inout) :: batch  !! the planned work whose file is abandoned
      !> the error that stopped the run: the checkpoint kept is added to its message
      type(error_t), allocatable, intent(inout), optional :: error
      call progress_end(batch%progress)
      call discard_output(batch%file)
      if (batch%checkpoint_made) then
         call clear_interrupt_note()
         if (present(error)) then
            if (allocated(error)) error%message = error%message//"; "//kept_text(batch)
         end if
      end if
   end subroutine batch_discard

   !> Run a distributable scene unit by unit in this process, keeping a checkpoint (default
   !> options without `options`): the serial program's run of chart, points and lyapunov
   !> scenes, text or binary, and the reference order of work of a distributed run. With at least 4
   !> units a thread, units are computed on OpenMP threads, each written as soon as it is
   !> next in order; at most 16 a thread are held at once (a unit waits to start until it is
   !> within that window of the next to write). With fewer, units go one by one, each
   !> computed in parallel within (a chart's row in chunks, a run of points point by point).
   subroutine run_batch(scene, quiet, error, options)
      type(scene_t), intent(in) :: scene  !! a validated chart, points or lyapunov scene
      logical, intent(in) :: quiet  !! no progress on stderr
      type(error_t), allocatable, intent(out) :: error  !! what failed (err_points_failed: written with failed points)
      !> checkpoint and resume (default: a checkpoint, no resume)
      type(checkpoint_options_t), intent(in), optional :: options
      type(batch_t) :: batch
      type(batch_result_t), allocatable :: window(:)
      integer :: next_claim, next_write, slots, threads, status
      logical :: in_parallel, stopped
      integer(lock_kind) :: writer
      call batch_plan(scene, 1, batch)
      if (present(options)) then
         call batch_open(batch, quiet, error, options)
      else
         call batch_open(batch, quiet, error, checkpoint_options_t())
      end if
      if (allocated(error)) return
      threads = max_threads()
      in_parallel = batch%n_units >= 4*threads .or. &
                    (batch%scene%task%units_in_parallel .and. threads > 1 .and. batch%n_units > 1)
      slots = merge(16*threads, 1, in_parallel)
      allocate (window(0:slots - 1), stat=status)
      if (status /= 0) then
         call set_error(error, err_input, scene%source//": "//scene%task%size_variables()//": the buffers of "// &
            integer_text(slots)//" units cannot be allocated (out of memory)")
         call batch_discard(batch, error)
         return
      end if
      next_claim = batch%first_unit
      next_write = batch%first_unit
      stopped = .false.
      ! units are computed on several threads at once: a task's unit_text must not call a
      ! function with a deferred-length character result (gfortran 12 keeps that length in a
      ! static variable of the caller; concurrent calls lost a unit's text now and then),
      ! hence join_lines, not joined_lines, in the tasks
      !$ call omp_init_lock(writer)
      ! (a run of one thread is no parallel region at all: a region inside a region, even an
      ! inactive one, is nested, and libgomp starts and ends new threads for every nested
      ! team, such as the chunks of the rows of a chart with few rows)
      if (in_parallel) then
         !$omp parallel default(shared)
         call batch_loop(batch, window, slots, next_claim, next_write, stopped, writer, error)
         !$omp end parallel
      else
         call batch_loop(batch, window, slots, next_claim, next_write, stopped, writer, error)
      end if
      ! what arrived after the last writer's last look
      call write_ready(batch, window, slots, next_write, stopped, writer, error)
      !$ call omp_destroy_lock(writer)
      if (allocated(error)) then
         call batch_discard(batch, error)
      else
         call batch_commit(batch, error)
      end if
   end subroutine run_batch

   !> The units of `run_batch`, claimed one at a time by each thread that calls this (every
   !> thread of the team, or the one thread of a serial run): computed, kept in the window,
   !> written in order.
   subroutine batch_loop(batch, window, slots, next_claim, next_write, stopped, writer, error)
      type(batch_t), intent(inout) :: batch
      type(batch_result_t), intent(inout) :: window(0:)
      integer, intent(in) :: slots
      integer, intent(inout) :: next_claim, next_write
      logical, intent(inout) :: stopped
      integer(lock_kind), intent(inout) :: writer
      type(error_t), allocatable, intent(inout) :: error
      type(batch_result_t) :: result
      integer :: unit, written, slot
      logical :: stop_now
      do
         !$omp atomic capture
         unit = next_claim
         next_claim = next_claim + 1
         !$omp end atomic
         if (unit > batch%n_units) exit
         ! hold the unit back while it lies beyond the window of results kept, writing what
         ! is ready meanwhile: the unit next in order may have arrived just as the writer
         ! was leaving (it found the writer's lock held and went on), and with every other
         ! thread waiting here nobody else would write it
         do
            !$omp atomic read
            written = next_write
            !$omp atomic read
            stop_now = stopped
            if (unit < written + slots .or. stop_now) exit
            call write_ready(batch, window, slots, next_write, stopped, writer, error)
            call pause_briefly()
         end do
         if (stop_now) cycle
         call batch_compute(batch, unit, result)
         !$omp critical (hillstab_batch_window)
         slot = mod(unit, slots)
         window(slot)%unit = unit
         call move_alloc(result%text, window(slot)%text)
         call move_alloc(result%status, window(slot)%status)
         !$omp end critical (hillstab_batch_window)
         ! the units that are next in order are written by one thread at a time, outside the
         ! window's lock, while the others compute: the thread that holds the writer's lock
         ! writes what is ready; one that finds it held goes on (the holder, or the sweep
         ! after the loop, writes its unit)
         call write_ready(batch, window, slots, next_write, stopped, writer, error)
      end do
   end subroutine batch_loop

   !> Write the units of the window that are next in order, if no other thread is writing
   !> (the writer's lock, tested, not waited for); `next_write` advances past each. The
   !> window's entries are taken under its lock and written outside it.
   subroutine write_ready(batch, window, slots, next_write, stopped, writer, error)
      type(batch_t), intent(inout) :: batch
      type(batch_result_t), intent(inout) :: window(0:)
      integer, intent(in) :: slots
      integer, intent(inout) :: next_write
      logical, intent(inout) :: stopped
      integer(lock_kind), intent(inout) :: writer
      type(error_t), allocatable, intent(inout) :: error
      type(batch_result_t) :: ready
      type(error_t), allocatable :: failure
      integer :: slot
      logical :: have, mine
      mine = .true.
      !$ mine = omp_test_lock(writer)
      if (.not. mine) return
      do
         have = .false.
         !$omp critical (hillstab_batch_window)
         if (next_write <= batch%n_units .and. .not. stopped) then
            slot = mod(next_write, slots)
            if (allocated(window(slot)%status)) then
               if (window(slot)%unit == next_write) then
                  ready%unit = window(slot)%unit
                  call move_alloc(window(slot)%text, ready%text)
                  call move_alloc(window(slot)%status, ready%status)
                  have = .true.
               end if
            end if
         end if
         !$omp end critical (hillstab_batch_window)
         if (.not. have) exit
         call batch_write(batch, ready, failure)
         deallocate (ready%text, ready%status)
         if (allocated(failure)) then
            call move_alloc(failure, error)
            !$omp atomic write
            stopped = .true.
         end if
         !$omp atomic update
         next_write = next_write + 1
      end do
      !$ call omp_unset_lock(writer)
   end subroutine write_ready

   !> Wait a millisecond.
   subroutine pause_briefly()
      call pause_for(1000000_c_long)
   end subroutine pause_briefly

   !> Wait `nanoseconds` (< 1 s).
   subroutine pause_for(nanoseconds)
      integer(c_long), intent(in) :: nanoseconds
      type(timespec_t) :: remaining
      integer(c_int) :: status
      status = c_nanosleep(timespec_t(0_c_long, nanoseconds), remaining)
   end subroutine pause_for

   !> The kind of problem of a scene and its task, as a checkpoint records it: "scalar chart"
   !> (a Hill equation of `&scene model`), "system points" (`model = 'system'`).
   function problem_kind(scene) result(text)
      type(scene_t), intent(in) :: scene  !! a validated scene
      character(len=:), allocatable :: text
      if (allocated(scene%system)) then
         text = "system "//scene%task%name
      else
         text = "scalar "//scene%task%name
      end if
   end function problem_kind

   !> For a run that keeps no checkpoint (a task other than chart, points and lyapunov): what
   !> is at its output's checkpoint name is dealt with as a run that keeps one deals with it, so that a later --resume never continues a
   !> checkpoint this run has overwritten the output of. Without `resume`, a checkpoint found
   !> is discarded with a note (an incomplete or damaged one too); with it, a checkpoint
   !> (of another kind of problem: this run keeps none) is refused, err_input, and kept; an
   !> incomplete one is discarded with a note. Anything else at the name (a symbolic link, a
   !> file, a member that is not a regular file) is refused (err_io), as is a checkpoint
   !> another run is writing; nothing at the name: nothing is done.
   subroutine settle_checkpoint(scene, options, error)
      type(scene_t), intent(in) :: scene  !! a validated scene whose run keeps no checkpoint
      type(checkpoint_options_t), intent(in) :: options  !! --resume, the program's name
      type(error_t), allocatable, intent(out) :: error  !! err_input (refused), err_io (in the way)
      type(checkpoint_state_t) :: saved
      character(len=:), allocatable :: directory, reason, context, what
      integer :: kind
      directory = checkpoint_directory(output_path(scene))
      context = scene%source//": &scene: output: "
      call find_checkpoint(directory, kind, saved, reason, error)
      if (allocated(error)) then
         error%message = context//error%message
         return
      end if
      if (kind == checkpoint_usable) then
         what = " of a "//saved%problem//" ("//progress_text(saved)//")"
      else
         what = " ("//reason//")"
      end if
      select case (kind)
      case (checkpoint_usable, checkpoint_damaged)
         if (options%resume) then
            call set_error(error, err_input, scene%source//": &scene: model: the checkpoint '"//directory//"'"// &
               what//" cannot be resumed by this run ("//problem_kind(scene)//"), which keeps no checkpoint; "// &
               "it is not resumed and kept as it is: run without --resume to discard it and start afresh")
            return
         end if
      case (checkpoint_incomplete)
      case default
         return
      end select
      call remove_stale_temporary(directory, saved, temporary_prefix(output_path(scene)))
      call remove_checkpoint(directory, error)
      if (allocated(error)) then
         error%message = context//error%message
         return
      end if
      call checkpoint_note(options, "discarded the checkpoint '"//directory//"'"//what//": this run ("// &
         problem_kind(scene)//") keeps no checkpoint and writes "//output_path(scene)//" afresh")
   end subroutine settle_checkpoint

end module hillstab_batch_run_units

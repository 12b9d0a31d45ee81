!> Running scenes: read a scene file (hillstab_batch_run_read) and run its task, after
!> the checks every run makes before any work (the output must fit where it goes).
!> Errors come back in `error` with the scene file, group and variable named; no output
!> file is created or touched unless the task completes. A point that cannot be computed
!> does not stop a chart, points or lyapunov task: its row carries status 2 and
!> placeholders, the file is written, and `error` comes back with err_points_failed.
!>
!> Scenes whose points are independent (chart over `&chart`, points, lyapunov), text or
!> binary, run unit by unit (hillstab_batch_run_units `run_batch`, the driver `hillstab_mpi`
!> shares) and keep a checkpoint as they go, so that `--resume` continues them; the others
!> run their task's own loop and keep none.
!>
!>```fortran
!> type(error_t), allocatable :: error
!> call run_scene_file("data/scenes/default_exact.nml", quiet=.false., error=error)
!>```
module hillstab_batch_run_scenes
   use hillstab_core_error, only: error_t, err_points_failed, err_io
   use hillstab_batch_scene_types, only: scene_t, output_path
   use hillstab_batch_run_read, only: read_scene
   use hillstab_batch_run_limits, only: check_output_room, check_memory_room
   use hillstab_batch_run_units, only: batch_distributable, run_batch, settle_checkpoint
   use hillstab_batch_output_checkpoint, only: checkpoint_options_t, checkpoint_note
   use, intrinsic :: iso_fortran_env, only: error_unit
   implicit none
   private
   public :: run_scene_file, run_scene, output_path, warn_scene, name_scene_file

contains

   !> Read the scene file `path` and run it.
   subroutine run_scene_file(path, quiet, error, written, options)
      character(len=*), intent(in) :: path  !! scene file (a previous output file also works)
      logical, intent(in) :: quiet          !! no progress on stderr
      type(error_t), allocatable, intent(out) :: error  !! what failed (err_points_failed: written with failed points)
      character(len=:), allocatable, intent(out), optional :: written  !! the file written
      !> checkpoints: resume, interval (default: a checkpoint every 3 s, no resume)
      type(checkpoint_options_t), intent(in), optional :: options
      type(scene_t) :: scene
      call read_scene(path, scene, error)
      if (allocated(error)) return
      call warn_scene(scene)
      call run_scene(scene, quiet, error, options)
      if (allocated(error)) then
         if (error%code /= err_points_failed) return
      end if
      if (present(written)) written = output_path(scene)
   end subroutine run_scene_file

   !> Say on stderr, one line each, what reading the scene found suspect (`scene%warnings`:
   !> a group its task does not read, a spring longer than 100 m, ...), also when quiet:
   !> it may mean the run is not the one meant.
   subroutine warn_scene(scene, program)
      type(scene_t), intent(in) :: scene  !! a validated scene
      character(len=*), intent(in), optional :: program  !! the name the lines start with (default hillstab)
      character(len=:), allocatable :: name
      integer :: start, stop
      if (.not. allocated(scene%warnings)) return
      name = "hillstab"
      if (present(program)) name = program
      start = 1
      do while (start <= len(scene%warnings))
         stop = index(scene%warnings(start:), achar(10))
         if (stop == 0) then
            stop = len(scene%warnings) + 1
         else
            stop = start + stop - 1
         end if
         write (error_unit, '(a)') name//": warning: "//scene%warnings(start:stop - 1)
         start = stop + 1
      end do
   end subroutine warn_scene

   !> Run a validated scene: unit by unit with a checkpoint when its points are independent,
   !> else by its task's own loop (with `options%resume`, afresh with a note).
   !> A run that keeps no checkpoint deals with one found at its output's name first
   !> (hillstab_batch_run_units `settle_checkpoint`: discarded with a note, refused under
   !> `--resume`).
   subroutine run_scene(scene, quiet, error, options)
      type(scene_t), intent(in) :: scene  !! a validated scene
      logical, intent(in) :: quiet  !! no progress on stderr
      type(error_t), allocatable, intent(out) :: error  !! what failed (err_points_failed: written with failed points)
      !> checkpoints: resume, interval (default: a checkpoint every 3 s, no resume)
      type(checkpoint_options_t), intent(in), optional :: options
      logical :: resume
      resume = .false.
      if (present(options)) resume = options%resume
      ! an output that cannot fit where it goes is refused before any work
      call check_output_room(scene, output_path(scene), error)
      if (allocated(error)) return
      ! as are buffers that would not fit in memory
      call check_memory_room(scene, error)
      if (allocated(error)) return
      if (batch_distributable(scene)) then
         call run_batch(scene, quiet, error, options)
         call name_scene_file(scene, error)
         return
      end if
      ! a checkpoint at its output's name is discarded with a note, or refused under --resume
      if (present(options)) then
         call settle_checkpoint(scene, options, error)
         if (allocated(error)) return
      end if
      if (resume) call checkpoint_note(options, scene%source//": this run keeps no checkpoint (only charts, points "// &
         "and lyapunov runs do): running it afresh")
      call scene%task%run(scene, quiet, error)
      call name_scene_file(scene, error)
   end subroutine run_scene

   !> A failure to write the output (err_io: a full file system, a file-size limit) named by
   !> the scene that set the output, "<scene>: &scene: output: cannot write '…': …", as every
   !> other message of a run is (nothing is added to a message that names the scene already).
   subroutine name_scene_file(scene, error)
      type(scene_t), intent(in) :: scene  !! the scene run
      type(error_t), allocatable, intent(inout) :: error  !! what the run ended with (if anything)
      if (.not. allocated(error)) return
      if (error%code /= err_io .or. len(error%message) == 0) return
      if (index(error%message, scene%source//": ") == 1) return
      error%message = scene%source//": &scene: output: "//error%message
   end subroutine name_scene_file
end module hillstab_batch_run_scenes

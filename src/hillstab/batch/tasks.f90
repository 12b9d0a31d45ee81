!> Running scenes: read a scene file (hillstab_batch_scene_read) and run its task, after
!> the checks every run makes before any work (the output must fit where it goes).
!> Errors come back in `error` with the scene file, group and variable named; no output
!> file is created or touched unless the task completes. A point that cannot be computed
!> does not stop a chart, points or lyapunov task: its row carries status 2 and
!> placeholders, the file is written, and `error` comes back with err_points_failed.
!>
!>```fortran
!> type(error_t), allocatable :: error
!> call run_scene_file("data/scenes/default_exact.nml", quiet=.false., error=error)
!>```
module hillstab_batch_tasks
   use hillstab_core_error, only: error_t, err_points_failed
   use hillstab_batch_scene, only: scene_t, output_path
   use hillstab_batch_scene_read, only: read_scene
   use hillstab_batch_limits, only: check_output_room, check_memory_room
   implicit none
   private
   public :: run_scene_file, run_scene, output_path

contains

   !> Read the scene file `path` and run it.
   subroutine run_scene_file(path, quiet, error, written)
      character(len=*), intent(in) :: path  !! scene file (a previous output file also works)
      logical, intent(in) :: quiet          !! no progress on stderr
      type(error_t), allocatable, intent(out) :: error  !! what failed (err_points_failed: written with failed points)
      character(len=:), allocatable, intent(out), optional :: written  !! the file written
      type(scene_t) :: scene
      call read_scene(path, scene, error)
      if (allocated(error)) return
      call run_scene(scene, quiet, error)
      if (allocated(error)) then
         if (error%code /= err_points_failed) return
      end if
      if (present(written)) written = output_path(scene)
   end subroutine run_scene_file

   !> Run a validated scene.
   subroutine run_scene(scene, quiet, error)
      type(scene_t), intent(in) :: scene  !! a validated scene
      logical, intent(in) :: quiet  !! no progress on stderr
      type(error_t), allocatable, intent(out) :: error  !! what failed (err_points_failed: written with failed points)
      ! an output that cannot fit where it goes is refused before any work
      call check_output_room(scene, output_path(scene), error)
      if (allocated(error)) return
      ! as are buffers that would not fit in memory
      call check_memory_room(scene, error)
      if (allocated(error)) return
      call scene%task%run(scene, quiet, error)
   end subroutine run_scene
end module hillstab_batch_tasks

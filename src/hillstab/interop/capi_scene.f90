!> C-callable scene runs: a namelist scene file run as the command line `hillstab SCENE.nml`
!> runs it (hillstab_batch_run_scenes `run_scene_file`), its output file written where the
!> scene says (a relative path is taken from the current directory). Conventions as in
!> hillstab_interop_capi: a status returned, the full message in `hillstab_last_error`.
!> Bad input (a missing file, a bad group or variable) is err_input (5) with a message
!> naming the file, the group and the variable, and nothing is written; a scene whose
!> file was written but some of whose points failed returns HILLSTAB_ERR_POINTS_FAILED
!> (8), the file's path in `written` all the same.
!>
!>```c
!> char written[4096];
!> int status = hillstab_run_scene("data/scenes/default_exact.nml", 1, written, sizeof written);
!>```
module hillstab_interop_capi_scene
   use, intrinsic :: iso_c_binding, only: c_int, c_char, c_size_t
   use hillstab_core_error, only: error_t, set_error, err_input, err_points_failed
   use hillstab_core_text, only: integer_text
   use hillstab_batch_run_scenes, only: run_scene_file
   use hillstab_interop_outcome, only: record_outcome
   use hillstab_interop_capi_models, only: c_text, copy_text, max_c_text
   implicit none
   private
   public :: hillstab_c_run_scene

contains

   !> `int hillstab_run_scene(const char *path, int quiet, char *written, size_t length)`:
   !> read the scene file `path` and run it; `quiet` = 0 shows progress on stderr. The
   !> path of the file written goes to `written` (NUL-terminated, cut to `length` bytes) on
   !> success and with HILLSTAB_ERR_POINTS_FAILED; it is untouched otherwise.
   function hillstab_c_run_scene(path, quiet, written, length) result(status) bind(C, name="hillstab_run_scene")
      character(kind=c_char), intent(in) :: path(*)  !! the scene file, NUL-terminated
      integer(c_int), value, intent(in) :: quiet  !! 1: no progress on stderr
      integer(c_size_t), value, intent(in) :: length  !! size of `written` in bytes
      character(kind=c_char), intent(inout) :: written(*)  !! receives the output file's path
      integer(c_int) :: status
      type(error_t), allocatable :: error
      character(len=:), allocatable :: text, output
      logical :: ok
      call c_text(path, text, ok)
      if (.not. ok) then
         call set_error(error, err_input, "the scene path is longer than "//integer_text(max_c_text)//" characters")
      else
         call run_scene_file(text, quiet /= 0, error, written=output)
      end if
      call record_outcome(error)
      status = 0
      if (allocated(error)) status = int(error%code, c_int)
      if (allocated(output)) then
         if (status == 0 .or. status == err_points_failed) call copy_text(output, written, length)
      end if
   end function hillstab_c_run_scene
end module hillstab_interop_capi_scene

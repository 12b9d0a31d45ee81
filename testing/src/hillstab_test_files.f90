!> Test helpers shared by the task suites: run a scene given as lines, and run a
!> result file again as a scene and compare what it writes.
module hillstab_test_files
   use hillstab_core_error, only: error_t
   use hillstab_batch_run_scenes, only: run_scene_file
   use hillstab_testing, only: test_context_t, check
   use hillstab_test_scratch, only: scratch_prefix, write_file, read_lines, delete_file
   implicit none
   private
   public :: run_text_scene, check_rerun

contains

   !> Write `lines` to the scratch scene file `scratch_prefix(name)//".nml"`, run it
   !> quietly, delete the scene file.
   subroutine run_text_scene(name, lines, error, written)
      character(len=*), intent(in) :: name      !! scratch name of the scene file
      character(len=*), intent(in) :: lines(:)  !! the scene's lines
      type(error_t), allocatable, intent(out) :: error  !! the run's error
      character(len=:), allocatable, intent(out) :: written  !! path of the file written
      character(len=:), allocatable :: path
      path = scratch_prefix(name)//".nml"
      call write_file(path, lines)
      call run_scene_file(path, .true., error, written)
      call delete_file(path)
   end subroutine run_text_scene

   !> Run the result file `written` as a scene: it must run, and the file it writes
   !> (`again`) must hold the lines `first` apart from the `# scene file:` line.
   !> `ok` is false when the second run failed.
   subroutine check_rerun(ctx, written, first, again, ok)
      type(test_context_t), intent(inout) :: ctx
      character(len=*), intent(in) :: written   !! the first run's result file
      character(len=*), intent(in) :: first(:)  !! its lines
      character(len=:), allocatable, intent(out) :: again  !! the second run's result file
      logical, intent(out) :: ok                !! the second run succeeded
      type(error_t), allocatable :: error
      character(len=1024), allocatable :: second(:)
      integer :: k
      call run_scene_file(written, .true., error, again)
      ok = .not. allocated(error)
      call check(ctx, ok, "second run from the output file")
      if (.not. ok) then
         call check(ctx, .false., error%message)
         return
      end if
      second = read_lines(again)
      call check(ctx, size(first) == size(second), "same number of lines")
      if (size(first) /= size(second)) return
      do k = 1, size(first)
         if (index(first(k), "# scene file:") == 1) cycle
         call check(ctx, first(k) == second(k), "line "//trim(first(k)))
      end do
   end subroutine check_rerun
end module hillstab_test_files

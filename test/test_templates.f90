!> Tests of the scene templates (`hillstab --template TASK`): every template is a valid
!> scene whose values are the defaults, names every variable of its task's effective
!> scene, and every task the scene reader accepts has one.
module test_templates
   use hillstab_core_error, only: error_t, err_input
   use hillstab_batch_scene, only: scene_t, task_t, scene_namelist
   use hillstab_batch_scene_read, only: read_scene
   use hillstab_batch_declaration, only: group_t
   use hillstab_batch_task_registry, only: new_task, task_names
   use hillstab_batch_templates, only: template_task_names, scene_template
   use test_scene, only: scratch_prefix, write_file, delete_file
   use hillstab_testing
   implicit none
   private
   public :: collect_templates

contains

   function collect_templates() result(suite)
      type(testsuite_t) :: suite
      suite = new_testsuite("templates", [ &
         new_unittest("templates_read_back_as_defaults", templates_read_back_as_defaults), &
         new_unittest("templates_name_every_variable", templates_name_every_variable), &
         new_unittest("physical_variant_reads", physical_variant_reads), &
         new_unittest("every_task_has_a_template", every_task_has_a_template), &
         new_unittest("unknown_task", unknown_task), &
         new_unittest("guide_shows_every_template", guide_shows_every_template)])
   end function collect_templates

   !> The scene reference of the guide (docs/guide/scene-reference.md) holds every task's
   !> template verbatim: regenerate it with `python3 scripts/scene_reference.py`.
   subroutine guide_shows_every_template(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=*), parameter :: page_path = "docs/guide/scene-reference.md"
      character(len=:), allocatable :: page, text, names(:)
      character(len=4096) :: line
      type(error_t), allocatable :: error
      integer :: unit, ios, k, last
      page = ""
      open (newunit=unit, file=page_path, status="old", action="read", iostat=ios)
      call check(ctx, ios == 0, "cannot open "//page_path//" (run the tests from the repository root)")
      if (ios /= 0) return
      do
         read (unit, '(a)', iostat=ios) line
         if (ios /= 0) exit
         page = page//trim(line)//new_line("a")
      end do
      close (unit)
      names = template_task_names()
      do k = 1, size(names)
         call scene_template(trim(names(k)), text, error)
         call check(ctx, .not. allocated(error), "template of "//trim(names(k)))
         if (allocated(error)) cycle
         last = len(text)
         do while (last > 0)
            if (text(last:last) /= new_line("a")) exit
            last = last - 1
         end do
         call check(ctx, index(page, "```text"//new_line("a")//text(:last)//new_line("a")//"```") > 0, &
            page_path//" shows the current template of task '"//trim(names(k))// &
            "' (run python3 scripts/scene_reference.py)")
      end do
   end subroutine guide_shows_every_template

   !> `text` with every `old` replaced by `new`.
   function replaced(text, old, new) result(out)
      character(len=*), intent(in) :: text, old, new
      character(len=:), allocatable :: out
      integer :: at, from
      out = ""
      from = 1
      do
         at = index(text(from:), old)
         if (at == 0) exit
         out = out//text(from:from + at - 2)//new
         from = from + at - 1 + len(old)
      end do
      out = out//text(from:)
   end function replaced

   !> Write the template of `task` to a scratch scene file (its example points file made
   !> real) and read it back.
   subroutine read_template(task, path, scene, error)
      character(len=*), intent(in) :: task
      character(len=:), allocatable, intent(out) :: path
      type(scene_t), intent(out) :: scene
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: text
      call scene_template(task, text, error)
      if (allocated(error)) return
      path = scratch_prefix("template_"//task)//".nml"
      call write_file(path//".points", ["1.0 2.0"])
      text = replaced(text, "'points.dat'", "'"//path//".points'")
      call write_file(path, [text])
      call read_scene(path, scene, error)
   end subroutine read_template

   !> A template read back gives the scene of its task with every group given empty: its
   !> values are the defaults.
   subroutine templates_read_back_as_defaults(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=:), allocatable :: names(:), path, got(:), expected(:), minimal(:)
      type(scene_t) :: scene, defaults
      type(error_t), allocatable :: error
      class(task_t), allocatable :: task
      type(group_t), allocatable :: groups(:)
      integer :: k, g
      names = template_task_names()
      do k = 1, size(names)
         call read_template(trim(names(k)), path, scene, error)
         if (allocated(error)) then
            call check(ctx, .false., trim(names(k))//": "//error%message)
            cycle
         end if
         call check(ctx, scene%task%name == trim(names(k)), trim(names(k))//": the template's task")
         call new_task(trim(names(k)), task, error)
         groups = task%declarations()
         allocate (character(len=200) :: minimal(1 + size(groups)))
         minimal(1) = "&scene task = '"//trim(names(k))//"' /"
         do g = 1, size(groups)
            minimal(1 + g) = "&"//groups(g)%name//" /"
            if (groups(g)%name == "points") minimal(1 + g) = "&points file = '"//path//".points' /"
         end do
         call write_file(path, minimal)
         call read_scene(path, defaults, error)
         deallocate (minimal)
         if (allocated(error)) then
            call check(ctx, .false., trim(names(k))//" (empty groups): "//error%message)
            cycle
         end if
         got = scene_namelist(scene)
         expected = scene_namelist(defaults)
         call check(ctx, size(got) == size(expected), trim(names(k))//": as many groups")
         if (size(got) == size(expected)) call check(ctx, all(got == expected), trim(names(k))// &
            ": values are the defaults: "//trim(got(1))//" "//trim(got(2))//" against "//trim(expected(1))//" "// &
            trim(expected(2)))
         call delete_file(path)
         call delete_file(path//".points")
      end do
   end subroutine templates_read_back_as_defaults

   !> Every `name =` of the effective scene (as written into output headers) appears in
   !> the template, so a variable added to a group must be documented there too.
   subroutine templates_name_every_variable(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=:), allocatable :: names(:), path, lines(:), text, variable
      type(scene_t) :: scene
      type(error_t), allocatable :: error
      integer :: k, line, at, from, start
      names = template_task_names()
      do k = 1, size(names)
         call read_template(trim(names(k)), path, scene, error)
         if (allocated(error)) cycle  ! reported by templates_read_back_as_defaults
         call scene_template(trim(names(k)), text, error)
         lines = scene_namelist(scene)
         do line = 1, size(lines)
            from = 1
            do
               at = index(lines(line)(from:), " = ")
               if (at == 0) exit
               at = from + at - 1
               start = index(lines(line)(:at - 1), " ", back=.true.) + 1
               variable = lines(line)(start:at - 1)
               call check(ctx, index(text, " "//variable//" = ") > 0, trim(names(k))//": the template "// &
                  "names '"//variable//"' (declare it in its group)")
               from = at + 3
            end do
         end do
         call delete_file(path)
         call delete_file(path//".points")
      end do
   end subroutine templates_name_every_variable

   !> Following the template's own instructions for `&physical` (uncomment it, drop
   !> `&scene epsilon` and what `r0` with `a` replace) gives a valid physical scene.
   subroutine physical_variant_reads(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=:), allocatable :: names(:), path, text, line, out
      character(len=*), parameter :: dropped(4) = [character(len=12) :: "epsilon =", "file =", "alphas =", "beta ="]
      type(scene_t) :: scene
      type(error_t), allocatable :: error
      logical :: inside
      integer :: k, from, at, j
      names = template_task_names()
      do k = 1, size(names)
         call scene_template(trim(names(k)), text, error)
         if (allocated(error)) cycle
         ! a task whose template offers no &physical variant (series takes r0, g itself)
         if (index(text, "! &physical") == 0) cycle
         out = ""
         inside = .false.
         from = 1
         do while (from <= len(text))
            at = index(text(from:), new_line("a"))
            if (at == 0) at = len(text) - from + 2
            line = text(from:from + at - 2)
            from = from + at
            if (line == "! &physical") inside = .true.
            if (inside) line = line(3:)
            if (line == "/" .and. inside) inside = .false.
            do j = 1, size(dropped)
               if (index(adjustl(line), trim(dropped(j))) == 1) line = ""
            end do
            out = out//line//new_line("a")
         end do
         path = scratch_prefix("template_physical_"//trim(names(k)))//".nml"
         call write_file(path, [out])
         call read_scene(path, scene, error)
         if (allocated(error)) then
            call check(ctx, .false., trim(names(k))//" with &physical: "//error%message)
         else
            call check(ctx, scene%physical, trim(names(k))//": the scene is physical")
         end if
         call delete_file(path)
      end do
   end subroutine physical_variant_reads

   !> A task that the scene reader accepts (anything but "not available in this build")
   !> has a template.
   subroutine every_task_has_a_template(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=:), allocatable :: names(:), text
      type(error_t), allocatable :: error
      integer :: k
      names = task_names()
      do k = 1, size(names)
         call scene_template(trim(names(k)), text, error)
         call check(ctx, .not. allocated(error) .and. any(template_task_names() == names(k)), "task '"// &
            trim(names(k))//"' has a template")
      end do
   end subroutine every_task_has_a_template

   subroutine unknown_task(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=:), allocatable :: text
      type(error_t), allocatable :: error
      call scene_template("typo", text, error)
      call check(ctx, allocated(error), "an error")
      if (.not. allocated(error)) return
      call check(ctx, error%code == err_input .and. index(error%message, "'typo'") > 0 .and. &
         index(error%message, "chart") > 0, "names the task and the known ones: "//error%message)
   end subroutine unknown_task
end module test_templates

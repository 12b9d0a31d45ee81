!> Tests of the scene templates (`hillstab --template TASK`): every template is a valid
!> scene whose values are the defaults, names every variable of its task's effective
!> scene, runs as printed and with each commented alternative uncommented as its comment
!> instructs, and every task the scene reader accepts has one.
module test_templates
   use hillstab_core_error, only: error_t, err_input
   use hillstab_batch_scene_types, only: scene_t, task_t, scene_namelist
   use hillstab_batch_run_read, only: read_scene
   use hillstab_batch_run_scenes, only: run_scene_file
   use hillstab_batch_scene_declaration, only: group_t
   use hillstab_batch_tasks_registry, only: new_task, task_names
   use hillstab_batch_run_templates, only: template_task_names, scene_template
   use hillstab_test_scratch, only: scratch_prefix, write_file, delete_file
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
         new_unittest("templates_run_as_printed", templates_run_as_printed), &
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

   !> Every template runs as printed (exit 0; the points template names its points file,
   !> the one thing to fill in, and runs once it exists), and every commented alternative
   !> runs when uncommented as its comment instructs: the &physical group (its lines from
   !> &physical to / without their first two characters, and what it replaces deleted), in
   !> it k and m instead of omega, the range a_min, a_max, n_a instead of a, r0 alone for
   !> the critical amplitudes of a spring (the &chart group deleted), and the &points group
   !> of task lyapunov with over = 'points'. Task lyapunov's own chart (200 x 200 points of
   !> 50 periods, seconds of work) is read and checked, not run; its &points variant runs.
   subroutine templates_run_as_printed(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=:), allocatable :: names(:), text, physical, variant, points_path, prefix
      type(error_t), allocatable :: error
      type(scene_t) :: scene
      integer :: k
      names = template_task_names()
      prefix = scratch_prefix("tpl_run")
      points_path = prefix//"_pts.dat"
      call write_file(points_path, ["1.0 2.0", "3.0 2.5"])
      do k = 1, size(names)
         call scene_template(trim(names(k)), text, error)
         if (allocated(error)) cycle
         text = with_output(text, prefix//"_"//trim(names(k)))
         select case (trim(names(k)))
         case ("points")
            call run_text(ctx, "points as printed", text, error)
            call check(ctx, allocated(error), "points as printed: the points file is missing")
            if (allocated(error)) call check(ctx, error%code == err_input .and. &
               index(error%message, "&points: file: cannot open 'points.dat'") > 0, &
               "names the points file to fill in: "//error%message)
            call run_ok(ctx, "points with its file", replaced(text, "'points.dat'", "'"//points_path//"'"))
         case ("lyapunov")
            call write_file(prefix//"_lyap.nml", [text])
            call read_scene(prefix//"_lyap.nml", scene, error)
            call check(ctx, .not. allocated(error), "lyapunov as printed reads")
            call delete_file(prefix//"_lyap.nml")
            variant = uncommented_group(text, "points")
            variant = replaced(replaced(variant, "over = 'chart'", "over = 'points'"), "'points.dat'", &
                               "'"//points_path//"'")
            call check(ctx, index(variant, "over = 'points'") > 0 .and. index(variant, "&points") > 0, &
                       "lyapunov: the &points alternative and over = 'points'")
            call run_ok(ctx, "lyapunov over the points of its &points alternative", variant)
         case default
            call run_ok(ctx, trim(names(k))//" as printed", text)
         end select
         if (index(text, "! &physical") == 0) cycle
         ! the &physical alternative, as its comment says
         physical = uncommented_group(text, "physical")
         select case (trim(names(k)))
         case ("points")
            physical = without_group(physical, "points")
         case ("coefficient")
            physical = without_lines(without_lines(physical, "  alphas ="), "  beta =")
         case ("series")
            physical = without_lines(without_lines(without_lines(without_lines(physical, "  alpha ="), "  beta ="), &
                                     "  r0 ="), "  g =")
         case ("lyapunov")
            physical = without_group(without_lines(without_lines(physical, "  r0 ="), "  g ="), "chart")
         end select
         call run_ok(ctx, trim(names(k))//" with &physical", physical)
         ! k and m instead of omega
         variant = without_lines(replaced(replaced(physical, new_line("a")//"! k =", new_line("a")//"k ="), &
                                          new_line("a")//"! m =", new_line("a")//"m ="), "omega =")
         call check(ctx, index(variant, new_line("a")//"k =") > 0 .and. index(variant, new_line("a")//"m =") > 0, &
                    trim(names(k))//": k and m offered")
         call run_ok(ctx, trim(names(k))//" with &physical k and m", variant)
         if (index(physical, "! a_min =") > 0 .and. index(physical, "! omega_min =") == 0) then
            variant = without_lines(replaced(replaced(replaced(physical, new_line("a")//"! a_min =", &
               new_line("a")//"a_min ="), new_line("a")//"! a_max =", new_line("a")//"a_max ="), &
               new_line("a")//"! n_a =", new_line("a")//"n_a ="), "a =")
            call run_ok(ctx, trim(names(k))//" with &physical a_min, a_max, n_a", variant)
         end if
         if (index(physical, new_line("a")//"! omega_min =") > 0) then
            ! r0 with the ranges of a and omega: a chart over (a, omega)
            variant = physical
            variant = replaced(variant, new_line("a")//"! r0 =", new_line("a")//"r0 =")
            variant = replaced(variant, new_line("a")//"! a_min =", new_line("a")//"a_min =")
            variant = replaced(variant, new_line("a")//"! a_max =", new_line("a")//"a_max =")
            variant = replaced(variant, new_line("a")//"! n_a =", new_line("a")//"n_a =")
            variant = replaced(variant, new_line("a")//"! omega_min =", new_line("a")//"omega_min =")
            variant = replaced(variant, new_line("a")//"! omega_max =", new_line("a")//"omega_max =")
            variant = replaced(variant, new_line("a")//"! n_omega =", new_line("a")//"n_omega =")
            ! the list a, where the task also takes one, goes: the range replaces it
            variant = without_group(without_lines(without_lines(variant, "omega ="), "a ="), "chart")
            call run_ok(ctx, trim(names(k))//" with &physical over (a, omega)", variant)
         else if (index(physical, new_line("a")//"! r0 =") > 0) then
            variant = without_group(replaced(physical, new_line("a")//"! r0 =", new_line("a")//"r0 ="), "chart")
            call run_ok(ctx, trim(names(k))//" with &physical r0 (the critical amplitudes)", variant)
         end if
      end do
      call delete_file(points_path)
   contains
      subroutine run_ok(ctx, what, scene_text)
         type(test_context_t), intent(inout) :: ctx
         character(len=*), intent(in) :: what, scene_text
         type(error_t), allocatable :: error
         call run_text(ctx, what, scene_text, error)
         call check(ctx, .not. allocated(error), what//" runs")
         if (allocated(error)) call check(ctx, .false., what//": "//error%message)
      end subroutine run_ok
      subroutine run_text(ctx, what, scene_text, error)
         type(test_context_t), intent(inout) :: ctx
         character(len=*), intent(in) :: what, scene_text
         type(error_t), allocatable, intent(out) :: error
         character(len=:), allocatable :: path, written
         path = prefix//".nml"
         call write_file(path, [scene_text])
         call run_scene_file(path, .true., error, written)
         if (.not. allocated(error)) call check(ctx, len(written) > 0, what//": a file written")
         if (.not. allocated(error)) call delete_file(written)
         call delete_file(path)
      end subroutine run_text
   end subroutine templates_run_as_printed

   !> The template with `output` set in its &scene group (the runs write to scratch files).
   function with_output(text, output) result(out)
      character(len=*), intent(in) :: text, output
      character(len=:), allocatable :: out
      integer :: at
      at = index(text, new_line("a")//"&scene")
      out = text(:at + len("&scene"))//" output = '"//output//"',"//text(at + len("&scene") + 1:)
   end function with_output

   !> The text with the lines of the commented group `name` (from "! &name" to "! /")
   !> without their first two characters.
   function uncommented_group(text, name) result(out)
      character(len=*), intent(in) :: text, name
      character(len=:), allocatable :: out, line
      logical :: inside
      integer :: from, at
      out = ""
      inside = .false.
      from = 1
      do while (from <= len(text))
         at = index(text(from:), new_line("a"))
         if (at == 0) at = len(text) - from + 2
         line = text(from:from + at - 2)
         from = from + at
         if (line == "! &"//name) inside = .true.
         if (inside .and. len(line) >= 2) then
            if (line(1:2) == "! ") line = line(3:)
         end if
         if (inside .and. line == "/") inside = .false.
         out = out//line//new_line("a")
      end do
   end function uncommented_group

   !> The text without the lines that start with `start`.
   function without_lines(text, start) result(out)
      character(len=*), intent(in) :: text, start
      character(len=:), allocatable :: out, line
      integer :: from, at
      out = ""
      from = 1
      do while (from <= len(text))
         at = index(text(from:), new_line("a"))
         if (at == 0) at = len(text) - from + 2
         line = text(from:from + at - 2)
         from = from + at
         if (index(line, start) == 1) cycle
         out = out//line//new_line("a")
      end do
   end function without_lines

   !> The text without the (uncommented) group `name`: its lines from "&name" to "/".
   function without_group(text, name) result(out)
      character(len=*), intent(in) :: text, name
      character(len=:), allocatable :: out, line
      logical :: inside
      integer :: from, at
      out = ""
      inside = .false.
      from = 1
      do while (from <= len(text))
         at = index(text(from:), new_line("a"))
         if (at == 0) at = len(text) - from + 2
         line = text(from:from + at - 2)
         from = from + at
         if (index(line, "&"//name) == 1) inside = .true.
         if (inside) then
            if (line == "/") inside = .false.
            cycle
         end if
         out = out//line//new_line("a")
      end do
   end function without_group

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

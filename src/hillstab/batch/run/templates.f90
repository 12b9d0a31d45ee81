!> Commented scene templates: `hillstab --template TASK` prints a complete scene for a
!> task, every variable at its default with a comment saying what it means, so the
!> installed program documents its own input. Everything comes from the declarations of
!> the groups (hillstab_batch_scene_declaration) and the task registry: the groups a task
!> reads (`task_t%declarations`), the alternatives it offers commented out, and the
!> optional `&physical` group. A new task or variable has a template without an edit here.
!>
!>```fortran
!> character(len=:), allocatable :: text
!> type(error_t), allocatable :: error
!> call scene_template("chart", text, error)
!> if (.not. allocated(error)) write (*, '(a)') text
!>```
module hillstab_batch_run_templates
   use hillstab_core_error, only: error_t, set_error, err_input
   use hillstab_batch_scene_types, only: task_t
   use hillstab_batch_scene_physical, only: pendulum_task_t
   use hillstab_batch_scene_declaration, only: group_t, variable_t, var_real_list
   use hillstab_batch_run_read, only: scene_group, physical_group
   use hillstab_batch_tasks_registry, only: task_entry_t, task_entries, task_names, task_names_text, new_task
   implicit none
   private
   public :: template_task_names, scene_template

   !> Line break inside a template text.
   character(len=*), parameter :: nl = new_line("a")
   !> Column at which the comments of the variables start.
   integer, parameter :: comment_column = 28
   !> Longest line of a template (longer comments are wrapped).
   integer, parameter :: line_width = 100

contains

   !> The tasks that have a template, in the order `--help` lists them (every registered task).
   function template_task_names() result(names)
      character(len=:), allocatable :: names(:)  !! task names, blank-padded to a common length
      names = task_names()
   end function template_task_names

   !> The complete commented scene of `task` (lines separated by new_line('a'), no final
   !> newline); an `err_input` error naming the known tasks when there is no such template.
   subroutine scene_template(task, text, error)
      character(len=*), intent(in) :: task                  !! a task name, e.g. "chart"
      character(len=:), allocatable, intent(out) :: text    !! the scene
      type(error_t), allocatable, intent(out) :: error      !! unknown task
      class(task_t), allocatable :: job
      type(error_t), allocatable :: cause
      type(task_entry_t), allocatable :: entries(:)
      type(group_t), allocatable :: groups(:), alternatives(:)
      character(len=80), allocatable :: notes(:)
      character(len=:), allocatable :: block, note
      integer :: k
      logical :: pendulum
      text = ""
      call new_task(task, job, cause)
      if (allocated(cause)) then
         call set_error(error, err_input, "no template for task '"//task//"' (tasks: "//task_names_text(", ")//")")
         return
      end if
      entries = task_entries()
      do k = 1, size(entries)
         if (entries(k)%name == task) text = header(task, entries(k)%purpose)
      end do
      select type (job)
      class is (pendulum_task_t)
         pendulum = .true.
      class default
         pendulum = .false.
      end select
      if (pendulum) then
         ! epsilon shown commented out: with &physical the damping is kappa
         block = group_block(scene_group(), ["task"], ["'"//task//"'"], ["epsilon"])
      else
         block = group_block(scene_group(), ["task"], ["'"//task//"'"])
      end if
      text = text//block
      groups = job%declarations()
      do k = 1, size(groups)
         block = group_block(groups(k))
         text = text//nl//block
      end do
      call job%template_alternatives(alternatives, notes)
      do k = 1, size(alternatives)
         note = trim(notes(k))
         block = commented_block(alternatives(k))
         text = text//nl//"! "//note//nl//block
      end do
      select type (job)
      class is (pendulum_task_t)
         block = physical_block(job)
         text = text//nl//block
      end select
      if (text(len(text):) == nl) text = text(:len(text) - 1)
   end subroutine scene_template

   !> Comment lines opening a template.
   function header(task, purpose) result(text)
      character(len=*), intent(in) :: task, purpose
      character(len=:), allocatable :: text
      text = wrapped("! ", "hillstab scene, task '"//task//"': "//purpose//".")// &
             "! Run: hillstab FILE.nml. Every variable is shown at its default; delete what you do not change."//nl// &
             "! '!' starts a comment; names and keyword values are case-insensitive; group order does not matter."//nl
   end function header

   !> A group with every variable at its default (or, given in `names`, at `values`); a
   !> variable without a default is shown commented out with its example.
   function group_block(group, names, values, commented) result(text)
      type(group_t), intent(in) :: group
      character(len=*), intent(in), optional :: names(:), values(:)
      !> variables shown commented out at their default (an alternative group replaces them)
      character(len=*), intent(in), optional :: commented(:)
      character(len=:), allocatable :: text, value
      integer :: k, j
      logical :: hidden
      text = group_line(group)
      do k = 1, size(group%variables)
         associate (v => group%variables(k))
            value = v%default
            if (present(names)) then
               do j = 1, size(names)
                  if (trim(names(j)) == v%name) value = trim(values(j))
               end do
            end if
            hidden = .false.
            if (present(commented)) hidden = any(commented == v%name)
            if (hidden) then
               text = text//item("! "//v%name//" = "//value, v%help)
            else if (len(value) == 0 .and. v%required) then
               text = text//item(v%name//" = "//v%example, v%help)
            else if (len(value) == 0) then
               text = text//item("! "//v%name//" = "//v%example, v%help)
            else
               text = text//item(v%name//" = "//value, v%help)
            end if
         end associate
      end do
      text = text//"/"//nl
   end function group_block

   !> A group commented out, every variable at its default or example (but those in `skip`).
   function commented_block(group, skip) result(text)
      type(group_t), intent(in) :: group
      character(len=*), intent(in), optional :: skip(:)  !! variables left out
      character(len=:), allocatable :: text, value
      integer :: k
      text = "! &"//group%name//nl
      do k = 1, size(group%variables)
         associate (v => group%variables(k))
            if (present(skip)) then
               if (any(skip == v%name)) cycle
            end if
            value = v%default
            if (len(value) == 0) value = v%example
            text = text//commented_item(v%name//" = "//value, v%help)
         end associate
      end do
      text = text//"! /"
   end function commented_block

   !> The optional `&physical` group, commented out (a scene gives either it or the
   !> dimensionless values), with instructions that make a valid scene when followed:
   !> remove the '! ' of its lines (and delete what it replaces); its own alternatives
   !> (k and m for omega, the range a_min, a_max, n_a for the list a, r0 alone for the
   !> spring of task boundaries) are '! !' lines inside it.
   function physical_block(task) result(text)
      class(pendulum_task_t), intent(in) :: task
      character(len=:), allocatable :: text, what
      type(group_t) :: group
      integer :: k
      associate (u => task%physical_use)
      group = physical_group()
      if (u%single_amplitude) group = group%with_default("a", "0.05")
      what = ""
      if (u%takes_amplitudes) what = " and delete "//u%amplitudes_replace
      text = "Optional, instead of the dimensionless values: the pendulum in SI units. To use it, delete the "// &
         "first two characters of each line from &physical to /"//what//". The lines that then stay commented "// &
         "are alternatives: k and m instead of omega (uncomment them and delete omega)"
      if (u%takes_amplitudes .and. .not. u%single_amplitude) text = text//"; a_min, a_max, n_a instead "// &
         "of a (uncomment them and delete a)"
      if (u%takes_spring .and. .not. u%takes_amplitudes) text = text//"; r0 alone gives the critical "// &
         "amplitudes of that spring (uncomment it and delete the &chart group)"
      if (u%takes_omega_range) text = text//"; r0 with a_min, a_max, n_a and omega_min, omega_max, n_omega "// &
         "give a chart over (a, omega) (uncomment them, delete omega and the &chart group)"
      text = wrapped("! ", text//".")
      text = text//"! &"//group%name//nl
      do k = 1, size(group%variables)
         associate (v => group%variables(k))
            select case (v%name)
            case ("k", "m")
               text = text//commented_item("! "//v%name//" = "//value_of(v), v%help)
            case ("r0")
               if (u%takes_amplitudes) then
                  text = text//commented_item(v%name//" = "//value_of(v), v%help)
               else if (u%takes_spring .or. u%takes_omega_range) then
                  text = text//commented_item("! "//v%name//" = "//value_of(v), v%help)
               end if
            case ("a")
               if (u%takes_amplitudes) text = text//commented_item(v%name//" = "//value_of(v), v%help)
            case ("a_min", "a_max", "n_a")
               if ((u%takes_amplitudes .and. .not. u%single_amplitude) .or. u%takes_omega_range) &
                  text = text//commented_item("! "//v%name//" = "//value_of(v), v%help)
            case ("omega_min", "omega_max", "n_omega")
               if (u%takes_omega_range) text = text//commented_item("! "//v%name//" = "//value_of(v), v%help)
            case default
               text = text//commented_item(v%name//" = "//value_of(v), v%help)
            end select
         end associate
      end do
      text = text//"! /"
      end associate
   contains
      function value_of(v) result(value)
         type(variable_t), intent(in) :: v
         character(len=:), allocatable :: value
         value = v%default
         if (len(value) == 0) value = v%example
      end function value_of
   end function physical_block

   !> The first line of a group: its name, and its help at the comment column.
   function group_line(group) result(text)
      type(group_t), intent(in) :: group
      character(len=:), allocatable :: text
      text = "&"//group%name
      if (len(group%help) > 0) then
         if (len(text) < comment_column - 1) text = text//repeat(" ", comment_column - 1 - len(text))
         text = text//" ! "//group%help
      end if
      text = text//nl
   end function group_line

   !> `words` after `lead`, wrapped at word boundaries into lines of at most `line_width`
   !> characters, each continuation starting with `lead`; every line ends with a new line.
   function wrapped(lead, words) result(text)
      character(len=*), intent(in) :: lead, words
      character(len=:), allocatable :: text
      character(len=:), allocatable :: rest
      integer :: cut, room
      text = ""
      rest = words
      room = line_width - len(lead)
      do while (len(rest) > room)
         cut = index(rest(:room + 1), " ", back=.true.)
         if (cut <= 1) cut = room + 1
         text = text//lead//rest(:cut - 1)//nl
         rest = trim(adjustl(rest(cut:)))
      end do
      text = text//lead//rest//nl
   end function wrapped

   !> `name = value` followed by its comment at a fixed column, the comment wrapped at
   !> word boundaries onto continuation comment lines so that no line passes `line_width`.
   function item(assignment, comment) result(text)
      character(len=*), intent(in) :: assignment, comment
      character(len=:), allocatable :: text
      character(len=:), allocatable :: line, rest
      integer :: cut, room
      line = "  "//assignment
      if (len(line) < comment_column - 1) line = line//repeat(" ", comment_column - 1 - len(line))
      line = line//" ! "
      text = ""
      rest = comment
      do
         room = line_width - len(line)
         if (len(rest) <= room) exit
         cut = index(rest(:room + 1), " ", back=.true.)
         if (cut <= 1) cut = room + 1
         text = text//line//rest(:cut - 1)//nl
         rest = adjustl(rest(cut:))
         rest = trim(rest)
         line = repeat(" ", comment_column)//"!   "
      end do
      text = text//line//rest//nl
   end function item

   !> `item` commented out: its first column becomes `!`.
   function commented_item(assignment, comment) result(text)
      character(len=*), intent(in) :: assignment, comment
      character(len=:), allocatable :: text
      text = item(assignment, comment)
      text(1:1) = "!"
   end function commented_item
end module hillstab_batch_run_templates

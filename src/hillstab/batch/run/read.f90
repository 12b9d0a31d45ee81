!> Reading a scene: `&scene` (always), `&physical` (optional: the pendulum in SI units, in
!> place of the dimensionless ε and, for points and coefficient, of α and β), then the
!> groups of the task, which the task reads itself (hillstab_batch_tasks_registry makes it
!> from `&scene task`). Group order in the file does not matter; other groups are ignored
!> with a warning naming them (`scene%warnings`), so one file may hold the groups of several
!> tasks, and a misspelt group does not pass in silence; `#` lines before a group are tolerated, which
!> lets a run be repeated from the header of its own output file. Every error names the
!> file, the group and the variable.
!>
!>```fortran
!> type(scene_t) :: scene
!> type(error_t), allocatable :: error
!> call read_scene("data/scenes/default_exact.nml", scene, error)
!>```
module hillstab_batch_run_read
   use hillstab_core_kinds, only: wp, pi
   use hillstab_core_error, only: error_t
   use hillstab_core_text, only: real_text, quoted
   use hillstab_hill_model, only: hill_model_t
   use hillstab_hill_models, only: model_names, new_model
   use hillstab_hill_systems, only: system_kinds, new_system, is_system_name, system_kinds_text
   use hillstab_integrate_system, only: system_method_from_name, system_method_names_text
   use hillstab_hill_coefficient, only: sampling_name, sampling_from_name, sampling_names_text
   use hillstab_hill_units, only: physical_t, physical_epsilon, check_physical, equilibrium_length
   use hillstab_integrate_monodromy, only: method_t, method_table, method_name, method_from_name, method_names_text, &
      method_description
   use hillstab_batch_scene_types, only: scene_t, task_t, add_warning
   use hillstab_batch_scene_physical, only: pendulum_task_t
   use hillstab_batch_scene_group_model, only: read_model_group, model_group_name
   use hillstab_batch_scene_file, only: scene_file_t, open_scene_file, close_scene_file, group_present, group_sets, &
      group_names, fail, read_len
   use hillstab_batch_scene_declaration, only: new_group, group_t, group_values_t, group_reader_t, variable, var_real, &
      var_integer, &
      var_logical, var_name, var_path, var_words, var_real_list, begin_group, next_item, end_group, list_value
   use hillstab_batch_scene_checks, only: require_finite, require_positive_count, max_segments, min_tolerance, &
      max_epsilon, max_points, longest_spring, slowest_omega
   use hillstab_batch_scene_group_chart, only: grid_value
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use hillstab_batch_tasks_registry, only: new_task, task_names, task_names_text
   use hillstab_core_text, only: integer_text, lower_case
   implicit none
   private
   public :: read_scene, scene_group, physical_group

contains

   !> Read and validate the scene in `path`.
   subroutine read_scene(path, scene, error)
      character(len=*), intent(in) :: path       !! scene file
      type(scene_t), intent(out) :: scene        !! the validated scene
      type(error_t), allocatable, intent(out) :: error  !! err_input naming file, group and variable; unallocated on success
      type(scene_file_t) :: file
      class(task_t), allocatable :: task
      character(len=:), allocatable :: task_name
      type(error_t), allocatable :: cause
      scene%source = path
      scene%columns = ""
      scene%warnings = ""
      call open_scene_file(path, file, error)
      if (allocated(error)) return
      call read_scene_group(file, scene, task_name, error)
      if (.not. allocated(error)) call read_model_group(file, scene, error)
      if (.not. allocated(error) .and. .not. allocated(scene%system)) then
         if (.not. scene%model%takes_scene_damping() .and. scene%epsilon > 0.0_wp) &
            call fail(error, path, "scene", "epsilon", "the "//scene%model%name()//" model carries its own "// &
               "damping (&"//scene%model%name()//" damping, in its own units, converted at every point): "// &
               "epsilon must be 0")
      else if (.not. allocated(error)) then
         if (.not. scene%system%takes_scene_damping() .and. scene%epsilon > 0.0_wp) &
            call fail(error, path, "scene", "epsilon", "the "//scene%system%name()//" system carries its own "// &
               "damping (&"//scene%system%name()//" damping, in its own units, converted at every row): "// &
               "epsilon must be 0")
      end if
      if (.not. allocated(error)) then
         call new_task(task_name, task, cause, system=allocated(scene%system))
         if (allocated(cause)) call fail(error, path, "scene", "task", cause%message)
      end if
      if (.not. allocated(error)) then
         select type (task)
         class is (pendulum_task_t)
            allocate (task%physical%amplitudes(0), task%physical%omegas(0))
         end select
      end if
      if (.not. allocated(error) .and. allocated(scene%system)) call check_first_order(path, scene, task_name, error)
      if (.not. allocated(error)) call check_task_settings(file, scene, task, error)
      if (.not. allocated(error)) then
         if (group_present(file%unit, "physical")) then
            if (allocated(scene%system)) then
               call fail(error, path, "physical", "omega", "a system scene (&scene model = 'system') is "// &
                  "dimensionless: its matrices are in &system, and &physical describes the elastic pendulum only")
            else
               select type (task)
               class is (pendulum_task_t)
                  call read_physical_group(file, task, scene, error)
               class default
                  call fail(error, path, "physical", "omega", "task '"//task%name//"' takes its values "// &
                     "dimensionless (its own groups, and the damping as &scene epsilon), not &physical: the "// &
                     "pendulum in SI units is for tasks "//pendulum_task_names())
               end select
            end if
         end if
      end if
      if (.not. allocated(error)) call task%read(file, scene, error)
      if (.not. allocated(error)) then
         call warn_foreign_groups(file, task, scene)
         if (allocated(task%warnings)) then
            if (len(task%warnings) > 0) call add_warning(scene%warnings, task%warnings)
         end if
      end if
      call close_scene_file(file)
      if (.not. allocated(error)) call move_alloc(task, scene%task)
   end subroutine read_scene

   !> A system in first-order form (`&equations state`) runs tasks chart, points and
   !> coefficient: the regions, edges and boundaries need the natural frequencies of M and K.
   subroutine check_first_order(path, scene, task_name, error)
      character(len=*), intent(in) :: path       !! scene file
      type(scene_t), intent(in) :: scene         !! the scene read so far
      character(len=*), intent(in) :: task_name  !! `&scene task`
      type(error_t), allocatable, intent(inout) :: error  !! err_input naming file, group and variable
      if (.not. scene%system%first_order()) return
      select case (task_name)
      case ("chart", "points", "coefficient")
      case default
         call fail(error, path, "scene", "task", "task '"//task_name//"' does not run on a system in "// &
            "first-order form (&equations state): it takes chart, points and coefficient (regions, edges and "// &
            "boundaries need the natural frequencies of a second-order form M x'' + C x' + K(t) x = 0)")
         return
      end select
   end subroutine check_first_order

   !> A warning for each group of the file that the task does not read (another task's
   !> group, or a misspelt name whose values would otherwise be ignored in silence), saying
   !> which groups it reads and which tasks read the stray one. Not an error: one file may
   !> hold the groups of several tasks, `&scene task` choosing among them.
   subroutine warn_foreign_groups(file, task, scene)
      type(scene_file_t), intent(in) :: file
      class(task_t), intent(in) :: task
      type(scene_t), intent(inout) :: scene
      character(len=63), allocatable :: names(:)
      character(len=:), allocatable :: reads, readers, tasks(:)
      class(task_t), allocatable :: other
      class(hill_model_t), allocatable :: other_model
      type(error_t), allocatable :: cause
      type(group_t), allocatable :: groups(:)
      integer :: k, j, n
      names = group_names(file%unit)
      reads = "&scene"
      select type (task)
      class is (pendulum_task_t)
         if (task%physical%given) reads = reads//", &physical"
      end select
      ! a local, not an associate name: gfortran does not free the function result's
      ! allocatable components through an associate name
      groups = task%declarations()
      do j = 1, size(groups)
         reads = reads//", &"//groups(j)%name
      end do
      tasks = task_names()
      do k = 1, size(names)
         if (task_reads(task, trim(names(k)))) cycle
         if (trim(names(k)) == model_group_name(scene)) cycle
         call new_model(trim(names(k)), other_model, cause)
         if (.not. allocated(cause) .and. allocated(scene%model)) then
            call add_warning(scene%warnings, file%path//": &"//trim(names(k))//": ignored: the group of model '"// &
               trim(names(k))//"', and &scene model is '"//scene%model%name()//"'")
            cycle
         end if
         readers = ""
         n = 0
         do j = 1, size(tasks)
            call new_task(trim(tasks(j)), other, cause)
            if (allocated(cause)) cycle
            if (.not. task_reads(other, trim(names(k)))) cycle
            n = n + 1
            if (n > 1) readers = readers//", "
            readers = readers//trim(tasks(j))
         end do
         if (n == 0) then
            readers = "no task reads a group of that name (misspelt?)"
         else if (n == 1) then
            readers = "task "//readers//" reads it"
         else
            readers = "tasks "//readers//" read it"
         end if
         call add_warning(scene%warnings, file%path//": &"//trim(names(k))//": ignored: task '"//task%name// &
            "' reads "//reads//"; "//readers)
      end do
   end subroutine warn_foreign_groups

   !> The tasks that take `&physical` (the registry's pendulum tasks), for messages: "chart,
   !> points, …".
   function pendulum_task_names() result(text)
      character(len=:), allocatable :: text
      character(len=:), allocatable :: tasks(:)
      class(task_t), allocatable :: task
      type(error_t), allocatable :: cause
      integer :: j
      text = ""
      tasks = task_names()
      do j = 1, size(tasks)
         call new_task(trim(tasks(j)), task, cause)
         if (allocated(cause)) cycle
         select type (task)
         class is (pendulum_task_t)
            if (len(text) > 0) text = text//", "
            text = text//trim(tasks(j))
         end select
      end do
   end function pendulum_task_names

   !> Whether the task reads a group of this name: &scene, &physical (read, or refused with
   !> an error, before this is asked), its own groups and the alternatives its template shows.
   logical function task_reads(task, name)
      class(task_t), intent(in) :: task
      character(len=*), intent(in) :: name
      type(group_t), allocatable :: declared(:), alternatives(:)
      character(len=80), allocatable :: notes(:)
      integer :: j
      task_reads = name == "scene" .or. name == "physical"
      if (task_reads) return
      declared = task%declarations()
      call task%template_alternatives(alternatives, notes)
      do j = 1, size(declared)
         if (declared(j)%name == name) task_reads = .true.
      end do
      do j = 1, size(alternatives)
         if (alternatives(j)%name == name) task_reads = .true.
      end do
   end function task_reads

   !> The declaration of `&scene`.
   function scene_group() result(group)
      type(group_t) :: group
      group = new_group("scene", "what to compute and how")
      call group%add("task", var_name, "'chart'", task_names_text(" | "))
      call group%add("model", var_name, "'"//trim(model_names(1))//"'", model_choices())
      call group%add("method", var_name, "'"//method_name(0)//"'", method_choices())
      call group%add("n_segments", var_integer, "2", "method segments (and Qseg of task coefficient): pieces per "// &
         ""// &
         "period, at least 1")
      call group%add("sampling", var_name, "'endpoint'", "segments: endpoint (eq. (28)) | midpoint | average (exact "// &
         ""// &
         "mean of Q per piece)")
      call group%add("tolerance", var_real, "1.0e-10", "exact methods: target error on S, scaled by max(1, |S|); > "// &
         ""// &
         "0")
      call group%add("epsilon", var_real, "0.0", "damping eps = kappa pi/omega of eqs. (46)-(47); >= 0 (with &physical: "// &
         "kappa instead)")
      call group%add("output", var_path, "", "prefix: files are <output>_<task>.dat, relative to the current "// &
         "directory; default: the scene file's name without directory and extension", example="'run1'")
      call group%add("columns", var_words, "''", "chart, points: columns to write, e.g. 'alpha beta stable mu'; '' "// &
         ""// &
         "= all (see the # columns: line)")
      call group%add("format", var_name, "'text'", "chart, points: text | binary (float64 records after the # "// &
         "header, <output>_<task>.bin; the header gives the gnuplot and numpy commands)")
      call group%add("names_line", var_logical, ".false.", "text: .true. adds an uncommented line of column names "// &
         ""// &
         "after the # header, for gnuplot using 'alpha':'mu'")
   end function scene_group

   !> The declaration of `&physical` (no defaults for omega, k, m, r0 and the amplitudes:
   !> omega or k with m is required, r0 goes with the amplitudes, which are the list a or the
   !> range a_min, a_max, n_a).
   function physical_group() result(group)
      type(group_t) :: group
      group = new_group("physical", "the pendulum in SI units, instead of the dimensionless values")
      call group%add("omega", var_real, "", "radial angular frequency sqrt(k/m), rad/s; > 0 (or k and m instead)", &
         example="10.0")
      call group%add("k", var_real, "", "spring constant, N/m; > 0 (with m, instead of omega: omega = sqrt(k/m))", &
         example="25.0")
      call group%add("m", var_real, "", "mass, kg; > 0 (with k)", example="0.25")
      call group%add("g", var_real, "9.80665", "gravity, m/s^2; >= 0")
      call group%add("kappa", var_real, "0.0", "damping rate of eqs. (40)-(42), 1/s: gives epsilon = kappa "// &
         "pi/omega")
      call group%add("r0", var_real, "", "natural length of the spring, m; > 0 (with a or a_min, a_max, n_a)", &
         example="0.3")
      call group%add("a", var_real_list, "", "bounce amplitudes, m, up to 64; 0 <= a < rho = r0 + g/omega^2", &
         example="0.05, 0.1, 0.2", max_count=64)
      call group%add("a_min", var_real, "", "first amplitude of a range, m (with a_max, n_a; instead of a)", &
         example="0.0")
      call group%add("a_max", var_real, "", "last amplitude of the range, m; < rho", example="0.3")
      call group%add("n_a", var_integer, "", "amplitudes from a_min to a_max inclusive (1: a_min only)", &
         example="31")
      call group%add("omega_min", var_real, "", "chart over (a, omega): first omega, rad/s (with omega_max, "// &
         "n_omega, r0 and the amplitudes; instead of omega)", example="5.0")
      call group%add("omega_max", var_real, "", "last omega, rad/s", example="20.0")
      call group%add("n_omega", var_integer, "", "omega values from omega_min to omega_max inclusive", &
         example="151")
   end function physical_group

   !> `&scene`: task, model, method and its settings, damping, output prefix, columns, format.
   subroutine read_scene_group(file, this, task_name, error)
      type(scene_file_t), intent(in) :: file
      type(scene_t), intent(inout) :: this
      character(len=:), allocatable, intent(out) :: task_name
      type(error_t), allocatable, intent(out) :: error
      type(group_t) :: group
      character(len=read_len) :: task, model, method, sampling, output, columns, format
      integer :: n_segments
      real(wp) :: tolerance, epsilon
      logical :: names_line
      type(error_t), allocatable :: model_error
      namelist /scene/ task, model, method, n_segments, sampling, tolerance, epsilon, output, columns, format, &
         names_line
      type(group_reader_t) :: reader
      group = scene_group()
      call begin_group(reader, file, group)
      read (reader%defaults, nml=scene, iostat=reader%defaults_status, iomsg=reader%defaults_msg)
      if (reader%from_file) read (file%unit, nml=scene, iostat=reader%ios, iomsg=reader%msg)
      do while (next_item(reader, file, group))
         read (reader%record, nml=scene, iostat=reader%stat, iomsg=reader%message)
      end do
      write (reader%echo, nml=scene, delim="apostrophe", iostat=reader%echo_status)
      call end_group(reader, file, group, this%settings, error)
      if (allocated(error)) return
      task_name = lower_case(trim(task))

      if (is_system_name(model)) then
         call new_system(model, this%system, model_error)
         this%method%kind = system_method_from_name(trim(method))
         if (this%method%kind < 0) then
            call fail(error, file%path, group%name, "method", "a system (model = '"//lower_case(trim(model))// &
               "') takes method "//system_method_names_text()//", got '"//trim(method)//"'")
            return
         end if
      else
         call new_model(trim(model), this%model, model_error)
         if (allocated(model_error)) then
            call fail(error, file%path, group%name, "model", model_error%message//" ("// &
               system_kinds_text("or ", "; ", quote=.true.)//")")
            return
         end if
         this%method%kind = method_from_name(trim(method))
      end if
      if (this%method%kind < 0) then
         call fail(error, file%path, group%name, "method", "unknown method '"//trim(method)// &
            "' (expected "//method_names_text()//")")
         return
      end if

      this%method%sampling = sampling_from_name(trim(sampling))
      if (this%method%sampling < 0) then
         call fail(error, file%path, group%name, "sampling", "unknown sampling '"//trim(sampling)// &
            "' (expected "//sampling_names_text()//")")
         return
      end if

      call require_positive_count(file%path, group%name, "n_segments", n_segments, 1, error)
      if (allocated(error)) return
      if (n_segments > max_segments) then
         call fail(error, file%path, group%name, "n_segments", "must be <= "//integer_text(max_segments)// &
            " (the work of one point), got "//integer_text(n_segments))
         return
      end if
      this%method%n_segments = n_segments

      call require_finite(file%path, group%name, "tolerance", tolerance, error)
      if (allocated(error)) return
      if (.not. (tolerance >= min_tolerance .and. tolerance < 1.0_wp)) then
         call fail(error, file%path, group%name, "tolerance", "must be >= "//real_text(min_tolerance)// &
            " (the smallest error double precision can be asked for) and < 1, got "//real_text(tolerance))
         return
      end if
      this%method%tolerance = tolerance

      call require_finite(file%path, group%name, "epsilon", epsilon, error)
      if (allocated(error)) return
      if (epsilon < 0.0_wp .or. epsilon > max_epsilon) then
         call fail(error, file%path, group%name, "epsilon", "damping must be >= 0 and <= "//real_text(max_epsilon)// &
            " (exp(epsilon) must stay far from overflow), got "//real_text(epsilon))
         return
      end if
      this%epsilon = epsilon

      if (this%settings%given("output")) then
         if (len_trim(output) == 0) then
            call fail(error, file%path, group%name, "output", "the output prefix is empty")
            return
         end if
         this%output = trim(output)
      else
         this%output = default_output(file%path)
         call this%settings%set("output", quoted(this%output))
      end if

      select case (lower_case(trim(format)))
      case ("text"); this%binary = .false.
      case ("binary"); this%binary = .true.
      case default
         call fail(error, file%path, group%name, "format", "unknown format '"//trim(format)// &
            "' (expected text or binary)")
         return
      end select
      this%columns = trim(adjustl(columns))
      this%names_line = names_line
      if (this%binary .and. this%names_line) then
         call fail(error, file%path, group%name, "names_line", "a line of column names is for format = 'text' only")
         return
      end if
      ! the effective scene names the choices as they were understood
      call this%settings%set("task", quoted(task_name))
      if (allocated(this%system)) then
         call this%settings%set("model", quoted(this%system%name()))
      else
         call this%settings%set("model", quoted(this%model%name()))
      end if
      call this%settings%set("method", quoted(method_name(this%method%kind)))
      call this%settings%set("sampling", quoted(sampling_name(this%method%sampling)))
      call this%settings%set("columns", quoted(this%columns))
      call this%settings%set("format", quoted(trim(merge("binary", "text  ", this%binary))))
   end subroutine read_scene_group

   !> The models for a template's comment: "elastic: Q = ... | mathieu: Q = ...".
   function model_choices() result(text)
      character(len=:), allocatable :: text
      class(hill_model_t), allocatable :: model
      type(error_t), allocatable :: error
      integer :: k
      text = ""
      do k = 1, size(model_names)
         call new_model(model_names(k), model, error)
         if (k > 1) text = text//" | "
         text = text//model%name()//": "//model%summary()
      end do
      do k = 1, size(system_kinds)
         text = text//" | "//trim(system_kinds(k)%choice)
      end do
   end function model_choices

   !> The methods for a template's comment: "auto (…) | formula (…) | …".
   function method_choices() result(text)
      character(len=:), allocatable :: text
      integer :: k
      text = ""
      do k = lbound(method_table, 1), ubound(method_table, 1)
         if (k > lbound(method_table, 1)) text = text//" | "
         text = text//method_name(k)//" ("//method_description(k)//")"
      end do
   end function method_choices

   !> What `&scene` asks of the task that only some tasks offer.
   subroutine check_task_settings(file, scene, task, error)
      type(scene_file_t), intent(in) :: file
      type(scene_t), intent(in) :: scene
      class(task_t), intent(in) :: task
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: variable
      if (task%takes_columns) return
      if (scene%binary) then
         variable = "format"
      else if (len(scene%columns) > 0) then
         variable = "columns"
      else if (scene%names_line) then
         variable = "names_line"
      else
         return
      end if
      call fail(error, file%path, "scene", variable, "columns, format = 'binary' and names_line apply to tasks "// &
         "chart and points (task '"//task%name//"' writes every column of its file as text, named on the "// &
         "'# columns:' line)")
   end subroutine check_task_settings

   !> The default output prefix: the scene file's base name without extension.
   pure function default_output(path) result(output)
      character(len=*), intent(in) :: path
      character(len=:), allocatable :: output
      integer :: slash, dot
      slash = index(path, "/", back=.true.)
      dot = index(path(slash + 1:), ".", back=.true.)
      if (dot > 1) then
         output = path(slash + 1:slash + dot - 1)
      else
         output = path(slash + 1:)
      end if
      if (len(output) == 0) output = "hillstab"
   end function default_output

   !> `&physical`: the pendulum in SI units (eqs. (4), (15), (24), (46)). Gives ε (from κ)
   !> and ω (given, or √(k/m); rates per second); with amplitudes (the list `a` or the range
   !> `a_min`, `a_max`, `n_a`) and `r0`, also the α and β of a points or coefficient task.
   !> Mixing it with the dimensionless values, or two forms of one value, is an error naming
   !> both.
   subroutine read_physical_group(file, task, scene, error)
      type(scene_file_t), intent(in) :: file
      class(pendulum_task_t), intent(inout) :: task  !! receives the group (`physical`)
      type(scene_t), intent(inout) :: scene  !! its ε from κ
      type(error_t), allocatable, intent(out) :: error
      type(group_t) :: group
      real(wp) :: omega, k, m, g, kappa, r0, a(64), a_min, a_max, omega_min, omega_max
      integer :: n_a, n_omega
      namelist /physical/ omega, k, m, g, kappa, r0, a, a_min, a_max, n_a, omega_min, omega_max, n_omega
      type(group_reader_t) :: reader
      real(wp), allocatable :: amplitudes(:)
      character(len=:), allocatable :: variable
      type(physical_t) :: p
      type(error_t), allocatable :: cause
      integer :: j, n_range
      logical :: spring, ranged, omega_ranged, reaches
      real(wp), allocatable :: omegas(:)
      group = physical_group()
      call begin_group(reader, file, group)
      read (reader%defaults, nml=physical, iostat=reader%defaults_status, iomsg=reader%defaults_msg)
      if (reader%from_file) read (file%unit, nml=physical, iostat=reader%ios, iomsg=reader%msg)
      do while (next_item(reader, file, group))
         read (reader%record, nml=physical, iostat=reader%stat, iomsg=reader%message)
      end do
      write (reader%echo, nml=physical, delim="apostrophe", iostat=reader%echo_status)
      call end_group(reader, file, group, task%physical%values, error)
      if (allocated(error)) return
      associate (values => task%physical%values)
         spring = values%given("k") .or. values%given("m")
         omega_ranged = values%given("omega_min") .or. values%given("omega_max") .or. values%given("n_omega")
         allocate (omegas(0))
         if (omega_ranged) then
            if (values%given("omega") .or. spring) then
               call fail(error, file%path, group%name, "omega_min", "give omega (or k and m) or the range "// &
                  "omega_min, omega_max, n_omega, not both")
               return
            end if
            do j = 1, 3
               variable = trim(omega_range_names(j))
               if (.not. values%given(variable)) then
                  call fail(error, file%path, group%name, variable, "omega_min, omega_max and n_omega go "// &
                     "together (a chart over (a, omega))")
                  return
               end if
            end do
            if (.not. task%physical_use%takes_omega_range) then
               call fail(error, file%path, group%name, "n_omega", "a range of omega makes a chart over (a, "// &
                  "omega): task 'chart', not '"//task%name//"'")
               return
            end if
            call require_finite(file%path, group%name, "omega_min", omega_min, error)
            if (.not. allocated(error)) call require_finite(file%path, group%name, "omega_max", omega_max, error)
            if (allocated(error)) return
            if (.not. omega_min > 0.0_wp) then
               call fail(error, file%path, group%name, "omega_min", "must be > 0 (rad/s), got "//real_text(omega_min))
               return
            end if
            if (omega_max < omega_min) then
               call fail(error, file%path, group%name, "omega_max", "must be >= omega_min = "//real_text(omega_min)// &
                  ", got "//real_text(omega_max))
               return
            end if
            call require_positive_count(file%path, group%name, "n_omega", n_omega, 1, error)
            if (allocated(error)) return
            if (n_omega > max_points) then
               call fail(error, file%path, group%name, "n_omega", "must be <= "//integer_text(max_points)// &
                  ", got "//integer_text(n_omega))
               return
            end if
            deallocate (omegas)
            allocate (omegas(n_omega))
            do j = 1, n_omega
               omegas(j) = grid_value(omega_min, omega_max, n_omega, j)
            end do
            ! the pendulum is checked at the largest omega (the smallest rho) below
            omega = omega_max
         end if
         if (values%given("omega") .and. spring) then
            call fail(error, file%path, group%name, merge("k", "m", values%given("k")), "omega and "// &
               merge("k", "m", values%given("k"))//" are both given: give the radial angular frequency either as "// &
               "omega or as k and m (omega = sqrt(k/m)), not both")
            return
         end if
         if (.not. (values%given("omega") .or. spring .or. omega_ranged)) then
            call fail(error, file%path, group%name, "omega", "the radial angular frequency is required: omega = "// &
               "sqrt(k/m) (rad/s), or the spring constant k (N/m) and the mass m (kg)")
            return
         end if
         if (spring) then
            if (.not. (values%given("k") .and. values%given("m"))) then
               call fail(error, file%path, group%name, merge("m", "k", values%given("k")), "k (spring constant, "// &
                  "N/m) and m (mass, kg) go together: omega = sqrt(k/m)")
               return
            end if
            call require_finite(file%path, group%name, "k", k, error)
            if (.not. allocated(error)) call require_finite(file%path, group%name, "m", m, error)
            if (allocated(error)) return
            if (.not. k > 0.0_wp) then
               call fail(error, file%path, group%name, "k", "the spring constant must be > 0 (N/m), got "// &
                  real_text(k))
               return
            end if
            if (.not. m > 0.0_wp) then
               call fail(error, file%path, group%name, "m", "the mass must be > 0 (kg), got "//real_text(m))
               return
            end if
            ! k/m itself may overflow (a trap in debug builds): compared through logarithms first
            if (log(k) - log(m) < log(huge(1.0_wp)) .and. log(k) - log(m) > log(tiny(1.0_wp))) then
               omega = sqrt(k/m)
            else
               omega = 0.0_wp
            end if
            if (.not. ieee_is_finite(omega) .or. omega <= 0.0_wp) then
               call fail(error, file%path, group%name, "k", "omega = sqrt(k/m) must be a finite number > 0, got k "// &
                  "= "//real_text(k)//", m = "//real_text(m))
               return
            end if
            task%physical%k = k
            task%physical%m = m
         end if
         if (group_sets(file%unit, "scene", "epsilon")) then
            call fail(error, file%path, group%name, "kappa", "give the damping either as &scene epsilon "// &
               "(dimensionless) or as &physical kappa (1/s), not both")
            return
         end if
         ranged = values%given("a_min") .or. values%given("a_max") .or. values%given("n_a")
         if (ranged .and. values%given("a")) then
            call fail(error, file%path, group%name, first_given(values, ["a_min", "a_max", "n_a  "]), "give the "// &
               "amplitudes either as the list a or as the range a_min, a_max, n_a, not both")
            return
         end if
         if (ranged) then
            do j = 1, 3
               variable = trim(range_names(j))
               if (.not. values%given(variable)) then
                  call fail(error, file%path, group%name, variable, "a_min, a_max and n_a go together (the "// &
                     "amplitudes from a_min to a_max inclusive)")
                  return
               end if
            end do
            call require_finite(file%path, group%name, "a_min", a_min, error)
            if (.not. allocated(error)) call require_finite(file%path, group%name, "a_max", a_max, error)
            if (allocated(error)) return
            if (a_max < a_min) then
               call fail(error, file%path, group%name, "a_max", "must be >= a_min = "//real_text(a_min)// &
                  ", got "//real_text(a_max))
               return
            end if
            call require_positive_count(file%path, group%name, "n_a", n_a, 1, error)
            if (allocated(error)) return
            if (n_a > max_points) then
               call fail(error, file%path, group%name, "n_a", "must be <= "//integer_text(max_points)// &
                  " (the most points of task points), got "//integer_text(n_a))
               return
            end if
            allocate (amplitudes(n_a))
            do j = 1, n_a
               amplitudes(j) = grid_value(a_min, a_max, n_a, j)
            end do
         else
            amplitudes = list_value(values, "a", a)
         end if
         if (size(amplitudes) > 0 .and. .not. values%given("r0")) then
            call fail(error, file%path, group%name, "r0", "the amplitudes (a, or a_min, a_max, n_a; m) need r0, "// &
               "the natural length of the spring (m)")
            return
         end if
         if (omega_ranged .and. size(amplitudes) == 0) then
            call fail(error, file%path, group%name, "a_min", "a chart over (a, omega) needs the amplitudes: "// &
               "a_min, a_max, n_a (or the list a) with r0")
            return
         end if
         if (values%given("r0") .and. size(amplitudes) == 0 .and. .not. task%physical_use%takes_spring) then
            call fail(error, file%path, group%name, "r0", "r0 fixes beta = g pi^2/(rho omega^2), rho = r0 + "// &
               "g/omega^2: task '"//task%name//"' takes it only with amplitudes (a, or a_min, a_max, n_a)")
            return
         end if
         p = physical_t(g=g, omega=omega, a=0.0_wp, kappa=kappa)
         if (values%given("r0")) p%r0 = r0
         n_range = size(amplitudes)
         do j = 1, max(n_range, 1)
            ! a range is checked at its ends (the values between lie between them)
            if (ranged .and. j > 1 .and. j < n_range) cycle
            if (n_range > 0) p%a = amplitudes(j)
            call check_physical(p, cause, variable)
            if (allocated(cause)) then
               reaches = variable == "a" .and. p%a >= 0.0_wp
               if (variable == "a" .and. ranged) variable = merge("a_min", "a_max", j == 1)
            if (reaches .and. omega_ranged) then
               call fail(error, file%path, group%name, variable, "a = "//real_text(p%a)//" m reaches the pivot at "// &
                  "omega_max = "//real_text(omega_max)//" rad/s: a chart over (a, omega) must stay inside 0 <= a "// &
                  "< rho(omega) = r0 + g/omega^2 everywhere, and the largest valid a is rho(omega_max) = "// &
                  real_text(equilibrium_length(p))//" m (lower a_max or omega_max)")
               return
            end if
            if (variable == "omega" .and. omega_ranged) variable = "omega_max"
               if (variable == "omega" .and. spring) variable = "k"
               call fail(error, file%path, group%name, variable, cause%message//"; got r0 = "//real_text(p%r0)// &
                  ", g = "//real_text(p%g)//", omega = "//real_text(p%omega)//", a = "//real_text(p%a)// &
                  ", kappa = "//real_text(p%kappa))
               return
            end if
         end do
         if (size(amplitudes) > 0 .and. .not. (task%physical_use%takes_amplitudes .or. omega_ranged)) then
            call fail(error, file%path, group%name, trim(merge("n_a", "a  ", ranged)), "task '"//task%name// &
               "' takes no amplitudes (a chart runs over the grid of &chart; task boundaries finds the critical "// &
               "amplitudes itself); amplitudes with r0 make the points of task 'points' or the curves of task "// &
               "'coefficient'")
            return
         end if
      end associate
      task%physical%given = .true.
      task%physical%r0_given = task%physical%values%given("r0")
      call warn_implausible(file, group, scene, p, spring, omega_ranged, omegas, task%physical%r0_given)
      task%physical%pendulum = p
      task%physical%pendulum%a = 0.0_wp
      task%physical%amplitudes = amplitudes
      task%physical%omegas = omegas
      if (size(omegas) > 0) task%physical%pendulum%omega = omegas(1)
      scene%epsilon = physical_epsilon(task%physical%pendulum)
      ! with &physical the damping is kappa; epsilon in &scene would be an error
      call scene%settings%hide("epsilon")
   end subroutine read_physical_group

   !> Warnings for a valid `&physical` that is most likely in the wrong units: a spring longer
   !> than 100 m (r0, or the loaded length ρ = r0 + g/ω² at the smallest ω), an ω below 1e-3
   !> rad/s (a radial period of 105 minutes).
   subroutine warn_implausible(file, group, scene, p, spring, omega_ranged, omegas, r0_given)
      type(scene_file_t), intent(in) :: file
      type(group_t), intent(in) :: group
      type(scene_t), intent(inout) :: scene
      type(physical_t), intent(in) :: p  !! the pendulum (at the largest ω of a range)
      logical, intent(in) :: spring, omega_ranged  !! ω given as k and m; as a range
      real(wp), intent(in) :: omegas(:)  !! the range of ω (empty when one ω)
      logical, intent(in) :: r0_given  !! the group gives r0
      type(physical_t) :: slowest
      character(len=:), allocatable :: omega_name, hint
      slowest = p
      if (omega_ranged) slowest%omega = omegas(1)
      omega_name = "omega"
      if (omega_ranged) omega_name = "omega_min"
      if (spring) omega_name = "k"
      if (r0_given) then
         if (equilibrium_length(slowest) > longest_spring) then
            hint = "(k in N/m, m in kg?)"
            if (p%r0 > longest_spring) then
               omega_name = "r0"
               hint = "(lengths are in metres: 25 cm is r0 = 0.25)"
            end if
            call add_warning(scene%warnings, file%path//": &"//group%name//": "//omega_name//": a spring longer than "// &
               real_text(longest_spring)//" m: r0 = "//real_text(p%r0)//" m, rho = r0 + g/omega^2 = "// &
               real_text(equilibrium_length(slowest))//" m at omega = "//real_text(slowest%omega)//" rad/s "//hint)
         end if
      end if
      if (slowest%omega < slowest_omega) then
         omega_name = "omega"
         if (omega_ranged) omega_name = "omega_min"
         if (spring) omega_name = "k"
         call add_warning(scene%warnings, file%path//": &"//group%name//": "//omega_name//": omega = "// &
            real_text(slowest%omega)//" rad/s is below "//real_text(slowest_omega)//" rad/s, a radial period of "// &
            real_text(2.0_wp*pi/slowest%omega/60.0_wp)//" minutes (k in N/m, m in kg?)")
      end if
   end subroutine warn_implausible

   !> The first of `names` the group gives.
   function first_given(values, names) result(name)
      type(group_values_t), intent(in) :: values
      character(len=*), intent(in) :: names(:)
      character(len=:), allocatable :: name
      integer :: j
      name = trim(names(1))
      do j = size(names), 1, -1
         if (values%given(trim(names(j)))) name = trim(names(j))
      end do
   end function first_given

   !> The variables of an omega range.
   pure function omega_range_names(j) result(name)
      integer, intent(in) :: j
      character(len=9) :: name
      character(len=9), parameter :: names(3) = ["omega_min", "omega_max", "n_omega  "]
      name = names(j)
   end function omega_range_names

   !> The variables of an amplitude range.
   pure function range_names(j) result(name)
      integer, intent(in) :: j
      character(len=5) :: name
      character(len=5), parameter :: names(3) = ["a_min", "a_max", "n_a  "]
      name = names(j)
   end function range_names
end module hillstab_batch_run_read

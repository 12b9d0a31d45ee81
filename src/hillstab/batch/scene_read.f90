!> Reading a scene: `&scene` (always), `&physical` (optional: the pendulum in SI units, in
!> place of the dimensionless ε and, for points and coefficient, of α and β), then the
!> groups of the task, which the task reads itself (hillstab_batch_task_registry makes it
!> from `&scene task`). Group order in the file does not matter and other groups are
!> ignored, so one file may hold several; `#` lines before a group are tolerated, which
!> lets a run be repeated from the header of its own output file. Every error names the
!> file, the group and the variable.
!>
!>```fortran
!> type(scene_t) :: scene
!> type(error_t), allocatable :: error
!> call read_scene("data/scenes/default_exact.nml", scene, error)
!>```
module hillstab_batch_scene_read
   use hillstab_core_kinds, only: wp
   use hillstab_core_error, only: error_t
   use hillstab_core_text, only: real_text, quoted
   use hillstab_hill_models, only: model_table, model_name, model_from_name, model_names_text, model_summary
   use hillstab_hill_coefficient, only: sampling_name, sampling_from_name, sampling_names_text
   use hillstab_hill_units, only: physical_t, physical_epsilon, check_physical
   use hillstab_integrate_monodromy, only: method_t, method_table, method_name, method_from_name, method_names_text, &
      method_description
   use hillstab_batch_scene, only: scene_t, task_t
   use hillstab_batch_scene_file, only: scene_file_t, open_scene_file, close_scene_file, group_present, group_sets, &
      fail, read_len
   use hillstab_batch_declaration, only: new_group, group_t, group_values_t, group_reader_t, variable, var_real, var_integer, &
      var_logical, var_name, var_path, var_words, var_real_list, begin_group, next_item, end_group, list_value
   use hillstab_batch_scene_checks, only: require_finite, require_positive_count, max_segments, min_tolerance, &
      max_epsilon
   use hillstab_batch_task_registry, only: new_task, task_names_text
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
      allocate (scene%amplitudes(0))
      call open_scene_file(path, file, error)
      if (allocated(error)) return
      call read_scene_group(file, scene, task_name, error)
      if (.not. allocated(error)) then
         call new_task(task_name, task, cause)
         if (allocated(cause)) call fail(error, path, "scene", "task", cause%message)
      end if
      if (.not. allocated(error)) call check_task_settings(file, scene, task, error)
      if (.not. allocated(error)) then
         if (group_present(file%unit, "physical")) call read_physical_group(file, task, scene, error)
      end if
      if (.not. allocated(error)) call task%read(file, scene, error)
      call close_scene_file(file)
      if (.not. allocated(error)) call move_alloc(task, scene%task)
   end subroutine read_scene

   !> The declaration of `&scene`.
   function scene_group() result(group)
      type(group_t) :: group
      group = new_group("scene", "what to compute and how")
      call group%add("task", var_name, "'chart'", task_names_text(" | "))
      call group%add("model", var_name, "'"//model_name(1)//"'", model_choices())
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
      call group%add("epsilon", var_real, "0.0", "damping eps = kappa pi/omega of eqs. (46)-(47); >= 0")
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

   !> The declaration of `&physical` (omega and r0 have no default: omega is required, r0
   !> goes with a).
   function physical_group() result(group)
      type(group_t) :: group
      group = new_group("physical", "the pendulum in SI units, instead of the dimensionless values")
      call group%add("omega", var_real, "", "required: radial angular frequency sqrt(k/m), rad/s; > 0", &
         example="10.0", required=.true.)
      call group%add("g", var_real, "9.80665", "gravity, m/s^2; >= 0")
      call group%add("kappa", var_real, "0.0", "damping rate of eqs. (40)-(42), 1/s: gives epsilon = kappa "// &
         "pi/omega")
      call group%add("r0", var_real, "", "natural length of the spring, m; > 0 (with a)", example="0.3")
      call group%add("a", var_real_list, "", "bounce amplitudes, m, up to 64; 0 <= a < rho = r0 + g/omega^2", &
         example="0.05, 0.1, 0.2", max_count=64)
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

      this%model = model_from_name(trim(model))
      if (this%model < 0) then
         call fail(error, file%path, group%name, "model", "unknown model '"//trim(model)// &
            "' (expected "//model_names_text()//")")
         return
      end if

      this%method%kind = method_from_name(trim(method))
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
      call this%settings%set("model", quoted(model_name(this%model)))
      call this%settings%set("method", quoted(method_name(this%method%kind)))
      call this%settings%set("sampling", quoted(sampling_name(this%method%sampling)))
      call this%settings%set("columns", quoted(this%columns))
      call this%settings%set("format", quoted(trim(merge("binary", "text  ", this%binary))))
   end subroutine read_scene_group

   !> The models for a template's comment: "elastic: Q = ... | mathieu: Q = ...".
   function model_choices() result(text)
      character(len=:), allocatable :: text
      integer :: k
      text = ""
      do k = 1, size(model_table)
         if (k > 1) text = text//" | "
         text = text//model_name(k)//": "//model_summary(k)
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
      if (.not. task%takes_columns .and. (scene%binary .or. len(scene%columns) > 0)) then
         call fail(error, file%path, "scene", trim(merge("format ", "columns", scene%binary)), &
            "columns and format = 'binary' apply to tasks chart and points")
      end if
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
   !> and ω (rates per second); with `a` and `r0`, also the α and β of a points or
   !> coefficient task. Mixing it with the dimensionless values is an error naming both.
   subroutine read_physical_group(file, task, scene, error)
      type(scene_file_t), intent(in) :: file
      class(task_t), intent(in) :: task
      type(scene_t), intent(inout) :: scene
      type(error_t), allocatable, intent(out) :: error
      type(group_t) :: group
      real(wp) :: omega, g, kappa, r0, a(64)
      namelist /physical/ omega, g, kappa, r0, a
      type(group_reader_t) :: reader
      real(wp), allocatable :: amplitudes(:)
      character(len=:), allocatable :: variable
      type(physical_t) :: p
      type(error_t), allocatable :: cause
      integer :: k
      group = physical_group()
      call begin_group(reader, file, group)
      read (reader%defaults, nml=physical, iostat=reader%defaults_status, iomsg=reader%defaults_msg)
      if (reader%from_file) read (file%unit, nml=physical, iostat=reader%ios, iomsg=reader%msg)
      do while (next_item(reader, file, group))
         read (reader%record, nml=physical, iostat=reader%stat, iomsg=reader%message)
      end do
      write (reader%echo, nml=physical, delim="apostrophe", iostat=reader%echo_status)
      call end_group(reader, file, group, scene%physical_values, error)
      if (allocated(error)) return
      associate (values => scene%physical_values)
         if (.not. values%given("omega")) then
            call fail(error, file%path, group%name, "omega", "the radial angular frequency omega = sqrt(k/m) "// &
               "(rad/s) is required")
            return
         end if
         if (group_sets(file%unit, "scene", "epsilon")) then
            call fail(error, file%path, group%name, "kappa", "give the damping either as &scene epsilon "// &
               "(dimensionless) or as &physical kappa (1/s), not both")
            return
         end if
         amplitudes = list_value(values, "a", a)
         if (values%given("a") .neqv. values%given("r0")) then
            call fail(error, file%path, group%name, merge("r0", "a ", values%given("a")), &
               "a (amplitudes, m) and r0 (natural length, m) go together")
            return
         end if
         p = physical_t(g=g, omega=omega, a=0.0_wp, kappa=kappa)
         if (values%given("r0")) p%r0 = r0
         do k = 1, max(size(amplitudes), 1)
            if (size(amplitudes) > 0) p%a = amplitudes(k)
            call check_physical(p, cause, variable)
            if (allocated(cause)) then
               call fail(error, file%path, group%name, variable, cause%message//"; got r0 = "//real_text(p%r0)// &
                  ", g = "//real_text(p%g)//", omega = "//real_text(p%omega)//", a = "//real_text(p%a)// &
                  ", kappa = "//real_text(p%kappa))
               return
            end if
         end do
         if (size(amplitudes) > 0 .and. .not. task%takes_amplitudes) then
            call fail(error, file%path, group%name, "a", "task '"//task%name//"' takes no amplitudes "// &
               "(a chart runs over the grid of &chart, alpha and beta); amplitudes a with r0 make the points of "// &
               "task 'points' or the curves of task 'coefficient'")
            return
         end if
      end associate
      scene%physical = .true.
      scene%pendulum = p
      scene%pendulum%a = 0.0_wp
      scene%amplitudes = amplitudes
      scene%epsilon = physical_epsilon(p)
      ! with &physical the damping is kappa; epsilon in &scene would be an error
      call scene%settings%hide("epsilon")
   end subroutine read_physical_group
end module hillstab_batch_scene_read

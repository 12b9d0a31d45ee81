!> A scene: one namelist file describing one run. `scene_t` holds what every task
!> shares — the `&scene` settings (model, method, damping, output, columns, format) and the
!> model's own group — and the task itself, an extension of the abstract `task_t` that
!> holds its own groups (a chart's grid, a series' pendulum; the tasks that take the
!> pendulum in SI units, `&physical`, hold it too: hillstab_batch_scene_physical) and
!> knows how to read, run, size and split itself. The dispatcher, the MPI splitter and
!> the resource limits call the task's bindings; nothing switches on the task.
!>
!> This module declares the types and writes the effective scene back as namelist text
!> (`scene_namelist`): every output header carries it, so that the file repeats its
!> run. Reading is in hillstab_batch_run_read, the tasks in hillstab_batch_task_*.
!>
!>```fortran
!> type(scene_t) :: scene
!> type(error_t), allocatable :: error
!> call read_scene("data/scenes/default_exact.nml", scene, error)
!> if (.not. allocated(error)) print '(a)', scene_namelist(scene)
!>```
module hillstab_batch_scene_types
   use hillstab_core_kinds, only: wp, int64
   use hillstab_core_kinds, only: pi
   use hillstab_core_text, only: quoted, real_text, integer_text
   use hillstab_core_error, only: error_t, set_error, err_input
   use hillstab_hill_model, only: hill_model_t
   use hillstab_hill_system, only: hill_system_t
   use hillstab_integrate_monodromy, only: method_t
   use hillstab_batch_scene_declaration, only: group_t, group_values_t
   use hillstab_batch_scene_file, only: scene_file_t
   use hillstab_batch_output_file, only: output_file_t, open_output
   implicit none
   private
   public :: scene_t, task_t, output_path, scene_namelist, scene_header, open_scene_output, add_warning
   public :: task_header_groups

   !> A task: what it reads, runs and writes. Concrete tasks extend it (the registry,
   !> hillstab_batch_tasks_registry, makes one from its name); a task whose points are
   !> independent also overrides the unit bindings, so that a driver can compute its
   !> points in units anywhere (hillstab_batch_run_units, the MPI program).
   type, abstract :: task_t
      character(len=:), allocatable :: name       !! the task name, as in `&scene task`
      logical :: takes_columns = .false.          !! `&scene columns` and format = 'binary' apply
      !> its units are computed on OpenMP threads as soon as there are two (each unit is
      !> computed on one thread: a system's row shares its nodes); otherwise only with at
      !> least 4 units a thread, fewer going one by one, each in parallel within
      logical :: units_in_parallel = .false.
      !> the effective values of the task's groups, in the order the header writes them
      type(group_values_t), allocatable :: groups(:)
      !> what reading its groups found suspect though valid (a value in the wrong unit?), one
      !> warning a line (new lines between them; "" when none): read_scene adds them to the scene's
      character(len=:), allocatable :: warnings
   contains
      !> read and check the task's groups from the scene file
      procedure(task_read), deferred :: read
      !> run the task in one loop of its own: write its output file (default: none; a task
      !> whose points are independent, `point_count` > 0, runs in units instead)
      procedure :: run => task_run_by_units
      !> the groups the task reads, with its defaults, in the order the header writes them
      procedure(task_declarations), deferred :: declarations
      !> the effective values of the groups the header writes after `&scene` and the model's
      !> group (default: `groups`; a task that takes a group read before its own, as
      !> `&physical`, puts it first)
      procedure :: header_groups => task_header_groups
      !> groups a template shows commented out, each an alternative to one it reads
      procedure :: template_alternatives => task_template_alternatives
      !> an upper estimate of the bytes of the output file (0: the task bounds its own)
      procedure :: estimated_bytes => task_estimated_bytes
      !> an upper estimate of the memory its buffers need (0: a few MB whatever the scene)
      procedure :: memory_bytes => task_memory_bytes
      !> what sets the size of the output, for messages ("&chart: n_alpha, n_beta: 200 x 200 points")
      procedure :: size_variables => task_size_variables
      !> what sets the memory the task needs, for messages (default: `size_variables`)
      procedure :: memory_variables => task_memory_variables
      !> points a distributed run computes (0: the task runs in one process)
      procedure :: point_count => task_point_count
      !> how many consecutive points make one unit for `n_workers` processes
      procedure :: unit_size => task_unit_size
      !> prepare what every unit shares (once, before the units)
      procedure :: prepare_units => task_prepare_units
      !> the text (a binary file: the records' bytes, hillstab_batch_output_file `record_bytes`)
      !> and statuses of the points `first` … `last` (called on several OpenMP threads
      !> at once: no function with a deferred-length character result, see hillstab_batch_output_file
      !> `join_lines`)
      procedure :: unit_text => task_unit_text
      !> open the output of a distributed run: checks, the header
      procedure :: open_units => task_open_units
      !> after a distributed run: warnings, and the error naming the first failed point
      procedure :: finish_units => task_finish_units
      !> (α, β) of point k
      procedure :: point_of => task_point_of
   end type task_t

   !> One validated run description.
   type :: scene_t
      character(len=:), allocatable :: source       !! path of the scene file
      class(task_t), allocatable :: task            !! the task, with its groups
      !> the model of Q, made by the model registry (hillstab_hill_models) from `&scene model`
      class(hill_model_t), allocatable :: model
      !> `&scene model = 'system'`: the system of Hill equations of `&system`
      !> (hillstab_hill_system_matrix), in place of `model` (then unallocated)
      class(hill_system_t), allocatable :: system
      type(method_t) :: method                      !! method, n_segments, sampling, tolerance
      real(wp) :: epsilon = 0.0_wp                  !! damping ε of eq. (46)
      character(len=:), allocatable :: output       !! prefix: files are <output>_<task>.dat (.bin)
      !> chart and points: the columns to write, blank-separated ("" = all the task offers)
      character(len=:), allocatable :: columns
      logical :: binary = .false.      !! chart and points: float64 records after a text header
      logical :: names_line = .false.  !! text: a line of column names after the `#` header
      type(group_values_t) :: settings              !! the effective `&scene` values
      !> the model carries data, read from its group `&<model name>` (hillstab_batch_scene_group_model)
      logical :: model_group = .false.
      type(group_values_t) :: model_values          !! the effective values of that group
      !> what reading the scene found suspect though valid — a group the task does not read,
      !> a spring longer than 100 m, ω below 1e-3 rad/s — one warning a line, each naming the
      !> file and the group (new lines between them; "" when none). The programs print them
      !> on stderr before the run (`warn_scene` of hillstab_batch_run_scenes).
      character(len=:), allocatable :: warnings
   end type scene_t

   abstract interface
      !> Read and check the task's groups (`file` holds the scene; `scene` its common part).
      subroutine task_read(self, file, scene, error)
         import :: task_t, scene_file_t, scene_t, error_t
         class(task_t), intent(inout) :: self  !! the task, its groups filled in
         type(scene_file_t), intent(in) :: file  !! the scene file
         type(scene_t), intent(in) :: scene  !! the `&scene` settings and the model
         !> err_input naming file, group and variable; unallocated on success
         type(error_t), allocatable, intent(out) :: error
      end subroutine task_read
      !> The groups the task reads, with its defaults.
      function task_declarations(self) result(groups)
         import :: task_t, group_t
         class(task_t), intent(in) :: self  !! the task
         type(group_t), allocatable :: groups(:)
      end function task_declarations
   end interface

contains

   !> The file a scene's task writes: `<output>_<task>.dat` (`.bin` for format = 'binary').
   pure function output_path(scene) result(path)
      type(scene_t), intent(in) :: scene  !! the scene
      character(len=:), allocatable :: path
      if (scene%binary) then
         path = scene%output//"_"//scene%task%name//".bin"
      else
         path = scene%output//"_"//scene%task%name//".dat"
      end if
   end function output_path

   !> Open the scene's output file (its temporary name), a failure reported against
   !> `&scene output`.
   subroutine open_scene_output(scene, file, error)
      type(scene_t), intent(in) :: scene  !! a validated scene
      type(output_file_t), intent(out) :: file  !! the open temporary output file
      type(error_t), allocatable, intent(out) :: error  !! err_io naming &scene output
      call open_output(file, output_path(scene), error, binary=scene%binary, context=scene%source//": &scene: output: ")
   end subroutine open_scene_output

   !> The effective scene as namelist groups, one group a line, every variable with its
   !> value (defaults filled in): `&scene`, the model's own group when it has one, then the
   !> task's (`header_groups`: `&physical` first when the scene has it). Reading these lines
   !> back as a scene reproduces the run.
   function scene_namelist(scene) result(lines)
      type(scene_t), intent(in) :: scene  !! the scene
      character(len=:), allocatable :: lines(:)
      character(len=:), allocatable :: settings, settings_model
      type(group_values_t) :: values
      type(group_values_t), allocatable :: groups(:)
      integer :: k, width, n_task, first
      ! the output prefix as the scene holds it (a driver may direct the file elsewhere)
      values = scene%settings
      call values%set("output", quoted(scene%output))
      settings = values%line()
      if (scene%model_group) settings_model = scene%model_values%line()
      groups = scene%task%header_groups()
      n_task = size(groups)
      width = len(settings)
      if (scene%model_group) width = max(width, len(settings_model))
      do k = 1, n_task
         width = max(width, len(groups(k)%line()))
      end do
      ! &scene, the model's own group, then the task's groups
      first = 2 + merge(1, 0, scene%model_group)
      allocate (character(len=width) :: lines(first - 1 + n_task))
      lines(1) = settings
      if (scene%model_group) lines(2) = settings_model
      do k = 1, n_task
         lines(first - 1 + k) = groups(k)%line()
      end do
   end function scene_namelist

   !> The lines an output file's header holds: `title`, the scene file, the effective scene
   !> (`scene_namelist`: given back as a scene, the file repeats its run), then `extra`.
   function scene_header(scene, title, extra) result(lines)
      type(scene_t), intent(in) :: scene  !! the scene of the run
      character(len=*), intent(in) :: title  !! the first line: the program, its version, what the file holds
      character(len=*), intent(in) :: extra(:)  !! the lines after the namelist groups
      character(len=:), allocatable :: lines(:)
      character(len=:), allocatable :: groups(:), source_line
      groups = scene_namelist(scene)
      source_line = "scene file: "//scene%source//" (the namelist lines below repeat this run)"
      allocate (character(len=max(len(title), len(source_line), len(groups), len(extra))) :: &
         lines(2 + size(groups) + size(extra)))
      lines(1) = title
      lines(2) = source_line
      lines(3:2 + size(groups)) = groups
      lines(3 + size(groups):) = extra
   end function scene_header

   !> Add a warning (or several, one a line) to a list of warnings (`scene_t%warnings`,
   !> `task_t%warnings`).
   pure subroutine add_warning(warnings, text)
      character(len=:), allocatable, intent(inout) :: warnings  !! the warnings so far, one a line
      character(len=*), intent(in) :: text  !! the new warning
      if (.not. allocated(warnings)) warnings = ""
      if (len(warnings) > 0) then
         warnings = warnings//achar(10)//text
      else
         warnings = text
      end if
   end subroutine add_warning

   !> The task's own groups (none when it has not read them): the default `header_groups`.
   function task_header_groups(self) result(groups)
      class(task_t), intent(in) :: self  !! the task
      type(group_values_t), allocatable :: groups(:)
      if (allocated(self%groups)) then
         groups = self%groups
      else
         allocate (groups(0))
      end if
   end function task_header_groups

   !> Default: no alternative groups.
   subroutine task_template_alternatives(self, groups, notes)
      class(task_t), intent(in) :: self  !! the task
      type(group_t), allocatable, intent(out) :: groups(:)  !! the groups, commented out in templates
      character(len=80), allocatable, intent(out) :: notes(:)  !! one comment line per group
      allocate (groups(0), notes(0))
   end subroutine task_template_alternatives

   !> Default: the task bounds its own output.
   pure function task_estimated_bytes(self, scene) result(bytes)
      class(task_t), intent(in) :: self  !! the task
      type(scene_t), intent(in) :: scene  !! its scene
      integer(int64) :: bytes
      bytes = 0
   end function task_estimated_bytes

   !> Default: memory of a task whose buffers do not grow with its scene (a few MB).
   function task_memory_bytes(self, scene) result(bytes)
      class(task_t), intent(in) :: self  !! the task
      type(scene_t), intent(in) :: scene  !! its scene
      integer(int64) :: bytes
      bytes = 0
   end function task_memory_bytes

   !> Default: the task's groups.
   function task_size_variables(self) result(text)
      class(task_t), intent(in) :: self  !! the task
      character(len=:), allocatable :: text
      text = "task '"//self%name//"'"
   end function task_size_variables

   !> Default: what sets the size of the output.
   function task_memory_variables(self) result(text)
      class(task_t), intent(in) :: self  !! the task
      character(len=:), allocatable :: text
      text = self%size_variables()
   end function task_memory_variables

   !> Default: not distributable.
   pure function task_point_count(self) result(n)
      class(task_t), intent(in) :: self  !! the task
      integer(int64) :: n
      n = 0
   end function task_point_count

   !> Default: one point a unit.
   pure integer function task_unit_size(self, n_workers) result(size)
      class(task_t), intent(in) :: self  !! the task
      integer, intent(in) :: n_workers   !! processes computing units (>= 1)
      size = 1
   end function task_unit_size

   !> Default: nothing shared.
   subroutine task_prepare_units(self, scene)
      class(task_t), intent(inout) :: self  !! the task
      type(scene_t), intent(in) :: scene    !! its scene
   end subroutine task_prepare_units

   !> Default: no loop of its own. The tasks whose points are independent (chart over
   !> `&chart`, points) are written unit by unit (`unit_text`) by the driver of
   !> hillstab_batch_run_units, which the scene runner (hillstab_batch_run_scenes `run_scene`)
   !> chooses for them: called for such a task, this says so (err_input) and writes nothing.
   subroutine task_run_by_units(self, scene, quiet, error)
      class(task_t), intent(in) :: self  !! the task
      type(scene_t), intent(in) :: scene  !! the scene (holding this task)
      logical, intent(in) :: quiet  !! no progress on stderr
      !> what failed (err_points_failed: the file is written with failed points)
      type(error_t), allocatable, intent(out) :: error
      call set_error(error, err_input, scene%source//": &scene: task: task '"//self%name// &
         "' runs unit by unit (hillstab_batch_run_scenes run_scene), not in a loop of its own")
   end subroutine task_run_by_units

   !> Default: no units (a driver asks only tasks with a point count).
   subroutine task_unit_text(self, scene, unit, first, last, text, statuses)
      class(task_t), intent(in) :: self  !! the task
      type(scene_t), intent(in) :: scene  !! its scene
      integer, intent(in) :: unit  !! the unit, 1 …
      integer(int64), intent(in) :: first, last  !! its points
      character(len=:), allocatable, intent(out) :: text  !! the lines as the file holds them, no final new line (or bytes)
      integer, intent(out) :: statuses(first:last)  !! per point
      text = ""
      statuses = 0
   end subroutine task_unit_text

   !> Default: the task cannot run in units.
   subroutine task_open_units(self, scene, file, error)
      class(task_t), intent(in) :: self  !! the task
      type(scene_t), intent(in) :: scene  !! its scene
      type(output_file_t), intent(inout) :: file  !! the open output file
      type(error_t), allocatable, intent(out) :: error  !! why the units cannot be written
      call set_error(error, err_input, scene%source//": &scene: task: task '"//self%name// &
         "' does not run in units")
   end subroutine task_open_units

   !> Default: nothing to report.
   subroutine task_finish_units(self, scene, n_points, n_failed, first_failed, n_inaccurate, first_inaccurate, error)
      class(task_t), intent(in) :: self  !! the task
      type(scene_t), intent(in) :: scene  !! its scene
      integer(int64), intent(in) :: n_points  !! all points
      integer(int64), intent(in) :: n_failed  !! failed points written
      real(wp), intent(in) :: first_failed(2)  !! (α, β) of the first of them
      integer(int64), intent(in) :: n_inaccurate  !! round-off limited points written
      real(wp), intent(in) :: first_inaccurate(2)  !! (α, β) of the first of them
      type(error_t), allocatable, intent(out) :: error  !! err_points_failed when points failed
   end subroutine task_finish_units

   !> Default: no points.
   pure function task_point_of(self, scene, k) result(point)
      class(task_t), intent(in) :: self  !! the task
      type(scene_t), intent(in) :: scene  !! its scene
      integer(int64), intent(in) :: k  !! the point, 1 … point_count
      real(wp) :: point(2)
      point = 0.0_wp
   end function task_point_of
end module hillstab_batch_scene_types

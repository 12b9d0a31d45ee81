!> Task `points`: the columns of a chart (hillstab_batch_tasks_chart_columns) at the (α, β)
!> points of a file (`&points file`), or at the bounce amplitudes of `&physical a` with
!> its r0, in order. The task runs in units of consecutive points (hillstab_batch_run_units:
!> on OpenMP threads or MPI ranks, text or binary records), the points of a unit in
!> parallel (dynamic schedule). A failed point is written with status 2 and placeholders;
!> the run then ends with err_points_failed.
module hillstab_batch_tasks_points
   use hillstab_core_kinds, only: wp, int64, pi
   use hillstab_core_error, only: error_t
   use hillstab_core_status, only: status_failed
   use hillstab_core_text, only: integer_text
   use hillstab_hill_coefficient, only: in_physical_domain
   use hillstab_hill_floquet, only: floquet_t
   use hillstab_batch_scene_types, only: scene_t
   use hillstab_batch_scene_physical, only: physical_points
   use hillstab_core_parallel, only: max_threads
   use hillstab_batch_scene_declaration, only: group_t
   use hillstab_batch_scene_file, only: scene_file_t, fail
   use hillstab_batch_scene_checks, only: check_integration_cost
   use hillstab_batch_scene_group_points, only: points_group, read_points_group
   use hillstab_batch_tasks_chart_columns, only: floquet_task_t, n_chart_columns, chart_values, failed_values, &
      chart_line, chart_header, chart_layout_t, chart_names, point_amplitude, tau_per_time, scene_chart_columns, &
      evaluate_point, &
      chart_line_length, header_bytes, text_row_bytes, binary_row_bytes, col_mu_per_s
   use hillstab_batch_output_file, only: output_file_t, write_header, record_bytes, join_lines
   implicit none
   private
   public :: points_task_t, points_task

   !> Points computed between two progress reports (in parallel within).
   integer, parameter :: points_chunk = 4096

   !> The points task and its points.
   type, extends(floquet_task_t) :: points_task_t
      character(len=:), allocatable :: file   !! `&points file` ("" with `&physical a`)
      real(wp), allocatable :: points(:, :)   !! (2, n): α, β in order
      type(chart_layout_t) :: columns         !! the columns written, made by `prepare_units`
   contains
      procedure :: read => points_read
      procedure :: declarations => points_declarations
      procedure :: estimated_bytes => points_estimated_bytes
      procedure :: memory_bytes => points_memory_bytes
      procedure :: size_variables => points_size_variables
      procedure :: point_count => points_point_count
      procedure :: unit_size => points_unit_size
      procedure :: prepare_units => points_prepare_units
      procedure :: unit_text => points_unit_text
      procedure :: open_units => points_open_units
      procedure :: point_of => points_point_of
   end type points_task_t

contains

   !> `&points`.
   function points_declarations(self) result(groups)
      class(points_task_t), intent(in) :: self  !! the task
      type(group_t), allocatable :: groups(:)
      allocate (groups(1))
      groups(1) = points_group()
   end function points_declarations

   !> The variables that set the size of the file.
   function points_size_variables(self) result(text)
      class(points_task_t), intent(in) :: self  !! the task
      character(len=:), allocatable :: text
      text = "&points: file: "//integer_text(size(self%points, 2))//" points"
   end function points_size_variables

   !> A points task before its scene is read.
   function points_task() result(task)
      type(points_task_t) :: task
      task%name = "points"
      task%physical_use%amplitudes_replace = "the &points group"
      task%takes_columns = .true.
      task%physical_use%takes_amplitudes = .true.
   end function points_task

   !> The points of `&points file`, or of `&physical a` (then `&points` may not name a file).
   subroutine points_read(self, file, scene, error)
      class(points_task_t), intent(inout) :: self  !! the task, its points filled in
      type(scene_file_t), intent(in) :: file      !! the scene file
      type(scene_t), intent(in) :: scene          !! the `&scene` settings
      type(error_t), allocatable, intent(out) :: error  !! err_input naming file, group and variable
      type(chart_layout_t) :: columns
      integer :: k
      logical :: from_physical
      from_physical = size(self%physical%amplitudes) > 0
      allocate (self%groups(1))
      call read_points_group(file, points_group(), scene%model, self%file, self%points, self%groups(1), error, &
                             optional=from_physical)
      if (allocated(error)) return
      if (from_physical) then
         if (self%groups(1)%given("file")) then
            call fail(error, file%path, "points", "file", "the points come either from &points file (alpha, beta) "// &
               "or from &physical a and r0, not both")
            return
         end if
         self%points = physical_points(self%physical, scene%model)
         call self%groups(1)%hide("file")
      end if
      do k = 1, size(self%points, 2)
         call check_integration_cost(file%path, "points", "file", scene%method, &
            abs(self%points(1, k)) + abs(self%points(2, k)), error, where="point "//integer_text(k))
         if (allocated(error)) return
      end do
      call scene_chart_columns(scene, self%physical, columns, error)
   end subroutine points_read

   !> Header plus one row a point.
   pure function points_estimated_bytes(self, scene) result(bytes)
      class(points_task_t), intent(in) :: self  !! the task
      type(scene_t), intent(in) :: scene  !! its scene
      integer(int64) :: bytes
      bytes = header_bytes + int(size(self%points, 2), int64)*merge(binary_row_bytes, text_row_bytes, scene%binary)
   end function points_estimated_bytes

   !> The points themselves, and the points of the units the driver holds at once (up to
   !> 16 units of at most 64 points a thread, hillstab_batch_run_units): each its line,
   !> status and values and its share of the unit's joined text (or records).
   function points_memory_bytes(self, scene) result(bytes)
      class(points_task_t), intent(in) :: self  !! the task
      type(scene_t), intent(in) :: scene  !! its scene
      integer(int64) :: bytes, n_points, held
      n_points = size(self%points, 2)
      held = min(n_points, int(16*64, int64)*max_threads())
      bytes = 16*n_points + held*(2*chart_line_length + 4 + 8*n_chart_columns)
   end function points_memory_bytes

   !> Whether some point lies outside the physical domain.
   pure logical function outside(self)
      class(points_task_t), intent(in) :: self
      outside = .not. all(in_physical_domain(self%points(1, :), self%points(2, :)))
   end function outside

   !> Text lines (with the file's columns) or records `values` of the points `first` …
   !> `last` (in parallel); a failed point gets its placeholders.
   subroutine compute_points(self, scene, columns, first, last, lines, statuses, values)
      class(points_task_t), intent(in) :: self  !! the task
      type(scene_t), intent(in) :: scene  !! its scene
      type(chart_layout_t), intent(in) :: columns  !! the columns written
      integer, intent(in) :: first, last  !! range of point indices
      character(len=*), intent(out) :: lines(first:)  !! one chart line per point
      integer, intent(out) :: statuses(first:)  !! per point: status_ok, status_roundoff or status_failed
      !> the same points as records (columns, points), for format = 'binary'
      real(wp), intent(out), optional :: values(:, first:)
      type(floquet_t) :: f
      type(error_t), allocatable :: cause
      real(wp) :: per_second, v(n_chart_columns), alpha, beta, a
      logical :: per_time
      integer :: k
      integer :: ids(size(columns%ids))  ! the binary records' columns (a gather through `columns` allocated)
      ids = columns%ids
      ! dτ/dt turns a rate per unit τ into one per unit of the user's time (the column mu_per_s)
      per_time = any(ids == col_mu_per_s)
      !$omp parallel do schedule(dynamic) default(shared) private(k, f, cause, v, alpha, beta, a, per_second)
      do k = first, last
         alpha = self%points(1, k)
         beta = self%points(2, k)
         a = 0.0_wp
         if (self%physical%given) a = point_amplitude(self%physical, k, alpha, beta)
         call evaluate_point(scene, alpha, beta, f, cause, statuses(k), columns=columns)
         if (statuses(k) == status_failed) then
            v = failed_values(columns, alpha, beta, in_physical_domain(alpha, beta), a)
         else
            per_second = 0.0_wp
            if (per_time) per_second = tau_per_time(scene, self%physical, alpha, beta)
            v = chart_values(alpha, beta, f, in_physical_domain(alpha, beta), statuses(k), per_second, a)
         end if
         if (present(values)) values(:, k) = v(ids)
         call chart_line(columns, v, lines(k))
      end do
      !$omp end parallel do
   end subroutine compute_points

   !> The points.
   pure function points_point_count(self) result(n)
      class(points_task_t), intent(in) :: self  !! the task
      integer(int64) :: n
      n = size(self%points, 2)
   end function points_point_count

   !> Runs of consecutive points, small enough (about 16 units a worker, at most 64 points)
   !> to balance points of very different cost.
   pure integer function points_unit_size(self, n_workers) result(size)
      class(points_task_t), intent(in) :: self  !! the task
      integer, intent(in) :: n_workers   !! processes computing units
      size = max(1, min(64, int(self%point_count())/(16*max(1, n_workers))))
   end function points_unit_size

   !> The columns, shared by every unit.
   subroutine points_prepare_units(self, scene)
      class(points_task_t), intent(inout) :: self  !! the task
      type(scene_t), intent(in) :: scene    !! its scene
      type(error_t), allocatable :: error
      call scene_chart_columns(scene, self%physical, self%columns, error)  ! checked when the scene was read
   end subroutine points_prepare_units

   !> The lines of the points `first` … `last` (a binary file: their records' bytes; the units
   !> prepared).
   subroutine points_unit_text(self, scene, unit, first, last, text, statuses)
      class(points_task_t), intent(in) :: self  !! the task
      type(scene_t), intent(in) :: scene  !! its scene
      integer, intent(in) :: unit  !! the unit
      integer(int64), intent(in) :: first, last  !! its points
      character(len=:), allocatable, intent(out) :: text  !! the lines, no final new line
      integer, intent(out) :: statuses(first:last)  !! per point
      character(len=chart_line_length), allocatable :: lines(:)
      real(wp), allocatable :: values(:, :)
      allocate (lines(first:last))
      if (scene%binary) then
         allocate (values(size(self%columns%ids), first:last))
         call compute_points(self, scene, self%columns, int(first), int(last), lines, statuses, values)
         call record_bytes(values, text)
      else
         call compute_points(self, scene, self%columns, int(first), int(last), lines, statuses)
         call join_lines(lines, .false., text)
      end if
   end subroutine points_unit_text

   !> The header of `points_run`.
   subroutine points_open_units(self, scene, file, error)
      class(points_task_t), intent(in) :: self  !! the task
      type(scene_t), intent(in) :: scene  !! its scene
      type(output_file_t), intent(inout) :: file  !! the open output file
      type(error_t), allocatable, intent(out) :: error  !! why the file cannot be written
      type(chart_layout_t) :: columns
      call scene_chart_columns(scene, self%physical, columns, error)
      if (allocated(error)) return
      call write_header(file, chart_header(scene, self%physical, outside(self), columns), chart_names(columns), &
                        error, names_line=scene%names_line, records=[size(self%points, 2), 1])
   end subroutine points_open_units

   !> (α, β) of point k.
   pure function points_point_of(self, scene, k) result(point)
      class(points_task_t), intent(in) :: self  !! the task
      type(scene_t), intent(in) :: scene  !! its scene
      integer(int64), intent(in) :: k  !! the point
      real(wp) :: point(2)
      point = self%points(:, k)
   end function points_point_of
end module hillstab_batch_tasks_points

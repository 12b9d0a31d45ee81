!> The tasks of a system scene (`&scene model = 'system'`, the matrices in `&system`):
!> `chart` over the (α, β) grid of `&chart` and `points` at the (α, β) of a `&points` file
!> (tasks `coefficient` and `boundaries` are hillstab_batch_tasks_system_coefficient and
!> hillstab_batch_tasks_system_boundaries). Chart and
!> points write the columns of `system_columns` (`&scene columns` chooses among them; a
!> verdict-only chart is `columns = 'alpha beta stable kind status'`), each point from the
!> exact monodromy (hillstab_integrate_system, the nodes shared along a chart row) and its
!> Floquet analysis (hillstab_hill_system_floquet): the trace and Broucke's a₂, the verdict
!> decided from the multipliers and the method's error bound, its kind, the largest |λ| and
!> exponent, the n largest exponents, the structural defect, the error estimate and status.
!> A point that cannot be computed carries status 2 and placeholders, and the run ends with
!> err_points_failed after the file is written; the file is written atomically.
!>
!> Chart and points run in units (hillstab_batch_run_units: a chart's row, up to 64
!> consecutive points of a points list), text or binary, on OpenMP threads, with
!> checkpoints and `--resume`, and spread over processes by the MPI program. The points of
!> a chart's row share their nodes (`system_row_values`); each point of a points list is
!> computed alone (`system_values`).
module hillstab_batch_tasks_system
   use hillstab_core_kinds, only: wp, int64, version_string
   use hillstab_core_error, only: error_t, set_error, err_points_failed
   use hillstab_core_text, only: real_text, integer_text
   use hillstab_hill_system, only: hill_system_t, system_form_t, prepare_system, system_equation_text, &
      system_description
   use hillstab_integrate_system, only: system_method_t, system_method_name
   use hillstab_batch_tasks_system_values, only: system_values, system_row_values, scalar_path, failure_text
   use hillstab_batch_tasks_floquet_columns, only: n_fixed, system_point_values, system_column_names, &
      system_column_table, status_column, plain_table
   use hillstab_batch_output_columns, only: column_t, put_row, columns_text
   use hillstab_batch_tasks_floquet_columns, only: chart_column_t, scene_columns
   use hillstab_batch_scene_types, only: scene_t, task_t, scene_header
   use hillstab_batch_tasks_regions, only: chart_region_lines
   use hillstab_batch_scene_declaration, only: group_t
   use hillstab_batch_scene_file, only: scene_file_t, fail
   use hillstab_batch_scene_checks, only: max_grid_count
   use hillstab_batch_scene_group_chart, only: chart_grid_t, chart_group, read_chart_group, grid_alpha, grid_beta, &
      grid_point, grid_size_text
   use hillstab_batch_scene_group_points, only: points_group, read_points_group
   use hillstab_batch_output_file, only: output_file_t, write_header, join_lines, record_bytes
   use hillstab_core_parallel, only: max_threads
   use hillstab_batch_tasks_system_cost, only: check_system_cost, extreme_name
   use, intrinsic :: iso_fortran_env, only: error_unit
   implicit none
   private
   public :: system_chart_task_t, system_points_task_t, system_chart_task, system_points_task, system_task_names

   !> Most exponent columns (mu_1 … mu_n, n ≤ max_dof).
   integer, parameter :: max_dof_columns = 20
   !> Bytes of a file's `#` header, an upper estimate (the matrices of n = 20 and 32
   !> harmonics written in full take about 0.7 MB).
   integer(int64), parameter :: header_bytes = 1000000

   !> The tasks a system scene takes.
   character(len=*), parameter :: system_task_names = "chart, points, coefficient, boundaries, regions, edges"


   !> Chart and points: what they share (the columns chosen; for runs in units, the
   !> prepared system).
   type, abstract, extends(task_t) :: system_floquet_task_t
      integer, allocatable :: chosen(:)  !! indices into `system_column_names`
      type(column_t), allocatable :: table(:)  !! the columns (`system_column_table`)
      type(system_form_t) :: form        !! the prepared system (`prepare_units`)
      !> why the system cannot be prepared ("" when it is), reported by `open_units`
      character(len=:), allocatable :: form_error
   contains
      procedure :: choose_columns => system_choose_columns
      procedure :: prepare_units => system_prepare_units
      procedure :: finish_units => system_finish_units
   end type system_floquet_task_t

   !> `chart` on a system.
   type, extends(system_floquet_task_t) :: system_chart_task_t
      type(chart_grid_t) :: grid  !! `&chart`
   contains
      procedure :: read => chart_read
      procedure :: declarations => chart_declarations
      procedure :: size_variables => chart_size_variables
      procedure :: memory_bytes => chart_memory_bytes
      procedure :: estimated_bytes => chart_estimated_bytes
      procedure :: point_count => chart_point_count
      procedure :: unit_size => chart_unit_size
      procedure :: unit_text => chart_unit_text
      procedure :: open_units => chart_open_units
      procedure :: point_of => chart_point_of
   end type system_chart_task_t

   !> `points` on a system.
   type, extends(system_floquet_task_t) :: system_points_task_t
      character(len=:), allocatable :: path   !! the points file
      real(wp), allocatable :: points(:, :)   !! (2, n): α, β
   contains
      procedure :: read => points_read
      procedure :: declarations => points_declarations
      procedure :: memory_bytes => points_memory_bytes
      procedure :: estimated_bytes => points_estimated_bytes
      procedure :: point_count => points_point_count
      procedure :: unit_size => points_unit_size
      procedure :: unit_text => points_unit_text
      procedure :: open_units => points_open_units
      procedure :: point_of => points_point_of
   end type system_points_task_t


contains

   !> A chart task of a system scene.
   function system_chart_task() result(task)
      type(system_chart_task_t) :: task
      task%name = "chart"
      task%takes_columns = .true.
      task%units_in_parallel = .true.
   end function system_chart_task

   !> A points task of a system scene.
   function system_points_task() result(task)
      type(system_points_task_t) :: task
      task%name = "points"
      task%takes_columns = .true.
      task%units_in_parallel = .true.
   end function system_points_task


   !> The columns of the scene's system as its files name them (`system_column_table`), the
   !> first two after the system's axes (an equations system's parameters).
   function scene_column_table(system) result(table)
      class(hill_system_t), intent(in) :: system  !! the system
      type(chart_column_t), allocatable :: table(:)
      table = system_column_table(system%dof(), system%first_order(), system%axis_name(1), system%axis_name(2))
   end function scene_column_table

   !> `&scene columns`: the names given, in that order (all when blank; the axes also as alpha
   !> and beta); err_input naming &scene columns for a name the system has not or named twice.
   subroutine system_choose_columns(self, scene, error)
      class(system_floquet_task_t), intent(inout) :: self  !! the task
      type(scene_t), intent(in) :: scene  !! its scene
      type(error_t), allocatable, intent(out) :: error  !! err_input naming &scene columns
      type(chart_column_t), allocatable :: table(:)
      integer :: k
      table = scene_column_table(scene%system)
      self%table = plain_table(table)
      call scene_columns(table, [(k, k=1, size(table))], scene%columns, scene%source, self%chosen, error)
   end subroutine system_choose_columns

   !> The text of one point's chosen columns, into a buffer (no deferred-length character
   !> results: this runs on OpenMP threads, see hillstab_batch_output_file `join_lines`), each
   !> in its style of `system_column_table`.
   pure subroutine point_line(table, chosen, v, line, length)
      type(column_t), intent(in) :: table(:)  !! the system's columns (`system_column_table`)
      integer, intent(in) :: chosen(:)  !! the columns written
      real(wp), intent(in) :: v(:)  !! the point's values
      character(len=*), intent(out) :: line  !! at least 26 characters a column
      integer, intent(out) :: length         !! the length of the text
      line = ""
      length = 0
      call put_row(table, chosen, v, line, length)
   end subroutine point_line

   !> The column names chosen, blank-separated (the axes named after the system's).
   function chosen_names(system, chosen) result(text)
      class(hill_system_t), intent(in) :: system
      integer, intent(in) :: chosen(:)
      character(len=:), allocatable :: text
      text = columns_text(plain_table(scene_column_table(system)), chosen)
   end function chosen_names

   !> The header lines of a system file: title, the scene, the equation, the columns' meanings.
   function system_lines(scene, what, chosen, regions) result(lines)
      type(scene_t), intent(in) :: scene
      character(len=*), intent(in) :: what
      integer, intent(in) :: chosen(:)
      character(len=*), intent(in), optional :: regions(:)  !! lines on the regions of a chart's ranges
      character(len=:), allocatable :: lines(:)
      character(len=500), allocatable :: extra(:)
      type(chart_column_t), allocatable :: table(:)
      integer :: k
      table = scene_column_table(scene%system)
      allocate (extra(3 + size(chosen)))
      extra(1) = system_description(scene%system)
      extra(2) = "method: "//system_method_name(scene%method%kind)//", tolerance "// &
                 real_text(scene%method%tolerance)//" on Phi's entries relative to max(1, max|Phi_ij|); epsilon "// &
                 real_text(scene%epsilon)//" adds C = epsilon M"
      extra(3) = "verdicts decided from the multipliers and the error bound of Phi (hillstab_hill_system_floquet); "// &
                 "n = 2 Hamiltonian: Broucke's criterion"
      if (scene%system%first_order()) then
         extra(2) = "method: "//system_method_name(scene%method%kind)//", tolerance "// &
                    real_text(scene%method%tolerance)//" on Phi's entries relative to max(1, max|Phi_ij|); "// &
                    "first-order form: the Magnus methods on the full A"
         extra(3) = "verdicts decided from the multipliers and the error bound of Phi (hillstab_hill_system_floquet); "// &
                    "first-order form: no structure assumed, stable when every multiplier lies inside the unit "// &
                    "circle with its error disc (one on the circle is marginal)"
      end if
      if (scalar_path(scene%system, scene%method%kind)) then
         extra(2) = "method: auto on the scalar form (one equation: the scalar method auto's lanes and meshes, "// &
                    "hillstab_integrate_auto), tolerance "//real_text(scene%method%tolerance)//" on S relative "// &
                    "to max(1, |S|); epsilon "//real_text(scene%epsilon)//" adds C = epsilon M"
         extra(3) = "verdicts decided from the trace S of chi = exp(eps tau/2) x and its error bound "// &
                    "(hillstab_hill_floquet): Phi has tr = exp(-eps P/2) S and det = a2 = exp(-eps P) exactly, "// &
                    "so the defect is 0; error_estimate is S's relative to max(1, |S|), steps the row's mean"
      end if
      do k = 1, size(chosen)
         extra(3 + k) = "column "//integer_text(k)//", "//table(chosen(k))%name//": "//table(chosen(k))%meaning
      end do
      if (present(regions)) extra = [character(len=500) :: extra, regions]
      lines = scene_header(scene, "hillstab "//version_string//": "//what//" of "// &
                           system_equation_text(scene%system), extra)
   end function system_lines

   !> `&chart` (any finite α), and the columns.
   subroutine chart_read(self, file, scene, error)
      class(system_chart_task_t), intent(inout) :: self  !! the task, its grid filled in
      type(scene_file_t), intent(in) :: file      !! the scene file
      type(scene_t), intent(in) :: scene          !! the `&scene` settings
      type(error_t), allocatable, intent(out) :: error  !! err_input naming file, group and variable
      allocate (self%groups(1))
      call read_chart_group(file, chart_group(), grid=self%grid, values=self%groups(1), error=error)
      if (allocated(error)) return
      if (int(self%grid%n_alpha, int64)*self%grid%n_beta > int(max_grid_count, int64)) then
         call fail(error, file%path, "chart", "n_beta", "n_alpha * n_beta exceeds the limit of 1e8 points")
         return
      end if
      call check_system_cost(scene, max(abs(self%grid%alpha_min), abs(self%grid%alpha_max)), &
                             max(abs(self%grid%beta_min), abs(self%grid%beta_max)), "chart", &
                             extreme_name("alpha", self%grid%alpha_min, self%grid%alpha_max), &
                             extreme_name("beta", self%grid%beta_min, self%grid%beta_max), error)
      if (allocated(error)) return
      call self%choose_columns(scene, error)
   end subroutine chart_read

   !> `&chart`.
   function chart_declarations(self) result(groups)
      class(system_chart_task_t), intent(in) :: self  !! the task
      type(group_t), allocatable :: groups(:)
      allocate (groups(1))
      groups(1) = chart_group()
   end function chart_declarations

   !> The variables that set the size of the file.
   function chart_size_variables(self) result(text)
      class(system_chart_task_t), intent(in) :: self  !! the task
      character(len=:), allocatable :: text
      text = grid_size_text(self%grid, .false.)
   end function chart_size_variables

   !> The buffers of a chart run in units (hillstab_batch_run_units), each row n_beta points:
   !> up to 16 rows a thread waiting to be written (their text, or their records of the
   !> chosen columns in binary), and each thread's row of values and text. Besides them a
   !> run holds a few MB whatever the grid (its nodes, one line per thread).
   function chart_memory_bytes(self, scene) result(bytes)
      class(system_chart_task_t), intent(in) :: self  !! the task
      type(scene_t), intent(in) :: scene  !! its scene
      integer(int64) :: bytes, row_values, row_text, row_written
      integer :: n
      n = scene%system%dof()
      row_values = 8*int(n_fixed + n, int64)*self%grid%n_beta
      row_text = int(row_text_width(size(self%chosen)), int64)*self%grid%n_beta
      row_written = row_text
      if (scene%binary) then
         row_written = 8*int(size(self%chosen), int64)*self%grid%n_beta
         row_text = 0
      end if
      bytes = int(min(16*max_threads(), self%grid%n_alpha), int64)*row_written + &
              int(max_threads(), int64)*(row_values + 2*row_text)
   end function chart_memory_bytes

   !> Header plus n_alpha n_beta lines of the chosen columns (or their float64 records) and
   !> one blank line per α block.
   pure function chart_estimated_bytes(self, scene) result(bytes)
      class(system_chart_task_t), intent(in) :: self  !! the task
      type(scene_t), intent(in) :: scene  !! its scene
      integer(int64) :: bytes
      bytes = header_bytes + int(self%grid%n_alpha, int64)*int(self%grid%n_beta, int64)* &
              merge(8*size(self%chosen), row_text_width(size(self%chosen)), scene%binary) + int(self%grid%n_alpha, int64)
   end function chart_estimated_bytes

   !> The characters a point's line may take in a row's text: 26 a column and its new line.
   pure integer function row_text_width(n_columns)
      integer, intent(in) :: n_columns  !! columns chosen
      row_text_width = 26*n_columns + 1
   end function row_text_width

   !> One row of the chart: its values and its text (the points' lines joined by new lines,
   !> no final one).
   subroutine chart_row(self, scene, form, method, i, values, text, text_length, n_failed, failure)
      class(system_chart_task_t), intent(in) :: self
      type(scene_t), intent(in) :: scene
      type(system_form_t), intent(in) :: form
      type(system_method_t), intent(in) :: method
      integer, intent(in) :: i
      real(wp), intent(out) :: values(:, :)
      character(len=*), intent(inout) :: text
      integer(int64), intent(out) :: text_length
      integer, intent(out) :: n_failed
      character(len=*), intent(out) :: failure
      character(len=(n_fixed + max_dof_columns)*26) :: line
      real(wp) :: alpha, betas(self%grid%n_beta)
      integer :: j, length
      alpha = grid_alpha(self%grid, i)
      betas = [(grid_beta(self%grid, j), j=1, self%grid%n_beta)]
      call system_row_values(scene%system, form, method, alpha, betas, values, n_failed, failure)
      text_length = 0
      if (scene%binary) return
      do j = 1, self%grid%n_beta
         call point_line(self%table, self%chosen, values(:, j), line, length)
         if (j > 1) then
            text_length = text_length + 1
            text(text_length:text_length) = new_line("a")
         end if
         text(text_length + 1:text_length + length) = line(:length)
         text_length = text_length + length
      end do
   end subroutine chart_row

   !> Points of the chart.
   pure function chart_point_count(self) result(n)
      class(system_chart_task_t), intent(in) :: self  !! the task
      integer(int64) :: n
      n = int(self%grid%n_alpha, int64)*self%grid%n_beta
   end function chart_point_count

   !> One row a unit (its points share their nodes).
   pure integer function chart_unit_size(self, n_workers) result(size)
      class(system_chart_task_t), intent(in) :: self  !! the task
      integer, intent(in) :: n_workers   !! processes computing units
      size = self%grid%n_beta
   end function chart_unit_size

   !> Row `unit` as the file holds it (a blank line before every row but the first; a binary
   !> file: its records' bytes), computed as `chart_run` computes it.
   subroutine chart_unit_text(self, scene, unit, first, last, text, statuses)
      class(system_chart_task_t), intent(in) :: self  !! the task, its units prepared
      type(scene_t), intent(in) :: scene  !! its scene
      integer, intent(in) :: unit  !! the row
      integer(int64), intent(in) :: first, last  !! its points
      character(len=:), allocatable, intent(out) :: text  !! the lines, no final new line
      integer, intent(out) :: statuses(first:last)  !! per point
      real(wp), allocatable :: values(:, :)
      character(len=:), allocatable :: buffer
      character(len=400) :: failure
      integer(int64) :: length
      integer :: n, n_failed, offset
      n = self%form%n
      allocate (values(n_fixed + n, self%grid%n_beta))
      ! (a binary row's values are all it needs)
      allocate (character(len=merge(1_int64, int(row_text_width(size(self%chosen)), int64)*self%grid%n_beta + 1, &
                                    scene%binary)) :: buffer)
      offset = merge(1, 0, unit > 1 .and. .not. scene%binary)
      if (offset == 1) buffer(1:1) = new_line("a")
      call chart_row(self, scene, self%form, system_method_t(scene%method%kind, scene%method%tolerance), unit, &
                     values, buffer(offset + 1:), length, n_failed, failure)
      if (scene%binary) then
         call record_bytes(values(self%chosen, :), text)
      else
         text = buffer(1:offset + length)
      end if
      statuses = nint(values(status_column(n), :))
   end subroutine chart_unit_text

   !> The checks and the header of `chart_run`.
   subroutine chart_open_units(self, scene, file, error)
      class(system_chart_task_t), intent(in) :: self  !! the task, its units prepared
      type(scene_t), intent(in) :: scene  !! its scene
      type(output_file_t), intent(inout) :: file  !! the open output file
      type(error_t), allocatable, intent(out) :: error  !! why the file cannot be written
      if (len(self%form_error) > 0) then
         call fail(error, scene%source, "system", "mass", self%form_error)
         return
      end if
      call write_header(file, system_lines(scene, "stability chart", self%chosen, &
                                           chart_region_lines(scene, self%grid)), &
                        chosen_names(scene%system, self%chosen), error, names_line=scene%names_line, &
                        records=[self%grid%n_beta, self%grid%n_alpha])
   end subroutine chart_open_units

   !> (α, β) of point k, numbered row by row.
   pure function chart_point_of(self, scene, k) result(point)
      class(system_chart_task_t), intent(in) :: self  !! the task
      type(scene_t), intent(in) :: scene  !! its scene
      integer(int64), intent(in) :: k  !! the point
      real(wp) :: point(2)
      point = grid_point(self%grid, k)
   end function chart_point_of

   !> `&points`, and the columns.
   subroutine points_read(self, file, scene, error)
      class(system_points_task_t), intent(inout) :: self  !! the task, its points read
      type(scene_file_t), intent(in) :: file      !! the scene file
      type(scene_t), intent(in) :: scene          !! the `&scene` settings
      type(error_t), allocatable, intent(out) :: error  !! err_input naming file, group and variable
      allocate (self%groups(1))
      call read_points_group(file, points_group(), path=self%path, pairs=self%points, values=self%groups(1), &
                             error=error)
      if (allocated(error)) return
      if (size(self%points, 2) > 0) then
         call check_system_cost(scene, maxval(abs(self%points(1, :))), maxval(abs(self%points(2, :))), "points", &
                                "file", "file", error)
         if (allocated(error)) return
      end if
      call self%choose_columns(scene, error)
   end subroutine points_read

   !> `&points`.
   function points_declarations(self) result(groups)
      class(system_points_task_t), intent(in) :: self  !! the task
      type(group_t), allocatable :: groups(:)
      allocate (groups(1))
      groups(1) = points_group()
   end function points_declarations

   !> The points themselves, and the points of the units the driver holds at once (up to
   !> 16 units of at most 64 points a thread, hillstab_batch_run_units): each its values,
   !> its line and the unit's joined text (or records).
   function points_memory_bytes(self, scene) result(bytes)
      class(system_points_task_t), intent(in) :: self  !! the task
      type(scene_t), intent(in) :: scene  !! its scene
      integer(int64) :: bytes, n_points, held
      n_points = size(self%points, 2)
      held = min(n_points, int(16*64, int64)*max_threads())
      bytes = 16*n_points + held*(8*int(n_fixed + scene%system%dof(), int64) + 2*(n_fixed + max_dof_columns)*26)
   end function points_memory_bytes

   !> Header plus a line (or a record) of the chosen columns per point.
   pure function points_estimated_bytes(self, scene) result(bytes)
      class(system_points_task_t), intent(in) :: self  !! the task
      type(scene_t), intent(in) :: scene  !! its scene
      integer(int64) :: bytes
      bytes = header_bytes + int(size(self%points, 2), int64)* &
              merge(8*size(self%chosen), row_text_width(size(self%chosen)), scene%binary)
   end function points_estimated_bytes

   !> The points.
   pure function points_point_count(self) result(n)
      class(system_points_task_t), intent(in) :: self  !! the task
      integer(int64) :: n
      n = size(self%points, 2)
   end function points_point_count

   !> Runs of consecutive points, small enough (about 16 units a worker, at most 64 points)
   !> to balance points of very different cost.
   pure integer function points_unit_size(self, n_workers) result(size)
      class(system_points_task_t), intent(in) :: self  !! the task
      integer, intent(in) :: n_workers   !! processes computing units
      size = max(1, min(64, int(self%point_count())/(16*max(1, n_workers))))
   end function points_unit_size

   !> The lines of the points `first` … `last` (a binary file: their records' bytes), each
   !> computed alone, as `points_run` computes them.
   subroutine points_unit_text(self, scene, unit, first, last, text, statuses)
      class(system_points_task_t), intent(in) :: self  !! the task, its units prepared
      type(scene_t), intent(in) :: scene  !! its scene
      integer, intent(in) :: unit  !! the unit
      integer(int64), intent(in) :: first, last  !! its points
      character(len=:), allocatable, intent(out) :: text  !! the lines, no final new line
      integer, intent(out) :: statuses(first:last)  !! per point
      character(len=(n_fixed + max_dof_columns)*26) :: line
      character(len=(n_fixed + max_dof_columns)*26), allocatable :: lines(:)
      character(len=:), allocatable :: message
      real(wp) :: v(n_fixed + self%form%n)
      real(wp), allocatable :: records(:, :)
      integer :: lengths(first:last)
      integer(int64) :: k
      logical :: failed
      allocate (lines(first:last), records(size(self%chosen), first:last))
      do k = first, last
         call system_values(scene%system, self%form, system_method_t(scene%method%kind, scene%method%tolerance), &
                            self%points(1, k), self%points(2, k), v, failed, message)
         statuses(k) = nint(v(status_column(self%form%n)))
         if (scene%binary) then
            records(:, k) = v(self%chosen)
         else
            call point_line(self%table, self%chosen, v, line, lengths(k))
            lines(k) = line(:lengths(k))
         end if
      end do
      if (scene%binary) then
         call record_bytes(records, text)
      else
         call join_lines(lines, .false., text, lengths=lengths)
      end if
   end subroutine points_unit_text

   !> The checks and the header of `points_run`.
   subroutine points_open_units(self, scene, file, error)
      class(system_points_task_t), intent(in) :: self  !! the task, its units prepared
      type(scene_t), intent(in) :: scene  !! its scene
      type(output_file_t), intent(inout) :: file  !! the open output file
      type(error_t), allocatable, intent(out) :: error  !! why the file cannot be written
      if (len(self%form_error) > 0) then
         call fail(error, scene%source, "system", "mass", self%form_error)
         return
      end if
      call write_header(file, system_lines(scene, "Floquet analysis at points", self%chosen), &
                        chosen_names(scene%system, self%chosen), error, names_line=scene%names_line, &
                        records=[size(self%points, 2), 1])
   end subroutine points_open_units

   !> (α, β) of point k.
   pure function points_point_of(self, scene, k) result(point)
      class(system_points_task_t), intent(in) :: self  !! the task
      type(scene_t), intent(in) :: scene  !! its scene
      integer(int64), intent(in) :: k  !! the point
      real(wp) :: point(2)
      point = self%points(:, k)
   end function points_point_of

   !> What every unit shares: the prepared system (or why it cannot be prepared).
   subroutine system_prepare_units(self, scene)
      class(system_floquet_task_t), intent(inout) :: self  !! the task
      type(scene_t), intent(in) :: scene  !! its scene
      type(error_t), allocatable :: cause
      call prepare_system(scene%system, scene%epsilon, self%form, cause)
      self%form_error = ""
      if (allocated(cause)) self%form_error = cause%message
   end subroutine system_prepare_units

   !> After a run in units, as after `chart_run` and `points_run`: round-off limited points
   !> warned about, failed ones an error naming the first (computed again for its message).
   subroutine system_finish_units(self, scene, n_points, n_failed, first_failed, n_inaccurate, first_inaccurate, &
                                  error)
      class(system_floquet_task_t), intent(in) :: self  !! the task, its units prepared
      type(scene_t), intent(in) :: scene  !! its scene
      integer(int64), intent(in) :: n_points  !! all points
      integer(int64), intent(in) :: n_failed  !! failed points written
      real(wp), intent(in) :: first_failed(2)  !! (α, β) of the first of them
      integer(int64), intent(in) :: n_inaccurate  !! round-off limited points written
      real(wp), intent(in) :: first_inaccurate(2)  !! (α, β) of the first of them
      type(error_t), allocatable, intent(out) :: error  !! err_points_failed when points failed
      character(len=:), allocatable :: message
      character(len=400) :: place
      real(wp) :: v(n_fixed + self%form%n)
      logical :: failed
      integer :: k
      call warn_roundoff(scene, n_inaccurate, first_inaccurate)
      if (n_failed == 0) return
      call system_values(scene%system, self%form, system_method_t(scene%method%kind, scene%method%tolerance), &
                         first_failed(1), first_failed(2), v, failed, message)
      select type (self)
      type is (system_points_task_t)
         k = findloc(self%points(1, :) == first_failed(1) .and. self%points(2, :) == first_failed(2), .true., dim=1)
         place = "point "//integer_text(k)//" of "//self%path//": "//message
      class default
         call failure_text(first_failed(1), first_failed(2), message, place)
      end select
      call set_error(error, err_points_failed, scene%source//": "//integer_text(n_failed)//" of "// &
         integer_text(n_points)//" points failed (status 2); the first: "//trim(place))
   end subroutine system_finish_units

   !> Say on stderr (even when quiet: it qualifies the results) how many points reached only
   !> the round-off level of double precision (status 1), not the tolerance.
   subroutine warn_roundoff(scene, n, first)
      type(scene_t), intent(in) :: scene  !! the scene
      integer(int64), intent(in) :: n  !! points of status 1
      real(wp), intent(in) :: first(2)  !! (α, β) of the first of them
      if (n == 0) return
      write (error_unit, '(a)') "hillstab: warning: "//scene%source//": "//integer_text(n)// &
         " point(s) reached only the round-off level of double precision, not the tolerance "// &
         real_text(scene%method%tolerance)//" (first at alpha = "//real_text(first(1))//", beta = "// &
         real_text(first(2))//"); their status is 1"
   end subroutine warn_roundoff

end module hillstab_batch_tasks_system

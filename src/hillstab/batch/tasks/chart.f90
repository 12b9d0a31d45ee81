!> Task `chart`: the columns of hillstab_batch_tasks_chart_columns over the (α, β) grid of
!> `&chart`, row by row (one α a row): the task's units (`unit_text`), which the driver of
!> hillstab_batch_run_units computes on OpenMP threads (many rows: rows in parallel,
!> dynamic schedule, the cost varies strongly near α → π²) or over MPI ranks and writes in
!> order, as text or binary records. With few rows, each row is split into chunks computed
!> in parallel that share the meshes method auto prepares for the row. A point that cannot
!> be computed does not stop the chart: its row carries status 2 and placeholders, and the
!> run ends with err_points_failed after the file is written. A chart over `&physical`
!> amplitudes and frequencies runs in units too, one amplitude a row (`physical_row`).
module hillstab_batch_tasks_chart
   use hillstab_core_kinds, only: wp, int64, pi
   use hillstab_core_error, only: error_t
   use hillstab_core_status, only: status_ok, status_roundoff, status_failed
   use hillstab_core_text, only: format_es, integer_text
   use hillstab_hill_coefficient, only: in_physical_domain
   use hillstab_hill_transfer, only: trace_t
   use hillstab_hill_floquet, only: floquet_t, set_from_trace, period_damping
   use hillstab_integrate_monodromy, only: monodromy_trace_batch, batch_plan_t, prepare_batch, need_verdict
   use hillstab_batch_scene_types, only: scene_t
   use hillstab_batch_scene_physical, only: grid_pendulum, physical_scene_t
   use hillstab_batch_scene_declaration, only: group_t
   use hillstab_batch_scene_file, only: scene_file_t, fail, group_present
   use hillstab_batch_scene_checks, only: check_integration_cost, max_grid_count
   use hillstab_hill_units, only: physical_t, physical_beta, physical_epsilon
   use hillstab_hill_model, only: hill_point_t
   use hillstab_hill_model_pendulum, only: pendulum_alpha
   use hillstab_batch_scene_group_chart, only: chart_grid_t, chart_group, read_chart_group, grid_alpha, grid_beta, grid_point, &
      grid_size_text
   use hillstab_batch_tasks_chart_columns, only: floquet_task_t, n_chart_columns, chart_values, failed_values, &
      chart_line, chart_header, chart_layout_t, chart_names, point_amplitude, tau_per_time, verdict_lines, scene_chart_columns, &
      check_method_runs, chart_line_length, evaluate_point, header_bytes, text_row_bytes, binary_row_bytes, &
      col_physical, col_mu_per_s
   use hillstab_batch_tasks_regions, only: chart_region_lines
   use hillstab_batch_output_file, only: output_file_t, write_header, record_bytes, join_lines
   use hillstab_core_parallel, only: max_threads
   implicit none
   private
   public :: chart_task_t, chart_task

   !> The chart task and its grid.
   type, extends(floquet_task_t) :: chart_task_t
      type(chart_grid_t) :: grid                     !! `&chart`
      !> what every row shares, made by `prepare_units`: the β values, their text, the columns
      real(wp), allocatable :: betas(:)
      character(len=24), allocatable :: beta_texts(:)  !! format_es(betas, 17)
      type(chart_layout_t) :: columns                !! the columns written
      !> `&physical a_min, a_max, n_a, omega_min, omega_max, n_omega` without `&chart`: the
      !> chart runs over (a, ω) at fixed r0, g (blocks of constant a)
      logical :: physical_grid = .false.
   contains
      procedure :: read => chart_read
      procedure :: declarations => chart_declarations
      procedure :: estimated_bytes => chart_estimated_bytes
      procedure :: memory_bytes => chart_memory_bytes
      procedure :: size_variables => chart_size_variables
      procedure :: point_count => chart_point_count
      procedure :: unit_size => chart_unit_size
      procedure :: prepare_units => chart_prepare_units
      procedure :: unit_text => chart_unit_text
      procedure :: open_units => chart_open_units
      procedure :: point_of => chart_point_of
   end type chart_task_t

contains

   !> `&chart`.
   function chart_declarations(self) result(groups)
      class(chart_task_t), intent(in) :: self  !! the task
      type(group_t), allocatable :: groups(:)
      if (self%physical_grid) then
         allocate (groups(0))
      else
         allocate (groups(1))
         groups(1) = chart_group()
      end if
   end function chart_declarations

   !> The variables that set the size of the file.
   function chart_size_variables(self) result(text)
      class(chart_task_t), intent(in) :: self  !! the task
      character(len=:), allocatable :: text
      text = grid_size_text(self%grid, self%physical_grid)
   end function chart_size_variables

   !> A chart task before its scene is read.
   function chart_task() result(task)
      type(chart_task_t) :: task
      task%name = "chart"
      task%takes_columns = .true.
      task%physical_use%takes_omega_range = .true.
   end function chart_task

   !> `&chart`, and what the scene's method and columns allow.
   subroutine chart_read(self, file, scene, error)
      class(chart_task_t), intent(inout) :: self  !! the task, its grid filled in
      type(scene_file_t), intent(in) :: file      !! the scene file
      type(scene_t), intent(in) :: scene          !! the `&scene` settings
      type(error_t), allocatable, intent(out) :: error  !! err_input naming file, group and variable
      type(chart_layout_t) :: columns
      if (size(self%physical%omegas) > 0) then
         ! a chart over (a, omega): the grid comes from &physical
         if (group_present(file%unit, "chart")) then
            call fail(error, file%path, "chart", "alpha_min", "the chart runs either over &chart (alpha, beta) or "// &
               "over &physical a_min, a_max, n_a and omega_min, omega_max, n_omega, not both")
            return
         end if
         self%physical_grid = .true.
         allocate (self%groups(0))
         self%grid%n_alpha = size(self%physical%amplitudes)
         self%grid%n_beta = size(self%physical%omegas)
         if (int(self%grid%n_alpha, int64)*self%grid%n_beta > int(max_grid_count, int64)) then
            call fail(error, file%path, "physical", "n_omega", "n_a * n_omega = "// &
               integer_text(int(self%grid%n_alpha, int64)*self%grid%n_beta)//" points exceed the limit of 1e8")
            return
         end if
         call scene_chart_columns(scene, self%physical, columns, error)
         return
      end if
      allocate (self%groups(1))
      call read_chart_group(file, chart_group(), scene%model, self%grid, self%groups(1), error)
      if (allocated(error)) return
      call check_integration_cost(scene%source, "chart", "alpha_max", scene%method, &
         max(abs(self%grid%alpha_min), abs(self%grid%alpha_max)) + &
         max(abs(self%grid%beta_min), abs(self%grid%beta_max)), error)
      if (allocated(error)) return
      call scene_chart_columns(scene, self%physical, columns, error)
   end subroutine chart_read

   !> Header plus n_alpha n_beta rows (and one blank line per α block).
   pure function chart_estimated_bytes(self, scene) result(bytes)
      class(chart_task_t), intent(in) :: self  !! the task
      type(scene_t), intent(in) :: scene  !! its scene
      integer(int64) :: bytes
      bytes = header_bytes + int(self%grid%n_alpha, int64)*int(self%grid%n_beta, int64)* &
              merge(binary_row_bytes, text_row_bytes, scene%binary) + int(self%grid%n_alpha, int64)
   end function chart_estimated_bytes

   !> The rows the unit driver holds at once (16 a thread when rows go in parallel, else one),
   !> each n_beta lines, statuses and values and the row's text joined for the writer, the
   !> β texts, and each thread's work on a row (auto's batch: its meshes and lanes, 64 bytes
   !> a point). Measured peaks: 265 MB for 1 x 500000 points (estimate 333 MB), 147 MB for
   !> 64 x 20000 on two threads (estimate 328 MB).
   function chart_memory_bytes(self, scene) result(bytes)
      class(chart_task_t), intent(in) :: self  !! the task
      type(scene_t), intent(in) :: scene  !! its scene
      integer(int64) :: bytes
      integer(int64) :: rows, per_point
      rows = 1
      if (rows_in_parallel(self%grid)) rows = 2*8*max_threads()
      per_point = 2*chart_line_length + 4 + 8*n_chart_columns
      bytes = int(self%grid%n_beta, int64)*(rows*per_point + 31 + 64*max_threads())
   end function chart_memory_bytes

   !> Row `unit` of a chart over `&physical` amplitudes and frequencies (one amplitude a, every
   !> ω; blocks of constant a): each point's α, β and ε from the pendulum, its line (a blank
   !> line before every row but the first) or its records, the points in parallel.
   subroutine physical_row(self, scene, unit, text, statuses)
      class(chart_task_t), intent(in) :: self  !! the task (a chart over `&physical`), its units prepared
      type(scene_t), intent(in) :: scene  !! its scene
      integer, intent(in) :: unit  !! the row: the amplitude `self%physical%amplitudes(unit)`
      character(len=:), allocatable, intent(out) :: text  !! the lines, no final new line (or records)
      integer, intent(out) :: statuses(:)  !! per point
      character(len=chart_line_length), allocatable :: lines(:)
      integer, allocatable :: lengths(:)
      real(wp), allocatable :: values(:, :)
      type(floquet_t) :: f
      type(error_t), allocatable :: cause
      type(physical_t) :: p
      real(wp) :: v(n_chart_columns), alpha, beta, epsilon
      integer :: j, n_omega
      integer :: ids(size(self%columns%ids))  ! the binary records' columns (a gather, `columns` allocated)
      ids = self%columns%ids
      n_omega = size(self%physical%omegas)
      ! a text file fills lines, a binary one records
      if (scene%binary) then
         allocate (lines(0), lengths(0), values(size(ids), n_omega))
      else
         allocate (lines(n_omega), lengths(n_omega), values(0, 0))
      end if
      !$omp parallel do schedule(dynamic) default(shared) private(j, p, f, cause, v, epsilon, alpha, beta)
      do j = 1, n_omega
         p = grid_pendulum(self%physical, unit, j)
         alpha = pendulum_alpha(scene%model, p)
         beta = physical_beta(p)
         epsilon = physical_epsilon(p)
         call evaluate_point(scene, alpha, beta, f, cause, statuses(j), epsilon, self%columns)
         if (statuses(j) == status_failed) then
            v = failed_values(self%columns, alpha, beta, in_physical_domain(alpha, beta), p%a, p%omega)
         else
            v = chart_values(alpha, beta, f, in_physical_domain(alpha, beta), statuses(j), p%omega/pi, p%a, p%omega)
         end if
         if (scene%binary) then
            values(:, j) = v(ids)
         else
            call chart_line(self%columns, v, lines(j), length=lengths(j))
         end if
      end do
      !$omp end parallel do
      call row_unit(scene%binary, values, lines, lengths, unit > 1, text)
   end subroutine physical_row

   !> Whether the grid leaves the physical domain.
   pure logical function outside(grid)
      type(chart_grid_t), intent(in) :: grid
      outside = .not. (in_physical_domain(grid%alpha_min, grid%beta_min) .and. &
                       in_physical_domain(grid%alpha_max, grid%beta_max))
   end function outside

   !> Text lines or binary records (and statuses) of the chart points (α, β_j) of one row
   !> or part of a row, with the file's columns.
   subroutine compute_row(scene, physical, columns, alpha, betas, lines, lengths, values, statuses, plan, beta_texts)
      type(scene_t), intent(in) :: scene
      type(physical_scene_t), intent(in) :: physical  !! the task's `&physical`
      type(chart_layout_t), intent(in) :: columns  !! the columns (hillstab_batch_tasks_chart_columns)
      real(wp), intent(in) :: alpha, betas(:)
      character(len=chart_line_length), intent(inout) :: lines(:)  !! text format: one line a point
      integer, intent(out) :: lengths(:)           !! text format: the length of each line
      real(wp), intent(inout) :: values(:, :)      !! binary format: (columns, points)
      !> status_ok, status_roundoff (computed only to the round-off level) or status_failed
      integer, intent(out) :: statuses(:)
      type(batch_plan_t), intent(in), optional :: plan  !! prepared for the whole row
      character(len=24), intent(in), optional :: beta_texts(:)  !! format_es(betas, 17), made once per chart
      type(trace_t) :: traces(size(betas))
      character(len=24) :: alpha_text
      type(error_t), allocatable :: cause
      type(floquet_t) :: f
      type(hill_point_t) :: row
      real(wp) :: v(n_chart_columns), per_second, a, damping, dampings(size(betas))
      logical :: failed(size(betas)), inaccurate(size(betas)), per_time
      integer :: j, need
      integer :: ids(size(columns%ids))  ! the binary records' columns (a gather through `columns` allocated)
      ids = columns%ids
      need = columns%need
      ! dτ/dt turns a rate per unit τ into one per unit of the user's time (the column mu_per_s)
      per_time = any(ids == col_mu_per_s)
      damping = scene%model%point_damping(alpha, scene%epsilon)
      row = hill_point_t(alpha, 0.0_wp, damping)
      call monodromy_trace_batch(scene%model, row, betas, scene%method, traces, failed, cause, plan=plan, inaccurate=inaccurate, &
                                 need=need, paper=columns%paper, dampings=dampings)
      alpha_text = format_es(alpha, 17)
      statuses = merge(status_roundoff, status_ok, inaccurate)
      where (failed) statuses = status_failed
      do j = 1, size(betas)
         a = 0.0_wp
         if (physical%given) a = point_amplitude(physical, j, alpha, betas(j))
         if (need <= need_verdict .and. .not. scene%binary) then
            ! a verdict line (or a failed point's), written directly
            lengths(j) = 0
            if (present(beta_texts)) then
               call verdict_lines(columns, alpha, betas(j:j), traces(j:j), period_damping(dampings(j:j), &
                                  scene%model%period()), scene%method%tolerance, &
                                  statuses(j:j), [in_physical_domain(alpha, betas(j))], [a], alpha_text, lines(j), &
                                  lengths(j), beta_texts(j:j))
            else
               call verdict_lines(columns, alpha, betas(j:j), traces(j:j), period_damping(dampings(j:j), &
                                  scene%model%period()), scene%method%tolerance, &
                                  statuses(j:j), [in_physical_domain(alpha, betas(j))], [a], alpha_text, lines(j), &
                                  lengths(j))
            end if
            cycle
         end if
         if (failed(j)) then
            v = failed_values(columns, alpha, betas(j), in_physical_domain(alpha, betas(j)), a)
         else
            ! verdicts only: no multipliers (their columns, not in a verdict file, stay 0)
            call set_from_trace(f, traces(j), dampings(j), scene%method%tolerance, scene%model%period(), &
                                need <= need_verdict)
            per_second = 0.0_wp
            if (per_time) per_second = tau_per_time(scene, physical, alpha, betas(j))
            v = chart_values(alpha, betas(j), f, in_physical_domain(alpha, betas(j)), statuses(j), per_second, a, &
                             need=need)
         end if
         if (scene%binary) then
            values(:, j) = v(ids)
         else if (present(beta_texts)) then
            call chart_line(columns, v, lines(j), alpha_text, beta_texts(j), lengths(j))
         else
            call chart_line(columns, v, lines(j), alpha_text, length=lengths(j))
         end if
      end do
   end subroutine compute_row

   !> A chart computes whole rows in parallel when it has enough of them, else the
   !> chunks of each row in parallel.
   logical function rows_in_parallel(grid)
      type(chart_grid_t), intent(in) :: grid
      rows_in_parallel = grid%n_alpha >= 4*max_threads()
   end function rows_in_parallel

   !> `compute_row` on a whole row, split into chunks computed in parallel that share
   !> the meshes prepared for the row.
   subroutine compute_row_in_chunks(scene, physical, columns, alpha, betas, lines, lengths, values, statuses, beta_texts)
      type(scene_t), intent(in) :: scene
      type(physical_scene_t), intent(in) :: physical  !! the task's `&physical`
      type(chart_layout_t), intent(in) :: columns  !! the columns
      real(wp), intent(in) :: alpha, betas(:)
      character(len=chart_line_length), intent(inout) :: lines(:)  !! text format: one line a point
      integer, intent(out) :: lengths(:)           !! text format: the length of each line
      real(wp), intent(inout) :: values(:, :)      !! binary format: (columns, points)
      integer, intent(out) :: statuses(:)
      character(len=24), intent(in) :: beta_texts(:)
      type(batch_plan_t) :: plan
      integer :: c, chunk, n_chunks, first, last, n
      n = size(betas)
      chunk = max(16, n/(8*max_threads()))
      n_chunks = (n + chunk - 1)/chunk
      call prepare_batch(scene%model, hill_point_t(alpha, 0.0_wp, scene%model%point_damping(alpha, scene%epsilon)), &
                         betas, scene%method, plan, &
                         columns%need)
      !$omp parallel do schedule(dynamic) default(shared) private(c, first, last)
      do c = 1, n_chunks
         first = (c - 1)*chunk + 1
         last = min(n, c*chunk)
         call compute_row(scene, physical, columns, alpha, betas(first:last), lines(first:last), lengths(first:last), &
            values(:, first:last), statuses(first:last), plan, beta_texts(first:last))
      end do
      !$omp end parallel do
   end subroutine compute_row_in_chunks

   !> The β values of a chart's rows and their text, made once per chart.
   subroutine chart_betas(grid, betas, beta_texts)
      type(chart_grid_t), intent(in) :: grid  !! the grid
      real(wp), allocatable, intent(out) :: betas(:)  !! the n_beta grid values
      character(len=24), allocatable, intent(out) :: beta_texts(:)  !! format_es(betas, 17)
      integer :: j
      betas = [(grid_beta(grid, j), j=1, grid%n_beta)]
      allocate (beta_texts(grid%n_beta))
      do j = 1, grid%n_beta
         beta_texts(j) = format_es(betas(j), 17)
      end do
   end subroutine chart_betas

   !> Points of the chart.
   pure function chart_point_count(self) result(n)
      class(chart_task_t), intent(in) :: self  !! the task
      integer(int64) :: n
      n = int(self%grid%n_alpha, int64)*self%grid%n_beta
   end function chart_point_count

   !> One row a unit.
   pure integer function chart_unit_size(self, n_workers) result(size)
      class(chart_task_t), intent(in) :: self  !! the task
      integer, intent(in) :: n_workers   !! processes computing units
      size = self%grid%n_beta
   end function chart_unit_size

   !> The β values, their text and the columns, shared by every row.
   subroutine chart_prepare_units(self, scene)
      class(chart_task_t), intent(inout) :: self  !! the task
      type(scene_t), intent(in) :: scene    !! its scene
      type(error_t), allocatable :: error
      call chart_betas(self%grid, self%betas, self%beta_texts)
      call scene_chart_columns(scene, self%physical, self%columns, error)  ! checked when the scene was read
   end subroutine chart_prepare_units

   !> Row `unit` as the file holds it (a blank line before every row but the first; a binary
   !> file: its records' bytes), computed as `chart_run` computes it.
   subroutine chart_unit_text(self, scene, unit, first, last, text, statuses)
      class(chart_task_t), intent(in) :: self  !! the task, its units prepared
      type(scene_t), intent(in) :: scene  !! its scene
      integer, intent(in) :: unit  !! the row
      integer(int64), intent(in) :: first, last  !! its points
      character(len=:), allocatable, intent(out) :: text  !! the lines, no final new line
      integer, intent(out) :: statuses(first:last)  !! per point
      character(len=chart_line_length), allocatable :: lines(:)
      integer, allocatable :: lengths(:)
      real(wp), allocatable :: values(:, :)
      real(wp) :: alpha
      if (self%physical_grid) then
         call physical_row(self, scene, unit, text, statuses)
         return
      end if
      alpha = grid_alpha(self%grid, unit)
      if (rows_in_parallel(self%grid) .and. self%columns%need <= need_verdict .and. .not. scene%binary) then
         call verdict_row_text(scene, self%physical, self%columns, alpha, self%betas, self%beta_texts, unit > 1, text, &
                               statuses)
         return
      end if
      allocate (lines(self%grid%n_beta), lengths(self%grid%n_beta), values(size(self%columns%ids), self%grid%n_beta))
      if (rows_in_parallel(self%grid)) then
         call compute_row(scene, self%physical, self%columns, alpha, self%betas, lines, lengths, values, statuses, &
                          beta_texts=self%beta_texts)
      else
         call compute_row_in_chunks(scene, self%physical, self%columns, alpha, self%betas, lines, lengths, values, &
                                    statuses, self%beta_texts)
      end if
      call row_unit(scene%binary, values, lines, lengths, unit > 1, text)
   end subroutine chart_unit_text

   !> The text of a row of a verdict file (columns that need no more than the verdict), as
   !> `compute_row` and `join_lines` make it, written straight into the unit's text: no
   !> array of lines, the physical domain tested only for a `physical` column (the verdict
   !> charts spent a fifth of their time between the traces and the text).
   subroutine verdict_row_text(scene, physical, columns, alpha, betas, beta_texts, separate, text, statuses)
      type(scene_t), intent(in) :: scene  !! the chart's scene (text format)
      type(physical_scene_t), intent(in) :: physical  !! the task's `&physical`
      type(chart_layout_t), intent(in) :: columns  !! the columns, none needing more than the verdict
      real(wp), intent(in) :: alpha, betas(:)  !! the row
      character(len=24), intent(in) :: beta_texts(:)  !! format_es(betas, 17)
      logical, intent(in) :: separate  !! a blank line before the row
      character(len=:), allocatable, intent(out) :: text  !! the lines, no final new line
      integer, intent(out) :: statuses(:)  !! per point
      type(trace_t) :: traces(size(betas))
      logical :: failed(size(betas)), inaccurate(size(betas))
      logical, allocatable :: in_domain(:)
      real(wp), allocatable :: amplitudes(:)
      type(error_t), allocatable :: cause
      character(len=:), allocatable :: buffer
      integer :: j, pos
      real(wp) :: dampings(size(betas))
      call monodromy_trace_batch(scene%model, hill_point_t(alpha, 0.0_wp, scene%model%point_damping(alpha, &
                                 scene%epsilon)), betas, scene%method, traces, failed, cause, inaccurate=inaccurate, &
                                 need=columns%need, paper=columns%paper, dampings=dampings)
      statuses = merge(status_roundoff, status_ok, inaccurate)
      where (failed) statuses = status_failed
      allocate (in_domain(0), amplitudes(0))
      if (any(columns%ids == col_physical)) in_domain = [(in_physical_domain(alpha, betas(j)), j=1, size(betas))]
      if (physical%given) amplitudes = [(point_amplitude(physical, j, alpha, betas(j)), j=1, size(betas))]
      ! room for every line at its longest (and one more, for the line being written)
      allocate (character(len=(size(betas) + 1)*(chart_line_length + 1) + 1) :: buffer)
      pos = 0
      if (separate) then
         buffer(1:1) = new_line("a")
         pos = 1
      end if
      call verdict_lines(columns, alpha, betas, traces, period_damping(dampings, scene%model%period()), &
                         scene%method%tolerance, statuses, in_domain, &
                         amplitudes, format_es(alpha, 17), buffer, pos, beta_texts)
      text = buffer(1:pos)
   end subroutine verdict_row_text

   !> The checks and the header of `chart_run`.
   subroutine chart_open_units(self, scene, file, error)
      class(chart_task_t), intent(in) :: self  !! the task
      type(scene_t), intent(in) :: scene  !! its scene
      type(output_file_t), intent(inout) :: file  !! the open output file
      type(error_t), allocatable, intent(out) :: error  !! why the file cannot be written
      type(chart_layout_t) :: columns
      call scene_chart_columns(scene, self%physical, columns, error)
      if (allocated(error)) return
      if (self%physical_grid) then
         call write_header(file, chart_header(scene, self%physical, .false., columns), chart_names(columns), error, &
                           names_line=scene%names_line, records=[self%grid%n_beta, self%grid%n_alpha])
         return
      end if
      call check_method_runs(scene, self%grid%alpha_min, self%grid%beta_min, error)
      if (allocated(error)) return
      call write_header(file, chart_header(scene, self%physical, outside(self%grid), columns, &
                                                chart_region_lines(scene, self%grid)), &
                        chart_names(columns), error, names_line=scene%names_line, &
                        records=[self%grid%n_beta, self%grid%n_alpha])
   end subroutine chart_open_units

   !> A row as its unit's text: its records' bytes (binary) or its lines joined (a blank line
   !> before them when `separate`).
   pure subroutine row_unit(binary, values, lines, lengths, separate, text)
      logical, intent(in) :: binary  !! the file is binary
      real(wp), intent(in) :: values(:, :)  !! binary: the records (columns, points)
      character(len=*), intent(in) :: lines(:)  !! text: a line a point
      integer, intent(in) :: lengths(:)  !! text: their lengths
      logical, intent(in) :: separate  !! text: a blank line first (every row but the first)
      character(len=:), allocatable, intent(out) :: text  !! the unit's text or bytes
      if (binary) then
         call record_bytes(values, text)
      else
         call join_lines(lines, separate, text, lengths=lengths)
      end if
   end subroutine row_unit

   !> (α, β) of point k, numbered row by row (over `&physical`: the pendulum's at the row's
   !> amplitude and the point's ω).
   pure function chart_point_of(self, scene, k) result(point)
      class(chart_task_t), intent(in) :: self  !! the task
      type(scene_t), intent(in) :: scene  !! its scene
      integer(int64), intent(in) :: k  !! the point
      real(wp) :: point(2)
      type(physical_t) :: p
      if (self%physical_grid) then
         p = grid_pendulum(self%physical, int((k - 1)/self%grid%n_beta) + 1, &
                           int(mod(k - 1, int(self%grid%n_beta, int64))) + 1)
         point = [pendulum_alpha(scene%model, p), physical_beta(p)]
      else
         point = grid_point(self%grid, k)
      end if
   end function chart_point_of
end module hillstab_batch_tasks_chart

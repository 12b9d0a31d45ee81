!> Task runners: scene → monodromy/Floquet → output file.
!>
!> - chart: the (α, β) grid row by row (one α a row); the β values of a row run in
!>   parallel (OpenMP, dynamic schedule: the cost varies strongly near α → π²),
!>   then the row is written in order and forgotten, so memory stays at one row;
!> - points: the same columns at the (α, β) points of a file, in file order;
!> - coefficient: Q(τ) and its segmented version for a list of α (the paper's Fig. 2).
!>
!> Each task computes only what its file holds. Errors come back in `error` with
!> the scene file, group and variable named; no output file is created or touched
!> unless the task completes. A point that cannot be computed does not stop a chart
!> or points task: its row carries status_failed (hillstab_core_status) and placeholders,
!> the file is written, and `error` comes back with err_points_failed.
!>
!>```fortran
!> type(error_t), allocatable :: error
!> call run_scene_file("data/scenes/default_exact.nml", quiet=.false., error=error)
!>```
module hillstab_batch_tasks
   use hillstab_core_kinds, only: wp, int64, pi, pi2, version_string
   use hillstab_core_error, only: error_t, set_error, err_input, err_accuracy, err_invalid_parameter, &
      err_points_failed
   use hillstab_core_status, only: status_ok, status_roundoff, status_failed
   use hillstab_hill_coefficient, only: hill_model_t, model_elastic, model_mathieu, hill_coefficient, &
      segment_coefficients, hill_period, in_physical_domain, sampling_name
   use hillstab_hill_transfer, only: trace_t
   use hillstab_hill_floquet, only: floquet_t, floquet_from_trace
   use hillstab_hill_units, only: equilibrium_length
   use hillstab_integrate_monodromy, only: monodromy_trace, monodromy_trace_batch, method_name, method_segments, &
      batch_plan_t, prepare_batch
   use hillstab_batch_task_series, only: run_series
   use hillstab_batch_task_lyapunov, only: run_lyapunov
   use hillstab_batch_task_poincare, only: run_poincare
   use hillstab_batch_scene, only: scene_t, read_scene, scene_header, task_chart, task_points, task_coefficient, &
      task_series, task_name, grid_value, real_text, integer_text, task_boundaries, task_lyapunov, task_poincare, &
      output_path, scene_columns
   use hillstab_batch_task_boundaries, only: run_boundaries
   use hillstab_core_text, only: format_es
   use hillstab_batch_output, only: output_file_t, open_output, finish_output, discard_output, write_header, &
      write_text, write_records, chart_line_length, real_columns, n_chart_columns, chart_values, failed_chart_values, &
      chart_text, chart_columns_text, default_chart_columns, joined_lines
   use hillstab_batch_limits, only: check_output_room
   use, intrinsic :: iso_fortran_env, only: error_unit
   use, intrinsic :: iso_c_binding, only: c_int
   !$ use omp_lib, only: omp_get_max_threads
   implicit none
   private
   public :: run_scene_file, run_scene, output_path
   ! the pieces a distributed driver (hillstab_batch_units, the MPI program) shares with the serial tasks
   public :: scene_columns, chart_betas, chart_row, compute_points, chart_header, open_scene_output, check_method_runs, &
      warn_inaccurate, &
      failed_points_error, progress_t, progress_begin, progress_update, progress_end

   !> Progress on stderr for runs longer than about a second.
   type :: progress_t
      logical :: enabled = .false.      !! not quiet
      logical :: shown = .false.        !! something has been printed
      logical :: terminal = .false.     !! stderr is a terminal: redraw one line
      integer(int64) :: total = 0       !! points to compute
      integer(int64) :: start = 0       !! clock at the start
      integer(int64) :: last = 0        !! clock at the last report
      integer(int64) :: ticks = 1       !! clock ticks per second
   end type progress_t

   interface
      function c_isatty(fd) bind(C, name="isatty") result(yes)
         import :: c_int
         integer(c_int), value :: fd
         integer(c_int) :: yes
      end function c_isatty
   end interface

contains

   !> Read the scene file `path` and run it.
   subroutine run_scene_file(path, quiet, error, written)
      character(len=*), intent(in) :: path  !! scene file (a previous output file also works)
      logical, intent(in) :: quiet          !! no progress on stderr
      type(error_t), allocatable, intent(out) :: error  !! what failed (err_points_failed: written with failed points)
      character(len=:), allocatable, intent(out), optional :: written  !! the file written
      type(scene_t) :: scene
      call read_scene(path, scene, error)
      if (allocated(error)) return
      call run_scene(scene, quiet, error)
      if (allocated(error)) then
         if (error%code /= err_points_failed) return
      end if
      if (present(written)) written = output_path(scene)
   end subroutine run_scene_file

   !> Run a validated scene.
   subroutine run_scene(scene, quiet, error)
      type(scene_t), intent(in) :: scene  !! a validated scene
      logical, intent(in) :: quiet  !! no progress on stderr
      type(error_t), allocatable, intent(out) :: error  !! what failed (err_points_failed: written with failed points)
      ! an output that cannot fit where it goes is refused before any work
      call check_output_room(scene, output_path(scene), error)
      if (allocated(error)) return
      select case (scene%task)
      case (task_chart)
         call run_chart(scene, quiet, error)
      case (task_points)
         call run_points(scene, quiet, error)
      case (task_coefficient)
         call run_coefficient(scene, error)
      case (task_boundaries)
         call run_boundaries(scene, quiet, error)
      case (task_series)
         call run_series(scene, error)
      case (task_lyapunov)
         call run_lyapunov(scene, quiet, error)
      case (task_poincare)
         call run_poincare(scene, quiet, error)
      case default
         call set_error(error, err_input, scene%source//": &scene: task: task '"//task_name(scene%task)// &
            "' is not available in this build")
      end select
   end subroutine run_scene

   !> Floquet data of one point; `error` only when the point failed.
   subroutine evaluate_point(scene, alpha, beta, f, error, status)
      type(scene_t), intent(in) :: scene
      real(wp), intent(in) :: alpha, beta
      type(floquet_t), intent(out) :: f
      type(error_t), allocatable, intent(out) :: error
      !> status_ok, status_roundoff (computed, but only to the round-off level) or status_failed
      integer, intent(out), optional :: status
      type(trace_t) :: tr
      if (present(status)) status = status_ok
      call monodromy_trace(hill_model_t(scene%model, alpha, beta, scene%epsilon), scene%method, tr, error)
      if (allocated(error)) then
         if (error%code /= err_accuracy) then
            if (present(status)) status = status_failed
            return
         end if
         deallocate (error)
         if (present(status)) status = status_roundoff
      end if
      f = floquet_from_trace(tr, scene%epsilon, scene%method%tolerance)
   end subroutine evaluate_point

   !> Count the failed points of a task and name the first: err_points_failed, after the
   !> file has been written. The first failure is computed again serially, so the message
   !> does not depend on thread timing.
   subroutine failed_points_error(scene, n_failed, n_total, first, error)
      type(scene_t), intent(in) :: scene  !! a validated scene
      integer(int64), intent(in) :: n_failed, n_total  !! failed points; all points
      real(wp), intent(in) :: first(2)  !! alpha, beta of the first failed point
      type(error_t), allocatable, intent(out) :: error  !! err_points_failed naming the count and the first point
      type(error_t), allocatable :: cause
      type(floquet_t) :: f
      if (n_failed == 0) return
      call evaluate_point(scene, first(1), first(2), f, cause)
      if (.not. allocated(cause)) call set_error(cause, err_input, "fails in parallel only")
      call set_error(error, err_points_failed, scene%source//": &scene: method: '"// &
         method_name(scene%method%kind)//"' failed at "//integer_text(n_failed)//" of "//integer_text(n_total)// &
         " point(s), written with status "//integer_text(status_failed)//" and placeholders to "//output_path(scene)// &
         "; first at alpha = "// &
         real_text(first(1))//", beta = "//real_text(first(2))//": "//cause%message)
   end subroutine failed_points_error

   !> The error of a failed point, naming the scene, the method and the point.
   subroutine point_error(scene, alpha, beta, cause, error)
      type(scene_t), intent(in) :: scene
      real(wp), intent(in) :: alpha, beta
      type(error_t), intent(in) :: cause
      type(error_t), allocatable, intent(out) :: error
      call set_error(error, cause%code, scene%source//": &scene: method: '"//method_name(scene%method%kind)// &
         "' fails at alpha = "//real_text(alpha)//", beta = "//real_text(beta)//": "//cause%message)
   end subroutine point_error

   !> Open the output file, reporting failure against `&scene output`.
   subroutine open_scene_output(scene, file, error)
      type(scene_t), intent(in) :: scene  !! a validated scene
      type(output_file_t), intent(out) :: file  !! the open temporary output file
      type(error_t), allocatable, intent(out) :: error  !! err_io naming &scene output
      call open_output(file, output_path(scene), error, binary=scene%binary, context=scene%source//": &scene: output: ")
   end subroutine open_scene_output

   !> Header lines common to every task: version, source, the effective scene, the model.
   function common_header(scene) result(lines)
      type(scene_t), intent(in) :: scene
      character(len=:), allocatable :: lines(:)
      character(len=:), allocatable :: model_text, common(:)
      if (scene%model == model_elastic) then
         model_text = "model: elastic, Q(tau) = (beta - alpha cos(pi tau))/(1 - (alpha/pi^2) cos(pi tau)), eq. (25)"
      else
         model_text = "model: mathieu, q(tau) = beta - alpha cos(pi tau), eq. (A1), alpha playing nu"
      end if
      common = scene_header(scene, "hillstab "//version_string//": x'' + Q(tau) x = 0, period 2 in tau", [model_text])
      if (scene%physical) then
         lines = stacked(common, physical_header(scene))
      else
         lines = common
      end if
   end function common_header

   !> Header lines of a scene given in physical units: the conversions used.
   function physical_header(scene) result(lines)
      type(scene_t), intent(in) :: scene
      character(len=:), allocatable :: lines(:)
      character(len=200) :: text(3)
      text(1) = "physical units (SI): rho = r0 + g/omega^2 (eq. (4)), tau = omega t/pi, alpha = a pi^2/rho, "// &
                "beta = g pi^2/(rho omega^2) (eq. (24)), epsilon = kappa pi/omega (eq. (46))"
      text(2) = "omega = "//real_text(scene%pendulum%omega)//" rad/s: one radial period 2 pi/omega = "// &
                real_text(2.0_wp*pi/scene%pendulum%omega)//" s is 2 units of tau; epsilon = "//real_text(scene%epsilon)
      if (size(scene%amplitudes) > 0) then
         text(3) = "rho = "//real_text(equilibrium_length(scene%pendulum))//" m; each row is one amplitude a of "// &
                   "&physical: a = alpha rho/pi^2"
         if (scene%model == model_mathieu) text(3) = trim(text(3))//" (here alpha is nu = a r0 pi^2/rho^2 of eq. (21))"
         lines = text(:3)
      else
         lines = text(:2)
      end if
   end function physical_header

   !> Header lines describing the chart/points columns.
   function chart_header(scene, outside) result(lines)
      type(scene_t), intent(in) :: scene  !! a validated scene
      logical, intent(in) :: outside  !! some point lies outside the physical domain
      character(len=:), allocatable :: lines(:)
      character(len=200) :: extra(14)
      integer :: n
      n = 0
      n = n + 1; extra(n) = "method: "//method_description(scene)
      n = n + 1; extra(n) = "S: trace of the one-period monodromy (with epsilon > 0: S1 of the chi equation (47))"
      n = n + 1; extra(n) = "|S| > 1e300 is written as +-1e300 with overflow = 1; log10_abs_S stays exact"
      if (scene%epsilon > 0.0_wp) then
         n = n + 1; extra(n) = "stable: 1 when |S1| < 2 cosh(epsilon) (all multipliers of x inside the unit circle)"
         n = n + 1; extra(n) = "stable_paper: 1 when |S1| <= 2, the sufficient criterion of the paper"
      else
         n = n + 1; extra(n) = "stable: 1 when |S| < 2"
      end if
      n = n + 1; extra(n) = "stable = 0.5: marginal, |S| is within its error bound max(error_estimate, tolerance) "// &
         "max(1, |S|) of the threshold, the value cannot decide"
      n = n + 1; extra(n) = "lambda_max: largest |multiplier| of x per period; mu: Floquet exponent ln(lambda_max)/2"
      if (scene%physical) then
         n = n + 1; extra(n) = "mu_per_s: the Floquet exponent per second, mu omega/pi (tau = omega t/pi)"
      end if
      if (scene%model == model_elastic) then
         n = n + 1; extra(n) = "physical: 1 inside the physical domain 0 <= alpha < pi^2, 0 <= beta < pi^2"
      end if
      n = n + 1; extra(n) = "error_estimate: the method's estimate of |error of S|/max(1, |S|) (-1: the method gives none)"
      n = n + 1; extra(n) = "status: 0 ok; 1 round-off limited (best value, error_estimate at the round-off level); 2 failed"
      n = n + 1; extra(n) = "status 2 rows: S = 0, mu = 0, stable = overflow = stable_paper = -1, lambda_max = -1, "// &
         "log10_abs_S = -999, error_estimate = -1 (placeholders, not values)"
      if (outside .and. scene%model == model_elastic) then
         n = n + 1; extra(n) = "note: this file leaves the physical domain (rows with physical = 0)"
      end if
      lines = stacked(common_header(scene), extra(:n))
   end function chart_header

   function method_description(scene) result(text)
      type(scene_t), intent(in) :: scene
      character(len=:), allocatable :: text
      text = method_name(scene%method%kind)
      if (scene%method%kind == method_segments) then
         text = text//", "//integer_text(scene%method%n_segments)//" pieces, sampling "// &
            sampling_name(scene%method%sampling)
      else if (method_name(scene%method%kind) /= "formula") then
         text = text//", tolerance "//real_text(scene%method%tolerance)
      end if
   end function method_description

   !> The lines of a followed by those of b, at the longer of their lengths.
   pure function stacked(a, b) result(c)
      character(len=*), intent(in) :: a(:), b(:)
      character(len=:), allocatable :: c(:)
      allocate (character(len=max(len(a), len(b))) :: c(size(a) + size(b)))
      c(:size(a)) = a
      c(size(a) + 1:) = b
   end function stacked

   !> The chart task.
   subroutine run_chart(scene, quiet, error)
      type(scene_t), intent(in) :: scene
      logical, intent(in) :: quiet
      type(error_t), allocatable, intent(out) :: error
      type(output_file_t) :: file
      type(progress_t) :: progress
      character(len=chart_line_length), allocatable :: lines(:)
      logical :: outside
      real(wp) :: alpha
      real(wp), allocatable :: all_betas(:)
      character(len=23), allocatable :: beta_texts(:)
      logical :: stopped, stop_now
      character(len=chart_line_length), allocatable :: block_lines(:, :, :)
      integer, allocatable :: block_status(:, :, :), statuses(:), ids(:)
      real(wp), allocatable :: block_values(:, :, :, :), values(:, :)
      integer(int64) :: n_inaccurate, n_failed
      real(wp) :: first_inaccurate(2), first_failed(2)
      integer :: group, n_groups, g
      integer :: i, n_alpha, n_beta

      n_alpha = scene%chart%n_alpha
      n_beta = scene%chart%n_beta
      call scene_columns(scene, ids, error)
      if (allocated(error)) return
      ! an unwritable output path fails before any computing
      call open_scene_output(scene, file, error)
      if (allocated(error)) return
      call check_method_runs(scene, error)
      if (allocated(error)) then
         call discard_output(file)
         return
      end if
      call chart_betas(scene, all_betas, beta_texts)
      outside = .not. (in_physical_domain(scene%chart%alpha_min, scene%chart%beta_min) .and. &
                       in_physical_domain(scene%chart%alpha_max, scene%chart%beta_max))
      call write_header(file, chart_header(scene, outside), chart_columns_text(ids), error, &
                        names_line=scene%names_line, records=[n_beta, n_alpha])
      if (allocated(error)) then
         call discard_output(file)
         return
      end if

      call progress_begin(progress, int(n_alpha, int64)*n_beta, quiet)
      stopped = .false.
      n_inaccurate = 0
      n_failed = 0
      if (rows_in_parallel(scene)) then
         ! groups of rows computed in parallel (mesh preparation, integration and
         ! formatting on every core) into one of two buffers, while one thread writes the
         ! previous group from the other buffer; a group holds a few rows per thread, so
         ! memory stays bounded however large the chart
         group = 8*max_threads()
         n_groups = (n_alpha + group - 1)/group
         allocate (block_lines(n_beta, group, 0:1), block_status(n_beta, group, 0:1), &
                   block_values(size(ids), n_beta, group, 0:1))
         !$omp parallel default(shared) private(g, i, alpha, stop_now)
         do g = 1, n_groups + 1
            ! every thread takes the same decision: stopped is read between two barriers
            ! (it is written only inside the single below)
            !$omp barrier
            stop_now = stopped
            !$omp barrier
            if (stop_now) exit
            if (g > 1) then
               !$omp single
               do i = (g - 2)*group + 1, min(n_alpha, (g - 1)*group)
                  alpha = grid_value(scene%chart%alpha_min, scene%chart%alpha_max, n_alpha, i)
                  call finish_row(i, alpha, block_lines(:, i - (g - 2)*group, mod(g - 1, 2)), &
                     block_values(:, :, i - (g - 2)*group, mod(g - 1, 2)), block_status(:, i - (g - 2)*group, mod(g - 1, 2)))
                  if (stopped) exit
               end do
               !$omp end single nowait
            end if
            if (g <= n_groups) then
               !$omp do schedule(dynamic)
               do i = (g - 1)*group + 1, min(n_alpha, g*group)
                  alpha = grid_value(scene%chart%alpha_min, scene%chart%alpha_max, n_alpha, i)
                  call compute_row(scene, ids, alpha, all_betas, block_lines(:, i - (g - 1)*group, mod(g, 2)), &
                     block_values(:, :, i - (g - 1)*group, mod(g, 2)), block_status(:, i - (g - 1)*group, mod(g, 2)), &
                     beta_texts=beta_texts)
               end do
               !$omp end do
            else
               !$omp barrier
            end if
         end do
         !$omp end parallel
      else
         ! few rows: the points of each row in parallel chunks sharing the prepared meshes
         allocate (lines(n_beta), statuses(n_beta), values(size(ids), n_beta))
         do i = 1, n_alpha
            alpha = grid_value(scene%chart%alpha_min, scene%chart%alpha_max, n_alpha, i)
            call compute_row_in_chunks(scene, ids, alpha, all_betas, lines, values, statuses, beta_texts)
            call finish_row(i, alpha, lines, values, statuses)
            if (stopped) exit
         end do
      end if
      call progress_end(progress)
      call finish_output(file, error)
      if (allocated(error)) return
      call warn_inaccurate(scene, n_inaccurate, first_inaccurate)
      call failed_points_error(scene, n_failed, int(n_alpha, int64)*n_beta, first_failed, error)
   contains
      !> Write a computed row (in order) and count its round-off limited and failed points.
      subroutine finish_row(i, alpha, lines, values, statuses)
         integer, intent(in) :: i
         real(wp), intent(in) :: alpha
         character(len=*), intent(in) :: lines(:)  !! text: the row's lines
         real(wp), intent(in) :: values(:, :)      !! binary: the row's records
         integer, intent(in) :: statuses(:)
         if (scene%binary) then
            call write_records(file, values, error)
         else
            ! blocks of constant alpha, separated by one blank line (gnuplot pm3d/image)
            call write_text(file, joined_lines(lines, i > 1), error)
         end if
         if (allocated(error)) then
            stopped = .true.
            return
         end if
         if (any(statuses == status_roundoff)) then
            if (n_inaccurate == 0) first_inaccurate = [alpha, all_betas(findloc(statuses, status_roundoff, dim=1))]
            n_inaccurate = n_inaccurate + count(statuses == status_roundoff)
         end if
         if (any(statuses == status_failed)) then
            if (n_failed == 0) first_failed = [alpha, all_betas(findloc(statuses, status_failed, dim=1))]
            n_failed = n_failed + count(statuses == status_failed)
         end if
         call progress_update(progress, int(i, int64)*n_beta)
      end subroutine finish_row
   end subroutine run_chart

   !> Text lines or binary records (and statuses) of the chart points (α, β_j) of one row
   !> or part of a row, with the columns `ids`.
   subroutine compute_row(scene, ids, alpha, betas, lines, values, statuses, plan, beta_texts)
      type(scene_t), intent(in) :: scene
      integer, intent(in) :: ids(:)  !! the columns (hillstab_batch_output's chart_column_names)
      real(wp), intent(in) :: alpha, betas(:)
      character(len=*), intent(inout) :: lines(:)  !! text format: one line a point
      real(wp), intent(inout) :: values(:, :)      !! binary format: (columns, points)
      !> status_ok, status_roundoff (computed only to the round-off level) or status_failed
      integer, intent(out) :: statuses(:)
      type(batch_plan_t), intent(in), optional :: plan  !! prepared for the whole row
      character(len=23), intent(in), optional :: beta_texts(:)  !! format_es(betas, 16), made once per chart
      type(trace_t) :: traces(size(betas))
      character(len=23) :: alpha_text
      type(error_t), allocatable :: cause
      type(floquet_t) :: f
      type(hill_model_t) :: row
      real(wp) :: v(n_chart_columns), per_second
      logical :: failed(size(betas)), inaccurate(size(betas))
      integer :: j
      ! ω/π turns a rate per unit τ into a rate per second (the mu_per_s column exists only
      ! when the scene knows ω)
      per_second = 0.0_wp
      if (scene%physical) per_second = scene%pendulum%omega/pi
      row = hill_model_t(scene%model, alpha, 0.0_wp, scene%epsilon)
      call monodromy_trace_batch(row, betas, scene%method, traces, failed, cause, plan=plan, inaccurate=inaccurate)
      alpha_text = format_es(alpha, 16)
      statuses = merge(status_roundoff, status_ok, inaccurate)
      where (failed) statuses = status_failed
      do j = 1, size(betas)
         if (failed(j)) then
            v = failed_chart_values(alpha, betas(j), in_physical_domain(alpha, betas(j)), status_failed)
         else
            f = floquet_from_trace(traces(j), scene%epsilon, scene%method%tolerance)
            v = chart_values(alpha, betas(j), f, in_physical_domain(alpha, betas(j)), statuses(j), per_second)
         end if
         if (scene%binary) then
            values(:, j) = v(ids)
         else if (present(beta_texts)) then
            lines(j) = chart_text(ids, v, alpha_text, beta_texts(j))
         else
            lines(j) = chart_text(ids, v, alpha_text)
         end if
      end do
   end subroutine compute_row

   !> A chart computes whole rows in parallel when it has enough of them, else the
   !> chunks of each row in parallel.
   logical function rows_in_parallel(scene)
      type(scene_t), intent(in) :: scene
      rows_in_parallel = scene%chart%n_alpha >= 4*max_threads()
   end function rows_in_parallel

   !> `compute_row` on a whole row, split into chunks computed in parallel that share
   !> the meshes prepared for the row.
   subroutine compute_row_in_chunks(scene, ids, alpha, betas, lines, values, statuses, beta_texts)
      type(scene_t), intent(in) :: scene
      integer, intent(in) :: ids(:)  !! the columns
      real(wp), intent(in) :: alpha, betas(:)
      character(len=*), intent(inout) :: lines(:)  !! text format: one line a point
      real(wp), intent(inout) :: values(:, :)      !! binary format: (columns, points)
      integer, intent(out) :: statuses(:)
      character(len=23), intent(in) :: beta_texts(:)
      type(batch_plan_t) :: plan
      integer :: c, chunk, n_chunks, first, last, n
      n = size(betas)
      chunk = max(16, n/(8*max_threads()))
      n_chunks = (n + chunk - 1)/chunk
      call prepare_batch(hill_model_t(scene%model, alpha, 0.0_wp, scene%epsilon), betas, scene%method, plan)
      !$omp parallel do schedule(dynamic) default(shared) private(c, first, last)
      do c = 1, n_chunks
         first = (c - 1)*chunk + 1
         last = min(n, c*chunk)
         call compute_row(scene, ids, alpha, betas(first:last), lines(first:last), values(:, first:last), &
            statuses(first:last), plan, beta_texts(first:last))
      end do
      !$omp end parallel do
   end subroutine compute_row_in_chunks

   !> The β values of a chart's rows and their text, made once per chart.
   subroutine chart_betas(scene, betas, beta_texts)
      type(scene_t), intent(in) :: scene  !! a chart scene
      real(wp), allocatable, intent(out) :: betas(:)  !! the n_beta grid values of &chart
      character(len=23), allocatable, intent(out) :: beta_texts(:)  !! format_es(betas, 16)
      integer :: j, n_beta
      n_beta = scene%chart%n_beta
      betas = [(grid_value(scene%chart%beta_min, scene%chart%beta_max, n_beta, j), j=1, n_beta)]
      allocate (beta_texts(n_beta))
      do j = 1, n_beta
         beta_texts(j) = format_es(betas(j), 16)
      end do
   end subroutine chart_betas

   !> Text lines of row `i` of a chart scene (α = the i-th grid value, all β) with the
   !> scene's columns, computed exactly as the chart task computes them, so that a driver
   !> computing rows elsewhere writes the same file (format = 'text').
   subroutine chart_row(scene, i, lines, statuses, betas, beta_texts, ids)
      type(scene_t), intent(in) :: scene  !! a chart scene
      integer, intent(in) :: i            !! row index, 1 … n_alpha
      character(len=*), intent(out) :: lines(:)  !! n_beta lines of `chart_line_length` characters
      integer, intent(out) :: statuses(:)  !! per point: status_ok, status_roundoff or status_failed
      !> `chart_betas` of the scene, made once for all rows (made here when absent)
      real(wp), intent(in), optional :: betas(:)
      character(len=23), intent(in), optional :: beta_texts(:)  !! `chart_betas` of the scene (with `betas`)
      integer, intent(in), optional :: ids(:)  !! `scene_columns` of the scene (made here when absent)
      real(wp), allocatable :: own_betas(:)
      character(len=23), allocatable :: own_texts(:)
      integer, allocatable :: own_ids(:)
      type(error_t), allocatable :: error
      if (present(ids)) then
         own_ids = ids
      else
         call scene_columns(scene, own_ids, error)  ! checked when the scene was read
         if (allocated(error)) own_ids = default_chart_columns(scene%epsilon > 0.0_wp, &
                                                               scene%model == model_elastic, scene%physical)
      end if
      if (present(betas) .and. present(beta_texts)) then
         call row(betas, beta_texts, own_ids)
      else
         call chart_betas(scene, own_betas, own_texts)
         call row(own_betas, own_texts, own_ids)
      end if
   contains
      subroutine row(betas, beta_texts, ids)
         real(wp), intent(in) :: betas(:)
         character(len=23), intent(in) :: beta_texts(:)
         integer, intent(in) :: ids(:)
         real(wp) :: alpha
         real(wp), allocatable :: values(:, :)  ! records: unused by text lines, sized for compute_row
         allocate (values(size(ids), size(betas)))
         alpha = grid_value(scene%chart%alpha_min, scene%chart%alpha_max, scene%chart%n_alpha, i)
         if (rows_in_parallel(scene)) then
            call compute_row(scene, ids, alpha, betas, lines, values, statuses, beta_texts=beta_texts)
         else
            call compute_row_in_chunks(scene, ids, alpha, betas, lines, values, statuses, beta_texts)
         end if
      end subroutine row
   end subroutine chart_row

   !> Text lines (with the scene's columns) or records `values` of the points `first` …
   !> `last` of a points scene (in parallel); a failed point gets its placeholders.
   subroutine compute_points(scene, first, last, lines, statuses, values)
      type(scene_t), intent(in) :: scene  !! a points scene
      integer, intent(in) :: first, last  !! range of point indices
      character(len=*), intent(out) :: lines(first:)  !! one chart line per point
      integer, intent(out) :: statuses(first:)  !! per point: status_ok, status_roundoff or status_failed
      !> the same points as records (columns, points), for format = 'binary'
      real(wp), intent(out), optional :: values(:, first:)
      type(floquet_t) :: f
      type(error_t), allocatable :: cause
      real(wp) :: per_second, v(n_chart_columns)
      integer, allocatable :: ids(:)
      integer :: k
      call scene_columns(scene, ids, cause)  ! checked when the scene was read
      if (allocated(cause)) ids = default_chart_columns(scene%epsilon > 0.0_wp, scene%model == model_elastic, &
                                                        scene%physical)
      ! ω/π turns a rate per unit τ into a rate per second (the mu_per_s column exists only
      ! when the scene knows ω)
      per_second = 0.0_wp
      if (scene%physical) per_second = scene%pendulum%omega/pi
      !$omp parallel do schedule(dynamic) default(shared) private(k, f, cause, v)
      do k = first, last
         call evaluate_point(scene, scene%points(1, k), scene%points(2, k), f, cause, statuses(k))
         if (statuses(k) == status_failed) then
            v = failed_chart_values(scene%points(1, k), scene%points(2, k), &
                                    in_physical_domain(scene%points(1, k), scene%points(2, k)), status_failed)
         else
            v = chart_values(scene%points(1, k), scene%points(2, k), f, &
                             in_physical_domain(scene%points(1, k), scene%points(2, k)), statuses(k), per_second)
         end if
         if (present(values)) values(:, k) = v(ids)
         lines(k) = chart_text(ids, v)
      end do
      !$omp end parallel do
   end subroutine compute_points

   !> A chart whose method cannot run at all (bad parameters) fails at its first point,
   !> before anything is written; a point where the computation fails is written with
   !> its status instead.
   subroutine check_method_runs(scene, error)
      type(scene_t), intent(in) :: scene  !! a chart scene
      type(error_t), allocatable, intent(out) :: error  !! why the method cannot run; unallocated when it can
      type(error_t), allocatable :: cause
      type(floquet_t) :: f
      real(wp) :: alpha, beta
      alpha = scene%chart%alpha_min
      beta = scene%chart%beta_min
      call evaluate_point(scene, alpha, beta, f, cause)
      if (allocated(cause)) then
         if (cause%code == err_invalid_parameter) call point_error(scene, alpha, beta, cause, error)
      end if
   end subroutine check_method_runs

   !> The points task.
   subroutine run_points(scene, quiet, error)
      type(scene_t), intent(in) :: scene
      logical, intent(in) :: quiet
      type(error_t), allocatable, intent(out) :: error
      type(output_file_t) :: file
      type(progress_t) :: progress
      character(len=chart_line_length), allocatable :: lines(:)
      integer, allocatable :: statuses(:)
      integer :: k, n
      integer, allocatable :: ids(:)
      real(wp), allocatable :: values(:, :)

      n = size(scene%points, 2)
      call scene_columns(scene, ids, error)
      if (allocated(error)) return
      call open_scene_output(scene, file, error)
      if (allocated(error)) return
      allocate (lines(n), statuses(n), values(size(ids), n))
      statuses = status_ok
      call progress_begin(progress, int(n, int64), quiet)
      call compute_points(scene, 1, n, lines, statuses, values)
      call progress_update(progress, int(n, int64))
      call progress_end(progress)
      call write_header(file, chart_header(scene, .not. all(in_physical_domain(scene%points(1, :), &
         scene%points(2, :)))), chart_columns_text(ids), error, names_line=scene%names_line, records=[n, 1])
      if (scene%binary .and. .not. allocated(error)) call write_records(file, values, error)
      do k = 1, n
         if (allocated(error) .or. scene%binary) exit
         call write_text(file, trim(lines(k)), error)
      end do
      call finish_output(file, error)
      if (allocated(error)) return
      if (any(statuses == status_roundoff)) then
         k = findloc(statuses, status_roundoff, dim=1)
         call warn_inaccurate(scene, int(count(statuses == status_roundoff), int64), scene%points(:, k))
      end if
      if (any(statuses == status_failed)) then
         k = findloc(statuses, status_failed, dim=1)
         call failed_points_error(scene, int(count(statuses == status_failed), int64), int(n, int64), &
                                  scene%points(:, k), error)
      end if
   end subroutine run_points

   !> The coefficient task: columns tau, then for each α: Q(τ) and its N-piece
   !> segmented value (n_segments and sampling of &scene).
   subroutine run_coefficient(scene, error)
      type(scene_t), intent(in) :: scene
      type(error_t), allocatable, intent(out) :: error
      type(output_file_t) :: file
      type(hill_model_t) :: model
      real(wp), allocatable :: pieces(:, :), row(:)
      character(len=:), allocatable :: columns, lines(:), q_line, segments_line, columns_line
      real(wp) :: tau, h
      integer :: i, k, n_alpha, n_pieces, piece

      n_alpha = size(scene%coefficient%alphas)
      n_pieces = scene%method%n_segments
      h = hill_period/n_pieces
      allocate (pieces(n_pieces, n_alpha), row(1 + 2*n_alpha))
      columns = "tau"
      do k = 1, n_alpha
         model = hill_model_t(scene%model, scene%coefficient%alphas(k), scene%coefficient%beta, scene%epsilon)
         call segment_coefficients(model, n_pieces, scene%method%sampling, pieces(:, k))
         columns = columns//" Q("//real_text(scene%coefficient%alphas(k))//") Qseg("// &
            real_text(scene%coefficient%alphas(k))//")"
      end do
      q_line = "Q: the coefficient at beta = "//real_text(scene%coefficient%beta)// &
               " (minus epsilon^2/4 when epsilon > 0: the chi equation (47))"
      segments_line = "Qseg: Q replaced by "//integer_text(n_pieces)//" constant pieces on [0, 2), sampling "// &
                      sampling_name(scene%method%sampling)//" (2 pieces, endpoint: eq. (28) of the paper)"
      columns_line = "Q(a), Qseg(a): the two columns of alpha = a"
      lines = stacked(common_header(scene), stacked([q_line], stacked([segments_line], [columns_line])))

      call open_scene_output(scene, file, error)
      if (allocated(error)) return
      call write_header(file, lines, columns, error)
      do i = 1, scene%coefficient%n_tau
         if (allocated(error)) exit
         tau = grid_value(scene%coefficient%tau_min, scene%coefficient%tau_max, scene%coefficient%n_tau, i)
         piece = min(int(modulo(tau, hill_period)/h) + 1, n_pieces)
         row(1) = tau
         do k = 1, n_alpha
            model = hill_model_t(scene%model, scene%coefficient%alphas(k), scene%coefficient%beta, scene%epsilon)
            row(2*k) = hill_coefficient(model, tau)
            row(2*k + 1) = pieces(piece, k)
         end do
         call write_text(file, real_columns(row), error)
      end do
      call finish_output(file, error)
   end subroutine run_coefficient

   !> Start reporting the progress of a run of `total` points (nothing when quiet).
   subroutine progress_begin(progress, total, quiet)
      type(progress_t), intent(out) :: progress  !! the progress state
      integer(int64), intent(in) :: total  !! points to compute
      logical, intent(in) :: quiet  !! no progress on stderr
      progress%enabled = .not. quiet
      progress%total = total
      call system_clock(progress%start, progress%ticks)
      progress%last = progress%start
      if (progress%enabled) progress%terminal = c_isatty(2_c_int) == 1
   end subroutine progress_begin

   !> Report `done` of `total` points: percentage, rate and time left, once the run
   !> has taken a second; redrawn in place on a terminal, a line every 5 s otherwise.
   subroutine progress_update(progress, done)
      type(progress_t), intent(inout) :: progress  !! the progress state
      integer(int64), intent(in) :: done  !! points computed so far
      integer(int64) :: now
      real(wp) :: elapsed, since_last, rate, left, interval
      character(len=160) :: text
      character(len=12) :: left_text
      if (.not. progress%enabled) return
      call system_clock(now)
      elapsed = real(now - progress%start, wp)/progress%ticks
      since_last = real(now - progress%last, wp)/progress%ticks
      if (elapsed < 1.0_wp) return
      interval = merge(0.25_wp, 5.0_wp, progress%terminal)
      if (progress%shown .and. since_last < interval .and. done < progress%total) return
      rate = real(done, wp)/elapsed
      left = real(progress%total - done, wp)/max(rate, tiny(1.0_wp))
      write (left_text, '(f12.1)') left
      write (text, '(a,f5.1,a,i0,a,i0,a,i0,a)') "hillstab: ", 100.0_wp*done/progress%total, "% (", &
         done, " of ", progress%total, " points, ", nint(rate, int64), " points/s, "
      text = trim(text)//" "//trim(adjustl(left_text))//" s left)"
      if (progress%terminal) then
         write (error_unit, '(a)', advance="no") achar(13)//trim(text)//"   "
      else
         write (error_unit, '(a)') trim(text)
      end if
      flush (error_unit)
      progress%shown = .true.
      progress%last = now
   end subroutine progress_update

   !> End the progress display (a final new line on a terminal).
   subroutine progress_end(progress)
      type(progress_t), intent(in) :: progress  !! the progress state
      if (progress%shown .and. progress%terminal) write (error_unit, '(a)') ""
   end subroutine progress_end

   !> Say on stderr (even when quiet: it qualifies the results) how many points could only
   !> be computed to the round-off level of double precision, not to the tolerance.
   subroutine warn_inaccurate(scene, n, first)
      type(scene_t), intent(in) :: scene  !! a validated scene
      integer(int64), intent(in) :: n  !! number of round-off limited points
      real(wp), intent(in) :: first(2)  !! alpha, beta of the first such point
      if (n == 0) return
      write (error_unit, '(a)') "hillstab: warning: "//scene%source//": "//integer_text(n)// &
         " point(s) reached only the round-off level of double precision, not the tolerance "// &
         real_text(scene%method%tolerance)//" (first at alpha = "//real_text(first(1))//", beta = "// &
         real_text(first(2))//"); their S is the best available"
   end subroutine warn_inaccurate

   !> Number of OpenMP threads a parallel region will use (1 without OpenMP).
   integer function max_threads()
      max_threads = 1
      !$ max_threads = omp_get_max_threads()
   end function max_threads
end module hillstab_batch_tasks

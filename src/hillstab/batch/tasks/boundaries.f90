!> Task `boundaries`: the transition curves (S = ±2) over the α grid of `&chart`,
!> inside its β window, written as one gnuplot block per curve.
!>
!> - method auto or any exact method: the exact curves by the model's route
!>   (hillstab_curves_boundaries `curve_route`): Hill's method on the pencil
!>   (hillstab_curves_hill_method: elastic, Mathieu), Hill's method on the Fourier
!>   coefficients of g = Q − β (hillstab_curves_hill_fourier: Q = β + g with finitely many
!>   harmonics), or root finding on S by method auto (brackets from n_beta samples of the
!>   window: infinitely many harmonics, a jump of Q); the header says which. Every boundary is
!>   checked independently by method auto (hillstab_curves_boundaries); a boundary
!>   that fails the check is written with status_failed and the run reports it
!>   (err_points_failed, exit status 3), it is never written as ok;
!> - method formula or segments: the roots of S_method(β) = ±2 by Brent's method on a
!>   bracket sampled at n_beta points of the window (`n_beta` is used only here);
!> - a model with an independent GSL witness (Mathieu: a_n, b_n) gets it as a column
!>   beside Hill's values.
!>
!> The work runs in parallel (OpenMP, dynamic schedule: the truncation grows towards
!> α → π² and with β): for the exact methods the four blocks of Hill's matrix at every α,
!> then the check by auto of every curve point found, each a unit of the progress line
!> (one α may take minutes and hold hundreds of curves); for formula and segments the α
!> values. The file is written once all are done, curve by curve.
!>
!> For one spring (`&physical r0` without amplitudes) the task writes the spring's critical
!> amplitudes instead (hillstab_batch_tasks_boundaries_spring).
module hillstab_batch_tasks_boundaries
   use hillstab_core_kinds, only: wp, int64, pi2, version_string
   use hillstab_batch_output_progress, only: progress_t, progress_begin, progress_step, progress_beat, &
      progress_end
   use hillstab_ffi_libc, only: c_nanosleep, timespec_t
   use, intrinsic :: iso_c_binding, only: c_int, c_long
   !$ use omp_lib, only: omp_get_thread_num, omp_get_num_threads
   use hillstab_core_error, only: error_t, set_error, err_input, err_points_failed
   use hillstab_core_status, only: status_ok, status_roundoff, status_failed
   use hillstab_hill_model, only: model_description, model_equation_text
   use hillstab_hill_units, only: physical_beta
   use hillstab_hill_coefficient, only: in_physical_domain, sampling_name
   use hillstab_hill_model_pendulum, only: is_elastic_pendulum
   use hillstab_integrate_monodromy, only: method_name, method_is_exact, method_uses_segments, method_pieces
   use hillstab_curves_hill_method, only: hill_boundary_t, hill_boundaries, coexistence_threshold, &
      hill_block_values_t, hill_block_values, hill_curves, route_pencil, route_fourier, route_roots, &
      route_closed_form
   use hillstab_curves_hill_fourier, only: fourier_drive_t, fourier_drive, fourier_blocks, fourier_block_t, &
      fourier_block_values, fourier_curves
   use hillstab_curves_boundaries, only: boundary_check_t, verify_boundary, approximate_root_t, &
      approximate_boundaries, beta_accuracy_factor, gsl_witness_max_q, curve_route, exact_boundaries
   use hillstab_batch_scene_types, only: scene_t, task_t, scene_header, output_path, open_scene_output
   use hillstab_batch_scene_physical, only: pendulum_task_t, physical_scene_t
   use hillstab_batch_scene_declaration, only: group_t
   use hillstab_batch_scene_file, only: scene_file_t, fail, group_present
   use hillstab_batch_scene_checks, only: max_boundaries_magnitude, min_pendulum_beta
   use hillstab_batch_tasks_chart_columns, only: point_amplitude
   use hillstab_batch_scene_group_chart, only: chart_grid_t, chart_group, read_chart_group, grid_alpha, scale_linear
   use hillstab_batch_output_columns, only: column_t, style_e17, style_e4, style_integer, style_width2, &
      style_width4, columns_text, put_row
   use hillstab_batch_output_file, only: output_file_t, finish_output, discard_output, write_header, write_text
   use hillstab_core_text, only: real_text, integer_text
   use hillstab_core_parallel, only: max_threads
   use hillstab_batch_tasks_boundaries_spring, only: spring_run
   implicit none
   private
   public :: boundaries_task_t, boundaries_task, boundary_row_t, compute_boundary_rows

   !> One row of the file: one curve at one α.
   type :: boundary_row_t
      real(wp) :: alpha = 0.0_wp, beta = 0.0_wp  !! the boundary point
      integer :: trace_sign = 2          !! +2 / −2
      integer :: order = 0               !! n of a_n, b_n
      integer :: branch = 1              !! exact: 1 even (a_n), 2 odd (b_n); approximate: 1 lower, 2 upper edge
      logical :: coexistent = .false.  !! both curves of this order coincide here (coexistence)
      integer :: status = status_ok  !! a status_* code of hillstab_core_status
      real(wp) :: check = 0.0_wp         !! exact: S by auto at the point; approximate: S_method
      real(wp) :: beta_error = 0.0_wp    !! error estimate of beta
      integer :: modes = 0               !! exact: modes of the truncation; approximate: pieces
      real(wp) :: beta_gsl = 0.0_wp      !! with a witness: GSL's value (beta when unavailable)
      integer :: gsl_ok = 0              !! 1 GSL agrees, 0 GSL not used here, 2 GSL disagrees with Hill
   end type boundary_row_t

   !> The columns of a boundaries file: where `boundary_columns` puts each column and
   !> `row_text` its value (the file's order is that of `boundary_columns`).
   integer, parameter :: curve_alpha = 1, curve_a = 2, curve_beta = 3, curve_kind = 4, curve_order = 5, &
      curve_branch = 6, curve_index = 7, curve_coexist = 8, curve_status = 9, curve_check = 10, curve_beta_error = 11, &
      curve_modes = 12, curve_beta_gsl = 13, curve_gsl_ok = 14
   integer, parameter :: n_curve_columns = 14  !! columns a boundaries file can hold

   !> GSL's value counts as agreeing with Hill's when within this times max(1, |β|).
   real(wp), parameter :: gsl_agreement = 1.0e-8_wp

   !> The rows of one α.
   type :: alpha_rows_t
      type(boundary_row_t), allocatable :: rows(:)
      logical :: failed = .false.                 !! Hill's method itself failed at this α
      character(len=:), allocatable :: message    !! why
   end type alpha_rows_t

   !> The boundaries task and the grid of `&chart` (`n_beta` used by formula and segments).
   type, extends(pendulum_task_t) :: boundaries_task_t
      type(chart_grid_t) :: grid  !! `&chart`
      !> `&physical` without `&chart`: the critical amplitudes of one spring (S = ±2 along α
      !> at its fixed β)
      logical :: spring = .false.
   contains
      procedure :: read => boundaries_read
      procedure :: run => boundaries_run
      procedure :: declarations => boundaries_declarations
      procedure :: memory_bytes => boundaries_memory_bytes
      procedure :: memory_variables => boundaries_memory_variables
   end type boundaries_task_t

contains

   !> `&chart`.
   function boundaries_declarations(self) result(groups)
      class(boundaries_task_t), intent(in) :: self  !! the task
      type(group_t), allocatable :: groups(:)
      allocate (groups(1))
      groups(1) = chart_group()
      if (self%spring) deallocate (groups)
      if (self%spring) allocate (groups(0))
   end function boundaries_declarations

   !> An upper estimate of the memory of a run over the grid: for every α its rows and (exact
   !> methods) its four blocks of Hill's matrix with their eigenvalues up to the top of the
   !> β window (about sqrt(β + |α|)/π + 2 a block, values and changes) and the curves they
   !> give (one row each), held until the file is written; and each thread's truncation at
   !> work (a banded pencil of up to the modes of the top, ten numbers a mode). The spring's
   !> critical amplitudes hold a few curves: nothing beyond the program's own.
   function boundaries_memory_bytes(self, scene) result(bytes)
      class(boundaries_task_t), intent(in) :: self  !! the task
      type(scene_t), intent(in) :: scene  !! its scene
      integer(int64) :: bytes
      type(hill_block_values_t) :: block
      type(alpha_rows_t) :: rows
      type(boundary_row_t) :: row
      real(wp) :: top, per_block
      integer(int64) :: per_alpha, modes
      if (self%spring) then
         bytes = 0
         return
      end if
      top = max(abs(self%grid%beta_min), abs(self%grid%beta_max))
      top = top + 1.0_wp + 0.25_wp*top + max(abs(self%grid%alpha_min), abs(self%grid%alpha_max))
      per_block = sqrt(top)/3.14_wp + 2.0_wp
      per_alpha = storage_size(rows)/8 + int(4.0_wp*per_block, int64)*(storage_size(row)/8)
      if (exact_method(scene)) then
         per_alpha = per_alpha + 4*(storage_size(block)/8 + storage_size(rows)/8 + int(16.0_wp*per_block, int64))
      end if
      ! the truncations grow by half past the top's modes until they converge
      modes = 2*int(per_block, int64) + 64
      bytes = int(self%grid%n_alpha, int64)*per_alpha + int(max_threads(), int64)*modes*80
   end function boundaries_memory_bytes

   !> What sets the memory of a run: the α grid and the top of the β window.
   function boundaries_memory_variables(self) result(text)
      class(boundaries_task_t), intent(in) :: self  !! the task
      character(len=:), allocatable :: text
      text = "&chart: n_alpha, beta_max: "//integer_text(self%grid%n_alpha)//" alphas up to beta = "// &
             real_text(max(abs(self%grid%beta_min), abs(self%grid%beta_max)))
   end function boundaries_memory_variables

   !> A boundaries task before its scene is read.
   function boundaries_task() result(task)
      type(boundaries_task_t) :: task
      task%name = "boundaries"
      task%physical_use%takes_spring = .true.
   end function boundaries_task

   !> `&chart`, bounded for Hill's method; the curves are those of the undamped equation.
   subroutine boundaries_read(self, file, scene, error)
      class(boundaries_task_t), intent(inout) :: self  !! the task, its grid filled in
      type(scene_file_t), intent(in) :: file      !! the scene file
      type(scene_t), intent(in) :: scene          !! the `&scene` settings
      type(error_t), allocatable, intent(out) :: error  !! err_input naming file, group and variable
      if (.not. scene%model%takes_scene_damping()) then
         ! its curves are traced in beta at each alpha from a Q whose beta is its mean stiffness
         call fail(error, file%path, "scene", "task", "task 'boundaries' takes the models of (alpha, beta) "// &
            "(elastic, mathieu, meissner, fourier, sampled, modulated); the "//scene%model%name()//" model: its "// &
            "regions' boundaries in its own plane are task 'edges' (traced from each region's tip; task 'regions' "// &
            "the tips), or chart it (task 'chart'), or find its critical drives along an axis "// &
            "(hillstab_critical_drives_along, Python critical_drives)")
         return
      end if
      if (scene%epsilon > 0.0_wp .and. .not. self%physical%given) then
         call fail(error, file%path, "scene", "epsilon", "task 'boundaries' draws the undamped curves: epsilon must be 0")
         return
      end if
      if (self%physical%given .and. .not. group_present(file%unit, "chart")) then
         call read_spring(self, file, scene, error)
         return
      end if
      if (self%physical%r0_given) then
         call fail(error, file%path, "physical", "r0", "r0 fixes beta: with &chart the curves run over its beta "// &
            "window (drop r0), without &chart the task finds the critical amplitudes of the spring (drop &chart)")
         return
      end if
      allocate (self%groups(1))
      call read_chart_group(file, chart_group(), scene%model, self%grid, self%groups(1), error)
      if (allocated(error)) return
      if (self%grid%beta_scale /= scale_linear) then
         ! the curves are found inside the beta window (Hill's method, roots), not on its samples
         call fail(error, file%path, "chart", "beta_scale", "task 'boundaries' finds the curves inside the "// &
            "beta window, not at grid values: beta_scale must be 'linear' (alpha_scale = 'log' spaces the alphas)")
         return
      end if
      call check_boundaries_cost(scene, self%grid, error)
   end subroutine boundaries_read

   !> `&physical` without `&chart`: one spring, whose β is fixed by r0, g and ω.
   subroutine read_spring(self, file, scene, error)
      class(boundaries_task_t), intent(inout) :: self
      type(scene_file_t), intent(in) :: file
      type(scene_t), intent(in) :: scene
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: beta
      self%spring = .true.
      allocate (self%groups(0))
      if (.not. self%physical%r0_given) then
         call fail(error, file%path, "physical", "r0", "the critical amplitudes of a spring (task boundaries with "// &
            "&physical and no &chart) need r0, the natural length of the spring (m); for the curves over a grid "// &
            "give &chart")
         return
      end if
      if (scene%epsilon > 0.0_wp) then
         call fail(error, file%path, "physical", "kappa", "task 'boundaries' draws the undamped curves: kappa "// &
            "must be 0")
         return
      end if
      if (.not. is_elastic_pendulum(scene%model)) then
         call fail(error, file%path, "scene", "model", "the critical amplitudes of a spring are those of the "// &
            "elastic model, not of model '"//scene%model%name()//"'")
         return
      end if
      if (.not. method_is_exact(scene%method%kind)) then
         call fail(error, file%path, "scene", "method", "the critical amplitudes of a spring are found by Hill's "// &
            "method: method must be auto or an exact method, not '"//method_name(scene%method%kind)//"'")
         return
      end if
      beta = physical_beta(self%physical%pendulum)
      if (beta < min_pendulum_beta) then
         call fail(error, file%path, "physical", "g", "beta = g pi^2/(rho omega^2) = "//real_text(beta)// &
            " lies below "//real_text(min_pendulum_beta)//" (g = 0 or a spring too stiff to sag): S = 2 "// &
            "there at every amplitude")
      else if (pi2 - beta < min_pendulum_beta*pi2) then
         call fail(error, file%path, "physical", "r0", "beta = "//real_text(beta)//" is within "// &
            real_text(min_pendulum_beta)//" pi^2 of pi^2 (r0 negligible beside the sag g/omega^2): Q = pi^2, "// &
            "nothing resonates")
      end if
   end subroutine read_spring

   !> The boundaries task (Hill's method, its matrix growing with sqrt|alpha|) is bounded
   !> to |alpha|, |beta| <= max_boundaries_magnitude.
   subroutine check_boundaries_cost(scene, grid, error)
      type(scene_t), intent(in) :: scene
      type(chart_grid_t), intent(in) :: grid
      type(error_t), allocatable, intent(out) :: error
      character(len=*), parameter :: why = " for task boundaries (the cost of Hill's method grows with the magnitude)"
      if (max(abs(grid%alpha_min), abs(grid%alpha_max)) > max_boundaries_magnitude) then
         call fail(error, scene%source, "chart", merge("alpha_max", "alpha_min", &
            abs(grid%alpha_max) >= abs(grid%alpha_min)), "|alpha| must be <= "// &
            real_text(max_boundaries_magnitude)//why)
      else if (max(abs(grid%beta_min), abs(grid%beta_max)) > max_boundaries_magnitude) then
         call fail(error, scene%source, "chart", merge("beta_max", "beta_min", &
            abs(grid%beta_max) >= abs(grid%beta_min)), "|beta| must be <= "// &
            real_text(max_boundaries_magnitude)//why)
      end if
   end subroutine check_boundaries_cost

   logical function exact_method(scene)
      type(scene_t), intent(in) :: scene
      exact_method = method_is_exact(scene%method%kind)
   end function exact_method

   !> The columns of a boundaries file of this scene, one record each, by its curve_*
   !> index, and those the file holds, in the order given here: the GSL witness columns for
   !> a model that has one, the column a [m] for a scene with `&physical` and the elastic
   !> model (a = alpha g/(beta omega^2)).
   subroutine boundary_columns(scene, physical, table, ids)
      type(scene_t), intent(in) :: scene  !! a boundaries scene
      type(physical_scene_t), intent(in) :: physical  !! its `&physical` (the task's)
      type(column_t), intent(out) :: table(n_curve_columns)  !! every column, by curve_* index
      integer, allocatable, intent(out) :: ids(:)  !! the columns of the file, in file order
      allocate (ids(0))
      call add(curve_alpha, column_t("alpha", "", "alpha of the boundary point", style_e17))
      call add(curve_a, column_t("a", "m", "bounce amplitude a = alpha rho/pi^2 with rho = g pi^2/(beta omega^2) "// &
         "(eq. (24)); -1 where beta <= 0 (no equilibrium length)", style_e17), amplitude_column(scene, physical))
      call add(curve_beta, column_t("beta", "", "beta of the boundary point", style_e17))
      call add(curve_kind, column_t("kind", "", "S on the curve: +2 periodic, -2 antiperiodic", style_integer))
      call add(curve_order, column_t("order", "", "n of a_n/b_n", style_width4))
      call add(curve_branch, column_t("branch", "", "exact 1 = a_n (even), 2 = b_n (odd); approximate 1 = lower, "// &
         "2 = upper edge", style_width2))
      call add(curve_index, column_t("curve", "", "the block's index (gnuplot index = curve)", style_width4))
      call add(curve_coexist, column_t("coexist", "", "1 when both curves of this order coincide", style_integer))
      call add(curve_status, column_t("status", "", "0 ok, 1 check by auto limited by round-off, 2 failed the check", &
         style_integer))
      call add(curve_check, column_t("check", "", "S by auto at the point (approximate: S_method)", style_e17))
      call add(curve_beta_error, column_t("beta_error", "", "estimated error of beta", style_e4))
      call add(curve_modes, column_t("modes", "", "Fourier modes of the truncation (approximate: pieces)", &
         style_integer))
      call add(curve_beta_gsl, column_t("beta_gsl", "", "GSL's value of the curve", style_e17), &
         scene%model%has_witness())
      call add(curve_gsl_ok, column_t("gsl_ok", "", "1 GSL agrees, 2 disagrees, 0 not used", style_integer), &
         scene%model%has_witness())
   contains
      !> Column k, next in the file when offered (default).
      subroutine add(k, column, offered)
         integer, intent(in) :: k
         type(column_t), intent(in) :: column
         logical, intent(in), optional :: offered
         table(k) = column
         if (present(offered)) then
            if (.not. offered) return
         end if
         ids = [ids, k]
      end subroutine add
   end subroutine boundary_columns

   !> All boundaries at one α, by Hill's method (checked by auto) or by root finding.
   subroutine compute_boundary_rows(scene, grid, alpha, rows, error)
      type(scene_t), intent(in) :: scene  !! a validated boundaries scene
      type(chart_grid_t), intent(in) :: grid  !! its `&chart`
      real(wp), intent(in) :: alpha  !! the alpha of the rows
      type(boundary_row_t), allocatable, intent(out) :: rows(:)  !! one row per curve crossing the beta window
      type(error_t), allocatable, intent(out) :: error  !! what failed at this alpha; unallocated on success
      integer :: i
      call find_boundary_rows(scene, grid, alpha, rows, error)
      if (exact_method(scene)) then
         do i = 1, size(rows)
            call check_boundary_row(scene, rows(i))
         end do
      end if
   end subroutine compute_boundary_rows

   !> The boundaries at one α before their check: Hill's method's curves (the check by auto,
   !> `check_boundary_row`, still to do for each; beta_error holds Hill's own bound), or the
   !> roots of the approximate methods (complete).
   subroutine find_boundary_rows(scene, grid, alpha, rows, error)
      type(scene_t), intent(in) :: scene
      type(chart_grid_t), intent(in) :: grid
      real(wp), intent(in) :: alpha
      type(boundary_row_t), allocatable, intent(out) :: rows(:)
      type(error_t), allocatable, intent(out) :: error
      type(hill_boundary_t), allocatable :: curves(:)
      type(approximate_root_t), allocatable :: roots(:)
      integer :: i, j
      if (exact_method(scene)) then
         call exact_boundaries(scene%model, alpha, grid%beta_min, grid%beta_max, &
                               scene%method%tolerance, curves, error, n_samples=max(grid%n_beta, 2))
         if (allocated(error)) then
            allocate (rows(0))
            return
         end if
         rows = rows_of_curves(alpha, curves)
      else
         call approximate_boundaries(scene%model, alpha, scene%method, grid%beta_min, grid%beta_max, &
                                     max(grid%n_beta, 2), scene%method%tolerance, roots, error)
         if (allocated(error)) then
            allocate (rows(0))
            return
         end if
         allocate (rows(size(roots)))
         do i = 1, size(roots)
            rows(i)%alpha = alpha
            rows(i)%beta = roots(i)%beta
            rows(i)%trace_sign = roots(i)%trace_sign
            rows(i)%order = roots(i)%order
            rows(i)%branch = max(roots(i)%edge, 1)
            rows(i)%check = roots(i)%residual + roots(i)%trace_sign
            rows(i)%beta_error = scene%method%tolerance*max(1.0_wp, abs(roots(i)%beta))
            rows(i)%modes = method_pieces(scene%method)
            if (scene%model%has_witness()) rows(i)%beta_gsl = rows(i)%beta
         end do
         ! coexistence: both edges of an order found and equal to the accuracy
         do i = 1, size(rows)
            do j = 1, size(rows)
               if (i == j .or. rows(i)%order /= rows(j)%order .or. rows(i)%order == 0) cycle
               if (abs(rows(i)%beta - rows(j)%beta) <= coexistence_threshold*scene%method%tolerance* &
                   max(1.0_wp, abs(rows(i)%beta))) rows(i)%coexistent = .true.
            end do
         end do
      end if
   end subroutine find_boundary_rows

   !> The rows of the exact curves at one alpha, before their check (beta_error: their own
   !> bound; branch 1 a_n, 2 b_n, or 1 lower, 2 upper edge where the blocks do not split).
   function rows_of_curves(alpha, curves) result(rows)
      real(wp), intent(in) :: alpha
      type(hill_boundary_t), intent(in) :: curves(:)
      type(boundary_row_t), allocatable :: rows(:)
      integer :: i
      allocate (rows(size(curves)))
      do i = 1, size(curves)
         rows(i)%alpha = alpha
         rows(i)%beta = curves(i)%beta
         rows(i)%trace_sign = curves(i)%trace_sign
         rows(i)%order = curves(i)%order
         if (curves(i)%parity == 0) then   ! no even/odd split: the lower or upper edge
            rows(i)%branch = max(curves(i)%edge, 1)
         else
            rows(i)%branch = merge(1, 2, curves(i)%parity == 1)
         end if
         rows(i)%coexistent = curves(i)%coexistent
         rows(i)%modes = curves(i)%modes
         rows(i)%beta_error = curves(i)%error_bound
      end do
   end function rows_of_curves

   !> One boundary of Hill's method checked by method auto (its status, check and beta_error),
   !> with GSL's witness value for a model that has one.
   subroutine check_boundary_row(scene, row)
      type(scene_t), intent(in) :: scene
      type(boundary_row_t), intent(inout) :: row
      type(boundary_check_t) :: check
      type(error_t), allocatable :: cause
      logical :: available
      call verify_boundary(scene%model, row%alpha, row%beta, row%trace_sign, scene%method%tolerance, check, cause)
      row%check = check%trace
      row%beta_error = max(row%beta_error, check%beta_error)
      if (allocated(cause)) then
         row%status = status_failed
      else if (.not. check%passed) then
         row%status = status_failed
      else if (check%roundoff) then
         row%status = status_roundoff
      end if
      if (scene%model%has_witness()) then
         ! the parity as hill_boundary_t has it: +1 even (a_n), -1 odd (b_n)
         call scene%model%witness_beta(row%order, merge(1, -1, row%branch == 1), row%alpha, row%beta_gsl, &
                                 available)
         if (.not. available) then
            row%gsl_ok = 0
            row%beta_gsl = row%beta
         else if (abs(row%beta_gsl - row%beta) <= gsl_agreement*max(1.0_wp, abs(row%beta))) then
            row%gsl_ok = 1
         else
            row%gsl_ok = 2   ! GSL computed a value that disagrees with Hill's method: flagged
         end if
      end if
   end subroutine check_boundary_row

   !> The boundaries task.
   subroutine boundaries_run(self, scene, quiet, error)
      class(boundaries_task_t), intent(in) :: self  !! the task
      type(scene_t), intent(in) :: scene  !! a validated boundaries scene
      logical, intent(in) :: quiet  !! no progress on stderr (alphas done, then curve points checked)
      type(error_t), allocatable, intent(out) :: error  !! what failed; unallocated on success
      type(output_file_t) :: file
      type(progress_t) :: progress
      type(alpha_rows_t), allocatable :: per_alpha(:)
      integer, allocatable :: keys(:, :)
      integer :: i, j, c, n_alpha, n_failed_rows, n_failed_alpha, last_i, first_failed, next, finished
      logical :: found, any_written
      character(len=:), allocatable :: line, first_message
      type(error_t), allocatable :: cause
      real(wp) :: first_failure(2)
      type(column_t) :: table(n_curve_columns)
      integer, allocatable :: ids(:)
      if (self%spring) then
         call spring_run(scene, self%physical, quiet, error)
         return
      end if
      if (scene%epsilon > 0.0_wp) then   ! damping from &physical kappa
         call set_error(error, err_input, scene%source//": &physical: kappa: task 'boundaries' draws the "// &
            "undamped curves: kappa must be 0")
         return
      end if
      n_alpha = self%grid%n_alpha
      ! (the estimate of `boundaries_memory_bytes` was checked before the run: should the
      ! machine still lack the memory, say so before the output is opened)
      allocate (per_alpha(n_alpha), stat=i)
      if (i /= 0) then
         call set_error(error, err_input, scene%source//": "//self%memory_variables()//": the rows of "// &
            integer_text(n_alpha)//" alphas cannot be allocated (out of memory)")
         return
      end if
      call open_scene_output(scene, file, error)
      if (allocated(error)) return
      if (exact_method(scene)) then
         ! the four blocks of Hill's matrix at every alpha, then the check of every curve point
         ! by auto: the units of progress and of the parallel loops (near alpha = pi^2 or at
         ! large |beta| one block takes many seconds and one alpha holds hundreds of curves)
         call find_hill_rows(scene, self%grid, per_alpha, quiet, error)
         if (allocated(error)) then
            error%message = scene%source//": "//self%memory_variables()//": "//error%message
            call discard_output(file)
            return
         end if
         call check_every_row(scene, per_alpha, quiet)
      else
         call progress_begin(progress, int(n_alpha, int64), quiet, "alphas")
         ! (an alpha of 10^8 samples of formula takes seconds: the line keeps its pace)
         next = 0
         finished = 0
         !$omp parallel num_threads(team_size(progress)) default(shared) private(i, cause)
         if (watches(progress)) then
            call watch_progress(progress, finished, n_alpha)
         else
            do
               !$omp atomic capture
               next = next + 1
               i = next
               !$omp end atomic
               if (i > n_alpha) exit
               call find_boundary_rows(scene, self%grid, grid_alpha(self%grid, i), per_alpha(i)%rows, cause)
               if (allocated(cause)) then
                  per_alpha(i)%failed = .true.
                  per_alpha(i)%message = cause%message
               end if
               call progress_step(progress)
               !$omp atomic update
               finished = finished + 1
            end do
         end if
         !$omp end parallel
         call progress_end(progress)
      end if

      ! the curves present anywhere, ordered by order, then branch
      allocate (keys(3, 0))
      do i = 1, n_alpha
         do j = 1, size(per_alpha(i)%rows)
            associate (r => per_alpha(i)%rows(j))
               found = .false.
               do c = 1, size(keys, 2)
                  if (all(keys(:, c) == [r%order, r%branch, r%trace_sign])) found = .true.
               end do
               if (.not. found) keys = reshape([keys, r%order, r%branch, r%trace_sign], [3, size(keys, 2) + 1])
            end associate
         end do
      end do
      call sort_keys(keys)

      call boundary_columns(scene, self%physical, table, ids)
      call write_header(file, header(scene, self%grid, size(keys, 2)), columns_text(table, ids), error)
      if (allocated(error)) then
         call discard_output(file)
         return
      end if
      n_failed_rows = 0
      first_failed = 0
      do c = 1, size(keys, 2)
         ! blocks separated by two blank lines (gnuplot `index`); a gap in α inside a curve by one
         if (c > 1) then
            call write_text(file, new_line("a"), error)
            if (allocated(error)) exit
         end if
         last_i = -1
         any_written = .false.
         do i = 1, n_alpha
            do j = 1, size(per_alpha(i)%rows)
               associate (r => per_alpha(i)%rows(j))
                  if (.not. all([r%order, r%branch, r%trace_sign] == keys(:, c))) cycle
                  if (any_written .and. last_i /= i - 1) call write_text(file, "", error)
                  line = row_text(table, ids, r, c - 1, scene, self%physical)
                  call write_text(file, line, error)
                  if (r%status == status_failed) then
                     n_failed_rows = n_failed_rows + 1
                     if (first_failed == 0) then
                        first_failed = 1
                        first_failure = [r%alpha, r%beta]
                     end if
                  end if
                  last_i = i
                  any_written = .true.
               end associate
            end do
            if (allocated(error)) exit
         end do
         if (allocated(error)) exit
      end do
      call finish_output(file, error)
      if (allocated(error)) return
      n_failed_alpha = count(per_alpha%failed)
      if (n_failed_alpha > 0 .or. n_failed_rows > 0) then
         first_message = ""
         do i = 1, n_alpha
            if (per_alpha(i)%failed) then
               first_message = "; Hill's method failed at alpha = "// &
                  real_text(grid_alpha(self%grid, i))//": "// &
                  per_alpha(i)%message
               exit
            end if
         end do
         if (first_failed > 0) first_message = first_message//"; first boundary failing the check by auto at alpha = "// &
            real_text(first_failure(1))//", beta = "//real_text(first_failure(2))
         call set_error(error, err_points_failed, scene%source//": &scene: method: '"// &
            method_name(scene%method%kind)//"': "//integer_text(n_failed_rows)// &
            " boundary point(s) failed the check (status "//integer_text(status_failed)//" in "// &
            output_path(scene)//") and "//integer_text(n_failed_alpha)//" alpha value(s) have no boundaries"// &
            first_message)
      end if
   end subroutine boundaries_run

   !> The exact curves at every alpha of the grid by the model's route, before their check:
   !> Hill's method block by block in parallel (with progress per block; the blocks claimed
   !> one at a time, and with progress on one more thread keeps the line's pace while a block
   !> takes a minute), the blocks of each alpha then joined into its rows (as `hill_boundaries`
   !> and `fourier_boundaries` do); or the roots of S, alpha by alpha. An alpha where this
   !> failed has no rows and the first failure's message; `error` when the blocks cannot be
   !> allocated.
   subroutine find_hill_rows(scene, grid, per_alpha, quiet, error)
      type(scene_t), intent(in) :: scene
      type(chart_grid_t), intent(in) :: grid
      type(alpha_rows_t), intent(inout) :: per_alpha(:)
      logical, intent(in) :: quiet
      type(error_t), allocatable, intent(out) :: error  !! err_input: the blocks cannot be allocated
      type(hill_block_values_t), allocatable :: blocks(:, :)
      type(fourier_block_t), allocatable :: fourier(:, :)
      type(fourier_drive_t) :: drive
      integer, allocatable :: n_blocks(:), ids(:, :)
      type(hill_boundary_t), allocatable :: curves(:)
      type(progress_t) :: progress
      type(error_t), allocatable :: cause
      type(alpha_rows_t), allocatable :: outcomes(:, :)   ! failed and message per block
      integer :: i, k, block, n_alpha, route, next, finished
      real(wp) :: alpha
      n_alpha = size(per_alpha)
      route = curve_route(scene%model)
      if (route == route_roots .or. route == route_closed_form) then
         call progress_begin(progress, int(n_alpha, int64), quiet, "alphas")
         !$omp parallel do schedule(dynamic) default(shared) private(i, cause)
         do i = 1, n_alpha
            call find_boundary_rows(scene, grid, grid_alpha(grid, i), &
                                    per_alpha(i)%rows, cause)
            if (allocated(cause)) then
               per_alpha(i)%failed = .true.
               per_alpha(i)%message = cause%message
            end if
            call progress_step(progress)
         end do
         !$omp end parallel do
         call progress_end(progress)
         return
      end if
      allocate (outcomes(4, n_alpha), n_blocks(n_alpha), ids(4, n_alpha), stat=i)
      if (i /= 0) then
         call set_error(error, err_input, "the blocks of Hill's matrix of "//integer_text(n_alpha)// &
            " alphas cannot be allocated (out of memory)")
         return
      end if
      n_blocks = 4
      ids = 0
      if (route == route_fourier) then
         ! the blocks of each alpha's drive: four for an even g, two coupled ones otherwise
         allocate (fourier(4, n_alpha))
         do i = 1, n_alpha
            call fourier_drive(scene%model, grid_alpha(grid, i), drive, cause)
            if (allocated(cause)) then
               outcomes(1, i)%failed = .true.
               outcomes(1, i)%message = cause%message
               n_blocks(i) = 0
               cycle
            end if
            associate (list => fourier_blocks(drive))
               n_blocks(i) = size(list)
               ids(:size(list), i) = list
            end associate
         end do
      else
         allocate (blocks(4, n_alpha), stat=i)
         if (i /= 0) then
            call set_error(error, err_input, "the blocks of Hill's matrix of "//integer_text(n_alpha)// &
               " alphas cannot be allocated (out of memory)")
            return
         end if
      end if
      call progress_begin(progress, 4_int64*n_alpha, quiet, "Hill blocks")
      ! the blocks claimed one at a time by the computing threads; with progress on, one
      ! more thread keeps the line's pace while a block takes a minute (one LAPACK call on
      ! a truncation of 10^4 modes near alpha = pi^2 or at large |beta|)
      next = 0
      finished = 0
      !$omp parallel num_threads(team_size(progress)) default(shared) private(k, i, block, cause, alpha)
      if (watches(progress)) then
         call watch_progress(progress, finished, 4*n_alpha)
      else
         do
            !$omp atomic capture
            next = next + 1
            k = next
            !$omp end atomic
            if (k > 4*n_alpha) exit
            i = (k - 1)/4 + 1
            block = k - 4*(i - 1)
            alpha = grid_alpha(grid, i)
            if (route == route_fourier) then
               if (block <= n_blocks(i)) call fourier_block_values(scene%model, alpha, ids(block, i), &
                  grid%beta_min, grid%beta_max, scene%method%tolerance, fourier(block, i), cause)
            else
               call hill_block_values(scene%model, alpha, block, grid%beta_min, grid%beta_max, &
                                      scene%method%tolerance, blocks(block, i), cause)
            end if
            if (allocated(cause)) then
               outcomes(block, i)%failed = .true.
               outcomes(block, i)%message = cause%message
            end if
            call progress_step(progress)
            !$omp atomic update
            finished = finished + 1
         end do
      end if
      !$omp end parallel
      call progress_end(progress)
      do i = 1, n_alpha
         alpha = grid_alpha(grid, i)
         block = findloc(outcomes(:, i)%failed, .true., dim=1)
         if (block > 0) then
            per_alpha(i)%failed = .true.
            per_alpha(i)%message = outcomes(block, i)%message
            allocate (per_alpha(i)%rows(0))
         else if (route == route_fourier) then
            call fourier_curves(grid%beta_min, grid%beta_max, fourier(:n_blocks(i), i), curves)
            per_alpha(i)%rows = rows_of_curves(alpha, curves)
         else
            call hill_curves(scene%model, alpha, grid%beta_min, grid%beta_max, blocks(:, i), curves)
            per_alpha(i)%rows = rows_of_curves(alpha, curves)
         end if
      end do
   end subroutine find_hill_rows

   !> The threads of a loop over long units: the computing threads, and one more that
   !> watches the progress (`watch_progress`) when it is shown and OpenMP runs the loop.
   integer function team_size(progress)
      type(progress_t), intent(in) :: progress
      team_size = max_threads()
      !$ if (progress%enabled) team_size = team_size + 1
   end function team_size

   !> Whether the calling thread of a team of `team_size` watches the progress: the first,
   !> when the progress is shown and the team has the extra thread.
   logical function watches(progress)
      type(progress_t), intent(in) :: progress
      watches = .false.
      !$ watches = progress%enabled .and. omp_get_thread_num() == 0 .and. omp_get_num_threads() > max_threads()
   end function watches

   !> Until `finished` reaches `total` (the computing threads count their units there):
   !> every 0.2 s the progress line, printed when due (`progress_beat`: every 5 s off a
   !> terminal however long a unit takes).
   subroutine watch_progress(progress, finished, total)
      type(progress_t), intent(inout) :: progress
      integer, intent(inout) :: finished  !! units done (updated by the other threads)
      integer, intent(in) :: total
      type(timespec_t) :: remaining
      integer(c_int) :: status
      integer :: now
      do
         !$omp atomic read
         now = finished
         if (now >= total) exit
         status = c_nanosleep(timespec_t(0_c_long, 200000000_c_long), remaining)
         call progress_beat(progress)
      end do
   end subroutine watch_progress

   !> Every curve point of Hill's method checked by auto (`check_boundary_row`), in parallel
   !> over all alphas, with progress per point.
   subroutine check_every_row(scene, per_alpha, quiet)
      type(scene_t), intent(in) :: scene
      type(alpha_rows_t), intent(inout) :: per_alpha(:)
      logical, intent(in) :: quiet
      type(progress_t) :: progress
      integer, allocatable :: alpha_of(:), row_of(:)
      integer :: i, j, k, n
      n = 0
      do i = 1, size(per_alpha)
         n = n + size(per_alpha(i)%rows)
      end do
      allocate (alpha_of(n), row_of(n))
      k = 0
      do i = 1, size(per_alpha)
         do j = 1, size(per_alpha(i)%rows)
            k = k + 1
            alpha_of(k) = i
            row_of(k) = j
         end do
      end do
      call progress_begin(progress, int(n, int64), quiet, "curve points")
      !$omp parallel do schedule(dynamic) default(shared) private(k)
      do k = 1, n
         call check_boundary_row(scene, per_alpha(alpha_of(k))%rows(row_of(k)))
         call progress_step(progress)
      end do
      !$omp end parallel do
      call progress_end(progress)
   end subroutine check_every_row

   !> Sort curve keys (order, branch, kind) by order, then branch.
   pure subroutine sort_keys(keys)
      integer, intent(inout) :: keys(:, :)
      integer :: i, j, t(3)
      do i = 2, size(keys, 2)
         t = keys(:, i)
         j = i - 1
         do while (j >= 1)
            if (keys(1, j)*3 + keys(2, j) <= t(1)*3 + t(2)) exit
            keys(:, j + 1) = keys(:, j)
            j = j - 1
         end do
         keys(:, j + 1) = t
      end do
   end subroutine sort_keys

   !> Whether the file has the column a: a scene with `&physical` and the elastic model.
   pure logical function amplitude_column(scene, physical)
      type(scene_t), intent(in) :: scene
      type(physical_scene_t), intent(in) :: physical
      amplitude_column = physical%given .and. is_elastic_pendulum(scene%model)
   end function amplitude_column

   !> One data line: the columns `ids` of the row `r` of curve `curve`.
   function row_text(table, ids, r, curve, scene, physical) result(line)
      type(column_t), intent(in) :: table(:)  !! every column (`boundary_columns`)
      integer, intent(in) :: ids(:)           !! the columns of the file
      type(boundary_row_t), intent(in) :: r   !! the boundary point
      integer, intent(in) :: curve            !! its curve's index (from 0)
      type(scene_t), intent(in) :: scene      !! the scene
      type(physical_scene_t), intent(in) :: physical  !! its `&physical` (the task's)
      character(len=:), allocatable :: line
      character(len=400) :: buffer
      integer :: pos
      real(wp) :: values(n_curve_columns)
      values(curve_alpha) = r%alpha
      values(curve_a) = 0.0_wp
      if (amplitude_column(scene, physical)) values(curve_a) = point_amplitude(physical, 1, r%alpha, r%beta)
      values(curve_beta) = r%beta
      values(curve_kind) = real(r%trace_sign, wp)
      values(curve_order) = real(r%order, wp)
      values(curve_branch) = real(r%branch, wp)
      values(curve_index) = real(curve, wp)
      values(curve_coexist) = merge(1.0_wp, 0.0_wp, r%coexistent)
      values(curve_status) = real(r%status, wp)
      values(curve_check) = r%check
      values(curve_beta_error) = r%beta_error
      values(curve_modes) = real(r%modes, wp)
      values(curve_beta_gsl) = r%beta_gsl
      values(curve_gsl_ok) = real(r%gsl_ok, wp)
      pos = 0
      call put_row(table, ids, values, buffer, pos)
      line = buffer(:pos)
   end function row_text

   !> Header: version, scene (repeatable), model, method, columns explained.
   function header(scene, grid, n_curves) result(lines)
      type(scene_t), intent(in) :: scene
      type(chart_grid_t), intent(in) :: grid
      integer, intent(in) :: n_curves
      character(len=:), allocatable :: lines(:)
      character(len=400) :: text(18)
      integer :: n
      n = 0
      n = n + 1; text(n) = model_description(scene%model)
      if (exact_method(scene)) then
         select case (curve_route(scene%model))
         case (route_pencil)
            n = n + 1; text(n) = "method: Hill's method (eigenvalues of the banded symmetric-definite pencil, LAPACK "// &
               "dsbgv), converged in the truncation to tolerance "//real_text(scene%method%tolerance)//"*max(1,|beta|)"
         case (route_fourier)
            n = n + 1; text(n) = "method: every curve by Hill's method on the Fourier coefficients of Q - beta ("// &
               integer_text(scene%model%drive_harmonic_count())//" harmonics over the period "// &
               real_text(scene%model%period())//"; inverted banded pencil, LAPACK dsbgv), converged in the "// &
               "truncation to tolerance "//real_text(scene%method%tolerance)//"*max(1,|beta|)"
            n = n + 1; text(n) = "branch of Q without the even symmetry (sine terms): 1 = lower, 2 = upper edge "// &
               "of the tongue; coexist: 1 where the harmonics of Q - beta make the tongue's order no multiple of "// &
               "their gcd (Q of a shorter period) or vanish"
         case (route_closed_form)
            n = n + 1; text(n) = "method: every curve by root finding on the closed-form trace (method formula, exact "// &
               "for this model: its two constant pieces are Q itself), Brent's method to tolerance "// &
               real_text(scene%method%tolerance)//" from brackets of "//integer_text(max(grid%n_beta, 2))// &
                " samples over the beta window (n_beta) and, where |S -+ 2| has a local minimum between them, its "// &
               "extremum (tongues narrower than a step); Q - beta has "// &
               "infinitely many harmonics (a jump of Q), where Hill's method converges slowly"
            n = n + 1; text(n) = "branch of the roots of S: 1 = lower, 2 = upper edge of the tongue (the rank among "// &
               "the roots of its kind from below)"
         case default
            n = n + 1; text(n) = "method: every curve by root finding on S: the roots of S = +-2 by method auto "// &
               "(tolerance "//real_text(scene%method%tolerance)//"), Brent's method from brackets of "// &
               integer_text(max(grid%n_beta, 2))//" samples over the beta window (n_beta) and, where |S -+ 2| has a "// &
               "local minimum between them, its extremum (tongues narrower than a step)"
            if (scene%model%drive_harmonic_count() /= 0) then
               text(n) = trim(text(n))//"; Q - beta has infinitely many harmonics (a jump of Q), where Hill's "// &
                  "method converges slowly"
            else
               text(n) = trim(text(n))//"; Q has no form Hill's method knows"
            end if
            n = n + 1; text(n) = "branch of the roots of S: 1 = lower, 2 = upper edge of the tongue (the rank among "// &
               "the roots of its kind from below)"
         end select
         n = n + 1; text(n) = "each boundary checked by method auto: S = +-2 within 2*tolerance*max(1,|S|), or implied "// &
            "beta error <= "//real_text(beta_accuracy_factor)//"*tolerance*max(1,|beta|)"
      else
         n = n + 1; text(n) = "method: "//method_name(scene%method%kind)//merge(" (the paper's eq. (37))", &
            "                       ", method_pieces(scene%method) == 2 .and. .not. method_uses_segments(scene%method%kind))
         if (method_uses_segments(scene%method%kind)) text(n) = trim(text(n))//", "// &
            integer_text(scene%method%n_segments)//" pieces, sampling "//sampling_name(scene%method%sampling)
         n = n + 1; text(n) = "roots of S_method = +-2 by Brent's method to tolerance*max(1,|beta|), brackets from "// &
            integer_text(grid%n_beta)//" samples over the beta window (n_beta); tongues narrower than a sample "// &
            "step can be missed"
      end if
      n = n + 1; text(n) = "one block per curve (gnuplot index = curve), blocks separated by two blank lines; "// &
         integer_text(n_curves)//" curves"
      n = n + 1; text(n) = "kind: S on the curve (+2 periodic, -2 antiperiodic); order: n of a_n/b_n; branch: exact 1 = a_n "// &
         "(even), 2 = b_n (odd), approximate 1 = lower, 2 = upper edge"
      if (exact_method(scene)) then
         n = n + 1; text(n) = "coexist: 1 when both curves of this order coincide (zero-width tongue), by the structure "// &
            "of Q: elastic S = +2 tongues always, S = -2 only at alpha = 0; Mathieu only at nu = 0 (Ince)"
      else
         n = n + 1; text(n) = "coexist: 1 when both curves of this order coincide (zero-width tongue, within "// &
            real_text(coexistence_threshold)//"*tolerance*max(1,|beta|))"
      end if
      n = n + 1; text(n) = "status: 0 ok, 1 check by auto limited by round-off, 2 failed the check; check: S by auto "// &
         "at the point (approximate: S_method)"
      n = n + 1; text(n) = "beta_error: estimated error of beta; modes: Fourier modes of the truncation (approximate: pieces)"
      if (scene%model%has_witness()) then
         n = n + 1; text(n) = "beta_gsl: (pi^2/4) a_n or b_n(2 nu/pi^2) by GSL; gsl_ok: 1 agrees with Hill's method within "// &
            real_text(gsl_agreement)//"*max(1,|beta|), 2 disagrees (a GSL failure), 0 not used (order > 60 or |q| > "// &
            real_text(gsl_witness_max_q)//"; beta_gsl = beta)"
      end if
      if (.not. (in_physical_domain(grid%alpha_min, grid%beta_min) .and. &
                 in_physical_domain(grid%alpha_max, grid%beta_max))) then
         n = n + 1; text(n) = "note: the window leaves the physical domain 0 <= alpha < pi^2, 0 < beta < pi^2"
      end if
      lines = scene_header(scene, "hillstab "//version_string//": "//model_equation_text(scene%model)//"; transition "// &
                           "curves S = +-2", text(:n))
   end function header
end module hillstab_batch_tasks_boundaries

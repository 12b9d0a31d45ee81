!> Task `boundaries`: the transition curves (S = ±2) over the α grid of `&chart`,
!> inside its β window, written as one gnuplot block per curve.
!>
!> - method auto or any exact method: Hill's method (hillstab_curves_hill_method), every
!>   boundary checked independently by method auto (hillstab_curves_boundaries); a boundary
!>   that fails the check is written with status_failed and the run reports it
!>   (err_points_failed, exit status 3), it is never written as ok;
!> - method formula or segments: the roots of S_method(β) = ±2 by Brent's method on a
!>   bracket sampled at n_beta points of the window (`n_beta` is used only here);
!> - a model with an independent GSL witness (Mathieu: a_n, b_n) gets it as a column
!>   beside Hill's values.
!>
!> The α values run in parallel (OpenMP, dynamic schedule: the truncation grows
!> towards α → π²); the file is written once all are done, curve by curve.
module hillstab_batch_task_boundaries
   use hillstab_core_kinds, only: wp, int64, version_string
   use hillstab_batch_progress, only: progress_t, progress_begin, progress_update, progress_end
   use hillstab_core_error, only: error_t, set_error, err_input, err_points_failed
   use hillstab_core_status, only: status_ok, status_roundoff, status_failed
   use hillstab_hill_models, only: model_description, model_has_witness, model_witness_beta, model_is_pendulum
   use hillstab_hill_coefficient, only: in_physical_domain, sampling_name
   use hillstab_integrate_monodromy, only: method_name, method_is_exact, method_uses_segments, method_pieces
   use hillstab_curves_hill_method, only: hill_boundary_t, hill_boundaries, coexistence_threshold
   use hillstab_curves_boundaries, only: boundary_check_t, verify_boundary, approximate_root_t, approximate_boundaries, &
      beta_accuracy_factor, gsl_witness_max_q
   use hillstab_batch_scene, only: scene_t, task_t, scene_header, output_path, open_scene_output
   use hillstab_batch_declaration, only: group_t
   use hillstab_batch_scene_file, only: scene_file_t, fail
   use hillstab_batch_scene_checks, only: max_boundaries_magnitude
   use hillstab_batch_group_chart, only: chart_grid_t, chart_group, read_chart_group, grid_value
   use hillstab_batch_columns, only: column_t, style_e17, style_e4, style_integer, style_width2, style_width4, &
      columns_text, put_row, all_columns
   use hillstab_batch_output, only: output_file_t, finish_output, discard_output, write_header, write_text
   use hillstab_core_text, only: real_text, integer_text
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

   !> GSL's value counts as agreeing with Hill's when within this times max(1, |β|).
   real(wp), parameter :: gsl_agreement = 1.0e-8_wp

   !> The rows of one α.
   type :: alpha_rows_t
      type(boundary_row_t), allocatable :: rows(:)
      logical :: failed = .false.                 !! Hill's method itself failed at this α
      character(len=:), allocatable :: message    !! why
   end type alpha_rows_t

   !> The boundaries task and the grid of `&chart` (`n_beta` used by formula and segments).
   type, extends(task_t) :: boundaries_task_t
      type(chart_grid_t) :: grid  !! `&chart`
   contains
      procedure :: read => boundaries_read
      procedure :: run => boundaries_run
      procedure :: declarations => boundaries_declarations
   end type boundaries_task_t

contains

   !> `&chart`.
   function boundaries_declarations(self) result(groups)
      class(boundaries_task_t), intent(in) :: self  !! the task
      type(group_t), allocatable :: groups(:)
      allocate (groups(1))
      groups(1) = chart_group()
   end function boundaries_declarations

   !> A boundaries task before its scene is read.
   function boundaries_task() result(task)
      type(boundaries_task_t) :: task
      task%name = "boundaries"
   end function boundaries_task

   !> `&chart`, bounded for Hill's method; the curves are those of the undamped equation.
   subroutine boundaries_read(self, file, scene, error)
      class(boundaries_task_t), intent(inout) :: self  !! the task, its grid filled in
      type(scene_file_t), intent(in) :: file      !! the scene file
      type(scene_t), intent(in) :: scene          !! the `&scene` settings
      type(error_t), allocatable, intent(out) :: error  !! err_input naming file, group and variable
      if (scene%epsilon > 0.0_wp .and. .not. scene%physical) then
         call fail(error, file%path, "scene", "epsilon", "task 'boundaries' draws the undamped curves: epsilon must be 0")
         return
      end if
      allocate (self%groups(1))
      call read_chart_group(file, chart_group(), scene%model, self%grid, self%groups(1), error)
      if (allocated(error)) return
      call check_boundaries_cost(scene, self%grid, error)
   end subroutine boundaries_read

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

   !> The columns of the boundaries file (the GSL witness columns for the Mathieu model).
   function boundary_columns(mathieu) result(table)
      logical, intent(in) :: mathieu  !! add the GSL witness columns
      type(column_t), allocatable :: table(:)
      allocate (table(merge(13, 11, mathieu)))
      table(1) = column_t("alpha", "", "alpha of the boundary point", style_e17)
      table(2) = column_t("beta", "", "beta of the boundary point", style_e17)
      table(3) = column_t("kind", "", "S on the curve: +2 periodic, -2 antiperiodic", style_integer)
      table(4) = column_t("order", "", "n of a_n/b_n", style_width4)
      table(5) = column_t("branch", "", "exact 1 = a_n (even), 2 = b_n (odd); approximate 1 = lower, 2 = upper edge", &
                          style_width2)
      table(6) = column_t("curve", "", "the block's index (gnuplot index = curve)", style_width4)
      table(7) = column_t("coexist", "", "1 when both curves of this order coincide", style_integer)
      table(8) = column_t("status", "", "0 ok, 1 check by auto limited by round-off, 2 failed the check", style_integer)
      table(9) = column_t("check", "", "S by auto at the point (approximate: S_method)", style_e17)
      table(10) = column_t("beta_error", "", "estimated error of beta", style_e4)
      table(11) = column_t("modes", "", "Fourier modes of the truncation (approximate: pieces)", style_integer)
      if (mathieu) then
         table(12) = column_t("beta_gsl", "", "GSL's value of the curve", style_e17)
         table(13) = column_t("gsl_ok", "", "1 GSL agrees, 2 disagrees, 0 not used", style_integer)
      end if
   end function boundary_columns

   !> All boundaries at one α, by Hill's method (checked by auto) or by root finding.
   subroutine compute_boundary_rows(scene, grid, alpha, rows, error)
      type(scene_t), intent(in) :: scene  !! a validated boundaries scene
      type(chart_grid_t), intent(in) :: grid  !! its `&chart`
      real(wp), intent(in) :: alpha  !! the alpha of the rows
      type(boundary_row_t), allocatable, intent(out) :: rows(:)  !! one row per curve crossing the beta window
      type(error_t), allocatable, intent(out) :: error  !! what failed at this alpha; unallocated on success
      type(hill_boundary_t), allocatable :: curves(:)
      type(approximate_root_t), allocatable :: roots(:)
      type(boundary_check_t) :: check
      type(error_t), allocatable :: cause
      integer :: i, j
      logical :: available
      if (exact_method(scene)) then
         call hill_boundaries(scene%model, alpha, grid%beta_min, grid%beta_max, &
                              scene%method%tolerance, curves, error)
         if (allocated(error)) then
            allocate (rows(0))
            return
         end if
         allocate (rows(size(curves)))
         do i = 1, size(curves)
            rows(i)%alpha = alpha
            rows(i)%beta = curves(i)%beta
            rows(i)%trace_sign = curves(i)%trace_sign
            rows(i)%order = curves(i)%order
            rows(i)%branch = merge(1, 2, curves(i)%parity == 1)
            rows(i)%coexistent = curves(i)%coexistent
            rows(i)%modes = curves(i)%modes
            call verify_boundary(scene%model, alpha, curves(i)%beta, curves(i)%trace_sign, scene%method%tolerance, &
                                 check, cause)
            rows(i)%check = check%trace
            rows(i)%beta_error = max(curves(i)%error_bound, check%beta_error)
            if (allocated(cause)) then
               rows(i)%status = status_failed
               deallocate (cause)
            else if (.not. check%passed) then
               rows(i)%status = status_failed
            else if (check%roundoff) then
               rows(i)%status = status_roundoff
            end if
            if (model_has_witness(scene%model)) then
               call model_witness_beta(scene%model, curves(i)%order, curves(i)%parity, alpha, rows(i)%beta_gsl, &
                                       available)
               if (.not. available) then
                  rows(i)%gsl_ok = 0
                  rows(i)%beta_gsl = rows(i)%beta
               else if (abs(rows(i)%beta_gsl - rows(i)%beta) <= gsl_agreement*max(1.0_wp, abs(rows(i)%beta))) then
                  rows(i)%gsl_ok = 1
               else
                  rows(i)%gsl_ok = 2   ! GSL computed a value that disagrees with Hill's method: flagged
               end if
            end if
         end do
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
            if (model_has_witness(scene%model)) rows(i)%beta_gsl = rows(i)%beta
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
   end subroutine compute_boundary_rows

   !> The boundaries task.
   subroutine boundaries_run(self, scene, quiet, error)
      class(boundaries_task_t), intent(in) :: self  !! the task
      type(scene_t), intent(in) :: scene  !! a validated boundaries scene
      logical, intent(in) :: quiet  !! no progress on stderr (alphas done)
      type(error_t), allocatable, intent(out) :: error  !! what failed; unallocated on success
      type(output_file_t) :: file
      type(progress_t) :: progress
      integer(int64) :: done
      type(alpha_rows_t), allocatable :: per_alpha(:)
      integer, allocatable :: keys(:, :)
      integer :: i, j, c, n_alpha, n_failed_rows, n_failed_alpha, last_i, first_failed
      logical :: mathieu, found, any_written
      character(len=:), allocatable :: line, first_message
      type(error_t), allocatable :: cause
      real(wp) :: first_failure(2)
      type(column_t), allocatable :: table(:)
      if (scene%epsilon > 0.0_wp) then   ! damping from &physical kappa
         call set_error(error, err_input, scene%source//": &physical: kappa: task 'boundaries' draws the "// &
            "undamped curves: kappa must be 0")
         return
      end if
      call open_scene_output(scene, file, error)
      if (allocated(error)) return
      mathieu = model_has_witness(scene%model)
      n_alpha = self%grid%n_alpha
      allocate (per_alpha(n_alpha))
      call progress_begin(progress, int(n_alpha, int64), quiet, "alphas")
      done = 0
      !$omp parallel do schedule(dynamic) default(shared) private(i, cause)
      do i = 1, n_alpha
         call compute_boundary_rows(scene, self%grid, grid_value(self%grid%alpha_min, self%grid%alpha_max, n_alpha, i), &
                                    per_alpha(i)%rows, cause)
         if (allocated(cause)) then
            per_alpha(i)%failed = .true.
            per_alpha(i)%message = cause%message
         end if
         !$omp critical (boundaries_progress)
         done = done + 1
         call progress_update(progress, done)
         !$omp end critical (boundaries_progress)
      end do
      !$omp end parallel do
      call progress_end(progress)

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

      table = boundary_columns(mathieu)
      call write_header(file, header(scene, self%grid, size(keys, 2)), columns_text(table, all_columns(table)), error)
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
                  line = row_text(table, r, c - 1, mathieu)
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
                  real_text(grid_value(self%grid%alpha_min, self%grid%alpha_max, n_alpha, i))//": "// &
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

   !> One data line.
   function row_text(table, r, curve, mathieu) result(line)
      type(column_t), intent(in) :: table(:)
      type(boundary_row_t), intent(in) :: r
      integer, intent(in) :: curve
      logical, intent(in) :: mathieu
      character(len=:), allocatable :: line
      character(len=400) :: buffer
      integer :: pos
      real(wp), allocatable :: values(:)
      values = [r%alpha, r%beta, real(r%trace_sign, wp), real(r%order, wp), real(r%branch, wp), real(curve, wp), &
                merge(1.0_wp, 0.0_wp, r%coexistent), real(r%status, wp), r%check, r%beta_error, real(r%modes, wp)]
      if (mathieu) values = [values, r%beta_gsl, real(r%gsl_ok, wp)]
      pos = 0
      call put_row(table, all_columns(table), values, buffer, pos)
      line = buffer(:pos)
   end function row_text

   !> Header: version, scene (repeatable), model, method, columns explained.
   function header(scene, grid, n_curves) result(lines)
      type(scene_t), intent(in) :: scene
      type(chart_grid_t), intent(in) :: grid
      integer, intent(in) :: n_curves
      character(len=:), allocatable :: lines(:)
      character(len=240) :: text(16)
      integer :: n
      n = 0
      n = n + 1; text(n) = model_description(scene%model)
      if (exact_method(scene)) then
         n = n + 1; text(n) = "method: Hill's method (eigenvalues of the banded symmetric-definite pencil, LAPACK "// &
            "dsbgv), converged in the truncation to tolerance "//real_text(scene%method%tolerance)//"*max(1,|beta|)"
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
      if (model_has_witness(scene%model)) then
         n = n + 1; text(n) = "beta_gsl: (pi^2/4) a_n or b_n(2 nu/pi^2) by GSL; gsl_ok: 1 agrees with Hill's method within "// &
            real_text(gsl_agreement)//"*max(1,|beta|), 2 disagrees (a GSL failure), 0 not used (order > 60 or |q| > "// &
            real_text(gsl_witness_max_q)//"; beta_gsl = beta)"
      end if
      if (.not. (in_physical_domain(grid%alpha_min, grid%beta_min) .and. &
                 in_physical_domain(grid%alpha_max, grid%beta_max))) then
         n = n + 1; text(n) = "note: the window leaves the physical domain 0 <= alpha < pi^2, 0 < beta < pi^2"
      end if
      lines = scene_header(scene, "hillstab "//version_string//": x'' + Q(tau) x = 0, period 2 in tau; transition "// &
                           "curves S = +-2", text(:n))
   end function header
end module hillstab_batch_task_boundaries

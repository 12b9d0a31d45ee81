!> C-callable entry points that compute many points of a system at once, as the tasks do:
!> `hillstab_system_points` (each point alone, the lines of task `points`) and
!> `hillstab_system_chart` (rows of one α sharing their nodes, the lines of task `chart`),
!> both on OpenMP threads, returning the values of the columns of a system's files
!> (`hillstab_system_column_name`: alpha, beta, trace, a2, overflow, stable, kind,
!> lambda_max, mu, argument, mu_1 … mu_n, defect, error_estimate, status, steps) and a
!> status per point: 0 within the tolerance, 1 round-off limited, 2 failed (placeholders, as
!> a file writes them). A call whose input is invalid (a null pointer, an unknown method, a
!> tolerance outside (1e-15, 1), a non-finite α or β, a negative or non-finite ε, an ε ≠ 0
!> for a system with a damping of its own, a point beyond what the system's methods
!> integrate) computes nothing and names the argument and the point; one whose points failed
!> returns HILLSTAB_ERR_POINTS_FAILED with every value written. A system whose damping
!> changes from row to row (the equations system) is prepared at each point's α, as the
!> tasks prepare it (hillstab_batch_tasks_system `system_values`, `system_row_values`).
!> Conventions as in hillstab_interop_capi_system.
!>
!>```c
!> double alpha[2] = {0.1, 0.2}, beta[2] = {1.0, 1.0}, eps[2] = {0, 0};
!> int n_columns, status[2];
!> hillstab_system_column_count(pair, &n_columns);
!> double *values = malloc(2 * n_columns * sizeof(double));
!> hillstab_system_points(pair, 2, alpha, beta, eps, HILLSTAB_METHOD_AUTO, 1e-10, 0, values, status);
!>```
module hillstab_interop_capi_system_batch
   use, intrinsic :: iso_c_binding, only: c_int, c_double, c_char, c_size_t, c_ptr, c_f_pointer
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use hillstab_core_kinds, only: wp, int64
   use hillstab_core_error, only: error_t, set_error, err_invalid_parameter, err_points_failed
   use hillstab_core_status, only: status_failed
   use hillstab_core_text, only: integer_text, real_text
   use hillstab_hill_system, only: system_form_t, prepare_system, check_system_point
   use hillstab_integrate_system, only: system_method_t
   use hillstab_batch_scene_group_chart, only: chart_grid_t, grid_alpha, grid_beta, scale_linear, scale_refusal
   use hillstab_batch_scene_checks, only: max_grid_count
   use hillstab_batch_tasks_system_values, only: system_values, system_row_values
   use hillstab_batch_tasks_floquet_columns, only: system_column_names, n_fixed, status_column
   use hillstab_interop_sizes, only: count_refusal
   use hillstab_interop_capi_models, only: copy_text
   use hillstab_interop_capi_system, only: system_handle_t, handle_system, check_output, outcome_status, &
      check_method_tolerance, own_damping_refusal
   !$ use omp_lib, only: omp_get_max_threads
   implicit none
   private
   public :: hillstab_c_system_column_count, hillstab_c_system_column_name, hillstab_c_system_points, &
      hillstab_c_system_chart, hillstab_c_system_chart_scaled, hillstab_c_system_tau_rate

contains

   !> `int hillstab_system_column_count(const hillstab_system *system, int *count)`: the
   !> values a point has (14 + n).
   function hillstab_c_system_column_count(system, count) result(status) &
      bind(C, name="hillstab_system_column_count")
      type(c_ptr), value, intent(in) :: system  !! the handle
      type(c_ptr), value, intent(in) :: count   !! receives the count (an `int *`)
      integer(c_int) :: status
      character(len=*), parameter :: where = "hillstab_system_column_count"
      type(system_handle_t), pointer :: handle
      type(error_t), allocatable :: error
      integer(c_int), pointer :: out
      call handle_system(where, system, handle, error)
      call check_output(where, "count", count, error)
      if (.not. allocated(error)) call complete(where, handle, error)
      if (.not. allocated(error)) then
         call c_f_pointer(count, out)
         out = int(n_fixed + handle%system%dof(), c_int)
      end if
      status = outcome_status(error)
   end function hillstab_c_system_column_count

   !> `int hillstab_system_tau_rate(const hillstab_system *system, size_t n, const double *alpha,
   !> const double *beta, double *rate)`: dτ/dt at the n points (α_j, β_j), which turns a rate
   !> per unit τ (mu, mu_1 … mu_n) into one per unit of the system's own time t: a system of
   !> equations' Ω/π at the point; 0 for a system in τ alone and at a point outside the domain.
   function hillstab_c_system_tau_rate(system, n, alpha, beta, rate) result(status) &
      bind(C, name="hillstab_system_tau_rate")
      type(c_ptr), value, intent(in) :: system  !! the handle
      integer(c_size_t), value, intent(in) :: n  !! the number of points
      real(c_double), intent(in) :: alpha(*), beta(*)  !! the points
      real(c_double), intent(inout) :: rate(*)  !! receives dτ/dt at each point
      integer(c_int) :: status
      character(len=*), parameter :: where = "hillstab_system_tau_rate"
      type(system_handle_t), pointer :: handle
      type(error_t), allocatable :: error
      integer(int64) :: j
      call handle_system(where, system, handle, error)
      if (.not. allocated(error)) call complete(where, handle, error)
      if (.not. allocated(error)) then
         do j = 1, int(n, int64)
            rate(j) = handle%system%tau_rate(real(alpha(j), wp), real(beta(j), wp))
         end do
      end if
      status = outcome_status(error)
   end function hillstab_c_system_tau_rate

   !> `int hillstab_system_column_name(const hillstab_system *system, int index, char *name,
   !> size_t length)`: the name of value `index` (0 … count − 1), as a file's `# columns:`
   !> line names it.
   function hillstab_c_system_column_name(system, index, buffer, length) result(status) &
      bind(C, name="hillstab_system_column_name")
      type(c_ptr), value, intent(in) :: system  !! the handle
      integer(c_int), value, intent(in) :: index  !! 0 … hillstab_system_column_count − 1
      character(kind=c_char), intent(inout) :: buffer(*)  !! receives the name
      integer(c_size_t), value, intent(in) :: length  !! size of buffer in bytes
      integer(c_int) :: status
      character(len=*), parameter :: where = "hillstab_system_column_name"
      type(system_handle_t), pointer :: handle
      type(error_t), allocatable :: error
      character(len=14), allocatable :: names(:)
      call handle_system(where, system, handle, error)
      if (.not. allocated(error)) call complete(where, handle, error)
      if (.not. allocated(error)) then
         names = system_column_names(handle%system%dof())
         if (index < 0 .or. index >= size(names)) then
            call set_error(error, err_invalid_parameter, where//": index: "//integer_text(int(index))// &
               " outside 0 to "//integer_text(size(names) - 1))
         else
            call copy_text(trim(names(index + 1)), buffer, length)
         end if
      end if
      status = outcome_status(error)
   end function hillstab_c_system_column_name

   !> `int hillstab_system_points(const hillstab_system *system, size_t n, const double
   !> *alpha, const double *beta, const double *epsilon, int method, double tolerance, int
   !> threads, double *values, int *status)`: the values (`values[j][k]`, k over the columns
   !> of hillstab_system_column_name) and status of the n points (α_j, β_j, ε_j), each
   !> computed alone as task `points` computes it, in parallel on `threads` threads (0:
   !> OpenMP's default).
   function hillstab_c_system_points(system, n, alpha, beta, epsilon, method, tolerance, threads, values, status) &
      result(code) bind(C, name="hillstab_system_points")
      type(c_ptr), value, intent(in) :: system  !! the handle
      integer(c_size_t), value, intent(in) :: n  !! number of points
      real(c_double), intent(in) :: alpha(*), beta(*), epsilon(*)  !! the points and their damping ε_j ≥ 0
      integer(c_int), value, intent(in) :: method  !! HILLSTAB_METHOD_AUTO, _MAGNUS4, _MAGNUS6, _RK or _GSL
      real(c_double), value, intent(in) :: tolerance  !! the target error of Φ
      integer(c_int), value, intent(in) :: threads  !! threads (0: the OpenMP default)
      type(c_ptr), value, intent(in) :: values  !! receives n × (14 + dof) doubles
      type(c_ptr), value, intent(in) :: status  !! receives n ints
      integer(c_int) :: code
      character(len=*), parameter :: where = "hillstab_system_points"
      type(system_handle_t), pointer :: handle
      type(error_t), allocatable :: error
      type(system_form_t) :: form
      real(c_double), pointer :: v(:, :)
      integer(c_int), pointer :: s(:)
      integer :: j, n_points, n_columns, n_failed
      call start(where, system, n, method, tolerance, threads, handle, n_points, error)
      call check_output(where, "values", values, error)
      call check_output(where, "status", status, error)
      if (.not. allocated(error)) then
         do j = 1, n_points
            call check_input_point(where, handle, j - 1, alpha(j), beta(j), epsilon(j), error)
            if (allocated(error)) exit
         end do
      end if
      ! the system checked as task points checks it (prepared at its given damping; a system
      ! whose damping changes with α is prepared again at each point by system_values)
      if (.not. allocated(error) .and. n_points > 0) then
         call prepare_system(handle%system, real(epsilon(1), wp), form, error)
         if (allocated(error)) error%message = where//": "//error%message
      end if
      if (.not. allocated(error) .and. n_points > 0) then
         n_columns = n_fixed + handle%system%dof()
         call c_f_pointer(values, v, [n_columns, n_points])
         call c_f_pointer(status, s, [n_points])
         ! runs of 8 points, each run preparing the system at its points' damping
         !$omp parallel do schedule(dynamic) num_threads(thread_count(threads)) default(shared) private(j)
         do j = 1, n_points, 8
            call run_values(handle, method, tolerance, alpha(j:min(j + 7, n_points)), beta(j:min(j + 7, n_points)), &
                            epsilon(j:min(j + 7, n_points)), v(:, j:min(j + 7, n_points)))
         end do
         !$omp end parallel do
         s = int(nint(v(status_column(handle%system%dof()), :)), c_int)
         n_failed = count(s == status_failed)
         if (n_failed > 0) then
            j = findloc(s, int(status_failed, c_int), dim=1)
            call set_error(error, err_points_failed, where//": "//integer_text(n_failed)//" of "// &
               integer_text(n_points)//" point(s) failed (status 2, placeholders), the first point "// &
               integer_text(j - 1)//" (alpha = "//real_text(real(alpha(j), wp))//", beta = "// &
               real_text(real(beta(j), wp))//")")
         end if
      end if
      code = outcome_status(error)
   end function hillstab_c_system_points

   !> `int hillstab_system_chart(const hillstab_system *system, double alpha_min, double
   !> alpha_max, size_t n_alpha, double beta_min, double beta_max, size_t n_beta, double
   !> epsilon, int method, double tolerance, int threads, double *alpha, double *beta, double
   !> *values, int *status)`: the chart of task `chart` over n_alpha values of α and n_beta
   !> values of β (both ends included, equally spaced), returned in `alpha`, `beta`,
   !> `values[i][j][k]` and `status[i][j]` (α index i outer), the rows on `threads` threads,
   !> the points of a row sharing their nodes as the task's do.
   function hillstab_c_system_chart(system, alpha_min, alpha_max, n_alpha, beta_min, beta_max, n_beta, epsilon, &
                                    method, tolerance, threads, alphas, betas, values, status) result(code) &
      bind(C, name="hillstab_system_chart")
      type(c_ptr), value, intent(in) :: system  !! the handle
      real(c_double), value, intent(in) :: alpha_min, alpha_max  !! first and last α
      integer(c_size_t), value, intent(in) :: n_alpha  !! number of α values (rows)
      real(c_double), value, intent(in) :: beta_min, beta_max  !! first and last β
      integer(c_size_t), value, intent(in) :: n_beta  !! number of β values (per row)
      real(c_double), value, intent(in) :: epsilon  !! damping ε ≥ 0
      integer(c_int), value, intent(in) :: method  !! HILLSTAB_METHOD_AUTO, _MAGNUS4, _MAGNUS6, _RK or _GSL
      real(c_double), value, intent(in) :: tolerance  !! the target error of Φ
      integer(c_int), value, intent(in) :: threads  !! threads (0: the OpenMP default)
      type(c_ptr), value, intent(in) :: alphas  !! receives the n_alpha values of α
      type(c_ptr), value, intent(in) :: betas   !! receives the n_beta values of β
      type(c_ptr), value, intent(in) :: values  !! receives n_alpha × n_beta × (14 + dof) doubles
      type(c_ptr), value, intent(in) :: status  !! receives n_alpha × n_beta ints
      integer(c_int) :: code
      code = system_chart("hillstab_system_chart", system, alpha_min, alpha_max, n_alpha, scale_linear, beta_min, &
                          beta_max, n_beta, scale_linear, epsilon, method, tolerance, threads, alphas, betas, values, &
                          status)
   end function hillstab_c_system_chart

   !> `int hillstab_system_chart_scaled(const hillstab_system *system, double alpha_min,
   !> double alpha_max, size_t n_alpha, int alpha_scale, double beta_min, double beta_max,
   !> size_t n_beta, int beta_scale, double epsilon, int method, double tolerance, int threads,
   !> double *alpha, double *beta, double *values, int *status)`: `hillstab_system_chart` with
   !> the scale of each axis, HILLSTAB_SCALE_LINEAR (0) or HILLSTAB_SCALE_LOG (1: geometric,
   !> both ends in (0, 1e300]), the values of task `chart` with `&chart alpha_scale, beta_scale`.
   function hillstab_c_system_chart_scaled(system, alpha_min, alpha_max, n_alpha, alpha_scale, beta_min, beta_max, &
                                           n_beta, beta_scale, epsilon, method, tolerance, threads, alphas, betas, &
                                           values, status) result(code) bind(C, name="hillstab_system_chart_scaled")
      type(c_ptr), value, intent(in) :: system  !! the handle
      real(c_double), value, intent(in) :: alpha_min, alpha_max  !! first and last α
      integer(c_size_t), value, intent(in) :: n_alpha  !! number of α values (rows)
      real(c_double), value, intent(in) :: beta_min, beta_max  !! first and last β
      integer(c_size_t), value, intent(in) :: n_beta  !! number of β values (per row)
      integer(c_int), value, intent(in) :: alpha_scale, beta_scale  !! HILLSTAB_SCALE_LINEAR or _LOG
      real(c_double), value, intent(in) :: epsilon  !! damping ε ≥ 0
      integer(c_int), value, intent(in) :: method  !! HILLSTAB_METHOD_AUTO, _MAGNUS4, _MAGNUS6, _RK or _GSL
      real(c_double), value, intent(in) :: tolerance  !! the target error of Φ
      integer(c_int), value, intent(in) :: threads  !! threads (0: the OpenMP default)
      type(c_ptr), value, intent(in) :: alphas  !! receives the n_alpha values of α
      type(c_ptr), value, intent(in) :: betas   !! receives the n_beta values of β
      type(c_ptr), value, intent(in) :: values  !! receives n_alpha × n_beta × (14 + dof) doubles
      type(c_ptr), value, intent(in) :: status  !! receives n_alpha × n_beta ints
      integer(c_int) :: code
      code = system_chart("hillstab_system_chart_scaled", system, alpha_min, alpha_max, n_alpha, int(alpha_scale), &
                          beta_min, beta_max, n_beta, int(beta_scale), epsilon, method, tolerance, threads, alphas, &
                          betas, values, status)
   end function hillstab_c_system_chart_scaled

   !> The chart of `hillstab_system_chart_scaled`, its messages naming `where`.
   function system_chart(where, system, alpha_min, alpha_max, n_alpha, alpha_scale, beta_min, beta_max, n_beta, &
                         beta_scale, epsilon, method, tolerance, threads, alphas, betas, values, status) result(code)
      character(len=*), intent(in) :: where  !! the entry point called
      type(c_ptr), intent(in) :: system  !! the handle
      real(c_double), value, intent(in) :: alpha_min, alpha_max  !! first and last α
      integer(c_size_t), value, intent(in) :: n_alpha  !! number of α values (rows)
      real(c_double), value, intent(in) :: beta_min, beta_max  !! first and last β
      integer(c_size_t), value, intent(in) :: n_beta  !! number of β values (per row)
      integer, intent(in) :: alpha_scale, beta_scale  !! scale_linear or scale_log
      real(c_double), value, intent(in) :: epsilon  !! damping ε ≥ 0
      integer(c_int), value, intent(in) :: method  !! HILLSTAB_METHOD_AUTO, _MAGNUS4, _MAGNUS6, _RK or _GSL
      real(c_double), value, intent(in) :: tolerance  !! the target error of Φ
      integer(c_int), value, intent(in) :: threads  !! threads (0: the OpenMP default)
      type(c_ptr), value, intent(in) :: alphas  !! receives the n_alpha values of α
      type(c_ptr), value, intent(in) :: betas   !! receives the n_beta values of β
      type(c_ptr), value, intent(in) :: values  !! receives n_alpha × n_beta × (14 + dof) doubles
      type(c_ptr), value, intent(in) :: status  !! receives n_alpha × n_beta ints
      integer(c_int) :: code
      type(system_handle_t), pointer :: handle
      type(error_t), allocatable :: error
      type(system_form_t) :: form
      real(c_double), pointer :: a(:), b(:), v(:, :, :)
      integer(c_int), pointer :: s(:, :)
      character(len=400), allocatable :: failures(:)
      integer, allocatable :: n_failed(:)
      integer :: i, j, rows, columns, first
      type(chart_grid_t) :: grid
      call start(where, system, n_alpha, method, tolerance, threads, handle, rows, error)
      if (.not. allocated(error)) then
         if (len(count_refusal("n_beta", n_beta, max_grid_count)) > 0) then
            call set_error(error, err_invalid_parameter, where//": "//count_refusal("n_beta", n_beta, max_grid_count))
         else if (int(n_alpha, c_size_t)*int(n_beta, c_size_t) > int(max_grid_count, c_size_t)) then
            call set_error(error, err_invalid_parameter, where//": n_alpha * n_beta exceeds the limit of "// &
               integer_text(max_grid_count)//" points")
         end if
      end if
      if (.not. allocated(error)) then
         if (.not. all(ieee_is_finite([alpha_min, alpha_max, beta_min, beta_max]))) then
            continue  ! named by the corners' check below
         else if (len(scale_refusal("alpha", alpha_scale, alpha_min, alpha_max)) > 0) then
            call set_error(error, err_invalid_parameter, where//": "//scale_refusal("alpha", alpha_scale, alpha_min, &
               alpha_max))
         else if (len(scale_refusal("beta", beta_scale, beta_min, beta_max)) > 0) then
            call set_error(error, err_invalid_parameter, where//": "//scale_refusal("beta", beta_scale, beta_min, &
               beta_max))
         end if
      end if
      call check_output(where, "alpha", alphas, error)
      call check_output(where, "beta", betas, error)
      call check_output(where, "values", values, error)
      call check_output(where, "status", status, error)
      if (.not. allocated(error)) then
         columns = int(n_beta)
         ! the corners bound every point of the grid
         call check_input_point(where, handle, -1, alpha_min, beta_min, epsilon, error)
         if (.not. allocated(error)) call check_input_point(where, handle, -1, alpha_min, beta_max, epsilon, error)
         if (.not. allocated(error)) call check_input_point(where, handle, -1, alpha_max, beta_min, epsilon, error)
         if (.not. allocated(error)) call check_input_point(where, handle, -1, alpha_max, beta_max, epsilon, error)
      end if
      ! checked as task chart checks it; a row-dependent system is prepared again per point
      ! (system_row_values)
      if (.not. allocated(error) .and. rows > 0 .and. columns > 0) then
         call prepare_system(handle%system, real(epsilon, wp), form, error)
         if (allocated(error)) error%message = where//": "//error%message
      end if
      if (.not. allocated(error) .and. rows > 0 .and. columns > 0) then
         call c_f_pointer(alphas, a, [rows])
         call c_f_pointer(betas, b, [columns])
         call c_f_pointer(values, v, [n_fixed + handle%system%dof(), columns, rows])
         call c_f_pointer(status, s, [columns, rows])
         grid = chart_grid_t(alpha_min, alpha_max, rows, beta_min, beta_max, columns, alpha_scale, beta_scale)
         a = [(grid_alpha(grid, i), i=1, rows)]
         b = [(grid_beta(grid, j), j=1, columns)]
         allocate (failures(rows), n_failed(rows))
         !$omp parallel do schedule(dynamic, 1) num_threads(thread_count(threads)) default(shared) private(i)
         do i = 1, rows
            call system_row_values(handle%system, form, system_method_t(int(method), real(tolerance, wp)), &
                                   real(a(i), wp), real(b, wp), v(:, :, i), n_failed(i), failures(i))
            s(:, i) = int(nint(v(status_column(form%n), :, i)), c_int)
         end do
         !$omp end parallel do
         if (sum(n_failed) > 0) then
            first = findloc(n_failed > 0, .true., dim=1)
            call set_error(error, err_points_failed, where//": "//integer_text(sum(n_failed))//" of "// &
               integer_text(rows*columns)//" point(s) failed (status 2, placeholders), the first at "// &
               trim(failures(first)))
         end if
      end if
      code = outcome_status(error)
   end function system_chart

   !> A run of points of `hillstab_system_points`, each computed alone, the system prepared
   !> again where a point's damping differs from the one before (a system valid at one ε is
   !> valid at every finite ε ≥ 0; `system_values` prepares a row-dependent system at each
   !> point's α).
   subroutine run_values(handle, method, tolerance, alpha, beta, epsilon, v)
      type(system_handle_t), intent(in) :: handle  !! the system
      integer(c_int), intent(in) :: method  !! the method's code
      real(c_double), intent(in) :: tolerance  !! the target error of Φ
      real(c_double), intent(in) :: alpha(:), beta(:), epsilon(:)  !! the points and their damping
      real(c_double), intent(out) :: v(:, :)  !! their values
      type(system_form_t) :: form
      type(error_t), allocatable :: cause
      character(len=:), allocatable :: message
      logical :: failed
      integer :: j
      do j = 1, size(alpha)
         if (j == 1) then
            call prepare_system(handle%system, real(epsilon(j), wp), form, cause)
         else if (abs(epsilon(j) - epsilon(j - 1)) > 0.0_wp) then
            call prepare_system(handle%system, real(epsilon(j), wp), form, cause)
         end if
         call system_values(handle%system, form, system_method_t(int(method), real(tolerance, wp)), &
                            real(alpha(j), wp), real(beta(j), wp), v(:, j), failed, message)
      end do
   end subroutine run_values

   !> The checks every batch makes first: the handle, a complete system, the count, the
   !> method and tolerance, the threads.
   subroutine start(where, system, n, method, tolerance, threads, handle, count, error)
      character(len=*), intent(in) :: where  !! the entry point
      type(c_ptr), intent(in) :: system  !! the handle
      integer(c_size_t), intent(in) :: n  !! the points (or rows) asked for
      integer(c_int), intent(in) :: method  !! the method's code
      real(c_double), intent(in) :: tolerance  !! the target error of Φ
      integer(c_int), intent(in) :: threads  !! threads (0: the OpenMP default)
      type(system_handle_t), pointer, intent(out) :: handle  !! the system
      integer, intent(out) :: count  !! n, checked
      type(error_t), allocatable, intent(out) :: error  !! the first thing wrong
      count = 0
      call handle_system(where, system, handle, error)
      if (allocated(error)) return
      call complete(where, handle, error)
      if (allocated(error)) return
      if (len(count_refusal("n", n, max_grid_count)) > 0) then
         call set_error(error, err_invalid_parameter, where//": "//count_refusal("n", n, max_grid_count))
         return
      end if
      count = int(n)
      call check_method_tolerance(method, tolerance, error)
      if (.not. allocated(error) .and. threads < 0) call set_error(error, err_invalid_parameter, &
         "threads: must be >= 0 (0: the OpenMP default), got "//integer_text(int(threads)))
      if (allocated(error)) error%message = where//": "//error%message
   end subroutine start

   !> err_invalid_parameter when the system's variables are incomplete or inconsistent.
   subroutine complete(where, handle, error)
      character(len=*), intent(in) :: where  !! the entry point
      type(system_handle_t), intent(in) :: handle  !! the system
      type(error_t), allocatable, intent(out) :: error  !! what is missing
      call handle%system%check_values(error)
      if (allocated(error)) error%message = where//": "//error%message
   end subroutine complete

   !> A point's α and β finite, ε finite and ≥ 0 (0 for a system with a damping of its own),
   !> and within what the methods integrate; the message names the point (`index` ≥ 0) or
   !> the grid.
   subroutine check_input_point(where, handle, index, alpha, beta, epsilon, error)
      character(len=*), intent(in) :: where  !! the entry point
      type(system_handle_t), intent(in) :: handle  !! the system
      integer, intent(in) :: index  !! the point's index from 0 (−1: a corner of a chart)
      real(c_double), intent(in) :: alpha, beta, epsilon  !! the point
      type(error_t), allocatable, intent(inout) :: error  !! what is wrong
      character(len=:), allocatable :: place
      if (index >= 0) then
         place = "point "//integer_text(index)
      else
         place = "the grid"
      end if
      if (.not. ieee_is_finite(alpha)) then
         call set_error(error, err_invalid_parameter, where//": alpha: "//place//": must be finite")
      else if (.not. ieee_is_finite(beta)) then
         call set_error(error, err_invalid_parameter, where//": beta: "//place//": must be finite")
      else if (.not. ieee_is_finite(epsilon)) then
         call set_error(error, err_invalid_parameter, where//": epsilon: "//place//": must be finite and >= 0")
      else if (epsilon < 0.0_wp) then
         call set_error(error, err_invalid_parameter, where//": epsilon: "//place//": must be finite and >= 0, got "// &
            real_text(real(epsilon, wp)))
      else if (.not. handle%system%takes_scene_damping() .and. epsilon > 0.0_wp) then
         call own_damping_refusal(handle%system, real(epsilon, wp), place//": ", error)
         error%message = where//": "//error%message
      else
         call check_system_point(handle%system, real(alpha, wp), real(beta, wp), error)
         if (allocated(error)) error%message = where//": "//place//" (alpha = "//real_text(real(alpha, wp))// &
            ", beta = "//real_text(real(beta, wp))//"): "//error%message
      end if
   end subroutine check_input_point

   !> Threads to use: `threads` when positive, else OpenMP's default.
   integer function thread_count(threads)
      integer(c_int), intent(in) :: threads  !! asked for (0: the default)
      thread_count = 1
      !$ thread_count = omp_get_max_threads()
      if (threads > 0) thread_count = int(threads)
   end function thread_count
end module hillstab_interop_capi_system_batch

!> C-callable batch entry points: arrays of points in, arrays of values out, the points
!> computed in parallel (OpenMP) inside the call, so that a caller (a Python binding, a C
!> program) never loops over points. Each point gets the values of a chart or points file
!> (hillstab_batch_tasks_chart_columns) and a per-point status; the computations are the
!> tasks' own, so the values equal the command line's to the bit for the same model,
!> method and tolerance:
!>
!> - `hillstab_points`: the points (α_j, β_j, ε_j) one by one, as task `points` computes
!>   them (each point a batch of one, `set_from_trace`);
!> - `hillstab_chart`, `hillstab_chart_scaled`: the grid of task `chart` (`grid_alpha`,
!>   `grid_beta`; linear or log axes), row by row as task `chart`
!>   computes it: with at least four rows a thread, whole rows in parallel; with fewer, each
!>   row in parallel chunks sharing the meshes `prepare_batch` makes for it; verdicts only
!>   (`set_from_trace` of the verdicts) when only the verdicts are needed (HILLSTAB_NEED_VERDICT);
!> - `hillstab_physical`: α, β and ε of a pendulum in SI units (eqs. (4), (24), (46)).
!>
!> The values of a point are HILLSTAB_VALUE_COUNT doubles, indexed by HILLSTAB_VALUE_*
!> (`value_*` here, counted from 0). A point whose computation failed has status 2 and the
!> files' placeholders (S 0, stable −1, λ_max −1, log10|S| −999, overflow −1, error
!> estimate −1; the logarithms and μ 0); status 1 marks a value limited by round-off (the
!> best double precision allows). Bad input (a model that is not complete, a point outside
!> the model's domain, a method that cannot run) fails the whole call before any work:
!> err_invalid_parameter, the message in `hillstab_last_error` naming the point, the
!> outputs untouched.
!>
!>```c
!> double values[2][HILLSTAB_VALUE_COUNT]; int status[2];
!> double alpha[2] = {3.7, 9.0}, beta[2] = {2.47, 2.47}, epsilon[2] = {0.0, 0.0};
!> hillstab_points(model, 2, alpha, beta, epsilon, HILLSTAB_METHOD_AUTO, 0, 0, 1e-10,
!>                 HILLSTAB_NEED_TRACE, 0, 0, &values[0][0], status);
!>```
module hillstab_interop_capi_batch
   use, intrinsic :: iso_c_binding, only: c_int, c_double, c_size_t, c_ptr
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   !$ use omp_lib, only: omp_get_max_threads
   use hillstab_core_kinds, only: wp, int64
   use hillstab_core_error, only: error_t, set_error, err_invalid_parameter
   use hillstab_core_status, only: status_ok, status_roundoff, status_failed
   use hillstab_core_text, only: real_text, integer_text
   use hillstab_hill_model, only: hill_model_t, hill_point_t, check_point, check_batch
   use hillstab_hill_transfer, only: trace_t
   use hillstab_hill_floquet, only: floquet_t, set_from_trace
   use hillstab_hill_units, only: physical_t, physical_beta, physical_epsilon, check_physical
   use hillstab_hill_model_pendulum, only: pendulum_alpha
   use hillstab_integrate_monodromy, only: method_t, monodromy_trace, monodromy_trace_batch, batch_plan_t, &
      prepare_batch, method_name, method_table, need_verdict, need_growth, need_trace
   use hillstab_batch_scene_group_chart, only: chart_grid_t, grid_alpha, grid_beta, scale_linear, scale_refusal
   use hillstab_batch_scene_checks, only: max_grid_count
   use hillstab_batch_tasks_floquet_columns, only: n_chart_columns, chart_values, chart_placeholders, col_s, &
      col_log10_abs_s, col_overflow, col_stable, col_stable_paper, col_lambda_max, col_mu, col_error_estimate, &
      col_kind, col_argument
   use hillstab_interop_outcome, only: record_outcome
   use hillstab_interop_sizes, only: count_refusal, row_extent
   use hillstab_interop_capi_models, only: model_handle_t, handle_model
   implicit none
   private
   public :: hillstab_c_points, hillstab_c_chart, hillstab_c_chart_scaled, hillstab_c_physical
   public :: value_trace, value_log_abs_trace, value_log10_abs_trace, value_overflow, value_stable, &
      value_stable_paper, value_lambda_max, value_log_modulus_max, value_log_modulus_min, value_exponent, &
      value_error_estimate, value_kind, value_argument, value_count

   !> The values of a point, by their index counted from 0 (the header's HILLSTAB_VALUE_*):
   !> S (±1e300 with overflow 1 beyond), ln|S|, log10|S| (at least −300), overflow (1 when
   !> |S| > 1e300), stable (1, 0 or 0.5 when marginal), stable_paper (|S₁| ≤ 2), λ_max (at
   !> most 1e300), ln|λ| of both multipliers of x (largest first), μ = ln|λ_max|/2 per unit
   !> τ, the method's error estimate (−1: none), the kind (kind_* of the one Floquet result:
   !> 0 stable, 1 at +1, 2 at −1, 4 damped, 5 undecided) and arg λ_max/π (the rotation number
   !> arccos(S/2)/π where |S| < 2).
   integer, parameter :: value_trace = 0, value_log_abs_trace = 1, value_log10_abs_trace = 2, value_overflow = 3, &
      value_stable = 4, value_stable_paper = 5, value_lambda_max = 6, value_log_modulus_max = 7, &
      value_log_modulus_min = 8, value_exponent = 9, value_error_estimate = 10, value_kind = 11, value_argument = 12
   !> Number of values of a point.
   integer, parameter :: value_count = 13
   !> The column of chart and points files each value is (its `col_*` place), 0 for the
   !> values no file has (ln|S|, the two ln|λ|).
   integer, parameter :: value_columns(0:value_count - 1) = [col_s, 0, col_log10_abs_s, col_overflow, col_stable, &
      col_stable_paper, col_lambda_max, 0, 0, col_mu, col_error_estimate, col_kind, col_argument]

contains

   !> The method of the C arguments.
   pure function make_method(method, n_segments, sampling, tolerance) result(m)
      integer(c_int), intent(in) :: method, n_segments, sampling
      real(c_double), intent(in) :: tolerance
      type(method_t) :: m
      m = method_t(int(method), int(n_segments), int(sampling), real(tolerance, wp))
   end function make_method

   !> Threads to use: `threads` when positive, else OpenMP's default.
   integer function thread_count(threads)
      integer(c_int), intent(in) :: threads
      thread_count = 1
      !$ thread_count = omp_get_max_threads()
      if (threads > 0) thread_count = int(threads)
   end function thread_count

   !> The checks every batch makes before any work: the model complete, `need` and
   !> `threads` valid, the method known and able to run at `first` (its parameters: the
   !> tolerance, the pieces), as the chart task's check_method_runs does.
   subroutine check_request(model, method, need, threads, first, error)
      class(hill_model_t), intent(in) :: model  !! the model
      type(method_t), intent(in) :: method  !! the method
      integer(c_int), intent(in) :: need, threads  !! HILLSTAB_NEED_*; threads (0: default)
      type(hill_point_t), intent(in), optional :: first  !! a valid point, to try the method on
      type(error_t), allocatable, intent(out) :: error  !! err_invalid_parameter
      type(trace_t) :: tr
      type(error_t), allocatable :: cause
      call model%check_values(error)
      if (allocated(error)) return
      if (need < need_verdict .or. need > need_trace) then
         call set_error(error, err_invalid_parameter, "need must be HILLSTAB_NEED_VERDICT (1), _GROWTH (2) or "// &
            "_TRACE (3), got "//integer_text(int(need)))
      else if (threads < 0) then
         call set_error(error, err_invalid_parameter, "threads must be >= 0 (0: the OpenMP default), got "// &
            integer_text(int(threads)))
      else if (method%kind < lbound(method_table, 1) .or. method%kind > ubound(method_table, 1)) then
         call set_error(error, err_invalid_parameter, "unknown method code "//integer_text(method%kind)// &
            " (expected 0 to "//integer_text(ubound(method_table, 1))//")")
      else if (present(first)) then
         call monodromy_trace(model, first, method, tr, cause)
         if (allocated(cause)) then
            if (cause%code == err_invalid_parameter) call set_error(error, err_invalid_parameter, "method '"// &
               method_name(method%kind)//"': "//cause%message)
         end if
      end if
   end subroutine check_request

   !> The values of one point from its trace: those of a chart or points file
   !> (`chart_values`, through `value_columns`), and ln|S| and both ln|λ|, which no file has;
   !> below need_growth (`growth` false) the multipliers, μ, the argument and the logarithms
   !> are 0, as a verdict file has them.
   pure subroutine computed_values(f, growth, v)
      type(floquet_t), intent(in) :: f  !! the point's Floquet data
      logical, intent(in) :: growth  !! the multipliers were computed
      real(c_double), intent(out) :: v(0:value_count - 1)  !! its values
      real(wp) :: columns(n_chart_columns)
      columns = chart_values(0.0_wp, 0.0_wp, f, .false., status_ok, need=merge(need_growth, need_verdict, growth))
      call from_columns(columns, v)
      if (growth) then
         v(value_log_abs_trace) = f%trace%log_abs
         v(value_log_modulus_max) = f%log_modulus(1)
         v(value_log_modulus_min) = f%log_modulus(2)
      end if
   end subroutine computed_values

   !> The placeholders of a failed point: a file's status 2 row (`chart_placeholders`), 0
   !> where no file has the value.
   pure subroutine failed_point_values(v)
      real(c_double), intent(out) :: v(0:value_count - 1)  !! its values
      call from_columns(chart_placeholders(), v)
   end subroutine failed_point_values

   !> The values from a chart row's columns (`value_columns`), 0 where no file has the value.
   pure subroutine from_columns(columns, v)
      real(wp), intent(in) :: columns(n_chart_columns)  !! every column of a chart or points file
      real(c_double), intent(out) :: v(0:value_count - 1)  !! the values
      integer :: k
      v = 0.0_wp
      do k = 0, value_count - 1
         if (value_columns(k) > 0) v(k) = columns(value_columns(k))
      end do
   end subroutine from_columns

   !> `int hillstab_points(const hillstab_model *model, size_t n, const double *alpha, const
   !> double *beta, const double *epsilon, int method, int n_segments, int sampling, double
   !> tolerance, int need, int paper, int threads, double *values, int *status)`: the values
   !> (`values[j][HILLSTAB_VALUE_*]`) and status of the n points (α_j, β_j, ε_j), as task
   !> `points` computes them, in parallel on `threads` threads (0: OpenMP's default). `need`
   !> (HILLSTAB_NEED_*) says what must be computed to the tolerance (VERDICT: the verdicts,
   !> screened; TRACE: S everywhere); `paper` = 1 settles the paper's verdict |S₁| ≤ 2 too.
   function hillstab_c_points(model, n, alpha, beta, epsilon, method, n_segments, sampling, tolerance, need, paper, &
                              threads, values, status) result(info) bind(C, name="hillstab_points")
      type(c_ptr), value, intent(in) :: model  !! the model handle
      integer(c_size_t), value, intent(in) :: n  !! number of points
      real(c_double), intent(in) :: alpha(*), beta(*), epsilon(*)  !! the points: α_j, β_j and damping ε_j ≥ 0
      !> HILLSTAB_METHOD_*; pieces and HILLSTAB_SAMPLING_* (segments)
      integer(c_int), value, intent(in) :: method, n_segments, sampling
      real(c_double), value, intent(in) :: tolerance  !! target error on S (exact methods)
      integer(c_int), value, intent(in) :: need  !! HILLSTAB_NEED_VERDICT, _GROWTH or _TRACE
      integer(c_int), value, intent(in) :: paper  !! 1: the paper's verdict is wanted too
      integer(c_int), value, intent(in) :: threads  !! threads (0: the OpenMP default)
      real(c_double), intent(inout) :: values(0:value_count - 1, *)  !! the values of each point
      integer(c_int), intent(inout) :: status(*)  !! each point's status: 0 ok, 1 round-off limited, 2 failed
      integer(c_int) :: info
      type(model_handle_t), pointer :: handle
      type(error_t), allocatable :: error, cause
      type(method_t) :: m
      type(trace_t) :: tr(1)
      type(floquet_t) :: f
      logical :: failed(1), inaccurate(1), wants_paper
      real(wp) :: damping(1)
      integer :: j, n_points, nt
      m = make_method(method, n_segments, sampling, tolerance)
      call handle_model(model, handle, error)
      if (.not. allocated(error)) then
         if (len(count_refusal("n", n, max_grid_count)) > 0) call set_error(error, err_invalid_parameter, &
            count_refusal("n", n, max_grid_count)//" (the points of one call, as of a chart)")
      end if
      n_points = 0
      if (.not. allocated(error)) then
         n_points = int(n)
         do j = 1, n_points
            call check_point(handle%model, hill_point_t(alpha(j), beta(j), epsilon(j)), cause)
            if (.not. allocated(cause)) call check_own_damping(handle%model, epsilon(j), cause)
            if (allocated(cause)) then
               call set_error(error, cause%code, "point "//integer_text(j - 1)//" (alpha = "//real_text(alpha(j))// &
                  ", beta = "//real_text(beta(j))//", epsilon = "//real_text(epsilon(j))//"): "//cause%message)
               exit
            end if
         end do
      end if
      if (.not. allocated(error)) then
         if (n_points > 0) then
            call check_request(handle%model, m, need, threads, hill_point_t(alpha(1), beta(1), epsilon(1)), error)
         else
            call check_request(handle%model, m, need, threads, error=error)
         end if
      end if
      call record_outcome(error)
      if (allocated(error)) then
         info = int(error%code, c_int)
         return
      end if
      wants_paper = paper /= 0
      nt = thread_count(threads)
      !$omp parallel do schedule(dynamic) num_threads(nt) default(shared) &
      !$omp private(j, tr, f, failed, inaccurate, cause, damping)
      do j = 1, n_points
         call monodromy_trace_batch(handle%model, hill_point_t(alpha(j), 0.0_wp, &
                                    handle%model%point_damping(alpha(j), epsilon(j))), [beta(j)], m, tr, &
                                    failed, cause, inaccurate=inaccurate, need=int(need), paper=wants_paper, &
                                    dampings=damping)
         if (failed(1)) then
            status(j) = int(status_failed, c_int)
            call failed_point_values(values(:, j))
            cycle
         end if
         status(j) = int(merge(status_roundoff, status_ok, inaccurate(1)), c_int)
         call set_from_trace(f, tr(1), damping(1), m%tolerance, handle%model%period(), .false.)
         call computed_values(f, .true., values(:, j))
      end do
      !$omp end parallel do
      info = 0
   end function hillstab_c_points

   !> `int hillstab_chart(const hillstab_model *model, double alpha_min, double alpha_max,
   !> size_t n_alpha, double beta_min, double beta_max, size_t n_beta, double epsilon, int
   !> method, int n_segments, int sampling, double tolerance, int need, int paper, int
   !> threads, double *alpha, double *beta, double *values, int *status)`: the chart of task
   !> `chart` over n_alpha values of α from alpha_min to alpha_max and n_beta values of β
   !> (both ends included, equally spaced), returned in `alpha`, `beta`,
   !> `values[i][j][HILLSTAB_VALUE_*]` and `status[i][j]` (α index i outer). With need =
   !> HILLSTAB_NEED_VERDICT only the verdicts are computed (the other values 0).
   !> `hillstab_chart_scaled` with both axes linear.
   function hillstab_c_chart(model, alpha_min, alpha_max, n_alpha, beta_min, beta_max, n_beta, epsilon, method, &
                             n_segments, sampling, tolerance, need, paper, threads, alphas, betas, values, status) &
      result(info) bind(C, name="hillstab_chart")
      type(c_ptr), value, intent(in) :: model  !! the model handle
      real(c_double), value, intent(in) :: alpha_min, alpha_max  !! first and last α
      integer(c_size_t), value, intent(in) :: n_alpha  !! number of α values (rows)
      real(c_double), value, intent(in) :: beta_min, beta_max  !! first and last β
      integer(c_size_t), value, intent(in) :: n_beta  !! number of β values (per row)
      real(c_double), value, intent(in) :: epsilon  !! damping ε ≥ 0
      !> HILLSTAB_METHOD_*; pieces and HILLSTAB_SAMPLING_* (segments)
      integer(c_int), value, intent(in) :: method, n_segments, sampling
      real(c_double), value, intent(in) :: tolerance  !! target error on S (exact methods)
      integer(c_int), value, intent(in) :: need  !! HILLSTAB_NEED_VERDICT, _GROWTH or _TRACE
      integer(c_int), value, intent(in) :: paper  !! 1: the paper's verdict is wanted too
      integer(c_int), value, intent(in) :: threads  !! threads (0: the OpenMP default)
      real(c_double), intent(inout) :: alphas(*)  !! receives the n_alpha values of α
      real(c_double), intent(inout) :: betas(*)  !! receives the n_beta values of β
      !> the values of each point, (value, β index, α index) in Fortran order
      real(c_double), intent(inout) :: values(0:value_count - 1, row_extent(n_beta), *)
      integer(c_int), intent(inout) :: status(row_extent(n_beta), *)  !! each point's status
      integer(c_int) :: info
      info = hillstab_c_chart_scaled(model, alpha_min, alpha_max, n_alpha, int(scale_linear, c_int), beta_min, &
                                     beta_max, n_beta, int(scale_linear, c_int), epsilon, method, n_segments, &
                                     sampling, tolerance, need, paper, threads, alphas, betas, values, status)
   end function hillstab_c_chart

   !> `int hillstab_chart_scaled(const hillstab_model *model, double alpha_min, double
   !> alpha_max, size_t n_alpha, int alpha_scale, double beta_min, double beta_max, size_t
   !> n_beta, int beta_scale, double epsilon, int method, int n_segments, int sampling, double
   !> tolerance, int need, int paper, int threads, double *alpha, double *beta, double
   !> *values, int *status)`: `hillstab_chart` with the scale of each axis,
   !> HILLSTAB_SCALE_LINEAR (0: equally spaced) or HILLSTAB_SCALE_LOG (1: geometric, both ends
   !> in (0, 1e300]), the values of task `chart` with `&chart alpha_scale, beta_scale`.
   function hillstab_c_chart_scaled(model, alpha_min, alpha_max, n_alpha, alpha_scale, beta_min, beta_max, n_beta, &
                                    beta_scale, epsilon, method, n_segments, sampling, tolerance, need, paper, &
                                    threads, alphas, betas, values, status) &
      result(info) bind(C, name="hillstab_chart_scaled")
      type(c_ptr), value, intent(in) :: model  !! the model handle
      real(c_double), value, intent(in) :: alpha_min, alpha_max  !! first and last α
      integer(c_size_t), value, intent(in) :: n_alpha  !! number of α values (rows)
      real(c_double), value, intent(in) :: beta_min, beta_max  !! first and last β
      integer(c_size_t), value, intent(in) :: n_beta  !! number of β values (per row)
      integer(c_int), value, intent(in) :: alpha_scale, beta_scale  !! HILLSTAB_SCALE_LINEAR or _LOG
      real(c_double), value, intent(in) :: epsilon  !! damping ε ≥ 0
      !> HILLSTAB_METHOD_*; pieces and HILLSTAB_SAMPLING_* (segments)
      integer(c_int), value, intent(in) :: method, n_segments, sampling
      real(c_double), value, intent(in) :: tolerance  !! target error on S (exact methods)
      integer(c_int), value, intent(in) :: need  !! HILLSTAB_NEED_VERDICT, _GROWTH or _TRACE
      integer(c_int), value, intent(in) :: paper  !! 1: the paper's verdict is wanted too
      integer(c_int), value, intent(in) :: threads  !! threads (0: the OpenMP default)
      real(c_double), intent(inout) :: alphas(*)  !! receives the n_alpha values of α
      real(c_double), intent(inout) :: betas(*)  !! receives the n_beta values of β
      !> the values of each point, (value, β index, α index) in Fortran order (an n_beta beyond
      !> INT_MAX, refused below, sets no extent: its stride would overflow)
      real(c_double), intent(inout) :: values(0:value_count - 1, row_extent(n_beta), *)
      integer(c_int), intent(inout) :: status(row_extent(n_beta), *)  !! each point's status
      integer(c_int) :: info
      type(model_handle_t), pointer :: handle
      type(error_t), allocatable :: error, cause
      type(method_t) :: m
      real(wp), allocatable :: grid_alphas(:), grid_betas(:)
      type(chart_grid_t) :: grid
      type(batch_plan_t) :: plan
      logical :: wants_paper
      integer :: i, j, na, nb, nt, c, chunk, n_chunks, first, last
      m = make_method(method, n_segments, sampling, tolerance)
      call handle_model(model, handle, error)
      if (.not. allocated(error)) then
         if (len(count_refusal("n_alpha", n_alpha)) > 0) then
            call set_error(error, err_invalid_parameter, count_refusal("n_alpha", n_alpha))
         else if (len(count_refusal("n_beta", n_beta)) > 0) then
            call set_error(error, err_invalid_parameter, count_refusal("n_beta", n_beta))
         else if (n_alpha < 1 .or. n_beta < 1) then
            call set_error(error, err_invalid_parameter, "n_alpha and n_beta must be >= 1")
         else if (int(n_alpha, int64)*int(n_beta, int64) > int(max_grid_count, int64)) then
            call set_error(error, err_invalid_parameter, "n_alpha * n_beta = "//integer_text(int(n_alpha, int64)* &
               int(n_beta, int64))//" points exceed the limit "//integer_text(max_grid_count))
         end if
      end if
      na = 0
      nb = 0
      if (.not. allocated(error)) then
         na = int(n_alpha)
         nb = int(n_beta)
         if (.not. all(ieee_is_finite([alpha_min, alpha_max, beta_min, beta_max]))) then
            call set_error(error, err_invalid_parameter, "the grid's ends must be finite")
         else if (len(scale_refusal("alpha", int(alpha_scale), alpha_min, alpha_max)) > 0) then
            call set_error(error, err_invalid_parameter, scale_refusal("alpha", int(alpha_scale), alpha_min, alpha_max))
         else if (len(scale_refusal("beta", int(beta_scale), beta_min, beta_max)) > 0) then
            call set_error(error, err_invalid_parameter, scale_refusal("beta", int(beta_scale), beta_min, beta_max))
         else
            grid = chart_grid_t(alpha_min, alpha_max, na, beta_min, beta_max, nb, int(alpha_scale), int(beta_scale))
            grid_alphas = [(grid_alpha(grid, i), i = 1, na)]
            grid_betas = [(grid_beta(grid, j), j = 1, nb)]
         end if
      end if
      if (.not. allocated(error)) then
         do i = 1, na
            call check_batch(handle%model, grid_alphas(i), epsilon, grid_betas, cause)
            if (.not. allocated(cause)) call check_own_damping(handle%model, epsilon, cause)
            if (allocated(cause)) then
               call set_error(error, cause%code, "row "//integer_text(i - 1)//" (alpha = "// &
                  real_text(grid_alphas(i))//"): "//cause%message)
               exit
            end if
         end do
      end if
      if (.not. allocated(error)) call check_request(handle%model, m, need, threads, &
                                                     hill_point_t(grid_alphas(1), grid_betas(1), epsilon), error)
      call record_outcome(error)
      if (allocated(error)) then
         info = int(error%code, c_int)
         return
      end if
      alphas(1:na) = grid_alphas
      betas(1:nb) = grid_betas
      wants_paper = paper /= 0
      nt = thread_count(threads)
      if (na >= 4*nt) then
         ! whole rows in parallel, as the chart task with many rows
         !$omp parallel do schedule(dynamic) num_threads(nt) default(shared) private(i)
         do i = 1, na
            call chart_row(handle%model, grid_alphas(i), grid_betas, handle%model%point_damping(grid_alphas(i), epsilon), &
                           m, int(need), wants_paper, &
                           values(:, 1:nb, i), status(1:nb, i))
         end do
         !$omp end parallel do
      else
         ! few rows: each row in chunks sharing the meshes prepared for it
         chunk = max(16, nb/(8*nt))
         n_chunks = (nb + chunk - 1)/chunk
         do i = 1, na
            call prepare_batch(handle%model, hill_point_t(grid_alphas(i), 0.0_wp, &
                               handle%model%point_damping(grid_alphas(i), epsilon)), grid_betas, m, plan, int(need))
            !$omp parallel do schedule(dynamic) num_threads(nt) default(shared) private(c, first, last)
            do c = 1, n_chunks
               first = (c - 1)*chunk + 1
               last = min(nb, c*chunk)
               call chart_row(handle%model, grid_alphas(i), grid_betas(first:last), &
                              handle%model%point_damping(grid_alphas(i), epsilon), m, int(need), &
                              wants_paper, values(:, first:last, i), status(first:last, i), plan)
            end do
            !$omp end parallel do
         end do
      end if
      info = 0
   end function hillstab_c_chart_scaled

   !> err_invalid_parameter when a model that carries its own damping (an equation) is
   !> given a damping ε ≠ 0 as well.
   pure subroutine check_own_damping(model, epsilon, error)
      class(hill_model_t), intent(in) :: model  !! the model
      real(wp), intent(in) :: epsilon           !! the damping given
      type(error_t), allocatable, intent(out) :: error  !! the refusal
      if (model%takes_scene_damping() .or. .not. epsilon > 0.0_wp) return
      call set_error(error, err_invalid_parameter, "epsilon: the "//model%name()//" model carries its own "// &
         "damping (its variable damping, in its own units): epsilon must be 0")
   end subroutine check_own_damping

   !> The values and statuses of the points (α, β_j) of a row or part of one, as the chart
   !> task's `compute_row` computes them.
   subroutine chart_row(model, alpha, betas, epsilon, method, need, paper, values, statuses, plan)
      class(hill_model_t), intent(in) :: model  !! the model
      real(wp), intent(in) :: alpha, betas(:), epsilon  !! the points
      type(method_t), intent(in) :: method  !! the method
      integer, intent(in) :: need  !! need_verdict … need_trace
      logical, intent(in) :: paper  !! settle the paper's verdict too
      real(c_double), intent(inout) :: values(0:, :)  !! (value, point)
      integer(c_int), intent(inout) :: statuses(:)  !! per point
      type(batch_plan_t), intent(in), optional :: plan  !! prepared for the whole row
      type(trace_t) :: traces(size(betas))
      logical :: failed(size(betas)), inaccurate(size(betas))
      type(error_t), allocatable :: cause
      type(floquet_t) :: f
      real(wp) :: dampings(size(betas))
      integer :: j
      call monodromy_trace_batch(model, hill_point_t(alpha, 0.0_wp, epsilon), betas, method, traces, failed, cause, &
                                 plan=plan, inaccurate=inaccurate, need=need, paper=paper, dampings=dampings)
      do j = 1, size(betas)
         if (failed(j)) then
            statuses(j) = int(status_failed, c_int)
            call failed_point_values(values(:, j))
            cycle
         end if
         statuses(j) = int(merge(status_roundoff, status_ok, inaccurate(j)), c_int)
         call set_from_trace(f, traces(j), dampings(j), method%tolerance, model%period(), need <= need_verdict)
         call computed_values(f, need >= need_growth, values(:, j))
      end do
   end subroutine chart_row

   !> `int hillstab_physical(const hillstab_model *model, double r0, double g, double omega,
   !> double a, double kappa, double *alpha, double *beta, double *epsilon)`: the model's α
   !> (elastic: a π²/ρ, eq. (24)), β = g π²/(ρ ω²) and ε = κ π/ω (eq. (46)) of a pendulum of
   !> natural length r0 (m), gravity g (m/s²), radial angular frequency ω = √(k/m) (rad/s),
   !> bounce amplitude a (m) and damping rate κ (1/s), with ρ = r0 + g/ω² (eq. (4));
   !> err_invalid_parameter naming the variable when the pendulum has no meaning.
   function hillstab_c_physical(model, r0, g, omega, a, kappa, alpha, beta, epsilon) result(info) &
      bind(C, name="hillstab_physical")
      type(c_ptr), value, intent(in) :: model  !! the model handle
      real(c_double), value, intent(in) :: r0, g, omega, a, kappa  !! the pendulum in SI units
      real(c_double), intent(inout) :: alpha, beta, epsilon  !! receive α, β and ε
      integer(c_int) :: info
      type(model_handle_t), pointer :: handle
      type(error_t), allocatable :: error, cause
      type(physical_t) :: p
      character(len=:), allocatable :: variable
      call handle_model(model, handle, error)
      if (.not. allocated(error)) then
         p = physical_t(r0=r0, g=g, omega=omega, a=a, kappa=kappa)
         call check_physical(p, cause, variable)
         if (allocated(cause)) call set_error(error, cause%code, variable//": "//cause%message)
      end if
      call record_outcome(error)
      if (allocated(error)) then
         info = int(error%code, c_int)
         return
      end if
      alpha = pendulum_alpha(handle%model, p)
      beta = physical_beta(p)
      epsilon = physical_epsilon(p)
      info = 0
   end function hillstab_c_physical
end module hillstab_interop_capi_batch

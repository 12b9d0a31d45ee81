!> Tests of the C entry points of models as handles, batches, transition curves and scenes
!> (hillstab_interop_capi_models, _batch, _curves, _scene) against independent routes:
!> the per-point C functions, the closed forms at α = 0, the formulas of the units, and
!> each other (threads, verdicts only, rows against chunks).
module test_capi_batch
   use, intrinsic :: iso_c_binding, only: c_int, c_double, c_char, c_size_t, c_null_char, c_ptr, c_null_ptr, &
      c_associated
   use hillstab_core_kinds, only: wp, pi, pi2
   use hillstab_core_error, only: err_invalid_parameter, err_input
   use hillstab_integrate_monodromy, only: method_auto, method_magnus6, method_segments, need_verdict, need_trace
   use hillstab_hill_coefficient, only: sampling_average
   use hillstab_hill_models, only: model_count, model_names, model_names_text
   use hillstab_interop_capi, only: hillstab_c_floquet, hillstab_c_last_error
   use hillstab_interop_capi_models
   use hillstab_interop_capi_batch
   use hillstab_interop_capi_curves, only: hillstab_c_transition_curves
   use hillstab_interop_capi_scene, only: hillstab_c_run_scene
   use hillstab_testing
   use hillstab_core_error, only: error_t
   use hillstab_test_files, only: run_text_scene
   use hillstab_test_scratch, only: padded, scratch_prefix, read_lines, delete_file
   implicit none
   private
   public :: collect_capi_batch

   integer, parameter :: nv = value_count

contains

   function collect_capi_batch() result(suite)
      type(testsuite_t) :: suite
      suite = new_testsuite("capi_batch", [ &
         new_unittest("model_handles", model_handles), &
         new_unittest("points_match_per_point", points_match_per_point), &
         new_unittest("chart_matches_points", chart_matches_points), &
         new_unittest("log_chart_equals_task_file", log_chart_equals_task_file), &
         new_unittest("threads_change_nothing", threads_change_nothing), &
         new_unittest("bad_input_untouched", bad_input_untouched), &
         new_unittest("physical_units", physical_units), &
         new_unittest("curves_closed_form", curves_closed_form), &
         new_unittest("run_scene_bad_path", run_scene_bad_path)])
   end function collect_capi_batch

   !> The C text of a buffer up to its NUL.
   function text_of(buffer) result(text)
      character(kind=c_char), intent(in) :: buffer(:)
      character(len=:), allocatable :: text
      integer :: i
      text = ""
      do i = 1, size(buffer)
         if (buffer(i) == c_null_char) exit
         text = text//buffer(i)
      end do
   end function text_of

   !> The calling thread's last message.
   function last_message() result(text)
      character(len=:), allocatable :: text
      character(kind=c_char) :: buffer(1024)
      integer(c_int) :: code
      code = hillstab_c_last_error(buffer, size(buffer, kind=c_size_t))
      text = text_of(buffer)
   end function last_message

   !> A handle of the named model (checked).
   function new_handle(ctx, name) result(model)
      type(test_context_t), intent(inout) :: ctx
      character(len=*), intent(in) :: name
      type(c_ptr) :: model
      integer(c_int) :: code
      model = c_null_ptr
      code = hillstab_c_model_new(name//c_null_char, model)
      call check(ctx, code == 0 .and. c_associated(model), "new "//name)
   end function new_handle

   !> The registry listed, names and formulas, unknown names and variables refused.
   subroutine model_handles(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(c_ptr) :: model
      character(kind=c_char) :: buffer(512)
      integer(c_int) :: count, most, k, code
      real(c_double) :: values(2) = [1.0_c_double, 2.0_c_double]
      call check(ctx, hillstab_c_model_count() == model_count, "count")
      do k = 1, int(model_count, c_int)
         code = hillstab_c_model_registry_name(k, buffer, size(buffer, kind=c_size_t))
         call check(ctx, code == 0 .and. text_of(buffer) == trim(model_names(k)), "registry name "//text_of(buffer))
      end do
      call check(ctx, hillstab_c_model_registry_name(0_c_int, buffer, size(buffer, kind=c_size_t)) == &
         err_invalid_parameter, "index 0 refused")
      model = new_handle(ctx, "MATHIEU")
      code = hillstab_c_model_name(model, buffer, size(buffer, kind=c_size_t))
      call check(ctx, code == 0 .and. text_of(buffer) == "mathieu", "name in lower case")
      code = hillstab_c_model_formula(model, buffer, size(buffer, kind=c_size_t))
      call check(ctx, code == 0 .and. index(text_of(buffer), "cos(pi tau)") > 0, "formula: "//text_of(buffer))
      count = -1
      code = hillstab_c_model_variable_count(model, count)
      call check(ctx, code == 0 .and. count == 0, "no variables")
      call check(ctx, hillstab_c_model_variable_name(model, 1_c_int, buffer, size(buffer, kind=c_size_t), most) == &
         err_invalid_parameter, "variable 1 of none refused")
      call check(ctx, hillstab_c_model_set(model, "c"//c_null_char, values, 2_c_size_t) == err_invalid_parameter, &
         "set refused")
      call check(ctx, last_message() == "the mathieu model has no variable 'c'", "message: "//last_message())
      call check(ctx, hillstab_c_model_check(model) == 0, "complete")
      call hillstab_c_model_free(model)
      call hillstab_c_model_free(c_null_ptr)
      model = c_null_ptr
      code = hillstab_c_model_new("pendulum"//c_null_char, model)
      call check(ctx, code == err_invalid_parameter .and. .not. c_associated(model), &
         "unknown model refused, handle untouched")
      call check(ctx, index(last_message(), "unknown model 'pendulum' (expected "//model_names_text()//")") > 0, &
         "message: "//last_message())
      call check(ctx, hillstab_c_model_name(c_null_ptr, buffer, size(buffer, kind=c_size_t)) == &
         err_invalid_parameter, "null handle refused")
   end subroutine model_handles

   !> hillstab_points against hillstab_floquet_data point by point (a batch of one against
   !> monodromy_trace), for both models, undamped and damped, two methods.
   subroutine points_match_per_point(ctx)
      type(test_context_t), intent(inout) :: ctx
      integer, parameter :: n = 9
      real(c_double) :: alpha(n), beta(n), epsilon(n), values(0:nv - 1, n), s, moduli(2), mu
      integer(c_int) :: status(n), stable, paper, code, methods(2), model_code, m
      type(c_ptr) :: model
      integer :: j, k
      alpha = [0.0_wp, 1.0_wp, 3.7_wp, 5.0_wp, 7.0_wp, 9.0_wp, 9.5_wp, 2.0_wp, 4.0_wp]
      beta = [1.0_wp, -2.0_wp, 2.47_wp, 10.0_wp, 30.0_wp, 2.0_wp, 5.0_wp, 0.5_wp, 6.0_wp]
      methods = [int(method_auto, c_int), int(method_magnus6, c_int)]
      do model_code = 1, 2
         model = new_handle(ctx, trim(model_names(model_code)))
         do k = 1, 2
            epsilon = merge(0.0_wp, 0.15_wp, k == 1)
            do m = 1, 2
               code = hillstab_c_points(model, int(n, c_size_t), alpha, beta, epsilon, methods(m), 2_c_int, 1_c_int, &
                  1.0e-11_c_double, int(need_trace, c_int), 1_c_int, 0_c_int, values, status)
               call check(ctx, code == 0 .and. all(status == 0), "points computed")
               do j = 1, n
                  code = hillstab_c_floquet(model_code, alpha(j), beta(j), epsilon(j), methods(m), 2_c_int, 1_c_int, &
                     1.0e-11_c_double, s, moduli, mu, stable, paper)
                  call check(ctx, code == 0, "per point")
                  call check(ctx, values(value_trace, j), s, rel=1.0e-9_wp, abs=1.0e-9_wp, message="S")
                  call check(ctx, values(value_exponent, j), mu, rel=1.0e-7_wp, abs=1.0e-8_wp, message="mu")
                  call check(ctx, values(value_log_modulus_max, j), moduli(1), rel=1.0e-7_wp, abs=1.0e-8_wp, &
                     message="ln|lambda_max|")
                  call check(ctx, values(value_log_modulus_min, j), moduli(2), rel=1.0e-7_wp, abs=1.0e-8_wp, &
                     message="ln|lambda_min|")
                  call check(ctx, values(value_stable, j) == 0.5_wp .or. values(value_stable, j) == real(stable, wp), &
                     "the verdict")
                  call check(ctx, values(value_stable_paper, j) == real(paper, wp), "the paper's verdict")
                  ! the kind and the argument of the largest multiplier, from this point's own S
                  if (values(value_stable, j) == 0.5_wp) then
                     call check(ctx, values(value_kind, j) == 5.0_wp, "marginal: kind 5")
                  else if (stable == 1) then
                     call check(ctx, values(value_kind, j) == merge(4.0_wp, 0.0_wp, k == 2), "stable: kind 0, damped 4")
                  else
                     call check(ctx, values(value_kind, j) == merge(1.0_wp, 2.0_wp, s > 0.0_wp), "unstable: kind 1, 2")
                  end if
                  if (abs(s) < 2.0_wp) then
                     call check(ctx, values(value_argument, j), acos(0.5_wp*s)/pi, abs=1.0e-6_wp, &
                                message="argument = arccos(S/2)/pi")
                  else
                     call check(ctx, values(value_argument, j) == merge(0.0_wp, 1.0_wp, s > 0.0_wp), "argument 0 or 1")
                  end if
                  call check(ctx, values(value_log_abs_trace, j), log(abs(s)), rel=1.0e-9_wp, abs=1.0e-9_wp, &
                     message="ln|S|")
                  call check(ctx, values(value_lambda_max, j), exp(moduli(1)), rel=1.0e-7_wp, message="lambda_max")
                  call check(ctx, values(value_error_estimate, j) >= 0.0_wp .and. &
                     values(value_error_estimate, j) <= 1.0e-11_wp, "the estimate within the tolerance")
               end do
            end do
         end do
         call hillstab_c_model_free(model)
      end do
   end subroutine points_match_per_point

   !> A chart: its grid (ends included), its values against the same points one by one,
   !> verdicts only against the full chart's verdicts, segments exactly as the points.
   subroutine chart_matches_points(ctx)
      type(test_context_t), intent(inout) :: ctx
      integer, parameter :: na = 5, nb = 13
      real(c_double) :: alphas(na), betas(nb), values(0:nv - 1, nb, na), verdicts(0:nv - 1, nb, na)
      real(c_double) :: pa(na*nb), pb(na*nb), pe(na*nb), pv(0:nv - 1, na*nb)
      integer(c_int) :: status(nb, na), vstatus(nb, na), pstatus(na*nb), code
      type(c_ptr) :: model
      integer :: i, j, k
      model = new_handle(ctx, "elastic")
      code = hillstab_c_chart(model, 0.0_c_double, 9.8_c_double, int(na, c_size_t), -2.0_c_double, 12.0_c_double, &
         int(nb, c_size_t), 0.0_c_double, int(method_auto, c_int), 2_c_int, 1_c_int, 1.0e-10_c_double, &
         int(need_trace, c_int), 0_c_int, 1_c_int, alphas, betas, values, status)
      call check(ctx, code == 0 .and. all(status == 0), "chart computed")
      call check(ctx, alphas(1) == 0.0_wp .and. alphas(na) == 9.8_wp .and. betas(1) == -2.0_wp .and. &
         betas(nb) == 12.0_wp, "the grid's ends exact")
      call check(ctx, betas(2), -2.0_wp + 14.0_wp/(nb - 1), rel=1.0e-15_wp, message="the grid's spacing")
      k = 0
      do i = 1, na
         do j = 1, nb
            k = k + 1
            pa(k) = alphas(i)
            pb(k) = betas(j)
         end do
      end do
      pe = 0.0_wp
      code = hillstab_c_points(model, int(na*nb, c_size_t), pa, pb, pe, int(method_auto, c_int), 2_c_int, 1_c_int, &
         1.0e-10_c_double, int(need_trace, c_int), 0_c_int, 0_c_int, pv, pstatus)
      call check(ctx, code == 0, "points computed")
      call check(ctx, maxval(abs(reshape(values(value_trace, :, :), [na*nb]) - pv(value_trace, :))/ &
         max(1.0_wp, abs(pv(value_trace, :)))) < 1.0e-9_wp, "chart S = points S within the tolerance")
      code = hillstab_c_chart(model, 0.0_c_double, 9.8_c_double, int(na, c_size_t), -2.0_c_double, 12.0_c_double, &
         int(nb, c_size_t), 0.0_c_double, int(method_auto, c_int), 2_c_int, 1_c_int, 1.0e-10_c_double, &
         int(need_verdict, c_int), 0_c_int, 1_c_int, alphas, betas, verdicts, vstatus)
      call check(ctx, code == 0 .and. all(vstatus == 0), "verdicts computed")
      call check(ctx, all(verdicts(value_stable, :, :) == values(value_stable, :, :)), "the same verdicts")
      call check(ctx, all(verdicts(value_exponent, :, :) == 0.0_wp), "no growth computed")
      ! segments: no sharing between points, so the chart is the points to the bit
      code = hillstab_c_chart(model, 0.0_c_double, 9.8_c_double, int(na, c_size_t), -2.0_c_double, 12.0_c_double, &
         int(nb, c_size_t), 0.0_c_double, int(method_segments, c_int), 64_c_int, int(sampling_average, c_int), &
         1.0e-10_c_double, int(need_trace, c_int), 0_c_int, 0_c_int, alphas, betas, values, status)
      code = hillstab_c_points(model, int(na*nb, c_size_t), pa, pb, pe, int(method_segments, c_int), 64_c_int, &
         int(sampling_average, c_int), 1.0e-10_c_double, int(need_trace, c_int), 0_c_int, 0_c_int, pv, pstatus)
      call check(ctx, all(reshape(values, [nv, na*nb]) == pv), "segments: chart = points")
      call check(ctx, all(pv(value_error_estimate, :) == -1.0_wp), "segments give no estimate")
      call hillstab_c_model_free(model)
   end subroutine chart_matches_points

   !> `hillstab_chart_scaled` over log axes against task `chart` with `alpha_scale`,
   !> `beta_scale` = 'log': the axes and S of every line to the bit; with both axes linear it
   !> is `hillstab_chart` to the bit; a bad scale code or a log axis reaching 0 is refused,
   !> the outputs untouched.
   subroutine log_chart_equals_task_file(ctx)
      type(test_context_t), intent(inout) :: ctx
      integer, parameter :: na = 5, nb = 5
      real(c_double) :: alphas(na), betas(nb), values(0:nv - 1, nb, na), linear(0:nv - 1, nb, na)
      real(c_double) :: alphas2(na), betas2(nb)
      integer(c_int) :: status(nb, na), status2(nb, na), code
      type(c_ptr) :: model
      type(error_t), allocatable :: error
      character(len=:), allocatable :: written
      character(len=1024), allocatable :: lines(:)
      real(wp) :: row(3)
      integer :: i, j, k, ios
      logical :: same
      model = new_handle(ctx, "elastic")
      code = hillstab_c_chart_scaled(model, 0.02_c_double, 9.5_c_double, int(na, c_size_t), 1_c_int, 0.01_c_double, &
         100.0_c_double, int(nb, c_size_t), 1_c_int, 0.0_c_double, int(method_auto, c_int), 2_c_int, 1_c_int, &
         1.0e-10_c_double, int(need_trace, c_int), 0_c_int, 0_c_int, alphas, betas, values, status)
      call check(ctx, code == 0 .and. all(status == 0), "log chart computed: "//last_message())
      call run_text_scene("capi_log", [padded("&scene columns = 'alpha beta S', output = '"// &
         scratch_prefix("capi_log")//"' /"), padded("&chart alpha_min = 0.02, alpha_max = 9.5, n_alpha = 5, "// &
         "alpha_scale = 'log', beta_min = 0.01, beta_max = 100, n_beta = 5, beta_scale = 'log' /")], error, written)
      call check(ctx, .not. allocated(error), "task chart runs")
      if (allocated(error)) return
      lines = read_lines(written)
      call delete_file(written)
      k = 0
      same = .true.
      do i = 1, na
         do j = 1, nb
            do
               k = k + 1
               if (k > size(lines)) exit
               if (lines(k)(1:1) /= "#" .and. len_trim(lines(k)) > 0) exit
            end do
            if (k > size(lines)) then
               same = .false.
               exit
            end if
            read (lines(k), *, iostat=ios) row
            same = same .and. ios == 0 .and. row(1) == alphas(i) .and. row(2) == betas(j) .and. &
                   row(3) == values(value_trace, j, i)
         end do
      end do
      call check(ctx, same, "the task's file: alpha, beta and S to the bit")
      call check(ctx, alphas(1) == 0.02_wp .and. alphas(na) == 9.5_wp .and. betas(1) == 0.01_wp .and. &
                 betas(nb) == 100.0_wp, "the ends exact")
      call check(ctx, betas(2), 0.1_wp, rel=4.0e-16_wp, message="a geometric beta axis, a decade a step")
      code = hillstab_c_chart_scaled(model, 0.0_c_double, 9.8_c_double, int(na, c_size_t), 0_c_int, -2.0_c_double, &
         12.0_c_double, int(nb, c_size_t), 0_c_int, 0.0_c_double, int(method_auto, c_int), 2_c_int, 1_c_int, &
         1.0e-10_c_double, int(need_trace, c_int), 0_c_int, 0_c_int, alphas, betas, values, status)
      code = hillstab_c_chart(model, 0.0_c_double, 9.8_c_double, int(na, c_size_t), -2.0_c_double, 12.0_c_double, &
         int(nb, c_size_t), 0.0_c_double, int(method_auto, c_int), 2_c_int, 1_c_int, 1.0e-10_c_double, &
         int(need_trace, c_int), 0_c_int, 0_c_int, alphas2, betas2, linear, status2)
      call check(ctx, all(alphas == alphas2) .and. all(betas == betas2) .and. all(values == linear) .and. &
                 all(status == status2), "linear scales: hillstab_chart to the bit")
      values = -7.0_wp
      alphas = -7.0_wp
      code = hillstab_c_chart_scaled(model, 0.0_c_double, 9.5_c_double, int(na, c_size_t), 1_c_int, 0.01_c_double, &
         100.0_c_double, int(nb, c_size_t), 1_c_int, 0.0_c_double, int(method_auto, c_int), 2_c_int, 1_c_int, &
         1.0e-10_c_double, int(need_trace, c_int), 0_c_int, 0_c_int, alphas, betas, values, status)
      call check(ctx, code == err_invalid_parameter .and. index(last_message(), "a log alpha axis needs") > 0, &
                 "log alpha from 0 refused: "//last_message())
      code = hillstab_c_chart_scaled(model, 0.5_c_double, 9.5_c_double, int(na, c_size_t), 0_c_int, 0.01_c_double, &
         100.0_c_double, int(nb, c_size_t), 2_c_int, 0.0_c_double, int(method_auto, c_int), 2_c_int, 1_c_int, &
         1.0e-10_c_double, int(need_trace, c_int), 0_c_int, 0_c_int, alphas, betas, values, status)
      call check(ctx, code == err_invalid_parameter .and. index(last_message(), "beta_scale must be 0 (linear) or 1 "// &
                 "(log), got 2") > 0, "scale code 2 refused: "//last_message())
      call check(ctx, all(values == -7.0_wp) .and. all(alphas == -7.0_wp), "outputs untouched")
      call hillstab_c_model_free(model)
   end subroutine log_chart_equals_task_file

   !> One, two and three threads: the same bits (a chart of 6 rows runs whole rows on one
   !> thread and chunks of rows on two and three).
   subroutine threads_change_nothing(ctx)
      type(test_context_t), intent(inout) :: ctx
      integer, parameter :: na = 6, nb = 40
      real(c_double) :: alphas(na), betas(nb), values(0:nv - 1, nb, na, 3), pe(nb)
      real(c_double) :: pv(0:nv - 1, nb, 3)
      integer(c_int) :: status(nb, na, 3), pstatus(nb, 3), code, t
      type(c_ptr) :: model
      model = new_handle(ctx, "elastic")
      pe = 0.05_wp
      do t = 1, 3
         code = hillstab_c_chart(model, 0.5_c_double, 9.7_c_double, int(na, c_size_t), -2.0_c_double, 40.0_c_double, &
            int(nb, c_size_t), 0.0_c_double, int(method_auto, c_int), 2_c_int, 1_c_int, 1.0e-10_c_double, &
            int(need_trace, c_int), 0_c_int, t, alphas, betas, values(:, :, :, t), status(:, :, t))
         call check(ctx, code == 0, "chart")
         code = hillstab_c_points(model, int(nb, c_size_t), abs(betas)*0.2_wp, betas, pe, int(method_auto, c_int), &
            2_c_int, 1_c_int, 1.0e-10_c_double, int(need_trace, c_int), 1_c_int, t, pv(:, :, t), pstatus(:, t))
         call check(ctx, code == 0, "points")
      end do
      do t = 2, 3
         call check(ctx, all(values(:, :, :, t) == values(:, :, :, 1)) .and. all(status(:, :, t) == status(:, :, 1)), &
            "chart: same values on each thread count")
         call check(ctx, all(pv(:, :, t) == pv(:, :, 1)), "points: same values on each thread count")
      end do
      call hillstab_c_model_free(model)
   end subroutine threads_change_nothing

   !> Bad input fails the call before any work: outputs untouched, the message naming the point.
   subroutine bad_input_untouched(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(c_double) :: alpha(3), beta(3), epsilon(3), values(0:nv - 1, 3), alphas(2), betas(2), grid(0:nv - 1, 2, 2)
      integer(c_int) :: status(3), gstatus(2, 2), code
      type(c_ptr) :: model
      model = new_handle(ctx, "elastic")
      alpha = [1.0_wp, 10.0_wp, 2.0_wp]
      beta = 2.0_wp
      epsilon = 0.0_wp
      values = -7.0_wp
      status = -7
      code = hillstab_c_points(model, 3_c_size_t, alpha, beta, epsilon, int(method_auto, c_int), 2_c_int, 1_c_int, &
         1.0e-10_c_double, int(need_trace, c_int), 0_c_int, 0_c_int, values, status)
      call check(ctx, code == err_invalid_parameter, "alpha = 10 refused")
      call check(ctx, all(values == -7.0_wp) .and. all(status == -7), "outputs untouched")
      call check(ctx, index(last_message(), "point 1 (alpha = 10") > 0 .and. &
         index(last_message(), "elastic model needs 0 <= alpha < pi**2") > 0, "message: "//last_message())
      alpha(2) = 3.0_wp
      code = hillstab_c_points(model, 3_c_size_t, alpha, beta, epsilon, int(method_auto, c_int), 2_c_int, 1_c_int, &
         2.0_c_double, int(need_trace, c_int), 0_c_int, 0_c_int, values, status)
      call check(ctx, code == err_invalid_parameter .and. all(values == -7.0_wp), "tolerance 2 refused")
      call check(ctx, index(last_message(), "method 'auto': ") == 1, "message: "//last_message())
      code = hillstab_c_points(model, 3_c_size_t, alpha, beta, epsilon, 9_c_int, 2_c_int, 1_c_int, &
         1.0e-10_c_double, int(need_trace, c_int), 0_c_int, 0_c_int, values, status)
      call check(ctx, code == err_invalid_parameter .and. index(last_message(), "unknown method code 9") > 0, &
         "method 9 refused: "//last_message())
      code = hillstab_c_points(model, 3_c_size_t, alpha, beta, epsilon, int(method_auto, c_int), 2_c_int, 1_c_int, &
         1.0e-10_c_double, 0_c_int, 0_c_int, 0_c_int, values, status)
      call check(ctx, code == err_invalid_parameter .and. index(last_message(), "need must be") > 0, "need 0")
      code = hillstab_c_chart(model, 0.0_c_double, 12.0_c_double, 2_c_size_t, 0.0_c_double, 1.0_c_double, 2_c_size_t, &
         0.0_c_double, int(method_auto, c_int), 2_c_int, 1_c_int, 1.0e-10_c_double, int(need_trace, c_int), 0_c_int, &
         0_c_int, alphas, betas, grid, gstatus)
      call check(ctx, code == err_invalid_parameter .and. index(last_message(), "row 1 (alpha = 12") > 0, &
         "chart beyond pi**2 refused: "//last_message())
      code = hillstab_c_chart(model, 0.0_c_double, 1.0_c_double, 0_c_size_t, 0.0_c_double, 1.0_c_double, 2_c_size_t, &
         0.0_c_double, int(method_auto, c_int), 2_c_int, 1_c_int, 1.0e-10_c_double, int(need_trace, c_int), 0_c_int, &
         0_c_int, alphas, betas, grid, gstatus)
      call check(ctx, code == err_invalid_parameter, "an empty grid refused")
      code = hillstab_c_points(c_null_ptr, 3_c_size_t, alpha, beta, epsilon, int(method_auto, c_int), 2_c_int, &
         1_c_int, 1.0e-10_c_double, int(need_trace, c_int), 0_c_int, 0_c_int, values, status)
      call check(ctx, code == err_invalid_parameter .and. index(last_message(), "null pointer") > 0, "null model")
      call hillstab_c_model_free(model)
   end subroutine bad_input_untouched

   !> α = aπ²/ρ, β = gπ²/(ρω²), ε = κπ/ω with ρ = r0 + g/ω² (eqs. (4), (24), (46)).
   subroutine physical_units(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(c_double) :: alpha, beta, epsilon, rho
      integer(c_int) :: code
      type(c_ptr) :: model
      model = new_handle(ctx, "elastic")
      call check(ctx, hillstab_c_physical(model, 0.3_c_double, 9.81_c_double, 10.0_c_double, 0.05_c_double, &
         0.2_c_double, alpha, beta, epsilon) == 0, "a spring")
      rho = 0.3_wp + 9.81_wp/100.0_wp
      call check(ctx, alpha, 0.05_wp*pi2/rho, rel=1.0e-15_wp, message="alpha")
      call check(ctx, beta, 9.81_wp*pi2/(rho*100.0_wp), rel=1.0e-15_wp, message="beta")
      call check(ctx, epsilon, 0.2_wp*pi/10.0_wp, rel=1.0e-15_wp, message="epsilon")
      alpha = -7.0_wp
      code = hillstab_c_physical(model, 0.3_c_double, 9.81_c_double, 10.0_c_double, 0.5_c_double, 0.0_c_double, &
         alpha, beta, epsilon)
      call check(ctx, code == err_invalid_parameter .and. alpha == -7.0_wp, "a >= rho refused")
      call check(ctx, index(last_message(), "a: the amplitude must satisfy") == 1, "message: "//last_message())
      call hillstab_c_model_free(model)
   end subroutine physical_units

   !> At α = 0 the curves are β = (nπ/2)² (n = 0 once, every other n twice); a capacity below
   !> the count stores what fits and reports the count.
   subroutine curves_closed_form(ctx)
      type(test_context_t), intent(inout) :: ctx
      integer, parameter :: cap = 16
      real(c_double) :: alpha(2), beta(cap, 2), bound(cap, 2)
      integer(c_int) :: order(cap, 2), parity(cap, 2), sign(cap, 2), coexistent(cap, 2), status(2), code
      integer(c_size_t) :: count(2)
      type(c_ptr) :: model
      integer :: k
      model = new_handle(ctx, "mathieu")
      alpha = [0.0_wp, 0.0_wp]
      code = hillstab_c_transition_curves(model, 2_c_size_t, alpha, -2.0_c_double, 100.0_c_double, 1.0e-12_c_double, &
         int(cap, c_size_t), 2_c_int, beta, order, parity, sign, bound, coexistent, count, status)
      call check(ctx, code == 0 .and. all(status == 0) .and. all(count == 13), "13 curves in [-2, 100]")
      do k = 1, 13
         call check(ctx, beta(k, 1), (order(k, 1)*pi/2)**2, rel=1.0e-13_wp, abs=1.0e-13_wp, message="(n pi/2)^2")
         call check(ctx, sign(k, 1) == merge(2, -2, mod(order(k, 1), 2) == 0), "S = +2 for even n")
         call check(ctx, (coexistent(k, 1) == 1) .eqv. (order(k, 1) > 0), "closed tongues")
      end do
      beta = -1.0_wp
      code = hillstab_c_transition_curves(model, 1_c_size_t, alpha, -2.0_c_double, 100.0_c_double, 1.0e-12_c_double, &
         4_c_size_t, 0_c_int, beta, order, parity, sign, bound, coexistent, count, status)
      call check(ctx, code == 0 .and. count(1) == 13 .and. beta(5, 1) == -1.0_wp .and. beta(4, 1) > 0.0_wp, &
         "capacity 4: four stored, thirteen counted")
      call hillstab_c_model_free(model)
      model = new_handle(ctx, "elastic")
      alpha(1) = 10.0_wp
      code = hillstab_c_transition_curves(model, 1_c_size_t, alpha, -2.0_c_double, 100.0_c_double, 1.0e-12_c_double, &
         4_c_size_t, 0_c_int, beta, order, parity, sign, bound, coexistent, count, status)
      call check(ctx, code == err_invalid_parameter .and. index(last_message(), "alpha 0 (alpha = 10") == 1, &
         "alpha beyond pi**2 refused: "//last_message())
      call hillstab_c_model_free(model)
   end subroutine curves_closed_form

   !> A scene that does not exist: err_input naming it, `written` untouched.
   subroutine run_scene_bad_path(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(kind=c_char) :: written(64)
      integer(c_int) :: code
      written = "x"
      code = hillstab_c_run_scene("no/such/scene.nml"//c_null_char, 1_c_int, written, size(written, kind=c_size_t))
      call check(ctx, code == err_input .and. index(last_message(), "no/such/scene.nml") > 0, &
         "missing scene: "//last_message())
      call check(ctx, all(written == "x"), "written untouched")
   end subroutine run_scene_bad_path
end module test_capi_batch

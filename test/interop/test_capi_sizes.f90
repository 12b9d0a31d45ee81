!> Tests of the `size_t` arguments of the C entry points at the limits of size_t and int,
!> called from Fortran as C calls them (a `size_t` from 2^63 up arrives as a negative
!> `integer(c_size_t)`): every count beyond what the function takes — SIZE_MAX, SIZE_MAX − 1,
!> 2^63, 2^63 − 1, 2^32, 2^32 − 1, INT_MAX + 1 and INT_MAX — is refused with
!> HILLSTAB_ERR_INVALID_PARAMETER and a message naming the argument and its value as C
!> prints it, nothing read, the outputs and the object untouched; a buffer length of
!> SIZE_MAX holds the whole text (hillstab_interop_sizes).
module test_capi_sizes
   use, intrinsic :: iso_c_binding, only: c_int, c_double, c_char, c_size_t, c_null_char, c_ptr, c_null_ptr, &
      c_associated, c_loc
   use hillstab_core_kinds, only: wp
   use hillstab_core_error, only: err_invalid_parameter
   use hillstab_integrate_monodromy, only: method_auto, need_trace
   use hillstab_interop_capi, only: hillstab_c_last_error, hillstab_c_error_message
   use hillstab_interop_capi_models, only: hillstab_c_model_new, hillstab_c_model_free, hillstab_c_model_set, &
      hillstab_c_model_name
   use hillstab_interop_capi_batch, only: hillstab_c_points, hillstab_c_chart, value_count
   use hillstab_interop_capi_curves, only: hillstab_c_transition_curves
   use hillstab_interop_capi_system, only: hillstab_c_system_new, hillstab_c_system_free, hillstab_c_system_set, &
      hillstab_c_system_check, hillstab_c_system_monodromy
   use hillstab_interop_sizes, only: size_text, count_refusal
   use hillstab_testing
   implicit none
   private
   public :: collect_capi_sizes

   !> The sizes at the limits: SIZE_MAX, SIZE_MAX − 1, 2^63, 2^63 − 1, 2^32, 2^32 − 1,
   !> INT_MAX + 1, INT_MAX.
   integer, parameter :: n_sizes = 8
   character(len=20), parameter :: size_texts(n_sizes) = [character(len=20) :: "18446744073709551615", &
      "18446744073709551614", "9223372036854775808", "9223372036854775807", "4294967296", "4294967295", &
      "2147483648", "2147483647"]

contains

   function collect_capi_sizes() result(suite)
      type(testsuite_t) :: suite
      suite = new_testsuite("capi_sizes", [ &
         new_unittest("size_text_as_c_prints", size_text_as_c_prints), &
         new_unittest("system_set_counts", system_set_counts), &
         new_unittest("model_set_counts", model_set_counts), &
         new_unittest("points_chart_curves_counts", points_chart_curves_counts), &
         new_unittest("buffer_lengths", buffer_lengths)])
   end function collect_capi_sizes

   !> The sizes of `size_texts`, as `integer(c_size_t)`.
   function limit_sizes() result(sizes)
      integer(c_size_t) :: sizes(n_sizes)
      sizes = [-1_c_size_t, -2_c_size_t, -huge(1_c_size_t) - 1_c_size_t, huge(1_c_size_t), 4294967296_c_size_t, &
               4294967295_c_size_t, 2147483648_c_size_t, 2147483647_c_size_t]
   end function limit_sizes

   !> The calling thread's last message.
   function last_message() result(text)
      character(len=:), allocatable :: text
      character(kind=c_char) :: buffer(1024)
      integer(c_int) :: code
      code = hillstab_c_last_error(buffer, size(buffer, kind=c_size_t))
      text = text_of(buffer)
   end function last_message

   !> The C text of a buffer up to its NUL ("<no NUL>" appended when there is none).
   function text_of(buffer) result(text)
      character(kind=c_char), intent(in) :: buffer(:)
      character(len=:), allocatable :: text
      integer :: i
      text = ""
      do i = 1, size(buffer)
         if (buffer(i) == c_null_char) return
         text = text//buffer(i)
      end do
      text = text//"<no NUL>"
   end function text_of

   !> A NUL-terminated copy of `name`.
   function c_name(name) result(chars)
      character(len=*), intent(in) :: name
      character(kind=c_char) :: chars(len(name) + 1)
      integer :: i
      do i = 1, len(name)
         chars(i) = name(i:i)
      end do
      chars(len(name) + 1) = c_null_char
   end function c_name

   !> `size_text` writes each size as `%zu` does; `count_refusal` accepts 0 … INT_MAX only.
   subroutine size_text_as_c_prints(ctx)
      type(test_context_t), intent(inout) :: ctx
      integer(c_size_t) :: sizes(n_sizes)
      integer :: k
      sizes = limit_sizes()
      do k = 1, n_sizes
         call check(ctx, size_text(sizes(k)) == trim(size_texts(k)), trim(size_texts(k))//": "//size_text(sizes(k)))
         call check(ctx, len(count_refusal("n", sizes(k))) > 0 .eqv. k < n_sizes, trim(size_texts(k))// &
                    ": refused beyond INT_MAX only: '"//count_refusal("n", sizes(k))//"'")
      end do
      call check(ctx, size_text(0_c_size_t) == "0", "0")
      call check(ctx, count_refusal("n", 0_c_size_t) == "", "0 accepted")
   end subroutine size_text_as_c_prints

   !> hillstab_system_set with each count: refused naming count and its value (the limit of
   !> the variable for INT_MAX), the system as before (its monodromy unchanged); an unknown
   !> variable with such a count is refused for the count, with 5 numbers for its name.
   subroutine system_set_counts(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(c_ptr), target :: system
      real(c_double), target :: values(4), phi(16), phi_after(16), log_scale, estimate
      integer(c_int), target :: status
      character(kind=c_char), target :: mass(5), n(2), other(4), b(2), cos(4)
      integer(c_size_t) :: sizes(n_sizes)
      character(len=:), allocatable :: message
      integer :: k
      sizes = limit_sizes()
      system = c_null_ptr
      call check(ctx, hillstab_c_system_new(c_loc(system)) == 0, "new")
      mass = c_name("mass")
      n = c_name("n")
      other = c_name("foo")
      b = c_name("b")
      cos = c_name("cos")
      values = [2.0_wp, 0.0_wp, 0.0_wp, 1.0_wp]
      call check(ctx, hillstab_c_system_set(system, c_loc(n), c_loc(values), 1_c_size_t) == 0, "n = 2")
      values = [2.0_wp, -1.0_wp, -1.0_wp, 1.5_wp]
      call check(ctx, hillstab_c_system_set(system, c_loc(b), c_loc(values), 4_c_size_t) == 0, "b")
      values = [-1.0_wp, 0.0_wp, 0.0_wp, -0.5_wp]
      call check(ctx, hillstab_c_system_set(system, c_loc(cos), c_loc(values), 4_c_size_t) == 0, "cos")
      call check(ctx, hillstab_c_system_check(system) == 0, "complete: "//last_message())
      call check(ctx, hillstab_c_system_monodromy(system, 0.5_wp, 1.0_wp, 0.0_wp, 0_c_int, 1.0e-10_wp, c_loc(phi), &
                                                  c_loc(log_scale), c_loc(estimate), c_loc(status)) == 0, "before")
      values = [4.0_wp, 0.0_wp, 0.0_wp, 4.0_wp]
      do k = 1, n_sizes
         call check(ctx, hillstab_c_system_set(system, c_loc(mass), c_loc(values), sizes(k)) == err_invalid_parameter, &
                    "mass, count "//trim(size_texts(k))//": refused")
         message = last_message()
         call check(ctx, index(message, "hillstab_system_set: count = "//trim(size_texts(k))//" exceeds the limit ") == 1, &
                    "names count and its value: "//message)
         call check(ctx, hillstab_c_system_set(system, c_loc(n), c_loc(values), sizes(k)) == err_invalid_parameter, &
                    "n, count "//trim(size_texts(k))//": refused")
         call check(ctx, hillstab_c_system_set(system, c_loc(other), c_loc(values), sizes(k)) == err_invalid_parameter, &
                    "foo, count "//trim(size_texts(k))//": refused")
         if (k < n_sizes) then
            call check(ctx, index(last_message(), "hillstab_system_set: count = "//trim(size_texts(k))) == 1, &
                       "foo: names count: "//last_message())
         else
            call check(ctx, index(last_message(), "has no variable 'foo'") > 0, "foo, INT_MAX: names foo, reads "// &
                       "nothing: "//last_message())
         end if
      end do
      call check(ctx, index(message, "hillstab_system_set: count = 2147483647 exceeds the limit 400, the most "// &
                            "numbers 'mass' takes") == 1, "INT_MAX: the limit of mass: "//message)
      call check(ctx, hillstab_c_system_set(system, c_loc(other), c_loc(values), 5_c_size_t) == err_invalid_parameter &
                 .and. index(last_message(), "has no variable 'foo'") > 0, "foo, 5 numbers: "//last_message())
      call check(ctx, hillstab_c_system_monodromy(system, 0.5_wp, 1.0_wp, 0.0_wp, 0_c_int, 1.0e-10_wp, &
                                                  c_loc(phi_after), c_loc(log_scale), c_loc(estimate), &
                                                  c_loc(status)) == 0, "after")
      call check(ctx, all(phi == phi_after), "the system unchanged (mass still I)")
      call hillstab_c_system_free(system)
   end subroutine system_set_counts

   !> hillstab_model_set of the Fourier model's `cos` with each count: refused naming count,
   !> the model's name and coefficient still readable.
   subroutine model_set_counts(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(c_ptr) :: model
      real(c_double) :: values(4)
      integer(c_size_t) :: sizes(n_sizes)
      integer :: k
      sizes = limit_sizes()
      model = c_null_ptr
      call check(ctx, hillstab_c_model_new("fourier"//c_null_char, model) == 0 .and. c_associated(model), "new")
      values = 1.0_wp
      do k = 1, n_sizes
         call check(ctx, hillstab_c_model_set(model, "cos"//c_null_char, values, sizes(k)) == err_invalid_parameter, &
                    "cos, count "//trim(size_texts(k))//": refused")
         call check(ctx, index(last_message(), "count = "//trim(size_texts(k))//" exceeds the limit ") == 1, &
                    "names count: "//last_message())
         call check(ctx, hillstab_c_model_set(model, "none"//c_null_char, values, sizes(k)) == err_invalid_parameter, &
                    "none, count "//trim(size_texts(k))//": refused")
      end do
      call check(ctx, hillstab_c_model_set(model, "cos"//c_null_char, values, 2_c_size_t) == 0, "2 numbers set")
      call hillstab_c_model_free(model)
   end subroutine model_set_counts

   !> hillstab_points (n), hillstab_chart (n_alpha, n_beta) and hillstab_transition_curves
   !> (n_alpha, capacity) with each size: refused naming the argument, outputs untouched;
   !> points beyond the 1e8 of a chart too.
   subroutine points_chart_curves_counts(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(c_ptr) :: model
      real(c_double) :: alpha(2), beta(2), epsilon(2), values(0:value_count - 1, 2), grid(0:value_count - 1, 2, 2), &
         cbeta(2, 2), bound(2, 2)
      integer(c_int) :: status(2), gstatus(2, 2), order(2, 2), parity(2, 2), sign(2, 2), coexistent(2, 2), code
      integer(c_size_t) :: sizes(n_sizes), count(2)
      integer :: k
      sizes = limit_sizes()
      model = c_null_ptr
      call check(ctx, hillstab_c_model_new("mathieu"//c_null_char, model) == 0, "new")
      alpha = 1.0_wp
      beta = 2.0_wp
      epsilon = 0.0_wp
      values = -7.0_wp
      grid = -7.0_wp
      cbeta = -7.0_wp
      status = -7
      gstatus = -7
      count = 77
      do k = 1, n_sizes
         code = hillstab_c_points(model, sizes(k), alpha, beta, epsilon, int(method_auto, c_int), 2_c_int, 1_c_int, &
                                  1.0e-10_c_double, int(need_trace, c_int), 0_c_int, 0_c_int, values, status)
         call check(ctx, code == err_invalid_parameter .and. index(last_message(), "n = "//trim(size_texts(k))// &
                    " exceeds the limit 100000000") == 1, "points, n = "//trim(size_texts(k))//": "//last_message())
         code = hillstab_c_chart(model, 0.0_c_double, 1.0_c_double, sizes(k), 0.0_c_double, 1.0_c_double, 2_c_size_t, &
                                 0.0_c_double, int(method_auto, c_int), 2_c_int, 1_c_int, 1.0e-10_c_double, &
                                 int(need_trace, c_int), 0_c_int, 0_c_int, alpha, beta, grid, gstatus)
         call check(ctx, code == err_invalid_parameter .and. index(last_message(), "n_alpha") == 1, &
                    "chart, n_alpha = "//trim(size_texts(k))//": "//last_message())
         code = hillstab_c_chart(model, 0.0_c_double, 1.0_c_double, 2_c_size_t, 0.0_c_double, 1.0_c_double, sizes(k), &
                                 0.0_c_double, int(method_auto, c_int), 2_c_int, 1_c_int, 1.0e-10_c_double, &
                                 int(need_trace, c_int), 0_c_int, 0_c_int, alpha, beta, grid, gstatus)
         call check(ctx, code == err_invalid_parameter .and. (index(last_message(), "n_beta = "//trim(size_texts(k))) &
                    == 1 .or. index(last_message(), "n_alpha * n_beta = ") == 1), &
                    "chart, n_beta = "//trim(size_texts(k))//": "//last_message())
         code = hillstab_c_transition_curves(model, sizes(k), alpha, 0.0_c_double, 10.0_c_double, 1.0e-10_c_double, &
                                             2_c_size_t, 0_c_int, cbeta, order, parity, sign, bound, coexistent, &
                                             count, status)
         call check(ctx, code == err_invalid_parameter .and. index(last_message(), "n_alpha = "//trim(size_texts(k))) &
                    == 1, "curves, n_alpha = "//trim(size_texts(k))//": "//last_message())
         if (k < n_sizes) then
            code = hillstab_c_transition_curves(model, 1_c_size_t, alpha, 0.0_c_double, 10.0_c_double, &
                                                1.0e-10_c_double, sizes(k), 0_c_int, cbeta, order, parity, sign, &
                                                bound, coexistent, count, status)
            call check(ctx, code == err_invalid_parameter .and. index(last_message(), "capacity = "// &
                       trim(size_texts(k))) == 1, "curves, capacity = "//trim(size_texts(k))//": "//last_message())
         end if
      end do
      code = hillstab_c_points(model, 100000001_c_size_t, alpha, beta, epsilon, int(method_auto, c_int), 2_c_int, &
                               1_c_int, 1.0e-10_c_double, int(need_trace, c_int), 0_c_int, 0_c_int, values, status)
      call check(ctx, code == err_invalid_parameter, "points, n = 1e8 + 1: refused")
      call check(ctx, all(values == -7.0_wp) .and. all(status == -7) .and. all(grid == -7.0_wp) .and. &
                 all(gstatus == -7) .and. all(cbeta == -7.0_wp) .and. all(count == 77), "outputs untouched")
      code = hillstab_c_points(model, 2_c_size_t, alpha, beta, epsilon, int(method_auto, c_int), 2_c_int, 1_c_int, &
                               1.0e-10_c_double, int(need_trace, c_int), 0_c_int, 0_c_int, values, status)
      call check(ctx, code == 0 .and. all(status == 0), "2 points computed")
      call hillstab_c_model_free(model)
   end subroutine points_chart_curves_counts

   !> A buffer length of SIZE_MAX (or 2^63) holds the whole text, NUL-terminated; 0 writes
   !> nothing; 1 writes the NUL alone.
   subroutine buffer_lengths(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(c_ptr) :: model
      character(kind=c_char) :: buffer(256)
      integer(c_int) :: code
      call hillstab_c_error_message(err_invalid_parameter, buffer, -1_c_size_t)
      call check(ctx, len(text_of(buffer)) > 0 .and. index(text_of(buffer), "<no NUL>") == 0, &
                 "error_message, SIZE_MAX: '"//text_of(buffer)//"'")
      model = c_null_ptr
      call check(ctx, hillstab_c_model_new("mathieu"//c_null_char, model) == 0, "new")
      ! (each call its own statement: a function that writes its argument is not evaluated
      ! beside a reference to that argument)
      buffer = "x"
      code = hillstab_c_model_name(model, buffer, -huge(1_c_size_t) - 1_c_size_t)
      call check(ctx, code == 0 .and. text_of(buffer) == "mathieu", "model_name, 2^63: '"//text_of(buffer)//"'")
      buffer = "x"
      code = hillstab_c_model_name(model, buffer, 0_c_size_t)
      call check(ctx, code == 0 .and. all(buffer == "x"), "model_name, 0: nothing written")
      code = hillstab_c_model_name(model, buffer, 1_c_size_t)
      call check(ctx, code == 0 .and. buffer(1) == c_null_char .and. buffer(2) == "x", "model_name, 1: the NUL alone")
      code = hillstab_c_model_set(model, "none"//c_null_char, [1.0_c_double], 1_c_size_t)
      buffer = "x"
      code = hillstab_c_last_error(buffer, -1_c_size_t)
      call check(ctx, code == err_invalid_parameter .and. index(text_of(buffer), "has no variable 'none'") > 0, &
                 "last_error, SIZE_MAX: '"//text_of(buffer)//"'")
      call hillstab_c_model_free(model)
   end subroutine buffer_lengths
end module test_capi_sizes

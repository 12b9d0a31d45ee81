!> C-callable entry points (`bind(C)`, `value` scalars, names prefixed `hillstab_`).
!> The matching declarations are in include/hillstab.h. Every function returns a
!> status: 0 on success, otherwise one of the hillstab_core_error codes; outputs are
!> left untouched on failure, except status 7 (the tolerance is below the round-off level
!> there), where they hold the best value double precision allows. (The outputs are
!> therefore `intent(inout)`: `intent(out)` lets a compiler drop their old value, and an
!> optimizing Fortran caller does: it removes the store before the call as dead.) `hillstab_error_message` turns a status into the name of
!> its code; `hillstab_last_error` gives the full message of the calling thread's most
!> recent failed call (the same text as `error_t%message` in Fortran). `hillstab_version`
!> and `hillstab_version_numbers` give the version of the library linked at run time
!> (the header's `HILLSTAB_VERSION_*` macros give the version compiled against).
!>
!>```c
!> double s, log_abs; int overflow;
!> int status = hillstab_trace(HILLSTAB_MODEL_ELASTIC, 3.7, 2.47, 0.0, HILLSTAB_METHOD_SEGMENTS,
!>                             256, HILLSTAB_SAMPLING_AVERAGE, 1e-10, &s, &log_abs, &overflow);
!>```
module hillstab_interop_capi
   use, intrinsic :: iso_c_binding, only: c_int, c_double, c_char, c_size_t, c_null_char, c_ptr, c_loc
   use hillstab_core_kinds, only: wp, int64, version_string
   use hillstab_core_error, only: error_t, error_code_name, set_error, err_invalid_parameter, err_overflow, err_accuracy
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite, ieee_is_nan
   use hillstab_hill_model, only: hill_model_t, hill_point_t, hill_coefficient, check_point
   use hillstab_hill_models, only: model_from_code
   use hillstab_hill_model_elastic, only: elastic_model_t
   use hillstab_hill_transfer, only: trace_t
   use hillstab_hill_formulas, only: trace_damped_paper
   use hillstab_hill_floquet, only: floquet_t, floquet_from_trace
   use hillstab_integrate_monodromy, only: method_t, monodromy_trace, method_formula
   use hillstab_interop_outcome, only: record_outcome, get_last_error
   use hillstab_interop_sizes, only: buffer_length
   use hillstab_curves_hill_method, only: hill_boundary_t
   use hillstab_curves_characteristic, only: characteristic_values
   use hillstab_core_text, only: integer_text
   implicit none
   private
   public :: hillstab_c_coefficient, hillstab_c_trace, hillstab_c_floquet, hillstab_c_trace_paper, &
      hillstab_c_trace_paper_checked, hillstab_c_error_message, hillstab_c_last_error, hillstab_c_version, &
      hillstab_c_version_numbers, version_numbers, hillstab_c_characteristic_values

   integer :: i_char
   !> The version as a NUL-terminated C string (a constant: safe from every thread).
   character(kind=c_char), parameter :: version_chars(len(version_string) + 1) = &
      [(version_string(i_char:i_char), i_char = 1, len(version_string)), c_null_char]
   character(kind=c_char), target, save :: version_c(size(version_chars)) = version_chars

contains

   function make_method(method, n_segments, sampling, tolerance) result(m)
      integer(c_int), intent(in) :: method, n_segments, sampling
      real(c_double), intent(in) :: tolerance
      type(method_t) :: m
      m = method_t(int(method), int(n_segments), int(sampling), real(tolerance, wp))
   end function make_method

   !> Q(τ) of the model (its code: HILLSTAB_MODEL_*), including the damping shift −ε²/4.
   function hillstab_c_coefficient(model, alpha, beta, epsilon, tau, q) result(status) &
      bind(C, name="hillstab_q")
      integer(c_int), value, intent(in) :: model  !! a model code, HILLSTAB_MODEL_* (ELASTIC 1, MATHIEU 2, ...)
      real(c_double), value, intent(in) :: alpha, beta, epsilon, tau  !! alpha, beta, damping epsilon >= 0, and tau
      real(c_double), intent(inout) :: q  !! Q(tau) - epsilon**2/4 (untouched on failure)
      integer(c_int) :: status
      class(hill_model_t), allocatable :: m
      type(hill_point_t) :: point
      type(error_t), allocatable :: error
      point = hill_point_t(real(alpha, wp), real(beta, wp), real(epsilon, wp))
      call model_from_code(int(model), m, error)
      if (.not. allocated(error)) call check_point(m, point, error)
      if (.not. allocated(error) .and. .not. ieee_is_finite(tau)) &
         call set_error(error, err_invalid_parameter, "tau must be finite")
      call record_outcome(error)
      if (allocated(error)) then
         status = int(error%code, c_int)
         return
      end if
      q = hill_coefficient(m, point, real(tau, wp))
      status = 0
   end function hillstab_c_coefficient

   !> One-period trace S (S₁ for χ when ε > 0) by the chosen method (HILLSTAB_METHOD_*).
   !> When |S| overflows, `trace` is ±DBL_MAX, `overflow` = 1 and `log_abs_trace` = ln|S|.
   function hillstab_c_trace(model, alpha, beta, epsilon, method, n_segments, sampling, tolerance, &
                             trace, log_abs_trace, overflow) result(status) bind(C, name="hillstab_trace")
      !> HILLSTAB_MODEL_*, HILLSTAB_METHOD_*; pieces and HILLSTAB_SAMPLING_* (segments)
      integer(c_int), value, intent(in) :: model, method, n_segments, sampling
      !> alpha, beta, damping epsilon >= 0; target error on S (exact methods)
      real(c_double), value, intent(in) :: alpha, beta, epsilon, tolerance
      real(c_double), intent(inout) :: trace, log_abs_trace  !! S (+-DBL_MAX on overflow) and ln|S|
      integer(c_int), intent(inout) :: overflow  !! 1 when |S| overflowed, else 0
      integer(c_int) :: status
      real(c_double) :: log_modulus(2), floquet_exponent
      integer(c_int) :: stable, stable_paper
      call evaluate_code(int(model), hill_point_t(real(alpha, wp), real(beta, wp), real(epsilon, wp)), &
         make_method(method, n_segments, sampling, tolerance), trace, log_abs_trace, overflow, &
         log_modulus, floquet_exponent, stable, stable_paper, status)
   end function hillstab_c_trace

   !> Floquet data of the swing x: ln|λ| of both multipliers (largest first), the
   !> exponent μ = ln|λ_max|/2, and the verdicts (correct: |S₁| < 2 cosh ε; paper: |S₁| ≤ 2).
   function hillstab_c_floquet(model, alpha, beta, epsilon, method, n_segments, sampling, tolerance, &
                               trace, log_moduli, floquet_exponent, stable, stable_paper) result(status) &
      bind(C, name="hillstab_floquet_data")
      !> HILLSTAB_MODEL_*, HILLSTAB_METHOD_*; pieces and HILLSTAB_SAMPLING_* (segments)
      integer(c_int), value, intent(in) :: model, method, n_segments, sampling
      !> alpha, beta, damping epsilon >= 0; target error on S (exact methods)
      real(c_double), value, intent(in) :: alpha, beta, epsilon, tolerance
      !> S; ln|lambda| of x's multipliers, largest first; mu per unit tau
      real(c_double), intent(inout) :: trace, log_moduli(2), floquet_exponent
      !> 1 when |S1| < 2 cosh epsilon; 1 when |S1| <= 2 (the paper's test)
      integer(c_int), intent(inout) :: stable, stable_paper
      integer(c_int) :: status
      real(c_double) :: log_abs_trace
      integer(c_int) :: overflow
      call evaluate_code(int(model), hill_point_t(real(alpha, wp), real(beta, wp), real(epsilon, wp)), &
         make_method(method, n_segments, sampling, tolerance), trace, log_abs_trace, overflow, &
         log_moduli, floquet_exponent, stable, stable_paper, status)
   end function hillstab_c_floquet

   !> Everything the C functions return: trace S, ln|S|, overflow flag, ln|λ| of both
   !> multipliers (largest first), exponent μ, verdicts (|S₁| < 2 cosh ε; |S₁| ≤ 2);
   !> status 0 or an error code, outputs untouched on error, except HILLSTAB_ERR_ACCURACY
   !> (the tolerance is below what double precision reaches there): the outputs then hold
   !> the best value, as the FORTRAN 77 routines' and the message says.
   subroutine evaluate(model, point, method, s, logs, iovf, rlogm, mu, istab, ipaper, info)
      class(hill_model_t), intent(in) :: model  !! the model
      type(hill_point_t), intent(in) :: point   !! α, β, ε
      type(method_t), intent(in) :: method
      real(wp), intent(inout) :: s, logs, rlogm(2), mu
      integer(c_int), intent(inout) :: iovf, istab, ipaper
      integer(c_int), intent(out) :: info
      type(trace_t) :: tr
      type(floquet_t) :: f
      type(error_t), allocatable :: error
      call monodromy_trace(model, point, method, tr, error)
      call record_outcome(error)
      info = 0
      if (allocated(error)) then
         info = int(error%code, c_int)
         if (error%code /= err_accuracy) return
      end if
      f = floquet_from_trace(tr, point%epsilon, period=model%period())
      s = tr%value
      logs = tr%log_abs
      iovf = 0
      if (tr%overflow) iovf = 1
      ! a stable undamped swing has ln|lambda| = -epsilon = -0.0: given to C as +0.0, so that
      ! printf does not write its growth rate as "-0"
      rlogm = f%log_modulus + 0.0_wp
      mu = f%exponent + 0.0_wp
      istab = 0
      if (f%stable) istab = 1
      ipaper = 0
      if (f%stable_paper) ipaper = 1
      ! never a silent NaN or Inf (S is +-DBL_MAX with the overflow flag; the logarithms are finite)
      if (.not. (ieee_is_finite(logs) .and. all(ieee_is_finite(rlogm)) .and. ieee_is_finite(mu) .and. &
                 .not. ieee_is_nan(s))) then
         call set_error(error, err_overflow, "the result is not finite")
         call record_outcome(error)
         info = int(error%code, c_int)
      end if
   end subroutine evaluate

   !> `evaluate` for the model of a code (HILLSTAB_MODEL_*); an unknown code is an error
   !> (err_invalid_parameter), the outputs untouched.
   subroutine evaluate_code(code, point, method, s, logs, iovf, rlogm, mu, istab, ipaper, info)
      integer, intent(in) :: code  !! the model's code
      type(hill_point_t), intent(in) :: point   !! α, β, ε
      type(method_t), intent(in) :: method
      real(wp), intent(inout) :: s, logs, rlogm(2), mu
      integer(c_int), intent(inout) :: iovf, istab, ipaper
      integer(c_int), intent(out) :: info
      class(hill_model_t), allocatable :: model
      type(error_t), allocatable :: error
      call model_from_code(code, model, error)
      if (allocated(error)) then
         call record_outcome(error)
         info = int(error%code, c_int)
         return
      end if
      call evaluate(model, point, method, s, logs, iovf, rlogm, mu, istab, ipaper, info)
   end subroutine evaluate_code

   !> The paper's closed form eq. (37)/(48) (ε = 0 gives eq. (37)); ±DBL_MAX on overflow.
   !> No error channel: parameters outside the model's domain or non-finite give a
   !> meaningless or non-finite value without a word (kept for compatibility; use
   !> `hillstab_trace_paper_checked`).
   function hillstab_c_trace_paper(alpha, beta, epsilon) result(s) bind(C, name="hillstab_trace_paper")
      real(c_double), value, intent(in) :: alpha, beta, epsilon  !! alpha, beta and damping epsilon (0: eq. (37))
      real(c_double) :: s
      type(trace_t) :: tr
      tr = trace_damped_paper(real(alpha, wp), real(beta, wp), real(epsilon, wp))
      s = tr%value
   end function hillstab_c_trace_paper

   !> The paper's closed form eq. (37)/(48) with a status, like `hillstab_trace` with
   !> HILLSTAB_METHOD_FORMULA on the elastic model: parameters are checked (0 ≤ α < π²,
   !> finite β, 0 ≤ ε), an overflowing S comes back as ±DBL_MAX with `overflow` = 1 and
   !> ln|S| in `log_abs_trace`; outputs untouched on failure.
   function hillstab_c_trace_paper_checked(alpha, beta, epsilon, trace, log_abs_trace, overflow) result(status) &
      bind(C, name="hillstab_trace_paper_checked")
      real(c_double), value, intent(in) :: alpha, beta, epsilon  !! alpha, beta and damping epsilon (0: eq. (37))
      real(c_double), intent(inout) :: trace          !! S (+-DBL_MAX on overflow)
      real(c_double), intent(inout) :: log_abs_trace  !! ln|S|
      integer(c_int), intent(inout) :: overflow       !! 1 when |S| overflowed, else 0
      integer(c_int) :: status
      real(c_double) :: log_modulus(2), floquet_exponent
      integer(c_int) :: stable, stable_paper
      call evaluate(elastic_model_t(), hill_point_t(real(alpha, wp), real(beta, wp), real(epsilon, wp)), &
         method_t(method_formula), trace, log_abs_trace, overflow, log_modulus, floquet_exponent, stable, &
         stable_paper, status)
   end function hillstab_c_trace_paper_checked

   !> The first n transition values of β of each kind at α (hillstab_curves_characteristic
   !> `characteristic_values`): `count` values in the first `count` places of the arrays, by
   !> kind, then ascending; kind is 1 periodic even (a_0, a_2, …), 2 periodic odd (b_2, b_4, …),
   !> 3 antiperiodic even (a_1, a_3, …), 4 antiperiodic odd (b_1, b_3, …) where Q is even, else
   !> 5 periodic and 6 antiperiodic (both edges of each order); 4n places always suffice.
   !> Status err_invalid_parameter when capacity < count, n < 1, α outside the model's domain
   !> or tolerance ≤ 0; the outputs are untouched on failure.
   function hillstab_c_characteristic_values(model, alpha, n, tolerance, capacity, count, beta, order, kind, &
                                             error_bound) result(status) bind(C, name="hillstab_characteristic_values")
      integer(c_int), value, intent(in) :: model      !! HILLSTAB_MODEL_*
      real(c_double), value, intent(in) :: alpha      !! alpha (nu for the Mathieu model)
      integer(c_int), value, intent(in) :: n          !! values of each kind, >= 1
      real(c_double), value, intent(in) :: tolerance  !! target error of beta relative to max(1, |beta|), > 0
      integer(c_int), value, intent(in) :: capacity   !! places in each output array
      integer(c_int), intent(inout) :: count          !! values written
      real(c_double), intent(inout) :: beta(*)        !! the values of beta
      integer(c_int), intent(inout) :: order(*)       !! n of a_n, b_n: their order
      integer(c_int), intent(inout) :: kind(*)        !! 1 … 6 (above)
      real(c_double), intent(inout) :: error_bound(*) !! bound of each value's error
      integer(c_int) :: status
      class(hill_model_t), allocatable :: m
      type(error_t), allocatable :: error
      type(hill_boundary_t), allocatable :: values(:)
      integer :: i
      call model_from_code(int(model), m, error)
      if (.not. allocated(error)) call characteristic_values(m, real(alpha, wp), int(n), values, error, &
                                                             real(tolerance, wp))
      if (.not. allocated(error)) then
         if (size(values) > capacity) call set_error(error, err_invalid_parameter, "characteristic values: "// &
            "capacity "//integer_text(int(capacity))//" < the "//integer_text(size(values))//" values")
      end if
      call record_outcome(error)
      if (allocated(error)) then
         status = int(error%code, c_int)
         return
      end if
      do i = 1, size(values)
         beta(i) = values(i)%beta
         order(i) = int(values(i)%order, c_int)
         kind(i) = int(values(i)%block, c_int)
         error_bound(i) = values(i)%error_bound
      end do
      count = int(size(values), c_int)
      status = 0
   end function hillstab_c_characteristic_values

   !> Copy a NUL-terminated description of `status` into `buffer` (at most `length` bytes).
   subroutine hillstab_c_error_message(status, buffer, length) bind(C, name="hillstab_error_message")
      integer(c_int), value, intent(in) :: status  !! a status returned by a hillstab function
      integer(c_size_t), value, intent(in) :: length  !! size of buffer in bytes
      character(kind=c_char), intent(out) :: buffer(*)  !! receives the NUL-terminated name of the status
      character(len=:), allocatable :: text
      if (status == 0) then
         text = "success"
      else
         text = error_code_name(int(status))
      end if
      call copy_c_string(text, buffer, length)
   end subroutine hillstab_c_error_message

   !> Copy the message of the calling thread's most recent status-returning call
   !> (empty when it succeeded) into `buffer`, NUL-terminated and cut to `length` bytes
   !> (`length` = 0: nothing is written); return that call's status.
   function hillstab_c_last_error(buffer, length) result(status) bind(C, name="hillstab_last_error")
      integer(c_size_t), value, intent(in) :: length    !! size of `buffer` in bytes
      character(kind=c_char), intent(out) :: buffer(*)  !! receives the message
      integer(c_int) :: status
      character(len=:), allocatable :: text
      integer :: code
      call get_last_error(code, text)
      call copy_c_string(text, buffer, length)
      status = int(code, c_int)
   end function hillstab_c_last_error

   !> The version of the library, "MAJOR.MINOR.PATCH" (`version_string`), as a pointer to a
   !> NUL-terminated string that lives as long as the program: `const char *hillstab_version(void)`.
   function hillstab_c_version() result(text) bind(C, name="hillstab_version")
      type(c_ptr) :: text
      text = c_loc(version_c(1))
   end function hillstab_c_version

   !> The three numbers of the version: `void hillstab_version_numbers(int *major, int *minor, int *patch)`.
   subroutine hillstab_c_version_numbers(major, minor, patch) bind(C, name="hillstab_version_numbers")
      integer(c_int), intent(out) :: major  !! the major version
      integer(c_int), intent(out) :: minor  !! the minor version
      integer(c_int), intent(out) :: patch  !! the patch level
      integer :: numbers(3)
      numbers = version_numbers(version_string)
      major = int(numbers(1), c_int)
      minor = int(numbers(2), c_int)
      patch = int(numbers(3), c_int)
   end subroutine hillstab_c_version_numbers

   !> The numbers of a "MAJOR.MINOR.PATCH" version text (−1 for a part that is missing or
   !> not a number).
   pure function version_numbers(text) result(numbers)
      character(len=*), intent(in) :: text  !! e.g. "0.1.0"
      integer :: numbers(3)
      integer :: part, from, dot, ios
      numbers = -1
      from = 1
      do part = 1, 3
         dot = index(text(from:), ".")
         if (dot == 0) then
            dot = len(text) + 1
         else
            dot = from + dot - 1
         end if
         if (dot > from .and. verify(text(from:dot - 1), "0123456789") == 0) then
            read (text(from:dot - 1), *, iostat=ios) numbers(part)
            if (ios /= 0) numbers(part) = -1
         end if
         from = dot + 1
         if (from > len(text)) exit
      end do
   end function version_numbers

   !> `text` into a C buffer of `length` bytes, cut to length − 1 and NUL-terminated.
   subroutine copy_c_string(text, buffer, length)
      character(len=*), intent(in) :: text
      integer(c_size_t), intent(in) :: length  !! any size_t (SIZE_MAX: a buffer that holds any text)
      character(kind=c_char), intent(inout) :: buffer(*)
      integer :: i, n
      if (length == 0_c_size_t) return
      n = int(min(int(len(text), int64), buffer_length(length) - 1))
      do i = 1, n
         buffer(i) = text(i:i)
      end do
      buffer(n + 1) = c_null_char
   end subroutine copy_c_string
end module hillstab_interop_capi

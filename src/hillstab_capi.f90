!> C-callable entry points (`bind(C)`, `value` scalars, names prefixed `hillstab_`).
!> The matching declarations are in include/hillstab.h. Every function returns a
!> status: 0 on success, otherwise one of the hillstab_error codes; outputs are
!> left untouched on failure. `hillstab_error_message` turns a status into text.
!>
!>```c
!> double s, log_abs; int overflow;
!> int status = hillstab_trace(HILLSTAB_MODEL_ELASTIC, 3.7, 2.47, 0.0, HILLSTAB_METHOD_SEGMENTS,
!>                             256, HILLSTAB_SAMPLING_AVERAGE, 1e-10, &s, &log_abs, &overflow);
!>```
module hillstab_capi
   use, intrinsic :: iso_c_binding, only: c_int, c_double, c_char, c_size_t, c_null_char
   use hillstab_kinds, only: wp
   use hillstab_error, only: error_t, error_code_name
   use hillstab_coefficient, only: hill_model_t, hill_coefficient, check_model
   use hillstab_transfer, only: trace_t
   use hillstab_formulas, only: trace_damped_paper
   use hillstab_legacy, only: hseval
   use hillstab_monodromy, only: method_t
   implicit none
   private
   public :: hillstab_c_coefficient, hillstab_c_trace, hillstab_c_floquet, hillstab_c_trace_paper, &
      hillstab_c_error_message

contains

   function make_method(method, n_segments, sampling, tolerance) result(m)
      integer(c_int), intent(in) :: method, n_segments, sampling
      real(c_double), intent(in) :: tolerance
      type(method_t) :: m
      m = method_t(int(method), int(n_segments), int(sampling), real(tolerance, wp))
   end function make_method

   !> Q(τ) of the model (elastic = 1, mathieu = 2), including the damping shift −ε²/4.
   function hillstab_c_coefficient(model, alpha, beta, epsilon, tau, q) result(status) &
      bind(C, name="hillstab_q")
      integer(c_int), value, intent(in) :: model
      real(c_double), value, intent(in) :: alpha, beta, epsilon, tau
      real(c_double), intent(out) :: q
      integer(c_int) :: status
      type(hill_model_t) :: m
      type(error_t), allocatable :: error
      m = hill_model_t(int(model), real(alpha, wp), real(beta, wp), real(epsilon, wp))
      call check_model(m, error)
      if (allocated(error)) then
         status = int(error%code, c_int)
         return
      end if
      q = hill_coefficient(m, real(tau, wp))
      status = 0
   end function hillstab_c_coefficient

   !> One-period trace S (S₁ for χ when ε > 0) by the chosen method (HILLSTAB_METHOD_*).
   !> When |S| overflows, `trace` is ±DBL_MAX, `overflow` = 1 and `log_abs_trace` = ln|S|.
   function hillstab_c_trace(model, alpha, beta, epsilon, method, n_segments, sampling, tolerance, &
                             trace, log_abs_trace, overflow) result(status) bind(C, name="hillstab_trace")
      integer(c_int), value, intent(in) :: model, method, n_segments, sampling
      real(c_double), value, intent(in) :: alpha, beta, epsilon, tolerance
      real(c_double), intent(out) :: trace, log_abs_trace
      integer(c_int), intent(out) :: overflow
      integer(c_int) :: status
      real(c_double) :: log_modulus(2), floquet_exponent
      integer(c_int) :: stable, stable_paper
      call hseval(hill_model_t(int(model), real(alpha, wp), real(beta, wp), real(epsilon, wp)), &
         make_method(method, n_segments, sampling, tolerance), trace, log_abs_trace, overflow, &
         log_modulus, floquet_exponent, stable, stable_paper, status)
   end function hillstab_c_trace

   !> Floquet data of the swing x: ln|λ| of both multipliers (largest first), the
   !> exponent μ = ln|λ_max|/2, and the verdicts (correct: |S₁| < 2 cosh ε; paper: |S₁| ≤ 2).
   function hillstab_c_floquet(model, alpha, beta, epsilon, method, n_segments, sampling, tolerance, &
                               trace, log_moduli, floquet_exponent, stable, stable_paper) result(status) &
      bind(C, name="hillstab_floquet_data")
      integer(c_int), value, intent(in) :: model, method, n_segments, sampling
      real(c_double), value, intent(in) :: alpha, beta, epsilon, tolerance
      real(c_double), intent(out) :: trace, log_moduli(2), floquet_exponent
      integer(c_int), intent(out) :: stable, stable_paper
      integer(c_int) :: status
      real(c_double) :: log_abs_trace
      integer(c_int) :: overflow
      call hseval(hill_model_t(int(model), real(alpha, wp), real(beta, wp), real(epsilon, wp)), &
         make_method(method, n_segments, sampling, tolerance), trace, log_abs_trace, overflow, &
         log_moduli, floquet_exponent, stable, stable_paper, status)
   end function hillstab_c_floquet

   !> The paper's closed form eq. (37)/(48) (ε = 0 gives eq. (37)); ±DBL_MAX on overflow.
   function hillstab_c_trace_paper(alpha, beta, epsilon) result(s) bind(C, name="hillstab_trace_paper")
      real(c_double), value, intent(in) :: alpha, beta, epsilon
      real(c_double) :: s
      s = paper_value(real(alpha, wp), real(beta, wp), real(epsilon, wp))
   end function hillstab_c_trace_paper

   pure real(wp) function paper_value(alpha, beta, epsilon)
      real(wp), intent(in) :: alpha, beta, epsilon
      type(trace_t) :: tr
      tr = trace_damped_paper(alpha, beta, epsilon)
      paper_value = tr%value
   end function paper_value

   !> Copy a NUL-terminated description of `status` into `buffer` (at most `length` bytes).
   subroutine hillstab_c_error_message(status, buffer, length) bind(C, name="hillstab_error_message")
      integer(c_int), value, intent(in) :: status
      integer(c_size_t), value, intent(in) :: length
      character(kind=c_char), intent(out) :: buffer(length)
      character(len=:), allocatable :: text
      integer :: i, n
      if (length < 1) return
      if (status == 0) then
         text = "success"
      else
         text = error_code_name(int(status))
      end if
      n = min(len(text), int(length) - 1)
      do i = 1, n
         buffer(i) = text(i:i)
      end do
      buffer(n + 1) = c_null_char
   end subroutine hillstab_c_error_message
end module hillstab_capi

!> Mathieu characteristic values a_n(q), b_n(q) by GSL (`gsl_sf_mathieu_a_e/_b_e`) and
!> the transition curves of the paper's Mathieu form q(τ) = β − ν cos πτ (A1): with
!> z = πτ/2 it is y'' + (a − 2q cos 2z) y = 0, a = 4β/π², q = 2ν/π², so the curves are
!> β = (π²/4) a_n(2ν/π²) and β = (π²/4) b_n(2ν/π²) (the Mathieu equation in its standard form). `mathieu_witness` gives
!> that β where GSL is trusted, as the independent witness of the Mathieu chart's curves.
!>
!> GSL's abort-on-error handler is switched off before every call and its status is
!> reported through `error_t`; no module state, so threads may call these at once.
!>
!>```fortran
!> real(wp) :: a0
!> type(error_t), allocatable :: error
!> call mathieu_a(0, 1.0_wp, a0, error)   ! -0.455138604107
!>```
module hillstab_hill_mathieu
   use, intrinsic :: iso_c_binding, only: c_int, c_double, c_funptr
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use hillstab_core_kinds, only: wp, pi2
   use hillstab_core_error, only: error_t, set_error, err_invalid_parameter, err_integration
   use hillstab_ffi_gsl, only: gsl_sf_result, gsl_sf_mathieu_a_e, gsl_sf_mathieu_b_e, gsl_set_error_handler_off, &
      gsl_success
   implicit none
   private
   public :: mathieu_a, mathieu_b, mathieu_transition_beta, mathieu_kind_a, mathieu_kind_b, mathieu_max_order
   public :: mathieu_witness, gsl_witness_max_q

   !> Curves of the even Mathieu functions ce_n: a_n(q), n ≥ 0.
   integer, parameter :: mathieu_kind_a = 1
   !> Curves of the odd Mathieu functions se_n: b_n(q), n ≥ 1.
   integer, parameter :: mathieu_kind_b = 2
   !> Largest order accepted. GSL's initial guess switches to n² at order 70 and
   !> its root search then converges to wrong values at large q (a known upstream
   !> bug); orders up to 60 keep a margin. (GSL's continued fractions also stop at
   !> 50 terms, so accuracy degrades for |q| of order 1e3 and beyond; hillstab's
   !> Mathieu charts need |q| = 2|ν|/π² of order 1.)
   integer, parameter :: mathieu_max_order = 60
   !> GSL's Mathieu values are used as a witness only for |q| up to this. Measured
   !> against Hill's method: every a_n, b_n with n ≤ 60 within 1e-12 relative (worst
   !> 9.7e-13) for q = 1 … 5000; orders beyond 60 are refused (GSL's root search fails
   !> there at large q). The bound keeps a margin below what was measured.
   real(wp), parameter :: gsl_witness_max_q = 1000.0_wp

contains

   !> Characteristic value a_n(q) of the even Mathieu functions (GSL).
   subroutine mathieu_a(n, q, value, error)
      integer, intent(in) :: n             !! order, 0 ≤ n ≤ mathieu_max_order
      real(wp), intent(in) :: q            !! Mathieu parameter (any sign)
      real(wp), intent(out) :: value       !! a_n(q)
      type(error_t), allocatable, intent(out) :: error  !! GSL failure; unallocated on success
      call mathieu_characteristic(mathieu_kind_a, n, q, value, error)
   end subroutine mathieu_a

   !> Characteristic value b_n(q) of the odd Mathieu functions (GSL).
   subroutine mathieu_b(n, q, value, error)
      integer, intent(in) :: n             !! order, 1 ≤ n ≤ mathieu_max_order
      real(wp), intent(in) :: q            !! Mathieu parameter (any sign)
      real(wp), intent(out) :: value       !! b_n(q)
      type(error_t), allocatable, intent(out) :: error  !! GSL failure; unallocated on success
      call mathieu_characteristic(mathieu_kind_b, n, q, value, error)
   end subroutine mathieu_b

   !> β on the n-th transition curve of q(τ) = β − ν cos πτ: (π²/4) a_n(2ν/π²)
   !> (kind a) or (π²/4) b_n(2ν/π²) (kind b). On it the trace is +2 for even n
   !> (2-periodic solution) and −2 for odd n (antiperiodic).
   subroutine mathieu_transition_beta(kind, n, nu, beta, error)
      integer, intent(in) :: kind          !! mathieu_kind_a or mathieu_kind_b
      integer, intent(in) :: n             !! order of the curve
      real(wp), intent(in) :: nu           !! ν, the amplitude of the cosine
      real(wp), intent(out) :: beta        !! β on the curve
      type(error_t), allocatable, intent(out) :: error  !! GSL failure or bad kind; unallocated on success
      real(wp) :: a
      call mathieu_characteristic(kind, n, 2.0_wp*nu/pi2, a, error)
      beta = 0.25_wp*pi2*a
   end subroutine mathieu_transition_beta

   !> GSL's β for the Mathieu curve (order, parity) at ν, when GSL is trusted there
   !> (order ≤ mathieu_max_order, |q| = 2|ν|/π² ≤ gsl_witness_max_q); `available` false otherwise.
   subroutine mathieu_witness(order, parity, nu, beta, available)
      integer, intent(in) :: order, parity  !! order n of the curve; parity: 1 even (a_n), 2 odd (b_n)
      real(wp), intent(in) :: nu  !! Mathieu amplitude nu
      real(wp), intent(out) :: beta  !! GSL's beta on the curve (0 when not available)
      logical, intent(out) :: available  !! GSL is trusted at this order and q
      type(error_t), allocatable :: error
      beta = 0.0_wp
      available = order <= mathieu_max_order .and. 2.0_wp*abs(nu)/pi2 <= gsl_witness_max_q .and. &
                  (parity == 1 .or. order >= 1)
      if (.not. available) return
      call mathieu_transition_beta(merge(mathieu_kind_a, mathieu_kind_b, parity == 1), order, nu, beta, error)
      if (allocated(error)) then
         available = .false.
         beta = 0.0_wp
      end if
   end subroutine mathieu_witness

   subroutine mathieu_characteristic(kind, n, q, value, error)
      integer, intent(in) :: kind, n
      real(wp), intent(in) :: q
      real(wp), intent(out) :: value
      type(error_t), allocatable, intent(out) :: error
      type(gsl_sf_result) :: result
      type(c_funptr) :: previous
      integer(c_int) :: status
      integer :: lowest
      character(len=120) :: buf
      value = 0.0_wp
      if (kind /= mathieu_kind_a .and. kind /= mathieu_kind_b) then
         call set_error(error, err_invalid_parameter, "Mathieu kind must be mathieu_kind_a or mathieu_kind_b")
         return
      end if
      lowest = merge(0, 1, kind == mathieu_kind_a)
      if (n < lowest .or. n > mathieu_max_order) then
         write (buf, '(a,a,a,i0,a,i0,a,i0)') "Mathieu order of ", trim(kind_letter(kind)), "_n must be in ", &
            lowest, "..", mathieu_max_order, " (GSL is unreliable beyond), got n = ", n
         call set_error(error, err_invalid_parameter, trim(buf))
         return
      end if
      if (.not. ieee_is_finite(q)) then
         call set_error(error, err_invalid_parameter, "Mathieu parameter q must be finite")
         return
      end if
      previous = gsl_set_error_handler_off()
      result = gsl_sf_result(0.0_c_double, 0.0_c_double)
      if (kind == mathieu_kind_a) then
         status = gsl_sf_mathieu_a_e(int(n, c_int), real(q, c_double), result)
      else
         status = gsl_sf_mathieu_b_e(int(n, c_int), real(q, c_double), result)
      end if
      if (status /= gsl_success .or. .not. (ieee_is_finite(result%val) .and. ieee_is_finite(result%err))) then
         write (buf, '(a,a,a,i0,a,es12.5,a,i0)') "GSL failed to compute Mathieu ", trim(kind_letter(kind)), "_", &
            n, "(q) at q = ", q, ", status ", status
         call set_error(error, err_integration, trim(buf))
         return
      end if
      value = result%val
   end subroutine mathieu_characteristic

   pure function kind_letter(kind) result(letter)
      integer, intent(in) :: kind
      character(len=1) :: letter
      letter = merge("a", "b", kind == mathieu_kind_a)
   end function kind_letter
end module hillstab_hill_mathieu

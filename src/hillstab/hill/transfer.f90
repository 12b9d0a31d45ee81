!> Exact transfer matrices of x'' + q x = 0 with constant q, their products,
!> and overflow-safe (log-scaled) monodromy matrices and traces.
!>
!> For constant q over a length h the transfer matrix is
!> [[C, h S], [−q h S, C]] with z = q h², C = cos √z, S = sin √z / √z
!> (cosh/sinh for z < 0; power series for |z| small, never 0/0).
!> Strongly negative q makes entries grow like e^{√|z|}; `scaled_matrix_t`
!> stores M = e^{log_scale} m with max|m| = 1 so products never overflow.
!>
!>```fortran
!> type(scaled_matrix_t) :: m
!> m = scaled_identity()
!> call multiply_transfer(m, q=3.0_wp, h=1.0_wp)
!> print *, trace_of(m)%value
!>```
module hillstab_hill_transfer
   use hillstab_core_kinds, only: wp, log_huge
   implicit none
   private
   public :: transfer_matrix, transfer_functions, transfer_increment, scaled_matrix_t, scaled_identity, scaled_from_matrix
   public :: cos_sinc_taylor, step_functions, taylor_max_degree, cos_taylor, sinc_taylor
   public :: multiply_transfer, multiply_scaled, multiply_matrix, normalize_scaled, add_compensated
   public :: trace_t, trace_of, trace_from_value, trace_from_scaled, matrix_of, determinant, determinant_of
   public :: monodromy_from_half_period, monodromy_from_window

   !> Full-period monodromy of an even coefficient from the half-period propagator
   !> Φ(1) = [[u, v], [u', v']] (Floquet theory of the even coefficient): M = [[u v' + u' v, 2 v v'], [2 u u', u v' + u' v]].
   interface monodromy_from_half_period
      module procedure monodromy_from_half_period_scaled
      module procedure monodromy_from_half_period_columns
   end interface monodromy_from_half_period

   !> The monodromy from the propagator over a method's window: `monodromy_from_half_period`
   !> where the window is half a period of a coefficient even about its start, the propagator
   !> itself where it is the whole period.
   interface monodromy_from_window
      module procedure monodromy_from_window_scaled
      module procedure monodromy_from_window_columns
   end interface monodromy_from_window

   !> 2×2 matrix M = exp(log_scale) · m, m normalized so that max |m_ij| = 1.
   type :: scaled_matrix_t
      real(wp) :: m(2, 2) = reshape([1.0_wp, 0.0_wp, 0.0_wp, 1.0_wp], [2, 2])  !! normalized matrix
      real(wp) :: log_scale = 0.0_wp  !! natural logarithm of the scale factor
   end type scaled_matrix_t

   !> A trace that may exceed the range of real(wp).
   type :: trace_t
      real(wp) :: value = 0.0_wp      !! S; clamped to ±huge(1.0_wp) when `overflow`
      real(wp) :: log_abs = -huge(1.0_wp)  !! ln|S| (−huge when S = 0)
      logical :: overflow = .false.   !! |S| does not fit in real(wp)
      !> estimated error of S relative to max(1, |S|) (the scale of the methods' tolerance),
      !> as the method measured it; negative when the method gives no estimate
      real(wp) :: error_estimate = -1.0_wp
   end type trace_t

   !> Below this |q h²| the series for C and S are used (12 terms reach round-off).
   real(wp), parameter :: series_limit = 0.5_wp
   !> Beyond this √|z| the hyperbolic functions are returned scaled by e^{−√|z|}.
   real(wp), parameter :: scale_limit = 20.0_wp
   !> Highest degree in z of the Taylor polynomials of `cos_sinc_taylor`.
   integer, parameter :: taylor_max_degree = 16
   !> Taylor coefficients of C = cos √z = Σ (−z)^k/(2k)! …
   real(wp), parameter :: cos_taylor(0:taylor_max_degree) = [ &
      1.0_wp/1.0_wp, -1.0_wp/2.0_wp, 1.0_wp/24.0_wp, -1.0_wp/720.0_wp, 1.0_wp/40320.0_wp, &
      -1.0_wp/3628800.0_wp, 1.0_wp/479001600.0_wp, -1.0_wp/87178291200.0_wp, 1.0_wp/20922789888000.0_wp, &
      -1.0_wp/6402373705728000.0_wp, 1.0_wp/2432902008176640000.0_wp, -1.0_wp/1124000727777607680000.0_wp, &
      1.0_wp/620448401733239439360000.0_wp, -1.0_wp/403291461126605635584000000.0_wp, &
      1.0_wp/304888344611713860501504000000.0_wp, -1.0_wp/265252859812191058636308480000000.0_wp, &
      1.0_wp/263130836933693530167218012160000000.0_wp]
   !> … and of S = sin √z/√z = Σ (−z)^k/(2k+1)!
   real(wp), parameter :: sinc_taylor(0:taylor_max_degree) = [ &
      1.0_wp/1.0_wp, -1.0_wp/6.0_wp, 1.0_wp/120.0_wp, -1.0_wp/5040.0_wp, 1.0_wp/362880.0_wp, &
      -1.0_wp/39916800.0_wp, 1.0_wp/6227020800.0_wp, -1.0_wp/1307674368000.0_wp, 1.0_wp/355687428096000.0_wp, &
      -1.0_wp/121645100408832000.0_wp, 1.0_wp/51090942171709440000.0_wp, &
      -1.0_wp/25852016738884976640000.0_wp, 1.0_wp/15511210043330985984000000.0_wp, &
      -1.0_wp/10888869450418352160768000000.0_wp, 1.0_wp/8841761993739701954543616000000.0_wp, &
      -1.0_wp/8222838654177922817725562880000000.0_wp, 1.0_wp/8683317618811886495518194401280000000.0_wp]

contains

   !> C = cos √z and S = sin √z/√z (cosh, sinh for z < 0), scaled by e^{−log_scale}:
   !> log_scale = √(−z) when z < −scale_limit², else 0.
   elemental subroutine transfer_functions(z, c, s, log_scale)
      real(wp), intent(in) :: z           !! q h²
      real(wp), intent(out) :: c          !! (scaled) cos √z
      real(wp), intent(out) :: s          !! (scaled) sin √z / √z
      real(wp), intent(out) :: log_scale  !! ln of the scale factor removed
      real(wp) :: x, decay
      log_scale = 0.0_wp
      if (abs(z) < series_limit) then
         call cos_sinc_series(z, 1.0_wp, c, s)
      else if (z > 0.0_wp) then
         x = sqrt(z)
         c = cos(x)
         s = sin(x)/x
      else
         x = sqrt(-z)
         if (x < scale_limit) then
            c = cosh(x)
            s = sinh(x)/x
         else
            decay = exp(-2.0_wp*x)
            c = 0.5_wp*(1.0_wp + decay)
            s = 0.5_wp*(1.0_wp - decay)/x
            log_scale = x
         end if
      end if
   end subroutine transfer_functions

   !> The series C = Σ (−z)^k/(2k)!, S = Σ (−z)^k/(2k+1)! for |z| < series_limit (11
   !> terms: 1e-17 at |z| < 0.5), C's sum started at `c_start` (1 for C, 0 for C − 1).
   elemental subroutine cos_sinc_series(z, c_start, c, s)
      real(wp), intent(in) :: z        !! q h²
      real(wp), intent(in) :: c_start  !! the k = 0 term of C's sum (1), or 0 for C − 1
      real(wp), intent(out) :: c       !! C, or C − 1
      real(wp), intent(out) :: s       !! sin √z / √z
      real(wp) :: term_c, term_s
      integer :: k
      c = c_start; s = 1.0_wp
      term_c = 1.0_wp; term_s = 1.0_wp
      do k = 1, 11
         term_c = -term_c*z/real((2*k - 1)*(2*k), wp)
         term_s = -term_s*z/real((2*k)*(2*k + 1), wp)
         c = c + term_c
         s = s + term_s
      end do
   end subroutine cos_sinc_series

   !> The Taylor polynomials of degree `degree` in z of C = cos √z and S = sin √z/√z, by
   !> Horner's rule (truncation below 5e-26 at degree 10, 1.3e-19 at degree 5 for |z| ≤ 0.02,
   !> relative to 1): the short series of Magnus steps, which are short against the local
   !> oscillation. (`cos_sinc_series`, whose roundings differ, serves `transfer_functions`.)
   elemental subroutine cos_sinc_taylor(z, degree, c, s)
      real(wp), intent(in) :: z        !! q h² (or −det of a Magnus generator)
      integer, intent(in) :: degree    !! degree in z, 0 … taylor_max_degree
      real(wp), intent(out) :: c       !! cos √z
      real(wp), intent(out) :: s       !! sin √z / √z
      integer :: k
      c = cos_taylor(degree)
      s = sinc_taylor(degree)
      do k = degree - 1, 0, -1
         c = cos_taylor(k) + z*c
         s = sinc_taylor(k) + z*s
      end do
   end subroutine cos_sinc_taylor

   !> C = cos √z, S = sin √z/√z of a Magnus step: Taylor polynomials of degree 5 for
   !> |z| ≤ 0.01 and 7 for |z| ≤ 0.1 (truncation below 3e-21 relative), otherwise the
   !> overflow-safe `transfer_functions`. Magnus steps are short against the local
   !> oscillation, so the polynomials serve almost every step.
   elemental subroutine step_functions(z, c, s, log_scale)
      real(wp), intent(in) :: z           !! −det of the step's generator (q h² for constant q)
      real(wp), intent(out) :: c          !! (scaled) cos √z
      real(wp), intent(out) :: s          !! (scaled) sin √z / √z
      real(wp), intent(out) :: log_scale  !! ln of the scale factor removed (as `transfer_functions`)
      log_scale = 0.0_wp
      if (abs(z) <= 0.01_wp) then
         call cos_sinc_taylor(z, 5, c, s)
      else if (abs(z) <= 0.1_wp) then
         call cos_sinc_taylor(z, 7, c, s)
      else
         call transfer_functions(z, c, s, log_scale)
      end if
   end subroutine step_functions

   !> As `transfer_functions`, but with C − 1 in place of C, accurate when C is close to 1
   !> (short steps): the step matrix C I + S Ω is then applied as I + ((C − 1) I + S Ω),
   !> whose increment carries rounding errors relative to the increment, not to the
   !> identity. When log_scale > 0 (long growing steps) `c_minus_1` is the scaled C − 1.
   elemental subroutine transfer_increment(z, c_minus_1, s, log_scale)
      real(wp), intent(in) :: z           !! q h²
      real(wp), intent(out) :: c_minus_1  !! cos √z − 1 (cosh for z < 0), or the scaled C minus 1
      real(wp), intent(out) :: s          !! (scaled) sin √z / √z
      real(wp), intent(out) :: log_scale  !! ln of the scale factor removed (as `transfer_functions`)
      real(wp) :: x, half
      log_scale = 0.0_wp
      if (abs(z) < series_limit) then
         call cos_sinc_series(z, 0.0_wp, c_minus_1, s)
      else if (z > 0.0_wp) then
         x = sqrt(z)
         half = sin(0.5_wp*x)
         c_minus_1 = -2.0_wp*half*half
         s = sin(x)/x
      else
         x = sqrt(-z)
         if (x < scale_limit) then
            half = sinh(0.5_wp*x)
            c_minus_1 = 2.0_wp*half*half
            s = sinh(x)/x
         else
            call transfer_functions(z, c_minus_1, s, log_scale)
            c_minus_1 = c_minus_1 - 1.0_wp
         end if
      end if
   end subroutine transfer_increment

   !> Exact transfer matrix T(h) of x'' + q x = 0, X = (x, x'), for moderate |q| h²
   !> (entries of order e^{√|q| h}; use `multiply_transfer` when that may overflow).
   pure function transfer_matrix(q, h) result(t)
      real(wp), intent(in) :: q  !! constant coefficient
      real(wp), intent(in) :: h  !! length of the piece
      real(wp) :: t(2, 2)
      real(wp) :: c, s, log_scale, f
      call transfer_functions(q*h*h, c, s, log_scale)
      f = exp(min(log_scale, log_huge))
      t(1, 1) = c*f; t(1, 2) = h*s*f
      t(2, 1) = -q*h*s*f; t(2, 2) = c*f
   end function transfer_matrix

   !> The identity as a scaled matrix.
   pure function scaled_identity() result(a)
      type(scaled_matrix_t) :: a
      a%m = reshape([1.0_wp, 0.0_wp, 0.0_wp, 1.0_wp], [2, 2])
      a%log_scale = 0.0_wp
   end function scaled_identity

   !> Wrap a plain matrix.
   pure function scaled_from_matrix(m) result(a)
      real(wp), intent(in) :: m(2, 2)  !! a 2x2 matrix
      type(scaled_matrix_t) :: a
      a%m = m
      a%log_scale = 0.0_wp
      call normalize_scaled(a)
   end function scaled_from_matrix

   !> Rescale so that max |m_ij| = 1 (powers of two: exact).
   pure subroutine normalize_scaled(a)
      type(scaled_matrix_t), intent(inout) :: a  !! the matrix, rescaled
      real(wp) :: big
      integer :: e
      big = maxval(abs(a%m))
      if (big == 0.0_wp) return
      e = exponent(big)
      a%m = scale(a%m, -e)
      a%log_scale = a%log_scale + e*log(2.0_wp)
   end subroutine normalize_scaled

   !> sum ← sum + term by compensated (Kahan) summation: `compensation` carries the rounding
   !> error of the running sum (start it at 0; the exact sum is about sum − compensation).
   elemental subroutine add_compensated(sum, term, compensation)
      real(wp), intent(inout) :: sum           !! the running sum
      real(wp), intent(in) :: term             !! the term added
      real(wp), intent(inout) :: compensation  !! the carried rounding error
      real(wp) :: increment, total
      increment = term - compensation
      total = sum + increment
      compensation = (total - sum) - increment
      sum = total
   end subroutine add_compensated

   !> a ← T(q, h) · a: advance by one constant piece.
   !>
   !> With `compensation`, the piece's increment of a%log_scale (its own scale and the
   !> power of two of the normalization) is added by compensated (Kahan) summation, the
   !> running rounding error kept in `compensation` (subtract it from a%log_scale at the
   !> end): plain summation of the ~ln|S|/ln 2 increments of ln 2 errs systematically,
   !> by 5e-10 in ln|S| at β = −1e6, α = 9.86 and 9e-12 at α = 0, β = −1e5.
   pure subroutine multiply_transfer(a, q, h, compensation)
      type(scaled_matrix_t), intent(inout) :: a  !! the product so far, advanced
      real(wp), intent(in) :: q, h  !! constant coefficient of the piece; its length in tau
      real(wp), intent(inout), optional :: compensation  !! Kahan carry of a%log_scale
      real(wp) :: c, s, log_scale, t(2, 2), before
      call transfer_functions(q*h*h, c, s, log_scale)
      t(1, 1) = c; t(1, 2) = h*s
      t(2, 1) = -q*h*s; t(2, 2) = c
      a%m = matmul(t, a%m)
      if (present(compensation)) then
         before = a%log_scale
         a%log_scale = log_scale
         call normalize_scaled(a)
         call add_compensated(before, a%log_scale, compensation)
         a%log_scale = before
      else
         a%log_scale = a%log_scale + log_scale
         call normalize_scaled(a)
      end if
   end subroutine multiply_transfer

   !> a ← m · a for a plain matrix m.
   pure subroutine multiply_matrix(a, m)
      type(scaled_matrix_t), intent(inout) :: a  !! the product so far, multiplied
      real(wp), intent(in) :: m(2, 2)  !! the left factor, a plain 2x2 matrix
      a%m = matmul(m, a%m)
      call normalize_scaled(a)
   end subroutine multiply_matrix

   !> Product b · a of scaled matrices.
   pure function multiply_scaled(b, a) result(c)
      type(scaled_matrix_t), intent(in) :: b, a  !! left and right factor
      type(scaled_matrix_t) :: c
      c%m = matmul(b%m, a%m)
      c%log_scale = a%log_scale + b%log_scale
      call normalize_scaled(c)
   end function multiply_scaled

   !> Trace of a scaled matrix, flagged (and clamped) if it does not fit.
   pure function trace_of(a) result(tr)
      type(scaled_matrix_t), intent(in) :: a  !! the matrix
      type(trace_t) :: tr
      tr = trace_from_scaled(a%m(1, 1) + a%m(2, 2), a%log_scale)
   end function trace_of

   !> The trace t·e^{log_scale}: its value, ln|·| and the overflow flag (value clamped to
   !> ±huge when it does not fit).
   elemental function trace_from_scaled(t, log_scale) result(tr)
      real(wp), intent(in) :: t          !! mantissa
      real(wp), intent(in) :: log_scale  !! natural logarithm of the scale factor
      type(trace_t) :: tr
      if (t == 0.0_wp) then
         tr = trace_t(0.0_wp, -huge(1.0_wp), .false.)
         return
      end if
      tr%log_abs = log(abs(t)) + log_scale
      if (log_scale == 0.0_wp) then
         tr%value = t   ! t·e⁰, without the call
         tr%overflow = .false.
      else if (tr%log_abs < log_huge) then
         tr%value = t*exp(log_scale)
         tr%overflow = .false.
      else
         tr%value = sign(huge(1.0_wp), t)
         tr%overflow = .true.
      end if
   end function trace_from_scaled

   !> `monodromy_from_window` for Φ held as one scaled matrix (the window of hillstab_hill_model
   !> `hill_window_t`).
   pure function monodromy_from_window_scaled(phi, half) result(m)
      type(scaled_matrix_t), intent(in) :: phi  !! the propagator over the window
      logical, intent(in) :: half               !! the window is half a period
      type(scaled_matrix_t) :: m
      if (half) then
         m = monodromy_from_half_period_scaled(phi)
      else
         m = phi
      end if
   end function monodromy_from_window_scaled

   !> `monodromy_from_window` for Φ = [[u, v], [u', v']] whose columns carry their own scales
   !> (u, u' times e^{log_u}; v, v' times e^{log_v}).
   pure function monodromy_from_window_columns(phi, log_u, log_v, half) result(m)
      real(wp), intent(in) :: phi(2, 2)  !! [[u, v], [u', v']] at the end of the window, each column scaled
      real(wp), intent(in) :: log_u, log_v  !! ln of the scales of the u and v columns
      logical, intent(in) :: half           !! the window is half a period
      type(scaled_matrix_t) :: m
      real(wp) :: top
      if (half) then
         m = monodromy_from_half_period_columns(phi, log_u, log_v)
      else
         top = max(log_u, log_v)
         m%m(:, 1) = phi(:, 1)*exp(max(log_u - top, -log_huge))
         m%m(:, 2) = phi(:, 2)*exp(max(log_v - top, -log_huge))
         m%log_scale = top
         call normalize_scaled(m)
      end if
   end function monodromy_from_window_columns

   !> monodromy_from_half_period for Φ(1) held as one scaled matrix. The scale doubles:
   !> M is quadratic in Φ.
   pure function monodromy_from_half_period_scaled(phi) result(m)
      type(scaled_matrix_t), intent(in) :: phi  !! the propagator over [0, 1]
      type(scaled_matrix_t) :: m
      m = monodromy_from_half_period_columns(phi%m, phi%log_scale, phi%log_scale)
   end function monodromy_from_half_period_scaled

   !> monodromy_from_half_period for Φ(1) = [[u, v], [u', v']] whose columns carry their own
   !> scales (u, u' times e^{log_u}; v, v' times e^{log_v}), as integrators that rescale
   !> each solution separately produce them.
   pure function monodromy_from_half_period_columns(phi, log_u, log_v) result(m)
      real(wp), intent(in) :: phi(2, 2)  !! [[u, v], [u', v']] at tau = 1, each column scaled
      real(wp), intent(in) :: log_u, log_v  !! ln of the scales of the u and v columns
      type(scaled_matrix_t) :: m
      real(wp) :: u, du, v, dv, top
      u = phi(1, 1); du = phi(2, 1)
      v = phi(1, 2); dv = phi(2, 2)
      ! the diagonal carries e^{log_u + log_v}, the corners e^{2 log_v} and e^{2 log_u}
      top = 2.0_wp*max(log_u, log_v)
      m%m(1, 1) = (u*dv + du*v)*exp(log_u + log_v - top)
      m%m(2, 2) = m%m(1, 1)
      m%m(1, 2) = 2.0_wp*v*dv*exp(2.0_wp*log_v - top)
      m%m(2, 1) = 2.0_wp*u*du*exp(2.0_wp*log_u - top)
      m%log_scale = top
      call normalize_scaled(m)
   end function monodromy_from_half_period_columns

   !> A finite trace value as a trace_t.
   elemental function trace_from_value(s) result(tr)
      real(wp), intent(in) :: s  !! a finite trace
      type(trace_t) :: tr
      tr%value = s
      tr%overflow = .false.
      if (s == 0.0_wp) then
         tr%log_abs = -huge(1.0_wp)
      else
         tr%log_abs = log(abs(s))
      end if
   end function trace_from_value

   !> The plain matrix (entries clamped to ±huge if the scale overflows).
   pure function matrix_of(a) result(m)
      type(scaled_matrix_t), intent(in) :: a  !! the matrix
      real(wp) :: m(2, 2)
      m = a%m*exp(min(a%log_scale, log_huge))
   end function matrix_of

   !> Determinant of a plain 2×2 matrix.
   pure real(wp) function determinant(m)
      real(wp), intent(in) :: m(2, 2)  !! a 2x2 matrix
      determinant = m(1, 1)*m(2, 2) - m(1, 2)*m(2, 1)
   end function determinant

   !> Determinant of a scaled matrix, returned as (mantissa, ln scale):
   !> det = d · e^{log_det_scale}.
   pure subroutine determinant_of(a, d, log_det_scale)
      type(scaled_matrix_t), intent(in) :: a  !! the matrix
      real(wp), intent(out) :: d, log_det_scale  !! mantissa and ln scale of the determinant
      d = determinant(a%m)
      log_det_scale = 2.0_wp*a%log_scale
   end subroutine determinant_of
end module hillstab_hill_transfer

!> A test-only model of the form Q(τ) = β + α f(τ) with f given by its harmonics over a
!> period P (cosine and sine terms, any P), or the square wave f = +1 on [0, P/2), −1 on
!> [P/2, P) (Meissner, infinitely many harmonics), or either withholding its harmonics (a
!> model Hill's method does not know), for the tests of Hill's method on the
!> Fourier coefficients; and the full-period references the tests compare it with: S by
!> sixth-order Magnus steps over [0, P] (no use of any symmetry of Q) and bisection on it.
module hillstab_test_drive_model
   use hillstab_core_kinds, only: wp, pi, int64
   use hillstab_hill_model, only: hill_model_t, hill_point_t, hill_window_t, harmonics_infinite, harmonics_none
   use hillstab_hill_transfer, only: scaled_matrix_t
   use hillstab_integrate_magnus, only: magnus_step
   implicit none
   private
   public :: drive_model_t, drive_model, square_model, full_period_trace, bisect_full_period

   !> Q = β + α (f₀ + Σₘ aₘ cos(2πmτ/P) + bₘ sin(2πmτ/P)), or β + α sq(τ) (`square`).
   type, extends(hill_model_t) :: drive_model_t
      real(wp) :: p = 2.0_wp                 !! the period P
      real(wp) :: f0 = 0.0_wp                !! mean of f
      real(wp), allocatable :: a(:), b(:)    !! cosine and sine coefficients of f
      logical :: square = .false.            !! f is the square wave instead
      !> the model does not say it is β + g (drive_harmonic_count = harmonics_none): the
      !> transition curves go by the roots of S
      logical :: withhold = .false.
   contains
      procedure :: name => drive_name
      procedure :: formula => drive_formula
      procedure :: coefficient => drive_coefficient
      procedure :: segment_mean => drive_segment_mean
      procedure :: split => drive_split
      procedure :: shapes => drive_shapes
      procedure :: shape_range => drive_shape_range
      procedure :: period => drive_period
      procedure :: window => drive_window
      procedure :: drive_harmonic_count => drive_count
      procedure :: drive_harmonics => drive_coefficients
   end type drive_model_t

contains

   !> A model with the given harmonics of f over the period p.
   function drive_model(p, f0, a, b) result(model)
      real(wp), intent(in) :: p, f0, a(:), b(:)
      type(drive_model_t) :: model
      model%p = p
      model%f0 = f0
      model%a = a
      model%b = b
   end function drive_model

   !> The square wave of period p (Meissner): f = +1 on [0, p/2), −1 on [p/2, p).
   function square_model(p) result(model)
      real(wp), intent(in) :: p
      type(drive_model_t) :: model
      model%p = p
      model%square = .true.
      allocate (model%a(0), model%b(0))
   end function square_model

   pure function drive_name(self) result(text)
      class(drive_model_t), intent(in) :: self
      character(len=:), allocatable :: text
      text = "drive_test"
   end function drive_name

   pure function drive_formula(self) result(text)
      class(drive_model_t), intent(in) :: self
      character(len=:), allocatable :: text
      text = "Q(tau) = beta + alpha f(tau), f given by its harmonics (test model)"
   end function drive_formula

   elemental real(wp) function shape(self, tau) result(f)
      class(drive_model_t), intent(in) :: self
      real(wp), intent(in) :: tau
      real(wp) :: x
      integer :: m
      if (self%square) then
         x = modulo(tau, self%p)
         f = merge(1.0_wp, -1.0_wp, x < 0.5_wp*self%p)
         return
      end if
      f = self%f0
      do m = 1, size(self%a)
         x = 2.0_wp*pi*m*tau/self%p
         f = f + self%a(m)*cos(x) + self%b(m)*sin(x)
      end do
   end function shape

   elemental real(wp) function drive_coefficient(self, alpha, beta, tau) result(q)
      class(drive_model_t), intent(in) :: self
      real(wp), intent(in) :: alpha, beta, tau
      q = beta + alpha*shape(self, tau)
   end function drive_coefficient

   !> Exact mean over [ta, tb] (the square wave: by its pieces).
   pure real(wp) function drive_segment_mean(self, alpha, beta, tau_a, tau_b) result(q)
      class(drive_model_t), intent(in) :: self
      real(wp), intent(in) :: alpha, beta, tau_a, tau_b
      real(wp) :: w, total, t, next, half
      integer :: m
      if (self%square) then
         half = 0.5_wp*self%p
         total = 0.0_wp
         t = tau_a
         do while (t < tau_b)
            next = min(tau_b, (floor(t/half) + 1)*half)
            total = total + (next - t)*shape(self, 0.5_wp*(t + next))
            t = next
         end do
         q = beta + alpha*total/(tau_b - tau_a)
         return
      end if
      w = self%f0
      do m = 1, size(self%a)
         associate (k => 2.0_wp*pi*m/self%p)
            w = w + (self%a(m)*(sin(k*tau_b) - sin(k*tau_a)) - self%b(m)*(cos(k*tau_b) - cos(k*tau_a)))/ &
                (k*(tau_b - tau_a))
         end associate
      end do
      q = beta + alpha*w
   end function drive_segment_mean

   elemental subroutine drive_split(self, alpha, beta, c0, c1)
      class(drive_model_t), intent(in) :: self
      real(wp), intent(in) :: alpha, beta
      real(wp), intent(out) :: c0, c1
      c0 = beta
      c1 = alpha
   end subroutine drive_split

   pure subroutine drive_shapes(self, alpha, tau, w)
      class(drive_model_t), intent(in) :: self
      real(wp), intent(in) :: alpha, tau(:)
      real(wp), intent(out) :: w(:)
      w = shape(self, tau)
   end subroutine drive_shapes

   !> A range containing f: ±(|f₀| + Σ √(aₘ² + bₘ²)), ±1 for the square wave.
   elemental subroutine drive_shape_range(self, alpha, w_min, w_max)
      class(drive_model_t), intent(in) :: self
      real(wp), intent(in) :: alpha
      real(wp), intent(out) :: w_min, w_max
      if (self%square) then
         w_max = 1.0_wp
      else
         w_max = abs(self%f0) + sum(hypot(self%a, self%b))
      end if
      w_min = -w_max
   end subroutine drive_shape_range

   pure real(wp) function drive_period(self) result(period)
      class(drive_model_t), intent(in) :: self
      period = self%p
   end function drive_period

   !> Half the period when f is even about 0 (cosines only), else the whole period.
   pure function drive_window(self, alpha) result(window)
      class(drive_model_t), intent(in) :: self
      real(wp), intent(in) :: alpha
      type(hill_window_t) :: window
      if (.not. self%square .and. all(self%b == 0.0_wp)) then
         window = hill_window_t(start=0.0_wp, length=0.5_wp*self%p, half=.true.)
      else
         window = hill_window_t(start=0.0_wp, length=self%p, half=.false., n_breaks=0)
         if (self%square) then
            window%n_breaks = 1
            window%breaks(1) = 0.5_wp*self%p
         end if
      end if
   end function drive_window

   pure integer function drive_count(self) result(count)
      class(drive_model_t), intent(in) :: self
      if (self%withhold) then
         count = harmonics_none
      else if (self%square) then
         count = harmonics_infinite
      else
         count = size(self%a)
      end if
   end function drive_count

   !> α times f's harmonics (the square wave: 4/(πm) sin for odd m).
   pure subroutine drive_coefficients(self, alpha, n, mean, c, s)
      class(drive_model_t), intent(in) :: self
      real(wp), intent(in) :: alpha
      integer, intent(in) :: n
      real(wp), intent(out) :: mean, c(n), s(n)
      integer :: m
      c = 0.0_wp
      s = 0.0_wp
      if (self%square) then
         mean = 0.0_wp
         do m = 1, n, 2
            s(m) = alpha*4.0_wp/(pi*m)
         end do
         return
      end if
      mean = alpha*self%f0
      do m = 1, min(n, size(self%a))
         c(m) = alpha*self%a(m)
         s(m) = alpha*self%b(m)
      end do
   end subroutine drive_coefficients

   !> S over the full period [0, P] by `n_steps` equal sixth-order Magnus steps (each piece
   !> of the square wave apart: its jump at P/2 is a mesh point when n_steps is even).
   function full_period_trace(model, alpha, beta, n_steps) result(s)
      class(hill_model_t), intent(in) :: model
      real(wp), intent(in) :: alpha, beta
      integer, intent(in) :: n_steps
      real(wp) :: s
      type(scaled_matrix_t) :: a
      integer(int64) :: n_evaluations
      real(wp) :: h
      integer :: i
      h = model%period()/n_steps
      n_evaluations = 0
      do i = 0, n_steps - 1
         call magnus_step(model, hill_point_t(alpha, beta, 0.0_wp), 6, i*h, h, a, n_evaluations)
      end do
      s = (a%m(1, 1) + a%m(2, 2))*exp(a%log_scale)
   end function full_period_trace

   !> β in [lo, hi] with S(β) = target by bisection on `full_period_trace` (S − target of
   !> opposite signs at the ends), to the bracket width `width`.
   function bisect_full_period(model, alpha, target, lo_in, hi_in, n_steps, width) result(beta)
      class(hill_model_t), intent(in) :: model
      real(wp), intent(in) :: alpha, target, lo_in, hi_in, width
      integer, intent(in) :: n_steps
      real(wp) :: beta
      real(wp) :: lo, hi, f_lo, f_mid, mid
      lo = lo_in; hi = hi_in
      f_lo = full_period_trace(model, alpha, lo, n_steps) - target
      do while (hi - lo > width)
         mid = 0.5_wp*(lo + hi)
         if (mid <= lo .or. mid >= hi) exit
         f_mid = full_period_trace(model, alpha, mid, n_steps) - target
         if ((f_mid < 0.0_wp) .eqv. (f_lo < 0.0_wp)) then
            lo = mid; f_lo = f_mid
         else
            hi = mid
         end if
      end do
      beta = 0.5_wp*(lo + hi)
   end function bisect_full_period
end module hillstab_test_drive_model

!> Meissner's equation, the square-wave drive:
!>
!>     Q(τ) = β + α  on [0, 1),   Q(τ) = β − α  on [1, 2)   (period 2),
!>
!> the coefficient of the paper's two-piece approximation (eq. (28)) taken as the exact
!> equation, and of a digital (switched) drive such as a Paul trap's. Q = c₀ + c₁ w with
!> c₀ = β, c₁ = α and w the unit square wave. Q is even about τ = 1/2 (and about 3/2), not
!> about 0: the methods integrate half a period from τ = 1/2, with the jump at τ = 1 in the
!> middle of it (`window`). Each piece is a constant, so the transfer matrices are exact
!> and the trace has the closed form of the paper's eq. (37),
!>
!>     S = 2 c₊c₋ − (k₊/k₋ + k₋/k₊) s₊s₋,   k± = √(β ± α), c± = cos k±, s± = sin k±
!>
!> (cosh and sinh where β ± α < 0): method formula is exact for this model
!> (`two_pieces_exact`). The square wave's Fourier series (4/π) Σ_{m odd} sin(mπτ)/m never
!> ends, so Hill's method converges slowly here; its transition curves come from the roots
!> of the closed form.
!>
!>```fortran
!> type(meissner_model_t) :: meissner
!> print *, meissner%coefficient(1.0_wp, 2.0_wp, 1.5_wp)   ! β − α = 1
!>```
module hillstab_hill_model_meissner
   use hillstab_core_kinds, only: wp, pi
   use hillstab_hill_model, only: hill_model_t, hill_window_t, harmonics_infinite
   implicit none
   private
   public :: meissner_model_t

   !> Meissner's square-wave coefficient as a model (hillstab_hill_model).
   type, extends(hill_model_t) :: meissner_model_t
   contains
      procedure :: name => meissner_name
      procedure :: formula => meissner_formula
      procedure :: summary => meissner_summary
      procedure :: coefficient => meissner_coefficient
      procedure :: segment_mean => meissner_segment_mean
      procedure :: split => meissner_split
      procedure :: shapes => meissner_shapes
      procedure :: shape_range => meissner_shape_range
      procedure :: shape_root_mean => meissner_shape_root_mean
      procedure :: window => meissner_window
      procedure :: two_pieces_exact => meissner_two_pieces_exact
      procedure :: drive_harmonic_count => meissner_harmonic_count
      procedure :: drive_harmonics => meissner_harmonics
   end type meissner_model_t

contains

   !> "meissner".
   pure function meissner_name(self) result(text)
      class(meissner_model_t), intent(in) :: self  !! the model
      character(len=:), allocatable :: text
      text = "meissner"
   end function meissner_name

   !> The coefficient as output headers state it.
   pure function meissner_formula(self) result(text)
      class(meissner_model_t), intent(in) :: self  !! the model
      character(len=:), allocatable :: text
      text = "Q(tau) = beta + alpha on [0, 1), beta - alpha on [1, 2) (period 2), Meissner's square wave"
   end function meissner_formula

   !> The coefficient in a few words (a template's comment).
   pure function meissner_summary(self) result(text)
      class(meissner_model_t), intent(in) :: self  !! the model
      character(len=:), allocatable :: text
      text = "Q = beta + alpha on [0, 1), beta - alpha on [1, 2): a square wave"
   end function meissner_summary

   !> The unit square wave: +1 on [0, 1), −1 on [1, 2), period 2.
   elemental real(wp) function square_wave(tau) result(w)
      real(wp), intent(in) :: tau  !! τ
      if (modulo(tau, 2.0_wp) < 1.0_wp) then
         w = 1.0_wp
      else
         w = -1.0_wp
      end if
   end function square_wave

   !> ∫₀^τ of the unit square wave: the triangle wave, τ on [0, 1], 2 − τ on [1, 2], period 2.
   elemental real(wp) function square_wave_integral(tau) result(f)
      real(wp), intent(in) :: tau  !! τ
      real(wp) :: t
      t = modulo(tau, 2.0_wp)
      f = min(t, 2.0_wp - t)
   end function square_wave_integral

   !> Q(τ) = β ± α.
   elemental real(wp) function meissner_coefficient(self, alpha, beta, tau) result(q)
      class(meissner_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha, beta          !! the point
      real(wp), intent(in) :: tau                  !! dimensionless time
      q = beta + alpha*square_wave(tau)
   end function meissner_coefficient

   !> Exact mean of Q over [τ_a, τ_b]: β + α (F(τ_b) − F(τ_a))/(τ_b − τ_a), F the triangle wave.
   pure real(wp) function meissner_segment_mean(self, alpha, beta, tau_a, tau_b) result(q)
      class(meissner_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha, beta          !! the point
      real(wp), intent(in) :: tau_a, tau_b         !! segment ends, tau_a < tau_b
      ! (whole periods contribute nothing: the square wave's mean is 0, F is periodic)
      q = beta + alpha*(square_wave_integral(tau_b) - square_wave_integral(tau_a))/(tau_b - tau_a)
   end function meissner_segment_mean

   !> Q = β + α w: c₀ = β, c₁ = α.
   elemental subroutine meissner_split(self, alpha, beta, c0, c1)
      class(meissner_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha, beta          !! the point
      real(wp), intent(out) :: c0                  !! β
      real(wp), intent(out) :: c1                  !! α
      c0 = beta
      c1 = alpha
   end subroutine meissner_split

   !> w = ±1, the unit square wave, at the times `tau`.
   pure subroutine meissner_shapes(self, alpha, tau, w)
      class(meissner_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha                !! α
      real(wp), intent(in) :: tau(:)               !! the times
      real(wp), intent(out) :: w(:)                !! w there
      w = square_wave(tau)
   end subroutine meissner_shapes

   !> w lies in [−1, 1].
   elemental subroutine meissner_shape_range(self, alpha, w_min, w_max)
      class(meissner_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha                !! α
      real(wp), intent(out) :: w_min, w_max        !! −1 and 1
      w_min = -1.0_wp
      w_max = 1.0_wp
   end subroutine meissner_shape_range

   !> ∫₀¹ √|w| dτ = 1.
   elemental real(wp) function meissner_shape_root_mean(self, alpha) result(mean)
      class(meissner_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha                !! α
      mean = 1.0_wp
   end function meissner_shape_root_mean

   !> Half a period from τ = 1/2, about which Q is even, with the jump at τ = 1 inside.
   pure function meissner_window(self, alpha) result(window)
      class(meissner_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha                !! α
      type(hill_window_t) :: window
      window = hill_window_t(start=0.5_wp, length=1.0_wp, half=.true., n_breaks=1)
      window%breaks(1) = 1.0_wp
   end function meissner_window

   !> The paper's two pieces, Q(0) on [0, 1) and Q(1) on [1, 2), are Q itself.
   pure logical function meissner_two_pieces_exact(self) result(exact)
      class(meissner_model_t), intent(in) :: self  !! the model
      exact = .true.
   end function meissner_two_pieces_exact

   !> Q = β + α w: of the form β + g(τ), with infinitely many harmonics (a jump).
   pure integer function meissner_harmonic_count(self) result(count)
      class(meissner_model_t), intent(in) :: self  !! the model
      count = harmonics_infinite
   end function meissner_harmonic_count

   !> g = α w = (4α/π) Σ_{m odd} sin(mπτ)/m: no mean, no cosines.
   pure subroutine meissner_harmonics(self, alpha, n, mean, c, s)
      class(meissner_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha                !! α
      integer, intent(in) :: n                     !! number of harmonics wanted
      real(wp), intent(out) :: mean                !! 0
      real(wp), intent(out) :: c(n), s(n)          !! 0 and 4α/(πm) for odd m
      integer :: m
      mean = 0.0_wp
      c = 0.0_wp
      do m = 1, n
         if (mod(m, 2) == 1) then
            s(m) = 4.0_wp*alpha/(pi*m)
         else
            s(m) = 0.0_wp
         end if
      end do
   end subroutine meissner_harmonics
end module hillstab_hill_model_meissner

!> The elastic pendulum's coefficient, paper eq. (25):
!>
!>     Q(τ) = (β − α cos πτ)/(1 − k cos πτ) = π² + (β − π²) w(τ),   w = 1/(1 − k cos πτ),  k = α/π²,
!>
!> the exact linearisation of the swing about the vertical bounce (the paper's eq. (20)), for
!> 0 ≤ α < π² (a < ρ). `elastic_model_t` is this model as a value (hillstab_hill_model):
!> its bindings answer, without the damping shift −ε²/4 of eq. (47), everything the methods
!> ask: Q, its exact segment means, the split q = c₀ + c₁ w that method auto relies on, w
!> from sin(πτ/2), ∫₀¹ √|w|, auto's mesh and step-count inputs, the Fourier terms of Hill's
!> method, the two-piece values of the paper's eq. (37)/(48)–(50) and the physical domain.
!>
!> 1 − k cos πτ is written (1 − k) + 2k sin²(πτ/2) with 1 − k = (π² − α)/π² from π²
!> in two doubles (`one_minus_alpha_over_pi2`): both keep their relative accuracy as
!> α → π² near τ = 0, where the dip of Q of depth ~ (β − π²)/(1 − k) sits.
!>
!>```fortran
!> type(elastic_model_t) :: elastic
!> print *, elastic%coefficient(9.8_wp, 2.47_wp, 0.0_wp)   ! the bottom of the dip
!>```
module hillstab_hill_model_elastic
   use hillstab_core_kinds, only: wp, pi, pi2, pi2_lo
   use hillstab_hill_model, only: hill_form_pencil
   use hillstab_hill_model_pendulum, only: pendulum_model_t
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   implicit none
   private
   public :: elastic_model_t
   public :: one_minus_alpha_over_pi2, in_physical_domain, elastic_alpha_valid, elastic_alpha_domain
   public :: elastic_coefficient, elastic_segment_mean, elastic_split, elastic_shape, elastic_shapes_from_half_sines
   public :: elastic_shape_root_mean, elastic_mesh_kappa, elastic_auto_difficulty, elastic_auto_amplitude
   public :: elastic_shape_range
   public :: elastic_hill_k, elastic_hill_coupling, elastic_fourier_decay, elastic_two_piece_values

   !> The α domain in words, for messages: a < ρ, the mass never reaches the pivot.
   character(len=*), parameter :: elastic_alpha_domain = "0 <= alpha < pi**2 = 9.8696044010893586 (amplitude a < rho)"

   !> The elastic pendulum's coefficient, eq. (25), as a model (hillstab_hill_model).
   type, extends(pendulum_model_t) :: elastic_model_t
   contains
      procedure :: name => elastic_name
      procedure :: formula => elastic_formula
      procedure :: summary => elastic_summary
      procedure :: alpha_domain => elastic_domain_text
      procedure :: alpha_valid => elastic_model_alpha_valid
      procedure :: is_pendulum => elastic_is_pendulum
      procedure :: coefficient => elastic_model_coefficient
      procedure :: segment_mean => elastic_model_segment_mean
      procedure :: split => elastic_model_split
      procedure :: shapes => elastic_model_shapes
      procedure :: shape_range => elastic_model_shape_range
      procedure :: shape_root_mean => elastic_model_shape_root_mean
      procedure :: shapes_from_half_sines => elastic_model_shapes_from_half_sines
      procedure :: mesh_kappa => elastic_model_mesh_kappa
      procedure :: auto_difficulty => elastic_model_auto_difficulty
      procedure :: auto_amplitude => elastic_model_auto_amplitude
      procedure :: two_piece_values => elastic_model_two_piece_values
      procedure :: hill_form => elastic_hill_form
      procedure :: hill_k => elastic_model_hill_k
      procedure :: hill_coupling => elastic_model_hill_coupling
      procedure :: hill_one_minus_k => elastic_model_hill_one_minus_k
      procedure :: fourier_decay => elastic_model_fourier_decay
   end type elastic_model_t

contains

   !> "elastic".
   pure function elastic_name(self) result(text)
      class(elastic_model_t), intent(in) :: self  !! the model
      character(len=:), allocatable :: text
      text = "elastic"
   end function elastic_name

   !> The coefficient as output headers state it.
   pure function elastic_formula(self) result(text)
      class(elastic_model_t), intent(in) :: self  !! the model
      character(len=:), allocatable :: text
      text = "Q(tau) = (beta - alpha cos(pi tau))/(1 - (alpha/pi^2) cos(pi tau)), eq. (25)"
   end function elastic_formula

   !> The coefficient in a few words (a template's comment).
   pure function elastic_summary(self) result(text)
      class(elastic_model_t), intent(in) :: self  !! the model
      character(len=:), allocatable :: text
      text = "Q = (beta - alpha cos pi tau)/(1 - (alpha/pi^2) cos pi tau), eq. (25)"
   end function elastic_summary

   !> The α domain in words: a < ρ.
   pure function elastic_domain_text(self) result(text)
      class(elastic_model_t), intent(in) :: self  !! the model
      character(len=:), allocatable :: text
      text = elastic_alpha_domain
   end function elastic_domain_text

   !> 0 ≤ α < π² (`elastic_alpha_valid`).
   elemental logical function elastic_model_alpha_valid(self, alpha) result(valid)
      class(elastic_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha               !! α
      valid = elastic_alpha_valid(alpha)
   end function elastic_model_alpha_valid

   !> The model is the elastic pendulum: physical domain, simulation, α = aπ²/ρ.
   elemental logical function elastic_is_pendulum(self)
      class(elastic_model_t), intent(in) :: self  !! the model
      elastic_is_pendulum = .true.
   end function elastic_is_pendulum

   !> Q(τ), eq. (25) (`elastic_coefficient`).
   elemental real(wp) function elastic_model_coefficient(self, alpha, beta, tau) result(q)
      class(elastic_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha, beta         !! the point
      real(wp), intent(in) :: tau                 !! dimensionless time
      q = elastic_coefficient(alpha, beta, tau)
   end function elastic_model_coefficient

   !> Exact mean of Q over [τ_a, τ_b] (`elastic_segment_mean`).
   pure real(wp) function elastic_model_segment_mean(self, alpha, beta, tau_a, tau_b) result(q)
      class(elastic_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha, beta         !! the point
      real(wp), intent(in) :: tau_a, tau_b        !! segment ends, tau_a < tau_b
      q = elastic_segment_mean(alpha, beta, tau_a, tau_b)
   end function elastic_model_segment_mean

   !> Q = π² + (β − π²) w (`elastic_split`).
   elemental subroutine elastic_model_split(self, alpha, beta, c0, c1)
      class(elastic_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha, beta         !! the point
      real(wp), intent(out) :: c0                 !! π²
      real(wp), intent(out) :: c1                 !! β − π²
      call elastic_split(beta, c0, c1)
   end subroutine elastic_model_split

   !> w(τ) = 1/(1 − (α/π²) cos πτ) at the times `tau`.
   pure subroutine elastic_model_shapes(self, alpha, tau, w)
      class(elastic_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha               !! α
      real(wp), intent(in) :: tau(:)              !! the times
      real(wp), intent(out) :: w(:)               !! w there
      w = elastic_shape(alpha, tau)
   end subroutine elastic_model_shapes

   !> The range of w, 1/(1 ± α/π²) (`elastic_shape_range`).
   elemental subroutine elastic_model_shape_range(self, alpha, w_min, w_max)
      class(elastic_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha               !! α
      real(wp), intent(out) :: w_min, w_max       !! the range of w
      call elastic_shape_range(alpha, w_min, w_max)
   end subroutine elastic_model_shape_range

   !> ∫₀¹ √w dτ, an elliptic integral (`elastic_shape_root_mean`).
   elemental real(wp) function elastic_model_shape_root_mean(self, alpha) result(mean)
      class(elastic_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha               !! α
      mean = elastic_shape_root_mean(alpha)
   end function elastic_model_shape_root_mean

   !> w from the half-angle sines, 1/((1 − k) + 2k s²) (`elastic_shapes_from_half_sines`).
   pure subroutine elastic_model_shapes_from_half_sines(self, alpha, n, s, w)
      class(elastic_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha               !! α
      integer, intent(in) :: n                    !! number of points
      real(wp), intent(in) :: s(n)                !! sin(πτ/2) at the points
      real(wp), intent(out) :: w(n)               !! w there
      call elastic_shapes_from_half_sines(alpha, n, s, w)
   end subroutine elastic_model_shapes_from_half_sines

   !> κ = 1 − (1 − α/π²)^power: steps packed into the dip (`elastic_mesh_kappa`).
   elemental real(wp) function elastic_model_mesh_kappa(self, alpha, power) result(kappa)
      class(elastic_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha               !! α
      real(wp), intent(in) :: power               !! method auto's mesh exponent
      kappa = elastic_mesh_kappa(alpha, power)
   end function elastic_model_mesh_kappa

   !> −ln(1 − α/π²) (`elastic_auto_difficulty`).
   elemental real(wp) function elastic_model_auto_difficulty(self, alpha) result(x)
      class(elastic_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha               !! α
      x = elastic_auto_difficulty(alpha)
   end function elastic_model_auto_difficulty

   !> |c₁| = |β − π²| (`elastic_auto_amplitude`).
   elemental real(wp) function elastic_model_auto_amplitude(self, c0, c1) result(amplitude)
      class(elastic_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: c0, c1              !! the split of q
      amplitude = elastic_auto_amplitude(c1)
   end function elastic_model_auto_amplitude

   !> The paper's two pieces with damping, eqs. (49)–(50) (`elastic_two_piece_values`).
   elemental subroutine elastic_model_two_piece_values(self, alpha, beta, epsilon, q_first, q_second)
      class(elastic_model_t), intent(in) :: self    !! the model
      real(wp), intent(in) :: alpha, beta, epsilon  !! the point and its damping
      real(wp), intent(out) :: q_first              !! B₂², the value on [0, 1)
      real(wp), intent(out) :: q_second             !! B₁², the value on [1, 2)
      call elastic_two_piece_values(alpha, beta, epsilon, q_first, q_second)
   end subroutine elastic_model_two_piece_values

   !> Hill's method in the pencil form.
   pure integer function elastic_hill_form(self) result(form)
      class(elastic_model_t), intent(in) :: self  !! the model
      form = hill_form_pencil
   end function elastic_hill_form

   !> k = α/π² (`elastic_hill_k`).
   elemental real(wp) function elastic_model_hill_k(self, alpha) result(k)
      class(elastic_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha               !! α
      k = elastic_hill_k(alpha)
   end function elastic_model_hill_k

   !> 1 − α/π², accurate as α → π² (`one_minus_alpha_over_pi2`).
   elemental real(wp) function elastic_model_hill_one_minus_k(self, alpha) result(one_minus_k)
      class(elastic_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha               !! α
      one_minus_k = one_minus_alpha_over_pi2(alpha)
   end function elastic_model_hill_one_minus_k

   !> α(1 − t) (`elastic_hill_coupling`).
   elemental real(wp) function elastic_model_hill_coupling(self, alpha, t) result(coupling)
      class(elastic_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha               !! α
      real(wp), intent(in) :: t                   !! the squared mode number
      coupling = elastic_hill_coupling(alpha, t)
   end function elastic_model_hill_coupling

   !> r = k/(1 + √(1 − k²)) (`elastic_fourier_decay`).
   elemental real(wp) function elastic_model_fourier_decay(self, alpha) result(r)
      class(elastic_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha               !! α
      r = elastic_fourier_decay(alpha)
   end function elastic_model_fourier_decay

   !> 1 − α/π² computed as (π² − α)/π² with π² split in two doubles: relative error of a
   !> few ulps for every 0 ≤ α < π² (1 − k from k = α/π² loses 1 − k's relative accuracy
   !> as α → π², about 2e-12 at α = 9.869).
   elemental real(wp) function one_minus_alpha_over_pi2(alpha) result(one_minus_k)
      real(wp), intent(in) :: alpha  !! α, 0 ≤ α < π²
      one_minus_k = ((pi2 - alpha) + pi2_lo)/pi2
   end function one_minus_alpha_over_pi2

   !> True when (α, β) describes a real spring pendulum: 0 ≤ α < π² (0 ≤ a < ρ),
   !> 0 ≤ β < π² (g ≥ 0, r0 > 0; β = 0 is the pendulum without gravity).
   elemental logical function in_physical_domain(alpha, beta)
      real(wp), intent(in) :: alpha, beta  !! the chart point (alpha, beta)
      in_physical_domain = alpha >= 0.0_wp .and. alpha < pi2 .and. beta >= 0.0_wp .and. beta < pi2
   end function in_physical_domain

   !> 0 ≤ α < π² and finite (a < ρ: the mass never reaches the pivot); no comparison
   !> with a NaN is made (it would raise the invalid flag).
   elemental logical function elastic_alpha_valid(alpha) result(valid)
      real(wp), intent(in) :: alpha  !! α
      valid = .false.
      if (.not. ieee_is_finite(alpha)) return
      valid = alpha >= 0.0_wp .and. alpha < pi2
   end function elastic_alpha_valid

   !> 1 − (α/π²) cos θ written as (1 − α/π²) + 2(α/π²) sin²(θ/2), accurate as α → π² near θ = 0.
   elemental real(wp) function one_minus_k_cos(alpha, theta)
      real(wp), intent(in) :: alpha, theta
      real(wp) :: s
      s = sin(0.5_wp*theta)
      one_minus_k_cos = one_minus_alpha_over_pi2(alpha) + 2.0_wp*(alpha/pi2)*s*s
   end function one_minus_k_cos

   !> Q(τ) = π² + (β − π²)/(1 − (α/π²) cos πτ), the second form of eq. (25). (Arguments by value:
   !> the integrators evaluate it at every stage, through `hill_coefficient`.)
   elemental real(wp) function elastic_coefficient(alpha, beta, tau) result(q)
      real(wp), intent(in), value :: alpha, beta  !! the chart point
      real(wp), intent(in), value :: tau          !! dimensionless time, πτ = ωt
      q = pi2 + (beta - pi2)/one_minus_k_cos(alpha, pi*tau)
   end function elastic_coefficient

   !> sin(πt) and cos(πt) with t first reduced to [−½, ½] about the nearest integer (exact:
   !> t − n and 1 − r are exact in floating point), so that an angle that is a multiple of
   !> π gives sine 0 exactly (sin(fl(π)·1) is 1.2e-16, not 0).
   elemental subroutine sin_cos_pi(t, s, c)
      real(wp), intent(in) :: t   !! the angle in units of π
      real(wp), intent(out) :: s  !! sin(πt)
      real(wp), intent(out) :: c  !! cos(πt)
      real(wp) :: r, n
      n = anint(t)
      r = t - n
      s = sin(pi*r)
      c = cos(pi*r)
      if (modulo(n, 2.0_wp) /= 0.0_wp) then
         s = -s
         c = -c
      end if
   end subroutine sin_cos_pi

   !> ∫ of 1/(1 − k cos πτ) over πτ from πτa to πτb, 0 ≤ τb − τa ≤ 2, 0 ≤ k < 1, from the
   !> antiderivative (2/√(1 − k²)) atan(√((1 + k)/(1 − k)) tan(θ/2)) with the difference of
   !> the two arctangents taken as one:
   !>
   !>   (2/√(1 − k²)) atan2(√(1 − k²) sin(π(τb − τa)/2),
   !>                       (1 − k) cos(πτa/2) cos(πτb/2) + (1 + k) sin(πτa/2) sin(πτb/2)),
   !>
   !> with 1 − k = (π² − α)/π² to full relative accuracy (`one_minus_alpha_over_pi2`) and the
   !> half-angle sines and cosines of `sin_cos_pi` (exact zeros at the dips τ = 0, 2). The
   !> difference of the antiderivative at the two ends, each of order π/√(1 − k), cancelled
   !> on the segments away from the dip as α → π², and 1 − k from k = α/π² had lost most of
   !> its digits: at α = π² − 8e-6, β = −19735 with 4 pieces the averages erred enough to put
   !> ln|S| off by 7.3e-8. (With sin(π) = 1.2e-16 in place of 0, the term (1 + k) sin sin
   !> alone moved the average over [1.5, 2] there by 1.2e-13.)
   pure real(wp) function inverse_cos_integral(alpha, tau_a, tau_b) result(f)
      real(wp), intent(in) :: alpha, tau_a, tau_b
      real(wp) :: k, one_minus_k, root, y, x, sa, ca, sb, cb, sd, cd
      k = alpha/pi2
      if (k == 0.0_wp) then
         f = pi*(tau_b - tau_a)
         return
      end if
      one_minus_k = one_minus_alpha_over_pi2(alpha)
      root = sqrt(one_minus_k*(1.0_wp + k))
      call sin_cos_pi(0.5_wp*tau_a, sa, ca)
      call sin_cos_pi(0.5_wp*tau_b, sb, cb)
      call sin_cos_pi(0.5_wp*(tau_b - tau_a), sd, cd)
      ! (sin of a half-sweep in [0, π] is ≥ 0; abs keeps a −0 of sin_cos_pi from turning π into −π)
      y = root*abs(sd)
      x = one_minus_k*ca*cb + (1.0_wp + k)*sa*sb
      f = 2.0_wp/root*atan2(y, x)
   end function inverse_cos_integral

   !> Exact mean of Q over [tau_a, tau_b] (tau_b − tau_a ≤ 2, one period at most): the
   !> integral of 1/(1 − k cos θ) is elementary, `inverse_cos_integral`.
   pure real(wp) function elastic_segment_mean(alpha, beta, tau_a, tau_b) result(q)
      real(wp), intent(in), value :: alpha, beta    !! the chart point
      real(wp), intent(in), value :: tau_a, tau_b   !! segment ends, tau_a < tau_b ≤ tau_a + 2
      q = pi2 + (beta - pi2)*inverse_cos_integral(alpha, tau_a, tau_b)/(pi*(tau_b - tau_a))
   end function elastic_segment_mean

   !> Q = c₀ + c₁ w(τ) with w independent of β: c₀ = π², c₁ = β − π².
   elemental subroutine elastic_split(beta, c0, c1)
      real(wp), intent(in) :: beta  !! β
      real(wp), intent(out) :: c0   !! constant part, π²
      real(wp), intent(out) :: c1   !! factor of w, β − π²
      c0 = pi2
      c1 = beta - pi2
   end subroutine elastic_split

   !> The shape function w(τ) = 1/(1 − (α/π²) cos πτ).
   elemental real(wp) function elastic_shape(alpha, tau) result(w)
      real(wp), intent(in) :: alpha  !! α
      real(wp), intent(in) :: tau    !! τ
      real(wp) :: s
      s = sin(0.5_wp*pi*tau)
      w = 1.0_wp/(one_minus_alpha_over_pi2(alpha) + 2.0_wp*(alpha/pi2)*s*s)
   end function elastic_shape

   !> The least and the largest value of w(τ) = 1/((1 − k) + 2k sin²(πτ/2)), k = α/π²: its
   !> values at τ = 0 and τ = 1, 1/(1 − k) and 1/(1 + k) (1 − k from
   !> `one_minus_alpha_over_pi2`, accurate as α → π²).
   elemental subroutine elastic_shape_range(alpha, w_min, w_max)
      real(wp), intent(in) :: alpha  !! α
      real(wp), intent(out) :: w_min, w_max  !! the range of w over the period
      real(wp) :: at_0, at_1
      at_0 = 1.0_wp/one_minus_alpha_over_pi2(alpha)
      at_1 = 1.0_wp/(1.0_wp + alpha/pi2)
      w_min = min(at_0, at_1)
      w_max = max(at_0, at_1)
   end subroutine elastic_shape_range

   !> w at the points whose half-angle sines s = sin(πτ/2) are given (method auto's mesh
   !> builds those by angle sums): w = 1/((1 − k) + 2k s²).
   pure subroutine elastic_shapes_from_half_sines(alpha, n, s, w)
      real(wp), intent(in) :: alpha  !! α
      integer, intent(in) :: n       !! number of points
      real(wp), intent(in) :: s(n)   !! sin(πτ/2) at the points
      real(wp), intent(out) :: w(n)  !! w(τ) there
      real(wp) :: k, one_minus_k
      integer :: i
      k = alpha/pi2
      one_minus_k = one_minus_alpha_over_pi2(alpha)
      do i = 1, n
         w(i) = 1.0_wp/(one_minus_k + 2.0_wp*k*s(i)*s(i))
      end do
   end subroutine elastic_shapes_from_half_sines

   !> ∫₀¹ √w dτ, the complete elliptic integral 1/(√(1 + k) AGM(1, √((1 − k)/(1 + k))))
   !> (1 at α = 0, growing like ln(1/(1 − k)) as α → π²).
   elemental real(wp) function elastic_shape_root_mean(alpha) result(mean)
      real(wp), intent(in) :: alpha  !! α
      real(wp) :: a, b, a_next, k
      integer :: i
      k = alpha/pi2
      a = 1.0_wp
      b = sqrt(one_minus_alpha_over_pi2(alpha)/(1.0_wp + k))
      do i = 1, 40
         if (a - b <= 4.0_wp*epsilon(1.0_wp)*a) exit
         a_next = 0.5_wp*(a + b)
         b = sqrt(a*b)
         a = a_next
      end do
      mean = 1.0_wp/(sqrt(1.0_wp + k)*a)
   end function elastic_shape_root_mean

   !> κ of method auto's Kepler-type mesh map, 1 − (1 − α/π²)^power: it packs the steps
   !> into the dip at τ = 0, whose width shrinks like √(1 − α/π²).
   elemental real(wp) function elastic_mesh_kappa(alpha, power) result(kappa)
      real(wp), intent(in) :: alpha  !! α
      real(wp), intent(in) :: power  !! method auto's mesh exponent
      kappa = 1.0_wp - (1.0_wp - alpha/pi2)**power
   end function elastic_mesh_kappa

   !> x = −ln(1 − α/π²), the variable of method auto's calibrated step table: how deep
   !> and narrow the dip is.
   elemental real(wp) function elastic_auto_difficulty(alpha) result(x)
      real(wp), intent(in) :: alpha  !! α
      x = -log(1.0_wp - alpha/pi2)
   end function elastic_auto_difficulty

   !> The amplitude of q that method auto's step count grows with (N ∝ amplitude^0.4): |c₁| = |β − π²|.
   elemental real(wp) function elastic_auto_amplitude(c1) result(amplitude)
      real(wp), intent(in) :: c1  !! the factor of w in the split of q (`elastic_split`)
      amplitude = abs(c1)
   end function elastic_auto_amplitude

   !> k of the weight 1 − k cos πτ that multiplies x'' in Hill's method: α/π².
   elemental real(wp) function elastic_hill_k(alpha) result(k)
      real(wp), intent(in) :: alpha  !! α
      k = alpha/pi2
   end function elastic_hill_k

   !> α − kπ²t, the weight of cos πτ on the Fourier mode t = (κ/π)² in Hill's method:
   !> α(1 − t) (exact at t = 1).
   elemental real(wp) function elastic_hill_coupling(alpha, t) result(coupling)
      real(wp), intent(in) :: alpha  !! α
      real(wp), intent(in) :: t      !! the squared mode number (κ/π)²
      coupling = alpha*(1.0_wp - t)
   end function elastic_hill_coupling

   !> r = k/(1 + √(1 − k²)): the eigenfunctions are analytic in the strip |Im πτ| <
   !> arccosh(1/k), so their Fourier coefficients decay like rⁿ; 0 at α = 0 (entire).
   elemental real(wp) function elastic_fourier_decay(alpha) result(r)
      real(wp), intent(in) :: alpha  !! α
      real(wp) :: k
      r = 0.0_wp
      if (.not. alpha > 0.0_wp) return
      k = alpha/pi2
      r = k/(1.0_wp + sqrt((1.0_wp - k)*(1.0_wp + k)))
   end function elastic_fourier_decay

   !> The paper's two pieces with damping, eqs. (49)–(50): Q(0) − ε²/4 on [0, 1) and
   !> Q(1) − ε²/4 on [1, 2) in the paper's closed form,
   !> B₂² = ((β − ε²/4) − α(1 − ε²/4π²))/(1 − α/π²), B₁² = ((β − ε²/4) + α(1 − ε²/4π²))/(1 + α/π²).
   elemental subroutine elastic_two_piece_values(alpha, beta, epsilon, q_first, q_second)
      real(wp), intent(in) :: alpha, beta, epsilon  !! the chart point and the damping ε = κπ/ω
      real(wp), intent(out) :: q_first   !! B₂², the value on [0, 1) (eq. (50))
      real(wp), intent(out) :: q_second  !! B₁², the value on [1, 2) (eq. (49))
      real(wp) :: shifted, amp
      shifted = beta - 0.25_wp*epsilon**2
      amp = alpha*(1.0_wp - 0.25_wp*epsilon**2/pi2)
      q_second = (shifted + amp)/(1.0_wp + alpha/pi2)
      q_first = (shifted - amp)/one_minus_alpha_over_pi2(alpha)
   end subroutine elastic_two_piece_values
end module hillstab_hill_model_elastic

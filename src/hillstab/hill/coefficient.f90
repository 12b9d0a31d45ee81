!> The periodic coefficient of the Hill equation x'' + Q(τ) x = 0 (period 2 in τ).
!>
!> Models:
!> - `model_elastic`: Q(τ) = (β − α cos πτ)/(1 − (α/π²) cos πτ), paper eq. (25);
!> - `model_mathieu`: q(τ) = β − α cos πτ, the paper's Mathieu form (A1) with α playing ν.
!> Both carry the damping shift −ε²/4 of eq. (47), so that they describe χ = e^{ετ/2} x.
!>
!>```fortran
!> type(hill_model_t) :: model
!> model = hill_model_t(model_elastic, alpha=4.0_wp, beta=6.0_wp, epsilon=0.0_wp)
!> print *, hill_coefficient(model, 0.5_wp)
!>```
module hillstab_hill_coefficient
   use hillstab_core_kinds, only: wp, pi, pi2, pi2_lo
   use hillstab_core_error, only: error_t, set_error, err_invalid_parameter
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   implicit none
   private
   public :: hill_model_t, model_elastic, model_mathieu, model_name
   public :: hill_coefficient, check_model, segment_average, segment_coefficients
   public :: sampling_endpoint, sampling_midpoint, sampling_average, sampling_name
   public :: damping_shift, hill_period, in_physical_domain, one_minus_alpha_over_pi2
   public :: phase_bound, shape_root_mean, coefficient_phase

   !> Q(τ) of eq. (25), the exact linearisation about the vertical bounce.
   integer, parameter :: model_elastic = 1
   !> q(τ) = β − α cos πτ, the small-amplitude (Mathieu) limit, eq. (A1).
   integer, parameter :: model_mathieu = 2

   !> Piece value = Q at the start of the piece (N = 2 is the paper's eq. (28)).
   integer, parameter :: sampling_endpoint = 1
   !> Piece value = Q at the midpoint of the piece.
   integer, parameter :: sampling_midpoint = 2
   !> Piece value = exact average of Q over the piece (closed form).
   integer, parameter :: sampling_average = 3

   !> Period of Q in τ: one radial oscillation.
   real(wp), parameter :: hill_period = 2.0_wp

   !> Parameters of one Hill equation.
   type :: hill_model_t
      integer :: kind = model_elastic  !! model_elastic or model_mathieu
      real(wp) :: alpha = 0.0_wp       !! α = aπ²/ρ (elastic) or ν (mathieu)
      real(wp) :: beta = 0.0_wp        !! β = gπ²/(ρω²)
      real(wp) :: epsilon = 0.0_wp     !! damping ε = κπ/ω of eq. (46)
   end type hill_model_t

contains

   !> Name of a model constant.
   pure function model_name(kind) result(name)
      integer, intent(in) :: kind  !! model_elastic or model_mathieu
      character(len=:), allocatable :: name
      select case (kind)
      case (model_elastic); name = "elastic"
      case (model_mathieu); name = "mathieu"
      case default; name = "unknown"
      end select
   end function model_name

   !> Name of a sampling constant.
   pure function sampling_name(sampling) result(name)
      integer, intent(in) :: sampling  !! sampling_endpoint, sampling_midpoint or sampling_average
      character(len=:), allocatable :: name
      select case (sampling)
      case (sampling_endpoint); name = "endpoint"
      case (sampling_midpoint); name = "midpoint"
      case (sampling_average); name = "average"
      case default; name = "unknown"
      end select
   end function sampling_name

   !> Validate the parameters: finite values, ε ≥ 0, and for the elastic model
   !> 0 ≤ α < π² (a < ρ: the mass never reaches the pivot).
   subroutine check_model(model, error)
      type(hill_model_t), intent(in) :: model  !! the parameters to check
      !> err_invalid_parameter naming the value and the limit; unallocated when valid
      type(error_t), allocatable, intent(out) :: error
      character(len=64) :: buf
      if (.not. (ieee_is_finite(model%alpha) .and. ieee_is_finite(model%beta) &
                 .and. ieee_is_finite(model%epsilon))) then
         call set_error(error, err_invalid_parameter, "alpha, beta and epsilon must be finite")
         return
      end if
      if (model%epsilon < 0.0_wp) then
         write (buf, '(es12.5)') model%epsilon
         call set_error(error, err_invalid_parameter, "epsilon must be >= 0, got "//trim(adjustl(buf)))
         return
      end if
      ! beyond these magnitudes Q, the grid spacings and the methods' scalings overflow
      if (max(abs(model%alpha), abs(model%beta)) > 1.0e15_wp .or. model%epsilon > 100.0_wp) then
         call set_error(error, err_invalid_parameter, "|alpha|, |beta| must be <= 1e15 and epsilon <= 100")
         return
      end if
      select case (model%kind)
      case (model_elastic)
         if (model%alpha < 0.0_wp .or. .not. (model%alpha < pi2)) then
            write (buf, '(es23.16)') model%alpha
            call set_error(error, err_invalid_parameter, &
               "elastic model needs 0 <= alpha < pi**2 = 9.8696044010893586, got alpha = "//trim(adjustl(buf)))
            return
         end if
      case (model_mathieu)
      case default
         call set_error(error, err_invalid_parameter, "unknown model kind")
      end select
   end subroutine check_model

   !> True when (α, β) describes a real spring pendulum: 0 ≤ α < π² (0 ≤ a < ρ),
   !> 0 ≤ β < π² (g ≥ 0, r0 > 0; β = 0 is the pendulum without gravity).
   elemental logical function in_physical_domain(alpha, beta)
      real(wp), intent(in) :: alpha, beta  !! the chart point (alpha, beta)
      in_physical_domain = alpha >= 0.0_wp .and. alpha < pi2 .and. beta >= 0.0_wp .and. beta < pi2
   end function in_physical_domain

   !> Damping shift −ε²/4 of eq. (47).
   elemental real(wp) function damping_shift(epsilon)
      real(wp), intent(in) :: epsilon  !! damping epsilon of eq. (46)
      damping_shift = -0.25_wp*epsilon*epsilon
   end function damping_shift

   !> 1 − α/π² computed as (π² − α)/π² with π² split in two doubles: relative error of a
   !> few ulps for every 0 ≤ α < π² (1 − k from k = α/π² loses 1 − k's relative accuracy
   !> as α → π², about 2e-12 at α = 9.869).
   elemental real(wp) function one_minus_alpha_over_pi2(alpha) result(one_minus_k)
      real(wp), intent(in) :: alpha  !! α, 0 ≤ α < π²
      one_minus_k = ((pi2 - alpha) + pi2_lo)/pi2
   end function one_minus_alpha_over_pi2

   !> 1 − (α/π²) cos θ written as (1 − α/π²) + 2(α/π²) sin²(θ/2), accurate as α → π² near θ = 0.
   elemental real(wp) function one_minus_k_cos(alpha, theta)
      real(wp), intent(in) :: alpha, theta
      real(wp) :: s
      s = sin(0.5_wp*theta)
      one_minus_k_cos = one_minus_alpha_over_pi2(alpha) + 2.0_wp*(alpha/pi2)*s*s
   end function one_minus_k_cos

   !> An upper bound of the phase (where q > 0) or growth exponent (where q < 0) that the
   !> solutions accumulate over one period, Φ = ∫₀² √|q(τ)| dτ, from q = c₀ + c₁ w(τ)
   !> and √|c₀ + c₁ w| ≤ √|c₀| + √|c₁| √|w|: Φ ≤ 2 (√|c₀| + √|c₁| `shape_root_mean`).
   !> It sets the part of the round-off level of S that no integrator can remove: Q is
   !> computed from rounded constants (1 − α/π², α/π², β − π², π²), a systematic relative
   !> error of a few ε that moves the phase by about ε Φ (hillstab_integrate_refine `roundoff_level`).
   elemental real(wp) function phase_bound(model) result(phase)
      type(hill_model_t), intent(in) :: model  !! model kind, alpha, beta, epsilon
      real(wp) :: c0, c1
      if (model%kind == model_mathieu) then
         c0 = model%beta + damping_shift(model%epsilon)
         c1 = model%alpha
      else
         c0 = pi2 + damping_shift(model%epsilon)
         c1 = model%beta - pi2
      end if
      phase = coefficient_phase(c0, c1, shape_root_mean(model%kind, model%alpha))
   end function phase_bound

   !> `phase_bound` from q = c₀ + c₁ w and ∫₀¹ √|w| dτ: 2 (√|c₀| + √|c₁| shape_root).
   elemental real(wp) function coefficient_phase(c0, c1, shape_root) result(phase)
      real(wp), intent(in) :: c0          !! constant part of q
      real(wp), intent(in) :: c1          !! factor of the shape function w
      real(wp), intent(in) :: shape_root  !! ∫₀¹ √|w| dτ (`shape_root_mean`)
      phase = 2.0_wp*(sqrt(abs(c0)) + sqrt(abs(c1))*shape_root)
   end function coefficient_phase

   !> ∫₀¹ √|w(τ)| dτ of the shape function of q = c₀ + c₁ w: elastic w = 1/(1 − k cos πτ),
   !> k = α/π², whose integral is the complete elliptic integral
   !> 1/(√(1 + k) AGM(1, √((1 − k)/(1 + k)))) (1 at α = 0, growing like ln(1/(1 − k)) as
   !> α → π²); Mathieu w = cos πτ, bounded by 1.
   elemental real(wp) function shape_root_mean(kind, alpha) result(mean)
      integer, intent(in) :: kind    !! model_elastic or model_mathieu
      real(wp), intent(in) :: alpha  !! α (ν for the Mathieu model)
      real(wp) :: a, b, a_next, k
      integer :: i
      mean = 1.0_wp
      if (kind == model_mathieu) return
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
   end function shape_root_mean

   !> The coefficient q(τ) of the (damping-shifted) Hill equation, eq. (25)/(A1) and (47).
   elemental real(wp) function hill_coefficient(model, tau) result(q)
      type(hill_model_t), intent(in) :: model  !! model kind, alpha, beta, epsilon
      real(wp), intent(in) :: tau  !! dimensionless time, πτ = ωt
      select case (model%kind)
      case (model_mathieu)
         q = model%beta - model%alpha*cos(pi*tau)
      case default
         ! π² + (β − π²)/(1 − (α/π²) cos πτ), the second form of eq. (25)
         q = pi2 + (model%beta - pi2)/one_minus_k_cos(model%alpha, pi*tau)
      end select
      q = q + damping_shift(model%epsilon)
   end function hill_coefficient

   !> Antiderivative F(θ) of 1/(1 − k cos θ), 0 ≤ k < 1, continuous in θ and F(0) = 0.
   pure real(wp) function inverse_cos_primitive(k, theta) result(f)
      real(wp), intent(in) :: k, theta
      real(wp) :: turns, reduced, c, s, root
      if (k == 0.0_wp) then
         f = theta
         return
      end if
      turns = floor(theta/(2.0_wp*pi))
      reduced = theta - 2.0_wp*pi*turns
      root = sqrt((1.0_wp - k)*(1.0_wp + k))
      s = sin(0.5_wp*reduced)
      c = cos(0.5_wp*reduced)
      ! 2/√(1−k²) · atan(√((1+k)/(1−k)) tan(θ/2)), unwrapped through atan2 on [0, 2π)
      f = 2.0_wp/root*(atan2(sqrt(1.0_wp + k)*s, sqrt(1.0_wp - k)*c) + pi*turns)
   end function inverse_cos_primitive

   !> Exact mean of q over [tau_a, tau_b] (closed form; BRIEF §3).
   pure real(wp) function segment_average(model, tau_a, tau_b) result(q)
      type(hill_model_t), intent(in) :: model  !! model kind, alpha, beta, epsilon
      real(wp), intent(in) :: tau_a, tau_b  !! segment ends, tau_a < tau_b
      real(wp) :: k, width
      width = tau_b - tau_a
      select case (model%kind)
      case (model_mathieu)
         q = model%beta - model%alpha*(sin(pi*tau_b) - sin(pi*tau_a))/(pi*width)
      case default
         k = model%alpha/pi2
         q = pi2 + (model%beta - pi2)*(inverse_cos_primitive(k, pi*tau_b) &
                                       - inverse_cos_primitive(k, pi*tau_a))/(pi*width)
      end select
      q = q + damping_shift(model%epsilon)
   end function segment_average

   !> Values of the piecewise-constant approximation of q with `n` equal pieces
   !> over one period [0, 2]: at each piece's start, midpoint, or its exact mean.
   pure subroutine segment_coefficients(model, n, sampling, q)
      type(hill_model_t), intent(in) :: model  !! model kind, alpha, beta, epsilon
      integer, intent(in) :: n          !! number of pieces, n ≥ 1
      integer, intent(in) :: sampling   !! sampling_endpoint, sampling_midpoint or sampling_average
      real(wp), intent(out) :: q(n)     !! piece values, in order of τ
      real(wp) :: h
      integer :: i
      h = hill_period/n
      do i = 1, n
         select case (sampling)
         case (sampling_midpoint)
            q(i) = hill_coefficient(model, (i - 0.5_wp)*h)
         case (sampling_average)
            q(i) = segment_average(model, (i - 1)*h, i*h)
         case default
            q(i) = hill_coefficient(model, (i - 1)*h)
         end select
      end do
   end subroutine segment_coefficients
end module hillstab_hill_coefficient

!> The swing about a modulated bounce, the paper's proposed refinement of the vertical
!> oscillation with ω' = ω/2: r(t) = ρ − a cos ωt cos(ωt/2), prescribed. Linearising the
!> swing about it exactly as about the plain bounce (x = rθ, the paper's eq. (20)) gives
!>
!>     Q(τ) = (β + k m''(τ))/(1 − k m(τ)),   m = cos πτ cos(πτ/2),   k = α/π²,
!>
!> with α = aπ²/ρ and β = gπ²/(ρω²) as for the elastic model and m'' = d²m/dτ² =
!> −(π²/8)(cos(πτ/2) + 9 cos(3πτ/2)). The period is 4 in τ (two radial oscillations), Q is
!> even about τ = 0 and about τ = 2, and 0 ≤ α < π² keeps r > 0 (m reaches 1 at τ = 0).
!> Unlike the plain bounce, where m'' = −π² m turns Q into π² + (β − π²) w, here k m'' is no
!> multiple of m: Q = β w + v with w = 1/(1 − k m) and the offset v = k m'' w, both
!> independent of β (`has_offset`, `offsets`: method auto's meshes carry v beside w). Q is no
!> trigonometric polynomial (1/(1 − k m) has
!> infinitely many harmonics), so the Fourier model cannot represent it exactly: this model
!> evaluates it in closed form. Transition curves come from the roots of S along β.
!>
!> With c = cos(πτ/2), m = 2c³ − c and 1 − k m = (1 − k) + 2k sin²(πτ/4)(1 + 2c + 2c²), both
!> terms of which keep their relative accuracy as α → π² near τ = 0 (1 − k from π² in two
!> doubles, as for the elastic model); k m'' = −(α/8) c (36c² − 26).
!>
!>```fortran
!> type(modulated_model_t) :: modulated
!> print *, modulated%coefficient(5.0_wp, 2.0_wp, 0.0_wp)   ! (β − 1.25 α)/(1 − k)
!>```
module hillstab_hill_model_modulated
   use hillstab_core_kinds, only: wp, pi, pi2
   use hillstab_hill_model, only: hill_model_t
   use hillstab_hill_model_elastic, only: one_minus_alpha_over_pi2, elastic_alpha_valid, elastic_alpha_domain, &
      elastic_auto_difficulty
   implicit none
   private
   public :: modulated_model_t, modulated_parts

   !> Gauss–Legendre 5-point nodes on [−1, 1] (the positive ones) and weights.
   real(wp), parameter :: gl_inner = sqrt(5.0_wp - 2.0_wp*sqrt(10.0_wp/7.0_wp))/3.0_wp
   real(wp), parameter :: gl_outer = sqrt(5.0_wp + 2.0_wp*sqrt(10.0_wp/7.0_wp))/3.0_wp
   real(wp), parameter :: gl_weight_centre = 128.0_wp/225.0_wp
   real(wp), parameter :: gl_weight_inner = (322.0_wp + 13.0_wp*sqrt(70.0_wp))/900.0_wp
   real(wp), parameter :: gl_weight_outer = (322.0_wp - 13.0_wp*sqrt(70.0_wp))/900.0_wp
   !> Deepest bisection of the adaptive quadrature of `modulated_segment_mean`.
   integer, parameter :: max_depth = 48

   !> The swing about the modulated bounce r = ρ − a cos ωt cos(ωt/2) as a model
   !> (hillstab_hill_model).
   type, extends(hill_model_t) :: modulated_model_t
   contains
      procedure :: name => modulated_name
      procedure :: formula => modulated_formula
      procedure :: summary => modulated_summary
      procedure :: alpha_domain => modulated_domain_text
      procedure :: alpha_valid => modulated_alpha_valid
      procedure :: coefficient => modulated_coefficient
      procedure :: segment_mean => modulated_segment_mean
      procedure :: split => modulated_split
      procedure :: shapes => modulated_shapes
      procedure :: shape_range => modulated_shape_range
      procedure :: has_offset => modulated_has_offset
      procedure :: offset_range => modulated_offset_range
      procedure :: offsets => modulated_offsets
      procedure :: auto_difficulty => modulated_auto_difficulty
      procedure :: auto_amplitude => modulated_auto_amplitude
      procedure :: auto_safety => modulated_auto_safety
      procedure :: period => modulated_period
   end type modulated_model_t

contains

   !> "modulated".
   pure function modulated_name(self) result(text)
      class(modulated_model_t), intent(in) :: self  !! the model
      character(len=:), allocatable :: text
      text = "modulated"
   end function modulated_name

   !> The coefficient as output headers state it.
   pure function modulated_formula(self) result(text)
      class(modulated_model_t), intent(in) :: self  !! the model
      character(len=:), allocatable :: text
      text = "Q(tau) = (beta + k m''(tau))/(1 - k m(tau)), m = cos(pi tau) cos(pi tau/2), k = alpha/pi^2: "// &
             "the bounce r = rho - a cos(wt) cos(wt/2)"
   end function modulated_formula

   !> The coefficient in a few words (a template's comment).
   pure function modulated_summary(self) result(text)
      class(modulated_model_t), intent(in) :: self  !! the model
      character(len=:), allocatable :: text
      text = "Q = (beta + k m'')/(1 - k m), m = cos(pi tau) cos(pi tau/2): a modulated bounce"
   end function modulated_summary

   !> The α domain in words: a < ρ, as for the elastic model.
   pure function modulated_domain_text(self) result(text)
      class(modulated_model_t), intent(in) :: self  !! the model
      character(len=:), allocatable :: text
      text = elastic_alpha_domain
   end function modulated_domain_text

   !> 0 ≤ α < π²: r = ρ(1 − k m) stays positive.
   elemental logical function modulated_alpha_valid(self, alpha) result(valid)
      class(modulated_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha                 !! α
      valid = elastic_alpha_valid(alpha)
   end function modulated_alpha_valid

   !> w = 1/(1 − k m(τ)) and v = k m''(τ) w at τ, so that Q = β w + v.
   elemental subroutine modulated_parts(alpha, tau, w, v)
      real(wp), intent(in) :: alpha  !! α, 0 ≤ α < π²
      real(wp), intent(in) :: tau    !! dimensionless time
      real(wp), intent(out) :: w     !! 1/(1 − k m)
      real(wp), intent(out) :: v     !! k m''/(1 − k m)
      real(wp) :: t, c, s4, k
      t = modulo(tau, 4.0_wp)
      c = cos(0.5_wp*pi*t)
      s4 = sin(0.25_wp*pi*t)
      k = alpha/pi2
      w = 1.0_wp/(one_minus_alpha_over_pi2(alpha) + 2.0_wp*k*s4*s4*(1.0_wp + 2.0_wp*c + 2.0_wp*c*c))
      v = -0.125_wp*alpha*c*(36.0_wp*c*c - 26.0_wp)*w
   end subroutine modulated_parts

   !> Q(τ) = β w + v.
   elemental real(wp) function modulated_coefficient(self, alpha, beta, tau) result(q)
      class(modulated_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha, beta           !! the point
      real(wp), intent(in) :: tau                   !! dimensionless time
      real(wp) :: w, v
      call modulated_parts(alpha, tau, w, v)
      q = beta*w + v
   end function modulated_coefficient

   !> Mean of Q over [τ_a, τ_b]: β ∫w + ∫v over the length, the integrals by adaptive
   !> Gauss–Legendre quadrature (5 points, a panel accepted when its two halves agree with
   !> it to a few roundings of the integrands' scale), exact to rounding for this analytic Q.
   pure real(wp) function modulated_segment_mean(self, alpha, beta, tau_a, tau_b) result(q)
      class(modulated_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha, beta           !! the point
      real(wp), intent(in) :: tau_a, tau_b          !! segment ends, tau_a < tau_b
      real(wp) :: integral_w, integral_v
      call shape_integrals(alpha, tau_a, tau_b, integral_w, integral_v)
      q = (beta*integral_w + integral_v)/(tau_b - tau_a)
   end function modulated_segment_mean

   !> ∫w and ∫v over [a, b] by adaptive Gauss–Legendre quadrature, with a stack of panels.
   pure subroutine shape_integrals(alpha, a, b, integral_w, integral_v)
      real(wp), intent(in) :: alpha, a, b
      real(wp), intent(out) :: integral_w, integral_v
      real(wp) :: lefts(max_depth + 1), rights(max_depth + 1)
      real(wp) :: left, right, middle, whole_w, whole_v, half_w(2), half_v(2), scale_w, scale_v, w_min, w_max
      real(wp) :: v_min, v_max
      integer :: top, depth(max_depth + 1), level
      ! accept a panel when its halves change its integrals by less than a few roundings of
      ! the integrands' largest values over the panel's length
      call modulated_range_of_w(alpha, w_min, w_max)
      call modulated_range_of_v(alpha, v_min, v_max)
      scale_w = 4.0_wp*epsilon(1.0_wp)*w_max
      scale_v = 4.0_wp*epsilon(1.0_wp)*max(abs(v_min), abs(v_max))
      integral_w = 0.0_wp
      integral_v = 0.0_wp
      top = 1
      lefts(1) = a
      rights(1) = b
      depth(1) = 0
      do while (top > 0)
         left = lefts(top)
         right = rights(top)
         level = depth(top)
         top = top - 1
         middle = 0.5_wp*(left + right)
         call panel(alpha, left, right, whole_w, whole_v)
         call panel(alpha, left, middle, half_w(1), half_v(1))
         call panel(alpha, middle, right, half_w(2), half_v(2))
         if (level >= max_depth .or. (abs(sum(half_w) - whole_w) <= scale_w*(right - left) .and. &
                                      abs(sum(half_v) - whole_v) <= scale_v*(right - left))) then
            integral_w = integral_w + sum(half_w)
            integral_v = integral_v + sum(half_v)
         else
            lefts(top + 1) = middle; rights(top + 1) = right; depth(top + 1) = level + 1
            lefts(top + 2) = left; rights(top + 2) = middle; depth(top + 2) = level + 1
            top = top + 2
         end if
      end do
   end subroutine shape_integrals

   !> ∫w and ∫v over one panel [a, b] by 5-point Gauss–Legendre.
   pure subroutine panel(alpha, a, b, integral_w, integral_v)
      real(wp), intent(in) :: alpha, a, b
      real(wp), intent(out) :: integral_w, integral_v
      real(wp) :: centre, half, taus(5), weights(5), w(5), v(5)
      centre = 0.5_wp*(a + b)
      half = 0.5_wp*(b - a)
      taus = centre + half*[-gl_outer, -gl_inner, 0.0_wp, gl_inner, gl_outer]
      weights = [gl_weight_outer, gl_weight_inner, gl_weight_centre, gl_weight_inner, gl_weight_outer]
      call modulated_parts(alpha, taus, w, v)
      integral_w = half*sum(weights*w)
      integral_v = half*sum(weights*v)
   end subroutine panel

   !> Q = c₀ + c₁ w + v with c₀ = 0, c₁ = β.
   elemental subroutine modulated_split(self, alpha, beta, c0, c1)
      class(modulated_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha, beta           !! the point
      real(wp), intent(out) :: c0                   !! 0
      real(wp), intent(out) :: c1                   !! β
      c0 = 0.0_wp
      c1 = beta
   end subroutine modulated_split

   !> w = 1/(1 − k m) at the times `tau`.
   pure subroutine modulated_shapes(self, alpha, tau, w)
      class(modulated_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha                 !! α
      real(wp), intent(in) :: tau(:)                !! the times
      real(wp), intent(out) :: w(:)                 !! w there
      real(wp) :: v(size(tau))
      call modulated_parts(alpha, tau, w, v)
   end subroutine modulated_shapes

   !> w over the period: m runs over [−1, 1], so w over [1/(1 + k), 1/(1 − k)].
   elemental subroutine modulated_shape_range(self, alpha, w_min, w_max)
      class(modulated_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha                 !! α
      real(wp), intent(out) :: w_min, w_max         !! the range of w
      call modulated_range_of_w(alpha, w_min, w_max)
   end subroutine modulated_shape_range

   !> The range of w (`modulated_shape_range`), rounded outwards.
   elemental subroutine modulated_range_of_w(alpha, w_min, w_max)
      real(wp), intent(in) :: alpha
      real(wp), intent(out) :: w_min, w_max
      w_min = (1.0_wp - 4.0_wp*epsilon(1.0_wp))/(1.0_wp + alpha/pi2)
      w_max = (1.0_wp + 4.0_wp*epsilon(1.0_wp))/one_minus_alpha_over_pi2(alpha)
   end subroutine modulated_range_of_w

   !> Q = β w + v: an offset v = k m'' w that β does not scale.
   elemental logical function modulated_has_offset(self)
      class(modulated_model_t), intent(in) :: self  !! the model
      modulated_has_offset = .true.
   end function modulated_has_offset

   !> v = k m'' w at the times `tau`.
   pure subroutine modulated_offsets(self, alpha, tau, v)
      class(modulated_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha                 !! α
      real(wp), intent(in) :: tau(:)                !! the times
      real(wp), intent(out) :: v(:)                 !! v there
      real(wp) :: w(size(tau))
      call modulated_parts(alpha, tau, w, v)
   end subroutine modulated_offsets

   !> Method auto's calibration variable: the elastic model's, −ln(1 − α/π²), for the dip of
   !> Q at τ = 0 of the same width (1 − k m has the same minimum 1 − k there).
   elemental real(wp) function modulated_auto_difficulty(self, alpha) result(x)
      class(modulated_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha                 !! α
      x = 2.0_wp*elastic_auto_difficulty(alpha) + 1.0_wp
   end function modulated_auto_difficulty

   !> The amplitude method auto's step count grows with: |β − π²| as for the elastic model
   !> (whose Q = π² + (β − π²) w has the same dip), plus 0.1 |c₀| (the damping shift).
   elemental real(wp) function modulated_auto_amplitude(self, c0, c1) result(amplitude)
      class(modulated_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: c0, c1               !! the split of q: c₁ = β
      amplitude = abs(c1 - pi2) + 0.1_wp*abs(c0)
   end function modulated_auto_amplitude

   !> Method auto's Richardson estimate counted fourfold: its meshes are uniform in τ (not
   !> packed into the dip as the elastic model's), and at tolerance 1e-6 their pairs were
   !> short of the asymptotic range by up to 1.5× the estimate.
   elemental real(wp) function modulated_auto_safety(self) result(factor)
      class(modulated_model_t), intent(in) :: self  !! the model
      factor = 4.0_wp
   end function modulated_auto_safety

   !> The range of v over the period (`modulated_range_of_v`).
   elemental subroutine modulated_offset_range(self, alpha, v_min, v_max)
      class(modulated_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha                 !! α
      real(wp), intent(out) :: v_min, v_max         !! bounds of v
      call modulated_range_of_v(alpha, v_min, v_max)
   end subroutine modulated_offset_range

   !> The range of v over the period: as a function of c = cos(πτ/2) ∈ [−1, 1],
   !> v = −(α/8) c (36c² − 26)/(1 + kc − 2kc³), whose derivative vanishes where
   !> −32k c³ + 108 c² − 26 = 0: at one root in (−1, 0) and one in (0, 1) (the cubic is
   !> positive at ±1 and −26 at 0 for 0 ≤ k < 1). v at c = ±1 and at those two roots
   !> (bisection), widened by a few roundings.
   elemental subroutine modulated_range_of_v(alpha, v_min, v_max)
      real(wp), intent(in) :: alpha
      real(wp), intent(out) :: v_min, v_max
      real(wp) :: values(4), slack
      values(1) = offset_at(1.0_wp)
      values(2) = offset_at(-1.0_wp)
      values(3) = offset_at(critical_point(-1.0_wp, 0.0_wp))
      values(4) = offset_at(critical_point(0.0_wp, 1.0_wp))
      slack = 64.0_wp*epsilon(1.0_wp)*maxval(abs(values))
      v_min = minval(values) - slack
      v_max = maxval(values) + slack
   contains
      !> v at c (1 − k m from 1 − k, accurate near c = 1).
      pure real(wp) function offset_at(c) result(v)
         real(wp), intent(in) :: c
         real(wp) :: k
         k = alpha/pi2
         v = -0.125_wp*alpha*c*(36.0_wp*c*c - 26.0_wp)/ &
             (one_minus_alpha_over_pi2(alpha) + k*(1.0_wp - c)*(1.0_wp + 2.0_wp*c + 2.0_wp*c*c))
      end function offset_at

      !> The root of −32k c³ + 108c² − 26 in (low, high), where it changes sign.
      pure real(wp) function critical_point(low, high) result(c)
         real(wp), intent(in) :: low, high
         real(wp) :: a, b
         integer :: i
         a = low
         b = high
         do i = 1, 60
            c = 0.5_wp*(a + b)
            if (sign(1.0_wp, cubic(c)) == sign(1.0_wp, cubic(a))) then
               a = c
            else
               b = c
            end if
         end do
         c = 0.5_wp*(a + b)
      end function critical_point

      pure real(wp) function cubic(c)
         real(wp), intent(in) :: c
         cubic = (-32.0_wp*(alpha/pi2)*c + 108.0_wp)*c*c - 26.0_wp
      end function cubic
   end subroutine modulated_range_of_v

   !> The period of Q in τ: 4, two oscillations of cos πτ and one of cos(πτ/2).
   pure real(wp) function modulated_period(self) result(period)
      class(modulated_model_t), intent(in) :: self  !! the model
      period = 4.0_wp
   end function modulated_period
end module hillstab_hill_model_modulated

!> Global error control for integrators with a local tolerance (`rk`, `gsl`): a local
!> tolerance does not bound the error of S, so S is computed on a ladder of local
!> tolerances ℓ, ℓ/10, ℓ/100, … and the difference of two successive values is the
!> error estimate of the coarser one (an upper estimate of the finer one's error, about
!> ten times too large when the error is proportional to the local tolerance).
!>
!> The ladder stops when that difference meets the tolerance (status ok, the finer value
!> is returned), or as round-off limited when the local tolerance has reached the
!> integrator's floor, or when a tenfold tighter local tolerance no longer halves the
!> difference (the values differ by rounding noise, not by truncation): then the finest
!> value is returned with the last difference as its error estimate.
!>
!>```fortran
!> type(refinement_t) :: ladder
!> call start_refinement(ladder, tolerance)
!> do
!>    ! ... compute tr at the next local tolerance ...
!>    call refine(ladder, tr, at_floor)
!>    if (ladder%verdict /= refine_more) exit
!> end do
!>```
module hillstab_integrate_refine
   use hillstab_core_kinds, only: wp, log_huge
   use hillstab_hill_transfer, only: trace_t, scaled_matrix_t
   implicit none
   private
   public :: refinement_t, start_refinement, refine, trace_distance, roundoff_level, propagator_condition, first_step_factor, &
      next_local_tolerance
   public :: refine_more, refine_met, refine_roundoff
   public :: sensitivity_t, accumulate_sensitivity, coefficient_level

   !> Safety factor of `roundoff_level` (calibrated with method auto on β = 0,
   !> α = 9.8 … 9.86, where S = 2 exactly).
   real(wp), parameter, public :: roundoff_safety = 0.1_wp
   !> The factor of the √N term of `roundoff_level` for the Runge–Kutta integrators (rk,
   !> gsl), whose steps round the state itself: one rounding of ε per step (its `step_rounding`).
   real(wp), parameter, public :: rk_rounding = 1.0_wp

   !> Compute S again at a tighter local tolerance.
   integer, parameter :: refine_more = 0
   !> The last two values agree to the tolerance: the last one is returned.
   integer, parameter :: refine_met = 1
   !> The tolerance lies below what the integrator can reach at this point.
   integer, parameter :: refine_roundoff = 2
   !> A difference above this fraction of the previous one (after a tenfold tighter local
   !> tolerance) is taken as rounding noise.
   real(wp), parameter :: noise_ratio = 0.5_wp

   !> State of one ladder of local tolerances.
   type :: refinement_t
      real(wp) :: tolerance = 0.0_wp     !! target |ΔS|/max(1, |S|)
      integer :: verdict = refine_more   !! refine_more | refine_met | refine_roundoff
      integer :: n_values = 0            !! values of S seen so far
      type(trace_t) :: previous          !! the last value seen
      real(wp) :: difference = huge(1.0_wp)  !! |S_last − S_before|/max(1, |S_last|)
   end type refinement_t

   !> Relative rounding error of the constants c₀, c₁ of q = c₀ + c₁ w(τ) and of the
   !> computed shape w, as a multiple of ε in `coefficient_level`: one rounding of c₀, one
   !> of c₁ and up to two of w (its denominator and the division).
   real(wp), parameter, public :: coefficient_roundings_c0 = 1.0_wp, coefficient_roundings_c1 = 3.0_wp
   !> `coefficient_level` trusts a sensitivity while the cancellation of its two terms, the
   !> ratio of the result to the sum of their magnitudes, stays above this: the solutions u,
   !> v it is made of carry the integrator's own error (relative errors up to about 1e-8 of
   !> the larger terms), which a stronger cancellation would leave as the whole result.
   real(wp), parameter, public :: cancellation_limit = 1.0e-6_wp

   !> Integrals along the window (the half period [0, 1], or the period) of the solutions
   !> u, v (u = 1, u' = 0 and v = 0, v' = 1 at its start) that give the sensitivity of S to
   !> the constants of q = c₀ + c₁ w(τ) (`coefficient_level`): ∫u², ∫v², ∫u² c₁w, ∫v² c₁w,
   !> ∫u² |c₁w|, ∫v² |c₁w|, and for a whole period the cross terms ∫uv, ∫|uv|, ∫uv c₁w,
   !> ∫|uv c₁w|, all in units of e^{log_unit}.
   type :: sensitivity_t
      real(wp) :: log_unit = 0.0_wp  !! the integrals are multiples of e^{log_unit}
      real(wp) :: u2 = 0.0_wp, v2 = 0.0_wp      !! ∫u², ∫v²
      real(wp) :: u2w = 0.0_wp, v2w = 0.0_wp    !! ∫u² c₁w, ∫v² c₁w
      real(wp) :: u2a = 0.0_wp, v2a = 0.0_wp    !! ∫u² |c₁w|, ∫v² |c₁w|
      real(wp) :: uv = 0.0_wp, uv_abs = 0.0_wp  !! ∫uv, ∫|uv|
      real(wp) :: uvw = 0.0_wp, uva = 0.0_wp    !! ∫uv c₁w, ∫|uv c₁w|
   end type sensitivity_t

contains

   !> Add one step of length h to the integrals of `acc`: u, v the solutions at the end of
   !> the step in units of e^{log_scale}, `shape_part` = c₁ w(τ) = q − c₀ within the step.
   pure subroutine accumulate_sensitivity(acc, u, v, log_scale, h, shape_part)
      type(sensitivity_t), intent(inout) :: acc  !! the integrals, advanced
      real(wp), intent(in) :: u, v        !! the even and odd solutions, times e^{-log_scale}
      real(wp), intent(in) :: log_scale   !! ln of the scale of u and v
      real(wp), intent(in) :: h           !! step length
      real(wp), intent(in) :: shape_part  !! c₁ w at the step (q − c₀)
      real(wp) :: f, uu, vv, uv
      if (acc%log_unit /= 2.0_wp*log_scale) then
         f = exp(max(acc%log_unit - 2.0_wp*log_scale, -700.0_wp))
         acc%u2 = acc%u2*f; acc%v2 = acc%v2*f
         acc%u2w = acc%u2w*f; acc%v2w = acc%v2w*f
         acc%u2a = acc%u2a*f; acc%v2a = acc%v2a*f
         acc%uv = acc%uv*f; acc%uv_abs = acc%uv_abs*f
         acc%uvw = acc%uvw*f; acc%uva = acc%uva*f
         acc%log_unit = 2.0_wp*log_scale
      end if
      uu = h*u*u
      vv = h*v*v
      uv = h*u*v
      acc%u2 = acc%u2 + uu; acc%v2 = acc%v2 + vv
      acc%u2w = acc%u2w + uu*shape_part; acc%v2w = acc%v2w + vv*shape_part
      acc%u2a = acc%u2a + uu*abs(shape_part); acc%v2a = acc%v2a + vv*abs(shape_part)
      acc%uv = acc%uv + uv; acc%uv_abs = acc%uv_abs + abs(uv)
      acc%uvw = acc%uvw + uv*shape_part; acc%uva = acc%uva + abs(uv*shape_part)
   end subroutine accumulate_sensitivity

   !> Round-off of S from the rounding of q itself, relative to max(1, |S|): q = c₀ + c₁ w is
   !> computed from rounded constants and a rounded shape w, a perturbation δq = δc₀ + δc₁ w
   !> that every method sees alike. To first order (the variation of the monodromy M,
   !> with the half-period symmetry of q)
   !>
   !>   ∂S/∂c₀ = 2 (m₂₁ ∫₀¹ v² − m₁₂ ∫₀¹ u²),   c₁ ∂S/∂c₁ = 2 (m₂₁ ∫₀¹ v² c₁w − m₁₂ ∫₀¹ u² c₁w),
   !>
   !> u, v the even and odd solutions, m₁₂ = 2 v(1) v'(1), m₂₁ = 2 u(1) u'(1). The level is
   !> ε (|c₀ ∂S/∂c₀| + 3 |c₁ ∂S/∂c₁|)/max(1, |S|) (`coefficient_roundings_c0`, `_c1`). For a
   !> constant q = ω² this is 2εω|sin 2ω| (c₀ and c₁ aside), the exact first-order effect of
   !> a relative error ε of q; near β = 0 with α → π², where S ≈ 2 but a solution is nearly
   !> periodic and the other grows secularly, it is the large ∂S/∂β that the rounding of
   !> β − π² meets. The two terms of each sensitivity cancel where the solutions grow
   !> (u², v² and m₁₂, m₂₁ of order |S|² for a result of order |S|): where the result is
   !> below `cancellation_limit` times its terms it is integration noise and 0 is returned;
   !> the phase term of `roundoff_level` (2εΦ, exact for growth at constant q) covers it.
   !>
   !> Over the whole period (`half` false: a coefficient without the symmetry) the variation
   !> is ∂S/∂q(τ) = −(m₁₂ u² − m₂₁ v² + (m₂₂ − m₁₁) u v) along [0, P], without the factor 2,
   !> with the cross terms' integrals. Their step sums are of low order, so the cancellation
   !> they would show for growing solutions drowns in their error: beyond |S| =
   !> 1/`cancellation_limit`, where growth alone puts the result below the limit, the level is
   !> 0 (the phase term covers it, as above); without that, points of |S| ~ 1e19 at β = −500
   !> had levels of 1e4.
   pure real(wp) function coefficient_level(acc, c0, m, log_abs_s, half) result(level)
      type(sensitivity_t), intent(in) :: acc    !! the integrals over [0, 1]
      real(wp), intent(in) :: c0                !! the constant c₀ of q
      type(scaled_matrix_t), intent(in) :: m    !! the monodromy
      real(wp), intent(in) :: log_abs_s         !! ln|S|
      !> the integrals are over half a period of an even coefficient (default) or over the period
      logical, intent(in), optional :: half
      real(wp) :: log_factor
      logical :: symmetric
      symmetric = .true.
      if (present(half)) symmetric = half
      level = coefficient_sum(acc, c0, m, symmetric)
      if (.not. symmetric .and. log_abs_s > log(1.0_wp/cancellation_limit)) level = 0.0_wp
      if (level == 0.0_wp) return
      log_factor = m%log_scale + acc%log_unit - max(0.0_wp, log_abs_s)
      level = epsilon(1.0_wp)*level*exp(min(log_factor, log_huge))
   end function coefficient_level

   !> |c₀ ∂S/∂c₀| + 3 |c₁ ∂S/∂c₁| of `coefficient_level` in the units of the integrals and
   !> of the monodromy (times e^{−m%log_scale − acc%log_unit}), each term 0 where it
   !> cancels to integration noise.
   pure real(wp) function coefficient_sum(acc, c0, m, half) result(level)
      type(sensitivity_t), intent(in) :: acc    !! the integrals over the window
      real(wp), intent(in) :: c0                !! the constant c₀ of q
      type(scaled_matrix_t), intent(in) :: m    !! the monodromy
      logical, intent(in) :: half               !! the window is half a period of an even q
      real(wp) :: d0, d1, size0, size1, m12, m21, cross0
      m12 = m%m(1, 2)
      m21 = m%m(2, 1)
      if (half) then
         d0 = 2.0_wp*abs(c0)*abs(m21*acc%v2 - m12*acc%u2)
         size0 = 2.0_wp*abs(c0)*(abs(m21)*acc%v2 + abs(m12)*acc%u2)
         d1 = 2.0_wp*abs(m21*acc%v2w - m12*acc%u2w)
         size1 = 2.0_wp*(abs(m21)*acc%v2a + abs(m12)*acc%u2a)
      else
         cross0 = m%m(2, 2) - m%m(1, 1)
         d0 = abs(c0)*abs(m21*acc%v2 - m12*acc%u2 - cross0*acc%uv)
         size0 = abs(c0)*(abs(m21)*acc%v2 + abs(m12)*acc%u2 + abs(cross0)*acc%uv_abs)
         d1 = abs(m21*acc%v2w - m12*acc%u2w - cross0*acc%uvw)
         size1 = abs(m21)*acc%v2a + abs(m12)*acc%u2a + abs(cross0)*acc%uva
      end if
      level = 0.0_wp
      if (d0 > cancellation_limit*size0) level = level + coefficient_roundings_c0*d0
      if (d1 > cancellation_limit*size1) level = level + coefficient_roundings_c1*d1
   end function coefficient_sum

   !> Start a ladder for the target `tolerance`.
   pure subroutine start_refinement(ladder, tolerance)
      type(refinement_t), intent(out) :: ladder  !! the ladder, reset
      real(wp), intent(in) :: tolerance  !! target |ΔS|/max(1, |S|)
      ladder%tolerance = tolerance
   end subroutine start_refinement

   !> Take the value `tr` computed at the next (tighter) local tolerance; `at_floor` says
   !> that no tighter one is possible; `noise` is the round-off level of S there
   !> (`roundoff_level`). Sets `ladder%verdict` and, when the ladder ends,
   !> `tr%error_estimate` (never below `noise`). A round-off level above the tolerance
   !> ends the ladder as round-off limited as soon as two values agree to that level.
   !>
   !> With `contraction` (gsl) the difference of the last two values is taken as the error
   !> bound of the finer one only once it has shrunk to at most `noise_ratio` of the
   !> difference before (or lies at the round-off level): rk8pd's global error need not
   !> follow its local epsilon (at (9.86, 2.47) it stayed between 2e-13 and 7e-13 for
   !> epsilons from 5e-11 to 3.6e-12, and the pair 5e-11, 3.6e-12 differed by 1.6e-13
   !> while the finer value was 2.4e-13 off), so the agreement of two values alone does
   !> not bound the finer one's error. Then if |S_k − S_{k+1}| ≤ |S_{k−1} − S_k|/2 holds on,
   !> |S_k − S| ≤ Σ_{j>k} |S_j − S_{j+1}| ≤ |S_{k−1} − S_k|, the difference reported. Until
   !> the differences contract, a difference within the tolerance asks for the next value
   !> rather than ending the ladder as round-off limited; where no finer value is possible
   !> (`at_floor`) such a difference still ends it with status met, the estimate resting on
   !> the agreement of the two values alone.
   pure subroutine refine(ladder, tr, at_floor, noise, near_floor, contraction)
      type(refinement_t), intent(inout) :: ladder  !! the ladder, advanced
      type(trace_t), intent(inout) :: tr  !! S at the new local tolerance; gets its error estimate when the ladder ends
      logical, intent(in) :: at_floor     !! no tighter local tolerance is possible
      real(wp), intent(in) :: noise       !! round-off level of S (`roundoff_level`)
      !> the local tolerance is within a few decades of its floor, where differences that
      !> stop halving are rounding noise (default true); far above it they are only a
      !> slow, pre-asymptotic convergence (seen with GSL at tolerance 1e-4, β = −1e5)
      logical, intent(in), optional :: near_floor
      !> end with status met only once the differences contract (see above; default false)
      logical, intent(in), optional :: contraction
      real(wp) :: d
      logical :: stagnation_is_noise, contracting
      stagnation_is_noise = .true.
      if (present(near_floor)) stagnation_is_noise = near_floor
      contracting = .false.
      if (present(contraction)) contracting = contraction
      ladder%n_values = ladder%n_values + 1
      if (ladder%n_values == 1) then
         ladder%previous = tr
         ladder%verdict = refine_more
         return
      end if
      d = trace_distance(tr, ladder%previous)
      if (contracting) then
         if (d <= ladder%tolerance .and. noise <= ladder%tolerance .and. (d <= noise .or. at_floor .or. &
             (ladder%n_values >= 3 .and. d <= noise_ratio*ladder%difference))) then
            ladder%verdict = refine_met
         else if (at_floor .or. (noise > ladder%tolerance .and. d <= noise) .or. &
                  (d > ladder%tolerance .and. stagnation_is_noise .and. ladder%n_values >= 3 .and. &
                   d > noise_ratio*ladder%difference)) then
            ladder%verdict = refine_roundoff
         else
            ladder%verdict = refine_more
         end if
      else if (d <= ladder%tolerance .and. noise <= ladder%tolerance) then
         ladder%verdict = refine_met
      else if (d <= max(ladder%tolerance, noise) .or. at_floor .or. &
               (stagnation_is_noise .and. ladder%n_values >= 3 .and. d > noise_ratio*ladder%difference)) then
         ladder%verdict = refine_roundoff
      else
         ladder%verdict = refine_more
      end if
      ladder%difference = d
      ladder%previous = tr
      if (ladder%verdict /= refine_more) tr%error_estimate = max(d, noise)
   end subroutine refine

   !> Scaled condition of a half-period propagator Φ = [[u, v], [u', v']]: the minimum over
   !> diagonal D of ‖D Φ D⁻¹‖²_F, u² + v'² + 2|v u'| (independent of the units of χ' against χ).
   elemental real(wp) function propagator_condition(u, du, v, dv) result(c)
      real(wp), intent(in) :: u   !! even solution u
      real(wp), intent(in) :: du  !! its derivative u'
      real(wp), intent(in) :: v   !! odd solution v
      real(wp), intent(in) :: dv  !! its derivative v'
      c = u*u + dv*dv + 2.0_wp*abs(v*du)
   end function propagator_condition

   !> Round-off level of S relative to max(1, |S|), the one model of every exact method
   !> (auto, Magnus, rk, gsl), for a propagation of `n_steps` steps whose propagator reached
   !> the scaled condition κ = e^{log_peak}, over a period that accumulates the phase (or
   !> growth exponent) Φ ≤ `phase` (hillstab_hill_coefficient `phase_bound`):
   !>
   !>   0.1 ε √N κ/max(1, |S|) + 2 ε Φ.
   !>
   !> The first term: every rounding of the propagator, and the rounding of Q itself, is
   !> amplified by its condition; no integrator in double precision gets S more accurately
   !> (β = 0 with α → π², Mathieu q = 20 on its transition curves). Its safety factor 0.1
   !> was calibrated on β = 0, α = 9.8 … 9.86, where S = 2 exactly. It assumes that the
   !> roundings of successive steps are independent: the integrators make them so (exact
   !> step times, compensated Magnus products), where a systematic error per step would
   !> grow like ε N instead.
   !>
   !> The second term: Q is computed from rounded constants, a systematic relative error of
   !> about 2ε that every method sees alike; it moves the phase by ε Φ, and S by up to
   !> 2 ε Φ relative to max(1, |S|) (S = 2 cos Φ for an oscillation; ln|S| ≈ Φ for growth,
   !> which a double also stores only to ε Φ). With |β| = 3e5 at α = 9.86 that is 1.1e-12
   !> (rk and gsl both settle 4e-13 to 6e-13 away from the reference there); at β = −1e6,
   !> α → π², 2.6e-12.
   !>
   !> Over a whole period (`half` false: S = tr Φ, no product of the half-period solutions)
   !> the amplification is √κ, the size of Φ's entries: at a point of |S| = 2.6e19 (a drive
   !> with sine terms at β = −500) κ/|S| was 1e19 and the level 1e4, where the methods agree
   !> to 1e-12 and the extended-precision reference of test suite model_fourier confirms them.
   !>
   !> `step_rounding` replaces the 0.1 for the Runge–Kutta integrators (rk, gsl), whose steps
   !> round the state itself (y + h Σ bᵢkᵢ, no compensation): one rounding of ε per step at
   !> the full condition. With 0.1 DOP853 at the Mathieu point ν = 226.17754433821787,
   !> β = −193.3961568448847 (S = −3.46e6, κ/|S| = 2e4) settled 2.6e-11 off at local
   !> tolerances 1e-14 and 1e-15 alike, against a level of 5.9e-12 (4.4×); with 1, 6e-11.
   elemental real(wp) function roundoff_level(log_peak, log_abs_s, n_steps, phase, step_rounding, half) result(level)
      real(wp), intent(in) :: log_peak   !! ln of the largest `propagator_condition` along the path
      real(wp), intent(in) :: log_abs_s  !! ln|S|
      integer, intent(in) :: n_steps     !! steps of the propagation
      real(wp), intent(in) :: phase      !! bound of the phase or growth over the period (`phase_bound`)
      real(wp), intent(in), optional :: step_rounding  !! factor of the √N term (default `roundoff_safety`)
      !> the propagation is half a period and S = 2(u v' + u' v) (default), or the whole
      !> period and S = tr Φ, whose entries carry roundings of the size of Φ itself: √κ
      logical, intent(in), optional :: half
      real(wp) :: factor, log_amplification
      factor = roundoff_safety
      if (present(step_rounding)) factor = step_rounding
      log_amplification = log_peak
      if (present(half)) then
         if (.not. half) log_amplification = 0.5_wp*log_peak
      end if
      level = factor*epsilon(1.0_wp)*sqrt(real(max(n_steps, 1), wp)) &
              *exp(min(log_amplification - max(0.0_wp, log_abs_s), log_huge)) + 2.0_wp*epsilon(1.0_wp)*phase
   end function roundoff_level

   !> |S_a − S_b|/max(1, |S_a|), through ln|S| when S is large or overflows; huge when the
   !> signs of large traces differ.
   elemental real(wp) function trace_distance(a, b) result(d)
      type(trace_t), intent(in) :: a  !! the trace whose scale max(1, |S_a|) is used
      type(trace_t), intent(in) :: b  !! the other trace
      if (a%overflow .or. b%overflow .or. a%log_abs > 300.0_wp) then
         d = abs(a%log_abs - b%log_abs)
         if (sign(1.0_wp, a%value) /= sign(1.0_wp, b%value)) d = huge(1.0_wp)
      else
         d = abs(a%value - b%value)/max(1.0_wp, abs(a%value))
      end if
   end function trace_distance

   !> Factor between the first two local tolerances of a ladder: 10, or the scaled
   !> condition κ/2 of the propagator (`propagator_condition`, 2 for a rotation) relative
   !> to max(1, |S|) when larger, at most 1e4.
   elemental real(wp) function first_step_factor(log_peak, log_abs_s) result(factor)
      real(wp), intent(in) :: log_peak   !! ln of the largest `propagator_condition` of the first pass
      real(wp), intent(in) :: log_abs_s  !! ln|S| of the first pass
      factor = max(10.0_wp, min(1.0e4_wp, 0.5_wp*exp(min(log_peak - max(0.0_wp, log_abs_s), 30.0_wp))))
   end function first_step_factor

   !> The next local tolerance of a ladder: `local/factor`, not below `floor`, and never a
   !> step of less than tenfold: between `floor` and 10·floor only the floor itself is used,
   !> reached from 10·floor or above (from 100·floor or above the step goes to 10·floor
   !> first). The last difference, the error estimate there, then comes from a step of at
   !> least ten: a step from 1.78e-14 to 10·floor = 1e-14 (rk at α = 9.52, β = 1.5e-3,
   !> tolerance 1e-10, where the error is about 400 times the local tolerance) gave a
   !> difference of 0.4 times the finer value's error.
   elemental real(wp) function next_local_tolerance(local, factor, floor) result(next)
      real(wp), intent(in) :: local   !! the current local tolerance
      real(wp), intent(in) :: factor  !! the step down, > 1
      real(wp), intent(in) :: floor   !! the smallest local tolerance the integrator can use
      next = max(local/factor, floor)
      if (next < 10.0_wp*floor .and. local > 10.001_wp*floor) then
         if (local >= 100.0_wp*floor) then
            next = 10.0_wp*floor
         else
            next = floor
         end if
      end if
   end function next_local_tolerance
end module hillstab_integrate_refine

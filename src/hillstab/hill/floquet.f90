!> Floquet multipliers, exponents and stability verdicts: the one result of a monodromy,
!> of one equation or of n (`floquet_t`), and its analysis from one equation's trace.
!>
!> For the undamped equation det M = 1 and the multipliers solve λ² − Sλ + 1 = 0.
!> With damping ε the trace S₁ belongs to χ = e^{ετ/2} x (eq. (47)); the
!> multipliers of the swing x are e^{−ε} λ_χ, so x is asymptotically stable iff
!> |S₁| < 2 cosh ε. The paper's |S₁| ≤ 2 is only sufficient; it is kept in
!> `stable_paper` beside the correct verdict, never instead of it.
!>
!> Multipliers are stored as log-modulus and argument so that they stay finite
!> however large the trace. A system's monodromy Φ (2n × 2n) fills the same result
!> (hillstab_hill_system_floquet), with every multiplier and exponent.
module hillstab_hill_floquet
   use hillstab_core_kinds, only: wp, pi, log_huge
   use hillstab_hill_transfer, only: trace_t, trace_from_value
   implicit none
   private
   public :: floquet_t, floquet_from_trace, floquet_verdict, set_from_trace, verdicts, near_threshold, floquet_from_value
   public :: multipliers, period_damping, largest_multiplier_modulus
   public :: bounds_verdict, bounds_stable, bounds_unstable, bounds_undecided
   public :: verdict_stable, verdict_unstable, verdict_marginal
   public :: kind_stable, kind_plus_one, kind_minus_one, kind_combination, kind_damped, kind_undecided, kind_name

   !> Verdict, stable: every multiplier on the unit circle (Hamiltonian) or inside it (damped), decided.
   integer, parameter :: verdict_stable = 1
   !> Verdict, unstable: a multiplier outside the unit circle, decided.
   integer, parameter :: verdict_unstable = 0
   !> Verdict, marginal: the error bound of the monodromy does not decide (on a boundary, at a collision).
   integer, parameter :: verdict_marginal = -1

   !> Kind, stable, the multipliers on the unit circle.
   integer, parameter :: kind_stable = 0
   !> Kind, a real pair leaves the circle at +1 (λ > 0; a parametric resonance of even order).
   integer, parameter :: kind_plus_one = 1
   !> Kind, a real pair leaves the circle at −1 (λ < 0; a parametric resonance of odd order).
   integer, parameter :: kind_minus_one = 2
   !> Kind, a complex quadruplet leaves the circle (a Krein collision: combination resonance).
   integer, parameter :: kind_combination = 3
   !> Kind, damped and asymptotically stable, every |λ| < 1.
   integer, parameter :: kind_damped = 4
   !> Kind, undecided: the verdict is marginal (the error bound of the monodromy does not tell
   !> whether and where a multiplier leaves the circle).
   integer, parameter :: kind_undecided = 5

   !> The Floquet analysis of one monodromy, of one equation or of n degrees of freedom: what
   !> charts, points files, boundaries and the APIs read, whoever computed it.
   !>
   !> - One equation's trace fills it on the scalar path (`floquet_from_trace`; `floquet_verdict`
   !>   the verdicts alone), allocating nothing: the verdict, the two multipliers of x, the
   !>   exponent, and the trace S it came from.
   !> - A system's monodromy Φ fills it through `system_floquet` (hillstab_hill_system_floquet):
   !>   the same verdict and largest multiplier, and every multiplier and exponent, the
   !>   invariants a₁, a₂ and the structural defect; `complete_from_trace` adds those to a
   !>   trace's result (one equation taken by a scalar method).
   type :: floquet_t
      integer :: n = 1                  !! degrees of freedom
      real(wp) :: period = 2.0_wp       !! P, the period in τ and the exponents' unit
      integer :: verdict = verdict_marginal  !! verdict_*, decided within the error bound
      !> kind_* (of the instability, or stable, damped, undecided)
      integer :: kind = kind_stable
      !> x stays bounded (decays when damped). One equation's trace: |S| < 2 cosh ε, the value's
      !> verdict even when `marginal`; a system's Φ: `verdict` is verdict_stable
      logical :: stable = .false.
      !> the paper's criterion |S| ≤ 2 (one equation's trace only; false for a system's Φ)
      logical :: stable_paper = .false.
      !> the error bound reaches across the stability threshold, so the computed value cannot
      !> decide the verdict (`verdict` is then verdict_marginal). One equation's trace: |S| within
      !> the trace's error bound of 2 cosh ε, set only when the trace carries an error estimate
      !> (see `floquet_from_trace`)
      logical :: marginal = .false.
      !> ln|λ| of the multipliers of x: the largest first, then (one degree of freedom) the other,
      !> (n > 1) the smallest
      real(wp) :: log_modulus(2) = 0.0_wp
      !> arg λ of the same two, in [−π, π]: ±θ when |S| < 2, 0 or π when real
      real(wp) :: argument(2) = 0.0_wp
      real(wp) :: rotation = 0.0_wp     !! θ = arccos(S/2) ∈ [0, π] when |S| ≤ 2, else 0 (one equation's trace)
      !> μ = ln|λ_max|/P per unit τ, the largest Floquet exponent (of x; −ε P/2 / P when |S| < 2)
      real(wp) :: exponent = 0.0_wp
      !> one equation's trace: S (S₁ of χ when ε > 0), with ln|S| and its error estimate
      type(trace_t) :: trace
      real(wp) :: epsilon = 0.0_wp      !! the damping ε of the trace's χ (0 for a system's Φ)
      !> a system's 2n multipliers of Φ̃ (times e^s: Φ's), by decreasing modulus
      complex(wp), allocatable :: multipliers(:)
      !> s of the multipliers: Φ's are e^s times `multipliers` (the scale given, or more where
      !> Φ̃'s entries exceeded 1e100 and were scaled)
      real(wp) :: log_scale = 0.0_wp
      real(wp), allocatable :: exponents(:)     !! ln|λ_i|/P of the n largest multipliers
      real(wp) :: a1 = 0.0_wp                   !! a₁ = tr Φ of x (e^s tr Φ̃; ±1e300 when it overflows)
      real(wp) :: a2 = 0.0_wp                   !! a₂ = ((tr Φ)² − tr Φ²)/2
      logical :: overflow = .false.             !! a₁ or a₂ exceeds 1e300
      !> ‖ΦᵀΩΦ − Ω‖/(‖Ω‖ max(1, ‖Φ‖)²) (Hamiltonian) or |det Φ − e^{P tr D}|/∏‖Φ's columns‖
      !> (0 for one equation's trace: the structure holds by construction)
      real(wp) :: defect = 0.0_wp
      real(wp) :: discriminant = 0.0_wp         !! n = 2 Hamiltonian: a₁² − 4a₂ + 8 (of Φ̃)
      !> every exponent meets the tolerance (false: one could not be resolved, the point at status 1)
      logical :: exponents_resolved = .true.
   end type floquet_t

   !> What the range of the coefficient alone decides (`bounds_verdict`).
   integer, parameter :: bounds_undecided = 0  !! nothing
   integer, parameter :: bounds_stable = 1     !! |S| < 2 (Zhukovskii's criterion)
   integer, parameter :: bounds_unstable = -1  !! S > 2 (q ≤ 0 throughout, q ≢ 0)

contains

   !> The verdict of x'' + q(τ) x = 0 (period 2) that the range [q_min, q_max] of q decides
   !> without integrating: Zhukovskii's criterion (1892), stable, |S| < 2, when
   !> (nπ/2)² < q_min and q_max < ((n + 1)π/2)² for some n ≥ 0 (q between two consecutive
   !> eigenvalues of the periodic and antiperiodic problems of a constant coefficient);
   !> S > 2 when q_max < 0 (u'' = −q u with u(0) = 1, u'(0) = 0 is convex and increasing,
   !> v' of the odd solution grows from 1, so S = u(2) + v'(2) > 2). Otherwise undecided.
   !> The caller widens the range for the roundings of q (`model_coefficient_range`); the
   !> band edges are compared with a margin of their own roundings.
   elemental integer function bounds_verdict(q_min, q_max) result(verdict)
      real(wp), intent(in) :: q_min, q_max  !! bounds of q over the period
      real(wp) :: n, low, high
      verdict = bounds_undecided
      if (q_max < 0.0_wp) then
         verdict = bounds_unstable
      else if (q_min > 0.0_wp .and. q_max < 1.0e12_wp) then
         ! the band of q_min: n = floor(2 √q_min/π)
         n = aint(2.0_wp*sqrt(q_min)/pi)
         low = (0.5_wp*pi*n)**2*(1.0_wp + 8.0_wp*epsilon(1.0_wp))
         high = (0.5_wp*pi*(n + 1.0_wp))**2*(1.0_wp - 8.0_wp*epsilon(1.0_wp))
         if (low < q_min .and. q_max < high) verdict = bounds_stable
      end if
   end function bounds_verdict

   !> Floquet data from the trace of the (χ-)monodromy and the damping ε.
   !> `marginal` is set when the trace has an error estimate e ≥ 0 (exact methods) and
   !> ||S| − 2 cosh ε| ≤ max(e, tolerance) max(1, |S|): the error bound of S, on the scale of
   !> `tolerance`, reaches across the stability threshold (always when e ≥ 1).
   pure function floquet_from_trace(tr, epsilon, tolerance, period) result(f)
      type(trace_t), intent(in) :: tr  !! trace of the (chi-)monodromy, with ln|S| and its error estimate
      real(wp), intent(in) :: epsilon  !! damping ε ≥ 0
      !> the tolerance S was computed to (relative to max(1, |S|)); default 0: the estimate alone
      real(wp), intent(in), optional :: tolerance
      !> the period P of Q in τ (default 2): x = e^{−ετ/2} χ loses εP/2 of ln|λ| a period
      real(wp), intent(in), optional :: period
      type(floquet_t) :: f
      real(wp) :: bound, p
      bound = 0.0_wp
      if (present(tolerance)) bound = tolerance
      p = 2.0_wp
      if (present(period)) p = period
      call set_from_trace(f, tr, epsilon, bound, p, .false.)
   end function floquet_from_trace

   !> `floquet_from_trace` (or, `verdict_only`, `floquet_verdict`) written into an existing
   !> result in place: every field of the trace's overwritten, a system's left as they are.
   !> The form of the loops over many points, which thus build and copy no result a point.
   pure subroutine set_from_trace(f, tr, epsilon, tolerance, period, verdict_only)
      type(floquet_t), intent(inout) :: f  !! the result, overwritten
      type(trace_t), intent(in) :: tr  !! trace of the (chi-)monodromy, with ln|S| and its error estimate
      real(wp), intent(in) :: epsilon  !! damping ε ≥ 0
      !> the tolerance S was computed to (relative to max(1, |S|)); 0: the estimate alone
      real(wp), intent(in) :: tolerance
      real(wp), intent(in) :: period  !! the period P of Q in τ
      !> the verdicts alone (`floquet_verdict`): the multipliers and exponent set to zero
      logical, intent(in) :: verdict_only
      real(wp) :: s, log_growth, decay
      decay = period_damping(epsilon, period)
      f%n = 1
      f%trace = tr
      f%epsilon = epsilon
      f%period = period
      call verdicts(tr, decay, tolerance, f%stable, f%stable_paper, f%marginal)
      if (f%marginal) then
         f%verdict = verdict_marginal
         f%kind = kind_undecided
      else if (f%stable) then
         f%verdict = verdict_stable
         f%kind = merge(kind_damped, kind_stable, decay > 0.0_wp)
      else
         f%verdict = verdict_unstable
         f%kind = merge(kind_plus_one, kind_minus_one, tr%value > 0.0_wp)
      end if
      if (verdict_only) then
         f%rotation = 0.0_wp
         f%log_modulus = 0.0_wp
         f%argument = 0.0_wp
         f%exponent = 0.0_wp
         return
      end if
      s = tr%value
      if (.not. tr%overflow .and. abs(s) <= 2.0_wp) then
         f%rotation = acos(0.5_wp*s)
         f%log_modulus = -decay
         f%argument = [f%rotation, -f%rotation]
      else
         log_growth = growth_of(tr)
         f%rotation = 0.0_wp
         f%log_modulus = [log_growth - decay, -log_growth - decay]
         if (s > 0.0_wp) then
            f%argument = 0.0_wp
         else
            f%argument = pi
         end if
      end if
      f%exponent = f%log_modulus(1)/period
   end subroutine set_from_trace

   !> The damping of one period of length P as the verdicts take it: εP/2 (ε for P = 2,
   !> exactly), ln of the factor e^{−εP/2} between the multipliers of χ and those of x.
   elemental real(wp) function period_damping(epsilon, period) result(decay)
      real(wp), intent(in) :: epsilon  !! damping ε ≥ 0
      real(wp), intent(in) :: period   !! the period P in τ
      decay = epsilon*(0.5_wp*period)
   end function period_damping

   !> The verdicts alone of `floquet_from_trace` (`verdict`, `kind`, `stable`, `stable_paper`,
   !> `marginal`, the trace, ε and the period; the multipliers left at zero): what a file of
   !> verdicts needs, without the inverse trigonometric and hyperbolic functions of the
   !> multipliers.
   pure function floquet_verdict(tr, epsilon, tolerance, period) result(f)
      type(trace_t), intent(in) :: tr  !! trace of the (chi-)monodromy, with its error estimate
      real(wp), intent(in) :: epsilon  !! damping ε ≥ 0
      !> the tolerance S was computed to (relative to max(1, |S|)); default 0: the estimate alone
      real(wp), intent(in), optional :: tolerance
      real(wp), intent(in), optional :: period  !! the period P of Q in τ (default 2)
      type(floquet_t) :: f
      real(wp) :: bound, p
      bound = 0.0_wp
      if (present(tolerance)) bound = tolerance
      p = 2.0_wp
      if (present(period)) p = period
      call set_from_trace(f, tr, epsilon, bound, p, .true.)
   end function floquet_verdict

   !> The name of a kind, for headers and docs.
   pure function kind_name(kind) result(name)
      integer, intent(in) :: kind  !! kind_*
      character(len=:), allocatable :: name
      select case (kind)
      case (kind_stable); name = "stable"
      case (kind_plus_one); name = "parametric at +1"
      case (kind_minus_one); name = "parametric at -1"
      case (kind_combination); name = "combination (Krein collision)"
      case (kind_damped); name = "damped, asymptotically stable"
      case (kind_undecided); name = "undecided (marginal)"
      case default; name = "unknown"
      end select
   end function kind_name

   !> The verdicts of `floquet_verdict` alone, as three flags: what a file of verdicts writes
   !> at every point (no Floquet data built).
   elemental subroutine verdicts(tr, epsilon, tolerance, stable, stable_paper, marginal)
      type(trace_t), intent(in) :: tr  !! trace of the (chi-)monodromy, with its error estimate
      !> damping of one period, ε ≥ 0 for the period 2 (εP/2 for a period P: `period_damping`)
      real(wp), intent(in) :: epsilon
      real(wp), intent(in) :: tolerance  !! the tolerance S was computed to (0: the estimate alone)
      logical, intent(out) :: stable        !! |S| < 2 cosh ε
      logical, intent(out) :: stable_paper  !! |S| ≤ 2
      logical, intent(out) :: marginal      !! the error bound reaches across 2 cosh ε
      real(wp) :: s, bound
      s = tr%value
      if (epsilon > 0.0_wp) then
         if (.not. tr%overflow .and. abs(s) <= 2.0_wp) then
            stable = 0.0_wp < epsilon
         else
            stable = growth_of(tr) < epsilon
         end if
      else
         stable = .not. tr%overflow .and. abs(s) < 2.0_wp
      end if
      stable_paper = .not. tr%overflow .and. abs(s) <= 2.0_wp
      marginal = .false.
      if (tr%error_estimate >= 1.0_wp .and. .not. tr%overflow) then
         ! an error bound of the order of S itself decides nothing
         marginal = .true.
      else if (tr%error_estimate >= 0.0_wp .and. .not. tr%overflow .and. epsilon < log_huge) then
         bound = max(tr%error_estimate, tolerance)
         marginal = near_threshold(s, epsilon, bound)
      end if
   end subroutine verdicts

   !> Whether |S| lies within bound·max(1, |S|) of the stability threshold 2 cosh ε (2
   !> without damping): the value cannot tell the side (for ε < log_huge).
   elemental logical function near_threshold(s, epsilon, bound) result(near)
      real(wp), intent(in) :: s        !! the trace
      real(wp), intent(in) :: epsilon  !! damping ε ≥ 0 (0: the threshold 2, also the paper's)
      real(wp), intent(in) :: bound    !! error bound relative to max(1, |S|)
      if (epsilon > 0.0_wp) then
         near = abs(abs(s) - 2.0_wp*cosh(epsilon)) <= bound*max(1.0_wp, abs(s))
      else
         near = abs(abs(s) - 2.0_wp) <= bound*max(1.0_wp, abs(s))
      end if
   end function near_threshold

   !> ln|λ_max| of χ for |S| ≥ 2: arccosh(|S|/2) = ln((|S| + √(S² − 4))/2); ≈ ln|S| for huge |S|.
   pure real(wp) function growth_of(tr) result(log_growth)
      type(trace_t), intent(in) :: tr
      if (tr%log_abs > 0.5_wp*log_huge) then
         log_growth = tr%log_abs + log1p_small(-exp(-2.0_wp*tr%log_abs))
      else
         log_growth = acosh(0.5_wp*abs(tr%value))
      end if
   end function growth_of

   !> Floquet data from a finite trace value.
   pure function floquet_from_value(s, epsilon) result(f)
      real(wp), intent(in) :: s, epsilon  !! a finite trace S; damping epsilon >= 0
      type(floquet_t) :: f
      f = floquet_from_trace(trace_from_value(s), epsilon)
   end function floquet_from_value

   pure real(wp) function log1p_small(x)
      real(wp), intent(in) :: x
      log1p_small = x - 0.5_wp*x*x
   end function log1p_small

   !> Multipliers of x as complex numbers (moduli clamped to huge when they overflow).
   pure function multipliers(f) result(lambda)
      type(floquet_t), intent(in) :: f  !! Floquet data of the swing
      complex(wp) :: lambda(2)
      integer :: i
      do i = 1, 2
         if (f%rotation == 0.0_wp) then
            ! real multipliers: argument exactly 0 or π, no sin(π) residue
            lambda(i) = cmplx(sign(exp(min(f%log_modulus(i), log_huge)), cos(f%argument(i))), 0.0_wp, wp)
         else
            lambda(i) = exp(min(f%log_modulus(i), log_huge))*cmplx(cos(f%argument(i)), sin(f%argument(i)), wp)
         end if
      end do
   end function multipliers

   !> max |λ| of x, clamped to huge(1.0_wp) when it overflows.
   pure real(wp) function largest_multiplier_modulus(f)
      type(floquet_t), intent(in) :: f  !! Floquet data of the swing
      if (f%log_modulus(1) >= log_huge) then
         largest_multiplier_modulus = huge(1.0_wp)
      else
         largest_multiplier_modulus = exp(f%log_modulus(1))
      end if
   end function largest_multiplier_modulus
end module hillstab_hill_floquet

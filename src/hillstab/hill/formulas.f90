!> The paper's closed-form traces for two-piece coefficients.
!>
!> - eq. (37): elastic Q sampled as eq. (28): (β − α)/(1 − α/π²) on [0,1), (β + α)/(1 + α/π²) on [1,2);
!> - eqs. (48)–(50): the same with the damping shift of eq. (47), giving S₁ for χ;
!> - eq. (A3)/(A9): Mathieu q = β ∓ ν on the two halves.
!>
!> All are evaluated as tr(T(q₂,1) T(q₁,1)) = 2 C₁C₂ − (q₁ + q₂) S₁S₂, with
!> C = cos √q, S = sin √q/√q (cosh, sinh for q < 0). Algebraically this is the
!> paper's expression, since (q₁ + q₂)/√(q₁q₂) = 2(β − α²/π²)/√((β² − α²)(1 − α²/π⁴)),
!> but it stays real and finite where the paper's radicands turn negative
!> (β < α, β + α < 0) and at β = ±α where the paper's form is 0/0.
module hillstab_hill_formulas
   use hillstab_core_kinds, only: wp, pi2
   use hillstab_hill_coefficient, only: one_minus_alpha_over_pi2
   use hillstab_hill_transfer, only: transfer_functions, trace_t, trace_from_scaled
   implicit none
   private
   public :: trace_two_segment_paper, trace_damped_paper, trace_mathieu_two_segment, trace_two_piece

contains

   !> Trace of T(q₂, 1)·T(q₁, 1) for two unit-length constant pieces, overflow-safe.
   pure function trace_two_piece(q1, q2) result(tr)
      real(wp), intent(in) :: q1  !! coefficient on [0, 1)
      real(wp), intent(in) :: q2  !! coefficient on [1, 2)
      type(trace_t) :: tr
      real(wp) :: c1, s1, l1, c2, s2, l2, t
      call transfer_functions(q1, c1, s1, l1)
      call transfer_functions(q2, c2, s2, l2)
      t = 2.0_wp*c1*c2 - (q1 + q2)*s1*s2
      tr = trace_from_scaled(t, l1 + l2)
   end function trace_two_piece

   !> The paper's eq. (37): 2-segment trace of the undamped elastic Hill equation.
   pure function trace_two_segment_paper(alpha, beta) result(tr)
      real(wp), intent(in) :: alpha  !! α, 0 ≤ α < π²
      real(wp), intent(in) :: beta   !! β
      type(trace_t) :: tr
      tr = trace_damped_paper(alpha, beta, 0.0_wp)
   end function trace_two_segment_paper

   !> The paper's eqs. (48)–(50): S₁ for the damped χ equation (47):
   !> B₁² = ((β − ε²/4) + α(1 − ε²/4π²))/(1 + α/π²), B₂² = ((β − ε²/4) − α(1 − ε²/4π²))/(1 − α/π²).
   pure function trace_damped_paper(alpha, beta, epsilon) result(tr)
      real(wp), intent(in) :: alpha, beta  !! the chart point (alpha, beta)
      real(wp), intent(in) :: epsilon  !! damping ε = κπ/ω
      type(trace_t) :: tr
      real(wp) :: shifted, amp, b1_sq, b2_sq
      shifted = beta - 0.25_wp*epsilon**2
      amp = alpha*(1.0_wp - 0.25_wp*epsilon**2/pi2)
      b1_sq = (shifted + amp)/(1.0_wp + alpha/pi2)   ! Q(1) − ε²/4, eq. (49)
      b2_sq = (shifted - amp)/one_minus_alpha_over_pi2(alpha)   ! Q(0) − ε²/4, eq. (50)
      tr = trace_two_piece(b2_sq, b1_sq)
   end function trace_damped_paper

   !> The paper's eq. (A3)/(A9): Mathieu q = β − ν on [0,1), β + ν on [1,2).
   pure function trace_mathieu_two_segment(nu, beta) result(tr)
      real(wp), intent(in) :: nu, beta  !! Mathieu amplitude nu and mean beta
      type(trace_t) :: tr
      tr = trace_two_piece(beta - nu, beta + nu)
   end function trace_mathieu_two_segment
end module hillstab_hill_formulas

!> The paper's closed-form traces for two-piece coefficients.
!>
!> - eq. (37): elastic Q sampled as eq. (28): (β − α)/(1 − α/π²) on [0,1), (β + α)/(1 + α/π²) on [1,2);
!> - eqs. (48)–(50): the same with the damping shift of eq. (47), giving S₁ for χ;
!> - eq. (A3)/(A9): Mathieu q = β ∓ ν on the two halves;
!> - `trace_formula`: method formula for any registered model, from its two pieces
!>   (hillstab_hill_model: the binding `two_piece_values`).
!>
!> All are evaluated as tr(T(q₂,1) T(q₁,1)) = 2 C₁C₂ − (q₁ + q₂) S₁S₂, with
!> C = cos √q, S = sin √q/√q (cosh, sinh for q < 0). Algebraically this is the
!> paper's expression, since (q₁ + q₂)/√(q₁q₂) = 2(β − α²/π²)/√((β² − α²)(1 − α²/π⁴)),
!> but it stays real and finite where the paper's radicands turn negative
!> (β < α, β + α < 0) and at β = ±α where the paper's form is 0/0.
module hillstab_hill_formulas
   use hillstab_core_kinds, only: wp
   use hillstab_hill_model, only: hill_model_t, hill_point_t
   use hillstab_hill_model_elastic, only: elastic_two_piece_values
   use hillstab_hill_transfer, only: transfer_functions, trace_t, trace_from_scaled
   implicit none
   private
   public :: trace_two_segment_paper, trace_damped_paper, trace_mathieu_two_segment, trace_two_piece, trace_formula

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
      real(wp) :: b1_sq, b2_sq
      call elastic_two_piece_values(alpha, beta, epsilon, b2_sq, b1_sq)   ! Q(0), Q(1) − ε²/4, eqs. (50), (49)
      tr = trace_two_piece(b2_sq, b1_sq)
   end function trace_damped_paper

   !> The paper's eq. (A3)/(A9): Mathieu q = β − ν on [0,1), β + ν on [1,2).
   pure function trace_mathieu_two_segment(nu, beta) result(tr)
      real(wp), intent(in) :: nu, beta  !! Mathieu amplitude nu and mean beta
      type(trace_t) :: tr
      tr = trace_two_piece(beta - nu, beta + nu)
   end function trace_mathieu_two_segment

   !> Method formula: the trace of the model's two pieces (the paper's sampling (28) in its
   !> closed form), S₁ of the χ equation when ε > 0: eq. (37)/(48)–(50) for the elastic
   !> model, (A3) with β − ε²/4 for the Mathieu model; over a period P ≠ 2 the two pieces
   !> are each P/2 long.
   pure function trace_formula(model, point) result(tr)
      class(hill_model_t), intent(in) :: model  !! the model
      type(hill_point_t), intent(in) :: point   !! α, β, ε
      type(trace_t) :: tr
      real(wp) :: q_first, q_second, scale
      call model%two_piece_values(point%alpha, point%beta, point%epsilon, q_first, q_second)
      ! pieces of length P/2: in s = 2τ/P they are of unit length and q scales by (P/2)²
      scale = (0.5_wp*model%period())**2
      tr = trace_two_piece(scale*q_first, scale*q_second)
   end function trace_formula
end module hillstab_hill_formulas

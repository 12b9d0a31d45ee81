!> The paper's Mathieu form (A1), q(τ) = β − ν cos πτ, the small-amplitude limit of the
!> elastic coefficient (ν = α(1 − β/π²), eq. (21)); in hillstab's parameters α plays ν
!> and takes any finite value. `mathieu_model_t` is this model as a value
!> (hillstab_hill_model): its bindings answer, without the damping shift −ε²/4 of eq. (47),
!> q, its exact segment means, the split q = c₀ + c₁ w with w = cos πτ, w from sin(πτ/2),
!> ∫₀¹ √|w|, auto's step-count inputs, the Fourier terms of Hill's method (the pencil's, and
!> the one harmonic of g = Q − β = −ν cos πτ), the two-piece
!> values of the paper's eq. (A3) and GSL's characteristic values as the independent
!> witness of its transition curves.
!>
!>```fortran
!> type(mathieu_model_t) :: mathieu
!> print *, mathieu%coefficient(1.0_wp, 2.47_wp, 0.5_wp)   ! 2.47
!>```
module hillstab_hill_model_mathieu
   use hillstab_core_kinds, only: wp, pi, pi2
   use hillstab_hill_model, only: hill_form_pencil
   use hillstab_hill_model_pendulum, only: pendulum_model_t
   use hillstab_hill_units, only: physical_t, physical_nu
   use hillstab_hill_mathieu, only: mathieu_witness
   implicit none
   private
   public :: mathieu_model_t
   public :: mathieu_coefficient, mathieu_segment_mean, mathieu_split, mathieu_shape, mathieu_shapes_from_half_sines
   public :: mathieu_shape_root_mean, mathieu_auto_difficulty, mathieu_auto_amplitude
   public :: mathieu_hill_coupling, mathieu_two_piece_values

   !> The paper's Mathieu form (A1), q = β − ν cos πτ, as a model (hillstab_hill_model).
   type, extends(pendulum_model_t) :: mathieu_model_t
   contains
      procedure :: name => mathieu_name
      procedure :: formula => mathieu_formula
      procedure :: summary => mathieu_summary
      procedure :: physical_note => mathieu_physical_note
      procedure :: physical_alpha => mathieu_physical_alpha
      procedure :: has_witness => mathieu_has_witness
      procedure :: witness_beta => mathieu_witness_beta
      procedure :: coefficient => mathieu_model_coefficient
      procedure :: segment_mean => mathieu_model_segment_mean
      procedure :: split => mathieu_model_split
      procedure :: shapes => mathieu_model_shapes
      procedure :: shape_range => mathieu_model_shape_range
      procedure :: shape_root_mean => mathieu_model_shape_root_mean
      procedure :: shapes_from_half_sines => mathieu_model_shapes_from_half_sines
      procedure :: auto_difficulty => mathieu_model_auto_difficulty
      procedure :: auto_amplitude => mathieu_model_auto_amplitude
      procedure :: two_piece_values => mathieu_model_two_piece_values
      procedure :: hill_form => mathieu_hill_form
      procedure :: hill_coupling => mathieu_model_hill_coupling
      procedure :: drive_harmonic_count => mathieu_drive_harmonic_count
      procedure :: drive_harmonics => mathieu_drive_harmonics
   end type mathieu_model_t

contains

   !> "mathieu".
   pure function mathieu_name(self) result(text)
      class(mathieu_model_t), intent(in) :: self  !! the model
      character(len=:), allocatable :: text
      text = "mathieu"
   end function mathieu_name

   !> The coefficient as output headers state it.
   pure function mathieu_formula(self) result(text)
      class(mathieu_model_t), intent(in) :: self  !! the model
      character(len=:), allocatable :: text
      text = "q(tau) = beta - alpha cos(pi tau), eq. (A1), alpha playing nu"
   end function mathieu_formula

   !> The coefficient in a few words (a template's comment).
   pure function mathieu_summary(self) result(text)
      class(mathieu_model_t), intent(in) :: self  !! the model
      character(len=:), allocatable :: text
      text = "Q = beta - alpha cos pi tau"
   end function mathieu_summary

   !> What α means when the scene gives physical units.
   pure function mathieu_physical_note(self) result(text)
      class(mathieu_model_t), intent(in) :: self  !! the model
      character(len=:), allocatable :: text
      text = " (here alpha is nu = a r0 pi^2/rho^2 of eq. (21))"
   end function mathieu_physical_note

   !> ν = a r0 π²/ρ² of eq. (21) for a pendulum given in physical units.
   elemental real(wp) function mathieu_physical_alpha(self, p) result(alpha)
      class(mathieu_model_t), intent(in) :: self  !! the model
      type(physical_t), intent(in) :: p           !! the pendulum (ω > 0, ρ > 0)
      alpha = physical_nu(p)
   end function mathieu_physical_alpha

   !> GSL's a_n, b_n witness the transition curves.
   elemental logical function mathieu_has_witness(self)
      class(mathieu_model_t), intent(in) :: self  !! the model
      mathieu_has_witness = .true.
   end function mathieu_has_witness

   !> β on the curve (order, parity) from GSL's characteristic values, where GSL is trusted
   !> (hillstab_hill_mathieu `mathieu_witness`).
   subroutine mathieu_witness_beta(self, order, parity, alpha, beta, available)
      class(mathieu_model_t), intent(in) :: self  !! the model
      integer, intent(in) :: order, parity        !! order n; parity 1 even (a_n), 2 odd (b_n)
      real(wp), intent(in) :: alpha               !! ν
      real(wp), intent(out) :: beta               !! the witness' β (0: none)
      logical, intent(out) :: available           !! a witness value was computed
      call mathieu_witness(order, parity, alpha, beta, available)
   end subroutine mathieu_witness_beta

   !> q(τ) = β − ν cos πτ.
   elemental real(wp) function mathieu_model_coefficient(self, alpha, beta, tau) result(q)
      class(mathieu_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha, beta         !! ν and β
      real(wp), intent(in) :: tau                 !! dimensionless time
      q = mathieu_coefficient(alpha, beta, tau)
   end function mathieu_model_coefficient

   !> Exact mean of q over [τ_a, τ_b].
   pure real(wp) function mathieu_model_segment_mean(self, alpha, beta, tau_a, tau_b) result(q)
      class(mathieu_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha, beta         !! ν and β
      real(wp), intent(in) :: tau_a, tau_b        !! segment ends, tau_a < tau_b
      q = mathieu_segment_mean(alpha, beta, tau_a, tau_b)
   end function mathieu_model_segment_mean

   !> q = β − ν w, w = cos πτ.
   elemental subroutine mathieu_model_split(self, alpha, beta, c0, c1)
      class(mathieu_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha, beta         !! ν and β
      real(wp), intent(out) :: c0                 !! β
      real(wp), intent(out) :: c1                 !! −ν
      call mathieu_split(alpha, beta, c0, c1)
   end subroutine mathieu_model_split

   !> w = cos πτ at the times `tau`.
   pure subroutine mathieu_model_shapes(self, alpha, tau, w)
      class(mathieu_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha               !! ν
      real(wp), intent(in) :: tau(:)              !! the times
      real(wp), intent(out) :: w(:)               !! w there
      w = mathieu_shape(tau)
   end subroutine mathieu_model_shapes

   !> cos πτ lies in [−1, 1].
   elemental subroutine mathieu_model_shape_range(self, alpha, w_min, w_max)
      class(mathieu_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha               !! ν
      real(wp), intent(out) :: w_min, w_max       !! −1 and 1
      w_min = -1.0_wp
      w_max = 1.0_wp
   end subroutine mathieu_model_shape_range

   !> A bound of ∫₀¹ √|cos πτ| dτ: 1.
   elemental real(wp) function mathieu_model_shape_root_mean(self, alpha) result(mean)
      class(mathieu_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha               !! ν
      mean = mathieu_shape_root_mean()
   end function mathieu_model_shape_root_mean

   !> w = 1 − 2 s² from the half-angle sines.
   pure subroutine mathieu_model_shapes_from_half_sines(self, alpha, n, s, w)
      class(mathieu_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha               !! ν
      integer, intent(in) :: n                    !! number of points
      real(wp), intent(in) :: s(n)                !! sin(πτ/2) at the points
      real(wp), intent(out) :: w(n)               !! w there
      call mathieu_shapes_from_half_sines(n, s, w)
   end subroutine mathieu_model_shapes_from_half_sines

   !> −ln(1 − min(|ν|, 9)/π²) (`mathieu_auto_difficulty`).
   elemental real(wp) function mathieu_model_auto_difficulty(self, alpha) result(x)
      class(mathieu_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha               !! ν
      x = mathieu_auto_difficulty(alpha)
   end function mathieu_model_auto_difficulty

   !> |c₁| + 0.1 |c₀| (`mathieu_auto_amplitude`).
   elemental real(wp) function mathieu_model_auto_amplitude(self, c0, c1) result(amplitude)
      class(mathieu_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: c0, c1              !! the split of q
      amplitude = mathieu_auto_amplitude(c0, c1)
   end function mathieu_model_auto_amplitude

   !> The two pieces of eq. (A3)/(A9) with the damping shift.
   elemental subroutine mathieu_model_two_piece_values(self, alpha, beta, epsilon, q_first, q_second)
      class(mathieu_model_t), intent(in) :: self    !! the model
      real(wp), intent(in) :: alpha, beta, epsilon  !! ν, β and the damping
      real(wp), intent(out) :: q_first              !! the value on [0, 1)
      real(wp), intent(out) :: q_second             !! the value on [1, 2)
      call mathieu_two_piece_values(alpha, beta, epsilon, q_first, q_second)
   end subroutine mathieu_model_two_piece_values

   !> Hill's method in the pencil form (k = 0).
   pure integer function mathieu_hill_form(self) result(form)
      class(mathieu_model_t), intent(in) :: self  !! the model
      form = hill_form_pencil
   end function mathieu_hill_form

   !> ν on every mode (`mathieu_hill_coupling`).
   elemental real(wp) function mathieu_model_hill_coupling(self, alpha, t) result(coupling)
      class(mathieu_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha               !! ν
      real(wp), intent(in) :: t                   !! the squared mode number
      coupling = mathieu_hill_coupling(alpha)
   end function mathieu_model_hill_coupling

   !> Q = β + g(τ) with g = −ν cos πτ: one harmonic (Hill's method on the Fourier coefficients).
   pure integer function mathieu_drive_harmonic_count(self) result(count)
      class(mathieu_model_t), intent(in) :: self  !! the model
      count = 1
   end function mathieu_drive_harmonic_count

   !> g = −ν cos πτ over the period 2: mean 0, c(1) = −ν, every other coefficient 0.
   pure subroutine mathieu_drive_harmonics(self, alpha, n, mean, c, s)
      class(mathieu_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha               !! ν
      integer, intent(in) :: n                    !! number of harmonics wanted
      real(wp), intent(out) :: mean               !! 0
      real(wp), intent(out) :: c(n), s(n)         !! −ν, 0, 0, … and 0
      mean = 0.0_wp
      c = 0.0_wp
      s = 0.0_wp
      if (n >= 1) c(1) = -alpha
   end subroutine mathieu_drive_harmonics

   !> q(τ) = β − ν cos πτ, eq. (A1). (Arguments by value: the integrators evaluate it at every
   !> stage, through `hill_coefficient`.)
   elemental real(wp) function mathieu_coefficient(nu, beta, tau) result(q)
      real(wp), intent(in), value :: nu, beta  !! amplitude ν (hillstab's α) and mean β
      real(wp), intent(in), value :: tau       !! dimensionless time
      q = beta - nu*cos(pi*tau)
   end function mathieu_coefficient

   !> Exact mean of q over [tau_a, tau_b].
   pure real(wp) function mathieu_segment_mean(nu, beta, tau_a, tau_b) result(q)
      real(wp), intent(in), value :: nu, beta      !! amplitude ν and mean β
      real(wp), intent(in), value :: tau_a, tau_b  !! segment ends, tau_a < tau_b
      q = beta - nu*(sin(pi*tau_b) - sin(pi*tau_a))/(pi*(tau_b - tau_a))
   end function mathieu_segment_mean

   !> q = c₀ + c₁ w(τ) with w = cos πτ: c₀ = β, c₁ = −ν.
   elemental subroutine mathieu_split(nu, beta, c0, c1)
      real(wp), intent(in) :: nu, beta  !! amplitude ν and mean β
      real(wp), intent(out) :: c0       !! constant part, β
      real(wp), intent(out) :: c1       !! factor of w, −ν
      c0 = beta
      c1 = -nu
   end subroutine mathieu_split

   !> The shape function w(τ) = cos πτ.
   elemental real(wp) function mathieu_shape(tau) result(w)
      real(wp), intent(in) :: tau  !! τ
      w = cos(pi*tau)
   end function mathieu_shape

   !> w = cos πτ = 1 − 2 s² at the points whose half-angle sines s = sin(πτ/2) are given.
   pure subroutine mathieu_shapes_from_half_sines(n, s, w)
      integer, intent(in) :: n       !! number of points
      real(wp), intent(in) :: s(n)   !! sin(πτ/2) at the points
      real(wp), intent(out) :: w(n)  !! w(τ) there
      integer :: i
      do i = 1, n
         w(i) = 1.0_wp - 2.0_wp*s(i)*s(i)
      end do
   end subroutine mathieu_shapes_from_half_sines

   !> A bound of ∫₀¹ √|cos πτ| dτ (0.76…): 1.
   elemental real(wp) function mathieu_shape_root_mean() result(mean)
      mean = 1.0_wp
   end function mathieu_shape_root_mean

   !> x of method auto's calibrated step table: no dip, so the amplitude ν plays α's
   !> role, −ln(1 − min(|ν|, 9)/π²) (clipped to the table).
   elemental real(wp) function mathieu_auto_difficulty(nu) result(x)
      real(wp), intent(in) :: nu  !! amplitude ν
      x = -log(1.0_wp - min(abs(nu), 9.0_wp)/pi2)
   end function mathieu_auto_difficulty

   !> The amplitude of q that method auto's step count grows with: |c₁| + 0.1 |c₀|
   !> (|ν| and, for large |β|, the oscillation itself).
   elemental real(wp) function mathieu_auto_amplitude(c0, c1) result(amplitude)
      real(wp), intent(in) :: c0, c1  !! the split of q (`mathieu_split`)
      amplitude = abs(c1) + 0.1_wp*abs(c0)
   end function mathieu_auto_amplitude

   !> The weight of cos πτ on every Fourier mode in Hill's method: ν (the weight of x'' is 1).
   elemental real(wp) function mathieu_hill_coupling(nu) result(coupling)
      real(wp), intent(in) :: nu  !! amplitude ν
      coupling = nu
   end function mathieu_hill_coupling

   !> The two pieces of eq. (A3)/(A9) with the damping shift: β − ε²/4 − ν on [0, 1),
   !> β − ε²/4 + ν on [1, 2).
   elemental subroutine mathieu_two_piece_values(nu, beta, epsilon, q_first, q_second)
      real(wp), intent(in) :: nu, beta, epsilon  !! amplitude ν, mean β, damping ε
      real(wp), intent(out) :: q_first   !! value on [0, 1)
      real(wp), intent(out) :: q_second  !! value on [1, 2)
      real(wp) :: shifted
      shifted = beta - 0.25_wp*epsilon**2
      q_first = shifted - nu
      q_second = shifted + nu
   end subroutine mathieu_two_piece_values
end module hillstab_hill_model_mathieu

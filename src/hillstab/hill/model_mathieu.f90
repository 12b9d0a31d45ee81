!> The paper's Mathieu form (A1), q(τ) = β − ν cos πτ, the small-amplitude limit of the
!> elastic coefficient (ν = α(1 − β/π²), eq. (21)); in hillstab's parameters α plays ν
!> and takes any finite value. Every quantity the methods need of this model is here,
!> without the damping shift −ε²/4 of eq. (47) (added by hillstab_hill_models, where the
!> models are registered): q, its exact segment means, the split q = c₀ + c₁ w with
!> w = cos πτ, w from sin(πτ/2), ∫₀¹ √|w|, auto's step-count inputs, the Fourier terms
!> of Hill's method and the two-piece values of the paper's eq. (A3).
!>
!>```fortran
!> print *, mathieu_coefficient(1.0_wp, 2.47_wp, 0.5_wp)   ! 2.47
!>```
module hillstab_hill_model_mathieu
   use hillstab_core_kinds, only: wp, pi, pi2
   implicit none
   private
   public :: mathieu_coefficient, mathieu_segment_mean, mathieu_split, mathieu_shape, mathieu_shapes_from_half_sines
   public :: mathieu_shape_root_mean, mathieu_auto_difficulty, mathieu_auto_amplitude
   public :: mathieu_hill_coupling, mathieu_two_piece_values

contains

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

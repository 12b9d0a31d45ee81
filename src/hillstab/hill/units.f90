!> Physical units ↔ the dimensionless parameters of the Hill equation (23).
!>
!> The pendulum: natural length r0 of the spring (m), gravity g (m/s²), radial angular
!> frequency ω = √(k/m) (rad/s), bounce amplitude a (m), damping rate κ (1/s) of the
!> Rayleigh dissipation (40)-(42). The paper's equations:
!>
!> - (4)  equilibrium length ρ = r0 + m g/k = r0 + g/ω²;
!> - (15) radial motion r(t) = ρ − a cos ωt (so a < ρ: the mass never reaches the pivot);
!> - (24) α = a π²/ρ, β = g π²/(ρ ω²), π τ = ω t; (23), (25) the Hill equation in τ;
!> - (21) the Mathieu limit's ν = a r0 π²/ρ² = α (1 − β/π²);
!> - (46) ε = κ π/ω.
!>
!> Back from (α, β, ε) two of r0, g and ω are needed (`physical_from_dimensionless`):
!> with r0, ρ = r0 π²/(π² − β) (as in the initial condition (38)); with g and ω,
!> ρ = g π²/(β ω²). Then a = α ρ/π², the third of r0, g, ω from (4) and (24), κ = ε ω/π.
!>
!> Time: τ = ω t/π, so a Floquet exponent μ per unit τ (the growth of the swing x
!> is ∝ e^{μτ}) is μ ω/π per second, and one radial period 2π/ω is 2 units of τ.
!>
!> Numerical code only: no files, no namelists.
!>
!>```fortran
!> type(physical_t) :: p
!> p = physical_t(r0=1.0_wp, g=9.81_wp, omega=5.0_wp, a=0.3_wp, kappa=0.0_wp)
!> print *, physical_alpha(p), physical_beta(p), physical_epsilon(p)
!> print *, rate_per_second(0.1_wp, p%omega)   ! μ = 0.1 per unit τ, in 1/s
!>```
module hillstab_hill_units
   use hillstab_core_kinds, only: wp, pi, pi2
   use hillstab_core_error, only: error_t, set_error, err_invalid_parameter
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   implicit none
   private
   public :: physical_t, standard_gravity, smallest_scale, largest_scale
   public :: equilibrium_length, physical_alpha, physical_beta, physical_epsilon, physical_nu, check_physical
   public :: physical_from_dimensionless, rate_per_second, tau_from_time, time_from_tau

   !> Standard gravity (m/s²), the default of g.
   real(wp), parameter :: standard_gravity = 9.80665_wp
   !> Bounds of a pendulum's scales (ω, r0, g, κ in SI units; also ρ in hillstab_pendulum_equations):
   !> within them no product of the model overflows or underflows to zero.
   real(wp), parameter :: smallest_scale = 1.0e-50_wp, largest_scale = 1.0e50_wp

   !> A pendulum in SI units.
   type :: physical_t
      real(wp) :: r0 = 1.0_wp                 !! natural length of the spring r0 (m)
      real(wp) :: g = standard_gravity        !! gravitational acceleration g (m/s²)
      real(wp) :: omega = 1.0_wp              !! radial angular frequency ω = √(k/m) (rad/s)
      real(wp) :: a = 0.0_wp                  !! amplitude a of the radial bounce (15) (m)
      real(wp) :: kappa = 0.0_wp              !! damping rate κ of (40)-(42) (1/s)
   end type physical_t

contains

   !> Equilibrium length ρ = r0 + g/ω², eq. (4) (m g/k = g/ω²).
   elemental real(wp) function equilibrium_length(p)
      type(physical_t), intent(in) :: p  !! the pendulum (ω > 0)
      equilibrium_length = p%r0 + p%g/(p%omega*p%omega)
   end function equilibrium_length

   !> α = a π²/ρ, eq. (24).
   elemental real(wp) function physical_alpha(p)
      type(physical_t), intent(in) :: p  !! the pendulum (ω > 0, ρ > 0)
      physical_alpha = p%a*pi2/equilibrium_length(p)
   end function physical_alpha

   !> β = g π²/(ρ ω²), eq. (24); written as π² (g/ω²)/(r0 + g/ω²) so that r0 = 0 gives π² exactly.
   elemental real(wp) function physical_beta(p)
      type(physical_t), intent(in) :: p  !! the pendulum (ω > 0, ρ > 0)
      real(wp) :: sag
      sag = p%g/(p%omega*p%omega)
      physical_beta = pi2*sag/(p%r0 + sag)
   end function physical_beta

   !> ν = a r0 π²/ρ², the amplitude of the Mathieu limit (21) q(τ) = β − ν cos πτ;
   !> equal to α (1 − β/π²).
   elemental real(wp) function physical_nu(p)
      type(physical_t), intent(in) :: p  !! the pendulum (ω > 0, ρ > 0)
      real(wp) :: rho
      rho = equilibrium_length(p)
      physical_nu = p%a*p%r0*pi2/(rho*rho)
   end function physical_nu

   !> ε = κ π/ω, eq. (46).
   elemental real(wp) function physical_epsilon(p)
      type(physical_t), intent(in) :: p  !! the pendulum (ω > 0)
      physical_epsilon = p%kappa*pi/p%omega
   end function physical_epsilon

   !> Check that a pendulum has a meaning: every value finite, ω > 0, r0 > 0, g ≥ 0,
   !> ρ > 0, 0 ≤ a < ρ (eq. (15): the mass stays away from the pivot), κ ≥ 0.
   !> On failure `variable` names the offending component (r0, g, omega, a or kappa).
   pure subroutine check_physical(p, error, variable)
      type(physical_t), intent(in) :: p  !! the pendulum (r0, g, omega, a, kappa)
      !> err_invalid_parameter saying what is wrong; unallocated when valid
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable, intent(out) :: variable  !! the bad component, "" when none
      character(len=:), allocatable :: message
      real(wp) :: rho
      variable = ""
      message = ""
      if (.not. ieee_is_finite(p%omega)) then
         variable = "omega"; message = "not a finite number"
      else if (.not. p%omega > 0.0_wp) then
         variable = "omega"; message = "the radial angular frequency must be > 0"
      else if (.not. ieee_is_finite(p%r0)) then
         variable = "r0"; message = "not a finite number"
      else if (.not. p%r0 > 0.0_wp) then
         variable = "r0"; message = "the natural length must be > 0"
      else if (.not. ieee_is_finite(p%g)) then
         variable = "g"; message = "not a finite number"
      else if (p%g < 0.0_wp) then
         variable = "g"; message = "gravity must be >= 0"
      else if (.not. ieee_is_finite(p%a)) then
         variable = "a"; message = "not a finite number"
      else if (.not. ieee_is_finite(p%kappa)) then
         variable = "kappa"; message = "not a finite number"
      else if (p%kappa < 0.0_wp) then
         variable = "kappa"; message = "the damping rate must be >= 0"
      else if (p%omega < smallest_scale .or. p%omega > largest_scale) then
         variable = "omega"; message = "must lie in [1e-50, 1e50] (rad/s): beyond, the model's scalings overflow"
      else if (p%r0 > largest_scale) then
         variable = "r0"; message = "must be <= 1e50 (m)"
      else if (p%g > largest_scale) then
         variable = "g"; message = "must be <= 1e50 (m/s^2)"
      else if (p%kappa > largest_scale) then
         variable = "kappa"; message = "must be <= 1e50 (1/s)"
      else
         rho = equilibrium_length(p)
         if (.not. (rho > 0.0_wp .and. ieee_is_finite(rho))) then
            variable = "r0"; message = "the equilibrium length rho = r0 + g/omega**2 of eq. (4) must be > 0 and finite"
         else if (p%a < 0.0_wp .or. p%a >= rho) then
            variable = "a"; message = "the amplitude must satisfy 0 <= a < rho = r0 + g/omega**2 (eq. (4), (15))"
         end if
      end if
      if (len(variable) > 0) call set_error(error, err_invalid_parameter, message)
   end subroutine check_physical

   !> The pendulum with the dimensionless parameters (α, β, ε), given two of r0, g and ω
   !> (exactly two): the inverse of `physical_alpha`, `physical_beta`, `physical_epsilon`.
   !> - ω and r0: ρ = r0 π²/(π² − β) (as in (38)), g = β ρ ω²/π²; needs 0 ≤ β < π²;
   !> - ω and g: ρ = g π²/(β ω²), r0 = ρ − g/ω² (4); needs 0 < β < π², g > 0;
   !> - r0 and g: ρ = r0 π²/(π² − β), ω² = g π²/(ρ β); needs 0 < β < π², g > 0.
   !> Then a = α ρ/π² and κ = ε ω/π. Needs 0 ≤ α < π², ε ≥ 0, ω > 0, r0 > 0, g ≥ 0, all
   !> finite; and, as `check_physical` bounds a pendulum, ω and r0 in [1e-50, 1e50], g = 0 or
   !> in [1e-50, 1e50], ε ≤ 1e50 and, with g given, β ≥ 1e-100: within these no value
   !> below overflows or divides by zero.
   pure subroutine physical_from_dimensionless(alpha, beta, epsilon, p, error, r0, g, omega)
      real(wp), intent(in) :: alpha    !! α of eq. (24)
      real(wp), intent(in) :: beta     !! β of eq. (24)
      real(wp), intent(in) :: epsilon  !! ε of eq. (46)
      type(physical_t), intent(out) :: p  !! the pendulum
      type(error_t), allocatable, intent(out) :: error  !! err_invalid_parameter when no pendulum has these values
      real(wp), intent(in), optional :: r0     !! natural length (m)
      real(wp), intent(in), optional :: g      !! gravity (m/s²)
      real(wp), intent(in), optional :: omega  !! radial angular frequency ω = √(k/m) (rad/s)
      real(wp), parameter :: smallest = smallest_scale, largest = largest_scale
      real(wp) :: rho
      if (count([present(r0), present(g), present(omega)]) /= 2) then
         call set_error(error, err_invalid_parameter, "give exactly two of r0, g and omega")
         return
      end if
      if (.not. (alpha >= 0.0_wp .and. alpha < pi2)) then
         call set_error(error, err_invalid_parameter, "alpha must satisfy 0 <= alpha < pi**2")
         return
      end if
      if (.not. (epsilon >= 0.0_wp .and. ieee_is_finite(epsilon) .and. ieee_is_finite(beta))) then
         call set_error(error, err_invalid_parameter, "epsilon must be finite and >= 0, beta finite")
         return
      end if
      if (epsilon > largest) then
         call set_error(error, err_invalid_parameter, "epsilon must be <= 1e50")
         return
      end if
      if (beta < 0.0_wp) then
         call set_error(error, err_invalid_parameter, "beta must be >= 0 (g >= 0)")
         return
      end if
      if (present(omega)) then
         if (.not. (omega > 0.0_wp .and. ieee_is_finite(omega))) then
            call set_error(error, err_invalid_parameter, "omega must be finite and > 0")
            return
         end if
         if (omega < smallest .or. omega > largest) then
            call set_error(error, err_invalid_parameter, "omega must lie in [1e-50, 1e50] (rad/s)")
            return
         end if
      end if
      if (present(r0)) then
         if (.not. (r0 > 0.0_wp .and. ieee_is_finite(r0))) then
            call set_error(error, err_invalid_parameter, "r0 must be finite and > 0")
            return
         end if
         if (r0 < smallest .or. r0 > largest) then
            call set_error(error, err_invalid_parameter, "r0 must lie in [1e-50, 1e50] (m)")
            return
         end if
         if (.not. beta < pi2) then
            call set_error(error, err_invalid_parameter, "with r0 given, beta < pi**2 is needed (r0 > 0)")
            return
         end if
         rho = r0*pi2/(pi2 - beta)
         p%r0 = r0
      end if
      if (present(g)) then
         if (.not. (g >= 0.0_wp .and. ieee_is_finite(g))) then
            call set_error(error, err_invalid_parameter, "g must be finite and >= 0")
            return
         end if
         if (g > largest .or. (g > 0.0_wp .and. g < smallest)) then
            call set_error(error, err_invalid_parameter, "g must be 0 or lie in [1e-50, 1e50] (m/s^2)")
            return
         end if
         if (.not. beta > 0.0_wp) then
            call set_error(error, err_invalid_parameter, "with g given, beta > 0 is needed")
            return
         end if
         if (beta < 1.0e-100_wp) then
            call set_error(error, err_invalid_parameter, "with g given, beta >= 1e-100 is needed (smaller values "// &
               "overflow rho or omega)")
            return
         end if
         p%g = g
      end if
      if (present(omega)) then
         p%omega = omega
         if (present(r0)) then
            p%g = beta*rho*omega*omega/pi2
         else
            if (.not. (g > 0.0_wp .and. beta < pi2)) then
               call set_error(error, err_invalid_parameter, "with omega and g given, g > 0 and beta < pi**2 are "// &
                  "needed (r0 = rho - g/omega**2 > 0)")
               return
            end if
            rho = g*pi2/(beta*omega*omega)
            p%r0 = rho - g/(omega*omega)
            if (.not. p%r0 > 0.0_wp) then
               call set_error(error, err_invalid_parameter, "beta is too close to pi**2: r0 = rho - g/omega**2 "// &
                  "cancels to <= 0")
               return
            end if
         end if
      else
         if (.not. g > 0.0_wp) then
            call set_error(error, err_invalid_parameter, "with r0 and g given, g > 0 is needed")
            return
         end if
         p%omega = sqrt(g*pi2/(rho*beta))
      end if
      p%a = alpha*rho/pi2
      p%kappa = epsilon*p%omega/pi
   end subroutine physical_from_dimensionless

   !> A rate per unit τ (a Floquet exponent μ) in 1/s: μ ω/π, since τ = ω t/π (24).
   elemental real(wp) function rate_per_second(rate_per_tau, omega)
      real(wp), intent(in) :: rate_per_tau  !! rate per unit τ
      real(wp), intent(in) :: omega         !! ω (rad/s)
      rate_per_second = rate_per_tau*omega/pi
   end function rate_per_second

   !> τ = ω t/π, eq. (24).
   elemental real(wp) function tau_from_time(t, omega)
      real(wp), intent(in) :: t      !! time (s)
      real(wp), intent(in) :: omega  !! ω (rad/s)
      tau_from_time = omega*t/pi
   end function tau_from_time

   !> t = π τ/ω, eq. (24).
   elemental real(wp) function time_from_tau(tau, omega)
      real(wp), intent(in) :: tau    !! dimensionless time τ
      real(wp), intent(in) :: omega  !! ω (rad/s), > 0
      time_from_tau = pi*tau/omega
   end function time_from_tau
end module hillstab_hill_units

!> Tests of the physical ↔ dimensionless conversions: the Hill coefficient of eq. (25)
!> with the converted (α, β, ε) must be the physical coefficient of eqs. (20), (46)
!> rescaled to τ; round trips through both inverse routes; the special values r0 = 0
!> (β = π²) and g = 0 (β = 0); and bad pendulums naming the bad component.
module test_units
   use hillstab_core_kinds, only: wp, pi, pi2
   use hillstab_core_error, only: error_t
   use hillstab_hill_units
   use hillstab_pendulum_equations, only: pendulum_t, pendulum_from_chart
   use hillstab_testing
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use hillstab_hill_model, only: hill_model_t, hill_point_t, hill_coefficient
   use hillstab_hill_model_elastic, only: elastic_model_t
   use hillstab_test_models, only: model_of_code
   implicit none
   private
   public :: collect_units

contains

   function collect_units() result(suite)
      type(testsuite_t) :: suite
      suite = new_testsuite("units", [ &
         new_unittest("coefficient_in_seconds", coefficient_in_seconds), &
         new_unittest("round_trips", round_trips), &
         new_unittest("special_values", special_values), &
         new_unittest("rates_and_times", rates_and_times), &
         new_unittest("bad_pendulums", bad_pendulums), &
         new_unittest("inverse_bounds", inverse_bounds)])
   end function collect_units

   !> (ω/π)² Q(ωt/π) = (g − a ω² cos ωt)/(ρ − a cos ωt) − κ²/4: eq. (20) with the damping
   !> shift of eq. (46), computed from the physical values alone.
   subroutine coefficient_in_seconds(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(physical_t) :: pendulums(3)
      type(physical_t) :: p
      class(hill_model_t), pointer :: model
      type(hill_point_t) :: point
      real(wp) :: t, rho, physical_q, scaled_q
      integer :: k, i
      pendulums = [physical_t(r0=1.0_wp, g=9.81_wp, omega=5.0_wp, a=0.3_wp, kappa=0.0_wp), &
                   physical_t(r0=0.2_wp, g=9.81_wp, omega=12.0_wp, a=0.2649_wp, kappa=0.7_wp), &
                   physical_t(r0=3.0_wp, g=1.62_wp, omega=0.9_wp, a=4.5_wp, kappa=0.05_wp)]
      do k = 1, size(pendulums)
         p = pendulums(k)
         rho = p%r0 + p%g/p%omega**2
         model => model_of_code(1)
         point = hill_point_t(physical_alpha(p), physical_beta(p), physical_epsilon(p))
         do i = 0, 12
            t = 0.37_wp*i/p%omega
            physical_q = (p%g - p%a*p%omega**2*cos(p%omega*t))/(rho - p%a*cos(p%omega*t)) - 0.25_wp*p%kappa**2
            scaled_q = (p%omega/pi)**2*hill_coefficient(model, point, tau_from_time(t, p%omega))
            call check(ctx, scaled_q, physical_q, rel=1.0e-12_wp, abs=1.0e-12_wp*p%omega**2)
         end do
      end do
   end subroutine coefficient_in_seconds

   !> physical → (α, β, ε) → physical, through r0 and through g.
   subroutine round_trips(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(physical_t) :: p, back
      type(error_t), allocatable :: error
      p = physical_t(r0=0.45_wp, g=9.81_wp, omega=7.0_wp, a=0.5_wp, kappa=0.3_wp)
      call physical_from_dimensionless(physical_alpha(p), physical_beta(p), physical_epsilon(p), back, &
                                       error, r0=p%r0, omega=p%omega)
      call check(ctx, .not. allocated(error), "r0 route")
      call check(ctx, back%g, p%g, rel=1.0e-14_wp)
      call check(ctx, back%a, p%a, rel=1.0e-14_wp)
      call check(ctx, back%kappa, p%kappa, rel=1.0e-14_wp)
      call physical_from_dimensionless(physical_alpha(p), physical_beta(p), physical_epsilon(p), back, &
                                       error, g=p%g, omega=p%omega)
      call check(ctx, .not. allocated(error), "g route")
      call check(ctx, back%r0, p%r0, rel=1.0e-13_wp)
      call check(ctx, back%a, p%a, rel=1.0e-14_wp)
      call physical_from_dimensionless(physical_alpha(p), physical_beta(p), physical_epsilon(p), back, &
                                       error, r0=p%r0, g=p%g)
      call check(ctx, .not. allocated(error), "r0, g route")
      call check(ctx, back%omega, p%omega, rel=1.0e-14_wp)
      call check(ctx, back%a, p%a, rel=1.0e-14_wp)
      call check(ctx, back%kappa, p%kappa, rel=1.0e-14_wp)
      call same_as_pendulum_module(ctx, 1.48_wp, 2.47_wp, 0.3_wp, 0.1_wp, 9.81_wp)
      call same_as_pendulum_module(ctx, 9.5_wp, 0.2_wp, 0.0_wp, 2.0_wp, 1.62_wp)
      ! the paper's Fig. 4 (a): alpha = 1.48, beta = 2.47 with r0 = 1 m, omega = 10 rad/s
      call physical_from_dimensionless(1.48_wp, 2.47_wp, 0.0_wp, back, error, r0=1.0_wp, omega=10.0_wp)
      call check(ctx, .not. allocated(error), "Fig. 4 (a)")
      call check(ctx, equilibrium_length(back), pi2/(pi2 - 2.47_wp), rel=1.0e-14_wp)  ! eq. (38)
      call check(ctx, physical_alpha(back), 1.48_wp, rel=1.0e-14_wp)
      call check(ctx, physical_beta(back), 2.47_wp, rel=1.0e-14_wp)
      ! exactly two of r0, g and omega
      call physical_from_dimensionless(1.0_wp, 2.0_wp, 0.0_wp, back, error, omega=1.0_wp)
      call check(ctx, allocated(error), "omega alone")
      call physical_from_dimensionless(1.0_wp, 2.0_wp, 0.0_wp, back, error, r0=1.0_wp, g=9.8_wp, omega=1.0_wp)
      call check(ctx, allocated(error), "all three")
      call physical_from_dimensionless(1.0_wp, pi2, 0.0_wp, back, error, r0=1.0_wp, omega=1.0_wp)
      call check(ctx, allocated(error), "beta = pi**2 has no finite rho for r0 > 0")
      call physical_from_dimensionless(1.0_wp, 0.0_wp, 0.0_wp, back, error, g=9.8_wp, omega=1.0_wp)
      call check(ctx, allocated(error), "beta = 0 has no finite rho for g > 0")
   end subroutine round_trips

   !> The r0, g route against hillstab_pendulum_equations's own conversion (written separately).
   subroutine same_as_pendulum_module(ctx, alpha, beta, epsilon, r0, g)
      type(test_context_t), intent(inout) :: ctx
      real(wp), intent(in) :: alpha, beta, epsilon, r0, g
      type(pendulum_t) :: q
      type(physical_t) :: p
      type(error_t), allocatable :: error
      call pendulum_from_chart(alpha, beta, epsilon, r0, g, q, error)
      call check(ctx, .not. allocated(error), "pendulum_from_chart")
      call physical_from_dimensionless(alpha, beta, epsilon, p, error, r0=r0, g=g)
      call check(ctx, .not. allocated(error), "physical_from_dimensionless")
      if (allocated(error)) return
      call check(ctx, p%omega, q%omega, rel=1.0e-14_wp, message="omega")
      call check(ctx, p%a, q%a, rel=1.0e-14_wp, message="a")
      call check(ctx, p%kappa, q%kappa, rel=1.0e-14_wp, abs=0.0_wp, message="kappa")
      call check(ctx, equilibrium_length(p), q%rho, rel=1.0e-14_wp, message="rho")
   end subroutine same_as_pendulum_module

   !> r0 = 0: β = π² exactly (isotropic oscillator); g = 0: β = 0; a = 0: α = 0.
   subroutine special_values(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(physical_t) :: p
      p = physical_t(r0=0.0_wp, g=9.81_wp, omega=3.0_wp, a=0.5_wp, kappa=0.0_wp)
      call check(ctx, physical_beta(p), pi2, rel=0.0_wp, abs=0.0_wp)
      call check(ctx, equilibrium_length(p), 9.81_wp/9.0_wp, rel=1.0e-15_wp)
      p = physical_t(r0=2.0_wp, g=0.0_wp, omega=3.0_wp, a=1.0_wp, kappa=0.0_wp)
      call check(ctx, physical_beta(p), 0.0_wp, abs=0.0_wp)
      call check(ctx, physical_alpha(p), pi2/2.0_wp, rel=1.0e-15_wp)
      call check(ctx, physical_epsilon(physical_t(omega=2.0_wp, kappa=4.0_wp)), 2.0_wp*pi, rel=1.0e-15_wp)
      ! nu of eq. (21) is alpha (1 - beta/pi**2)
      p = physical_t(r0=0.7_wp, g=9.81_wp, omega=4.0_wp, a=0.6_wp, kappa=0.0_wp)
      call check(ctx, physical_nu(p), physical_alpha(p)*(1.0_wp - physical_beta(p)/pi2), rel=1.0e-14_wp)
   end subroutine special_values

   !> τ = ω t/π: one radial period 2π/ω is 2 units of τ; e^{μ τ} = e^{(μ ω/π) t}.
   subroutine rates_and_times(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp) :: omega, mu, t
      omega = 6.5_wp
      call check(ctx, tau_from_time(2.0_wp*pi/omega, omega), 2.0_wp, rel=1.0e-15_wp)
      call check(ctx, time_from_tau(2.0_wp, omega), 2.0_wp*pi/omega, rel=1.0e-15_wp)
      mu = 0.137_wp
      t = 3.3_wp
      call check(ctx, rate_per_second(mu, omega)*t, mu*tau_from_time(t, omega), rel=1.0e-15_wp)
      ! growth over one radial period: |lambda_max| = e^{2 mu} per period, period 2 pi/omega seconds
      call check(ctx, exp(rate_per_second(mu, omega)*2.0_wp*pi/omega), exp(2.0_wp*mu), rel=1.0e-14_wp)
   end subroutine rates_and_times

   subroutine bad_pendulums(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(physical_t) :: cases(8)
      character(len=5) :: names(8)
      type(error_t), allocatable :: error
      character(len=:), allocatable :: variable
      real(wp) :: zero
      integer :: k
      zero = 0.0_wp
      cases = [physical_t(omega=0.0_wp), physical_t(omega=-1.0_wp), physical_t(r0=-0.1_wp), &
               physical_t(g=-9.8_wp), physical_t(a=-0.1_wp), physical_t(r0=1.0_wp, g=9.8_wp, omega=1.0_wp, a=10.8_wp), &
               physical_t(kappa=-1.0_wp), physical_t(r0=0.0_wp)]
      names = [character(len=5) :: "omega", "omega", "r0", "g", "a", "a", "kappa", "r0"]
      do k = 1, size(cases)
         call check_physical(cases(k), error, variable)
         call check(ctx, allocated(error), "bad pendulum "//trim(names(k)))
         call check(ctx, variable == trim(names(k)), "names "//trim(names(k))//", got "//variable)
      end do
      call check_physical(physical_t(r0=1.0_wp, g=9.8_wp, omega=1.0_wp, a=10.79_wp), error, variable)
      call check(ctx, .not. allocated(error) .and. variable == "", "a just below rho")
   end subroutine bad_pendulums

   !> physical_from_dimensionless refuses what has no pendulum (it returned r0 <= 0, g < 0,
   !> or an infinite omega or kappa without an error) and stays finite at the edges it accepts.
   subroutine inverse_bounds(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(physical_t) :: p
      type(error_t), allocatable :: error
      call physical_from_dimensionless(1.0_wp, 1.5_wp*pi2, 0.0_wp, p, error, g=9.8_wp, omega=2.0_wp)
      call check(ctx, allocated(error), "omega, g: beta > pi**2 gives r0 < 0")
      call physical_from_dimensionless(1.0_wp, 2.0_wp, 0.0_wp, p, error, g=0.0_wp, omega=1.0_wp)
      call check(ctx, allocated(error), "omega, g: g = 0 gives r0 = 0")
      call physical_from_dimensionless(1.0_wp, -1.0_wp, 0.0_wp, p, error, r0=1.0_wp, omega=1.0_wp)
      call check(ctx, allocated(error), "r0, omega: beta < 0 gives g < 0")
      call physical_from_dimensionless(1.0_wp, 1.0e-200_wp, 0.0_wp, p, error, r0=1.0_wp, g=9.8_wp)
      call check(ctx, allocated(error), "r0, g: beta = 1e-200 overflows omega")
      call physical_from_dimensionless(1.0_wp, 2.0_wp, 1.0e300_wp, p, error, r0=1.0_wp, omega=1.0e10_wp)
      call check(ctx, allocated(error), "epsilon = 1e300 overflows kappa")
      call physical_from_dimensionless(1.0_wp, 2.0_wp, 0.0_wp, p, error, r0=1.0e-60_wp, omega=1.0_wp)
      call check(ctx, allocated(error), "r0 below 1e-50")
      ! the edges accepted: every component finite, and back to (alpha, beta, epsilon)
      call physical_from_dimensionless(1.0_wp, 1.0e-100_wp, 1.0e50_wp, p, error, r0=1.0e-50_wp, g=1.0e50_wp)
      call check(ctx, .not. allocated(error), "r0, g at the edges")
      call check(ctx, all(ieee_is_finite([p%r0, p%g, p%omega, p%a, p%kappa])), "finite at the edges")
      call check(ctx, physical_beta(p), 1.0e-100_wp, rel=1.0e-13_wp)
      call check(ctx, physical_epsilon(p), 1.0e50_wp, rel=1.0e-14_wp)
      call physical_from_dimensionless(9.8_wp, 1.0e-100_wp, 0.0_wp, p, error, g=1.0e-50_wp, omega=1.0e-50_wp)
      call check(ctx, .not. allocated(error), "omega, g at the edges")
      call check(ctx, all(ieee_is_finite([p%r0, p%g, p%omega, p%a, p%kappa])), "finite at the edges (omega, g)")
      call check(ctx, physical_alpha(p), 9.8_wp, rel=1.0e-13_wp)
      call physical_from_dimensionless(0.0_wp, 0.0_wp, 0.0_wp, p, error, r0=1.0_wp, omega=2.0_wp)
      call check(ctx, .not. allocated(error) .and. p%g == 0.0_wp, "r0, omega: beta = 0 is g = 0")
   end subroutine inverse_bounds
end module test_units

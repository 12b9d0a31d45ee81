!> Tests of the nonlinear pendulum model (hillstab_pendulum_equations) against independent
!> references: the defining relations of ρ, ω, a; the closed-form energy (C1); the exact
!> bounce solution; energy conservation; monotone energy loss with damping; the Jacobian
!> against central differences; and the swing block of the 4×4 variational monodromy
!> along the bounce against the core's trace S (GSL rk8pd on the Hill equation).
module test_pendulum
   use hillstab_core_kinds, only: wp, pi, pi2
   use hillstab_core_error, only: error_t
   use hillstab_core_stats, only: work_stats_t
   use hillstab_hill_transfer, only: trace_t
   use hillstab_integrate_monodromy, only: monodromy_trace, method_t, method_gsl
   use hillstab_integrate_rk, only: rk_options_t, rk_integrate, rk_dop853, rk_step_t
   use hillstab_pendulum_equations
   use hillstab_pendulum_gsl, only: pendulum_gsl
   use hillstab_testing
   use hillstab_test_pendulum, only: pendulum_at
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use hillstab_hill_model, only: hill_point_t
   use hillstab_hill_model_elastic, only: elastic_model_t
   implicit none
   private
   public :: collect_pendulum

   !> The pendulum with an observer that records the energy at every accepted step.
   type, extends(pendulum_system_t) :: energy_samples_t
      integer :: n = 0
      real(wp), allocatable :: energy(:)
   contains
      procedure :: observe => record_energy
   end type energy_samples_t

contains

   function collect_pendulum() result(suite)
      type(testsuite_t) :: suite
      suite = new_testsuite("pendulum", [ &
         new_unittest("parameters", parameters), &
         new_unittest("invalid_parameters", invalid_parameters), &
         new_unittest("extreme_parameters", extreme_parameters), &
         new_unittest("energy_closed_form", energy_closed_form), &
         new_unittest("exact_bounce", exact_bounce), &
         new_unittest("energy_conserved", energy_conserved), &
         new_unittest("damped_energy_decreases", damped_energy_decreases), &
         new_unittest("jacobian_differences", jacobian_differences), &
         new_unittest("swing_block_trace", swing_block_trace), &
         new_unittest("dop853_vs_gsl_rk8pd", dop853_vs_gsl_rk8pd)])
   end function collect_pendulum

   subroutine record_energy(self, step, stop)
      class(energy_samples_t), intent(inout) :: self
      type(rk_step_t), intent(in) :: step
      logical, intent(inout) :: stop
      real(wp), allocatable :: grown(:)
      if (.not. allocated(self%energy)) allocate (self%energy(1024))
      if (self%n == size(self%energy)) then
         allocate (grown(2*self%n))
         grown(1:self%n) = self%energy
         call move_alloc(grown, self%energy)
      end if
      self%n = self%n + 1
      self%energy(self%n) = pendulum_energy(self%pendulum, step%y)
   end subroutine record_energy

   !> ρ = r0 + g/ω² (equilibrium of the spring), β = gπ²/(ρω²), α = aπ²/ρ, T ω = 2π, κ = εω/π.
   subroutine parameters(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(pendulum_t) :: p
      p = pendulum_at(7.88_wp, 3.95_wp, 0.3_wp)
      call check(ctx, p%rho, p%r0 + p%g/p%omega**2, rel=1.0e-14_wp, message="rho = r0 + g/omega**2")
      call check(ctx, p%g*pi2/(p%rho*p%omega**2), 3.95_wp, rel=1.0e-14_wp, message="beta")
      call check(ctx, p%a*pi2/p%rho, 7.88_wp, rel=1.0e-14_wp, message="alpha")
      call check(ctx, p%period*p%omega, 2.0_wp*pi, rel=1.0e-15_wp, message="T omega = 2 pi")
      call check(ctx, p%kappa*pi/p%omega, 0.3_wp, rel=1.0e-15_wp, message="kappa")
      ! the 4/3 pendulum: β = π²/4 means ρ/r0 = 4/3
      p = pendulum_at(1.0_wp, pi2/4.0_wp, 0.0_wp)
      call check(ctx, p%rho/p%r0, 4.0_wp/3.0_wp, rel=1.0e-15_wp, message="4/3 pendulum")
   end subroutine parameters

   subroutine invalid_parameters(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(pendulum_t) :: p
      type(error_t), allocatable :: error
      call pendulum_from_chart(pi2, 2.0_wp, 0.0_wp, 0.1_wp, 9.81_wp, p, error)
      call check(ctx, allocated(error), "alpha = pi**2 rejected")
      call pendulum_from_chart(-0.1_wp, 2.0_wp, 0.0_wp, 0.1_wp, 9.81_wp, p, error)
      call check(ctx, allocated(error), "alpha < 0 rejected")
      call pendulum_from_chart(1.0_wp, 0.0_wp, 0.0_wp, 0.1_wp, 9.81_wp, p, error)
      call check(ctx, allocated(error), "beta = 0 rejected")
      call pendulum_from_chart(1.0_wp, pi2, 0.0_wp, 0.1_wp, 9.81_wp, p, error)
      call check(ctx, allocated(error), "beta = pi**2 rejected")
      call pendulum_from_chart(1.0_wp, 2.0_wp, -1.0_wp, 0.1_wp, 9.81_wp, p, error)
      call check(ctx, allocated(error), "epsilon < 0 rejected")
      call pendulum_from_chart(1.0_wp, 2.0_wp, 0.0_wp, 0.0_wp, 9.81_wp, p, error)
      call check(ctx, allocated(error), "r0 = 0 rejected")
      call pendulum_from_chart(1.0_wp, 2.0_wp, 0.0_wp, 0.1_wp, -9.81_wp, p, error)
      call check(ctx, allocated(error), "g < 0 rejected")
      if (allocated(error)) call check(ctx, index(error%message, "g must") > 0, "message names g")
   end subroutine invalid_parameters

   !> Parameters inside the domain whose derived scales would overflow are refused before
   !> anything is computed (a trapping build would stop otherwise); the scene reader's
   !> smallest beta still gives a pendulum.
   subroutine extreme_parameters(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(pendulum_t) :: p
      type(error_t), allocatable :: error
      real(wp) :: rho
      call pendulum_from_chart(1.0_wp, 1.0e-300_wp, 0.0_wp, 0.1_wp, 9.81_wp, p, error)
      call check(ctx, allocated(error), "beta = 1e-300 (omega ~ 3e151) refused")
      if (allocated(error)) call check(ctx, index(error%message, "out of range") > 0, "message says out of range")
      call pendulum_from_chart(1.0_wp, 1.0e-320_wp, 0.0_wp, 0.1_wp, 9.81_wp, p, error)
      call check(ctx, allocated(error), "beta = 1e-320 (omega**2 overflows) refused")
      call pendulum_from_chart(1.0_wp, 2.0_wp, 0.0_wp, 1.0e308_wp, 9.81_wp, p, error)
      call check(ctx, allocated(error), "r0 = 1e308 (rho overflows) refused")
      call pendulum_from_chart(1.0_wp, 2.0_wp, 0.0_wp, 1.0e-300_wp, 9.81_wp, p, error)
      call check(ctx, allocated(error), "r0 = 1e-300 refused")
      call pendulum_from_chart(1.0_wp, 2.0_wp, 1.0e300_wp, 0.1_wp, 9.81_wp, p, error)
      call check(ctx, allocated(error), "epsilon = 1e300 (kappa ~ 1e301) refused")
      call pendulum_from_chart(1.0_wp, 1.0e-8_wp, 0.0_wp, 0.1_wp, 9.81_wp, p, error)
      call check(ctx, .not. allocated(error), "beta = 1e-8 accepted")
      rho = 0.1_wp*pi2/(pi2 - 1.0e-8_wp)
      call check(ctx, p%omega, sqrt(9.81_wp*pi2/(rho*1.0e-8_wp)), rel=1.0e-15_wp)
   end subroutine extreme_parameters

   !> E(0) at φ0 = 0 equals (C1): ½ ω² r0² (β² + α² − 2βπ²)/(π² − β)² per unit mass.
   subroutine energy_closed_form(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(pendulum_t) :: p
      real(wp) :: points(2, 4), closed
      integer :: i
      points = reshape([1.48_wp, 2.47_wp, 5.0_wp, 0.76_wp, 7.88_wp, 3.95_wp, 9.8_wp, 8.0_wp], [2, 4])
      do i = 1, size(points, 2)
         p = pendulum_at(points(1, i), points(2, i), 0.0_wp)
         closed = 0.5_wp*p%omega**2*p%r0**2*(p%beta**2 + p%alpha**2 - 2.0_wp*p%beta*pi2)/(pi2 - p%beta)**2
         call check(ctx, pendulum_energy(p, pendulum_initial_state(p, 0.0_wp)), closed, rel=1.0e-13_wp, &
            message="energy (C1)")
      end do
   end subroutine energy_closed_form

   !> From φ0 = 0 the integration follows x ≡ 0, z = ρ − a cos ωt (eq. (15)) over 5 periods.
   subroutine exact_bounce(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(pendulum_system_t) :: system
      type(rk_options_t) :: options
      type(error_t), allocatable :: error
      real(wp) :: t, y(4), t_out(50), y_out(4, 50), worst
      integer :: j
      system%pendulum = pendulum_at(9.5_wp, 2.47_wp, 0.0_wp)
      associate (p => system%pendulum)
         y = pendulum_initial_state(p, 0.0_wp)
         call check(ctx, maxval(abs(y - pendulum_bounce(p, 0.0_wp))), 0.0_wp, abs=1.0e-16_wp, &
            message="initial state is the bounce at t = 0")
         t_out = [(5*p%period*j/50.0_wp, j=1, 50)]
         options = rk_options_t(method=rk_dop853, rtol=1.0e-12_wp)
         options%atol_components = pendulum_atol(p, y, 1.0e-12_wp)
         t = 0.0_wp
         call rk_integrate(system, t, 5*p%period, y, options, error=error, t_out=t_out, y_out=y_out)
         call check(ctx, .not. allocated(error), "integration succeeds")
         worst = 0.0_wp
         do j = 1, 50
            worst = max(worst, maxval(abs(y_out(:, j) - pendulum_bounce(p, t_out(j)))/[1.0_wp, 1.0_wp, p%omega, p%omega])/p%rho)
         end do
         write (*, '(4x,a,es10.3)') "alpha = 9.5 bounce, 5 periods: max |y - exact| (velocities / omega) / rho = ", worst
         call check(ctx, worst < 1.0e-9_wp, "z follows rho - a cos(omega t)")
         call check(ctx, all(y_out(px, :) == 0.0_wp) .and. all(y_out(pvx, :) == 0.0_wp), "x stays exactly 0")
      end associate
   end subroutine exact_bounce

   !> ε = 0, tolerance 1e-12: relative energy drift over 50 radial periods below 1e-10
   !> (relative to the energy scale ½|v|² + ½ω²(r − r0)² + g|z| at the start).
   subroutine energy_conserved(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(energy_samples_t) :: system
      type(rk_options_t) :: options
      type(error_t), allocatable :: error
      real(wp) :: t, y(4), e0, drift, points(3, 3)
      integer :: i
      ! (α, β, φ0): Fig. 4 (a), (e) and a large initial angle
      points = reshape([1.48_wp, 2.47_wp, 0.017_wp, 7.88_wp, 3.95_wp, 0.017_wp, 5.0_wp, 0.76_wp, 1.5_wp], [3, 3])
      do i = 1, size(points, 2)
         system = energy_samples_t()
         system%pendulum = pendulum_at(points(1, i), points(2, i), 0.0_wp)
         y = pendulum_initial_state(system%pendulum, points(3, i))
         e0 = pendulum_energy(system%pendulum, y)
         options = rk_options_t(method=rk_dop853, rtol=1.0e-12_wp, max_steps=10**7)
         options%atol_components = pendulum_atol(system%pendulum, y, 1.0e-12_wp)
         t = 0.0_wp
         call rk_integrate(system, t, 50*system%pendulum%period, y, options, error=error)
         call check(ctx, .not. allocated(error), "integration succeeds")
         drift = maxval(abs(system%energy(1:system%n) - e0))/pendulum_energy_scale(system%pendulum, &
            pendulum_initial_state(system%pendulum, points(3, i)))
         write (*, '(4x,a,f5.2,a,f5.2,a,f6.3,a,es10.3)') "alpha=", points(1, i), " beta=", points(2, i), &
            " phi0=", points(3, i), ": max relative energy drift over 50 periods ", drift
         call check(ctx, drift < 1.0e-10_wp, "energy drift < 1e-10")
      end do
   end subroutine energy_conserved

   !> ε > 0: the energy decreases monotonically along the accepted steps (dE/dt = −κ|v|² ≤ 0),
   !> up to the round-off of E (a few ulps of the energy scale) once it has settled.
   subroutine damped_energy_decreases(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(energy_samples_t) :: system
      type(rk_options_t) :: options
      type(error_t), allocatable :: error
      real(wp) :: t, y(4), eps(2) = [0.05_wp, 3.0_wp], noise
      integer :: i
      do i = 1, 2
         system = energy_samples_t()
         system%pendulum = pendulum_at(7.88_wp, 3.95_wp, eps(i))
         y = pendulum_initial_state(system%pendulum, 0.3_wp)
         options = rk_options_t(method=rk_dop853, rtol=1.0e-12_wp)
         options%atol_components = pendulum_atol(system%pendulum, y, 1.0e-12_wp)
         noise = 16*epsilon(1.0_wp)*pendulum_energy_scale(system%pendulum, y)
         t = 0.0_wp
         call rk_integrate(system, t, 20*system%pendulum%period, y, options, error=error)
         call check(ctx, .not. allocated(error), "integration succeeds")
         write (*, '(4x,a,f5.2,a,es10.3,a,i0)') "epsilon=", eps(i), ": largest increase between steps ", &
            maxval(system%energy(2:system%n) - system%energy(1:system%n - 1)), " of ", system%n
         call check(ctx, all(system%energy(2:system%n) <= system%energy(1:system%n - 1) + noise), &
            "energy never increases")
         call check(ctx, system%energy(system%n) < system%energy(1), "energy decreases")
      end do
   end subroutine damped_energy_decreases

   !> J against central differences of the right-hand side at a generic state.
   subroutine jacobian_differences(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(pendulum_t) :: p
      real(wp) :: y(4), jac(4, 4), fd(4, 4), fp(4), fm(4), h, yh(4)
      integer :: j
      p = pendulum_at(5.0_wp, 2.0_wp, 0.4_wp)
      y = [0.03_wp, 0.11_wp, -0.2_wp, 0.5_wp]
      jac = pendulum_jacobian(p, y)
      do j = 1, 4
         h = 1.0e-6_wp*max(abs(y(j)), 0.01_wp)
         yh = y; yh(j) = y(j) + h
         call pendulum_rhs(p, yh, fp)
         yh(j) = y(j) - h
         call pendulum_rhs(p, yh, fm)
         fd(:, j) = (fp - fm)/(2.0_wp*h)
      end do
      call check(ctx, maxval(abs(jac - fd))/maxval(abs(jac)) < 1.0e-8_wp, "Jacobian = central differences")
   end subroutine jacobian_differences

   !> The swing block of the 4×4 variational monodromy along the bounce has trace S of the
   !> core (GSL rk8pd on the Hill equation), the radial block is the identity (harmonic
   !> oscillator over one period), and the two blocks do not couple.
   subroutine swing_block_trace(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp) :: points(2, 6), m(4, 4), s_pendulum
      type(pendulum_t) :: p
      type(trace_t) :: core
      type(work_stats_t) :: stats
      type(error_t), allocatable :: error
      integer :: i
      ! stable (a few) and unstable points, up to α = 9.5
      points = reshape([1.48_wp, 2.47_wp, 3.7_wp, 2.47_wp, 2.57_wp, 1.29_wp, 5.0_wp, 0.76_wp, &
                        7.88_wp, 3.95_wp, 9.5_wp, 2.47_wp], [2, 6])
      do i = 1, size(points, 2)
         p = pendulum_at(points(1, i), points(2, i), 0.0_wp)
         call pendulum_bounce_monodromy(p, 1.0e-13_wp, m, stats, error)
         call check(ctx, .not. allocated(error), "monodromy succeeds")
         call monodromy_trace(elastic_model_t(), hill_point_t(p%alpha, p%beta, 0.0_wp), &
                              method_t(method_gsl, tolerance=1.0e-13_wp), core, error)
         call check(ctx, .not. allocated(error), "core trace succeeds")
         s_pendulum = m(px, px) + m(pvx, pvx)
         write (*, '(4x,a,f5.2,a,f5.2,a,es22.14,a,es22.14)') "alpha=", p%alpha, " beta=", p%beta, &
            ": swing-block trace ", s_pendulum, ", core S ", core%value
         ! measured: at most 2.5e-13 relative
         call check(ctx, s_pendulum, core%value, abs=1.0e-10_wp*max(1.0_wp, abs(core%value)), &
            message="swing trace = S")
         call check(ctx, maxval(abs(m([pz, pvz], [pz, pvz]) - reshape([1.0_wp, 0.0_wp, 0.0_wp, 1.0_wp], [2, 2]))) &
            < 1.0e-9_wp*p%omega, "radial block = identity")
         call check(ctx, all(m([px, pvx], [pz, pvz]) == 0.0_wp) .and. all(m([pz, pvz], [px, pvx]) == 0.0_wp), &
            "blocks decouple")
      end do
   end subroutine swing_block_trace

   !> A second method: GSL rk8pd on the same equations agrees with DOP853 after 5 radial
   !> periods of Fig. 4 (e) (chaotic later on: see the speed benchmark) and of (c).
   subroutine dop853_vs_gsl_rk8pd(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(pendulum_system_t) :: system
      type(rk_options_t) :: options
      type(work_stats_t) :: stats
      type(error_t), allocatable :: error
      real(wp) :: t, y(4), y_gsl(4), points(2, 2), difference, drift, end_drift
      type(work_stats_t) :: watched
      integer :: i
      points = reshape([7.88_wp, 3.95_wp, 2.57_wp, 1.29_wp], [2, 2])
      do i = 1, 2
         system%pendulum = pendulum_at(points(1, i), points(2, i), 0.0_wp)
         associate (p => system%pendulum)
            y = pendulum_initial_state(p, 0.017_wp)
            y_gsl = y
            options = rk_options_t(method=rk_dop853, rtol=1.0e-12_wp)
            options%atol_components = pendulum_atol(p, y, 1.0e-12_wp)
            t = 0.0_wp
            call rk_integrate(system, t, 5*p%period, y, options, stats, error)
            call check(ctx, .not. allocated(error), "DOP853 succeeds")
            call pendulum_gsl(p, y_gsl, 5*p%period, 1.0e-12_wp, stats, error)
            call check(ctx, .not. allocated(error), "GSL rk8pd succeeds")
            difference = max(maxval(abs(y(1:2) - y_gsl(1:2)))/p%rho, maxval(abs(y(3:4) - y_gsl(3:4)))/(p%rho*p%omega))
            write (*, '(4x,a,f5.2,a,f5.2,a,es10.3)') "alpha=", p%alpha, " beta=", p%beta, &
               ": DOP853 vs GSL rk8pd after 5 periods, scaled difference ", difference
            call check(ctx, difference < 1.0e-9_wp, "DOP853 = GSL rk8pd")
            ! the watched loop (energy_drift) takes the driver's steps: the same end state to
            ! the bit and evaluations; its drift is at least the end value and small at 1e-12
            y = pendulum_initial_state(p, 0.017_wp)
            call pendulum_gsl(p, y, 5*p%period, 1.0e-12_wp, watched, error, energy_drift=drift)
            call check(ctx, .not. allocated(error), "GSL rk8pd watched succeeds")
            call check(ctx, all(y == y_gsl) .and. watched%n_evaluations == stats%n_evaluations, &
               "watched GSL loop takes the driver's steps")
            end_drift = abs(pendulum_energy(p, y) - pendulum_energy(p, pendulum_initial_state(p, 0.017_wp))) &
                        /pendulum_energy_scale(p, pendulum_initial_state(p, 0.017_wp))
            write (*, '(4x,a,es10.3,a,es10.3)') "GSL rk8pd 1e-12, 5 periods: largest energy error ", drift, &
               ", at the end ", end_drift
            ! measured 2.7e-13 and 7.4e-13
            call check(ctx, drift >= end_drift .and. drift < 3.0e-12_wp, "GSL energy drift along the run")
         end associate
      end do
   end subroutine dop853_vs_gsl_rk8pd
end module test_pendulum

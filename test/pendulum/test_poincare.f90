!> Tests of the Poincaré section (hillstab_pendulum_poincare): every recorded crossing is checked
!> by a separate tight integration from the start straight to the crossing time (x
!> vanishes there, r and r' agree); the crossings lie in the part of the (r, r') plane
!> that the energy allows and cross with φ' > 0; crossings come once per swing; the
!> state at a given energy has that energy and is the bounce start at φ0 = 0; the root
!> refinement finds the zero of a step's interpolant to rounding.
module test_poincare
   use hillstab_core_kinds, only: wp, pi
   use hillstab_core_error, only: error_t
   use hillstab_integrate_rk, only: rk_options_t, rk_integrate, rk_step_t, rk_dop853
   use hillstab_pendulum_equations
   use hillstab_pendulum_poincare
   use hillstab_testing
   use hillstab_test_pendulum, only: pendulum_at
   implicit none
   private
   public :: collect_poincare

   !> Records the steps of an integration, to test the refinement on real steps.
   type, extends(pendulum_system_t) :: step_keeper_t
      type(rk_step_t) :: kept
      logical :: found = .false.
      real(wp) :: previous_x = 0.0_wp
   contains
      procedure :: observe => keep_crossing_step
   end type step_keeper_t

contains

   function collect_poincare() result(suite)
      type(testsuite_t) :: suite
      suite = new_testsuite("poincare", [ &
         new_unittest("crossings_verified", crossings_verified), &
         new_unittest("energy_region", energy_region), &
         new_unittest("state_at_energy", state_at_energy), &
         new_unittest("refinement_to_rounding", refinement_to_rounding), &
         new_unittest("bounce_has_no_crossings", bounce_has_no_crossings)])
   end function collect_poincare

   !> The regular case (c) and the first crossings of case (g): integrating from the
   !> start to each crossing time at tolerance 1e-13 gives x ≈ 0 (to 1e-10 ρ) and the
   !> recorded r, r' (to 1e-8 of ρ and ρω).
   subroutine crossings_verified(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp), parameter :: cases(2, 2) = reshape([2.57_wp, 1.29_wp, 7.48_wp, 2.47_wp], [2, 2])
      type(pendulum_t) :: p
      type(pendulum_system_t) :: system
      type(section_t) :: section
      type(rk_options_t) :: options
      type(error_t), allocatable :: error
      real(wp) :: y0(4), y(4), t, worst_x, worst_r
      integer :: k, j
      do k = 1, 2
         p = pendulum_at(cases(1, k), cases(2, k))
         y0 = pendulum_initial_state(p, 0.017_wp)
         call poincare_section(p, y0, 20*p%period, 1.0e-12_wp, section, error)
         call check(ctx, .not. allocated(error) .and. section%n >= 3, "crossings found")
         if (allocated(error)) cycle
         system%pendulum = p
         options = rk_options_t(method=rk_dop853, rtol=1.0e-13_wp, atol=1.0e-13_wp, max_steps=10000000)
         options%atol_components = pendulum_atol(p, y0, 1.0e-13_wp)
         worst_x = 0.0_wp
         worst_r = 0.0_wp
         do j = 1, min(section%n, 6)
            t = 0.0_wp
            y = y0
            call rk_integrate(system, t, section%points(1, j), y, options, error=error)
            call check(ctx, .not. allocated(error), "reference integration")
            worst_x = max(worst_x, abs(y(px))/p%rho)
            worst_r = max(worst_r, abs(y(pz) - section%points(2, j))/p%rho, &
                          abs(y(pvz) - section%points(3, j))/(p%rho*p%omega))
            call check(ctx, y(pvx) > 0.0_wp, "phi' > 0 at the crossing")
         end do
         call check(ctx, worst_x < 1.0e-10_wp, "x = 0 at the crossing times")
         call check(ctx, worst_r < 1.0e-8_wp, "r, r' at the crossings")
         write (*, '(4x,a,2f6.2,a,i0,a,es9.2,a,es9.2)') "case", cases(:, k), ": ", section%n, &
            " crossings in 20 periods; worst |x|/rho ", worst_x, ", worst r, r' difference ", worst_r
      end do
   end subroutine crossings_verified

   !> At a crossing x = 0 and x' > 0, so E = ½(x'² + r'²) + ½ω²(r − r0)² − g r gives
   !> x'² = 2E − r'² − ω²(r − r0)² + 2 g r > 0: the points lie inside the energy's region.
   !> Crossings come at most once per swing period (about 2π/√(g/ρ) here).
   subroutine energy_region(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(pendulum_t) :: p
      type(section_t) :: section
      type(error_t), allocatable :: error
      real(wp) :: y0(4), e, room, drift, swing
      integer :: j
      p = pendulum_at(7.48_wp, 2.47_wp)
      swing = 2.0_wp*pi/sqrt(p%g/p%rho)
      y0 = pendulum_initial_state(p, 0.3_wp)
      e = pendulum_energy(p, y0)
      call poincare_section(p, y0, 200*p%period, 1.0e-10_wp, section, error)
      call check(ctx, .not. allocated(error) .and. section%n > 20, "crossings found")
      if (allocated(error)) return
      room = huge(1.0_wp)
      do j = 1, section%n
         associate (r => section%points(2, j), rdot => section%points(3, j))
            room = min(room, (2.0_wp*e - rdot**2 - p%omega**2*(r - p%r0)**2 + 2.0_wp*p%g*r)/(p%g*p%rho))
         end associate
      end do
      call check(ctx, room > 0.0_wp, "inside the energy's region")
      call check(ctx, all(section%points(1, 2:section%n) > section%points(1, :section%n - 1)), "times increase")
      ! measured: successive crossings 0.76 to 1.44 swing periods apart
      call check(ctx, minval(section%points(1, 2:section%n) - section%points(1, :section%n - 1)) > &
         0.5_wp*swing, "at most one crossing per swing")
      ! the drift is over the sum of the energy terms' magnitudes, not over |E(0)|, which is
      ! small where the terms of E nearly cancel
      drift = section%energy_drift
      write (*, '(4x,a,es9.2,a)') "drift ", drift, " of the energy scale"
      call check(ctx, drift < 1.0e-7_wp, "energy kept")
   end subroutine energy_region

   subroutine state_at_energy(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(pendulum_t) :: p
      type(error_t), allocatable :: error
      real(wp) :: y(4), e
      integer :: k
      p = pendulum_at(7.48_wp, 2.47_wp)
      e = pendulum_energy(p, pendulum_initial_state(p, 0.0_wp))
      call pendulum_state_at_energy(p, 0.0_wp, e, y, error)
      call check(ctx, .not. allocated(error), "phi0 = 0")
      call check(ctx, y(pz), p%rho - p%a, abs=0.0_wp, rel=1.0e-13_wp)
      call check(ctx, y(px) == 0.0_wp .and. all(y(3:4) == 0.0_wp), "on the axis, at rest")
      do k = 1, 6
         call pendulum_state_at_energy(p, 0.25_wp*k, e, y, error)
         call check(ctx, .not. allocated(error), "phi0 > 0")
         call check(ctx, pendulum_energy(p, y), e, abs=0.0_wp, rel=1.0e-12_wp)
         call check(ctx, pendulum_angle(y), 0.25_wp*k, abs=1.0e-15_wp, rel=1.0e-14_wp)
      end do
      ! far below the bottom of the potential: no such state
      call pendulum_state_at_energy(p, 0.0_wp, -1.0e3_wp, y, error)
      call check(ctx, allocated(error), "unreachable energy refused")
   end subroutine state_at_energy

   !> On a real step that contains a crossing, `refine_crossing` returns a time where the
   !> interpolated x is zero to rounding (|x| within a few ulps of x'·t).
   subroutine refinement_to_rounding(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(step_keeper_t) :: system
      type(rk_options_t) :: options
      type(error_t), allocatable :: error
      real(wp) :: t, y(4), t_cross, state(4)
      system%pendulum = pendulum_at(3.7_wp, 2.47_wp)
      y = pendulum_initial_state(system%pendulum, -0.2_wp)
      options = rk_options_t(method=rk_dop853, rtol=1.0e-10_wp, atol=1.0e-12_wp, dense_output=.true.)
      t = 0.0_wp
      call rk_integrate(system, t, 5*system%pendulum%period, y, options, error=error)
      call check(ctx, system%found, "a step with a crossing")
      if (.not. system%found) return
      t_cross = refine_crossing(system%kept)
      state = rk_dense_value_of(system%kept, t_cross)
      call check(ctx, t_cross >= system%kept%t_old .and. t_cross <= system%kept%t, "inside the step")
      call check(ctx, abs(state(px)) <= 8.0_wp*epsilon(1.0_wp)*abs(state(pvx))*abs(t_cross) + tiny(1.0_wp), &
         "x = 0 to rounding")
   end subroutine refinement_to_rounding

   function rk_dense_value_of(step, t) result(y)
      use hillstab_integrate_rk, only: rk_dense_value
      type(rk_step_t), intent(in) :: step
      real(wp), intent(in) :: t
      real(wp) :: y(4)
      y = rk_dense_value(step, t)
   end function rk_dense_value_of

   subroutine keep_crossing_step(self, step, stop)
      class(step_keeper_t), intent(inout) :: self
      type(rk_step_t), intent(in) :: step
      logical, intent(inout) :: stop
      if (step%index > 0 .and. self%previous_x < 0.0_wp .and. step%y(px) >= 0.0_wp) then
         self%kept = step
         self%found = .true.
         stop = .true.
      end if
      self%previous_x = step%y(px)
   end subroutine keep_crossing_step

   !> φ0 = 0: the orbit is the bounce, x stays exactly 0, no crossing is recorded.
   subroutine bounce_has_no_crossings(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(pendulum_t) :: p
      type(section_t) :: section
      type(error_t), allocatable :: error
      p = pendulum_at(7.48_wp, 2.47_wp)
      call poincare_section(p, pendulum_initial_state(p, 0.0_wp), 20*p%period, 1.0e-10_wp, section, error)
      call check(ctx, .not. allocated(error) .and. section%n == 0, "no crossing")
   end subroutine bounce_has_no_crossings
end module test_poincare

!> Tests of the symplectic schemes and their tangent maps (hillstab_pendulum_symplectic)
!> against independent references: the observed order on a closed-form nonlinear orbit
!> (a circular orbit of the spring without gravity), time reversibility, the tangent map
!> against central differences of the map and against the symplectic condition
!> MᵀJM = J, the energy error bounded over 10⁴ radial periods, lanes that give each
!> orbit's own result, and the coefficient tables.
module test_symplectic
   use hillstab_core_kinds, only: wp
   use hillstab_pendulum_equations, only: pendulum_t, pendulum_initial_state, pendulum_energy, pendulum_energy_scale
   use hillstab_pendulum_symplectic
   use hillstab_testing
   use hillstab_test_pendulum, only: pendulum_at
   implicit none
   private
   public :: collect_symplectic

contains

   function collect_symplectic() result(suite)
      type(testsuite_t) :: suite
      suite = new_testsuite("symplectic", [ &
         new_unittest("scheme_tables", scheme_tables), &
         new_unittest("order_on_circular_orbit", order_on_circular_orbit), &
         new_unittest("time_reversible", time_reversible), &
         new_unittest("tangent_map_is_derivative", tangent_map_is_derivative), &
         new_unittest("tangent_map_symplectic", tangent_map_symplectic), &
         new_unittest("energy_bounded_1e4_periods", energy_bounded_1e4_periods), &
         new_unittest("lanes_match_single_orbits", lanes_match_single_orbits)])
   end function collect_symplectic

   !> Every scheme: consistent (Σa = Σb = 1 to rounding), symmetric (a_i = a_{s+1−i},
   !> b_i = b_{s+2−i}: time-reversible), named; an unknown id gives scheme 0.
   subroutine scheme_tables(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(symplectic_scheme_t) :: s
      integer :: id, m
      do id = 1, symplectic_scheme_count
         s = symplectic_scheme(id)
         m = s%stages
         call check(ctx, s%id == id .and. m >= 1 .and. m <= symplectic_max_stages, "stages of "//symplectic_scheme_name(id))
         call check(ctx, sum(s%drift(1:m)), 1.0_wp, abs=4.0_wp*epsilon(1.0_wp), message="sum a")
         call check(ctx, sum(s%kick(1:m + 1)), 1.0_wp, abs=4.0_wp*epsilon(1.0_wp), message="sum b")
         call check(ctx, all(s%drift(1:m) == s%drift(m:1:-1)), "drifts symmetric: "//symplectic_scheme_name(id))
         call check(ctx, all(s%kick(1:m + 1) == s%kick(m + 1:1:-1)), "kicks symmetric: "//symplectic_scheme_name(id))
         call check(ctx, len(symplectic_scheme_name(id)) > 0, "named")
      end do
      s = symplectic_scheme(symplectic_scheme_count + 1)
      call check(ctx, s%id == 0 .and. s%stages == 0, "unknown id")
      do id = 1, symplectic_scheme_count
         call check(ctx, symplectic_scheme_id(symplectic_scheme_name(id)) == id, "id from the name")
      end do
      call check(ctx, symplectic_scheme_id("rk4") == 0, "unknown name")
   end subroutine scheme_tables

   !> Without gravity the spring pendulum has the circular orbits r = R, angular speed
   !> Ω = ω √(1 − r0/R) — exact, and nonlinear in the force. Over t = 3 s (3.4 turns) with
   !> 50 and 100 steps the position error falls by 2^p: measured p = 2.02 (leapfrog), 4.06
   !> (yoshida4), 6.03 (yoshida6), 4.06 (blanes_moan4), 6.02 (blanes_moan6), 8.26
   !> (mclachlan8); required within 0.3 of the scheme's order.
   subroutine order_on_circular_orbit(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp), parameter :: radius = 0.2_wp, t_end = 3.0_wp
      type(pendulum_t) :: p
      type(symplectic_scheme_t) :: s
      real(wp) :: w, exact(4), y(4), error(2), observed
      integer :: id, k
      p%omega = 10.0_wp
      p%r0 = 0.1_wp
      p%g = 0.0_wp
      w = p%omega*sqrt(1.0_wp - p%r0/radius)
      exact = [radius*sin(w*t_end), radius*cos(w*t_end), radius*w*cos(w*t_end), -radius*w*sin(w*t_end)]
      do id = 1, symplectic_scheme_count
         s = symplectic_scheme(id)
         do k = 1, 2
            y = [0.0_wp, radius, radius*w, 0.0_wp]
            call symplectic_steps(p, s, t_end/(50*k), 50*k, y)
            error(k) = norm2(y(1:2) - exact(1:2))/radius
         end do
         observed = log(error(1)/error(2))/log(2.0_wp)
         call check(ctx, abs(observed - s%order) < 0.3_wp, "order of "//symplectic_scheme_name(id))
         write (*, '(4x,a14,a,i0,a,f6.2,a,2es10.2)') symplectic_scheme_name(id), ": order ", s%order, ", observed ", &
            observed, ", errors", error
      end do
   end subroutine order_on_circular_orbit

   !> The schemes are symmetric: n steps of h then n steps of −h come back to the start
   !> (to rounding: 1e-12 of the orbit's size), orbit and tangent vector, on the chaotic
   !> case (g) over two radial periods.
   subroutine time_reversible(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(pendulum_t) :: p
      real(wp) :: y0(4), y(4), d0(4, 1), d(4, 1), h
      integer :: id
      p = pendulum_at(7.48_wp, 2.47_wp)
      y0 = pendulum_initial_state(p, 0.6_wp)
      d0(:, 1) = [1.0_wp, -0.5_wp, 2.0_wp, 0.3_wp]
      h = p%period/32
      do id = 1, symplectic_scheme_count
         y = y0
         d = d0
         call symplectic_steps(p, symplectic_scheme(id), h, 64, y, d)
         call symplectic_steps(p, symplectic_scheme(id), -h, 64, y, d)
         call check(ctx, maxval(abs(y(1:2) - y0(1:2))) < 1.0e-12_wp*p%rho .and. &
            maxval(abs(y(3:4) - y0(3:4))) < 1.0e-12_wp*p%rho*p%omega, "orbit back: "//symplectic_scheme_name(id))
         call check(ctx, maxval(abs(d - d0)) < 1.0e-10_wp*maxval(abs(d0)), "tangent back: "//symplectic_scheme_name(id))
      end do
   end subroutine time_reversible

   !> The tangent map is the derivative of the map: over one radial period (16 steps) of
   !> a large swing (case (g), φ0 = 0.6) each column of the tangent matrix equals the
   !> central difference (Φ(y + ε e_j) − Φ(y − ε e_j))/(2ε), ε = 1e-6 of the component's
   !> scale, to 1e-7 of the column's size (the difference's own error: ε² times the third
   !> derivative, and rounding over ε).
   subroutine tangent_map_is_derivative(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(pendulum_t) :: p
      type(symplectic_scheme_t) :: s
      real(wp) :: y0(4), y(4), yp(4), ym(4), m(4, 4), scale(4), eps, worst
      integer :: j, id
      p = pendulum_at(7.48_wp, 2.47_wp)
      y0 = pendulum_initial_state(p, 0.6_wp, vx0=0.3_wp)
      scale = [p%rho, p%rho, p%rho*p%omega, p%rho*p%omega]
      do id = 1, symplectic_scheme_count
         s = symplectic_scheme(id)
         m = 0.0_wp
         do j = 1, 4
            m(j, j) = 1.0_wp
         end do
         y = y0
         call symplectic_steps(p, s, p%period/16, 16, y, m)
         worst = 0.0_wp
         do j = 1, 4
            eps = 1.0e-6_wp*scale(j)
            yp = y0
            yp(j) = yp(j) + eps
            ym = y0
            ym(j) = ym(j) - eps
            call symplectic_steps(p, s, p%period/16, 16, yp)
            call symplectic_steps(p, s, p%period/16, 16, ym)
            ! compare in the scaled components (position/ρ, velocity/ρω)
            worst = max(worst, maxval(abs(((yp - ym)/(2.0_wp*eps) - m(:, j))*scale(j)/scale))/ &
                               maxval(abs(m(:, j)*scale(j)/scale)))
         end do
         call check(ctx, worst < 1.0e-7_wp, "tangent = central difference: "//symplectic_scheme_name(id))
         write (*, '(4x,a14,a,es9.2)') symplectic_scheme_name(id), ": largest relative difference ", worst
      end do
   end subroutine tangent_map_is_derivative

   !> The tangent matrix M of a symplectic map satisfies MᵀJM = J (J the canonical form in
   !> (x, z, x', z')); over 60 radial periods of the chaotic case (g), where M has grown
   !> large, to 1e-12 of max|M|².
   subroutine tangent_map_symplectic(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(pendulum_t) :: p
      real(wp) :: y(4), m(4, 4), j(4, 4), defect
      integer :: i, id
      p = pendulum_at(7.48_wp, 2.47_wp)
      j = 0.0_wp
      j(1, 3) = 1.0_wp; j(2, 4) = 1.0_wp; j(3, 1) = -1.0_wp; j(4, 2) = -1.0_wp
      do id = 1, symplectic_scheme_count
         m = 0.0_wp
         do i = 1, 4
            m(i, i) = 1.0_wp
         end do
         y = pendulum_initial_state(p, 0.6_wp)
         call symplectic_steps(p, symplectic_scheme(id), p%period/32, 60*32, y, m)
         ! the velocities in units of ω so that all entries are of one size
         m(3:4, :) = m(3:4, :)/p%omega
         m(:, 3:4) = m(:, 3:4)*p%omega
         defect = maxval(abs(matmul(transpose(m), matmul(j, m)) - j))/maxval(abs(m))**2
         call check(ctx, defect < 1.0e-12_wp, "M^T J M = J: "//symplectic_scheme_name(id))
         call check(ctx, maxval(abs(m)) > 1.0e3_wp, "M has grown (chaotic case)")
         write (*, '(4x,a14,a,es9.2,a,es9.2)') symplectic_scheme_name(id), ": max abs M ", maxval(abs(m)), ", defect ", defect
      end do
   end subroutine tangent_map_symplectic

   !> Energy error bounded, not drifting: Blanes & Moan's order-6 scheme over 10⁴ radial
   !> periods on the regular case (c) (16 steps per period) and the chaotic case (g) (32
   !> steps per period, large swings over the top): the largest |E − E(0)| (over the sum
   !> of the energy terms' magnitudes) over all 10⁴ periods stays within 3 times that of
   !> the first 10³, and below 1e-8.
   subroutine energy_bounded_1e4_periods(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp), parameter :: cases(2, 2) = reshape([2.57_wp, 1.29_wp, 7.48_wp, 2.47_wp], [2, 2])
      integer, parameter :: steps(2) = [16, 32]
      type(pendulum_t) :: p
      type(tangent_lanes_t) :: lanes
      type(symplectic_scheme_t) :: s
      real(wp) :: y0(4), e0, scale, e(1), first, whole
      integer :: k, n
      s = symplectic_scheme(symplectic_blanes_moan6)
      do k = 1, 2
         p = pendulum_at(cases(1, k), cases(2, k))
         y0 = pendulum_initial_state(p, 0.017_wp)
         e0 = pendulum_energy(p, y0)
         scale = pendulum_energy_scale(p, y0)
         call lanes_allocate(lanes, 1)
         call lanes_load(lanes, 1, p, y0, [0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp], p%period/steps(k))
         first = 0.0_wp
         whole = 0.0_wp
         do n = 1, 10000*steps(k)
            call lanes_step(s, lanes)
            call lanes_energy(lanes, e)
            whole = max(whole, abs(e(1) - e0)/scale)
            if (n == 1000*steps(k)) first = whole
         end do
         call check(ctx, whole <= 3.0_wp*first, "no drift")
         call check(ctx, whole < 1.0e-8_wp, "bounded")
         write (*, '(4x,a,2f6.2,a,es9.2,a,es9.2)') "case", cases(:, k), ": largest energy error over 1e3 periods ", &
            first, ", over 1e4 ", whole
      end do
   end subroutine energy_bounded_1e4_periods

   !> Three lanes with different pendula and steps give, bit for bit, what each orbit
   !> gives alone.
   subroutine lanes_match_single_orbits(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp), parameter :: cases(2, 3) = reshape([2.57_wp, 1.29_wp, 7.48_wp, 2.47_wp, 9.5_wp, 6.0_wp], [2, 3])
      integer, parameter :: steps(3) = [8, 16, 40]
      type(pendulum_t) :: p(3)
      type(tangent_lanes_t) :: lanes
      type(symplectic_scheme_t) :: s
      real(wp) :: y(4), d(4, 1), y_lane(4), d_lane(4)
      real(wp), parameter :: d0(4) = [0.5_wp, 0.5_wp, 0.1_wp, -0.2_wp]
      integer :: k, n
      s = symplectic_scheme(symplectic_blanes_moan6)
      call lanes_allocate(lanes, 3)
      do k = 1, 3
         p(k) = pendulum_at(cases(1, k), cases(2, k))
         call lanes_load(lanes, k, p(k), pendulum_initial_state(p(k), 0.3_wp), d0, p(k)%period/steps(k))
      end do
      do n = 1, 100
         call lanes_step(s, lanes)
      end do
      do k = 1, 3
         y = pendulum_initial_state(p(k), 0.3_wp)
         d(:, 1) = d0
         call symplectic_steps(p(k), s, p(k)%period/steps(k), 100, y, d)
         call lanes_state(lanes, k, y_lane, d_lane)
         call check(ctx, all(y_lane == y) .and. all(d_lane == d(:, 1)), "lane = single orbit")
      end do
   end subroutine lanes_match_single_orbits
end module test_symplectic

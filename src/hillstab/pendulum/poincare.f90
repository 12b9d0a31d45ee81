!> Poincaré sections of the nonlinear elastic pendulum (hillstab_pendulum_equations): the points
!> where an orbit crosses φ = 0 (the downward vertical, x = 0 with z > 0) with φ' > 0
!> (there φ' = x'/z, so x' > 0), recorded as (t, r, r'). At such a point r = z and r' = z'.
!>
!> Crossings are located inside each accepted step of DOP853 with its 7th-order dense
!> output (never by taking the nearest step): a sign change of x across the step
!> brackets the crossing, and Newton's method on the interpolated x, with the
!> interpolated x' as derivative and bisection as safeguard, refines it to the
!> resolution of the time axis. The section is taken by the integrator's observer, so
!> the steps are those the error control chooses for the orbit alone.
!>
!> An orbit of the undamped pendulum keeps its energy E, so its section points lie in
!> the region of the (r, r') plane that E allows; orbits of one energy share one plane.
!> `pendulum_state_at_energy` starts an orbit at rest at angle φ0 with the radius that
!> gives a chosen energy (the energy of the bounce at φ0 = 0, say).
!>
!>```fortran
!> type(pendulum_t) :: p
!> type(section_t) :: section
!> type(error_t), allocatable :: error
!> real(wp) :: y0(4)
!> call pendulum_from_chart(7.48_wp, 2.47_wp, 0.0_wp, 0.1_wp, 9.81_wp, p, error)
!> call pendulum_state_at_energy(p, 0.3_wp, pendulum_energy(p, pendulum_initial_state(p, 0.0_wp)), y0, error)
!> call poincare_section(p, y0, 1000*p%period, 1.0e-10_wp, section, error)
!> print *, section%n, section%points(:, 1)   ! t, r, r'
!>```
module hillstab_pendulum_poincare
   use hillstab_core_kinds, only: wp
   use hillstab_core_error, only: error_t, set_error, err_invalid_parameter
   use hillstab_core_stats, only: work_stats_t
   use hillstab_integrate_rk, only: rk_step_t, rk_options_t, rk_integrate, rk_dense_value, rk_dop853
   use hillstab_pendulum_equations, only: pendulum_t, pendulum_system_t, pendulum_atol, pendulum_energy, pendulum_energy_scale, &
      px, pz, pvx, pvz
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   implicit none
   private
   public :: section_t, poincare_section, pendulum_state_at_energy, refine_crossing

   !> Crossings of φ = 0 with φ' > 0.
   type :: section_t
      integer :: n = 0                        !! number of crossings
      real(wp), allocatable :: points(:, :)   !! (3, n): t [s], r [m], r' [m/s] at each crossing
      !> |E(t_end) − E(0)| over the sum of the energy terms' magnitudes at t = 0
      !> (`pendulum_energy_scale`, as in hillstab_pendulum_lyapunov and task series)
      real(wp) :: energy_drift = 0.0_wp
      type(work_stats_t) :: stats             !! steps, rejections, f-evaluations
   end type section_t

   !> The equations of motion with an observer that records the section.
   type, extends(pendulum_system_t) :: section_system_t
      type(section_t) :: section
      real(wp) :: previous(4) = 0.0_wp   !! state at the start of the step being observed
      logical :: started = .false.
   contains
      procedure :: observe => record_crossings
   end type section_system_t

contains

   !> The section of the orbit from `y0` over [0, t_end], integrated by DOP853 with
   !> relative tolerance `rtol` and the absolute tolerances of `pendulum_atol`.
   subroutine poincare_section(p, y0, t_end, rtol, section, error)
      type(pendulum_t), intent(in) :: p   !! the pendulum
      real(wp), intent(in) :: y0(4)       !! initial state (x, z, x', z')
      real(wp), intent(in) :: t_end       !! end time [s], > 0
      real(wp), intent(in) :: rtol        !! relative tolerance (> 0)
      type(section_t), intent(out) :: section  !! the crossings (t, r, r'), the energy drift and the work done
      type(error_t), allocatable, intent(out) :: error  !! invalid arguments; integration failure
      type(section_system_t) :: system
      type(rk_options_t) :: options
      real(wp) :: t, y(4), e0
      if (.not. (ieee_is_finite(rtol) .and. rtol > 0.0_wp)) then
         call set_error(error, err_invalid_parameter, "poincare_section: rtol must be > 0")
      else if (.not. (ieee_is_finite(t_end) .and. t_end > 0.0_wp)) then
         call set_error(error, err_invalid_parameter, "poincare_section: t_end must be > 0")
      else if (.not. all(ieee_is_finite(y0))) then
         call set_error(error, err_invalid_parameter, "poincare_section: non-finite initial state")
      end if
      if (allocated(error)) return
      system%pendulum = p
      allocate (system%section%points(3, 64))
      options = rk_options_t(method=rk_dop853, rtol=rtol, atol=rtol, max_steps=huge(1), dense_output=.true.)
      options%atol_components = pendulum_atol(p, y0, rtol)
      t = 0.0_wp
      y = y0
      e0 = pendulum_energy(p, y0)
      call rk_integrate(system, t, t_end, y, options, system%section%stats, error)
      section = system%section
      section%points = section%points(:, :section%n)
      if (allocated(error)) then
         error%message = "poincare_section: "//error%message
         return
      end if
      section%energy_drift = abs(pendulum_energy(p, y) - e0)/max(pendulum_energy_scale(p, y0), tiny(1.0_wp))
   end subroutine poincare_section

   !> The observer. A crossing of x from negative to non-negative with z > 0 inside the step
   !> is refined on the dense output and recorded.
   subroutine record_crossings(self, step, stop)
      class(section_system_t), intent(inout) :: self
      type(rk_step_t), intent(in) :: step
      logical, intent(inout) :: stop
      real(wp) :: t_cross, y(4)
      real(wp), allocatable :: grown(:, :)
      if (self%started .and. step%index > 0) then
         if (self%previous(px) < 0.0_wp .and. step%y(px) >= 0.0_wp) then
            t_cross = refine_crossing(step)
            y = rk_dense_value(step, t_cross)
            if (y(pz) > 0.0_wp .and. y(pvx) > 0.0_wp) then
               associate (s => self%section)
                  if (s%n == size(s%points, 2)) then
                     allocate (grown(3, 2*s%n))
                     grown(:, :s%n) = s%points
                     call move_alloc(grown, s%points)
                  end if
                  s%n = s%n + 1
                  ! at x = 0: r = z, r' = (x x' + z z')/r = z'
                  s%points(:, s%n) = [t_cross, y(pz), y(pvz)]
               end associate
            end if
         end if
      end if
      self%previous = step%y(1:4)
      self%started = .true.
   end subroutine record_crossings

   !> The time in [t_old, t] of an accepted step where the interpolated x vanishes,
   !> given x(t_old) < 0 ≤ x(t): Newton on the dense output (x' from the dense output
   !> too), kept inside a shrinking bracket, bisecting when a Newton step leaves it.
   function refine_crossing(step) result(t_cross)
      type(rk_step_t), intent(in) :: step  !! the step (with its dense output)
      real(wp) :: t_cross
      real(wp) :: lo, hi, y(size(step%y)), t_new
      integer :: iteration
      lo = step%t_old
      hi = step%t
      ! start from the secant of the end values
      t_cross = lo + (hi - lo)*(-interpolated_x(lo))/(step%y(px) - interpolated_x(lo))
      if (.not. (t_cross > lo .and. t_cross < hi)) t_cross = 0.5_wp*(lo + hi)
      do iteration = 1, 60
         y = rk_dense_value(step, t_cross)
         if (y(px) == 0.0_wp) exit
         if (y(px) < 0.0_wp) then
            lo = t_cross
         else
            hi = t_cross
         end if
         t_new = t_cross - y(px)/y(pvx)
         if (.not. (t_new > lo .and. t_new < hi) .or. y(pvx) == 0.0_wp) t_new = 0.5_wp*(lo + hi)
         if (abs(t_new - t_cross) <= 4.0_wp*epsilon(1.0_wp)*abs(t_cross) .or. hi - lo <= &
             4.0_wp*epsilon(1.0_wp)*abs(t_cross)) then
            t_cross = t_new
            exit
         end if
         t_cross = t_new
      end do
   contains
      real(wp) function interpolated_x(t)
         real(wp), intent(in) :: t
         real(wp) :: state(size(step%y))
         state = rk_dense_value(step, t)
         interpolated_x = state(px)
      end function interpolated_x
   end function refine_crossing

   !> The state at rest at angle φ0 whose energy is `energy` [J/kg]: the radius r solves
   !> ½ω²(r − r0)² − g r cos φ0 = E; of its two roots the shorter one, which for φ0 = 0 and
   !> E the energy of eq. (38) is the bounce's start ρ − a. Fails when no such r > 0 exists.
   pure subroutine pendulum_state_at_energy(p, phi0, energy, y, error)
      type(pendulum_t), intent(in) :: p  !! the pendulum
      real(wp), intent(in) :: phi0       !! angle from the downward vertical [rad]
      real(wp), intent(in) :: energy     !! energy per unit mass [J/kg]
      real(wp), intent(out) :: y(4)      !! (x, z, 0, 0)
      type(error_t), allocatable, intent(out) :: error  !! no radius r > 0 has this energy at phi0; unallocated on success
      real(wp) :: c, shift, discriminant, r
      c = cos(phi0)
      ! u = r − r0: u² − 2 (g c/ω²) u − 2 (E + g c r0)/ω² = 0
      shift = p%g*c/p%omega**2
      discriminant = shift**2 + 2.0_wp*(energy + p%g*c*p%r0)/p%omega**2
      y = 0.0_wp
      if (discriminant < 0.0_wp) then
         call set_error(error, err_invalid_parameter, "pendulum_state_at_energy: no state at rest at this angle "// &
            "has this energy")
         return
      end if
      r = p%r0 + shift - sqrt(discriminant)
      if (.not. (r > 0.0_wp)) then
         call set_error(error, err_invalid_parameter, "pendulum_state_at_energy: the state at rest with this "// &
            "energy would need r <= 0 at this angle")
         return
      end if
      y = [r*sin(phi0), r*cos(phi0), 0.0_wp, 0.0_wp]
   end subroutine pendulum_state_at_energy
end module hillstab_pendulum_poincare

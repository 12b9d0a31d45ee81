!> The nonlinear (optionally damped) elastic pendulum in Cartesian form, its link to the
!> chart's parameters, and its variational (tangent) equations. Pure numerics, no I/O.
!>
!> Coordinates: x horizontal, z downward from the pivot, r = √(x² + z²), φ = atan2(x, z).
!> The state vector is y = (x, z, x', z') [m, m, m/s, m/s] (indices `px`, `pz`, `pvx`, `pvz`).
!> Equations of motion (the paper's eq. (10)/(42) in Cartesian components):
!>
!>   x'' = −ω²(1 − r0/r) x − κ x',   z'' = −ω²(1 − r0/r) z + g − κ z',   κ = ε ω/π.
!>
!> Chart parameters (α, β) and the physical r0, g give (the paper's eq. (23)–(25), (38)):
!> ρ = r0 π²/(π² − β), ω² = g π²/(ρ β), a = α ρ/π², T = 2π/ω. The vertical bounce
!> x ≡ 0, z = ρ − a cos ωt is an exact solution when ε = 0 (`pendulum_bounce`), and the
!> swing linearised about it is exactly the Hill equation of the chart (the paper's eq. (20)):
!> `pendulum_bounce_monodromy` integrates the 4×4 variational equations along it.
!>
!> Two RK systems (extensions of `rk_system_t`, see hillstab_integrate_rk):
!> - `pendulum_system_t`: the 4-D equations of motion;
!> - `pendulum_tangent_t`: the state plus m tangent vectors, y = (state, v₁, …, v_m) with
!>   size(y) = 4 + 4m, each v_k' = J(state) v_k (J = `pendulum_jacobian`). Use it for the
!>   monodromy along the bounce (m = 4 from the identity) or for Lyapunov exponents
!>   (extend it and override `observe` to renormalise the vectors).
!>
!> Tolerances: the swing coordinate x may be 1e-20 m in the linear phase, so a fixed
!> absolute tolerance on x would drown it; `pendulum_atol` scales the absolute tolerance
!> of x, x' with the initial swing amplitude (see there).
!>
!>```fortran
!> use hillstab_pendulum_equations
!> use hillstab_integrate_rk
!> type(pendulum_t) :: p
!> type(pendulum_system_t) :: system
!> type(rk_options_t) :: options
!> type(error_t), allocatable :: error
!> real(wp) :: t, y(4)
!> call pendulum_from_chart(1.48_wp, 2.47_wp, 0.0_wp, 0.1_wp, 9.81_wp, p, error)
!> system%pendulum = p
!> y = pendulum_initial_state(p, 0.017_wp)
!> options = rk_options_t(method=rk_dop853, rtol=1.0e-10_wp)
!> options%atol_components = pendulum_atol(p, y, 1.0e-10_wp)
!> t = 0.0_wp
!> call rk_integrate(system, t, 50*p%period, y, options, error=error)
!> print *, pendulum_angle(y), pendulum_energy(p, y)
!>```
module hillstab_pendulum_equations
   use hillstab_core_kinds, only: wp, pi, pi2
   use hillstab_core_error, only: error_t, set_error, err_invalid_parameter, err_integration
   use hillstab_hill_units, only: largest_scale
   use hillstab_core_stats, only: work_stats_t
   use hillstab_integrate_rk, only: rk_system_t, rk_options_t, rk_integrate, rk_dop853
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   implicit none
   private
   public :: pendulum_t, pendulum_from_chart, pendulum_initial_state, pendulum_energy, pendulum_angle
   public :: pendulum_energy_scale, pendulum_radius, pendulum_rhs, pendulum_jacobian, pendulum_bounce, pendulum_atol
   public :: pendulum_system_t, pendulum_tangent_t, pendulum_bounce_monodromy
   public :: px, pz, pvx, pvz

   !> Index of x (horizontal position) in the state vector.
   integer, parameter :: px = 1
   !> Index of z (downward position) in the state vector.
   integer, parameter :: pz = 2
   !> Index of x' in the state vector.
   integer, parameter :: pvx = 3
   !> Index of z' in the state vector.
   integer, parameter :: pvz = 4

   !> Parameters of one pendulum: the chart's (α, β, ε), the physical r0 and g, and the
   !> derived quantities. Build it with `pendulum_from_chart` (which validates).
   type :: pendulum_t
      real(wp) :: alpha = 0.0_wp    !! α = a π²/ρ (dimensionless bounce amplitude)
      real(wp) :: beta = 0.0_wp     !! β = g π²/(ρ ω²)
      real(wp) :: epsilon = 0.0_wp  !! ε = κ π/ω, damping of eq. (46)
      real(wp) :: r0 = 0.1_wp       !! natural length of the spring [m]
      real(wp) :: g = 9.81_wp       !! gravity [m/s²]
      real(wp) :: rho = 0.0_wp      !! equilibrium length ρ = r0 π²/(π² − β) [m]
      real(wp) :: omega = 0.0_wp    !! radial angular frequency ω = √(k/m) [1/s]
      real(wp) :: a = 0.0_wp        !! bounce amplitude a = α ρ/π² [m]
      real(wp) :: period = 0.0_wp   !! radial period T = 2π/ω [s]
      real(wp) :: kappa = 0.0_wp    !! damping rate κ = ε ω/π [1/s]
   end type pendulum_t

   !> The equations of motion as an RK system: y = (x, z, x', z').
   type, extends(rk_system_t) :: pendulum_system_t
      type(pendulum_t) :: pendulum  !! the parameters
   contains
      !> f(t, y) by `pendulum_rhs`
      procedure :: rhs => system_rhs
   end type pendulum_system_t

   !> The equations of motion with m tangent vectors: y = (state(4), v₁(4), …, v_m(4)),
   !> v_k' = J(state) v_k. m = (size(y) − 4)/4 is taken from the state size.
   type, extends(rk_system_t) :: pendulum_tangent_t
      type(pendulum_t) :: pendulum  !! the parameters
   contains
      !> f(t, y) and J v_k
      procedure :: rhs => tangent_rhs
   end type pendulum_tangent_t

contains

   !> Physical pendulum from the chart's parameters, validated: 0 ≤ α < π² and
   !> 0 < β < π² (the physical domain: a < ρ, r0 > 0), ε ≥ 0, r0 > 0, g > 0, all finite.
   !> ρ, ω and κ must come out within [1e-50, 1e50] (hillstab_hill_units' scale bounds; checked on their logarithms before
   !> they are computed, so nothing overflows). On error `p` holds the given values only
   !> and `error` names the parameter.
   pure subroutine pendulum_from_chart(alpha, beta, epsilon, r0, g, p, error)
      real(wp), intent(in) :: alpha    !! α = a π²/ρ, in [0, π²)
      real(wp), intent(in) :: beta     !! β = g π²/(ρ ω²), in (0, π²)
      real(wp), intent(in) :: epsilon  !! damping ε ≥ 0 (κ = ε ω/π)
      real(wp), intent(in) :: r0       !! natural length [m], > 0
      real(wp), intent(in) :: g        !! gravity [m/s²], > 0
      type(pendulum_t), intent(out) :: p  !! parameters and derived quantities
      type(error_t), allocatable, intent(out) :: error  !! allocated (err_invalid_parameter) if invalid
      real(wp), parameter :: log_bound = log(largest_scale)  ! symmetric: smallest_scale = 1/largest_scale
      real(wp) :: log_rho, log_omega, log_kappa
      p%alpha = alpha; p%beta = beta; p%epsilon = epsilon; p%r0 = r0; p%g = g
      if (.not. all(ieee_is_finite([alpha, beta, epsilon, r0, g]))) then
         call set_error(error, err_invalid_parameter, "pendulum: non-finite parameter")
      else if (alpha < 0.0_wp .or. alpha >= pi2) then
         call set_error(error, err_invalid_parameter, &
            "pendulum: alpha must lie in [0, pi**2) (bounce amplitude below the equilibrium length)")
      else if (beta <= 0.0_wp .or. beta >= pi2) then
         call set_error(error, err_invalid_parameter, &
            "pendulum: beta must lie in (0, pi**2), the physical domain (r0 > 0, finite spring constant)")
      else if (epsilon < 0.0_wp) then
         call set_error(error, err_invalid_parameter, "pendulum: epsilon (damping) must be >= 0")
      else if (r0 <= 0.0_wp) then
         call set_error(error, err_invalid_parameter, "pendulum: r0 must be > 0")
      else if (g <= 0.0_wp) then
         call set_error(error, err_invalid_parameter, "pendulum: g must be > 0")
      end if
      if (allocated(error)) return
      ! ρ and ω from their logarithms first: with β → 0, β → π², or extreme r0 and g they
      ! would overflow or underflow (a trapping build stops there); keeping ρ, ω and κ
      ! within [1e-50, 1e50] keeps ω²ρ² and every other product of the model finite
      log_rho = log(r0) + log(pi2) - log(pi2 - beta)
      log_omega = 0.5_wp*(log(g) + log(pi2) - log_rho - log(beta))
      log_kappa = -huge(1.0_wp)   ! (Fortran does not short-circuit: no log(0) inside the test)
      if (epsilon > 0.0_wp) log_kappa = log(epsilon) + log_omega - log(pi)
      if (abs(log_rho) > log_bound .or. abs(log_omega) > log_bound .or. log_kappa > log_bound) then
         call set_error(error, err_invalid_parameter, "pendulum: derived parameters out of range (rho, omega "// &
            "and kappa must lie within [1e-50, 1e50]; beta near 0 or pi**2, or extreme r0, g, epsilon)")
         return
      end if
      p%rho = r0*pi2/(pi2 - beta)
      p%omega = sqrt(g*pi2/(p%rho*beta))
      p%a = alpha*p%rho/pi2
      p%period = 2.0_wp*pi/p%omega
      p%kappa = epsilon*p%omega/pi
      if (.not. all(ieee_is_finite([p%rho, p%omega, p%a, p%period, p%kappa])) .or. p%omega <= 0.0_wp) then
         call set_error(error, err_invalid_parameter, "pendulum: derived parameters (rho, omega) not finite")
      end if
   end subroutine pendulum_from_chart

   !> Initial state of eq. (38): r(0) = ρ − a, φ(0) = φ0, at rest unless velocities are given.
   pure function pendulum_initial_state(p, phi0, vx0, vz0) result(y)
      type(pendulum_t), intent(in) :: p       !! the pendulum
      real(wp), intent(in) :: phi0            !! initial angle from the downward vertical [rad]
      real(wp), intent(in), optional :: vx0   !! initial horizontal velocity [m/s] (default 0)
      real(wp), intent(in), optional :: vz0   !! initial downward velocity [m/s] (default 0)
      real(wp) :: y(4)                        !! (x, z, x', z')
      real(wp) :: r
      r = p%rho - p%a
      y = [r*sin(phi0), r*cos(phi0), 0.0_wp, 0.0_wp]
      if (present(vx0)) y(pvx) = vx0
      if (present(vz0)) y(pvz) = vz0
   end function pendulum_initial_state

   !> Distance r = √(x² + z²) from the pivot [m] (without overflow or underflow in between).
   pure real(wp) function pendulum_radius(y) result(r)
      real(wp), intent(in) :: y(:)  !! state (x, z, …)
      r = hypot(y(px), y(pz))
   end function pendulum_radius

   !> Angle φ = atan2(x, z) from the downward vertical [rad], in (−π, π].
   pure real(wp) function pendulum_angle(y) result(phi)
      real(wp), intent(in) :: y(:)  !! state (x, z, …)
      phi = atan2(y(px), y(pz))
   end function pendulum_angle

   !> Energy per unit mass E = ½(x'² + z'²) + ½ω²(r − r0)² − g z [J/kg] (eq. (3) divided by m;
   !> conserved when ε = 0).
   pure real(wp) function pendulum_energy(p, y) result(e)
      type(pendulum_t), intent(in) :: p  !! the pendulum
      real(wp), intent(in) :: y(:)       !! state (x, z, x', z')
      e = 0.5_wp*(y(pvx)**2 + y(pvz)**2) + 0.5_wp*p%omega**2*(pendulum_radius(y) - p%r0)**2 - p%g*y(pz)
   end function pendulum_energy

   !> Sum of the magnitudes of the three energy terms, ½|v|² + ½ω²(r − r0)² + g|z| [J/kg]:
   !> the scale against which an energy error is relative. E itself is no such scale: it
   !> vanishes on the ellipse β² + α² = 2βπ² of (C1) (Fig. 4 (e) lies close to it, with
   !> |E| about 1/250 of this sum), so |ΔE|/|E| would measure the cancellation, not the
   !> integration.
   pure real(wp) function pendulum_energy_scale(p, y) result(scale)
      type(pendulum_t), intent(in) :: p  !! the pendulum
      real(wp), intent(in) :: y(:)       !! state (x, z, x', z')
      scale = 0.5_wp*(y(pvx)**2 + y(pvz)**2) + 0.5_wp*p%omega**2*(pendulum_radius(y) - p%r0)**2 + p%g*abs(y(pz))
   end function pendulum_energy_scale

   !> The exact undamped bounce at time t: x = 0, z = ρ − a cos ωt, z' = a ω sin ωt
   !> (eq. (15); a solution of the equations of motion when ε = 0).
   pure function pendulum_bounce(p, t) result(y)
      type(pendulum_t), intent(in) :: p  !! the pendulum
      real(wp), intent(in) :: t          !! time [s]
      real(wp) :: y(4)                   !! (0, z, 0, z')
      y = [0.0_wp, p%rho - p%a*cos(p%omega*t), 0.0_wp, p%a*p%omega*sin(p%omega*t)]
   end function pendulum_bounce

   !> Right-hand side of the equations of motion: dydt = (x', z', x'', z'').
   pure subroutine pendulum_rhs(p, y, dydt)
      type(pendulum_t), intent(in) :: p   !! the pendulum
      real(wp), intent(in) :: y(:)        !! state (x, z, x', z')
      real(wp), intent(out) :: dydt(:)    !! its derivative
      real(wp) :: stiffness, r2
      ! sqrt(x² + z²) rather than hypot: |x|, |z| ≲ ρ, so neither overflow nor harmful
      ! underflow can occur (x² underflowing only drops a term below z²·eps), and hypot
      ! costs as much as the rest of the right-hand side together. r0/r as r0·r/r²: the
      ! square root and the division then run side by side instead of one after the other
      ! (this is on the critical path of every stage of an integrator)
      r2 = y(px)**2 + y(pz)**2
      stiffness = p%omega**2 - (p%omega**2*p%r0/r2)*sqrt(r2)
      dydt(px) = y(pvx)
      dydt(pz) = y(pvz)
      dydt(pvx) = -stiffness*y(px) - p%kappa*y(pvx)
      dydt(pvz) = -stiffness*y(pz) + p%g - p%kappa*y(pvz)
   end subroutine pendulum_rhs

   !> Jacobian J = ∂f/∂y of the equations of motion at state y (4×4):
   !> ∂x''/∂x = −ω²(1 − r0/r + r0 x²/r³), ∂x''/∂z = ∂z''/∂x = −ω² r0 x z/r³,
   !> ∂z''/∂z = −ω²(1 − r0/r + r0 z²/r³), ∂/∂(x', z') = −κ.
   pure function pendulum_jacobian(p, y) result(jac)
      type(pendulum_t), intent(in) :: p  !! the pendulum
      real(wp), intent(in) :: y(:)       !! state (x, z, x', z'), r > 0
      real(wp) :: jac(4, 4)              !! J(i, j) = ∂f_i/∂y_j
      real(wp) :: r, w2, c, q
      r = pendulum_radius(y)
      w2 = p%omega**2
      c = w2*(1.0_wp - p%r0/r)
      q = w2*p%r0/r**3
      jac = 0.0_wp
      jac(px, pvx) = 1.0_wp
      jac(pz, pvz) = 1.0_wp
      jac(pvx, px) = -c - q*y(px)**2
      jac(pvx, pz) = -q*y(px)*y(pz)
      jac(pvz, px) = jac(pvx, pz)
      jac(pvz, pz) = -c - q*y(pz)**2
      jac(pvx, pvx) = -p%kappa
      jac(pvz, pvz) = -p%kappa
   end function pendulum_jacobian

   !> Absolute tolerances for the state (x, z, x', z') that keep relative accuracy rtol in
   !> every component: z and z' are measured against ρ and ρω; x and x' against the initial
   !> swing amplitude s = max(|x0|, |x0'|/ω) (ρ when the start is on the axis, where x stays
   !> exactly 0), floored at the smallest normal number. A swing that starts at 1e-20 m is
   !> then integrated with relative accuracy rtol from the first step (the linear phase is
   !> scale invariant), and once it has grown the relative part rtol·|x| dominates.
   pure function pendulum_atol(p, y0, rtol) result(atol)
      type(pendulum_t), intent(in) :: p  !! the pendulum
      real(wp), intent(in) :: y0(:)      !! initial state (x, z, x', z')
      real(wp), intent(in) :: rtol       !! relative tolerance of the integration
      real(wp) :: atol(4)                !! absolute tolerances for (x, z, x', z')
      real(wp) :: swing
      swing = max(abs(y0(px)), abs(y0(pvx))/p%omega)
      if (swing == 0.0_wp) swing = p%rho
      swing = min(swing, p%rho)
      atol(px) = max(rtol*swing, tiny(1.0_wp))
      atol(pvx) = max(rtol*swing*p%omega, tiny(1.0_wp))
      atol(pz) = max(rtol*p%rho, tiny(1.0_wp))
      atol(pvz) = max(rtol*p%rho*p%omega, tiny(1.0_wp))
   end function pendulum_atol

   !> 4×4 monodromy of the variational equations along the exact bounce over one radial
   !> period T (the state starts at (0, ρ − a, 0, 0) and is integrated with the tangent
   !> vectors; x stays exactly 0, so with ε = 0 the base orbit is the bounce of eq. (15);
   !> with ε > 0 it is the damped radial oscillation from the same start). Rows and columns
   !> in the order (x, z, x', z'). With ε = 0 its eigenvalues are those of the radial block
   !> (a harmonic oscillator over one period: {1, 1}) and the two of the swing block, whose
   !> sum is the chart's S (the paper's eq. (20) is exact). The swing block couples to nothing along the bounce.
   !> With ε > 0 the radial pair has modulus e^{−ε} (κT/2 = ε), and the swing block is
   !> taken along the decaying radial motion, which is not the periodic orbit of eq. (47).
   subroutine pendulum_bounce_monodromy(p, rtol, m, stats, error)
      type(pendulum_t), intent(in) :: p       !! the pendulum
      real(wp), intent(in) :: rtol            !! relative tolerance of the integration (> 0)
      real(wp), intent(out) :: m(4, 4)        !! monodromy: m(:, j) = ∂y(T)/∂y_j(0)
      type(work_stats_t), intent(out) :: stats  !! steps, rejections, f-evaluations
      type(error_t), allocatable, intent(out) :: error  !! allocated on failure
      type(pendulum_tangent_t) :: system
      type(rk_options_t) :: options
      real(wp) :: t, y(20), units(4), atol(4, 5)
      integer :: j
      m = 0.0_wp
      stats = work_stats_t()
      if (.not. (ieee_is_finite(rtol) .and. rtol > 0.0_wp)) then
         call set_error(error, err_invalid_parameter, "pendulum_bounce_monodromy: rtol must be > 0")
         return
      end if
      system%pendulum = p
      y = 0.0_wp
      y(1:4) = [0.0_wp, p%rho - p%a, 0.0_wp, 0.0_wp]
      do j = 1, 4
         y(4*j + j) = 1.0_wp
      end do
      ! column j of the tangent block has units of y_i/y_j: velocities ~ ω × positions
      units = [1.0_wp, 1.0_wp, p%omega, p%omega]
      atol(:, 1) = rtol*[p%rho, p%rho, p%rho*p%omega, p%rho*p%omega]
      do j = 1, 4
         atol(:, j + 1) = rtol*units/units(j)
      end do
      options = rk_options_t(method=rk_dop853, rtol=rtol, atol=rtol, max_steps=1000000)
      options%atol_components = reshape(atol, [20])
      t = 0.0_wp
      call rk_integrate(system, t, p%period, y, options, stats, error)
      if (allocated(error)) then
         error%message = "pendulum_bounce_monodromy: "//error%message
         return
      end if
      m = reshape(y(5:20), [4, 4])
   end subroutine pendulum_bounce_monodromy

   subroutine system_rhs(self, t, y, dydt)
      class(pendulum_system_t), intent(inout) :: self
      real(wp), intent(in) :: t, y(:)
      real(wp), intent(out) :: dydt(:)
      real(wp) :: stiffness, r2
      ! `pendulum_rhs` written out: this is the integrator's inner loop, one call less
      associate (p => self%pendulum)
         r2 = y(px)**2 + y(pz)**2
         stiffness = p%omega**2 - (p%omega**2*p%r0/r2)*sqrt(r2)
         dydt(px) = y(pvx)
         dydt(pz) = y(pvz)
         dydt(pvx) = -stiffness*y(px) - p%kappa*y(pvx)
         dydt(pvz) = -stiffness*y(pz) + p%g - p%kappa*y(pvz)
      end associate
   end subroutine system_rhs

   subroutine tangent_rhs(self, t, y, dydt)
      class(pendulum_tangent_t), intent(inout) :: self
      real(wp), intent(in) :: t, y(:)
      real(wp), intent(out) :: dydt(:)
      real(wp) :: jac(4, 4)
      integer :: k
      call pendulum_rhs(self%pendulum, y(1:4), dydt(1:4))
      jac = pendulum_jacobian(self%pendulum, y(1:4))
      do k = 5, size(y) - 3, 4
         dydt(k:k + 3) = matmul(jac, y(k:k + 3))
      end do
   end subroutine tangent_rhs
end module hillstab_pendulum_equations

!> Explicit symplectic integration of the undamped pendulum with its tangent map, in lanes.
!>
!> Without damping the pendulum is Hamiltonian with the separable
!> H = ½|v|² + V(x, z), V = ½ω²(r − r0)² − g z (z downward, per unit mass), so
!> compositions of the exact flows of the kinetic part (the drift x += h v) and of the
!> potential (the kick v += h F(x), F = −∇V = −ω²(1 − r0/r)(x, z) + (0, g)) are symplectic
!> maps; with fixed steps their energy error stays bounded instead of drifting. Every
!> scheme here is of the form (BAB, time-symmetric)
!>
!>   Φ_h = K(b₁h) D(a₁h) K(b₂h) D(a₂h) … D(a_s h) K(b_{s+1}h),
!>
!> and the kick that ends a step and the one that starts the next share one force
!> evaluation (s evaluations per step). The tangent vector δ = (δx, δz, δx', δz') is
!> advanced by the derivative of the same map (the tangent map method of Skokos &
!> Gerlach, Phys. Rev. E 82, 036704 (2010), eq. (14)–(16)): a drift is δx += h δv, a kick
!> δv −= h ∇²V(x) δx with the Hessian
!>
!>   ∇²V = c I + q x xᵀ,   c = ω²(1 − r0/r),   q = ω² r0/r³,
!>
!> so the exponent measured is that of the numerical map itself, and each kick costs one
!> square root and one division for both the orbit and its tangent vector.
!>
!> Schemes (`symplectic_scheme`): Störmer–Verlet (order 2), Yoshida's compositions of it
!> of order 4 (H. Yoshida, Phys. Lett. A 150 (1990) 262, eq. (4.5)) and 6 (ibid. Table 1,
!> solution A), Blanes & Moan's SRKN₆ᵇ (order 4) and SRKN₁₁ᵇ (order 6) (S. Blanes,
!> P. C. Moan, J. Comput. Appl. Math. 142 (2002) 313, Table 3), and McLachlan's
!> 17-stage composition of order 8 (R. I. McLachlan, SIAM J. Sci. Comput. 16 (1995) 151,
!> "SS17"). The coefficients were read as printed in those papers and as reproduced in
!> Principia's `integrators/methods.hpp` (github.com/mockingbirdnest/Principia); the
!> central coefficient of each symmetric scheme is computed here from the consistency
!> condition Σa = Σb = 1 (the papers print it rounded). Their order is checked in the
!> tests on a closed-form orbit. Laskar & Robutel's SABA/SBAB schemes are not offered:
!> they gain order only in a small parameter of a near-integrable splitting
!> (H = A + εB), and here the kinetic and potential parts are of one size.
!>
!> Lanes (`tangent_lanes_t`): several orbits, each with its own pendulum and step, are
!> advanced together in structure-of-arrays loops that the compiler vectorises; every
!> lane's arithmetic is that of the same orbit advanced alone (one lane), so results do
!> not depend on the lane mates. No state in the module: threads may run their own lanes.
!>
!>```fortran
!> type(tangent_lanes_t) :: lanes
!> type(symplectic_scheme_t) :: scheme
!> scheme = symplectic_scheme(symplectic_blanes_moan6)
!> call lanes_allocate(lanes, 4)
!> call lanes_load(lanes, 1, p, y0, [1.0_wp, 0.0_wp, 0.0_wp, 0.0_wp], p%period/32)
!> do k = 1, 32
!>    call lanes_step(scheme, lanes)
!> end do
!>```
module hillstab_pendulum_symplectic
   use hillstab_core_kinds, only: wp, int64
   use hillstab_pendulum_equations, only: pendulum_t
   implicit none
   private
   public :: symplectic_scheme_t, symplectic_scheme, symplectic_scheme_name, symplectic_scheme_id, symplectic_max_stages
   public :: symplectic_leapfrog, symplectic_yoshida4, symplectic_yoshida6, symplectic_blanes_moan4, &
      symplectic_blanes_moan6, symplectic_mclachlan8, symplectic_scheme_count
   public :: tangent_lanes_t, lanes_allocate, lanes_load, lanes_step, lanes_energy, lanes_state, symplectic_steps

   !> Störmer–Verlet (leapfrog), order 2, one force evaluation per step.
   integer, parameter :: symplectic_leapfrog = 1
   !> Yoshida's triple-jump composition of Störmer–Verlet, order 4, 3 evaluations per step.
   integer, parameter :: symplectic_yoshida4 = 2
   !> Yoshida's 7-stage composition (solution A), order 6, 7 evaluations per step.
   integer, parameter :: symplectic_yoshida6 = 3
   !> Blanes & Moan's SRKN₆ᵇ, order 4, 6 evaluations per step.
   integer, parameter :: symplectic_blanes_moan4 = 4
   !> Blanes & Moan's SRKN₁₁ᵇ, order 6, 11 evaluations per step.
   integer, parameter :: symplectic_blanes_moan6 = 5
   !> McLachlan's 17-stage composition SS17, order 8, 17 evaluations per step.
   integer, parameter :: symplectic_mclachlan8 = 6
   !> Number of schemes (ids 1 … symplectic_scheme_count).
   integer, parameter :: symplectic_scheme_count = 6
   !> Largest number of drifts (force evaluations) per step of any scheme.
   integer, parameter :: symplectic_max_stages = 17

   !> One scheme Φ_h = K(b₁h) D(a₁h) … D(a_s h) K(b_{s+1}h): s drifts, s + 1 kicks.
   type :: symplectic_scheme_t
      integer :: id = 0                   !! one of the symplectic_* constants (0: none)
      integer :: order = 0                !! classical order
      integer :: stages = 0               !! s: drifts = force evaluations per step
      real(wp) :: drift(symplectic_max_stages) = 0.0_wp      !! a₁ … a_s
      real(wp) :: kick(symplectic_max_stages + 1) = 0.0_wp   !! b₁ … b_{s+1}
   end type symplectic_scheme_t

   !> Orbits with their tangent vectors, one per lane, as structure of arrays.
   !> Positions x, z [m], velocities [m/s]; the tangent vector in the same units. The
   !> force terms of the current position are kept (the first kick of a step reuses
   !> those of the last kick of the previous one).
   type :: tangent_lanes_t
      integer :: n = 0  !! lanes in use (1 … size of the arrays)
      real(wp), allocatable :: x(:)    !! horizontal position
      real(wp), allocatable :: z(:)    !! downward position
      real(wp), allocatable :: vx(:)   !! x'
      real(wp), allocatable :: vz(:)   !! z'
      real(wp), allocatable :: dx(:)   !! tangent vector: δx
      real(wp), allocatable :: dz(:)   !! δz
      real(wp), allocatable :: dvx(:)  !! δx'
      real(wp), allocatable :: dvz(:)  !! δz'
      real(wp), allocatable :: w2(:)   !! ω² of the lane's pendulum
      real(wp), allocatable :: w2r0(:) !! ω² r0
      real(wp), allocatable :: r0(:)   !! r0
      real(wp), allocatable :: g(:)    !! g
      real(wp), allocatable :: h(:)    !! the lane's step [s]
      real(wp), allocatable :: r(:)    !! r at the current position
      real(wp), allocatable :: c(:)    !! ω²(1 − r0/r) at the current position
      real(wp), allocatable :: q(:)    !! ω² r0/r³ at the current position
      integer(int64) :: n_evaluations = 0  !! force evaluations per lane so far (all lanes step together)
   end type tangent_lanes_t

contains

   !> The coefficients of scheme `id` (a scheme with id 0 when `id` is unknown).
   pure function symplectic_scheme(id) result(scheme)
      integer, intent(in) :: id  !! one of the symplectic_* constants
      type(symplectic_scheme_t) :: scheme
      real(wp), parameter :: cbrt2 = 2.0_wp**(1.0_wp/3.0_wp)
      ! Yoshida (1990) Table 1, solution A: w1, w2, w3; w0 = 1 − 2(w1 + w2 + w3)
      real(wp), parameter :: y6(3) = [-1.17767998417887_wp, 0.235573213359357_wp, 0.784513610477560_wp]
      ! McLachlan (1995) SS17: the first eight of the 17 symmetric weights
      real(wp), parameter :: ss17(8) = [0.12886597938144329897_wp, 0.5815140871052509624_wp, &
         -0.41017537146985013753_wp, 0.1851469357165877327_wp, -0.40955234342085141934_wp, &
         0.14440594108001204106_wp, 0.27833550039367965131_wp, 0.31495668391629485789_wp]
      ! Blanes & Moan (2002) SRKN6b: a1, a2 (a3 = 1/2 − a1 − a2), b1 … b3 (b4 = 1 − 2(b1 + b2 + b3))
      real(wp), parameter :: bm4_a(2) = [0.245298957184271_wp, 0.604872665711080_wp]
      real(wp), parameter :: bm4_b(3) = [0.0829844064174052_wp, 0.396309801498368_wp, -0.0390563049223486_wp]
      ! Blanes & Moan (2002) SRKN11b: a1 … a5 (a6 = 1 − 2Σ), b1 … b5 (b6 = b7 = 1/2 − Σ)
      real(wp), parameter :: bm6_a(5) = [0.123229775946271_wp, 0.290553797799558_wp, -0.127049212625417_wp, &
         -0.246331761062075_wp, 0.357208872795928_wp]
      real(wp), parameter :: bm6_b(5) = [0.0414649985182624_wp, 0.198128671918067_wp, -0.0400061921041533_wp, &
         0.0752539843015807_wp, -0.0115113874206879_wp]
      select case (id)
      case (symplectic_leapfrog)
         scheme = composition(id, 2, [1.0_wp])
      case (symplectic_yoshida4)
         scheme = composition(id, 4, [1.0_wp/(2.0_wp - cbrt2), -cbrt2/(2.0_wp - cbrt2), 1.0_wp/(2.0_wp - cbrt2)])
      case (symplectic_yoshida6)
         scheme = composition(id, 6, [y6(3), y6(2), y6(1), 1.0_wp - 2.0_wp*sum(y6), y6(1), y6(2), y6(3)])
      case (symplectic_mclachlan8)
         scheme = composition(id, 8, [ss17, 1.0_wp - 2.0_wp*sum(ss17), ss17(8:1:-1)])
      case (symplectic_blanes_moan4)
         scheme = direct(id, 4, [bm4_a, 0.5_wp - sum(bm4_a)], [bm4_b, 1.0_wp - 2.0_wp*sum(bm4_b)])
      case (symplectic_blanes_moan6)
         scheme = direct(id, 6, [bm6_a, 1.0_wp - 2.0_wp*sum(bm6_a)], [bm6_b, 0.5_wp - sum(bm6_b)])
      case default
         scheme = symplectic_scheme_t()
      end select
   contains
      !> A symmetric composition of Störmer–Verlet steps with weights γ: a_i = γ_i,
      !> b₁ = γ₁/2, b_i = (γ_{i−1} + γ_i)/2, b_{s+1} = γ_s/2.
      pure function composition(id, order, gamma) result(s)
         integer, intent(in) :: id, order
         real(wp), intent(in) :: gamma(:)
         type(symplectic_scheme_t) :: s
         integer :: i, m
         m = size(gamma)
         s%id = id
         s%order = order
         s%stages = m
         s%drift(1:m) = gamma
         s%kick(1) = 0.5_wp*gamma(1)
         do i = 2, m
            s%kick(i) = 0.5_wp*(gamma(i - 1) + gamma(i))
         end do
         s%kick(m + 1) = 0.5_wp*gamma(m)
      end function composition
      !> A symmetric SRKN scheme from its first half: drifts a₁ … a_⌈s/2⌉ and kicks
      !> b₁ … b_⌈(s+1)/2⌉ (the middle one last), mirrored.
      pure function direct(id, order, half_drift, half_kick) result(s)
         integer, intent(in) :: id, order
         real(wp), intent(in) :: half_drift(:), half_kick(:)
         type(symplectic_scheme_t) :: s
         integer :: m, nd, nk
         ! s drifts: s even → the two middle drifts equal (half_drift holds s/2 values); s odd →
         ! one middle drift. Likewise for the s + 1 kicks.
         nd = size(half_drift)
         nk = size(half_kick)
         s%id = id
         s%order = order
         if (nk == nd + 1) then
            ! s = 2 nd drifts (even), s + 1 = 2 nk − 1 kicks (odd, one middle kick)
            m = 2*nd
            s%drift(1:nd) = half_drift
            s%drift(nd + 1:m) = half_drift(nd:1:-1)
            s%kick(1:nk) = half_kick
            s%kick(nk + 1:m + 1) = half_kick(nk - 1:1:-1)
         else
            ! s = 2 nd − 1 drifts (odd, one middle drift), s + 1 = 2 nk kicks (even)
            m = 2*nd - 1
            s%drift(1:nd) = half_drift
            s%drift(nd + 1:m) = half_drift(nd - 1:1:-1)
            s%kick(1:nk) = half_kick
            s%kick(nk + 1:m + 1) = half_kick(nk:1:-1)
         end if
         s%stages = m
      end function direct
   end function symplectic_scheme

   !> Name of scheme `id` ("" when unknown).
   pure function symplectic_scheme_name(id) result(name)
      integer, intent(in) :: id  !! one of the symplectic_* constants
      character(len=:), allocatable :: name
      select case (id)
      case (symplectic_leapfrog); name = "leapfrog"
      case (symplectic_yoshida4); name = "yoshida4"
      case (symplectic_yoshida6); name = "yoshida6"
      case (symplectic_blanes_moan4); name = "blanes_moan4"
      case (symplectic_blanes_moan6); name = "blanes_moan6"
      case (symplectic_mclachlan8); name = "mclachlan8"
      case default; name = ""
      end select
   end function symplectic_scheme_name

   !> The id of the scheme named `name` (0 when unknown), for readers of scene variables.
   pure integer function symplectic_scheme_id(name) result(id)
      character(len=*), intent(in) :: name  !! a scheme's name (`symplectic_scheme_name`)
      do id = 1, symplectic_scheme_count
         if (symplectic_scheme_name(id) == trim(name)) return
      end do
      id = 0
   end function symplectic_scheme_id

   !> Room for `capacity` lanes (none in use).
   pure subroutine lanes_allocate(lanes, capacity)
      type(tangent_lanes_t), intent(out) :: lanes  !! the lanes
      integer, intent(in) :: capacity              !! number of lanes (≥ 1)
      integer :: m
      m = max(1, capacity)
      allocate (lanes%x(m), lanes%z(m), lanes%vx(m), lanes%vz(m), lanes%dx(m), lanes%dz(m), lanes%dvx(m), &
         lanes%dvz(m), lanes%w2(m), lanes%w2r0(m), lanes%r0(m), lanes%g(m), lanes%h(m), lanes%r(m), lanes%c(m), &
         lanes%q(m))
      lanes%x = 0.0_wp; lanes%z = 1.0_wp; lanes%vx = 0.0_wp; lanes%vz = 0.0_wp
      lanes%dx = 0.0_wp; lanes%dz = 0.0_wp; lanes%dvx = 0.0_wp; lanes%dvz = 0.0_wp
      lanes%w2 = 0.0_wp; lanes%w2r0 = 0.0_wp; lanes%r0 = 0.0_wp; lanes%g = 0.0_wp; lanes%h = 0.0_wp
      lanes%n = 0
      lanes%n_evaluations = 0
      call lanes_force(lanes, 1, m)
   end subroutine lanes_allocate

   !> Put an orbit into lane `k` (k ≤ size of the arrays; lanes%n grows to k if smaller):
   !> its pendulum, state, tangent vector and step. The force at the new position is
   !> evaluated here (not counted in n_evaluations).
   pure subroutine lanes_load(lanes, k, p, y, d, h)
      type(tangent_lanes_t), intent(inout) :: lanes  !! the lanes
      integer, intent(in) :: k                     !! the lane
      type(pendulum_t), intent(in) :: p            !! its pendulum (damping ignored: ε = 0 assumed)
      real(wp), intent(in) :: y(4)                 !! state (x, z, x', z'), r > 0
      real(wp), intent(in) :: d(4)                 !! tangent vector (δx, δz, δx', δz')
      real(wp), intent(in) :: h                    !! step [s]
      lanes%x(k) = y(1); lanes%z(k) = y(2); lanes%vx(k) = y(3); lanes%vz(k) = y(4)
      lanes%dx(k) = d(1); lanes%dz(k) = d(2); lanes%dvx(k) = d(3); lanes%dvz(k) = d(4)
      lanes%w2(k) = p%omega**2
      lanes%w2r0(k) = p%omega**2*p%r0
      lanes%r0(k) = p%r0
      lanes%g(k) = p%g
      lanes%h(k) = h
      lanes%n = max(lanes%n, k)
      call lanes_force(lanes, k, k)
   end subroutine lanes_load

   !> State and tangent vector of lane k.
   pure subroutine lanes_state(lanes, k, y, d)
      type(tangent_lanes_t), intent(in) :: lanes  !! the lanes
      integer, intent(in) :: k                    !! the lane
      real(wp), intent(out) :: y(4)               !! (x, z, x', z')
      real(wp), intent(out) :: d(4)               !! (δx, δz, δx', δz')
      y = [lanes%x(k), lanes%z(k), lanes%vx(k), lanes%vz(k)]
      d = [lanes%dx(k), lanes%dz(k), lanes%dvx(k), lanes%dvz(k)]
   end subroutine lanes_state

   !> Energy per unit mass of every lane in use, from the kept r:
   !> E = ½|v|² + ½ω²(r − r0)² − g z (as `pendulum_energy`).
   pure subroutine lanes_energy(lanes, e)
      type(tangent_lanes_t), intent(in) :: lanes  !! the lanes
      real(wp), intent(out) :: e(:)               !! E of lanes 1 … lanes%n
      integer :: l
      do l = 1, lanes%n
         e(l) = 0.5_wp*(lanes%vx(l)**2 + lanes%vz(l)**2) + 0.5_wp*lanes%w2(l)*(lanes%r(l) - lanes%r0(l))**2 - &
                lanes%g(l)*lanes%z(l)
      end do
   end subroutine lanes_energy

   !> One step of `scheme` in every lane in use, each with its own h: the orbit by the
   !> scheme, the tangent vector by its derivative (module description). s force
   !> evaluations per lane (the first kick uses the force kept from the previous one).
   !> Each stage is one loop over the lanes (force, kick, drift fused), so that a lane's
   !> values stay in registers from one operation to the next.
   pure subroutine lanes_step(scheme, lanes)
      type(symplectic_scheme_t), intent(in) :: scheme  !! the scheme
      type(tangent_lanes_t), intent(inout) :: lanes    !! advanced by one step
      integer :: i, l, n
      real(wp) :: hb, ha, c, q, inv_r, w, dot
      n = lanes%n
      ! stage 1 with the force kept from the last kick; the stages after it evaluate the
      ! force first (two loops rather than a test in one: the test would stop the loop
      ! from being vectorised)
      do l = 1, n
         hb = lanes%h(l)*scheme%kick(1)
         ha = lanes%h(l)*scheme%drift(1)
         c = lanes%c(l)
         q = lanes%q(l)
         ! kick: v += hb F, δv −= hb ∇²V δx with ∇²V = c I + q x xᵀ; then drift: x += ha v, δx += ha δv
         lanes%vx(l) = lanes%vx(l) - hb*c*lanes%x(l)
         lanes%vz(l) = lanes%vz(l) - hb*(c*lanes%z(l) - lanes%g(l))
         dot = q*(lanes%x(l)*lanes%dx(l) + lanes%z(l)*lanes%dz(l))
         lanes%dvx(l) = lanes%dvx(l) - hb*(c*lanes%dx(l) + dot*lanes%x(l))
         lanes%dvz(l) = lanes%dvz(l) - hb*(c*lanes%dz(l) + dot*lanes%z(l))
         lanes%x(l) = lanes%x(l) + ha*lanes%vx(l)
         lanes%z(l) = lanes%z(l) + ha*lanes%vz(l)
         lanes%dx(l) = lanes%dx(l) + ha*lanes%dvx(l)
         lanes%dz(l) = lanes%dz(l) + ha*lanes%dvz(l)
      end do
      do i = 2, scheme%stages
         do l = 1, n
            hb = lanes%h(l)*scheme%kick(i)
            ha = lanes%h(l)*scheme%drift(i)
            ! sqrt(x² + z²) rather than hypot: |x|, |z| ≲ ρ (as in pendulum_rhs)
            inv_r = 1.0_wp/sqrt(lanes%x(l)**2 + lanes%z(l)**2)
            w = lanes%w2r0(l)*inv_r
            c = lanes%w2(l) - w
            q = w*inv_r*inv_r
            ! the same kick and drift as stage 1
            lanes%vx(l) = lanes%vx(l) - hb*c*lanes%x(l)
            lanes%vz(l) = lanes%vz(l) - hb*(c*lanes%z(l) - lanes%g(l))
            dot = q*(lanes%x(l)*lanes%dx(l) + lanes%z(l)*lanes%dz(l))
            lanes%dvx(l) = lanes%dvx(l) - hb*(c*lanes%dx(l) + dot*lanes%x(l))
            lanes%dvz(l) = lanes%dvz(l) - hb*(c*lanes%dz(l) + dot*lanes%z(l))
            lanes%x(l) = lanes%x(l) + ha*lanes%vx(l)
            lanes%z(l) = lanes%z(l) + ha*lanes%vz(l)
            lanes%dx(l) = lanes%dx(l) + ha*lanes%dvx(l)
            lanes%dz(l) = lanes%dz(l) + ha*lanes%dvz(l)
         end do
      end do
      ! the last kick, its force kept for the next step
      call lanes_force(lanes, 1, n)
      i = scheme%stages + 1
      do l = 1, n
         hb = lanes%h(l)*scheme%kick(i)
         lanes%vx(l) = lanes%vx(l) - hb*lanes%c(l)*lanes%x(l)
         lanes%vz(l) = lanes%vz(l) - hb*(lanes%c(l)*lanes%z(l) - lanes%g(l))
         dot = lanes%q(l)*(lanes%x(l)*lanes%dx(l) + lanes%z(l)*lanes%dz(l))
         lanes%dvx(l) = lanes%dvx(l) - hb*(lanes%c(l)*lanes%dx(l) + dot*lanes%x(l))
         lanes%dvz(l) = lanes%dvz(l) - hb*(lanes%c(l)*lanes%dz(l) + dot*lanes%z(l))
      end do
      lanes%n_evaluations = lanes%n_evaluations + scheme%stages
   end subroutine lanes_step

   !> r, c = ω²(1 − r0/r) and q = ω² r0/r³ at the current positions of lanes first … last.
   !> F = −c (x, z) + (0, g) and ∇²V = c I + q x xᵀ follow from them.
   pure subroutine lanes_force(lanes, first, last)
      type(tangent_lanes_t), intent(inout) :: lanes
      integer, intent(in) :: first, last
      integer :: l
      real(wp) :: r2, inv_r, w
      do l = first, last
         ! sqrt(x² + z²) rather than hypot: |x|, |z| ≲ ρ (as in pendulum_rhs)
         r2 = lanes%x(l)**2 + lanes%z(l)**2
         lanes%r(l) = sqrt(r2)
         inv_r = 1.0_wp/lanes%r(l)
         w = lanes%w2r0(l)*inv_r
         lanes%c(l) = lanes%w2(l) - w
         lanes%q(l) = w*inv_r*inv_r
      end do
   end subroutine lanes_force

   !> `n` steps of size h of `scheme` from state y with tangent vectors d(:, k) (each
   !> advanced by the same tangent map): the one-orbit form of `lanes_step`, for tests
   !> and small uses. Damping is ignored (ε = 0 assumed).
   pure subroutine symplectic_steps(p, scheme, h, n, y, d, n_evaluations)
      type(pendulum_t), intent(in) :: p                 !! the pendulum
      type(symplectic_scheme_t), intent(in) :: scheme   !! the scheme
      real(wp), intent(in) :: h                         !! step [s] (negative: backwards)
      integer, intent(in) :: n                          !! number of steps
      real(wp), intent(inout) :: y(4)                   !! state (x, z, x', z')
      real(wp), intent(inout), optional :: d(:, :)      !! tangent vectors (4, m)
      integer(int64), intent(out), optional :: n_evaluations  !! force evaluations (per tangent vector)
      type(tangent_lanes_t) :: lanes
      real(wp) :: unused(4), zero(4)
      integer :: k, m, j
      m = 1
      if (present(d)) m = max(1, size(d, 2))
      call lanes_allocate(lanes, m)
      zero = 0.0_wp
      do k = 1, m
         if (present(d)) then
            call lanes_load(lanes, k, p, y, d(:, k), h)
         else
            call lanes_load(lanes, k, p, y, zero, h)
         end if
      end do
      do j = 1, n
         call lanes_step(scheme, lanes)
      end do
      do k = 1, m
         if (present(d)) then
            call lanes_state(lanes, k, y, d(:, k))
         else
            call lanes_state(lanes, k, y, unused)
         end if
      end do
      if (present(n_evaluations)) n_evaluations = lanes%n_evaluations
   end subroutine symplectic_steps
end module hillstab_pendulum_symplectic

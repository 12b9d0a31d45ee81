!> The options, the verdict rule and the per-orbit bookkeeping of the chaos indicators
!> (hillstab_pendulum_chaos): finite-time Lyapunov exponent, MEGNO and FLI from one
!> tangent vector, kept for several orbits at once as structure of arrays (`track_t`, one
!> lane per orbit), whichever integrator advances them (the symplectic lanes or DOP853).
!> Its own module so that the per-step loop over the lanes (`sample_lanes`) is compiled
!> apart from the driver and vectorised.
!>
!> MEGNO (Cincotta & Simó, A&AS 147 (2000) 205, eq. (2)–(3)), t in radial periods:
!> Y(t) = (2/t) ∫₀ᵗ s (δ̇·δ)/(δ·δ) ds, ⟨Y⟩(t) = (1/t) ∫₀ᵗ Y ds, both integrals by the
!> trapezoidal rule over the integrator's steps (`megno_step`), with the norm
!> ‖δ‖² = δx² + δz² + (δx'² + δz'²)/ω² of `tangent_norm`.
!>
!>```fortran
!> type(chaos_options_t) :: options
!> real(wp) :: verdict
!> logical :: certain
!> call chaos_verdict(options, 300, 300, 2.1_wp, 1.9_wp, 4.0_wp, verdict, certain)   ! verdict = 0 (regular)
!>```
module hillstab_pendulum_chaos_track
   use hillstab_core_kinds, only: wp, int64
   use hillstab_pendulum_equations, only: pendulum_t, pendulum_energy, pendulum_energy_scale, pendulum_jacobian, &
      pendulum_radius, px, pz, pvx
   use hillstab_pendulum_symplectic, only: symplectic_blanes_moan6, tangent_lanes_t
   implicit none
   private
   public :: chaos_options_t, chaos_verdict, chaos_verdict_rule, chaos_transient_allowance
   public :: chaos_auto, chaos_symplectic, chaos_dop853
   public :: track_t, track_allocate, track_start, track_period_end, track_move, sample_lanes, megno_step, growth_rate
   public :: track_go_on, track_finish, track_refine

   !> Integrator choice: symplectic where it holds the accuracy, else DOP853.
   integer, parameter :: chaos_auto = 0
   !> Integrator choice: fixed-step symplectic scheme with its tangent map (undamped only).
   integer, parameter :: chaos_symplectic = 1
   !> Integrator choice: DOP853 on the trajectory and the variational equations.
   integer, parameter :: chaos_dop853 = 2

   !> Options of `chaos_indicators`. The defaults give the fastest correct verdicts on the
   !> physical domain from the paper's start (φ0 = 0.017 at rest); see the guide page *Chaos*.
   type :: chaos_options_t
      integer :: integrator = chaos_auto  !! chaos_auto, chaos_symplectic or chaos_dop853
      !> symplectic scheme (a symplectic_* constant of hillstab_pendulum_symplectic)
      integer :: scheme = symplectic_blanes_moan6
      !> steps per radial period of the symplectic scheme: > 0 fixed, 0 from the orbit
      !> (`chaos_steps_per_period`)
      integer :: steps_per_period = 0
      !> the step rule's steps per radial period for a gentle orbit (see `chaos_steps_per_period`)
      real(wp) :: base_steps = 8.0_wp
      !> largest energy error |E − E(0)| along the orbit, over the sum of the energy terms'
      !> magnitudes at t = 0, that a symplectic run may reach
      real(wp) :: energy_tolerance = 1.0e-6_wp
      !> most steps per radial period a symplectic run may take (auto: more → DOP853)
      integer :: max_steps_per_period = 256
      logical :: early_stop = .true.  !! stop an orbit as soon as its verdict is certain
      !> ⟨Y⟩ above this at the end: chaotic (`chaos_verdict`)
      real(wp) :: megno_chaotic = 3.5_wp
      !> ⟨Y⟩ below this at the end: regular (`chaos_verdict`)
      real(wp) :: megno_regular = 3.0_wp
      !> early stop as chaotic once ⟨Y⟩ exceeds this plus the start's transient allowance
      !> and still grows (`chaos_verdict`)
      real(wp) :: megno_stop = 4.0_wp
      !> no early stop before this many radial periods
      integer :: min_periods = 10
      !> orbits advanced together by `chaos_indicators_batch`
      integer :: lanes = 16
   end type chaos_options_t

   !> What the runs keep per orbit, one lane each (structure of arrays: the per-step
   !> updates run over the lanes in vectorised loops).
   type :: track_t
      integer, allocatable :: point(:)   !! the orbit's index in the batch (0: lane free)
      integer, allocatable :: steps(:)   !! symplectic steps per radial period
      integer, allocatable :: step(:)    !! steps made in the current period
      integer, allocatable :: done(:)    !! radial periods completed
      integer, allocatable :: attempts(:) !! symplectic runs begun
      real(wp), allocatable :: dt(:)     !! step in radial periods (1/steps)
      real(wp), allocatable :: t(:)      !! time in radial periods
      real(wp), allocatable :: period(:) !! the radial period T [s]
      real(wp), allocatable :: inv_w2(:) !! 1/ω²
      real(wp), allocatable :: e0(:)     !! E(0)
      real(wp), allocatable :: scale(:)  !! the sum of the energy terms' magnitudes at t = 0
      real(wp), allocatable :: allowance(:)  !! the start's transient allowance (`chaos_verdict`)
      real(wp), allocatable :: de(:)     !! largest |E − E(0)|
      real(wp), allocatable :: swing_x(:)  !! the largest angle seen as the pair (|x|, r + z):
      real(wp), allocatable :: swing_w(:)  !! tan(|φ|/2) = |x|/(r + z), compared without division
      real(wp), allocatable :: rate(:)   !! T (δ̇·δ)/(δ·δ) at the last sample
      real(wp), allocatable :: j1(:)     !! ∫₀ᵗ s (δ̇·δ)/(δ·δ) ds
      real(wp), allocatable :: y(:)      !! Y at the last sample
      real(wp), allocatable :: i2(:)     !! ∫₀ᵗ Y ds
      real(wp), allocatable :: level(:)  !! ln‖δ‖ summed over the renormalisations
      real(wp), allocatable :: fli(:)    !! max of level at the period ends
      integer(int64), allocatable :: evaluations(:)  !! of the runs before the current one
      real(wp), allocatable :: growth(:, :)  !! (periods, lane): ln growth per period
      real(wp), allocatable :: megno(:, :)   !! (periods, lane): ⟨Y⟩ at the period ends
   end type track_t

   !> What a period end asks of the run: go on.
   integer, parameter :: track_go_on = 0
   !> What a period end asks of the run: the orbit is done (verdict certain or periods reached).
   integer, parameter :: track_finish = 1
   !> What a period end asks of the run: repeat the orbit with a finer step (energy error).
   integer, parameter :: track_refine = 2

contains

   !> The verdict rule in words, with the thresholds of `options` (for file headers; under
   !> 240 characters).
   function chaos_verdict_rule(options) result(text)
      type(chaos_options_t), intent(in) :: options  !! the thresholds
      character(len=:), allocatable :: text  !! one line
      character(len=300) :: buffer
      write (buffer, '(a,f0.2,a,f0.2,a,f0.2,a,i0,a)') "chaotic: 1 if megno > ", options%megno_chaotic, &
         " at the end, 0 if < ", options%megno_regular, ", else 0.5; stopped early as 1 once megno > ", &
         options%megno_stop, " + ln(rho/s0) (s0 = max(|x0|, |x0'|/omega)) and >= 1.5 x megno at half the time, after ", &
         options%min_periods, " periods"
      text = trim(buffer)
   end function chaos_verdict_rule

   !> The transient allowance of a start: A = ln(ρ/s0) with s0 = max(|x0|, |x0'|/ω) the
   !> initial swing (0 when s0 = 0 or s0 ≥ ρ). While the swing grows linearly about an
   !> unstable bounce, the tangent vector grows with it, by about ρ/s0 in all before the
   !> swing saturates; on a regular orbit that transient lifts ⟨Y⟩ by up to about 0.6 A
   !> (the peak of (1/t)(L₁t₁/2 + L₁t₁ ln(t/t₁)) for a growth L₁ = A that stops at t₁),
   !> so an early verdict must clear it.
   pure real(wp) function chaos_transient_allowance(p, y0) result(allowance)
      type(pendulum_t), intent(in) :: p  !! the pendulum
      real(wp), intent(in) :: y0(4)      !! the start (x, z, x', z')
      real(wp) :: swing
      swing = max(abs(y0(px)), abs(y0(pvx))/p%omega)
      allowance = 0.0_wp
      if (swing > 0.0_wp .and. swing < p%rho) allowance = log(p%rho/swing)
   end function chaos_transient_allowance

   !> The verdict from MEGNO after n radial periods, and whether it is certain.
   !>
   !> At the end (n = periods): chaotic (1) if ⟨Y⟩ > megno_chaotic, regular (0) if
   !> ⟨Y⟩ < megno_regular, undecided (0.5) between. ⟨Y⟩ tends to 2 on a quasi-periodic
   !> orbit (0 on a stable periodic one) and grows like λn/2 on a chaotic one; the
   !> defaults 3 and 3.5 were set on a 40 × 40 map of the physical domain at 300 periods,
   !> where the regular orbits' ⟨Y⟩ reached 2.5 and the chaotic ones' started at 3.7
   !> (apart from sticky orbits, which look regular for hundreds of periods). A chaotic
   !> orbit with λ ≲ 7/n stays below 3.5 after n periods.
   !>
   !> Before the end the verdict is certain (the orbit may stop) only as chaotic, once
   !> n ≥ min_periods, ⟨Y⟩(n) > megno_stop + A (A the start's transient allowance,
   !> `chaos_transient_allowance`) and ⟨Y⟩(n) ≥ 1.5 ⟨Y⟩(⌈n/2⌉): ⟨Y⟩ still grows linearly
   !> (the ratio tends to 2 on a chaotic orbit), whereas on a regular orbit it falls back
   !> towards 2 once the swing has saturated. A regular orbit is never stopped early: a
   !> sticky orbit looks regular for hundreds of periods before it is not.
   pure subroutine chaos_verdict(options, n, periods, megno_now, megno_half, allowance, verdict, certain)
      type(chaos_options_t), intent(in) :: options  !! the thresholds
      integer, intent(in) :: n          !! radial periods so far
      integer, intent(in) :: periods    !! radial periods asked
      real(wp), intent(in) :: megno_now   !! ⟨Y⟩(n)
      real(wp), intent(in) :: megno_half  !! ⟨Y⟩(⌈n/2⌉)
      real(wp), intent(in) :: allowance   !! the start's transient allowance A
      real(wp), intent(out) :: verdict  !! 1, 0 or 0.5
      logical, intent(out) :: certain   !! the verdict is final: the orbit may stop here
      certain = .false.
      if (n >= options%min_periods .and. megno_now > options%megno_stop + allowance .and. &
          megno_now >= 1.5_wp*megno_half) then
         verdict = 1.0_wp
         certain = .true.
      else if (megno_now > options%megno_chaotic) then
         verdict = 1.0_wp
      else if (megno_now < options%megno_regular) then
         verdict = 0.0_wp
      else
         verdict = 0.5_wp
      end if
      if (n >= periods) certain = .true.
   end subroutine chaos_verdict

   !> Room for `capacity` lanes of `periods` periods.
   pure subroutine track_allocate(track, capacity, periods)
      type(track_t), intent(out) :: track  !! the bookkeeping
      integer, intent(in) :: capacity      !! lanes
      integer, intent(in) :: periods       !! radial periods asked
      allocate (track%point(capacity), track%steps(capacity), track%step(capacity), track%done(capacity), &
         track%attempts(capacity), track%dt(capacity), track%t(capacity), track%period(capacity), &
         track%inv_w2(capacity), track%e0(capacity), track%scale(capacity), track%allowance(capacity), &
         track%de(capacity), track%swing_x(capacity), &
         track%swing_w(capacity), track%rate(capacity), track%j1(capacity), track%y(capacity), track%i2(capacity), &
         track%level(capacity), track%fli(capacity), track%evaluations(capacity), &
         track%growth(periods, capacity), track%megno(periods, capacity))
      track%point = 0
      track%attempts = 0
      track%evaluations = 0
   end subroutine track_allocate

   !> Start lane k: orbit `point` of pendulum p from y0 with tangent vector d0 (‖d0‖ = 1).
   pure subroutine track_start(track, k, point, p, y0, d0, steps)
      type(track_t), intent(inout) :: track  !! the bookkeeping
      integer, intent(in) :: k               !! the lane
      integer, intent(in) :: point           !! the orbit's index in the batch
      type(pendulum_t), intent(in) :: p      !! its pendulum
      real(wp), intent(in) :: y0(4)          !! its start (x, z, x', z')
      real(wp), intent(in) :: d0(4)          !! the initial tangent vector (norm 1)
      integer, intent(in) :: steps           !! symplectic steps per period (1 for DOP853: dt unused)
      track%point(k) = point
      track%steps(k) = steps
      track%step(k) = 0
      track%done(k) = 0
      track%attempts(k) = track%attempts(k) + 1
      track%dt(k) = 1.0_wp/steps
      track%t(k) = 0.0_wp
      track%period(k) = p%period
      track%inv_w2(k) = 1.0_wp/p%omega**2
      track%e0(k) = pendulum_energy(p, y0)
      track%scale(k) = max(pendulum_energy_scale(p, y0), tiny(1.0_wp))
      track%allowance(k) = chaos_transient_allowance(p, y0)
      track%de(k) = 0.0_wp
      track%swing_x(k) = abs(y0(px))
      track%swing_w(k) = pendulum_radius(y0) + y0(pz)
      track%rate(k) = track%period(k)*growth_rate(d0, pendulum_jacobian(p, y0), track%inv_w2(k))
      track%j1(k) = 0.0_wp
      track%y(k) = 0.0_wp
      track%i2(k) = 0.0_wp
      track%level(k) = 0.0_wp
      track%fli(k) = 0.0_wp
   end subroutine track_start

   !> (δ̇·δ)/(δ·δ) in the norm ‖δ‖² = δx² + δz² + (δx'² + δz'²)/ω², δ̇ = J δ.
   pure real(wp) function growth_rate(d, jac, inv_w2) result(rate)
      real(wp), intent(in) :: d(4)         !! tangent vector δ
      real(wp), intent(in) :: jac(4, 4)    !! J at the state
      real(wp), intent(in) :: inv_w2       !! 1/ω²
      real(wp) :: dd(4)
      dd = matmul(jac, d)
      rate = (d(1)*dd(1) + d(2)*dd(2) + (d(3)*dd(3) + d(4)*dd(4))*inv_w2)/ &
             (d(1)**2 + d(2)**2 + (d(3)**2 + d(4)**2)*inv_w2)
   end function growth_rate

   !> The MEGNO integrals over one step ending at t (radial periods) of length dt, with
   !> rate = T (δ̇·δ)/(δ·δ) at its end: J₁ = ∫ s·rate ds and I₂ = ∫ Y ds, Y = 2 J₁/t, by the
   !> trapezoidal rule. Elemental: the lanes update all their orbits in one loop.
   elemental subroutine megno_step(t, dt, rate_new, rate, j1, y, i2)
      real(wp), intent(in) :: t         !! end of the step [radial periods]
      real(wp), intent(in) :: dt        !! its length [radial periods]
      real(wp), intent(in) :: rate_new  !! T (δ̇·δ)/(δ·δ) at t
      real(wp), intent(inout) :: rate   !! the same at t − dt in, at t out
      real(wp), intent(inout) :: j1     !! J₁(t − dt) in, J₁(t) out
      real(wp), intent(inout) :: y      !! Y(t − dt) in, Y(t) out
      real(wp), intent(inout) :: i2     !! I₂(t − dt) in, I₂(t) out
      real(wp) :: y_new
      j1 = j1 + 0.5_wp*dt*((t - dt)*rate + t*rate_new)
      y_new = 2.0_wp*j1/t
      i2 = i2 + 0.5_wp*dt*(y + y_new)
      y = y_new
      rate = rate_new
   end subroutine megno_step

   !> The end of a radial period in lane k, where the tangent vector had norm `norm`
   !> (the caller divides it by norm): growth, level, FLI, ⟨Y⟩; what the run must do next.
   pure subroutine track_period_end(track, k, norm, periods, options, action)
      type(track_t), intent(inout) :: track          !! the bookkeeping
      integer, intent(in) :: k                       !! the lane
      real(wp), intent(in) :: norm                   !! ‖δ‖ at the period's end (> 0, finite)
      integer, intent(in) :: periods                 !! radial periods asked
      type(chaos_options_t), intent(in) :: options   !! thresholds, early stop
      integer, intent(out) :: action                 !! track_go_on or track_finish
      real(wp) :: verdict
      integer :: n
      logical :: certain
      n = track%done(k) + 1
      track%done(k) = n
      track%step(k) = 0
      track%t(k) = real(n, wp)
      track%growth(n, k) = log(norm)
      track%level(k) = track%level(k) + track%growth(n, k)
      track%fli(k) = max(track%fli(k), track%level(k))
      track%megno(n, k) = track%i2(k)/track%t(k)
      call chaos_verdict(options, n, periods, track%megno(n, k), track%megno((n + 1)/2, k), track%allowance(k), verdict, &
         certain)
      action = track_go_on
      if (certain .and. (options%early_stop .or. n >= periods)) action = track_finish
   end subroutine track_period_end

   !> Copy lane `from` of the track into lane `to` (compaction when lanes empty).
   pure subroutine track_move(track, from, to)
      type(track_t), intent(inout) :: track  !! the bookkeeping
      integer, intent(in) :: from            !! the lane copied
      integer, intent(in) :: to              !! the lane overwritten
      track%point(to) = track%point(from); track%steps(to) = track%steps(from); track%step(to) = track%step(from)
      track%done(to) = track%done(from); track%attempts(to) = track%attempts(from); track%dt(to) = track%dt(from)
      track%t(to) = track%t(from); track%period(to) = track%period(from); track%inv_w2(to) = track%inv_w2(from)
      track%e0(to) = track%e0(from); track%scale(to) = track%scale(from)
      track%allowance(to) = track%allowance(from); track%de(to) = track%de(from); track%swing_x(to) = track%swing_x(from)
      track%swing_w(to) = track%swing_w(from); track%rate(to) = track%rate(from); track%j1(to) = track%j1(from)
      track%y(to) = track%y(from); track%i2(to) = track%i2(from); track%level(to) = track%level(from)
      track%fli(to) = track%fli(from); track%evaluations(to) = track%evaluations(from)
      track%growth(:track%done(from), to) = track%growth(:track%done(from), from)
      track%megno(:track%done(from), to) = track%megno(:track%done(from), from)
   end subroutine track_move

   !> The per-step samples of every lane in use after a step: energy error, largest
   !> angle, MEGNO (δ̇ = (δv, −∇²V δx) at the end of the step from the kept force terms).
   pure subroutine sample_lanes(lanes, track)
      type(tangent_lanes_t), intent(in) :: lanes  !! the lanes after the step
      type(track_t), intent(inout) :: track       !! their bookkeeping
      real(wp) :: energy, dot, ax, az, bx, bz, rate(lanes%n)
      logical :: wider
      integer :: l, n
      n = lanes%n
      track%step(1:n) = track%step(1:n) + 1
      do l = 1, n
         track%t(l) = track%t(l) + track%dt(l)
         energy = 0.5_wp*(lanes%vx(l)**2 + lanes%vz(l)**2) + 0.5_wp*lanes%w2(l)*(lanes%r(l) - lanes%r0(l))**2 - &
                  lanes%g(l)*lanes%z(l)
         track%de(l) = max(track%de(l), abs(energy - track%e0(l)))
         ax = abs(lanes%x(l))
         az = lanes%r(l) + lanes%z(l)
         wider = ax*track%swing_w(l) > track%swing_x(l)*az
         track%swing_x(l) = merge(ax, track%swing_x(l), wider)
         track%swing_w(l) = merge(az, track%swing_w(l), wider)
         dot = lanes%q(l)*(lanes%x(l)*lanes%dx(l) + lanes%z(l)*lanes%dz(l))
         bx = -(lanes%c(l)*lanes%dx(l) + dot*lanes%x(l))
         bz = -(lanes%c(l)*lanes%dz(l) + dot*lanes%z(l))
         rate(l) = track%period(l)*(lanes%dx(l)*lanes%dvx(l) + lanes%dz(l)*lanes%dvz(l) + &
                                    (lanes%dvx(l)*bx + lanes%dvz(l)*bz)*track%inv_w2(l))/ &
                   (lanes%dx(l)**2 + lanes%dz(l)**2 + (lanes%dvx(l)**2 + lanes%dvz(l)**2)*track%inv_w2(l))
      end do
      call megno_step(track%t(1:n), track%dt(1:n), rate, track%rate(1:n), track%j1(1:n), track%y(1:n), track%i2(1:n))
   end subroutine sample_lanes
end module hillstab_pendulum_chaos_track

!> What is measured on the nonlinear pendulum: the Floquet multipliers of the 4×4
!> variational monodromy along the bounce (LAPACK dgeev), the predicted onset of the
!> swing (onset law), and a watching RK system that records, while it integrates, the
!> largest |φ|, the energy error and the first time |φ| exceeds a threshold. Pure
!> numerics, no I/O.
!>
!> The onset law: in the linear phase the swing grows by λ_max (the largest multiplier
!> modulus of the Hill equation, from the core) per radial period, so from φ0 it first
!> reaches φ_sat after about n* = ln(φ_sat/|φ0|)/ln λ_max periods (`onset_periods`).
!>
!>```fortran
!> type(pendulum_watch_t) :: watch
!> type(work_stats_t) :: stats
!> real(wp) :: y(4)
!> call pendulum_from_chart(7.88_wp, 3.95_wp, 0.0_wp, 0.1_wp, 9.81_wp, watch%pendulum, error)
!> y = pendulum_initial_state(watch%pendulum, 1.0e-20_wp)
!> call pendulum_integrate(watch, y, 50*watch%pendulum%period, 1.0e-10_wp, stats, error)
!> print *, watch%onset_time/watch%pendulum%period, watch%max_abs_phi
!>```
module hillstab_pendulum_analysis
   use hillstab_core_kinds, only: wp, int64, pi, pi2
   use hillstab_core_error, only: error_t, set_error, err_invalid_parameter, err_singular
   use hillstab_core_stats, only: work_stats_t
   use hillstab_integrate_rk, only: rk_options_t, rk_step_t, rk_integrate, rk_dense_value, rk_dop853
   use hillstab_pendulum_equations, only: pendulum_t, pendulum_system_t, pendulum_bounce_monodromy, pendulum_angle, &
      pendulum_energy, pendulum_energy_scale, pendulum_atol, px, pvx
   use hillstab_ffi_lapack, only: dgeev
   use hillstab_hill_model, only: hill_point_t
   use hillstab_hill_model_elastic, only: elastic_model_t
   use hillstab_hill_model_elastic, only: one_minus_alpha_over_pi2
   use hillstab_hill_transfer, only: scaled_matrix_t, scaled_identity
   use hillstab_integrate_magnus, only: magnus_step
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   implicit none
   private
   public :: bounce_multipliers_t, bounce_multipliers, onset_periods, linear_onset_periods
   public :: pendulum_watch_t, pendulum_integrate, default_phi_sat

   !> The swing threshold of the onset law: |φ| = 0.1 rad ends the linear phase.
   real(wp), parameter :: default_phi_sat = 0.1_wp
   !> Points of the dense output examined inside every accepted step.
   integer, parameter :: dense_points_per_step = 16

   !> Eigenvalues of the 4×4 monodromy along the bounce, split by their eigenvectors
   !> into the swing pair (x, x') and the radial pair (z, z').
   type :: bounce_multipliers_t
      real(wp) :: monodromy(4, 4) = 0.0_wp     !! the monodromy, rows/columns (x, z, x', z')
      complex(wp) :: swing(2) = (0.0_wp, 0.0_wp)   !! the two multipliers of the swing
      complex(wp) :: radial(2) = (0.0_wp, 0.0_wp)  !! the two of the radial oscillation ({1, 1} undamped)
      real(wp) :: swing_sum = 0.0_wp          !! swing(1) + swing(2): the chart's S when ε = 0
   end type bounce_multipliers_t

   !> The pendulum with observers: the largest |φ| (16 dense points per step), the energy
   !> error against the start at every step end, energy increases (for damped runs), and
   !> the first time |φ| > phi_sat (located on the dense output to round-off). Extend it
   !> and override `observe` (calling `watch_observe` through the parent) to do more.
   type, extends(pendulum_system_t) :: pendulum_watch_t
      real(wp) :: phi_sat = default_phi_sat   !! onset threshold [rad]
      logical :: stop_at_onset = .false.      !! end the integration at the onset
      real(wp) :: max_abs_phi = 0.0_wp        !! largest |φ| seen [rad]
      real(wp) :: time_of_max_phi = 0.0_wp    !! where [s]
      real(wp) :: energy_start = 0.0_wp       !! E at the start [J/kg]
      real(wp) :: energy_scale = 0.0_wp       !! ½|v|² + ½ω²(r − r0)² + g|z| at the start [J/kg]
      real(wp) :: max_energy_error = 0.0_wp   !! max |E − E(0)| over step ends [J/kg]
      !> sample times t_j = j T / samples_per_period, j = 0 … n_samples, whose energies are
      !> also watched (from the dense output, as the series task writes its rows; 0: none)
      integer :: samples_per_period = 0
      integer(int64) :: n_samples = 0                  !! the last sample index j
      integer(int64) :: next_sample = 0                !! the next sample index to watch
      real(wp) :: max_sample_energy_error = 0.0_wp  !! max |E − E(0)| over the sample times [J/kg]
      real(wp) :: energy_last = 0.0_wp        !! E at the last step end
      integer(int64) :: energy_increases = 0  !! steps over which E rose by more than round-off
      real(wp) :: onset_time = -1.0_wp        !! first t with |φ| > phi_sat [s]; < 0: not reached
   contains
      procedure :: observe => watch_observe
   end type pendulum_watch_t

contains

   !> Multipliers of the 4×4 variational monodromy along the bounce (one radial period,
   !> `pendulum_bounce_monodromy`), from LAPACK dgeev. Each eigenvalue is assigned to the
   !> swing or the radial pair by where its eigenvector lives (velocities scaled by 1/ω).
   subroutine bounce_multipliers(p, rtol, result, stats, error)
      type(pendulum_t), intent(in) :: p              !! the pendulum
      real(wp), intent(in) :: rtol                   !! relative tolerance of the integration
      type(bounce_multipliers_t), intent(out) :: result  !! monodromy and multipliers
      type(work_stats_t), intent(out) :: stats       !! work of the integration
      type(error_t), allocatable, intent(out) :: error  !! integration or LAPACK failure; unallocated on success
      real(wp) :: a(4, 4), wr(4), wi(4), vl(1, 1), vr(4, 4), work(64), v(4, 2), weight(4), scale(4)
      integer :: info, j, n_swing, n_radial
      call pendulum_bounce_monodromy(p, rtol, result%monodromy, stats, error)
      if (allocated(error)) return
      a = result%monodromy
      call dgeev("N", "V", 4, a, 4, wr, wi, vl, 1, vr, 4, work, size(work), info)
      if (info /= 0) then
         call set_error(error, err_singular, "bounce_multipliers: dgeev did not converge")
         return
      end if
      scale = [1.0_wp, 1.0_wp, 1.0_wp/p%omega, 1.0_wp/p%omega]
      j = 1
      do while (j <= 4)
         if (wi(j) == 0.0_wp) then
            v(:, 1) = vr(:, j)*scale
            v(:, 2) = 0.0_wp
            weight(j) = swing_weight(v)
            j = j + 1
         else
            v(:, 1) = vr(:, j)*scale
            v(:, 2) = vr(:, j + 1)*scale
            weight(j) = swing_weight(v)
            weight(j + 1) = weight(j)
            j = j + 2
         end if
      end do
      n_swing = 0
      n_radial = 0
      do j = 1, 4
         if (weight(j) > 0.5_wp .and. n_swing < 2) then
            n_swing = n_swing + 1
            result%swing(n_swing) = cmplx(wr(j), wi(j), wp)
         else if (n_radial < 2) then
            n_radial = n_radial + 1
            result%radial(n_radial) = cmplx(wr(j), wi(j), wp)
         else
            n_swing = n_swing + 1
            if (n_swing <= 2) result%swing(n_swing) = cmplx(wr(j), wi(j), wp)
         end if
      end do
      if (n_swing /= 2) then
         call set_error(error, err_singular, "bounce_multipliers: eigenvectors do not separate swing and radial motion")
         return
      end if
      result%swing_sum = real(result%swing(1) + result%swing(2), wp)
   contains
      !> Share of the swing components (x, x'/ω) in an eigenvector (real and imaginary parts).
      pure real(wp) function swing_weight(vec) result(w)
         real(wp), intent(in) :: vec(4, 2)
         real(wp) :: total
         total = sum(vec**2)
         w = 0.0_wp
         if (total > 0.0_wp) w = (sum(vec(px, :)**2) + sum(vec(pvx, :)**2))/total
      end function swing_weight
   end subroutine bounce_multipliers

   !> Predicted number of radial periods until |φ| first reaches phi_sat from phi0,
   !> n* = ln(phi_sat/|phi0|)/ln λ_max. Returns −1 when the swing never grows there
   !> (λ_max ≤ 1, or φ0 = 0: the bounce is an exact solution) and 0 when |φ0| ≥ phi_sat.
   pure real(wp) function onset_periods(phi0, phi_sat, lambda_max) result(n)
      real(wp), intent(in) :: phi0        !! initial angle [rad]
      real(wp), intent(in) :: phi_sat     !! threshold [rad], > 0
      real(wp), intent(in) :: lambda_max  !! largest multiplier modulus per radial period
      if (abs(phi0) >= phi_sat) then
         n = 0.0_wp
      else if (phi0 == 0.0_wp .or. .not. lambda_max > 1.0_wp .or. .not. ieee_is_finite(lambda_max)) then
         n = -1.0_wp
      else
         n = log(phi_sat/abs(phi0))/log(lambda_max)
      end if
   end function onset_periods

   !> The onset of the swing from the linear theory in full: the first time, in radial
   !> periods, at which the linearised swing from the start of eq. (38) reaches |φ| = φ_sat
   !> (−1: never, no growth or φ0 = 0), undamped.
   !>
   !> About the bounce r(τ) = ρ(1 − k cos πτ) (τ = ωt/π, k = α/π²) the swing x = r sin φ
   !> obeys the Hill equation x'' + Q(τ) x = 0 exactly (eq. (20)), and the start at rest
   !> with φ(0) = φ0 is x(0) = r(0) sin φ0, x'(0) = 0: x = r(0) sin φ0 · u(τ), u the even
   !> solution. Over the n-th period u(2n + s) = (Φ(s) Mⁿ e₁)₁ — Φ the propagator within the
   !> period, M = Φ(2) the monodromy, so Mⁿ e₁ = c₊ λⁿ v₊ + c₋ λ⁻ⁿ v₋ carries both Floquet
   !> solutions with the coefficients of the start, and Φ(s) their periodic factors — and
   !> |φ| = φ_sat where |x|/r = sin φ_sat, that is
   !>
   !>   |sin φ0| |u(τ)| (1 − k)/(1 − k cos πτ) = sin φ_sat.
   !>
   !> Φ on 4096 equal Magnus-6 steps of the period; the crossing located between two of
   !> them by linear interpolation. The law n* = ln(φ_sat/|φ0|)/ln λ_max (`onset_periods`)
   !> keeps only the multiplier and comes 0.2–1.1 periods early; this also has the
   !> projection of the start onto the growing solution and where within the period |φ|
   !> peaks. It holds while the swing is linear up to φ_sat: for φ0 ≤ 1e-5 the nonlinear
   !> terms act only over the last fraction of a period; from larger φ0 the swing feeds
   !> back on the bounce before φ_sat (tested: within 0.1 period at φ0 ≤ 1e-5 at the paper's
   !> (b), (e), (g)).
   function linear_onset_periods(alpha, beta, phi0, phi_sat) result(n_onset)
      real(wp), intent(in) :: alpha, beta  !! the chart point, 0 ≤ α < π²
      real(wp), intent(in) :: phi0         !! initial angle [rad]
      real(wp), intent(in) :: phi_sat      !! threshold [rad], 0 < phi_sat < π/2
      real(wp) :: n_onset
      integer, parameter :: steps = 4096
      real(wp) :: p11(0:steps), p12(0:steps), shape(0:steps), m(2, 2), w(2), log_w, h, target, value, before, &
                  big, law, lambda
      type(scaled_matrix_t) :: a
      type(elastic_model_t) :: elastic
      type(hill_point_t) :: point
      integer(int64) :: n_evaluations
      integer :: j, n, n_max
      n_onset = -1.0_wp
      if (phi0 == 0.0_wp .or. .not. (alpha >= 0.0_wp .and. alpha < pi2)) return
      if (abs(phi0) >= phi_sat) then
         n_onset = 0.0_wp
         return
      end if
      point = hill_point_t(alpha, beta, 0.0_wp)
      h = 2.0_wp/steps
      a = scaled_identity()
      n_evaluations = 0
      p11(0) = 1.0_wp
      p12(0) = 0.0_wp
      do j = 1, steps
         call magnus_step(elastic, point, 6, (j - 1)*h, h, a, n_evaluations)
         if (a%log_scale > 600.0_wp) return   ! growth beyond doubles within one period: no prediction
         p11(j) = a%m(1, 1)*exp(a%log_scale)
         p12(j) = a%m(1, 2)*exp(a%log_scale)
      end do
      m = a%m*exp(a%log_scale)
      lambda = 0.5_wp*(abs(m(1, 1) + m(2, 2)) + sqrt(max((m(1, 1) + m(2, 2))**2 - 4.0_wp, 0.0_wp)))
      law = onset_periods(phi0, phi_sat, lambda)
      if (law < 0.0_wp) return
      n_max = min(10**6, ceiling(2.0_wp*law) + 20)
      ! (1 − k)/(1 − k cos πτ) = r(0)/r(τ) at the mesh points
      do j = 0, steps
         shape(j) = one_minus_alpha_over_pi2(alpha)/(one_minus_alpha_over_pi2(alpha) + &
                    2.0_wp*(alpha/pi2)*sin(0.5_wp*pi*j*h)**2)
      end do
      target = sin(phi_sat)/abs(sin(phi0))
      w = [1.0_wp, 0.0_wp]
      log_w = 0.0_wp
      before = shape(0)
      do n = 0, n_max
         do j = 1, steps
            value = exp(log_w)*abs(p11(j)*w(1) + p12(j)*w(2))*shape(j)
            if (value >= target) then
               n_onset = n + ((j - 1) + (target - before)/(value - before))*h/2.0_wp
               return
            end if
            before = value
         end do
         w = matmul(m, w)
         big = maxval(abs(w))
         w = w/big
         log_w = log_w + log(big)
      end do
   end function linear_onset_periods

   !> Integrate `system` (any pendulum system, e.g. a `pendulum_watch_t`) from t = 0 to
   !> t_end with DOP853 and its 7th-order dense output, relative tolerance rtol and the
   !> absolute tolerances of `pendulum_atol` (relative accuracy in a tiny swing). On
   !> return y is the state at t_end (or where an observer stopped).
   subroutine pendulum_integrate(system, y, t_end, rtol, stats, error, t_reached)
      class(pendulum_system_t), intent(inout) :: system  !! the pendulum and its observers
      real(wp), intent(inout) :: y(4)          !! initial state in, final state out
      real(wp), intent(in) :: t_end            !! end time [s]
      real(wp), intent(in) :: rtol             !! relative tolerance (> 0)
      type(work_stats_t), intent(out) :: stats  !! steps, rejections, f-evaluations
      type(error_t), allocatable, intent(out) :: error  !! invalid arguments; integration failure
      real(wp), intent(out), optional :: t_reached  !! where the integration ended [s]
      type(rk_options_t) :: options
      real(wp) :: t
      if (.not. (ieee_is_finite(rtol) .and. rtol > 0.0_wp)) then
         call set_error(error, err_invalid_parameter, "pendulum_integrate: rtol must be > 0")
         return
      end if
      options = rk_options_t(method=rk_dop853, rtol=rtol, atol=rtol, dense_output=.true., max_steps=huge(1))
      options%atol_components = pendulum_atol(system%pendulum, y, rtol)
      t = 0.0_wp
      call rk_integrate(system, t, t_end, y, options, stats, error)
      if (present(t_reached)) t_reached = t
   end subroutine pendulum_integrate

   !> The watching observer: see `pendulum_watch_t`.
   subroutine watch_observe(self, step, stop)
      class(pendulum_watch_t), intent(inout) :: self
      type(rk_step_t), intent(in) :: step
      logical, intent(inout) :: stop
      real(wp) :: e, ts, t_prev, phi, y(4), noise
      integer :: s
      if (step%index == 0) then
         self%energy_start = pendulum_energy(self%pendulum, step%y)
         self%energy_scale = pendulum_energy_scale(self%pendulum, step%y)
         self%energy_last = self%energy_start
         self%max_energy_error = 0.0_wp
         self%energy_increases = 0
         self%max_abs_phi = abs(pendulum_angle(step%y))
         self%time_of_max_phi = step%t
         self%onset_time = -1.0_wp
         if (self%max_abs_phi > self%phi_sat) self%onset_time = step%t
         self%max_sample_energy_error = 0.0_wp
         self%next_sample = 1
         return
      end if
      ! the sample times in (t_old, t], computed as the series task computes them
      do while (self%samples_per_period > 0 .and. self%next_sample <= self%n_samples)
         ts = real(self%next_sample, wp)*self%pendulum%period/real(self%samples_per_period, wp)
         if (ts > step%t) exit
         if (ts == step%t) then
            y = step%y
         else
            y = rk_dense_value(step, ts)
         end if
         self%max_sample_energy_error = max(self%max_sample_energy_error, &
                                            abs(pendulum_energy(self%pendulum, y) - self%energy_start))
         self%next_sample = self%next_sample + 1
      end do
      e = pendulum_energy(self%pendulum, step%y)
      self%max_energy_error = max(self%max_energy_error, abs(e - self%energy_start))
      noise = 16*epsilon(1.0_wp)*self%energy_scale
      if (e > self%energy_last + noise) self%energy_increases = self%energy_increases + 1
      self%energy_last = e
      t_prev = step%t_old
      do s = 1, dense_points_per_step
         if (s == dense_points_per_step) then
            ts = step%t
            y = step%y
         else
            ts = step%t_old + step%h*real(s, wp)/dense_points_per_step
            y = rk_dense_value(step, ts)
         end if
         phi = abs(pendulum_angle(y))
         if (phi > self%max_abs_phi) then
            self%max_abs_phi = phi
            self%time_of_max_phi = ts
         end if
         if (self%onset_time < 0.0_wp .and. phi > self%phi_sat) then
            self%onset_time = crossing(t_prev, ts)
            if (self%stop_at_onset) stop = .true.
         end if
         t_prev = ts
      end do
   contains
      !> The first t in (lo, hi] with |φ(t)| = phi_sat, by bisection on the dense output
      !> (|φ(lo)| ≤ phi_sat < |φ(hi)|).
      real(wp) function crossing(lo, hi) result(t_cross)
         real(wp), intent(in) :: lo, hi
         real(wp) :: a, b, mid
         integer :: iteration
         a = lo
         b = hi
         do iteration = 1, 200
            mid = 0.5_wp*(a + b)
            if (mid <= a .or. mid >= b) exit
            if (abs(pendulum_angle(rk_dense_value(step, mid))) > self%phi_sat) then
               b = mid
            else
               a = mid
            end if
         end do
         t_cross = b
      end function crossing
   end subroutine watch_observe
end module hillstab_pendulum_analysis

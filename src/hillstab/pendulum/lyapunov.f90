!> The largest Lyapunov exponent of the nonlinear elastic pendulum (hillstab_pendulum_equations),
!> per radial period, by Benettin's method: the trajectory and one tangent vector of the
!> variational equations v' = J(y) v are integrated together (DOP853 or DOPRI5 with
!> error control on both), and at the end of every radial period T the tangent vector
!> is renormalised; the exponent after n periods is the mean of the logarithmic growths,
!>
!>   λ_n = (1/n) Σ_{k=1..n} ln(‖v(kT)‖ / ‖v((k−1)T)‖),   per radial period,
!>
!> with ‖v‖² = δx² + δz² + (δx'/ω)² + (δz'/ω)² (positions and velocities on one scale;
!> the limit does not depend on the norm). The running estimate λ_n is kept so that
!> convergence can be seen; its spread (max − min) over the last half of the run,
!> n ∈ [⌈N/2⌉, N], shows how far it still moves. On a regular orbit λ_n → 0 like ln n / n
!> (the tangent vector grows at most polynomially); on a chaotic one λ_n settles at a
!> positive value. The spread is no error bar: λ_n moves little in the second half while
!> runs from starts 1e-12 apart, which part after ~ln(1e12)/λ periods, scatter several
!> times more. The error bar (`lyapunov_error_bar`) is that of the mean of the growths
!> by batch means: the N growths in B = min(5, N) consecutive batches, the batch means'
!> standard error times Student's t (95 %, B − 1 degrees of freedom); batching absorbs
!> the correlation of neighbouring periods, since a batch mean is the growth of ln‖v‖
!> across the batch over its length.
!> While the swing is still tiny the trajectory is the vertical bounce, whose swing
!> block is the chart's Hill equation, so the first periods grow like the chart's
!> λ_max (`lyapunov_largest` with φ0 = 1e-12 reproduces ln λ_max).
!>
!> Pure numerics: no I/O, errors through error_t, threads may run independent points.
!>
!>```fortran
!> type(pendulum_t) :: p
!> type(lyapunov_t) :: result
!> type(error_t), allocatable :: error
!> call pendulum_from_chart(7.48_wp, 2.47_wp, 0.0_wp, 0.1_wp, 9.81_wp, p, error)
!> call lyapunov_largest(p, pendulum_initial_state(p, 0.017_wp), 300, 1.0e-10_wp, result, error)
!> print *, result%exponent, result%spread, result%max_abs_phi
!>```
module hillstab_pendulum_lyapunov
   use hillstab_core_kinds, only: wp
   use hillstab_core_error, only: error_t, set_error, err_invalid_parameter, err_integration
   use hillstab_core_stats, only: work_stats_t, add_work
   use hillstab_integrate_rk, only: rk_step_t, rk_options_t, rk_integrate, rk_dop853, rk_dopri5
   use hillstab_pendulum_equations, only: pendulum_t, pendulum_tangent_t, pendulum_atol, pendulum_angle, pendulum_energy, &
      pendulum_energy_scale
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   implicit none
   private
   public :: lyapunov_t, lyapunov_largest, tangent_norm, lyapunov_error_bar

   !> Result of `lyapunov_largest`.
   type :: lyapunov_t
      integer :: periods = 0              !! radial periods integrated
      real(wp) :: exponent = 0.0_wp       !! λ_N: largest Lyapunov exponent per radial period
      !> max − min of λ_n over n ∈ [⌈N/2⌉, N]: how far the estimate still moves
      real(wp) :: spread = 0.0_wp
      !> half-width of the 95 % interval of λ_N by batch means (`lyapunov_error_bar`)
      real(wp) :: exponent_error = 0.0_wp
      real(wp) :: max_abs_phi = 0.0_wp    !! largest |φ| [rad] at the integrator's steps
      !> |E(NT) − E(0)| / (the sum of the magnitudes of the energy terms at t = 0)
      !> (only meaningful without damping)
      real(wp) :: energy_drift = 0.0_wp
      real(wp), allocatable :: running(:)     !! λ_n, n = 1 … N
      real(wp), allocatable :: log_growth(:)  !! ln(‖v(nT)‖/‖v((n−1)T)‖), n = 1 … N
      real(wp) :: final_state(4) = 0.0_wp     !! (x, z, x', z') at t = NT
      type(work_stats_t) :: stats             !! steps, rejections, f-evaluations (of the 8-D system)
   end type lyapunov_t

   !> The tangent system that also records the largest |φ| at every accepted step.
   type, extends(pendulum_tangent_t) :: watched_tangent_t
      real(wp) :: max_abs_phi = 0.0_wp  !! largest |φ| seen so far
   contains
      procedure :: observe => watch_angle
   end type watched_tangent_t

contains

   !> The norm of a tangent vector (δx, δz, δx', δz') with velocities divided by ω.
   pure real(wp) function tangent_norm(p, v) result(norm)
      type(pendulum_t), intent(in) :: p  !! the pendulum (for ω)
      real(wp), intent(in) :: v(4)       !! tangent vector
      norm = norm2([v(1), v(2), v(3)/p%omega, v(4)/p%omega])
   end function tangent_norm

   !> Largest Lyapunov exponent over `periods` radial periods from state `y0`.
   !>
   !> The tangent vector starts as (1, 1, ω, ω)/2 (both the swing and the radial
   !> directions), is renormalised to norm 1 every period, and its growth is summed.
   !> Tolerances: relative `rtol`; absolute as `pendulum_atol` for the state (relative
   !> accuracy even in a swing of 1e-20) and rtol·(1, 1, ω, ω) for the tangent vector
   !> (norm 1 at the start of every period). Each period is one `rk_integrate` call that
   !> starts with the step predicted at the end of the previous one.
   subroutine lyapunov_largest(p, y0, periods, rtol, result, error, method)
      type(pendulum_t), intent(in) :: p        !! the pendulum
      real(wp), intent(in) :: y0(4)            !! initial state (x, z, x', z')
      integer, intent(in) :: periods           !! number of radial periods N ≥ 1
      real(wp), intent(in) :: rtol             !! relative tolerance of the integration
      !> the exponent, its spread over the second half, the largest angle, the energy drift
      type(lyapunov_t), intent(out) :: result
      type(error_t), allocatable, intent(out) :: error  !! invalid arguments; integration failure
      integer, intent(in), optional :: method  !! rk_dop853 (default) or rk_dopri5
      type(watched_tangent_t) :: system
      type(rk_options_t) :: options
      type(work_stats_t) :: part
      real(wp) :: y(8), t, h_next, norm, sum_log, e0, scale0
      integer :: n, half
      character(len=120) :: text

      if (periods < 1) then
         call set_error(error, err_invalid_parameter, "lyapunov_largest: periods must be >= 1")
         return
      end if
      if (.not. (ieee_is_finite(rtol) .and. rtol > 0.0_wp)) then
         call set_error(error, err_invalid_parameter, "lyapunov_largest: rtol must be > 0")
         return
      end if
      if (.not. all(ieee_is_finite(y0))) then
         call set_error(error, err_invalid_parameter, "lyapunov_largest: non-finite initial state")
         return
      end if
      system%pendulum = p
      system%max_abs_phi = abs(pendulum_angle(y0))
      options = rk_options_t(method=rk_dop853, rtol=rtol, atol=rtol, max_steps=1000000)
      if (present(method)) options%method = method
      if (options%method /= rk_dop853 .and. options%method /= rk_dopri5) then
         call set_error(error, err_invalid_parameter, "lyapunov_largest: unknown Runge-Kutta method")
         return
      end if
      options%atol_components = [pendulum_atol(p, y0, rtol), rtol*[1.0_wp, 1.0_wp, p%omega, p%omega]]
      allocate (result%running(periods), result%log_growth(periods))
      result%stats = work_stats_t()
      y(1:4) = y0
      y(5:8) = 0.5_wp*[1.0_wp, 1.0_wp, p%omega, p%omega]
      e0 = pendulum_energy(p, y0)
      scale0 = pendulum_energy_scale(p, y0)
      t = 0.0_wp
      sum_log = 0.0_wp
      h_next = 0.0_wp
      do n = 1, periods
         options%h_initial = h_next
         call rk_integrate(system, t, n*p%period, y, options, part, error, h_next=h_next)
         call add_work(result%stats, part)
         if (allocated(error)) then
            write (text, '(a,i0,a)') "lyapunov_largest: radial period ", n, ": "
            error%message = trim(text)//" "//error%message
            result%periods = n - 1
            return
         end if
         norm = tangent_norm(p, y(5:8))
         if (.not. (norm > 0.0_wp .and. ieee_is_finite(norm))) then
            write (text, '(a,i0)') "lyapunov_largest: tangent vector lost (zero or not finite) in radial period ", n
            call set_error(error, err_integration, trim(text))
            result%periods = n - 1
            return
         end if
         y(5:8) = y(5:8)/norm
         result%log_growth(n) = log(norm)
         sum_log = sum_log + log(norm)
         result%running(n) = sum_log/n
      end do
      result%periods = periods
      result%exponent = result%running(periods)
      half = (periods + 1)/2
      result%spread = maxval(result%running(half:)) - minval(result%running(half:))
      result%exponent_error = lyapunov_error_bar(result%log_growth)
      result%max_abs_phi = system%max_abs_phi
      result%final_state = y(1:4)
      result%energy_drift = abs(pendulum_energy(p, y(1:4)) - e0)/max(scale0, tiny(1.0_wp))
   end subroutine lyapunov_largest

   !> The error bar of the finite-time exponent λ_N = mean of the growths g_1 … g_N, by
   !> batch means: the growths in B = min(5, N) consecutive batches of ⌊N/B⌋ or ⌈N/B⌉
   !> periods, batch means m_b with weights w_b = (batch length)/N (Σ w_b m_b = λ_N), and
   !>
   !>   error = t_{0.975, B−1} · sqrt( B/(B − 1) · Σ w_b² (m_b − λ_N)² ),
   !>
   !> the standard error of the mean of B batch means times Student's t (for equal batches
   !> s/√B with s the batch means' standard deviation). A batch mean is (ln‖v‖ at the
   !> batch's end − at its start)/length, so correlations between neighbouring periods
   !> shorter than a batch do not make the bar too small. Five batches rather than more:
   !> at (8.3, 5.2), 400 periods, 100 runs from starts 1e-12 apart, 94 of the runs lay
   !> within their own bar of the runs' mean with B = 5, only 80 with B = 10 (episodes of
   !> weak growth near regular islands last longer than 40 periods). On a chaotic orbit it estimates
   !> the scatter of λ_N between runs that differ by round-off or 1e-12 in the start; on a
   !> regular orbit, where ln‖v‖ grows like ln n plus a bounded oscillation, it is of the
   !> order of √B t/N. Early-stopped runs (few periods) get fewer or shorter batches and
   !> a larger t: the bar widens with the lack of data. N = 1: no scatter can be measured,
   !> the bar is |g_1| (the whole value). Never NaN for finite growths.
   pure real(wp) function lyapunov_error_bar(growth, batches) result(bar)
      real(wp), intent(in) :: growth(:)  !! ln growth per radial period, g_1 … g_N
      integer, intent(in), optional :: batches  !! most batches B, 2 … 10 (default 5)
      !> Student's t, two-sided 95 %, for 1 … 9 degrees of freedom
      real(wp), parameter :: t95(9) = [12.706_wp, 4.303_wp, 3.182_wp, 2.776_wp, 2.571_wp, 2.447_wp, 2.365_wp, &
                                       2.306_wp, 2.262_wp]
      real(wp) :: mean, batch_mean, w, total
      integer :: n, nb, b, lo, hi, max_batches
      n = size(growth)
      bar = 0.0_wp
      if (n == 0) return
      if (n == 1) then
         bar = abs(growth(1))
         return
      end if
      max_batches = 5
      if (present(batches)) max_batches = max(2, min(10, batches))
      nb = min(max_batches, n)
      mean = sum(growth)/n
      total = 0.0_wp
      do b = 1, nb
         lo = ((b - 1)*n)/nb + 1
         hi = (b*n)/nb
         w = real(hi - lo + 1, wp)/n
         batch_mean = sum(growth(lo:hi))/(hi - lo + 1)
         total = total + (w*(batch_mean - mean))**2
      end do
      bar = t95(nb - 1)*sqrt(real(nb, wp)/(nb - 1)*total)
   end function lyapunov_error_bar

   !> The observer keeps the largest |φ| at the accepted steps.
   subroutine watch_angle(self, step, stop)
      class(watched_tangent_t), intent(inout) :: self
      type(rk_step_t), intent(in) :: step
      logical, intent(inout) :: stop
      self%max_abs_phi = max(self%max_abs_phi, abs(pendulum_angle(step%y)))
   end subroutine watch_angle
end module hillstab_pendulum_lyapunov

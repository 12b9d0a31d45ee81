!> Monodromy of the χ equation χ'' + q(τ) χ = 0 (q = hill_coefficient, eq. (25)/(47)) by
!> hillstab's adaptive Runge–Kutta integrator, over half a period.
!>
!> q is even and 2-periodic, so with the even and odd fundamental solutions u
!> (u(0) = 1, u'(0) = 0) and v (v(0) = 0, v'(0) = 1) on [0, 1] the one-period monodromy is
!> M = R Φ(1)⁻¹ R Φ(1), R = diag(1, −1), Φ = [[u, v], [u', v']], that is
!>
!>   M = [[u v' + u' v, 2 v v'], [2 u u', u v' + u' v]] at τ = 1,  S = 2 (u v' + u' v),
!>
!> and det M = (u v' − u' v)² = W² = 1 (BRIEF §4). Only [0, 1] is integrated.
!>
!> Strongly negative q (β ≪ 0, α → π²) makes u, v grow like e^{∫√|q|}; the
!> integration stops whenever a pair exceeds 2^200, rescales it by a power of two
!> (exact) and resumes, so the result is a `scaled_matrix_t` that cannot overflow.
!>
!>```fortran
!> type(trace_t) :: tr
!> type(error_t), allocatable :: error
!> call trace_rk(hill_model_t(model_elastic, 9.8_wp, 2.47_wp, 0.0_wp), 1.0e-10_wp, tr, error)
!>```
module hillstab_monodromy_rk
   use hillstab_kinds, only: wp
   use hillstab_error, only: error_t, set_error, err_invalid_parameter, err_integration
   use hillstab_stats, only: work_stats_t, add_work
   use hillstab_coefficient, only: hill_model_t, hill_coefficient, check_model
   use hillstab_transfer, only: scaled_matrix_t, normalize_scaled, trace_t, trace_of, monodromy_from_half_period
   use hillstab_rk, only: rk_system_t, rk_options_t, rk_step_t, rk_integrate, rk_dopri5, rk_dop853
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   implicit none
   private
   public :: monodromy_rk, trace_rk, rk_tolerances

   !> rtol = atol = tolerance × this factor for DOP853. Measured over α ∈ {0, 2, 5, 9, 9.8},
   !> β ∈ {−50, 1, 2.47, 6, 400}, tolerance 1e-6…1e-13: the error of S divided by
   !> max(1, |S|) is at most 0.93 × (10·rtol) and typically 0.05–0.3 × (10·rtol), so 0.05
   !> keeps it below about half the requested tolerance.
   real(wp), parameter :: dop853_tolerance_factor = 0.05_wp
   !> The same for DOPRI5 (measured error of S at most 0.6 × (50·rtol) on the same grid).
   real(wp), parameter :: dopri5_tolerance_factor = 0.02_wp
   !> Local tolerances are not taken below this (round-off floor of the pairs).
   real(wp), parameter :: tolerance_floor = 1.0e-15_wp
   !> A solution pair is rescaled when its largest component passes 2^200.
   integer, parameter :: rescale_exponent = 200

   !> The even and odd solutions (u, u', v, v') of χ'' + q(τ) χ = 0 as one RK system; the
   !> observer stops the integration before either pair can overflow.
   type, extends(rk_system_t) :: even_odd_pair_t
      type(hill_model_t) :: model
   contains
      procedure :: rhs => even_odd_rhs
      procedure :: observe => watch_growth
   end type even_odd_pair_t

contains

   !> Local tolerances rtol = atol used for a target error `tolerance` on S.
   pure real(wp) function rk_tolerances(tolerance, method) result(local)
      real(wp), intent(in) :: tolerance  !! target error on S, scaled by max(1, |S|)
      integer, intent(in) :: method      !! rk_dopri5 or rk_dop853
      if (method == rk_dopri5) then
         local = max(tolerance*dopri5_tolerance_factor, tolerance_floor)
      else
         local = max(tolerance*dop853_tolerance_factor, tolerance_floor)
      end if
   end function rk_tolerances

   !> One-period monodromy M of the χ equation from the even/odd solutions on [0, 1].
   subroutine monodromy_rk(model, tolerance, m, stats, error, method)
      type(hill_model_t), intent(in) :: model  !! the Hill equation
      real(wp), intent(in) :: tolerance        !! target error on S, scaled by max(1, |S|)
      type(scaled_matrix_t), intent(out) :: m  !! M = e^{log_scale} m
      type(work_stats_t), intent(out) :: stats !! steps, rejections, Q evaluations
      type(error_t), allocatable, intent(out) :: error  !! integration failure; unallocated on success
      integer, intent(in), optional :: method  !! rk_dop853 (default) or rk_dopri5
      type(rk_options_t) :: options
      type(even_odd_pair_t) :: pair
      type(work_stats_t) :: part
      real(wp) :: t, y(4), h_next, log_u, log_v
      integer :: e
      character(len=80) :: buffer

      stats = work_stats_t()
      m = scaled_matrix_t()
      call check_model(model, error)
      if (allocated(error)) return
      if (.not. (ieee_is_finite(tolerance) .and. tolerance > 0.0_wp)) then
         write (buffer, '(es12.4)') tolerance
         call set_error(error, err_invalid_parameter, "monodromy_rk: tolerance must be > 0, got "// &
            trim(adjustl(buffer)))
         return
      end if
      options%method = rk_dop853
      if (present(method)) options%method = method
      if (options%method /= rk_dop853 .and. options%method /= rk_dopri5) then
         call set_error(error, err_invalid_parameter, "monodromy_rk: unknown Runge-Kutta method")
         return
      end if
      options%rtol = rk_tolerances(tolerance, options%method)
      options%atol = options%rtol
      options%max_steps = 1000000
      pair%model = model

      ! y = (u, u', v, v') with the even and odd initial values
      y = [1.0_wp, 0.0_wp, 0.0_wp, 1.0_wp]
      t = 0.0_wp
      log_u = 0.0_wp
      log_v = 0.0_wp
      do
         call rk_integrate(pair, t, 1.0_wp, y, options, part, error, h_next=h_next)
         call add_work(stats, part)
         if (allocated(error)) then
            error%message = "monodromy_rk: "//error%message
            return
         end if
         if (t == 1.0_wp) exit
         ! stopped by watch_growth: rescale each pair by a power of two and resume
         e = exponent(maxval(abs(y(1:2))))
         y(1:2) = scale(y(1:2), -e)
         log_u = log_u + e*log(2.0_wp)
         e = exponent(maxval(abs(y(3:4))))
         y(3:4) = scale(y(3:4), -e)
         log_v = log_v + e*log(2.0_wp)
         options%h_initial = abs(h_next)
      end do

      m = monodromy_from_half_period(reshape(y, [2, 2]), log_u, log_v)
      if (.not. (all(ieee_is_finite(m%m)) .and. ieee_is_finite(m%log_scale))) then
         call set_error(error, err_integration, "monodromy_rk: non-finite monodromy")
         m = scaled_matrix_t()
      end if
   end subroutine monodromy_rk

   !> Trace S of the one-period monodromy of the χ equation by `monodromy_rk`.
   subroutine trace_rk(model, tolerance, tr, error, stats, method)
      type(hill_model_t), intent(in) :: model  !! the Hill equation
      real(wp), intent(in) :: tolerance        !! target error on S, scaled by max(1, |S|)
      type(trace_t), intent(out) :: tr         !! S, flagged if it overflows
      type(error_t), allocatable, intent(out) :: error  !! integration failure; unallocated on success
      type(work_stats_t), intent(out), optional :: stats  !! steps, rejections, Q evaluations
      integer, intent(in), optional :: method  !! rk_dop853 (default) or rk_dopri5
      type(scaled_matrix_t) :: m
      type(work_stats_t) :: work
      call monodromy_rk(model, tolerance, m, work, error, method)
      if (present(stats)) stats = work
      if (allocated(error)) then
         tr = trace_t()
         return
      end if
      tr = trace_of(m)
   end subroutine trace_rk

   !> χ'' = −q χ for both solutions: one evaluation of q per call.
   subroutine even_odd_rhs(self, t, y, dydt)
      class(even_odd_pair_t), intent(inout) :: self
      real(wp), intent(in) :: t, y(:)
      real(wp), intent(out) :: dydt(:)
      real(wp) :: q
      q = hill_coefficient(self%model, t)
      dydt(1) = y(2)
      dydt(2) = -q*y(1)
      dydt(3) = y(4)
      dydt(4) = -q*y(3)
   end subroutine even_odd_rhs

   !> Stop before the solutions can overflow, so they can be rescaled.
   subroutine watch_growth(self, step, stop)
      class(even_odd_pair_t), intent(inout) :: self
      type(rk_step_t), intent(in) :: step
      logical, intent(inout) :: stop
      if (step%t < 1.0_wp) then
         stop = exponent(maxval(abs(step%y(1:2)))) > rescale_exponent &
                .or. exponent(maxval(abs(step%y(3:4)))) > rescale_exponent
      end if
   end subroutine watch_growth
end module hillstab_monodromy_rk

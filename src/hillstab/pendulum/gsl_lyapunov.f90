!> The largest Lyapunov exponent of the nonlinear pendulum with GSL's odeiv2 driver and
!> the Prince–Dormand 8(7) pair rk8pd driving the same equations as
!> `hillstab_pendulum_lyapunov` (state and one tangent vector, `pendulum_rhs` and
!> `pendulum_jacobian`), with the same renormalisation every radial period and the same
!> tolerances (GSL's scaled control: absolute part per component as
!> `pendulum_atol` and rtol·(1, 1, ω, ω) for the tangent vector, relative part rtol·|y|).
!> An independent reference for tests and the speed benchmark.
!>
!> The right-hand side receives the pendulum through GSL's `params` pointer (no module
!> state): independent points may run in parallel threads.
!>
!>```fortran
!> call lyapunov_largest_gsl(p, pendulum_initial_state(p, 0.017_wp), 300, 1.0e-10_wp, result, error)
!>```
module hillstab_pendulum_gsl_lyapunov
   use, intrinsic :: iso_c_binding, only: c_int, c_double, c_size_t, c_long, c_ptr, c_null_funptr, &
      c_loc, c_funloc, c_f_pointer, c_associated
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use hillstab_core_kinds, only: wp, int64
   use hillstab_core_error, only: error_t, set_error, err_invalid_parameter, err_integration
   use hillstab_ffi_gsl, only: gsl_odeiv2_system, gsl_odeiv2_driver_apply, gsl_odeiv2_driver_free, gsl_success, &
      gsl_ebadfunc
   use hillstab_pendulum_gsl, only: gsl_rk8pd_scaled_driver
   use hillstab_pendulum_equations, only: pendulum_t, pendulum_rhs, pendulum_jacobian, pendulum_atol, pendulum_angle, &
      pendulum_energy, pendulum_energy_scale
   use hillstab_pendulum_lyapunov, only: lyapunov_t, lyapunov_error_bar, tangent_norm
   implicit none
   private
   public :: lyapunov_largest_gsl

   !> What the right-hand side needs: the pendulum and a counter of its calls.
   type :: context_t
      type(pendulum_t) :: pendulum
      integer(int64) :: n_evaluations = 0
   end type context_t

contains

   !> Largest Lyapunov exponent over `periods` radial periods by GSL rk8pd (see the module
   !> description); the result has the fields of `lyapunov_largest` (max_abs_phi from the
   !> states at the period ends; stats count f-evaluations only).
   subroutine lyapunov_largest_gsl(p, y0, periods, rtol, result, error)
      type(pendulum_t), intent(in) :: p        !! the pendulum
      real(wp), intent(in) :: y0(4)            !! initial state (x, z, x', z')
      integer, intent(in) :: periods           !! number of radial periods N ≥ 1
      real(wp), intent(in) :: rtol             !! relative tolerance (> 0)
      type(lyapunov_t), intent(out) :: result  !! the exponent, its spread, the largest angle, the energy drift
      type(error_t), allocatable, intent(out) :: error  !! invalid arguments; integration failure
      type(context_t), target :: context
      type(gsl_odeiv2_system), target :: system
      type(c_ptr) :: driver
      real(c_double) :: state(8), t
      real(wp) :: norm, sum_log
      integer(c_int) :: status
      integer :: n, half
      character(len=160) :: text

      if (periods < 1 .or. .not. (ieee_is_finite(rtol) .and. rtol > 0.0_wp) .or. .not. all(ieee_is_finite(y0))) then
         call set_error(error, err_invalid_parameter, "lyapunov_largest_gsl: need periods >= 1, rtol > 0 and a "// &
            "finite initial state")
         return
      end if
      context%pendulum = p
      system = gsl_odeiv2_system(c_funloc(tangent_rhs), c_null_funptr, 8_c_size_t, c_loc(context))
      driver = gsl_rk8pd_scaled_driver(system, 1.0e-3_wp*p%period, rtol, &
         [pendulum_atol(p, y0, rtol), rtol*[1.0_wp, 1.0_wp, p%omega, p%omega]]/rtol, 10000000_c_long)
      if (.not. c_associated(driver)) then
         call set_error(error, err_integration, "GSL could not allocate the odeiv2 driver")
         return
      end if
      allocate (result%running(periods), result%log_growth(periods))
      state(1:4) = y0
      state(5:8) = 0.5_wp*[1.0_wp, 1.0_wp, p%omega, p%omega]
      t = 0.0_c_double
      sum_log = 0.0_wp
      result%max_abs_phi = abs(pendulum_angle(y0))
      do n = 1, periods
         status = gsl_odeiv2_driver_apply(driver, t, real(n*p%period, c_double), state)
         if (status == gsl_success .and. .not. all(ieee_is_finite(state))) status = gsl_ebadfunc
         if (status /= gsl_success) then
            write (text, '(a,i0,a,i0)') "lyapunov_largest_gsl: GSL rk8pd failed with status ", status, &
               " in radial period ", n
            call set_error(error, err_integration, trim(text))
            exit
         end if
         norm = tangent_norm(p, state(5:8))
         state(5:8) = state(5:8)/norm
         result%log_growth(n) = log(norm)
         sum_log = sum_log + log(norm)
         result%running(n) = sum_log/n
         result%max_abs_phi = max(result%max_abs_phi, abs(pendulum_angle(state(1:4))))
      end do
      call gsl_odeiv2_driver_free(driver)
      result%stats%n_evaluations = context%n_evaluations
      if (allocated(error)) then
         result%periods = n - 1
         return
      end if
      result%periods = periods
      result%exponent = result%running(periods)
      half = (periods + 1)/2
      result%spread = maxval(result%running(half:)) - minval(result%running(half:))
      result%exponent_error = lyapunov_error_bar(result%log_growth)
      result%final_state = state(1:4)
      result%energy_drift = abs(pendulum_energy(p, state(1:4)) - pendulum_energy(p, y0))/ &
                            max(pendulum_energy_scale(p, y0), tiny(1.0_wp))
   end subroutine lyapunov_largest_gsl

   !> int f(double t, const double y[], double dydt[], void *params): state and J v.
   function tangent_rhs(t, y, dydt, params) bind(C) result(status)
      real(c_double), value :: t
      real(c_double), intent(in) :: y(8)
      real(c_double), intent(out) :: dydt(8)
      type(c_ptr), value :: params
      integer(c_int) :: status
      type(context_t), pointer :: context
      real(wp) :: jac(4, 4)
      call c_f_pointer(params, context)
      context%n_evaluations = context%n_evaluations + 1
      call pendulum_rhs(context%pendulum, y(1:4), dydt(1:4))
      jac = pendulum_jacobian(context%pendulum, y(1:4))
      dydt(5:8) = matmul(jac, y(5:8))
      status = gsl_success
      if (.not. all(ieee_is_finite(dydt))) status = gsl_ebadfunc
   end function tangent_rhs
end module hillstab_pendulum_gsl_lyapunov

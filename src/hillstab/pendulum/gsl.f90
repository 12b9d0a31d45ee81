!> The nonlinear pendulum integrated by GSL's odeiv2 driver with the Prince–Dormand 8(7)
!> pair rk8pd: the same equations (`pendulum_rhs`) and the same tolerances as hillstab's
!> DOP853 runs (GSL's scaled control: absolute part per component as `pendulum_atol`,
!> relative part rtol·|y|). A second method for tests and the speed benchmark.
!>
!> The right-hand side receives the pendulum and its evaluation counter through GSL's
!> `params` pointer (no module state, no internal procedure).
!>
!>```fortran
!> real(wp) :: y(4)
!> y = pendulum_initial_state(p, 0.017_wp)
!> call pendulum_gsl(p, y, 100*p%period, 1.0e-10_wp, stats, error)
!>```
module hillstab_pendulum_gsl
   use, intrinsic :: iso_c_binding, only: c_int, c_double, c_size_t, c_long, c_ptr, c_funptr, c_null_funptr, &
      c_loc, c_funloc, c_f_pointer, c_associated
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use hillstab_core_kinds, only: wp, int64
   use hillstab_core_error, only: error_t, set_error, err_invalid_parameter, err_integration
   use hillstab_core_stats, only: work_stats_t
   use hillstab_ffi_gsl, only: gsl_odeiv2_system, gsl_odeiv2_driver_apply, gsl_odeiv2_driver_free, &
      gsl_odeiv2_driver_view, gsl_odeiv2_evolve_apply, gsl_odeiv2_step_rk8pd, gsl_odeiv2_driver_alloc_scaled_new, &
      gsl_odeiv2_driver_set_nmax, gsl_set_error_handler_off, gsl_success, gsl_ebadfunc, gsl_emaxiter
   use hillstab_pendulum_equations, only: pendulum_t, pendulum_rhs, pendulum_atol, pendulum_energy, pendulum_energy_scale
   implicit none
   private
   public :: pendulum_gsl, gsl_rk8pd_scaled_driver

   !> Steps allowed per integration (GSL's driver limit, applied by the watched loop too)
   integer(c_long), parameter :: step_limit = 100000000_c_long

   !> What the right-hand side needs.
   type :: context_t
      type(pendulum_t) :: pendulum
      integer(int64) :: n_evaluations = 0
   end type context_t

contains

   !> Integrate the pendulum from t = 0 to t_end with GSL rk8pd at relative tolerance rtol
   !> (absolute tolerances of `pendulum_atol`). On return y is the state at t_end.
   !> With `energy_drift`, the steps are taken one by one (GSL's evolve loop, the steps of
   !> its driver) and the largest |E − E(0)|/E_scale at their ends is returned.
   subroutine pendulum_gsl(p, y, t_end, rtol, stats, error, energy_drift)
      type(pendulum_t), intent(in) :: p          !! the pendulum
      real(wp), intent(inout) :: y(4)            !! initial state in, final state out
      real(wp), intent(in) :: t_end              !! end time [s], > 0
      real(wp), intent(in) :: rtol               !! relative tolerance (> 0)
      type(work_stats_t), intent(out) :: stats   !! f-evaluations (steps are not counted)
      type(error_t), allocatable, intent(out) :: error  !! allocated when GSL fails (y unchanged)
      real(wp), intent(out), optional :: energy_drift  !! max |E − E(0)|/E_scale over the step ends
      type(context_t), target :: context
      type(gsl_odeiv2_driver_view), pointer :: view
      real(wp) :: energy0, energy_scale
      integer(c_long) :: steps
      type(gsl_odeiv2_system), target :: system
      type(c_ptr) :: driver
      real(c_double) :: state(4), t
      integer(c_int) :: status
      character(len=160) :: text
      stats = work_stats_t()
      if (.not. (ieee_is_finite(rtol) .and. rtol > 0.0_wp .and. ieee_is_finite(t_end) .and. t_end > 0.0_wp) &
          .or. .not. all(ieee_is_finite(y))) then
         call set_error(error, err_invalid_parameter, "pendulum_gsl: need rtol > 0, t_end > 0, a finite state")
         return
      end if
      context%pendulum = p
      system = gsl_odeiv2_system(c_funloc(gsl_rhs), c_null_funptr, 4_c_size_t, c_loc(context))
      driver = gsl_rk8pd_scaled_driver(system, 1.0e-3_wp*p%period, rtol, pendulum_atol(p, y, rtol)/rtol, &
                                       step_limit)
      if (.not. c_associated(driver)) then
         call set_error(error, err_integration, "pendulum_gsl: GSL could not allocate the odeiv2 driver")
         return
      end if
      state = y
      t = 0.0_c_double
      if (present(energy_drift)) then
         ! driver_apply's loop, watched per step, with its step limit (its other checks, h_max
         ! (none here) and h_min (0 here), cannot act)
         call c_f_pointer(driver, view)
         energy0 = pendulum_energy(p, y)
         energy_scale = pendulum_energy_scale(p, y)
         energy_drift = 0.0_wp
         status = gsl_success
         steps = 0
         do while (t < t_end .and. status == gsl_success)
            status = gsl_odeiv2_evolve_apply(view%evolve, view%control, view%step, view%sys, t, &
                                             real(t_end, c_double), view%h, state)
            if (status /= gsl_success) exit
            energy_drift = max(energy_drift, abs(pendulum_energy(p, state) - energy0)/energy_scale)
            steps = steps + 1
            if (steps == step_limit) status = gsl_emaxiter
         end do
      else
         status = gsl_odeiv2_driver_apply(driver, t, real(t_end, c_double), state)
      end if
      if (status == gsl_success .and. .not. all(ieee_is_finite(state))) status = gsl_ebadfunc
      call gsl_odeiv2_driver_free(driver)
      stats%n_evaluations = context%n_evaluations
      if (status /= gsl_success) then
         write (text, '(a,i0,a,es12.5)') "pendulum_gsl: GSL rk8pd failed with status ", status, " at t = ", t
         call set_error(error, err_integration, trim(text))
         return
      end if
      y = state
   end subroutine pendulum_gsl

   !> A GSL odeiv2 driver with the rk8pd stepper and GSL's scaled error control set up
   !> like hillstab's: the error of component i is kept below rtol·(scale_abs(i) + |y_i|)
   !> (absolute part rtol·scale_abs(i), relative part rtol·|y_i|), with GSL's error
   !> handler switched off so that failures come back as status codes. The driver keeps
   !> the address of `system`, which must outlive it. A null pointer when GSL cannot
   !> allocate it; free it with `gsl_odeiv2_driver_free`. Shared by the pendulum's GSL
   !> drivers (this module and hillstab_pendulum_gsl_lyapunov).
   function gsl_rk8pd_scaled_driver(system, h_start, rtol, scale_abs, step_limit) result(driver)
      type(gsl_odeiv2_system), intent(in), target :: system  !! the system (kept by the driver)
      real(wp), intent(in) :: h_start              !! first trial step
      real(wp), intent(in) :: rtol                 !! relative tolerance (> 0)
      real(c_double), intent(in) :: scale_abs(:)   !! absolute tolerances over rtol, per component
      integer(c_long), intent(in) :: step_limit    !! most steps per gsl_odeiv2_driver_apply call
      type(c_ptr) :: driver                        !! the driver, or a null pointer
      type(c_funptr) :: previous
      integer(c_int) :: status
      previous = gsl_set_error_handler_off()
      driver = gsl_odeiv2_driver_alloc_scaled_new(system, gsl_odeiv2_step_rk8pd, real(h_start, c_double), &
         real(rtol, c_double), real(rtol, c_double), 1.0_c_double, 0.0_c_double, scale_abs)
      if (c_associated(driver)) status = gsl_odeiv2_driver_set_nmax(driver, step_limit)
   end function gsl_rk8pd_scaled_driver

   function gsl_rhs(t, y, dydt, params) bind(C) result(status)
      real(c_double), value :: t
      real(c_double), intent(in) :: y(4)
      real(c_double), intent(out) :: dydt(4)
      type(c_ptr), value :: params
      integer(c_int) :: status
      type(context_t), pointer :: context
      call c_f_pointer(params, context)
      context%n_evaluations = context%n_evaluations + 1
      call pendulum_rhs(context%pendulum, y, dydt)
      status = gsl_success
      if (.not. all(ieee_is_finite(dydt))) status = gsl_ebadfunc
   end function gsl_rhs
end module hillstab_pendulum_gsl

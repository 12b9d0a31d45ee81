!> hillstab's own `bind(C)` interfaces to the few GSL routines it uses, the public
!> layouts of GSL structs that its evolve loops read, and GSL's status codes: the
!> bindings only. The methods built on them live with their layers: the Mathieu
!> characteristic values in `hillstab_hill_mathieu`, the rk8pd monodromy in
!> `hillstab_integrate_monodromy_gsl`, the pendulum drivers in `hillstab_pendulum_gsl`
!> and `hillstab_pendulum_gsl_lyapunov`.
!>
!> GSL's default error handler aborts the program: every caller switches it off
!> (`gsl_set_error_handler_off`) before a call that can fail and reads the status.
!>
!>```fortran
!> type(gsl_sf_result) :: r
!> type(c_funptr) :: previous
!> previous = gsl_set_error_handler_off()
!> if (gsl_sf_mathieu_a_e(0_c_int, 1.0_c_double, r) == gsl_success) print *, r%val   ! -0.455138604107
!>```
module hillstab_ffi_gsl
   use, intrinsic :: iso_c_binding, only: c_int, c_double, c_size_t, c_long, c_ptr, c_funptr
   implicit none
   private
   public :: gsl_sf_result, gsl_odeiv2_system, gsl_odeiv2_driver_view, gsl_odeiv2_evolve_view
   public :: gsl_odeiv2_step_rk8pd
   public :: gsl_set_error_handler_off, gsl_sf_mathieu_a_e, gsl_sf_mathieu_b_e
   public :: gsl_odeiv2_driver_alloc_y_new, gsl_odeiv2_driver_alloc_scaled_new, gsl_odeiv2_evolve_apply, &
      gsl_odeiv2_driver_set_nmax, gsl_odeiv2_driver_apply, gsl_odeiv2_driver_free, gsl_odeiv2_driver_reset
   public :: gsl_success, gsl_failure, gsl_ebadfunc, gsl_emaxiter

   !> Status GSL_SUCCESS.
   integer(c_int), parameter :: gsl_success = 0
   !> Status GSL_FAILURE, returned when the step control cannot meet its epsilon even at the smallest step
   !> (rounding noise in the step's error estimate exceeds it).
   integer(c_int), parameter :: gsl_failure = -1
   !> Status GSL_EBADFUNC: the right-hand side returned a non-finite value (set by hillstab's
   !> right-hand sides, read by GSL as a failed evaluation).
   integer(c_int), parameter :: gsl_ebadfunc = 9
   !> Status GSL_EMAXITER: more steps than a driver's limit.
   integer(c_int), parameter :: gsl_emaxiter = 11

   !> gsl_sf_result: value and GSL's error estimate.
   type, bind(C) :: gsl_sf_result
      real(c_double) :: val  !! the value
      real(c_double) :: err  !! GSL's estimate of its absolute error
   end type gsl_sf_result

   !> gsl_odeiv2_system.
   type, bind(C) :: gsl_odeiv2_system
      type(c_funptr) :: function      !! int f(double t, const double y[], double dydt[], void *params)
      type(c_funptr) :: jacobian      !! unused by explicit steppers: null
      integer(c_size_t) :: dimension  !! number of equations
      type(c_ptr) :: params  !! context handed to the right-hand side
   end type gsl_odeiv2_system

   !> The public layout of struct gsl_odeiv2_driver_struct (gsl_odeiv2.h): its stepper,
   !> control and evolve objects and its step, for loops that run GSL's evolve themselves.
   type, bind(C) :: gsl_odeiv2_driver_view
      type(c_ptr) :: sys      !! the gsl_odeiv2_system
      type(c_ptr) :: step     !! the stepper
      type(c_ptr) :: control  !! the step-size control
      type(c_ptr) :: evolve   !! the evolve object
      real(c_double) :: h     !! the next step proposed
      real(c_double) :: hmin  !! smallest step allowed
      real(c_double) :: hmax  !! largest step allowed
      integer(c_long) :: n, nmax   !! steps taken and the limit (unsigned long in C)
   end type gsl_odeiv2_driver_view

   !> The public layout of struct gsl_odeiv2_evolve_struct: `count` counts every
   !> attempted step (accepted or not), `failed_steps` the rejected ones.
   type, bind(C) :: gsl_odeiv2_evolve_view
      integer(c_size_t) :: dimension  !! number of equations
      !> work arrays: state, error estimate, derivatives at the start and the end of a step
      type(c_ptr) :: y0, yerr, dydt_in, dydt_out
      real(c_double) :: last_step  !! the last step taken
      integer(c_long) :: count, failed_steps  !! attempted and rejected steps (unsigned long in C)
   end type gsl_odeiv2_evolve_view

   !> `const gsl_odeiv2_step_type *gsl_odeiv2_step_rk8pd`, a global of libgsl.
   !> It must be public: gfortran gives private module variables hidden
   !> visibility, even with BIND(C), and the linker then allocates a hidden, null
   !> copy instead of referring to libgsl's (GSL segfaults on it).
   !> `protected`: nothing in hillstab may assign it.
   type(c_ptr), bind(C, name="gsl_odeiv2_step_rk8pd"), protected :: gsl_odeiv2_step_rk8pd

   interface
      !> Turn GSL's abort-on-error handler off (errors come back as status codes); returns the previous handler.
      function gsl_set_error_handler_off() bind(C, name="gsl_set_error_handler_off") result(previous)
         import :: c_funptr
         type(c_funptr) :: previous
      end function gsl_set_error_handler_off

      !> Characteristic value a_n(q) of the even Mathieu functions, with a status.
      function gsl_sf_mathieu_a_e(order, qq, result) bind(C, name="gsl_sf_mathieu_a_e") result(status)
         import :: c_int, c_double, gsl_sf_result
         integer(c_int), value :: order  !! n ≥ 0
         real(c_double), value :: qq     !! the Mathieu parameter q
         type(gsl_sf_result), intent(out) :: result  !! a_n(q) and its error estimate
         integer(c_int) :: status
      end function gsl_sf_mathieu_a_e

      !> Characteristic value b_n(q) of the odd Mathieu functions, with a status.
      function gsl_sf_mathieu_b_e(order, qq, result) bind(C, name="gsl_sf_mathieu_b_e") result(status)
         import :: c_int, c_double, gsl_sf_result
         integer(c_int), value :: order  !! n ≥ 1
         real(c_double), value :: qq     !! the Mathieu parameter q
         type(gsl_sf_result), intent(out) :: result  !! b_n(q) and its error estimate
         integer(c_int) :: status
      end function gsl_sf_mathieu_b_e

      !> Driver with GSL's y-control: the error of component i is kept below epsabs + epsrel |y_i|.
      function gsl_odeiv2_driver_alloc_y_new(sys, step_type, hstart, epsabs, epsrel) &
         bind(C, name="gsl_odeiv2_driver_alloc_y_new") result(driver)
         import :: c_ptr, c_double, gsl_odeiv2_system
         type(gsl_odeiv2_system), intent(in) :: sys  !! the system (function, dimension, params)
         type(c_ptr), value :: step_type  !! the stepper, e.g. gsl_odeiv2_step_rk8pd
         real(c_double), value :: hstart, epsabs, epsrel  !! first step; absolute and relative tolerance
         type(c_ptr) :: driver
      end function gsl_odeiv2_driver_alloc_y_new

      !> Driver with GSL's scaled control: the error of component i is kept below
      !> epsabs·scale_abs(i) + epsrel·(a_y |y_i| + a_dydt h |y_i'|) (the array is copied).
      function gsl_odeiv2_driver_alloc_scaled_new(sys, step_type, hstart, epsabs, epsrel, a_y, a_dydt, scale_abs) &
         bind(C, name="gsl_odeiv2_driver_alloc_scaled_new") result(driver)
         import :: c_ptr, c_double, gsl_odeiv2_system
         type(gsl_odeiv2_system), intent(in) :: sys  !! the system (function, dimension, params)
         type(c_ptr), value :: step_type  !! the stepper, e.g. gsl_odeiv2_step_rk8pd
         !> first step; absolute and relative tolerance; weights of y and h y'
         real(c_double), value :: hstart, epsabs, epsrel, a_y, a_dydt
         real(c_double), intent(in) :: scale_abs(*)  !! per-component scale of epsabs
         type(c_ptr) :: driver
      end function gsl_odeiv2_driver_alloc_scaled_new

      !> One step of the evolution (with GSL's internal retries on rejection).
      function gsl_odeiv2_evolve_apply(evolve, control, step, system, t, t1, h, y) &
         bind(C, name="gsl_odeiv2_evolve_apply") result(status)
         import :: c_ptr, c_double, c_int
         type(c_ptr), value :: evolve   !! the evolve object (its step counters)
         type(c_ptr), value :: control  !! the step-size control
         type(c_ptr), value :: step     !! the stepper
         type(c_ptr), value :: system   !! the gsl_odeiv2_system
         real(c_double), intent(inout) :: t  !! time, advanced by the accepted step
         real(c_double), value :: t1         !! do not step past t1
         real(c_double), intent(inout) :: h  !! proposed step in, next proposal out
         real(c_double), intent(inout) :: y(*)  !! state at t, advanced
         integer(c_int) :: status
      end function gsl_odeiv2_evolve_apply

      !> Limit the number of steps of one gsl_odeiv2_driver_apply call.
      function gsl_odeiv2_driver_set_nmax(driver, nmax) bind(C, name="gsl_odeiv2_driver_set_nmax") result(status)
         import :: c_ptr, c_long, c_int
         type(c_ptr), value :: driver  !! the driver
         integer(c_long), value :: nmax  !! largest number of steps per apply (0: no limit)
         integer(c_int) :: status
      end function gsl_odeiv2_driver_set_nmax

      !> Integrate from t to t1 (GSL_SUCCESS = 0, else a GSL error code).
      function gsl_odeiv2_driver_apply(driver, t, t1, y) bind(C, name="gsl_odeiv2_driver_apply") result(status)
         import :: c_ptr, c_double, c_int
         type(c_ptr), value :: driver  !! the driver
         real(c_double), intent(inout) :: t  !! time, advanced to t1
         real(c_double), value :: t1  !! end time
         real(c_double), intent(inout) :: y(*)  !! state at t, advanced
         integer(c_int) :: status
      end function gsl_odeiv2_driver_apply

      !> Free a driver.
      subroutine gsl_odeiv2_driver_free(driver) bind(C, name="gsl_odeiv2_driver_free")
         import :: c_ptr
         type(c_ptr), value :: driver  !! the driver
      end subroutine gsl_odeiv2_driver_free

      !> Reset the driver's evolve, stepper and control objects (after the state was changed outside them).
      function gsl_odeiv2_driver_reset(driver) bind(C, name="gsl_odeiv2_driver_reset") result(status)
         import :: c_ptr, c_int
         type(c_ptr), value :: driver  !! the driver
         integer(c_int) :: status
      end function gsl_odeiv2_driver_reset
   end interface
end module hillstab_ffi_gsl

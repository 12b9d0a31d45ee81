!> The monodromy of a system of Hill equations by GSL's odeiv2 driver with the Prince–Dormand
!> 8(7) pair rk8pd on the 4n² entries of the fundamental matrix (method `gsl` of a system: the
!> reference of another library, beside hillstab's own rk). Two passes, epsabs = epsrel =
!> tolerance/10 and then /320, over the whole period (no symmetry used, unlike hillstab's own methods);
!> the second value is returned, the difference of the two its error estimate (divided by 32,
!> GSL's global error following its epsilon about linearly), status_roundoff when that
!> estimate misses the tolerance (`system_monodromy` of hillstab_integrate_monodromy adds the
!> rounding level rk8pd accumulates). Where GSL's control cannot reach an epsilon (GSL_FAILURE, at its floor on a
!> strongly growing solution), the point is round-off limited, not failed: a failed second
!> pass leaves the first pass's Φ, a failed first pass at the floor is run again at ten
!> times the epsilon, each at status_roundoff. The right-hand side receives the system through GSL's
!> `params` pointer (no module state: calls may run on several threads at once).
!>
!>```fortran
!> call system_monodromy_gsl(system, form, alpha, beta, 1.0e-10_wp, result, error)
!>```
module hillstab_integrate_system_gsl
   use, intrinsic :: iso_c_binding, only: c_int, c_double, c_size_t, c_ptr, c_funptr, c_null_funptr, c_loc, &
      c_funloc, c_f_pointer, c_associated
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use hillstab_core_kinds, only: wp
   use hillstab_core_error, only: error_t, set_error, err_integration
   use hillstab_core_status, only: status_ok, status_roundoff, status_failed
   use hillstab_hill_system, only: hill_system_t, system_form_t, fundamental_derivative, lower_block
   use hillstab_integrate_system_magnus, only: system_monodromy_t, push_factor, window_length
   use hillstab_ffi_gsl, only: gsl_odeiv2_system, gsl_odeiv2_step_rk8pd, gsl_set_error_handler_off, &
      gsl_odeiv2_driver_alloc_y_new, gsl_odeiv2_driver_apply, gsl_odeiv2_driver_free, gsl_odeiv2_driver_set_nmax, &
      gsl_success, gsl_ebadfunc
   implicit none
   private
   public :: system_monodromy_gsl, gsl_period_factors

   !> What the right-hand side needs (GSL's params).
   type :: gsl_context_t
      class(hill_system_t), allocatable :: system
      type(system_form_t) :: form
      real(wp) :: alpha = 0.0_wp, beta = 0.0_wp
      real(wp), allocatable :: p(:, :), b(:, :)
      integer :: rhs_calls = 0   !! right-hand sides evaluated
   end type gsl_context_t

contains

   !> y' = A(t) y for the m × m fundamental matrix stored column by column.
   function fundamental_rhs(t, y, dydt, params) bind(C) result(status)
      real(c_double), value :: t
      real(c_double), intent(in) :: y(*)
      real(c_double), intent(out) :: dydt(*)
      type(c_ptr), value :: params
      integer(c_int) :: status
      type(gsl_context_t), pointer :: c
      integer :: m
      call c_f_pointer(params, c)
      m = c%form%states
      c%rhs_calls = c%rhs_calls + 1
      call c%system%stiffness(c%alpha, t, c%p, c%b)
      call fundamental_derivative(c%form, lower_block(c%form, c%p + c%beta*c%b), y(1:m*m), dydt(1:m*m))
      status = gsl_success
      if (.not. all(ieee_is_finite(dydt(1:m*m)))) status = gsl_ebadfunc
   end function fundamental_rhs

   !> The monodromy by rk8pd (see the module's text).
   subroutine system_monodromy_gsl(system, form, alpha, beta, tolerance, result, error)
      class(hill_system_t), intent(in) :: system  !! the system
      type(system_form_t), intent(in) :: form     !! prepared at its ε
      real(wp), intent(in) :: alpha, beta         !! the point
      real(wp), intent(in) :: tolerance           !! target error of Φ relative to max(1, max|Φ_ij|)
      !> Φ (log_scale 0), its error estimate, status and right-hand sides (`steps`)
      type(system_monodromy_t), intent(out) :: result
      type(error_t), allocatable, intent(out) :: error  !! err_integration when GSL fails
      real(wp), allocatable :: first(:, :), second(:, :)
      real(wp) :: eps, scale
      integer :: m, pass
      logical :: roundoff
      m = form%states
      roundoff = .false.
      ! the whole period, whatever the symmetry: an independent reference
      eps = gsl_first_epsilon(tolerance)
      allocate (result%phi(m, m), second(m, m))
      result%phi = 0.0_wp
      do pass = 1, 2
         call system_propagator_gsl(system, form, alpha, beta, eps, 0.0_wp, form%period, second, &
                                    result%steps, error)
         if (allocated(error) .and. pass == 1 .and. eps > 0.1_wp*tolerance) then
            ! at its floor GSL's control could not reach eps (GSL_FAILURE: the step falls
            ! below what rounding allows); ten times more, the tolerance out of reach
            deallocate (error)
            eps = 10.0_wp*eps
            call system_propagator_gsl(system, form, alpha, beta, eps, 0.0_wp, form%period, second, &
                                       result%steps, error)
            roundoff = .true.
         end if
         if (allocated(error) .and. pass == 2) then
            ! the first pass stands, its error unknown but above the second pass's reach
            deallocate (error)
            second = first
            roundoff = .true.
            exit
         end if
         if (allocated(error)) then
            result%status = status_failed
            return
         end if
         if (pass == 1) first = second
         eps = gsl_second_epsilon(eps)
      end do
      scale = max(1.0_wp, maxval(abs(second)))
      result%phi = second
      result%error_estimate = max(maxval(abs(second - first))/scale/32.0_wp, epsilon(1.0_wp))
      if (roundoff) result%error_estimate = max(result%error_estimate, 10.0_wp*tolerance)
      result%status = merge(status_ok, status_roundoff, result%error_estimate <= tolerance)
   end subroutine system_monodromy_gsl

   !> The factors of rk8pd over `pieces` equal subintervals of the window, each from the
   !> identity at the second pass's epsilon; the right-hand sides added to `steps`.
   subroutine gsl_period_factors(system, form, alpha, beta, tolerance, pieces, factors, count, steps, error)
      class(hill_system_t), intent(in) :: system      !! the system
      type(system_form_t), intent(in) :: form         !! prepared at the point's ε
      real(wp), intent(in) :: alpha, beta             !! the point
      real(wp), intent(in) :: tolerance               !! the method's tolerance
      integer, intent(in) :: pieces                   !! the subintervals (`factor_pieces`)
      real(wp), allocatable, intent(inout) :: factors(:, :, :)  !! receives F_1 … F_count
      integer, intent(inout) :: count                 !! the number of factors
      integer, intent(inout) :: steps                 !! right-hand sides spent
      type(error_t), allocatable, intent(out) :: error  !! err_integration when a piece fails
      real(wp) :: y(form%states, form%states), local, window
      integer :: k
      window = window_length(form)
      local = gsl_second_epsilon(gsl_first_epsilon(tolerance))
      do k = 1, pieces
         call system_propagator_gsl(system, form, alpha, beta, local, window*(k - 1)/pieces, window*k/pieces, &
                                    y, steps, error)
         if (allocated(error)) return
         call push_factor(factors, count, y)
      end do
   end subroutine gsl_period_factors

   !> GSL's epsilon of the first pass.
   pure real(wp) function gsl_first_epsilon(tolerance) result(eps)
      real(wp), intent(in) :: tolerance  !! the point's tolerance
      eps = max(0.1_wp*tolerance, 1.0e-14_wp)
   end function gsl_first_epsilon

   !> GSL's epsilon of the second pass from the first's.
   pure real(wp) function gsl_second_epsilon(first) result(eps)
      real(wp), intent(in) :: first  !! the first pass's epsilon
      eps = max(first/320.0_wp, 1.0e-15_wp)
   end function gsl_second_epsilon

   !> Y' = A(τ) Y from Y(t0) = I to t1 by rk8pd at epsabs = epsrel = eps; its right-hand sides
   !> added to `evaluations`.
   subroutine system_propagator_gsl(system, form, alpha, beta, eps, t0, t1, y, evaluations, error)
      class(hill_system_t), intent(in) :: system  !! the system
      type(system_form_t), intent(in) :: form     !! prepared at its ε
      real(wp), intent(in) :: alpha, beta         !! the point
      real(wp), intent(in) :: eps                 !! GSL's epsabs and epsrel
      real(wp), intent(in) :: t0, t1              !! the interval
      real(wp), intent(out) :: y(:, :)            !! Y(t1) (2n × 2n)
      integer, intent(inout) :: evaluations       !! right-hand sides, counted on
      type(error_t), allocatable, intent(out) :: error  !! err_integration when GSL fails
      type(gsl_context_t), target :: context
      type(gsl_odeiv2_system) :: sys
      type(c_ptr) :: driver
      type(c_funptr) :: previous
      real(wp), allocatable :: state(:)
      real(c_double) :: t
      integer :: m, i
      integer(c_int) :: status
      m = form%states
      allocate (context%system, source=system)
      context%form = form
      context%alpha = alpha
      context%beta = beta
      allocate (context%p(form%n, form%n), context%b(form%n, form%n))
      previous = gsl_set_error_handler_off()
      sys = gsl_odeiv2_system(c_funloc(fundamental_rhs), c_null_funptr, int(m*m, c_size_t), c_loc(context))
      y = 0.0_wp
      driver = gsl_odeiv2_driver_alloc_y_new(sys, gsl_odeiv2_step_rk8pd, 1.0e-3_c_double, eps, eps)
      if (.not. c_associated(driver)) then
         call set_error(error, err_integration, "gsl: the driver could not be allocated")
         return
      end if
      status = gsl_odeiv2_driver_set_nmax(driver, 10000000_8)
      state = [(merge(1.0_wp, 0.0_wp, mod(i, m + 1) == 0), i=0, m*m - 1)]
      t = t0
      status = gsl_odeiv2_driver_apply(driver, t, real(t1, c_double), state)
      call gsl_odeiv2_driver_free(driver)
      evaluations = evaluations + context%rhs_calls
      if (status /= gsl_success) then
         call set_error(error, err_integration, "gsl: rk8pd failed (GSL status "//trim(int_text(status))//")")
         return
      end if
      y = reshape(state, [m, m])
   end subroutine system_propagator_gsl

   pure function int_text(i) result(text)
      integer(c_int), intent(in) :: i
      character(len=16) :: text
      write (text, '(i0)') i
   end function int_text
end module hillstab_integrate_system_gsl

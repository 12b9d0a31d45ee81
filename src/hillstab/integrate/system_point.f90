!> One point of a system, as every task and the C API compute it: the monodromy by the
!> chosen method (hillstab_integrate_system), its Floquet analysis
!> (hillstab_hill_system_floquet), and, where one double-precision Φ cannot resolve the
!> smaller exponents, all of them again from the period's product kept factored
!> (`system_factors`, hillstab_hill_system_exponents).
!>
!> A multiplier λ_i of Φ is known only to about (e + 64 m ε_mach) max|Φ_jk| (e the method's
!> error estimate relative to max|Φ_jk|); its exponent ln|λ_i|/P then to that over |λ_i| P.
!> When that exceeds a tenth of the tolerance for one of the n exponents printed and that
!> multiplier lies three decades or more below the largest, the exponents are recomputed
!> from the factors, which keeps every one of them to the method's accuracy however many
!> decades they span. An exponent the iteration cannot resolve marks the point
!> status_roundoff (its numbers are the best reached, never a silent guess at status 0).
!>
!>```fortran
!> call system_point(system, form, alpha, beta, method, nodes, r, f, error)
!> print *, f%exponents   ! mu_1 … mu_n
!>```
module hillstab_integrate_system_point
   use hillstab_core_kinds, only: wp
   use hillstab_core_error, only: error_t
   use hillstab_core_status, only: status_ok, status_roundoff, status_failed
   use hillstab_hill_system, only: hill_system_t, system_form_t
   use hillstab_hill_system_floquet, only: system_floquet_t, system_floquet
   use hillstab_hill_system_exponents, only: factored_exponents
   use hillstab_integrate_system, only: system_method_t, system_monodromy_t, system_nodes_t, system_monodromy, &
      system_factors
   implicit none
   private
   public :: system_point, resolve_exponents, exponents_need_factoring

   !> a multiplier this far below the largest, or farther, may be lost in Φ
   real(wp), parameter :: spread_limit = 1.0e-3_wp

contains

   !> The monodromy at (α, β), its analysis, and all exponents resolved (see the module's text).
   subroutine system_point(system, form, alpha, beta, method, nodes, monodromy, floquet, error)
      class(hill_system_t), intent(in) :: system          !! the system
      type(system_form_t), intent(in) :: form             !! prepared at the point's ε
      real(wp), intent(in) :: alpha, beta                 !! the point
      type(system_method_t), intent(in) :: method         !! method and tolerance
      type(system_nodes_t), intent(inout) :: nodes        !! shared along a row (a fresh one for one point)
      type(system_monodromy_t), intent(out) :: monodromy  !! Φ, its scale, estimate, status, steps
      type(system_floquet_t), intent(out) :: floquet      !! the analysis (unset when the point failed)
      !> err_integration when the monodromy fails (status_failed); unallocated otherwise
      type(error_t), allocatable, intent(out) :: error
      call system_monodromy(system, form, alpha, beta, method, nodes, monodromy, error)
      if (allocated(error) .or. monodromy%status == status_failed) return
      call system_floquet(monodromy%phi, form, monodromy%error_estimate*max(1.0_wp, maxval(abs(monodromy%phi))), &
                          floquet, monodromy%log_scale)
      call resolve_exponents(system, form, alpha, beta, method, nodes, monodromy, floquet)
   end subroutine system_point

   !> The exponents of `floquet` from the factored product where Φ cannot resolve them
   !> (`exponents_need_factoring`); status_roundoff on `monodromy` where they stay unresolved.
   subroutine resolve_exponents(system, form, alpha, beta, method, nodes, monodromy, floquet)
      class(hill_system_t), intent(in) :: system            !! the system
      type(system_form_t), intent(in) :: form               !! prepared at the point's ε
      real(wp), intent(in) :: alpha, beta                   !! the point
      type(system_method_t), intent(in) :: method           !! method and tolerance
      type(system_nodes_t), intent(inout) :: nodes          !! as for `system_monodromy`
      type(system_monodromy_t), intent(inout) :: monodromy  !! the point's monodromy: status, steps
      type(system_floquet_t), intent(inout) :: floquet      !! its analysis: the exponents
      real(wp), allocatable :: factors(:, :, :), all_exponents(:)
      logical, allocatable :: resolved(:)
      type(error_t), allocatable :: cause
      integer :: count, n
      if (.not. exponents_need_factoring(floquet, monodromy, method%tolerance)) return
      n = form%n
      call system_factors(system, form, alpha, beta, method, nodes, monodromy, factors, count, cause)
      if (allocated(cause)) then
         ! the exponents stay those of Φ, which do not meet the tolerance
         monodromy%status = max(monodromy%status, status_roundoff)
         floquet%exponents_resolved = .false.
         return
      end if
      allocate (all_exponents(2*n), resolved(2*n))
      call factored_exponents(factors(:, :, 1:count), form%period, method%tolerance, all_exponents, resolved)
      floquet%exponents = all_exponents(1:n)
      floquet%exponents_resolved = all(resolved(1:n))
      if (.not. floquet%exponents_resolved) monodromy%status = max(monodromy%status, status_roundoff)
   end subroutine resolve_exponents

   !> Whether one of the n exponents of `floquet` may be off by more than a tenth of the
   !> tolerance because its multiplier lies far below the largest (see the module's text).
   pure logical function exponents_need_factoring(floquet, monodromy, tolerance) result(need)
      type(system_floquet_t), intent(in) :: floquet      !! the analysis of Φ
      type(system_monodromy_t), intent(in) :: monodromy  !! Φ̃, its scale and error estimate
      real(wp), intent(in) :: tolerance                  !! the point's tolerance
      real(wp) :: log_norm, log_top, log_lambda, relative
      integer :: i, m
      need = .false.
      if (floquet%n < 2) return
      m = 2*floquet%n
      log_norm = log(max(1.0_wp, maxval(abs(monodromy%phi)))) + monodromy%log_scale
      log_top = floquet%exponents(1)*floquet%period
      relative = monodromy%error_estimate + 64.0_wp*m*epsilon(1.0_wp)
      do i = 2, floquet%n
         if (floquet%exponents(i) < -huge(1.0_wp)/8.0_wp) then
            ! a multiplier Φ̃ rounds to 0: lost
            need = .true.
            return
         end if
         log_lambda = floquet%exponents(i)*floquet%period
         if (log_lambda - log_top > log(spread_limit)) cycle
         ! |Δλ_i|/|λ_i| ≈ relative ‖Φ‖/|λ_i|; its exponent's error that over P
         if (log(relative) + log_norm - log_lambda > log(0.1_wp*tolerance*floquet%period)) need = .true.
      end do
   end function exponents_need_factoring

end module hillstab_integrate_system_point

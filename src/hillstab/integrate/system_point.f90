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
   use hillstab_hill_system_floquet, only: floquet_t, system_floquet
   use hillstab_hill_system_exponents, only: factored_exponents
   use hillstab_integrate_system, only: system_method_t, system_monodromy_t, system_nodes_t, system_monodromy, &
      system_factors
   implicit none
   private
   public :: system_point, resolve_exponents, exponents_need_factoring, a2_needs_factoring, second_invariant

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
      type(floquet_t), intent(out) :: floquet      !! the analysis (unset when the point failed)
      !> err_integration when the monodromy fails (status_failed); unallocated otherwise
      type(error_t), allocatable, intent(out) :: error
      call system_monodromy(system, form, alpha, beta, method, nodes, monodromy, error)
      if (allocated(error) .or. monodromy%status == status_failed) return
      call system_floquet(monodromy%phi, form, monodromy%error_estimate*max(1.0_wp, maxval(abs(monodromy%phi))), &
                          floquet, monodromy%log_scale, beta)
      call resolve_exponents(system, form, alpha, beta, method, nodes, monodromy, floquet)
   end subroutine system_point

   !> The exponents of `floquet` from the factored product where Φ cannot resolve them
   !> (`exponents_need_factoring`), and a₂ from the multipliers found there where the
   !> cancellation in ((tr Φ)² − tr Φ²)/2 exceeds a tenth of the tolerance relative to
   !> max(1, |a₂|) (`a2_needs_factoring`); status_roundoff on `monodromy` where they stay
   !> unresolved.
   subroutine resolve_exponents(system, form, alpha, beta, method, nodes, monodromy, floquet)
      class(hill_system_t), intent(in) :: system            !! the system
      type(system_form_t), intent(in) :: form               !! prepared at the point's ε
      real(wp), intent(in) :: alpha, beta                   !! the point
      type(system_method_t), intent(in) :: method           !! method and tolerance
      type(system_nodes_t), intent(inout) :: nodes          !! as for `system_monodromy`
      type(system_monodromy_t), intent(inout) :: monodromy  !! the point's monodromy: status, steps
      type(floquet_t), intent(inout) :: floquet      !! its analysis: exponents, a₂
      real(wp), allocatable :: factors(:, :, :), all_exponents(:), arguments(:)
      logical, allocatable :: resolved(:)
      type(error_t), allocatable :: cause
      integer :: count, n
      logical :: need_exponents, need_a2
      need_exponents = exponents_need_factoring(floquet, monodromy, method%tolerance)
      need_a2 = a2_needs_factoring(floquet, monodromy, method%tolerance)
      if (.not. (need_exponents .or. need_a2)) return
      n = form%n
      call system_factors(system, form, alpha, beta, method, nodes, monodromy, factors, count, cause)
      if (allocated(cause)) then
         ! the values stay those of Φ, which do not meet the tolerance
         monodromy%status = max(monodromy%status, status_roundoff)
         floquet%exponents_resolved = .false.
         return
      end if
      allocate (all_exponents(form%states), resolved(form%states), arguments(form%states))
      call factored_exponents(factors(:, :, 1:count), form%period, method%tolerance, all_exponents, resolved, &
                              arguments=arguments)
      if (need_exponents) then
         floquet%exponents = all_exponents(1:n)
         floquet%exponents_resolved = all(resolved(1:n))
         if (.not. floquet%exponents_resolved) monodromy%status = max(monodromy%status, status_roundoff)
      end if
      if (need_a2) then
         call second_invariant(all_exponents*form%period, arguments, floquet%a2, floquet%overflow)
         if (.not. all(resolved)) monodromy%status = max(monodromy%status, status_roundoff)
      end if
   end subroutine resolve_exponents

   !> Whether the cancellation in a₂ = ((tr Φ)² − tr Φ²)/2 loses it: the terms it cancels,
   !> T = Σ Φ_ii² + Σ_{i<j} (|Φ_ii Φ_jj| + |Φ_ij Φ_ji|), exceed |a₂| (at least 1) ten
   !> thousandfold and their rounding, 4 ε T, exceeds a tenth of the tolerance relative to
   !> max(1, |a₂|). (The method's own error of Φ moves a₂ alike by every route.)
   pure logical function a2_needs_factoring(floquet, monodromy, tolerance) result(need)
      type(floquet_t), intent(in) :: floquet      !! the analysis of Φ
      type(system_monodromy_t), intent(in) :: monodromy  !! Φ̃ and its scale
      real(wp), intent(in) :: tolerance                  !! the point's tolerance
      real(wp) :: terms, big, log_cancellation
      integer :: i, j, m
      m = size(monodromy%phi, 1)
      ! on Φ̃ scaled to its largest entry (T of Φ is e^{2s} big² times this)
      big = max(maxval(abs(monodromy%phi)), tiny(1.0_wp))
      terms = 0.0_wp
      do i = 1, m
         terms = terms + (monodromy%phi(i, i)/big)**2
         do j = i + 1, m
            terms = terms + abs((monodromy%phi(i, i)/big)*(monodromy%phi(j, j)/big)) + &
                    abs((monodromy%phi(i, j)/big)*(monodromy%phi(j, i)/big))
         end do
      end do
      need = .false.
      if (terms <= 0.0_wp) return
      log_cancellation = log(terms) + 2.0_wp*(log(big) + monodromy%log_scale) - log(max(1.0_wp, abs(floquet%a2)))
      need = log_cancellation > log(1.0e4_wp) .and. &
             log(4.0_wp*epsilon(1.0_wp)) + log_cancellation > log(0.1_wp*tolerance)
   end function a2_needs_factoring

   !> a₂ = Σ_{i<j} λ_i λ_j from the multipliers' logarithms of modulus and their arguments,
   !> scaled by the largest product so that nothing overflows (±1e300 with `overflow`).
   pure subroutine second_invariant(log_moduli, arguments, a2, overflow)
      real(wp), intent(in) :: log_moduli(:), arguments(:)  !! by decreasing modulus
      real(wp), intent(out) :: a2          !! a₂ (±1e300 where it overflows)
      logical, intent(inout) :: overflow   !! set where a₂ overflows
      real(wp) :: top, x, power
      integer :: i, j
      top = log_moduli(1) + log_moduli(2)
      x = 0.0_wp
      do i = 1, size(log_moduli) - 1
         do j = i + 1, size(log_moduli)
            power = log_moduli(i) + log_moduli(j) - top
            if (power > -700.0_wp) x = x + exp(power)*cos(arguments(i) + arguments(j))
         end do
      end do
      if (x == 0.0_wp) then
         a2 = 0.0_wp
      else if (log(abs(x)) + top > log(1.0e300_wp)) then
         a2 = sign(1.0e300_wp, x)
         overflow = .true.
      else
         a2 = x*exp(max(top, -700.0_wp))
      end if
   end subroutine second_invariant

   !> Whether one of the n exponents of `floquet` may be off by more than a tenth of the
   !> tolerance because its multiplier lies far below the largest (see the module's text).
   pure logical function exponents_need_factoring(floquet, monodromy, tolerance) result(need)
      type(floquet_t), intent(in) :: floquet      !! the analysis of Φ
      type(system_monodromy_t), intent(in) :: monodromy  !! Φ̃, its scale and error estimate
      real(wp), intent(in) :: tolerance                  !! the point's tolerance
      real(wp) :: log_norm, log_top, log_lambda, relative
      integer :: i, m
      need = .false.
      if (floquet%n < 2) return
      m = size(monodromy%phi, 1)
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

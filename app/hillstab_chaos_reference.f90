!> Long reference runs for the chaos indicators:
!> `hillstab_chaos_reference GRID N PERIODS RTOL FILE` or `hillstab_chaos_reference POINTS LIST PERIODS RTOL FILE`.
!>
!> Every point is integrated by `lyapunov_largest` (DOP853 on the trajectory and the
!> variational equations, Benettin's renormalisation every radial period: the code that
!> predates the chaos indicators and shares nothing with the symplectic tangent maps),
!> from φ0 = 0.017 at rest (eq. (38)), r0 = 0.1 m, g = 9.81 m/s², for PERIODS radial
!> periods at tolerance RTOL. Written per point: the finite-time exponent λ_n and MEGNO
!> ⟨Y⟩_n at n = 300, 1000 and PERIODS (MEGNO from ln‖δ‖ at the period ends: Y(t) =
!> 2(L(t) − (1/t)∫₀ᵗ L ds), ⟨Y⟩ = (1/t)∫₀ᵗ Y ds, L = ln‖δ‖, by the trapezoidal rule over
!> the periods), the largest |φ| and the energy drift, and the reference verdict:
!>
!>   1 (chaotic) when λ_PERIODS > 0.02 and ⟨Y⟩_PERIODS > 8,
!>   0 (regular) when λ_PERIODS < 0.01 and ⟨Y⟩_PERIODS < 4,
!>   0.5 (not clear) otherwise.
!>
!> A regular orbit has ‖δ‖ growing at most linearly, so λ_n ≲ ln n / n (2.7e-3 at
!> n = 3000) and ⟨Y⟩ → 2; a chaotic one λ_n → λ > 0 and ⟨Y⟩ ≈ λ n/2 (30 at λ = 0.02,
!> n = 3000). The gaps between the two rules leave out the orbits that a finite run cannot
!> call (sticky or weakly chaotic ones).
!>
!> GRID N: the cell-centred N × N grid of the physical domain, α_i = (i − ½)π²/N,
!> β_j = (j − ½)π²/N (α outer). POINTS LIST: the (α, β) pairs of file LIST, one a line
!> ('#' lines skipped). Points run in parallel (OpenMP); the file is written in order.
program hillstab_chaos_reference
   use hillstab_core_kinds, only: wp, pi2
   use hillstab_core_error, only: error_t
   use hillstab_pendulum_equations, only: pendulum_t, pendulum_from_chart, pendulum_initial_state
   use hillstab_pendulum_lyapunov, only: lyapunov_t, lyapunov_largest
   implicit none
   real(wp), parameter :: phi0 = 0.017_wp
   character(len=512) :: mode, argument, path, list
   real(wp), allocatable :: points(:, :), rows(:, :)
   real(wp) :: rtol, a, b
   integer :: n, periods, i, j, k, unit, ios, n_points
   character(len=512) :: line

   if (command_argument_count() /= 5) then
      write (*, '(a)') "usage: hillstab_chaos_reference grid N PERIODS RTOL FILE | points LIST PERIODS RTOL FILE"
      error stop 2
   end if
   call get_command_argument(1, mode)
   call get_command_argument(2, list)
   call get_command_argument(3, argument); read (argument, *) periods
   call get_command_argument(4, argument); read (argument, *) rtol
   call get_command_argument(5, path)
   if (periods < 1000) error stop "hillstab_chaos_reference: PERIODS must be >= 1000"
   if (mode == "grid") then
      read (list, *) n
      allocate (points(2, n*n))
      k = 0
      do i = 1, n
         do j = 1, n
            k = k + 1
            points(:, k) = [(i - 0.5_wp)*pi2/n, (j - 0.5_wp)*pi2/n]
         end do
      end do
   else if (mode == "points") then
      open (newunit=unit, file=trim(list), status="old", action="read", iostat=ios)
      if (ios /= 0) error stop "hillstab_chaos_reference: cannot read the points list"
      allocate (points(2, 100000))
      n_points = 0
      do
         read (unit, '(a)', iostat=ios) line
         if (ios /= 0) exit
         line = adjustl(line)
         if (len_trim(line) == 0 .or. line(1:1) == "#") cycle
         read (line, *) a, b
         n_points = n_points + 1
         points(:, n_points) = [a, b]
      end do
      close (unit)
      points = points(:, 1:n_points)
   else
      error stop "hillstab_chaos_reference: mode must be grid or points"
   end if
   n_points = size(points, 2)
   allocate (rows(12, n_points))
   !$omp parallel do schedule(dynamic) default(shared) private(k)
   do k = 1, n_points
      call reference_point(points(1, k), points(2, k), rows(:, k))
   end do
   !$omp end parallel do
   open (newunit=unit, file=trim(path), status="replace", action="write")
   write (unit, '(a)') "# hillstab_chaos_reference: lyapunov_largest (DOP853, variational equations, "// &
      "renormalised every radial period), phi0 = 0.017 at rest, r0 = 0.1, g = 9.81"
   write (unit, '(a,i0,a,es8.1)') "# periods = ", periods, ", rtol = ", rtol
   write (unit, '(a)') "# verdict: 1 chaotic (lambda > 0.02 and megno > 8 at the last period), 0 regular "// &
      "(lambda < 0.01 and megno < 4), 0.5 not clear; megno from ln|delta| at the period ends"
   write (unit, '(a)') "# columns: alpha beta lambda_300 lambda_1000 lambda_end megno_300 megno_1000 megno_end "// &
      "max_abs_phi energy_drift verdict failed"
   do k = 1, n_points
      write (unit, '(2f22.17,3es16.8,3es14.6,es14.6,es10.2,f5.1,i3)') rows(1:10, k), rows(11, k), nint(rows(12, k))
   end do
   close (unit)

contains

   !> One point: its row (alpha beta lambda×3 megno×3 max_abs_phi drift verdict failed).
   subroutine reference_point(alpha, beta, row)
      real(wp), intent(in) :: alpha, beta
      real(wp), intent(out) :: row(12)
      type(pendulum_t) :: p
      type(lyapunov_t) :: result
      type(error_t), allocatable :: error
      real(wp) :: megno(3), lam(3), level, i1, i2, y_prev, y_now, l_prev, l_now
      integer :: m, checkpoints(3), c
      row = 0.0_wp
      row(1:2) = [alpha, beta]
      call pendulum_from_chart(alpha, beta, 0.0_wp, 0.1_wp, 9.81_wp, p, error)
      if (.not. allocated(error)) &
         call lyapunov_largest(p, pendulum_initial_state(p, phi0), periods, rtol, result, error)
      if (allocated(error)) then
         row(11) = 0.5_wp
         row(12) = 1.0_wp
         return
      end if
      checkpoints = [300, 1000, periods]
      ! MEGNO by the trapezoidal rule over the period ends (t in radial periods)
      level = 0.0_wp
      i1 = 0.0_wp
      i2 = 0.0_wp
      l_prev = 0.0_wp
      y_prev = 0.0_wp
      c = 1
      do m = 1, periods
         l_now = level + result%log_growth(m)
         level = l_now
         i1 = i1 + 0.5_wp*(l_prev + l_now)
         y_now = 2.0_wp*(l_now - i1/m)
         i2 = i2 + 0.5_wp*(y_prev + y_now)
         l_prev = l_now
         y_prev = y_now
         do while (c <= 3)
            if (checkpoints(c) /= m) exit
            megno(c) = i2/m
            lam(c) = result%running(m)
            c = c + 1
         end do
      end do
      row(3:5) = lam
      row(6:8) = megno
      row(9) = result%max_abs_phi
      row(10) = result%energy_drift
      if (lam(3) > 0.02_wp .and. megno(3) > 8.0_wp) then
         row(11) = 1.0_wp
      else if (lam(3) < 0.01_wp .and. megno(3) < 4.0_wp) then
         row(11) = 0.0_wp
      else
         row(11) = 0.5_wp
      end if
   end subroutine reference_point
end program hillstab_chaos_reference

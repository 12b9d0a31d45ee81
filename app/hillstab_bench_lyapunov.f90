!> Benchmark of the Lyapunov map: `hillstab_bench_lyapunov [STRIDE [RTOL]]`.
!>
!> A 100 × 100 map over the physical domain (α = 0.05 … 9.8, β = 0.1 … 9.75) at 300
!> radial periods from φ0 = 0.017 (r0 = 0.1 m, g = 9.81 m/s², tolerance 1e-10), one
!> thread, computed by hillstab (DOP853, `lyapunov_largest`) and by GSL rk8pd driving the
!> same equations (`lyapunov_largest_gsl`), side by side in one run: points per second
!> per core and their ratio, f-evaluations per point. Times are CPU times of this
!> (single-threaded) process, so that other jobs on the machine do not count. STRIDE > 1
!> takes every STRIDE-th α and β only; RTOL sets hillstab's tolerance (GSL keeps 1e-10),
!> to compare at equal accuracy. Then, on every 10th point of the map:
!> - accuracy: both against a reference at tolerance 1e-13 (DOP853), on the points whose
!>   reference looks regular (exponent below 3 ln N / N; on chaotic orbits a finite-time
!>   exponent depends on the path the rounding takes, so no reference exists there);
!> - where the time goes: the trajectory alone (4-D system, same tolerances), the
!>   trajectory with the tangent vector (the exponent), and writing the line.
!> Prints a table on stdout; writes out/bench_lyapunov.dat (per point: α β, both
!> exponents, both times, both f-evaluation counts) for the cost map.
program hillstab_bench_lyapunov
   use hillstab_core_kinds, only: wp, int64
   use hillstab_core_error, only: error_t
   use hillstab_integrate_rk, only: rk_options_t, rk_integrate, rk_dop853
   use hillstab_core_stats, only: work_stats_t
   use hillstab_pendulum_equations, only: pendulum_t, pendulum_from_chart, pendulum_initial_state, pendulum_system_t, &
      pendulum_atol
   use hillstab_pendulum_lyapunov, only: lyapunov_t, lyapunov_largest
   use hillstab_pendulum_gsl_lyapunov, only: lyapunov_largest_gsl
   use hillstab_core_text, only: put_es
   implicit none
   integer, parameter :: n_grid = 100, periods = 300
   real(wp), parameter :: alpha_min = 0.05_wp, alpha_max = 9.8_wp, beta_min = 0.1_wp, beta_max = 9.75_wp
   real(wp), parameter :: phi0 = 0.017_wp, gsl_rtol = 1.0e-10_wp
   real(wp) :: rtol
   real(wp), allocatable :: alphas(:), betas(:), lam(:, :), seconds(:, :), evaluations(:, :)
   type(pendulum_t), allocatable :: pendula(:)
   type(lyapunov_t) :: result, reference
   type(error_t), allocatable :: error
   integer :: stride, i, j, k, n, unit, n_failed(2), n_regular, method
   real(wp) :: t0, t1
   real(wp) :: total(2), error_sum(2), error_max(2), e, t_trajectory, t_full, t_output
   character(len=32) :: argument
   character(len=240) :: line
   character(len=*), parameter :: names(2) = [character(len=16) :: "hillstab DOP853", "GSL rk8pd"]

   stride = 1
   rtol = 1.0e-10_wp
   if (command_argument_count() >= 1) then
      call get_command_argument(1, argument)
      read (argument, *) stride
   end if
   if (command_argument_count() >= 2) then
      call get_command_argument(2, argument)
      read (argument, *) rtol
   end if
   alphas = [(alpha_min + (alpha_max - alpha_min)*(i - 1)/(n_grid - 1), i=1, n_grid, stride)]
   betas = [(beta_min + (beta_max - beta_min)*(j - 1)/(n_grid - 1), j=1, n_grid, stride)]
   n = size(alphas)*size(betas)
   allocate (pendula(n), lam(n, 2), seconds(n, 2), evaluations(n, 2))
   k = 0
   do i = 1, size(alphas)
      do j = 1, size(betas)
         k = k + 1
         call pendulum_from_chart(alphas(i), betas(j), 0.0_wp, 0.1_wp, 9.81_wp, pendula(k), error)
         if (allocated(error)) error stop "bench: bad grid"
      end do
   end do
   write (*, '(a,i0,a,i0,a,i0,a,es8.1,a)') "Lyapunov map: ", size(alphas), " x ", size(betas), " points, ", periods, &
      " radial periods, phi0 = 0.017, tolerance ", rtol, " (hillstab), 1e-10 (GSL), one thread, CPU time"
   n_failed = 0
   do method = 1, 2
      do k = 1, n
         call cpu_time(t0)
         if (method == 1) then
            call lyapunov_largest(pendula(k), pendulum_initial_state(pendula(k), phi0), periods, rtol, result, error)
         else
            call lyapunov_largest_gsl(pendula(k), pendulum_initial_state(pendula(k), phi0), periods, gsl_rtol, result, &
               error)
         end if
         call cpu_time(t1)
         seconds(k, method) = (t1 - t0)
         lam(k, method) = result%exponent
         evaluations(k, method) = real(result%stats%n_evaluations, wp)
         if (allocated(error)) n_failed(method) = n_failed(method) + 1
      end do
      total(method) = sum(seconds(:, method))
   end do
   write (*, '(/,a)') "| integrator | points/s per core | f-evaluations per point | failed points |"
   write (*, '(a)') "|---|---|---|---|"
   do method = 1, 2
      write (*, '(a,a,a,f8.1,a,f10.0,a,i0,a)') "| ", trim(names(method)), " | ", n/total(method), " | ", &
         sum(evaluations(:, method))/n, " | ", n_failed(method), " |"
   end do
   write (*, '(a,f6.2,a)') "hillstab is ", total(2)/total(1), " x the speed of GSL rk8pd on the same equations"
   write (*, '(a,f6.2,a,f6.2,a)') "busiest point: ", maxval(seconds(:, 1))*1e3_wp, " ms (hillstab), mean ", &
      total(1)/n*1e3_wp, " ms"

   ! accuracy on the regular points of every 10th point
   error_sum = 0.0_wp
   error_max = 0.0_wp
   n_regular = 0
   do k = 1, n, 10
      call lyapunov_largest(pendula(k), pendulum_initial_state(pendula(k), phi0), periods, 1.0e-13_wp, reference, error)
      if (allocated(error)) cycle
      if (reference%exponent >= 3.0_wp*log(real(periods, wp))/periods) cycle
      n_regular = n_regular + 1
      do method = 1, 2
         e = abs(lam(k, method) - reference%exponent)
         error_sum(method) = error_sum(method) + e
         error_max(method) = max(error_max(method), e)
      end do
   end do
   write (*, '(/,a,i0,a)') "accuracy against tolerance 1e-13, on ", n_regular, &
      " regular points (reference exponent < 3 ln N/N):"
   do method = 1, 2
      write (*, '(a,a,a,es9.2,a,es9.2)') "  ", trim(names(method)), ": mean |error| ", &
         error_sum(method)/max(1, n_regular), ", max ", error_max(method)
   end do

   ! where the time goes, on every 10th point
   t_trajectory = 0.0_wp
   t_full = 0.0_wp
   t_output = 0.0_wp
   do k = 1, n, 10
      call cpu_time(t0)
      call trajectory_only(pendula(k))
      call cpu_time(t1)
      t_trajectory = t_trajectory + (t1 - t0)
      call cpu_time(t0)
      call lyapunov_largest(pendula(k), pendulum_initial_state(pendula(k), phi0), periods, rtol, result, error)
      call cpu_time(t1)
      t_full = t_full + (t1 - t0)
      call cpu_time(t0)
      do i = 1, 100
         call format_line(pendula(k), result, line)
      end do
      call cpu_time(t1)
      t_output = t_output + (t1 - t0)/100
   end do
   write (*, '(/,a)') "where the time goes (hillstab, every 10th point):"
   write (*, '(a,f6.1,a)') "  trajectory alone (4-D):           ", 100*t_trajectory/(t_full + t_output), " %"
   write (*, '(a,f6.1,a)') "  tangent vector (8-D minus 4-D):   ", 100*(t_full - t_trajectory)/(t_full + t_output), " %"
   write (*, '(a,f6.3,a)') "  formatting the output line:       ", 100*t_output/(t_full + t_output), " %"

   open (newunit=unit, file="out/bench_lyapunov.dat", status="replace", action="write")
   write (unit, '(a,es8.1,a)') "# hillstab_bench_lyapunov: 300 radial periods, phi0 = 0.017, tolerance ", rtol, &
      " (hillstab), 1e-10 (GSL), one thread, CPU seconds"
   write (unit, '(a)') "# columns: alpha beta lyapunov_dop853 lyapunov_rk8pd seconds_dop853 seconds_rk8pd "// &
      "evaluations_dop853 evaluations_rk8pd"
   k = 0
   do i = 1, size(alphas)
      if (i > 1) write (unit, '(a)') ""
      do j = 1, size(betas)
         k = k + 1
         write (unit, '(2f10.5,2es16.8,2es12.4,2f12.0)') alphas(i), betas(j), lam(k, :), seconds(k, :), evaluations(k, :)
      end do
   end do
   close (unit)
   write (*, '(/,a)') "wrote out/bench_lyapunov.dat"

contains

   !> The trajectory alone over the same periods, with the same state tolerances and the
   !> same period-by-period restarts.
   subroutine trajectory_only(p)
      type(pendulum_t), intent(in) :: p
      type(pendulum_system_t) :: system
      type(rk_options_t) :: options
      type(error_t), allocatable :: error
      real(wp) :: y(4), t, h_next
      integer :: m
      system%pendulum = p
      y = pendulum_initial_state(p, phi0)
      options = rk_options_t(method=rk_dop853, rtol=rtol, atol=rtol, max_steps=1000000)
      options%atol_components = pendulum_atol(p, y, rtol)
      t = 0.0_wp
      h_next = 0.0_wp
      do m = 1, periods
         options%h_initial = h_next
         call rk_integrate(system, t, m*p%period, y, options, error=error, h_next=h_next)
      end do
   end subroutine trajectory_only

   !> One line as the task writes it (eleven numbers).
   subroutine format_line(p, r, line)
      type(pendulum_t), intent(in) :: p
      type(lyapunov_t), intent(in) :: r
      character(len=*), intent(out) :: line
      integer :: pos
      pos = 0
      call put_es(line, pos, p%alpha, 16)
      call put_es(line, pos, p%beta, 16)
      call put_es(line, pos, r%exponent, 10)
      call put_es(line, pos, r%spread, 3)
      call put_es(line, pos, 1.5_wp, 10)
      call put_es(line, pos, 0.4_wp, 10)
      call put_es(line, pos, r%max_abs_phi, 6)
      call put_es(line, pos, r%energy_drift, 3)
   end subroutine format_line
end program hillstab_bench_lyapunov

!> Benchmark of the chaos map (`make bench-lyapunov`), two modes:
!>
!> `hillstab_bench_lyapunov map N PERIODS ROUNDS REFERENCE GSL_PROGRAM`
!>   The cell-centred N × N map of the physical domain, α_i = (i − ½)π²/N,
!>   β_j = (j − ½)π²/N, PERIODS radial periods from φ0 = 0.017 at rest (r0 = 0.1 m,
!>   g = 9.81 m/s²), one thread, three contenders side by side, interleaved A, B, C, A,
!>   B, C, … for ROUNDS rounds:
!>   A. hillstab `chaos_indicators_batch` with the default options (integrator auto: the
!>      symplectic tangent map in lanes, DOP853 where a fixed step cannot hold the energy;
!>      MEGNO verdict; early stop);
!>   B. the plain C program a user would write (bench/lyapunov_gsl.c, GSL's rk8pd driver
!>      on the 8 equations, `gsl_odeiv2_driver_apply` to every radial period,
!>      epsabs = epsrel = 1e-10; verdict λ > 0.03 per radial period), run as a separate
!>      process that reports its own CPU time;
!>   C. hillstab `lyapunov_largest` (DOP853 at 1e-10), what the lyapunov task computes per
!>      point today (verdict λ > 0.03).
!>   CPU time of each contender (per core: one thread); its verdicts against REFERENCE,
!>   a 3000-period run of every point (app/hillstab_chaos_reference.f90, `lyapunov_largest`
!>   at 1e-11), on the points it calls clearly regular or chaotic; evaluations per
!>   point; the energy error along the orbits; λ against the reference's λ at the same
!>   number of periods on the regular and the chaotic set (A without early stop for this,
!>   untimed). Then A's options varied one at a time (lanes, scheme, step base, early
!>   stop; each timed once). Writes out/bench_lyapunov.dat (per point) for
!>   plots/bench_lyapunov.gp.
!>
!> `hillstab_bench_lyapunov estimate N PERIODS STRIDE`
!>   Every STRIDE-th point of the N × N map (row by row) with A at PERIODS radial periods,
!>   in parallel (OpenMP threads over units of 64 points, as many threads as
!>   OMP_NUM_THREADS), wall and CPU time, and the whole map's time extrapolated by the
!>   number of points (exact when STRIDE = 1). Writes out/bench_lyapunov_map.dat.
program hillstab_bench_lyapunov
   use hillstab_core_kinds, only: wp, int64, pi2
   use hillstab_core_error, only: error_t
   use hillstab_pendulum_equations, only: pendulum_t, pendulum_from_chart, pendulum_initial_state
   use hillstab_pendulum_lyapunov, only: lyapunov_t, lyapunov_largest
   use hillstab_pendulum_chaos, only: chaos_t, chaos_options_t, chaos_indicators_batch, chaos_symplectic, chaos_dop853, &
      chaos_verdict_rule
   use hillstab_pendulum_symplectic, only: symplectic_blanes_moan4, symplectic_mclachlan8, symplectic_yoshida6
   implicit none
   real(wp), parameter :: phi0 = 0.017_wp, rtol = 1.0e-10_wp, lambda_chaotic = 0.03_wp
   character(len=512) :: mode, argument

   call get_command_argument(1, mode)
   select case (mode)
   case ("map")
      call run_map()
   case ("estimate")
      call run_estimate()
   case default
      write (*, '(a)') "usage: hillstab_bench_lyapunov map N PERIODS ROUNDS REFERENCE GSL_PROGRAM"
      write (*, '(a)') "       hillstab_bench_lyapunov estimate N PERIODS STRIDE"
      error stop 2
   end select

contains

   !> Integer command-line argument i.
   integer function int_argument(i)
      integer, intent(in) :: i
      character(len=64) :: text
      call get_command_argument(i, text)
      read (text, *) int_argument
   end function int_argument

   !> The pendula and starts of the cell-centred n × n map (α outer).
   subroutine grid(n, pendula, y0)
      integer, intent(in) :: n
      type(pendulum_t), allocatable, intent(out) :: pendula(:)
      real(wp), allocatable, intent(out) :: y0(:, :)
      type(error_t), allocatable :: error
      integer :: i, j, k
      allocate (pendula(n*n), y0(4, n*n))
      k = 0
      do i = 1, n
         do j = 1, n
            k = k + 1
            call pendulum_from_chart((i - 0.5_wp)*pi2/n, (j - 0.5_wp)*pi2/n, 0.0_wp, 0.1_wp, 9.81_wp, pendula(k), error)
            if (allocated(error)) error stop "bench: grid point refused"
            y0(:, k) = pendulum_initial_state(pendula(k), phi0)
         end do
      end do
   end subroutine grid

   !> Median of x (a copy is sorted).
   real(wp) function median(x)
      real(wp), intent(in) :: x(:)
      real(wp) :: s(size(x)), v
      integer :: i, j
      median = 0.0_wp
      if (size(x) == 0) return
      s = x
      do i = 2, size(s)
         v = s(i)
         j = i - 1
         do while (j >= 1)
            if (s(j) <= v) exit
            s(j + 1) = s(j)
            j = j - 1
         end do
         s(j + 1) = v
      end do
      median = s((size(s) + 1)/2)
   end function median

   subroutine run_map()
      integer :: n, periods, rounds, n_points, k, r, c, unit, ios, i, j
      character(len=512) :: reference_path, gsl_program, line, command
      type(pendulum_t), allocatable :: pendula(:)
      real(wp), allocatable :: y0(:, :), seconds(:, :), reference(:, :), lam(:, :), verdict(:, :), evaluations(:, :), &
         energy(:, :), row(:)
      type(chaos_t), allocatable :: a(:), a_full(:)
      type(lyapunov_t) :: today
      type(chaos_options_t) :: options, full
      type(error_t), allocatable :: error
      real(wp) :: t0, t1, ratio(2, 100), ref_lambda
      integer :: agree(3), wrong(3), undecided(3), n_clear, ref_col
      logical, allocatable :: regular(:), chaotic(:)
      character(len=*), parameter :: names(3) = [character(len=34) :: "A hillstab chaos (auto, lanes)", &
         "B plain C program, GSL rk8pd", "C hillstab lyapunov_largest DOP853"]
      character(len=*), parameter :: points_file = "out/bench_lyapunov_points.txt", gsl_file = "out/bench_lyapunov_gsl.dat"

      n = int_argument(2)
      periods = int_argument(3)
      rounds = min(100, int_argument(4))
      call get_command_argument(5, reference_path)
      call get_command_argument(6, gsl_program)
      call grid(n, pendula, y0)
      n_points = n*n
      allocate (seconds(3, rounds), lam(n_points, 3), verdict(n_points, 3), evaluations(n_points, 3), &
         energy(n_points, 3), a(n_points), a_full(n_points), reference(n_points, 12), row(12))

      ! the reference: the same points, 3000 periods
      open (newunit=unit, file=trim(reference_path), status="old", action="read", iostat=ios)
      if (ios /= 0) error stop "bench: reference file missing (make bench-lyapunov computes it)"
      k = 0
      do
         read (unit, '(a)', iostat=ios) line
         if (ios /= 0) exit
         if (line(1:1) == "#") cycle
         k = k + 1
         if (k > n_points) error stop "bench: reference file holds more points than the map"
         read (line, *) row
         reference(k, :) = row
         if (abs(row(1) - pendula(k)%alpha) > 1.0e-12_wp .or. abs(row(2) - pendula(k)%beta) > 1.0e-12_wp) &
            error stop "bench: reference file is for another grid (delete it to recompute)"
      end do
      close (unit)
      if (k /= n_points) error stop "bench: reference file is for another grid (delete it to recompute)"
      select case (periods)
      case (300); ref_col = 3
      case (1000); ref_col = 4
      case default; ref_col = 0
      end select

      open (newunit=unit, file=points_file, status="replace", action="write")
      do k = 1, n_points
         write (unit, '(2es26.17)') pendula(k)%alpha, pendula(k)%beta
      end do
      close (unit)
      write (command, '(a,1x,a,1x,i0,a,1x,a)') trim(gsl_program), points_file, periods, " 1e-10", gsl_file

      write (*, '(a,i0,a,i0,a,i0,a,i0,a)') "chaos map: ", n, " x ", n, " points of the physical domain, ", periods, &
         " radial periods from phi0 = 0.017, one thread, CPU time, ", rounds, " interleaved rounds (A, B, C, A, ...)"
      do r = 1, rounds
         ! A
         call cpu_time(t0)
         call chaos_indicators_batch(pendula, y0, periods, rtol, options, a)
         call cpu_time(t1)
         seconds(1, r) = t1 - t0
         ! B: a separate process; its own clock()
         call execute_command_line(trim(command), exitstat=ios)
         if (ios /= 0) error stop "bench: the C program failed"
         open (newunit=unit, file=gsl_file, status="old", action="read")
         read (unit, '(a)') line
         read (unit, '(a)') line
         read (line(15:), *) seconds(2, r)
         read (unit, '(a)') line
         do k = 1, n_points
            read (unit, *) row(1:7)
            lam(k, 2) = row(3)
            verdict(k, 2) = row(4)
            evaluations(k, 2) = row(5)
            energy(k, 2) = row(6)
            if (row(7) /= 0.0_wp) error stop "bench: GSL failed at a point"
         end do
         close (unit)
         ! C
         call cpu_time(t0)
         do k = 1, n_points
            call lyapunov_largest(pendula(k), y0(:, k), periods, rtol, today, error)
            if (allocated(error)) error stop "bench: lyapunov_largest failed"
            lam(k, 3) = today%exponent
            evaluations(k, 3) = real(today%stats%n_evaluations, wp)
            energy(k, 3) = today%energy_drift
         end do
         call cpu_time(t1)
         seconds(3, r) = t1 - t0
         ratio(:, r) = seconds(2:3, r)/seconds(1, r)
         write (*, '(a,i0,a,3f10.3,a,2f8.1)') "  round ", r, ": CPU s A B C", seconds(:, r), "   B/A, C/A", ratio(:, r)
      end do
      do k = 1, n_points
         if (allocated(a(k)%error)) error stop "bench: hillstab chaos failed at a point"
         lam(k, 1) = a(k)%lyapunov
         verdict(k, 1) = a(k)%chaotic
         evaluations(k, 1) = real(a(k)%stats%n_evaluations, wp)
         energy(k, 1) = a(k)%energy_error
         verdict(k, 3) = merge(1.0_wp, 0.0_wp, lam(k, 3) > lambda_chaotic)
      end do
      ! untimed: A without early stop, for λ at the reference's period count
      full%early_stop = .false.
      call chaos_indicators_batch(pendula, y0, periods, rtol, full, a_full)

      ! verdicts against the reference (its column 11: 1, 0, 0.5 not clear)
      regular = reference(:, 11) == 0.0_wp
      chaotic = reference(:, 11) == 1.0_wp
      n_clear = count(regular .or. chaotic)
      do c = 1, 3
         agree(c) = count((regular .or. chaotic) .and. verdict(:, c) == reference(:, 11))
         undecided(c) = count((regular .or. chaotic) .and. verdict(:, c) == 0.5_wp)
         wrong(c) = n_clear - agree(c) - undecided(c)
      end do

      write (*, '(/,a,i0,a,i0,a)') "verdicts against the 3000-period reference on its ", n_clear, " clear points (", &
         n_points - n_clear, " not clear left out)"
      write (*, '(a)') "| contender | CPU s per map (min ... max) | ms per point | points/s per core | "// &
         "evaluations per point | agree | undecided | wrong |"
      write (*, '(a)') "|---|---|---|---|---|---|---|---|"
      do c = 1, 3
         write (*, '(a,a,a,f8.3,a,f8.3,a,f8.3,a,f9.0,a,f10.0,a,f6.2,a,i0,a,i0,a)') "| ", trim(names(c)), " | ", &
            minval(seconds(c, :)), " ... ", maxval(seconds(c, :)), " | ", 1.0e3_wp*median(seconds(c, :))/n_points, &
            " | ", n_points/median(seconds(c, :)), " | ", sum(evaluations(:, c))/n_points, " | ", &
            100.0_wp*agree(c)/max(1, n_clear), " % | ", undecided(c), " | ", wrong(c), " |"
      end do
      write (*, '(a,f6.1,a,f6.1,a,f6.1,a)') "A is ", median(ratio(1, :rounds)), " x as fast as B (per round: ", &
         minval(ratio(1, :rounds)), " ... ", maxval(ratio(1, :rounds)), ")"
      write (*, '(a,f6.1,a,f6.1,a,f6.1,a)') "A is ", median(ratio(2, :rounds)), " x as fast as C (per round: ", &
         minval(ratio(2, :rounds)), " ... ", maxval(ratio(2, :rounds)), ")"
      write (*, '(a)') "A's verdict rule: "//chaos_verdict_rule(options)
      write (*, '(a,f4.2,a)') "B's and C's verdict rule: chaotic when lambda > ", lambda_chaotic, " per radial period"

      write (*, '(/,a)') "A in detail:"
      write (*, '(a,i0,a,i0,a,i0,a,f7.1)') "  symplectic points ", count(a%integrator == chaos_symplectic), &
         ", DOP853 points ", count(a%integrator == chaos_dop853), ", refined after an energy error ", &
         count(a%attempts > 1), "; mean periods integrated ", sum(real(a%periods, wp))/n_points
      write (*, '(a,f7.1,a,f10.0,a,f10.0)') "  mean steps per radial period (symplectic) ", &
         sum(real(a%steps_per_period, wp), a%integrator == chaos_symplectic)/max(1, count(a%integrator == &
         chaos_symplectic)), "; evaluations per point: symplectic ", sum(evaluations(:, 1), a%integrator == &
         chaos_symplectic)/max(1, count(a%integrator == chaos_symplectic)), ", DOP853 ", &
         sum(evaluations(:, 1), a%integrator == chaos_dop853)/max(1, count(a%integrator == chaos_dop853))
      write (*, '(/,a)') "energy error along the orbits, |dE| over the sum of the energy terms' magnitudes "// &
         "(median, max over the points):"
      write (*, '(a,2es10.2)') "  A, symplectic points, at every step:       ", &
         median(pack(energy(:, 1), a%integrator == chaos_symplectic)), &
         maxval(energy(:, 1), a%integrator == chaos_symplectic)
      write (*, '(a,2es10.2)') "  B, at the period ends:                     ", median(energy(:, 2)), maxval(energy(:, 2))
      write (*, '(a,2es10.2)') "  C, at the end:                             ", median(energy(:, 3)), maxval(energy(:, 3))

      if (ref_col > 0) then
         lam(:, 1) = a_full%lyapunov
         write (*, '(/,a,i0,a)') "lambda against the reference's lambda after ", periods, " periods (A without early "// &
            "stop; median and max |difference|):"
         write (*, '(a,i0,a)') "  regular set (", count(regular), " points):"
         do c = 1, 3
            write (*, '(4x,a34,2es10.2)') names(c), median(pack(abs(lam(:, c) - reference(:, ref_col)), regular)), &
               maxval(abs(lam(:, c) - reference(:, ref_col)), regular)
         end do
         write (*, '(a,i0,a,f6.3,a)') "  chaotic set (", count(chaotic), " points, median reference lambda ", &
            median(pack(reference(:, ref_col), chaotic)), "; relative differences: on a chaotic orbit a finite-time "// &
            "exponent depends on the path the rounding takes):"
         do c = 1, 3
            write (*, '(4x,a34,2f8.3)') names(c), median(pack(abs(lam(:, c)/reference(:, ref_col) - 1.0_wp), chaotic)), &
               maxval(abs(lam(:, c)/reference(:, ref_col) - 1.0_wp), chaotic)
         end do
      end if

      call variants(pendula, y0, periods, reference, ref_col)

      open (newunit=unit, file="out/bench_lyapunov.dat", status="replace", action="write")
      write (unit, '(a,i0,a,i0,a,i0,a)') "# hillstab_bench_lyapunov map: ", n, " x ", n, " points, ", periods, &
         " radial periods, phi0 = 0.017; A hillstab chaos (auto), B plain C GSL rk8pd, C hillstab lyapunov_largest"
      write (unit, '(a)') "# columns: alpha beta reference_verdict reference_lambda_end chaotic_A megno_A lambda_A "// &
         "periods_A integrator_A(1 symplectic, 2 dop853) steps_A evaluations_A lambda_B chaotic_B evaluations_B "// &
         "lambda_C evaluations_C energy_error_A"
      k = 0
      do i = 1, n
         if (i > 1) write (unit, '(a)') ""
         do j = 1, n
            k = k + 1
            ref_lambda = reference(k, 5)
            write (unit, '(2f10.5,f5.1,es12.4,f5.1,es12.4,es12.4,i6,i3,i6,es12.4,es12.4,f5.1,es12.4,es12.4,es12.4,'// &
               'es10.2)') pendula(k)%alpha, pendula(k)%beta, reference(k, 11), ref_lambda, a(k)%chaotic, a(k)%megno, &
               a(k)%lyapunov, a(k)%periods, a(k)%integrator, a(k)%steps_per_period, evaluations(k, 1), lam(k, 2), &
               verdict(k, 2), evaluations(k, 2), lam(k, 3), evaluations(k, 3), energy(k, 1)
         end do
      end do
      close (unit)
      write (*, '(/,a)') "wrote out/bench_lyapunov.dat"
   end subroutine run_map

   !> A's options varied one at a time, each timed once after the interleaved rounds (so
   !> not interleaved: read them against each other, not against B): the number of lanes,
   !> the scheme, the step rule's base, early stopping. Per variant: CPU time, agreement
   !> with the clear reference verdicts, the regular set's λ error (without early stop
   !> only, at the reference's period count) and the energy error on the symplectic points.
   subroutine variants(pendula, y0, periods, reference, ref_col)
      type(pendulum_t), intent(in) :: pendula(:)
      real(wp), intent(in) :: y0(:, :), reference(:, :)
      integer, intent(in) :: periods, ref_col
      type(chaos_options_t) :: options(9)
      type(chaos_t) :: results(size(pendula))
      character(len=48) :: labels(9)
      logical :: clear(size(pendula)), regular(size(pendula)), symplectic(size(pendula))
      real(wp) :: t0, t1, lambda_error
      integer :: v
      labels = [character(len=48) :: "defaults (blanes_moan6, base 8, 16 lanes)", "1 lane (one orbit at a time)", &
         "4 lanes", "blanes_moan4 (order 4)", "mclachlan8 (order 8)", "yoshida6 (order 6)", "base_steps 12", &
         "base_steps 16", "no early stop"]
      options(2)%lanes = 1
      options(3)%lanes = 4
      options(4)%scheme = symplectic_blanes_moan4
      options(5)%scheme = symplectic_mclachlan8
      options(6)%scheme = symplectic_yoshida6
      options(7)%base_steps = 12.0_wp
      options(8)%base_steps = 16.0_wp
      options(9)%early_stop = .false.
      clear = reference(:, 11) /= 0.5_wp
      regular = reference(:, 11) == 0.0_wp
      write (*, '(/,a)') "A's options one at a time (each timed once, after the rounds):"
      write (*, '(a)') "| variant | CPU s | agree | DOP853 points | refined | regular-set max abs(d lambda) | "// &
         "energy error, median / max |"
      write (*, '(a)') "|---|---|---|---|---|---|---|"
      do v = 1, size(options)
         call cpu_time(t0)
         call chaos_indicators_batch(pendula, y0, periods, rtol, options(v), results)
         call cpu_time(t1)
         symplectic = results%integrator == chaos_symplectic
         lambda_error = -1.0_wp
         if (ref_col > 0 .and. .not. options(v)%early_stop) &
            lambda_error = maxval(abs(results%lyapunov - reference(:, ref_col)), regular)
         write (*, '(a,a,a,f7.3,a,f6.2,a,i0,a,i0,a,es9.2,a,es9.2,a,es9.2,a)') "| ", trim(labels(v)), " | ", t1 - t0, &
            " | ", 100.0_wp*count(clear .and. results%chaotic == reference(:, 11))/max(1, count(clear)), " % | ", &
            count(results%integrator == chaos_dop853), " | ", count(results%attempts > 1), " | ", lambda_error, " | ", &
            median(pack(results%energy_error, symplectic)), " / ", maxval(results%energy_error, symplectic), " |"
      end do
      write (*, '(a)') "(regular-set lambda error -1: not measured with early stop, where chaotic and regular "// &
         "orbits end at different periods)"
   end subroutine variants

   subroutine run_estimate()
      integer :: n, periods, stride, n_sample, first, last, unit, u, k
      integer, parameter :: unit_size = 64
      integer, allocatable :: sample(:)
      type(pendulum_t), allocatable :: pendula(:), chosen(:)
      real(wp), allocatable :: y0(:, :), starts(:, :)
      type(chaos_t), allocatable :: results(:)
      type(chaos_options_t) :: options
      integer(int64) :: clock_0, clock_1, rate
      real(wp) :: cpu_0, cpu_1, wall, cpu
      n = int_argument(2)
      periods = int_argument(3)
      stride = max(1, int_argument(4))
      call grid(n, pendula, y0)
      sample = [(k, k=1, n*n, stride)]
      n_sample = size(sample)
      chosen = pendula(sample)
      starts = y0(:, sample)
      allocate (results(n_sample))
      call system_clock(clock_0, rate)
      call cpu_time(cpu_0)
      !$omp parallel do schedule(dynamic) default(shared) private(u, first, last)
      do u = 1, (n_sample + unit_size - 1)/unit_size
         first = (u - 1)*unit_size + 1
         last = min(n_sample, u*unit_size)
         call chaos_indicators_batch(chosen(first:last), starts(:, first:last), periods, rtol, options, results(first:last))
      end do
      !$omp end parallel do
      call cpu_time(cpu_1)
      call system_clock(clock_1)
      wall = real(clock_1 - clock_0, wp)/rate
      cpu = cpu_1 - cpu_0
      write (*, '(/,a,i0,a,i0,a,i0,a,i0,a,i0,a,i0,a)') "estimate: ", n_sample, " of the ", n, " x ", n, " points (every ", &
         stride, "th), ", periods, " radial periods, defaults (auto, lanes, early stop), units of ", unit_size, &
         " points over the OpenMP threads"
      write (*, '(a,f9.2,a,f9.2,a,f8.4,a)') "  wall ", wall, " s, CPU (all threads) ", cpu, " s, ", 1.0e3_wp*cpu/n_sample, &
         " ms CPU per point"
      write (*, '(a,i0,a,f9.1,a,f7.2,a,f9.1,a)') "  the whole map (", n*n, " points): wall ", wall*n*n/n_sample, " s = ", &
         wall*n*n/n_sample/60.0_wp, " min, CPU ", cpu*n*n/n_sample, " s"
      write (*, '(a,i0,a,i0,a,i0,a,f7.1)') "  symplectic points ", count(results%integrator == chaos_symplectic), &
         ", DOP853 points ", count(results%integrator == chaos_dop853), ", refined ", count(results%attempts > 1), &
         ", mean periods ", sum(real(results%periods, wp))/n_sample
      write (*, '(a,i0,a,i0,a,i0,a)') "  chaotic ", count(results%chaotic == 1.0_wp), ", regular ", &
         count(results%chaotic == 0.0_wp), ", undecided ", count(results%chaotic == 0.5_wp), " points"
      if (any([(allocated(results(k)%error), k=1, n_sample)])) write (*, '(a)') "  (some points failed)"
      open (newunit=unit, file="out/bench_lyapunov_map.dat", status="replace", action="write")
      write (unit, '(a,i0,a,i0,a,i0,a,i0,a)') "# hillstab_bench_lyapunov estimate: every ", stride, "th point of the ", n, &
         " x ", n, " map, ", periods, " radial periods, phi0 = 0.017, defaults"
      write (unit, '(a)') "# columns: alpha beta chaotic megno lyapunov periods integrator(1 symplectic, 2 dop853)"
      do k = 1, n_sample
         if (stride == 1 .and. k > 1 .and. mod(k - 1, n) == 0) write (unit, '(a)') ""
         write (unit, '(2f10.5,f5.1,es12.4,es12.4,i6,i3)') chosen(k)%alpha, chosen(k)%beta, results(k)%chaotic, &
            results(k)%megno, results(k)%lyapunov, results(k)%periods, results(k)%integrator
      end do
      close (unit)
      write (*, '(a)') "wrote out/bench_lyapunov_map.dat"
   end subroutine run_estimate
end program hillstab_bench_lyapunov

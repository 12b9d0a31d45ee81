!> Benchmark of the systems of Hill equations (`make bench-system`):
!>
!> `hillstab_bench_system [--n N] [--alpha-n N] [--beta-n N] [--cost-n N] [--rounds R] [--no-gsl] [--no-cost]`
!>
!> Every timed contender runs R times (default 3), the rounds interleaved (each contender once
!> per round), and its fastest time is kept; the 2-core machine is shared with other work.
!>
!> 1. Speed at equal accuracy. The N_ALPHA × N_BETA chart (default 300 × 300) of the pendula
!>    pair of data/scenes/system_pendula.nml (M = diag(1, 0.64), B = diag(1, 0.8) + 0.1
!>    [[1, −1], [−1, 1]], K = β B − α cos πτ diag(1, 0.8)) over α in [0, 2], β in [0, 12],
!>    the grid of bench/chart_gsl_system.c:
!>    - hillstab: `system_monodromy` (method auto, one `system_nodes_t` per row of fixed α)
!>      and `system_floquet` at every point, timed with system_clock, one thread, at the
!>      tolerances 1e-10 (the benchmark's), 1e-9 and 1e-8; then at 1e-10 with the rows
!>      shared among OMP_NUM_THREADS OpenMP threads when that is more than one;
!>    - the plain C GSL program (bench/chart_gsl_system.c, rk8pd on the 4 × 4 fundamental
!>      matrix over the period, compiled into build/chart_gsl_system when missing) at
!>      eps = 1e-10, 1e-11, 1e-12, 1e-13, in the same run, its own wall time of the loop
!>      (which leaves out its verdicts; hillstab's time includes them);
!>    - the reference: the same GSL program at eps = 1e-14, itself checked on every 37th
!>      point against hillstab's magnus6 at tolerance 1e-13 (an independent method); every
!>      contender's max error against that check is printed as well.
!>    The error of a point is max|Φ − Φ_ref| / max(1, max|Φ_ref|) (Φ = e^s Φ̃); the table gives
!>    the max and median over the grid. "Equal accuracy": for each hillstab run the fastest
!>    GSL run whose max error is not larger than hillstab's, the speed ratio its time over
!>    hillstab's (when no GSL run is that accurate, the most accurate one and "> ": a lower
!>    bound); and the other way round, for each GSL run the fastest hillstab run at least as
!>    accurate.
!> 2. Cost against n: chains of n = 1, 2, 4, 10, 20 driven oscillators (M = I, K0 the
!>    tridiagonal spring chain 2, −1 with fixed ends, B = I, the drive −(0.6 + 0.4 (i−1)/(n−1))
!>    on the diagonal and 0.15 between neighbours, so that the modes couple) over a
!>    COST_N × COST_N grid (default 12) of α in [0, 1], β in [0.5, 6] at 1e-10: microseconds
!>    and Magnus steps per point.
!>
!> Writes build/bench/system_speed.dat and build/bench/system_cost.dat (plots/bench_system.gp).
program hillstab_bench_system
   use hillstab_core_kinds, only: wp, int64
   use hillstab_core_error, only: error_t
   use hillstab_core_status, only: status_ok
   use hillstab_hill_system, only: system_form_t, prepare_system
   use hillstab_hill_system_matrix, only: matrix_system_t
   use hillstab_hill_system_floquet, only: floquet_t, system_floquet, verdict_unstable
   use hillstab_integrate_system, only: system_method_t, system_monodromy_t, system_nodes_t, system_monodromy, &
      system_auto, system_magnus6
   !$ use omp_lib, only: omp_get_max_threads
   implicit none
   integer, parameter :: n_h = 3, n_gsl = 4, n_c = n_h + n_gsl, stride = 37
   !> hillstab's tolerances (the first the benchmark's) and GSL's eps
   real(wp), parameter :: tolerances(n_h) = [1.0e-10_wp, 1.0e-9_wp, 1.0e-8_wp]
   real(wp), parameter :: gsl_eps(n_gsl) = [1.0e-10_wp, 1.0e-11_wp, 1.0e-12_wp, 1.0e-13_wp]
   real(wp), parameter :: reference_eps = 1.0e-14_wp, tolerance = tolerances(1)
   character(len=*), parameter :: gsl_program = "build/chart_gsl_system", out_dir = "build/bench"
   integer :: n_alpha = 300, n_beta = 300, cost_n = 12, n_points
   logical :: run_gsl = .true., run_cost = .true.
   !> per contender (hillstab's tolerances, then GSL's eps): Φ row-major per point, seconds,
   !> steps or evaluations per point, errors against the reference
   real(wp), allocatable :: phi(:, :, :), phi_ref(:, :), phi_sub(:, :), err(:, :)
   real(wp) :: seconds(n_c), work(n_c), sub_max(n_c), time_ref, ref_check, seconds_threads = 0.0_wp, steps_threads
   real(wp), allocatable :: phi_threads(:, :)
   real(wp) :: time_round
   integer :: failures, unstable, k, threads, round, rounds = 3

   call read_arguments()
   n_points = n_alpha*n_beta
   call execute_command_line("mkdir -p "//out_dir)
   write (*, '(a, i0, a, i0, a)') "pendula pair, ", n_alpha, " x ", n_beta, &
      " grid, alpha in [0, 2], beta in [0, 12], one thread"
   allocate (phi(16, n_points, n_c))
   ! rounds: every contender once per round, interleaved, the fastest time of each kept
   seconds = huge(1.0_wp)
   do round = 1, rounds
      do k = 1, n_h
         call hillstab_chart(system_method_t(system_auto, tolerances(k)), phi(:, :, k), time_round, work(k), &
                             failures, unstable)
         seconds(k) = min(seconds(k), time_round)
         if (round == rounds) write (*, '(a, es8.1, a, f9.2, a, f8.2, a, i0, a, i0)') "hillstab auto tolerance", &
            tolerances(k), ":", 1.0e6_wp*seconds(k)/n_points, " us/point, ", work(k), " steps/point, failures ", &
            failures, ", unstable points ", unstable
      end do
      if (.not. run_gsl) cycle
      do k = 1, n_gsl
         call gsl_chart(gsl_eps(k), phi(:, :, n_h + k), time_round, work(n_h + k), read_data=round == rounds)
         seconds(n_h + k) = min(seconds(n_h + k), time_round)
         if (round == rounds) write (*, '(a, es8.1, a, f9.2, a, f9.1, a)') "GSL rk8pd eps", gsl_eps(k), ":", &
            1.0e6_wp*seconds(n_h + k)/n_points, " us/point, ", work(n_h + k), " evaluations/point"
      end do
   end do
   ! the same chart with the rows shared among OpenMP threads (OMP_NUM_THREADS)
   threads = 1
   !$ threads = omp_get_max_threads()
   if (threads > 1) then
      allocate (phi_threads(16, n_points))
      seconds_threads = huge(1.0_wp)
      do round = 1, rounds
         call hillstab_chart(system_method_t(system_auto, tolerance), phi_threads, time_round, steps_threads, &
                             failures, unstable, threads=.true.)
         seconds_threads = min(seconds_threads, time_round)
      end do
      write (*, '(a, es8.1, a, i0, a, f9.2, a, l1)') "hillstab auto tolerance", tolerance, ", ", threads, &
         " threads:", 1.0e6_wp*seconds_threads/n_points, " us/point (wall), the same Phi: ", &
         all(phi_threads == phi(:, :, 1))
   end if
   if (run_gsl) then
      allocate (phi_ref(16, n_points), err(n_points, n_c))
      call gsl_chart(reference_eps, phi_ref, time_ref, ref_check, read_data=.true.)
      write (*, '(a, es8.1, a, f9.2, a)') "GSL rk8pd eps", reference_eps, ":", 1.0e6_wp*time_ref/n_points, &
         " us/point (the reference, one run)"
      do k = 1, n_c
         err(:, k) = point_errors(phi(:, :, k), phi_ref)
      end do
      ! an independent check on every stride-th point: magnus6 at 1e-13
      allocate (phi_sub(16, n_points))
      call hillstab_chart(system_method_t(system_magnus6, 1.0e-13_wp), phi_sub, time_ref, ref_check, failures, &
                          unstable, stride)
      ref_check = subsample_max(point_errors(phi_ref, phi_sub))
      do k = 1, n_c
         sub_max(k) = subsample_max(point_errors(phi(:, :, k), phi_sub))
      end do
      call speed_table()
   end if
   if (run_cost) call cost_table()

contains

   !> The command-line options (see the program's text).
   subroutine read_arguments()
      character(len=64) :: arg, value
      integer :: i
      i = 1
      do while (i <= command_argument_count())
         call get_command_argument(i, arg)
         select case (arg)
         case ("--n", "--alpha-n", "--beta-n", "--cost-n", "--rounds")
            call get_command_argument(i + 1, value)
            i = i + 1
            select case (arg)
            case ("--n"); read (value, *) n_alpha; n_beta = n_alpha
            case ("--alpha-n"); read (value, *) n_alpha
            case ("--beta-n"); read (value, *) n_beta
            case ("--cost-n"); read (value, *) cost_n
            case ("--rounds"); read (value, *) rounds
            end select
         case ("--no-gsl"); run_gsl = .false.
         case ("--no-cost"); run_cost = .false.
         case default
            write (*, '(a)') "usage: hillstab_bench_system [--n N] [--alpha-n N] [--beta-n N] [--cost-n N] "// &
               "[--rounds R] [--no-gsl] [--no-cost]"
            error stop 2
         end select
         i = i + 1
      end do
      if (n_alpha < 2 .or. n_beta < 2 .or. cost_n < 2) error stop "bench: grids need at least 2 x 2 points"
      if (rounds < 1) error stop "bench: rounds must be >= 1"
   end subroutine read_arguments

   !> The grid value i of n over [lo, hi] as bench/chart_gsl_system.c computes it.
   pure real(wp) function grid_value(lo, hi, n, i)
      real(wp), intent(in) :: lo, hi
      integer, intent(in) :: n, i
      if (i == n) then
         grid_value = hi
      else
         grid_value = lo + (hi - lo)*real(i - 1, wp)/real(n - 1, wp)
      end if
   end function grid_value

   !> The pendula pair of the benchmark (l2 = 0.8, c = 0.1).
   function pendula_pair() result(pair)
      type(matrix_system_t) :: pair
      type(error_t), allocatable :: error
      real(wp), parameter :: l2 = 0.8_wp, c = 0.1_wp
      call pair%set_values("n", [2.0_wp], error)
      call pair%set_values("mass", [1.0_wp, 0.0_wp, 0.0_wp, l2*l2], error)
      call pair%set_values("b", [1.0_wp + c, -c, -c, l2 + c], error)
      call pair%set_values("cos", [-1.0_wp, 0.0_wp, 0.0_wp, -l2], error)
      call pair%check_values(error)
      if (allocated(error)) error stop "bench: pendula pair refused"
   end function pendula_pair

   !> A chain of n driven oscillators (see the program's text).
   function oscillator_chain(n) result(chain)
      integer, intent(in) :: n
      type(matrix_system_t) :: chain
      type(error_t), allocatable :: error
      real(wp) :: k0(n, n), drive(n, n), b(n, n)
      integer :: i
      k0 = 0.0_wp
      drive = 0.0_wp
      b = 0.0_wp
      do i = 1, n
         k0(i, i) = 2.0_wp
         b(i, i) = 1.0_wp
         drive(i, i) = -(0.6_wp + 0.4_wp*real(i - 1, wp)/real(max(1, n - 1), wp))
         if (i < n) then
            k0(i, i + 1) = -1.0_wp
            k0(i + 1, i) = -1.0_wp
            drive(i, i + 1) = 0.15_wp
            drive(i + 1, i) = 0.15_wp
         end if
      end do
      call chain%set_values("n", [real(n, wp)], error)
      call chain%set_values("k0", reshape(transpose(k0), [n*n]), error)
      call chain%set_values("b", reshape(transpose(b), [n*n]), error)
      call chain%set_values("cos", reshape(transpose(drive), [n*n]), error)
      call chain%check_values(error)
      if (allocated(error)) error stop "bench: oscillator chain refused"
   end function oscillator_chain

   !> Seconds of the wall clock.
   real(wp) function wall_seconds()
      integer(int64) :: count, rate
      call system_clock(count, rate)
      wall_seconds = real(count, wp)/real(rate, wp)
   end function wall_seconds

   !> hillstab's chart of the pendula pair: Φ = e^s Φ̃ row-major per point, the time of the
   !> loop (monodromy and Floquet verdict), steps per point, failures and unstable points.
   subroutine hillstab_chart(method, phi, seconds, steps, failures, unstable, stride, threads)
      type(system_method_t), intent(in) :: method
      real(wp), intent(out) :: phi(:, :)
      real(wp), intent(out) :: seconds, steps
      integer, intent(out) :: failures, unstable
      integer, intent(in), optional :: stride  !! only every stride-th point (the others zero)
      logical, intent(in), optional :: threads  !! rows in parallel (OpenMP), else one thread
      type(matrix_system_t) :: pair
      type(system_form_t) :: form
      type(system_nodes_t) :: nodes
      type(system_monodromy_t) :: r
      type(floquet_t) :: f
      type(error_t), allocatable :: error
      integer :: i, j, p, every
      integer(int64) :: total_steps
      real(wp) :: alpha, beta, t0
      logical :: parallel
      every = 1
      if (present(stride)) every = stride
      parallel = .false.
      if (present(threads)) parallel = threads
      pair = pendula_pair()
      call prepare_system(pair, 0.0_wp, form, error)
      if (allocated(error)) error stop "bench: prepare_system"
      phi = 0.0_wp
      failures = 0
      unstable = 0
      total_steps = 0
      t0 = wall_seconds()
      !$omp parallel do schedule(dynamic) if(parallel) default(shared) &
      !$omp private(i, j, p, alpha, beta, nodes, r, f, error) reduction(+:failures, unstable, total_steps)
      do i = 1, n_alpha
         alpha = grid_value(0.0_wp, 2.0_wp, n_alpha, i)
         nodes = system_nodes_t()
         do j = 1, n_beta
            p = (i - 1)*n_beta + j
            if (mod(p - 1, every) /= 0) cycle
            beta = grid_value(0.0_wp, 12.0_wp, n_beta, j)
            call system_monodromy(pair, form, alpha, beta, method, nodes, r, error)
            call system_floquet(r%phi, form, r%error_estimate*max(1.0_wp, maxval(abs(r%phi))), f, r%log_scale)
            if (r%status /= status_ok) failures = failures + 1
            if (f%verdict == verdict_unstable) unstable = unstable + 1
            total_steps = total_steps + r%steps
            phi(:, p) = reshape(transpose(r%phi*exp(r%log_scale)), [16])
         end do
      end do
      !$omp end parallel do
      seconds = wall_seconds() - t0
      steps = real(total_steps, wp)/real((n_points + every - 1)/every, wp)
   end subroutine hillstab_chart

   !> The GSL program at eps: Φ row-major per point and the time of its loop.
   subroutine gsl_chart(eps, phi, seconds, per_point, read_data)
      real(wp), intent(in) :: eps
      real(wp), intent(inout) :: phi(:, :)          !! Φ when read_data (else untouched)
      real(wp), intent(out) :: seconds, per_point  !! the loop's time, evaluations per point
      logical, intent(in) :: read_data             !! have the program write Φ and read it
      character(len=256) :: data_file, time_file, command
      character(len=16) :: eps_text
      logical :: exists
      integer :: unit, ios, p, stable, failures
      integer(int64) :: evaluations
      real(wp) :: row(21)
      inquire (file=gsl_program, exist=exists)
      if (.not. exists) then
         call execute_command_line("cc -O2 bench/chart_gsl_system.c -o "//gsl_program//" -lgsl -lgslcblas -lm", &
                                   exitstat=ios)
         if (ios /= 0) error stop "bench: cannot compile bench/chart_gsl_system.c"
      end if
      write (eps_text, '(es8.1)') eps
      eps_text = adjustl(eps_text)
      data_file = out_dir//"/system_gsl_"//trim(eps_text)//".dat"
      time_file = out_dir//"/system_gsl_"//trim(eps_text)//".time"
      if (read_data) then
         write (command, '(a, 1x, i0, 1x, i0, 1x, a, 1x, a, a, a)') gsl_program, n_alpha, n_beta, trim(eps_text), &
            trim(data_file), " > ", trim(time_file)
      else
         write (command, '(a, 1x, i0, 1x, i0, 1x, a, a, a)') gsl_program, n_alpha, n_beta, trim(eps_text), &
            " > ", trim(time_file)
      end if
      call execute_command_line(trim(command), exitstat=ios)
      if (ios /= 0) error stop "bench: the GSL program failed"
      open (newunit=unit, file=time_file, status="old", action="read")
      read (unit, *) seconds, evaluations, failures
      close (unit, status="delete")
      per_point = real(evaluations, wp)/n_points
      if (failures /= 0) write (*, '(a, es8.1, a, i0, a)') "GSL at eps", eps, ": ", failures, " failures"
      if (.not. read_data) return
      open (newunit=unit, file=data_file, status="old", action="read")
      do p = 1, n_points
         read (unit, *) row(1:4), stable, row(6:21)
         phi(:, p) = row(6:21)
      end do
      close (unit, status="delete")
   end subroutine gsl_chart

   !> max|Φ − Φ_ref| / max(1, max|Φ_ref|) per point.
   pure function point_errors(phi, ref) result(err)
      real(wp), intent(in) :: phi(:, :), ref(:, :)
      real(wp) :: err(size(phi, 2))
      integer :: p
      do p = 1, size(phi, 2)
         err(p) = maxval(abs(phi(:, p) - ref(:, p)))/max(1.0_wp, maxval(abs(ref(:, p))))
      end do
   end function point_errors

   !> The median of x (x is sorted in a copy).
   real(wp) function median(x)
      real(wp), intent(in) :: x(:)
      real(wp) :: y(size(x))
      y = x
      call heap_sort(y)
      if (mod(size(y), 2) == 1) then
         median = y(size(y)/2 + 1)
      else
         median = 0.5_wp*(y(size(y)/2) + y(size(y)/2 + 1))
      end if
   end function median

   !> Ascending heap sort in place.
   subroutine heap_sort(a)
      real(wp), intent(inout) :: a(:)
      integer :: n, i
      real(wp) :: t
      n = size(a)
      do i = n/2, 1, -1
         call sift(a, i, n)
      end do
      do i = n, 2, -1
         t = a(1); a(1) = a(i); a(i) = t
         call sift(a, 1, i - 1)
      end do
   end subroutine heap_sort

   !> Sift a(start) down the heap a(1:last).
   subroutine sift(a, start, last)
      real(wp), intent(inout) :: a(:)
      integer, intent(in) :: start, last
      integer :: root, child
      real(wp) :: v
      root = start
      v = a(root)
      do
         child = 2*root
         if (child > last) exit
         if (child < last) then
            if (a(child + 1) > a(child)) child = child + 1
         end if
         if (a(child) <= v) exit
         a(root) = a(child)
         root = child
      end do
      a(root) = v
   end subroutine sift

   !> The largest of x over every stride-th point.
   pure real(wp) function subsample_max(x)
      real(wp), intent(in) :: x(:)
      subsample_max = maxval(x(1:size(x):stride))
   end function subsample_max

   !> The speed table at equal accuracy (screen and build/bench/system_speed.dat).
   subroutine speed_table()
      integer :: unit, k, g, h
      character(len=16) :: names(n_c)
      real(wp) :: values(n_c)
      do k = 1, n_c
         if (k <= n_h) then
            names(k) = "hillstab auto"
            values(k) = tolerances(k)
         else
            names(k) = "GSL rk8pd"
            values(k) = gsl_eps(k - n_h)
         end if
      end do
      open (newunit=unit, file=out_dir//"/system_speed.dat", status="replace", action="write")
      write (unit, '(a, i0, a, i0, a)') "# system benchmark: pendula pair, ", n_alpha, " x ", n_beta, &
         " grid of alpha in [0, 2], beta in [0, 12], one thread"
      write (unit, '(a, es8.1, a, i0, a, es9.2)') "# reference: GSL rk8pd at eps ", reference_eps, &
         "; check: magnus6 at 1e-13 on every ", stride, "th point, the reference's max error against it ", ref_check
      write (unit, '(a)') "# columns: contender(0 hillstab auto, 1 GSL rk8pd) tolerance_or_eps us_per_point "// &
         "steps_or_evaluations_per_point max_error median_error max_error_subsample"
      write (*, '(/, a, es8.1, a, i0, a, es9.2, a)') "errors of Phi against GSL at eps ", reference_eps, &
         " (its own max error against magnus6 at 1e-13 on every ", stride, "th point: ", ref_check, ")"
      write (*, '(a)') "contender      tol/eps    us/point  steps|evals    max error  median error  "// &
         "max (subsample vs magnus6)"
      do k = 1, n_c
         write (*, '(a14, es8.1, f12.2, f13.1, 2es13.3, es14.3)') names(k), values(k), 1.0e6_wp*seconds(k)/n_points, &
            work(k), maxval(err(:, k)), median(err(:, k)), sub_max(k)
         write (unit, '(i2, es10.2, f12.3, f12.2, 3es12.3)') merge(0, 1, k <= n_h), values(k), &
            1.0e6_wp*seconds(k)/n_points, work(k), maxval(err(:, k)), median(err(:, k)), sub_max(k)
      end do
      ! equal accuracy: for each hillstab run the cheapest GSL run at least as accurate (the
      ! largest eps whose max error is not larger), and for each GSL run the cheapest such hillstab run
      write (*, '(/, a)') "equal accuracy (max error over the grid not larger), speed ratio = GSL time / hillstab time:"
      do h = 1, n_h
         g = cheapest(n_h + 1, n_c, maxval(err(:, h)))
         if (g > 0) then
            write (*, '(a, es8.1, a, es8.1, a, f7.2)') "  hillstab tolerance ", tolerances(h), " vs GSL eps ", &
               gsl_eps(g - n_h), ": ", seconds(g)/seconds(h)
            write (unit, '(a, es8.1, a, es8.1, a, f8.3)') "# equal accuracy: hillstab tolerance ", tolerances(h), &
               " vs GSL eps ", gsl_eps(g - n_h), " speed ratio ", seconds(g)/seconds(h)
         else
            g = n_h + minloc([(maxval(err(:, k)), k=n_h + 1, n_c)], dim=1)
            write (*, '(a, es8.1, a, es8.1, a, f7.2)') "  hillstab tolerance ", tolerances(h), &
               ": no GSL run as accurate; against the most accurate, eps ", gsl_eps(g - n_h), ": > ", &
               seconds(g)/seconds(h)
            write (unit, '(a, es8.1, a, es8.1, a, f8.3)') "# equal accuracy: hillstab tolerance ", tolerances(h), &
               " vs GSL eps ", gsl_eps(g - n_h), " (not as accurate) speed ratio > ", seconds(g)/seconds(h)
         end if
      end do
      if (seconds_threads > 0.0_wp) then
         g = cheapest(n_h + 1, n_c, maxval(err(:, 1)))
         if (g == 0) g = n_h + minloc([(maxval(err(:, k)), k=n_h + 1, n_c)], dim=1)
         write (*, '(a, es8.1, a, i0, a, f9.2, a, es8.1, a, f7.2)') "  hillstab tolerance ", tolerance, " on ", &
            threads, " threads (", 1.0e6_wp*seconds_threads/n_points, " us/point) vs GSL eps ", gsl_eps(g - n_h), &
            " on one: ", seconds(g)/seconds_threads
         write (unit, '(a, i0, a, f10.3, a, es8.1, a, f8.3)') "# hillstab tolerance 1e-10 on ", threads, &
            " threads: us_per_point ", 1.0e6_wp*seconds_threads/n_points, ", against GSL eps ", gsl_eps(g - n_h), &
            " on one thread: speed ratio ", seconds(g)/seconds_threads
      end if
      do g = n_h + 1, n_c
         h = cheapest(1, n_h, maxval(err(:, g)))
         if (h > 0) then
            write (*, '(a, es8.1, a, es8.1, a, f7.2)') "  GSL eps ", gsl_eps(g - n_h), " vs hillstab tolerance ", &
               tolerances(h), ": ", seconds(g)/seconds(h)
            write (unit, '(a, es8.1, a, es8.1, a, f8.3)') "# equal accuracy: GSL eps ", gsl_eps(g - n_h), &
               " vs hillstab tolerance ", tolerances(h), " speed ratio ", seconds(g)/seconds(h)
         else
            write (*, '(a, es8.1, a)') "  GSL eps ", gsl_eps(g - n_h), ": no hillstab run as accurate"
         end if
      end do
      close (unit)
   end subroutine speed_table

   !> Of contenders first … last, the fastest whose max error is at most bound (0: none).
   integer function cheapest(first, last, bound) result(best)
      integer, intent(in) :: first, last
      real(wp), intent(in) :: bound
      integer :: k
      best = 0
      do k = first, last
         if (maxval(err(:, k)) > bound) cycle
         if (best == 0) then
            best = k
         else if (seconds(k) < seconds(best)) then
            best = k
         end if
      end do
   end function cheapest

   !> Cost against n (screen and build/bench/system_cost.dat): the fastest of `rounds` runs of
   !> the grid at 1e-10, and the max error of Φ there against magnus6 at 1e-13.
   subroutine cost_table()
      integer, parameter :: sizes(5) = [1, 2, 4, 10, 20]
      type(matrix_system_t) :: chain
      type(system_form_t) :: form
      type(error_t), allocatable :: error
      real(wp), allocatable :: phi_cost(:, :, :), phi_best(:, :, :)
      integer :: s, unit, failures, round, m
      real(wp) :: seconds, best, steps, worst, dummy
      open (newunit=unit, file=out_dir//"/system_cost.dat", status="replace", action="write")
      write (unit, '(a, i0, a, i0, a)') "# cost against n: chains of n driven oscillators, ", cost_n, " x ", cost_n, &
         " grid of alpha in [0, 1], beta in [0.5, 6], tolerance 1e-10, method auto, one thread"
      write (unit, '(a)') "# columns: n us_per_point steps_per_point us_per_step failures max_error"
      write (*, '(/, a, i0, a, i0, a)') "cost against n (oscillator chains, ", cost_n, " x ", cost_n, &
         " grid, tolerance 1e-10, error against magnus6 at 1e-13)"
      write (*, '(a)') "   n    us/point  steps/point    us/step  failures    max error"
      do s = 1, size(sizes)
         chain = oscillator_chain(sizes(s))
         call prepare_system(chain, 0.0_wp, form, error)
         if (allocated(error)) error stop "bench: prepare_system (chain)"
         m = 2*sizes(s)
         best = huge(1.0_wp)
         do round = 1, rounds
            call chain_grid(chain, form, system_method_t(system_auto, tolerance), phi_cost, seconds, steps, failures)
            best = min(best, seconds)
         end do
         call chain_grid(chain, form, system_method_t(system_magnus6, 1.0e-13_wp), phi_best, dummy, dummy, round)
         worst = maxval(maxval(maxval(abs(phi_cost - phi_best), dim=1), dim=1)/ &
                        max(1.0_wp, maxval(maxval(abs(phi_best), dim=1), dim=1)))
         write (*, '(i4, f12.2, f13.2, f11.3, i10, es13.3)') sizes(s), 1.0e6_wp*best/cost_n**2, steps, &
            1.0e6_wp*best/cost_n**2/steps, failures, worst
         write (unit, '(i4, f14.3, f12.3, f12.4, i6, es12.3)') sizes(s), 1.0e6_wp*best/cost_n**2, steps, &
            1.0e6_wp*best/cost_n**2/steps, failures, worst
      end do
      close (unit)
   end subroutine cost_table

   !> One run of the cost grid: Φ = e^s Φ̃ per point (m × m × points), the time, steps per
   !> point and the points whose status is not ok.
   subroutine chain_grid(chain, form, method, phi_grid, seconds, steps, failures)
      type(matrix_system_t), intent(in) :: chain
      type(system_form_t), intent(in) :: form
      type(system_method_t), intent(in) :: method
      real(wp), allocatable, intent(out) :: phi_grid(:, :, :)
      real(wp), intent(out) :: seconds, steps
      integer, intent(out) :: failures
      type(system_nodes_t) :: nodes
      type(system_monodromy_t) :: r
      type(floquet_t) :: f
      type(error_t), allocatable :: error
      integer :: i, j, m
      integer(int64) :: total
      real(wp) :: t0, alpha, beta
      m = 2*form%n
      allocate (phi_grid(m, m, cost_n*cost_n))
      failures = 0
      total = 0
      t0 = wall_seconds()
      do i = 1, cost_n
         alpha = grid_value(0.0_wp, 1.0_wp, cost_n, i)
         nodes = system_nodes_t()
         do j = 1, cost_n
            beta = grid_value(0.5_wp, 6.0_wp, cost_n, j)
            call system_monodromy(chain, form, alpha, beta, method, nodes, r, error)
            call system_floquet(r%phi, form, r%error_estimate*max(1.0_wp, maxval(abs(r%phi))), f, r%log_scale)
            if (r%status /= status_ok) failures = failures + 1
            total = total + r%steps
            phi_grid(:, :, (i - 1)*cost_n + j) = r%phi*exp(r%log_scale)
         end do
      end do
      seconds = wall_seconds() - t0
      steps = real(total, wp)/cost_n**2
   end subroutine chain_grid
end program hillstab_bench_system

!> Speed against error: work-precision data for every monodromy method on a
!> fixed sample of (α, β), and the cost growth with β.
!>
!> Usage: hillstab_bench [--quick] [--chart-only] [--out PREFIX]
!> Writes PREFIX_work_precision.dat, PREFIX_beta_cost.dat and PREFIX_chart.dat (default
!> PREFIX = out/bench) and prints the tables. Times are wall-clock, measured side by side
!> in one run; compare them as ratios.
!>
!> The chart part runs whole scenes through the batch program's entry point
!> (`run_scene_file`: namelist in, chart file out): method auto on all cores against
!> GSL rk8pd point by point on one thread, both at tolerance 1e-10, and checks every
!> point of both files against a reference chart (GSL at 1e-13).
program hillstab_bench
   use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
   use hillstab, only: wp => hillstab_wp, int64 => hillstab_int64, version_string => hillstab_version_string, &
      error_t => hillstab_error_t, work_stats_t, elastic_model_t, hill_point_t, &
      sampling_midpoint => hillstab_sampling_midpoint, sampling_average => hillstab_sampling_average, &
      sampling_name => hillstab_sampling_name, trace_t, method_t, method_auto => hillstab_method_auto, &
      method_formula => hillstab_method_formula, method_segments => hillstab_method_segments, &
      method_magnus4 => hillstab_method_magnus4, method_magnus6 => hillstab_method_magnus6, &
      method_rk => hillstab_method_rk, method_gsl => hillstab_method_gsl, method_name => hillstab_method_name, &
      monodromy_trace, monodromy_trace_batch, trace_segmented
   use hillstab_batch_run_scenes, only: run_scene_file
   !$ use omp_lib, only: omp_get_max_threads, omp_set_num_threads
   implicit none

   type :: sample_t
      real(wp) :: alpha, beta
   end type sample_t

   !> What `seconds_per_call` times.
   integer, parameter :: timed_points = 1, timed_rows = 2, timed_point = 3

   type(sample_t), allocatable :: samples(:)
   character(len=:), allocatable :: block_names
   ! what the timed_* procedures run (internal procedures cannot nest, so the work to
   ! time is described here before each seconds_per_call)
   type(method_t) :: timed_method
   type(hill_point_t) :: timed_at
   type(elastic_model_t) :: elastic
   type(trace_t), allocatable :: timed_traces(:)
   integer(int64) :: timed_evaluations
   real(wp), allocatable :: truth(:)
   character(len=256) :: prefix, arg
   logical :: quick, chart_only
   integer :: i, unit, stat
   character(len=256) :: msg

   prefix = "out/bench"
   quick = .false.
   chart_only = .false.
   i = 1
   do while (i <= command_argument_count())
      call get_command_argument(i, arg)
      select case (trim(arg))
      case ("--quick")
         quick = .true.
      case ("--chart-only")
         chart_only = .true.
      case ("--out")
         i = i + 1
         call get_command_argument(i, prefix)
      case ("--help", "-h")
         write (output_unit, '(a)') "usage: hillstab_bench [--quick] [--chart-only] [--out PREFIX]"
         stop
      case default
         write (error_unit, '(a)') "hillstab_bench: unknown argument '"//trim(arg)//"'"
         stop 2
      end select
      i = i + 1
   end do
   call execute_command_line("mkdir -p $(dirname "//trim(prefix)//"_x)", exitstat=stat)

   call chart_bar(trim(prefix), quick)
   if (chart_only) stop

   samples = make_samples()
   allocate (truth(size(samples)))
   call reference_traces(samples, truth)

   open (newunit=unit, file=trim(prefix)//"_work_precision.dat", status="replace", action="write", &
         iostat=stat, iomsg=msg)
   if (stat /= 0) then
      write (error_unit, '(a)') "hillstab_bench: "//trim(msg)
      stop 2
   end if
   write (unit, '(a)') "# hillstab "//version_string//" work-precision benchmark"
   write (unit, '(a,i0,a)') "# sample: ", size(samples), " (alpha, beta) points: alpha in {0.5,2,5,8,9.5,9.8} x 24 beta in [-2,12]"
   write (unit, '(a)') "# error = max over the sample of |S - S_ref| / max(1, |S_ref|)"
   write (unit, '(a)') "# one gnuplot index (block separated by two blank lines) per method"
   write (unit, '(a)') "# columns: method setting seconds_per_point max_error mean_error q_evaluations_per_point"
   write (output_unit, '(a)') ""
   write (output_unit, '(a)') "Work-precision over the sample (time per point, error scaled by max(1,|S|))"
   write (output_unit, '(a10,a12,a14,a12,a12,a12)') "method", "setting", "us/point", "max error", &
      "mean error", "Q evals"
   block_names = ""
   call sweep_formula(unit)
   call sweep_segments(unit, sampling_midpoint, quick)
   call sweep_segments(unit, sampling_average, quick)
   call sweep_tolerance(unit, method_magnus4, quick)
   call sweep_tolerance(unit, method_magnus6, quick)
   call sweep_tolerance(unit, method_rk, quick)
   call sweep_tolerance(unit, method_gsl, quick)
   call sweep_tolerance(unit, method_auto, quick)
   call sweep_rows(unit, quick)
   close (unit)
   write (output_unit, '(a)') "wrote "//trim(prefix)//"_work_precision.dat"
   open (newunit=unit, file=trim(prefix)//"_methods.gp", status="replace", action="write")
   write (unit, '(a)') 'names = "'//trim(adjustl(block_names))//'"'
   close (unit)

   call beta_cost(trim(prefix)//"_beta_cost.dat")

contains

   !> Write a chart scene (α ∈ [0, 9.8], β ∈ [−2, 12], n × n points) for `method`.
   subroutine write_chart_scene(path, method, tolerance, n, output)
      character(len=*), intent(in) :: path, method, output
      real(wp), intent(in) :: tolerance
      integer, intent(in) :: n
      integer :: u
      open (newunit=u, file=path, status="replace", action="write")
      write (u, '(a,es9.2,a)') "&scene task='chart', model='elastic', method='"//method//"', tolerance=", &
         tolerance, ", output='"//output//"' /"
      write (u, '(a,i0,a,i0,a)') "&chart alpha_min=0, alpha_max=9.8, n_alpha=", n, &
         ", beta_min=-2, beta_max=12, n_beta=", n, " /"
      close (u)
   end subroutine write_chart_scene

   !> Wall time of a whole scene run (best of `repeats`), on `threads` threads.
   real(wp) function time_scene(path, threads, repeats) result(best)
      character(len=*), intent(in) :: path
      integer, intent(in) :: threads, repeats
      type(error_t), allocatable :: error
      integer(int64) :: t0, t1, rate
      integer :: r, saved
      saved = 1
      !$ saved = omp_get_max_threads()
      !$ call omp_set_num_threads(threads)
      best = huge(1.0_wp)
      do r = 1, repeats
         call system_clock(t0, rate)
         call run_scene_file(path, .true., error)
         call system_clock(t1)
         if (allocated(error)) then
            write (error_unit, '(a)') "hillstab_bench: "//error%message
            stop 1
         end if
         best = min(best, real(t1 - t0, wp)/rate)
      end do
      !$ call omp_set_num_threads(saved)
   end function time_scene

   !> S column of a chart file, in file order.
   function chart_traces(path) result(s)
      character(len=*), intent(in) :: path
      real(wp), allocatable :: s(:)
      character(len=512) :: line
      real(wp) :: a, b, t
      integer :: u, ios, n
      real(wp), allocatable :: grown(:)
      allocate (s(1024))
      open (newunit=u, file=path, status="old", action="read")
      n = 0
      do
         read (u, '(a)', iostat=ios) line
         if (ios /= 0) exit
         if (len_trim(line) == 0 .or. line(1:1) == "#") cycle
         read (line, *) a, b, t
         if (n == size(s)) then   ! grow geometrically, not by one element a line
            allocate (grown(2*n))
            grown(1:n) = s
            call move_alloc(grown, s)
         end if
         n = n + 1
         s(n) = t
      end do
      close (u)
      s = s(1:n)
   end function chart_traces

   !> max |S − S_ref| / max(1, |S_ref|) over two chart files of the same grid.
   real(wp) function chart_error(path, reference) result(worst)
      character(len=*), intent(in) :: path, reference
      real(wp), allocatable :: s(:), r(:)
      s = chart_traces(path)
      r = chart_traces(reference)
      if (size(s) /= size(r)) then
         worst = huge(1.0_wp)
         return
      end if
      worst = maxval(abs(s - r)/max(1.0_wp, abs(r)))
   end function chart_error

   !> The speed bar: whole chart runs, auto on all cores against GSL rk8pd on one thread.
   subroutine chart_bar(prefix, quick)
      character(len=*), intent(in) :: prefix
      logical, intent(in) :: quick
      integer, parameter :: sizes(4) = [50, 100, 200, 300]
      integer :: k, n, u, threads, n_sizes
      real(wp) :: t_auto, t_gsl, t_auto1, t_ref, e_auto, e_gsl
      character(len=:), allocatable :: base
      threads = 1
      !$ threads = omp_get_max_threads()
      base = prefix//"_chart"
      n_sizes = merge(2, size(sizes), quick)
      open (newunit=u, file=prefix//"_chart.dat", status="replace", action="write")
      write (u, '(a)') "# hillstab "//version_string//" whole chart runs, alpha in [0, 9.8], beta in [-2, 12], tol 1e-10"
      write (u, '(a,i0,a)') "# auto on ", threads, " threads; gsl rk8pd point by point on 1 thread; best of repeats"
      write (u, '(a)') "# error = max over the chart of |S - S_ref|/max(1,|S_ref|), S_ref: gsl at 1e-13"
      write (u, '(a)') "# columns: n_points auto_seconds auto_1thread_seconds gsl_seconds ratio auto_error gsl_error"
      write (output_unit, '(a,i0,a)') "Whole chart runs at tolerance 1e-10 (auto on ", threads, &
         " threads, GSL rk8pd on 1 thread)"
      write (output_unit, '(a8,4a12,2a12)') "points", "auto [s]", "auto 1t [s]", "gsl 1t [s]", "ratio", &
         "auto err", "gsl err"
      do k = 1, n_sizes
         n = sizes(k)
         call write_chart_scene(base//"_auto.nml", "auto", 1.0e-10_wp, n, base//"_auto")
         call write_chart_scene(base//"_gsl.nml", "gsl", 1.0e-10_wp, n, base//"_gsl")
         call write_chart_scene(base//"_ref.nml", "gsl", 1.0e-13_wp, n, base//"_ref")
         t_auto = time_scene(base//"_auto.nml", threads, 5)
         t_auto1 = time_scene(base//"_auto.nml", 1, 3)
         t_gsl = time_scene(base//"_gsl.nml", 1, 3)
         t_auto = min(t_auto, time_scene(base//"_auto.nml", threads, 5))  ! interleaved with gsl: same conditions
         t_gsl = min(t_gsl, time_scene(base//"_gsl.nml", 1, 2))
         t_ref = time_scene(base//"_ref.nml", threads, 1)
         e_auto = chart_error(base//"_auto_chart.dat", base//"_ref_chart.dat")
         e_gsl = chart_error(base//"_gsl_chart.dat", base//"_ref_chart.dat")
         write (u, '(i8,4(1x,es12.5),2(1x,es10.3))') n*n, t_auto, t_auto1, t_gsl, t_gsl/t_auto, e_auto, e_gsl
         write (output_unit, '(i8,3f12.4,f12.1,2es12.2,a,f8.3,a)') n*n, t_auto, t_auto1, t_gsl, t_gsl/t_auto, e_auto, &
            e_gsl, "   (reference: ", t_ref, " s)"
      end do
      close (u)
      write (output_unit, '(a)') "wrote "//prefix//"_chart.dat"
   end subroutine chart_bar

   function make_samples() result(s)
      type(sample_t), allocatable :: s(:)
      real(wp), parameter :: alphas(6) = [0.5_wp, 2.0_wp, 5.0_wp, 8.0_wp, 9.5_wp, 9.8_wp]
      integer, parameter :: n_beta = 24
      integer :: a, b, k
      ! rows of constant alpha (β from −2 to 12), so that chart-style batches can be timed too
      allocate (s(size(alphas)*n_beta))
      k = 0
      do a = 1, size(alphas)
         do b = 1, n_beta
            k = k + 1
            s(k) = sample_t(alphas(a), -2.0_wp + 14.0_wp*(b - 1)/(n_beta - 1))
         end do
      end do
   end function make_samples

   !> Reference traces: Magnus-6 at 1e-14 checked against GSL rk8pd at 1e-13 (two
   !> independent methods); falls back to Richardson-extrapolated segments.
   subroutine reference_traces(s, ref)
      type(sample_t), intent(in) :: s(:)
      real(wp), intent(out) :: ref(:)
      type(trace_t) :: a, b
      type(error_t), allocatable :: err_a, err_b
      real(wp) :: worst
      integer :: k
      worst = 0.0_wp
      do k = 1, size(s)
         call monodromy_trace(elastic, point_at(s(k)), method_t(method_magnus6, tolerance=1.0e-14_wp), a, err_a)
         call monodromy_trace(elastic, point_at(s(k)), method_t(method_gsl, tolerance=1.0e-13_wp), b, err_b)
         if (.not. allocated(err_a)) then
            ref(k) = a%value
            if (.not. allocated(err_b)) worst = max(worst, abs(a%value - b%value)/max(1.0_wp, abs(a%value)))
         else if (.not. allocated(err_b)) then
            ref(k) = b%value
         else
            a = trace_segmented(elastic, point_at(s(k)), 65536, sampling_average)
            b = trace_segmented(elastic, point_at(s(k)), 131072, sampling_average)
            ref(k) = (4.0_wp*b%value - a%value)/3.0_wp
         end if
      end do
      write (output_unit, '(a,es9.2)') "reference: Magnus-6 (1e-14) vs GSL rk8pd (1e-13), max scaled difference ", worst
   end subroutine reference_traces

   pure function point_at(s) result(point)
      type(sample_t), intent(in) :: s
      type(hill_point_t) :: point
      point = hill_point_t(s%alpha, s%beta, 0.0_wp)
   end function point_at

   !> Time all sample points with one method (repeated until ≥ 0.05 s), errors and work.
   subroutine measure(method, seconds, max_err, mean_err, evals, ok)
      type(method_t), intent(in) :: method
      real(wp), intent(out) :: seconds, max_err, mean_err, evals
      logical, intent(out) :: ok
      type(trace_t) :: traces(size(samples))
      type(error_t), allocatable :: error
      type(work_stats_t) :: work
      integer(int64) :: total_evals
      integer :: k
      ok = .true.
      total_evals = 0
      do k = 1, size(samples)
         call monodromy_trace(elastic, point_at(samples(k)), method, traces(k), error, work)
         if (allocated(error)) then
            ok = .false.
            return
         end if
         total_evals = total_evals + work%n_evaluations
      end do
      evals = real(total_evals, wp)/size(samples)
      call sample_errors(traces, max_err, mean_err)
      timed_method = method
      seconds = seconds_per_call(timed_points, 0.05_wp)/size(samples)
   end subroutine measure

   !> Timed work: every sample point by `timed_method`, point by point.
   subroutine timed_all_points()
      type(trace_t) :: tr
      type(error_t), allocatable :: error
      integer :: k
      do k = 1, size(samples)
         call monodromy_trace(elastic, point_at(samples(k)), timed_method, tr, error)
      end do
   end subroutine timed_all_points

   !> Timed work: the sample's rows of constant α, each as one batch, by `timed_method`;
   !> fills `timed_traces` and counts Q evaluations in `timed_evaluations`.
   subroutine timed_all_rows()
      logical :: failed(size(samples))
      type(error_t), allocatable :: error
      type(work_stats_t) :: work
      integer :: first, last
      timed_evaluations = 0
      first = 1
      do while (first <= size(samples))
         last = first
         do while (last < size(samples))
            if (samples(last + 1)%alpha /= samples(first)%alpha) exit
            last = last + 1
         end do
         call monodromy_trace_batch(elastic, point_at(samples(first)), samples(first:last)%beta, timed_method, &
            timed_traces(first:last), failed(first:last), error, work)
         timed_evaluations = timed_evaluations + work%n_evaluations
         first = last + 1
      end do
   end subroutine timed_all_rows

   !> Timed work: `timed_at` by `timed_method`.
   subroutine timed_one_point()
      type(trace_t) :: tr
      type(error_t), allocatable :: error
      call monodromy_trace(elastic, timed_at, timed_method, tr, error)
   end subroutine timed_one_point

   !> max and mean of |S − S_ref|/max(1, |S_ref|) over the sample.
   subroutine sample_errors(traces, max_err, mean_err)
      type(trace_t), intent(in) :: traces(:)
      real(wp), intent(out) :: max_err, mean_err
      real(wp) :: e(size(traces))
      e = abs(traces%value - truth)/max(1.0_wp, abs(truth))
      max_err = maxval(e)
      mean_err = sum(e)/size(e)
   end subroutine sample_errors

   !> Wall time of one call of `run`, repeated (doubling) until the repeats take at
   !> least `min_seconds`.
   !> `run` selects the work (1 all points, 2 all rows, 3 one point): a selector rather than
   !> a procedure argument, since an internal procedure passed as an argument makes
   !> gfortran build a trampoline and mark the program as needing an executable stack.
   real(wp) function seconds_per_call(run, min_seconds) result(seconds)
      integer, intent(in) :: run
      real(wp), intent(in) :: min_seconds
      integer(int64) :: t0, t1, rate
      integer :: r, repeats
      repeats = 1
      do
         call system_clock(t0, rate)
         do r = 1, repeats
            select case (run)
            case (timed_points); call timed_all_points()
            case (timed_rows); call timed_all_rows()
            case default; call timed_one_point()
            end select
         end do
         call system_clock(t1)
         if (real(t1 - t0, wp)/rate >= min_seconds .or. repeats > 1000000) exit
         repeats = 2*repeats
      end do
      seconds = real(t1 - t0, wp)/rate/repeats
   end function seconds_per_call

   !> One line of the work-precision table (file and screen); the first line of a block
   !> adds the block's name for the plot.
   subroutine write_result(unit, name, setting, seconds, max_err, mean_err, evals, written)
      integer, intent(in) :: unit
      character(len=*), intent(in) :: name
      real(wp), intent(in) :: setting, seconds, max_err, mean_err, evals
      logical, intent(inout) :: written  !! a line of this block was written
      if (.not. written) block_names = block_names//" "//name
      written = .true.
      write (unit, '(a,1x,es10.3,4(1x,es12.5))') name, setting, seconds, max_err, mean_err, evals
      write (output_unit, '(a10,es12.2,f14.2,es12.2,es12.2,f12.1)') name, setting, 1.0e6_wp*seconds, max_err, &
         mean_err, evals
   end subroutine write_result

   subroutine report(unit, name, setting, method, written)
      integer, intent(in) :: unit
      character(len=*), intent(in) :: name
      real(wp), intent(in) :: setting
      type(method_t), intent(in) :: method
      logical, intent(inout) :: written  !! a line of this block was written
      real(wp) :: seconds, max_err, mean_err, evals
      logical :: ok
      call measure(method, seconds, max_err, mean_err, evals, ok)
      if (ok) call write_result(unit, name, setting, seconds, max_err, mean_err, evals, written)
   end subroutine report

   subroutine sweep_formula(unit)
      integer, intent(in) :: unit
      logical :: written
      written = .false.
      call report(unit, "formula", 2.0_wp, method_t(method_formula), written)
      if (written) write (unit, '(/)')
   end subroutine sweep_formula

   subroutine sweep_segments(unit, sampling, quick)
      integer, intent(in) :: unit, sampling
      logical, intent(in) :: quick
      integer :: n
      logical :: written
      written = .false.
      n = 4
      do while (n <= merge(4096, 65536, quick))
         call report(unit, "seg-"//sampling_name(sampling), real(n, wp), method_t(method_segments, n, sampling), &
            written)
         n = 4*n
      end do
      if (written) write (unit, '(/)')
   end subroutine sweep_segments

   subroutine sweep_tolerance(unit, kind, quick)
      integer, intent(in) :: unit, kind
      logical, intent(in) :: quick
      integer :: p
      logical :: written
      written = .false.
      do p = 3, 12, merge(3, 1, quick)
         call report(unit, method_name(kind), 10.0_wp**(-p), method_t(kind, tolerance=10.0_wp**(-p)), written)
      end do
      if (written) write (unit, '(/)')
   end subroutine sweep_tolerance

   !> Method auto the way charts use it: the sample's rows of constant α as batches.
   subroutine sweep_rows(unit, quick)
      integer, intent(in) :: unit
      logical, intent(in) :: quick
      integer :: p
      real(wp) :: tol, max_err, mean_err, seconds, evals
      logical :: written
      written = .false.
      if (allocated(timed_traces)) deallocate (timed_traces)
      allocate (timed_traces(size(samples)))
      do p = 3, 12, merge(3, 1, quick)
         tol = 10.0_wp**(-p)
         timed_method = method_t(method_auto, tolerance=tol)
         call timed_all_rows()
         evals = real(timed_evaluations, wp)/size(samples)
         seconds = seconds_per_call(timed_rows, 0.05_wp)/size(samples)
         call sample_errors(timed_traces, max_err, mean_err)
         call write_result(unit, "auto-rows", tol, seconds, max_err, mean_err, evals, written)
      end do
      if (written) write (unit, '(/)')
   end subroutine sweep_rows

   !> Cost per point of `auto` and GSL at tolerance 1e-10 as β grows (α = 5 and 9.8).
   subroutine beta_cost(path)
      character(len=*), intent(in) :: path
      real(wp), parameter :: betas(8) = [1.0_wp, 10.0_wp, 30.0_wp, 100.0_wp, 300.0_wp, 1000.0_wp, 3000.0_wp, 1.0e4_wp]
      real(wp), parameter :: alphas(2) = [5.0_wp, 9.8_wp]
      integer :: u, a, b, m
      integer, parameter :: kinds(3) = [method_auto, method_magnus6, method_gsl]
      real(wp) :: seconds(3), evals(3)
      open (newunit=u, file=path, status="replace", action="write")
      write (u, '(a)') "# hillstab "//version_string//" cost per point against beta at tolerance 1e-10"
      write (u, '(a)') "# columns: alpha beta auto_seconds auto_evals magnus6_seconds magnus6_evals gsl_seconds gsl_evals"
      write (output_unit, '(/,a)') "Cost per point against beta (tolerance 1e-10): microseconds (Q evaluations)"
      write (output_unit, '(a6,a10,3a22)') "alpha", "beta", "auto", "magnus6", "gsl rk8pd"
      do a = 1, size(alphas)
         do b = 1, size(betas)
            do m = 1, size(kinds)
               call time_point(hill_point_t(alphas(a), betas(b), 0.0_wp), &
                  method_t(kinds(m), tolerance=1.0e-10_wp), seconds(m), evals(m))
            end do
            write (u, '(2(es12.5,1x),6(es12.5,1x))') alphas(a), betas(b), (seconds(m), evals(m), m=1, 3)
            write (output_unit, '(f6.2,f10.1,3(f12.1," (",i7,")"))') alphas(a), betas(b), &
               (1.0e6_wp*seconds(m), nint(evals(m)), m=1, 3)
         end do
         write (u, '(/)')
      end do
      close (u)
      write (output_unit, '(a)') "wrote "//path
   end subroutine beta_cost

   subroutine time_point(point, method, seconds, evals)
      type(hill_point_t), intent(in) :: point
      type(method_t), intent(in) :: method
      real(wp), intent(out) :: seconds, evals
      type(trace_t) :: tr
      type(error_t), allocatable :: error
      type(work_stats_t) :: work
      seconds = -1.0_wp; evals = -1.0_wp
      call monodromy_trace(elastic, point, method, tr, error, work)
      if (allocated(error)) return
      evals = real(work%n_evaluations, wp)
      timed_at = point
      timed_method = method
      seconds = seconds_per_call(timed_point, 0.02_wp)
   end subroutine time_point
end program hillstab_bench

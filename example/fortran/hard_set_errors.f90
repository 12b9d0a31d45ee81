!> Every exact method against the stored high-precision reference at the hard points
!> (data/reference/hard_set.dat, made by data/reference/make_reference.py), at
!> tolerances 1e-8, 1e-10 and 1e-12. Prints a Markdown table: per method and tolerance,
!> the worst error/tolerance over the points with status ok, the number of round-off
!> limited points and the worst error/estimate among them, failed points, and the time
!> per point (one thread; shared machine, so only ratios within one run mean much).
!> Run from the repository root: `fpm run --profile release --example hard_set_errors`.
!> Arguments (any order): a reference file (`data/reference/check_set.dat`: the check set;
!> default the hard set), `loose` (tolerances 1e-4, 1e-6, 1e-8), `m=NAME` (one method),
!> `all` (list every point with its error, estimate and status); any other argument lists
!> every point with status ok whose error exceeds the tolerance.
program hard_set_errors
   use hillstab, only: wp => hillstab_wp, int64 => hillstab_int64, error_t => hillstab_error_t, &
      err_accuracy => hillstab_err_accuracy, elastic_model_t, mathieu_model_t, hill_point_t, &
      trace_t, method_t, method_auto => hillstab_method_auto, &
      method_magnus4 => hillstab_method_magnus4, method_magnus6 => hillstab_method_magnus6, &
      method_rk => hillstab_method_rk, method_gsl => hillstab_method_gsl, method_name => hillstab_method_name, &
      monodromy_trace
   implicit none
   integer, parameter :: n_max = 200
   real(wp) :: tolerances(3) = [1.0e-8_wp, 1.0e-10_wp, 1.0e-12_wp]
   integer :: methods(5)
   integer :: model(n_max), n, unit, ios, m, k, i, n_roundoff, n_failed, kind
   real(wp) :: alpha(n_max), beta(n_max), sgn(n_max), log_abs(n_max), value(n_max), ref_error
   real(wp) :: err, worst_ok, worst_roundoff, largest_estimate
   integer(int64) :: t0, t1, rate
   character(len=400) :: line
   type(trace_t) :: tr
   type(elastic_model_t) :: elastic
   type(mathieu_model_t) :: mathieu
   type(error_t), allocatable :: error
   logical :: verbose, list_all
   character(len=400) :: file, arg
   character(len=20) :: only = ""
   verbose = .false.
   list_all = .false.
   file = "data/reference/hard_set.dat"
   do i = 1, command_argument_count()
      call get_command_argument(i, arg)
      if (arg == "loose") then
         tolerances = [1.0e-4_wp, 1.0e-6_wp, 1.0e-8_wp]
      else if (arg(1:2) == "m=") then
         only = arg(3:)
      else if (arg == "all") then
         list_all = .true.
         verbose = .true.
      else if (index(arg, ".dat") > 0) then
         file = arg
      else
         verbose = .true.
      end if
   end do
   methods = [method_auto, method_magnus4, method_magnus6, method_rk, method_gsl]
   open (newunit=unit, file=trim(file), status="old", action="read", iostat=ios)
   if (ios /= 0) error stop "run from the repository root: reference file not found"
   n = 0
   do
      read (unit, '(a)', iostat=ios) line
      if (ios /= 0) exit
      if (line(1:1) == "#" .or. len_trim(line) == 0) cycle
      line = line(1:index(line//"#", "#") - 1)
      n = n + 1
      read (line, *) kind, alpha(n), beta(n), sgn(n), log_abs(n), value(n), ref_error
      model(n) = kind
   end do
   close (unit)
   write (*, '(a,i0,a)') trim(file)//": ", n, " points"
   write (*, '(a)') "| method | tolerance | worst error/tolerance, status 0 | round-off limited | "// &
      "worst error/estimate there | largest estimate | failed | ms/point |"
   write (*, '(a)') "|---|---|---|---|---|---|---|---|"
   do m = 1, size(methods)
      if (len_trim(only) > 0 .and. method_name(methods(m)) /= only) cycle
      do k = 1, size(tolerances)
         worst_ok = 0.0_wp
         worst_roundoff = 0.0_wp
         largest_estimate = 0.0_wp
         n_roundoff = 0
         n_failed = 0
         call system_clock(t0, rate)
         do i = 1, n
            ! the files' first column: 0 the elastic model, 1 the Mathieu model
            if (model(i) == 0) then
               call monodromy_trace(elastic, hill_point_t(alpha(i), beta(i), 0.0_wp), &
                                    method_t(methods(m), tolerance=tolerances(k)), tr, error)
            else
               call monodromy_trace(mathieu, hill_point_t(alpha(i), beta(i), 0.0_wp), &
                                    method_t(methods(m), tolerance=tolerances(k)), tr, error)
            end if
            if (log_abs(i) > log(1.0e6_wp)) then
               err = abs(exp(min(tr%log_abs - log_abs(i), 700.0_wp)) - 1.0_wp)
               if (sign(1.0_wp, tr%value) /= sgn(i)) err = 2.0_wp
            else
               err = abs(tr%value - value(i))/max(1.0_wp, abs(value(i)))
            end if
            if (list_all) print '(a8,es8.1,f8.3,es11.3,a,es10.2,a,es10.2,a,i0)', method_name(methods(m)), &
               tolerances(k), alpha(i), beta(i), " err", err, " est", tr%error_estimate, " status ", &
               merge(0, merge(1, 2, error_code(error) == err_accuracy), .not. allocated(error))
            if (allocated(error)) then
               if (error%code == err_accuracy) then
                  n_roundoff = n_roundoff + 1
                  worst_roundoff = max(worst_roundoff, err/tr%error_estimate)
                  largest_estimate = max(largest_estimate, tr%error_estimate)
               else
                  n_failed = n_failed + 1
               end if
            else
               worst_ok = max(worst_ok, err/tolerances(k))
               if (err > tolerances(k) .and. verbose) print '(a,1x,a,es8.1,f7.3,es11.3,a,es10.2,a,es10.2)', "MISS", &
                  method_name(methods(m)), tolerances(k), alpha(i), beta(i), " err", err, " est", tr%error_estimate
            end if
         end do
         call system_clock(t1)
         write (*, '("| ",a," | ",es7.0," | ",f6.3," | ",i0," | ",f6.3," | ",es8.1," | ",i0," | ",f8.3," |")') &
            method_name(methods(m)), tolerances(k), worst_ok, n_roundoff, worst_roundoff, largest_estimate, n_failed, &
            1.0e3_wp*real(t1 - t0, wp)/rate/n
      end do
   end do
contains
   integer function error_code(e)
      type(error_t), allocatable, intent(in) :: e
      error_code = 0
      if (allocated(e)) error_code = e%code
   end function error_code
end program hard_set_errors

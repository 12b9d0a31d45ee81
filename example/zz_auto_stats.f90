program zz
   use hillstab
   implicit none
   integer :: i, j, na, nb, n0, ndoubled, hist(0:6)
   real(wp) :: a, b, tol, c0, c1, e, worst
   type(trace_t) :: t, ref
   type(work_stats_t) :: st
   type(error_t), allocatable :: err
   character(len=32) :: arg
   tol = 1.0e-10_wp
   if (command_argument_count() > 0) then
      call get_command_argument(1, arg); read (arg, *) tol
   end if
   na = 40; nb = 40; ndoubled = 0; hist = 0; worst = 0
   do i = 1, na
      do j = 0, nb - 1
         a = 9.8_wp*i/na; b = -2.0_wp + 14.0_wp*j/(nb - 1)
         c0 = pi2; c1 = b - pi2
         n0 = auto_initial_steps(model_elastic, a, c0, c1, tol)
         call trace_auto(hill_model_t(model_elastic, a, b, 0.0_wp), tol, t, st, err)
         call trace_gsl(hill_model_t(model_elastic, a, b, 0.0_wp), 1.0e-13_wp, ref, st, err)
         call trace_auto(hill_model_t(model_elastic, a, b, 0.0_wp), tol, t, st, err)
         e = abs(t%value - ref%value)/max(1.0_wp, abs(ref%value))/tol
         worst = max(worst, e)
         hist(min(6, max(0, nint(log10(max(e, 1e-6_wp))) + 6))) = hist(min(6, max(0, nint(log10(max(e, 1e-6_wp))) + 6))) + 1
         if (st%n_steps > (3*n0)/2) ndoubled = ndoubled + 1
      end do
      write (*, '(f6.2,i6)', advance='no') a, n0
      if (mod(i, 5) == 0) write (*, *)
   end do
   print *, 'doubled fraction', real(ndoubled)/(na*nb), ' worst err/tol', worst
   print *, 'hist of log10(err/tol) from -6..0:', hist
end program

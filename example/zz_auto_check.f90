program zz
   use hillstab
   implicit none
   integer :: i, j, na, nb, worst_i, worst_j, np
   real(wp) :: a, b, e, worst, tol
   type(trace_t) :: ref, t
   type(work_stats_t) :: st, tot
   type(error_t), allocatable :: err
   integer(int64) :: t0, t1, rate
   real(wp) :: ta, tg
   tol = 1.0e-10_wp
   na = 60; nb = 60
   worst = 0; tot = work_stats_t(); np = 0
   do i = 0, na - 1
      do j = 0, nb - 1
         a = 9.8_wp*i/(na - 1); b = -2.0_wp + 14.0_wp*j/(nb - 1)
         call trace_gsl(hill_model_t(model_elastic, a, b, 0.0_wp), 1.0e-13_wp, ref, st, err)
         call trace_auto(hill_model_t(model_elastic, a, b, 0.0_wp), tol, t, st, err)
         if (allocated(err)) print *, 'err', a, b, err%message
         call add_work(tot, st); np = np + 1
         e = abs(t%value - ref%value)/max(1.0_wp, abs(ref%value))
         if (e > worst) then
            worst = e; worst_i = i; worst_j = j
         end if
      end do
   end do
   print '(a,es10.2,a,2f8.3,a,f8.1)', 'worst scaled error vs gsl 1e-13: ', worst, ' at', 9.8_wp*worst_i/(na-1), &
      -2.0_wp + 14.0_wp*worst_j/(nb-1), '  mean steps/point ', real(tot%n_steps, wp)/np
   call system_clock(t0, rate)
   do i = 0, na - 1
      do j = 0, nb - 1
         a = 9.8_wp*i/(na - 1); b = -2.0_wp + 14.0_wp*j/(nb - 1)
         call trace_auto(hill_model_t(model_elastic, a, b, 0.0_wp), tol, t, st, err)
      end do
   end do
   call system_clock(t1); ta = real(t1 - t0, wp)/rate/(na*nb)
   call system_clock(t0, rate)
   do i = 0, na - 1
      do j = 0, nb - 1
         a = 9.8_wp*i/(na - 1); b = -2.0_wp + 14.0_wp*j/(nb - 1)
         call trace_gsl(hill_model_t(model_elastic, a, b, 0.0_wp), tol, t, st, err)
      end do
   end do
   call system_clock(t1); tg = real(t1 - t0, wp)/rate/(na*nb)
   print '(a,f8.3,a,f8.3,a,f6.2)', 'per point us: auto ', ta*1e6, '  gsl ', tg*1e6, '  ratio ', tg/ta
   block
      real(wp) :: betas(60)
      type(trace_t) :: trs(60)
      do j = 1, 60
         betas(j) = -2.0_wp + 14.0_wp*(j - 1)/59
      end do
      call system_clock(t0, rate)
      do i = 0, na - 1
         call trace_auto_batch(model_elastic, 9.8_wp*i/(na - 1), 0.0_wp, betas, tol, trs, st, err)
      end do
      call system_clock(t1); ta = real(t1 - t0, wp)/rate/(na*nb)
      print '(a,f8.3,a,f6.2)', 'batch per point us: ', ta*1e6, '  ratio vs gsl ', tg/ta
   end block
end program

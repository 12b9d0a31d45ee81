program zz
   use hillstab
   implicit none
   real(wp) :: alphas(3) = [9.8_wp, 9.85_wp, 9.86_wp]
   integer :: i
   type(trace_t) :: tr
   type(work_stats_t) :: st
   type(error_t), allocatable :: err
   real(wp) :: tols(2) = [1e-12_wp, 1e-10_wp]
   integer :: k
   do i = 1, 3
      do k = 1, 2
         call trace_auto(hill_model_t(model_elastic, alphas(i), 0.0_wp, 0.0_wp), tols(k), tr, st, err)
         print "(f6.2,es9.1,a,es10.2,a,i8,a,l2)", alphas(i), tols(k), " err ", abs(tr%value - 2.0_wp)/2, " steps ", &
            st%n_steps, ' errflag ', allocated(err)
         if (allocated(err)) print *, err%message
      end do
   end do
end program

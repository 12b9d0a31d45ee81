!> The round-off floor of the hard case β = 0, α → π² (guide page *Validation*, hard cases).
!>
!> With no gravity (β = 0) the rigidly turned bounce is 2-periodic, so the exact
!> trace is S = 2 for every α; but the propagator passes through large, badly
!> conditioned values near α = π², and double precision cannot give S better than
!> about 1e-11 at α = 9.8 and 1e-10 at α = 9.86. Method auto estimates that level
!> along the way: where the tolerance lies below it, auto returns its best value
!> with `err_accuracy` instead of claiming the tolerance. This program prints, per
!> α and tolerance, the achieved error |S − 2|/2, the Magnus steps taken and
!> whether auto reported the floor. Run: `fpm run --example roundoff_floor`.
program roundoff_floor
   use hillstab, only: wp => hillstab_wp, error_t => hillstab_error_t, err_accuracy => hillstab_err_accuracy, &
      work_stats_t, elastic_model_t, hill_point_t, trace_t, trace_auto
   implicit none
   real(wp), parameter :: alphas(3) = [9.8_wp, 9.85_wp, 9.86_wp]
   real(wp), parameter :: tolerances(2) = [1.0e-12_wp, 1.0e-10_wp]
   type(trace_t) :: tr
   type(work_stats_t) :: stats
   type(error_t), allocatable :: error
   integer :: i, k
   write (*, '(a)') "# alpha   tolerance  |S-2|/2    steps  floor reported"
   do i = 1, size(alphas)
      do k = 1, size(tolerances)
         call trace_auto(elastic_model_t(), hill_point_t(alphas(i), 0.0_wp, 0.0_wp), tolerances(k), tr, stats, error)
         write (*, '(f6.2, es11.1, es11.2, i8, 2x, l1)') alphas(i), tolerances(k), abs(tr%value - 2.0_wp)/2.0_wp, &
            stats%n_steps, allocated(error)
         if (allocated(error)) then
            if (error%code /= err_accuracy) then
               write (*, '(a)') "  unexpected error: "//error%message
               error stop 1
            end if
         end if
      end do
   end do
end program roundoff_floor

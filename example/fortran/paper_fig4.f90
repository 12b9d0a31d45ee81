!> The paper's Fig. 4 points: the trace by eq. (37) beside a converged
!> segmented trace (average sampling, N = 8192 and 16384, Richardson-extrapolated)
!> and the exact trace (method auto at tolerance 1e-12), the difference between
!> eq. (37) and the converged trace, and the stability verdicts. Prints a Markdown table.
program paper_fig4
   use hillstab, only: wp => hillstab_wp, error_t => hillstab_error_t, elastic_model_t, &
      hill_point_t, sampling_average => hillstab_sampling_average, trace_t, &
      trace_two_segment_paper, floquet_t, floquet_from_trace, largest_multiplier_modulus, method_t, &
      method_auto => hillstab_method_auto, monodromy_trace, trace_segmented
   implicit none
   real(wp), parameter :: points(2, 6) = reshape([1.48_wp, 2.47_wp, 3.70_wp, 2.47_wp, 2.57_wp, 1.29_wp, &
                                                  5.0_wp, 0.76_wp, 7.88_wp, 3.95_wp, 7.48_wp, 2.47_wp], [2, 6])
   character(len=1), parameter :: labels(6) = ['a', 'b', 'c', 'd', 'e', 'g']
   type(elastic_model_t) :: elastic
   type(hill_point_t) :: point
   type(trace_t) :: paper, coarse, fine, auto
   type(floquet_t) :: f_paper, f_exact
   type(error_t), allocatable :: error
   real(wp) :: exact
   integer :: i
   write (*, '(a)') "| case | α | β | S by eq. (37) | S, 16384 pieces (Richardson) | S exact (auto, 1e-12) "// &
      "| eq. (37) − converged | eq. (37) verdict | true verdict | largest \|λ\| per period |"
   write (*, '(a)') "|---|---|---|---|---|---|---|---|---|---|"
   do i = 1, size(points, 2)
      point = hill_point_t(points(1, i), points(2, i), 0.0_wp)
      paper = trace_two_segment_paper(point%alpha, point%beta)
      coarse = trace_segmented(elastic, point, 8192, sampling_average)
      fine = trace_segmented(elastic, point, 16384, sampling_average)
      exact = (4.0_wp*fine%value - coarse%value)/3.0_wp   ! second-order error removed
      call monodromy_trace(elastic, point, method_t(method_auto, tolerance=1.0e-12_wp), auto, error)
      if (allocated(error)) error stop 1
      f_paper = floquet_from_trace(paper, 0.0_wp)
      f_exact = floquet_from_trace(auto, 0.0_wp)
      write (*, '("| (",a,") | ",f5.2," | ",f5.2," | ",f10.4," | ",f14.9," | ",f14.9," | ",f10.4," | ",a," | ",a,'// &
         '" | ",f8.4," |")') labels(i), point%alpha, point%beta, paper%value, exact, auto%value, paper%value - exact, &
         verdict(f_paper%stable), verdict(f_exact%stable), largest_multiplier_modulus(f_exact)
   end do
contains
   pure function verdict(stable) result(word)
      logical, intent(in) :: stable
      character(len=:), allocatable :: word
      if (stable) then
         word = "stable"
      else
         word = "unstable"
      end if
   end function verdict
end program paper_fig4

!> Links against an installed hillstab through its Fortran modules: the trace S at the
!> paper's Fig. 4 (c) by 4096 averaged pieces, checked against its value -1.6401.
program installed_trace
   use hillstab, only: wp => hillstab_wp, hillstab_error_t, elastic_model_t, hill_point_t, hillstab_method_segments, &
      hillstab_sampling_average, method_t, trace_t, monodromy_trace
   implicit none
   type(trace_t) :: tr
   type(hillstab_error_t), allocatable :: error
   call monodromy_trace(elastic_model_t(), hill_point_t(2.57_wp, 1.29_wp, 0.0_wp), &
      method_t(hillstab_method_segments, 4096, hillstab_sampling_average), tr, error)
   if (allocated(error)) error stop 1
   print '(a,f10.6)', "Fortran: S at case (c) = ", tr%value
   if (abs(tr%value + 1.6401_wp) > 1.0e-3_wp) error stop 1
end program installed_trace

!> Links against an installed hillstab through its Fortran modules.
program installed_trace
   use hillstab
   implicit none
   type(trace_t) :: tr
   type(error_t), allocatable :: error
   call monodromy_trace(elastic_model_t(), hill_point_t(2.57_wp, 1.29_wp, 0.0_wp), &
      method_t(method_segments, 4096, sampling_average), tr, error)
   if (allocated(error)) error stop 1
   print '(a,f10.6)', "Fortran: S at case (c) = ", tr%value
   if (abs(tr%value + 1.6401_wp) > 1.0e-3_wp) error stop 1
end program installed_trace

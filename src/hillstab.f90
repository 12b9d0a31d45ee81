!> The umbrella module of hillstab, the stability of the elastic pendulum through the Hill
!> equation x'' + Q(τ) x = 0 and Floquet theory: it re-exports the public API.
!>
!>```fortran
!> use hillstab
!> type(floquet_t) :: f
!> f = floquet_from_trace(trace_segmented(hill_model_t(model_elastic, 1.48_wp, 2.47_wp, 0.0_wp), &
!>                        256, sampling_average), 0.0_wp)
!> print *, f%trace%value, f%stable
!>```
module hillstab
   use hillstab_kinds
   use hillstab_error
   use hillstab_status
   use hillstab_stats
   use hillstab_coefficient
   use hillstab_units
   use hillstab_transfer
   use hillstab_formulas
   use hillstab_floquet
   use hillstab_magnus
   use hillstab_auto
   use hillstab_monodromy
   use hillstab_gsl
   use hillstab_hill_method
   use hillstab_rk
   use hillstab_monodromy_rk
   use hillstab_refine
   use hillstab_pendulum
   use hillstab_pendulum_analysis
   use hillstab_lyapunov
   use hillstab_gsl_lyapunov
   use hillstab_poincare
   use hillstab_scene
   use hillstab_output
   use hillstab_tasks
   use hillstab_task_series
   implicit none
   public
end module hillstab

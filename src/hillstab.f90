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
   use hillstab_core_kinds
   use hillstab_core_error
   use hillstab_core_status
   use hillstab_core_stats
   use hillstab_hill_coefficient
   use hillstab_hill_units
   use hillstab_hill_transfer
   use hillstab_hill_formulas
   use hillstab_hill_floquet
   use hillstab_integrate_magnus
   use hillstab_integrate_auto
   use hillstab_integrate_monodromy
   use hillstab_integrate_gsl
   use hillstab_curves_hill_method
   use hillstab_integrate_rk
   use hillstab_integrate_monodromy_rk
   use hillstab_integrate_refine
   use hillstab_pendulum_equations
   use hillstab_pendulum_analysis
   use hillstab_pendulum_lyapunov
   use hillstab_pendulum_gsl_lyapunov
   use hillstab_pendulum_poincare
   use hillstab_pendulum_symplectic
   use hillstab_pendulum_chaos
   use hillstab_batch_scene
   use hillstab_batch_output
   use hillstab_batch_tasks
   use hillstab_batch_task_series
   implicit none
   public
end module hillstab

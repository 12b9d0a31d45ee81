!> The umbrella module of hillstab, the stability of the elastic pendulum through the Hill
!> equation x'' + Q(τ) x = 0 and Floquet theory: it re-exports the public API.
module hillstab
   use hillstab_core_kinds
   use hillstab_core_error
   use hillstab_core_status
   use hillstab_core_stats
   use hillstab_hill_models
   use hillstab_hill_coefficient
   use hillstab_hill_units
   use hillstab_hill_transfer
   use hillstab_hill_formulas
   use hillstab_hill_floquet
   use hillstab_integrate_magnus
   use hillstab_integrate_auto
   use hillstab_integrate_segments
   use hillstab_integrate_monodromy
   use hillstab_integrate_monodromy_gsl
   use hillstab_hill_mathieu
   use hillstab_curves_hill_method
   use hillstab_integrate_rk
   use hillstab_integrate_monodromy_rk
   use hillstab_integrate_refine
   use hillstab_pendulum_equations
   use hillstab_pendulum_analysis
   use hillstab_pendulum_lyapunov
   use hillstab_pendulum_gsl_lyapunov
   use hillstab_pendulum_poincare
   implicit none
   public
end module hillstab

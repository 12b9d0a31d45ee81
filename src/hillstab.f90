!> The umbrella module of hillstab, the stability of the elastic pendulum through the Hill
!> equation x'' + Q(τ) x = 0 and Floquet theory: it re-exports the library's numerical
!> API — the models of Q, the exact transfer matrices and the paper's closed forms, the
!> monodromy methods and their one entry point, Floquet multipliers and verdicts, physical
!> units, the transition curves, and the nonlinear pendulum. The batch program's modules
!> (scenes, tasks, output files: `hillstab_batch_*`) are not part of it; programs that run
!> scenes use them by name.
!>
!>```fortran
!> use hillstab
!> type(floquet_t) :: f
!> f = floquet_from_trace(trace_segmented(hill_model_t(model_elastic, 1.48_wp, 2.47_wp, 0.0_wp), &
!>                        256, sampling_average), 0.0_wp)
!> print *, f%trace%value, f%stable
!>```
module hillstab
   use hillstab_core_kinds, only: wp, int64, pi, pi2, version_string
   use hillstab_core_error, only: error_t, set_error, error_code_name, err_invalid_parameter, err_overflow, &
      err_integration, err_io, err_input, err_singular, err_accuracy, err_points_failed
   use hillstab_core_status, only: status_ok, status_roundoff, status_failed, status_name
   use hillstab_core_stats, only: work_stats_t
   use hillstab_hill_models, only: hill_model_t, model_elastic, model_mathieu, model_name, model_from_name, &
      model_names_text, model_description, model_is_pendulum, check_model, hill_coefficient, segment_average, &
      damping_shift
   use hillstab_hill_coefficient, only: sampling_endpoint, sampling_midpoint, sampling_average, sampling_name, &
      sampling_from_name, segment_coefficients, hill_period, in_physical_domain
   use hillstab_hill_units, only: physical_t, standard_gravity, equilibrium_length, physical_alpha, physical_beta, &
      physical_epsilon, physical_nu, check_physical, physical_from_dimensionless, rate_per_second, tau_from_time, &
      time_from_tau
   use hillstab_hill_transfer, only: trace_t, transfer_matrix, scaled_matrix_t, trace_of, trace_from_value, &
      matrix_of, determinant
   use hillstab_hill_formulas, only: trace_two_segment_paper, trace_damped_paper, trace_mathieu_two_segment
   use hillstab_hill_floquet, only: floquet_t, floquet_from_trace, floquet_from_value, multipliers, &
      largest_multiplier_modulus
   use hillstab_hill_mathieu, only: mathieu_a, mathieu_b, mathieu_transition_beta
   use hillstab_integrate_monodromy, only: method_t, method_auto, method_formula, method_segments, method_magnus4, &
      method_magnus6, method_rk, method_gsl, method_name, method_from_name, method_names_text, method_is_exact, &
      monodromy_trace, monodromy_trace_batch, monodromy_segmented, trace_segmented, swing_monodromy
   use hillstab_integrate_auto, only: trace_auto, trace_auto_batch
   use hillstab_integrate_magnus, only: trace_magnus, monodromy_magnus
   use hillstab_integrate_monodromy_rk, only: trace_rk, monodromy_rk
   use hillstab_integrate_monodromy_gsl, only: trace_gsl, monodromy_gsl
   use hillstab_integrate_rk, only: rk_system_t, rk_options_t, rk_step_t, rk_integrate, rk_dense_value, rk_dopri5, &
      rk_dop853, rk_pd87, rk_vern98, rk_method_name
   use hillstab_curves_hill_method, only: hill_boundary_t, hill_boundaries, hill_block_eigenvalues
   use hillstab_curves_boundaries, only: boundary_check_t, verify_boundary, approximate_root_t, approximate_boundaries, &
      unstable_intervals_from_roots
   use hillstab_pendulum_equations, only: pendulum_t, pendulum_from_chart, pendulum_initial_state, pendulum_energy, &
      pendulum_angle, pendulum_radius, pendulum_bounce, pendulum_system_t
   use hillstab_pendulum_analysis, only: bounce_multipliers_t, bounce_multipliers, onset_periods, pendulum_watch_t, &
      pendulum_integrate
   use hillstab_pendulum_lyapunov, only: lyapunov_t, lyapunov_largest
   use hillstab_pendulum_poincare, only: section_t, poincare_section
   use hillstab_pendulum_symplectic, only: symplectic_scheme_t, symplectic_scheme, symplectic_scheme_name, &
      symplectic_scheme_id, symplectic_leapfrog, symplectic_yoshida4, symplectic_yoshida6, symplectic_blanes_moan4, &
      symplectic_blanes_moan6, symplectic_mclachlan8, symplectic_scheme_count
   use hillstab_pendulum_chaos, only: chaos_options_t, chaos_t, chaos_indicators, chaos_indicators_batch, &
      chaos_verdict, chaos_integrator_name, chaos_integrator_id, chaos_method_text, chaos_verdict_rule, chaos_auto, &
      chaos_symplectic, chaos_dop853
   use hillstab_pendulum_gsl, only: pendulum_gsl
   use hillstab_pendulum_gsl_lyapunov, only: lyapunov_largest_gsl
   implicit none
   public
end module hillstab

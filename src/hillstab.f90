!> The umbrella module of hillstab, the stability of the elastic pendulum through the Hill
!> equation x'' + Q(τ) x = 0 and Floquet theory: it re-exports the library's numerical
!> API — the models of Q, the exact transfer matrices and the paper's closed forms, the
!> monodromy methods and their one entry point, Floquet multipliers and verdicts, physical
!> units, the transition curves, and the nonlinear pendulum. The batch program's modules
!> (scenes, tasks, output files: `hillstab_batch_*`) are not part of it; programs that run
!> scenes use them by name.
!>
!> **What it exports.**
!>
!> Each name links to its entry; the guide page [The public API](../page/api.html)
!> gives the first doc line of each. Written by `scripts/api_page.py`.
!>
!> - [[hillstab_core_kinds]]: `hillstab_wp`, `hillstab_int64`, `hillstab_pi` = [[hillstab_core_kinds:pi]],
!>   `hillstab_pi2` = [[hillstab_core_kinds:pi2]],
!>   `hillstab_version_string` = [[hillstab_core_kinds:version_string]]
!> - [[hillstab_core_error]]: `hillstab_error_t` = [[hillstab_core_error:error_t]],
!>   `hillstab_set_error` = [[hillstab_core_error:set_error]], [[hillstab_core_error:error_code_name]],
!>   `hillstab_err_invalid_parameter` = [[hillstab_core_error:err_invalid_parameter]],
!>   `hillstab_err_overflow` = [[hillstab_core_error:err_overflow]],
!>   `hillstab_err_integration` = [[hillstab_core_error:err_integration]],
!>   `hillstab_err_io` = [[hillstab_core_error:err_io]],
!>   `hillstab_err_input` = [[hillstab_core_error:err_input]],
!>   `hillstab_err_singular` = [[hillstab_core_error:err_singular]],
!>   `hillstab_err_accuracy` = [[hillstab_core_error:err_accuracy]],
!>   `hillstab_err_points_failed` = [[hillstab_core_error:err_points_failed]]
!> - [[hillstab_core_status]]: `hillstab_status_ok` = [[hillstab_core_status:status_ok]],
!>   `hillstab_status_roundoff` = [[hillstab_core_status:status_roundoff]],
!>   `hillstab_status_failed` = [[hillstab_core_status:status_failed]],
!>   `hillstab_status_name` = [[hillstab_core_status:status_name]]
!> - [[hillstab_core_stats]]: [[hillstab_core_stats:work_stats_t]]
!> - [[hillstab_hill_model]]: [[hillstab_hill_model:hill_model_t]], [[hillstab_hill_model:hill_point_t]],
!>   [[hillstab_hill_model:hill_window_t]], [[hillstab_hill_model:model_description]],
!>   [[hillstab_hill_model:check_point]], [[hillstab_hill_model:check_alpha]],
!>   [[hillstab_hill_model:hill_coefficient]], [[hillstab_hill_model:segment_average]],
!>   [[hillstab_hill_model:model_split]], [[hillstab_hill_model:damping_shift]],
!>   [[hillstab_hill_model:damping_at]]
!> - [[hillstab_hill_models]]: `hillstab_model_names` = [[hillstab_hill_models:model_names]],
!>   `hillstab_model_count` = [[hillstab_hill_models:model_count]], [[hillstab_hill_models:new_model]],
!>   [[hillstab_hill_models:model_from_code]], [[hillstab_hill_models:model_code]],
!>   [[hillstab_hill_models:model_names_text]]
!> - [[hillstab_hill_model_pendulum]]: [[hillstab_hill_model_pendulum:pendulum_model_t]],
!>   [[hillstab_hill_model_pendulum:pendulum_alpha]], [[hillstab_hill_model_pendulum:pendulum_note]],
!>   [[hillstab_hill_model_pendulum:is_elastic_pendulum]]
!> - [[hillstab_hill_model_elastic]]: [[hillstab_hill_model_elastic:elastic_model_t]]
!> - [[hillstab_hill_model_mathieu]]: [[hillstab_hill_model_mathieu:mathieu_model_t]]
!> - [[hillstab_hill_model_meissner]]: [[hillstab_hill_model_meissner:meissner_model_t]]
!> - [[hillstab_hill_model_base]]: [[hillstab_hill_model_base:model_base_t]]
!> - [[hillstab_hill_system]]: [[hillstab_hill_system:hill_system_t]], [[hillstab_hill_system:system_form_t]],
!>   [[hillstab_hill_system:prepare_system]], `hillstab_max_dof` = [[hillstab_hill_system:max_dof]]
!> - [[hillstab_hill_system_matrix]]: [[hillstab_hill_system_matrix:matrix_system_t]]
!> - [[hillstab_hill_system_scalar]]: [[hillstab_hill_system_scalar:scalar_system_t]]
!> - [[hillstab_hill_systems]]: `hillstab_system_names` = [[hillstab_hill_systems:system_names]],
!>   [[hillstab_hill_systems:new_system]]
!> - [[hillstab_hill_system_floquet]]: [[hillstab_hill_system_floquet:system_floquet]]
!> - [[hillstab_hill_coefficient]]:
!>   `hillstab_sampling_endpoint` = [[hillstab_hill_coefficient:sampling_endpoint]],
!>   `hillstab_sampling_midpoint` = [[hillstab_hill_coefficient:sampling_midpoint]],
!>   `hillstab_sampling_average` = [[hillstab_hill_coefficient:sampling_average]],
!>   `hillstab_sampling_name` = [[hillstab_hill_coefficient:sampling_name]],
!>   [[hillstab_hill_coefficient:sampling_from_name]], [[hillstab_hill_coefficient:segment_coefficients]],
!>   [[hillstab_hill_model_elastic:in_physical_domain]]
!> - [[hillstab_hill_units]]: [[hillstab_hill_units:physical_t]],
!>   `hillstab_standard_gravity` = [[hillstab_hill_units:standard_gravity]],
!>   [[hillstab_hill_units:equilibrium_length]], [[hillstab_hill_units:physical_alpha]],
!>   [[hillstab_hill_units:physical_beta]], [[hillstab_hill_units:physical_epsilon]],
!>   [[hillstab_hill_units:physical_nu]], [[hillstab_hill_units:check_physical]],
!>   [[hillstab_hill_units:physical_from_dimensionless]], [[hillstab_hill_units:rate_per_second]],
!>   [[hillstab_hill_units:tau_from_time]], [[hillstab_hill_units:time_from_tau]]
!> - [[hillstab_hill_transfer]]: [[hillstab_hill_transfer:trace_t]],
!>   [[hillstab_hill_transfer:transfer_matrix]], [[hillstab_hill_transfer:scaled_matrix_t]],
!>   `hillstab_trace_of` = [[hillstab_hill_transfer:trace_of]], [[hillstab_hill_transfer:trace_from_value]],
!>   `hillstab_matrix_of` = [[hillstab_hill_transfer:matrix_of]],
!>   `hillstab_determinant` = [[hillstab_hill_transfer:determinant]]
!> - [[hillstab_hill_formulas]]: [[hillstab_hill_formulas:trace_two_segment_paper]],
!>   [[hillstab_hill_formulas:trace_damped_paper]], [[hillstab_hill_formulas:trace_mathieu_two_segment]]
!> - [[hillstab_hill_floquet]]: [[hillstab_hill_floquet:floquet_t]],
!>   [[hillstab_hill_floquet:floquet_from_trace]], [[hillstab_hill_floquet:floquet_from_value]],
!>   `hillstab_multipliers` = [[hillstab_hill_floquet:multipliers]],
!>   [[hillstab_hill_floquet:largest_multiplier_modulus]],
!>   `hillstab_verdict_stable` = [[hillstab_hill_floquet:verdict_stable]],
!>   `hillstab_verdict_unstable` = [[hillstab_hill_floquet:verdict_unstable]],
!>   `hillstab_verdict_marginal` = [[hillstab_hill_floquet:verdict_marginal]],
!>   `hillstab_kind_stable` = [[hillstab_hill_floquet:kind_stable]],
!>   `hillstab_kind_plus_one` = [[hillstab_hill_floquet:kind_plus_one]],
!>   `hillstab_kind_minus_one` = [[hillstab_hill_floquet:kind_minus_one]],
!>   `hillstab_kind_combination` = [[hillstab_hill_floquet:kind_combination]],
!>   `hillstab_kind_damped` = [[hillstab_hill_floquet:kind_damped]],
!>   `hillstab_kind_undecided` = [[hillstab_hill_floquet:kind_undecided]]
!> - [[hillstab_hill_mathieu]]: [[hillstab_hill_mathieu:mathieu_a]], [[hillstab_hill_mathieu:mathieu_b]],
!>   [[hillstab_hill_mathieu:mathieu_transition_beta]]
!> - [[hillstab_integrate_monodromy]]: [[hillstab_integrate_monodromy:method_t]],
!>   `hillstab_method_auto` = [[hillstab_integrate_monodromy:method_auto]],
!>   `hillstab_method_formula` = [[hillstab_integrate_monodromy:method_formula]],
!>   `hillstab_method_segments` = [[hillstab_integrate_monodromy:method_segments]],
!>   `hillstab_method_magnus4` = [[hillstab_integrate_monodromy:method_magnus4]],
!>   `hillstab_method_magnus6` = [[hillstab_integrate_monodromy:method_magnus6]],
!>   `hillstab_method_rk` = [[hillstab_integrate_monodromy:method_rk]],
!>   `hillstab_method_gsl` = [[hillstab_integrate_monodromy:method_gsl]],
!>   `hillstab_method_name` = [[hillstab_integrate_monodromy:method_name]],
!>   [[hillstab_integrate_monodromy:method_from_name]], [[hillstab_integrate_monodromy:method_names_text]],
!>   [[hillstab_integrate_monodromy:method_is_exact]], [[hillstab_integrate_monodromy:monodromy_trace]],
!>   [[hillstab_integrate_monodromy:monodromy_trace_batch]],
!>   [[hillstab_integrate_segments:monodromy_segmented]], [[hillstab_integrate_segments:trace_segmented]],
!>   [[hillstab_integrate_monodromy:swing_monodromy]]
!> - [[hillstab_integrate_auto]]: [[hillstab_integrate_auto:trace_auto]],
!>   [[hillstab_integrate_auto:trace_auto_batch]]
!> - [[hillstab_integrate_magnus]]: [[hillstab_integrate_magnus:trace_magnus]],
!>   [[hillstab_integrate_magnus:monodromy_magnus]]
!> - [[hillstab_integrate_monodromy_rk]]: [[hillstab_integrate_monodromy_rk:trace_rk]],
!>   [[hillstab_integrate_monodromy_rk:monodromy_rk]]
!> - [[hillstab_integrate_monodromy_gsl]]: [[hillstab_integrate_monodromy_gsl:trace_gsl]],
!>   [[hillstab_integrate_monodromy_gsl:monodromy_gsl]]
!> - [[hillstab_integrate_system]]: [[hillstab_integrate_monodromy:system_method_t]],
!>   [[hillstab_integrate_system_magnus:system_monodromy_t]],
!>   [[hillstab_integrate_system_magnus:system_nodes_t]], [[hillstab_integrate_monodromy:system_monodromy]],
!>   `hillstab_system_auto` = [[hillstab_integrate_system:system_auto]],
!>   `hillstab_system_magnus4` = [[hillstab_integrate_system:system_magnus4]],
!>   `hillstab_system_magnus6` = [[hillstab_integrate_system:system_magnus6]],
!>   `hillstab_system_rk` = [[hillstab_integrate_system:system_rk]],
!>   `hillstab_system_gsl` = [[hillstab_integrate_system:system_gsl]]
!> - [[hillstab_integrate_rk]]: [[hillstab_integrate_rk_stages:rk_system_t]],
!>   [[hillstab_integrate_rk:rk_options_t]], [[hillstab_integrate_rk_stages:rk_step_t]],
!>   [[hillstab_integrate_rk:rk_integrate]], [[hillstab_integrate_rk:rk_dense_value]],
!>   `hillstab_rk_dopri5` = [[hillstab_integrate_rk_tableaux:rk_dopri5]],
!>   `hillstab_rk_dop853` = [[hillstab_integrate_rk_tableaux:rk_dop853]],
!>   `hillstab_rk_pd87` = [[hillstab_integrate_rk_tableaux:rk_pd87]],
!>   `hillstab_rk_vern98` = [[hillstab_integrate_rk_tableaux:rk_vern98]],
!>   [[hillstab_integrate_rk_tableaux:rk_method_name]]
!> - [[hillstab_curves_hill_method]]: [[hillstab_curves_hill_method:hill_boundary_t]],
!>   [[hillstab_curves_hill_method:hill_boundaries]], [[hillstab_curves_hill_method:hill_block_eigenvalues]]
!> - [[hillstab_curves_boundaries]]: [[hillstab_curves_boundaries:boundary_check_t]],
!>   [[hillstab_curves_boundaries:verify_boundary]], [[hillstab_curves_boundaries:approximate_root_t]],
!>   [[hillstab_curves_boundaries:approximate_boundaries]],
!>   [[hillstab_curves_boundaries:unstable_intervals_from_roots]], [[hillstab_curves_boundaries:curve_route]],
!>   [[hillstab_curves_boundaries:exact_boundaries]]
!> - [[hillstab_curves_hill_fourier]]: [[hillstab_curves_hill_fourier:fourier_boundaries]]
!> - [[hillstab_curves_characteristic]]: [[hillstab_curves_characteristic:characteristic_values]]
!> - [[hillstab_curves_critical]]: [[hillstab_curves_critical:critical_drive_t]],
!>   [[hillstab_curves_critical:critical_drives]], [[hillstab_curves_critical:critical_drives_along]],
!>   `hillstab_along_alpha` = [[hillstab_curves_critical:along_alpha]],
!>   `hillstab_along_beta` = [[hillstab_curves_critical:along_beta]]
!> - [[hillstab_curves_system_boundaries]]: [[hillstab_curves_system_boundaries:system_boundary_t]],
!>   [[hillstab_curves_system_boundaries:system_boundaries]]
!> - [[hillstab_curves_oracle]]: [[hillstab_curves_oracle:oracle_t]],
!>   [[hillstab_curves_oracle:oracle_sample_t]], [[hillstab_curves_oracle:scalar_oracle_t]],
!>   [[hillstab_curves_oracle:system_oracle_t]]
!> - [[hillstab_curves_regions]]: [[hillstab_curves_regions:region_t]],
!>   [[hillstab_curves_regions:predict_regions]], [[hillstab_curves_regions:find_regions]],
!>   [[hillstab_curves_regions:region_kind_name]], [[hillstab_curves_regions:region_status_name]],
!>   `hillstab_region_simple` = [[hillstab_curves_regions:region_simple]],
!>   `hillstab_region_sum` = [[hillstab_curves_regions:region_sum]],
!>   `hillstab_region_difference` = [[hillstab_curves_regions:region_difference]],
!>   `hillstab_region_found` = [[hillstab_curves_regions:region_found]],
!>   `hillstab_region_closed` = [[hillstab_curves_regions:region_closed]],
!>   `hillstab_region_unconfirmed` = [[hillstab_curves_regions:region_unconfirmed]],
!>   `hillstab_region_open_below` = [[hillstab_curves_regions:region_open_below]],
!>   `hillstab_region_theory` = [[hillstab_curves_regions:region_theory]],
!>   `hillstab_region_same_signature` = [[hillstab_curves_regions:region_same_signature]],
!>   `hillstab_region_uncovered` = [[hillstab_curves_regions:region_uncovered]],
!>   `hillstab_region_unassigned` = [[hillstab_curves_regions:region_unassigned]],
!>   `hillstab_max_region_order` = [[hillstab_curves_regions:max_region_order]]
!> - [[hillstab_curves_region_edges]]: [[hillstab_curves_region_edges:edge_point_t]],
!>   [[hillstab_curves_region_edges:trace_edges]], [[hillstab_curves_region_edges:edge_status_name]],
!>   `hillstab_edge_boundary` = [[hillstab_curves_region_edges:edge_boundary]],
!>   `hillstab_edge_overlap` = [[hillstab_curves_region_edges:edge_overlap]],
!>   `hillstab_edge_unconfirmed` = [[hillstab_curves_region_edges:edge_unconfirmed]],
!>   `hillstab_edge_range_end` = [[hillstab_curves_region_edges:edge_range_end]],
!>   `hillstab_edge_tip` = [[hillstab_curves_region_edges:edge_tip]]
!> - [[hillstab_pendulum_equations]]: [[hillstab_pendulum_equations:pendulum_t]],
!>   [[hillstab_pendulum_equations:pendulum_from_chart]],
!>   [[hillstab_pendulum_equations:pendulum_initial_state]], [[hillstab_pendulum_equations:pendulum_energy]],
!>   [[hillstab_pendulum_equations:pendulum_angle]], [[hillstab_pendulum_equations:pendulum_radius]],
!>   [[hillstab_pendulum_equations:pendulum_bounce]], [[hillstab_pendulum_equations:pendulum_system_t]]
!> - [[hillstab_pendulum_analysis]]: [[hillstab_pendulum_analysis:bounce_multipliers_t]],
!>   [[hillstab_pendulum_analysis:bounce_multipliers]], [[hillstab_pendulum_analysis:onset_periods]],
!>   [[hillstab_pendulum_analysis:pendulum_watch_t]], [[hillstab_pendulum_analysis:pendulum_integrate]]
!> - [[hillstab_pendulum_lyapunov]]: [[hillstab_pendulum_lyapunov:lyapunov_t]],
!>   [[hillstab_pendulum_lyapunov:lyapunov_largest]]
!> - [[hillstab_pendulum_poincare]]: [[hillstab_pendulum_poincare:section_t]],
!>   [[hillstab_pendulum_poincare:poincare_section]]
!> - [[hillstab_pendulum_symplectic]]: [[hillstab_pendulum_symplectic:symplectic_scheme_t]],
!>   [[hillstab_pendulum_symplectic:symplectic_scheme]],
!>   [[hillstab_pendulum_symplectic:symplectic_scheme_name]],
!>   [[hillstab_pendulum_symplectic:symplectic_scheme_id]],
!>   `hillstab_symplectic_leapfrog` = [[hillstab_pendulum_symplectic:symplectic_leapfrog]],
!>   `hillstab_symplectic_yoshida4` = [[hillstab_pendulum_symplectic:symplectic_yoshida4]],
!>   `hillstab_symplectic_yoshida6` = [[hillstab_pendulum_symplectic:symplectic_yoshida6]],
!>   `hillstab_symplectic_blanes_moan4` = [[hillstab_pendulum_symplectic:symplectic_blanes_moan4]],
!>   `hillstab_symplectic_blanes_moan6` = [[hillstab_pendulum_symplectic:symplectic_blanes_moan6]],
!>   `hillstab_symplectic_mclachlan8` = [[hillstab_pendulum_symplectic:symplectic_mclachlan8]],
!>   `hillstab_symplectic_scheme_count` = [[hillstab_pendulum_symplectic:symplectic_scheme_count]]
!> - [[hillstab_pendulum_chaos]]: [[hillstab_pendulum_chaos_track:chaos_options_t]],
!>   [[hillstab_pendulum_chaos:chaos_t]], [[hillstab_pendulum_chaos:chaos_indicators]],
!>   [[hillstab_pendulum_chaos:chaos_indicators_batch]], [[hillstab_pendulum_chaos_track:chaos_verdict]],
!>   [[hillstab_pendulum_chaos:chaos_integrator_name]], [[hillstab_pendulum_chaos:chaos_integrator_id]],
!>   [[hillstab_pendulum_chaos:chaos_method_text]], [[hillstab_pendulum_chaos_track:chaos_verdict_rule]],
!>   `hillstab_chaos_auto` = [[hillstab_pendulum_chaos_track:chaos_auto]],
!>   `hillstab_chaos_symplectic` = [[hillstab_pendulum_chaos_track:chaos_symplectic]],
!>   `hillstab_chaos_dop853` = [[hillstab_pendulum_chaos_track:chaos_dop853]]
!> - [[hillstab_pendulum_gsl]]: [[hillstab_pendulum_gsl:pendulum_gsl]]
!> - [[hillstab_pendulum_gsl_lyapunov]]: [[hillstab_pendulum_gsl_lyapunov:lyapunov_largest_gsl]]
!>
!> (end of the exports)
!>
!> Every constant and every name a program might also define (`pi`, `wp`, `error_t`,
!> `determinant`, ...) carries the prefix `hillstab_` here; the modules that define them
!> keep the short names. Take what a program needs, under names of its choosing:
!>
!>```fortran
!> use hillstab, only: wp => hillstab_wp, elastic_model_t, hill_point_t, hillstab_sampling_average, &
!>                     floquet_t, floquet_from_trace, trace_segmented
!> type(floquet_t) :: f
!> f = floquet_from_trace(trace_segmented(elastic_model_t(), hill_point_t(1.48_wp, 2.47_wp, 0.0_wp), &
!>                        256, hillstab_sampling_average), 0.0_wp)
!> print *, f%trace%value, f%stable
!>```
module hillstab
   use hillstab_core_kinds, only: hillstab_wp => wp, hillstab_int64 => int64, hillstab_pi => pi, &
      hillstab_pi2 => pi2, hillstab_version_string => version_string
   use hillstab_core_error, only: hillstab_error_t => error_t, hillstab_set_error => set_error, error_code_name, &
      hillstab_err_invalid_parameter => err_invalid_parameter, hillstab_err_overflow => err_overflow, &
      hillstab_err_integration => err_integration, hillstab_err_io => err_io, hillstab_err_input => err_input, &
      hillstab_err_singular => err_singular, hillstab_err_accuracy => err_accuracy, &
      hillstab_err_points_failed => err_points_failed
   use hillstab_core_status, only: hillstab_status_ok => status_ok, hillstab_status_roundoff => status_roundoff, &
      hillstab_status_failed => status_failed, hillstab_status_name => status_name
   use hillstab_core_stats, only: work_stats_t
   use hillstab_hill_model, only: hill_model_t, hill_point_t, hill_window_t, model_description, check_point, &
      check_alpha, hill_coefficient, segment_average, model_split, damping_shift, damping_at
   use hillstab_hill_models, only: hillstab_model_names => model_names, hillstab_model_count => model_count, &
      new_model, model_from_code, model_code, model_names_text
   use hillstab_hill_model_pendulum, only: pendulum_model_t, pendulum_alpha, pendulum_note, is_elastic_pendulum
   use hillstab_hill_model_elastic, only: elastic_model_t
   use hillstab_hill_model_mathieu, only: mathieu_model_t
   use hillstab_hill_model_meissner, only: meissner_model_t
   use hillstab_hill_model_base, only: model_base_t
   use hillstab_hill_system, only: hill_system_t, system_form_t, prepare_system, hillstab_max_dof => max_dof
   use hillstab_hill_system_matrix, only: matrix_system_t
   use hillstab_hill_system_scalar, only: scalar_system_t
   use hillstab_hill_systems, only: hillstab_system_names => system_names, new_system
   use hillstab_hill_system_floquet, only: system_floquet
   use hillstab_hill_coefficient, only: hillstab_sampling_endpoint => sampling_endpoint, &
      hillstab_sampling_midpoint => sampling_midpoint, hillstab_sampling_average => sampling_average, &
      hillstab_sampling_name => sampling_name, sampling_from_name, segment_coefficients, in_physical_domain
   use hillstab_hill_units, only: physical_t, hillstab_standard_gravity => standard_gravity, equilibrium_length, &
      physical_alpha, physical_beta, physical_epsilon, physical_nu, check_physical, physical_from_dimensionless, &
      rate_per_second, tau_from_time, time_from_tau
   use hillstab_hill_transfer, only: trace_t, transfer_matrix, scaled_matrix_t, hillstab_trace_of => trace_of, &
      trace_from_value, hillstab_matrix_of => matrix_of, hillstab_determinant => determinant
   use hillstab_hill_formulas, only: trace_two_segment_paper, trace_damped_paper, trace_mathieu_two_segment
   use hillstab_hill_floquet, only: floquet_t, floquet_from_trace, floquet_from_value, &
      hillstab_multipliers => multipliers, largest_multiplier_modulus, &
      hillstab_verdict_stable => verdict_stable, hillstab_verdict_unstable => verdict_unstable, &
      hillstab_verdict_marginal => verdict_marginal, hillstab_kind_stable => kind_stable, &
      hillstab_kind_plus_one => kind_plus_one, hillstab_kind_minus_one => kind_minus_one, &
      hillstab_kind_combination => kind_combination, hillstab_kind_damped => kind_damped, &
      hillstab_kind_undecided => kind_undecided
   use hillstab_hill_mathieu, only: mathieu_a, mathieu_b, mathieu_transition_beta
   use hillstab_integrate_monodromy, only: method_t, hillstab_method_auto => method_auto, &
      hillstab_method_formula => method_formula, hillstab_method_segments => method_segments, &
      hillstab_method_magnus4 => method_magnus4, hillstab_method_magnus6 => method_magnus6, &
      hillstab_method_rk => method_rk, hillstab_method_gsl => method_gsl, hillstab_method_name => method_name, &
      method_from_name, method_names_text, method_is_exact, monodromy_trace, monodromy_trace_batch, &
      monodromy_segmented, trace_segmented, swing_monodromy
   use hillstab_integrate_auto, only: trace_auto, trace_auto_batch
   use hillstab_integrate_magnus, only: trace_magnus, monodromy_magnus
   use hillstab_integrate_monodromy_rk, only: trace_rk, monodromy_rk
   use hillstab_integrate_monodromy_gsl, only: trace_gsl, monodromy_gsl
   use hillstab_integrate_system, only: system_method_t, system_monodromy_t, system_nodes_t, system_monodromy, &
      hillstab_system_auto => system_auto, hillstab_system_magnus4 => system_magnus4, &
      hillstab_system_magnus6 => system_magnus6, hillstab_system_rk => system_rk, &
      hillstab_system_gsl => system_gsl
   use hillstab_integrate_rk, only: rk_system_t, rk_options_t, rk_step_t, rk_integrate, rk_dense_value, &
      hillstab_rk_dopri5 => rk_dopri5, hillstab_rk_dop853 => rk_dop853, hillstab_rk_pd87 => rk_pd87, &
      hillstab_rk_vern98 => rk_vern98, rk_method_name
   use hillstab_curves_hill_method, only: hill_boundary_t, hill_boundaries, hill_block_eigenvalues
   use hillstab_curves_boundaries, only: boundary_check_t, verify_boundary, approximate_root_t, approximate_boundaries, &
      unstable_intervals_from_roots, curve_route, exact_boundaries
   use hillstab_curves_hill_fourier, only: fourier_boundaries
   use hillstab_curves_characteristic, only: characteristic_values
   use hillstab_curves_critical, only: critical_drive_t, critical_drives, critical_drives_along, &
      hillstab_along_alpha => along_alpha, hillstab_along_beta => along_beta
   use hillstab_curves_system_boundaries, only: system_boundary_t, system_boundaries
   use hillstab_curves_oracle, only: oracle_t, oracle_sample_t, scalar_oracle_t, system_oracle_t
   use hillstab_curves_regions, only: region_t, predict_regions, find_regions, region_kind_name, region_status_name, &
      hillstab_region_simple => region_simple, hillstab_region_sum => region_sum, &
      hillstab_region_difference => region_difference, hillstab_region_found => region_found, &
      hillstab_region_closed => region_closed, hillstab_region_unconfirmed => region_unconfirmed, &
      hillstab_region_open_below => region_open_below, hillstab_region_theory => region_theory, &
      hillstab_region_same_signature => region_same_signature, hillstab_region_uncovered => region_uncovered, &
      hillstab_region_unassigned => region_unassigned, hillstab_max_region_order => max_region_order
   use hillstab_curves_region_edges, only: edge_point_t, trace_edges, edge_status_name, &
      hillstab_edge_boundary => edge_boundary, hillstab_edge_overlap => edge_overlap, &
      hillstab_edge_unconfirmed => edge_unconfirmed, hillstab_edge_range_end => edge_range_end, &
      hillstab_edge_tip => edge_tip
   use hillstab_pendulum_equations, only: pendulum_t, pendulum_from_chart, pendulum_initial_state, pendulum_energy, &
      pendulum_angle, pendulum_radius, pendulum_bounce, pendulum_system_t
   use hillstab_pendulum_analysis, only: bounce_multipliers_t, bounce_multipliers, onset_periods, pendulum_watch_t, &
      pendulum_integrate
   use hillstab_pendulum_lyapunov, only: lyapunov_t, lyapunov_largest
   use hillstab_pendulum_poincare, only: section_t, poincare_section
   use hillstab_pendulum_symplectic, only: symplectic_scheme_t, symplectic_scheme, symplectic_scheme_name, &
      symplectic_scheme_id, hillstab_symplectic_leapfrog => symplectic_leapfrog, &
      hillstab_symplectic_yoshida4 => symplectic_yoshida4, hillstab_symplectic_yoshida6 => symplectic_yoshida6, &
      hillstab_symplectic_blanes_moan4 => symplectic_blanes_moan4, &
      hillstab_symplectic_blanes_moan6 => symplectic_blanes_moan6, &
      hillstab_symplectic_mclachlan8 => symplectic_mclachlan8, &
      hillstab_symplectic_scheme_count => symplectic_scheme_count
   use hillstab_pendulum_chaos, only: chaos_options_t, chaos_t, chaos_indicators, chaos_indicators_batch, &
      chaos_verdict, chaos_integrator_name, chaos_integrator_id, chaos_method_text, chaos_verdict_rule, &
      hillstab_chaos_auto => chaos_auto, hillstab_chaos_symplectic => chaos_symplectic, &
      hillstab_chaos_dop853 => chaos_dop853
   use hillstab_pendulum_gsl, only: pendulum_gsl
   use hillstab_pendulum_gsl_lyapunov, only: lyapunov_largest_gsl
   implicit none
   public
end module hillstab

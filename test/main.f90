!> Test driver: `fpm test [-- SUITE [TEST]]`. Exits non-zero on any failure.
program tester
   use hillstab_testing, only: testsuite_t, run_testsuites
   use test_coefficient, only: collect_coefficient
   use test_models, only: collect_models
   use test_model_meissner, only: collect_model_meissner
   use test_model_fourier, only: collect_model_fourier
   use test_model_modulated, only: collect_model_modulated
   use test_system, only: collect_system
   use test_system_point, only: collect_system_point
   use test_system_boundaries, only: collect_system_boundaries
   use test_task_system, only: collect_task_system
   use test_codes, only: collect_codes
   use test_transfer, only: collect_transfer
   use test_formulas, only: collect_formulas
   use test_floquet, only: collect_floquet
   use test_monodromy, only: collect_monodromy
   use test_capi, only: collect_capi
   use test_capi_batch, only: collect_capi_batch
   use test_capi_system, only: collect_capi_system
   use test_capi_sizes, only: collect_capi_sizes
   use test_capi_system_batch, only: collect_capi_system_batch
   use test_capi_regions, only: collect_capi_regions
   use test_expression, only: collect_expression
   use test_critical, only: collect_critical
   use test_regions, only: collect_regions
   use test_region_edges, only: collect_region_edges
   use test_named_parameters, only: collect_named_parameters
   use test_model_equation, only: collect_model_equation
   use test_gsl, only: collect_gsl
   use test_rk, only: collect_rk
   use test_magnus, only: collect_magnus
   use test_scene, only: collect_scene
   use test_tasks, only: collect_tasks
   use test_format, only: collect_format
   use test_auto, only: collect_auto
   use test_output, only: collect_output
   use test_batch, only: collect_batch
   use test_lyapunov, only: collect_lyapunov
   use test_poincare, only: collect_poincare
   use test_task_lyapunov, only: collect_task_lyapunov
   use test_task_poincare, only: collect_task_poincare
   use test_units, only: collect_units
   use test_pendulum, only: collect_pendulum
   use test_pendulum_analysis, only: collect_pendulum_analysis
   use test_task_series, only: collect_task_series
   use test_hill_method, only: collect_hill_method
   use test_hill_fourier, only: collect_hill_fourier
   use test_characteristic, only: collect_characteristic
   use test_task_boundaries, only: collect_task_boundaries
   use test_boundaries, only: collect_boundaries
   use test_templates, only: collect_templates
   use test_symplectic, only: collect_symplectic
   use test_chaos, only: collect_chaos
   use test_checkpoint, only: collect_checkpoint
   use test_floquet_columns, only: collect_floquet_columns
   implicit none
   ! one by one, not as an array constructor of the collect functions' results: gfortran 12
   type(testsuite_t) :: suites(53)
   integer :: n_failed
   suites(1) = collect_models()
   suites(2) = collect_codes()
   suites(3) = collect_coefficient()
   suites(4) = collect_transfer()
   suites(5) = collect_formulas()
   suites(6) = collect_floquet()
   suites(7) = collect_monodromy()
   suites(8) = collect_capi()
   suites(9) = collect_gsl()
   suites(10) = collect_rk()
   suites(11) = collect_magnus()
   suites(12) = collect_scene()
   suites(13) = collect_tasks()
   suites(14) = collect_format()
   suites(15) = collect_auto()
   suites(16) = collect_units()
   suites(17) = collect_pendulum()
   suites(18) = collect_hill_method()
   suites(19) = collect_templates()
   suites(20) = collect_batch()
   suites(21) = collect_boundaries()
   suites(22) = collect_task_boundaries()
   suites(23) = collect_lyapunov()
   suites(24) = collect_poincare()
   suites(25) = collect_task_lyapunov()
   suites(26) = collect_task_poincare()
   suites(27) = collect_pendulum_analysis()
   suites(28) = collect_task_series()
   suites(29) = collect_output()
   suites(30) = collect_symplectic()
   suites(31) = collect_chaos()
   suites(32) = collect_checkpoint()
   suites(33) = collect_model_meissner()
   suites(34) = collect_hill_fourier()
   suites(35) = collect_characteristic()
   suites(36) = collect_capi_batch()
   suites(37) = collect_model_fourier()
   suites(38) = collect_model_modulated()
   suites(39) = collect_system()
   suites(40) = collect_capi_system()
   suites(41) = collect_task_system()
   suites(42) = collect_system_boundaries()
   suites(43) = collect_system_point()
   suites(44) = collect_capi_sizes()
   suites(45) = collect_capi_system_batch()
   suites(46) = collect_expression()
   suites(47) = collect_critical()
   suites(48) = collect_model_equation()
   suites(49) = collect_regions()
   suites(50) = collect_capi_regions()
   suites(51) = collect_region_edges()
   suites(52) = collect_named_parameters()
   suites(53) = collect_floquet_columns()
   call run_testsuites(suites, n_failed)
   if (n_failed > 0) error stop 1
end program tester

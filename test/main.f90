!> Test driver: `fpm test [-- SUITE [TEST]]`. Exits non-zero on any failure.
program tester
   use hillstab_testing, only: testsuite_t, run_testsuites
   use test_coefficient, only: collect_coefficient
   use test_models, only: collect_models
   use test_codes, only: collect_codes
   use test_transfer, only: collect_transfer
   use test_formulas, only: collect_formulas
   use test_floquet, only: collect_floquet
   use test_monodromy, only: collect_monodromy
   use test_capi, only: collect_capi
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
   use test_task_boundaries, only: collect_task_boundaries
   use test_boundaries, only: collect_boundaries
   use test_templates, only: collect_templates
   use test_symplectic, only: collect_symplectic
   use test_chaos, only: collect_chaos
   use test_checkpoint, only: collect_checkpoint
   implicit none
   type(testsuite_t), allocatable :: suites(:)
   integer :: n_failed
   suites = [collect_models(), collect_codes(), collect_coefficient(), collect_transfer(), collect_formulas(), collect_floquet(), &
             collect_monodromy(), collect_capi(), collect_gsl(), collect_rk(), collect_magnus(), &
             collect_scene(), collect_tasks(), collect_format(), collect_auto(), &
             collect_units(), collect_pendulum(), collect_hill_method(), collect_templates(), &
             collect_batch(), collect_boundaries(), collect_task_boundaries(), &
             collect_lyapunov(), collect_poincare(), collect_task_lyapunov(), collect_task_poincare(), &
             collect_pendulum_analysis(), collect_task_series(), collect_output(), collect_symplectic(), &
             collect_chaos(), collect_checkpoint()]
   call run_testsuites(suites, n_failed)
   if (n_failed > 0) error stop 1
end program tester

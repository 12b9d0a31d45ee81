!> The onset law of the swing (the paper's open question, Fig. 4 (f), (h)): for the
!> unstable cases (b), (e), (g) of Fig. 4 and φ0 = 1e-2, 1e-5, 1e-10, 1e-15, 1e-20, the
!> predicted number of radial periods until |φ| first exceeds 0.1,
!> n* = ln(0.1/φ0)/ln λ_max (λ_max from the core), beside the observed one (the first
!> crossing on DOP853's dense output at tolerance 1e-10, located to round-off), and the
!> prediction from the full linear solution (`linear_onset_periods`: the even solution of
!> the Hill equation from the start at rest, the first |x|/r = sin 0.1).
!>
!> Usage: fpm run --example onset_law [-- OUTPUT]  (default out/onset_law.dat); plot with
!> gnuplot plots/onset.gp. The file is written atomically, with a `# columns:` line and
!> a per-row status (0 ok, 2 failed: the integration did not complete).
program onset_law
   use hillstab_core_kinds, only: wp
   use hillstab_core_error, only: error_t
   use hillstab_core_status, only: status_ok, status_failed
   use hillstab_core_stats, only: work_stats_t
   use hillstab_hill_coefficient, only: hill_model_t, model_elastic
   use hillstab_hill_transfer, only: trace_t
   use hillstab_hill_floquet, only: floquet_from_trace, largest_multiplier_modulus
   use hillstab_integrate_monodromy, only: monodromy_trace, method_t, method_gsl
   use hillstab_pendulum_equations, only: pendulum_from_chart, pendulum_initial_state
   use hillstab_pendulum_analysis, only: pendulum_watch_t, pendulum_integrate, onset_periods, default_phi_sat, &
      linear_onset_periods
   use hillstab_batch_output_file, only: output_file_t, open_output, write_header, write_text, commit_output, discard_output
   implicit none
   character(len=*), parameter :: labels(3) = ["b", "e", "g"]
   real(wp), parameter :: cases(2, 3) = reshape([3.70_wp, 2.47_wp, 7.88_wp, 3.95_wp, 7.48_wp, 2.47_wp], [2, 3])
   real(wp), parameter :: phi0s(5) = [1.0e-2_wp, 1.0e-5_wp, 1.0e-10_wp, 1.0e-15_wp, 1.0e-20_wp]
   real(wp), parameter :: tolerance = 1.0e-10_wp
   integer, parameter :: max_periods = 400
   type(output_file_t) :: file
   type(error_t), allocatable :: error
   type(pendulum_watch_t) :: watch
   type(work_stats_t) :: stats
   type(trace_t) :: tr
   character(len=256) :: path
   character(len=300) :: line
   real(wp) :: lambda, predicted, observed, linear, y(4)
   integer :: i, j, status

   path = "out/onset_law.dat"
   if (command_argument_count() >= 1) call get_command_argument(1, path)
   call open_output(file, trim(path), error)
   if (allocated(error)) then
      write (*, '(a)') "onset_law: "//error%message
      error stop 2
   end if
   call write_header(file, [character(len=160) :: &
      "hillstab example onset_law: onset of the swing, predicted against observed", &
      "pendulum: r0 = 0.1 m, g = 9.81 m/s^2, at rest from phi0, undamped; case 2 = (b), 5 = (e), 7 = (g) of Fig. 4", &
      "lambda_max: largest |multiplier| per radial period from the core (GSL rk8pd, tolerance 1e-13)", &
      "n_predicted = ln(0.1/phi0)/ln(lambda_max) radial periods; n_observed: first |phi| > 0.1 on the dense "// &
      "output of DOP853 (tolerance 1e-10)", &
      "t_*: the same in seconds; difference = n_observed - n_predicted (constant in the linear regime)", &
      "status: 0 ok; 2 failed (integration incomplete: n_observed = -1 is a placeholder)", &
      "n_linear: first |x|/r = sin(0.1) of the linear swing x = r(0) sin(phi0) u(t), u the even solution of the "// &
      "Hill equation; linear_difference = n_observed - n_linear"], &
      "case alpha beta phi0 lambda_max n_predicted n_observed t_predicted t_observed difference status n_linear "// &
      "linear_difference", error)
   do i = 1, size(cases, 2)
      call monodromy_trace(hill_model_t(model_elastic, cases(1, i), cases(2, i), 0.0_wp), &
                           method_t(method_gsl, tolerance=1.0e-13_wp), tr, error)
      if (allocated(error)) exit
      lambda = largest_multiplier_modulus(floquet_from_trace(tr, 0.0_wp))
      do j = 1, size(phi0s)
         watch = pendulum_watch_t()
         call pendulum_from_chart(cases(1, i), cases(2, i), 0.0_wp, 0.1_wp, 9.81_wp, watch%pendulum, error)
         if (allocated(error)) exit
         watch%stop_at_onset = .true.
         y = pendulum_initial_state(watch%pendulum, phi0s(j))
         call pendulum_integrate(watch, y, max_periods*watch%pendulum%period, tolerance, stats, error)
         status = status_ok
         observed = -1.0_wp
         if (allocated(error)) then
            status = status_failed
            deallocate (error)
         else if (watch%onset_time >= 0.0_wp) then
            observed = watch%onset_time/watch%pendulum%period
         end if
         predicted = onset_periods(phi0s(j), default_phi_sat, lambda)
         linear = linear_onset_periods(cases(1, i), cases(2, i), phi0s(j), default_phi_sat)
         write (line, '(i2,2f6.2,es9.1,es15.7,2f12.5,2es15.7,f10.5,i3,f12.5,f10.5)') index("abcdefgh", labels(i)), &
            cases(:, i), phi0s(j), lambda, predicted, observed, predicted*watch%pendulum%period, &
            observed*watch%pendulum%period, observed - predicted, status, linear, observed - linear
         call write_text(file, trim(line), error)
         if (allocated(error)) exit
         write (*, '(a,a,a,es8.1,a,f9.4,a,f9.4,a,f9.4,a)') "(", labels(i), ") phi0 = ", phi0s(j), ": predicted ", &
            predicted, " periods (law), ", linear, " (linear solution), observed ", observed, " periods"
      end do
      if (allocated(error)) exit
   end do
   if (allocated(error)) then
      call discard_output(file)
      write (*, '(a)') "onset_law: "//error%message
      error stop 1
   end if
   call commit_output(file, error)
   if (allocated(error)) then
      write (*, '(a)') "onset_law: "//error%message
      error stop 1
   end if
end program onset_law

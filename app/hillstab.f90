!> The hillstab command line: `hillstab [--quiet] SCENE.nml...`, `--template TASK`, `--help`,
!> `--version` (hillstab_batch_run_cli). Runs each scene in turn. Output goes to files named
!> in the scenes; progress and errors go to stderr; stdout carries only --template,
!> --help and --version. Exit status: 0 on success, 2 for bad input, 1 when a computation
!> fails, 3 when a file was written but some of its points failed, 128 + N after signal
!> N (SIGINT, SIGTERM, SIGHUP), the unfinished output file removed.
program hillstab_cli
   use hillstab_batch_run_cli, only: serial_runner_t, run_command_line
   use hillstab_batch_output_signals, only: install_signal_cleanup
   implicit none
   type(serial_runner_t) :: runner
   integer :: status
   call install_signal_cleanup()
   runner%program = "hillstab"
   call run_command_line(runner, status)
   ! the run's exit status, silently (no STOP banner, no floating-point summary)
   stop status, quiet=.true.
end program hillstab_cli

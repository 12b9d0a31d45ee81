!> The hillstab command line: `hillstab [--quiet] SCENE.nml...`, `--template TASK`, `--help`,
!> `--version`.
!>
!> Runs each scene in turn. Output goes to files named in the scenes; progress
!> and errors go to stderr; stdout carries only --template, --help and --version.
!> Exit status: 0 on success, 2 for bad input (scene, points file, output path,
!> command line) or an output file that cannot be written completely, 1 when a
!> computation fails, 3 (exit_points_failed) when a file was written but some of its
!> points failed (status 2 in their rows), 128 + N after signal N (SIGINT, SIGTERM,
!> SIGHUP), the unfinished output file removed.
program hillstab_cli
   use hillstab_core_kinds, only: version_string
   use hillstab_core_error, only: error_t, err_points_failed
   use hillstab_core_status, only: exit_points_failed
   use hillstab_batch_tasks, only: run_scene_file
   use hillstab_batch_units, only: exit_status
   use hillstab_batch_signals, only: install_signal_cleanup
   use hillstab_batch_templates, only: template_task_names, scene_template
   use, intrinsic :: iso_fortran_env, only: error_unit, output_unit
   use, intrinsic :: ieee_arithmetic, only: ieee_set_flag, ieee_all
   implicit none
   type(error_t), allocatable :: error
   character(len=:), allocatable :: argument, written
   character(len=:), allocatable :: scenes(:)
   logical :: quiet
   integer :: i, n_scenes
   logical :: points_failed
   integer, parameter :: max_path = 4096
   character(len=*), parameter :: max_path_text = "4096"

   call install_signal_cleanup()
   quiet = .false.
   n_scenes = 0
   allocate (character(len=max_path) :: scenes(command_argument_count()))
   do i = 1, command_argument_count()
      argument = command_argument(i)
      select case (argument)
      case ("-h", "--help")
         call print_help()
         call quit("", 0)
      case ("-V", "--version")
         write (output_unit, '(a)') "hillstab "//version_string
         call quit("", 0)
      case ("-t", "--template")
         call print_template(i + 1)
         call quit("", 0)
      case ("-q", "--quiet")
         quiet = .true.
      case default
         if (len(argument) > 1 .and. argument(1:1) == "-") then
            call quit("hillstab: unknown option '"//argument//"' (see hillstab --help)", 2)
         end if
         if (len(argument) > max_path) then
            call quit("hillstab: scene path longer than "//max_path_text//" characters", 2)
         end if
         n_scenes = n_scenes + 1
         scenes(n_scenes) = argument
      end select
   end do
   if (n_scenes == 0) call quit("usage: hillstab [--quiet] SCENE.nml... (see hillstab --help)", 2)

   points_failed = .false.
   do i = 1, n_scenes
      call run_scene_file(trim(scenes(i)), quiet, error, written)
      if (allocated(error)) then
         if (error%code /= err_points_failed) call quit("hillstab: "//error%message, exit_status(error))
         ! the file is written; the message says where (also with --quiet: it qualifies the file)
         write (error_unit, '(a)') "hillstab: "//error%message
         points_failed = .true.
      end if
      if (.not. quiet) write (error_unit, '(a)') "hillstab: wrote "//written
   end do
   if (points_failed) call quit("", exit_points_failed)
   call quit("", 0)

contains

   function command_argument(i) result(text)
      integer, intent(in) :: i
      character(len=:), allocatable :: text
      integer :: length
      call get_command_argument(i, length=length)
      allocate (character(len=length) :: text)
      call get_command_argument(i, text)
   end function command_argument

   !> One message on stderr, then exit with `status` (silently: no STOP banner,
   !> no floating-point summary).
   subroutine quit(message, status)
      character(len=*), intent(in) :: message
      integer, intent(in) :: status
      if (len(message) > 0) write (error_unit, '(a)') message
      ! free what the program allocated, so that memory checkers see no leak
      if (allocated(scenes)) deallocate (scenes)
      if (allocated(argument)) deallocate (argument)
      if (allocated(written)) deallocate (written)
      if (allocated(error)) deallocate (error)
      call ieee_set_flag(ieee_all, .false.)
      stop status, quiet=.true.
   end subroutine quit

   !> The commented scene of the task named by argument `k` on stdout; exit 2 when
   !> it is missing or unknown.
   subroutine print_template(k)
      integer, intent(in) :: k
      character(len=:), allocatable :: text
      type(error_t), allocatable :: template_error
      if (k > command_argument_count()) then
         call quit("hillstab: --template needs a task: "//task_list()//" (see hillstab --help)", 2)
      end if
      call scene_template(command_argument(k), text, template_error)
      if (allocated(template_error)) call quit("hillstab: "//template_error%message, 2)
      write (output_unit, '(a)') text
   end subroutine print_template

   !> The tasks that have a template, comma-separated.
   function task_list() result(text)
      character(len=:), allocatable :: text
      character(len=:), allocatable :: names(:)
      integer :: k
      names = template_task_names()
      text = trim(names(1))
      do k = 2, size(names)
         text = text//", "//trim(names(k))
      end do
   end function task_list

   subroutine print_help()
      write (output_unit, '(a)') &
         "usage: hillstab [--quiet] SCENE.nml...", &
         "       hillstab --template TASK > SCENE.nml", &
         "", &
         "Stability charts of the elastic pendulum (Hill equation x'' + Q(tau) x = 0).", &
         "Each SCENE is a namelist file (&scene plus the group of its task);", &
         "results go to <output>_<task>.dat, gnuplot-ready. An output file can be given", &
         "as SCENE to repeat its run.", &
         "", &
         "Tasks: "//task_list(), &
         "  (hillstab --template TASK prints a complete scene for TASK, every variable", &
         "  at its default with a comment)", &
         "", &
         "  -q, --quiet          no progress or messages on stderr (errors still)", &
         "  -t, --template TASK  a commented scene for TASK on stdout", &
         "  -h, --help           this text", &
         "  -V, --version        the version", &
         "", &
         "Exit status: 0 success, 2 bad input or an output file that cannot be written,", &
         "1 a computation failed, 3 files written but some points failed (status 2 in", &
         "their rows), 128 + N killed by signal N (SIGINT, SIGTERM, SIGHUP: the unfinished", &
         "output file is removed)."
   end subroutine print_help
end program hillstab_cli

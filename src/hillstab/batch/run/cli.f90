!> The command line of the hillstab programs, one for both: `hillstab` and `hillstab_mpi`
!> parse the same options, print the same help and messages, run the scenes in turn and
!> exit with the same statuses. A program supplies a `scene_runner_t`: how it runs one
!> scene (in this process, or over MPI ranks), whether this process prints (rank 0), and
!> what to do before it exits (MPI_Finalize).
!>
!> Exit status: 0 on success, 2 for bad input (scene, points file, output path, command
!> line) or an output file that cannot be written completely, 1 when a computation
!> fails, 3 (exit_points_failed) when a file was written but some of its points failed
!> (status 2 in their rows), 128 + N after signal N (SIGINT, SIGTERM, SIGHUP), the
!> unfinished output file removed and its checkpoint kept. `--resume` continues the runs of
!> the scenes from their checkpoints (hillstab_batch_output_checkpoint); `--checkpoint-interval S`
!> sets how often a checkpoint is updated.
!>
!>```fortran
!> type(serial_runner_t) :: runner
!> integer :: status
!> call run_command_line(runner, status)
!> stop status, quiet=.true.   ! the program turns the status into its exit code
!>```
module hillstab_batch_run_cli
   use hillstab_core_kinds, only: version_string
   use hillstab_core_error, only: error_t, err_input, err_io, err_invalid_parameter, err_points_failed
   use hillstab_core_status, only: exit_points_failed
   use hillstab_batch_run_scenes, only: run_scene_file
   use hillstab_batch_run_templates, only: scene_template
   use hillstab_batch_tasks_registry, only: task_names_text
   use hillstab_batch_output_signals, only: settle_signals
   use hillstab_batch_output_checkpoint, only: checkpoint_options_t
   use hillstab_batch_run_threads, only: place_threads
   use hillstab_batch_run_limits, only: check_start_memory
   !$ use omp_lib, only: omp_get_max_threads
   use hillstab_core_kinds, only: wp
   use hillstab_core_text, only: integer_text
   use hillstab_ffi_libc, only: c_mallopt, malloc_trim_threshold, malloc_top_pad, malloc_mmap_threshold
   use, intrinsic :: iso_c_binding, only: c_int
   use, intrinsic :: iso_fortran_env, only: error_unit, output_unit
   use, intrinsic :: ieee_arithmetic, only: ieee_set_flag, ieee_all
   implicit none
   private
   public :: scene_runner_t, serial_runner_t, run_command_line, exit_status, max_path, printable

   !> Longest scene path accepted (a longer one would be cut and another file read).
   integer, parameter :: max_path = 4096

   !> How a program runs its scenes.
   type, abstract :: scene_runner_t
      character(len=:), allocatable :: program  !! the program's name, the prefix of its messages
      !> the usage lines of `--help` (the program's name and arguments)
      character(len=:), allocatable :: usage(:)
      !> what the program does, for `--help`
      character(len=:), allocatable :: description(:)
      !> checkpoints: `--resume`, `--checkpoint-interval`; the command that resumes the
      !> scene being run (for messages)
      type(checkpoint_options_t) :: options
   contains
      !> run one scene file; on return the outcome is the same in every process
      procedure(runner_run), deferred :: run
      !> whether this process prints (help, version, template, "wrote")
      procedure :: reports => runner_reports
      !> what to do before the program exits
      procedure :: finish => runner_finish
   end type scene_runner_t

   abstract interface
      !> Run the scene file `path`.
      subroutine runner_run(self, path, quiet, error, written)
         import :: scene_runner_t, error_t
         class(scene_runner_t), intent(inout) :: self  !! the runner
         character(len=*), intent(in) :: path  !! the scene file
         logical, intent(in) :: quiet  !! no progress on stderr
         !> what failed (err_points_failed: written with failed points); a message that is
         !> empty is printed by another process
         type(error_t), allocatable, intent(out) :: error
         character(len=:), allocatable, intent(out) :: written  !! the file written
      end subroutine runner_run
   end interface

   !> The one-process runner of the `hillstab` program.
   type, extends(scene_runner_t) :: serial_runner_t
   contains
      procedure :: run => serial_run
   end type serial_runner_t

contains

   !> Run a scene in this process.
   subroutine serial_run(self, path, quiet, error, written)
      class(serial_runner_t), intent(inout) :: self  !! the runner
      character(len=*), intent(in) :: path  !! the scene file
      logical, intent(in) :: quiet  !! no progress on stderr
      type(error_t), allocatable, intent(out) :: error  !! what failed
      character(len=:), allocatable, intent(out) :: written  !! the file written
      call place_threads()   ! once: one thread per CPU (hillstab_batch_run_threads)
      call run_scene_file(path, quiet, error, written, self%options)
   end subroutine serial_run

   !> Default: every process prints.
   logical function runner_reports(self)
      class(scene_runner_t), intent(in) :: self  !! the runner
      runner_reports = .true.
   end function runner_reports

   !> Default: nothing before exit.
   subroutine runner_finish(self)
      class(scene_runner_t), intent(inout) :: self  !! the runner
   end subroutine runner_finish

   !> The exit status of a run that ended with `error`: 2 for bad input (scene, points
   !> file, output path), 3 when the file was written but some points failed
   !> (err_points_failed), 1 when a computation failed otherwise.
   pure integer function exit_status(error)
      type(error_t), intent(in) :: error  !! the error a run ended with
      select case (error%code)
      case (err_input, err_io, err_invalid_parameter)
         exit_status = 2
      case (err_points_failed)
         exit_status = exit_points_failed
      case default
         exit_status = 1
      end select
   end function exit_status

   !> Parse the command line and run every scene it names:
   !> `[--quiet] [--resume] [--checkpoint-interval S] SCENE.nml...`, `--template TASK`,
   !> `--help`, `--version`. On return the message of a failure is on stderr, the runner
   !> has finished (`finish`: MPI_Finalize) and `status` is the exit status the program
   !> ends with (0, 1, 2, 3 or 128 + N, as the module says).
   subroutine run_command_line(runner, status)
      class(scene_runner_t), intent(inout) :: runner  !! how the scenes run
      integer, intent(out) :: status  !! the exit status of the run
      type(error_t), allocatable :: error
      character(len=:), allocatable :: argument, written
      character(len=max_path), allocatable :: scenes(:)
      character(len=:), allocatable :: text
      logical :: quiet, points_failed, value_next
      integer :: i, n_scenes, signum
      call keep_heap()
      if (.not. allocated(runner%program)) runner%program = "hillstab"
      if (.not. allocated(runner%usage)) runner%usage = default_usage(runner%program)
      if (.not. allocated(runner%description)) runner%description = default_description()
      runner%options%program = runner%program
      quiet = .false.
      value_next = .false.
      n_scenes = 0
      allocate (scenes(command_argument_count()))
      do i = 1, command_argument_count()
         argument = command_argument(i)
         if (value_next) then
            ! the seconds of --checkpoint-interval
            value_next = .false.
            runner%options%interval = seconds_value(argument)
            if (runner%options%interval < 0.0_wp) then
               call quit(on_reporter(runner%program//": --checkpoint-interval: '"//argument//"' is not a number of "// &
                  "seconds >= 0 (see "//runner%program//" --help)"), 2)
               return
            end if
            cycle
         end if
         select case (argument)
         case ("-h", "--help")
            if (runner%reports()) call print_help(runner)
            call quit("", 0)
            return
         case ("-V", "--version")
            if (runner%reports()) write (output_unit, '(a)') runner%program//" "//version_string
            call quit("", 0)
            return
         case ("-t", "--template")
            if (i + 1 > command_argument_count()) then
               call quit(on_reporter(runner%program//": --template needs a task: "//task_names_text(", ")// &
                  " (see "//runner%program//" --help)"), 2)
               return
            end if
            call scene_template(command_argument(i + 1), text, error)
            if (allocated(error)) then
               call quit(on_reporter(runner%program//": "//error%message), 2)
               return
            end if
            if (runner%reports()) write (output_unit, '(a)') text
            call quit("", 0)
            return
         case ("-q", "--quiet")
            quiet = .true.
         case ("--resume")
            runner%options%resume = .true.
         case ("--checkpoint-interval")
            if (i + 1 > command_argument_count()) then
               call quit(on_reporter(runner%program//": --checkpoint-interval needs a number of seconds (see "// &
                  runner%program//" --help)"), 2)
               return
            end if
            value_next = .true.
         case default
            if (len(argument) > 1 .and. argument(1:1) == "-") then
               call quit(on_reporter(runner%program//": unknown option '"//argument//"' (see "//runner%program// &
                  " --help)"), 2)
               return
            end if
            if (len(argument) > max_path) then
               call quit(on_reporter(runner%program//": scene path longer than 4096 characters"), 2)
               return
            end if
            n_scenes = n_scenes + 1
            scenes(n_scenes) = argument
         end select
      end do
      if (n_scenes == 0) then
         call quit(on_reporter("usage: "//trim(runner%usage(1))//" (see "//runner%program//" --help)"), 2)
         return
      end if
      ! an address-space limit that cannot hold the threads' stacks: said before the first
      ! thread is made (the OpenMP runtime would stop the program with a line of its own)
      call check_start_memory(extra_threads(), text)
      if (len(text) > 0) then
         call quit(on_reporter(runner%program//": "//text), 2)
         return
      end if

      points_failed = .false.
      do i = 1, n_scenes
         runner%options%command = runner%program//" --resume "//shell_word(trim(scenes(i)))
         call runner%run(trim(scenes(i)), quiet, error, written)
         if (allocated(error)) then
            if (len(error%message) > 0) error%message = runner%program//": "//error%message
            if (error%code /= err_points_failed) then
               signum = settle_signals()
               call quit(error%message, exit_status(error))
               return
            end if
            ! the file is written; the message says where (also with --quiet: it qualifies the file)
            if (len(error%message) > 0) write (error_unit, '(a)') printable(error%message)
            points_failed = .true.
         end if
         if (.not. quiet .and. runner%reports()) write (error_unit, '(a)') runner%program//": wrote "//written
         ! a signal that arrived while the file took its name: it is written and said so;
         ! stop here (after the last scene signals stay held until the exit, whose status is
         ! that of the files written)
         signum = settle_signals(keep_holding=i == n_scenes)
         if (signum /= 0) then
            if (i < n_scenes) then
               call quit(on_reporter(runner%program//": signal "//integer_text(signum)//" arrived after "// &
                  written//" was written; the scenes after "//trim(scenes(i))//" were not run"), 128 + signum)
               return
            end if
            call quit(on_reporter(runner%program//": signal "//integer_text(signum)//" arrived after "// &
               written//" was written: the run is complete"), merge(exit_points_failed, 0, points_failed))
            return
         end if
      end do
      call quit("", merge(exit_points_failed, 0, points_failed))

   contains

      !> `message` on the reporting process, "" elsewhere.
      function on_reporter(message) result(shown)
         character(len=*), intent(in) :: message
         character(len=:), allocatable :: shown
         shown = ""
         if (runner%reports()) shown = message
      end function on_reporter

      !> The end of the run: one message on stderr, what the run allocated freed, the runner
      !> finished, the floating-point flags cleared (the program's `stop` then prints no
      !> summary), the exit status `code` returned; the caller returns next.
      subroutine quit(message, code)
         character(len=*), intent(in) :: message
         integer, intent(in) :: code
         status = code
         if (len(message) > 0) write (error_unit, '(a)') printable(message)
         ! free what the program allocated, so that memory checkers see no leak
         if (allocated(scenes)) deallocate (scenes)
         if (allocated(argument)) deallocate (argument)
         if (allocated(written)) deallocate (written)
         if (allocated(error)) deallocate (error)
         if (allocated(text)) deallocate (text)
         call runner%finish()
         call ieee_set_flag(ieee_all, .false.)
      end subroutine quit
   end subroutine run_command_line

   !> The threads a run makes besides the first: the OpenMP team's others, and one more for
   !> the first team that binds them (hillstab_batch_run_threads); none with one thread.
   integer function extra_threads() result(n)
      n = 0
      !$ n = omp_get_max_threads()
      if (n < 2) n = 0
   end function extra_threads

   !> The allocator keeps the memory it was given (up to 256 MiB freed at the top of the heap,
   !> blocks up to 32 MiB from the heap, 16 MiB more asked for at a time): the units of a
   !> chart allocate and free their rows' buffers hundreds of times, and by default glibc
   !> gave the top of the heap back and asked for it again with brk each time (1550 system
   !> calls, a fifth of the time of a 300 × 300 verdict chart). A batch program ends soon
   !> after its peak, so the memory kept costs nothing. Without glibc the request fails and
   !> nothing changes.
   subroutine keep_heap()
      integer(c_int) :: status
      status = c_mallopt(malloc_trim_threshold, 268435456_c_int)
      status = c_mallopt(malloc_top_pad, 16777216_c_int)
      status = c_mallopt(malloc_mmap_threshold, 33554432_c_int)
   end subroutine keep_heap

   !> A message as one line of plain text: control characters (NUL, form feed, a line
   !> break a scene value carried, ...), the C1 controls U+0080 … U+009F in UTF-8 (U+0085,
   !> next line, splits lines for some tools; U+009B starts terminal control sequences) and
   !> the Unicode line and paragraph separators U+2028, U+2029 shown as \xNN, \u0085 and
   !> \u2028 escapes, so that what a scene file holds cannot break or forge lines of the
   !> program's messages.
   pure function printable(message) result(text)
      character(len=*), intent(in) :: message  !! the message
      character(len=:), allocatable :: text  !! the same as plain printable text
      character(len=*), parameter :: hex = "0123456789abcdef"
      integer :: i, c
      text = ""
      i = 1
      do while (i <= len(message))
         c = iachar(message(i:i))
         if (c < 32 .or. c == 127) then
            text = text//"\x"//hex(c/16 + 1:c/16 + 1)//hex(mod(c, 16) + 1:mod(c, 16) + 1)
         else if (c == 194 .and. i + 1 <= len(message)) then
            c = iachar(message(i + 1:i + 1))
            if (c >= 128 .and. c <= 159) then
               text = text//"\u00"//hex(c/16 + 1:c/16 + 1)//hex(mod(c, 16) + 1:mod(c, 16) + 1)
               i = i + 2
               cycle
            end if
            text = text//message(i:i)
         else if (c == 226 .and. i + 2 <= len(message)) then
            if (iachar(message(i + 1:i + 1)) == 128 .and. (iachar(message(i + 2:i + 2)) == 168 .or. &
                                                        iachar(message(i + 2:i + 2)) == 169)) then
               text = text//merge("\u2028", "\u2029", iachar(message(i + 2:i + 2)) == 168)
               i = i + 3
               cycle
            end if
            text = text//message(i:i)
         else
            text = text//message(i:i)
         end if
         i = i + 1
      end do
   end function printable

   !> The seconds of `--checkpoint-interval`: a plain non-negative number (-1 for anything
   !> else, a NaN or an infinity included).
   function seconds_value(text) result(seconds)
      character(len=*), intent(in) :: text  !! the argument
      real(wp) :: seconds
      integer :: ios
      seconds = -1.0_wp
      if (len(text) == 0 .or. len(text) > 30) return
      if (verify(text, "0123456789.eE+-") /= 0) return
      read (text, *, iostat=ios) seconds
      if (ios /= 0) seconds = -1.0_wp
      if (.not. (seconds >= 0.0_wp .and. seconds <= 1.0e9_wp)) seconds = -1.0_wp
   end function seconds_value

   !> `text` as one word of a POSIX shell command line (quoted when it holds anything but
   !> letters, digits and ._/+-), for the resume command shown in messages.
   pure function shell_word(text) result(word)
      character(len=*), intent(in) :: text  !! a path
      character(len=:), allocatable :: word
      character(len=*), parameter :: plain = "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789._/+-"
      integer :: k
      if (len(text) > 0 .and. verify(text, plain) == 0) then
         word = text
         return
      end if
      word = "'"
      do k = 1, len(text)
         if (text(k:k) == "'") then
            word = word//"'\''"
         else
            word = word//text(k:k)
         end if
      end do
      word = word//"'"
   end function shell_word

   !> Command-line argument i.
   function command_argument(i) result(text)
      integer, intent(in) :: i
      character(len=:), allocatable :: text
      integer :: length
      call get_command_argument(i, length=length)
      allocate (character(len=length) :: text)
      call get_command_argument(i, text)
   end function command_argument

   function default_usage(program) result(lines)
      character(len=*), intent(in) :: program
      character(len=:), allocatable :: lines(:)
      lines = [character(len=80) :: program//" [--quiet] [--resume] [--checkpoint-interval S] SCENE.nml...", &
               program//" --template TASK > SCENE.nml"]
   end function default_usage

   function default_description() result(lines)
      character(len=:), allocatable :: lines(:)
      lines = [character(len=80) :: "Stability charts of the elastic pendulum (Hill equation x'' + Q(tau) x = 0)."]
   end function default_description

   subroutine print_help(runner)
      class(scene_runner_t), intent(in) :: runner
      integer :: k
      write (output_unit, '(a)') "usage: "//trim(runner%usage(1))
      do k = 2, size(runner%usage)
         write (output_unit, '(a)') "       "//trim(runner%usage(k))
      end do
      write (output_unit, '(a)') ""
      do k = 1, size(runner%description)
         write (output_unit, '(a)') trim(runner%description(k))
      end do
      write (output_unit, '(a)') &
         "Each SCENE is a namelist file (&scene plus the group of its task);", &
         "results go to <output>_<task>.dat, gnuplot-ready. An output file can be given", &
         "as SCENE to repeat its run.", &
         "", &
         "Tasks: "//task_names_text(", "), &
         "  (--template TASK prints a complete scene for TASK, every variable", &
         "  at its default with a comment)", &
         "", &
         "  -q, --quiet          no progress or messages on stderr (errors still)", &
         "  --resume             continue each run from the checkpoint an interrupted run", &
         "                       left; without it an old checkpoint is discarded", &
         "  --checkpoint-interval S  seconds between checkpoint updates (default 3;", &
         "                       0: after every row or unit)", &
         "  -t, --template TASK  a commented scene for TASK on stdout", &
         "  -h, --help           this text", &
         "  -V, --version        the version", &
         "", &
         "Checkpoints: charts over &chart, points and lyapunov runs written as text keep", &
         "<output file>.checkpoint/ (the rows written so far, on the disk every few", &
         "seconds); a successful run removes it. --resume computes only what is missing", &
         "and writes the same file; it refuses a checkpoint of another scene (exit 2).", &
         "", &
         "Exit status (of every process): 0 success, 2 bad input or an output file that", &
         "cannot be written, 1 a computation failed, 3 files written but some points failed", &
         "(status 2 in their rows), 128 + N killed by signal N (SIGINT, SIGTERM, SIGHUP: the", &
         "unfinished output file is removed, its checkpoint kept)."
   end subroutine print_help
end module hillstab_batch_run_cli

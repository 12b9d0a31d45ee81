!> `mpirun -np N hillstab_mpi [--quiet] SCENE.nml...`: hillstab spread over MPI ranks.
!>
!> The points of chart, points and lyapunov scenes are computed on all ranks with dynamic
!> load balancing: rank 0 hands out units (hillstab_batch_run_units: a chart row, a run of points) on
!> demand, keeps two units queued at every other rank so that no rank waits for the
!> next, computes units itself between requests, and writes the results in order into
!> the same file as a single-process `hillstab` run (identical data lines), through the
!> atomic writers of hillstab_batch_output_file: the file appears whole or not at all. Other tasks
!> run on rank 0. Options, messages and exit statuses are those of `hillstab` (one command
!> line module, hillstab_batch_run_cli, for both programs); every rank
!> exits with the status of the run (0 success, 2 bad input, 3 written with failed
!> points, 1 a computation failed).
!>
!> Rank 0 keeps the run's checkpoint as hillstab does (hillstab_batch_run_units), so that
!> `hillstab_mpi --resume` (or `hillstab --resume`, whatever the number of ranks) continues
!> an interrupted run: the units of the checkpoint are those of the resumed run, and only
!> the units it lacks are handed out.
module hillstab_mpi_runner
   use mpi_f08
   use hillstab_core_kinds, only: wp, int64
   use hillstab_core_error, only: error_t, set_error, err_input, err_points_failed
   use hillstab_core_text, only: integer_text
   use hillstab_batch_scene_types, only: scene_t, output_path
   use hillstab_batch_run_read, only: read_scene
   use hillstab_batch_run_scenes, only: run_scene, warn_scene, name_scene_file
   use hillstab_batch_run_units, only: batch_t, batch_result_t, batch_distributable, batch_plan, batch_set_unit_size, &
      batch_compute, &
      batch_open, batch_write, batch_commit, batch_discard, scene_fingerprint
   use hillstab_batch_run_cli, only: scene_runner_t, exit_status
   use hillstab_batch_run_limits, only: check_memory_room
   use hillstab_batch_output_signals, only: watch_temp_file, forget_temp_file
   use, intrinsic :: iso_fortran_env, only: error_unit
   implicit none
   private
   public :: mpi_runner_t

   integer, parameter :: manager = 0
   integer, parameter :: tag_assign = 1, tag_result = 2, tag_text = 3, tag_status = 4
   !> units queued at a worker: it starts the next while its last result travels
   integer, parameter :: queue_depth = 2

   !> Rank 0's bookkeeping while it hands out units.
   type :: manager_t
      type(batch_result_t), allocatable :: done(:)  !! computed units not yet written
      integer, allocatable :: queued(:)            !! units queued at each worker 1 …
      integer :: next_unit = 1                     !! next unit to hand out
      integer :: next_write = 1                    !! next unit to write
      logical :: stopping = .false.                !! an error: start nothing new
      real(wp) :: busy(2) = 0.0_wp                 !! rank 0's computing time [s]: CPU, wall
   end type manager_t

   !> hillstab over MPI ranks: the scene runner of hillstab_batch_run_cli.
   type, extends(scene_runner_t) :: mpi_runner_t
      integer :: rank = 0     !! this rank
      integer :: n_ranks = 1  !! ranks in MPI_COMM_WORLD
      logical :: quiet = .false.  !! the --quiet of the scene being run
   contains
      procedure :: run => run_scene_everywhere
      procedure :: reports => mpi_reports
      procedure :: finish => mpi_finish
   end type mpi_runner_t

contains

   !> Only rank 0 prints.
   logical function mpi_reports(self)
      class(mpi_runner_t), intent(in) :: self
      mpi_reports = self%rank == manager
   end function mpi_reports

   !> MPI_Finalize before the exit.
   subroutine mpi_finish(self)
      class(mpi_runner_t), intent(inout) :: self
      call MPI_Finalize()
   end subroutine mpi_finish

   !> Read and run one scene on all ranks. On return every rank holds the same outcome:
   !> `error` allocated on all ranks or on none (with the message on the rank that
   !> knows it, a generic one elsewhere).
   subroutine run_scene_everywhere(self, path, quiet, error, written)
      class(mpi_runner_t), intent(inout) :: self
      character(len=*), intent(in) :: path
      logical, intent(in) :: quiet
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable, intent(out) :: written
      type(scene_t) :: scene
      type(batch_t) :: batch
      real(wp) :: busy(2)
      logical :: written_ok
      integer :: slot
      self%quiet = quiet
      ! the resume command of messages, as this job was started
      if (allocated(self%options%command)) self%options%command = "mpirun -np "//integer_text(self%n_ranks)// &
         " "//self%options%command
      ! every rank reads the scene (and its points file); the worst outcome wins, so a
      ! file one rank cannot read stops all of them
      call read_scene(path, scene, error)
      call agree(self, error)
      if (allocated(error)) return
      call same_scene_everywhere(self, scene, error)
      if (allocated(error)) return
      if (self%rank == manager) call warn_scene(scene, "hillstab_mpi")
      written = output_path(scene)
      if (.not. batch_distributable(scene)) then
         if (self%rank == manager) call run_scene(scene, quiet, error, self%options)
         call agree(self, error)
         return
      end if
      ! buffers that cannot fit are refused before any work, as by hillstab
      call check_memory_room(scene, error)
      call agree(self, error)
      if (allocated(error)) return
      call batch_plan(scene, self%n_ranks, batch)
      if (self%rank == manager) then
         ! a resumed run keeps the units of its checkpoint: the workers are told below
         call batch_open(batch, quiet, error, self%options)
         call agree(self, error)
         if (allocated(error)) return
         call share_unit_size(self, batch)
         call share_temporary_name(self, batch%file%temp_path, slot)
         call manage(self, batch, error, busy)
         if (allocated(error)) then
            call batch_discard(batch, error)
         else
            call batch_commit(batch, error)
         end if
         call name_scene_file(scene, error)
      else
         call agree(self, error)
         if (allocated(error)) return
         call share_unit_size(self, batch)
         call share_temporary_name(self, "", slot)
         call work(batch, busy)
         call forget_temp_file(slot)
      end if
      call agree(self, error)
      written_ok = .true.
      if (allocated(error)) written_ok = error%code == err_points_failed
      call report_balance(self, busy, written_ok)
   end subroutine run_scene_everywhere

   !> Rank 0 sends the points per unit of the run (a resumed run's are its checkpoint's) to the
   !> other ranks, which plan their units alike.
   subroutine share_unit_size(self, batch)
      class(mpi_runner_t), intent(in) :: self
      type(batch_t), intent(inout) :: batch  !! rank 0: opened; elsewhere planned
      integer :: unit_size
      unit_size = batch%unit_size
      call MPI_Bcast(unit_size, 1, MPI_INTEGER, manager, MPI_COMM_WORLD)
      if (self%rank /= manager) call batch_set_unit_size(batch, unit_size)
   end subroutine share_unit_size

   !> Rank 0 sends the name of its temporary output to the other ranks, which watch it as
   !> their own: when the job is stopped by a signal (to mpirun, or after a rank died),
   !> whichever rank handles it removes the file, also if rank 0 itself is killed first.
   subroutine share_temporary_name(self, name, slot)
      class(mpi_runner_t), intent(in) :: self
      character(len=*), intent(in) :: name  !! rank 0: the temporary file; elsewhere ignored
      integer, intent(out) :: slot  !! the watch of the other ranks (0 on rank 0)
      character(len=:), allocatable :: received
      integer :: n
      slot = 0
      n = len(name)
      call MPI_Bcast(n, 1, MPI_INTEGER, manager, MPI_COMM_WORLD)
      allocate (character(len=n) :: received)
      if (self%rank == manager) received = name
      call MPI_Bcast(received, n, MPI_CHARACTER, manager, MPI_COMM_WORLD)
      if (self%rank /= manager) call watch_temp_file(received, slot)
   end subroutine share_temporary_name

   !> Every rank must have read the same scene and points: their fingerprints are compared
   !> (bad input on every rank when they differ; rank 0 says so).
   subroutine same_scene_everywhere(self, scene, error)
      class(mpi_runner_t), intent(in) :: self
      type(scene_t), intent(in) :: scene
      type(error_t), allocatable, intent(out) :: error
      integer(int64) :: mine(2), low(2), high(2)
      mine = scene_fingerprint(scene)
      call MPI_Allreduce(mine, low, 2, MPI_INTEGER8, MPI_MIN, MPI_COMM_WORLD)
      call MPI_Allreduce(mine, high, 2, MPI_INTEGER8, MPI_MAX, MPI_COMM_WORLD)
      if (all(low == high)) return
      if (self%rank == manager) then
         call set_error(error, err_input, scene%source//": the ranks read different scenes or points files "// &
            "(another working directory, or a file changed while the ranks started): every rank must read "// &
            "the same; nothing was computed")
      else
         call set_error(error, err_input, "")
      end if
   end subroutine same_scene_everywhere

   !> Make the outcome collective: if any rank has an error, all have one, the most
   !> severe (bad input, then a failed computation, then failed points in a written
   !> file), with the message of the lowest rank holding it; the others get the same
   !> code and an empty message, so that one rank prints it.
   subroutine agree(self, error)
      class(mpi_runner_t), intent(in) :: self
      type(error_t), allocatable, intent(inout) :: error
      integer, parameter :: severity_of_status(0:3) = [0, 2, 3, 1]  ! exit status -> severity
      integer, parameter :: code_of_severity(3) = [err_points_failed, 0, err_input]
      integer :: mine(2), worst(2)
      mine = [0, self%n_ranks]
      if (allocated(error)) mine = [severity_of_status(exit_status(error)), self%rank]
      ! the highest severity, and among the ranks with it the lowest rank number
      call MPI_Allreduce(mine(1), worst(1), 1, MPI_INTEGER, MPI_MAX, MPI_COMM_WORLD)
      if (mine(1) /= worst(1)) mine(2) = self%n_ranks
      call MPI_Allreduce(mine(2), worst(2), 1, MPI_INTEGER, MPI_MIN, MPI_COMM_WORLD)
      if (worst(1) == 0) return
      if (self%rank /= worst(2)) call set_error(error, code_of_severity(worst(1)), "")
   end subroutine agree

   !> Rank 0: hand out units, compute some, write all in order. Returns the first error
   !> (a failed point, a write failure); after one, no new unit is started and the
   !> queued ones are drained.
   subroutine manage(self, batch, error, busy)
      class(mpi_runner_t), intent(in) :: self
      type(batch_t), intent(inout) :: batch
      type(error_t), allocatable, intent(out) :: error
      real(wp), intent(out) :: busy(2)  !! seconds rank 0 spent computing units: CPU, wall
      type(manager_t) :: m
      integer :: w, d
      logical :: computes, arrived
      type(MPI_Status) :: probe

      allocate (m%done(batch%n_units), m%queued(self%n_ranks - 1))
      m%queued = 0
      ! a resumed run: the units before first_unit are in the file already
      m%next_unit = batch%first_unit
      m%next_write = batch%first_unit
      ! with many ranks, rank 0 only manages: answering at once keeps the others busy
      computes = self%n_ranks <= 8
      do d = 1, queue_depth
         do w = 1, self%n_ranks - 1
            call assign(m, batch, w)
         end do
      end do
      do w = 1, self%n_ranks - 1
         if (m%queued(w) == 0) call MPI_Send(0, 1, MPI_INTEGER, w, tag_assign, MPI_COMM_WORLD)
      end do
      do
         ! serve every result that has arrived
         do
            call MPI_Iprobe(MPI_ANY_SOURCE, tag_result, MPI_COMM_WORLD, arrived, probe)
            if (.not. arrived) exit
            call receive_result(m, batch, probe%MPI_SOURCE, error)
         end do
         if (.not. m%stopping .and. m%next_unit <= batch%n_units .and. (computes .or. self%n_ranks == 1)) then
            m%next_unit = m%next_unit + 1
            call compute_timed(batch, m%next_unit - 1, m%done(m%next_unit - 1), m%busy)
            call write_ready(m, batch, error)
         else if (any(m%queued > 0)) then
            call MPI_Probe(MPI_ANY_SOURCE, tag_result, MPI_COMM_WORLD, probe)
            call receive_result(m, batch, probe%MPI_SOURCE, error)
         else
            exit
         end if
      end do
      busy = m%busy
   end subroutine manage

   !> Queue the next unit at worker `w` (nothing once all are out or the run stops).
   subroutine assign(m, batch, w)
      type(manager_t), intent(inout) :: m
      type(batch_t), intent(in) :: batch
      integer, intent(in) :: w
      if (m%stopping .or. m%next_unit > batch%n_units) return
      call MPI_Send(m%next_unit, 1, MPI_INTEGER, w, tag_assign, MPI_COMM_WORLD)
      m%next_unit = m%next_unit + 1
      m%queued(w) = m%queued(w) + 1
   end subroutine assign

   !> Receive a result from `source`, give it its next unit (or tell it to stop), and
   !> write what is ready.
   subroutine receive_result(m, batch, source, error)
      type(manager_t), intent(inout) :: m
      type(batch_t), intent(inout) :: batch
      integer, intent(in) :: source
      type(error_t), allocatable, intent(inout) :: error
      integer :: head(3)
      type(batch_result_t) :: result
      call MPI_Recv(head, 3, MPI_INTEGER, source, tag_result, MPI_COMM_WORLD, MPI_STATUS_IGNORE)
      result%unit = head(1)
      allocate (character(len=head(2)) :: result%text)
      allocate (result%status(head(3)))
      call MPI_Recv(result%text, head(2), MPI_CHARACTER, source, tag_text, MPI_COMM_WORLD, MPI_STATUS_IGNORE)
      call MPI_Recv(result%status, head(3), MPI_INTEGER, source, tag_status, MPI_COMM_WORLD, MPI_STATUS_IGNORE)
      m%queued(source) = m%queued(source) - 1
      call assign(m, batch, source)
      ! a worker with nothing queued and nothing more to get is told to stop
      if (m%queued(source) == 0) call MPI_Send(0, 1, MPI_INTEGER, source, tag_assign, MPI_COMM_WORLD)
      m%done(result%unit) = result
      call write_ready(m, batch, error)
   end subroutine receive_result

   !> Write the results that are next in order; the first error stops the run.
   subroutine write_ready(m, batch, error)
      type(manager_t), intent(inout) :: m
      type(batch_t), intent(inout) :: batch
      type(error_t), allocatable, intent(inout) :: error
      do while (m%next_write <= batch%n_units)
         if (.not. allocated(m%done(m%next_write)%status)) exit
         if (.not. m%stopping) then
            call batch_write(batch, m%done(m%next_write), error)
            if (allocated(error)) m%stopping = .true.
         end if
         deallocate (m%done(m%next_write)%text, m%done(m%next_write)%status)
         m%next_write = m%next_write + 1
      end do
   end subroutine write_ready

   !> Ranks 1 …: compute the units rank 0 assigns until told to stop (unit 0).
   subroutine work(batch, busy)
      type(batch_t), intent(in) :: batch
      real(wp), intent(out) :: busy(2)  !! seconds spent computing units: CPU, wall
      type(batch_result_t) :: result
      integer :: unit
      busy = 0.0_wp
      do
         call MPI_Recv(unit, 1, MPI_INTEGER, manager, tag_assign, MPI_COMM_WORLD, MPI_STATUS_IGNORE)
         if (unit == 0) exit
         call compute_timed(batch, unit, result, busy)
         call MPI_Send([result%unit, len(result%text), size(result%status)], 3, MPI_INTEGER, manager, &
            tag_result, MPI_COMM_WORLD)
         call MPI_Send(result%text, len(result%text), MPI_CHARACTER, manager, tag_text, MPI_COMM_WORLD)
         call MPI_Send(result%status, size(result%status), MPI_INTEGER, manager, tag_status, MPI_COMM_WORLD)
      end do
   end subroutine work

   subroutine compute_timed(batch, unit, result, busy)
      type(batch_t), intent(in) :: batch
      integer, intent(in) :: unit
      type(batch_result_t), intent(out) :: result
      real(wp), intent(inout) :: busy(2)  !! seconds spent computing so far: CPU, wall
      real(wp) :: start(2), finish(2)
      call cpu_time(start(1))
      start(2) = MPI_Wtime()
      call batch_compute(batch, unit, result)
      call cpu_time(finish(1))
      finish(2) = MPI_Wtime()
      busy = busy + (finish - start)
   end subroutine compute_timed

   !> Collective: rank 0 says (unless quiet, after a successful run) how evenly the
   !> computing was spread: the busiest rank's computing time over the mean of the ranks
   !> that computed, in CPU time (the work, whatever else runs on the machine) and in wall
   !> time.
   subroutine report_balance(self, busy, succeeded)
      class(mpi_runner_t), intent(in) :: self
      real(wp), intent(in) :: busy(2)    !! this rank's computing time [s]: CPU, wall
      logical, intent(in) :: succeeded   !! the same on every rank
      real(wp) :: all_busy(2, self%n_ranks), mean(2)
      integer :: n_computing
      character(len=240) :: text
      call MPI_Gather(busy, 2, MPI_DOUBLE_PRECISION, all_busy, 2, MPI_DOUBLE_PRECISION, manager, MPI_COMM_WORLD)
      if (self%rank /= manager .or. self%quiet .or. .not. succeeded .or. self%n_ranks == 1) return
      n_computing = count(all_busy(2, :) > 0.0_wp)
      if (n_computing == 0) return
      mean = sum(all_busy, dim=2)/n_computing
      write (text, '(a,i0,a,i0,a,es9.3,a,f6.3,a,es9.3,a,f6.3,a)') "hillstab_mpi: ", n_computing, " of ", self%n_ranks, &
         " ranks computed; per rank: CPU mean ", mean(1), " s, busiest/mean ", &
         maxval(all_busy(1, :))/max(mean(1), tiny(1.0_wp)), "; wall mean ", mean(2), " s, busiest/mean ", &
         maxval(all_busy(2, :))/max(mean(2), tiny(1.0_wp)), " (load balance)"
      write (error_unit, '(a)') trim(text)
   end subroutine report_balance
end module hillstab_mpi_runner

program hillstab_mpi
   use mpi_f08, only: MPI_Init, MPI_Comm_rank, MPI_Comm_size, MPI_COMM_WORLD
   use hillstab_mpi_runner, only: mpi_runner_t
   use hillstab_batch_run_cli, only: run_command_line
   use hillstab_batch_output_signals, only: install_signal_cleanup
   implicit none
   type(mpi_runner_t) :: runner
   integer :: status
   ! as hillstab: SIGINT, SIGTERM, SIGHUP remove the temporary output (rank 0 writes it);
   ! SIGXFSZ ignored, so a file-size limit is a write error that stops every rank (also
   ! while MPI_Init creates its shared-memory files); again after MPI_Init, in case the MPI
   ! library installed handlers of its own
   call install_signal_cleanup()
   call MPI_Init()
   call install_signal_cleanup()
   call MPI_Comm_rank(MPI_COMM_WORLD, runner%rank)
   call MPI_Comm_size(MPI_COMM_WORLD, runner%n_ranks)
   runner%program = "hillstab_mpi"
   runner%usage = [character(len=80) :: "mpirun -np N hillstab_mpi [--quiet] [--resume] SCENE.nml...", &
                   "hillstab_mpi --template TASK > SCENE.nml"]
   runner%description = [character(len=80) :: &
      "hillstab spread over MPI ranks: the points of chart, points and lyapunov scenes", &
      "are computed on all ranks (dynamic load balancing), rank 0 writes the same file", &
      "as a single-process hillstab run; other tasks run on rank 0. Rank 0 keeps the", &
      "checkpoint: --resume continues a run that hillstab or hillstab_mpi began."]
   call run_command_line(runner, status)
   ! every rank ends with the run's exit status (MPI finalized), silently
   stop status, quiet=.true.
end program hillstab_mpi

!> Task `poincare`: Poincaré sections (hillstab_pendulum_poincare) of several orbits of the
!> nonlinear pendulum at the (α, β, r0, g) of `&series`, one orbit per angle of
!> `&poincare phi0s`, over `&series periods` radial periods at the `&scene tolerance`.
!> With `same_energy` (the default) every orbit starts at rest at its φ0 with the energy
!> of the `&series` start (eq. (38) at `&series phi0`), so that all sections share one
!> (r, r') plane; otherwise each starts at r = ρ − a.
!>
!> `<output>_poincare.dat`: one block per orbit (blocks separated by two blank lines:
!> gnuplot `index`), one line per crossing of φ = 0 with φ' > 0.
module hillstab_batch_tasks_poincare
   use hillstab_core_kinds, only: wp, int64, version_string
   use hillstab_batch_output_progress, only: progress_t, progress_begin, progress_step, progress_end
   use hillstab_core_error, only: error_t, set_error, err_input, err_points_failed
   use hillstab_core_status, only: status_ok, status_failed
   use hillstab_pendulum_equations, only: pendulum_t, pendulum_from_chart, pendulum_initial_state, pendulum_energy
   use hillstab_pendulum_poincare, only: section_t, poincare_section, pendulum_state_at_energy
   use hillstab_batch_scene_types, only: scene_t, task_t, scene_header, output_path, open_scene_output
   use hillstab_batch_scene_file, only: scene_file_t, fail
   use hillstab_batch_scene_checks, only: require_finite
   use hillstab_batch_scene_declaration, only: new_group, group_t, group_reader_t, variable, var_real_list, var_logical, &
      begin_group, next_item, end_group, list_value
   use hillstab_batch_scene_group_series, only: series_plan_t, series_group, read_series_group, start_angle_text
   use hillstab_batch_output_columns, only: column_t, style_e17, style_integer, columns_text, put_row, all_columns
   use hillstab_batch_output_file, only: output_file_t, finish_output, write_header, write_text
   use hillstab_core_text, only: real_text, integer_text
   use hillstab_core_kinds, only: pi
   use hillstab_core_parallel, only: max_threads
   implicit none
   private
   public :: poincare_task_t, poincare_task, poincare_group

   !> Largest number of orbits (φ0 values) of a Poincaré section.
   integer, parameter :: max_orbits = 64

   !> The poincare task: orbits of the pendulum of `&series`, one per φ0.
   type, extends(task_t) :: poincare_task_t
      type(series_plan_t) :: series         !! the pendulum, its r0, g and periods
      real(wp), allocatable :: phi0s(:)     !! initial angles [rad], |φ0| < π
      !> .true.: every orbit has the energy of the `&series` start; .false.: each starts at
      !> r = ρ − a as eq. (38)
      logical :: same_energy = .true.
   contains
      procedure :: read => poincare_read
      procedure :: run => poincare_run
      procedure :: declarations => poincare_declarations
      procedure :: memory_bytes => poincare_memory_bytes
      procedure :: memory_variables => poincare_memory_variables
   end type poincare_task_t

contains

   !> The crossings an orbit may have, an estimate: one and a half for every swing of the
   !> linear pendulum (sqrt(beta)/pi swings a radial period; 0.48 crossings a period measured
   !> at beta = 2.47), and 64 (the section's first allocation).
   pure integer(int64) function crossings_bound(self)
      class(poincare_task_t), intent(in) :: self
      crossings_bound = int(1.5_wp*sqrt(max(self%series%beta, 0.0_wp))/pi*self%series%periods, int64) + 64
   end function crossings_bound

   !> An upper estimate of the memory of a run: every orbit's crossings (t, r, r': 24 bytes,
   !> in an array that doubles as it grows, and its copy when the last doubling or the final
   !> cut happens), held until the file is written, then the text of the longest orbit's
   !> rows (160 bytes a row) and a header line an orbit.
   function poincare_memory_bytes(self, scene) result(bytes)
      class(poincare_task_t), intent(in) :: self  !! the task
      type(scene_t), intent(in) :: scene  !! its scene
      integer(int64) :: bytes
      integer(int64) :: n, crossings
      n = size(self%phi0s)
      crossings = crossings_bound(self)
      bytes = n*crossings*48 + min(n, int(max_threads(), int64))*crossings*24 + crossings*160 + n*240
   end function poincare_memory_bytes

   !> What sets the memory of a run: the orbits and their periods.
   function poincare_memory_variables(self) result(text)
      class(poincare_task_t), intent(in) :: self  !! the task
      character(len=:), allocatable :: text
      text = "&series: periods: "//integer_text(self%series%periods)//" periods of "// &
             integer_text(size(self%phi0s))//" orbit(s) (&poincare phi0s), up to about "// &
             integer_text(crossings_bound(self))//" crossings each"
   end function poincare_memory_variables

   !> `&series`, `&poincare`.
   function poincare_declarations(self) result(groups)
      class(poincare_task_t), intent(in) :: self  !! the task
      type(group_t), allocatable :: groups(:)
      allocate (groups(2))
      groups(1) = series_group()
      groups(2) = poincare_group()
   end function poincare_declarations

   !> A poincare task before its scene is read.
   function poincare_task() result(task)
      type(poincare_task_t) :: task
      task%name = "poincare"
   end function poincare_task

   !> The declaration of `&poincare` (the default angles lie below 0.35 rad: states at rest
   !> at the default `&series` energy exist there).
   function poincare_group() result(group)
      type(group_t) :: group
      group = new_group("poincare", "the orbits of the section")
      call group%add("phi0s", var_real_list, "0.05, 0.1, 0.15, 0.2, 0.3", "initial angles of the orbits, rad, "// &
         "|phi0| < pi, up to "//integer_text(max_orbits)//" (one block each)", max_count=max_orbits)
      call group%add("same_energy", var_logical, ".true.", ".true.: every orbit starts at rest with the energy of "// &
         ""// &
         "the &series start (one section plane) | .false.: each at r = rho - a, eq. (38)")
   end function poincare_group

   !> `&series`, then `&poincare` (optional).
   subroutine poincare_read(self, file, scene, error)
      class(poincare_task_t), intent(inout) :: self  !! the task, its orbits filled in
      type(scene_file_t), intent(in) :: file      !! the scene file
      type(scene_t), intent(in) :: scene          !! the `&scene` settings
      type(error_t), allocatable, intent(out) :: error  !! err_input naming file, group and variable
      type(group_t) :: group
      real(wp) :: phi0s(max_orbits)
      logical :: same_energy
      namelist /poincare/ phi0s, same_energy
      type(group_reader_t) :: reader
      integer :: k
      allocate (self%groups(2))
      call read_series_group(file, series_group(), scene%model, self%series, self%groups(1), error, &
         samples=.false., warnings=self%warnings)
      if (allocated(error)) return
      group = poincare_group()
      call begin_group(reader, file, group, optional=.true.)
      read (reader%defaults, nml=poincare, iostat=reader%defaults_status, iomsg=reader%defaults_msg)
      if (reader%from_file) read (file%unit, nml=poincare, iostat=reader%ios, iomsg=reader%msg)
      do while (next_item(reader, file, group))
         read (reader%record, nml=poincare, iostat=reader%stat, iomsg=reader%message)
      end do
      write (reader%echo, nml=poincare, delim="apostrophe", iostat=reader%echo_status)
      call end_group(reader, file, group, self%groups(2), error)
      if (allocated(error)) return
      self%phi0s = list_value(self%groups(2), "phi0s", phi0s)
      if (size(self%phi0s) == 0) then
         call fail(error, file%path, group%name, "phi0s", "no initial angle given")
         return
      end if
      do k = 1, size(self%phi0s)
         call require_finite(file%path, group%name, "phi0s", self%phi0s(k), error)
         if (allocated(error)) return
         if (abs(self%phi0s(k)) >= pi) then
            call fail(error, file%path, group%name, "phi0s", "each angle must lie in (-pi, pi), got "// &
               real_text(self%phi0s(k)))
            return
         end if
      end do
      self%same_energy = same_energy
   end subroutine poincare_read

   !> The columns of `<output>_poincare.dat`.
   function poincare_columns() result(table)
      type(column_t), allocatable :: table(:)
      allocate (table(6))
      table(1) = column_t("orbit", "", "1, 2, ... in the order of phi0s (gnuplot index orbit-1)", style_integer)
      table(2) = column_t("phi0", "rad", "the orbit's initial angle", style_e17)
      table(3) = column_t("t", "s", "time of the crossing", style_e17)
      table(4) = column_t("r", "m", "r = z at the crossing", style_e17)
      table(5) = column_t("r_dot", "m/s", "r' = z' at the crossing", style_e17)
      table(6) = column_t("status", "", "0 ok; 2 the integration failed after the crossings written", style_integer)
   end function poincare_columns

   !> The poincare task. An angle at which no state at rest has the common energy is bad
   !> input (err_input naming `&poincare phi0s`); an orbit whose integration fails is
   !> written with status 2 and the crossings found before, and the run reports
   !> err_points_failed after writing the file.
   subroutine poincare_run(self, scene, quiet, error)
      class(poincare_task_t), intent(in) :: self  !! the task
      type(scene_t), intent(in) :: scene  !! a validated poincare scene
      logical, intent(in) :: quiet  !! no progress on stderr (orbits done)
      !> err_input (an angle without a state of the common energy), err_io, err_points_failed
      type(error_t), allocatable, intent(out) :: error
      type(pendulum_t) :: p
      type(section_t), allocatable :: sections(:)
      type(error_t), allocatable :: cause
      type(output_file_t) :: file
      real(wp), allocatable :: starts(:, :)
      integer, allocatable :: statuses(:)
      character(len=:), allocatable :: lines(:), failure
      character(len=200) :: summary
      real(wp) :: energy
      integer :: k, n, j, first_failed
      type(column_t), allocatable :: table(:)
      type(progress_t) :: progress

      n = size(self%phi0s)
      call pendulum_from_chart(self%series%alpha, self%series%beta, scene%epsilon, self%series%r0, &
         self%series%g, p, cause)
      if (allocated(cause)) then
         call set_error(error, err_input, scene%source//": &series: "//cause%message)
         return
      end if
      energy = pendulum_energy(p, pendulum_initial_state(p, self%series%phi0, self%series%vx0, self%series%vz0))
      allocate (starts(4, n), sections(n), statuses(n), stat=k)
      if (k /= 0) then
         call set_error(error, err_input, scene%source//": "//self%memory_variables()//": the orbits cannot be "// &
            "allocated (out of memory)")
         return
      end if
      do k = 1, n
         if (self%same_energy) then
            call pendulum_state_at_energy(p, self%phi0s(k), energy, starts(:, k), cause)
            if (allocated(cause)) then
               call set_error(error, err_input, scene%source//": &poincare: phi0s: at phi0 = "// &
                  real_text(self%phi0s(k))//" no state at rest has the energy E = "//real_text(energy)// &
                  " J/kg of the &series start (set same_energy = .false. or change the angle)")
               return
            end if
         else
            starts(:, k) = pendulum_initial_state(p, self%phi0s(k))
         end if
      end do

      call open_scene_output(scene, file, error)
      if (allocated(error)) return
      call progress_begin(progress, int(n, int64), quiet, "orbits")
      !$omp parallel do schedule(dynamic) default(shared) private(k, cause)
      do k = 1, n
         call poincare_section(p, starts(:, k), self%series%periods*p%period, scene%method%tolerance, sections(k), &
            cause)
         statuses(k) = merge(status_failed, status_ok, allocated(cause))
         call progress_step(progress)
      end do
      !$omp end parallel do
      call progress_end(progress)

      table = poincare_columns()
      call write_header(file, header(), columns_text(table, all_columns(table)), error)
      do k = 1, n
         if (allocated(error)) exit
         if (k > 1) call write_text(file, new_line("a"), error)
         if (allocated(error)) exit
         if (sections(k)%n == 0) then
            ! an empty block still separates the orbits: one comment line
            call write_text(file, "# orbit "//integer_text(k)//": no crossing", error)
            cycle
         end if
         lines = block_lines(k)
         do j = 1, size(lines)
            if (allocated(error)) exit
            call write_text(file, trim(lines(j)), error)
         end do
      end do
      call finish_output(file, error)
      if (allocated(error)) return
      if (any(statuses == status_failed)) then
         first_failed = findloc(statuses, status_failed, dim=1)
         call poincare_section(p, starts(:, first_failed), self%series%periods*p%period, scene%method%tolerance, &
            sections(first_failed), cause)
         failure = "integration failed"
         if (allocated(cause)) failure = cause%message
         call set_error(error, err_points_failed, scene%source//": &poincare: "//integer_text(count(statuses == &
            status_failed))//" of "//integer_text(n)//" orbit(s) could not be integrated to the end, written with "// &
            "status 2 and their crossings so far to "//output_path(scene)//"; first at phi0 = "// &
            real_text(self%phi0s(first_failed))//": "//failure)
      end if
   contains
      function header() result(text)
         character(len=:), allocatable :: text(:)
         character(len=240) :: extra(5 + n)
         integer :: m, i
         m = 0
         m = m + 1; extra(m) = "Poincare section: crossings of phi = 0 with phi' > 0 (x = 0, x' > 0, z > 0), located "// &
            "on DOP853's dense output (Newton), tolerance "//real_text(scene%method%tolerance)
         m = m + 1; extra(m) = "pendulum: alpha = "//real_text(p%alpha)//", beta = "//real_text(p%beta)//", rho = "// &
            real_text(p%rho)//" m, omega = "//real_text(p%omega)//" rad/s, radial period T = "//real_text(p%period)// &
            " s, "//integer_text(self%series%periods)//" periods"
         if (self%same_energy) then
            m = m + 1; extra(m) = "every orbit starts at rest at its phi0 with the energy E = "//real_text(energy)// &
               " J/kg of the &series start at phi0 = "//start_angle_text(self%series%phi0)//" (one section plane)"
         else
            m = m + 1; extra(m) = "every orbit starts at rest at r = rho - a (eq. (38)) at its phi0 (energies differ)"
         end if
         m = m + 1; extra(m) = "orbit: 1, 2, ... in the order of phi0s (one block each, gnuplot index orbit-1); "// &
            "t [s], r [m], r_dot [m/s] at each crossing (there r = z, r_dot = z')"
         m = m + 1; extra(m) = "status: 0 ok; 2 the integration failed after the crossings written"
         do i = 1, n
            write (summary, '(a,i0,a,a,a,i0,a,a,a,a)') "orbit ", i, ": phi0 = ", real_text(self%phi0s(i)), &
               ", ", sections(i)%n, " crossings, energy drift ", trim(real_text(sections(i)%energy_drift)), &
               ", status ", integer_text(statuses(i))
            m = m + 1; extra(m) = summary
         end do
         text = scene_header(scene, "hillstab "//version_string//": Poincare sections of the nonlinear elastic pendulum", &
                             extra(:m))
      end function header

      function block_lines(k) result(text)
         integer, intent(in) :: k
         character(len=:), allocatable :: text(:)
         integer :: i, pos
         allocate (character(len=160) :: text(sections(k)%n))
         do i = 1, sections(k)%n
            pos = 0
            call put_row(table, all_columns(table), [real(k, wp), self%phi0s(k), sections(k)%points(1:3, i), &
                         real(statuses(k), wp)], text(i), pos)
            text(i)(pos + 1:) = ""
         end do
      end function block_lines
   end subroutine poincare_run
end module hillstab_batch_tasks_poincare

!> Task `poincare`: Poincaré sections (hillstab_pendulum_poincare) of several orbits of the
!> nonlinear pendulum at the (α, β, r0, g) of `&series`, one orbit per angle of
!> `&poincare phi0s`, over `&series periods` radial periods at the `&scene tolerance`.
!> With `same_energy` (the default) every orbit starts at rest at its φ0 with the energy
!> of the `&series` start (eq. (38) at `&series phi0`), so that all sections share one
!> (r, r') plane; otherwise each starts at r = ρ − a.
!>
!> `<output>_poincare.dat`: one block per orbit (blocks separated by two blank lines:
!> gnuplot `index`), one line per crossing of φ = 0 with φ' > 0.
module hillstab_batch_task_poincare
   use hillstab_core_kinds, only: wp, version_string
   use hillstab_core_error, only: error_t, set_error, err_input, err_points_failed
   use hillstab_core_status, only: status_ok, status_failed
   use hillstab_pendulum_equations, only: pendulum_t, pendulum_from_chart, pendulum_initial_state, pendulum_energy
   use hillstab_pendulum_poincare, only: section_t, poincare_section, pendulum_state_at_energy
   use hillstab_batch_scene, only: scene_t, scene_header, real_text, integer_text, output_path
   use hillstab_batch_output, only: output_file_t, open_output, finish_output, write_header, write_text
   use hillstab_core_text, only: put_es
   implicit none
   private
   public :: run_poincare, poincare_columns

contains

   !> Column names of `<output>_poincare.dat`.
   pure function poincare_columns() result(names)
      character(len=:), allocatable :: names
      names = "orbit phi0 t r r_dot status"
   end function poincare_columns

   !> The poincare task. An angle at which no state at rest has the common energy is bad
   !> input (err_input naming `&poincare phi0s`); an orbit whose integration fails is
   !> written with status 2 and the crossings found before, and the run reports
   !> err_points_failed after writing the file.
   subroutine run_poincare(scene, quiet, error)
      type(scene_t), intent(in) :: scene  !! a validated poincare scene
      logical, intent(in) :: quiet  !! unused: the task is short
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

      n = size(scene%poincare%phi0s)
      call pendulum_from_chart(scene%series%alpha, scene%series%beta, scene%epsilon, scene%series%r0, &
         scene%series%g, p, cause)
      if (allocated(cause)) then
         call set_error(error, err_input, scene%source//": &series: "//cause%message)
         return
      end if
      energy = pendulum_energy(p, pendulum_initial_state(p, scene%series%phi0, scene%series%vx0, scene%series%vz0))
      allocate (starts(4, n), sections(n), statuses(n))
      do k = 1, n
         if (scene%poincare%same_energy) then
            call pendulum_state_at_energy(p, scene%poincare%phi0s(k), energy, starts(:, k), cause)
            if (allocated(cause)) then
               call set_error(error, err_input, scene%source//": &poincare: phi0s: at phi0 = "// &
                  real_text(scene%poincare%phi0s(k))//" no state at rest has the energy E = "//real_text(energy)// &
                  " J/kg of the &series start (set same_energy = .false. or change the angle)")
               return
            end if
         else
            starts(:, k) = pendulum_initial_state(p, scene%poincare%phi0s(k))
         end if
      end do

      call open_output(file, output_path(scene), error, context=scene%source//": &scene: output: ")
      if (allocated(error)) return
      !$omp parallel do schedule(dynamic) default(shared) private(k, cause)
      do k = 1, n
         call poincare_section(p, starts(:, k), scene%series%periods*p%period, scene%method%tolerance, sections(k), &
            cause)
         statuses(k) = merge(status_failed, status_ok, allocated(cause))
      end do
      !$omp end parallel do

      call write_header(file, header(), poincare_columns(), error)
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
         call poincare_section(p, starts(:, first_failed), scene%series%periods*p%period, scene%method%tolerance, &
            sections(first_failed), cause)
         failure = "integration failed"
         if (allocated(cause)) failure = cause%message
         call set_error(error, err_points_failed, scene%source//": &poincare: "//integer_text(count(statuses == &
            status_failed))//" of "//integer_text(n)//" orbit(s) could not be integrated to the end, written with "// &
            "status 2 and their crossings so far to "//output_path(scene)//"; first at phi0 = "// &
            real_text(scene%poincare%phi0s(first_failed))//": "//failure)
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
            " s, "//integer_text(scene%series%periods)//" periods"
         if (scene%poincare%same_energy) then
            m = m + 1; extra(m) = "every orbit starts at rest at its phi0 with the energy E = "//real_text(energy)// &
               " J/kg of the &series start (one section plane)"
         else
            m = m + 1; extra(m) = "every orbit starts at rest at r = rho - a (eq. (38)) at its phi0 (energies differ)"
         end if
         m = m + 1; extra(m) = "orbit: 1, 2, ... in the order of phi0s (one block each, gnuplot index orbit-1); "// &
            "t [s], r [m], r_dot [m/s] at each crossing (there r = z, r_dot = z')"
         m = m + 1; extra(m) = "status: 0 ok; 2 the integration failed after the crossings written"
         do i = 1, n
            write (summary, '(a,i0,a,a,a,i0,a,a,a,a)') "orbit ", i, ": phi0 = ", real_text(scene%poincare%phi0s(i)), &
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
            write (text(i), '(i0)') k
            pos = len_trim(text(i))
            text(i)(pos + 1:pos + 1) = " "
            pos = pos + 1
            call put_es(text(i), pos, scene%poincare%phi0s(k), 16)
            text(i)(pos + 1:pos + 1) = " "
            pos = pos + 1
            call put_es(text(i), pos, sections(k)%points(1, i), 16)
            text(i)(pos + 1:pos + 1) = " "
            pos = pos + 1
            call put_es(text(i), pos, sections(k)%points(2, i), 16)
            text(i)(pos + 1:pos + 1) = " "
            pos = pos + 1
            call put_es(text(i), pos, sections(k)%points(3, i), 16)
            text(i)(pos + 1:) = " "//integer_text(statuses(k))
         end do
      end function block_lines
   end subroutine run_poincare
end module hillstab_batch_task_poincare

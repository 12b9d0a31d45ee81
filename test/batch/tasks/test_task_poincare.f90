!> Tests of the poincare task (hillstab_batch_tasks_poincare) through `run_scene_file`: one
!> block per orbit (gnuplot index), crossings in time order; with same_energy every
!> crossing lies inside the region of the (r, r') plane that the common energy allows
!> (an independent check from E = ½(x'² + r'²) + ½ω²(r − r0)² − g r at x = 0); the
!> first orbit's crossings equal the library's section; bad input names the variable.
module test_task_poincare
   use hillstab_core_kinds, only: wp
   use hillstab_core_error, only: error_t, err_input
   use hillstab_pendulum_equations, only: pendulum_t, pendulum_from_chart, pendulum_initial_state, pendulum_energy
   use hillstab_pendulum_poincare, only: section_t, poincare_section, pendulum_state_at_energy
   use hillstab_testing
   use hillstab_test_files, only: run_text_scene
   use hillstab_test_scratch, only: padded, scratch_prefix, read_lines, file_exists, delete_file, contains_text
   implicit none
   private
   public :: collect_task_poincare

contains

   function collect_task_poincare() result(suite)
      type(testsuite_t) :: suite
      suite = new_testsuite("task_poincare", [ &
         new_unittest("orbits_of_one_energy", orbits_of_one_energy), &
         new_unittest("bad_input", bad_input)])
   end function collect_task_poincare

   subroutine orbits_of_one_energy(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(error_t), allocatable :: error
      character(len=:), allocatable :: written
      character(len=1024), allocatable :: lines(:)
      type(pendulum_t) :: p
      type(section_t) :: section
      real(wp) :: row(6), e, room, last_t, y0(4)
      integer :: k, ios, n_rows(3), orbit, n_double_blank
      logical :: ordered
      call run_text_scene("poinc", [padded("&scene task='poincare', tolerance=1e-10, output='"//scratch_prefix("poinc")// &
         "' /"), padded("&series alpha=7.48, beta=2.47, phi0=0.017, periods=60 /"), &
         padded("&poincare phi0s=0.02, 0.4, 0.8 /")], error, written)
      call check(ctx, .not. allocated(error), "runs")
      if (allocated(error)) return
      call pendulum_from_chart(7.48_wp, 2.47_wp, 0.0_wp, 0.1_wp, 9.81_wp, p, error)
      e = pendulum_energy(p, pendulum_initial_state(p, 0.017_wp))
      lines = read_lines(written)
      n_rows = 0
      room = huge(1.0_wp)
      ordered = .true.
      last_t = -1.0_wp
      n_double_blank = 0
      do k = 1, size(lines)
         if (lines(k)(1:1) == "#") cycle
         if (len_trim(lines(k)) == 0) then
            if (k > 1) then
               if (len_trim(lines(k - 1)) == 0) n_double_blank = n_double_blank + 1
            end if
            last_t = -1.0_wp
            cycle
         end if
         read (lines(k), *, iostat=ios) row
         call check(ctx, ios == 0, "six numbers")
         orbit = nint(row(1))
         if (orbit >= 1 .and. orbit <= 3) n_rows(orbit) = n_rows(orbit) + 1
         ordered = ordered .and. row(3) > last_t
         last_t = row(3)
         ! x'^2 = 2E - r'^2 - omega^2 (r - r0)^2 + 2 g r must be positive at a crossing
         room = min(room, 2.0_wp*e - row(5)**2 - p%omega**2*(row(4) - p%r0)**2 + 2.0_wp*p%g*row(4))
      end do
      call check(ctx, all(n_rows > 10), "three orbits with crossings")
      call check(ctx, n_double_blank == 2, "blocks separated by two blank lines")
      call check(ctx, ordered, "times increase within an orbit")
      call check(ctx, room > 0.0_wp, "inside the common energy's region")
      ! the first orbit against the library
      call pendulum_state_at_energy(p, 0.02_wp, e, y0, error)
      call poincare_section(p, y0, 60*p%period, 1.0e-10_wp, section, error)
      call check(ctx, section%n == n_rows(1), "orbit 1: the library's crossings")
      call delete_file(written)
   end subroutine orbits_of_one_energy

   subroutine bad_input(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(error_t), allocatable :: error
      character(len=:), allocatable :: written
      call run_text_scene("poinc_bad", [padded("&scene task='poincare', output='"//scratch_prefix("poinc_bad")//"' /"), &
         padded("&series alpha=7.48, beta=2.47 /"), padded("&poincare phi0s=0.1, 4.0 /")], error, written)
      call check(ctx, allocated(error), "phi0 = 4 refused")
      if (allocated(error)) call check(ctx, error%code == err_input .and. contains_text(error%message, "&poincare") &
         .and. contains_text(error%message, "phi0s"), "names &poincare phi0s: "//error%message)
      ! at phi0 = 3 (nearly upside down) no state at rest has the energy of a start near the bottom
      call run_text_scene("poinc_bad", [padded("&scene task='poincare', output='"//scratch_prefix("poinc_bad")//"' /"), &
         padded("&series alpha=0.5, beta=2.47, phi0=0.01 /"), padded("&poincare phi0s=3.0 /")], error, written)
      call check(ctx, allocated(error), "unreachable energy refused")
      if (allocated(error)) call check(ctx, error%code == err_input .and. contains_text(error%message, "phi0s"), &
         "names phi0s: "//error%message)
      call check(ctx, .not. file_exists(scratch_prefix("poinc_bad")//"_poincare.dat"), "no file")
   end subroutine bad_input
end module test_task_poincare

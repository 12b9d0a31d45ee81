!> Benchmark of the resonance regions' tips (hillstab_curves_regions) on Bolotin's damped
!> column of three modes (data/scenes/column_regions.nml): every region up to order 2 over
!> Om in [0.5, 20], P1 in [0, 1.5], against the loop a user would write on the same library:
!> a scan of 121 frequencies, at each the drive sampled (150 values) and the first unstable
!> one bisected (largest |λ| of all multipliers, to 1e-10), then a golden-section search of
!> the frequency around every local minimum of that scan, a bisection at each of its points.
!> Both are measured against the tips found at a tighter tolerance (1e-12 on Φ and the
!> tips), and both counts are of monodromies; ours without the sweep of the top drive for
!> instability outside every region (which the loop does not do), and its cost printed
!> beside. Prints a table and writes
!> out/bench_regions.dat (one line per region: our tip and error, the loop's, the counts).
!> Times are wall-clock; run with OMP_NUM_THREADS=1 to compare one thread with the loop's one.
!> Usage: hillstab_bench_regions [--out FILE]
program hillstab_bench_regions
   use hillstab_core_kinds, only: wp
   use hillstab_core_error, only: error_t
   use hillstab_hill_system, only: system_form_t, prepare_system
   use hillstab_hill_system_equation, only: equations_system_t
   use hillstab_hill_system_floquet, only: floquet_t
   use hillstab_integrate_system, only: system_method_t, system_monodromy_t, system_nodes_t
   use hillstab_integrate_system_point, only: system_point
   use hillstab_curves_critical, only: along_beta
   use hillstab_curves_oracle, only: system_oracle_t
   use hillstab_curves_regions, only: region_t, find_regions, region_found, region_kind_name
   use hillstab_batch_scene_types, only: scene_t
   use hillstab_batch_run_read, only: read_scene
   implicit none
   integer, parameter :: n_scan = 121, n_drive = 150
   real(wp), parameter :: f_min = 0.5_wp, f_max = 20.0_wp, d_min = 0.0_wp, d_max = 1.5_wp
   type(equations_system_t) :: column
   type(scene_t) :: scene
   type(system_oracle_t) :: oracle, fine
   type(region_t), allocatable :: regions(:), reference(:), swept_regions(:)
   type(error_t), allocatable :: error
   real(wp) :: f(n_scan), c(n_scan), t0, t1, t_ours, t_loop, loop_tip(2), worst_ours, worst_loop
   integer :: j, k, loop_count, ours, unit, ios, swept
   character(len=256) :: out, argument
   out = "out/bench_regions.dat"
   j = 1
   do while (j <= command_argument_count())
      call get_command_argument(j, argument)
      if (trim(argument) == "--out") then
         j = j + 1
         call get_command_argument(j, out)
      end if
      j = j + 1
   end do
   ! the column of the shipped scene (the one the guide charts)
   call read_scene("data/scenes/column_equations.nml", scene, error)
   if (.not. allocated(error)) then
      select type (system => scene%system)
      type is (equations_system_t)
         column = system
      class default
         error stop "data/scenes/column_equations.nml: not an &equations system"
      end select
   end if
   if (allocated(error)) error stop "the column"
   allocate (oracle%system, source=column)
   oracle%drive_axis = along_beta
   oracle%method = system_method_t(tolerance=1.0e-10_wp)
   fine = oracle
   fine%method%tolerance = 1.0e-12_wp

   t0 = wall()
   call find_regions(oracle, f_min, f_max, d_min, d_max, 2, 1.0e-10_wp, 32, regions, error, cover=0)
   t1 = wall()
   if (allocated(error)) error stop "regions"
   t_ours = t1 - t0
   ours = sum(regions%evaluations)
   call find_regions(fine, f_min, f_max, d_min, d_max, 2, 1.0e-12_wp, 32, reference, error, cover=0)
   if (allocated(error)) error stop "reference regions"
   ! the sweep of the top drive a regions task adds by default (400 samples)
   call find_regions(oracle, f_min, f_max, d_min, d_max, 2, 1.0e-10_wp, 32, swept_regions, error, swept=swept)
   if (allocated(error)) error stop "swept regions"

   ! the user's loop
   loop_count = 0
   t0 = wall()
   f = [(f_min + (f_max - f_min)*real(j - 1, wp)/real(n_scan - 1, wp), j=1, n_scan)]
   do j = 1, n_scan
      c(j) = least_unstable(f(j))
   end do
   t1 = wall()
   t_loop = t1 - t0

   open (newunit=unit, file=trim(out)//".part", status="replace", action="write", iostat=ios)
   if (ios /= 0) error stop "cannot write the output"
   write (unit, '(a)') "# hillstab_bench_regions: the tips of Bolotin's damped column (3 modes, order 2) against a "// &
      "scan-and-bisect loop on the same library"
   write (unit, '(a)') "# columns: kind order mode_i mode_j Om P1 P1_error_ours Om_loop P1_loop P1_error_loop"
   print '(a)', "region            tip Om        tip P1           error (ours)  error (loop: scan 121 x 150, "// &
      "bisect, golden)"
   worst_ours = 0.0_wp
   worst_loop = 0.0_wp
   do k = 1, size(regions)
      if (regions(k)%status /= region_found .or. reference(k)%status /= region_found) cycle
      call loop_tip_near(reference(k)%frequency, loop_tip)
      worst_ours = max(worst_ours, abs(regions(k)%drive - reference(k)%drive)/reference(k)%drive)
      worst_loop = max(worst_loop, abs(loop_tip(2) - reference(k)%drive)/reference(k)%drive)
      print '(a10,i2,1x,i1,i1,f12.6,es18.10,2es14.2)', region_kind_name(regions(k)%kind), regions(k)%order, &
         regions(k)%modes, reference(k)%frequency, reference(k)%drive, &
         abs(regions(k)%drive - reference(k)%drive)/reference(k)%drive, &
         abs(loop_tip(2) - reference(k)%drive)/reference(k)%drive
      write (unit, '(4i3,6es18.10)') regions(k)%kind, regions(k)%order, regions(k)%modes, reference(k)%frequency, &
         reference(k)%drive, abs(regions(k)%drive - reference(k)%drive), loop_tip, &
         abs(loop_tip(2) - reference(k)%drive)
   end do
   t1 = wall()
   t_loop = t_loop + (t1 - t0)
   print '(a,i8,a,f8.3,a,es9.2)', "ours:  ", ours, " monodromies, ", t_ours, " s, worst tip error ", worst_ours
   print '(a,i8,a,f8.3,a,es9.2)', "loop:  ", loop_count, " monodromies, ", t_loop, " s, worst tip error ", worst_loop
   print '(a,f8.1)', "fewer monodromies: ", real(loop_count, wp)/real(ours, wp)
   print '(a,i8,a,f8.1,a)', "with the sweep of the top drive: +", swept, " monodromies (", &
      real(loop_count, wp)/real(ours + swept, wp), "x fewer than the loop)"
   write (unit, '(a,i0,a,i0,a,i0,a,es9.2,a,es9.2)') "# monodromies: ours ", ours, ", loop ", loop_count, &
      ", the sweep of the top drive ", swept, "; worst relative tip error: ours ", worst_ours, ", loop ", worst_loop
   close (unit)
   call execute_command_line("mv -f '"//trim(out)//".part' '"//trim(out)//"'")
   print '(a)', "wrote "//trim(out)

contains

   !> Wall-clock seconds.
   real(wp) function wall()
      integer(8) :: count, rate
      call system_clock(count, rate)
      wall = real(count, wp)/real(rate, wp)
   end function wall

   !> ln of the largest |λ| of all multipliers at (Om, P1).
   real(wp) function log_largest(om, p1)
      real(wp), intent(in) :: om, p1
      type(system_form_t) :: form
      type(system_nodes_t) :: nodes
      type(system_monodromy_t) :: monodromy
      type(floquet_t) :: floquet
      type(error_t), allocatable :: e
      call prepare_system(column, 0.0_wp, form, e, om)
      call system_point(column, form, om, p1, system_method_t(tolerance=1.0e-10_wp), nodes, monodromy, floquet, e)
      log_largest = floquet%log_modulus(1)
      loop_count = loop_count + 1
   end function log_largest

   !> The least P1 of the drive samples where the column is unstable at Om, bisected to 1e-10
   !> (huge when stable up to d_max).
   real(wp) function least_unstable(om) result(p1)
      real(wp), intent(in) :: om
      real(wp) :: lo, hi, mid
      integer :: i
      p1 = huge(1.0_wp)
      lo = d_min
      do i = 1, n_drive
         hi = d_min + (d_max - d_min)*real(i - 1, wp)/real(n_drive - 1, wp)
         if (log_largest(om, hi) > 0.0_wp) exit
         lo = hi
         if (i == n_drive) return
      end do
      if (hi == d_min) then
         p1 = d_min
         return
      end if
      do while (hi - lo > 1.0e-10_wp)
         mid = 0.5_wp*(lo + hi)
         if (log_largest(om, mid) > 0.0_wp) then
            hi = mid
         else
            lo = mid
         end if
      end do
      p1 = 0.5_wp*(lo + hi)
   end function least_unstable

   !> The loop's tip near Om: the scan's local minimum nearest it, refined by golden section
   !> over its two neighbours' interval until it is 1e-5 Om wide.
   subroutine loop_tip_near(om, tip)
      real(wp), intent(in) :: om
      real(wp), intent(out) :: tip(2)
      real(wp), parameter :: ratio = 0.6180339887498949_wp
      real(wp) :: a, b, x1, x2, c1, c2
      integer :: j, best
      best = 0
      do j = 2, n_scan - 1
         if (c(j) <= c(j - 1) .and. c(j) <= c(j + 1) .and. c(j) < huge(1.0_wp)) then
            if (best == 0) then
               best = j
            else if (abs(f(j) - om) < abs(f(best) - om)) then
               best = j
            end if
         end if
      end do
      tip = [om, huge(1.0_wp)]
      if (best == 0) return
      a = f(best - 1)
      b = f(best + 1)
      x1 = b - ratio*(b - a)
      x2 = a + ratio*(b - a)
      c1 = least_unstable(x1)
      c2 = least_unstable(x2)
      do while (b - a > 1.0e-5_wp*om)
         if (c1 <= c2) then
            b = x2
            x2 = x1
            c2 = c1
            x1 = b - ratio*(b - a)
            c1 = least_unstable(x1)
         else
            a = x1
            x1 = x2
            c1 = c2
            x2 = a + ratio*(b - a)
            c2 = least_unstable(x2)
         end if
      end do
      tip = merge([x1, c1], [x2, c2], c1 <= c2)
   end subroutine loop_tip_near
end program hillstab_bench_regions

!> Tests of the resonance regions and their tips (hillstab_curves_regions, task `regions`):
!> the damped Mathieu equation x'' + 2ζx' + (1 + h cos Wt)x = 0, written as an equation in
!> physical time, whose principal tip has the drive ratio h → 4ζ as ζ → 0 (20 damping ratios)
!> and equals a brute-force scan of W with the critical drive at each (a second search on
!> the same equation); its principal region's width at a small drive against Bolotin's
!> first approximation; the undamped Mathieu model's regions at the resonances (kπ/2)² with
!> their edges on GSL's characteristic values, and its instability below a_0 (no resonance)
!> found by the sweep of the top drive; the tips of a damped column of three modes
!> against a scan-and-bisect on the largest multiplier and against an independent reference
!> (numpy and scipy: data/reference/column_tips.dat); the task's file against the library
!> and its header rerunning it; bad input refused naming the file, the group and the variable.
module test_regions
   use hillstab_core_kinds, only: wp, pi, pi2
   use hillstab_core_text, only: real_text
   use hillstab_core_error, only: error_t, err_input
   use hillstab_hill_model_mathieu, only: mathieu_model_t
   use hillstab_hill_model_equation, only: equation_model_t
   use hillstab_hill_mathieu, only: mathieu_transition_beta, mathieu_kind_a, mathieu_kind_b
   use hillstab_hill_system, only: system_form_t, prepare_system
   use hillstab_hill_system_equation, only: equations_system_t
   use hillstab_hill_system_floquet, only: floquet_t
   use hillstab_integrate_monodromy, only: method_t
   use hillstab_integrate_system, only: system_method_t, system_monodromy_t, system_nodes_t
   use hillstab_integrate_system_point, only: system_point
   use hillstab_curves_critical, only: critical_drive_t, critical_drives_along, along_alpha, along_beta
   use hillstab_curves_oracle, only: scalar_oracle_t, system_oracle_t
   use hillstab_curves_regions
   use hillstab_testing
   use hillstab_test_files, only: run_text_scene, check_rerun
   use hillstab_test_problems, only: damped_mathieu, damped_column
   use hillstab_test_scratch, only: scratch_prefix, read_lines, file_exists, delete_file
   implicit none
   private
   public :: collect_regions

contains

   function collect_regions() result(suite)
      type(testsuite_t) :: suite
      suite = new_testsuite("regions", [ &
         new_unittest("damped_mathieu_tip_law", damped_mathieu_tip_law), &
         new_unittest("damped_mathieu_against_scan", damped_mathieu_against_scan), &
         new_unittest("bolotin_principal_width", bolotin_principal_width), &
         new_unittest("undamped_mathieu_theory", undamped_mathieu_theory), &
         new_unittest("column_tips_against_scan", column_tips_against_scan), &
         new_unittest("column_tips_against_reference", column_tips_against_reference), &
         new_unittest("task_file", task_file), &
         new_unittest("bad_input_refused", bad_input_refused)])
   end function collect_regions

   !> The principal region (order 1, simple) of a region list; 0 when there is none.
   pure integer function principal(regions, mode)
      type(region_t), intent(in) :: regions(:)
      integer, intent(in) :: mode
      integer :: k
      principal = 0
      do k = 1, size(regions)
         if (regions(k)%kind == region_simple .and. regions(k)%order == 1 .and. regions(k)%modes(1) == mode) &
            principal = k
      end do
   end function principal

   !> At 20 damping ratios ζ from 0.001 to 0.069, the principal tip: found and confirmed, its
   !> drive ratio h* within ζ² of 4ζ (the first-order law h* → 4ζ; its next term is of order ζ²)
   !> and W* within 2ζ² of 2, its drive error below 1e-6 relative.
   subroutine damped_mathieu_tip_law(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(scalar_oracle_t) :: oracle
      type(region_t), allocatable :: regions(:)
      type(error_t), allocatable :: error
      real(wp) :: zeta, worst
      integer :: j, k
      worst = 0.0_wp
      do j = 1, 20
         zeta = 0.001_wp*1.25_wp**(j - 1)
         call damped_mathieu(zeta, oracle, error)
         if (.not. allocated(error)) &
            call find_regions(oracle, 1.5_wp, 3.0_wp, 0.0_wp, 0.5_wp, 1, 1.0e-10_wp, 32, regions, error)
         call check(ctx, .not. allocated(error), "regions at zeta = "//real_text(zeta))
         if (allocated(error)) return
         k = principal(regions, 1)
         call check(ctx, k > 0, "the principal region at zeta = "//real_text(zeta))
         if (k == 0) cycle
         call check(ctx, regions(k)%status == region_found, "its tip found and confirmed")
         call check(ctx, abs(regions(k)%drive/(4.0_wp*zeta) - 1.0_wp) <= zeta**2, "h*/(4 zeta) = "// &
                    real_text(regions(k)%drive/(4.0_wp*zeta))//" at zeta = "//real_text(zeta))
         call check(ctx, abs(regions(k)%frequency - 2.0_wp) <= 2.0_wp*zeta**2 + regions(k)%frequency_error, &
                    "W* = "//real_text(regions(k)%frequency)//" at zeta = "//real_text(zeta))
         call check(ctx, regions(k)%drive_error <= 1.0e-6_wp*regions(k)%drive, "drive error "// &
                    real_text(regions(k)%drive_error))
         worst = max(worst, abs(regions(k)%drive/(4.0_wp*zeta) - 1.0_wp)/zeta**2)
      end do
      call check(ctx, worst > 0.0_wp, "the tips measured")
   end subroutine damped_mathieu_tip_law

   !> The principal tip at three damping ratios against a brute-force search on the same
   !> equation: 41 frequencies across the tip, the least critical drive at each by
   !> `critical_drives_along` (64 samples of h, then refined), the minimum by the parabola
   !> through the three lowest. The tips agree within 1e-6 relative, and the search (with the
   !> region's width at the top) costs at least 8 times fewer monodromies than this scan,
   !> which is already told where the tip lies.
   subroutine damped_mathieu_against_scan(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp), parameter :: zetas(2) = [0.004_wp, 0.05_wp]
      integer, parameter :: n_scan = 31, n_samples = 64
      type(scalar_oracle_t) :: oracle
      type(region_t), allocatable :: regions(:)
      type(critical_drive_t), allocatable :: drives(:)
      type(error_t), allocatable :: error
      real(wp) :: w(n_scan), c(n_scan), zeta, width, h_min, best
      integer :: z, j, k, m, scan_cost
      do z = 1, size(zetas)
         zeta = zetas(z)
         call damped_mathieu(zeta, oracle, error)
         if (.not. allocated(error)) &
            call find_regions(oracle, 1.5_wp, 3.0_wp, 0.0_wp, 0.5_wp, 1, 1.0e-10_wp, 32, regions, error)
         call check(ctx, .not. allocated(error), "regions")
         if (allocated(error)) return
         k = principal(regions, 1)
         call check(ctx, k > 0, "the principal region")
         if (k == 0) return
         ! the scan: W across the tip (the region is about 4 zeta wide at twice the tip's drive)
         width = 2.0_wp*zeta
         w = [(regions(k)%frequency - width + 2.0_wp*width*real(j - 1, wp)/real(n_scan - 1, wp), j=1, n_scan)]
         scan_cost = 0
         do j = 1, n_scan
            call critical_drives_along(oracle%model, along_beta, w(j), 0.0_wp, 0.5_wp, 0.0_wp, oracle%method, &
                                       n_samples, drives, error)
            call check(ctx, .not. allocated(error) .and. size(drives) > 0, "a critical drive at W = "// &
                       real_text(w(j)))
            if (allocated(error) .or. size(drives) == 0) return
            c(j) = drives(1)%alpha
            ! the samples, the refinement (about 40 steps to 1e-12) and the two confirmations
            scan_cost = scan_cost + n_samples + 42
         end do
         m = minloc(c, 1)
         call check(ctx, m > 1 .and. m < n_scan, "the scan's least drive lies inside it")
         if (m == 1 .or. m == n_scan) return
         ! the parabola's vertex through the three lowest
         h_min = 0.5_wp*(c(m - 1) - c(m + 1))/(c(m - 1) - 2.0_wp*c(m) + c(m + 1))
         best = c(m) - 0.25_wp*(c(m - 1) - c(m + 1))*h_min
         call check_close(ctx, regions(k)%drive, best, rel=1.0e-6_wp, message="the tip against the scan at zeta = "// &
                          real_text(zeta))
         call check(ctx, abs(regions(k)%frequency - (w(m) + h_min*(w(2) - w(1)))) <= 0.05_wp*(w(2) - w(1)) + &
                    regions(k)%frequency_error, "the tip's W against the scan's")
         call check(ctx, 8*regions(k)%evaluations <= scan_cost, "8 times fewer monodromies: "// &
                    real_text(real(regions(k)%evaluations, wp))//" against "//real_text(real(scan_cost, wp)))
      end do
   end subroutine damped_mathieu_against_scan

   !> Bolotin's first approximation of the damped principal region of x'' + 2ζωx' +
   !> ω²(1 − 2μ cos θt)x = 0: θ*/(2ω) = √(1 ± √(μ² − (Δ/π)²)) with Δ/π = 2ζ (ω = 1, μ = h/2).
   !> At ζ = 0.005 and h = 0.05 (μ = 0.025), the edges within 2μ² (its neglected order).
   subroutine bolotin_principal_width(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(scalar_oracle_t) :: oracle
      type(region_t), allocatable :: regions(:)
      type(error_t), allocatable :: error
      real(wp), parameter :: zeta = 0.005_wp, h = 0.05_wp
      real(wp) :: mu, root, low, high
      integer :: k
      call damped_mathieu(zeta, oracle, error)
      if (.not. allocated(error)) call find_regions(oracle, 1.5_wp, 3.0_wp, 0.0_wp, h, 1, 1.0e-10_wp, 32, regions, error)
      call check(ctx, .not. allocated(error), "regions")
      if (allocated(error)) return
      k = principal(regions, 1)
      call check(ctx, k > 0, "the principal region")
      if (k == 0) return
      mu = 0.5_wp*h
      root = sqrt(mu**2 - (2.0_wp*zeta)**2)
      low = 2.0_wp*sqrt(1.0_wp - root)
      high = 2.0_wp*sqrt(1.0_wp + root)
      call check(ctx, .not. any(regions(k)%clipped), "both edges found inside the window")
      call check_close(ctx, regions(k)%edges(1), low, abs=2.0_wp*mu**2, message="the lower edge")
      call check_close(ctx, regions(k)%edges(2), high, abs=2.0_wp*mu**2, message="the upper edge")
      ! the tip below, at Bolotin's mu* = Delta/pi
      call check_close(ctx, 0.5_wp*regions(k)%drive, 2.0_wp*zeta, rel=2.0_wp*zeta, message="mu* = Delta/pi")
   end subroutine bolotin_principal_width

   !> The undamped Mathieu model x'' + (β − α cos πτ)x = 0 with α the drive: the regions at
   !> β = (kπ/2)², k = 1 … 4, tips by theory at α = 0, and their edges at α = 4 on GSL's
   !> characteristic values (between b_k and a_k).
   subroutine undamped_mathieu_theory(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(scalar_oracle_t) :: oracle
      type(region_t), allocatable :: regions(:)
      type(error_t), allocatable :: error
      real(wp) :: a, b, low, high
      integer :: k
      allocate (oracle%model, source=mathieu_model_t())
      oracle%drive_axis = along_alpha
      oracle%method = method_t(tolerance=1.0e-12_wp)
      call find_regions(oracle, -1.0_wp, 40.0_wp, 0.0_wp, 4.0_wp, 4, 1.0e-12_wp, 32, regions, error)
      call check(ctx, .not. allocated(error), "regions")
      if (allocated(error)) return
      ! and below a_0(4), unstable without a resonance: the stretch of the top drive outside them
      call check(ctx, size(regions) == 5, "four regions and one stretch, got "//real_text(real(size(regions), wp)))
      if (size(regions) == 5) then
         call check(ctx, regions(5)%kind == region_unassigned .and. regions(5)%status == region_uncovered, &
                    "the stretch below a_0 uncovered")
         call mathieu_transition_beta(mathieu_kind_a, 0, 4.0_wp, a, error)
         call check(ctx, .not. allocated(error), "GSL's a_0")
         if (allocated(error)) return
         call check(ctx, regions(5)%edges(1) == -1.0_wp .and. regions(5)%clipped(1), "from the range's end")
         call check_close(ctx, regions(5)%edges(2), a, rel=1.0e-8_wp, message="up to a_0(4)")
      end if
      do k = 1, min(4, size(regions))
         call check(ctx, regions(k)%order == k .and. regions(k)%kind == region_simple, "region "//real_text(real(k, wp)))
         call check_close(ctx, regions(k)%predicted, (k*pi/2.0_wp)**2, rel=1.0e-12_wp, message="its resonance")
         call check(ctx, regions(k)%status == region_theory .and. regions(k)%drive == 0.0_wp, "its tip by theory")
         call mathieu_transition_beta(mathieu_kind_a, k, 4.0_wp, a, error)
         if (.not. allocated(error)) call mathieu_transition_beta(mathieu_kind_b, k, 4.0_wp, b, error)
         call check(ctx, .not. allocated(error), "GSL's values")
         if (allocated(error)) return
         low = min(a, b)
         high = max(a, b)
         call check(ctx, .not. any(regions(k)%clipped), "both edges inside the window")
         call check_close(ctx, regions(k)%edges(1), low, rel=1.0e-8_wp, message="lower edge at alpha = 4")
         call check_close(ctx, regions(k)%edges(2), high, rel=1.0e-8_wp, message="upper edge at alpha = 4")
      end do
   end subroutine undamped_mathieu_theory

   !> The damped column of three modes (data/scenes/column_equations.nml): the principal tips
   !> of modes 1 and 2 and the sum tip ω₁ + ω₂ against a scan of 21 frequencies around each,
   !> the critical P1 at each by bisection on the largest |λ| of all multipliers (to 1e-10),
   !> the minimum by the parabola through the three lowest: within 1e-6 relative. The
   !> difference regions are closed (one Krein signature).
   subroutine column_tips_against_scan(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(equations_system_t) :: column
      type(system_oracle_t) :: oracle
      type(region_t), allocatable :: regions(:)
      type(error_t), allocatable :: error
      integer :: k, r, which(3)
      call damped_column(column, error)
      call check(ctx, .not. allocated(error), "the column")
      if (allocated(error)) return
      allocate (oracle%system, source=column)
      oracle%drive_axis = along_beta
      oracle%method = system_method_t(tolerance=1.0e-11_wp)
      call find_regions(oracle, 0.5_wp, 10.0_wp, 0.0_wp, 1.5_wp, 1, 1.0e-10_wp, 32, regions, error)
      call check(ctx, .not. allocated(error), "regions")
      if (allocated(error)) return
      which = 0
      do k = 1, size(regions)
         if (regions(k)%kind == region_simple .and. regions(k)%modes(1) == 1) which(1) = k
         if (regions(k)%kind == region_simple .and. regions(k)%modes(1) == 2) which(2) = k
         if (regions(k)%kind == region_sum .and. all(regions(k)%modes == [1, 2])) which(3) = k
         if (regions(k)%kind == region_difference) &
            call check(ctx, regions(k)%status == region_same_signature, "a difference region stays closed")
      end do
      call check(ctx, all(which > 0), "the principal regions of modes 1, 2 and the sum region 1 + 2")
      if (.not. all(which > 0)) return
      do r = 1, 3
         k = which(r)
         call check(ctx, regions(k)%status == region_found, "tip "//real_text(real(r, wp))//" found and confirmed")
         call scan_tip(regions(k))
      end do
   contains
      subroutine scan_tip(region)
         type(region_t), intent(in) :: region
         integer, parameter :: n_scan = 21
         real(wp) :: w(n_scan), c(n_scan), width, h_min, best
         integer :: j, m
         width = 0.01_wp*region%frequency
         w = [(region%frequency - width + 2.0_wp*width*real(j - 1, wp)/real(n_scan - 1, wp), j=1, n_scan)]
         do j = 1, n_scan
            c(j) = least_unstable(w(j))
         end do
         m = minloc(c, 1)
         call check(ctx, m > 1 .and. m < n_scan, "the scan's least drive lies inside it")
         if (m == 1 .or. m == n_scan) return
         h_min = 0.5_wp*(c(m - 1) - c(m + 1))/(c(m - 1) - 2.0_wp*c(m) + c(m + 1))
         best = c(m) - 0.25_wp*(c(m - 1) - c(m + 1))*h_min
         call check_close(ctx, region%drive, best, rel=1.0e-6_wp, message="the tip P1 against the scan")
         call check(ctx, abs(region%frequency - (w(m) + h_min*(w(2) - w(1)))) <= 0.1_wp*(w(2) - w(1)), &
                    "the tip's Om against the scan's")
      end subroutine scan_tip

      !> The least P1 where the largest |λ| exceeds 1 at Om, by bisection from [0, 1.5].
      real(wp) function least_unstable(om) result(p1)
         real(wp), intent(in) :: om
         real(wp) :: lo, hi, mid
         integer :: iteration
         lo = 0.0_wp
         hi = 1.5_wp
         do iteration = 1, 60
            mid = 0.5_wp*(lo + hi)
            if (log_largest(om, mid) > 0.0_wp) then
               hi = mid
            else
               lo = mid
            end if
            if (hi - lo <= 1.0e-10_wp) exit
         end do
         p1 = 0.5_wp*(lo + hi)
      end function least_unstable

      real(wp) function log_largest(om, p1)
         real(wp), intent(in) :: om, p1
         type(system_form_t) :: form
         type(system_nodes_t) :: nodes
         type(system_monodromy_t) :: monodromy
         type(floquet_t) :: floquet
         type(error_t), allocatable :: e
         call prepare_system(column, 0.0_wp, form, e, om)
         call system_point(column, form, om, p1, system_method_t(tolerance=1.0e-11_wp), nodes, monodromy, floquet, e)
         log_largest = floquet%log_modulus(1)
      end function log_largest
   end subroutine column_tips_against_scan

   !> The damped column's tips against data/reference/column_tips.dat (made by
   !> data/reference/make_column_tips.py, numpy and scipy, no code of this library: monodromies
   !> by DOP853 at rtol 1e-12, the critical P1 by brentq to 1e-11, minimised over Om by bounded
   !> Brent; self-consistent to 4e-12 between rtol 1e-12 and 1e-11): six tips up to order 2
   !> over Om in [0.5, 20] (the principal regions of modes 1–3, the second-order regions of
   !> modes 1 and 2, the sum ω₁ + ω₂), each found and confirmed, its P1 within 1e-6 relative
   !> and its Om within 1e-3 relative of the reference. Oracle tolerance 1e-10.
   subroutine column_tips_against_reference(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=*), parameter :: path = "data/reference/column_tips.dat"
      character(len=1024), allocatable :: lines(:)
      type(equations_system_t) :: column
      type(system_oracle_t) :: oracle
      type(region_t), allocatable :: regions(:)
      type(error_t), allocatable :: error
      integer :: k, line, kind, order, modes(2), ios, match, checked
      real(wp) :: om, p1, worst_drive, worst_frequency
      lines = read_lines(path)
      call check(ctx, size(lines) > 0, "reads "//path)
      call damped_column(column, error)
      call check(ctx, .not. allocated(error), "the column")
      if (allocated(error)) return
      allocate (oracle%system, source=column)
      oracle%drive_axis = along_beta
      oracle%method = system_method_t(tolerance=1.0e-10_wp)
      call find_regions(oracle, 0.5_wp, 20.0_wp, 0.0_wp, 1.5_wp, 2, 1.0e-10_wp, 32, regions, error)
      call check(ctx, .not. allocated(error), "regions")
      if (allocated(error)) return
      worst_drive = 0.0_wp
      worst_frequency = 0.0_wp
      checked = 0
      do line = 1, size(lines)
         if (len_trim(lines(line)) == 0 .or. lines(line)(1:1) == "#") cycle
         read (lines(line), *, iostat=ios) kind, order, modes, om, p1
         call check(ctx, ios == 0, "reads "//trim(lines(line)))
         if (ios /= 0) cycle
         match = 0
         do k = 1, size(regions)
            if (regions(k)%kind == kind .and. regions(k)%order == order .and. all(regions(k)%modes == modes)) match = k
         end do
         call check(ctx, match > 0, "a region for "//trim(lines(line)))
         if (match == 0) cycle
         checked = checked + 1
         call check(ctx, regions(match)%status == region_found, "tip found and confirmed: "//trim(lines(line)))
         call check(ctx, abs(regions(match)%drive - p1) <= 1.0e-6_wp*p1, "tip P1 "// &
                    real_text(regions(match)%drive)//" against "//trim(lines(line)))
         call check(ctx, abs(regions(match)%frequency - om) <= 1.0e-3_wp*om, "tip Om "// &
                    real_text(regions(match)%frequency)//" against "//trim(lines(line)))
         worst_drive = max(worst_drive, abs(regions(match)%drive - p1)/p1)
         worst_frequency = max(worst_frequency, abs(regions(match)%frequency - om)/om)
      end do
      call check(ctx, checked == 6, "six reference tips checked")
      print '(4x,a,i0,a,es9.2,a,es9.2)', "column tips: ", checked, " against the reference; worst relative P1 ", &
         worst_drive, ", Om ", worst_frequency
   end subroutine column_tips_against_reference

   !> Task `regions` on the damped Mathieu equation: one line per region with the columns
   !> named after the axes, its values those of `find_regions`, and its header rerunning it.
   subroutine task_file(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=300) :: lines(4)
      character(len=:), allocatable :: written, again, out
      character(len=1024), allocatable :: file_lines(:)
      type(scalar_oracle_t) :: oracle
      type(region_t), allocatable :: regions(:)
      type(error_t), allocatable :: error
      real(wp) :: v(15)
      integer :: k
      logical :: ok
      out = scratch_prefix("regions_task")
      lines(1) = "&scene task = 'regions', model = 'equation', tolerance = 1e-12, output = '"//out//"' /"
      lines(2) = "&equation parameters = 'zeta = 0.01, h = 0, W = 2', stiffness = '1 + h*cos(W*t)', "// &
                 "damping = '2*zeta', frequency = 'W', alpha = 'W', beta = 'h' /"
      lines(3) = "&chart alpha_min = 0.5, alpha_max = 3.0, n_alpha = 10, beta_min = 0.0, beta_max = 0.5, n_beta = 10 /"
      lines(4) = "&regions order = 3 /"
      call run_text_scene("regions_task", lines, error, written)
      call check(ctx, .not. allocated(error), "the task runs")
      if (allocated(error)) then
         call check(ctx, .false., error%message)
         return
      end if
      file_lines = read_lines(written)
      call check(ctx, any(index(file_lines, "# columns: kind order mode_i mode_j predicted W W_error h h_error") == 1), &
                 "the columns named after the axes")
      call check_rerun(ctx, written, file_lines, again, ok)
      if (ok) call delete_file(again)
      call damped_mathieu(0.01_wp, oracle, error)
      if (.not. allocated(error)) &
         call find_regions(oracle, 0.5_wp, 3.0_wp, 0.0_wp, 0.5_wp, 3, 1.0e-12_wp, 32, regions, error)
      call check(ctx, .not. allocated(error), "the library's regions")
      if (allocated(error)) return
      file_lines = pack(file_lines, file_lines(:)(1:1) /= "#" .and. len_trim(file_lines) > 0)
      call check(ctx, size(file_lines) == size(regions) .and. size(regions) == 3, "one line per region")
      do k = 1, min(size(file_lines), size(regions))
         read (file_lines(k), *) v
         call check(ctx, nint(v(1)) == regions(k)%kind .and. nint(v(2)) == regions(k)%order .and. &
                    nint(v(14)) == regions(k)%status, "kind, order and status of line "//real_text(real(k, wp)))
         call check_close(ctx, v(6), regions(k)%frequency, rel=1.0e-15_wp, message="the tip's W")
         call check_close(ctx, v(8), regions(k)%drive, rel=1.0e-15_wp, message="the tip's h")
      end do
      call delete_file(written)
   end subroutine task_file

   !> Bad input: exit 2 naming the file, the group and the variable, nothing written; and the
   !> library's arguments refused naming them.
   subroutine bad_input_refused(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=*), parameter :: equation = "&equation parameters = 'zeta = 0.01, h = 0, W = 2', stiffness = "// &
         "'1 + h*cos(W*t)', damping = '2*zeta', frequency = 'W', alpha = 'W', beta = 'h' /"
      character(len=*), parameter :: chart = "&chart alpha_min = 0.5, alpha_max = 3.0, n_alpha = 10, beta_min = 0.0, "// &
         "beta_max = 0.5, n_beta = 10 /"
      type(scalar_oracle_t) :: oracle
      type(region_t), allocatable :: regions(:)
      type(error_t), allocatable :: error
      call refused(equation, "&regions order = 0 /", "regions", "order", "1 to")
      call refused(equation, "&regions order = 9 /", "regions", "order", "1 to")
      call refused(equation, "&regions n_samples = 1 /", "regions", "n_samples", "2 to")
      call refused(equation, "&regions drive = 'gamma' /", "regions", "drive", "'alpha', 'beta' or 'auto'")
      call refused(equation, "&regions drive = 'alpha' /", "regions", "drive", "undriven problem")
      call refused("&equation parameters = 'zeta = 0.01, h = 0, W = 2', stiffness = '1 + h + cos(W*t)', "// &
                   "damping = '2*zeta', frequency = 'W', alpha = 'W', beta = 'h' /", "&regions /", "regions", "drive", &
                   "no drive")
      call refused(equation, "&regions /", "chart", "alpha_max", "frequency range is empty", &
                   "&chart alpha_min = 3.0, alpha_max = 3.0, n_alpha = 1, beta_min = 0.0, beta_max = 0.5 /")
      call refused(equation, "&regions /", "chart", "beta_max", "drive range is empty", &
                   "&chart alpha_min = 0.5, alpha_max = 3.0, beta_min = 0.5, beta_max = 0.5, n_beta = 1 /")
      ! the library
      call damped_mathieu(0.01_wp, oracle, error)
      call find_regions(oracle, 0.5_wp, 3.0_wp, 0.0_wp, 0.5_wp, 0, 1.0e-10_wp, 32, regions, error)
      call check(ctx, allocated(error), "order 0 refused")
      if (allocated(error)) call check(ctx, index(error%message, "order") > 0, error%message)
      call find_regions(oracle, 0.5_wp, 3.0_wp, 0.5_wp, 0.5_wp, 1, 1.0e-10_wp, 32, regions, error)
      call check(ctx, allocated(error), "an empty drive range refused")
      if (allocated(error)) call check(ctx, index(error%message, "drive range") > 0, error%message)
      call find_regions(oracle, 0.5_wp, 3.0_wp, 0.0_wp, 0.5_wp, 1, 1.0e-10_wp, 1, regions, error)
      call check(ctx, allocated(error), "one sample refused")
      if (allocated(error)) call check(ctx, index(error%message, "n_samples") > 0, error%message)
   contains
      subroutine refused(problem, group, group_name, variable, what, grid)
         character(len=*), intent(in) :: problem, group, group_name, variable, what
         character(len=*), intent(in), optional :: grid
         type(error_t), allocatable :: error
         character(len=:), allocatable :: written, out, scene
         character(len=1000) :: lines(4)
         out = scratch_prefix("regions_bad")
         scene = scratch_prefix("regions_bad_scene")//".nml"
         lines(1) = "&scene task = 'regions', model = 'equation', output = '"//out//"' /"
         lines(2) = chart
         if (present(grid)) lines(2) = grid
         lines(3) = problem
         lines(4) = group
         call run_text_scene("regions_bad_scene", lines, error, written)
         call check(ctx, allocated(error), variable//" "//what//": refused")
         if (.not. allocated(error)) return
         call check(ctx, error%code == err_input, variable//" "//what//": an input error (exit 2)")
         call check(ctx, index(error%message, scene) > 0 .and. index(error%message, "&"//group_name//": "// &
                    variable//":") > 0 .and. index(error%message, what) > 0, "the message names file, group, "// &
                    "variable and '"//what//"': "//error%message)
         call check(ctx, .not. file_exists(out//"_regions.dat"), variable//" "//what//": no file written")
      end subroutine refused
   end subroutine bad_input_refused
end module test_regions

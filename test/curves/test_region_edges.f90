!> Tests of the regions' boundaries by continuation from their tips (hillstab_curves_region_edges,
!> task `edges`): the undamped Mathieu model's edges on GSL's characteristic values; the
!> damped Mathieu equation's, the damped column's and the undamped column's sum region's (a
!> Krein collision) edges against a bisection of the overall verdict by another method
!> (Runge–Kutta); two uncoupled Mathieu equations as one system, where one region lies inside
!> the other's: its edges are each equation's own, and labelled overlap exactly where the
!> other equation alone is unstable; the task's file against the library and its header
!> rerunning it; a chart's list of its regions; bad input refused naming the file, the group
!> and the variable.
module test_region_edges
   use hillstab_core_kinds, only: wp
   use hillstab_core_text, only: real_text
   use hillstab_core_error, only: error_t, err_input
   use hillstab_hill_model_mathieu, only: mathieu_model_t
   use hillstab_hill_model_equation, only: equation_model_t
   use hillstab_hill_mathieu, only: mathieu_transition_beta, mathieu_kind_a, mathieu_kind_b
   use hillstab_hill_system_equation, only: equations_system_t
   use hillstab_integrate_monodromy, only: method_t, method_rk
   use hillstab_integrate_system, only: system_method_t, system_rk
   use hillstab_curves_critical, only: along_alpha, along_beta
   use hillstab_curves_oracle, only: oracle_t, oracle_sample_t, scalar_oracle_t, system_oracle_t
   use hillstab_curves_regions, only: region_t, find_regions, region_simple, region_theory, region_found
   use hillstab_curves_region_edges
   use hillstab_testing
   use hillstab_test_files, only: run_text_scene, check_rerun
   use hillstab_test_problems, only: damped_mathieu, damped_column, uncoupled_pair, mathieu_equation
   use hillstab_test_scratch, only: scratch_prefix, read_lines, file_exists, delete_file
   implicit none
   private
   public :: collect_region_edges

contains

   function collect_region_edges() result(suite)
      type(testsuite_t) :: suite
      suite = new_testsuite("region_edges", [ &
         new_unittest("undamped_mathieu_on_gsl", undamped_mathieu_on_gsl), &
         new_unittest("damped_mathieu_against_rk", damped_mathieu_against_rk), &
         new_unittest("column_against_rk", column_against_rk), &
         new_unittest("undamped_sum_against_rk", undamped_sum_against_rk), &
         new_unittest("overlap_labelled", overlap_labelled), &
         new_unittest("task_file", task_file), &
         new_unittest("chart_lists_regions", chart_lists_regions), &
         new_unittest("bad_input_refused", bad_input_refused)])
   end function collect_region_edges

   !> The overall verdict's transition along f at drive d, bisected to 1e-13 relative between
   !> a and b (the distance of opposite signs there), on the oracle given.
   subroutine bisect_overall(oracle, a0, b0, d, x, ok)
      class(oracle_t), intent(in) :: oracle
      real(wp), intent(in) :: a0, b0, d
      real(wp), intent(out) :: x
      logical, intent(out) :: ok
      type(oracle_sample_t) :: sa, sm
      type(error_t), allocatable :: error
      real(wp) :: a, b
      integer :: k
      a = a0
      b = b0
      call oracle%distance(a, d, 0, -1.0_wp, sa, error)
      call oracle%distance(b, d, 0, -1.0_wp, sm, error)
      ok = .not. allocated(error) .and. (sa%g > 0.0_wp .neqv. sm%g > 0.0_wp)
      x = 0.5_wp*(a + b)
      if (.not. ok) return
      do k = 1, 200
         if (b - a <= 1.0e-13_wp*max(1.0_wp, abs(a))) exit
         x = 0.5_wp*(a + b)
         call oracle%distance(x, d, 0, -1.0_wp, sm, error)
         if (allocated(error)) then
            ok = .false.
            return
         end if
         if ((sm%g > 0.0_wp) .eqv. (sa%g > 0.0_wp)) then
            a = x
         else
            b = x
         end if
      end do
      x = 0.5_wp*(a + b)
   end subroutine bisect_overall

   !> Each point of the edges against the reference oracle's bisection (`reference`), within its
   !> stated error and `slack`; every point but the tips a confirmed boundary.
   subroutine check_points(ctx, points, reference, slack, what)
      type(test_context_t), intent(inout) :: ctx
      type(edge_point_t), intent(in) :: points(:)
      class(oracle_t), intent(in) :: reference
      real(wp), intent(in) :: slack
      character(len=*), intent(in) :: what
      real(wp) :: x, h, worst
      integer :: j, compared
      logical :: ok
      worst = 0.0_wp
      compared = 0
      do j = 1, size(points)
         if (points(j)%status == edge_tip) cycle
         call check(ctx, points(j)%status == edge_boundary, what//": a boundary at "// &
                    real_text(points(j)%frequency)//", "//real_text(points(j)%drive)//": status "// &
                    real_text(real(points(j)%status, wp)))
         h = 1.0e-6_wp*max(1.0_wp, abs(points(j)%frequency))
         call bisect_overall(reference, points(j)%frequency - h, points(j)%frequency + h, points(j)%drive, x, ok)
         call check(ctx, ok, what//": the reference brackets the edge at "//real_text(points(j)%frequency))
         if (.not. ok) cycle
         compared = compared + 1
         worst = max(worst, abs(x - points(j)%frequency)/max(points(j)%frequency_error, tiny(1.0_wp)))
         call check(ctx, abs(x - points(j)%frequency) <= points(j)%frequency_error + slack*max(1.0_wp, abs(x)), &
                    what//": the edge "//real_text(points(j)%frequency)//" +- "// &
                    real_text(points(j)%frequency_error)//" against "//real_text(x))
      end do
      call check(ctx, compared > 0, what//": points compared")
   end subroutine check_points

   !> The undamped Mathieu model x'' + (β − 2α cos 2τ... in its own axes (α the drive, β the
   !> frequency-like axis): regions of order 1 to 3 from their resonances at α = 0, their
   !> edges at 6 levels up to α = 4 on GSL's characteristic values a_k(α), b_k(α).
   subroutine undamped_mathieu_on_gsl(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(scalar_oracle_t) :: oracle
      type(region_t), allocatable :: regions(:)
      type(edge_point_t), allocatable :: points(:)
      type(error_t), allocatable :: error
      real(wp) :: a, b, reference
      integer :: j, k, counted(3)
      allocate (oracle%model, source=mathieu_model_t())
      oracle%drive_axis = along_alpha
      oracle%method = method_t(tolerance=1.0e-12_wp)
      call find_regions(oracle, -1.0_wp, 30.0_wp, 0.0_wp, 4.0_wp, 3, 1.0e-12_wp, 32, regions, error)
      if (.not. allocated(error)) &
         call trace_edges(oracle, regions, -1.0_wp, 30.0_wp, 0.0_wp, 4.0_wp, 1.0e-12_wp, 6, points, error)
      call check(ctx, .not. allocated(error), "regions and edges")
      if (allocated(error)) return
      counted = 0
      do j = 1, size(points)
         k = regions(points(j)%region)%order
         call check(ctx, regions(points(j)%region)%status == region_theory, "theory tips")
         if (points(j)%status == edge_tip) then
            call check(ctx, points(j)%drive == 0.0_wp, "the tip at alpha = 0")
            cycle
         end if
         call mathieu_transition_beta(mathieu_kind_a, k, points(j)%drive, a, error)
         if (.not. allocated(error)) call mathieu_transition_beta(mathieu_kind_b, k, points(j)%drive, b, error)
         call check(ctx, .not. allocated(error), "GSL's values")
         if (allocated(error)) return
         ! a region narrower than 1e-6 may be too thin to tell its inside beyond |S| - 2's error
         call check(ctx, points(j)%status == edge_boundary .or. (points(j)%status == edge_unconfirmed .and. &
                    abs(a - b) < 1.0e-6_wp), "a boundary, order "//real_text(real(k, wp))//" at alpha "// &
                    real_text(points(j)%drive)//": status "//real_text(real(points(j)%status, wp)))
         reference = merge(min(a, b), max(a, b), points(j)%branch < 0)
         call check(ctx, abs(points(j)%frequency - reference) <= points(j)%frequency_error + &
                    1.0e-11_wp*max(1.0_wp, abs(reference)), "order "//real_text(real(k, wp))//" at alpha "// &
                    real_text(points(j)%drive)//": "//real_text(points(j)%frequency)//" +- "// &
                    real_text(points(j)%frequency_error)//" against GSL's "//real_text(reference))
         counted(k) = counted(k) + 1
      end do
      call check(ctx, all(counted == 12), "12 edge points a region, got "//real_text(real(counted(1), wp))//" "// &
                 real_text(real(counted(2), wp))//" "//real_text(real(counted(3), wp)))
   end subroutine undamped_mathieu_on_gsl

   !> The damped Mathieu equation (ζ = 0.02) over (W, h) in [0.5, 3] × [0, 0.6]: every edge
   !> point of its regions of order 1 and 2 against a bisection of the verdict of method rk.
   subroutine damped_mathieu_against_rk(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(scalar_oracle_t) :: oracle, reference
      type(region_t), allocatable :: regions(:)
      type(edge_point_t), allocatable :: points(:)
      type(error_t), allocatable :: error
      call damped_mathieu(0.02_wp, oracle, error)
      if (.not. allocated(error)) &
         call find_regions(oracle, 0.5_wp, 3.0_wp, 0.0_wp, 0.6_wp, 2, 1.0e-12_wp, 32, regions, error)
      if (.not. allocated(error)) &
         call trace_edges(oracle, regions, 0.5_wp, 3.0_wp, 0.0_wp, 0.6_wp, 1.0e-12_wp, 5, points, error)
      call check(ctx, .not. allocated(error), "regions and edges")
      if (allocated(error)) return
      call check(ctx, size(regions) == 2, "two regions")
      call check(ctx, all(regions%status == region_found), "both tips found")
      call check(ctx, size(points) == 2*(2*5 + 1), "two regions of 11 points each")
      call damped_mathieu(0.02_wp, reference, error)
      reference%method = method_t(kind=method_rk, tolerance=1.0e-13_wp)
      call check_points(ctx, points, reference, 1.0e-10_wp, "damped Mathieu")
   end subroutine damped_mathieu_against_rk

   !> The damped column: the edges of its principal region of mode 1 and of its sum region
   !> ω₁ + ω₂ = Ω (whose damped colliding multipliers leave the circle at two arguments) at 4
   !> levels against a bisection of the largest multiplier of method rk.
   subroutine column_against_rk(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(equations_system_t) :: column
      type(system_oracle_t) :: oracle, reference
      type(region_t), allocatable :: regions(:), chosen(:)
      type(edge_point_t), allocatable :: points(:)
      type(error_t), allocatable :: error
      integer :: k
      call damped_column(column, error)
      call check(ctx, .not. allocated(error), "the column")
      if (allocated(error)) return
      allocate (oracle%system, source=column)
      oracle%method = system_method_t(tolerance=1.0e-10_wp)
      oracle%drive_axis = along_beta
      call find_regions(oracle, 1.0_wp, 6.0_wp, 0.0_wp, 1.5_wp, 1, 1.0e-10_wp, 32, regions, error)
      call check(ctx, .not. allocated(error), "regions")
      if (allocated(error)) return
      chosen = pack(regions, regions%order == 1 .and. regions%status == region_found .and. &
                    ((regions%kind == region_simple .and. regions%modes(1) == 1) .or. regions%kind == 2))
      call check(ctx, size(chosen) == 2, "the principal region of mode 1 and the sum region")
      call trace_edges(oracle, chosen, 1.0_wp, 6.0_wp, 0.0_wp, 1.5_wp, 1.0e-10_wp, 4, points, error)
      call check(ctx, .not. allocated(error), "edges")
      if (allocated(error)) return
      allocate (reference%system, source=column)
      reference%method = system_method_t(kind=system_rk, tolerance=1.0e-12_wp)
      reference%drive_axis = along_beta
      do k = 1, size(chosen)
         call check(ctx, count(points%region == k) == 2*4 + 1, "9 points a region")
      end do
      call check_points(ctx, points, reference, 1.0e-9_wp, "column")
   end subroutine column_against_rk

   !> The column undamped (ζ = 0): its sum region ω₁ + ω₂ = Ω opens from the resonance at
   !> P1 = 0 (theory); its edges, where the colliding pair leaves the circle off the real axis
   !> (a Krein collision), at 4 levels against a bisection of the largest multiplier of
   !> Runge–Kutta at 1e-12.
   subroutine undamped_sum_against_rk(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(equations_system_t) :: column
      type(system_oracle_t) :: oracle, reference
      type(region_t), allocatable :: regions(:), chosen(:)
      type(edge_point_t), allocatable :: points(:)
      type(error_t), allocatable :: error
      call damped_column(column, error)
      if (.not. allocated(error)) call column%set_text("parameters", "P0 = 0.3, P1 = 0, Om = 2, zeta = 0", error)
      if (.not. allocated(error)) call column%check_values(error)
      call check(ctx, .not. allocated(error), "the undamped column")
      if (allocated(error)) return
      allocate (oracle%system, source=column)
      oracle%method = system_method_t(tolerance=1.0e-10_wp)
      oracle%drive_axis = along_beta
      call find_regions(oracle, 4.0_wp, 5.5_wp, 0.0_wp, 0.5_wp, 1, 1.0e-10_wp, 32, regions, error, cover=0)
      call check(ctx, .not. allocated(error), "regions")
      if (allocated(error)) return
      chosen = pack(regions, regions%kind == 2 .and. regions%order == 1)
      call check(ctx, size(chosen) == 1, "the sum region")
      if (size(chosen) /= 1) return
      call check(ctx, chosen(1)%status == region_theory, "its tip by theory")
      call trace_edges(oracle, chosen, 4.0_wp, 5.5_wp, 0.0_wp, 0.5_wp, 1.0e-10_wp, 4, points, error)
      call check(ctx, .not. allocated(error), "edges")
      if (allocated(error)) return
      call check(ctx, size(points) == 2*4 + 1, "9 points")
      allocate (reference%system, source=column)
      reference%method = system_method_t(kind=system_rk, tolerance=1.0e-12_wp)
      reference%drive_axis = along_beta
      call check_points(ctx, points, reference, 1.0e-8_wp, "undamped sum")
   end subroutine undamped_sum_against_rk

   !> x₁'' + (1 + h cos Wt)x₁ = 0 and x₂'' + (2.3² + h cos Wt)x₂ = 0 as one system: the region
   !> 2ω₂ = 2W (W ≈ 2.3) lies inside the principal region of x₁ once h is large. Each edge of
   !> the system's two simple regions equals the edge of its own equation alone (bisected on
   !> that equation with method rk), and is labelled overlap exactly where the other equation
   !> alone is unstable there.
   subroutine overlap_labelled(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(equations_system_t) :: pair
      type(system_oracle_t) :: oracle
      type(scalar_oracle_t) :: alone(2)
      type(equation_model_t) :: e
      type(region_t), allocatable :: regions(:), chosen(:)
      type(edge_point_t), allocatable :: points(:)
      type(error_t), allocatable :: error
      type(oracle_sample_t) :: other
      real(wp), parameter :: w(2) = [1.0_wp, 2.3_wp]
      real(wp) :: x, h
      integer :: j, mode, overlaps
      logical :: ok
      call uncoupled_pair(w, pair, error)
      call check(ctx, .not. allocated(error), "the pair")
      if (allocated(error)) return
      allocate (oracle%system, source=pair)
      oracle%method = system_method_t(tolerance=1.0e-11_wp)
      oracle%drive_axis = along_beta
      do mode = 1, 2
         call mathieu_equation(0.0_wp, w(mode), e, error)
         if (allocated(error)) return
         allocate (alone(mode)%model, source=e)
         alone(mode)%drive_axis = along_beta
         alone(mode)%method = method_t(kind=method_rk, tolerance=1.0e-13_wp)
      end do
      call find_regions(oracle, 1.5_wp, 3.0_wp, 0.0_wp, 2.5_wp, 2, 1.0e-11_wp, 32, regions, error)
      call check(ctx, .not. allocated(error), "regions")
      if (allocated(error)) return
      chosen = pack(regions, regions%kind == region_simple .and. &
                    ((regions%order == 1 .and. regions%modes(1) == 1) .or. (regions%order == 2 .and. &
                     regions%modes(1) == 2)))
      call check(ctx, size(chosen) == 2, "the principal region of x1 and the second-order region of x2")
      if (size(chosen) /= 2) return
      call trace_edges(oracle, chosen, 1.5_wp, 3.0_wp, 0.0_wp, 2.5_wp, 1.0e-11_wp, 10, points, error)
      call check(ctx, .not. allocated(error), "edges")
      if (allocated(error)) return
      overlaps = 0
      do j = 1, size(points)
         if (points(j)%status == edge_tip .or. points(j)%status == edge_range_end) cycle
         mode = chosen(points(j)%region)%modes(1)
         h = 1.0e-6_wp*max(1.0_wp, abs(points(j)%frequency))
         call bisect_overall(alone(mode), points(j)%frequency - h, points(j)%frequency + h, points(j)%drive, x, ok)
         call check(ctx, ok, "its own equation brackets the edge")
         if (ok) call check(ctx, abs(x - points(j)%frequency) <= points(j)%frequency_error + 1.0e-9_wp, &
                            "x"//real_text(real(mode, wp))//"'s edge "//real_text(points(j)%frequency)// &
                            " against its own equation's "//real_text(x))
         call alone(3 - mode)%distance(points(j)%frequency, points(j)%drive, 0, -1.0_wp, other, error)
         if (allocated(error)) return
         if (abs(other%g) > 1.0e-6_wp) then
            call check(ctx, (points(j)%status == edge_overlap) .eqv. (other%g > 0.0_wp), &
                       "overlap exactly where the other equation is unstable, at "// &
                       real_text(points(j)%frequency)//", "//real_text(points(j)%drive))
         end if
         if (points(j)%status == edge_overlap) overlaps = overlaps + 1
      end do
      call check(ctx, overlaps >= 4, "overlaps found, got "//real_text(real(overlaps, wp)))
   end subroutine overlap_labelled

   !> Task `edges` on the damped Mathieu equation: its columns named after the axes, one block
   !> per region, equal to the library's edges, and its header rerunning it.
   subroutine task_file(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=300) :: lines(5)
      character(len=:), allocatable :: written, again, out
      character(len=1024), allocatable :: file_lines(:), data(:)
      type(scalar_oracle_t) :: oracle
      type(region_t), allocatable :: regions(:)
      type(edge_point_t), allocatable :: points(:)
      type(error_t), allocatable :: error
      real(wp) :: v(11)
      integer :: k, blanks
      logical :: ok
      out = scratch_prefix("edges_task")
      lines(1) = "&scene task = 'edges', model = 'equation', tolerance = 1e-12, output = '"//out//"' /"
      lines(2) = "&equation parameters = 'zeta = 0.02, nu = 1, h = 0, W = 2', stiffness = 'nu^2 + h*cos(W*t)', "// &
                 "damping = '2*zeta*nu', frequency = 'W', alpha = 'W', beta = 'h' /"
      lines(3) = "&chart alpha_min = 0.5, alpha_max = 3.0, n_alpha = 10, beta_min = 0.0, beta_max = 0.6, n_beta = 10 /"
      lines(4) = "&regions order = 2 /"
      lines(5) = "&edges levels = 5 /"
      call run_text_scene("edges_task", lines, error, written)
      call check(ctx, .not. allocated(error), "the task runs")
      if (allocated(error)) then
         call check(ctx, .false., error%message)
         return
      end if
      file_lines = read_lines(written)
      call check(ctx, any(index(file_lines, "# columns: region kind order mode_i mode_j branch W W_error h status") &
                          == 1), "the columns named after the axes")
      call check_rerun(ctx, written, file_lines, again, ok)
      if (ok) call delete_file(again)
      call damped_mathieu(0.02_wp, oracle, error)
      if (.not. allocated(error)) &
         call find_regions(oracle, 0.5_wp, 3.0_wp, 0.0_wp, 0.6_wp, 2, 1.0e-12_wp, 32, regions, error)
      if (.not. allocated(error)) &
         call trace_edges(oracle, regions, 0.5_wp, 3.0_wp, 0.0_wp, 0.6_wp, 1.0e-12_wp, 5, points, error)
      call check(ctx, .not. allocated(error), "the library's edges")
      if (allocated(error)) return
      blanks = count(file_lines(:)(1:1) /= "#" .and. len_trim(file_lines) == 0)
      call check(ctx, blanks == 2, "two blank lines between the two regions, got "//real_text(real(blanks, wp)))
      data = pack(file_lines, file_lines(:)(1:1) /= "#" .and. len_trim(file_lines) > 0)
      call check(ctx, size(data) == size(points), "one line per point")
      do k = 1, min(size(data), size(points))
         read (data(k), *) v
         call check(ctx, nint(v(1)) == points(k)%region .and. nint(v(6)) == points(k)%branch .and. &
                    nint(v(10)) == points(k)%status, "region, branch and status of line "//real_text(real(k, wp)))
         call check_close(ctx, v(7), points(k)%frequency, rel=1.0e-15_wp, message="the edge's W")
         call check_close(ctx, v(9), points(k)%drive, rel=1.0e-15_wp, message="its h")
      end do
      call delete_file(written)
   end subroutine task_file

   !> A chart of the damped Mathieu equation over (W, h) on a coarse grid (W spacing 0.25):
   !> its header lists each region of order 1 and 2 with its tip as the library finds it, and
   !> flags the second-order region, narrower at the top than the spacing, as such; a chart of
   !> a built-in model lists none.
   subroutine chart_lists_regions(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=300) :: lines(3)
      character(len=:), allocatable :: written, out
      character(len=1024), allocatable :: file_lines(:), listed(:)
      type(scalar_oracle_t) :: oracle
      type(region_t), allocatable :: regions(:)
      type(error_t), allocatable :: error
      real(wp) :: tip(2)
      integer :: k, at
      out = scratch_prefix("edges_chart")
      lines(1) = "&scene task = 'chart', model = 'equation', tolerance = 1e-12, output = '"//out//"' /"
      lines(2) = "&equation parameters = 'zeta = 0.02, nu = 1, h = 0, W = 2', stiffness = 'nu^2 + h*cos(W*t)', "// &
                 "damping = '2*zeta*nu', frequency = 'W', alpha = 'W', beta = 'h' /"
      lines(3) = "&chart alpha_min = 0.5, alpha_max = 3.0, n_alpha = 11, beta_min = 0.0, beta_max = 0.6, n_beta = 5 /"
      call run_text_scene("edges_chart", lines, error, written)
      call check(ctx, .not. allocated(error), "the chart runs")
      if (allocated(error)) return
      file_lines = read_lines(written)
      listed = pack(file_lines, index(file_lines, "# region ") == 1)
      call damped_mathieu(0.02_wp, oracle, error)
      if (.not. allocated(error)) &
         call find_regions(oracle, 0.5_wp, 3.0_wp, 0.0_wp, 0.6_wp, 2, 1.0e-12_wp, 32, regions, error, cover=0)
      call check(ctx, .not. allocated(error), "the library's regions")
      if (allocated(error)) return
      call check(ctx, size(listed) == 2 .and. size(regions) == 2, "two regions listed, got "// &
                 real_text(real(size(listed), wp)))
      do k = 1, min(size(listed), size(regions))
         at = index(listed(k), "tip W ")
         call check(ctx, at > 0, "the tip in W and h: "//trim(listed(k)))
         if (at == 0) cycle
         read (listed(k)(at + 6:), *) tip(1)
         at = index(listed(k), ", h ")
         read (listed(k)(at + 4:), *) tip(2)
         call check_close(ctx, tip(1), regions(k)%frequency, rel=1.0e-5_wp, message="the tip's W")
         call check_close(ctx, tip(2), regions(k)%drive, rel=1.0e-5_wp, message="the tip's h")
         call check(ctx, (index(listed(k), "NARROWER") > 0) .eqv. &
                    (regions(k)%edges(2) - regions(k)%edges(1) < 0.25_wp), "narrow exactly when narrower than 0.25")
      end do
      call check(ctx, any(index(listed, "NARROWER") > 0), "the second-order region flagged")
      call delete_file(written)
      lines(1) = "&scene task = 'chart', model = 'mathieu', output = '"//out//"' /"
      lines(2) = "&chart alpha_min = 0.0, alpha_max = 3.0, n_alpha = 5, beta_min = 0.0, beta_max = 5.0, n_beta = 5 /"
      call run_text_scene("edges_chart", lines(1:2), error, written)
      call check(ctx, .not. allocated(error), "a Mathieu chart runs")
      if (allocated(error)) return
      file_lines = read_lines(written)
      call check(ctx, .not. any(index(file_lines, "# region") == 1), "no regions listed for a built-in model")
      call delete_file(written)
   end subroutine chart_lists_regions

   !> `&edges levels` out of range, refused naming the file, the group and the variable, with
   !> nothing written; the library refuses it too.
   subroutine bad_input_refused(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(scalar_oracle_t) :: oracle
      type(region_t), allocatable :: regions(:)
      type(edge_point_t), allocatable :: points(:)
      type(error_t), allocatable :: error
      call refused("&edges levels = 0 /")
      call refused("&edges levels = 10001 /")
      call damped_mathieu(0.02_wp, oracle, error)
      allocate (regions(0))
      call trace_edges(oracle, regions, 0.5_wp, 3.0_wp, 0.0_wp, 0.6_wp, 1.0e-12_wp, 0, points, error)
      call check(ctx, allocated(error), "levels 0 refused")
      if (allocated(error)) call check(ctx, index(error%message, "levels") > 0, error%message)
      call trace_edges(oracle, regions, 3.0_wp, 0.5_wp, 0.0_wp, 0.6_wp, 1.0e-12_wp, 4, points, error)
      call check(ctx, allocated(error), "an empty frequency range refused")
   contains
      subroutine refused(group)
         character(len=*), intent(in) :: group
         type(error_t), allocatable :: error
         character(len=:), allocatable :: written, out, scene
         character(len=1000) :: lines(5)
         out = scratch_prefix("edges_bad")
         scene = scratch_prefix("edges_bad_scene")//".nml"
         lines(1) = "&scene task = 'edges', model = 'equation', output = '"//out//"' /"
         lines(2) = "&chart alpha_min = 0.5, alpha_max = 3.0, n_alpha = 10, beta_min = 0.0, beta_max = 0.5, n_beta = 10 /"
         lines(3) = "&equation parameters = 'zeta = 0.01, h = 0, W = 2', stiffness = '1 + h*cos(W*t)', "// &
                    "damping = '2*zeta', frequency = 'W', alpha = 'W', beta = 'h' /"
         lines(4) = "&regions order = 1 /"
         lines(5) = group
         call run_text_scene("edges_bad_scene", lines, error, written)
         call check(ctx, allocated(error), group//": refused")
         if (.not. allocated(error)) return
         call check(ctx, error%code == err_input, group//": an input error (exit 2)")
         call check(ctx, index(error%message, scene) > 0 .and. index(error%message, "&edges: levels:") > 0, &
                    "the message names file, group and variable: "//error%message)
         call check(ctx, .not. file_exists(out//"_edges.dat"), group//": no file written")
      end subroutine refused
   end subroutine bad_input_refused
end module test_region_edges

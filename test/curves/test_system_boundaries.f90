!> Tests of the transition curves of systems (hillstab_curves_system_boundaries): Hill's
!> method with blocks against the Mathieu characteristic values for one equation and for a
!> decoupled pair, each point confirmed by the monodromy; the combination tongue's edges
!> found by root-finding on Broucke's discriminant against first-order perturbation theory;
!> the edges of a damped combination tongue, of narrow tongues of a 3-DOF system, of
!> overlapping tongues and of random systems against an independent fine scan of the
!> point routine's verdict and bisection on its largest |λ| or discriminant; twelve systems
!> against an independent reference confirmed in extended precision (audit_set.dat).
module test_system_boundaries
   use hillstab_core_kinds, only: wp, pi
   use hillstab_core_error, only: error_t
   use hillstab_core_status, only: status_ok
   use hillstab_hill_model_mathieu, only: mathieu_model_t
   use hillstab_curves_hill_method, only: hill_boundary_t
   use hillstab_curves_characteristic, only: characteristic_values
   use hillstab_hill_system, only: system_form_t, prepare_system
   use hillstab_hill_system_matrix, only: matrix_system_t
   use hillstab_hill_system_floquet, only: kind_plus_one, kind_minus_one, kind_combination
   use hillstab_integrate_system, only: system_method_t, system_auto, system_nodes_t, system_monodromy_t
   use hillstab_integrate_system_point, only: system_point
   use hillstab_hill_system_floquet, only: floquet_t, verdict_unstable, verdict_marginal
   use hillstab_curves_system_boundaries
   use hillstab_testing
   use hillstab_test_scratch, only: read_lines
   implicit none
   private
   public :: collect_system_boundaries

   !> The counts of the audit over all its systems.
   type :: audit_tally_t
      integer :: systems = 0       !! systems audited
      integer :: edges = 0         !! reference transitions
      integer :: missed = 0        !! reference transitions without a stability edge of the task
      integer :: false_edges = 0   !! stability edges of the task at no reference transition
      integer :: misplaced = 0     !! matched edges farther from the transition than error + w
      integer :: wrong_kind = 0    !! matched edges of another kind than the reference's
      integer :: negated = 0       !! negated kinds (both sides unstable)
      integer :: failed = 0        !! edges whose status is not ok
      integer :: at_reference = 0  !! matched edges whose estimate is below the reference's w
      real(wp) :: worst_stated = 0.0_wp     !! max |β − e|/error over edges with error ≥ w
      real(wp) :: worst_combined = 0.0_wp   !! max |β − e|/(error + w) over all matched edges
   end type audit_tally_t

contains

   function collect_system_boundaries() result(suite)
      type(testsuite_t) :: suite
      suite = new_testsuite("system_boundaries", [ &
         new_unittest("hill_blocks_are_mathieu", hill_blocks_are_mathieu), &
         new_unittest("decoupled_pair_curves", decoupled_pair_curves), &
         new_unittest("combination_edges_first_order", combination_edges_first_order), &
         new_unittest("damped_combination_tongue", damped_combination_tongue), &
         new_unittest("narrow_tongues_three_dof", narrow_tongues_three_dof), &
         new_unittest("discriminant_edges_within_estimate", discriminant_edges_within_estimate), &
         new_unittest("overlapping_tongues_no_false_edge", overlapping_tongues_no_false_edge), &
         new_unittest("random_systems_audit", random_systems_audit), &
         new_unittest("audit_against_reference", audit_against_reference)])
   end function collect_system_boundaries

   !> A system from its lists.
   function system_of(n, b, cos, mass) result(s)
      integer, intent(in) :: n
      real(wp), intent(in) :: b(:), cos(:)
      real(wp), intent(in), optional :: mass(:)
      type(matrix_system_t) :: s
      type(error_t), allocatable :: error
      call s%set_values("n", [real(n, wp)], error)
      call s%set_values("b", b, error)
      call s%set_values("cos", cos, error)
      if (present(mass)) call s%set_values("mass", mass, error)
      call s%check_values(error)
      if (allocated(error)) error stop error%message
   end function system_of

   !> Every β of `expected` inside the window is found once in `found` (to `tol`), of its sign.
   subroutine same_betas(ctx, found, expected, signs, lo, hi, tol, what)
      type(test_context_t), intent(inout) :: ctx
      type(system_boundary_t), intent(in) :: found(:)
      real(wp), intent(in) :: expected(:), lo, hi, tol
      integer, intent(in) :: signs(:)
      character(len=*), intent(in) :: what
      integer :: k, j, hits
      do k = 1, size(expected)
         if (expected(k) < lo + 1.0e-6_wp .or. expected(k) > hi - 1.0e-6_wp) cycle
         hits = 0
         do j = 1, size(found)
            if (abs(found(j)%kind) == kind_combination) cycle
            ! a kind negated: the same crossing with both sides unstable (overlapping tongues)
            if (abs(found(j)%beta - expected(k)) <= tol*max(1.0_wp, abs(expected(k))) .and. &
                abs(found(j)%kind) == merge(kind_plus_one, kind_minus_one, signs(k) > 0)) hits = hits + 1
         end do
         call check(ctx, hits >= 1, what//": a characteristic value found")
      end do
      do j = 1, size(found)
         if (abs(found(j)%kind) == kind_combination) cycle
         call check(ctx, minval(abs(expected - found(j)%beta)) <= tol*max(1.0_wp, abs(found(j)%beta)), &
                    what//": no spurious curve")
         call check(ctx, found(j)%status == status_ok, what//": confirmed by the monodromy")
      end do
   end subroutine same_betas

   !> n = 1, B = 1, K₁ᶜ = −1: the β of Hill's block method are Mathieu's characteristic values.
   subroutine hill_blocks_are_mathieu(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(matrix_system_t) :: one
      type(system_form_t) :: form
      type(system_boundary_t), allocatable :: found(:)
      type(hill_boundary_t), allocatable :: values(:)
      type(error_t), allocatable :: error
      real(wp) :: alphas(4) = [0.5_wp, 2.0_wp, 5.0_wp, 9.0_wp], betas(41)
      integer :: a, k
      one = system_of(1, [1.0_wp], [-1.0_wp])
      call prepare_system(one, 0.0_wp, form, error)
      betas = [(-2.0_wp + 0.5_wp*k, k=0, 40)]
      do a = 1, size(alphas)
         call system_boundaries(one, form, alphas(a), betas, system_method_t(system_auto, 1.0e-11_wp), found, error)
         call check(ctx, .not. allocated(error), "boundaries computed")
         call characteristic_values(mathieu_model_t(), alphas(a), 6, values, error)
         call check(ctx, .not. allocated(error), "characteristic values")
         if (allocated(error)) cycle
         call same_betas(ctx, found, values%beta, values%trace_sign, betas(1), betas(size(betas)), 1.0e-9_wp, &
                         "one equation")
      end do
   end subroutine hill_blocks_are_mathieu

   !> x₁'' + (β − α cos πτ) x₁ = 0 and x₂'' + (3β − 0.5 α cos πτ) x₂ = 0 with M = diag(1, 2):
   !> the union of the two Mathieu curves (the second at (α/4, 3β/2) after dividing by 2).
   subroutine decoupled_pair_curves(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(matrix_system_t) :: pair
      type(system_form_t) :: form
      type(system_boundary_t), allocatable :: found(:)
      type(hill_boundary_t), allocatable :: first(:), second(:)
      type(error_t), allocatable :: error
      real(wp) :: betas(31), alpha
      integer :: k
      pair = system_of(2, [1.0_wp, 0.0_wp, 0.0_wp, 3.0_wp], [-1.0_wp, 0.0_wp, 0.0_wp, -0.5_wp], &
                       mass=[1.0_wp, 0.0_wp, 0.0_wp, 2.0_wp])
      call prepare_system(pair, 0.0_wp, form, error)
      betas = [(0.2_wp*k, k=0, 30)]
      alpha = 1.5_wp
      call system_boundaries(pair, form, alpha, betas, system_method_t(system_auto, 1.0e-11_wp), found, error)
      call check(ctx, .not. allocated(error), "boundaries computed")
      call characteristic_values(mathieu_model_t(), alpha, 6, first, error)
      call characteristic_values(mathieu_model_t(), 0.25_wp*alpha, 8, second, error)
      ! the second equation: 3β/2 = β₂ on its curves, β = 2 β₂/3
      call same_betas(ctx, found, [first%beta, 2.0_wp*second%beta/3.0_wp], [first%trace_sign, second%trace_sign], &
                      betas(1), betas(size(betas)), 1.0e-9_wp, "decoupled pair")
      call check(ctx, count(found%kind == kind_combination) == 0, "no combination tongue without coupling")
   end subroutine decoupled_pair_curves

   !> The pendula pair of the shipped scene (l₂ = 0.5, c = 1): at α = 0.03 its tongue
   !> ω₁ + ω₂ = π has the centre and width of first-order perturbation theory.
   subroutine combination_edges_first_order(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(matrix_system_t) :: pair
      type(system_form_t) :: form
      type(system_boundary_t), allocatable :: found(:)
      type(error_t), allocatable :: error
      real(wp) :: betas(31), mu(2), sum_root, beta_c, half, alpha, edges(2), f12, w1, w2
      real(wp), parameter :: s2 = 1.4142135623730951_wp
      integer :: k, m
      pair = system_of(2, [2.0_wp, -1.0_wp, -1.0_wp, 1.5_wp], [-1.0_wp, 0.0_wp, 0.0_wp, -0.5_wp], &
                       mass=[1.0_wp, 0.0_wp, 0.0_wp, 0.25_wp])
      call prepare_system(pair, 0.0_wp, form, error)
      ! M^{-1/2} B M^{-1/2} = [[2, -2], [-2, 6]]: mu = 4 -+ 2 sqrt 2; its modes v (unit), the
      ! modal drive f_12 = u1ᵀ M^{-1/2} D M^{-1/2} u2 with M^{-1/2} D M^{-1/2} = diag(1, 2)
      mu = [4.0_wp - 2.0_wp*s2, 4.0_wp + 2.0_wp*s2]
      f12 = modal_coupling()
      sum_root = sqrt(mu(1)) + sqrt(mu(2))
      beta_c = (pi/sum_root)**2
      alpha = 0.03_wp
      w1 = sqrt(beta_c*mu(1))
      w2 = sqrt(beta_c*mu(2))
      half = (0.5_wp*alpha*abs(f12)/sqrt(w1*w2))/(sum_root/(2.0_wp*sqrt(beta_c)))
      betas = [(0.5_wp + 0.02_wp*k, k=0, 30)]
      call system_boundaries(pair, form, alpha, betas, system_method_t(system_auto, 1.0e-12_wp), found, error)
      call check(ctx, .not. allocated(error), "boundaries computed")
      m = 0
      do k = 1, size(found)
         if (found(k)%kind /= kind_combination) cycle
         m = m + 1
         if (m <= 2) edges(m) = found(k)%beta
         call check(ctx, found(k)%route == route_discriminant, "by Broucke's discriminant")
      end do
      call check(ctx, m == 2, "two edges of the combination tongue")
      if (m /= 2) return
      call check(ctx, (edges(2) - edges(1))/(2.0_wp*half), 1.0_wp, abs=0.03_wp, message="width / first order")
      call check(ctx, 0.5_wp*(edges(1) + edges(2)), beta_c, abs=0.1_wp*half, message="centre")

   contains

      real(wp) function modal_coupling()
         real(wp) :: u(2, 2)
         integer :: i
         ! eigenvectors of [[2, -2], [-2, 6]]: (−2, μ − 2), unit
         do i = 1, 2
            u(:, i) = [-2.0_wp, mu(i) - 2.0_wp]
            u(:, i) = u(:, i)/norm2(u(:, i))
         end do
         modal_coupling = u(1, 1)*u(1, 2) + 2.0_wp*u(2, 1)*u(2, 2)
      end function modal_coupling
   end subroutine combination_edges_first_order

   !> The reference at one point: the point routine (a fresh node set) at `tolerance`.
   subroutine reference_point(system, form, alpha, beta, tolerance, verdict, log_top, discriminant)
      type(matrix_system_t), intent(in) :: system
      type(system_form_t), intent(in) :: form
      real(wp), intent(in) :: alpha, beta, tolerance
      integer, intent(out) :: verdict
      real(wp), intent(out) :: log_top, discriminant
      type(system_nodes_t) :: nodes
      type(system_monodromy_t) :: r
      type(floquet_t) :: f
      type(error_t), allocatable :: error
      call system_point(system, form, alpha, beta, system_method_t(system_auto, tolerance), nodes, r, f, error)
      verdict = verdict_marginal
      log_top = 0.0_wp
      discriminant = 0.0_wp
      if (allocated(error)) return
      verdict = f%verdict
      log_top = f%log_modulus(1)
      discriminant = f%discriminant
   end subroutine reference_point

   !> The reference's sign at β: what = 1, ln max|λ| > 0; 2, D < 0; 3, the verdict unstable.
   logical function reference_inside(system, form, alpha, beta, what)
      type(matrix_system_t), intent(in) :: system
      type(system_form_t), intent(in) :: form
      real(wp), intent(in) :: alpha, beta
      integer, intent(in) :: what
      integer :: verdict
      real(wp) :: log_top, d
      call reference_point(system, form, alpha, beta, 1.0e-12_wp, verdict, log_top, d)
      select case (what)
      case (1); reference_inside = log_top > 0.0_wp
      case (2); reference_inside = d < 0.0_wp
      case default; reference_inside = verdict == verdict_unstable
      end select
   end function reference_inside

   !> Bisection of the reference's sign over [lo, hi] (signs differ) to 1e-13 max(1, |β|).
   real(wp) function reference_edge(system, form, alpha, lo, hi, what) result(edge)
      type(matrix_system_t), intent(in) :: system
      type(system_form_t), intent(in) :: form
      real(wp), intent(in) :: alpha, lo, hi
      integer, intent(in) :: what
      real(wp) :: a, b, mid
      logical :: at_a
      integer :: step
      a = lo
      b = hi
      at_a = reference_inside(system, form, alpha, a, what)
      do step = 1, 80
         mid = 0.5_wp*(a + b)
         if (reference_inside(system, form, alpha, mid, what) .eqv. at_a) then
            a = mid
         else
            b = mid
         end if
         if (b - a <= 1.0e-13_wp*max(1.0_wp, abs(mid))) exit
      end do
      edge = 0.5_wp*(a + b)
   end function reference_edge

   !> The brackets of a fine scan of the reference verdict: consecutive decided samples (marginal
   !> ones skipped) of which one is stable and the other unstable.
   subroutine scan_transitions(system, form, alpha, lo, hi, count, los, his)
      type(matrix_system_t), intent(in) :: system
      type(system_form_t), intent(in) :: form
      real(wp), intent(in) :: alpha, lo, hi
      integer, intent(in) :: count
      real(wp), allocatable, intent(out) :: los(:), his(:)
      integer :: j, verdict, last_verdict
      real(wp) :: beta, last_beta, log_top, d
      allocate (los(0), his(0))
      last_verdict = verdict_marginal
      last_beta = lo
      do j = 0, count - 1
         beta = lo + (hi - lo)*j/(count - 1)
         call reference_point(system, form, alpha, beta, 1.0e-10_wp, verdict, log_top, d)
         if (verdict == verdict_marginal) cycle
         if (last_verdict /= verdict_marginal .and. verdict /= last_verdict) then
            los = [los, last_beta]
            his = [his, beta]
         end if
         last_verdict = verdict
         last_beta = beta
      end do
   end subroutine scan_transitions

   !> The reference verdicts on the two sides of β at β ∓ d, d from 1e-9 max(1, |β|) growing
   !> fourfold up to `cap` until both are decided.
   subroutine reference_sides(system, form, alpha, beta, cap, below, above)
      type(matrix_system_t), intent(in) :: system
      type(system_form_t), intent(in) :: form
      real(wp), intent(in) :: alpha, beta, cap
      integer, intent(out) :: below, above
      real(wp) :: d, log_top, disc
      d = min(1.0e-9_wp*max(1.0_wp, abs(beta)), cap)
      do
         call reference_point(system, form, alpha, beta - d, 1.0e-11_wp, below, log_top, disc)
         call reference_point(system, form, alpha, beta + d, 1.0e-11_wp, above, log_top, disc)
         if ((below /= verdict_marginal .and. above /= verdict_marginal) .or. d >= cap) exit
         d = min(4.0_wp*d, cap)
      end do
   end subroutine reference_sides

   !> Every edge of `found` is what its kind says: a positive kind stable on one side and
   !> unstable on the other, a negated kind unstable on both (the reference's verdicts).
   subroutine edges_are_transitions(ctx, system, form, alpha, found, what)
      type(test_context_t), intent(inout) :: ctx
      type(matrix_system_t), intent(in) :: system
      type(system_form_t), intent(in) :: form
      real(wp), intent(in) :: alpha
      type(system_boundary_t), intent(in) :: found(:)
      character(len=*), intent(in) :: what
      integer :: k, below, above
      real(wp) :: gap
      do k = 1, size(found)
         gap = 1.0e-3_wp
         if (k > 1) gap = min(gap, found(k)%beta - found(k - 1)%beta)
         if (k < size(found)) gap = min(gap, found(k + 1)%beta - found(k)%beta)
         if (gap <= 0.0_wp) cycle
         call reference_sides(system, form, alpha, found(k)%beta, 0.45_wp*gap, below, above)
         if (below == verdict_marginal .or. above == verdict_marginal) then
            call check(ctx, found(k)%status /= status_ok .or. found(k)%route == route_hill, &
                       what//": an edge the reference cannot decide is not claimed confirmed")
            cycle
         end if
         if (found(k)%kind > 0) then
            call check(ctx, below /= above, what//": a stability edge is one ("//trim(real_text(found(k)%beta))// &
                       ")")
         else
            call check(ctx, below == verdict_unstable .and. above == verdict_unstable, &
                       what//": a negated kind is unstable on both sides")
         end if
      end do
   end subroutine edges_are_transitions

   pure function real_text(x) result(text)
      real(wp), intent(in) :: x
      character(len=32) :: text
      write (text, '(es22.14)') x
   end function real_text

   !> The damped pair of the issue: its combination tongue (β ≈ 1.46 … 1.63 at α = 0.2875)
   !> has both edges (route_modulus), each confirmed by the point routine and at the fine scan's
   !> bisection on ln max|λ| within its error estimate.
   subroutine damped_combination_tongue(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(matrix_system_t) :: pair
      type(system_form_t) :: form
      type(system_boundary_t), allocatable :: found(:), tongue(:)
      type(error_t), allocatable :: error
      real(wp), allocatable :: los(:), his(:)
      real(wp) :: betas(400), alpha, edge
      integer :: k
      pair = system_of(2, [1.621_wp, 0.1409_wp, 0.1409_wp, 1.8294_wp], [1.3493_wp, -2.0399_wp, -2.0399_wp, &
                       -1.5668_wp], mass=[0.8768_wp, 0.1721_wp, 0.1721_wp, 1.3369_wp])
      call pair%set_values("damping", [0.05_wp, 0.01_wp, 0.01_wp, 0.03_wp], error)
      call pair%check_values(error)
      call prepare_system(pair, 0.03_wp, form, error)
      call check(ctx, .not. allocated(error), "prepared")
      if (allocated(error)) return
      alpha = 0.2875_wp
      betas = [(0.5_wp + 6.5_wp*k/399.0_wp, k=0, 399)]
      call system_boundaries(pair, form, alpha, betas, system_method_t(system_auto, 1.0e-10_wp), found, error)
      call check(ctx, .not. allocated(error), "boundaries computed")
      if (allocated(error)) return
      ! between the tongues at −1 ending at 1.4353 and starting at 1.7000
      tongue = pack(found, found%kind == kind_combination .and. found%beta > 1.44_wp .and. found%beta < 1.69_wp)
      call check(ctx, size(tongue) == 2, "two combination edges in 1.44 .. 1.69")
      call scan_transitions(pair, form, alpha, 1.44_wp, 1.69_wp, 2000, los, his)
      call check(ctx, size(los) == 2, "the reference scan: two transitions")
      if (size(tongue) /= 2 .or. size(los) /= 2) return
      do k = 1, 2
         call check(ctx, tongue(k)%route == route_modulus, "by the largest modulus")
         call check(ctx, tongue(k)%status == status_ok, "confirmed")
         edge = reference_edge(pair, form, alpha, los(k), his(k), 1)
         call check(ctx, tongue(k)%beta, edge, abs=tongue(k)%error_estimate, message="edge vs bisection on ln max|l|")
         call check(ctx, tongue(k)%error_estimate < 1.0e-7_wp, "a tight estimate")
      end do
      call edges_are_transitions(ctx, pair, form, alpha, found, "damped pair")
   end subroutine damped_combination_tongue

   !> The 3-DOF system of the issue at α = 0.05: its narrow combination tongues at β ≈ 1.757982
   !> and 2.203680 (|λ| ≈ 1.002) have two edges each, at the fine scan's transitions.
   subroutine narrow_tongues_three_dof(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(matrix_system_t) :: three
      type(system_form_t) :: form
      type(system_boundary_t), allocatable :: found(:), tongue(:)
      type(error_t), allocatable :: error
      real(wp), allocatable :: los(:), his(:)
      real(wp) :: betas(400), alpha, edge, centres(2) = [1.757982_wp, 2.203680_wp]
      integer :: k, c
      three = three_dof()
      call prepare_system(three, 0.0_wp, form, error)
      alpha = 0.05_wp
      betas = [(0.5_wp + 9.5_wp*k/399.0_wp, k=0, 399)]
      call system_boundaries(three, form, alpha, betas, system_method_t(system_auto, 1.0e-10_wp), found, error)
      call check(ctx, .not. allocated(error), "boundaries computed")
      if (allocated(error)) return
      do c = 1, 2
         tongue = pack(found, found%kind == kind_combination .and. abs(found%beta - centres(c)) < 0.01_wp)
         call check(ctx, size(tongue) == 2, "two edges around "//trim(real_text(centres(c))))
         call scan_transitions(three, form, alpha, centres(c) - 0.008_wp, centres(c) + 0.008_wp, 1500, los, his)
         call check(ctx, size(los) == 2, "the reference scan: two transitions")
         if (size(tongue) /= 2 .or. size(los) /= 2) cycle
         do k = 1, 2
            call check(ctx, tongue(k)%status == status_ok, "confirmed")
            edge = reference_edge(three, form, alpha, los(k), his(k), 3)
            ! the verdict's marginal band around the edge is about 1e-9 wide
            call check(ctx, tongue(k)%beta, edge, abs=tongue(k)%error_estimate + 1.0e-8_wp, &
                       message="edge vs bisection on the verdict")
         end do
      end do
      call edges_are_transitions(ctx, three, form, alpha, found, "three DOF")
   end subroutine narrow_tongues_three_dof

   function three_dof() result(s)
      type(matrix_system_t) :: s
      type(error_t), allocatable :: error
      s = system_of(3, [1.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, 1.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, 1.0_wp], &
                    [-0.6_wp, -0.2_wp, 0.0_wp, -0.2_wp, -0.1_wp, -0.2_wp, 0.0_wp, -0.2_wp, -0.4_wp], &
                    mass=[1.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, 0.8_wp, 0.0_wp, 0.0_wp, 0.0_wp, 1.2_wp])
      call s%set_values("k0", [0.6_wp, -0.3_wp, 0.0_wp, -0.3_wp, 0.6_wp, -0.3_wp, 0.0_wp, -0.3_wp, 0.6_wp], error)
      call s%set_values("sin", [0.705_wp, -0.2843_wp, 0.014_wp, -0.2843_wp, -0.2327_wp, 0.0584_wp, 0.014_wp, &
                                0.0584_wp, -0.1682_wp], error)
      call s%check_values(error)
      if (allocated(error)) error stop error%message
   end function three_dof

   !> The pendula pair: every edge of Broucke's discriminant (the tongues at ω₁ + ω₂ = π and
   !> 2π) lies within its error estimate of a bisection of D to 1e-13 at tolerance 1e-12.
   subroutine discriminant_edges_within_estimate(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(matrix_system_t) :: pair
      type(system_form_t) :: form
      type(system_boundary_t), allocatable :: found(:)
      type(error_t), allocatable :: error
      real(wp) :: betas(121), alphas(2) = [0.06_wp, 0.5_wp], edge, w
      integer :: k, a, seen
      pair = system_of(2, [2.0_wp, -1.0_wp, -1.0_wp, 1.5_wp], [-1.0_wp, 0.0_wp, 0.0_wp, -0.5_wp], &
                       mass=[1.0_wp, 0.0_wp, 0.0_wp, 0.25_wp])
      call prepare_system(pair, 0.0_wp, form, error)
      betas = [(0.025_wp*k, k=0, 120)]
      seen = 0
      do a = 1, size(alphas)
         call system_boundaries(pair, form, alphas(a), betas, system_method_t(system_auto, 1.0e-10_wp), found, error)
         call check(ctx, .not. allocated(error), "boundaries computed")
         if (allocated(error)) return
         do k = 1, size(found)
            if (found(k)%route /= route_discriminant) cycle
            seen = seen + 1
            ! a bracket around the edge that holds no other edge
            w = 2.0_wp*found(k)%error_estimate + 1.0e-9_wp
            do while (reference_inside(pair, form, alphas(a), found(k)%beta - w, 2) .eqv. &
                      reference_inside(pair, form, alphas(a), found(k)%beta + w, 2))
               w = 1.5_wp*w
               if (w > 0.4_wp*gap_of(k)) exit
            end do
            edge = reference_edge(pair, form, alphas(a), found(k)%beta - w, found(k)%beta + w, 2)
            call check(ctx, found(k)%beta, edge, abs=found(k)%error_estimate, message="edge within its estimate")
         end do
      end do
      call check(ctx, seen == 8, "four tongues' edges")

   contains

      real(wp) function gap_of(k)
         integer, intent(in) :: k
         gap_of = 1.0_wp
         if (k > 1) gap_of = min(gap_of, found(k)%beta - found(k - 1)%beta)
         if (k < size(found)) gap_of = min(gap_of, found(k + 1)%beta - found(k)%beta)
      end function gap_of
   end subroutine discriminant_edges_within_estimate

   !> Where the pendula's simple tongues overlap (α = 1.3, 1.45), and for the 3-DOF system,
   !> every stability edge is a transition of the reference verdict and every negated kind
   !> is unstable on both sides; some negated kinds occur.
   subroutine overlapping_tongues_no_false_edge(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(matrix_system_t) :: pair
      type(system_form_t) :: form
      type(system_boundary_t), allocatable :: found(:)
      type(error_t), allocatable :: error
      real(wp) :: betas(121), alphas(2) = [1.3_wp, 1.45_wp]
      integer :: k, a, negated
      pair = system_of(2, [2.0_wp, -1.0_wp, -1.0_wp, 1.5_wp], [-1.0_wp, 0.0_wp, 0.0_wp, -0.5_wp], &
                       mass=[1.0_wp, 0.0_wp, 0.0_wp, 0.25_wp])
      call prepare_system(pair, 0.0_wp, form, error)
      betas = [(0.025_wp*k, k=0, 120)]
      negated = 0
      do a = 1, size(alphas)
         call system_boundaries(pair, form, alphas(a), betas, system_method_t(system_auto, 1.0e-10_wp), found, error)
         call check(ctx, .not. allocated(error), "boundaries computed")
         if (allocated(error)) return
         negated = negated + count(found%kind < 0)
         call edges_are_transitions(ctx, pair, form, alphas(a), found, "pendula")
      end do
      call check(ctx, negated > 0, "crossings inside unstable regions are labelled")
   end subroutine overlapping_tongues_no_false_edge

   !> Random systems, 2–4 DOF, damped and not: a fine scan (4000 samples) of the reference
   !> verdict has no transition without an edge of the task (missed), and every stability
   !> edge is a transition (false).
   subroutine random_systems_audit(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(matrix_system_t) :: s
      type(system_form_t) :: form
      type(system_boundary_t), allocatable :: found(:)
      type(error_t), allocatable :: error
      real(wp), allocatable :: los(:), his(:)
      real(wp) :: betas(100), lo, hi, alpha
      integer :: case, n, k, missed, j
      integer, parameter :: dofs(4) = [2, 3, 2, 4]
      logical, parameter :: damped(4) = [.false., .true., .true., .false.]
      integer :: seed
      seed = 12345
      lo = 0.5_wp
      hi = 3.0_wp
      alpha = 0.4_wp
      betas = [(lo + (hi - lo)*k/99.0_wp, k=0, 99)]
      do case = 1, size(dofs)
         n = dofs(case)
         s = random_system(n, damped(case), seed)
         call prepare_system(s, merge(0.02_wp, 0.0_wp, damped(case)), form, error)
         call check(ctx, .not. allocated(error), "prepared")
         if (allocated(error)) return
         call system_boundaries(s, form, alpha, betas, system_method_t(system_auto, 1.0e-10_wp), found, error)
         call check(ctx, .not. allocated(error), "boundaries computed")
         if (allocated(error)) return
         call scan_transitions(s, form, alpha, lo, hi, 4000, los, his)
         missed = 0
         do j = 1, size(los)
            if (count(found%kind > 0 .and. found%beta >= los(j) .and. found%beta <= his(j)) == 0) missed = missed + 1
         end do
         call check(ctx, missed == 0, "random system "//trim(real_text(real(case, wp)))//": no transition missed")
         call edges_are_transitions(ctx, s, form, alpha, found, "random system")
      end do
   end subroutine random_systems_audit

   !> A random system: M = I + small symmetric, B = I + small symmetric, K0 symmetric, a
   !> symmetric drive, and damping C = 0.02 I + small when `damped`.
   function random_system(n, damped, seed) result(s)
      integer, intent(in) :: n
      logical, intent(in) :: damped
      integer, intent(inout) :: seed
      type(matrix_system_t) :: s
      type(error_t), allocatable :: error
      real(wp) :: m(n, n), b(n, n), k0(n, n), c(n, n), d(n, n)
      integer :: i
      m = symmetric(0.1_wp)
      b = symmetric(0.2_wp)
      k0 = symmetric(0.3_wp)
      d = symmetric(0.6_wp)
      c = symmetric(0.005_wp)
      do i = 1, n
         m(i, i) = m(i, i) + 1.0_wp + 0.3_wp*i
         b(i, i) = b(i, i) + 1.0_wp
         k0(i, i) = k0(i, i) + 0.4_wp*i
         c(i, i) = c(i, i) + 0.02_wp
      end do
      s = system_of(n, reshape(b, [n*n]), reshape(d, [n*n]), mass=reshape(m, [n*n]))
      call s%set_values("k0", reshape(k0, [n*n]), error)
      if (damped) call s%set_values("damping", reshape(c, [n*n]), error)
      call s%check_values(error)
      if (allocated(error)) error stop error%message

   contains

      function symmetric(size_) result(a)
         real(wp), intent(in) :: size_
         real(wp) :: a(n, n)
         integer :: p, q
         do q = 1, n
            do p = 1, q
               seed = modulo(1103515245*int(seed, kind=8) + 12345, 2147483648_8)
               a(p, q) = size_*(2.0_wp*real(seed, wp)/2147483648.0_wp - 1.0_wp)
               a(q, p) = a(p, q)
            end do
         end do
      end function symmetric
   end function random_system

   !> The audit against data/reference/audit_set.dat (data/reference/make_audit_reference.py,
   !> independent of this code: a double-precision numpy scan of 4000 samples a row with a
   !> search of every local minimum of its signed quantity, each transition e confirmed by the
   !> verdicts in extended precision, mpmath, at e ∓ w, and each region's verdict at its
   !> midpoint). Twelve systems, 2–4 DOF, undamped (one gyroscopic) and damped (C, εM or
   !> both), some with sine terms or two harmonics, one row each at the file's α and samples,
   !> tolerance 1e-11.
   !> No reference transition without a stability edge of the task within 1e-4 max(1, |e|)
   !> (missed), no stability edge of the task without one (false), each matched edge of the
   !> reference's kind and within its error estimate plus w of the transition (w is the
   !> reference's precision, about 2e-11 max(1, |e|)), each negated kind inside an unstable
   !> region of the reference, every status ok.
   subroutine audit_against_reference(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=*), parameter :: path = "data/reference/audit_set.dat"
      character(len=1024), allocatable :: lines(:)
      character(len=16) :: key
      type(matrix_system_t) :: s
      type(error_t), allocatable :: error
      type(audit_tally_t) :: tally
      real(wp), allocatable :: values(:), ref_beta(:), ref_w(:), reg_lo(:), reg_hi(:)
      integer, allocatable :: ref_kind(:), reg_stable(:)
      real(wp) :: eps, alpha, lo, hi, x(6)
      integer :: k, ios, id, n, h, has_sin, samples, ham, count_values, below, kind
      lines = read_lines(path)
      call check(ctx, size(lines) > 0, "reads "//path)
      allocate (values(0))
      do k = 1, size(lines)
         if (len_trim(lines(k)) == 0 .or. lines(k)(1:1) == "#") cycle
         read (lines(k), *, iostat=ios) key
         select case (trim(key))
         case ("system")
            read (lines(k), *, iostat=ios) key, id, n, h, has_sin, eps, alpha, lo, hi, samples, ham
            call check(ctx, ios == 0, "reads "//trim(lines(k)))
            s = matrix_system_t()
            call s%set_values("n", [real(n, wp)], error)
            allocate (ref_beta(0), ref_w(0), ref_kind(0), reg_lo(0), reg_hi(0), reg_stable(0))
         case ("mass", "damping", "gyroscopic", "k0", "b", "cos", "sin")
            count_values = n*n
            if (trim(key) == "cos" .or. trim(key) == "sin") count_values = h*n*n
            deallocate (values)
            allocate (values(count_values))
            read (lines(k), *, iostat=ios) key, values
            call check(ctx, ios == 0, "reads the "//trim(key)//" of system "//trim(real_text(real(id, wp))))
            call s%set_values(trim(key), values, error)
            call check(ctx, .not. allocated(error), "sets the "//trim(key))
         case ("edge")
            ! edge beta w stable_below kind q_below q_above
            read (lines(k), *, iostat=ios) key, x(1:2), below, kind
            call check(ctx, ios == 0, "reads "//trim(lines(k)))
            ref_beta = [ref_beta, x(1)]
            ref_w = [ref_w, x(2)]
            ref_kind = [ref_kind, kind]
         case ("region")
            ! region lo hi stable beta_mid q_mid
            read (lines(k), *, iostat=ios) key, x(1:2), below
            call check(ctx, ios == 0, "reads "//trim(lines(k)))
            reg_lo = [reg_lo, x(1)]
            reg_hi = [reg_hi, x(2)]
            reg_stable = [reg_stable, below]
         case ("end")
            call s%check_values(error)
            call check(ctx, .not. allocated(error), "system "//trim(real_text(real(id, wp)))//" complete")
            if (allocated(error)) return
            call audit_row(ctx, s, id, eps, alpha, lo, hi, samples, ham == 1, ref_beta, ref_w, ref_kind, reg_lo, &
                           reg_hi, reg_stable == 1, tally)
            deallocate (ref_beta, ref_w, ref_kind, reg_lo, reg_hi, reg_stable)
         end select
      end do
      print '(4x,a,i0,a,i0,a,i0,a,i0,a,i0,a,i0,a,i0)', "audit: ", tally%systems, " systems, ", tally%edges, &
         " transitions; missed ", tally%missed, ", false ", tally%false_edges, ", misplaced ", tally%misplaced, &
         ", wrong kind ", tally%wrong_kind, ", failed ", tally%failed
      print '(4x,a,es9.2,a,es9.2,a,i0,a,i0,a)', "audit: worst |beta - e|/error ", tally%worst_stated, &
         " (error >= w), worst |beta - e|/(error + w) ", tally%worst_combined, "; ", tally%at_reference, &
         " estimates below w; ", tally%negated, " negated kinds"
      call check(ctx, tally%systems >= 10, "at least ten systems")
      call check(ctx, tally%missed == 0, "no transition missed")
      call check(ctx, tally%false_edges == 0, "no false edge")
      call check(ctx, tally%misplaced == 0, "every edge within its estimate (plus the reference's w)")
      call check(ctx, tally%wrong_kind == 0, "every edge of the reference's kind")
      call check(ctx, tally%failed == 0, "every edge confirmed")
   end subroutine audit_against_reference

   !> One row of the audit: the task at the row's samples against the reference's transitions
   !> (ref_*) and regions (reg_*).
   subroutine audit_row(ctx, s, id, eps, alpha, lo, hi, samples, hamiltonian, ref_beta, ref_w, ref_kind, reg_lo, &
                        reg_hi, reg_stable, tally)
      type(test_context_t), intent(inout) :: ctx
      type(matrix_system_t), intent(in) :: s
      integer, intent(in) :: id, samples
      real(wp), intent(in) :: eps, alpha, lo, hi
      logical, intent(in) :: hamiltonian
      real(wp), intent(in) :: ref_beta(:), ref_w(:), reg_lo(:), reg_hi(:)
      integer, intent(in) :: ref_kind(:)
      logical, intent(in) :: reg_stable(:)
      type(audit_tally_t), intent(inout) :: tally
      !> the monodromy's tolerance: at 1e-10 the shallowest tongue of the set (system 2 at
      !> β ≈ 12.7445, D ≥ −5.9e-9) lies within D's error bound (2e-8) and the verdict is
      !> marginal inside it
      real(wp), parameter :: audit_tolerance = 1.0e-11_wp
      type(system_form_t) :: form
      type(system_boundary_t), allocatable :: found(:)
      type(error_t), allocatable :: error
      real(wp) :: betas(samples), distance, near
      integer :: hits(size(ref_beta)), k, j, r
      character(len=:), allocatable :: what
      what = "audit system "//trim(adjustl(int_text(id)))
      call prepare_system(s, eps, form, error)
      call check(ctx, .not. allocated(error), what//": prepared")
      if (allocated(error)) return
      call check(ctx, form%hamiltonian .eqv. hamiltonian, what//": Hamiltonian as the reference says")
      betas = [(lo + (hi - lo)*k/real(samples - 1, wp), k=0, samples - 1)]
      call system_boundaries(s, form, alpha, betas, system_method_t(system_auto, audit_tolerance), found, error)
      call check(ctx, .not. allocated(error), what//": boundaries computed")
      if (allocated(error)) return
      tally%systems = tally%systems + 1
      tally%edges = tally%edges + size(ref_beta)
      hits = 0
      do k = 1, size(found)
         if (found(k)%status /= status_ok) then
            tally%failed = tally%failed + 1
            call check(ctx, .false., what//": status ok at "//trim(real_text(found(k)%beta)))
         end if
         if (found(k)%kind < 0) then
            ! both sides unstable: inside an unstable region, away from every transition
            tally%negated = tally%negated + 1
            r = findloc(reg_lo <= found(k)%beta .and. reg_hi >= found(k)%beta, .true., dim=1)
            distance = huge(1.0_wp)
            if (size(ref_beta) > 0) distance = minval(abs(ref_beta - found(k)%beta) - ref_w)
            if (r == 0) cycle
            if (reg_stable(r) .or. distance <= found(k)%error_estimate) then
               tally%false_edges = tally%false_edges + 1
               call check(ctx, .false., what//": a negated kind inside an unstable region at "// &
                          trim(real_text(found(k)%beta)))
            end if
            cycle
         end if
         j = 0
         if (size(ref_beta) > 0) j = minloc(abs(ref_beta - found(k)%beta), dim=1)
         near = 0.0_wp
         if (j > 0) near = 1.0e-4_wp*max(1.0_wp, abs(ref_beta(j)))
         if (j == 0) then
            distance = huge(1.0_wp)
         else
            distance = abs(found(k)%beta - ref_beta(j))
         end if
         if (distance > near) then
            tally%false_edges = tally%false_edges + 1
            call check(ctx, .false., what//": no reference transition at the edge "//trim(real_text(found(k)%beta)))
            cycle
         end if
         hits(j) = hits(j) + 1
         if (hits(j) > 1) then
            tally%false_edges = tally%false_edges + 1
            call check(ctx, .false., what//": a second edge at the transition "//trim(real_text(ref_beta(j))))
            cycle
         end if
         if (task_kind(ref_kind(j)) /= found(k)%kind) then
            tally%wrong_kind = tally%wrong_kind + 1
            call check(ctx, .false., what//": the kind of the edge at "//trim(real_text(ref_beta(j))))
         end if
         if (distance > found(k)%error_estimate + ref_w(j)) then
            tally%misplaced = tally%misplaced + 1
            call check(ctx, found(k)%beta, ref_beta(j), abs=found(k)%error_estimate + ref_w(j), &
                       message=what//": the edge within its estimate (plus the reference's w)")
         end if
         tally%worst_combined = max(tally%worst_combined, distance/(found(k)%error_estimate + ref_w(j)))
         if (found(k)%error_estimate >= ref_w(j)) then
            tally%worst_stated = max(tally%worst_stated, distance/found(k)%error_estimate)
         else
            tally%at_reference = tally%at_reference + 1
         end if
      end do
      do j = 1, size(ref_beta)
         if (hits(j) > 0) cycle
         tally%missed = tally%missed + 1
         call check(ctx, .false., what//": the transition at "//trim(real_text(ref_beta(j)))//" found")
      end do
   end subroutine audit_row

   !> The task's kind of the reference's: 1 at +1, −1 at −1, 0 a combination.
   pure integer function task_kind(reference)
      integer, intent(in) :: reference
      select case (reference)
      case (1); task_kind = kind_plus_one
      case (-1); task_kind = kind_minus_one
      case default; task_kind = kind_combination
      end select
   end function task_kind

   pure function int_text(i) result(text)
      integer, intent(in) :: i
      character(len=16) :: text
      write (text, '(i0)') i
   end function int_text
end module test_system_boundaries

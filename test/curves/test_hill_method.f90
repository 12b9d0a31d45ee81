!> Tests of Hill's method for the transition curves: α = 0 closed form β = (nπ/2)²,
!> published Mathieu characteristic values and GSL's, the exact boundaries β = 0 and
!> β = π² of the elastic model, S = ±2 by method auto on every computed boundary,
!> β = π²/4 inside the first tongue, monotone (Ritz) convergence in the truncation,
!> agreement of the three formulations, coexistence (Mathieu never for ν ≠ 0, elastic
!> S = +2 tongues always), and bad input.
module test_hill_method
   use hillstab_core_kinds, only: wp, pi, pi2
   use hillstab_core_error, only: error_t, err_invalid_parameter
   use hillstab_hill_transfer, only: trace_t
   use hillstab_integrate_monodromy, only: method_t, method_auto, monodromy_trace
   use hillstab_hill_mathieu, only: mathieu_transition_beta, mathieu_kind_a, mathieu_kind_b
   use hillstab_curves_hill_method
   use hillstab_testing
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   use hillstab_hill_model, only: hill_point_t
   use hillstab_hill_model_elastic, only: elastic_model_t
   use hillstab_hill_model_mathieu, only: mathieu_model_t
   use hillstab_hill_model, only: hill_model_t
   use hillstab_hill_models, only: model_from_code
   use hillstab_test_models, only: model_of_code
   implicit none
   private
   public :: collect_hill_method

contains

   function collect_hill_method() result(suite)
      type(testsuite_t) :: suite
      suite = new_testsuite("hill_method", [ &
         new_unittest("alpha_zero_closed_form", alpha_zero_closed_form), &
         new_unittest("mathieu_published", mathieu_published), &
         new_unittest("mathieu_against_gsl", mathieu_against_gsl), &
         new_unittest("exact_boundaries_zero_and_pi2", exact_boundaries_zero_and_pi2), &
         new_unittest("trace_on_boundaries", trace_on_boundaries), &
         new_unittest("quarter_pi2_in_first_tongue", quarter_pi2_in_first_tongue), &
         new_unittest("tongues_open_and_closed", tongues_open_and_closed), &
         new_unittest("coexistence_by_structure", coexistence_by_structure), &
         new_unittest("error_bound_against_references", error_bound_against_references), &
         new_unittest("ritz_convergence", ritz_convergence), &
         new_unittest("formulations_agree", formulations_agree), &
         new_unittest("bad_input", bad_input)])
   end function collect_hill_method

   !> α = 0: Q ≡ β, S = 2 cos 2√β: boundaries exactly β = (nπ/2)², S = +2 for even n,
   !> −2 for odd n, each order twice (a_n = b_n), in both models.
   subroutine alpha_zero_closed_form(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(hill_boundary_t), allocatable :: c(:)
      type(error_t), allocatable :: error
      class(hill_model_t), pointer :: model
      integer :: i, code, n
      do code = 1, 2   ! the elastic and the Mathieu model
         model => model_of_code(code)
         call hill_boundaries(model, 0.0_wp, -2.0_wp, 100.0_wp, 1.0e-12_wp, c, error)
         call check(ctx, .not. allocated(error), "no error")
         if (allocated(error)) return
         ! n = 0 once, n = 1 … 6 twice: (6π/2)² = 88.8 < 100 < (7π/2)²
         call check(ctx, size(c) == 13, "13 boundaries in [-2, 100]")
         do i = 1, size(c)
            n = c(i)%order
            call check(ctx, c(i)%beta, (n*pi/2)**2, rel=1.0e-13_wp, abs=1.0e-13_wp, message="(n pi/2)^2")
            call check(ctx, c(i)%trace_sign == merge(2, -2, mod(n, 2) == 0), "kind follows the parity of n")
            call check(ctx, c(i)%coexistent .eqv. n > 0, "alpha = 0: every tongue has zero width")
         end do
      end do
   end subroutine alpha_zero_closed_form

   !> The Mathieu model's curves are β = (π²/4) a_n(q), (π²/4) b_n(q) with q = 2ν/π²:
   !> published values at q = 1, 10, 25.
   subroutine mathieu_published(ctx)
      type(test_context_t), intent(inout) :: ctx
      call expect(1.0_wp, 0, 1, -0.455138604107_wp)
      call expect(1.0_wp, 1, -1, -0.110248816992_wp)
      call expect(1.0_wp, 1, 1, 1.859108072514_wp)
      call expect(1.0_wp, 2, -1, 3.917024772998_wp)
      call expect(10.0_wp, 0, 1, -13.936979956659_wp)
      call expect(10.0_wp, 1, -1, -13.936552479250_wp)
      call expect(25.0_wp, 0, 1, -40.256779546567_wp)
      call expect(25.0_wp, 1, 1, -21.314899690666_wp)
   contains
      subroutine expect(q, order, parity, a)
         real(wp), intent(in) :: q, a
         integer, intent(in) :: order, parity
         type(hill_boundary_t), allocatable :: c(:)
         type(error_t), allocatable :: error
         integer :: i, hits
         character(len=40) :: label
         write (label, '(a,i0,a,f5.1)') merge("a", "b", parity == 1), order, " at q = ", q
         call hill_boundaries(mathieu_model_t(), q*pi2/2, -0.25_wp*pi2*(2*q + 2), 0.25_wp*pi2*(order + 1)**2 + 1, &
                              1.0e-13_wp, c, error)
         call check(ctx, .not. allocated(error), trim(label)//": no error")
         if (allocated(error)) return
         hits = 0
         do i = 1, size(c)
            if (c(i)%order /= order .or. c(i)%parity /= parity) cycle
            hits = hits + 1
            call check(ctx, 4*c(i)%beta/pi2, a, abs=1.0e-11_wp, message=trim(label))
         end do
         call check(ctx, hits == 1, trim(label)//": found once")
      end subroutine expect
   end subroutine mathieu_published

   !> Hill's method on the Mathieu operator against GSL's a_n, b_n, orders 0 … 12.
   subroutine mathieu_against_gsl(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp), parameter :: nus(5) = [-8.0_wp, 0.3_wp, 2.0_wp, 7.0_wp, 20.0_wp]
      type(hill_boundary_t), allocatable :: c(:)
      type(error_t), allocatable :: error
      real(wp) :: beta_gsl
      integer :: i, f, n_checked
      do f = 1, size(nus)
         call hill_boundaries(mathieu_model_t(), nus(f), -30.0_wp, 0.25_wp*pi2*12.5_wp**2, 1.0e-12_wp, c, error)
         call check(ctx, .not. allocated(error), "no error")
         if (allocated(error)) return
         n_checked = 0
         do i = 1, size(c)
            if (c(i)%order > 12) cycle
            call mathieu_transition_beta(merge(mathieu_kind_a, mathieu_kind_b, c(i)%parity == 1), c(i)%order, &
                                         nus(f), beta_gsl, error)
            call check(ctx, .not. allocated(error), "GSL computes it")
            call check(ctx, c(i)%beta, beta_gsl, rel=1.0e-11_wp, abs=1.0e-10_wp, message="Hill against GSL")
            n_checked = n_checked + 1
         end do
         call check(ctx, n_checked == 25, "a_0 … a_12 and b_1 … b_12 all found")
      end do
   end subroutine mathieu_against_gsl

   !> Elastic model: β = 0 is a periodic boundary for every α (x = 1 − (α/π²) cos πτ
   !> solves the equation), and β = π² is a periodic boundary of both parities
   !> (x = cos πτ and sin πτ: Q ≡ π²), so that tongue has zero width.
   subroutine exact_boundaries_zero_and_pi2(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp), parameter :: alphas(6) = [0.5_wp, 2.0_wp, 5.0_wp, 8.0_wp, 9.5_wp, 9.8_wp]
      type(hill_boundary_t), allocatable :: c(:)
      type(error_t), allocatable :: error
      integer :: f, i, n_zero, n_pi2
      do f = 1, size(alphas)
         call hill_boundaries(elastic_model_t(), alphas(f), -1.0_wp, 12.0_wp, 1.0e-12_wp, c, error)
         call check(ctx, .not. allocated(error), "no error")
         if (allocated(error)) return
         n_zero = 0; n_pi2 = 0
         do i = 1, size(c)
            if (c(i)%order == 0) then
               n_zero = n_zero + 1
               call check(ctx, c(i)%beta, 0.0_wp, abs=1.0e-11_wp, message="a_0 = 0")
            else if (c(i)%order == 2) then
               n_pi2 = n_pi2 + 1
               call check(ctx, c(i)%beta, pi2, rel=1.0e-11_wp, message="a_2 = b_2 = pi^2")
               call check(ctx, c(i)%coexistent, "beta = pi^2: coexistence")
            end if
         end do
         call check(ctx, n_zero == 1 .and. n_pi2 == 2, "one a_0 and both curves of order 2")
      end do
   end subroutine exact_boundaries_zero_and_pi2

   !> Every boundary in β ∈ [−2, 40] has S = ±2 by method auto (an independent
   !> integration): |S ∓ 2| within the trace error plus |S'| times the β accuracy,
   !> S' from a centred difference of auto.
   subroutine trace_on_boundaries(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp), parameter :: alphas(5) = [0.7_wp, 3.0_wp, 6.5_wp, 9.0_wp, 9.7_wp]
      type(hill_boundary_t), allocatable :: c(:)
      type(error_t), allocatable :: error
      real(wp) :: s, s_plus, s_minus, h, slope
      integer :: f, i
      do f = 1, size(alphas)
         call hill_boundaries(elastic_model_t(), alphas(f), -2.0_wp, 40.0_wp, 1.0e-12_wp, c, error)
         call check(ctx, .not. allocated(error), "no error")
         if (allocated(error)) return
         call check(ctx, size(c) >= 9, "at least nine curves below beta = 40")
         do i = 1, size(c)
            s = trace(alphas(f), c(i)%beta)
            h = 1.0e-5_wp*max(1.0_wp, abs(c(i)%beta))
            s_plus = trace(alphas(f), c(i)%beta + h)
            s_minus = trace(alphas(f), c(i)%beta - h)
            slope = (s_plus - s_minus)/(2*h)
            call check(ctx, s, real(c(i)%trace_sign, wp), abs=2.0e-11_wp + abs(slope)*1.0e-10_wp*max(1.0_wp, &
                       abs(c(i)%beta)), message="S = +-2 on the boundary")
         end do
      end do
   contains
      real(wp) function trace(alpha, beta)
         real(wp), intent(in) :: alpha, beta
         type(trace_t) :: tr
         type(error_t), allocatable :: err
         call monodromy_trace(elastic_model_t(), hill_point_t(alpha, beta, 0.0_wp), &
                              method_t(method_auto, tolerance=1.0e-12_wp), tr, err)
         trace = tr%value
      end function trace
   end subroutine trace_on_boundaries

   !> β = π²/4 lies strictly inside the first antiperiodic tongue, between b_1 and
   !> a_1, for every 0 < α < π² (parametric resonance), and the tongue edges have S = −2.
   subroutine quarter_pi2_in_first_tongue(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(hill_boundary_t), allocatable :: c(:)
      type(error_t), allocatable :: error
      real(wp) :: alpha, lo, hi
      integer :: f, i
      do f = 1, 12
         alpha = 9.85_wp*f/12
         call hill_boundaries(elastic_model_t(), alpha, -1.0_wp, 12.0_wp, 1.0e-11_wp, c, error)
         call check(ctx, .not. allocated(error), "no error")
         if (allocated(error)) return
         lo = huge(1.0_wp); hi = -huge(1.0_wp)
         do i = 1, size(c)
            if (c(i)%order /= 1) cycle
            call check(ctx, c(i)%trace_sign == -2, "order 1 is antiperiodic")
            lo = min(lo, c(i)%beta); hi = max(hi, c(i)%beta)
         end do
         call check(ctx, lo < 0.25_wp*pi2 .and. 0.25_wp*pi2 < hi, "pi^2/4 inside the first tongue")
      end do
   end subroutine quarter_pi2_in_first_tongue

   !> Open and closed tongues at α = 5, against S by auto inside: the antiperiodic
   !> tongues (orders 1, 3) are open (S < −2 at their middle), the periodic ones
   !> (orders 2, 4) have zero width (S ≤ 2 just beside the double boundary).
   !> Coexistence at every order below 250: Mathieu at q = 0.5 and 1 never (Ince's theorem;
   !> its tongues of orders 6–9 are 1e-9 … 4e-13 wide, within a distance threshold of
   !> 100·tolerance, which took them for closed), its lowest tongues visibly open (S < −2 or
   !> S > 2 by auto at their middle); the elastic model at α = 2, 5, 8: every S = +2 tongue
   !> closed, its two computed edges within 1e-10·max(1, |β|), every S = −2 tongue open.
   subroutine coexistence_by_structure(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(hill_boundary_t), allocatable :: c(:)
      type(error_t), allocatable :: error
      type(trace_t) :: tr
      real(wp), parameter :: qs(2) = [0.5_wp, 1.0_wp], alphas(3) = [2.0_wp, 5.0_wp, 8.0_wp]
      real(wp) :: nu, edges(2)
      integer :: k, i, j, order, m, n_orders
      do k = 1, size(qs)
         nu = qs(k)*pi2/2.0_wp
         call hill_boundaries(mathieu_model_t(), nu, -50.0_wp, 250.0_wp, 1.0e-12_wp, c, error)
         call check(ctx, .not. allocated(error), "mathieu: no error")
         if (allocated(error)) return
         call check(ctx, count(c%order >= 6) >= 6, "mathieu: the thin tongues of orders 6 and up are in the window")
         do i = 1, size(c)
            if (c(i)%order > 0) call check(ctx, .not. c(i)%coexistent, "mathieu q /= 0: no coexistence")
         end do
         do order = 1, 3
            m = 0
            do i = 1, size(c)
               if (c(i)%order /= order) cycle
               m = m + 1
               edges(min(m, 2)) = c(i)%beta
            end do
            call check(ctx, m == 2, "mathieu: two edges per order")
            call monodromy_trace(mathieu_model_t(), hill_point_t(nu, sum(edges)/2, 0.0_wp), &
                                 method_t(method_auto, tolerance=1.0e-12_wp), tr, error)
            call check(ctx, abs(tr%value) > 2.0_wp, "mathieu: open tongue, |S| > 2 at its middle")
         end do
      end do
      do k = 1, size(alphas)
         call hill_boundaries(elastic_model_t(), alphas(k), -2.0_wp, 150.0_wp, 1.0e-12_wp, c, error)
         call check(ctx, .not. allocated(error), "elastic: no error")
         if (allocated(error)) return
         n_orders = 0
         do i = 1, size(c)
            if (c(i)%order == 0) cycle
            call check(ctx, c(i)%coexistent .eqv. c(i)%trace_sign == 2, "elastic: S = +2 tongues closed, S = -2 open")
            if (c(i)%trace_sign /= 2) cycle
            do j = 1, size(c)
               if (j /= i .and. c(j)%order == c(i)%order .and. c(j)%trace_sign == 2) then
                  n_orders = n_orders + 1
                  call check(ctx, abs(c(j)%beta - c(i)%beta) <= 1.0e-10_wp*max(1.0_wp, abs(c(i)%beta)), &
                             "elastic: the two edges of an S = +2 tongue agree")
               end if
            end do
         end do
         call check(ctx, n_orders >= 6, "elastic: several S = +2 tongues seen")
      end do
   end subroutine coexistence_by_structure

   !> The error bound of every curve point of the stored 50-digit references
   !> (data/reference/curve_set.dat, `make_reference.py --curves`: elastic curves at
   !> α = 2 … 9.8 up to β = 40) bounds its actual error, at tolerances 1e-8, 1e-10, 1e-12,
   !> and is not vacuous (below 1e-10 relative at 1e-12).
   subroutine error_bound_against_references(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=*), parameter :: file = "data/reference/curve_set.dat"
      type(hill_boundary_t), allocatable :: c(:)
      type(error_t), allocatable :: error
      real(wp) :: alpha(200), beta(200), ref_error, tolerance, err, worst, largest
      integer :: kind(200), order(200), parity(200), n, unit, ios, i, j, t, found
      character(len=400) :: line
      open (newunit=unit, file=file, status="old", action="read", iostat=ios)
      call check(ctx, ios == 0, "reference table "//file//" read")
      if (ios /= 0) return
      n = 0
      do
         read (unit, '(a)', iostat=ios) line
         if (ios /= 0) exit
         if (line(1:1) == "#" .or. len_trim(line) == 0) cycle
         n = n + 1
         read (line, *) alpha(n), kind(n), order(n), parity(n), beta(n), ref_error
      end do
      close (unit)
      call check(ctx, n >= 40, "at least 40 reference points")
      do t = 1, 3
         tolerance = 10.0_wp**(-6 - 2*t)
         worst = 0.0_wp
         largest = 0.0_wp
         do i = 1, n
            call hill_boundaries(elastic_model_t(), alpha(i), -50.0_wp, 45.0_wp, tolerance, c, error)
            call check(ctx, .not. allocated(error), "no error")
            if (allocated(error)) return
            found = 0
            do j = 1, size(c)
               if (c(j)%trace_sign /= kind(i) .or. c(j)%order /= order(i) .or. c(j)%parity /= parity(i)) cycle
               found = found + 1
               err = abs(c(j)%beta - beta(i))
               worst = max(worst, err/c(j)%error_bound)
               largest = max(largest, c(j)%error_bound/max(1.0_wp, abs(beta(i))))
               if (err > c(j)%error_bound) print "(a,es8.1,f6.2,3i3,4es11.3,i6)", "MISS", tolerance, alpha(i), &
                  kind(i), order(i), parity(i), beta(i), err, c(j)%change, c(j)%error_bound, c(j)%modes
               call check(ctx, err <= c(j)%error_bound, "error bound of the curve point")
            end do
            call check(ctx, found == 1, "the reference curve is found")
         end do
         print '(4x,a,es8.1,a,f6.3,a,es9.2)', "tolerance ", tolerance, ": worst error/bound ", worst, &
            ", largest bound/max(1,|beta|) ", largest
         if (t == 3) call check(ctx, largest < 1.0e-10_wp, "the bound is not vacuous at tolerance 1e-12")
      end do
   end subroutine error_bound_against_references

   subroutine tongues_open_and_closed(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(hill_boundary_t), allocatable :: c(:)
      type(error_t), allocatable :: error
      type(trace_t) :: tr
      real(wp) :: betas(2)
      integer :: order, i, m
      call hill_boundaries(elastic_model_t(), 5.0_wp, -2.0_wp, 40.0_wp, 1.0e-12_wp, c, error)
      call check(ctx, .not. allocated(error), "no error")
      if (allocated(error)) return
      do order = 1, 4
         m = 0
         do i = 1, size(c)
            if (c(i)%order /= order) cycle
            m = m + 1
            betas(m) = c(i)%beta
            call check(ctx, c(i)%coexistent .eqv. mod(order, 2) == 0, "coexistence flag")
         end do
         call check(ctx, m == 2, "two curves per order")
         if (mod(order, 2) == 1) then
            call monodromy_trace(elastic_model_t(), hill_point_t(5.0_wp, sum(betas)/2, 0.0_wp), &
                                 method_t(method_auto, tolerance=1.0e-12_wp), tr, error)
            call check(ctx, tr%value < -2.0_wp, "open antiperiodic tongue: S < -2 inside")
         else
            do i = -1, 1, 2
               call monodromy_trace(elastic_model_t(), hill_point_t(5.0_wp, betas(1) + i*1.0e-4_wp, 0.0_wp), &
                                    method_t(method_auto, tolerance=1.0e-12_wp), tr, error)
               call check(ctx, tr%value <= 2.0_wp .and. tr%value > 1.99_wp, "closed periodic tongue: S <= 2 beside")
            end do
         end if
      end do
   end subroutine tongues_open_and_closed

   !> Ritz values only decrease as modes are added, and converge geometrically:
   !> at α = 9.5 the first five eigenvalues of each block with n modes, against n = 400.
   subroutine ritz_convergence(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp), allocatable :: ref(:), v(:), previous(:)
      type(error_t), allocatable :: error
      real(wp) :: err_now, err_before
      integer :: block, n, j
      do block = block_periodic_even, block_antiperiodic_odd
         call hill_block_eigenvalues(elastic_model_t(), 9.5_wp, block, 400, ref, error)
         call check(ctx, .not. allocated(error), "no error")
         if (allocated(error)) return
         err_before = huge(1.0_wp)
         if (allocated(previous)) deallocate (previous)
         do n = 20, 140, 40
            call hill_block_eigenvalues(elastic_model_t(), 9.5_wp, block, n, v, error)
            err_now = maxval(abs(v(:5) - ref(:5)))
            do j = 1, 5
               call check(ctx, v(j) >= ref(j) - 1.0e-11_wp*max(1.0_wp, abs(ref(j))), "upper bound (Ritz)")
            end do
            if (allocated(previous)) then
               do j = 1, 5
                  call check(ctx, v(j) <= previous(j) + 1.0e-11_wp*max(1.0_wp, abs(v(j))), "monotone in n")
               end do
            end if
            ! geometric: r = 0.73 at alpha = 9.5, r^(2*40) = 1e-11; stop at round-off
            if (err_before < 1.0e-6_wp) then
               call check(ctx, err_now < max(1.0e-3_wp*err_before, 1.0e-11_wp), "geometric convergence")
            end if
            err_before = err_now
            previous = v
         end do
         call check(ctx, err_now < 1.0e-11_wp, "converged with 140 modes")
      end do
   end subroutine ritz_convergence

   !> The inverted pencil, the direct pencil and the nonsymmetric tridiagonal give
   !> the same eigenvalues at moderate α and size (where all three are accurate).
   subroutine formulations_agree(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp), allocatable :: a(:), b(:), c(:)
      type(error_t), allocatable :: error
      class(hill_model_t), pointer :: model
      integer :: block, code
      do code = 1, 2   ! the elastic and the Mathieu model
         model => model_of_code(code)
         do block = block_periodic_even, block_antiperiodic_odd
            call hill_block_eigenvalues(model, 6.0_wp, block, 60, a, error, formulation_inverted_pencil)
            call hill_block_eigenvalues(model, 6.0_wp, block, 60, b, error, formulation_pencil)
            call hill_block_eigenvalues(model, 6.0_wp, block, 60, c, error, formulation_nonsymmetric)
            call check(ctx, .not. allocated(error), "no error")
            call check(ctx, maxval(abs(a(:8) - b(:8))) < 1.0e-9_wp, "pencil and inverted pencil")
            call check(ctx, maxval(abs(a(:8) - c(:8))) < 1.0e-9_wp, "nonsymmetric and inverted pencil")
         end do
      end do
   end subroutine formulations_agree

   !> Bad input comes back as err_invalid_parameter, never a stop or a NaN.
   subroutine bad_input(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(hill_boundary_t), allocatable :: c(:)
      type(error_t), allocatable :: error
      real(wp), allocatable :: v(:)
      real(wp) :: nan
      nan = ieee_value(1.0_wp, ieee_quiet_nan)
      call hill_boundaries(elastic_model_t(), pi2, 0.0_wp, 10.0_wp, 1.0e-10_wp, c, error)
      call check(ctx, allocated(error), "alpha = pi^2 refused")
      if (allocated(error)) call check(ctx, error%code == err_invalid_parameter, "code")
      call hill_boundaries(elastic_model_t(), -0.1_wp, 0.0_wp, 10.0_wp, 1.0e-10_wp, c, error)
      call check(ctx, allocated(error), "alpha < 0 refused")
      call hill_boundaries(mathieu_model_t(), nan, 0.0_wp, 10.0_wp, 1.0e-10_wp, c, error)
      call check(ctx, allocated(error), "NaN refused")
      call hill_boundaries(elastic_model_t(), 1.0_wp, 10.0_wp, 0.0_wp, 1.0e-10_wp, c, error)
      call check(ctx, allocated(error), "beta_min > beta_max refused")
      call hill_boundaries(elastic_model_t(), 1.0_wp, 0.0_wp, 10.0_wp, 0.0_wp, c, error)
      call check(ctx, allocated(error), "tolerance 0 refused")
      call hill_block_eigenvalues(elastic_model_t(), 1.0_wp, 7, 10, v, error)
      call check(ctx, allocated(error), "unknown block refused")
   end subroutine bad_input
end module test_hill_method

!> Tests of hillstab_curves_boundaries: the check by auto accepts true boundaries and rejects
!> a boundary moved by 1e-6; approximate curves of N-piece midpoint segmentation
!> converge to Hill's at second order; the unstable intervals of eq. (37) at α = 0
!> are empty (S = 2 cos 2√β); interval arithmetic against hand-made sets; the GSL
!> witness agrees with Hill's method and refuses high orders and large q.
module test_boundaries
   use hillstab_core_kinds, only: wp, pi2
   use hillstab_core_error, only: error_t
   use hillstab_hill_coefficient, only: sampling_midpoint
   use hillstab_integrate_monodromy, only: method_t, method_formula, method_segments
   use hillstab_curves_hill_method, only: hill_boundary_t, hill_boundaries
   use hillstab_curves_boundaries
   use hillstab_testing
   use hillstab_hill_model_elastic, only: elastic_model_t
   use hillstab_hill_model_mathieu, only: mathieu_model_t
   implicit none
   private
   public :: collect_boundaries

contains

   function collect_boundaries() result(suite)
      type(testsuite_t) :: suite
      suite = new_testsuite("boundaries", [ &
         new_unittest("check_accepts_and_rejects", check_accepts_and_rejects), &
         new_unittest("segments_converge_second_order", segments_converge_second_order), &
         new_unittest("formula_alpha_zero", formula_alpha_zero), &
         new_unittest("interval_lengths", interval_lengths), &
         new_unittest("gsl_witness_and_guards", gsl_witness_and_guards)])
   end function collect_boundaries

   subroutine check_accepts_and_rejects(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(hill_boundary_t), allocatable :: c(:)
      type(error_t), allocatable :: error
      type(boundary_check_t) :: chk
      integer :: i
      call hill_boundaries(elastic_model_t(), 5.0_wp, -2.0_wp, 40.0_wp, 1.0e-11_wp, c, error)
      call check(ctx, .not. allocated(error), "Hill's method runs")
      if (allocated(error)) return
      ! 9 boundaries, 4 of them coexistent
      call check(ctx, size(c) >= 6 .and. count(.not. c%coexistent) >= 3, "boundaries to check")
      do i = 1, size(c)
         call verify_boundary(elastic_model_t(), 5.0_wp, c(i)%beta, c(i)%trace_sign, 1.0e-11_wp, chk, error)
         call check(ctx, .not. allocated(error) .and. chk%passed, "true boundary passes")
         if (c(i)%coexistent) cycle   ! S touches 2 there: a shifted point is still |S| ~ 2
         call verify_boundary(elastic_model_t(), 5.0_wp, c(i)%beta + 1.0e-6_wp, c(i)%trace_sign, 1.0e-11_wp, chk, error)
         call check(ctx, .not. chk%passed, "boundary moved by 1e-6 fails")
         call check(ctx, chk%beta_error, 1.0e-6_wp, rel=2.0e-2_wp, message="implied beta error (to first order)")
         call verify_boundary(elastic_model_t(), 5.0_wp, c(i)%beta, -c(i)%trace_sign, 1.0e-11_wp, chk, error)
         call check(ctx, .not. chk%passed, "wrong kind fails")
      end do
   end subroutine check_accepts_and_rejects

   !> First-tongue edges of midpoint segmentation: error against Hill's method falls
   !> by ~4 per doubling of N (second order), and is small at N = 256.
   subroutine segments_converge_second_order(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(hill_boundary_t), allocatable :: c(:)
      type(approximate_root_t), allocatable :: r(:)
      type(error_t), allocatable :: error
      real(wp) :: exact(2), err(3), ratio
      integer :: i, k, n
      call hill_boundaries(elastic_model_t(), 3.0_wp, 0.0_wp, 9.0_wp, 1.0e-12_wp, c, error)
      exact = 0.0_wp
      do i = 1, size(c)
         if (c(i)%order == 1) exact(merge(1, 2, c(i)%parity == -1)) = c(i)%beta
      end do
      do k = 1, 3
         n = 64*2**(k - 1)
         call approximate_boundaries(elastic_model_t(), 3.0_wp, method_t(method_segments, n, sampling_midpoint, 1.0e-13_wp), &
                                     0.5_wp, 9.0_wp, 200, 1.0e-13_wp, r, error)
         call check(ctx, .not. allocated(error), "roots found")
         err(k) = 0.0_wp
         do i = 1, size(r)
            if (r(i)%order == 1) err(k) = max(err(k), abs(r(i)%beta - exact(r(i)%edge)))
            call check(ctx, abs(r(i)%residual) < 1.0e-9_wp, "Brent residual")
         end do
      end do
      do k = 2, 3
         ratio = err(k - 1)/err(k)
         call check(ctx, ratio > 3.5_wp .and. ratio < 4.5_wp, "second order")
      end do
      call check(ctx, err(3) < 1.0e-3_wp, "N = 256 close")
   end subroutine segments_converge_second_order

   !> α = 0: eq. (37) is S = 2 cos 2√β, which only touches ±2 for β > 0: the unstable
   !> set inside (0, π²) is empty and the only crossing is β = 0.
   subroutine formula_alpha_zero(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(approximate_root_t), allocatable :: r(:)
      type(error_t), allocatable :: error
      real(wp), allocatable :: intervals(:, :)
      call approximate_boundaries(elastic_model_t(), 0.0_wp, method_t(method_formula), -2.0_wp, 12.0_wp, 500, &
                                  1.0e-12_wp, r, error)
      call check(ctx, .not. allocated(error) .and. size(r) == 1, "one crossing")
      if (size(r) == 1) call check(ctx, r(1)%beta, 0.0_wp, abs=1.0e-12_wp, message="beta = 0")
      call unstable_intervals_from_roots(elastic_model_t(), 0.0_wp, method_t(method_formula), 0.1_wp, pi2, &
                                         [real(wp) ::], intervals, error)
      call check(ctx, size(intervals, 2) == 0, "no unstable interval")
   end subroutine formula_alpha_zero

   subroutine interval_lengths(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp) :: a(2, 2), b(2, 1), empty(2, 0)
      a = reshape([0.0_wp, 1.0_wp, 2.0_wp, 4.0_wp], [2, 2])
      b = reshape([0.5_wp, 3.0_wp], [2, 1])
      call check(ctx, interval_length(a), 3.0_wp, abs=1.0e-15_wp, message="length")
      ! a Δ b = [0, 0.5) ∪ (1, 2) ∪ (3, 4]: 0.5 + 1 + 1
      call check(ctx, symmetric_difference_length(a, b), 2.5_wp, abs=1.0e-15_wp, message="symmetric difference")
      call check(ctx, symmetric_difference_length(a, empty), 3.0_wp, abs=1.0e-15_wp, message="against empty")
      call check(ctx, symmetric_difference_length(a, a), 0.0_wp, abs=1.0e-15_wp, message="against itself")
   end subroutine interval_lengths

   subroutine gsl_witness_and_guards(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(hill_boundary_t), allocatable :: c(:)
      type(error_t), allocatable :: error
      real(wp) :: beta
      logical :: available
      integer :: i
      call hill_boundaries(mathieu_model_t(), 30.0_wp, -30.0_wp, 120.0_wp, 1.0e-12_wp, c, error)
      ! 13 boundaries
      call check(ctx, .not. allocated(error) .and. size(c) >= 10, "Hill's method runs")
      do i = 1, size(c)
         call mathieu_witness(c(i)%order, c(i)%parity, 30.0_wp, beta, available)
         call check(ctx, available, "GSL available at low order and q = 6")
         call check(ctx, beta, c(i)%beta, rel=1.0e-11_wp, abs=1.0e-10_wp, message="GSL = Hill")
      end do
      call mathieu_witness(61, 1, 1.0_wp, beta, available)
      call check(ctx, .not. available, "order 61 refused")
      call mathieu_witness(2, -1, 0.5_wp*pi2*1500.0_wp, beta, available)
      call check(ctx, .not. available, "q = 1500 refused")
      call mathieu_witness(0, -1, 1.0_wp, beta, available)
      call check(ctx, .not. available, "b_0 does not exist")
   end subroutine gsl_witness_and_guards
end module test_boundaries

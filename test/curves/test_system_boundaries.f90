!> Tests of the transition curves of systems (hillstab_curves_system_boundaries): Hill's
!> method with blocks against the Mathieu characteristic values for one equation and for a
!> decoupled pair, each point confirmed by the monodromy; the combination tongue's edges
!> found by root-finding on Broucke's discriminant against first-order perturbation theory.
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
   use hillstab_integrate_system, only: system_method_t, system_auto
   use hillstab_curves_system_boundaries
   use hillstab_testing
   implicit none
   private
   public :: collect_system_boundaries

contains

   function collect_system_boundaries() result(suite)
      type(testsuite_t) :: suite
      suite = new_testsuite("system_boundaries", [ &
         new_unittest("hill_blocks_are_mathieu", hill_blocks_are_mathieu), &
         new_unittest("decoupled_pair_curves", decoupled_pair_curves), &
         new_unittest("combination_edges_first_order", combination_edges_first_order)])
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
            if (found(j)%kind == kind_combination) cycle
            if (abs(found(j)%beta - expected(k)) <= tol*max(1.0_wp, abs(expected(k))) .and. &
                found(j)%kind == merge(kind_plus_one, kind_minus_one, signs(k) > 0)) hits = hits + 1
         end do
         call check(ctx, hits >= 1, what//": a characteristic value found")
      end do
      do j = 1, size(found)
         if (found(j)%kind == kind_combination) cycle
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
end module test_system_boundaries

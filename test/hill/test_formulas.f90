!> Tests of the paper's closed forms: the α = 0 limit, the literal eq. (37),
!> agreement with the 2-piece matrix product (eq. (28)) on a grid with negative
!> radicands, the damped eqs. (48)–(50) and the Mathieu eq. (A3).
module test_formulas
   use hillstab_core_kinds, only: wp, pi, pi2
   use hillstab_hill_coefficient
   use hillstab_hill_transfer, only: trace_t
   use hillstab_hill_formulas
   use hillstab_integrate_monodromy, only: trace_segmented
   use hillstab_testing
   use hillstab_test_reference, only: value_of
   use hillstab_hill_model, only: hill_point_t
   use hillstab_hill_model_elastic, only: elastic_model_t
   use hillstab_hill_model_mathieu, only: mathieu_model_t
   use hillstab_hill_model_fourier, only: fourier_model_t
   use hillstab_core_error, only: error_t
   implicit none
   private
   public :: collect_formulas

contains

   function collect_formulas() result(suite)
      type(testsuite_t) :: suite
      suite = new_testsuite("formulas", [ &
         new_unittest("alpha_zero_closed_form", alpha_zero_closed_form), &
         new_unittest("eq37_literal", eq37_literal), &
         new_unittest("eq37_equals_two_pieces", eq37_equals_two_pieces), &
         new_unittest("damped_eq48_equals_two_pieces", damped_eq48_equals_two_pieces), &
         new_unittest("mathieu_a3", mathieu_a3), &
         new_unittest("zero_radicands_finite", zero_radicands_finite), &
         new_unittest("two_pieces_over_period_four", two_pieces_over_period_four)])
   end function collect_formulas

   !> α = 0: Q ≡ β, S = 2 cos(2√β) (2 cosh(2√−β) for β < 0), β from −400 to 1e4.
   subroutine alpha_zero_closed_form(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp) :: beta, exact
      type(trace_t) :: tr
      integer :: i, n
      do i = 0, 200
         beta = -400.0_wp + (1.0e4_wp + 400.0_wp)*(real(i, wp)/200)**3
         if (beta >= 0.0_wp) then
            exact = 2.0_wp*cos(2.0_wp*sqrt(beta))
         else
            exact = 2.0_wp*cosh(2.0_wp*sqrt(-beta))
         end if
         tr = trace_two_segment_paper(0.0_wp, beta)
         call check(ctx, tr%value, exact, rel=1.0e-12_wp, abs=2.0e-12_wp*max(1.0_wp, sqrt(abs(beta))))
         do n = 1, 7, 3
            tr = trace_segmented(elastic_model_t(), hill_point_t(0.0_wp, beta, 0.0_wp), n, sampling_midpoint)
            call check(ctx, tr%value, exact, rel=1.0e-12_wp, abs=1.0e-11_wp*max(1.0_wp, sqrt(abs(beta))))
         end do
      end do
   end subroutine alpha_zero_closed_form

   !> Where every radicand is positive, eq. (37) evaluated literally.
   subroutine eq37_literal(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp) :: alpha, beta, b1, b2, literal
      integer :: i, j
      do i = 1, 9
         do j = 1, 10
            alpha = 0.95_wp*i
            beta = alpha + 0.7_wp*j
            b1 = sqrt((beta + alpha)/(1.0_wp + alpha/pi2))
            b2 = sqrt((beta - alpha)/(1.0_wp - alpha/pi2))
            literal = 2.0_wp*cos(b1)*cos(b2) - 2.0_wp*(beta - alpha**2/pi2) &
                      /sqrt((beta**2 - alpha**2)*(1.0_wp - (alpha/pi2)**2))*sin(b1)*sin(b2)
            call check(ctx, value_of(trace_two_segment_paper(alpha, beta)), literal, rel=1.0e-12_wp, abs=1.0e-12_wp)
         end do
      end do
   end subroutine eq37_literal

   !> Eq. (37) equals the product of the two exact transfer matrices of eq. (28),
   !> on a grid with β < α, β < 0, β + α < 0 and α up to 9.86.
   subroutine eq37_equals_two_pieces(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp) :: alphas(9) = [0.0_wp, 0.2_wp, 1.48_wp, 3.7_wp, 5.0_wp, 7.88_wp, 9.0_wp, 9.8_wp, 9.86_wp]
      real(wp) :: betas(10) = [-400.0_wp, -20.0_wp, -5.0_wp, -0.5_wp, 0.76_wp, 2.47_wp, 3.95_wp, 6.0_wp, &
                               12.0_wp, 100.0_wp]
      type(trace_t) :: formula, product
      integer :: i, j
      do i = 1, size(alphas)
         do j = 1, size(betas)
            formula = trace_two_segment_paper(alphas(i), betas(j))
            product = trace_segmented(elastic_model_t(), hill_point_t(alphas(i), betas(j), 0.0_wp), 2, sampling_endpoint)
            call check(ctx, formula%log_abs, product%log_abs, rel=1.0e-12_wp, abs=1.0e-12_wp)
            if (.not. formula%overflow) call check(ctx, formula%value, product%value, rel=1.0e-12_wp, abs=1.0e-12_wp)
         end do
      end do
   end subroutine eq37_equals_two_pieces

   subroutine damped_eq48_equals_two_pieces(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp) :: eps(3) = [0.1_wp, 1.0_wp, 4.0_wp]
      type(trace_t) :: formula, product
      integer :: i, j, k
      do k = 1, size(eps)
         do i = 0, 4
            do j = -2, 6
               formula = trace_damped_paper(2.4_wp*i, 2.0_wp*j, eps(k))
               product = trace_segmented(elastic_model_t(), hill_point_t(2.4_wp*i, 2.0_wp*j, eps(k)), 2, sampling_endpoint)
               call check(ctx, formula%value, product%value, rel=1.0e-12_wp, abs=1.0e-12_wp)
            end do
         end do
      end do
      ! ε = 0 recovers eq. (37)
      call check(ctx, value_of(trace_damped_paper(3.7_wp, 2.47_wp, 0.0_wp)), value_of(trace_two_segment_paper(3.7_wp, 2.47_wp)), &
         rel=1.0e-15_wp)
   end subroutine damped_eq48_equals_two_pieces

   !> Eq. (A3) literally (β > ν > 0) and against the Mathieu two-piece product.
   subroutine mathieu_a3(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp) :: nu, beta, literal
      integer :: i, j
      do i = 1, 5
         do j = 1, 5
            nu = 0.5_wp*i
            beta = nu + 1.3_wp*j
            literal = 2.0_wp*cos(sqrt(beta + nu))*cos(sqrt(beta - nu)) &
                      - 2.0_wp*beta*sin(sqrt(beta + nu))*sin(sqrt(beta - nu))/sqrt(beta**2 - nu**2)
            call check(ctx, value_of(trace_mathieu_two_segment(nu, beta)), literal, rel=1.0e-12_wp, abs=1.0e-12_wp)
            call check(ctx, value_of(trace_mathieu_two_segment(nu, -beta)), &
               value_of(trace_segmented(mathieu_model_t(), hill_point_t(nu, -beta, 0.0_wp), 2, sampling_endpoint)), &
               rel=1.0e-12_wp)
         end do
      end do
   end subroutine mathieu_a3

   !> β = α (Q(0) = 0) and β = −α (Q(1) = 0): the paper's form is 0/0; the limit is finite
   !> and continuous.
   subroutine zero_radicands_finite(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp) :: s0, s_near
      s0 = value_of(trace_two_segment_paper(5.0_wp, 5.0_wp))
      s_near = value_of(trace_two_segment_paper(5.0_wp, 5.0_wp + 1.0e-9_wp))
      call check(ctx, s0, s_near, rel=1.0e-7_wp)
      ! Q(0) = 0 on [0,1): T = [[1,1],[0,1]]; Q(1) = 10/(1 + 5/π²) on [1,2)
      call check(ctx, s0, 2.0_wp*cos(sqrt(10.0_wp/(1.0_wp + 5.0_wp/pi2))) - sqrt(10.0_wp/(1.0_wp + 5.0_wp/pi2)) &
         *sin(sqrt(10.0_wp/(1.0_wp + 5.0_wp/pi2))), rel=1.0e-13_wp)
      s0 = value_of(trace_two_segment_paper(5.0_wp, -5.0_wp))
      s_near = value_of(trace_two_segment_paper(5.0_wp, -5.0_wp - 1.0e-9_wp))
      call check(ctx, s0, s_near, rel=1.0e-7_wp)
   end subroutine zero_radicands_finite
   !> Method formula over a period 4: the fourier model f = cos πτ given over P = 4 has
   !> Q(0) = Q(2) = β + α, so both pieces (each 2 long) are that constant and
   !> S = 2 cos(4√(β + α)) (2 cosh(4√−(β + α)) below 0); with damping β − ε²/4 in their place.
   subroutine two_pieces_over_period_four(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(fourier_model_t) :: model
      type(error_t), allocatable :: error
      type(trace_t) :: tr
      real(wp) :: q, exact, alpha, beta, eps
      integer :: i
      call model%set_values("cos", [0.0_wp, 1.0_wp], error)
      call model%set_values("period", [4.0_wp], error)
      call check(ctx, .not. allocated(error), "the model's data")
      if (allocated(error)) return
      do i = 0, 40
         alpha = 0.1_wp*i
         beta = -3.0_wp + 0.5_wp*i
         eps = 0.05_wp*mod(i, 3)
         q = beta + alpha - 0.25_wp*eps**2
         if (q >= 0.0_wp) then
            exact = 2.0_wp*cos(4.0_wp*sqrt(q))
         else
            exact = 2.0_wp*cosh(4.0_wp*sqrt(-q))
         end if
         tr = trace_formula(model, hill_point_t(alpha, beta, eps))
         call check_close(ctx, value_of(tr), exact, rel=1.0e-12_wp, abs=1.0e-12_wp, &
                          message="S at alpha = "//trim(adjustl(ftext(alpha)))//", beta = "//trim(adjustl(ftext(beta))))
      end do
   contains
      function ftext(x) result(t)
         real(wp), intent(in) :: x
         character(len=24) :: t
         write (t, '(g0.6)') x
      end function ftext
   end subroutine two_pieces_over_period_four
end module test_formulas

!> Tests of the exact constant-coefficient transfer matrices and scaled products.
module test_transfer
   use hillstab_core_kinds, only: wp
   use hillstab_hill_transfer
   use hillstab_testing
   use hillstab_test_reference, only: value_of
   implicit none
   private
   public :: collect_transfer

contains

   function collect_transfer() result(suite)
      type(testsuite_t) :: suite
      suite = new_testsuite("transfer", [ &
         new_unittest("closed_forms", closed_forms), &
         new_unittest("unit_determinant", unit_determinant), &
         new_unittest("small_q_series", small_q_series), &
         new_unittest("step_series", step_series), &
         new_unittest("meissner", meissner), &
         new_unittest("overflow_is_scaled", overflow_is_scaled), &
         new_unittest("composition", composition)])
   end function collect_transfer

   !> The short Taylor polynomials of Magnus steps (`cos_sinc_taylor`, `step_functions`)
   !> against the intrinsics: degree 10 to rounding for |z| ≤ 0.5, degree 5 for |z| ≤ 0.02,
   !> and step_functions equal to transfer_functions beyond |z| = 0.1 (log scale included).
   subroutine step_series(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp) :: z, c, s, l, c_ref, s_ref, l_ref
      integer :: i
      do i = -50, 50
         z = 0.01_wp*i
         call reference(z, c_ref, s_ref)
         call cos_sinc_taylor(z, 10, c, s)
         call check(ctx, c, c_ref, rel=4.0e-16_wp, message="degree 10, cos")
         call check(ctx, s, s_ref, rel=4.0e-16_wp, message="degree 10, sinc")
         if (abs(z) <= 0.02_wp) then
            call cos_sinc_taylor(z, 5, c, s)
            call check(ctx, c, c_ref, rel=4.0e-16_wp, message="degree 5, cos")
            call check(ctx, s, s_ref, rel=4.0e-16_wp, message="degree 5, sinc")
         end if
         call step_functions(z, c, s, l)
         call check(ctx, c, c_ref, rel=1.0e-15_wp, message="step_functions, cos")
         call check(ctx, s, s_ref, rel=1.0e-15_wp, message="step_functions, sinc")
         call check(ctx, l == 0.0_wp, "no scale for small z")
      end do
      do i = 1, 6
         z = -(10.0_wp**i)
         call step_functions(z, c, s, l)
         call transfer_functions(z, c_ref, s_ref, l_ref)
         call check(ctx, c == c_ref .and. s == s_ref .and. l == l_ref, "step_functions = transfer_functions")
      end do
   contains
      subroutine reference(z, c, s)
         real(wp), intent(in) :: z
         real(wp), intent(out) :: c, s
         if (z > 0.0_wp) then
            c = cos(sqrt(z)); s = sin(sqrt(z))/sqrt(z)
         else if (z < 0.0_wp) then
            c = cosh(sqrt(-z)); s = sinh(sqrt(-z))/sqrt(-z)
         else
            c = 1.0_wp; s = 1.0_wp
         end if
      end subroutine reference
   end subroutine step_series

   subroutine closed_forms(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp) :: t(2, 2), w
      t = transfer_matrix(3.0_wp, 0.7_wp)
      w = sqrt(3.0_wp)
      call check(ctx, t(1, 1), cos(w*0.7_wp), rel=1.0e-15_wp)
      call check(ctx, t(1, 2), sin(w*0.7_wp)/w, rel=1.0e-15_wp)
      call check(ctx, t(2, 1), -w*sin(w*0.7_wp), rel=1.0e-15_wp)
      t = transfer_matrix(-5.0_wp, 1.3_wp)
      w = sqrt(5.0_wp)
      call check(ctx, t(1, 1), cosh(w*1.3_wp), rel=1.0e-15_wp)
      call check(ctx, t(1, 2), sinh(w*1.3_wp)/w, rel=1.0e-15_wp)
      call check(ctx, t(2, 1), w*sinh(w*1.3_wp), rel=1.0e-15_wp)
      t = transfer_matrix(0.0_wp, 0.4_wp)
      call check(ctx, t(1, 1), 1.0_wp, rel=0.0_wp)
      call check(ctx, t(1, 2), 0.4_wp, rel=0.0_wp)
      call check(ctx, t(2, 1), 0.0_wp, abs=0.0_wp)
   end subroutine closed_forms

   subroutine unit_determinant(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp) :: q
      integer :: i
      ! det = C² + q h² S² = 1; for q < 0 it is a difference of two numbers of size
      ! cosh²(√|q| h), so the attainable accuracy degrades like e^{2√|q| h} ε_mach.
      do i = -20, 30
         q = sign(10.0_wp**(abs(i)/6.0_wp), real(i, wp))
         call check(ctx, determinant(transfer_matrix(q, 0.1_wp)), 1.0_wp, &
            rel=1.0e-14_wp*max(1.0_wp, abs(q)*1.0e-2_wp, cosh(sqrt(max(-q, 0.0_wp))*0.1_wp)**2))
      end do
   end subroutine unit_determinant

   !> Across the switch between series and trig/hyperbolic evaluation the
   !> functions must agree (|z| = 0.5), and tiny z must not lose accuracy.
   subroutine small_q_series(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp) :: c, s, l, z
      integer :: i
      do i = -1, 1, 2
         z = i*(0.5_wp - 1.0e-12_wp)
         call transfer_functions(z, c, s, l)
         if (i > 0) then
            call check(ctx, c, cos(sqrt(z)), rel=1.0e-15_wp)
            call check(ctx, s, sin(sqrt(z))/sqrt(z), rel=1.0e-15_wp)
         else
            call check(ctx, c, cosh(sqrt(-z)), rel=1.0e-15_wp)
            call check(ctx, s, sinh(sqrt(-z))/sqrt(-z), rel=1.0e-15_wp)
         end if
      end do
      z = 1.0e-300_wp
      call transfer_functions(z, c, s, l)
      call check(ctx, c, 1.0_wp, rel=1.0e-16_wp)
      call check(ctx, s, 1.0_wp, rel=1.0e-16_wp)
      z = -3.0e-9_wp
      call transfer_functions(z, c, s, l)
      call check(ctx, c, 1.0_wp + 1.5e-9_wp, rel=3.0e-16_wp)
      call check(ctx, s, 1.0_wp + 0.5e-9_wp, rel=3.0e-16_wp)
   end subroutine small_q_series

   !> y'' + r s(t) y = 0 with s = +1 then −1 on unit halves: trace 2 cos √r cosh √r.
   subroutine meissner(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp) :: rs(6) = [1.0e-6_wp, 0.1_wp, 1.0_wp, 5.0_wp, 20.0_wp, 100.0_wp]
      type(scaled_matrix_t) :: a
      integer :: i
      do i = 1, size(rs)
         a = scaled_identity()
         call multiply_transfer(a, rs(i), 1.0_wp)
         call multiply_transfer(a, -rs(i), 1.0_wp)
         call check(ctx, value_of(trace_of(a)), 2.0_wp*cos(sqrt(rs(i)))*cosh(sqrt(rs(i))), rel=1.0e-13_wp, abs=1.0e-14_wp)
      end do
   end subroutine meissner

   subroutine overflow_is_scaled(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(scaled_matrix_t) :: a
      type(trace_t) :: tr
      a = scaled_identity()
      call multiply_transfer(a, -1.0e6_wp, 1.0_wp)   ! trace 2 cosh(1000)
      tr = trace_of(a)
      call check(ctx, tr%overflow, "trace flagged as overflow")
      call check(ctx, tr%log_abs, 1000.0_wp, rel=1.0e-14_wp)
      call check(ctx, abs(tr%value) == huge(1.0_wp), "value clamped to huge")
      a = scaled_identity()
      call multiply_transfer(a, -2500.0_wp, 1.0_wp)  ! 2 cosh(50), representable
      tr = trace_of(a)
      call check(ctx, .not. tr%overflow, "2 cosh 50 not flagged")
      call check(ctx, tr%value, 2.0_wp*cosh(50.0_wp), rel=1.0e-13_wp)
   end subroutine overflow_is_scaled

   !> Two pieces of the same q compose to one piece of the summed length.
   subroutine composition(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(scaled_matrix_t) :: a
      real(wp) :: m(2, 2), t(2, 2)
      integer :: i, j
      real(wp) :: qs(4) = [-30.0_wp, -0.01_wp, 0.2_wp, 40.0_wp]
      do i = 1, size(qs)
         a = scaled_identity()
         call multiply_transfer(a, qs(i), 0.3_wp)
         call multiply_transfer(a, qs(i), 0.5_wp)
         m = matrix_of(a)
         t = transfer_matrix(qs(i), 0.8_wp)
         do j = 1, 4
            call check(ctx, m(mod(j - 1, 2) + 1, (j - 1)/2 + 1), t(mod(j - 1, 2) + 1, (j - 1)/2 + 1), &
               rel=1.0e-13_wp, abs=1.0e-13_wp*maxval(abs(t)))
         end do
      end do
   end subroutine composition
end module test_transfer

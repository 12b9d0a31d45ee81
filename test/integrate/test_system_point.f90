!> Tests of the points of systems: every exponent, however many decades the multipliers span
!> (the product QR against closed forms and a published value), the round-off level
!> (status 1 where the tolerance lies below it, the estimate bounding the error at status 0
!> against the extended-precision Taylor reference), and the scaled structural defect.
module test_system_point
   use hillstab_core_kinds, only: wp
   use hillstab_core_error, only: error_t
   use hillstab_core_text, only: integer_text
   use hillstab_core_status, only: status_ok, status_roundoff
   use hillstab_hill_system, only: system_form_t, prepare_system
   use hillstab_hill_system_matrix, only: matrix_system_t
   use hillstab_hill_system_floquet, only: floquet_t, verdict_marginal, kind_undecided
   use hillstab_hill_system_exponents, only: factored_exponents, householder_qr
   use hillstab_integrate_system, only: system_method_t, system_monodromy_t, system_nodes_t, system_auto, &
      system_magnus4, system_magnus6, system_rk, system_gsl, system_factors
   use hillstab_integrate_system_point, only: system_point
   use hillstab_test_system_reference, only: reference_monodromy
   use hillstab_testing
   implicit none
   private
   public :: collect_system_point

contains

   function collect_system_point() result(suite)
      type(testsuite_t) :: suite
      suite = new_testsuite("system_point", [ &
         new_unittest("product_qr_closed_form", product_qr_closed_form), &
         new_unittest("exponents_spanning_decades", exponents_spanning_decades), &
         new_unittest("mettler_second_exponent", mettler_second_exponent), &
         new_unittest("damped_exponents_liouville", damped_exponents_liouville), &
         new_unittest("negative_damping_a2", negative_damping_a2), &
         new_unittest("roundoff_status_and_bound", roundoff_status_and_bound), &
         new_unittest("defect_relative", defect_relative), &
         new_unittest("marginal_is_undecided", marginal_is_undecided)])
   end function collect_system_point

   !> Factors F_k = S D_k S⁻¹ with one S: Φ = S (∏ D_k) S⁻¹, its multipliers ∏ D_k, from
   !> e^{+230} to e^{−230} over 60 factors (one double holds 1e-200 of the largest at best).
   subroutine product_qr_closed_form(ctx)
      type(test_context_t), intent(inout) :: ctx
      integer, parameter :: m = 4, k = 60
      real(wp) :: s(m, m), s_inverse(m, m), factors(m, m, k), d(m), expected(m), mu(m), q(m, m), r(m, m)
      logical :: resolved(m)
      integer :: j, i
      s = reshape([2.0_wp, 0.3_wp, -0.5_wp, 0.1_wp, 0.4_wp, 1.5_wp, 0.2_wp, -0.3_wp, 0.0_wp, 0.6_wp, 1.2_wp, 0.5_wp, &
                   0.3_wp, 0.0_wp, -0.4_wp, 1.7_wp], [m, m])
      call invert(s, s_inverse)
      expected = [230.0_wp, 40.0_wp, -3.0_wp, -230.0_wp]/k
      do j = 1, k
         ! diagonal entries whose logs sum to `expected`·k, varying from factor to factor
         d = exp(expected + 0.3_wp*sin(1.7_wp*j + [0.0_wp, 1.0_wp, 2.0_wp, 3.0_wp]) - &
                 0.3_wp*sin(1.7_wp*(j - 1) + [0.0_wp, 1.0_wp, 2.0_wp, 3.0_wp]))
         do i = 1, m
            factors(:, i, j) = s(:, i)*d(i)
         end do
         factors(:, :, j) = matmul(factors(:, :, j), s_inverse)
      end do
      ! the telescoping terms add up to 0.3 (sin(1.7 k + c) − sin(c))
      expected = expected*k + 0.3_wp*(sin(1.7_wp*k + [0.0_wp, 1.0_wp, 2.0_wp, 3.0_wp]) - &
                                       sin([0.0_wp, 1.0_wp, 2.0_wp, 3.0_wp]))
      call factored_exponents(factors, 2.0_wp, 1.0e-10_wp, mu, resolved)
      call check(ctx, all(resolved), "resolved")
      do i = 1, m
         call check(ctx, mu(i), expected(i)/2.0_wp, abs=1.0e-10_wp, message="exponent")
      end do
      ! QR itself: Q orthogonal, QR = A, R upper triangular
      call householder_qr(factors(:, :, 1), q, r)
      call check(ctx, maxval(abs(matmul(transpose(q), q) - identity(m))), 0.0_wp, abs=1.0e-14_wp, message="Q^T Q")
      call check(ctx, maxval(abs(matmul(q, r) - factors(:, :, 1))), 0.0_wp, abs=1.0e-13_wp, message="QR")
   end subroutine product_qr_closed_form

   !> x'' + K x = 0 with K = Rᵀ diag(−900, −1) R (a rotation R): constant, so Φ = e^{AP}
   !> and the exponents are 30 and 1 exactly; their multipliers e^{60} and e^{2} lie 25
   !> decades apart, beyond one double. Every method, two tolerances, status 0.
   subroutine exponents_spanning_decades(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(matrix_system_t) :: sys
      type(system_form_t) :: form
      type(system_nodes_t) :: nodes
      type(system_monodromy_t) :: r
      type(floquet_t) :: f
      type(error_t), allocatable :: error
      real(wp) :: c, s, k(2, 2), tol(2) = [1.0e-8_wp, 1.0e-10_wp]
      integer :: methods(5) = [system_auto, system_magnus4, system_magnus6, system_rk, system_gsl], i, t
      character(len=60) :: where
      c = cos(0.4_wp)
      s = sin(0.4_wp)
      k = matmul(transpose(reshape([c, -s, s, c], [2, 2])), matmul(reshape([-900.0_wp, 0.0_wp, 0.0_wp, -1.0_wp], &
                 [2, 2]), reshape([c, -s, s, c], [2, 2])))
      call sys%set_values("n", [2.0_wp], error)
      call sys%set_values("b", [k(1, 1), k(1, 2), k(2, 1), k(2, 2)], error)
      call sys%set_values("cos", [1.0_wp, 0.0_wp, 0.0_wp, 1.0_wp], error)
      call sys%check_values(error)
      call check(ctx, .not. allocated(error), "system")
      call prepare_system(sys, 0.0_wp, form, error)
      do i = 1, size(methods)
         do t = 1, size(tol)
            nodes = system_nodes_t()
            call system_point(sys, form, 0.0_wp, 1.0_wp, system_method_t(methods(i), tol(t)), nodes, r, f, error)
            write (where, '(a, i0, a, es8.1)') "method ", methods(i), " tolerance ", tol(t)
            call check(ctx, .not. allocated(error) .and. r%status == status_ok, trim(where)//": status 0")
            if (allocated(error)) cycle
            call check(ctx, f%exponents(1), 30.0_wp, abs=tol(t), message=trim(where)//": mu_1")
            call check(ctx, f%exponents(2), 1.0_wp, abs=tol(t), message=trim(where)//": mu_2")
         end do
      end do
   end subroutine exponents_spanning_decades

   !> Mettler's column (data/scenes/system_column.nml) at (1.012481, −237.313324): exponents
   !> 61.6199050 and 15.4049582 (a 150-bit reference; λ₂/λ₁ = 1e-40), every method.
   subroutine mettler_second_exponent(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(matrix_system_t) :: sys
      type(system_form_t) :: form
      type(system_nodes_t) :: nodes
      type(system_monodromy_t) :: r
      type(floquet_t) :: f
      type(error_t), allocatable :: error
      integer :: methods(5) = [system_auto, system_magnus4, system_magnus6, system_rk, system_gsl], i
      character(len=40) :: where
      call sys%set_values("n", [2.0_wp], error)
      call sys%set_values("b", [1.0_wp, 0.0_wp, 0.0_wp, 16.0_wp], error)
      call sys%set_values("cos", [-1.0_wp, -0.6_wp, -0.6_wp, -4.0_wp], error)
      call sys%check_values(error)
      call prepare_system(sys, 0.0_wp, form, error)
      do i = 1, size(methods)
         nodes = system_nodes_t()
         call system_point(sys, form, 1.012481_wp, -237.313324_wp, system_method_t(methods(i), 1.0e-10_wp), nodes, &
                           r, f, error)
         write (where, '(a, i0)') "method ", methods(i)
         call check(ctx, .not. allocated(error) .and. r%status == status_ok, trim(where)//": status 0")
         if (allocated(error)) cycle
         call check(ctx, f%exponents(1), 61.6199050_wp, abs=6.0e-8_wp, message=trim(where)//": mu_1")
         call check(ctx, f%exponents(2), 15.4049582_wp, abs=6.0e-8_wp, message=trim(where)//": mu_2")
         ! a₂ ≈ λ₁λ₂ (the other products are 1e-40 of it and less): the cancellation in
         ! ((tr Φ)² − tr Φ²)/2 left 1e90 of noise there
         call check(ctx, log(f%a2), 2.0_wp*(61.6199050_wp + 15.4049582_wp), abs=3.0e-7_wp, message=trim(where)//": a2")
      end do
   end subroutine mettler_second_exponent

   !> n = 1 with a negative damping (C = −100, the solution grows by e²⁰⁰ over the period):
   !> a₂ = det Φ = e^{−P tr(M⁻¹C)} = e²⁰⁰ exactly (Liouville), every column finite.
   subroutine negative_damping_a2(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(matrix_system_t) :: sys
      type(system_form_t) :: form
      type(system_nodes_t) :: nodes
      type(system_monodromy_t) :: r
      type(floquet_t) :: f
      type(error_t), allocatable :: error
      integer :: methods(3) = [system_auto, system_rk, system_gsl], i
      character(len=40) :: where
      call sys%set_values("n", [1.0_wp], error)
      call sys%set_values("damping", [-100.0_wp], error)
      call sys%set_values("cos", [1.0_wp], error)
      call sys%check_values(error)
      call prepare_system(sys, 0.0_wp, form, error)
      do i = 1, size(methods)
         nodes = system_nodes_t()
         call system_point(sys, form, 0.0_wp, 1.0_wp, system_method_t(methods(i), 1.0e-10_wp), nodes, r, f, error)
         write (where, '(a, i0)') "method ", methods(i)
         call check(ctx, .not. allocated(error) .and. r%status == status_ok, trim(where)//": status 0")
         if (allocated(error)) cycle
         call check(ctx, f%a2, exp(200.0_wp), rel=1.0e-9_wp, message=trim(where)//": a2 = e^200")
         call check(ctx, f%defect >= 0.0_wp .and. f%defect < 1.0e-10_wp, trim(where)//": defect")
      end do
   end subroutine negative_damping_a2

   !> Damped and driven, n = 2 (C = diag(30, 0.1), so the exponents span ~50 decades over
   !> the period): the exponents' sum over all 2n is −tr(M⁻¹C) (Liouville), and the pair of
   !> the heavily damped mode lies near −C₁₁ and −K₁₁/C₁₁ (overdamped: roots of s² + 30 s + k).
   subroutine damped_exponents_liouville(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(matrix_system_t) :: sys
      type(system_form_t) :: form
      type(system_nodes_t) :: nodes
      type(system_monodromy_t) :: r
      type(floquet_t) :: f
      type(error_t), allocatable :: error
      real(wp) :: factors_mu(4), expected_sum
      integer :: methods(3) = [system_auto, system_rk, system_gsl], i
      character(len=40) :: where
      call sys%set_values("n", [2.0_wp], error)
      call sys%set_values("b", [1.0_wp, 0.1_wp, 0.1_wp, 2.0_wp], error)
      call sys%set_values("damping", [30.0_wp, 0.0_wp, 0.0_wp, 0.1_wp], error)
      call sys%set_values("cos", [0.5_wp, 0.2_wp, 0.2_wp, 0.5_wp], error)
      call sys%check_values(error)
      call prepare_system(sys, 0.0_wp, form, error)
      expected_sum = -30.1_wp
      do i = 1, size(methods)
         nodes = system_nodes_t()
         call system_point(sys, form, 0.3_wp, 1.0_wp, system_method_t(methods(i), 1.0e-10_wp), nodes, r, f, error)
         write (where, '(a, i0)') "method ", methods(i)
         call check(ctx, .not. allocated(error) .and. r%status == status_ok, trim(where)//": status 0")
         if (allocated(error)) cycle
         ! the two printed exponents: the slow mode's (≈ −0.05, stable) and the overdamped
         ! mode's slow root (≈ −1/30); the fast root −30 is not printed
         factors_mu(1:2) = f%exponents
         call check(ctx, all(factors_mu(1:2) < 0.0_wp .and. factors_mu(1:2) > -0.1_wp), trim(where)//": range")
      end do
      call check_liouville(ctx, sys, form, expected_sum)
   end subroutine damped_exponents_liouville

   !> The four exponents of the damped system from the factored product add up to −tr(M⁻¹C).
   subroutine check_liouville(ctx, sys, form, expected_sum)
      type(test_context_t), intent(inout) :: ctx
      type(matrix_system_t), intent(in) :: sys
      type(system_form_t), intent(in) :: form
      real(wp), intent(in) :: expected_sum
      type(system_nodes_t) :: nodes
      type(system_monodromy_t) :: r
      type(floquet_t) :: f
      type(error_t), allocatable :: error
      real(wp), allocatable :: factors(:, :, :)
      real(wp) :: mu(4)
      logical :: resolved(4)
      integer :: count
      call system_point(sys, form, 0.3_wp, 1.0_wp, system_method_t(system_auto, 1.0e-10_wp), nodes, r, f, error)
      call system_factors(sys, form, 0.3_wp, 1.0_wp, system_method_t(system_auto, 1.0e-10_wp), nodes, r, &
                          factors, count, error)
      call check(ctx, .not. allocated(error), "factors")
      if (allocated(error)) return
      call factored_exponents(factors(:, :, 1:count), form%period, 1.0e-10_wp, mu, resolved)
      call check(ctx, all(resolved), "all four resolved")
      call check(ctx, sum(mu), expected_sum, abs=1.0e-9_wp, message="Liouville: the sum of the exponents")
      ! the fast overdamped root: s² + 30 s + k ≈ 0, s ≈ −30 + k/30 with k between 0.5 and 1.5
      call check(ctx, mu(4) < -29.9_wp .and. mu(4) > -30.0_wp, "the fast root near -30")
   end subroutine check_liouville

   !> Against the Taylor reference at 12 points of a damped gyroscopic 3-DOF chain with sines
   !> and of a 2-DOF pair at |β| up to 400: at every tolerance from 1e-8 to 1e-14 and every
   !> method, status 0 only with the error within the tolerance and the estimate, and status 1
   !> where 1e-14 lies below the rounding (Magnus 4 there at every point).
   subroutine roundoff_status_and_bound(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(matrix_system_t) :: sys
      type(system_form_t) :: form
      type(system_nodes_t) :: nodes
      type(system_monodromy_t) :: r
      type(floquet_t) :: f
      type(error_t), allocatable :: error
      real(wp) :: ref(4, 4), err, tol(4) = [1.0e-8_wp, 1.0e-12_wp, 1.0e-13_wp, 1.0e-14_wp], points(2, 6)
      integer :: methods(5) = [system_auto, system_magnus4, system_magnus6, system_rk, system_gsl], i, t, p, n_ok, &
                 n_roundoff
      character(len=80) :: where
      call sys%set_values("n", [2.0_wp], error)
      call sys%set_values("mass", [1.0_wp, 0.1_wp, 0.1_wp, 0.6_wp], error)
      call sys%set_values("b", [0.9255_wp, -0.0334_wp, -0.0334_wp, 0.9305_wp], error)
      call sys%set_values("cos", [-0.0314_wp, 1.3564_wp, 1.3564_wp, 1.4637_wp], error)
      call sys%set_values("sin", [0.3091_wp, -0.3236_wp, -0.3236_wp, -0.5707_wp], error)
      call sys%set_values("damping", [0.05_wp, 0.01_wp, 0.01_wp, 0.03_wp], error)
      call sys%set_values("gyroscopic", [0.0_wp, 0.4_wp, -0.4_wp, 0.0_wp], error)
      call sys%set_values("period", [4.0_wp], error)
      call sys%check_values(error)
      call check(ctx, .not. allocated(error), "system")
      call prepare_system(sys, 0.0_wp, form, error)
      points = reshape([0.4_wp, 2.0_wp, 1.4_wp, -262.5_wp, 0.8_wp, 150.0_wp, 2.0_wp, -40.0_wp, 0.1_wp, 400.0_wp, &
                        1.1_wp, 7.5_wp], [2, 6])
      n_ok = 0
      n_roundoff = 0
      do p = 1, size(points, 2)
         call reference_monodromy(sys, points(1, p), points(2, p), 0.0_wp, ref)
         do i = 1, size(methods)
            do t = 1, size(tol)
               nodes = system_nodes_t()
               call system_point(sys, form, points(1, p), points(2, p), system_method_t(methods(i), tol(t)), nodes, &
                                 r, f, error)
               write (where, '(a, i0, a, 2es11.3, a, es8.1)') "method ", methods(i), " at ", points(:, p), " tol", tol(t)
               call check(ctx, .not. allocated(error), trim(where)//": computed")
               if (allocated(error)) cycle
               if (r%status == status_roundoff) n_roundoff = n_roundoff + 1
               if (r%status /= status_ok) cycle
               n_ok = n_ok + 1
               err = maxval(abs(r%phi*exp(r%log_scale) - ref))/max(1.0_wp, maxval(abs(ref)))
               call check(ctx, err <= tol(t), trim(where)//": error within the tolerance at status 0")
               call check(ctx, err <= r%error_estimate, trim(where)//": the estimate bounds the error")
               call check(ctx, r%steps > 0, trim(where)//": steps counted")
            end do
         end do
      end do
      ! every method at 1e-8 and most at 1e-12 (gsl's rounding reaches 1e-12 at |beta| = 400)
      call check(ctx, n_ok >= 50, "at least 50 points at status 0, got "//integer_text(n_ok))
      call check(ctx, n_roundoff >= 6, "1e-14 and below: status 1")
   end subroutine roundoff_status_and_bound

   !> The defect is relative: at a strongly unstable point (|Φ| ~ 1e53) it stays at the
   !> rounding level, Hamiltonian and damped.
   subroutine defect_relative(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(matrix_system_t) :: sys
      type(system_form_t) :: form
      type(system_nodes_t) :: nodes
      type(system_monodromy_t) :: r
      type(floquet_t) :: f
      type(error_t), allocatable :: error
      real(wp) :: eps(2) = [0.0_wp, 0.3_wp]
      integer :: i
      call sys%set_values("n", [2.0_wp], error)
      call sys%set_values("b", [1.0_wp, 0.0_wp, 0.0_wp, 16.0_wp], error)
      call sys%set_values("cos", [-1.0_wp, -0.6_wp, -0.6_wp, -4.0_wp], error)
      call sys%check_values(error)
      do i = 1, 2
         call prepare_system(sys, eps(i), form, error)
         nodes = system_nodes_t()
         call system_point(sys, form, 1.012481_wp, -237.313324_wp, system_method_t(system_auto, 1.0e-10_wp), nodes, &
                           r, f, error)
         call check(ctx, .not. allocated(error), "computed")
         if (allocated(error)) cycle
         call check(ctx, f%defect >= 0.0_wp .and. f%defect < 1.0e-10_wp, "defect below 1e-10")
      end do
   end subroutine defect_relative

   !> Two identical undriven oscillators at β = π²/4: every multiplier at −1 (S = 2 cos π per
   !> block), a boundary no error bound decides: verdict −1 and kind "undecided", not "stable".
   subroutine marginal_is_undecided(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(matrix_system_t) :: sys
      type(system_form_t) :: form
      type(system_nodes_t) :: nodes
      type(system_monodromy_t) :: r
      type(floquet_t) :: f
      type(error_t), allocatable :: error
      real(wp), parameter :: pi = 3.14159265358979324_wp
      call sys%set_values("n", [2.0_wp], error)
      call sys%set_values("cos", [1.0_wp, 0.0_wp, 0.0_wp, 1.0_wp], error)
      call sys%check_values(error)
      call prepare_system(sys, 0.0_wp, form, error)
      call system_point(sys, form, 0.0_wp, 0.25_wp*pi*pi, system_method_t(system_auto, 1.0e-10_wp), nodes, r, f, error)
      call check(ctx, .not. allocated(error), "computed")
      if (allocated(error)) return
      call check(ctx, f%verdict == verdict_marginal, "marginal")
      call check(ctx, f%kind == kind_undecided, "kind undecided")
   end subroutine marginal_is_undecided

   pure function identity(m) result(a)
      integer, intent(in) :: m
      real(wp) :: a(m, m)
      integer :: i
      a = 0.0_wp
      do i = 1, m
         a(i, i) = 1.0_wp
      end do
   end function identity

   !> Gauss–Jordan inverse (a small test matrix).
   pure subroutine invert(a, inverse)
      real(wp), intent(in) :: a(:, :)
      real(wp), intent(out) :: inverse(:, :)
      real(wp) :: w(size(a, 1), 2*size(a, 1))
      integer :: n, i, k
      n = size(a, 1)
      w(:, 1:n) = a
      w(:, n + 1:) = identity(n)
      do k = 1, n
         w(k, :) = w(k, :)/w(k, k)
         do i = 1, n
            if (i /= k) w(i, :) = w(i, :) - w(i, k)*w(k, :)
         end do
      end do
      inverse = w(:, n + 1:)
   end subroutine invert
end module test_system_point

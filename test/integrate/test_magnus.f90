!> Tests of the Magnus integrators: the closed-form sl(2) algebra against generic
!> 2×2 matrix commutators and a second published sixth-order formula, exactness for
!> constant q, observed orders 4 and 6 against an independent RK4 reference, the
!> half-period identity, det M = 1, and the adaptive tolerance over the (α, β) grid
!> (including α → π²) against a fine uniform Magnus-6 with Richardson extrapolation.
module test_magnus
   use hillstab_core_kinds, only: wp, int64, pi2
   use hillstab_core_error, only: error_t, err_integration, err_invalid_parameter, err_accuracy
   use hillstab_core_stats, only: work_stats_t
   use hillstab_hill_transfer, only: scaled_matrix_t, trace_t, trace_of, determinant_of, monodromy_from_half_period
   use hillstab_integrate_magnus
   use hillstab_integrate_monodromy, only: monodromy_trace, method_t, method_magnus4, method_magnus6
   use hillstab_test_reference, only: rk4_monodromy, value_of
   use hillstab_testing
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use hillstab_hill_model, only: hill_model_t, hill_point_t, hill_coefficient
   use hillstab_hill_model_elastic, only: elastic_model_t
   use hillstab_hill_model_mathieu, only: mathieu_model_t
   use hillstab_hill_models, only: model_from_code
   use hillstab_test_models, only: model_of_code
   implicit none
   private
   public :: collect_magnus

contains

   function collect_magnus() result(suite)
      type(testsuite_t) :: suite
      suite = new_testsuite("magnus", [ &
         new_unittest("sl2_algebra", sl2_algebra), &
         new_unittest("sixth_order_formulas_agree", sixth_order_formulas_agree), &
         new_unittest("constant_coefficient_exact", constant_coefficient_exact), &
         new_unittest("observed_order", observed_order), &
         new_unittest("half_period_identity", half_period_identity), &
         new_unittest("unit_determinant", unit_determinant), &
         new_unittest("adaptive_grid", adaptive_grid), &
         new_unittest("adaptive_order4", adaptive_order4), &
         new_unittest("adaptive_mesh_pays", adaptive_mesh_pays), &
         new_unittest("errors_reported", errors_reported), &
         new_unittest("dispatch", dispatch)])
   end function collect_magnus

   !> [X, Y] = XY − YX for plain 2×2 matrices.
   pure function matrix_commutator(x, y) result(z)
      real(wp), intent(in) :: x(2, 2), y(2, 2)
      real(wp) :: z(2, 2)
      z = matmul(x, y) - matmul(y, x)
   end function matrix_commutator

   !> A(q) = [[0, 1], [−q, 0]].
   pure function hill_matrix(q) result(a)
      real(wp), intent(in) :: q
      real(wp) :: a(2, 2)
      a = reshape([0.0_wp, -q, 1.0_wp, 0.0_wp], [2, 2])
   end function hill_matrix

   !> Generic sixth-order Magnus generator (same Phys. Rep. formula as the library,
   !> but with full matrix commutators).
   pure function generic_magnus6(q, h) result(omega)
      real(wp), intent(in) :: q(3), h
      real(wp) :: omega(2, 2), a1(2, 2), a2(2, 2), a3(2, 2), c1(2, 2), c2(2, 2)
      a1 = h*hill_matrix(q(2))
      a2 = sqrt(15.0_wp)*h/3*(hill_matrix(q(3)) - hill_matrix(q(1)))
      a3 = 10*h/3*(hill_matrix(q(3)) - 2*hill_matrix(q(2)) + hill_matrix(q(1)))
      c1 = matrix_commutator(a1, a2)
      c2 = -matrix_commutator(a1, 2*a3 + c1)/60
      omega = a1 + a3/12 + matrix_commutator(-20*a1 - a3 + c1, a2 + c2)/240
   end function generic_magnus6

   !> The sixth-order scheme of Blanes, Casas, Ros, BIT 40 (2000) 434 in its moment form
   !> (B0, B1, B2 from the same three Gauss values): an independent transcription.
   pure function moment_magnus6(q, h) result(omega)
      real(wp), intent(in) :: q(3), h
      real(wp) :: omega(2, 2), b0(2, 2), b1(2, 2), b2(2, 2), omega2(2, 2)
      b0 = (5*(hill_matrix(q(1)) + hill_matrix(q(3))) + 8*hill_matrix(q(2)))/18
      b1 = sqrt(15.0_wp)/36*(hill_matrix(q(3)) - hill_matrix(q(1)))
      b2 = (hill_matrix(q(1)) + hill_matrix(q(3)))/24
      omega2 = h*h*matrix_commutator(b1, 1.5_wp*b0 - 6*b2)
      omega = h*b0 + omega2 + h*h*matrix_commutator(b0, matrix_commutator(b0, h*b2/2 - omega2/60)) &
              + 0.6_wp*h*matrix_commutator(b1, omega2)
   end function moment_magnus6

   !> The closed-form bracket and generators against generic matrix algebra.
   subroutine sl2_algebra(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp) :: x(3), y(3), z(2, 2), q(3), h, g(3), omega(2, 2)
      integer :: k
      do k = 1, 5
         x = [sin(1.0_wp*k), cos(2.0_wp*k), 0.3_wp*k - 1]
         y = [0.7_wp - 0.2_wp*k, sin(3.0_wp*k), exp(-0.5_wp*k)]
         z = matrix_commutator(sl2_matrix(x), sl2_matrix(y))
         call check(ctx, maxval(abs(sl2_matrix(sl2_commutator(x, y)) - z)) < 1.0e-15_wp, "sl2 bracket")
      end do
      ! fourth order: (h/2)(A1 + A2) + (√3 h²/12)[A2, A1]
      q(1:2) = [3.0_wp, -7.5_wp]; h = 0.3_wp
      omega = h/2*(hill_matrix(q(1)) + hill_matrix(q(2))) &
              + sqrt(3.0_wp)*h*h/12*matrix_commutator(hill_matrix(q(2)), hill_matrix(q(1)))
      g = magnus4_generator(q(1:2), h)
      call check(ctx, maxval(abs(sl2_matrix(g) - omega)) < 1.0e-15_wp, "magnus4 closed form")
      ! sixth order: closed form in sl(2) coordinates = the formula with matrix commutators
      q = [12.0_wp, -3.0_wp, 40.0_wp]; h = 0.2_wp
      g = magnus6_generator(q, h)
      omega = generic_magnus6(q, h)
      call check(ctx, maxval(abs(sl2_matrix(g) - omega)) < 1.0e-14_wp*maxval(abs(omega)), "magnus6 closed form")
   end subroutine sl2_algebra

   !> The Phys. Rep. 2009 (α, C1, C2) form and the BIT 2000 moment form differ by O(h^7)
   !> for smooth q: halving h divides the difference by about 2^7.
   subroutine sixth_order_formulas_agree(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp), parameter :: offset = 0.38729833462074168852_wp
      class(hill_model_t), pointer :: model
      type(hill_point_t) :: point
      real(wp) :: h, q(3), diff(4)
      integer :: k
      model => model_of_code(1)
      point = hill_point_t(8.0_wp, 2.47_wp, 0.0_wp)
      h = 0.2_wp
      do k = 1, 4
         q = [hill_coefficient_at(model, point, 0.3_wp + (0.5_wp - offset)*h), hill_coefficient_at(model, point, &
            0.3_wp + 0.5_wp*h), &
              hill_coefficient_at(model, point, 0.3_wp + (0.5_wp + offset)*h)]
         diff(k) = maxval(abs(sl2_matrix(magnus6_generator(q, h)) - moment_magnus6(q, h)))
         h = h/2
      end do
      do k = 1, 3
         call check(ctx, log(diff(k)/diff(k + 1))/log(2.0_wp), 7.0_wp, abs=0.5_wp, message="O(h^7) difference")
      end do
   end subroutine sixth_order_formulas_agree

   real(wp) function hill_coefficient_at(model, point, tau) result(q)
      use hillstab_hill_model, only: hill_coefficient
      class(hill_model_t), intent(in) :: model  !! the model
      type(hill_point_t), intent(in) :: point   !! α, β, ε
      real(wp), intent(in) :: tau
      q = hill_coefficient(model, point, tau)
   end function hill_coefficient_at

   !> α = 0: Q ≡ β and S = 2 cos(2√β) (2 cosh(2√−β) for β < 0), for every step size.
   subroutine constant_coefficient_exact(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp) :: betas(10) = [-400.0_wp, -50.0_wp, -2.0_wp, -1.0e-3_wp, 0.0_wp, 1.0e-3_wp, 2.47_wp, &
                               pi2, 1.0e3_wp, 1.0e4_wp]
      real(wp) :: exact, tol
      type(trace_t) :: tr
      type(work_stats_t) :: stats
      type(error_t), allocatable :: error
      integer :: j, order, kind
      class(hill_model_t), pointer :: kind_model
      character(len=60) :: label
      do j = 1, size(betas)
         if (betas(j) >= 0.0_wp) then
            exact = 2*cos(2*sqrt(betas(j)))
         else
            exact = 2*cosh(2*sqrt(-betas(j)))
         end if
         ! 2√β rad of phase carry a round-off of about ε·2√β
         tol = 1.0e-14_wp*max(1.0_wp, abs(exact))*max(1.0_wp, 2*sqrt(abs(betas(j))))
         do kind = 1, 2   ! the elastic and the Mathieu model
            kind_model => model_of_code(kind)
            do order = 4, 6, 2
               write (label, '(a,es10.3,a,i0,a,i0)') "beta=", betas(j), " order ", order, " model ", kind
               call trace_magnus(kind_model, hill_point_t(0.0_wp, betas(j), 0.0_wp), order, 1.0e-10_wp, tr, stats, error)
               call check(ctx, .not. allocated(error), "no error "//trim(label))
               call check(ctx, tr%value, exact, abs=tol, message=trim(label))
               call check(ctx, stats%n_evaluations <= 60_int64, "cheap for constant q "//trim(label))
               tr = trace_of(monodromy_magnus_uniform(kind_model, hill_point_t(0.0_wp, betas(j), 0.0_wp), order, 3))
               call check(ctx, tr%value, exact, abs=tol, message="3 uniform steps "//trim(label))
            end do
         end do
      end do
   end subroutine constant_coefficient_exact

   !> Orders 4 and 6 on uniform full-period meshes, against RK4 with 40000 steps.
   subroutine observed_order(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(hill_point_t) :: points(2)
      integer :: codes(2)  !! the models by registry code (1 elastic, 2 Mathieu)
      real(wp) :: reference, e1, e2, m(2, 2)
      integer :: i, order, n
      ! coarsest mesh per (order, model): errors well above RK4's ~1e-13 yet asymptotic
      integer, parameter :: first_steps(2, 2) = reshape([32, 16, 16, 8], [2, 2])
      character(len=60) :: label
      codes(1) = 1
      points(1) = hill_point_t(5.0_wp, 2.47_wp, 0.0_wp)
      codes(2) = 2
      points(2) = hill_point_t(2.0_wp, 2.47_wp, 0.0_wp)
      do i = 1, 2
         m = rk4_monodromy(model_of_code(codes(i)), points(i), 0.0_wp, 40000)
         reference = m(1, 1) + m(2, 2)
         do order = 4, 6, 2
            n = first_steps(order/2 - 1, i)
            e1 = abs(value_of(trace_of(monodromy_magnus_uniform(model_of_code(codes(i)), points(i), order, n))) - reference)
            e2 = abs(value_of(trace_of(monodromy_magnus_uniform(model_of_code(codes(i)), points(i), order, 2*n))) - reference)
            write (label, '(a,i0,a,i0,a,2es9.2)') "model ", codes(i), " order ", order, " errors ", e1, e2
            call check(ctx, e2 > 1.0e-11_wp, "above the reference's accuracy "//trim(label))
            call check(ctx, log(e1/e2)/log(2.0_wp), real(order, wp), abs=0.25_wp, message=trim(label))
         end do
      end do
   end subroutine observed_order

   !> M from Φ(1) (u even, v odd) equals the product over the full period.
   subroutine half_period_identity(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(hill_point_t) :: points(5)
      integer :: codes(5)  !! the models by registry code (1 elastic, 2 Mathieu)
      type(scaled_matrix_t) :: half, full
      real(wp) :: a(2, 2), b(2, 2)
      integer :: i, order
      codes(1) = 1
      points(1) = hill_point_t(5.0_wp, 2.47_wp, 0.0_wp)
      codes(2) = 1
      points(2) = hill_point_t(9.8_wp, -50.0_wp, 0.0_wp)
      codes(3) = 1
      points(3) = hill_point_t(9.8_wp, 400.0_wp, 0.0_wp)
      codes(4) = 1
      points(4) = hill_point_t(7.0_wp, 1.6_wp, 1.5_wp)
      codes(5) = 2
      points(5) = hill_point_t(3.0_wp, 6.0_wp, 0.0_wp)
      do i = 1, size(points)
         do order = 4, 6, 2
            half = monodromy_from_half_period(half_period_magnus_uniform(model_of_code(codes(i)), points(i), order, 300))
            full = monodromy_magnus_uniform(model_of_code(codes(i)), points(i), order, 600)
            ! compare on the scale of the larger matrix (entries in units of e^log_scale)
            a = half%m*exp(half%log_scale - max(half%log_scale, full%log_scale))
            b = full%m*exp(full%log_scale - max(half%log_scale, full%log_scale))
            call check(ctx, maxval(abs(a - b)) < 1.0e-11_wp, "identity, model index "//achar(48 + i))
            call check(ctx, abs(a(1, 1) - a(2, 2)) < 1.0e-15_wp, "equal diagonal")
            call check(ctx, abs(b(1, 1) - b(2, 2)) < 1.0e-11_wp, "full product: equal diagonal")
         end do
      end do
   end subroutine half_period_identity

   !> det M = 1 to round-off (relative to max|M_ij|², the size of the products in det).
   subroutine unit_determinant(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp) :: alphas(4) = [0.0_wp, 5.0_wp, 9.8_wp, 9.85_wp], betas(5) = [-50.0_wp, -2.0_wp, 2.47_wp, 12.0_wp, 400.0_wp]
      type(scaled_matrix_t) :: m
      type(work_stats_t) :: stats
      type(error_t), allocatable :: error
      real(wp) :: d, log_det_scale
      integer :: i, j
      do i = 1, size(alphas)
         do j = 1, size(betas)
            call monodromy_magnus(elastic_model_t(), hill_point_t(alphas(i), betas(j), 0.0_wp), 6, 1.0e-10_wp, &
               m, stats, error)
            call determinant_of(m, d, log_det_scale)
            ! det M − 1 in units of max|M_ij|² = e^{log_det_scale}
            call check(ctx, d, exp(-log_det_scale), abs=2.0e-14_wp)
            if (log_det_scale < 10.0_wp) call check(ctx, d*exp(log_det_scale), 1.0_wp, abs=1.0e-13_wp)
            call check(ctx, .not. allocated(error), "tolerance met")
         end do
      end do
   end subroutine unit_determinant

   !> Reference S: uniform full-period Magnus-6 with n and 2n steps, Richardson-extrapolated.
   function richardson_reference(model, point, n) result(s)
      class(hill_model_t), intent(in) :: model  !! the model
      type(hill_point_t), intent(in) :: point   !! α, β, ε
      integer, intent(in) :: n
      real(wp) :: s, s1, s2
      s1 = value_of(trace_of(monodromy_magnus_uniform(model, point, 6, n)))
      s2 = value_of(trace_of(monodromy_magnus_uniform(model, point, 6, 2*n)))
      s = s2 + (s2 - s1)/63
   end function richardson_reference

   !> Tolerance 1e-10 met over the (α, β) grid and at hard points near α → π².
   subroutine adaptive_grid(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp) :: alphas(7) = [0.0_wp, 2.0_wp, 5.0_wp, 8.0_wp, 9.5_wp, 9.8_wp, 9.85_wp]
      real(wp) :: betas(7) = [-2.0_wp, 2.47_wp, 6.0_wp, 12.0_wp, -50.0_wp, 400.0_wp, 2500.0_wp]
      real(wp), parameter :: tolerance = 1.0e-10_wp
      class(hill_model_t), pointer :: model
      type(hill_point_t) :: point
      type(trace_t) :: tr
      type(work_stats_t) :: stats
      type(error_t), allocatable :: error
      real(wp) :: reference, m(2, 2), estimate
      integer :: i, j
      character(len=80) :: label
      do i = 1, size(alphas)
         do j = 1, size(betas)
            if (j > 4 .and. alphas(i) /= 9.8_wp) cycle
            model => model_of_code(1)
            point = hill_point_t(alphas(i), betas(j), 0.0_wp)
            reference = richardson_reference(model, point, merge(8192, 32768, j <= 4))
            call trace_magnus(model, point, 6, tolerance, tr, stats, error, estimate)
            write (label, '(a,f5.2,a,f8.2,a,es9.2,a,i0)') "alpha=", alphas(i), " beta=", betas(j), &
               " estimate ", estimate, " evaluations ", stats%n_evaluations
            call check(ctx, .not. allocated(error), "no error "//trim(label))
            call check(ctx, tr%value, reference, abs=tolerance*max(1.0_wp, abs(reference)), message=trim(label))
            call check(ctx, estimate <= tolerance, "estimate meets tolerance "//trim(label))
         end do
      end do
      ! the Richardson reference itself against the independent RK4 where RK4 is affordable
      model => model_of_code(1)
      point = hill_point_t(9.8_wp, 2.47_wp, 0.0_wp)
      m = rk4_monodromy(model, point, 0.0_wp, 200000)
      reference = richardson_reference(model, point, 8192)
      call check(ctx, m(1, 1) + m(2, 2), reference, rel=1.0e-10_wp, message="reference vs RK4, alpha = 9.8")
      model => model_of_code(1)
      point = hill_point_t(5.0_wp, 6.0_wp, 0.0_wp)
      m = rk4_monodromy(model, point, 0.0_wp, 40000)
      call check(ctx, m(1, 1) + m(2, 2), richardson_reference(model, point, 8192), rel=1.0e-11_wp, &
         message="reference vs RK4, alpha = 5")
   end subroutine adaptive_grid

   !> The order-4 integrator meets its tolerance too (1e-8, a few points).
   subroutine adaptive_order4(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp) :: points(2, 4) = reshape([2.0_wp, 2.47_wp, 8.0_wp, -2.0_wp, 9.8_wp, 6.0_wp, 9.85_wp, 12.0_wp], [2, 4])
      class(hill_model_t), pointer :: model
      type(hill_point_t) :: point
      type(trace_t) :: tr
      type(work_stats_t) :: stats
      type(error_t), allocatable :: error
      real(wp) :: reference
      integer :: k
      do k = 1, size(points, 2)
         model => model_of_code(1)
         point = hill_point_t(points(1, k), points(2, k), 0.0_wp)
         reference = richardson_reference(model, point, 8192)
         call trace_magnus(model, point, 4, 1.0e-8_wp, tr, stats, error)
         call check(ctx, .not. allocated(error), "no error")
         call check(ctx, tr%value, reference, abs=1.0e-8_wp*max(1.0_wp, abs(reference)))
      end do
   end subroutine adaptive_order4

   !> At α = 9.85 the adapted mesh is far more accurate than a uniform mesh of the same
   !> number of steps (the dip at τ = 0 is resolved, the smooth part is not over-resolved).
   subroutine adaptive_mesh_pays(ctx)
      type(test_context_t), intent(inout) :: ctx
      class(hill_model_t), pointer :: model
      type(hill_point_t) :: point
      type(scaled_matrix_t) :: m
      type(work_stats_t) :: stats
      type(error_t), allocatable :: error
      real(wp) :: reference, adaptive_error, uniform_error
      integer :: n_steps
      model => model_of_code(1)
      point = hill_point_t(9.85_wp, 2.47_wp, 0.0_wp)
      reference = richardson_reference(model, point, 8192)
      call monodromy_magnus(model, point, 6, 1.0e-8_wp, m, stats, error)
      adaptive_error = abs(value_of(trace_of(m)) - reference)
      ! steps of the returned pass: total evaluations ≈ 3 (fine + coarse/2) per step
      n_steps = int(stats%n_evaluations/4.5_wp)
      uniform_error = abs(value_of(trace_of(monodromy_from_half_period( &
                      half_period_magnus_uniform(model, point, 6, n_steps)))) - reference)
      call check(ctx, adaptive_error <= 1.0e-8_wp*abs(reference), "adaptive meets tolerance")
      call check(ctx, uniform_error > 30*adaptive_error, "uniform mesh of equal size is much worse")
   end subroutine adaptive_mesh_pays

   subroutine errors_reported(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(trace_t) :: tr
      type(work_stats_t) :: stats
      type(error_t), allocatable :: error
      real(wp) :: estimate
      class(hill_model_t), pointer :: model
      type(hill_point_t) :: point
      model => model_of_code(1)
      point = hill_point_t(5.0_wp, 2.47_wp, 0.0_wp)
      call trace_magnus(model, point, 5, 1.0e-8_wp, tr, stats, error)
      call check(ctx, allocated(error), "order 5 rejected")
      if (allocated(error)) call check(ctx, error%code == err_invalid_parameter, "invalid parameter")
      call trace_magnus(model, point, 6, 0.0_wp, tr, stats, error)
      call check(ctx, allocated(error), "tolerance 0 rejected")
      call trace_magnus(elastic_model_t(), hill_point_t(pi2, 2.47_wp, 0.0_wp), 6, 1.0e-8_wp, tr, stats, error)
      call check(ctx, allocated(error), "alpha = pi**2 rejected")
      ! below round-off the tolerance cannot be met: round-off limited (err_accuracy), the
      ! best value with an estimate above the tolerance, never NaN
      call trace_magnus(elastic_model_t(), hill_point_t(2.0_wp, 2.47_wp, 0.0_wp), 6, 1.0e-17_wp, tr, stats, error, estimate)
      call check(ctx, allocated(error), "1e-17 not reachable")
      if (allocated(error)) call check(ctx, error%code == err_accuracy, "round-off limited")
      call check(ctx, estimate > 1.0e-17_wp .and. estimate < 1.0e-12_wp, "estimate at the round-off level")
      call check(ctx, ieee_is_finite(tr%value) .and. abs(tr%value) < 100.0_wp, "finite trace returned")
   end subroutine errors_reported

   subroutine dispatch(ctx)
      type(test_context_t), intent(inout) :: ctx
      class(hill_model_t), pointer :: model
      type(hill_point_t) :: point
      type(trace_t) :: tr, direct
      type(work_stats_t) :: stats
      type(error_t), allocatable :: error
      integer :: kind
      model => model_of_code(1)
      point = hill_point_t(7.48_wp, 2.47_wp, 0.3_wp)
      do kind = method_magnus4, method_magnus6
         call monodromy_trace(model, point, method_t(kind=kind, tolerance=1.0e-9_wp), tr, error)
         call check(ctx, .not. allocated(error), "dispatched")
         call trace_magnus(model, point, merge(4, 6, kind == method_magnus4), 1.0e-9_wp, direct, stats, error)
         call check(ctx, tr%value, direct%value, rel=0.0_wp, message="same result")
      end do
   end subroutine dispatch
end module test_magnus

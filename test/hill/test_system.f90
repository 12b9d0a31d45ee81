!> Tests of systems of Hill equations: the matrix system and its checks, the scalar models as
!> systems of one equation, the system methods against an extended-precision Taylor reference
!> (hillstab_test_system_reference), Broucke's fast path against the eigenvalues, verdicts
!> and kinds, and the combination tongue against first-order perturbation theory.
module test_system
   use hillstab_core_kinds, only: wp, pi
   use hillstab_core_error, only: error_t
   use hillstab_core_status, only: status_ok, status_roundoff
   use hillstab_hill_model, only: hill_point_t
   use hillstab_hill_model_elastic, only: elastic_model_t
   use hillstab_hill_model_mathieu, only: mathieu_model_t
   use hillstab_hill_model_fourier, only: fourier_model_t
   use hillstab_hill_model_meissner, only: meissner_model_t
   use hillstab_hill_transfer, only: trace_t
   use hillstab_hill_floquet, only: floquet_from_trace
   use hillstab_integrate_monodromy, only: method_t, monodromy_trace, method_magnus6
   use hillstab_hill_system, only: system_form_t, prepare_system, cholesky_inverse
   use hillstab_hill_system_matrix, only: matrix_system_t
   use hillstab_hill_system_scalar, only: scalar_system_t
   use hillstab_hill_systems, only: system_kinds, system_names, new_system, is_system_name, system_kinds_text
   use hillstab_hill_system, only: hill_system_t
   use hillstab_hill_system_floquet
   use hillstab_integrate_system
   use hillstab_integrate_system_point, only: system_point
   use hillstab_core_text, only: real_text
   use hillstab_test_system_reference, only: reference_monodromy
   use hillstab_testing
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   implicit none
   private
   public :: collect_system, pendula_pair

contains

   function collect_system() result(suite)
      type(testsuite_t) :: suite
      suite = new_testsuite("system", [ &
         new_unittest("one_dof_is_scalar_trace", one_dof_is_scalar_trace), &
         new_unittest("one_result_two_routes", one_result_two_routes), &
         new_unittest("kinds_of_system", kinds_of_system), &
         new_unittest("zero_multipliers_finite", zero_multipliers_finite), &
         new_unittest("decoupled_multipliers", decoupled_multipliers), &
         new_unittest("reference_two_dof", reference_two_dof), &
         new_unittest("reference_three_dof", reference_three_dof), &
         new_unittest("broucke_matches_eigenvalues", broucke_matches_eigenvalues), &
         new_unittest("verdicts_with_clear_margin", verdicts_with_clear_margin), &
         new_unittest("combination_tongue_first_order", combination_tongue_first_order), &
         new_unittest("structure_defects", structure_defects), &
         new_unittest("scaled_growth_exponent", scaled_growth_exponent), &
         new_unittest("trace_form_extremes", trace_form_extremes), &
         new_unittest("bad_matrices_named", bad_matrices_named), &
         new_unittest("mass_scales_apart", mass_scales_apart)])
   end function collect_system

   !> Two pendula of lengths 1 and l2 joined by a spring (c: its stiffness against gravity's),
   !> the support shaken vertically: M = diag(1, l2²), B = diag(1, l2) + c [[1, −1], [−1, 1]],
   !> K = β B − α cos πτ diag(1, l2); damping ζ adds C = ζ M, gyroscopic g adds G = [[0, g], [−g, 0]].
   function pendula_pair(l2, c, damping, gyroscopic, sine) result(pair)
      real(wp), intent(in) :: l2, c
      real(wp), intent(in), optional :: damping, gyroscopic, sine
      type(matrix_system_t) :: pair
      type(error_t), allocatable :: error
      call pair%set_values("n", [2.0_wp], error)
      call pair%set_values("mass", [1.0_wp, 0.0_wp, 0.0_wp, l2*l2], error)
      call pair%set_values("b", [1.0_wp + c, -c, -c, l2 + c], error)
      call pair%set_values("cos", [-1.0_wp, 0.0_wp, 0.0_wp, -l2], error)
      if (present(damping)) call pair%set_values("damping", damping*[1.0_wp, 0.0_wp, 0.0_wp, l2*l2], error)
      if (present(gyroscopic)) call pair%set_values("gyroscopic", [0.0_wp, gyroscopic, -gyroscopic, 0.0_wp], error)
      if (present(sine)) call pair%set_values("sin", sine*[0.0_wp, 1.0_wp, 1.0_wp, 0.5_wp], error)
      call pair%check_values(error)
      if (allocated(error)) error stop "pendula_pair: "//error%message
   end function pendula_pair

   !> A chain of three masses (1, 1.5, 0.7) with springs, the middle one driven, C and G optional.
   function chain_of_three(damping, gyroscopic) result(chain)
      real(wp), intent(in) :: damping, gyroscopic
      type(matrix_system_t) :: chain
      type(error_t), allocatable :: error
      call chain%set_values("n", [3.0_wp], error)
      call chain%set_values("mass", [1.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, 1.5_wp, 0.0_wp, 0.0_wp, 0.0_wp, 0.7_wp], error)
      call chain%set_values("k0", [2.0_wp, -1.0_wp, 0.0_wp, -1.0_wp, 2.0_wp, -1.0_wp, 0.0_wp, -1.0_wp, 2.0_wp], error)
      call chain%set_values("b", [1.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, 1.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, 1.0_wp], error)
      call chain%set_values("cos", [0.3_wp, 0.2_wp, 0.0_wp, 0.2_wp, 1.0_wp, 0.2_wp, 0.0_wp, 0.2_wp, 0.3_wp, &
                                    0.0_wp, 0.0_wp, 0.1_wp, 0.0_wp, 0.2_wp, 0.0_wp, 0.1_wp, 0.0_wp, 0.0_wp], error)
      call chain%set_values("sin", [0.0_wp, 0.1_wp, 0.0_wp, 0.1_wp, 0.3_wp, 0.0_wp, 0.0_wp, 0.0_wp, -0.2_wp], error)
      call chain%set_values("damping", damping*[1.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, 1.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, &
                                                2.0_wp], error)
      call chain%set_values("gyroscopic", gyroscopic*[0.0_wp, 1.0_wp, 0.0_wp, -1.0_wp, 0.0_wp, 1.0_wp, 0.0_wp, &
                                                      -1.0_wp, 0.0_wp], error)
      call chain%check_values(error)
      if (allocated(error)) error stop "chain_of_three: "//error%message
   end function chain_of_three

   !> n = 1: the trace of Φ is the scalar model's, e^{−εP/2} S₁ with damping, at every system
   !> method and two tolerances, for four models (elastic, mathieu, fourier with sines, meissner's jumps).
   subroutine one_dof_is_scalar_trace(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(scalar_system_t) :: one
      type(system_form_t) :: form
      type(system_nodes_t) :: nodes
      type(system_monodromy_t) :: r
      type(trace_t) :: tr
      type(error_t), allocatable :: error
      type(fourier_model_t) :: fourier
      real(wp) :: alphas(3) = [0.7_wp, 2.5_wp, 6.0_wp], betas(3) = [-1.0_wp, 2.3_wp, 9.0_wp], eps(2) = [0.0_wp, 0.4_wp]
      real(wp) :: tols(2) = [1.0e-8_wp, 1.0e-10_wp], s, expected
      integer :: model, i, k, t, method
      integer :: methods(4) = [system_auto, system_magnus4, system_rk, system_gsl]
      call fourier%set_values("cos", [1.0_wp, 0.3_wp], error)
      call fourier%set_values("sin", [0.0_wp, 0.4_wp], error)
      do model = 1, 4
         if (allocated(one%model)) deallocate (one%model)
         select case (model)
         case (1); allocate (one%model, source=elastic_model_t())
         case (2); allocate (one%model, source=mathieu_model_t())
         case (3); allocate (one%model, source=fourier)
         case (4); allocate (one%model, source=meissner_model_t())
         end select
         do k = 1, 2
            call prepare_system(one, eps(k), form, error)
            call check(ctx, .not. allocated(error), "prepare")
            do i = 1, 3
               if (model == 4 .and. alphas(i) >= 1.0_wp) cycle
               call monodromy_trace(one%model, hill_point_t(alphas(i), betas(i), eps(k)), &
                                    method_t(kind=method_magnus6, tolerance=1.0e-13_wp), tr, error)
               expected = tr%value*exp(-0.5_wp*eps(k)*one%model%period())
               do method = 1, 4
                  do t = 1, 2
                     nodes = system_nodes_t()
                     call system_monodromy(one, form, alphas(i), betas(i), system_method_t(methods(method), tols(t)), &
                                           nodes, r, error)
                     call check(ctx, .not. allocated(error), "system monodromy")
                     if (allocated(error)) cycle
                     s = (r%phi(1, 1) + r%phi(2, 2))*exp(r%log_scale)
                     call check(ctx, s, expected, abs=2.0_wp*tols(t)*max(1.0_wp, maxval(abs(r%phi))) + &
                                1.0e-12_wp*max(1.0_wp, abs(expected)), message=one%model%name()//" n = 1 trace")
                  end do
               end do
            end do
         end do
      end do
   end subroutine one_dof_is_scalar_trace

   !> A singular monodromy (Φ = 0 of a damped first-order pair: every multiplier 0, the
   !> exponents −huge) leaves every number of the result finite: ln|λ_max| is −huge, not the
   !> exponent times the period (which overflows), and the verdict is damped, stable.
   subroutine zero_multipliers_finite(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(system_form_t) :: form
      type(floquet_t) :: f
      real(wp) :: phi(2, 2)
      form%n = 2
      form%states = 2
      form%first_order = .true.
      form%hamiltonian = .false.
      form%period = 4.0_wp
      phi = 0.0_wp
      call system_floquet(phi, form, 1.0e-12_wp, f)
      call check(ctx, f%log_modulus(1) == -huge(1.0_wp) .and. f%exponent == -huge(1.0_wp), "ln|lambda_max| = -huge")
      call check(ctx, all(f%exponents == -huge(1.0_wp)), "every exponent -huge")
      call check(ctx, f%verdict == verdict_stable .and. f%kind == kind_damped .and. f%stable, "damped, stable")
      call check(ctx, f%a1 == 0.0_wp .and. f%a2 == 0.0_wp .and. .not. f%overflow, "a1 = a2 = 0")
   end subroutine zero_multipliers_finite

   !> The kinds of system (hillstab_hill_systems): each name makes an empty system of that name,
   !> is known in any case, has a purpose and a template line that starts with it; an unknown name is
   !> refused naming every kind and its purpose.
   subroutine kinds_of_system(ctx)
      type(test_context_t), intent(inout) :: ctx
      class(hill_system_t), allocatable :: system
      type(error_t), allocatable :: error
      integer :: k
      call check(ctx, size(system_names) >= 2, "two kinds at least")
      do k = 1, size(system_names)
         call new_system(" "//trim(system_names(k))//" ", system, error)
         call check(ctx, .not. allocated(error) .and. allocated(system), trim(system_names(k))//": made")
         if (allocated(system)) call check(ctx, system%name() == trim(system_names(k)), &
                                           trim(system_names(k))//": its name")
         call check(ctx, len_trim(system_kinds(k)%purpose) > 10, trim(system_names(k))//": a purpose")
         call check(ctx, index(system_kinds(k)%choice, trim(system_names(k))//": ") == 1, &
                    trim(system_names(k))//": its template line")
      end do
      call check(ctx, is_system_name(" EQUATIONS") .and. is_system_name("System "), "any case, blanks trimmed")
      call check(ctx, .not. is_system_name("elastic"), "elastic is a model")
      call new_system("chain", system, error)
      call check(ctx, allocated(error) .and. .not. allocated(system), "chain refused")
      if (allocated(error)) call check(ctx, error%message == "unknown system 'chain' ("// &
                                       system_kinds_text("", "; ")//")" .and. &
                                       index(error%message, "equations: n coupled equations in physical time") > 0, &
                                       error%message)
   end subroutine kinds_of_system

   !> The one Floquet result by its two routes at the same points of Mathieu's equation, undamped
   !> and damped: from the scalar trace (`floquet_from_trace`, then `complete_from_trace`) and
   !> from the 2 × 2 monodromy of the equation as a system (`system_point`, magnus6). Each route
   !> fills the fields the other's readers take: the verdict and kind, `stable` and `marginal`, the
   !> largest exponent, both multipliers' ln|λ| and |arg λ|, a₁, a₂ and the exponents. The points
   !> reach all three kinds of the undamped equation (stable, at +1 for β < 0, at −1 in the
   !> first tongue) and the damped kind.
   subroutine one_result_two_routes(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(scalar_system_t) :: one
      type(system_form_t) :: form
      type(system_nodes_t) :: nodes
      type(system_monodromy_t) :: r
      type(floquet_t) :: by_trace, by_matrix
      type(trace_t) :: tr
      type(error_t), allocatable :: error
      real(wp), parameter :: alpha = 2.5_wp, betas(6) = [-1.0_wp, 1.0_wp, 2.2_wp, 2.6_wp, 5.0_wp, 14.0_wp]
      real(wp), parameter :: eps(2) = [0.0_wp, 0.3_wp]
      logical :: seen(0:5)
      character(len=:), allocatable :: where
      integer :: i, k, j
      allocate (one%model, source=mathieu_model_t())
      seen = .false.
      do k = 1, size(eps)
         call prepare_system(one, eps(k), form, error)
         call check(ctx, .not. allocated(error), "prepare")
         if (allocated(error)) return
         do i = 1, size(betas)
            where = "beta = "//real_text(betas(i))//", eps = "//real_text(eps(k))
            call monodromy_trace(one%model, hill_point_t(alpha, betas(i), eps(k)), &
                                 method_t(kind=method_magnus6, tolerance=1.0e-13_wp), tr, error)
            call check(ctx, .not. allocated(error), where//": trace")
            if (allocated(error)) cycle
            by_trace = floquet_from_trace(tr, eps(k), 1.0e-13_wp, one%model%period())
            nodes = system_nodes_t()
            call system_point(one, form, alpha, betas(i), system_method_t(system_magnus6, 1.0e-12_wp), nodes, r, &
                              by_matrix, error)
            call check(ctx, .not. allocated(error) .and. r%status == status_ok, where//": system point")
            if (allocated(error)) cycle
            call check(ctx, by_trace%n == 1 .and. by_matrix%n == 1, where//": n = 1")
            call check(ctx, by_trace%verdict == by_matrix%verdict .and. by_trace%kind == by_matrix%kind, &
                       where//": the same verdict and kind")
            call check(ctx, (by_trace%stable .eqv. by_matrix%stable) .and. .not. by_trace%marginal .and. &
                       .not. by_matrix%marginal, where//": the same stable, decided")
            call check(ctx, by_matrix%exponent, by_trace%exponent, abs=1.0e-9_wp, message=where//": exponent")
            do j = 1, 2
               call check(ctx, by_matrix%log_modulus(j), by_trace%log_modulus(j), abs=1.0e-9_wp, &
                          message=where//": ln|lambda_"//real_text(real(j, wp))//"|")
               call check(ctx, abs(by_matrix%argument(j)), abs(by_trace%argument(j)), abs=1.0e-6_wp, &
                          message=where//": |arg lambda_"//real_text(real(j, wp))//"|")
            end do
            call complete_from_trace(by_trace, form)
            call check(ctx, by_trace%a1, by_matrix%a1, abs=1.0e-10_wp*max(1.0_wp, abs(by_matrix%a1)), &
                       message=where//": a1")
            call check(ctx, by_trace%a2, by_matrix%a2, abs=1.0e-10_wp, message=where//": a2")
            call check(ctx, size(by_trace%exponents) == 1 .and. size(by_matrix%exponents) == 1, where//": one exponent")
            if (size(by_trace%exponents) == 1 .and. size(by_matrix%exponents) == 1) &
               call check(ctx, by_trace%exponents(1), by_matrix%exponents(1), abs=1.0e-9_wp, message=where//": mu_1")
            if (by_trace%kind >= 0 .and. by_trace%kind <= 5) seen(by_trace%kind) = .true.
         end do
      end do
      call check(ctx, seen(kind_stable) .and. seen(kind_plus_one) .and. seen(kind_minus_one) .and. seen(kind_damped), &
                 "the points reach stable, +1, -1 and damped")
   end subroutine one_result_two_routes

   !> A diagonal system of three Mathieu equations x_i'' + (b_i β − a_i α cos πτ) x_i = 0 has
   !> the multipliers of each: λ = (S_i ± √(S_i² − 4))/2 with S_i the Mathieu trace at
   !> (a_i α, b_i β).
   subroutine decoupled_multipliers(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(matrix_system_t) :: three
      type(system_form_t) :: form
      type(system_nodes_t) :: nodes
      type(system_monodromy_t) :: r
      type(floquet_t) :: f
      type(trace_t) :: tr
      type(error_t), allocatable :: error
      real(wp) :: a(3) = [1.0_wp, 0.5_wp, 2.0_wp], b(3) = [1.0_wp, 3.0_wp, 0.4_wp], alpha, beta
      complex(wp) :: expected(6), lambda
      integer :: i, k, p
      call three%set_values("n", [3.0_wp], error)
      call three%set_values("b", [b(1), 0.0_wp, 0.0_wp, 0.0_wp, b(2), 0.0_wp, 0.0_wp, 0.0_wp, b(3)], error)
      call three%set_values("cos", -[a(1), 0.0_wp, 0.0_wp, 0.0_wp, a(2), 0.0_wp, 0.0_wp, 0.0_wp, a(3)], error)
      call three%check_values(error)
      call check(ctx, .not. allocated(error), "assembled")
      call prepare_system(three, 0.0_wp, form, error)
      do p = 1, 8
         alpha = 0.3_wp*p
         beta = -0.5_wp + 1.1_wp*p
         do i = 1, 3
            call monodromy_trace(mathieu_model_t(), hill_point_t(a(i)*alpha, b(i)*beta, 0.0_wp), &
                                 method_t(kind=method_magnus6, tolerance=1.0e-13_wp), tr, error)
            lambda = 0.5_wp*(tr%value + sqrt(cmplx(tr%value**2 - 4.0_wp, 0.0_wp, wp)))
            expected(2*i - 1) = lambda
            expected(2*i) = 1.0_wp/lambda
         end do
         call system_monodromy(three, form, alpha, beta, system_method_t(system_auto, 1.0e-11_wp), nodes, r, error)
         call system_floquet(r%phi, form, r%error_estimate*max(1.0_wp, maxval(abs(r%phi))), f, r%log_scale)
         ! every expected multiplier is among the computed ones
         do k = 1, 6
            call check(ctx, minval(abs(f%multipliers*exp(f%log_scale) - expected(k))), 0.0_wp, &
                       abs=1.0e-8_wp*max(1.0_wp, abs(expected(k))), message="decoupled multiplier")
         end do
      end do
   end subroutine decoupled_multipliers

   !> |Φ − Φ_ref| ≤ tol max(1, max|Φ_ref|) at status 0 for one system over a list of points.
   subroutine against_reference(ctx, system, points, eps, methods, tol, n_checked)
      type(test_context_t), intent(inout) :: ctx
      type(matrix_system_t), intent(in) :: system
      real(wp), intent(in) :: points(:, :), eps, tol
      integer, intent(in) :: methods(:)
      integer, intent(inout) :: n_checked
      type(system_form_t) :: form
      type(system_nodes_t) :: nodes
      type(system_monodromy_t) :: r
      type(error_t), allocatable :: error
      real(wp) :: ref(2*system%n, 2*system%n), err
      integer :: k, j
      character(len=120) :: where
      call prepare_system(system, eps, form, error)
      call check(ctx, .not. allocated(error), "prepare")
      do k = 1, size(points, 2)
         call reference_monodromy(system, points(1, k), points(2, k), eps, ref)
         do j = 1, size(methods)
            nodes = system_nodes_t()
            call system_monodromy(system, form, points(1, k), points(2, k), system_method_t(methods(j), tol), nodes, &
                                  r, error)
            write (where, '(a, i0, a, 2es11.3, a, es8.1)') "method ", methods(j), " at ", points(:, k), " eps", eps
            call check(ctx, r%status == status_ok .or. r%status == status_roundoff, trim(where)//": status")
            if (r%status /= status_ok) cycle
            err = maxval(abs(r%phi*exp(r%log_scale) - ref))/max(1.0_wp, maxval(abs(ref)))
            call check(ctx, err, 0.0_wp, abs=tol, message=trim(where)//": error of Phi")
            ! the estimate bounds the error (with a round-off's margin)
            call check(ctx, err <= r%error_estimate + 4.0_wp*epsilon(1.0_wp), trim(where)//": estimate bounds it")
            n_checked = n_checked + 1
         end do
      end do
   end subroutine against_reference

   !> 2-DOF: the pendula pair (Hamiltonian, half period), damped, gyroscopic with sine
   !> terms, large |β|, and near its combination tongue; 84 points, auto and magnus4 at 1e-10,
   !> rk at 1e-9.
   subroutine reference_two_dof(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp) :: points(2, 12), tongue(2, 6), large(2, 4)
      integer :: k, n_checked
      do k = 1, 12
         points(:, k) = [0.15_wp*k, -2.0_wp + 1.2_wp*k]
      end do
      do k = 1, 6
         tongue(:, k) = [0.3_wp, 2.9_wp + 0.03_wp*k]
      end do
      large(:, 1) = [1.0_wp, -40.0_wp]
      large(:, 2) = [3.0_wp, 150.0_wp]
      large(:, 3) = [0.5_wp, 400.0_wp]
      large(:, 4) = [8.0_wp, 30.0_wp]
      n_checked = 0
      call against_reference(ctx, pendula_pair(0.8_wp, 0.1_wp), points, 0.0_wp, [system_auto, system_magnus4], &
                             1.0e-10_wp, n_checked)
      call against_reference(ctx, pendula_pair(0.8_wp, 0.1_wp), tongue, 0.0_wp, [system_auto], 1.0e-10_wp, n_checked)
      call against_reference(ctx, pendula_pair(0.8_wp, 0.1_wp), large, 0.0_wp, [system_auto], 1.0e-10_wp, n_checked)
      call against_reference(ctx, pendula_pair(0.8_wp, 0.1_wp, damping=0.2_wp), points, 0.0_wp, [system_auto], &
                             1.0e-10_wp, n_checked)
      call against_reference(ctx, pendula_pair(0.8_wp, 0.1_wp), points, 0.5_wp, [system_auto], 1.0e-10_wp, n_checked)
      call against_reference(ctx, pendula_pair(0.7_wp, 0.3_wp, gyroscopic=0.6_wp, sine=0.5_wp), points, 0.0_wp, &
                             [system_auto, system_rk], 1.0e-9_wp, n_checked)
      call against_reference(ctx, pendula_pair(0.8_wp, 0.1_wp, damping=0.2_wp), points(:, 1:6), 0.0_wp, [system_gsl], &
                             1.0e-9_wp, n_checked)
      call check(ctx, n_checked >= 80, "at least 80 two-dof comparisons")
   end subroutine reference_two_dof

   !> 3-DOF: a chain with sine terms, damped and gyroscopic; 36 points.
   subroutine reference_three_dof(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp) :: points(2, 12)
      integer :: k, n_checked
      do k = 1, 12
         points(:, k) = [0.25_wp*k, -1.0_wp + 0.9_wp*k]
      end do
      n_checked = 0
      call against_reference(ctx, chain_of_three(0.0_wp, 0.0_wp), points, 0.0_wp, [system_auto], 1.0e-10_wp, &
                             n_checked)
      call against_reference(ctx, chain_of_three(0.1_wp, 0.0_wp), points, 0.0_wp, [system_auto], 1.0e-10_wp, &
                             n_checked)
      call against_reference(ctx, chain_of_three(0.0_wp, 0.4_wp), points, 0.0_wp, [system_magnus6], 1.0e-10_wp, &
                             n_checked)
      call check(ctx, n_checked >= 36, "36 three-dof comparisons")
   end subroutine reference_three_dof

   !> n = 2 Hamiltonian: Broucke's multipliers are Φ's eigenvalues (LAPACK, through the
   !> general path of a 2n = 4 non-Hamiltonian form), and the verdicts agree where both decide.
   subroutine broucke_matches_eigenvalues(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(matrix_system_t) :: pair
      type(system_form_t) :: form, general
      type(system_nodes_t) :: nodes
      type(system_monodromy_t) :: r
      type(floquet_t) :: f, g
      type(error_t), allocatable :: error
      integer :: i, j, k
      real(wp) :: e
      pair = pendula_pair(0.8_wp, 0.1_wp)
      call prepare_system(pair, 0.0_wp, form, error)
      general = form
      general%hamiltonian = .false.
      do i = 1, 6
         do j = 1, 10
            call system_monodromy(pair, form, 0.3_wp*i, 0.8_wp*j, system_method_t(system_auto, 1.0e-11_wp), nodes, &
                                  r, error)
            e = r%error_estimate*max(1.0_wp, maxval(abs(r%phi)))
            call system_floquet(r%phi, form, e, f)
            call system_floquet(r%phi, general, e, g)
            do k = 1, 4
               call check(ctx, minval(abs(g%multipliers - f%multipliers(k))), 0.0_wp, &
                          abs=1.0e-6_wp*max(1.0_wp, abs(f%multipliers(k))), message="Broucke multiplier")
            end do
            if (f%verdict == verdict_unstable .and. g%verdict == verdict_unstable) &
               call check(ctx, f%kind == g%kind, "the same kind")
            call check(ctx, .not. (f%verdict == verdict_unstable .and. g%verdict == verdict_stable), &
                       "no contradiction")
         end do
      end do
   end subroutine broucke_matches_eigenvalues

   !> Where the reference's largest |λ| is off 1 by more than 1e-6 the verdict is never wrong:
   !> unstable points are unstable (and of the reference's kind), and points whose reference
   !> multipliers all lie on the circle and apart are never called unstable.
   subroutine verdicts_with_clear_margin(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(matrix_system_t) :: systems(2)
      type(system_form_t) :: form
      type(system_nodes_t) :: nodes
      type(system_monodromy_t) :: r
      type(floquet_t) :: f, truth
      type(error_t), allocatable :: error
      real(wp) :: ref(6, 6)
      integer :: s, i, j, n, decided, m
      systems(1) = pendula_pair(0.8_wp, 0.1_wp)
      systems(2) = chain_of_three(0.0_wp, 0.0_wp)
      decided = 0
      do s = 1, 2
         n = systems(s)%n
         m = 2*n
         call prepare_system(systems(s), 0.0_wp, form, error)
         do i = 1, 5
            do j = 1, 8
               call reference_monodromy(systems(s), 0.35_wp*i, 0.45_wp*j, 0.0_wp, ref(1:m, 1:m))
               call system_floquet(ref(1:m, 1:m), form, 1.0e-14_wp*max(1.0_wp, maxval(abs(ref(1:m, 1:m)))), truth)
               call system_monodromy(systems(s), form, 0.35_wp*i, 0.45_wp*j, system_method_t(system_auto, 1.0e-10_wp), &
                                     nodes, r, error)
               call system_floquet(r%phi, form, r%error_estimate*max(1.0_wp, maxval(abs(r%phi))), f, r%log_scale)
               if (abs(truth%log_modulus(1)) > 1.0e-6_wp) then
                  call check(ctx, f%verdict == verdict_unstable, "clear instability decided")
                  call check(ctx, f%kind == truth%kind, "its kind")
                  decided = decided + 1
               end if
               if (truth%verdict == verdict_stable) then
                  call check(ctx, f%verdict /= verdict_unstable, "a stable point never unstable")
                  if (f%verdict == verdict_stable) decided = decided + 1
               end if
            end do
         end do
      end do
      call check(ctx, decided >= 60, "most points decided")
   end subroutine verdicts_with_clear_margin

   !> The combination tongue ω₁ + ω₂ = π of the pendula pair at small α: its centre and width
   !> in β against first-order perturbation theory in the modal coordinates
   !> (|π − ω₁ − ω₂| < (α/2) |f₁₂|/√(ω₁ω₂)), the edges found by bisection on Broucke's
   !> discriminant (negative inside); the width ratio tends to 1 as α → 0.
   subroutine combination_tongue_first_order(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(matrix_system_t) :: pair
      type(system_form_t) :: form
      real(wp) :: mu(2), v(2, 2), f12, sum_root, beta_c, half, lo, hi, edges(2), alphas(2), ratio(2), b11, b12, b22
      real(wp) :: l2, c, w1, w2
      type(error_t), allocatable :: prepare_error
      integer :: a, side
      l2 = 0.8_wp
      c = 0.1_wp
      pair = pendula_pair(l2, c)
      call prepare_system(pair, 0.0_wp, form, prepare_error)
      ! M^{-1/2} B M^{-1/2} with M = diag(1, l2²): its eigenvalues mu, eigenvectors u; modes v = M^{-1/2} u
      b11 = 1.0_wp + c
      b12 = -c/l2
      b22 = (l2 + c)/(l2*l2)
      mu(1) = 0.5_wp*(b11 + b22) - sqrt(0.25_wp*(b11 - b22)**2 + b12**2)
      mu(2) = 0.5_wp*(b11 + b22) + sqrt(0.25_wp*(b11 - b22)**2 + b12**2)
      v(:, 1) = [b12, mu(1) - b11]
      v(:, 2) = [b12, mu(2) - b11]
      v(:, 1) = v(:, 1)/norm2(v(:, 1))
      v(:, 2) = v(:, 2)/norm2(v(:, 2))
      v(2, :) = v(2, :)/l2
      ! modal drive f = Vᵀ D V with D = diag(1, l2) (K's drive is −α cos πτ D)
      f12 = v(1, 1)*v(1, 2) + l2*v(2, 1)*v(2, 2)
      sum_root = sqrt(mu(1)) + sqrt(mu(2))
      beta_c = (pi/sum_root)**2
      alphas = [0.02_wp, 0.04_wp]
      do a = 1, 2
         w1 = sqrt(beta_c*mu(1))
         w2 = sqrt(beta_c*mu(2))
         half = (0.5_wp*alphas(a)*abs(f12)/sqrt(w1*w2))/(sum_root/(2.0_wp*sqrt(beta_c)))
         call check(ctx, discriminant(beta_c) < 0.0_wp, "the tongue's centre is unstable")
         do side = 1, 2
            lo = beta_c
            hi = beta_c + merge(-3.0_wp, 3.0_wp, side == 1)*half
            call check(ctx, discriminant(hi) > 0.0_wp, "outside the tongue")
            edges(side) = bisect(lo, hi)
         end do
         ratio(a) = (edges(2) - edges(1))/(2.0_wp*half)
         call check(ctx, ratio(a), 1.0_wp, abs=0.05_wp, message="tongue width / first-order width")
         call check(ctx, 0.5_wp*(edges(1) + edges(2)), beta_c, abs=0.2_wp*half, message="tongue centre")
      end do
      call check(ctx, abs(ratio(1) - 1.0_wp) <= abs(ratio(2) - 1.0_wp) + 1.0e-3_wp, "closer as alpha shrinks")

   contains

      real(wp) function discriminant(beta)
         real(wp), intent(in) :: beta
         type(system_nodes_t) :: nodes
         type(system_monodromy_t) :: r
         type(floquet_t) :: f
         type(error_t), allocatable :: error
         call system_monodromy(pair, form, alphas(a), beta, system_method_t(system_auto, 1.0e-12_wp), nodes, r, error)
         call system_floquet(r%phi, form, r%error_estimate, f, r%log_scale)
         discriminant = f%discriminant
      end function discriminant

      real(wp) function bisect(inside, outside)
         real(wp), intent(in) :: inside, outside
         real(wp) :: x_in, x_out, x
         integer :: k
         x_in = inside
         x_out = outside
         do k = 1, 50
            x = 0.5_wp*(x_in + x_out)
            if (discriminant(x) < 0.0_wp) then
               x_in = x
            else
               x_out = x
            end if
         end do
         bisect = 0.5_wp*(x_in + x_out)
      end function bisect
   end subroutine combination_tongue_first_order

   !> Hamiltonian: ‖ΦᵀΩΦ − Ω‖ at round-off (gyroscopic too); damped: det Φ = e^{P tr D} (Liouville).
   subroutine structure_defects(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(system_form_t) :: form
      type(system_nodes_t) :: nodes
      type(system_monodromy_t) :: r
      type(floquet_t) :: f
      type(error_t), allocatable :: error
      type(matrix_system_t) :: gyro, damped
      gyro = pendula_pair(0.7_wp, 0.3_wp, gyroscopic=0.6_wp, sine=0.5_wp)
      call prepare_system(gyro, 0.0_wp, form, error)
      call check(ctx, form%hamiltonian .and. .not. form%half, "gyroscopic: Hamiltonian, whole period")
      call system_monodromy(gyro, form, 0.8_wp, 2.0_wp, system_method_t(system_auto, 1.0e-11_wp), nodes, r, error)
      call system_floquet(r%phi, form, r%error_estimate, f, r%log_scale)
      call check(ctx, f%defect, 0.0_wp, abs=1.0e-9_wp, message="symplectic defect")
      damped = pendula_pair(0.8_wp, 0.1_wp, damping=0.3_wp)
      call prepare_system(damped, 0.2_wp, form, error)
      call check(ctx, .not. form%hamiltonian, "damped: not Hamiltonian")
      nodes = system_nodes_t()
      call system_monodromy(damped, form, 0.8_wp, 2.0_wp, system_method_t(system_auto, 1.0e-11_wp), nodes, r, error)
      call system_floquet(r%phi, form, r%error_estimate, f, r%log_scale)
      call check(ctx, f%defect, 0.0_wp, abs=1.0e-9_wp, message="Liouville defect")
      call check(ctx, f%verdict == verdict_stable .and. f%kind == kind_damped, "damped and asymptotically stable")
   end subroutine structure_defects

   !> A growth beyond 1e100 over the window keeps Φ scaled (Φ = e^s Φ̃): at α = 0 and β = −3e4
   !> the pendula pair's largest exponent is √(|β| μ_max), μ_max the largest eigenvalue of M⁻¹B,
   !> and the verdict unstable at +1 (real multipliers), whatever the scale.
   subroutine scaled_growth_exponent(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(matrix_system_t) :: pair
      type(system_form_t) :: form
      type(system_nodes_t) :: nodes
      type(system_monodromy_t) :: r
      type(floquet_t) :: f
      type(error_t), allocatable :: error
      real(wp) :: b11, b12, b22, mu_max, beta
      pair = pendula_pair(0.8_wp, 0.1_wp)
      call prepare_system(pair, 0.0_wp, form, error)
      ! M^{-1/2} B M^{-1/2} for M = diag(1, 0.64), B = [[1.1, -0.1], [-0.1, 0.9]]
      b11 = 1.1_wp
      b12 = -0.1_wp/0.8_wp
      b22 = 0.9_wp/0.64_wp
      mu_max = 0.5_wp*(b11 + b22) + sqrt(0.25_wp*(b11 - b22)**2 + b12**2)
      beta = -3.0e4_wp
      call system_monodromy(pair, form, 0.0_wp, beta, system_method_t(system_auto, 1.0e-10_wp), nodes, r, error)
      call check(ctx, .not. allocated(error), "computed")
      if (allocated(error)) return
      call system_floquet(r%phi, form, r%error_estimate*max(1.0_wp, maxval(abs(r%phi))), f, r%log_scale)
      call check(ctx, f%log_scale > 0.0_wp, "kept scaled")
      call check(ctx, f%exponent, sqrt(-beta*mu_max), rel=1.0e-12_wp, message="mu = sqrt(|beta| mu_max)")
      call check(ctx, f%verdict == verdict_unstable .and. f%kind == kind_plus_one, "unstable at +1")
      call check(ctx, f%overflow, "trace clamped with the overflow flag")
   end subroutine scaled_growth_exponent

   !> The analysis of a system of one equation from the scalar trace (`floquet_from_trace`, `complete_from_trace`) at
   !> the extremes, against closed forms: S = 1e305 with εP/2 = 0.1 (tr Φ = e^{−0.1} S is
   !> above 1e300: clamped, with the overflow flag); ln|S| = 710 (S itself overflows) with
   !> εP/2 = 30 (tr Φ = e^{680}, no overflow) and with εP/2 = 0 (clamped); ln|S| = 1000 (the
   !> multipliers kept scaled: ln λ_max = 1000 − εP/2 (λ = S in double), |λ₁ e^{−s}| = 1);
   !> a negative S = −1e305 keeps its sign and is unstable at −1; and S = 1.5 damped is
   !> stable with |λ| = e^{−εP/2}, a₂ = e^{−εP}.
   subroutine trace_form_extremes(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(system_form_t) :: form
      type(floquet_t) :: f
      form%period = 2.0_wp
      ! S = 1e305, eps = 0.1 (decay 0.1): e^{-0.1} 1e305 > 1e300
      f = floquet_from_trace(trace_t(value=1.0e305_wp, log_abs=log(1.0e305_wp)), 0.1_wp, period=2.0_wp)
      call complete_from_trace(f, form)
      call check(ctx, f%a1 == 1.0e300_wp .and. f%overflow, "S = 1e305: tr clamped to 1e300, overflow")
      call check(ctx, f%a2, exp(-0.2_wp), rel=1.0e-15_wp, message="a2 = exp(-eps P)")
      call check(ctx, f%log_modulus(1), log(1.0e305_wp) - 0.1_wp, rel=1.0e-14_wp, &
                 message="ln lambda_max = ln S - eps P/2 (S^2/4 >> 1)")
      call check(ctx, f%verdict == verdict_unstable .and. f%kind == kind_plus_one, "unstable at +1")
      call check(ctx, f%defect == 0.0_wp .and. f%n == 1, "no defect, one degree of freedom")
      ! S itself overflows (ln|S| = 710), decay 30: tr = e^680
      f = floquet_from_trace(trace_t(value=huge(1.0_wp), log_abs=710.0_wp, overflow=.true.), 30.0_wp, period=2.0_wp)
      call complete_from_trace(f, form)
      call check(ctx, f%a1, exp(680.0_wp), rel=1.0e-13_wp, message="ln S = 710, eps P/2 = 30: tr = e^680")
      call check(ctx, .not. f%overflow, "which fits: no overflow")
      call check(ctx, f%a2, exp(-60.0_wp), rel=1.0e-14_wp, message="a2 = exp(-60)")
      f = floquet_from_trace(trace_t(value=huge(1.0_wp), log_abs=710.0_wp, overflow=.true.), 0.0_wp, period=2.0_wp)
      call complete_from_trace(f, form)
      call check(ctx, f%a1 == 1.0e300_wp .and. f%overflow, "undamped: clamped, overflow")
      call check(ctx, f%a2 == 1.0_wp, "a2 = 1 undamped")
      ! ln|S| = 1000: the multipliers scaled by e^{-s}, s = ln lambda_max
      f = floquet_from_trace(trace_t(value=huge(1.0_wp), log_abs=1000.0_wp, overflow=.true.), 0.5_wp, period=2.0_wp)
      call complete_from_trace(f, form)
      call check(ctx, f%log_modulus(1), 1000.0_wp - 0.5_wp, rel=1.0e-15_wp, &
                 message="ln lambda_max = ln S - eps P/2 (lambda = S)")
      call check(ctx, f%log_scale, f%log_modulus(1), rel=1.0e-15_wp, message="scaled by lambda_max")
      call check(ctx, abs(f%multipliers(1)), 1.0_wp, rel=1.0e-13_wp, message="|lambda_1 e^-s| = 1")
      call check(ctx, abs(f%multipliers(2)) < 1.0e-300_wp, "lambda_2 e^-s below any double's range: tiny")
      call check(ctx, f%exponent, f%log_modulus(1)/2.0_wp, rel=1.0e-15_wp, message="mu = ln lambda_max / P")
      call check(ctx, f%a1 == 1.0e300_wp .and. f%overflow, "tr clamped")
      ! a negative S keeps its sign
      f = floquet_from_trace(trace_t(value=-1.0e305_wp, log_abs=log(1.0e305_wp)), 0.1_wp, period=2.0_wp)
      call complete_from_trace(f, form)
      call check(ctx, f%a1 == -1.0e300_wp .and. f%overflow, "S = -1e305: tr = -1e300, overflow")
      call check(ctx, f%verdict == verdict_unstable .and. f%kind == kind_minus_one, "unstable at -1")
      ! a stable damped point: |lambda| = e^{-eps P/2}
      f = floquet_from_trace(trace_t(value=1.5_wp, log_abs=log(1.5_wp)), 0.1_wp, period=2.0_wp)
      call complete_from_trace(f, form)
      call check(ctx, f%a1, 1.5_wp*exp(-0.1_wp), rel=1.0e-15_wp, message="tr = e^{-0.1} 1.5")
      call check(ctx, abs(f%multipliers(1)), exp(-0.1_wp), rel=1.0e-14_wp, message="|lambda_1| = e^{-eps P/2}")
      call check(ctx, abs(f%multipliers(2)), exp(-0.1_wp), rel=1.0e-14_wp, message="|lambda_2| = e^{-eps P/2}")
      call check(ctx, real(f%multipliers(1)*f%multipliers(2)), f%a2, rel=1.0e-14_wp, message="lambda_1 lambda_2 = a2")
      call check(ctx, f%verdict == verdict_stable .and. f%kind == kind_damped .and. .not. f%overflow, &
                 "stable, damped, no overflow")
   end subroutine trace_form_extremes

   !> The checks of a matrix system name the variable: M not symmetric, not positive definite,
   !> G not skew, C not symmetric, a list of the wrong length, n above the limit, a NaN.
   subroutine bad_matrices_named(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(matrix_system_t) :: s
      type(error_t), allocatable :: error
      call expect("mass", [1.0_wp, 0.5_wp, 0.0_wp, 1.0_wp], "mass", "symmetric")
      call expect("mass", [1.0_wp, 2.0_wp, 2.0_wp, 1.0_wp], "mass", "positive definite")
      call expect("gyroscopic", [0.0_wp, 1.0_wp, 1.0_wp, 0.0_wp], "gyroscopic", "skew")
      call expect("damping", [0.0_wp, 1.0_wp, -1.0_wp, 0.0_wp], "damping", "symmetric")
      call expect("k0", [1.0_wp, 2.0_wp, 3.0_wp], "k0", "needs 4 numbers")
      call expect("cos", [1.0_wp, 2.0_wp, 3.0_wp, 4.0_wp, 5.0_wp], "cos", "blocks of 4")
      s = matrix_system_t()
      call s%set_values("n", [21.0_wp], error)
      call check(ctx, allocated(error), "n = 21 refused")
      if (allocated(error)) call check(ctx, index(error%message, "n:") == 1 .and. index(error%message, "20") > 0, &
                                       "names n and the limit: "//error%message)
      call s%set_values("mass", [1.0_wp, ieee_value(1.0_wp, ieee_quiet_nan), 0.0_wp, 1.0_wp], error)
      call check(ctx, allocated(error), "NaN refused")
      if (allocated(error)) call check(ctx, index(error%message, "mass") == 1, "names mass: "//error%message)

   contains

      subroutine expect(variable, values, name, words)
         character(len=*), intent(in) :: variable, name, words
         real(wp), intent(in) :: values(:)
         type(matrix_system_t) :: t
         type(error_t), allocatable :: error
         t = pendula_pair(0.8_wp, 0.1_wp)
         call t%set_values(variable, values, error)
         if (.not. allocated(error)) call t%check_values(error)
         call check(ctx, allocated(error), variable//" refused")
         if (.not. allocated(error)) return
         call check(ctx, index(error%message, name) == 1 .and. index(error%message, words) > 0, &
                    "message names "//name//": "//error%message)
      end subroutine expect
   end subroutine bad_matrices_named

   !> Positive definiteness does not depend on the rows' scales: diag(1e154, 1) and
   !> diag(1e20, 1) are accepted with their exact inverses, [[1e20, 1e10], [1e10, 1 + 1e-6]]
   !> too (its second pivot is 1e-6); [[1, 2], [2, 1]] is refused as not positive definite,
   !> diag(1e-300, 1) and diag(1, 1e308) as out of range, not as indefinite.
   subroutine mass_scales_apart(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp) :: inverse(2, 2)
      logical :: ok, out_of_range
      call cholesky_inverse(reshape([1.0e154_wp, 0.0_wp, 0.0_wp, 1.0_wp], [2, 2]), inverse, ok, out_of_range)
      call check(ctx, ok, "diag(1e154, 1) is positive definite")
      call check(ctx, inverse(1, 1), 1.0e-154_wp, rel=1.0e-15_wp)
      call check(ctx, inverse(2, 2), 1.0_wp, rel=1.0e-15_wp)
      call check(ctx, inverse(1, 2) == 0.0_wp .and. inverse(2, 1) == 0.0_wp, "diagonal inverse")
      call cholesky_inverse(reshape([1.0e20_wp, 0.0_wp, 0.0_wp, 1.0_wp], [2, 2]), inverse, ok, out_of_range)
      call check(ctx, ok, "diag(1e20, 1) is positive definite")
      call cholesky_inverse(reshape([1.0e20_wp, 1.0e10_wp, 1.0e10_wp, 1.0_wp + 1.0e-6_wp], [2, 2]), inverse, ok, &
                            out_of_range)
      call check(ctx, ok, "second pivot 1e-6")
      ! the inverse: [[1 + 1e-6, -1e10], [-1e10, 1e20]]/(1e14)
      call check(ctx, inverse(2, 2), 1.0e6_wp, rel=1.0e-8_wp)
      call check(ctx, inverse(1, 2), -1.0e-4_wp, rel=1.0e-8_wp)
      call cholesky_inverse(reshape([1.0_wp, 2.0_wp, 2.0_wp, 1.0_wp], [2, 2]), inverse, ok, out_of_range)
      call check(ctx, .not. ok .and. .not. out_of_range, "[[1, 2], [2, 1]] is not positive definite")
      call cholesky_inverse(reshape([1.0e-300_wp, 0.0_wp, 0.0_wp, 1.0_wp], [2, 2]), inverse, ok, out_of_range)
      call check(ctx, .not. ok .and. out_of_range, "diag(1e-300, 1) out of range")
      call cholesky_inverse(reshape([1.0_wp, 0.0_wp, 0.0_wp, 1.0e308_wp], [2, 2]), inverse, ok, out_of_range)
      call check(ctx, .not. ok .and. out_of_range, "diag(1, 1e308) out of range")
      call cholesky_inverse(reshape([1.0e-300_wp, 1.0e300_wp, 1.0e300_wp, 1.0_wp], [2, 2]), inverse, ok)
      call check(ctx, .not. ok, "no overflow on [[1e-300, 1e300], [1e300, 1]]")
   end subroutine mass_scales_apart
end module test_system

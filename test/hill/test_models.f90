!> Tests of the model registry (hillstab_hill_models) and of each model's bindings against
!> independent references: the split q = c₀ + c₁ w against Q itself, w from half-angle
!> sines against w, ∫√|w| against quadrature, the two pieces of method formula against
!> Q(0) and Q(1), Hill's method's terms against their closed identities, the α domain,
!> the physical α against eqs. (24) and (21), the witness against a_n(0) = n².
module test_models
   use hillstab_core_kinds, only: wp, pi, pi2
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   use hillstab_core_error, only: error_t
   use hillstab_hill_model, only: hill_model_t, hill_point_t, hill_coefficient, model_split, model_description, &
      check_alpha, check_point, hill_form_pencil
   use hillstab_hill_models, only: model_names, model_count, new_model, model_from_code, model_code, model_names_text
   use hillstab_hill_model_elastic, only: elastic_model_t
   use hillstab_hill_model_mathieu, only: mathieu_model_t
   use hillstab_hill_model_pendulum, only: pendulum_alpha, pendulum_note, is_elastic_pendulum
   use hillstab_hill_units, only: physical_t, equilibrium_length, physical_beta
   use hillstab_testing
   use hillstab_test_models, only: model_of_code
   implicit none
   private
   public :: collect_models

   !> (α, β, ε) of the checks, the same for both models (α plays ν for Mathieu).
   real(wp), parameter :: alphas(5) = [0.0_wp, 1.48_wp, 5.0_wp, 9.5_wp, 9.86_wp]
   real(wp), parameter :: betas(4) = [-30.0_wp, 0.0_wp, 2.47_wp, 40.0_wp]
   real(wp), parameter :: epsilons(2) = [0.0_wp, 0.3_wp]

contains

   function collect_models() result(suite)
      type(testsuite_t) :: suite
      suite = new_testsuite("models", [ &
         new_unittest("table", table), &
         new_unittest("split_is_q", split_is_q), &
         new_unittest("half_sine_shapes", half_sine_shapes), &
         new_unittest("shape_root_mean", shape_root_mean_quadrature), &
         new_unittest("two_pieces_are_q0_q1", two_pieces_are_q0_q1), &
         new_unittest("hill_method_terms", hill_method_terms), &
         new_unittest("alpha_domain", alpha_domain), &
         new_unittest("physical_alpha", physical_alpha_of_models), &
         new_unittest("witness", witness), &
         new_unittest("auto_inputs", auto_inputs)])
   end function collect_models

   !> The registry: codes, names, the texts of messages and headers, the flags.
   subroutine table(ctx)
      type(test_context_t), intent(inout) :: ctx
      class(hill_model_t), allocatable :: model
      type(error_t), allocatable :: error
      type(elastic_model_t) :: elastic
      type(mathieu_model_t) :: mathieu
      integer :: k
      call check(ctx, model_count == 7, "seven models")
      call check(ctx, model_code(elastic) == 1 .and. model_code(mathieu) == 2, "codes of the C API: elastic 1, mathieu 2")
      do k = 1, model_count
         call new_model(model_names(k), model, error)
         call check(ctx, .not. allocated(error), "a model of every registered name")
         if (allocated(error)) return
         call check(ctx, model%name() == trim(model_names(k)) .and. model_code(model) == k, &
            "name and code round trip of "//trim(model_names(k)))
         call model_from_code(k, model, error)
         call check(ctx, model%name() == trim(model_names(k)), "the model of code k")
      end do
      call new_model(" Mathieu ", model, error)
      call check(ctx, .not. allocated(error), "names in any case, blanks trimmed")
      if (.not. allocated(error)) call check(ctx, model%name() == "mathieu", "the Mathieu model by name")
      call new_model("meissner-x", model, error)
      call check(ctx, allocated(error), "unknown name refused")
      if (allocated(error)) call check(ctx, index(error%message, "unknown model 'meissner-x' (expected "// &
         model_names_text()//")") > 0, "message names the models: "//error%message)
      call model_from_code(0, model, error)
      call check(ctx, allocated(error), "code 0 refused")
      call model_from_code(model_count + 1, model, error)
      call check(ctx, allocated(error), "code past the last refused")
      call check(ctx, model_names_text() == "elastic, mathieu, meissner, fourier, sampled, modulated or equation", &
                 "names text: "//model_names_text())
      call check(ctx, model_description(elastic) == "model: elastic, Q(tau) = (beta - alpha cos(pi tau))/"// &
         "(1 - (alpha/pi^2) cos(pi tau)), eq. (25)", "elastic header line")
      call check(ctx, model_description(mathieu) == "model: mathieu, q(tau) = beta - alpha cos(pi tau), "// &
         "eq. (A1), alpha playing nu", "mathieu header line")
      call check(ctx, elastic%is_pendulum() .and. .not. mathieu%is_pendulum(), "pendulum flag")
      call check(ctx, mathieu%has_witness() .and. .not. elastic%has_witness(), "witness flag")
      call check(ctx, elastic%physical_note() == "" .and. index(mathieu%physical_note(), "nu") > 0, "physical note")
      call check(ctx, elastic%period() == 2.0_wp .and. mathieu%period() == 2.0_wp, "period 2")
   end subroutine table


   !> c₀ + c₁ w(τ) = q(τ) for every model, with damping; for a model with an offset
   !> (`has_offset`) the rest v = q − c₀ − c₁ w is the same at every β and lies in its range.
   subroutine split_is_q(ctx)
      type(test_context_t), intent(inout) :: ctx
      class(hill_model_t), pointer :: model
      real(wp) :: c0, c1, tau, q, w(1), v, v_first(0:10), v_min, v_max, scale
      integer :: kind, i, j, e, n
      do kind = 1, model_count
         model => model_of_code(kind)
         do i = 1, size(alphas)
            if (.not. model%alpha_valid(alphas(i))) cycle
            call model%offset_range(alphas(i), v_min, v_max)
            do j = 1, size(betas)
               do e = 1, size(epsilons)
                  call model_split(model, alphas(i), betas(j), epsilons(e), c0, c1)
                  do n = 0, 10
                     tau = 0.1_wp*n
                     q = hill_coefficient(model, hill_point_t(alphas(i), betas(j), epsilons(e)), tau)
                     call model%shapes(alphas(i), [tau], w)
                     scale = max(1.0_wp, abs(c0), abs(c1), abs(v_min), abs(v_max))
                     if (.not. model%has_offset()) then
                        call check(ctx, c0 + c1*w(1), q, rel=1.0e-12_wp, abs=1.0e-12_wp*scale, &
                                   message=model%name()//" split")
                        cycle
                     end if
                     v = q - c0 - c1*w(1)
                     call check(ctx, v >= v_min - 1.0e-12_wp*scale .and. v <= v_max + 1.0e-12_wp*scale, &
                                model%name()//" offset inside its range")
                     if (j == 1 .and. e == 1) then
                        v_first(n) = v
                     else
                        call check(ctx, v, v_first(n), abs=1.0e-12_wp*scale, &
                                   message=model%name()//" offset independent of beta")
                     end if
                  end do
               end do
            end do
         end do
      end do
   end subroutine split_is_q

   !> w from s = sin(πτ/2) equals w(τ).
   subroutine half_sine_shapes(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp) :: taus(21), s(21), w(21), direct(21)
      class(hill_model_t), pointer :: model
      integer :: kind, i, n
      taus = [(0.05_wp*n, n = 0, 20)]
      s = sin(0.5_wp*pi*taus)
      do kind = 1, model_count
         model => model_of_code(kind)
         do i = 1, size(alphas)
            call model%shapes_from_half_sines(alphas(i), size(s), s, w)
            call model%shapes(alphas(i), taus, direct)
            do n = 1, size(taus)
               call check(ctx, w(n), direct(n), rel=1.0e-14_wp, abs=1.0e-15_wp, &
                  message=model%name()//" w from sin(pi tau/2)")
            end do
         end do
      end do
   end subroutine half_sine_shapes

   !> ∫₀¹ √|w| by composite Gauss–Legendre quadrature (elastic: equal; Mathieu: a bound).
   subroutine shape_root_mean_quadrature(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp), parameter :: nodes(3) = [0.5_wp - sqrt(15.0_wp)/10, 0.5_wp, 0.5_wp + sqrt(15.0_wp)/10]
      real(wp), parameter :: weights(3) = [5.0_wp, 8.0_wp, 5.0_wp]/18.0_wp
      integer, parameter :: pieces = 4000
      real(wp) :: integral, h, w(3)
      class(hill_model_t), pointer :: model
      integer :: kind, i, p, g
      h = 1.0_wp/pieces
      do kind = 1, model_count
         model => model_of_code(kind)
         do i = 1, size(alphas) - 1   ! α = 9.86: the dip is too narrow for this uniform rule
            integral = 0.0_wp
            do p = 0, pieces - 1
               call model%shapes(alphas(i), (p + nodes)*h, w)
               integral = integral + h*sum(weights*sqrt(abs(w)))
            end do
            select case (model%name())
            case ("elastic")
               call check(ctx, model%shape_root_mean(alphas(i)), integral, rel=1.0e-10_wp, message="elastic AGM")
            case ("meissner")
               call check(ctx, model%shape_root_mean(alphas(i)), integral, rel=1.0e-12_wp, message="meissner: |w| = 1")
            case ("mathieu")
               call check(ctx, model%shape_root_mean(alphas(i)) >= integral, "mathieu: a bound of the integral")
               ! (2/π) ∫₀^{π/2} √cos x dx = Γ(3/4)/(√π Γ(5/4)); the rule converges slowly at the
               ! square-root zero of w at τ = 1/2
               call check(ctx, integral, 0.7627597635018131_wp, rel=1.0e-6_wp, message="mathieu: Gamma(3/4)/(sqrt(pi) Gamma(5/4))")
            case default
               call check(ctx, model%shape_root_mean(alphas(i)) >= integral, model%name()//": a bound of the integral")
            end select
         end do
      end do
   end subroutine shape_root_mean_quadrature

   !> The two pieces of method formula are q(0) and q(P/2) (the paper's sampling (28)).
   subroutine two_pieces_are_q0_q1(ctx)
      type(test_context_t), intent(inout) :: ctx
      class(hill_model_t), pointer :: model
      type(hill_point_t) :: point
      real(wp) :: first, second
      integer :: kind, i, j, e
      do kind = 1, model_count
         model => model_of_code(kind)
         do i = 1, size(alphas) - 1
            do j = 1, size(betas)
               do e = 1, size(epsilons)
                  point = hill_point_t(alphas(i), betas(j), epsilons(e))
                  call model%two_piece_values(point%alpha, point%beta, point%epsilon, first, second)
                  call check(ctx, first, hill_coefficient(model, point, 0.0_wp), rel=1.0e-12_wp, abs=1.0e-12_wp, &
                     message=model%name()//" piece on [0, 1)")
                  call check(ctx, second, hill_coefficient(model, point, 0.5_wp*model%period()), rel=1.0e-12_wp, &
                     abs=1.0e-12_wp, message=model%name()//" piece on the second half period")
               end do
            end do
         end do
      end do
   end subroutine two_pieces_are_q0_q1

   !> coupling(t) = α − kπ²t; the decay ratio r solves k r² − 2r + k = 0 (r < 1), or is 0.
   subroutine hill_method_terms(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp) :: k, r, t
      class(hill_model_t), pointer :: model
      type(elastic_model_t) :: elastic
      integer :: kind, i, n
      do kind = 1, model_count
         model => model_of_code(kind)
         ! (the pencil's terms, of the models that have that form)
         if (model%hill_form() /= hill_form_pencil) cycle
         do i = 1, size(alphas)
            k = model%hill_k(alphas(i))
            do n = 0, 6
               t = (0.5_wp*n)**2
               call check(ctx, model%hill_coupling(alphas(i), t), alphas(i) - k*pi2*t, rel=1.0e-14_wp, &
                  abs=1.0e-13_wp, message=model%name()//" coupling")
            end do
            r = model%fourier_decay(alphas(i))
            if (k > 0.0_wp) then
               call check(ctx, k*r*r - 2.0_wp*r + k, 0.0_wp, abs=1.0e-14_wp, message="decay ratio")
               call check(ctx, r > 0.0_wp .and. r < 1.0_wp, "0 < r < 1")
            else
               call check(ctx, r == 0.0_wp, model%name()//": no geometric decay")
            end if
            call check(ctx, model%hill_one_minus_k(alphas(i)), 1.0_wp - k, rel=1.0e-12_wp, message="1 - k")
         end do
      end do
      call check(ctx, elastic%hill_k(pi2/2) == 0.5_wp, "elastic k = alpha/pi^2")
   end subroutine hill_method_terms

   !> The elastic model takes 0 ≤ α < π² (NaN refused without a trap); Mathieu any finite ν.
   subroutine alpha_domain(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(error_t), allocatable :: error
      type(elastic_model_t) :: elastic
      type(mathieu_model_t) :: mathieu
      real(wp) :: nan
      nan = ieee_value(1.0_wp, ieee_quiet_nan)
      call check(ctx, elastic%alpha_valid(0.0_wp) .and. elastic%alpha_valid(9.869_wp), "elastic: 0 and 9.869 valid")
      call check(ctx, .not. (elastic%alpha_valid(pi2) .or. elastic%alpha_valid(-1.0e-300_wp) &
         .or. elastic%alpha_valid(nan)), "elastic: pi^2, negative, NaN refused")
      call check(ctx, mathieu%alpha_valid(100.0_wp) .and. mathieu%alpha_valid(-5.0_wp) &
         .and. .not. mathieu%alpha_valid(nan), "mathieu: any finite nu")
      call check_alpha(elastic, 10.0_wp, error)
      call check(ctx, allocated(error), "elastic alpha = 10 reported")
      if (allocated(error)) call check(ctx, index(error%message, elastic%alpha_domain()) > 0 .and. &
         index(error%message, "1.0000000000000000E+01") > 0, "message names domain and value: "//error%message)
      call check_alpha(mathieu, 10.0_wp, error)
      call check(ctx, .not. allocated(error), "mathieu nu = 10 accepted")
      call check_point(mathieu, hill_point_t(1.0_wp, nan, 0.0_wp), error)
      call check(ctx, allocated(error), "a NaN beta reported")
   end subroutine alpha_domain

   !> α of a pendulum in SI units: aπ²/ρ (eq. (24)); ν = α(1 − β/π²) (eq. (21)).
   subroutine physical_alpha_of_models(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(physical_t) :: p
      type(elastic_model_t) :: elastic
      type(mathieu_model_t) :: mathieu
      real(wp) :: alpha
      class(hill_model_t), allocatable :: model
      type(error_t), allocatable :: error
      integer :: k
      p = physical_t(r0=0.8_wp, g=9.81_wp, omega=6.0_wp, a=0.3_wp, kappa=0.0_wp)
      alpha = p%a*pi2/equilibrium_length(p)
      call check(ctx, elastic%physical_alpha(p), alpha, rel=1.0e-15_wp, message="elastic alpha")
      call check(ctx, mathieu%physical_alpha(p), alpha*(1.0_wp - physical_beta(p)/pi2), rel=1.0e-14_wp, &
         message="mathieu nu of eq. (21)")
      ! the same through the functions any model answers; a model that is not a form of the
      ! pendulum takes a pi^2/rho, no note, and is not the pendulum
      call check(ctx, pendulum_alpha(mathieu, p), alpha*(1.0_wp - physical_beta(p)/pi2), rel=1.0e-14_wp, &
         message="mathieu nu through pendulum_alpha")
      call check(ctx, pendulum_alpha(elastic, p), alpha, rel=1.0e-15_wp, message="elastic alpha through pendulum_alpha")
      call check(ctx, is_elastic_pendulum(elastic) .and. .not. is_elastic_pendulum(mathieu), "elastic is the pendulum")
      call check(ctx, index(pendulum_note(mathieu), "nu") > 0 .and. pendulum_note(elastic) == "", "notes")
      do k = 3, model_count
         call model_from_code(k, model, error)
         if (allocated(error)) then
            call check(ctx, .false., "model of code "//trim(model_names(k)))
            return
         end if
         call check(ctx, pendulum_alpha(model, p), alpha, rel=1.0e-15_wp, message=trim(model_names(k))//": a pi^2/rho")
         call check(ctx, .not. is_elastic_pendulum(model) .and. pendulum_note(model) == "", &
            trim(model_names(k))//": not the pendulum, no note")
      end do
   end subroutine physical_alpha_of_models

   !> At ν = 0 the Mathieu curves are β = (π²/4) n² (a_n(0) = b_n(0) = n²); the elastic model has no witness.
   subroutine witness(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(elastic_model_t) :: elastic
      type(mathieu_model_t) :: mathieu
      real(wp) :: beta
      logical :: available
      integer :: n
      do n = 0, 4
         call mathieu%witness_beta(n, 1, 0.0_wp, beta, available)
         call check(ctx, available, "a_n witness available")
         call check(ctx, beta, 0.25_wp*pi2*n*n, rel=1.0e-12_wp, abs=1.0e-12_wp, message="a_n(0) = n^2")
      end do
      call mathieu%witness_beta(0, 2, 0.0_wp, beta, available)
      call check(ctx, .not. available, "no b_0")
      call elastic%witness_beta(1, 1, 1.0_wp, beta, available)
      call check(ctx, .not. available .and. beta == 0.0_wp, "elastic: no witness")
   end subroutine witness

   !> Method auto's inputs: the mesh map's κ in [0, 1), 0 where there is no dip; x = −ln(1 − α/π²).
   subroutine auto_inputs(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(elastic_model_t) :: elastic
      type(mathieu_model_t) :: mathieu
      real(wp) :: kappa
      integer :: i
      do i = 1, size(alphas)
         kappa = elastic%mesh_kappa(alphas(i), 0.35_wp)
         call check(ctx, kappa >= 0.0_wp .and. kappa < 1.0_wp, "elastic kappa in [0, 1)")
         call check(ctx, (alphas(i) == 0.0_wp) .eqv. (kappa == 0.0_wp), "elastic kappa 0 only at alpha = 0")
         call check(ctx, exp(-elastic%auto_difficulty(alphas(i))), 1.0_wp - alphas(i)/pi2, rel=1.0e-14_wp)
         call check(ctx, mathieu%mesh_kappa(alphas(i), 0.35_wp) == 0.0_wp, "mathieu: uniform mesh")
      end do
      call check(ctx, elastic%auto_amplitude(5.0_wp, -3.0_wp), 3.0_wp, rel=0.0_wp)
      call check(ctx, mathieu%auto_amplitude(10.0_wp, -3.0_wp), 4.0_wp, rel=1.0e-15_wp)
   end subroutine auto_inputs
end module test_models

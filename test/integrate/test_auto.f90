!> Tests of method auto (hillstab_integrate_auto) against independent references: GSL rk8pd
!> at a tight tolerance over a coarse chart and at the hard points near α → π², the
!> batch path against the point path, error and work against the tolerance, the
!> α = 0 closed form, damping, the Mathieu transition curves (S = ±2), overflow at a
!> huge negative Q, bad input, and the sixth order of the fixed-N Magnus mesh.
module test_auto
   use hillstab_core_kinds, only: wp, pi2
   use hillstab_core_error, only: error_t, err_invalid_parameter, err_accuracy
   use hillstab_core_stats, only: work_stats_t
   use hillstab_hill_transfer, only: trace_t
   use hillstab_integrate_auto, only: trace_auto, trace_auto_batch, auto_plan_t, auto_prepare, fixed_n_trace, &
      trace_auto_screen
   use hillstab_integrate_refine, only: trace_distance
   use hillstab_integrate_monodromy, only: method_t, method_auto, monodromy_trace, monodromy_trace_batch, &
      batch_plan_t, prepare_batch
   use hillstab_integrate_monodromy_gsl, only: trace_gsl
   use hillstab_hill_mathieu, only: mathieu_transition_beta, mathieu_kind_a, mathieu_kind_b
   use hillstab_integrate_monodromy_rk, only: trace_rk
   use hillstab_testing
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite, ieee_value, ieee_quiet_nan
   use hillstab_hill_model, only: hill_model_t, hill_point_t
   use hillstab_hill_model_elastic, only: elastic_model_t
   use hillstab_hill_model_mathieu, only: mathieu_model_t
   use hillstab_hill_models, only: model_from_code
   use hillstab_test_models, only: model_of_code
   implicit none
   private
   public :: collect_auto

   !> Reference tolerance of GSL rk8pd (its attained error is ~1e-14 relative on the chart).
   real(wp), parameter :: reference_tolerance = 1.0e-13_wp

   !> The exact trace at β = 0 (elastic, ε = 0): without gravity the swing x = r(τ) of
   !> the rigidly turned radial orbit solves x'' + Q x = 0 and is 2-periodic, so a
   !> multiplier is 1 and S = 2 for every α. GSL is ill-conditioned there as α → π²
   !> (its condition κ ~ 3e3 at α = 9.8; measured error 8e-11 at α = 9.85).
   real(wp), parameter :: trace_at_beta_zero = 2.0_wp

contains

   function collect_auto() result(suite)
      type(testsuite_t) :: suite
      suite = new_testsuite("auto", [ &
         new_unittest("contract_chart", contract_chart), &
         new_unittest("contract_hard_points", contract_hard_points), &
         new_unittest("beta_zero_parabolic", beta_zero_parabolic), &
         new_unittest("roundoff_floor_reported", roundoff_floor_reported), &
         new_unittest("batch_equals_point", batch_equals_point), &
         new_unittest("tolerance_scaling", tolerance_scaling), &
         new_unittest("alpha_zero_exact", alpha_zero_exact), &
         new_unittest("damping", damping), &
         new_unittest("mathieu_transitions", mathieu_transitions), &
         new_unittest("overflow_finite", overflow_finite), &
         new_unittest("bad_input", bad_input), &
         new_unittest("fixed_n_order", fixed_n_order), &
         new_unittest("nan_inputs_no_trap", nan_inputs_no_trap), &
         new_unittest("roundoff_best_value", roundoff_best_value), &
         new_unittest("screen_bound_grids", screen_bound_grids), &
         new_unittest("screen_huge_traces", screen_huge_traces)])
   end function collect_auto

   !> Error of S relative to max(1, |S_ref|); through ln|S| when either value overflowed
   !> (δ ln|S| is the relative error of S), infinite on a sign mismatch there.
   pure real(wp) function trace_error(tr, reference) result(e)
      type(trace_t), intent(in) :: tr, reference
      if (tr%overflow .or. reference%overflow) then
         e = abs(tr%log_abs - reference%log_abs)
         if (sign(1.0_wp, tr%value) /= sign(1.0_wp, reference%value)) e = huge(1.0_wp)
      else
         e = abs(tr%value - reference%value)/max(1.0_wp, abs(reference%value))
      end if
   end function trace_error

   !> No error, or only err_accuracy: the tolerance lies below the round-off level of the
   !> point and auto says so, returning its best value (whose error is still checked).
   pure logical function succeeded(error)
      type(error_t), allocatable, intent(in) :: error
      succeeded = .not. allocated(error)
      if (allocated(error)) succeeded = error%code == err_accuracy
   end function succeeded

   !> Reference trace by GSL rk8pd at `reference_tolerance`.
   subroutine gsl_reference(model, point, tr, error)
      class(hill_model_t), intent(in) :: model  !! the model
      type(hill_point_t), intent(in) :: point   !! α, β, ε
      type(trace_t), intent(out) :: tr
      type(error_t), allocatable, intent(out) :: error
      type(work_stats_t) :: stats
      call trace_gsl(model, point, reference_tolerance, tr, stats, error)
   end subroutine gsl_reference

   !> The issue's contract: auto at 1e-10 agrees with GSL rk8pd (1e-13) to
   !> 1e-9·max(1, |S|) on a 12 × 12 chart α ∈ [0, 9.85], β ∈ [−2, 12]; and the
   !> stricter claim: the measured error stays within 2 × tolerance.
   subroutine contract_chart(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp), parameter :: tolerance = 1.0e-10_wp
      real(wp), parameter :: alphas(12) = [0.0_wp, 1.0_wp, 2.5_wp, 4.0_wp, 5.5_wp, 7.0_wp, 8.0_wp, 9.0_wp, &
                                           9.5_wp, 9.7_wp, 9.8_wp, 9.85_wp]
      real(wp), parameter :: betas(12) = [-2.0_wp, -1.0_wp, 0.0_wp, 0.6_wp, 1.29_wp, pi2/4, 3.3_wp, 4.5_wp, &
                                          6.0_wp, 8.0_wp, 10.0_wp, 12.0_wp]
      type(trace_t) :: tr, reference
      type(work_stats_t) :: stats
      type(error_t), allocatable :: error
      real(wp) :: e, worst, worst_alpha, worst_beta
      character(len=60) :: label
      integer :: i, j
      worst = 0.0_wp; worst_alpha = 0.0_wp; worst_beta = 0.0_wp
      do i = 1, size(alphas)
         do j = 1, size(betas)
            write (label, '(a,f5.2,a,f6.2)') "alpha = ", alphas(i), " beta = ", betas(j)
            call trace_auto(elastic_model_t(), hill_point_t(alphas(i), betas(j), 0.0_wp), tolerance, tr, stats, error)
            call check(ctx, succeeded(error), "auto succeeds at "//trim(label))
            if (betas(j) == 0.0_wp) then
               reference = trace_t(trace_at_beta_zero, log(trace_at_beta_zero), .false.)
            else
               call gsl_reference(elastic_model_t(), hill_point_t(alphas(i), betas(j), 0.0_wp), reference, error)
               ! (round-off limited at 1e-13 near pi^2: its best value, within its estimate)
               call check(ctx, succeeded(error), "gsl succeeds at "//trim(label))
            end if
            call check(ctx, ieee_is_finite(tr%value) .and. .not. tr%overflow, "finite at "//trim(label))
            e = trace_error(tr, reference)
            call check(ctx, e <= 1.0e-9_wp, "contract 1e-9 at "//trim(label))
            call check(ctx, e <= 2.0_wp*tolerance, "error <= 2 tol at "//trim(label))
            if (e > worst) then
               worst = e; worst_alpha = alphas(i); worst_beta = betas(j)
            end if
         end do
      end do
      write (*, '(4x,a,es9.2,a,f5.2,a,f6.2,a)') "chart, tol 1e-10: max error/tol ", worst/tolerance, &
         " (alpha ", worst_alpha, ", beta ", worst_beta, ")"
   end subroutine contract_chart

   !> The contract at the hard points α ∈ {9.8, 9.85} × β ∈ {−50, 400, 2500}: deep
   !> narrow dip of Q at τ = 0, large |S| or fast oscillation. At β = 2500 GSL rk8pd
   !> fails (status −1: its rerun for the condition drives the epsilon to the 1e-15
   !> floor, which rk8pd cannot meet there); the reference is then hillstab's DOP853
   !> (trace_rk) at 1e-12, which agrees with itself at 1e-14 to 2e-12.
   subroutine contract_hard_points(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp), parameter :: tolerance = 1.0e-10_wp
      real(wp), parameter :: alphas(2) = [9.8_wp, 9.85_wp], betas(3) = [-50.0_wp, 400.0_wp, 2500.0_wp]
      type(trace_t) :: tr, reference
      type(work_stats_t) :: stats
      type(error_t), allocatable :: error
      real(wp) :: e
      character(len=60) :: label
      character(len=3) :: source
      integer :: i, j
      do i = 1, size(alphas)
         do j = 1, size(betas)
            write (label, '(a,f5.2,a,f7.1)') "alpha = ", alphas(i), " beta = ", betas(j)
            call trace_auto(elastic_model_t(), hill_point_t(alphas(i), betas(j), 0.0_wp), tolerance, tr, stats, error)
            call check(ctx, .not. allocated(error), "auto succeeds at "//trim(label))
            call gsl_reference(elastic_model_t(), hill_point_t(alphas(i), betas(j), 0.0_wp), reference, error)
            source = "gsl"
            if (allocated(error)) then
               call trace_rk(elastic_model_t(), hill_point_t(alphas(i), betas(j), 0.0_wp), 1.0e-12_wp, reference, error)
               call check(ctx, .not. allocated(error), "trace_rk succeeds at "//trim(label))
               source = "rk"
            end if
            call check(ctx, ieee_is_finite(tr%value) .and. ieee_is_finite(tr%log_abs), "finite at "//trim(label))
            e = trace_error(tr, reference)
            call check(ctx, e <= 1.0e-9_wp, "contract 1e-9 at "//trim(label))
            call check(ctx, e <= 2.0_wp*tolerance, "error <= 2 tol at "//trim(label))
            write (*, '(4x,a,a,es22.14,a,es9.2,a,i0,a)') trim(label), ": S = ", reference%value, ", error/tol ", &
               e/tolerance, ", steps ", stats%n_steps, " (reference "//trim(source)//")"
         end do
      end do
   end subroutine contract_hard_points

   !> β = 0: S = 2 exactly for every α (see trace_at_beta_zero), up to α = 9.85, at
   !> tolerances 1e-8 and 1e-10 — a closed-form check right where the dip of Q is
   !> deepest and GSL loses digits.
   subroutine beta_zero_parabolic(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp), parameter :: alphas(6) = [0.5_wp, 3.0_wp, 7.0_wp, 9.5_wp, 9.8_wp, 9.85_wp]
      real(wp), parameter :: tolerances(2) = [1.0e-8_wp, 1.0e-10_wp]
      type(trace_t) :: tr
      type(work_stats_t) :: stats
      type(error_t), allocatable :: error
      real(wp) :: worst(size(tolerances)), e
      integer :: i, k
      character(len=40) :: label
      worst = 0.0_wp
      do k = 1, size(tolerances)
         do i = 1, size(alphas)
            write (label, '(a,es8.1,a,f5.2)') "tol ", tolerances(k), " alpha ", alphas(i)
            call trace_auto(elastic_model_t(), hill_point_t(alphas(i), 0.0_wp, 0.0_wp), tolerances(k), tr, stats, error)
            call check(ctx, succeeded(error), "auto succeeds, "//trim(label))
            e = abs(tr%value - trace_at_beta_zero)/trace_at_beta_zero
            call check(ctx, e <= 2.0_wp*tolerances(k), "S = 2 within 2 tol, "//trim(label))
            worst(k) = max(worst(k), e/tolerances(k))
         end do
      end do
      write (*, '(4x,a,2es9.2)') "beta = 0, S = 2: max error/tol at 1e-8, 1e-10:", worst
   end subroutine beta_zero_parabolic

   !> Where round-off, not truncation, limits the accuracy, auto must still meet the
   !> tolerance or say that it cannot (err_integration), never return a value silently
   !> outside it. At β = 0, α → π² the solutions grow by κ ~ 1e3–1e4 inside the period
   !> and cancel to S = 2; in double precision the attainable error of the Magnus product
   !> is then ~1e-11 (α = 9.8) to ~5e-10 (α = 9.86) whatever N (measured with
   !> fixed_n_trace, N = 512 … 65536). The Richardson estimate |S_N − S_{N/2}|/63 divides
   !> that round-off difference by 63 and so accepts it.
   subroutine roundoff_floor_reported(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp), parameter :: cases(2, 4) = reshape([9.8_wp, 1.0e-12_wp, 9.85_wp, 1.0e-12_wp, &
                                                     9.86_wp, 1.0e-12_wp, 9.86_wp, 1.0e-10_wp], [2, 4])
      type(trace_t) :: tr
      type(work_stats_t) :: stats
      type(error_t), allocatable :: error
      real(wp) :: e
      integer :: i
      character(len=80) :: label
      do i = 1, size(cases, 2)
         call trace_auto(elastic_model_t(), hill_point_t(cases(1, i), 0.0_wp, 0.0_wp), cases(2, i), tr, stats, error)
         e = abs(tr%value - trace_at_beta_zero)/trace_at_beta_zero
         write (label, '(a,f5.2,a,es8.1,a,es9.2,a,l1)') "alpha ", cases(1, i), " beta 0 tol ", cases(2, i), &
            ": error/tol ", e/cases(2, i), ", error reported ", allocated(error)
         write (*, '(4x,a)') trim(label)
         call check(ctx, allocated(error) .or. e <= 2.0_wp*cases(2, i), "tolerance met or error reported, "//trim(label))
      end do
   end subroutine roundoff_floor_reported

   !> trace_auto_batch on a row of β equals trace_auto point by point (with and without
   !> a plan), and so does monodromy_trace_batch (with and without prepare_batch).
   !> The paths share meshes; lanes group points differently, and a lane group may take
   !> the general exponential where a single point takes the polynomial, so round-off
   !> differences are allowed (1e-10 relative).
   subroutine batch_equals_point(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp), parameter :: tolerance = 1.0e-10_wp
      real(wp), parameter :: betas(14) = [-50.0_wp, -2.0_wp, -0.5_wp, 0.0_wp, 0.76_wp, 1.29_wp, pi2/4, 3.95_wp, &
                                          6.0_wp, 9.0_wp, pi2, 12.0_wp, 40.0_wp, 400.0_wp]
      real(wp), parameter :: alphas(3) = [3.7_wp, 9.0_wp, 9.8_wp]
      type(trace_t) :: single(size(betas)), batch(size(betas)), planned(size(betas)), dispatched(size(betas)), &
         prepared(size(betas))
      logical :: failed(size(betas))
      type(work_stats_t) :: stats
      type(error_t), allocatable :: error
      type(auto_plan_t) :: plan
      type(batch_plan_t) :: row_plan
      type(method_t) :: method
      type(hill_point_t) :: row
      real(wp) :: worst, e
      integer :: i, j, kind
      class(hill_model_t), pointer :: kind_model
      character(len=40) :: label
      worst = 0.0_wp
      method = method_t(method_auto, tolerance=tolerance)
      do kind = 1, 2   ! the elastic and the Mathieu model
         kind_model => model_of_code(kind)
         do i = 1, size(alphas)
            write (label, '(a,i0,a,f4.1)') "kind ", kind, " alpha ", alphas(i)
            row = hill_point_t(alphas(i), 0.0_wp, 0.0_wp)
            do j = 1, size(betas)
               call trace_auto(kind_model, hill_point_t(alphas(i), betas(j), 0.0_wp), tolerance, single(j), stats, error)
               call check(ctx, .not. allocated(error), "point "//trim(label))
            end do
            call trace_auto_batch(kind_model, alphas(i), 0.0_wp, betas, tolerance, batch, stats, error)
            call check(ctx, .not. allocated(error), "batch "//trim(label))
            call auto_prepare(kind_model, alphas(i), 0.0_wp, betas, tolerance, plan)
            call trace_auto_batch(kind_model, alphas(i), 0.0_wp, betas, tolerance, planned, stats, error, plan)
            call check(ctx, .not. allocated(error), "planned batch "//trim(label))
            call monodromy_trace_batch(kind_model, row, betas, method, dispatched, failed, error)
            call check(ctx, .not. allocated(error) .and. .not. any(failed), "monodromy_trace_batch "//trim(label))
            call prepare_batch(kind_model, row, betas, method, row_plan)
            call monodromy_trace_batch(kind_model, row, betas, method, prepared, failed, error, plan=row_plan)
            call check(ctx, .not. allocated(error) .and. .not. any(failed), "prepared batch "//trim(label))
            do j = 1, size(betas)
               e = max(trace_error(batch(j), single(j)), trace_error(planned(j), single(j)), &
                       trace_error(dispatched(j), single(j)), trace_error(prepared(j), single(j)))
               call check(ctx, e <= 1.0e-10_wp, "batch = point, "//trim(label))
               worst = max(worst, e)
            end do
         end do
      end do
      ! a single-point dispatch goes through the same path
      call monodromy_trace(elastic_model_t(), hill_point_t(9.0_wp, 2.47_wp, 0.0_wp), method, batch(1), error)
      call trace_auto(elastic_model_t(), hill_point_t(9.0_wp, 2.47_wp, 0.0_wp), tolerance, single(1), stats, error)
      call check(ctx, batch(1)%value == single(1)%value, "monodromy_trace(method_auto) = trace_auto")
      write (*, '(4x,a,es9.2)') "batch vs point: max relative difference ", worst
   end subroutine batch_equals_point

   !> At tolerances 1e-4 … 1e-12 the error against GSL stays within 3 × tolerance on a
   !> small grid of both α near 0 and α near π², and the work grows as the tolerance tightens.
   subroutine tolerance_scaling(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp), parameter :: tolerances(4) = [1.0e-4_wp, 1.0e-6_wp, 1.0e-8_wp, 1.0e-12_wp]
      real(wp), parameter :: alphas(4) = [1.0_wp, 5.0_wp, 9.0_wp, 9.8_wp]
      real(wp), parameter :: betas(5) = [-2.0_wp, 1.0_wp, 2.47_wp, 6.0_wp, 12.0_wp]
      type(trace_t) :: tr, reference(size(alphas), size(betas))
      type(work_stats_t) :: stats
      type(error_t), allocatable :: error
      real(wp) :: e, worst(size(tolerances))
      integer :: i, j, k, total_steps(size(tolerances)), n_not_grown
      integer :: steps(size(tolerances), size(alphas), size(betas))
      character(len=60) :: label
      do i = 1, size(alphas)
         do j = 1, size(betas)
            call gsl_reference(elastic_model_t(), hill_point_t(alphas(i), betas(j), 0.0_wp), reference(i, j), error)
            call check(ctx, .not. allocated(error), "gsl reference")
         end do
      end do
      worst = 0.0_wp
      do k = 1, size(tolerances)
         do i = 1, size(alphas)
            do j = 1, size(betas)
               write (label, '(a,es8.1,a,f4.1,a,f5.2)') "tol ", tolerances(k), " alpha ", alphas(i), " beta ", betas(j)
               call trace_auto(elastic_model_t(), hill_point_t(alphas(i), betas(j), 0.0_wp), tolerances(k), tr, stats, error)
               call check(ctx, .not. allocated(error), "auto succeeds, "//trim(label))
               e = trace_error(tr, reference(i, j))
               call check(ctx, e <= 3.0_wp*tolerances(k), "error <= 3 tol, "//trim(label))
               worst(k) = max(worst(k), e/tolerances(k))
               steps(k, i, j) = int(stats%n_steps)
               call check(ctx, stats%n_steps > 0 .and. stats%n_evaluations == 3*stats%n_steps, "work counted")
            end do
         end do
         total_steps(k) = sum(steps(k, :, :))
         write (*, '(4x,a,es8.1,a,es9.2,a,i0)') "tol ", tolerances(k), ": max error/tol ", worst(k), &
            ", total steps ", total_steps(k)
      end do
      do k = 2, size(tolerances)
         call check(ctx, total_steps(k) >= total_steps(k - 1), "total work non-decreasing")
      end do
      ! point by point the work may stall between neighbouring tolerances but must grow
      ! from the loosest to the tightest
      n_not_grown = count(steps(size(tolerances), :, :) <= steps(1, :, :))
      call check(ctx, n_not_grown == 0, "work at 1e-12 exceeds work at 1e-4 at every point")
   end subroutine tolerance_scaling

   !> α = 0: q ≡ β (minus nothing), S = 2 cos(2√β) or 2 cosh(2√−β), for both models.
   subroutine alpha_zero_exact(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp), parameter :: betas(14) = [-400.0_wp, -50.0_wp, -2.0_wp, -1.0e-3_wp, -1.0e-12_wp, 0.0_wp, &
                                          1.0e-12_wp, 0.7_wp, pi2/4, pi2, 37.0_wp, 500.0_wp, 2500.0_wp, 1.0e4_wp]
      type(trace_t) :: tr, batch(size(betas))
      type(work_stats_t) :: stats
      type(error_t), allocatable :: error
      real(wp) :: exact, worst
      integer :: j, kind
      class(hill_model_t), pointer :: kind_model
      character(len=40) :: label
      worst = 0.0_wp
      do kind = 1, 2   ! the elastic and the Mathieu model
         kind_model => model_of_code(kind)
         call trace_auto_batch(kind_model, 0.0_wp, 0.0_wp, betas, 1.0e-6_wp, batch, stats, error)
         call check(ctx, .not. allocated(error), "batch at alpha = 0")
         do j = 1, size(betas)
            write (label, '(a,i0,a,es10.3)') "kind ", kind, " beta ", betas(j)
            if (betas(j) >= 0.0_wp) then
               exact = 2.0_wp*cos(2.0_wp*sqrt(betas(j)))
            else
               exact = 2.0_wp*cosh(2.0_wp*sqrt(-betas(j)))
            end if
            call trace_auto(kind_model, hill_point_t(0.0_wp, betas(j), 0.0_wp), 1.0e-6_wp, tr, stats, error)
            call check(ctx, .not. allocated(error), "auto succeeds, "//trim(label))
            call check(ctx, tr%value, exact, abs=1.0e-13_wp*max(1.0_wp, abs(exact)), message=trim(label))
            call check(ctx, batch(j)%value, exact, abs=1.0e-13_wp*max(1.0_wp, abs(exact)), message="batch "//trim(label))
            call check(ctx, tr%log_abs, log(abs(exact)), abs=1.0e-13_wp, message="ln|S| "//trim(label))
            worst = max(worst, abs(tr%value - exact)/max(1.0_wp, abs(exact)))
         end do
      end do
      write (*, '(4x,a,es9.2)') "alpha = 0: max relative error ", worst
   end subroutine alpha_zero_exact

   !> Damping: auto solves the χ equation (47), q − ε²/4, like GSL on the same model;
   !> at α = 0 also the closed form S₁ = 2 cos(2√(β − ε²/4)).
   subroutine damping(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp), parameter :: tolerance = 1.0e-10_wp
      real(wp), parameter :: epsilons(3) = [0.5_wp, 1.0_wp, 3.0_wp]
      real(wp), parameter :: points(2, 4) = reshape([1.48_wp, 2.47_wp, 5.0_wp, 0.76_wp, 7.88_wp, 3.95_wp, &
                                                     9.8_wp, 12.0_wp], [2, 4])
      type(trace_t) :: tr, reference, undamped
      type(work_stats_t) :: stats
      type(error_t), allocatable :: error
      class(hill_model_t), pointer :: model
      type(hill_point_t) :: point
      real(wp) :: e, worst, exact, q
      integer :: i, k, kind
      class(hill_model_t), pointer :: kind_model
      character(len=60) :: label
      worst = 0.0_wp
      do kind = 1, 2   ! the elastic and the Mathieu model
         kind_model => model_of_code(kind)
         do k = 1, size(epsilons)
            do i = 1, size(points, 2)
               write (label, '(a,i0,a,f4.1,a,f5.2,a,f5.2)') "kind ", kind, " eps ", epsilons(k), " alpha ", &
                  points(1, i), " beta ", points(2, i)
               model => kind_model
               point = hill_point_t(points(1, i), points(2, i), epsilons(k))
               call trace_auto(model, point, tolerance, tr, stats, error)
               call check(ctx, .not. allocated(error), "auto succeeds, "//trim(label))
               call gsl_reference(model, point, reference, error)
               call check(ctx, .not. allocated(error), "gsl succeeds, "//trim(label))
               e = trace_error(tr, reference)
               call check(ctx, e <= 2.0_wp*tolerance, "damped vs gsl, "//trim(label))
               worst = max(worst, e/tolerance)
               ! the damping changes the answer (guards against ε being ignored)
               call trace_auto(kind_model, hill_point_t(points(1, i), points(2, i), 0.0_wp), tolerance, undamped, stats, error)
               call check(ctx, abs(undamped%value - tr%value) > 1.0e-3_wp, "epsilon has an effect, "//trim(label))
            end do
            ! α = 0, β = 2.47: q = β − ε²/4, constant
            q = 2.47_wp - 0.25_wp*epsilons(k)**2
            if (q >= 0.0_wp) then
               exact = 2.0_wp*cos(2.0_wp*sqrt(q))
            else
               exact = 2.0_wp*cosh(2.0_wp*sqrt(-q))
            end if
            call trace_auto(kind_model, hill_point_t(0.0_wp, 2.47_wp, epsilons(k)), tolerance, tr, stats, error)
            call check(ctx, tr%value, exact, abs=1.0e-13_wp*max(1.0_wp, abs(exact)), message="alpha = 0 damped")
         end do
      end do
      write (*, '(4x,a,es9.2)') "damped, tol 1e-10: max error/tol ", worst
   end subroutine damping

   !> Mathieu model on its transition curves β = (π²/4) a_n(2ν/π²), (π²/4) b_n(2ν/π²):
   !> S = +2 for even n, −2 for odd n.
   subroutine mathieu_transitions(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp), parameter :: nus(2) = [0.5_wp, 3.0_wp]
      real(wp) :: beta, expected, worst
      type(trace_t) :: tr
      type(work_stats_t) :: stats
      type(error_t), allocatable :: error
      integer :: n, i, kind
      character(len=60) :: label
      worst = 0.0_wp
      do kind = mathieu_kind_a, mathieu_kind_b
         do n = merge(0, 1, kind == mathieu_kind_a), 3
            do i = 1, size(nus)
               write (label, '(a,a,i0,a,f4.1)') merge("a_", "b_", kind == mathieu_kind_a), "", n, " nu = ", nus(i)
               call mathieu_transition_beta(kind, n, nus(i), beta, error)
               call check(ctx, .not. allocated(error), "transition beta "//trim(label))
               if (allocated(error)) cycle
               expected = merge(2.0_wp, -2.0_wp, mod(n, 2) == 0)
               call trace_auto(mathieu_model_t(), hill_point_t(nus(i), beta, 0.0_wp), 1.0e-12_wp, tr, stats, error)
               call check(ctx, .not. allocated(error), "auto succeeds, "//trim(label))
               call check(ctx, tr%value, expected, abs=1.0e-9_wp, message=trim(label))
               worst = max(worst, abs(tr%value - expected))
            end do
         end do
      end do
      write (*, '(4x,a,es9.2)') "Mathieu transitions, tol 1e-12: max |S - (+-2)| ", worst
   end subroutine mathieu_transitions

   !> α = 9.86, β = −1e5: ln|S| ≈ 2e3, far beyond the range of real64. The result is
   !> flagged as overflowing, or finite, with ln|S| matching trace_rk; never NaN/Inf.
   subroutine overflow_finite(ctx)
      type(test_context_t), intent(inout) :: ctx
      class(hill_model_t), pointer :: model
      type(hill_point_t) :: point
      type(trace_t) :: tr, reference, batch(3)
      type(work_stats_t) :: stats
      type(error_t), allocatable :: error
      model => model_of_code(1)
      point = hill_point_t(9.86_wp, -1.0e5_wp, 0.0_wp)
      call trace_auto(model, point, 1.0e-10_wp, tr, stats, error)
      call check(ctx, .not. allocated(error), "auto succeeds")
      call check(ctx, ieee_is_finite(tr%value) .and. ieee_is_finite(tr%log_abs), "value and ln|S| finite")
      call trace_rk(model, point, 1.0e-10_wp, reference, error)
      call check(ctx, .not. allocated(error), "trace_rk succeeds")
      call check(ctx, tr%overflow .eqv. reference%overflow, "overflow flag as in trace_rk")
      call check(ctx, tr%overflow .or. tr%log_abs < log(huge(1.0_wp)), "flagged or representable")
      call check(ctx, tr%log_abs, reference%log_abs, rel=1.0e-6_wp, message="ln|S| vs trace_rk")
      write (*, '(4x,a,es22.14,a,es22.14,a,l1,a,i0)') "alpha 9.86 beta -1e5: ln|S| ", tr%log_abs, " (rk ", &
         reference%log_abs, "), overflow ", tr%overflow, ", steps ", stats%n_steps
      ! in a batch with ordinary points the others are unaffected
      call trace_auto_batch(elastic_model_t(), 9.86_wp, 0.0_wp, [2.47_wp, -1.0e5_wp, 5.0_wp], 1.0e-10_wp, batch, stats, error)
      call check(ctx, .not. allocated(error), "batch succeeds")
      call check(ctx, all(ieee_is_finite(batch%value)) .and. all(ieee_is_finite(batch%log_abs)), "batch finite")
      call check(ctx, batch(2)%log_abs, reference%log_abs, rel=1.0e-6_wp, message="batch ln|S| vs trace_rk")
      call trace_auto(elastic_model_t(), hill_point_t(9.86_wp, 2.47_wp, 0.0_wp), 1.0e-10_wp, tr, stats, error)
      call check(ctx, trace_error(batch(1), tr) <= 1.0e-10_wp, "neighbour of an overflowing point unaffected")
   end subroutine overflow_finite

   !> Bad input is reported through error_t, never by a crash.
   subroutine bad_input(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp), parameter :: bad_tolerances(4) = [0.0_wp, -1.0e-8_wp, 1.0_wp, 2.0_wp]
      type(trace_t) :: tr, batch(3)
      type(work_stats_t) :: stats
      type(error_t), allocatable :: error
      real(wp) :: nan
      logical :: failed(3)
      integer :: k
      nan = ieee_value(1.0_wp, ieee_quiet_nan)
      call trace_auto(elastic_model_t(), hill_point_t(pi2, 2.0_wp, 0.0_wp), 1.0e-10_wp, tr, stats, error)
      call check(ctx, allocated(error), "alpha = pi**2 rejected")
      if (allocated(error)) call check(ctx, error%code == err_invalid_parameter, "code invalid_parameter")
      call trace_auto(elastic_model_t(), hill_point_t(12.0_wp, 2.0_wp, 0.0_wp), 1.0e-10_wp, tr, stats, error)
      call check(ctx, allocated(error), "alpha > pi**2 rejected")
      call trace_auto(elastic_model_t(), hill_point_t(-0.5_wp, 2.0_wp, 0.0_wp), 1.0e-10_wp, tr, stats, error)
      call check(ctx, allocated(error), "alpha < 0 rejected")
      ! the Mathieu model has no bound on ν
      call trace_auto(mathieu_model_t(), hill_point_t(12.0_wp, 2.0_wp, 0.0_wp), 1.0e-8_wp, tr, stats, error)
      call check(ctx, .not. allocated(error), "mathieu nu = 12 accepted")
      do k = 1, size(bad_tolerances)
         call trace_auto(elastic_model_t(), hill_point_t(5.0_wp, 2.0_wp, 0.0_wp), bad_tolerances(k), tr, stats, error)
         call check(ctx, allocated(error), "bad tolerance rejected")
         if (allocated(error)) call check(ctx, error%code == err_invalid_parameter, "code invalid_parameter")
      end do
      call trace_auto(elastic_model_t(), hill_point_t(5.0_wp, nan, 0.0_wp), 1.0e-10_wp, tr, stats, error)
      call check(ctx, allocated(error), "NaN beta rejected")
      call trace_auto(elastic_model_t(), hill_point_t(nan, 2.0_wp, 0.0_wp), 1.0e-10_wp, tr, stats, error)
      call check(ctx, allocated(error), "NaN alpha rejected")
      call trace_auto(elastic_model_t(), hill_point_t(5.0_wp, 2.0_wp, -1.0_wp), 1.0e-10_wp, tr, stats, error)
      call check(ctx, allocated(error), "negative epsilon rejected")
      call trace_auto_batch(elastic_model_t(), 5.0_wp, 0.0_wp, [1.0_wp, nan, 3.0_wp], 1.0e-10_wp, batch, stats, error)
      call check(ctx, allocated(error), "NaN beta in a batch rejected")
      ! the dispatcher's batch locates the bad point and still computes the others
      call monodromy_trace_batch(elastic_model_t(), hill_point_t(5.0_wp, 0.0_wp, 0.0_wp), [1.0_wp, nan, 3.0_wp], &
         method_t(method_auto, tolerance=1.0e-10_wp), batch, failed, error)
      call check(ctx, allocated(error), "monodromy_trace_batch reports the NaN")
      call check(ctx, (.not. failed(1)) .and. failed(2) .and. (.not. failed(3)), "only the NaN point failed")
      call trace_auto(elastic_model_t(), hill_point_t(5.0_wp, 3.0_wp, 0.0_wp), 1.0e-10_wp, tr, stats, error)
      call check(ctx, batch(3)%value == tr%value, "good point of a failed batch computed")
   end subroutine bad_input

   !> NaN in the tolerance, β or α of auto_prepare/prepare_batch and a NaN tolerance of
   !> trace_auto are reported (or ignored by the plan), not turned into a floating-point
   !> trap: with -ffpe-trap=invalid (the debug build) an ordered comparison with NaN
   !> aborts, so the checks must test ieee_is_nan/ieee_is_finite first (as
   !> check_model and hillstab_integrate_monodromy_gsl do). Last in the suite: where it fails, it aborts.
   subroutine nan_inputs_no_trap(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(trace_t) :: tr, traces(3)
      type(work_stats_t) :: stats
      type(error_t), allocatable :: error
      type(auto_plan_t) :: plan
      type(batch_plan_t) :: row_plan
      logical :: failed(3)
      real(wp) :: nan
      nan = ieee_value(1.0_wp, ieee_quiet_nan)
      call trace_auto(elastic_model_t(), hill_point_t(5.0_wp, 2.0_wp, 0.0_wp), nan, tr, stats, error)
      call check(ctx, allocated(error), "NaN tolerance rejected")
      ! a plan built from bad input is harmless: the batch still validates its input
      call auto_prepare(elastic_model_t(), 5.0_wp, 0.0_wp, [1.0_wp, 2.0_wp], nan, plan)
      call auto_prepare(elastic_model_t(), nan, 0.0_wp, [1.0_wp, 2.0_wp], 1.0e-10_wp, plan)
      call auto_prepare(elastic_model_t(), 5.0_wp, 0.0_wp, [1.0_wp, nan, 3.0_wp], 1.0e-10_wp, plan)
      call trace_auto_batch(elastic_model_t(), 5.0_wp, 0.0_wp, [1.0_wp, nan, 3.0_wp], 1.0e-10_wp, traces, stats, error, plan)
      call check(ctx, allocated(error), "NaN beta rejected with a plan")
      call prepare_batch(elastic_model_t(), hill_point_t(5.0_wp, 0.0_wp, 0.0_wp), [1.0_wp, nan, 3.0_wp], &
         method_t(method_auto, tolerance=1.0e-10_wp), row_plan)
      call monodromy_trace_batch(elastic_model_t(), hill_point_t(5.0_wp, 0.0_wp, 0.0_wp), [1.0_wp, nan, 3.0_wp], &
         method_t(method_auto, tolerance=1.0e-10_wp), traces, failed, error, plan=row_plan)
      call check(ctx, allocated(error) .and. failed(2) .and. .not. (failed(1) .or. failed(3)), &
                 "NaN beta located by monodromy_trace_batch with a plan")
   end subroutine nan_inputs_no_trap

   !> Magnus-6 on the mapped mesh converges at order 6: errors against GSL (1e-14) for
   !> N = 8, 16, 32 at α = 5, β = 2.47 (and a harder α = 9 point with N = 16, 32, 64).
   subroutine fixed_n_order(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp), parameter :: cases(2, 2) = reshape([5.0_wp, 2.47_wp, 9.0_wp, 6.0_wp], [2, 2])
      integer, parameter :: first_n(2) = [8, 16]
      type(trace_t) :: reference
      type(work_stats_t) :: stats
      type(error_t), allocatable :: error
      real(wp) :: errors(3), order
      integer :: i, k, n
      do i = 1, size(cases, 2)
         call trace_gsl(elastic_model_t(), hill_point_t(cases(1, i), cases(2, i), 0.0_wp), 1.0e-14_wp, reference, &
            stats, error)
         call check(ctx, .not. allocated(error), "gsl reference")
         do k = 1, 3
            n = first_n(i)*2**(k - 1)
            errors(k) = abs(fixed_n_trace(elastic_model_t(), cases(1, i), cases(2, i), n) - reference%value)
         end do
         do k = 1, 2
            order = log(errors(k)/errors(k + 1))/log(2.0_wp)
            write (*, '(4x,a,f4.1,a,f5.2,a,i0,a,i0,a,es9.2,a,es9.2,a,f5.2)') "alpha ", cases(1, i), " beta ", &
               cases(2, i), ": N ", first_n(i)*2**(k - 1), " -> ", first_n(i)*2**k, ", errors ", errors(k), " -> ", &
               errors(k + 1), ", observed order ", order
            call check(ctx, order >= 5.5_wp .and. order <= 6.5_wp, "observed order in [5.5, 6.5]")
         end do
         call check(ctx, errors(3) > 100.0_wp*1.0e-14_wp*max(1.0_wp, abs(reference%value)), &
            "errors above the reference's own")
      end do
   end subroutine fixed_n_order

   !> α = 9.869, β = 0 (S = 2 exactly) is round-off limited at tolerance 1e-10: the value
   !> returned is the best double precision allows (measured 2e-8 off; the first value
   !> whose Richardson difference reached the round-off level was 3.9e-7 off), with
   !> err_accuracy and an error estimate that covers the error.
   subroutine roundoff_best_value(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(trace_t) :: tr
      type(work_stats_t) :: stats
      type(error_t), allocatable :: error
      call trace_auto(elastic_model_t(), hill_point_t(9.869_wp, 0.0_wp, 0.0_wp), 1.0e-10_wp, tr, stats, error)
      call check(ctx, allocated(error), "round-off limited")
      if (allocated(error)) call check(ctx, error%code == err_accuracy, "err_accuracy")
      call check(ctx, tr%value, 2.0_wp, abs=1.0e-7_wp, message="S = 2 to the round-off level")
      call check(ctx, abs(tr%value - 2.0_wp)/2.0_wp <= tr%error_estimate, "error within the estimate")
   end subroutine roundoff_best_value

   !> The screening pass of a verdict on 30 × 30 grids: the elastic chart α ∈ [0, 9.8],
   !> β ∈ [−2, 12]; the hard band α ∈ [9.5, π²(1 − 1e-7)], β ∈ [−50, 50]; the band near β = 0,
   !> α up to π²(1 − 1e-9); Mathieu ν ∈ [0, 10], β ∈ [−5, 15]; damped (ε = 0.3); large β
   !> (±1000). At every point the error of the screen's S against auto at 1e-13 lies within
   !> the bound it reports (where that error exceeds 1e-12, the reference's own level), and
   !> most points are settled (their |S| beyond the bound from 2 cosh ε).
   subroutine screen_bound_grids(ctx)
      type(test_context_t), intent(inout) :: ctx
      call grid(elastic_model_t(), 0.0_wp, 9.8_wp, -2.0_wp, 12.0_wp, 0.0_wp, "elastic")
      call grid(elastic_model_t(), 9.5_wp, pi2*(1.0_wp - 1.0e-7_wp), -50.0_wp, 50.0_wp, 0.0_wp, "hard band")
      call grid(elastic_model_t(), 9.3_wp, pi2*(1.0_wp - 1.0e-9_wp), -0.01_wp, 0.01_wp, 0.0_wp, "band near beta = 0")
      call grid(mathieu_model_t(), 0.0_wp, 10.0_wp, -5.0_wp, 15.0_wp, 0.0_wp, "mathieu")
      call grid(elastic_model_t(), 0.0_wp, 9.8_wp, -2.0_wp, 12.0_wp, 0.3_wp, "damped")
      call grid(elastic_model_t(), 0.0_wp, 9.8_wp, -1000.0_wp, 1000.0_wp, 0.0_wp, "large beta")
   contains
      subroutine grid(model, a0, a1, b0, b1, epsilon, name)
         class(hill_model_t), intent(in) :: model
         real(wp), intent(in) :: a0, a1, b0, b1, epsilon
         character(len=*), intent(in) :: name
         integer, parameter :: n = 30
         real(wp) :: alpha, betas(n), e, worst, threshold
         type(trace_t) :: screened(n), reference(n)
         type(work_stats_t) :: stats
         type(error_t), allocatable :: error
         integer :: i, j, n_settled, n_violations
         do j = 1, n
            betas(j) = b0 + (b1 - b0)*(j - 1)/real(n - 1, wp)
         end do
         threshold = 2.0_wp*cosh(epsilon)
         worst = 0.0_wp
         n_settled = 0
         n_violations = 0
         do i = 1, n
            alpha = a0 + (a1 - a0)*(i - 1)/real(n - 1, wp)
            call trace_auto_screen(model, alpha, epsilon, betas, screened, stats, error)
            call check(ctx, .not. allocated(error), name//": screened")
            if (allocated(error)) return
            call trace_auto_batch(model, alpha, epsilon, betas, 1.0e-13_wp, reference, stats, error)
            if (allocated(error)) deallocate (error)   ! round-off limited points: their best values
            do j = 1, n
               e = trace_distance(screened(j), reference(j))
               if (e > 1.0e-12_wp) then
                  worst = max(worst, e/screened(j)%error_estimate)
                  if (e > screened(j)%error_estimate) n_violations = n_violations + 1
               end if
               if (abs(abs(screened(j)%value) - threshold) > max(screened(j)%error_estimate, 1.0e-10_wp)* &
                   max(1.0_wp, abs(screened(j)%value))) n_settled = n_settled + 1
            end do
         end do
         call check(ctx, n_violations == 0, name//": screen errors within their bounds")
         call check(ctx, n_settled >= 9*n*n/10, name//": most points settled by the screen")
         print '(4x,a,a,es9.2,a,i0,a,i0)', name, ": largest error/bound ", worst, ", settled ", n_settled, " of ", n*n
      end subroutine grid
   end subroutine screen_bound_grids
   !> Deeply unstable points (β ≪ 0, |S| between e^300 and 1e300, compared by their
   !> logarithms) get a screen bound below 1, within which auto's S lies: their coarser
   !> meshes' ln|S| is set (it was not, and the bound was huge, sending them to the full pass).
   subroutine screen_huge_traces(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp), parameter :: betas(3) = [-3.0e4_wp, -6.0e4_wp, -1.0e5_wp]
      type(trace_t) :: screened(size(betas)), tr
      type(work_stats_t) :: stats
      type(error_t), allocatable :: error
      integer :: j
      call trace_auto_screen(elastic_model_t(), 1.0_wp, 0.0_wp, betas, screened, stats, error)
      call check(ctx, .not. allocated(error), "screened")
      if (allocated(error)) return
      do j = 1, size(betas)
         call check(ctx, screened(j)%log_abs > 300.0_wp .and. .not. screened(j)%overflow, "|S| beyond e^300")
         call check(ctx, screened(j)%error_estimate < 1.0_wp, "a bound below 1")
         call trace_auto(elastic_model_t(), hill_point_t(1.0_wp, betas(j), 0.0_wp), 1.0e-10_wp, tr, stats, error)
         if (allocated(error)) deallocate (error)
         call check(ctx, trace_distance(tr, screened(j)) <= screened(j)%error_estimate, &
                    "auto's S within the bound")
      end do
   end subroutine screen_huge_traces
end module test_auto

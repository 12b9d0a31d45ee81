!> Tests of the segmented monodromy against an independent fine-step RK4
!> integration: unit determinant, second-order convergence of midpoint and
!> average sampling, the 4/3 pendulum resonance, the damped criterion, and
!> finite results in the hard cases; every exact method at tolerances 1e-8, 1e-10 and 1e-12
!> against the stored high-precision reference at the hard points and at a check set of
!> other points of the same kind (data/reference/hard_set.dat and check_set.dat, made by
!> data/reference/make_reference.py: Taylor series at 50 digits in mpmath, no shared code).
module test_monodromy
   use hillstab_core_kinds, only: wp, pi2
   use hillstab_core_error, only: error_t, err_accuracy
   use hillstab_hill_coefficient
   use hillstab_hill_transfer
   use hillstab_hill_floquet
   use hillstab_integrate_monodromy
   use hillstab_integrate_auto, only: trace_auto_screen
   use hillstab_core_stats, only: work_stats_t
   use hillstab_test_reference, only: rk4_monodromy, value_of
   use hillstab_testing
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use hillstab_hill_model, only: hill_model_t, hill_point_t, model_coefficient_range
   use hillstab_hill_model_elastic, only: elastic_model_t
   use hillstab_hill_model_mathieu, only: mathieu_model_t
   use hillstab_test_models, only: model_of_code
   implicit none
   private
   public :: collect_monodromy

   !> The stored reference tables, relative to the repository root (where fpm test runs):
   !> the hard set, a check set of points of the same kind that no method was tuned on, and
   !> the band β ∈ ±[1e-5, 1e-2] ∪ {0}, α ∈ [9.3, π² − 1e-6] (S near 2 with a nearly
   !> periodic solution, where the error of S is a difference of large contributions), and the
   !> approach to the pivot α = π² − 10^−k, k = 3 … 6, |β| = 1e2 … 1e5 (the deepest dips of Q).
   character(len=*), parameter :: hard_set_files(4) = [character(len=31) :: &
      "data/reference/hard_set.dat", "data/reference/check_set.dat", "data/reference/band_set.dat", &
      "data/reference/pivot_set.dat"]
   !> Tolerances of the hard-set tests (1e-10 is the default of a scene).
   real(wp), parameter :: hard_set_tolerances(3) = [1.0e-8_wp, 1.0e-10_wp, 1.0e-12_wp]
   !> A round-off limited point passes when its error is at most this factor times the
   !> error estimate the method reports with it (the estimate of the round-off level is an
   !> order of magnitude, not a bound).
   real(wp), parameter :: roundoff_factor = 4.0_wp

   !> One point of the reference table.
   type :: reference_point_t
      integer :: model = 1  !! the model's registry code (1 elastic, 2 Mathieu)
      real(wp) :: alpha = 0.0_wp, beta = 0.0_wp
      real(wp) :: sign = 1.0_wp      !! sign of S
      real(wp) :: log_abs = 0.0_wp   !! ln|S|
      real(wp) :: value = 0.0_wp     !! S (0 when |S| > 1e300)
      real(wp) :: ref_error = 0.0_wp !! the reference's own error bound, relative to max(1, |S|)
   end type reference_point_t

contains

   function collect_monodromy() result(suite)
      type(testsuite_t) :: suite
      suite = new_testsuite("monodromy", [ &
         new_unittest("unit_determinant", unit_determinant), &
         new_unittest("damped_determinant", damped_determinant), &
         new_unittest("second_order_convergence", second_order_convergence), &
         new_unittest("resonance_four_thirds", resonance_four_thirds), &
         new_unittest("damped_stable_beyond_paper", damped_stable_beyond_paper), &
         new_unittest("hard_cases_finite", hard_cases_finite), &
         new_unittest("method_dispatch", method_dispatch), &
         new_unittest("method_table_agrees", method_table_agrees), &
         new_unittest("hard_set_auto", hard_set_auto), &
         new_unittest("hard_set_magnus4", hard_set_magnus4), &
         new_unittest("hard_set_magnus6", hard_set_magnus6), &
         new_unittest("hard_set_rk", hard_set_rk), &
         new_unittest("hard_set_gsl", hard_set_gsl), &
         new_unittest("screen_bound_hard_sets", screen_bound_hard_sets), &
         new_unittest("pivot_scan_every_method", pivot_scan_every_method), &
         new_unittest("verdict_need_every_method", verdict_need_every_method), &
         new_unittest("growth_need", growth_need), &
         new_unittest("bounds_settle_correctly", bounds_settle_correctly)])
   end function collect_monodromy

   subroutine unit_determinant(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp) :: alphas(4) = [0.0_wp, 4.0_wp, 8.0_wp, 9.8_wp], betas(4) = [-2.0_wp, 2.47_wp, 6.0_wp, 12.0_wp]
      integer :: i, j, s
      real(wp) :: m(2, 2)
      do i = 1, 4
         do j = 1, 4
            do s = sampling_endpoint, sampling_average
               m = matrix_of(monodromy_segmented(elastic_model_t(), hill_point_t(alphas(i), betas(j), 0.0_wp), 64, s))
               call check(ctx, determinant(m), 1.0_wp, rel=1.0e-12_wp*max(1.0_wp, maxval(abs(m))**2*1.0e-2_wp))
            end do
         end do
      end do
   end subroutine unit_determinant

   !> The damped swing x'' + εx' + Qx = 0 over one period: det M_x = e^{−2ε}
   !> (Liouville) and tr M_x = e^{−ε} S₁, checked by direct RK4 integration.
   subroutine damped_determinant(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp) :: eps(3) = [0.2_wp, 1.0_wp, 3.0_wp], mx(2, 2), ref(2, 2)
      class(hill_model_t), pointer :: chi_model
      type(hill_point_t) :: chi
      type(hill_point_t) :: bare
      integer :: k
      do k = 1, size(eps)
         chi_model => model_of_code(1)
         chi = hill_point_t(5.0_wp, 1.6_wp, eps(k))
         bare = chi; bare%epsilon = 0.0_wp
         ref = rk4_monodromy(chi_model, bare, eps(k), 20000)
         call check(ctx, determinant(ref), exp(-2*eps(k)), rel=1.0e-10_wp)
         mx = matrix_of(swing_monodromy(monodromy_segmented(chi_model, chi, 8192, sampling_average), eps(k)))
         call check(ctx, determinant(mx), exp(-2*eps(k)), rel=1.0e-12_wp)
         call check(ctx, mx(1, 1) + mx(2, 2), ref(1, 1) + ref(2, 2), rel=1.0e-6_wp, abs=1.0e-6_wp)
         call check(ctx, mx(2, 1), ref(2, 1), rel=1.0e-6_wp, abs=1.0e-6_wp)
      end do
   end subroutine damped_determinant

   !> Midpoint and average sampling are second order as N doubles.
   subroutine second_order_convergence(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp) :: alphas(2) = [2.0_wp, 5.0_wp], betas(2) = [2.47_wp, 6.0_wp], exact, e1, e2, order
      integer :: i, j, s, n
      class(hill_model_t), pointer :: model
      type(hill_point_t) :: point
      character(len=80) :: label
      do i = 1, 2
         do j = 1, 2
            model => model_of_code(1)
            point = hill_point_t(alphas(i), betas(j), 0.0_wp)
            ref: block
               real(wp) :: m(2, 2)
               m = rk4_monodromy(model, point, 0.0_wp, 20000)
               exact = m(1, 1) + m(2, 2)
            end block ref
            do s = sampling_midpoint, sampling_average
               do n = 32, 256, 224
                  e1 = abs(value_of(trace_segmented(model, point, n, s)) - exact)
                  e2 = abs(value_of(trace_segmented(model, point, 2*n, s)) - exact)
                  order = log(e1/e2)/log(2.0_wp)
                  write (label, '(a,f4.1,a,f5.2,a,a,a,i0)') "alpha=", alphas(i), " beta=", betas(j), " ", &
                     sampling_name(s), " N=", n
                  call check(ctx, order, 2.0_wp, abs=0.1_wp, message=trim(label))
               end do
            end do
         end do
      end do
   end subroutine second_order_convergence

   !> β = π²/4 (the 4/3 pendulum) lies in the antiperiodic tongue for every α.
   subroutine resonance_four_thirds(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp) :: alphas(5) = [0.1_wp, 1.0_wp, 4.0_wp, 8.0_wp, 9.5_wp], m(2, 2)
      class(hill_model_t), pointer :: model
      type(hill_point_t) :: point
      type(floquet_t) :: f
      integer :: i
      do i = 1, size(alphas)
         model => model_of_code(1)
         point = hill_point_t(alphas(i), pi2/4, 0.0_wp)
         f = floquet_from_trace(trace_segmented(model, point, 4096, sampling_average), 0.0_wp)
         call check(ctx, .not. f%stable, "segmented unstable")
         call check(ctx, f%trace%value < -2.0_wp, "antiperiodic: S < -2")
         m = rk4_monodromy(model, point, 0.0_wp, 40000)
         call check(ctx, f%trace%value, m(1, 1) + m(2, 2), rel=1.0e-5_wp)
      end do
   end subroutine resonance_four_thirds

   !> ε = 1, α = 5, β = 1.6: |S₁| > 2 yet the swing decays (|S₁| < 2 cosh 1), confirmed
   !> by the spectral radius of the directly integrated damped monodromy.
   subroutine damped_stable_beyond_paper(ctx)
      type(test_context_t), intent(inout) :: ctx
      class(hill_model_t), pointer :: chi_model
      type(hill_point_t) :: chi
      type(hill_point_t) :: bare
      type(floquet_t) :: f
      real(wp) :: m(2, 2), tr, det, radius
      chi_model => model_of_code(1)
      chi = hill_point_t(5.0_wp, 1.6_wp, 1.0_wp)
      f = floquet_from_trace(trace_segmented(chi_model, chi, 8192, sampling_average), chi%epsilon)
      call check(ctx, abs(f%trace%value) > 2.0_wp, "|S1| > 2")
      call check(ctx, f%stable, "stable by |S1| < 2 cosh eps")
      call check(ctx, .not. f%stable_paper, "paper's criterion says unstable")
      bare = chi; bare%epsilon = 0.0_wp
      m = rk4_monodromy(chi_model, bare, 1.0_wp, 20000)
      tr = m(1, 1) + m(2, 2); det = determinant(m)
      radius = (abs(tr) + sqrt(max(tr**2 - 4*det, 0.0_wp)))/2
      if (tr**2 < 4*det) radius = sqrt(det)
      call check(ctx, radius < 1.0_wp, "integrated damped swing decays")
      call check(ctx, log(radius), f%log_modulus(1), rel=1.0e-5_wp)
   end subroutine damped_stable_beyond_paper

   subroutine hard_cases_finite(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp) :: alphas(3) = [9.8_wp, 9.86_wp, 9.8696_wp], betas(4) = [-400.0_wp, 0.0_wp, 3.95_wp, 1.0e4_wp]
      type(floquet_t) :: f
      type(trace_t) :: tr
      integer :: i, j, s
      do i = 1, 3
         do j = 1, 4
            do s = sampling_endpoint, sampling_average
               tr = trace_segmented(elastic_model_t(), hill_point_t(alphas(i), betas(j), 0.0_wp), 512, s)
               f = floquet_from_trace(tr, 0.0_wp)
               call check(ctx, ieee_is_finite(tr%value) .and. ieee_is_finite(tr%log_abs) .and. &
                  ieee_is_finite(f%exponent), "finite")
            end do
            tr = trace_segmented(elastic_model_t(), hill_point_t(alphas(i), betas(j), 0.0_wp), 2, sampling_endpoint)
            call check(ctx, ieee_is_finite(tr%value) .and. ieee_is_finite(tr%log_abs), "finite eq. (37)")
         end do
      end do
      ! q = 0 pieces: β = α makes the first endpoint piece exactly zero
      tr = trace_segmented(elastic_model_t(), hill_point_t(5.0_wp, 5.0_wp, 0.0_wp), 2, sampling_endpoint)
      call check(ctx, ieee_is_finite(tr%value), "zero piece finite")
      ! extreme negative coefficient: the trace overflows and is flagged, exponent finite
      tr = trace_segmented(elastic_model_t(), hill_point_t(9.86_wp, -1.0e6_wp, 0.0_wp), 256, sampling_average)
      f = floquet_from_trace(tr, 0.0_wp)
      call check(ctx, tr%overflow .and. ieee_is_finite(f%exponent) .and. f%exponent > 300.0_wp, "overflow flagged")
   end subroutine hard_cases_finite

   subroutine method_dispatch(ctx)
      type(test_context_t), intent(inout) :: ctx
      class(hill_model_t), pointer :: model
      type(hill_point_t) :: point
      type(trace_t) :: tr
      type(error_t), allocatable :: error
      model => model_of_code(1)
      point = hill_point_t(3.7_wp, 2.47_wp, 0.0_wp)
      call monodromy_trace(model, point, method_t(method_formula), tr, error)
      call check(ctx, .not. allocated(error), "formula works")
      call check(ctx, tr%value, value_of(trace_segmented(model, point, 2, sampling_endpoint)), rel=1.0e-12_wp)
      call monodromy_trace(model, point, method_t(method_segments, 0, sampling_average), tr, error)
      call check(ctx, allocated(error), "n_segments = 0 rejected")
      call monodromy_trace(elastic_model_t(), hill_point_t(10.0_wp, 1.0_wp, 0.0_wp), method_t(method_formula), tr, error)
      call check(ctx, allocated(error), "alpha > pi**2 rejected")
      call check(ctx, method_from_name("magnus6") == method_magnus6 .and. method_from_name("x") == -1, "names")
   end subroutine method_dispatch

   !> What the method table says of each method, against what the method does at one
   !> point (α = 5, β = 2.47; reference S by a fine RK4 of test_reference): the exact
   !> methods meet the tolerance and give an estimate, the others not necessarily and give
   !> −1; the segmented one changes with n_segments and sampling; the names round-trip.
   subroutine method_table_agrees(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp), parameter :: tolerance = 1.0e-9_wp
      class(hill_model_t), pointer :: model
      type(hill_point_t) :: point
      type(trace_t) :: tr, other
      type(error_t), allocatable :: error
      real(wp) :: m(2, 2), reference
      integer :: k
      model => model_of_code(1)
      point = hill_point_t(5.0_wp, 2.47_wp, 0.0_wp)
      m = rk4_monodromy(model, point, 0.0_wp, 40000)
      reference = m(1, 1) + m(2, 2)
      do k = lbound(method_table, 1), ubound(method_table, 1)
         call check(ctx, method_from_name(method_name(k)) == k, "name round trip of "//method_name(k))
         call monodromy_trace(model, point, method_t(k, 64, sampling_average, tolerance), tr, error)
         call check(ctx, .not. allocated(error), method_name(k)//" computes")
         if (method_is_exact(k)) then
            call check(ctx, tr%value, reference, rel=tolerance, abs=tolerance, message=method_name(k)//" meets the tolerance")
         end if
         call check(ctx, method_gives_estimate(k) .eqv. tr%error_estimate >= 0.0_wp, method_name(k)//": estimate or -1")
         call monodromy_trace(model, point, method_t(k, 96, sampling_midpoint, tolerance), other, error)
         call check(ctx, method_uses_segments(k) .eqv. other%value /= tr%value, &
            method_name(k)//": n_segments and sampling used or ignored")
         call check(ctx, method_pieces(method_t(k, 64)) == merge(64, merge(2, 0, k == method_formula), &
            method_uses_segments(k)), method_name(k)//": pieces")
      end do
      call check(ctx, count(method_table%batch_rows) == 1 .and. method_batches_rows(method_auto), "auto batches rows")
      call check(ctx, .not. method_is_exact(-1) .and. method_name(99) == "unknown", "an unknown code offers nothing")
      call check(ctx, method_names_text() == "auto, formula, segments, magnus4, magnus6, rk or gsl", method_names_text())
   end subroutine method_table_agrees

   !> Read the reference table; `ok` false when it cannot be read.
   subroutine read_hard_set(file, points, ok)
      character(len=*), intent(in) :: file
      type(reference_point_t), allocatable, intent(out) :: points(:)
      logical, intent(out) :: ok
      type(reference_point_t) :: p, buffer(200)
      character(len=400) :: line
      integer :: unit, ios, n
      open (newunit=unit, file=file, status="old", action="read", iostat=ios)
      ok = ios == 0
      if (.not. ok) return
      n = 0
      do
         read (unit, '(a)', iostat=ios) line
         if (ios /= 0) exit
         if (line(1:1) == "#" .or. len_trim(line) == 0) cycle
         line = line(1:index(line//"#", "#") - 1)
         read (line, *, iostat=ios) p%model, p%alpha, p%beta, p%sign, p%log_abs, p%value, p%ref_error
         if (ios /= 0) then
            ok = .false.
            exit
         end if
         if (p%model == 0) then
            p%model = 1
         else
            p%model = 2
         end if
         n = n + 1
         buffer(n) = p
      end do
      close (unit)
      points = buffer(:n)
      ok = ok .and. n >= 20
   end subroutine read_hard_set

   !> |S − S_ref|/max(1, |S_ref|), through ln|S| where S is large (or overflows).
   pure real(wp) function reference_error(tr, ref) result(e)
      type(trace_t), intent(in) :: tr
      type(reference_point_t), intent(in) :: ref
      if (ref%log_abs > log(1.0e6_wp)) then
         if (sign(1.0_wp, tr%value) /= ref%sign) then
            e = 2.0_wp
         else
            e = abs(expm1_small(tr%log_abs - ref%log_abs))
         end if
      else
         e = abs(tr%value - ref%value)/max(1.0_wp, abs(ref%value))
      end if
   end function reference_error

   !> e^x − 1, accurate for small x.
   pure real(wp) function expm1_small(x) result(y)
      real(wp), intent(in) :: x
      if (abs(x) < 1.0e-5_wp) then
         y = x*(1.0_wp + 0.5_wp*x)
      else
         y = exp(min(x, 700.0_wp)) - 1.0_wp
      end if
   end function expm1_small

   !> Every point of the hard set, the check set and the band set with method `kind` at each
   !> of `hard_set_tolerances`: no point fails; status ok: error ≤ tolerance, error_estimate
   !> ≤ tolerance and error ≤ error_estimate;
   !> status round-off limited: error ≤ roundoff_factor × error_estimate.
   subroutine check_hard_set(ctx, kind)
      type(test_context_t), intent(inout) :: ctx
      integer, intent(in) :: kind
      type(reference_point_t), allocatable :: points(:)
      type(trace_t) :: tr
      type(error_t), allocatable :: error
      real(wp) :: err, worst_ok, worst_roundoff, worst_estimate, tolerance
      integer :: k, n_roundoff, f, t
      logical :: ok
      character(len=200) :: where
      do f = 1, size(hard_set_files)
         call read_hard_set(trim(hard_set_files(f)), points, ok)
         call check(ctx, ok, "reference table "//trim(hard_set_files(f))//" read")
         if (.not. ok) cycle
         do t = 1, size(hard_set_tolerances)
            tolerance = hard_set_tolerances(t)
            worst_ok = 0.0_wp
            worst_roundoff = 0.0_wp
            worst_estimate = 0.0_wp
            n_roundoff = 0
            do k = 1, size(points)
               call monodromy_trace(model_of_code(points(k)%model), hill_point_t(points(k)%alpha, points(k)%beta, 0.0_wp), &
                                    method_t(kind, tolerance=tolerance), tr, error)
               err = reference_error(tr, points(k))
               write (where, '(a,es8.1,a,i0,a,es10.3,a,es11.3,a)') "tolerance ", tolerance, ", model ", &
                  points(k)%model, " alpha ", points(k)%alpha, " beta ", points(k)%beta, ": "
               if (allocated(error)) then
                  if (error%code /= err_accuracy) then
                     call check(ctx, .false., trim(where)//" fails: "//error%message)
                     cycle
                  end if
                  n_roundoff = n_roundoff + 1
                  worst_roundoff = max(worst_roundoff, err/tr%error_estimate)
                  worst_estimate = max(worst_estimate, tr%error_estimate)
                  call check(ctx, err <= roundoff_factor*tr%error_estimate, trim(where)// &
                             " round-off limited, error "//real_text(err)//" above "//real_text(roundoff_factor)// &
                             " x its estimate "//real_text(tr%error_estimate))
               else
                  worst_ok = max(worst_ok, err)
                  call check(ctx, err <= tolerance, trim(where)//" error "//real_text(err)//" > tolerance")
                  call check(ctx, err <= tr%error_estimate, &
                             trim(where)//" error "//real_text(err)//" above its estimate "//real_text(tr%error_estimate))
                  call check(ctx, tr%error_estimate >= 0.0_wp .and. tr%error_estimate <= tolerance, &
                             trim(where)//" error estimate "//real_text(tr%error_estimate)//" outside [0, tolerance]")
               end if
            end do
            print '(4x,a,a,es8.1,a,f6.3,a,i0,a,i0,a,f6.3,a,es9.2)', trim(hard_set_files(f)(16:)), " tol", tolerance, &
               ": worst error/tol (status 0) ", worst_ok/tolerance, "; round-off limited ", n_roundoff, " of ", &
               size(points), ", worst error/estimate ", worst_roundoff, ", largest estimate ", worst_estimate
         end do
      end do
   end subroutine check_hard_set

   !> The approach to the pivot, α = π² − 10^−k (k = 3 … 8) against β = ±1e2, ±1e4, ±3e4, ±1e5
   !> and the point (1 − α/π² = 1e-8, β = −66515.8) where auto's mapped mesh needed more than
   !> 2^18 steps: every exact method at 1e-10 and 1e-12 returns a value with status 0 or 1
   !> (auto failed at 13 of 88 such points before it handed them to adaptive Magnus-6), and
   !> the methods' values agree within the sum of their estimates (relative to max(1, |S|),
   !> through ln|S| beyond 1e6).
   subroutine pivot_scan_every_method(ctx)
      type(test_context_t), intent(inout) :: ctx
      integer, parameter :: kinds(5) = [method_auto, method_magnus4, method_magnus6, method_rk, method_gsl]
      real(wp), parameter :: betas(8) = [-1.0e5_wp, -3.0e4_wp, -1.0e4_wp, -1.0e2_wp, 1.0e2_wp, 1.0e4_wp, &
                                         3.0e4_wp, 1.0e5_wp]
      real(wp), parameter :: tolerances(2) = [1.0e-10_wp, 1.0e-12_wp]
      real(wp) :: alphas(49), bs(49), gap, tolerance
      type(trace_t) :: tr(5)
      type(error_t), allocatable :: error
      character(len=160) :: where
      integer :: k, i, n, m, t, n_failed
      n = 0
      do k = 3, 8
         do i = 1, size(betas)
            n = n + 1
            alphas(n) = pi2 - 10.0_wp**(-k)
            bs(n) = betas(i)
         end do
      end do
      n = n + 1
      alphas(n) = 9.869604301014792_wp
      bs(n) = -66515.82489436984_wp
      do t = 1, size(tolerances)
         tolerance = tolerances(t)
         n_failed = 0
         do i = 1, n
            write (where, '(a,es8.1,a,es23.16,a,es11.4,a)') "tolerance ", tolerance, ", alpha ", alphas(i), &
               " beta ", bs(i), ": "
            do m = 1, size(kinds)
               call monodromy_trace(elastic_model_t(), hill_point_t(alphas(i), bs(i), 0.0_wp), &
                                    method_t(kinds(m), tolerance=tolerance), tr(m), error)
               if (allocated(error)) then
                  if (error%code /= err_accuracy) n_failed = n_failed + 1
                  call check(ctx, error%code == err_accuracy, trim(where)//method_name(kinds(m))//" fails: "// &
                             error%message)
               end if
            end do
            do m = 2, size(kinds)
               gap = trace_gap(tr(1), tr(m))
               call check(ctx, gap <= tr(1)%error_estimate + tr(m)%error_estimate, trim(where)//"auto and "// &
                          method_name(kinds(m))//" differ by "//real_text(gap)//", beyond their estimates "// &
                          real_text(tr(1)%error_estimate)//", "//real_text(tr(m)%error_estimate))
            end do
         end do
         print '(4x,a,es8.1,a,i0,a,i0,a)', "pivot scan at ", tolerance, ": ", n_failed, " failed of ", &
            n*size(kinds), " (5 methods)"
      end do
   contains
      !> |S_a − S_b|/max(1, |S_b|), through ln|S| beyond 1e6.
      pure real(wp) function trace_gap(a, b) result(g)
         type(trace_t), intent(in) :: a, b
         if (max(abs(a%value), abs(b%value)) > 1.0e6_wp .or. a%overflow .or. b%overflow) then
            g = 2.0_wp
            if (sign(1.0_wp, a%value) == sign(1.0_wp, b%value)) g = abs(expm1_small(a%log_abs - b%log_abs))
         else
            g = abs(a%value - b%value)/max(1.0_wp, abs(b%value))
         end if
      end function trace_gap
   end subroutine pivot_scan_every_method

   pure function real_text(x) result(text)
      real(wp), intent(in) :: x
      character(len=:), allocatable :: text
      character(len=16) :: buffer
      write (buffer, '(es10.3)') x
      text = trim(adjustl(buffer))
   end function real_text

   subroutine hard_set_auto(ctx)
      type(test_context_t), intent(inout) :: ctx
      call check_hard_set(ctx, method_auto)
   end subroutine hard_set_auto

   subroutine hard_set_magnus4(ctx)
      type(test_context_t), intent(inout) :: ctx
      call check_hard_set(ctx, method_magnus4)
   end subroutine hard_set_magnus4

   subroutine hard_set_magnus6(ctx)
      type(test_context_t), intent(inout) :: ctx
      call check_hard_set(ctx, method_magnus6)
   end subroutine hard_set_magnus6

   subroutine hard_set_rk(ctx)
      type(test_context_t), intent(inout) :: ctx
      call check_hard_set(ctx, method_rk)
   end subroutine hard_set_rk

   subroutine hard_set_gsl(ctx)
      type(test_context_t), intent(inout) :: ctx
      call check_hard_set(ctx, method_gsl)
   end subroutine hard_set_gsl

   !> The screening pass of a verdict (auto) at every point of the hard, check and band sets:
   !> the error of its S against the 50-digit reference is within the bound it reports, and
   !> a verdict (need_verdict, tolerance 1e-10) agrees with the reference's wherever the
   !> reference lies farther than 1e-7 from |S| = 2.
   subroutine screen_bound_hard_sets(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(reference_point_t), allocatable :: points(:)
      type(trace_t) :: tr(1)
      type(work_stats_t) :: stats
      type(error_t), allocatable :: error
      logical :: failed(1), ok
      real(wp) :: err, worst, distance
      integer :: i_file, k, n_points, n_marginal
      type(floquet_t) :: f
      character(len=160) :: where
      worst = 0.0_wp
      n_points = 0
      n_marginal = 0
      do i_file = 1, size(hard_set_files)
         call read_hard_set(trim(hard_set_files(i_file)), points, ok)
         call check(ctx, ok, "reference table "//trim(hard_set_files(i_file))//" read")
         if (.not. ok) cycle
         do k = 1, size(points)
            write (where, '(a,i0,a,es10.3,a,es11.3)') "model ", points(k)%model, " alpha ", points(k)%alpha, &
               " beta ", points(k)%beta
            call trace_auto_screen(model_of_code(points(k)%model), points(k)%alpha, 0.0_wp, [points(k)%beta], tr, stats, error)
            call check(ctx, .not. allocated(error), trim(where)//": screened")
            if (allocated(error)) cycle
            n_points = n_points + 1
            err = reference_error(tr(1), points(k))
            worst = max(worst, err/tr(1)%error_estimate)
            call check(ctx, err <= tr(1)%error_estimate, trim(where)//": screen error "//real_text(err)// &
                       " above its bound "//real_text(tr(1)%error_estimate))
            call monodromy_trace_batch(model_of_code(points(k)%model), hill_point_t(points(k)%alpha, 0.0_wp, 0.0_wp), &
               [points(k)%beta], method_t(method_auto, tolerance=1.0e-10_wp), tr, failed, error, need=need_verdict)
            if (failed(1)) then
               call check(ctx, .false., trim(where)//": verdict failed")
               cycle
            end if
            ! where the verdict is not marginal (its error bound does not reach |S| = 2)
            f = floquet_from_trace(tr(1), 0.0_wp, 1.0e-10_wp)
            if (f%marginal) then
               n_marginal = n_marginal + 1
               distance = abs(exp(min(points(k)%log_abs, 1.0_wp)) - 2.0_wp)
               call check(ctx, distance <= 2.0_wp*max(tr(1)%error_estimate, 1.0e-10_wp)*max(1.0_wp, abs(tr(1)%value)) &
                          + reference_error(tr(1), points(k))*max(1.0_wp, abs(tr(1)%value)), &
                          trim(where)//": marginal only within its bound of |S| = 2")
            else
               call check(ctx, f%stable .eqv. points(k)%log_abs < log(2.0_wp), trim(where)//": verdict")
            end if
         end do
      end do
      print '(4x,a,i0,a,es9.2,a,i0)', "screened ", n_points, " reference points: largest error/bound ", worst, &
         "; marginal verdicts ", n_marginal
   end subroutine screen_bound_hard_sets

   !> need_verdict and need_trace give the same verdicts wherever neither is marginal, for
   !> every exact method, on a row across the first tongues (α = 5) and on a row of the hard
   !> band (α = 9.8, β near 0); the verdict does less work (auto: fewer Q evaluations).
   subroutine verdict_need_every_method(ctx)
      type(test_context_t), intent(inout) :: ctx
      integer, parameter :: methods(4) = [method_auto, method_magnus6, method_rk, method_gsl]
      integer, parameter :: n = 41
      real(wp) :: betas(n), alphas(2)
      type(trace_t) :: full(n), verdict(n)
      logical :: failed(n)
      type(error_t), allocatable :: error
      type(work_stats_t) :: work_full, work_verdict
      type(floquet_t) :: f_full, f_verdict
      integer :: m, j, r, n_compared
      alphas = [5.0_wp, 9.8_wp]
      do r = 1, 2
         do j = 1, n
            if (r == 1) then
               betas(j) = -2.0_wp + 14.0_wp*(j - 1)/real(n - 1, wp)
            else
               betas(j) = -0.5_wp + 1.0_wp*(j - 1)/real(n - 1, wp)
            end if
         end do
         do m = 1, size(methods)
            call monodromy_trace_batch(elastic_model_t(), hill_point_t(alphas(r), 0.0_wp, 0.0_wp), betas, &
               method_t(methods(m), tolerance=1.0e-10_wp), full, failed, error, work_full)
            call check(ctx, .not. any(failed), method_name(methods(m))//": full row computed")
            call monodromy_trace_batch(elastic_model_t(), hill_point_t(alphas(r), 0.0_wp, 0.0_wp), betas, &
               method_t(methods(m), tolerance=1.0e-10_wp), verdict, failed, error, work_verdict, need=need_verdict)
            call check(ctx, .not. any(failed), method_name(methods(m))//": verdict row computed")
            n_compared = 0
            do j = 1, n
               f_full = floquet_from_trace(full(j), 0.0_wp, 1.0e-10_wp)
               f_verdict = floquet_from_trace(verdict(j), 0.0_wp, 1.0e-10_wp)
               if (f_full%marginal .or. f_verdict%marginal) cycle
               n_compared = n_compared + 1
               call check(ctx, f_full%stable .eqv. f_verdict%stable, method_name(methods(m))//": same verdict")
            end do
            call check(ctx, n_compared >= n - 2, method_name(methods(m))//": at most two marginal points")
            if (methods(m) == method_auto) call check(ctx, work_verdict%n_evaluations < work_full%n_evaluations/2, &
               "auto: a verdict costs less than half the evaluations of S")
         end do
      end do
   end subroutine verdict_need_every_method

   !> need_growth: where |S| < 2, λ_max = 1 and μ = 0 exactly (as from S computed to the
   !> tolerance), whether the range of q, the screen or S itself settled it; elsewhere S
   !> agrees with need_trace's to the tolerance. Elastic and Mathieu rows, and a damped one
   !> (where λ_max = e^{−ε} below |S| = 2).
   subroutine growth_need(ctx)
      type(test_context_t), intent(inout) :: ctx
      integer, parameter :: n = 41
      real(wp) :: betas(n)
      type(trace_t) :: full(n), growth(n)
      logical :: failed(n)
      type(error_t), allocatable :: error
      type(floquet_t) :: f_full, f_growth
      class(hill_model_t), pointer :: row_model
      type(hill_point_t) :: row
      integer :: j, r, n_exact
      do j = 1, n
         betas(j) = -2.0_wp + 14.0_wp*(j - 1)/real(n - 1, wp)
      end do
      do r = 1, 3
         select case (r)
         case (1)
            row_model => model_of_code(1)
            row = hill_point_t(7.0_wp, 0.0_wp, 0.0_wp)
         case (2)
            row_model => model_of_code(2)
            row = hill_point_t(4.0_wp, 0.0_wp, 0.0_wp)
         case default
            row_model => model_of_code(1)
            row = hill_point_t(7.0_wp, 0.0_wp, 0.4_wp)
         end select
         call monodromy_trace_batch(row_model, row, betas, method_t(method_auto, tolerance=1.0e-10_wp), full, failed, error)
         call monodromy_trace_batch(row_model, row, betas, method_t(method_auto, tolerance=1.0e-10_wp), growth, failed, error, &
                                    need=need_growth)
         n_exact = 0
         do j = 1, n
            f_full = floquet_from_trace(full(j), row%epsilon, 1.0e-10_wp)
            f_growth = floquet_from_trace(growth(j), row%epsilon, 1.0e-10_wp)
            if (abs(full(j)%value) < 2.0_wp .and. .not. f_full%marginal) then
               ! |S| < 2 (settled by the range of q, by the screen, or computed): the
               ! multipliers of x have modulus e^{-epsilon} exactly
               if (growth(j)%error_estimate > 1.0e-10_wp .or. growth(j)%error_estimate == 0.0_wp) &
                  n_exact = n_exact + 1
               call check(ctx, largest_multiplier_modulus(f_growth) == largest_multiplier_modulus(f_full) .and. &
                          f_growth%exponent == f_full%exponent, "lambda_max and mu exact where |S| < 2")
            else
               call check(ctx, growth(j)%value, full(j)%value, abs=2.0e-10_wp*max(1.0_wp, abs(full(j)%value)), &
                          message="S to the tolerance elsewhere")
               call check(ctx, f_growth%exponent, f_full%exponent, abs=1.0e-9_wp, message="mu elsewhere")
            end if
         end do
         call check(ctx, n_exact > 5, "some points settled without S to the tolerance")
      end do
   end subroutine growth_need

   !> What the range of q alone decides (Zhukovskii's criterion, q < 0 throughout) against S
   !> computed by auto at 1e-12: every point declared stable has |S| < 2 and every point
   !> declared unstable S > 2, beyond S's error bound, on grids of the elastic model (β from
   !> −20 to 40, across the bands of q), of the Mathieu model and of the damped χ equation;
   !> and the criterion decides a good share of each grid. Near a band edge (q constant at
   !> (nπ/2)², S = ±2) nothing is declared.
   subroutine bounds_settle_correctly(ctx)
      type(test_context_t), intent(inout) :: ctx
      call sweep(elastic_model_t(), 0.0_wp, 9.8_wp, -20.0_wp, 40.0_wp, 0.0_wp, "elastic")
      call sweep(mathieu_model_t(), 0.0_wp, 20.0_wp, -10.0_wp, 40.0_wp, 0.0_wp, "mathieu")
      call sweep(elastic_model_t(), 0.0_wp, 9.8_wp, -20.0_wp, 40.0_wp, 0.5_wp, "damped")
      ! q ≡ π²/4 (α = 0, β = π²/4): on the edge of the first band, S = −2: undecided
      call check(ctx, bounds_verdict(pi2/4.0_wp, pi2/4.0_wp) == bounds_undecided, "band edge undecided")
      call check(ctx, bounds_verdict(pi2/4.0_wp*(1.0_wp - 1.0e-6_wp), pi2/4.0_wp*(1.0_wp - 1.0e-6_wp)) == &
                 bounds_stable, "just inside the first band")
      call check(ctx, bounds_verdict(-1.0e-3_wp, -1.0e-6_wp) == bounds_unstable, "q < 0 throughout")
      call check(ctx, bounds_verdict(-1.0_wp, 0.5_wp) == bounds_undecided, "q changes sign")
   contains
      subroutine sweep(model, a0, a1, b0, b1, epsilon, name)
         class(hill_model_t), intent(in) :: model
         real(wp), intent(in) :: a0, a1, b0, b1, epsilon
         character(len=*), intent(in) :: name
         integer, parameter :: n = 40
         real(wp) :: alpha, beta, q_min, q_max, bound
         type(trace_t) :: tr
         type(error_t), allocatable :: error
         integer :: i, j, verdict, n_stable, n_unstable
         n_stable = 0
         n_unstable = 0
         do i = 1, n
            alpha = a0 + (a1 - a0)*(i - 1)/real(n - 1, wp)
            do j = 1, n
               beta = b0 + (b1 - b0)*(j - 1)/real(n - 1, wp)
               call model_coefficient_range(model, hill_point_t(alpha, beta, epsilon), q_min, q_max)
               verdict = bounds_verdict(q_min, q_max)
               if (verdict == bounds_undecided) cycle
               call monodromy_trace(model, hill_point_t(alpha, beta, epsilon), method_t(method_auto, &
                                    tolerance=1.0e-12_wp), tr, error)
               if (allocated(error)) deallocate (error)
               bound = max(tr%error_estimate, 1.0e-12_wp)*max(1.0_wp, abs(tr%value))
               if (verdict == bounds_stable) then
                  n_stable = n_stable + 1
                  call check(ctx, abs(tr%value) + bound < 2.0_wp, name//": declared stable, |S| < 2")
               else
                  n_unstable = n_unstable + 1
                  call check(ctx, tr%value - bound > 2.0_wp, name//": declared unstable, S > 2")
               end if
            end do
         end do
         call check(ctx, n_stable + n_unstable > n*n/10, name//": the range decides some points")
         print '(4x,a,a,i0,a,i0,a,i0)', name, ": declared stable ", n_stable, ", unstable ", n_unstable, " of ", n*n
      end subroutine sweep
   end subroutine bounds_settle_correctly
end module test_monodromy

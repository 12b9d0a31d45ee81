!> Tests of the models of the user's own (hillstab_hill_model_fourier,
!> hillstab_hill_model_sampled) against references written here: f = −cos πτ gives Mathieu's
!> characteristic values (GSL's a_n, b_n) to 1e-12; S of drives with several and with 64
!> harmonics, sine terms, periods 2 and 4, |β| up to 1e4 and damping, by every exact method
!> at two tolerances, against a fourth-order Magnus integrator in 80-bit extended precision
!> with Richardson extrapolation written out here (none of the library's integrators); the
!> sampled model equal to the fourier model of the trigonometric polynomial it samples, and
!> its interpolation spectrally accurate for an analytic f; transition values of a drive
!> with sine terms against bisection on that reference; bad scene input refused naming file,
!> group and variable, with no file written.
module test_model_fourier
   use hillstab_core_kinds, only: wp, pi
   use hillstab_core_error, only: error_t, err_accuracy, err_input
   use hillstab_hill_model, only: hill_point_t
   use hillstab_hill_model_fourier, only: fourier_model_t
   use hillstab_hill_model_sampled, only: sampled_model_t
   use hillstab_hill_mathieu, only: mathieu_transition_beta, mathieu_kind_a, mathieu_kind_b
   use hillstab_hill_transfer, only: trace_t
   use hillstab_integrate_monodromy, only: method_t, monodromy_trace, method_auto, method_magnus4, method_magnus6, &
      method_rk, method_gsl, method_name
   use hillstab_curves_hill_method, only: hill_boundary_t
   use hillstab_curves_characteristic, only: characteristic_values
   use hillstab_testing
   use hillstab_test_files, only: run_text_scene
   use hillstab_test_reference, only: auto_row_errors
   use hillstab_test_scratch, only: scratch_prefix, padded, file_exists, write_file, delete_file
   implicit none
   private
   public :: collect_model_fourier

   !> 80-bit extended precision of the reference integrator.
   integer, parameter :: xp = selected_real_kind(18)
   !> The exact methods and the tolerances every one is checked at.
   integer, parameter :: exact_methods(5) = [method_auto, method_magnus4, method_magnus6, method_rk, method_gsl]
   real(wp), parameter :: tolerances(2) = [1.0e-6_wp, 1.0e-10_wp]

   !> A drive f = Σ cₙ cos(2πnτ/P) + sₙ sin(2πnτ/P), as the reference evaluates it.
   type :: drive_t
      real(xp), allocatable :: c(:), s(:)
      real(xp) :: p = 2.0_xp
   end type drive_t

contains

   function collect_model_fourier() result(suite)
      type(testsuite_t) :: suite
      suite = new_testsuite("model_fourier", [ &
         new_unittest("mathieu_characteristic_values", mathieu_characteristic_values), &
         new_unittest("reference_integrator_order", reference_integrator_order), &
         new_unittest("exact_methods_against_reference", exact_methods_against_reference), &
         new_unittest("auto_chart_grid", auto_chart_grid), &
         new_unittest("sampled_equals_fourier", sampled_equals_fourier), &
         new_unittest("sampled_interpolation_spectral", sampled_interpolation_spectral), &
         new_unittest("transition_values_with_sines", transition_values_with_sines), &
         new_unittest("bad_scene_input", bad_scene_input)])
   end function collect_model_fourier

   !> The fourier model of a drive (its coefficients in double precision).
   subroutine model_of(drive, model)
      type(drive_t), intent(in) :: drive
      type(fourier_model_t), intent(out) :: model
      type(error_t), allocatable :: error
      call model%set_values("cos", real(drive%c, wp), error)
      if (.not. allocated(error)) call model%set_values("sin", real(drive%s, wp), error)
      if (.not. allocated(error)) call model%set_values("period", [real(drive%p, wp)], error)
      if (.not. allocated(error)) call model%check_values(error)
      if (allocated(error)) error stop "test_model_fourier: "//error%message
   end subroutine model_of

   !> f(τ) of a drive.
   pure real(xp) function drive_value(drive, tau) result(f)
      type(drive_t), intent(in) :: drive
      real(xp), intent(in) :: tau
      real(xp) :: x, c1, s1, cn, sn, t
      integer :: n
      f = 0.0_xp
      x = 2.0_xp*acos(-1.0_xp)*tau/drive%p
      c1 = cos(x)
      s1 = sin(x)
      cn = c1
      sn = s1
      ! cos nx, sin nx by the rotation (cos x, sin x): no trigonometric call per harmonic
      do n = 1, size(drive%c)
         f = f + drive%c(n)*cn + drive%s(n)*sn
         t = cn*c1 - sn*s1
         sn = sn*c1 + cn*s1
         cn = t
      end do
   end function drive_value

   !> S of χ'' + (β + α f(τ) − ε²/4) χ = 0 over one period: n steps of the fourth-order
   !> Magnus integrator (two Gauss nodes, the commutator term) with the exact exponential of
   !> each traceless 2×2 step, in extended precision.
   real(xp) function magnus4_trace(drive, alpha, beta, epsilon, n) result(s)
      type(drive_t), intent(in) :: drive
      real(xp), intent(in) :: alpha, beta, epsilon
      integer, intent(in) :: n
      real(xp) :: h, t1, t2, q1, q2, qm, d, k2, k, c, sk, e(2, 2), phi(2, 2), omega(2, 2)
      real(xp), parameter :: offset = 0.5_xp/sqrt(3.0_xp)
      integer :: i
      h = drive%p/n
      phi = reshape([1.0_xp, 0.0_xp, 0.0_xp, 1.0_xp], [2, 2])
      do i = 0, n - 1
         t1 = (i + 0.5_xp - offset)*h
         t2 = (i + 0.5_xp + offset)*h
         q1 = beta + alpha*drive_value(drive, t1) - 0.25_xp*epsilon**2
         q2 = beta + alpha*drive_value(drive, t2) - 0.25_xp*epsilon**2
         qm = 0.5_xp*(q1 + q2)
         ! Ω = (h/2)(A₁ + A₂) + (√3/12) h² [A₂, A₁], A = [[0, 1], [−q, 0]]
         d = sqrt(3.0_xp)/12.0_xp*h*h*(q2 - q1)
         omega = reshape([d, -h*qm, h, -d], [2, 2])
         ! Ω² = −det(Ω) I = −k² I with k² = h² q̄ − d²
         k2 = h*h*qm - d*d
         if (k2 > 1.0e-8_xp) then
            k = sqrt(k2)
            c = cos(k)
            sk = sin(k)/k
         else if (k2 < -1.0e-8_xp) then
            k = sqrt(-k2)
            c = cosh(k)
            sk = sinh(k)/k
         else
            c = 1.0_xp - k2/2 + k2*k2/24 - k2**3/720
            sk = 1.0_xp - k2/6 + k2*k2/120 - k2**3/5040
         end if
         e = sk*omega
         e(1, 1) = e(1, 1) + c
         e(2, 2) = e(2, 2) + c
         phi = matmul(e, phi)
      end do
      s = phi(1, 1) + phi(2, 2)
   end function magnus4_trace

   !> The reference S: Richardson's extrapolation of `magnus4_trace` on n and 2n steps.
   real(xp) function reference_trace(drive, alpha, beta, epsilon, n) result(s)
      type(drive_t), intent(in) :: drive
      real(xp), intent(in) :: alpha, beta, epsilon
      integer, intent(in) :: n
      real(xp) :: coarse, fine
      coarse = magnus4_trace(drive, alpha, beta, epsilon, n)
      fine = magnus4_trace(drive, alpha, beta, epsilon, 2*n)
      s = fine + (fine - coarse)/15.0_xp
   end function reference_trace

   !> The three drives of the tests: three harmonics with a sine term over P = 2; 64 decaying
   !> harmonics of both kinds over P = 2; four harmonics over P = 4 (a commensurate
   !> modulation: cos πτ is its second harmonic).
   function test_drive(k) result(drive)
      integer, intent(in) :: k
      type(drive_t) :: drive
      integer :: n
      select case (k)
      case (1)
         drive%c = [1.0_xp, 0.4_xp, 0.0_xp]
         drive%s = [0.0_xp, 0.0_xp, 0.3_xp]
      case (2)
         allocate (drive%c(64), drive%s(64))
         do n = 1, 64
            drive%c(n) = 0.8_xp**n*cos(real(n, xp))
            drive%s(n) = 0.8_xp**n*sin(0.5_xp*n)
         end do
      case default
         drive%c = [0.5_xp, 1.0_xp, 0.0_xp, 0.2_xp]
         drive%s = [0.0_xp, 0.0_xp, 0.25_xp, 0.0_xp]
         drive%p = 4.0_xp
      end select
   end function test_drive

   !> The fourier model with f = −cos πτ is Mathieu's equation with ν = α: its first five
   !> values of each kind at several α equal GSL's (π²/4) a_n(2α/π²) and (π²/4) b_n(2α/π²)
   !> to 1e-12 relative to max(1, |β|).
   subroutine mathieu_characteristic_values(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp), parameter :: alphas(5) = [0.25_wp, 1.0_wp, 4.0_wp, 12.0_wp, 30.0_wp]
      type(fourier_model_t) :: model
      type(hill_boundary_t), allocatable :: values(:)
      type(error_t), allocatable :: error
      real(wp) :: beta_gsl, worst
      integer :: i, k, n_checked
      call model%set_values("cos", [-1.0_wp], error)
      call check(ctx, .not. allocated(error), "f = -cos(pi tau)")
      if (allocated(error)) return
      worst = 0.0_wp
      n_checked = 0
      do i = 1, size(alphas)
         call characteristic_values(model, alphas(i), 5, values, error, tolerance=1.0e-13_wp)
         call check(ctx, .not. allocated(error), "characteristic values at alpha = "//text(alphas(i)))
         if (allocated(error)) return
         call check(ctx, count(values%parity == 1) >= 5 .and. count(values%parity == -1) >= 5, &
                    "five values of each parity (an even drive)")
         do k = 1, size(values)
            if (values(k)%parity == 1) then
               call mathieu_transition_beta(mathieu_kind_a, values(k)%order, alphas(i), beta_gsl, error)
            else
               call mathieu_transition_beta(mathieu_kind_b, values(k)%order, alphas(i), beta_gsl, error)
            end if
            call check(ctx, .not. allocated(error), "GSL's value")
            if (allocated(error)) return
            call check_close(ctx, values(k)%beta, beta_gsl, abs=1.0e-12_wp*max(1.0_wp, abs(beta_gsl)), &
                             message="order "//text(real(values(k)%order, wp))//" at alpha = "//text(alphas(i)))
            call check(ctx, values(k)%trace_sign == merge(2, -2, mod(values(k)%order, 2) == 0), &
                       "even orders periodic, odd antiperiodic")
            worst = max(worst, abs(values(k)%beta - beta_gsl)/max(1.0_wp, abs(beta_gsl)))
            n_checked = n_checked + 1
         end do
      end do
      print '(4x,a,i0,a,es9.2)', "against GSL: ", n_checked, " values, worst relative difference ", worst
   end subroutine mathieu_characteristic_values

   !> The reference integrator converges at its order: Magnus-4's error falls 16× a
   !> halving of the step, and its Richardson value agrees with a run of twice the steps to
   !> far below the tests' tolerances (the reference's own error bound here).
   subroutine reference_integrator_order(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(drive_t) :: drive
      real(xp) :: s1, s2, s4, ratio, r1, r2
      drive = test_drive(1)
      s1 = magnus4_trace(drive, 3.0_xp, 40.0_xp, 0.0_xp, 200)
      s2 = magnus4_trace(drive, 3.0_xp, 40.0_xp, 0.0_xp, 400)
      s4 = magnus4_trace(drive, 3.0_xp, 40.0_xp, 0.0_xp, 800)
      ratio = (s1 - s2)/(s2 - s4)
      call check(ctx, abs(ratio - 16.0_xp) < 1.0_xp, "Magnus-4 error ratio 16 (got "//text(real(ratio, wp))//")")
      r1 = reference_trace(drive, 3.0_xp, 40.0_xp, 0.0_xp, 2000)
      r2 = reference_trace(drive, 3.0_xp, 40.0_xp, 0.0_xp, 4000)
      call check(ctx, abs(r1 - r2) < 1.0e-13_xp*max(1.0_xp, abs(r2)), "Richardson values agree to 1e-13")
   end subroutine reference_integrator_order

   !> S of the three drives at 36 points each (108 in all: α up to 8, β from −500 to 1e4,
   !> a third damped) by every exact method at 1e-6 and 1e-10 against the reference: at
   !> status 0 the error relative to max(1, |S|) is within the tolerance; at status 1
   !> (round-off limited) within four times the estimate.
   subroutine exact_methods_against_reference(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp), parameter :: alphas(3) = [0.5_wp, 3.0_wp, 8.0_wp]
      real(wp), parameter :: betas(6) = [-500.0_wp, -2.0_wp, 1.5_wp, 9.0_wp, 300.0_wp, 1.0e4_wp]
      real(wp), parameter :: epsilons(2) = [0.0_wp, 0.3_wp]
      type(drive_t) :: drive
      type(fourier_model_t) :: model
      type(trace_t) :: tr
      type(error_t), allocatable :: error
      real(wp) :: reference, e, worst(size(exact_methods), size(tolerances)), eps, log_ref
      integer :: d, i, j, m, t, n_steps, n_points, n_roundoff, n_large
      character(len=160) :: label
      worst = 0.0_wp
      n_points = 0
      n_roundoff = 0
      n_large = 0
      do d = 1, 3
         drive = test_drive(d)
         call model_of(drive, model)
         do i = 1, size(alphas)
            do j = 1, size(betas)
               eps = epsilons(1 + mod(i + j, 2))
               if (j == 3 .and. d == 3) eps = 0.0_wp
               ! steps: resolve the drive's top harmonic and the oscillation √|β| over the period
               n_steps = max(400, int(20*size(drive%c)*real(drive%p, wp)), int(8*sqrt(abs(betas(j)))*real(drive%p, wp)))
               reference = real(reference_trace(drive, real(alphas(i), xp), real(betas(j), xp), real(eps, xp), n_steps), wp)
               log_ref = log(max(1.0_wp, abs(reference)))
               if (log_ref > 600.0_wp) cycle
               n_points = n_points + 1
               do m = 1, size(exact_methods)
                  do t = 1, size(tolerances)
                     write (label, '(a,i0,a,es8.1,a,3es11.3)') "drive ", d, " "//method_name(exact_methods(m))//" tol", &
                        tolerances(t), " at", alphas(i), betas(j), eps
                     call monodromy_trace(model, hill_point_t(alphas(i), betas(j), eps), &
                                          method_t(exact_methods(m), tolerance=tolerances(t)), tr, error)
                     e = abs(tr%value - reference)/max(1.0_wp, abs(reference))
                     if (allocated(error)) then
                        call check(ctx, error%code == err_accuracy, trim(label)//": a value (status 1): "//error%message)
                        if (error%code == err_accuracy) then
                           n_roundoff = n_roundoff + 1
                           call check(ctx, e <= 4.0_wp*tr%error_estimate + 1.0e-13_wp, &
                                      trim(label)//": round-off limited, within its estimate")
                        end if
                     else
                        call check(ctx, e <= tolerances(t), trim(label)//": error "//text(e)//" within the tolerance")
                        worst(m, t) = max(worst(m, t), e/tolerances(t))
                     end if
                  end do
               end do
               if (abs(reference) > 1.0e6_wp) n_large = n_large + 1
            end do
         end do
      end do
      call check(ctx, n_points >= 50, "points compared")
      do m = 1, size(exact_methods)
         print '(4x,a8,a,2es9.2)', method_name(exact_methods(m)), ": worst error/tolerance at 1e-6, 1e-10:", worst(m, :)
      end do
      print '(4x,i0,a,i0,a,i0,a)', n_points, " points (", n_large, " with |S| > 1e6), ", n_roundoff, &
         " results round-off limited"
   end subroutine exact_methods_against_reference

   !> Samples of a trigonometric polynomial of degree 3 (16 a period) are that polynomial:
   !> the sampled model's Q equals the fourier model's to rounding at 50 τ, and its S at 30
   !> points equals the fourier model's within the tolerance (magnus6, 1e-11).
   subroutine sampled_equals_fourier(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(fourier_model_t) :: fourier
      type(sampled_model_t) :: sampled
      type(error_t), allocatable :: error
      type(drive_t) :: drive
      type(trace_t) :: a, b
      real(wp) :: samples(16), tau, alpha, beta
      integer :: j
      drive = test_drive(1)
      call model_of(drive, fourier)
      do j = 0, 15
         samples(j + 1) = real(drive_value(drive, real(j, xp)*2.0_xp/16), wp)
      end do
      call sampled%set_values("samples", samples, error)
      if (.not. allocated(error)) call sampled%check_values(error)
      call check(ctx, .not. allocated(error), "16 samples")
      if (allocated(error)) return
      do j = 0, 49
         tau = 0.0413_wp*j
         call check_close(ctx, sampled%coefficient(2.0_wp, 1.0_wp, tau), fourier%coefficient(2.0_wp, 1.0_wp, tau), &
                          abs=1.0e-14_wp*4.0_wp, message="Q at tau = "//text(tau))
      end do
      do j = 1, 30
         alpha = 0.3_wp*j
         beta = -3.0_wp + 1.7_wp*j
         call monodromy_trace(fourier, hill_point_t(alpha, beta, 0.0_wp), method_t(method_magnus6, tolerance=1.0e-11_wp), &
                              a, error)
         call monodromy_trace(sampled, hill_point_t(alpha, beta, 0.0_wp), method_t(method_magnus6, tolerance=1.0e-11_wp), &
                              b, error)
         call check_close(ctx, b%value, a%value, abs=2.0e-11_wp*max(1.0_wp, abs(a%value)), &
                          message="S at alpha = "//text(alpha)//", beta = "//text(beta))
      end do
   end subroutine sampled_equals_fourier

   !> For an analytic f (exp(cos πτ), its mean I₀(1) removed) the trigonometric interpolant
   !> of N samples converges spectrally: its largest error between the samples falls from
   !> N = 8 to 16 to 32 by more than 100× each, to below 1e-13 at N = 32.
   subroutine sampled_interpolation_spectral(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp), parameter :: mean = 1.2660658777520083_wp  ! I₀(1), the mean of exp(cos πτ)
      type(sampled_model_t) :: sampled
      type(error_t), allocatable :: error
      real(wp), allocatable :: samples(:)
      real(wp) :: errors(3), tau, exact
      integer :: k, n, j
      do k = 1, 3
         n = 4*2**k
         samples = [(exp(cos(pi*2.0_wp*j/n)), j=0, n - 1)]
         call sampled%set_values("samples", samples, error)
         if (.not. allocated(error)) call sampled%check_values(error)
         call check(ctx, .not. allocated(error), "samples")
         if (allocated(error)) return
         errors(k) = 0.0_wp
         do j = 0, 199
            tau = 2.0_wp*(j + 0.37_wp)/200
            exact = exp(cos(pi*tau)) - mean
            errors(k) = max(errors(k), abs(sampled%coefficient(1.0_wp, 0.0_wp, tau) - exact))
         end do
      end do
      print '(4x,a,3es10.2)', "largest interpolation error at N = 8, 16, 32:", errors
      call check(ctx, errors(2) < errors(1)/100 .and. errors(3) < max(errors(2)/100, 1.0e-13_wp), "spectral convergence")
      call check(ctx, errors(3) < 1.0e-13_wp, "N = 32 to rounding")
   end subroutine sampled_interpolation_spectral

   !> The first transition values of drive 1 (a sine term: no even symmetry, Hill's method on
   !> the coupled blocks) at α = 2 against the roots of S ∓ 2 of the reference, bracketed on a
   !> grid of β and bisected: each within 1e-9 (relative to max(1, |β|)).
   subroutine transition_values_with_sines(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(drive_t) :: drive
      type(fourier_model_t) :: model
      type(hill_boundary_t), allocatable :: values(:)
      type(error_t), allocatable :: error
      real(xp) :: lo, hi, f_lo, f_hi, mid, f_mid, target
      real(wp) :: beta
      integer :: k, n_checked
      drive = test_drive(1)
      call model_of(drive, model)
      call characteristic_values(model, 2.0_wp, 3, values, error, tolerance=1.0e-12_wp)
      call check(ctx, .not. allocated(error), "characteristic values")
      if (allocated(error)) return
      n_checked = 0
      do k = 1, size(values)
         beta = values(k)%beta
         target = real(values(k)%trace_sign, xp)
         ! a bracket of the root around the value, then bisection on the reference
         lo = real(beta, xp) - 1.0e-6_xp*max(1.0_xp, abs(real(beta, xp)))
         hi = real(beta, xp) + 1.0e-6_xp*max(1.0_xp, abs(real(beta, xp)))
         f_lo = reference_trace(drive, 2.0_xp, lo, 0.0_xp, 400) - target
         f_hi = reference_trace(drive, 2.0_xp, hi, 0.0_xp, 400) - target
         if (f_lo*f_hi > 0.0_xp) then
            ! a double root (a closed tongue) touches S = ±2 without crossing: |S ∓ 2| small there
            f_mid = reference_trace(drive, 2.0_xp, real(beta, xp), 0.0_xp, 400) - target
            call check(ctx, abs(f_mid) < 1.0e-8_xp, "S = +-2 at the value (touching) at beta = "//text(beta))
            cycle
         end if
         do while (hi - lo > 1.0e-13_xp*max(1.0_xp, abs(lo)))
            mid = 0.5_xp*(lo + hi)
            f_mid = reference_trace(drive, 2.0_xp, mid, 0.0_xp, 400) - target
            if ((f_mid < 0.0_xp) .eqv. (f_lo < 0.0_xp)) then
               lo = mid
               f_lo = f_mid
            else
               hi = mid
            end if
         end do
         call check_close(ctx, beta, real(0.5_xp*(lo + hi), wp), abs=1.0e-9_wp*max(1.0_wp, abs(beta)), &
                          message="value "//text(real(k, wp))//" against bisection")
         n_checked = n_checked + 1
      end do
      call check(ctx, n_checked >= 3, "values checked by bisection: "//text(real(n_checked, wp)))
   end subroutine transition_values_with_sines

   !> Bad input of the model groups: exit status 2 (err_input) with a message naming the
   !> scene file, the group and the variable, and no output file.
   subroutine bad_scene_input(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=:), allocatable :: many, few, ragged, nan_file
      integer :: j
      many = "&fourier cos = 0.1"
      do j = 2, 257
         many = many//", 0.1"
      end do
      many = many//" /"
      few = scratch_prefix("fourier_few")//".dat"
      ragged = scratch_prefix("fourier_ragged")//".dat"
      nan_file = scratch_prefix("fourier_nan")//".dat"
      call write_file(few, [padded("1"), padded("2"), padded("3")])
      call write_file(ragged, [padded("0 1"), padded("0.5 2 3"), padded("1 3"), padded("1.5 4")])
      call write_file(nan_file, [padded("1"), padded("2"), padded("nan"), padded("3")])
      call refused("fourier", "&fourier cos = /", "&fourier: cos:", "no value")
      call refused("fourier", "&fourier cos = 1, nan /", "&fourier: cos:", "finite")
      call refused("fourier", "&fourier sin = 1, inf /", "&fourier: sin:", "finite")
      call refused("fourier", many, "&fourier: cos:", "at most 256")
      call refused("fourier", "&fourier cos = 1, period = 3 /", "&fourier: period:", "multiple of 2")
      call refused("fourier", "&fourier cos = 0, 0 /", "&fourier: cos", "nonzero")
      call refused("fourier", "&fourier coss = 1 /", "&fourier: coss:", "unknown variable")
      call refused("sampled", "&sampled file = '"//few//"' /", "&sampled: file:", "got 3")
      call refused("sampled", "&sampled file = '"//ragged//"' /", "&sampled: file:", "line 2")
      call refused("sampled", "&sampled file = '"//nan_file//"' /", "&sampled: file:", "line 3")
      call refused("sampled", "&sampled file = '"//scratch_prefix("no_such")//".dat' /", "&sampled: file:", "cannot open")
      call refused("sampled", "&sampled samples = 1, 2, nan, 4 /", "&sampled: samples:", "finite")
      call delete_file(few)
      call delete_file(ragged)
      call delete_file(nan_file)
   contains
      subroutine refused(model, group, where, what)
         character(len=*), intent(in) :: model, group, where, what
         type(error_t), allocatable :: error
         character(len=:), allocatable :: written, out, scene
         character(len=2000) :: lines(3)
         out = scratch_prefix("fourier_bad")
         scene = scratch_prefix("fourier_bad_scene")//".nml"
         lines(1) = "&scene task = 'chart', model = '"//model//"', output = '"//out//"' /"
         lines(2) = "&chart n_alpha = 3, n_beta = 3 /"
         lines(3) = group
         call run_text_scene("fourier_bad_scene", lines, error, written)
         call check(ctx, allocated(error), model//" "//what//": refused")
         if (.not. allocated(error)) return
         call check(ctx, error%code == err_input, model//" "//what//": an input error (exit 2)")
         call check(ctx, index(error%message, scene) > 0 .and. index(error%message, where) > 0 .and. &
                    index(error%message, what) > 0, "the message names file, group and variable: "//error%message)
         call check(ctx, .not. file_exists(out//"_chart.dat"), model//" "//what//": no file written")
      end subroutine refused
   end subroutine bad_scene_input

   !> Method auto over chart grids as the chart task computes them (one row per α,
   !> `monodromy_trace_batch`: shared meshes), against magnus6 at 1e-12, error ≤ tolerance at
   !> status 0 at 1e-6 and 1e-10: the pivot f = cos πτ + 0.5 cos 2πτ over the range of
   !> own_pivot_chart.nml (32 × 32) and the row of its point α = 0.5017, β = 4.0468, where a
   !> first mesh of 4 steps per wavelength of the top harmonic made a Richardson pair whose
   !> difference was a twelfth of its error (3.9e-10 at 1e-10); three harmonics with a sine
   !> term over the benchmark's range; f = −cos πτ at α = 1.12 with damping, where a first
   !> mesh of 8 steps left 1.9e-10 at 1e-10 with status 0.
   subroutine auto_chart_grid(ctx)
      type(test_context_t), intent(inout) :: ctx
      integer, parameter :: n = 32
      real(wp), parameter :: tols(2) = [1.0e-6_wp, 1.0e-10_wp]
      type(fourier_model_t) :: model
      type(error_t), allocatable :: error
      real(wp) :: betas(n), worst, alpha_max, beta_min, beta_max
      integer :: d, i, j, t, n_checked
      do d = 1, 2
         if (d == 1) then
            call model%set_values("cos", [1.0_wp, 0.5_wp], error)
            alpha_max = 30.0_wp; beta_min = -10.0_wp; beta_max = 40.0_wp
         else
            call model%set_values("cos", [1.0_wp, 0.4_wp, 0.0_wp], error)
            if (.not. allocated(error)) call model%set_values("sin", [0.0_wp, 0.0_wp, 0.3_wp], error)
            alpha_max = 9.8_wp; beta_min = -2.0_wp; beta_max = 12.0_wp
         end if
         if (.not. allocated(error)) call model%check_values(error)
         call check(ctx, .not. allocated(error), "the drive")
         if (allocated(error)) return
         betas = [(beta_min + (beta_max - beta_min)*(j - 1)/real(n - 1, wp), j=1, n)]
         do t = 1, size(tols)
            worst = 0.0_wp
            n_checked = 0
            do i = 1, n
               call auto_row_errors(model, 0.1_wp + (alpha_max - 0.1_wp)*(i - 1)/real(n - 1, wp), betas, tols(t), &
                                    worst, n_checked)
            end do
            if (d == 1) call auto_row_errors(model, 5.0167224080267558e-1_wp, [4.0468227424749159_wp], tols(t), &
                                             worst, n_checked)
            call check(ctx, worst <= 1.0_wp, "drive "//text(real(d, wp))//" at "//text(tols(t))// &
                       ": worst error/tolerance "//text(worst))
            call check(ctx, n_checked >= n*n - 10, "points compared")
            print '(4x,a,i0,a,es8.1,a,es9.2)', "drive ", d, " auto chart grid at", tols(t), ": worst error/tolerance", worst
         end do
      end do
      ! f = -cos(pi tau), a small drive and damping (the Kapitza pendulum at 167 rad/s): a
      ! first mesh of 8 steps made a Richardson pair a twentieth of its error
      call model%set_values("cos", [-1.0_wp], error)
      if (.not. allocated(error)) call model%set_values("sin", [0.0_wp], error)
      call check(ctx, .not. allocated(error), "the drive -cos")
      do t = 1, size(tols)
         worst = 0.0_wp
         n_checked = 0
         call auto_row_errors(model, 1.1222961526322346_wp, [-0.01735337923136149_wp, 0.5_wp, 3.0_wp], tols(t), &
                              worst, n_checked, 0.003761859044546849_wp)
         call check(ctx, worst <= 1.0_wp .and. n_checked == 3, "-cos, small drive, damped, at "//text(tols(t))// &
                    ": worst error/tolerance "//text(worst))
      end do
   end subroutine auto_chart_grid

   !> A number as short text for messages.
   function text(x) result(t)
      real(wp), intent(in) :: x
      character(len=:), allocatable :: t
      character(len=32) :: buffer
      write (buffer, '(g0.8)') x
      t = trim(adjustl(buffer))
   end function text
end module test_model_fourier

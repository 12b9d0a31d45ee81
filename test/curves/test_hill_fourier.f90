!> Tests of Hill's method on the Fourier coefficients of g = Q − β
!> (hillstab_curves_hill_fourier): the Mathieu model (g = −ν cos πτ) against the published
!> characteristic values and GSL's a_n, b_n, and against the pencil route; drives with
!> several harmonics and sine terms (no even symmetry) against bisection on S over the full
!> period by sixth-order Magnus steps, for periods 2 and 4; α = 0 and the closed tongues of
!> a drive of a shorter period; the three formulations; error bounds that bound; a drive
!> with infinitely many harmonics (the square wave, Meissner's closed form); bad input.
module test_hill_fourier
   use hillstab_core_kinds, only: wp, pi, pi2
   use hillstab_core_error, only: error_t, err_invalid_parameter
   use hillstab_hill_mathieu, only: mathieu_transition_beta, mathieu_kind_a, mathieu_kind_b
   use hillstab_hill_model, only: hill_model_t
   use hillstab_hill_model_mathieu, only: mathieu_model_t
   use hillstab_hill_model_elastic, only: elastic_model_t
   use hillstab_curves_hill_method, only: hill_boundary_t, hill_boundaries, block_periodic_even, block_periodic_odd, &
      block_antiperiodic_even, block_antiperiodic_odd, block_periodic, block_antiperiodic, route_fourier
   use hillstab_curves_hill_fourier
   use hillstab_testing
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   use hillstab_test_drive_model, only: drive_model_t, drive_model, square_model, full_period_trace, &
      bisect_full_period
   implicit none
   private
   public :: collect_hill_fourier

contains

   function collect_hill_fourier() result(suite)
      type(testsuite_t) :: suite
      suite = new_testsuite("hill_fourier", [ &
         new_unittest("mathieu_published", mathieu_published), &
         new_unittest("mathieu_against_gsl", mathieu_against_gsl), &
         new_unittest("mathieu_same_as_pencil", mathieu_same_as_pencil), &
         new_unittest("alpha_zero_closed_form", alpha_zero_closed_form), &
         new_unittest("sine_terms_against_full_period", sine_terms_against_full_period), &
         new_unittest("period_four_against_full_period", period_four_against_full_period), &
         new_unittest("even_drive_blocks", even_drive_blocks), &
         new_unittest("shorter_period_tongues_closed", shorter_period_tongues_closed), &
         new_unittest("error_bounds_bound", error_bounds_bound), &
         new_unittest("formulations_agree", formulations_agree), &
         new_unittest("ritz_convergence", ritz_convergence), &
         new_unittest("square_wave_infinite", square_wave_infinite), &
         new_unittest("bad_input", bad_input)])
   end function collect_hill_fourier

   !> The value of the curve (order, parity) among curves, and how many matched.
   subroutine find_curve(curves, order, parity, beta, hits, bound)
      type(hill_boundary_t), intent(in) :: curves(:)
      integer, intent(in) :: order, parity
      real(wp), intent(out) :: beta, bound
      integer, intent(out) :: hits
      integer :: i
      hits = 0
      beta = 0.0_wp
      bound = 0.0_wp
      do i = 1, size(curves)
         if (curves(i)%order /= order .or. curves(i)%parity /= parity) cycle
         hits = hits + 1
         beta = curves(i)%beta
         bound = curves(i)%error_bound
      end do
   end subroutine find_curve

   !> β = (π²/4) a_n(q), (π²/4) b_n(q) at ν = π²q/2: the published values at q = 1, 10, 25
   !> to 1e-12 in a (the values are given to 12 decimals).
   subroutine mathieu_published(ctx)
      type(test_context_t), intent(inout) :: ctx
      call expect(1.0_wp, 0, 1, -0.455138604107_wp)
      call expect(1.0_wp, 1, -1, -0.110248816992_wp)
      call expect(1.0_wp, 1, 1, 1.859108072514_wp)
      call expect(1.0_wp, 2, -1, 3.917024772998_wp)
      call expect(10.0_wp, 0, 1, -13.936979956659_wp)
      call expect(10.0_wp, 1, -1, -13.936552479250_wp)
      call expect(25.0_wp, 0, 1, -40.256779546567_wp)
      call expect(25.0_wp, 1, 1, -21.314899690666_wp)
   contains
      subroutine expect(q, order, parity, a)
         real(wp), intent(in) :: q, a
         integer, intent(in) :: order, parity
         type(hill_boundary_t), allocatable :: c(:)
         type(error_t), allocatable :: error
         integer :: hits
         real(wp) :: beta, bound
         character(len=40) :: label
         write (label, '(a,i0,a,f5.1)') merge("a", "b", parity == 1), order, " at q = ", q
         call fourier_boundaries(mathieu_model_t(), q*pi2/2, -0.25_wp*pi2*(2*q + 2), 0.25_wp*pi2*(order + 1)**2 + 1, &
                                 1.0e-14_wp, c, error)
         call check(ctx, .not. allocated(error), trim(label)//": no error")
         if (allocated(error)) return
         call find_curve(c, order, parity, beta, hits, bound)
         call check(ctx, hits == 1, trim(label)//": found once")
         ! the published values carry 12 decimals: 0.5e-12 from their rounding
         call check(ctx, 4*beta/pi2, a, abs=1.0e-12_wp, message=trim(label))
         call check(ctx, bound < 1.0e-12_wp, trim(label)//": bound below 1e-12")
         call check(ctx, all(c%route == route_fourier), trim(label)//": route")
      end subroutine expect
   end subroutine mathieu_published

   !> Orders 0 … 14 at ν = −8 … 40 against GSL's a_n, b_n (GSL's own accuracy ~1e-13 here):
   !> within 1e-12·max(1, |β|), and within the error bound plus GSL's share.
   subroutine mathieu_against_gsl(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp), parameter :: nus(6) = [-8.0_wp, 0.3_wp, 2.0_wp, 7.0_wp, 20.0_wp, 40.0_wp]
      type(hill_boundary_t), allocatable :: c(:)
      type(error_t), allocatable :: error
      real(wp) :: beta_gsl, worst
      integer :: i, f, n_checked
      worst = 0.0_wp
      n_checked = 0
      do f = 1, size(nus)
         call fourier_boundaries(mathieu_model_t(), nus(f), -60.0_wp, 0.25_wp*pi2*14.5_wp**2, 1.0e-13_wp, c, error)
         call check(ctx, .not. allocated(error), "no error")
         if (allocated(error)) return
         do i = 1, size(c)
            if (c(i)%order > 14) cycle
            call mathieu_transition_beta(merge(mathieu_kind_a, mathieu_kind_b, c(i)%parity == 1), c(i)%order, &
                                         nus(f), beta_gsl, error)
            call check(ctx, .not. allocated(error), "GSL")
            if (allocated(error)) return
            call check(ctx, c(i)%beta, beta_gsl, abs=1.0e-12_wp*max(1.0_wp, abs(beta_gsl)), message="against GSL")
            worst = max(worst, abs(c(i)%beta - beta_gsl)/max(1.0_wp, abs(beta_gsl)))
            n_checked = n_checked + 1
         end do
      end do
      call check(ctx, n_checked >= 6*20, "at least 20 curves per nu")
      print '(a,es9.2,a,i0,a)', "    hill_fourier: Mathieu against GSL, largest relative difference ", worst, &
         " over ", n_checked, " values"
   end subroutine mathieu_against_gsl

   !> The Mathieu model through both routes (pencil and Fourier) gives the same curves, in the
   !> same order, kinds and parities, within 1e-12·max(1, |β|).
   subroutine mathieu_same_as_pencil(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp), parameter :: nus(5) = [-5.0_wp, 0.0_wp, 1.0_wp, 9.0_wp, 30.0_wp]
      type(hill_boundary_t), allocatable :: a(:), b(:)
      type(error_t), allocatable :: error
      real(wp) :: worst
      integer :: f, i
      worst = 0.0_wp
      do f = 1, size(nus)
         call hill_boundaries(mathieu_model_t(), nus(f), -40.0_wp, 120.0_wp, 1.0e-13_wp, a, error)
         call check(ctx, .not. allocated(error), "pencil: no error")
         if (allocated(error)) return
         call fourier_boundaries(mathieu_model_t(), nus(f), -40.0_wp, 120.0_wp, 1.0e-13_wp, b, error)
         call check(ctx, .not. allocated(error), "Fourier: no error")
         if (allocated(error)) return
         call check(ctx, size(a) == size(b), "as many curves")
         if (size(a) /= size(b)) return
         do i = 1, size(a)
            call check(ctx, b(i)%beta, a(i)%beta, abs=1.0e-12_wp*max(1.0_wp, abs(a(i)%beta)), message="same beta")
            call check(ctx, a(i)%order == b(i)%order .and. a(i)%parity == b(i)%parity .and. &
                       a(i)%trace_sign == b(i)%trace_sign, "same order, parity and kind")
            call check(ctx, a(i)%coexistent .eqv. b(i)%coexistent, "same coexistence")
            worst = max(worst, abs(a(i)%beta - b(i)%beta)/max(1.0_wp, abs(a(i)%beta)))
         end do
      end do
      print '(a,es9.2)', "    hill_fourier: Mathieu pencil against Fourier, largest relative difference ", worst
   end subroutine mathieu_same_as_pencil

   !> α = 0: g = 0, β = (nπ/P)² exactly, each order n ≥ 1 twice and coexistent, periods 2 and 4.
   subroutine alpha_zero_closed_form(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(drive_model_t) :: model
      type(hill_boundary_t), allocatable :: c(:)
      type(error_t), allocatable :: error
      real(wp) :: p
      integer :: i, k
      do k = 1, 2
         p = 2.0_wp*k
         model = drive_model(p, 0.3_wp, [1.0_wp, 0.0_wp, -0.5_wp], [0.0_wp, 0.7_wp, 0.2_wp])
         call fourier_boundaries(model, 0.0_wp, -1.0_wp, 60.0_wp, 1.0e-13_wp, c, error)
         call check(ctx, .not. allocated(error), "no error")
         if (allocated(error)) return
         ! orders n with (n pi/p)^2 <= 60
         call check(ctx, size(c) == 1 + 2*floor(sqrt(60.0_wp)*p/pi), "every order twice")
         do i = 1, size(c)
            call check(ctx, c(i)%beta, (c(i)%order*pi/p)**2, abs=1.0e-12_wp*max(1.0_wp, c(i)%beta), &
                       message="(n pi/P)^2")
            call check(ctx, c(i)%trace_sign == merge(2, -2, mod(c(i)%order, 2) == 0), "kind by parity of n")
            call check(ctx, c(i)%coexistent .eqv. c(i)%order > 0, "zero width at alpha = 0")
         end do
      end do
   end subroutine alpha_zero_closed_form

   !> Every curve of `model` at α in [beta_min, beta_max] against bisection on S over the full
   !> period (Magnus 6, n_steps), bracketed by the curve's error bound widened: |Δβ| ≤ 1e-11
   !> and within the curve's error bound plus the reference's 2e-12.
   subroutine against_full_period(ctx, model, alpha, beta_min, beta_max, n_steps, label, n_min)
      type(test_context_t), intent(inout) :: ctx
      class(hill_model_t), intent(in) :: model
      real(wp), intent(in) :: alpha, beta_min, beta_max
      integer, intent(in) :: n_steps, n_min
      character(len=*), intent(in) :: label
      type(hill_boundary_t), allocatable :: c(:)
      type(error_t), allocatable :: error
      real(wp) :: ref, h, f_lo, f_hi, worst, ratio
      integer :: i, n_checked
      call fourier_boundaries(model, alpha, beta_min, beta_max, 1.0e-13_wp, c, error)
      call check(ctx, .not. allocated(error), label//": no error")
      if (allocated(error)) return
      call check(ctx, size(c) >= n_min, label//": enough curves")
      worst = 0.0_wp
      ratio = 0.0_wp
      n_checked = 0
      do i = 1, size(c)
         call check(ctx, c(i)%parity == 0 .and. c(i)%edge >= merge(0, 1, c(i)%order == 0), label//": coupled edges")
         ! a bracket of S = ±2 around the value; a closed tongue (double root) has none
         h = 1.0e-7_wp*max(1.0_wp, abs(c(i)%beta))
         f_lo = full_period_trace(model, alpha, c(i)%beta - h, n_steps) - c(i)%trace_sign
         f_hi = full_period_trace(model, alpha, c(i)%beta + h, n_steps) - c(i)%trace_sign
         if ((f_lo < 0.0_wp) .eqv. (f_hi < 0.0_wp)) then
            ! the two edges of one order within 2h: both are the double root, S touches ±2
            call check(ctx, abs(f_lo) < 1.0e-6_wp .and. abs(f_hi) < 1.0e-6_wp, label//": S = +-2 at a double root")
            cycle
         end if
         ref = bisect_full_period(model, alpha, real(c(i)%trace_sign, wp), c(i)%beta - h, c(i)%beta + h, n_steps, &
                                  1.0e-14_wp*max(1.0_wp, abs(c(i)%beta)))
         call check(ctx, c(i)%beta, ref, abs=1.0e-11_wp*max(1.0_wp, abs(ref)), message=label//": against bisection")
         call check(ctx, abs(c(i)%beta - ref) <= c(i)%error_bound + 2.0e-12_wp*max(1.0_wp, abs(ref)), &
                    label//": within the error bound")
         worst = max(worst, abs(c(i)%beta - ref)/max(1.0_wp, abs(ref)))
         ratio = max(ratio, abs(c(i)%beta - ref)/max(c(i)%error_bound, tiny(1.0_wp)))
         n_checked = n_checked + 1
      end do
      print '(4x,a,a,i0,a,es9.2,a,es9.2)', label, ": ", n_checked, " curves, largest relative difference ", worst, &
         ", largest difference / bound ", ratio
   end subroutine against_full_period

   !> A drive of period 2 with three harmonics, cosine and sine terms (no even symmetry about
   !> any τ), against bisection on S over the full period.
   subroutine sine_terms_against_full_period(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(drive_model_t) :: model
      model = drive_model(2.0_wp, 0.4_wp, [-1.0_wp, 0.3_wp, 0.25_wp], [0.6_wp, -0.45_wp, 0.15_wp])
      call against_full_period(ctx, model, 3.0_wp, -10.0_wp, 60.0_wp, 1200, "period 2, alpha 3", 8)
      call against_full_period(ctx, model, 12.0_wp, -30.0_wp, 40.0_wp, 1600, "period 2, alpha 12", 5)
      call against_full_period(ctx, model, -2.5_wp, -10.0_wp, 40.0_wp, 1200, "period 2, alpha -2.5", 5)
   end subroutine sine_terms_against_full_period

   !> Period 4 (a commensurate modulation): orders by the wavenumber nπ/4.
   subroutine period_four_against_full_period(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(drive_model_t) :: model
      model = drive_model(4.0_wp, -0.2_wp, [0.5_wp, -1.0_wp, 0.0_wp, 0.3_wp], [0.4_wp, 0.0_wp, 0.2_wp, -0.1_wp])
      call against_full_period(ctx, model, 2.0_wp, -10.0_wp, 25.0_wp, 2400, "period 4, alpha 2", 10)
      call against_full_period(ctx, model, 7.0_wp, -20.0_wp, 20.0_wp, 2400, "period 4, alpha 7", 8)
   end subroutine period_four_against_full_period

   !> An even drive (cosines only) splits into the four blocks: curves with parities ±1 and
   !> orders as for Mathieu, the same values as the coupled computation of the drive with
   !> a sine term of 0 … and against the full-period bisection.
   subroutine even_drive_blocks(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(drive_model_t) :: model
      type(fourier_drive_t) :: drive
      type(hill_boundary_t), allocatable :: c(:)
      type(error_t), allocatable :: error
      real(wp), allocatable :: even_values(:), odd_values(:), coupled(:), joined(:)
      integer :: i
      model = drive_model(2.0_wp, 0.1_wp, [-1.0_wp, 0.5_wp, -0.2_wp], [0.0_wp, 0.0_wp, 0.0_wp])
      call fourier_drive(model, 4.0_wp, drive, error)
      call check(ctx, .not. allocated(error) .and. drive%even, "cosines only: even")
      call check(ctx, all(fourier_blocks(drive) == [1, 2, 3, 4]), "four blocks")
      call fourier_boundaries(model, 4.0_wp, -10.0_wp, 50.0_wp, 1.0e-13_wp, c, error)
      call check(ctx, .not. allocated(error), "no error")
      if (allocated(error)) return
      call check(ctx, all(abs(c%parity) == 1), "parities +-1")
      ! the periodic blocks joined equal the coupled periodic matrix of the same drive
      call fourier_drive_eigenvalues(drive, block_periodic_even, 30, even_values, error)
      call fourier_drive_eigenvalues(drive, block_periodic_odd, 30, odd_values, error)
      drive%even = .false.
      call fourier_drive_eigenvalues(drive, block_periodic, 30, coupled, error)
      call check(ctx, .not. allocated(error), "coupled block of an even drive")
      if (allocated(error)) return
      joined = [even_values, odd_values]
      call sort(joined)
      do i = 1, 20
         call check(ctx, coupled(i), joined(i), abs=1.0e-11_wp*max(1.0_wp, abs(joined(i))), message="split = coupled")
      end do
      call against_full_period(ctx, drive_model(2.0_wp, 0.1_wp, [-1.0_wp, 0.5_wp, -0.2_wp], [0.0_wp, 0.0_wp, &
                               1.0e-300_wp]), 4.0_wp, -10.0_wp, 50.0_wp, 1200, "even drive as coupled", 8)
   contains
      pure subroutine sort(x)
         real(wp), intent(inout) :: x(:)
         integer :: a, b
         real(wp) :: t
         do a = 2, size(x)
            t = x(a)
            b = a - 1
            do while (b >= 1)
               if (x(b) <= t) exit
               x(b + 1) = x(b)
               b = b - 1
            end do
            x(b + 1) = t
         end do
      end subroutine sort
   end subroutine even_drive_blocks

   !> A drive of period 4 holding only the harmonics 2 and 4 has period 2: the tongues of odd
   !> order (S = −2 over 4) are closed (coexistence by structure, both edges equal), and S
   !> over 4 is S₂² − 2 with S₂ of the period-2 model.
   subroutine shorter_period_tongues_closed(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(drive_model_t) :: model
      type(hill_boundary_t), allocatable :: c(:)
      type(error_t), allocatable :: error
      integer :: i, j
      model = drive_model(4.0_wp, 0.0_wp, [0.0_wp, -1.0_wp, 0.0_wp, 0.3_wp], [0.0_wp, 0.5_wp, 0.0_wp, 0.0_wp])
      call fourier_boundaries(model, 3.0_wp, -10.0_wp, 30.0_wp, 1.0e-13_wp, c, error)
      call check(ctx, .not. allocated(error), "no error")
      if (allocated(error)) return
      do i = 1, size(c)
         call check(ctx, c(i)%coexistent .eqv. mod(c(i)%order, 2) == 1, "closed exactly for the odd orders")
         if (mod(c(i)%order, 2) /= 1) cycle
         do j = 1, size(c)
            if (j /= i .and. c(j)%order == c(i)%order) call check(ctx, c(j)%beta, c(i)%beta, &
               abs=1.0e-10_wp*max(1.0_wp, abs(c(i)%beta)), message="both edges of a closed tongue agree")
         end do
      end do
   end subroutine shorter_period_tongues_closed

   !> Every value's error bound holds against the 40-digit eigenvalues of the same operator
   !> (data/reference/fourier_set.dat, made by mpmath: make_fourier_reference.py), for the
   !> drives of the tests above at tolerance 1e-13; the values within 1e-13·max(1, |β|).
   subroutine error_bounds_bound(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=*), parameter :: file = "data/reference/fourier_set.dat"
      type(drive_model_t) :: models(2)
      type(hill_boundary_t), allocatable :: c(:)
      type(error_t), allocatable :: error
      character(len=256) :: line
      real(wp) :: alpha, beta, ref_error, last_alpha, worst, ratio
      integer :: unit, ios, model, kind, rank, last_model, i, seen, n_checked
      models(1) = drive_model(2.0_wp, 0.4_wp, [-1.0_wp, 0.3_wp, 0.25_wp], [0.6_wp, -0.45_wp, 0.15_wp])
      models(2) = drive_model(4.0_wp, -0.2_wp, [0.5_wp, -1.0_wp, 0.0_wp, 0.3_wp], [0.4_wp, 0.0_wp, 0.2_wp, -0.1_wp])
      open (newunit=unit, file=file, status="old", action="read", iostat=ios)
      call check(ctx, ios == 0, "reference table "//file//" read")
      if (ios /= 0) return
      last_model = 0
      last_alpha = huge(1.0_wp)
      worst = 0.0_wp
      ratio = 0.0_wp
      n_checked = 0
      do
         read (unit, '(a)', iostat=ios) line
         if (ios /= 0) exit
         if (line(1:1) == "#" .or. len_trim(line) == 0) cycle
         read (line, *) model, alpha, kind, rank, beta, ref_error
         if (model /= last_model .or. alpha /= last_alpha) then
            call fourier_boundaries(models(model), alpha, -60.0_wp, 200.0_wp, 1.0e-13_wp, c, error)
            call check(ctx, .not. allocated(error), "no error")
            if (allocated(error)) exit
            last_model = model
            last_alpha = alpha
         end if
         seen = 0
         do i = 1, size(c)
            if (c(i)%trace_sign /= kind) cycle
            seen = seen + 1
            if (seen /= rank) cycle
            call check(ctx, abs(c(i)%beta - beta) <= c(i)%error_bound + ref_error, "within the error bound")
            call check(ctx, c(i)%beta, beta, abs=1.0e-13_wp*max(1.0_wp, abs(beta)), message="against mpmath")
            worst = max(worst, abs(c(i)%beta - beta)/max(1.0_wp, abs(beta)))
            ratio = max(ratio, abs(c(i)%beta - beta)/c(i)%error_bound)
            n_checked = n_checked + 1
         end do
      end do
      close (unit)
      call check(ctx, n_checked == 80, "80 reference values")
      print '(a,i0,a,es9.2,a,f6.3)', "    hill_fourier: ", n_checked, " values against mpmath, largest relative "// &
         "error ", worst, ", largest error / bound ", ratio
   end subroutine error_bounds_bound

   !> The three formulations (inverted pencil, standard real, complex Hermitian) agree on a
   !> coupled drive to 1e-10 (the complex one's rounding, growing with the truncation as
   !> ε‖H‖, keeps it from tighter tolerances); the complex one refuses the even/odd blocks.
   subroutine formulations_agree(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(drive_model_t) :: model
      type(hill_boundary_t), allocatable :: a(:), b(:), c(:)
      type(error_t), allocatable :: error
      real(wp), allocatable :: v(:)
      integer :: i
      model = drive_model(2.0_wp, 0.0_wp, [-1.0_wp, 0.3_wp], [0.5_wp, 0.2_wp])
      call fourier_boundaries(model, 5.0_wp, -10.0_wp, 80.0_wp, 1.0e-10_wp, a, error, fourier_formulation_inverted)
      call check(ctx, .not. allocated(error), "inverted: no error")
      if (allocated(error)) return
      call fourier_boundaries(model, 5.0_wp, -10.0_wp, 80.0_wp, 1.0e-10_wp, b, error, fourier_formulation_standard)
      call check(ctx, .not. allocated(error), "standard: no error")
      if (allocated(error)) call check(ctx, .false., error%message)
      if (allocated(error)) return
      call fourier_boundaries(model, 5.0_wp, -10.0_wp, 80.0_wp, 1.0e-10_wp, c, error, fourier_formulation_complex)
      call check(ctx, .not. allocated(error), "complex: no error")
      if (allocated(error)) call check(ctx, .false., error%message)
      if (allocated(error)) return
      call check(ctx, size(a) == size(b) .and. size(a) == size(c) .and. size(a) > 8, "as many curves")
      if (size(a) /= size(b) .or. size(a) /= size(c)) return
      do i = 1, size(a)
         call check(ctx, b(i)%beta, a(i)%beta, abs=1.0e-10_wp*max(1.0_wp, abs(a(i)%beta)), message="standard")
         call check(ctx, c(i)%beta, a(i)%beta, abs=1.0e-10_wp*max(1.0_wp, abs(a(i)%beta)), message="complex")
      end do
      call fourier_block_eigenvalues(mathieu_model_t(), 1.0_wp, block_periodic_even, 10, v, error, &
                                     fourier_formulation_complex)
      call check(ctx, allocated(error), "complex formulation on an even/odd block refused")
   end subroutine formulations_agree

   !> Rayleigh–Ritz: the j-th value never increases as the truncation grows.
   subroutine ritz_convergence(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(drive_model_t) :: model
      type(error_t), allocatable :: error
      real(wp), allocatable :: coarse(:), fine(:)
      integer :: level, block
      model = drive_model(2.0_wp, 0.0_wp, [-1.0_wp, 0.3_wp, 0.2_wp], [0.5_wp, 0.0_wp, -0.3_wp])
      do block = block_periodic, block_antiperiodic
         call fourier_block_eigenvalues(model, 8.0_wp, block, 4, coarse, error)
         do level = 5, 20
            call fourier_block_eigenvalues(model, 8.0_wp, block, level, fine, error)
            call check(ctx, .not. allocated(error), "no error")
            if (allocated(error)) return
            call check(ctx, all(fine(:size(coarse)) <= coarse + 1.0e-12_wp*max(1.0_wp, abs(coarse))), &
                       "values decrease as modes are added")
            call move_alloc(fine, coarse)
         end do
      end do
   end subroutine ritz_convergence

   !> The square wave (Meissner, infinitely many harmonics) is refused by default; with
   !> allow_infinite its curves come flagged and agree with the roots of the closed form
   !> S = 2 c₁c₂ − (k₁/k₂ + k₂/k₁) s₁s₂ within their (truncation-change) bound.
   subroutine square_wave_infinite(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(drive_model_t) :: model
      type(hill_boundary_t), allocatable :: c(:)
      type(error_t), allocatable :: error
      real(wp) :: ref
      integer :: i
      model = square_model(2.0_wp)
      call fourier_boundaries(model, 1.0_wp, -2.0_wp, 12.0_wp, 1.0e-6_wp, c, error)
      call check(ctx, allocated(error), "refused without allow_infinite")
      if (allocated(error)) call check(ctx, index(error%message, "infinitely many harmonics") > 0, "says why")
      call fourier_boundaries(model, 1.0_wp, -2.0_wp, 12.0_wp, 1.0e-4_wp, c, error, allow_infinite=.true.)
      call check(ctx, .not. allocated(error), "allow_infinite: no error")
      if (allocated(error)) return
      call check(ctx, size(c) >= 5 .and. all(c%truncated_drive), "flagged truncated_drive")
      do i = 1, size(c)
         ref = meissner_root(1.0_wp, real(c(i)%trace_sign, wp), c(i)%beta - 0.05_wp, c(i)%beta + 0.05_wp)
         call check(ctx, abs(c(i)%beta - ref) <= c(i)%error_bound + 1.0e-9_wp, "within the truncation bound")
      end do
   contains
      !> S = tr(T₂T₁) of the two constant pieces q₁ = β + α on [0, 1), q₂ = β − α on [1, 2).
      real(wp) function meissner(alpha, beta) result(s)
         real(wp), intent(in) :: alpha, beta
         real(wp) :: q(2), k, cs(2), sk(2), m21(2)
         integer :: j
         q = [beta + alpha, beta - alpha]
         do j = 1, 2
            k = sqrt(abs(q(j)))
            if (k == 0.0_wp) then
               cs(j) = 1.0_wp; sk(j) = 1.0_wp; m21(j) = 0.0_wp
            else if (q(j) > 0.0_wp) then
               cs(j) = cos(k); sk(j) = sin(k)/k; m21(j) = -k*sin(k)
            else
               cs(j) = cosh(k); sk(j) = sinh(k)/k; m21(j) = k*sinh(k)
            end if
         end do
         s = 2.0_wp*cs(1)*cs(2) + sk(2)*m21(1) + sk(1)*m21(2)
      end function meissner
      real(wp) function meissner_root(alpha, target, lo_in, hi_in) result(root)
         real(wp), intent(in) :: alpha, target, lo_in, hi_in
         real(wp) :: lo, hi, f_lo, mid, f_mid
         integer :: it
         lo = lo_in; hi = hi_in
         f_lo = meissner(alpha, lo) - target
         if ((f_lo < 0.0_wp) .eqv. (meissner(alpha, hi) - target < 0.0_wp)) then
            root = huge(1.0_wp)   ! no bracket: the check above fails
            return
         end if
         do it = 1, 200
            mid = 0.5_wp*(lo + hi)
            f_mid = meissner(alpha, mid) - target
            if ((f_mid < 0.0_wp) .eqv. (f_lo < 0.0_wp)) then
               lo = mid; f_lo = f_mid
            else
               hi = mid
            end if
         end do
         root = 0.5_wp*(lo + hi)
      end function meissner_root
   end subroutine square_wave_infinite

   !> Bad input: a model that is not β + g(τ), a non-finite α, a bad window, tolerance, block,
   !> count or level: errors, never a stop.
   subroutine bad_input(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(hill_boundary_t), allocatable :: c(:)
      type(fourier_block_t) :: values
      type(error_t), allocatable :: error
      real(wp), allocatable :: v(:)
      real(wp) :: nan
      nan = ieee_value(nan, ieee_quiet_nan)
      call fourier_boundaries(elastic_model_t(), 1.0_wp, 0.0_wp, 10.0_wp, 1.0e-12_wp, c, error)
      call check(ctx, allocated(error), "elastic model (no harmonics)")
      if (allocated(error)) call check(ctx, error%code == err_invalid_parameter .and. &
                                       index(error%message, "elastic") > 0, "names the model")
      call fourier_boundaries(mathieu_model_t(), nan, 0.0_wp, 10.0_wp, 1.0e-12_wp, c, error)
      call check(ctx, allocated(error), "NaN alpha")
      call fourier_boundaries(mathieu_model_t(), 1.0_wp, 10.0_wp, 0.0_wp, 1.0e-12_wp, c, error)
      call check(ctx, allocated(error), "beta_min > beta_max")
      call fourier_boundaries(mathieu_model_t(), 1.0_wp, 0.0_wp, 10.0_wp, 0.0_wp, c, error)
      call check(ctx, allocated(error), "tolerance 0")
      call fourier_block_first(mathieu_model_t(), 1.0_wp, block_periodic_even, 0, 1.0e-12_wp, values, error)
      call check(ctx, allocated(error), "count 0")
      call fourier_block_first(mathieu_model_t(), 1.0_wp, block_periodic, 3, 1.0e-12_wp, values, error)
      call check(ctx, allocated(error), "coupled block of an even drive")
      call fourier_block_eigenvalues(mathieu_model_t(), 1.0_wp, 7, 10, v, error)
      call check(ctx, allocated(error), "unknown block")
      call fourier_block_eigenvalues(mathieu_model_t(), 1.0_wp, block_periodic_even, 0, v, error)
      call check(ctx, allocated(error), "level 0")
      call fourier_block_first(mathieu_model_t(), 1.0_wp, block_periodic_even, 100000, 1.0e-12_wp, values, error)
      call check(ctx, allocated(error), "too many modes")
      if (allocated(error)) call check(ctx, index(error%message, "not converged") > 0 .or. &
                                       index(error%message, "too many") > 0, "says why")
   end subroutine bad_input
end module test_hill_fourier

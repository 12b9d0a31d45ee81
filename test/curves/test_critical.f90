!> Tests of the critical drives (hillstab_curves_critical): on Mathieu's equation every
!> crossing of the range against the characteristic values a_n, b_n of GSL (the α where
!> (π²/4) a_n(2α/π²) = β, found here by bisection on GSL's values), each within its stated
!> error and confirmed; the Kapitza pendulum's least stabilising amplitude at 50 Hz against
!> the value of a 150-digit reference (6.30680 mm) and the classic √(2gl)/ω to first order,
!> undamped at 10 frequencies against a_0(q) on GSL's values and its series;
!> a narrow region between two samples found; bad ranges refused naming the argument.
module test_critical
   use hillstab_core_kinds, only: wp, pi, pi2
   use hillstab_core_text, only: real_text
   use hillstab_core_error, only: error_t, err_invalid_parameter
   use hillstab_core_status, only: status_ok
   use hillstab_hill_model_mathieu, only: mathieu_model_t
   use hillstab_hill_mathieu, only: mathieu_transition_beta, mathieu_kind_a, mathieu_kind_b, mathieu_a
   use hillstab_integrate_monodromy, only: method_t
   use hillstab_curves_critical, only: critical_drive_t, critical_drives, critical_drives_along, along_alpha, &
      along_beta
   use hillstab_hill_model_equation, only: equation_model_t
   use hillstab_hill_model, only: hill_point_t
   use hillstab_hill_transfer, only: trace_t
   use hillstab_integrate_monodromy, only: monodromy_trace
   use hillstab_testing
   implicit none
   private
   public :: collect_critical

contains

   function collect_critical() result(suite)
      type(testsuite_t) :: suite
      suite = new_testsuite("critical", [ &
         new_unittest("mathieu_against_gsl", mathieu_against_gsl), &
         new_unittest("kapitza_least_amplitude", kapitza_least_amplitude), &
         new_unittest("kapitza_ten_frequencies", kapitza_ten_frequencies), &
         new_unittest("narrow_region_between_samples", narrow_region_between_samples), &
         new_unittest("equation_along_either_axis", equation_along_either_axis), &
         new_unittest("equation_axes_swapped", equation_axes_swapped), &
         new_unittest("bad_ranges_refused", bad_ranges_refused)])
   end function collect_critical

   !> Every ν in [lo, hi] where the curve (kind, n) passes β: GSL's values on 3000 steps of
   !> ν, each sign change bisected on them (appended to `roots`, counted in `count`).
   subroutine gsl_crossings(kind, n, beta, lo, hi, roots, count)
      integer, intent(in) :: kind, n
      real(wp), intent(in) :: beta, lo, hi
      real(wp), intent(inout) :: roots(:)
      integer, intent(inout) :: count
      type(error_t), allocatable :: error
      real(wp) :: a, b, fa, fb, fm, nu, value
      integer :: i, step
      integer, parameter :: steps = 3000
      a = lo
      call mathieu_transition_beta(kind, n, a, value, error)
      fa = value - beta
      do step = 1, steps
         b = lo + (hi - lo)*real(step, wp)/real(steps, wp)
         call mathieu_transition_beta(kind, n, b, value, error)
         fb = value - beta
         if (fa*fb < 0.0_wp) then
            block
               real(wp) :: left, right, f_left
               left = a
               right = b
               f_left = fa
               do i = 1, 200
                  nu = 0.5_wp*(left + right)
                  call mathieu_transition_beta(kind, n, nu, value, error)
                  fm = value - beta
                  if (f_left*fm <= 0.0_wp) then
                     right = nu
                  else
                     left = nu
                     f_left = fm
                  end if
                  if (right - left <= 1.0e-14_wp*max(1.0_wp, nu)) exit
               end do
               count = count + 1
               roots(count) = 0.5_wp*(left + right)
            end block
         end if
         a = b
         fa = fb
      end do
   end subroutine gsl_crossings

   !> β = 5 and β = −1.3, α in [0.02, 30]: the crossings of the curves a_0 … a_7, b_1 … b_7
   !> found on GSL's values (a_1 rises and falls again: it crosses β = 5 twice), the same count and each
   !> within the error bound the search states (at most 1e-8 relative), every one confirmed.
   subroutine mathieu_against_gsl(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(mathieu_model_t) :: mathieu
      type(critical_drive_t), allocatable :: drives(:)
      type(error_t), allocatable :: error
      real(wp) :: reference(64), betas(2)
      integer :: count, n, kind, j, m, t, nearest
      betas = [5.0_wp, -1.3_wp]
      do t = 1, size(betas)
         count = 0
         do kind = mathieu_kind_a, mathieu_kind_b
            do n = merge(0, 1, kind == mathieu_kind_a), 7
               call gsl_crossings(kind, n, betas(t), 0.02_wp, 30.0_wp, reference, count)
            end do
         end do
         call critical_drives(mathieu, betas(t), 0.02_wp, 30.0_wp, 0.0_wp, method_t(tolerance=1.0e-11_wp), 300, &
                              drives, error)
         call check(ctx, .not. allocated(error), "the search runs")
         if (allocated(error)) return
         call check(ctx, size(drives) == count .and. count >= 2, "as many crossings as GSL's curves give: "// &
                    trim(adjustl(int_text(size(drives))))//" and "//trim(adjustl(int_text(count))))
         do j = 1, size(drives)
            nearest = 1
            do m = 2, count
               if (abs(reference(m) - drives(j)%alpha) < abs(reference(nearest) - drives(j)%alpha)) nearest = m
            end do
            call check(ctx, abs(drives(j)%alpha - reference(nearest)) <= drives(j)%alpha_error + &
                       1.0e-12_wp*reference(nearest), "within its error bound")
            call check(ctx, drives(j)%alpha_error <= 1.0e-8_wp*max(1.0_wp, drives(j)%alpha), "a tight bound")
            call check(ctx, drives(j)%status == status_ok, "confirmed on both sides")
            if (j > 1) call check(ctx, drives(j)%alpha > drives(j - 1)%alpha, "ascending")
            if (j > 1) call check(ctx, drives(j)%direction == -drives(j - 1)%direction, "stable and unstable alternate")
         end do
      end do
   end subroutine mathieu_against_gsl

   !> θ'' + κθ' + (−g/l + (Aω²/l) cos ωt) θ = 0 at l = 0.2 m, κ = 0.2 1/s, 50 Hz: in
   !> τ = ωt/π, Mathieu's Q = β − α cos πτ with β = −gπ²/(lω²), α = Aπ²/l, ε = κπ/ω. The
   !> upright position is unstable at A = 0 and first stable from A = 6.30680 mm (a
   !> 150-digit reference); √(2gl)/ω = 6.30543 mm to first order; the window closes again
   !> near 91.0 mm.
   subroutine kapitza_least_amplitude(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(mathieu_model_t) :: mathieu
      type(critical_drive_t), allocatable :: drives(:)
      type(error_t), allocatable :: error
      real(wp), parameter :: g = 9.81_wp, l = 0.2_wp, kappa = 0.2_wp
      real(wp) :: omega, beta, epsilon, amplitude
      omega = 2.0_wp*pi*50.0_wp
      beta = -g*pi2/(l*omega**2)
      epsilon = kappa*pi/omega
      call critical_drives(mathieu, beta, 0.0_wp, 0.1_wp*pi2/l, epsilon, method_t(tolerance=1.0e-12_wp), 400, &
                           drives, error)
      call check(ctx, .not. allocated(error), "the search runs")
      if (allocated(error)) return
      call check(ctx, size(drives) >= 2, "the stable window opens and closes in A < 0.1 m")
      if (size(drives) < 2) return
      amplitude = drives(1)%alpha*l/pi2
      call check(ctx, amplitude, 6.30680e-3_wp, abs=5.0e-9_wp, message="the least stabilising amplitude")
      call check(ctx, drives(1)%direction == -1, "stable above it")
      call check(ctx, abs(amplitude - sqrt(2.0_wp*g*l)/omega) < 2.0e-6_wp, "near sqrt(2gl)/omega")
      call check(ctx, drives(2)%alpha*l/pi2, 91.0e-3_wp, abs=0.6e-3_wp, message="the window closes")
      call check(ctx, drives(2)%direction == 1, "unstable above it")
   end subroutine kapitza_least_amplitude

   !> The damped Kapitza pendulum written as its user writes it (model equation, axes ω and
   !> A): along β, the critical amplitudes at 50 Hz are the Mathieu model's at the hand-made
   !> mapping α = Aπ²/l, β = −gπ²/(lω²), ε = κπ/ω (within the two bounds; 6.30680 mm first);
   !> along α, the critical frequencies at A = 8 mm, where the damping κπ/ω changes with the
   !> frequency searched, each confirmed by the equation's own verdicts on both sides and
   !> the first one inside (ω where A ω = √(2gl) ± 1 %); ε ≠ 0 refused for the equation.
   subroutine equation_along_either_axis(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(equation_model_t) :: kapitza
      type(mathieu_model_t) :: mathieu
      type(critical_drive_t), allocatable :: drives(:), mapped(:)
      type(error_t), allocatable :: error
      type(trace_t) :: tr
      real(wp), parameter :: g = 9.81_wp, l = 0.2_wp, kappa = 0.2_wp
      real(wp) :: omega, eps, s(2), threshold, w, x
      integer :: j, side
      call kapitza%set_text("parameters", "g = 9.81, l = 0.2, kappa = 0.2, A = 0.005, w = 314.16", error)
      call kapitza%set_text("stiffness", "-g/l + A*w^2/l*cos(w*t)", error)
      call kapitza%set_text("damping", "kappa", error)
      call kapitza%set_text("frequency", "w", error)
      call kapitza%set_text("alpha", "w", error)
      call kapitza%set_text("beta", "A", error)
      call kapitza%check_values(error)
      call check(ctx, .not. allocated(error), "the equation")
      if (allocated(error)) return
      omega = 2.0_wp*pi*50.0_wp
      call critical_drives_along(kapitza, along_beta, omega, 0.0_wp, 0.1_wp, 0.0_wp, method_t(tolerance=1.0e-12_wp), &
                                 400, drives, error)
      call check(ctx, .not. allocated(error), "along beta runs")
      if (allocated(error)) return
      call critical_drives(mathieu, -g*pi2/(l*omega**2), 0.0_wp, 0.1_wp*pi2/l, kappa*pi/omega, &
                           method_t(tolerance=1.0e-12_wp), 400, mapped, error)
      call check(ctx, size(drives) == size(mapped) .and. size(drives) >= 2, "as many changes as mapped by hand")
      do j = 1, min(size(drives), size(mapped))
         call check(ctx, abs(drives(j)%alpha - mapped(j)%alpha*l/pi2) <= drives(j)%alpha_error + &
                    mapped(j)%alpha_error*l/pi2 + 1.0e-15_wp, "change "//real_text(real(j, wp))//": A = "// &
                    real_text(drives(j)%alpha)//" against "//real_text(mapped(j)%alpha*l/pi2))
         call check(ctx, drives(j)%direction == mapped(j)%direction .and. drives(j)%status == status_ok, &
                    "direction and confirmation of change "//real_text(real(j, wp)))
      end do
      if (size(drives) > 0) call check(ctx, drives(1)%alpha, 6.30680e-3_wp, abs=5.0e-9_wp, &
                                       message="the least stabilising amplitude at 50 Hz")
      ! along alpha: the frequencies at A = 8 mm, the damping changing with them
      call critical_drives_along(kapitza, along_alpha, 0.008_wp, 100.0_wp, 700.0_wp, 0.0_wp, &
                                 method_t(tolerance=1.0e-12_wp), 200, drives, error)
      call check(ctx, .not. allocated(error) .and. size(drives) >= 1, "along alpha finds a change")
      if (allocated(error) .or. size(drives) < 1) return
      call check(ctx, abs(drives(1)%alpha*0.008_wp/sqrt(2.0_wp*g*l) - 1.0_wp) < 0.01_wp, &
                 "the first at A w = sqrt(2 g l) within 1 %: w = "//real_text(drives(1)%alpha))
      do j = 1, size(drives)
         call check(ctx, drives(j)%status == status_ok, "confirmed: change "//real_text(real(j, wp)))
         ! the equation's own verdicts just either side (stable where the direction says)
         do side = -1, 1, 2
            w = drives(j)%alpha + side*4.0_wp*max(drives(j)%alpha_error, 1.0e-9_wp*drives(j)%alpha)
            eps = kapitza%point_damping(w, 0.0_wp)
            call monodromy_trace(kapitza, hill_point_t(w, 0.008_wp, eps), method_t(tolerance=1.0e-12_wp), tr, error)
            if (allocated(error)) deallocate (error)
            threshold = 2.0_wp*cosh(eps)
            s(1) = abs(tr%value) - threshold
            x = merge(1.0_wp, -1.0_wp, (side == 1) .eqv. (drives(j)%direction == 1))
            call check(ctx, x*s(1) > 0.0_wp, "the verdict on side "//real_text(real(side, wp))//" of change "// &
                       real_text(real(j, wp)))
         end do
      end do
      call critical_drives_along(kapitza, along_beta, omega, 0.0_wp, 0.1_wp, 0.1_wp, method_t(), 40, drives, error)
      call check(ctx, allocated(error), "epsilon refused for an equation")
      if (allocated(error)) call check(ctx, index(error%message, "epsilon") == 1, "named: "//error%message)
   end subroutine equation_along_either_axis

   !> The damped Kapitza pendulum with its axes swapped (alpha = 'A', beta = 'w': the frequency
   !> and the damping κπ/ω along β, each point the equation at its ω): along α at 50 Hz the
   !> critical amplitudes of the unswapped equation along β, the first 6.30680 mm; along β at
   !> A = 8 mm its critical frequencies along α; each pair within the two error bounds.
   subroutine equation_axes_swapped(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(equation_model_t) :: kapitza, swapped
      type(critical_drive_t), allocatable :: drives(:), mapped(:)
      type(error_t), allocatable :: error
      integer :: j, axis
      character(len=*), parameter :: parameters = "g = 9.81, l = 0.2, kappa = 0.2, A = 0.005, w = 314.16"
      real(wp) :: omega
      call kapitza%set_text("parameters", parameters, error)
      call kapitza%set_text("stiffness", "-g/l + A*w^2/l*cos(w*t)", error)
      call kapitza%set_text("damping", "kappa", error)
      call kapitza%set_text("frequency", "w", error)
      swapped = kapitza
      call kapitza%set_text("alpha", "w", error)
      call kapitza%set_text("beta", "A", error)
      call kapitza%check_values(error)
      call check(ctx, .not. allocated(error), "the equation over (w, A)")
      call swapped%set_text("alpha", "A", error)
      call swapped%set_text("beta", "w", error)
      call swapped%check_values(error)
      call check(ctx, .not. allocated(error), "the equation over (A, w)")
      if (allocated(error)) return
      call check(ctx, kapitza%shares_rows() .and. .not. swapped%shares_rows(), "only the first shares its rows")
      omega = 2.0_wp*pi*50.0_wp
      do axis = 1, 2
         if (axis == 1) then
            call critical_drives_along(swapped, along_alpha, omega, 0.0_wp, 0.1_wp, 0.0_wp, &
                                       method_t(tolerance=1.0e-12_wp), 400, drives, error)
            if (.not. allocated(error)) call critical_drives_along(kapitza, along_beta, omega, 0.0_wp, 0.1_wp, 0.0_wp, &
                                                                   method_t(tolerance=1.0e-12_wp), 400, mapped, error)
         else
            call critical_drives_along(swapped, along_beta, 0.008_wp, 100.0_wp, 700.0_wp, 0.0_wp, &
                                       method_t(tolerance=1.0e-12_wp), 200, drives, error)
            if (.not. allocated(error)) call critical_drives_along(kapitza, along_alpha, 0.008_wp, 100.0_wp, 700.0_wp, &
                                                                   0.0_wp, method_t(tolerance=1.0e-12_wp), 200, mapped, &
                                                                   error)
         end if
         call check(ctx, .not. allocated(error), "axis "//real_text(real(axis, wp))//": both run")
         if (allocated(error)) then
            call check(ctx, .false., error%message)
            return
         end if
         call check(ctx, size(drives) == size(mapped) .and. size(drives) >= 1, "axis "//real_text(real(axis, wp))// &
                    ": as many changes, "//real_text(real(size(drives), wp)))
         do j = 1, min(size(drives), size(mapped))
            call check(ctx, abs(drives(j)%alpha - mapped(j)%alpha) <= drives(j)%alpha_error + mapped(j)%alpha_error + &
                       1.0e-15_wp*abs(mapped(j)%alpha), "axis "//real_text(real(axis, wp))//", change "// &
                       real_text(real(j, wp))//": "//real_text(drives(j)%alpha)//" against "//real_text(mapped(j)%alpha))
            call check(ctx, drives(j)%direction == mapped(j)%direction .and. drives(j)%status == status_ok, &
                       "axis "//real_text(real(axis, wp))//": direction and confirmation of change "// &
                       real_text(real(j, wp)))
         end do
         if (axis == 1 .and. size(drives) > 0) call check(ctx, drives(1)%alpha, 6.30680e-3_wp, abs=5.0e-9_wp, &
                                                          message="the least stabilising amplitude at 50 Hz")
      end do
   end subroutine equation_axes_swapped

   !> The undamped Kapitza pendulum (l = 0.2 m) at 10 frequencies from 30 to 120 Hz: its
   !> least stabilising amplitude is where Mathieu's a_0(q) = −4g/(lω²), q = 2A/l. Against
   !> that equation solved on GSL's a_0 (relative 1e-9), the series a_0 ≈ −q²/2 + 7q⁴/128
   !> (relative q⁴, its next term's order) and the first order Aω = √(2gl) (relative q²).
   subroutine kapitza_ten_frequencies(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(mathieu_model_t) :: mathieu
      type(critical_drive_t), allocatable :: drives(:)
      type(error_t), allocatable :: error
      real(wp), parameter :: g = 9.81_wp, l = 0.2_wp
      real(wp) :: omega, a, amplitude, q, lo, hi, mid, value, series
      integer :: f, i
      do f = 1, 10
         omega = 2.0_wp*pi*(30.0_wp + 10.0_wp*(f - 1))
         a = -4.0_wp*g/(l*omega**2)
         call critical_drives(mathieu, 0.25_wp*pi2*a, 0.0_wp, 2.0_wp*pi2/l*sqrt(2.0_wp*g*l)/omega, 0.0_wp, &
                              method_t(tolerance=1.0e-12_wp), 100, drives, error)
         call check(ctx, .not. allocated(error) .and. size(drives) == 1, "one change below twice the first order")
         if (allocated(error) .or. size(drives) /= 1) cycle
         amplitude = drives(1)%alpha*l/pi2
         ! a_0(q) = a on GSL's values: a_0 falls with q
         lo = 0.0_wp
         hi = 1.0_wp
         do i = 1, 200
            mid = 0.5_wp*(lo + hi)
            call mathieu_a(0, mid, value, error)
            if (value > a) then
               lo = mid
            else
               hi = mid
            end if
         end do
         q = 0.5_wp*(lo + hi)
         call check(ctx, amplitude, 0.5_wp*q*l, rel=1.0e-9_wp, message="a_0(q) = -4g/(l w^2) on GSL's values")
         ! −q²/2 + 7q⁴/128 = a: q² = (32/7)(1 − sqrt(1 + 7a/8)), the root that vanishes with a
         series = 0.5_wp*l*sqrt((32.0_wp/7.0_wp)*(1.0_wp - sqrt(1.0_wp + 7.0_wp*a/8.0_wp)))
         call check(ctx, abs(amplitude - series) <= q**4*amplitude, "the series to order q^4")
         call check(ctx, abs(amplitude*omega - sqrt(2.0_wp*g*l)) <= q**2*amplitude*omega, "A w = sqrt(2 g l) to order q^2")
         call check(ctx, drives(1)%direction == -1 .and. drives(1)%status == status_ok, "stable above, confirmed")
      end do
   end subroutine kapitza_ten_frequencies

   !> Regions narrower than the samples: at β = 40 the region between b_4's and a_4's
   !> crossings (α ≈ 11.93 … 12.89, 1 wide) with 4 samples over [0.02, 30] (10 apart), and at
   !> β = 6.21 the region where a_1 passes above β (α ≈ 13.38 … 15.02) with 8 samples: the
   !> crossings of a search with 3000 samples, at the same places within their bounds.
   subroutine narrow_region_between_samples(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(mathieu_model_t) :: mathieu
      type(critical_drive_t), allocatable :: coarse(:), fine(:)
      type(error_t), allocatable :: error
      real(wp), parameter :: betas(2) = [40.0_wp, 6.21_wp]
      integer, parameter :: samples(2) = [4, 8]
      integer :: j, t
      do t = 1, 2
         call critical_drives(mathieu, betas(t), 0.02_wp, 30.0_wp, 0.0_wp, method_t(tolerance=1.0e-11_wp), 3000, &
                              fine, error)
         call check(ctx, .not. allocated(error), "fine search runs")
         call critical_drives(mathieu, betas(t), 0.02_wp, 30.0_wp, 0.0_wp, method_t(tolerance=1.0e-11_wp), &
                              samples(t), coarse, error)
         call check(ctx, .not. allocated(error), "coarse search runs")
         if (allocated(error)) return
         call check(ctx, size(fine) >= 2 .and. size(coarse) == size(fine), "the same crossings with few samples "// &
                    "as with 3000: "//trim(adjustl(int_text(size(coarse))))//" and "//trim(adjustl(int_text(size(fine)))))
         if (size(coarse) /= size(fine)) cycle
         do j = 1, size(fine)
            call check(ctx, abs(coarse(j)%alpha - fine(j)%alpha) <= coarse(j)%alpha_error + fine(j)%alpha_error, &
                       "the same position")
            call check(ctx, coarse(j)%status == status_ok, "confirmed")
         end do
      end do
   end subroutine narrow_region_between_samples

   !> An empty or non-finite range, too few samples, a negative damping: err_invalid_parameter
   !> naming the argument.
   subroutine bad_ranges_refused(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(mathieu_model_t) :: mathieu
      type(critical_drive_t), allocatable :: drives(:)
      type(error_t), allocatable :: error
      real(wp) :: zero
      zero = 0.0_wp
      call critical_drives(mathieu, 1.0_wp, 2.0_wp, 1.0_wp, 0.0_wp, method_t(), 10, drives, error)
      call refused("alpha_min, alpha_max", "empty range")
      call critical_drives(mathieu, 1.0_wp, 0.0_wp, huge(1.0_wp)*(1.0_wp + zero), 0.0_wp, method_t(), 1, drives, error)
      call refused("n_samples", "one sample")
      call critical_drives(mathieu, 1.0_wp, 0.0_wp, 1.0_wp, -0.5_wp, method_t(), 10, drives, error)
      call check(ctx, allocated(error), "a negative damping refused")
      if (allocated(error)) call check(ctx, error%code == err_invalid_parameter, "as an invalid parameter")
   contains
      subroutine refused(part, what)
         character(len=*), intent(in) :: part, what
         call check(ctx, allocated(error), what//": refused")
         if (.not. allocated(error)) return
         call check(ctx, error%code == err_invalid_parameter .and. index(error%message, part) == 1, &
                    what//": names "//part//": "//error%message)
      end subroutine refused
   end subroutine bad_ranges_refused

   pure function int_text(i) result(text)
      integer, intent(in) :: i
      character(len=12) :: text
      write (text, '(i0)') i
   end function int_text
end module test_critical

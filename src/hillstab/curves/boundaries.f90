!> Transition curves beyond the eigenvalues: the independent check of a boundary by
!> method auto, the boundaries of the approximate methods (the paper's eq. (37),
!> N-piece segmentation) by a bracketing root finder, and the unstable β intervals of
!> both (for the misclassified area); the GSL witness for the Mathieu model
!> (`mathieu_witness`) is re-exported from hillstab_hill_mathieu.
!> Numerics only: no files, no namelists.
!>
!> - `verify_boundary`: S(α, β) by method auto at the boundary. It passes when
!>   |S ∓ 2| ≤ 2·tolerance·max(1, |S|) (the trace error auto guarantees), or when the
!>   β error this residual implies, (|S ∓ 2| − that allowance)/|dS/dβ|, is at most
!>   `beta_accuracy_factor`·tolerance·max(1, |β|); dS/dβ by a centred difference of auto.
!> - `curve_route`, `exact_boundaries`: the exact transition curves of any model, by the
!>   route that suits it: Hill's method on the pencil (`hill_form_pencil`: elastic, Mathieu),
!>   Hill's method on the Fourier coefficients of g = Q − β (a finite `drive_harmonic_count`,
!>   hillstab_curves_hill_fourier), or else root finding on S by method auto
!>   (`approximate_boundaries` with an exact method: infinitely many harmonics, a jump of Q,
!>   where the truncation converges slowly, or a model not of the form β + g). Each curve
!>   says its route (`hill_boundary_t%route`).
!> - `approximate_boundaries`: the roots of S_method(β) = ±2 for the closed-form or
!>   segmented methods (or an exact one): S sampled on `n_samples` points from below every boundary
!>   (β ≥ −|α| on any curve) to the top of the window, each sign change of S ∓ 2
!>   refined by Brent's method to tolerance·max(1, |β|). The order of a root is its
!>   rank among the roots of its kind counted from below (a₀ | b₁ a₁ | b₂ a₂ …), so
!>   a tongue narrower than the sampling step is missed and shifts the orders above it —
!>   unless `narrow` asks for the search of such tongues (the exact roots route does).
!>
!>```fortran
!> type(boundary_check_t) :: check
!> type(error_t), allocatable :: error
!> call verify_boundary(elastic_model_t(), 5.0_wp, 0.8766005119978297_wp, -2, 1.0e-11_wp, check, error)
!> print *, check%passed, check%trace
!>```
module hillstab_curves_boundaries
   use hillstab_core_kinds, only: wp, pi2
   use hillstab_core_text, only: real_text, integer_text
   use hillstab_core_error, only: error_t, set_error, err_invalid_parameter, err_accuracy
   use hillstab_hill_model, only: hill_model_t, hill_point_t, hill_form_pencil, model_coefficient_range
   use hillstab_hill_transfer, only: trace_t
   use hillstab_integrate_monodromy, only: method_t, method_auto, method_formula, monodromy_trace
   use hillstab_hill_mathieu, only: mathieu_witness, gsl_witness_max_q
   use hillstab_curves_hill_method, only: hill_boundary_t, hill_boundaries, route_pencil, route_fourier, route_roots, &
      route_closed_form, &
      block_periodic, block_antiperiodic
   use hillstab_curves_hill_fourier, only: fourier_boundaries
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   implicit none
   private
   public :: boundary_check_t, verify_boundary, approximate_root_t, approximate_boundaries
   public :: mathieu_witness, gsl_witness_max_q, beta_accuracy_factor, unstable_intervals_from_roots
   public :: interval_length, symmetric_difference_length
   public :: alpha_crossing_t, alpha_crossings, crossing_samples, crossing_search_gap
   public :: curve_route, exact_boundaries, roots_to_curves, beta_floor, default_root_samples

   !> Samples of the bracket search of the roots route over the β window when the caller
   !> gives none.
   integer, parameter :: default_root_samples = 400

   !> A boundary passes the check when the β error implied by the trace residual is at
   !> most this times tolerance·max(1, |β|) (tolerance 1e-11 → 1e-9 at |β| ≤ 1).
   real(wp), parameter :: beta_accuracy_factor = 100.0_wp
   !> Trace allowance (times 1e-8·max(1, |S|)) when auto is limited by round-off there.
   real(wp), parameter :: roundoff_trace_allowance = 1.0e-8_wp

   !> Result of the independent check of one boundary.
   type :: boundary_check_t
      logical :: passed = .false.      !! |S| = 2 to the accuracy (see the module doc)
      logical :: roundoff = .false.    !! auto could give S only to the round-off level there
      real(wp) :: trace = 0.0_wp       !! S by method auto at the boundary
      real(wp) :: slope = 0.0_wp       !! dS/dβ (0 when not needed)
      real(wp) :: beta_error = 0.0_wp  !! β error implied by the residual (0 when within the trace allowance)
   end type boundary_check_t

   !> The search for crossings along α ends at α = π²(1 − crossing_search_gap): a bounce
   !> reaching to within 1e-4 ρ of the pivot (Hill's truncation grows like 1/√(1 − α/π²)).
   real(wp), parameter :: crossing_search_gap = 1.0e-4_wp

   !> One α where a transition curve crosses a fixed β (S = ±2 along α).
   type :: alpha_crossing_t
      real(wp) :: alpha = 0.0_wp        !! α of the crossing
      integer :: trace_sign = 2         !! +2 / −2: S there
      integer :: order = 0              !! n of a_n / b_n
      integer :: parity = 1             !! +1 a_n (even), −1 b_n (odd)
      !> error bound of α: the last bracket or |β_curve − β|/|dβ/dα|, plus the curve's own error
      !> in β over |dβ/dα| (twice each, for the change of the slope)
      real(wp) :: alpha_error = 0.0_wp
      integer :: modes = 0              !! Fourier modes of the last truncation
   end type alpha_crossing_t

   !> The transition curves at one sample α.
   type :: sample_curves_t
      type(hill_boundary_t), allocatable :: curves(:)
      type(error_t), allocatable :: error
   end type sample_curves_t

   !> One root of S_method(β) = ±2.
   type :: approximate_root_t
      real(wp) :: beta = 0.0_wp      !! β of the root
      integer :: trace_sign = 2      !! +2 or −2
      integer :: order = 0           !! n: rank among the roots of its kind (a₀ | b₁ a₁ | …)
      integer :: edge = 1            !! 1 lower, 2 upper edge of the tongue of this order (0 for n = 0)
      real(wp) :: residual = 0.0_wp  !! S_method(β) ∓ 2 at the root
   end type approximate_root_t

contains

   !> S by method auto; `limited` when only the round-off level could be reached.
   subroutine auto_trace(model, alpha, beta, tolerance, s, limited, error)
      class(hill_model_t), intent(in) :: model  !! the model
      real(wp), intent(in) :: alpha, beta, tolerance
      real(wp), intent(out) :: s
      logical, intent(inout) :: limited
      type(error_t), allocatable, intent(out) :: error
      type(trace_t) :: tr
      call monodromy_trace(model, hill_point_t(alpha, beta, 0.0_wp), method_t(method_auto, tolerance=tolerance), &
                           tr, error)
      s = tr%value
      if (allocated(error)) then
         if (error%code /= err_accuracy) return
         deallocate (error)
         limited = .true.
      end if
      if (tr%overflow .or. .not. ieee_is_finite(s)) then
         call set_error(error, err_invalid_parameter, "boundary check: S overflows at a boundary")
      end if
   end subroutine auto_trace

   !> Check a boundary independently: S(α, β) = trace_sign by method auto.
   subroutine verify_boundary(model, alpha, beta, trace_sign, tolerance, check, error)
      class(hill_model_t), intent(in) :: model           !! the model
      real(wp), intent(in) :: alpha, beta   !! the boundary point
      integer, intent(in) :: trace_sign     !! +2 or −2
      real(wp), intent(in) :: tolerance     !! the tolerance the boundary was computed to
      type(boundary_check_t), intent(out) :: check  !! S by auto at the point and its distance from trace_sign
      type(error_t), allocatable, intent(out) :: error  !! auto failed at the point; unallocated on success
      real(wp) :: residual, allowance, h, s_plus, s_minus
      call auto_trace(model, alpha, beta, tolerance, check%trace, check%roundoff, error)
      if (allocated(error)) return
      residual = abs(check%trace - trace_sign)
      allowance = 2.0_wp*tolerance*max(1.0_wp, abs(check%trace))
      if (check%roundoff) allowance = max(allowance, roundoff_trace_allowance*max(1.0_wp, abs(check%trace)))
      if (residual <= allowance) then
         check%passed = .true.
         return
      end if
      h = 1.0e-5_wp*max(1.0_wp, abs(beta))
      call auto_trace(model, alpha, beta + h, tolerance, s_plus, check%roundoff, error)
      if (allocated(error)) return
      call auto_trace(model, alpha, beta - h, tolerance, s_minus, check%roundoff, error)
      if (allocated(error)) return
      check%slope = (s_plus - s_minus)/(2.0_wp*h)
      if (check%slope == 0.0_wp) then
         check%beta_error = huge(1.0_wp)
      else
         check%beta_error = (residual - allowance)/abs(check%slope)
      end if
      check%passed = check%beta_error <= beta_accuracy_factor*tolerance*max(1.0_wp, abs(beta))
   end subroutine verify_boundary

   !> S_method(α, β) − target, finite (an overflowing S keeps its sign, clamped).
   subroutine shifted_trace(model, alpha, beta, method, target, value, error)
      class(hill_model_t), intent(in) :: model  !! the model
      real(wp), intent(in) :: alpha, beta
      type(method_t), intent(in) :: method
      real(wp), intent(in) :: target
      real(wp), intent(out) :: value
      type(error_t), allocatable, intent(out) :: error
      type(trace_t) :: tr
      call monodromy_trace(model, hill_point_t(alpha, beta, 0.0_wp), method, tr, error)
      if (allocated(error)) then
         if (error%code /= err_accuracy) return
         deallocate (error)
      end if
      value = sign(min(abs(tr%value), 1.0e300_wp), tr%value) - target
   end subroutine shifted_trace

   !> Brent's method for S_method(β) = target on [a, b] with a sign change.
   subroutine brent_root(model, alpha, method, target, a_in, b_in, fa_in, fb_in, xtol, root, residual, error)
      class(hill_model_t), intent(in) :: model  !! the model
      real(wp), intent(in) :: alpha, target, a_in, b_in, fa_in, fb_in, xtol
      type(method_t), intent(in) :: method
      real(wp), intent(out) :: root, residual
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: a, b, c, d, e, fa, fb, fc, p, q, r, s, tol1, xm
      integer :: iteration
      a = a_in; b = b_in; fa = fa_in; fb = fb_in
      c = b; fc = fb; d = b - a; e = d
      do iteration = 1, 200
         if ((fb > 0.0_wp .and. fc > 0.0_wp) .or. (fb < 0.0_wp .and. fc < 0.0_wp)) then
            c = a; fc = fa; d = b - a; e = d
         end if
         if (abs(fc) < abs(fb)) then
            a = b; b = c; c = a
            fa = fb; fb = fc; fc = fa
         end if
         tol1 = 2.0_wp*epsilon(1.0_wp)*abs(b) + 0.5_wp*xtol
         xm = 0.5_wp*(c - b)
         if (abs(xm) <= tol1 .or. fb == 0.0_wp) exit
         if (abs(e) >= tol1 .and. abs(fa) > abs(fb)) then
            s = fb/fa
            if (a == c) then
               p = 2.0_wp*xm*s
               q = 1.0_wp - s
            else
               q = fa/fc
               r = fb/fc
               p = s*(2.0_wp*xm*q*(q - r) - (b - a)*(r - 1.0_wp))
               q = (q - 1.0_wp)*(r - 1.0_wp)*(s - 1.0_wp)
            end if
            if (p > 0.0_wp) q = -q
            p = abs(p)
            if (2.0_wp*p < min(3.0_wp*xm*q - abs(tol1*q), abs(e*q))) then
               e = d
               d = p/q
            else
               d = xm; e = d
            end if
         else
            d = xm; e = d
         end if
         a = b; fa = fb
         if (abs(d) > tol1) then
            b = b + d
         else
            b = b + sign(tol1, xm)
         end if
         call shifted_trace(model, alpha, b, method, target, fb, error)
         if (allocated(error)) return
      end do
      root = b
      residual = fb
   end subroutine brent_root

   !> The route of a model's exact transition curves: route_pencil for a model with Hill's
   !> pencil form, route_closed_form for a model whose trace has the closed form of method
   !> formula (`two_pieces_exact`: Meissner's square wave, whose Fourier series never ends),
   !> route_fourier for Q = β + g with finitely many harmonics, route_roots for the rest
   !> (infinitely many harmonics, or no form Hill's method knows).
   pure integer function curve_route(model) result(route)
      class(hill_model_t), intent(in) :: model  !! the model
      if (model%two_pieces_exact()) then
         route = route_closed_form
      else if (model%hill_form() == hill_form_pencil) then
         route = route_pencil
      else if (model%drive_harmonic_count() > 0) then
         route = route_fourier
      else
         route = route_roots
      end if
   end function curve_route

   !> A β below every transition curve of the model at α: −|α| − 1 for the pencil models
   !> (every curve of a weighted Hill equation lies at β ≥ −|α|), else −max Q(τ; α, β = 0) − 1
   !> (for Q = β + g the operator −d² − g is ≥ −sup g), doubled until Q < 0 over the whole
   !> period there (by the model's range of Q), for a model whose β is a weighted eigenvalue
   !> (Q = β w + v, w > 0: no solution oscillates where Q < 0 everywhere, and Q grows with β).
   pure real(wp) function beta_floor(model, alpha) result(floor)
      class(hill_model_t), intent(in) :: model  !! the model
      real(wp), intent(in) :: alpha             !! α
      real(wp) :: q_min, q_max
      integer :: i
      if (model%hill_form() == hill_form_pencil) then
         floor = -abs(alpha) - 1.0_wp
      else
         call model_coefficient_range(model, hill_point_t(alpha, 0.0_wp, 0.0_wp), q_min, q_max)
         floor = -max(q_max, abs(q_min)) - 1.0_wp
         do i = 1, 40
            call model_coefficient_range(model, hill_point_t(alpha, floor, 0.0_wp), q_min, q_max)
            if (q_max < 0.0_wp .or. floor < -1.0e14_wp) exit
            floor = 2.0_wp*floor
         end do
      end if
   end function beta_floor

   !> The exact transition curves crossing [beta_min, beta_max] at α, by the model's route
   !> (`curve_route`): Hill's method on the pencil or on the Fourier coefficients (converged
   !> to tolerance·max(1, |β|)), or the roots of S = ±2 by method auto at `tolerance`, refined
   !> by Brent's method from brackets sampled at `n_samples` points over the window (default
   !> `default_root_samples`; tongues narrower than a step are sought where |S ∓ 2| has a
   !> local minimum among the samples: `approximate_boundaries`' `narrow`). Ordered by β,
   !> each with its route.
   subroutine exact_boundaries(model, alpha, beta_min, beta_max, tolerance, curves, error, n_samples)
      class(hill_model_t), intent(in) :: model    !! the model
      real(wp), intent(in) :: alpha               !! α
      real(wp), intent(in) :: beta_min, beta_max  !! the β window
      real(wp), intent(in) :: tolerance           !! target accuracy of β, relative to max(1, |β|)
      type(hill_boundary_t), allocatable, intent(out) :: curves(:)  !! the curves, by beta
      !> failure of Hill's method or of auto at a sample; unallocated on success
      type(error_t), allocatable, intent(out) :: error
      integer, intent(in), optional :: n_samples  !! samples of the roots route's bracket search
      type(approximate_root_t), allocatable :: roots(:)
      integer :: samples, route, method
      route = curve_route(model)
      select case (route)
      case (route_pencil)
         call hill_boundaries(model, alpha, beta_min, beta_max, tolerance, curves, error)
      case (route_fourier)
         call fourier_boundaries(model, alpha, beta_min, beta_max, tolerance, curves, error)
      case default
         samples = default_root_samples
         if (present(n_samples)) samples = n_samples
         allocate (curves(0))
         if (.not. (ieee_is_finite(beta_min) .and. ieee_is_finite(beta_max) .and. ieee_is_finite(tolerance) &
                    .and. ieee_is_finite(alpha))) then
            call set_error(error, err_invalid_parameter, "transition curves: alpha, the beta window and the "// &
               "tolerance must be finite")
            return
         end if
         if (beta_min > beta_max .or. .not. tolerance > 0.0_wp) then
            call set_error(error, err_invalid_parameter, "transition curves: need beta_min <= beta_max and tolerance > 0")
            return
         end if
         method = merge(method_formula, method_auto, route == route_closed_form)
         call approximate_boundaries(model, alpha, method_t(method, tolerance=tolerance), beta_min, beta_max, &
                                     max(samples, 2), tolerance, roots, error, floor=beta_floor(model, alpha), &
                                     narrow=.true.)
         if (allocated(error)) return
         curves = roots_to_curves(roots, tolerance)
         curves%route = route
      end select
   end subroutine exact_boundaries

   !> Roots of S = ±2 (`approximate_boundaries` with an exact method) as transition curves of
   !> the roots route: the coupled block of their kind, parity 0 with their edge, error bound
   !> tolerance·max(1, |β|) (the root finder's).
   pure function roots_to_curves(roots, tolerance) result(curves)
      type(approximate_root_t), intent(in) :: roots(:)     !! the roots, ascending
      real(wp), intent(in) :: tolerance                    !! their accuracy relative to max(1, |β|)
      type(hill_boundary_t), allocatable :: curves(:)
      integer :: i
      allocate (curves(size(roots)))
      do i = 1, size(roots)
         curves(i)%beta = roots(i)%beta
         curves(i)%trace_sign = roots(i)%trace_sign
         curves(i)%order = roots(i)%order
         curves(i)%parity = 0
         curves(i)%edge = roots(i)%edge
         curves(i)%block = merge(block_periodic, block_antiperiodic, roots(i)%trace_sign == 2)
         curves(i)%route = route_roots
         curves(i)%modes = 0
         curves(i)%change = 0.0_wp
         curves(i)%error_bound = tolerance*max(1.0_wp, abs(roots(i)%beta))
         curves(i)%truncated_drive = .false.
         curves(i)%coexistent = .false.
      end do
   end function roots_to_curves

   !> The roots of S_method(β) = ±2 in [beta_min, beta_max] for an approximate method
   !> (formula or segments), with their orders, ascending in β.
   subroutine approximate_boundaries(model, alpha, method, beta_min, beta_max, n_samples, tolerance, roots, error, &
                                     floor, narrow)
      class(hill_model_t), intent(in) :: model            !! the model
      real(wp), intent(in) :: alpha          !! α (ν)
      type(method_t), intent(in) :: method   !! method_formula or method_segments
      real(wp), intent(in) :: beta_min, beta_max  !! the beta window searched
      integer, intent(in) :: n_samples       !! sampling points of the bracket search over the window
      real(wp), intent(in) :: tolerance      !! root accuracy, relative to max(1, |β|)
      type(approximate_root_t), allocatable, intent(out) :: roots(:)  !! the roots with their orders, ascending in beta
      type(error_t), allocatable, intent(out) :: error  !! the method failed at a sample; unallocated on success
      !> a β below every curve, where the search starts (default −|α| − 1, right for the
      !> elastic and Mathieu models; `beta_floor` for the others)
      real(wp), intent(in), optional :: floor
      !> also look for tongues narrower than a sample step (`narrow_pair`): where |S ∓ 2| has
      !> a local minimum among the samples without a sign change, the extremum of S between
      !> the neighbouring samples is sought and, where it crosses ±2, both edges are refined
      logical, intent(in), optional :: narrow
      real(wp) :: low, step, b0, b1, root, residual, targets(2)
      real(wp), allocatable :: f(:, :)
      integer :: n, i, t, count_kind(2), m
      logical :: look_narrow
      type(approximate_root_t), allocatable :: found(:)
      real(wp), allocatable :: keys(:)
      allocate (roots(0), found(0))
      look_narrow = .false.
      if (present(narrow)) look_narrow = narrow
      if (n_samples < 2) then
         call set_error(error, err_invalid_parameter, "approximate boundaries: need at least 2 samples")
         return
      end if
      ! every curve of a weighted Hill equation lies at β ≥ −|α|; start below it
      low = min(beta_min, -abs(alpha) - 1.0_wp)
      if (present(floor)) low = min(beta_min, floor)
      step = (beta_max - beta_min)/real(n_samples - 1, wp)
      if (step <= 0.0_wp) step = 1.0_wp
      n = n_samples + ceiling((beta_min - low)/step)
      targets = [2.0_wp, -2.0_wp]
      allocate (f(0:n - 1, 2))
      do i = 0, n - 1
         call shifted_trace(model, alpha, sample(i), method, 0.0_wp, f(i, 1), error)
         if (allocated(error)) return
         f(i, 2) = f(i, 1) - targets(2)
         f(i, 1) = f(i, 1) - targets(1)
      end do
      count_kind = 0
      do i = 0, n - 2
         b0 = sample(i); b1 = sample(i + 1)
         do t = 1, 2
            if (look_narrow .and. i > 0) then
               call narrow_pair(i, t)
               if (allocated(error)) return
            end if
            if (f(i, t) == 0.0_wp) then
               root = b0; residual = 0.0_wp
            else if (f(i, t)*f(i + 1, t) < 0.0_wp) then
               call brent_root(model, alpha, method, targets(t), b0, b1, f(i, t), f(i + 1, t), &
                               tolerance*max(1.0_wp, abs(b0), abs(b1)), root, residual, error)
               if (allocated(error)) return
            else
               cycle
            end if
            call record(t, root, residual)
         end do
      end do
      ! a narrow pair may lie below a root of the other kind found in the step before
      keys = found%beta
      roots = found(ascending_order(keys))
   contains
      !> Count a root of kind t (in ascending β within its kind) and keep it when inside the window.
      subroutine record(t, root, residual)
         integer, intent(in) :: t
         real(wp), intent(in) :: root, residual
         count_kind(t) = count_kind(t) + 1
         m = count_kind(t)
         if (root < beta_min .or. root > beta_max) return
         if (t == 1) then   ! a0 | b2 a2 | b4 a4 ...: ranks 1 | 2 3 | 4 5
            found = [found, approximate_root_t(root, 2, 2*(m/2), merge(0, 1 + mod(m, 2), m == 1), residual)]
         else               ! b1 a1 | b3 a3 ...: ranks 1 2 | 3 4
            found = [found, approximate_root_t(root, -2, 2*((m - 1)/2) + 1, 2 - mod(m, 2), residual)]
         end if
      end subroutine record

      !> A tongue of kind t between samples i − 1 and i + 1 that no sign change shows: where
      !> f = S ∓ 2 keeps its sign over the three samples and |f| is least at the middle one,
      !> and the parabola through them dips below half that value (or |f| there is below
      !> 1/20 of its neighbours'), the extremum of S is sought by golden sections (up to 50,
      !> stopping at the first value of the other sign); a value of the other sign gives both
      !> edges by Brent's method, a value of exactly ±2 a double root (a closed tongue).
      subroutine narrow_pair(i, t)
         integer, intent(in) :: i, t
         real(wp), parameter :: golden = 0.38196601125010515_wp
         real(wp) :: a, b, c, ga, gb, gc, sgn, x, gx, predicted, first, second, best, g_best, root_low, root_high
         real(wp) :: residual_low, residual_high, value
         integer :: iteration
         if (f(i, t) == 0.0_wp .or. f(i - 1, t)*f(i, t) <= 0.0_wp .or. f(i, t)*f(i + 1, t) <= 0.0_wp) return
         if (.not. (abs(f(i, t)) < abs(f(i - 1, t)) .and. abs(f(i, t)) <= abs(f(i + 1, t)))) return
         sgn = sign(1.0_wp, f(i, t))
         a = sample(i - 1); b = sample(i); c = sample(i + 1)
         ga = sgn*f(i - 1, t); gb = sgn*f(i, t); gc = sgn*f(i + 1, t)
         ! the least value of the parabola through the three samples (Newton's form)
         first = (gb - ga)/(b - a)
         second = ((gc - gb)/(c - b) - first)/(c - a)
         predicted = gb
         if (second > 0.0_wp) then
            x = 0.5_wp*(a + b) - 0.5_wp*first/second
            predicted = ga + first*(x - a) + second*(x - a)*(x - b)
         end if
         if (.not. (predicted < 0.5_wp*gb .or. gb < 0.05_wp*min(ga, gc))) return
         best = b; g_best = gb
         do iteration = 1, 50
            ! golden section on the larger side of the best point
            if (c - best > best - a) then
               x = best + golden*(c - best)
            else
               x = best - golden*(best - a)
            end if
            call shifted_trace(model, alpha, x, method, targets(t), value, error)
            if (allocated(error)) return
            gx = sgn*value
            if (gx <= 0.0_wp) then
               best = x; g_best = gx
               exit
            end if
            if (gx < g_best) then
               if (x > best) then
                  a = best
               else
                  c = best
               end if
               best = x; g_best = gx
            else
               if (x > best) then
                  c = x
               else
                  a = x
               end if
            end if
            if (c - a <= 4.0_wp*epsilon(1.0_wp)*max(1.0_wp, abs(best))) exit
         end do
         if (g_best > 0.0_wp) return
         if (g_best == 0.0_wp) then
            call record(t, best, 0.0_wp)
            call record(t, best, 0.0_wp)
            return
         end if
         call brent_root(model, alpha, method, targets(t), sample(i - 1), best, f(i - 1, t), sgn*g_best, &
                         tolerance*max(1.0_wp, abs(best)), root_low, residual_low, error)
         if (allocated(error)) return
         call brent_root(model, alpha, method, targets(t), best, sample(i + 1), sgn*g_best, f(i + 1, t), &
                         tolerance*max(1.0_wp, abs(best)), root_high, residual_high, error)
         if (allocated(error)) return
         call record(t, root_low, residual_low)
         call record(t, root_high, residual_high)
      end subroutine narrow_pair

      pure real(wp) function sample(j)
         integer, intent(in) :: j
         if (j == n - 1) then
            sample = beta_max
         else
            sample = beta_max - step*real(n - 1 - j, wp)
         end if
      end function sample
   end subroutine approximate_boundaries

   !> The order that sorts `keys` ascending, ties in their given order (an insertion sort of
   !> the indices: the lists are short and nearly sorted): the roots by β, the crossings by α.
   pure function ascending_order(keys) result(order)
      real(wp), intent(in) :: keys(:)  !! the keys
      integer :: order(size(keys))
      integer :: i, j, held
      order = [(i, i=1, size(keys))]
      do i = 2, size(keys)
         held = order(i)
         j = i - 1
         do while (j >= 1)
            if (keys(order(j)) <= keys(held)) exit
            order(j + 1) = order(j)
            j = j - 1
         end do
         order(j + 1) = held
      end do
   end function ascending_order

   !> The unstable β intervals inside [lo, hi] for a method, from its sorted roots of
   !> |S| = 2 in [lo, hi]: between consecutive roots (and the ends) the verdict is
   !> that of S_method at the midpoint.
   subroutine unstable_intervals_from_roots(model, alpha, method, lo, hi, roots, intervals, error)
      class(hill_model_t), intent(in) :: model  !! the model
      real(wp), intent(in) :: alpha, lo, hi  !! alpha (nu); the beta window [lo, hi]
      type(method_t), intent(in) :: method  !! the method whose verdicts are used
      real(wp), intent(in) :: roots(:)   !! ascending, inside [lo, hi]
      real(wp), allocatable, intent(out) :: intervals(:, :)  !! (2, m): [start, end] of each unstable interval
      type(error_t), allocatable, intent(out) :: error  !! the method failed at a midpoint; unallocated on success
      real(wp), allocatable :: cuts(:)
      real(wp) :: s
      integer :: i
      allocate (intervals(2, 0))
      cuts = [lo, roots, hi]
      do i = 1, size(cuts) - 1
         if (cuts(i + 1) <= cuts(i)) cycle
         call shifted_trace(model, alpha, 0.5_wp*(cuts(i) + cuts(i + 1)), method, 0.0_wp, s, error)
         if (allocated(error)) return
         if (abs(s) > 2.0_wp) intervals = reshape([intervals, cuts(i), cuts(i + 1)], [2, size(intervals, 2) + 1])
      end do
   end subroutine unstable_intervals_from_roots

   !> The sample α of the crossing search, ascending from 0 to `alpha_end` < π²: steps of
   !> 0.1 up to 0.9 π², then 8 a decade in the gap 1 − α/π² (where the curves change on
   !> the scale of that gap).
   pure function crossing_samples(alpha_end) result(alphas)
      real(wp), intent(in) :: alpha_end  !! the last α, in (0.9 π², π²)
      real(wp), allocatable :: alphas(:)
      integer :: n_uniform, n_geometric, j
      real(wp) :: gap_end
      n_uniform = ceiling(0.9_wp*pi2/0.1_wp)
      gap_end = 1.0_wp - alpha_end/pi2
      n_geometric = max(1, ceiling(8.0_wp*log10(0.1_wp/gap_end)))
      allocate (alphas(n_uniform + 1 + n_geometric))
      do j = 0, n_uniform
         alphas(j + 1) = 0.9_wp*pi2*real(j, wp)/real(n_uniform, wp)
      end do
      do j = 1, n_geometric
         alphas(n_uniform + 1 + j) = pi2*(1.0_wp - 0.1_wp*(gap_end/0.1_wp)**(real(j, wp)/real(n_geometric, wp)))
      end do
      alphas(size(alphas)) = alpha_end
   end function crossing_samples

   !> Every α in [0, alpha_end] where a transition curve of `kind` crosses the fixed β:
   !> the curves by `exact_boundaries` (β window [−1, π² + 1]) at the samples of
   !> `crossing_samples`, each sign change of β_curve(α) − β between neighbouring samples
   !> refined by the Illinois variant of regula falsi (bisection when it stalls) to
   !> tolerance·max(1, α), or until β_curve − β is within the curves' own accuracy
   !> tolerance·max(1, β). Zero-width tongues (both edges coincide: S touches ±2, the
   !> stability does not change) are skipped. Ascending in α.
   subroutine alpha_crossings(model, beta, alpha_end, tolerance, crossings, error)
      class(hill_model_t), intent(in) :: model           !! the model
      real(wp), intent(in) :: beta          !! the fixed β, inside (0, π²)
      real(wp), intent(in) :: alpha_end     !! the end of the search, < π²
      real(wp), intent(in) :: tolerance     !! target accuracy of α and of the curves' β
      type(alpha_crossing_t), allocatable, intent(out) :: crossings(:)  !! ascending in α
      type(error_t), allocatable, intent(out) :: error  !! Hill's method failed; unallocated on success
      real(wp), allocatable :: alphas(:), keys(:)
      type(sample_curves_t), allocatable :: samples(:)
      real(wp) :: f0, f1, beta1
      integer :: j, c, n
      logical :: found
      type(alpha_crossing_t) :: crossing
      allocate (crossings(0))
      alphas = crossing_samples(alpha_end)
      n = size(alphas)
      allocate (samples(n))
      !$omp parallel do schedule(dynamic) default(shared) private(j)
      do j = n, 1, -1
         call exact_boundaries(model, alphas(j), -1.0_wp, pi2 + 1.0_wp, tolerance, samples(j)%curves, samples(j)%error)
      end do
      !$omp end parallel do
      do j = 1, n
         if (allocated(samples(j)%error)) then
            call set_error(error, samples(j)%error%code, "Hill's method at alpha = "// &
               real_text((alphas(j)))//": "//samples(j)%error%message)
            return
         end if
      end do
      do j = 1, n - 1
         do c = 1, size(samples(j)%curves)
            associate (curve => samples(j)%curves(c))
               call matching_beta(samples(j + 1)%curves, curve, beta1, found)
               if (.not. found) cycle
               if (curve%coexistent .and. sample_coexistent(samples(j + 1)%curves, curve)) cycle
               f0 = curve%beta - beta
               f1 = beta1 - beta
               if (f0 == 0.0_wp .and. j == 1) then
                  crossing = alpha_crossing_t(alphas(j), curve%trace_sign, curve%order, curve%parity, 0.0_wp, &
                                              curve%modes)
               else if (f1 == 0.0_wp) then
                  crossing = alpha_crossing_t(alphas(j + 1), curve%trace_sign, curve%order, curve%parity, 0.0_wp, &
                                              curve%modes)
               else if ((f0 < 0.0_wp .and. f1 > 0.0_wp) .or. (f0 > 0.0_wp .and. f1 < 0.0_wp)) then
                  call refine_crossing(model, beta, curve, alphas(j), alphas(j + 1), f0, f1, tolerance, crossing, error)
                  if (allocated(error)) return
               else
                  cycle
               end if
               crossings = [crossings, crossing]
            end associate
         end do
      end do
      keys = crossings%alpha
      crossings = crossings(ascending_order(keys))
   end subroutine alpha_crossings

   !> β of the curve with the same kind, order and parity as `like` among `curves`.
   pure subroutine matching_beta(curves, like, beta, found)
      type(hill_boundary_t), intent(in) :: curves(:)
      type(hill_boundary_t), intent(in) :: like
      real(wp), intent(out) :: beta
      logical, intent(out) :: found
      integer :: c
      found = .false.
      beta = 0.0_wp
      do c = 1, size(curves)
         if (curves(c)%trace_sign == like%trace_sign .and. curves(c)%order == like%order .and. &
             curves(c)%parity == like%parity) then
            beta = curves(c)%beta
            found = .true.
            return
         end if
      end do
   end subroutine matching_beta

   !> Whether the curve like `like` is flagged coexistent among `curves`.
   pure logical function sample_coexistent(curves, like)
      type(hill_boundary_t), intent(in) :: curves(:)
      type(hill_boundary_t), intent(in) :: like
      integer :: c
      sample_coexistent = .false.
      do c = 1, size(curves)
         if (curves(c)%trace_sign == like%trace_sign .and. curves(c)%order == like%order .and. &
             curves(c)%parity == like%parity) sample_coexistent = curves(c)%coexistent
      end do
   end function sample_coexistent

   !> The crossing of one curve with β inside [lo, hi] (f = β_curve − β of opposite signs
   !> at the ends): Illinois regula falsi, a bisection after two steps that do not halve
   !> the bracket.
   subroutine refine_crossing(model, beta, curve, lo_in, hi_in, f_lo_in, f_hi_in, tolerance, crossing, error)
      class(hill_model_t), intent(in) :: model  !! the model
      real(wp), intent(in) :: beta, lo_in, hi_in, f_lo_in, f_hi_in, tolerance
      type(hill_boundary_t), intent(in) :: curve
      type(alpha_crossing_t), intent(out) :: crossing
      type(error_t), allocatable, intent(out) :: error
      type(hill_boundary_t), allocatable :: curves(:)
      real(wp) :: lo, hi, f_lo, f_hi, x, fx, width, slope, beta_x, g_lo, g_hi, beta_bound
      integer :: iteration, side, stalls, c
      logical :: found
      lo = lo_in; hi = hi_in; f_lo = f_lo_in; f_hi = f_hi_in
      slope = 0.0_wp
      ! the values of f at the bracket's ends as computed (f_lo, f_hi are halved by Illinois)
      g_lo = f_lo; g_hi = f_hi
      beta_bound = tolerance*max(1.0_wp, abs(beta))
      side = 0
      stalls = 0
      x = lo
      fx = f_lo
      crossing = alpha_crossing_t(lo, curve%trace_sign, curve%order, curve%parity, hi - lo, curve%modes)
      do iteration = 1, 200
         width = hi - lo
         if (stalls >= 2) then
            x = 0.5_wp*(lo + hi)
            stalls = 0
         else
            x = (lo*f_hi - hi*f_lo)/(f_hi - f_lo)
            if (.not. (x > lo .and. x < hi)) x = 0.5_wp*(lo + hi)
         end if
         call exact_boundaries(model, x, -1.0_wp, pi2 + 1.0_wp, tolerance, curves, error)
         if (allocated(error)) return
         call matching_beta(curves, curve, beta_x, found)
         if (.not. found) then
            call set_error(error, err_invalid_parameter, "the curve of order "//integer_text((curve%order))// &
               " left the window at alpha = "//real_text((x)))
            return
         end if
         do c = 1, size(curves)
            if (curves(c)%trace_sign == curve%trace_sign .and. curves(c)%order == curve%order .and. &
                curves(c)%parity == curve%parity) then
               crossing%modes = curves(c)%modes
               beta_bound = max(curves(c)%error_bound, tolerance*max(1.0_wp, abs(beta)))
            end if
         end do
         fx = beta_x - beta
         if (hi > lo) slope = abs(g_hi - g_lo)/(hi - lo)
         if (fx == 0.0_wp) then
            lo = x; hi = x
            exit
         end if
         if ((fx < 0.0_wp) .eqv. (f_lo < 0.0_wp)) then
            lo = x; f_lo = fx; g_lo = fx
            if (side == -1) f_hi = 0.5_wp*f_hi
            side = -1
         else
            hi = x; f_hi = fx; g_hi = fx
            if (side == 1) f_lo = 0.5_wp*f_lo
            side = 1
         end if
         if (hi - lo > 0.5_wp*width) then
            stalls = stalls + 1
         else
            stalls = 0
         end if
         if (hi - lo <= tolerance*max(1.0_wp, abs(x))) exit
         if (abs(fx) <= tolerance*max(1.0_wp, abs(beta))) exit
      end do
      crossing%alpha = x
      ! the root of the computed curve lies within the bracket and within |fx|/|dβ/dα| of x,
      ! that of the true curve farther by the curve's own error in β over the slope (the
      ! secant of the last bracket of nonzero width, through the computed values; twice, for
      ! the slope's change across it); at least the rounding of α (a bracket closed on an
      ! exact zero of fx was 0)
      if (hi > lo) slope = abs(g_hi - g_lo)/(hi - lo)
      crossing%alpha_error = hi - lo
      if (slope > 0.0_wp) crossing%alpha_error = min(crossing%alpha_error, 2.0_wp*abs(fx)/slope) + &
                                                 2.0_wp*beta_bound/slope
      crossing%alpha_error = max(crossing%alpha_error, 2.0_wp*epsilon(1.0_wp)*abs(x))
   end subroutine refine_crossing

   !> Total length of a union of disjoint intervals (2, m).
   pure real(wp) function interval_length(intervals)
      real(wp), intent(in) :: intervals(:, :)  !! (2, m): [start, end] of each interval
      interval_length = sum(intervals(2, :) - intervals(1, :))
   end function interval_length

   !> Length of the symmetric difference of two unions of disjoint sorted intervals.
   pure real(wp) function symmetric_difference_length(a, b) result(length)
      real(wp), intent(in) :: a(:, :), b(:, :)  !! (2, m) unions of disjoint intervals, sorted
      integer :: i, j
      real(wp) :: overlap
      overlap = 0.0_wp
      do i = 1, size(a, 2)
         do j = 1, size(b, 2)
            overlap = overlap + max(0.0_wp, min(a(2, i), b(2, j)) - max(a(1, i), b(1, j)))
         end do
      end do
      length = interval_length(a) + interval_length(b) - 2.0_wp*overlap
   end function symmetric_difference_length
end module hillstab_curves_boundaries

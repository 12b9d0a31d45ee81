!> Tests of the modulated-bounce model (hillstab_hill_model_modulated) against references
!> that share none of its algebra: Q against (β − r̈)/r with r = 1 − k cos πτ cos(πτ/2)
!> differentiated by the product rule in extended precision; segment means against a fine
!> composite Gauss rule; the ranges of w, v and Q against dense samples; and the trace of
!> every exact method against the trace of the swing written for the angle θ = x/r,
!> (r² θ')' + (β − ε² r/4) r θ = 0 — the same multipliers, but neither m'' nor the split
!> appears in it — integrated by fourth-order Magnus in extended precision with Richardson's
!> extrapolation, its own convergence checked. Transition values (the roots route) against
!> that reference, and the α domain.
module test_model_modulated
   use hillstab_core_kinds, only: wp
   use hillstab_core_error, only: error_t, err_accuracy
   use hillstab_hill_model, only: hill_point_t, hill_window_t, model_coefficient_range
   use hillstab_hill_model_modulated, only: modulated_model_t, modulated_parts
   use hillstab_hill_transfer, only: trace_t
   use hillstab_integrate_monodromy, only: method_t, monodromy_trace, method_auto, method_magnus4, method_magnus6, &
      method_rk, method_gsl, method_name
   use hillstab_curves_hill_method, only: hill_boundary_t, route_roots
   use hillstab_curves_characteristic, only: characteristic_values
   use hillstab_core_text, only: real_text
   use hillstab_testing
   use hillstab_test_reference, only: auto_row_errors
   implicit none
   private
   public :: collect_model_modulated

   !> Extended precision of the references.
   integer, parameter :: xp = selected_real_kind(18)
   real(xp), parameter :: pi_x = 3.14159265358979323846264338327950288_xp
   !> The exact methods and the tolerances every one is checked at.
   integer, parameter :: exact_methods(5) = [method_auto, method_magnus4, method_magnus6, method_rk, method_gsl]
   real(wp), parameter :: tolerances(2) = [1.0e-6_wp, 1.0e-10_wp]

contains

   function collect_model_modulated() result(suite)
      type(testsuite_t) :: suite
      suite = new_testsuite("modulated", [ &
         new_unittest("coefficient_against_definition", coefficient_against_definition), &
         new_unittest("segment_means", segment_means), &
         new_unittest("ranges_contain_samples", ranges_contain_samples), &
         new_unittest("period_and_symmetry", period_and_symmetry), &
         new_unittest("exact_methods_against_reference", exact_methods_against_reference), &
         new_unittest("deep_dip_at_1e12", deep_dip_at_1e12), &
         new_unittest("auto_chart_grid", auto_chart_grid), &
         new_unittest("transition_values", transition_values), &
         new_unittest("alpha_domain", alpha_domain)])
   end function collect_model_modulated

   !> r/ρ = 1 − k cos πτ cos(πτ/2) and its second derivative by the product rule.
   pure subroutine bounce(alpha, tau, r, r2)
      real(xp), intent(in) :: alpha, tau
      real(xp), intent(out) :: r, r2
      real(xp) :: k, a, b, a1, b1, a2, b2
      k = alpha/pi_x**2
      a = cos(pi_x*tau); a1 = -pi_x*sin(pi_x*tau); a2 = -pi_x**2*cos(pi_x*tau)
      b = cos(0.5_xp*pi_x*tau); b1 = -0.5_xp*pi_x*sin(0.5_xp*pi_x*tau); b2 = -0.25_xp*pi_x**2*cos(0.5_xp*pi_x*tau)
      r = 1.0_xp - k*a*b
      r2 = -k*(a2*b + 2.0_xp*a1*b1 + a*b2)
   end subroutine bounce

   !> Q = (β − r̈)/r, the swing about a prescribed bounce (x = rθ).
   real(xp) function definition_q(alpha, beta, tau) result(q)
      real(xp), intent(in) :: alpha, beta, tau
      real(xp) :: r, r2
      call bounce(alpha, tau, r, r2)
      q = (beta - r2)/r
   end function definition_q

   subroutine coefficient_against_definition(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp), parameter :: alphas(5) = [0.0_wp, 0.5_wp, 5.0_wp, 9.5_wp, 9.86_wp]
      real(wp), parameter :: betas(3) = [-3.0_wp, 2.0_wp, 40.0_wp]
      type(modulated_model_t) :: model
      real(wp) :: tau, q, w, v, worst
      real(xp) :: reference
      integer :: i, j, n
      worst = 0.0_wp
      do i = 1, size(alphas)
         do j = 1, size(betas)
            do n = 0, 400
               tau = -1.0_wp + 6.0_wp*n/400.0_wp
               q = model%coefficient(alphas(i), betas(j), tau)
               call modulated_parts(alphas(i), tau, w, v)
               reference = definition_q(real(alphas(i), xp), real(betas(j), xp), real(tau, xp))
               ! relative to the size of its two parts (Q itself passes through zero)
               worst = max(worst, real(abs(q - reference), wp)/(abs(betas(j)*w) + abs(v) + 1.0_wp))
            end do
         end do
      end do
      call check(ctx, worst <= 2.0e-14_wp, "Q = (beta - r'')/r to rounding: worst "//real_text(worst))
      call check(ctx, model%coefficient(5.0_wp, 2.0_wp, 0.0_wp), (2.0_wp - 1.25_wp*5.0_wp)/(1.0_wp - 5.0_wp/pi2()), &
                 rel=1.0e-14_wp, message="Q(0) = (beta - 1.25 alpha)/(1 - k)")
   end subroutine coefficient_against_definition

   pure real(wp) function pi2()
      pi2 = real(pi_x**2, wp)
   end function pi2

   !> Segment means against the composite 3-point Gauss rule on 20 000 panels in extended
   !> precision, over segments inside and across the period's dips.
   subroutine segment_means(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp), parameter :: alphas(3) = [1.0_wp, 7.0_wp, 9.7_wp]
      real(wp), parameter :: ends(2, 4) = reshape([0.0_wp, 0.25_wp, -0.3_wp, 0.7_wp, 1.0_wp, 3.5_wp, 0.0_wp, 4.0_wp], [2, 4])
      type(modulated_model_t) :: model
      real(xp) :: sum_q, h, t0, node
      real(wp) :: mean
      integer :: i, s, p, g
      real(xp), parameter :: offsets(3) = [-sqrt(0.6_xp), 0.0_xp, sqrt(0.6_xp)]
      real(xp), parameter :: weights(3) = [5.0_xp/9.0_xp, 8.0_xp/9.0_xp, 5.0_xp/9.0_xp]
      do i = 1, size(alphas)
         do s = 1, size(ends, 2)
            h = (real(ends(2, s), xp) - real(ends(1, s), xp))/20000
            sum_q = 0.0_xp
            do p = 0, 19999
               t0 = real(ends(1, s), xp) + (p + 0.5_xp)*h
               do g = 1, 3
                  node = t0 + 0.5_xp*h*offsets(g)
                  sum_q = sum_q + 0.5_xp*h*weights(g)*definition_q(real(alphas(i), xp), 3.0_xp, node)
               end do
            end do
            mean = model%segment_mean(alphas(i), 3.0_wp, ends(1, s), ends(2, s))
            call check(ctx, mean, real(sum_q/(real(ends(2, s), xp) - real(ends(1, s), xp)), wp), rel=1.0e-13_wp, &
                       abs=1.0e-13_wp, message="segment mean at alpha = "//real_text(alphas(i)))
         end do
      end do
   end subroutine segment_means

   !> The ranges of w and v, and through them of Q, contain Q's values at dense samples of the
   !> period and are tight (v's to 1e-6 of its extremes: they are computed, not bounded).
   subroutine ranges_contain_samples(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp), parameter :: alphas(4) = [0.3_wp, 4.0_wp, 9.0_wp, 9.8_wp]
      real(wp), parameter :: betas(3) = [-20.0_wp, 1.0_wp, 30.0_wp]
      type(modulated_model_t) :: model
      real(wp) :: w(20001), v(20001), taus(20001), w_min, w_max, v_min, v_max, q_min, q_max
      integer :: i, j, n
      taus = [(4.0_wp*n/20000.0_wp, n=0, 20000)]
      do i = 1, size(alphas)
         call modulated_parts(alphas(i), taus, w, v)
         call model%shape_range(alphas(i), w_min, w_max)
         call model%offset_range(alphas(i), v_min, v_max)
         call check(ctx, all(w >= w_min) .and. all(w <= w_max), "w inside its range at alpha = "//real_text(alphas(i)))
         call check(ctx, all(v >= v_min) .and. all(v <= v_max), "v inside its range at alpha = "//real_text(alphas(i)))
         call check(ctx, maxval(v), v_max, rel=1.0e-6_wp, message="largest v attained")
         call check(ctx, minval(v), v_min, rel=1.0e-6_wp, message="least v attained")
         call check(ctx, maxval(w), w_max, rel=1.0e-12_wp, message="largest w attained (tau = 0)")
         do j = 1, size(betas)
            call model_coefficient_range(model, hill_point_t(alphas(i), betas(j), 0.0_wp), q_min, q_max)
            call check(ctx, all(betas(j)*w + v >= q_min) .and. all(betas(j)*w + v <= q_max), &
                       "Q inside its range at beta = "//real_text(betas(j)))
         end do
      end do
   end subroutine ranges_contain_samples

   !> Period 4, Q even about 0 and 2, and the window half a period from 0.
   subroutine period_and_symmetry(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(modulated_model_t) :: model
      type(hill_window_t) :: window
      real(wp) :: tau, scale
      integer :: n
      logical :: even, periodic
      call check(ctx, model%period(), 4.0_wp, message="period 4")
      window = model%window(6.0_wp)
      call check(ctx, window%half .and. window%start == 0.0_wp .and. window%length == 2.0_wp, &
                 "window: half a period from 0")
      even = .true.
      periodic = .true.
      do n = 1, 99
         tau = 0.02_wp*n
         scale = 1.0e-13_wp*max(1.0_wp, abs(model%coefficient(6.0_wp, 2.0_wp, tau)))
         even = even .and. abs(model%coefficient(6.0_wp, 2.0_wp, -tau) - model%coefficient(6.0_wp, 2.0_wp, tau)) <= scale
         even = even .and. abs(model%coefficient(6.0_wp, 2.0_wp, 4.0_wp - tau) - &
                               model%coefficient(6.0_wp, 2.0_wp, tau)) <= scale
         periodic = periodic .and. abs(model%coefficient(6.0_wp, 2.0_wp, tau + 4.0_wp) - &
                                       model%coefficient(6.0_wp, 2.0_wp, tau)) <= scale
      end do
      call check(ctx, even, "Q(-tau) = Q(4 - tau) = Q(tau)")
      call check(ctx, periodic, "Q(tau + 4) = Q(tau)")
   end subroutine period_and_symmetry

   !> S of (r² θ')' + G r θ = 0, G = β − ε² r/4, as the system y = (θ, r² θ'),
   !> y' = [[0, 1/r²], [−G r, 0]] y over one period [0, 4]: n steps of fourth-order Magnus
   !> (two Gauss nodes and the commutator) with the exact exponential of each traceless step.
   real(xp) function theta_trace(alpha, beta, epsilon, n) result(s)
      real(xp), intent(in) :: alpha, beta, epsilon
      integer, intent(in) :: n
      real(xp), parameter :: offset = 0.5_xp/sqrt(3.0_xp)
      real(xp) :: h, a1(2, 2), a2(2, 2), omega(2, 2), e(2, 2), phi(2, 2), d2, k, c, sk
      integer :: i
      h = 4.0_xp/n
      phi = reshape([1.0_xp, 0.0_xp, 0.0_xp, 1.0_xp], [2, 2])
      do i = 0, n - 1
         a1 = generator((i + 0.5_xp - offset)*h)
         a2 = generator((i + 0.5_xp + offset)*h)
         omega = 0.5_xp*h*(a1 + a2) + sqrt(3.0_xp)/12.0_xp*h*h*(matmul(a2, a1) - matmul(a1, a2))
         ! Ω is traceless: Ω² = d2 I with d2 = −det Ω
         d2 = -(omega(1, 1)*omega(2, 2) - omega(1, 2)*omega(2, 1))
         if (d2 > 1.0e-8_xp) then
            k = sqrt(d2); c = cosh(k); sk = sinh(k)/k
         else if (d2 < -1.0e-8_xp) then
            k = sqrt(-d2); c = cos(k); sk = sin(k)/k
         else
            c = 1.0_xp + d2/2 + d2*d2/24 + d2**3/720
            sk = 1.0_xp + d2/6 + d2*d2/120 + d2**3/5040
         end if
         e = sk*omega
         e(1, 1) = e(1, 1) + c
         e(2, 2) = e(2, 2) + c
         phi = matmul(e, phi)
      end do
      s = phi(1, 1) + phi(2, 2)
   contains
      function generator(tau) result(a)
         real(xp), intent(in) :: tau
         real(xp) :: a(2, 2), r, r2
         call bounce(alpha, tau, r, r2)
         a = reshape([0.0_xp, -(beta - 0.25_xp*epsilon**2*r)*r, 1.0_xp/(r*r), 0.0_xp], [2, 2])
      end function generator
   end function theta_trace

   !> The reference S: Richardson's extrapolation of `theta_trace` on n and 2n steps, n
   !> doubled until it agrees with the extrapolation on 2n and 4n to 1e-13 relative to
   !> max(1, |S|) (`converged` false when 2^20 steps do not reach that).
   subroutine reference_trace(alpha, beta, epsilon, s, converged)
      real(wp), intent(in) :: alpha, beta, epsilon
      real(xp), intent(out) :: s
      logical, intent(out) :: converged
      real(xp) :: a, b, eps, s1, s2, s4, previous, current
      integer :: n
      a = real(alpha, xp); b = real(beta, xp); eps = real(epsilon, xp)
      n = max(256, 64*ceiling(4.0_wp*sqrt(abs(beta) + 1.0_wp)))
      s1 = theta_trace(a, b, eps, n)
      s2 = theta_trace(a, b, eps, 2*n)
      previous = s2 + (s2 - s1)/15.0_xp
      converged = .false.
      do while (4*n <= 2**20)
         s4 = theta_trace(a, b, eps, 4*n)
         current = s4 + (s4 - s2)/15.0_xp
         if (abs(current - previous) <= 1.0e-13_xp*max(1.0_xp, abs(current))) then
            converged = .true.
            exit
         end if
         previous = current
         s2 = s4
         n = 2*n
      end do
      s = current
   end subroutine reference_trace

   !> Near α → π² (1 − k m down to 0.031) at tolerance 1e-12: (9.559071, 5.044662), where the
   !> θ-form reference gives S = −340.85299379438509 (and an independent quadruple-precision
   !> RK4 on the definition of Q, extrapolated from 1e5 and 2e5 steps, the same to 2e-16):
   !> every exact method within 1e-12 at status 0, or status 1 within its estimate.
   subroutine deep_dip_at_1e12(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(modulated_model_t) :: model
      type(trace_t) :: tr
      type(error_t), allocatable :: error
      real(xp) :: reference
      real(wp) :: e
      integer :: m
      logical :: converged
      call reference_trace(9.559071_wp, 5.044662_wp, 0.0_wp, reference, converged)
      call check(ctx, converged, "reference converged")
      call check(ctx, real(reference, wp), -340.85299379438509_wp, rel=1.0e-14_wp, message="reference value")
      do m = 1, size(exact_methods)
         call monodromy_trace(model, hill_point_t(9.559071_wp, 5.044662_wp, 0.0_wp), &
                              method_t(exact_methods(m), tolerance=1.0e-12_wp), tr, error)
         e = abs(tr%value - real(reference, wp))/abs(real(reference, wp))
         if (allocated(error)) then
            call check(ctx, e <= 4.0_wp*tr%error_estimate, method_name(exact_methods(m))//": within its estimate")
         else
            call check(ctx, e <= 1.0e-12_wp, method_name(exact_methods(m))//": within 1e-12")
         end if
      end do
   end subroutine deep_dip_at_1e12

   !> Every exact method at 1e-6 and 1e-10 against the θ-form reference: 48 points, α up to
   !> 9.7 (the dip at τ = 0 as deep as 1/(1 − k) = 55), |β| up to 2000, with and without
   !> damping; error ≤ tolerance at status 0, within 4× the estimate when round-off limited.
   subroutine exact_methods_against_reference(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp), parameter :: alphas(4) = [0.5_wp, 3.0_wp, 7.0_wp, 9.7_wp]
      real(wp), parameter :: betas(8) = [-40.0_wp, -1.0_wp, 0.7_wp, 1.6_wp, 5.0_wp, 7.9_wp, 60.0_wp, 2000.0_wp]
      real(wp), parameter :: epsilons(2) = [0.0_wp, 0.3_wp]
      type(modulated_model_t) :: model
      type(trace_t) :: tr
      type(error_t), allocatable :: error
      real(xp) :: reference
      real(wp) :: e, worst(size(exact_methods), size(tolerances)), ref
      integer :: i, j, d, m, t, n_points
      logical :: converged
      character(len=160) :: label
      worst = 0.0_wp
      n_points = 0
      do i = 1, size(alphas)
         do j = 1, size(betas)
            do d = 1, size(epsilons)
               call reference_trace(alphas(i), betas(j), epsilons(d), reference, converged)
               call check(ctx, converged, "reference converged at "//real_text(alphas(i))//", "//real_text(betas(j)))
               if (.not. converged) cycle
               ref = real(reference, wp)
               if (abs(ref) > 1.0e300_wp) cycle
               n_points = n_points + 1
               do m = 1, size(exact_methods)
                  do t = 1, size(tolerances)
                     write (label, '(a,es8.1,a,3es11.3)') method_name(exact_methods(m))//" tol", tolerances(t), &
                        " at", alphas(i), betas(j), epsilons(d)
                     call monodromy_trace(model, hill_point_t(alphas(i), betas(j), epsilons(d)), &
                                          method_t(exact_methods(m), tolerance=tolerances(t)), tr, error)
                     e = abs(tr%value - ref)/max(1.0_wp, abs(ref))
                     if (allocated(error)) then
                        call check(ctx, error%code == err_accuracy, trim(label)//": a value (status 1): "//error%message)
                        if (error%code == err_accuracy) call check(ctx, e <= 4.0_wp*tr%error_estimate + 1.0e-13_wp, &
                                                                   trim(label)//": round-off limited, within its estimate")
                     else
                        call check(ctx, e <= tolerances(t), trim(label)//": error "//real_text(e)//" within the tolerance")
                        worst(m, t) = max(worst(m, t), e/tolerances(t))
                     end if
                  end do
               end do
            end do
         end do
      end do
      call check(ctx, n_points >= 40, "points compared")
      do m = 1, size(exact_methods)
         print '(4x,a8,a,2es9.2)', method_name(exact_methods(m)), ": worst error/tolerance at 1e-6, 1e-10:", worst(m, :)
      end do
      print '(4x,i0,a)', n_points, " points"
   end subroutine exact_methods_against_reference

   !> Method auto over a 36 × 36 grid of (α, β) ∈ [0.1, 9.8] × [−2, 12] at 1e-6 and 1e-10, one
   !> chart row per α as the chart task computes it (`monodromy_trace_batch`: shared meshes),
   !> against magnus6 at 1e-12: error ≤ tolerance at status 0 (at 1e-6 the uniform meshes'
   !> Richardson pairs were short of the asymptotic range near α = 7 before auto's estimate
   !> was counted fourfold for this model).
   subroutine auto_chart_grid(ctx)
      type(test_context_t), intent(inout) :: ctx
      integer, parameter :: n = 36
      real(wp), parameter :: tols(2) = [1.0e-6_wp, 1.0e-10_wp]
      type(modulated_model_t) :: model
      real(wp) :: betas(n), worst
      integer :: i, j, t, n_checked
      betas = [(-2.0_wp + 14.0_wp*(j - 1)/real(n - 1, wp), j=1, n)]
      do t = 1, size(tols)
         worst = 0.0_wp
         n_checked = 0
         do i = 1, n
            call auto_row_errors(model, 0.1_wp + 9.7_wp*(i - 1)/real(n - 1, wp), betas, tols(t), worst, n_checked)
         end do
         call check(ctx, worst <= 1.0_wp, "auto at "//real_text(tols(t))//" over the grid: worst error/tolerance "// &
                    real_text(worst))
         call check(ctx, n_checked >= n*n - 10, "points compared")
         print '(4x,a,es8.1,a,es9.2)', "auto chart grid at", tols(t), ": worst error/tolerance", worst
      end do
   end subroutine auto_chart_grid

   !> The first three transition values of each kind (the roots route) at four α: the
   !> reference S minus ±2 changes sign across [β − δ, β + δ], δ = 1e-9 max(1, |β|). At
   !> α = 0.5 the tongue from β = π²/4 (S = +2) opens only at second order in α, far
   !> narrower than the scan's samples: both its edges must be found (the search between the
   !> samples), not the next tongue's.
   subroutine transition_values(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp), parameter :: alphas(4) = [0.5_wp, 1.0_wp, 5.0_wp, 9.0_wp]
      type(modulated_model_t) :: model
      type(hill_boundary_t), allocatable :: values(:)
      type(error_t), allocatable :: error
      real(xp) :: below, above
      real(wp) :: delta, target, width
      integer :: i, k
      logical :: converged
      do i = 1, size(alphas)
         call characteristic_values(model, alphas(i), 3, values, error, tolerance=1.0e-12_wp)
         if (allocated(error)) then
            call check(ctx, .false., "characteristic values: "//error%message)
            return
         end if
         call check(ctx, all(values%route == route_roots), "route: the roots of S")
         call check(ctx, count(values%trace_sign == 2) == 3 .and. count(values%trace_sign == -2) == 3, &
                    "three values of each kind")
         if (i == 1) then
            call check(ctx, count(values%trace_sign == 2 .and. abs(values%beta - 0.25_wp*pi2()) < 0.01_wp) == 2, &
                       "both edges of the narrow tongue from pi^2/4 at alpha = 0.5")
            width = maxval(values%beta, values%trace_sign == 2) - minval(values%beta, values%trace_sign == 2 .and. &
                                                                          values%beta > 1.0_wp)
            print '(4x,a,es10.3)', "width of the tongue from pi^2/4 at alpha = 0.5:", width
            call check(ctx, width > 0.0_wp .and. width < 0.01_wp, "that tongue narrower than the scan's step (about 0.05)")
         end if
         do k = 1, size(values)
            delta = 1.0e-9_wp*max(1.0_wp, abs(values(k)%beta))
            target = real(values(k)%trace_sign, wp)
            call reference_trace(alphas(i), values(k)%beta - delta, 0.0_wp, below, converged)
            call reference_trace(alphas(i), values(k)%beta + delta, 0.0_wp, above, converged)
            call check(ctx, (below - target)*(above - target) <= 0.0_xp, "S = "//real_text(target)//" between beta -+ delta at "// &
                       real_text(values(k)%beta)//" (alpha = "//real_text(alphas(i))//")")
         end do
      end do
   end subroutine transition_values

   !> 0 ≤ α < π²: α = π² and α < 0 are refused with the domain in the message.
   subroutine alpha_domain(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(modulated_model_t) :: model
      type(trace_t) :: tr
      type(error_t), allocatable :: error
      call monodromy_trace(model, hill_point_t(pi2(), 1.0_wp, 0.0_wp), method_t(method_auto, tolerance=1.0e-8_wp), tr, error)
      call check(ctx, allocated(error), "alpha = pi^2 refused")
      if (allocated(error)) call check(ctx, index(error%message, "alpha < pi**2") > 0, "message names the domain: "// &
                                       error%message)
      call monodromy_trace(model, hill_point_t(-1.0_wp, 1.0_wp, 0.0_wp), method_t(method_auto, tolerance=1.0e-8_wp), tr, error)
      call check(ctx, allocated(error), "alpha < 0 refused")
   end subroutine alpha_domain
end module test_model_modulated

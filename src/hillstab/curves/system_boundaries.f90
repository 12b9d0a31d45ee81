!> Stability edges of a system of Hill equations at one α: the β where a multiplier pair
!> passes +1 or −1 (simple resonances), where two multipliers meet and leave the unit circle
!> off the real axis (combination resonances), and, for a damped system, where the largest
!> |λ| crosses 1. Every edge is checked on both sides by the monodromy's verdict.
!>
!> - Simple resonances by Hill's method with block matrices: a solution with multiplier ±1 is
!>   x = Σ_k c_k e^{iν_k τ}, ν_k = (k + s/2) 2π/P (s = 0: +1, s = 1: −1), and the equation
!>   becomes the generalised eigenproblem [−ν_k² M + iν_k(C + εM + G)] c_k + Σ_h P̂_h c_{k−h}
!>   = −β Σ_h B̂_h c_{k−h} in β, its blocks n × n, the harmonics P̂_h, B̂_h of K's two parts
!>   (p + βb) taken from K at 2H + 2 points of the period (exact for H harmonics), |k| ≤ K
!>   modes, solved by LAPACK zggev. The truncation is checked by a second solve with more
!>   modes: a β whose two values differ by more than 1e-8 max(1, |β|) is dropped; its error
!>   estimate is that difference plus the eigen-solve's rounding, ε_mach times the pencil's
!>   largest entries (ν² M at the highest mode, K) over B's; `check` is the distance of the
!>   nearest multiplier from ±1 at it.
!> - The other edges by root-finding on a signed quantity q, negative inside an unstable
!>   region (hillstab_curves_system_edges): Broucke's discriminant D = a₁² − 4a₂ + 8
!>   (Hamiltonian, n = 2: `route_discriminant`), the nearest two z = λ + 1/λ's Re (z_k − z_l)²
!>   (Hamiltonian, n ≥ 3: `route_collision`), −ln max|λ| (dissipative, tr D < 0:
!>   `route_modulus`, whose edges at +1 and −1 are left to Hill's method where it has them).
!>   q is sampled at the row's β and, around each combination resonance predicted at α = 0
!>   (ω_i + ω_j = kΩ, and |ω_i − ω_j| = kΩ where it can open), at 10 more β within half a
!>   spacing; every sign change is closed by Brent's method on q itself, and every positive
!>   local minimum of q (below both neighbours by more than δq) is probed by golden section
!>   for a tongue narrower than the samples. `check` is |q| at the edge over its error bound
!>   δq; the error estimate is the final bracket plus δq/|q'|.
!> - Both sides: the verdict at β ∓ δ, δ growing until decided, at most 0.45 of the distance
!>   to the next edge. Stable on one side, unstable on the other: a stability edge. Unstable
!>   on both (two overlapping tongues): the kind negated. Stable on both (a touch, as at
!>   α = 0): dropped. Undecided within the cap: status_failed, except for Hill's points,
!>   whose status is that of their check.
!> - Consistency: two consecutive stability edges see one region between them. Where one
!>   says stable and the other unstable, a transition between them was missed (a stable gap
!>   narrower than the samples between two unstable regions): it is closed on q between
!>   their sides and every candidate confirmed anew.
!>
!>```fortran
!> type(system_boundary_t), allocatable :: found(:)
!> call system_boundaries(system, form, alpha, betas, method, found, error)
!>```
module hillstab_curves_system_boundaries
   use hillstab_core_kinds, only: wp, pi
   use hillstab_core_error, only: error_t, set_error, err_singular
   use hillstab_core_status, only: status_ok, status_failed
   use hillstab_ffi_lapack, only: zggev
   use hillstab_hill_system, only: hill_system_t, system_form_t
   use hillstab_hill_system_floquet, only: floquet_t, system_floquet, kind_plus_one, kind_minus_one, &
      kind_combination, kind_undecided, verdict_stable
   use hillstab_integrate_system, only: system_method_t, system_monodromy_t, system_monodromy
   use hillstab_curves_system_edges, only: edge_row_t, edge_sample_t, side_check_t, quantity_of, evaluate, &
      find_root, dip_probe, check_sides, predicted_combinations, quantity_none, quantity_discriminant, &
      quantity_collision
   implicit none
   private
   public :: system_boundary_t, system_boundaries, system_hill_betas, route_hill, route_discriminant, &
      route_collision, route_modulus

   !> Route, Hill's method (a simple resonance).
   integer, parameter :: route_hill = 1
   !> Route, a root of Broucke's discriminant (Hamiltonian, n = 2).
   integer, parameter :: route_discriminant = 2
   !> Route, a root of the nearest pair's Re (z_k − z_l)² (Hamiltonian, n ≥ 3).
   integer, parameter :: route_collision = 3
   !> Route, a root of −ln max|λ| (dissipative).
   integer, parameter :: route_modulus = 4

   !> One point of a transition curve.
   type :: system_boundary_t
      real(wp) :: alpha = 0.0_wp          !! α
      real(wp) :: beta = 0.0_wp           !! β on the curve
      !> kind_plus_one, kind_minus_one or kind_combination: the multiplier's place at a
      !> stability edge; negated where both sides are unstable (no stability edge)
      integer :: kind = kind_plus_one
      integer :: route = route_hill       !! how it was found (route_*)
      !> the check at (α, β): distance of the nearest multiplier from ±1 (route_hill), |q| over
      !> its error bound (the other routes)
      real(wp) :: check = 0.0_wp
      real(wp) :: error_estimate = 0.0_wp !! of β
      integer :: status = status_ok       !! status_ok, or status_failed when the check fails
   end type system_boundary_t

contains

   !> The β in [beta_min, beta_max] where the system at α has a multiplier s = +1 or −1, by
   !> Hill's method (see the module's text); `estimates` their truncation errors. Empty when
   !> the system gives no harmonic count (`drive_harmonics` 0).
   subroutine system_hill_betas(system, form, alpha, sign, beta_min, beta_max, betas, estimates, error)
      class(hill_system_t), intent(in) :: system      !! the system
      type(system_form_t), intent(in) :: form         !! prepared at its ε
      real(wp), intent(in) :: alpha                   !! α
      integer, intent(in) :: sign                     !! +1 or −1
      real(wp), intent(in) :: beta_min, beta_max      !! the window
      real(wp), allocatable, intent(out) :: betas(:)  !! ascending
      real(wp), allocatable, intent(out) :: estimates(:)  !! their error estimates
      type(error_t), allocatable, intent(out) :: error    !! err_singular when LAPACK fails
      real(wp), allocatable :: coarse(:), fine(:), ph(:, :, :), bh(:, :, :)
      real(wp) :: scale, omega, nu_top, rounding
      integer :: h, modes, k
      h = system%drive_harmonics()
      allocate (betas(0), estimates(0))
      if (h < 1) return
      call harmonics(system, alpha, h, form%period, ph, bh)
      omega = 2.0_wp*pi/form%period
      ! enough modes that −ν² M dominates K at the window's β
      scale = maxval(sum(abs(matmul(form%m_inverse, ph(:, :, 0))), dim=2)) + &
              max(abs(beta_min), abs(beta_max))*maxval(sum(abs(matmul(form%m_inverse, bh(:, :, 0))), dim=2)) + &
              2.0_wp*sum(abs(ph(:, :, 1:)))*maxval(abs(form%m_inverse)) + &
              2.0_wp*max(abs(beta_min), abs(beta_max))*sum(abs(bh(:, :, 1:)))*maxval(abs(form%m_inverse))
      nu_top = 3.0_wp*sqrt(max(scale, 1.0_wp))
      modes = max(8, ceiling(nu_top/omega) + 2*h + 4)
      call solve(modes, coarse, error)
      if (allocated(error)) return
      call solve(modes + max(6, 2*h), fine, error)
      if (allocated(error)) return
      ! the eigen-solve's own rounding: the pencil's largest entries, ν² M at the highest mode
      ! and K, over B's (the truncation difference alone misses it)
      rounding = epsilon(1.0_wp)*((real(modes + max(6, 2*h), wp)*omega)**2*maxval(abs(form%m)) + &
                                  maxval(abs(ph)) + max(abs(beta_min), abs(beta_max))*maxval(abs(bh)))/ &
                 max(maxval(abs(bh(:, :, 0))), tiny(1.0_wp))
      do k = 1, size(fine)
         if (size(coarse) == 0) exit
         if (minval(abs(coarse - fine(k))) <= 1.0e-8_wp*max(1.0_wp, abs(fine(k)))) then
            betas = [betas, fine(k)]
            estimates = [estimates, max(minval(abs(coarse - fine(k))), epsilon(1.0_wp)*max(1.0_wp, abs(fine(k)))) + &
                         rounding]
         end if
      end do
      call sort_pairs(betas, estimates)

   contains

      subroutine solve(modes, found, error)
         integer, intent(in) :: modes
         real(wp), allocatable, intent(out) :: found(:)
         type(error_t), allocatable, intent(out) :: error
         complex(wp), allocatable :: a(:, :), b(:, :), ev_a(:), ev_b(:), vl(:, :), vr(:, :), work(:)
         real(wp), allocatable :: rwork(:)
         complex(wp) :: lambda
         real(wp) :: nu, s
         integer :: n, kmin, kmax, size_total, i, j, q, r, info, lwork
         n = form%n
         s = merge(0.0_wp, 0.5_wp, sign > 0)
         kmin = -modes
         kmax = merge(modes, modes - 1, sign > 0)
         size_total = n*(kmax - kmin + 1)
         allocate (a(size_total, size_total), b(size_total, size_total), ev_a(size_total), ev_b(size_total), &
                   vl(1, 1), vr(1, 1))
         a = (0.0_wp, 0.0_wp)
         b = (0.0_wp, 0.0_wp)
         do i = kmin, kmax
            nu = (i + s)*omega
            q = (i - kmin)*n
            ! −ν² M + iν (C + εM + G) = −ν² M − iν M D   (D = −M⁻¹(C + εM + G))
            a(q + 1:q + n, q + 1:q + n) = cmplx(-nu*nu*form%m, 0.0_wp, wp) - &
                                          cmplx(0.0_wp, nu, wp)*matmul(form%m, form%d)
            do j = kmin, kmax
               if (abs(i - j) > h) cycle
               r = (j - kmin)*n
               a(q + 1:q + n, r + 1:r + n) = a(q + 1:q + n, r + 1:r + n) + harmonic(ph, i - j)
               b(q + 1:q + n, r + 1:r + n) = -harmonic(bh, i - j)
            end do
         end do
         lwork = 4*size_total
         allocate (work(lwork), rwork(8*size_total))
         call zggev("N", "N", size_total, a, size_total, b, size_total, ev_a, ev_b, vl, 1, vr, 1, work, lwork, &
                    rwork, info)
         allocate (found(0))
         if (info /= 0) then
            call set_error(error, err_singular, "Hill's method: zggev failed (info "//trim(int_text(info))//")")
            return
         end if
         do i = 1, size_total
            if (abs(ev_b(i)) <= 1.0e-12_wp*abs(ev_a(i))) cycle
            lambda = ev_a(i)/ev_b(i)
            if (abs(aimag(lambda)) > 1.0e-7_wp*max(1.0_wp, abs(lambda))) cycle
            if (real(lambda) < beta_min .or. real(lambda) > beta_max) cycle
            found = [found, real(lambda)]
         end do
      end subroutine solve
   end subroutine system_hill_betas

   !> The complex harmonic m of a part from its cosine and sine coefficients (index 0: the mean):
   !> X_m = (c_m − i s_m)/2 for m > 0, (c_|m| + i s_|m|)/2 for m < 0.
   pure function harmonic(parts, m) result(x)
      real(wp), intent(in) :: parts(:, :, 0:)   !! (n, n, 0:2H): mean, cosines 1..H, sines H+1..2H
      integer, intent(in) :: m
      complex(wp) :: x(size(parts, 1), size(parts, 2))
      integer :: h
      h = (size(parts, 3) - 1)/2
      if (m == 0) then
         x = cmplx(parts(:, :, 0), 0.0_wp, wp)
      else if (m > 0) then
         x = 0.5_wp*cmplx(parts(:, :, m), -parts(:, :, h + m), wp)
      else
         x = 0.5_wp*cmplx(parts(:, :, -m), parts(:, :, h - m), wp)
      end if
   end function harmonic

   !> Mean, cosine and sine coefficients of K's parts p and b at α from 2H + 2 samples.
   subroutine harmonics(system, alpha, h, period, ph, bh)
      class(hill_system_t), intent(in) :: system
      real(wp), intent(in) :: alpha, period
      integer, intent(in) :: h
      real(wp), allocatable, intent(out) :: ph(:, :, :), bh(:, :, :)
      real(wp), allocatable :: p(:, :), b(:, :)
      integer :: n, samples, j, m
      real(wp) :: tau, angle
      n = system%dof()
      samples = 2*h + 2
      allocate (ph(n, n, 0:2*h), bh(n, n, 0:2*h), p(n, n), b(n, n))
      ph = 0.0_wp
      bh = 0.0_wp
      do j = 0, samples - 1
         tau = period*j/samples
         call system%stiffness(alpha, tau, p, b)
         ph(:, :, 0) = ph(:, :, 0) + p/samples
         bh(:, :, 0) = bh(:, :, 0) + b/samples
         do m = 1, h
            angle = 2.0_wp*pi*m*real(j, wp)/samples
            ph(:, :, m) = ph(:, :, m) + (2.0_wp/samples)*cos(angle)*p
            ph(:, :, h + m) = ph(:, :, h + m) + (2.0_wp/samples)*sin(angle)*p
            bh(:, :, m) = bh(:, :, m) + (2.0_wp/samples)*cos(angle)*b
            bh(:, :, h + m) = bh(:, :, h + m) + (2.0_wp/samples)*sin(angle)*b
         end do
      end do
   end subroutine harmonics

   !> Every stability edge of one α over the window of `betas` (the samples of a row): the
   !> simple ones by Hill's method, the others by root-finding on the row's signed quantity
   !> over the samples refined around the predicted combination resonances; each edge's two
   !> sides checked by the monodromy's verdict. Sorted by β.
   subroutine system_boundaries(system, form, alpha, betas, method, found, error)
      class(hill_system_t), intent(in) :: system      !! the system
      type(system_form_t), intent(in) :: form         !! prepared at its ε
      real(wp), intent(in) :: alpha                   !! α
      real(wp), intent(in) :: betas(:)                !! ascending samples (the window and the brackets)
      type(system_method_t), intent(in) :: method     !! the monodromy's method and tolerance
      type(system_boundary_t), allocatable, intent(out) :: found(:)  !! the points, by β
      type(error_t), allocatable, intent(out) :: error  !! err_singular when Hill's method fails
      type(edge_row_t) :: row
      type(system_boundary_t), allocatable :: candidates(:), pristine(:)
      type(edge_sample_t), allocatable :: samples(:)
      type(edge_sample_t) :: probe
      type(side_check_t), allocatable :: sides(:)
      real(wp), allocatable :: roots(:), estimates(:), grid(:), predicted(:), bounds(:)
      logical, allocatable :: inside(:)
      type(system_boundary_t) :: point
      real(wp) :: spacing
      integer :: s, k, j, round, added, last
      logical :: hit
      allocate (found(0), candidates(0), bounds(0))
      row%alpha = alpha
      row%method = method
      row%quantity = quantity_of(form)
      spacing = (betas(size(betas)) - betas(1))/max(1, size(betas) - 1)
      do s = 1, 2
         call system_hill_betas(system, form, alpha, merge(1, -1, s == 1), betas(1), betas(size(betas)), roots, &
                                estimates, error)
         if (allocated(error)) return
         do k = 1, size(roots)
            point = system_boundary_t(alpha, roots(k), merge(kind_plus_one, kind_minus_one, s == 1), route_hill, &
                                      0.0_wp, estimates(k), status_ok)
            point%check = distance_from(merge(1.0_wp, -1.0_wp, s == 1), roots(k))
            if (.not. (point%check <= 1.0e-4_wp)) point%status = status_failed
            candidates = [candidates, point]
            bounds = [bounds, 0.0_wp]
         end do
      end do
      if (row%quantity /= quantity_none) then
         call predicted_combinations(system, form, betas, predicted)
         grid = refined_grid(betas, predicted, spacing)
         allocate (samples(size(grid)), inside(size(grid)))
         do j = 1, size(grid)
            samples(j) = evaluate(system, form, row, grid(j))
            inside(j) = samples(j)%ok .and. samples(j)%q < -samples(j)%dq
         end do
         do j = 1, size(grid) - 1
            if (inside(j) .eqv. inside(j + 1)) cycle
            call close_edge(samples(j), samples(j + 1))
         end do
         ! a tongue narrower than the samples: a positive local minimum of q, below both
         ! neighbours by more than its error bound (mass-proportional damping alone leaves q
         ! flat, e^{−εP/2} the modulus of every multiplier, wherever the system is stable:
         ! its noise is no dip)
         do j = 2, size(grid) - 1
            if (inside(j - 1) .or. inside(j) .or. inside(j + 1)) cycle
            if (.not. (samples(j - 1)%ok .and. samples(j)%ok .and. samples(j + 1)%ok)) cycle
            if (.not. (samples(j)%q < samples(j - 1)%q - samples(j)%dq .and. &
                       samples(j)%q < samples(j + 1)%q - samples(j)%dq)) cycle
            call dip_probe(system, form, row, grid(j - 1), grid(j + 1), probe, hit)
            if (.not. hit) cycle
            call close_edge(samples(j - 1), probe)
            call close_edge(probe, samples(j + 1))
         end do
      end if
      call sort_candidates(candidates, bounds)
      ! as found: confirm_edges negates kinds and adds to the estimates
      pristine = candidates
      call confirm_edges(system, form, row, candidates, bounds, spacing, found, sides)
      if (row%quantity /= quantity_none) then
         ! consecutive stability edges see one region between them: stable above the one and
         ! below the next, or unstable at both. Where they disagree a transition between them
         ! was missed (a stable gap narrower than the samples between two unstable regions,
         ! both its samples inside): closed on q between the two sides, then all confirmed anew.
         do round = 1, 3
            candidates = pristine
            added = size(candidates)
            last = 0
            do k = 1, size(found)
               if (found(k)%kind <= 0 .or. found(k)%status /= status_ok .or. .not. sides(k)%decided) cycle
               if (last > 0) then
                  if ((sides(last)%above%verdict == verdict_stable) .neqv. &
                      (sides(k)%below%verdict == verdict_stable)) then
                     if (sides(last)%above%ok .and. sides(k)%below%ok .and. &
                         ((sides(last)%above%q < 0.0_wp) .neqv. (sides(k)%below%q < 0.0_wp))) &
                        call close_edge(sides(last)%above, sides(k)%below)
                  end if
               end if
               last = k
            end do
            if (size(candidates) == added) exit
            call sort_candidates(candidates, bounds)
            pristine = candidates
            deallocate (found)
            allocate (found(0))
            call confirm_edges(system, form, row, candidates, bounds, spacing, found, sides)
         end do
      end if
      call sort_points(found)

   contains

      !> The edge between a sample inside and one outside (route by the row's quantity).
      subroutine close_edge(a, b)
         type(edge_sample_t), intent(in) :: a, b
         type(edge_sample_t) :: root, other, in_side
         real(wp) :: width
         integer :: kind, route, i
         if ((a%q < 0.0_wp) .neqv. (b%q < 0.0_wp)) then
            call find_root(system, form, row, a, b, root, other, width)
         else
            ! the outside sample lies within its error bound of the edge (q < 0 undecided)
            root = merge(a, b, a%q >= -a%dq .and. a%q < 0.0_wp)
            other = merge(b, a, a%q >= -a%dq .and. a%q < 0.0_wp)
            width = 0.0_wp
         end if
         in_side = merge(root, other, root%q < 0.0_wp)
         if (row%quantity /= quantity_discriminant) root = evaluate(system, form, row, root%beta, sharp=.true.)
         select case (row%quantity)
         case (quantity_discriminant)
            kind = kind_combination
            route = route_discriminant
         case (quantity_collision)
            kind = kind_combination
            route = route_collision
         case default
            kind = in_side%kind
            route = route_modulus
            if (kind == kind_undecided) kind = kind_combination
            ! a multiplier through +1 or −1: Hill's method has it (more accurately) when it
            ! found one of that kind in the bracket
            if (kind /= kind_combination) then
               do i = 1, size(candidates)
                  if (candidates(i)%route /= route_hill .or. candidates(i)%kind /= kind) cycle
                  if (candidates(i)%beta >= min(a%beta, b%beta) .and. candidates(i)%beta <= max(a%beta, b%beta)) &
                     return
               end do
            end if
         end select
         point = system_boundary_t(alpha, root%beta, kind, route, 0.0_wp, width, status_ok)
         point%check = abs(root%q)/max(root%dq, tiny(1.0_wp))
         candidates = [candidates, point]
         ! the error bound of q at the root: the estimate adds it over the slope (confirm_edges)
         bounds = [bounds, root%dq]
      end subroutine close_edge

      !> The distance of the multiplier nearest to `target` at β.
      real(wp) function distance_from(target, beta)
         real(wp), intent(in) :: target, beta
         type(system_monodromy_t) :: r
         type(floquet_t) :: f
         type(error_t), allocatable :: cause
         call system_monodromy(system, form, alpha, beta, method, row%nodes, r, cause)
         distance_from = huge(1.0_wp)
         if (allocated(cause)) return
         call system_floquet(r%phi, form, r%error_estimate*max(1.0_wp, maxval(abs(r%phi))), f, r%log_scale)
         distance_from = minval(abs(f%multipliers*exp(f%log_scale) - target))
      end function distance_from
   end subroutine system_boundaries

   !> The samples and, around each predicted resonance β_p, β_p + h·o for o = 0, ±1/64, ±1/16,
   !> ±1/8, ±1/4, ±1/2 (h the samples' spacing), inside the window, ascending and distinct.
   pure function refined_grid(betas, predicted, spacing) result(grid)
      real(wp), intent(in) :: betas(:), predicted(:), spacing
      real(wp), allocatable :: grid(:)
      real(wp), parameter :: offsets(11) = [0.0_wp, -1.0_wp/64, 1.0_wp/64, -1.0_wp/16, 1.0_wp/16, -0.125_wp, &
                                            0.125_wp, -0.25_wp, 0.25_wp, -0.5_wp, 0.5_wp]
      real(wp), allocatable :: all(:)
      real(wp) :: x
      integer :: i, k, count
      allocate (all(size(betas) + size(offsets)*size(predicted)))
      count = size(betas)
      all(1:count) = betas
      do i = 1, size(predicted)
         do k = 1, size(offsets)
            x = predicted(i) + offsets(k)*spacing
            if (x <= betas(1) .or. x >= betas(size(betas))) cycle
            count = count + 1
            all(count) = x
         end do
      end do
      call sort_values(all(1:count))
      allocate (grid(count))
      k = 1
      grid(1) = all(1)
      do i = 2, count
         if (all(i) - grid(k) <= 1.0e-12_wp*max(1.0_wp, abs(all(i)))) cycle
         k = k + 1
         grid(k) = all(i)
      end do
      grid = grid(1:k)
   end function refined_grid

   !> Each candidate's two sides by the verdict (`check_sides`), δ capped by 0.45 of the gap to
   !> its neighbours, half the samples' spacing and 1 % of max(1, |β|); candidates closer than
   !> their errors (a double root, as at the tip of a tongue) are checked as one. Stable on one
   !> side and unstable on the other: a stability edge. Unstable on both: kept with the kind
   !> negated. Stable on both: dropped. Undecided: Hill's points keep the status of their
   !> check, the others get status_failed. The error estimate of a root of q adds δq/|q'|
   !> (the slope from the two sides) to its bracket.
   subroutine confirm_edges(system, form, row, candidates, bounds, spacing, found, sides_found)
      class(hill_system_t), intent(in) :: system
      type(system_form_t), intent(in) :: form
      type(edge_row_t), intent(inout) :: row
      type(system_boundary_t), intent(inout) :: candidates(:)
      real(wp), intent(in) :: bounds(:)   !! the error bound of q at each root (0: Hill's method)
      real(wp), intent(in) :: spacing
      type(system_boundary_t), allocatable, intent(inout) :: found(:)
      type(side_check_t), allocatable, intent(out) :: sides_found(:)  !! the sides of each of `found`
      type(side_check_t) :: sides
      real(wp) :: gap, cap, start, scale, slope, lo, hi, close
      integer :: k, first, last
      logical :: stable_below, stable_above
      allocate (sides_found(0))
      first = 1
      do while (first <= size(candidates))
         ! the cluster of candidates within their errors of each other
         last = first
         do while (last < size(candidates))
            close = candidates(last)%error_estimate + candidates(last + 1)%error_estimate + &
                    1.0e-12_wp*max(1.0_wp, abs(candidates(last)%beta))
            if (candidates(last + 1)%beta - candidates(last)%beta > close) exit
            last = last + 1
         end do
         lo = candidates(first)%beta
         hi = candidates(last)%beta
         scale = max(1.0_wp, abs(lo))
         gap = huge(1.0_wp)
         if (first > 1) gap = min(gap, lo - candidates(first - 1)%beta)
         if (last < size(candidates)) gap = min(gap, candidates(last + 1)%beta - hi)
         cap = min(0.45_wp*gap, 0.5_wp*spacing, 0.01_wp*scale)
         start = max(4.0_wp*maxval(candidates(first:last)%error_estimate), 1.0e-10_wp*scale)
         sides = check_sides(system, form, row, 0.5_wp*(lo + hi), start + 0.5_wp*(hi - lo), &
                             max(cap, start) + 0.5_wp*(hi - lo))
         do k = first, last
            if (candidates(k)%route /= route_hill) then
               ! the estimate: the bracket, plus the error bound of q at the root over q's slope
               slope = 0.0_wp
               if (sides%below%ok .and. sides%above%ok .and. sides%above%beta > sides%below%beta) &
                  slope = abs(sides%above%q - sides%below%q)/(sides%above%beta - sides%below%beta)
               if (slope > 0.0_wp) then
                  candidates(k)%error_estimate = candidates(k)%error_estimate + bounds(k)/slope
               else
                  candidates(k)%error_estimate = candidates(k)%error_estimate + sides%offset
               end if
               candidates(k)%error_estimate = max(candidates(k)%error_estimate, &
                                                  4.0_wp*epsilon(1.0_wp)*max(1.0_wp, abs(candidates(k)%beta)))
            end if
            if (.not. sides%decided) then
               if (candidates(k)%route /= route_hill) candidates(k)%status = status_failed
               found = [found, candidates(k)]
               sides_found = [sides_found, sides]
               cycle
            end if
            stable_below = sides%below%verdict == verdict_stable
            stable_above = sides%above%verdict == verdict_stable
            if (stable_below .and. stable_above) cycle
            if (.not. (stable_below .or. stable_above)) candidates(k)%kind = -candidates(k)%kind
            found = [found, candidates(k)]
            sides_found = [sides_found, sides]
         end do
         first = last + 1
      end do
   end subroutine confirm_edges
   !> Candidates by β, their bounds alongside.
   pure subroutine sort_candidates(p, bounds)
      type(system_boundary_t), intent(inout) :: p(:)
      real(wp), intent(inout) :: bounds(:)
      type(system_boundary_t) :: t
      real(wp) :: b
      integer :: i, j
      do i = 2, size(p)
         t = p(i)
         b = bounds(i)
         j = i - 1
         do while (j >= 1)
            if (p(j)%beta <= t%beta) exit
            p(j + 1) = p(j)
            bounds(j + 1) = bounds(j)
            j = j - 1
         end do
         p(j + 1) = t
         bounds(j + 1) = b
      end do
   end subroutine sort_candidates

   pure subroutine sort_values(x)
      real(wp), intent(inout) :: x(:)
      real(wp) :: a
      integer :: i, j
      do i = 2, size(x)
         a = x(i)
         j = i - 1
         do while (j >= 1)
            if (x(j) <= a) exit
            x(j + 1) = x(j)
            j = j - 1
         end do
         x(j + 1) = a
      end do
   end subroutine sort_values

   pure subroutine sort_pairs(x, y)
      real(wp), intent(inout) :: x(:), y(:)
      integer :: i, j
      real(wp) :: a, b
      do i = 2, size(x)
         a = x(i)
         b = y(i)
         j = i - 1
         do while (j >= 1)
            if (x(j) <= a) exit
            x(j + 1) = x(j)
            y(j + 1) = y(j)
            j = j - 1
         end do
         x(j + 1) = a
         y(j + 1) = b
      end do
   end subroutine sort_pairs

   pure subroutine sort_points(p)
      type(system_boundary_t), intent(inout) :: p(:)
      type(system_boundary_t) :: t
      integer :: i, j
      do i = 2, size(p)
         t = p(i)
         j = i - 1
         do while (j >= 1)
            if (p(j)%beta <= t%beta) exit
            p(j + 1) = p(j)
            j = j - 1
         end do
         p(j + 1) = t
      end do
   end subroutine sort_points

   pure function int_text(i) result(text)
      integer, intent(in) :: i
      character(len=16) :: text
      write (text, '(i0)') i
   end function int_text
end module hillstab_curves_system_boundaries

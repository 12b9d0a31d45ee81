!> The pieces of the search for a system's stability edges along one row (one α) that the
!> driver hillstab_curves_system_boundaries assembles: a signed distance from the stability
!> threshold at one β, the root-finder that closes a bracket on it, the probe that finds a
!> tongue narrower than the samples, the check of an edge's two sides by the monodromy's
!> verdict, and the β where combination resonances are predicted at α = 0.
!>
!> The signed quantity q (negative inside an unstable region) with its error bound δq from the
!> monodromy's own error:
!>
!> - `quantity_discriminant` (Hamiltonian, n = 2): Broucke's D = a₁² − 4a₂ + 8 = (z₁ − z₂)²,
!>   z = λ + 1/λ; negative where the two pairs have collided and left the circle
!>   (a combination tongue); δD from |Δa₁| ≤ 4e, |Δa₂| ≤ 24‖Φ‖e (e the bound of Φ's entries), as
!>   the verdict takes them.
!> - `quantity_collision` (Hamiltonian, n ≥ 3): the same for the nearest two of the n values
!>   z_k = λ_k + 1/λ_k (one multiplier of each reciprocal pair), Re (z_k − z_l)²; δz_k from
!>   the multiplier's disc, ‖ΔΦ‖ over its condition number.
!> - `quantity_modulus` (dissipative, tr D < 0): −ln max|λ|, negative where the largest
!>   multiplier lies outside the unit circle (at +1, at −1 or off the real axis); δ from the
!>   largest multiplier's disc.
!>
!>```fortran
!> type(edge_row_t) :: row
!> type(edge_sample_t) :: s
!> row = edge_row_t(alpha, method, quantity=quantity_of(system, form))
!> s = evaluate(system, form, row, beta)
!>```
module hillstab_curves_system_edges
   use hillstab_core_kinds, only: wp, pi
   use hillstab_core_error, only: error_t
   use hillstab_core_status, only: status_failed
   use hillstab_ffi_lapack, only: dgeev
   use hillstab_hill_system, only: hill_system_t, system_form_t
   use hillstab_hill_system_floquet, only: floquet_t, system_floquet, verdict_stable, verdict_unstable, &
      verdict_marginal, kind_plus_one, kind_minus_one, kind_combination, kind_undecided
   use hillstab_integrate_system, only: system_method_t, system_monodromy_t, system_nodes_t, system_monodromy
   implicit none
   private
   public :: edge_row_t, edge_sample_t, quantity_of, evaluate, find_root, dip_probe, side_check_t, check_sides, &
      predicted_combinations, quantity_none, quantity_discriminant, quantity_collision, quantity_modulus

   !> No signed quantity: the form has no combination search (n = 1, or not Hamiltonian and not dissipative).
   integer, parameter :: quantity_none = 0
   !> Broucke's discriminant (Hamiltonian, n = 2).
   integer, parameter :: quantity_discriminant = 1
   !> The nearest pair's Re (z_k − z_l)² (Hamiltonian, n ≥ 3).
   integer, parameter :: quantity_collision = 2
   !> −ln max|λ| (dissipative).
   integer, parameter :: quantity_modulus = 3

   !> What one row's evaluations share: α, the method, the nodes of the row, the quantity.
   type :: edge_row_t
      real(wp) :: alpha = 0.0_wp              !! α
      type(system_method_t) :: method         !! method and tolerance of the monodromy
      integer :: quantity = quantity_none     !! quantity_*
      type(system_nodes_t) :: nodes           !! shared along the row
      integer :: evaluations = 0              !! monodromies computed
   end type edge_row_t

   !> The monodromy's answer at one β.
   type :: edge_sample_t
      real(wp) :: beta = 0.0_wp               !! β
      real(wp) :: q = 1.0_wp                  !! the signed quantity (negative inside)
      real(wp) :: dq = 0.0_wp                 !! its error bound
      integer :: verdict = verdict_marginal   !! the Floquet verdict
      !> the kind of the largest multiplier's place: kind_plus_one, kind_minus_one or
      !> kind_combination (real within its disc or not), kind_undecided when the point failed
      integer :: kind = kind_undecided
      logical :: ok = .false.                 !! the monodromy was computed
   end type edge_sample_t

   !> What the two sides of an edge say.
   type :: side_check_t
      type(edge_sample_t) :: below, above     !! the verdicts at β − δ₋ and β + δ₊
      real(wp) :: offset = 0.0_wp             !! the larger δ reached
      logical :: decided = .false.            !! both sides' verdicts decided within the cap
   end type side_check_t

contains

   !> The quantity a form's combination search uses (quantity_none: none).
   pure integer function quantity_of(form) result(quantity)
      type(system_form_t), intent(in) :: form  !! the prepared system
      quantity = quantity_none
      if (form%hamiltonian) then
         if (form%n == 2) quantity = quantity_discriminant
         if (form%n >= 3) quantity = quantity_collision
      else if (form%trace_d < 0.0_wp) then
         quantity = quantity_modulus
      end if
   end function quantity_of

   !> The monodromy at (α, β), its verdict and the row's signed quantity.
   function evaluate(system, form, row, beta, sharp) result(s)
      class(hill_system_t), intent(in) :: system  !! the system
      type(system_form_t), intent(in) :: form     !! prepared at its ε
      type(edge_row_t), intent(inout) :: row      !! α, method, nodes
      real(wp), intent(in) :: beta                !! β
      !> δq of quantity_collision and quantity_modulus from q's gradient in Φ's entries,
      !> Σ |∂q/∂Φ_ij| e (at an edge), instead of the multipliers' discs
      logical, intent(in), optional :: sharp
      type(edge_sample_t) :: s
      type(system_monodromy_t) :: r
      type(floquet_t) :: f
      type(error_t), allocatable :: cause
      complex(wp), allocatable :: lambda(:)
      real(wp), allocatable :: radius(:)
      real(wp) :: e, scale, a1, a2, tr2
      integer :: i, m
      s%beta = beta
      row%evaluations = row%evaluations + 1
      call system_monodromy(system, form, row%alpha, beta, row%method, row%nodes, r, cause)
      if (allocated(cause)) return
      if (r%status == status_failed) return
      s%ok = .true.
      m = 2*form%n
      scale = max(1.0_wp, maxval(abs(r%phi)))
      e = r%error_estimate*scale
      call system_floquet(r%phi, form, e, f, r%log_scale)
      s%verdict = f%verdict
      call spectrum(r%phi, e, lambda, radius)
      s%kind = lead_kind(lambda(1), radius(1))
      if (f%verdict == verdict_unstable .and. f%kind /= kind_undecided) s%kind = f%kind
      select case (row%quantity)
      case (quantity_discriminant)
         if (r%log_scale /= 0.0_wp .or. f%log_scale /= 0.0_wp) then
            call deep(s, f)
            return
         end if
         a1 = sum([(r%phi(i, i), i=1, m)])
         tr2 = sum(r%phi*transpose(r%phi))
         a2 = 0.5_wp*(a1*a1 - tr2)
         s%q = a1*a1 - 4.0_wp*a2 + 8.0_wp
         s%dq = discriminant_bound(a1, a2, e, scale)
      case (quantity_collision)
         if (r%log_scale /= 0.0_wp .or. f%log_scale /= 0.0_wp) then
            call deep(s, f)
            return
         end if
         call nearest_collision(lambda, radius, form%n, s%q, s%dq)
      case (quantity_modulus)
         s%q = -(log(max(abs(lambda(1)), tiny(1.0_wp))) + r%log_scale)
         s%dq = radius(1)/max(abs(lambda(1)), tiny(1.0_wp))
      end select
      if (present(sharp)) then
         if (sharp .and. row%quantity /= quantity_discriminant) s%dq = gradient_bound(r%phi, e, form%n, row%quantity)
      end if
   end function evaluate

   !> Σ_ij |∂q/∂Φ_ij| e + the rounding of q, the derivatives by central differences: the first-
   !> order effect of Φ's error on q (q a smooth function of Φ even where two multipliers
   !> meet and their discs do not bound them).
   function gradient_bound(phi, e, n, quantity) result(dq)
      real(wp), intent(in) :: phi(:, :), e
      integer, intent(in) :: n, quantity
      real(wp) :: dq
      real(wp) :: work(size(phi, 1), size(phi, 2)), h, plus, minus, q0
      integer :: i, j
      h = 1.0e-6_wp*max(1.0_wp, maxval(abs(phi)))
      q0 = plain_quantity(phi, n, quantity)
      dq = 64.0_wp*epsilon(1.0_wp)*max(1.0_wp, abs(q0))
      work = phi
      do j = 1, size(phi, 2)
         do i = 1, size(phi, 1)
            work(i, j) = phi(i, j) + h
            plus = plain_quantity(work, n, quantity)
            work(i, j) = phi(i, j) - h
            minus = plain_quantity(work, n, quantity)
            work(i, j) = phi(i, j)
            dq = dq + abs(plus - minus)/(2.0_wp*h)*e
         end do
      end do
   end function gradient_bound

   !> q of Φ̃ without bounds (the log-scale left out: it does not change q's derivatives).
   function plain_quantity(phi, n, quantity) result(q)
      real(wp), intent(in) :: phi(:, :)
      integer, intent(in) :: n, quantity
      real(wp) :: q
      complex(wp), allocatable :: lambda(:)
      real(wp), allocatable :: radius(:)
      real(wp) :: dq
      call spectrum(phi, 0.0_wp, lambda, radius, vectors=.false.)
      if (quantity == quantity_collision) then
         radius = 0.0_wp
         call nearest_collision(lambda, radius, n, q, dq)
      else
         q = -log(max(abs(lambda(1)), tiny(1.0_wp)))
      end if
   end function plain_quantity

   !> A point scaled by the method (Φ beyond what one double holds) is far from every edge:
   !> q = −1 inside a combination region, +1 elsewhere, decided.
   pure subroutine deep(s, f)
      type(edge_sample_t), intent(inout) :: s
      type(floquet_t), intent(in) :: f
      s%q = merge(-1.0_wp, 1.0_wp, f%verdict == verdict_unstable .and. f%kind == kind_combination)
      s%dq = 0.0_wp
   end subroutine deep

   !> The bound of D = a₁² − 4a₂ + 8 that Broucke's verdict uses: |Δa₁| ≤ 4e, |Δa₂| ≤ 24‖Φ‖e,
   !> and the rounding of the terms.
   pure real(wp) function discriminant_bound(a1, a2, e, scale) result(dd)
      real(wp), intent(in) :: a1, a2, e, scale
      real(wp) :: d1, d2, round
      round = 32.0_wp*epsilon(1.0_wp)
      d1 = 4.0_wp*e + round*scale
      d2 = 24.0_wp*scale*e + round*scale*scale
      dd = 2.0_wp*abs(a1)*d1 + 4.0_wp*d2 + round*(a1*a1 + 4.0_wp*abs(a2) + 8.0_wp)
   end function discriminant_bound

   !> The place of an unstable largest multiplier: real within its disc (at +1 or −1) or not.
   pure integer function lead_kind(lambda, radius) result(kind)
      complex(wp), intent(in) :: lambda
      real(wp), intent(in) :: radius
      if (abs(aimag(lambda)) <= max(radius, 1.0e-12_wp*abs(lambda))) then
         kind = merge(kind_plus_one, kind_minus_one, real(lambda) > 0.0_wp)
      else
         kind = kind_combination
      end if
   end function lead_kind

   !> Eigenvalues of Φ̃ by decreasing modulus, each with the radius ‖ΔΦ‖/s_i of its disc (s_i
   !> the reciprocal condition number from the left and right eigenvectors).
   subroutine spectrum(phi, e, lambda, radius, vectors)
      real(wp), intent(in) :: phi(:, :)                !! Φ̃
      real(wp), intent(in) :: e                        !! bound of the error of its entries
      complex(wp), allocatable, intent(out) :: lambda(:)
      real(wp), allocatable, intent(out) :: radius(:)
      logical, intent(in), optional :: vectors         !! false: the eigenvalues only (radius 0)
      real(wp) :: a(size(phi, 1), size(phi, 1)), vl(size(phi, 1), size(phi, 1)), vr(size(phi, 1), size(phi, 1))
      real(wp) :: wr(size(phi, 1)), wi(size(phi, 1)), cond(size(phi, 1)), work(8*size(phi, 1)), norm_error
      complex(wp) :: x(size(phi, 1)), y(size(phi, 1)), values(size(phi, 1))
      integer :: m, i, j, info, order(size(phi, 1)), moving
      m = size(phi, 1)
      a = phi
      allocate (lambda(m), radius(m))
      if (present(vectors)) then
         if (.not. vectors) then
            call dgeev("N", "N", m, a, m, wr, wi, vl, m, vr, m, work, size(work), info)
            vl = 0.0_wp
            vr = 0.0_wp
            vr(1, :) = 1.0_wp
            vl(1, :) = 1.0_wp
         else
            call dgeev("V", "V", m, a, m, wr, wi, vl, m, vr, m, work, size(work), info)
         end if
      else
         call dgeev("V", "V", m, a, m, wr, wi, vl, m, vr, m, work, size(work), info)
      end if
      if (info /= 0) then
         lambda = cmplx(0.0_wp, 0.0_wp, wp)
         radius = huge(1.0_wp)
         return
      end if
      i = 1
      do while (i <= m)
         if (wi(i) == 0.0_wp .or. i == m) then
            x = vr(:, i)
            y = vl(:, i)
            values(i) = cmplx(wr(i), 0.0_wp, wp)
            cond(i) = abs(dot_product(y, x))/max(tiny(1.0_wp), norm2(abs(x))*norm2(abs(y)))
            i = i + 1
         else
            x = cmplx(vr(:, i), vr(:, i + 1), wp)
            y = cmplx(vl(:, i), vl(:, i + 1), wp)
            cond(i) = abs(dot_product(y, x))/max(tiny(1.0_wp), norm2(abs(x))*norm2(abs(y)))
            cond(i + 1) = cond(i)
            values(i) = cmplx(wr(i), wi(i), wp)
            values(i + 1) = cmplx(wr(i + 1), wi(i + 1), wp)
            i = i + 2
         end if
      end do
      norm_error = m*e + 64.0_wp*m*epsilon(1.0_wp)*max(1.0_wp, maxval(abs(phi)))
      ! by decreasing modulus
      order = [(i, i=1, m)]
      do i = 2, m
         j = i - 1
         moving = order(i)
         do while (j >= 1)
            if (abs(values(order(j))) >= abs(values(moving))) exit
            order(j + 1) = order(j)
            j = j - 1
         end do
         order(j + 1) = moving
      end do
      lambda = values(order)
      radius = norm_error/max(cond(order), 1.0e-300_wp)
   end subroutine spectrum

   !> Hamiltonian, any n: z_k = λ_k + 1/λ_k of one multiplier of each reciprocal pair (the
   !> complex ones above the real axis, the real ones of modulus ≥ 1), and for the nearest two
   !> q = Re (z_k − z_l)² (negative for a conjugate pair: a quadruplet off the circle) with
   !> its bound from the discs.
   subroutine nearest_collision(lambda, radius, n, q, dq)
      complex(wp), intent(in) :: lambda(:)   !! the 2n multipliers, by decreasing modulus
      real(wp), intent(in) :: radius(:)      !! their discs
      integer, intent(in) :: n
      real(wp), intent(out) :: q, dq
      complex(wp) :: z(size(lambda)), d
      real(wp) :: dz(size(lambda)), best
      integer :: i, k, l, count, reals
      count = 0
      reals = 0
      do i = 1, size(lambda)
         if (aimag(lambda(i)) == 0.0_wp) reals = reals + 1
      end do
      ! the real ones come by decreasing modulus: the first half of them have |λ| ≥ 1
      k = 0
      do i = 1, size(lambda)
         if (aimag(lambda(i)) > 0.0_wp) then
            call keep(i)
         else if (aimag(lambda(i)) == 0.0_wp) then
            k = k + 1
            if (k <= (reals + 1)/2) call keep(i)
         end if
      end do
      q = huge(1.0_wp)
      dq = 0.0_wp
      best = huge(1.0_wp)
      do k = 1, min(count, n) - 1
         do l = k + 1, min(count, n)
            d = z(k) - z(l)
            if (abs(d) >= best) cycle
            best = abs(d)
            q = real(d*d)
            dq = 2.0_wp*abs(d)*(dz(k) + dz(l)) + (dz(k) + dz(l))**2 + 64.0_wp*epsilon(1.0_wp)*abs(d)**2
         end do
      end do
      if (best == huge(1.0_wp)) q = 1.0_wp

   contains

      subroutine keep(i)
         integer, intent(in) :: i
         if (count >= size(z)) return
         count = count + 1
         if (abs(lambda(i)) > 0.0_wp) then
            z(count) = lambda(i) + 1.0_wp/lambda(i)
            dz(count) = radius(i)*abs(1.0_wp - 1.0_wp/lambda(i)**2)
         else
            z(count) = cmplx(huge(1.0_wp)/4.0_wp, 0.0_wp, wp)
            dz(count) = 0.0_wp
         end if
      end subroutine keep
   end subroutine nearest_collision

   !> Brent's root-finder on q over [a, b], q(a) and q(b) of opposite signs (or one zero):
   !> `root` the evaluation at the final estimate, `width` the final bracket's width (0 when
   !> q(root) is exactly 0), `other` the evaluation at its other end.
   subroutine find_root(system, form, row, sa, sb, root, other, width)
      class(hill_system_t), intent(in) :: system  !! the system
      type(system_form_t), intent(in) :: form  !! prepared at its ε
      type(edge_row_t), intent(inout) :: row  !! α, method, nodes; counts the evaluations
      type(edge_sample_t), intent(in) :: sa, sb   !! the bracket's ends
      type(edge_sample_t), intent(out) :: root  !! the evaluation at the root
      type(edge_sample_t), intent(out) :: other  !! the evaluation at the final bracket's other end
      real(wp), intent(out) :: width  !! the final bracket's width
      type(edge_sample_t) :: a, b, c
      real(wp) :: d, e, tol, xm, p, q, r, s, xtol
      integer :: step
      a = sa
      b = sb
      c = a
      d = b%beta - a%beta
      e = d
      xtol = 1.0e-13_wp*max(1.0_wp, abs(sa%beta), abs(sb%beta))
      if (b%q == 0.0_wp) then
         root = b
         other = a
         width = 0.0_wp
         return
      end if
      do step = 1, 200
         if (sign(1.0_wp, b%q) == sign(1.0_wp, c%q) .and. c%q /= 0.0_wp) then
            c = a
            d = b%beta - a%beta
            e = d
         end if
         if (abs(c%q) < abs(b%q)) then
            a = b
            b = c
            c = a
         end if
         tol = 2.0_wp*epsilon(1.0_wp)*abs(b%beta) + 0.5_wp*xtol
         xm = 0.5_wp*(c%beta - b%beta)
         if (abs(xm) <= tol .or. b%q == 0.0_wp) exit
         if (abs(e) >= tol .and. abs(a%q) > abs(b%q)) then
            s = b%q/a%q
            if (a%beta == c%beta) then
               p = 2.0_wp*xm*s
               q = 1.0_wp - s
            else
               q = a%q/c%q
               r = b%q/c%q
               p = s*(2.0_wp*xm*q*(q - r) - (b%beta - a%beta)*(r - 1.0_wp))
               q = (q - 1.0_wp)*(r - 1.0_wp)*(s - 1.0_wp)
            end if
            if (p > 0.0_wp) q = -q
            p = abs(p)
            if (2.0_wp*p < min(3.0_wp*xm*q - abs(tol*q), abs(e*q))) then
               e = d
               d = p/q
            else
               d = xm
               e = d
            end if
         else
            d = xm
            e = d
         end if
         a = b
         if (abs(d) > tol) then
            b = evaluate(system, form, row, b%beta + d)
         else
            b = evaluate(system, form, row, b%beta + sign(tol, xm))
         end if
      end do
      root = b
      other = c
      width = merge(0.0_wp, abs(c%beta - b%beta), b%q == 0.0_wp)
   end subroutine find_root

   !> A tongue narrower than the samples: golden-section search for q's minimum over [lo, hi]
   !> (q positive at the samples, smallest at the middle one), stopped at the first evaluation
   !> decided inside (q < −δq), returned in `inside` (`found`).
   subroutine dip_probe(system, form, row, lo, hi, inside, found)
      class(hill_system_t), intent(in) :: system  !! the system
      type(system_form_t), intent(in) :: form  !! prepared at its ε
      type(edge_row_t), intent(inout) :: row  !! α, method, nodes; counts the evaluations
      real(wp), intent(in) :: lo  !! the interval, lower end
      real(wp), intent(in) :: hi  !! the interval, upper end
      type(edge_sample_t), intent(out) :: inside  !! an evaluation decided inside (when found)
      logical, intent(out) :: found  !! a tongue was found
      real(wp), parameter :: ratio = 0.6180339887498949_wp
      type(edge_sample_t) :: s1, s2
      real(wp) :: a, b
      integer :: step
      a = lo
      b = hi
      found = .false.
      s1 = evaluate(system, form, row, b - ratio*(b - a))
      s2 = evaluate(system, form, row, a + ratio*(b - a))
      do step = 1, 60
         if (decided_inside(s1)) then
            inside = s1
            found = .true.
            return
         end if
         if (decided_inside(s2)) then
            inside = s2
            found = .true.
            return
         end if
         if (b - a <= 1.0e-12_wp*max(1.0_wp, abs(b))) return
         if (s1%q <= s2%q) then
            b = s2%beta
            s2 = s1
            s1 = evaluate(system, form, row, b - ratio*(b - a))
         else
            a = s1%beta
            s1 = s2
            s2 = evaluate(system, form, row, a + ratio*(b - a))
         end if
      end do
   end subroutine dip_probe

   !> Inside an unstable region, decided: q < −δq.
   pure logical function decided_inside(s)
      type(edge_sample_t), intent(in) :: s
      decided_inside = s%ok .and. s%q < -s%dq
   end function decided_inside

   !> The verdicts on the two sides of an edge at β: at β ∓ δ, δ from `start` growing fourfold
   !> up to `cap` until both are decided.
   function check_sides(system, form, row, beta, start, cap) result(sides)
      class(hill_system_t), intent(in) :: system  !! the system
      type(system_form_t), intent(in) :: form  !! prepared at its ε
      type(edge_row_t), intent(inout) :: row  !! α, method, nodes; counts the evaluations
      real(wp), intent(in) :: beta  !! the edge
      real(wp), intent(in) :: start  !! the first δ
      real(wp), intent(in) :: cap  !! the largest δ
      type(side_check_t) :: sides
      real(wp) :: delta
      logical :: below_done, above_done
      delta = min(start, cap)
      below_done = .false.
      above_done = .false.
      do
         if (.not. below_done) then
            sides%below = evaluate(system, form, row, beta - delta)
            below_done = sides%below%verdict /= verdict_marginal
         end if
         if (.not. above_done) then
            sides%above = evaluate(system, form, row, beta + delta)
            above_done = sides%above%verdict /= verdict_marginal
         end if
         sides%offset = delta
         if (below_done .and. above_done) exit
         if (delta >= cap) exit
         delta = min(4.0_wp*delta, cap)
      end do
      sides%decided = below_done .and. above_done
   end function check_sides

   !> The β of [β_min, β_max] where a combination resonance is predicted at α = 0: the
   !> undriven frequencies ω_i(β) (the imaginary parts of the eigenvalues of A = [[0, I],
   !> [−M⁻¹K(β), D]], K(β) the mean of K at α = 0) meet ω_i + ω_j = kΩ (sum type, any form)
   !> or |ω_i − ω_j| = kΩ (difference type: when G ≠ 0, K is unsymmetric or the system is
   !> not Hamiltonian), Ω = 2π/P, k = 1 … 8; found by bisection over the samples `betas`.
   subroutine predicted_combinations(system, form, betas, predicted)
      class(hill_system_t), intent(in) :: system  !! the system
      type(system_form_t), intent(in) :: form  !! prepared at its ε
      real(wp), intent(in) :: betas(:)                  !! ascending samples
      real(wp), allocatable, intent(out) :: predicted(:)  !! the predicted β
      real(wp), allocatable :: omega(:, :), p0(:, :), b0(:, :)
      logical, allocatable :: valid(:)
      real(wp) :: big_omega, lo, hi, f_lo, f_hi, mid, f_mid
      integer :: n, j, i, l, k, kind, step
      logical :: difference
      n = form%n
      allocate (predicted(0))
      if (n < 2 .or. size(betas) < 2) return
      call mean_stiffness(system, form, p0, b0)
      allocate (omega(n, size(betas)), valid(size(betas)))
      do j = 1, size(betas)
         call frequencies(betas(j), omega(:, j), valid(j))
      end do
      big_omega = 2.0_wp*pi/form%period
      difference = form%gyroscopic .or. .not. system%symmetric() .or. .not. form%hamiltonian
      do kind = 1, merge(2, 1, difference)
         do i = 1, n - 1
            do l = i + 1, n
               do k = 1, 8
                  do j = 1, size(betas) - 1
                     if (.not. (valid(j) .and. valid(j + 1))) cycle
                     f_lo = condition(omega(:, j), i, l, k, kind)
                     f_hi = condition(omega(:, j + 1), i, l, k, kind)
                     if ((f_lo < 0.0_wp) .eqv. (f_hi < 0.0_wp)) cycle
                     lo = betas(j)
                     hi = betas(j + 1)
                     do step = 1, 50
                        mid = 0.5_wp*(lo + hi)
                        f_mid = condition_at(mid, i, l, k, kind)
                        if ((f_mid < 0.0_wp) .eqv. (f_lo < 0.0_wp)) then
                           lo = mid
                        else
                           hi = mid
                        end if
                        if (hi - lo <= 1.0e-12_wp*max(1.0_wp, abs(mid))) exit
                     end do
                     predicted = [predicted, 0.5_wp*(lo + hi)]
                  end do
               end do
            end do
         end do
      end do

   contains

      !> ω_i + ω_l − kΩ (kind 1) or |ω_i − ω_l| − kΩ (kind 2).
      pure real(wp) function condition(w, i, l, k, kind)
         real(wp), intent(in) :: w(:)
         integer, intent(in) :: i
         integer, intent(in) :: l
         integer, intent(in) :: k
         integer, intent(in) :: kind
         if (kind == 1) then
            condition = w(i) + w(l) - k*big_omega
         else
            condition = abs(w(i) - w(l)) - k*big_omega
         end if
      end function condition

      real(wp) function condition_at(beta, i, l, k, kind)
         real(wp), intent(in) :: beta
         integer, intent(in) :: i, l, k, kind
         real(wp) :: w(n)
         logical :: ok
         call frequencies(beta, w, ok)
         condition_at = condition(w, i, l, k, kind)
         if (.not. ok) condition_at = 0.0_wp
      end function condition_at

      !> The n undriven frequencies at β, ascending; `ok` false when fewer than n oscillate.
      subroutine frequencies(beta, w, ok)
         real(wp), intent(in) :: beta
         real(wp), intent(out) :: w(:)
         logical, intent(out) :: ok
         real(wp) :: a(2*n, 2*n), wr(2*n), wi(2*n), vl(1, 1), vr(1, 1), work(8*2*n), t
         integer :: info, c, q, r
         a = 0.0_wp
         do q = 1, n
            a(q, n + q) = 1.0_wp
         end do
         a(n + 1:, 1:n) = -matmul(form%m_inverse, p0 + beta*b0)
         a(n + 1:, n + 1:) = form%d
         call dgeev("N", "N", 2*n, a, 2*n, wr, wi, vl, 1, vr, 1, work, size(work), info)
         w = 0.0_wp
         ok = .false.
         if (info /= 0) return
         c = 0
         do q = 1, 2*n
            if (wi(q) > 0.0_wp .and. c < n) then
               c = c + 1
               w(c) = wi(q)
            end if
         end do
         ok = c == n
         ! ascending (insertion sort)
         do q = 2, c
            t = w(q)
            r = q - 1
            do while (r >= 1)
               if (w(r) <= t) exit
               w(r + 1) = w(r)
               r = r - 1
            end do
            w(r + 1) = t
         end do
      end subroutine frequencies
   end subroutine predicted_combinations

   !> The mean over the period of K's two parts at α = 0.
   subroutine mean_stiffness(system, form, p0, b0)
      class(hill_system_t), intent(in) :: system
      type(system_form_t), intent(in) :: form
      real(wp), allocatable, intent(out) :: p0(:, :), b0(:, :)
      real(wp) :: p(form%n, form%n), b(form%n, form%n)
      integer :: j
      integer, parameter :: samples = 8
      allocate (p0(form%n, form%n), b0(form%n, form%n))
      p0 = 0.0_wp
      b0 = 0.0_wp
      do j = 0, samples - 1
         call system%stiffness(0.0_wp, form%period*j/samples, p, b)
         p0 = p0 + p/samples
         b0 = b0 + b/samples
      end do
   end subroutine mean_stiffness
end module hillstab_curves_system_edges

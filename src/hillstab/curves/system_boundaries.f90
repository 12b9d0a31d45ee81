!> Transition curves of a system of Hill equations at one α: the β where a multiplier pair
!> passes +1 or −1 (simple resonances) and the β where two multipliers of opposite Krein
!> signature meet on the unit circle and leave it (combination resonances).
!>
!> - Simple resonances by Hill's method with block matrices: a solution with multiplier ±1 is
!>   x = Σ_k c_k e^{iν_k τ}, ν_k = (k + s/2) 2π/P (s = 0: +1, s = 1: −1), and the equation
!>   becomes the generalised eigenproblem [−ν_k² M + iν_k(C + εM + G)] c_k + Σ_h P̂_h c_{k−h}
!>   = −β Σ_h B̂_h c_{k−h} in β, its blocks n × n, the harmonics P̂_h, B̂_h of K's two parts
!>   (p + βb) taken from K at 2H + 2 points of the period (exact for H harmonics), |k| ≤ K
!>   modes, solved by LAPACK zggev. The truncation is checked by a second solve with more
!>   modes: a β whose two values differ by more than 1e-8 max(1, |β|) is dropped, the
!>   difference is its error estimate. Each β is then checked against the monodromy: the
!>   distance of the nearest multiplier from ±1 (`check`).
!> - Combination resonances (Hamiltonian n = 2) by root-finding on Broucke's discriminant
!>   D(β) = a₁² − 4a₂ + 8, negative inside a combination tongue: its sign changes over the
!>   samples of a row, each bracket closed by bisection to 1e-12 max(1, |β|); for other n by
!>   bisection on the verdict `kind_combination`.
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
   use hillstab_hill_system_floquet, only: system_floquet_t, system_floquet, kind_plus_one, kind_minus_one, &
      kind_combination, verdict_unstable
   use hillstab_integrate_system, only: system_method_t, system_monodromy_t, system_nodes_t, system_monodromy
   implicit none
   private
   public :: system_boundary_t, system_boundaries, system_hill_betas, route_hill, route_discriminant, route_verdict

   !> Route, Hill's method (a simple resonance).
   integer, parameter :: route_hill = 1
   !> Route, a root of Broucke's discriminant (combination, n = 2).
   integer, parameter :: route_discriminant = 2
   !> Route, bisection on the verdict (combination, any n).
   integer, parameter :: route_verdict = 3

   !> One point of a transition curve.
   type :: system_boundary_t
      real(wp) :: alpha = 0.0_wp          !! α
      real(wp) :: beta = 0.0_wp           !! β on the curve
      integer :: kind = kind_plus_one     !! kind_plus_one, kind_minus_one or kind_combination
      integer :: route = route_hill       !! how it was found (route_*)
      !> the check at (α, β): distance of the nearest multiplier from ±1 (simple), |D| relative
      !> to its scale (discriminant), the final bracket's width (verdict)
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
      real(wp) :: scale, omega, nu_top
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
      do k = 1, size(fine)
         if (size(coarse) == 0) exit
         if (minval(abs(coarse - fine(k))) <= 1.0e-8_wp*max(1.0_wp, abs(fine(k)))) then
            betas = [betas, fine(k)]
            estimates = [estimates, max(minval(abs(coarse - fine(k))), epsilon(1.0_wp)*max(1.0_wp, abs(fine(k))))]
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

   !> Every transition point of one α over the window of `betas` (the samples of a row): the
   !> simple ones by Hill's method, checked; the combination ones by root-finding on the
   !> samples' brackets. Sorted by β.
   subroutine system_boundaries(system, form, alpha, betas, method, found, error)
      class(hill_system_t), intent(in) :: system      !! the system
      type(system_form_t), intent(in) :: form         !! prepared at its ε
      real(wp), intent(in) :: alpha                   !! α
      real(wp), intent(in) :: betas(:)                !! ascending samples (the window and the brackets)
      type(system_method_t), intent(in) :: method     !! the monodromy's method and tolerance
      type(system_boundary_t), allocatable, intent(out) :: found(:)  !! the points, by β
      type(error_t), allocatable, intent(out) :: error  !! err_singular when Hill's method fails
      real(wp), allocatable :: roots(:), estimates(:), g(:)
      logical, allocatable :: inside(:)
      type(system_nodes_t) :: nodes
      type(system_boundary_t) :: point
      integer :: s, k, j
      allocate (found(0))
      do s = 1, 2
         call system_hill_betas(system, form, alpha, merge(1, -1, s == 1), betas(1), betas(size(betas)), roots, &
                                estimates, error)
         if (allocated(error)) return
         do k = 1, size(roots)
            point = system_boundary_t(alpha, roots(k), merge(kind_plus_one, kind_minus_one, s == 1), route_hill, &
                                      0.0_wp, estimates(k), status_ok)
            point%check = distance_from(merge(1.0_wp, -1.0_wp, s == 1), roots(k))
            if (.not. (point%check <= 1.0e-4_wp)) point%status = status_failed
            found = [found, point]
         end do
      end do
      if (.not. form%hamiltonian) return
      ! combination tongues: D < 0 (n = 2), or the verdict's kind (any n)
      allocate (g(size(betas)), inside(size(betas)))
      do j = 1, size(betas)
         g(j) = combination_function(betas(j))
         inside(j) = g(j) < 0.0_wp
      end do
      do j = 1, size(betas) - 1
         if (inside(j) .eqv. inside(j + 1)) cycle
         call close_bracket(betas(j), betas(j + 1), g(j))
      end do
      ! n = 2: a tongue narrower than the samples shows as a positive local minimum of D
      ! (z₁ and z₂ nearly meet): its minimum, by golden section, decides whether D dips below 0
      if (form%n == 2) then
         do j = 2, size(betas) - 1
            if (inside(j) .or. inside(j - 1) .or. inside(j + 1)) cycle
            if (.not. (g(j) <= g(j - 1) .and. g(j) <= g(j + 1))) cycle
            call dip(betas(j - 1), betas(j + 1))
         end do
      end if
      call sort_points(found)

   contains

      !> Bisection between a sample inside a combination tongue and one outside.
      subroutine close_bracket(a, b, g_a)
         real(wp), intent(in) :: a, b, g_a
         real(wp) :: lo, hi, mid
         integer :: step
         lo = a
         hi = b
         do step = 1, 80
            mid = 0.5_wp*(lo + hi)
            if ((combination_function(mid) < 0.0_wp) .eqv. (g_a < 0.0_wp)) then
               lo = mid
            else
               hi = mid
            end if
            if (abs(hi - lo) <= 1.0e-12_wp*max(1.0_wp, abs(mid))) exit
         end do
         point = system_boundary_t(alpha, 0.5_wp*(lo + hi), kind_combination, &
                                   merge(route_discriminant, route_verdict, form%n == 2), abs(hi - lo), abs(hi - lo), &
                                   status_ok)
         found = [found, point]
      end subroutine close_bracket

      !> Golden-section search for D's minimum on [a, b]; where it is negative, the tongue's two
      !> edges by bisection on each side.
      subroutine dip(a, b)
         real(wp), intent(in) :: a, b
         real(wp), parameter :: ratio = 0.6180339887498949_wp
         real(wp) :: x1, x2, f1, f2, lo, hi
         integer :: step
         lo = a
         hi = b
         x1 = hi - ratio*(hi - lo)
         x2 = lo + ratio*(hi - lo)
         f1 = combination_function(x1)
         f2 = combination_function(x2)
         do step = 1, 60
            if (f1 < 0.0_wp .or. f2 < 0.0_wp) exit
            if (f1 <= f2) then
               hi = x2
               x2 = x1
               f2 = f1
               x1 = hi - ratio*(hi - lo)
               f1 = combination_function(x1)
            else
               lo = x1
               x1 = x2
               f1 = f2
               x2 = lo + ratio*(hi - lo)
               f2 = combination_function(x2)
            end if
            if (hi - lo <= 1.0e-12_wp*max(1.0_wp, abs(hi))) exit
         end do
         if (f1 < 0.0_wp) then
            call close_bracket(x1, a, f1)
            call close_bracket(x1, b, f1)
         else if (f2 < 0.0_wp) then
            call close_bracket(x2, a, f2)
            call close_bracket(x2, b, f2)
         end if
      end subroutine dip

      !> The distance of the multiplier nearest to `target` at β.
      real(wp) function distance_from(target, beta)
         real(wp), intent(in) :: target, beta
         type(system_monodromy_t) :: r
         type(system_floquet_t) :: f
         type(error_t), allocatable :: cause
         call system_monodromy(system, form, alpha, beta, method, nodes, r, cause)
         distance_from = huge(1.0_wp)
         if (allocated(cause)) return
         call system_floquet(r%phi, form, r%error_estimate*max(1.0_wp, maxval(abs(r%phi))), f, r%log_scale)
         distance_from = minval(abs(f%multipliers*exp(f%log_scale) - target))
      end function distance_from

      !> Negative inside a combination tongue: D (n = 2), else −1 where the verdict's kind is
      !> combination, +1 elsewhere.
      real(wp) function combination_function(beta)
         real(wp), intent(in) :: beta
         type(system_monodromy_t) :: r
         type(system_floquet_t) :: f
         type(error_t), allocatable :: cause
         call system_monodromy(system, form, alpha, beta, method, nodes, r, cause)
         combination_function = 1.0_wp
         if (allocated(cause)) return
         call system_floquet(r%phi, form, r%error_estimate*max(1.0_wp, maxval(abs(r%phi))), f, r%log_scale)
         if (form%n == 2 .and. f%log_scale == 0.0_wp) then
            ! D, less what round-off and the error of Φ leave undecided (a touch of D = 0,
            ! as at α = 0, is no tongue)
            combination_function = f%discriminant + (64.0_wp*epsilon(1.0_wp) + 8.0_wp*r%error_estimate)* &
                                   (f%trace**2 + 4.0_wp*abs(f%a2) + 8.0_wp)
         else if (f%verdict == verdict_unstable .and. f%kind == kind_combination) then
            combination_function = -1.0_wp
         end if
      end function combination_function
   end subroutine system_boundaries

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

!> All Floquet exponents of a period product kept factored, Φ = F_K ⋯ F_2 F_1, however many
!> decades the multipliers span. One double-precision Φ resolves a multiplier only down to
!> about ε_mach ‖Φ‖: at a strongly unstable point the smaller ones are lost in the largest.
!> The factors are each well conditioned; the product QR (orthogonal iteration over the
!> period) keeps them apart: Q₀ = I, and for k = 1 … K, F_k Q_{k−1} = Q_k R_k, so that
!> Φ Q₀ = Q_K R_K ⋯ R₁. Repeated over the period (Q₀ ← Q_K, a sweep) the leading columns of Q₀
!> converge to Φ's dominant invariant subspaces, each at the rate of the gap between the
!> moduli on either side of it, and W = Q₀ᵀ Q_K becomes block diagonal. Between two converged
!> splits lies a group of multipliers of nearly equal modulus (a complex pair, say): its
!> multipliers are the eigenvalues of W_gg ∏ R_k,gg, a small product accumulated with its
!> own scale, whose moduli are close, so that LAPACK's dgeev resolves them all. The
!> logarithms of the moduli come from the scales and these small eigenvalues: no quantity
!> ever holds two multipliers of different magnitude in one double.
!>
!> A sweep stops the iteration when its splits are those of the sweep before, every exponent
!> moved by less than a tenth of the target since then (or by less than the rounding of the
!> sums, 4 m ε √K), and every group's eigenvalues are known to that; or after five such
!> sweeps in a row whose groups' eigenvalues are not known to that (a cluster of moduli too
!> close to split soon, whose block is too far from normal). An exponent is
!> `resolved` when the iteration stopped so and that rounding lies below the target; else
!> the value is the best the iteration reached and the caller says so.
!>
!>```fortran
!> real(wp) :: factors(4, 4, 3), mu(4)
!> logical :: resolved(4)
!> call factored_exponents(factors, 2.0_wp, 1.0e-10_wp, mu, resolved)
!>```
module hillstab_hill_system_exponents
   use hillstab_core_kinds, only: wp
   use hillstab_ffi_lapack, only: dgeev
   implicit none
   private
   public :: factored_exponents, householder_qr, identity_matrix

   !> most sweeps over the period
   integer, parameter :: max_sweeps = 60
   !> a split between leading and trailing columns is converged when the trailing rows of W's
   !> leading columns fall below this
   real(wp), parameter :: split_level = 1.0e-13_wp
   !> sweeps with the same splits and exponents after which the iteration stops unsettled
   integer, parameter :: stagnation = 5

contains

   !> The exponents ln|λ_i|/period of Φ = F_K ⋯ F_1 (`factors(:, :, k)` = F_k), all m of them,
   !> by decreasing value.
   subroutine factored_exponents(factors, period, target, exponents, resolved, sweeps, arguments)
      real(wp), intent(in) :: factors(:, :, :)   !! F_1 … F_K (m × m × K), F_1 applied first
      real(wp), intent(in) :: period             !! the period the exponents are per
      real(wp), intent(in) :: target             !! the accuracy wanted of each exponent
      real(wp), intent(out) :: exponents(:)      !! m exponents, decreasing
      logical, intent(out) :: resolved(:)        !! each exponent to the target
      integer, intent(out), optional :: sweeps   !! sweeps spent
      !> arg λ_i of the same multipliers, in (−π, π]: with the exponents, every multiplier
      real(wp), intent(out), optional :: arguments(:)
      integer :: m, k, sweep, g, n_groups, lo, hi, i
      real(wp) :: q(size(factors, 1), size(factors, 1)), q0(size(factors, 1), size(factors, 1)), &
                  z(size(factors, 1), size(factors, 1)), r(size(factors, 1), size(factors, 1)), &
                  w(size(factors, 1), size(factors, 1)), blocks(size(factors, 1), size(factors, 1)), &
                  block_scale(size(factors, 1)), previous(size(factors, 1)), current(size(factors, 1)), &
                  uncertainty(size(factors, 1)), phases(size(factors, 1))
      integer :: starts(size(factors, 1) + 1), new_starts(size(factors, 1) + 1), n_new, unchanged
      logical :: settled
      real(wp) :: noise
      m = size(factors, 1)
      ! the rounding of the sums of ln R_kk: each QR moves R_kk by a few m ε relative
      noise = 4.0_wp*m*epsilon(1.0_wp)*sqrt(real(size(factors, 3), wp))
      q = identity_matrix(m)
      ! one group of all at first: the first sweep is the plain product in R's form
      n_groups = 1
      starts(1) = 1
      starts(2) = m + 1
      previous = huge(1.0_wp)
      current = 0.0_wp
      uncertainty = 0.0_wp
      settled = .false.
      unchanged = 0
      do sweep = 1, max_sweeps
         q0 = q
         blocks = 0.0_wp
         do g = 1, n_groups
            lo = starts(g)
            hi = starts(g + 1) - 1
            blocks(lo:hi, lo:hi) = identity_matrix(hi - lo + 1)
         end do
         block_scale = 0.0_wp
         do k = 1, size(factors, 3)
            z = matmul(factors(:, :, k), q)
            call householder_qr(z, q, r)
            do g = 1, n_groups
               lo = starts(g)
               hi = starts(g + 1) - 1
               call accumulate(r(lo:hi, lo:hi), blocks(lo:hi, lo:hi), block_scale(lo))
            end do
         end do
         w = matmul(transpose(q0), q)
         ! the group's multipliers from its block of the closed product
         do g = 1, n_groups
            lo = starts(g)
            hi = starts(g + 1) - 1
            call group_moduli(matmul(w(lo:hi, lo:hi), blocks(lo:hi, lo:hi)), block_scale(lo), current(lo:hi), &
                              uncertainty(lo:hi), phases(lo:hi))
         end do
         ! the splits W shows converged now
         n_new = 1
         new_starts(1) = 1
         do i = 1, m - 1
            if (maxval(abs(w(i + 1:m, 1:i))) <= split_level) then
               n_new = n_new + 1
               new_starts(n_new) = i + 1
            end if
         end do
         new_starts(n_new + 1) = m + 1
         if (sweep > 1 .and. n_new == n_groups) then
            if (all(new_starts(1:n_new + 1) == starts(1:n_groups + 1)) .and. &
                all(abs(sorted(current) - sorted(previous)) <= max(0.1_wp*target*period, noise))) then
               settled = all(uncertainty <= max(0.1_wp*target*period, noise))
               unchanged = unchanged + 1
            else
               unchanged = 0
            end if
         end if
         previous = current
         ! settled, or stagnant: the groups left split only at the rate of moduli within a few
         ! tenths of each other, which their blocks' eigenvalues resolve already (or never will)
         if (settled .or. unchanged >= stagnation) exit
         ! the groups of the next sweep: those converged, never coarser than those used now
         n_groups = n_new
         starts(1:n_new + 1) = new_starts(1:n_new + 1)
      end do
      if (present(sweeps)) sweeps = min(sweep, max_sweeps)
      exponents = sorted(current)/period
      ! an exponent is resolved when the iteration settled and its group's eigenvalues are
      ! known to the target (their moduli within a few decades of each other)
      resolved = settled .and. noise <= target*period
      do i = 1, m
         if (uncertainty(i) > 0.1_wp*target*period) resolved(i) = .false.
      end do
      resolved = resolved_sorted(current, resolved)
      if (present(arguments)) arguments = values_sorted(current, phases)
   end subroutine factored_exponents

   !> blk ← r blk, rescaled by a power of two into `scale` (its logarithm).
   pure subroutine accumulate(r, blk, scale)
      real(wp), intent(in) :: r(:, :)
      real(wp), intent(inout) :: blk(:, :)
      real(wp), intent(inout) :: scale
      real(wp) :: big
      blk = matmul(r, blk)
      big = maxval(abs(blk))
      if (big > 0.0_wp .and. (big > 1.0e50_wp .or. big < 1.0e-50_wp)) then
         blk = blk*2.0_wp**(-exponent(big))
         scale = scale + exponent(big)*log(2.0_wp)
      end if
   end subroutine accumulate

   !> ln|λ| of the eigenvalues of e^scale b, and each one's uncertainty in ln|λ| (its
   !> eigenvalue's error bound relative to its modulus).
   subroutine group_moduli(b, scale, log_moduli, uncertainty, phases)
      real(wp), intent(in) :: b(:, :), scale
      real(wp), intent(out) :: log_moduli(:), uncertainty(:), phases(:)
      real(wp) :: a(size(b, 1), size(b, 1)), wr(size(b, 1)), wi(size(b, 1)), dummy(1, 1), work(8*size(b, 1))
      real(wp) :: modulus, norm
      integer :: p, info, i
      p = size(b, 1)
      if (p == 1) then
         modulus = abs(b(1, 1))
         log_moduli(1) = safe_log(modulus) + scale
         uncertainty(1) = 0.0_wp
         phases(1) = merge(0.0_wp, 4.0_wp*atan(1.0_wp), b(1, 1) >= 0.0_wp)
         return
      end if
      a = b
      norm = maxval(sum(abs(b), dim=1))
      call dgeev("N", "N", p, a, p, wr, wi, dummy, 1, dummy, 1, work, size(work), info)
      if (info /= 0) then
         log_moduli = safe_log(norm) + scale
         uncertainty = huge(1.0_wp)
         phases = 0.0_wp
         return
      end if
      do i = 1, p
         modulus = hypot(wr(i), wi(i))
         log_moduli(i) = safe_log(modulus) + scale
         phases(i) = atan2(wi(i), wr(i))
         ! backward-stable eigenvalues: |Δλ| ≲ p ε ‖b‖ (a simple eigenvalue of a group whose
         ! moduli are close); relative to |λ| that is the uncertainty of ln|λ|
         if (modulus > 0.0_wp) then
            uncertainty(i) = 16.0_wp*p*epsilon(1.0_wp)*norm/modulus
         else
            uncertainty(i) = huge(1.0_wp)
         end if
      end do
   end subroutine group_moduli

   !> ln x, and a very negative number for 0.
   pure real(wp) function safe_log(x)
      real(wp), intent(in) :: x
      if (x > 0.0_wp) then
         safe_log = log(x)
      else
         safe_log = -huge(1.0_wp)/4.0_wp
      end if
   end function safe_log

   !> x in decreasing order.
   pure function sorted(x) result(y)
      real(wp), intent(in) :: x(:)
      real(wp) :: y(size(x))
      y = x(decreasing_order(x))
   end function sorted

   !> The values v carried into x's decreasing order.
   pure function values_sorted(x, v) result(out)
      real(wp), intent(in) :: x(:), v(:)
      real(wp) :: out(size(x))
      out = v(decreasing_order(x))
   end function values_sorted

   !> The indices of x in decreasing order (insertion sort: m ≤ 40).
   pure function decreasing_order(x) result(order)
      real(wp), intent(in) :: x(:)
      integer :: order(size(x)), i, k, t
      order = [(i, i=1, size(x))]
      do i = 2, size(x)
         t = order(i)
         k = i - 1
         do while (k >= 1)
            if (x(order(k)) >= x(t)) exit
            order(k + 1) = order(k)
            k = k - 1
         end do
         order(k + 1) = t
      end do
   end function decreasing_order

   !> The flags of x carried into x's decreasing order.
   pure function resolved_sorted(x, flags) result(out)
      real(wp), intent(in) :: x(:)
      logical, intent(in) :: flags(:)
      logical :: out(size(x))
      out = flags(decreasing_order(x))
   end function resolved_sorted

   !> a = q r by Householder reflections (a square matrix): q orthogonal, r upper triangular
   !> with a non-negative diagonal.
   pure subroutine householder_qr(a, q, r)
      real(wp), intent(in) :: a(:, :)   !! the matrix (m × m)
      real(wp), intent(out) :: q(:, :)  !! Q
      real(wp), intent(out) :: r(:, :)  !! R
      real(wp) :: v(size(a, 1)), norm, alpha, vtv
      real(wp) :: vs(size(a, 1), size(a, 1)), betas(size(a, 1))
      integer :: m, k, j
      m = size(a, 1)
      r = a
      betas = 0.0_wp
      vs = 0.0_wp
      do k = 1, m - 1
         norm = norm2(r(k:m, k))
         if (norm == 0.0_wp) cycle
         alpha = -sign(norm, r(k, k))
         v(k:m) = r(k:m, k)
         v(k) = v(k) - alpha
         vtv = dot_product(v(k:m), v(k:m))
         if (vtv == 0.0_wp) cycle
         betas(k) = 2.0_wp/vtv
         vs(k:m, k) = v(k:m)
         do j = k, m
            r(k:m, j) = r(k:m, j) - (betas(k)*dot_product(v(k:m), r(k:m, j)))*v(k:m)
         end do
         r(k + 1:m, k) = 0.0_wp
      end do
      ! Q = H_1 H_2 ⋯ H_{m−1} applied to the identity, last reflection first
      q = identity_matrix(m)
      do k = m - 1, 1, -1
         if (betas(k) == 0.0_wp) cycle
         do j = 1, m
            q(k:m, j) = q(k:m, j) - (betas(k)*dot_product(vs(k:m, k), q(k:m, j)))*vs(k:m, k)
         end do
      end do
      ! a non-negative diagonal: flip the signs of R's rows and Q's columns together
      do k = 1, m
         if (r(k, k) < 0.0_wp) then
            r(k, :) = -r(k, :)
            q(:, k) = -q(:, k)
         end if
      end do
   end subroutine householder_qr

   !> The identity matrix of order m.
   pure function identity_matrix(m) result(a)
      integer, intent(in) :: m  !! the order
      real(wp) :: a(m, m)
      integer :: i
      a = 0.0_wp
      do i = 1, m
         a(i, i) = 1.0_wp
      end do
   end function identity_matrix
end module hillstab_hill_system_exponents

!> Floquet analysis of a system's monodromy Φ (2n × 2n, acting on y = (x, x')): the
!> multipliers λ (eigenvalues of Φ), the exponents ln|λ|/P, the invariants a₁ = tr Φ and
!> a₂ = ((tr Φ)² − tr Φ²)/2, the structural defect, and a verdict that is decided, not
!> guessed: every decision holds for any Φ within the method's error bound of the computed
!> one, else the point is `verdict_marginal`.
!>
!> - Hamiltonian, n = 1: S = tr Φ, stable when |S| < 2 − δ, unstable when |S| > 2 + δ.
!> - Hamiltonian, n = 2 (the fast path, no eigenvalue solver): Broucke's form. The numbers
!>   z = λ + 1/λ of the two pairs are the roots of z² − a₁ z + a₂ − 2 = 0; the system is
!>   stable iff both are real in (−2, 2). A negative discriminant D = a₁² − 4a₂ + 8 is a
!>   complex quadruplet off the unit circle: two multipliers of opposite Krein signature have
!>   met and left it, a combination resonance. A real z beyond ±2 is a real pair at +1 or −1.
!> - Hamiltonian, any n: the eigenvalues (LAPACK dgeev) with their condition numbers s_i
!>   (left and right eigenvectors) give each multiplier a disc of radius δ_i = ‖ΔΦ‖/s_i.
!>   Unstable when a disc lies outside the unit circle; stable when every disc meets the
!>   circle and no two discs meet, nor a disc the real axis (a simple multiplier on the circle
!>   stays there under every Hamiltonian perturbation); else marginal.
!> - Damped or otherwise non-Hamiltonian (C ≠ 0, ε > 0, K unsymmetric): asymptotically
!>   stable when the largest |λ| + δ < 1 (`kind_damped`), unstable when the largest |λ| − δ
!>   > 1, else marginal.
!>
!> The kind of an instability is where its largest multiplier leaves the circle: at +1
!> (`kind_plus_one`, real λ > 0), at −1 (`kind_minus_one`), or off the real axis
!> (`kind_combination`, a Krein collision: a combination resonance ω_i + ω_j ≈ kΩ).
!>
!> - One degree of freedom taken by a scalar method: the result of the trace S of
!>   χ = e^{ετ/2} x (`floquet_from_trace`, hillstab_hill_floquet), whose monodromy has
!>   determinant 1, its verdict that of the trace within its error bound, completed here
!>   (`complete_from_trace`): x's Φ has tr Φ = e^{−εP/2} S and det Φ = a₂ = e^{−εP} exactly,
!>   the multipliers e^{−εP/2}(S/2 ± √(S²/4 − 1)), and no structural defect (the structure
!>   holds by construction).
!>
!> Both fill the one result `floquet_t` of hillstab_hill_floquet, which this module also
!> exports with the verdict_* and kind_* codes.
!>
!> Φ may be given scaled, Φ = e^s Φ̃ (`log_scale` s), so that strongly unstable points do
!> not overflow: the multipliers' moduli and exponents come from Φ̃ and s (entries of Φ̃ beyond
!> 1e100 are scaled once more here, `floquet_t%log_scale` the total).
!>
!>```fortran
!> type(floquet_t) :: f
!> call system_floquet(phi, form, phi_error, f)
!> if (f%verdict == verdict_unstable .and. f%kind == kind_combination) print *, "combination resonance"
!>```
module hillstab_hill_system_floquet
   use hillstab_core_kinds, only: wp, pi
   use hillstab_ffi_lapack, only: dgeev
   use hillstab_hill_system, only: system_form_t
   use hillstab_hill_floquet, only: floquet_t, period_damping, verdict_stable, verdict_unstable, verdict_marginal, &
      kind_stable, kind_plus_one, kind_minus_one, kind_combination, kind_damped, kind_undecided, kind_name
   implicit none
   private
   public :: floquet_t, system_floquet, verdict_stable, verdict_unstable, verdict_marginal
   public :: kind_stable, kind_plus_one, kind_minus_one, kind_combination, kind_damped, kind_undecided, kind_name
   public :: symplectic_form, matrix_determinant, broucke_multipliers, complete_from_trace

contains

   !> Ω = [[G, M], [−M, 0]], the form a Hamiltonian system's Φ keeps: ΦᵀΩΦ = Ω.
   pure function symplectic_form(form) result(omega)
      type(system_form_t), intent(in) :: form  !! the prepared system
      real(wp) :: omega(2*form%n, 2*form%n)
      integer :: n
      n = form%n
      omega = 0.0_wp
      omega(1:n, 1:n) = form%g
      omega(1:n, n + 1:2*n) = form%m
      omega(n + 1:2*n, 1:n) = -form%m
   end function symplectic_form

   !> det a by Gaussian elimination with partial pivoting (a small matrix).
   pure real(wp) function matrix_determinant(a) result(det)
      real(wp), intent(in) :: a(:, :)  !! a square matrix
      real(wp) :: lu(size(a, 1), size(a, 1)), row(size(a, 1))
      integer :: n, i, k, p
      n = size(a, 1)
      lu = a
      det = 1.0_wp
      do k = 1, n
         p = k - 1 + maxloc(abs(lu(k:n, k)), 1)
         if (lu(p, k) == 0.0_wp) then
            det = 0.0_wp
            return
         end if
         if (p /= k) then
            row = lu(k, :)
            lu(k, :) = lu(p, :)
            lu(p, :) = row
            det = -det
         end if
         det = det*lu(k, k)
         do i = k + 1, n
            lu(i, k + 1:n) = lu(i, k + 1:n) - (lu(i, k)/lu(k, k))*lu(k, k + 1:n)
         end do
      end do
   end function matrix_determinant

   !> The four multipliers of a 4 × 4 symplectic Φ from Broucke's z₁, z₂ (roots of
   !> z² − a₁ z + a₂ − 2): λ = (z ± √(z² − 4))/2 for each.
   pure subroutine broucke_multipliers(a1, a2, z, lambda)
      real(wp), intent(in) :: a1, a2           !! the invariants of Φ
      complex(wp), intent(out) :: z(2)         !! the two z, the larger modulus first
      complex(wp), intent(out) :: lambda(4)    !! the multipliers
      complex(wp) :: root, w
      integer :: k
      root = sqrt(cmplx(a1*a1 - 4.0_wp*a2 + 8.0_wp, 0.0_wp, wp))
      ! the root that does not cancel, then the other from the product z₁ z₂ = a₂ − 2
      if (a1 >= 0.0_wp) then
         z(1) = 0.5_wp*(a1 + root)
      else
         z(1) = 0.5_wp*(a1 - root)
      end if
      if (z(1) /= (0.0_wp, 0.0_wp)) then
         z(2) = (a2 - 2.0_wp)/z(1)
      else
         z(2) = a1 - z(1)
      end if
      do k = 1, 2
         w = sqrt(z(k)*z(k) - 4.0_wp)
         if (real(conjg(z(k))*w) < 0.0_wp) w = -w
         lambda(2*k - 1) = 0.5_wp*(z(k) + w)
         ! the reciprocal without cancellation
         lambda(2*k) = 1.0_wp/lambda(2*k - 1)
      end do
   end subroutine broucke_multipliers

   !> Analyse Φ = e^s Φ̃ with entries known to `phi_error` (absolute, of Φ̃'s entries).
   subroutine system_floquet(phi, form, phi_error, result, log_scale, beta)
      real(wp), intent(in) :: phi(:, :)             !! Φ̃ (2n × 2n)
      type(system_form_t), intent(in) :: form       !! the prepared system
      real(wp), intent(in) :: phi_error             !! bound of the error of Φ̃'s entries
      type(floquet_t), intent(out) :: result !! the analysis
      real(wp), intent(in), optional :: log_scale   !! s (0 when absent)
      !> β of the point, for Liouville's check of a first-order system (whose mean tr A is
      !> `trace_d` + β `trace_b`); 0 when absent
      real(wp), intent(in), optional :: beta
      integer :: n, m, i, k
      real(wp) :: work(size(phi, 1), size(phi, 2)), big
      real(wp) :: s, scale, tr, tr2, e, mean_trace
      n = form%n
      m = form%states
      result%n = n
      result%period = form%period
      s = 0.0_wp
      if (present(log_scale)) s = log_scale
      result%log_scale = s
      e = max(phi_error, 0.0_wp)
      ! entries beyond 1e100 (a growth the method kept unscaled) are scaled here, so that the
      ! invariants and the eigenvalues stay finite: Φ̃ / 2^k, s + k ln 2
      work = phi
      big = maxval(abs(work))
      if (big > 1.0e100_wp) then
         k = exponent(big)
         work = work*2.0_wp**(-k)
         e = e*2.0_wp**(-k)
         s = s + k*log(2.0_wp)
         result%log_scale = s
      end if
      tr = sum([(work(i, i), i=1, m)])
      tr2 = sum(work*transpose(work))
      ! the invariants of Φ itself: a₁ scales with e^s, a₂ with e^{2s}
      call scaled_value(tr, s, result%a1, result%overflow)
      call scaled_value(0.5_wp*(tr*tr - tr2), 2.0_wp*s, result%a2, result%overflow)
      allocate (result%multipliers(m), result%exponents(n))
      scale = max(1.0_wp, maxval(abs(work)))
      ! the defect of the structure Φ keeps, relative to the size its terms have
      mean_trace = form%trace_d
      if (present(beta)) mean_trace = mean_trace + beta*form%trace_b
      result%defect = structure_defect(work, s, form, mean_trace)
      ! a scaled Φ̃ is not symplectic (its pairs multiply to e^{−2s}): the eigenvalues then
      if (form%hamiltonian .and. n == 1 .and. s == 0.0_wp) then
         call scalar_verdict(tr, e, form%period, result)
      else if (form%hamiltonian .and. n == 2 .and. s == 0.0_wp) then
         call broucke_verdict(tr, 0.5_wp*(tr*tr - tr2), e, scale, form%period, result)
      else
         call eigen_verdict(work, e, s, form, result)
      end if
      result%stable = result%verdict == verdict_stable
      result%marginal = result%verdict == verdict_marginal
   end subroutine system_floquet

   !> The rest of a system's analysis for one degree of freedom whose result `f` came from its
   !> trace (`floquet_from_trace` at the point's ε; see the module's text): the multipliers and
   !> exponent as arrays, the invariants a₁ = e^{−εP/2} S and a₂ = e^{−εP}, no defect. The
   !> verdict, kind and largest multiplier are the trace's, kept.
   pure subroutine complete_from_trace(f, form)
      type(floquet_t), intent(inout) :: f      !! from `floquet_from_trace`; completed
      type(system_form_t), intent(in) :: form  !! the prepared system (n = 1, second-order form)
      real(wp), parameter :: clamp = 1.0e300_wp
      real(wp) :: decay, s
      integer :: i
      f%n = 1
      f%period = form%period
      decay = period_damping(f%epsilon, form%period)
      ! the multipliers e^{s} (|λ_i| e^{−s}) e^{i θ_i}, scaled when the larger would overflow
      s = 0.0_wp
      if (f%log_modulus(1) > 600.0_wp) s = f%log_modulus(1)
      f%log_scale = s
      if (allocated(f%multipliers)) deallocate (f%multipliers)
      if (allocated(f%exponents)) deallocate (f%exponents)
      allocate (f%multipliers(2), f%exponents(1))
      do i = 1, 2
         f%multipliers(i) = exp(max(f%log_modulus(i) - s, -745.0_wp))*cmplx(cos(f%argument(i)), sin(f%argument(i)), wp)
      end do
      f%exponents(1) = f%exponent
      ! tr Φ = e^{−εP/2} S, clamped as `scaled_value` clamps
      f%overflow = .false.
      if (f%trace%overflow) then
         if (f%trace%log_abs - decay > log(clamp)) then
            f%a1 = sign(clamp, f%trace%value)
            f%overflow = .true.
         else
            f%a1 = sign(exp(f%trace%log_abs - decay), f%trace%value)
         end if
      else
         call scaled_value(f%trace%value, -decay, f%a1, f%overflow)
      end if
      f%a2 = exp(max(-2.0_wp*decay, -745.0_wp))
      f%defect = 0.0_wp
   end subroutine complete_from_trace

   !> The defect of the structure Φ = e^s Φ̃ keeps, relative to the size of its terms, so that
   !> it measures rounding and not growth: Hamiltonian, ‖ΦᵀΩΦ − Ω‖/(‖Ω‖ max(1, ‖Φ‖)²)
   !> (max norms); else Liouville's |det Φ − e^{P mean tr A}| over Hadamard's bound ∏‖Φ's columns‖₂
   !> of |det Φ|, both computed on Φ̃ so that nothing overflows.
   function structure_defect(phi, s, form, mean_trace) result(defect)
      real(wp), intent(in) :: phi(:, :)     !! Φ̃
      real(wp), intent(in) :: s             !! its scale
      type(system_form_t), intent(in) :: form
      real(wp), intent(in) :: mean_trace    !! the mean of tr A over the period
      real(wp) :: defect
      ! explicit shapes: no reallocation on assignment (gfortran's size arithmetic for an
      ! unallocated left side overflows under UBSan)
      real(wp) :: omega(size(phi, 1), size(phi, 1)), unit_columns(size(phi, 1), size(phi, 1))
      real(wp) :: shrink, size_phi, log_hadamard, norms(size(phi, 2)), target
      integer :: i, m
      m = size(phi, 1)
      if (form%hamiltonian) then
         omega = symplectic_form(form)
         ! e^{−s}: Φ̃ᵀΩΦ̃ − e^{−2s}Ω is ΦᵀΩΦ − Ω over e^{2s}
         shrink = exp(-min(max(s, 0.0_wp), 300.0_wp))
         if (s < 0.0_wp) shrink = exp(min(-s, 300.0_wp))
         size_phi = max(shrink, maxval(abs(phi)))
         defect = maxval(abs(matmul(transpose(phi), matmul(omega, phi)) - (shrink*shrink)*omega))/ &
                  (maxval(abs(omega))*size_phi*size_phi)
      else
         do i = 1, m
            norms(i) = norm2(phi(:, i))
         end do
         if (any(norms == 0.0_wp)) then
            defect = 1.0_wp
            return
         end if
         log_hadamard = sum(log(norms))
         do i = 1, m
            unit_columns(:, i) = phi(:, i)/norms(i)
         end do
         ! det Φ / ∏‖col‖ = det Φ̃ / ∏‖col of Φ̃‖; Liouville's value over the same bound
         target = exp(max(-700.0_wp, min(700.0_wp, form%period*mean_trace - m*s - log_hadamard)))
         defect = abs(matrix_determinant(unit_columns) - target)
      end if
   end function structure_defect

   !> e^s x, clamped to ±1e300 with the overflow flag.
   pure subroutine scaled_value(x, s, value, overflow)
      real(wp), intent(in) :: x, s
      real(wp), intent(out) :: value
      logical, intent(inout) :: overflow
      real(wp), parameter :: clamp = 1.0e300_wp
      if (x == 0.0_wp) then
         value = 0.0_wp
      else if (log(abs(x)) + s > log(clamp)) then
         value = sign(clamp, x)
         overflow = .true.
      else
         value = x*exp(s)
      end if
   end subroutine scaled_value

   !> n = 1: the trace criterion.
   pure subroutine scalar_verdict(tr, e, period, r)
      real(wp), intent(in) :: tr, e, period
      type(floquet_t), intent(inout) :: r
      real(wp) :: delta
      complex(wp) :: lambda(2), z
      delta = 2.0_wp*e + 4.0_wp*epsilon(1.0_wp)*max(1.0_wp, abs(tr))
      ! multipliers of λ² − S λ + 1 (det Φ = 1): λ = (S ± √(S² − 4))/2, the larger first
      z = tr
      lambda(1) = 0.5_wp*(z + sign(1.0_wp, tr)*sqrt(z*z - 4.0_wp))
      lambda(2) = 1.0_wp/lambda(1)
      r%multipliers = lambda
      call finish_from_multipliers(r, 0.0_wp, period)
      if (abs(tr) < 2.0_wp - delta) then
         r%verdict = verdict_stable
         r%kind = kind_stable
      else if (abs(tr) > 2.0_wp + delta) then
         r%verdict = verdict_unstable
         r%kind = merge(kind_plus_one, kind_minus_one, tr > 0.0_wp)
      else
         r%verdict = verdict_marginal
         r%kind = kind_undecided
      end if
   end subroutine scalar_verdict

   !> n = 2 Hamiltonian: Broucke's z₁, z₂ with error bounds from those of a₁ and a₂.
   pure subroutine broucke_verdict(a1, a2, e, scale, period, r)
      real(wp), intent(in) :: a1, a2, e, scale, period
      type(floquet_t), intent(inout) :: r
      real(wp) :: d, d1, d2, dd, dz, round
      complex(wp) :: z(2), lambda(4)
      round = 32.0_wp*epsilon(1.0_wp)
      ! |Δa₁| ≤ 4 e; a₂ is the sum of the six principal 2 × 2 minors: |Δa₂| ≤ 24 ‖Φ‖ e
      d1 = 4.0_wp*e + round*scale
      d2 = 24.0_wp*scale*e + round*scale*scale
      d = a1*a1 - 4.0_wp*a2 + 8.0_wp
      dd = 2.0_wp*abs(a1)*d1 + 4.0_wp*d2 + round*(a1*a1 + 4.0_wp*abs(a2) + 8.0_wp)
      r%discriminant = d
      call broucke_multipliers(a1, a2, z, lambda)
      r%multipliers = lambda
      call finish_from_multipliers(r, 0.0_wp, period)
      if (d < -dd) then
         r%verdict = verdict_unstable
         r%kind = kind_combination
         return
      end if
      if (d <= dd) then
         r%verdict = verdict_marginal
         r%kind = kind_undecided
         return
      end if
      ! two real z: |Δz| ≤ (|Δa₁| + |ΔD|/(2√D))/2 with the factor 2 of the root's sign
      dz = 0.5_wp*(d1 + dd/sqrt(d)) + round*max(1.0_wp, abs(a1))
      if (abs(real(z(1))) > 2.0_wp + dz) then
         r%verdict = verdict_unstable
         r%kind = merge(kind_plus_one, kind_minus_one, real(z(1)) > 0.0_wp)
      else if (abs(real(z(2))) > 2.0_wp + dz) then
         r%verdict = verdict_unstable
         r%kind = merge(kind_plus_one, kind_minus_one, real(z(2)) > 0.0_wp)
      else if (abs(real(z(1))) < 2.0_wp - dz .and. abs(real(z(2))) < 2.0_wp - dz) then
         r%verdict = verdict_stable
         r%kind = kind_stable
      else
         r%verdict = verdict_marginal
         r%kind = kind_undecided
      end if
   end subroutine broucke_verdict

   !> Any n: eigenvalues and their condition numbers.
   subroutine eigen_verdict(phi, e, s, form, r)
      real(wp), intent(in) :: phi(:, :), e, s
      type(system_form_t), intent(in) :: form
      type(floquet_t), intent(inout) :: r
      integer :: m, info, i, j, lwork
      real(wp) :: a(size(phi, 1), size(phi, 1)), vl(size(phi, 1), size(phi, 1)), vr(size(phi, 1), size(phi, 1))
      real(wp) :: wr(size(phi, 1)), wi(size(phi, 1)), radius(size(phi, 1)), cond(size(phi, 1))
      real(wp), allocatable :: work(:)
      complex(wp) :: x(size(phi, 1)), y(size(phi, 1)), lambda(size(phi, 1))
      integer :: order(size(phi, 1))
      real(wp) :: norm_error, top, rho, round
      logical :: on_circle, apart, unstable
      m = size(phi, 1)
      a = phi
      lwork = 8*m
      allocate (work(lwork))
      call dgeev("V", "V", m, a, m, wr, wi, vl, m, vr, m, work, lwork, info)
      if (info /= 0) then
         r%multipliers = cmplx(0.0_wp, 0.0_wp, wp)
         r%verdict = verdict_marginal
         r%kind = kind_undecided
         call finish_from_multipliers(r, s, form%period)
         return
      end if
      ! reciprocal condition numbers |yᴴx| of the unit left and right eigenvectors
      i = 1
      do while (i <= m)
         if (wi(i) == 0.0_wp) then
            x = vr(:, i)
            y = vl(:, i)
            lambda(i) = cmplx(wr(i), 0.0_wp, wp)
            cond(i) = abs(dot_product(y, x))/max(tiny(1.0_wp), norm2(abs(x))*norm2(abs(y)))
            i = i + 1
         else
            x = cmplx(vr(:, i), vr(:, i + 1), wp)
            y = cmplx(vl(:, i), vl(:, i + 1), wp)
            cond(i) = abs(dot_product(y, x))/max(tiny(1.0_wp), norm2(abs(x))*norm2(abs(y)))
            cond(i + 1) = cond(i)
            lambda(i) = cmplx(wr(i), wi(i), wp)
            lambda(i + 1) = cmplx(wr(i + 1), wi(i + 1), wp)
            i = i + 2
         end if
      end do
      round = 64.0_wp*m*epsilon(1.0_wp)*max(1.0_wp, maxval(abs(phi)))
      norm_error = m*e + round
      do i = 1, m
         radius(i) = norm_error/max(cond(i), 1.0e-300_wp)
      end do
      ! by decreasing modulus
      order = sort_by_modulus(lambda)
      r%multipliers = lambda(order)
      radius = radius(order)
      call finish_from_multipliers(r, s, form%period)
      top = abs(r%multipliers(1))
      unstable = s > 0.0_wp .or. top - radius(1) > 1.0_wp
      if (unstable) then
         r%verdict = verdict_unstable
         r%kind = kind_of(r%multipliers(1), radius(1))
         return
      end if
      if (.not. form%hamiltonian) then
         rho = top + radius(1)
         do i = 2, m
            rho = max(rho, abs(r%multipliers(i)) + radius(i))
         end do
         if (rho < 1.0_wp) then
            r%verdict = verdict_stable
            r%kind = kind_damped
         else
            r%verdict = verdict_marginal
            r%kind = kind_undecided
         end if
         return
      end if
      on_circle = .true.
      apart = .true.
      do i = 1, m
         if (abs(abs(r%multipliers(i)) - 1.0_wp) > radius(i)) on_circle = .false.
         if (abs(aimag(r%multipliers(i))) <= radius(i)) apart = .false.
         do j = i + 1, m
            if (abs(r%multipliers(i) - r%multipliers(j)) <= radius(i) + radius(j)) apart = .false.
         end do
      end do
      if (on_circle .and. apart) then
         r%verdict = verdict_stable
         r%kind = kind_stable
      else
         ! a disc off the circle but not decided outside, or two discs that meet
         r%verdict = verdict_marginal
         r%kind = kind_undecided
      end if
   end subroutine eigen_verdict

   !> The kind of an unstable multiplier: real (within its disc) positive or negative, or complex.
   pure integer function kind_of(lambda, radius) result(kind)
      complex(wp), intent(in) :: lambda
      real(wp), intent(in) :: radius
      if (abs(aimag(lambda)) <= radius) then
         kind = merge(kind_plus_one, kind_minus_one, real(lambda) > 0.0_wp)
      else
         kind = kind_combination
      end if
   end function kind_of

   !> The indices of λ by decreasing modulus (insertion sort: 2n ≤ 40).
   pure function sort_by_modulus(lambda) result(order)
      complex(wp), intent(in) :: lambda(:)
      integer :: order(size(lambda))
      integer :: i, j, k
      order = [(i, i=1, size(lambda))]
      do i = 2, size(lambda)
         k = order(i)
         j = i - 1
         do while (j >= 1)
            if (abs(lambda(order(j))) >= abs(lambda(k))) exit
            order(j + 1) = order(j)
            j = j - 1
         end do
         order(j + 1) = k
      end do
   end function sort_by_modulus

   !> Exponents, the largest modulus and its argument from the sorted multipliers.
   pure subroutine finish_from_multipliers(r, s, period)
      type(floquet_t), intent(inout) :: r
      real(wp), intent(in) :: s, period
      integer :: i, k
      complex(wp) :: t
      real(wp) :: modulus
      ! by decreasing modulus (Broucke's and the scalar's come unsorted)
      do i = 2, size(r%multipliers)
         t = r%multipliers(i)
         k = i - 1
         do while (k >= 1)
            if (abs(r%multipliers(k)) >= abs(t)) exit
            r%multipliers(k + 1) = r%multipliers(k)
            k = k - 1
         end do
         r%multipliers(k + 1) = t
      end do
      do i = 1, r%n
         modulus = abs(r%multipliers(i))
         if (modulus > 0.0_wp) then
            r%exponents(i) = (log(modulus) + s)/period
         else
            r%exponents(i) = -huge(1.0_wp)
         end if
      end do
      r%exponent = r%exponents(1)
      ! a zero multiplier (an eigenvalue solver that failed) has the exponent -huge, whose
      ! product with the period would overflow
      r%log_modulus(1) = -huge(1.0_wp)
      if (r%exponent > -huge(1.0_wp)/max(period, 1.0_wp)) r%log_modulus(1) = r%exponent*period
      r%argument(1) = atan2(aimag(r%multipliers(1)), real(r%multipliers(1)))
      ! the smallest multiplier (the largest's partner for one degree of freedom)
      t = r%multipliers(size(r%multipliers))
      modulus = abs(t)
      r%log_modulus(2) = -huge(1.0_wp)
      if (modulus > 0.0_wp) r%log_modulus(2) = log(modulus) + s
      r%argument(2) = atan2(aimag(t), real(t))
   end subroutine finish_from_multipliers
end module hillstab_hill_system_floquet

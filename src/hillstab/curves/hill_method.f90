!> Transition curves by Hill's method: for fixed α, β is a boundary of the stability
!> chart (S = +2 or S = −2) exactly when it is an eigenvalue of the periodic
!> (Fourier modes e^{inπτ}, S = +2) or antiperiodic (e^{i(n+½)πτ}, S = −2) problem
!>
!>     L x = −(1 − k cos πτ) x'' + α cos πτ x = β x,   k = α/π²   (elastic, eq. (25))
!>     L x = −x'' + ν cos πτ x = β x                              (Mathieu, eq. (A1); k = 0, α ↔ ν)
!>
!> The model's terms (k, the weight of cos πτ on each mode, the decay of the Fourier
!> coefficients, the α domain) come from hillstab_hill_models.
!>
!> Q is even, so each problem splits into cosine-type (even) and sine-type (odd)
!> solutions: four independent blocks. Their eigenvalues in each block, in
!> ascending order, are the curves a₀, a₂, a₄, … (periodic even), b₂, b₄, …
!> (periodic odd), a₁, a₃, … (antiperiodic even), b₁, b₃, … (antiperiodic odd) in
!> the Mathieu naming; the instability tongue of order n ≥ 1 lies between a_n and
!> b_n, and has zero width (coexistence of two periodic solutions) when they agree.
!>
!> ## Formulation (chosen by measurement, see the guide page *Transition curves*)
!> In the Fourier basis L is tridiagonal but not symmetric. Writing x = p z with
!> p = 1 − k cos πτ > 0 turns L x = β x into the symmetric-definite pencil
!>
!>     A z = β P z,   A = P D P + α C P (pentadiagonal),   P = I − k C (tridiagonal, positive definite),
!>
!> D = diag(κ²) the matrix of −d², C that of cos πτ: A is symmetric because
!> ⟨φ, −p(pz)''⟩ = ⟨(pφ)', (pz)'⟩. Truncation is then a Rayleigh–Ritz method,
!> so the computed eigenvalues are upper bounds that decrease monotonically as
!> modes are added. LAPACK's `dsbgv` (banded symmetric-definite) solves it in
!> O(n²) operations and O(n) memory. The error bound of the direct pencil grows
!> like ‖A‖‖P⁻¹‖ ~ n²π²/(1 − k), so the code solves the inverted pencil
!>
!>     P z = μ (A − σP) z,   β = σ + 1/μ,   σ = −|α| − 1 < every eigenvalue,
!>
!> in which A − σP is positive definite and the wanted small β are the largest μ
!> (in practice the two pencils come out within a factor 2 of each other). Measured (`make bench`, guide page *Transition curves*): on the antiperiodic curves
!> 10 < β < 40 against bisection on S by method auto at tolerance 1e-13, the largest
!> error is 1.5e-12 / 2.3e-12 / 1.6e-10 at α = 9.5 / 9.8 / 9.86 for the inverted
!> pencil, 1.2e-12 / 5.6e-12 / 2.7e-10 for the direct pencil and 6.9e-11 / 3.3e-10 /
!> 1.1e-8 for the nonsymmetric tridiagonal through `dgeev` (QR on a strongly
!> non-normal matrix), which also costs O(n³): 77 ms against 1.8 ms at 262 modes,
!> 1.04 s against 11 ms at 667. (The nonsymmetric form keeps β = 0 and β = π² exact,
!> since there the matrix decouples; the pencils reach them to 1e-14 and 2e-12 at
!> α = 9.8.) Both alternatives are kept (`formulation_*`) for that measurement and
!> for the tests.
!>
!> ## Truncation
!> Eigenfunctions are analytic in the strip |Im πτ| < arccosh(1/k), so their
!> Fourier coefficients decay like r^n, r = k/(1 + √(1 − k²)), and the Ritz values
!> like r^{2n}: slowly as α → π² (r → 1). The number of modes starts from that
!> estimate and grows by half until every eigenvalue below the top of the β window
!> changes by less than the tolerance between two truncations.
!>
!>```fortran
!> type(hill_boundary_t), allocatable :: curves(:)
!> type(error_t), allocatable :: error
!> call hill_boundaries(elastic_model_t(), 5.0_wp, -2.0_wp, 40.0_wp, 1.0e-11_wp, curves, error)
!> print *, curves%beta
!>```
module hillstab_curves_hill_method
   use hillstab_core_kinds, only: wp, pi, pi2
   use hillstab_core_error, only: error_t, set_error, err_invalid_parameter, err_singular, err_accuracy
   use hillstab_hill_model, only: hill_model_t, check_alpha, hill_form_pencil
   use hillstab_ffi_lapack, only: dsbgv, dgeev
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   implicit none
   private
   public :: hill_boundary_t, hill_boundaries, hill_block_eigenvalues, hill_block_name
   public :: hill_block_values_t, hill_block_values, hill_curves
   public :: block_periodic_even, block_periodic_odd, block_antiperiodic_even, block_antiperiodic_odd
   public :: formulation_inverted_pencil, formulation_pencil, formulation_nonsymmetric
   public :: hill_initial_modes, hill_max_modes, block_order, coexistence_threshold, structural_coexistence
   public :: route_pencil, route_fourier, route_roots, route_closed_form, route_name
   public :: block_periodic, block_antiperiodic

   !> Periodic, cosine-type: curves a₀, a₂, a₄, … (S = +2).
   integer, parameter :: block_periodic_even = 1
   !> Periodic, sine-type: curves b₂, b₄, … (S = +2).
   integer, parameter :: block_periodic_odd = 2
   !> Antiperiodic, cosine-type: curves a₁, a₃, … (S = −2).
   integer, parameter :: block_antiperiodic_even = 3
   !> Antiperiodic, sine-type: curves b₁, b₃, … (S = −2).
   integer, parameter :: block_antiperiodic_odd = 4
   !> Periodic, both types coupled (Q without the even symmetry; Hill's method on the Fourier
   !> coefficients of Q − β, hillstab_curves_hill_fourier): every S = +2 curve, ascending.
   integer, parameter :: block_periodic = 5
   !> Antiperiodic, both types coupled: every S = −2 curve, ascending.
   integer, parameter :: block_antiperiodic = 6

   !> The curve comes from Hill's method on the pencil (`hill_form_pencil`: elastic, Mathieu).
   integer, parameter :: route_pencil = 1
   !> The curve comes from Hill's method on the Fourier coefficients of g = Q − β
   !> (hillstab_curves_hill_fourier: models of the form Q = β + g(τ)).
   integer, parameter :: route_fourier = 2
   !> The curve comes from root finding on S (Brent's method on S ∓ 2 by an exact method).
   integer, parameter :: route_roots = 3
   !> The curve comes from root finding on the model's closed-form trace (method formula,
   !> exact for a model whose two pieces are Q itself: `two_pieces_exact`, Meissner's).
   integer, parameter :: route_closed_form = 4

   !> P z = μ (A − σP) z by `dsbgv` (the default).
   integer, parameter :: formulation_inverted_pencil = 1
   !> A z = β P z by `dsbgv`.
   integer, parameter :: formulation_pencil = 2
   !> The nonsymmetric tridiagonal L by `dgeev`.
   integer, parameter :: formulation_nonsymmetric = 3

   !> Largest truncation (modes per block) tried before giving up.
   integer, parameter :: hill_max_modes = 40000
   !> Two curves of one order closer than this times tolerance·max(1, |β|) count as one
   !> (zero-width tongue, coexistence) for the approximate methods of the boundaries task,
   !> whose piecewise-constant Q has no structure to decide it by; the exact curves use
   !> `structural_coexistence`.
   real(wp), parameter :: coexistence_threshold = 100.0_wp

   !> The converged eigenvalues of one block up to the top of a β window: what
   !> `hill_boundaries` computes for each of the four blocks before it joins them. The blocks
   !> are independent: a caller may compute them apart (in parallel, or reporting progress
   !> per block: `hill_block_values`) and join them with `hill_curves`.
   type :: hill_block_values_t
      real(wp), allocatable :: values(:)   !! converged eigenvalues up to the top, ascending
      real(wp), allocatable :: changes(:)  !! their change between the last two truncations
      integer :: used = 0                  !! modes of the final truncation
   end type hill_block_values_t

   !> One point of a transition curve at the α of the call.
   type :: hill_boundary_t
      real(wp) :: beta = 0.0_wp        !! β on the curve
      integer :: trace_sign = 2        !! +2 (periodic) or −2 (antiperiodic): S on the curve
      integer :: order = 0             !! n of a_n / b_n
      integer :: parity = 1            !! +1 even (a_n, cosine-type), −1 odd (b_n, sine-type)
      integer :: modes = 0             !! modes of the block's truncation
      real(wp) :: change = 0.0_wp      !! change between the last two truncations
      !> bound of the error of beta: the truncation change or the rounding bound of the
      !> eigensolver (`rounding_bound`), whichever is larger
      real(wp) :: error_bound = 0.0_wp
      logical :: coexistent = .false.  !! the other curve of this order coincides (zero-width tongue)
      !> the block it is an eigenvalue of (block_*; 0 for a root of S)
      integer :: block = 0
      !> 1 lower, 2 upper edge of the tongue of its order where the parity is not known
      !> (parity 0: Q without the even symmetry, or a root of S); 0 otherwise and for order 0
      integer :: edge = 0
      !> how it was computed: route_pencil, route_fourier or route_roots
      integer :: route = route_pencil
      !> the drive g has infinitely many harmonics (a jump of Q), truncated: Hill's method
      !> converges slowly there and error_bound is only the change between truncations
      logical :: truncated_drive = .false.
   end type hill_boundary_t

contains

   !> Short name of a block.
   pure function hill_block_name(block) result(name)
      integer, intent(in) :: block  !! one of the blocks (block_*)
      character(len=:), allocatable :: name
      select case (block)
      case (block_periodic_even); name = "periodic even (a_2m)"
      case (block_periodic_odd); name = "periodic odd (b_2m)"
      case (block_antiperiodic_even); name = "antiperiodic even (a_2m+1)"
      case (block_antiperiodic_odd); name = "antiperiodic odd (b_2m+1)"
      case (block_periodic); name = "periodic"
      case (block_antiperiodic); name = "antiperiodic"
      case default; name = "unknown"
      end select
   end function hill_block_name

   !> The name of a route (`route_*`) for headers: "Hill's method (pencil)", …
   pure function route_name(route) result(name)
      integer, intent(in) :: route  !! route_pencil, route_fourier or route_roots
      character(len=:), allocatable :: name
      select case (route)
      case (route_pencil); name = "Hill's method on the pencil"
      case (route_fourier); name = "Hill's method on the Fourier coefficients of Q - beta"
      case (route_roots); name = "roots of S = +-2"
      case (route_closed_form); name = "roots of the closed-form S = +-2"
      case default; name = "unknown"
      end select
   end function route_name

   !> Whether the two curves of every order n ≥ 1 of this kind (S = +2 or −2) coincide: decided
   !> by the structure of the blocks, not by the distance of two computed eigenvalues (thin
   !> tongues — Mathieu q = 1 at order 9 has width 4e-13, below the error of its edges —
   !> cannot be told from closed ones by a threshold).
   !>
   !> On the Fourier modes the even (cosine) and odd (sine) blocks of one kind are the same
   !> matrix except where the lowest modes meet their mirror images: in the periodic
   !> blocks the cosine block has the extra mode 0, coupled to mode 1 by the weight
   !> c(1) of cos πτ there (`model_hill_coupling` at t = 1); in the antiperiodic blocks the
   !> first diagonal entries differ by ±c(1/4)/2. When that weight is 0 the cosine block is
   !> block-triangular over the sine block (periodic: its eigenvalues are a₀ and those of the
   !> sine block) or equal to it (antiperiodic), and every tongue of that kind has zero
   !> width. For the elastic model c(t) = α(1 − t): the periodic tongues (S = +2) are closed
   !> for every α — the two 2-periodic solutions coexist — and the antiperiodic ones only at
   !> α = 0 (their widths are measured nonzero, falling geometrically with the order). For
   !> the Mathieu model c = ν: no tongue is closed for ν ≠ 0 (Ince's theorem), all at ν = 0.
   elemental logical function structural_coexistence(model, alpha, trace_sign) result(closed)
      class(hill_model_t), intent(in) :: model        !! the model
      real(wp), intent(in) :: alpha      !! α (ν for the Mathieu model)
      integer, intent(in) :: trace_sign  !! +2 periodic, −2 antiperiodic
      closed = model%hill_coupling(alpha, merge(1.0_wp, 0.25_wp, trace_sign == 2)) == 0.0_wp
   end function structural_coexistence

   !> Rounding error bound of an eigenvalue β of the inverted pencil P z = μ (A − σP) z,
   !> β = σ + 1/μ (the default formulation): for a symmetric-definite pencil LAPACK's
   !> computed μ lies within p(n) ε ‖P‖ ‖(A − σP)⁻¹‖ of the exact one (the Users' Guide
   !> bound; its modest function of n taken as √n, n the modes), and ‖P‖ ≤ 1 + k, ‖(A − σP)⁻¹‖ ≤
   !> 1/((β₁ − σ)(1 − k)) since A − σP ≥ (β₁ − σ) P ≥ (β₁ − σ)(1 − k) I, β₁ the block's
   !> smallest eigenvalue; δβ = (β − σ)² δμ. So
   !>
   !>   δβ ≤ √n ε (1 + k)(β − σ)² / ((β₁ − σ)(1 − k)) + ε |β|.
   !>
   !> It grows like 1/(1 − k) as α → π²: at α = 9.8 the errors of the curves below β = 40 reach
   !> 6.9e-12 (against 50-digit references, `data/reference/curve_set.dat`) while the change
   !> between truncations is 1e-14. With the factor 1 in place of √n the errors exceeded it
   !> by up to 2.75× at α = 2 … 8 (a dozen ulps of β, 23–48 modes).
   pure real(wp) function rounding_bound(model, alpha, beta_lowest, beta, modes) result(bound)
      class(hill_model_t), intent(in) :: model  !! the model
      integer, intent(in) :: modes
      real(wp), intent(in) :: alpha, beta_lowest, beta
      real(wp) :: k, one_minus_k, sigma
      k = model%hill_k(alpha)
      one_minus_k = model%hill_one_minus_k(alpha)
      sigma = -abs(alpha) - 1.0_wp
      bound = sqrt(real(modes, wp))*epsilon(1.0_wp)*(1.0_wp + k)*(beta - sigma)**2 &
              /(max(beta_lowest - sigma, tiny(1.0_wp))*one_minus_k) + epsilon(1.0_wp)*abs(beta)
   end function rounding_bound

   !> Order n of the j-th eigenvalue (j = 1, 2, …) of a block.
   elemental integer function block_order(block, j)
      integer, intent(in) :: block, j  !! the block; index of the eigenvalue, ascending from 1
      select case (block)
      case (block_periodic_even); block_order = 2*(j - 1)
      case (block_periodic_odd); block_order = 2*j
      case default; block_order = 2*j - 1
      end select
   end function block_order

   !> Number of modes to start from: enough for the eigenfunctions up to β_top and
   !> for the geometric decay r^{2n} of the Ritz error to reach the tolerance.
   pure integer function hill_initial_modes(model, alpha, beta_top, tolerance) result(n)
      class(hill_model_t), intent(in) :: model  !! the model
      !> alpha; highest beta wanted; target error relative to max(1, |beta|)
      real(wp), intent(in) :: alpha, beta_top, tolerance
      real(wp) :: r, oscillation
      oscillation = sqrt(max(beta_top, 0.0_wp) + abs(alpha))/pi
      r = model%fourier_decay(alpha)
      if (r > 0.0_wp) then
         n = 8 + nint(oscillation) + ceiling(log(max(tolerance, 1.0e-16_wp))/(2.0_wp*log(r)))
      else
         n = 16 + 2*nint(oscillation)
      end if
      n = min(max(n, 12), hill_max_modes)
   end function hill_initial_modes

   !> (j + s)² for the Fourier index j of a block: κ_j = (j + s)π.
   pure real(wp) function mode_t(block, j)
      integer, intent(in) :: block, j
      if (block == block_periodic_even .or. block == block_periodic_odd) then
         mode_t = real(j, wp)**2
      else
         mode_t = (real(j, wp) + 0.5_wp)**2
      end if
   end function mode_t

   !> Entry (i, j) of A = P D P + α C P in the exponential basis e^{iκ_jτ}.
   pure real(wp) function a_entry(model, alpha, k, block, i, j) result(a)
      class(hill_model_t), intent(in) :: model  !! the model
      integer, intent(in) :: block, i, j
      real(wp), intent(in) :: alpha, k
      integer :: lo
      lo = min(i, j)
      select case (abs(i - j))
      case (0)
         a = pi2*mode_t(block, i) - 0.25_wp*k*(model%hill_coupling(alpha, mode_t(block, i - 1)) + &
                                               model%hill_coupling(alpha, mode_t(block, i + 1)))
      case (1)
         a = 0.5_wp*(model%hill_coupling(alpha, mode_t(block, lo)) &
                     + model%hill_coupling(alpha, mode_t(block, lo + 1)) - alpha)
      case (2)
         a = -0.25_wp*k*model%hill_coupling(alpha, mode_t(block, lo + 1))
      case default
         a = 0.0_wp
      end select
   end function a_entry

   !> Entry (i, j) of P = I − k C.
   pure real(wp) function p_entry(k, i, j) result(p)
      real(wp), intent(in) :: k
      integer, intent(in) :: i, j
      select case (abs(i - j))
      case (0); p = 1.0_wp
      case (1); p = -0.5_wp*k
      case default; p = 0.0_wp
      end select
   end function p_entry

   !> Entry (i, j) of the nonsymmetric L = D + C·diag(coupling)/… : L_ij = κ_i² δ_ij + ½(α − kκ_j²) for |i − j| = 1.
   pure real(wp) function l_entry(model, alpha, block, i, j) result(l)
      class(hill_model_t), intent(in) :: model  !! the model
      integer, intent(in) :: block, i, j
      real(wp), intent(in) :: alpha
      select case (abs(i - j))
      case (0); l = pi2*mode_t(block, i)
      case (1); l = 0.5_wp*model%hill_coupling(alpha, mode_t(block, j))
      case default; l = 0.0_wp
      end select
   end function l_entry

   !> Fourier index of basis function r (1-based) of a block and of its mirror, and the sign.
   pure subroutine basis_index(block, r, i, mirror, sign)
      integer, intent(in) :: block, r
      integer, intent(out) :: i, mirror
      real(wp), intent(out) :: sign
      select case (block)
      case (block_periodic_even)
         i = r - 1; mirror = -i; sign = 1.0_wp
      case (block_periodic_odd)
         i = r; mirror = -i; sign = -1.0_wp
      case (block_antiperiodic_even)
         i = r - 1; mirror = -1 - i; sign = 1.0_wp
      case default
         i = r - 1; mirror = -1 - i; sign = -1.0_wp
      end select
   end subroutine basis_index

   !> ⟨φ_r, M φ_s⟩ for the orthonormal symmetric basis φ_r = (e_i + sign e_mirror)/√2
   !> (φ = e_0 for the periodic even constant), M given by `which`.
   pure real(wp) function folded(which, model, alpha, k, block, r, s) result(value)
      class(hill_model_t), intent(in) :: model  !! the model
      integer, intent(in) :: which, block, r, s
      real(wp), intent(in) :: alpha, k
      integer :: i, ip, j, jp
      real(wp) :: si, sj, wi, wj
      call basis_index(block, r, i, ip, si)
      call basis_index(block, s, j, jp, sj)
      if (i == ip) then
         wi = 1.0_wp
      else
         wi = sqrt(0.5_wp)
      end if
      if (j == jp) then
         wj = 1.0_wp
      else
         wj = sqrt(0.5_wp)
      end if
      value = element(i, j)
      if (jp /= j) value = value + sj*element(i, jp)
      if (ip /= i) then
         value = value + si*element(ip, j)
         if (jp /= j) value = value + si*sj*element(ip, jp)
      end if
      value = value*wi*wj
   contains
      pure real(wp) function element(a, b)
         integer, intent(in) :: a, b
         select case (which)
         case (1); element = a_entry(model, alpha, k, block, a, b)
         case (2); element = p_entry(k, a, b)
         case default; element = l_entry(model, alpha, block, a, b)
         end select
      end function element
   end function folded

   !> All n eigenvalues, ascending, of the n-mode truncation of one block.
   subroutine hill_block_eigenvalues(model, alpha, block, n, values, error, formulation)
      class(hill_model_t), intent(in) :: model          !! the model
      real(wp), intent(in) :: alpha        !! α (elastic, 0 ≤ α < π²) or ν (Mathieu)
      integer, intent(in) :: block         !! block_* constant
      integer, intent(in) :: n             !! number of modes
      real(wp), allocatable, intent(out) :: values(:)  !! β, ascending
      type(error_t), allocatable, intent(out) :: error  !! LAPACK failure; unallocated on success
      integer, intent(in), optional :: formulation  !! formulation_* (default inverted pencil)
      real(wp), allocatable :: ab(:, :), bb(:, :), w(:), work(:), h(:, :), wr(:), wi(:)
      real(wp) :: k, sigma, z(1, 1)
      integer :: form, r, d, info, lwork
      character(len=160) :: buf
      form = formulation_inverted_pencil
      if (present(formulation)) form = formulation
      allocate (values(0))
      call check_parameters(model, alpha, error)
      if (allocated(error)) return
      if (block < block_periodic_even .or. block > block_antiperiodic_odd .or. n < 1) then
         call set_error(error, err_invalid_parameter, "Hill's method: unknown block or no modes")
         return
      end if
      k = model%hill_k(alpha)
      sigma = -abs(alpha) - 1.0_wp
      select case (form)
      case (formulation_inverted_pencil, formulation_pencil)
         ! upper band storage: ab(3 + r - s, s) = M(r, s) for s - 2 <= r <= s
         allocate (ab(3, n), bb(3, n), w(n), work(3*n))
         ab = 0.0_wp; bb = 0.0_wp
         do r = 1, n
            do d = 0, min(2, r - 1)
               if (form == formulation_inverted_pencil) then
                  ab(3 - d, r) = folded(2, model, alpha, k, block, r - d, r)
                  bb(3 - d, r) = folded(1, model, alpha, k, block, r - d, r) - sigma*folded(2, model, alpha, k, block, r - d, r)
               else
                  ab(3 - d, r) = folded(1, model, alpha, k, block, r - d, r)
                  bb(3 - d, r) = folded(2, model, alpha, k, block, r - d, r)
               end if
            end do
         end do
         call dsbgv("N", "U", n, 2, 2, ab, 3, bb, 3, w, z, 1, work, info)
         if (info /= 0) then
            write (buf, '(a,i0,a,i0,a)') "Hill's method: LAPACK dsbgv failed (info = ", info, ", ", n, " modes)"
            call set_error(error, err_singular, trim(buf))
            return
         end if
         if (form == formulation_inverted_pencil) then
            if (any(.not. (w > 0.0_wp))) then
               call set_error(error, err_singular, "Hill's method: non-positive eigenvalue of the inverted pencil")
               return
            end if
            values = sigma + 1.0_wp/w(n:1:-1)
         else
            values = w
         end if
      case default
         allocate (h(n, n), wr(n), wi(n))
         h = 0.0_wp
         do r = 1, n
            do d = max(1, r - 1), min(n, r + 1)
               h(r, d) = folded(3, model, alpha, k, block, r, d)
            end do
         end do
         lwork = -1
         allocate (work(1))
         call dgeev("N", "N", n, h, n, wr, wi, z, 1, z, 1, work, lwork, info)
         lwork = max(4*n, int(work(1)))
         deallocate (work)
         allocate (work(lwork))
         call dgeev("N", "N", n, h, n, wr, wi, z, 1, z, 1, work, lwork, info)
         if (info /= 0) then
            write (buf, '(a,i0,a,i0,a)') "Hill's method: LAPACK dgeev failed (info = ", info, ", ", n, " modes)"
            call set_error(error, err_singular, trim(buf))
            return
         end if
         values = wr
         call sort_ascending(values)
      end select
      if (.not. all(ieee_is_finite(values))) then
         call set_error(error, err_singular, "Hill's method: non-finite eigenvalue")
      end if
   end subroutine hill_block_eigenvalues

   subroutine check_parameters(model, alpha, error)
      class(hill_model_t), intent(in) :: model  !! the model
      real(wp), intent(in) :: alpha
      type(error_t), allocatable, intent(out) :: error
      if (.not. ieee_is_finite(alpha)) then
         call set_error(error, err_invalid_parameter, "Hill's method: alpha must be finite")
         return
      end if
      if (model%hill_form() /= hill_form_pencil) then
         call set_error(error, err_invalid_parameter, "Hill's method does not apply to the "//model%name()//" model")
         return
      end if
      call check_alpha(model, alpha, error)
      if (allocated(error)) error%message = "Hill's method: "//error%message
   end subroutine check_parameters

   !> Insertion sort (the arrays are short and nearly sorted).
   pure subroutine sort_ascending(x)
      real(wp), intent(inout) :: x(:)
      integer :: i, j
      real(wp) :: t
      do i = 2, size(x)
         t = x(i)
         j = i - 1
         do while (j >= 1)
            if (x(j) <= t) exit
            x(j + 1) = x(j)
            j = j - 1
         end do
         x(j + 1) = t
      end do
   end subroutine sort_ascending

   !> Every transition curve crossing β_min ≤ β ≤ β_max at this α, converged in
   !> the truncation to `tolerance`·max(1, |β|), ordered by β; with the coexistence
   !> of the two curves of each order decided (even when the partner lies outside).
   !> (The four blocks by `hill_block_values`, joined by `hill_curves`.)
   subroutine hill_boundaries(model, alpha, beta_min, beta_max, tolerance, curves, error, modes, formulation)
      class(hill_model_t), intent(in) :: model          !! the model
      real(wp), intent(in) :: alpha        !! α (ν for the Mathieu model)
      real(wp), intent(in) :: beta_min, beta_max  !! the β window
      real(wp), intent(in) :: tolerance    !! convergence target on β, relative to max(1, |β|)
      !> the transition curves crossing [beta_min, beta_max], by beta
      type(hill_boundary_t), allocatable, intent(out) :: curves(:)
      type(error_t), allocatable, intent(out) :: error  !! failure to converge or LAPACK failure; unallocated on success
      integer, intent(out), optional :: modes(4)  !! final truncation of each block
      integer, intent(in), optional :: formulation  !! formulation_* (default inverted pencil)
      type(hill_block_values_t) :: blocks(4)
      integer :: block
      allocate (curves(0))
      do block = block_periodic_even, block_antiperiodic_odd
         call hill_block_values(model, alpha, block, beta_min, beta_max, tolerance, blocks(block), error, formulation)
         if (allocated(error)) return
      end do
      call hill_curves(model, alpha, beta_min, beta_max, blocks, curves)
      if (present(modes)) modes = blocks%used
   end subroutine hill_boundaries

   !> One block's eigenvalues for the window [beta_min, beta_max] of `hill_boundaries`
   !> (converged up to one order above it), with the same checks of the arguments.
   subroutine hill_block_values(model, alpha, block, beta_min, beta_max, tolerance, block_values, error, formulation)
      class(hill_model_t), intent(in) :: model          !! the model
      real(wp), intent(in) :: alpha        !! α (ν for the Mathieu model)
      integer, intent(in) :: block         !! block_periodic_even … block_antiperiodic_odd
      real(wp), intent(in) :: beta_min, beta_max  !! the β window
      real(wp), intent(in) :: tolerance    !! convergence target on β, relative to max(1, |β|)
      type(hill_block_values_t), intent(out) :: block_values  !! the converged eigenvalues of the block
      type(error_t), allocatable, intent(out) :: error  !! failure to converge or LAPACK failure; unallocated on success
      integer, intent(in), optional :: formulation  !! formulation_* (default inverted pencil)
      real(wp) :: top
      allocate (block_values%values(0), block_values%changes(0))
      if (.not. (ieee_is_finite(beta_min) .and. ieee_is_finite(beta_max) .and. ieee_is_finite(tolerance))) then
         call set_error(error, err_invalid_parameter, "Hill's method: beta window and tolerance must be finite")
         return
      end if
      if (beta_min > beta_max .or. .not. tolerance > 0.0_wp) then
         call set_error(error, err_invalid_parameter, "Hill's method: need beta_min <= beta_max and tolerance > 0")
         return
      end if
      if (block < block_periodic_even .or. block > block_antiperiodic_odd) then
         call set_error(error, err_invalid_parameter, "Hill's method: block must be 1 to 4")
         return
      end if
      call check_parameters(model, alpha, error)
      if (allocated(error)) return
      ! one order above the window too, so that every tongue reaching into it has both edges
      top = beta_max + 1.0_wp + 0.25_wp*abs(beta_max)
      call converged_block(model, alpha, block, top, tolerance, block_values%values, block_values%changes, &
                           block_values%used, error, formulation)
   end subroutine hill_block_values

   !> The transition curves crossing [beta_min, beta_max] from the four blocks'
   !> eigenvalues (`hill_block_values` with this window), ordered by β, with their error
   !> bounds and the coexistence of the two curves of each order.
   subroutine hill_curves(model, alpha, beta_min, beta_max, blocks, curves)
      class(hill_model_t), intent(in) :: model          !! the model
      real(wp), intent(in) :: alpha        !! α (ν for the Mathieu model)
      real(wp), intent(in) :: beta_min, beta_max  !! the β window
      type(hill_block_values_t), intent(in) :: blocks(4)  !! the four blocks, in block order
      type(hill_boundary_t), allocatable, intent(out) :: curves(:)  !! the curves, by beta
      integer :: counts(4), block, j, m, n_out, jp, other
      type(hill_boundary_t), allocatable :: all(:)
      logical :: found
      do block = block_periodic_even, block_antiperiodic_odd
         counts(block) = size(blocks(block)%values)
      end do
      allocate (all(sum(counts)))
      n_out = 0
      do block = block_periodic_even, block_antiperiodic_odd
         associate (values => blocks(block)%values, changes => blocks(block)%changes, used => blocks(block)%used)
            do j = 1, counts(block)
               if (values(j) < beta_min .or. values(j) > beta_max) cycle
               n_out = n_out + 1
               all(n_out)%beta = values(j)
               all(n_out)%trace_sign = merge(2, -2, block <= block_periodic_odd)
               all(n_out)%order = block_order(block, j)
               all(n_out)%parity = merge(1, -1, block == block_periodic_even .or. block == block_antiperiodic_even)
               all(n_out)%modes = used
               all(n_out)%block = block
               all(n_out)%change = changes(j)
               all(n_out)%error_bound = max(changes(j), rounding_bound(model, alpha, values(1), values(j), used))
               ! the partner of the same order in the other block of this kind
               all(n_out)%coexistent = .false.
               if (all(n_out)%order > 0) then
                  other = partner_block(block)
                  found = .false.
                  do jp = 1, counts(other)
                     if (block_order(other, jp) == all(n_out)%order) found = .true.
                  end do
                  if (found) all(n_out)%coexistent = structural_coexistence(model, alpha, all(n_out)%trace_sign)
               end if
            end do
         end associate
      end do
      ! ascending β
      curves = all(:n_out)
      do j = 2, n_out
         m = j
         do while (m > 1)
            if (curves(m - 1)%beta <= curves(m)%beta) exit
            call swap(curves(m - 1), curves(m))
            m = m - 1
         end do
      end do
   contains
      subroutine swap(a, b)
         type(hill_boundary_t), intent(inout) :: a, b
         type(hill_boundary_t) :: t
         t = a; a = b; b = t
      end subroutine swap
   end subroutine hill_curves

   pure integer function partner_block(block)
      integer, intent(in) :: block
      select case (block)
      case (block_periodic_even); partner_block = block_periodic_odd
      case (block_periodic_odd); partner_block = block_periodic_even
      case (block_antiperiodic_even); partner_block = block_antiperiodic_odd
      case default; partner_block = block_antiperiodic_even
      end select
   end function partner_block

   !> The eigenvalues ≤ top of one block, converged: the truncation grows by half
   !> until every one of them changes by at most tolerance·max(1, |β|) (Ritz values
   !> only decrease as modes are added, and the count below top only grows).
   subroutine converged_block(model, alpha, block, top, tolerance, values, changes, used, error, formulation)
      class(hill_model_t), intent(in) :: model  !! the model
      integer, intent(in) :: block
      real(wp), intent(in) :: alpha, top, tolerance
      real(wp), allocatable, intent(out) :: values(:), changes(:)
      integer, intent(out) :: used
      type(error_t), allocatable, intent(out) :: error
      integer, intent(in), optional :: formulation
      real(wp), allocatable :: coarse(:), fine(:)
      integer :: n, n_fine, m, j
      logical :: done
      character(len=200) :: buf
      allocate (values(0), changes(0))
      n = hill_initial_modes(model, alpha, top, tolerance)
      call hill_block_eigenvalues(model, alpha, block, n, coarse, error, formulation)
      if (allocated(error)) return
      do
         n_fine = min(n + max(8, n/2), hill_max_modes)
         call hill_block_eigenvalues(model, alpha, block, n_fine, fine, error, formulation)
         if (allocated(error)) return
         m = count(fine <= top)
         done = m < size(fine) .and. m < size(coarse)   ! a value above top exists in both
         if (done) then
            do j = 1, m
               if (abs(coarse(j) - fine(j)) > tolerance*max(1.0_wp, abs(fine(j)))) done = .false.
            end do
         end if
         if (done) exit
         if (n_fine >= hill_max_modes) then
            write (buf, '(a,i0,a,es10.3,a,a)') "Hill's method: not converged with ", n_fine, &
               " modes at alpha = ", alpha, " in block ", hill_block_name(block)
            call set_error(error, err_accuracy, trim(buf))
            return
         end if
         n = n_fine
         call move_alloc(fine, coarse)
      end do
      used = n_fine
      values = fine(:m)
      changes = abs(coarse(:m) - fine(:m))
   end subroutine converged_block
end module hillstab_curves_hill_method

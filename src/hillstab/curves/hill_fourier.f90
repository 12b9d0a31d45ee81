!> Transition curves by Hill's method for every model of the form Q(τ) = β + g(τ), g
!> independent of β (`drive_harmonic_count` > 0): g = ĝ₀ + Σₘ (cₘ cos mωτ + sₘ sin mωτ),
!> ω = 2π/P, P the model's period. The S = +2 (periodic over P) and S = −2 (antiperiodic)
!> solutions are Fourier series Σ c_k e^{iκ_kτ} with κ_k = kω and κ_k = (k + ½)ω;
!> substituting gives
!>
!>     β c_k = κ_k² c_k − Σₘ ĝₘ c_{k−m},   ĝ_{±m} = (cₘ ∓ i sₘ)/2,
!>
!> so the transition values of β at fixed α are the eigenvalues of the Hermitian band matrix
!> H = diag(κ_k²) − (ĝ_{k−j}) (bandwidth = number of harmonics M). Order n of a curve is that
!> of the wavenumber nπ/P its eigenfunction has at g = 0 (β = (nπ/P)²): even n periodic, odd n
!> antiperiodic; for P = 2 and g = −ν cos πτ they are Mathieu's a_n, b_n.
!>
!> ## The blocks
!> In the orthonormal real basis 1, √2 cos κτ, √2 sin κτ the matrix is real symmetric of the
!> same order (the "real symmetric form", with no doubling: g is real). When g is even
!> (every sₘ = 0) cosines and sines decouple into four blocks, the same as for the pencil
!> (hillstab_curves_hill_method `block_periodic_even` … `block_antiperiodic_odd`; bandwidth
!> M, curves a_n and b_n). Sine terms couple them: then one block per kind,
!> `block_periodic` and `block_antiperiodic` (bandwidth 2M + 1 with cosine and sine of each
!> wavenumber next to each other); the sorted values of a kind are the lower and upper edges
!> of the tongues of orders 0 | 2 2 | 4 4 … (periodic) and 1 1 | 3 3 … (antiperiodic),
!> Hill's oscillation theorem (λ₀ < λ₁ ≤ λ₂ < λ₃ ≤ …).
!>
!> ## Formulation (chosen by measurement, see the guide page *Transition curves*)
!> Default: the inverted pencil I z = μ (H − σI) z by LAPACK's `dsbgv`, β = σ + 1/μ, with
!> σ = −(|ĝ₀| + 2Σ|ĝₘ|) − 1 below every eigenvalue (H ≥ −sup|g|), as for the elastic pencil:
!> its rounding bound (√n + 2kd + 1) ε (β − σ)²/(β₁ − σ) + ε|β| stays at the size of the error
!> (error/bound ≤ 0.56 against 40-digit values) where the bound of the standard problem,
!> ∝ ε ‖H‖ with ‖H‖ ≈ κ_max², grows with the square of the truncation. Measured at 81 modes
!> (`make bench`): errors 1.7e-14 (dsbgv, 0.65 ms), 1.6e-14 (dsbev, 0.39 ms), 5.2e-12 (zhbev on
!> the exponentials, 0.39 ms: the complex band reduction loses digits on this graded matrix).
!> The standard real (`dsbev`) and the complex Hermitian form (`zhbev`, coupled blocks only)
!> are kept (`fourier_formulation_*`) for that measurement and for the tests.
!>
!> ## Truncation and error bounds
!> Truncation is a Rayleigh–Ritz method (the bases are nested), so the values decrease
!> monotonically as modes are added. The number of modes starts from the wavenumber of the
!> top of the β window (plus the band) and grows by half until every value below the top
!> changes by less than tolerance·max(1, |β|) between two truncations; the bound of each
!> value is that change or the eigensolver's rounding bound, whichever is larger.
!> A drive with infinitely many harmonics (`harmonics_infinite`: a jump of Q, coefficients
!> falling like 1/m) converges slowly: it is refused unless `allow_infinite` is given; then
!> the truncation uses every harmonic the matrix couples, the curves are flagged
!> `truncated_drive` and their bound is the truncation change.
!>
!>```fortran
!> type(hill_boundary_t), allocatable :: curves(:)
!> type(error_t), allocatable :: error
!> call fourier_boundaries(mathieu_model_t(), 2.0_wp, -5.0_wp, 40.0_wp, 1.0e-12_wp, curves, error)
!> print *, curves%beta
!>```
module hillstab_curves_hill_fourier
   use hillstab_core_kinds, only: wp, pi
   use hillstab_core_text, only: real_text, integer_text
   use hillstab_core_error, only: error_t, set_error, err_invalid_parameter, err_singular, err_accuracy
   use hillstab_hill_model, only: hill_model_t, check_alpha, harmonics_none, harmonics_infinite
   use hillstab_curves_hill_method, only: hill_boundary_t, block_periodic_even, block_periodic_odd, &
      block_antiperiodic_even, block_antiperiodic_odd, block_periodic, block_antiperiodic, block_order, &
      hill_block_name, route_fourier
   use hillstab_ffi_lapack, only: dsbgv, dsbev, zhbev
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   implicit none
   private
   public :: fourier_drive_t, fourier_drive, fourier_applies, fourier_blocks, fourier_block_t
   public :: fourier_block_eigenvalues, fourier_drive_eigenvalues, fourier_block_values, fourier_block_first
   public :: fourier_curves, fourier_boundaries, fourier_block_size
   public :: fourier_formulation_inverted, fourier_formulation_standard, fourier_formulation_complex
   public :: fourier_max_modes, fourier_max_modes_infinite, fourier_default_harmonics

   !> I z = μ (H − σI) z by `dsbgv` (the default).
   integer, parameter :: fourier_formulation_inverted = 1
   !> H z = β z by `dsbev` in the real basis.
   integer, parameter :: fourier_formulation_standard = 2
   !> H z = β z by `zhbev` on the exponentials (coupled blocks only).
   integer, parameter :: fourier_formulation_complex = 3

   !> Largest truncation level N (wavenumbers per block) tried for a finite drive.
   integer, parameter :: fourier_max_modes = 20000
   !> Largest truncation level for a drive with infinitely many harmonics (the matrix is full).
   integer, parameter :: fourier_max_modes_infinite = 400
   !> Harmonics asked of a drive with infinitely many of them when no truncation gives the count.
   integer, parameter :: fourier_default_harmonics = 64

   !> The drive g = Q − β of a model at one α: its mean and harmonics over the period.
   type :: fourier_drive_t
      real(wp) :: period = 2.0_wp         !! P
      real(wp) :: omega = pi              !! 2π/P
      integer :: harmonics = 0            !! M, the harmonics held
      real(wp) :: mean = 0.0_wp           !! ĝ₀
      real(wp), allocatable :: c(:), s(:) !! cosine and sine coefficients (M each)
      logical :: even = .true.            !! every sₘ = 0: g even about τ = 0, the blocks split
      logical :: infinite = .false.       !! the model's g has infinitely many harmonics (truncated here)
      !> |ĝ₀| + Σ √(cₘ² + sₘ²) ≥ sup |g|
      real(wp) :: bound = 0.0_wp
      !> gcd of the m with a nonzero harmonic (0: none): g has period P/divisor, and the
      !> tongues of the orders that are no multiple of it are closed
      integer :: divisor = 0
   end type fourier_drive_t

   !> The converged values of one block: what `fourier_block_values` and `fourier_block_first`
   !> compute and `fourier_curves` joins.
   type :: fourier_block_t
      integer :: block = 0                    !! block_* of hillstab_curves_hill_method
      real(wp), allocatable :: values(:)      !! converged eigenvalues, ascending
      real(wp), allocatable :: changes(:)     !! their change between the last two truncations
      real(wp), allocatable :: bounds(:)      !! the eigensolver's rounding bound of each
      integer :: used = 0                     !! order of the final truncation's matrix
      logical :: truncated_drive = .false.    !! the drive has infinitely many harmonics
      integer :: divisor = 0                  !! the drive's divisor (`fourier_drive_t`)
   end type fourier_block_t

contains

   !> Whether Hill's method on the Fourier coefficients applies to the model: Q = β + g(τ)
   !> with finitely many harmonics, or infinitely many when `allow_infinite`.
   pure logical function fourier_applies(model, allow_infinite)
      class(hill_model_t), intent(in) :: model       !! the model
      logical, intent(in), optional :: allow_infinite  !! accept infinitely many harmonics
      integer :: count
      count = model%drive_harmonic_count()
      fourier_applies = count > 0
      if (present(allow_infinite)) then
         if (allow_infinite .and. count == harmonics_infinite) fourier_applies = .true.
      end if
   end function fourier_applies

   !> The drive of a model at α (`drive_harmonics`), checked: the model must be of the form
   !> β + g(τ), α in its domain, the period and every coefficient finite. A drive with
   !> infinitely many harmonics is truncated to `harmonics` (default
   !> `fourier_default_harmonics`).
   subroutine fourier_drive(model, alpha, drive, error, harmonics)
      class(hill_model_t), intent(in) :: model  !! the model
      real(wp), intent(in) :: alpha             !! α
      type(fourier_drive_t), intent(out) :: drive  !! its harmonics
      !> err_invalid_parameter naming what is wrong; unallocated on success
      type(error_t), allocatable, intent(out) :: error
      integer, intent(in), optional :: harmonics  !! harmonics kept of an infinite drive
      integer :: count, m, d
      allocate (drive%c(0), drive%s(0))
      if (.not. ieee_is_finite(alpha)) then
         call set_error(error, err_invalid_parameter, "Hill's method: alpha must be finite")
         return
      end if
      count = model%drive_harmonic_count()
      if (count == harmonics_none .or. count < harmonics_infinite) then
         call set_error(error, err_invalid_parameter, "Hill's method on the Fourier coefficients does not apply "// &
            "to the "//model%name()//" model (Q is not beta + g(tau) with g independent of beta)")
         return
      end if
      call check_alpha(model, alpha, error)
      if (allocated(error)) then
         error%message = "Hill's method: "//error%message
         return
      end if
      drive%period = model%period()
      if (.not. (ieee_is_finite(drive%period) .and. drive%period > 0.0_wp)) then
         call set_error(error, err_invalid_parameter, "Hill's method: the "//model%name()// &
            " model's period must be finite and positive")
         return
      end if
      drive%omega = 2.0_wp*pi/drive%period
      drive%infinite = count == harmonics_infinite
      if (drive%infinite) then
         count = fourier_default_harmonics
         if (present(harmonics)) count = max(1, harmonics)
      end if
      drive%harmonics = count
      deallocate (drive%c, drive%s)
      allocate (drive%c(count), drive%s(count))
      call model%drive_harmonics(alpha, count, drive%mean, drive%c, drive%s)
      if (.not. (ieee_is_finite(drive%mean) .and. all(ieee_is_finite(drive%c)) .and. all(ieee_is_finite(drive%s)))) then
         call set_error(error, err_invalid_parameter, "Hill's method: the "//model%name()// &
            " model's harmonics of Q - beta are not finite at alpha = "//real_text(alpha))
         return
      end if
      drive%even = all(drive%s == 0.0_wp)
      drive%bound = abs(drive%mean) + sum(hypot(drive%c, drive%s))
      if (.not. drive%bound < 1.0e150_wp) then
         call set_error(error, err_invalid_parameter, "Hill's method: the harmonics of Q - beta are too large")
         return
      end if
      d = 0
      do m = 1, count
         if (drive%c(m) /= 0.0_wp .or. drive%s(m) /= 0.0_wp) d = gcd(d, m)
      end do
      drive%divisor = d
   end subroutine fourier_drive

   pure integer function gcd(a, b)
      integer, intent(in) :: a, b
      integer :: x, y, t
      x = abs(a); y = abs(b)
      do while (y /= 0)
         t = mod(x, y); x = y; y = t
      end do
      gcd = x
   end function gcd

   !> The blocks of the drive: the four even/odd blocks when g is even, else the two
   !> coupled ones (`block_periodic`, `block_antiperiodic`).
   pure function fourier_blocks(drive) result(blocks)
      type(fourier_drive_t), intent(in) :: drive  !! the drive
      integer, allocatable :: blocks(:)
      if (drive%even) then
         blocks = [block_periodic_even, block_periodic_odd, block_antiperiodic_even, block_antiperiodic_odd]
      else
         blocks = [block_periodic, block_antiperiodic]
      end if
   end function fourier_blocks

   !> Order of the matrix of a block at truncation level N: N for the even/odd blocks
   !> (wavenumbers 0 … N − 1, 1 … N or ½ … N − ½), 2N + 1 and 2N for the coupled ones.
   elemental integer function fourier_block_size(block, level) result(n)
      integer, intent(in) :: block  !! block_*
      integer, intent(in) :: level  !! truncation level N ≥ 1
      select case (block)
      case (block_periodic); n = 2*level + 1
      case (block_antiperiodic); n = 2*level
      case default; n = level
      end select
   end function fourier_block_size

   !> ĝ_m (complex), zero beyond the harmonics held.
   pure complex(wp) function g_hat(drive, m)
      type(fourier_drive_t), intent(in) :: drive
      integer, intent(in) :: m
      if (m == 0) then
         g_hat = cmplx(drive%mean, 0.0_wp, wp)
      else if (abs(m) > drive%harmonics) then
         g_hat = (0.0_wp, 0.0_wp)
      else if (m > 0) then
         g_hat = 0.5_wp*cmplx(drive%c(m), -drive%s(m), wp)
      else
         g_hat = 0.5_wp*cmplx(drive%c(-m), drive%s(-m), wp)
      end if
   end function g_hat

   !> Whether a block's wavenumbers are (k + ½)ω (antiperiodic).
   pure logical function antiperiodic(block)
      integer, intent(in) :: block
      antiperiodic = block == block_antiperiodic_even .or. block == block_antiperiodic_odd .or. &
                     block == block_antiperiodic
   end function antiperiodic

   !> H(a, b) on the exponentials e^{iκ_aτ}, e^{iκ_bτ}.
   pure complex(wp) function h_entry(drive, block, a, b)
      type(fourier_drive_t), intent(in) :: drive
      integer, intent(in) :: block, a, b
      real(wp) :: kappa
      h_entry = -g_hat(drive, a - b)
      if (a == b) then
         kappa = real(a, wp)*drive%omega
         if (antiperiodic(block)) kappa = (real(a, wp) + 0.5_wp)*drive%omega
         h_entry = h_entry + kappa*kappa
      end if
   end function h_entry

   !> Basis function r (1-based) of a block as a combination of one or two exponentials:
   !> 1, √2 cos κτ = (e_k + e_{−k})/√2, √2 sin κτ = (−i e_k + i e_{−k})/√2 (e_{−1−k} for the
   !> antiperiodic mirror).
   pure subroutine basis(block, r, index, coefficient, terms)
      integer, intent(in) :: block, r
      integer, intent(out) :: index(2), terms
      complex(wp), intent(out) :: coefficient(2)
      real(wp), parameter :: h = 0.70710678118654752440_wp
      integer :: k
      logical :: cosine
      select case (block)
      case (block_periodic_even)
         k = r - 1; cosine = .true.
      case (block_periodic_odd)
         k = r; cosine = .false.
      case (block_antiperiodic_even)
         k = r - 1; cosine = .true.
      case (block_antiperiodic_odd)
         k = r - 1; cosine = .false.
      case (block_periodic)   ! 1, cos 1, sin 1, cos 2, sin 2, …
         k = r/2; cosine = mod(r, 2) == 0 .or. r == 1
      case default            ! cos ½, sin ½, cos 3/2, …
         k = (r - 1)/2; cosine = mod(r, 2) == 1
      end select
      index(1) = k
      if (antiperiodic(block)) then
         index(2) = -1 - k
      else
         index(2) = -k
      end if
      if (.not. antiperiodic(block) .and. k == 0) then
         terms = 1
         coefficient = [(1.0_wp, 0.0_wp), (0.0_wp, 0.0_wp)]
         return
      end if
      terms = 2
      if (cosine) then
         coefficient = [cmplx(h, 0.0_wp, wp), cmplx(h, 0.0_wp, wp)]
      else
         coefficient = [cmplx(0.0_wp, -h, wp), cmplx(0.0_wp, h, wp)]
      end if
   end subroutine basis

   !> ⟨φ_r, H φ_q⟩ in a block's real orthonormal basis (real: g is real).
   pure real(wp) function real_entry(drive, block, r, q) result(value)
      type(fourier_drive_t), intent(in) :: drive
      integer, intent(in) :: block, r, q
      integer :: ir(2), iq(2), nr, nq, a, b
      complex(wp) :: cr(2), cq(2), total
      call basis(block, r, ir, cr, nr)
      call basis(block, q, iq, cq, nq)
      total = (0.0_wp, 0.0_wp)
      do a = 1, nr
         do b = 1, nq
            total = total + conjg(cr(a))*cq(b)*h_entry(drive, block, ir(a), iq(b))
         end do
      end do
      value = real(total, wp)
   end function real_entry

   !> Bandwidth of a block's real matrix of order n.
   pure integer function real_bandwidth(drive, block, n) result(b)
      type(fourier_drive_t), intent(in) :: drive
      integer, intent(in) :: block, n
      if (block == block_periodic .or. block == block_antiperiodic) then
         b = 2*drive%harmonics + 1
      else
         b = drive%harmonics
      end if
      b = max(0, min(b, n - 1))
   end function real_bandwidth

   !> All eigenvalues, ascending, of a block of the model's drive at truncation level N.
   subroutine fourier_block_eigenvalues(model, alpha, block, level, values, error, formulation)
      class(hill_model_t), intent(in) :: model  !! the model (of the form β + g(τ))
      real(wp), intent(in) :: alpha             !! α
      integer, intent(in) :: block              !! block_*: an even/odd block for an even g, else a coupled one
      integer, intent(in) :: level              !! truncation level N ≥ 1 (`fourier_block_size`)
      real(wp), allocatable, intent(out) :: values(:)  !! β, ascending
      type(error_t), allocatable, intent(out) :: error  !! bad input or LAPACK failure; unallocated on success
      integer, intent(in), optional :: formulation      !! fourier_formulation_* (default inverted)
      type(fourier_drive_t) :: drive
      allocate (values(0))
      call fourier_drive(model, alpha, drive, error, harmonics=2*max(level, 1) + 1)
      if (allocated(error)) return
      call fourier_drive_eigenvalues(drive, block, level, values, error, formulation)
   end subroutine fourier_block_eigenvalues

   !> All eigenvalues, ascending, of a block of a drive at truncation level N.
   subroutine fourier_drive_eigenvalues(drive, block, level, values, error, formulation)
      type(fourier_drive_t), intent(in) :: drive  !! the drive (`fourier_drive`)
      integer, intent(in) :: block                !! block_*
      integer, intent(in) :: level                !! truncation level N ≥ 1
      real(wp), allocatable, intent(out) :: values(:)  !! β, ascending
      type(error_t), allocatable, intent(out) :: error  !! bad input or LAPACK failure; unallocated on success
      integer, intent(in), optional :: formulation      !! fourier_formulation_* (default inverted)
      real(wp), allocatable :: ab(:, :), bb(:, :), w(:), work(:), rwork(:)
      complex(wp), allocatable :: cab(:, :), cwork(:)
      real(wp) :: sigma, z(1, 1)
      complex(wp) :: cz(1, 1)
      integer :: form, n, kd, r, d, info, lo, i, j
      character(len=200) :: buf
      form = fourier_formulation_inverted
      if (present(formulation)) form = formulation
      allocate (values(0))
      if (block < block_periodic_even .or. block > block_antiperiodic .or. level < 1) then
         call set_error(error, err_invalid_parameter, "Hill's method: unknown block or no modes")
         return
      end if
      if (drive%even .neqv. (block <= block_antiperiodic_odd)) then
         if (drive%even) then
            call set_error(error, err_invalid_parameter, "Hill's method: block "//hill_block_name(block)// &
               " is for a drive with sine terms (an even drive splits into the even/odd blocks)")
         else
            call set_error(error, err_invalid_parameter, "Hill's method: block "//hill_block_name(block)// &
               " needs an even drive (no sine terms)")
         end if
         return
      end if
      if (form < fourier_formulation_inverted .or. form > fourier_formulation_complex) then
         call set_error(error, err_invalid_parameter, "Hill's method: unknown formulation")
         return
      end if
      if (form == fourier_formulation_complex .and. block <= block_antiperiodic_odd) then
         call set_error(error, err_invalid_parameter, "Hill's method: the complex formulation is for the "// &
            "coupled blocks (a drive with sine terms)")
         return
      end if
      n = fourier_block_size(block, level)
      sigma = -drive%bound - 1.0_wp
      select case (form)
      case (fourier_formulation_complex)
         ! exponentials k = −N … N (periodic) or −N … N − 1, in order: bandwidth M
         kd = max(0, min(drive%harmonics, n - 1))
         lo = -level
         allocate (cab(kd + 1, n), cwork(n), rwork(max(1, 3*n - 2)), w(n))
         cab = (0.0_wp, 0.0_wp)
         do j = 1, n
            do i = max(1, j - kd), j
               cab(kd + 1 + i - j, j) = h_entry(drive, block, lo + i - 1, lo + j - 1)
            end do
         end do
         call zhbev("N", "U", n, kd, cab, kd + 1, w, cz, 1, cwork, rwork, info)
         if (info /= 0) then
            write (buf, '(a,i0,a,i0,a)') "Hill's method: LAPACK zhbev failed (info = ", info, ", order ", n, ")"
            call set_error(error, err_singular, trim(buf))
            return
         end if
         values = w
      case (fourier_formulation_standard)
         kd = real_bandwidth(drive, block, n)
         allocate (ab(kd + 1, n), w(n), work(max(1, 3*n - 2)))
         ab = 0.0_wp
         do r = 1, n
            do d = 0, min(kd, r - 1)
               ab(kd + 1 - d, r) = real_entry(drive, block, r - d, r)
            end do
         end do
         call dsbev("N", "U", n, kd, ab, kd + 1, w, z, 1, work, info)
         if (info /= 0) then
            write (buf, '(a,i0,a,i0,a)') "Hill's method: LAPACK dsbev failed (info = ", info, ", order ", n, ")"
            call set_error(error, err_singular, trim(buf))
            return
         end if
         values = w
      case default
         ! I z = μ (H − σI) z: H − σI ≥ I is positive definite, the wanted small β the largest μ
         kd = real_bandwidth(drive, block, n)
         allocate (ab(kd + 1, n), bb(kd + 1, n), w(n), work(3*n))
         ab = 0.0_wp; bb = 0.0_wp
         do r = 1, n
            ab(kd + 1, r) = 1.0_wp
            do d = 0, min(kd, r - 1)
               bb(kd + 1 - d, r) = real_entry(drive, block, r - d, r)
            end do
            bb(kd + 1, r) = bb(kd + 1, r) - sigma
         end do
         call dsbgv("N", "U", n, kd, kd, ab, kd + 1, bb, kd + 1, w, z, 1, work, info)
         if (info /= 0) then
            write (buf, '(a,i0,a,i0,a)') "Hill's method: LAPACK dsbgv failed (info = ", info, ", order ", n, ")"
            call set_error(error, err_singular, trim(buf))
            return
         end if
         if (any(.not. (w > 0.0_wp))) then
            call set_error(error, err_singular, "Hill's method: non-positive eigenvalue of the inverted pencil")
            return
         end if
         values = sigma + 1.0_wp/w(n:1:-1)
      end select
      if (.not. all(ieee_is_finite(values))) then
         call set_error(error, err_singular, "Hill's method: non-finite eigenvalue")
      end if
   end subroutine fourier_drive_eigenvalues

   !> Rounding bound of an eigenvalue β of a block of order n and bandwidth kd (the module
   !> doc): for the inverted pencil (√n + 2kd + 1) ε (β − σ)²/(β₁ − σ) + ε|β| — LAPACK's
   !> p(n) ε ‖I‖ ‖(H − σI)⁻¹‖ on μ, δβ = (β − σ)² δμ, with p(n) = √n, plus the rounding of
   !> the band's entries (2kd + 1 of them a row, each within ε of its value): with √n alone
   !> the errors against 40-digit references (data/reference/fourier_set.dat) reached 1.7×
   !> the bound at P = 4, kd = 9; for the standard problem (√n + 2kd + 1) ε ‖H‖ + ε|β| with
   !> ‖H‖ ≤ κ_max² + sup|g|.
   pure real(wp) function rounding_bound(drive, n, kd, level, beta_lowest, beta, form) result(bound)
      type(fourier_drive_t), intent(in) :: drive
      integer, intent(in) :: n, kd, level, form
      real(wp), intent(in) :: beta_lowest, beta
      real(wp) :: sigma, kappa, factor
      factor = (sqrt(real(n, wp)) + real(2*kd + 1, wp))*epsilon(1.0_wp)
      if (form == fourier_formulation_inverted) then
         sigma = -drive%bound - 1.0_wp
         bound = factor*(beta - sigma)**2/max(beta_lowest - sigma, 1.0_wp)
      else
         kappa = (real(level, wp) + 1.0_wp)*drive%omega
         bound = factor*(kappa*kappa + drive%bound)
      end if
      bound = bound + epsilon(1.0_wp)*abs(beta)
   end function rounding_bound

   !> One block's eigenvalues converged up to the top of the window [beta_min, beta_max]
   !> (one order above it, so that every tongue reaching into it has both edges).
   subroutine fourier_block_values(model, alpha, block, beta_min, beta_max, tolerance, values, error, &
                                   formulation, allow_infinite)
      class(hill_model_t), intent(in) :: model      !! the model (of the form β + g(τ))
      real(wp), intent(in) :: alpha                 !! α
      integer, intent(in) :: block                  !! block_* (`fourier_blocks` of the drive at α)
      real(wp), intent(in) :: beta_min, beta_max    !! the β window
      real(wp), intent(in) :: tolerance             !! convergence target on β, relative to max(1, |β|)
      type(fourier_block_t), intent(out) :: values  !! the converged values of the block
      !> bad input, no convergence or LAPACK failure; unallocated on success
      type(error_t), allocatable, intent(out) :: error
      integer, intent(in), optional :: formulation     !! fourier_formulation_* (default inverted)
      logical, intent(in), optional :: allow_infinite  !! accept infinitely many harmonics (slow)
      allocate (values%values(0), values%changes(0), values%bounds(0))
      values%block = block
      if (.not. (ieee_is_finite(beta_min) .and. ieee_is_finite(beta_max) .and. ieee_is_finite(tolerance))) then
         call set_error(error, err_invalid_parameter, "Hill's method: beta window and tolerance must be finite")
         return
      end if
      if (beta_min > beta_max .or. .not. tolerance > 0.0_wp) then
         call set_error(error, err_invalid_parameter, "Hill's method: need beta_min <= beta_max and tolerance > 0")
         return
      end if
      call converge(model, alpha, block, beta_max + 1.0_wp + 0.25_wp*abs(beta_max), 0, tolerance, values, error, &
                    formulation, allow_infinite)
   end subroutine fourier_block_values

   !> The `count` lowest eigenvalues of one block, converged.
   subroutine fourier_block_first(model, alpha, block, count, tolerance, values, error, formulation, allow_infinite)
      class(hill_model_t), intent(in) :: model      !! the model (of the form β + g(τ))
      real(wp), intent(in) :: alpha                 !! α
      integer, intent(in) :: block                  !! block_* (`fourier_blocks` of the drive at α)
      integer, intent(in) :: count                  !! how many values, ≥ 1
      real(wp), intent(in) :: tolerance             !! convergence target on β, relative to max(1, |β|)
      type(fourier_block_t), intent(out) :: values  !! the converged values of the block
      !> bad input, no convergence or LAPACK failure; unallocated on success
      type(error_t), allocatable, intent(out) :: error
      integer, intent(in), optional :: formulation     !! fourier_formulation_* (default inverted)
      logical, intent(in), optional :: allow_infinite  !! accept infinitely many harmonics (slow)
      allocate (values%values(0), values%changes(0), values%bounds(0))
      values%block = block
      if (count < 1) then
         call set_error(error, err_invalid_parameter, "Hill's method: the number of values must be >= 1")
         return
      end if
      if (.not. (ieee_is_finite(tolerance) .and. tolerance > 0.0_wp)) then
         call set_error(error, err_invalid_parameter, "Hill's method: tolerance must be finite and > 0")
         return
      end if
      call converge(model, alpha, block, 0.0_wp, count, tolerance, values, error, formulation, allow_infinite)
   end subroutine fourier_block_first

   !> The values ≤ top (want = 0) or the `want` lowest of one block, converged: the truncation
   !> grows by half until every one of them changes by at most tolerance·max(1, |β|).
   subroutine converge(model, alpha, block, top, want, tolerance, result, error, formulation, allow_infinite)
      class(hill_model_t), intent(in) :: model
      real(wp), intent(in) :: alpha, top, tolerance
      integer, intent(in) :: block, want
      type(fourier_block_t), intent(inout) :: result
      type(error_t), allocatable, intent(out) :: error
      integer, intent(in), optional :: formulation
      logical, intent(in), optional :: allow_infinite
      type(fourier_drive_t) :: drive, drive_fine
      real(wp), allocatable :: coarse(:), fine(:)
      real(wp) :: reach
      integer :: level, level_fine, m, j, form, cap, n
      logical :: done, infinite_ok
      character(len=240) :: buf
      form = fourier_formulation_inverted
      if (present(formulation)) form = formulation
      infinite_ok = .false.
      if (present(allow_infinite)) infinite_ok = allow_infinite
      call fourier_drive(model, alpha, drive, error)
      if (allocated(error)) return
      if (drive%infinite .and. .not. infinite_ok) then
         call set_error(error, err_invalid_parameter, "Hill's method: Q - beta of the "//model%name()// &
            " model has infinitely many harmonics (a jump of Q): the truncation converges slowly; its transition "// &
            "values come from root finding on S (allow_infinite computes them anyway)")
         return
      end if
      if (drive%even .neqv. (block <= block_antiperiodic_odd) .or. block < block_periodic_even .or. &
          block > block_antiperiodic) then
         call set_error(error, err_invalid_parameter, "Hill's method: block "//hill_block_name(block)// &
            " does not fit the drive (even/odd blocks for an even g, coupled ones otherwise)")
         return
      end if
      result%truncated_drive = drive%infinite
      result%divisor = drive%divisor
      cap = merge(fourier_max_modes_infinite, fourier_max_modes, drive%infinite)
      ! the wavenumber index the eigenfunctions up to the top reach, plus the band
      if (want > 0) then
         reach = real(want, wp) + sqrt(drive%bound)/drive%omega
         if (block == block_periodic .or. block == block_antiperiodic) reach = 0.5_wp*real(want, wp) + &
                                                                               sqrt(drive%bound)/drive%omega
      else
         reach = sqrt(max(top, 0.0_wp) + drive%bound)/drive%omega
      end if
      level = 8 + ceiling(min(reach, 1.0e9_wp)) + merge(8, 2*drive%harmonics, drive%infinite)
      if (level > cap) then
         call set_error(error, err_invalid_parameter, "Hill's method: the values asked need more than "// &
            integer_text(fourier_block_size(block, cap))//" modes in block "//hill_block_name(block)// &
            " (too many values or too large a window)")
         return
      end if
      call level_values(level, coarse)
      if (allocated(error)) return
      do
         level_fine = min(level + max(4, level/2), cap)
         call level_values(level_fine, fine, drive_fine)
         if (allocated(error)) return
         if (want > 0) then
            m = want
            done = size(fine) >= want .and. size(coarse) >= want
         else
            m = count(fine <= top)
            done = m < size(fine) .and. m < size(coarse)   ! a value above top exists in both
         end if
         if (done) then
            do j = 1, m
               if (abs(coarse(j) - fine(j)) > tolerance*max(1.0_wp, abs(fine(j)))) done = .false.
            end do
         end if
         if (done) exit
         if (level_fine >= cap) then
            write (buf, '(a,i0,a,a,a,a)') "Hill's method: not converged with ", fourier_block_size(block, level_fine), &
               " modes at alpha = ", real_text(alpha), " in block ", hill_block_name(block)
            call set_error(error, err_accuracy, trim(buf))
            return
         end if
         level = level_fine
         call move_alloc(fine, coarse)
      end do
      n = fourier_block_size(block, level_fine)
      result%used = n
      result%values = fine(:m)
      result%changes = abs(coarse(:m) - fine(:m))
      if (allocated(result%bounds)) deallocate (result%bounds)
      allocate (result%bounds(m))
      do j = 1, m
         result%bounds(j) = rounding_bound(drive_fine, n, real_bandwidth(drive_fine, block, n), level_fine, &
                                           fine(1), fine(j), form)
      end do
   contains
      !> The eigenvalues at one truncation level (an infinite drive with every harmonic the
      !> matrix couples).
      subroutine level_values(lev, v, used_drive)
         integer, intent(in) :: lev
         real(wp), allocatable, intent(out) :: v(:)
         type(fourier_drive_t), intent(out), optional :: used_drive
         type(fourier_drive_t) :: d
         if (drive%infinite) then
            call fourier_drive(model, alpha, d, error, harmonics=2*lev + 1)
            if (allocated(error)) return
         else
            d = drive
         end if
         call fourier_drive_eigenvalues(d, block, lev, v, error, form)
         if (present(used_drive)) used_drive = d
      end subroutine level_values
   end subroutine converge

   !> The transition curves crossing [beta_min, beta_max] from the blocks' values (any
   !> number of blocks, each with its block id), ordered by β, with their error bounds,
   !> orders, parities (±1 for the even/odd blocks, 0 with the edge for the coupled ones) and
   !> the coexistence decided by structure: a tongue of order n ≥ 1 is closed when g has no
   !> harmonic (g constant) or when n is no multiple of the drive's divisor (g of period P/d).
   subroutine fourier_curves(beta_min, beta_max, blocks, curves)
      real(wp), intent(in) :: beta_min, beta_max      !! the β window
      type(fourier_block_t), intent(in) :: blocks(:)  !! the blocks' values
      type(hill_boundary_t), allocatable, intent(out) :: curves(:)  !! the curves, by beta
      type(hill_boundary_t), allocatable :: all(:)
      type(hill_boundary_t) :: t
      integer :: b, j, n_out, m, total, block
      total = 0
      do b = 1, size(blocks)
         total = total + size(blocks(b)%values)
      end do
      allocate (all(total))
      n_out = 0
      do b = 1, size(blocks)
         block = blocks(b)%block
         do j = 1, size(blocks(b)%values)
            if (blocks(b)%values(j) < beta_min .or. blocks(b)%values(j) > beta_max) cycle
            n_out = n_out + 1
            associate (c => all(n_out))
               c%beta = blocks(b)%values(j)
               c%block = block
               c%route = route_fourier
               c%truncated_drive = blocks(b)%truncated_drive
               c%modes = blocks(b)%used
               c%change = blocks(b)%changes(j)
               c%error_bound = max(blocks(b)%changes(j), blocks(b)%bounds(j))
               c%trace_sign = merge(2, -2, .not. antiperiodic(block))
               select case (block)
               case (block_periodic)
                  c%parity = 0
                  c%order = 2*(j/2)
                  c%edge = merge(0, 1 + mod(j, 2), j == 1)
               case (block_antiperiodic)
                  c%parity = 0
                  c%order = 2*((j - 1)/2) + 1
                  c%edge = 1 + mod(j - 1, 2)
               case default
                  c%order = block_order(block, j)
                  c%parity = merge(1, -1, block == block_periodic_even .or. block == block_antiperiodic_even)
                  c%edge = 0
               end select
               c%coexistent = .false.
               if (c%order > 0) then
                  if (blocks(b)%divisor == 0) then
                     c%coexistent = .true.
                  else
                     c%coexistent = mod(c%order, blocks(b)%divisor) /= 0
                  end if
               end if
            end associate
         end do
      end do
      curves = all(:n_out)
      do j = 2, n_out
         m = j
         do while (m > 1)
            if (curves(m - 1)%beta <= curves(m)%beta) exit
            t = curves(m - 1); curves(m - 1) = curves(m); curves(m) = t
            m = m - 1
         end do
      end do
   end subroutine fourier_curves

   !> Every transition curve crossing β_min ≤ β ≤ β_max at this α, converged in the truncation
   !> to tolerance·max(1, |β|), ordered by β (`fourier_block_values` on every block of the
   !> drive, joined by `fourier_curves`).
   subroutine fourier_boundaries(model, alpha, beta_min, beta_max, tolerance, curves, error, formulation, &
                                 allow_infinite)
      class(hill_model_t), intent(in) :: model    !! the model (of the form β + g(τ))
      real(wp), intent(in) :: alpha               !! α
      real(wp), intent(in) :: beta_min, beta_max  !! the β window
      real(wp), intent(in) :: tolerance           !! convergence target on β, relative to max(1, |β|)
      type(hill_boundary_t), allocatable, intent(out) :: curves(:)  !! the curves, by beta
      !> bad input, no convergence or LAPACK failure; unallocated on success
      type(error_t), allocatable, intent(out) :: error
      integer, intent(in), optional :: formulation     !! fourier_formulation_* (default inverted)
      logical, intent(in), optional :: allow_infinite  !! accept infinitely many harmonics (slow)
      type(fourier_drive_t) :: drive
      type(fourier_block_t), allocatable :: blocks(:)
      integer, allocatable :: ids(:)
      integer :: b
      allocate (curves(0))
      call fourier_drive(model, alpha, drive, error)
      if (allocated(error)) return
      ids = fourier_blocks(drive)
      allocate (blocks(size(ids)))
      do b = 1, size(ids)
         call fourier_block_values(model, alpha, ids(b), beta_min, beta_max, tolerance, blocks(b), error, &
                                   formulation, allow_infinite)
         if (allocated(error)) return
      end do
      call fourier_curves(beta_min, beta_max, blocks, curves)
   end subroutine fourier_boundaries
end module hillstab_curves_hill_fourier

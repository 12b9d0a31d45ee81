!> Characteristic values as a library call: for any model and α, the first n transition
!> values of β of each kind, with their error bounds, by the model's route
!> (hillstab_curves_boundaries `curve_route`): Hill's method on the pencil (elastic,
!> Mathieu), on the Fourier coefficients of g = Q − β (Q = β + g with finitely many
!> harmonics), or the roots of S = ±2 by method auto (the rest).
!>
!> The kinds are the blocks of hillstab_curves_hill_method: where Q is even the four
!> `block_periodic_even` (a₀, a₂, a₄, …), `block_periodic_odd` (b₂, b₄, …),
!> `block_antiperiodic_even` (a₁, a₃, …) and `block_antiperiodic_odd` (b₁, b₃, …), n values
!> each; where it is not (sine terms), or for the roots of S, `block_periodic` (orders 0, 2,
!> 2, 4, 4, …: both edges of each tongue) and `block_antiperiodic` (1, 1, 3, 3, …), n values
!> each. The values come ordered by kind, then ascending.
!>
!> Mathieu's a_n(q), b_n(q) are the special case: y'' + (a − 2q cos 2t) y = 0 with t = πτ/2 is
!> the Mathieu model x'' + (β − ν cos πτ) x = 0 with β = π²a/4 and α = ν = π²q/2 (the guide's
!> *The model*: a = 4β/π², q = 2ν/π²), so at α = π²q/2 the values of kind
!> block_periodic_even are (π²/4)(a₀, a₂, …, a_{2n−2}), and so on.
!>
!>```fortran
!> type(hill_boundary_t), allocatable :: values(:)
!> type(error_t), allocatable :: error
!> call characteristic_values(mathieu_model_t(), 0.5_wp*pi2*1.0_wp, 3, values, error)   ! q = 1
!> print *, 4*values%beta/pi2   ! a0, a2, a4, b2, b4, b6, a1, a3, a5, b1, b3, b5
!>```
module hillstab_curves_characteristic
   use hillstab_core_kinds, only: wp, pi
   use hillstab_core_text, only: integer_text
   use hillstab_core_error, only: error_t, set_error, err_invalid_parameter, err_accuracy
   use hillstab_hill_model, only: hill_model_t, check_alpha
   use hillstab_integrate_monodromy, only: method_t, method_auto, method_formula
   use hillstab_curves_hill_method, only: hill_boundary_t, hill_block_values_t, hill_block_values, hill_curves, &
      block_periodic_even, block_antiperiodic_odd, block_periodic, block_antiperiodic, route_pencil, route_fourier, &
      route_roots
   use hillstab_curves_hill_fourier, only: fourier_drive_t, fourier_drive, fourier_blocks, fourier_block_t, &
      fourier_block_first, fourier_curves
   use hillstab_curves_boundaries, only: curve_route, approximate_root_t, approximate_boundaries, roots_to_curves, &
      beta_floor
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   implicit none
   private
   public :: characteristic_values, characteristic_capacity, max_characteristic_count, default_characteristic_tolerance

   !> Most values of one kind a call computes.
   integer, parameter :: max_characteristic_count = 2000
   !> The tolerance of a call that gives none (relative to max(1, |β|)).
   real(wp), parameter :: default_characteristic_tolerance = 1.0e-12_wp

contains

   !> How many values a call with n may return: 4n (four kinds of n, or two of 2n… of n each:
   !> at most 4n in every route).
   elemental integer function characteristic_capacity(n) result(capacity)
      integer, intent(in) :: n  !! values of each kind
      capacity = 4*max(n, 0)
   end function characteristic_capacity

   !> The first n transition values of β of each kind at α (module doc), each with its
   !> order, kind (`block`), trace sign, parity (±1 a/b where the blocks split, else 0 with
   !> its edge), error bound and route, ordered by kind, then ascending.
   subroutine characteristic_values(model, alpha, n, values, error, tolerance)
      class(hill_model_t), intent(in) :: model  !! the model
      real(wp), intent(in) :: alpha             !! α (ν for the Mathieu model)
      integer, intent(in) :: n                  !! values of each kind, 1 … max_characteristic_count
      type(hill_boundary_t), allocatable, intent(out) :: values(:)  !! the values, by kind then beta
      !> err_invalid_parameter (n, α, tolerance), err_accuracy (not converged) or a failure of the
      !> eigensolver or of auto; unallocated on success
      type(error_t), allocatable, intent(out) :: error
      !> convergence target on β relative to max(1, |β|) (default 1e-12)
      real(wp), intent(in), optional :: tolerance
      real(wp) :: tol
      allocate (values(0))
      tol = default_characteristic_tolerance
      if (present(tolerance)) tol = tolerance
      if (n < 1 .or. n > max_characteristic_count) then
         call set_error(error, err_invalid_parameter, "characteristic values: n must be 1 to "// &
            integer_text(max_characteristic_count)//", got "//integer_text(n))
         return
      end if
      if (.not. (ieee_is_finite(tol) .and. tol > 0.0_wp)) then
         call set_error(error, err_invalid_parameter, "characteristic values: tolerance must be finite and > 0")
         return
      end if
      if (.not. ieee_is_finite(alpha)) then
         call set_error(error, err_invalid_parameter, "characteristic values: alpha must be finite")
         return
      end if
      call check_alpha(model, alpha, error)
      if (allocated(error)) return
      select case (curve_route(model))
      case (route_pencil)
         call pencil_values(model, alpha, n, tol, values, error)
      case (route_fourier)
         call fourier_values(model, alpha, n, tol, values, error)
      case default
         call root_values(model, alpha, n, tol, values, error)
      end select
   end subroutine characteristic_values

   !> The pencil route: the four blocks up to a top that holds n values of each (doubled until
   !> it does), joined by `hill_curves`, the first n of each block kept.
   subroutine pencil_values(model, alpha, n, tol, values, error)
      class(hill_model_t), intent(in) :: model
      real(wp), intent(in) :: alpha, tol
      integer, intent(in) :: n
      type(hill_boundary_t), allocatable, intent(inout) :: values(:)
      type(error_t), allocatable, intent(out) :: error
      type(hill_block_values_t) :: blocks(4)
      type(hill_boundary_t), allocatable :: curves(:)
      real(wp) :: top
      integer :: block, attempt
      ! the n-th value of the highest block (b_2n) lies near (nπ)² at α = 0
      top = (real(n, wp)*pi)**2 + 2.0_wp*abs(alpha) + 10.0_wp
      do attempt = 1, 40
         do block = block_periodic_even, block_antiperiodic_odd
            call hill_block_values(model, alpha, block, -huge(1.0_wp)/4, top, tol, blocks(block), error)
            if (allocated(error)) return
         end do
         if (all([(size(blocks(block)%values) >= n, block=1, 4)])) exit
         top = 2.0_wp*top + 10.0_wp
      end do
      call hill_curves(model, alpha, -huge(1.0_wp), huge(1.0_wp), blocks, curves)
      call first_of_each(curves, [block_periodic_even, 2, 3, block_antiperiodic_odd], n, values, error)
   end subroutine pencil_values

   !> The Fourier route: the n lowest values of each block of the drive (`fourier_block_first`).
   subroutine fourier_values(model, alpha, n, tol, values, error)
      class(hill_model_t), intent(in) :: model
      real(wp), intent(in) :: alpha, tol
      integer, intent(in) :: n
      type(hill_boundary_t), allocatable, intent(inout) :: values(:)
      type(error_t), allocatable, intent(out) :: error
      type(fourier_drive_t) :: drive
      type(fourier_block_t), allocatable :: blocks(:)
      type(hill_boundary_t), allocatable :: curves(:)
      integer, allocatable :: ids(:)
      integer :: b
      call fourier_drive(model, alpha, drive, error)
      if (allocated(error)) return
      ids = fourier_blocks(drive)
      allocate (blocks(size(ids)))
      do b = 1, size(ids)
         call fourier_block_first(model, alpha, ids(b), n, tol, blocks(b), error)
         if (allocated(error)) return
      end do
      call fourier_curves(-huge(1.0_wp), huge(1.0_wp), blocks, curves)
      call first_of_each(curves, ids, n, values, error)
   end subroutine fourier_values

   !> The roots route: S = ±2 by method auto (by the closed form where the model has it),
   !> scanned from below every curve (`beta_floor`) up to a top that holds n roots of each
   !> kind (the samples doubled at every try, up to 200 000, the top raised by half at every
   !> other, 12 tries), tongues narrower than a sample step sought between the samples
   !> (`approximate_boundaries`' `narrow`); the first n of each kind kept (a closed tongue,
   !> where S only touches ±2, is missed and shifts the orders above it).
   subroutine root_values(model, alpha, n, tol, values, error)
      class(hill_model_t), intent(in) :: model
      real(wp), intent(in) :: alpha, tol
      integer, intent(in) :: n
      type(hill_boundary_t), allocatable, intent(inout) :: values(:)
      type(error_t), allocatable, intent(out) :: error
      type(approximate_root_t), allocatable :: roots(:)
      type(hill_boundary_t), allocatable :: curves(:)
      real(wp) :: floor, top, p
      integer :: attempt, samples
      p = model%period()
      floor = beta_floor(model, alpha)
      top = (real(n + 1, wp)*pi/p)**2 + abs(floor) + 2.0_wp
      do attempt = 1, 12
         ! the samples doubled at every attempt, the top raised by half at every other one:
         ! narrow tongues need a finer scan more often than a higher window
         samples = min(60*(n + 2)*2**(attempt - 1), 200000)
         if (attempt > 1 .and. mod(attempt, 2) == 1) top = 1.5_wp*top
         call approximate_boundaries(model, alpha, method_t(merge(method_formula, method_auto, &
            model%two_pieces_exact()), tolerance=tol), floor, top, samples, tol, &
                                     roots, error, floor=floor, narrow=.true.)
         if (allocated(error)) return
         if (count(roots%trace_sign == 2) >= n .and. count(roots%trace_sign == -2) >= n) exit
      end do
      curves = roots_to_curves(roots, tol)
      curves%route = curve_route(model)
      call first_of_each(curves, [block_periodic, block_antiperiodic], n, values, error)
   end subroutine root_values

   !> The first n curves of each block in `ids` (curves ascending in β), kind by kind; an
   !> error when a block has fewer.
   subroutine first_of_each(curves, ids, n, values, error)
      type(hill_boundary_t), intent(in) :: curves(:)
      integer, intent(in) :: ids(:), n
      type(hill_boundary_t), allocatable, intent(inout) :: values(:)
      type(error_t), allocatable, intent(out) :: error
      integer :: b, i, m, k
      deallocate (values)
      allocate (values(n*size(ids)))
      k = 0
      do b = 1, size(ids)
         m = 0
         do i = 1, size(curves)
            if (curves(i)%block /= ids(b) .or. m >= n) cycle
            m = m + 1
            k = k + 1
            values(k) = curves(i)
         end do
         if (m < n) then
            call set_error(error, err_accuracy, "characteristic values: only "//integer_text(m)//" of the "// &
               integer_text(n)//" values of one kind were found")
            deallocate (values)
            allocate (values(0))
            return
         end if
      end do
   end subroutine first_of_each
end module hillstab_curves_characteristic

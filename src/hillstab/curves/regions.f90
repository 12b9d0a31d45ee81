!> The resonance regions of a driven problem and the tip of each: the least drive at which it
!> opens and the frequency there, with its kind and its width at the top of the drive range.
!> Works on any stability oracle (hillstab_curves_oracle): a scalar model, an equation in
!> physical time, a system.
!>
!> **Predicted regions.** The natural frequencies ν_i(f) of the undriven problem (fractions of
!> the drive frequency) are sampled over the frequency range; every f where 2ν_i = k (simple,
!> multipliers near (−1)^k), ν_i + ν_j = k (sum) or |ν_i − ν_j| = k (difference), k = 1 …
!> `order`, is found by bisection and is a candidate region. Each region is searched inside
!> its window: from the midpoint to its neighbouring prediction on the left to the one on
!> the right (the range's ends for the outermost).
!>
!> **Tips.** With the critical drive c(f) the least drive of [d_min, d_max] where the oracle's
!> distance g (for a scalar model, the side (−1)^k of the region's family) is positive:
!> - undamped and an undriven coefficient constant in time: the tip is the resonance itself,
!>   at drive 0 (theory);
!> - otherwise c is found at the prediction by sampling the drive range and refining the first
!>   sign change (Illinois regula falsi); then Brent's minimisation over the window, each c(f)
!>   bracketed from the previous one (a few evaluations each), gives the tip. Its drive error
!>   is the root's error plus the spread of c over Brent's final bracket; its frequency error
!>   Brent's bracket. The tip is confirmed when the point just below it is stable and the one
!>   just above unstable, beyond the oracle's error.
!> - where the distance stays negative at d_max over the whole window (golden section on
!>   g(f, d_max)), the region is closed in the range (status `region_closed`): damping keeps
!>   it shut up to the top drive.
!>
!> A difference region of two modes whose Krein signatures agree (a system without gyroscopic
!> terms whose undriven, averaged stiffness is positive definite) is not searched: the two
!> multipliers pass each other on the circle, and the region stays closed (status
!> `region_same_signature`).
!>
!> **Width.** At d_max, the edges either side of the tip (the roots of g(f, d_max) stepping
!> out from the tip, or from the window's largest g(f, d_max) where the region bends away from
!> its tip's frequency); an edge that reaches the window's end is that end and flagged; both
!> are 0 where the region is not open at d_max.
module hillstab_curves_regions
   use hillstab_core_kinds, only: wp
   use hillstab_core_error, only: error_t, set_error, err_invalid_parameter
   use hillstab_core_status, only: status_ok
   use hillstab_core_text, only: real_text, integer_text
   use hillstab_curves_oracle, only: oracle_t, oracle_sample_t, scalar_oracle_t, system_oracle_t
   use hillstab_curves_region_search, only: search_t, evaluate, bracketed_root, peak_at, changes
   implicit none
   private
   public :: region_t, predict_regions, find_regions, region_kind_name, region_status_name
   public :: region_simple, region_sum, region_difference, region_unassigned
   public :: region_found, region_closed, region_unconfirmed, region_open_below, region_theory, region_same_signature, &
      region_uncovered
   public :: max_region_order
   public :: region_search, region_kind_text

   integer, parameter :: region_simple = 1      !! 2ν_i = k
   integer, parameter :: region_sum = 2         !! ν_i + ν_j = k
   integer, parameter :: region_difference = 3  !! |ν_i − ν_j| = k
   integer, parameter :: region_unassigned = 0  !! unstable at the top drive outside every predicted region

   integer, parameter :: region_found = 0        !! tip found and confirmed on both sides
   integer, parameter :: region_closed = 1       !! stable up to d_max over the whole window
   integer, parameter :: region_unconfirmed = 2  !! tip found, not confirmed (or at the window's end)
   integer, parameter :: region_open_below = 3   !! unstable already at d_min: the tip lies below the range
   integer, parameter :: region_theory = 4       !! undamped, constant undriven problem: the tip is the resonance at drive 0
   !> a difference region of two modes of equal Krein signature (no gyroscopic terms, the
   !> undriven stiffness positive definite): closed, its multipliers pass without leaving the circle
   integer, parameter :: region_same_signature = 5
   !> a stretch of the top drive unstable outside every predicted region's edges (kind
   !> region_unassigned): its edges there, its tip not searched
   integer, parameter :: region_uncovered = 6

   !> Highest order searched.
   integer, parameter :: max_region_order = 8
   !> Samples of the frequency range for the predictions.
   integer, parameter :: predict_samples = 400
   !> Samples of the top drive for instability outside every region (`find_regions`' cover).
   integer, parameter :: cover_samples = 1000

   !> One resonance region.
   type :: region_t
      integer :: kind = region_simple       !! region_simple, region_sum or region_difference
      integer :: order = 1                  !! k
      integer :: modes(2) = [1, 1]          !! i, j (i = j for a simple region)
      real(wp) :: predicted = 0.0_wp        !! f where the resonance holds at drive 0
      real(wp) :: window(2) = 0.0_wp        !! the frequencies searched
      real(wp) :: frequency = 0.0_wp        !! the tip's f
      real(wp) :: frequency_error = 0.0_wp  !! its error bound
      real(wp) :: drive = 0.0_wp            !! the tip's drive: the least at which the region is open
      real(wp) :: drive_error = 0.0_wp      !! its error bound
      real(wp) :: edges(2) = 0.0_wp         !! f of the region's edges at d_max (both 0 when not open there)
      logical :: clipped(2) = .false.       !! an edge is the window's end (the region is wider)
      integer :: status = region_found      !! region_found … region_theory
      integer :: evaluations = 0            !! distances computed (monodromies)
   end type region_t

   !> The natural frequencies at one sample of the frequency range.
   type :: nu_t
      real(wp), allocatable :: v(:)
   end type nu_t

   !> A least drive this near an end of the window (a fraction of its width) is on that end.
   real(wp), parameter :: edge_fraction = 1.0e-3_wp

   !> The "none" of c(f): stable up to d_max.
   real(wp), parameter :: none = huge(1.0_wp)

contains

   !> The name of a region kind.
   pure function region_kind_name(kind) result(name)
      integer, intent(in) :: kind  !! region_simple, region_sum or region_difference
      character(len=:), allocatable :: name
      select case (kind)
      case (region_simple)
         name = "simple"
      case (region_sum)
         name = "sum"
      case (region_difference)
         name = "difference"
      case (region_unassigned)
         name = "unassigned"
      case default
         name = "unknown"
      end select
   end function region_kind_name

   !> The name of a region status.
   pure function region_status_name(status) result(name)
      integer, intent(in) :: status  !! region_found … region_theory
      character(len=:), allocatable :: name
      select case (status)
      case (region_found)
         name = "found"
      case (region_closed)
         name = "closed"
      case (region_unconfirmed)
         name = "unconfirmed"
      case (region_open_below)
         name = "open below"
      case (region_theory)
         name = "theory"
      case (region_same_signature)
         name = "same signature"
      case (region_uncovered)
         name = "uncovered"
      case default
         name = "unknown"
      end select
   end function region_status_name

   !> Every resonance of order 1 … `order` whose frequency lies in [f_min, f_max], ascending in
   !> f, with its window (see the module's text); tips not yet searched.
   subroutine predict_regions(oracle, f_min, f_max, order, regions, error)
      class(oracle_t), intent(in) :: oracle   !! the problem
      real(wp), intent(in) :: f_min, f_max    !! the frequency range
      integer, intent(in) :: order            !! highest order k (1 … max_region_order)
      type(region_t), allocatable, intent(out) :: regions(:)  !! the candidates
      !> err_invalid_parameter naming the argument; a frequency the undriven problem fails at
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: f(predict_samples), left, right
      type(nu_t) :: nu(predict_samples)
      type(region_t) :: r
      real(wp), allocatable :: centres(:)
      integer :: j, k, i, m, kind, n_modes
      allocate (regions(0))
      if (order < 1 .or. order > max_region_order) then
         call set_error(error, err_invalid_parameter, "order: must be 1 to "//integer_text(max_region_order)// &
            ", got "//integer_text(order))
         return
      end if
      if (.not. (f_max > f_min)) then
         call set_error(error, err_invalid_parameter, "the frequency range is empty or not finite")
         return
      end if
      f = [(f_min + (f_max - f_min)*real(j - 1, wp)/real(predict_samples - 1, wp), j=1, predict_samples)]
      f(predict_samples) = f_max
      do j = 1, predict_samples
         call oracle%natural(f(j), nu(j)%v, error)
         if (allocated(error)) then
            error%message = "at "//real_text(f(j))//": "//error%message
            return
         end if
      end do
      n_modes = 0
      do j = 1, predict_samples
         n_modes = max(n_modes, size(nu(j)%v))
      end do
      do kind = region_simple, region_difference
         do k = 1, order
            do i = 1, n_modes
               do m = i, n_modes
                  if ((kind == region_simple) .neqv. (m == i)) cycle
                  do j = 1, predict_samples - 1
                     if (size(nu(j)%v) < m .or. size(nu(j + 1)%v) < m) cycle
                     if (changes(resonance(nu(j)%v, kind, k, i, m), resonance(nu(j + 1)%v, kind, k, i, m))) then
                        r = region_t(kind=kind, order=k, modes=[i, m])
                        call bisect_resonance(oracle, f(j), f(j + 1), r, error)
                        if (allocated(error)) return
                        regions = [regions, r]
                     end if
                  end do
               end do
            end do
         end do
      end do
      ! ascending, and the windows between neighbours
      call sort_regions(regions)
      centres = regions%predicted
      do j = 1, size(regions)
         left = f_min
         right = f_max
         do i = 1, size(centres)
            if (centres(i) < regions(j)%predicted) left = max(left, 0.5_wp*(centres(i) + regions(j)%predicted))
            if (centres(i) > regions(j)%predicted) right = min(right, 0.5_wp*(centres(i) + regions(j)%predicted))
         end do
         regions(j)%window = [left, right]
      end do
   end subroutine predict_regions

   !> The predicted regions (`predict_regions`) and, for each, its tip, its width at d_max and
   !> its status, searched on OpenMP threads (one region a thread).
   subroutine find_regions(oracle, f_min, f_max, d_min, d_max, order, tolerance, n_samples, regions, error, cover, &
                           swept)
      class(oracle_t), intent(in) :: oracle   !! the problem
      real(wp), intent(in) :: f_min, f_max    !! the frequency range
      real(wp), intent(in) :: d_min, d_max    !! the drive range
      integer, intent(in) :: order            !! highest order k
      real(wp), intent(in) :: tolerance       !! target of the tips, relative to max(1, |x|)
      integer, intent(in) :: n_samples        !! samples of the drive range for a first root (≥ 2)
      type(region_t), allocatable, intent(out) :: regions(:)  !! the regions, ascending in f
      !> err_invalid_parameter naming the argument; a point the method cannot compute
      type(error_t), allocatable, intent(out) :: error
      !> samples of the top drive for instability outside every region (`cover_top`; default
      !> 1000, 0 none)
      integer, intent(in), optional :: cover
      integer, intent(out), optional :: swept  !! distances the sweep computed
      character(len=300), allocatable :: failures(:)
      type(error_t), allocatable :: cause
      integer :: j, n_cover, n_swept
      n_cover = cover_samples
      if (present(cover)) n_cover = cover
      if (present(swept)) swept = 0
      if (n_cover /= 0 .and. (n_cover < 2 .or. n_cover > 100000)) then
         call set_error(error, err_invalid_parameter, "cover: must be 0 or 2 to 100000, got "//integer_text(n_cover))
         return
      end if
      if (.not. (d_max > d_min)) then
         call set_error(error, err_invalid_parameter, "the drive range is empty or not finite")
         return
      end if
      if (n_samples < 2 .or. n_samples > 100000) then
         call set_error(error, err_invalid_parameter, "n_samples: must be 2 to 100000, got "//integer_text(n_samples))
         return
      end if
      if (.not. (tolerance > 0.0_wp .and. tolerance < 1.0_wp)) then
         call set_error(error, err_invalid_parameter, "tolerance: must lie in (0, 1)")
         return
      end if
      call oracle%check(f_min, 0.0_wp, error)
      if (.not. allocated(error)) call oracle%check(f_max, 0.0_wp, error)
      if (allocated(error)) then
         error%message = "the undriven problem (drive 0) lies outside the domain: "//error%message
         return
      end if
      call oracle%check(f_min, d_min, error)
      if (.not. allocated(error)) call oracle%check(f_max, d_max, error)
      if (.not. allocated(error)) call oracle%check(f_min, d_max, error)
      if (.not. allocated(error)) call oracle%check(f_max, d_min, error)
      if (allocated(error)) return
      call predict_regions(oracle, f_min, f_max, order, regions, error)
      if (allocated(error)) return
      allocate (failures(size(regions)))
      failures = ""
      !$omp parallel do schedule(dynamic) default(shared) private(j, cause)
      do j = 1, size(regions)
         call search_region(oracle, d_min, d_max, tolerance, n_samples, regions(j), cause)
         if (allocated(cause)) failures(j) = cause%message
      end do
      !$omp end parallel do
      do j = 1, size(regions)
         if (len_trim(failures(j)) > 0) then
            call set_error(error, err_invalid_parameter, "the "//region_kind_name(regions(j)%kind)// &
               " region of order "//integer_text(regions(j)%order)//": "//trim(failures(j)))
            return
         end if
      end do
      if (n_cover == 0) return
      call cover_top(oracle, f_min, f_max, d_min, d_max, tolerance, n_cover, regions, n_swept, error)
      if (present(swept)) swept = n_swept
   end subroutine find_regions

   !> The top drive sampled at n frequencies on the problem's overall distance (those within a
   !> region's edges there skipped): each stretch of unstable samples that meets no region's
   !> edges is appended as a region of kind region_unassigned and status region_uncovered, its
   !> ends refined, so that no instability at the top of the range wider than the samples'
   !> spacing goes unreported, whatever drifted out of its window or lies beyond the order.
   subroutine cover_top(oracle, f_min, f_max, d_min, d_max, tolerance, n, regions, swept, error)
      class(oracle_t), intent(in) :: oracle
      real(wp), intent(in) :: f_min, f_max, d_min, d_max, tolerance
      integer, intent(in) :: n
      type(region_t), allocatable, intent(inout) :: regions(:)
      integer, intent(out) :: swept
      type(error_t), allocatable, intent(out) :: error
      type(oracle_sample_t) :: samples(n)
      type(search_t) :: s
      type(region_t) :: r
      character(len=300) :: failures(n)
      type(error_t), allocatable :: cause
      real(wp) :: f(n), step, x, x_error
      logical :: unstable(n), inside(n)
      integer :: j, first, last, k
      s = search_t(d_min=d_min, d_max=d_max, tolerance=tolerance, side=0, argument=-1.0_wp)
      step = (f_max - f_min)/real(n - 1, wp)
      f = [(f_min + step*real(j - 1, wp), j=1, n)]
      f(n) = f_max
      do j = 1, n
         inside(j) = any([(regions(k)%edges(2) > regions(k)%edges(1) .and. regions(k)%edges(1) <= f(j) .and. &
                           regions(k)%edges(2) >= f(j), k=1, size(regions))])
      end do
      swept = count(.not. inside)
      failures = ""
      !$omp parallel do schedule(dynamic) default(shared) private(j, cause)
      do j = 1, n
         if (inside(j)) then
            samples(j) = oracle_sample_t(g=-1.0_wp, bound=0.0_wp)
         else
            call oracle%distance(f(j), d_max, 0, -1.0_wp, samples(j), cause)
            if (allocated(cause)) failures(j) = cause%message
         end if
      end do
      !$omp end parallel do
      do j = 1, n
         if (len_trim(failures(j)) > 0) then
            call set_error(error, err_invalid_parameter, "the top drive at "//real_text(f(j))//": "//trim(failures(j)))
            return
         end if
      end do
      unstable = samples%g > samples%bound
      j = 1
      do while (j <= n)
         if (.not. unstable(j)) then
            j = j + 1
            cycle
         end if
         first = j
         do while (j < n)
            if (.not. unstable(j + 1)) exit
            j = j + 1
         end do
         last = j
         j = j + 1
         ! met by a region open at the top (one sample's spacing of slack)
         if (any([(regions(k)%edges(2) > regions(k)%edges(1) .and. regions(k)%edges(1) <= f(last) + step .and. &
                   regions(k)%edges(2) >= f(first) - step, k=1, size(regions))])) cycle
         r = region_t(kind=region_unassigned, order=0, modes=[0, 0], predicted=0.0_wp, &
                      window=[f(max(1, first - 1)), f(min(n, last + 1))], drive=d_max, &
                      status=region_uncovered, evaluations=last - first + 1)
         r%edges = [f(first), f(last)]
         r%clipped = [first == 1, last == n]
         if (first > 1) then
            call bracketed_root(oracle, s, .false., d_max, f(first - 1), f(first), samples(first - 1), &
                                samples(first), x, x_error, error)
            if (allocated(error)) return
            r%edges(1) = x
         end if
         if (last < n) then
            call bracketed_root(oracle, s, .false., d_max, f(last), f(last + 1), samples(last), samples(last + 1), &
                                x, x_error, error)
            if (allocated(error)) return
            r%edges(2) = x
         end if
         r%frequency = 0.5_wp*(r%edges(1) + r%edges(2))
         r%frequency_error = 0.5_wp*(r%edges(2) - r%edges(1))
         r%evaluations = r%evaluations + s%count
         s%count = 0
         regions = [regions, r]
      end do
   end subroutine cover_top

   !> The tip, width and status of one predicted region.
   subroutine search_region(oracle, d_min, d_max, tolerance, n_samples, r, error)
      class(oracle_t), intent(in) :: oracle
      real(wp), intent(in) :: d_min, d_max, tolerance
      integer, intent(in) :: n_samples
      type(region_t), intent(inout) :: r
      type(error_t), allocatable, intent(out) :: error
      type(search_t) :: s
      type(oracle_sample_t) :: top, below, above
      real(wp) :: f0, c0, c_error, f_error, e
      logical :: exact
      call region_search(oracle, r, d_min, d_max, tolerance, n_samples, s, error)
      if (allocated(error)) return
      call undriven_constant(oracle, r%predicted, exact)
      if (r%kind == region_difference .and. oracle%signatures_agree(r%predicted)) then
         r%status = region_same_signature
         r%frequency = r%predicted
         r%drive = d_max
         return
      end if
      if (.not. oracle%damped(r%predicted) .and. exact) then
         r%frequency = r%predicted
         r%frequency_error = 0.0_wp
         r%drive = 0.0_wp
         r%drive_error = 0.0_wp
         r%status = region_theory
      else
         f0 = r%predicted
         ! stable at the top drive there: no need to sample the drive range first
         call evaluate(oracle, s, f0, d_max, top, error)
         if (allocated(error)) return
         c0 = none
         if (top%g > 0.0_wp) then
            call first_critical(oracle, s, f0, c0, c_error, error)
            if (allocated(error)) return
         end if
         if (c0 == none) then
            ! closed at the prediction: is it open anywhere in the window at the top?
            call top_peak(oracle, s, r%window, f0, top, error)
            if (allocated(error)) return
            if (top%g <= 0.0_wp) then
               r%status = region_closed
               r%frequency = f0
               r%drive = d_max
               r%evaluations = s%count
               return
            end if
            ! open at the top from there to the window's nearer end: a neighbour's flank that
            ! reaches into the window; its least drive on that end, not confirmed as a tip
            e = r%window(merge(1, 2, f0 - r%window(1) <= r%window(2) - f0))
            call evaluate(oracle, s, e, d_max, top, error)
            if (allocated(error)) return
            if (top%g > 0.0_wp) then
               call first_critical(oracle, s, e, c0, c_error, error)
               if (allocated(error)) return
               r%frequency = e
               r%frequency_error = 0.0_wp
               r%drive = c0
               r%drive_error = c_error
               r%status = region_unconfirmed
               call top_edges(oracle, s, r, error)
               r%evaluations = s%count
               return
            end if
            call first_critical(oracle, s, f0, c0, c_error, error)
            if (allocated(error)) return
         end if
         call minimise_critical(oracle, s, r%window, f0, c0, c_error, f_error, error)
         if (allocated(error)) return
         r%frequency = f0
         r%frequency_error = f_error
         r%drive = c0
         r%drive_error = c_error
         if (c0 <= d_min) then
            r%status = region_open_below
         else
            call oracle%distance(f0, max(d_min, c0 - 2.0_wp*c_error), s%side, s%argument, below, error)
            if (allocated(error)) return
            call oracle%distance(f0, min(d_max, c0 + 2.0_wp*c_error), s%side, s%argument, above, error)
            if (allocated(error)) return
            s%count = s%count + 2
            r%status = region_unconfirmed
            if (below%g < -below%bound .and. above%g > above%bound) r%status = region_found
            ! a least drive on the window's end is no tip of this region but a neighbour's flank
            if (f0 - r%window(1) <= edge_fraction*(r%window(2) - r%window(1)) .or. &
                r%window(2) - f0 <= edge_fraction*(r%window(2) - r%window(1))) r%status = region_unconfirmed
         end if
      end if
      call top_edges(oracle, s, r, error)
      r%evaluations = s%count
   end subroutine search_region

   !> A search of region r: the ranges and the family of tongues its distance follows (a
   !> scalar model's side (−1)^k, a system's multipliers' argument at the resonance).
   subroutine region_search(oracle, r, d_min, d_max, tolerance, n_samples, s, error)
      class(oracle_t), intent(in) :: oracle      !! the problem
      type(region_t), intent(in) :: r            !! a predicted region
      real(wp), intent(in) :: d_min, d_max       !! the drive range
      real(wp), intent(in) :: tolerance          !! target of roots, relative to max(1, |x|)
      integer, intent(in) :: n_samples           !! samples of the drive range for a first root
      type(search_t), intent(out) :: s           !! the search, no distance computed yet
      type(error_t), allocatable, intent(out) :: error  !! the undriven problem cannot be computed
      s = search_t(d_min=d_min, d_max=d_max, tolerance=tolerance, n_samples=n_samples)
      if (oracle_is_scalar(oracle)) then
         s%side = merge(1, -1, mod(r%order, 2) == 0)
      else
         call family_argument(oracle, r, s%argument, error)
      end if
   end subroutine region_search

   !> A region's resonance as text: "2 w1 = 1 Om" style, the frequency named `frequency`.
   function region_kind_text(r, frequency) result(text)
      type(region_t), intent(in) :: r                !! the region
      character(len=*), intent(in) :: frequency      !! the frequency's name
      character(len=:), allocatable :: text
      character(len=:), allocatable :: k
      k = integer_text(r%order)
      select case (r%kind)
      case (region_simple)
         text = "2 w"//integer_text(r%modes(1))//" = "//k//" "//frequency
      case (region_sum)
         text = "w"//integer_text(r%modes(1))//" + w"//integer_text(r%modes(2))//" = "//k//" "//frequency
      case (region_difference)
         text = "w"//integer_text(r%modes(2))//" - w"//integer_text(r%modes(1))//" = "//k//" "//frequency
      case default
         text = "unassigned"
      end select
   end function region_kind_text

   !> The argument/π, folded into [0, 1], of the multipliers at which a system's region sets
   !> in: 2ν_i at its resonance (k mod 2 for a simple region; the common argument of the two
   !> colliding multipliers of a combination region).
   subroutine family_argument(oracle, r, argument, error)
      class(oracle_t), intent(in) :: oracle
      type(region_t), intent(in) :: r
      real(wp), intent(out) :: argument
      type(error_t), allocatable, intent(out) :: error
      real(wp), allocatable :: nu(:)
      argument = -1.0_wp
      if (r%kind == region_simple) then
         argument = real(mod(r%order, 2), wp)
         return
      end if
      call oracle%natural(r%predicted, nu, error)
      if (allocated(error) .or. size(nu) < r%modes(1)) return
      argument = modulo(2.0_wp*nu(r%modes(1)), 2.0_wp)
      if (argument > 1.0_wp) argument = 2.0_wp - argument
   end subroutine family_argument

   !> Whether the oracle is a scalar model (its two families searched apart).
   logical function oracle_is_scalar(oracle)
      class(oracle_t), intent(in) :: oracle
      select type (oracle)
      type is (scalar_oracle_t)
         oracle_is_scalar = .true.
      class default
         oracle_is_scalar = .false.
      end select
   end function oracle_is_scalar

   !> Whether the undriven problem at f is constant in time (its resonances then exact).
   subroutine undriven_constant(oracle, f, exact)
      class(oracle_t), intent(in) :: oracle
      real(wp), intent(in) :: f
      logical, intent(out) :: exact
      integer, parameter :: nodes = 64
      real(wp) :: alpha, beta, tau, q(nodes), scale
      real(wp), allocatable :: p(:, :), b(:, :), k0(:, :)
      integer :: j, n
      call oracle%coordinates(f, 0.0_wp, alpha, beta)
      exact = .false.
      select type (oracle)
      type is (scalar_oracle_t)
         q = oracle%model%coefficient(alpha, beta, [(oracle%model%period()*real(j - 1, wp)/nodes, j=1, nodes)])
         exact = maxval(q) - minval(q) <= 64.0_wp*epsilon(1.0_wp)*max(1.0_wp, maxval(abs(q)))
      type is (system_oracle_t)
         n = oracle%system%dof()
         allocate (p(n, n), b(n, n), k0(n, n))
         call oracle%system%stiffness(alpha, 0.0_wp, p, b)
         k0 = p + beta*b
         scale = max(1.0_wp, maxval(abs(k0)))
         exact = .true.
         do j = 2, nodes
            tau = oracle%system%period()*real(j - 1, wp)/nodes
            call oracle%system%stiffness(alpha, tau, p, b)
            if (maxval(abs(p + beta*b - k0)) > 64.0_wp*epsilon(1.0_wp)*scale) exact = .false.
         end do
      end select
   end subroutine undriven_constant

   !> The value whose sign change marks a resonance of the given kind and order.
   pure real(wp) function resonance(nu, kind, k, i, m)
      real(wp), intent(in) :: nu(:)
      integer, intent(in) :: kind, k, i, m
      select case (kind)
      case (region_simple)
         resonance = 2.0_wp*nu(i) - real(k, wp)
      case (region_sum)
         resonance = nu(i) + nu(m) - real(k, wp)
      case default
         resonance = abs(nu(m) - nu(i)) - real(k, wp)
      end select
   end function resonance

   !> The resonance of r between a and b by bisection (to round-off).
   subroutine bisect_resonance(oracle, a0, b0, r, error)
      class(oracle_t), intent(in) :: oracle
      real(wp), intent(in) :: a0, b0
      type(region_t), intent(inout) :: r
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: a, b, c, ra, rc
      real(wp), allocatable :: nu(:)
      integer :: iteration
      a = a0
      b = b0
      call oracle%natural(a, nu, error)
      if (allocated(error)) return
      ra = resonance(nu, r%kind, r%order, r%modes(1), r%modes(2))
      do iteration = 1, 100
         c = 0.5_wp*(a + b)
         if (c <= a .or. c >= b) exit
         call oracle%natural(c, nu, error)
         if (allocated(error)) return
         if (size(nu) < r%modes(2)) exit
         rc = resonance(nu, r%kind, r%order, r%modes(1), r%modes(2))
         if (changes(ra, rc)) then
            b = c
         else
            a = c
            ra = rc
         end if
      end do
      r%predicted = 0.5_wp*(a + b)
   end subroutine bisect_resonance

   !> The least drive where the distance is positive at f, by sampling the drive range and
   !> refining the first change; `none` when it stays negative up to d_max.
   subroutine first_critical(oracle, s, f, c, c_error, error)
      class(oracle_t), intent(in) :: oracle
      type(search_t), intent(inout) :: s
      real(wp), intent(in) :: f
      real(wp), intent(out) :: c, c_error
      type(error_t), allocatable, intent(out) :: error
      type(oracle_sample_t) :: previous, current
      real(wp) :: d, d_previous
      integer :: j
      c = none
      c_error = 0.0_wp
      do j = 1, s%n_samples
         d = s%d_min + (s%d_max - s%d_min)*real(j - 1, wp)/real(s%n_samples - 1, wp)
         if (j == s%n_samples) d = s%d_max
         call evaluate(oracle, s, f, d, current, error)
         if (allocated(error)) return
         if (current%g > 0.0_wp) then
            if (j == 1) then
               c = s%d_min
               return
            end if
            call drive_root(oracle, s, f, d_previous, d, previous, current, c, c_error, error)
            return
         end if
         previous = current
         d_previous = d
      end do
   end subroutine first_critical

   !> c(f) from a nearby value c_near: bracketed by steps growing fourfold, then refined;
   !> `none` when stable up to d_max, d_min when unstable there already.
   subroutine next_critical(oracle, s, f, c_near, c, c_error, error)
      class(oracle_t), intent(in) :: oracle
      type(search_t), intent(inout) :: s
      real(wp), intent(in) :: f, c_near
      real(wp), intent(out) :: c, c_error
      type(error_t), allocatable, intent(out) :: error
      type(oracle_sample_t) :: s0, s1
      real(wp) :: d0, d1, h
      integer :: iteration
      c_error = 0.0_wp
      d0 = min(max(c_near, s%d_min), s%d_max)
      call evaluate(oracle, s, f, d0, s0, error)
      if (allocated(error)) return
      h = max(1.0e-3_wp*abs(d0), 1.0e-6_wp*(s%d_max - s%d_min))
      ! the last root's slope predicts this one: the first step goes a little beyond it
      if (s%slope > 0.0_wp) then
         if (abs(s0%g) < s%slope*(s%d_max - s%d_min)) then
            h = max(h, 1.2_wp*abs(s0%g)/s%slope)
         else
            h = s%d_max - s%d_min
         end if
      end if
      do iteration = 1, 200
         if (s0%g > 0.0_wp) then
            d1 = max(s%d_min, d0 - h)
         else
            d1 = min(s%d_max, d0 + h)
         end if
         call evaluate(oracle, s, f, d1, s1, error)
         if (allocated(error)) return
         if (changes(s0%g, s1%g) .or. (s1%g == 0.0_wp .neqv. s0%g == 0.0_wp)) then
            if (d1 < d0) then
               call drive_root(oracle, s, f, d1, d0, s1, s0, c, c_error, error)
            else
               call drive_root(oracle, s, f, d0, d1, s0, s1, c, c_error, error)
            end if
            return
         end if
         if (d1 <= s%d_min .and. s1%g > 0.0_wp) then
            c = s%d_min
            return
         end if
         if (d1 >= s%d_max .and. s1%g <= 0.0_wp) then
            c = none
            return
         end if
         d0 = d1
         s0 = s1
         h = 4.0_wp*h
      end do
      c = none
   end subroutine next_critical

   !> The root of the distance in the drive between a (stable, g ≤ 0) and b (g > 0) at f.
   subroutine drive_root(oracle, s, f, a, b, sa, sb, c, c_error, error)
      class(oracle_t), intent(in) :: oracle
      type(search_t), intent(inout) :: s
      real(wp), intent(in) :: f, a, b
      type(oracle_sample_t), intent(in) :: sa, sb
      real(wp), intent(out) :: c, c_error
      type(error_t), allocatable, intent(out) :: error
      call bracketed_root(oracle, s, .true., f, a, b, sa, sb, c, c_error, error)
   end subroutine drive_root

   !> Golden-section search of the window for the largest distance at d_max, starting at f.
   subroutine top_peak(oracle, s, window, f, peak, error)
      class(oracle_t), intent(in) :: oracle
      type(search_t), intent(inout) :: s
      real(wp), intent(in) :: window(2)
      real(wp), intent(inout) :: f
      type(oracle_sample_t), intent(out) :: peak
      type(error_t), allocatable, intent(out) :: error
      ! a region open at the top only within 1e-4 of the window around the peak has its tip
      ! within about (1e-4)² of the top drive (its width grows as the root of the drive's
      ! excess over the tip): closed up to the top, to that
      call peak_at(oracle, s, window, s%d_max, 1.0e-4_wp, f, peak, error)
   end subroutine top_peak

   !> Brent's minimisation of c(f) over the window from f (c(f) = c): the tip's f and c, the
   !> error of c (the root's plus the spread of c over the final bracket) and of f (the
   !> bracket).
   subroutine minimise_critical(oracle, s, window, f, c, c_error, f_error, error)
      class(oracle_t), intent(in) :: oracle
      type(search_t), intent(inout) :: s
      real(wp), intent(in) :: window(2)
      real(wp), intent(inout) :: f, c, c_error
      real(wp), intent(out) :: f_error
      type(error_t), allocatable, intent(out) :: error
      real(wp), parameter :: golden = 0.3819660112501051_wp
      real(wp) :: a, b, v, w, x, fv, fw, fx, d, e, u, fu, tol1, tol2, xm, p, q, rr, eu, ex
      integer :: iteration
      a = window(1)
      b = window(2)
      x = min(max(f, a), b)
      fx = c
      ex = c_error
      v = x
      w = x
      fv = fx
      fw = fx
      d = 0.0_wp
      e = 0.0_wp
      do iteration = 1, 100
         xm = 0.5_wp*(a + b)
         tol1 = 1.0e-2_wp*sqrt(s%tolerance)*abs(x) + 1.0e-12_wp*(window(2) - window(1))
         tol2 = 2.0_wp*tol1
         if (abs(x - xm) <= tol2 - 0.5_wp*(b - a)) exit
         ! the least drive on the window's end: a neighbour's flank (search_region marks it
         ! unconfirmed), not worth converging on
         if (min(x - window(1), window(2) - x) <= edge_fraction*(window(2) - window(1))) exit
         ! the three best points' parabola dips no deeper below the best value than its error
         if (iteration > 3 .and. parabola_gap(x, w, v, fx, fw, fv) <= ex) exit
         if (abs(e) > tol1 .and. max(abs(fx), abs(fv), abs(fw)) < none) then
            rr = (x - w)*(fx - fv)
            q = (x - v)*(fx - fw)
            p = (x - v)*q - (x - w)*rr
            q = 2.0_wp*(q - rr)
            if (q > 0.0_wp) p = -p
            q = abs(q)
            rr = e
            e = d
            if (abs(p) >= abs(0.5_wp*q*rr) .or. p <= q*(a - x) .or. p >= q*(b - x)) then
               e = merge(a - x, b - x, x >= xm)
               d = golden*e
            else
               d = p/q
               u = x + d
               if (u - a < tol2 .or. b - u < tol2) d = sign(tol1, xm - x)
            end if
         else
            e = merge(a - x, b - x, x >= xm)
            d = golden*e
         end if
         u = x + merge(d, sign(tol1, d), abs(d) >= tol1)
         ! c(u) above the best c(x) need not be refined further than that
         s%stop_above = fx
         call next_critical(oracle, s, u, merge(fx, s%d_max, fx < none), fu, eu, error)
         s%stop_above = huge(1.0_wp)
         if (allocated(error)) return
         if (fu <= fx) then
            if (u >= x) then
               a = x
            else
               b = x
            end if
            v = w
            fv = fw
            w = x
            fw = fx
            x = u
            fx = fu
            ex = eu
         else
            if (u < x) then
               a = u
            else
               b = u
            end if
            if (fu <= fw .or. w == x) then
               v = w
               fv = fw
               w = u
               fw = fu
            else if (fu <= fv .or. v == x .or. v == w) then
               v = u
               fv = fu
            end if
         end if
      end do
      f = x
      c = fx
      f_error = max(0.5_wp*(b - a), 4.0_wp*spacing(abs(x)))
      c_error = ex + parabola_gap(x, w, v, fx, fw, fv)
   end subroutine minimise_critical

   !> How far below the best value fx the minimum may lie: the depth of the vertex of the
   !> parabola through the three best points below fx, or (no parabola) the spread of c
   !> over them.
   pure real(wp) function parabola_gap(x, w, v, fx, fw, fv) result(gap)
      real(wp), intent(in) :: x, w, v, fx, fw, fv
      real(wp) :: p, q, curvature
      gap = huge(1.0_wp)
      if (.not. (max(fv, fw) < none)) return
      gap = max(fv, fw) - fx
      if (w == x .or. v == x .or. v == w) return
      p = (x - w)*(fx - fv) - (x - v)*(fx - fw)
      q = (x - w)**2*(fx - fv) - (x - v)**2*(fx - fw)
      if (.not. (abs(p) > 0.0_wp)) return
      ! the vertex lies q/(2p) from x; its depth is the curvature times that squared
      curvature = ((fw - fx)/(w - x) - (fv - fx)/(v - x))/(w - v)
      if (curvature > 0.0_wp) gap = min(gap, curvature*(0.5_wp*q/p)**2)
   end function parabola_gap

   !> The region's edges at d_max, stepping out from its tip (see the module's text).
   subroutine top_edges(oracle, s, r, error)
      class(oracle_t), intent(in) :: oracle
      type(search_t), intent(inout) :: s
      type(region_t), intent(inout) :: r
      type(error_t), allocatable, intent(out) :: error
      type(oracle_sample_t) :: tip, inside, current
      real(wp) :: x0, x1, h, edge, edge_error, start
      integer :: direction, iteration
      r%edges = 0.0_wp
      start = r%frequency
      call evaluate(oracle, s, start, s%d_max, tip, error)
      if (allocated(error)) return
      if (.not. (tip%g > 0.0_wp)) then
         ! the region bends away from its tip's frequency: open elsewhere in the window?
         call top_peak(oracle, s, r%window, start, tip, error)
         if (allocated(error) .or. .not. (tip%g > 0.0_wp)) return
      end if
      do direction = 1, 2
         inside = tip
         x0 = start
         h = 1.0e-2_wp*(r%window(2) - r%window(1))
         r%clipped(direction) = .true.
         edge = r%window(direction)
         do iteration = 1, 100
            if (direction == 1) then
               x1 = max(r%window(1), x0 - h)
            else
               x1 = min(r%window(2), x0 + h)
            end if
            call evaluate(oracle, s, x1, s%d_max, current, error)
            if (allocated(error)) return
            if (.not. (current%g > 0.0_wp)) then
               if (direction == 1) then
                  call bracketed_root(oracle, s, .false., s%d_max, x1, x0, current, inside, edge, edge_error, error)
               else
                  call bracketed_root(oracle, s, .false., s%d_max, x0, x1, inside, current, edge, edge_error, error)
               end if
               if (allocated(error)) return
               r%clipped(direction) = .false.
               exit
            end if
            if (x1 == r%window(direction)) exit
            x0 = x1
            inside = current
            h = 2.0_wp*h
         end do
         r%edges(direction) = edge
      end do
   end subroutine top_edges

   !> Regions ascending in their predicted f (insertion).
   pure subroutine sort_regions(regions)
      type(region_t), intent(inout) :: regions(:)
      type(region_t) :: t
      integer :: i, j
      do i = 2, size(regions)
         t = regions(i)
         j = i - 1
         do while (j >= 1)
            if (regions(j)%predicted <= t%predicted) exit
            regions(j + 1) = regions(j)
            j = j - 1
         end do
         regions(j + 1) = t
      end do
   end subroutine sort_regions
end module hillstab_curves_regions

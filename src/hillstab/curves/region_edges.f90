!> The boundaries of the resonance regions in the problem's own plane (frequency f, drive d),
!> by continuation from each region's tip (hillstab_curves_regions).
!>
!> From the tip (f₀, c) up to the top of the drive range, at drive levels d_j = c + (d_max −
!> c)(j/L)², j = 1 … L (closer near the tip, where the edges open as √(d − c)), each region's
!> two edges are found on the distance of its own family of tongues (a scalar model's side
!> (−1)^k, a system's multipliers at the resonance's argument): from a point inside the region
!> at d_j (the middle of the previous level's edges, or the tip's frequency, or a previous
!> edge), the search steps outward from the previous level's edge, doubling its step, until
!> the distance changes sign, and refines the change (Illinois regula falsi to the tolerance,
!> the error bound the bracket's or the distance's error over its slope). The steps never
!> leave the frequency range: an edge beyond it is marked at the range's end.
!>
!> Every edge point is then checked on both sides, at twice its error bound: inside, the
!> family's distance beyond its error (unstable); outside, the problem's overall distance
!> (every family) below minus its error (stable). A point that passes is a stability boundary
!> (`edge_boundary`); one whose outside is unstable too (beyond the square root of the
!> distance's error, the error of a multiplier's modulus near a collision) lies between two
!> unstable kinds, an overlap with another region (`edge_overlap`), and is no stability
!> boundary; one that cannot be told either way is `edge_unconfirmed`. A region that closes again below the top
!> (no point inside at a level) ends there.
module hillstab_curves_region_edges
   use hillstab_core_kinds, only: wp
   use hillstab_core_error, only: error_t, set_error, err_invalid_parameter
   use hillstab_core_text, only: integer_text
   use hillstab_curves_oracle, only: oracle_t, oracle_sample_t
   use hillstab_curves_regions, only: region_t, region_search, region_found, region_theory, region_open_below, &
      region_kind_name
   use hillstab_curves_region_search, only: search_t, evaluate, bracketed_root, peak_at
   implicit none
   private
   public :: edge_point_t, trace_edges, edge_status_name, max_edge_levels
   public :: edge_boundary, edge_overlap, edge_unconfirmed, edge_range_end, edge_tip

   integer, parameter :: edge_boundary = 0     !! stable outside, unstable inside: a stability boundary
   integer, parameter :: edge_overlap = 1      !! unstable on both sides: another region overlaps this one
   integer, parameter :: edge_unconfirmed = 2  !! neither side told beyond the distance's error
   integer, parameter :: edge_range_end = 3    !! still inside at the frequency range's end
   integer, parameter :: edge_tip = 4          !! the region's tip, where its two edges meet

   !> Most drive levels a region's edges are traced at.
   integer, parameter :: max_edge_levels = 10000

   !> One point of a region's boundary.
   type :: edge_point_t
      integer :: region = 0                 !! the region's index in the regions given
      integer :: branch = 0                 !! −1 the lower edge in f, +1 the upper, 0 the tip
      real(wp) :: frequency = 0.0_wp        !! f
      real(wp) :: frequency_error = 0.0_wp  !! its error bound
      real(wp) :: drive = 0.0_wp            !! d (exact: the level)
      integer :: status = edge_boundary     !! edge_boundary … edge_tip
      integer :: evaluations = 0            !! distances computed for this point
   end type edge_point_t

   !> One region's points, as found.
   type :: edge_list_t
      type(edge_point_t), allocatable :: p(:)
   end type edge_list_t

contains

   !> The name of an edge point's status.
   pure function edge_status_name(status) result(name)
      integer, intent(in) :: status  !! edge_boundary … edge_tip
      character(len=:), allocatable :: name
      select case (status)
      case (edge_boundary)
         name = "boundary"
      case (edge_overlap)
         name = "overlap"
      case (edge_unconfirmed)
         name = "unconfirmed"
      case (edge_range_end)
         name = "range end"
      case (edge_tip)
         name = "tip"
      case default
         name = "unknown"
      end select
   end function edge_status_name

   !> The boundary of every region whose tip is known (found, by theory, or open below the
   !> range; not closed, unconfirmed, of equal signature or uncovered), traced from its tip at `levels` drive levels (see the module's text); the
   !> points of a region run from its lower edge at the top down to the tip and up its upper
   !> edge, regions in the order given.
   subroutine trace_edges(oracle, regions, f_min, f_max, d_min, d_max, tolerance, levels, points, error)
      class(oracle_t), intent(in) :: oracle        !! the problem
      type(region_t), intent(in) :: regions(:)     !! its regions with their tips (find_regions)
      real(wp), intent(in) :: f_min, f_max         !! the frequency range
      real(wp), intent(in) :: d_min, d_max         !! the drive range
      real(wp), intent(in) :: tolerance            !! target of the edges, relative to max(1, |f|)
      integer, intent(in) :: levels                !! drive levels above each tip, 1 … max_edge_levels
      type(edge_point_t), allocatable, intent(out) :: points(:)  !! the boundary points
      !> err_invalid_parameter naming the argument or the region whose distance failed
      type(error_t), allocatable, intent(out) :: error
      type(edge_list_t), allocatable :: lists(:)
      character(len=300), allocatable :: failures(:)
      type(error_t), allocatable :: cause
      integer :: j, n
      if (levels < 1 .or. levels > max_edge_levels) then
         call set_error(error, err_invalid_parameter, "levels: must be 1 to "//integer_text(max_edge_levels)// &
                        ", got "//integer_text(levels))
         return
      end if
      if (.not. (f_max > f_min .and. d_max > d_min)) then
         call set_error(error, err_invalid_parameter, "the frequency or drive range is empty or not finite")
         return
      end if
      allocate (lists(size(regions)), failures(size(regions)))
      failures = ""
      !$omp parallel do schedule(dynamic) default(shared) private(j, cause)
      do j = 1, size(regions)
         call trace_region(oracle, regions(j), j, f_min, f_max, d_min, d_max, tolerance, levels, lists(j)%p, cause)
         if (allocated(cause)) failures(j) = cause%message
      end do
      !$omp end parallel do
      n = 0
      do j = 1, size(regions)
         if (len_trim(failures(j)) > 0) then
            call set_error(error, err_invalid_parameter, "the edges of the "//region_kind_name(regions(j)%kind)// &
                           " region of order "//integer_text(regions(j)%order)//": "//trim(failures(j)))
            return
         end if
         n = n + size(lists(j)%p)
      end do
      allocate (points(n))
      n = 0
      do j = 1, size(regions)
         points(n + 1:n + size(lists(j)%p)) = lists(j)%p
         n = n + size(lists(j)%p)
      end do
   end subroutine trace_edges

   !> One region's boundary points (none when it does not open in the range).
   subroutine trace_region(oracle, r, index, f_min, f_max, d_min, d_max, tolerance, levels, points, error)
      class(oracle_t), intent(in) :: oracle
      type(region_t), intent(in) :: r
      integer, intent(in) :: index, levels
      real(wp), intent(in) :: f_min, f_max, d_min, d_max, tolerance
      type(edge_point_t), allocatable, intent(out) :: points(:)
      type(error_t), allocatable, intent(out) :: error
      type(search_t) :: s
      type(edge_point_t) :: low(levels), high(levels), tip
      type(oracle_sample_t) :: sample
      real(wp) :: c, d, previous(2), before(2), inside, candidates(4), span, near(2)
      integer :: j, k, n, count0
      logical :: found
      allocate (points(0))
      if (.not. (r%status == region_found .or. r%status == region_theory .or. r%status == region_open_below)) return
      call region_search(oracle, r, d_min, d_max, tolerance, 32, s, error)
      if (allocated(error)) return
      c = min(max(r%drive, d_min), d_max)
      tip = edge_point_t(region=index, branch=0, frequency=r%frequency, frequency_error=r%frequency_error, &
                         drive=c, status=edge_tip)
      ! open already at the lowest drive: the curve starts at the range's end, no tip
      if (r%drive < d_min .or. r%status == region_open_below) tip%status = edge_range_end
      previous = r%frequency
      before = r%frequency
      n = 0
      do j = 1, levels
         count0 = s%count
         d = c + (d_max - c)*(real(j, wp)/real(levels, wp))**2
         if (j == levels) d = d_max
         if (.not. (d > c)) exit
         ! a point inside the region at this level: a guess, else the largest distance near
         ! the previous level's edges, else over the window
         candidates = [0.5_wp*(previous(1) + previous(2)), r%frequency, previous(1), previous(2)]
         found = .false.
         do k = 1, size(candidates)
            call evaluate(oracle, s, candidates(k), d, sample, error)
            if (allocated(error)) return
            if (sample%g > 0.0_wp) then
               found = .true.
               inside = candidates(k)
               exit
            end if
         end do
         if (.not. found) then
            span = max(previous(2) - previous(1), 1.0e-2_wp*(r%window(2) - r%window(1)))
            near = [max(f_min, previous(1) - span), min(f_max, previous(2) + span)]
            call peak_at(oracle, s, near, d, 1.0e-6_wp, inside, sample, error)
            if (allocated(error)) return
            if (.not. (sample%g > 0.0_wp)) then
               call peak_at(oracle, s, [max(f_min, r%window(1)), min(f_max, r%window(2))], d, 1.0e-6_wp, inside, &
                            sample, error)
               if (allocated(error)) return
            end if
            ! too narrow to find at this level, or closed again: the next level
            if (.not. (sample%g > 0.0_wp)) cycle
         end if
         n = n + 1
         call edge_at(oracle, s, r, f_min, f_max, d, inside, previous(1), before(1), -1, low(n), error)
         if (allocated(error)) return
         low(n)%evaluations = s%count - count0
         count0 = s%count
         call edge_at(oracle, s, r, f_min, f_max, d, inside, previous(2), before(2), 1, high(n), error)
         if (allocated(error)) return
         low(n)%region = index
         high(n)%region = index
         before = previous
         previous = [low(n)%frequency, high(n)%frequency]
      end do
      points = [low(n:1:-1), tip, high(1:n)]
   end subroutine trace_region

   !> The edge on one side (`direction` −1 lower, +1 upper) at drive d, from the point `inside`
   !> (distance positive there), stepping outward from the previous level's edge; checked on
   !> both sides.
   subroutine edge_at(oracle, s, r, f_min, f_max, d, inside, previous, before, direction, point, error)
      class(oracle_t), intent(in) :: oracle
      type(search_t), intent(inout) :: s
      type(region_t), intent(in) :: r
      real(wp), intent(in) :: f_min, f_max, d, inside, previous, before
      integer, intent(in) :: direction
      type(edge_point_t), intent(out) :: point
      type(error_t), allocatable, intent(out) :: error
      type(oracle_sample_t) :: s_in, s_out, current
      real(wp) :: x_in, x_out, h, x, x_error, limit, width, step_cap
      integer :: count0, iteration
      count0 = s%count
      point = edge_point_t(branch=direction, drive=d)
      limit = merge(f_min, f_max, direction < 0)
      width = r%window(2) - r%window(1)
      if (.not. (width > 0.0_wp)) width = f_max - f_min
      step_cap = 0.05_wp*width
      x_in = inside
      call evaluate(oracle, s, x_in, d, s_in, error)
      if (allocated(error)) return
      ! the previous edge, when it lies outward of `inside`, is the first step
      h = max(2.0_wp*abs(previous - before), 1.0e-3_wp*width, 64.0_wp*s%tolerance*max(1.0_wp, abs(inside)))
      h = min(h, step_cap)
      x_out = x_in + direction*h
      if (direction*(previous - x_in) > 0.0_wp) x_out = previous
      do iteration = 1, 200
         if (direction*(x_out - limit) >= 0.0_wp) x_out = limit
         call evaluate(oracle, s, x_out, d, s_out, error)
         if (allocated(error)) return
         if (.not. (s_out%g > 0.0_wp)) exit
         if (x_out == limit) then
            point%frequency = limit
            point%frequency_error = 0.0_wp
            point%status = edge_range_end
            point%evaluations = s%count - count0
            return
         end if
         x_in = x_out
         s_in = s_out
         x_out = x_in + direction*h
         h = min(2.0_wp*h, step_cap)
      end do
      if (s_out%g > 0.0_wp) then
         call set_error(error, err_invalid_parameter, "no edge found stepping out from the region")
         return
      end if
      if (direction < 0) then
         call bracketed_root(oracle, s, .false., d, x_out, x_in, s_out, s_in, x, x_error, error)
      else
         call bracketed_root(oracle, s, .false., d, x_in, x_out, s_in, s_out, x, x_error, error)
      end if
      if (allocated(error)) return
      point%frequency = x
      point%frequency_error = x_error
      ! checked on both sides: the family unstable inside, the problem stable outside
      call evaluate(oracle, s, x - direction*2.0_wp*x_error, d, s_in, error)
      if (allocated(error)) return
      call overall(oracle, s, x + direction*2.0_wp*x_error, d, current, error)
      if (allocated(error)) return
      ! an overlap needs more than the distance's error: near a collision of multipliers their
      ! moduli carry the square root of the monodromy's error
      point%status = edge_unconfirmed
      if (s_in%g > s_in%bound) then
         if (current%g < -current%bound) then
            point%status = edge_boundary
         else if (current%g > max(current%bound, sqrt(current%bound))) then
            point%status = edge_overlap
         end if
      end if
      point%evaluations = s%count - count0
   end subroutine edge_at

   !> The problem's distance from stability over every family at (f, d).
   subroutine overall(oracle, s, f, d, sample, error)
      class(oracle_t), intent(in) :: oracle
      type(search_t), intent(inout) :: s
      real(wp), intent(in) :: f, d
      type(oracle_sample_t), intent(out) :: sample
      type(error_t), allocatable, intent(out) :: error
      type(search_t) :: any_family
      any_family = s
      any_family%side = 0
      any_family%argument = -1.0_wp
      call evaluate(oracle, any_family, f, d, sample, error)
      s%count = any_family%count
   end subroutine overall
end module hillstab_curves_region_edges

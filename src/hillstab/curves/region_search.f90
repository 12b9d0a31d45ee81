!> The searches of the resonance regions (hillstab_curves_regions) and of their edges
!> (hillstab_curves_region_edges) on a stability oracle: one evaluation of the distance
!> counted, the root of the distance along either coordinate (Illinois regula falsi with
!> its error bound), and the golden-section search for the largest distance along the
!> frequency at one drive.
module hillstab_curves_region_search
   use hillstab_core_kinds, only: wp
   use hillstab_core_error, only: error_t
   use hillstab_core_text, only: real_text
   use hillstab_curves_oracle, only: oracle_t, oracle_sample_t
   implicit none
   private
   public :: search_t, evaluate, bracketed_root, peak_at, changes

   !> A search: the oracle, the ranges and the side of the family.
   type :: search_t
      real(wp) :: d_min = 0.0_wp, d_max = 1.0_wp  !! the drive range
      real(wp) :: tolerance = 1.0e-10_wp          !! target of roots, relative to max(1, |x|)
      integer :: side = 0                         !! scalar models' family: ±1; 0 either
      real(wp) :: argument = -1.0_wp              !! systems' family: the multipliers' argument/π
      integer :: n_samples = 32                   !! samples of the drive range for the first root
      integer :: count = 0                        !! distances computed
      real(wp) :: slope = 0.0_wp                  !! dg/dd at the last root along the drive (0: none yet)
      !> a root along the drive whose bracket lies wholly above this, and is narrower than a
      !> hundredth of its height above it, stops there (a minimum over the frequency needs a
      !> value above its best no closer than that)
      real(wp) :: stop_above = huge(1.0_wp)
   end type search_t

contains

   !> The distance at (f, d), counted.
   subroutine evaluate(oracle, s, f, d, sample, error)
      class(oracle_t), intent(in) :: oracle              !! the problem
      type(search_t), intent(inout) :: s                 !! the search: its family, its count grows
      real(wp), intent(in) :: f, d                       !! the point: frequency, drive
      type(oracle_sample_t), intent(out) :: sample       !! the distance there and its error
      type(error_t), allocatable, intent(out) :: error   !! the point cannot be computed (named)
      call oracle%distance(f, d, s%side, s%argument, sample, error)
      s%count = s%count + 1
      if (allocated(error)) error%message = "at ("//real_text(f)//", "//real_text(d)//"): "//error%message
   end subroutine evaluate

   !> The root of the distance along the drive (`along_drive`, at f = fixed) or along f (at
   !> d = fixed) in [a0, b0], the distance changing sign between the ends: Illinois regula
   !> falsi to tolerance × max(1, |x|) or until |g| is within its error; the error bound is
   !> the final bracket or the distance's error over the slope, whichever is larger.
   subroutine bracketed_root(oracle, s, along_drive, fixed, a0, b0, sa, sb, x, x_error, error)
      class(oracle_t), intent(in) :: oracle              !! the problem
      type(search_t), intent(inout) :: s                 !! the search (its tolerance; its count grows)
      logical, intent(in) :: along_drive                 !! the root along the drive (else along f)
      real(wp), intent(in) :: fixed                      !! the other coordinate
      real(wp), intent(in) :: a0, b0                     !! the bracket, a0 < b0
      type(oracle_sample_t), intent(in) :: sa, sb        !! the distances at a0 and b0, of opposite signs
      real(wp), intent(out) :: x, x_error                !! the root and its error bound
      type(error_t), allocatable, intent(out) :: error   !! a point that cannot be computed
      !> distances beyond this are those of an overflowed monodromy: no secant, no slope
      real(wp), parameter :: big = 1.0e150_wp
      real(wp) :: a, b, fa, fb, ga, gb, fc, width, slope, bound
      type(oracle_sample_t) :: sc
      integer :: iteration, kept
      logical :: on_value
      on_value = .false.
      a = a0
      b = b0
      fa = sa%g
      fb = sb%g
      ga = fa
      gb = fb
      bound = max(sa%bound, sb%bound)
      kept = 0
      x = 0.5_wp*(a + b)
      do iteration = 1, 200
         width = b - a
         if (width <= s%tolerance*max(1.0_wp, abs(a), abs(b))) exit
         if (along_drive .and. a > s%stop_above .and. width <= 1.0e-2_wp*(a - s%stop_above)) exit
         x = 0.5_wp*(a + b)
         if (max(abs(fa), abs(fb)) < big .and. fa /= fb) then
            x = a + (b - a)*(fa/(fa - fb))
            if (.not. (x > a + 0.01_wp*width .and. x < b - 0.01_wp*width)) x = 0.5_wp*(a + b)
         end if
         if (along_drive) then
            call evaluate(oracle, s, fixed, x, sc, error)
         else
            call evaluate(oracle, s, x, fixed, sc, error)
         end if
         if (allocated(error)) return
         fc = sc%g
         bound = sc%bound
         on_value = abs(fc) <= bound
         if (on_value) exit
         if (changes(fa, fc) .or. (fc > 0.0_wp .and. fa == 0.0_wp)) then
            b = x
            fb = fc
            gb = fc
            if (kept == -1) fa = 0.5_wp*fa
            kept = -1
         else
            a = x
            fa = fc
            ga = fc
            if (kept == 1) fb = 0.5_wp*fb
            kept = 1
         end if
      end do
      if (.not. (x >= a .and. x <= b)) x = 0.5_wp*(a + b)
      slope = 0.0_wp
      if (max(abs(sa%g), abs(sb%g)) < big) slope = abs(sb%g - sa%g)/(b0 - a0)
      if (b > a .and. max(abs(ga), abs(gb)) < big) slope = abs(gb - ga)/(b - a)
      x_error = b - a
      if (slope > 0.0_wp) then
         if (on_value) then
            ! |g| within its error at x: the root lies within that error over the slope
            x_error = min(b - a, 2.0_wp*bound/slope)
         else
            x_error = max(b - a, min(2.0_wp*bound/slope, b0 - a0))
         end if
      end if
      x_error = max(x_error, 4.0_wp*spacing(max(1.0_wp, abs(x))))
      if (along_drive .and. slope > 0.0_wp) s%slope = slope
   end subroutine bracketed_root

   !> Golden-section search of the window for the largest distance at drive d, stopping at the
   !> first positive one (the region open there) or at `resolution` of the window: f, the
   !> distance there.
   subroutine peak_at(oracle, s, window, d, resolution, f, peak, error)
      class(oracle_t), intent(in) :: oracle              !! the problem
      type(search_t), intent(inout) :: s                 !! the search (its count grows)
      real(wp), intent(in) :: window(2)                  !! the frequencies searched
      real(wp), intent(in) :: d                          !! the drive
      real(wp), intent(in) :: resolution                 !! stop at this fraction of the window
      real(wp), intent(out) :: f                         !! the best frequency found
      type(oracle_sample_t), intent(out) :: peak         !! the distance there
      type(error_t), allocatable, intent(out) :: error   !! a distance that cannot be computed
      real(wp), parameter :: ratio = 0.6180339887498949_wp
      real(wp) :: a, b, x1, x2
      type(oracle_sample_t) :: s1, s2
      integer :: iteration
      a = window(1)
      b = window(2)
      x1 = b - ratio*(b - a)
      x2 = a + ratio*(b - a)
      call evaluate(oracle, s, x1, d, s1, error)
      if (allocated(error)) return
      call evaluate(oracle, s, x2, d, s2, error)
      if (allocated(error)) return
      do iteration = 1, 60
         if (s1%g > 0.0_wp .or. s2%g > 0.0_wp) exit
         if (b - a <= resolution*(window(2) - window(1))) exit
         if (s1%g >= s2%g) then
            b = x2
            x2 = x1
            s2 = s1
            x1 = b - ratio*(b - a)
            call evaluate(oracle, s, x1, d, s1, error)
         else
            a = x1
            x1 = x2
            s1 = s2
            x2 = a + ratio*(b - a)
            call evaluate(oracle, s, x2, d, s2, error)
         end if
         if (allocated(error)) return
      end do
      if (s1%g >= s2%g) then
         f = x1
         peak = s1
      else
         f = x2
         peak = s2
      end if
   end subroutine peak_at

   !> Whether two values have strictly opposite signs.
   pure logical function changes(a, b)
      real(wp), intent(in) :: a, b  !! two values
      changes = (a > 0.0_wp .and. b < 0.0_wp) .or. (a < 0.0_wp .and. b > 0.0_wp)
   end function changes
end module hillstab_curves_region_search

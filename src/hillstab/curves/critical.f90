!> The critical drives of a Hill equation x'' + ε x' + Q(α, β, τ) x = 0 at a fixed β: every
!> α of a range where the stability changes, each with an error bound and confirmed on both
!> sides. The answer to "the least drive that destabilises (or stabilises) it here", and
!> every other change in the range, not only the first. `critical_drives_along` searches
!> either axis at a fixed value of the other: for an equation in physical time (model
!> `equation`), whose β axis is a drive amplitude and α a frequency, the critical amplitudes
!> at one frequency. The damping of each point is the model's (`point_damping`: an
!> equation's changes with its α axis), and so is the threshold.
!>
!> The distance from the threshold: with the trace S (of χ = e^{ετ/2} x when damped) and
!> T = 2 cosh(εP/2) the threshold of |S|, the point is unstable where g₊ = S − T or
!> g₋ = −S − T is positive (at most one is). Each of g± is a smooth function of α (of the
!> coordinate searched), and the stability changes exactly where one of them changes sign.
!> The range is sampled at `n_samples` values of α (S by the method, on OpenMP threads); a
!> sign change of g₊ or g₋
!> between neighbours is refined by the Illinois variant of regula falsi (bisection when it
!> stalls) until the bracket is within tolerance·max(1, |α|) or |g| within S's own error; a
!> neighbour pair where g₊ or g₋ comes within 5 % of T of zero without changing sign is
!> searched by golden section for a narrow region between the samples. The error bound of α
!> is the final bracket or S's error over the slope, whichever is larger; the verdicts just
!> outside it, decided beyond S's error, confirm that the stability differs on the two sides
!> (status 0; 2 where they do not).
!>
!>```fortran
!> type(critical_drive_t), allocatable :: drives(:)
!> ! the Kapitza pendulum at 50 Hz: β = -g π²/(l ω²), ε = κ π/ω (Mathieu's Q = β − α cos πτ)
!> call critical_drives(mathieu, -9.81_wp*pi2/(0.2_wp*omega**2), 0.0_wp, 1.0_wp, 0.2_wp*pi/omega, &
!>                      method_t(), 400, drives, error)
!> print *, drives(1)%alpha*0.2_wp/pi2   ! the least stabilising amplitude, 6.3068e-3 m
!>```
module hillstab_curves_critical
   use hillstab_core_kinds, only: wp
   use hillstab_core_error, only: error_t, set_error, err_invalid_parameter, err_accuracy
   use hillstab_core_status, only: status_ok, status_failed
   use hillstab_core_text, only: real_text, integer_text
   use hillstab_hill_model, only: hill_model_t, hill_point_t, check_point, damping_at
   use hillstab_hill_transfer, only: trace_t
   use hillstab_hill_floquet, only: period_damping
   use hillstab_integrate_monodromy, only: method_t, monodromy_trace
   implicit none
   private
   public :: critical_drive_t, critical_drives, critical_drives_along, max_critical_samples
   public :: along_alpha, along_beta

   !> `critical_drives_along`: α varies, β is fixed.
   integer, parameter :: along_alpha = 1
   !> `critical_drives_along`: β varies, α is fixed.
   integer, parameter :: along_beta = 2

   !> Most samples of one search.
   integer, parameter :: max_critical_samples = 1000000

   !> One change of stability at the fixed β (or, along β, at the fixed α).
   type :: critical_drive_t
      real(wp) :: alpha = 0.0_wp        !! α where the stability changes (β when searched along β)
      real(wp) :: alpha_error = 0.0_wp  !! error bound of α (of β)
      !> +1: S reaches +T there (a 2P-periodic solution at ε = 0), −1: S reaches −T
      integer :: side = 0
      !> +1: stable below α and unstable above it; −1: unstable below, stable above
      integer :: direction = 0
      !> 0: the verdicts on both sides differ beyond S's error; 2: not confirmed
      integer :: status = status_ok
   end type critical_drive_t

   !> The line searched: which coordinate varies, the other's value and the scene's damping.
   type :: line_t
      integer :: axis = along_alpha   !! along_alpha or along_beta
      real(wp) :: fixed = 0.0_wp      !! the coordinate held fixed
      real(wp) :: epsilon = 0.0_wp    !! the damping given (a model's own is added by `point_damping`)
   end type line_t

   !> What a sample knows: the distances g₊, g₋ and the error of S.
   type :: sample_t
      real(wp) :: g(2) = 0.0_wp     !! S − T and −S − T (±huge where S overflows)
      real(wp) :: bound = 0.0_wp    !! the error of S (absolute)
      real(wp) :: threshold = 2.0_wp  !! T = 2 cosh(εP/2) at the point
   end type sample_t

   !> A pair of samples is searched for a narrow region when g± comes this near zero (a
   !> fraction of T) without changing sign.
   real(wp), parameter :: near_fraction = 0.05_wp
   !> Distances beyond this are those of an overflowed S (no secant, no slope through them).
   real(wp), parameter :: big = 1.0e150_wp

contains

   !> Every α in [alpha_min, alpha_max] where the stability of the model's equation at β and
   !> damping ε changes, ascending (see the module's text). `method` computes S (its
   !> tolerance is also the target of α, relative to max(1, |α|)).
   subroutine critical_drives(model, beta, alpha_min, alpha_max, epsilon, method, n_samples, drives, error)
      class(hill_model_t), intent(in) :: model  !! the model of Q
      real(wp), intent(in) :: beta              !! the fixed β
      real(wp), intent(in) :: alpha_min         !! the range of α searched, from
      real(wp), intent(in) :: alpha_max         !! to (> alpha_min)
      real(wp), intent(in) :: epsilon           !! damping ε ≥ 0
      type(method_t), intent(in) :: method      !! the method of S and its tolerance
      integer, intent(in) :: n_samples          !! samples of the range, ≥ 2
      type(critical_drive_t), allocatable, intent(out) :: drives(:)  !! the changes, ascending in α
      !> err_invalid_parameter naming the argument; a sample where S cannot be computed
      type(error_t), allocatable, intent(out) :: error
      call critical_drives_along(model, along_alpha, beta, alpha_min, alpha_max, epsilon, method, n_samples, &
                                 drives, error)
   end subroutine critical_drives

   !> Every value in [low, high] of the coordinate `axis` (along_alpha or along_beta) where
   !> the stability changes at the other coordinate's value `fixed`, ascending, in
   !> `critical_drive_t%alpha` (which holds β when searched along β). The damping of a point
   !> is the model's `point_damping` at its α (ε itself unless the model carries its own).
   subroutine critical_drives_along(model, axis, fixed, low, high, epsilon, method, n_samples, drives, error)
      class(hill_model_t), intent(in) :: model  !! the model of Q
      integer, intent(in) :: axis               !! along_alpha or along_beta
      real(wp), intent(in) :: fixed             !! the other coordinate
      real(wp), intent(in) :: low               !! the range searched, from
      real(wp), intent(in) :: high              !! to (> low)
      real(wp), intent(in) :: epsilon           !! damping ε ≥ 0 (0 for a model with its own)
      type(method_t), intent(in) :: method      !! the method of S and its tolerance
      integer, intent(in) :: n_samples          !! samples of the range, ≥ 2
      type(critical_drive_t), allocatable, intent(out) :: drives(:)  !! the changes, ascending
      !> err_invalid_parameter naming the argument; a sample where S cannot be computed
      type(error_t), allocatable, intent(out) :: error
      type(line_t) :: line
      real(wp), allocatable :: alphas(:)
      type(sample_t), allocatable :: samples(:)
      character(len=300), allocatable :: failures(:)
      type(error_t), allocatable :: cause
      real(wp) :: peak
      type(sample_t) :: at_peak
      integer :: j, k
      allocate (drives(0))
      line = line_t(axis, fixed, epsilon)
      call check_range(model, line, low, high, method, n_samples, error)
      if (allocated(error)) return
      allocate (alphas(n_samples), samples(n_samples), failures(n_samples))
      alphas = [(low + (high - low)*real(j - 1, wp)/real(n_samples - 1, wp), j=1, n_samples)]
      alphas(n_samples) = high
      failures = ""
      !$omp parallel do schedule(dynamic) default(shared) private(j, cause)
      do j = 1, n_samples
         call sample(model, line, alphas(j), method, samples(j), cause)
         if (allocated(cause)) failures(j) = cause%message
      end do
      !$omp end parallel do
      do j = 1, n_samples
         if (len_trim(failures(j)) > 0) then
            call set_error(error, err_invalid_parameter, trim(merge("alpha", "beta ", axis == along_alpha))// &
               " = "//real_text(alphas(j))//": "//trim(failures(j)))
            return
         end if
      end do
      do j = 1, n_samples - 1
         do k = 1, 2
            if (changes(samples(j)%g(k), samples(j + 1)%g(k))) then
               call add_root(alphas(j), alphas(j + 1), samples(j), samples(j + 1), k)
            else if (min(abs(samples(j)%g(k)), abs(samples(j + 1)%g(k))) < &
                     near_fraction*min(samples(j)%threshold, samples(j + 1)%threshold)) then
               ! g_k keeps its sign at both samples but comes near zero: a narrow region between them?
               call extremum(model, line, method, k, alphas(j), alphas(j + 1), &
                             samples(j)%g(k) < 0.0_wp, peak, at_peak, cause)
               if (allocated(cause)) then
                  call move_alloc(cause, error)
                  return
               end if
               if (changes(samples(j)%g(k), at_peak%g(k))) then
                  call add_root(alphas(j), peak, samples(j), at_peak, k)
                  call add_root(peak, alphas(j + 1), at_peak, samples(j + 1), k)
               end if
            end if
            if (allocated(error)) return
         end do
      end do
   contains
      !> Refine the root of g_k in [a, b] and append it.
      subroutine add_root(a, b, sa, sb, k)
         real(wp), intent(in) :: a, b
         type(sample_t), intent(in) :: sa, sb
         integer, intent(in) :: k
         type(critical_drive_t) :: drive
         call refine(model, line, method, k, a, b, sa, sb, drive, error)
         if (allocated(error)) return
         drives = [drives, drive]
      end subroutine add_root
   end subroutine critical_drives_along

   !> The arguments of `critical_drives_along`, checked (err_invalid_parameter naming the one
   !> wrong).
   subroutine check_range(model, line, low, high, method, n_samples, error)
      class(hill_model_t), intent(in) :: model
      type(line_t), intent(in) :: line
      real(wp), intent(in) :: low, high
      type(method_t), intent(in) :: method
      integer, intent(in) :: n_samples
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: name
      name = trim(merge("alpha", "beta ", line%axis == along_alpha))
      if (line%axis /= along_alpha .and. line%axis /= along_beta) then
         call set_error(error, err_invalid_parameter, "axis: 1 (along alpha) or 2 (along beta), got "// &
            integer_text(line%axis))
         return
      end if
      if (n_samples < 2 .or. n_samples > max_critical_samples) then
         call set_error(error, err_invalid_parameter, "n_samples: must be 2 to "//integer_text(max_critical_samples)// &
            ", got "//integer_text(n_samples))
         return
      end if
      if (.not. (high > low)) then
         call set_error(error, err_invalid_parameter, name//"_min, "//name//"_max: the range is empty or not "// &
            "finite ("//name//"_max must exceed "//name//"_min)")
         return
      end if
      if (.not. model%takes_scene_damping() .and. line%epsilon > 0.0_wp) then
         call set_error(error, err_invalid_parameter, "epsilon: the "//model%name()//" model carries its own "// &
            "damping: epsilon must be 0")
         return
      end if
      call check_point(model, point_of(model, line, low), error)
      if (.not. allocated(error)) call check_point(model, point_of(model, line, high), error)
      if (.not. allocated(error) .and. .not. (method%tolerance > 0.0_wp .and. method%tolerance < 1.0_wp)) &
         call set_error(error, err_invalid_parameter, "tolerance: must lie in (0, 1)")
   end subroutine check_range

   !> The point at coordinate x of the line, its damping the model's there.
   function point_of(model, line, x) result(point)
      class(hill_model_t), intent(in) :: model
      type(line_t), intent(in) :: line
      real(wp), intent(in) :: x
      type(hill_point_t) :: point
      if (line%axis == along_alpha) then
         point = hill_point_t(x, line%fixed, damping_at(model, x, line%fixed, line%epsilon))
      else
         point = hill_point_t(line%fixed, x, damping_at(model, line%fixed, x, line%epsilon))
      end if
   end function point_of

   !> Whether two values of g have strictly opposite signs.
   pure logical function changes(a, b)
      real(wp), intent(in) :: a, b
      changes = (a > 0.0_wp .and. b < 0.0_wp) .or. (a < 0.0_wp .and. b > 0.0_wp)
   end function changes

   !> S at the line's point x as the distances g± from the point's threshold and its
   !> absolute error (a result limited by round-off is taken, its estimate being the bound).
   subroutine sample(model, line, x, method, s, error)
      class(hill_model_t), intent(in) :: model
      type(line_t), intent(in) :: line
      real(wp), intent(in) :: x
      type(method_t), intent(in) :: method
      type(sample_t), intent(out) :: s
      type(error_t), allocatable, intent(out) :: error
      type(trace_t) :: tr
      type(hill_point_t) :: point
      point = point_of(model, line, x)
      s%threshold = 2.0_wp*cosh(min(period_damping(point%epsilon, model%period()), 700.0_wp))
      call monodromy_trace(model, point, method, tr, error)
      if (allocated(error)) then
         if (error%code /= err_accuracy) return
         deallocate (error)
      end if
      if (tr%overflow) then
         s%g = [sign(huge(1.0_wp), tr%value), -sign(huge(1.0_wp), tr%value)]
         s%bound = 0.0_wp
         return
      end if
      s%g = [tr%value - s%threshold, -tr%value - s%threshold]
      s%bound = max(tr%error_estimate, method%tolerance)*max(1.0_wp, abs(tr%value))
   end subroutine sample

   !> The root of g_k in [a, b] (g_k of opposite signs at the ends) by the Illinois variant
   !> of regula falsi, then its bound and its confirmation.
   subroutine refine(model, line, method, k, a0, b0, sa, sb, drive, error)
      class(hill_model_t), intent(in) :: model
      type(line_t), intent(in) :: line
      real(wp), intent(in) :: a0, b0
      type(method_t), intent(in) :: method
      integer, intent(in) :: k
      type(sample_t), intent(in) :: sa, sb
      type(critical_drive_t), intent(out) :: drive
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: a, b, fa, fb, ga, gb, c, fc, width, slope, bound
      type(sample_t) :: sc, below, above
      integer :: iteration, side
      a = a0
      b = b0
      fa = sa%g(k)
      fb = sb%g(k)
      ga = fa
      gb = fb
      bound = max(sa%bound, sb%bound)
      side = 0
      c = 0.5_wp*(a + b)
      do iteration = 1, 200
         width = b - a
         if (width <= method%tolerance*max(1.0_wp, abs(a), abs(b))) exit
         ! the secant, inside the bracket (bisection when it leaves it or hugs an end, and
         ! where S overflowed at an end)
         c = 0.5_wp*(a + b)
         if (max(abs(fa), abs(fb)) < big) then
            c = a + (b - a)*(fa/(fa - fb))
            if (.not. (c > a + 0.01_wp*width .and. c < b - 0.01_wp*width)) c = 0.5_wp*(a + b)
         end if
         call sample(model, line, c, method, sc, error)
         if (allocated(error)) return
         fc = sc%g(k)
         bound = sc%bound
         if (abs(fc) <= bound) exit
         if (changes(fa, fc)) then
            b = c
            fb = fc
            gb = fc
            ! Illinois: the value kept at the other end is halved when it is kept again
            if (side == -1) fa = 0.5_wp*fa
            side = -1
         else
            a = c
            fa = fc
            ga = fc
            if (side == 1) fb = 0.5_wp*fb
            side = 1
         end if
      end do
      ! the root: the last secant point, or the middle of the final bracket
      if (.not. (c >= a .and. c <= b)) c = 0.5_wp*(a + b)
      ! the slope of g_k at the root: the final bracket's secant (the samples' when it closed)
      slope = 0.0_wp
      if (max(abs(sa%g(k)), abs(sb%g(k))) < big) slope = abs(sb%g(k) - sa%g(k))/(b0 - a0)
      if (b > a .and. max(abs(ga), abs(gb)) < big) slope = abs(gb - ga)/(b - a)
      drive%alpha = c
      drive%alpha_error = b - a
      if (slope > 0.0_wp) drive%alpha_error = max(b - a, min(2.0_wp*bound/slope, b0 - a0))
      drive%alpha_error = max(drive%alpha_error, 4.0_wp*spacing(max(1.0_wp, abs(c))))
      drive%side = merge(1, -1, k == 1)
      ! g_k rises through zero (unstable above) or falls
      drive%direction = merge(1, -1, sa%g(k) < 0.0_wp)
      ! confirmed: the verdicts just outside the bound differ, beyond S's error
      call sample(model, line, max(a0, c - 2.0_wp*drive%alpha_error), method, below, error)
      if (allocated(error)) return
      call sample(model, line, min(b0, c + 2.0_wp*drive%alpha_error), method, above, error)
      if (allocated(error)) return
      drive%status = status_failed
      if (decided(below, .not. (drive%direction == 1)) .and. decided(above, drive%direction == 1)) &
         drive%status = status_ok
   end subroutine refine

   !> Whether a sample is unstable (`unstable`) or stable, beyond its error.
   pure logical function decided(s, unstable)
      type(sample_t), intent(in) :: s
      logical, intent(in) :: unstable
      if (unstable) then
         decided = maxval(s%g) > s%bound
      else
         decided = maxval(s%g) < -s%bound
      end if
   end function decided

   !> Golden-section search of [a, b] for the largest g_k (`rising`: g_k negative at the
   !> ends, a peak above zero wanted) or the smallest (a dip below zero); returns where, and
   !> the sample there. Stops early once the extremum crosses zero.
   subroutine extremum(model, line, method, k, a0, b0, rising, peak, at_peak, error)
      class(hill_model_t), intent(in) :: model
      type(line_t), intent(in) :: line
      real(wp), intent(in) :: a0, b0
      type(method_t), intent(in) :: method
      integer, intent(in) :: k
      logical, intent(in) :: rising
      real(wp), intent(out) :: peak
      type(sample_t), intent(out) :: at_peak
      type(error_t), allocatable, intent(out) :: error
      real(wp), parameter :: ratio = 0.6180339887498949_wp
      real(wp) :: a, b, x1, x2, f1, f2, sense
      type(sample_t) :: s1, s2
      integer :: iteration
      sense = merge(1.0_wp, -1.0_wp, rising)
      a = a0
      b = b0
      x1 = b - ratio*(b - a)
      x2 = a + ratio*(b - a)
      call sample(model, line, x1, method, s1, error)
      if (allocated(error)) return
      call sample(model, line, x2, method, s2, error)
      if (allocated(error)) return
      f1 = sense*s1%g(k)
      f2 = sense*s2%g(k)
      do iteration = 1, 60
         if (f1 > 0.0_wp .or. f2 > 0.0_wp) exit
         if (b - a <= method%tolerance*max(1.0_wp, abs(a), abs(b))) exit
         if (f1 >= f2) then
            b = x2
            x2 = x1
            f2 = f1
            s2 = s1
            x1 = b - ratio*(b - a)
            call sample(model, line, x1, method, s1, error)
            if (allocated(error)) return
            f1 = sense*s1%g(k)
         else
            a = x1
            x1 = x2
            f1 = f2
            s1 = s2
            x2 = a + ratio*(b - a)
            call sample(model, line, x2, method, s2, error)
            if (allocated(error)) return
            f2 = sense*s2%g(k)
         end if
      end do
      if (f1 >= f2) then
         peak = x1
         at_peak = s1
      else
         peak = x2
         at_peak = s2
      end if
   end subroutine extremum
end module hillstab_curves_critical

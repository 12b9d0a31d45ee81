!> Benchmark of Hill's method on the Fourier coefficients of g = Q − β (`make bench`,
!> hillstab_curves_hill_fourier): prints tables, writes out/bench_fourier.dat.
!>
!> 1. Formulations: the inverted pencil (dsbgv, the default), the standard real problem
!>    (dsbev) and the complex Hermitian band (zhbev) on a drive with sine terms, at one
!>    truncation far beyond the truncation error: relative error against the 40-digit
!>    eigenvalues of data/reference/fourier_set.dat, time per block solve. (With any
!>    argument only this table.)
!> 2. All transition curves for 1000 α in [0, 10], β ∈ [−10, 40], tolerance 1e-12, of an even
!>    three-harmonic model (f = 0.2 − cos πτ + 0.4 cos 2πτ + 0.1 cos 3πτ, period 2, where method
!>    auto's half period applies): Hill's method against scanning S by method auto (tolerance
!>    1e-12, S every 0.1 in β as a chart row) and bisecting each sign change of S ∓ 2 to
!>    1e-12·max(1, |β|), side by side in one run; the time ratio, the largest difference of
!>    each bisected root from Hill's nearest value, and the curves either way finds.
!> 3. The same for a three-harmonic drive with sine terms (no even symmetry) over 100 α,
!>    against scanning and bisecting S over the full period by 1200 sixth-order Magnus steps
!>    (method auto integrates half a period and needs an even Q).
program hillstab_bench_fourier
   use hillstab_core_kinds, only: wp, int64
   use hillstab_core_error, only: error_t
   use hillstab_hill_transfer, only: trace_t
   use hillstab_hill_model, only: hill_model_t, hill_point_t
   use hillstab_integrate_monodromy, only: method_t, method_auto, monodromy_trace, monodromy_trace_batch
   use hillstab_curves_hill_method, only: hill_boundary_t
   use hillstab_curves_hill_fourier
   use hillstab_app_bench_drive, only: drive_model_t, drive_model, full_period_trace
   implicit none
   real(wp), parameter :: tolerance = 1.0e-12_wp
   integer :: unit
   open (newunit=unit, file="out/bench_fourier.dat", status="replace", action="write")
   write (unit, '(a)') "# hillstab benchmark of Hill's method on the Fourier coefficients (app/hillstab_bench_fourier.f90)"
   call formulations()
   if (command_argument_count() == 0) then
      call scan_against_hill(.true., 1000)
      call scan_against_hill(.false., 100)
   end if
   close (unit)

contains

   real(wp) function now()
      integer(int64) :: count, rate
      call system_clock(count, rate)
      now = real(count, wp)/real(rate, wp)
   end function now

   !> Error against the 40-digit references of model 1 at α = 3 and 12 (periodic and
   !> antiperiodic, 8 each) at one truncation (N = 40: 81 and 80 modes, far beyond the
   !> truncation error, so the rounding alone), and time per block solve.
   subroutine formulations()
      character(len=*), parameter :: names(3) = [character(len=26) :: "inverted pencil (dsbgv)", &
                                                 "standard real (dsbev)", "complex Hermitian (zhbev)"]
      integer, parameter :: level = 40, reps = 200
      type(drive_model_t) :: model
      type(fourier_drive_t) :: drive
      type(error_t), allocatable :: error
      real(wp), allocatable :: v(:)
      real(wp) :: ref(2, 2, 8), alpha(2), t0, elapsed, worst
      integer :: f, a, k, r
      model = drive_model(2.0_wp, 0.4_wp, [-1.0_wp, 0.3_wp, 0.25_wp], [0.6_wp, -0.45_wp, 0.15_wp])
      alpha = [3.0_wp, 12.0_wp]
      call read_reference(alpha, ref)
      print '(a)', "Formulations on a drive with sine terms (P = 2, 3 harmonics), alpha = 3 and 12, the 8 lowest "// &
         "values of each kind at N = 40 (81/80 modes) against 40-digit references"
      print '(a)', "| formulation | largest error | ms per block solve |"
      print '(a)', "|---|---|---|"
      write (unit, '(a)') "# formulations: formulation(1 inverted, 2 standard, 3 complex) max_error ms_per_solve"
      do f = 1, 3
         worst = 0.0_wp
         t0 = now()
         do r = 1, reps
            do a = 1, 2
               call fourier_drive(model, alpha(a), drive, error)
               do k = 1, 2
                  call fourier_drive_eigenvalues(drive, merge(5, 6, k == 1), level, v, error, f)
                  if (allocated(error)) then
                     print '(a)', "  "//error%message
                     return
                  end if
                  if (r == 1) worst = max(worst, maxval(abs(v(:8) - ref(a, k, :))/max(1.0_wp, abs(ref(a, k, :)))))
               end do
            end do
         end do
         elapsed = (now() - t0)/(4*reps)
         print '(a,a,a,es9.2,a,f8.4,a)', "| ", trim(names(f)), " | ", worst, " | ", 1.0e3_wp*elapsed, " |"
         write (unit, '(i2,es12.4,f10.5)') f, worst, 1.0e3_wp*elapsed
      end do
      write (unit, '(/)')
      print '(a)', ""
   end subroutine formulations

   !> The references of model 1 at the given α from data/reference/fourier_set.dat.
   subroutine read_reference(alpha, ref)
      real(wp), intent(in) :: alpha(2)
      real(wp), intent(out) :: ref(2, 2, 8)
      character(len=256) :: line
      real(wp) :: a, beta, ref_error
      integer :: u, ios, model, kind, rank, i
      ref = 0.0_wp
      open (newunit=u, file="data/reference/fourier_set.dat", status="old", action="read", iostat=ios)
      if (ios /= 0) return
      do
         read (u, '(a)', iostat=ios) line
         if (ios /= 0) exit
         if (line(1:1) == "#") cycle
         read (line, *) model, a, kind, rank, beta, ref_error
         do i = 1, 2
            if (model == 1 .and. a == alpha(i)) ref(i, merge(1, 2, kind == 2), rank) = beta
         end do
      end do
      close (u)
   end subroutine read_reference

   !> Hill's method against scanning S every 0.1 in β and bisecting, for n_alpha α in [0, 10].
   subroutine scan_against_hill(even, n_alpha)
      logical, intent(in) :: even
      integer, intent(in) :: n_alpha
      integer, parameter :: n_scan = 501, n_steps = 1200
      real(wp), parameter :: beta_min = -10.0_wp, beta_max = 40.0_wp
      type(drive_model_t) :: model
      type(hill_boundary_t), allocatable :: curves(:)
      type(error_t), allocatable :: error
      type(trace_t) :: traces(n_scan)
      logical :: failed(n_scan)
      real(wp) :: betas(n_scan), s(n_scan), alpha, t0, t_hill, t_scan, target, lo, hi, mid, f_lo, f_mid
      real(wp) :: worst, nearest
      real(wp), allocatable :: hill_values(:, :), roots(:, :)
      integer, allocatable :: hill_count(:), root_count(:)
      integer :: i, j, k, t, n_hill, n_bisect, n_crossing_hill, missed
      real(wp), allocatable :: found(:)
      if (even) then
         model = drive_model(2.0_wp, 0.2_wp, [-1.0_wp, 0.4_wp, 0.1_wp], [0.0_wp, 0.0_wp, 0.0_wp])
      else
         model = drive_model(2.0_wp, 0.2_wp, [-1.0_wp, 0.4_wp, 0.1_wp], [0.5_wp, -0.3_wp, 0.2_wp])
      end if
      betas = [(beta_min + (beta_max - beta_min)*(j - 1)/real(n_scan - 1, wp), j=1, n_scan)]
      allocate (hill_values(64, n_alpha), hill_count(n_alpha), roots(64, n_alpha), root_count(n_alpha))
      ! Hill's method
      t0 = now()
      n_hill = 0
      n_crossing_hill = 0
      do i = 1, n_alpha
         alpha = 10.0_wp*(i - 1)/real(max(n_alpha - 1, 1), wp)
         call fourier_boundaries(model, alpha, beta_min, beta_max, tolerance, curves, error)
         if (allocated(error)) then
            print '(a)', error%message
            return
         end if
         hill_count(i) = size(curves)
         hill_values(:size(curves), i) = curves%beta
         n_hill = n_hill + size(curves)
         n_crossing_hill = n_crossing_hill + count(.not. curves%coexistent)
      end do
      t_hill = now() - t0
      ! scan S and bisect every sign change of S -+ 2
      t0 = now()
      n_bisect = 0
      do i = 1, n_alpha
         alpha = 10.0_wp*(i - 1)/real(max(n_alpha - 1, 1), wp)
         if (even) then
            call monodromy_trace_batch(model, hill_point_t(alpha, 0.0_wp, 0.0_wp), betas, &
                                       method_t(method_auto, tolerance=tolerance), traces, failed, error)
            s = traces%value
         else
            do j = 1, n_scan
               s(j) = full_period_trace(model, alpha, betas(j), n_steps)
            end do
         end if
         allocate (found(0))
         do t = 1, 2
            target = merge(2.0_wp, -2.0_wp, t == 1)
            do j = 1, n_scan - 1
               if ((s(j) - target)*(s(j + 1) - target) >= 0.0_wp) cycle
               lo = betas(j); hi = betas(j + 1); f_lo = s(j) - target
               do while (hi - lo > tolerance*max(1.0_wp, abs(lo)))
                  mid = 0.5_wp*(lo + hi)
                  f_mid = trace(model, even, n_steps, alpha, mid) - target
                  if ((f_mid > 0.0_wp) .eqv. (f_lo > 0.0_wp)) then
                     lo = mid; f_lo = f_mid
                  else
                     hi = mid
                  end if
               end do
               found = [found, 0.5_wp*(lo + hi)]
            end do
         end do
         n_bisect = n_bisect + size(found)
         ! kept for the comparison after the timing
         root_count(i) = min(size(found), 64)
         roots(:root_count(i), i) = found(:root_count(i))
         deallocate (found)
      end do
      t_scan = now() - t0
      ! every bisected root against Hill's nearest value; Hill's crossing curves the scan missed
      worst = 0.0_wp
      missed = 0
      do i = 1, n_alpha
         do k = 1, root_count(i)
            nearest = huge(1.0_wp)
            do j = 1, hill_count(i)
               nearest = min(nearest, abs(hill_values(j, i) - roots(k, i)))
            end do
            worst = max(worst, nearest/max(1.0_wp, abs(roots(k, i))))
         end do
      end do
      missed = n_crossing_hill - n_bisect
      if (even) then
         print '(a,i0,a)', "All curves of an even 3-harmonic model (P = 2) for ", n_alpha, &
            " alpha in [0, 10], beta in [-10, 40], tolerance 1e-12 (one thread): Hill's method against "// &
            "scanning S by method auto (every 0.1) and bisecting to 1e-12"
      else
         print '(a,i0,a)', "All curves of a 3-harmonic model with sine terms (P = 2) for ", n_alpha, &
            " alpha in [0, 10], beta in [-10, 40]: Hill's method against scanning S over the full period "// &
            "(1200 Magnus-6 steps, every 0.1) and bisecting to 1e-12"
      end if
      print '(a)', "| way | curve points | seconds | ms per alpha |"
      print '(a)', "|---|---|---|---|"
      print '(a,i7,a,f9.3,a,f9.3,a)', "| Hill's method (Fourier, dsbgv) | ", n_hill, " | ", t_hill, " | ", &
         1.0e3_wp*t_hill/n_alpha, " |"
      print '(a,i7,a,f9.3,a,f9.3,a)', "| scan + bisection of S | ", n_bisect, " | ", t_scan, " | ", &
         1.0e3_wp*t_scan/n_alpha, " |"
      print '(a,f9.1,a,es9.2,a,i0,a)', "time ratio scan/Hill ", t_scan/t_hill, "; largest |bisected - Hill| / "// &
         "max(1,|beta|) ", worst, "; ", missed, " curve points of open tongues the scan missed (tongues narrower "// &
         "than 0.1, or closed: S touches +-2)"
      print '(a)', ""
      write (unit, '(a)') "# scan_against_hill: even(1/0) n_alpha hill_points hill_seconds scan_points scan_seconds "// &
         "ratio max_relative_difference missed"
      write (unit, '(i2,i6,i8,f10.4,i8,f10.4,f9.2,es12.4,i6)') merge(1, 0, even), n_alpha, n_hill, t_hill, n_bisect, &
         t_scan, t_scan/t_hill, worst, missed
      write (unit, '(/)')
   end subroutine scan_against_hill

   !> S at (α, β): by method auto (even model) or over the full period by n_steps Magnus steps.
   real(wp) function trace(model, even, n_steps, a, b)
      type(drive_model_t), intent(in) :: model
      logical, intent(in) :: even
      integer, intent(in) :: n_steps
      real(wp), intent(in) :: a, b
      type(trace_t) :: tr
      type(error_t), allocatable :: e
      if (even) then
         call monodromy_trace(model, hill_point_t(a, b, 0.0_wp), method_t(method_auto, tolerance=tolerance), tr, e)
         trace = tr%value
      else
         trace = full_period_trace(model, a, b, n_steps)
      end if
   end function trace
end program hillstab_bench_fourier

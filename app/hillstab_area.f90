!> Where the approximate charts are wrong (`make area`): the fraction of the physical
!> domain 0 ≤ α < π², 0 < β < π² that the paper's 2-piece chart (eq. (37)) and the
!> N-piece endpoint / midpoint charts (N = 4, 8, 16, 64) classify wrongly, computed
!> from the boundaries and cross-checked by counting pixels; and the paper's claim
!> that its chart agrees with the Strutt diagram for small α (Fig. 3, α ≲ 0.2).
!>
!> From the boundaries: inside the physical domain the exact chart is unstable only
!> in the first tongue b₁ < β < a₁ (a₀ = 0 is its bottom edge and the order-2 tongue
!> has zero width at β = π²), from Hill's method; an approximate chart is unstable
!> where |S_method| > 2, between its roots of S = ±2 (Brent, brackets from 2000
!> samples of (0, π²)). The misclassified length at each α is the length of the
!> symmetric difference of the two unstable sets; the area is its integral over α
!> (trapezoids: step 0.01 up to α = 9.8, then 40 points graded towards π²(1 − 1e-4);
!> the strip left out is below 1e-4 of the domain). Pixels: 400 × 400 cell centres,
!> exact verdicts by method auto (tolerance 1e-8), approximate ones by the method.
!>
!> Writes out/area_table.dat, out/area_length.dat, out/area_map.dat, out/area_small_alpha.dat.
!> Usage: hillstab_area [--quick]; --quick: α in steps of 0.1 and 10 graded points, 40 × 40
!> pixels, every tenth small α (the same files, coarse: a check of the files and plots/area.gp).
program hillstab_area
   use hillstab_core_kinds, only: wp, pi2
   use hillstab_core_error, only: error_t
   use hillstab_hill_coefficient, only: sampling_endpoint, sampling_midpoint
   use hillstab_hill_transfer, only: trace_t
   use hillstab_integrate_monodromy, only: method_t, method_auto, method_formula, method_segments, monodromy_trace, &
      monodromy_trace_batch
   use hillstab_curves_hill_method, only: hill_boundary_t, hill_boundaries
   use hillstab_curves_boundaries, only: approximate_root_t, approximate_boundaries, unstable_intervals_from_roots, &
      symmetric_difference_length
   use hillstab_hill_model, only: hill_point_t
   use hillstab_hill_model_elastic, only: elastic_model_t
   use hillstab_hill_model_mathieu, only: mathieu_model_t
   implicit none
   integer, parameter :: n_methods = 9
   type(method_t) :: methods(n_methods)
   character(len=24) :: labels(n_methods)
   real(wp), allocatable :: alphas(:), lengths(:, :)
   real(wp) :: area(n_methods), pixel_area(n_methods)
   integer :: m, i, unit, n_pixels, n_graded, stride
   integer, parameter :: pieces(4) = [4, 8, 16, 64]
   character(len=16) :: arg
   logical :: quick
   real(wp), parameter :: area_tolerance = 1.0e-10_wp

   methods(1) = method_t(method_formula, 2, sampling_endpoint, area_tolerance)
   labels(1) = "paper eq. (37), 2 pieces"
   do m = 1, 4
      methods(1 + m) = method_t(method_segments, pieces(m), sampling_endpoint, area_tolerance)
      write (labels(1 + m), '(a,i0)') "endpoint N = ", pieces(m)
      methods(5 + m) = method_t(method_segments, pieces(m), sampling_midpoint, area_tolerance)
      write (labels(5 + m), '(a,i0)') "midpoint N = ", pieces(m)
   end do

   quick = .false.
   do i = 1, command_argument_count()
      call get_command_argument(i, arg)
      if (arg == "--quick") then
         quick = .true.
      else
         write (*, '(a)') "usage: hillstab_area [--quick]"
         error stop 2
      end if
   end do
   stride = merge(10, 1, quick)
   n_graded = merge(10, 40, quick)
   n_pixels = merge(40, 400, quick)
   alphas = [(0.01_wp*i, i=0, 980, stride), &
             (pi2 - (pi2 - 9.8_wp)*(1.0e-4_wp*pi2/(pi2 - 9.8_wp))**(real(i, wp)/n_graded), i=1, n_graded)]
   allocate (lengths(size(alphas), n_methods))
   !$omp parallel do schedule(dynamic) default(shared) private(i)
   do i = 1, size(alphas)
      call misclassified_lengths(alphas(i), lengths(i, :))
   end do
   !$omp end parallel do
   do m = 1, n_methods
      area(m) = sum(0.5_wp*(lengths(2:, m) + lengths(:size(alphas) - 1, m))*(alphas(2:) - alphas(:size(alphas) - 1)))
   end do
   open (newunit=unit, file="out/area_length.dat", status="replace", action="write")
   write (unit, '(a)') "# misclassified length in beta at each alpha (physical domain 0 < beta < pi^2)"
   write (unit, '(a)') "# columns: alpha paper endpoint4 endpoint8 endpoint16 endpoint64 midpoint4 midpoint8 "// &
      "midpoint16 midpoint64"
   do i = 1, size(alphas)
      write (unit, '(*(es16.8))') alphas(i), lengths(i, :)
   end do
   close (unit)

   call pixel_count(n_pixels, pixel_area)

   print '(a)', "Misclassified fraction of the physical domain 0 <= alpha < pi^2, 0 < beta < pi^2 (area pi^4)"
   print '(a,i0,a,i0,a)', "| chart | from the boundaries | pixel count (", n_pixels, " x ", n_pixels, ") |"
   print '(a)', "|---|---|---|"
   open (newunit=unit, file="out/area_table.dat", status="replace", action="write")
   write (unit, '(a)') "# columns: method_index fraction_boundaries fraction_pixels  (1 paper, 2-5 endpoint N = 4 8 16 64, "// &
      "6-9 midpoint N = 4 8 16 64)"
   do m = 1, n_methods
      print '(a,a,a,f9.5,a,f9.5,a)', "| ", trim(labels(m)), " | ", 100*area(m)/pi2**2, " % | ", &
         100*pixel_area(m), " % |"
      write (unit, '(i3,2es16.8)') m, area(m)/pi2**2, pixel_area(m)
   end do
   close (unit)

   call small_alpha()

contains

   !> Exact unstable set in (0, π²) at α, and each method's; their symmetric differences.
   subroutine misclassified_lengths(alpha, length)
      real(wp), intent(in) :: alpha
      real(wp), intent(out) :: length(n_methods)
      type(hill_boundary_t), allocatable :: curves(:)
      type(approximate_root_t), allocatable :: roots(:)
      type(error_t), allocatable :: error
      real(wp), allocatable :: exact(:, :), approximate(:, :)
      real(wp) :: lo, hi
      integer :: k, j
      call hill_boundaries(elastic_model_t(), alpha, 0.0_wp, pi2, 1.0e-10_wp, curves, error)
      if (allocated(error)) error stop "hillstab_area: Hill's method failed"
      lo = pi2; hi = 0.0_wp
      do k = 1, size(curves)
         if (curves(k)%order /= 1) cycle
         lo = min(lo, curves(k)%beta); hi = max(hi, curves(k)%beta)
      end do
      if (alpha > 0.0_wp) then
         exact = reshape([max(lo, 0.0_wp), min(hi, pi2)], [2, 1])
      else
         allocate (exact(2, 0))
      end if
      do j = 1, n_methods
         call approximate_boundaries(elastic_model_t(), alpha, methods(j), 1.0e-9_wp, pi2 - 1.0e-9_wp, 2000, &
                                     area_tolerance, roots, error)
         if (allocated(error)) error stop "hillstab_area: root finding failed"
         call unstable_intervals_from_roots(elastic_model_t(), alpha, methods(j), 0.0_wp, pi2, roots%beta, approximate, &
                                            error)
         length(j) = symmetric_difference_length(exact, approximate)
      end do
   end subroutine misclassified_lengths

   !> Fraction of n × n cell centres classified differently from the exact chart.
   subroutine pixel_count(n, fraction)
      integer, intent(in) :: n
      real(wp), intent(out) :: fraction(n_methods)
      real(wp) :: betas(n), alpha
      type(trace_t) :: exact(n), tr
      logical :: failed(n)
      type(error_t), allocatable :: error
      integer :: i, j, k, wrong(n_methods), u
      integer, allocatable :: wrong_rows(:, :)
      integer(kind=1), allocatable :: map(:, :)
      betas = [((j - 0.5_wp)*pi2/n, j=1, n)]
      allocate (wrong_rows(n_methods, n), map(n, n))
      !$omp parallel do schedule(dynamic) default(shared) private(i, alpha, exact, failed, error, j, k, tr)
      do i = 1, n
         alpha = (i - 0.5_wp)*pi2/n
         call monodromy_trace_batch(elastic_model_t(), hill_point_t(alpha, 0.0_wp, 0.0_wp), betas, &
                                    method_t(method_auto, tolerance=1.0e-8_wp), exact, failed, error)
         wrong_rows(:, i) = 0
         do j = 1, n
            do k = 1, n_methods
               call monodromy_trace(elastic_model_t(), hill_point_t(alpha, betas(j), 0.0_wp), methods(k), tr, error)
               if ((abs(tr%value) > 2.0_wp) .neqv. (abs(exact(j)%value) > 2.0_wp)) wrong_rows(k, i) = wrong_rows(k, i) + 1
               ! map of the paper's chart: 0 both stable, 1 both unstable, 2 exact stable but eq. (37)
               ! unstable, 3 exact unstable but eq. (37) stable
               if (k == 1) map(j, i) = int(merge(1, 0, abs(exact(j)%value) > 2.0_wp) + &
                  merge(2, 0, (abs(tr%value) > 2.0_wp) .neqv. (abs(exact(j)%value) > 2.0_wp)), 1)
            end do
         end do
      end do
      !$omp end parallel do
      wrong = sum(wrong_rows, dim=2)
      fraction = real(wrong, wp)/real(n, wp)**2
      open (newunit=u, file="out/area_map.dat", status="replace", action="write")
      write (u, '(a,i0,a,i0,a)') "# the paper's eq. (37) chart against the exact one on ", n, " x ", n, " cell centres"
      write (u, '(a)') "# class: 0 both stable, 1 both unstable, 2 exact stable but eq. (37) unstable, "// &
         "3 exact unstable but eq. (37) stable"
      write (u, '(a)') "# columns: alpha beta class"
      do i = 1, n
         do j = 1, n
            write (u, '(2f10.5,i3)') (i - 0.5_wp)*pi2/n, betas(j), map(j, i)
         end do
         write (u, '(a)') ""
      end do
      close (u)
   end subroutine pixel_count

   !> First tongue at small α: exact (Hill), the Mathieu limit (21) with ν = α(1 − β/π²)
   !> (fixed point on Hill's method for the Mathieu operator) and the paper's eq. (37).
   subroutine small_alpha()
      type(hill_boundary_t), allocatable :: curves(:)
      type(approximate_root_t), allocatable :: roots(:)
      type(error_t), allocatable :: error
      real(wp) :: alpha, exact(2), limit(2), paper(2), nu, beta
      real(wp) :: first_001, first_005
      integer :: i, k, it, u, parity
      first_001 = -1.0_wp; first_005 = -1.0_wp
      open (newunit=u, file="out/area_small_alpha.dat", status="replace", action="write")
      write (u, '(a)') "# first tongue: exact (Hill), Mathieu limit nu = alpha (1 - beta/pi^2) (eq. (21)), eq. (37)"
      write (u, '(a)') "# columns: alpha exact_lower exact_upper mathieu_lower mathieu_upper paper_lower paper_upper"
      print '(a)', ""
      print '(a)', "First tongue at small alpha: edges (b1, a1) exact, Mathieu limit (21), eq. (37); " // &
         "largest edge difference of eq. (37) from the exact curve"
      print '(a)', "| alpha | exact | Mathieu limit | eq. (37) | eq. (37) - exact | Mathieu limit - exact |"
      print '(a)', "|---|---|---|---|---|---|"
      do i = stride, 200, stride
         alpha = 0.01_wp*i
         call hill_boundaries(elastic_model_t(), alpha, 0.0_wp, pi2, 1.0e-11_wp, curves, error)
         exact = [pi2, 0.0_wp]
         do k = 1, size(curves)
            if (curves(k)%order /= 1) cycle
            exact(merge(1, 2, curves(k)%parity == -1)) = curves(k)%beta
         end do
         do parity = -1, 1, 2
            beta = exact(merge(1, 2, parity == -1))
            do it = 1, 60
               nu = alpha*(1.0_wp - beta/pi2)
               call hill_boundaries(mathieu_model_t(), nu, 0.0_wp, pi2, 1.0e-12_wp, curves, error)
               do k = 1, size(curves)
                  if (curves(k)%order == 1 .and. curves(k)%parity == parity) beta = curves(k)%beta
               end do
            end do
            limit(merge(1, 2, parity == -1)) = beta
         end do
         call approximate_boundaries(elastic_model_t(), alpha, method_t(method_formula, tolerance=1.0e-12_wp), &
                                     0.1_wp, 6.0_wp, 2000, 1.0e-12_wp, roots, error)
         paper = [pi2, 0.0_wp]
         do k = 1, size(roots)
            if (roots(k)%order /= 1) cycle
            paper(roots(k)%edge) = roots(k)%beta
         end do
         write (u, '(7es18.10)') alpha, exact, limit, paper
         if (first_001 < 0.0_wp .and. maxval(abs(paper - exact)) > 0.01_wp) first_001 = alpha
         if (first_005 < 0.0_wp .and. maxval(abs(paper - exact)) > 0.05_wp) first_005 = alpha
         if (any(i == [5, 10, 20, 30, 50, 100, 200])) then
            print '(a,f5.2,a,2f9.5,a,2f9.5,a,2f9.5,a,es9.2,a,es9.2,a)', "| ", alpha, " | ", exact, " | ", limit, &
               " | ", paper, " | ", maxval(abs(paper - exact)), " | ", maxval(abs(limit - exact)), " |"
         end if
      end do
      close (u)
      print '(a,f5.2,a,f5.2)', "eq. (37) edges first differ from the exact ones by more than 0.01 at alpha = ", &
         first_001, ", by more than 0.05 at alpha = ", first_005
   end subroutine small_alpha
end program hillstab_area

!> Benchmark of the transition curves (`make bench`): prints tables, writes
!> out/bench_boundaries.dat.
!>
!> 1. Formulations of Hill's method: the inverted pencil (the default), the direct
!>    pencil (both LAPACK dsbgv) and the nonsymmetric tridiagonal (dgeev), at the
!>    truncation the adaptive loop settles on; error against the exact eigenvalues
!>    β = 0 and β = π² of the periodic even block, and time per solve.
!> 2. Modes needed: the smallest truncation with every eigenvalue below β = 40
!>    within 1e-11·max(1, |β|) of a reference with twice the modes, at α = 9.5, 9.8, 9.86.
!> 3. All boundaries for 1000 α in [0, 9.8], β ∈ [−2, 40], tolerance 1e-11: Hill's
!>    method (with and without the check by auto) against locating the crossing
!>    boundaries by bisection on S with method auto (S sampled every 0.1 in β as a
!>    chart row, each sign change of S ∓ 2 bisected to 1e-9).
program hillstab_bench_boundaries
   use hillstab_core_kinds, only: wp, int64, pi2
   use hillstab_core_error, only: error_t
   use hillstab_hill_transfer, only: trace_t
   use hillstab_integrate_monodromy, only: method_t, method_auto, monodromy_trace, monodromy_trace_batch
   use hillstab_curves_hill_method
   use hillstab_curves_boundaries, only: boundary_check_t, verify_boundary
   use hillstab_hill_model, only: hill_point_t
   use hillstab_hill_model_elastic, only: elastic_model_t
   implicit none
   real(wp), parameter :: tolerance = 1.0e-11_wp
   integer :: unit
   open (newunit=unit, file="out/bench_boundaries.dat", status="replace", action="write")
   write (unit, '(a)') "# hillstab benchmark of the transition curves (app/hillstab_bench_boundaries.f90)"
   call formulations()
   if (command_argument_count() == 0) then
      call modes_needed()
      call thousand_alphas()
   end if
   close (unit)

contains

   real(wp) function now()
      integer(int64) :: count, rate
      call system_clock(count, rate)
      now = real(count, wp)/real(rate, wp)
   end function now

   subroutine formulations()
      real(wp), parameter :: alphas(4) = [5.0_wp, 9.5_wp, 9.8_wp, 9.86_wp]
      character(len=*), parameter :: names(3) = [character(len=16) :: "inverted pencil", "direct pencil", &
                                                 "nonsymmetric"]
      type(hill_boundary_t), allocatable :: curves(:)
      type(error_t), allocatable :: error
      real(wp), allocatable :: v(:)
      real(wp) :: t0, elapsed
      integer :: i, f, modes(4), reps, r
      print '(a)', "Formulations (periodic even block at the converged truncation): error of beta = 0 and pi^2, time"
      print '(a)', "| alpha | modes | formulation | error at beta = 0 | error at beta = pi^2 | ms per solve |"
      print '(a)', "|---|---|---|---|---|---|"
      write (unit, '(a)') "# formulations: alpha modes formulation(1 inverted, 2 direct, 3 nonsymmetric) err_0 err_pi2 ms"
      do i = 1, size(alphas)
         call hill_boundaries(elastic_model_t(), alphas(i), -2.0_wp, 40.0_wp, tolerance, curves, error, modes)
         do f = 1, 3
            reps = merge(1, 20, f == 3 .and. modes(1) > 200)
            t0 = now()
            do r = 1, reps
               call hill_block_eigenvalues(elastic_model_t(), alphas(i), block_periodic_even, modes(1), v, error, f)
            end do
            elapsed = (now() - t0)/reps
            print '(a,f5.2,a,i5,a,a,a,es9.2,a,es9.2,a,f10.3,a)', "| ", alphas(i), " | ", modes(1), " | ", &
               trim(names(f)), " | ", abs(v(1)), " | ", abs(v(2) - pi2), " | ", 1.0e3_wp*elapsed, " |"
            write (unit, '(f6.3,i6,i3,2es12.3,f12.4)') alphas(i), modes(1), f, abs(v(1)), abs(v(2) - pi2), &
               1.0e3_wp*elapsed
         end do
      end do
      write (unit, '(/)')
      print '(a)', ""
      call formulations_against_auto()
   end subroutine formulations

   !> The antiperiodic curves of orders 3 … 7 (β ≈ 10 … 40, where auto reaches 1e-13)
   !> against bisection on S by auto at tolerance 1e-13 to a bracket of 1e-13.
   subroutine formulations_against_auto()
      real(wp), parameter :: alphas(3) = [9.5_wp, 9.8_wp, 9.86_wp]
      character(len=*), parameter :: names(3) = [character(len=16) :: "inverted pencil", "direct pencil", &
                                                 "nonsymmetric"]
      type(hill_boundary_t), allocatable :: curves(:)
      type(error_t), allocatable :: error
      real(wp), allocatable :: v(:, :), ref(:)
      real(wp), allocatable :: w(:)
      real(wp) :: lo, hi, mid, f_lo, f_mid, worst(3)
      integer :: i, f, modes(4), j, block, m
      print '(a)', "Formulations against bisection on S by auto (tolerance 1e-13): antiperiodic curves 10 < beta < 40"
      print '(a)', "| alpha | modes | curves | inverted pencil | direct pencil | nonsymmetric |"
      print '(a)', "|---|---|---|---|---|---|"
      do i = 1, size(alphas)
         call hill_boundaries(elastic_model_t(), alphas(i), -2.0_wp, 40.0_wp, tolerance, curves, error, modes)
         worst = 0.0_wp
         m = 0
         do block = block_antiperiodic_even, block_antiperiodic_odd
            call hill_block_eigenvalues(elastic_model_t(), alphas(i), block, modes(block), w, error, 1)
            allocate (v(size(w), 3))
            do f = 1, 3
               call hill_block_eigenvalues(elastic_model_t(), alphas(i), block, modes(block), w, error, f)
               v(:, f) = w
            end do
            do j = 1, size(w)
               if (v(j, 1) < 10.0_wp .or. v(j, 1) > 40.0_wp) cycle
               lo = v(j, 1) - 1.0e-7_wp; hi = v(j, 1) + 1.0e-7_wp
               f_lo = trace13(alphas(i), lo) + 2.0_wp
               do while (hi - lo > 1.0e-13_wp*v(j, 1))
                  mid = 0.5_wp*(lo + hi)
                  f_mid = trace13(alphas(i), mid) + 2.0_wp
                  if ((f_mid > 0.0_wp) .eqv. (f_lo > 0.0_wp)) then
                     lo = mid; f_lo = f_mid
                  else
                     hi = mid
                  end if
               end do
               m = m + 1
               do f = 1, 3
                  worst(f) = max(worst(f), abs(v(j, f) - 0.5_wp*(lo + hi)))
               end do
            end do
            deallocate (v)
         end do
         print '(a,f5.2,a,i5,a,i3,3(a,es9.2),a)', "| ", alphas(i), " | ", modes(3), " | ", m, &
            " | ", worst(1), " | ", worst(2), " | ", worst(3), " |"
      end do
      print '(a)', ""
      if (.false.) ref = [0.0_wp]
   end subroutine formulations_against_auto

   real(wp) function trace13(alpha, beta)
      real(wp), intent(in) :: alpha, beta
      type(trace_t) :: tr
      type(error_t), allocatable :: error
      call monodromy_trace(elastic_model_t(), hill_point_t(alpha, beta, 0.0_wp), method_t(method_auto, tolerance=1.0e-13_wp), &
                           tr, error)
      trace13 = tr%value
   end function trace13

   subroutine modes_needed()
      real(wp), parameter :: alphas(4) = [5.0_wp, 9.5_wp, 9.8_wp, 9.86_wp]
      type(hill_boundary_t), allocatable :: curves(:)
      type(error_t), allocatable :: error
      real(wp), allocatable :: ref(:), v(:)
      integer :: i, block, modes(4), needed(4), n, m, j
      logical :: ok
      print '(a)', "Modes needed for every eigenvalue below beta = 40 within 1e-11*max(1,|beta|)"
      print '(a)', "| alpha | needed (per block: P+ P- A+ A-) | used by the adaptive loop | decay r = k/(1+sqrt(1-k^2)) |"
      print '(a)', "|---|---|---|---|"
      write (unit, '(a)') "# modes: alpha needed(4 blocks) used"
      do i = 1, size(alphas)
         call hill_boundaries(elastic_model_t(), alphas(i), -2.0_wp, 40.0_wp, tolerance, curves, error, modes)
         do block = 1, 4
            call hill_block_eigenvalues(elastic_model_t(), alphas(i), block, 2*modes(block), ref, error)
            m = count(ref <= 40.0_wp)
            needed(block) = -1
            do n = max(m + 1, 8), 2*modes(block), max(1, modes(block)/100)
               call hill_block_eigenvalues(elastic_model_t(), alphas(i), block, n, v, error)
               ok = size(v) > m
               if (ok) then
                  do j = 1, m
                     if (abs(v(j) - ref(j)) > tolerance*max(1.0_wp, abs(ref(j)))) ok = .false.
                  end do
               end if
               if (ok) then
                  needed(block) = n
                  exit
               end if
            end do
         end do
         print '(a,f5.2,a,4i5,a,i5,a,f8.5,a)', "| ", alphas(i), " | ", needed, " | ", modes(1), " | ", &
            (alphas(i)/pi2)/(1.0_wp + sqrt(1.0_wp - (alphas(i)/pi2)**2)), " |"
         write (unit, '(f6.3,5i6)') alphas(i), needed, modes(1)
      end do
      write (unit, '(/)')
      print '(a)', ""
   end subroutine modes_needed

   subroutine thousand_alphas()
      integer, parameter :: n_alpha = 1000, n_scan = 421
      real(wp), parameter :: beta_min = -2.0_wp, beta_max = 40.0_wp, bisection_width = 1.0e-9_wp
      type(hill_boundary_t), allocatable :: curves(:)
      type(error_t), allocatable :: error
      type(boundary_check_t) :: check
      type(trace_t) :: traces(n_scan)
      logical :: failed(n_scan)
      real(wp) :: betas(n_scan), s(n_scan), alpha, t0, t_hill, t_check, t_bisect, target, lo, hi, mid, f_lo, f_mid
      real(wp) :: worst_difference, nearest
      integer :: i, j, k, t, n_hill, n_bisect, n_crossing_hill, iterations
      real(wp), allocatable :: found(:)
      betas = [(beta_min + (beta_max - beta_min)*(j - 1)/real(n_scan - 1, wp), j=1, n_scan)]
      ! Hill's method alone
      t0 = now()
      n_hill = 0
      do i = 1, n_alpha
         alpha = 9.8_wp*(i - 1)/real(n_alpha - 1, wp)
         call hill_boundaries(elastic_model_t(), alpha, beta_min, beta_max, tolerance, curves, error)
         n_hill = n_hill + size(curves)
      end do
      t_hill = now() - t0
      ! Hill's method and the check of every boundary by auto (what task boundaries does)
      t0 = now()
      n_crossing_hill = 0
      do i = 1, n_alpha
         alpha = 9.8_wp*(i - 1)/real(n_alpha - 1, wp)
         call hill_boundaries(elastic_model_t(), alpha, beta_min, beta_max, tolerance, curves, error)
         do k = 1, size(curves)
            call verify_boundary(elastic_model_t(), alpha, curves(k)%beta, curves(k)%trace_sign, tolerance, check, error)
            if (.not. curves(k)%coexistent) n_crossing_hill = n_crossing_hill + 1
         end do
      end do
      t_check = now() - t0
      ! bisection on S by auto, brackets from a scan of the window
      t0 = now()
      n_bisect = 0
      iterations = 0
      worst_difference = 0.0_wp
      do i = 1, n_alpha
         alpha = 9.8_wp*(i - 1)/real(n_alpha - 1, wp)
         call monodromy_trace_batch(elastic_model_t(), hill_point_t(alpha, 0.0_wp, 0.0_wp), betas, &
                                    method_t(method_auto, tolerance=tolerance), traces, failed, error)
         s = traces%value
         allocate (found(0))
         do t = 1, 2
            target = merge(2.0_wp, -2.0_wp, t == 1)
            do j = 1, n_scan - 1
               if ((s(j) - target)*(s(j + 1) - target) >= 0.0_wp) cycle
               lo = betas(j); hi = betas(j + 1); f_lo = s(j) - target
               do while (hi - lo > bisection_width)
                  mid = 0.5_wp*(lo + hi)
                  f_mid = trace(alpha, mid) - target
                  iterations = iterations + 1
                  if ((f_mid > 0.0_wp) .eqv. (f_lo > 0.0_wp)) then
                     lo = mid; f_lo = f_mid
                  else
                     hi = mid
                  end if
               end do
               found = [found, 0.5_wp*(lo + hi)]
               n_bisect = n_bisect + 1
            end do
         end do
         ! each bisected boundary against Hill's nearest (outside the timing would be fairer; it is cheap)
         if (mod(i, 50) == 1) then
            call hill_boundaries(elastic_model_t(), alpha, beta_min, beta_max, tolerance, curves, error)
            do k = 1, size(found)
               nearest = huge(1.0_wp)
               do j = 1, size(curves)
                  nearest = min(nearest, abs(curves(j)%beta - found(k)))
               end do
               worst_difference = max(worst_difference, nearest)
            end do
         end if
         deallocate (found)
      end do
      t_bisect = now() - t0
      print '(a)', "All boundaries for 1000 alpha in [0, 9.8], beta in [-2, 40], tolerance 1e-11 (one thread)"
      print '(a)', "| way | boundaries found | seconds | per alpha (ms) |"
      print '(a)', "|---|---|---|---|"
      print '(a,i6,a,f8.3,a,f8.3,a)', "| Hill's method (dsbgv) | ", n_hill, " | ", t_hill, " | ", 1.0e3_wp*t_hill/n_alpha, " |"
      print '(a,i6,a,f8.3,a,f8.3,a)', "| Hill's method + check of each by auto | ", n_hill, " | ", t_check, " | ", &
         1.0e3_wp*t_check/n_alpha, " |"
      print '(a,i6,a,f8.3,a,f8.3,a)', "| scan (dbeta = 0.1) + bisection on S by auto to 1e-9 | ", n_bisect, " | ", &
         t_bisect, " | ", 1.0e3_wp*t_bisect/n_alpha, " |"
      print '(a,f8.1,a,f8.1)', "ratio bisection/Hill: ", t_bisect/t_hill, "; bisection/(Hill + check): ", t_bisect/t_check
      print '(a,i0,a,i0,a,es9.2)', "crossing (non-coexistent) boundaries by Hill: ", n_crossing_hill, &
         "; found by the scan: ", n_bisect, "; largest distance of a bisected boundary to Hill's: ", worst_difference
      print '(a,i0)', "auto evaluations in the bisections: ", iterations
      write (unit, '(a)') "# thousand alphas: n_hill t_hill t_hill_check n_bisect t_bisect"
      write (unit, '(i8,2f10.4,i8,f10.4)') n_hill, t_hill, t_check, n_bisect, t_bisect
   end subroutine thousand_alphas

   real(wp) function trace(alpha, beta)
      real(wp), intent(in) :: alpha, beta
      type(trace_t) :: tr
      type(error_t), allocatable :: error
      call monodromy_trace(elastic_model_t(), hill_point_t(alpha, beta, 0.0_wp), method_t(method_auto, tolerance=tolerance), &
                           tr, error)
      trace = tr%value
   end function trace
end program hillstab_bench_boundaries

!> Tests of the task runners through `run_scene_file`, reading the files back:
!> layout (header, one `# columns:` line, numeric columns, α blocks), values
!> against closed forms written here independently (Q ≡ β at α = 0, the
!> paper's eq. (37) in its own notation, eq. (25) for the coefficient), the
!> damped verdicts, overflow clamping, repeating a run from its output, and that
!> bad input or an unwritable path leaves no file behind and touches none.
module test_tasks
   use hillstab_core_kinds, only: wp, pi, pi2
   use hillstab_core_error, only: error_t, err_input, err_io, err_points_failed
   use hillstab_core_text, only: integer_text, real_text
   use hillstab_batch_run_scenes, only: run_scene_file
   use hillstab_batch_run_cli, only: printable
   use hillstab_testing
   use hillstab_test_files, only: run_text_scene, check_rerun
   use hillstab_test_progress, only: run_with_progress, progress_numbers
   use hillstab_test_scratch, only: padded, scratch_prefix, write_file, read_lines, file_exists, delete_file, contains_text, &
      c_getpid, any_temp_file
   use hillstab_test_bad_scenes, only: bad_case_t, bad_cases, bad_case_text, write_bad_points_files, &
      delete_bad_points_files
   use hillstab_batch_scene_group_chart, only: grid_value
   implicit none
   private
   public :: collect_tasks

contains

   function collect_tasks() result(suite)
      type(testsuite_t) :: suite
      suite = new_testsuite("tasks", [ &
         new_unittest("chart_layout", chart_layout), &
         new_unittest("chart_constant_coefficient", chart_constant_coefficient), &
         new_unittest("points_paper_formula", points_paper_formula), &
         new_unittest("coefficient_columns", coefficient_columns), &
         new_unittest("damped_verdicts", damped_verdicts), &
         new_unittest("overflow_clamped", overflow_clamped), &
         new_unittest("roundoff_limited_points_written", roundoff_limited_points_written), &
         new_unittest("failed_points_written", failed_points_written), &
         new_unittest("repeat_from_output", repeat_from_output), &
         new_unittest("physical_units", physical_units), &
         new_unittest("spring_k_m_and_range", spring_k_m_and_range), &
         new_unittest("chart_over_a_and_omega", chart_over_a_and_omega), &
         new_unittest("domain_notes", domain_notes), &
         new_unittest("chosen_columns_and_binary", chosen_columns_and_binary), &
         new_unittest("verdict_chart_matches_full", verdict_chart_matches_full), &
         new_unittest("log_chart_matches_points", log_chart_matches_points), &
         new_unittest("growth_columns_match_full", growth_columns_match_full), &
         new_unittest("columns_state_their_accuracy", columns_state_their_accuracy), &
         new_unittest("bad_input_touches_nothing", bad_input_touches_nothing), &
         new_unittest("planted_links_untouched", planted_links_untouched), &
         new_unittest("long_file_names", long_file_names), &
         new_unittest("messages_printable", messages_printable), &
         new_unittest("unwritable_output", unwritable_output), &
         new_unittest("progress_every_task", progress_every_task)])
   end function collect_tasks

   !> The numeric rows of a file: each must hold exactly `n_columns` numbers.
   subroutine data_rows(lines, n_columns, rows, n_blank, all_numeric)
      character(len=*), intent(in) :: lines(:)
      integer, intent(in) :: n_columns
      real(wp), allocatable, intent(out) :: rows(:, :)
      integer, intent(out) :: n_blank       !! blank lines between rows
      logical, intent(out) :: all_numeric   !! every data line has exactly n_columns numbers
      real(wp) :: values(n_columns + 1)
      integer :: k, n, ios
      allocate (rows(n_columns, size(lines)))
      n = 0
      n_blank = 0
      all_numeric = .true.
      do k = 1, size(lines)
         if (lines(k)(1:1) == "#") cycle
         if (len_trim(lines(k)) == 0) then
            n_blank = n_blank + 1
            cycle
         end if
         read (lines(k), *, iostat=ios) values(:n_columns)
         if (ios /= 0) all_numeric = .false.
         read (lines(k), *, iostat=ios) values
         if (ios == 0) all_numeric = .false.  ! one column too many
         n = n + 1
         rows(:, n) = values(:n_columns)
      end do
      rows = rows(:, :n)
   end subroutine data_rows

   !> The one `# columns:` line; empty when there is not exactly one.
   function columns_line(lines) result(columns)
      character(len=*), intent(in) :: lines(:)
      character(len=:), allocatable :: columns
      integer :: k, n
      columns = ""
      n = 0
      do k = 1, size(lines)
         if (index(lines(k), "# columns: ") == 1) then
            n = n + 1
            columns = trim(lines(k)(len("# columns: ") + 1:))
         end if
      end do
      if (n /= 1) columns = ""
   end function columns_line

   subroutine chart_layout(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(error_t), allocatable :: error
      character(len=:), allocatable :: written, out
      character(len=1024), allocatable :: lines(:)
      real(wp), allocatable :: rows(:, :)
      integer :: n_blank, k, first_data
      logical :: numeric
      real(wp), parameter :: block_alphas(3) = [1.0_wp, 5.0_wp, 9.0_wp]
      out = scratch_prefix("layout")
      call run_text_scene("layout", [ &
         padded("&scene method = 'segments', n_segments = 16, sampling = 'midpoint', output = '"//out//"' /"), &
         padded("&chart alpha_min = 1, alpha_max = 9, n_alpha = 3, beta_min = -1, beta_max = 11, n_beta = 4 /")], &
         error, written)
      call check(ctx, .not. allocated(error), "chart runs")
      if (allocated(error)) return
      call check(ctx, written == out//"_chart.dat", "file name <output>_chart.dat")
      lines = read_lines(written)
      call check(ctx, index(lines(1), "# hillstab 0.1.0") == 1, "version first: "//trim(lines(1)))
      call check(ctx, columns_line(lines) == &
                 "alpha beta S stable lambda_max mu log10_abs_S overflow physical error_estimate status", &
                 "exactly one columns line")
      call check(ctx, any(index(lines, "# &scene task = 'chart'") == 1), "effective &scene in the header")
      call check(ctx, any(index(lines, "# &chart alpha_min = 1.0, alpha_max = 9.0, n_alpha = 3") == 1), &
                 "effective &chart in the header")
      call check(ctx, any(index(lines, "leaves the physical domain") > 0), "outside-domain note")
      first_data = findloc(lines(:)(1:1) == "#", .false., dim=1)
      call check(ctx, all(lines(:first_data - 1)(1:1) == "#"), "header before data")
      call data_rows(lines, 11, rows, n_blank, numeric)
      call check(ctx, numeric, "every data line holds exactly 11 numbers")
      call check(ctx, size(rows, 2) == 12, "3 x 4 rows")
      call check(ctx, n_blank == 2, "one blank line between the 3 alpha blocks")
      if (size(rows, 2) /= 12) return
      ! blocks: alpha constant inside, beta running min..max
      do k = 1, 12
         call check(ctx, rows(1, k), block_alphas((k - 1)/4 + 1), message="alpha of the block")
         call check(ctx, rows(2, k), -1.0_wp + 4.0_wp*mod(k - 1, 4), rel=1.0e-15_wp, message="beta")
         call check(ctx, rows(4, k) == 0.0_wp .or. rows(4, k) == 1.0_wp, "stable flag 0/1")
         call check(ctx, (rows(4, k) == 1.0_wp) .eqv. (abs(rows(3, k)) < 2.0_wp), "stable iff |S| < 2")
         call check(ctx, rows(9, k) == merge(1.0_wp, 0.0_wp, rows(2, k) > 0.0_wp .and. rows(2, k) < pi2), &
                    "physical flag")
         ! segments gives no error estimate (it approximates Q, not the solution)
         call check(ctx, rows(10, k) == -1.0_wp, "error_estimate -1: not estimated")
         call check(ctx, rows(11, k) == 0.0_wp, "status 0")
      end do
      call delete_file(written)
   end subroutine chart_layout

   !> α = 0: Q ≡ β, S = 2 cos 2√β (2 cosh 2√−β for β < 0), |λ| and μ follow.
   subroutine chart_constant_coefficient(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(error_t), allocatable :: error
      character(len=:), allocatable :: written, out
      character(len=1024), allocatable :: lines(:)
      real(wp), allocatable :: rows(:, :)
      real(wp) :: beta, s, lambda
      integer :: n_blank, k
      logical :: numeric
      out = scratch_prefix("alpha0")
      call run_text_scene("alpha0", [ &
         padded("&scene method = 'segments', n_segments = 4, output = '"//out//"' /"), &
         padded("&chart alpha_min = 0, alpha_max = 0, n_alpha = 1, beta_min = -3, beta_max = 9, n_beta = 7 /")], &
         error, written)
      call check(ctx, .not. allocated(error), "chart runs")
      if (allocated(error)) return
      lines = read_lines(written)
      call data_rows(lines, 11, rows, n_blank, numeric)
      call check(ctx, numeric .and. size(rows, 2) == 7 .and. n_blank == 0, "7 rows, one block")
      do k = 1, size(rows, 2)
         beta = -3.0_wp + 2.0_wp*(k - 1)
         if (beta >= 0.0_wp) then
            s = 2.0_wp*cos(2.0_wp*sqrt(beta))
         else
            s = 2.0_wp*cosh(2.0_wp*sqrt(-beta))
         end if
         call check(ctx, rows(3, k), s, rel=1.0e-13_wp, abs=1.0e-13_wp, message="S at alpha = 0")
         lambda = 1.0_wp
         if (abs(s) > 2.0_wp) lambda = 0.5_wp*(abs(s) + sqrt(s*s - 4.0_wp))
         call check(ctx, rows(5, k), lambda, rel=1.0e-8_wp, message="lambda_max")
         call check(ctx, rows(6, k), 0.5_wp*log(lambda), abs=1.0e-9_wp, message="mu")
         call check(ctx, rows(7, k), log10(abs(s)), rel=1.0e-8_wp, abs=1.0e-9_wp, message="log10_abs_S")
         call check(ctx, rows(8, k) == 0.0_wp, "no overflow")
      end do
      call delete_file(written)
   end subroutine chart_constant_coefficient

   !> method = 'formula' through the points task, against eq. (37) in the paper's
   !> own notation (valid for β > α), points kept in file order.
   subroutine points_paper_formula(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(error_t), allocatable :: error
      character(len=:), allocatable :: written, out, points
      character(len=1024), allocatable :: lines(:)
      real(wp), allocatable :: rows(:, :)
      real(wp) :: alphas(4) = [1.48_wp, 0.5_wp, 2.0_wp, 1.0_wp], betas(4) = [2.47_wp, 6.0_wp, 9.0_wp, 1.29_wp]
      real(wp) :: b1, b2, s
      integer :: n_blank, k
      logical :: numeric
      out = scratch_prefix("pts")
      points = out//"_in.dat"
      call write_file(points, [character(len=40) :: "# alpha beta", "1.48 2.47 # (a)", "0.5 6.0", "", &
                                "2.0 9.0", "1.0 1.29"])
      call run_text_scene("pts", [ padded("&scene task = 'points', method = 'formula', output = '"// &
                                  out//"' /"), padded("&points file = '"//points//"' /")], error, written)
      call delete_file(points)
      call check(ctx, .not. allocated(error), "points run")
      if (allocated(error)) return
      call check(ctx, written == out//"_points.dat", "file name <output>_points.dat")
      lines = read_lines(written)
      call check(ctx, columns_line(lines) == &
                 "alpha beta S stable lambda_max mu log10_abs_S overflow physical error_estimate status", &
                 "same columns as the chart")
      call data_rows(lines, 11, rows, n_blank, numeric)
      call check(ctx, numeric .and. size(rows, 2) == 4, "one row per point")
      if (size(rows, 2) /= 4) return
      do k = 1, 4
         call check(ctx, rows(1, k), alphas(k), message="alpha in input order")
         call check(ctx, rows(2, k), betas(k), message="beta in input order")
         b1 = sqrt((betas(k) + alphas(k))/(1.0_wp + alphas(k)/pi2))
         b2 = sqrt((betas(k) - alphas(k))/(1.0_wp - alphas(k)/pi2))
         s = 2.0_wp*cos(b1)*cos(b2) - 2.0_wp*(betas(k) - alphas(k)**2/pi2) &
             /sqrt((betas(k)**2 - alphas(k)**2)*(1.0_wp - alphas(k)**2/pi2**2))*sin(b1)*sin(b2)
         call check(ctx, rows(3, k), s, rel=1.0e-12_wp, abs=1.0e-13_wp, message="eq. (37)")
      end do
      ! (1.48, 2.47) is unstable (Fig. 4a), (1.0, 1.29) stable by the paper's chart
      call check(ctx, rows(4, 1) == 0.0_wp, "point (a) unstable")
      call delete_file(written)
   end subroutine points_paper_formula

   !> Q(τ) of eq. (25) and its 2-piece endpoint version (eq. (28)); Mathieu with
   !> 4 averaged pieces gives β ∓ 2ν/π (the paper's (A18)).
   subroutine coefficient_columns(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(error_t), allocatable :: error
      character(len=:), allocatable :: written, out
      character(len=1024), allocatable :: lines(:)
      real(wp), allocatable :: rows(:, :)
      real(wp) :: tau, q, alpha, alphas(2) = [4.0_wp, 9.7_wp], beta
      integer :: n_blank, k, j
      logical :: numeric
      out = scratch_prefix("coef")
      beta = 6.0_wp
      call run_text_scene("coef", [ padded("&scene task = 'coefficient', output = '"//out//"' /"), &
                                   padded("&coefficient alphas = 4, 9.7, beta = 6, n_tau = 9 /")], error, written)
      call check(ctx, .not. allocated(error), "coefficient run")
      if (allocated(error)) return
      call check(ctx, written == out//"_coefficient.dat", "file name <output>_coefficient.dat")
      lines = read_lines(written)
      call check(ctx, columns_line(lines) == "tau Q(4.0) Qseg(4.0) Q(9.7) Qseg(9.7)", "columns: "//columns_line(lines))
      call data_rows(lines, 5, rows, n_blank, numeric)
      call check(ctx, numeric .and. size(rows, 2) == 9, "9 rows of 5 numbers")
      if (size(rows, 2) /= 9) return
      do k = 1, 9
         tau = 0.25_wp*(k - 1)
         call check(ctx, rows(1, k), tau, message="tau")
         do j = 1, 2
            alpha = alphas(j)
            q = (beta - alpha*cos(pi*tau))/(1.0_wp - alpha/pi2*cos(pi*tau))
            call check(ctx, rows(2*j, k), q, rel=1.0e-12_wp, abs=1.0e-12_wp, message="Q of eq. (25)")
            if (tau < 1.0_wp .or. tau >= 2.0_wp) then
               q = (beta - alpha)/(1.0_wp - alpha/pi2)
            else
               q = (beta + alpha)/(1.0_wp + alpha/pi2)
            end if
            call check(ctx, rows(2*j + 1, k), q, rel=1.0e-12_wp, message="Qseg of eq. (28)")
         end do
      end do
      call delete_file(written)

      call run_text_scene("coef", [ padded("&scene task = 'coefficient', model = 'mathieu', "// &
                                   "n_segments = 4, sampling = 'average', output = '"//out//"' /"), &
                                   padded("&coefficient alphas = 3, beta = 1, n_tau = 9, tau_max = 1.75 /")], error, written)
      call check(ctx, .not. allocated(error), "mathieu coefficient run")
      if (allocated(error)) return
      lines = read_lines(written)
      call data_rows(lines, 3, rows, n_blank, numeric)
      call check(ctx, numeric .and. size(rows, 2) == 9, "9 rows of 3 numbers")
      if (size(rows, 2) /= 9) return
      do k = 1, 9
         tau = 1.75_wp*(k - 1)/8
         call check(ctx, rows(2, k), 1.0_wp - 3.0_wp*cos(pi*tau), rel=1.0e-12_wp, abs=1.0e-14_wp, message="q of (A1)")
         q = 1.0_wp - 6.0_wp/pi*merge(1.0_wp, -1.0_wp, tau < 0.5_wp .or. tau >= 1.5_wp)
         call check(ctx, rows(3, k), q, rel=1.0e-12_wp, message="beta -+ 2 nu/pi")
      end do
      call delete_file(written)
   end subroutine coefficient_columns

   !> ε = 1: stable iff |S1| < 2 cosh 1, stable_paper iff |S1| <= 2; at α = 0,
   !> S1 = 2 cosh(2√(ε²/4 − β)) for β < ε²/4, so β ∈ (−0.93, 0.25) separates them.
   subroutine damped_verdicts(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(error_t), allocatable :: error
      character(len=:), allocatable :: written, out
      character(len=1024), allocatable :: lines(:)
      real(wp), allocatable :: rows(:, :)
      integer :: n_blank, k, n_differ
      logical :: numeric
      out = scratch_prefix("damped")
      call run_text_scene("damped", [ &
         padded("&scene method = 'segments', n_segments = 8, epsilon = 1, output = '"//out//"' /"), &
         padded("&chart alpha_min = 0, alpha_max = 6, n_alpha = 3, beta_min = -1, beta_max = 1, n_beta = 11 /")], &
         error, written)
      call check(ctx, .not. allocated(error), "damped chart runs")
      if (allocated(error)) return
      lines = read_lines(written)
      call check(ctx, columns_line(lines) == &
                 "alpha beta S stable lambda_max mu log10_abs_S overflow physical stable_paper error_estimate status", &
                 "12 columns")
      call data_rows(lines, 12, rows, n_blank, numeric)
      call check(ctx, numeric .and. size(rows, 2) == 33, "33 rows of 12 numbers")
      n_differ = 0
      do k = 1, size(rows, 2)
         call check(ctx, (rows(4, k) == 1.0_wp) .eqv. (abs(rows(3, k)) < 2.0_wp*cosh(1.0_wp)), "correct verdict")
         call check(ctx, (rows(10, k) == 1.0_wp) .eqv. (abs(rows(3, k)) <= 2.0_wp), "paper's verdict")
         call check(ctx, (rows(4, k) == 1.0_wp) .eqv. (rows(5, k) < 1.0_wp), "stable iff lambda_max < 1")
         if (rows(4, k) /= rows(10, k)) n_differ = n_differ + 1
      end do
      call check(ctx, n_differ >= 1, "the two verdicts differ somewhere")
      call check(ctx, rows(4, 7) == 1.0_wp .and. rows(10, 7) == 0.0_wp, "alpha = 0, beta = 0.2: stable, not by the paper")
      ! α = 0, β = 0.2: S1 = 2 cosh(2√0.05)
      call check(ctx, rows(3, 7), 2.0_wp*cosh(2.0_wp*sqrt(0.05_wp)), rel=1.0e-12_wp, message="S1 at alpha = 0")
      call delete_file(written)
   end subroutine damped_verdicts

   !> Mathieu formula at β = −1e6: S1 = 2 cosh 2000 overflows; written as 1e300
   !> with overflow = 1 and log10|S| = 2000/ln 10; no Inf/NaN text anywhere.
   !> A chart whose tolerance lies below the round-off level at some points (β = 0,
   !> α → π², tolerance 1e-12, where S = 2 exactly) still runs and writes those points,
   !> with S as good as double precision allows (the warning goes to stderr).
   subroutine roundoff_limited_points_written(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(error_t), allocatable :: error
      character(len=:), allocatable :: written, out
      character(len=1024), allocatable :: lines(:)
      real(wp), allocatable :: rows(:, :)
      integer :: n_blank
      logical :: numeric
      out = scratch_prefix("roundoff")
      call run_text_scene("roundoff", [ &
         padded("&scene method = 'auto', tolerance = 1e-12, output = '"//out//"' /"), &
         padded("&chart alpha_min = 9.85, alpha_max = 9.86, n_alpha = 2, beta_min = 0, beta_max = 1, n_beta = 2 /")], &
         error, written)
      call check(ctx, .not. allocated(error), "chart runs")
      if (allocated(error)) return
      lines = read_lines(written)
      call data_rows(lines, 11, rows, n_blank, numeric)
      call check(ctx, numeric .and. size(rows, 2) == 4, "4 rows")
      if (size(rows, 2) /= 4) return
      ! β = 0 rows: S = 2 exactly (x = r(τ) is 2-periodic); round-off level ~1e-10 here
      call check(ctx, rows(3, 1), 2.0_wp, abs=1.0e-8_wp, message="S at alpha 9.85, beta 0")
      call check(ctx, rows(3, 3), 2.0_wp, abs=1.0e-8_wp, message="S at alpha 9.86, beta 0")
      ! their status says round-off limited, with an error estimate above the tolerance that
      ! does bound the error; the β = 1 rows meet the tolerance
      call check(ctx, rows(11, 1) == 1.0_wp .and. rows(11, 3) == 1.0_wp, "status 1 at beta = 0")
      call check(ctx, rows(10, 1) > 1.0e-12_wp .and. rows(10, 3) > 1.0e-12_wp, "estimate above the tolerance")
      call check(ctx, abs(rows(3, 1) - 2.0_wp) <= 0.5_wp*rows(10, 1), "error within the estimate, alpha 9.85")
      call check(ctx, abs(rows(3, 3) - 2.0_wp) <= 0.5_wp*rows(10, 3), "error within the estimate, alpha 9.86")
      call check(ctx, rows(11, 2) == 0.0_wp .and. rows(11, 4) == 0.0_wp, "status 0 at beta = 1")
      ! the verdict at beta = 0 (exact S = 2) is marginal, not flipped by the round-off in S
      call check(ctx, rows(4, 1) == 0.5_wp .and. rows(4, 3) == 0.5_wp, "marginal (stable = 0.5) at beta = 0")
      call check(ctx, rows(4, 2) == 0.0_wp .and. rows(4, 4) == 0.0_wp, "unstable at beta = 1")
      call check(ctx, rows(10, 2) <= 1.0e-12_wp .and. rows(10, 2) >= 0.0_wp .and. rows(10, 4) <= 1.0e-12_wp &
                 .and. rows(10, 4) >= 0.0_wp, "estimate within the tolerance at beta = 1")
      call delete_file(written)
   end subroutine roundoff_limited_points_written

   !> A point no method run can compute (α = 9.8696, β = 1e13: neither auto's mesh nor
   !> adaptive Magnus-6 leaves a digit of S, round-off level 9e293) does not stop the run: points and chart files are written, the failed
   !> rows carry status 2 and placeholders outside every column's range, the other rows
   !> are computed as usual, and the run reports err_points_failed naming the point.
   subroutine failed_points_written(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(error_t), allocatable :: error
      character(len=:), allocatable :: written, out, points
      character(len=1024), allocatable :: lines(:)
      real(wp), allocatable :: rows(:, :)
      integer :: n_blank, k
      logical :: numeric
      out = scratch_prefix("failedpts")
      points = out//"_in.dat"
      call write_file(points, [character(len=40) :: "5.0 2.47", "9.8696 1e13", "0.0 2.0"])
      call run_text_scene("failedpts", [padded("&scene task = 'points', method = 'auto', output = '"// &
                                         out//"' /"), padded("&points file = '"//points//"' /")], error, written)
      call delete_file(points)
      call check(ctx, allocated(error), "the run reports the failure")
      if (.not. allocated(error)) return
      call check(ctx, error%code == err_points_failed, "err_points_failed")
      call check(ctx, contains_text(error%message, "1 of 3 point"), "counts the failed points: "//error%message)
      call check(ctx, contains_text(error%message, "beta = 10000000000000.0"), "names the point: "//error%message)
      call check(ctx, file_exists(out//"_points.dat"), "the file is written")
      lines = read_lines(out//"_points.dat")
      call data_rows(lines, 11, rows, n_blank, numeric)
      call check(ctx, numeric .and. size(rows, 2) == 3, "3 rows of 11 numbers")
      if (size(rows, 2) /= 3) return
      call check(ctx, rows(11, 1) == 0.0_wp .and. rows(11, 3) == 0.0_wp, "status 0 elsewhere")
      call check(ctx, rows(3, 3), 2.0_wp*cos(2.0_wp*sqrt(2.0_wp)), rel=1.0e-12_wp, message="S at alpha = 0")
      call check(ctx, rows(10, 1) >= 0.0_wp .and. rows(10, 1) <= 1.0e-10_wp, "estimate within the tolerance")
      call check(ctx, rows(11, 2) == 2.0_wp, "status 2 at the failed point")
      call check(ctx, rows(1, 2) == 9.8696_wp .and. rows(2, 2) == 1.0e13_wp, "alpha, beta of the failed point")
      call check(ctx, rows(3, 2) == 0.0_wp .and. rows(6, 2) == 0.0_wp, "S, mu placeholders 0")
      call check(ctx, rows(4, 2) == -1.0_wp .and. rows(8, 2) == -1.0_wp, "flags -1")
      call check(ctx, rows(5, 2) == -1.0_wp, "lambda_max -1")
      call check(ctx, rows(7, 2) == -999.0_wp, "log10_abs_S -999")
      call check(ctx, rows(9, 2) == 0.0_wp, "physical as for any point (beta > pi^2)")
      call check(ctx, rows(10, 2) == -1.0_wp, "error_estimate -1")
      do k = 1, size(lines)
         call check(ctx, index(lines(k), "Inf") == 0 .and. index(lines(k), "NaN") == 0 .and. &
                    index(lines(k), "nan") == 0 .and. index(lines(k), "inf") == 0, "no Inf/NaN text")
      end do
      call delete_file(out//"_points.dat")

      ! the chart path (rows in parallel, lines formatted on every thread), damped: 12 columns
      call run_text_scene("failedchart", [ &
         padded("&scene method = 'auto', epsilon = 0.5, output = '"//out//"' /"), &
         padded("&chart alpha_min = 9.8696, alpha_max = 9.8696, n_alpha = 1, beta_min = 1, beta_max = 1e13, n_beta = 2 /")], &
         error, written)
      call check(ctx, allocated(error), "the chart reports the failure")
      if (.not. allocated(error)) return
      call check(ctx, error%code == err_points_failed, "err_points_failed (chart)")
      call check(ctx, contains_text(error%message, "1 of 2 point"), "counts the failed points: "//error%message)
      lines = read_lines(out//"_chart.dat")
      call data_rows(lines, 12, rows, n_blank, numeric)
      call check(ctx, numeric .and. size(rows, 2) == 2 .and. n_blank == 0, "2 rows of 12 numbers")
      if (size(rows, 2) /= 2) return
      call check(ctx, rows(12, 1) == 0.0_wp .and. rows(12, 2) == 2.0_wp, "statuses 0, 2")
      call check(ctx, rows(10, 2) == -1.0_wp, "stable_paper -1 at the failed point")
      call check(ctx, rows(10, 1) >= 0.0_wp, "stable_paper a flag elsewhere")
      call delete_file(written)
   end subroutine failed_points_written

   subroutine overflow_clamped(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(error_t), allocatable :: error
      character(len=:), allocatable :: written, out
      character(len=1024), allocatable :: lines(:)
      real(wp), allocatable :: rows(:, :)
      integer :: n_blank, k
      logical :: numeric
      out = scratch_prefix("overflow")
      call run_text_scene("overflow", [ &
         padded("&scene model = 'mathieu', method = 'formula', output = '"//out//"' /"), &
         padded("&chart alpha_min = 0, alpha_max = 0, n_alpha = 1, beta_min = -1e6, beta_max = 1, n_beta = 2 /")], &
         error, written)
      call check(ctx, .not. allocated(error), "chart runs")
      if (allocated(error)) return
      lines = read_lines(written)
      ! the Mathieu model's files have no physical column
      call data_rows(lines, 10, rows, n_blank, numeric)
      call check(ctx, numeric .and. size(rows, 2) == 2, "2 rows of 10 numbers")
      if (size(rows, 2) /= 2) return
      call check(ctx, rows(3, 1), 1.0e300_wp, rel=1.0e-15_wp, message="S clamped")
      call check(ctx, rows(8, 1) == 1.0_wp .and. rows(8, 2) == 0.0_wp, "overflow flags")
      call check(ctx, rows(7, 1), 2000.0_wp/log(10.0_wp), rel=1.0e-9_wp, message="log10|S| exact")
      call check(ctx, rows(5, 1), 1.0e300_wp, rel=1.0e-9_wp, message="lambda_max clamped")
      call check(ctx, rows(6, 1), 1000.0_wp, rel=1.0e-9_wp, message="mu = ln(lambda)/2")
      call check(ctx, rows(4, 1) == 0.0_wp, "unstable")
      do k = 1, size(lines)
         call check(ctx, index(lines(k), "Inf") == 0 .and. index(lines(k), "NaN") == 0 .and. &
                    index(lines(k), "Infinity") == 0, "no Inf/NaN text")
      end do
      call delete_file(written)
   end subroutine overflow_clamped

   !> Running an output file as the scene repeats the run: same file, line for line
   !> (except the line naming the scene file).
   subroutine repeat_from_output(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(error_t), allocatable :: error
      character(len=:), allocatable :: written, out, again
      character(len=1024), allocatable :: first(:)
      logical :: ok
      out = scratch_prefix("repeat")
      call run_text_scene("repeat", [ &
         padded("&scene method = 'segments', n_segments = 32, sampling = 'average', epsilon = 0.25,"), &
         padded("  output = '"//out//"' /"), &
         padded("&chart alpha_min = 0.3, alpha_max = 9.7, n_alpha = 2, beta_min = 0.1, beta_max = 9.3, n_beta = 3 /")], &
         error, written)
      call check(ctx, .not. allocated(error), "first run")
      if (allocated(error)) return
      first = read_lines(written)
      call check_rerun(ctx, written, first, again, ok)
      if (.not. ok) return
      call check(ctx, again == written, "same output name")
      call check(ctx, .not. any(index(first, "leaves the physical domain") > 0), "inside the physical domain")
      call delete_file(written)
   end subroutine repeat_from_output

   !> A points run in physical units: α and β from eqs. (4), (24) computed here, the
   !> mu_per_s column = μ ω/π, the same file again from the output file, and the Mathieu
   !> model given ν = α (1 − β/π²) of eq. (21).
   subroutine physical_units(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(error_t), allocatable :: error
      character(len=:), allocatable :: written, out, again
      character(len=1024), allocatable :: first(:)
      real(wp), allocatable :: rows(:, :)
      real(wp), parameter :: omega = 10.0_wp, g = 9.81_wp, r0 = 0.3_wp, amplitudes(3) = [0.05_wp, 0.2_wp, 0.3_wp]
      real(wp) :: rho, beta
      integer :: n_blank, k
      logical :: numeric, ok
      out = scratch_prefix("physical")
      call run_text_scene("physical", [ &
         padded("&scene task = 'points', method = 'magnus6', tolerance = 1e-9, output = '"//out//"' /"), &
         padded("&physical omega = 10, g = 9.81, r0 = 0.3, a = 0.05, 0.2, 0.3 /")], error, written)
      call check(ctx, .not. allocated(error), "physical points run")
      if (allocated(error)) then
         call check(ctx, .false., error%message)
         return
      end if
      first = read_lines(written)
      call check(ctx, columns_line(first) == "alpha a beta S stable lambda_max mu log10_abs_S overflow physical "// &
                 "mu_per_s error_estimate status", &
                 "columns: "//columns_line(first))
      call data_rows(first, 13, rows, n_blank, numeric)
      call check(ctx, numeric .and. size(rows, 2) == 3, "three rows of 13 numbers")
      if (size(rows, 2) /= 3) return
      rho = r0 + g/omega**2
      beta = g*pi2/(rho*omega**2)
      do k = 1, 3
         call check(ctx, rows(1, k), amplitudes(k)*pi2/rho, rel=1.0e-14_wp, message="alpha = a pi^2/rho")
         call check(ctx, rows(2, k), amplitudes(k), rel=1.0e-15_wp, message="a as given")
         call check(ctx, rows(3, k), beta, rel=1.0e-14_wp, message="beta = g pi^2/(rho omega^2)")
         call check(ctx, rows(11, k), rows(7, k)*omega/pi, rel=1.0e-9_wp, abs=1.0e-300_wp, message="mu_per_s")
      end do
      call check(ctx, rows(11, 3) > 0.0_wp, "a = 0.3 m grows")
      call check_rerun(ctx, written, first, again, ok)
      if (.not. ok) return
      call delete_file(written)
      ! Mathieu: the first column is nu, no physical column
      call run_text_scene("physical_m", [ &
         padded("&scene task = 'points', model = 'mathieu', method = 'magnus6', output = '"//out//"' /"), &
         padded("&physical omega = 10, g = 9.81, r0 = 0.3, a = 0.05, 0.2, 0.3, kappa = 0.5 /")], error, written)
      call check(ctx, .not. allocated(error), "physical Mathieu points run")
      if (allocated(error)) return
      first = read_lines(written)
      call check(ctx, columns_line(first) == "alpha a beta S stable lambda_max mu log10_abs_S overflow stable_paper "// &
                 "mu_per_s error_estimate status", "Mathieu columns: "//columns_line(first))
      call data_rows(first, 13, rows, n_blank, numeric)
      call check(ctx, numeric .and. size(rows, 2) == 3, "three rows of 13 numbers")
      if (size(rows, 2) /= 3) return
      do k = 1, 3
         call check(ctx, rows(1, k), amplitudes(k)*pi2/rho*(1.0_wp - beta/pi2), rel=1.0e-14_wp, message="nu")
         call check(ctx, rows(2, k), amplitudes(k), rel=1.0e-15_wp, message="Mathieu: a as given")
      end do
      call check(ctx, any(index(first, "# &physical omega = 10.0, g = 9.81, kappa = 0.5, r0 = 0.3, a = 0.05, 0.2, "// &
                 "0.3 /") == 1), "effective &physical in the header")
      call check(ctx, .not. any(index(first, "epsilon = 0.") > 0 .and. index(first, "# &scene") == 1), &
                 "no epsilon in &scene when kappa gives it")
      call delete_file(written)
      ! a chart with &physical omega, kappa: where the swing is stable its amplitude decays as
      ! e^{-kappa t/2} (x = e^{-eps tau/2} chi, |chi| bounded), so mu_per_s = -kappa/2 exactly
      call run_text_scene("physical_c", [ &
         padded("&scene method = 'formula', output = '"//out//"' /"), &
         padded("&chart alpha_min = 0, alpha_max = 9, n_alpha = 3, beta_min = 1, beta_max = 12, n_beta = 5 /"), &
         padded("&physical omega = 5, kappa = 0.5 /")], error, written)
      call check(ctx, .not. allocated(error), "physical chart run")
      if (allocated(error)) return
      first = read_lines(written)
      call check(ctx, columns_line(first) == "alpha a beta S stable lambda_max mu log10_abs_S overflow physical "// &
                 "stable_paper mu_per_s error_estimate status", "chart columns: "//columns_line(first))
      call data_rows(first, 14, rows, n_blank, numeric)
      call check(ctx, numeric .and. size(rows, 2) == 15, "15 rows of 14 numbers")
      call check(ctx, count(rows(5, :) == 1.0_wp) >= 3, "some stable points")
      do k = 1, size(rows, 2)
         if (rows(5, k) == 1.0_wp) call check(ctx, rows(12, k), -0.25_wp, rel=1.0e-9_wp, message="decay -kappa/2")
         if (rows(5, k) == 0.0_wp) call check(ctx, rows(12, k) > -0.25_wp, "unstable: slower decay or growth")
         ! a = alpha rho/pi^2 with rho = g pi^2/(beta omega^2), g the default 9.80665
         call check(ctx, rows(2, k), rows(1, k)*9.80665_wp/(rows(3, k)*25.0_wp), rel=1.0e-14_wp, abs=1.0e-300_wp, &
                    message="chart a = alpha g/(beta omega^2)")
      end do
      call delete_file(written)
   end subroutine physical_units

   !> A spring given by k and m with a range of amplitudes: the rows are those of the same
   !> spring given by omega = sqrt(k/m) with the list of the same amplitudes (apart from
   !> the header's spring line); a is the range written out here, alpha = a pi^2/rho with
   !> rho = r0 + m g/k (eq. (4)); the header states k, m, omega, rho and the radial period;
   !> the file repeats its run.
   subroutine spring_k_m_and_range(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(error_t), allocatable :: error
      character(len=:), allocatable :: written, by_omega, out, again
      character(len=1024), allocatable :: first(:), second(:)
      real(wp), allocatable :: rows(:, :), rows_omega(:, :)
      real(wp), parameter :: k_spring = 25.0_wp, mass = 0.25_wp, g = 9.81_wp, r0 = 0.3_wp
      real(wp) :: rho, a
      integer :: n_blank, j
      logical :: numeric, ok
      out = scratch_prefix("spring_km")
      call run_text_scene("spring_km", [ &
         padded("&scene task = 'points', method = 'magnus6', tolerance = 1e-9, output = '"//out//"' /"), &
         padded("&physical k = 25, m = 0.25, g = 9.81, r0 = 0.3, a_min = 0.01, a_max = 0.35, n_a = 5 /")], &
         error, written)
      call check(ctx, .not. allocated(error), "k, m, a range run")
      if (allocated(error)) then
         call check(ctx, .false., error%message)
         return
      end if
      first = read_lines(written)
      call data_rows(first, 13, rows, n_blank, numeric)
      call check(ctx, numeric .and. size(rows, 2) == 5, "five rows of 13 numbers")
      if (size(rows, 2) /= 5) return
      rho = r0 + mass*g/k_spring
      do j = 1, 5
         a = 0.01_wp + (0.35_wp - 0.01_wp)*real(j - 1, wp)/4.0_wp
         call check(ctx, rows(2, j), a, rel=1.0e-15_wp, message="a of the range")
         call check(ctx, rows(1, j), a*pi2/rho, rel=1.0e-14_wp, message="alpha = a pi^2/(r0 + m g/k)")
         call check(ctx, rows(3, j), g*pi2*mass/(rho*k_spring), rel=1.0e-14_wp, message="beta = g pi^2 m/(rho k)")
      end do
      call check(ctx, any(index(first, "# spring: k = 25.0 N/m, m = 0.25 kg, omega = sqrt(k/m) = 10.0 rad/s") == 1), &
                 "header states k, m, omega")
      call check(ctx, any(index(first, "rho = r0 + g/omega^2 = 0.3981 m") > 0), "header states rho")
      call check(ctx, any(index(first, "radial period 2 pi/omega = 0.6283185307179586 s") > 0), &
                 "header states the radial period")
      call check(ctx, any(index(first, "# &physical k = 25.0, m = 0.25, g = 9.81, kappa = 0.0, r0 = 0.3, "// &
                 "a_min = 0.01, a_max = 0.35, n_a = 5 /") == 1), "effective &physical")
      call check_rerun(ctx, written, first, again, ok)
      if (ok) call delete_file(again)
      ! the same spring by omega and the list of the same amplitudes: the same rows
      call run_text_scene("spring_om", [ &
         padded("&scene task = 'points', method = 'magnus6', tolerance = 1e-9, output = '"//out//"_om' /"), &
         padded("&physical omega = 10, g = 9.81, r0 = 0.3, a = 0.01, 0.095, 0.18, 0.265, 0.35 /")], &
         error, by_omega)
      call check(ctx, .not. allocated(error), "omega run")
      if (allocated(error)) return
      second = read_lines(by_omega)
      call data_rows(second, 13, rows_omega, n_blank, numeric)
      call check(ctx, size(rows_omega, 2) == 5, "five rows by omega")
      if (size(rows_omega, 2) == 5) then
         do j = 1, 5
            call check(ctx, all(abs(rows(:, j) - rows_omega(:, j)) <= 1.0e-15_wp*max(1.0_wp, abs(rows(:, j)))), &
                       "row by k, m = row by omega")
         end do
      end if
      call delete_file(written)
      call delete_file(by_omega)
   end subroutine spring_k_m_and_range

   !> A chart over (a, omega) of &physical (r0, g fixed): blocks of constant a, every row's
   !> a, omega, alpha = a pi^2/rho, beta = g pi^2/(rho omega^2) with rho = r0 + g/omega^2
   !> written out here, mu_per_s = mu omega/pi at the row's omega; the point at omega = 10 is
   !> the points run of that spring (the same S).
   subroutine chart_over_a_and_omega(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(error_t), allocatable :: error
      character(len=:), allocatable :: written, out
      character(len=1024), allocatable :: lines(:)
      real(wp), allocatable :: rows(:, :), spring(:, :)
      real(wp), parameter :: g = 9.81_wp, r0 = 0.3_wp
      real(wp) :: a, omega, rho, beta_range(2)
      integer :: n_blank, i, j, k
      logical :: numeric
      character(len=:), allocatable :: prefix
      character(len=8) :: text
      out = scratch_prefix("a_omega")
      call run_text_scene("a_omega", [ &
         padded("&scene method = 'magnus6', tolerance = 1e-9, output = '"//out//"' /"), &
         padded("&physical g = 9.81, r0 = 0.3, a_min = 0.0, a_max = 0.2, n_a = 3, omega_min = 8, omega_max = 12, "// &
                "n_omega = 3 /")], error, written)
      call check(ctx, .not. allocated(error), "chart over (a, omega)")
      if (allocated(error)) then
         call check(ctx, .false., error%message)
         return
      end if
      lines = read_lines(written)
      ! the header states the spring in SI, with its loaded length and beta over the range of omega
      prefix = "# spring: omega = 8.0 ... 12.0 rad/s (3 values, the chart's second axis), r0 = 0.3 m, g = 9.81 "// &
         "m/s^2; rho = r0 + g/omega^2 from "//real_text(r0 + g/64.0_wp)//" m down to "//real_text(r0 + g/144.0_wp)// &
         " m, beta = g pi^2/(rho omega^2) from "
      k = findloc(index(lines, prefix), 1, dim=1)
      call check(ctx, k > 0, "the spring line of the header")
      if (k > 0) then
         read (lines(k)(len(prefix) + 1:), *, iostat=i) beta_range(1), text, text, beta_range(2)
         call check(ctx, i == 0 .and. text == "to", "beta from ... down to ...: "//trim(lines(k)))
         call check(ctx, beta_range(1), g*pi2/((r0 + g/64.0_wp)*64.0_wp), rel=1.0e-14_wp, message="beta at omega_min")
         call check(ctx, beta_range(2), g*pi2/((r0 + g/144.0_wp)*144.0_wp), rel=1.0e-14_wp, message="beta at omega_max")
      end if
      call check(ctx, columns_line(lines) == "alpha a beta omega S stable lambda_max mu log10_abs_S overflow "// &
                 "physical mu_per_s error_estimate status", "columns: "//columns_line(lines))
      call data_rows(lines, 14, rows, n_blank, numeric)
      call check(ctx, numeric .and. size(rows, 2) == 9 .and. n_blank == 2, "3 blocks of 3 rows")
      if (size(rows, 2) /= 9) return
      do i = 1, 3
         do j = 1, 3
            k = 3*(i - 1) + j
            a = 0.1_wp*real(i - 1, wp)
            omega = 8.0_wp + 2.0_wp*real(j - 1, wp)
            rho = r0 + g/omega**2
            call check(ctx, rows(2, k), a, rel=1.0e-15_wp, abs=1.0e-300_wp, message="a of the block")
            call check(ctx, rows(4, k), omega, rel=1.0e-15_wp, message="omega of the row")
            call check(ctx, rows(1, k), a*pi2/rho, rel=1.0e-14_wp, abs=1.0e-300_wp, message="alpha = a pi^2/rho")
            call check(ctx, rows(3, k), g*pi2/(rho*omega**2), rel=1.0e-14_wp, message="beta")
            call check(ctx, rows(12, k), rows(8, k)*omega/pi, rel=1.0e-9_wp, abs=1.0e-300_wp, message="mu_per_s")
            call check(ctx, rows(11, k) == 1.0_wp .and. rows(14, k) == 0.0_wp, "physical, status 0")
         end do
      end do
      call delete_file(written)
      ! the spring omega = 10 at a = 0.1 as a points run
      call run_text_scene("a_omega_p", [ &
         padded("&scene task = 'points', method = 'magnus6', tolerance = 1e-9, output = '"//out//"' /"), &
         padded("&physical omega = 10, g = 9.81, r0 = 0.3, a = 0.1 /")], error, written)
      call check(ctx, .not. allocated(error), "the spring of the middle row")
      if (allocated(error)) return
      lines = read_lines(written)
      call data_rows(lines, 13, spring, n_blank, numeric)
      if (size(spring, 2) == 1) call check(ctx, rows(5, 5), spring(4, 1), rel=1.0e-15_wp, message="the same S")
      call delete_file(written)
   end subroutine chart_over_a_and_omega

   !> `columns` picks and orders columns with the same text as the full file; `names_line`
   !> adds one uncommented line of names; `format = 'binary'` writes the same values as
   !> float64 records after a text header whose skip count is right; a binary file given
   !> back as a scene repeats the run byte for byte after the header.
   subroutine chosen_columns_and_binary(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(error_t), allocatable :: error
      character(len=:), allocatable :: full_path, picked_path, binary_path, again, out, text
      character(len=1024), allocatable :: full(:), picked(:)
      real(wp), allocatable :: full_rows(:, :), picked_rows(:, :), records(:, :), records_again(:, :)
      character(len=*), parameter :: chart = &
         "&chart alpha_min = 1, alpha_max = 9.86, n_alpha = 3, beta_min = 0, beta_max = 11, n_beta = 4 /"
      integer :: n_blank, k, c, header_bytes, first_data
      logical :: numeric
      out = scratch_prefix("columns")
      call run_text_scene("columns1", [padded("&scene method = 'auto', output = '"//out//"_full' /"), &
                                       padded(chart)], error, full_path)
      call check(ctx, .not. allocated(error), "full chart")
      if (allocated(error)) return
      call run_text_scene("columns2", [padded("&scene method = 'auto', output = '"//out//"_picked',"), &
                                       padded("  columns = 'mu Alpha, stable beta', names_line = .true. /"), &
                                       padded(chart)], error, picked_path)
      call check(ctx, .not. allocated(error), "chart with chosen columns")
      if (allocated(error)) return
      full = read_lines(full_path)
      picked = read_lines(picked_path)
      call check(ctx, columns_line(picked) == "mu alpha stable beta", "columns line: "//columns_line(picked))
      first_data = findloc(picked(:)(1:1) == "#", .false., dim=1)
      call check(ctx, picked(first_data) == "mu alpha stable beta", "names line after the header: "// &
                 trim(picked(first_data)))
      call data_rows(full, 11, full_rows, n_blank, numeric)
      call check(ctx, numeric .and. size(full_rows, 2) == 12, "full: 12 rows of 11")
      call data_rows(picked(first_data + 1:), 4, picked_rows, n_blank, numeric)
      call check(ctx, numeric .and. size(picked_rows, 2) == 12 .and. n_blank == 2, "picked: 12 rows of 4, 3 blocks")
      if (size(full_rows, 2) /= 12 .or. size(picked_rows, 2) /= 12) return
      call check(ctx, all(picked_rows(1, :) == full_rows(6, :)) .and. all(picked_rows(2, :) == full_rows(1, :)) .and. &
                 all(picked_rows(3, :) == full_rows(4, :)) .and. all(picked_rows(4, :) == full_rows(2, :)), &
                 "the same values in the chosen order")
      ! beta = 0 is S = 2 exactly: marginal at least at alpha = 9.86
      call check(ctx, picked_rows(3, 9) == 0.5_wp, "marginal point at alpha = 9.86, beta = 0")

      call run_text_scene("columns3", [padded("&scene method = 'auto', output = '"//out//"_bin', format = 'binary' /"), &
                                       padded(chart)], error, binary_path)
      call check(ctx, .not. allocated(error), "binary chart")
      if (allocated(error)) return
      call check(ctx, binary_path == out//"_bin_chart.bin", "binary file name")
      call read_binary(binary_path, 11, records, header_bytes, text)
      call check(ctx, index(text, "skip="//integer_text(header_bytes)//" ") > 0, &
                 "the header states its own length: "//integer_text(header_bytes))
      call check(ctx, size(records, 2) == 12, "12 records of 11")
      if (size(records, 2) /= 12) return
      ! the text holds 17 significant digits of alpha, beta, S (which read back to the same
      ! doubles), 11 of lambda_max, mu, log10_abs_S, 4 of error_estimate; the binary file the
      ! full values
      do k = 1, 12
         do c = 1, 3
            call check(ctx, records(c, k) == full_rows(c, k), "alpha beta S: the text reads back to the binary value")
         end do
         do c = 5, 7
            call check(ctx, records(c, k), full_rows(c, k), rel=1.0e-9_wp, abs=1.0e-300_wp, &
                       message="lambda_max mu log10_abs_S")
         end do
         call check(ctx, records(10, k), full_rows(10, k), rel=1.0e-2_wp, message="error_estimate")
         call check(ctx, all(records([4, 8, 9, 11], k) == full_rows([4, 8, 9, 11], k)), "flags and status")
      end do
      call run_scene_file(binary_path, .true., error, again)
      call check(ctx, .not. allocated(error), "second run from the binary file")
      if (allocated(error)) then
         call check(ctx, .false., error%message)
         return
      end if
      call read_binary(again, 11, records_again, header_bytes, text)
      call check(ctx, size(records_again, 2) == 12, "same size again")
      if (size(records_again, 2) == 12) call check(ctx, all(records_again == records), "same records again")
      call delete_file(full_path)
      call delete_file(picked_path)
      call delete_file(binary_path)
   contains
      !> Records of a binary output file: the header ends after the `# columns:` line.
      subroutine read_binary(path, n_columns, records, header_bytes, header)
         character(len=*), intent(in) :: path
         integer, intent(in) :: n_columns
         real(wp), allocatable, intent(out) :: records(:, :)
         integer, intent(out) :: header_bytes
         character(len=:), allocatable, intent(out) :: header
         integer :: unit, size_bytes, at
         character(len=:), allocatable :: bytes
         open (newunit=unit, file=path, access="stream", form="unformatted", status="old", action="read")
         inquire (unit=unit, size=size_bytes)
         allocate (character(len=size_bytes) :: bytes)
         read (unit) bytes
         at = index(bytes, new_line("a")//"# columns:")
         header_bytes = at + index(bytes(at + 1:), new_line("a"))
         header = bytes(:header_bytes)
         allocate (records(n_columns, (size_bytes - header_bytes)/(8*n_columns)))
         read (unit, pos=header_bytes + 1) records
         close (unit)
      end subroutine read_binary
   end subroutine chosen_columns_and_binary

   !> The physical-domain note only where it means something: not for the Mathieu model,
   !> not for a chart starting at beta = 0 (no gravity); yes above beta = pi**2.
   subroutine domain_notes(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=:), allocatable :: out
      out = scratch_prefix("notes")
      call check_note("notes1", "&scene model = 'mathieu', method = 'formula', output = '"//out//"' /", &
         "&chart alpha_min = 0, alpha_max = 12, n_alpha = 2, beta_min = -2, beta_max = 12, n_beta = 2 /", &
         "physical", .false., "Mathieu chart", "no physical column or note for Mathieu")
      call check_note("notes2", "&scene method = 'formula', output = '"//out//"' /", &
         "&chart alpha_min = 0, alpha_max = 9, n_alpha = 2, beta_min = 0, beta_max = 9, n_beta = 2 /", &
         "leaves the physical domain", .false., "chart from beta = 0", "beta = 0 is physical (g = 0)")
      call check_note("notes3", "&scene method = 'formula', output = '"//out//"' /", &
         "&chart alpha_min = 0, alpha_max = 9, n_alpha = 2, beta_min = 0, beta_max = 10, n_beta = 2 /", &
         "leaves the physical domain", .true., "chart to beta = 10", "beta > pi**2 leaves it")
   contains
      !> Run the scene (two lines); the file mentions `text` exactly when `expected`.
      subroutine check_note(name, scene_line, chart_line, text, expected, run_label, label)
         character(len=*), intent(in) :: name, scene_line, chart_line, text, run_label, label
         logical, intent(in) :: expected
         type(error_t), allocatable :: error
         character(len=:), allocatable :: written
         character(len=1024), allocatable :: lines(:)
         call run_text_scene(name, [padded(scene_line), padded(chart_line)], error, written)
         call check(ctx, .not. allocated(error), run_label)
         if (allocated(error)) return
         lines = read_lines(written)
         call check(ctx, any(index(lines, text) > 0) .eqv. expected, label)
         call delete_file(written)
      end subroutine check_note
   end subroutine domain_notes

   !> Every bad scene of the scene suite: an error, no output file created, an
   !> existing output file unchanged, no temporary file left.
   subroutine bad_input_touches_nothing(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(bad_case_t), allocatable :: cases(:)
      type(error_t), allocatable :: error
      character(len=:), allocatable :: written, out, dir, text
      character(len=1024), allocatable :: kept(:)
      character(len=*), parameter :: tasks(3) = [character(len=11) :: "chart", "points", "coefficient"]
      integer :: k, t
      out = scratch_prefix("keep")
      dir = scratch_prefix("keeppts")
      call write_bad_points_files(dir)
      cases = bad_cases()
      do k = 1, size(cases)
         text = bad_case_text(cases(k), out, dir)
         ! an existing chart file must survive; the other tasks' files must not appear
         call write_file(out//"_chart.dat", ["sentinel"])
         call run_text_scene("badrun", [text], error, written)
         call check(ctx, allocated(error), "error for "//text)
         kept = read_lines(out//"_chart.dat")
         call check(ctx, size(kept) == 1, "existing file untouched: "//text)
         if (size(kept) == 1) call check(ctx, kept(1) == "sentinel", "existing file untouched: "//text)
         do t = 1, 3
            call check(ctx, .not. any_temp_file(out//"_"//trim(tasks(t))//".dat"), "no temporary file")
            if (t > 1) call check(ctx, .not. file_exists(out//"_"//trim(tasks(t))//".dat"), "no file created: "//text)
         end do
      end do
      call delete_file(out//"_chart.dat")
      call delete_bad_points_files(dir)
   end subroutine bad_input_touches_nothing

   !> Links planted where a writer might write: a symbolic link at the temporary name
   !> older versions used (`<file>.part<pid>`) and at the final name, a hard link at the
   !> final name. The run writes its file; neither victim changes; the final name is then a
   !> regular file of its own; no temporary file is left (and the check for one works).
   subroutine planted_links_untouched(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(error_t), allocatable :: error
      character(len=:), allocatable :: written, out, victim, other
      character(len=1024), allocatable :: lines(:)
      character(len=16) :: pid
      integer :: status
      write (pid, '(i0)') c_getpid()
      out = scratch_prefix("planted")
      victim = scratch_prefix("victim")//".txt"
      other = scratch_prefix("victim_hard")//".txt"
      call write_file(out//"_chart.dat.partAbc123", ["x"])
      call check(ctx, any_temp_file(out//"_chart.dat"), "a temporary file is seen")
      call delete_file(out//"_chart.dat.partAbc123")
      call check(ctx, .not. any_temp_file(out//"_chart.dat"), "no temporary file is seen")
      call write_file(victim, ["victim"])
      call write_file(other, ["other"])
      ! a symbolic link at the old temporary name, to the victim
      call execute_command_line("ln -s '"//victim(index(victim, "/", back=.true.) + 1:)//"' '"//out// &
         "_chart.dat.part"//trim(pid)//"'", exitstat=status)
      call check(ctx, status == 0, "symbolic link planted")
      ! the final name a hard link to the other victim
      call execute_command_line("ln '"//other//"' '"//out//"_chart.dat'", exitstat=status)
      call check(ctx, status == 0, "hard link planted")
      call run_text_scene("planted", [padded("&scene method = 'formula', output = '"//out//"' /"), &
         padded("&chart n_alpha = 3, n_beta = 3 /")], error, written)
      call check(ctx, .not. allocated(error), "runs")
      lines = read_lines(victim)
      call check(ctx, size(lines) == 1, "the victim keeps its one line")
      if (size(lines) == 1) call check(ctx, lines(1) == "victim", "the victim is unchanged")
      lines = read_lines(other)
      call check(ctx, size(lines) == 1, "the hard-linked file keeps its one line")
      if (size(lines) == 1) call check(ctx, lines(1) == "other", "the hard-linked file is unchanged")
      lines = read_lines(out//"_chart.dat")
      call check(ctx, size(lines) > 9, "the output is written")
      call execute_command_line("test -L '"//out//"_chart.dat.part"//trim(pid)//"'", exitstat=status)
      call check(ctx, status == 0, "the planted link is left as it was")
      call execute_command_line("test -f '"//out//"_chart.dat' && test ! -L '"//out//"_chart.dat' && "// &
         "test ""$(stat -c %h '"//out//"_chart.dat')"" = 1", exitstat=status)
      call check(ctx, status == 0, "the output is a regular file with one link")
      call check(ctx, .not. any_temp_file(out//"_chart.dat"), "no temporary file left")
      call delete_file(out//"_chart.dat.part"//trim(pid))
      call delete_file(out//"_chart.dat")
      call delete_file(victim)
      call delete_file(other)
   end subroutine planted_links_untouched

   !> A file name of 255 bytes (the most a name may have) is written, whatever the temporary
   !> name needs; 256 bytes is refused, naming &scene output and the length, with no file.
   subroutine long_file_names(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(error_t), allocatable :: error
      character(len=:), allocatable :: written, dir, base
      character(len=600) :: scene(2)
      integer :: n
      dir = scratch_prefix("long")//"_dir"
      call execute_command_line("mkdir -p '"//dir//"'")
      do n = 255, 256
         base = repeat("n", n - len("_chart.dat"))
         scene(1) = "&scene method = 'formula', output = '"//dir//"/"//base//"' /"
         scene(2) = "&chart n_alpha = 2, n_beta = 2 /"
         call run_text_scene("long", scene, error, written)
         if (n == 255) then
            call check(ctx, .not. allocated(error), "a name of 255 bytes is written")
            call check(ctx, file_exists(dir//"/"//base//"_chart.dat"), "the file exists")
            call delete_file(dir//"/"//base//"_chart.dat")
         else
            call check(ctx, allocated(error), "a name of 256 bytes is refused")
            if (allocated(error)) call check(ctx, contains_text(error%message, "&scene: output:") .and. &
               contains_text(error%message, "256 bytes"), "names &scene output and the length: "//error%message)
         end if
         call check(ctx, .not. any_temp_file(dir//"/"//base//"_chart.dat"), "no temporary file left")
      end do
      call execute_command_line("rmdir '"//dir//"'")
   end subroutine long_file_names

   !> Messages echo what scene files hold as one plain line: control characters (C0 and the
   !> C1 controls of UTF-8) and the Unicode line separators are escaped; plain text and other
   !> UTF-8 pass unchanged.
   subroutine messages_printable(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=*), parameter :: ls = achar(226)//achar(128)//achar(168)
      call check(ctx, printable("a"//achar(12)//"b"//achar(0)//"c"//achar(10)) == "a\x0cb\x00c\x0a", &
         "form feed, NUL, line feed escaped: "//printable("a"//achar(12)//"b"//achar(0)//"c"//achar(10)))
      call check(ctx, printable("x"//ls//"y") == "x\u2028y", "U+2028 escaped")
      ! the C1 controls of UTF-8: U+0085 (next line: a line break for some tools), U+009B
      ! (a terminal's control sequence introducer); U+00A0 (no-break space) is text
      call check(ctx, printable("a"//achar(194)//achar(133)//"b"//achar(194)//achar(155)//"c"//achar(194)// &
         achar(160)) == "a\u0085b\u009bc"//achar(194)//achar(160), "U+0085, U+009B escaped, U+00A0 kept: "// &
         printable("a"//achar(194)//achar(133)//"b"//achar(194)//achar(155)//"c"//achar(194)//achar(160)))
      call check(ctx, printable("&scene: output: 'é' α") == "&scene: output: 'é' α", "plain text unchanged")
   end subroutine messages_printable

   !> An output under a regular file cannot be written: an i/o error naming the path, no
   !> file; an output whose directories are missing gets them made (as mkdir -p).
   subroutine unwritable_output(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(error_t), allocatable :: error
      character(len=:), allocatable :: written, blocker, dir
      blocker = scratch_prefix("blocker")
      call write_file(blocker, ["not a directory"])
      call run_text_scene("unwritable", [ &
         padded("&scene method = 'segments', output = '"//blocker//"/sub/run' /"), &
         padded("&chart n_alpha = 2, n_beta = 2 /")], error, written)
      call check(ctx, allocated(error), "unwritable output is an error")
      if (allocated(error)) then
         call check(ctx, error%code == err_io, "i/o error code")
         call check(ctx, contains_text(error%message, scratch_prefix("unwritable")//".nml: &scene: output:"), &
                    "names file, group, variable: "//error%message)
         call check(ctx, contains_text(error%message, blocker//"/sub/run_chart.dat"), "names the path")
         call check(ctx, contains_text(error%message, "cannot make the directory '"//blocker//"'"), &
                    "names the directory: "//error%message)
      end if
      call delete_file(blocker)
      ! missing directories are made
      dir = scratch_prefix("newdir")
      call run_text_scene("newdir", [ &
         padded("&scene method = 'segments', output = '"//dir//"/a/b/run' /"), &
         padded("&chart n_alpha = 2, n_beta = 2 /")], error, written)
      call check(ctx, .not. allocated(error), "output into missing directories")
      if (allocated(error)) call check(ctx, .false., error%message)
      call check(ctx, file_exists(dir//"/a/b/run_chart.dat"), "the file in the new directories")
      call delete_file(dir//"/a/b/run_chart.dat")
      call execute_command_line("rmdir '"//dir//"/a/b' '"//dir//"/a' '"//dir//"'")
   end subroutine unwritable_output

   !> A chart asking only for verdicts (`columns = 'alpha beta stable'`, with stable_paper
   !> when damped) against the same chart with S: the same verdict at every point where
   !> neither file says 0.5 (marginal); where one does, S lies within twice the tolerance
   !> (relative to max(1, |S|)) of the threshold. Elastic across the first tongues, the hard
   !> band α → π² near β = 0 (S = 2 exactly at β = 0), Mathieu, and damped (ε = 0.3, where
   !> stable_paper settles |S| = 2 as well).
   !> A chart over log axes (`alpha_scale`, `beta_scale` = 'log'): its α and β are the
   !> geometric values of `grid_value` to the bit (both ends exact), its rows are the points
   !> task's lines at the same (α, β) (segments: the same numbers to the bit; auto: the same
   !> verdicts, S within the tolerance), and the file run again as a scene writes itself;
   !> task boundaries draws its curves at the log alphas.
   subroutine log_chart_matches_points(ctx)
      type(test_context_t), intent(inout) :: ctx
      integer, parameter :: na = 6, nb = 9
      character(len=*), parameter :: grid = "&chart alpha_min = 0.05, alpha_max = 9.5, n_alpha = 6, alpha_scale = 'log', "// &
                                     "beta_min = 0.01, beta_max = 100, n_beta = 9, beta_scale = 'log' /"
      character(len=*), parameter :: methods(2) = [character(len=40) :: "method = 'segments', n_segments = 8", &
                                                   "method = 'auto'"]
      type(error_t), allocatable :: error
      character(len=:), allocatable :: out, chart_path, points_path, again, points
      character(len=1024), allocatable :: lines(:), point_lines(:)
      character(len=60) :: pairs(na*nb)
      real(wp), allocatable :: rows(:, :), point_rows(:, :)
      integer :: n_blank, i, j, k, m
      logical :: numeric, ok
      out = scratch_prefix("logchart")
      points = out//"_input.dat"
      do m = 1, size(methods)
         call run_text_scene("logchart", [padded("&scene "//trim(methods(m))//", columns = 'alpha beta S stable', "// &
            "output = '"//out//"' /"), padded(grid)], error, chart_path)
         call check(ctx, .not. allocated(error), trim(methods(m))//": the log chart runs")
         if (allocated(error)) return
         lines = read_lines(chart_path)
         call check(ctx, any(index(lines, "alpha_scale = 'log'") > 0 .and. index(lines, "beta_scale = 'log'") > 0), &
                    "the header names the scales")
         call data_rows(lines, 4, rows, n_blank, numeric)
         call check(ctx, numeric .and. size(rows, 2) == na*nb .and. n_blank == na - 1, "6 blocks of 9 rows")
         if (size(rows, 2) /= na*nb) return
         k = 0
         do i = 1, na
            do j = 1, nb
               k = k + 1
               call check(ctx, rows(1, k) == grid_value(0.05_wp, 9.5_wp, na, i, geometric=.true.) .and. &
                          rows(2, k) == grid_value(0.01_wp, 100.0_wp, nb, j, geometric=.true.), &
                          "the geometric grid to the bit, point "//integer_text(k))
               write (pairs(k), '(es25.17, 1x, es25.17)') rows(1, k), rows(2, k)
            end do
         end do
         call check(ctx, rows(1, 1) == 0.05_wp .and. rows(1, na*nb) == 9.5_wp .and. rows(2, 1) == 0.01_wp .and. &
                    rows(2, nb) == 100.0_wp, "the ends exact")
         call write_file(points, pairs)
         call run_text_scene("logchart_points", [padded("&scene task = 'points', "//trim(methods(m))// &
            ", columns = 'alpha beta S stable', output = '"//out//"' /"), padded("&points file = '"//points//"' /")], &
            error, points_path)
         call check(ctx, .not. allocated(error), "the points task runs")
         if (allocated(error)) return
         point_lines = read_lines(points_path)
         call data_rows(point_lines, 4, point_rows, n_blank, numeric)
         call check(ctx, numeric .and. size(point_rows, 2) == na*nb, "a line a point")
         if (size(point_rows, 2) /= na*nb) return
         call check(ctx, all(point_rows(1:2, :) == rows(1:2, :)), "the same (alpha, beta)")
         if (m == 1) then
            call check(ctx, all(point_rows == rows), "segments: the chart's rows are the points' lines to the bit")
         else
            call check(ctx, all(point_rows(4, :) == rows(4, :)), "auto: the same verdicts")
            call check(ctx, maxval(abs(point_rows(3, :) - rows(3, :))/max(1.0_wp, abs(rows(3, :)))) < 1.0e-9_wp, &
                       "auto: S within the tolerance")
         end if
         call check_rerun(ctx, chart_path, lines, again, ok)
         if (ok) call delete_file(again)
         call delete_file(chart_path)
         call delete_file(points_path)
      end do
      call delete_file(points)
      ! task boundaries draws its curves at the log alphas
      call run_text_scene("logchart_curves", [padded("&scene task = 'boundaries', model = 'mathieu', output = '"// &
         out//"' /"), padded("&chart alpha_min = 0.1, alpha_max = 3, n_alpha = 4, alpha_scale = 'log', "// &
         "beta_min = -1, beta_max = 5, n_beta = 50 /")], error, chart_path)
      call check(ctx, .not. allocated(error), "boundaries over log alphas run")
      if (allocated(error)) return
      lines = read_lines(chart_path)
      call delete_file(chart_path)
      call data_rows(lines, 13, rows, n_blank, numeric)
      call check(ctx, numeric .and. size(rows, 2) > 8, "curve points: "//integer_text(size(rows, 2)))
      do i = 1, 4
         call check(ctx, count(rows(1, :) == grid_value(0.1_wp, 3.0_wp, 4, i, geometric=.true.)) >= 2, &
                    "curve points at log alpha "//integer_text(i))
      end do
      call check(ctx, all(rows(1, :) == grid_value(0.1_wp, 3.0_wp, 4, 1, geometric=.true.) .or. &
                          rows(1, :) == grid_value(0.1_wp, 3.0_wp, 4, 2, geometric=.true.) .or. &
                          rows(1, :) == grid_value(0.1_wp, 3.0_wp, 4, 3, geometric=.true.) .or. &
                          rows(1, :) == grid_value(0.1_wp, 3.0_wp, 4, 4, geometric=.true.)), "only the log alphas")
   end subroutine log_chart_matches_points

   subroutine verdict_chart_matches_full(ctx)
      type(test_context_t), intent(inout) :: ctx
      call compare("elastic", "model = 'elastic'", &
                   "alpha_min = 0, alpha_max = 9.8, n_alpha = 24, beta_min = -2, beta_max = 12, n_beta = 37", .false.)
      call compare("band", "model = 'elastic'", &
                   "alpha_min = 9.5, alpha_max = 9.8696, n_alpha = 12, beta_min = -0.01, beta_max = 0.01, n_beta = 21", &
                   .false.)
      call compare("mathieu", "model = 'mathieu'", &
                   "alpha_min = 0, alpha_max = 10, n_alpha = 21, beta_min = -5, beta_max = 15, n_beta = 31", .false.)
      call compare("damped", "model = 'elastic', epsilon = 0.3", &
                   "alpha_min = 0, alpha_max = 9.8, n_alpha = 24, beta_min = -2, beta_max = 12, n_beta = 37", .true.)
      ! a period 4 (f = cos(πτ/2) + 0.3 cos πτ + 0.2 sin πτ): the range shortcut's bands and the
      ! damped threshold are those of the period 4 (2 cosh(εP/2) = 2 cosh(0.3) at ε = 0.15)
      call compare("period4", "model = 'fourier'", &
                   "alpha_min = 0.02, alpha_max = 1, n_alpha = 12, beta_min = 0.3, beta_max = 2.6, n_beta = 47", .false., &
                   "&fourier cos = 1, 0.3, sin = 0, 0.2, period = 4 /")
      call compare("period4_damped", "model = 'fourier', epsilon = 0.15", &
                   "alpha_min = 0.02, alpha_max = 3, n_alpha = 12, beta_min = 0.3, beta_max = 2.6, n_beta = 47", .true., &
                   "&fourier cos = 1, 0.3, sin = 0, 0.2, period = 4 /")
   contains
      subroutine compare(name, settings, chart, damped, model_group)
         character(len=*), intent(in) :: name, settings, chart
         logical, intent(in) :: damped
         character(len=*), intent(in), optional :: model_group  !! the model's group, when it has data
         type(error_t), allocatable :: error
         character(len=:), allocatable :: out, full_path, verdict_path, verdict_columns, full_columns, group
         character(len=1024), allocatable :: full(:), verdict(:)
         real(wp), allocatable :: full_rows(:, :), verdict_rows(:, :)
         real(wp) :: s, bound, tolerance
         integer :: n_blank, k, c, n_columns, n_marginal
         logical :: numeric
         tolerance = 1.0e-10_wp
         out = scratch_prefix("verdict_"//name)
         verdict_columns = "alpha beta stable"
         if (damped) verdict_columns = verdict_columns//" stable_paper"
         full_columns = verdict_columns//" S"
         n_columns = merge(4, 3, damped)
         group = ""
         if (present(model_group)) group = model_group
         call run_text_scene("verdict_full", [padded("&scene "//settings//", output = '"//out//"_full',"), &
            padded("  columns = '"//full_columns//"' /"), padded("&chart "//chart//" /"), padded(group)], error, full_path)
         call check(ctx, .not. allocated(error), name//": full chart")
         if (allocated(error)) return
         call run_text_scene("verdict_only", [padded("&scene "//settings//", output = '"//out//"_verdict',"), &
            padded("  columns = '"//verdict_columns//"' /"), padded("&chart "//chart//" /"), padded(group)], error, &
            verdict_path)
         call check(ctx, .not. allocated(error), name//": verdict chart")
         if (allocated(error)) return
         full = read_lines(full_path)
         verdict = read_lines(verdict_path)
         call data_rows(full, n_columns + 1, full_rows, n_blank, numeric)
         call check(ctx, numeric, name//": full rows numeric")
         call data_rows(verdict, n_columns, verdict_rows, n_blank, numeric)
         call check(ctx, numeric .and. size(verdict_rows, 2) == size(full_rows, 2), name//": as many verdict rows")
         if (size(verdict_rows, 2) /= size(full_rows, 2)) return
         n_marginal = 0
         do k = 1, size(full_rows, 2)
            call check(ctx, all(verdict_rows(1:2, k) == full_rows(1:2, k)), name//": the same grid")
            s = full_rows(n_columns + 1, k)
            ! the full file's own verdict against its S (threshold 2 cosh(0.3) when damped)
            if (full_rows(3, k) /= 0.5_wp) then
               call check(ctx, (full_rows(3, k) == 1.0_wp) .eqv. (abs(s) < merge(2.0_wp*cosh(0.3_wp), 2.0_wp, damped)), &
                          name//": stable as S says")
            end if
            do c = 3, n_columns
               if (verdict_rows(c, k) == full_rows(c, k)) cycle
               if (verdict_rows(c, k) == 0.5_wp .or. full_rows(c, k) == 0.5_wp) then
                  n_marginal = n_marginal + 1
                  ! the threshold of stable: 2 cosh(0.3) when damped; of stable_paper: 2
                  bound = 2.0_wp*tolerance*max(1.0_wp, abs(s))
                  if (c == 3 .and. damped) then
                     call check(ctx, abs(abs(s) - 2.0_wp*cosh(0.3_wp)) <= bound, name//": marginal near the threshold")
                  else
                     call check(ctx, abs(abs(s) - 2.0_wp) <= bound, name//": marginal near |S| = 2")
                  end if
               else
                  call check(ctx, .false., name//": the same verdict where neither is marginal")
               end if
            end do
         end do
         print '(4x,a,a,i0,a,i0,a)', name, ": ", size(full_rows, 2), " points, ", n_marginal, &
            " verdicts marginal in one file only"
         call delete_file(full_path)
         call delete_file(verdict_path)
      end subroutine compare
   end subroutine verdict_chart_matches_full

   !> `columns = 'alpha beta lambda_max mu'` (what the growth of the swing needs) against
   !> the full chart: lambda_max and mu equal where the full chart has |S| < 2 (1 and 0
   !> exactly), within 1e-9 relative elsewhere (the header's accuracy at tolerance 1e-10).
   subroutine growth_columns_match_full(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(error_t), allocatable :: error
      character(len=:), allocatable :: out, full_path, growth_path
      character(len=1024), allocatable :: full(:), growth(:)
      real(wp), allocatable :: full_rows(:, :), growth_rows(:, :)
      character(len=*), parameter :: chart = &
         "&chart alpha_min = 0.5, alpha_max = 9.8, n_alpha = 16, beta_min = -2, beta_max = 12, n_beta = 29 /"
      integer :: n_blank, k, n_stable
      logical :: numeric
      out = scratch_prefix("growth")
      call run_text_scene("growth_full", [padded("&scene output = '"//out//"_full', "// &
         "columns = 'alpha beta lambda_max mu S' /"), padded(chart)], error, full_path)
      call check(ctx, .not. allocated(error), "full chart")
      if (allocated(error)) return
      call run_text_scene("growth_only", [padded("&scene output = '"//out//"_growth', "// &
         "columns = 'alpha beta lambda_max mu' /"), padded(chart)], error, growth_path)
      call check(ctx, .not. allocated(error), "growth chart")
      if (allocated(error)) return
      full = read_lines(full_path)
      growth = read_lines(growth_path)
      call data_rows(full, 5, full_rows, n_blank, numeric)
      call check(ctx, numeric, "full chart: numeric rows")
      call data_rows(growth, 4, growth_rows, n_blank, numeric)
      call check(ctx, numeric .and. size(growth_rows, 2) == size(full_rows, 2), "as many rows")
      if (size(growth_rows, 2) /= size(full_rows, 2)) return
      n_stable = 0
      do k = 1, size(full_rows, 2)
         if (abs(full_rows(5, k)) < 2.0_wp) then
            n_stable = n_stable + 1
            call check(ctx, growth_rows(3, k) == 1.0_wp .and. growth_rows(4, k) == 0.0_wp, &
                       "lambda_max = 1 and mu = 0 exactly where |S| < 2")
         else
            call check(ctx, growth_rows(3, k), full_rows(3, k), rel=1.0e-9_wp, message="lambda_max")
            call check(ctx, growth_rows(4, k), full_rows(4, k), rel=1.0e-9_wp, abs=1.0e-9_wp, message="mu")
         end if
      end do
      call check(ctx, n_stable > 50 .and. n_stable < size(full_rows, 2) - 50, "stable and unstable points")
      call delete_file(full_path)
      call delete_file(growth_path)
   end subroutine growth_columns_match_full

   !> The header says what accuracy each written column has: a verdict chart that its
   !> verdicts come from a screening pass; a chart with S the tolerance of S; a chart of the
   !> grid's columns alone that nothing is computed; an approximate method that it has no
   !> error bound.
   subroutine columns_state_their_accuracy(ctx)
      type(test_context_t), intent(inout) :: ctx
      call expect("alpha beta stable", "auto", "# accuracy of stable: exact except at 0.5 (marginal): each point "// &
                  "computed only until |S| = 2 lies beyond the error bound of its S")
      call expect("alpha beta S stable", "auto", "# accuracy of S: to the tolerance 1.0e-10: |error of S| <= "// &
                  "max(error_estimate, 1.0e-10) max(1, |S|) at status 0")
      call expect("alpha beta S stable", "auto", "# accuracy of stable: exact except at 0.5 (marginal), from S "// &
                  "computed to the tolerance 1.0e-10")
      call expect("alpha beta mu", "auto", "# accuracy of mu: exact where |S| < 2")
      call expect("alpha beta physical", "auto", "# accuracy: no trace is computed (the columns written need none)")
      call expect("alpha beta S", "formula", "# accuracy of S: the value of method 'formula' itself (an "// &
                  "approximation, no error bound)")
   contains
      subroutine expect(columns, method, line)
         character(len=*), intent(in) :: columns, method, line
         type(error_t), allocatable :: error
         character(len=:), allocatable :: path
         character(len=1024), allocatable :: lines(:)
         integer :: k
         logical :: found
         call run_text_scene("accuracy", [padded("&scene method = '"//method//"', output = '"// &
            scratch_prefix("accuracy")//"', columns = '"//columns//"' /"), &
            padded("&chart alpha_min = 1, alpha_max = 2, n_alpha = 2, beta_min = 1, beta_max = 2, n_beta = 2 /")], &
            error, path)
         call check(ctx, .not. allocated(error), columns//": chart")
         if (allocated(error)) return
         lines = read_lines(path)
         found = .false.
         do k = 1, size(lines)
            if (index(lines(k), line) == 1) found = .true.
         end do
         call check(ctx, found, columns//" ("//method//"): header line '"//line//"'")
         call delete_file(path)
      end subroutine expect
   end subroutine columns_state_their_accuracy
   !> Every task reports its progress in the same line (percentage, units done of the total,
   !> rate, time left): with HILLSTAB_PROGRESS=always each update is a line, the units done
   !> grow, the total stays, the last line says 100%.
   subroutine progress_every_task(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=100), parameter :: scenes(2, 7) = reshape([character(len=100) :: &
         "task = 'chart'", "&chart n_alpha = 3, n_beta = 4 /", &
         "task = 'points'", "&points file = 'data/points/fig4.dat' /", &
         "task = 'coefficient'", "&coefficient n_tau = 10000 /", &
         "task = 'boundaries'", "&chart n_alpha = 3, alpha_max = 5, beta_max = 20 /", &
         "task = 'series'", "&series periods = 3, samples_per_period = 10 /", &
         "task = 'lyapunov'", "&chart n_alpha = 2, n_beta = 2 / &series periods = 10 /", &
         "task = 'poincare'", "&series periods = 5 / &poincare phi0s = 0.05, 0.1 /"], [2, 7])
      character(len=1024), allocatable :: progress(:)
      type(error_t), allocatable :: error
      character(len=:), allocatable :: path, out, written, label, task, previous_label
      real :: percent, last_percent
      integer :: i, k, done, total, last_done, first_total
      logical :: ok, growing
      do i = 1, size(scenes, 2)
         task = trim(scenes(1, i))
         out = scratch_prefix("progress_task")
         path = out//".nml"
         call write_file(path, [padded("&scene "//task//", output = '"//out//"' /"), padded(scenes(2, i))])
         call run_with_progress(path, progress, error, written)
         call check(ctx, .not. allocated(error), "runs: "//task)
         if (allocated(error)) then
            call check(ctx, .false., error%message)
            call delete_file(path)
            cycle
         end if
         call check(ctx, size(progress) >= 1, "progress lines: "//task)
         growing = .true.
         previous_label = ""
         do k = 1, size(progress)
            call progress_numbers(progress(k), percent, done, total, label, ok)
            call check(ctx, ok .and. len(label) > 0, task//": the form of "//trim(progress(k)))
            if (label /= previous_label) then
               ! a new count (boundaries: alphas by Hill's method, then curve points checked)
               previous_label = label
               first_total = total
               last_done = 0
               last_percent = 0.0
            end if
            growing = growing .and. done > last_done .and. percent >= last_percent .and. total == first_total
            last_done = done
            last_percent = percent
         end do
         call check(ctx, growing, task//": units done grow to one total")
         if (size(progress) >= 1) then
            call progress_numbers(progress(size(progress)), percent, done, total, label, ok)
            call check(ctx, done == total .and. abs(percent - 100.0) < 0.05, task//": 100% at the end: "// &
                       trim(progress(size(progress))))
         end if
         call delete_file(written)
         call delete_file(path)
      end do
   end subroutine progress_every_task

end module test_tasks

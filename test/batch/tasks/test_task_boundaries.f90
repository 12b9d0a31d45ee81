!> Tests of the `boundaries` task through `run_scene_file`, reading the file back:
!> layout (header, `# columns:`, one block per curve separated by two blank lines),
!> values at α = 0 against β = (nπ/2)², the accuracy bar (a boundary at a grid α
!> within 1e-9 of the β found by bisection on S with method auto at tolerance 1e-13,
!> or of the exact β = 0 and π²), repeating a run from its output, the approximate
!> curves of eq. (37) (S_formula = ±2 at every root), the Mathieu model's GSL column, and
!> the critical amplitudes of a spring (`&physical` without `&chart`) against a scan of S
!> along α with method auto and bisection; progress inside one α (per curve point checked).
module test_task_boundaries
   use hillstab_core_kinds, only: wp, pi, pi2
   use hillstab_core_error, only: error_t, err_input
   use hillstab_hill_transfer, only: trace_t
   use hillstab_integrate_monodromy, only: method_t, method_auto, monodromy_trace
   use hillstab_hill_formulas, only: trace_two_segment_paper
   use hillstab_batch_run_scenes, only: run_scene_file
   use hillstab_testing
   use hillstab_test_files, only: run_text_scene
   use hillstab_test_progress, only: run_with_progress, progress_numbers
   use hillstab_test_scratch, only: scratch_prefix, write_file, read_lines, delete_file
   use hillstab_hill_model, only: hill_point_t
   use hillstab_hill_model_elastic, only: elastic_model_t
   use hillstab_batch_run_read, only: read_scene
   use hillstab_batch_scene_types, only: scene_t
   use hillstab_batch_run_scenes, only: run_scene, output_path
   use hillstab_curves_hill_method, only: hill_boundary_t
   use hillstab_curves_hill_fourier, only: fourier_boundaries
   use hillstab_test_drive_model, only: drive_model_t, drive_model
   implicit none
   private
   public :: collect_task_boundaries

contains

   function collect_task_boundaries() result(suite)
      type(testsuite_t) :: suite
      suite = new_testsuite("task_boundaries", [ &
         new_unittest("layout_and_alpha_zero", layout_and_alpha_zero), &
         new_unittest("accuracy_on_grid", accuracy_on_grid), &
         new_unittest("repeat_from_output", repeat_from_output), &
         new_unittest("paper_formula_curves", paper_formula_curves), &
         new_unittest("mathieu_gsl_column", mathieu_gsl_column), &
         new_unittest("damping_refused", damping_refused), &
         new_unittest("spring_critical_amplitudes", spring_critical_amplitudes), &
         new_unittest("spring_bad_input", spring_bad_input), &
         new_unittest("physical_curves_a_column", physical_curves_a_column), &
         new_unittest("progress_within_an_alpha", progress_within_an_alpha), &
         new_unittest("spring_progress", spring_progress), &
         new_unittest("fourier_and_roots_routes", fourier_and_roots_routes)])
   end function collect_task_boundaries

   !> A model of the form β + g with three cosine harmonics goes by Hill's method on the
   !> Fourier coefficients (the header says so; every point passes the check by auto; the
   !> values are those of `fourier_boundaries`), and the same model withholding its harmonics
   !> by the roots of S (the header says so; the same curves to 1e-9).
   subroutine fourier_and_roots_routes(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(drive_model_t) :: model
      real(wp), allocatable :: fourier_rows(:, :), root_rows(:, :)
      type(hill_boundary_t), allocatable :: curves(:)
      type(error_t), allocatable :: error
      integer :: k, j
      logical :: found
      model = drive_model(2.0_wp, 0.2_wp, [-1.0_wp, 0.4_wp, 0.1_wp], [0.0_wp, 0.0_wp, 0.0_wp])
      call run_with_model(model, "bnd_fourier", "Hill's method on the Fourier coefficients", fourier_rows)
      model%withhold = .true.
      call run_with_model(model, "bnd_roots", "root finding on S", root_rows)
      call check(ctx, size(fourier_rows, 2) > 10 .and. size(fourier_rows, 2) == size(root_rows, 2), &
                 "the same number of curve points")
      if (size(fourier_rows, 2) /= size(root_rows, 2)) return
      call check(ctx, all(fourier_rows(8, :) == 0.0_wp) .and. all(root_rows(8, :) == 0.0_wp), "every check passed")
      model%withhold = .false.
      do k = 1, size(fourier_rows, 2)
         call fourier_boundaries(model, fourier_rows(1, k), -5.0_wp, 30.0_wp, 1.0e-11_wp, curves, error)
         if (allocated(error)) return
         found = .false.
         do j = 1, size(curves)
            if (abs(curves(j)%beta - fourier_rows(2, k)) <= 1.0e-12_wp*max(1.0_wp, abs(curves(j)%beta))) found = .true.
         end do
         call check(ctx, found, "a value of fourier_boundaries")
         found = .false.
         do j = 1, size(root_rows, 2)
            if (root_rows(1, j) == fourier_rows(1, k) .and. abs(root_rows(2, j) - fourier_rows(2, k)) <= &
                1.0e-9_wp*max(1.0_wp, abs(fourier_rows(2, k)))) found = .true.
         end do
         call check(ctx, found, "the same curve point by the roots of S")
      end do
   contains
      subroutine run_with_model(model, name, route_text, rows)
         type(drive_model_t), intent(in) :: model
         character(len=*), intent(in) :: name, route_text
         real(wp), allocatable, intent(out) :: rows(:, :)
         type(scene_t) :: scene
         type(error_t), allocatable :: error
         character(len=:), allocatable :: path, out
         character(len=1024), allocatable :: lines(:)
         integer :: k, n, ios
         logical :: said
         allocate (rows(11, 0))
         path = scratch_prefix(name)//".nml"
         out = scratch_prefix(name)
         call write_file(path, two_lines("&scene task='boundaries', model='mathieu', tolerance=1e-11, "// &
            "output='"//out//"' /", "&chart alpha_min=1, alpha_max=6, n_alpha=4, beta_min=-5, beta_max=30, n_beta=400 /"))
         call read_scene(path, scene, error)
         call delete_file(path)
         call check(ctx, .not. allocated(error), name//": scene read")
         if (allocated(error)) return
         deallocate (scene%model)
         allocate (scene%model, source=model)
         call run_scene(scene, .true., error)
         call check(ctx, .not. allocated(error), name//": runs")
         if (allocated(error)) call check(ctx, .false., error%message)
         if (allocated(error)) return
         lines = read_lines(output_path(scene))
         call delete_file(output_path(scene))
         said = .false.
         deallocate (rows)
         allocate (rows(11, size(lines)))
         n = 0
         do k = 1, size(lines)
            if (index(lines(k), "method: every curve by "//route_text) > 0) said = .true.
            if (lines(k)(1:1) == "#" .or. len_trim(lines(k)) == 0) cycle
            n = n + 1
            read (lines(k), *, iostat=ios) rows(:, n)
         end do
         rows = rows(:, :n)
         call check(ctx, said, name//": the header names the route")
      end subroutine run_with_model
   end subroutine fourier_and_roots_routes

   !> Two scene lines as one array (built here: typed array constructors with
   !> deferred-length concatenations corrupt the heap in gfortran 12).
   function two_lines(first, second) result(lines)
      character(len=*), intent(in) :: first, second
      character(len=240) :: lines(2)
      lines(1) = first
      lines(2) = second
   end function two_lines

   !> Run a scene given as lines; return the data rows (n_columns each) and the file lines.
   subroutine run_rows(name, scene_lines, n_columns, rows, lines, error)
      character(len=*), intent(in) :: name
      character(len=*), intent(in) :: scene_lines(:)
      integer, intent(in) :: n_columns
      real(wp), allocatable, intent(out) :: rows(:, :)
      character(len=1024), allocatable, intent(out) :: lines(:)
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: written
      integer :: k, n, ios
      call run_text_scene(name, scene_lines, error, written)
      allocate (rows(n_columns, 0))
      if (allocated(error)) return
      lines = read_lines(written)
      call delete_file(written)
      deallocate (rows)
      allocate (rows(n_columns, size(lines)))
      n = 0
      do k = 1, size(lines)
         if (lines(k)(1:1) == "#" .or. len_trim(lines(k)) == 0) cycle
         n = n + 1
         read (lines(k), *, iostat=ios) rows(:, n)
         if (ios /= 0) rows(:, n) = -999.0_wp
      end do
      rows = rows(:, :n)
   end subroutine run_rows

   subroutine layout_and_alpha_zero(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp), allocatable :: rows(:, :)
      character(len=1024), allocatable :: lines(:)
      type(error_t), allocatable :: error
      character(len=:), allocatable :: out
      integer :: k, n_columns_lines, n_double_blank, curve, j
      out = scratch_prefix("bnd_layout")
      call run_rows("bnd_layout", two_lines("&scene task='boundaries', tolerance=1e-11, output='"//out//"' /", &
         "&chart alpha_min=0, alpha_max=6, n_alpha=4, beta_min=-2, beta_max=30 /"), 11, rows, lines, error)
      call check(ctx, .not. allocated(error), "runs")
      if (allocated(error)) return
      n_columns_lines = 0
      n_double_blank = 0
      do k = 1, size(lines)
         if (lines(k)(1:11) == "# columns: ") then
            n_columns_lines = n_columns_lines + 1
            call check(ctx, trim(lines(k)) == "# columns: alpha beta kind order branch curve coexist status "// &
                       "check beta_error modes", "column names")
         end if
         if (k > 1) then
            if (len_trim(lines(k)) == 0 .and. len_trim(lines(k - 1)) == 0) n_double_blank = n_double_blank + 1
         end if
      end do
      call check(ctx, n_columns_lines == 1, "one columns line")
      call check(ctx, all(rows(8, :) == 0.0_wp .or. rows(8, :) == 1.0_wp), "status ok or round-off limited")
      call check(ctx, all(abs(rows(9, :) - rows(3, :)) < 1.0e-8_wp), "S = kind by auto at every point")
      ! below 30: a0, b1 a1, b2 a2, b3 a3: 7 curves, so 6 double blank lines between blocks
      call check(ctx, n_double_blank == 6, "blocks separated by two blank lines")
      do k = 1, size(rows, 2)
         if (rows(1, k) == 0.0_wp) then
            call check(ctx, rows(2, k), (rows(4, k)*pi/2)**2, rel=1.0e-12_wp, abs=1.0e-12_wp, message="(n pi/2)^2")
            call check(ctx, rows(7, k) == merge(0.0_wp, 1.0_wp, rows(4, k) == 0.0_wp), "alpha = 0: coexistence")
         end if
         ! rows of one block share kind, order and branch
         curve = nint(rows(6, k))
         do j = 1, k - 1
            if (nint(rows(6, j)) == curve) then
               call check(ctx, all(rows(3:5, j) == rows(3:5, k)), "one curve per block")
               exit
            end if
         end do
         ! periodic tongues of the elastic model have zero width, antiperiodic ones (alpha > 0) do not
         if (rows(1, k) > 0.0_wp .and. rows(4, k) > 0.0_wp) then
            call check(ctx, (rows(7, k) == 1.0_wp) .eqv. (rows(3, k) == 2.0_wp), "coexistence flag")
         end if
      end do
      ! blocks in file order are curves 0, 1, 2, ...
      call check(ctx, all(rows(6, 2:) >= rows(6, :size(rows, 2) - 1)), "curves in order")
   end subroutine layout_and_alpha_zero

   !> The bar: at a grid α, every boundary within 1e-9 of the true β (tolerance 1e-11).
   !> References: bisection on S by auto (tolerance 1e-13) for the crossing curves,
   !> the exact β = 0 (order 0) and β = π² (order 2, both curves).
   subroutine accuracy_on_grid(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp), allocatable :: rows(:, :)
      character(len=1024), allocatable :: lines(:)
      type(error_t), allocatable :: error
      character(len=:), allocatable :: out
      real(wp) :: reference
      integer :: k, n_bisected
      out = scratch_prefix("bnd_accuracy")
      call run_rows("bnd_accuracy", two_lines("&scene task='boundaries', tolerance=1e-11, output='"//out//"' /", &
         "&chart alpha_min=2.5, alpha_max=9.8, n_alpha=4, beta_min=-2, beta_max=25 /"), 11, rows, lines, error)
      call check(ctx, .not. allocated(error), "runs")
      if (allocated(error)) return
      n_bisected = 0
      do k = 1, size(rows, 2)
         if (rows(4, k) == 0.0_wp) then
            reference = 0.0_wp
         else if (rows(4, k) == 2.0_wp) then
            reference = pi2
         else if (rows(3, k) == -2.0_wp) then
            reference = bisect(rows(1, k), rows(2, k))
            n_bisected = n_bisected + 1
         else
            cycle
         end if
         call check(ctx, rows(2, k), reference, abs=1.0e-9_wp, message="boundary within 1e-9")
      end do
      call check(ctx, n_bisected >= 16, "the antiperiodic curves of orders 1 and 3 at four alphas")
   contains
      !> S(β) + 2 changes sign across the curve: bisection from a bracket of ±1e-6.
      real(wp) function bisect(alpha, beta)
         real(wp), intent(in) :: alpha, beta
         real(wp) :: lo, hi, mid, f_lo, f_mid
         integer :: it
         lo = beta - 1.0e-6_wp; hi = beta + 1.0e-6_wp
         f_lo = s(alpha, lo) + 2.0_wp
         do it = 1, 60
            mid = 0.5_wp*(lo + hi)
            f_mid = s(alpha, mid) + 2.0_wp
            if (sign(1.0_wp, f_mid) == sign(1.0_wp, f_lo)) then
               lo = mid; f_lo = f_mid
            else
               hi = mid
            end if
            if (hi - lo < 1.0e-13_wp) exit
         end do
         bisect = 0.5_wp*(lo + hi)
      end function bisect
      real(wp) function s(alpha, beta)
         real(wp), intent(in) :: alpha, beta
         type(trace_t) :: tr
         type(error_t), allocatable :: err
         call monodromy_trace(elastic_model_t(), hill_point_t(alpha, beta, 0.0_wp), &
                              method_t(method_auto, tolerance=1.0e-13_wp), tr, err)
         s = tr%value
      end function s
   end subroutine accuracy_on_grid

   !> The output file read back as a scene repeats the run exactly.
   subroutine repeat_from_output(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp), allocatable :: first(:, :), second(:, :)
      character(len=1024), allocatable :: lines(:)
      type(error_t), allocatable :: error
      character(len=:), allocatable :: out, written
      integer :: k
      out = scratch_prefix("bnd_repeat")
      call run_rows("bnd_repeat", two_lines("&scene task='boundaries', method='segments', n_segments=8, "// &
         "sampling='midpoint', output='"//out//"' /", &
         "&chart alpha_min=1, alpha_max=8, n_alpha=3, beta_min=-2, beta_max=12, n_beta=150 /"), &
         11, first, lines, error)
      call check(ctx, .not. allocated(error), "first run")
      if (allocated(error)) return
      call write_file(out//"_copy.dat", lines)
      call run_scene_file(out//"_copy.dat", .true., error, written)
      call check(ctx, .not. allocated(error), "second run from the output file")
      if (allocated(error)) return
      lines = read_lines(written)
      call delete_file(out//"_copy.dat")
      call delete_file(written)
      allocate (second(11, 0))
      do k = 1, size(lines)
         if (lines(k)(1:1) == "#" .or. len_trim(lines(k)) == 0) cycle
         second = reshape([second, values(lines(k))], [11, size(second, 2) + 1])
      end do
      call check(ctx, size(second, 2) == size(first, 2) .and. size(first, 2) > 6, "same number of rows")
      if (size(second, 2) == size(first, 2)) call check(ctx, all(second == first), "same rows")
   contains
      function values(line) result(v)
         character(len=*), intent(in) :: line
         real(wp) :: v(11)
         read (line, *) v
      end function values
   end subroutine repeat_from_output

   !> method formula: every root has S by eq. (37) = ±2 (evaluated here independently)
   !> and at α = 0 they are (nπ/2)².
   subroutine paper_formula_curves(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp), allocatable :: rows(:, :)
      character(len=1024), allocatable :: lines(:)
      type(error_t), allocatable :: error
      character(len=:), allocatable :: out
      real(wp) :: s, ds
      integer :: k
      out = scratch_prefix("bnd_formula")
      call run_rows("bnd_formula", two_lines("&scene task='boundaries', method='formula', tolerance=1e-12, "// &
         "output='"//out//"' /", &
         "&chart alpha_min=0, alpha_max=8, n_alpha=5, beta_min=-2, beta_max=12, n_beta=400 /"), &
         11, rows, lines, error)
      call check(ctx, .not. allocated(error), "runs")
      if (allocated(error)) return
      ! alpha = 0: only beta = 0 crosses; the double roots (n pi/2)^2, n >= 1, only touch +-2
      call check(ctx, size(rows, 2) >= 10, "roots found")
      do k = 1, size(rows, 2)
         s = paper(rows(1, k), rows(2, k))
         ds = (paper(rows(1, k), rows(2, k) + 1.0e-7_wp) - paper(rows(1, k), rows(2, k) - 1.0e-7_wp))/2.0e-7_wp
         call check(ctx, s, rows(3, k), abs=1.0e-9_wp + abs(ds)*1.0e-11_wp*max(1.0_wp, abs(rows(2, k))), &
                    message="eq. (37) = +-2 at the root")
         if (rows(1, k) == 0.0_wp) call check(ctx, rows(2, k), (rows(4, k)*pi/2)**2, abs=1.0e-10_wp, &
                                              message="alpha = 0")
      end do
   contains
      real(wp) function paper(alpha, beta)
         real(wp), intent(in) :: alpha, beta
         type(trace_t) :: tr
         tr = trace_two_segment_paper(alpha, beta)
         paper = tr%value
      end function paper
   end subroutine paper_formula_curves

   !> Mathieu model: GSL's column agrees with Hill's β where GSL is trusted.
   subroutine mathieu_gsl_column(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp), allocatable :: rows(:, :)
      character(len=1024), allocatable :: lines(:)
      type(error_t), allocatable :: error
      character(len=:), allocatable :: out
      integer :: k
      out = scratch_prefix("bnd_mathieu")
      call run_rows("bnd_mathieu", two_lines("&scene task='boundaries', model='mathieu', tolerance=1e-11, "// &
         "output='"//out//"' /", &
         "&chart alpha_min=0, alpha_max=12, n_alpha=4, beta_min=-10, beta_max=40 /"), 13, rows, lines, error)
      call check(ctx, .not. allocated(error), "runs")
      if (allocated(error)) return
      call check(ctx, any(lines == "# columns: alpha beta kind order branch curve coexist status "// &
                          "check beta_error modes beta_gsl gsl_ok"), "GSL columns")
      call check(ctx, all(rows(13, :) == 1.0_wp), "GSL trusted everywhere here")
      do k = 1, size(rows, 2)
         call check(ctx, rows(12, k), rows(2, k), rel=1.0e-10_wp, abs=1.0e-10_wp, message="GSL = Hill")
      end do
   end subroutine mathieu_gsl_column
   !> The curves are those of the undamped equation: damping from &physical kappa is
   !> refused as bad input naming the group and variable, and no file is written.
   subroutine damping_refused(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp), allocatable :: rows(:, :)
      character(len=1024), allocatable :: lines(:)
      type(error_t), allocatable :: error
      character(len=:), allocatable :: out
      logical :: exists
      out = scratch_prefix("bnd_damped")
      call run_rows("bnd_damped", two_lines("&scene task='boundaries', output='"//out//"' / "// &
         "&physical omega=3, kappa=1 /", "&chart n_alpha=2 /"), 11, rows, lines, error)
      call check(ctx, allocated(error), "refused")
      if (.not. allocated(error)) return
      call check(ctx, error%code == err_input, "input error")
      call check(ctx, index(error%message, "&physical: kappa") > 0, "names &physical kappa: "//error%message)
      inquire (file=out//"_boundaries.dat", exist=exists)
      call check(ctx, .not. exists, "no file written")
   end subroutine damping_refused
   !> |S(alpha, beta)| - 2 by method auto (the reference of the spring tests).
   real(wp) function excess(alpha, beta)
      real(wp), intent(in) :: alpha, beta
      type(trace_t) :: tr
      type(error_t), allocatable :: error
      call monodromy_trace(elastic_model_t(), hill_point_t(alpha, beta, 0.0_wp), method_t(method_auto, tolerance=1.0e-12_wp), &
                           tr, error)
      excess = abs(tr%value) - 2.0_wp
   end function excess

   !> Every alpha in [0, alpha_end] where |S| - 2 by auto changes sign along alpha at fixed
   !> beta: a scan (400 steps up to 0.95 pi^2, then 40 a decade in 1 - alpha/pi^2), each
   !> sign change bisected to 1e-12.
   function bisected_crossings(beta, alpha_end) result(roots)
      real(wp), intent(in) :: beta, alpha_end
      real(wp), allocatable :: roots(:)
      real(wp), allocatable :: alphas(:), f(:)
      real(wp) :: lo, hi, mid, f_lo, f_mid
      integer :: j, n_uniform, n_end, iteration
      n_uniform = 400
      n_end = ceiling(40.0_wp*log10(0.05_wp/(1.0_wp - alpha_end/pi2)))
      allocate (alphas(n_uniform + 1 + n_end))
      do j = 0, n_uniform
         alphas(j + 1) = 0.95_wp*pi2*real(j, wp)/real(n_uniform, wp)
      end do
      do j = 1, n_end
         alphas(n_uniform + 1 + j) = pi2*(1.0_wp - 0.05_wp*((1.0_wp - alpha_end/pi2)/0.05_wp)**(real(j, wp)/n_end))
      end do
      allocate (f(size(alphas)), roots(0))
      do j = 1, size(alphas)
         f(j) = excess(alphas(j), beta)
      end do
      do j = 1, size(alphas) - 1
         if ((f(j) < 0.0_wp) .eqv. (f(j + 1) < 0.0_wp)) cycle
         lo = alphas(j); hi = alphas(j + 1); f_lo = f(j)
         do iteration = 1, 100
            if (hi - lo <= 1.0e-12_wp) exit
            mid = 0.5_wp*(lo + hi)
            f_mid = excess(mid, beta)
            if ((f_mid < 0.0_wp) .eqv. (f_lo < 0.0_wp)) then
               lo = mid; f_lo = f_mid
            else
               hi = mid
            end if
         end do
         roots = [roots, 0.5_wp*(lo + hi)]
      end do
   end function bisected_crossings

   !> The critical amplitudes of three springs — k = 25 N/m, m = 0.25 kg, r0 = 0.3 m
   !> (beta just below pi^2/4), omega = 10 rad/s with r0 = 0.1 m (beta > pi^2/4) and with
   !> r0 = 0.005 m (beta = 9.39, near pi^2: the crossing at 1 - alpha/pi^2 = 5e-4) and with
   !> r0 = 0.002 m (beta = 9.67: the crossing beyond the end of the search) — against
   !> bisection on S by auto along alpha: the same number of crossings, each alpha within
   !> 1e-8, a = alpha rho/pi^2 with rho = r0 + g m/k, S = -2 by auto there; the header's
   !> unstable interval from the reference's verdicts.
   subroutine spring_critical_amplitudes(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=40), parameter :: springs(4) = [character(len=40) :: "k = 25, m = 0.25, r0 = 0.3", &
                                                   "omega = 10, r0 = 0.1", "omega = 10, r0 = 0.005", &
                                                   "omega = 10, r0 = 0.002"]
      real(wp), parameter :: r0s(4) = [0.3_wp, 0.1_wp, 0.005_wp, 0.002_wp], g = 9.81_wp
      real(wp), parameter :: alpha_end = pi2*(1.0_wp - 1.0e-4_wp)
      real(wp), allocatable :: rows(:, :), reference(:)
      character(len=1024), allocatable :: lines(:)
      type(error_t), allocatable :: error
      character(len=:), allocatable :: out
      real(wp) :: rho, beta
      integer :: i, j
      do i = 1, 4
         out = scratch_prefix("bnd_spring")
         call run_rows("bnd_spring", two_lines("&scene task='boundaries', output='"//out//"' /", &
            "&physical "//trim(springs(i))//", g = 9.81 /"), 11, rows, lines, error)
         call check(ctx, .not. allocated(error), "spring run: "//trim(springs(i)))
         if (allocated(error)) then
            call check(ctx, .false., error%message)
            cycle
         end if
         call check(ctx, any(lines == "# columns: a alpha beta kind order branch status check a_error alpha_error "// &
                             "modes"), "columns")
         rho = r0s(i) + g/100.0_wp   ! omega = 10 rad/s in all three (k/m = 100)
         beta = g*pi2/(rho*100.0_wp)
         reference = bisected_crossings(beta, alpha_end)
         call check(ctx, size(rows, 2) == size(reference), "as many crossings as bisection finds: "//trim(springs(i)))
         if (i == 4) then
            ! beta = 9.67: the tongue's edge lies closer to the pivot than the search goes
            call check(ctx, size(reference) == 0, "no crossing within the search by bisection either")
            call check(ctx, excess(0.5_wp*alpha_end, beta) < 0.0_wp .and. excess(alpha_end, beta) < 0.0_wp, &
                       "stable at the middle and at the end of the search")
            call check(ctx, any(index(lines, "stable for every 0 m <= a <= (1 - 0.0001) rho") > 0), &
                       "stable up to the end of the search, no claim beyond")
            cycle
         end if
         call check(ctx, size(reference) == 1, "one crossing (the first tongue's edge)")
         if (size(rows, 2) /= size(reference)) cycle
         do j = 1, size(reference)
            call check(ctx, rows(2, j), reference(j), rel=1.0e-8_wp, abs=1.0e-8_wp, message="alpha against bisection")
            call check(ctx, rows(1, j), rows(2, j)*rho/pi2, rel=1.0e-14_wp, message="a = alpha rho/pi^2")
            call check(ctx, rows(3, j), beta, rel=1.0e-14_wp, message="beta of the spring")
            call check(ctx, rows(4, j) == -2.0_wp .and. rows(7, j) == 0.0_wp, "antiperiodic, status 0")
            call check(ctx, rows(8, j), -2.0_wp, rel=1.0e-8_wp, message="check: S = -2 by auto")
         end do
         ! unstable from the crossing to the pivot: the reference's verdicts either side
         call check(ctx, excess(0.5_wp*reference(1), beta) < 0.0_wp .and. &
                    excess(0.5_wp*(reference(1) + alpha_end), beta) > 0.0_wp, "stable below, unstable above")
         call check(ctx, any(index(lines, "unstable for "//digits(reference(1)*rho/pi2)//" m <= a < "// &
                             digits(rho)//" m") > 0), "unstable interval in metres: "//digits(reference(1)*rho/pi2))
         if (i == 1) call check(ctx, any(index(lines, "unstable for 0.003811 m <= a < 0.3981 m") > 0), &
                                "the spring of the README")
      end do
   contains
      function digits(x) result(text)
         real(wp), intent(in) :: x
         character(len=:), allocatable :: text
         character(len=32) :: buffer
         write (buffer, '(f0.'//char(iachar('0') + max(0, 3 - floor(log10(x))))//')') x
         text = trim(adjustl(buffer))
         if (text(1:1) == ".") text = "0"//text
      end function digits
   end subroutine spring_critical_amplitudes

   !> A spring's critical amplitudes need r0, no damping, no amplitudes, the elastic model
   !> and an exact method; a chart with r0 is refused; each is bad input naming the variable.
   subroutine spring_bad_input(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=80), parameter :: cases(6) = [character(len=80) :: &
         "&physical omega = 10 /", "&physical omega = 10, r0 = 0.3, kappa = 0.1 /", &
         "&physical omega = 10, r0 = 0.3, a = 0.1 /", "&physical omega = 10, r0 = 0.3, g = 0 /", &
         "&physical omega = 10, r0 = 0.3 / &chart n_alpha = 2 /", "&physical omega = 10, r0 = 0.3 /"]
      character(len=12), parameter :: variables(6) = [character(len=12) :: "r0", "kappa", "a", "g", "r0", "method"]
      real(wp), allocatable :: rows(:, :)
      character(len=1024), allocatable :: lines(:)
      type(error_t), allocatable :: error
      character(len=:), allocatable :: out, scene
      logical :: exists
      integer :: i
      do i = 1, size(cases)
         out = scratch_prefix("bnd_spring_bad")
         scene = "&scene task='boundaries', output='"//out//"'"
         if (i == 6) scene = scene//", method = 'formula'"
         call run_rows("bnd_spring_bad", two_lines(scene//" /", trim(cases(i))), 11, rows, lines, error)
         call check(ctx, allocated(error), "refused: "//trim(cases(i)))
         if (.not. allocated(error)) cycle
         call check(ctx, error%code == err_input, "input error")
         call check(ctx, index(error%message, ": "//trim(variables(i))//": ") > 0, "names "//trim(variables(i))// &
                    ": "//error%message)
         inquire (file=out//"_boundaries.dat", exist=exists)
         call check(ctx, .not. exists, "no file written")
      end do
   end subroutine spring_bad_input
   !> The curves over &chart of a scene with &physical omega carry a = alpha rho/pi^2 with
   !> rho = g pi^2/(beta omega^2), written out here, beside alpha.
   subroutine physical_curves_a_column(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp), allocatable :: rows(:, :)
      character(len=1024), allocatable :: lines(:)
      type(error_t), allocatable :: error
      character(len=:), allocatable :: out
      integer :: j
      out = scratch_prefix("bnd_phys")
      call run_rows("bnd_phys", two_lines("&scene task='boundaries', output='"//out//"' / &physical omega = 10, "// &
         "g = 9.81 /", "&chart alpha_max = 2, n_alpha = 3, beta_min = 0.5, beta_max = 4 /"), 12, rows, lines, error)
      call check(ctx, .not. allocated(error), "curves with &physical omega")
      if (allocated(error)) return
      call check(ctx, any(lines == "# columns: alpha a beta kind order branch curve coexist status check beta_error "// &
                          "modes"), "the a column beside alpha")
      call check(ctx, size(rows, 2) >= 6, "the two edges of the first tongue at three alpha")
      do j = 1, size(rows, 2)
         call check(ctx, rows(2, j), rows(1, j)*9.81_wp/(rows(3, j)*100.0_wp), rel=1.0e-14_wp, abs=1.0e-300_wp, &
                    message="a = alpha g/(beta omega^2)")
      end do
   end subroutine physical_curves_a_column

   !> Progress inside one alpha (issue 19: `n_alpha = 1` up to beta = 1e6 ran two minutes in
   !> silence): a step per block of Hill's matrix (four), then one per curve point checked by
   !> auto, each reported (HILLSTAB_PROGRESS=always) up to 100%; the file as a quiet run's.
   subroutine progress_within_an_alpha(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=1024), allocatable :: progress(:), lines(:), quiet_lines(:)
      type(error_t), allocatable :: error
      character(len=:), allocatable :: path, out, written, label
      real :: percent
      integer :: k, n_rows, n_points, n_alphas, done, total, last_done
      logical :: ok, in_order
      out = scratch_prefix("bnd_progress")
      path = out//".nml"
      call write_file(path, two_lines("&scene task = 'boundaries', output = '"//out//"' /", &
                                      "&chart n_alpha = 1, alpha_min = 5, alpha_max = 5, beta_min = -2, "// &
                                      "beta_max = 60 /"))
      call run_with_progress(path, progress, error, written)
      call check(ctx, .not. allocated(error), "the run")
      if (allocated(error)) then
         call check(ctx, .false., error%message)
         call delete_file(path)
         return
      end if
      lines = read_lines(written)
      n_rows = count(lines(:)(1:1) /= "#" .and. len_trim(lines) > 0)
      call check(ctx, n_rows >= 8, "several curves cross the window at alpha = 5")
      n_points = 0
      n_alphas = 0
      last_done = 0
      in_order = .true.
      do k = 1, size(progress)
         call progress_numbers(progress(k), percent, done, total, label, ok)
         call check(ctx, ok, "a progress line: "//trim(progress(k)))
         if (label == "Hill blocks") then
            n_alphas = n_alphas + 1
            call check(ctx, done == n_alphas .and. total == 4, "four blocks of Hill's matrix: "//trim(progress(k)))
         else if (label == "curve points") then
            n_points = n_points + 1
            call check(ctx, total == n_rows, "as many curve points as data rows: "//trim(progress(k)))
            in_order = in_order .and. done == last_done + 1
            last_done = done
            if (done == total) call check(ctx, real(percent, wp), 100.0_wp, abs=0.0_wp, message="100% at the end")
         else
            call check(ctx, .false., "unexpected unit: "//trim(progress(k)))
         end if
      end do
      call check(ctx, n_alphas == 4, "a step per block of Hill's matrix at the one alpha")
      call check(ctx, n_points == n_rows .and. in_order, "a step per curve point, in order")
      call run_scene_file(path, .true., error, written)
      call check(ctx, .not. allocated(error), "the quiet run")
      quiet_lines = read_lines(written)
      call check(ctx, size(quiet_lines) == size(lines), "as many lines quiet")
      if (size(quiet_lines) == size(lines)) call check(ctx, all(quiet_lines == lines), "the same file quiet")
      call delete_file(written)
      call delete_file(path)
   end subroutine progress_within_an_alpha

   !> The critical amplitudes of a spring: progress over the checks by auto of the crossings
   !> and of the verdicts between them (2 n + 1 for n crossings).
   subroutine spring_progress(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=1024), allocatable :: progress(:), lines(:)
      type(error_t), allocatable :: error
      character(len=:), allocatable :: path, out, written, label
      real :: percent
      integer :: k, n_rows, done, total
      logical :: ok
      out = scratch_prefix("bnd_spring_progress")
      path = out//".nml"
      call write_file(path, two_lines("&scene task = 'boundaries', output = '"//out//"' /", &
                                      "&physical omega = 10, r0 = 0.1, g = 9.81 /"))
      call run_with_progress(path, progress, error, written)
      call check(ctx, .not. allocated(error), "the run")
      if (allocated(error)) then
         call check(ctx, .false., error%message)
         call delete_file(path)
         return
      end if
      lines = read_lines(written)
      n_rows = count(lines(:)(1:1) /= "#" .and. len_trim(lines) > 0)
      call check(ctx, n_rows >= 1 .and. size(progress) == 2*n_rows + 1, "a line per check by auto")
      do k = 1, size(progress)
         call progress_numbers(progress(k), percent, done, total, label, ok)
         call check(ctx, ok .and. label == "auto checks" .and. done == k .and. total == 2*n_rows + 1, &
                    "progress line "//trim(progress(k)))
      end do
      call delete_file(written)
      call delete_file(path)
   end subroutine spring_progress
end module test_task_boundaries

!> Tests of the series task through `run_scene_file`, reading the files back: layout and
!> units, samples at exactly t = j T / samples_per_period, the columns against each
!> other (r, φ from x, z; E from the state), the exact bounce from φ0 = 0, a run repeated
!> from its own output, bad input (exit-2 class errors naming file, group and variable,
!> no file), the 1e8-line limit, the hard cases (finite, documented behaviour), and a
!> spring of `&physical` run for a duration in seconds against the same run in periods.
module test_task_series
   use hillstab_core_kinds, only: wp, pi, pi2
   use hillstab_core_error, only: error_t, err_input
   use hillstab_pendulum_equations, only: pendulum_t, pendulum_bounce
   use hillstab_testing
   use hillstab_test_pendulum, only: pendulum_at
   use hillstab_test_files, only: run_text_scene, check_rerun
   use hillstab_test_scratch, only: padded, scratch_prefix, write_file, read_lines, file_exists, delete_file, contains_text
   use hillstab_core_text, only: real_text
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   implicit none
   private
   public :: collect_task_series

contains

   function collect_task_series() result(suite)
      type(testsuite_t) :: suite
      suite = new_testsuite("task_series", [ &
         new_unittest("layout_and_sample_times", layout_and_sample_times), &
         new_unittest("bounce_from_zero_angle", bounce_from_zero_angle), &
         new_unittest("repeat_from_output", repeat_from_output), &
         new_unittest("start_angle_in_both_units", start_angle_in_both_units), &
         new_unittest("onset_summary", onset_summary), &
         new_unittest("bad_input", bad_input), &
         new_unittest("seconds_and_physical", seconds_and_physical), &
         new_unittest("physical_bad_input", physical_bad_input), &
         new_unittest("hard_cases", hard_cases)])
   end function collect_task_series

   !> Run a scene given as lines; return the output file's lines (and delete both files).
   subroutine run_series_text(name, group_series, scene_extra, lines, error)
      character(len=*), intent(in) :: name, group_series, scene_extra
      character(len=1024), allocatable, intent(out) :: lines(:)
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: written
      call run_text_scene(name, [padded("&scene task = 'series', output = '"//scratch_prefix(name)//"' "// &
                                        scene_extra//" /"), padded(group_series)], error, written)
      if (allocated(error)) return
      call read_series_file(written, lines)
      call delete_file(written)
   end subroutine run_series_text

   !> All lines of a series file, read in linear time (the array grows by doubling).
   subroutine read_series_file(path, lines)
      character(len=*), intent(in) :: path
      character(len=1024), allocatable, intent(out) :: lines(:)
      character(len=1024), allocatable :: grown(:)
      character(len=1024) :: line
      integer :: unit, ios, n
      allocate (lines(1024))
      n = 0
      open (newunit=unit, file=path, status="old", action="read", iostat=ios)
      if (ios /= 0) then
         lines = lines(:0)
         return
      end if
      do
         read (unit, '(a)', iostat=ios) line
         if (ios /= 0) exit
         if (n == size(lines)) then
            allocate (grown(2*n))
            grown(:n) = lines
            call move_alloc(grown, lines)
         end if
         n = n + 1
         lines(n) = line
      end do
      close (unit)
      lines = lines(:n)
   end subroutine read_series_file

   !> The numeric rows (8 columns) of a series file.
   function rows_of(lines) result(rows)
      character(len=*), intent(in) :: lines(:)
      real(wp), allocatable :: rows(:, :)
      integer :: k, n, ios
      allocate (rows(8, size(lines)))
      n = 0
      do k = 1, size(lines)
         if (lines(k)(1:1) == "#" .or. len_trim(lines(k)) == 0) cycle
         n = n + 1
         read (lines(k), *, iostat=ios) rows(:, n)
         if (ios /= 0) rows(:, n) = huge(1.0_wp)
      end do
      rows = rows(:, :n)
   end function rows_of

   !> One `# columns:` line `t r phi x z E vx vz`; periods × samples + 1 rows at exactly
   !> t_j = j T/samples (T from ρ, ω written independently here); r = √(x² + z²),
   !> φ = atan2(x, z); the header summary is there.
   subroutine layout_and_sample_times(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=1024), allocatable :: lines(:)
      type(error_t), allocatable :: error
      real(wp), allocatable :: rows(:, :)
      real(wp) :: rho, omega, period, drift, scale, row_drift
      integer :: j
      call run_series_text("series_layout", "&series alpha = 3.7, beta = 2.47, periods = 7, samples_per_period = 13 /", &
                           ", tolerance = 1e-10", lines, error)
      call check(ctx, .not. allocated(error), "run succeeds")
      if (allocated(error)) then
         call check(ctx, .false., error%message)
         return
      end if
      call check(ctx, count(index(lines, "# columns: ") == 1) == 1, "one columns line")
      call check(ctx, any(lines == "# columns: t r phi x z E vx vz"), "columns t r phi x z E vx vz")
      call check(ctx, any(index(lines, "# &series alpha = 3.7, beta = 2.47, phi0 = 0.017, periods = 7") == 1), &
         "effective &series in the header")
      call check(ctx, any(index(lines, "# summary: max |phi|") == 1), "summary: max |phi|")
      call check(ctx, any(index(lines, "lambda_max =") > 0), "summary: lambda_max")
      call check(ctx, any(index(lines, "# summary: onset") == 1), "summary: onset")
      call check(ctx, any(index(lines, "f-evaluations") > 0), "summary: work")
      rows = rows_of(lines)
      call check(ctx, size(rows, 2) == 7*13 + 1, "periods * samples_per_period + 1 rows")
      rho = 0.1_wp*pi2/(pi2 - 2.47_wp)
      omega = sqrt(9.81_wp/(rho - 0.1_wp))
      period = 2.0_wp*pi/omega
      do j = 0, size(rows, 2) - 1
         call check(ctx, rows(1, j + 1), j*period/13, abs=1.0e-15_wp*max(1.0_wp, j*period/13), message="t_j")
      end do
      call check(ctx, maxval(abs(rows(2, :) - hypot(rows(4, :), rows(5, :)))) < 1.0e-15_wp, "r = |(x, z)|")
      call check(ctx, maxval(abs(rows(3, :) - atan2(rows(4, :), rows(5, :)))) < 1.0e-15_wp, "phi = atan2(x, z)")
      call check(ctx, rows(3, 1), 0.017_wp, abs=1.0e-16_wp, message="phi(0) = phi0")
      call check(ctx, rows(2, 1), rho*(1.0_wp - 3.7_wp/pi2), rel=1.0e-15_wp, message="r(0) = rho - a")
      ! energy per unit mass from the written state, against the E column
      call check(ctx, maxval(abs(rows(6, :) - (0.5_wp*(rows(7, :)**2 + rows(8, :)**2) &
         + 0.5_wp*omega**2*(rows(2, :) - 0.1_wp)**2 - 9.81_wp*rows(5, :)))) < 1.0e-12_wp, "E column")
      call check(ctx, maxval(abs(rows(6, :) - rows(6, 1))) < 1.0e-8_wp*abs(rows(6, 1)) + 1.0e-9_wp, &
         "energy conserved on the samples")
      ! the header's drift is the largest over the written rows (their E column, 17 digits)
      drift = header_number(lines, "max|E - E(0)|/E_scale = ")
      scale = header_number(lines, "summary: E_scale = ")
      row_drift = maxval(abs(rows(6, :) - rows(6, 1)))/scale
      call check(ctx, drift, row_drift, rel=1.0e-6_wp, abs=1.0e-3_wp*row_drift, &
                 message="header drift = max over the written rows")
      call check(ctx, drift > 0.0_wp .and. header_number(lines, "over the written rows (") > 0.0_wp, &
                 "both drifts stated")
   end subroutine layout_and_sample_times

   !> The summary's onset at (e) from φ0 = 1e-8: the predicted X (the linear swing) within
   !> 0.1 radial period of the observed Y, and the multiplier law on its own line.
   subroutine onset_summary(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=1024), allocatable :: lines(:)
      type(error_t), allocatable :: error
      real(wp) :: predicted, observed, law
      call run_series_text("series_onset", "&series alpha = 7.88, beta = 3.95, phi0 = 1e-8, periods = 12, "// &
                           "samples_per_period = 4 /", ", tolerance = 1e-10", lines, error)
      call check(ctx, .not. allocated(error), "run succeeds")
      if (allocated(error)) return
      predicted = header_number(lines, "u(t) = ")
      observed = header_number(lines, " s), observed ")
      law = header_number(lines, "ln(0.1/|phi0|)/ln(lambda_max) = ")
      call check(ctx, any(index(lines, "# summary: onset (|phi| > 0.1): predicted n* = ") == 1), "summary line form")
      call check(ctx, predicted > 0.0_wp .and. observed > 0.0_wp .and. law > 0.0_wp, "three onsets stated")
      call check(ctx, predicted, observed, abs=0.1_wp, message="predicted onset within 0.1 period of the observed")
      call check(ctx, observed - law > 0.2_wp, "the multiplier law alone comes earlier")
   end subroutine onset_summary

   !> The number that follows `key` on the first header line containing it (−1 if none).
   real(wp) function header_number(lines, key) result(x)
      character(len=*), intent(in) :: lines(:), key
      integer :: i, at, ios
      x = -1.0_wp
      do i = 1, size(lines)
         at = index(lines(i), key)
         if (at == 0 .or. lines(i)(1:1) /= "#") cycle
         read (lines(i)(at + len(key):), *, iostat=ios) x
         if (ios /= 0) x = -1.0_wp
         return
      end do
   end function header_number

   !> φ0 = 0: the swing never starts (x ≡ 0 exactly) and z follows ρ − a cos ωt.
   subroutine bounce_from_zero_angle(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=1024), allocatable :: lines(:)
      type(error_t), allocatable :: error
      real(wp), allocatable :: rows(:, :)
      type(pendulum_t) :: p
      integer :: j
      real(wp) :: exact(4), worst
      call run_series_text("series_zero", "&series alpha = 7.88, beta = 3.95, phi0 = 0.0, periods = 60 /", &
                           ", tolerance = 1e-11", lines, error)
      call check(ctx, .not. allocated(error), "run succeeds")
      if (allocated(error)) return
      rows = rows_of(lines)
      call check(ctx, all(rows(4, :) == 0.0_wp) .and. all(rows(7, :) == 0.0_wp), "x = vx = 0 exactly")
      call check(ctx, any(index(lines, "u(t) = never") > 0) .and. any(index(lines, "ln(lambda_max) = never") > 0), &
         "no onset predicted")
      call check(ctx, any(index(lines, "observed not within the run") > 0), "no onset observed")
      p = pendulum_at(7.88_wp, 3.95_wp)
      worst = 0.0_wp
      do j = 1, size(rows, 2)
         exact = pendulum_bounce(p, rows(1, j))
         worst = max(worst, abs(rows(5, j) - exact(2))/p%rho)
      end do
      call check(ctx, worst < 1.0e-9_wp, "z = rho - a cos(omega t)")
   end subroutine bounce_from_zero_angle

   !> The output file as a scene repeats the run line for line.
   subroutine repeat_from_output(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(error_t), allocatable :: error
      character(len=:), allocatable :: written, again
      character(len=1024), allocatable :: first(:)
      logical :: ok
      call run_text_scene("series_repeat", [padded("&scene task = 'series', output = '"// &
         scratch_prefix("series_repeat")//"', epsilon = 0.2 /"), &
         padded("&series alpha = 5.0, beta = 0.76, phi0 = -0.3, periods = 3, samples_per_period = 7, vx0 = 0.05 /")], &
         error, written)
      call check(ctx, .not. allocated(error), "first run")
      if (allocated(error)) return
      first = read_lines(written)
      call check_rerun(ctx, written, first, again, ok)
      if (.not. ok) return
      call check(ctx, any(index(first, "E decreases monotonically") > 0), "damped summary")
      call delete_file(written)
   end subroutine repeat_from_output

   !> The header gives the start angle in radians and in degrees, whichever the scene used;
   !> a run started by `phi0_degrees` repeats from its output, and equals the run started
   !> by the same angle in radians.
   subroutine start_angle_in_both_units(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(error_t), allocatable :: error
      character(len=1024), allocatable :: by_degrees(:), by_radians(:)
      character(len=:), allocatable :: written, again
      character(len=:), allocatable :: first(:)
      logical :: ok
      integer :: k
      call run_series_text("series_degrees", "&series phi0_degrees = 1, periods = 2, samples_per_period = 5 /", "", &
         by_degrees, error)
      call check(ctx, .not. allocated(error), "phi0_degrees runs")
      if (allocated(error)) return
      call check(ctx, any(index(by_degrees, "phi(0) = phi0 = "//real_text(pi/180.0_wp)//" rad = 1.0 degrees") > 0), &
         "the header gives 1 degree in both units")
      call run_series_text("series_radians", "&series phi0 = "//real_text(pi/180.0_wp)//", periods = 2, "// &
         "samples_per_period = 5 /", "", by_radians, error)
      call check(ctx, .not. allocated(error), "phi0 runs")
      if (allocated(error)) return
      call check(ctx, any(index(by_radians, "phi(0) = phi0 = "//real_text(pi/180.0_wp)//" rad = ") > 0), &
         "the header gives the angle in radians and degrees")
      call check(ctx, size(by_degrees) == size(by_radians), "as many lines")
      if (size(by_degrees) /= size(by_radians)) return
      do k = 1, size(by_degrees)
         if (by_degrees(k)(1:1) == "#") cycle
         call check(ctx, by_degrees(k) == by_radians(k), "the same data line "//trim(by_degrees(k)))
      end do
      call run_text_scene("series_degrees_again", [padded("&scene task = 'series', output = '"// &
         scratch_prefix("series_degrees_again")//"' /"), padded("&series phi0_degrees = -3.5, periods = 1 /")], &
         error, written)
      call check(ctx, .not. allocated(error), "phi0_degrees = -3.5 runs")
      if (allocated(error)) return
      first = read_lines(written)
      call check_rerun(ctx, written, first, again, ok)
      call delete_file(written)
   end subroutine start_angle_in_both_units

   !> Each bad `&series` value: err_input naming file, group and variable; no file.
   subroutine bad_input(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=64), parameter :: groups(12) = [character(len=64) :: &
         "&series periods = 0 /", "&series samples_per_period = 0 /", "&series r0 = 0.0 /", &
         "&series g = -9.81 /", "&series beta = 0.0 /", "&series beta = 9.87 /", "&series alpha = 9.87 /", &
         "&series phi0 = nan /", "&series alpha = inf /", "&series periods = 2000000, samples_per_period = 51 /", &
         "&series periods = 'x' /", "&series colour = 1 /"]
      character(len=24), parameter :: variables(12) = [character(len=24) :: "periods", "samples_per_period", &
         "r0", "g", "beta", "beta", "alpha", "phi0", "alpha", "periods", "periods", "colour"]
      type(error_t), allocatable :: error
      character(len=:), allocatable :: path, out, written
      integer :: k
      out = scratch_prefix("series_bad")
      path = out//".nml"
      do k = 1, size(groups)
         call run_text_scene("series_bad", [padded("&scene task = 'series', output = '"//out//"' /"), padded(groups(k))], &
                             error, written)
         call check(ctx, allocated(error), "error for "//trim(groups(k)))
         if (allocated(error)) then
            call check(ctx, error%code == err_input, "input error code for "//trim(groups(k)))
            call check(ctx, contains_text(error%message, path//": &series: "//trim(variables(k))//":"), &
               "names file, group, variable: "//error%message)
         end if
         call check(ctx, .not. file_exists(out//"_series.dat"), "no file for "//trim(groups(k)))
      end do
      ! the limit names its size
      call run_text_scene("series_bad", [padded("&scene task = 'series', output = '"//out//"' /"), padded(groups(10))], &
                          error, written)
      if (allocated(error)) call check(ctx, contains_text(error%message, "limit of 1e8"), "line limit message")
      ! the model must be the elastic pendulum
      call run_text_scene("series_bad", [padded("&scene task = 'series', model = 'mathieu', output = '"//out//"' /"), &
         padded("&series /")], error, written)
      call check(ctx, allocated(error), "mathieu model refused")
      if (allocated(error)) call check(ctx, contains_text(error%message, "&scene: model:"), error%message)
   end subroutine bad_input

   !> A spring of &physical (k, m, r0, g, one a) run for `duration` seconds: rows at exactly
   !> t_j = j T/samples (T = 2 pi sqrt(m/k) here), the last one at t <= duration within one
   !> spacing, as many as floor(duration/spacing) + 1; and the same rows as the run of
   !> &series alpha, beta, r0, g (alpha, beta read from the first run's header) in periods,
   !> when the duration ends within that run's last spacing.
   subroutine seconds_and_physical(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=*), parameter :: spring = "&physical k = 25, m = 0.25, g = 9.81, r0 = 0.3, a = 0.05 /"
      character(len=1024), allocatable :: lines(:), by_periods(:), by_seconds(:)
      type(error_t), allocatable :: error
      real(wp), allocatable :: rows(:, :)
      real(wp) :: period, spacing, t_last
      character(len=:), allocatable :: alpha_text, beta_text, header
      character(len=64) :: duration_text
      integer :: k, j, n_data
      period = 2.0_wp*pi*sqrt(0.25_wp/25.0_wp)
      spacing = period/20.0_wp
      call run_physical("series_sec", "&series duration = 3.0, samples_per_period = 20 /", spring, lines, error)
      call check(ctx, .not. allocated(error), "series in seconds with &physical")
      if (allocated(error)) then
         call check(ctx, .false., error%message)
         return
      end if
      rows = rows_of(lines)
      call check(ctx, size(rows, 2) == floor(3.0_wp/spacing) + 1, "floor(duration/spacing) + 1 rows")
      do j = 1, size(rows, 2)
         call check(ctx, rows(1, j), real(j - 1, wp)*period/20.0_wp, rel=1.0e-15_wp, abs=1.0e-300_wp, &
                    message="t_j = j T/samples")
      end do
      t_last = rows(1, size(rows, 2))
      call check(ctx, t_last <= 3.0_wp .and. 3.0_wp - t_last < spacing, "last row within one spacing of duration")
      call check(ctx, rows(2, 1), 0.3_wp + 9.81_wp*0.25_wp/25.0_wp - 0.05_wp, rel=1.0e-14_wp, &
                 message="r(0) = rho - a, rho = r0 + m g/k")
      ! alpha and beta as the header states them (shortest round-trip text)
      alpha_text = ""
      beta_text = ""
      do k = 1, size(lines)
         header = trim(lines(k))
         j = index(header, "# the pendulum of &physical: alpha = a pi^2/rho = ")
         if (j == 1) then
            header = header(len("# the pendulum of &physical: alpha = a pi^2/rho = ") + 1:)
            alpha_text = header(:index(header, ",") - 1)
            beta_text = header(index(header, "beta = ") + 7:index(header, " (eq.") - 1)
         end if
      end do
      call check(ctx, len(alpha_text) > 0 .and. len(beta_text) > 0, "alpha and beta in the header")
      if (len(alpha_text) == 0) return
      call run_series_text("series_per", "&series alpha = "//alpha_text//", beta = "//beta_text// &
                           ", r0 = 0.3, g = 9.81, periods = 4, samples_per_period = 20 /", "", by_periods, error)
      call check(ctx, .not. allocated(error), "the same pendulum in periods")
      if (allocated(error)) return
      rows = rows_of(by_periods)
      t_last = rows(1, size(rows, 2))
      write (duration_text, '(es24.17)') t_last + 0.5_wp*spacing
      call run_physical("series_sec2", "&series duration = "//trim(duration_text)//", samples_per_period = 20 /", &
                        spring, by_seconds, error)
      call check(ctx, .not. allocated(error), "the duration of 4 periods")
      if (allocated(error)) return
      n_data = 0
      call check(ctx, size(rows_of(by_seconds), 2) == 81, "4 periods of 20 samples and t = 0")
      do k = 1, size(by_periods)
         if (by_periods(k)(1:1) == "#") cycle
         n_data = n_data + 1
         j = data_line(by_seconds, n_data)
         if (j == 0) exit
         call check(ctx, by_seconds(j) == by_periods(k), "the same row in seconds and in periods")
      end do
      call check(ctx, n_data == 81, "every row compared")
      ! the header's energy drift over the written rows is that of the rows, in seconds as in
      ! periods (it was 0 in seconds: no sample time was watched)
      call check(ctx, drift_text(by_seconds) == drift_text(by_periods), "the same drift in seconds ("// &
                 drift_text(by_seconds)//") and in periods ("//drift_text(by_periods)//")")
      call check(ctx, drift_text(by_seconds) /= "0" .and. len(drift_text(by_seconds)) > 0, &
                 "a drift over the rows in seconds: "//drift_text(by_seconds))
   end subroutine seconds_and_physical

   !> The header's energy drift over the written rows (the text after "max|E - E(0)|/E_scale = ").
   function drift_text(lines) result(text)
      character(len=*), intent(in) :: lines(:)
      character(len=:), allocatable :: text
      character(len=*), parameter :: key = "max|E - E(0)|/E_scale = "
      integer :: k, j
      text = ""
      do k = 1, size(lines)
         if (lines(k)(1:1) /= "#") cycle
         j = index(lines(k), key)
         if (j == 0) cycle
         text = lines(k)(j + len(key):)
         text = text(:index(text//" ", " ") - 1)
         return
      end do
   end function drift_text

   !> The index of the n-th data line (0 when there are fewer).
   pure integer function data_line(lines, n) result(j)
      character(len=*), intent(in) :: lines(:)
      integer, intent(in) :: n
      integer :: count
      count = 0
      do j = 1, size(lines)
         if (lines(j)(1:1) == "#" .or. len_trim(lines(j)) == 0) cycle
         count = count + 1
         if (count == n) return
      end do
      j = 0
   end function data_line

   !> Run a series scene with a &physical line.
   subroutine run_physical(name, group_series, physical, lines, error)
      character(len=*), intent(in) :: name, group_series, physical
      character(len=1024), allocatable, intent(out) :: lines(:)
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: written
      call run_text_scene(name, [padded("&scene task = 'series', output = '"//scratch_prefix(name)//"' /"), &
                                 padded(group_series), padded(physical)], error, written)
      if (allocated(error)) return
      call read_series_file(written, lines)
      call delete_file(written)
   end subroutine run_physical

   !> Bad input of a series in seconds or in physical units: exit-2 class errors naming
   !> file, group and variable, no file.
   subroutine physical_bad_input(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=80), parameter :: cases(8) = [character(len=80) :: &
         "&series duration = 0 /", "&series duration = -2 /", "&series duration = 2, periods = 3 /", &
         "&series alpha = 1.0 /", "&series r0 = 0.2 /", "&series duration = 1e-4 /", &
         "&series duration = 1e9, samples_per_period = 1000 /", "&series /"]
      character(len=40), parameter :: where(8) = [character(len=40) :: "&series: duration:", "&series: duration:", &
         "&series: duration:", "&series: alpha:", "&series: r0:", "&series: duration:", "&series: duration:", &
         "&physical: a:"]
      type(error_t), allocatable :: error
      character(len=:), allocatable :: out, written, physical
      integer :: k
      out = scratch_prefix("series_pbad")
      do k = 1, size(cases)
         physical = "&physical k = 25, m = 0.25, g = 9.81, r0 = 0.3, a = 0.05 /"
         if (k == 8) physical = "&physical k = 25, m = 0.25, g = 9.81, r0 = 0.3, a = 0.05, 0.1 /"
         call run_text_scene("series_pbad", [padded("&scene task = 'series', output = '"//out//"' /"), &
                             padded(cases(k)), padded(physical)], error, written)
         call check(ctx, allocated(error), "error for "//trim(cases(k)))
         if (allocated(error)) then
            call check(ctx, error%code == err_input, "input error code for "//trim(cases(k)))
            call check(ctx, contains_text(error%message, trim(where(k))), "names "//trim(where(k))//": "// &
                       error%message)
         end if
         call check(ctx, .not. file_exists(out//"_series.dat"), "no file for "//trim(cases(k)))
      end do
   end subroutine physical_bad_input

   !> α = 9.8 (r_min = 0.7 % of ρ), ε = 3, φ0 = 1e-300, φ0 = π/2, 10⁴ periods: finite rows,
   !> and the documented behaviour of each.
   subroutine hard_cases(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=1024), allocatable :: lines(:)
      type(error_t), allocatable :: error
      real(wp), allocatable :: rows(:, :)
      type(pendulum_t) :: p
      ! α = 9.8: the bounce comes within 0.7 % of ρ of the pivot; energy still conserved
      call run_series_text("series_hard1", "&series alpha = 9.8, beta = 2.47, phi0 = 0.017, periods = 20 /", &
                           ", tolerance = 1e-10", lines, error)
      call check_finite("alpha = 9.8")
      if (allocated(rows)) then
         p = pendulum_at(9.8_wp, 2.47_wp)
         call check(ctx, minval(rows(2, :)) > 0.0_wp, "alpha = 9.8: r > 0")
         write (*, '(4x,a,es10.3,a,es10.3)') "alpha = 9.8: min r/rho = ", minval(rows(2, :))/p%rho, &
            ", max |phi| on samples ", maxval(abs(rows(3, :)))
      end if
      ! ε = 3: the swing and the bounce decay; E decreases monotonically
      call run_series_text("series_hard2", "&series alpha = 7.88, beta = 3.95, phi0 = 0.5, periods = 30 /", &
                           ", epsilon = 3.0", lines, error)
      call check_finite("epsilon = 3")
      if (allocated(rows)) then
         call check(ctx, all(rows(6, 2:) <= rows(6, :size(rows, 2) - 1) + 1.0e-14_wp), "epsilon = 3: E decreases")
         call check(ctx, abs(rows(3, size(rows, 2))) < 1.0e-6_wp, "epsilon = 3: the swing has died out")
      end if
      ! φ0 = 1e-300: relative accuracy in x from the start; the swing grows from 1e-300
      call run_series_text("series_hard3", "&series alpha = 7.88, beta = 3.95, phi0 = 1e-300, periods = 20 /", &
                           "", lines, error)
      call check_finite("phi0 = 1e-300")
      if (allocated(rows)) then
         call check(ctx, rows(3, 1), 1.0e-300_wp, rel=1.0e-15_wp, message="phi0 = 1e-300 written")
         call check(ctx, abs(rows(3, size(rows, 2))) > 1.0e-290_wp, "phi0 = 1e-300 grows")
      end if
      ! φ0 = π/2: a large swing from the horizontal
      call run_series_text("series_hard4", "&series alpha = 1.48, beta = 2.47, phi0 = 1.5707963267948966, periods = 20 /", &
                           ", tolerance = 1e-11", lines, error)
      call check_finite("phi0 = pi/2")
      if (allocated(rows)) call check(ctx, maxval(abs(rows(6, :) - rows(6, 1))) < 1.0e-8_wp, "phi0 = pi/2: energy")
      ! 10⁴ periods, one sample a period
      call run_series_text("series_hard5", "&series alpha = 7.88, beta = 3.95, periods = 10000, samples_per_period = 1 /", &
                           "", lines, error)
      call check_finite("10^4 periods")
      if (allocated(rows)) then
         call check(ctx, size(rows, 2) == 10001, "10^4 periods: all rows")
         write (*, '(4x,a,a)') "10^4 periods: ", trim(lines(findloc(index(lines, "drift") > 0, .true., 1)))
      end if
   contains
      subroutine check_finite(label)
         character(len=*), intent(in) :: label
         if (allocated(rows)) deallocate (rows)
         call check(ctx, .not. allocated(error), label//": run succeeds")
         if (allocated(error)) then
            call check(ctx, .false., error%message)
            return
         end if
         rows = rows_of(lines)
         call check(ctx, all(ieee_is_finite(rows)) .and. all(rows /= huge(1.0_wp)), label//": finite rows")
      end subroutine check_finite
   end subroutine hard_cases
end module test_task_series

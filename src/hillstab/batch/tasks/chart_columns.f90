!> What the chart and points tasks of one equation share: the columns of their files (their
!> records, `chart_column_table`, and the value of each at a computed point, `chart_values`,
!> both of hillstab_batch_tasks_floquet_columns), the evaluation of one point by the scene's
!> method, the header lines, the text rows, and the messages for failed and round-off limited
!> points.
!>
!> A new column of chart and points files is added in hillstab_batch_tasks_floquet_columns
!> and nowhere else: its key in `chart_keys` (its place in the file order, its `col_*`
!> index), its record in `floquet_column` and its value in `chart_values`. The `# columns:`
!> line, the header's lines (the column's meaning, its `# accuracy of` line, its
!> placeholder), `&scene columns`, what a file computes, the text and binary rows and the
!> units of the MPI program follow from the table.
!>
!>```fortran
!> type(chart_layout_t) :: columns
!> type(error_t), allocatable :: error
!> call scene_chart_columns(scene, columns, error)
!> print '(a)', chart_names(columns)   ! the `# columns:` line's names
!>```
module hillstab_batch_tasks_chart_columns
   use hillstab_core_kinds, only: wp, int64, version_string, pi
   use hillstab_core_error, only: error_t, set_error, err_input, err_accuracy, err_invalid_parameter, &
      err_points_failed
   use hillstab_core_status, only: status_ok, status_roundoff, status_failed
   use hillstab_core_text, only: real_text, integer_text, put_es
   use hillstab_hill_model, only: hill_model_t, hill_point_t, model_description, model_equation_text
   use hillstab_hill_coefficient, only: sampling_name
   use hillstab_hill_transfer, only: trace_t
   use hillstab_hill_floquet, only: floquet_t, set_from_trace, floquet_verdict, largest_multiplier_modulus, &
      verdicts, near_threshold
   use hillstab_hill_model_pendulum, only: is_elastic_pendulum, pendulum_note
   use hillstab_integrate_monodromy, only: monodromy_trace_batch, method_name, method_uses_segments, method_is_exact, &
      need_nothing, need_verdict, need_growth, need_trace
   use hillstab_batch_scene_types, only: scene_t, task_t, scene_header, output_path
   use hillstab_batch_scene_physical, only: physical_summary, physical_scene_t, pendulum_task_t
   use hillstab_batch_scene_file, only: fail
   use hillstab_batch_tasks_floquet_columns, only: chart_column_t, column_context_t, floquet_column, scene_columns, &
      chart_keys, plain_table, accuracy_none, accuracy_verdict, n_chart_columns, chart_values, clamp_magnitude, log10_floor, &
      col_alpha, col_a, col_beta, col_omega, col_stable, col_physical, col_stable_paper, col_status, accuracy_growth, &
      accuracy_estimate, accuracy_argument, col_mu_per_s
   use hillstab_batch_output_columns, only: column_t, style_flag, column_lines, columns_text, put_value
   use, intrinsic :: iso_fortran_env, only: error_unit
   implicit none
   private
   public :: floquet_task_t, chart_column_t, chart_layout_t, chart_column_table, chart_names, chart_values
   public :: scene_chart_columns, n_chart_columns
   public :: chart_header, common_header, evaluate_point, failed_points_error, check_method_runs, warn_inaccurate
   public :: clamp_magnitude, log10_floor, chart_line_length, stacked, chart_line, failed_values
   public :: header_bytes, text_row_bytes, binary_row_bytes, point_amplitude, tau_per_time, verdict_lines, col_physical
   public :: col_mu_per_s

   !> Characters in one chart line (17 columns of at most 24 characters, with blanks: 254 at
   !> most).
   integer, parameter :: chart_line_length = 280

   !> The columns of one chart or points file, made once per file (`scene_chart_columns`):
   !> the table of its scene, the columns written and what they need.
   type :: chart_layout_t
      type(chart_column_t), allocatable :: table(:)  !! every column (`chart_column_table`), by col_* index
      integer, allocatable :: ids(:)                  !! the columns written, in file order
      integer :: need = need_nothing  !! what they need computed at each point: the most any of them needs
      logical :: paper = .false.      !! they include a verdict by the paper's criterion
      !> the table's digits and styles by col_* index, as plain arrays for the row writers
      !> (read through the records at every value of every line they cost a fifth of the
      !> lines' formatting)
      integer :: digits(n_chart_columns) = 0
      integer :: styles(n_chart_columns) = 0  !! see `digits`
   end type chart_layout_t

   !> Bytes of a header (an upper bound), of one row as text (an upper bound) and binary.
   integer(int64), parameter :: header_bytes = 16384, text_row_bytes = 255, binary_row_bytes = 8*18

   !> A task writing the chart's columns (chart, points): what runs in units ends as a
   !> serial run ends.
   type, abstract, extends(pendulum_task_t) :: floquet_task_t
   contains
      procedure :: finish_units => floquet_finish_units
   end type floquet_task_t

contains

   !> After a distributed run, as after a serial one: round-off limited points warned about,
   !> failed ones an error naming the first.
   subroutine floquet_finish_units(self, scene, n_points, n_failed, first_failed, n_inaccurate, first_inaccurate, &
                                   error)
      class(floquet_task_t), intent(in) :: self  !! the task
      type(scene_t), intent(in) :: scene  !! its scene
      integer(int64), intent(in) :: n_points  !! all points
      integer(int64), intent(in) :: n_failed  !! failed points written
      real(wp), intent(in) :: first_failed(2)  !! (α, β) of the first of them
      integer(int64), intent(in) :: n_inaccurate  !! round-off limited points written
      real(wp), intent(in) :: first_inaccurate(2)  !! (α, β) of the first of them
      type(error_t), allocatable, intent(out) :: error  !! err_points_failed when points failed
      call warn_inaccurate(scene, n_inaccurate, first_inaccurate)
      call failed_points_error(scene, n_failed, n_points, first_failed, error)
   end subroutine floquet_finish_units

   !> Every column of a chart or points file of this scene, one record each, by its col_*
   !> index: the records of `floquet_column` for one equation's file (meanings and what is
   !> offered depend on the model, the damping and `&physical`).
   function chart_column_table(scene, physical) result(table)
      type(scene_t), intent(in) :: scene  !! the scene
      type(physical_scene_t), intent(in) :: physical  !! its `&physical` (the task's)
      type(chart_column_t) :: table(n_chart_columns)
      type(column_context_t) :: context
      integer :: k
      context%damped = scene%epsilon > 0.0_wp .or. scene%model%has_damping()
      context%pendulum = is_elastic_pendulum(scene%model)
      context%physical = physical%given
      context%amplitudes = size(physical%amplitudes) > 0
      context%omegas = size(physical%omegas) > 0
      context%own_time = scene%model%has_time()
      context%alpha_name = scene%model%axis_name(1)
      context%beta_name = scene%model%axis_name(2)
      context%summary = scene%model%summary()
      context%threshold = damped_threshold(scene)
      context%period = period_text(scene)
      do k = 1, n_chart_columns
         table(k) = floquet_column(trim(chart_keys(k)), context)
      end do
   end function chart_column_table

   !> The columns a chart or points file of this scene holds: `&scene columns` when given,
   !> else all it offers (in file order); an error naming `&scene columns` when a name is
   !> not offered.
   subroutine scene_chart_columns(scene, physical, columns, error)
      type(scene_t), intent(in) :: scene  !! a chart or points scene
      type(physical_scene_t), intent(in) :: physical  !! its `&physical` (the task's)
      type(chart_layout_t), intent(out) :: columns  !! its table, the columns written and what they need
      type(error_t), allocatable, intent(out) :: error  !! err_input naming &scene columns
      integer, allocatable :: available(:)
      integer :: k
      columns%table = chart_column_table(scene, physical)
      allocate (available(0))
      do k = 1, n_chart_columns
         if (columns%table(k)%offered) available = [available, k]
      end do
      call scene_columns(columns%table, available, scene%columns, scene%source, columns%ids, error, &
                         pack(available, .not. columns%table(available)%on_request))
      columns%digits = columns%table%digits
      columns%styles = columns%table%style
      columns%need = need_nothing
      columns%paper = .false.
      do k = 1, size(columns%ids)
         columns%need = max(columns%need, columns%table(columns%ids(k))%need)
         columns%paper = columns%paper .or. columns%table(columns%ids(k))%paper
      end do
   end subroutine scene_chart_columns

   !> The names of the columns written, blank-separated (the `# columns:` line).
   function chart_names(columns) result(text)
      type(chart_layout_t), intent(in) :: columns  !! the file's columns
      character(len=:), allocatable :: text
      text = columns_text(plain_table(columns%table), columns%ids)
   end function chart_names

   !> The header's line on the accuracy of column `k` of a file's columns ("" for a column
   !> that needs nothing computed).
   function accuracy_line(scene, columns, k) result(line)
      type(scene_t), intent(in) :: scene  !! the scene
      type(chart_layout_t), intent(in) :: columns  !! the file's columns
      integer, intent(in) :: k            !! a column
      character(len=:), allocatable :: line
      character(len=:), allocatable :: tolerance, threshold
      line = ""
      if (columns%table(k)%accuracy == accuracy_none) return
      line = "accuracy of "//columns%table(k)%name//": "
      if (.not. method_is_exact(scene%method%kind)) then
         line = line//"the value of method '"//method_name(scene%method%kind)//"' itself (an approximation, "// &
            "no error bound)"
         return
      end if
      tolerance = real_text(scene%method%tolerance)
      threshold = "|S| = "//damped_threshold(scene)
      if (.not. (scene%epsilon > 0.0_wp .or. scene%model%has_damping())) threshold = "|S| = 2"
      select case (columns%table(k)%accuracy)
      case (accuracy_verdict)
         if (columns%table(k)%paper) threshold = "|S| = 2"
         if (columns%need == need_verdict) then
            line = line//"exact except at 0.5 (marginal): each point computed only until "//threshold// &
               " lies beyond the error bound of its S (a screening pass; the tolerance "//tolerance// &
               " where that does not settle it)"
         else
            line = line//"exact except at 0.5 (marginal), from S computed to the tolerance "//tolerance
         end if
      case (accuracy_growth)
         line = line//"exact where |S| < 2 (lambda_max = exp(-epsilon), mu = -epsilon/2); elsewhere from S "// &
            "computed to the tolerance "//tolerance//": relative error of lambda_max (absolute error of 2 mu) "// &
            "at most "//tolerance//" max(1, |S|)/sqrt(S^2 - 4)"
      case (accuracy_estimate)
         line = line//"the method's own estimate; at status 0 at most the tolerance "//tolerance
      case (accuracy_argument)
         line = line//"exact (0 or 1) where |S| > 2; where |S| < 2 from S computed to the tolerance "// &
            tolerance//": absolute error at most "//tolerance//" max(1, |S|)/(pi sqrt(4 - S^2))"
      case default
         line = line//"to the tolerance "//tolerance//": |error of S| <= max(error_estimate, "//tolerance// &
            ") max(1, |S|) at status 0"
      end select
   end function accuracy_line


   !> The text lines of points computed for their verdicts only, written directly into
   !> buffer(pos + 1 : …), one new-line character between two lines, pos advanced past the
   !> last (what `chart_values` of `floquet_verdict` and `chart_line` write, without the array of every
   !> column's value and the dispatch by style: a verdict chart writes little more than the
   !> grid and a flag, and this loop is most of its text's cost). The verdicts are those of
   !> `verdicts` (hillstab_hill_floquet), the usual case (no damping, an estimate below 1)
   !> written out here; a failed point's line is `chart_line`'s of `failed_values`; a column
   !> without a case here gets its value from `chart_values` of `floquet_verdict`.
   pure subroutine verdict_lines(columns, alpha, betas, traces, decays, tolerance, statuses, physical, amplitudes, &
                                 alpha_text, buffer, pos, beta_texts)
      type(chart_layout_t), intent(in) :: columns  !! the columns to write (none needing more than the verdict)
      real(wp), intent(in) :: alpha        !! the points' α
      real(wp), intent(in) :: betas(:)     !! their β
      type(trace_t), intent(in) :: traces(:)  !! their traces, with error bounds
      real(wp), intent(in) :: decays(:)    !! each point's damping over a period (`period_damping`)
      real(wp), intent(in) :: tolerance    !! the scene's tolerance
      integer, intent(in) :: statuses(:)   !! per-point status codes (status_failed: no trace)
      !> (α, β) inside the physical domain, per point; empty when no column asks
      logical, intent(in) :: physical(:)
      real(wp), intent(in) :: amplitudes(:)  !! a (m) per point; empty for 0
      character(len=24), intent(in) :: alpha_text  !! put_es(alpha, 17)
      character(len=*), intent(inout) :: buffer  !! room for the lines (chart_line_length + 1 each)
      integer, intent(inout) :: pos        !! last position written; advanced past the lines
      character(len=24), intent(in), optional :: beta_texts(:)  !! put_es(betas, 17)
      logical :: stable, stable_paper, marginal, inside
      real(wp) :: s, a, v(n_chart_columns)
      integer :: j, k, p, length
      ! the columns in a local array: read through `columns` at every point and column, they
      ! cost a tenth of a verdict line
      integer :: ids(size(columns%ids))
      ids = columns%ids
      do j = 1, size(betas)
         if (j > 1) then
            buffer(pos + 1:pos + 1) = new_line("a")
            pos = pos + 1
         end if
         inside = .true.
         if (size(physical) > 0) inside = physical(j)
         a = 0.0_wp
         if (size(amplitudes) > 0) a = amplitudes(j)
         if (statuses(j) == status_failed) then
            if (present(beta_texts)) then
               call chart_line(columns, failed_values(columns, alpha, betas(j), inside, a), &
                               buffer(pos + 1:pos + chart_line_length), alpha_text, beta_texts(j), length)
            else
               call chart_line(columns, failed_values(columns, alpha, betas(j), inside, a), &
                               buffer(pos + 1:pos + chart_line_length), alpha_text, length=length)
            end if
            pos = pos + length
            cycle
         end if
         s = traces(j)%value
         if (decays(j) == 0.0_wp .and. .not. traces(j)%overflow .and. traces(j)%error_estimate >= 0.0_wp .and. &
             traces(j)%error_estimate < 1.0_wp) then
            stable = abs(s) < 2.0_wp
            stable_paper = abs(s) <= 2.0_wp
            marginal = near_threshold(s, 0.0_wp, max(traces(j)%error_estimate, tolerance))
         else
            call verdicts(traces(j), decays(j), tolerance, stable, stable_paper, marginal)
         end if
         do k = 1, size(ids)
            if (k > 1) then
               buffer(pos + 1:pos + 1) = " "
               pos = pos + 1
            end if
            select case (ids(k))
            case (col_alpha)
               call put_text24(buffer, pos, alpha_text)
            case (col_beta)
               if (present(beta_texts)) then
                  call put_text24(buffer, pos, beta_texts(j))
               else
                  p = pos
                  call put_es(buffer, p, betas(j), columns%digits(col_beta))
                  pos = p
               end if
            case (col_stable)
               if (marginal) then
                  buffer(pos + 1:pos + 3) = "0.5"
                  pos = pos + 3
               else
                  buffer(pos + 1:pos + 1) = merge("1", "0", stable)
                  pos = pos + 1
               end if
            case (col_stable_paper)
               buffer(pos + 1:pos + 1) = merge("1", "0", stable_paper)
               pos = pos + 1
            case (col_physical)
               buffer(pos + 1:pos + 1) = merge("1", "0", inside)
               pos = pos + 1
            case (col_status)
               p = pos
               call put_value(style_flag, real(statuses(j), wp), buffer, p)
               pos = p
            case (col_a)
               p = pos
               call put_value(columns%styles(col_a), a, buffer, p)
               pos = p
            case default
               ! no other column reaches a chart's verdict file today (omega is offered to
               ! points files only): the value `chart_values` gives
               v = chart_values(alpha, betas(j), floquet_verdict(traces(j), decays(j), tolerance), inside, statuses(j), &
                                amplitude=a, need=need_verdict)
               p = pos
               call put_value(columns%styles(ids(k)), v(ids(k)), buffer, p)
               pos = p
            end select
         end do
      end do
   end subroutine verdict_lines

   !> A 24-character field (a grid value's text) into buffer(pos + 1 : pos + 24), pos
   !> advanced: three 8-character pieces, which the compiler copies as words (the whole
   !> field went through memmove, a fifth of a verdict line's cost).
   pure subroutine put_text24(buffer, pos, text)
      character(len=*), intent(inout) :: buffer  !! the line being built
      integer, intent(inout) :: pos  !! last position written; advanced past the field
      character(len=24), intent(in) :: text  !! the field
      buffer(pos + 1:pos + 8) = text(1:8)
      buffer(pos + 9:pos + 16) = text(9:16)
      buffer(pos + 17:pos + 24) = text(17:24)
      pos = pos + 24
   end subroutine put_text24

   !> The values of a point where nothing could be computed: its own values in the columns
   !> that keep them (alpha, a, beta, omega, physical; status 2), the placeholders in the
   !> others.
   pure function failed_values(columns, alpha, beta, physical, amplitude, omega) result(v)
      type(chart_layout_t), intent(in) :: columns  !! the file's columns
      real(wp), intent(in) :: alpha, beta  !! the point
      logical, intent(in) :: physical      !! (α, β) inside the physical domain
      real(wp), intent(in), optional :: amplitude  !! a (m)
      real(wp), intent(in), optional :: omega      !! ω (rad/s)
      real(wp) :: v(n_chart_columns)
      integer :: k
      v = 0.0_wp
      if (present(amplitude)) v(col_a) = amplitude
      if (present(omega)) v(col_omega) = omega
      v(col_alpha) = alpha
      v(col_beta) = beta
      v(col_physical) = merge(1.0_wp, 0.0_wp, physical)
      v(col_status) = real(status_failed, wp)
      do k = 1, n_chart_columns
         if (.not. columns%table(k)%keep_on_failure) v(k) = columns%table(k)%placeholder
      end do
   end function failed_values

   !> One text line of the columns written of a point's values `v` (`chart_values`), each in
   !> its column's style; alpha and beta from `alpha_text`, `beta_text` when at hand (a
   !> chart formats each grid value once, not once per point). No allocation. With
   !> `length`, the characters after it are left as they were (not blanked).
   pure subroutine chart_line(columns, v, line, alpha_text, beta_text, length)
      type(chart_layout_t), intent(in) :: columns  !! the file's columns
      real(wp), intent(in) :: v(n_chart_columns)  !! every column's value
      character(len=chart_line_length), intent(inout) :: line  !! the line (blank-padded without `length`)
      character(len=24), intent(in), optional :: alpha_text  !! put_es(alpha, 17)
      character(len=24), intent(in), optional :: beta_text   !! put_es(beta, 17)
      integer, intent(out), optional :: length  !! characters written
      integer :: k, pos, id, digits
      logical :: have_alpha, have_beta
      have_alpha = present(alpha_text)
      have_beta = present(beta_text)
      pos = 0
      do k = 1, size(columns%ids)
         id = columns%ids(k)
         if (k > 1) then
            line(pos + 1:pos + 1) = " "
            pos = pos + 1
         end if
         digits = columns%digits(id)
         if (digits > 0) then
            if (id == col_alpha .and. have_alpha) then
               line(pos + 1:pos + 24) = alpha_text
               pos = pos + 24
            else if (id == col_beta .and. have_beta) then
               line(pos + 1:pos + 24) = beta_text
               pos = pos + 24
            else
               ! the numbers straight to put_es (put_value's dispatch by style, once per
               ! column of every line, cost a tenth of a full chart's text)
               call put_es(line, pos, v(id), digits)
            end if
         else if (v(id) == 0.0_wp) then
            ! the flags' usual values written here (through put_value they cost 3 % of a
            ! full chart)
            line(pos + 1:pos + 1) = "0"
            pos = pos + 1
         else if (v(id) == 1.0_wp) then
            line(pos + 1:pos + 1) = "1"
            pos = pos + 1
         else
            call put_value(columns%styles(id), v(id), line, pos)
         end if
      end do
      if (present(length)) then
         length = pos
      else
         line(pos + 1:) = ""
      end if
   end subroutine chart_line

   !> Header lines of a chart or points file: the common header, the method, one line per
   !> column written, the placeholders of failed rows.
   function chart_header(scene, physical, outside, columns, regions) result(lines)
      type(scene_t), intent(in) :: scene  !! a validated scene
      type(physical_scene_t), intent(in) :: physical  !! its `&physical` (the task's)
      logical, intent(in) :: outside  !! some point lies outside the physical domain
      type(chart_layout_t), intent(in) :: columns  !! the file's columns
      character(len=*), intent(in), optional :: regions(:)  !! lines on the regions of the chart's ranges
      character(len=:), allocatable :: lines(:)
      character(len=:), allocatable :: per_column(:), placeholder
      character(len=400) :: text(2*n_chart_columns + 3)
      character(len=:), allocatable :: accuracy
      integer :: k, n, id
      per_column = column_lines(plain_table(columns%table), columns%ids)
      n = 1
      text(1) = "method: "//method_description(scene)
      do k = 1, size(per_column)
         text(n + k) = per_column(k)
      end do
      n = n + size(per_column)
      do k = 1, size(columns%ids)
         accuracy = accuracy_line(scene, columns, columns%ids(k))
         if (len(accuracy) == 0) cycle
         n = n + 1
         text(n) = accuracy
      end do
      if (columns%need == need_nothing) then
         n = n + 1
         text(n) = "accuracy: no trace is computed (the columns written need none)"
      end if
      n = n + 1
      text(n) = "status 2 rows (placeholders, not values):"
      do k = 1, size(columns%ids)
         id = columns%ids(k)
         if (columns%table(id)%keep_on_failure) cycle
         placeholder = real_text(columns%table(id)%placeholder)
         text(n) = trim(text(n))//merge(" ", ",", index(text(n), "=") == 0)//" "//columns%table(id)%name//" = "// &
            placeholder
      end do
      if (outside .and. is_elastic_pendulum(scene%model)) then
         n = n + 1
         text(n) = "note: this file leaves the physical domain (rows with physical = 0)"
      end if
      if (present(regions)) then
         lines = stacked(common_header(scene, physical), [character(len=400) :: text(:n), regions])
      else
         lines = stacked(common_header(scene, physical), text(:n))
      end if
   end function chart_header

   !> Floquet data of one point; `error` only when the point failed.
   subroutine evaluate_point(scene, alpha, beta, f, error, status, epsilon, columns)
      type(scene_t), intent(in) :: scene  !! the scene (model, method, damping)
      real(wp), intent(in) :: alpha, beta  !! the point
      type(floquet_t), intent(out) :: f  !! its Floquet data
      type(error_t), allocatable, intent(out) :: error  !! why the point failed
      !> status_ok, status_roundoff (computed, but only to the round-off level) or status_failed
      integer, intent(out), optional :: status
      !> the point's damping (a chart over (a, ω): κπ/ω); default the scene's
      real(wp), intent(in), optional :: epsilon
      !> the columns written: only what they need is computed; default all of S
      type(chart_layout_t), intent(in), optional :: columns
      type(trace_t) :: tr(1)
      logical :: failed(1), inaccurate(1)
      real(wp) :: damping, dampings(1)
      integer :: need
      logical :: paper
      damping = scene%model%point_damping(alpha, scene%epsilon)
      if (present(epsilon)) damping = epsilon
      if (present(status)) status = status_ok
      need = need_trace
      paper = .false.
      if (present(columns)) then
         need = columns%need
         paper = columns%paper
      end if
      call monodromy_trace_batch(scene%model, hill_point_t(alpha, 0.0_wp, damping), [beta], scene%method, tr, &
                                 failed, error, inaccurate=inaccurate, need=need, paper=paper, dampings=dampings)
      if (failed(1)) then
         if (present(status)) status = status_failed
         return
      end if
      if (allocated(error)) deallocate (error)
      if (inaccurate(1) .and. present(status)) status = status_roundoff
      call set_from_trace(f, tr(1), dampings(1), scene%method%tolerance, scene%model%period(), .false.)
   end subroutine evaluate_point

   !> Count the failed points of a task and name the first: err_points_failed, after the
   !> file has been written. The first failure is computed again serially, so the message
   !> does not depend on thread timing.
   subroutine failed_points_error(scene, n_failed, n_total, first, error)
      type(scene_t), intent(in) :: scene  !! a validated scene
      integer(int64), intent(in) :: n_failed, n_total  !! failed points; all points
      real(wp), intent(in) :: first(2)  !! alpha, beta of the first failed point
      type(error_t), allocatable, intent(out) :: error  !! err_points_failed naming the count and the first point
      type(error_t), allocatable :: cause
      type(floquet_t) :: f
      if (n_failed == 0) return
      call evaluate_point(scene, first(1), first(2), f, cause)
      if (.not. allocated(cause)) call set_error(cause, err_input, "fails in parallel only")
      call set_error(error, err_points_failed, scene%source//": &scene: method: '"// &
         method_name(scene%method%kind)//"' failed at "//integer_text(n_failed)//" of "//integer_text(n_total)// &
         " point(s), written with status "//integer_text(status_failed)//" and placeholders to "//output_path(scene)// &
         "; first at alpha = "// &
         real_text(first(1))//", beta = "//real_text(first(2))//": "//cause%message)
   end subroutine failed_points_error

   !> The error of a failed point, naming the scene, the method and the point.
   subroutine point_error(scene, alpha, beta, cause, error)
      type(scene_t), intent(in) :: scene
      real(wp), intent(in) :: alpha, beta
      type(error_t), intent(in) :: cause
      type(error_t), allocatable, intent(out) :: error
      call set_error(error, cause%code, scene%source//": &scene: method: '"//method_name(scene%method%kind)// &
         "' fails at alpha = "//real_text(alpha)//", beta = "//real_text(beta)//": "//cause%message)
   end subroutine point_error

   !> A chart whose method cannot run at all (bad parameters) fails at its first point,
   !> before anything is written; a point where the computation fails is written with
   !> its status instead.
   subroutine check_method_runs(scene, alpha, beta, error)
      type(scene_t), intent(in) :: scene  !! a chart scene
      real(wp), intent(in) :: alpha, beta  !! its first point
      type(error_t), allocatable, intent(out) :: error  !! why the method cannot run; unallocated when it can
      type(error_t), allocatable :: cause
      type(floquet_t) :: f
      call evaluate_point(scene, alpha, beta, f, cause)
      if (allocated(cause)) then
         if (cause%code == err_invalid_parameter) call point_error(scene, alpha, beta, cause, error)
      end if
   end subroutine check_method_runs

   !> Say on stderr (even when quiet: it qualifies the results) how many points could only
   !> be computed to the round-off level of double precision, not to the tolerance.
   subroutine warn_inaccurate(scene, n, first)
      type(scene_t), intent(in) :: scene  !! a validated scene
      integer(int64), intent(in) :: n  !! number of round-off limited points
      real(wp), intent(in) :: first(2)  !! alpha, beta of the first such point
      if (n == 0) return
      write (error_unit, '(a)') "hillstab: warning: "//scene%source//": "//integer_text(n)// &
         " point(s) reached only the round-off level of double precision, not the tolerance "// &
         real_text(scene%method%tolerance)//" (first at alpha = "//real_text(first(1))//", beta = "// &
         real_text(first(2))//"); their S is the best available"
   end subroutine warn_inaccurate

   function method_description(scene) result(text)
      type(scene_t), intent(in) :: scene
      character(len=:), allocatable :: text
      text = method_name(scene%method%kind)
      if (method_uses_segments(scene%method%kind)) then
         text = text//", "//integer_text(scene%method%n_segments)//" pieces, sampling "// &
            sampling_name(scene%method%sampling)
      else if (method_is_exact(scene%method%kind)) then
         text = text//", tolerance "//real_text(scene%method%tolerance)
      end if
   end function method_description

   !> Header lines of a scene given in physical units: the spring, the conversions used.
   function physical_header(scene, physical) result(lines)
      type(scene_t), intent(in) :: scene
      type(physical_scene_t), intent(in) :: physical
      character(len=:), allocatable :: lines(:)
      character(len=400) :: text(1)
      if (size(physical%amplitudes) > 0) then
         text(1) = "each amplitude a of &physical is one point (points: a row; coefficient: a curve): alpha = "// &
            "a pi^2/rho"//pendulum_note(scene%model)
         lines = stacked(physical_summary(physical, scene%epsilon), text)
      else
         lines = physical_summary(physical, scene%epsilon)
      end if
   end function physical_header

   !> The bounce amplitude a (m) of a point of a scene with `&physical`: the k-th
   !> amplitude when the scene gives them, else a = α ρ/π² with ρ = g π²/(β ω²)
   !> (eq. (24)), that is α g/(β ω²); −1 where β ≤ 0 or g = 0 (no equilibrium length).
   pure real(wp) function point_amplitude(physical, k, alpha, beta) result(a)
      type(physical_scene_t), intent(in) :: physical  !! a scene's `&physical` (given)
      integer, intent(in) :: k  !! the point's index
      real(wp), intent(in) :: alpha, beta  !! the point
      if (size(physical%amplitudes) > 0) then
         a = physical%amplitudes(k)
      else if (beta > 0.0_wp .and. physical%pendulum%g > 0.0_wp) then
         a = alpha*physical%pendulum%g/(beta*physical%pendulum%omega**2)
      else
         a = -1.0_wp
      end if
   end function point_amplitude

   !> dτ/dt at a point of the scene, which turns a rate per unit τ into one per unit of its
   !> user's time (the column mu_per_s): ω/π of `&physical` (a row of a chart over
   !> amplitudes and frequencies has each point's own, `physical_row`), else the model's at
   !> the point (`tau_rate`: an equation's Ω/π), 0 when the scene has no time but τ.
   elemental real(wp) function tau_per_time(scene, physical, alpha, beta) result(rate)
      type(scene_t), intent(in) :: scene  !! the scene
      type(physical_scene_t), intent(in) :: physical  !! its `&physical` (the task's)
      real(wp), intent(in) :: alpha, beta  !! the point
      if (physical%given) then
         rate = physical%pendulum%omega/pi
      else
         rate = scene%model%tau_rate(alpha, beta)
      end if
   end function tau_per_time

   !> The model's period as the header writes it in a formula: 2, or P = 4.0's value.
   function period_text(scene) result(text)
      type(scene_t), intent(in) :: scene  !! the scene
      character(len=:), allocatable :: text
      if (scene%model%period() == 2.0_wp) then
         text = "2"
      else
         text = real_text(scene%model%period())
      end if
   end function period_text

   !> The stability threshold of a damped scene: 2 cosh(epsilon), 2 cosh(epsilon P/2) for a
   !> model of period P ≠ 2 (its value of x loses εP/2 of ln|λ| a period).
   function damped_threshold(scene) result(text)
      type(scene_t), intent(in) :: scene  !! the scene
      character(len=:), allocatable :: text
      if (scene%model%period() == 2.0_wp) then
         text = "2 cosh(epsilon)"
      else
         text = "2 cosh(epsilon P/2), P = "//real_text(scene%model%period())
      end if
   end function damped_threshold

   !> Header lines common to the pendulum tasks: version, source, the effective scene, the
   !> model, and the spring of `&physical` when the scene has it.
   function common_header(scene, physical) result(lines)
      type(scene_t), intent(in) :: scene  !! the scene
      type(physical_scene_t), intent(in) :: physical  !! its `&physical` (the task's)
      character(len=:), allocatable :: lines(:)
      character(len=:), allocatable :: model_text, common(:)
      model_text = model_description(scene%model)
      common = scene_header(scene, "hillstab "//version_string//": "//model_equation_text(scene%model), [model_text])
      if (physical%given) then
         lines = stacked(common, physical_header(scene, physical))
      else
         lines = common
      end if
   end function common_header

   !> The lines of a followed by those of b, at the longer of their lengths.
   pure function stacked(a, b) result(c)
      character(len=*), intent(in) :: a(:)  !! the first lines
      character(len=*), intent(in) :: b(:)  !! the lines after them
      character(len=:), allocatable :: c(:)
      allocate (character(len=max(len(a), len(b))) :: c(size(a) + size(b)))
      c(:size(a)) = a
      c(size(a) + 1:) = b
   end function stacked

end module hillstab_batch_tasks_chart_columns

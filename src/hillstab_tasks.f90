!> Task runners: scene → monodromy/Floquet → output file.
!>
!> - chart: the (α, β) grid row by row (one α a row); the β values of a row run in
!>   parallel (OpenMP, dynamic schedule: the cost varies strongly near α → π²),
!>   then the row is written in order and forgotten, so memory stays at one row;
!> - points: the same columns at the (α, β) points of a file, in file order;
!> - coefficient: Q(τ) and its segmented version for a list of α (the paper's Fig. 2).
!>
!> Each task computes only what its file holds. Errors come back in `error` with
!> the scene file, group and variable named; no output file is created or touched
!> unless the whole task succeeds.
!>
!>```fortran
!> type(error_t), allocatable :: error
!> call run_scene_file("data/scenes/default_exact.nml", quiet=.false., error=error)
!>```
module hillstab_tasks
   use hillstab_kinds, only: wp, int64, pi2, version_string
   use hillstab_error, only: error_t, set_error, err_input, err_io
   use hillstab_coefficient, only: hill_model_t, model_elastic, model_mathieu, hill_coefficient, &
      segment_coefficients, hill_period, in_physical_domain, sampling_name
   use hillstab_transfer, only: trace_t
   use hillstab_floquet, only: floquet_t, floquet_from_trace
   use hillstab_monodromy, only: monodromy_trace, method_name, method_segments
   use hillstab_scene, only: scene_t, read_scene, scene_namelist, task_chart, task_points, task_coefficient, &
      task_name, grid_value, real_text, integer_text
   use hillstab_output, only: output_file_t, open_output, commit_output, discard_output, write_header, &
      write_text, chart_columns, chart_line, chart_line_length, real_columns
   use, intrinsic :: iso_fortran_env, only: error_unit
   use, intrinsic :: iso_c_binding, only: c_int
   implicit none
   private
   public :: run_scene_file, run_scene, output_path

   !> Progress on stderr for runs longer than about a second.
   type :: progress_t
      logical :: enabled = .false.      !! not quiet
      logical :: shown = .false.        !! something has been printed
      logical :: terminal = .false.     !! stderr is a terminal: redraw one line
      integer(int64) :: total = 0       !! points to compute
      integer(int64) :: start = 0       !! clock at the start
      integer(int64) :: last = 0        !! clock at the last report
      integer(int64) :: ticks = 1       !! clock ticks per second
   end type progress_t

   interface
      function c_isatty(fd) bind(C, name="isatty") result(yes)
         import :: c_int
         integer(c_int), value :: fd
         integer(c_int) :: yes
      end function c_isatty
   end interface

contains

   !> Read the scene file `path` and run it.
   subroutine run_scene_file(path, quiet, error, written)
      character(len=*), intent(in) :: path  !! scene file (a previous output file also works)
      logical, intent(in) :: quiet          !! no progress on stderr
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable, intent(out), optional :: written  !! the file written
      type(scene_t) :: scene
      call read_scene(path, scene, error)
      if (allocated(error)) return
      call run_scene(scene, quiet, error)
      if (allocated(error)) return
      if (present(written)) written = output_path(scene)
   end subroutine run_scene_file

   !> Run a validated scene.
   subroutine run_scene(scene, quiet, error)
      type(scene_t), intent(in) :: scene
      logical, intent(in) :: quiet  !! no progress on stderr
      type(error_t), allocatable, intent(out) :: error
      select case (scene%task)
      case (task_chart)
         call run_chart(scene, quiet, error)
      case (task_points)
         call run_points(scene, quiet, error)
      case (task_coefficient)
         call run_coefficient(scene, error)
      case default
         call set_error(error, err_input, scene%source//": &scene: task: task '"//task_name(scene%task)// &
            "' is not available in this build")
      end select
   end subroutine run_scene

   !> `<output>_<task>.dat`.
   pure function output_path(scene) result(path)
      type(scene_t), intent(in) :: scene
      character(len=:), allocatable :: path
      path = scene%output//"_"//task_name(scene%task)//".dat"
   end function output_path

   !> Floquet data of one point.
   subroutine evaluate_point(scene, alpha, beta, f, error)
      type(scene_t), intent(in) :: scene
      real(wp), intent(in) :: alpha, beta
      type(floquet_t), intent(out) :: f
      type(error_t), allocatable, intent(out) :: error
      type(trace_t) :: tr
      call monodromy_trace(hill_model_t(scene%model, alpha, beta, scene%epsilon), scene%method, tr, error)
      if (.not. allocated(error)) f = floquet_from_trace(tr, scene%epsilon)
   end subroutine evaluate_point

   !> The error of a failed point, naming the scene, the method and the point.
   subroutine point_error(scene, alpha, beta, cause, error)
      type(scene_t), intent(in) :: scene
      real(wp), intent(in) :: alpha, beta
      type(error_t), intent(in) :: cause
      type(error_t), allocatable, intent(out) :: error
      call set_error(error, cause%code, scene%source//": &scene: method: '"//method_name(scene%method%kind)// &
         "' fails at alpha = "//real_text(alpha)//", beta = "//real_text(beta)//": "//cause%message)
   end subroutine point_error

   !> Open the output file, reporting failure against `&scene output`.
   subroutine open_scene_output(scene, file, error)
      type(scene_t), intent(in) :: scene
      type(output_file_t), intent(out) :: file
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: cause
      call open_output(file, output_path(scene), cause)
      if (allocated(cause)) call set_error(error, err_io, scene%source//": &scene: output: "//cause%message)
   end subroutine open_scene_output

   !> Header lines common to every task: version, source, the effective scene, the model.
   function common_header(scene) result(lines)
      type(scene_t), intent(in) :: scene
      character(len=:), allocatable :: lines(:)
      character(len=:), allocatable :: groups(:), model_text
      groups = scene_namelist(scene)
      if (scene%model == model_elastic) then
         model_text = "model: elastic, Q(tau) = (beta - alpha cos(pi tau))/(1 - (alpha/pi^2) cos(pi tau)), eq. (25)"
      else
         model_text = "model: mathieu, q(tau) = beta - alpha cos(pi tau), eq. (A1), alpha playing nu"
      end if
      lines = stacked(["hillstab "//version_string//": x'' + Q(tau) x = 0, period 2 in tau"], &
                      stacked(["scene file: "//scene%source//" (the two namelist lines below repeat this run)"], &
                              stacked(groups, [model_text])))
   end function common_header

   !> Header lines describing the chart/points columns.
   function chart_header(scene, outside) result(lines)
      type(scene_t), intent(in) :: scene
      logical, intent(in) :: outside  !! some point lies outside the physical domain
      character(len=:), allocatable :: lines(:)
      character(len=200) :: extra(9)
      integer :: n
      n = 0
      n = n + 1; extra(n) = "method: "//method_description(scene)
      n = n + 1; extra(n) = "S: trace of the one-period monodromy (with epsilon > 0: S1 of the chi equation (47))"
      n = n + 1; extra(n) = "|S| > 1e300 is written as +-1e300 with overflow = 1; log10_abs_S stays exact"
      if (scene%epsilon > 0.0_wp) then
         n = n + 1; extra(n) = "stable: 1 when |S1| < 2 cosh(epsilon) (all multipliers of x inside the unit circle)"
         n = n + 1; extra(n) = "stable_paper: 1 when |S1| <= 2, the sufficient criterion of the paper"
      else
         n = n + 1; extra(n) = "stable: 1 when |S| < 2"
      end if
      n = n + 1; extra(n) = "lambda_max: largest |multiplier| of x per period; mu: Floquet exponent ln(lambda_max)/2"
      n = n + 1; extra(n) = "physical: 1 inside the physical domain 0 <= alpha < pi^2, 0 < beta < pi^2"
      if (outside) then
         n = n + 1; extra(n) = "note: this file leaves the physical domain (rows with physical = 0)"
      end if
      lines = stacked(common_header(scene), extra(:n))
   end function chart_header

   function method_description(scene) result(text)
      type(scene_t), intent(in) :: scene
      character(len=:), allocatable :: text
      text = method_name(scene%method%kind)
      if (scene%method%kind == method_segments) then
         text = text//", "//integer_text(scene%method%n_segments)//" pieces, sampling "// &
            sampling_name(scene%method%sampling)
      else if (method_name(scene%method%kind) /= "formula") then
         text = text//", tolerance "//real_text(scene%method%tolerance)
      end if
   end function method_description

   !> The lines of a followed by those of b, at the longer of their lengths.
   pure function stacked(a, b) result(c)
      character(len=*), intent(in) :: a(:), b(:)
      character(len=:), allocatable :: c(:)
      allocate (character(len=max(len(a), len(b))) :: c(size(a) + size(b)))
      c(:size(a)) = a
      c(size(a) + 1:) = b
   end function stacked

   !> The chart task.
   subroutine run_chart(scene, quiet, error)
      type(scene_t), intent(in) :: scene
      logical, intent(in) :: quiet
      type(error_t), allocatable, intent(out) :: error
      type(output_file_t) :: file
      type(progress_t) :: progress
      type(floquet_t) :: f
      type(error_t), allocatable :: cause
      character(len=chart_line_length), allocatable :: lines(:)
      logical, allocatable :: failed(:)
      logical :: damped, outside
      real(wp) :: alpha, beta
      integer :: i, j, n_alpha, n_beta

      n_alpha = scene%chart%n_alpha
      n_beta = scene%chart%n_beta
      damped = scene%epsilon > 0.0_wp
      ! an unwritable output path fails before any computing
      call open_scene_output(scene, file, error)
      if (allocated(error)) return
      ! a method that cannot run fails at the first point
      alpha = scene%chart%alpha_min
      beta = scene%chart%beta_min
      call evaluate_point(scene, alpha, beta, f, cause)
      if (allocated(cause)) then
         call point_error(scene, alpha, beta, cause, error)
         call discard_output(file)
         return
      end if
      outside = .not. (in_physical_domain(scene%chart%alpha_min, scene%chart%beta_min) .and. &
                       in_physical_domain(scene%chart%alpha_max, scene%chart%beta_max))
      call write_header(file, chart_header(scene, outside), chart_columns(damped), error)
      if (allocated(error)) then
         call discard_output(file)
         return
      end if

      allocate (lines(n_beta), failed(n_beta))
      call progress_begin(progress, int(n_alpha, int64)*n_beta, quiet)
      do i = 1, n_alpha
         alpha = grid_value(scene%chart%alpha_min, scene%chart%alpha_max, n_alpha, i)
         failed = .false.
         !$omp parallel do schedule(dynamic) default(shared) private(j, beta, f, cause)
         do j = 1, n_beta
            beta = grid_value(scene%chart%beta_min, scene%chart%beta_max, n_beta, j)
            call evaluate_point(scene, alpha, beta, f, cause)
            if (allocated(cause)) then
               failed(j) = .true.
            else
               lines(j) = chart_line(alpha, beta, f, damped, in_physical_domain(alpha, beta))
            end if
         end do
         !$omp end parallel do
         if (any(failed)) then
            ! repeat the first failure serially, so the message does not depend on thread timing
            j = findloc(failed, .true., dim=1)
            beta = grid_value(scene%chart%beta_min, scene%chart%beta_max, n_beta, j)
            call evaluate_point(scene, alpha, beta, f, cause)
            if (.not. allocated(cause)) call set_error(cause, err_input, "fails in parallel only")
            call point_error(scene, alpha, beta, cause, error)
            exit
         end if
         ! blocks of constant alpha, separated by one blank line (gnuplot pm3d/image)
         if (i > 1) call write_text(file, "", error)
         do j = 1, n_beta
            if (allocated(error)) exit
            call write_text(file, trim(lines(j)), error)
         end do
         if (allocated(error)) exit
         call progress_update(progress, int(i, int64)*n_beta)
      end do
      call progress_end(progress)
      if (allocated(error)) then
         call discard_output(file)
         return
      end if
      call commit_output(file, error)
   end subroutine run_chart

   !> The points task.
   subroutine run_points(scene, quiet, error)
      type(scene_t), intent(in) :: scene
      logical, intent(in) :: quiet
      type(error_t), allocatable, intent(out) :: error
      type(output_file_t) :: file
      type(progress_t) :: progress
      type(floquet_t) :: f
      type(error_t), allocatable :: cause
      character(len=chart_line_length), allocatable :: lines(:)
      logical, allocatable :: failed(:)
      logical :: damped
      integer :: k, n

      n = size(scene%points, 2)
      damped = scene%epsilon > 0.0_wp
      call open_scene_output(scene, file, error)
      if (allocated(error)) return
      allocate (lines(n), failed(n))
      failed = .false.
      call progress_begin(progress, int(n, int64), quiet)
      !$omp parallel do schedule(dynamic) default(shared) private(k, f, cause)
      do k = 1, n
         call evaluate_point(scene, scene%points(1, k), scene%points(2, k), f, cause)
         if (allocated(cause)) then
            failed(k) = .true.
         else
            lines(k) = chart_line(scene%points(1, k), scene%points(2, k), f, damped, &
                                  in_physical_domain(scene%points(1, k), scene%points(2, k)))
         end if
      end do
      !$omp end parallel do
      call progress_update(progress, int(n, int64))
      call progress_end(progress)
      if (any(failed)) then
         k = findloc(failed, .true., dim=1)
         call evaluate_point(scene, scene%points(1, k), scene%points(2, k), f, cause)
         if (.not. allocated(cause)) call set_error(cause, err_input, "fails in parallel only")
         call point_error(scene, scene%points(1, k), scene%points(2, k), cause, error)
         call discard_output(file)
         return
      end if
      call write_header(file, chart_header(scene, .not. all(in_physical_domain(scene%points(1, :), &
         scene%points(2, :)))), chart_columns(damped), error)
      do k = 1, n
         if (allocated(error)) exit
         call write_text(file, trim(lines(k)), error)
      end do
      if (allocated(error)) then
         call discard_output(file)
         return
      end if
      call commit_output(file, error)
   end subroutine run_points

   !> The coefficient task: columns tau, then for each α: Q(τ) and its N-piece
   !> segmented value (n_segments and sampling of &scene).
   subroutine run_coefficient(scene, error)
      type(scene_t), intent(in) :: scene
      type(error_t), allocatable, intent(out) :: error
      type(output_file_t) :: file
      type(hill_model_t) :: model
      real(wp), allocatable :: pieces(:, :), row(:)
      character(len=:), allocatable :: columns, lines(:), q_line, segments_line, columns_line
      real(wp) :: tau, h
      integer :: i, k, n_alpha, n_pieces, piece

      n_alpha = size(scene%coefficient%alphas)
      n_pieces = scene%method%n_segments
      h = hill_period/n_pieces
      allocate (pieces(n_pieces, n_alpha), row(1 + 2*n_alpha))
      columns = "tau"
      do k = 1, n_alpha
         model = hill_model_t(scene%model, scene%coefficient%alphas(k), scene%coefficient%beta, scene%epsilon)
         call segment_coefficients(model, n_pieces, scene%method%sampling, pieces(:, k))
         columns = columns//" Q("//real_text(scene%coefficient%alphas(k))//") Qseg("// &
            real_text(scene%coefficient%alphas(k))//")"
      end do
      q_line = "Q: the coefficient at beta = "//real_text(scene%coefficient%beta)// &
               " (minus epsilon^2/4 when epsilon > 0: the chi equation (47))"
      segments_line = "Qseg: Q replaced by "//integer_text(n_pieces)//" constant pieces on [0, 2), sampling "// &
                      sampling_name(scene%method%sampling)//" (2 pieces, endpoint: eq. (28) of the paper)"
      columns_line = "Q(a), Qseg(a): the two columns of alpha = a"
      lines = stacked(common_header(scene), stacked([q_line], stacked([segments_line], [columns_line])))

      call open_scene_output(scene, file, error)
      if (allocated(error)) return
      call write_header(file, lines, columns, error)
      do i = 1, scene%coefficient%n_tau
         if (allocated(error)) exit
         tau = grid_value(scene%coefficient%tau_min, scene%coefficient%tau_max, scene%coefficient%n_tau, i)
         piece = min(int(modulo(tau, hill_period)/h) + 1, n_pieces)
         row(1) = tau
         do k = 1, n_alpha
            model = hill_model_t(scene%model, scene%coefficient%alphas(k), scene%coefficient%beta, scene%epsilon)
            row(2*k) = hill_coefficient(model, tau)
            row(2*k + 1) = pieces(piece, k)
         end do
         call write_text(file, real_columns(row), error)
      end do
      if (allocated(error)) then
         call discard_output(file)
         return
      end if
      call commit_output(file, error)
   end subroutine run_coefficient

   subroutine progress_begin(progress, total, quiet)
      type(progress_t), intent(out) :: progress
      integer(int64), intent(in) :: total
      logical, intent(in) :: quiet
      progress%enabled = .not. quiet
      progress%total = total
      call system_clock(progress%start, progress%ticks)
      progress%last = progress%start
      if (progress%enabled) progress%terminal = c_isatty(2_c_int) == 1
   end subroutine progress_begin

   !> Report `done` of `total` points: percentage, rate and time left, once the run
   !> has taken a second; redrawn in place on a terminal, a line every 5 s otherwise.
   subroutine progress_update(progress, done)
      type(progress_t), intent(inout) :: progress
      integer(int64), intent(in) :: done
      integer(int64) :: now
      real(wp) :: elapsed, since_last, rate, left, interval
      character(len=160) :: text
      character(len=12) :: left_text
      if (.not. progress%enabled) return
      call system_clock(now)
      elapsed = real(now - progress%start, wp)/progress%ticks
      since_last = real(now - progress%last, wp)/progress%ticks
      if (elapsed < 1.0_wp) return
      interval = merge(0.25_wp, 5.0_wp, progress%terminal)
      if (progress%shown .and. since_last < interval .and. done < progress%total) return
      rate = real(done, wp)/elapsed
      left = real(progress%total - done, wp)/max(rate, tiny(1.0_wp))
      write (left_text, '(f12.1)') left
      write (text, '(a,f5.1,a,i0,a,i0,a,i0,a)') "hillstab: ", 100.0_wp*done/progress%total, "% (", &
         done, " of ", progress%total, " points, ", nint(rate, int64), " points/s, "
      text = trim(text)//" "//trim(adjustl(left_text))//" s left)"
      if (progress%terminal) then
         write (error_unit, '(a)', advance="no") achar(13)//trim(text)//"   "
      else
         write (error_unit, '(a)') trim(text)
      end if
      flush (error_unit)
      progress%shown = .true.
      progress%last = now
   end subroutine progress_update

   subroutine progress_end(progress)
      type(progress_t), intent(in) :: progress
      if (progress%shown .and. progress%terminal) write (error_unit, '(a)') ""
   end subroutine progress_end
end module hillstab_tasks

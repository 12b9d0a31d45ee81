!> Tests of the one column table of chart and points files (hillstab_batch_tasks_floquet_columns):
!> the places of one equation's columns follow their keys; the axes are named after a model's
!> or a system's parameters and are chosen by name or as alpha and beta in both kinds of file;
!> `&scene columns` is refused alike, naming the file, the group and the variable; and the
!> values both kinds write of the same one-equation result agree where their meanings do.
module test_floquet_columns
   use hillstab_core_kinds, only: wp, pi
   use hillstab_core_error, only: error_t, err_input
   use hillstab_core_status, only: status_ok
   use hillstab_hill_transfer, only: trace_t
   use hillstab_hill_system, only: system_form_t
   use hillstab_hill_floquet, only: floquet_t, floquet_from_trace, verdict_stable, verdict_unstable
   use hillstab_hill_system_floquet, only: complete_from_trace
   use hillstab_integrate_system, only: system_monodromy_t
   use hillstab_batch_tasks_floquet_columns
   use hillstab_testing
   use hillstab_test_files, only: run_text_scene
   use hillstab_test_scratch, only: read_lines, delete_file
   implicit none
   private
   public :: collect_floquet_columns

contains

   function collect_floquet_columns() result(suite)
      type(testsuite_t) :: suite
      suite = new_testsuite("floquet_columns", [ &
         new_unittest("places_follow_keys", places_follow_keys), &
         new_unittest("axes_named_and_chosen", axes_named_and_chosen), &
         new_unittest("columns_refused_alike", columns_refused_alike), &
         new_unittest("one_result_both_files", one_result_both_files), &
         new_unittest("kind_and_argument_of_one_equation", kind_and_argument_of_one_equation)])
   end function collect_floquet_columns

   !> Each `col_*` index is its key's place in `chart_keys`, every key of both kinds of file has
   !> a record whose name is the key (the axes unnamed), and a system's places by name
   !> (`system_layout`) are those of `system_column_names`.
   subroutine places_follow_keys(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(column_context_t) :: equation, system
      type(chart_column_t) :: column
      character(len=14), allocatable :: names(:)
      type(system_layout_t) :: layout
      integer :: k
      integer, parameter :: places(17) = [col_alpha, col_a, col_beta, col_omega, col_s, col_stable, col_lambda_max, &
                                          col_mu, col_log10_abs_s, col_overflow, col_physical, col_stable_paper, &
                                          col_mu_per_s, col_error_estimate, col_status, col_kind, col_argument]
      character(len=14), parameter :: keys(17) = [character(len=14) :: "alpha", "a", "beta", "omega", "S", &
         "stable", "lambda_max", "mu", "log10_abs_S", "overflow", "physical", "stable_paper", "mu_per_s", &
         "error_estimate", "status", "kind", "argument"]
      call check(ctx, n_chart_columns == size(keys), "17 columns of one equation")
      do k = 1, size(keys)
         call check(ctx, chart_keys(places(k)) == keys(k), "col_"//trim(keys(k))//" is the place of its key")
      end do
      call check(ctx, all([(count(places == k) == 1, k=1, n_chart_columns)]), "every place once")
      ! a failed point's row as the guide's output page states it (what the C API gives too)
      call check(ctx, all(chart_placeholders() == [0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, -1.0_wp, -1.0_wp, 0.0_wp, &
                                                   -999.0_wp, -1.0_wp, 0.0_wp, -1.0_wp, 0.0_wp, -1.0_wp, 0.0_wp, &
                                                   -1.0_wp, -1.0_wp]), "the placeholders of a failed point")
      equation = context_of(.false., "alpha", "beta")
      equation%pendulum = .true.
      do k = 1, n_chart_columns
         column = floquet_column(trim(chart_keys(k)), equation)
         call check(ctx, column%name == trim(chart_keys(k)) .and. column%key == trim(chart_keys(k)) .and. &
                    len(column%meaning) > 10, "record of "//trim(chart_keys(k)))
      end do
      system = context_of(.true., "alpha", "beta")
      system%n = 3
      names = system_column_names(3)
      layout = system_layout(3)
      call check(ctx, size(names) == n_fixed + 3 .and. layout%columns == size(names), "n_fixed + 3 columns")
      do k = 1, size(names)
         column = floquet_column(trim(names(k)), system)
         call check(ctx, column%name == trim(names(k)) .and. len(column%meaning) > 10, "record of "//trim(names(k)))
      end do
      call check(ctx, names(layout%stable) == "stable" .and. names(layout%kind) == "kind" .and. &
                 names(layout%mu_1 + 2) == "mu_3" .and. names(layout%steps) == "steps" .and. &
                 names(layout%status) == "status", "the system's places by name")
   end subroutine places_follow_keys

   !> The axes named after the parameters w, A (one equation) and Om, P1 (a system): each file's
   !> meaning of them, and `&scene columns` choosing them by name or as alpha and beta, in any case.
   subroutine axes_named_and_chosen(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(chart_column_t), allocatable :: table(:)
      character(len=14), allocatable :: names(:)
      integer, allocatable :: ids(:)
      character(len=:), allocatable :: bad, known
      integer :: k
      ! one equation
      allocate (table(n_chart_columns))
      do k = 1, n_chart_columns
         table(k) = floquet_column(trim(chart_keys(k)), context_of(.false., "w", "A"))
      end do
      call check(ctx, table(col_alpha)%name == "w" .and. table(col_beta)%name == "A", "one equation: w and A")
      call check(ctx, table(col_alpha)%meaning == "the parameter w of the equation, the chart's alpha axis (rows)", &
                 "one equation: the meaning of w")
      call check(ctx, table(col_beta)%meaning == "the parameter A of the equation, the chart's beta axis", &
                 "one equation: the meaning of A")
      call choose_columns(table, [col_alpha, col_beta, col_s, col_stable], "alpha, a STABLE", ids, bad, known)
      call check(ctx, len(bad) == 0 .and. size(ids) == 3, "one equation: alpha, a, STABLE found")
      if (size(ids) == 3) call check(ctx, all(ids == [col_alpha, col_beta, col_stable]), "one equation: in order")
      call check(ctx, known == "w A S stable", "one equation: the names available")
      ! a system
      names = system_column_names(2)
      deallocate (table)
      allocate (table(size(names)))
      do k = 1, size(names)
         table(k) = floquet_column(trim(names(k)), context_of(.true., "Om", "P1"))
      end do
      call check(ctx, table(1)%name == "Om" .and. table(2)%name == "P1", "system: Om and P1")
      call check(ctx, table(1)%meaning == "the parameter Om, the chart's alpha axis" .and. &
                 table(2)%meaning == "the parameter P1, the chart's beta axis", "system: their meanings")
      call choose_columns(table, [(k, k=1, size(table))], "beta om kind mu_2", ids, bad, known)
      call check(ctx, len(bad) == 0 .and. size(ids) == 4, "system: beta, om, kind, mu_2 found")
      if (size(ids) == 4) call check(ctx, all(ids == [2, 1, 7, 12]), "system: in order")
      ! a system whose axes are unnamed keeps alpha, beta and the drive's meaning
      table(1) = floquet_column("alpha", context_of(.true., "alpha", "beta"))
      call check(ctx, table(1)%name == "alpha" .and. table(1)%meaning == "alpha, the drive", "system: unnamed alpha")
   end subroutine axes_named_and_chosen

   !> A name a file has not, a column named twice and no name at all are refused by
   !> `scene_columns` with err_input naming the file, &scene and columns, for both kinds; a
   !> column one equation's file does not offer (physical of a model that is not the pendulum)
   !> is not taken.
   subroutine columns_refused_alike(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(chart_column_t) :: equation(n_chart_columns)
      type(chart_column_t), allocatable :: system(:)
      character(len=14), allocatable :: names(:)
      integer, allocatable :: ids(:), offered(:)
      type(error_t), allocatable :: error
      integer :: k
      do k = 1, n_chart_columns
         equation(k) = floquet_column(trim(chart_keys(k)), context_of(.false., "alpha", "beta"))
      end do
      allocate (offered(0))
      do k = 1, n_chart_columns
         if (equation(k)%offered) offered = [offered, k]
      end do
      call check(ctx, .not. any(offered == col_physical) .and. any(offered == col_s), "physical not offered")
      names = system_column_names(1)
      allocate (system(size(names)))
      do k = 1, size(names)
         system(k) = floquet_column(trim(names(k)), context_of(.true., "alpha", "beta"))
      end do
      call scene_columns(equation, offered, "alpha physical", "one.nml", ids, error)
      call expect_refusal("one.nml: &scene: columns: 'physical' is not a column of this file or is named twice")
      call scene_columns(system, [(k, k=1, size(system))], "alpha S", "sys.nml", ids, error)
      call expect_refusal("sys.nml: &scene: columns: 'S' is not a column of this file or is named twice")
      call scene_columns(system, [(k, k=1, size(system))], "mu mu", "sys.nml", ids, error)
      call expect_refusal("sys.nml: &scene: columns: 'mu' is not a column of this file or is named twice")
      call scene_columns(equation, offered, " , ", "one.nml", ids, error)
      call expect_refusal("one.nml: &scene: columns: no column named")
      call scene_columns(system, [(k, k=1, size(system))], "", "sys.nml", ids, error)
      call check(ctx, .not. allocated(error) .and. size(ids) == size(system), "blank: every column")
   contains
      subroutine expect_refusal(start)
         character(len=*), intent(in) :: start
         call check(ctx, allocated(error), start)
         if (.not. allocated(error)) return
         call check(ctx, error%code == err_input .and. index(error%message, start) == 1, error%message)
      end subroutine expect_refusal
   end subroutine columns_refused_alike

   !> One equation's result (`floquet_from_trace`, completed for a system of one equation) written
   !> into both kinds of file: the exponent, the largest multiplier and the verdict agree where
   !> the meanings do (a system's stable 1, 0 is one equation's; its trace is e^{-εP/2} S), for a
   !> stable, an unstable and a damped point.
   subroutine one_result_both_files(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(floquet_t) :: f
      type(system_form_t) :: form
      type(system_monodromy_t) :: r
      type(system_layout_t) :: layout
      real(wp) :: scalar(n_chart_columns), system(n_fixed + 1)
      real(wp), parameter :: traces(3) = [1.2_wp, -7.5_wp, 1.2_wp], eps(3) = [0.0_wp, 0.0_wp, 0.2_wp]
      integer :: k
      form%period = 2.0_wp
      layout = system_layout(1)
      r%status = status_ok
      do k = 1, 3
         f = floquet_from_trace(trace_t(value=traces(k), log_abs=log(abs(traces(k))), error_estimate=1.0e-12_wp), &
                                eps(k), 1.0e-10_wp, 2.0_wp)
         scalar = chart_values(0.5_wp, 3.0_wp, f, .true., status_ok)
         call complete_from_trace(f, form)
         system = system_point_values(layout, 0.5_wp, 3.0_wp, f, r, .false.)
         call check(ctx, system(layout%mu), scalar(col_mu), rel=1.0e-15_wp, abs=1.0e-300_wp, message="mu")
         call check(ctx, system(layout%lambda_max), scalar(col_lambda_max), rel=1.0e-15_wp, message="lambda_max")
         call check(ctx, system(layout%mu_1), scalar(col_mu), rel=1.0e-15_wp, abs=1.0e-300_wp, message="mu_1")
         call check(ctx, system(layout%stable), scalar(col_stable), abs=0.0_wp, message="stable")
         call check(ctx, system(layout%trace), exp(-eps(k))*scalar(col_s), rel=1.0e-15_wp, message="trace")
      end do
      call check(ctx, f%verdict == verdict_stable .and. system(layout%kind) == 4.0_wp, "the damped point: kind 4")
      f = floquet_from_trace(trace_t(value=-7.5_wp, log_abs=log(7.5_wp)), 0.0_wp)
      call check(ctx, f%verdict == verdict_unstable, "S = -7.5 unstable")
   end subroutine one_result_both_files

   !> One equation's files write the kind and the argument of the largest multiplier when
   !> `&scene columns` names them (not by default: the default file keeps its columns). Mathieu's
   !> equation at α = 0 is x'' + β x = 0, S = 2 cos(2√β): where |S| < 2 the argument is
   !> arccos(cos 2√β)/π and the kind 0; at β < 0 the kind is 1 (S > 2) and the argument 0; in the
   !> first tongue (α = 2, β = 10/3, S < −2) the kind is 2 and the argument 1. Every point's kind
   !> and argument agree with the sign and size of its S.
   subroutine kind_and_argument_of_one_equation(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(error_t), allocatable :: error
      character(len=:), allocatable :: written
      character(len=1024), allocatable :: lines(:)
      real(wp) :: v(5), expected
      integer :: k, n_rows, n_closed, n_minus, n_plus
      call run_text_scene("kind_argument", [character(len=200) :: &
         "&scene task='chart', model='mathieu', tolerance=1e-12, columns='alpha beta kind argument S' /", &
         "&chart alpha_min=0, alpha_max=2, n_alpha=2, beta_min=-1, beta_max=12, n_beta=40 /"], error, written)
      call check(ctx, .not. allocated(error), "the chart runs")
      if (allocated(error)) then
         call check(ctx, .false., error%message)
         return
      end if
      lines = read_lines(written)
      n_rows = 0
      n_closed = 0
      n_minus = 0
      n_plus = 0
      do k = 1, size(lines)
         if (index(lines(k), "# columns:") == 1) call check(ctx, trim(lines(k)) == "# columns: alpha beta kind argument S", &
                                                             "the columns named")
         if (lines(k)(1:1) == "#" .or. len_trim(lines(k)) == 0) cycle
         read (lines(k), *) v
         n_rows = n_rows + 1
         if (abs(v(5)) < 2.0_wp) then
            call check(ctx, nint(v(3)) == 0 .and. v(4) > 0.0_wp .and. v(4) < 1.0_wp, "stable: kind 0, argument in (0, 1)")
            call check(ctx, v(4), acos(0.5_wp*v(5))/pi, abs=1.0e-15_wp, message="argument = arccos(S/2)/pi")
         else if (abs(abs(v(5)) - 2.0_wp) < 1.0e-9_wp) then
            ! |S| = 2 within the error bound (beta = 0 at alpha = 0): undecided
            call check(ctx, nint(v(3)) == 5, "|S| = 2: kind 5, undecided")
         else
            call check(ctx, nint(v(3)) == merge(1, 2, v(5) > 0.0_wp), "unstable: kind from the sign of S")
            call check(ctx, v(4) == merge(0.0_wp, 1.0_wp, v(5) > 0.0_wp), "unstable: argument 0 or 1")
            if (v(5) < 0.0_wp) n_minus = n_minus + 1
            if (v(5) > 0.0_wp) n_plus = n_plus + 1
         end if
         if (v(1) == 0.0_wp .and. v(2) > 0.0_wp) then
            expected = acos(cos(2.0_wp*sqrt(v(2))))/pi
            if (abs(cos(2.0_wp*sqrt(v(2)))) < 0.999_wp) then
               call check(ctx, v(4), expected, abs=1.0e-9_wp, message="alpha = 0: arccos(cos 2 sqrt(beta))/pi")
               n_closed = n_closed + 1
            end if
         end if
      end do
      call check(ctx, n_rows == 80, "80 points")
      call check(ctx, n_closed >= 30 .and. n_minus >= 1 .and. n_plus >= 2, "the closed form, -1 and +1 reached")
      call delete_file(written)
      ! the default file keeps its columns
      call run_text_scene("kind_argument_default", [character(len=200) :: &
         "&scene task='chart', model='mathieu', tolerance=1e-12 /", &
         "&chart alpha_min=0, alpha_max=2, n_alpha=2, beta_min=-1, beta_max=12, n_beta=3 /"], error, written)
      call check(ctx, .not. allocated(error), "the default chart runs")
      if (allocated(error)) return
      lines = read_lines(written)
      do k = 1, size(lines)
         if (index(lines(k), "# columns:") == 1) &
            call check(ctx, index(lines(k), "kind") == 0 .and. index(lines(k), "argument") == 0, &
                       "kind and argument only on request: "//trim(lines(k)))
      end do
      call delete_file(written)
   end subroutine kind_and_argument_of_one_equation

   !> A context of one equation or a system with the axes' names.
   function context_of(system, alpha_name, beta_name) result(context)
      logical, intent(in) :: system
      character(len=*), intent(in) :: alpha_name, beta_name
      type(column_context_t) :: context
      context%system = system
      context%alpha_name = alpha_name
      context%beta_name = beta_name
      context%summary = "the model"
      context%threshold = "2 cosh(epsilon)"
      context%period = "2"
   end function context_of
end module test_floquet_columns

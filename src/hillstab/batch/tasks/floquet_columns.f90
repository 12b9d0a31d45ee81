!> The columns of chart and points files, of one equation and of systems alike, in one
!> table keyed by name: each column's record (`floquet_column`: its name as files write it,
!> the axes' after the axes, unit, meaning, text style, placeholder, what it needs computed
!> and when it is offered, the meaning given by what the file analyses, one equation's trace
!> or a system's monodromy Φ, `column_context_t`), the columns of each kind of file in order
!> (`chart_keys`; `system_column_names`), the value of each at a point from the one Floquet
!> result `floquet_t` (`chart_values`; `system_point_values`), and the one reader of
!> `&scene columns` for both (`scene_columns`).
!>
!> A new column is added here and nowhere else: its key in the file's list, its record and
!> its value. The headers, `&scene columns`, the text and binary rows and the units of the
!> MPI program follow from the table.
!>
!>```fortran
!> type(chart_column_t) :: column
!> column = floquet_column("mu", column_context_t(system=.true., n=2))
!> print '(a)', column%meaning
!>```
module hillstab_batch_tasks_floquet_columns
   use hillstab_core_kinds, only: wp, pi
   use hillstab_core_error, only: error_t
   use hillstab_core_status, only: status_failed
   use hillstab_hill_floquet, only: floquet_t, largest_multiplier_modulus
   use hillstab_integrate_monodromy, only: need_nothing, need_verdict, need_growth, need_trace
   use hillstab_integrate_system, only: system_monodromy_t
   use hillstab_batch_scene_file, only: fail
   use hillstab_batch_output_columns, only: column_t, style_e17, style_e11, style_e7, style_e4, style_flag, &
      style_integer, columns_text, failed_row, find_columns
   implicit none
   private
   public :: chart_column_t, column_context_t, floquet_column, choose_columns, scene_columns, chart_keys
   public :: n_chart_columns, chart_values, chart_placeholders, clamp_magnitude, log10_floor
   public :: col_alpha, col_a, col_beta, col_omega, col_s, col_stable, col_lambda_max, col_mu, col_log10_abs_s, &
      col_overflow, col_physical, col_stable_paper, col_mu_per_s, col_error_estimate, col_status, col_kind, col_argument
   public :: n_fixed, system_layout_t, system_layout, system_column_names, status_column, system_point_values, &
      plain_table, system_column_table
   public :: accuracy_none, accuracy_trace, accuracy_verdict, accuracy_growth, accuracy_estimate, accuracy_argument

   !> The header's `# accuracy of` statement for a column of one equation's files: none (the
   !> column needs nothing computed), S to the tolerance, a verdict, the growth (λ, μ), the
   !> method's own error estimate, the argument of the largest multiplier.
   integer, parameter :: accuracy_none = 0, accuracy_trace = 1, accuracy_verdict = 2, accuracy_growth = 3, &
      accuracy_estimate = 4, accuracy_argument = 5

   !> The columns of one equation's chart and points files, by key in file order (the place of
   !> each is its `col_*` index of hillstab_batch_tasks_chart_columns).
   character(len=14), parameter :: chart_keys(17) = [character(len=14) :: "alpha", "a", "beta", "omega", "S", &
      "stable", "lambda_max", "mu", "log10_abs_S", "overflow", "physical", "stable_paper", "mu_per_s", &
      "error_estimate", "status", "kind", "argument"]

   !> One column of chart and points files: what the `# columns:` line, the header, the rows
   !> of failed points (`placeholder`, `keep_on_failure`), `&scene columns`, the text of a
   !> row and the computation know of it. Made by `floquet_column`.
   type, extends(column_t) :: chart_column_t
      !> its key in the table (`floquet_column`): the name, but "alpha" and "beta" for the axes
      !> whatever their names; `&scene columns` takes either
      character(len=:), allocatable :: key
      !> what the column needs computed at a point (need_* of hillstab_integrate_monodromy):
      !> nothing, the verdict, the growth (exact where |S| < 2, S to the tolerance elsewhere)
      !> or S to the tolerance; a file computes what the most demanding of its columns needs
      !> (one equation's files; a system's compute everything)
      integer :: need = need_nothing
      integer :: accuracy = accuracy_none  !! its `# accuracy of` statement (accuracy_*)
      !> significant digits of its text, from its style (e17 17, e11 11, e7 7, e4 4; 0 for
      !> the flags and integers, which `put_value` writes)
      integer :: digits = 17
      !> a verdict by the paper's criterion |S1| <= 2 (the computation then settles |S| = 2
      !> too, and its accuracy is stated at |S| = 2)
      logical :: paper = .false.
      logical :: offered = .true.  !! files of this scene offer the column
      !> an offered column written only when `&scene columns` names it (not in the default
      !> list: one equation's kind and argument, which its files gained after their first
      !> version)
      logical :: on_request = .false.
   end type chart_column_t

   !> What the columns' records depend on: the file's kind (one equation's trace or a system's
   !> Φ) and the scene's model, damping, `&physical` and axes.
   type :: column_context_t
      logical :: system = .false.       !! a system's file (the analysis of its Φ)
      integer :: n = 1                  !! a system's degrees of freedom
      logical :: first_order = .false.  !! a system given as y' = A y
      logical :: damped = .false.       !! one equation: ε > 0 or a model with damping of its own
      logical :: pendulum = .false.     !! one equation: the elastic pendulum's
      logical :: physical = .false.     !! one equation: `&physical` given
      logical :: amplitudes = .false.   !! one equation: `&physical` amplitudes given
      logical :: omegas = .false.       !! one equation: `&physical` frequencies given
      !> one equation: its model has a time of its user's (`has_time`: an equation in t)
      logical :: own_time = .false.
      character(len=:), allocatable :: alpha_name  !! the α axis's name ("alpha" when unnamed)
      character(len=:), allocatable :: beta_name   !! the β axis's name
      character(len=:), allocatable :: summary     !! one equation: its model's summary
      !> one equation: the stability threshold 2 cosh(epsilon) in words (damped)
      character(len=:), allocatable :: threshold
      character(len=:), allocatable :: period      !! one equation: the period in words ("2")
   end type column_context_t

   !> The places of the columns of a chart or points file, in file order: where
   !> `chart_column_table` puts each record and `chart_values` each value, found by key in
   !> `chart_keys` (hillstab_batch_tasks_floquet_columns).
   integer, parameter :: col_alpha = findloc(chart_keys, "alpha", 1), col_a = findloc(chart_keys, "a", 1), &
      col_beta = findloc(chart_keys, "beta", 1), col_omega = findloc(chart_keys, "omega", 1), &
      col_s = findloc(chart_keys, "S", 1), col_stable = findloc(chart_keys, "stable", 1), &
      col_lambda_max = findloc(chart_keys, "lambda_max", 1), col_mu = findloc(chart_keys, "mu", 1), &
      col_log10_abs_s = findloc(chart_keys, "log10_abs_S", 1), col_overflow = findloc(chart_keys, "overflow", 1), &
      col_physical = findloc(chart_keys, "physical", 1), col_stable_paper = findloc(chart_keys, "stable_paper", 1), &
      col_mu_per_s = findloc(chart_keys, "mu_per_s", 1), col_error_estimate = findloc(chart_keys, "error_estimate", 1), &
      col_status = findloc(chart_keys, "status", 1), col_kind = findloc(chart_keys, "kind", 1), &
      col_argument = findloc(chart_keys, "argument", 1)
   !> Number of columns a chart or points file can hold.
   integer, parameter :: n_chart_columns = size(chart_keys)

   !> Magnitudes beyond this are written as ±clamp_magnitude with the overflow flag set.
   real(wp), parameter :: clamp_magnitude = 1.0e300_wp
   !> log10|S| is written as at least this (only S = 0 exactly reaches it).
   real(wp), parameter :: log10_floor = -300.0_wp

   !> The columns of a system's chart and points files before the exponents mu_1 … mu_n and
   !> after them, in file order: the one place their order is set. Every column's record
   !> (meaning, style, placeholder) is `system_column_table`'s, its value `system_point_values`',
   !> each found by name (`system_layout_t`).
   character(len=14), parameter :: before_exponents(10) = [character(len=14) :: "alpha", "beta", "trace", "a2", &
                                                          "overflow", "stable", "kind", "lambda_max", "mu", "argument"]
   character(len=14), parameter :: after_exponents(4) = [character(len=14) :: "defect", "error_estimate", "status", &
                                                         "steps"]
   !> The columns besides the n exponents.
   integer, parameter :: n_fixed = size(before_exponents) + size(after_exponents)

   !> Where each column sits among a point's values, by name (`system_layout`): what
   !> `system_point_values` fills, the C API's status and every file's rows follow from it.
   type :: system_layout_t
      integer :: n = 0            !! degrees of freedom (the exponents mu_1 … mu_n)
      integer :: columns = 0      !! every column: n_fixed + n
      !> the places of the columns of those names
      integer :: alpha = 0, beta = 0, trace = 0, a2 = 0, overflow = 0, stable = 0, kind = 0, lambda_max = 0
      !> the places of the columns of those names
      integer :: mu = 0, argument = 0, defect = 0, error_estimate = 0, status = 0, steps = 0
      integer :: mu_1 = 0         !! the first exponent; mu_k is at mu_1 + k − 1
   end type system_layout_t

contains

   !> The record of the column `key` of a file analysing what `context` says: one equation's
   !> columns are `chart_keys`; a system's `system_column_names` (alpha, beta, trace, a2,
   !> overflow, stable, kind, lambda_max, mu, argument, mu_1 … mu_n, defect, error_estimate,
   !> status, steps). The columns of both keep their meaning of their own where the analyses
   !> differ (stable, overflow, lambda_max, mu, error_estimate, status).
   pure function floquet_column(key, context) result(column)
      character(len=*), intent(in) :: key  !! the column's key
      type(column_context_t), intent(in) :: context  !! the file's kind and scene
      type(chart_column_t) :: column
      character(len=:), allocatable :: text
      logical :: system
      system = context%system
      select case (key)
      case ("alpha", "beta")
         if (system) then
            text = trim(merge("alpha, the drive     ", "beta, the factor of B", key == "alpha"))
         else if (context%pendulum) then
            text = trim(merge("alpha = a pi^2/rho, eq. (24)         ", "beta = g pi^2/(rho omega^2), eq. (24)", &
                              key == "alpha"))
         else
            text = key//" of "//context%summary
         end if
         if (key == "alpha") then
            column = record(name_of(context%alpha_name, key), "", text, style_e17, need_nothing, kept=.true.)
         else
            column = record(name_of(context%beta_name, key), "", text, style_e17, need_nothing, kept=.true.)
         end if
         if (column%name /= key) column%meaning = axis_meaning(column%name, key, system)
      case ("a")
         if (context%amplitudes) then
            text = "bounce amplitude of &physical (alpha = a pi^2/rho)"
         else
            text = "bounce amplitude a = alpha rho/pi^2 with rho = g pi^2/(beta omega^2) (eq. (24)); -1 where "// &
                   "beta <= 0 (no equilibrium length)"
         end if
         column = record("a", "m", text, style_e17, need_nothing, kept=.true., &
                         offered=context%physical .and. (context%amplitudes .or. context%pendulum))
      case ("omega")
         column = record("omega", "rad/s", "radial angular frequency sqrt(k/m) of the point (rho = r0 + g/omega^2)", &
                         style_e17, need_nothing, kept=.true., offered=context%omegas)
      case ("S")
         column = record("S", "", "trace of the one-period monodromy (with epsilon > 0: S1 of the chi equation "// &
                         "(47)); |S| > 1e300 is written as +-1e300 with overflow = 1", style_e17, need_trace)
      case ("trace")
         if (context%first_order) then
            text = "a1 = tr Phi of the one-period monodromy of y' = A y (+-1e300 with overflow = 1)"
         else
            text = "a1 = tr Phi of the one-period monodromy of y = (x, x') (+-1e300 with overflow = 1)"
         end if
         column = record("trace", "", text, style_e17, need_trace)
      case ("a2")
         column = record("a2", "", "a2 = ((tr Phi)^2 - tr Phi^2)/2 = sum of lambda_i lambda_j (from the "// &
                         "multipliers where that difference cancels; Broucke: z^2 - a1 z + a2 - 2 = 0 for n = 2)", &
                         style_e17, need_trace)
      case ("stable")
         if (system) then
            column = record("stable", "", "1 stable, 0 unstable, -1 marginal (the error bound of Phi does not "// &
                            "decide)", style_integer, need_verdict, placeholder=-1.0_wp)
         else
            if (context%damped) then
               text = "1 when |S1| < "//context%threshold//" (all multipliers of x inside the unit circle)"
            else
               text = "1 when |S| < 2"
            end if
            text = text//"; 0.5: marginal, |S| is within its error bound max(error_estimate, tolerance) "// &
                   "max(1, |S|) of the threshold, the value cannot decide"
            column = record("stable", "", text, style_flag, need_verdict, placeholder=-1.0_wp)
         end if
      case ("kind")
         if (system) then
            column = record("kind", "", "0 stable, 1 unstable at +1, 2 at -1, 3 combination (Krein collision), "// &
                            "4 damped (asymptotically stable), 5 undecided (stable = -1)", style_integer, need_verdict, &
                            placeholder=-1.0_wp)
         else
            column = record("kind", "", "0 stable, 1 unstable at +1 (S > 2: a tongue of even order), 2 at -1 "// &
                            "(S < -2: odd order), 4 damped (asymptotically stable), 5 undecided (stable = 0.5)", &
                            style_flag, need_verdict, placeholder=-1.0_wp)
            column%on_request = .true.
         end if
      case ("lambda_max")
         if (system) then
            column = record("lambda_max", "", "largest |multiplier| (1e300 when it overflows; mu is exact)", &
                            style_e17, need_growth)
         else
            column = record("lambda_max", "", "largest |multiplier| of x per "// &
                            trim(merge("radial period", "period of Q  ", context%pendulum)), style_e11, need_growth, &
                            placeholder=-1.0_wp)
         end if
      case ("mu")
         if (system) then
            column = record("mu", "", "ln(lambda_max)/period, the largest Floquet exponent per unit tau", &
                            style_e17, need_growth)
         else
            column = record("mu", "", "Floquet exponent ln(lambda_max)/"//context%period//" per unit tau", &
                            style_e11, need_growth)
         end if
      case ("argument")
         if (system) then
            column = record("argument", "", "arg(lambda)/pi of the largest multiplier, in [0, 1]", style_e17, &
                            need_growth)
         else
            column = record("argument", "", "arg(lambda)/pi of the largest multiplier, in [0, 1]: 0 at +1, 1 at "// &
                            "-1, arccos(S/2)/pi where |S| < 2 (the rotation number of the swing per period)", &
                            style_e17, need_growth, placeholder=-1.0_wp, accuracy=accuracy_argument)
            column%on_request = .true.
         end if
      case ("log10_abs_S")
         column = record("log10_abs_S", "", "log10|S|, exact also where S overflows", style_e11, need_trace, &
                         placeholder=-999.0_wp)
      case ("overflow")
         if (system) then
            column = record("overflow", "", "1 when |a1| or |a2| exceeds 1e300 (clamped)", style_integer, &
                            need_trace)
         else
            column = record("overflow", "", "1 when |S| > 1e300", style_flag, need_trace, placeholder=-1.0_wp)
         end if
      case ("physical")
         column = record("physical", "", "1 inside the physical domain 0 <= alpha < pi^2, 0 <= beta < pi^2", &
                         style_flag, need_nothing, kept=.true., offered=context%pendulum)
      case ("stable_paper")
         column = record("stable_paper", "", "1 when |S1| <= 2, the sufficient criterion of the paper", style_flag, &
                         need_verdict, placeholder=-1.0_wp, paper=.true., offered=context%damped)
      case ("mu_per_s")
         if (context%own_time .and. .not. context%physical) then
            column = record("mu_per_s", "1/t", "the Floquet exponent per unit of the equation's time t (per second "// &
                            "when t is in seconds), mu Omega/pi at the point (tau = Omega t/pi)", style_e11, need_growth)
            column%on_request = .true.
         else
            column = record("mu_per_s", "1/s", "the Floquet exponent per second, mu omega/pi (tau = omega t/pi)", &
                            style_e11, need_growth, offered=context%physical)
         end if
      case ("defect")
         if (context%first_order) then
            text = "|det Phi - exp(P mean tr A)| over Hadamard's bound of |det Phi| (relative, max norms)"
         else
            text = "Hamiltonian: |Phi^T Omega Phi - Omega|/(|Omega| max(1, |Phi|)^2); else |det Phi - exp(P tr D)| "// &
                   "over Hadamard's bound of |det Phi| (relative, max norms)"
         end if
         column = record("defect", "", text, style_e17, need_trace, placeholder=-1.0_wp)
      case ("error_estimate")
         if (system) then
            column = record("error_estimate", "", "the method's estimate of the error of Phi's entries relative "// &
                            "to max(1, max|Phi_ij|)", style_e17, need_trace, placeholder=-1.0_wp, &
                            accuracy=accuracy_estimate)
         else
            column = record("error_estimate", "", "the method's estimate of |error of S|/max(1, |S|), not a bound "// &
                            "(-1: the method gives none; the bound at status 0 is the tolerance)", style_e4, &
                            need_trace, placeholder=-1.0_wp, accuracy=accuracy_estimate)
         end if
      case ("status")
         if (system) then
            column = record("status", "", "0 ok; 1 round-off limited (the tolerance lies below the rounding of "// &
                            "the method, or an exponent mu_k is not resolved to it); 2 failed (placeholders)", &
                            style_integer, need_nothing, placeholder=real(status_failed, wp))
         else
            column = record("status", "", "0 ok; 1 round-off limited (best value, error_estimate at the "// &
                            "round-off level); 2 failed (placeholders in the other columns)", style_flag, &
                            need_nothing, kept=.true.)
         end if
      case ("steps")
         column = record("steps", "", "Magnus steps (rk, gsl: right-hand sides) spent on the point", &
                         style_integer, need_nothing)
      case default
         ! mu_1 … mu_n
         column = record(key, "", "ln|lambda_k|/period of the k-th largest multiplier (from the period's "// &
                         "product kept factored where Phi cannot resolve it)", style_e17, need_growth)
      end select
      column%key = key
   end function floquet_column

   !> An axis's name: the given one, else the generic.
   pure function name_of(given, generic) result(name)
      character(len=:), allocatable, intent(in) :: given  !! the axis's name (unallocated: unnamed)
      character(len=*), intent(in) :: generic  !! "alpha" or "beta"
      character(len=:), allocatable :: name
      name = generic
      if (allocated(given)) then
         if (len_trim(given) > 0) name = trim(given)
      end if
   end function name_of

   !> The meaning of an axis named after a parameter: one equation's names the equation and
   !> the rows of the chart.
   pure function axis_meaning(name, axis, system) result(text)
      character(len=*), intent(in) :: name  !! the parameter
      character(len=*), intent(in) :: axis  !! "alpha" or "beta"
      logical, intent(in) :: system         !! a system's file
      character(len=:), allocatable :: text
      if (system) then
         text = "the parameter "//name//", the chart's "//axis//" axis"
      else if (axis == "alpha") then
         text = "the parameter "//name//" of the equation, the chart's alpha axis (rows)"
      else
         text = "the parameter "//name//" of the equation, the chart's beta axis"
      end if
   end function axis_meaning

   !> One column's record: its name, unit and meaning (the header's line), its text style,
   !> what it needs computed at a point (need_* of hillstab_integrate_monodromy), the value
   !> a failed point writes (`placeholder`: outside the column's range; default 0) unless it
   !> keeps its own (`kept`: the point's coordinates, flags and status), its `# accuracy of`
   !> statement (default: that of what it needs), whether it is a verdict by the paper's
   !> criterion, and whether this scene's files offer it (default: always).
   pure function record(name, unit, meaning, style, need, placeholder, kept, accuracy, paper, offered) &
      result(column)
      character(len=*), intent(in) :: name     !! as in the `# columns:` line and `&scene columns`
      character(len=*), intent(in) :: unit     !! "" when dimensionless
      character(len=*), intent(in) :: meaning  !! one line for the header
      integer, intent(in) :: style             !! style_* of hillstab_batch_output_columns
      integer, intent(in) :: need              !! need_* of hillstab_integrate_monodromy
      real(wp), intent(in), optional :: placeholder  !! the value of a failed point
      logical, intent(in), optional :: kept     !! a failed point writes its own value
      integer, intent(in), optional :: accuracy  !! accuracy_*
      logical, intent(in), optional :: paper    !! a verdict by |S1| <= 2
      logical, intent(in), optional :: offered  !! files of the scene offer it
      type(chart_column_t) :: column
      column%name = name
      column%unit = unit
      column%meaning = meaning
      column%style = style
      column%need = need
      if (present(placeholder)) column%placeholder = placeholder
      if (present(kept)) column%keep_on_failure = kept
      select case (need)
      case (need_verdict)
         column%accuracy = accuracy_verdict
      case (need_growth)
         column%accuracy = accuracy_growth
      case (need_trace)
         column%accuracy = accuracy_trace
      case default
         column%accuracy = accuracy_none
      end select
      if (present(accuracy)) column%accuracy = accuracy
      select case (style)
      case (style_e17)
         column%digits = 17
      case (style_e11)
         column%digits = 11
      case (style_e7)
         column%digits = 7
      case (style_e4)
         column%digits = 4
      case default
         column%digits = 0
      end select
      if (present(paper)) column%paper = paper
      if (present(offered)) column%offered = offered
   end function record

   !> The columns `text` names (`&scene columns`: names, the axes also as alpha and beta,
   !> blank- or comma-separated, any case), in its order, among those `available`; `bad` the
   !> first name that is not one of them or is named twice ("" when every name was found),
   !> and `known` the names available for the message.
   pure subroutine choose_columns(table, available, text, ids, bad, known)
      type(chart_column_t), intent(in) :: table(:)  !! every column of the file's kind
      integer, intent(in) :: available(:)           !! the indices of `table` this file offers
      character(len=*), intent(in) :: text          !! the names
      integer, allocatable, intent(out) :: ids(:)   !! the columns found, in order
      character(len=:), allocatable, intent(out) :: bad    !! the first name not found or repeated
      character(len=:), allocatable, intent(out) :: known  !! the names available, blank-separated
      type(column_t) :: plain(size(table))
      character(len=5) :: aliases(size(table))
      integer :: k
      plain = plain_table(table)
      aliases = ""
      do k = 1, size(table)
         if (table(k)%key == "alpha" .or. table(k)%key == "beta") aliases(k) = table(k)%key
      end do
      call find_columns(plain, available, text, ids, bad, aliases)
      known = columns_text(plain, available)
   end subroutine choose_columns
   !> The columns a chart or points file holds: those `&scene columns` (`text`) names
   !> (`choose_columns`), else every one `available` (or those of `defaults`), in file order;
   !> err_input naming the scene file, `&scene` and `columns` for a name that is not available
   !> or is named twice, or for no name at all.
   subroutine scene_columns(table, available, text, source, ids, error, defaults)
      type(chart_column_t), intent(in) :: table(:)  !! every column of the file's kind
      integer, intent(in) :: available(:)           !! the indices of `table` this file offers
      character(len=*), intent(in) :: text          !! `&scene columns`
      character(len=*), intent(in) :: source        !! the scene file
      integer, allocatable, intent(out) :: ids(:)   !! the columns written, in order
      type(error_t), allocatable, intent(out) :: error  !! err_input naming &scene columns
      !> the columns written when `text` is blank (default `available`): those not only on request
      integer, intent(in), optional :: defaults(:)
      character(len=:), allocatable :: bad, known
      if (len_trim(text) == 0) then
         ids = available
         if (present(defaults)) ids = defaults
         return
      end if
      call choose_columns(table, available, text, ids, bad, known)
      if (len(bad) > 0) then
         call fail(error, source, "scene", "columns", "'"//bad//"' is not a column of this file or is named "// &
                   "twice (available: "//known//")")
      else if (size(ids) == 0) then
         call fail(error, source, "scene", "columns", "no column named")
      end if
   end subroutine scene_columns
   !> The value of every column (table order) at one computed point: S and lambda_max
   !> clamped to ±1e300, flags 1 or 0, stable 0.5 when marginal, mu_per_s = μ ω/π
   !> (0 without `per_second`), error_estimate −1 when the method gives none, a the
   !> amplitude (0 without `amplitude`).
   pure function chart_values(alpha, beta, f, physical, status, per_second, amplitude, omega, need) result(v)
      real(wp), intent(in) :: alpha, beta  !! the grid point
      type(floquet_t), intent(in) :: f  !! Floquet data of the point
      logical, intent(in) :: physical   !! (α, β) inside the physical domain
      integer, intent(in) :: status     !! per-point status code (hillstab_core_status)
      real(wp), intent(in), optional :: per_second  !! ω/π
      real(wp), intent(in), optional :: amplitude   !! a (m), `point_amplitude`
      real(wp), intent(in), optional :: omega       !! ω (rad/s) of a chart over (a, ω)
      !> what was computed (`chart_layout_t` need): below need_growth the columns of λ, μ and ln|S|
      !> are left at 0 (not written)
      integer, intent(in), optional :: need
      real(wp) :: v(n_chart_columns)
      real(wp) :: s, estimate
      logical :: overflow, growth
      s = f%trace%value
      overflow = f%trace%overflow .or. abs(s) > clamp_magnitude
      if (overflow) s = sign(clamp_magnitude, s)
      estimate = f%trace%error_estimate
      if (estimate < 0.0_wp) estimate = -1.0_wp
      v(col_alpha) = alpha
      v(col_a) = 0.0_wp
      if (present(amplitude)) v(col_a) = amplitude
      v(col_beta) = beta
      v(col_omega) = 0.0_wp
      if (present(omega)) v(col_omega) = omega
      v(col_s) = s
      v(col_stable) = merge(1.0_wp, 0.0_wp, f%stable)
      if (f%marginal) v(col_stable) = 0.5_wp
      growth = .true.
      if (present(need)) growth = need >= need_growth
      if (growth) then
         v(col_lambda_max) = min(largest_multiplier_modulus(f), clamp_magnitude)
         v(col_mu) = f%exponent + 0.0_wp  ! no "-0.0" in the file
         v(col_log10_abs_s) = max(f%trace%log_abs/log(10.0_wp), log10_floor)
      else
         v(col_lambda_max) = 0.0_wp
         v(col_mu) = 0.0_wp
         v(col_log10_abs_s) = 0.0_wp
      end if
      v(col_overflow) = merge(1.0_wp, 0.0_wp, overflow)
      v(col_physical) = merge(1.0_wp, 0.0_wp, physical)
      v(col_stable_paper) = merge(1.0_wp, 0.0_wp, f%stable_paper)
      v(col_mu_per_s) = 0.0_wp
      if (present(per_second) .and. growth) v(col_mu_per_s) = v(col_mu)*per_second + 0.0_wp
      v(col_error_estimate) = min(estimate, clamp_magnitude)
      v(col_status) = real(status, wp)
      v(col_kind) = real(f%kind, wp)
      v(col_argument) = 0.0_wp
      if (growth) v(col_argument) = abs(f%argument(1))/pi
   end function chart_values

   !> The placeholders of one equation's columns (`chart_keys` order): what a failed point
   !> writes in each column that does not keep its own value (0 in those that do).
   pure function chart_placeholders() result(v)
      real(wp) :: v(n_chart_columns)
      type(column_context_t) :: context
      type(chart_column_t) :: column
      integer :: k
      context = column_context_t(alpha_name="alpha", beta_name="beta", summary="", threshold="", period="2")
      do k = 1, n_chart_columns
         column = floquet_column(trim(chart_keys(k)), context)
         v(k) = merge(0.0_wp, column%placeholder, column%keep_on_failure)
      end do
   end function chart_placeholders

   !> Every column of a system of n degrees of freedom, by name, in file order.
   pure function system_column_names(n) result(names)
      integer, intent(in) :: n  !! degrees of freedom
      character(len=14) :: names(n_fixed + n)
      integer :: k
      names(1:size(before_exponents)) = before_exponents
      do k = 1, n
         write (names(size(before_exponents) + k), '(a, i0)') "mu_", k
      end do
      names(size(before_exponents) + n + 1:) = after_exponents
   end function system_column_names

   !> Each column's place among a point's values, found by its name (without making the
   !> names of the exponents: this runs once a row).
   pure function system_layout(n) result(layout)
      integer, intent(in) :: n  !! degrees of freedom
      type(system_layout_t) :: layout
      layout%n = n
      layout%columns = n_fixed + n
      layout%alpha = place("alpha")
      layout%beta = place("beta")
      layout%trace = place("trace")
      layout%a2 = place("a2")
      layout%overflow = place("overflow")
      layout%stable = place("stable")
      layout%kind = place("kind")
      layout%lambda_max = place("lambda_max")
      layout%mu = place("mu")
      layout%argument = place("argument")
      layout%mu_1 = size(before_exponents) + 1
      layout%defect = place("defect")
      layout%error_estimate = place("error_estimate")
      layout%status = place("status")
      layout%steps = place("steps")
   contains
      pure integer function place(name)
         character(len=*), intent(in) :: name
         place = findloc(before_exponents, name, dim=1)
         if (place == 0) place = size(before_exponents) + n + findloc(after_exponents, name, dim=1)
      end function place
   end function system_layout

   !> The place of the column `status` among a point's values (`system_layout`).
   pure integer function status_column(n)
      integer, intent(in) :: n  !! degrees of freedom
      type(system_layout_t) :: layout
      layout = system_layout(n)
      status_column = layout%status
   end function status_column

   !> The values of every column at one point, each at its place in `layout` (the
   !> placeholders of `system_column_table` when the point failed).
   pure function system_point_values(layout, alpha, beta, f, r, failed) result(v)
      type(system_layout_t), intent(in) :: layout   !! the columns' places (`system_layout`)
      real(wp), intent(in) :: alpha, beta           !! the point
      type(floquet_t), intent(in) :: f       !! its analysis
      type(system_monodromy_t), intent(in) :: r     !! its monodromy
      logical, intent(in) :: failed                 !! no value
      real(wp) :: v(layout%columns)
      v = 0.0_wp
      v(layout%alpha) = alpha
      v(layout%beta) = beta
      if (failed) then
         call failed_row(plain_table(system_column_table(layout%n, .false.)), v)
         return
      end if
      v(layout%trace) = f%a1
      v(layout%a2) = f%a2
      v(layout%overflow) = merge(1.0_wp, 0.0_wp, f%overflow .or. f%log_modulus(1) > log(1.0e300_wp))
      v(layout%stable) = real(f%verdict, wp)
      v(layout%kind) = real(f%kind, wp)
      v(layout%lambda_max) = exp(min(f%log_modulus(1), log(1.0e300_wp)))
      v(layout%mu) = f%exponent
      v(layout%argument) = abs(f%argument(1))/pi
      v(layout%mu_1:layout%mu_1 + layout%n - 1) = f%exponents
      v(layout%defect) = f%defect
      v(layout%error_estimate) = r%error_estimate
      v(layout%status) = real(r%status, wp)
      v(layout%steps) = real(r%steps, wp)
   end function system_point_values

   !> The records of a table as plain output columns (name, unit, meaning, style, placeholder).
   pure function plain_table(table) result(plain)
      type(chart_column_t), intent(in) :: table(:)  !! the records
      type(column_t) :: plain(size(table))
      integer :: k
      do k = 1, size(table)
         plain(k) = table(k)%column_t
      end do
   end function plain_table

   !> Every column of a system's chart and points files (`system_column_names`), its record
   !> of `floquet_column` for a system's file: the meaning the header gives it (of the
   !> first-order form's where it differs), its text style (flags, codes and counts as
   !> integers, the rest in 17 digits) and the placeholder of a failed point (the axes keep
   !> their values); the axes named after the system's when it names them.
   pure function system_column_table(n, first_order, alpha_name, beta_name) result(table)
      integer, intent(in) :: n  !! degrees of freedom (first-order form: the states)
      logical, intent(in) :: first_order  !! the system is y' = A y
      character(len=*), intent(in), optional :: alpha_name, beta_name  !! the axes' names (default alpha, beta)
      type(chart_column_t) :: table(n_fixed + n)
      type(column_context_t) :: context
      character(len=14) :: names(n_fixed + n)
      integer :: k
      context%system = .true.
      context%n = n
      context%first_order = first_order
      if (present(alpha_name)) context%alpha_name = alpha_name
      if (present(beta_name)) context%beta_name = beta_name
      names = system_column_names(n)
      do k = 1, size(names)
         table(k) = floquet_column(trim(names(k)), context)
      end do
   end function system_column_table

end module hillstab_batch_tasks_floquet_columns

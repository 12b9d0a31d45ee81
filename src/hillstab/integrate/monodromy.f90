!> One entry point from a method choice to the monodromy trace of one period, and the
!> table of the methods from which every other use derives: code, name, what each
!> offers, whether it applies to scalar models, to systems or both, a one-line description.
!> A new monodromy method is its own module plus its row in `method_table` and its case in
!> `monodromy_trace`, and for systems its cases in `system_monodromy` (with its round-off
!> level) and `system_factors`, here too: the choice among the methods is this module's
!> alone, for one equation and for n (the system integrators are
!> hillstab_integrate_system_magnus and hillstab_integrate_system_gsl). `make codes` writes
!> its code into C, FORTRAN 77 and Python; test suite codes compares them.
!>
!> Methods (the codes are the C API's HILLSTAB_METHOD_* and the F77 METHOD codes):
!> `auto` 0, `formula` 1 (the paper's closed 2-piece forms), `segments` 2 (N-piece
!> piecewise-constant product), `magnus4` 3, `magnus6` 4, `rk` 5, `gsl` 6. All return the
!> trace of the χ equation (47), i.e. S₁ when ε > 0. Systems take auto, magnus4, magnus6,
!> rk and gsl (`method_takes_systems`), under the same codes: a system's method is a row of
!> this table, never a second numbering.
!>
!>```fortran
!> type(trace_t) :: tr
!> type(error_t), allocatable :: error
!> call monodromy_trace(elastic_model_t(), hill_point_t(9.8_wp, 2.47_wp, 0.0_wp), &
!>                      method_t(method_from_name("magnus6"), tolerance=1.0e-10_wp), tr, error)
!> print *, tr%value, method_description(method_magnus6)
!>```
module hillstab_integrate_monodromy
   use hillstab_core_kinds, only: wp, log_huge
   use hillstab_core_error, only: error_t, set_error, err_invalid_parameter, err_accuracy
   use hillstab_core_text, only: name_position, alternatives_text, integer_text
   use hillstab_hill_model, only: hill_model_t, hill_point_t, check_point, check_batch, coefficient_range, model_split, &
      model_split_row, &
      widen_by_offset, max_magnitude
   use hillstab_hill_coefficient, only: sampling_endpoint, sampling_count
   use hillstab_hill_floquet, only: bounds_verdict, bounds_stable, bounds_unstable, near_threshold, period_damping
   use hillstab_hill_transfer, only: scaled_matrix_t, multiply_matrix, trace_t, trace_from_value
   use hillstab_hill_formulas, only: trace_formula
   use hillstab_core_stats, only: work_stats_t, add_work
   use hillstab_integrate_segments, only: monodromy_segmented, trace_segmented
   use hillstab_integrate_monodromy_gsl, only: trace_gsl
   use hillstab_integrate_monodromy_rk, only: trace_rk
   use hillstab_integrate_magnus, only: trace_magnus
   use hillstab_integrate_auto, only: trace_auto, trace_auto_batch, auto_plan_t, auto_prepare, trace_auto_screen
   use hillstab_core_status, only: status_ok, status_roundoff, status_failed
   use hillstab_hill_system, only: hill_system_t, system_form_t
   use hillstab_integrate_system_magnus, only: system_monodromy_t, system_nodes_t, monodromy_magnus, &
      magnus_period_factors, monodromy_rk, rk_period_factors, factor_pieces, complete_half_factors
   use hillstab_integrate_system_gsl, only: system_monodromy_gsl, gsl_period_factors
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   implicit none
   private
   public :: method_t, method_auto, method_formula, method_segments, method_magnus4, method_magnus6, &
      method_rk, method_gsl, method_name, method_from_name
   public :: method_info_t, method_table, method_info, method_names_text, method_description, method_is_exact, &
      method_uses_segments, method_gives_estimate, method_batches_rows, method_cost_grows, method_pieces, &
      max_integrated_magnitude, method_takes_scalars, method_takes_systems
   public :: need_nothing, need_verdict, need_growth, need_trace, verdict_is_certain, screen_tolerance, screen_safety
   public :: monodromy_segmented, trace_segmented, swing_monodromy, monodromy_trace, monodromy_trace_batch
   public :: batch_plan_t, prepare_batch, max_segments
   public :: system_method_t, system_monodromy, system_factors

   !> Largest `n_segments` of method segments, for every caller (scenes, the C and
   !> FORTRAN 77 entry points): it bounds the work and the memory of one point (the
   !> pieces' coefficients are n_segments numbers).
   integer, parameter :: max_segments = 100000

   integer, parameter :: method_auto = 0     !! cheapest exact method meeting the tolerance
   integer, parameter :: method_formula = 1  !! the paper's closed forms, eq. (37)/(48)/(A3)
   integer, parameter :: method_segments = 2 !! N-piece piecewise-constant product
   integer, parameter :: method_magnus4 = 3  !! fourth-order Magnus integrator
   integer, parameter :: method_magnus6 = 4  !! sixth-order Magnus integrator
   integer, parameter :: method_rk = 5       !! hillstab's adaptive Runge–Kutta
   integer, parameter :: method_gsl = 6      !! GSL odeiv2 rk8pd reference

   !> The integrating methods (those with `cost_grows`) take steps in proportion to
   !> √(|α| + |β|): beyond this |α| + |β| one point would take seconds to minutes (auto
   !> stops at its own step limit; formula and segments cost the same at any magnitude).
   real(wp), parameter :: max_integrated_magnitude = 1.0e8_wp

   !> What a caller needs of the traces of a batch (`monodromy_trace_batch`; a chart asks for
   !> the most any of its columns needs). The exact methods do only that work: a verdict is
   !> settled by a cheap screening pass wherever |S| lies beyond the screen's error bound from
   !> the threshold, and only the other points are computed to the tolerance.
   integer, parameter :: need_nothing = 0  !! no trace at all (columns of the grid only)
   integer, parameter :: need_verdict = 1  !! the side of the stability threshold |S| = 2 cosh ε
   !> the verdict, and S to the tolerance wherever |S| < 2 is not certain (λ_max, μ: exact
   !> where |S| < 2, from S elsewhere)
   integer, parameter :: need_growth = 2
   integer, parameter :: need_trace = 3    !! S to the tolerance at every point
   !> The tolerance of the screening pass of the exact methods other than auto (auto has
   !> its own, `auto_screen_tolerance`).
   real(wp), parameter :: screen_tolerance = 1.0e-6_wp
   !> Factor on the error estimate of those methods' screening pass, so that the bound
   !> stands also where the estimate is not yet asymptotic (auto's screen returns a bound).
   real(wp), parameter :: screen_safety = 64.0_wp

   !> What a method is and offers (one row of `method_table`; its code is its row).
   type :: method_info_t
      character(len=12) :: name = ""         !! the scene's, the C enum's and the messages' name
      character(len=80) :: description = ""  !! one line for templates and headers
      logical :: exact = .false.          !! meets `tolerance` (or says round-off limited)
      logical :: segments = .false.       !! uses `n_segments` and `sampling`
      logical :: estimate = .false.       !! gives an error estimate of S (others: −1)
      logical :: batch_rows = .false.     !! shares work across the β of a chart row (`prepare_batch`)
      logical :: cost_grows = .false.     !! cost grows like √(|α| + |β|) (`max_integrated_magnitude`)
      integer :: pieces = 0               !! constant pieces of Q when fixed (formula: 2), else 0
      logical :: scalars = .true.         !! applies to scalar models (`monodromy_trace`)
      !> applies to systems (hillstab_integrate_system `system_monodromy`, under the same code)
      logical :: systems = .false.
   end type method_info_t

   !> The methods, in the order of their codes (0 … 6), for scalar models and systems alike.
   type(method_info_t), parameter :: method_table(0:6) = [ &
      method_info_t("auto", "exact to tolerance, fastest (sixth-order Magnus, Richardson check)", &
                    exact=.true., estimate=.true., batch_rows=.true., systems=.true.), &
      method_info_t("formula", "the paper's 2 pieces, eq. (37) (Mathieu: eq. (A3))", pieces=2), &
      method_info_t("segments", "n_segments constant pieces (endpoint, midpoint or average sampling)", &
                    segments=.true.), &
      method_info_t("magnus4", "fourth-order Magnus, adaptive mesh, Richardson check", &
                    exact=.true., estimate=.true., cost_grows=.true., systems=.true.), &
      method_info_t("magnus6", "sixth-order Magnus, adaptive mesh, Richardson check", &
                    exact=.true., estimate=.true., cost_grows=.true., systems=.true.), &
      method_info_t("rk", "DOP853 under the global error control", &
                    exact=.true., estimate=.true., cost_grows=.true., systems=.true.), &
      method_info_t("gsl", "GSL odeiv2 rk8pd under the global error control, the independent reference", &
                    exact=.true., estimate=.true., cost_grows=.true., systems=.true.)]
   !> The names, contiguous (passing `method_table%name` would copy the column on every call).
   character(len=len(method_table%name)), parameter :: method_names(0:6) = method_table%name

   !> How to compute the monodromy.
   type :: method_t
      integer :: kind = method_auto  !! one of the method_* constants
      integer :: n_segments = 2             !! pieces for method_segments
      integer :: sampling = sampling_endpoint  !! piece values for method_segments
      real(wp) :: tolerance = 1.0e-10_wp    !! target error on S, scaled by max(1, |S|)
   end type method_t

   !> A system's method and its tolerance.
   type :: system_method_t
      integer :: kind = method_auto        !! a method code that `method_takes_systems`
      real(wp) :: tolerance = 1.0e-10_wp   !! target error of Φ, relative to max(1, max|Φ_ij|)
   end type system_method_t

   !> Work shared by the batches of one chart row (the meshes of method auto).
   type :: batch_plan_t
      type(auto_plan_t) :: auto  !! meshes of method auto
   end type batch_plan_t

contains

   !> Prepare what batches of the points (row%alpha, β_j, row%epsilon) of a model
   !> can share; pass the plan to `monodromy_trace_batch`.
   subroutine prepare_batch(model, row, betas, method, plan, need)
      class(hill_model_t), intent(in) :: model  !! the model
      type(hill_point_t), intent(in) :: row     !! α and ε of the batch (β ignored)
      real(wp), intent(in) :: betas(:)  !! the betas of the batch
      type(method_t), intent(in) :: method  !! how the traces will be computed
      type(batch_plan_t), intent(out) :: plan  !! what the batches can share
      integer, intent(in), optional :: need  !! what the batches will need (default need_trace)
      logical :: screen
      ! a model that does not share rows takes each point alone: nothing to share
      if (.not. model%shares_rows()) return
      screen = .false.
      if (present(need)) screen = need < need_trace
      if (method%kind == method_auto) call auto_prepare(model, row%alpha, row%epsilon, betas, &
                                                       method%tolerance, plan%auto, screen)
   end subroutine prepare_batch

   !> The points of a batch whose need the range of q decides without integrating
   !> (hillstab_hill_floquet `bounds_verdict`): Zhukovskii's criterion gives |S| < 2, which
   !> settles need_verdict (stable, and stable by the paper's criterion too) and need_growth
   !> (λ_max = e^{−ε} whatever S); q < 0 throughout gives S > 2, which settles need_verdict
   !> of an undamped point. Their traces stand for S alone where it decides nothing else:
   !> 0 for |S| < 2, 3 for S > 2, with error estimate 0 (no column of S is written where the
   !> need is below need_trace).
   pure subroutine settle_by_bounds(model, row, betas, need, traces, settled)
      class(hill_model_t), intent(in) :: model  !! the model
      type(hill_point_t), intent(in) :: row     !! α and ε of the batch (β ignored)
      real(wp), intent(in) :: betas(:)         !! the betas of the batch
      integer, intent(in) :: need              !! need_verdict or need_growth
      type(trace_t), intent(inout) :: traces(:)  !! the settled points' stand-ins
      logical, intent(out) :: settled(:)       !! which points are settled
      real(wp) :: q_min, q_max, w_min, w_max, v_min, v_max, scale, c0s(size(betas)), c1s(size(betas))
      integer :: j, verdict
      call model_split_row(model, row%alpha, betas, row%epsilon, c0s, c1s)
      call model%shape_range(row%alpha, w_min, w_max)
      call model%offset_range(row%alpha, v_min, v_max)
      ! the criterion is stated for the period 2: over a period P, in s = 2τ/P, q is (P/2)² q
      scale = (0.5_wp*model%period())**2
      do j = 1, size(betas)
         call coefficient_range(c0s(j), c1s(j), w_min, w_max, q_min, q_max)
         if (model%has_offset()) call widen_by_offset(v_min, v_max, q_min, q_max)
         verdict = bounds_verdict(scale*q_min, scale*q_max)
         settled(j) = verdict == bounds_stable .or. (verdict == bounds_unstable .and. need == need_verdict .and. &
                                                    .not. row%epsilon > 0.0_wp)
         if (.not. settled(j)) cycle
         if (verdict == bounds_stable) then
            traces(j) = trace_from_value(0.0_wp)
         else
            traces(j) = trace_from_value(3.0_wp)
         end if
         traces(j)%error_estimate = 0.0_wp
      end do
   end subroutine settle_by_bounds

   !> The indices of the points not settled, in order (what pack([(j, j = 1, n)], .not.
   !> settled) gives, without its temporary array and library call: once or twice per row).
   pure subroutine unsettled_points(settled, open)
      logical, intent(in) :: settled(:)  !! which points are settled
      integer, allocatable, intent(out) :: open(:)  !! the others' indices
      integer :: j, k
      allocate (open(count(.not. settled)))
      k = 0
      do j = 1, size(settled)
         if (settled(j)) cycle
         k = k + 1
         open(k) = j
      end do
   end subroutine unsettled_points

   !> Whether the trace `tr`, with its error bound max(error_estimate, tolerance)·max(1, |S|),
   !> settles what `need` asks: for need_verdict the side of |S| = 2 cosh ε (and of |S| = 2
   !> too with `paper`, the criterion of the paper); for need_growth that |S| < 2, where
   !> λ_max = e^{−ε} and μ = −ε/2 whatever the value of S. Never for need_trace.
   pure logical function verdict_is_certain(tr, epsilon, tolerance, need, paper) result(certain)
      type(trace_t), intent(in) :: tr  !! a trace with its error estimate (relative to max(1, |S|))
      real(wp), intent(in) :: epsilon    !! damping ε
      real(wp), intent(in) :: tolerance  !! the tolerance S is asked to
      integer, intent(in) :: need        !! need_verdict or need_growth
      logical, intent(in) :: paper       !! also the side of |S| = 2 (need_verdict)
      real(wp) :: bound
      certain = .false.
      ! no estimate, or one of the order of S itself (the screen's difference of two
      ! values of opposite sign, or overflowing ones): nothing is settled
      if (tr%error_estimate < 0.0_wp .or. tr%error_estimate >= 1.0_wp .or. tr%overflow) return
      bound = max(tr%error_estimate, tolerance)
      select case (need)
      case (need_verdict)
         ! not marginal in the sense of `floquet_verdict` (the paper's threshold 2 too)
         certain = epsilon < log_huge .and. .not. near_threshold(tr%value, epsilon, bound)
         if (paper .and. epsilon > 0.0_wp) certain = certain .and. .not. near_threshold(tr%value, 0.0_wp, bound)
      case (need_growth)
         certain = abs(tr%value) < 2.0_wp - bound*max(1.0_wp, abs(tr%value))
      end select
   end function verdict_is_certain

   !> The row of a method code (a row named "unknown", offering nothing, for any other code).
   pure function method_info(kind) result(info)
      integer, intent(in) :: kind  !! one of the method_* constants
      type(method_info_t) :: info
      info%name = "unknown"
      info%scalars = .false.
      if (kind >= lbound(method_table, 1) .and. kind <= ubound(method_table, 1)) info = method_table(kind)
   end function method_info

   !> Name of a method constant ("unknown" for any other code).
   pure function method_name(kind) result(name)
      integer, intent(in) :: kind  !! one of the method_* constants
      character(len=:), allocatable :: name
      type(method_info_t) :: row
      row = method_info(kind)
      name = trim(row%name)
   end function method_name

   !> Method constant from its name (any case, blanks trimmed); −1 when unknown.
   pure integer function method_from_name(name) result(kind)
      character(len=*), intent(in) :: name  !! a method name
      kind = name_position(name, method_names)
      kind = merge(kind - 1 + lbound(method_table, 1), -1, kind > 0)
   end function method_from_name

   !> The method names as a choice for messages: "auto, formula, segments, magnus4, magnus6, rk or gsl".
   pure function method_names_text() result(text)
      character(len=:), allocatable :: text
      text = alternatives_text(method_names)
   end function method_names_text

   !> One line on what the method does, for templates and headers.
   pure function method_description(kind) result(text)
      integer, intent(in) :: kind  !! one of the method_* constants
      character(len=:), allocatable :: text
      type(method_info_t) :: row
      row = method_info(kind)
      text = trim(row%description)
   end function method_description

   !> The method meets `tolerance` (or says that it is below the round-off level there).
   elemental logical function method_is_exact(kind)
      integer, intent(in) :: kind  !! one of the method_* constants
      type(method_info_t) :: row
      row = method_info(kind)
      method_is_exact = row%exact
   end function method_is_exact

   !> The method uses `n_segments` and `sampling`.
   elemental logical function method_uses_segments(kind)
      integer, intent(in) :: kind  !! one of the method_* constants
      type(method_info_t) :: row
      row = method_info(kind)
      method_uses_segments = row%segments
   end function method_uses_segments

   !> The method gives an error estimate with S (the others give −1).
   elemental logical function method_gives_estimate(kind)
      integer, intent(in) :: kind  !! one of the method_* constants
      type(method_info_t) :: row
      row = method_info(kind)
      method_gives_estimate = row%estimate
   end function method_gives_estimate

   !> The method applies to scalar models (`monodromy_trace`); .false. for an unknown code.
   elemental logical function method_takes_scalars(kind)
      integer, intent(in) :: kind  !! one of the method_* constants
      type(method_info_t) :: row
      row = method_info(kind)
      method_takes_scalars = row%scalars
   end function method_takes_scalars

   !> The method applies to systems (hillstab_integrate_system, under the same code).
   elemental logical function method_takes_systems(kind)
      integer, intent(in) :: kind  !! one of the method_* constants
      type(method_info_t) :: row
      row = method_info(kind)
      method_takes_systems = row%systems
   end function method_takes_systems

   !> The method shares work across the β of a chart row (`prepare_batch`, `monodromy_trace_batch`).
   elemental logical function method_batches_rows(kind)
      integer, intent(in) :: kind  !! one of the method_* constants
      type(method_info_t) :: row
      row = method_info(kind)
      method_batches_rows = row%batch_rows
   end function method_batches_rows

   !> The method's cost grows like √(|α| + |β|): scenes keep |α| + |β| ≤ `max_integrated_magnitude`.
   elemental logical function method_cost_grows(kind)
      integer, intent(in) :: kind  !! one of the method_* constants
      type(method_info_t) :: row
      row = method_info(kind)
      method_cost_grows = row%cost_grows
   end function method_cost_grows

   !> Constant pieces of Q the method uses: 2 for formula, n_segments for segments, 0 for
   !> the exact methods (which integrate Q itself).
   elemental integer function method_pieces(method) result(pieces)
      type(method_t), intent(in) :: method  !! method and its settings
      type(method_info_t) :: row
      row = method_info(method%kind)
      pieces = row%pieces
      if (row%segments) pieces = method%n_segments
   end function method_pieces

   !> Monodromy of the damped swing x'' + ε x' + Q x = 0 from that of χ:
   !> M_x = e^{−ε} P M_χ P⁻¹ with P = [[1, 0], [−ε/2, 1]] (x = e^{−ετ/2} χ).
   pure function swing_monodromy(chi, epsilon) result(x)
      type(scaled_matrix_t), intent(in) :: chi  !! monodromy of the chi equation (47)
      real(wp), intent(in) :: epsilon  !! damping epsilon >= 0
      type(scaled_matrix_t) :: x
      real(wp) :: p(2, 2), p_inv(2, 2)
      p = reshape([1.0_wp, -0.5_wp*epsilon, 0.0_wp, 1.0_wp], [2, 2])
      p_inv = reshape([1.0_wp, 0.5_wp*epsilon, 0.0_wp, 1.0_wp], [2, 2])
      x = chi
      x%m = matmul(x%m, p_inv)
      call multiply_matrix(x, p)
      x%log_scale = x%log_scale - epsilon
   end function swing_monodromy

   !> Trace of the one-period monodromy of the χ equation by the chosen method. A model
   !> that does not share rows (`shares_rows`) is taken at the point's β (`at_point`), its
   !> point (α, 0, ε) there; ε is the point's damping (`damping_at`).
   recursive subroutine monodromy_trace(model, point, method, tr, error, stats)
      class(hill_model_t), intent(in) :: model  !! the model of Q
      type(hill_point_t), intent(in) :: point   !! the Hill equation's α, β and damping ε
      type(method_t), intent(in) :: method  !! method and its settings
      type(trace_t), intent(out) :: tr  !! the trace S (S1 of the chi equation when epsilon > 0)
      !> what failed (err_accuracy: tr is the best value); unallocated on success
      type(error_t), allocatable, intent(out) :: error
      type(work_stats_t), intent(out), optional :: stats  !! work done (Q evaluations, steps)
      type(work_stats_t) :: work
      class(hill_model_t), allocatable :: local
      if (.not. model%shares_rows()) then
         call point_alone(model, point%alpha, point%beta, point%epsilon, local, error)
         if (.not. allocated(error)) call monodromy_trace(local, hill_point_t(point%alpha, 0.0_wp, point%epsilon), &
                                                          method, tr, error, stats)
         return
      end if
      call check_point(model, point, error)
      if (allocated(error)) return
      select case (method%kind)
      case (method_formula)
         tr = trace_formula(model, point)
         work = work_stats_t(2, 0, 2)
      case (method_segments)
         if (method%n_segments < 1 .or. method%n_segments > max_segments) then
            call set_error(error, err_invalid_parameter, "n_segments must lie in [1, 100000], got "// &
               integer_text(method%n_segments))
            return
         end if
         if (method%sampling < 1 .or. method%sampling > sampling_count) then
            call set_error(error, err_invalid_parameter, "unknown sampling")
            return
         end if
         tr = trace_segmented(model, point, method%n_segments, method%sampling)
         work = work_stats_t(method%n_segments, 0, method%n_segments)
      case (method_gsl)
         call trace_gsl(model, point, method%tolerance, tr, work, error)
      case (method_rk)
         call trace_rk(model, point, method%tolerance, tr, error, work)
      case (method_auto)
         call trace_auto(model, point, method%tolerance, tr, work, error)
      case (method_magnus4)
         call trace_magnus(model, point, 4, method%tolerance, tr, work, error)
      case (method_magnus6)
         call trace_magnus(model, point, 6, method%tolerance, tr, work, error)
      case default
         call set_error(error, err_invalid_parameter, "method '"//method_name(method%kind)// &
            "' is not available in this build")
      end select
      if (present(stats)) stats = work
   end subroutine monodromy_trace

   !> The model at the point (α, β) of a model that does not share rows (`at_point`), whose
   !> point (α, 0) the methods then take; err_invalid_parameter where β is out of every
   !> model's limits (`check_point`: finite, |β| ≤ 1e15) or the point out of the model's
   !> domain (`alpha_domain`, which then names both axes).
   subroutine point_alone(model, alpha, beta, epsilon, local, error)
      class(hill_model_t), intent(in) :: model  !! the model
      real(wp), intent(in) :: alpha, beta       !! the point
      real(wp), intent(in) :: epsilon           !! its damping, for `check_point`'s message
      class(hill_model_t), allocatable, intent(out) :: local  !! the model at β
      type(error_t), allocatable, intent(out) :: error  !! the refusal
      character(len=24) :: a, b
      ! NaN first, on its own: an ordered comparison of a NaN raises the invalid flag
      if (.not. ieee_is_finite(beta)) then
         call check_point(model, hill_point_t(alpha, beta, epsilon), error)
         return
      end if
      if (abs(beta) > max_magnitude) then
         call check_point(model, hill_point_t(alpha, beta, epsilon), error)
         return
      end if
      call model%at_point(alpha, beta, local)
      if (local%alpha_valid(alpha)) return
      write (a, '(es23.16)') alpha
      write (b, '(es23.16)') beta
      call set_error(error, err_invalid_parameter, model%name()//" model needs "//model%alpha_domain()// &
         ", got alpha = "//trim(adjustl(a))//", beta = "//trim(adjustl(b)))
   end subroutine point_alone

   !> Traces of the points (α, β_j) of one model kind, α and ε, e.g. a chart row. Method
   !> auto shares its meshes and coefficient values across the batch (much faster than
   !> point by point); the other methods go point by point. `failed(j)` marks points that
   !> could not be computed; `error` describes the first of them. A model that does not
   !> share rows (`shares_rows`) takes each point alone, at its β (`at_point`), with its
   !> own damping (`dampings`).
   recursive subroutine monodromy_trace_batch(model, row, betas, method, traces, failed, error, stats, plan, inaccurate, &
                                              need, paper, dampings)
      class(hill_model_t), intent(in) :: model  !! the model
      !> α and ε of the batch (β ignored): ε the row's damping (`point_damping`), which for
      !> a model that does not share rows is the scene's ε alone
      type(hill_point_t), intent(in) :: row
      real(wp), intent(in) :: betas(:)  !! the betas of the batch
      type(method_t), intent(in) :: method  !! method and its settings
      !> S of each beta (where a verdict settled the need: the screening value, its bound as
      !> error estimate)
      type(trace_t), intent(out) :: traces(size(betas))
      logical, intent(out) :: failed(size(betas))  !! true where no value could be computed
      type(error_t), allocatable, intent(out) :: error  !! the first failure; unallocated when none failed
      type(work_stats_t), intent(out), optional :: stats  !! work done over the batch
      type(batch_plan_t), intent(in), optional :: plan  !! from `prepare_batch` for this row
      !> computed, but the tolerance is below the round-off level there (err_accuracy): the
      !> trace is the best double precision allows; not counted in `failed`
      logical, intent(out), optional :: inaccurate(size(betas))
      !> what is needed of the traces (need_nothing … need_trace, default need_trace; only
      !> the exact methods do less than need_trace)
      integer, intent(in), optional :: need
      !> need_verdict: the side of |S| = 2 too (the paper's criterion), when damped
      logical, intent(in), optional :: paper
      !> the damping ε of each point (row%epsilon where the model shares rows)
      real(wp), intent(out), optional :: dampings(size(betas))
      type(work_stats_t) :: work, part
      class(hill_model_t), allocatable :: local
      logical :: one_inaccurate(1)
      logical :: reached(size(betas)), roundoff(size(betas)), settled(size(betas))
      type(error_t), allocatable :: point_error
      type(hill_point_t) :: single
      type(method_t) :: screening
      type(trace_t), allocatable :: rest(:), screened(:)
      logical, allocatable :: rest_failed(:), rest_inaccurate(:)
      integer, allocatable :: open(:)
      integer :: j, wanted
      logical :: paper_side
      real(wp) :: decay
      failed = .false.
      if (present(inaccurate)) inaccurate = .false.
      if (present(dampings)) dampings = row%epsilon
      work = work_stats_t()
      if (.not. model%shares_rows()) then
         ! each point alone: the model at its β, the point (α, 0) there with its damping
         do j = 1, size(betas)
            call point_alone(model, row%alpha, betas(j), row%epsilon, local, point_error)
            if (allocated(point_error)) then
               traces(j) = trace_t()
               failed(j) = .true.
               if (.not. allocated(error)) call move_alloc(point_error, error)
               if (allocated(point_error)) deallocate (point_error)
               cycle
            end if
            single = hill_point_t(row%alpha, 0.0_wp, local%point_damping(row%alpha, row%epsilon))
            if (present(dampings)) dampings(j) = single%epsilon
            call monodromy_trace_batch(local, single, [0.0_wp], method, traces(j:j), failed(j:j), point_error, part, &
                                       inaccurate=one_inaccurate, need=need, paper=paper)
            call add_work(work, part)
            if (present(inaccurate)) inaccurate(j) = one_inaccurate(1)
            if (allocated(point_error)) then
               if (.not. allocated(error)) call move_alloc(point_error, error)
               if (allocated(point_error)) deallocate (point_error)
            end if
         end do
         if (present(stats)) stats = work
         return
      end if
      wanted = need_trace
      if (present(need)) wanted = need
      paper_side = .false.
      if (present(paper)) paper_side = paper
      if (wanted == need_nothing) then
         traces = trace_t()
         if (present(stats)) stats = work
         return
      end if
      if (wanted < need_trace .and. method_is_exact(method%kind)) then
         ! first what the range of q decides, then the screening pass; the points they settle
         ! are done, the others computed in full
         ! (an invalid point settles nothing: the full computation below reports it)
         ! the damping of one period, as the verdicts take it
         decay = period_damping(row%epsilon, model%period())
         call check_batch(model, row%alpha, row%epsilon, betas, point_error)
         if (allocated(point_error)) then
            deallocate (point_error)
            settled = .false.
         else
            call settle_by_bounds(model, row, betas, wanted, traces, settled)
         end if
         if (.not. all(settled)) then
            ! the points left, by index (no packed copies of the traces)
            call unsettled_points(settled, open)
            allocate (screened(size(open)))
            if (method%kind == method_auto) then
               if (present(plan)) then
                  call trace_auto_screen(model, row%alpha, row%epsilon, betas(open), screened, part, &
                                         point_error, plan%auto)
               else
                  call trace_auto_screen(model, row%alpha, row%epsilon, betas(open), screened, part, &
                                         point_error)
               end if
               call add_work(work, part)
               if (.not. allocated(point_error)) then
                  do j = 1, size(open)
                     traces(open(j)) = screened(j)
                     settled(open(j)) = verdict_is_certain(screened(j), decay, method%tolerance, wanted, &
                                                           paper_side)
                  end do
               end if
            else
               screening = method
               screening%tolerance = max(method%tolerance, screen_tolerance)
               single = row
               do j = 1, size(open)
                  single%beta = betas(open(j))
                  call monodromy_trace(model, single, screening, traces(open(j)), point_error, part)
                  call add_work(work, part)
                  if (allocated(point_error)) then
                     deallocate (point_error)
                     cycle
                  end if
                  traces(open(j))%error_estimate = screen_safety*traces(open(j))%error_estimate
                  settled(open(j)) = verdict_is_certain(traces(open(j)), decay, method%tolerance, wanted, &
                                                        paper_side)
               end do
            end if
            if (allocated(point_error)) deallocate (point_error)
         end if
         if (all(settled)) then
            if (present(stats)) stats = work
            return
         end if
         call unsettled_points(settled, open)
         allocate (rest(size(open)), rest_failed(size(open)), rest_inaccurate(size(open)))
         call monodromy_trace_batch(model, row, betas(open), method, rest, rest_failed, error, part, plan, rest_inaccurate)
         call add_work(work, part)
         traces(open) = rest
         failed(open) = rest_failed
         if (present(inaccurate)) inaccurate(open) = rest_inaccurate
         if (present(stats)) stats = work
         return
      end if
      if (method%kind == method_auto) then
         if (present(plan)) then
            call trace_auto_batch(model, row%alpha, row%epsilon, betas, method%tolerance, traces, work, &
               error, plan%auto, reached, roundoff)
         else
            call trace_auto_batch(model, row%alpha, row%epsilon, betas, method%tolerance, traces, work, &
               error, reached=reached, roundoff=roundoff)
         end if
         if (allocated(error)) then
            ! only round-off limited points: their traces are the best values; a point that
            ! failed as well is located below, point by point
            if (error%code == err_accuracy .and. all(reached .or. roundoff)) then
               if (present(inaccurate)) inaccurate = roundoff
               if (present(stats)) stats = work
               return
            end if
         end if
         ! any other batch error (a point out of range, a tolerance not met) is located point by point
         if (.not. allocated(error)) then
            if (present(stats)) stats = work
            return
         end if
         deallocate (error)
      end if
      do j = 1, size(betas)
         single = row
         single%beta = betas(j)
         call monodromy_trace(model, single, method, traces(j), point_error, part)
         call add_work(work, part)
         if (allocated(point_error)) then
            if (point_error%code == err_accuracy) then
               if (present(inaccurate)) inaccurate(j) = .true.
               cycle
            end if
            failed(j) = .true.
            if (.not. allocated(error)) call move_alloc(point_error, error)
         end if
      end do
      if (present(stats)) stats = work
   end subroutine monodromy_trace_batch

   !> The monodromy of the system at (α, β) by `method` (hillstab_integrate_system_magnus,
   !> hillstab_integrate_system_gsl), its estimate at least the rounding the method
   !> accumulates (`system_roundoff_level`: status 1 where the tolerance lies under it).
   subroutine system_monodromy(system, form, alpha, beta, method, nodes, result, error)
      class(hill_system_t), intent(in) :: system   !! the system
      type(system_form_t), intent(in) :: form      !! prepared at the point's ε
      real(wp), intent(in) :: alpha, beta          !! the point
      type(system_method_t), intent(in) :: method  !! method and tolerance
      type(system_nodes_t), intent(inout) :: nodes !! shared along a row (a fresh one for one point)
      type(system_monodromy_t), intent(out) :: result  !! Φ, its scale, error estimate and status
      !> err_integration when no mesh of the ladder meets the tolerance (status_failed);
      !> unallocated otherwise
      type(error_t), allocatable, intent(out) :: error
      select case (method%kind)
      case (method_rk)
         call monodromy_rk(system, form, alpha, beta, method%tolerance, result, error)
      case (method_gsl)
         call system_monodromy_gsl(system, form, alpha, beta, method%tolerance, result, error)
      case (method_magnus4)
         call monodromy_magnus(system, form, alpha, beta, method%tolerance, 4, nodes, result, error)
      case default
         call monodromy_magnus(system, form, alpha, beta, method%tolerance, 6, nodes, result, error)
      end select
      if (allocated(error) .or. result%status == status_failed) return
      result%error_estimate = max(result%error_estimate, system_roundoff_level(method%kind, result, form))
      if (result%status == status_ok .and. result%error_estimate > method%tolerance) result%status = status_roundoff
   end subroutine system_monodromy

   !> The rounding error of Φ̃'s entries relative to max(1, max|Φ̃_ij|) that a method accumulates
   !> over N steps, c ε √N: c = 40 (Magnus 6), 100 (Magnus 4), 10 (rk), and for gsl, which
   !> integrates the whole period without rescaling, 150 (1 + ln max|Φ_ij|/10). The factors
   !> are about twice the largest ratio of the error to ε √N seen against the
   !> extended-precision Taylor reference at tolerances 1e-12 to 1e-14 over 99 random systems
   !> (2–5 DOF, damped, gyroscopic, sine drives, periods 2 and 4, |β| up to 500,
   !> ln max|Φ_ij| up to 110): 18.5, 38.8, 4.3 and 79.
   pure real(wp) function system_roundoff_level(kind, result, form) result(level)
      integer, intent(in) :: kind                     !! the method
      type(system_monodromy_t), intent(in) :: result  !! its monodromy (steps, mesh, Φ̃)
      type(system_form_t), intent(in) :: form         !! the system's form
      real(wp) :: steps, log_norm
      select case (kind)
      case (method_rk)
         steps = result%steps/12.0_wp
         level = 10.0_wp
      case (method_gsl)
         steps = result%steps/13.0_wp
         log_norm = log(max(1.0_wp, maxval(abs(result%phi)))) + result%log_scale
         level = 150.0_wp*(1.0_wp + log_norm/10.0_wp)
      case (method_magnus4)
         steps = result%mesh
         level = 100.0_wp
      case default
         steps = result%mesh
         level = 40.0_wp
      end select
      if (form%half) steps = 2.0_wp*steps
      level = level*epsilon(1.0_wp)*sqrt(max(steps, 1.0_wp))
   end function system_roundoff_level

   !> The period's product kept factored, Φ = F_K ⋯ F_1 (for `factored_exponents`), each factor
   !> well conditioned (∫‖A‖ over it at most 2), by the point's method: the Magnus steps of
   !> the mesh `monodromy` accepted, grouped into chunks, or rk and gsl from the identity over
   !> subintervals at their second pass's tolerance. Where half a period is enough, the
   !> second half's factors are R F_k⁻¹ R, in reverse order.
   subroutine system_factors(system, form, alpha, beta, method, nodes, monodromy, factors, count, error)
      class(hill_system_t), intent(in) :: system      !! the system
      type(system_form_t), intent(in) :: form         !! prepared at the point's ε
      real(wp), intent(in) :: alpha, beta             !! the point
      type(system_method_t), intent(in) :: method     !! method and tolerance
      type(system_nodes_t), intent(inout) :: nodes    !! as for `system_monodromy`
      type(system_monodromy_t), intent(inout) :: monodromy  !! the point's monodromy (its mesh); steps added
      real(wp), allocatable, intent(out) :: factors(:, :, :)  !! F_1 … F_count (2n × 2n × ≥ count)
      integer, intent(out) :: count                   !! the number of factors
      type(error_t), allocatable, intent(out) :: error  !! err_integration when an integration fails
      integer :: pieces
      count = 0
      allocate (factors(form%states, form%states, 16))
      select case (method%kind)
      case (method_rk)
         pieces = factor_pieces(system, form, alpha, beta, nodes)
         call rk_period_factors(system, form, alpha, beta, method%tolerance, pieces, factors, count, monodromy%steps, error)
      case (method_gsl)
         pieces = factor_pieces(system, form, alpha, beta, nodes)
         call gsl_period_factors(system, form, alpha, beta, method%tolerance, pieces, factors, count, monodromy%steps, &
                                 error)
      case (method_magnus4)
         call magnus_period_factors(system, form, alpha, beta, 4, nodes, monodromy, factors, count, error)
      case default
         call magnus_period_factors(system, form, alpha, beta, 6, nodes, monodromy, factors, count, error)
      end select
      if (allocated(error)) return
      call complete_half_factors(form, factors, count)
   end subroutine system_factors
end module hillstab_integrate_monodromy

!> Method `auto`: the one-period trace S to a requested tolerance, as cheaply as
!> possible, for one point or for a batch of points sharing α (a chart row).
!>
!> - Constant coefficient (α = 0): one exact transfer matrix, no error at all.
!> - Otherwise: sixth-order Magnus on the half period [0, 1] (the even symmetry of
!>   Q, Floquet theory) on a mesh that is uniform in a Kepler-type variable ψ,
!>   tan(πτ/2) = √((1 − κ)/(1 + κ)) tan(πψ/2), κ = 1 − (1 − α/π²)^0.35, which
!>   packs steps into the dip of Q at τ = 0 whose width shrinks like √(1 − α/π²).
!>   The step count comes from a calibrated a-priori model; the error is then
!>   measured, not assumed: the same mesh with steps merged in pairs gives the
!>   Richardson estimate |S_N − S_{N/2}|/(2⁶ − 1), and the mesh is refined until
!>   that estimate (times a safety factor) meets the tolerance; the value returned is
!>   then the extrapolated S_N + (S_N − S_{N/2})/(2⁶ − 1), whose error lies below the
!>   estimate even where the error ratio falls somewhat short of 2⁶.
!>
!> Speed comes from the structure of Q: for fixed α, q(τ) = c₀ + c₁ w(τ) with w
!> independent of β (elastic: w = 1/(1 − (α/π²) cos πτ), c₁ = β − π²,
!> c₀ = π² − ε²/4; Mathieu: w = cos πτ, c₁ = −ν, c₀ = β − ε²/4; every model gives its
!> split, w and the inputs of the mesh and the step count through its bindings, hillstab_hill_model).
!> A batch of points shares the mesh and the w values at its Gauss nodes, so each step
!> costs three multiply-adds, a few flops for the Magnus generator and one
!> exponential of a traceless 2×2 matrix, evaluated by a short power series when
!> the step is small against the local oscillation.
!>
!>```fortran
!> real(wp) :: betas(3) = [1.0_wp, 2.0_wp, 3.0_wp]
!> type(trace_t) :: traces(3)
!> call trace_auto_batch(elastic_model_t(), 5.0_wp, 0.0_wp, betas, 1.0e-10_wp, traces, stats, error)
!>```
module hillstab_integrate_auto
   use hillstab_core_kinds, only: wp, pi
   use hillstab_core_error, only: error_t, set_error, err_invalid_parameter, err_integration, err_accuracy
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use hillstab_core_stats, only: work_stats_t
   use hillstab_hill_model, only: hill_model_t, hill_point_t, hill_window_t, check_batch, model_split
   use hillstab_hill_coefficient, only: coefficient_phase
   use hillstab_hill_transfer, only: transfer_functions, step_functions, cos_taylor, sinc_taylor, trace_t, &
      trace_from_scaled, scaled_matrix_t
   use hillstab_integrate_magnus, only: trace_magnus
   use hillstab_integrate_refine, only: roundoff_level, trace_distance, sensitivity_t, coefficient_level, &
      roundoff_safety, coefficient_roundings_c0, coefficient_roundings_c1, cancellation_limit
   implicit none
   private
   public :: trace_auto, trace_auto_batch, auto_initial_steps, auto_mesh_power, fixed_n_trace
   public :: auto_plan_t, auto_prepare, trace_auto_screen, auto_screen_tolerance

   !> Exponent p of the mesh map: κ = 1 − (1 − α/π²)^p (measured best among 0 … 0.7).
   real(wp), parameter :: auto_mesh_power = 0.35_wp
   !> Gauss–Legendre 3-point offsets on [0, 1]: 1/2 ∓ √15/10.
   real(wp), parameter :: gauss3_offset = 0.38729833462074168851792653997823996_wp
   real(wp), parameter :: sqrt15 = 3.87298334620741688517926539978239961_wp
   !> Error estimate (relative to max(1, |S|)) of the exact constant-coefficient trace at α = 0.
   real(wp), parameter :: exact_transfer_error = 4.0_wp*epsilon(1.0_wp)
   !> Safety factor on the Richardson estimate.
   real(wp), parameter :: richardson_safety = 1.0_wp
   !> The tolerance whose a-priori step count the screening pass of a verdict uses
   !> (`trace_auto_screen`).
   real(wp), parameter :: auto_screen_tolerance = 1.0e-6_wp
   !> The fewest steps of the finest screening mesh (its coarsest has a quarter of them).
   integer, parameter :: screen_min_steps = 8
   !> The fewest steps of the a-priori mesh of the Richardson check (its coarse mesh has half
   !> of them): with 4 and 2 steps (tolerance 1e-6, |β − π²| ≲ 1) the pair was far from the
   !> asymptotic regime and the extrapolated S missed the tolerance by up to 1.13×.
   integer, parameter :: check_min_steps = 8
   !> Largest number of Magnus steps on [0, 1].
   integer, parameter :: max_auto_steps = 2**18
   !> Step counts N used by auto: even, ratio ≈ 2^{1/4} (2 round(2^{k/4} 2), from 4 to 2^18), so
   !> that the points of a batch share a few meshes instead of building one each.
   integer, parameter :: ladder(64) = [ &
      4, 6, 8, 10, 12, 14, 16, 20, 22, 26, 32, 38, 46, 54, 64, 76, 90, 108, 128, 152, 182, 216, 256, 304, &
      362, 430, 512, 608, 724, 862, 1024, 1218, 1448, 1722, 2048, 2436, 2896, 3444, 4096, 4870, 5792, 6888, &
      8192, 9742, 11586, 13778, 16384, 19484, 23170, 27554, 32768, 38968, 46340, 55108, 65536, 77936, 92682, &
      110218, 131072, 155872, 185364, 220436, 262144, 262144]
   !> What `lane_traces` computes: S and its round-off level (`roundoff_level` and
   !> `coefficient_level`, their exponentials written out as plain products where the
   !> propagator was never rescaled, the usual case); or S alone (ln|S| left unset below
   !> |S| = e^300 ≈ 1.9e130); or S and its round-off level with ln|S| from the vectorised logarithm
   !> (the screening pass: its logarithms one by one were 2 % of a verdict chart).
   integer, parameter :: lanes_plain = 1, lanes_values = 2, lanes_screen = 3
   !> Lanes propagated together by `lane_traces` (work arrays of this size on the stack).
   integer, parameter :: lane_block = 64
   !> Rescale the propagator when an entry exceeds 2^rescale_exponent.
   integer, parameter :: rescale_exponent = 400

   !> One mesh of the model's window (half a period of an even q, or the period) with the
   !> shape function w at its Gauss nodes.
   type :: mesh_t
      integer :: key = 0                 !! the step count it was asked for (its cache key)
      logical :: half = .true.           !! the window is half a period: S = 2(u v' + u' v)
      integer :: n_steps = 0
      real(wp), allocatable :: h(:)      !! step lengths
      real(wp), allocatable :: w(:, :)   !! w at the three Gauss nodes of each step
   end type mesh_t

   !> The meshes built so far for one (model kind, α) — local to one batch call.
   type :: mesh_cache_t
      integer :: n_meshes = 0
      type(mesh_t) :: meshes(40)
   end type mesh_cache_t

   !> Meshes prepared once for a batch sharing (model, α) — a chart row — and then read
   !> by all threads (`auto_prepare`, `trace_auto_batch(..., plan)`, which must be given
   !> the model the plan was prepared with).
   type :: auto_plan_t
      logical :: prepared = .false.  !! meshes were built (for the model of the batch)
      real(wp) :: alpha = -1.0_wp  !! alpha the meshes were built for (-1: none yet)
      type(mesh_cache_t) :: cache  !! the meshes, by number of steps
   end type auto_plan_t

contains

   !> Build the meshes the points of a batch start with (N₀ and N₀/2 of each β), so
   !> that threads working on parts of the batch share them.
   subroutine auto_prepare(model, alpha, epsilon, betas, tolerance, plan, screen)
      class(hill_model_t), intent(in) :: model  !! the model
      !> alpha and epsilon of the batch, its betas, the target error on S
      real(wp), intent(in) :: alpha, epsilon, betas(:), tolerance
      type(auto_plan_t), intent(out) :: plan  !! the meshes, to pass to trace_auto_batch
      !> the meshes of the screening pass (`trace_auto_screen`) instead
      logical, intent(in), optional :: screen
      real(wp) :: c0, c1, base
      integer :: j, n, index
      logical :: screening
      plan%prepared = .true.
      plan%alpha = alpha
      ! unchecked input: leave the plan empty (the batch reports the error)
      if (.not. (ieee_is_finite(alpha) .and. ieee_is_finite(epsilon) .and. ieee_is_finite(tolerance))) return
      if (.not. all(ieee_is_finite(betas))) return
      if (alpha == 0.0_wp .or. .not. (tolerance > 0.0_wp .and. tolerance < 1.0_wp)) return
      if (.not. model%alpha_valid(alpha)) return
      screening = .false.
      if (present(screen)) screening = screen
      if (screening) then
         base = auto_base_steps(model, alpha, auto_screen_tolerance)
      else
         base = auto_base_steps(model, alpha, tolerance)
      end if
      do j = 1, size(betas)
         call model_split(model, alpha, betas(j), epsilon, c0, c1)
         n = steps_for_point(base, model, c0, c1)
         if (screening) n = max(screen_min_steps, n)
         if (plan%cache%n_meshes + 3 > size(plan%cache%meshes)) exit
         call get_mesh(plan%cache, model, alpha, n, index)
         call get_mesh(plan%cache, model, alpha, n/2, index)
         if (screening) call get_mesh(plan%cache, model, alpha, n/4, index)
      end do
   end subroutine auto_prepare

   !> A-priori number of Magnus-6 steps on [0, 1]: `auto_base_steps` (α, tolerance)
   !> times max(1, (|c₁|/12)^0.4) for large |β − π²| (fitted on β = −50 … 1000), raised
   !> to the next rung of the ladder. The a-posteriori check corrects what this misses.
   pure integer function auto_initial_steps(model, alpha, c0, c1, tolerance) result(n)
      class(hill_model_t), intent(in) :: model  !! the model
      real(wp), intent(in) :: alpha, c0, c1, tolerance  !! alpha; Q's expansion c0, c1 at the point; the target error on S
      n = steps_for_point(auto_base_steps(model, alpha, tolerance), model, c0, c1)
   end function auto_initial_steps

   !> N for one point from the batch's base count: the error of Magnus-6 grows with the
   !> amplitude of q (`model_auto_amplitude`: |β − π²| for the elastic model, about ν for Mathieu) like |c₁|^{2.4}
   !> (N ∝ |c₁|^0.4, fitted on β = −50 … 1000 and measured down to |c₁| = 2), normalised to
   !> |c₁| = 12 (β = −2), where the table was measured.
   pure integer function steps_for_point(base, model, c0, c1) result(n)
      real(wp), intent(in) :: base, c0, c1
      class(hill_model_t), intent(in) :: model
      real(wp) :: amplitude
      amplitude = model%auto_amplitude(c0, c1)
      n = max(check_min_steps, ladder_steps(base*(max(amplitude, 1.0_wp)/12.0_wp)**0.4_wp))
   end function steps_for_point

   !> `steps_for_point` of every point of a batch, without a power per point: rung r of
   !> the ladder serves the amplitudes x ≤ 12 (r/base)^2.5 (base (x/12)^0.4 ≤ r), so the
   !> rungs' thresholds are computed once and each point's rung found among them.
   pure subroutine steps_for_points(base, model, c0s, c1s, ns)
      real(wp), intent(in) :: base, c0s(:), c1s(:)
      class(hill_model_t), intent(in) :: model
      integer, intent(out) :: ns(:)
      real(wp) :: thresholds(size(ladder)), x
      integer :: j, k, first
      ! the rung of the smallest amplitude (x = 1), then the thresholds of the rungs above it
      first = findloc(ladder, ladder_steps(base*(1.0_wp/12.0_wp)**0.4_wp), dim=1)
      thresholds(first:) = 12.0_wp*(real(ladder(first:), wp)/base)**2.5_wp
      do j = 1, size(c0s)
         x = max(model%auto_amplitude(c0s(j), c1s(j)), 1.0_wp)
         k = first
         do while (k < size(ladder))
            if (x <= thresholds(k)) exit
            k = k + 1
         end do
         ns(j) = max(check_min_steps, ladder(k))
      end do
   end subroutine steps_for_points

   !> The α- and tolerance-dependent part of the step count. Measured: the smallest N
   !> meeting 1e-10 against GSL rk8pd at 1e-14 for β ∈ [−2, 12], tabulated against
   !> x = −ln(1 − α/π²) (`model_auto_difficulty`; ln N linear in between, N ∝ (1 − α/π²)^−0.3 beyond), times 0.8
   !> (cheapest on average with the check), times (1e-10/tol)^{1/6} (the order; tolerances
   !> looser than 1e-6 use the 1e-6 count so that the check stays in the asymptotic regime).
   pure real(wp) function auto_base_steps(model, alpha, tolerance) result(base)
      class(hill_model_t), intent(in) :: model
      real(wp), intent(in) :: alpha, tolerance
      real(wp), parameter :: table_x(9) = [0.0_wp, 0.052_wp, 0.227_wp, 0.519_wp, 0.937_wp, 1.666_wp, 2.43_wp, &
                                           3.29_wp, 4.95_wp]
      real(wp), parameter :: table_n(9) = [12.0_wp, 18.0_wp, 26.0_wp, 36.0_wp, 48.0_wp, 62.0_wp, 76.0_wp, &
                                           90.0_wp, 134.0_wp]
      real(wp), parameter :: slope_beyond = 0.3_wp
      real(wp) :: x, log_n
      integer :: i
      x = model%auto_difficulty(alpha)
      if (x >= table_x(size(table_x))) then
         log_n = log(table_n(size(table_n))) + slope_beyond*(x - table_x(size(table_x)))
      else
         i = 1
         do while (table_x(i + 1) < x)
            i = i + 1
         end do
         log_n = log(table_n(i)) + (log(table_n(i + 1)) - log(table_n(i)))*(x - table_x(i))/(table_x(i + 1) - table_x(i))
      end if
      base = 1.0_wp*exp(log_n)*(1.0e-10_wp/min(tolerance, 1.0e-6_wp))**(1.0_wp/6.0_wp)
   end function auto_base_steps

   !> The smallest rung of the ladder ≥ n.
   pure integer function ladder_steps(n) result(rung)
      real(wp), intent(in) :: n
      integer :: low, high, middle
      if (n >= real(ladder(size(ladder)), wp)) then
         rung = ladder(size(ladder))
         return
      end if
      low = 1
      high = size(ladder)
      do while (low < high)
         middle = (low + high)/2
         if (real(ladder(middle), wp) >= n) then
            high = middle
         else
            low = middle + 1
         end if
      end do
      rung = ladder(low)
   end function ladder_steps

   !> Trace S of one point by method auto.
   subroutine trace_auto(model, point, tolerance, tr, stats, error)
      class(hill_model_t), intent(in) :: model  !! the model
      type(hill_point_t), intent(in) :: point   !! α, β, ε
      real(wp), intent(in) :: tolerance   !! target |ΔS|/max(1, |S|)
      type(trace_t), intent(out) :: tr  !! the trace S, or the best value with err_accuracy
      type(work_stats_t), intent(out) :: stats  !! work done: steps, rejected steps, Q evaluations
      type(error_t), allocatable, intent(out) :: error  !! failure description; unallocated on success
      type(trace_t) :: traces(1)
      call trace_auto_batch(model, point%alpha, point%epsilon, [point%beta], tolerance, traces, stats, error)
      tr = traces(1)
   end subroutine trace_auto

   !> Traces of the points (α, β_j, ε), j = 1 … size(betas), sharing meshes and w values.
   !> On error (a parameter out of range, or a tolerance that cannot be met) the
   !> remaining traces are still filled with the best values available.
   subroutine trace_auto_batch(model, alpha, epsilon, betas, tolerance, traces, stats, error, plan, reached, roundoff)
      class(hill_model_t), intent(in) :: model            !! the model
      real(wp), intent(in) :: alpha          !! α (ν for the Mathieu model)
      real(wp), intent(in) :: epsilon        !! damping ε
      real(wp), intent(in) :: betas(:)       !! β values
      real(wp), intent(in) :: tolerance      !! target |ΔS|/max(1, |S|)
      type(trace_t), intent(out) :: traces(:)  !! S of each beta (best values where the tolerance is not met)
      type(work_stats_t), intent(out) :: stats  !! work done over the batch
      !> the first failure (err_accuracy: round-off limited); unallocated on success
      type(error_t), allocatable, intent(out) :: error
      type(auto_plan_t), intent(in), optional :: plan  !! meshes prepared for this (model, α)
      logical, intent(out), optional :: reached(:)     !! the tolerance was met at point j
      !> point j is round-off limited: its trace is the best value, not a failure
      logical, intent(out), optional :: roundoff(:)
      type(mesh_cache_t) :: cache
      real(wp) :: base, estimate, q
      real(wp), allocatable :: c0s(:), c1s(:), phases(:)
      integer, allocatable :: ns(:), n_coarse(:)
      logical, allocatable :: pending(:), converged(:), handed_over(:)
      type(trace_t), allocatable :: fine(:), coarse(:)
      real(wp), allocatable :: floors(:), coarse_floors(:), estimates(:), previous(:)
      real(wp) :: noise
      integer :: j, m, pass
      character(len=160) :: buffer
      stats = work_stats_t()
      if (present(reached)) reached = .false.
      if (present(roundoff)) roundoff = .false.
      if (.not. ieee_is_finite(tolerance)) then
         call set_error(error, err_invalid_parameter, "auto: tolerance must be finite")
         return
      end if
      if (.not. (tolerance > 0.0_wp .and. tolerance < 1.0_wp)) then
         call set_error(error, err_invalid_parameter, "auto: tolerance must lie in (0, 1)")
         return
      end if
      call check_batch(model, alpha, epsilon, betas, error)
      if (allocated(error)) return
      if (present(plan)) then
         if (plan%prepared .and. plan%alpha == alpha) cache = plan%cache
      end if
      base = auto_base_steps(model, alpha, tolerance)
      m = size(betas)
      allocate (c0s(m), c1s(m), ns(m))
      do j = 1, m
         call model_split(model, alpha, betas(j), epsilon, c0s(j), c1s(j))
      end do
      if (alpha == 0.0_wp) then
         do j = 1, m
            ! w is constant at α = 0 (its value then at any τ)
            q = c0s(j) + c1s(j)*shape_at_start(model, alpha)
            traces(j) = constant_trace(q, model%period())
            ! one exact transfer matrix: the rounding of its few operations, and of its
            ! argument 2√|q|, the phase (or the growth) over the period, which moves S by
            ! up to ε·2√|q| relative to max(1, |S|) (1e-13 at q = 3e5)
            traces(j)%error_estimate = exact_transfer_error*(1.0_wp + sqrt(abs(q)))
            if (present(reached)) reached(j) = traces(j)%error_estimate <= tolerance
            if (traces(j)%error_estimate > tolerance) call roundoff_limited(j, traces(j)%error_estimate)
         end do
         stats%n_steps = stats%n_steps + m
         stats%n_evaluations = stats%n_evaluations + m
         return
      end if
      call steps_for_points(base, model, c0s, c1s, ns)
      ! the phase bound of each point, for its round-off level (hillstab_integrate_refine)
      phases = coefficient_phase(c0s, c1s, model%shape_root_mean(alpha))
      ! first pass: S_N and S_{N/2} of all points sharing N together, in lanes
      allocate (fine(m), coarse(m), n_coarse(m), pending(m), floors(m), coarse_floors(m), estimates(m), previous(m), &
                converged(m), handed_over(m))
      converged = .false.
      handed_over = .false.
      previous = huge(1.0_wp)
      call traces_in_lanes(ns, fine, floors)
      n_coarse = ns/2
      call traces_in_lanes(n_coarse, coarse, coarse_floors)
      ! Richardson check; the points that miss the tolerance get a finer N chosen from
      ! their estimate and the order, again computed in lanes, until all pass. Where the
      ! round-off level of S exceeds the tolerance no N can meet it: the best value is
      ! returned with err_accuracy (the difference there is noise, not truncation).
      pending = .true.
      if (present(reached)) reached = .true.
      do pass = 1, 12
         do j = 1, m
            if (.not. pending(j)) cycle
            estimate = richardson_safety*trace_distance(fine(j), coarse(j))/ &
                       ((real(ns(j), wp)/n_coarse(j))**6 - 1.0_wp)
            noise = max(floors(j), coarse_floors(j))
            estimates(j) = max(estimate, noise)
            if (estimate <= tolerance .and. noise <= tolerance) then
               pending(j) = .false.
               converged(j) = .true.
            else if (estimate <= max(tolerance, 2.0_wp*noise) .and. estimate < previous(j)/16.0_wp .and. &
                     ns(j) < max_auto_steps .and. pass < 12) then
               ! round-off limited, but the difference still falls like truncation (2⁶ per
               ! doubling; at least 16 here): refine on, so that the value returned is the
               ! best double precision allows, not the first one whose difference reached
               ! the round-off level
               previous(j) = estimate
               coarse(j) = fine(j)
               coarse_floors(j) = floors(j)
               n_coarse(j) = ns(j)
               ns(j) = ladder_steps(2.0_wp*ns(j))
            else if (estimate <= max(tolerance, 2.0_wp*noise)) then
               ! the difference is at the round-off level: more steps cannot help. After a
               ! refinement that did not reduce the difference like truncation, the coarser
               ! value is kept (the extra steps added rounding noise only)
               if (previous(j) < huge(1.0_wp)) then
                  fine(j) = coarse(j)
                  floors(j) = coarse_floors(j)
               end if
               pending(j) = .false.
               if (present(reached)) reached(j) = .false.
               call roundoff_limited(j, noise)
            else if (ns(j) >= max_auto_steps .or. pass == 12) then
               ! the mapped mesh cannot resolve this point (the dip of Q at α → π² with
               ! |β| ≳ 1e4 needs more than 2^18 of its steps): `hand_over` below
               pending(j) = .false.
               handed_over(j) = .true.
            else
               coarse(j) = fine(j)
               coarse_floors(j) = floors(j)
               n_coarse(j) = ns(j)
               ns(j) = ladder_steps(1.2_wp*ns(j)*min(2.0_wp, max(1.15_wp, (estimate/tolerance)**(1.0_wp/6.0_wp))))
            end if
         end do
         if (.not. any(pending)) exit
         call traces_in_lanes(ns, fine, floors, pending)
      end do
      ! where the check passed, the value returned is the Richardson-extrapolated one,
      ! S_N + (S_N − S_c)/(r⁶ − 1): its error is below the estimate (S_N − S_c)/(r⁶ − 1)
      ! whenever the observed error ratio S_c/S_N exceeds r⁶/2, while S_N's own error is
      ! below it only when the ratio reaches r⁶ (the estimate alone missed the tolerance
      ! by 2–4 % where the ratio came out just below r⁶: Magnus' error is not yet in its
      ! asymptotic regime)
      do j = 1, m
         if (converged(j)) then
            traces(j) = extrapolated(fine(j), coarse(j), (real(ns(j), wp)/n_coarse(j))**6)
         else
            traces(j) = fine(j)
         end if
      end do
      traces%error_estimate = estimates
      do j = 1, m
         if (handed_over(j)) call hand_over(j, estimates(j))
      end do
   contains
      !> Point j, which the mapped mesh could not bring to the tolerance (its estimate
      !> `estimate` there), computed again by adaptive Magnus-6 (`trace_magnus`), whose mesh
      !> follows the local scale of q wherever the dip lies; its value, estimate and status
      !> replace auto's (round-off limited only with a level below `estimate` and below 1),
      !> or, where that fails too, the better estimate's value is kept and the point fails.
      subroutine hand_over(j, estimate)
         integer, intent(in) :: j
         real(wp), intent(in) :: estimate
         type(trace_t) :: adaptive
         type(work_stats_t) :: work
         type(error_t), allocatable :: cause
         call trace_magnus(model, hill_point_t(alpha, betas(j), epsilon), 6, tolerance, adaptive, work, cause)
         stats%n_steps = stats%n_steps + work%n_steps
         stats%n_evaluations = stats%n_evaluations + work%n_evaluations
         if (.not. allocated(cause)) then
            traces(j) = adaptive
            return
         end if
         ! round-off limited: its best value, where its round-off level lies below auto's own
         ! estimate and below 1 (no value beyond)
         if (cause%code == err_accuracy .and. adaptive%error_estimate < min(estimate, 1.0_wp)) then
            traces(j) = adaptive
            if (present(reached)) reached(j) = .false.
            call roundoff_limited(j, adaptive%error_estimate)
            return
         end if
         if (adaptive%error_estimate >= 0.0_wp .and. adaptive%error_estimate < estimate) traces(j) = adaptive
         if (present(reached)) reached(j) = .false.
         write (buffer, '(a,es9.2,a,es9.2,a,es10.3,a)') "auto: estimated error ", traces(j)%error_estimate, &
            " in S exceeds the tolerance ", tolerance, " (at beta = ", betas(j), "; mapped mesh and adaptive Magnus-6)"
         if (.not. allocated(error)) call set_error(error, err_integration, trim(buffer))
      end subroutine hand_over


      !> S on meshes of n(j) steps for the selected points (all without `selected`), in lanes.
      subroutine traces_in_lanes(n, result, floors, selected)
         integer, intent(in) :: n(:)
         type(trace_t), intent(inout) :: result(:)
         real(wp), intent(inout) :: floors(:)
         logical, intent(in), optional :: selected(:)
         call lanes_pass(cache, model, alpha, n, c0s, c1s, phases, result, floors, stats, selected)
      end subroutine traces_in_lanes

      !> Point j is round-off limited at `level`: flagged, and the first such point (unless
      !> an error is already recorded) named in an err_accuracy error. A level of 1 or more
      !> leaves no digit of S: the point fails (err_integration), it is no best value.
      subroutine roundoff_limited(j, level)
         integer, intent(in) :: j
         real(wp), intent(in) :: level
         if (.not. level < 1.0_wp) then
            if (present(reached)) reached(j) = .false.
            write (buffer, '(a,es10.2e3,a,es10.3,a)') "auto: the round-off level of S is ", level, &
               " (at beta = ", betas(j), "): no digit of S is reliable"
            if (.not. allocated(error)) call set_error(error, err_integration, trim(buffer))
            return
         end if
         if (present(roundoff)) roundoff(j) = .true.
         write (buffer, '(a,es9.2,a,es9.2,a,es10.3,a)') "auto: the tolerance ", tolerance, &
            " is below the round-off level ", level, " of S (at beta = ", betas(j), "); best value returned"
         if (.not. allocated(error)) call set_error(error, err_accuracy, trim(buffer))
      end subroutine roundoff_limited

   end subroutine trace_auto_batch


   !> The screening pass of a verdict (`need_verdict`, `need_growth` of
   !> hillstab_integrate_monodromy): S of each point on three meshes, N, N/2 and N/4 steps
   !> with N the a-priori count for `auto_screen_tolerance` (at least `screen_min_steps`),
   !> and the error bound |S_N − S_{N/2}| + |S_{N/2} − S_{N/4}|/8 + the round-off levels
   !> of the three, relative to max(1, |S|), as its `error_estimate`. The first difference
   !> alone bounds the error of S_N whenever halving the steps at least doubles the error,
   !> but on coarse meshes it passes through zero where the errors of S_N and S_{N/2}
   !> happen to be equal (seen on a 300 × 300 chart: 47 points with errors up to 150
   !> times the difference); the second difference is not small there, and over 8 it
   !> bounds the error of S_N whenever each halving at least doubles it. A point whose
   !> |S| lies beyond the bound from a stability threshold has its verdict; the others go
   !> to `trace_auto_batch`. S_N itself is returned (not extrapolated): the bound is a
   !> bound on S_N.
   subroutine trace_auto_screen(model, alpha, epsilon, betas, traces, stats, error, plan)
      class(hill_model_t), intent(in) :: model            !! the model
      real(wp), intent(in) :: alpha          !! α (ν for the Mathieu model)
      real(wp), intent(in) :: epsilon        !! damping ε
      real(wp), intent(in) :: betas(:)       !! β values
      type(trace_t), intent(out) :: traces(:)  !! S_N of each β with its error bound
      type(work_stats_t), intent(out) :: stats  !! work done over the batch
      type(error_t), allocatable, intent(out) :: error  !! a parameter out of range (nothing screened)
      type(auto_plan_t), intent(in), optional :: plan  !! meshes prepared for this (model, α)
      type(mesh_cache_t) :: cache
      real(wp) :: base, q
      real(wp), dimension(size(betas)) :: c0s, c1s, phases, floors
      integer, dimension(size(betas)) :: ns
      type(trace_t) :: coarse(size(betas)), coarser(size(betas))
      integer :: j
      stats = work_stats_t()
      call check_batch(model, alpha, epsilon, betas, error)
      if (allocated(error)) return
      do j = 1, size(betas)
         call model_split(model, alpha, betas(j), epsilon, c0s(j), c1s(j))
      end do
      if (alpha == 0.0_wp) then
         ! one exact transfer matrix (as `trace_auto_batch`)
         do j = 1, size(betas)
            q = c0s(j) + c1s(j)*shape_at_start(model, alpha)
            traces(j) = constant_trace(q, model%period())
            traces(j)%error_estimate = exact_transfer_error*(1.0_wp + sqrt(abs(q)))
         end do
         stats%n_steps = size(betas)
         stats%n_evaluations = size(betas)
         return
      end if
      if (present(plan)) then
         if (plan%prepared .and. plan%alpha == alpha) cache = plan%cache
      end if
      base = auto_base_steps(model, alpha, auto_screen_tolerance)
      call steps_for_points(base, model, c0s, c1s, ns)
      ns = max(screen_min_steps, ns)
      phases = coefficient_phase(c0s, c1s, model%shape_root_mean(alpha))
      call screen_lanes(cache, model, alpha, ns, c0s, c1s, phases, traces, floors, coarse, coarser, stats)
      do j = 1, size(betas)
         ! differences of the order of S itself (values of opposite signs, overflow) count
         ! as 1: such a bound settles nothing, and the sum stays finite
         traces(j)%error_estimate = min(1.0_wp, trace_distance(traces(j), coarse(j))) + &
            min(1.0_wp, trace_distance(coarse(j), coarser(j)))*(max(1.0_wp, abs(coarse(j)%value))/ &
            max(1.0_wp, abs(traces(j)%value)))/8.0_wp + 3.0_wp*floors(j)
      end do
   end subroutine trace_auto_screen

   !> The three passes of `trace_auto_screen`: the points grouped once by their N, each
   !> group propagated (`group_pass`) on the meshes of N (S and its round-off level), N/2
   !> and N/4 steps (S only: their round-off levels are taken as the finest one's, the same
   !> solutions over fewer steps).
   subroutine screen_lanes(cache, model, alpha, n, c0s, c1s, phases, fine, floors, coarse, coarser, stats)
      type(mesh_cache_t), intent(inout) :: cache  !! meshes of this (model, α)
      class(hill_model_t), intent(in) :: model            !! the model
      real(wp), intent(in) :: alpha          !! α of the batch
      integer, intent(in) :: n(:)            !! N of each point
      real(wp), intent(in) :: c0s(:), c1s(:)  !! q = c₀ + c₁ w of each point
      real(wp), intent(in) :: phases(:)      !! phase bound of each point
      type(trace_t), intent(out) :: fine(:), coarse(:), coarser(:)  !! S on N, N/2, N/4 steps
      real(wp), intent(out) :: floors(:)     !! round-off level of each S on N steps
      type(work_stats_t), intent(inout) :: stats  !! steps counted
      logical :: todo(size(n))
      integer :: group(size(n))
      real(wp) :: lane_c0(size(n)), lane_c1(size(n)), lane_phases(size(n)), unused(size(n))
      integer :: i, m
      todo = .true.
      do i = 1, size(n)
         if (.not. todo(i)) cycle
         call next_group(n, i, todo, group, m)
         lane_c0(1:m) = c0s(group(1:m))
         lane_c1(1:m) = c1s(group(1:m))
         lane_phases(1:m) = phases(group(1:m))
         call group_pass(cache, model, alpha, n(i), group(1:m), lane_c0(1:m), lane_c1(1:m), lane_phases(1:m), &
                         fine, floors, stats, lanes_screen)
         call group_pass(cache, model, alpha, n(i)/2, group(1:m), lane_c0(1:m), lane_c1(1:m), lane_phases(1:m), &
                         coarse, unused, stats, lanes_values)
         call group_pass(cache, model, alpha, n(i)/4, group(1:m), lane_c0(1:m), lane_c1(1:m), lane_phases(1:m), &
                         coarser, unused, stats, lanes_values)
      end do
   end subroutine screen_lanes

   !> S on meshes of n(j) steps for the selected points (all without `selected`), grouped by
   !> n and propagated in lanes; the meshes come from (or go into) `cache`.
   subroutine lanes_pass(cache, model, alpha, n, c0s, c1s, phases, result, floors, stats, selected)
      type(mesh_cache_t), intent(inout) :: cache  !! meshes of this (model, α)
      class(hill_model_t), intent(in) :: model            !! the model
      real(wp), intent(in) :: alpha          !! α of the batch
      integer, intent(in) :: n(:)            !! steps of each point
      real(wp), intent(in) :: c0s(:), c1s(:)  !! q = c₀ + c₁ w of each point
      real(wp), intent(in) :: phases(:)      !! phase bound of each point
      type(trace_t), intent(inout) :: result(:)  !! S of the selected points
      real(wp), intent(inout) :: floors(:)   !! their round-off levels
      type(work_stats_t), intent(inout) :: stats  !! steps counted
      logical, intent(in), optional :: selected(:)  !! the points to compute
      logical :: todo(size(n))
      integer :: group(size(n))
      real(wp) :: lane_c0(size(n)), lane_c1(size(n)), lane_phases(size(n))
      integer :: i, m
      todo = .true.
      if (present(selected)) todo = selected
      do i = 1, size(n)
         if (.not. todo(i)) cycle
         call next_group(n, i, todo, group, m)
         lane_c0(1:m) = c0s(group(1:m))
         lane_c1(1:m) = c1s(group(1:m))
         lane_phases(1:m) = phases(group(1:m))
         call group_pass(cache, model, alpha, n(i), group(1:m), lane_c0(1:m), lane_c1(1:m), lane_phases(1:m), &
                         result, floors, stats, lanes_plain)
      end do
   end subroutine lanes_pass

   !> The points k ≥ i still to do whose n(k) equals n(i), in order, taken off `todo`.
   pure subroutine next_group(n, i, todo, group, m_group)
      integer, intent(in) :: n(:)        !! steps of each point
      integer, intent(in) :: i           !! the first point of the group
      logical, intent(inout) :: todo(:)  !! the points not yet in a group
      integer, intent(inout) :: group(:) !! the group's points in group(1:m_group)
      integer, intent(out) :: m_group    !! its size
      integer :: k
      m_group = 0
      do k = i, size(n)
         if (todo(k) .and. n(k) == n(i)) then
            m_group = m_group + 1
            group(m_group) = k
            todo(k) = .false.
         end if
      end do
   end subroutine next_group

   !> The points `group`, their coefficients gathered into contiguous lanes by the caller
   !> (no allocation: this runs for every group of every pass of every batch), on the mesh of
   !> `steps` steps: propagated by `lane_traces` in mode `how`, the results scattered back.
   subroutine group_pass(cache, model, alpha, steps, group, lane_c0, lane_c1, lane_phases, result, floors, stats, how)
      type(mesh_cache_t), intent(inout) :: cache  !! meshes of this (model, α)
      class(hill_model_t), intent(in) :: model            !! the model
      real(wp), intent(in) :: alpha          !! α of the batch
      integer, intent(in) :: steps           !! steps of the mesh
      integer, intent(in) :: group(:)        !! the points
      real(wp), intent(in) :: lane_c0(:), lane_c1(:)  !! q = c₀ + c₁ w of each point of the group
      real(wp), intent(in) :: lane_phases(:)  !! phase bound of each point of the group
      type(trace_t), intent(inout) :: result(:)  !! S of every point (those of the group set)
      real(wp), intent(inout) :: floors(:)   !! round-off levels of every point (likewise)
      type(work_stats_t), intent(inout) :: stats  !! steps counted
      integer, intent(in) :: how             !! what `lane_traces` computes
      real(wp) :: lane_floors(size(group))
      type(trace_t) :: lane_results(size(group))
      integer :: index
      call get_mesh(cache, model, alpha, steps, index)
      call lane_traces(cache%meshes(index), lane_c0, lane_c1, lane_phases, lane_results, lane_floors, how)
      result(group) = lane_results
      floors(group) = lane_floors
      call count_steps(stats, size(group)*steps)
   end subroutine group_pass

   !> Exact trace for constant q over the period 2.
   pure function constant_trace(q, period) result(tr)
      real(wp), intent(in) :: q       !! the constant coefficient
      real(wp), intent(in) :: period  !! the model's period
      type(trace_t) :: tr
      real(wp) :: c, s, log_scale
      call transfer_functions(q*period*period, c, s, log_scale)   ! z = q h², h = the period
      tr = trace_from_scaled(2.0_wp*c, log_scale)
   end function constant_trace


   !> Count n Magnus-6 steps: three values of q each.
   pure subroutine count_steps(stats, n)
      type(work_stats_t), intent(inout) :: stats
      integer, intent(in) :: n
      stats%n_steps = stats%n_steps + n
      stats%n_evaluations = stats%n_evaluations + 3*n
   end subroutine count_steps

   !> w at τ = 0: at α = 0 every model's coefficient is constant, and w is its value
   !> anywhere.
   pure real(wp) function shape_at_start(model, alpha) result(w)
      class(hill_model_t), intent(in) :: model  !! the model
      real(wp), intent(in) :: alpha             !! α
      real(wp) :: values(1)
      call model%shapes(alpha, [0.0_wp], values)
      w = values(1)
   end function shape_at_start

   !> Richardson extrapolation of an order-6 pair: fine + (fine − coarse)/(ratio − 1),
   !> ratio = (N_fine/N_coarse)⁶; through ln|S| when S is large or overflows (and left
   !> alone if the two signs differ).
   pure function extrapolated(fine, coarse, ratio) result(tr)
      type(trace_t), intent(in) :: fine, coarse
      real(wp), intent(in) :: ratio
      type(trace_t) :: tr
      real(wp) :: value, log_abs, correction, relative
      tr = fine
      if (fine%overflow .or. coarse%overflow .or. fine%log_abs > 300.0_wp) then
         if (sign(1.0_wp, fine%value) /= sign(1.0_wp, coarse%value)) return
         log_abs = fine%log_abs + (fine%log_abs - coarse%log_abs)/(ratio - 1.0_wp)
         tr = trace_from_scaled(sign(1.0_wp, fine%value), log_abs)
      else
         correction = (fine%value - coarse%value)/(ratio - 1.0_wp)
         value = fine%value + correction
         if (abs(correction) <= 1.0e-6_wp*abs(fine%value) .and. fine%value /= 0.0_wp) then
            ! ln|S| moves by ln(1 + δ) = δ − δ²/2 + O(δ³): no logarithm per point
            relative = correction/fine%value
            tr%value = value
            tr%log_abs = fine%log_abs + relative*(1.0_wp - 0.5_wp*relative)
         else
            tr = trace_from_scaled(value, 0.0_wp)
         end if
      end if
   end function extrapolated

   !> Index of the mesh with n steps in the cache, building it if needed.
   subroutine get_mesh(cache, model, alpha, n, index)
      type(mesh_cache_t), intent(inout) :: cache
      class(hill_model_t), intent(in) :: model
      integer, intent(in) :: n
      real(wp), intent(in) :: alpha
      integer, intent(out) :: index
      integer :: i
      do i = 1, cache%n_meshes
         if (cache%meshes(i)%key == n) then
            index = i
            return
         end if
      end do
      if (cache%n_meshes == size(cache%meshes)) then
         index = size(cache%meshes)          ! full: reuse the last slot
      else
         cache%n_meshes = cache%n_meshes + 1
         index = cache%n_meshes
      end if
      call build_mesh(model, alpha, n, cache%meshes(index))
   end subroutine get_mesh

   !> τ(ψ) of the Kepler-type map on [0, 1]: tan(πτ/2) = √((1 − κ)/(1 + κ)) tan(πψ/2).
   pure real(wp) function mapped_time(psi, kappa)
      real(wp), intent(in) :: psi, kappa
      mapped_time = 2.0_wp/pi*atan2(sqrt(1.0_wp - kappa)*sin(0.5_wp*pi*psi), sqrt(1.0_wp + kappa)*cos(0.5_wp*pi*psi))
   end function mapped_time

   !> Mesh of the model's window with w at the Gauss nodes, n steps per unit of τ: on [0, 1]
   !> (half a period of a q even about 0, no jump) n steps uniform in ψ of the Kepler-type
   !> map; on any other window uniform steps in τ on each piece between the jumps of q (an
   !> even number on each piece).
   pure subroutine build_mesh(model, alpha, n, mesh)
      class(hill_model_t), intent(in) :: model
      integer, intent(in) :: n
      real(wp), intent(in) :: alpha
      type(mesh_t), intent(out) :: mesh
      ! the sines at the nodes (3 n) and the mesh points' X, Y and τ (n each): one allocation
      ! (an allocation costs about as much as a mesh step)
      real(wp), allocatable :: work(:)
      type(hill_window_t) :: window
      mesh%key = n
      window = model%window(alpha)
      mesh%half = window%half
      if (.not. (window%start == 0.0_wp .and. window%length == 1.0_wp .and. window%half .and. &
                 window%n_breaks == 0)) then
         call build_piece_mesh(model, alpha, window, n, mesh)
         return
      end if
      mesh%n_steps = n
      allocate (mesh%h(n), mesh%w(3, n), work(6*n))
      call mesh_points(n, model%mesh_kappa(alpha, auto_mesh_power), mesh%h, work(1:3*n), &
                       work(3*n + 1:4*n), work(4*n + 1:5*n), work(5*n + 1:6*n))
      call model%shapes_from_half_sines(alpha, 3*n, work(1:3*n), mesh%w)
   end subroutine build_mesh

   !> `build_mesh` on a general window: each piece [a, b] between the window's ends and
   !> jumps gets 2 round(n (b − a)/2) ≥ 2 equal steps (n steps per unit of τ, as on the
   !> half period [0, 1]), w at their Gauss nodes from the model's `shapes`.
   pure subroutine build_piece_mesh(model, alpha, window, n, mesh)
      class(hill_model_t), intent(in) :: model
      real(wp), intent(in) :: alpha
      type(hill_window_t), intent(in) :: window
      integer, intent(in) :: n
      type(mesh_t), intent(inout) :: mesh
      real(wp), parameter :: nodes(3) = [0.5_wp - gauss3_offset, 0.5_wp, 0.5_wp + gauss3_offset]
      real(wp) :: edges(size(window%breaks) + 2), h
      real(wp), allocatable :: taus(:, :), w(:)
      integer :: counts(size(window%breaks) + 1), k, i, first, n_pieces
      n_pieces = window%n_breaks + 1
      edges(1) = window%start
      edges(2:n_pieces) = window%breaks(1:window%n_breaks)
      edges(n_pieces + 1) = window%start + window%length
      do k = 1, n_pieces
         counts(k) = max(2, 2*nint(0.5_wp*n*(edges(k + 1) - edges(k))))
      end do
      mesh%n_steps = sum(counts(1:n_pieces))
      allocate (mesh%h(mesh%n_steps), mesh%w(3, mesh%n_steps), taus(3, mesh%n_steps))
      first = 0
      do k = 1, n_pieces
         h = (edges(k + 1) - edges(k))/counts(k)
         do i = 1, counts(k)
            mesh%h(first + i) = h
            taus(:, first + i) = edges(k) + (real(i - 1, wp) + nodes)*h
         end do
         first = first + counts(k)
      end do
      allocate (w(3*mesh%n_steps))
      call model%shapes(alpha, reshape(taus, [3*mesh%n_steps]), w)
      mesh%w = reshape(w, [3, mesh%n_steps])
   end subroutine build_piece_mesh

   !> The step lengths h and the sines sin(πτ/2) at the Gauss nodes (`half_sin`) of
   !> `build_mesh`'s mesh for the map's κ; xs, ys, ts are work space.
   pure subroutine mesh_points(n, kappa, h, half_sin, xs, ys, ts)
      integer, intent(in) :: n
      real(wp), intent(in) :: kappa
      real(wp), intent(out) :: h(n), half_sin(3, n), xs(n), ys(n), ts(n)
      real(wp), parameter :: nodes(3) = [0.5_wp - gauss3_offset, 0.5_wp, 0.5_wp + gauss3_offset]
      real(wp) :: sa, sb, t0, cs, sn, cr, sr, x, sin0, cos0, b, sb_k, cb_k
      integer :: i, j
      ! the map tan(πτ/2) = √((1 − κ)/(1 + κ)) tan(πψ/2) as a point (X, Y) = (√(1+κ) cos, √(1−κ) sin)(πψ/2)
      ! turning by π/(2n) per step (exact cos/sin every 32 steps against drift); then
      ! sin(πτ/2) = Y/R, cos(πτ/2) = X/R at the mesh points and, at the Gauss nodes
      ! τ = t0 + c h, the angle-sum formula with the small angle πch/2 (Taylor); w from
      ! those sines (`model_shapes_from_half_sines`). The points first, then their angles
      ! in a loop of its own, which the compiler vectorises (atan2 four at a time: it was
      ! 3 % of a full chart one by one)
      sa = sqrt(1.0_wp - kappa)
      sb = sqrt(1.0_wp + kappa)
      cr = cos(0.5_wp*pi/n)
      sr = sin(0.5_wp*pi/n)
      cs = 1.0_wp; sn = 0.0_wp
      do i = 1, n
         if (iand(i, 31) == 0) then
            cs = cos(0.5_wp*pi*real(i, wp)/n)
            sn = sin(0.5_wp*pi*real(i, wp)/n)
         else
            x = cs*cr - sn*sr
            sn = sn*cr + cs*sr
            cs = x
         end if
         xs(i) = sb*cs
         ys(i) = sa*sn
      end do
      do i = 1, n
         ts(i) = 2.0_wp/pi*atan2(ys(i), xs(i))
      end do
      ts(n) = 1.0_wp
      t0 = 0.0_wp
      sin0 = 0.0_wp; cos0 = 1.0_wp
      do i = 1, n
         h(i) = ts(i) - t0
         do j = 1, 3
            b = 0.5_wp*pi*nodes(j)*h(i)
            call small_angle(b, sb_k, cb_k)
            half_sin(j, i) = sin0*cb_k + cos0*sb_k        ! sin(πτ/2) at the node
         end do
         t0 = ts(i)
         if (i == n) exit
         x = sqrt(xs(i)*xs(i) + ys(i)*ys(i))
         sin0 = ys(i)/x; cos0 = xs(i)/x
      end do
   end subroutine mesh_points

   !> sin b and cos b for 0 ≤ b ≤ π/4: below 0.3 the Taylor polynomials of degree 7 in b²
   !> (those of `cos_sinc_taylor`, to b^17 and b^16, its Horner loop written out here: the
   !> mesh builder calls this at every Gauss node, and through the call the chart rows took
   !> 10 % more instructions), else the intrinsics.
   elemental subroutine small_angle(b, sin_b, cos_b)
      real(wp), intent(in) :: b
      real(wp), intent(out) :: sin_b, cos_b
      real(wp) :: z, sinc_b
      integer :: k
      if (b > 0.3_wp) then
         sin_b = sin(b)
         cos_b = cos(b)
         return
      end if
      z = b*b
      cos_b = cos_taylor(7)
      sinc_b = sinc_taylor(7)
      do k = 6, 0, -1
         cos_b = cos_taylor(k) + z*cos_b
         sinc_b = sinc_taylor(k) + z*sinc_b
      end do
      sin_b = b*sinc_b
   end subroutine small_angle

   !> Traces of several points on one mesh, propagated together: the points are the
   !> lanes of structure-of-arrays loops that the compiler vectorises (same mesh, same
   !> control flow; a step where some lane leaves the polynomial range of the
   !> exponential is done lane by lane), in blocks of `lane_block` lanes whose work
   !> arrays live on the stack (arrays sized by the call would be allocated on the heap,
   !> about twenty times a call).
   pure subroutine lane_traces(mesh, c0, c1, phases, traces, floors, mode)
      type(mesh_t), intent(in) :: mesh
      real(wp), intent(in) :: c0(:), c1(:)
      real(wp), intent(in) :: phases(:)  !! phase bound of each lane (`coefficient_phase`)
      type(trace_t), intent(out) :: traces(size(c0))
      real(wp), intent(out) :: floors(size(c0))  !! round-off level of each S, relative to max(1, |S|)
      !> lanes_plain (default: S and its round-off level), lanes_values (S only: floors 0,
      !> and ln|S| left unset below |S| = e^300 where the propagator was never rescaled) or
      !> lanes_screen (S and its round-off level, ln|S| from the vectorised logarithm)
      integer, intent(in), optional :: mode
      integer :: first, last, how
      how = lanes_plain
      if (present(mode)) how = mode
      do first = 1, size(c0), lane_block
         last = min(size(c0), first + lane_block - 1)
         call lane_block_traces(mesh, c0(first:last), c1(first:last), phases(first:last), traces(first:last), &
                                floors(first:last), how)
      end do
   end subroutine lane_traces

   !> `lane_traces` of at most `lane_block` lanes.
   pure subroutine lane_block_traces(mesh, c0, c1, phases, traces, floors, how)
      type(mesh_t), intent(in) :: mesh
      real(wp), intent(in) :: c0(:), c1(:)
      real(wp), intent(in) :: phases(:)  !! phase bound of each lane (`coefficient_phase`)
      type(trace_t), intent(out) :: traces(size(c0))
      real(wp), intent(out) :: floors(size(c0))  !! round-off level of each S, relative to max(1, |S|)
      integer, intent(in) :: how  !! lanes_plain, lanes_values or lanes_screen
      real(wp), parameter :: c_d2 = -sqrt15/3.0_wp, c_d3 = -10.0_wp/3.0_wp, c_60 = 1.0_wp/30.0_wp
      real(wp), parameter :: c_240 = 1.0_wp/240.0_wp, c_120 = 1.0_wp/120.0_wp, c_12 = 1.0_wp/12.0_wp
      real(wp), dimension(lane_block) :: p11, p12, p21, p22, log_scale, ga, gb, gc, z, log_peak, peak, cs, sn
      ! the integrals of `sensitivity_t` (hillstab_integrate_refine), in units of e^{2 log_scale}·2^512
      ! (the propagator is rescaled only every eighth step, so its entries may pass 2^400; their
      ! squares times 2^-512 stay in range)
      real(wp), dimension(lane_block) :: su2, sv2, su2w, sv2w, su2a, sv2a
      ! and over a whole period (no symmetry) the cross terms ∫uv, ∫|uv|, ∫uv c₁w, ∫|uv c₁w|
      real(wp), dimension(lane_block) :: suv, suv_abs, suvw, suva
      real(wp), parameter :: square_unit = 2.0_wp**(-256)
      real(wp) :: z_max, uu, vv, sw, level, values_limit
      real(wp) :: h, w1, w2, w3, q1, q2, q3, d2, d3, x3, y1, y2, y3, ls, e11, e12, e21, e22, a, b, big
      real(wp) :: big_max, big_min, root_n, size_s, m12, m21, d0, d1, size0, size1
      real(wp), dimension(lane_block) :: s_lane, log_abs
      logical :: special(lane_block)
      integer :: i, l, k, shift, nl
      logical :: rescaled(lane_block)
      nl = size(c0)
      rescaled = .false.
      p11 = 1.0_wp; p12 = 0.0_wp; p21 = 0.0_wp; p22 = 1.0_wp
      log_scale = 0.0_wp
      log_peak = 0.0_wp
      peak = 2.0_wp
      su2 = 0.0_wp; sv2 = 0.0_wp; su2w = 0.0_wp; sv2w = 0.0_wp; su2a = 0.0_wp; sv2a = 0.0_wp
      suv = 0.0_wp; suv_abs = 0.0_wp; suvw = 0.0_wp; suva = 0.0_wp
      do i = 1, mesh%n_steps
         h = mesh%h(i)
         w1 = mesh%w(1, i); w2 = mesh%w(2, i); w3 = mesh%w(3, i)
         ! sixth-order Gauss–Legendre Magnus generators Ω = [[ga, gb], [gc, −ga]] of all lanes:
         ! `magnus6_generator` of hillstab_integrate_magnus (Blanes, Casas, Oteo, Ros, Phys. Rep. 470 (2009) §5)
         ! written out in components (α₂, α₃ have only a lower-left entry) so that the loop vectorises
         z_max = 0.0_wp
         do l = 1, nl
            q1 = c0(l) + c1(l)*w1
            q2 = c0(l) + c1(l)*w2
            q3 = c0(l) + c1(l)*w3
            d2 = c_d2*h*(q3 - q1)
            d3 = c_d3*h*((q3 - q2) + (q1 - q2))
            x3 = 20.0_wp*h*q2 - d3
            y1 = -c_60*h*d3
            y2 = c_60*h*h*d2
            y3 = d2 + c_60*h*h*q2*d2
            ga(l) = c_240*(-20.0_wp*h*y3 - x3*y2)
            gb(l) = h + c_120*(h*d2*y2 + 20.0_wp*h*y1)
            gc(l) = -h*q2 + c_12*d3 + c_120*(x3*y1 - h*d2*y3)
            z(l) = -(ga(l)*ga(l) + gb(l)*gc(l))
            z_max = max(z_max, abs(z(l)))   ! in the loop: a vectorised reduction (maxval is not)
         end do
         ! C, S of `cos_sinc_taylor` (hillstab_hill_transfer), its Horner loop written out here
         ! with its coefficients so that the loop over the lanes vectorises (through a call,
         ! even one per step for all lanes, the chart rows took 17 % to 33 % more instructions)
         if (z_max <= 0.02_wp) then
            ! the usual case (steps short against the local oscillation): degree 5 is enough
            ! (truncation below 1.3e-19)
            do l = 1, nl
               cs(l) = cos_taylor(5)
               sn(l) = sinc_taylor(5)
               do k = 4, 0, -1
                  cs(l) = cos_taylor(k) + z(l)*cs(l)
                  sn(l) = sinc_taylor(k) + z(l)*sn(l)
               end do
            end do
         else if (z_max <= 0.5_wp) then
            do l = 1, nl
               cs(l) = cos_taylor(10)
               sn(l) = sinc_taylor(10)
               do k = 9, 0, -1
                  cs(l) = cos_taylor(k) + z(l)*cs(l)
                  sn(l) = sinc_taylor(k) + z(l)*sn(l)
               end do
            end do
         else if (z_max <= 8.0_wp) then
            ! long steps (the coarse meshes of a verdict's screening pass): degree 16,
            ! truncation below 2e-21 at |z| = 8, still in vectorised lanes
            do l = 1, nl
               cs(l) = cos_taylor(16)
               sn(l) = sinc_taylor(16)
               do k = 15, 0, -1
                  cs(l) = cos_taylor(k) + z(l)*cs(l)
                  sn(l) = sinc_taylor(k) + z(l)*sn(l)
               end do
            end do
         else
            do l = 1, nl
               call step_functions(z(l), cs(l), sn(l), ls)
               log_scale(l) = log_scale(l) + ls
            end do
         end if
         if (how == lanes_values) then
            ! S only: the propagator, without the sensitivity integrals
            do l = 1, nl
               e11 = cs(l) + sn(l)*ga(l); e12 = sn(l)*gb(l)
               e21 = sn(l)*gc(l); e22 = cs(l) - sn(l)*ga(l)
               a = p11(l); b = p21(l)
               p11(l) = e11*a + e12*b
               p21(l) = e21*a + e22*b
               a = p12(l); b = p22(l)
               p12(l) = e11*a + e12*b
               p22(l) = e21*a + e22*b
            end do
         else
         do l = 1, nl
            e11 = cs(l) + sn(l)*ga(l); e12 = sn(l)*gb(l)
            e21 = sn(l)*gc(l); e22 = cs(l) - sn(l)*ga(l)
            a = p11(l); b = p21(l)
            p11(l) = e11*a + e12*b
            p21(l) = e21*a + e22*b
            a = p12(l); b = p22(l)
            p12(l) = e11*a + e12*b
            p22(l) = e21*a + e22*b
            ! the sensitivity integrals ∫u², ∫v², ∫u² c₁w, … (rectangle rule at the step end)
            uu = h*(square_unit*p11(l))**2
            vv = h*(square_unit*p12(l))**2
            sw = c1(l)*w2
            su2(l) = su2(l) + uu; sv2(l) = sv2(l) + vv
            su2w(l) = su2w(l) + uu*sw; sv2w(l) = sv2w(l) + vv*sw
            su2a(l) = su2a(l) + uu*abs(sw); sv2a(l) = sv2a(l) + vv*abs(sw)
         end do
         if (.not. mesh%half) then
            do l = 1, nl
               uu = h*(square_unit*p11(l))*(square_unit*p12(l))
               sw = c1(l)*w2
               suv(l) = suv(l) + uu; suv_abs(l) = suv_abs(l) + abs(uu)
               suvw(l) = suvw(l) + uu*sw; suva(l) = suva(l) + abs(uu*sw)
            end do
         end if
         end if
         if (iand(i, 7) == 0 .or. i == mesh%n_steps) then
            ! conditioning of the propagator, invariant under rescaling x' against x:
            ! min over diagonal D of ‖D Φ D⁻¹‖²_F = a² + d² + 2|b c| (kept at the current
            ! scale; folded into log_peak only when the scale changes, to keep log out of the loop);
            ! the largest and smallest entries, so that the lane-by-lane rescaling runs only
            ! where some lane needs it (all of this in vectorised loops)
            big_max = 0.0_wp
            big_min = huge(1.0_wp)
            do l = 1, nl
               peak(l) = max(peak(l), p11(l)**2 + p22(l)**2 + 2.0_wp*abs(p12(l)*p21(l)))
               big = max(abs(p11(l)), abs(p12(l)), abs(p21(l)), abs(p22(l)))
               big_max = max(big_max, big)
               big_min = min(big_min, big)
            end do
            if (big_max > 2.0_wp**rescale_exponent .or. big_min < 2.0_wp**(-rescale_exponent)) then
            do l = 1, nl
               big = max(abs(p11(l)), abs(p12(l)), abs(p21(l)), abs(p22(l)))
               if (big > 2.0_wp**rescale_exponent .or. big < 2.0_wp**(-rescale_exponent)) then
                  rescaled(l) = .true.
                  log_peak(l) = max(log_peak(l), log(peak(l)) + 2.0_wp*log_scale(l))
                  peak(l) = 0.0_wp
                  shift = exponent(big)
                  p11(l) = scale(p11(l), -shift); p12(l) = scale(p12(l), -shift)
                  p21(l) = scale(p21(l), -shift); p22(l) = scale(p22(l), -shift)
                  su2(l) = scale(su2(l), -2*shift); sv2(l) = scale(sv2(l), -2*shift)
                  su2w(l) = scale(su2w(l), -2*shift); sv2w(l) = scale(sv2w(l), -2*shift)
                  su2a(l) = scale(su2a(l), -2*shift); sv2a(l) = scale(sv2a(l), -2*shift)
                  suv(l) = scale(suv(l), -2*shift); suv_abs(l) = scale(suv_abs(l), -2*shift)
                  suvw(l) = scale(suvw(l), -2*shift); suva(l) = scale(suva(l), -2*shift)
                  log_scale(l) = log_scale(l) + shift*log(2.0_wp)
               end if
            end do
            end if
         end if
      end do
      ! S of every lane, and, where the propagator was never rescaled (the usual case), its
      ! round-off level (`roundoff_level` and `coefficient_level` with their exponentials
      ! written out: log_scale = 0, log_peak = ln max(1, peak), the integrals in units of
      ! 2^-512), all in loops over the lanes that the compiler vectorises; the other lanes
      ! (`special`) one by one through the logarithms (`lane_result`); with S alone
      ! (lanes_values), also every lane beyond e^300 ≈ 1.9e130, where `trace_distance`
      ! compares logarithms (left unset, they made such points' screen bound huge)
      values_limit = merge(1.0e130_wp, 1.0e300_wp, how == lanes_values)
      if (mesh%half) then
         do l = 1, nl
            s_lane(l) = 2.0_wp*(p11(l)*p22(l) + p21(l)*p12(l))
            special(l) = rescaled(l) .or. log_scale(l) /= 0.0_wp .or. .not. abs(s_lane(l)) < values_limit
         end do
      else
         ! the whole period: S = tr Φ
         do l = 1, nl
            s_lane(l) = p11(l) + p22(l)
            special(l) = rescaled(l) .or. log_scale(l) /= 0.0_wp .or. .not. abs(s_lane(l)) < values_limit
         end do
      end if
      if (how == lanes_values) then
         do l = 1, nl
            floors(l) = 0.0_wp
         end do
      else if (.not. mesh%half) then
         ! the level of `coefficient_level` over the whole period (M = Φ, no factor 2, the
         ! cross terms of u v), and `roundoff_level`'s
         root_n = sqrt(real(max(mesh%n_steps, 1), wp))
         do l = 1, nl
            size_s = max(1.0_wp, abs(s_lane(l)))
            m21 = p21(l)
            m12 = p12(l)
            x3 = p22(l) - p11(l)
            d0 = abs(c0(l))*abs(m21*sv2(l) - m12*su2(l) - x3*suv(l))
            size0 = abs(c0(l))*(abs(m21)*sv2(l) + abs(m12)*su2(l) + abs(x3)*suv_abs(l))
            d1 = abs(m21*sv2w(l) - m12*su2w(l) - x3*suvw(l))
            size1 = abs(m21)*sv2a(l) + abs(m12)*su2a(l) + abs(x3)*suva(l)
            level = merge(coefficient_roundings_c0*d0, 0.0_wp, d0 > cancellation_limit*size0) + &
                    merge(coefficient_roundings_c1*d1, 0.0_wp, d1 > cancellation_limit*size1)
            special(l) = special(l) .or. .not. level < 2.0_wp**400
            floors(l) = roundoff_safety*epsilon(1.0_wp)*root_n*max(1.0_wp, peak(l))/size_s + &
                        2.0_wp*epsilon(1.0_wp)*phases(l) + epsilon(1.0_wp)*(level*2.0_wp**512)/size_s
         end do
      else
         root_n = sqrt(real(max(mesh%n_steps, 1), wp))
         do l = 1, nl
            size_s = max(1.0_wp, abs(s_lane(l)))
            m21 = 2.0_wp*p11(l)*p21(l)
            m12 = 2.0_wp*p12(l)*p22(l)
            d0 = 2.0_wp*abs(c0(l))*abs(m21*sv2(l) - m12*su2(l))
            size0 = 2.0_wp*abs(c0(l))*(abs(m21)*sv2(l) + abs(m12)*su2(l))
            d1 = 2.0_wp*abs(m21*sv2w(l) - m12*su2w(l))
            size1 = 2.0_wp*(abs(m21)*sv2a(l) + abs(m12)*su2a(l))
            level = merge(coefficient_roundings_c0*d0, 0.0_wp, d0 > cancellation_limit*size0) + &
                    merge(coefficient_roundings_c1*d1, 0.0_wp, d1 > cancellation_limit*size1)
            ! beyond 2^400 the integrals times 2^512 may overflow: those lanes go the long way
            special(l) = special(l) .or. .not. level < 2.0_wp**400
            floors(l) = roundoff_safety*epsilon(1.0_wp)*root_n*max(1.0_wp, peak(l))/size_s + &
                        2.0_wp*epsilon(1.0_wp)*phases(l) + epsilon(1.0_wp)*(level*2.0_wp**512)/size_s
         end do
      end if
      if (how == lanes_screen) then
         ! ln|S| of every lane in a loop of its own, which the compiler vectorises (the
         ! logarithms four at a time, within a few ulp of the scalar one; one by one they were
         ! 2 % of a verdict chart); S = 0 has ln|S| = −huge, as in `trace_from_scaled`
         do l = 1, nl
            log_abs(l) = log(max(abs(s_lane(l)), tiny(1.0_wp)))
         end do
      end if
      do l = 1, nl
         if (special(l)) then
            call lane_result(p11(l), p12(l), p21(l), p22(l), log_scale(l), log_peak(l), peak(l), &
               sensitivity_t(2.0_wp*log_scale(l) + 512.0_wp*log(2.0_wp), su2(l), sv2(l), su2w(l), sv2w(l), &
               su2a(l), sv2a(l), suv(l), suv_abs(l), suvw(l), suva(l)), c0(l), mesh%n_steps, phases(l), traces(l), &
               floors(l), mesh%half)
            if (how == lanes_values) floors(l) = 0.0_wp
         else if (how == lanes_values) then
            ! ln|S| is left unset (below 1.9e130 nothing reads it)
            traces(l)%value = s_lane(l)
            traces(l)%overflow = .false.
         else if (how == lanes_screen) then
            traces(l)%value = s_lane(l)
            traces(l)%overflow = .false.
            traces(l)%log_abs = merge(log_abs(l), -huge(1.0_wp), s_lane(l) /= 0.0_wp)
         else
            traces(l) = trace_from_scaled(s_lane(l), 0.0_wp)
         end if
      end do
   end subroutine lane_block_traces

   !> S of one lane from its propagator Φ = [[p11, p12], [p21, p22]]·e^{log_scale} over the
   !> window (half a period: S = 2(u v' + u' v); the period: S = tr Φ) and its round-off
   !> level (`roundoff_level`, `coefficient_level`).
   pure subroutine lane_result(p11, p12, p21, p22, log_scale, log_peak, peak, sensitivity, c0, n_steps, phase, &
                               trace, floor, half)
      real(wp), intent(in) :: p11, p12, p21, p22, log_scale, peak, c0, phase
      real(wp), intent(in) :: log_peak  !! ln of the largest condition before the last rescaling
      type(sensitivity_t), intent(in) :: sensitivity  !! the integrals, in units of e^{2 log_scale}·2^512
      integer, intent(in) :: n_steps
      type(trace_t), intent(out) :: trace
      real(wp), intent(out) :: floor
      logical, intent(in) :: half  !! the window is half a period of an even q
      type(scaled_matrix_t) :: monodromy
      real(wp) :: peak_log
      if (.not. half) then
         ! the whole period: M = Φ
         trace = trace_from_scaled(p11 + p22, log_scale)
         peak_log = log_peak
         if (peak > 0.0_wp) peak_log = max(log_peak, log(peak) + 2.0_wp*log_scale)
         floor = roundoff_level(peak_log, trace%log_abs, n_steps, phase)
         monodromy%m = reshape([p11, p21, p12, p22], [2, 2])
         monodromy%log_scale = log_scale
         floor = floor + coefficient_level(sensitivity, c0, monodromy, trace%log_abs, half=.false.)
         return
      end if
      ! S = 2(u v' + u' v) from Φ(1) = [[u, v], [u', v']] (Floquet theory)
      trace = trace_from_scaled(2.0_wp*(p11*p22 + p21*p12), 2.0_wp*log_scale)
      peak_log = log_peak
      if (peak > 0.0_wp) peak_log = max(log_peak, log(peak) + 2.0_wp*log_scale)
      floor = roundoff_level(peak_log, trace%log_abs, n_steps, phase)
      ! the rounding of q itself, through the sensitivity of S to its constants; the corners
      ! of M = monodromy_from_half_period (its diagonal is not used), element by element,
      ! not through reshape, a library call per point
      monodromy%m(1, 1) = 0.0_wp
      monodromy%m(2, 1) = 2.0_wp*p11*p21
      monodromy%m(1, 2) = 2.0_wp*p12*p22
      monodromy%m(2, 2) = 0.0_wp
      monodromy%log_scale = 2.0_wp*log_scale
      floor = floor + coefficient_level(sensitivity, c0, monodromy, trace%log_abs)
   end subroutine lane_result

   !> S by Magnus-6 on the auto mesh with exactly n steps on [0, 1] (no error control;
   !> for calibration, tests and benchmarks). Undamped β (ε = 0).
   function fixed_n_trace(model, alpha, beta, n) result(s)
      class(hill_model_t), intent(in) :: model  !! the model
      integer, intent(in) :: n  !! number of Magnus-6 steps on [0, 1]
      real(wp), intent(in) :: alpha, beta  !! the point (alpha, beta)
      real(wp) :: s
      type(mesh_t) :: mesh
      type(trace_t) :: tr(1)
      real(wp) :: c0, c1, floor(1)
      call model_split(model, alpha, beta, 0.0_wp, c0, c1)
      call build_mesh(model, alpha, n, mesh)
      call lane_traces(mesh, [c0], [c1], [coefficient_phase(c0, c1, model%shape_root_mean(alpha))], tr, floor)
      s = tr(1)%value
   end function fixed_n_trace
end module hillstab_integrate_auto

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
!> split, w and the inputs of the mesh and the step count through its bindings, hillstab_hill_model;
!> a model whose q = c₀ + c₁ w + v has an offset v independent of β gives v too, and the
!> meshes carry it).
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
   use hillstab_core_kinds, only: wp
   use hillstab_core_error, only: error_t, set_error, err_invalid_parameter, err_integration, err_accuracy
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use hillstab_core_stats, only: work_stats_t
   use hillstab_hill_model, only: hill_model_t, hill_point_t, check_batch, model_split, model_split_row, &
      auto_table_steps
   use hillstab_hill_coefficient, only: split_phases
   use hillstab_hill_transfer, only: transfer_functions, trace_t, trace_from_scaled
   use hillstab_integrate_magnus, only: trace_magnus
   use hillstab_integrate_refine, only: trace_distance
   use hillstab_integrate_auto_mesh, only: mesh_t, mesh_cache_t, get_mesh, build_mesh, auto_mesh_power
   use hillstab_integrate_auto_lanes, only: lane_traces, lanes_plain, lanes_values, lanes_screen
   implicit none
   private
   public :: trace_auto, trace_auto_batch, auto_initial_steps, auto_mesh_power, fixed_n_trace
   public :: auto_plan_t, auto_prepare, trace_auto_screen, auto_screen_tolerance

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
      real(wp) :: base
      real(wp), allocatable :: c0s(:), c1s(:)
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
      allocate (c0s(size(betas)), c1s(size(betas)))
      call model_split_row(model, alpha, betas, epsilon, c0s, c1s)
      do j = 1, size(betas)
         n = steps_for_point(base, model, c0s(j), c1s(j))
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
      n = max(check_min_steps, model%auto_min_steps(), ladder_steps(base*(max(amplitude, 1.0_wp)/12.0_wp)**0.4_wp))
   end function steps_for_point

   !> `steps_for_point` of every point of a batch, without a power per point: rung r of
   !> the ladder serves the amplitudes x ≤ 12 (r/base)^2.5 (base (x/12)^0.4 ≤ r), so the
   !> rungs' thresholds are computed once and each point's rung found among them.
   pure subroutine steps_for_points(base, model, c0s, c1s, ns)
      real(wp), intent(in) :: base, c0s(:), c1s(:)
      class(hill_model_t), intent(in) :: model
      integer, intent(out) :: ns(:)
      real(wp) :: thresholds(size(ladder)), x
      integer :: j, k, first, least
      least = max(check_min_steps, model%auto_min_steps())
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
         ns(j) = max(least, ladder(k))
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
      base = auto_table_steps(model%auto_difficulty(alpha))*(1.0e-10_wp/min(tolerance, 1.0e-6_wp))**(1.0_wp/6.0_wp)
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
      real(wp) :: noise, safety
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
      safety = richardson_safety*model%auto_safety()
      m = size(betas)
      allocate (c0s(m), c1s(m), ns(m), phases(m))
      call model_split_row(model, alpha, betas, epsilon, c0s, c1s)
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
      phases = split_phases(model, alpha, c0s, c1s)
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
            estimate = safety*trace_distance(fine(j), coarse(j))/ &
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
      call model_split_row(model, alpha, betas, epsilon, c0s, c1s)
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
      phases = split_phases(model, alpha, c0s, c1s)
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
      call lane_traces(mesh, [c0], [c1], split_phases(model, alpha, [c0], [c1]), tr, floor)
      s = tr(1)%value
   end function fixed_n_trace
end module hillstab_integrate_auto

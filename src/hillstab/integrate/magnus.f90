!> Magnus integrators of order 4 and 6 for the 2×2 Hill system X' = A(τ) X,
!> A = [[0, 1], [−q(τ), 0]], with an adaptive mesh and an a-posteriori check of
!> the error in the trace S.
!>
!> Each step replaces A on [t, t + h] by one traceless generator Ω (an element of
!> sl(2)) and multiplies by exp(Ω) = C I + S Ω, C = cos √z, S = sin √z/√z,
!> z = −(a² + b c) for Ω = [[a, b], [c, −a]] (cosh/sinh when z < 0). That exponential
!> is exact and has det = 1, so det M = 1 up to round-off for any step size.
!> Generators are stored as triples g = [a, b, c]; in that basis the Lie bracket is
!> three 2×2 cross products (`sl2_commutator`), and [A(q_i), A(q_j)] = (q_i − q_j) H,
!> H = diag(1, −1), so a step costs a few tens of flops plus the Q evaluations.
!>
!> Because q is even and 2-periodic only [0, 1] is integrated: with
!> Φ(1) = [[u, v], [u', v']] (u even, v odd),
!> M = [[u v' + u' v, 2 v v'], [2 u u', u v' + u' v]] and S = 2 (u v' + u' v).
!>
!> Step selection (`monodromy_magnus`): one march over [0, 1] takes h = θ/λ, where the
!> monitor λ (an inverse length from the Gauss samples of the step itself: no extra
!> Q evaluations) measures how fast q varies; θ follows from the tolerance through the
!> order. This equidistributes the error, so the α → π² dip at τ = 0 (width
!> ~ √(1 − α/π²)) gets small steps and the smooth rest large ones. The error in S is
!> then measured, not assumed: the same mesh with steps merged in pairs gives a
!> Richardson estimate |S − S_coarse|/(2^p − 1) (×2 for safety) at half the cost of
!> the march; if it exceeds the tolerance every step is subdivided and the check
!> repeated. An embedded 4(6) pair was not used: its estimate is the O(h⁵) error of
!> the order-4 member, so the step count would grow like tolerance^{−1/4} instead of
!> tolerance^{−1/6}.
!>
!>```fortran
!> type(trace_t) :: tr
!> type(work_stats_t) :: stats
!> type(error_t), allocatable :: error
!> call trace_magnus(elastic_model_t(), hill_point_t(9.8_wp, 2.47_wp, 0.0_wp), 6, 1.0e-10_wp, tr, stats, error)
!> print *, tr%value, stats%n_evaluations
!>```
module hillstab_integrate_magnus
   use hillstab_core_kinds, only: wp, int64, log_huge
   use hillstab_core_error, only: error_t, set_error, err_invalid_parameter, err_integration, err_accuracy
   use hillstab_integrate_refine, only: roundoff_level, propagator_condition, sensitivity_t, accumulate_sensitivity, &
      coefficient_level
   use hillstab_core_stats, only: work_stats_t
   use hillstab_hill_model, only: hill_model_t, hill_point_t, hill_window_t, hill_coefficient, check_point, model_split
   use hillstab_hill_coefficient, only: phase_bound
   use hillstab_hill_transfer, only: scaled_matrix_t, scaled_identity, transfer_functions, transfer_increment, multiply_matrix, &
      multiply_scaled, &
      add_compensated, normalize_scaled, trace_t, trace_of, monodromy_from_window
   implicit none
   private
   public :: monodromy_magnus, trace_magnus, monodromy_magnus_uniform, half_period_magnus_uniform
   public :: magnus4_generator, magnus6_generator, sl2_commutator, sl2_matrix
   public :: multiply_exp_sl2, magnus_step, relative_trace_difference

   !> Nodes of 2-point Gauss–Legendre on [0, 1]: 1/2 ∓ √3/6.
   real(wp), parameter :: gauss2_offset = 0.28867513459481288225457439025097873_wp
   !> Nodes of 3-point Gauss–Legendre on [0, 1]: 1/2 ∓ √15/10, 1/2.
   real(wp), parameter :: gauss3_offset = 0.38729833462074168851792653997823996_wp
   real(wp), parameter :: sqrt3 = 1.73205080756887729352744634150587237_wp
   real(wp), parameter :: sqrt15 = 3.87298334620741688517926539978239961_wp

   !> Largest step on [0, 1]; for (nearly) constant q the monitor allows any step.
   real(wp), parameter :: max_step = 0.25_wp
   !> Largest factor by which one step may exceed the previous one.
   real(wp), parameter :: max_growth = 2.0_wp
   !> A step is rejected when λ h exceeds the target θ by this factor.
   real(wp), parameter :: reject_factor = 1.6_wp
   !> θ = theta_constant(order) · tolerance^{1/order}: steps in units of the local scale.
   !> Calibrated on α ∈ [0.01, 9.86], β ∈ [−50, 2500] so that the first pass meets the
   !> tolerance with a margin (errors ≈ tolerance/3 … tolerance/1000), rarely needing a refinement.
   real(wp), parameter :: theta_constant_4 = 2.0_wp, theta_constant_6 = 4.0_wp
   !> Weight of the oscillatory term (q'² |q|)^{1/7} of the order-6 monitor (`local_scale`);
   !> with it the first-pass error/tolerance spread over the grid drops from ~1000 to ~100.
   real(wp), parameter :: oscillation_weight = 0.5_wp
   !> Cap on θ: with λ h near 1 a step is far from the asymptotic regime and the
   !> Richardson estimate can miss the error (seen at α → π², β > π², tolerance 1e-4).
   real(wp), parameter :: max_theta = 0.45_wp
   !> Safety factor on the Richardson estimate |S_fine − S_coarse|/(r^p − 1).
   real(wp), parameter :: richardson_safety = 2.0_wp
   !> Refinement passes after the first one before giving up.
   integer, parameter :: max_refinements = 6
   !> Cap on steps over [0, 1]. A tolerance below the round-off level is recognised by
   !> `roundoff_level` before this; the cap only bounds the work (magnus4 needs about
   !> 2^18 steps at α = 9.869, β = −1e6, tolerance 1e-10).
   integer, parameter :: max_steps = 2**20

contains

   !> Lie bracket [x, y] of traceless generators g = [a, b, c] ↔ [[a, b], [c, −a]]:
   !> with H = diag(1, −1), E = [[0, 1], [0, 0]], F = [[0, 0], [1, 0]],
   !> [H, E] = 2E, [H, F] = −2F, [E, F] = H.
   pure function sl2_commutator(x, y) result(z)
      real(wp), intent(in) :: x(3), y(3)  !! generators [a, b, c]
      real(wp) :: z(3)
      z(1) = x(2)*y(3) - x(3)*y(2)
      z(2) = 2.0_wp*(x(1)*y(2) - x(2)*y(1))
      z(3) = 2.0_wp*(x(3)*y(1) - x(1)*y(3))
   end function sl2_commutator

   !> The 2×2 matrix [[a, b], [c, −a]] of a generator g = [a, b, c].
   pure function sl2_matrix(g) result(m)
      real(wp), intent(in) :: g(3)  !! generator [a, b, c]
      real(wp) :: m(2, 2)
      m = reshape([g(1), g(3), g(2), -g(1)], [2, 2])
   end function sl2_matrix

   !> Fourth-order Magnus generator from q at the 2-point Gauss nodes t + (1/2 ∓ √3/6) h:
   !> Ω = (h/2)(A1 + A2) + (√3 h²/12)[A2, A1], and [A2, A1] = (q2 − q1) H.
   pure function magnus4_generator(q, h) result(g)
      real(wp), intent(in) :: q(2)  !! q at the two Gauss nodes, in order
      real(wp), intent(in) :: h     !! step
      real(wp) :: g(3)
      g(1) = sqrt3/12.0_wp*h*h*(q(2) - q(1))
      g(2) = h
      g(3) = -0.5_wp*h*(q(1) + q(2))
   end function magnus4_generator

   !> Sixth-order Magnus generator from q at the 3-point Gauss nodes t + (1/2 − √15/10, 1/2, 1/2 + √15/10) h.
   !> Blanes, Casas, Oteo, Ros, Phys. Rep. 470 (2009) 151–238, §5 (sixth-order
   !> Gauss–Legendre Magnus method; also Blanes, Casas, Ros, BIT 40 (2000) 434):
   !>   α1 = h A2, α2 = (√15 h/3)(A3 − A1), α3 = (10 h/3)(A3 − 2 A2 + A1),
   !>   C1 = [α1, α2], C2 = −(1/60)[α1, 2 α3 + C1],
   !>   Ω = α1 + α3/12 + (1/240)[−20 α1 − α3 + C1, α2 + C2].
   !> Here α2 and α3 are multiples of F (only q differs between nodes).
   pure function magnus6_generator(q, h) result(g)
      real(wp), intent(in) :: q(3)  !! q at the three Gauss nodes, in order
      real(wp), intent(in) :: h     !! step
      real(wp) :: g(3)
      real(wp) :: alpha1(3), alpha2(3), alpha3(3), c1(3), c2(3)
      alpha1 = [0.0_wp, h, -h*q(2)]
      alpha2 = [0.0_wp, 0.0_wp, -sqrt15/3.0_wp*h*(q(3) - q(1))]
      alpha3 = [0.0_wp, 0.0_wp, -10.0_wp/3.0_wp*h*((q(3) - q(2)) + (q(1) - q(2)))]
      c1 = sl2_commutator(alpha1, alpha2)
      c2 = -sl2_commutator(alpha1, 2.0_wp*alpha3 + c1)/60.0_wp
      g = alpha1 + alpha3/12.0_wp + sl2_commutator(-20.0_wp*alpha1 - alpha3 + c1, alpha2 + c2)/240.0_wp
   end function magnus6_generator

   !> a ← exp(Ω) a with exp(Ω) = C I + S Ω, z = −(a² + b c); overflow-safe through
   !> the log scale returned by `transfer_functions`.
   !>
   !> With `compensation`, the step's increment of a%log_scale is added by compensated
   !> (Kahan) summation, the running rounding error kept in `compensation` (subtract it
   !> from a%log_scale at the end). Plain summation of ~1e5 increments onto a log scale of
   !> a few thousand (β = −1e6, α → π²) errs by ~1e-10 in ln|S|, more than a tolerance of
   !> 1e-10 allows and invisible to a Richardson check.
   !>
   !> With `low` as well (and `compensation`), the product itself is compensated: a%m + low
   !> is the propagator to about twice the working precision, and the step is applied as
   !> a ← a + F a with F = exp(Ω) − I = (C − 1) I + S Ω computed directly
   !> (`transfer_increment`), the sum by an error-free transformation whose rounding
   !> error goes into `low` (add it to a%m at the end). Plain products round each entry
   !> of exp(Ω) to ε relative to the identity, an error of the step's angle of about ε
   !> that repeats on every step where q changes little: ~ε N over N steps (1e-11 in S
   !> after 6e4 steps at constant q = 1e5). Compensated, each step errs by ε relative to
   !> F, ~ε √|q| h, and N steps by ε times the accumulated phase ∫√|q|.
   !>
   !> With `from_right` (compensated form only) the product is a ← a exp(Ω) instead, for
   !> propagators built from τ = 1 backwards.
   pure subroutine multiply_exp_sl2(a, g, compensation, low, from_right)
      type(scaled_matrix_t), intent(inout) :: a  !! the propagator, advanced
      real(wp), intent(in) :: g(3)  !! generator [a, b, c]
      real(wp), intent(inout), optional :: compensation  !! Kahan carry of a%log_scale
      real(wp), intent(inout), optional :: low(2, 2)  !! low part of the propagator (a%m + low), same scale
      logical, intent(in), optional :: from_right  !! multiply by exp(Ω) from the right
      real(wp) :: c, s, log_scale, e(2, 2), before, d(2, 2), sum(2, 2), part(2, 2)
      integer :: k
      logical :: right
      right = .false.
      if (present(from_right)) right = from_right
      if (present(low) .and. present(compensation)) then
         call transfer_increment(-(g(1)*g(1) + g(2)*g(3)), c, s, log_scale)
         e(1, 1) = c + s*g(1); e(1, 2) = s*g(2)
         e(2, 1) = s*g(3); e(2, 2) = c - s*g(1)
         if (log_scale > 0.0_wp) then
            ! a long growing step: exp(Ω) is far from I, no increment form
            e(1, 1) = e(1, 1) + 1.0_wp; e(2, 2) = e(2, 2) + 1.0_wp
            if (right) then
               a%m = matmul(a%m, e)
               low = matmul(low, e)
            else
               a%m = matmul(e, a%m)
               low = matmul(e, low)
            end if
         else
            if (right) then
               d = matmul(a%m, e) + (low + matmul(low, e))
            else
               d = matmul(e, a%m) + (low + matmul(e, low))
            end if
            sum = a%m + d
            part = sum - a%m
            low = (a%m - (sum - part)) + (d - part)
            a%m = sum
         end if
         k = exponent(maxval(abs(a%m)))
         a%m = scale(a%m, -k)
         low = scale(low, -k)
         call add_compensated(a%log_scale, log_scale + k*log(2.0_wp), compensation)
         return
      end if
      call transfer_functions(-(g(1)*g(1) + g(2)*g(3)), c, s, log_scale)
      e(1, 1) = c + s*g(1); e(1, 2) = s*g(2)
      e(2, 1) = s*g(3); e(2, 2) = c - s*g(1)
      if (present(compensation)) then
         before = a%log_scale
         a%log_scale = log_scale
         call multiply_matrix(a, e)
         call add_compensated(before, a%log_scale, compensation)
         a%log_scale = before
      else
         a%log_scale = a%log_scale + log_scale
         call multiply_matrix(a, e)
      end if
   end subroutine multiply_exp_sl2

   !> q at the Gauss nodes of [t, t + h] for a method of the given order (2 or 3 nodes).
   pure subroutine gauss_samples(model, point, order, t, h, q, n_nodes)
      class(hill_model_t), intent(in) :: model  !! the model
      type(hill_point_t), intent(in) :: point   !! α, β, ε
      integer, intent(in) :: order
      real(wp), intent(in) :: t, h
      real(wp), intent(out) :: q(3)
      integer, intent(out) :: n_nodes
      if (order == 4) then
         n_nodes = 2
         q(1) = hill_coefficient(model, point, t + (0.5_wp - gauss2_offset)*h)
         q(2) = hill_coefficient(model, point, t + (0.5_wp + gauss2_offset)*h)
         q(3) = 0.0_wp
      else
         n_nodes = 3
         q(1) = hill_coefficient(model, point, t + (0.5_wp - gauss3_offset)*h)
         q(2) = hill_coefficient(model, point, t + 0.5_wp*h)
         q(3) = hill_coefficient(model, point, t + (0.5_wp + gauss3_offset)*h)
      end if
   end subroutine gauss_samples

   !> Generator of one step from its Gauss samples.
   pure function step_generator(order, q, h) result(g)
      integer, intent(in) :: order
      real(wp), intent(in) :: q(3), h
      real(wp) :: g(3)
      if (order == 4) then
         g = magnus4_generator(q(1:2), h)
      else
         g = magnus6_generator(q, h)
      end if
   end function step_generator

   !> a ← (one Magnus step over [t, t + h]) a; adds the Q evaluations to `n_evaluations`.
   pure subroutine magnus_step(model, point, order, t, h, a, n_evaluations, compensation, low, from_right)
      class(hill_model_t), intent(in) :: model  !! the model
      type(hill_point_t), intent(in) :: point   !! α, β, ε
      integer, intent(in) :: order                    !! 4 or 6
      real(wp), intent(in) :: t, h                    !! step start and length
      type(scaled_matrix_t), intent(inout) :: a       !! propagator so far
      integer(int64), intent(inout) :: n_evaluations  !! Q evaluation counter
      real(wp), intent(inout), optional :: compensation  !! see `multiply_exp_sl2`
      real(wp), intent(inout), optional :: low(2, 2)     !! see `multiply_exp_sl2`
      logical, intent(in), optional :: from_right        !! see `multiply_exp_sl2`
      real(wp) :: q(3)
      integer :: n_nodes
      call gauss_samples(model, point, order, t, h, q, n_nodes)
      n_evaluations = n_evaluations + n_nodes
      call multiply_exp_sl2(a, step_generator(order, q, h), compensation, low, from_right)
   end subroutine magnus_step

   !> Propagator Φ(1) over [0, 1] with `n_steps` equal Magnus steps.
   pure function half_period_magnus_uniform(model, point, order, n_steps) result(phi)
      class(hill_model_t), intent(in) :: model  !! the model
      type(hill_point_t), intent(in) :: point   !! α, β, ε
      integer, intent(in) :: order    !! 4 or 6
      integer, intent(in) :: n_steps  !! number of equal steps on [0, 1]
      type(scaled_matrix_t) :: phi
      phi = uniform_product(model, point, order, n_steps, 1.0_wp)
   end function half_period_magnus_uniform

   !> Monodromy over the full period [0, 2] with `n_steps` equal Magnus steps (no use of
   !> the symmetry of q: a fixed-mesh reference for order tests and benchmarks).
   pure function monodromy_magnus_uniform(model, point, order, n_steps) result(m)
      class(hill_model_t), intent(in) :: model  !! the model
      type(hill_point_t), intent(in) :: point   !! α, β, ε
      integer, intent(in) :: order    !! 4 or 6
      integer, intent(in) :: n_steps  !! number of equal steps on [0, 2]
      type(scaled_matrix_t) :: m
      m = uniform_product(model, point, order, n_steps, 2.0_wp)
   end function monodromy_magnus_uniform

   pure function uniform_product(model, point, order, n_steps, length) result(a)
      class(hill_model_t), intent(in) :: model  !! the model
      type(hill_point_t), intent(in) :: point   !! α, β, ε
      integer, intent(in) :: order, n_steps
      real(wp), intent(in) :: length
      type(scaled_matrix_t) :: a
      integer(int64) :: n_evaluations
      real(wp) :: h
      integer :: i
      h = length/n_steps
      a = scaled_identity()
      n_evaluations = 0
      do i = 0, n_steps - 1
         call magnus_step(model, point, order, i*h, h, a, n_evaluations)
      end do
   end function uniform_product


   !> |S_a − S_b| / max(1, |S_a|) for two scaled matrices, without forming values
   !> that could overflow.
   pure real(wp) function relative_trace_difference(a, b) result(r)
      type(scaled_matrix_t), intent(in) :: a, b  !! the two matrices
      real(wp) :: top, ta, tb, floor_scale
      top = max(a%log_scale, b%log_scale)
      ta = (a%m(1, 1) + a%m(2, 2))*exp(max(a%log_scale - top, -log_huge))
      tb = (b%m(1, 1) + b%m(2, 2))*exp(max(b%log_scale - top, -log_huge))
      ! max(1, |S_a|) in units of e^top
      floor_scale = exp(max(min(-top, log_huge), -log_huge))
      r = abs(ta - tb)/max(floor_scale, abs(ta))
   end function relative_trace_difference

   !> |S_a − S_b| / max(1, |S_c|): `relative_trace_difference` on the scale of a third matrix.
   pure real(wp) function relative_trace_difference_at(a, b, c) result(r)
      type(scaled_matrix_t), intent(in) :: a, b, c  !! the two matrices and the one giving the scale
      real(wp) :: top, ta, tb, tc, floor_scale
      top = max(a%log_scale, b%log_scale, c%log_scale)
      ta = (a%m(1, 1) + a%m(2, 2))*exp(max(a%log_scale - top, -log_huge))
      tb = (b%m(1, 1) + b%m(2, 2))*exp(max(b%log_scale - top, -log_huge))
      tc = (c%m(1, 1) + c%m(2, 2))*exp(max(c%log_scale - top, -log_huge))
      floor_scale = exp(max(min(-top, log_huge), -log_huge))
      r = abs(ta - tb)/max(floor_scale, abs(tc))
   end function relative_trace_difference_at

   !> Monitor λ(τ), an inverse length, from the Gauss samples of one step; the mesh
   !> takes h ≈ θ/λ so that every step makes about the same error.
   !>
   !> λ = |q'|^{1/3} + |q''|^{1/4} (+ w (q'² |q|)^{1/7} for order 6). The first two terms
   !> are the scales on which q varies. The Magnus error does not grow with the local
   !> frequency √q alone (for constant q every step is exact), but it does grow with
   !> the product of variation and size: on uniform meshes the order-6 error in S
   !> scales like q'² |q| (Mathieu q = β − ν cos πτ: ∝ ν² β for β = 250 … 16000; the
   !> elastic dip: ∝ (β − π²)³), hence the third term. Weights are calibrated in
   !> test_magnus; the Richardson check in `monodromy_magnus` guards the result.
   pure real(wp) function local_scale(order, q, h, slope_before) result(lambda)
      integer, intent(in) :: order
      real(wp), intent(in) :: q(3), h
      real(wp), intent(in) :: slope_before  !! q' on the previous step (order 4: gives q'')
      real(wp) :: slope, curvature, size
      slope = sample_slope(order, q, h)
      if (order == 4) then
         curvature = abs(slope - slope_before)/h
         lambda = abs(slope)**(1.0_wp/3) + curvature**(1.0_wp/4)
      else
         curvature = abs((q(3) - q(2)) + (q(1) - q(2)))/(gauss3_offset*h)**2
         size = max(abs(q(1)), abs(q(2)), abs(q(3)))
         lambda = abs(slope)**(1.0_wp/3) + curvature**(1.0_wp/4) &
                  + oscillation_weight*(slope*slope*size)**(1.0_wp/7)
      end if
   end function local_scale

   !> Slope of q estimated from one step's samples.
   pure real(wp) function sample_slope(order, q, h) result(slope)
      integer, intent(in) :: order
      real(wp), intent(in) :: q(3), h
      if (order == 4) then
         slope = (q(2) - q(1))/(2.0_wp*gauss2_offset*h)
      else
         slope = (q(3) - q(1))/(2.0_wp*gauss3_offset*h)
      end if
   end function sample_slope

   !> March over [0, 1] with steps h ≈ θ/λ(τ) (equidistributing the monitor λ of
   !> `local_scale`), rejecting a step when λ h > reject_factor θ. Returns the mesh
   !> (n_mesh + 1 points) and the propagator Φ(1).
   !>
   !> The number of steps is always even: the Richardson check merges the steps in pairs,
   !> and a step left alone there (the last one of an odd mesh) would be absent from the
   !> difference. Near β = 0 with α → π² the last step, where q' → 0 lets the steps grow,
   !> carried nearly all the error of S (9.95e-9 of the 1.04e-8 at α = 9.82, β = −7e-4,
   !> tolerance 1e-10, 199 steps) and the estimate missed it by 23×; so the march ends on
   !> two halves of the last step when it would otherwise end on an odd count.
   !> `prefix(j)` is Φ at the end of the j-th pair of steps (`prefix(0)` = I), for
   !> `block_estimate`.
   subroutine adaptive_march(model, point, order, theta, mesh, n_mesh, phi, stats, log_peak, sensitivity, prefix)
      class(hill_model_t), intent(in) :: model  !! the model
      type(hill_point_t), intent(in) :: point   !! α, β, ε
      integer, intent(in) :: order
      real(wp), intent(in) :: theta
      real(wp), allocatable, intent(out) :: mesh(:)
      integer, intent(out) :: n_mesh
      type(scaled_matrix_t), intent(out) :: phi
      type(work_stats_t), intent(inout) :: stats
      !> ln of the largest scaled condition of Φ along the march (`propagator_condition`)
      real(wp), intent(out) :: log_peak
      !> the integrals of u and v for the rounding of q (hillstab_integrate_refine `coefficient_level`)
      type(sensitivity_t), intent(out) :: sensitivity
      type(scaled_matrix_t), allocatable, intent(out) :: prefix(:)  !! Φ at the pair ends
      real(wp) :: t, h, q(3), lambda, slope_before, h_next, carry, low(2, 2), c0, c1, piece_end, window_end
      real(wp), allocatable :: grown(:)
      type(scaled_matrix_t), allocatable :: grown_prefix(:)
      type(hill_window_t) :: window
      integer :: n_nodes, closing, n_piece, next_break
      logical :: last
      allocate (mesh(0:255), prefix(0:127))
      ! the window: half a period from τ = start (Q even about it) or the whole period, in
      ! pieces between the jumps of Q, each marched on its own with an even number of steps
      ! (so that no pair of the Richardson check straddles a jump)
      window = model%window(point%alpha)
      window_end = window%start + window%length
      next_break = 1
      piece_end = window_end
      if (window%n_breaks > 0) piece_end = window%breaks(1)
      mesh(0) = window%start
      prefix(0) = scaled_identity()
      n_mesh = 0
      n_piece = 0
      phi = scaled_identity()
      carry = 0.0_wp
      low = 0.0_wp
      log_peak = log(2.0_wp)
      t = window%start
      ! first guess from the size of q at the start (the dip of Q sits at τ = 0)
      h = min(max_step, theta/sqrt(abs(hill_coefficient(model, point, t)) + 1.0e-300_wp))
      stats%n_evaluations = stats%n_evaluations + 1
      slope_before = 0.0_wp  ! q is even about the start: q'(start) = 0 (a guess only, else)
      call model_split(model, point%alpha, point%beta, point%epsilon, c0, c1)
      closing = 0
      do while (t < window_end)
         if (closing == 0 .and. t + 1.05_wp*h >= piece_end) then
            ! the end of the piece is in reach: finish on one step, or two halves if one would
            ! leave the piece's count odd
            closing = 2 - mod(n_piece, 2)
         end if
         last = closing == 1
         if (closing > 1) then
            h = (piece_end - t)/closing
            h = (t + h) - t
         else if (last) then
            h = piece_end - t
         else
            ! t + h exact: the propagator is advanced by exactly the time t moves (a rounded
            ! t + h would be a jump of q, a phase error √|q|·ulp(t) per step)
            h = (t + h) - t
         end if
         call gauss_samples(model, point, order, t, h, q, n_nodes)
         stats%n_evaluations = stats%n_evaluations + n_nodes
         lambda = local_scale(order, q, h, slope_before)
         if (lambda*h > reject_factor*theta .and. h > 1.0e-12_wp) then
            stats%n_rejected = stats%n_rejected + 1
            h = max(0.1_wp*h, min(0.5_wp*h, 0.9_wp*theta/lambda))
            closing = 0
            cycle
         end if
         if (closing > 0) closing = closing - 1
         call multiply_exp_sl2(phi, step_generator(order, q, h), carry, low)
         log_peak = max(log_peak, 2.0_wp*phi%log_scale + &
                        log(propagator_condition(phi%m(1, 1), phi%m(2, 1), phi%m(1, 2), phi%m(2, 2))))
         call accumulate_sensitivity(sensitivity, phi%m(1, 1), phi%m(1, 2), phi%log_scale, h, q(2) - c0)
         stats%n_steps = stats%n_steps + 1
         slope_before = sample_slope(order, q, h)
         if (last) then
            t = piece_end
         else
            t = t + h
         end if
         n_mesh = n_mesh + 1
         n_piece = n_piece + 1
         if (n_mesh > ubound(mesh, 1)) then
            allocate (grown(0:2*ubound(mesh, 1) + 1))
            grown(0:n_mesh - 1) = mesh(0:n_mesh - 1)
            call move_alloc(grown, mesh)
         end if
         mesh(n_mesh) = t
         if (mod(n_mesh, 2) == 0) then
            if (n_mesh/2 > ubound(prefix, 1)) then
               allocate (grown_prefix(0:2*ubound(prefix, 1) + 1))
               grown_prefix(0:n_mesh/2 - 1) = prefix(0:n_mesh/2 - 1)
               call move_alloc(grown_prefix, prefix)
            end if
            prefix(n_mesh/2)%m = phi%m + low
            prefix(n_mesh/2)%log_scale = phi%log_scale - carry
         end if
         if (lambda > 0.0_wp) then
            h_next = theta/lambda
         else
            h_next = max_step
         end if
         h = min(max_step, max_growth*h, h_next)
         if (last .and. t < window_end) then
            ! across a jump of q: the next piece starts afresh (its size at the start, no slope)
            next_break = next_break + 1
            piece_end = window_end
            if (next_break <= window%n_breaks) piece_end = window%breaks(next_break)
            n_piece = 0
            closing = 0
            slope_before = 0.0_wp
            h = min(max_step, theta/sqrt(abs(hill_coefficient(model, point, t)) + 1.0e-300_wp))
            stats%n_evaluations = stats%n_evaluations + 1
         end if
      end do
      mesh(n_mesh) = window_end
      phi%m = phi%m + low
      phi%log_scale = phi%log_scale - carry
   end subroutine adaptive_march

   !> Φ(1) on a given mesh of [0, 1], each interval split into `split` equal steps.
   subroutine mesh_product(model, point, order, mesh, n_mesh, split, phi, stats)
      class(hill_model_t), intent(in) :: model  !! the model
      type(hill_point_t), intent(in) :: point   !! α, β, ε
      integer, intent(in) :: order, n_mesh, split
      real(wp), intent(in) :: mesh(0:n_mesh)
      type(scaled_matrix_t), intent(out) :: phi
      type(work_stats_t), intent(inout) :: stats
      real(wp) :: h, carry, low(2, 2)
      integer :: i, j
      phi = scaled_identity()
      carry = 0.0_wp
      low = 0.0_wp
      do i = 1, n_mesh
         h = (mesh(i) - mesh(i - 1))/split
         do j = 0, split - 1
            call magnus_step(model, point, order, mesh(i - 1) + j*h, h, phi, stats%n_evaluations, carry, low)
         end do
      end do
      phi%m = phi%m + low
      phi%log_scale = phi%log_scale - carry
      stats%n_steps = stats%n_steps + int(n_mesh, int64)*split
   end subroutine mesh_product

   !> Σ_b |ΔS_b|/max(1, |S|) over blocks b of the half period, ΔS_b the change of S when the
   !> pairs of steps of block b alone are merged: the Richardson difference S_fine − S_coarse
   !> split by where along [0, 1] it arises, with the magnitudes summed.
   !>
   !> The error of S is a sum of contributions from the whole half period, and they can
   !> cancel: near β = 0 with α → π² the middle of [0, 1] and the approach to τ = 1, where
   !> the even solution has grown by (1 + k)/(1 − k), give contributions of opposite sign,
   !> each several times the total, and the long steps near τ = 1 are not yet in the
   !> asymptotic regime, so the coarse error is no multiple 2^p of the fine one (at
   !> α = 9.576, β = 3.8e-5, tolerance 1e-10 it was −5.6 times it) and the plain difference
   !> missed the error by 4.9×. With the contributions taken block by block their
   !> cancellation no longer hides them.
   !>
   !> ΔS_b telescopes through hybrid products H_b = S(coarse on [τ_b, 1]·fine on [0, τ_b]):
   !> H_0 = S_coarse, H_B = S_fine, ΔS_b = H_b − H_{b−1}. The fine parts are the march's
   !> `prefix`; the coarse parts are multiplied here from τ = 1 backwards (half the
   !> march's steps: this is the plain check's coarse product too, returned as `m_coarse`).
   function block_estimate(model, point, order, mesh, n_mesh, prefix, m_fine, stats, m_coarse) result(total)
      class(hill_model_t), intent(in) :: model  !! the model
      type(hill_point_t), intent(in) :: point   !! α, β, ε
      integer, intent(in) :: order, n_mesh
      real(wp), intent(in) :: mesh(0:n_mesh)
      type(scaled_matrix_t), intent(in) :: prefix(0:)   !! Φ_fine at the end of each pair
      type(scaled_matrix_t), intent(in) :: m_fine       !! the fine monodromy (for the scale)
      type(work_stats_t), intent(inout) :: stats
      type(scaled_matrix_t), intent(out) :: m_coarse    !! the coarse monodromy (steps merged in pairs)
      real(wp) :: total
      integer, parameter :: n_blocks = 8
      type(scaled_matrix_t) :: suffix, whole, hybrid, before
      integer :: n_pairs, j, block_pairs
      real(wp) :: carry, low(2, 2)
      logical :: half
      half = window_is_half(model, point)
      n_pairs = n_mesh/2
      block_pairs = max(1, (n_pairs + n_blocks - 1)/n_blocks)
      total = 0.0_wp
      suffix = scaled_identity()
      carry = 0.0_wp
      low = 0.0_wp
      before = m_fine
      do j = n_pairs, 1, -1
         ! compensated as the forward products are (a plain product errs by ε per step)
         call magnus_step(model, point, order, mesh(2*j - 2), mesh(2*j) - mesh(2*j - 2), suffix, stats%n_evaluations, &
                          carry, low, from_right=.true.)
         stats%n_steps = stats%n_steps + 1
         if (mod(j - 1, block_pairs) == 0 .or. j == 1) then
            whole%m = suffix%m + low
            whole%log_scale = suffix%log_scale - carry
            hybrid = monodromy_from_window(multiply_scaled(whole, prefix(j - 1)), half)
            total = total + relative_trace_difference_at(hybrid, before, m_fine)
            before = hybrid
         end if
      end do
      ! the last hybrid has the coarse steps everywhere
      m_coarse = before
   end function block_estimate

   !> The Richardson estimate |S_fine − S_coarse|/(r^p − 1) (times the safety factor) of a
   !> refinement, or, where the observed convergence does not look asymptotic, the
   !> undivided |S_fine − S_coarse| (an upper estimate of the fine error as soon as the
   !> coarse error is at least twice it): the difference is compared with the one before it
   !> (`previous`, between the coarse value and the one before); their ratio must be the
   !> expected `expected_ratio` within a factor 4 (contributions of opposite sign from
   !> different parts of [0, 1] that converge at different rates break it, see
   !> `block_estimate`).
   pure real(wp) function checked_estimate(difference, previous, ratio, expected_ratio) result(estimate)
      real(wp), intent(in) :: difference      !! |S_fine − S_coarse|/max(1, |S_fine|)
      real(wp), intent(in) :: previous        !! |S_coarse − S_coarser|/max(1, |S_fine|)
      real(wp), intent(in) :: ratio           !! r^p: the error ratio of coarse to fine
      real(wp), intent(in) :: expected_ratio  !! the expected previous/difference
      real(wp), parameter :: ratio_slack = 4.0_wp
      estimate = richardson_safety*difference/(ratio - 1.0_wp)
      if (.not. (previous*ratio_slack >= expected_ratio*difference .and. &
                 previous <= ratio_slack*expected_ratio*difference)) estimate = max(estimate, difference)
   end function checked_estimate

   !> One-period monodromy of the χ equation by an adaptive Magnus method.
   !>
   !> The mesh on [0, 1] follows the local scale of q (`adaptive_march`) with a step
   !> parameter θ set from the tolerance through the order; the error in S is then
   !> estimated by Richardson against the same mesh with steps merged in pairs, and
   !> the mesh is subdivided uniformly until the estimate meets the tolerance.
   !> `tolerance` is the target error in S relative to max(1, |S|). `stats` counts the
   !> steps of all passes (march, check, refinements) and every Q evaluation. When the
   !> tolerance cannot be met (round-off, or more than 2^17 steps on [0, 1]) the best
   !> monodromy is returned together with an `err_integration` error.
   subroutine monodromy_magnus(model, point, order, tolerance, m, stats, error, error_estimate)
      class(hill_model_t), intent(in) :: model  !! the model
      type(hill_point_t), intent(in) :: point   !! α, β, ε
      integer, intent(in) :: order                  !! 4 or 6
      real(wp), intent(in) :: tolerance             !! target |ΔS|/max(1, |S|)
      type(scaled_matrix_t), intent(out) :: m       !! monodromy over [0, 2]
      type(work_stats_t), intent(out) :: stats      !! steps of all passes and Q evaluations
      !> err_integration when the tolerance is not met (best value returned)
      type(error_t), allocatable, intent(out) :: error
      real(wp), intent(out), optional :: error_estimate  !! estimated |ΔS|/max(1, |S|)
      real(wp), allocatable :: mesh(:)
      type(scaled_matrix_t) :: phi, m_check
      type(scaled_matrix_t), allocatable :: prefix(:)
      real(wp) :: theta, estimate, ratio, log_peak, noise, previous, phase, c0, c1, difference, previous_difference
      real(wp) :: previous_ratio, blocks
      type(sensitivity_t) :: sensitivity
      logical :: stagnated
      type(trace_t) :: tr
      integer :: n_mesh, split, pass, factor
      logical :: half
      character(len=100) :: buffer
      stats = work_stats_t()
      m = scaled_identity()
      if (present(error_estimate)) error_estimate = huge(1.0_wp)
      call check_point(model, point, error)
      if (allocated(error)) return
      if (order /= 4 .and. order /= 6) then
         write (buffer, '(a,i0)') "Magnus order must be 4 or 6, got ", order
         call set_error(error, err_invalid_parameter, trim(buffer))
         return
      end if
      if (.not. (tolerance > 0.0_wp .and. tolerance < 1.0_wp)) then
         call set_error(error, err_invalid_parameter, "Magnus tolerance must lie in (0, 1)")
         return
      end if
      if (order == 4) then
         theta = min(max_theta, theta_constant_4*tolerance**(1.0_wp/4))
      else
         theta = min(max_theta, theta_constant_6*tolerance**(1.0_wp/6))
      end if
      call adaptive_march(model, point, order, theta, mesh, n_mesh, phi, stats, log_peak, sensitivity, prefix)
      call model_split(model, point%alpha, point%beta, point%epsilon, c0, c1)
      half = window_is_half(model, point)
      m = monodromy_from_window(phi, half)
      blocks = block_estimate(model, point, order, mesh, n_mesh, prefix, m, stats, m_check)
      ratio = 2.0_wp**order
      difference = relative_trace_difference(m, m_check)
      estimate = richardson_safety*max(difference, blocks)/(ratio - 1.0_wp)
      split = 1
      tr = trace_of(m)
      phase = phase_bound(model, point)
      noise = roundoff_level(log_peak, tr%log_abs, n_mesh, phase, half=half) + &
         coefficient_level(sensitivity, c0, m, tr%log_abs, half)
      stagnated = .false.
      do pass = 1, max_refinements
         if (estimate <= tolerance .and. noise <= tolerance) exit
         ! the difference is at the round-off level: more steps cannot help
         if (estimate <= max(tolerance, 2.0_wp*noise) .or. stagnated) exit
         ! subdivide every step by `factor` so that the error drops by factor^p below the tolerance
         factor = max(2, ceiling(1.2_wp*(estimate/tolerance)**(1.0_wp/order)))
         if (real(factor, wp)*split*n_mesh > real(max_steps, wp)) exit
         m_check = m
         split = split*factor
         call mesh_product(model, point, order, mesh, n_mesh, split, phi, stats)
         m = monodromy_from_window(phi, half)
         previous = estimate
         previous_difference = difference
         previous_ratio = ratio
         ratio = real(factor, wp)**order
         difference = relative_trace_difference(m, m_check)
         ! successive differences fall by r (r_before − 1)/(r − 1) in the asymptotic regime
         estimate = checked_estimate(difference, previous_difference, ratio, &
                                     ratio*(previous_ratio - 1.0_wp)/(ratio - 1.0_wp))
         tr = trace_of(m)
         noise = roundoff_level(log_peak, tr%log_abs, split*n_mesh, phase, half=half) + &
                 coefficient_level(sensitivity, c0, m, tr%log_abs, half)
         ! truncation falls by factor^p (at least 16); a difference that no longer falls
         ! by a quarter of that, within a few times the round-off level, is rounding noise
         stagnated = estimate > previous*4.0_wp/real(factor, wp)**order .and. estimate <= 10.0_wp*noise
      end do
      if (present(error_estimate)) error_estimate = max(estimate, noise)
      if ((estimate > tolerance .or. noise > tolerance) .and. &
          (estimate <= max(tolerance, 2.0_wp*noise) .or. stagnated)) then
         write (buffer, '(a,es9.2,a,es9.2)') "Magnus: the tolerance ", tolerance, &
            " is below the round-off level of S here, ", noise
         call set_error(error, err_accuracy, trim(buffer))
      else if (estimate > tolerance) then
         write (buffer, '(a,es9.2,a,es9.2)') "Magnus: estimated error ", estimate, &
            " in S exceeds the tolerance ", tolerance
         call set_error(error, err_integration, trim(buffer))
      end if
   end subroutine monodromy_magnus

   !> Whether the model's window at the point is half a period of an even coefficient.
   pure logical function window_is_half(model, point) result(half)
      class(hill_model_t), intent(in) :: model  !! the model
      type(hill_point_t), intent(in) :: point   !! α, β, ε
      type(hill_window_t) :: window
      window = model%window(point%alpha)
      half = window%half
   end function window_is_half

   !> Trace of `monodromy_magnus`.
   subroutine trace_magnus(model, point, order, tolerance, tr, stats, error, error_estimate)
      class(hill_model_t), intent(in) :: model  !! the model
      type(hill_point_t), intent(in) :: point   !! α, β, ε
      integer, intent(in) :: order                  !! 4 or 6
      real(wp), intent(in) :: tolerance             !! target |ΔS|/max(1, |S|)
      type(trace_t), intent(out) :: tr  !! the trace S
      type(work_stats_t), intent(out) :: stats  !! work done: steps, rejected steps, Q evaluations
      !> err_integration when the tolerance is not met (best value returned)
      type(error_t), allocatable, intent(out) :: error
      real(wp), intent(out), optional :: error_estimate  !! the Richardson estimate of |dS|/max(1, |S|)
      type(scaled_matrix_t) :: m
      real(wp) :: estimate
      call monodromy_magnus(model, point, order, tolerance, m, stats, error, estimate)
      tr = trace_of(m)
      ! no estimate when the method stopped before measuring one (bad input)
      if (estimate < huge(1.0_wp)) tr%error_estimate = estimate
      if (present(error_estimate)) error_estimate = estimate
   end subroutine trace_magnus
end module hillstab_integrate_magnus

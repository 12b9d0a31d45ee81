!> The integrators of a system's one-period monodromy Φ (hillstab_hill_system): the 2n × 2n
!> fundamental matrix of y' = A(τ) y, A = [[0, I], [−M⁻¹K(τ), D]], y = (x, x'), over one
!> period from τ = 0, to a tolerance, with an error estimate, and the period's product kept
!> in well-conditioned factors. The method table and the choice among the methods are
!> hillstab_integrate_monodromy's (`system_monodromy`, `system_factors`); GSL's is
!> hillstab_integrate_system_gsl.
!>
!> - Magnus of order 6 (methods magnus6 and auto): the sixth-order Magnus integrator of
!>   Blanes, Casas and Ros in its matrix form (three Gauss nodes; Ω = α₁ + α₃/12 + [−20α₁ −
!>   α₃ + C₁, α₂ + C₂]/240, C₁ = [α₁, α₂], C₂ = −[α₁, 2α₃ + C₁]/60). A's blocks make α₂, α₃
!>   one-block matrices, so that C₁ and C₂ are formed from n × n products
!>   (`magnus6_exponent_blocks`); the state is balanced by S = diag(cI, I), c = 2^−k ≈
!>   ‖M⁻¹K‖^−½ (a similarity, exact in binary), so that Ω's norm is about h√‖M⁻¹K‖ rather
!>   than h‖M⁻¹K‖. Each step's exponential by scaling and squaring of the optimised Taylor
!>   approximants of Bader, Blanes and Casas (`system_exponential`: degree 12 in four
!>   products, 18 in five; backward error below the unit round-off). n = 2 runs on
!>   fixed-size 4 × 4 arrays (products inline). N equal steps over the window; the error of
!>   Φ_N is estimated by Richardson's comparison with N/2 steps, ‖Φ_N − Φ_{N/2}‖/(2⁶ − 1),
!>   and N climbs a ladder (4, 5, 6, 7 times powers of two, even counts accepted) until the
!>   estimate, relative to max(1, max|Φ_ij|), meets the tolerance; the result is the
!>   extrapolation Φ_N + (Φ_N − Φ_{N/2})/(2⁶ − 1), whose error is of higher order (eighth:
!>   the method is symmetric) and which the estimate of Φ_N's error bounds in the asymptotic
!>   range (measured on the benchmark chart at 1e-10: estimate ≤ 1e-10, error ≤ 8e-13).
!>   Order 4 (magnus4): the two-node Magnus integrator, likewise (its exponent in full
!>   2n × 2n products). `monodromy_magnus`, `magnus_period_factors`.
!> - rk: Dormand–Prince 8(5,3) (hillstab_integrate_rk) on the 4n² entries of the
!>   fundamental matrix, local tolerance tolerance/10, then /320, the difference of the two
!>   the estimate (the reference the tests and benchmarks compare with). `monodromy_rk`,
!>   `rk_period_factors`.
!>
!> A system in first-order form (`system_form_t%first_order`, y' = A y with A given, n states)
!> runs on the same ladder with the exponent in full n × n products (`magnus_exponent`; no
!> blocks, no balancing), and rk on the same A.
!>
!> Where half a period is enough (`system_form_t%half`: Hamiltonian, G = 0, K even) the
!> integrators take Y over [0, P/2] and return Φ = R Y⁻¹ R Y, Y⁻¹ = Ω⁻¹YᵀΩ by the
!> symplectic form (`complete_half_factors` for the factors). The solution is rescaled by
!> powers of two when it grows (`log_scale`: Φ = e^s Φ̃), so that strongly unstable points
!> do not overflow.
!>
!> In a chart the values of K at the Gauss nodes depend on α and the mesh only (K = p + β b):
!> a `system_nodes_t` keeps them for the meshes used at one α, so that the points of a
!> row share them, and carries as the next point's first try the mesh the previous point's
!> estimate asked for (N (estimate/tolerance)^(1/6), the smallest level above it). No module
!> state: threads each use their own `system_nodes_t`.
!>
!>```fortran
!> type(system_form_t) :: form
!> type(system_monodromy_t) :: result
!> type(system_nodes_t) :: nodes
!> call prepare_system(system, 0.0_wp, form, error)
!> call monodromy_magnus(system, form, alpha, beta, 1.0e-10_wp, 6, nodes, result, error)
!>```
module hillstab_integrate_system_magnus
   use hillstab_core_kinds, only: wp, int64
   use hillstab_core_stats, only: work_stats_t
   use hillstab_core_error, only: error_t, set_error, err_integration
   use hillstab_core_status, only: status_ok, status_roundoff, status_failed
   use hillstab_hill_system, only: hill_system_t, system_form_t, fundamental_derivative, lower_block
   use hillstab_hill_system_exponents, only: identity => identity_matrix
   use hillstab_integrate_rk, only: rk_system_t, rk_options_t, rk_integrate, rk_dop853
   use hillstab_integrate_system_kernels, only: node_level_t, magnus6_steps_4, magnus6_steps, &
      exponential_explicit, full_from_half, reversed_inverse, magnus6_exponent, commutator, system_exponential
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   implicit none
   private
   public :: system_monodromy_t, system_nodes_t, magnus_ladder, system_exponential
   public :: monodromy_magnus, magnus_period_factors, monodromy_rk, rk_period_factors, factor_pieces, push_factor, &
      complete_half_factors, window_length

   !> The step counts of the Magnus ladder, 4, 5, 6, 7 times powers of two (ratios at most
   !> 1.25); every even count from 4 on has its half among the earlier ones, and only those
   !> are accepted (the odd 5 and 7 serve as halves).
   integer, parameter :: magnus_ladder(*) = [2, 3, 4, 5, 6, 7, 8, 10, 12, 14, 16, 20, 24, 28, 32, 40, 48, 56, 64, &
                                             80, 96, 112, 128, 160, 192, 224, 256, 320, 384, 448, 512, 640, 768, &
                                             896, 1024, 1280, 1536, 1792, 2048, 2560, 3072, 3584, 4096, 5120, 6144, &
                                             7168, 8192, 10240, 12288, 14336, 16384]

   !> The monodromy of one point.
   type :: system_monodromy_t
      real(wp), allocatable :: phi(:, :)   !! Φ̃ (2n × 2n): Φ = e^s Φ̃
      real(wp) :: log_scale = 0.0_wp       !! s
      !> the estimated error of Φ̃'s entries relative to max(1, max|Φ̃_ij|)
      real(wp) :: error_estimate = 0.0_wp
      integer :: status = status_ok        !! status_ok, status_roundoff or status_failed
      integer :: steps = 0                 !! steps (Magnus) or right-hand sides (rk, gsl) spent
      integer :: mesh = 0                  !! the accepted Magnus mesh (steps over the window); 0: rk, gsl
   end type system_monodromy_t

   !> What the points of one α share (see the module's text).
   type :: system_nodes_t
      real(wp) :: alpha = huge(1.0_wp)     !! the α of the levels held
      integer :: order = 0                 !! the Magnus order they are for
      type(node_level_t) :: levels(size(magnus_ladder))  !! K at the Gauss nodes, one per ladder level
      integer :: hint = 0                  !! ladder index that met the tolerance at the last point
      !> −M⁻¹p and −M⁻¹b at τ = 0, P/4, P/2, 3P/4 (the size of A for the coarsest mesh)
      real(wp), allocatable :: corner_p(:, :, :), corner_b(:, :, :)
   end type system_nodes_t

   !> The right-hand side of the fundamental matrix for rk.
   type, extends(rk_system_t) :: fundamental_t
      class(hill_system_t), allocatable :: system
      type(system_form_t) :: form
      real(wp) :: alpha = 0.0_wp, beta = 0.0_wp
      real(wp), allocatable :: p(:, :), b(:, :)
   contains
      procedure :: rhs => fundamental_rhs
   end type fundamental_t

   real(wp), parameter :: sqrt15 = 3.87298334620741688_wp, sqrt3 = 1.73205080756887729_wp
   !> the factor on Richardson's estimate (1: the extrapolated Φ returned has a margin of its
   !> own; 2 when Φ_N itself was returned, as before)
   real(wp), parameter :: safety = 1.0_wp
   !> return Richardson's extrapolation of the accepted mesh and its half
   logical, parameter :: extrapolate = .true.
   !> the margin of a failed mesh's successor and of the next point's first mesh over the
   !> mesh the estimate asks for
   real(wp), parameter :: grow = 1.1_wp, hint_margin = 1.0_wp
   !> the coarsest mesh accepted: this many steps per unit of (√‖M⁻¹K‖ + the highest drive
   !> frequency) times the window, so that the Richardson pair is in its asymptotic range
   real(wp), parameter :: resolution = 1.0_wp
   !> a factor of `system_factors` spans at most this much of ∫‖A‖ (its condition ≤ e^{2·this})
   real(wp), parameter :: chunk_limit = 2.0_wp

contains

   !> The factors of the mesh `monodromy` accepted by Magnus of `order` (its steps grouped into
   !> chunks of ∫‖Ω‖ ≤ `chunk_limit`), over the window; its steps added.
   subroutine magnus_period_factors(system, form, alpha, beta, order, nodes, monodromy, factors, count, error)
      class(hill_system_t), intent(in) :: system      !! the system
      type(system_form_t), intent(in) :: form         !! prepared at the point's ε
      real(wp), intent(in) :: alpha, beta             !! the point
      integer, intent(in) :: order                    !! 4 or 6
      type(system_nodes_t), intent(inout) :: nodes    !! as for `monodromy_magnus`
      type(system_monodromy_t), intent(inout) :: monodromy  !! the point's monodromy (its mesh); steps added
      real(wp), allocatable, intent(inout) :: factors(:, :, :)  !! receives F_1 … F_count
      integer, intent(inout) :: count                 !! the number of factors
      type(error_t), allocatable, intent(out) :: error  !! err_integration when no mesh was accepted
      integer :: j
      j = findloc(magnus_ladder, monodromy%mesh, dim=1)
      if (j == 0) then
         call set_error(error, err_integration, "magnus: no accepted mesh to factor")
         return
      end if
      call fill_level(system, form, alpha, order, j, nodes)
      call magnus_factors(form, beta, order, magnus_ladder(j), nodes%levels(j), factors, count)
      monodromy%steps = monodromy%steps + magnus_ladder(j)
   end subroutine magnus_period_factors

   !> How many equal subintervals of the window keep ∫‖A‖ over each at most `chunk_limit`
   !> (‖A‖ bounded from K at the four corners and D), for the factors of a propagating method.
   integer function factor_pieces(system, form, alpha, beta, nodes) result(pieces)
      class(hill_system_t), intent(in) :: system      !! the system
      type(system_form_t), intent(in) :: form         !! prepared at the point's ε
      real(wp), intent(in) :: alpha, beta             !! the point
      type(system_nodes_t), intent(inout) :: nodes    !! its corners filled at α
      real(wp) :: size_a
      integer :: k
      call renew_nodes(system, form, alpha, 6, nodes)
      size_a = 0.0_wp
      do k = 1, 4
         size_a = max(size_a, maxval(sum(abs(nodes%corner_p(:, :, k) + beta*nodes%corner_b(:, :, k)), dim=2)))
      end do
      ! ‖A‖ grows as √‖M⁻¹K‖ in second-order form, as the given A in first-order form
      if (.not. form%first_order) size_a = sqrt(size_a)
      pieces = max(1, ceiling(window_length(form)*(1.0_wp + size_a + maxval(sum(abs(form%d), dim=2)))/chunk_limit))
   end function factor_pieces

   !> The factors of rk over `pieces` equal subintervals of the window, each from the
   !> identity at the second pass's local tolerance; the right-hand sides added to `steps`.
   subroutine rk_period_factors(system, form, alpha, beta, tolerance, pieces, factors, count, steps, error)
      class(hill_system_t), intent(in) :: system      !! the system
      type(system_form_t), intent(in) :: form         !! prepared at the point's ε
      real(wp), intent(in) :: alpha, beta             !! the point
      real(wp), intent(in) :: tolerance               !! the method's tolerance
      integer, intent(in) :: pieces                   !! the subintervals (`factor_pieces`)
      real(wp), allocatable, intent(inout) :: factors(:, :, :)  !! receives F_1 … F_count
      integer, intent(inout) :: count                 !! the number of factors
      integer, intent(inout) :: steps                 !! right-hand sides spent
      type(error_t), allocatable, intent(out) :: error  !! err_integration when a piece fails
      type(fundamental_t) :: f
      real(wp) :: y(form%states, form%states), local, window
      integer :: k
      window = window_length(form)
      call rk_context(system, form, alpha, beta, f)
      local = rk_second_tolerance(rk_first_tolerance(tolerance))
      do k = 1, pieces
         call propagate_rk(f, window*(k - 1)/pieces, window*k/pieces, local, y, steps, error)
         if (allocated(error)) return
         call push_factor(factors, count, y)
      end do
   end subroutine rk_period_factors

   !> Where half a period is enough, the second half's factors after the first's: R F_k⁻¹ R,
   !> in reverse order (nothing otherwise).
   subroutine complete_half_factors(form, factors, count)
      type(system_form_t), intent(in) :: form         !! the system's form
      real(wp), allocatable, intent(inout) :: factors(:, :, :)  !! F_1 … F_count of the half period
      integer, intent(inout) :: count                 !! the number of factors
      real(wp) :: y(form%states, form%states)
      integer :: k, half_count
      if (.not. form%half) return
      half_count = count
      do k = half_count, 1, -1
         call reversed_inverse(form%n, form%m, form%m_inverse, factors(:, :, k), y)
         call push_factor(factors, count, y)
      end do
   end subroutine complete_half_factors

   !> Append a factor, growing the array by doubling.
   pure subroutine push_factor(factors, count, y)
      real(wp), allocatable, intent(inout) :: factors(:, :, :)  !! the factors (allocated)
      integer, intent(inout) :: count  !! their number
      real(wp), intent(in) :: y(:, :)  !! the factor appended
      real(wp), allocatable :: grown(:, :, :)
      if (count == size(factors, 3)) then
         allocate (grown(size(factors, 1), size(factors, 2), 2*count))
         grown(:, :, 1:count) = factors
         call move_alloc(grown, factors)
      end if
      count = count + 1
      factors(:, :, count) = y
   end subroutine push_factor

   !> The Magnus steps of one mesh over the window (balanced as `magnus6_steps`, a similarity
   !> undone per chunk), multiplied into chunks of ∫‖Ω‖ ≤ `chunk_limit`.
   subroutine magnus_factors(form, beta, order, steps, level, factors, count)
      type(system_form_t), intent(in) :: form
      real(wp), intent(in) :: beta
      integer, intent(in) :: order, steps
      type(node_level_t), intent(in) :: level
      real(wp), allocatable, intent(inout) :: factors(:, :, :)
      integer, intent(inout) :: count
      real(wp) :: a(form%states, form%states, 3), big_omega(form%states, form%states), &
                  e(form%states, form%states), chunk(form%states, form%states), span, c, c2, hc, big
      integer :: n, m, k, i, nq
      n = form%n
      m = form%states
      nq = merge(3, 2, order == 6)
      if (form%first_order) then
         call first_order_factors()
         return
      end if
      c = 1.0_wp
      big = maxval(sum(abs(level%lp(:, :, 1:nq) + beta*level%lb(:, :, 1:nq)), dim=2))
      if (big > 4.0_wp) c = 2.0_wp**(-nint(0.5_wp*log(big)/log(2.0_wp)))
      c2 = c*c
      hc = window_length(form)/steps/c
      a = 0.0_wp
      do i = 1, nq
         do k = 1, n
            a(k, n + k, i) = 1.0_wp
         end do
         a(n + 1:m, n + 1:m, i) = c*form%d
      end do
      chunk = identity(m)
      span = 0.0_wp
      do k = 1, steps
         do i = 1, nq
            a(n + 1:m, 1:n, i) = c2*(level%lp(:, :, nq*(k - 1) + i) + beta*level%lb(:, :, nq*(k - 1) + i))
         end do
         if (order == 6) then
            big_omega = magnus6_exponent(a(:, :, 1), a(:, :, 2), a(:, :, 3), hc)
         else
            big_omega = 0.5_wp*hc*(a(:, :, 1) + a(:, :, 2)) + (sqrt3*hc*hc/12.0_wp)*commutator(a(:, :, 2), a(:, :, 1))
         end if
         call exponential_explicit(m, big_omega, e)
         chunk = matmul(e, chunk)
         span = span + maxval(sum(abs(big_omega), dim=1))
         if (span >= chunk_limit .or. k == steps) then
            chunk(1:n, n + 1:m) = c*chunk(1:n, n + 1:m)
            chunk(n + 1:m, 1:n) = chunk(n + 1:m, 1:n)/c
            call push_factor(factors, count, chunk)
            chunk = identity(m)
            span = 0.0_wp
         end if
      end do

   contains

      !> In first-order form A = p + β b itself, unbalanced.
      subroutine first_order_factors()
         hc = window_length(form)/steps
         chunk = identity(m)
         span = 0.0_wp
         do k = 1, steps
            do i = 1, nq
               a(:, :, i) = level%lp(:, :, nq*(k - 1) + i) + beta*level%lb(:, :, nq*(k - 1) + i)
            end do
            big_omega = magnus_exponent(order, a, hc)
            call exponential_explicit(m, big_omega, e)
            chunk = matmul(e, chunk)
            span = span + maxval(sum(abs(big_omega), dim=1))
            if (span >= chunk_limit .or. k == steps) then
               call push_factor(factors, count, chunk)
               chunk = identity(m)
               span = 0.0_wp
            end if
         end do
      end subroutine first_order_factors
   end subroutine magnus_factors

   !> The Magnus exponent of one step of length h from A at its Gauss nodes (order 4: two
   !> nodes; 6: three), in full products.
   pure function magnus_exponent(order, a, h) result(big_omega)
      integer, intent(in) :: order
      real(wp), intent(in) :: a(:, :, :)
      real(wp), intent(in) :: h
      real(wp) :: big_omega(size(a, 1), size(a, 2))
      if (order == 6) then
         big_omega = magnus6_exponent(a(:, :, 1), a(:, :, 2), a(:, :, 3), h)
      else
         big_omega = 0.5_wp*h*(a(:, :, 1) + a(:, :, 2)) + (sqrt3*h*h/12.0_wp)*commutator(a(:, :, 2), a(:, :, 1))
      end if
   end function magnus_exponent

   !> The window: half the period (`form%half`) or the period.
   pure real(wp) function window_length(form)
      type(system_form_t), intent(in) :: form  !! the system's form
      window_length = form%period
      if (form%half) window_length = 0.5_wp*form%period
   end function window_length

   !> Fill the nodes of ladder level j at α (Gauss nodes of N steps over the window).
   subroutine fill_level(system, form, alpha, order, j, nodes)
      class(hill_system_t), intent(in) :: system
      type(system_form_t), intent(in) :: form
      real(wp), intent(in) :: alpha
      integer, intent(in) :: order, j
      type(system_nodes_t), intent(inout) :: nodes
      integer :: steps, k, q, nq, n
      real(wp) :: h, tau, c(3)
      real(wp), allocatable :: p(:, :), b(:, :)
      call renew_nodes(system, form, alpha, order, nodes)
      if (nodes%levels(j)%ready) return
      n = form%n
      steps = magnus_ladder(j)
      h = window_length(form)/steps
      if (order == 6) then
         nq = 3
         c = [0.5_wp - sqrt15/10.0_wp, 0.5_wp, 0.5_wp + sqrt15/10.0_wp]
      else
         nq = 2
         c = [0.5_wp - sqrt3/6.0_wp, 0.5_wp + sqrt3/6.0_wp, 0.0_wp]
      end if
      if (allocated(nodes%levels(j)%lp)) deallocate (nodes%levels(j)%lp, nodes%levels(j)%lb)
      allocate (nodes%levels(j)%lp(n, n, nq*steps), nodes%levels(j)%lb(n, n, nq*steps), p(n, n), b(n, n))
      do k = 1, steps
         do q = 1, nq
            tau = (k - 1 + c(q))*h
            call system%stiffness(alpha, tau, p, b)
            nodes%levels(j)%lp(:, :, nq*(k - 1) + q) = lower_block(form, p)
            nodes%levels(j)%lb(:, :, nq*(k - 1) + q) = lower_block(form, b)
         end do
      end do
      nodes%levels(j)%ready = .true.
   end subroutine fill_level

   !> Forget the levels when α or the order changed; fill the corners for the first mesh.
   subroutine renew_nodes(system, form, alpha, order, nodes)
      class(hill_system_t), intent(in) :: system
      type(system_form_t), intent(in) :: form
      real(wp), intent(in) :: alpha
      integer, intent(in) :: order
      type(system_nodes_t), intent(inout) :: nodes
      real(wp) :: p(form%n, form%n), b(form%n, form%n)
      integer :: k
      if (nodes%alpha == alpha .and. nodes%order == order .and. allocated(nodes%corner_p)) then
         if (size(nodes%corner_p, 1) == form%n) return
      end if
      do k = 1, size(nodes%levels)
         nodes%levels(k)%ready = .false.
      end do
      nodes%alpha = alpha
      nodes%order = order
      nodes%hint = 0
      if (allocated(nodes%corner_p)) deallocate (nodes%corner_p, nodes%corner_b)
      allocate (nodes%corner_p(form%n, form%n, 4), nodes%corner_b(form%n, form%n, 4))
      do k = 0, 3
         call system%stiffness(alpha, 0.25_wp*k*form%period, p, b)
         nodes%corner_p(:, :, k + 1) = lower_block(form, p)
         nodes%corner_b(:, :, k + 1) = lower_block(form, b)
      end do
   end subroutine renew_nodes

   !> The coarsest ladder level accepted at β (and the first tried without a hint): `resolution`
   !> steps per unit of √‖M⁻¹K‖ (its largest at the four corners) plus the drive's highest
   !> frequency, over the window; coarser, Richardson's estimate of a point of the pendula
   !> chart at β ≈ 11 understated the error threefold (N = 4 against 2 at tolerance 1e-6).
   integer function first_level(system, form, beta, nodes) result(j)
      class(hill_system_t), intent(in) :: system
      type(system_form_t), intent(in) :: form
      real(wp), intent(in) :: beta
      type(system_nodes_t), intent(in) :: nodes   !! with its corners (`renew_nodes`)
      real(wp) :: size_a, want
      integer :: k
      size_a = 0.0_wp
      do k = 1, 4
         size_a = max(size_a, maxval(sum(abs(nodes%corner_p(:, :, k) + beta*nodes%corner_b(:, :, k)), dim=2)))
      end do
      size_a = max(size_a, maxval(sum(abs(form%d), dim=2))**2)
      ! ‖A‖ grows as √‖M⁻¹K‖ in second-order form, as the given A in first-order form
      if (form%first_order) then
         want = window_length(form)*resolution*(size_a + max(1, system%drive_harmonics())*2.0_wp/form%period)
      else
         want = window_length(form)*resolution*(sqrt(size_a) + max(1, system%drive_harmonics())*2.0_wp/form%period)
      end if
      j = 3
      do while (j < size(magnus_ladder) - 2 .and. (magnus_ladder(j) < want .or. .not. has_half(j)))
         j = j + 1
      end do
   end function first_level

   !> Level j may be accepted: an even count from 4 on (its half on the ladder).
   pure logical function has_half(j)
      integer, intent(in) :: j
      has_half = magnus_ladder(j) >= 4 .and. mod(magnus_ladder(j), 2) == 0
   end function has_half

   !> Magnus of order 4 or 6 up the ladder until the Richardson estimate meets the tolerance.
   subroutine monodromy_magnus(system, form, alpha, beta, tolerance, order, nodes, result, error)
      class(hill_system_t), intent(in) :: system    !! the system
      type(system_form_t), intent(in) :: form       !! prepared at the point's ε
      real(wp), intent(in) :: alpha, beta           !! the point
      real(wp), intent(in) :: tolerance             !! target error of Φ, relative to max(1, max|Φ_ij|)
      integer, intent(in) :: order                  !! 4 or 6
      type(system_nodes_t), intent(inout) :: nodes  !! shared along a row (a fresh one for one point)
      type(system_monodromy_t), intent(out) :: result  !! Φ, its scale, error estimate, status, mesh
      !> err_integration when no mesh of the ladder meets the tolerance (status_failed)
      type(error_t), allocatable, intent(out) :: error
      integer :: m, j, jh, last, k
      real(wp), allocatable :: phi(:, :, :)
      real(wp) :: s(size(magnus_ladder)), estimate, previous, scale, floor, need
      integer :: previous_steps
      logical :: done(size(magnus_ladder))
      m = form%states
      allocate (phi(m, m, size(magnus_ladder)))
      done = .false.
      last = size(magnus_ladder)
      call renew_nodes(system, form, alpha, order, nodes)
      j = first_level(system, form, beta, nodes)
      if (nodes%hint > 0) j = max(j, nodes%hint)
      previous = huge(1.0_wp)
      previous_steps = 1
      result%steps = 0
      do
         jh = half_level(j)
         do k = 1, 2
            if (k == 1) then
               call ensure(jh)
            else
               call ensure(j)
            end if
         end do
         scale = max(1.0_wp, maxval(abs(phi(:, :, j))))
         estimate = safety*maxval(abs(phi(:, :, j) - phi(:, :, jh)*exp(s(jh) - s(j))))/ &
                    (2.0_wp**order - 1.0_wp)/scale
         floor = 16.0_wp*epsilon(1.0_wp)*magnus_ladder(j)
         if (.not. ieee_is_finite(estimate)) estimate = huge(1.0_wp)
         if (estimate <= tolerance) then
            result%status = status_ok
            exit
         end if
         ! round-off: the estimate hardly falls where the order says it should (by at least
         ! (8/7)^order, to a half and more between far levels)
         if (estimate <= floor .or. (estimate < 1.0e-7_wp .and. estimate > previous* &
             max(0.5_wp, min(0.9_wp, 4.0_wp*(real(previous_steps, wp)/magnus_ladder(j))**order)))) then
            result%status = status_roundoff
            exit
         end if
         if (j >= last) then
            result%status = status_failed
            call set_error(error, err_integration, "magnus: no mesh of up to "//trim(int_text(magnus_ladder(last)))// &
               " steps meets the tolerance (estimate "//trim(real_short(estimate))//")")
            exit
         end if
         previous = estimate
         previous_steps = magnus_ladder(j)
         ! the mesh the estimate asks for, by the order (at least the next level)
         need = magnus_ladder(j)*(estimate/tolerance)**(1.0_wp/order)*grow
         j = j + 1
         do while (j < last .and. (magnus_ladder(j) < need .or. .not. has_half(j)))
            j = j + 1
         end do
      end do
      ! Richardson's extrapolation: Φ_N + (Φ_N − Φ_{N/2})/(2^order − 1), its error of higher
      ! order; the estimate stays that of Φ_N (the extrapolation moves Φ by at most it)
      result%phi = phi(:, :, j)
      result%mesh = magnus_ladder(j)
      if (extrapolate .and. result%status == status_ok) result%phi = phi(:, :, j) + &
         (phi(:, :, j) - phi(:, :, jh)*exp(s(jh) - s(j)))/(2.0_wp**order - 1.0_wp)
      result%log_scale = s(j)
      result%error_estimate = max(estimate, epsilon(1.0_wp))
      ! the next point of the row (β a little larger) starts at the mesh this one's estimate
      ! asks for, with a margin
      nodes%hint = j
      if (result%status == status_ok .and. estimate > 0.0_wp) then
         need = magnus_ladder(j)*(estimate/tolerance)**(1.0_wp/order)*hint_margin
         k = 3
         do while (k < j .and. (magnus_ladder(k) < need .or. .not. has_half(k)))
            k = k + 1
         end do
         nodes%hint = k
      end if
      if (.not. all(ieee_is_finite(result%phi))) then
         result%status = status_failed
         if (.not. allocated(error)) call set_error(error, err_integration, "magnus: the monodromy is not finite")
      end if

   contains

      subroutine ensure(level)
         integer, intent(in) :: level
         if (done(level)) return
         call fill_level(system, form, alpha, order, level, nodes)
         call magnus_mesh(form, beta, order, magnus_ladder(level), nodes%levels(level), phi(:, :, level), s(level))
         result%steps = result%steps + magnus_ladder(level)
         done(level) = .true.
      end subroutine ensure
   end subroutine monodromy_magnus

   !> The ladder index of half the steps of level j.
   pure integer function half_level(j) result(jh)
      integer, intent(in) :: j
      integer :: k
      jh = 1
      do k = 1, j - 1
         if (2*magnus_ladder(k) == magnus_ladder(j)) jh = k
      end do
   end function half_level

   !> Y over the window by N Magnus steps, then Φ (from the half period when `form%half`).
   subroutine magnus_mesh(form, beta, order, steps, level, phi, log_scale)
      type(system_form_t), intent(in) :: form
      real(wp), intent(in) :: beta
      integer, intent(in) :: order, steps
      type(node_level_t), intent(in) :: level
      real(wp), intent(out) :: phi(:, :)
      real(wp), intent(out) :: log_scale
      integer :: n, m, k, i, nq
      real(wp) :: h, big
      logical :: steps_done
      real(wp) :: y(form%states, form%states), a(form%states, form%states, 3), &
                  big_omega(form%states, form%states), e(form%states, form%states)
      n = form%n
      m = form%states
      nq = merge(3, 2, order == 6)
      h = window_length(form)/steps
      y = identity(m)
      log_scale = 0.0_wp
      ! the block kernels take the second-order form; a first-order A runs on full products
      steps_done = order == 6 .and. .not. form%first_order
      if (form%first_order) then
         continue
      else if (order == 6 .and. m == 4) then
         call magnus6_steps_4(form%d, beta, h, steps, level, y, log_scale)
      else if (order == 6) then
         call magnus6_steps(n, form%d, beta, h, steps, level, y, log_scale)
      end if
      ! the constant blocks of A
      a = 0.0_wp
      if (.not. form%first_order) then
         do i = 1, nq
            do k = 1, n
               a(k, n + k, i) = 1.0_wp
            end do
            a(n + 1:m, n + 1:m, i) = form%d
         end do
      end if
      do k = 1, merge(0, steps, steps_done)
         do i = 1, nq
            if (form%first_order) then
               a(:, :, i) = level%lp(:, :, nq*(k - 1) + i) + beta*level%lb(:, :, nq*(k - 1) + i)
            else
               a(n + 1:m, 1:n, i) = level%lp(:, :, nq*(k - 1) + i) + beta*level%lb(:, :, nq*(k - 1) + i)
            end if
         end do
         big_omega = magnus_exponent(order, a(:, :, 1:nq), h)
         call system_exponential(big_omega, e)
         y = matmul(e, y)
         big = maxval(abs(y))
         if (big > 1.0e100_wp) then
            y = y*2.0_wp**(-exponent(big))
            log_scale = log_scale + exponent(big)*log(2.0_wp)
         end if
      end do
      if (form%half) then
         call full_from_half(form, y, phi)
         log_scale = 2.0_wp*log_scale
      else
         phi = y
      end if
   end subroutine magnus_mesh

   !> y' = A y for the m × m fundamental matrix, column by column.
   subroutine fundamental_rhs(self, t, y, dydt)
      class(fundamental_t), intent(inout) :: self
      real(wp), intent(in) :: t, y(:)
      real(wp), intent(out) :: dydt(:)
      call self%system%stiffness(self%alpha, t, self%p, self%b)
      call fundamental_derivative(self%form, lower_block(self%form, self%p + self%beta*self%b), y, dydt)
   end subroutine fundamental_rhs

   !> DOP853 at tolerance/10, then /320: the second value, the difference the estimate.
   subroutine monodromy_rk(system, form, alpha, beta, tolerance, result, error)
      class(hill_system_t), intent(in) :: system    !! the system
      type(system_form_t), intent(in) :: form       !! prepared at the point's ε
      real(wp), intent(in) :: alpha, beta           !! the point
      real(wp), intent(in) :: tolerance             !! target error of Φ, relative to max(1, max|Φ_ij|)
      type(system_monodromy_t), intent(out) :: result  !! Φ, its error estimate and status
      type(error_t), allocatable, intent(out) :: error  !! err_integration when DOP853 fails
      type(fundamental_t) :: f
      real(wp), allocatable :: y(:, :), first(:, :), second(:, :)
      real(wp) :: local, scale, estimate
      integer :: m, pass
      m = form%states
      call rk_context(system, form, alpha, beta, f)
      local = rk_first_tolerance(tolerance)
      result%status = status_ok
      result%steps = 0
      allocate (y(m, m), second(m, m))
      do pass = 1, 2
         call propagate_rk(f, 0.0_wp, window_length(form), local, y, result%steps, error)
         if (allocated(error)) then
            result%status = status_failed
            allocate (result%phi(m, m))
            result%phi = 0.0_wp
            return
         end if
         if (form%half) then
            call full_from_half(form, y, second)
         else
            second = y
         end if
         if (pass == 1) first = second
         local = rk_second_tolerance(local)
      end do
      scale = max(1.0_wp, maxval(abs(second)))
      estimate = maxval(abs(second - first))/scale/32.0_wp
      result%phi = second
      result%error_estimate = max(estimate, epsilon(1.0_wp))
      if (estimate > tolerance) result%status = status_roundoff
   end subroutine monodromy_rk

   !> The local tolerance of rk's first pass.
   pure real(wp) function rk_first_tolerance(tolerance) result(local)
      real(wp), intent(in) :: tolerance
      local = max(0.1_wp*tolerance, 1.0e-14_wp)
   end function rk_first_tolerance

   !> The local tolerance of rk's second pass from the first's.
   pure real(wp) function rk_second_tolerance(first) result(local)
      real(wp), intent(in) :: first
      local = max(first/320.0_wp, 1.0e-15_wp)
   end function rk_second_tolerance

   !> The right-hand side of the fundamental matrix at (α, β).
   subroutine rk_context(system, form, alpha, beta, f)
      class(hill_system_t), intent(in) :: system
      type(system_form_t), intent(in) :: form
      real(wp), intent(in) :: alpha, beta
      type(fundamental_t), intent(out) :: f
      allocate (f%system, source=system)
      f%form = form
      f%alpha = alpha
      f%beta = beta
      allocate (f%p(form%n, form%n), f%b(form%n, form%n))
   end subroutine rk_context

   !> Y' = A(τ) Y from Y(t0) = I to t1 by DOP853 at the local tolerance; its right-hand sides
   !> added to `evaluations`.
   subroutine propagate_rk(f, t0, t1, local, y, evaluations, error)
      type(fundamental_t), intent(inout) :: f
      real(wp), intent(in) :: t0, t1, local
      real(wp), intent(out) :: y(:, :)
      integer, intent(inout) :: evaluations
      type(error_t), allocatable, intent(out) :: error
      type(rk_options_t) :: options
      type(work_stats_t) :: stats
      real(wp), allocatable :: state(:)
      real(wp) :: t
      integer :: m
      m = size(y, 1)
      state = reshape(identity(m), [m*m])
      t = t0
      options = rk_options_t(method=rk_dop853, rtol=local, atol=local, max_steps=2000000)
      call rk_integrate(f, t, t1, state, options, stats=stats, error=error)
      evaluations = int(min(int(evaluations, int64) + stats%n_evaluations, int(huge(1), int64)))
      if (allocated(error)) return
      y = reshape(state, [m, m])
   end subroutine propagate_rk

   pure function int_text(i) result(text)
      integer, intent(in) :: i
      character(len=16) :: text
      write (text, '(i0)') i
   end function int_text

   pure function real_short(x) result(text)
      real(wp), intent(in) :: x
      character(len=16) :: text
      write (text, '(es9.2)') x
   end function real_short
end module hillstab_integrate_system_magnus

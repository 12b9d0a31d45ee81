!> Method `auto`: the one-period trace S to a requested tolerance, as cheaply as
!> possible, for one point or for a batch of points sharing α (a chart row).
!>
!> - Constant coefficient (α = 0): one exact transfer matrix, no error at all.
!> - Otherwise: sixth-order Magnus on the half period [0, 1] (the even symmetry of
!>   Q, BRIEF §4) on a mesh that is uniform in a Kepler-type variable ψ,
!>   tan(πτ/2) = √((1 − κ)/(1 + κ)) tan(πψ/2), κ = 1 − (1 − α/π²)^0.35, which
!>   packs steps into the dip of Q at τ = 0 whose width shrinks like √(1 − α/π²).
!>   The step count comes from a calibrated a-priori model; the error is then
!>   measured, not assumed: the same mesh with steps merged in pairs gives the
!>   Richardson estimate |S_N − S_{N/2}|/(2⁶ − 1), and the mesh is doubled until
!>   that estimate (times a safety factor) meets the tolerance.
!>
!> Speed comes from the structure of Q: for fixed α, q(τ) = c₀ + c₁ w(τ) with w
!> independent of β (elastic: w = 1/(1 − (α/π²) cos πτ), c₁ = β − π²,
!> c₀ = π² − ε²/4; Mathieu: w = cos πτ, c₁ = −ν, c₀ = β − ε²/4). A batch of
!> points shares the mesh and the w values at its Gauss nodes, so each step
!> costs three multiply-adds, a few flops for the Magnus generator and one
!> exponential of a traceless 2×2 matrix, evaluated by a short power series when
!> the step is small against the local oscillation.
!>
!>```fortran
!> real(wp) :: betas(3) = [1.0_wp, 2.0_wp, 3.0_wp]
!> type(trace_t) :: traces(3)
!> call trace_auto_batch(model_elastic, 5.0_wp, 0.0_wp, betas, 1.0e-10_wp, traces, stats, error)
!>```
module hillstab_auto
   use hillstab_kinds, only: wp, pi, pi2, log_huge
   use hillstab_error, only: error_t, set_error, err_invalid_parameter, err_integration
   use hillstab_stats, only: work_stats_t
   use hillstab_coefficient, only: hill_model_t, model_elastic, model_mathieu, check_model
   use hillstab_transfer, only: transfer_functions, trace_t
   implicit none
   private
   public :: trace_auto, trace_auto_batch, auto_initial_steps, half_period_auto, auto_mesh_power

   !> Exponent p of the mesh map: κ = 1 − (1 − α/π²)^p (measured best among 0 … 0.7).
   real(wp), parameter :: auto_mesh_power = 0.35_wp
   !> Gauss–Legendre 3-point offsets on [0, 1]: 1/2 ∓ √15/10.
   real(wp), parameter :: gauss3_offset = 0.38729833462074168851792653997823996_wp
   real(wp), parameter :: sqrt15 = 3.87298334620741688517926539978239961_wp
   !> Safety factor on the Richardson estimate.
   real(wp), parameter :: richardson_safety = 1.0_wp
   !> Largest number of Magnus steps on [0, 1].
   integer, parameter :: max_auto_steps = 2**18
   !> Rescale the propagator when an entry exceeds 2^rescale_exponent.
   integer, parameter :: rescale_exponent = 400

   !> One mesh of the half period with the shape function w at its Gauss nodes.
   type :: mesh_t
      integer :: n_steps = 0
      real(wp), allocatable :: h(:)      !! step lengths
      real(wp), allocatable :: w(:, :)   !! w at the three Gauss nodes of each step
   end type mesh_t

   !> The meshes built so far for one (model kind, α) — local to one batch call.
   type :: mesh_cache_t
      integer :: n_meshes = 0
      type(mesh_t) :: meshes(24)
   end type mesh_cache_t

contains

   !> A-priori number of Magnus-6 steps on [0, 1] (even) for the tolerance:
   !> N ≈ 0.45 (1 − α/π²)^−0.3 tol^−1/6 · max(1, (c₁² q_max/550)^{1/7}),
   !> fitted on α ∈ [0, 9.86], β ∈ [−50, 2500]; the a-posteriori check corrects it.
   pure integer function auto_initial_steps(kind, alpha, c0, c1, tolerance) result(n)
      integer, intent(in) :: kind
      real(wp), intent(in) :: alpha, c0, c1, tolerance
      real(wp) :: gap, q_max, grow, estimate
      if (kind == model_elastic) then
         gap = 1.0_wp - alpha/pi2
         q_max = max(abs(c0 + c1/gap), abs(c0 + c1/(2.0_wp - gap)))
      else
         gap = 1.0_wp
         q_max = abs(c0) + abs(c1)
      end if
      grow = max(1.0_wp, (c1*c1*q_max/550.0_wp)**(1.0_wp/7.0_wp))
      estimate = 0.45_wp*gap**(-0.3_wp)*tolerance**(-1.0_wp/6.0_wp)*grow
      n = 2*max(2, ceiling(0.5_wp*min(estimate, real(max_auto_steps, wp))))
   end function auto_initial_steps

   !> Trace S of one point by method auto.
   subroutine trace_auto(model, tolerance, tr, stats, error)
      type(hill_model_t), intent(in) :: model
      real(wp), intent(in) :: tolerance   !! target |ΔS|/max(1, |S|)
      type(trace_t), intent(out) :: tr
      type(work_stats_t), intent(out) :: stats
      type(error_t), allocatable, intent(out) :: error
      type(trace_t) :: traces(1)
      call trace_auto_batch(model%kind, model%alpha, model%epsilon, [model%beta], tolerance, traces, stats, error)
      tr = traces(1)
   end subroutine trace_auto

   !> Traces of the points (α, β_j, ε), j = 1 … size(betas), sharing meshes and w values.
   !> On error (a parameter out of range, or a tolerance that cannot be met) the
   !> remaining traces are still filled with the best values available.
   subroutine trace_auto_batch(kind, alpha, epsilon, betas, tolerance, traces, stats, error)
      integer, intent(in) :: kind            !! model_elastic or model_mathieu
      real(wp), intent(in) :: alpha          !! α (ν for the Mathieu model)
      real(wp), intent(in) :: epsilon        !! damping ε
      real(wp), intent(in) :: betas(:)       !! β values
      real(wp), intent(in) :: tolerance      !! target |ΔS|/max(1, |S|)
      type(trace_t), intent(out) :: traces(:)
      type(work_stats_t), intent(out) :: stats
      type(error_t), allocatable, intent(out) :: error
      type(mesh_cache_t) :: cache
      type(error_t), allocatable :: point_error
      real(wp) :: c0, c1
      integer :: j
      character(len=120) :: buffer
      stats = work_stats_t()
      if (.not. (tolerance > 0.0_wp .and. tolerance < 1.0_wp)) then
         call set_error(error, err_invalid_parameter, "auto: tolerance must lie in (0, 1)")
         return
      end if
      do j = 1, size(betas)
         call check_model(hill_model_t(kind, alpha, betas(j), epsilon), point_error)
         if (allocated(point_error)) then
            call move_alloc(point_error, error)
            return
         end if
      end do
      do j = 1, size(betas)
         call coefficients(kind, alpha, betas(j), epsilon, c0, c1)
         if (alpha == 0.0_wp) then
            traces(j) = constant_trace(c0 + c1*shape_at_zero_amplitude(kind))
            stats%n_steps = stats%n_steps + 1
            stats%n_evaluations = stats%n_evaluations + 1
         else
            call converge_point(kind, alpha, c0, c1, tolerance, cache, traces(j), stats, point_error)
            if (allocated(point_error) .and. .not. allocated(error)) then
               write (buffer, '(a,es10.3,a)') " (at beta = ", betas(j), ")"
               call set_error(error, point_error%code, point_error%message//trim(buffer))
            end if
         end if
      end do
   end subroutine trace_auto_batch

   !> q = c0 + c1 w(τ) for the model; see the module header.
   pure subroutine coefficients(kind, alpha, beta, epsilon, c0, c1)
      integer, intent(in) :: kind
      real(wp), intent(in) :: alpha, beta, epsilon
      real(wp), intent(out) :: c0, c1
      if (kind == model_mathieu) then
         c0 = beta - 0.25_wp*epsilon**2
         c1 = -alpha
      else
         c0 = pi2 - 0.25_wp*epsilon**2
         c1 = beta - pi2
      end if
   end subroutine coefficients

   !> w at α = 0 (constant): elastic w ≡ 1; Mathieu c1 = 0 so any value.
   pure real(wp) function shape_at_zero_amplitude(kind)
      integer, intent(in) :: kind
      shape_at_zero_amplitude = 1.0_wp
      if (kind == model_mathieu) shape_at_zero_amplitude = 0.0_wp
   end function shape_at_zero_amplitude

   !> Exact trace for constant q over the period 2.
   pure function constant_trace(q) result(tr)
      real(wp), intent(in) :: q
      type(trace_t) :: tr
      real(wp) :: c, s, log_scale
      call transfer_functions(4.0_wp*q, c, s, log_scale)   ! z = q h², h = 2
      tr%value = 2.0_wp*c
      tr%overflow = .false.
      if (c == 0.0_wp) then
         tr%log_abs = -huge(1.0_wp)
         tr%value = 0.0_wp
         return
      end if
      tr%log_abs = log(abs(2.0_wp*c)) + log_scale
      if (tr%log_abs >= log_huge) then
         tr%overflow = .true.
         tr%value = sign(huge(1.0_wp), c)
      else
         tr%value = 2.0_wp*c*exp(log_scale)
      end if
   end function constant_trace

   !> Magnus-6 with N and N/2 steps, doubling N until the Richardson estimate meets the tolerance.
   subroutine converge_point(kind, alpha, c0, c1, tolerance, cache, tr, stats, error)
      integer, intent(in) :: kind
      real(wp), intent(in) :: alpha, c0, c1, tolerance
      type(mesh_cache_t), intent(inout) :: cache
      type(trace_t), intent(out) :: tr
      type(work_stats_t), intent(inout) :: stats
      type(error_t), allocatable, intent(out) :: error
      type(trace_t) :: fine, coarse
      integer :: n, i_fine, i_coarse
      real(wp) :: estimate
      character(len=120) :: buffer
      n = auto_initial_steps(kind, alpha, c0, c1, tolerance)
      call get_mesh(cache, kind, alpha, n/2, i_coarse)
      coarse = half_period_trace(cache%meshes(i_coarse), c0, c1)
      call count_steps(stats, n/2)
      do
         call get_mesh(cache, kind, alpha, n, i_fine)
         fine = half_period_trace(cache%meshes(i_fine), c0, c1)
         call count_steps(stats, n)
         estimate = richardson_safety*trace_difference(fine, coarse)/63.0_wp
         if (estimate <= tolerance) exit
         if (2*n > max_auto_steps) then
            write (buffer, '(a,es9.2,a,es9.2)') "auto: estimated error ", estimate, " in S exceeds the tolerance ", &
               tolerance
            call set_error(error, err_integration, trim(buffer))
            exit
         end if
         coarse = fine
         n = 2*n
      end do
      tr = fine
   end subroutine converge_point

   !> Count n Magnus-6 steps: three values of q each.
   pure subroutine count_steps(stats, n)
      type(work_stats_t), intent(inout) :: stats
      integer, intent(in) :: n
      stats%n_steps = stats%n_steps + n
      stats%n_evaluations = stats%n_evaluations + 3*n
   end subroutine count_steps

   !> |S_a − S_b| / max(1, |S_a|), safe for overflowed traces (compared through ln|S|).
   pure real(wp) function trace_difference(a, b) result(d)
      type(trace_t), intent(in) :: a, b
      if (a%overflow .or. b%overflow .or. a%log_abs > 300.0_wp) then
         d = abs(a%log_abs - b%log_abs)
         if (sign(1.0_wp, a%value) /= sign(1.0_wp, b%value)) d = huge(1.0_wp)
      else
         d = abs(a%value - b%value)/max(1.0_wp, abs(a%value))
      end if
   end function trace_difference

   !> Index of the mesh with n steps in the cache, building it if needed.
   subroutine get_mesh(cache, kind, alpha, n, index)
      type(mesh_cache_t), intent(inout) :: cache
      integer, intent(in) :: kind, n
      real(wp), intent(in) :: alpha
      integer, intent(out) :: index
      integer :: i
      do i = 1, cache%n_meshes
         if (cache%meshes(i)%n_steps == n) then
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
      call build_mesh(kind, alpha, n, cache%meshes(index))
   end subroutine get_mesh

   !> τ(ψ) of the Kepler-type map on [0, 1]: tan(πτ/2) = √((1 − κ)/(1 + κ)) tan(πψ/2).
   pure real(wp) function mapped_time(psi, kappa)
      real(wp), intent(in) :: psi, kappa
      mapped_time = 2.0_wp/pi*atan2(sqrt(1.0_wp - kappa)*sin(0.5_wp*pi*psi), sqrt(1.0_wp + kappa)*cos(0.5_wp*pi*psi))
   end function mapped_time

   !> The shape function w(τ) (see the module header).
   elemental real(wp) function shape_function(kind, alpha, tau) result(w)
      integer, intent(in) :: kind
      real(wp), intent(in) :: alpha, tau
      real(wp) :: k, s
      if (kind == model_mathieu) then
         w = cos(pi*tau)
      else
         k = alpha/pi2
         s = sin(0.5_wp*pi*tau)
         w = 1.0_wp/((1.0_wp - k) + 2.0_wp*k*s*s)   ! 1/(1 − k cos πτ), accurate as k → 1
      end if
   end function shape_function

   !> Mesh of n steps on [0, 1], uniform in ψ, with w at the Gauss nodes.
   pure subroutine build_mesh(kind, alpha, n, mesh)
      integer, intent(in) :: kind, n
      real(wp), intent(in) :: alpha
      type(mesh_t), intent(out) :: mesh
      real(wp) :: kappa, t0, t1, h
      integer :: i
      kappa = 0.0_wp
      if (kind == model_elastic) kappa = 1.0_wp - (1.0_wp - alpha/pi2)**auto_mesh_power
      mesh%n_steps = n
      allocate (mesh%h(n), mesh%w(3, n))
      t0 = 0.0_wp
      do i = 1, n
         t1 = mapped_time(real(i, wp)/n, kappa)
         if (i == n) t1 = 1.0_wp
         h = t1 - t0
         mesh%h(i) = h
         mesh%w(:, i) = shape_function(kind, alpha, [t0 + (0.5_wp - gauss3_offset)*h, t0 + 0.5_wp*h, &
                                                      t0 + (0.5_wp + gauss3_offset)*h])
         t0 = t1
      end do
   end subroutine build_mesh

   !> Φ(1) of the half period by Magnus-6 on `mesh` for q = c0 + c1 w, returned
   !> with a log scale: Φ = e^{log_scale} phi.
   pure subroutine half_period_auto(mesh, c0, c1, phi, log_scale)
      type(mesh_t), intent(in) :: mesh
      real(wp), intent(in) :: c0, c1
      real(wp), intent(out) :: phi(2, 2), log_scale
      real(wp) :: q1, q2, q3, h, ga, gb, gc, z, c, s, ls, e11, e12, e21, e22, p11, p21, big
      integer :: i, shift
      phi = reshape([1.0_wp, 0.0_wp, 0.0_wp, 1.0_wp], [2, 2])
      log_scale = 0.0_wp
      do i = 1, mesh%n_steps
         h = mesh%h(i)
         q1 = c0 + c1*mesh%w(1, i)
         q2 = c0 + c1*mesh%w(2, i)
         q3 = c0 + c1*mesh%w(3, i)
         call magnus6_sl2(q1, q2, q3, h, ga, gb, gc)
         z = -(ga*ga + gb*gc)
         call exp_functions(z, c, s, ls)
         e11 = c + s*ga; e12 = s*gb
         e21 = s*gc; e22 = c - s*ga
         p11 = phi(1, 1); p21 = phi(2, 1)
         phi(1, 1) = e11*p11 + e12*p21
         phi(2, 1) = e21*p11 + e22*p21
         p11 = phi(1, 2); p21 = phi(2, 2)
         phi(1, 2) = e11*p11 + e12*p21
         phi(2, 2) = e21*p11 + e22*p21
         log_scale = log_scale + ls
         if (ls > 0.0_wp .or. iand(i, 7) == 0) then
            big = maxval(abs(phi))
            if (big > 2.0_wp**rescale_exponent .or. big < 2.0_wp**(-rescale_exponent)) then
               shift = exponent(big)
               phi = scale(phi, -shift)
               log_scale = log_scale + shift*log(2.0_wp)
            end if
         end if
      end do
   end subroutine half_period_auto

   !> S = 2(u v' + u' v) from Φ(1) = [[u, v], [u', v']] (BRIEF §4).
   pure function half_period_trace(mesh, c0, c1) result(tr)
      type(mesh_t), intent(in) :: mesh
      real(wp), intent(in) :: c0, c1
      type(trace_t) :: tr
      real(wp) :: phi(2, 2), log_scale, t
      call half_period_auto(mesh, c0, c1, phi, log_scale)
      t = 2.0_wp*(phi(1, 1)*phi(2, 2) + phi(2, 1)*phi(1, 2))
      tr%overflow = .false.
      if (t == 0.0_wp) then
         tr%value = 0.0_wp
         tr%log_abs = -huge(1.0_wp)
         return
      end if
      tr%log_abs = log(abs(t)) + 2.0_wp*log_scale
      if (tr%log_abs >= log_huge) then
         tr%overflow = .true.
         tr%value = sign(huge(1.0_wp), t)
      else
         tr%value = t*exp(2.0_wp*log_scale)
      end if
   end function half_period_trace

   !> Sixth-order Gauss–Legendre Magnus generator Ω = [[a, b], [c, −a]] for
   !> A = [[0, 1], [−q, 0]] from q at the three Gauss nodes (Blanes, Casas, Oteo,
   !> Ros, Phys. Rep. 470 (2009) §5; same formula as `magnus6_generator` of
   !> hillstab_magnus, written out in components: α₂, α₃ have only a lower-left entry).
   pure subroutine magnus6_sl2(q1, q2, q3, h, ga, gb, gc)
      real(wp), intent(in) :: q1, q2, q3, h
      real(wp), intent(out) :: ga, gb, gc
      real(wp), parameter :: c_d2 = -sqrt15/3.0_wp, c_d3 = -10.0_wp/3.0_wp, c_60 = 1.0_wp/30.0_wp
      real(wp), parameter :: c_240 = 1.0_wp/240.0_wp, c_120 = 1.0_wp/120.0_wp, c_12 = 1.0_wp/12.0_wp
      real(wp) :: d2, d3, x1, x2, x3, y1, y2, y3, hh
      hh = h*h
      ! α1 = [0, h, −h q2], α2 = [0, 0, d2], α3 = [0, 0, d3]
      d2 = c_d2*h*(q3 - q1)
      d3 = c_d3*h*((q3 - q2) + (q1 - q2))
      ! X = −20 α1 − α3 + C1, C1 = [α1, α2] = [h d2, 0, 0]
      x1 = h*d2
      x2 = -20.0_wp*h
      x3 = 20.0_wp*h*q2 - d3
      ! Y = α2 + C2, C2 = −[α1, 2 α3 + C1]/60 = −[2 h d3, −2 h² d2, −2 h² q2 d2]/60
      y1 = -c_60*h*d3
      y2 = c_60*hh*d2
      y3 = d2 + c_60*hh*q2*d2
      ! Ω = α1 + α3/12 + [X, Y]/240, [x, y] = (x2 y3 − x3 y2, 2(x1 y2 − x2 y1), 2(x3 y1 − x1 y3))
      ga = c_240*(x2*y3 - x3*y2)
      gb = h + c_120*(x1*y2 - x2*y1)
      gc = -h*q2 + c_12*d3 + c_120*(x3*y1 - x1*y3)
   end subroutine magnus6_sl2

   !> C = cos √z, S = sin √z/√z: a degree-7 polynomial for |z| ≤ 0.1 (truncation
   !> below 1e-21), otherwise the overflow-safe `transfer_functions`.
   pure subroutine exp_functions(z, c, s, log_scale)
      real(wp), intent(in) :: z
      real(wp), intent(out) :: c, s, log_scale
      if (abs(z) <= 0.1_wp) then
         c = 1.0_wp + z*(-1.0_wp/2 + z*(1.0_wp/24 + z*(-1.0_wp/720 + z*(1.0_wp/40320 + z*(-1.0_wp/3628800 &
             + z*(1.0_wp/479001600 + z*(-1.0_wp/87178291200.0_wp)))))))
         s = 1.0_wp + z*(-1.0_wp/6 + z*(1.0_wp/120 + z*(-1.0_wp/5040 + z*(1.0_wp/362880 + z*(-1.0_wp/39916800 &
             + z*(1.0_wp/6227020800.0_wp + z*(-1.0_wp/1307674368000.0_wp)))))))
         log_scale = 0.0_wp
      else
         call transfer_functions(z, c, s, log_scale)
      end if
   end subroutine exp_functions
end module hillstab_auto

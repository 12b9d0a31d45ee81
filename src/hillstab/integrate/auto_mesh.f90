!> Method auto's meshes (hillstab_integrate_auto): steps over the model's window and the
!> shape function w at their three Gauss nodes, built once for a batch and shared by its
!> points. On [0, 1] (half a period of a q even about 0, no jump) the steps are uniform in
!> the variable ψ of the Kepler-type map tan(πτ/2) = √((1 − κ)/(1 + κ)) tan(πψ/2) that
!> packs them into the dip of the elastic Q at τ = 0; on any other window they are uniform
!> in τ on each piece between the jumps of Q. A model with an offset (q = c₀ + c₁ w + v) has
!> v at the nodes too.
module hillstab_integrate_auto_mesh
   use hillstab_core_kinds, only: wp, pi
   use hillstab_hill_model, only: hill_model_t, hill_window_t
   use hillstab_hill_transfer, only: cos_taylor, sinc_taylor
   implicit none
   private
   public :: mesh_t, mesh_cache_t, get_mesh, build_mesh, auto_mesh_power, gauss3_offset

   !> Exponent p of the mesh map: κ = 1 − (1 − α/π²)^p (measured best among 0 … 0.7).
   real(wp), parameter :: auto_mesh_power = 0.35_wp
   !> Gauss–Legendre 3-point offsets on [0, 1]: 1/2 ∓ √15/10.
   real(wp), parameter :: gauss3_offset = 0.38729833462074168851792653997823996_wp

   !> One mesh of the model's window (half a period of an even q, or the period) with the
   !> shape function w at its Gauss nodes.
   type :: mesh_t
      integer :: key = 0                 !! the step count it was asked for (its cache key)
      logical :: half = .true.           !! the window is half a period: S = 2(u v' + u' v)
      integer :: n_steps = 0             !! number of steps
      real(wp), allocatable :: h(:)      !! step lengths
      real(wp), allocatable :: w(:, :)   !! w at the three Gauss nodes of each step
      !> the offset v at the Gauss nodes, for a model that `has_offset` (q = c₀ + c₁ w + v)
      real(wp), allocatable :: v(:, :)
      !> max |v| over the mesh (0 without an offset): counted with |c₀| in the round-off level
      real(wp) :: offset_size = 0.0_wp
   end type mesh_t

   !> The meshes built so far for one (model kind, α) — local to one batch call.
   type :: mesh_cache_t
      integer :: n_meshes = 0            !! meshes held
      type(mesh_t) :: meshes(40)         !! the meshes, the first n_meshes in use
   end type mesh_cache_t

contains

   !> Index of the mesh with n steps in the cache, building it if needed.
   subroutine get_mesh(cache, model, alpha, n, index)
      type(mesh_cache_t), intent(inout) :: cache  !! the meshes of this batch call
      class(hill_model_t), intent(in) :: model    !! the model whose window and shape w it meshes
      integer, intent(in) :: n                    !! steps per unit of τ
      real(wp), intent(in) :: alpha               !! α, for the Kepler-type map of the pendulum
      integer, intent(out) :: index               !! position of the mesh in cache%meshes
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
      class(hill_model_t), intent(in) :: model  !! the model whose window and shape w it meshes
      integer, intent(in) :: n                  !! steps per unit of τ
      real(wp), intent(in) :: alpha             !! α, for the Kepler-type map of the pendulum
      type(mesh_t), intent(out) :: mesh         !! the mesh, its key n
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
      if (model%has_offset()) then
         ! v from τ = (2/π) asin(sin(πτ/2)) at the nodes (the sines overwritten by v)
         call model%offsets(alpha, (2.0_wp/pi)*asin(min(1.0_wp, max(-1.0_wp, work(1:3*n)))), work(1:3*n))
         mesh%v = reshape(work(1:3*n), [3, n])
         mesh%offset_size = maxval(abs(mesh%v))
      end if
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
      if (model%has_offset()) then
         call model%offsets(alpha, reshape(taus, [3*mesh%n_steps]), w)
         mesh%v = reshape(w, [3, mesh%n_steps])
         mesh%offset_size = maxval(abs(mesh%v))
      end if
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
end module hillstab_integrate_auto_mesh

!> A stability oracle: for one problem (a scalar model with the scene's damping, or a system),
!> the signed distance of a point from the threshold of stability with its error bound, and
!> the natural frequencies of the undriven problem. The point is given in the searcher's
!> terms, a frequency-like coordinate f and a drive d; `drive_axis` says which of the model's
!> coordinates is the drive (along_alpha: d = α, f = β, as for the built-in models whose α is
!> the drive amplitude; along_beta: d = β, f = α, as for an equation in physical time whose
!> rows are its frequency and whose β is a drive amplitude).
!>
!> The distance g is positive exactly where the point is unstable:
!> - a scalar model: g = σ S − T with T = 2 cosh(εP/2) (S of χ = e^{ετ/2} x when damped), for
!>   the side σ = +1 or −1 asked (the two families of tongues, multipliers near +1 and −1), or
!>   the larger of the two for side 0;
!> - a system: g = ln max|λ| when damped; when it is Hamiltonian (every multiplier on the unit
!>   circle while stable) g = ln max|λ| − m with m = 100 × (the method's tolerance), so that the
!>   stable side is negative and the root sits where |λ| first exceeds 1 beyond round-off.
!>
!> The natural frequencies, as fractions ν_i of the drive frequency (ν = ω P/(2π), ω in the
!> τ units of the model, P its period), are those of the problem at drive 0 with its
!> coefficient averaged over a period (exact when the undriven problem is constant, Hill's
!> first approximation otherwise): a scalar model's √(mean Q) P/(2π) (none where mean Q ≤ 0),
!> a system's the positive imaginary parts of the eigenvalues of its first-order matrix.
!> Parametric resonance of order k lies where 2ν_i = k (simple), ν_i + ν_j = k (sum) or
!> |ν_i − ν_j| = k (difference).
module hillstab_curves_oracle
   use hillstab_core_kinds, only: wp, pi
   use hillstab_core_error, only: error_t, set_error, err_invalid_parameter, err_accuracy
   use hillstab_core_status, only: status_failed
   use hillstab_ffi_lapack, only: dgeev
   use hillstab_hill_model, only: hill_model_t, hill_point_t, check_point, damping_at
   use hillstab_hill_transfer, only: trace_t
   use hillstab_hill_floquet, only: period_damping
   use hillstab_hill_system, only: hill_system_t, system_form_t, prepare_system, check_system_point
   use hillstab_hill_system_floquet, only: floquet_t
   use hillstab_integrate_monodromy, only: method_t, monodromy_trace
   use hillstab_integrate_system, only: system_method_t, system_monodromy_t, system_nodes_t
   use hillstab_integrate_system_point, only: system_point
   use hillstab_curves_critical, only: along_alpha, along_beta
   implicit none
   private
   public :: oracle_t, scalar_oracle_t, system_oracle_t, oracle_sample_t

   !> Nodes of a period for the mean of the undriven coefficient (exact for its harmonics up
   !> to 31; beyond, a first approximation as the mean itself is).
   integer, parameter :: mean_nodes = 32

   !> One evaluation of the distance.
   type :: oracle_sample_t
      real(wp) :: g = 0.0_wp       !! the signed distance (±huge where the monodromy overflows)
      real(wp) :: bound = 0.0_wp   !! its error bound (absolute)
   end type oracle_sample_t

   !> The oracle's interface (see the module's text).
   type, abstract :: oracle_t
      integer :: drive_axis = along_beta  !! which model coordinate is the drive
   contains
      procedure(distance_interface), deferred :: distance
      procedure(natural_interface), deferred :: natural
      procedure(damped_interface), deferred :: damped
      procedure(check_interface), deferred :: check
      procedure :: coordinates
      procedure :: signatures_agree => no_signatures
      procedure :: driven
   end type oracle_t

   abstract interface
      !> The signed distance at (f, d) for one family of regions: the side σ of a scalar
      !> model's trace, the argument of a system's multipliers.
      subroutine distance_interface(self, f, d, side, argument, s, error)
         import :: oracle_t, oracle_sample_t, wp, error_t
         class(oracle_t), intent(in) :: self
         real(wp), intent(in) :: f, d   !! frequency-like coordinate, drive
         integer, intent(in) :: side    !! scalar models: +1, −1 or 0 (either)
         !> for systems, the multipliers' argument/π the family's instability sets in at: 0 the
         !> real positive multipliers, 1 the real negative, between the complex ones (a
         !> combination region); negative: the largest modulus of all
         real(wp), intent(in) :: argument
         type(oracle_sample_t), intent(out) :: s
         !> a point the method cannot compute
         type(error_t), allocatable, intent(out) :: error
      end subroutine distance_interface

      !> The natural frequencies ν_i (fractions of the drive frequency) at f and drive 0,
      !> ascending (empty where there is none).
      subroutine natural_interface(self, f, nu, error)
         import :: oracle_t, wp, error_t
         class(oracle_t), intent(in) :: self
         real(wp), intent(in) :: f
         real(wp), allocatable, intent(out) :: nu(:)
         type(error_t), allocatable, intent(out) :: error
      end subroutine natural_interface

      !> Whether the problem at f has damping (its tongues' tips then lie above drive 0).
      logical function damped_interface(self, f)
         import :: oracle_t, wp
         class(oracle_t), intent(in) :: self
         real(wp), intent(in) :: f
      end function damped_interface

      !> The point (f, d) checked against the problem's domain (err_invalid_parameter).
      subroutine check_interface(self, f, d, error)
         import :: oracle_t, wp, error_t
         class(oracle_t), intent(in) :: self
         real(wp), intent(in) :: f, d
         type(error_t), allocatable, intent(out) :: error
      end subroutine check_interface
   end interface

   !> A scalar model x'' + ε x' + Q(α, β, τ) x = 0 (ε the model's `point_damping`).
   type, extends(oracle_t) :: scalar_oracle_t
      class(hill_model_t), allocatable :: model  !! the model of Q
      type(method_t) :: method                   !! the method of S and its tolerance
      real(wp) :: epsilon = 0.0_wp               !! the scene's damping (0 for a model with its own)
   contains
      procedure :: distance => scalar_distance
      procedure :: natural => scalar_natural
      procedure :: damped => scalar_damped
      procedure :: check => scalar_check
   end type scalar_oracle_t

   !> A system M x'' + (C + εM + G) x' + K(α, β, τ) x = 0.
   type, extends(oracle_t) :: system_oracle_t
      class(hill_system_t), allocatable :: system  !! the system
      type(system_method_t) :: method              !! the method of Φ and its tolerance
      real(wp) :: epsilon = 0.0_wp                 !! the scene's damping ε
   contains
      procedure :: distance => system_distance
      procedure :: natural => system_natural
      procedure :: damped => system_damped
      procedure :: check => system_check
      procedure :: signatures_agree => system_signatures_agree
   end type system_oracle_t

contains

   !> The model's (α, β) of the searcher's (f, d).
   pure subroutine coordinates(self, f, d, alpha, beta)
      class(oracle_t), intent(in) :: self
      real(wp), intent(in) :: f, d
      real(wp), intent(out) :: alpha, beta
      if (self%drive_axis == along_alpha) then
         alpha = d
         beta = f
      else
         alpha = f
         beta = d
      end if
   end subroutine coordinates

   !> Whether the drive changes the problem's time dependence at f: the coefficient (a system's
   !> stiffness) at drive d less that at drive 0 is not constant over a period (both points
   !> checked by `check` beforehand).
   logical function driven(self, f, d)
      class(oracle_t), intent(in) :: self
      real(wp), intent(in) :: f, d
      integer, parameter :: nodes = 64
      real(wp) :: a0, b0, a1, b1, tau(nodes), dq(nodes), period, scale
      real(wp), allocatable :: p0(:, :), q0(:, :), p1(:, :), q1(:, :), first(:, :), delta(:, :)
      class(hill_system_t), allocatable :: at0, at1
      integer :: j, n
      call self%coordinates(f, 0.0_wp, a0, b0)
      call self%coordinates(f, d, a1, b1)
      driven = .false.
      select type (self)
      type is (scalar_oracle_t)
         period = self%model%period()
         tau = [(period*real(j - 1, wp)/nodes, j=1, nodes)]
         dq = self%model%coefficient(a1, b1, tau) - self%model%coefficient(a0, b0, tau)
         scale = max(1.0_wp, maxval(abs(dq)))
         driven = maxval(dq) - minval(dq) > 1.0e-12_wp*scale
      type is (system_oracle_t)
         n = self%system%dof()
         period = self%system%period()
         allocate (p0(n, n), q0(n, n), p1(n, n), q1(n, n), first(n, n), delta(n, n))
         if (.not. self%system%shares_rows()) then
            ! each point's K is the system's at its β
            call self%system%at_point(a0, b0, at0)
            call self%system%at_point(a1, b1, at1)
         end if
         do j = 1, nodes
            if (allocated(at0)) then
               call at0%stiffness(a0, period*real(j - 1, wp)/nodes, p0, q0)
               call at1%stiffness(a1, period*real(j - 1, wp)/nodes, p1, q1)
            else
               call self%system%stiffness(a0, period*real(j - 1, wp)/nodes, p0, q0)
               call self%system%stiffness(a1, period*real(j - 1, wp)/nodes, p1, q1)
            end if
            delta = (p1 + b1*q1) - (p0 + b0*q0)
            if (j == 1) first = delta
            if (maxval(abs(delta - first)) > 1.0e-12_wp*max(1.0_wp, maxval(abs(first)))) driven = .true.
         end do
      end select
   end function driven

   !> Whether every mode of the undriven problem at f has the same Krein signature (none for
   !> a scalar model: it has one mode).
   logical function no_signatures(self, f)
      class(oracle_t), intent(in) :: self
      real(wp), intent(in) :: f
      no_signatures = .false.
   end function no_signatures

   !> The scalar model's point at (f, d), its damping the model's there.
   function scalar_point(self, f, d) result(point)
      class(scalar_oracle_t), intent(in) :: self
      real(wp), intent(in) :: f, d
      type(hill_point_t) :: point
      call self%coordinates(f, d, point%alpha, point%beta)
      point%epsilon = damping_at(self%model, point%alpha, point%beta, self%epsilon)
   end function scalar_point

   subroutine scalar_distance(self, f, d, side, argument, s, error)
      class(scalar_oracle_t), intent(in) :: self
      real(wp), intent(in) :: f, d
      integer, intent(in) :: side
      real(wp), intent(in) :: argument
      type(oracle_sample_t), intent(out) :: s
      type(error_t), allocatable, intent(out) :: error
      type(hill_point_t) :: point
      type(trace_t) :: tr
      real(wp) :: threshold, g(2)
      point = scalar_point(self, f, d)
      threshold = 2.0_wp*cosh(min(period_damping(point%epsilon, self%model%period()), 700.0_wp))
      call monodromy_trace(self%model, point, self%method, tr, error)
      if (allocated(error)) then
         if (error%code /= err_accuracy) return
         deallocate (error)
      end if
      if (tr%overflow) then
         g = [sign(huge(1.0_wp), tr%value), -sign(huge(1.0_wp), tr%value)]
         s%bound = 0.0_wp
      else
         g = [tr%value - threshold, -tr%value - threshold]
         s%bound = max(tr%error_estimate, self%method%tolerance)*max(1.0_wp, abs(tr%value))
      end if
      select case (side)
      case (1)
         s%g = g(1)
      case (-1)
         s%g = g(2)
      case default
         s%g = maxval(g)
      end select
   end subroutine scalar_distance

   subroutine scalar_natural(self, f, nu, error)
      class(scalar_oracle_t), intent(in) :: self
      real(wp), intent(in) :: f
      real(wp), allocatable, intent(out) :: nu(:)
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: tau(mean_nodes), alpha, beta, mean, period
      integer :: j
      call self%check(f, 0.0_wp, error)
      if (allocated(error)) return
      call self%coordinates(f, 0.0_wp, alpha, beta)
      period = self%model%period()
      tau = [(period*real(j - 1, wp)/real(mean_nodes, wp), j=1, mean_nodes)]
      mean = sum(self%model%coefficient(alpha, beta, tau)/real(mean_nodes, wp))
      if (.not. (abs(mean) < huge(1.0_wp))) then
         call set_error(error, err_invalid_parameter, "the undriven coefficient is not finite")
         return
      end if
      if (mean > 0.0_wp) then
         nu = [sqrt(mean)*period/(2.0_wp*pi)]
      else
         allocate (nu(0))
      end if
   end subroutine scalar_natural

   logical function scalar_damped(self, f)
      class(scalar_oracle_t), intent(in) :: self
      real(wp), intent(in) :: f
      type(hill_point_t) :: point
      point = scalar_point(self, f, 0.0_wp)
      scalar_damped = point%epsilon > 0.0_wp
   end function scalar_damped

   subroutine scalar_check(self, f, d, error)
      class(scalar_oracle_t), intent(in) :: self
      real(wp), intent(in) :: f, d
      type(error_t), allocatable, intent(out) :: error
      call check_point(self%model, scalar_point(self, f, d), error)
   end subroutine scalar_check

   !> The system's form at the row of (f, d); where the system does not share rows, the
   !> system at the point's β (`local`, allocated), its form there and the point (α, 0).
   subroutine system_form(self, f, d, form, alpha, beta, error, local)
      class(system_oracle_t), intent(in) :: self
      real(wp), intent(in) :: f, d
      type(system_form_t), intent(out) :: form
      real(wp), intent(out) :: alpha, beta
      type(error_t), allocatable, intent(out) :: error
      class(hill_system_t), allocatable, intent(out) :: local
      call self%coordinates(f, d, alpha, beta)
      if (self%system%shares_rows()) then
         call prepare_system(self%system, self%epsilon, form, error, alpha)
      else
         call self%system%at_point(alpha, beta, local)
         beta = 0.0_wp
         call prepare_system(local, self%epsilon, form, error, alpha)
      end if
   end subroutine system_form

   subroutine system_distance(self, f, d, side, argument, s, error)
      class(system_oracle_t), intent(in) :: self
      real(wp), intent(in) :: f, d
      integer, intent(in) :: side
      real(wp), intent(in) :: argument
      type(oracle_sample_t), intent(out) :: s
      type(error_t), allocatable, intent(out) :: error
      type(system_form_t) :: form
      type(system_nodes_t) :: nodes
      type(system_monodromy_t) :: monodromy
      type(floquet_t) :: floquet
      class(hill_system_t), allocatable :: local
      real(wp) :: alpha, beta, margin
      if (side < -1 .or. side > 1) then
         call set_error(error, err_invalid_parameter, "side: must be -1, 0 or 1")
         return
      end if
      call system_form(self, f, d, form, alpha, beta, error, local)
      if (allocated(error)) return
      if (allocated(local)) then
         call system_point(local, form, alpha, beta, self%method, nodes, monodromy, floquet, error)
      else
         call system_point(self%system, form, alpha, beta, self%method, nodes, monodromy, floquet, error)
      end if
      if (allocated(error)) return
      if (monodromy%status == status_failed) then
         call set_error(error, err_invalid_parameter, "the monodromy failed")
         return
      end if
      margin = 0.0_wp
      if (form%hamiltonian) margin = 100.0_wp*self%method%tolerance
      s%g = family_log_modulus(floquet, argument) - margin
      ! the error of ln|λ|: Φ's relative to its largest entry, over the multiplier's size
      s%bound = max(monodromy%error_estimate, self%method%tolerance)* &
                exp(min(max(0.0_wp, log(max(1.0_wp, maxval(abs(monodromy%phi)))) + monodromy%log_scale - &
                                    floquet%log_modulus(1)), 50.0_wp))
   end subroutine system_distance

   subroutine system_natural(self, f, nu, error)
      class(system_oracle_t), intent(in) :: self
      real(wp), intent(in) :: f
      real(wp), allocatable, intent(out) :: nu(:)
      type(error_t), allocatable, intent(out) :: error
      type(system_form_t) :: form
      real(wp), allocatable :: k(:, :), a(:, :), wr(:), wi(:), work(:), vl(:, :)
      integer :: n, m, j, info
      call undriven_stiffness(self, f, form, k, error)
      if (allocated(error)) return
      n = form%n
      m = 2*n
      allocate (a(m, m), wr(m), wi(m), work(8*m), vl(1, 1))
      a = 0.0_wp
      do j = 1, n
         a(j, n + j) = 1.0_wp
      end do
      a(n + 1:m, 1:n) = -matmul(form%m_inverse, k)
      a(n + 1:m, n + 1:m) = form%d
      if (.not. all(abs(a) < huge(1.0_wp))) then
         call set_error(error, err_invalid_parameter, "the undriven stiffness is not finite")
         return
      end if
      call dgeev('N', 'N', m, a, m, wr, wi, vl, 1, vl, 1, work, size(work), info)
      if (info /= 0) then
         call set_error(error, err_invalid_parameter, "the undriven system's eigenvalues did not converge")
         return
      end if
      nu = pack(wi, wi > 0.0_wp)*form%period/(2.0_wp*pi)
      call sort(nu)
   end subroutine system_natural

   !> The system's form at f and its stiffness at drive 0 averaged over a period.
   subroutine undriven_stiffness(self, f, form, k, error)
      class(system_oracle_t), intent(in) :: self
      real(wp), intent(in) :: f
      type(system_form_t), intent(out) :: form
      real(wp), allocatable, intent(out) :: k(:, :)
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: alpha, beta, tau
      real(wp), allocatable :: p(:, :), b(:, :)
      class(hill_system_t), allocatable :: local
      integer :: n, j
      call system_form(self, f, 0.0_wp, form, alpha, beta, error, local)
      if (allocated(error)) return
      n = form%n
      allocate (k(n, n), p(n, n), b(n, n))
      k = 0.0_wp
      do j = 1, mean_nodes
         tau = form%period*real(j - 1, wp)/real(mean_nodes, wp)
         if (allocated(local)) then
            call local%stiffness(alpha, tau, p, b)
         else
            call self%system%stiffness(alpha, tau, p, b)
         end if
         k = k + p + beta*b
      end do
      k = k/real(mean_nodes, wp)
   end subroutine undriven_stiffness

   logical function system_damped(self, f)
      class(system_oracle_t), intent(in) :: self
      real(wp), intent(in) :: f
      type(system_form_t) :: form
      type(error_t), allocatable :: error
      class(hill_system_t), allocatable :: local
      real(wp) :: alpha, beta
      call system_form(self, f, 0.0_wp, form, alpha, beta, error, local)
      system_damped = .true.
      if (.not. allocated(error)) system_damped = .not. form%hamiltonian
   end function system_damped

   subroutine system_check(self, f, d, error)
      class(system_oracle_t), intent(in) :: self
      real(wp), intent(in) :: f, d
      type(error_t), allocatable, intent(out) :: error
      type(system_form_t) :: form
      class(hill_system_t), allocatable :: local
      real(wp) :: alpha, beta
      call system_form(self, f, d, form, alpha, beta, error, local)
      if (allocated(error)) return
      if (allocated(local)) then
         call check_system_point(local, alpha, beta, error)
      else
         call check_system_point(self%system, alpha, beta, error)
      end if
   end subroutine system_check

   !> ln|λ| of the family at `argument` (see `distance_interface`), or of all multipliers when
   !> it is negative. A simple region's multipliers leave the circle as a real pair: of sign
   !> +1 for argument 0, −1 for argument 1; the family is those real multipliers, and where
   !> there are none (the pair still complex) the nearest multiplier's ln|λ| less π times its
   !> argument's distance, continuous through the collision on the axis. A combination
   !> region's (argument in (0, 1)) leave it as complex multipliers of two modes, which,
   !> damped, need not share an argument: the family is every multiplier off the real axis
   !> (−1 where there is none). Regions of one family in one window are told apart by the
   !> window only.
   pure real(wp) function family_log_modulus(floquet, argument) result(g)
      type(floquet_t), intent(in) :: floquet
      real(wp), intent(in) :: argument
      real(wp) :: modulus(size(floquet%multipliers)), distance(size(floquet%multipliers))
      integer :: i, nearest
      if (argument < 0.0_wp .or. size(floquet%multipliers) == 0) then
         g = floquet%log_modulus(1)
         return
      end if
      modulus = abs(floquet%multipliers)
      g = -huge(1.0_wp)
      if (argument == 0.0_wp .or. argument == 1.0_wp) then
         do i = 1, size(modulus)
            if (modulus(i) > 0.0_wp .and. aimag(floquet%multipliers(i)) == 0.0_wp .and. &
                (real(floquet%multipliers(i)) > 0.0_wp .eqv. argument == 0.0_wp)) &
               g = max(g, floquet%log_scale + log(modulus(i)))
         end do
         if (g > -huge(1.0_wp)) return
         distance = abs(abs(atan2(aimag(floquet%multipliers), real(floquet%multipliers)))/pi - argument)
         nearest = minloc(distance, dim=1, mask=modulus > 0.0_wp)
         if (nearest > 0) g = floquet%log_scale + log(modulus(nearest)) - pi*distance(nearest)
         return
      end if
      do i = 1, size(modulus)
         if (modulus(i) > 0.0_wp .and. aimag(floquet%multipliers(i)) /= 0.0_wp) &
            g = max(g, floquet%log_scale + log(modulus(i)))
      end do
      if (g == -huge(1.0_wp)) g = -1.0_wp
   end function family_log_modulus

   !> A system without gyroscopic terms whose averaged undriven stiffness is positive definite
   !> (its Cholesky factor exists): every mode's Krein signature is the same.
   logical function system_signatures_agree(self, f)
      class(system_oracle_t), intent(in) :: self
      real(wp), intent(in) :: f
      type(system_form_t) :: form
      type(error_t), allocatable :: error
      real(wp), allocatable :: k(:, :)
      integer :: n, i, j, l
      system_signatures_agree = .false.
      call undriven_stiffness(self, f, form, k, error)
      if (allocated(error) .or. form%gyroscopic) return
      n = form%n
      k = 0.5_wp*(k + transpose(k))
      ! Cholesky in place: positive definite when every pivot is positive
      do j = 1, n
         do l = 1, j - 1
            k(j:n, j) = k(j:n, j) - k(j:n, l)*k(j, l)
         end do
         if (.not. (k(j, j) > 0.0_wp)) return
         k(j, j) = sqrt(k(j, j))
         do i = j + 1, n
            k(i, j) = k(i, j)/k(j, j)
         end do
      end do
      system_signatures_agree = .true.
   end function system_signatures_agree

   !> Ascending order, in place (insertion: a handful of values).
   pure subroutine sort(x)
      real(wp), intent(inout) :: x(:)
      real(wp) :: t
      integer :: i, j
      do i = 2, size(x)
         t = x(i)
         j = i - 1
         do while (j >= 1)
            if (x(j) <= t) exit
            x(j + 1) = x(j)
            j = j - 1
         end do
         x(j + 1) = t
      end do
   end subroutine sort
end module hillstab_curves_oracle

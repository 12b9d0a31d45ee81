!> A system of Hill equations: n coupled degrees of freedom
!>
!>     M x'' + (C + ε M + G) x' + K(τ; α, β) x = 0,   K = P(τ; α) + β B(τ; α),   x in Rⁿ,
!>
!> M symmetric positive definite (the masses), C symmetric (damping; the scene's ε adds the
!> mass-proportional part ε M), G skew (gyroscopic), K periodic in τ with period `period()`
!> and affine in β as every scalar model is (a system whose β enters elsewhere is taken a
!> point at a time, as the system at the point's β: `shares_rows`, `at_point`). The abstract type `hill_system_t` extends
!> `model_base_t` (name, formula, the variables of a model carrying data) and is what the
!> system methods (hillstab_integrate_system) and verdicts (hillstab_hill_system_floquet)
!> receive; they never ask which system it is. Concrete systems: the matrix system of the
!> scenes (hillstab_hill_system_matrix: K = K0 + β B + α Σ (K_kᶜ cos kπτ' + K_kˢ sin kπτ'))
!> and any scalar model as a system of one equation (hillstab_hill_system_scalar).
!>
!> A system may instead be given in first-order form, y' = A(τ) y with y in Rⁿ (n states;
!> `first_order` true): its `stiffness` then gives A itself, A = p + β b, and it has no mass,
!> damping or gyroscopic matrix. The Magnus methods integrate the full A (no blocks, no
!> balancing), rk and gsl the same right-hand side; its verdicts are those of a
!> non-Hamiltonian system, and all its n exponents are reported.
!>
!> `system_form_t` is what the methods need of a system at one damping, prepared once:
!> M⁻¹ (Cholesky), the constant block D = −M⁻¹(C + εM + G) of the first-order matrix
!> A(τ) = [[0, I], [−M⁻¹K(τ), D]] acting on y = (x, x'), whether the system is Hamiltonian
!> (C = 0, ε = 0, K symmetric: the monodromy Φ keeps the form Ω = [[G, M], [−M, 0]],
!> ΦᵀΩΦ = Ω, and its multipliers come in pairs λ, 1/λ) and whether half a period is enough
!> (Hamiltonian, G = 0 and K even about the window's start: Φ = R Y⁻¹ R Y with Y the
!> solution over half the period and R = diag(I, −I)).
!>
!>```fortran
!> type(system_form_t) :: form
!> type(error_t), allocatable :: error
!> call prepare_system(system, epsilon=0.0_wp, form=form, error=error)
!>```
module hillstab_hill_system
   use hillstab_core_kinds, only: wp
   use hillstab_core_error, only: error_t, set_error, err_invalid_parameter
   use hillstab_core_text, only: integer_text, real_text
   use hillstab_hill_model_base, only: model_base_t
   use hillstab_hill_model, only: hill_model_t
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   implicit none
   private
   public :: hill_system_t, system_form_t, prepare_system, max_dof, check_system_point, system_equation_text, &
      system_description, symmetric_defect, cholesky_inverse, fundamental_derivative, lower_block, min_pivot, &
      mass_refusal

   !> Most degrees of freedom of a system (a 40 × 40 monodromy; the cost grows as n³).
   integer, parameter :: max_dof = 20
   !> The smallest Cholesky pivot of a mass matrix, and one over the largest magnitude of
   !> its entries: beyond, M⁻¹ (about one over the pivot) or the methods' products (ν² M
   !> in Hill's method) would leave the range of double precision.
   real(wp), parameter :: min_pivot = 1.0e-280_wp
   !> `min_pivot` and its inverse in messages (pure procedures write no numbers).
   character(len=*), parameter :: min_pivot_text = "1.0e-280", max_entry_text = "1.0e280"

   !> A system of n coupled Hill equations (see the module's text).
   type, abstract, extends(model_base_t) :: hill_system_t
   contains
      !> n, the degrees of freedom
      procedure(system_dof), deferred :: dof
      !> the mass matrix M (n × n, symmetric positive definite)
      procedure(system_matrix), deferred :: mass
      !> the stiffness K = p + β b at τ: its two parts p(τ; α) and b(τ; α)
      procedure(system_stiffness), deferred :: stiffness
      procedure :: damping => zero_matrix
      procedure :: gyroscopic => zero_matrix
      procedure :: damping_at => damping_anywhere
      procedure :: gyroscopic_at => gyroscopic_anywhere
      procedure :: row_dependent => same_every_row
      procedure :: shares_rows => rows_shared
      procedure :: at_point => system_copy
      procedure :: takes_scene_damping => scene_damping_taken
      procedure :: period => period_two
      procedure :: even => not_even
      procedure :: even_at => even_anywhere
      procedure :: symmetric => symmetric_stiffness
      procedure :: alpha_domain => any_alpha
      procedure :: alpha_valid => finite_alpha
      procedure :: drive_harmonics => no_harmonics
      procedure :: has_time => no_time_of_its_own
      procedure :: tau_rate => no_tau_rate
      procedure :: first_order => second_order_form
      procedure :: scalar_model => no_scalar_model
   end type hill_system_t

   abstract interface
      !> The degrees of freedom.
      pure integer function system_dof(self)
         import :: hill_system_t
         class(hill_system_t), intent(in) :: self  !! the system
      end function system_dof

      !> A constant n × n matrix of the system.
      pure subroutine system_matrix(self, a)
         import :: hill_system_t, wp
         class(hill_system_t), intent(in) :: self  !! the system
         real(wp), intent(out) :: a(:, :)         !! the matrix (n × n)
      end subroutine system_matrix

      !> K(τ) = p + β b at the drive α.
      pure subroutine system_stiffness(self, alpha, tau, p, b)
         import :: hill_system_t, wp
         class(hill_system_t), intent(in) :: self  !! the system
         real(wp), intent(in) :: alpha            !! α
         real(wp), intent(in) :: tau              !! dimensionless time
         real(wp), intent(out) :: p(:, :)         !! the part of K independent of β (n × n)
         real(wp), intent(out) :: b(:, :)         !! the factor of β (n × n)
      end subroutine system_stiffness
   end interface

   !> What the methods need of a system at one damping ε (`prepare_system`).
   type :: system_form_t
      integer :: n = 0                       !! degrees of freedom (first-order form: the states)
      integer :: states = 0                  !! the size of y: 2n, or n in first-order form
      logical :: first_order = .false.       !! y' = A(τ) y given directly (A = p + β b)
      real(wp), allocatable :: m(:, :)       !! M
      real(wp), allocatable :: m_inverse(:, :)  !! M⁻¹
      real(wp), allocatable :: d(:, :)       !! D = −M⁻¹(C + εM + G)
      real(wp), allocatable :: g(:, :)       !! G
      !> tr D (Liouville: det Φ = exp(P tr D)); first-order form: the mean of tr p over a period
      real(wp) :: trace_d = 0.0_wp
      !> first-order form: the mean of tr b over a period (det Φ = exp(P (trace_d + β trace_b)))
      real(wp) :: trace_b = 0.0_wp
      real(wp) :: period = 2.0_wp            !! P
      real(wp) :: epsilon = 0.0_wp           !! ε
      logical :: hamiltonian = .false.       !! C = 0, ε = 0, K symmetric
      logical :: half = .false.              !! half a period is enough (Hamiltonian, G = 0, K even)
      logical :: gyroscopic = .false.        !! G ≠ 0
   end type system_form_t

contains

   !> The system as one scalar Hill equation, when it is one: a model (hillstab_hill_model)
   !> whose Q(τ; α, β) is M⁻¹K and whose damping at a point (`point_damping` with the form's
   !> ε) is M⁻¹C + ε, so that the scalar methods' fast paths compute its monodromy. None
   !> (unallocated) unless the system says otherwise.
   subroutine no_scalar_model(self, model)
      class(hill_system_t), intent(in) :: self  !! the system
      class(hill_model_t), allocatable, intent(out) :: model  !! unallocated: no scalar form
   end subroutine no_scalar_model

   !> No damping: C = 0 unless the system has it.
   pure subroutine zero_matrix(self, a)
      class(hill_system_t), intent(in) :: self  !! the system
      real(wp), intent(out) :: a(:, :)         !! the matrix (n × n)
      a = 0.0_wp
   end subroutine zero_matrix

   !> C at row α: the same at every α (`damping`) unless the system says otherwise.
   pure subroutine damping_anywhere(self, alpha, a)
      class(hill_system_t), intent(in) :: self  !! the system
      real(wp), intent(in) :: alpha            !! α of the row
      real(wp), intent(out) :: a(:, :)         !! the matrix (n × n)
      call self%damping(a)
   end subroutine damping_anywhere

   !> G at row α: the same at every α (`gyroscopic`) unless the system says otherwise.
   pure subroutine gyroscopic_anywhere(self, alpha, a)
      class(hill_system_t), intent(in) :: self  !! the system
      real(wp), intent(in) :: alpha            !! α of the row
      real(wp), intent(out) :: a(:, :)         !! the matrix (n × n)
      call self%gyroscopic(a)
   end subroutine gyroscopic_anywhere

   !> C or G change with α, so that the system is prepared per row (`prepare_system` with
   !> `alpha`): false unless the system says so.
   pure logical function same_every_row(self)
      class(hill_system_t), intent(in) :: self  !! the system
      same_every_row = .false.
   end function same_every_row

   !> The points of a row share the row's form and nodes, β entering K as β b alone: true
   !> unless the system says otherwise (an equations system whose β axis enters its
   !> frequency, damping, gyroscopic matrix, or its stiffness other than affinely); its points
   !> are then each the point (α, 0) of the system at its β (`at_point`), prepared alone.
   pure logical function rows_shared(self)
      class(hill_system_t), intent(in) :: self  !! the system
      rows_shared = .true.
   end function rows_shared

   !> The system at β: a system whose point (α, 0) is this system's (α, β) — its K, damping,
   !> gyroscopic matrix and period there — and whose rows are shared. A system that shares
   !> rows already is its own copy.
   subroutine system_copy(self, alpha, beta, local)
      class(hill_system_t), intent(in) :: self  !! the system
      real(wp), intent(in) :: alpha            !! α of the point
      real(wp), intent(in) :: beta             !! β of the point
      class(hill_system_t), allocatable, intent(out) :: local  !! the system at β
      allocate (local, source=self)
   end subroutine system_copy

   !> The scene's ε (the damping ε M) may be added: true unless the system carries a damping
   !> of its own in its own units (the equations system: its C, converted at every row), for
   !> which ε must be 0.
   pure logical function scene_damping_taken(self)
      class(hill_system_t), intent(in) :: self  !! the system
      scene_damping_taken = .true.
   end function scene_damping_taken

   !> The period of K in τ: 2 unless the system says otherwise.
   pure real(wp) function period_two(self) result(period)
      class(hill_system_t), intent(in) :: self  !! the system
      period = 2.0_wp
   end function period_two

   !> K is even about τ = 0 at row α: as at every row (`even`) unless the system says
   !> otherwise.
   pure logical function even_anywhere(self, alpha)
      class(hill_system_t), intent(in) :: self  !! the system
      real(wp), intent(in) :: alpha            !! α of the row
      even_anywhere = self%even()
      if (alpha /= alpha) even_anywhere = .false.
   end function even_anywhere

   !> K is even about τ = 0 (K(−τ) = K(τ)): false unless the system says so.
   pure logical function not_even(self)
      class(hill_system_t), intent(in) :: self  !! the system
      not_even = .false.
   end function not_even

   !> K(τ) is symmetric at every τ: true unless the system says otherwise (a circulatory
   !> force, such as a follower load, makes it unsymmetric and the system non-Hamiltonian).
   pure logical function symmetric_stiffness(self)
      class(hill_system_t), intent(in) :: self  !! the system
      symmetric_stiffness = .true.
   end function symmetric_stiffness

   !> The α domain in words ("" when every finite α is accepted).
   pure function any_alpha(self) result(text)
      class(hill_system_t), intent(in) :: self  !! the system
      character(len=:), allocatable :: text
      text = ""
   end function any_alpha

   !> α lies in the system's domain: any finite α unless the system says otherwise.
   elemental logical function finite_alpha(self, alpha) result(valid)
      class(hill_system_t), intent(in) :: self  !! the system
      real(wp), intent(in) :: alpha            !! α
      valid = ieee_is_finite(alpha)
   end function finite_alpha

   !> The highest harmonic of K's drive (0: unknown or none); methods use it for their first mesh.
   pure integer function no_harmonics(self)
      class(hill_system_t), intent(in) :: self  !! the system
      no_harmonics = 0
   end function no_harmonics

   !> The system has a time of its user's, t (a system of equations in physical time, τ =
   !> Ωt/π): `tau_rate` gives dτ/dt at each point. False unless the system says so.
   elemental logical function no_time_of_its_own(self)
      class(hill_system_t), intent(in) :: self  !! the system
      no_time_of_its_own = .false.
   end function no_time_of_its_own

   !> dτ/dt at the point (α, β): 2 over the period in the user's time t (a system of
   !> equations: Ω/π at the point), which turns a rate per unit τ into one per unit of t; 0 for
   !> a system without a time of its own (`has_time`) and where the point has no period.
   elemental real(wp) function no_tau_rate(self, alpha, beta) result(rate)
      class(hill_system_t), intent(in) :: self  !! the system
      real(wp), intent(in) :: alpha, beta       !! the point
      rate = 0.0_wp
   end function no_tau_rate

   !> The system is in second-order form unless it says otherwise.
   pure logical function second_order_form(self)
      class(hill_system_t), intent(in) :: self  !! the system
      second_order_form = .false.
   end function second_order_form

   !> The largest |a_ij − a_ji| relative to the largest |a_ij| (0 for a zero matrix).
   pure real(wp) function symmetric_defect(a, sign) result(defect)
      real(wp), intent(in) :: a(:, :)  !! a square matrix
      real(wp), intent(in) :: sign     !! +1: defect from symmetry; −1: from skew symmetry
      real(wp) :: scale
      scale = maxval(abs(a))
      defect = 0.0_wp
      if (scale > 0.0_wp) defect = maxval(abs(a - sign*transpose(a)))/scale
   end function symmetric_defect

   !> The inverse of a symmetric positive definite matrix by Cholesky; `ok` false when the
   !> matrix is not positive definite (a pivot ≤ n ε times its own diagonal entry: the
   !> test does not depend on the scale of the other rows, so diag(1e154, 1) passes) or
   !> when an entry exceeds 1/`min_pivot` in magnitude or a pivot lies below `min_pivot`
   !> (then `out_of_range`: the inverse or the products with M would leave the range of
   !> double precision).
   pure subroutine cholesky_inverse(a, inverse, ok, out_of_range)
      real(wp), intent(in) :: a(:, :)          !! the matrix (n × n, symmetric)
      real(wp), intent(out) :: inverse(:, :)   !! its inverse
      logical, intent(out) :: ok               !! a was positive definite
      logical, intent(out), optional :: out_of_range  !! refused for a pivot below min_pivot
      real(wp) :: l(size(a, 1), size(a, 1)), s
      integer :: n, i, j, k
      n = size(a, 1)
      l = 0.0_wp
      inverse = 0.0_wp
      ok = .false.
      if (present(out_of_range)) out_of_range = .false.
      if (.not. (maxval(abs(a)) <= 1.0_wp/min_pivot)) then
         if (present(out_of_range)) out_of_range = .true.
         return
      end if
      do j = 1, n
         s = a(j, j) - sum(l(j, 1:j - 1)**2)
         if (.not. (s > n*epsilon(1.0_wp)*abs(a(j, j)) .and. s > 0.0_wp)) return
         if (s < min_pivot) then
            if (present(out_of_range)) out_of_range = .true.
            return
         end if
         l(j, j) = sqrt(s)
         do i = j + 1, n
            ! positive definite: l_ij² ≤ a_ii, so a larger quotient (which might overflow) means it is not
            s = a(i, j) - sum(l(i, 1:j - 1)*l(j, 1:j - 1))
            if (.not. (abs(s) <= 2.0_wp*l(j, j)*sqrt(abs(a(i, i))))) return
            l(i, j) = s/l(j, j)
         end do
      end do
      ! columns of the inverse: solve L Lᵀ x = e_k
      do k = 1, n
         inverse(k, k) = 1.0_wp
         do i = 1, n
            inverse(i, k) = (inverse(i, k) - sum(l(i, 1:i - 1)*inverse(1:i - 1, k)))/l(i, i)
         end do
         do i = n, 1, -1
            inverse(i, k) = (inverse(i, k) - sum(l(i + 1:n, i)*inverse(i + 1:n, k)))/l(i, i)
         end do
      end do
      inverse = 0.5_wp*(inverse + transpose(inverse))
      ok = .true.
   end subroutine cholesky_inverse

   !> The message for a mass matrix `cholesky_inverse` refuses: not positive definite, or
   !> positive definite with an inverse out of the range of double precision.
   pure function mass_refusal(out_of_range) result(message)
      logical, intent(in) :: out_of_range  !! as `cholesky_inverse` returned it
      character(len=:), allocatable :: message
      if (out_of_range) then
         message = "mass: M is out of the range the methods take (an entry above "//max_entry_text// &
                   " in magnitude or a Cholesky pivot below "//min_pivot_text//": M^-1 or the products with M "// &
                   "would leave double precision): scale the masses"
      else
         message = "mass: M must be positive definite (its Cholesky factorisation meets a pivot <= 0)"
      end if
   end function mass_refusal

   !> Prepare a system at damping ε for the methods: M⁻¹, D, the flags; err_invalid_parameter
   !> when M is not symmetric positive definite, C not symmetric or G not skew (naming which),
   !> or an entry is not finite.
   subroutine prepare_system(system, epsilon, form, error, alpha)
      class(hill_system_t), intent(in) :: system  !! the system
      real(wp), intent(in) :: epsilon             !! ε ≥ 0 (the damping ε M)
      type(system_form_t), intent(out) :: form    !! what the methods need
      !> err_invalid_parameter naming the matrix; unallocated on success
      type(error_t), allocatable, intent(out) :: error
      !> the row, for a system whose C or G change with α (`row_dependent`)
      real(wp), intent(in), optional :: alpha
      real(wp), allocatable :: c(:, :), g(:, :)
      integer :: n, i
      logical :: ok, out_of_range
      n = system%dof()
      if (n < 1 .or. n > max_dof) then
         call set_error(error, err_invalid_parameter, "n: the degrees of freedom must be 1 to "// &
            integer_text(max_dof)//", got "//integer_text(n))
         return
      end if
      if (.not. (ieee_is_finite(epsilon) .and. epsilon >= 0.0_wp)) then
         call set_error(error, err_invalid_parameter, "epsilon must be finite and >= 0")
         return
      end if
      form%n = n
      form%states = 2*n
      if (system%first_order()) then
         call prepare_first_order(system, form, error, alpha)
         return
      end if
      allocate (form%m(n, n), form%m_inverse(n, n), form%d(n, n), form%g(n, n), c(n, n), g(n, n))
      call system%mass(form%m)
      if (present(alpha)) then
         call system%damping_at(alpha, c)
         call system%gyroscopic_at(alpha, g)
      else
         call system%damping(c)
         call system%gyroscopic(g)
      end if
      if (.not. (all(ieee_is_finite(form%m)) .and. all(ieee_is_finite(c)) .and. all(ieee_is_finite(g)))) then
         call set_error(error, err_invalid_parameter, "mass, damping, gyroscopic: the entries must be finite")
         return
      end if
      if (symmetric_defect(form%m, 1.0_wp) > 1.0e-12_wp) then
         call set_error(error, err_invalid_parameter, "mass: M must be symmetric (|M_ij - M_ji| = "// &
            real_text(symmetric_defect(form%m, 1.0_wp))//" of its largest entry)")
         return
      end if
      call cholesky_inverse(form%m, form%m_inverse, ok, out_of_range)
      if (.not. ok) then
         call set_error(error, err_invalid_parameter, mass_refusal(out_of_range))
         return
      end if
      if (symmetric_defect(c, 1.0_wp) > 1.0e-12_wp) then
         call set_error(error, err_invalid_parameter, "damping: C must be symmetric (the skew part is G, "// &
            "variable gyroscopic)")
         return
      end if
      if (symmetric_defect(g, -1.0_wp) > 1.0e-12_wp) then
         call set_error(error, err_invalid_parameter, "gyroscopic: G must be skew (G_ji = -G_ij; the "// &
            "symmetric part is C, variable damping)")
         return
      end if
      form%g = g
      form%d = -matmul(form%m_inverse, c + g) - epsilon*reshape([(merge(1.0_wp, 0.0_wp, i/n == mod(i, n)), &
                                                                   i=0, n*n - 1)], [n, n])
      form%trace_d = sum([(form%d(i, i), i=1, n)])
      form%period = system%period()
      form%epsilon = epsilon
      form%gyroscopic = any(g /= 0.0_wp)
      form%hamiltonian = all(c == 0.0_wp) .and. epsilon == 0.0_wp .and. system%symmetric()
      form%half = form%hamiltonian .and. .not. form%gyroscopic
      if (form%half) then
         if (present(alpha)) then
            form%half = system%even_at(alpha)
         else
            form%half = system%even()
         end if
      end if
   end subroutine prepare_system

   !> A system in first-order form at row α: M = I, no damping, D = 0, and the mean traces of
   !> p and b over a period (by the trapezoidal rule on 64 nodes, exact for a trigonometric
   !> polynomial of degree below 64) for Liouville's check. Such a system is prepared per row
   !> (`row_dependent`); without α (a check of the system alone) the traces are left 0.
   subroutine prepare_first_order(system, form, error, alpha)
      class(hill_system_t), intent(in) :: system  !! the system (`first_order`)
      type(system_form_t), intent(inout) :: form  !! n set; the rest filled
      type(error_t), allocatable, intent(out) :: error  !! A not finite at a node of the row
      real(wp), intent(in), optional :: alpha     !! the row
      real(wp) :: p(form%n, form%n), b(form%n, form%n)
      integer :: n, i, k
      integer, parameter :: nodes = 64
      n = form%n
      form%states = n
      form%first_order = .true.
      allocate (form%m(n, n), form%m_inverse(n, n), form%d(n, n), form%g(n, n))
      form%m = 0.0_wp
      do i = 1, n
         form%m(i, i) = 1.0_wp
      end do
      form%m_inverse = form%m
      form%d = 0.0_wp
      form%g = 0.0_wp
      form%period = system%period()
      form%epsilon = 0.0_wp
      form%gyroscopic = .false.
      form%hamiltonian = .false.
      form%half = .false.
      form%trace_d = 0.0_wp
      form%trace_b = 0.0_wp
      if (.not. present(alpha)) return
      do k = 0, nodes - 1
         call system%stiffness(alpha, form%period*k/nodes, p, b)
         if (.not. (all(ieee_is_finite(p)) .and. all(ieee_is_finite(b)))) then
            call set_error(error, err_invalid_parameter, "state: A is not finite at tau = "// &
               real_text(form%period*k/nodes)//" of the row alpha = "//real_text(alpha))
            return
         end if
         form%trace_d = form%trace_d + sum([(p(i, i), i=1, n)])/nodes
         form%trace_b = form%trace_b + sum([(b(i, i), i=1, n)])/nodes
      end do
   end subroutine prepare_first_order

   !> Y' = A Y for the fundamental matrix Y (m × m, stored column by column in y): A =
   !> [[0, I], [L, D]] with L = −M⁻¹K(τ) given and D of the form (m = 2n), or in first-order
   !> form A = L itself (m = n); the right-hand side the Runge–Kutta methods integrate
   !> (hillstab_integrate_system_magnus's rk, hillstab_integrate_system_gsl).
   pure subroutine fundamental_derivative(form, l, y, dydt)
      type(system_form_t), intent(in) :: form  !! the prepared system (D)
      real(wp), intent(in) :: l(:, :)          !! L = −M⁻¹K(τ), or A in first-order form (n × n)
      real(wp), intent(in) :: y(:)             !! Y, column by column (m²)
      real(wp), intent(out) :: dydt(:)         !! A Y, column by column (m²)
      integer :: n, m, col, o
      n = form%n
      m = form%states
      if (form%first_order) then
         do col = 1, m
            o = (col - 1)*m
            dydt(o + 1:o + m) = matmul(l, y(o + 1:o + m))
         end do
         return
      end if
      do col = 1, m
         o = (col - 1)*m
         dydt(o + 1:o + n) = y(o + n + 1:o + m)
         dydt(o + n + 1:o + m) = matmul(l, y(o + 1:o + n)) + matmul(form%d, y(o + n + 1:o + m))
      end do
   end subroutine fundamental_derivative

   !> The lower-left block L of A at K = p + β b: −M⁻¹K, or K itself (A) in first-order form.
   pure function lower_block(form, k) result(l)
      type(system_form_t), intent(in) :: form  !! the prepared system
      real(wp), intent(in) :: k(:, :)          !! K, or A in first-order form (n × n)
      real(wp) :: l(size(k, 1), size(k, 2))
      if (form%first_order) then
         l = k
      else
         l = -matmul(form%m_inverse, k)
      end if
   end function lower_block

   !> err_invalid_parameter unless α lies in the system's domain and α, β are finite with
   !> magnitudes ≤ 1e15.
   subroutine check_system_point(system, alpha, beta, error)
      class(hill_system_t), intent(in) :: system  !! the system
      real(wp), intent(in) :: alpha, beta         !! the point
      !> err_invalid_parameter naming the value; unallocated when valid
      type(error_t), allocatable, intent(out) :: error
      if (.not. (ieee_is_finite(alpha) .and. ieee_is_finite(beta))) then
         call set_error(error, err_invalid_parameter, "alpha and beta must be finite")
      else if (max(abs(alpha), abs(beta)) > 1.0e15_wp) then
         call set_error(error, err_invalid_parameter, "|alpha|, |beta| must be <= 1e15")
      else if (.not. system%alpha_valid(alpha)) then
         call set_error(error, err_invalid_parameter, system%name()//" system needs "//system%alpha_domain()// &
            ", got alpha = "//real_text(alpha))
      end if
   end subroutine check_system_point

   !> The equation and the period as output headers state them.
   function system_equation_text(system) result(text)
      class(hill_system_t), intent(in) :: system  !! the system
      character(len=:), allocatable :: text
      character(len=32) :: buffer
      real(wp) :: p
      p = system%period()
      if (p == aint(p) .and. abs(p) < 1.0e9_wp) then
         write (buffer, '(i0)') nint(p)
      else
         write (buffer, '(g0)') p
      end if
      if (system%first_order()) then
         text = "y' = A(tau) y, n = "//integer_text(system%dof())//" states, period "//trim(buffer)//" in tau"
         return
      end if
      text = "M x'' + (C + eps M + G) x' + K(tau) x = 0, n = "//integer_text(system%dof())//", period "// &
             trim(buffer)//" in tau"
   end function system_equation_text

   !> The line an output header gives the system: "model: system, K(tau) = ...".
   pure function system_description(system) result(text)
      class(hill_system_t), intent(in) :: system  !! the system
      character(len=:), allocatable :: text
      text = "model: "//system%name()//", "//system%formula()
   end function system_description
end module hillstab_hill_system

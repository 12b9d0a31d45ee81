!> The system of the scenes: n coupled Hill equations with constant matrices,
!>
!>     M x'' + (C + ε M + G) x' + K(τ) x = 0,
!>     K(τ) = K0 + β B + α Σₖ (Kₖᶜ cos(2πkτ/P) + Kₖˢ sin(2πkτ/P)),   k = 1 … H,
!>
!> the period P a multiple of 2 as for the Fourier model (P = 2: cos kπτ, sin kπτ). Its
!> variables (the scene group `&system`, the C API's system calls, Python) are `n`, then the
!> n × n matrices as lists of n² numbers read row by row (`mass`, `damping`, `gyroscopic`,
!> `k0`, `b`), the drive matrices `cos` and `sin` as H lists of n² numbers one after the
!> other (K₁ first), and `period`. Defaults: M = I, C = 0, G = 0, K0 = 0, B = I, no sine
!> terms; at least one drive matrix must be nonzero. The matrices are checked when the
!> system is complete (`check_values`): M symmetric positive definite, C and K0, B, Kₖ
!> symmetric or not (an unsymmetric K, a circulatory force, makes the system
!> non-Hamiltonian: the verdicts then compare |λ| with 1), G skew.
!>
!>```fortran
!> type(matrix_system_t) :: pair
!> type(error_t), allocatable :: error
!> call pair%set_values("n", [2.0_wp], error)
!> call pair%set_values("k0", [0.0_wp, -0.1_wp, -0.1_wp, 0.3_wp], error)
!> call pair%set_values("cos", [1.0_wp, 0.0_wp, 0.0_wp, 1.0_wp], error)
!> call pair%check_values(error)
!>```
module hillstab_hill_system_matrix
   use hillstab_core_kinds, only: wp, pi
   use hillstab_core_error, only: error_t, set_error, err_invalid_parameter
   use hillstab_core_text, only: integer_text
   use hillstab_hill_model_base, only: model_variable_t, model_variable_real, model_variable_list
   use hillstab_hill_system, only: hill_system_t, max_dof, symmetric_defect, cholesky_inverse, mass_refusal
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   implicit none
   private
   public :: matrix_system_t, max_system_harmonics, max_system_period

   !> Most drive harmonics H of `cos` and of `sin`.
   integer, parameter :: max_system_harmonics = 32
   !> Longest period P (a multiple of 2).
   real(wp), parameter :: max_system_period = 128.0_wp

   !> K = K0 + β B + α Σ (Kₖᶜ cos + Kₖˢ sin) with constant M, C, G (see the module's text).
   type, extends(hill_system_t) :: matrix_system_t
      integer :: n = 0                       !! degrees of freedom (0: not yet given)
      real(wp) :: p = 2.0_wp                 !! the period P
      !> the lists as given, row by row (empty: the default)
      real(wp), allocatable :: mass_list(:), damping_list(:), gyroscopic_list(:), k0_list(:), b_list(:)
      !> the drive lists as given: H blocks of n² numbers each
      real(wp), allocatable :: cos_list(:), sin_list(:)
      !> the matrices, set by `assemble` (n × n; kc, ks: n × n × H)
      real(wp), allocatable :: m(:, :), c(:, :), g(:, :), k0(:, :), b(:, :), kc(:, :, :), ks(:, :, :)
      integer :: harmonics = 0               !! H
      logical :: has_sin = .false.           !! some Kₖˢ ≠ 0
      logical :: symmetric_k = .true.        !! K0, B and every Kₖ symmetric
   contains
      procedure :: name => matrix_name
      procedure :: formula => matrix_formula
      procedure :: dof => matrix_dof
      procedure :: mass => matrix_mass
      procedure :: damping => matrix_damping
      procedure :: gyroscopic => matrix_gyroscopic
      procedure :: stiffness => matrix_stiffness
      procedure :: period => matrix_period
      procedure :: even => matrix_even
      procedure :: symmetric => matrix_symmetric
      procedure :: drive_harmonics => matrix_harmonics
      procedure :: variables => matrix_variables
      procedure :: set_values => matrix_set_values
      procedure :: check_values => matrix_check_values
      procedure :: assemble => matrix_assemble
   end type matrix_system_t

contains

   pure function matrix_name(self) result(text)
      class(matrix_system_t), intent(in) :: self  !! the system
      character(len=:), allocatable :: text
      text = "system"
   end function matrix_name

   pure function matrix_formula(self) result(text)
      class(matrix_system_t), intent(in) :: self  !! the system
      character(len=:), allocatable :: text
      text = "K(tau) = K0 + beta B + alpha sum_k (Kc_k cos(2 pi k tau/P) + Ks_k sin(2 pi k tau/P)), "// &
             "k = 1.."//integer_text(self%harmonics)
   end function matrix_formula

   pure integer function matrix_dof(self)
      class(matrix_system_t), intent(in) :: self  !! the system
      matrix_dof = self%n
   end function matrix_dof

   pure subroutine matrix_mass(self, a)
      class(matrix_system_t), intent(in) :: self  !! the system
      real(wp), intent(out) :: a(:, :)           !! M
      a = self%m
   end subroutine matrix_mass

   pure subroutine matrix_damping(self, a)
      class(matrix_system_t), intent(in) :: self  !! the system
      real(wp), intent(out) :: a(:, :)           !! C
      a = self%c
   end subroutine matrix_damping

   pure subroutine matrix_gyroscopic(self, a)
      class(matrix_system_t), intent(in) :: self  !! the system
      real(wp), intent(out) :: a(:, :)           !! G
      a = self%g
   end subroutine matrix_gyroscopic

   !> p = K0 + α Σ (Kₖᶜ cos + Kₖˢ sin), b = B.
   pure subroutine matrix_stiffness(self, alpha, tau, p, b)
      class(matrix_system_t), intent(in) :: self  !! the system
      real(wp), intent(in) :: alpha, tau         !! α and τ
      real(wp), intent(out) :: p(:, :), b(:, :)  !! the parts of K
      integer :: k
      real(wp) :: theta
      p = self%k0
      b = self%b
      theta = 2.0_wp*pi*tau/self%p
      do k = 1, self%harmonics
         p = p + (alpha*cos(k*theta))*self%kc(:, :, k)
         if (self%has_sin) p = p + (alpha*sin(k*theta))*self%ks(:, :, k)
      end do
   end subroutine matrix_stiffness

   pure real(wp) function matrix_period(self) result(period)
      class(matrix_system_t), intent(in) :: self  !! the system
      period = self%p
   end function matrix_period

   !> Even about τ = 0 without sine terms.
   pure logical function matrix_even(self)
      class(matrix_system_t), intent(in) :: self  !! the system
      matrix_even = .not. self%has_sin
   end function matrix_even

   pure logical function matrix_symmetric(self)
      class(matrix_system_t), intent(in) :: self  !! the system
      matrix_symmetric = self%symmetric_k
   end function matrix_symmetric

   pure integer function matrix_harmonics(self)
      class(matrix_system_t), intent(in) :: self  !! the system
      matrix_harmonics = self%harmonics
   end function matrix_harmonics

   !> n, mass, damping, gyroscopic, k0, b, cos, sin, period.
   pure function matrix_variables(self) result(variables)
      class(matrix_system_t), intent(in) :: self  !! the system
      type(model_variable_t), allocatable :: variables(:)
      integer, parameter :: n2 = max_dof*max_dof
      allocate (variables(9))
      variables(1) = model_variable_t("n", model_variable_real, 1, "", "degrees of freedom, 1 to 20", whole=.true.)
      variables(2) = model_variable_t("mass", model_variable_list, n2, "", "M, n*n numbers row by row, "// &
                                      "symmetric positive definite (or a quoted file of its rows); default: I")
      variables(3) = model_variable_t("damping", model_variable_list, n2, "", "C, n*n numbers, symmetric; "// &
                                      "default: 0")
      variables(4) = model_variable_t("gyroscopic", model_variable_list, n2, "", "G, n*n numbers, skew; "// &
                                      "default: 0")
      variables(5) = model_variable_t("k0", model_variable_list, n2, "", "K0, n*n numbers; default: 0")
      variables(6) = model_variable_t("b", model_variable_list, n2, "", "B, the factor of beta, n*n numbers; "// &
                                      "default: I")
      variables(7) = model_variable_t("cos", model_variable_list, n2*max_system_harmonics, "", &
                                      "Kc_1, Kc_2, ...: H blocks of n*n numbers, up to 32 (the factors of alpha "// &
                                      "cos(2 pi k tau/P))")
      variables(8) = model_variable_t("sin", model_variable_list, n2*max_system_harmonics, "", &
                                      "Ks_1, Ks_2, ...: H blocks of n*n numbers; default: none")
      variables(9) = model_variable_t("period", model_variable_real, 1, "2.0", "P, a multiple of 2 up to 128")
   end function matrix_variables

   !> Set one variable; the matrices are assembled (and checked) by `check_values`.
   pure subroutine matrix_set_values(self, name, values, error)
      class(matrix_system_t), intent(inout) :: self  !! the system
      character(len=*), intent(in) :: name           !! the variable
      real(wp), intent(in) :: values(:)              !! its numbers
      !> err_invalid_parameter naming the variable; unallocated when set
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: ignored
      if (.not. all(ieee_is_finite(values))) then
         call set_error(error, err_invalid_parameter, trim(name)//": the values must be finite numbers")
         return
      end if
      select case (trim(name))
      case ("n")
         if (size(values) /= 1) then
            call set_error(error, err_invalid_parameter, "n: one number, got "//integer_text(size(values)))
         else if (.not. (values(1) >= 1.0_wp .and. values(1) <= max_dof .and. values(1) == aint(values(1)))) then
            call set_error(error, err_invalid_parameter, "n: the degrees of freedom must be an integer from 1 "// &
               "to "//integer_text(max_dof)//" (the documented limit)")
         else
            self%n = nint(values(1))
         end if
      case ("mass"); self%mass_list = values
      case ("damping"); self%damping_list = values
      case ("gyroscopic"); self%gyroscopic_list = values
      case ("k0"); self%k0_list = values
      case ("b"); self%b_list = values
      case ("cos"); self%cos_list = values
      case ("sin"); self%sin_list = values
      case ("period")
         if (size(values) /= 1) then
            call set_error(error, err_invalid_parameter, "period: one number, got "//integer_text(size(values)))
         else if (.not. (values(1) >= 2.0_wp .and. values(1) <= max_system_period .and. &
                         modulo(values(1), 2.0_wp) == 0.0_wp)) then
            call set_error(error, err_invalid_parameter, "period: must be a multiple of 2 from 2 to 128")
         else
            self%p = values(1)
         end if
      case default
         call set_error(error, err_invalid_parameter, "the system model has no variable '"//trim(name)// &
            "' (it has n, mass, damping, gyroscopic, k0, b, cos, sin, period)")
      end select
      ! assembled as soon as the lists allow (check_values reports what is still missing)
      if (.not. allocated(error)) call self%assemble(ignored)
   end subroutine matrix_set_values

   !> Whether the system is complete and consistent: n given, every list of n² numbers (the
   !> drives of a multiple of n²), M symmetric positive definite, C symmetric, G skew, a
   !> nonzero drive. Checks a copy assembled from the lists.
   pure subroutine matrix_check_values(self, error)
      class(matrix_system_t), intent(in) :: self  !! the system
      !> err_invalid_parameter naming the variable; unallocated when complete
      type(error_t), allocatable, intent(out) :: error
      type(matrix_system_t) :: copy
      copy = self
      call copy%assemble(error)
   end subroutine matrix_check_values

   !> Build the matrices from the lists (defaults where a list was not given) and check them.
   pure subroutine matrix_assemble(self, error)
      class(matrix_system_t), intent(inout) :: self  !! the system
      !> err_invalid_parameter naming the variable; unallocated on success
      type(error_t), allocatable, intent(out) :: error
      integer :: n, h, k
      logical :: ok, out_of_range
      real(wp), allocatable :: inverse(:, :)
      n = self%n
      if (n < 1) then
         call set_error(error, err_invalid_parameter, "n: the degrees of freedom are not given")
         return
      end if
      call square("mass", self%mass_list, 1.0_wp, self%m, error)
      if (.not. allocated(error)) call square("damping", self%damping_list, 0.0_wp, self%c, error)
      if (.not. allocated(error)) call square("gyroscopic", self%gyroscopic_list, 0.0_wp, self%g, error)
      if (.not. allocated(error)) call square("k0", self%k0_list, 0.0_wp, self%k0, error)
      if (.not. allocated(error)) call square("b", self%b_list, 1.0_wp, self%b, error)
      if (.not. allocated(error)) call blocks("cos", self%cos_list, self%kc, error)
      if (.not. allocated(error)) call blocks("sin", self%sin_list, self%ks, error)
      if (allocated(error)) return
      h = max(size(self%kc, 3), size(self%ks, 3))
      call pad(self%kc, h)
      call pad(self%ks, h)
      ! trailing zero harmonics dropped
      do while (h > 0)
         if (any(self%kc(:, :, h) /= 0.0_wp) .or. any(self%ks(:, :, h) /= 0.0_wp)) exit
         h = h - 1
      end do
      self%harmonics = h
      self%kc = self%kc(:, :, 1:h)
      self%ks = self%ks(:, :, 1:h)
      if (h == 0) then
         call set_error(error, err_invalid_parameter, "cos, sin: the system needs at least one nonzero drive "// &
            "matrix (without one alpha does nothing)")
         return
      end if
      self%has_sin = any(self%ks /= 0.0_wp)
      if (symmetric_defect(self%m, 1.0_wp) > 1.0e-12_wp) then
         call set_error(error, err_invalid_parameter, "mass: M must be symmetric")
         return
      end if
      allocate (inverse(n, n))
      call cholesky_inverse(self%m, inverse, ok, out_of_range)
      if (.not. ok) then
         call set_error(error, err_invalid_parameter, mass_refusal(out_of_range))
         return
      end if
      if (symmetric_defect(self%c, 1.0_wp) > 1.0e-12_wp) then
         call set_error(error, err_invalid_parameter, "damping: C must be symmetric (the skew part goes in "// &
            "gyroscopic)")
         return
      end if
      if (symmetric_defect(self%g, -1.0_wp) > 1.0e-12_wp) then
         call set_error(error, err_invalid_parameter, "gyroscopic: G must be skew, G_ji = -G_ij (the "// &
            "symmetric part goes in damping)")
         return
      end if
      self%symmetric_k = symmetric_defect(self%k0, 1.0_wp) == 0.0_wp .and. symmetric_defect(self%b, 1.0_wp) == 0.0_wp
      do k = 1, h
         self%symmetric_k = self%symmetric_k .and. symmetric_defect(self%kc(:, :, k), 1.0_wp) == 0.0_wp .and. &
                            symmetric_defect(self%ks(:, :, k), 1.0_wp) == 0.0_wp
      end do

   contains

      pure subroutine square(variable, list, diagonal, a, error)
         character(len=*), intent(in) :: variable
         real(wp), allocatable, intent(in) :: list(:)
         real(wp), intent(in) :: diagonal
         real(wp), allocatable, intent(out) :: a(:, :)
         type(error_t), allocatable, intent(out) :: error
         integer :: i
         allocate (a(n, n))
         a = 0.0_wp
         if (.not. allocated(list)) then
            do i = 1, n
               a(i, i) = diagonal
            end do
            return
         end if
         if (size(list) /= n*n) then
            call set_error(error, err_invalid_parameter, variable//": n = "//integer_text(n)//" needs "// &
               integer_text(n*n)//" numbers (the rows of an n x n matrix), got "//integer_text(size(list)))
            return
         end if
         a = transpose(reshape(list, [n, n]))
      end subroutine square

      pure subroutine blocks(variable, list, a, error)
         character(len=*), intent(in) :: variable
         real(wp), allocatable, intent(in) :: list(:)
         real(wp), allocatable, intent(out) :: a(:, :, :)
         type(error_t), allocatable, intent(out) :: error
         integer :: count, j
         if (.not. allocated(list)) then
            allocate (a(n, n, 0))
            return
         end if
         count = size(list)/(n*n)
         if (mod(size(list), n*n) /= 0 .or. count < 1) then
            call set_error(error, err_invalid_parameter, variable//": n = "//integer_text(n)//" needs blocks "// &
               "of "//integer_text(n*n)//" numbers (one n x n matrix per harmonic), got "// &
               integer_text(size(list)))
            return
         end if
         if (count > max_system_harmonics) then
            call set_error(error, err_invalid_parameter, variable//": at most "// &
               integer_text(max_system_harmonics)//" harmonics, got "//integer_text(count))
            return
         end if
         allocate (a(n, n, count))
         do j = 1, count
            a(:, :, j) = transpose(reshape(list((j - 1)*n*n + 1:j*n*n), [n, n]))
         end do
      end subroutine blocks

      pure subroutine pad(a, h)
         real(wp), allocatable, intent(inout) :: a(:, :, :)
         integer, intent(in) :: h
         real(wp), allocatable :: b(:, :, :)
         allocate (b(n, n, h))
         b = 0.0_wp
         b(:, :, 1:size(a, 3)) = a
         call move_alloc(b, a)
      end subroutine pad
   end subroutine matrix_assemble
end module hillstab_hill_system_matrix

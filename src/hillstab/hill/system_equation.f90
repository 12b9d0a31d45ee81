!> A system as its user writes it: n coupled equations in physical time t with named
!> parameters and named constant matrices,
!>
!>     M x'' + (C + G) x' + K(t) x = 0,   x in Rⁿ,  K of period T = 2π/Ω,
!>
!> each of M, C, G and K a *matrix expression*: a scalar expression (hillstab_core_expression)
!> of t, the parameters and the matrices' names that is linear in the matrices, its part
!> without a matrix standing for that multiple of the identity (K = 'W - (P0 + P1*cos(Om*t))*S'
!> is W − (P0 + P1 cos Ωt) S; damping = 'kappa' is κ I; mass = '1' is I). The matrices are
!> given by rows, 'W = [1, 0, 0; 0, 16, 0; 0, 0, 81], S = [...]'. As for one equation
!> (hillstab_hill_model_equation), two parameters are the chart's axes: `alpha` (the rows)
!> and `beta` may enter anywhere but M; where `beta` enters K alone and affinely a row's
!> points share its form and nodes, else each point is the system at its β (`at_point`,
!> K = p there, b = 0), prepared alone. In τ = Ωt/π (one period is
!> τ ∈ [0, 2]) the system is the one the system methods take, at each row α,
!>
!>     M x'' + (π/Ω)(C + G) x' + (π/Ω)² K(πτ/Ω) x = 0,
!>
!> so that the damping changes along a frequency axis (`damping_at`, `row_dependent`: the
!> tasks prepare the system per row) and the multipliers are the physical system's over one
!> period 2π/Ω. K = p + β b with p = K at β = 0 and b the difference of K at β = 1 and 0; at
!> every τ the coefficients of the matrices come from two evaluations of the expression on
!> the unit vectors of the matrices' names. The whole period is integrated.
!>
!> The first-order form y' = A(t) y, y in Rⁿ (a periodic state-space model), is given by
!> `state` = A(t) instead of `stiffness`, with the same rules (β enters A anywhere);
!> in τ it is dy/dτ = (π/Ω) A(πτ/Ω) y, and it has no mass, damping or gyroscopic matrix
!> (`first_order`: the methods integrate A itself).
!>
!> Variables (`&equations`): `n`, `parameters`, `matrices`, `stiffness` or `state`, `mass`
!> (default '1': I), `damping` ('0'), `gyroscopic` ('0'), `frequency` or `period`, `alpha`,
!> `beta`.
!>
!>```fortran
!> type(equations_system_t) :: column
!> type(error_t), allocatable :: error
!> call column%set_values("n", [3.0_wp], error)
!> call column%set_text("matrices", "W = [1, 0, 0; 0, 16, 0; 0, 0, 81], S = [1, 0.3, 0.1; 0.3, 4, 0.4; "// &
!>                      "0.1, 0.4, 9], Z = [1, 0, 0; 0, 4, 0; 0, 0, 9]", error)
!> call column%set_text("parameters", "P0 = 0.3, P1 = 0, Om = 2, zeta = 0.01", error)
!> call column%set_text("stiffness", "W - (P0 + P1*cos(Om*t))*S", error)
!> call column%set_text("damping", "2*zeta*Z", error)
!> call column%set_text("frequency", "Om", error)
!> call column%set_text("alpha", "Om", error)
!> call column%set_text("beta", "P1", error)
!>```
module hillstab_hill_system_equation
   use hillstab_core_kinds, only: wp, pi
   use hillstab_core_error, only: error_t, set_error, err_invalid_parameter
   use hillstab_core_text, only: integer_text, format_es
   use hillstab_core_expression, only: expression_t, parse_expression, parse_parameters, name_length
   use hillstab_hill_model_base, only: model_variable_t, model_variable_real, model_variable_text
   use hillstab_hill_system, only: hill_system_t, max_dof
   use hillstab_hill_model, only: hill_model_t
   use hillstab_hill_model_equation, only: equation_model_t
   use hillstab_hill_named_parameters, only: drive_t, parse_drive, find_axes, values_text, list_text => names_text, &
      number => message_number, position => parameter_position
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite, ieee_value, ieee_quiet_nan
   implicit none
   private
   public :: equations_system_t, max_equations_text, max_matrices

   !> Longest text of a variable.
   integer, parameter :: max_equations_text = 8000
   !> Most named matrices.
   integer, parameter :: max_matrices = 16

   !> M x'' + (C + G) x' + K(t) x = 0 with named parameters and matrices (see the module).
   type, extends(hill_system_t) :: equations_system_t
      integer :: n = 0                                  !! degrees of freedom
      character(len=:), allocatable :: parameters_text  !! `parameters`
      character(len=:), allocatable :: matrices_text    !! `matrices`
      character(len=:), allocatable :: stiffness_text   !! `stiffness`
      character(len=:), allocatable :: state_text       !! `state`: A(t) of the first-order form
      character(len=:), allocatable :: mass_text        !! `mass`
      character(len=:), allocatable :: damping_text     !! `damping`
      character(len=:), allocatable :: gyroscopic_text  !! `gyroscopic`
      character(len=:), allocatable :: alpha_name       !! the parameter of the α axis
      character(len=:), allocatable :: beta_name        !! the parameter of the β axis
      !> what `prepare` found wrong, beginning with the variables concerned ("" when ready)
      character(len=:), allocatable :: problem
      !> the parameters' names
      character(len=name_length), allocatable :: names(:)
      real(wp), allocatable :: values(:)                !! the parameters' values as given
      !> the matrices' names
      character(len=name_length), allocatable :: matrix_names(:)
      real(wp), allocatable :: matrices(:, :, :)        !! the matrices (n, n, count)
      integer :: i_alpha = 0                            !! position of the α axis among the parameters
      integer :: i_beta = 0                             !! position of the β axis
      !> K, M, C, G over the names (matrices…, t, parameters…)
      type(expression_t) :: k, m, c, g
      type(drive_t) :: drive                            !! `frequency` Ω or `period` T
      real(wp), allocatable :: mass_matrix(:, :)        !! M at the given parameters
      logical :: ready = .false.                        !! `prepare` succeeded
      !> the same system as one scalar equation (`equations_scalar_model`), when it is one
      type(equation_model_t), allocatable :: twin
      !> the β axis enters Ω (or T), C, G, or K other than affinely: no row is shared, each
      !> point is the point (α, 0) of the system at its β (`at_point`)
      logical :: beta_general = .false.
      !> the β axis is fixed at its value in `values` (the system at a point's β)
      logical :: pinned = .false.
   contains
      procedure :: name => equations_name
      procedure :: formula => equations_formula
      procedure :: dof => equations_dof
      procedure :: mass => equations_mass
      procedure :: damping => equations_damping
      procedure :: gyroscopic => equations_gyroscopic
      procedure :: damping_at => equations_damping_at
      procedure :: gyroscopic_at => equations_gyroscopic_at
      procedure :: row_dependent => equations_row_dependent
      procedure :: shares_rows => equations_shares_rows
      procedure :: at_point => equations_at_point
      procedure :: takes_scene_damping => equations_own_damping
      procedure :: stiffness => equations_stiffness
      procedure :: symmetric => equations_symmetric
      procedure :: even => equations_even
      procedure :: even_at => equations_even_at
      procedure :: alpha_domain => equations_alpha_domain
      procedure :: alpha_valid => equations_alpha_valid
      procedure :: axis_name => equations_axis_name
      procedure :: variables => equations_variables
      procedure :: set_values => equations_set_values
      procedure :: set_text => equations_set_text
      procedure :: check_values => equations_check_values
      procedure :: first_order => equations_first_order
      procedure :: scalar_model => equations_scalar_model
      procedure :: has_time => equations_has_time
      procedure :: tau_rate => equations_tau_rate
   end type equations_system_t

contains

   !> "equations".
   pure function equations_name(self) result(text)
      class(equations_system_t), intent(in) :: self  !! the system
      character(len=:), allocatable :: text
      text = "equations"
   end function equations_name

   !> The system as headers state it.
   pure function equations_formula(self) result(text)
      class(equations_system_t), intent(in) :: self  !! the system
      character(len=:), allocatable :: text
      if (.not. self%ready) then
         text = "M x'' + (C + G) x' + K(t) x = 0 (&equations)"
         return
      end if
      if (equations_first_order(self)) then
         text = "y' = A(t) y, n = "//integer_text(self%n)//" states, A(t) = "//self%state_text
         text = text//self%drive%summary()
         text = text//"; tau = Omega t/pi: dy/dtau = (pi/Omega) A(pi tau/Omega) y; parameters: "// &
                self%parameters_text//"; matrices: "//self%matrices_text//"; alpha = "//self%alpha_name// &
                ", beta = "//self%beta_name
         return
      end if
      text = "M x'' + (C + G) x' + K(t) x = 0, n = "//integer_text(self%n)//", K(t) = "//self%stiffness_text// &
             ", M = "//self%mass_text//", C = "//self%damping_text//", G = "//self%gyroscopic_text
      text = text//self%drive%summary()
      text = text//"; tau = Omega t/pi: M x'' + (pi/Omega)(C + G) x' + (pi/Omega)^2 K(pi tau/Omega) x = 0; "// &
             "parameters: "//self%parameters_text//"; matrices: "//self%matrices_text//"; alpha = "// &
             self%alpha_name//", beta = "//self%beta_name
   end function equations_formula

   !> The system is given in first-order form, y' = A(t) y (`state`).
   pure logical function equations_first_order(self)
      class(equations_system_t), intent(in) :: self  !! the system
      equations_first_order = .false.
      if (allocated(self%state_text)) equations_first_order = len(self%state_text) > 0
   end function equations_first_order

   !> One equation in second-order form without a gyroscopic term is the scalar equation
   !> m x'' + c x' + k(t) x = 0 of model `equation` (hillstab_hill_model_equation) with the
   !> same texts, each 1 × 1 matrix a parameter of its value (17 digits: the same double); none
   !> when that equation does not accept them (a damping it refuses, say). Made by `prepare`.
   subroutine equations_scalar_model(self, model)
      class(equations_system_t), intent(in) :: self  !! the system
      class(hill_model_t), allocatable, intent(out) :: model  !! the equation, or unallocated
      if (.not. self%ready) return
      if (allocated(self%twin)) allocate (model, source=self%twin)
   end subroutine equations_scalar_model

   !> `twin`, the system as one scalar equation (`equations_scalar_model`), when it is one.
   pure subroutine make_twin(self)
      class(equations_system_t), intent(inout) :: self  !! the system, ready
      type(equation_model_t) :: one
      type(error_t), allocatable :: error
      character(len=:), allocatable :: parameters
      integer :: j
      if (allocated(self%twin)) deallocate (self%twin)
      if (self%n /= 1 .or. equations_first_order(self)) return
      if (len_trim(self%gyroscopic_text) > 0 .and. trim(adjustl(self%gyroscopic_text)) /= "0") return
      parameters = self%parameters_text
      do j = 1, size(self%matrix_names)
         if (len_trim(parameters) > 0) parameters = parameters//", "
         parameters = parameters//trim(self%matrix_names(j))//" = "//trim(adjustl(format_es(self%matrices(1, 1, j), 17)))
      end do
      call one%set_text("parameters", parameters, error)
      if (.not. allocated(error)) call one%set_text("stiffness", self%stiffness_text, error)
      if (.not. allocated(error)) call one%set_text("mass", self%mass_text, error)
      if (.not. allocated(error)) call one%set_text("damping", self%damping_text, error)
      if (.not. allocated(error) .and. len(self%drive%frequency_text) > 0) &
         call one%set_text("frequency", self%drive%frequency_text, error)
      if (.not. allocated(error) .and. len(self%drive%period_text) > 0) &
         call one%set_text("period", self%drive%period_text, error)
      if (.not. allocated(error)) call one%set_text("alpha", self%alpha_name, error)
      if (.not. allocated(error)) call one%set_text("beta", self%beta_name, error)
      if (.not. allocated(error)) call one%check_values(error)
      if (allocated(error)) return
      allocate (self%twin, source=one)
   end subroutine make_twin

   !> The variable of the time-dependent coefficient: `state` in first-order form, else `stiffness`.
   pure function coefficient_variable(self) result(name)
      class(equations_system_t), intent(in) :: self  !! the system
      character(len=:), allocatable :: name
      if (equations_first_order(self)) then
         name = "state"
      else
         name = "stiffness"
      end if
   end function coefficient_variable

   !> n.
   pure integer function equations_dof(self)
      class(equations_system_t), intent(in) :: self  !! the system
      equations_dof = self%n
   end function equations_dof

   !> The variables of `&equations`.
   pure function equations_variables(self) result(variables)
      class(equations_system_t), intent(in) :: self  !! the system
      type(model_variable_t), allocatable :: variables(:)
      allocate (variables(12))
      variables(1) = model_variable_t("n", model_variable_real, 1, "", "degrees of freedom, 1 to 20 (with state: "// &
         "the states)", whole=.true.)
      variables(2) = model_variable_t("parameters", model_variable_text, max_equations_text, "''", &
         "the named parameters, 'name = value, ...'; a value may use the parameters before it")
      variables(3) = model_variable_t("matrices", model_variable_text, max_equations_text, "''", &
         "named constant matrices by rows, 'W = [1, 0; 0, 4], S = [...]'")
      variables(4) = model_variable_t("stiffness", model_variable_text, max_equations_text, "", &
         "K(t): an expression of t, the parameters and the matrices, linear in the matrices")
      variables(5) = model_variable_t("mass", model_variable_text, max_equations_text, "'1'", &
         "M: a matrix expression of the parameters (not of the axes), symmetric positive definite")
      variables(6) = model_variable_t("damping", model_variable_text, max_equations_text, "'0'", &
         "C: a matrix expression of the parameters, symmetric")
      variables(7) = model_variable_t("gyroscopic", model_variable_text, max_equations_text, "'0'", &
         "G: a matrix expression of the parameters, skew")
      variables(8) = model_variable_t("frequency", model_variable_text, max_equations_text, "", &
         "Omega: the drive's angular frequency (the period is 2 pi/Omega), an expression of the parameters")
      variables(9) = model_variable_t("period", model_variable_text, max_equations_text, "", &
         "T: the period of K instead of frequency")
      variables(10) = model_variable_t("alpha", model_variable_text, name_length, "", &
         "the parameter the chart's alpha axis runs over (the rows)")
      variables(11) = model_variable_t("beta", model_variable_text, name_length, "", &
         "the parameter the chart's beta axis runs over (in K alone and affinely: a row's points share their "// &
         "form; elsewhere but M: each point alone)")
      variables(12) = model_variable_t("state", model_variable_text, max_equations_text, "", &
         "A(t) of the first-order form y' = A(t) y instead of stiffness (n states; no mass, damping, gyroscopic)")
   end function equations_variables

   !> `n`.
   pure subroutine equations_set_values(self, name, values, error)
      class(equations_system_t), intent(inout) :: self  !! the system
      character(len=*), intent(in) :: name             !! the variable
      real(wp), intent(in) :: values(:)                !! its numbers
      type(error_t), allocatable, intent(out) :: error  !! the refusal
      if (trim(name) /= "n") then
         call set_error(error, err_invalid_parameter, "the equations system has no numeric variable '"// &
            trim(name)//"' (n; the others are texts)")
         return
      end if
      if (size(values) /= 1) then
         call set_error(error, err_invalid_parameter, "n: one number, got "//integer_text(size(values)))
         return
      end if
      if (.not. (ieee_is_finite(values(1)) .and. values(1) >= 1.0_wp .and. values(1) <= max_dof)) then
         call set_error(error, err_invalid_parameter, "n: the degrees of freedom must be an integer from 1 to "// &
            integer_text(max_dof))
         return
      end if
      if (abs(values(1) - anint(values(1))) > 0.0_wp) then
         call set_error(error, err_invalid_parameter, "n: the degrees of freedom must be an integer from 1 to "// &
            integer_text(max_dof))
         return
      end if
      self%n = nint(values(1))
      call prepare(self)
   end subroutine equations_set_values

   !> Set one text of the system.
   pure subroutine equations_set_text(self, name, text, error)
      class(equations_system_t), intent(inout) :: self  !! the system
      character(len=*), intent(in) :: name             !! the variable
      character(len=*), intent(in) :: text             !! its text
      type(error_t), allocatable, intent(out) :: error  !! unknown variable, too long a text
      if (len_trim(text) > max_equations_text) then
         call set_error(error, err_invalid_parameter, trim(name)//": "//integer_text(len_trim(text))// &
            " characters, more than the "//integer_text(max_equations_text)//" a text may have")
         return
      end if
      select case (trim(name))
      case ("parameters"); self%parameters_text = trim(adjustl(text))
      case ("matrices"); self%matrices_text = trim(adjustl(text))
      case ("stiffness"); self%stiffness_text = trim(adjustl(text))
      case ("state"); self%state_text = trim(adjustl(text))
      case ("mass"); self%mass_text = trim(adjustl(text))
      case ("damping"); self%damping_text = trim(adjustl(text))
      case ("gyroscopic"); self%gyroscopic_text = trim(adjustl(text))
      case ("frequency"); self%drive%frequency_text = trim(adjustl(text))
      case ("period"); self%drive%period_text = trim(adjustl(text))
      case ("alpha"); self%alpha_name = trim(adjustl(text))
      case ("beta"); self%beta_name = trim(adjustl(text))
      case default
         call set_error(error, err_invalid_parameter, "the equations system has no variable '"//trim(name)// &
            "' (it has: n, parameters, matrices, stiffness, mass, damping, gyroscopic, frequency, period, alpha, beta, "// &
            "state)")
         return
      end select
      call prepare(self)
   end subroutine equations_set_text

   !> What `prepare` found at the last change.
   pure subroutine equations_check_values(self, error)
      class(equations_system_t), intent(in) :: self  !! the system
      type(error_t), allocatable, intent(out) :: error  !! what is wrong, named
      if (.not. allocated(self%problem)) then
         call set_error(error, err_invalid_parameter, "n, stiffness, frequency, alpha, beta: the system needs "// &
            "n, its stiffness K(t), its frequency (or period) and the parameters of the two axes")
      else if (len(self%problem) > 0) then
         call set_error(error, err_invalid_parameter, self%problem)
      end if
   end subroutine equations_check_values

   !> Parse and check everything given so far (`problem` says what is wrong).
   pure subroutine prepare(self)
      class(equations_system_t), intent(inout) :: self  !! the system
      type(error_t), allocatable :: error
      logical, allocatable :: depends(:, :)
      character(len=name_length), allocatable :: all_names(:), matrix_names(:)
      character(len=:), allocatable :: known, drive_name, kv
      real(wp) :: drive, period
      real(wp), allocatable :: k_now(:, :), k_later(:, :), c(:, :), g(:, :), shifted(:), r_now(:), r_later(:)
      type(error_t), allocatable :: failure
      integer :: j, i
      self%ready = .false.
      self%problem = ""
      ! set again after it was complete (a C or Python caller changing one text)
      if (allocated(self%mass_matrix)) deallocate (self%mass_matrix)
      if (.not. allocated(self%parameters_text)) self%parameters_text = ""
      if (.not. allocated(self%matrices_text)) self%matrices_text = ""
      if (.not. allocated(self%mass_text)) self%mass_text = "1"
      if (.not. allocated(self%damping_text)) self%damping_text = "0"
      if (.not. allocated(self%gyroscopic_text)) self%gyroscopic_text = "0"
      if (.not. allocated(self%stiffness_text)) self%stiffness_text = ""
      if (.not. allocated(self%state_text)) self%state_text = ""
      kv = coefficient_variable(self)
      if (.not. allocated(self%alpha_name)) self%alpha_name = ""
      if (.not. allocated(self%beta_name)) self%beta_name = ""
      if (self%n < 1) then
         self%problem = "n: the degrees of freedom are required (1 to "//integer_text(max_dof)//")"
         return
      end if
      call parse_parameters(self%parameters_text, self%names, self%values, error, reserved=["t"], depends=depends)
      if (allocated(error)) then
         self%problem = error%message
         return
      end if
      known = list_text(self%names)
      call read_matrices(self%matrices_text, self%n, self%names, self%values, matrix_names, self%matrices, &
                         self%problem)
      if (len(self%problem) > 0) return
      self%matrix_names = matrix_names
      ! the axes
      call find_axes(self%names, depends, self%alpha_name, self%beta_name, self%i_alpha, self%i_beta, self%problem)
      if (len(self%problem) > 0) return
      ! the expressions over (matrices..., t, parameters...)
      all_names = [character(len=name_length) :: matrix_names, "t", self%names]
      if (equations_first_order(self)) then
         if (len(self%stiffness_text) > 0) then
            self%problem = "stiffness, state: give one of the two (stiffness K(t) of M x'' + (C + G) x' + K(t) x = "// &
                           "0, or state A(t) of y' = A(t) y)"
            return
         end if
         if (self%mass_text /= "1" .or. self%damping_text /= "0" .or. self%gyroscopic_text /= "0") then
            self%problem = "mass, damping, gyroscopic: the first-order form y' = A(t) y (state) has none; "// &
                           "write them into A"
            return
         end if
         call parse_one("state", self%state_text, all_names, self%k, self%problem)
      else if (len(self%stiffness_text) == 0) then
         self%problem = "stiffness: K(t) is required (an expression of t, the parameters and the matrices "// &
                        list_text(matrix_names)//"), or state: A(t) of the first-order form y' = A(t) y"
         return
      else
         call parse_one("stiffness", self%stiffness_text, all_names, self%k, self%problem)
      end if
      if (len(self%problem) > 0) return
      call parse_one("mass", self%mass_text, all_names, self%m, self%problem)
      if (len(self%problem) > 0) return
      call parse_one("damping", self%damping_text, all_names, self%c, self%problem)
      if (len(self%problem) > 0) return
      call parse_one("gyroscopic", self%gyroscopic_text, all_names, self%g, self%problem)
      if (len(self%problem) > 0) return
      if (self%m%uses("t") .or. self%c%uses("t") .or. self%g%uses("t")) then
         self%problem = trim(merge("mass      ", "damping   ", self%m%uses("t")))// &
            ": constant in time (only the "//kv//" may use t)"
         if (self%g%uses("t") .and. .not. (self%m%uses("t") .or. self%c%uses("t"))) &
            self%problem = "gyroscopic: constant in time (only the "//kv//" may use t)"
         return
      end if
      if (self%m%uses(self%alpha_name) .or. self%m%uses(self%beta_name)) then
         self%problem = "mass: M may not depend on the axes (it is the same at every point)"
         return
      end if
      call parse_drive(self%drive, self%names, self%problem)
      if (len(self%problem) > 0) return
      drive_name = self%drive%name()
      ! the β axis: in K alone and affinely (rows shared), or anywhere but M (each point alone)
      self%beta_general = self%drive%uses(self%beta_name) .or. self%c%uses(self%beta_name) .or. &
                          self%g%uses(self%beta_name) .or. .not. self%k%affine_in(self%beta_name)
      self%pinned = .false.
      do j = 1, size(matrix_names)
         if (.not. (self%k%affine_in(trim(matrix_names(j))) .and. self%m%affine_in(trim(matrix_names(j))) .and. &
                    self%c%affine_in(trim(matrix_names(j))) .and. self%g%affine_in(trim(matrix_names(j))))) then
            self%problem = kv//", mass, damping, gyroscopic: an expression is not linear in the matrix '"// &
               trim(matrix_names(j))//"' (a sum of matrices times scalar expressions is expected)"
            return
         end if
      end do
      drive = self%drive%expression%value(self%values)
      if (.not. (ieee_is_finite(drive) .and. drive > 0.0_wp)) then
         self%problem = drive_name//": must be finite and > 0 at the parameters ("//parameter_text(self)//")"
         return
      end if
      period = self%drive%period_of(drive)
      ! M, C, G and K at the given parameters: finite, and K periodic and linear in the matrices
      self%ready = .true.
      allocate (self%mass_matrix(self%n, self%n), k_now(self%n, self%n), k_later(self%n, self%n), &
                c(self%n, self%n), g(self%n, self%n))
      allocate (r_now(size(self%matrix_names) + 1), r_later(size(self%matrix_names) + 1))
      call matrix_value(self, self%m, 0.0_wp, self%values, self%mass_matrix, self%problem, "mass")
      if (len(self%problem) == 0) call matrix_value(self, self%c, 0.0_wp, self%values, c, self%problem, "damping")
      if (len(self%problem) == 0) call matrix_value(self, self%g, 0.0_wp, self%values, g, self%problem, "gyroscopic")
      do i = 0, 15
         if (len(self%problem) > 0) exit
         call matrix_value(self, self%k, period*i/16.0_wp, self%values, k_now, self%problem, kv)
         if (len(self%problem) == 0) call matrix_value(self, self%k, period*i/16.0_wp + period, self%values, &
                                                     k_later, self%problem, kv)
         if (len(self%problem) > 0) exit
         if (maxval(abs(k_later - k_now)) > 1.0e-9_wp*max(maxval(abs(k_now)), tiny(1.0_wp))) then
            self%problem = kv//": not of period T = "//number(period)//" (2 pi/Omega) at the parameters ("// &
                           parameter_text(self)//"): K(t + T) differs from K(t) at t = "//number(period*i/16.0_wp)
         end if
      end do
      ! the factor of the beta axis too (a term it multiplies is 0 where beta is): K at beta + 1,
      ! where K is finite there (an affine K; a general one is checked at the given values)
      shifted = self%values
      shifted(self%i_beta) = shifted(self%i_beta) + 1.0_wp
      do i = 0, 15
         if (len(self%problem) > 0 .or. self%beta_general) exit
         call coefficients(self, self%k, period*i/16.0_wp, shifted, r_now, failure)
         if (.not. allocated(failure)) call coefficients(self, self%k, period*i/16.0_wp + period, shifted, r_later, &
                                                         failure)
         if (allocated(failure)) exit
         call assemble(self, r_now, k_now)
         call assemble(self, r_later, k_later)
         if (maxval(abs(k_later - k_now)) > 1.0e-9_wp*max(maxval(abs(k_now)), tiny(1.0_wp))) then
            self%problem = kv//": not of period T = "//number(period)//" (2 pi/Omega) at the parameters ("// &
                           parameter_text(self)//") with "//self%beta_name//" = "//number(shifted(self%i_beta))// &
                           ": K(t + T) differs from K(t) at t = "//number(period*i/16.0_wp)
         end if
      end do
      if (len(self%problem) == 0) call check_linear(self, period)
      if (len(self%problem) > 0) self%ready = .false.
      if (self%ready) call make_twin(self)

   end subroutine prepare

   !> Parse one matrix expression over all names; `problem` on an error.
   pure subroutine parse_one(variable, text, all_names, expression, problem)
      character(len=*), intent(in) :: variable, text     !! the variable and its text
      character(len=*), intent(in) :: all_names(:)      !! the matrices, t and the parameters
      type(expression_t), intent(out) :: expression     !! the parsed expression
      character(len=:), allocatable, intent(inout) :: problem  !! set on an error
      type(error_t), allocatable :: failure
      call parse_expression(text, all_names, expression, failure)
      if (allocated(failure)) problem = variable//": "//failure%message
   end subroutine parse_one

   !> K, M, C and G are linear in the matrices jointly: the sum of two matrices' terms is
   !> the two terms (at 3 times; a product W*S is affine in each name but not linear).
   pure subroutine check_linear(self, period)
      class(equations_system_t), intent(inout) :: self  !! the system
      real(wp), intent(in) :: period                    !! T
      real(wp) :: nodes(4, size(self%matrix_names)), r(4)
      type(error_t), allocatable :: failure
      integer :: i, j, q
      character(len=10) :: variables(4)
      variables = [character(len=10) :: coefficient_variable(self), "mass", "damping", "gyroscopic"]
      do i = 1, size(self%matrix_names)
         do j = i + 1, size(self%matrix_names)
            nodes = 0.0_wp
            nodes(2, i) = 1.0_wp
            nodes(3, j) = 1.0_wp
            nodes(4, i) = 1.0_wp
            nodes(4, j) = 1.0_wp
            do q = 1, 4
               select case (q)
               case (1); call self%k%evaluate(nodes, r, failure, scalars=[0.37_wp*period, self%values])
               case (2); call self%m%evaluate(nodes, r, failure, scalars=[0.0_wp, self%values])
               case (3); call self%c%evaluate(nodes, r, failure, scalars=[0.0_wp, self%values])
               case (4); call self%g%evaluate(nodes, r, failure, scalars=[0.0_wp, self%values])
               end select
               if (allocated(failure)) cycle
               if (abs(r(4) - r(3) - r(2) + r(1)) > 1.0e-12_wp*max(abs(r(4)), abs(r(3)), abs(r(2)), abs(r(1)), &
                                                                   tiny(1.0_wp))) then
                  self%problem = trim(variables(q))//": not linear in the matrices "//trim(self%matrix_names(i))// &
                     " and "//trim(self%matrix_names(j))//" together (a product of two matrices? only sums of "// &
                     "matrices times scalar expressions are taken)"
                  return
               end if
            end do
         end do
      end do
   end subroutine check_linear

   !> A matrix expression's value at time t and the parameters p: e(0) I + Σ (e(e_k) − e(0)) M_k.
   pure subroutine matrix_value(self, expression, t, p, a, problem, variable)
      class(equations_system_t), intent(in) :: self  !! the system
      type(expression_t), intent(in) :: expression   !! the expression
      real(wp), intent(in) :: t                      !! time
      real(wp), intent(in) :: p(:)                   !! the parameters
      real(wp), intent(out) :: a(:, :)               !! its value (n × n)
      character(len=:), allocatable, intent(inout) :: problem  !! set when the value is not finite
      character(len=*), intent(in) :: variable       !! for the message
      real(wp) :: r(size(self%matrix_names) + 1)
      type(error_t), allocatable :: failure
      call coefficients(self, expression, t, p, r, failure)
      if (allocated(failure)) then
         problem = variable//": not finite at t = "//number(t)//" ("//parameter_text(self)//"): "//failure%message
         a = ieee_value(0.0_wp, ieee_quiet_nan)
         return
      end if
      call assemble(self, r, a)
   end subroutine matrix_value

   !> The identity's and the matrices' coefficients of an expression at (t, p): r(1) = e(0),
   !> r(1 + k) = e(e_k) − e(0).
   pure subroutine coefficients(self, expression, t, p, r, error)
      class(equations_system_t), intent(in) :: self  !! the system
      type(expression_t), intent(in) :: expression   !! the expression
      real(wp), intent(in) :: t                      !! time
      real(wp), intent(in) :: p(:)                   !! the parameters
      real(wp), intent(out) :: r(:)                  !! the coefficients (count + 1)
      type(error_t), allocatable, intent(out) :: error  !! not finite
      real(wp) :: nodes(size(r), size(r) - 1)
      integer :: k
      nodes = 0.0_wp
      do k = 1, size(r) - 1
         nodes(k + 1, k) = 1.0_wp
      end do
      call expression%evaluate(nodes, r, error, scalars=[t, p])
      if (allocated(error)) return
      r(2:) = r(2:) - r(1)
   end subroutine coefficients

   !> r(1) I + Σ r(1 + k) M_k.
   pure subroutine assemble(self, r, a)
      class(equations_system_t), intent(in) :: self  !! the system
      real(wp), intent(in) :: r(:)                   !! the coefficients
      real(wp), intent(out) :: a(:, :)               !! the matrix
      integer :: i, k
      a = 0.0_wp
      do i = 1, self%n
         a(i, i) = r(1)
      end do
      do k = 1, size(self%matrix_names)
         if (abs(r(k + 1)) > 0.0_wp) a = a + r(k + 1)*self%matrices(:, :, k)
      end do
   end subroutine assemble

   !> The parameters at row α (the β axis at 0), Ω and π/Ω there; `ok` false outside the
   !> domain (Ω not finite and positive).
   pure subroutine row_at(self, alpha, p, ratio, ok)
      class(equations_system_t), intent(in) :: self  !! the system
      real(wp), intent(in) :: alpha                  !! α
      real(wp), intent(out) :: p(:)                  !! the parameters
      real(wp), intent(out) :: ratio                 !! π/Ω
      logical, intent(out) :: ok                     !! in the domain
      real(wp) :: drive, omega
      ok = .false.
      ratio = 1.0_wp
      p = 0.0_wp
      if (.not. self%ready) return
      p = self%values
      p(self%i_alpha) = alpha
      if (.not. self%beta_general) p(self%i_beta) = 0.0_wp
      drive = self%drive%expression%value(p)
      if (.not. (ieee_is_finite(drive) .and. drive > 0.0_wp)) return
      omega = self%drive%omega_of(drive)
      ratio = pi/omega
      ok = ieee_is_finite(ratio) .and. ratio > 0.0_wp
   end subroutine row_at

   !> A system of equations is in its user's time t (τ = Ωt/π).
   elemental logical function equations_has_time(self)
      class(equations_system_t), intent(in) :: self  !! the system
      equations_has_time = .true.
   end function equations_has_time

   !> dτ/dt at the point: Ω/π there (τ = Ωt/π, the period 2π/Ω in t); 0 outside the domain.
   !> The system at a point's β (`pinned`) keeps that β whatever `beta` is.
   elemental real(wp) function equations_tau_rate(self, alpha, beta) result(rate)
      class(equations_system_t), intent(in) :: self  !! the system
      real(wp), intent(in) :: alpha, beta            !! the point
      rate = 0.0_wp
      if (self%ready) rate = self%drive%tau_rate(self%values, self%i_alpha, self%i_beta, alpha, beta, self%pinned)
   end function equations_tau_rate

   !> M at the given parameters.
   pure subroutine equations_mass(self, a)
      class(equations_system_t), intent(in) :: self  !! the system
      real(wp), intent(out) :: a(:, :)               !! M
      if (allocated(self%mass_matrix)) then
         a = self%mass_matrix
      else
         a = 0.0_wp
      end if
   end subroutine equations_mass

   !> (π/Ω) C at the given parameters (`damping_at` gives it per row).
   pure subroutine equations_damping(self, a)
      class(equations_system_t), intent(in) :: self  !! the system
      real(wp), intent(out) :: a(:, :)               !! the damping
      call self%damping_at(self%values(max(1, self%i_alpha)), a)
   end subroutine equations_damping

   !> (π/Ω) G at the given parameters.
   pure subroutine equations_gyroscopic(self, a)
      class(equations_system_t), intent(in) :: self  !! the system
      real(wp), intent(out) :: a(:, :)               !! the gyroscopic matrix
      call self%gyroscopic_at(self%values(max(1, self%i_alpha)), a)
   end subroutine equations_gyroscopic

   !> (π/Ω) C at row α (NaN outside the domain).
   pure subroutine equations_damping_at(self, alpha, a)
      class(equations_system_t), intent(in) :: self  !! the system
      real(wp), intent(in) :: alpha                  !! α
      real(wp), intent(out) :: a(:, :)               !! the damping in τ
      call scaled(self, self%c, alpha, a)
   end subroutine equations_damping_at

   !> (π/Ω) G at row α.
   pure subroutine equations_gyroscopic_at(self, alpha, a)
      class(equations_system_t), intent(in) :: self  !! the system
      real(wp), intent(in) :: alpha                  !! α
      real(wp), intent(out) :: a(:, :)               !! the gyroscopic matrix in τ
      call scaled(self, self%g, alpha, a)
   end subroutine equations_gyroscopic_at

   !> (π/Ω) times a constant matrix expression at row α.
   pure subroutine scaled(self, expression, alpha, a)
      class(equations_system_t), intent(in) :: self  !! the system
      type(expression_t), intent(in) :: expression   !! C or G
      real(wp), intent(in) :: alpha                  !! α
      real(wp), intent(out) :: a(:, :)               !! the matrix
      real(wp) :: p(size(self%values)), ratio, r(size(self%matrix_names) + 1)
      type(error_t), allocatable :: failure
      logical :: ok
      a = ieee_value(0.0_wp, ieee_quiet_nan)
      call row_at(self, alpha, p, ratio, ok)
      if (.not. ok) return
      call coefficients(self, expression, 0.0_wp, p, r, failure)
      if (allocated(failure)) return
      call assemble(self, ratio*r, a)
   end subroutine scaled

   !> The damping and the gyroscopic matrix change along the α axis (a frequency axis, or
   !> an α in C or G): the tasks prepare the system per row.
   pure logical function equations_row_dependent(self)
      class(equations_system_t), intent(in) :: self  !! the system
      equations_row_dependent = .true.
   end function equations_row_dependent

   !> Rows are shared unless the β axis enters anywhere (`beta_general`) and the system is
   !> not at a point's β.
   pure logical function equations_shares_rows(self)
      class(equations_system_t), intent(in) :: self  !! the system
      equations_shares_rows = self%pinned .or. .not. self%beta_general
   end function equations_shares_rows

   !> The system at β (its β axis fixed there, `pinned`; no scalar twin, whose β would be
   !> the argument's), when β enters anywhere; else the system itself.
   subroutine equations_at_point(self, alpha, beta, local)
      class(equations_system_t), intent(in) :: self  !! the system
      real(wp), intent(in) :: alpha                  !! α of the point
      real(wp), intent(in) :: beta                   !! β of the point
      class(hill_system_t), allocatable, intent(out) :: local  !! the system at β
      allocate (local, source=self)
      select type (local)
      type is (equations_system_t)
         if (local%beta_general .and. local%ready .and. .not. local%pinned) then
            local%values(local%i_beta) = beta
            local%pinned = .true.
            if (allocated(local%twin)) deallocate (local%twin)
         end if
      end select
   end subroutine equations_at_point

   !> The damping is the system's own (`damping`, in physical units, converted at every
   !> row): the scene's ε must be 0.
   pure logical function equations_own_damping(self)
      class(equations_system_t), intent(in) :: self  !! the system
      equations_own_damping = .false.
   end function equations_own_damping

   !> K(τ) = p + β b at row α in τ: (π/Ω)² K(πτ/Ω) at β = 0, and the change per unit β.
   pure subroutine equations_stiffness(self, alpha, tau, p, b)
      class(equations_system_t), intent(in) :: self  !! the system
      real(wp), intent(in) :: alpha                  !! α
      real(wp), intent(in) :: tau                    !! dimensionless time
      real(wp), intent(out) :: p(:, :)               !! the part independent of β
      real(wp), intent(out) :: b(:, :)               !! the factor of β
      real(wp) :: q(size(self%values)), ratio, r0(size(self%matrix_names) + 1), r1(size(self%matrix_names) + 1), t
      type(error_t), allocatable :: failure
      logical :: ok
      p = ieee_value(0.0_wp, ieee_quiet_nan)
      b = p
      call row_at(self, alpha, q, ratio, ok)
      if (.not. ok) return
      t = ratio*tau
      call coefficients(self, self%k, t, q, r0, failure)
      if (allocated(failure)) return
      if (self%beta_general) then
         ! K at the row's β (the system's value, or the point's when pinned): no factor of β
         r1 = r0
      else
         q(self%i_beta) = 1.0_wp
         call coefficients(self, self%k, t, q, r1, failure)
         if (allocated(failure)) return
      end if
      ! dy/dτ = (π/Ω) A y in first-order form; (π/Ω)² K in second-order form
      if (equations_first_order(self)) then
         call assemble(self, ratio*r0, p)
         call assemble(self, ratio*(r1 - r0), b)
      else
         call assemble(self, ratio**2*r0, p)
         call assemble(self, ratio**2*(r1 - r0), b)
      end if
   end subroutine equations_stiffness

   !> K is even about t = 0 at every row: at the axis α's own value and three others (each
   !> where Ω is defined; at least one), by `equations_even_at`.
   pure logical function equations_even(self)
      class(equations_system_t), intent(in) :: self  !! the system
      real(wp) :: alphas(4), p(size(self%values)), ratio
      logical :: ok
      integer :: j, tested
      equations_even = .false.
      if (.not. self%ready) return
      alphas(1) = self%values(self%i_alpha)
      alphas(2:4) = [1.37_wp*alphas(1) + 0.61_wp, alphas(1) + 1.7_wp, -2.3_wp - 0.9_wp*alphas(1)]
      tested = 0
      do j = 1, size(alphas)
         call row_at(self, alphas(j), p, ratio, ok)
         if (.not. ok) cycle
         if (.not. equations_even_at(self, alphas(j))) return
         tested = tested + 1
      end do
      equations_even = tested > 0
   end function equations_even

   !> K is even about t = 0 at row α: K(−t) equals K(t) to the bit at 7 times and at β = 0
   !> and 1 (K being affine in β).
   pure logical function equations_even_at(self, alpha) result(even)
      class(equations_system_t), intent(in) :: self  !! the system
      real(wp), intent(in) :: alpha                  !! α of the row
      real(wp) :: q(size(self%values)), ratio, plus(size(self%matrix_names) + 1), minus(size(self%matrix_names) + 1), t
      type(error_t), allocatable :: failure
      logical :: ok
      integer :: j, level
      even = .false.
      if (.not. self%ready) return
      call row_at(self, alpha, q, ratio, ok)
      if (.not. ok) return
      do level = 0, merge(0, 1, self%beta_general)
         ! K affine in β: even at β = 0 and 1; else at the row's β
         if (.not. self%beta_general) q(self%i_beta) = real(level, wp)
         do j = 0, 6
            t = ratio*(0.1234567_wp + 0.2718281_wp*j)
            call coefficients(self, self%k, t, q, plus, failure)
            if (allocated(failure)) return
            call coefficients(self, self%k, -t, q, minus, failure)
            if (allocated(failure)) return
            if (any(plus /= minus)) return
         end do
      end do
      even = .true.
   end function equations_even_at

   !> K is symmetric when every matrix is.
   pure logical function equations_symmetric(self)
      class(equations_system_t), intent(in) :: self  !! the system
      integer :: k
      equations_symmetric = .true.
      if (.not. allocated(self%matrices)) return
      do k = 1, size(self%matrices, 3)
         if (maxval(abs(self%matrices(:, :, k) - transpose(self%matrices(:, :, k)))) > 0.0_wp) &
            equations_symmetric = .false.
      end do
   end function equations_symmetric

   !> The α domain in words.
   pure function equations_alpha_domain(self) result(text)
      class(equations_system_t), intent(in) :: self  !! the system
      character(len=:), allocatable :: text
      text = "the values of "//self%alpha_name//" where the frequency is finite and > 0"
   end function equations_alpha_domain

   !> α gives a finite, positive Ω.
   elemental logical function equations_alpha_valid(self, alpha) result(valid)
      class(equations_system_t), intent(in) :: self  !! the system
      real(wp), intent(in) :: alpha                  !! α
      real(wp) :: p(size(self%values)), ratio
      valid = .false.
      if (.not. ieee_is_finite(alpha)) return
      call row_at(self, alpha, p, ratio, valid)
   end function equations_alpha_valid

   !> The parameter of axis k (1: α, 2: β), as the files name its column.
   pure function equations_axis_name(self, k) result(name)
      class(equations_system_t), intent(in) :: self  !! the system
      integer, intent(in) :: k                       !! 1 or 2
      character(len=:), allocatable :: name
      if (k == 1) then
         name = self%alpha_name
      else
         name = self%beta_name
      end if
      if (.not. allocated(name)) name = trim(merge("alpha", "beta ", k == 1))
      if (len(name) == 0) name = trim(merge("alpha", "beta ", k == 1))
   end function equations_axis_name

   !> Named matrices 'W = [1, 0; 0, 4], S = [...]': n rows of n entries (constant
   !> expressions of the parameters, evaluated at their given values); `problem` names what
   !> is wrong.
   pure subroutine read_matrices(text, n, names, values, matrix_names, matrices, problem)
      character(len=*), intent(in) :: text          !! `matrices`
      integer, intent(in) :: n                      !! the dimension
      character(len=*), intent(in) :: names(:)      !! the parameters
      real(wp), intent(in) :: values(:)             !! their values
      character(len=name_length), allocatable, intent(out) :: matrix_names(:)
      real(wp), allocatable, intent(out) :: matrices(:, :, :)
      character(len=:), allocatable, intent(inout) :: problem
      character(len=name_length) :: found(max_matrices)
      real(wp) :: held(n, n, max_matrices)
      integer :: count, start, open_at, close_at, equals, row, col, i, entry_start, k
      character(len=:), allocatable :: name, body, item
      type(expression_t) :: e
      type(error_t), allocatable :: failure
      count = 0
      start = 1
      do while (start <= len_trim(text))
         equals = index(text(start:), "=")
         open_at = index(text(start:), "[")
         close_at = index(text(start:), "]")
         if (equals == 0 .or. open_at == 0 .or. close_at == 0 .or. .not. (equals < open_at .and. open_at < close_at)) then
            problem = "matrices: expected name = [row; row; ...] at column "//integer_text(start)
            return
         end if
         name = trim(adjustl(text(start:start + equals - 2)))
         if (len(name) > 0) then
            if (name(1:1) == ",") name = trim(adjustl(name(2:)))
         end if
         if (len(name) == 0 .or. len(name) > name_length .or. verify(name, &
             "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_") /= 0 .or. &
             verify(name(1:1), "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ") /= 0) then
            problem = "matrices: '"//name//"' at column "//integer_text(start)//" is no name (a letter, then "// &
                      "letters, digits and underscores)"
            return
         end if
         if (position(names, name) > 0 .or. name == "t") then
            problem = "matrices: '"//name//"' is the name of a parameter (or of the time t)"
            return
         end if
         if (count > 0) then
            if (position(found(:count), name) > 0) then
               problem = "matrices: '"//name//"' is given twice"
               return
            end if
         end if
         if (count == max_matrices) then
            problem = "matrices: at most "//integer_text(max_matrices)//" matrices"
            return
         end if
         count = count + 1
         found(count) = name
         body = text(start + open_at:start + close_at - 2)
         ! rows separated by ';', entries by ',' or blanks
         row = 1
         col = 0
         entry_start = 1
         body = body//";"
         do i = 1, len(body)
            if (body(i:i) /= "," .and. body(i:i) /= ";") cycle
            item = trim(adjustl(body(entry_start:i - 1)))
            entry_start = i + 1
            if (len(item) > 0) then
               col = col + 1
               if (row > n .or. col > n) then
                  problem = "matrices: "//name//" has more than "//integer_text(n)//" rows or columns (n = "// &
                            integer_text(n)//")"
                  return
               end if
               call parse_expression(item, names, e, failure)
               if (.not. allocated(failure)) held(row, col, count) = e%value(values)
               if (allocated(failure)) then
                  problem = "matrices: "//name//", row "//integer_text(row)//": "//failure%message
                  return
               end if
               if (.not. ieee_is_finite(held(row, col, count))) then
                  problem = "matrices: "//name//", row "//integer_text(row)//", column "//integer_text(col)// &
                            ": not a finite number"
                  return
               end if
            end if
            if (body(i:i) == ";") then
               if (col /= n) then
                  problem = "matrices: "//name//", row "//integer_text(row)//" has "//integer_text(col)// &
                            " entries, n = "//integer_text(n)//" are needed"
                  return
               end if
               row = row + 1
               col = 0
            end if
         end do
         if (row - 1 /= n) then
            problem = "matrices: "//name//" has "//integer_text(row - 1)//" rows, n = "//integer_text(n)//" are needed"
            return
         end if
         start = start + close_at
      end do
      matrix_names = found(:count)
      allocate (matrices(n, n, count))
      do k = 1, count
         matrices(:, :, k) = held(:, :, k)
      end do
   end subroutine read_matrices

   !> The parameters as `name = value, ...`.
   pure function parameter_text(self) result(text)
      class(equations_system_t), intent(in) :: self
      character(len=:), allocatable :: text
      text = values_text(self%names, self%values)
   end function parameter_text
end module hillstab_hill_system_equation

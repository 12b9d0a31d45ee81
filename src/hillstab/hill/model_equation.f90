!> A Hill equation as its user writes it: in physical time t, with named parameters,
!>
!>     m x'' + c x' + k(t) x = 0,   k of period T = 2π/Ω,
!>
!> the stiffness k an expression of t and the parameters, the mass m, the damping c and the
!> drive frequency Ω (or the period T) expressions of the parameters (hillstab_core_expression).
!> Any two parameters are a chart's axes: the one named `alpha` runs down the rows, the one
!> named `beta` along them. In τ = Ωt/π (one period is τ ∈ [0, 2]) the equation is the
!> damped Hill equation x'' + ε x' + Q x = 0 of every model, at each point
!>
!>     Q(τ) = (π/Ω)² k(πτ/Ω)/m,   ε = πc/(mΩ),
!>
!> so that S, the multipliers (those of x over one period T: the physical ones) and the
!> verdicts are the equation's own. The multipliers' exponent per unit τ, μ, is μ_t π/Ω in
!> terms of the exponent per unit time μ_t.
!>
!> The α axis may enter anything. The β axis too: where it enters k alone (not Ω, m or c)
!> and affinely, k = a(t) + β b(t) (a and b are k at β = 0 and the difference of k at β = 1
!> and β = 0), the points of a row share its meshes (the fast path); else (`beta_general`)
!> each point is the point (α, 0) of the equation at its β (`at_point`: the β axis fixed,
!> b = 0), a row of one point with its own damping. In a shared row
!> the damping is one per row (`point_damping`), and with s = (π/Ω)²/m and the means
!> and maxima taken on 16 nodes a period, Q takes the methods' split Q = c₀ + c₁ w(τ) + v(τ)
!> (w and v independent of β, max|w| = 1 so that c₁ is the drive's amplitude in method
!> auto's step rules) in one of two forms, chosen per row:
!>
!>     b constant (β a mean stiffness):  c₀ = mean(s a) + β s b,  c₁ = max|s a − mean|,
!>                                       w = (s a − mean)/c₁,     v = 0;
!>     else (β scales a drive):          c₀ = mean(s a),  c₁ = β max|s b|,  w = s b/max|s b|,
!>                                       v = s a − mean(s a).
!>
!> The first is Mathieu's form (c₀ = β, c₁ = α for k = b − a cos πt), so that method auto
!> takes the steps it takes for the built-in model (`auto_amplitude`); the offset v of the
!> second counts as the drive in its calibration variable (`auto_difficulty`). A user's
!> coefficient was not in auto's calibration: it gets at least 16 steps per unit τ
!> (8 on the coarse mesh of the Richardson check) and the check's estimate counts 4 times.
!> Q is integrated over the whole period unless it is even about τ = 0 at
!> the row's parameters (k(−t) = k(t) at 7 incommensurate times, both at β = 0 and 1): then
!> over half, as for every even model. The ranges of w and v are their extremes on 512
!> points a period widened by a tenth of their spread (no closed form bounds an arbitrary
!> expression; a feature narrower than a few hundredths of the period escapes them). The
!> exact segment means of the paper's segmented methods are Gauss–Legendre quadratures
!> (8 panels of 8 nodes), exact to rounding for a coefficient smooth on the segment.
!>
!> Variables (`&equation`, the C API's `hillstab_model_set_text`): `parameters`
!> ('g = 9.81, l = 0.2, ...': each value an expression of numbers and the parameters
!> before it), `stiffness`, `mass` (default '1'), `damping` (default '0'), `frequency` or
!> `period`, `alpha` and `beta` (the parameters of the axes). A parameter computed from
!> another (w = 2*pi*f) does not follow it along an axis, so no axis may be one that other
!> parameters are computed from.
!>
!>```fortran
!> type(equation_model_t) :: kapitza
!> type(error_t), allocatable :: error
!> call kapitza%set_text("parameters", "g = 9.81, l = 0.2, kappa = 0.2, A = 0.005, w = 314.16", error)
!> call kapitza%set_text("stiffness", "-g/l + A*w^2/l*cos(w*t)", error)
!> call kapitza%set_text("damping", "kappa", error)
!> call kapitza%set_text("frequency", "w", error)
!> call kapitza%set_text("alpha", "w", error)
!> call kapitza%set_text("beta", "A", error)
!> call kapitza%check_values(error)
!> print *, kapitza%point_damping(314.16_wp, 0.0_wp)   ! 0.2 pi/314.16
!>```
module hillstab_hill_model_equation
   use hillstab_core_kinds, only: wp, pi
   use hillstab_core_error, only: error_t, set_error, err_invalid_parameter
   use hillstab_core_text, only: integer_text, format_es
   use hillstab_core_expression, only: expression_t, expression_work_t, parse_expression, parse_parameters, &
      name_length
   use hillstab_hill_model, only: hill_model_t, hill_window_t, model_variable_t, model_variable_text, auto_table_steps
   use hillstab_hill_named_parameters, only: drive_t, parse_drive, find_axes, names_text, values_text, &
      number => message_number
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite, ieee_value, ieee_quiet_nan
   implicit none
   private
   public :: equation_model_t, max_equation_text

   !> Longest text of a variable (an expression or the parameter list).
   integer, parameter :: max_equation_text = 2000

   !> Nodes a period of the scale D and the mean c₀ of the split.
   integer, parameter :: scale_nodes = 16
   !> Nodes a period of the ranges of w and v.
   integer, parameter :: range_nodes = 512

   !> What one row α needs, made from the parameters there: Ω, the scale s = (π/Ω)²/m, the
   !> split's D and c₀, and the parameters with the α axis set.
   type :: row_t
      real(wp), allocatable :: p(:)      !! the parameters (α axis at the row's value, β at 0)
      real(wp) :: omega = 1.0_wp         !! Ω
      real(wp) :: s = 1.0_wp             !! (π/Ω)²/m
      real(wp) :: scale = 1.0_wp         !! D
      real(wp) :: mean = 0.0_wp          !! the mean of s a
      !> b is constant over the period (the β axis a mean stiffness): Q = c₀ + c₁ w with
      !> c₀ = mean + β s b, c₁ = D, w = (s a − mean)/D, and no offset
      logical :: constant_b = .false.
      real(wp) :: sb = 0.0_wp            !! s b when `constant_b`
      real(wp) :: drive = 0.0_wp         !! max |s a − mean| when not `constant_b` (the offset's size)
      logical :: valid = .false.         !! Ω, m finite and positive, c finite and ≥ 0, D and c₀ finite
   end type row_t

   !> m x'' + c x' + k(t) x = 0 with named parameters (hillstab_hill_model_equation).
   type, extends(hill_model_t) :: equation_model_t
      character(len=:), allocatable :: parameters_text  !! `parameters` as given
      character(len=:), allocatable :: stiffness_text   !! `stiffness`
      character(len=:), allocatable :: mass_text        !! `mass`
      character(len=:), allocatable :: damping_text     !! `damping`
      character(len=:), allocatable :: alpha_name       !! the parameter of the α axis
      character(len=:), allocatable :: beta_name        !! the parameter of the β axis
      !> what `prepare` found wrong, beginning with the variables concerned ("" when ready)
      character(len=:), allocatable :: problem
      !> the parameters' names (`parameters`)
      character(len=name_length), allocatable :: names(:)
      real(wp), allocatable :: values(:)                !! the parameters' values as given
      integer :: i_alpha = 0                            !! position of the α axis among the parameters
      integer :: i_beta = 0                             !! position of the β axis
      type(expression_t) :: k                           !! k(t; parameters)
      type(expression_t) :: m                           !! m(parameters)
      type(expression_t) :: c                           !! c(parameters)
      type(drive_t) :: drive                            !! `frequency` Ω or `period` T
      logical :: ready = .false.                        !! `check_values` succeeded
      !> the β axis enters Ω (or T), m or c, or k other than affinely: no row is shared, each
      !> point is the point (α, 0) of the equation at its β (`at_point`)
      logical :: beta_general = .false.
      !> the β axis is fixed at its value in `values` (the equation at a point's β): the β
      !> argument of the bindings is ignored
      logical :: pinned = .false.
      !> a pinned equation keeps what it derives at its point's α (`at_point`)
      logical :: kept = .false.
      real(wp) :: kept_alpha = 0.0_wp               !! that α
      type(row_t) :: kept_row                       !! the row there
      real(wp) :: kept_ranges(4) = 0.0_wp           !! the ranges of w and v there: w_min, w_max, v_min, v_max
      type(hill_window_t) :: kept_window            !! the window there
   contains
      procedure :: name => equation_name
      procedure :: formula => equation_formula
      procedure :: summary => equation_summary
      procedure :: coefficient => equation_coefficient
      procedure :: segment_mean => equation_segment_mean
      procedure :: split => equation_split
      procedure :: split_row => equation_split_row
      procedure :: shapes => equation_shapes
      procedure :: shape_range => equation_shape_range
      procedure :: has_offset => equation_has_offset
      procedure :: offset_range => equation_offset_range
      procedure :: offsets => equation_offsets
      procedure :: window => equation_window
      procedure :: alpha_domain => equation_alpha_domain
      procedure :: alpha_valid => equation_alpha_valid
      procedure :: auto_difficulty => equation_auto_difficulty
      procedure :: auto_amplitude => equation_auto_amplitude
      procedure :: auto_safety => equation_auto_safety
      procedure :: auto_min_steps => equation_auto_min_steps
      procedure :: point_damping => equation_point_damping
      procedure :: shares_rows => equation_shares_rows
      procedure :: at_point => equation_at_point
      procedure :: has_damping => equation_has_damping
      procedure :: takes_scene_damping => equation_own_damping
      procedure :: axis_name => equation_axis_name
      procedure :: variables => equation_variables
      procedure :: set_text => equation_set_text
      procedure :: check_values => equation_check_values
      procedure :: at => equation_at
      procedure :: has_time => equation_has_time
      procedure :: tau_rate => equation_tau_rate
   end type equation_model_t

contains

   !> "equation".
   pure function equation_name(self) result(text)
      class(equation_model_t), intent(in) :: self  !! the model
      character(len=:), allocatable :: text
      text = "equation"
   end function equation_name

   !> The equation as headers state it: the physical form, its texts and the reduction.
   pure function equation_formula(self) result(text)
      class(equation_model_t), intent(in) :: self  !! the model
      character(len=:), allocatable :: text
      if (.not. self%ready) then
         text = "m x'' + c x' + k(t) x = 0 (&equation)"
         return
      end if
      text = "m x'' + c x' + k(t) x = 0, k(t) = "//self%stiffness_text//", m = "//self%mass_text//", c = "// &
             self%damping_text
      text = text//self%drive%summary()
      text = text//"; tau = Omega t/pi: Q(tau) = (pi/Omega)^2 k(pi tau/Omega)/m, epsilon = pi c/(m Omega); "// &
             "parameters: "//self%parameters_text//"; alpha = "//self%alpha_name//", beta = "//self%beta_name
   end function equation_formula

   !> The coefficient in a few words (a template's comment).
   pure function equation_summary(self) result(text)
      class(equation_model_t), intent(in) :: self  !! the model
      character(len=:), allocatable :: text
      text = "m x'' + c x' + k(t) x = 0 in physical time, with named parameters (&equation)"
   end function equation_summary

   !> The variables of `&equation`.
   pure function equation_variables(self) result(variables)
      class(equation_model_t), intent(in) :: self  !! the model
      type(model_variable_t), allocatable :: variables(:)
      allocate (variables(8))
      variables(1) = model_variable_t("parameters", model_variable_text, max_equation_text, "''", &
         "the named parameters, 'name = value, ...'; a value may use the parameters before it")
      variables(2) = model_variable_t("stiffness", model_variable_text, max_equation_text, "", &
         "k(t): an expression of t and the parameters (+ - * / ^, pi, sin cos tan exp log sqrt abs sinh cosh "// &
         "tanh atan atan2)")
      variables(3) = model_variable_t("mass", model_variable_text, max_equation_text, "'1'", &
         "m: an expression of the parameters, > 0")
      variables(4) = model_variable_t("damping", model_variable_text, max_equation_text, "'0'", &
         "c: an expression of the parameters, >= 0 (kappa = c/m, or 2 zeta omega_0 m)")
      variables(5) = model_variable_t("frequency", model_variable_text, max_equation_text, "", &
         "Omega: the drive's angular frequency (the period is 2 pi/Omega), an expression of the parameters")
      variables(6) = model_variable_t("period", model_variable_text, max_equation_text, "", &
         "T: the period of k instead of frequency, an expression of the parameters")
      variables(7) = model_variable_t("alpha", model_variable_text, name_length, "", &
         "the parameter the chart's alpha axis runs over (the rows)")
      variables(8) = model_variable_t("beta", model_variable_text, name_length, "", &
         "the parameter the chart's beta axis runs over (in k alone and affinely: a row's points share their "// &
         "meshes; elsewhere: each point alone)")
   end function equation_variables

   !> Set one text of the equation (`equation_variables`).
   pure subroutine equation_set_text(self, name, text, error)
      class(equation_model_t), intent(inout) :: self  !! the model
      character(len=*), intent(in) :: name           !! the variable
      character(len=*), intent(in) :: text           !! its text, unquoted
      type(error_t), allocatable, intent(out) :: error  !! unknown variable, too long a text
      if (len_trim(text) > max_equation_text) then
         call set_error(error, err_invalid_parameter, trim(name)//": "//integer_text(len_trim(text))// &
            " characters, more than the "//integer_text(max_equation_text)//" a text may have")
         return
      end if
      self%ready = .false.
      select case (trim(name))
      case ("parameters"); self%parameters_text = trim(adjustl(text))
      case ("stiffness"); self%stiffness_text = trim(adjustl(text))
      case ("mass"); self%mass_text = trim(adjustl(text))
      case ("damping"); self%damping_text = trim(adjustl(text))
      case ("frequency"); self%drive%frequency_text = trim(adjustl(text))
      case ("period"); self%drive%period_text = trim(adjustl(text))
      case ("alpha"); self%alpha_name = trim(adjustl(text))
      case ("beta"); self%beta_name = trim(adjustl(text))
      case default
         call set_error(error, err_invalid_parameter, "the equation model has no variable '"//trim(name)// &
            "' (it has: parameters, stiffness, mass, damping, frequency, period, alpha, beta)")
         return
      end select
      call prepare(self)
   end subroutine equation_set_text

   !> Whether the equation is complete and consistent: what `prepare` found at the last
   !> `set_text`.
   pure subroutine equation_check_values(self, error)
      class(equation_model_t), intent(in) :: self  !! the model
      type(error_t), allocatable, intent(out) :: error  !! what is wrong, named
      if (.not. allocated(self%problem)) then
         call set_error(error, err_invalid_parameter, "stiffness, frequency, alpha, beta: the equation needs "// &
            "its stiffness k(t), its frequency (or period) and the parameters of the two axes")
      else if (len(self%problem) > 0) then
         call set_error(error, err_invalid_parameter, self%problem)
      end if
   end subroutine equation_check_values

   !> Parse every text given so far and check the equation (`problem` says what is wrong):
   !> the parameters and expressions parse, the axes are parameters (two, distinct, that no
   !> other parameter is computed from), the β axis enters k alone and affinely, Ω (or T),
   !> m and c are finite and positive (c ≥ 0) at the given values, and k is finite and of
   !> period T there.
   pure subroutine prepare(self)
      class(equation_model_t), intent(inout) :: self  !! the model
      type(error_t), allocatable :: error
      logical, allocatable :: depends(:, :)
      character(len=name_length), allocatable :: with_t(:)
      character(len=:), allocatable :: known, drive_name, listing
      real(wp) :: drive, m, c, period, scale
      real(wp), allocatable :: t(:), k_now(:), k_later(:), shifted(:)
      integer :: j, n_nodes
      self%ready = .false.
      self%problem = ""
      if (.not. allocated(self%parameters_text)) self%parameters_text = ""
      if (.not. allocated(self%mass_text)) self%mass_text = "1"
      if (.not. allocated(self%damping_text)) self%damping_text = "0"
      if (.not. allocated(self%stiffness_text)) self%stiffness_text = ""
      if (.not. allocated(self%alpha_name)) self%alpha_name = ""
      if (.not. allocated(self%beta_name)) self%beta_name = ""
      call parse_parameters(self%parameters_text, self%names, self%values, error, reserved=["t"], depends=depends)
      if (allocated(error)) then
         self%problem = error%message
         return
      end if
      known = names_text(self%names)
      listing = values_text(self%names, self%values)
      ! the axes
      call find_axes(self%names, depends, self%alpha_name, self%beta_name, self%i_alpha, self%i_beta, self%problem)
      if (len(self%problem) > 0) return
      ! the expressions
      with_t = [character(len=name_length) :: "t", self%names]
      if (len(self%stiffness_text) == 0) then
         self%problem = "stiffness: k(t) is required (an expression of t and the parameters: "//known//")"
         return
      end if
      call parse_expression(self%stiffness_text, with_t, self%k, error)
      if (allocated(error)) then
         self%problem = "stiffness: "//error%message
         return
      end if
      call parse_expression(self%mass_text, self%names, self%m, error)
      if (allocated(error)) then
         self%problem = "mass: "//error%message
         return
      end if
      call parse_expression(self%damping_text, self%names, self%c, error)
      if (allocated(error)) then
         self%problem = "damping: "//error%message
         return
      end if
      call parse_drive(self%drive, self%names, self%problem)
      if (len(self%problem) > 0) return
      drive_name = self%drive%name()
      ! the β axis: in k alone and affinely, or anywhere (each point then alone)
      self%beta_general = self%drive%uses(self%beta_name) .or. self%m%uses(self%beta_name) .or. &
                          self%c%uses(self%beta_name) .or. .not. self%k%affine_in(self%beta_name)
      self%pinned = .false.
      ! the values at the given parameters
      drive = self%drive%expression%value(self%values)
      m = self%m%value(self%values)
      c = self%c%value(self%values)
      if (.not. (ieee_is_finite(drive) .and. drive > 0.0_wp)) then
         self%problem = drive_name//": must be finite and > 0 at the parameters ("//listing//")"
         return
      end if
      if (.not. (ieee_is_finite(m) .and. m > 0.0_wp)) then
         self%problem = "mass: must be finite and > 0 at the parameters ("//listing//")"
         return
      end if
      if (.not. (ieee_is_finite(c) .and. c >= 0.0_wp)) then
         self%problem = "damping: must be finite and >= 0 at the parameters ("//listing//")"
         return
      end if
      period = self%drive%period_of(drive)
      ! k finite over a period and periodic, at the given parameters
      n_nodes = 256
      allocate (t(n_nodes), k_now(n_nodes), k_later(n_nodes))
      t = [(period*real(j - 1, wp)/n_nodes, j=1, n_nodes)]
      call self%k%evaluate(t, k_now, error, scalars=self%values, failed_node=j)
      if (allocated(error)) then
         self%problem = "stiffness: not finite at t = "//number(t(max(j, 1)))//" ("//listing// &
            "): "//error%message
         return
      end if
      call self%k%evaluate(t + period, k_later, error, scalars=self%values, failed_node=j)
      if (allocated(error)) then
         self%problem = "stiffness: not finite at t = "//number(t(max(j, 1)) + period)//" ("// &
            listing//"): "//error%message
         return
      end if
      scale = max(maxval(abs(k_now)), tiny(1.0_wp))
      j = maxloc(abs(k_later - k_now), dim=1)
      if (abs(k_later(j) - k_now(j)) > 1.0e-9_wp*scale) then
         self%problem = "stiffness: not of period T = "//number(period)//" (2 pi/Omega) at the parameters ("// &
            listing//"): k(t) = "//number(k_now(j))//" but k(t + T) = "//number(k_later(j))// &
            " at t = "//number(t(j))
         return
      end if
      ! the factor of the beta axis too (a term it multiplies is 0 where beta is): k at beta + 1,
      ! where k is finite there (an affine k; a general one is checked at the given values)
      if (self%beta_general) then
         self%ready = .true.
         return
      end if
      shifted = self%values
      shifted(self%i_beta) = shifted(self%i_beta) + 1.0_wp
      call self%k%evaluate(t, k_now, error, scalars=shifted)
      if (.not. allocated(error)) call self%k%evaluate(t + period, k_later, error, scalars=shifted)
      if (.not. allocated(error)) then
         scale = max(maxval(abs(k_now)), tiny(1.0_wp))
         j = maxloc(abs(k_later - k_now), dim=1)
         if (abs(k_later(j) - k_now(j)) > 1.0e-9_wp*scale) then
            self%problem = "stiffness: not of period T = "//number(period)//" (2 pi/Omega) at the parameters ("// &
               listing//") with "//self%beta_name//" = "//number(shifted(self%i_beta))//": k(t) = "// &
               number(k_now(j))//" but k(t + T) = "//number(k_later(j))//" at t = "//number(t(j))
            return
         end if
      end if
      self%ready = .true.

   end subroutine prepare

   !> The parameters at row α and the row's constants (`row_t`). The β axis is 0 there when
   !> it enters k alone and affinely; else it is `beta` when given and the equation is not
   !> `pinned` (the row of one point), or the equation's value.
   pure function row_at(self, alpha, beta) result(row)
      class(equation_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha                !! the α axis' value
      real(wp), intent(in), optional :: beta       !! the β axis' value of a point
      type(row_t) :: row
      real(wp) :: t(scale_nodes), a(scale_nodes), b(scale_nodes), m, c, drive
      type(error_t), allocatable :: failure
      integer :: j
      if (kept_at(self, alpha)) then
         row = self%kept_row
         return
      end if
      if (.not. self%ready) then
         allocate (row%p(0))
         return
      end if
      row%p = self%values
      row%p(self%i_alpha) = alpha
      if (.not. self%beta_general) then
         row%p(self%i_beta) = 0.0_wp
      else if (present(beta) .and. .not. self%pinned) then
         row%p(self%i_beta) = beta
      end if
      drive = self%drive%expression%value(row%p)
      m = self%m%value(row%p)
      c = self%c%value(row%p)
      if (.not. (ieee_is_finite(drive) .and. ieee_is_finite(m) .and. ieee_is_finite(c))) return
      if (.not. (drive > 0.0_wp .and. m > 0.0_wp .and. c >= 0.0_wp)) return
      row%omega = self%drive%omega_of(drive)
      if (.not. (ieee_is_finite(row%omega) .and. row%omega > 0.0_wp)) return
      row%s = (pi/row%omega)**2/m
      if (.not. (ieee_is_finite(row%s) .and. row%s > 0.0_wp)) return
      t = [((2.0_wp*pi/row%omega)*(real(j, wp) - 0.5_wp)/scale_nodes, j=1, scale_nodes)]
      call both_parts(self, row, t, a, b, failure)
      if (allocated(failure)) return
      row%mean = sum(row%s*a)/scale_nodes
      row%constant_b = maxval(abs(b - b(1))) <= 1.0e-14_wp*maxval(abs(b))
      if (row%constant_b) then
         row%sb = row%s*b(1)
         row%scale = maxval(abs(row%s*a - row%mean))
      else
         row%scale = maxval(abs(row%s*b))
         row%drive = maxval(abs(row%s*a - row%mean))
      end if
      if (.not. row%scale > 0.0_wp) row%scale = 1.0_wp
      row%valid = ieee_is_finite(row%scale) .and. ieee_is_finite(row%mean) .and. ieee_is_finite(row%sb) .and. &
                  ieee_is_finite(row%drive)
   end function row_at

   !> a = k at β = 0 and b = k(β = 1) − k(β = 0) at the times t of the row; when β enters
   !> anywhere (`beta_general`), a = k at the row's β (the equation's value, or the point's
   !> when `pinned`) and b = 0.
   pure subroutine both_parts(self, row, t, a, b, error)
      class(equation_model_t), intent(in) :: self  !! the model
      type(row_t), intent(in) :: row               !! the row (its parameters)
      real(wp), intent(in) :: t(:)                 !! the times
      real(wp), intent(out) :: a(:), b(:)          !! the parts there
      type(error_t), allocatable, intent(out) :: error  !! k not finite somewhere
      real(wp) :: p(size(row%p))
      p = row%p
      if (self%beta_general) then
         b = 0.0_wp
         call self%k%evaluate(t, a, error, scalars=p)
         return
      end if
      p(self%i_beta) = 0.0_wp
      call self%k%evaluate(t, a, error, scalars=p)
      if (allocated(error)) return
      p(self%i_beta) = 1.0_wp
      call self%k%evaluate(t, b, error, scalars=p)
      if (allocated(error)) return
      b = b - a
   end subroutine both_parts

   !> Q(τ) without damping: (π/Ω)² k(πτ/Ω)/m at the point (NaN outside the domain).
   elemental real(wp) function equation_coefficient(self, alpha, beta, tau) result(q)
      class(equation_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha, beta          !! the point
      real(wp), intent(in) :: tau                  !! dimensionless time
      real(wp) :: p(size(self%values)), omega, m, k(1)
      type(error_t), allocatable :: failure
      q = ieee_nan()
      if (.not. self%ready) return
      p = self%values
      p(self%i_alpha) = alpha
      if (.not. self%pinned) p(self%i_beta) = beta
      omega = self%drive%expression%value(p)
      m = self%m%value(p)
      if (.not. (ieee_is_finite(omega) .and. ieee_is_finite(m) .and. omega > 0.0_wp .and. m > 0.0_wp)) return
      omega = self%drive%omega_of(omega)
      call self%k%evaluate([pi*tau/omega], k, failure, scalars=p)
      if (allocated(failure)) return
      q = (pi/omega)**2*k(1)/m
   end function equation_coefficient

   !> w and v of the split at the times τ of the row (NaN where k is not finite).
   pure subroutine row_shapes(self, row, tau, w, v)
      class(equation_model_t), intent(in) :: self  !! the model
      type(row_t), intent(in) :: row               !! the row
      real(wp), intent(in) :: tau(:)               !! the times τ
      real(wp), intent(out) :: w(:), v(:)          !! w and v there
      real(wp) :: a(size(tau)), b(size(tau))
      type(error_t), allocatable :: failure
      if (.not. row%valid) then
         w = ieee_nan()
         v = ieee_nan()
         return
      end if
      call both_parts(self, row, (pi/row%omega)*tau, a, b, failure)
      if (row%constant_b) then
         w = (row%s*a - row%mean)/row%scale
         v = 0.0_wp
      else
         w = row%s*b/row%scale
         v = row%s*a - row%mean
      end if
      if (allocated(failure)) then
         where (.not. (ieee_is_finite(a) .and. ieee_is_finite(b)))
            w = ieee_nan()
            v = ieee_nan()
         end where
      end if
   end subroutine row_shapes

   !> A quiet NaN.
   elemental real(wp) function ieee_nan()
      ieee_nan = ieee_value(0.0_wp, ieee_quiet_nan)
   end function ieee_nan

   !> The mean of Q over [τ_a, τ_b]: 8 panels of 8-point Gauss–Legendre.
   pure real(wp) function equation_segment_mean(self, alpha, beta, tau_a, tau_b) result(q)
      class(equation_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha, beta          !! the point
      real(wp), intent(in) :: tau_a, tau_b         !! segment ends, tau_a < tau_b
      real(wp), parameter :: x(4) = [0.1834346424956498_wp, 0.5255324099163290_wp, 0.7966664774136267_wp, &
                                     0.9602898564975363_wp]
      real(wp), parameter :: g(4) = [0.3626837833783620_wp, 0.3137066458778873_wp, 0.2223810344533745_wp, &
                                     0.1012285362903763_wp]
      integer, parameter :: panels = 8
      real(wp) :: tau(8*panels), weight(8*panels), w(8*panels), v(8*panels), h, centre
      type(row_t) :: row
      integer :: i, k
      h = (tau_b - tau_a)/panels
      do i = 1, panels
         centre = tau_a + (real(i, wp) - 0.5_wp)*h
         do k = 1, 4
            tau(8*(i - 1) + 2*k - 1) = centre - 0.5_wp*h*x(k)
            tau(8*(i - 1) + 2*k) = centre + 0.5_wp*h*x(k)
            weight(8*(i - 1) + 2*k - 1:8*(i - 1) + 2*k) = 0.5_wp*g(k)/panels
         end do
      end do
      row = row_at(self, alpha, beta)
      call row_shapes(self, row, tau, w, v)
      if (row%constant_b) then
         q = row%mean + beta*row%sb + row%scale*sum(weight*w)
      else
         q = row%mean + sum(weight*(beta*row%scale*w + v))
      end if
   end function equation_segment_mean

   !> Q = c₀ + c₁ w + v: c₀ the row's mean, c₁ = β D.
   elemental subroutine equation_split(self, alpha, beta, c0, c1)
      class(equation_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha, beta          !! the point
      real(wp), intent(out) :: c0, c1              !! constant part and factor of w
      type(row_t) :: row
      row = row_at(self, alpha, beta)
      if (row%constant_b) then
         c0 = row%mean + beta*row%sb
         c1 = row%scale
      else
         c0 = row%mean
         c1 = beta*row%scale
      end if
      if (.not. row%valid) then
         c0 = ieee_nan()
         c1 = ieee_nan()
      end if
   end subroutine equation_split

   !> `equation_split` at every β of row α, the row's constants computed once (each point alone
   !> when β enters anywhere).
   pure subroutine equation_split_row(self, alpha, betas, c0s, c1s)
      class(equation_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha                !! α of the row
      real(wp), intent(in) :: betas(:)             !! its β
      real(wp), intent(out) :: c0s(:), c1s(:)      !! the split at each β
      type(row_t) :: row
      if (self%beta_general .and. .not. self%pinned) then
         call self%split(alpha, betas, c0s, c1s)
         return
      end if
      row = row_at(self, alpha)
      if (.not. row%valid) then
         c0s = ieee_nan()
         c1s = ieee_nan()
      else if (row%constant_b) then
         c0s = row%mean + betas*row%sb
         c1s = row%scale
      else
         c0s = row%mean
         c1s = betas*row%scale
      end if
   end subroutine equation_split_row

   !> w at the times τ of row α.
   pure subroutine equation_shapes(self, alpha, tau, w)
      class(equation_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha                !! α
      real(wp), intent(in) :: tau(:)               !! the times
      real(wp), intent(out) :: w(:)                !! w there
      real(wp) :: v(size(tau))
      call row_shapes(self, row_at(self, alpha), tau, w, v)
   end subroutine equation_shapes

   !> The offset v is part of every equation's split.
   elemental logical function equation_has_offset(self)
      class(equation_model_t), intent(in) :: self  !! the model
      equation_has_offset = .true.
   end function equation_has_offset

   !> v at the times τ of row α.
   pure subroutine equation_offsets(self, alpha, tau, v)
      class(equation_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha                !! α
      real(wp), intent(in) :: tau(:)               !! the times
      real(wp), intent(out) :: v(:)                !! v there
      real(wp) :: w(size(tau))
      if (kept_at(self, alpha)) then
         ! a point's equation: b = 0, so v = 0 (w, from `equation_shapes`, is NaN where k is not finite)
         v = 0.0_wp
         return
      end if
      call row_shapes(self, row_at(self, alpha), tau, w, v)
   end subroutine equation_offsets

   !> The ranges of w and v over the period: extremes on `range_nodes` points widened by a
   !> tenth of their spread.
   pure subroutine sampled_ranges(self, alpha, w_min, w_max, v_min, v_max)
      class(equation_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha                !! α
      real(wp), intent(out) :: w_min, w_max, v_min, v_max  !! the ranges
      real(wp) :: tau(range_nodes), w(range_nodes), v(range_nodes), spread
      integer :: j
      if (kept_at(self, alpha)) then
         w_min = self%kept_ranges(1)
         w_max = self%kept_ranges(2)
         v_min = self%kept_ranges(3)
         v_max = self%kept_ranges(4)
         return
      end if
      tau = [(2.0_wp*real(j - 1, wp)/range_nodes, j=1, range_nodes)]
      call row_shapes(self, row_at(self, alpha), tau, w, v)
      if (.not. all(ieee_is_finite(w) .and. ieee_is_finite(v))) then
         w_min = ieee_nan()
         w_max = ieee_nan()
         v_min = ieee_nan()
         v_max = ieee_nan()
         return
      end if
      spread = maxval(w) - minval(w)
      w_min = minval(w) - 0.1_wp*spread
      w_max = maxval(w) + 0.1_wp*spread
      spread = maxval(v) - minval(v)
      v_min = minval(v) - 0.1_wp*spread
      v_max = maxval(v) + 0.1_wp*spread
   end subroutine sampled_ranges

   !> The range of w over the period (sampled and widened: `sampled_ranges`).
   elemental subroutine equation_shape_range(self, alpha, w_min, w_max)
      class(equation_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha                !! α
      real(wp), intent(out) :: w_min, w_max        !! the range of w
      real(wp) :: v_min, v_max
      call sampled_ranges(self, alpha, w_min, w_max, v_min, v_max)
   end subroutine equation_shape_range

   !> The range of v over the period (sampled and widened: `sampled_ranges`).
   elemental subroutine equation_offset_range(self, alpha, v_min, v_max)
      class(equation_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha                !! α
      real(wp), intent(out) :: v_min, v_max        !! bounds of v
      real(wp) :: w_min, w_max
      call sampled_ranges(self, alpha, w_min, w_max, v_min, v_max)
   end subroutine equation_offset_range

   !> Half the period when k is even about t = 0 at the row's parameters (at 7 times and
   !> both β = 0 and 1, to the bit), else the whole period.
   pure function equation_window(self, alpha) result(window)
      class(equation_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha                !! α
      type(hill_window_t) :: window
      real(wp) :: tau(7), a_plus(7), b_plus(7), a_minus(7), b_minus(7)
      type(row_t) :: row
      type(error_t), allocatable :: failure
      integer :: j
      logical :: even
      if (kept_at(self, alpha)) then
         window = self%kept_window
         return
      end if
      row = row_at(self, alpha)
      even = .false.
      if (row%valid) then
         tau = [(0.1234567_wp + 0.2718281_wp*j, j=0, 6)]
         call both_parts(self, row, (pi/row%omega)*tau, a_plus, b_plus, failure)
         if (.not. allocated(failure)) call both_parts(self, row, -(pi/row%omega)*tau, a_minus, b_minus, failure)
         if (.not. allocated(failure)) even = all(abs(a_plus - a_minus) <= 0.0_wp) .and. &
                                               all(abs(b_plus - b_minus) <= 0.0_wp)
      end if
      if (even) then
         window = hill_window_t(start=0.0_wp, length=1.0_wp, half=.true.)
      else
         window = hill_window_t(start=0.0_wp, length=2.0_wp, half=.false.)
      end if
   end function equation_window

   !> The α domain in words.
   pure function equation_alpha_domain(self) result(text)
      class(equation_model_t), intent(in) :: self  !! the model
      character(len=:), allocatable :: text
      if (self%beta_general) then
         text = "the points ("//self%alpha_name//", "//self%beta_name//") where the frequency, the mass (> 0) and "// &
                "the damping (>= 0) are finite and k is finite over the period"
         return
      end if
      text = "the values of "//self%alpha_name//" where the frequency, the mass (> 0) and the damping (>= 0) "// &
             "are finite and k is finite over the period"
   end function equation_alpha_domain

   !> α gives a valid row: Ω, m > 0, c ≥ 0 finite and k finite on the scale nodes.
   elemental logical function equation_alpha_valid(self, alpha) result(valid)
      class(equation_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha                !! α
      type(row_t) :: row
      valid = .false.
      if (.not. ieee_is_finite(alpha)) return
      row = row_at(self, alpha)
      valid = row%valid
   end function equation_alpha_valid

   !> Method auto's calibration variable: the Mathieu model's, −ln(1 − min(E, 9)/π²), with the
   !> largest excursion E of the offset v in the place of ν (0 when b is constant: v = 0).
   !> The drive c₁ w is seen by `equation_auto_amplitude`.
   elemental real(wp) function equation_auto_difficulty(self, alpha) result(x)
      class(equation_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha                !! α
      type(row_t) :: row
      row = row_at(self, alpha)
      x = 0.0_wp
      if (row%valid .and. .not. row%constant_b) x = -log(1.0_wp - min(row%drive, 9.0_wp)/(pi*pi))
   end function equation_auto_difficulty

   !> The amplitude method auto's step count grows with, made so that the count is the
   !> Mathieu model's for the drive c₁ w (max|w| = 1, so |c₁| plays ν): (T(x(|c₁|))/12)^2.5
   !> (|c₁| + 0.1 |c₀|), T the calibrated table (`auto_table_steps`) and x(ν) the Mathieu
   !> model's variable; the count grows as T times ((|c₁| + 0.1 |c₀|)/12)^0.4.
   elemental real(wp) function equation_auto_amplitude(self, c0, c1) result(amplitude)
      class(equation_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: c0, c1               !! the split of q
      amplitude = (auto_table_steps(-log(1.0_wp - min(abs(c1), 9.0_wp)/(pi*pi)))/12.0_wp)**2.5_wp* &
                  max(abs(c1) + 0.1_wp*abs(c0), 1.0_wp)
   end function equation_auto_amplitude

   !> The factor on method auto's Richardson estimate: 4. Its step rules were calibrated on
   !> the built-in coefficients; a user's coefficient gets a margin.
   elemental real(wp) function equation_auto_safety(self) result(factor)
      class(equation_model_t), intent(in) :: self  !! the model
      factor = 4.0_wp
   end function equation_auto_safety

   !> The fewest steps per unit of τ of method auto's first mesh: 16 (8 on the coarse mesh of
   !> its Richardson check). With 8, a Richardson pair of the Kapitza pendulum's chart (its
   !> Q that of Mathieu at α = 1.12, β = −0.017) differed by a twentieth of its error
   !> (1.9e-10 at tolerance 1e-10); with 16 the chart's worst point is 0.06 of it.
   elemental integer function equation_auto_min_steps(self) result(steps)
      class(equation_model_t), intent(in) :: self  !! the model
      steps = 16
   end function equation_auto_min_steps

   !> ε = πc/(mΩ) at the row's parameters (the scene's ε is 0 for an equation); when β
   !> enters anywhere (`beta_general`) and the equation is not at a point's β (`pinned`),
   !> no damping is the row's: the scene's ε (each point's is `damping_at`).
   elemental real(wp) function equation_point_damping(self, alpha, epsilon) result(damping)
      class(equation_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha                !! α of the row
      real(wp), intent(in) :: epsilon              !! the scene's ε (0)
      type(row_t) :: row
      if (self%beta_general .and. .not. self%pinned) then
         damping = epsilon
         return
      end if
      row = row_at(self, alpha)
      damping = ieee_nan()
      if (row%valid) damping = epsilon + pi*self%c%value(row%p)/(self%m%value(row%p)*row%omega)
   end function equation_point_damping

   !> Rows are shared unless the β axis enters anywhere (`beta_general`) and the equation is
   !> not at a point's β.
   elemental logical function equation_shares_rows(self)
      class(equation_model_t), intent(in) :: self  !! the model
      equation_shares_rows = self%pinned .or. .not. self%beta_general
   end function equation_shares_rows

   !> The equation at β: a copy with its β axis fixed there (`pinned`) when β enters anywhere,
   !> its row at α, the ranges of its split and its window there kept; else the equation.
   subroutine equation_at_point(self, alpha, beta, local)
      class(equation_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha                !! α of the point
      real(wp), intent(in) :: beta                 !! β of the point
      class(hill_model_t), allocatable, intent(out) :: local  !! the equation at β
      allocate (local, source=self)
      select type (local)
      class is (equation_model_t)
         if (.not. (local%beta_general .and. local%ready) .or. local%pinned) return
         local%values(local%i_beta) = beta
         local%pinned = .true.
         if (.not. ieee_is_finite(alpha)) return
         local%kept_row = row_at(local, alpha)
         local%kept_alpha = alpha
         call sampled_ranges(local, alpha, local%kept_ranges(1), local%kept_ranges(2), local%kept_ranges(3), &
                             local%kept_ranges(4))
         local%kept_window = equation_window(local, alpha)
         ! kept last: the values above are computed, not read back
         local%kept = .true.
      end select
   end subroutine equation_at_point

   !> The equation keeps what it derives at α: it is a point's equation, at the point's α.
   elemental logical function kept_at(self, alpha)
      class(equation_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha                !! α
      kept_at = self%kept .and. alpha == self%kept_alpha
   end function kept_at

   !> The damping is the equation's own (`damping`), not the scene's ε.
   elemental logical function equation_own_damping(self)
      class(equation_model_t), intent(in) :: self  !! the model
      equation_own_damping = .false.
   end function equation_own_damping

   !> The damping c is not the constant 0.
   elemental logical function equation_has_damping(self)
      class(equation_model_t), intent(in) :: self  !! the model
      equation_has_damping = .false.
      if (.not. self%ready) return
      equation_has_damping = .not. self%c%is_constant()
      if (.not. equation_has_damping) equation_has_damping = abs(self%c%value(self%values)) > 0.0_wp
   end function equation_has_damping

   !> The parameter of axis k (1: α, 2: β), as the files name its column.
   pure function equation_axis_name(self, k) result(name)
      class(equation_model_t), intent(in) :: self  !! the model
      integer, intent(in) :: k                     !! 1 or 2
      character(len=:), allocatable :: name
      if (k == 1) then
         name = self%alpha_name
      else
         name = self%beta_name
      end if
   end function equation_axis_name

   !> The parameters at the point (α, β): the given values with the axes set.
   pure function equation_at(self, alpha, beta) result(p)
      class(equation_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha, beta          !! the point
      real(wp), allocatable :: p(:)
      if (.not. self%ready) then
         allocate (p(0))
         return
      end if
      p = self%values
      p(self%i_alpha) = alpha
      p(self%i_beta) = beta
   end function equation_at

   !> An equation is in its user's time t (τ = Ωt/π).
   elemental logical function equation_has_time(self)
      class(equation_model_t), intent(in) :: self  !! the model
      equation_has_time = .true.
   end function equation_has_time

   !> dτ/dt at the point: Ω/π there (τ = Ωt/π, the period 2π/Ω in t); 0 outside the domain.
   !> The equation at a point's β (`pinned`) keeps that β whatever `beta` is.
   elemental real(wp) function equation_tau_rate(self, alpha, beta) result(rate)
      class(equation_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha, beta          !! the point
      rate = 0.0_wp
      if (self%ready) rate = self%drive%tau_rate(self%values, self%i_alpha, self%i_beta, alpha, beta, self%pinned)
   end function equation_tau_rate
end module hillstab_hill_model_equation

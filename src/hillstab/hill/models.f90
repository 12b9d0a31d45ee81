!> The models of the periodic coefficient Q(τ) of x'' + Q(τ) x = 0 (period 2 in τ): one
!> table, from which every other use derives, and the dispatch of every quantity the
!> numerical methods need of a model. Each model's formulas live in its own module
!> (hillstab_hill_model_elastic, hillstab_hill_model_mathieu); this module registers
!> them. A new model of Q is its module plus one row of `model_table` and one case in
!> each `select case` below.
!>
!> Models (the codes are the C API's HILLSTAB_MODEL_* and the F77 MODEL codes):
!> - `model_elastic` (1): Q(τ) = (β − α cos πτ)/(1 − (α/π²) cos πτ), paper eq. (25);
!> - `model_mathieu` (2): q(τ) = β − α cos πτ, the paper's Mathieu form (A1) with α playing ν.
!> Both carry the damping shift −ε²/4 of eq. (47), so that they describe χ = e^{ετ/2} x.
!>
!>```fortran
!> type(hill_model_t) :: model
!> model = hill_model_t(model_from_name("elastic"), alpha=4.0_wp, beta=6.0_wp, epsilon=0.0_wp)
!> print *, hill_coefficient(model, 0.5_wp), model_description(model%kind)
!>```
module hillstab_hill_models
   use hillstab_core_kinds, only: wp
   use hillstab_core_error, only: error_t, set_error, err_invalid_parameter
   use hillstab_core_text, only: name_position, alternatives_text
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use hillstab_hill_units, only: physical_t, physical_alpha, physical_nu
   use hillstab_hill_mathieu, only: mathieu_witness
   use hillstab_hill_model_elastic, only: elastic_alpha_valid, elastic_alpha_domain, elastic_coefficient, &
      elastic_segment_mean, elastic_split, elastic_shape, elastic_shapes_from_half_sines, elastic_shape_root_mean, &
      elastic_mesh_kappa, elastic_auto_difficulty, elastic_auto_amplitude, elastic_hill_k, elastic_hill_coupling, &
      elastic_fourier_decay, elastic_two_piece_values, elastic_shape_range
   use hillstab_hill_model_mathieu, only: mathieu_coefficient, mathieu_segment_mean, mathieu_split, mathieu_shape, &
      mathieu_shapes_from_half_sines, mathieu_shape_root_mean, mathieu_auto_difficulty, mathieu_auto_amplitude, &
      mathieu_hill_coupling, mathieu_two_piece_values
   implicit none
   private
   public :: hill_model_t, model_info_t, model_table, model_count, model_elastic, model_mathieu, model_info
   public :: model_name, model_from_name, model_names_text, model_description, model_summary, model_alpha_domain, &
      model_physical_note, model_is_pendulum, model_has_witness
   public :: check_model, check_model_alpha, check_model_batch, model_alpha_valid, damping_shift
   public :: hill_coefficient, segment_average, model_split, model_shape, model_shapes_from_half_sines, shape_root_mean
   public :: model_mesh_kappa, model_auto_difficulty, model_auto_amplitude, model_coefficient_range, &
      model_shape_range, coefficient_range
   public :: model_hill_k, model_hill_coupling, model_fourier_decay
   public :: model_two_piece_values, model_witness_beta, model_physical_alpha

   !> Q(τ) of eq. (25), the exact linearisation about the vertical bounce.
   integer, parameter :: model_elastic = 1
   !> q(τ) = β − α cos πτ, the small-amplitude (Mathieu) limit, eq. (A1).
   integer, parameter :: model_mathieu = 2

   !> What a model is, in words and flags (one row of `model_table`; its code is its row).
   type :: model_info_t
      character(len=16) :: name = ""          !! the scene's and the messages' name
      !> the coefficient as output headers state it, after "model: <name>, "
      character(len=100) :: formula = ""
      character(len=80) :: summary = ""       !! the coefficient in a template's comment
      !> the α domain for messages ("" when any finite α is accepted)
      character(len=60) :: alpha_domain = ""
      !> what α means when it comes from physical units, for headers ("" when it is α = aπ²/ρ)
      character(len=60) :: physical_note = ""
      !> the model is the elastic pendulum itself: it has the physical domain (a `physical`
      !> column), it can be simulated (task series) and α = aπ²/ρ
      logical :: pendulum = .false.
      logical :: witness = .false.            !! GSL gives an independent witness of its transition curves
   end type model_info_t

   !> The models, in the order of their codes.
   type(model_info_t), parameter :: model_table(2) = [ &
      model_info_t(name="elastic", &
         formula="Q(tau) = (beta - alpha cos(pi tau))/(1 - (alpha/pi^2) cos(pi tau)), eq. (25)", &
         summary="Q = (beta - alpha cos pi tau)/(1 - (alpha/pi^2) cos pi tau), eq. (25)", &
         alpha_domain=elastic_alpha_domain, physical_note="", pendulum=.true., witness=.false.), &
      model_info_t(name="mathieu", &
         formula="q(tau) = beta - alpha cos(pi tau), eq. (A1), alpha playing nu", &
         summary="Q = beta - alpha cos pi tau", &
         alpha_domain="", physical_note=" (here alpha is nu = a r0 pi^2/rho^2 of eq. (21))", &
         pendulum=.false., witness=.true.)]
   !> Number of models; their codes are 1 … model_count.
   integer, parameter :: model_count = size(model_table)
   !> The names, contiguous (passing `model_table%name` would copy the column on every call).
   character(len=16), parameter :: model_names(model_count) = model_table%name

   !> Parameters of one Hill equation.
   type :: hill_model_t
      integer :: kind = model_elastic  !! model_elastic or model_mathieu
      real(wp) :: alpha = 0.0_wp       !! α = aπ²/ρ (elastic) or ν (mathieu)
      real(wp) :: beta = 0.0_wp        !! β = gπ²/(ρω²)
      real(wp) :: epsilon = 0.0_wp     !! damping ε = κπ/ω of eq. (46)
   end type hill_model_t

   !> Largest |α| and |β| of a model: beyond it Q, the grid spacings and the methods'
   !> scalings overflow.
   real(wp), parameter :: max_magnitude = 1.0e15_wp

contains

   !> The row of a model code (a row named "unknown", its texts empty, for any other code).
   pure function model_info(kind) result(info)
      integer, intent(in) :: kind  !! a model constant
      type(model_info_t) :: info
      info%name = "unknown"
      if (kind >= 1 .and. kind <= model_count) info = model_table(kind)
   end function model_info

   !> Name of a model constant ("unknown" for any other code).
   pure function model_name(kind) result(name)
      integer, intent(in) :: kind  !! model_elastic or model_mathieu
      character(len=:), allocatable :: name
      type(model_info_t) :: row
      row = model_info(kind)
      name = trim(row%name)
   end function model_name

   !> Model constant from its name (any case, blanks trimmed); −1 when unknown.
   pure integer function model_from_name(name) result(kind)
      character(len=*), intent(in) :: name  !! a model name
      kind = name_position(name, model_names)
      if (kind == 0) kind = -1
   end function model_from_name

   !> The model names as a choice for messages: "elastic or mathieu".
   pure function model_names_text() result(text)
      character(len=:), allocatable :: text
      text = alternatives_text(model_names)
   end function model_names_text

   !> The line an output header gives the model, e.g. "model: mathieu, q(tau) = beta - alpha cos(pi tau),
   !> eq. (A1), alpha playing nu".
   pure function model_description(kind) result(text)
      integer, intent(in) :: kind  !! a model constant
      character(len=:), allocatable :: text
      type(model_info_t) :: row
      row = model_info(kind)
      text = "model: "//model_name(kind)//", "//trim(row%formula)
   end function model_description

   !> The coefficient in a few words (a template's comment), e.g. "Q = beta - alpha cos pi tau".
   pure function model_summary(kind) result(text)
      integer, intent(in) :: kind  !! a model constant
      character(len=:), allocatable :: text
      type(model_info_t) :: row
      row = model_info(kind)
      text = trim(row%summary)
   end function model_summary

   !> The α domain in words, e.g. "0 <= alpha < pi**2 = 9.8696044010893586"; "" when every
   !> finite α is accepted.
   pure function model_alpha_domain(kind) result(text)
      integer, intent(in) :: kind  !! a model constant
      character(len=:), allocatable :: text
      type(model_info_t) :: row
      row = model_info(kind)
      text = trim(row%alpha_domain)
   end function model_alpha_domain

   !> What α means when a scene gives physical units, to append to a header line ("" when it is aπ²/ρ).
   pure function model_physical_note(kind) result(text)
      integer, intent(in) :: kind  !! a model constant
      character(len=:), allocatable :: text
      type(model_info_t) :: row
      row = model_info(kind)
      text = trim(row%physical_note)
   end function model_physical_note

   !> The model is the elastic pendulum: it has the physical domain (0 ≤ α, β < π²), a
   !> `physical` column, the nonlinear simulation and α = aπ²/ρ.
   elemental logical function model_is_pendulum(kind)
      integer, intent(in) :: kind  !! a model constant
      type(model_info_t) :: row
      row = model_info(kind)
      model_is_pendulum = row%pendulum
   end function model_is_pendulum

   !> GSL gives an independent witness of the model's transition curves (`model_witness_beta`).
   elemental logical function model_has_witness(kind)
      integer, intent(in) :: kind  !! a model constant
      type(model_info_t) :: row
      row = model_info(kind)
      model_has_witness = row%witness
   end function model_has_witness

   !> α lies in the model's domain (finite; elastic: 0 ≤ α < π², a < ρ). False for an unknown model.
   elemental logical function model_alpha_valid(kind, alpha) result(valid)
      integer, intent(in) :: kind    !! a model constant
      real(wp), intent(in) :: alpha  !! α (ν for the Mathieu model)
      select case (kind)
      case (model_elastic)
         valid = elastic_alpha_valid(alpha)
      case (model_mathieu)
         valid = ieee_is_finite(alpha)
      case default
         valid = .false.
      end select
   end function model_alpha_valid

   !> err_invalid_parameter unless `kind` is a model and α lies in its domain, naming the
   !> domain and the value.
   pure subroutine check_model_alpha(kind, alpha, error)
      integer, intent(in) :: kind    !! a model constant
      real(wp), intent(in) :: alpha  !! α (ν for the Mathieu model)
      !> err_invalid_parameter naming the value and the limit; unallocated when valid
      type(error_t), allocatable, intent(out) :: error
      character(len=64) :: buf
      if (kind < 1 .or. kind > model_count) then
         call set_error(error, err_invalid_parameter, "unknown model kind")
      else if (.not. model_alpha_valid(kind, alpha)) then
         write (buf, '(es23.16)') alpha
         call set_error(error, err_invalid_parameter, model_name(kind)//" model needs "//model_alpha_domain(kind)// &
            ", got alpha = "//trim(adjustl(buf)))
      end if
   end subroutine check_model_alpha

   !> Validate the parameters: finite values, ε ≥ 0, magnitudes the methods can scale,
   !> a known model and α in its domain (elastic: 0 ≤ α < π², the mass never reaches the pivot).
   pure subroutine check_model(model, error)
      type(hill_model_t), intent(in) :: model  !! the parameters to check
      !> err_invalid_parameter naming the value and the limit; unallocated when valid
      type(error_t), allocatable, intent(out) :: error
      character(len=64) :: buf
      if (.not. (ieee_is_finite(model%alpha) .and. ieee_is_finite(model%beta) &
                 .and. ieee_is_finite(model%epsilon))) then
         call set_error(error, err_invalid_parameter, "alpha, beta and epsilon must be finite")
         return
      end if
      if (model%epsilon < 0.0_wp) then
         write (buf, '(es12.5)') model%epsilon
         call set_error(error, err_invalid_parameter, "epsilon must be >= 0, got "//trim(adjustl(buf)))
         return
      end if
      ! beyond these magnitudes Q, the grid spacings and the methods' scalings overflow
      if (max(abs(model%alpha), abs(model%beta)) > max_magnitude .or. model%epsilon > 100.0_wp) then
         call set_error(error, err_invalid_parameter, "|alpha|, |beta| must be <= 1e15 and epsilon <= 100")
         return
      end if
      call check_model_alpha(model%kind, model%alpha, error)
   end subroutine check_model

   !> `check_model` for the points (kind, α, β_j, ε) of a batch: α and ε checked once, each
   !> β for what depends on it (finite, |β| ≤ 1e15); the error of the first failing point.
   pure subroutine check_model_batch(kind, alpha, epsilon, betas, error)
      integer, intent(in) :: kind              !! a model constant
      real(wp), intent(in) :: alpha, epsilon   !! α and ε of the batch
      real(wp), intent(in) :: betas(:)         !! the β values
      !> err_invalid_parameter naming the value and the limit; unallocated when all are valid
      type(error_t), allocatable, intent(out) :: error
      integer :: j
      if (size(betas) == 0) return
      call check_model(hill_model_t(kind, alpha, betas(1), epsilon), error)
      if (allocated(error)) return
      do j = 2, size(betas)
         ! NaN first, on its own: an ordered comparison of a NaN raises the invalid flag
         ! (a trap in debug builds), and Fortran's .and. need not stop at the first operand
         if (.not. ieee_is_finite(betas(j))) then
            call check_model(hill_model_t(kind, alpha, betas(j), epsilon), error)
            return
         end if
         if (abs(betas(j)) > max_magnitude) then
            call check_model(hill_model_t(kind, alpha, betas(j), epsilon), error)
            return
         end if
      end do
   end subroutine check_model_batch

   !> Damping shift −ε²/4 of eq. (47).
   elemental real(wp) function damping_shift(epsilon)
      real(wp), intent(in) :: epsilon  !! damping epsilon of eq. (46)
      damping_shift = -0.25_wp*epsilon*epsilon
   end function damping_shift

   !> The coefficient q(τ) of the (damping-shifted) Hill equation, eq. (25)/(A1) and (47).
   elemental real(wp) function hill_coefficient(model, tau) result(q)
      type(hill_model_t), intent(in) :: model  !! model kind, alpha, beta, epsilon
      real(wp), intent(in) :: tau  !! dimensionless time, πτ = ωt
      select case (model%kind)
      case (model_mathieu)
         q = mathieu_coefficient(model%alpha, model%beta, tau)
      case default
         q = elastic_coefficient(model%alpha, model%beta, tau)
      end select
      q = q + damping_shift(model%epsilon)
   end function hill_coefficient

   !> Exact mean of q over [tau_a, tau_b] (closed form).
   pure real(wp) function segment_average(model, tau_a, tau_b) result(q)
      type(hill_model_t), intent(in) :: model  !! model kind, alpha, beta, epsilon
      real(wp), intent(in) :: tau_a, tau_b  !! segment ends, tau_a < tau_b
      select case (model%kind)
      case (model_mathieu)
         q = mathieu_segment_mean(model%alpha, model%beta, tau_a, tau_b)
      case default
         q = elastic_segment_mean(model%alpha, model%beta, tau_a, tau_b)
      end select
      q = q + damping_shift(model%epsilon)
   end function segment_average

   !> q = c₀ + c₁ w(τ) with the shape function w independent of β (`model_shape`), the
   !> damping shift in c₀: elastic c₀ = π² − ε²/4, c₁ = β − π²; Mathieu c₀ = β − ε²/4,
   !> c₁ = −ν. Method auto shares w over the β of a chart row.
   elemental subroutine model_split(kind, alpha, beta, epsilon, c0, c1)
      integer, intent(in) :: kind    !! a model constant
      real(wp), intent(in) :: alpha, beta, epsilon  !! the point and its damping
      real(wp), intent(out) :: c0  !! constant part of q
      real(wp), intent(out) :: c1  !! factor of w
      select case (kind)
      case (model_mathieu)
         call mathieu_split(alpha, beta, c0, c1)
      case default
         call elastic_split(beta, c0, c1)
      end select
      c0 = c0 + damping_shift(epsilon)
   end subroutine model_split

   !> The shape function w(τ) of `model_split`: elastic 1/(1 − (α/π²) cos πτ), Mathieu cos πτ.
   elemental real(wp) function model_shape(kind, alpha, tau) result(w)
      integer, intent(in) :: kind    !! a model constant
      real(wp), intent(in) :: alpha  !! α (ν)
      real(wp), intent(in) :: tau    !! τ
      select case (kind)
      case (model_mathieu)
         w = mathieu_shape(tau)
      case default
         w = elastic_shape(alpha, tau)
      end select
   end function model_shape

   !> w at n points given by their half-angle sines s = sin(πτ/2) (method auto's mesh).
   pure subroutine model_shapes_from_half_sines(kind, alpha, n, s, w)
      integer, intent(in) :: kind    !! a model constant
      real(wp), intent(in) :: alpha  !! α (ν)
      integer, intent(in) :: n       !! number of points
      real(wp), intent(in) :: s(n)   !! sin(πτ/2) at the points
      real(wp), intent(out) :: w(n)  !! the shape function there
      select case (kind)
      case (model_mathieu)
         call mathieu_shapes_from_half_sines(n, s, w)
      case default
         call elastic_shapes_from_half_sines(alpha, n, s, w)
      end select
   end subroutine model_shapes_from_half_sines

   !> The least and the largest value over the period of the shape function w(τ) of the
   !> split q = c₀ + c₁ w (`model_split`): elastic 1/(1 ± α/π²), Mathieu cos πτ in [−1, 1].
   elemental subroutine model_shape_range(kind, alpha, w_min, w_max)
      integer, intent(in) :: kind    !! a model constant
      real(wp), intent(in) :: alpha  !! α (ν)
      real(wp), intent(out) :: w_min, w_max  !! the range of w
      select case (kind)
      case (model_mathieu)
         w_min = -1.0_wp
         w_max = 1.0_wp
      case default
         call elastic_shape_range(alpha, w_min, w_max)
      end select
   end subroutine model_shape_range

   !> The least and the largest value over the period of q = c₀ + c₁ w(τ) for the split
   !> (c₀, c₁) of a point and the range of w (`model_shape_range`), widened by a few
   !> roundings of the values it is made of, so that the true range lies inside it.
   elemental subroutine coefficient_range(c0, c1, w_min, w_max, q_min, q_max)
      real(wp), intent(in) :: c0, c1        !! the split of q at the point
      real(wp), intent(in) :: w_min, w_max  !! the range of w
      real(wp), intent(out) :: q_min, q_max  !! bounds of q over the period
      real(wp) :: a, b, slack
      a = c0 + c1*w_min
      b = c0 + c1*w_max
      slack = 16.0_wp*epsilon(1.0_wp)*(abs(c0) + abs(c1)*max(abs(w_min), abs(w_max)))
      q_min = min(a, b) - slack
      q_max = max(a, b) + slack
   end subroutine coefficient_range

   !> `coefficient_range` of the point (α, β, ε) of a model.
   elemental subroutine model_coefficient_range(kind, alpha, beta, damping, q_min, q_max)
      integer, intent(in) :: kind    !! a model constant
      real(wp), intent(in) :: alpha, beta  !! the point
      real(wp), intent(in) :: damping      !! its damping ε
      real(wp), intent(out) :: q_min, q_max  !! bounds of q over the period
      real(wp) :: c0, c1, w_min, w_max
      call model_split(kind, alpha, beta, damping, c0, c1)
      call model_shape_range(kind, alpha, w_min, w_max)
      call coefficient_range(c0, c1, w_min, w_max, q_min, q_max)
   end subroutine model_coefficient_range

   !> ∫₀¹ √|w(τ)| dτ of the shape function (or a bound of it): elastic an elliptic integral
   !> by an AGM (1 at α = 0, growing like ln(1/(1 − α/π²))), Mathieu 1. It enters the phase
   !> bound of the round-off level (hillstab_hill_coefficient `phase_bound`).
   elemental real(wp) function shape_root_mean(kind, alpha) result(mean)
      integer, intent(in) :: kind    !! a model constant
      real(wp), intent(in) :: alpha  !! α (ν for the Mathieu model)
      select case (kind)
      case (model_mathieu)
         mean = mathieu_shape_root_mean()
      case default
         mean = elastic_shape_root_mean(alpha)
      end select
   end function shape_root_mean

   !> κ of method auto's mesh map tan(πτ/2) = √((1 − κ)/(1 + κ)) tan(πψ/2) for its exponent
   !> `power`: elastic 1 − (1 − α/π²)^power (steps packed into the dip), Mathieu 0 (uniform).
   elemental real(wp) function model_mesh_kappa(kind, alpha, power) result(kappa)
      integer, intent(in) :: kind    !! a model constant
      real(wp), intent(in) :: alpha  !! α (ν)
      real(wp), intent(in) :: power  !! method auto's mesh exponent
      select case (kind)
      case (model_elastic)
         kappa = elastic_mesh_kappa(alpha, power)
      case default
         kappa = 0.0_wp
      end select
   end function model_mesh_kappa

   !> x of method auto's calibrated step table (elastic −ln(1 − α/π²); Mathieu the same of
   !> min(|ν|, 9)).
   elemental real(wp) function model_auto_difficulty(kind, alpha) result(x)
      integer, intent(in) :: kind    !! a model constant
      real(wp), intent(in) :: alpha  !! α (ν)
      select case (kind)
      case (model_elastic)
         x = elastic_auto_difficulty(alpha)
      case default
         x = mathieu_auto_difficulty(alpha)
      end select
   end function model_auto_difficulty

   !> The amplitude of q that method auto's step count grows with (elastic |c₁|, Mathieu
   !> |c₁| + 0.1 |c₀|), from the split of `model_split`.
   elemental real(wp) function model_auto_amplitude(kind, c0, c1) result(amplitude)
      integer, intent(in) :: kind    !! a model constant
      real(wp), intent(in) :: c0, c1  !! the split of q
      select case (kind)
      case (model_elastic)
         amplitude = elastic_auto_amplitude(c1)
      case default
         amplitude = mathieu_auto_amplitude(c0, c1)
      end select
   end function model_auto_amplitude

   !> Hill's method writes x'' + Q x = 0 as −(1 − k cos πτ) x'' + α cos πτ x = β (1 − k cos πτ) x:
   !> k = α/π² (elastic), 0 (Mathieu).
   elemental real(wp) function model_hill_k(kind, alpha) result(k)
      integer, intent(in) :: kind    !! a model constant
      real(wp), intent(in) :: alpha  !! α (ν)
      select case (kind)
      case (model_elastic)
         k = elastic_hill_k(alpha)
      case default
         k = 0.0_wp
      end select
   end function model_hill_k

   !> The weight α − kπ²t of cos πτ on the Fourier mode t = (κ/π)² in Hill's method
   !> (elastic α(1 − t), Mathieu ν).
   elemental real(wp) function model_hill_coupling(kind, alpha, t) result(coupling)
      integer, intent(in) :: kind    !! a model constant
      real(wp), intent(in) :: alpha  !! α (ν)
      real(wp), intent(in) :: t      !! the squared mode number
      select case (kind)
      case (model_elastic)
         coupling = elastic_hill_coupling(alpha, t)
      case default
         coupling = mathieu_hill_coupling(alpha)
      end select
   end function model_hill_coupling

   !> The ratio r < 1 by which the Fourier coefficients of the eigenfunctions decay per
   !> mode (elastic k/(1 + √(1 − k²)) for α > 0); 0 when they decay faster than any
   !> geometric sequence (Mathieu, α = 0): Hill's method then sizes its truncation by
   !> the oscillation alone.
   elemental real(wp) function model_fourier_decay(kind, alpha) result(r)
      integer, intent(in) :: kind    !! a model constant
      real(wp), intent(in) :: alpha  !! α (ν)
      select case (kind)
      case (model_elastic)
         r = elastic_fourier_decay(alpha)
      case default
         r = 0.0_wp
      end select
   end function model_fourier_decay

   !> The two constant pieces of method formula, the paper's sampling (28) with the
   !> damping shift in its closed form: elastic eqs. (49)–(50), Mathieu (A3)/(A9).
   elemental subroutine model_two_piece_values(model, q_first, q_second)
      type(hill_model_t), intent(in) :: model  !! model kind, alpha, beta, epsilon
      real(wp), intent(out) :: q_first   !! the value on [0, 1)
      real(wp), intent(out) :: q_second  !! the value on [1, 2)
      select case (model%kind)
      case (model_mathieu)
         call mathieu_two_piece_values(model%alpha, model%beta, model%epsilon, q_first, q_second)
      case default
         call elastic_two_piece_values(model%alpha, model%beta, model%epsilon, q_first, q_second)
      end select
   end subroutine model_two_piece_values

   !> An independent value of β on the transition curve (order, parity) at α where the
   !> model has one (`model_has_witness`: Mathieu, GSL's characteristic values within the
   !> orders and q where GSL is trusted); `available` false otherwise.
   subroutine model_witness_beta(kind, order, parity, alpha, beta, available)
      integer, intent(in) :: kind           !! a model constant
      integer, intent(in) :: order, parity  !! order n of the curve; parity: 1 even (a_n), 2 odd (b_n)
      real(wp), intent(in) :: alpha         !! α (ν)
      real(wp), intent(out) :: beta         !! the witness' β (0 when not available)
      logical, intent(out) :: available     !! a witness value was computed
      select case (kind)
      case (model_mathieu)
         call mathieu_witness(order, parity, alpha, beta, available)
      case default
         beta = 0.0_wp
         available = .false.
      end select
   end subroutine model_witness_beta

   !> The model's α of a pendulum given in physical units: α = aπ²/ρ (elastic, eq. (24)),
   !> ν = a r0 π²/ρ² (Mathieu, eq. (21)).
   elemental real(wp) function model_physical_alpha(kind, p) result(alpha)
      integer, intent(in) :: kind         !! a model constant
      type(physical_t), intent(in) :: p   !! the pendulum (ω > 0, ρ > 0)
      select case (kind)
      case (model_mathieu)
         alpha = physical_nu(p)
      case default
         alpha = physical_alpha(p)
      end select
   end function model_physical_alpha
end module hillstab_hill_models

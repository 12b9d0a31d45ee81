!> A model of the periodic coefficient of the Hill equation x'' + Q(τ) x = 0 as a value:
!> the abstract type `hill_model_t`, whose bindings answer everything the methods ask of a
!> model (Q, its exact segment means, the split Q = c₀ + c₁ w(τ) with w independent of β,
!> the range of w, the window a method integrates over, the hints of method auto's mesh
!> and step count, the terms of Hill's method, the paper's two pieces, the α domain and
!> the texts that headers and messages give), and the point of a chart, `hill_point_t`
!> (α, β and the damping ε). `hill_model_t` extends `model_base_t` (hillstab_hill_model_base:
!> name, formula, the variables of a model carrying data). A concrete model extends `hill_model_t`, carries its own data
!> (coefficients, samples) and is registered in hillstab_hill_models, which builds it from
!> its name; the methods receive `class(hill_model_t)` and never ask which model it is.
!>
!> Every model describes the damped equation through χ = e^{ετ/2} x (eq. (47)): its
!> bindings give Q without damping, and the procedures of this module add the shift
!> −ε²/4 (`hill_coefficient`, `segment_average`, `model_split`).
!>
!> The defaults of the optional bindings suit a smooth coefficient of period 2 that is even
!> about τ = 0 (Q(−τ) = Q(τ)): a model overrides what differs.
!>
!>```fortran
!> type(elastic_model_t) :: elastic
!> print *, hill_coefficient(elastic, hill_point_t(alpha=4.0_wp, beta=6.0_wp), 0.5_wp)
!> print *, model_description(elastic)
!>```
module hillstab_hill_model
   use hillstab_core_kinds, only: wp, pi, pi2
   use hillstab_core_error, only: error_t, set_error, err_invalid_parameter
   use hillstab_hill_model_base, only: model_base_t, model_variable_t, model_variable_real, model_variable_list, &
      model_variable_file, model_variable_text
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   implicit none
   private
   public :: hill_model_t, hill_point_t, hill_window_t, max_window_breaks
   public :: hill_form_none, hill_form_pencil
   public :: model_variable_t, model_variable_real, model_variable_list, model_variable_file, model_variable_text
   public :: harmonics_none, harmonics_infinite
   public :: hill_coefficient, hill_coefficient_before, segment_average, model_split, model_split_row, damping_shift, &
      model_description, damping_at
   public :: window_piece_end, model_equation_text
   public :: coefficient_range, model_coefficient_range, widen_by_offset, offset_bound
   public :: check_point, check_alpha, check_batch, max_magnitude, auto_table_steps

   !> Hill's method does not apply to the model (its transition curves come from elsewhere).
   integer, parameter :: hill_form_none = 0
   !> Hill's method on the pencil −(1 − k cos πτ) x'' + a(t) cos πτ x = β (1 − k cos πτ) x
   !> (`hill_k`, `hill_coupling`, `fourier_decay`): the elastic and the Mathieu coefficient.
   integer, parameter :: hill_form_pencil = 1

   !> `drive_harmonic_count`: Q is not of the form β + g(τ) with g independent of β.
   integer, parameter :: harmonics_none = 0
   !> `drive_harmonic_count`: g has infinitely many harmonics (truncated on request).
   integer, parameter :: harmonics_infinite = -1

   !> Most interior jumps of Q a window can hold.
   integer, parameter :: max_window_breaks = 16

   !> Largest |α| and |β| of a point: beyond it Q, the grid spacings and the methods'
   !> scalings overflow.
   real(wp), parameter :: max_magnitude = 1.0e15_wp

   !> One point of a chart: the parameters of one Hill equation of a model.
   type :: hill_point_t
      real(wp) :: alpha = 0.0_wp    !! α: the drive (elastic: aπ²/ρ; Mathieu: ν)
      real(wp) :: beta = 0.0_wp     !! β: the mean stiffness (elastic: gπ²/(ρω²))
      real(wp) :: epsilon = 0.0_wp  !! damping ε = κπ/ω of eq. (46)
   end type hill_point_t

   !> Where a method integrates to get the trace of one period: from `start` over `length`.
   !> When Q is even about `start` (Q(start + s) = Q(start − s)), half a period is enough
   !> (`half`, Floquet theory: S = 2(u v' + u' v) at the end); else the whole period. Q is
   !> smooth inside the window but at `breaks`, where it may jump (the methods put a mesh
   !> point there and integrate each piece apart).
   type :: hill_window_t
      real(wp) :: start = 0.0_wp   !! τ where the integration starts
      real(wp) :: length = 1.0_wp  !! half the period (`half`) or the period
      logical :: half = .true.     !! Q is even about `start`
      integer :: n_breaks = 0      !! number of interior jumps
      !> the jumps, ascending, strictly inside (start, start + length)
      real(wp) :: breaks(max_window_breaks) = 0.0_wp
   end type hill_window_t

   !> A model of Q(τ; α, β), period `period()` in τ (2 unless the model says otherwise).
   !> At α = 0 every model's Q is the constant β (the chart's axis of an undriven oscillator).
   type, abstract, extends(model_base_t) :: hill_model_t
   contains
      !> Q(τ) without damping
      procedure(coefficient_interface), deferred :: coefficient
      !> exact mean of Q over [τ_a, τ_b] without damping
      procedure(segment_mean_interface), deferred :: segment_mean
      !> Q = c₀ + c₁ w(τ) (+ v(τ), `has_offset`) with w and v independent of β, without damping
      procedure(split_interface), deferred :: split
      !> `split` at every β of a row at once (what the row shares is computed once)
      procedure :: split_row => split_each
      !> w(τ) at many τ
      procedure(shapes_interface), deferred :: shapes
      !> the least and largest value of w over the period
      procedure(shape_range_interface), deferred :: shape_range
      procedure :: summary => formula_summary
      procedure :: alpha_domain => no_alpha_domain
      procedure :: alpha_valid => finite_alpha
      procedure :: point_damping => scene_damping
      procedure :: shares_rows => rows_shared
      procedure :: at_point => model_copy
      procedure :: has_time => no_time_of_its_own
      procedure :: tau_rate => no_tau_rate
      procedure :: has_damping => no_own_damping
      procedure :: takes_scene_damping => scene_damping_taken
      procedure :: has_witness => no_witness
      procedure :: witness_beta => no_witness_beta
      procedure :: period => period_two
      procedure :: window => even_half_window
      procedure :: shape_root_mean => shape_root_bound
      procedure :: has_offset => no_offset
      procedure :: offset_range => zero_offset_range
      procedure :: offsets => zero_offsets
      procedure :: shapes_from_half_sines => shapes_at_half_sines
      procedure :: mesh_kappa => uniform_mesh
      procedure :: auto_difficulty => amplitude_difficulty
      procedure :: auto_amplitude => oscillation_amplitude
      procedure :: auto_safety => calibrated_safety
      procedure :: auto_min_steps => no_min_steps
      procedure :: two_piece_values => sampled_two_pieces
      procedure :: two_pieces_exact => two_pieces_approximate
      procedure :: hill_form => no_hill_form
      procedure :: hill_k => no_hill_k
      procedure :: hill_coupling => no_hill_coupling
      procedure :: hill_one_minus_k => complement_of_hill_k
      procedure :: fourier_decay => entire_decay
      procedure :: drive_harmonic_count => no_drive_harmonics
      procedure :: drive_harmonics => zero_drive_harmonics
   end type hill_model_t

   abstract interface
      !> Q(τ) at the point (α, β), without damping.
      elemental real(wp) function coefficient_interface(self, alpha, beta, tau) result(q)
         import :: hill_model_t, wp
         class(hill_model_t), intent(in) :: self  !! the model
         real(wp), intent(in) :: alpha, beta      !! the point
         real(wp), intent(in) :: tau              !! dimensionless time
      end function coefficient_interface

      !> Exact mean of Q over [τ_a, τ_b] at (α, β), without damping.
      pure real(wp) function segment_mean_interface(self, alpha, beta, tau_a, tau_b) result(q)
         import :: hill_model_t, wp
         class(hill_model_t), intent(in) :: self  !! the model
         real(wp), intent(in) :: alpha, beta      !! the point
         real(wp), intent(in) :: tau_a, tau_b     !! segment ends, tau_a < tau_b
      end function segment_mean_interface

      !> Q = c₀ + c₁ w(τ) at (α, β), w independent of β, without damping (plus the offset
      !> v(τ), also independent of β, for a model that `has_offset`).
      elemental subroutine split_interface(self, alpha, beta, c0, c1)
         import :: hill_model_t, wp
         class(hill_model_t), intent(in) :: self  !! the model
         real(wp), intent(in) :: alpha, beta      !! the point
         real(wp), intent(out) :: c0              !! constant part of Q
         real(wp), intent(out) :: c1              !! factor of w
      end subroutine split_interface

      !> The shape function w of the split at the times `tau`.
      pure subroutine shapes_interface(self, alpha, tau, w)
         import :: hill_model_t, wp
         class(hill_model_t), intent(in) :: self  !! the model
         real(wp), intent(in) :: alpha            !! α
         real(wp), intent(in) :: tau(:)           !! the times
         real(wp), intent(out) :: w(:)            !! w there (size(tau))
      end subroutine shapes_interface

      !> The least and the largest value of w over the period.
      elemental subroutine shape_range_interface(self, alpha, w_min, w_max)
         import :: hill_model_t, wp
         class(hill_model_t), intent(in) :: self  !! the model
         real(wp), intent(in) :: alpha            !! α
         real(wp), intent(out) :: w_min, w_max    !! the range of w
      end subroutine shape_range_interface
   end interface

contains

   !> The coefficient in a few words (a template's comment): the formula unless the model
   !> says otherwise.
   pure function formula_summary(self) result(text)
      class(hill_model_t), intent(in) :: self  !! the model
      character(len=:), allocatable :: text
      text = self%formula()
   end function formula_summary

   !> The α domain in words, for messages ("" when every finite α is accepted).
   pure function no_alpha_domain(self) result(text)
      class(hill_model_t), intent(in) :: self  !! the model
      character(len=:), allocatable :: text
      text = ""
   end function no_alpha_domain

   !> α lies in the model's domain: any finite α unless the model says otherwise.
   elemental logical function finite_alpha(self, alpha) result(valid)
      class(hill_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha            !! α
      valid = ieee_is_finite(alpha)
   end function finite_alpha

   !> The damping ε of the points of chart row α: the scene's `epsilon` unless the model
   !> carries its own (an equation in physical time: πc/(mΩ) at the row's parameters). A
   !> model that does not share rows (`shares_rows`) has no damping a row: the scene's ε,
   !> to which each point adds its own (`damping_at`).
   elemental real(wp) function scene_damping(self, alpha, epsilon) result(damping)
      class(hill_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha            !! α of the row
      real(wp), intent(in) :: epsilon          !! the scene's ε
      damping = epsilon
   end function scene_damping

   !> The points of a chart row share what the methods compute once a row: the shape w and
   !> offset v of the split, the window, the damping (`point_damping`) and method auto's
   !> meshes, β entering Q as c₀ and c₁ alone. True unless the model says otherwise (an
   !> equation whose β axis enters its frequency, mass, damping, or its stiffness other than
   !> affinely); the methods then take each point alone, as the point (α, 0) of the model at
   !> its β (`at_point`).
   elemental logical function rows_shared(self)
      class(hill_model_t), intent(in) :: self  !! the model
      rows_shared = .true.
   end function rows_shared

   !> The model at β: a model whose point (α, 0) is this model's point (α, β) — its Q, split,
   !> window and damping (`point_damping`) there — and whose rows are shared; what it
   !> derives at α it may keep (the point's α is given for that). A model that shares rows
   !> already is its own copy.
   subroutine model_copy(self, alpha, beta, local)
      class(hill_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha            !! α of the point
      real(wp), intent(in) :: beta             !! β of the point
      class(hill_model_t), allocatable, intent(out) :: local  !! the model at β
      allocate (local, source=self)
   end subroutine model_copy

   !> The model has a time of its user's, t (an equation in physical time, τ = Ωt/π):
   !> `tau_rate` gives dτ/dt at each point, so that a rate per unit τ becomes one per unit
   !> of t. False unless the model says so (τ is the model's only time).
   elemental logical function no_time_of_its_own(self)
      class(hill_model_t), intent(in) :: self  !! the model
      no_time_of_its_own = .false.
   end function no_time_of_its_own

   !> dτ/dt at the point (α, β): the units of τ in one unit of the user's time t, 2 over the
   !> period in t (an equation: Ω/π at the point); 0 for a model without a time of its own
   !> (`has_time`) and where the point has no period (outside the domain).
   elemental real(wp) function no_tau_rate(self, alpha, beta) result(rate)
      class(hill_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha, beta      !! the point
      rate = 0.0_wp
   end function no_tau_rate

   !> The damping ε of the point (α, β) given the scene's ε: the row's (`point_damping`)
   !> when the model shares rows, else that of the model at β (`at_point`) at α.
   function damping_at(model, alpha, beta, epsilon) result(damping)
      class(hill_model_t), intent(in) :: model  !! the model
      real(wp), intent(in) :: alpha, beta       !! the point
      real(wp), intent(in) :: epsilon           !! the scene's ε
      real(wp) :: damping
      class(hill_model_t), allocatable :: local
      if (model%shares_rows()) then
         damping = model%point_damping(alpha, epsilon)
      else
         call model%at_point(alpha, beta, local)
         damping = local%point_damping(alpha, epsilon)
      end if
   end function damping_at

   !> The model carries a damping of its own (`point_damping`), nonzero somewhere: false
   !> unless the model says so.
   elemental logical function no_own_damping(self)
      class(hill_model_t), intent(in) :: self  !! the model
      no_own_damping = .false.
   end function no_own_damping

   !> The scene's `epsilon` is the damping (true unless the model carries its own).
   elemental logical function scene_damping_taken(self)
      class(hill_model_t), intent(in) :: self  !! the model
      scene_damping_taken = .true.
   end function scene_damping_taken

   !> `split` at every β of a row, one after the other (a model whose split shares work along
   !> a row does it once).
   pure subroutine split_each(self, alpha, betas, c0s, c1s)
      class(hill_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha            !! α of the row
      real(wp), intent(in) :: betas(:)         !! its β
      real(wp), intent(out) :: c0s(:), c1s(:)  !! the split at each β
      integer :: j
      do j = 1, size(betas)
         call self%split(alpha, betas(j), c0s(j), c1s(j))
      end do
   end subroutine split_each

   !> An independent witness of the transition curves exists (`witness_beta`): none unless
   !> the model has one.
   elemental logical function no_witness(self)
      class(hill_model_t), intent(in) :: self  !! the model
      no_witness = .false.
   end function no_witness

   !> An independent value of β on the transition curve (order, parity) at α: none.
   subroutine no_witness_beta(self, order, parity, alpha, beta, available)
      class(hill_model_t), intent(in) :: self  !! the model
      integer, intent(in) :: order, parity     !! order n; parity 1 even (a_n), 2 odd (b_n)
      real(wp), intent(in) :: alpha            !! α
      real(wp), intent(out) :: beta            !! the witness' β (0: none)
      logical, intent(out) :: available        !! a witness value was computed
      beta = 0.0_wp
      available = .false.
   end subroutine no_witness_beta

   !> The period of Q in τ: 2, one radial oscillation.
   pure real(wp) function period_two(self) result(period)
      class(hill_model_t), intent(in) :: self  !! the model
      period = 2.0_wp
   end function period_two

   !> The window of a smooth Q even about τ = 0: [0, period/2], half a period.
   pure function even_half_window(self, alpha) result(window)
      class(hill_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha            !! α
      type(hill_window_t) :: window
      window = hill_window_t(start=0.0_wp, length=0.5_wp*self%period(), half=.true.)
   end function even_half_window

   !> A bound of ∫₀¹ √|w(τ)| dτ: √max|w| (the range of w), for the phase bound of the
   !> round-off level (hillstab_hill_coefficient `phase_bound`).
   elemental real(wp) function shape_root_bound(self, alpha) result(mean)
      class(hill_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha            !! α
      real(wp) :: w_min, w_max
      call self%shape_range(alpha, w_min, w_max)
      mean = sqrt(max(abs(w_min), abs(w_max)))
   end function shape_root_bound

   !> Q = c₀ + c₁ w(τ) + v(τ) with an offset v ≠ 0 (independent of β, like w): false unless
   !> the model says so. Method auto's shared meshes then carry v beside w (`offsets`); the
   !> ranges and the round-off levels of every method take v into account through
   !> `offset_range`.
   elemental logical function no_offset(self)
      class(hill_model_t), intent(in) :: self  !! the model
      no_offset = .false.
   end function no_offset

   !> Bounds of the offset v over the period (v_min ≤ v ≤ v_max): 0 and 0 unless the model
   !> `has_offset`.
   elemental subroutine zero_offset_range(self, alpha, v_min, v_max)
      class(hill_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha            !! α
      real(wp), intent(out) :: v_min, v_max    !! bounds of v
      v_min = 0.0_wp
      v_max = 0.0_wp
   end subroutine zero_offset_range

   !> The offset v at the times `tau`: 0 unless the model `has_offset`.
   pure subroutine zero_offsets(self, alpha, tau, v)
      class(hill_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha            !! α
      real(wp), intent(in) :: tau(:)           !! the times
      real(wp), intent(out) :: v(:)            !! v there (size(tau))
      v = 0.0_wp
   end subroutine zero_offsets

   !> w at n points of [0, 1] given by their half-angle sines s = sin(πτ/2) (method auto's
   !> mesh builds those by angle sums): through τ = (2/π) asin s unless the model has a
   !> closed form in s.
   pure subroutine shapes_at_half_sines(self, alpha, n, s, w)
      class(hill_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha            !! α
      integer, intent(in) :: n                 !! number of points
      real(wp), intent(in) :: s(n)             !! sin(πτ/2) at the points
      real(wp), intent(out) :: w(n)            !! w there
      call self%shapes(alpha, (2.0_wp/pi)*asin(min(1.0_wp, max(-1.0_wp, s))), w)
   end subroutine shapes_at_half_sines

   !> κ of method auto's mesh map tan(πτ/2) = √((1 − κ)/(1 + κ)) tan(πψ/2): 0, a uniform
   !> mesh, unless Q has a narrow feature at τ = 0 to pack steps into.
   elemental real(wp) function uniform_mesh(self, alpha, power) result(kappa)
      class(hill_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha            !! α
      real(wp), intent(in) :: power            !! method auto's mesh exponent
      kappa = 0.0_wp
   end function uniform_mesh

   !> x of method auto's calibrated step table, −ln(1 − min(|α|, 9)/π²): without a dip the
   !> amplitude α plays the role the elastic model's dip has (clipped to the table).
   elemental real(wp) function amplitude_difficulty(self, alpha) result(x)
      class(hill_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha            !! α
      x = -log(1.0_wp - min(abs(alpha), 9.0_wp)/pi2)
   end function amplitude_difficulty

   !> The amplitude of q that method auto's step count grows with: |c₁| + 0.1 |c₀| (the
   !> drive and, for large |β|, the oscillation itself).
   elemental real(wp) function oscillation_amplitude(self, c0, c1) result(amplitude)
      class(hill_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: c0, c1           !! the split of q (`model_split`)
      amplitude = abs(c1) + 0.1_wp*abs(c0)
   end function oscillation_amplitude

   !> Method auto's calibrated step table: the smallest N of Magnus-6 steps on [0, 1] that
   !> met 1e-10 against GSL rk8pd at 1e-14 for β ∈ [−2, 12], against x = −ln(1 − α/π²)
   !> (`auto_difficulty`; ln N linear in between, N ∝ (1 − α/π²)^−0.3 beyond), times 0.8
   !> (cheapest on average with the check).
   elemental real(wp) function auto_table_steps(x) result(n)
      real(wp), intent(in) :: x  !! the calibration variable
      real(wp), parameter :: table_x(9) = [0.0_wp, 0.052_wp, 0.227_wp, 0.519_wp, 0.937_wp, 1.666_wp, 2.43_wp, &
                                           3.29_wp, 4.95_wp]
      real(wp), parameter :: table_n(9) = [12.0_wp, 18.0_wp, 26.0_wp, 36.0_wp, 48.0_wp, 62.0_wp, 76.0_wp, &
                                           90.0_wp, 134.0_wp]
      real(wp), parameter :: slope_beyond = 0.3_wp
      real(wp) :: log_n
      integer :: i
      if (x >= table_x(size(table_x))) then
         log_n = log(table_n(size(table_n))) + slope_beyond*(x - table_x(size(table_x)))
      else
         i = 1
         do while (table_x(i + 1) < x)
            i = i + 1
         end do
         log_n = log(table_n(i)) + (log(table_n(i + 1)) - log(table_n(i)))*(x - table_x(i))/(table_x(i + 1) - table_x(i))
      end if
      n = exp(log_n)
   end function auto_table_steps

   !> The fewest steps per unit of τ method auto's first mesh may have (its Richardson check
   !> compares it with half as many): 0, auto's own floor, unless the drive's harmonics need
   !> more to be resolved on the coarser mesh.
   elemental integer function no_min_steps(self) result(n)
      class(hill_model_t), intent(in) :: self  !! the model
      n = 0
   end function no_min_steps

   !> The factor method auto's Richardson estimate is multiplied by before it is held against
   !> the tolerance: 1 where auto's step counts were calibrated (its first meshes put the
   !> pair in the asymptotic range), more for a model whose first meshes may be coarser.
   elemental real(wp) function calibrated_safety(self) result(factor)
      class(hill_model_t), intent(in) :: self  !! the model
      factor = 1.0_wp
   end function calibrated_safety

   !> The two constant pieces of method formula, the paper's sampling (28): Q(0) − ε²/4 on
   !> the first half period and Q(period/2) − ε²/4 on the second.
   elemental subroutine sampled_two_pieces(self, alpha, beta, epsilon, q_first, q_second)
      class(hill_model_t), intent(in) :: self   !! the model
      real(wp), intent(in) :: alpha, beta, epsilon  !! the point and its damping
      real(wp), intent(out) :: q_first   !! the value on the first half period
      real(wp), intent(out) :: q_second  !! the value on the second
      q_first = self%coefficient(alpha, beta, 0.0_wp) + damping_shift(epsilon)
      q_second = self%coefficient(alpha, beta, 0.5_wp*self%period()) + damping_shift(epsilon)
   end subroutine sampled_two_pieces

   !> The two pieces of method formula are Q itself (a square-wave coefficient), so that
   !> the paper's closed form is exact: false unless the model says so.
   pure logical function two_pieces_approximate(self) result(exact)
      class(hill_model_t), intent(in) :: self  !! the model
      exact = .false.
   end function two_pieces_approximate

   !> Which form of Hill's method the model offers (`hill_form_*`): none.
   pure integer function no_hill_form(self) result(form)
      class(hill_model_t), intent(in) :: self  !! the model
      form = hill_form_none
   end function no_hill_form

   !> k of the weight 1 − k cos πτ on x'' in Hill's pencil form: 0.
   elemental real(wp) function no_hill_k(self, alpha) result(k)
      class(hill_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha            !! α
      k = 0.0_wp
   end function no_hill_k

   !> 1 − k of Hill's pencil form (`hill_k`), from k unless the model has it more accurately.
   elemental real(wp) function complement_of_hill_k(self, alpha) result(one_minus_k)
      class(hill_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha            !! α
      one_minus_k = 1.0_wp - self%hill_k(alpha)
   end function complement_of_hill_k

   !> The weight of cos πτ on the Fourier mode t = (κ/π)² in Hill's pencil form: 0.
   elemental real(wp) function no_hill_coupling(self, alpha, t) result(coupling)
      class(hill_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha            !! α
      real(wp), intent(in) :: t                !! the squared mode number
      coupling = 0.0_wp
   end function no_hill_coupling

   !> The ratio r < 1 by which the Fourier coefficients of the eigenfunctions decay per
   !> mode; 0 when they decay faster than any geometric sequence.
   elemental real(wp) function entire_decay(self, alpha) result(r)
      class(hill_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha            !! α
      r = 0.0_wp
   end function entire_decay

   !> How many harmonics g(τ) = Q − β has when Q is of the form β + g(τ) with g independent
   !> of β (Hill's method for such models: `drive_harmonics`): harmonics_none unless the model
   !> says so, harmonics_infinite when they never end (a jump of Q).
   pure integer function no_drive_harmonics(self) result(count)
      class(hill_model_t), intent(in) :: self  !! the model
      count = harmonics_none
   end function no_drive_harmonics

   !> The mean and the first n harmonics of g(τ) = Q(τ) − β over the period P:
   !> g = mean + Σₘ (c(m) cos(2πmτ/P) + s(m) sin(2πmτ/P)). Zero unless the model has them.
   pure subroutine zero_drive_harmonics(self, alpha, n, mean, c, s)
      class(hill_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha            !! α
      integer, intent(in) :: n                 !! number of harmonics wanted
      real(wp), intent(out) :: mean            !! the mean of g
      real(wp), intent(out) :: c(n), s(n)      !! cosine and sine coefficients
      mean = 0.0_wp
      c = 0.0_wp
      s = 0.0_wp
   end subroutine zero_drive_harmonics

   !> Damping shift −ε²/4 of eq. (47).
   elemental real(wp) function damping_shift(epsilon)
      real(wp), intent(in) :: epsilon  !! damping ε of eq. (46)
      damping_shift = -0.25_wp*epsilon*epsilon
   end function damping_shift

   !> The coefficient q(τ) of the damping-shifted Hill equation (47) at a point.
   elemental real(wp) function hill_coefficient(model, point, tau) result(q)
      class(hill_model_t), intent(in) :: model  !! the model
      type(hill_point_t), intent(in) :: point   !! α, β, ε
      real(wp), intent(in) :: tau               !! dimensionless time, πτ = ωt
      q = model%coefficient(point%alpha, point%beta, tau) + damping_shift(point%epsilon)
   end function hill_coefficient

   !> `hill_coefficient` inside a piece of a window that ends at a jump of Q at `piece_end`:
   !> at τ ≥ piece_end (an integrator's stage at the end of its last step) Q's value from the
   !> left, at the last double below the jump (a model's Q at a jump is its value after it).
   elemental real(wp) function hill_coefficient_before(model, point, tau, piece_end) result(q)
      class(hill_model_t), intent(in) :: model  !! the model
      type(hill_point_t), intent(in) :: point   !! α, β, ε
      real(wp), intent(in) :: tau               !! dimensionless time
      real(wp), intent(in) :: piece_end         !! the jump that ends the piece (huge: none)
      q = hill_coefficient(model, point, min(tau, nearest(piece_end, -1.0_wp)))
   end function hill_coefficient_before

   !> The end of piece k of a window (its k-th jump, or the window's end after the last), and
   !> the jump there as `hill_coefficient_before` takes it (huge where the piece ends with
   !> the window: no jump to stop short of).
   pure subroutine window_piece_end(window, k, piece_end, jump)
      type(hill_window_t), intent(in) :: window  !! the window
      integer, intent(in) :: k                   !! the piece, 1 … n_breaks + 1
      real(wp), intent(out) :: piece_end         !! where the piece ends
      real(wp), intent(out) :: jump              !! the jump there (huge: none)
      if (k <= window%n_breaks) then
         piece_end = window%breaks(k)
         jump = piece_end
      else
         piece_end = window%start + window%length
         jump = huge(1.0_wp)
      end if
   end subroutine window_piece_end

   !> Exact mean of q over [tau_a, tau_b] at a point (damping shift included).
   pure real(wp) function segment_average(model, point, tau_a, tau_b) result(q)
      class(hill_model_t), intent(in) :: model  !! the model
      type(hill_point_t), intent(in) :: point   !! α, β, ε
      real(wp), intent(in) :: tau_a, tau_b      !! segment ends, tau_a < tau_b
      q = model%segment_mean(point%alpha, point%beta, tau_a, tau_b) + damping_shift(point%epsilon)
   end function segment_average

   !> q = c₀ + c₁ w(τ) at (α, β, ε), the damping shift in c₀; method auto shares w over the
   !> β of a chart row.
   elemental subroutine model_split(model, alpha, beta, epsilon, c0, c1)
      class(hill_model_t), intent(in) :: model      !! the model
      real(wp), intent(in) :: alpha, beta, epsilon  !! the point and its damping
      real(wp), intent(out) :: c0  !! constant part of q
      real(wp), intent(out) :: c1  !! factor of w
      call model%split(alpha, beta, c0, c1)
      c0 = c0 + damping_shift(epsilon)
   end subroutine model_split

   !> `model_split` at every β of a row: `split_row`, the damping shift added.
   pure subroutine model_split_row(model, alpha, betas, epsilon, c0s, c1s)
      class(hill_model_t), intent(in) :: model  !! the model
      real(wp), intent(in) :: alpha             !! α of the row
      real(wp), intent(in) :: betas(:)          !! its β
      real(wp), intent(in) :: epsilon           !! its damping
      real(wp), intent(out) :: c0s(:), c1s(:)   !! the split at each β
      call model%split_row(alpha, betas, c0s, c1s)
      c0s = c0s + damping_shift(epsilon)
   end subroutine model_split_row

   !> The line an output header gives the model, e.g. "model: mathieu, q(tau) = beta -
   !> alpha cos(pi tau), eq. (A1), alpha playing nu".
   pure function model_description(model) result(text)
      class(hill_model_t), intent(in) :: model  !! the model
      character(len=:), allocatable :: text
      text = "model: "//model%name()//", "//model%formula()
   end function model_description

   !> The equation and the model's period as output headers state them:
   !> "x'' + Q(tau) x = 0, period 2 in tau" (the period as an integer when it is one).
   function model_equation_text(model) result(text)
      class(hill_model_t), intent(in) :: model  !! the model
      character(len=:), allocatable :: text
      character(len=32) :: buffer
      real(wp) :: p
      p = model%period()
      if (p == aint(p) .and. abs(p) < 1.0e9_wp) then
         write (buffer, '(i0)') nint(p)
      else
         write (buffer, '(g0)') p
      end if
      text = "x'' + Q(tau) x = 0, period "//trim(buffer)//" in tau"
   end function model_equation_text

   !> The least and the largest value over the period of q = c₀ + c₁ w(τ) for the split
   !> (c₀, c₁) of a point and the range of w, widened by a few roundings of the values it
   !> is made of, so that the true range lies inside it.
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

   !> `coefficient_range` of a point of a model.
   elemental subroutine model_coefficient_range(model, point, q_min, q_max)
      class(hill_model_t), intent(in) :: model  !! the model
      type(hill_point_t), intent(in) :: point   !! α, β, ε
      real(wp), intent(out) :: q_min, q_max     !! bounds of q over the period
      real(wp) :: c0, c1, w_min, w_max, v_min, v_max
      call model_split(model, point%alpha, point%beta, point%epsilon, c0, c1)
      call model%shape_range(point%alpha, w_min, w_max)
      call coefficient_range(c0, c1, w_min, w_max, q_min, q_max)
      if (model%has_offset()) then
         call model%offset_range(point%alpha, v_min, v_max)
         call widen_by_offset(v_min, v_max, q_min, q_max)
      end if
   end subroutine model_coefficient_range

   !> Bounds of q widened by those of the offset v (`has_offset`): q + v lies in
   !> [q_min + v_min, q_max + v_max], and a few roundings more.
   elemental subroutine widen_by_offset(v_min, v_max, q_min, q_max)
      real(wp), intent(in) :: v_min, v_max       !! bounds of v
      real(wp), intent(inout) :: q_min, q_max    !! bounds of q, widened
      real(wp) :: slack
      slack = 16.0_wp*epsilon(1.0_wp)*max(abs(v_min), abs(v_max))
      q_min = q_min + v_min - slack
      q_max = q_max + v_max + slack
   end subroutine widen_by_offset

   !> The largest |v| of the model's offset over the period (`has_offset`; 0 without one): the
   !> phase bounds count it with |c₀|, the β-independent part of q.
   elemental real(wp) function offset_bound(model, alpha) result(bound)
      class(hill_model_t), intent(in) :: model  !! the model
      real(wp), intent(in) :: alpha             !! α
      real(wp) :: v_min, v_max
      bound = 0.0_wp
      if (.not. model%has_offset()) return
      call model%offset_range(alpha, v_min, v_max)
      bound = max(abs(v_min), abs(v_max))
   end function offset_bound

   !> err_invalid_parameter unless α lies in the model's domain, naming the domain and the value.
   pure subroutine check_alpha(model, alpha, error)
      class(hill_model_t), intent(in) :: model  !! the model
      real(wp), intent(in) :: alpha             !! α
      !> err_invalid_parameter naming the value and the limit; unallocated when valid
      type(error_t), allocatable, intent(out) :: error
      character(len=64) :: buf
      if (.not. model%alpha_valid(alpha)) then
         write (buf, '(es23.16)') alpha
         call set_error(error, err_invalid_parameter, model%name()//" model needs "//model%alpha_domain()// &
            ", got alpha = "//trim(adjustl(buf)))
      end if
   end subroutine check_alpha

   !> Validate a point: finite values, ε ≥ 0, magnitudes the methods can scale, α in the
   !> model's domain (elastic: 0 ≤ α < π², the mass never reaches the pivot).
   pure subroutine check_point(model, point, error)
      class(hill_model_t), intent(in) :: model  !! the model
      type(hill_point_t), intent(in) :: point   !! the parameters to check
      !> err_invalid_parameter naming the value and the limit; unallocated when valid
      type(error_t), allocatable, intent(out) :: error
      character(len=64) :: buf
      if (.not. (ieee_is_finite(point%alpha) .and. ieee_is_finite(point%beta) &
                 .and. ieee_is_finite(point%epsilon))) then
         call set_error(error, err_invalid_parameter, "alpha, beta and epsilon must be finite")
         return
      end if
      if (point%epsilon < 0.0_wp) then
         write (buf, '(es12.5)') point%epsilon
         call set_error(error, err_invalid_parameter, "epsilon must be >= 0, got "//trim(adjustl(buf)))
         return
      end if
      ! beyond these magnitudes Q, the grid spacings and the methods' scalings overflow
      if (max(abs(point%alpha), abs(point%beta)) > max_magnitude .or. point%epsilon > 100.0_wp) then
         call set_error(error, err_invalid_parameter, "|alpha|, |beta| must be <= 1e15 and epsilon <= 100")
         return
      end if
      call check_alpha(model, point%alpha, error)
   end subroutine check_point

   !> `check_point` for the points (α, β_j, ε) of a batch: α and ε checked once, each β for
   !> what depends on it (finite, |β| ≤ 1e15); the error of the first failing point.
   pure subroutine check_batch(model, alpha, epsilon, betas, error)
      class(hill_model_t), intent(in) :: model  !! the model
      real(wp), intent(in) :: alpha, epsilon    !! α and ε of the batch
      real(wp), intent(in) :: betas(:)          !! the β values
      !> err_invalid_parameter naming the value and the limit; unallocated when all are valid
      type(error_t), allocatable, intent(out) :: error
      integer :: j
      if (size(betas) == 0) return
      call check_point(model, hill_point_t(alpha, betas(1), epsilon), error)
      if (allocated(error)) return
      do j = 2, size(betas)
         ! NaN first, on its own: an ordered comparison of a NaN raises the invalid flag
         ! (a trap in debug builds), and Fortran's .and. need not stop at the first operand
         if (.not. ieee_is_finite(betas(j))) then
            call check_point(model, hill_point_t(alpha, betas(j), epsilon), error)
            return
         end if
         if (abs(betas(j)) > max_magnitude) then
            call check_point(model, hill_point_t(alpha, betas(j), epsilon), error)
            return
         end if
      end do
   end subroutine check_batch
end module hillstab_hill_model

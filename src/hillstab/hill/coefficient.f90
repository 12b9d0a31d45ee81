!> The periodic coefficient of the Hill equation x'' + Q(τ) x = 0 (period 2 in τ) as the
!> methods sample it: the piecewise-constant values of method segments (at each piece's
!> start, midpoint or exact mean: the sampling table, whose codes are the C API's
!> HILLSTAB_SAMPLING_* and the F77 ISAMP codes) and the phase bound of the round-off level.
!>
!> The models of Q themselves (`hill_model_t`, `hill_coefficient`, `check_point`, segment
!> averages, …) are in hillstab_hill_model, each model in its own module, registered in
!> hillstab_hill_models.
!>
!>```fortran
!> type(elastic_model_t) :: elastic
!> real(wp) :: q(4)
!> call segment_coefficients(elastic, hill_point_t(alpha=4.0_wp, beta=6.0_wp), 4, sampling_from_name("average"), q)
!>```
module hillstab_hill_coefficient
   use hillstab_core_kinds, only: wp
   use hillstab_core_text, only: name_position, alternatives_text
   use hillstab_hill_model, only: hill_model_t, hill_point_t, hill_coefficient, segment_average, model_split, &
      offset_bound
   use hillstab_hill_model_elastic, only: in_physical_domain, one_minus_alpha_over_pi2
   implicit none
   private
   public :: segment_coefficients
   public :: sampling_endpoint, sampling_midpoint, sampling_average, sampling_name, sampling_from_name, &
      sampling_names_text, sampling_count
   public :: in_physical_domain, one_minus_alpha_over_pi2
   public :: phase_bound, split_phases, coefficient_phase

   !> Piece value = Q at the start of the piece (N = 2 is the paper's eq. (28)).
   integer, parameter :: sampling_endpoint = 1
   !> Piece value = Q at the midpoint of the piece.
   integer, parameter :: sampling_midpoint = 2
   !> Piece value = exact average of Q over the piece (closed form).
   integer, parameter :: sampling_average = 3
   !> Names of the samplings, in the order of their codes.
   character(len=*), parameter :: sampling_names(3) = [character(len=8) :: "endpoint", "midpoint", "average"]
   !> Number of samplings; their codes are 1 … sampling_count.
   integer, parameter :: sampling_count = size(sampling_names)

contains

   !> Name of a sampling constant ("unknown" for any other code).
   pure function sampling_name(sampling) result(name)
      integer, intent(in) :: sampling  !! sampling_endpoint, sampling_midpoint or sampling_average
      character(len=:), allocatable :: name
      if (sampling >= 1 .and. sampling <= sampling_count) then
         name = trim(sampling_names(sampling))
      else
         name = "unknown"
      end if
   end function sampling_name

   !> Sampling constant from its name (any case, blanks trimmed); −1 when unknown.
   pure integer function sampling_from_name(name) result(sampling)
      character(len=*), intent(in) :: name  !! a sampling name
      sampling = name_position(name, sampling_names)
      if (sampling == 0) sampling = -1
   end function sampling_from_name

   !> The sampling names as a choice for messages: "endpoint, midpoint or average".
   pure function sampling_names_text() result(text)
      character(len=:), allocatable :: text
      text = alternatives_text(sampling_names)
   end function sampling_names_text

   !> An upper bound of the phase (where q > 0) or growth exponent (where q < 0) that the
   !> solutions accumulate over one period, Φ = ∫₀² √|q(τ)| dτ, from q = c₀ + c₁ w(τ)
   !> and √|c₀ + c₁ w| ≤ √|c₀| + √|c₁| √|w|: Φ ≤ 2 (√|c₀| + √|c₁| `shape_root_mean`).
   !> It sets the part of the round-off level of S that no integrator can remove: Q is
   !> computed from rounded constants (1 − α/π², α/π², β − π², π²), a systematic relative
   !> error of a few ε that moves the phase by about ε Φ (hillstab_integrate_refine `roundoff_level`).
   !> An offset v of the split (`has_offset`) counts with |c₀| (√|c₀ + v| ≤ √(|c₀| + max|v|)),
   !> and a period P other than 2 scales Φ by P/2.
   elemental real(wp) function phase_bound(model, point) result(phase)
      class(hill_model_t), intent(in) :: model  !! the model
      type(hill_point_t), intent(in) :: point   !! α, β, ε
      real(wp) :: c0, c1, phases(1)
      call model_split(model, point%alpha, point%beta, point%epsilon, c0, c1)
      phases = split_phases(model, point%alpha, [c0], [c1])
      phase = phases(1)
   end function phase_bound

   !> `phase_bound` of points sharing α from their splits (c₀ with the damping shift), the
   !> model's constants (period, offset, `shape_root_mean`) taken once for all of them.
   pure function split_phases(model, alpha, c0s, c1s) result(phases)
      class(hill_model_t), intent(in) :: model  !! the model
      real(wp), intent(in) :: alpha             !! α of the points
      real(wp), intent(in) :: c0s(:), c1s(:)    !! their splits q = c₀ + c₁ w (+ v)
      real(wp) :: phases(size(c0s))
      phases = 0.5_wp*model%period()*coefficient_phase(abs(c0s) + offset_bound(model, alpha), c1s, &
                                                       model%shape_root_mean(alpha))
   end function split_phases

   !> `phase_bound` from q = c₀ + c₁ w and ∫₀¹ √|w| dτ: 2 (√|c₀| + √|c₁| shape_root).
   elemental real(wp) function coefficient_phase(c0, c1, shape_root) result(phase)
      real(wp), intent(in) :: c0          !! constant part of q
      real(wp), intent(in) :: c1          !! factor of the shape function w
      real(wp), intent(in) :: shape_root  !! ∫₀¹ √|w| dτ (`shape_root_mean`)
      phase = 2.0_wp*(sqrt(abs(c0)) + sqrt(abs(c1))*shape_root)
   end function coefficient_phase

   !> Values of the piecewise-constant approximation of q with `n` equal pieces
   !> over one period [0, P] (P = 2 unless the model's period differs): at each piece's
   !> start, midpoint, or its exact mean.
   pure subroutine segment_coefficients(model, point, n, sampling, q)
      class(hill_model_t), intent(in) :: model  !! the model
      type(hill_point_t), intent(in) :: point   !! α, β, ε
      integer, intent(in) :: n          !! number of pieces, n ≥ 1
      integer, intent(in) :: sampling   !! sampling_endpoint, sampling_midpoint or sampling_average
      real(wp), intent(out) :: q(n)     !! piece values, in order of τ
      real(wp) :: h
      integer :: i
      h = model%period()/n
      do i = 1, n
         select case (sampling)
         case (sampling_midpoint)
            q(i) = hill_coefficient(model, point, (i - 0.5_wp)*h)
         case (sampling_average)
            q(i) = segment_average(model, point, (i - 1)*h, i*h)
         case default
            q(i) = hill_coefficient(model, point, (i - 1)*h)
         end select
      end do
   end subroutine segment_coefficients
end module hillstab_hill_coefficient

!> A Hill equation of measured drive: f given by N equally spaced samples of one period,
!>
!>     Q(τ) = β + α f(τ),   f the trigonometric interpolant of the samples f_j = f(jP/N),
!>
!> j = 0 … N − 1, their mean removed (β is the mean stiffness). The interpolant is the
!> unique trigonometric polynomial of degree ⌊N/2⌋ through the samples (the Nyquist term
!> halved for even N), found by the discrete Fourier transform: it passes through every
!> sample (to rounding), and for samples of a smooth periodic function its error between
!> them falls faster than any power of 1/N (of a function analytic in a strip, like e^{-N d}).
!> It is then a Fourier model (hillstab_hill_model_fourier) with those harmonics: every
!> method, Hill's method included, works on it unchanged. Variables: `samples` (a list,
!> at least 4 and at most `max_samples`), `file` (the same read from a file: one sample a
!> row, or τ and the sample), `period`.
!>
!>```fortran
!> type(sampled_model_t) :: measured
!> type(error_t), allocatable :: error
!> call measured%set_values("samples", [1.0_wp, 0.0_wp, -1.0_wp, 0.0_wp], error)   ! f = cos πτ
!>```
module hillstab_hill_model_sampled
   use hillstab_core_kinds, only: wp, pi
   use hillstab_core_error, only: error_t, set_error, err_invalid_parameter
   use hillstab_core_text, only: integer_text
   use hillstab_hill_model, only: model_variable_t, model_variable_real, model_variable_list, model_variable_file
   use hillstab_hill_model_fourier, only: fourier_model_t
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   implicit none
   private
   public :: sampled_model_t, max_samples, min_samples

   !> Most samples of one period (the interpolant then has 2048 harmonics).
   integer, parameter :: max_samples = 4096
   !> Fewest samples (the interpolant's degree is 2).
   integer, parameter :: min_samples = 4

   !> Q = β + α f, f the trigonometric interpolant of samples over one period.
   type, extends(fourier_model_t) :: sampled_model_t
      real(wp), allocatable :: samples(:)  !! the samples as given (the mean not yet removed)
   contains
      procedure :: name => sampled_name
      procedure :: formula => sampled_formula
      procedure :: summary => sampled_summary
      procedure :: variables => sampled_variables
      procedure :: set_values => sampled_set_values
      procedure :: check_values => sampled_check_values
   end type sampled_model_t

contains

   !> "sampled".
   pure function sampled_name(self) result(text)
      class(sampled_model_t), intent(in) :: self  !! the model
      character(len=:), allocatable :: text
      text = "sampled"
   end function sampled_name

   !> The coefficient as output headers state it.
   pure function sampled_formula(self) result(text)
      class(sampled_model_t), intent(in) :: self  !! the model
      character(len=:), allocatable :: text
      integer :: n
      n = 0
      if (allocated(self%samples)) n = size(self%samples)
      text = "Q(tau) = beta + alpha f(tau), f the trigonometric interpolant of "//integer_text(n)// &
             " equally spaced samples over P = "//integer_text(nint(self%p))//", their mean removed (&sampled)"
   end function sampled_formula

   !> The coefficient in a few words (a template's comment).
   pure function sampled_summary(self) result(text)
      class(sampled_model_t), intent(in) :: self  !! the model
      character(len=:), allocatable :: text
      text = "Q = beta + alpha f, f interpolating samples of one period given in &sampled (samples or file)"
   end function sampled_summary

   !> `samples`, `file` and `period`.
   pure function sampled_variables(self) result(variables)
      class(sampled_model_t), intent(in) :: self  !! the model
      type(model_variable_t), allocatable :: variables(:)
      allocate (variables(3))
      variables(1) = model_variable_t("samples", model_variable_list, max_samples, "", &
         "f(0), f(P/N), ..., f((N-1)P/N): equally spaced samples of one period of the drive (4 or more)")
      variables(2) = model_variable_t("file", model_variable_file, max_samples, "", &
         "a file of the samples instead: one a row, or tau and the sample (tau equally spaced from 0); # comments")
      variables(3) = model_variable_t("period", model_variable_real, 1, "2.0", &
         "P: the period of Q in tau, a multiple of 2")
   end function sampled_variables

   !> Set `samples` (or `file`, the same numbers) or `period`, and the harmonics from them.
   pure subroutine sampled_set_values(self, name, values, error)
      class(sampled_model_t), intent(inout) :: self  !! the model
      character(len=*), intent(in) :: name           !! the variable
      real(wp), intent(in) :: values(:)              !! its numbers
      !> err_invalid_parameter naming the variable and what is wrong; unallocated when set
      type(error_t), allocatable, intent(out) :: error
      select case (trim(name))
      case ("samples", "file")
         if (.not. all(ieee_is_finite(values))) then
            call set_error(error, err_invalid_parameter, trim(name)//": the samples must be finite numbers")
         else if (size(values) < min_samples .or. size(values) > max_samples) then
            call set_error(error, err_invalid_parameter, trim(name)//": "//integer_text(min_samples)//" to "// &
               integer_text(max_samples)//" samples of one period, got "//integer_text(size(values)))
         else
            self%samples = values
            call interpolate(self)
         end if
      case ("period")
         call self%fourier_model_t%set_values(name, values, error)
      case default
         call set_error(error, err_invalid_parameter, "the sampled model has no variable '"//trim(name)// &
            "' (it has samples, file, period)")
      end select
   end subroutine sampled_set_values

   !> The samples are given, and vary.
   pure subroutine sampled_check_values(self, error)
      class(sampled_model_t), intent(in) :: self  !! the model
      !> err_invalid_parameter naming the variables; unallocated when complete
      type(error_t), allocatable, intent(out) :: error
      if (.not. allocated(self%samples)) then
         call set_error(error, err_invalid_parameter, "samples, file: the sampled model needs the samples of one "// &
            "period (samples = ... or file = '...')")
      else if (all(self%samples == self%samples(1))) then
         call set_error(error, err_invalid_parameter, "samples, file: the samples are all equal (no drive)")
      end if
   end subroutine sampled_check_values

   !> The harmonics of the interpolant by the discrete Fourier transform (O(N²), once):
   !> c_n = (2/N) Σ f_j cos(2πnj/N), s_n = (2/N) Σ f_j sin(2πnj/N), n < N/2, and for even N
   !> the Nyquist term c_{N/2} = (1/N) Σ f_j (−1)^j; the mean (1/N) Σ f_j left out.
   pure subroutine interpolate(self)
      class(sampled_model_t), intent(inout) :: self  !! the model, its samples set
      real(wp), allocatable :: c(:), s(:)
      integer :: n_samples, n_top, n, j
      real(wp) :: angle
      n_samples = size(self%samples)
      n_top = n_samples/2
      allocate (c(n_top), s(n_top))
      do n = 1, n_top
         c(n) = 0.0_wp
         s(n) = 0.0_wp
         do j = 0, n_samples - 1
            ! the angle reduced exactly: n j mod N before the division
            angle = 2.0_wp*pi*real(modulo(n*j, n_samples), wp)/n_samples
            c(n) = c(n) + self%samples(j + 1)*cos(angle)
            s(n) = s(n) + self%samples(j + 1)*sin(angle)
         end do
         if (2*n == n_samples) then
            c(n) = c(n)/n_samples
            s(n) = 0.0_wp
         else
            c(n) = 2.0_wp*c(n)/n_samples
            s(n) = 2.0_wp*s(n)/n_samples
         end if
      end do
      call self%set_drive(c, s)
   end subroutine interpolate
end module hillstab_hill_model_sampled

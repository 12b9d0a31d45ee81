!> A Hill equation of the user's own, given by the Fourier series of its drive:
!>
!>     Q(τ) = β + α f(τ),   f(τ) = Σₙ (cₙ cos(2πnτ/P) + sₙ sin(2πnτ/P)),   n = 1 … N,
!>
!> β the mean stiffness and α the drive strength, the axes of Strutt's diagram; the period
!> P is 2 (one radial period of the pendulum: cos nπτ, sin nπτ) unless a multiple of 2 is
!> given (a commensurate modulation, ω'/ω = 2/P). The model's variables (`variables`, the
!> scene group `&fourier`, the C API's `hillstab_model_set`) are the lists `cos` and `sin`
!> (up to `max_fourier_harmonics` terms each) and `period`.
!>
!> Q = c₀ + c₁ f with c₀ = β, c₁ = α: method auto shares f over the β of a chart row.
!> With cosines only Q is even about τ = 0 and the methods integrate half a period; with
!> sine terms they integrate the whole period (`window`). f's range over the period, which
!> the verdicts' shortcut (the range of Q) needs as a bound, is f's extremes on a grid of
!> 64N points per period widened by Bernstein's inequality |f'| ≤ (2πN/P) Σ(|cₙ| + |sₙ|).
!> The harmonics are Hill's method's matrix (hillstab_curves_hill_fourier).
!>
!>```fortran
!> type(fourier_model_t) :: pivot
!> type(error_t), allocatable :: error
!> call pivot%set_values("cos", [1.0_wp, 0.5_wp], error)   ! f = cos πτ + 0.5 cos 2πτ
!> print *, pivot%coefficient(2.0_wp, 3.0_wp, 0.0_wp)      ! 3 + 2·1.5 = 6
!>```
module hillstab_hill_model_fourier
   use hillstab_core_kinds, only: wp, pi
   use hillstab_core_error, only: error_t, set_error, err_invalid_parameter
   use hillstab_core_text, only: integer_text
   use hillstab_hill_model, only: hill_model_t, hill_window_t, model_variable_t, model_variable_real, &
      model_variable_list
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   implicit none
   private
   public :: fourier_model_t, max_fourier_harmonics, max_fourier_period

   !> Most harmonics of `cos` and of `sin`.
   integer, parameter :: max_fourier_harmonics = 256
   !> Longest period P (a multiple of 2).
   real(wp), parameter :: max_fourier_period = 128.0_wp

   !> Q = β + α f with f a trigonometric polynomial of period P (hillstab_hill_model).
   type, extends(hill_model_t) :: fourier_model_t
      real(wp), allocatable :: c(:)  !! cosine coefficients c₁ … c_N
      real(wp), allocatable :: s(:)  !! sine coefficients s₁ … s_N (same length)
      real(wp) :: p = 2.0_wp         !! the period P in τ
      real(wp) :: f_min = 0.0_wp     !! a lower bound of f over the period
      real(wp) :: f_max = 0.0_wp     !! an upper bound of f over the period
      !> Σ n² (|cₙ| + |sₙ|): the curvature bound max|f''| ≤ (2π/P)² times it
      real(wp) :: curvature = 0.0_wp
      !> the highest n whose n² (|cₙ| + |sₙ|) reaches 1e-3 of `curvature` (0 without a drive)
      integer :: top_harmonic = 0
   contains
      procedure :: name => fourier_name
      procedure :: formula => fourier_formula
      procedure :: summary => fourier_summary
      procedure :: coefficient => fourier_coefficient
      procedure :: segment_mean => fourier_segment_mean
      procedure :: split => fourier_split
      procedure :: shapes => fourier_shapes
      procedure :: shape_range => fourier_shape_range
      procedure :: period => fourier_period
      procedure :: window => fourier_window
      procedure :: auto_difficulty => fourier_auto_difficulty
      procedure :: auto_amplitude => fourier_auto_amplitude
      procedure :: auto_min_steps => fourier_auto_min_steps
      procedure :: drive_harmonic_count => fourier_harmonic_count
      procedure :: drive_harmonics => fourier_harmonics
      procedure :: variables => fourier_variables
      procedure :: set_values => fourier_set_values
      procedure :: check_values => fourier_check_values
      procedure :: set_drive
   end type fourier_model_t

contains

   !> "fourier".
   pure function fourier_name(self) result(text)
      class(fourier_model_t), intent(in) :: self  !! the model
      character(len=:), allocatable :: text
      text = "fourier"
   end function fourier_name

   !> The coefficient as output headers state it, with its number of harmonics and period.
   pure function fourier_formula(self) result(text)
      class(fourier_model_t), intent(in) :: self  !! the model
      character(len=:), allocatable :: text
      text = "Q(tau) = beta + alpha f(tau), f = sum_n (c_n cos(2 pi n tau/P) + s_n sin(2 pi n tau/P)), "// &
             integer_text(harmonic_count(self))//" harmonics, P = "//integer_text(nint(self%p))//" (&fourier)"
   end function fourier_formula

   !> The coefficient in a few words (a template's comment).
   pure function fourier_summary(self) result(text)
      class(fourier_model_t), intent(in) :: self  !! the model
      character(len=:), allocatable :: text
      text = "Q = beta + alpha f, f a Fourier series given in &fourier (cos, sin, period)"
   end function fourier_summary

   !> N, the number of harmonics held.
   pure integer function harmonic_count(self) result(n)
      class(fourier_model_t), intent(in) :: self  !! the model
      n = 0
      if (allocated(self%c)) n = size(self%c)
   end function harmonic_count

   !> f at one τ: the harmonics by the rotation e^{inθ} = e^{iθ} e^{i(n−1)θ} (one cos and sin).
   pure real(wp) function drive(self, tau) result(f)
      class(fourier_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: tau                 !! τ
      real(wp) :: theta, c1, s1, cn, sn, x
      integer :: n
      f = 0.0_wp
      if (harmonic_count(self) == 0) return
      ! the angle reduced to one period first: τ may be far from 0
      theta = 2.0_wp*pi*modulo(tau, self%p)/self%p
      c1 = cos(theta)
      s1 = sin(theta)
      cn = c1
      sn = s1
      do n = 1, size(self%c)
         f = f + self%c(n)*cn + self%s(n)*sn
         x = cn*c1 - sn*s1
         sn = sn*c1 + cn*s1
         cn = x
      end do
   end function drive

   !> ∫₀^τ f: Σ (cₙ sin nθ − sₙ (cos nθ − 1))/(nω), θ = ωτ, ω = 2π/P (periodic: f has no mean).
   pure real(wp) function drive_integral(self, tau) result(f)
      class(fourier_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: tau                 !! τ
      real(wp) :: omega, theta, c1, s1, cn, sn, x
      integer :: n
      f = 0.0_wp
      if (harmonic_count(self) == 0) return
      omega = 2.0_wp*pi/self%p
      theta = omega*modulo(tau, self%p)
      c1 = cos(theta)
      s1 = sin(theta)
      cn = c1
      sn = s1
      do n = 1, size(self%c)
         f = f + (self%c(n)*sn - self%s(n)*(cn - 1.0_wp))/(n*omega)
         x = cn*c1 - sn*s1
         sn = sn*c1 + cn*s1
         cn = x
      end do
   end function drive_integral

   !> Q(τ) = β + α f(τ).
   elemental real(wp) function fourier_coefficient(self, alpha, beta, tau) result(q)
      class(fourier_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha, beta         !! the point
      real(wp), intent(in) :: tau                 !! dimensionless time
      q = beta + alpha*drive(self, tau)
   end function fourier_coefficient

   !> Exact mean of Q over [τ_a, τ_b]: β + α (F(τ_b) − F(τ_a))/(τ_b − τ_a), F = ∫f.
   pure real(wp) function fourier_segment_mean(self, alpha, beta, tau_a, tau_b) result(q)
      class(fourier_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha, beta         !! the point
      real(wp), intent(in) :: tau_a, tau_b        !! segment ends, tau_a < tau_b
      q = beta + alpha*(drive_integral(self, tau_b) - drive_integral(self, tau_a))/(tau_b - tau_a)
   end function fourier_segment_mean

   !> Q = β + α f: c₀ = β, c₁ = α.
   elemental subroutine fourier_split(self, alpha, beta, c0, c1)
      class(fourier_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha, beta         !! the point
      real(wp), intent(out) :: c0                 !! β
      real(wp), intent(out) :: c1                 !! α
      c0 = beta
      c1 = alpha
   end subroutine fourier_split

   !> w = f at the times `tau`.
   pure subroutine fourier_shapes(self, alpha, tau, w)
      class(fourier_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha               !! α
      real(wp), intent(in) :: tau(:)              !! the times
      real(wp), intent(out) :: w(:)               !! f there
      integer :: i
      do i = 1, size(tau)
         w(i) = drive(self, tau(i))
      end do
   end subroutine fourier_shapes

   !> Bounds of f over the period (made when the coefficients are set).
   elemental subroutine fourier_shape_range(self, alpha, w_min, w_max)
      class(fourier_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha               !! α
      real(wp), intent(out) :: w_min, w_max       !! the bounds
      w_min = self%f_min
      w_max = self%f_max
   end subroutine fourier_shape_range

   !> The period P.
   pure real(wp) function fourier_period(self) result(period)
      class(fourier_model_t), intent(in) :: self  !! the model
      period = self%p
   end function fourier_period

   !> Half a period from 0 when f has cosines only (even), else the whole period.
   pure function fourier_window(self, alpha) result(window)
      class(fourier_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha               !! α
      type(hill_window_t) :: window
      logical :: even
      even = .true.
      if (allocated(self%s)) even = all(self%s == 0.0_wp)
      if (even) then
         window = hill_window_t(start=0.0_wp, length=0.5_wp*self%p, half=.true.)
      else
         window = hill_window_t(start=0.0_wp, length=self%p, half=.false.)
      end if
   end function fourier_window

   !> Method auto's calibration variable: half the Mathieu model's, with the drive's largest
   !> excursion |α| max|f| in the place of ν (a Fourier drive has no dip for the elastic
   !> table to follow; with none at all, auto at 1e-6 let 1.5× the tolerance through at α = 8,
   !> β = −500 for the test drive of three harmonics and a sine term).
   elemental real(wp) function fourier_auto_difficulty(self, alpha) result(x)
      class(fourier_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha               !! α
      x = -0.5_wp*log(1.0_wp - min(abs(alpha)*max(abs(self%f_min), abs(self%f_max)), 9.0_wp)/(pi*pi))
   end function fourier_auto_difficulty

   !> The amplitude method auto's step count grows with: |c₁| (2/P)² Σ n² (|cₙ| + |sₙ|) + 0.1 |c₀|,
   !> the drive's curvature bound (max|f''| ≤ that sum times π²) and, for large |β|, the
   !> oscillation itself; with the floor `fourier_auto_min_steps` (the first mesh resolves the
   !> highest harmonic) in place of the former weight max|f| N², which cost a 300 × 300 chart
   !> of three harmonics 2.2× the elastic chart's instructions (now 1.36×).
   elemental real(wp) function fourier_auto_amplitude(self, c0, c1) result(amplitude)
      class(fourier_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: c0, c1              !! the split of q
      amplitude = abs(c1)*self%curvature*(2.0_wp/self%p)**2 + 0.1_wp*abs(c0)
   end function fourier_auto_amplitude

   !> The fewest steps per unit of τ of method auto's first mesh: 8 per wavelength of the
   !> highest harmonic that matters (4 on the coarse mesh of its Richardson check), 16 N/P,
   !> N the highest n whose n² (|cₙ| + |sₙ|) reaches 1e-3 of the sum over all n (the
   !> curvature bound of `fourier_auto_amplitude`; an interpolant's tiny top harmonics do not
   !> count). With 4 per wavelength a Richardson pair of the two-harmonic pivot
   !> (own_pivot_chart.nml, α = 0.50, β = 4.05) had errors of S_N and S_{N/2} so alike
   !> that their difference was a twelfth of the error: 3.9e-10 at tolerance 1e-10. And at
   !> least 16 (8 on the coarse mesh) whatever the harmonics: with 8 a pair of f = −cos πτ at
   !> α = 1.12, β = −0.017, ε = 0.0038 (the Kapitza pendulum at 167 rad/s) differed by a
   !> twentieth of its error (1.9e-10 at tolerance 1e-10, status 0).
   elemental integer function fourier_auto_min_steps(self) result(steps)
      class(fourier_model_t), intent(in) :: self  !! the model
      steps = max(16, 2*ceiling(8.0_wp*real(self%top_harmonic, wp)/self%p))
   end function fourier_auto_min_steps

   !> Q = β + g, g = α f: N harmonics.
   pure integer function fourier_harmonic_count(self) result(count)
      class(fourier_model_t), intent(in) :: self  !! the model
      count = harmonic_count(self)
   end function fourier_harmonic_count

   !> g = α f: no mean, α cₙ and α sₙ (0 beyond N).
   pure subroutine fourier_harmonics(self, alpha, n, mean, c, s)
      class(fourier_model_t), intent(in) :: self  !! the model
      real(wp), intent(in) :: alpha               !! α
      integer, intent(in) :: n                    !! number of harmonics wanted
      real(wp), intent(out) :: mean               !! 0
      real(wp), intent(out) :: c(n), s(n)         !! the coefficients of g
      integer :: m
      mean = 0.0_wp
      c = 0.0_wp
      s = 0.0_wp
      m = min(n, harmonic_count(self))
      if (m > 0) then
         c(1:m) = alpha*self%c(1:m)
         s(1:m) = alpha*self%s(1:m)
      end if
   end subroutine fourier_harmonics

   !> `cos`, `sin` (lists) and `period`.
   pure function fourier_variables(self) result(variables)
      class(fourier_model_t), intent(in) :: self  !! the model
      type(model_variable_t), allocatable :: variables(:)
      allocate (variables(3))
      variables(1) = model_variable_t("cos", model_variable_list, max_fourier_harmonics, "", &
         "c_1, c_2, ...: the cosine coefficients of f, cos(2 pi n tau/P)")
      variables(2) = model_variable_t("sin", model_variable_list, max_fourier_harmonics, "", &
         "s_1, s_2, ...: the sine coefficients of f, sin(2 pi n tau/P) (sine terms: Q is not even)")
      variables(3) = model_variable_t("period", model_variable_real, 1, "2.0", &
         "P: the period of Q in tau, a multiple of 2 (2: the radial period; 4: a modulation at half the frequency)")
   end function fourier_variables

   !> Set `cos`, `sin` or `period`: finite numbers, at most `max_fourier_harmonics`
   !> coefficients, P a multiple of 2 up to `max_fourier_period`.
   pure subroutine fourier_set_values(self, name, values, error)
      class(fourier_model_t), intent(inout) :: self  !! the model
      character(len=*), intent(in) :: name           !! the variable
      real(wp), intent(in) :: values(:)              !! its numbers
      !> err_invalid_parameter naming the variable and what is wrong; unallocated when set
      type(error_t), allocatable, intent(out) :: error
      real(wp), allocatable :: c(:), s(:)
      if (.not. all(ieee_is_finite(values))) then
         call set_error(error, err_invalid_parameter, trim(name)//": the values must be finite numbers")
         return
      end if
      select case (trim(name))
      case ("cos", "sin")
         if (size(values) > max_fourier_harmonics) then
            call set_error(error, err_invalid_parameter, trim(name)//": at most "// &
               integer_text(max_fourier_harmonics)//" coefficients, got "//integer_text(size(values)))
            return
         end if
         c = [real(wp) ::]
         s = [real(wp) ::]
         if (allocated(self%c)) then
            c = self%c
            s = self%s
         end if
         if (trim(name) == "cos") then
            call self%set_drive(values, s)
         else
            call self%set_drive(c, values)
         end if
      case ("period")
         if (size(values) /= 1) then
            call set_error(error, err_invalid_parameter, "period: one number, got "//integer_text(size(values)))
         else if (.not. (values(1) >= 2.0_wp .and. values(1) <= max_fourier_period .and. &
                         modulo(values(1), 2.0_wp) == 0.0_wp)) then
            call set_error(error, err_invalid_parameter, "period: must be a multiple of 2 from 2 to "// &
               integer_text(nint(max_fourier_period)))
         else
            self%p = values(1)
            if (allocated(self%c)) then
               c = self%c
               s = self%s
               call self%set_drive(c, s)
            end if
         end if
      case default
         call set_error(error, err_invalid_parameter, "the fourier model has no variable '"//trim(name)// &
            "' (it has cos, sin, period)")
      end select
   end subroutine fourier_set_values

   !> A drive needs at least one nonzero coefficient.
   pure subroutine fourier_check_values(self, error)
      class(fourier_model_t), intent(in) :: self  !! the model
      !> err_invalid_parameter naming the variables; unallocated when complete
      type(error_t), allocatable, intent(out) :: error
      logical :: any_term
      any_term = .false.
      if (allocated(self%c)) any_term = any(self%c /= 0.0_wp) .or. any(self%s /= 0.0_wp)
      if (.not. any_term) call set_error(error, err_invalid_parameter, "cos, sin: the fourier model needs at "// &
         "least one nonzero coefficient (f = 0 would be Q = beta, no drive)")
   end subroutine fourier_check_values

   !> The coefficients (the shorter list padded with zeros, trailing zero harmonics dropped)
   !> and the bounds of f over the period: its extremes at 64N + 64 points, widened by the
   !> largest change of f between neighbours, (2πN/P)(Σ|cₙ| + |sₙ|) δ/2 (Bernstein).
   pure subroutine set_drive(self, c, s)
      class(fourier_model_t), intent(inout) :: self  !! the model
      real(wp), intent(in) :: c(:), s(:)             !! cosine and sine coefficients
      integer :: n, m, k
      real(wp) :: delta, f, slack
      real(wp), allocatable :: cc(:), ss(:)
      n = max(size(c), size(s))
      allocate (cc(n), ss(n))
      cc = 0.0_wp
      ss = 0.0_wp
      cc(1:size(c)) = c
      ss(1:size(s)) = s
      do while (n > 0)
         if (cc(n) /= 0.0_wp .or. ss(n) /= 0.0_wp) exit
         n = n - 1
      end do
      ! allocated anew, not by assignment: gfortran's reallocation of a shorter array than the
      ! one held overflowed an integer under -fsanitize=undefined
      if (allocated(self%c)) deallocate (self%c)
      if (allocated(self%s)) deallocate (self%s)
      allocate (self%c(n), self%s(n))
      self%c(:) = cc(1:n)
      self%s(:) = ss(1:n)
      self%f_min = 0.0_wp
      self%f_max = 0.0_wp
      call curvature_of_drive(self)
      if (n == 0) return
      m = 64*n + 64
      delta = self%p/m
      self%f_min = huge(1.0_wp)
      self%f_max = -huge(1.0_wp)
      do k = 0, m - 1
         f = drive(self, k*delta)
         self%f_min = min(self%f_min, f)
         self%f_max = max(self%f_max, f)
      end do
      slack = (2.0_wp*pi*n/self%p)*(sum(abs(self%c)) + sum(abs(self%s)))*0.5_wp*delta
      ! and a few roundings of the sum
      slack = slack + 8.0_wp*n*epsilon(1.0_wp)*(sum(abs(self%c)) + sum(abs(self%s)))
      self%f_min = self%f_min - slack
      self%f_max = self%f_max + slack
   end subroutine set_drive

   !> `curvature` and `top_harmonic` of the drive's coefficients (method auto's first mesh).
   pure subroutine curvature_of_drive(self)
      class(fourier_model_t), intent(inout) :: self
      real(wp) :: weights(size(self%c))
      integer :: n
      do n = 1, size(weights)
         weights(n) = real(n, wp)**2*(abs(self%c(n)) + abs(self%s(n)))
      end do
      self%curvature = sum(weights)
      self%top_harmonic = 0
      do n = size(weights), 1, -1
         if (weights(n) >= 1.0e-3_wp*self%curvature) then
            self%top_harmonic = n
            exit
         end if
      end do
   end subroutine curvature_of_drive
end module hillstab_hill_model_fourier

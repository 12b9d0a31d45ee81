!> What a problem written in its user's terms shares, one equation (`equation_model_t`,
!> hillstab_hill_model_equation) or n of them (`equations_system_t`,
!> hillstab_hill_system_equation): named parameters, two of them the chart's axes, and a
!> drive of period T = 2π/Ω given as the frequency Ω or the period T, an expression of the
!> parameters, so that the period is the one *at a point*.
!>
!> `drive_t` is the drive: its texts, its expression, Ω and T from its value at a point
!> (`omega_of`, `period_of`) and what its header says (`drive_summary`). `find_axes`
!> finds the two axes among the parameters and refuses a parameter computed from an axis;
!> `names_text`, `values_text` and `message_number` write parameters and numbers into
!> messages alike for both.
!>
!>```fortran
!> type(drive_t) :: drive
!> character(len=:), allocatable :: problem
!> drive%frequency_text = "w"
!> problem = ""
!> call parse_drive(drive, [character(len=8) :: "w", "A"], problem)
!> print *, drive%period_of(drive%expression%value([314.16_wp, 0.005_wp]))   ! 2 pi/314.16
!>```
module hillstab_hill_named_parameters
   use hillstab_core_kinds, only: wp, pi
   use hillstab_core_error, only: error_t
   use hillstab_core_text, only: format_es
   use hillstab_core_expression, only: expression_t, parse_expression
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   implicit none
   private
   public :: drive_t, parse_drive, find_axes, names_text, values_text, message_number, parameter_position

   !> The drive of a problem in its user's terms: Ω (`frequency`) or T (`period`), one of
   !> the two, an expression of the parameters.
   type :: drive_t
      character(len=:), allocatable :: frequency_text   !! `frequency` ("" when `period` is given)
      character(len=:), allocatable :: period_text      !! `period` ("" when `frequency` is given)
      type(expression_t) :: expression                  !! Ω, or T with `from_period`
      logical :: from_period = .false.                  !! `expression` is the period T
   contains
      !> "frequency" or "period": the variable the drive was given as
      procedure :: name => drive_name
      !> Ω from the drive's value at a point (the frequency, or 2π/T)
      procedure :: omega_of => drive_omega_of
      !> T from the drive's value at a point (the period, or 2π/Ω)
      procedure :: period_of => drive_period_of
      !> dτ/dt = Ω/π at a point (0 outside the domain)
      procedure :: tau_rate => drive_tau_rate
      !> the header's text of the drive: ", Omega = ..." or ", period T = ..., Omega = 2 pi/T"
      procedure :: summary => drive_summary
      !> the drive uses this parameter
      procedure :: uses => drive_uses
   end type drive_t

contains

   !> "frequency" or "period".
   pure function drive_name(self) result(text)
      class(drive_t), intent(in) :: self  !! the drive
      character(len=:), allocatable :: text
      text = trim(merge("period   ", "frequency", self%from_period))
   end function drive_name

   !> Ω = the frequency, or 2π/T, from the drive's value (`expression` at a point's
   !> parameters, > 0: the caller checks it first).
   elemental real(wp) function drive_omega_of(self, drive) result(omega)
      class(drive_t), intent(in) :: self  !! the drive (parsed)
      real(wp), intent(in) :: drive       !! its value at the point
      omega = drive
      if (self%from_period) omega = 2.0_wp*pi/drive
   end function drive_omega_of

   !> T = the period, or 2π/Ω, from the drive's value (> 0: the caller checks it first).
   elemental real(wp) function drive_period_of(self, drive) result(period)
      class(drive_t), intent(in) :: self  !! the drive (parsed)
      real(wp), intent(in) :: drive       !! its value at the point
      period = drive
      if (.not. self%from_period) period = 2.0_wp*pi/drive
   end function drive_period_of

   !> dτ/dt = Ω/π at the point (α, β) (τ = Ωt/π): 2 over the period in the problem's own
   !> time; 0 where the drive is not finite and positive there (outside the domain). The
   !> parameters are `values` with the axes set; a problem fixed at its point's β (`pinned`)
   !> keeps its β.
   pure real(wp) function drive_tau_rate(self, values, i_alpha, i_beta, alpha, beta, pinned) result(rate)
      class(drive_t), intent(in) :: self         !! the drive (parsed)
      real(wp), intent(in) :: values(:)          !! the problem's parameters
      integer, intent(in) :: i_alpha, i_beta     !! the axes' positions among them
      real(wp), intent(in) :: alpha, beta        !! the point
      logical, intent(in) :: pinned              !! β is fixed in `values`
      real(wp) :: p(size(values)), drive, omega
      rate = 0.0_wp
      p = values
      p(i_alpha) = alpha
      if (.not. pinned) p(i_beta) = beta
      drive = self%expression%value(p)
      if (.not. (ieee_is_finite(drive) .and. drive > 0.0_wp)) return
      omega = self%omega_of(drive)
      if (ieee_is_finite(omega) .and. omega > 0.0_wp) rate = omega/pi
   end function drive_tau_rate

   !> ", Omega = <frequency>" or ", period T = <period>, Omega = 2 pi/T".
   pure function drive_summary(self) result(text)
      class(drive_t), intent(in) :: self  !! the drive
      character(len=:), allocatable :: text
      if (self%from_period) then
         text = ", period T = "//self%period_text//", Omega = 2 pi/T"
      else
         text = ", Omega = "//self%frequency_text
      end if
   end function drive_summary

   !> Whether the drive's expression uses the parameter `name`.
   pure logical function drive_uses(self, name)
      class(drive_t), intent(in) :: self      !! the drive (parsed)
      character(len=*), intent(in) :: name    !! a parameter
      drive_uses = self%expression%uses(name)
   end function drive_uses

   !> Parse the drive over the parameters: exactly one of frequency and period, an
   !> expression of the parameters; `problem` names what is wrong (unchanged when nothing is).
   pure subroutine parse_drive(drive, names, problem)
      type(drive_t), intent(inout) :: drive  !! its texts set ("" when not given)
      character(len=*), intent(in) :: names(:)  !! the parameters
      character(len=:), allocatable, intent(inout) :: problem  !! set when the drive is wrong
      type(error_t), allocatable :: error
      if (.not. allocated(drive%frequency_text)) drive%frequency_text = ""
      if (.not. allocated(drive%period_text)) drive%period_text = ""
      if (len(drive%frequency_text) > 0 .and. len(drive%period_text) > 0) then
         problem = "frequency, period: give one of the two (the period is 2 pi/frequency)"
         return
      end if
      if (len(drive%frequency_text) == 0 .and. len(drive%period_text) == 0) then
         problem = "frequency: the drive's angular frequency Omega is required (or the period T = 2 pi/Omega)"
         return
      end if
      drive%from_period = len(drive%period_text) > 0
      if (drive%from_period) then
         call parse_expression(drive%period_text, names, drive%expression, error)
      else
         call parse_expression(drive%frequency_text, names, drive%expression, error)
      end if
      if (allocated(error)) problem = drive%name()//": "//error%message
   end subroutine parse_drive

   !> The two axes among the parameters: `alpha_name` and `beta_name` each a parameter, not
   !> the same one, and no parameter computed from either (`depends(j, i)`: parameter j is
   !> computed from parameter i); `problem` names what is wrong (unchanged when nothing is).
   pure subroutine find_axes(names, depends, alpha_name, beta_name, i_alpha, i_beta, problem)
      character(len=*), intent(in) :: names(:)   !! the parameters
      logical, intent(in) :: depends(:, :)       !! which parameter is computed from which
      character(len=*), intent(in) :: alpha_name, beta_name  !! the axes' parameters ("" when not given)
      integer, intent(out) :: i_alpha, i_beta    !! their positions (0 when not found)
      character(len=:), allocatable, intent(inout) :: problem  !! set when the axes are wrong
      character(len=:), allocatable :: known
      integer :: j
      known = names_text(names)
      i_alpha = parameter_position(names, alpha_name)
      i_beta = parameter_position(names, beta_name)
      if (len(alpha_name) > 0 .and. i_alpha == 0) then
         problem = "alpha: '"//alpha_name//"' is no parameter (the parameters: "//known//")"
      else if (len(beta_name) > 0 .and. i_beta == 0) then
         problem = "beta: '"//beta_name//"' is no parameter (the parameters: "//known//")"
      else if (len(alpha_name) == 0) then
         problem = "alpha: name the parameter of the chart's alpha axis (one of: "//known//")"
      else if (len(beta_name) == 0) then
         problem = "beta: name the parameter of the chart's beta axis (one of: "//known//")"
      else if (i_alpha == i_beta) then
         problem = "alpha, beta: the two axes are one parameter, '"//alpha_name//"'"
      else
         do j = 1, size(names)
            if (depends(j, i_alpha) .or. depends(j, i_beta)) then
               problem = trim(merge("alpha", "beta ", depends(j, i_alpha)))//": the parameter '"// &
                  trim(names(j))//"' is computed from the axis '"// &
                  trim(merge(alpha_name//repeat(" ", len(beta_name)), beta_name//repeat(" ", len(alpha_name)), &
                             depends(j, i_alpha)))// &
                  "' and would not follow it along the axis; write that dependence into the expressions instead"
               return
            end if
         end do
      end if
   end subroutine find_axes

   !> The position of a parameter among the parameters (0 when it is none or `name` is "").
   pure integer function parameter_position(names, name) result(position)
      character(len=*), intent(in) :: names(:)  !! the parameters
      character(len=*), intent(in) :: name      !! a name
      if (len(name) > 0) then
         do position = 1, size(names)
            if (trim(names(position)) == name) return
         end do
      end if
      position = 0
   end function parameter_position

   !> Names as a list for messages ("none" for none).
   pure function names_text(names) result(text)
      character(len=*), intent(in) :: names(:)  !! the names
      character(len=:), allocatable :: text
      integer :: j
      text = ""
      do j = 1, size(names)
         if (j > 1) text = text//", "
         text = text//trim(names(j))
      end do
      if (size(names) == 0) text = "none"
   end function names_text

   !> The parameters as `name = value, ...`, for messages.
   pure function values_text(names, values) result(text)
      character(len=*), intent(in) :: names(:)  !! the parameters
      real(wp), intent(in) :: values(:)         !! their values
      character(len=:), allocatable :: text
      integer :: j
      text = ""
      do j = 1, size(names)
         if (j > 1) text = text//", "
         text = text//trim(names(j))//" = "//message_number(values(j))
      end do
   end function values_text

   !> A number for messages: 12 significant digits, no blanks.
   pure function message_number(x) result(text)
      real(wp), intent(in) :: x  !! the number
      character(len=:), allocatable :: text
      text = trim(adjustl(format_es(x, 12)))
   end function message_number

end module hillstab_hill_named_parameters

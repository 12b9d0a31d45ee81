!> Tests of what one equation and a system in their user's terms share (hillstab_hill_named_parameters):
!> the drive's Ω and T at given parameters against 2π/T and the given values, its header
!> text, each refusal of `parse_drive` and `find_axes` naming the variable, and the same
!> refusal from the scalar `equation` model and the `equations` system, which now share
!> them.
module test_named_parameters
   use hillstab_core_kinds, only: wp, pi
   use hillstab_core_error, only: error_t
   use hillstab_core_expression, only: parse_parameters, name_length
   use hillstab_hill_named_parameters, only: drive_t, parse_drive, find_axes, names_text, values_text, &
      message_number, parameter_position
   use hillstab_hill_model_equation, only: equation_model_t
   use hillstab_hill_system_equation, only: equations_system_t
   use hillstab_testing
   implicit none
   private
   public :: collect_named_parameters

contains

   function collect_named_parameters() result(suite)
      type(testsuite_t) :: suite
      suite = new_testsuite("named_parameters", [ &
         new_unittest("drive_at_a_point", drive_at_a_point), &
         new_unittest("drive_refusals", drive_refusals), &
         new_unittest("axes", axes), &
         new_unittest("messages", messages), &
         new_unittest("same_refusals_scalar_and_system", same_refusals_scalar_and_system)])
   end function collect_named_parameters

   !> Ω and T from the drive's value where it is given as a frequency and as a period, at two points.
   subroutine drive_at_a_point(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(drive_t) :: by_frequency, by_period
      character(len=:), allocatable :: problem
      character(len=8) :: names(2)
      real(wp) :: values(2), f, t
      integer :: k
      names = [character(len=8) :: "w", "l"]
      problem = ""
      by_frequency%frequency_text = "2*w"
      call parse_drive(by_frequency, names, problem)
      by_period%period_text = "l/w"
      call parse_drive(by_period, names, problem)
      call check(ctx, problem == "", "both parse: "//problem)
      if (len(problem) > 0) return
      call check(ctx, by_frequency%name() == "frequency" .and. by_period%name() == "period", "names")
      call check(ctx, .not. by_frequency%from_period .and. by_period%from_period, "from_period")
      do k = 1, 2
         values = [3.0_wp*k, 0.5_wp + k]
         f = by_frequency%expression%value(values)
         t = by_period%expression%value(values)
         call check(ctx, by_frequency%omega_of(f), 2.0_wp*values(1), rel=1.0e-15_wp, message="Omega given")
         call check(ctx, by_frequency%period_of(f), 2.0_wp*pi/(2.0_wp*values(1)), rel=1.0e-15_wp, &
                    message="T = 2 pi/Omega")
         call check(ctx, by_period%period_of(t), values(2)/values(1), rel=1.0e-15_wp, message="T given")
         call check(ctx, by_period%omega_of(t), 2.0_wp*pi*values(1)/values(2), rel=1.0e-14_wp, &
                    message="Omega = 2 pi/T")
      end do
      call check(ctx, by_frequency%uses("w") .and. .not. by_frequency%uses("l") .and. by_period%uses("l"), "uses")
      call check(ctx, by_frequency%summary() == ", Omega = 2*w", "summary: "//by_frequency%summary())
      call check(ctx, by_period%summary() == ", period T = l/w, Omega = 2 pi/T", "summary: "//by_period%summary())
   end subroutine drive_at_a_point

   !> Both, neither, and an expression of an unknown name.
   subroutine drive_refusals(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(drive_t) :: drive
      character(len=:), allocatable :: problem
      character(len=8) :: names(1)
      names = [character(len=8) :: "w"]
      problem = ""
      drive%frequency_text = "w"
      drive%period_text = "1/w"
      call parse_drive(drive, names, problem)
      call check(ctx, index(problem, "frequency, period: give one of the two") == 1, problem)
      problem = ""
      drive = drive_t()
      call parse_drive(drive, names, problem)
      call check(ctx, index(problem, "frequency: the drive's angular frequency Omega is required") == 1, problem)
      problem = ""
      drive = drive_t(period_text="2*pi/q")
      call parse_drive(drive, names, problem)
      call check(ctx, index(problem, "period: ") == 1 .and. index(problem, "q") > 0, problem)
   end subroutine drive_refusals

   !> The axes found, and each refusal naming its axis.
   subroutine axes(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=name_length), allocatable :: names(:)
      real(wp), allocatable :: values(:)
      logical, allocatable :: depends(:, :)
      type(error_t), allocatable :: error
      integer :: i_alpha, i_beta
      call parse_parameters("g = 9.81, l = 0.2, w = 300, A = 0.005, v = 2*A, u = g/2", names, values, error, &
                            reserved=["t"], depends=depends)
      call check(ctx, .not. allocated(error), "parameters")
      if (allocated(error)) return
      call expect("w", "l", "", 3, 2)
      call expect("x", "A", "alpha: 'x' is no parameter (the parameters: g, l, w, A, v, u)", 0, 4)
      call expect("w", "y", "beta: 'y' is no parameter (the parameters: g, l, w, A, v, u)", 3, 0)
      call expect("", "A", "alpha: name the parameter of the chart's alpha axis (one of: g, l, w, A, v, u)", 0, 4)
      call expect("w", "", "beta: name the parameter of the chart's beta axis (one of: g, l, w, A, v, u)", 3, 0)
      call expect("l", "l", "alpha, beta: the two axes are one parameter, 'l'", 2, 2)
      call expect("w", "l", "", 3, 2)
      call expect("w", "A", "beta: the parameter 'v' is computed from the axis 'A' and would not follow it along "// &
                  "the axis; write that dependence into the expressions instead", 3, 4)
      call expect("g", "w", "alpha: the parameter 'u' is computed from the axis 'g' and would not follow it along "// &
                  "the axis; write that dependence into the expressions instead", 1, 3)
   contains
      subroutine expect(alpha, beta, message, alpha_at, beta_at)
         character(len=*), intent(in) :: alpha, beta, message
         integer, intent(in) :: alpha_at, beta_at
         character(len=:), allocatable :: problem
         problem = ""
         call find_axes(names, depends, alpha, beta, i_alpha, i_beta, problem)
         call check(ctx, problem == message, "axes '"//alpha//"', '"//beta//"': "//problem)
         call check(ctx, i_alpha == alpha_at .and. i_beta == beta_at, "positions of '"//alpha//"', '"//beta//"'")
      end subroutine expect
   end subroutine axes

   !> The texts of names, values and numbers.
   subroutine messages(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=4) :: none(0)
      call check(ctx, names_text([character(len=4) :: "a", "bc"]) == "a, bc", "names")
      call check(ctx, names_text(none) == "none", "no names")
      call check(ctx, values_text([character(len=4) :: "a", "b"], [0.5_wp, -2.0_wp]) == &
                 "a = 5.00000000000e-001, b = -2.00000000000e+000", values_text([character(len=4) :: "a", "b"], &
                 [0.5_wp, -2.0_wp]))
      call check(ctx, message_number(1.0_wp/3.0_wp) == "3.33333333333e-001", message_number(1.0_wp/3.0_wp))
      call check(ctx, parameter_position([character(len=4) :: "a", "b"], "b") == 2 .and. &
                 parameter_position([character(len=4) :: "a", "b"], "") == 0 .and. &
                 parameter_position([character(len=4) :: "a", "b"], "c") == 0, "positions")
   end subroutine messages

   !> The scalar equation and the system of one equation refuse the same axes and drive
   !> with the same message (their variable, the axis, the parameter).
   subroutine same_refusals_scalar_and_system(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=*), parameter :: parameters = "g = 9.81, l = 0.2, w = 300, A = 0.005, v = 2*A"
      call compare("w", "v2", "w", "", "beta: 'v2' is no parameter")
      call compare("w", "A", "w", "", "beta: the parameter 'v' is computed from the axis 'A'")
      call compare("w", "w", "w", "", "alpha, beta: the two axes are one parameter, 'w'")
      call compare("w", "l", "", "", "frequency: the drive's angular frequency Omega is required")
      call compare("w", "l", "w", "1/w", "frequency, period: give one of the two")
   contains
      subroutine compare(alpha, beta, frequency, period, message)
         character(len=*), intent(in) :: alpha, beta, frequency, period, message
         type(equation_model_t) :: one
         type(equations_system_t) :: system
         type(error_t), allocatable :: e1, e2
         call one%set_text("parameters", parameters, e1)
         call one%set_text("stiffness", "-g/l + A*w^2/l*cos(w*t)", e1)
         call system%set_values("n", [1.0_wp], e2)
         call system%set_text("parameters", parameters, e2)
         call system%set_text("stiffness", "-g/l + A*w^2/l*cos(w*t)", e2)
         call one%set_text("alpha", alpha, e1)
         call one%set_text("beta", beta, e1)
         call system%set_text("alpha", alpha, e2)
         call system%set_text("beta", beta, e2)
         if (len(frequency) > 0) then
            call one%set_text("frequency", frequency, e1)
            call system%set_text("frequency", frequency, e2)
         end if
         if (len(period) > 0) then
            call one%set_text("period", period, e1)
            call system%set_text("period", period, e2)
         end if
         call one%check_values(e1)
         call system%check_values(e2)
         call check(ctx, allocated(e1) .and. allocated(e2), "both refuse: "//message)
         if (.not. (allocated(e1) .and. allocated(e2))) return
         call check(ctx, index(e1%message, message) > 0, "equation: "//e1%message)
         call check(ctx, index(e2%message, message) > 0, "equations: "//e2%message)
      end subroutine compare
   end subroutine same_refusals_scalar_and_system

end module test_named_parameters

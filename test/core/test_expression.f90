!> Tests of hillstab_core_expression: values against the same formulas written in Fortran
!> at many nodes, precedence and associativity, constant folding (instruction counts),
!> every parse error with its column and text, names and parameter lists, non-finite
!> results reported by node without a floating-point trap (halting switched on around the
!> evaluations), the vector evaluation against the scalar one bit for bit, and an OpenMP
!> evaluation against the serial one.
module test_expression
   use hillstab_core_kinds, only: wp, pi
   use hillstab_core_error, only: error_t, err_input, err_overflow, err_invalid_parameter
   use hillstab_core_expression, only: expression_t, expression_work_t, parse_expression, parse_parameters, &
      name_length
   use hillstab_testing
   use, intrinsic :: ieee_arithmetic, only: ieee_is_nan, ieee_is_finite, ieee_support_halting, &
      ieee_get_halting_mode, ieee_set_halting_mode, ieee_overflow, ieee_divide_by_zero, ieee_invalid, &
      ieee_value, ieee_quiet_nan
   implicit none
   private
   public :: collect_expression

   character(len=*), parameter :: hill_names(5) = ["t", "g", "l", "A", "w"]
   real(wp), parameter :: g = 9.81_wp, l = 0.2_wp, amplitude = 0.005_wp, w = 314.16_wp

contains

   function collect_expression() result(suite)
      type(testsuite_t) :: suite
      suite = new_testsuite("expression", [ &
         new_unittest("closed_forms", closed_forms), &
         new_unittest("precedence", precedence), &
         new_unittest("numbers_and_names", numbers_and_names), &
         new_unittest("constant_folding", constant_folding), &
         new_unittest("parse_errors", parse_errors), &
         new_unittest("name_list_errors", name_list_errors), &
         new_unittest("parameters", parameters), &
         new_unittest("parameter_errors", parameter_errors), &
         new_unittest("not_finite_without_trap", not_finite_without_trap), &
         new_unittest("vector_equals_scalar", vector_equals_scalar), &
         new_unittest("openmp_equals_serial", openmp_equals_serial), &
         new_unittest("uses_and_affine", uses_and_affine), &
         new_unittest("evaluate_arguments", evaluate_arguments)])
   end function collect_expression

   ! n nodes from a to b
   function nodes(n, a, b) result(t)
      integer, intent(in) :: n
      real(wp), intent(in) :: a, b
      real(wp) :: t(n)
      integer :: i
      t = [(a + (b - a)*real(i - 1, wp)/real(n - 1, wp), i = 1, n)]
   end function nodes

   ! parse `text` for `names`, recording a failure when it does not parse
   subroutine parse_ok(ctx, text, names, e)
      type(test_context_t), intent(inout) :: ctx
      character(len=*), intent(in) :: text, names(:)
      type(expression_t), intent(out) :: e
      type(error_t), allocatable :: error
      call parse_expression(text, names, e, error)
      call check(ctx, .not. allocated(error), "parses: "//text)
      if (allocated(error)) call check(ctx, .false., error%message)
   end subroutine parse_ok

   ! the value of a constant expression
   real(wp) function constant(ctx, text) result(v)
      type(test_context_t), intent(inout) :: ctx
      character(len=*), intent(in) :: text
      type(expression_t) :: e
      call parse_ok(ctx, text, ["x"], e)
      v = e%value([3.0_wp])
   end function constant

   ! the message of a parse error of `text` (names t, g, l, A, w), "" when it parses
   function parse_message(text) result(message)
      character(len=*), intent(in) :: text
      character(len=:), allocatable :: message
      type(expression_t) :: e
      type(error_t), allocatable :: error
      call parse_expression(text, hill_names, e, error)
      message = ""
      if (allocated(error)) then
         message = error%message
         if (error%code /= err_input) message = "(not err_input) "//message
      end if
   end function parse_message

   subroutine check_message(ctx, text, expected)
      type(test_context_t), intent(inout) :: ctx
      character(len=*), intent(in) :: text, expected
      character(len=:), allocatable :: message
      message = parse_message(text)
      call check(ctx, message == expected, "'"//text//"': got """//message//""" expected """//expected//"""")
   end subroutine check_message

   !> Expressions against the same formulas in Fortran at 1001 nodes: equal where the
   !> operations are the same in the same order, else within 1e-15 relative.
   subroutine closed_forms(ctx)
      type(test_context_t), intent(inout) :: ctx
      integer, parameter :: n = 1001
      type(expression_t) :: e
      type(error_t), allocatable :: error
      real(wp) :: t(n), q(n), expected(n), kappa
      integer :: i
      t = nodes(n, 0.01_wp, 10.0_wp)
      kappa = 0.2_wp
      call parse_ok(ctx, "-g/l + A*w^2/l*cos(w*t)", hill_names, e)
      call e%evaluate(t, q, error, scalars=[g, l, amplitude, w])
      call check(ctx, .not. allocated(error), "hill evaluates")
      expected = -g/l + amplitude*w**2/l*cos(w*t)
      call check(ctx, all(q == expected), "hill coefficient exact")

      call parse_ok(ctx, "exp(-kappa*t)*sin(2*pi*t) + sqrt(1 + t^2)", ["t    ", "kappa"], e)
      call e%evaluate(t, q, error, scalars=[kappa])
      expected = exp(-kappa*t)*sin(2*pi*t) + sqrt(1 + t**2)
      call check(ctx, all(q == expected), "damped sine exact")

      call parse_ok(ctx, "sinh(t/3) - cosh(t/5) + tanh(t) + atan(t) + abs(t - 1) + tan(t/7) + log(1 + t)", ["t"], e)
      call e%evaluate(t, q, error)
      expected = sinh(t/3) - cosh(t/5) + tanh(t) + atan(t) + abs(t - 1) + tan(t/7) + log(1 + t)
      do i = 1, n
         call check(ctx, q(i), expected(i), rel=1.0e-15_wp, message="functions")
      end do

      call parse_ok(ctx, "atan2(sin(t), cos(t)) + t^1.5 + (t - 2)^3 - 1/t^2 + t**-3", ["t"], e)
      call e%evaluate(t, q, error)
      expected = atan2(sin(t), cos(t)) + t**1.5_wp + (t - 2)**3 - 1/t**2 + t**(-3)
      do i = 1, n
         call check(ctx, q(i), expected(i), rel=1.0e-15_wp, message="powers")
      end do

      call parse_ok(ctx, "1e-3*t + .5 - 2. + 1.5D+2 - 25E-1/t", ["t"], e)
      call e%evaluate(t, q, error)
      expected = 1.0e-3_wp*t + 0.5_wp - 2.0_wp + 150.0_wp - 2.5_wp/t
      call check(ctx, all(q == expected), "number formats exact")
   end subroutine closed_forms

   !> Precedence and associativity, exactly.
   subroutine precedence(ctx)
      type(test_context_t), intent(inout) :: ctx
      call check(ctx, constant(ctx, "2^3^2") == 512.0_wp, "2^3^2")
      call check(ctx, constant(ctx, "2**3**2") == 512.0_wp, "2**3**2")
      call check(ctx, constant(ctx, "(2^3)^2") == 64.0_wp, "(2^3)^2")
      call check(ctx, constant(ctx, "-2^2") == -4.0_wp, "-2^2")
      call check(ctx, constant(ctx, "(-2)^2") == 4.0_wp, "(-2)^2")
      call check(ctx, constant(ctx, "-x^2") == -9.0_wp, "-x^2")
      call check(ctx, constant(ctx, "2*-3") == -6.0_wp, "2*-3")
      call check(ctx, constant(ctx, "2*+3") == 6.0_wp, "2*+3")
      call check(ctx, constant(ctx, "--3") == 3.0_wp, "--3")
      call check(ctx, constant(ctx, "1/2/4") == 0.125_wp, "1/2/4")
      call check(ctx, constant(ctx, "2-3-4") == -5.0_wp, "2-3-4")
      call check(ctx, constant(ctx, "2+3*4") == 14.0_wp, "2+3*4")
      call check(ctx, constant(ctx, "(2+3)*4") == 20.0_wp, "(2+3)*4")
      call check(ctx, constant(ctx, "2^-1") == 0.5_wp, "2^-1")
      call check(ctx, constant(ctx, "2^-2^2") == 0.0625_wp, "2^-2^2")
      call check(ctx, constant(ctx, "x^-2") == 1.0_wp/9.0_wp, "x^-2")
      call check(ctx, constant(ctx, "-x*2") == -6.0_wp, "-x*2")
      call check(ctx, constant(ctx, "x^0") == 1.0_wp, "x^0")
      call check(ctx, constant(ctx, "(-x)^3") == -27.0_wp, "(-x)^3")
      call check(ctx, constant(ctx, "x^x") == 27.0_wp, "x^x")
      call check(ctx, constant(ctx, "(-x)^(x-1)") == 9.0_wp, "(-x)^(x-1): an integer power of a negative number")
   end subroutine precedence

   !> Number forms, pi and functions in any case, blanks and tabs.
   subroutine numbers_and_names(ctx)
      type(test_context_t), intent(inout) :: ctx
      call check(ctx, constant(ctx, "1e-3") == 1.0e-3_wp, "1e-3")
      call check(ctx, constant(ctx, ".5") == 0.5_wp, ".5")
      call check(ctx, constant(ctx, "2.") == 2.0_wp, "2.")
      call check(ctx, constant(ctx, "1.5d2") == 150.0_wp, "1.5d2")
      call check(ctx, constant(ctx, "1E+2") == 100.0_wp, "1E+2")
      call check(ctx, constant(ctx, "1.7976931348623157e308") == huge(1.0_wp), "huge")
      call check(ctx, constant(ctx, "1e-400") == 0.0_wp, "1e-400 underflows to 0")
      call check(ctx, constant(ctx, "pi") == pi, "pi")
      call check(ctx, constant(ctx, "PI*Sin(0) + COS(0)") == 1.0_wp, "any case")
      call check(ctx, constant(ctx, "  x"//achar(9)//"* 2 ") == 6.0_wp, "blanks and tabs")
      call check(ctx, constant(ctx, "atan2(1, 1)") == atan2(1.0_wp, 1.0_wp), "atan2")
   end subroutine numbers_and_names

   !> Parts of numbers and pi fold into one constant: 2*pi*50*t is 3 instructions.
   subroutine constant_folding(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(expression_t) :: e
      call parse_ok(ctx, "2*pi*50*t", ["t"], e)
      call check(ctx, e%instruction_count() <= 3, "2*pi*50*t: 3 instructions or fewer")
      call check(ctx, e%value([0.5_wp]) == 2*pi*50*0.5_wp, "2*pi*50*t value")
      call parse_ok(ctx, "2*pi*50", ["t"], e)
      call check(ctx, e%instruction_count() == 1, "2*pi*50: one constant")
      call check(ctx, e%is_constant(), "2*pi*50 is constant")
      call parse_ok(ctx, "sqrt(2)*exp(-(1/2)^2)*t + cos(pi/3)", ["t"], e)
      call check(ctx, e%instruction_count() == 5, "functions of constants folded")
      call check(ctx, e%value([2.0_wp]) == sqrt(2.0_wp)*exp(-(0.5_wp)**2)*2.0_wp + cos(pi/3), "folded value")
      call parse_ok(ctx, "-(3)", ["t"], e)
      call check(ctx, e%instruction_count() == 1 .and. e%value([0.0_wp]) == -3.0_wp, "sign folded")
      call parse_ok(ctx, "t^2", ["t"], e)
      call check(ctx, e%instruction_count() == 2, "t^2: an integer power")
      call parse_ok(ctx, "t*2*pi", ["t"], e)
      call check(ctx, e%instruction_count() == 5, "t*2*pi: the written order kept")
      call check(ctx, .not. e%is_constant(), "t*2*pi is not constant")
   end subroutine constant_folding

   !> Every parse error: its text and column.
   subroutine parse_errors(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=*), parameter :: operand = "; expected a number, a name, a function or '('"
      call check_message(ctx, "g/lenght", "unknown name 'lenght' at column 3; the names are t, g, l, A, w")
      call check_message(ctx, "a*w", "unknown name 'a' at column 1; the names are t, g, l, A, w "// &
         "(names are case-sensitive: 'A')")
      call check_message(ctx, "", "empty expression at column 1"//operand)
      call check_message(ctx, "   ", "empty expression at column 1"//operand)
      call check_message(ctx, "(g + l", "unbalanced parentheses: '(' at column 1 is not closed")
      call check_message(ctx, "sin(w*(t + 1)", "unbalanced parentheses: '(' at column 4 is not closed")
      call check_message(ctx, "g + l)", "unbalanced parentheses: ')' at column 6 has no '('")
      call check_message(ctx, "g*", "missing operand at the end of the expression, after '*' at column 2"//operand)
      call check_message(ctx, "-", "missing operand at the end of the expression, after '-' at column 1"//operand)
      call check_message(ctx, "*g", "missing operand before '*' at column 1"//operand)
      call check_message(ctx, "(g+)", "missing operand before ')' at column 4"//operand)
      call check_message(ctx, "sin(,t)", "missing operand before ',' at column 5"//operand)
      call check_message(ctx, "()", "empty parentheses at column 1"//operand)
      call check_message(ctx, "g*/l", "two operators in a row: '/' at column 3 after '*' at column 2"//operand)
      call check_message(ctx, "g + ^ l", "two operators in a row: '^' at column 5 after '+' at column 3"//operand)
      call check_message(ctx, "g l", "unexpected 'l' at column 3; expected an operator or the end of the expression")
      call check_message(ctx, "2t", "unexpected 't' at column 2; expected an operator or the end of the expression")
      call check_message(ctx, "g, l", "unexpected ',' at column 2; expected an operator or the end of the expression")
      call check_message(ctx, "(g l)", "unexpected 'l' at column 4; expected an operator or ')'")
      call check_message(ctx, "sin(g l)", "unexpected 'l' at column 7; expected an operator, ',' or ')'")
      call check_message(ctx, "sin t", "function 'sin' at column 1 needs its argument in parentheses: sin(x)")
      call check_message(ctx, "2*exp", "function 'exp' at column 3 needs its argument in parentheses: exp(x)")
      call check_message(ctx, "atan2", "function 'atan2' at column 1 needs its argument in parentheses: atan2(x, x)")
      call check_message(ctx, "cos(t, w)", "function 'cos' at column 1 takes 1 argument, found 2")
      call check_message(ctx, "cos()", "function 'cos' at column 1 takes 1 argument, found 0")
      call check_message(ctx, "atan2(t)", "function 'atan2' at column 1 takes 2 arguments, found 1")
      call check_message(ctx, "g $ l", "unexpected character '$' at column 3; expected a number, a name, "// &
         "an operator or a parenthesis")
      call check_message(ctx, "2e+", "malformed number '2e+' at column 1; expected the digits of the exponent")
      call check_message(ctx, "g*.", "malformed number '.' at column 3; expected digits")
      call check_message(ctx, "1e400*t", "number '1e400' at column 1 is too large (the largest is about 1.797e308)")
      call check_message(ctx, "1.8e308", "number '1.8e308' at column 1 is too large (the largest is about 1.797e308)")
      call check_message(ctx, "t + 1/0", "division by zero at column 6 (a constant part of the expression)")
      call check_message(ctx, "log(-1)", "log of zero or of a negative number at column 1 (a constant part of "// &
         "the expression)")
      call check_message(ctx, "t*exp(1000)", "overflow at column 3 (a constant part of the expression)")
      call check_message(ctx, "sqrt(-2)", "square root of a negative number at column 1 (a constant part of "// &
         "the expression)")
      call check_message(ctx, "(-2)^0.5", "negative number to a non-integer power at column 5 (a constant part "// &
         "of the expression)")
      call check_message(ctx, "0^-1", "zero to a negative power at column 2 (a constant part of the expression)")
      call check_message(ctx, repeat("(", 201)//"t"//repeat(")", 201), &
         "more than 200 nested signs and parentheses at column 201")
   end subroutine parse_errors

   !> The list of names: letters, digits, underscores; no function or pi; no repeat.
   subroutine name_list_errors(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(expression_t) :: e
      type(error_t), allocatable :: error
      call parse_expression("x", ["x  ", "sin"], e, error)
      call check(ctx, allocated(error), "sin refused")
      if (allocated(error)) call check(ctx, error%message == "'sin' cannot name a variable: it is the function sin", &
         error%message)
      call parse_expression("x", ["x ", "Pi"], e, error)
      call check(ctx, allocated(error), "Pi refused")
      if (allocated(error)) call check(ctx, error%message == "'Pi' cannot name a variable: it is the constant pi", &
         error%message)
      call parse_expression("x", ["x ", "2x"], e, error)
      call check(ctx, allocated(error), "2x refused")
      if (allocated(error)) call check(ctx, error%message == &
         "'2x' is no name (letters, digits and underscores, starting with a letter)", error%message)
      call parse_expression("x", ["x", "x"], e, error)
      call check(ctx, allocated(error), "twice refused")
      if (allocated(error)) call check(ctx, error%message == "name 'x' is given twice in the list of names", &
         error%message)
      call parse_expression("x", ["x", " "], e, error)
      call check(ctx, allocated(error), "empty name refused")
      call parse_expression("omega_2 + Omega_2", [" omega_2", "Omega_2 "], e, error)
      call check(ctx, .not. allocated(error), "case-sensitive names, blanks around ignored")
      if (.not. allocated(error)) call check(ctx, e%value([1.0_wp, 2.0_wp]) == 3.0_wp, "two names")
   end subroutine name_list_errors

   !> A parameter list with values depending on earlier ones and on pi.
   subroutine parameters(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=name_length), allocatable :: names(:)
      real(wp), allocatable :: values(:)
      type(error_t), allocatable :: error
      call parse_parameters("g = 9.81, l = 0.2, kappa = 0.2, A = 0.005, w = 2*pi*50, w0 = sqrt(g/l), "// &
         "z = atan2(1, 2)", names, values, error, reserved=["t"])
      call check(ctx, .not. allocated(error), "parses")
      if (allocated(error)) then
         call check(ctx, .false., error%message)
         return
      end if
      call check(ctx, size(names) == 7 .and. size(values) == 7, "seven parameters")
      if (size(names) /= 7) return
      call check(ctx, names(1) == "g" .and. names(3) == "kappa" .and. names(4) == "A" .and. names(6) == "w0", "names")
      call check(ctx, values(1) == 9.81_wp .and. values(2) == 0.2_wp .and. values(4) == 0.005_wp, "values")
      call check(ctx, values(5) == 2*pi*50, "w = 2*pi*50")
      call check(ctx, values(6) == sqrt(9.81_wp/0.2_wp), "w0 = sqrt(g/l), of earlier parameters")
      call check(ctx, values(7) == atan2(1.0_wp, 2.0_wp), "a comma inside parentheses")
      call parse_parameters("  ", names, values, error)
      call check(ctx, .not. allocated(error) .and. size(names) == 0, "blank: no parameters")
   end subroutine parameters

   subroutine check_parameter_message(ctx, text, expected)
      type(test_context_t), intent(inout) :: ctx
      character(len=*), intent(in) :: text, expected
      character(len=name_length), allocatable :: names(:)
      real(wp), allocatable :: values(:)
      type(error_t), allocatable :: error
      character(len=:), allocatable :: message
      call parse_parameters(text, names, values, error, reserved=["t"])
      message = ""
      if (allocated(error)) message = error%message
      call check(ctx, message == expected, "'"//text//"': got """//message//""" expected """//expected//"""")
      if (allocated(error)) call check(ctx, error%code == err_input, "err_input")
   end subroutine check_parameter_message

   !> Parameter list errors name the item and the column.
   subroutine parameter_errors(ctx)
      type(test_context_t), intent(inout) :: ctx
      call check_parameter_message(ctx, "g = 9.81, l 0.2", &
         "parameters: item 2 'l 0.2' at column 11 has no '='; expected name = value")
      call check_parameter_message(ctx, "g = 9.81, l = 0.2 kappa = 0.2", &
         "parameters: item 2 'l': a second '=' at column 25; expected ',' between items")
      call check_parameter_message(ctx, "g = 9.81, l = 2*w, w = 3", &
         "parameters: item 2 'l': unknown name 'w' at column 17; the names are g")
      call check_parameter_message(ctx, "l = 2*g, g = 1", &
         "parameters: item 1 'l': unknown name 'g' at column 7; no names are defined here "// &
         "(only numbers, pi and functions)")
      call check_parameter_message(ctx, "g = 9.81, g = 1", "parameters: item 2: 'g' at column 11 is given twice")
      call check_parameter_message(ctx, "g = 1, t = 2", &
         "parameters: item 2: 't' at column 8 is reserved; a parameter cannot take it")
      call check_parameter_message(ctx, "pi = 3", &
         "parameters: item 1: 'pi' at column 1 cannot name a parameter: it is the constant pi")
      call check_parameter_message(ctx, "g = 1,, l = 2", "parameters: item 2 at column 7 is empty; expected name = value")
      call check_parameter_message(ctx, "g = 1,", "parameters: item 2 at column 7 is empty; expected name = value")
      call check_parameter_message(ctx, "g = ", "parameters: item 1 'g' has no value after '=' at column 3; "// &
         "expected name = value")
      call check_parameter_message(ctx, " = 2", "parameters: item 1 has no name before '=' at column 2")
      call check_parameter_message(ctx, "2g = 2", "parameters: item 1: '2g' at column 1 is no name (letters, "// &
         "digits and underscores, starting with a letter, at most 63)")
      call check_parameter_message(ctx, "g = 9.81, l = g*/2", "parameters: item 2 'l': two operators in a row: "// &
         "'/' at column 17 after '*' at column 16; expected a number, a name, a function or '('")
      call check_parameter_message(ctx, "g = 0, l = 1/g", "parameters: item 2 'l': the expression is not finite: "// &
         "division by zero at column 13")
   end subroutine parameter_errors

   ! halting on overflow, division by zero and invalid switched on (saved in `saved`), when
   ! the processor can: a trap would stop the test
   subroutine traps_on(saved)
      logical, intent(out) :: saved(3)
      call ieee_get_halting_mode(ieee_overflow, saved(1))
      call ieee_get_halting_mode(ieee_divide_by_zero, saved(2))
      call ieee_get_halting_mode(ieee_invalid, saved(3))
      if (ieee_support_halting(ieee_overflow)) call ieee_set_halting_mode(ieee_overflow, .true.)
      if (ieee_support_halting(ieee_divide_by_zero)) call ieee_set_halting_mode(ieee_divide_by_zero, .true.)
      if (ieee_support_halting(ieee_invalid)) call ieee_set_halting_mode(ieee_invalid, .true.)
   end subroutine traps_on

   subroutine traps_restore(saved)
      logical, intent(in) :: saved(3)
      if (ieee_support_halting(ieee_overflow)) call ieee_set_halting_mode(ieee_overflow, saved(1))
      if (ieee_support_halting(ieee_divide_by_zero)) call ieee_set_halting_mode(ieee_divide_by_zero, saved(2))
      if (ieee_support_halting(ieee_invalid)) call ieee_set_halting_mode(ieee_invalid, saved(3))
   end subroutine traps_restore

   ! evaluate `text` in x at the nodes `x`, traps on; the error's message and code, the first
   ! failed node, and whether exactly the nodes `bad` are NaN
   subroutine check_not_finite(ctx, text, x, first, code, message, bad)
      type(test_context_t), intent(inout) :: ctx
      character(len=*), intent(in) :: text, message
      real(wp), intent(in) :: x(:)
      integer, intent(in) :: first, code
      logical, intent(in) :: bad(:)
      type(expression_t) :: e
      type(error_t), allocatable :: error
      real(wp) :: r(size(x))
      logical :: saved(3)
      integer :: failed
      call parse_ok(ctx, text, ["x"], e)
      call traps_on(saved)
      call e%evaluate(x, r, error, failed_node=failed)
      call traps_restore(saved)
      call check(ctx, allocated(error), text//": reported")
      if (.not. allocated(error)) return
      call check(ctx, error%code == code, text//": code")
      call check(ctx, error%message == message, text//": got """//error%message//""" expected """//message//"""")
      call check(ctx, failed == first, text//": failed node")
      call check(ctx, all(ieee_is_nan(r) .eqv. bad), text//": NaN at the failed nodes")
      call check(ctx, all(ieee_is_finite(r) .eqv. .not. bad), text//": finite elsewhere")
   end subroutine check_not_finite

   !> Non-finite results reported with the first node, its reason and column, with halting
   !> on overflow, division by zero and invalid switched on: no trap.
   subroutine not_finite_without_trap(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(expression_t) :: e
      type(error_t), allocatable :: error
      real(wp) :: r(4), x(4)
      logical :: saved(3)
      integer :: failed
      x = [2.0_wp, 1.0_wp, -1.0_wp, 0.0_wp]
      call check_not_finite(ctx, "log(x)", x, 3, err_invalid_parameter, &
         "the expression is not finite at node 3 of 4: log of zero or of a negative number at column 1", &
         [.false., .false., .true., .true.])
      call check_not_finite(ctx, "1 + 1/x", x, 4, err_invalid_parameter, &
         "the expression is not finite at node 4 of 4: division by zero at column 6", &
         [.false., .false., .false., .true.])
      call check_not_finite(ctx, "exp(x)", [1.0_wp, 1000.0_wp, 709.0_wp], 2, err_overflow, &
         "the expression is not finite at node 2 of 3: overflow at column 1", [.false., .true., .false.])
      call check_not_finite(ctx, "log(x) + 1/(x - 3)", [1.0_wp, 3.0_wp, 4.0_wp, -1.0_wp], 2, err_invalid_parameter, &
         "the expression is not finite at node 2 of 4: division by zero at column 11", &
         [.false., .true., .false., .true.])
      call check_not_finite(ctx, "x*x", [1.0e200_wp, 1.0e100_wp, -1.0e150_wp], 1, err_overflow, &
         "the expression is not finite at node 1 of 3: overflow at column 2", [.true., .false., .false.])
      call check_not_finite(ctx, "x + 1.7e308", [1.0e307_wp, -1.0e308_wp, 2.0e307_wp], 1, err_overflow, &
         "the expression is not finite at node 1 of 3: overflow at column 3", [.true., .false., .true.])
      call check_not_finite(ctx, "1e300/x", [1.0_wp, 1.0e10_wp, 1.0e-10_wp], 3, err_overflow, &
         "the expression is not finite at node 3 of 3: overflow at column 6", [.false., .false., .true.])
      call check_not_finite(ctx, "sqrt(x) + cosh(x)", [4.0_wp, -1.0_wp, 800.0_wp], 2, err_invalid_parameter, &
         "the expression is not finite at node 2 of 3: square root of a negative number at column 1", &
         [.false., .true., .true.])
      call check_not_finite(ctx, "x^0.5 + x^-3", [4.0_wp, -1.0_wp, 0.0_wp, 1.0e-200_wp], 2, err_invalid_parameter, &
         "the expression is not finite at node 2 of 4: negative number to a non-integer power at column 2", &
         [.false., .true., .true., .true.])
      call check_not_finite(ctx, "x^10 + 10^x", [1.0_wp, 1.0e31_wp, 400.0_wp], 2, err_overflow, &
         "the expression is not finite at node 2 of 3: overflow at column 2", [.false., .true., .true.])
      call check_not_finite(ctx, "2*x", [1.0_wp, ieee_value(1.0_wp, ieee_quiet_nan), huge(1.0_wp)], 2, &
         err_invalid_parameter, "the value of 'x' at node 2 of 3 is not finite", [.false., .true., .true.])
      ! a part of scalars alone fails at every node
      call parse_ok(ctx, "t + log(g)", ["t", "g"], e)
      call traps_on(saved)
      call e%evaluate(x, r, error, scalars=[-1.0_wp], failed_node=failed)
      call traps_restore(saved)
      call check(ctx, allocated(error) .and. failed == 1, "scalar part fails")
      call check(ctx, all(ieee_is_nan(r)), "scalar part fails at every node")
      ! the scalar convenience gives NaN
      call parse_ok(ctx, "log(x)", ["x"], e)
      call traps_on(saved)
      r(1) = e%value([-1.0_wp])
      call traps_restore(saved)
      call check(ctx, ieee_is_nan(r(1)), "value: NaN")
      ! the limits: finite up to them
      call parse_ok(ctx, "exp(x)", ["x"], e)
      call traps_on(saved)
      r(1) = e%value([log(huge(1.0_wp))])
      r(2) = e%value([-1000.0_wp])
      call traps_restore(saved)
      call check(ctx, ieee_is_finite(r(1)) .and. r(1) > 1.0e308_wp, "exp(log(huge)) finite")
      call check(ctx, r(2) == 0.0_wp, "exp(-1000) underflows to 0")
      call parse_ok(ctx, "x*2", ["x"], e)
      call traps_on(saved)
      r(1) = e%value([0.5_wp*huge(1.0_wp)])
      r(2) = e%value([nearest(0.5_wp*huge(1.0_wp), 2.0_wp)])
      call traps_restore(saved)
      call check(ctx, r(1) == huge(1.0_wp), "huge/2 * 2 = huge")
      call check(ctx, ieee_is_nan(r(2)), "just above: overflow")
   end subroutine not_finite_without_trap

   !> 10^5 nodes at once against one node at a time, bit for bit; and every variable as a
   !> column against t as a vector with scalars.
   subroutine vector_equals_scalar(ctx)
      type(test_context_t), intent(inout) :: ctx
      integer, parameter :: n = 100000
      type(expression_t) :: e
      type(error_t), allocatable :: error
      real(wp), allocatable :: t(:), q(:), q_columns(:), values(:, :)
      integer :: i, n_differ
      t = nodes(n, -3.0_wp, 7.0_wp)
      allocate (q(n), q_columns(n), values(n, 5))
      call parse_ok(ctx, "-g/l + A*w^2/l*cos(w*t) + exp(-t^2)*atan(t)/(1 + t^2) + sqrt(abs(t))^3 - abs(t)^1.25", &
         hill_names, e)
      call e%evaluate(t, q, error, scalars=[g, l, amplitude, w])
      call check(ctx, .not. allocated(error), "evaluates")
      n_differ = 0
      do i = 1, n
         if (q(i) /= e%value([t(i), g, l, amplitude, w])) n_differ = n_differ + 1
      end do
      call check(ctx, n_differ == 0, "every node equals its scalar evaluation")
      values(:, 1) = t
      values(:, 2) = g
      values(:, 3) = l
      values(:, 4) = amplitude
      values(:, 5) = w
      call e%evaluate(values, q_columns, error)
      call check(ctx, all(q_columns == q), "all variables as columns: the same values")
   end subroutine vector_equals_scalar

   !> Two threads evaluate one expression, each with its own work arrays, on chunks of
   !> the nodes: the serial values.
   subroutine openmp_equals_serial(ctx)
      type(test_context_t), intent(inout) :: ctx
      integer, parameter :: n = 20000, chunk = 1000
      type(expression_t) :: e
      type(error_t), allocatable :: error
      type(expression_work_t) :: work
      real(wp), allocatable :: t(:), serial(:), parallel(:)
      integer :: c, n_errors
      t = nodes(n, 0.0_wp, 20.0_wp)
      allocate (serial(n), parallel(n))
      call parse_ok(ctx, "-g/l + A*w^2/l*cos(w*t) + sinh(t/10)*log(1 + t)", hill_names, e)
      call e%evaluate(t, serial, error, scalars=[g, l, amplitude, w])
      n_errors = 0
      !$omp parallel do num_threads(2) default(none) shared(e, t, parallel) private(work, error) &
      !$omp reduction(+:n_errors) schedule(dynamic)
      do c = 1, n/chunk
         call e%evaluate(t((c - 1)*chunk + 1:c*chunk), parallel((c - 1)*chunk + 1:c*chunk), error, &
            scalars=[g, l, amplitude, w], work=work)
         if (allocated(error)) n_errors = n_errors + 1
      end do
      !$omp end parallel do
      call check(ctx, n_errors == 0, "no errors")
      call check(ctx, all(parallel == serial), "parallel equals serial")
   end subroutine openmp_equals_serial

   !> Which variables an expression uses, and whether it is affine in one.
   subroutine uses_and_affine(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(expression_t) :: e
      call parse_ok(ctx, "-g/l + A*w^2/l*cos(w*t)", hill_names, e)
      call check(ctx, e%uses("t") .and. e%uses("A") .and. e%uses("w"), "uses t, A, w")
      call check(ctx, .not. e%uses("a") .and. .not. e%uses("kappa"), "not a nor kappa")
      call check(ctx, e%affine_in("A") .and. e%affine_in("g"), "affine in A and g")
      call check(ctx, .not. e%affine_in("l") .and. .not. e%affine_in("w") .and. .not. e%affine_in("t"), &
         "not affine in l, w, t")
      call parse_ok(ctx, "-g/l + A*cos(w*t)", hill_names, e)
      call check(ctx, e%uses("t") .and. e%affine_in("A"), "uses t, affine in A")
      call parse_ok(ctx, "-g/l", hill_names, e)
      call check(ctx, .not. e%uses("t") .and. .not. e%is_constant(), "time-free, not constant")
      call check(ctx, e%affine_in("t"), "a name not used: affine")
      call parse_ok(ctx, "(A - 2*A)/l + A^1 + -A*3 + sin(t)*A + A^0*t^2", hill_names, e)
      call check(ctx, e%affine_in("A"), "affine forms in A")
      call parse_ok(ctx, "A*A", hill_names, e)
      call check(ctx, .not. e%affine_in("A"), "A*A")
      call parse_ok(ctx, "1/A", hill_names, e)
      call check(ctx, .not. e%affine_in("A"), "1/A")
      call parse_ok(ctx, "sin(A)", hill_names, e)
      call check(ctx, .not. e%affine_in("A"), "sin(A)")
      call parse_ok(ctx, "2^A", hill_names, e)
      call check(ctx, .not. e%affine_in("A"), "2^A")
      call check(ctx, e%variable_count() == 5, "five variables")
   end subroutine uses_and_affine

   !> Wrong shapes and an unparsed expression give errors, not crashes.
   subroutine evaluate_arguments(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(expression_t) :: e
      type(error_t), allocatable :: error
      real(wp) :: r(3), values(3, 2)
      call e%evaluate([1.0_wp, 2.0_wp, 3.0_wp], r, error)
      call check(ctx, allocated(error), "not parsed")
      call parse_ok(ctx, "t*g", ["t", "g"], e)
      call e%evaluate([1.0_wp, 2.0_wp, 3.0_wp], r, error)
      call check(ctx, allocated(error), "scalar missing")
      if (allocated(error)) call check(ctx, error%message == &
         "evaluate: 1 node variables and 0 scalars given for 2 variables", error%message)
      call e%evaluate([1.0_wp, 2.0_wp], r, error, scalars=[2.0_wp])
      call check(ctx, allocated(error), "sizes differ")
      values(:, 1) = [1.0_wp, 2.0_wp, 3.0_wp]
      values(:, 2) = 2.0_wp
      call e%evaluate(values, r, error)
      call check(ctx, .not. allocated(error) .and. all(r == [2.0_wp, 4.0_wp, 6.0_wp]), "columns")
      call check(ctx, ieee_is_nan(e%value([1.0_wp])), "value with too few variables: NaN")
   end subroutine evaluate_arguments

end module test_expression

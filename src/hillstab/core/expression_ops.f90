!> The parts of hillstab_core_expression that its parser and its evaluator share: the
!> instruction and failure codes, the functions' table, the limits beyond which a value
!> would not be finite, the rules of names, and the arithmetic on finite operands that
!> returns a result or a failure code and never raises a floating-point exception (one
!> value, or a vector at once with the nodes where it fails marked). An internal module:
!> users take hillstab_core_expression.
module hillstab_core_expression_ops
   use hillstab_core_kinds, only: wp, int64
   use hillstab_core_text, only: lower_case
   implicit none
   public
   private :: wp, int64, lower_case

   !> Longest variable or parameter name.
   integer, parameter :: name_length = 63

   ! instructions
   integer, parameter :: op_const = 1, op_var = 2, op_neg = 3, op_add = 4, op_sub = 5, op_mul = 6, &
      op_div = 7, op_pow = 8, op_powi = 9, op_atan2 = 10, op_sin = 11, op_cos = 12, op_tan = 13, &
      op_exp = 14, op_log = 15, op_sqrt = 16, op_abs = 17, op_sinh = 18, op_cosh = 19, op_tanh = 20, &
      op_atan = 21
   ! the functions: name, instruction, number of arguments
   character(len=5), parameter :: function_names(12) = [character(len=5) :: "sin", "cos", "tan", "exp", &
      "log", "sqrt", "abs", "sinh", "cosh", "tanh", "atan", "atan2"]
   integer, parameter :: function_ops(12) = [op_sin, op_cos, op_tan, op_exp, op_log, op_sqrt, op_abs, &
      op_sinh, op_cosh, op_tanh, op_atan, op_atan2]
   integer, parameter :: function_arity(12) = [1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 2]
   ! why a value is not finite
   integer, parameter :: fail_overflow = 1, fail_division = 2, fail_log = 3, fail_sqrt = 4, &
      fail_power = 5, fail_zero_power = 6, fail_input = 7
   ! tokens
   integer, parameter :: tk_end = 0, tk_number = 1, tk_name = 2, tk_plus = 3, tk_minus = 4, tk_star = 5, &
      tk_slash = 6, tk_caret = 7, tk_lparen = 8, tk_rparen = 9, tk_comma = 10
   ! largest |n| of an integer power compiled as such
   integer, parameter :: max_integer_power = 64
   ! deepest nesting of parentheses and unary signs
   integer, parameter :: max_nesting = 200

   real(wp), parameter :: half_huge = 0.5_wp*huge(1.0_wp)
   real(wp), parameter :: quarter_huge = 0.25_wp*huge(1.0_wp)
   ! exp(x) is finite for x <= log(huge) (the correctly rounded value)
   real(wp), parameter :: exp_limit = log(huge(1.0_wp))
   ! sinh and cosh are finite below log(2 huge) = 710.4758600739…
   real(wp), parameter :: hyperbolic_limit = 710.475_wp
   ! a power a^b whose logarithm b log|a| is at most this is finite (e^709.78 = 0.9973 huge)
   real(wp), parameter :: power_limit = 709.78_wp
   ! the decimal digits of the overflow threshold 2^1024 − 2^970 (numbers from it up are infinite)
   character(len=40), parameter :: overflow_digits = "1797693134862315807937289714053034150799"

   ! nodes where an evaluation failed, and the first of them
   type :: failure_t
      integer :: first = 0        ! first failed node (0: none)
      integer :: code = 0         ! fail_* of the first failed node
      integer :: instruction = 0  ! its instruction
      integer :: current = 0      ! the instruction being run
      logical, allocatable :: failed(:)
   end type failure_t

contains

   ! ---------------------------------------------------------------------------------------
   ! names

   pure logical function is_name_character(c)
      character, intent(in) :: c
      is_name_character = (c >= "a" .and. c <= "z") .or. (c >= "A" .and. c <= "Z") .or. &
         (c >= "0" .and. c <= "9") .or. c == "_"
   end function is_name_character

   ! letters, digits and underscores, starting with a letter
   pure logical function is_name(text)
      character(len=*), intent(in) :: text
      integer :: i
      is_name = len(text) > 0
      if (.not. is_name) return
      is_name = (text(1:1) >= "a" .and. text(1:1) <= "z") .or. (text(1:1) >= "A" .and. text(1:1) <= "Z")
      do i = 2, len(text)
         is_name = is_name .and. is_name_character(text(i:i))
      end do
   end function is_name

   pure integer function function_index(name)
      character(len=*), intent(in) :: name
      integer :: i
      function_index = 0
      if (len(name) > len(function_names)) return
      do i = 1, size(function_names)
         if (lower_case(name) == function_names(i)) function_index = i
      end do
   end function function_index

   ! a function name or pi, in any case
   pure logical function is_reserved(name)
      character(len=*), intent(in) :: name
      is_reserved = function_index(name) > 0 .or. lower_case(name) == "pi"
   end function is_reserved

   pure function reserved_what(name) result(text)
      character(len=*), intent(in) :: name
      character(len=:), allocatable :: text
      if (function_index(name) > 0) then
         text = "the function "//trim(function_names(function_index(name)))
      else
         text = "the constant pi"
      end if
   end function reserved_what

   pure integer function variable_index(names, name)
      character(len=*), intent(in) :: names(:), name
      integer :: i
      variable_index = 0
      if (len(name) > name_length) return
      do i = 1, size(names)
         if (names(i) == name) then
            variable_index = i
            return
         end if
      end do
   end function variable_index

   ! "the names are t, g, l" (with a hint when only the case differs)
   pure function names_text(names, name) result(text)
      character(len=*), intent(in) :: names(:), name
      character(len=:), allocatable :: text
      integer :: i
      if (size(names) == 0) then
         text = "no names are defined here (only numbers, pi and functions)"
         return
      end if
      text = "the names are "
      do i = 1, size(names)
         if (i > 1) text = text//", "
         text = text//trim(names(i))
      end do
      do i = 1, size(names)
         if (lower_case(trim(names(i))) == lower_case(name)) then
            text = text//" (names are case-sensitive: '"//trim(names(i))//"')"
            exit
         end if
      end do
   end function names_text

   ! ---------------------------------------------------------------------------------------
   ! safe arithmetic on finite operands: a result or a fail_* code, never a trap

   pure function failure_text(code) result(text)
      integer, intent(in) :: code
      character(len=:), allocatable :: text
      select case (code)
      case (fail_overflow); text = "overflow"
      case (fail_division); text = "division by zero"
      case (fail_log); text = "log of zero or of a negative number"
      case (fail_sqrt); text = "square root of a negative number"
      case (fail_power); text = "negative number to a non-integer power"
      case (fail_zero_power); text = "zero to a negative power"
      case (fail_input); text = "a value given is not finite"
      case default; text = "not finite"
      end select
   end function failure_text

   pure logical function finite(x)
      real(wp), intent(in) :: x
      integer(int64), parameter :: exponent_bits = int(z'7FF0000000000000', int64)
      finite = iand(transfer(x, 0_int64), exponent_bits) /= exponent_bits
   end function finite

   pure real(wp) function quiet_nan()
      quiet_nan = transfer(int(z'7FF8000000000000', int64), 1.0_wp)
   end function quiet_nan

   pure subroutine add_1(a, b, r, code)
      real(wp), intent(in) :: a, b
      real(wp), intent(out) :: r
      integer, intent(out) :: code
      real(wp) :: h
      code = 0
      if (abs(a) <= half_huge .and. abs(b) <= half_huge) then
         r = a + b
      else
         h = 0.5_wp*a + 0.5_wp*b
         if (abs(h) <= half_huge) then
            r = 2.0_wp*h
         else
            r = 0.0_wp
            code = fail_overflow
         end if
      end if
   end subroutine add_1

   pure subroutine mul_1(a, b, r, code)
      real(wp), intent(in) :: a, b
      real(wp), intent(out) :: r
      integer, intent(out) :: code
      real(wp) :: q
      code = 0
      r = 0.0_wp
      if (abs(a) <= 1.0_wp .or. abs(b) <= 1.0_wp) then
         r = a*b
      else if (abs(a) <= half_huge/abs(b)) then
         r = a*b
      else if (exponent(a) + exponent(b) >= 1026) then
         code = fail_overflow
      else
         q = scale(a, -2)*b
         if (abs(q) <= quarter_huge) then
            r = 4.0_wp*q
         else
            code = fail_overflow
         end if
      end if
   end subroutine mul_1

   pure subroutine div_1(a, b, r, code)
      real(wp), intent(in) :: a, b
      real(wp), intent(out) :: r
      integer, intent(out) :: code
      real(wp) :: q
      code = 0
      r = 0.0_wp
      if (b == 0.0_wp) then
         code = fail_division
      else if (abs(b) >= 1.0_wp) then
         r = a/b
      else if (abs(a) <= abs(b)*half_huge) then
         r = a/b
      else if (exponent(a) - exponent(b) - 1 >= 1024) then
         code = fail_overflow
      else
         q = scale(a, -2)/b
         if (abs(q) <= quarter_huge) then
            r = 4.0_wp*q
         else
            code = fail_overflow
         end if
      end if
   end subroutine div_1

   pure subroutine pow_1(a, b, r, code)
      real(wp), intent(in) :: a, b
      real(wp), intent(out) :: r
      integer, intent(out) :: code
      real(wp) :: t
      code = 0
      r = 0.0_wp
      if (a == 0.0_wp) then
         if (b > 0.0_wp) then
            r = a**b
         else if (b == 0.0_wp) then
            r = 1.0_wp
         else
            code = fail_zero_power
         end if
         return
      end if
      if (a < 0.0_wp .and. b /= aint(b)) then
         code = fail_power
         return
      end if
      t = log(abs(a))
      if (t == 0.0_wp) then
         r = a**b
      else if (abs(b) > 1.0e300_wp) then
         ! |a^b| is 0 (underflow) or beyond huge
         if ((t > 0.0_wp) .eqv. (b > 0.0_wp)) code = fail_overflow
      else if (b*t > power_limit) then
         code = fail_overflow
      else
         r = a**b
      end if
   end subroutine pow_1

   ! a^n for an integer n, `bound` = exp(power_limit/|n|)
   pure subroutine powi_1(a, n, bound, r, code)
      real(wp), intent(in) :: a, bound
      integer, intent(in) :: n
      real(wp), intent(out) :: r
      integer, intent(out) :: code
      code = 0
      r = 0.0_wp
      if (n == 0) then
         r = 1.0_wp
      else if (a == 0.0_wp) then
         if (n > 0) then
            r = a**n
         else
            code = fail_zero_power
         end if
      else if (n > 0) then
         if (abs(a) <= bound) then
            r = a**n
         else
            code = fail_overflow
         end if
      else if (abs(a) > bound) then
         r = (1.0_wp/a)**(-n)  ! underflows, finite
      else if (abs(a) < 1.0_wp/bound) then
         code = fail_overflow
      else
         r = a**n
      end if
   end subroutine powi_1

   ! one operand (n, bound: the integer power's)
   pure subroutine unary_1(op, n, bound, a, r, code)
      integer, intent(in) :: op, n
      real(wp), intent(in) :: bound, a
      real(wp), intent(out) :: r
      integer, intent(out) :: code
      code = 0
      r = 0.0_wp
      select case (op)
      case (op_neg); r = -a
      case (op_abs); r = abs(a)
      case (op_sin); r = sin(a)
      case (op_cos); r = cos(a)
      case (op_tan); r = tan(a)
      case (op_tanh); r = tanh(a)
      case (op_atan); r = atan(a)
      case (op_exp)
         if (a <= exp_limit) then
            r = exp(a)
         else
            code = fail_overflow
         end if
      case (op_log)
         if (a > 0.0_wp) then
            r = log(a)
         else
            code = fail_log
         end if
      case (op_sqrt)
         if (a >= 0.0_wp) then
            r = sqrt(a)
         else
            code = fail_sqrt
         end if
      case (op_sinh)
         if (abs(a) <= hyperbolic_limit) then
            r = sinh(a)
         else
            code = fail_overflow
         end if
      case (op_cosh)
         if (abs(a) <= hyperbolic_limit) then
            r = cosh(a)
         else
            code = fail_overflow
         end if
      case (op_powi)
         call powi_1(a, n, bound, r, code)
      end select
   end subroutine unary_1

   ! two operands
   pure subroutine binary_1(op, a, b, r, code)
      integer, intent(in) :: op
      real(wp), intent(in) :: a, b
      real(wp), intent(out) :: r
      integer, intent(out) :: code
      code = 0
      r = 0.0_wp
      select case (op)
      case (op_add); call add_1(a, b, r, code)
      case (op_sub); call add_1(a, -b, r, code)
      case (op_mul); call mul_1(a, b, r, code)
      case (op_div); call div_1(a, b, r, code)
      case (op_pow); call pow_1(a, b, r, code)
      case (op_atan2); r = atan2(a, b)
      end select
   end subroutine binary_1

   ! whether x op y is safe at every node from the operands' largest and smallest magnitudes
   pure logical function binary_safe(op, x_max, y_max, y_min) result(safe)
      integer, intent(in) :: op
      real(wp), intent(in) :: x_max, y_max, y_min
      select case (op)
      case (op_add, op_sub)
         safe = x_max <= half_huge .and. y_max <= half_huge
      case (op_mul)
         safe = x_max <= 1.0_wp .or. y_max <= 1.0_wp
         if (.not. safe) safe = x_max <= half_huge/y_max
      case (op_div)
         safe = y_min >= 1.0_wp
         if (.not. safe .and. y_min > 0.0_wp) safe = x_max <= y_min*half_huge
      case (op_atan2)
         safe = .true.
      case default
         safe = .false.
      end select
   end function binary_safe

   ! ---------------------------------------------------------------------------------------
   ! kernels: one instruction over all nodes; a checked fast loop, else node by node

   pure subroutine mark(fail, i, code)
      type(failure_t), intent(inout) :: fail
      integer, intent(in) :: i, code
      if (.not. allocated(fail%failed)) return
      fail%failed(i) = .true.
      if (fail%first == 0 .or. i < fail%first) then
         fail%first = i
         fail%code = code
         fail%instruction = fail%current
      end if
   end subroutine mark

   ! a scalar operation failed: every node fails
   pure subroutine mark_all(fail, code)
      type(failure_t), intent(inout) :: fail
      integer, intent(in) :: code
      fail%failed = .true.
      if (fail%first /= 1) then
         fail%first = 1
         fail%code = code
         fail%instruction = fail%current
      end if
   end subroutine mark_all

   ! x = x op y
   pure subroutine binary_vv(op, x, y, fail)
      integer, intent(in) :: op
      real(wp), intent(inout) :: x(:)
      real(wp), intent(in) :: y(:)
      type(failure_t), intent(inout) :: fail
      integer :: i, code
      real(wp) :: r
      if (op == op_pow) then
         do i = 1, size(x)
            call pow_1(x(i), y(i), r, code)
            x(i) = r
            if (code /= 0) call mark(fail, i, code)
         end do
         return
      end if
      if (binary_safe(op, maxval(abs(x)), maxval(abs(y)), minval(abs(y)))) then
         select case (op)
         case (op_add); x = x + y
         case (op_sub); x = x - y
         case (op_mul); x = x*y
         case (op_div); x = x/y
         case (op_atan2); x = atan2(x, y)
         end select
         return
      end if
      do i = 1, size(x)
         call binary_1(op, x(i), y(i), r, code)
         x(i) = r
         if (code /= 0) call mark(fail, i, code)
      end do
   end subroutine binary_vv

   ! x = x op s
   pure subroutine binary_vs(op, x, s, fail)
      integer, intent(in) :: op
      real(wp), intent(inout) :: x(:)
      real(wp), intent(in) :: s
      type(failure_t), intent(inout) :: fail
      integer :: i, code
      real(wp) :: r
      if (op == op_pow) then
         do i = 1, size(x)
            call pow_1(x(i), s, r, code)
            x(i) = r
            if (code /= 0) call mark(fail, i, code)
         end do
         return
      end if
      if (binary_safe(op, maxval(abs(x)), abs(s), abs(s))) then
         select case (op)
         case (op_add); x = x + s
         case (op_sub); x = x - s
         case (op_mul); x = x*s
         case (op_div); x = x/s
         case (op_atan2); x = atan2(x, s)
         end select
         return
      end if
      do i = 1, size(x)
         call binary_1(op, x(i), s, r, code)
         x(i) = r
         if (code /= 0) call mark(fail, i, code)
      end do
   end subroutine binary_vs

   ! r = s op y
   pure subroutine binary_sv(op, s, y, r, fail)
      integer, intent(in) :: op
      real(wp), intent(in) :: s
      real(wp), intent(in) :: y(:)
      real(wp), intent(out) :: r(:)
      type(failure_t), intent(inout) :: fail
      integer :: i, code
      if (op == op_pow) then
         do i = 1, size(y)
            call pow_1(s, y(i), r(i), code)
            if (code /= 0) call mark(fail, i, code)
         end do
         return
      end if
      if (binary_safe(op, abs(s), maxval(abs(y)), minval(abs(y)))) then
         select case (op)
         case (op_add); r = s + y
         case (op_sub); r = s - y
         case (op_mul); r = s*y
         case (op_div); r = s/y
         case (op_atan2); r = atan2(s, y)
         end select
         return
      end if
      do i = 1, size(y)
         call binary_1(op, s, y(i), r(i), code)
         if (code /= 0) call mark(fail, i, code)
      end do
   end subroutine binary_sv

   ! x = f(x)
   pure subroutine unary_v(op, n, bound, x, fail)
      integer, intent(in) :: op, n
      real(wp), intent(in) :: bound
      real(wp), intent(inout) :: x(:)
      type(failure_t), intent(inout) :: fail
      integer :: i, code
      real(wp) :: r
      logical :: safe
      select case (op)
      case (op_neg); x = -x; return
      case (op_abs); x = abs(x); return
      case (op_sin); x = sin(x); return
      case (op_cos); x = cos(x); return
      case (op_tan); x = tan(x); return
      case (op_tanh); x = tanh(x); return
      case (op_atan); x = atan(x); return
      case (op_exp)
         if (maxval(x) <= exp_limit) then
            x = exp(x)
            return
         end if
      case (op_log)
         if (minval(x) > 0.0_wp) then
            x = log(x)
            return
         end if
      case (op_sqrt)
         if (minval(x) >= 0.0_wp) then
            x = sqrt(x)
            return
         end if
      case (op_sinh, op_cosh)
         if (maxval(abs(x)) <= hyperbolic_limit) then
            if (op == op_sinh) then
               x = sinh(x)
            else
               x = cosh(x)
            end if
            return
         end if
      case (op_powi)
         if (n == 0) then
            x = 1.0_wp
            return
         end if
         safe = maxval(abs(x)) <= bound
         if (n < 0) safe = safe .and. minval(abs(x)) >= 1.0_wp/bound
         if (safe) then
            x = x**n
            return
         end if
      end select
      do i = 1, size(x)
         call unary_1(op, n, bound, x(i), r, code)
         x(i) = r
         if (code /= 0) call mark(fail, i, code)
      end do
   end subroutine unary_v
end module hillstab_core_expression_ops

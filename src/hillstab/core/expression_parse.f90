!> The parser of hillstab_core_expression: a text and the variables' names to postfix
!> instructions with the parts of numbers and `pi` alone folded (`compile_expression`), by
!> recursive descent over the tokens; every error is err_input with its column. An internal
!> module: users take hillstab_core_expression (`parse_expression`).
module hillstab_core_expression_parse
   use hillstab_core_kinds, only: wp, pi
   use hillstab_core_error, only: error_t, set_error, err_input
   use hillstab_core_text, only: integer_text, lower_case
   use hillstab_core_expression_ops
   implicit none
   private
   public :: compiled_t, compile_expression

   !> The postfix code of an expression, as `compile_expression` makes it.
   type :: compiled_t
      integer :: n_code = 0                  !! number of instructions
      integer :: depth = 0                   !! largest stack depth of the evaluation
      integer, allocatable :: op(:)          !! instruction codes
      integer, allocatable :: arg(:)         !! variable index or integer exponent
      integer, allocatable :: column(:)      !! column of each instruction's token
      real(wp), allocatable :: constant(:)   !! constant value, or the integer power's bound
      character(len=name_length), allocatable :: names(:)  !! the variables' names
   end type compiled_t

   ! the parser's state
   type :: parser_t
      character(len=:), allocatable :: text
      integer :: offset = 0                  ! column of text(1:1) minus 1
      integer :: n_tokens = 0, pos = 1, nesting = 0
      integer, allocatable :: kind(:), first(:), last(:)
      real(wp), allocatable :: number(:)
      character(len=name_length), allocatable :: names(:)
      ! the code being emitted and the compile-time stack (constant or not)
      integer :: n_code = 0, n_stack = 0, depth = 0
      integer, allocatable :: op(:), arg(:), column(:)
      real(wp), allocatable :: constant(:)
      logical, allocatable :: stack_constant(:)
      type(error_t), allocatable :: error
   end type parser_t

contains

   !> Compile `text` into postfix code `compiled` for the variables `names` (blanks around each ignored).
   !> On an error, `error` (code err_input) says what was expected where, by column.
   pure subroutine compile_expression(text, names, compiled, error, first_column)
      character(len=*), intent(in) :: text             !! the expression
      character(len=*), intent(in) :: names(:)         !! the variables' names, in the order of evaluation
      type(compiled_t), intent(out) :: compiled   !! the postfix code
      type(error_t), allocatable, intent(out) :: error !! err_input with the column, or unallocated
      integer, intent(in), optional :: first_column    !! column of text(1:1) in messages (default 1)
      type(parser_t) :: p
      integer :: i, j
      character(len=:), allocatable :: name
      allocate (p%names(size(names)))
      do i = 1, size(names)
         name = trim(adjustl(names(i)))
         if (len(name) == 0) then
            call set_error(error, err_input, "name "//integer_text(i)//" of the list of names is empty")
            return
         end if
         if (len(name) > name_length) then
            call set_error(error, err_input, "name '"//name//"' is longer than "//integer_text(name_length)// &
               " characters")
            return
         end if
         if (.not. is_name(name)) then
            call set_error(error, err_input, "'"//name//"' is no name (letters, digits and underscores, "// &
               "starting with a letter)")
            return
         end if
         if (is_reserved(name)) then
            call set_error(error, err_input, "'"//name//"' cannot name a variable: it is "//reserved_what(name))
            return
         end if
         do j = 1, i - 1
            if (p%names(j) == name) then
               call set_error(error, err_input, "name '"//name//"' is given twice in the list of names")
               return
            end if
         end do
         p%names(i) = name
      end do
      p%text = text
      if (present(first_column)) p%offset = first_column - 1
      call tokenize(p)
      if (allocated(p%error)) then
         call move_alloc(p%error, error)
         return
      end if
      if (p%n_tokens == 1) then
         call set_error(error, err_input, "empty expression at column "//integer_text(p%offset + 1)// &
            "; expected a number, a name, a function or '('")
         return
      end if
      allocate (p%op(p%n_tokens), p%arg(p%n_tokens), p%column(p%n_tokens), p%constant(p%n_tokens), &
         p%stack_constant(p%n_tokens))
      p%arg = 0
      p%constant = 0.0_wp
      call parse_sum(p)
      if (.not. allocated(p%error)) then
         select case (p%kind(p%pos))
         case (tk_end)
         case (tk_rparen)
            call fail(p, "unbalanced parentheses: ')' at column "//integer_text(token_column(p, p%pos))// &
               " has no '('")
         case default
            call fail(p, "unexpected "//token_text(p, p%pos)//" at column "//integer_text(token_column(p, p%pos))// &
               "; expected an operator or the end of the expression")
         end select
      end if
      if (allocated(p%error)) then
         call move_alloc(p%error, error)
         return
      end if
      compiled%n_code = p%n_code
      compiled%depth = p%depth
      compiled%op = p%op(1:p%n_code)
      compiled%arg = p%arg(1:p%n_code)
      compiled%column = p%column(1:p%n_code)
      compiled%constant = p%constant(1:p%n_code)
      call move_alloc(p%names, compiled%names)
   end subroutine compile_expression

   ! split the text into tokens; the last is tk_end
   pure subroutine tokenize(p)
      type(parser_t), intent(inout) :: p
      integer :: i, n, start, kind
      character :: c
      n = len(p%text)
      allocate (p%kind(n + 1), p%first(n + 1), p%last(n + 1), p%number(n + 1))
      p%number = 0.0_wp
      i = 1
      do
         do while (i <= n)
            if (p%text(i:i) /= " " .and. p%text(i:i) /= achar(9)) exit
            i = i + 1
         end do
         p%n_tokens = p%n_tokens + 1
         p%first(p%n_tokens) = i
         p%last(p%n_tokens) = i
         if (i > n) then
            p%kind(p%n_tokens) = tk_end
            exit
         end if
         c = p%text(i:i)
         start = i
         select case (c)
         case ("0":"9", ".")
            call scan_number(p, start, i)
            if (allocated(p%error)) return
            kind = tk_number
         case ("a":"z", "A":"Z")
            do while (i < n)
               if (.not. is_name_character(p%text(i + 1:i + 1))) exit
               i = i + 1
            end do
            kind = tk_name
         case ("+"); kind = tk_plus
         case ("-"); kind = tk_minus
         case ("*")
            kind = tk_star
            if (i < n) then
               if (p%text(i + 1:i + 1) == "*") then
                  kind = tk_caret
                  i = i + 1
               end if
            end if
         case ("/"); kind = tk_slash
         case ("^"); kind = tk_caret
         case ("("); kind = tk_lparen
         case (")"); kind = tk_rparen
         case (","); kind = tk_comma
         case default
            call fail(p, "unexpected character '"//c//"' at column "//integer_text(p%offset + i)// &
               "; expected a number, a name, an operator or a parenthesis")
            return
         end select
         p%kind(p%n_tokens) = kind
         p%last(p%n_tokens) = i
         i = i + 1
      end do
   end subroutine tokenize

   ! a number from text(start:): digits [. digits] [e|E|d|D [+|-] digits]; `last` its end
   pure subroutine scan_number(p, start, last)
      type(parser_t), intent(inout) :: p
      integer, intent(in) :: start
      integer, intent(out) :: last
      integer :: i, n, mantissa_digits, exponent10, exponent_sign, int_digits, first_significant, k
      character(len=:), allocatable :: digits
      character(len=40) :: significant
      character :: c
      logical :: seen_point
      integer :: ios
      real(wp) :: x
      n = len(p%text)
      i = start
      mantissa_digits = 0
      int_digits = 0
      seen_point = .false.
      digits = ""
      do while (i <= n)
         c = p%text(i:i)
         if (c >= "0" .and. c <= "9") then
            mantissa_digits = mantissa_digits + 1
            if (.not. seen_point) int_digits = int_digits + 1
            digits = digits//c
         else if (c == "." .and. .not. seen_point) then
            seen_point = .true.
         else
            exit
         end if
         i = i + 1
      end do
      last = i - 1
      if (mantissa_digits == 0) then
         call fail(p, "malformed number '"//p%text(start:last)//"' at column "//integer_text(p%offset + start)// &
            "; expected digits")
         return
      end if
      exponent10 = 0
      if (i <= n) then
         c = p%text(i:i)
         if (c == "e" .or. c == "E" .or. c == "d" .or. c == "D") then
            i = i + 1
            exponent_sign = 1
            if (i <= n) then
               if (p%text(i:i) == "+" .or. p%text(i:i) == "-") then
                  if (p%text(i:i) == "-") exponent_sign = -1
                  i = i + 1
               end if
            end if
            k = 0
            do while (i <= n)
               c = p%text(i:i)
               if (c < "0" .or. c > "9") exit
               if (exponent10 < 100000) exponent10 = 10*exponent10 + (iachar(c) - iachar("0"))
               k = k + 1
               i = i + 1
            end do
            if (k == 0) then
               call fail(p, "malformed number '"//p%text(start:i - 1)//"' at column "//integer_text(p%offset + start)// &
                  "; expected the digits of the exponent")
               return
            end if
            exponent10 = exponent_sign*exponent10
            last = i - 1
         end if
      end if
      ! decimal exponent of the first significant digit: refuse what would overflow, unread
      first_significant = verify(digits, "0")
      if (first_significant > 0) then
         exponent10 = exponent10 + int_digits - first_significant
         significant = digits(first_significant:)
         if (exponent10 > 308 .or. (exponent10 == 308 .and. significant >= overflow_digits)) then
            call fail(p, "number '"//p%text(start:last)//"' at column "//integer_text(p%offset + start)// &
               " is too large (the largest is about 1.797e308)")
            return
         end if
      end if
      read (p%text(start:last), *, iostat=ios) x
      if (ios /= 0) then
         call fail(p, "malformed number '"//p%text(start:last)//"' at column "//integer_text(p%offset + start))
         return
      end if
      p%number(p%n_tokens) = x
   end subroutine scan_number

   ! sum := product {(+|-) product}
   pure recursive subroutine parse_sum(p)
      type(parser_t), intent(inout) :: p
      integer :: op, column
      call parse_product(p)
      do while (.not. allocated(p%error))
         select case (p%kind(p%pos))
         case (tk_plus); op = op_add
         case (tk_minus); op = op_sub
         case default; return
         end select
         column = token_column(p, p%pos)
         p%pos = p%pos + 1
         call parse_product(p)
         if (allocated(p%error)) return
         call emit_binary(p, op, column)
      end do
   end subroutine parse_sum

   ! product := unary {(*|/) unary}
   pure recursive subroutine parse_product(p)
      type(parser_t), intent(inout) :: p
      integer :: op, column
      call parse_unary(p)
      do while (.not. allocated(p%error))
         select case (p%kind(p%pos))
         case (tk_star); op = op_mul
         case (tk_slash); op = op_div
         case default; return
         end select
         column = token_column(p, p%pos)
         p%pos = p%pos + 1
         call parse_unary(p)
         if (allocated(p%error)) return
         call emit_binary(p, op, column)
      end do
   end subroutine parse_product

   ! unary := (-|+) unary | power
   pure recursive subroutine parse_unary(p)
      type(parser_t), intent(inout) :: p
      integer :: column, kind
      kind = p%kind(p%pos)
      if (kind /= tk_minus .and. kind /= tk_plus) then
         call parse_power(p)
         return
      end if
      column = token_column(p, p%pos)
      p%nesting = p%nesting + 1
      if (p%nesting > max_nesting) then
         call fail(p, "more than "//integer_text(max_nesting)//" nested signs and parentheses at column "// &
            integer_text(column))
         return
      end if
      p%pos = p%pos + 1
      call parse_unary(p)
      p%nesting = p%nesting - 1
      if (allocated(p%error)) return
      if (kind == tk_minus) call emit_unary(p, op_neg, column)
   end subroutine parse_unary

   ! power := primary [^ unary]   (right associative through unary)
   pure recursive subroutine parse_power(p)
      type(parser_t), intent(inout) :: p
      integer :: column
      call parse_primary(p)
      if (allocated(p%error)) return
      if (p%kind(p%pos) /= tk_caret) return
      column = token_column(p, p%pos)
      p%pos = p%pos + 1
      call parse_unary(p)
      if (allocated(p%error)) return
      call emit_binary(p, op_pow, column)
   end subroutine parse_power

   ! primary := number | pi | variable | function ( sum {, sum} ) | ( sum )
   pure recursive subroutine parse_primary(p)
      type(parser_t), intent(inout) :: p
      integer :: column, f, j, n_args, parenthesis
      character(len=:), allocatable :: name
      logical :: ok
      column = token_column(p, p%pos)
      select case (p%kind(p%pos))
      case (tk_number)
         call emit(p, op_const, 0, p%number(p%pos), column, .true.)
         p%pos = p%pos + 1
      case (tk_name)
         name = p%text(p%first(p%pos):p%last(p%pos))
         f = function_index(name)
         if (f > 0) then
            if (p%kind(p%pos + 1) /= tk_lparen) then
               call fail(p, "function '"//name//"' at column "//integer_text(column)// &
                  " needs its argument in parentheses: "//trim(function_names(f))//"("// &
                  repeat("x, ", function_arity(f) - 1)//"x)")
               return
            end if
            parenthesis = token_column(p, p%pos + 1)
            call enter(p, parenthesis, ok)
            if (.not. ok) return
            p%pos = p%pos + 2
            n_args = 0
            if (p%kind(p%pos) /= tk_rparen) then
               do
                  call parse_sum(p)
                  if (allocated(p%error)) return
                  n_args = n_args + 1
                  if (p%kind(p%pos) /= tk_comma) exit
                  p%pos = p%pos + 1
               end do
            end if
            call close_parenthesis(p, parenthesis, "an operator, ',' or ')'", ok)
            if (.not. ok) return
            if (n_args /= function_arity(f)) then
               call fail(p, "function '"//name//"' at column "//integer_text(column)//" takes "// &
                  arguments_text(function_arity(f))//", found "//integer_text(n_args))
               return
            end if
            if (function_arity(f) == 1) then
               call emit_unary(p, function_ops(f), column)
            else
               call emit_binary(p, function_ops(f), column)
            end if
         else if (lower_case(name) == "pi") then
            call emit(p, op_const, 0, pi, column, .true.)
            p%pos = p%pos + 1
         else
            j = variable_index(p%names, name)
            if (j == 0) then
               call fail(p, "unknown name '"//name//"' at column "//integer_text(column)//"; "// &
                  names_text(p%names, name))
               return
            end if
            call emit(p, op_var, j, 0.0_wp, column, .false.)
            p%pos = p%pos + 1
         end if
      case (tk_lparen)
         if (p%kind(p%pos + 1) == tk_rparen) then
            call fail(p, "empty parentheses at column "//integer_text(column)// &
               "; expected a number, a name, a function or '('")
            return
         end if
         call enter(p, column, ok)
         if (.not. ok) return
         p%pos = p%pos + 1
         call parse_sum(p)
         if (allocated(p%error)) return
         call close_parenthesis(p, column, "an operator or ')'", ok)
      case default
         call missing_operand(p)
      end select
   end subroutine parse_primary

   ! one more level of parentheses (`ok` false with an error beyond max_nesting)
   pure subroutine enter(p, column, ok)
      type(parser_t), intent(inout) :: p
      integer, intent(in) :: column
      logical, intent(out) :: ok
      p%nesting = p%nesting + 1
      ok = p%nesting <= max_nesting
      if (.not. ok) call fail(p, "more than "//integer_text(max_nesting)// &
         " nested signs and parentheses at column "//integer_text(column))
   end subroutine enter

   ! the ')' closing the '(' opened at `column` (`ok` false with an error); `expected`
   ! names what else could have followed
   pure subroutine close_parenthesis(p, column, expected, ok)
      type(parser_t), intent(inout) :: p
      integer, intent(in) :: column
      character(len=*), intent(in) :: expected
      logical, intent(out) :: ok
      ok = p%kind(p%pos) == tk_rparen
      if (ok) then
         p%pos = p%pos + 1
         p%nesting = p%nesting - 1
      else if (p%kind(p%pos) == tk_end) then
         call fail(p, "unbalanced parentheses: '(' at column "//integer_text(column)//" is not closed")
      else
         call fail(p, "unexpected "//token_text(p, p%pos)//" at column "//integer_text(token_column(p, p%pos))// &
            "; expected "//expected)
      end if
   end subroutine close_parenthesis

   ! the message for a token where an operand was expected
   pure subroutine missing_operand(p)
      type(parser_t), intent(inout) :: p
      character(len=*), parameter :: expected = "; expected a number, a name, a function or '('"
      integer :: column, previous
      column = token_column(p, p%pos)
      previous = p%pos - 1
      select case (p%kind(p%pos))
      case (tk_end)
         call fail(p, "missing operand at the end of the expression, after "//token_text(p, previous)// &
            " at column "//integer_text(token_column(p, previous))//expected)
      case (tk_star, tk_slash, tk_caret)
         if (previous >= 1) then
            if (is_operator(p%kind(previous))) then
               call fail(p, "two operators in a row: "//token_text(p, p%pos)//" at column "// &
                  integer_text(column)//" after "//token_text(p, previous)//" at column "// &
                  integer_text(token_column(p, previous))//expected)
               return
            end if
         end if
         call fail(p, "missing operand before "//token_text(p, p%pos)//" at column "//integer_text(column)//expected)
      case default
         call fail(p, "missing operand before "//token_text(p, p%pos)//" at column "//integer_text(column)//expected)
      end select
   end subroutine missing_operand

   pure logical function is_operator(kind)
      integer, intent(in) :: kind
      is_operator = kind == tk_plus .or. kind == tk_minus .or. kind == tk_star .or. kind == tk_slash &
         .or. kind == tk_caret
   end function is_operator

   pure subroutine fail(p, message)
      type(parser_t), intent(inout) :: p
      character(len=*), intent(in) :: message
      if (.not. allocated(p%error)) call set_error(p%error, err_input, message)
   end subroutine fail

   pure integer function token_column(p, i)
      type(parser_t), intent(in) :: p
      integer, intent(in) :: i
      token_column = p%offset + p%first(i)
   end function token_column

   ! a token as quoted in messages
   pure function token_text(p, i) result(text)
      type(parser_t), intent(in) :: p
      integer, intent(in) :: i
      character(len=:), allocatable :: text
      if (p%kind(i) == tk_end) then
         text = "the end"
      else
         text = "'"//p%text(p%first(i):p%last(i))//"'"
      end if
   end function token_text

   pure function arguments_text(n) result(text)
      integer, intent(in) :: n
      character(len=:), allocatable :: text
      text = integer_text(n)//" argument"
      if (n /= 1) text = text//"s"
   end function arguments_text

   ! ---------------------------------------------------------------------------------------
   ! emitting postfix code, folding constants

   pure subroutine emit(p, op, arg, constant, column, is_constant)
      type(parser_t), intent(inout) :: p
      integer, intent(in) :: op, arg, column
      real(wp), intent(in) :: constant
      logical, intent(in) :: is_constant
      p%n_code = p%n_code + 1
      p%op(p%n_code) = op
      p%arg(p%n_code) = arg
      p%constant(p%n_code) = constant
      p%column(p%n_code) = column
      p%n_stack = p%n_stack + 1
      p%stack_constant(p%n_stack) = is_constant
      p%depth = max(p%depth, p%n_stack)
   end subroutine emit

   ! a function of one argument (or the sign): folded when the argument is a constant
   pure subroutine emit_unary(p, op, column)
      type(parser_t), intent(inout) :: p
      integer, intent(in) :: op, column
      real(wp) :: r
      integer :: code
      if (p%stack_constant(p%n_stack)) then
         call unary_1(op, 0, 0.0_wp, p%constant(p%n_code), r, code)
         if (code /= 0) then
            call fail(p, failure_text(code)//" at column "//integer_text(column)//" (a constant part of the expression)")
            return
         end if
         p%constant(p%n_code) = r
         p%column(p%n_code) = column
      else
         p%n_code = p%n_code + 1
         p%op(p%n_code) = op
         p%arg(p%n_code) = 0
         p%constant(p%n_code) = 0.0_wp
         p%column(p%n_code) = column
      end if
   end subroutine emit_unary

   ! an operator of two operands: folded when both are constants; x^n for a constant
   ! integer n compiled as an integer power
   pure subroutine emit_binary(p, op, column)
      type(parser_t), intent(inout) :: p
      integer, intent(in) :: op, column
      real(wp) :: r, b
      integer :: code, n
      if (p%stack_constant(p%n_stack) .and. p%stack_constant(p%n_stack - 1)) then
         call binary_1(op, p%constant(p%n_code - 1), p%constant(p%n_code), r, code)
         if (code /= 0) then
            call fail(p, failure_text(code)//" at column "//integer_text(column)//" (a constant part of the expression)")
            return
         end if
         p%n_code = p%n_code - 1
         p%n_stack = p%n_stack - 1
         p%constant(p%n_code) = r
         p%column(p%n_code) = column
         return
      end if
      if (op == op_pow .and. p%stack_constant(p%n_stack)) then
         b = p%constant(p%n_code)
         if (abs(b) <= max_integer_power) then
            if (b == aint(b)) then
               n = nint(b)
               p%n_stack = p%n_stack - 1
               p%op(p%n_code) = op_powi
               p%arg(p%n_code) = n
               p%constant(p%n_code) = 0.0_wp
               if (n /= 0) p%constant(p%n_code) = exp(power_limit/abs(n))
               p%column(p%n_code) = column
               return
            end if
         end if
      end if
      p%n_code = p%n_code + 1
      p%op(p%n_code) = op
      p%arg(p%n_code) = 0
      p%constant(p%n_code) = 0.0_wp
      p%column(p%n_code) = column
      p%n_stack = p%n_stack - 1
      p%stack_constant(p%n_stack) = .false.
   end subroutine emit_binary
end module hillstab_core_expression_parse

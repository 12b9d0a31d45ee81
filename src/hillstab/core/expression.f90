!> Arithmetic expressions written by users, parsed once and evaluated over many nodes:
!> a coefficient such as `-g/l + A*w^2/l*cos(w*t)` with the names `t, g, l, A, w`.
!>
!> Syntax: numbers (`2`, `2.`, `.5`, `1e-3`, `1.5D+2`), `+ - * /`, `^` (or `**`; right
!> associative: `2^3^2` = 512), unary `-` and `+` (looser than `^`: `-x^2` = −(x²), and
!> allowed after an operator: `2*-3` = −6), parentheses, the constant `pi`, the functions
!> `sin cos tan exp log sqrt abs sinh cosh tanh atan` (one argument) and `atan2(y, x)`,
!> and the caller's named variables. Variable names are letters, digits and underscores
!> starting with a letter, case-sensitive (`A` and `a` are two names); function names and
!> `pi` are read in any case, and no variable may take their name in any case. Blanks and
!> tabs between tokens are ignored; columns in messages are 1-based character positions.
!>
!> Compiled form: postfix instructions (`expression_t`), with every part made of numbers
!> and `pi` alone folded into one constant, in the written order (`2*pi*50*t` is three
!> instructions; `t*2*pi` keeps its two products, so that the value is bit for bit the
!> written one), and `x^n` for a constant integer |n| ≤ 64 compiled as an integer power.
!>
!> Evaluation: `evaluate` runs each instruction over all nodes at once on a small stack
!> of vectors; the first variables of the list vary over the nodes (columns of `nodes`, or
!> the one vector `t`), the others are scalars, and a part that depends on scalars alone
!> is computed once, as a scalar. Every operation is checked before it is done, so that
!> no overflow, division by zero or invalid operation is ever raised (the code runs under
!> `-ffpe-trap=invalid,zero,overflow`): a result that would not be finite is reported with
!> the first node where it happens, the reason and the column of the operation, and those
!> nodes of the result are NaN. The limits are conservative by a hair: exp(x) is refused
!> above log(huge), sinh and cosh above |x| = 710.475, a power whose logarithm exceeds
!> 709.78 (within 0.3 % of huge); sums, products and quotients are exact to the overflow
!> threshold. The compiled form is read-only while it is evaluated: threads evaluate one
!> expression at once, each with its own `expression_work_t` (or none: then a local one).
!>
!>```fortran
!> type(expression_t) :: q
!> type(error_t), allocatable :: error
!> call parse_expression("-g/l + A*w^2/l*cos(w*t)", ["t", "g", "l", "A", "w"], q, error)
!> call q%evaluate(t_nodes, q_values, error, scalars=[9.81_wp, 0.2_wp, 0.005_wp, 314.16_wp])
!>```
module hillstab_core_expression
   use hillstab_core_kinds, only: wp, int64, pi
   use hillstab_core_error, only: error_t, set_error, err_input, err_invalid_parameter, err_overflow
   use hillstab_core_text, only: integer_text, lower_case
   implicit none
   private
   public :: expression_t, expression_work_t, parse_expression, parse_parameters, name_length

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

   !> A parsed expression: postfix instructions with constants folded. Built by
   !> `parse_expression`; read-only while it is evaluated.
   type :: expression_t
      private
      integer :: n_code = 0                       !! number of instructions
      integer :: depth = 0                        !! largest stack depth of the evaluation
      integer :: n_variables = 0                  !! number of named variables
      integer, allocatable :: op(:)               !! instruction codes
      integer, allocatable :: arg(:)              !! variable index or integer exponent
      integer, allocatable :: column(:)           !! column of each instruction's token
      real(wp), allocatable :: constant(:)        !! constant value, or the integer power's bound
      character(len=name_length), allocatable :: names(:)  !! the variables' names
   contains
      !> Evaluate over nodes: `call e%evaluate(nodes, result, error [, scalars, work, failed_node])`.
      generic :: evaluate => evaluate_columns, evaluate_vector
      procedure, private :: evaluate_columns, evaluate_vector
      !> The value at one point, NaN when it is not finite: `e%value(x)`.
      procedure :: value => expression_value
      !> Whether the expression uses the named variable.
      procedure :: uses
      !> Whether the expression is provably affine in the named variable.
      procedure :: affine_in
      !> Whether the expression uses no variable.
      procedure :: is_constant
      !> The number of compiled instructions.
      procedure :: instruction_count
      !> The number of named variables.
      procedure :: variable_count
   end type expression_t

   !> Work arrays of one evaluating thread (the stack of vectors), kept between calls.
   type :: expression_work_t
      private
      real(wp), allocatable :: stack(:, :)  !! (nodes, stack depth)
   end type expression_work_t

   ! nodes where an evaluation failed, and the first of them
   type :: failure_t
      integer :: first = 0        ! first failed node (0: none)
      integer :: code = 0         ! fail_* of the first failed node
      integer :: instruction = 0  ! its instruction
      integer :: current = 0      ! the instruction being run
      logical, allocatable :: failed(:)
   end type failure_t

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

   ! ---------------------------------------------------------------------------------------
   ! parsing

   !> Parse `text` into `expression` for the variables `names` (blanks around each ignored).
   !> On an error, `error` (code err_input) says what was expected where, by column.
   pure subroutine parse_expression(text, names, expression, error, first_column)
      character(len=*), intent(in) :: text             !! the expression
      character(len=*), intent(in) :: names(:)         !! the variables' names, in the order of evaluation
      type(expression_t), intent(out) :: expression    !! the compiled expression
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
      expression%n_code = p%n_code
      expression%depth = p%depth
      expression%n_variables = size(names)
      expression%op = p%op(1:p%n_code)
      expression%arg = p%arg(1:p%n_code)
      expression%column = p%column(1:p%n_code)
      expression%constant = p%constant(1:p%n_code)
      call move_alloc(p%names, expression%names)
   end subroutine parse_expression

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

   ! ---------------------------------------------------------------------------------------
   ! evaluation

   !> Evaluate at `size(result)` nodes: the first `size(nodes, 2)` variables are the
   !> columns of `nodes(n_nodes, :)`, the rest the `scalars` in order. A non-finite result
   !> (or a non-finite value given) allocates `error` (err_overflow or
   !> err_invalid_parameter) naming the first such node, the reason and the column;
   !> those nodes of `result` are NaN. Pure, with the expression read-only.
   pure subroutine evaluate_columns(self, nodes, result, error, scalars, work, failed_node)
      class(expression_t), intent(in) :: self            !! the parsed expression
      real(wp), intent(in) :: nodes(:, :)                 !! (n_nodes, m): the first m variables at each node
      real(wp), intent(out) :: result(:)                  !! (n_nodes) the values
      type(error_t), allocatable, intent(out) :: error    !! the first node where the value is not finite
      real(wp), intent(in), optional :: scalars(:)        !! the other variables (n_variables − m), one value each
      type(expression_work_t), intent(inout), optional :: work  !! this thread's work arrays, reused between calls
      integer, intent(out), optional :: failed_node       !! the first node not finite, 0 when all are
      type(expression_work_t) :: local
      integer :: failed
      if (size(nodes, 1) /= size(result)) then
         call set_error(error, err_invalid_parameter, "evaluate: "//integer_text(size(nodes, 1))// &
            " nodes for "//integer_text(size(result))//" results")
         if (present(failed_node)) failed_node = 0
         return
      end if
      if (present(work)) then
         call evaluate_core(self, size(result), size(nodes, 2), nodes, scalars, result, work, error, failed)
      else
         call evaluate_core(self, size(result), size(nodes, 2), nodes, scalars, result, local, error, failed)
      end if
      if (present(failed_node)) failed_node = failed
   end subroutine evaluate_columns

   !> Evaluate at the nodes `x` of the first variable, the others being the `scalars`.
   pure subroutine evaluate_vector(self, x, result, error, scalars, work, failed_node)
      class(expression_t), intent(in) :: self            !! the parsed expression
      real(wp), intent(in) :: x(:)                        !! the first variable at each node
      real(wp), intent(out) :: result(:)                  !! (size(x)) the values
      type(error_t), allocatable, intent(out) :: error    !! the first node where the value is not finite
      real(wp), intent(in), optional :: scalars(:)        !! the other variables (n_variables − 1), one value each
      type(expression_work_t), intent(inout), optional :: work  !! this thread's work arrays, reused between calls
      integer, intent(out), optional :: failed_node       !! the first node not finite, 0 when all are
      type(expression_work_t) :: local
      integer :: failed
      if (size(x) /= size(result)) then
         call set_error(error, err_invalid_parameter, "evaluate: "//integer_text(size(x))// &
            " nodes for "//integer_text(size(result))//" results")
         if (present(failed_node)) failed_node = 0
         return
      end if
      if (present(work)) then
         call evaluate_core(self, size(x), 1, x, scalars, result, work, error, failed)
      else
         call evaluate_core(self, size(x), 1, x, scalars, result, local, error, failed)
      end if
      if (present(failed_node)) failed_node = failed
   end subroutine evaluate_vector

   !> The value at one point `x(n_variables)`; NaN when it is not finite (evaluate says why).
   pure real(wp) function expression_value(self, x) result(v)
      class(expression_t), intent(in) :: self  !! the parsed expression
      real(wp), intent(in) :: x(:)             !! every variable's value, in the order of the names
      type(expression_work_t) :: local
      type(error_t), allocatable :: error
      real(wp) :: r(1)
      integer :: failed
      call evaluate_core(self, 1, size(x), x, result=r, work=local, error=error, failed_node=failed)
      v = r(1)
      if (allocated(error)) v = quiet_nan()
   end function expression_value

   pure subroutine evaluate_core(self, n, m, nodes, scalars, result, work, error, failed_node)
      class(expression_t), intent(in) :: self
      integer, intent(in) :: n, m
      real(wp), intent(in) :: nodes(n, m)
      real(wp), intent(in), optional :: scalars(:)
      real(wp), intent(out) :: result(n)
      type(expression_work_t), intent(inout) :: work
      type(error_t), allocatable, intent(out) :: error
      integer, intent(out) :: failed_node
      logical :: varying(max(self%depth, 1))
      real(wp) :: uniform(max(self%depth, 1)), r
      type(failure_t) :: fail
      integer :: k, s, j, code, n_scalars, i
      failed_node = 0
      n_scalars = 0
      if (present(scalars)) n_scalars = size(scalars)
      if (self%n_code == 0) then
         call set_error(error, err_invalid_parameter, "evaluate: the expression was not parsed")
         return
      end if
      if (m > self%n_variables .or. m + n_scalars /= self%n_variables) then
         call set_error(error, err_invalid_parameter, "evaluate: "//integer_text(m)//" node variables and "// &
            integer_text(n_scalars)//" scalars given for "//integer_text(self%n_variables)//" variables")
         return
      end if
      if (n == 0) return
      if (allocated(work%stack)) then
         if (size(work%stack, 1) < n .or. size(work%stack, 2) < self%depth) deallocate (work%stack)
      end if
      if (.not. allocated(work%stack)) allocate (work%stack(n, self%depth))
      allocate (fail%failed(n))
      fail%failed = .false.
      s = 0
      do k = 1, self%n_code
         fail%current = k
         select case (self%op(k))
         case (op_const)
            s = s + 1
            varying(s) = .false.
            uniform(s) = self%constant(k)
         case (op_var)
            s = s + 1
            j = self%arg(k)
            if (j <= m) then
               varying(s) = .true.
               do i = 1, n
                  work%stack(i, s) = nodes(i, j)
                  if (.not. finite(nodes(i, j))) then
                     work%stack(i, s) = 0.0_wp
                     call mark(fail, i, fail_input)
                  end if
               end do
            else
               varying(s) = .false.
               uniform(s) = scalars(j - m)
               if (.not. finite(uniform(s))) then
                  uniform(s) = 0.0_wp
                  call mark_all(fail, fail_input)
               end if
            end if
         case (op_add, op_sub, op_mul, op_div, op_pow, op_atan2)
            s = s - 1
            if (varying(s) .and. varying(s + 1)) then
               call binary_vv(self%op(k), work%stack(1:n, s), work%stack(1:n, s + 1), fail)
            else if (varying(s)) then
               call binary_vs(self%op(k), work%stack(1:n, s), uniform(s + 1), fail)
            else if (varying(s + 1)) then
               call binary_sv(self%op(k), uniform(s), work%stack(1:n, s + 1), work%stack(1:n, s), fail)
               varying(s) = .true.
            else
               call binary_1(self%op(k), uniform(s), uniform(s + 1), r, code)
               uniform(s) = r
               if (code /= 0) call mark_all(fail, code)
            end if
         case default
            if (varying(s)) then
               call unary_v(self%op(k), self%arg(k), self%constant(k), work%stack(1:n, s), fail)
            else
               call unary_1(self%op(k), self%arg(k), self%constant(k), uniform(s), r, code)
               uniform(s) = r
               if (code /= 0) call mark_all(fail, code)
            end if
         end select
      end do
      if (varying(1)) then
         result = work%stack(1:n, 1)
      else
         result = uniform(1)
      end if
      if (fail%first == 0) return
      failed_node = fail%first
      where (fail%failed) result = quiet_nan()
      if (fail%code == fail_input) then
         j = self%arg(fail%instruction)
         if (n == 1) then
            call set_error(error, err_invalid_parameter, "the value of '"//trim(self%names(j))//"' is not finite")
         else
            call set_error(error, err_invalid_parameter, "the value of '"//trim(self%names(j))//"' at node "// &
               integer_text(fail%first)//" of "//integer_text(n)//" is not finite")
         end if
      else
         code = err_invalid_parameter
         if (fail%code == fail_overflow) code = err_overflow
         if (n == 1) then
            call set_error(error, code, "the expression is not finite: "//failure_text(fail%code)//" at column "// &
               integer_text(self%column(fail%instruction)))
         else
            call set_error(error, code, "the expression is not finite at node "//integer_text(fail%first)//" of "// &
               integer_text(n)//": "//failure_text(fail%code)//" at column "// &
               integer_text(self%column(fail%instruction)))
         end if
      end if
   end subroutine evaluate_core

   ! ---------------------------------------------------------------------------------------
   ! questions about the compiled form

   !> Whether the expression uses the variable `name` (false for a name it does not know).
   pure logical function uses(self, name)
      class(expression_t), intent(in) :: self  !! the parsed expression
      character(len=*), intent(in) :: name     !! a variable's name (case-sensitive)
      integer :: j
      uses = .false.
      if (.not. allocated(self%names)) return
      j = variable_index(self%names, trim(adjustl(name)))
      if (j == 0) return
      uses = any(self%op(1:self%n_code) == op_var .and. self%arg(1:self%n_code) == j)
   end function uses

   !> Whether the expression uses no variable (its value is `value([real(wp) ::])` when
   !> it has no names, or any point's).
   pure logical function is_constant(self)
      class(expression_t), intent(in) :: self  !! the parsed expression
      is_constant = .true.
      if (self%n_code > 0) is_constant = .not. any(self%op(1:self%n_code) == op_var)
   end function is_constant

   !> Whether the expression is affine in the variable `name` — a + b·name with a and b
   !> free of it — as far as the compiled form proves it (conservative: `name*name/name`
   !> is not proven; a name the expression does not use is affine).
   pure logical function affine_in(self, name)
      class(expression_t), intent(in) :: self  !! the parsed expression
      character(len=*), intent(in) :: name     !! a variable's name (case-sensitive)
      ! degree in the variable: 0 free of it, 1 affine, 2 anything else
      integer :: degree(max(self%depth, 1)), k, s, j
      affine_in = .true.
      if (.not. allocated(self%names)) return
      j = variable_index(self%names, trim(adjustl(name)))
      if (j == 0) return
      s = 0
      do k = 1, self%n_code
         select case (self%op(k))
         case (op_const)
            s = s + 1
            degree(s) = 0
         case (op_var)
            s = s + 1
            degree(s) = 0
            if (self%arg(k) == j) degree(s) = 1
         case (op_add, op_sub)
            s = s - 1
            degree(s) = max(degree(s), degree(s + 1))
         case (op_mul)
            s = s - 1
            if (degree(s) == 0 .or. degree(s + 1) == 0) then
               degree(s) = max(degree(s), degree(s + 1))
            else
               degree(s) = 2
            end if
         case (op_div)
            s = s - 1
            if (degree(s + 1) /= 0) degree(s) = 2
         case (op_pow, op_atan2)
            s = s - 1
            if (degree(s) /= 0 .or. degree(s + 1) /= 0) degree(s) = 2
         case (op_neg)
         case (op_powi)
            if (self%arg(k) == 0) then
               degree(s) = 0
            else if (self%arg(k) /= 1 .and. degree(s) /= 0) then
               degree(s) = 2
            end if
         case default
            if (degree(s) /= 0) degree(s) = 2
         end select
      end do
      affine_in = degree(1) <= 1
   end function affine_in

   !> The number of compiled instructions (after folding constants).
   pure integer function instruction_count(self)
      class(expression_t), intent(in) :: self  !! the parsed expression
      instruction_count = self%n_code
   end function instruction_count

   !> The number of named variables the expression was parsed with.
   pure integer function variable_count(self)
      class(expression_t), intent(in) :: self  !! the parsed expression
      variable_count = self%n_variables
   end function variable_count

   ! ---------------------------------------------------------------------------------------
   ! parameter lists

   !> Parse a list `name = value, name = value, …` (e.g. `'l = 0.2, w = 2*pi*50'`): each
   !> value an expression of numbers, pi, functions and the parameters before it. Items
   !> are separated by commas outside parentheses; an empty (blank) text is no parameter.
   !> Messages name the item and the column in `text`.
   pure subroutine parse_parameters(text, names, values, error, reserved)
      character(len=*), intent(in) :: text  !! the list
      character(len=name_length), allocatable, intent(out) :: names(:)  !! the parameters' names, in order
      real(wp), allocatable, intent(out) :: values(:)   !! their values
      type(error_t), allocatable, intent(out) :: error  !! err_input naming the item and column
      character(len=*), intent(in), optional :: reserved(:)  !! names no parameter may take (e.g. "t")
      character(len=name_length) :: found(len(text)/2 + 1)
      real(wp) :: value(len(text)/2 + 1)
      integer :: n, start, finish, depth, i, equals, name_start, name_end, j
      type(expression_t) :: e
      type(error_t), allocatable :: item_error
      real(wp) :: r(1), none(1, 0)
      character(len=:), allocatable :: name, item
      integer :: failed
      type(expression_work_t) :: work
      n = 0
      if (len_trim(text) > 0) then
         start = 1
         do
            ! the item text(start:finish), up to a comma outside parentheses
            depth = 0
            finish = len(text)
            do i = start, len(text)
               if (text(i:i) == "(") depth = depth + 1
               if (text(i:i) == ")") depth = depth - 1
               if (text(i:i) == "," .and. depth <= 0) then
                  finish = i - 1
                  exit
               end if
            end do
            item = text(start:finish)
            if (len_trim(item) == 0) then
               call set_error(error, err_input, "parameters: item "//integer_text(n + 1)//" at column "// &
                  integer_text(start)//" is empty; expected name = value")
               return
            end if
            equals = index(item, "=")
            if (equals == 0) then
               call set_error(error, err_input, "parameters: item "//integer_text(n + 1)//" '"// &
                  trim(adjustl(item))//"' at column "//integer_text(start + first_nonblank(item) - 1)// &
                  " has no '='; expected name = value")
               return
            end if
            name = trim(adjustl(item(1:equals - 1)))
            name_start = start + first_nonblank(item(1:equals - 1)) - 1
            if (len(name) == 0) then
               call set_error(error, err_input, "parameters: item "//integer_text(n + 1)//" has no name before '=' "// &
                  "at column "//integer_text(start + equals - 1))
               return
            end if
            if (.not. is_name(name) .or. len(name) > name_length) then
               call set_error(error, err_input, "parameters: item "//integer_text(n + 1)//": '"//name// &
                  "' at column "//integer_text(name_start)//" is no name (letters, digits and underscores, "// &
                  "starting with a letter, at most "//integer_text(name_length)//")")
               return
            end if
            if (is_reserved(name)) then
               call set_error(error, err_input, "parameters: item "//integer_text(n + 1)//": '"//name// &
                  "' at column "//integer_text(name_start)//" cannot name a parameter: it is "//reserved_what(name))
               return
            end if
            if (present(reserved)) then
               do j = 1, size(reserved)
                  if (trim(adjustl(reserved(j))) == name) then
                     call set_error(error, err_input, "parameters: item "//integer_text(n + 1)//": '"//name// &
                        "' at column "//integer_text(name_start)//" is reserved; a parameter cannot take it")
                     return
                  end if
               end do
            end if
            do j = 1, n
               if (found(j) == name) then
                  call set_error(error, err_input, "parameters: item "//integer_text(n + 1)//": '"//name// &
                     "' at column "//integer_text(name_start)//" is given twice")
                  return
               end if
            end do
            name_end = start + equals - 1
            if (len_trim(item(equals + 1:)) == 0) then
               call set_error(error, err_input, "parameters: item "//integer_text(n + 1)//" '"//name// &
                  "' has no value after '=' at column "//integer_text(name_end)//"; expected name = value")
               return
            end if
            j = index(item(equals + 1:), "=")
            if (j > 0) then
               call set_error(error, err_input, "parameters: item "//integer_text(n + 1)//" '"//name// &
                  "': a second '=' at column "//integer_text(name_end + j)//"; expected ',' between items")
               return
            end if
            call parse_expression(item(equals + 1:), found(1:n), e, item_error, first_column=name_end + 1)
            if (allocated(item_error)) then
               call set_error(error, err_input, "parameters: item "//integer_text(n + 1)//" '"//name//"': "// &
                  item_error%message)
               return
            end if
            call evaluate_core(e, 1, 0, none, value(1:n), r, work, item_error, failed)
            if (allocated(item_error)) then
               call set_error(error, err_input, "parameters: item "//integer_text(n + 1)//" '"//name//"': "// &
                  item_error%message)
               return
            end if
            n = n + 1
            found(n) = name
            value(n) = r(1)
            if (finish >= len(text)) exit
            start = finish + 2
         end do
      end if
      names = found(1:n)
      values = value(1:n)
   end subroutine parse_parameters

   pure integer function first_nonblank(text)
      character(len=*), intent(in) :: text
      first_nonblank = verify(text, " "//achar(9))
      if (first_nonblank == 0) first_nonblank = 1
   end function first_nonblank

end module hillstab_core_expression

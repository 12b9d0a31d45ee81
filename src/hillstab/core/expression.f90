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
   use hillstab_core_kinds, only: wp, pi
   use hillstab_core_error, only: error_t, set_error, err_input, err_invalid_parameter, err_overflow
   use hillstab_core_text, only: integer_text
   use hillstab_core_expression_ops
   use hillstab_core_expression_parse, only: compiled_t, compile_expression
   implicit none
   private
   public :: expression_t, expression_work_t, parse_expression, parse_parameters, name_length

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

contains

   !> Parse `text` into `expression` for the variables `names` (blanks around each ignored).
   !> On an error, `error` (code err_input) says what was expected where, by column.
   pure subroutine parse_expression(text, names, expression, error, first_column)
      character(len=*), intent(in) :: text             !! the expression
      character(len=*), intent(in) :: names(:)         !! the variables' names, in the order of evaluation
      type(expression_t), intent(out) :: expression    !! the compiled expression
      type(error_t), allocatable, intent(out) :: error !! err_input with the column, or unallocated
      integer, intent(in), optional :: first_column    !! column of text(1:1) in messages (default 1)
      type(compiled_t) :: code
      call compile_expression(text, names, code, error, first_column)
      if (allocated(error)) return
      expression%n_code = code%n_code
      expression%depth = code%depth
      expression%n_variables = size(names)
      call move_alloc(code%op, expression%op)
      call move_alloc(code%arg, expression%arg)
      call move_alloc(code%column, expression%column)
      call move_alloc(code%constant, expression%constant)
      call move_alloc(code%names, expression%names)
   end subroutine parse_expression

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
   pure subroutine parse_parameters(text, names, values, error, reserved, depends)
      character(len=*), intent(in) :: text  !! the list
      character(len=name_length), allocatable, intent(out) :: names(:)  !! the parameters' names, in order
      real(wp), allocatable, intent(out) :: values(:)   !! their values
      type(error_t), allocatable, intent(out) :: error  !! err_input naming the item and column
      character(len=*), intent(in), optional :: reserved(:)  !! names no parameter may take (e.g. "t")
      !> depends(i, j): the value of parameter i is computed from parameter j, directly or
      !> through others (j < i)
      logical, allocatable, intent(out), optional :: depends(:, :)
      character(len=name_length) :: found(len(text)/2 + 1)
      real(wp) :: value(len(text)/2 + 1)
      logical, allocatable :: direct(:, :)
      integer :: n, start, finish, depth, i, equals, name_start, name_end, j
      type(expression_t) :: e
      type(error_t), allocatable :: item_error
      real(wp) :: r(1), none(1, 0)
      character(len=:), allocatable :: name, item
      integer :: failed
      type(expression_work_t) :: work
      n = 0
      ! at most one item per comma and one more
      j = 1
      do i = 1, len(text)
         if (text(i:i) == ",") j = j + 1
      end do
      allocate (direct(j, j))
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
            direct(n, :) = .false.
            do j = 1, n - 1
               ! through the parameters it uses, on everything they depend on
               if (e%uses(trim(found(j)))) direct(n, 1:n - 1) = direct(n, 1:n - 1) .or. direct(j, 1:n - 1)
               if (e%uses(trim(found(j)))) direct(n, j) = .true.
            end do
            if (finish >= len(text)) exit
            start = finish + 2
         end do
      end if
      names = found(1:n)
      values = value(1:n)
      if (present(depends)) depends = direct(1:n, 1:n)
   end subroutine parse_parameters

   pure integer function first_nonblank(text)
      character(len=*), intent(in) :: text
      first_nonblank = verify(text, " "//achar(9))
      if (first_nonblank == 0) first_nonblank = 1
   end function first_nonblank
end module hillstab_core_expression

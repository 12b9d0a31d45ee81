!> C-callable entry points for systems of Hill equations,
!>
!>     M x'' + (C + ε M + G) x' + K(τ) x = 0,   x in Rⁿ,
!>
!> as an opaque `hillstab_system` handle holding a system of either kind: the matrix system
!> of the scenes' `&system` (hillstab_hill_system_matrix), made empty by `hillstab_system_new`,
!> its variables set by name (`n` first, then the matrices as n² numbers row by row: `mass`,
!> `damping`, `gyroscopic`, `k0`, `b`; the drives `cos`, `sin` as H blocks of n² numbers;
!> `period`), or the equations system of `&equations` (hillstab_hill_system_equation: n
!> coupled equations in physical time), made by `hillstab_system_new_named("equations", ...)`,
!> `n` set by `hillstab_system_set` and its texts (parameters, matrices, stiffness, ...) by
!> `hillstab_system_set_text`; checked, and then its monodromy Φ (hillstab_integrate_system)
!> and Floquet analysis (hillstab_hill_system_floquet) at points (α, β, ε). A system whose
!> damping changes from row to row (`row_dependent`: the equations system, its (π/Ω) C) is
!> prepared at the point's α, as the tasks prepare it; one that carries its own damping
!> (`takes_scene_damping` false) refuses ε ≠ 0. Conventions as in hillstab_interop_capi_models: `bind(C)`, `value` scalars,
!> names prefixed `hillstab_`, a status returned (0 or an error code), outputs untouched on
!> failure, the full message in the calling thread's `hillstab_last_error`; here every
!> message starts with the entry point's name and names the argument
!> ("hillstab_system_set: mass: M must be positive definite ...", "hillstab_system_floquet:
!> tolerance: ..."). Null pointers are refused, not followed.
!>
!> The system methods are HILLSTAB_METHOD_AUTO (0), _MAGNUS4 (3), _MAGNUS6 (4) and _RK (5),
!> the codes of the scalar methods of the same names. A monodromy that no mesh brings to the
!> tolerance fails the call (HILLSTAB_ERR_INTEGRATION); one limited by round-off succeeds
!> with `*status` 1 (the best value double precision allows).
!>
!> A handle is read-only while computing: several threads may use one handle at once, but
!> `hillstab_system_set` and `hillstab_system_free` must not run while another thread uses it.
!>
!>```c
!> hillstab_system *pair = NULL;
!> double mass[4] = {1, 0, 0, 0.64}, drive[4] = {-1, 0, 0, -0.8}, two = 2;
!> hillstab_system_new(&pair);
!> hillstab_system_set(pair, "n", &two, 1);
!> hillstab_system_set(pair, "mass", mass, 4);
!> hillstab_system_set(pair, "cos", drive, 4);
!> if (hillstab_system_check(pair) == 0) { ... hillstab_system_floquet(pair, ...) ... }
!> hillstab_system_free(pair);
!>```
module hillstab_interop_capi_system
   use, intrinsic :: iso_c_binding, only: c_int, c_double, c_char, c_size_t, c_ptr, c_loc, c_f_pointer, &
      c_associated
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use hillstab_core_kinds, only: wp
   use hillstab_core_error, only: error_t, set_error, err_invalid_parameter
   use hillstab_core_text, only: integer_text, real_text, lower_case, alternatives_text
   use hillstab_hill_systems, only: system_names, new_system, is_system_name, system_kinds_text
   use hillstab_hill_system, only: hill_system_t, system_form_t, prepare_system, check_system_point
   use hillstab_integrate_system_point, only: resolve_exponents
   use hillstab_batch_tasks_system_values, only: scalar_point
   use hillstab_hill_system_matrix, only: matrix_system_t
   use hillstab_hill_system_equation, only: equations_system_t, max_equations_text
   use hillstab_hill_system_floquet, only: floquet_t, system_floquet
   use hillstab_integrate_system, only: system_method_t, system_monodromy_t, system_nodes_t, system_monodromy
   use hillstab_integrate_monodromy, only: method_table, method_name, method_takes_systems
   use hillstab_interop_outcome, only: record_outcome
   use hillstab_interop_sizes, only: values_count_refusal
   use hillstab_interop_capi_models, only: c_text, max_c_text
   implicit none
   private
   public :: system_handle_t
   public :: hillstab_c_system_new, hillstab_c_system_states, &
      hillstab_c_system_new_named, hillstab_c_system_free, hillstab_c_system_set, &
      hillstab_c_system_set_text, hillstab_c_system_check, hillstab_c_system_dof, hillstab_c_system_monodromy, &
      hillstab_c_system_floquet
   public :: min_system_tolerance, handle_system, check_output, outcome_status, check_method_tolerance, &
      own_damping_refusal

   !> Tolerances must lie strictly between this and 1.
   real(wp), parameter :: min_system_tolerance = 1.0e-15_wp

   !> What a `hillstab_system *` points to: one system (a matrix system or an equations
   !> system), with its data.
   type :: system_handle_t
      class(hill_system_t), allocatable :: system  !! the system (empty until its variables are set)
   end type system_handle_t

contains

   !> The handle behind a `hillstab_system *`; err_invalid_parameter for a null pointer.
   subroutine handle_system(where, pointer, handle, error)
      character(len=*), intent(in) :: where  !! the entry point, for the message
      type(c_ptr), intent(in) :: pointer  !! the C pointer
      type(system_handle_t), pointer, intent(out) :: handle  !! what it points to (null on error)
      type(error_t), allocatable, intent(out) :: error  !! a null handle
      handle => null()
      if (.not. c_associated(pointer)) then
         call set_error(error, err_invalid_parameter, where//": system: a null pointer (make it with "// &
            "hillstab_system_new)")
         return
      end if
      call c_f_pointer(pointer, handle)
   end subroutine handle_system

   !> err_invalid_parameter naming the output when its pointer is null (nothing done when
   !> `error` is already allocated).
   subroutine check_output(where, name, pointer, error)
      character(len=*), intent(in) :: where  !! the entry point
      character(len=*), intent(in) :: name   !! the argument
      type(c_ptr), intent(in) :: pointer     !! its pointer
      type(error_t), allocatable, intent(inout) :: error  !! set when null
      if (allocated(error)) return
      if (.not. c_associated(pointer)) call set_error(error, err_invalid_parameter, where//": "//name// &
         ": a null pointer")
   end subroutine check_output

   !> The status of a call: 0, or the code of `error` after recording it.
   integer(c_int) function outcome_status(error) result(status)
      type(error_t), allocatable, intent(in) :: error  !! the call's error, unallocated on success
      call record_outcome(error)
      status = 0
      if (allocated(error)) status = int(error%code, c_int)
   end function outcome_status

   !> `int hillstab_system_new(hillstab_system **system)`: an empty matrix system (no
   !> variables set; `n` comes first); `*system` untouched on failure. Free it with
   !> hillstab_system_free.
   function hillstab_c_system_new(system) result(status) bind(C, name="hillstab_system_new")
      type(c_ptr), value, intent(in) :: system  !! where the handle goes (a `hillstab_system **`)
      integer(c_int) :: status
      type(c_ptr), pointer :: out
      type(system_handle_t), pointer :: handle
      type(error_t), allocatable :: error
      if (.not. c_associated(system)) then
         call set_error(error, err_invalid_parameter, "hillstab_system_new: system: a null pointer (pass the "// &
            "address of a hillstab_system *)")
      else
         call c_f_pointer(system, out)
         allocate (handle)
         allocate (matrix_system_t :: handle%system)
         out = c_loc(handle)
      end if
      status = outcome_status(error)
   end function hillstab_c_system_new

   !> `int hillstab_system_new_named(const char *name, hillstab_system **system)`: an empty
   !> system of the kind `name` (any case): "system", the matrix system (as
   !> hillstab_system_new), or "equations", n coupled equations in physical time (its `n` by
   !> hillstab_system_set, its texts by hillstab_system_set_text); err_invalid_parameter naming
   !> `name` for another, `*system` untouched on failure. Free it with hillstab_system_free.
   function hillstab_c_system_new_named(name, system) result(status) bind(C, name="hillstab_system_new_named")
      type(c_ptr), value, intent(in) :: name    !! the kind, NUL-terminated
      type(c_ptr), value, intent(in) :: system  !! where the handle goes (a `hillstab_system **`)
      integer(c_int) :: status
      character(len=*), parameter :: where = "hillstab_system_new_named"
      type(c_ptr), pointer :: out
      type(system_handle_t), pointer :: handle
      type(error_t), allocatable :: error
      character(kind=c_char), pointer :: chars(:)
      character(len=:), allocatable :: which
      logical :: ok
      if (.not. c_associated(name)) then
         call set_error(error, err_invalid_parameter, where//": name: a null pointer (expected "// &
                        alternatives_text(system_names)//")")
      else if (.not. c_associated(system)) then
         call set_error(error, err_invalid_parameter, where//": system: a null pointer (pass the address of a "// &
            "hillstab_system *)")
      else
         call c_f_pointer(name, chars, [max_c_text + 1])
         call c_text(chars, which, ok)
         if (.not. ok) then
            call set_error(error, err_invalid_parameter, where//": name: longer than "//integer_text(max_c_text)// &
               " characters")
         else if (.not. is_system_name(which)) then
            call set_error(error, err_invalid_parameter, where//": name: unknown system '"//which//"' ("// &
               system_kinds_text("", "; ")//")")
         else
            call c_f_pointer(system, out)
            allocate (handle)
            call new_system(which, handle%system, error)
            out = c_loc(handle)
         end if
      end if
      status = outcome_status(error)
   end function hillstab_c_system_new_named

   !> `void hillstab_system_free(hillstab_system *system)`: release a system (a null pointer
   !> is ignored).
   subroutine hillstab_c_system_free(system) bind(C, name="hillstab_system_free")
      type(c_ptr), value, intent(in) :: system  !! the handle, or NULL
      type(system_handle_t), pointer :: handle
      if (.not. c_associated(system)) return
      call c_f_pointer(system, handle)
      deallocate (handle)
   end subroutine hillstab_c_system_free

   !> `int hillstab_system_set(hillstab_system *system, const char *variable, const double
   !> *values, size_t count)`: set a variable of the system (the matrix system's
   !> `set_values`) to `count` numbers: `n` (1 … 20) first, then `mass`, `damping`,
   !> `gyroscopic`, `k0`, `b` (n² numbers, row by row), `cos`, `sin` (H blocks of n²) and
   !> `period` (a multiple of 2). Once n is given, the variable is checked on its own (its
   !> size; M symmetric positive definite, C symmetric, G skew); err_invalid_parameter naming
   !> the variable otherwise, the system then as before the call. Whether the whole system is
   !> complete is checked by hillstab_system_check and by every computation.
   function hillstab_c_system_set(system, variable, values, count) result(status) bind(C, name="hillstab_system_set")
      type(c_ptr), value, intent(in) :: system    !! the handle
      type(c_ptr), value, intent(in) :: variable  !! the variable's name, NUL-terminated
      type(c_ptr), value, intent(in) :: values    !! the numbers (NULL only when count is 0)
      integer(c_size_t), value, intent(in) :: count  !! how many numbers
      integer(c_int) :: status
      character(len=*), parameter :: where = "hillstab_system_set"
      type(system_handle_t), pointer :: handle
      type(error_t), allocatable :: error
      character(kind=c_char), pointer :: chars(:)
      real(c_double), pointer :: numbers(:)
      real(wp), allocatable :: list(:)
      character(len=:), allocatable :: name, refusal
      class(hill_system_t), allocatable :: saved
      logical :: ok, known
      integer :: count_read
      call handle_system(where, system, handle, error)
      if (.not. allocated(error) .and. .not. c_associated(variable)) &
         call set_error(error, err_invalid_parameter, where//": variable: a null pointer")
      if (.not. allocated(error)) then
         call c_f_pointer(variable, chars, [max_c_text + 1])
         call c_text(chars, name, ok)
         if (.not. ok) then
            call set_error(error, err_invalid_parameter, where//": variable: the name is longer than "// &
               integer_text(max_c_text)//" characters")
         else
            call values_count_refusal(handle%system, name, count, known, refusal)
            if (len(refusal) > 0) call set_error(error, err_invalid_parameter, where//": "//refusal)
         end if
         ! a name the system does not have reads no number: set_values refuses the name
         count_read = 0
         if (.not. allocated(error) .and. known) then
            count_read = int(count)
            if (count_read > 0 .and. .not. c_associated(values)) call set_error(error, err_invalid_parameter, &
               where//": values: a null pointer for "//integer_text(count_read)//" numbers of '"//name//"'")
         end if
      end if
      if (.not. allocated(error)) then
         allocate (list(count_read))
         if (count_read > 0) then
            call c_f_pointer(values, numbers, [count_read])
            list = real(numbers, wp)
         end if
         allocate (saved, source=handle%system)
         call handle%system%set_values(name, list, error)
         if (.not. allocated(error)) then
            select type (matrix => handle%system)
            type is (matrix_system_t)
               call check_variable(matrix, name, list, error)
            end select
         end if
         if (allocated(error)) then
            call move_alloc(saved, handle%system)
            error%message = where//": "//error%message
         end if
      end if
      status = outcome_status(error)
   end function hillstab_c_system_set

   !> `int hillstab_system_set_text(hillstab_system *system, const char *variable, const char
   !> *text)`: set a text variable of the system (the equations system's `parameters`,
   !> `matrices`, `stiffness`, `mass`, `damping`, `gyroscopic`, `frequency`, `period`,
   !> `alpha`, `beta`: its `set_text`, as in the scene group &equations); err_invalid_parameter
   !> naming the variable when the system has no such variable or the text is too long, the
   !> system then as before the call. What the texts say together (they parse, the matrices
   !> have n rows of n entries, the axes are parameters, ...) is checked by
   !> hillstab_system_check and by every computation, naming the variable.
   function hillstab_c_system_set_text(system, variable, text) result(status) bind(C, name="hillstab_system_set_text")
      type(c_ptr), value, intent(in) :: system    !! the handle
      type(c_ptr), value, intent(in) :: variable  !! the variable's name, NUL-terminated
      type(c_ptr), value, intent(in) :: text      !! its text, NUL-terminated
      integer(c_int) :: status
      character(len=*), parameter :: where = "hillstab_system_set_text"
      type(system_handle_t), pointer :: handle
      type(error_t), allocatable :: error
      character(kind=c_char), pointer :: chars(:)
      character(len=:), allocatable :: name, value
      class(hill_system_t), allocatable :: saved
      logical :: ok
      call handle_system(where, system, handle, error)
      if (.not. allocated(error) .and. .not. c_associated(variable)) &
         call set_error(error, err_invalid_parameter, where//": variable: a null pointer")
      if (.not. allocated(error)) then
         call c_f_pointer(variable, chars, [max_c_text + 1])
         call c_text(chars, name, ok)
         if (.not. ok) call set_error(error, err_invalid_parameter, where//": variable: the name is longer than "// &
            integer_text(max_c_text)//" characters")
      end if
      if (.not. allocated(error) .and. .not. c_associated(text)) &
         call set_error(error, err_invalid_parameter, where//": "//name//": the text is a null pointer")
      if (.not. allocated(error)) then
         call c_f_pointer(text, chars, [max_equations_text + 1])
         call c_text(chars, value, ok, limit=max_equations_text)
         if (.not. ok) call set_error(error, err_invalid_parameter, where//": "//name//": the text is longer "// &
            "than the "//integer_text(max_equations_text)//" characters a text may have")
      end if
      if (.not. allocated(error)) then
         allocate (saved, source=handle%system)
         call handle%system%set_text(name, value, error)
         if (allocated(error)) then
            call move_alloc(saved, handle%system)
            error%message = where//": "//error%message
         end if
      end if
      status = outcome_status(error)
   end function hillstab_c_system_set_text

   !> Check one matrix variable on its own once n is given: a system of n, the variable and
   !> otherwise defaults (a unit drive where the variable is not one) must be complete;
   !> its message names the variable.
   subroutine check_variable(system, name, values, error)
      type(matrix_system_t), intent(in) :: system  !! the system after the set
      character(len=*), intent(in) :: name         !! the variable set
      real(wp), intent(in) :: values(:)            !! its numbers
      type(error_t), allocatable, intent(out) :: error  !! err_invalid_parameter naming the variable
      type(matrix_system_t) :: probe
      real(wp), allocatable :: unit(:)
      integer :: n, i
      n = system%n
      if (n < 1) return
      select case (trim(name))
      case ("mass", "damping", "gyroscopic", "k0", "b", "cos", "sin")
      case default
         return
      end select
      allocate (unit(n*n))
      unit = 0.0_wp
      do i = 1, n
         unit((i - 1)*n + i) = 1.0_wp
      end do
      call probe%set_values("n", [real(n, wp)], error)
      if (.not. allocated(error)) call probe%set_values(name, values, error)
      if (allocated(error)) return
      if (trim(name) == "cos") then
         call probe%set_values("sin", unit, error)
      else
         call probe%set_values("cos", unit, error)
      end if
      if (.not. allocated(error)) call probe%check_values(error)
   end subroutine check_variable

   !> `int hillstab_system_check(const hillstab_system *system)`: whether the system is
   !> complete and consistent (its `check_values`: n given, every matrix of n² numbers, M
   !> symmetric positive definite, C symmetric, G skew, a nonzero drive): 0, or
   !> err_invalid_parameter naming the variable.
   function hillstab_c_system_check(system) result(status) bind(C, name="hillstab_system_check")
      type(c_ptr), value, intent(in) :: system  !! the handle
      integer(c_int) :: status
      character(len=*), parameter :: where = "hillstab_system_check"
      type(system_handle_t), pointer :: handle
      type(error_t), allocatable :: error
      call handle_system(where, system, handle, error)
      if (.not. allocated(error)) then
         call handle%system%check_values(error)
         if (allocated(error)) error%message = where//": "//error%message
      end if
      status = outcome_status(error)
   end function hillstab_c_system_check

   !> `int hillstab_system_dof(const hillstab_system *system, int *n)`: the degrees of
   !> freedom n (Φ is 2n × 2n); err_invalid_parameter while n is not given.
   function hillstab_c_system_dof(system, n) result(status) bind(C, name="hillstab_system_dof")
      type(c_ptr), value, intent(in) :: system  !! the handle
      type(c_ptr), value, intent(in) :: n       !! receives n (an `int *`)
      integer(c_int) :: status
      status = size_out("hillstab_system_dof", "n", system, n, .false.)
   end function hillstab_c_system_dof

   !> `int hillstab_system_states(const hillstab_system *system, int *states)`: the size m of
   !> the state y (Φ is m × m, with m multipliers): 2n, or n for a system in first-order form
   !> (an equations system given `state`, y' = A(t) y); err_invalid_parameter while n is not
   !> given.
   function hillstab_c_system_states(system, states) result(status) bind(C, name="hillstab_system_states")
      type(c_ptr), value, intent(in) :: system  !! the handle
      type(c_ptr), value, intent(in) :: states  !! receives m (an `int *`)
      integer(c_int) :: status
      status = size_out("hillstab_system_states", "states", system, states, .true.)
   end function hillstab_c_system_states

   !> What `hillstab_system_dof` and `hillstab_system_states` share: the handle and the output
   !> checked, n given, then n or the size of the state (2n, n in first-order form) stored.
   integer(c_int) function size_out(where, name, system, out_pointer, states) result(status)
      character(len=*), intent(in) :: where  !! the entry point
      character(len=*), intent(in) :: name   !! the output's name, for messages
      type(c_ptr), intent(in) :: system      !! the handle
      type(c_ptr), intent(in) :: out_pointer  !! receives the count (an `int *`)
      logical, intent(in) :: states          !! the size of the state, not n
      type(system_handle_t), pointer :: handle
      type(error_t), allocatable :: error
      integer(c_int), pointer :: out
      call handle_system(where, system, handle, error)
      call check_output(where, name, out_pointer, error)
      if (.not. allocated(error)) then
         if (handle%system%dof() < 1) then
            call set_error(error, err_invalid_parameter, where//": "//name//": the degrees of freedom are not "// &
               "given (hillstab_system_set(system, ""n"", ...) first)")
         else
            call c_f_pointer(out_pointer, out)
            out = int(handle%system%dof(), c_int)
            if (states .and. .not. handle%system%first_order()) out = 2*out
         end if
      end if
      status = outcome_status(error)
   end function size_out

   !> Everything a point needs, checked: the handle, the method and tolerance, α, β, ε (0 for
   !> a system with a damping of its own), the system complete, prepared at ε (and at α for
   !> a system whose damping changes from row to row, as the tasks prepare it); then the
   !> monodromy. `error` names the argument, its
   !> message prefixed by `where`.
   subroutine system_point(where, system, alpha, beta, epsilon, method, tolerance, handle, form, result, error, &
                           floquet, analysed)
      character(len=*), intent(in) :: where            !! the entry point
      type(c_ptr), intent(in) :: system                !! the handle
      real(c_double), intent(in) :: alpha, beta, epsilon, tolerance  !! the point, the tolerance
      integer(c_int), intent(in) :: method             !! HILLSTAB_METHOD_AUTO, _MAGNUS4, _MAGNUS6, _RK or _GSL
      type(system_handle_t), pointer, intent(out) :: handle  !! the handle's system
      type(system_form_t), intent(out) :: form         !! the system prepared at ε
      type(system_monodromy_t), intent(out) :: result  !! the monodromy
      type(error_t), allocatable, intent(inout) :: error  !! allocated on entry: nothing done
      !> the analysis, when the point took the scalar path (`scalar_point`: method auto on a
      !> system of one scalar equation; `result` then has no Φ)
      type(floquet_t), intent(out), optional :: floquet
      logical, intent(out), optional :: analysed  !! `floquet` was computed (given with it)
      type(system_nodes_t) :: nodes
      class(hill_system_t), allocatable :: local
      logical :: taken
      if (present(analysed)) analysed = .false.
      if (allocated(error)) return
      call handle_system(where, system, handle, error)
      if (allocated(error)) return
      call check_method_tolerance(method, tolerance, error)
      if (allocated(error)) then
         continue
      else if (.not. ieee_is_finite(alpha)) then
         call set_error(error, err_invalid_parameter, "alpha: must be finite")
      else if (.not. ieee_is_finite(beta)) then
         call set_error(error, err_invalid_parameter, "beta: must be finite")
      else if (.not. in_range(epsilon, 0.0_wp, huge(1.0_wp), .true.)) then
         call set_error(error, err_invalid_parameter, "epsilon: the damping must be finite and >= 0, got "// &
            real_text(real(epsilon, wp)))
      end if
      if (.not. allocated(error)) call own_damping_refusal(handle%system, real(epsilon, wp), "", error)
      if (.not. allocated(error)) call handle%system%check_values(error)
      if (.not. allocated(error)) call check_system_point(handle%system, real(alpha, wp), real(beta, wp), error)
      if (.not. allocated(error)) then
         if (.not. handle%system%shares_rows()) then
            ! the point alone: the system at its β, prepared there, its point (α, 0)
            call handle%system%at_point(real(alpha, wp), real(beta, wp), local)
            call prepare_system(local, real(epsilon, wp), form, error, alpha=real(alpha, wp))
         else if (handle%system%row_dependent()) then
            call prepare_system(handle%system, real(epsilon, wp), form, error, alpha=real(alpha, wp))
         else
            call prepare_system(handle%system, real(epsilon, wp), form, error)
         end if
      end if
      if (.not. allocated(error) .and. present(floquet) .and. present(analysed)) then
         call scalar_point(handle%system, form, system_method_t(int(method), real(tolerance, wp)), real(alpha, wp), &
                           real(beta, wp), floquet, result, taken, error)
         analysed = taken
         if (taken) then
            if (allocated(error)) error%message = where//": "//error%message
            return
         end if
      end if
      if (.not. allocated(error)) then
         if (allocated(local)) then
            call system_monodromy(local, form, real(alpha, wp), 0.0_wp, system_method_t(int(method), &
                                  real(tolerance, wp)), nodes, result, error)
         else
            call system_monodromy(handle%system, form, real(alpha, wp), real(beta, wp), &
                                  system_method_t(int(method), real(tolerance, wp)), nodes, result, error)
         end if
      end if
      if (allocated(error)) error%message = where//": "//error%message
   end subroutine system_point

   !> err_invalid_parameter naming `epsilon` when a system that carries its own damping (the
   !> equations system: its C, in its own units) is given a damping ε > 0 as well (nothing
   !> done when `error` is already allocated); `place` ("point 3: ", "the grid: " or "")
   !> follows the argument's name.
   subroutine own_damping_refusal(system, epsilon, place, error)
      class(hill_system_t), intent(in) :: system  !! the system
      real(wp), intent(in) :: epsilon             !! the damping given
      character(len=*), intent(in) :: place       !! where, for the message
      type(error_t), allocatable, intent(inout) :: error  !! the refusal
      if (allocated(error)) return
      if (system%takes_scene_damping() .or. .not. epsilon > 0.0_wp) return
      call set_error(error, err_invalid_parameter, "epsilon: "//place//"the "//system%name()//" system carries "// &
         "its own damping (its variable damping, in its own units, converted at every row): epsilon must be 0, "// &
         "got "//real_text(epsilon))
   end subroutine own_damping_refusal

   !> err_invalid_parameter naming `method` (not a system method's code) or `tolerance` (not
   !> strictly between 1e-15 and 1).
   subroutine check_method_tolerance(method, tolerance, error)
      integer(c_int), intent(in) :: method  !! HILLSTAB_METHOD_AUTO, _MAGNUS4, _MAGNUS6, _RK or _GSL
      real(c_double), intent(in) :: tolerance  !! the target error of Φ
      type(error_t), allocatable, intent(out) :: error  !! what is wrong; unallocated when both are valid
      if (.not. method_takes_systems(int(method))) then
         call set_error(error, err_invalid_parameter, "method: unknown system method code "// &
            integer_text(int(method))//" ("//system_method_codes()//")")
      else if (.not. in_range(tolerance, min_system_tolerance, 1.0_wp, .false.)) then
         call set_error(error, err_invalid_parameter, "tolerance: must lie between 1e-15 and 1 (exclusive), "// &
            "got "//real_text(real(tolerance, wp)))
      end if
   end subroutine check_method_tolerance

   !> x finite and low < x < high (low <= x <= high when `closed`), decided without comparing
   !> a NaN (a comparison that would raise IEEE invalid under floating-point traps).
   pure logical function in_range(x, low, high, closed)
      real(c_double), intent(in) :: x  !! the value
      real(wp), intent(in) :: low, high  !! the bounds
      logical, intent(in) :: closed  !! the bounds included
      in_range = .false.
      if (.not. ieee_is_finite(x)) return
      if (closed) then
         in_range = x >= low .and. x <= high
      else
         in_range = x > low .and. x < high
      end if
   end function in_range

   !> `int hillstab_system_monodromy(const hillstab_system *system, double alpha, double beta,
   !> double epsilon, int method, double tolerance, double *phi, double *log_scale, double
   !> *error_estimate, int *status)`: the monodromy over one period, Φ = e^s Φ̃: Φ̃ in `phi`
   !> (2n × 2n, row by row, acting on y = (x, x')), s in `log_scale` (0 unless Φ grows
   !> large), the estimated error of Φ̃'s entries relative to max(1, max|Φ̃_ij|), and `status`
   !> 0 (met the tolerance) or 1 (round-off limited: the best value double precision allows).
   function hillstab_c_system_monodromy(system, alpha, beta, epsilon, method, tolerance, phi, log_scale, &
                                        error_estimate, status) result(code) bind(C, name="hillstab_system_monodromy")
      type(c_ptr), value, intent(in) :: system  !! the handle
      !> the point (alpha, beta), the damping epsilon >= 0 and the target error of Phi
      real(c_double), value, intent(in) :: alpha, beta, epsilon, tolerance
      integer(c_int), value, intent(in) :: method  !! HILLSTAB_METHOD_AUTO, _MAGNUS4, _MAGNUS6, _RK or _GSL
      type(c_ptr), value, intent(in) :: phi             !! receives Phi~ (4 n² doubles, row-major)
      type(c_ptr), value, intent(in) :: log_scale       !! receives s (a `double *`)
      type(c_ptr), value, intent(in) :: error_estimate  !! receives the error estimate (a `double *`)
      type(c_ptr), value, intent(in) :: status          !! receives 0 or 1 (an `int *`)
      integer(c_int) :: code
      character(len=*), parameter :: where = "hillstab_system_monodromy"
      type(system_handle_t), pointer :: handle
      type(system_form_t) :: form
      type(system_monodromy_t) :: result
      type(error_t), allocatable :: error
      real(c_double), pointer :: phi_out(:), scale_out, estimate_out
      integer(c_int), pointer :: status_out
      integer :: m
      call check_output(where, "phi", phi, error)
      call check_output(where, "log_scale", log_scale, error)
      call check_output(where, "error_estimate", error_estimate, error)
      call check_output(where, "status", status, error)
      call system_point(where, system, alpha, beta, epsilon, method, tolerance, handle, form, result, error)
      if (.not. allocated(error)) then
         m = form%states
         call c_f_pointer(phi, phi_out, [m*m])
         call c_f_pointer(log_scale, scale_out)
         call c_f_pointer(error_estimate, estimate_out)
         call c_f_pointer(status, status_out)
         phi_out = reshape(transpose(result%phi), [m*m])
         scale_out = result%log_scale
         estimate_out = result%error_estimate
         status_out = int(result%status, c_int)
      end if
      code = outcome_status(error)
   end function hillstab_c_system_monodromy

   !> `int hillstab_system_floquet(const hillstab_system *system, double alpha, double beta,
   !> double epsilon, int method, double tolerance, double *multipliers_re, double
   !> *multipliers_im, double *log_scale, double *exponents, int *verdict, int *kind, double
   !> *trace, double *a2, double *defect, double *error_estimate, int *status)`: the Floquet
   !> analysis of the monodromy: its 2n multipliers by decreasing modulus (Φ's own, and
   !> `log_scale` 0, when they are at most 1e300; else Φ̃'s, Φ's being e^log_scale times
   !> them), the exponents ln|λ_i|/P of the n largest, the verdict (HILLSTAB_SYSTEM_VERDICT_*:
   !> 1 stable, 0 unstable, −1 marginal, decided within the error bound), the kind
   !> (HILLSTAB_SYSTEM_KIND_*: 0 stable, 1 at +1, 2 at −1, 3 combination, 4 damped,
   !> 5 undecided), the invariants tr Φ and a₂ (±1e300 beyond), the structural defect
   !> (relative), the monodromy's error estimate and status (0 or 1).
   function hillstab_c_system_floquet(system, alpha, beta, epsilon, method, tolerance, multipliers_re, &
                                      multipliers_im, log_scale, exponents, verdict, kind, trace, a2, defect, &
                                      error_estimate, status) result(code) bind(C, name="hillstab_system_floquet")
      type(c_ptr), value, intent(in) :: system  !! the handle
      !> the point (alpha, beta), the damping epsilon >= 0 and the target error of Phi
      real(c_double), value, intent(in) :: alpha, beta, epsilon, tolerance
      integer(c_int), value, intent(in) :: method  !! HILLSTAB_METHOD_AUTO, _MAGNUS4, _MAGNUS6, _RK or _GSL
      type(c_ptr), value, intent(in) :: multipliers_re  !! receives the real parts (2n doubles)
      type(c_ptr), value, intent(in) :: multipliers_im  !! receives the imaginary parts (2n doubles)
      type(c_ptr), value, intent(in) :: log_scale       !! receives the scale of the multipliers (0 or s)
      type(c_ptr), value, intent(in) :: exponents       !! receives ln|lambda_i|/P of the n largest (n doubles)
      type(c_ptr), value, intent(in) :: verdict         !! receives the verdict (an `int *`)
      type(c_ptr), value, intent(in) :: kind            !! receives the kind (an `int *`)
      type(c_ptr), value, intent(in) :: trace           !! receives tr Phi (a `double *`)
      type(c_ptr), value, intent(in) :: a2              !! receives a2 (a `double *`)
      type(c_ptr), value, intent(in) :: defect          !! receives the structural defect (a `double *`)
      type(c_ptr), value, intent(in) :: error_estimate  !! receives the monodromy's error estimate
      type(c_ptr), value, intent(in) :: status          !! receives 0 or 1 (an `int *`)
      integer(c_int) :: code
      character(len=*), parameter :: where = "hillstab_system_floquet"
      type(system_handle_t), pointer :: handle
      type(system_form_t) :: form
      type(system_monodromy_t) :: result
      type(floquet_t) :: f
      type(system_nodes_t) :: nodes
      type(error_t), allocatable :: error
      real(c_double), pointer :: re_out(:), im_out(:), exponents_out(:), p
      integer(c_int), pointer :: q
      real(wp) :: s, largest
      integer :: n
      logical :: analysed
      call check_output(where, "multipliers_re", multipliers_re, error)
      call check_output(where, "multipliers_im", multipliers_im, error)
      call check_output(where, "log_scale", log_scale, error)
      call check_output(where, "exponents", exponents, error)
      call check_output(where, "verdict", verdict, error)
      call check_output(where, "kind", kind, error)
      call check_output(where, "trace", trace, error)
      call check_output(where, "a2", a2, error)
      call check_output(where, "defect", defect, error)
      call check_output(where, "error_estimate", error_estimate, error)
      call check_output(where, "status", status, error)
      call system_point(where, system, alpha, beta, epsilon, method, tolerance, handle, form, result, error, f, &
                        analysed)
      if (.not. allocated(error)) then
         if (.not. analysed) then
            call system_floquet(result%phi, form, result%error_estimate*max(1.0_wp, maxval(abs(result%phi))), f, &
                                result%log_scale, real(beta, wp))
            call resolve_exponents(handle%system, form, real(alpha, wp), real(beta, wp), &
                                   system_method_t(int(method), real(tolerance, wp)), nodes, result, f)
         end if
         n = form%n
         ! Φ's own multipliers where they stay finite, else Φ̃'s with the scale
         s = f%log_scale
         largest = maxval(abs(f%multipliers))
         if (s /= 0.0_wp .and. s < 690.0_wp) then
            if (largest*exp(s) <= 1.0e300_wp) then
               f%multipliers = f%multipliers*exp(s)
               s = 0.0_wp
            end if
         end if
         call c_f_pointer(multipliers_re, re_out, [form%states])
         call c_f_pointer(multipliers_im, im_out, [form%states])
         call c_f_pointer(exponents, exponents_out, [n])
         re_out = real(f%multipliers, c_double)
         im_out = aimag(f%multipliers)
         exponents_out = f%exponents
         call c_f_pointer(log_scale, p); p = s
         call c_f_pointer(trace, p); p = f%a1
         call c_f_pointer(a2, p); p = f%a2
         call c_f_pointer(defect, p); p = f%defect
         call c_f_pointer(error_estimate, p); p = result%error_estimate
         call c_f_pointer(verdict, q); q = int(f%verdict, c_int)
         call c_f_pointer(kind, q); q = int(f%kind, c_int)
         call c_f_pointer(status, q); q = int(result%status, c_int)
      end if
      code = outcome_status(error)
   end function hillstab_c_system_floquet

   !> The codes of the methods systems take, as the C enum names them: "HILLSTAB_METHOD_AUTO 0,
   !> _MAGNUS4 3, _MAGNUS6 4, _RK 5 or _GSL 6" (the method table's rows that say `systems`).
   pure function system_method_codes() result(text)
      character(len=:), allocatable :: text
      integer :: k, n, i, shown
      character(len=:), allocatable :: name
      n = count(method_table%systems)
      text = ""
      shown = 0
      do k = lbound(method_table, 1), ubound(method_table, 1)
         if (.not. method_takes_systems(k)) cycle
         shown = shown + 1
         if (shown == 1) then
            text = "HILLSTAB_METHOD_"
         else if (shown == n) then
            text = text//" or _"
         else
            text = text//", _"
         end if
         name = method_name(k)
         do i = 1, len(name)
            if (name(i:i) >= "a" .and. name(i:i) <= "z") name(i:i) = achar(iachar(name(i:i)) - 32)
         end do
         text = text//name//" "//integer_text(k)
      end do
   end function system_method_codes
end module hillstab_interop_capi_system

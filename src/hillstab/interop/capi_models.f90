!> C-callable entry points for models as values: an opaque `hillstab_model` handle made
!> from a name of the model registry (hillstab_hill_models), its variables set by name
!> (the model's `set_values`; data models such as a Fourier series have them, the elastic
!> and the Mathieu model have none), its texts, and the registry listed. The handle is
!> what the batch entry points (hillstab_interop_capi_batch) take. Conventions as in
!> hillstab_interop_capi: `bind(C)`, `value` scalars, names prefixed `hillstab_`, a status
!> returned (0 or an error code), outputs untouched on failure, the full message in the
!> calling thread's `hillstab_last_error`.
!>
!> A handle is read-only while computing: several threads may use one handle at once,
!> but `hillstab_model_set` and `hillstab_model_free` must not run while another thread
!> uses it.
!>
!>```c
!> hillstab_model *model = NULL;
!> if (hillstab_model_new("mathieu", &model) == 0) {
!>    char formula[200];
!>    hillstab_model_formula(model, formula, sizeof formula);
!>    hillstab_model_free(model);
!> }
!>```
module hillstab_interop_capi_models
   use, intrinsic :: iso_c_binding, only: c_int, c_double, c_char, c_size_t, c_null_char, c_ptr, c_loc, &
      c_f_pointer, c_associated, c_null_ptr
   use hillstab_core_kinds, only: wp, int64
   use hillstab_core_error, only: error_t, set_error, err_invalid_parameter
   use hillstab_core_text, only: integer_text
   use hillstab_hill_model, only: hill_model_t, model_variable_t
   use hillstab_hill_models, only: model_names, model_count, new_model
   use hillstab_interop_outcome, only: record_outcome
   use hillstab_interop_sizes, only: values_count_refusal, buffer_length
   implicit none
   private
   public :: model_handle_t, handle_model, c_text, copy_text, max_c_text
   public :: hillstab_c_model_new, hillstab_c_model_free, hillstab_c_model_set, hillstab_c_model_check, &
      hillstab_c_model_count, hillstab_c_model_set_text, hillstab_c_model_registry_name, hillstab_c_model_name, &
      hillstab_c_model_formula, &
      hillstab_c_model_variable_count, hillstab_c_model_variable_name, hillstab_c_model_tau_rate

   !> Longest C string read (a name, a path): longer ones are refused.
   integer, parameter :: max_c_text = 4096

   !> What a `hillstab_model *` points to: one model of the registry, with its data.
   type :: model_handle_t
      class(hill_model_t), allocatable :: model  !! the model
   end type model_handle_t

contains

   !> A Fortran string from a NUL-terminated C string (at most `max_c_text` characters, or
   !> `limit`; `ok` false when there is no NUL within them).
   subroutine c_text(chars, text, ok, limit)
      character(kind=c_char), intent(in) :: chars(*)  !! the C string
      character(len=:), allocatable, intent(out) :: text  !! its characters before the NUL
      logical, intent(out) :: ok  !! the string ended within max_c_text (or limit) characters
      integer, intent(in), optional :: limit  !! the most characters read instead of max_c_text
      integer :: n, i, most
      n = 0
      ok = .false.
      most = max_c_text
      if (present(limit)) most = limit
      do while (n < most)
         if (chars(n + 1) == c_null_char) then
            ok = .true.
            exit
         end if
         n = n + 1
      end do
      allocate (character(len=n) :: text)
      do i = 1, n
         text(i:i) = chars(i)
      end do
   end subroutine c_text

   !> `text` into a C buffer of `length` bytes, cut to length − 1 and NUL-terminated
   !> (nothing written when `length` is 0).
   subroutine copy_text(text, buffer, length)
      character(len=*), intent(in) :: text  !! the text
      integer(c_size_t), intent(in) :: length  !! size of the buffer in bytes (any size_t)
      character(kind=c_char), intent(inout) :: buffer(*)  !! receives the text
      integer :: i, n
      if (length == 0_c_size_t) return
      n = int(min(int(len(text), int64), buffer_length(length) - 1))
      do i = 1, n
         buffer(i) = text(i:i)
      end do
      buffer(n + 1) = c_null_char
   end subroutine copy_text

   !> The handle behind a `hillstab_model *`; err_invalid_parameter for a null pointer or a
   !> handle without a model.
   subroutine handle_model(model, handle, error)
      type(c_ptr), intent(in) :: model  !! the C pointer
      type(model_handle_t), pointer, intent(out) :: handle  !! what it points to (null on error)
      type(error_t), allocatable, intent(out) :: error  !! a null or empty handle
      handle => null()
      if (.not. c_associated(model)) then
         call set_error(error, err_invalid_parameter, "the model is a null pointer (make it with hillstab_model_new)")
         return
      end if
      call c_f_pointer(model, handle)
      if (.not. allocated(handle%model)) then
         handle => null()
         call set_error(error, err_invalid_parameter, "the model handle holds no model")
      end if
   end subroutine handle_model

   !> `int hillstab_model_new(const char *name, hillstab_model **model)`: a model of the
   !> registry by name (any case), its data at their defaults; `*model` untouched on failure
   !> (an unknown name: the message lists the known ones). Free it with hillstab_model_free.
   function hillstab_c_model_new(name, model) result(status) bind(C, name="hillstab_model_new")
      character(kind=c_char), intent(in) :: name(*)  !! the model's name, NUL-terminated
      type(c_ptr), intent(inout) :: model  !! receives the handle
      integer(c_int) :: status
      type(model_handle_t), pointer :: handle
      type(error_t), allocatable :: error
      character(len=:), allocatable :: text
      logical :: ok
      call c_text(name, text, ok)
      if (.not. ok) then
         call set_error(error, err_invalid_parameter, "the model name is longer than "//integer_text(max_c_text)// &
            " characters")
      else
         allocate (handle)
         call new_model(text, handle%model, error)
         if (allocated(error)) then
            deallocate (handle)
         else
            model = c_loc(handle)
         end if
      end if
      call record_outcome(error)
      status = 0
      if (allocated(error)) status = int(error%code, c_int)
   end function hillstab_c_model_new

   !> `void hillstab_model_free(hillstab_model *model)`: release a model (a null pointer is
   !> ignored).
   subroutine hillstab_c_model_free(model) bind(C, name="hillstab_model_free")
      type(c_ptr), value, intent(in) :: model  !! the handle, or NULL
      type(model_handle_t), pointer :: handle
      if (.not. c_associated(model)) return
      call c_f_pointer(model, handle)
      deallocate (handle)
   end subroutine hillstab_c_model_free

   !> `int hillstab_model_set(hillstab_model *model, const char *variable, const double
   !> *values, size_t count)`: set a variable of the model (its `set_values`) to `count`
   !> numbers; err_invalid_parameter naming the model and the variable when it has no such
   !> variable or refuses the numbers. Whether the model is then complete is checked by
   !> hillstab_model_check and by every computation.
   function hillstab_c_model_set(model, variable, values, count) result(status) bind(C, name="hillstab_model_set")
      type(c_ptr), value, intent(in) :: model  !! the handle
      character(kind=c_char), intent(in) :: variable(*)  !! the variable's name, NUL-terminated
      integer(c_size_t), value, intent(in) :: count  !! how many numbers
      real(c_double), intent(in) :: values(*)  !! the numbers
      integer(c_int) :: status
      type(model_handle_t), pointer :: handle
      type(error_t), allocatable :: error
      character(len=:), allocatable :: name, refusal
      logical :: ok, known
      call handle_model(model, handle, error)
      if (.not. allocated(error)) then
         call c_text(variable, name, ok)
         if (.not. ok) then
            call set_error(error, err_invalid_parameter, "the variable name is longer than "// &
               integer_text(max_c_text)//" characters")
         else
            call values_count_refusal(handle%model, name, count, known, refusal)
            if (len(refusal) > 0) then
               call set_error(error, err_invalid_parameter, refusal)
            else if (known) then
               call handle%model%set_values(name, real(values(1:count), wp), error)
            else
               call handle%model%set_values(name, [real(wp) ::], error)
            end if
         end if
      end if
      call record_outcome(error)
      status = 0
      if (allocated(error)) status = int(error%code, c_int)
   end function hillstab_c_model_set

   !> `int hillstab_model_set_text(hillstab_model *model, const char *variable, const char
   !> *text)`: set a text variable of the model (an equation's parameters, stiffness,
   !> frequency, axes: its `set_text`); err_invalid_parameter naming the model and the
   !> variable when it has no such variable or the text is too long. What the texts say
   !> together (they parse, the axes are parameters) is checked by hillstab_model_check and
   !> by every computation.
   function hillstab_c_model_set_text(model, variable, text) result(status) bind(C, name="hillstab_model_set_text")
      type(c_ptr), value, intent(in) :: model  !! the handle
      character(kind=c_char), intent(in) :: variable(*)  !! the variable's name, NUL-terminated
      character(kind=c_char), intent(in) :: text(*)  !! its text, NUL-terminated
      integer(c_int) :: status
      type(model_handle_t), pointer :: handle
      type(error_t), allocatable :: error
      character(len=:), allocatable :: name, value
      logical :: ok
      call handle_model(model, handle, error)
      if (.not. allocated(error)) then
         call c_text(variable, name, ok)
         if (.not. ok) call set_error(error, err_invalid_parameter, "the variable name is longer than "// &
            integer_text(max_c_text)//" characters")
      end if
      if (.not. allocated(error)) then
         call c_text(text, value, ok)
         if (.not. ok) then
            call set_error(error, err_invalid_parameter, name//": the text is longer than "// &
               integer_text(max_c_text)//" characters")
         else
            call handle%model%set_text(name, value, error)
         end if
      end if
      call record_outcome(error)
      status = 0
      if (allocated(error)) status = int(error%code, c_int)
   end function hillstab_c_model_set_text

   !> `int hillstab_model_check(const hillstab_model *model)`: whether the model is complete
   !> and consistent (its `check_values`): 0, or err_invalid_parameter naming what is missing.
   function hillstab_c_model_check(model) result(status) bind(C, name="hillstab_model_check")
      type(c_ptr), value, intent(in) :: model  !! the handle
      integer(c_int) :: status
      type(model_handle_t), pointer :: handle
      type(error_t), allocatable :: error
      call handle_model(model, handle, error)
      if (.not. allocated(error)) call handle%model%check_values(error)
      call record_outcome(error)
      status = 0
      if (allocated(error)) status = int(error%code, c_int)
   end function hillstab_c_model_check

   !> `int hillstab_model_count(void)`: the number of models in the registry.
   function hillstab_c_model_count() result(count) bind(C, name="hillstab_model_count")
      integer(c_int) :: count
      count = int(model_count, c_int)
   end function hillstab_c_model_count

   !> `int hillstab_model_registry_name(int index, char *buffer, size_t length)`: the name of
   !> the registry's model `index` (1 … hillstab_model_count(); also its HILLSTAB_MODEL_*
   !> code), NUL-terminated and cut to `length` bytes.
   function hillstab_c_model_registry_name(index, buffer, length) result(status) &
      bind(C, name="hillstab_model_registry_name")
      integer(c_int), value, intent(in) :: index  !! 1 … hillstab_model_count()
      integer(c_size_t), value, intent(in) :: length  !! size of buffer in bytes
      character(kind=c_char), intent(inout) :: buffer(*)  !! receives the name
      integer(c_int) :: status
      type(error_t), allocatable :: error
      if (index < 1 .or. index > model_count) then
         call set_error(error, err_invalid_parameter, "model index "//integer_text(int(index))// &
            " outside 1 to "//integer_text(model_count))
      else
         call copy_text(trim(model_names(index)), buffer, length)
      end if
      call record_outcome(error)
      status = 0
      if (allocated(error)) status = int(error%code, c_int)
   end function hillstab_c_model_registry_name

   !> `int hillstab_model_name(const hillstab_model *model, char *buffer, size_t length)`:
   !> the model's name, as a scene's `&scene model` gives it.
   function hillstab_c_model_name(model, buffer, length) result(status) bind(C, name="hillstab_model_name")
      type(c_ptr), value, intent(in) :: model  !! the handle
      integer(c_size_t), value, intent(in) :: length  !! size of buffer in bytes
      character(kind=c_char), intent(inout) :: buffer(*)  !! receives the name
      integer(c_int) :: status
      type(model_handle_t), pointer :: handle
      type(error_t), allocatable :: error
      call handle_model(model, handle, error)
      if (.not. allocated(error)) call copy_text(handle%model%name(), buffer, length)
      call record_outcome(error)
      status = 0
      if (allocated(error)) status = int(error%code, c_int)
   end function hillstab_c_model_name

   !> `int hillstab_model_formula(const hillstab_model *model, char *buffer, size_t length)`:
   !> the coefficient Q as output headers state it.
   function hillstab_c_model_formula(model, buffer, length) result(status) bind(C, name="hillstab_model_formula")
      type(c_ptr), value, intent(in) :: model  !! the handle
      integer(c_size_t), value, intent(in) :: length  !! size of buffer in bytes
      character(kind=c_char), intent(inout) :: buffer(*)  !! receives the formula
      integer(c_int) :: status
      type(model_handle_t), pointer :: handle
      type(error_t), allocatable :: error
      call handle_model(model, handle, error)
      if (.not. allocated(error)) call copy_text(handle%model%formula(), buffer, length)
      call record_outcome(error)
      status = 0
      if (allocated(error)) status = int(error%code, c_int)
   end function hillstab_c_model_formula

   !> `int hillstab_model_tau_rate(const hillstab_model *model, size_t n, const double *alpha,
   !> const double *beta, double *rate)`: dτ/dt at the n points (α_j, β_j), which turns a
   !> rate per unit τ (μ) into one per unit of the model's own time t: an equation's Ω/π at
   !> the point; 0 for a model in τ alone (the elastic and Mathieu models) and at a point
   !> outside the domain. The model must be complete (`hillstab_model_check`).
   function hillstab_c_model_tau_rate(model, n, alpha, beta, rate) result(status) &
      bind(C, name="hillstab_model_tau_rate")
      type(c_ptr), value, intent(in) :: model  !! the handle
      integer(c_size_t), value, intent(in) :: n  !! the number of points
      real(c_double), intent(in) :: alpha(*), beta(*)  !! the points
      real(c_double), intent(inout) :: rate(*)  !! receives dτ/dt at each point
      integer(c_int) :: status
      type(model_handle_t), pointer :: handle
      type(error_t), allocatable :: error
      integer(int64) :: j
      call handle_model(model, handle, error)
      if (.not. allocated(error)) call handle%model%check_values(error)
      if (.not. allocated(error)) then
         do j = 1, int(n, int64)
            rate(j) = handle%model%tau_rate(real(alpha(j), wp), real(beta(j), wp))
         end do
      end if
      call record_outcome(error)
      status = 0
      if (allocated(error)) status = int(error%code, c_int)
   end function hillstab_c_model_tau_rate

   !> `int hillstab_model_variable_count(const hillstab_model *model, int *count)`: how many
   !> variables the model has (0 for the elastic and the Mathieu model).
   function hillstab_c_model_variable_count(model, count) result(status) bind(C, name="hillstab_model_variable_count")
      type(c_ptr), value, intent(in) :: model  !! the handle
      integer(c_int), intent(inout) :: count  !! receives the number of variables
      integer(c_int) :: status
      type(model_handle_t), pointer :: handle
      type(error_t), allocatable :: error
      type(model_variable_t), allocatable :: variables(:)
      call handle_model(model, handle, error)
      if (.not. allocated(error)) then
         variables = handle%model%variables()
         count = int(size(variables), c_int)
      end if
      call record_outcome(error)
      status = 0
      if (allocated(error)) status = int(error%code, c_int)
   end function hillstab_c_model_variable_count

   !> `int hillstab_model_variable_name(const hillstab_model *model, int index, char *name,
   !> size_t length, int *max_count)`: the name of variable `index` (1 … count) and the most
   !> numbers it takes.
   function hillstab_c_model_variable_name(model, index, buffer, length, max_count) result(status) &
      bind(C, name="hillstab_model_variable_name")
      type(c_ptr), value, intent(in) :: model  !! the handle
      integer(c_int), value, intent(in) :: index  !! 1 … hillstab_model_variable_count
      integer(c_size_t), value, intent(in) :: length  !! size of buffer in bytes
      character(kind=c_char), intent(inout) :: buffer(*)  !! receives the name
      integer(c_int), intent(inout) :: max_count  !! receives the most numbers it takes
      integer(c_int) :: status
      type(model_handle_t), pointer :: handle
      type(error_t), allocatable :: error
      type(model_variable_t), allocatable :: variables(:)
      call handle_model(model, handle, error)
      if (.not. allocated(error)) then
         variables = handle%model%variables()
         if (index < 1 .or. index > size(variables)) then
            call set_error(error, err_invalid_parameter, "variable index "//integer_text(int(index))// &
               " outside 1 to "//integer_text(size(variables))//" of the "//handle%model%name()//" model")
         else
            call copy_text(trim(variables(index)%name), buffer, length)
            max_count = int(variables(index)%max_count, c_int)
         end if
      end if
      call record_outcome(error)
      status = 0
      if (allocated(error)) status = int(error%code, c_int)
   end function hillstab_c_model_variable_name
end module hillstab_interop_capi_models

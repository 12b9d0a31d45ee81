!> C-callable critical drives (hillstab_curves_critical): at a fixed β, every α of a range
!> where the stability of the model's equation changes, each with its error bound, the side
!> of the threshold it reaches (S = +T or −T), the direction of the change and whether the
!> verdicts on both sides confirm it. Conventions as in hillstab_interop_capi; bad input (an
!> empty or non-finite range, α outside the model's domain, fewer than 2 samples, ε < 0, a
!> tolerance outside (0, 1)) fails the call naming the argument, the outputs untouched.
!>
!>```c
!> double alpha[8], error[8]; int side[8], direction[8], status[8]; size_t count;
!> hillstab_critical_drives(mathieu, -0.0786, 0.0, 4.93, 0.002, HILLSTAB_METHOD_AUTO, 1e-12, 400, 8,
!>                          alpha, error, side, direction, status, &count);
!>```
module hillstab_interop_capi_critical
   use, intrinsic :: iso_c_binding, only: c_int, c_double, c_size_t, c_ptr, c_f_pointer, c_associated
   use hillstab_core_kinds, only: wp
   use hillstab_core_error, only: error_t, set_error, err_invalid_parameter
   use hillstab_integrate_monodromy, only: method_t, method_takes_scalars, method_names_text
   use hillstab_core_text, only: integer_text
   use hillstab_curves_critical, only: critical_drive_t, critical_drives_along, along_alpha, along_beta
   use hillstab_interop_outcome, only: record_outcome
   use hillstab_interop_capi_models, only: model_handle_t, handle_model
   implicit none
   private
   public :: hillstab_c_critical_drives, hillstab_c_critical_drives_along

contains

   !> `int hillstab_critical_drives(const hillstab_model *model, double beta, double
   !> alpha_min, double alpha_max, double epsilon, int method, double tolerance, int
   !> n_samples, size_t capacity, double *alpha, double *alpha_error, int *side, int
   !> *direction, int *status, size_t *count)`: the `*count` values of α in [alpha_min,
   !> alpha_max] where the stability at β and damping ε changes, ascending, the first
   !> `capacity` stored: α, the bound of its error, side (+1: S reaches +2 cosh(εP/2), −1:
   !> −2 cosh(εP/2)), direction (+1: stable below, unstable above; −1 the reverse) and status
   !> (0 confirmed on both sides, 2 not). `method` computes S (HILLSTAB_METHOD_*; `tolerance`
   !> its target and that of α, relative to max(1, |α|)); `n_samples` values of α are sampled.
   function hillstab_c_critical_drives(model, beta, alpha_min, alpha_max, epsilon, method, tolerance, n_samples, &
                                       capacity, alpha, alpha_error, side, direction, status, count) result(info) &
      bind(C, name="hillstab_critical_drives")
      type(c_ptr), value, intent(in) :: model  !! the model handle
      real(c_double), value, intent(in) :: beta  !! the fixed β
      real(c_double), value, intent(in) :: alpha_min, alpha_max  !! the range of α
      real(c_double), value, intent(in) :: epsilon  !! damping ε ≥ 0
      integer(c_int), value, intent(in) :: method  !! HILLSTAB_METHOD_*
      real(c_double), value, intent(in) :: tolerance  !! target of S and of α
      integer(c_int), value, intent(in) :: n_samples  !! samples of the range (≥ 2)
      integer(c_size_t), value, intent(in) :: capacity  !! entries the arrays hold
      real(c_double), intent(inout) :: alpha(*)  !! α of each change
      real(c_double), intent(inout) :: alpha_error(*)  !! the bound of its error
      integer(c_int), intent(inout) :: side(*)  !! +1 or −1
      integer(c_int), intent(inout) :: direction(*)  !! +1 or −1
      integer(c_int), intent(inout) :: status(*)  !! 0 confirmed, 2 not
      type(c_ptr), value, intent(in) :: count  !! receives the number of changes (a `size_t *`)
      integer(c_int) :: info
      info = critical_entry(model, int(along_alpha, c_int), beta, alpha_min, alpha_max, epsilon, method, tolerance, &
                            n_samples, capacity, alpha, alpha_error, side, direction, status, count)
   end function hillstab_c_critical_drives

   !> `int hillstab_critical_drives_along(const hillstab_model *model, int axis, double
   !> fixed, double low, double high, double epsilon, int method, double tolerance, int
   !> n_samples, size_t capacity, double *value, double *value_error, int *side, int
   !> *direction, int *status, size_t *count)`: `hillstab_critical_drives` along either axis
   !> (`critical_drives_along`): axis 1 searches α in [low, high] at β = fixed, axis 2 β at
   !> α = fixed (an equation's drive amplitude at one frequency); the damping of each point is
   !> the model's (`epsilon` must be 0 for a model with its own).
   function hillstab_c_critical_drives_along(model, axis, fixed, low, high, epsilon, method, tolerance, n_samples, &
                                             capacity, value, value_error, side, direction, status, count) &
      result(info) bind(C, name="hillstab_critical_drives_along")
      type(c_ptr), value, intent(in) :: model  !! the model handle
      integer(c_int), value, intent(in) :: axis  !! 1: along α, 2: along β
      real(c_double), value, intent(in) :: fixed  !! the other coordinate
      real(c_double), value, intent(in) :: low, high  !! the range searched
      real(c_double), value, intent(in) :: epsilon  !! damping ε ≥ 0
      integer(c_int), value, intent(in) :: method  !! HILLSTAB_METHOD_*
      real(c_double), value, intent(in) :: tolerance  !! target of S and of the value
      integer(c_int), value, intent(in) :: n_samples  !! samples of the range (≥ 2)
      integer(c_size_t), value, intent(in) :: capacity  !! entries the arrays hold
      real(c_double), intent(inout) :: value(*)  !! the coordinate of each change
      real(c_double), intent(inout) :: value_error(*)  !! the bound of its error
      integer(c_int), intent(inout) :: side(*)  !! +1 or −1
      integer(c_int), intent(inout) :: direction(*)  !! +1 or −1
      integer(c_int), intent(inout) :: status(*)  !! 0 confirmed, 2 not
      type(c_ptr), value, intent(in) :: count  !! receives the number of changes (a `size_t *`)
      integer(c_int) :: info
      info = critical_entry(model, axis, fixed, low, high, epsilon, method, tolerance, n_samples, capacity, value, &
                            value_error, side, direction, status, count)
   end function hillstab_c_critical_drives_along

   !> Both entry points: the search along `axis`, the arrays filled, the outcome recorded.
   function critical_entry(model, axis, fixed, low, high, epsilon, method, tolerance, n_samples, capacity, alpha, &
                           alpha_error, side, direction, status, count) result(info)
      type(c_ptr), intent(in) :: model
      integer(c_int), intent(in) :: axis
      real(c_double), intent(in) :: fixed, low, high, epsilon, tolerance
      integer(c_int), intent(in) :: method, n_samples
      integer(c_size_t), intent(in) :: capacity
      real(c_double), intent(inout) :: alpha(*), alpha_error(*)
      integer(c_int), intent(inout) :: side(*), direction(*), status(*)
      type(c_ptr), intent(in) :: count
      integer(c_int) :: info
      type(model_handle_t), pointer :: handle
      type(error_t), allocatable :: error
      type(critical_drive_t), allocatable :: drives(:)
      integer(c_size_t), pointer :: found
      integer :: j, stored
      call handle_model(model, handle, error)
      if (.not. allocated(error) .and. .not. c_associated(count)) &
         call set_error(error, err_invalid_parameter, "count: a null pointer")
      if (.not. allocated(error) .and. .not. method_takes_scalars(int(method))) &
         call set_error(error, err_invalid_parameter, "method: unknown method code "//integer_text(int(method))// &
            " (HILLSTAB_METHOD_*: "//method_names_text()//")")
      if (.not. allocated(error) .and. capacity > int(huge(1), c_size_t)) &
         call set_error(error, err_invalid_parameter, "capacity: more than the arrays can index")
      if (.not. allocated(error)) call critical_drives_along(handle%model, int(axis), real(fixed, wp), &
         real(low, wp), real(high, wp), real(epsilon, wp), method_t(kind=int(method), tolerance=real(tolerance, wp)), &
         int(n_samples), drives, error)
      if (.not. allocated(error)) then
         stored = min(size(drives), int(capacity))
         do j = 1, stored
            alpha(j) = drives(j)%alpha
            alpha_error(j) = drives(j)%alpha_error
            side(j) = int(drives(j)%side, c_int)
            direction(j) = int(drives(j)%direction, c_int)
            status(j) = int(drives(j)%status, c_int)
         end do
         call c_f_pointer(count, found)
         found = int(size(drives), c_size_t)
      end if
      call record_outcome(error)
      info = 0
      if (allocated(error)) info = int(error%code, c_int)
   end function critical_entry
end module hillstab_interop_capi_critical

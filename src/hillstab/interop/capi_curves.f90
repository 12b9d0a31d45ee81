!> C-callable transition curves: the β where |S| = 2 (the boundaries of the stability
!> chart) at many α in one call, by the model's route (hillstab_curves_boundaries
!> `exact_boundaries`: Hill's method on the pencil or on the Fourier coefficients of
!> Q − β, or the roots of S), the α values in parallel (OpenMP); the curves of a β window,
!> by β, each with its order n (a_n, b_n), parity (0 where the blocks do not split), the
!> sign of S on it and the bound of its error. Conventions as in hillstab_interop_capi; bad
!> input (α outside the model's domain, an empty window, a bad tolerance) fails the call,
!> outputs untouched.
!>
!>```c
!> double alpha[1] = {5.0}, beta[1][16], bound[1][16]; int order[1][16], parity[1][16], sign[1][16],
!>     coexistent[1][16], status[1]; size_t count[1];
!> hillstab_transition_curves(model, 1, alpha, -2.0, 40.0, 1e-11, 16, 0, &beta[0][0], &order[0][0],
!>     &parity[0][0], &sign[0][0], &bound[0][0], &coexistent[0][0], count, status);
!>```
module hillstab_interop_capi_curves
   use, intrinsic :: iso_c_binding, only: c_int, c_double, c_size_t, c_ptr
   !$ use omp_lib, only: omp_get_max_threads
   use hillstab_core_kinds, only: wp
   use hillstab_core_error, only: error_t, set_error, err_invalid_parameter
   use hillstab_core_status, only: status_ok, status_failed
   use hillstab_core_text, only: real_text, integer_text
   use hillstab_curves_hill_method, only: hill_boundary_t
   use hillstab_curves_boundaries, only: exact_boundaries
   use hillstab_interop_outcome, only: record_outcome
   use hillstab_interop_sizes, only: count_refusal, row_extent
   use hillstab_batch_scene_checks, only: max_grid_count
   use hillstab_interop_capi_models, only: model_handle_t, handle_model
   implicit none
   private
   public :: hillstab_c_transition_curves

   !> The curves found at one α.
   type :: curves_at_t
      type(hill_boundary_t), allocatable :: curves(:)  !! by β
      integer :: code = 0  !! error code (0: found)
      character(len=:), allocatable :: message  !! the error's message
   end type curves_at_t

contains

   !> `int hillstab_transition_curves(const hillstab_model *model, size_t n_alpha, const
   !> double *alpha, double beta_min, double beta_max, double tolerance, size_t capacity, int
   !> threads, double *beta, int *order, int *parity, int *trace_sign, double *error_bound,
   !> int *coexistent, size_t *count, int *status)`: at each α_i the transition curves
   !> crossing [beta_min, beta_max], by β: `count[i]` of them, the first `capacity` stored
   !> in row i of the [n_alpha][capacity] arrays (β on the curve, order n, parity +1 for
   !> a_n (cosine-type) and −1 for b_n, S = trace_sign (+2 or −2) on it, the bound of the
   !> error of β, coexistent 1 when the other curve of the order coincides: a tongue of
   !> zero width). `status[i]` is 2 where Hill's method failed at α_i (count 0), else 0.
   !> `tolerance` is the convergence target on β, relative to max(1, |β|).
   function hillstab_c_transition_curves(model, n_alpha, alpha, beta_min, beta_max, tolerance, capacity, threads, &
                                         beta, order, parity, trace_sign, error_bound, coexistent, count, status) &
      result(info) bind(C, name="hillstab_transition_curves")
      type(c_ptr), value, intent(in) :: model  !! the model handle
      integer(c_size_t), value, intent(in) :: n_alpha  !! number of α values
      real(c_double), intent(in) :: alpha(*)  !! the α values
      real(c_double), value, intent(in) :: beta_min, beta_max  !! the β window
      real(c_double), value, intent(in) :: tolerance  !! convergence target on β
      integer(c_size_t), value, intent(in) :: capacity  !! curves stored per α (the row length)
      integer(c_int), value, intent(in) :: threads  !! threads (0: the OpenMP default)
      real(c_double), intent(inout) :: beta(row_extent(capacity), *)  !! β of each curve
      integer(c_int), intent(inout) :: order(row_extent(capacity), *)  !! its order n
      integer(c_int), intent(inout) :: parity(row_extent(capacity), *)  !! +1 a_n, −1 b_n
      integer(c_int), intent(inout) :: trace_sign(row_extent(capacity), *)  !! S on it: +2 or −2
      real(c_double), intent(inout) :: error_bound(row_extent(capacity), *)  !! bound of the error of β
      integer(c_int), intent(inout) :: coexistent(row_extent(capacity), *)  !! 1: zero-width tongue
      integer(c_size_t), intent(inout) :: count(*)  !! curves found at each α
      integer(c_int), intent(inout) :: status(*)  !! 0, or 2 where Hill's method failed
      integer(c_int) :: info
      type(model_handle_t), pointer :: handle
      type(error_t), allocatable :: error, cause
      type(curves_at_t), allocatable :: found(:)
      integer :: i, k, n, nt, stored
      call handle_model(model, handle, error)
      if (.not. allocated(error)) then
         if (len(count_refusal("n_alpha", n_alpha, max_grid_count)) > 0) then
            call set_error(error, err_invalid_parameter, count_refusal("n_alpha", n_alpha, max_grid_count))
         else if (len(count_refusal("capacity", capacity)) > 0) then
            call set_error(error, err_invalid_parameter, count_refusal("capacity", capacity))
         end if
      end if
      if (.not. allocated(error)) call handle%model%check_values(error)
      if (.not. allocated(error) .and. threads < 0) call set_error(error, err_invalid_parameter, &
         "threads must be >= 0 (0: the OpenMP default), got "//integer_text(int(threads)))
      if (allocated(error)) then
         call record_outcome(error)
         info = int(error%code, c_int)
         return
      end if
      n = int(n_alpha)
      nt = 1
      !$ nt = omp_get_max_threads()
      if (threads > 0) nt = int(threads)
      allocate (found(n))
      !$omp parallel do schedule(dynamic) num_threads(nt) default(shared) private(i, cause)
      do i = 1, n
         call exact_boundaries(handle%model, alpha(i), beta_min, beta_max, tolerance, found(i)%curves, cause)
         if (allocated(cause)) then
            found(i)%code = cause%code
            found(i)%message = cause%message
         end if
      end do
      !$omp end parallel do
      ! bad input is an error of the call, found at the first α it concerns
      do i = 1, n
         if (found(i)%code == err_invalid_parameter) then
            call set_error(error, err_invalid_parameter, "alpha "//integer_text(i - 1)//" (alpha = "// &
               real_text(alpha(i))//"): "//found(i)%message)
            exit
         end if
      end do
      call record_outcome(error)
      if (allocated(error)) then
         info = int(error%code, c_int)
         return
      end if
      do i = 1, n
         if (found(i)%code /= 0) then
            status(i) = int(status_failed, c_int)
            count(i) = 0
            cycle
         end if
         status(i) = int(status_ok, c_int)
         count(i) = int(size(found(i)%curves), c_size_t)
         stored = min(size(found(i)%curves), int(capacity))
         do k = 1, stored
            beta(k, i) = found(i)%curves(k)%beta
            order(k, i) = int(found(i)%curves(k)%order, c_int)
            parity(k, i) = int(found(i)%curves(k)%parity, c_int)
            trace_sign(k, i) = int(found(i)%curves(k)%trace_sign, c_int)
            error_bound(k, i) = found(i)%curves(k)%error_bound
            coexistent(k, i) = int(merge(1, 0, found(i)%curves(k)%coexistent), c_int)
         end do
      end do
      info = 0
   end function hillstab_c_transition_curves
end module hillstab_interop_capi_curves

!> C-callable resonance regions (hillstab_curves_regions): for a driven problem, a model
!> (`hillstab_regions`) or a system (`hillstab_system_regions`), every resonance region of
!> order 1 … `order` predicted in a frequency range (simple 2ν_i = k, sum ν_i + ν_j = k,
!> difference |ν_i − ν_j| = k) and, for each, its tip in a drive range (the least drive at
!> which it opens and the frequency there, with their error bounds), its edges at the top of
!> the drive range and its status. `drive_axis` says which of the model's coordinates is the
!> drive: 1 (along α: the drive is α and the frequency β, as for the built-in models whose α
!> is the drive amplitude, and a system's α Σ drives) or 2 (along β: the drive is β and the
!> frequency α, as for an equation or equations in physical time whose rows are the drive
!> frequency).
!>
!> Conventions as in hillstab_interop_capi_critical (a model) and hillstab_interop_capi_system
!> (a system: every message starts with the entry point's name): a status returned, the full
!> message in the calling thread's `hillstab_last_error`, the outputs untouched on failure.
!> The regions are ascending in their predicted frequency; `*count` receives their number and
!> the first `capacity` are stored in the parallel arrays (two entries a region, one after
!> the other, for `modes`, `window`, `edges` and `clipped`). With `capacity` 0 the arrays may
!> be null (a count only); `count` may never be. Bad input (a null handle or pointer, an axis
!> other than 1 or 2, an empty or non-finite range, a point outside the problem's domain, ε
!> < 0 or ε > 0 for a problem with a damping of its own, an unknown method, a tolerance
!> outside (0, 1), an order outside 1 … 8, fewer than 2 samples) fails the call naming the
!> argument.
!>
!>```c
!> int kind[16], order[16], modes[32], clipped[32], status[16], evaluations[16];
!> double predicted[16], window[32], f[16], f_error[16], d[16], d_error[16], edges[32];
!> size_t count;
!> hillstab_regions(mathieu, 1, 0.5, 12.0, 0.0, 2.0, 0.05, HILLSTAB_METHOD_AUTO, 1e-10, 3, 32, 16, kind,
!>                  order, modes, predicted, window, f, f_error, d, d_error, edges, clipped, status,
!>                  evaluations, &count);
!>```
module hillstab_interop_capi_regions
   use, intrinsic :: iso_c_binding, only: c_int, c_double, c_size_t, c_ptr, c_f_pointer, c_associated
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use hillstab_core_kinds, only: wp
   use hillstab_core_error, only: error_t, set_error, err_invalid_parameter
   use hillstab_core_text, only: integer_text, real_text
   use hillstab_integrate_monodromy, only: method_t, method_takes_scalars, method_names_text
   use hillstab_integrate_system, only: system_method_t
   use hillstab_curves_critical, only: along_alpha, along_beta
   use hillstab_curves_oracle, only: oracle_t, scalar_oracle_t, system_oracle_t
   use hillstab_curves_regions, only: region_t, find_regions
   use hillstab_interop_outcome, only: record_outcome
   use hillstab_interop_capi_models, only: model_handle_t, handle_model
   use hillstab_interop_capi_system, only: system_handle_t, handle_system, check_method_tolerance, &
      own_damping_refusal
   implicit none
   private
   public :: hillstab_c_regions, hillstab_c_system_regions

   !> The names of the output arrays, in the order of the arguments.
   character(len=*), parameter :: output_names(13) = [character(len=15) :: "kind", "order", "modes", "predicted", &
      "window", "frequency", "frequency_error", "drive", "drive_error", "edges", "clipped", "status", "evaluations"]

contains

   !> `int hillstab_regions(const hillstab_model *model, int drive_axis, double f_min, double
   !> f_max, double d_min, double d_max, double epsilon, int method, double tolerance, int
   !> order, int n_samples, size_t capacity, int *kind, int *orders, int *modes, double
   !> *predicted, double *window, double *frequency, double *frequency_error, double *drive,
   !> double *drive_error, double *edges, int *clipped, int *status, int *evaluations, size_t
   !> *count)`: the resonance regions of the model's equation with damping ε (the model's own
   !> for a model that carries it: `epsilon` 0) over f in [f_min, f_max], their tips searched
   !> for drives in [d_min, d_max] (`find_regions`); S by `method` to `tolerance`, also the
   !> target of the tips relative to max(1, |x|); `n_samples` drives sampled for a first root.
   function hillstab_c_regions(model, drive_axis, f_min, f_max, d_min, d_max, epsilon, method, tolerance, order, &
                               n_samples, capacity, kind, orders, modes, predicted, window, frequency, &
                               frequency_error, drive, drive_error, edges, clipped, status, evaluations, count) &
      result(info) bind(C, name="hillstab_regions")
      type(c_ptr), value, intent(in) :: model  !! the model handle
      integer(c_int), value, intent(in) :: drive_axis  !! 1: the drive is α, 2: the drive is β
      real(c_double), value, intent(in) :: f_min, f_max  !! the frequency range
      real(c_double), value, intent(in) :: d_min, d_max  !! the drive range
      real(c_double), value, intent(in) :: epsilon  !! damping ε ≥ 0 (0 for a model with its own)
      integer(c_int), value, intent(in) :: method  !! HILLSTAB_METHOD_*
      real(c_double), value, intent(in) :: tolerance  !! target of S and of the tips, in (0, 1)
      integer(c_int), value, intent(in) :: order  !! highest order k (1 … 8)
      integer(c_int), value, intent(in) :: n_samples  !! samples of the drive range (≥ 2)
      integer(c_size_t), value, intent(in) :: capacity  !! regions the arrays hold
      type(c_ptr), value, intent(in) :: kind  !! receives HILLSTAB_REGION_SIMPLE, _SUM or _DIFFERENCE (`int *`)
      type(c_ptr), value, intent(in) :: orders  !! receives k (`int *`)
      type(c_ptr), value, intent(in) :: modes  !! receives the modes i, j, two a region (`int *`)
      type(c_ptr), value, intent(in) :: predicted  !! receives f of the resonance at drive 0 (`double *`)
      type(c_ptr), value, intent(in) :: window  !! receives the frequencies searched, two a region (`double *`)
      type(c_ptr), value, intent(in) :: frequency  !! receives the tip's f (`double *`)
      type(c_ptr), value, intent(in) :: frequency_error  !! receives its error bound (`double *`)
      type(c_ptr), value, intent(in) :: drive  !! receives the tip's drive (`double *`)
      type(c_ptr), value, intent(in) :: drive_error  !! receives its error bound (`double *`)
      type(c_ptr), value, intent(in) :: edges  !! receives f of the edges at d_max, two a region (`double *`)
      type(c_ptr), value, intent(in) :: clipped  !! receives 1 where an edge is the window's end, two a region
      type(c_ptr), value, intent(in) :: status  !! receives HILLSTAB_REGION_FOUND … _THEORY (`int *`)
      type(c_ptr), value, intent(in) :: evaluations  !! receives the distances computed (`int *`)
      type(c_ptr), value, intent(in) :: count  !! receives the number of regions (a `size_t *`)
      integer(c_int) :: info
      type(model_handle_t), pointer :: handle
      type(scalar_oracle_t) :: oracle
      type(error_t), allocatable :: error
      type(c_ptr) :: outputs(13)
      outputs = [kind, orders, modes, predicted, window, frequency, frequency_error, drive, drive_error, edges, &
                 clipped, status, evaluations]
      call handle_model(model, handle, error)
      call check_common(drive_axis, f_min, f_max, d_min, d_max, epsilon, capacity, outputs, count, error)
      if (.not. allocated(error) .and. .not. method_takes_scalars(int(method))) &
         call set_error(error, err_invalid_parameter, "method: unknown method code "//integer_text(int(method))// &
            " (HILLSTAB_METHOD_*: "//method_names_text()//")")
      if (.not. allocated(error)) call handle%model%check_values(error)
      if (.not. allocated(error)) then
         if (.not. handle%model%takes_scene_damping() .and. epsilon > 0.0_wp) &
            call set_error(error, err_invalid_parameter, "epsilon: the "//handle%model%name()//" model carries "// &
               "its own damping: epsilon must be 0, got "//real_text(real(epsilon, wp)))
      end if
      if (.not. allocated(error)) then
         allocate (oracle%model, source=handle%model)
         oracle%drive_axis = int(drive_axis)
         oracle%method = method_t(kind=int(method), tolerance=real(tolerance, wp))
         oracle%epsilon = real(epsilon, wp)
         call regions_entry(oracle, f_min, f_max, d_min, d_max, tolerance, order, n_samples, capacity, outputs, &
                            count, error)
      end if
      call record_outcome(error)
      info = 0
      if (allocated(error)) info = int(error%code, c_int)
   end function hillstab_c_regions

   !> `int hillstab_system_regions(const hillstab_system *system, int drive_axis, double f_min,
   !> double f_max, double d_min, double d_max, double epsilon, int method, double tolerance,
   !> int order, int n_samples, size_t capacity, int *kind, int *orders, int *modes, double
   !> *predicted, double *window, double *frequency, double *frequency_error, double *drive,
   !> double *drive_error, double *edges, int *clipped, int *status, int *evaluations, size_t
   !> *count)`: `hillstab_regions` for a system with damping ε M (0 for an equations system,
   !> which carries its own); Φ by a system method (HILLSTAB_METHOD_AUTO, _MAGNUS4, _MAGNUS6,
   !> _RK or _GSL) to `tolerance` in (1e-15, 1). Messages start with "hillstab_system_regions: ".
   function hillstab_c_system_regions(system, drive_axis, f_min, f_max, d_min, d_max, epsilon, method, tolerance, &
                                      order, n_samples, capacity, kind, orders, modes, predicted, window, frequency, &
                                      frequency_error, drive, drive_error, edges, clipped, status, evaluations, &
                                      count) result(info) bind(C, name="hillstab_system_regions")
      type(c_ptr), value, intent(in) :: system  !! the system handle
      integer(c_int), value, intent(in) :: drive_axis  !! 1: the drive is α, 2: the drive is β
      real(c_double), value, intent(in) :: f_min, f_max  !! the frequency range
      real(c_double), value, intent(in) :: d_min, d_max  !! the drive range
      real(c_double), value, intent(in) :: epsilon  !! damping ε ≥ 0 (0 for a system with its own)
      integer(c_int), value, intent(in) :: method  !! HILLSTAB_METHOD_AUTO, _MAGNUS4, _MAGNUS6, _RK or _GSL
      real(c_double), value, intent(in) :: tolerance  !! target of Φ and of the tips, in (1e-15, 1)
      integer(c_int), value, intent(in) :: order  !! highest order k (1 … 8)
      integer(c_int), value, intent(in) :: n_samples  !! samples of the drive range (≥ 2)
      integer(c_size_t), value, intent(in) :: capacity  !! regions the arrays hold
      type(c_ptr), value, intent(in) :: kind  !! receives HILLSTAB_REGION_SIMPLE, _SUM or _DIFFERENCE (`int *`)
      type(c_ptr), value, intent(in) :: orders  !! receives k (`int *`)
      type(c_ptr), value, intent(in) :: modes  !! receives the modes i, j, two a region (`int *`)
      type(c_ptr), value, intent(in) :: predicted  !! receives f of the resonance at drive 0 (`double *`)
      type(c_ptr), value, intent(in) :: window  !! receives the frequencies searched, two a region (`double *`)
      type(c_ptr), value, intent(in) :: frequency  !! receives the tip's f (`double *`)
      type(c_ptr), value, intent(in) :: frequency_error  !! receives its error bound (`double *`)
      type(c_ptr), value, intent(in) :: drive  !! receives the tip's drive (`double *`)
      type(c_ptr), value, intent(in) :: drive_error  !! receives its error bound (`double *`)
      type(c_ptr), value, intent(in) :: edges  !! receives f of the edges at d_max, two a region (`double *`)
      type(c_ptr), value, intent(in) :: clipped  !! receives 1 where an edge is the window's end, two a region
      type(c_ptr), value, intent(in) :: status  !! receives HILLSTAB_REGION_FOUND … _THEORY (`int *`)
      type(c_ptr), value, intent(in) :: evaluations  !! receives the distances computed (`int *`)
      type(c_ptr), value, intent(in) :: count  !! receives the number of regions (a `size_t *`)
      integer(c_int) :: info
      character(len=*), parameter :: where = "hillstab_system_regions"
      type(system_handle_t), pointer :: handle
      type(system_oracle_t) :: oracle
      type(error_t), allocatable :: error
      type(c_ptr) :: outputs(13)
      outputs = [kind, orders, modes, predicted, window, frequency, frequency_error, drive, drive_error, edges, &
                 clipped, status, evaluations]
      call handle_system(where, system, handle, error)
      if (allocated(error)) then
         call record_outcome(error)
         info = int(error%code, c_int)
         return
      end if
      call check_common(drive_axis, f_min, f_max, d_min, d_max, epsilon, capacity, outputs, count, error)
      if (.not. allocated(error)) call check_method_tolerance(method, tolerance, error)
      if (.not. allocated(error)) call own_damping_refusal(handle%system, real(epsilon, wp), "", error)
      if (.not. allocated(error)) call handle%system%check_values(error)
      if (.not. allocated(error)) then
         if (handle%system%first_order()) call set_error(error, err_invalid_parameter, "system: a system in "// &
            "first-order form (state) has no natural frequencies to find regions from; write it as M x'' + "// &
            "C x' + K(t) x = 0")
      end if
      if (.not. allocated(error)) then
         allocate (oracle%system, source=handle%system)
         oracle%drive_axis = int(drive_axis)
         oracle%method = system_method_t(int(method), real(tolerance, wp))
         oracle%epsilon = real(epsilon, wp)
         call regions_entry(oracle, f_min, f_max, d_min, d_max, tolerance, order, n_samples, capacity, outputs, &
                            count, error)
      end if
      if (allocated(error)) then
         if (index(error%message, where//": ") /= 1) error%message = where//": "//error%message
      end if
      call record_outcome(error)
      info = 0
      if (allocated(error)) info = int(error%code, c_int)
   end function hillstab_c_system_regions

   !> The arguments both entry points share, checked in order (nothing done when `error` is
   !> already allocated): the pointers, the axis, the ranges, ε and the capacity.
   subroutine check_common(drive_axis, f_min, f_max, d_min, d_max, epsilon, capacity, outputs, count, error)
      integer(c_int), intent(in) :: drive_axis  !! 1 or 2
      real(c_double), intent(in) :: f_min, f_max, d_min, d_max  !! the ranges
      real(c_double), intent(in) :: epsilon  !! the damping
      integer(c_size_t), intent(in) :: capacity  !! regions the arrays hold
      type(c_ptr), intent(in) :: outputs(:)  !! the arrays, in the order of `output_names`
      type(c_ptr), intent(in) :: count  !! the count's pointer
      type(error_t), allocatable, intent(inout) :: error  !! the first refusal
      integer :: k
      if (allocated(error)) return
      if (.not. c_associated(count)) then
         call set_error(error, err_invalid_parameter, "count: a null pointer")
         return
      end if
      if (capacity > int(huge(1)/2, c_size_t)) then
         call set_error(error, err_invalid_parameter, "capacity: more than the arrays can index")
         return
      end if
      if (capacity > 0) then
         do k = 1, size(outputs)
            if (.not. c_associated(outputs(k))) then
               call set_error(error, err_invalid_parameter, trim(output_names(k))//": a null pointer (capacity "// &
                  integer_text(int(capacity))//" > 0)")
               return
            end if
         end do
      end if
      if (drive_axis /= along_alpha .and. drive_axis /= along_beta) then
         call set_error(error, err_invalid_parameter, "drive_axis: 1 (the drive is alpha) or 2 (the drive is "// &
            "beta), got "//integer_text(int(drive_axis)))
      else if (.not. (ieee_is_finite(f_min) .and. ieee_is_finite(f_max))) then
         call set_error(error, err_invalid_parameter, "f_min, f_max: the frequency range must be finite")
      else if (.not. f_max > f_min) then
         call set_error(error, err_invalid_parameter, "f_min, f_max: the frequency range is empty (f_max must "// &
            "exceed f_min, got "//real_text(real(f_min, wp))//" and "//real_text(real(f_max, wp))//")")
      else if (.not. (ieee_is_finite(d_min) .and. ieee_is_finite(d_max))) then
         call set_error(error, err_invalid_parameter, "d_min, d_max: the drive range must be finite")
      else if (.not. d_max > d_min) then
         call set_error(error, err_invalid_parameter, "d_min, d_max: the drive range is empty (d_max must "// &
            "exceed d_min, got "//real_text(real(d_min, wp))//" and "//real_text(real(d_max, wp))//")")
      else if (.not. ieee_is_finite(epsilon)) then
         call set_error(error, err_invalid_parameter, "epsilon: the damping must be finite and >= 0")
      else if (epsilon < 0.0_wp) then
         call set_error(error, err_invalid_parameter, "epsilon: the damping must be finite and >= 0, got "// &
            real_text(real(epsilon, wp)))
      end if
   end subroutine check_common

   !> Both entry points: the regions of the oracle, the arrays filled and the count given.
   subroutine regions_entry(oracle, f_min, f_max, d_min, d_max, tolerance, order, n_samples, capacity, outputs, &
                            count, error)
      class(oracle_t), intent(in) :: oracle  !! the problem, its axis set
      real(c_double), intent(in) :: f_min, f_max, d_min, d_max, tolerance  !! the ranges, the target
      integer(c_int), intent(in) :: order, n_samples  !! highest order, samples of the drive range
      integer(c_size_t), intent(in) :: capacity  !! regions the arrays hold
      type(c_ptr), intent(in) :: outputs(:)  !! the arrays, in the order of `output_names`
      type(c_ptr), intent(in) :: count  !! the count's pointer
      type(error_t), allocatable, intent(out) :: error  !! the search's refusal or failure
      type(region_t), allocatable :: regions(:)
      integer(c_int), pointer :: kind(:), orders(:), modes(:), clipped(:), status(:), evaluations(:)
      real(c_double), pointer :: predicted(:), window(:), frequency(:), frequency_error(:), drive(:), &
         drive_error(:), edges(:)
      integer(c_size_t), pointer :: found
      integer :: j, n
      call oracle%check(real(f_min, wp), real(d_min, wp), error)
      if (allocated(error)) then
         error%message = "f_min, d_min: "//error%message
         return
      end if
      call oracle%check(real(f_max, wp), real(d_max, wp), error)
      if (allocated(error)) then
         error%message = "f_max, d_max: "//error%message
         return
      end if
      call find_regions(oracle, real(f_min, wp), real(f_max, wp), real(d_min, wp), real(d_max, wp), int(order), &
                        real(tolerance, wp), int(n_samples), regions, error)
      if (allocated(error)) return
      n = min(size(regions), int(capacity))
      if (n > 0) then
         call c_f_pointer(outputs(1), kind, [n])
         call c_f_pointer(outputs(2), orders, [n])
         call c_f_pointer(outputs(3), modes, [2*n])
         call c_f_pointer(outputs(4), predicted, [n])
         call c_f_pointer(outputs(5), window, [2*n])
         call c_f_pointer(outputs(6), frequency, [n])
         call c_f_pointer(outputs(7), frequency_error, [n])
         call c_f_pointer(outputs(8), drive, [n])
         call c_f_pointer(outputs(9), drive_error, [n])
         call c_f_pointer(outputs(10), edges, [2*n])
         call c_f_pointer(outputs(11), clipped, [2*n])
         call c_f_pointer(outputs(12), status, [n])
         call c_f_pointer(outputs(13), evaluations, [n])
         do j = 1, n
            kind(j) = int(regions(j)%kind, c_int)
            orders(j) = int(regions(j)%order, c_int)
            modes(2*j - 1:2*j) = int(regions(j)%modes, c_int)
            predicted(j) = regions(j)%predicted
            window(2*j - 1:2*j) = regions(j)%window
            frequency(j) = regions(j)%frequency
            frequency_error(j) = regions(j)%frequency_error
            drive(j) = regions(j)%drive
            drive_error(j) = regions(j)%drive_error
            edges(2*j - 1:2*j) = regions(j)%edges
            clipped(2*j - 1:2*j) = merge(1_c_int, 0_c_int, regions(j)%clipped)
            status(j) = int(regions(j)%status, c_int)
            evaluations(j) = int(regions(j)%evaluations, c_int)
         end do
      end if
      call c_f_pointer(count, found)
      found = int(size(regions), c_size_t)
   end subroutine regions_entry
end module hillstab_interop_capi_regions

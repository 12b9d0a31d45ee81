!> Tests of the C entry points of the resonance regions (hillstab_interop_capi_regions),
!> called from Fortran as C calls them: the damped Mathieu equation in physical time (a model
!> handle, along β) and a damped one-degree system (a system handle, along α) give every
!> field of `find_regions` called directly on the same problem, to the bit; the undamped
!> Mathieu model's tips are its resonances at drive 0; the capacity stores the first regions
!> and counts them all; bad input fails with its code, the argument named and the outputs
!> untouched.
module test_capi_regions
   use, intrinsic :: iso_c_binding, only: c_int, c_double, c_char, c_size_t, c_null_char, c_ptr, c_null_ptr, &
      c_associated, c_loc
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   use hillstab_core_kinds, only: wp, pi
   use hillstab_core_error, only: error_t, err_invalid_parameter
   use hillstab_core_text, only: integer_text
   use hillstab_hill_model_equation, only: equation_model_t
   use hillstab_hill_model_mathieu, only: mathieu_model_t
   use hillstab_hill_system_matrix, only: matrix_system_t
   use hillstab_integrate_monodromy, only: method_t, method_auto
   use hillstab_integrate_system, only: system_method_t, system_auto
   use hillstab_curves_critical, only: along_alpha, along_beta
   use hillstab_curves_oracle, only: oracle_t, scalar_oracle_t, system_oracle_t
   use hillstab_curves_regions, only: region_t, find_regions, region_simple, region_found, region_theory
   use hillstab_interop_capi, only: hillstab_c_last_error
   use hillstab_interop_capi_models, only: hillstab_c_model_new, hillstab_c_model_free, hillstab_c_model_set_text
   use hillstab_interop_capi_system, only: hillstab_c_system_new, hillstab_c_system_free, hillstab_c_system_set, &
      hillstab_c_system_check
   use hillstab_interop_capi_regions
   use hillstab_testing
   implicit none
   private
   public :: collect_capi_regions

   !> Regions the tests' arrays hold.
   integer, parameter :: places = 16

   !> The outputs of one call, with the count.
   type :: outputs_t
      integer(c_int) :: kind(places) = -7, orders(places) = -7, modes(2*places) = -7, clipped(2*places) = -7
      integer(c_int) :: status(places) = -7, evaluations(places) = -7
      real(c_double) :: predicted(places) = -7.0_wp, window(2*places) = -7.0_wp, frequency(places) = -7.0_wp
      real(c_double) :: frequency_error(places) = -7.0_wp, drive(places) = -7.0_wp, drive_error(places) = -7.0_wp
      real(c_double) :: edges(2*places) = -7.0_wp
      integer(c_size_t) :: count = 777
   end type outputs_t

   !> The arguments of one call (the damped Mathieu equation's by default).
   type :: call_t
      integer(c_int) :: axis = along_beta
      real(c_double) :: f_min = 1.5_wp, f_max = 2.5_wp, d_min = 0.0_wp, d_max = 0.3_wp, epsilon = 0.0_wp
      integer(c_int) :: method = method_auto
      real(c_double) :: tolerance = 1.0e-9_wp
      integer(c_int) :: order = 1, n_samples = 16
      integer(c_size_t) :: capacity = places
   end type call_t

contains

   function collect_capi_regions() result(suite)
      type(testsuite_t) :: suite
      suite = new_testsuite("capi_regions", [ &
         new_unittest("equation_matches_direct", equation_matches_direct), &
         new_unittest("system_matches_direct", system_matches_direct), &
         new_unittest("mathieu_theory_tips", mathieu_theory_tips), &
         new_unittest("capacity_and_count", capacity_and_count), &
         new_unittest("bad_input_named", bad_input_named), &
         new_unittest("system_bad_input_named", system_bad_input_named)])
   end function collect_capi_regions

   !> The calling thread's last message.
   function last_message() result(text)
      character(len=:), allocatable :: text
      character(kind=c_char) :: buffer(1024)
      integer(c_int) :: code
      integer :: i
      code = hillstab_c_last_error(buffer, size(buffer, kind=c_size_t))
      text = ""
      do i = 1, size(buffer)
         if (buffer(i) == c_null_char) exit
         text = text//buffer(i)
      end do
   end function last_message

   !> `hillstab_regions` with the arguments of `a` into `out` (null arrays when `null_arrays`).
   integer(c_int) function c_regions(model, a, out, null_arrays) result(code)
      type(c_ptr), intent(in) :: model
      type(call_t), intent(in) :: a
      type(outputs_t), intent(inout), target :: out
      logical, intent(in), optional :: null_arrays
      type(c_ptr) :: p(14)
      call pointers(out, p, null_arrays)
      code = hillstab_c_regions(model, a%axis, a%f_min, a%f_max, a%d_min, a%d_max, a%epsilon, a%method, a%tolerance, &
                                a%order, a%n_samples, a%capacity, p(1), p(2), p(3), p(4), p(5), p(6), p(7), p(8), &
                                p(9), p(10), p(11), p(12), p(13), p(14))
   end function c_regions

   !> `hillstab_system_regions` with the arguments of `a` into `out`.
   integer(c_int) function c_system_regions(system, a, out, null_arrays) result(code)
      type(c_ptr), intent(in) :: system
      type(call_t), intent(in) :: a
      type(outputs_t), intent(inout), target :: out
      logical, intent(in), optional :: null_arrays
      type(c_ptr) :: p(14)
      call pointers(out, p, null_arrays)
      code = hillstab_c_system_regions(system, a%axis, a%f_min, a%f_max, a%d_min, a%d_max, a%epsilon, a%method, &
                                       a%tolerance, a%order, a%n_samples, a%capacity, p(1), p(2), p(3), p(4), p(5), &
                                       p(6), p(7), p(8), p(9), p(10), p(11), p(12), p(13), p(14))
   end function c_system_regions

   !> The pointers of the outputs in the order of the arguments (the arrays null when asked).
   subroutine pointers(out, p, null_arrays)
      type(outputs_t), intent(inout), target :: out
      type(c_ptr), intent(out) :: p(14)
      logical, intent(in), optional :: null_arrays
      p = [c_loc(out%kind), c_loc(out%orders), c_loc(out%modes), c_loc(out%predicted), c_loc(out%window), &
           c_loc(out%frequency), c_loc(out%frequency_error), c_loc(out%drive), c_loc(out%drive_error), &
           c_loc(out%edges), c_loc(out%clipped), c_loc(out%status), c_loc(out%evaluations), c_loc(out%count)]
      if (present(null_arrays)) then
         if (null_arrays) p(1:13) = c_null_ptr
      end if
   end subroutine pointers

   !> Whether the C outputs hold exactly the regions of `find_regions`.
   subroutine check_same(ctx, out, regions, where)
      type(test_context_t), intent(inout) :: ctx
      type(outputs_t), intent(in) :: out
      type(region_t), intent(in) :: regions(:)
      character(len=*), intent(in) :: where
      integer :: j, n
      call check(ctx, int(out%count) == size(regions), where//": count "//integer_text(int(out%count))// &
                 ", find_regions "//integer_text(size(regions)))
      n = min(size(regions), places, int(out%count))
      do j = 1, n
         call check(ctx, out%kind(j) == regions(j)%kind .and. out%orders(j) == regions(j)%order .and. &
                    all(out%modes(2*j - 1:2*j) == regions(j)%modes) .and. out%status(j) == regions(j)%status .and. &
                    out%evaluations(j) == regions(j)%evaluations .and. &
                    all((out%clipped(2*j - 1:2*j) == 1) .eqv. regions(j)%clipped), &
                    where//": the integers of region "//integer_text(j))
         call check(ctx, out%predicted(j) == regions(j)%predicted .and. &
                    all(out%window(2*j - 1:2*j) == regions(j)%window) .and. &
                    out%frequency(j) == regions(j)%frequency .and. &
                    out%frequency_error(j) == regions(j)%frequency_error .and. out%drive(j) == regions(j)%drive .and. &
                    out%drive_error(j) == regions(j)%drive_error .and. all(out%edges(2*j - 1:2*j) == regions(j)%edges), &
                    where//": the reals of region "//integer_text(j)//" to the bit")
      end do
      call check(ctx, all(out%kind(n + 1:) == -7) .and. all(out%drive(n + 1:) == -7.0_wp), &
                 where//": nothing stored beyond the regions")
   end subroutine check_same

   !> The damped Mathieu equation x'' + 2ζx' + (1 + h cos Wt) x = 0 (α = W, β = h) as a text.
   subroutine equation_texts(ctx, model)
      type(test_context_t), intent(inout) :: ctx
      type(c_ptr), intent(in) :: model
      character(len=*), parameter :: names(6) = [character(len=10) :: "parameters", "stiffness", "damping", &
         "frequency", "alpha", "beta"]
      character(len=*), parameter :: texts(6) = [character(len=28) :: "zeta = 0.01, h = 0, W = 2", &
         "1 + h*cos(W*t)", "2*zeta", "W", "W", "h"]
      integer :: k
      do k = 1, size(names)
         call check(ctx, hillstab_c_model_set_text(model, trim(names(k))//c_null_char, trim(texts(k))//c_null_char) &
                    == 0, "set "//trim(names(k))//": "//last_message())
      end do
   end subroutine equation_texts

   !> A handle of the named model.
   function new_model(ctx, name) result(model)
      type(test_context_t), intent(inout) :: ctx
      character(len=*), intent(in) :: name
      type(c_ptr) :: model
      model = c_null_ptr
      call check(ctx, hillstab_c_model_new(name//c_null_char, model) == 0 .and. c_associated(model), "new "//name)
   end function new_model

   !> The damped Mathieu equation through the C API against `find_regions` on the same
   !> equation made directly: every field to the bit; the principal region's tip at W ≈ 2,
   !> h ≈ 4ζ.
   subroutine equation_matches_direct(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(c_ptr) :: model
      type(outputs_t) :: out
      type(call_t) :: a
      type(scalar_oracle_t) :: oracle
      type(equation_model_t) :: e
      type(region_t), allocatable :: regions(:)
      type(error_t), allocatable :: error
      integer :: k
      model = new_model(ctx, "equation")
      call equation_texts(ctx, model)
      call check(ctx, c_regions(model, a, out) == 0, "hillstab_regions: "//last_message())
      call hillstab_c_model_free(model)
      call e%set_text("parameters", "zeta = 0.01, h = 0, W = 2", error)
      if (.not. allocated(error)) call e%set_text("stiffness", "1 + h*cos(W*t)", error)
      if (.not. allocated(error)) call e%set_text("damping", "2*zeta", error)
      if (.not. allocated(error)) call e%set_text("frequency", "W", error)
      if (.not. allocated(error)) call e%set_text("alpha", "W", error)
      if (.not. allocated(error)) call e%set_text("beta", "h", error)
      if (.not. allocated(error)) call e%check_values(error)
      call check(ctx, .not. allocated(error), "the equation made directly")
      if (allocated(error)) return
      allocate (oracle%model, source=e)
      oracle%drive_axis = along_beta
      oracle%method = method_t(kind=method_auto, tolerance=a%tolerance)
      call find_regions(oracle, a%f_min, a%f_max, a%d_min, a%d_max, a%order, a%tolerance, a%n_samples, regions, error)
      call check(ctx, .not. allocated(error), "find_regions")
      if (allocated(error)) return
      call check_same(ctx, out, regions, "equation")
      k = findloc(out%kind(:min(places, int(out%count))), region_simple, 1)
      call check(ctx, k > 0, "a simple region")
      if (k == 0) return
      call check(ctx, out%status(k) == region_found, "the principal region found")
      call check(ctx, abs(out%drive(k) - 0.04_wp) < 1.0e-3_wp*0.04_wp, "its tip h near 4 zeta")
      call check(ctx, abs(out%frequency(k) - 2.0_wp) < 1.0e-2_wp, "its tip W near 2")
   end subroutine equation_matches_direct

   !> Set a variable of a system to one number through the C entry point; its status.
   integer(c_int) function c_set(system, name, value) result(status)
      type(c_ptr), intent(in) :: system
      character(len=*), intent(in) :: name
      real(c_double), intent(in) :: value
      character(kind=c_char), target :: chars(len(name) + 1)
      real(c_double), target :: values(1)
      integer :: i
      do i = 1, len(name)
         chars(i) = name(i:i)
      end do
      chars(len(name) + 1) = c_null_char
      values = value
      status = hillstab_c_system_set(system, c_loc(chars), c_loc(values), 1_c_size_t)
   end function c_set

   !> A damped one-degree system x'' + c x' + (β + α cos πτ) x = 0 through the C API (along α)
   !> against `find_regions` on the same system made directly.
   subroutine system_matches_direct(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(c_ptr), target :: system
      type(outputs_t) :: out
      type(call_t) :: a
      type(system_oracle_t) :: oracle
      type(matrix_system_t) :: s
      type(region_t), allocatable :: regions(:)
      type(error_t), allocatable :: error
      system = c_null_ptr
      call check(ctx, hillstab_c_system_new(c_loc(system)) == 0, "new")
      call check(ctx, c_set(system, "n", 1.0_wp) == 0, "n")
      call check(ctx, c_set(system, "damping", 0.05_wp) == 0, "damping")
      call check(ctx, c_set(system, "cos", 1.0_wp) == 0, "cos")
      call check(ctx, hillstab_c_system_check(system) == 0, "check: "//last_message())
      a = call_t(axis=along_alpha, f_min=1.5_wp, f_max=3.5_wp, d_min=0.0_wp, d_max=1.0_wp, method=system_auto)
      call check(ctx, c_system_regions(system, a, out) == 0, "hillstab_system_regions: "//last_message())
      call hillstab_c_system_free(system)
      call s%set_values("n", [1.0_wp], error)
      if (.not. allocated(error)) call s%set_values("damping", [0.05_wp], error)
      if (.not. allocated(error)) call s%set_values("cos", [1.0_wp], error)
      if (.not. allocated(error)) call s%check_values(error)
      call check(ctx, .not. allocated(error), "the system made directly")
      if (allocated(error)) return
      allocate (oracle%system, source=s)
      oracle%drive_axis = along_alpha
      oracle%method = system_method_t(system_auto, a%tolerance)
      call find_regions(oracle, a%f_min, a%f_max, a%d_min, a%d_max, a%order, a%tolerance, a%n_samples, regions, error)
      call check(ctx, .not. allocated(error), "find_regions")
      if (allocated(error)) return
      call check(ctx, size(regions) == 1, "one region of order 1 in range")
      call check_same(ctx, out, regions, "system")
      if (size(regions) == 1) then
         ! 2ν = 1 at drive 0, ν = √(β − c²/4)/π the damped frequency: β = π²/4 + c²/4; the tip
         ! lies at α ≈ 2c√β (first order)
         call check(ctx, abs(regions(1)%predicted - (pi**2 + 0.05_wp**2)/4.0_wp) < 1.0e-9_wp, &
                    "predicted at (pi^2 + c^2)/4")
         call check(ctx, regions(1)%status == region_found .and. abs(regions(1)%drive - 0.05_wp*pi) < 0.01_wp, &
                    "tip near alpha = 2 c sqrt(beta)")
      end if
   end subroutine system_matches_direct

   !> The undamped Mathieu model (drive α, frequency β): status theory, the tips at β = (kπ/2)²
   !> and drive 0, each simple region of order k.
   subroutine mathieu_theory_tips(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(c_ptr) :: model
      type(outputs_t) :: out
      type(call_t) :: a
      integer :: j
      model = new_model(ctx, "mathieu")
      a = call_t(axis=along_alpha, f_min=0.5_wp, f_max=10.5_wp, d_min=0.0_wp, d_max=1.0_wp, order=2)
      call check(ctx, c_regions(model, a, out) == 0, "hillstab_regions: "//last_message())
      call hillstab_c_model_free(model)
      call check(ctx, out%count == 2, "two regions, got "//integer_text(int(out%count)))
      do j = 1, min(2, int(out%count))
         call check(ctx, out%kind(j) == region_simple .and. out%orders(j) == j .and. out%status(j) == region_theory, &
                    "region "//integer_text(j)//": simple, order j, theory")
         call check(ctx, abs(out%frequency(j) - (j*pi/2.0_wp)**2) < 1.0e-9_wp .and. out%drive(j) == 0.0_wp, &
                    "region "//integer_text(j)//": tip at ((j pi/2)^2, 0)")
      end do
   end subroutine mathieu_theory_tips

   !> Capacity 0 with null arrays counts the regions; capacity 1 stores the first only.
   subroutine capacity_and_count(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(c_ptr) :: model
      type(outputs_t) :: out, every
      type(call_t) :: a
      model = new_model(ctx, "mathieu")
      a = call_t(axis=along_alpha, f_min=0.5_wp, f_max=10.5_wp, d_min=0.0_wp, d_max=1.0_wp, order=2)
      call check(ctx, c_regions(model, a, every) == 0, "every region")
      a%capacity = 0
      call check(ctx, c_regions(model, a, out, null_arrays=.true.) == 0, "capacity 0, null arrays: "//last_message())
      call check(ctx, out%count == every%count, "capacity 0 counts them all")
      out = outputs_t()
      a%capacity = 1
      call check(ctx, c_regions(model, a, out) == 0, "capacity 1")
      call check(ctx, out%count == every%count .and. out%frequency(1) == every%frequency(1) .and. &
                 all(out%frequency(2:) == -7.0_wp) .and. all(out%modes(3:) == -7), "capacity 1 stores the first")
      call hillstab_c_model_free(model)
   end subroutine capacity_and_count

   !> One refused call: its code, the message holding `words`, the outputs untouched.
   subroutine refused(ctx, code, out, words)
      type(test_context_t), intent(inout) :: ctx
      integer(c_int), intent(in) :: code
      type(outputs_t), intent(in) :: out
      character(len=*), intent(in) :: words
      character(len=:), allocatable :: message
      message = last_message()
      call check(ctx, code == err_invalid_parameter, words//": code "//integer_text(int(code))//" ("//message//")")
      call check(ctx, index(message, words) > 0, "the message names '"//words//"': "//message)
      call check(ctx, out%count == 777 .and. all(out%kind == -7) .and. all(out%drive == -7.0_wp), &
                 words//": the outputs untouched")
   end subroutine refused

   !> Bad input to hillstab_regions fails naming the argument, the outputs untouched.
   subroutine bad_input_named(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(c_ptr) :: model, mathieu
      type(outputs_t), target :: out
      type(call_t) :: a, good
      type(c_ptr) :: p(14)
      real(c_double) :: nan
      nan = ieee_value(1.0_c_double, ieee_quiet_nan)
      model = new_model(ctx, "equation")
      call equation_texts(ctx, model)
      mathieu = new_model(ctx, "mathieu")
      call refused(ctx, c_regions(c_null_ptr, good, out), out, "null pointer")
      a = good; a%axis = 3
      call refused(ctx, c_regions(model, a, out), out, "drive_axis")
      a = good; a%f_max = a%f_min
      call refused(ctx, c_regions(model, a, out), out, "f_min, f_max")
      a = good; a%f_min = nan
      call refused(ctx, c_regions(model, a, out), out, "f_min, f_max")
      a = good; a%d_max = -1.0_wp
      call refused(ctx, c_regions(model, a, out), out, "d_min, d_max")
      a = good; a%epsilon = -0.1_wp
      call refused(ctx, c_regions(mathieu, a, out), out, "epsilon")
      a = good; a%epsilon = 0.1_wp
      call refused(ctx, c_regions(model, a, out), out, "epsilon: the equation model carries its own damping")
      a = good; a%method = 99
      call refused(ctx, c_regions(model, a, out), out, "method")
      a = good; a%tolerance = 2.0_wp
      call refused(ctx, c_regions(model, a, out), out, "tolerance")
      a = good; a%order = 9
      call refused(ctx, c_regions(model, a, out), out, "order: must be 1 to 8, got 9")
      a = good; a%order = 0
      call refused(ctx, c_regions(model, a, out), out, "order")
      a = good; a%n_samples = 1
      call refused(ctx, c_regions(model, a, out), out, "n_samples")
      a = good
      call refused(ctx, c_regions(model, a, out, null_arrays=.true.), out, "kind: a null pointer")
      call pointers(out, p)
      call refused(ctx, hillstab_c_regions(model, a%axis, a%f_min, a%f_max, a%d_min, a%d_max, a%epsilon, a%method, &
                                           a%tolerance, a%order, a%n_samples, a%capacity, p(1), p(2), p(3), p(4), &
                                           p(5), p(6), p(7), p(8), p(9), p(10), p(11), p(12), p(13), c_null_ptr), &
                   out, "count: a null pointer")
      ! the frequency W must be positive: a point outside the equation's domain
      a = good; a%f_min = -1.0_wp
      call refused(ctx, c_regions(model, a, out), out, "f_min, d_min")
      call hillstab_c_model_free(model)
      call hillstab_c_model_free(mathieu)
   end subroutine bad_input_named

   !> Bad input to hillstab_system_regions fails naming the argument after the entry point.
   subroutine system_bad_input_named(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(c_ptr), target :: system
      type(outputs_t) :: out
      type(call_t) :: a, good
      good = call_t(axis=along_alpha, f_min=1.5_wp, f_max=3.5_wp, d_min=0.0_wp, d_max=1.0_wp, method=system_auto)
      call refused(ctx, c_system_regions(c_null_ptr, good, out), out, "hillstab_system_regions: system: a null pointer")
      system = c_null_ptr
      call check(ctx, hillstab_c_system_new(c_loc(system)) == 0, "new")
      call refused(ctx, c_system_regions(system, good, out), out, "hillstab_system_regions: n")
      a = good; a%axis = 0
      call refused(ctx, c_system_regions(system, a, out), out, "hillstab_system_regions: drive_axis")
      a = good; a%method = 1
      call refused(ctx, c_system_regions(system, a, out), out, "hillstab_system_regions: method")
      a = good; a%tolerance = 1.0e-16_wp
      call refused(ctx, c_system_regions(system, a, out), out, "hillstab_system_regions: tolerance")
      a = good; a%d_min = a%d_max
      call refused(ctx, c_system_regions(system, a, out), out, "hillstab_system_regions: d_min, d_max")
      a = good; a%epsilon = -1.0_wp
      call refused(ctx, c_system_regions(system, a, out), out, "hillstab_system_regions: epsilon")
      call hillstab_c_system_free(system)
   end subroutine system_bad_input_named
end module test_capi_regions

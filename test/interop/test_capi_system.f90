!> Tests of the C entry points of systems (hillstab_interop_capi_system), called from
!> Fortran as C calls them: the pendula pair built through `hillstab_system_set` gives the
!> monodromy, trace, verdict and kind of `system_monodromy` and `system_floquet` called
!> directly; bad input (null pointers, n not given, unknown variables and methods, a
!> tolerance, α, β or ε out of range, matrices that are not SPD, symmetric or skew) fails
!> with the argument named and the outputs and the system untouched; the header's
!> HILLSTAB_SYSTEM_VERDICT_* and HILLSTAB_SYSTEM_KIND_* codes are the library's.
module test_capi_system
   use, intrinsic :: iso_c_binding, only: c_int, c_double, c_char, c_size_t, c_null_char, c_ptr, c_null_ptr, &
      c_associated, c_loc
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_positive_inf
   use hillstab_core_kinds, only: wp
   use hillstab_core_error, only: error_t, err_invalid_parameter
   use hillstab_core_text, only: integer_text
   use hillstab_hill_system, only: system_form_t, prepare_system
   use hillstab_hill_system_matrix, only: matrix_system_t
   use hillstab_hill_system_floquet, only: floquet_t, system_floquet, verdict_stable, verdict_unstable, &
      verdict_marginal, kind_stable, kind_plus_one, kind_minus_one, kind_combination, kind_damped, &
      kind_undecided
   use hillstab_integrate_system, only: system_method_t, system_monodromy_t, system_nodes_t, system_monodromy, &
      system_auto, system_magnus4, system_rk
   use hillstab_interop_capi, only: hillstab_c_last_error
   use hillstab_interop_capi_system
   use hillstab_testing
   implicit none
   private
   public :: collect_capi_system

contains

   function collect_capi_system() result(suite)
      type(testsuite_t) :: suite
      suite = new_testsuite("capi_system", [ &
         new_unittest("pair_matches_direct", pair_matches_direct), &
         new_unittest("bad_input_named", bad_input_named), &
         new_unittest("failed_set_keeps_system", failed_set_keeps_system), &
         new_unittest("header_codes", header_codes)])
   end function collect_capi_system

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

   !> Set a variable through the C entry point; its status.
   integer(c_int) function set(system, name, values) result(status)
      type(c_ptr), intent(in) :: system
      character(len=*), intent(in) :: name
      real(c_double), intent(in), target, contiguous :: values(:)
      character(kind=c_char), target :: chars(len(name) + 1)
      integer :: i
      do i = 1, len(name)
         chars(i) = name(i:i)
      end do
      chars(len(name) + 1) = c_null_char
      status = hillstab_c_system_set(system, c_loc(chars), c_loc(values), size(values, kind=c_size_t))
   end function set

   !> The pendula pair of test_system (two pendula of lengths 1 and l2 joined by a spring c,
   !> the support shaken: M = diag(1, l2²), B = diag(1, l2) + c [[1, −1], [−1, 1]], K₁ᶜ =
   !> −diag(1, l2)) made directly with `set_values`.
   function pendula_pair(l2, c) result(pair)
      real(wp), intent(in) :: l2, c
      type(matrix_system_t) :: pair
      type(error_t), allocatable :: error
      call pair%set_values("n", [2.0_wp], error)
      call pair%set_values("mass", [1.0_wp, 0.0_wp, 0.0_wp, l2*l2], error)
      call pair%set_values("b", [1.0_wp + c, -c, -c, l2 + c], error)
      call pair%set_values("cos", [-1.0_wp, 0.0_wp, 0.0_wp, -l2], error)
      call pair%check_values(error)
      if (allocated(error)) error stop "pendula_pair: "//error%message
   end function pendula_pair

   !> The same pair made through the C API.
   function c_pair(ctx, l2, c) result(system)
      type(test_context_t), intent(inout) :: ctx
      real(wp), intent(in) :: l2, c
      type(c_ptr), target :: system
      system = c_null_ptr
      call check(ctx, hillstab_c_system_new(c_loc(system)) == 0 .and. c_associated(system), "new")
      call check(ctx, set(system, "n", [2.0_wp]) == 0, "set n")
      call check(ctx, set(system, "mass", [1.0_wp, 0.0_wp, 0.0_wp, l2*l2]) == 0, "set mass")
      call check(ctx, set(system, "b", [1.0_wp + c, -c, -c, l2 + c]) == 0, "set b")
      call check(ctx, set(system, "cos", [-1.0_wp, 0.0_wp, 0.0_wp, -l2]) == 0, "set cos")
      call check(ctx, hillstab_c_system_check(system) == 0, "check: "//last_message())
   end function c_pair

   !> The pair through the C API against system_monodromy and system_floquet called directly:
   !> Φ̃ (row by row), s, the error estimate, tr Φ, a₂, verdict and kind at stable, unstable
   !> and damped points, by auto, magnus4 and rk.
   subroutine pair_matches_direct(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(c_ptr) :: system
      type(matrix_system_t) :: pair
      type(system_form_t) :: form
      type(system_nodes_t) :: nodes
      type(system_monodromy_t) :: r
      type(floquet_t) :: f
      type(error_t), allocatable :: error
      real(c_double), target :: phi(16), log_scale, estimate, re(4), im(4), scale, exponents(2), trace, a2, defect, e2
      integer(c_int), target :: status, verdict, kind, n, status2
      real(wp), parameter :: points(3, 5) = reshape([0.3_wp, 1.2_wp, 0.0_wp, 0.9_wp, 0.25_wp, 0.0_wp, &
                                                     2.5_wp, 4.0_wp, 0.0_wp, 0.9_wp, 0.25_wp, 0.3_wp, &
                                                     6.0_wp, 0.5_wp, 0.0_wp], [3, 5])
      integer, parameter :: methods(3) = [system_auto, system_magnus4, system_rk]
      integer :: k, j, i
      character(len=80) :: where
      system = c_pair(ctx, 0.8_wp, 0.1_wp)
      call check(ctx, hillstab_c_system_dof(system, c_loc(n)) == 0 .and. n == 2, "dof 2")
      call check(ctx, hillstab_c_system_states(system, c_loc(n)) == 0 .and. n == 4, "states 4")
      pair = pendula_pair(0.8_wp, 0.1_wp)
      do k = 1, size(points, 2)
         call prepare_system(pair, points(3, k), form, error)
         call check(ctx, .not. allocated(error), "prepare")
         do j = 1, size(methods)
            write (where, '(a, i0, a, 3f6.2)') "method ", methods(j), " at ", points(:, k)
            nodes = system_nodes_t()
            call system_monodromy(pair, form, points(1, k), points(2, k), system_method_t(methods(j), 1.0e-10_wp), &
                                  nodes, r, error)
            call check(ctx, .not. allocated(error), trim(where)//": direct")
            if (allocated(error)) cycle
            call system_floquet(r%phi, form, r%error_estimate*max(1.0_wp, maxval(abs(r%phi))), f, r%log_scale)
            call check(ctx, hillstab_c_system_monodromy(system, points(1, k), points(2, k), points(3, k), &
                                                        int(methods(j), c_int), 1.0e-10_c_double, c_loc(phi), &
                                                        c_loc(log_scale), c_loc(estimate), c_loc(status)) == 0, &
                       trim(where)//": monodromy "//last_message())
            call check(ctx, all([(phi(4*(i - 1) + 1:4*i) == r%phi(i, :), i=1, 4)]), trim(where)//": phi row by row")
            call check(ctx, log_scale == r%log_scale .and. estimate == r%error_estimate .and. status == r%status, &
                       trim(where)//": scale, estimate, status")
            call check(ctx, hillstab_c_system_floquet(system, points(1, k), points(2, k), points(3, k), &
                                                      int(methods(j), c_int), 1.0e-10_c_double, c_loc(re), c_loc(im), &
                                                      c_loc(scale), c_loc(exponents), c_loc(verdict), c_loc(kind), &
                                                      c_loc(trace), c_loc(a2), c_loc(defect), c_loc(e2), &
                                                      c_loc(status2)) == 0, trim(where)//": floquet "//last_message())
            call check(ctx, trace, f%a1, rel=1.0e-15_wp, abs=1.0e-15_wp, message=trim(where)//": trace")
            call check(ctx, a2, f%a2, rel=1.0e-15_wp, abs=1.0e-15_wp, message=trim(where)//": a2")
            call check(ctx, verdict == f%verdict .and. kind == f%kind, trim(where)//": verdict and kind")
            call check(ctx, all(exponents == f%exponents) .and. defect == f%defect .and. e2 == r%error_estimate, &
                       trim(where)//": exponents, defect, estimate")
            ! Φ's own multipliers (small scale here), their sum the trace
            call check(ctx, scale == 0.0_wp, trim(where)//": multipliers unscaled")
            call check(ctx, sum(re), trace, rel=1.0e-12_wp, abs=1.0e-12_wp, message=trim(where)//": sum of multipliers")
            call check(ctx, abs(sum(im)) <= 1.0e-12_wp*max(1.0_wp, maxval(abs(im))), trim(where)//": conjugate pairs")
         end do
      end do
      call hillstab_c_system_free(system)
   end subroutine pair_matches_direct

   !> Bad input: a nonzero status, the argument named in the message, the outputs untouched.
   subroutine bad_input_named(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(c_ptr), target :: system, empty
      real(c_double), target :: phi(16), log_scale, estimate, re(4), im(4), scale, exponents(2), trace, a2, defect, e2
      integer(c_int), target :: status, verdict, kind, n
      real(c_double) :: nan, inf
      nan = ieee_value(1.0_c_double, ieee_quiet_nan)
      inf = ieee_value(1.0_c_double, ieee_positive_inf)
      trace = -7.0_wp
      phi = -7.0_wp
      n = -7
      ! null pointers
      call refused(hillstab_c_system_new(c_null_ptr), "hillstab_system_new: system:", "new into NULL")
      call refused(hillstab_c_system_check(c_null_ptr), "hillstab_system_check: system:", "check NULL")
      call refused(floquet(c_null_ptr, 0.3_wp, 1.0_wp, 0.0_wp, 0, 1.0e-10_wp), "hillstab_system_floquet: system:", &
                   "floquet NULL")
      ! n not given
      empty = c_null_ptr
      call check(ctx, hillstab_c_system_new(c_loc(empty)) == 0, "new empty")
      call refused(hillstab_c_system_dof(empty, c_loc(n)), "hillstab_system_dof: n:", "dof of empty")
      call check(ctx, n == -7, "n untouched")
      call refused(hillstab_c_system_states(empty, c_loc(n)), "hillstab_system_states: states:", "states of empty")
      call refused(hillstab_c_system_check(empty), "hillstab_system_check: n:", "check empty")
      call refused(floquet(empty, 0.3_wp, 1.0_wp, 0.0_wp, 0, 1.0e-10_wp), "hillstab_system_floquet: n:", &
                   "floquet of empty")
      call refused(set(empty, "n", [2.5_wp]), "hillstab_system_set: n:", "n = 2.5")
      call refused(set(empty, "n", [21.0_wp]), "hillstab_system_set: n:", "n = 21")
      call hillstab_c_system_free(empty)
      ! variables
      system = c_pair(ctx, 0.8_wp, 0.1_wp)
      call refused(set(system, "stiffness", [1.0_wp]), "hillstab_system_set: the system model has no variable", &
                   "unknown variable")
      call refused(set(system, "mass", [1.0_wp, 0.0_wp, 0.0_wp, -1.0_wp]), "hillstab_system_set: mass: M must be "// &
                   "positive definite", "mass not SPD")
      call refused(set(system, "mass", [1.0_wp, 0.5_wp, 0.0_wp, 1.0_wp]), "hillstab_system_set: mass: M must be "// &
                   "symmetric", "mass not symmetric")
      call refused(set(system, "mass", [1.0_wp, 0.0_wp, 1.0_wp]), "hillstab_system_set: mass: n = 2 needs 4", &
                   "mass of 3 numbers")
      call refused(set(system, "damping", [1.0_wp, 0.5_wp, 0.0_wp, 1.0_wp]), "hillstab_system_set: damping:", &
                   "damping not symmetric")
      call refused(set(system, "gyroscopic", [0.0_wp, 1.0_wp, 1.0_wp, 0.0_wp]), "hillstab_system_set: gyroscopic:", &
                   "gyroscopic not skew")
      call refused(set(system, "cos", [1.0_wp, 0.0_wp, 0.0_wp]), "hillstab_system_set: cos:", "cos of 3 numbers")
      call refused(set(system, "k0", [1.0_wp, nan, 0.0_wp, 1.0_wp]), "hillstab_system_set: k0:", "k0 with NaN")
      call refused(set(system, "period", [3.0_wp]), "hillstab_system_set: period:", "period 3")
      ! the point, the method, the tolerance
      call refused(floquet(system, 0.3_wp, 1.0_wp, 0.0_wp, 7, 1.0e-10_wp), "hillstab_system_floquet: method:", &
                   "method 7")
      call refused(floquet(system, 0.3_wp, 1.0_wp, 0.0_wp, 1, 1.0e-10_wp), "hillstab_system_floquet: method: "// &
                   "unknown system method code 1 (HILLSTAB_METHOD_AUTO 0, _MAGNUS4 3, _MAGNUS6 4, _RK 5 or _GSL 6)", &
                   "method formula")
      call refused(floquet(system, 0.3_wp, 1.0_wp, 0.0_wp, 0, 0.0_wp), "hillstab_system_floquet: tolerance:", &
                   "tolerance 0")
      call refused(floquet(system, 0.3_wp, 1.0_wp, 0.0_wp, 0, 1.0e-16_wp), "hillstab_system_floquet: tolerance:", &
                   "tolerance 1e-16")
      call refused(floquet(system, 0.3_wp, 1.0_wp, 0.0_wp, 0, 1.0_wp), "hillstab_system_floquet: tolerance:", &
                   "tolerance 1")
      call refused(floquet(system, 0.3_wp, 1.0_wp, 0.0_wp, 0, nan), "hillstab_system_floquet: tolerance:", &
                   "tolerance NaN")
      call refused(floquet(system, nan, 1.0_wp, 0.0_wp, 0, 1.0e-10_wp), "hillstab_system_floquet: alpha:", "alpha NaN")
      call refused(floquet(system, 0.3_wp, inf, 0.0_wp, 0, 1.0e-10_wp), "hillstab_system_floquet: beta:", "beta inf")
      call refused(floquet(system, 0.3_wp, 1.0_wp, -0.1_wp, 0, 1.0e-10_wp), "hillstab_system_floquet: epsilon:", &
                   "epsilon < 0")
      call refused(floquet(system, 0.3_wp, 1.0_wp, nan, 0, 1.0e-10_wp), "hillstab_system_floquet: epsilon:", &
                   "epsilon NaN")
      call refused(hillstab_c_system_monodromy(system, 0.3_wp, 1.0_wp, 0.0_wp, 0_c_int, 1.0_wp, c_loc(phi), &
                                               c_loc(log_scale), c_loc(estimate), c_loc(status)), &
                   "hillstab_system_monodromy: tolerance:", "monodromy tolerance 1")
      call check(ctx, all(phi == -7.0_wp), "phi untouched")
      ! null outputs
      call refused(hillstab_c_system_monodromy(system, 0.3_wp, 1.0_wp, 0.0_wp, 0_c_int, 1.0e-10_wp, c_null_ptr, &
                                               c_loc(log_scale), c_loc(estimate), c_loc(status)), &
                   "hillstab_system_monodromy: phi:", "phi NULL")
      call refused(hillstab_c_system_floquet(system, 0.3_wp, 1.0_wp, 0.0_wp, 0_c_int, 1.0e-10_wp, c_loc(re), c_loc(im), &
                                             c_loc(scale), c_null_ptr, c_loc(verdict), c_loc(kind), c_loc(trace), &
                                             c_loc(a2), c_loc(defect), c_loc(e2), c_loc(status)), &
                   "hillstab_system_floquet: exponents:", "exponents NULL")
      call refused(hillstab_c_system_dof(system, c_null_ptr), "hillstab_system_dof: n:", "dof into NULL")
      call check(ctx, trace == -7.0_wp, "trace untouched")
      ! and still good
      call check(ctx, floquet(system, 0.3_wp, 1.0_wp, 0.0_wp, 0, 1.0e-10_wp) == 0, "good after the refusals: "// &
                 last_message())
      call check(ctx, trace /= -7.0_wp .and. last_message() == "", "computed, no message")
      call hillstab_c_system_free(system)
      call hillstab_c_system_free(c_null_ptr)

   contains

      integer(c_int) function floquet(handle, alpha, beta, epsilon, method, tolerance) result(code)
         type(c_ptr), intent(in) :: handle
         real(wp), intent(in) :: alpha, beta, epsilon, tolerance
         integer, intent(in) :: method
         code = hillstab_c_system_floquet(handle, alpha, beta, epsilon, int(method, c_int), tolerance, c_loc(re), &
                                          c_loc(im), c_loc(scale), c_loc(exponents), c_loc(verdict), c_loc(kind), &
                                          c_loc(trace), c_loc(a2), c_loc(defect), c_loc(e2), c_loc(status))
      end function floquet

      subroutine refused(code, part, what)
         integer(c_int), intent(in) :: code
         character(len=*), intent(in) :: part, what
         character(len=:), allocatable :: message
         message = last_message()
         call check(ctx, code == err_invalid_parameter, what//": status "//integer_text(int(code)))
         call check(ctx, index(message, part) == 1, what//": the message '"//message//"' starts with '"//part//"'")
      end subroutine refused
   end subroutine bad_input_named

   !> A refused variable leaves the system as it was: its monodromy the same before and after.
   subroutine failed_set_keeps_system(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(c_ptr) :: system
      real(c_double), target :: phi(16), phi2(16), log_scale, estimate
      integer(c_int), target :: status
      system = c_pair(ctx, 0.8_wp, 0.1_wp)
      call check(ctx, hillstab_c_system_monodromy(system, 0.9_wp, 0.25_wp, 0.0_wp, 0_c_int, 1.0e-10_wp, c_loc(phi), &
                                                  c_loc(log_scale), c_loc(estimate), c_loc(status)) == 0, "before")
      call check(ctx, set(system, "mass", [1.0_wp, 2.0_wp, 2.0_wp, 1.0_wp]) /= 0, "indefinite mass refused")
      call check(ctx, set(system, "b", [1.0_wp, 2.0_wp]) /= 0, "b of 2 numbers refused")
      call check(ctx, hillstab_c_system_check(system) == 0, "still complete")
      call check(ctx, hillstab_c_system_monodromy(system, 0.9_wp, 0.25_wp, 0.0_wp, 0_c_int, 1.0e-10_wp, c_loc(phi2), &
                                                  c_loc(log_scale), c_loc(estimate), c_loc(status)) == 0, "after")
      call check(ctx, all(phi == phi2), "the same monodromy")
      call hillstab_c_system_free(system)
   end subroutine failed_set_keeps_system

   !> include/hillstab.h declares every verdict and kind with the library's code.
   subroutine header_codes(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=:), allocatable :: text
      character(len=1000) :: line
      integer :: unit, ios
      text = ""
      open (newunit=unit, file="include/hillstab.h", status="old", action="read", iostat=ios)
      call check(ctx, ios == 0, "cannot open include/hillstab.h (run the tests from the worktree root)")
      if (ios /= 0) return
      do
         read (unit, '(a)', iostat=ios) line
         if (ios /= 0) exit
         text = text//" "//trim(line)
      end do
      close (unit)
      call expect("HILLSTAB_SYSTEM_VERDICT_STABLE", verdict_stable)
      call expect("HILLSTAB_SYSTEM_VERDICT_UNSTABLE", verdict_unstable)
      call expect("HILLSTAB_SYSTEM_VERDICT_MARGINAL", verdict_marginal)
      call expect("HILLSTAB_SYSTEM_KIND_STABLE", kind_stable)
      call expect("HILLSTAB_SYSTEM_KIND_PLUS_ONE", kind_plus_one)
      call expect("HILLSTAB_SYSTEM_KIND_MINUS_ONE", kind_minus_one)
      call expect("HILLSTAB_SYSTEM_KIND_COMBINATION", kind_combination)
      call expect("HILLSTAB_SYSTEM_KIND_DAMPED", kind_damped)
      call expect("HILLSTAB_SYSTEM_KIND_UNDECIDED", kind_undecided)
   contains
      subroutine expect(name, code)
         character(len=*), intent(in) :: name
         integer, intent(in) :: code
         call check(ctx, index(text, " "//name//" = "//integer_text(code)//",") > 0 .or. &
            index(text, " "//name//" = "//integer_text(code)//" ") > 0, name//" = "//integer_text(code))
      end subroutine expect
   end subroutine header_codes
end module test_capi_system

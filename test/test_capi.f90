!> Tests of the C and legacy entry points against the modern API.
module test_capi
   use, intrinsic :: iso_c_binding, only: c_int, c_double, c_char, c_size_t, c_null_char
   use hillstab_kinds, only: wp, pi2
   use hillstab_coefficient, only: hill_model_t, model_elastic, sampling_average
   use hillstab_transfer, only: trace_t
   use hillstab_monodromy, only: trace_segmented, method_segments, method_formula
   use hillstab_formulas, only: trace_two_segment_paper
   use hillstab_capi
   use hillstab_legacy, only: hstrace, hsfloq
   use hillstab_testing
   implicit none
   private
   public :: collect_capi

contains

   function collect_capi() result(suite)
      type(testsuite_t) :: suite
      suite = new_testsuite("capi", [ &
         new_unittest("c_trace_matches_library", c_trace_matches_library), &
         new_unittest("c_errors", c_errors), &
         new_unittest("legacy_wrappers", legacy_wrappers)])
   end function collect_capi

   subroutine c_trace_matches_library(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(c_double) :: s, log_abs, log_modulus(2), mu, q
      integer(c_int) :: overflow, stable, stable_paper, status
      type(trace_t) :: tr
      tr = trace_segmented(hill_model_t(model_elastic, 3.7_wp, 2.47_wp, 0.0_wp), 64, sampling_average)
      status = hillstab_c_trace(1_c_int, 3.7_c_double, 2.47_c_double, 0.0_c_double, int(method_segments, c_int), &
         64_c_int, int(sampling_average, c_int), 1.0e-10_c_double, s, log_abs, overflow)
      call check(ctx, status == 0, "status 0")
      call check(ctx, real(s, wp), tr%value, rel=1.0e-15_wp)
      call check(ctx, real(log_abs, wp), log(abs(tr%value)), rel=1.0e-14_wp)
      call check(ctx, overflow == 0, "no overflow")
      status = hillstab_c_floquet(1_c_int, 3.7_c_double, 2.47_c_double, 0.0_c_double, int(method_segments, c_int), &
         64_c_int, int(sampling_average, c_int), 1.0e-10_c_double, s, log_modulus, mu, stable, stable_paper)
      call check(ctx, status == 0 .and. stable == 0 .and. stable_paper == 0, "unstable point")
      call check(ctx, real(mu, wp), 0.5_wp*acosh(0.5_wp*abs(tr%value)), rel=1.0e-13_wp)
      tr = trace_two_segment_paper(1.48_wp, 2.47_wp)
      call check(ctx, real(hillstab_c_trace_paper(1.48_c_double, 2.47_c_double, 0.0_c_double), wp), tr%value, &
         rel=1.0e-15_wp)
      status = hillstab_c_coefficient(1_c_int, 4.0_c_double, 6.0_c_double, 0.0_c_double, 1.0_c_double, q)
      call check(ctx, real(q, wp), 10.0_wp/(1.0_wp + 4.0_wp/pi2), rel=1.0e-14_wp)
   end subroutine c_trace_matches_library

   subroutine c_errors(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(c_double) :: s, log_abs
      integer(c_int) :: overflow, status
      character(kind=c_char) :: buffer(64)
      s = -7.0_c_double
      status = hillstab_c_trace(1_c_int, 10.0_c_double, 2.47_c_double, 0.0_c_double, int(method_formula, c_int), &
         2_c_int, 1_c_int, 1.0e-10_c_double, s, log_abs, overflow)
      call check(ctx, status /= 0, "alpha > pi**2 gives a non-zero status")
      call check(ctx, s == -7.0_c_double, "output untouched on error")
      call hillstab_c_error_message(status, buffer, size(buffer, kind=c_size_t))
      call check(ctx, any(buffer == c_null_char) .and. buffer(1) /= c_null_char, "message is a C string")
   end subroutine c_errors

   subroutine legacy_wrappers(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp) :: s, mu
      integer :: info, istab
      type(trace_t) :: tr
      call hstrace(1, 3.7_wp, 2.47_wp, 0.0_wp, method_formula, 2, 1, 1.0e-10_wp, s, info)
      tr = trace_two_segment_paper(3.7_wp, 2.47_wp)
      call check(ctx, info == 0, "info 0")
      call check(ctx, s, tr%value, rel=1.0e-15_wp)
      call hsfloq(1, 2.57_wp, 1.29_wp, 0.0_wp, method_segments, 512, 3, 1.0e-10_wp, s, mu, istab, info)
      call check(ctx, info == 0 .and. istab == 1, "case (c) is stable")
      call check(ctx, mu, 0.0_wp, abs=0.0_wp)
      call hstrace(1, -1.0_wp, 2.47_wp, 0.0_wp, method_formula, 2, 1, 1.0e-10_wp, s, info)
      call check(ctx, info /= 0, "alpha < 0 rejected")
   end subroutine legacy_wrappers
end module test_capi

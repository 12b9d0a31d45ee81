!> Tests of the C and legacy entry points against the modern API.
module test_capi
   use, intrinsic :: iso_c_binding, only: c_int, c_double, c_char, c_size_t, c_null_char, c_ptr, c_f_pointer
   use hillstab_core_kinds, only: wp, pi2, version_string
   use hillstab_hill_coefficient, only: sampling_average
   use hillstab_hill_transfer, only: trace_t
   use hillstab_integrate_monodromy, only: trace_segmented, method_segments, method_formula
   use hillstab_hill_formulas, only: trace_two_segment_paper, trace_damped_paper
   use hillstab_interop_capi
   use hillstab_core_error, only: error_t, err_invalid_parameter, err_accuracy
   use hillstab_integrate_monodromy, only: method_auto
   use hillstab_interop_legacy, only: hstrace, hsfloq, hserrm
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_is_finite, ieee_copy_sign
   !$ use omp_lib, only: omp_get_thread_num, omp_get_num_threads
   use hillstab_testing
   use hillstab_hill_model, only: hill_point_t, check_point
   use hillstab_hill_model_elastic, only: elastic_model_t
   implicit none
   private
   public :: collect_capi

contains

   !> hillstab_version gives version_string NUL-terminated; hillstab_version_numbers its
   !> numbers; version_numbers reads MAJOR.MINOR.PATCH and marks what is not a number.
   subroutine c_version(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(kind=c_char), pointer :: chars(:)
      integer(c_int) :: major, minor, patch
      character(len=:), allocatable :: text
      integer :: i
      call c_f_pointer(hillstab_c_version(), chars, [len(version_string) + 1])
      text = ""
      do i = 1, len(version_string)
         text = text//chars(i)
      end do
      call check(ctx, text == version_string, "hillstab_version() = "//text)
      call check(ctx, chars(len(version_string) + 1) == c_null_char, "NUL-terminated")
      call hillstab_c_version_numbers(major, minor, patch)
      call check(ctx, all(version_numbers(version_string) == [major, minor, patch]), "numbers of "//version_string)
      call check(ctx, all(version_numbers("12.3.45") == [12, 3, 45]), "12.3.45")
      call check(ctx, all(version_numbers("1.x") == [1, -1, -1]), "1.x")
      call check(ctx, all(version_numbers("") == [-1, -1, -1]), "empty")
   end subroutine c_version

   function collect_capi() result(suite)
      type(testsuite_t) :: suite
      suite = new_testsuite("capi", [ &
         new_unittest("c_trace_matches_library", c_trace_matches_library), &
         new_unittest("c_errors", c_errors), &
         new_unittest("c_last_error", c_last_error), &
         new_unittest("c_last_error_per_thread", c_last_error_per_thread), &
         new_unittest("legacy_wrappers", legacy_wrappers), &
         new_unittest("legacy_messages", legacy_messages), &
         new_unittest("legacy_roundoff_limited", legacy_roundoff_limited), &
         new_unittest("legacy_invalid_arguments", legacy_invalid_arguments), &
         new_unittest("extreme_inputs_status", extreme_inputs_status), &
         new_unittest("trace_paper_checked", trace_paper_checked), &
         new_unittest("c_version", c_version)])
   end function collect_capi

   subroutine c_trace_matches_library(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(c_double) :: s, log_abs, log_modulus(2), mu, q
      integer(c_int) :: overflow, stable, stable_paper, status
      type(trace_t) :: tr
      real(wp) :: legacy_s, legacy_mu
      integer :: legacy_stable, legacy_info
      tr = trace_segmented(elastic_model_t(), hill_point_t(3.7_wp, 2.47_wp, 0.0_wp), 64, sampling_average)
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
      ! a stable undamped point (the paper's case (c)): exponent and ln|lambda| are +0, not
      ! -0 (printf would write "-0"), from C and from HSFLOQ
      status = hillstab_c_floquet(1_c_int, 2.57_c_double, 1.29_c_double, 0.0_c_double, int(method_segments, c_int), &
         64_c_int, int(sampling_average, c_int), 1.0e-10_c_double, s, log_modulus, mu, stable, stable_paper)
      call check(ctx, status == 0 .and. stable == 1, "case (c) stable")
      call check(ctx, mu == 0.0_c_double .and. ieee_copy_sign(1.0_c_double, mu) > 0.0_c_double, &
         "exponent +0 at a stable point")
      call check(ctx, all(log_modulus == 0.0_c_double) .and. all(ieee_copy_sign(1.0_c_double, log_modulus) > 0.0_c_double), &
         "ln|lambda| +0")
      call hsfloq(1, 2.57_wp, 1.29_wp, 0.0_wp, int(method_segments), 64, int(sampling_average), 1.0e-10_wp, &
         legacy_s, legacy_mu, legacy_stable, legacy_info)
      call check(ctx, legacy_info == 0 .and. legacy_stable == 1 .and. legacy_mu == 0.0_wp .and. &
         ieee_copy_sign(1.0_wp, legacy_mu) > 0.0_wp, "HSFLOQ: MU +0 at a stable point")
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

   !> The C text of a buffer up to its NUL.
   function c_text(buffer) result(text)
      character(kind=c_char), intent(in) :: buffer(:)
      character(len=:), allocatable :: text
      integer :: i
      text = ""
      do i = 1, size(buffer)
         if (buffer(i) == c_null_char) exit
         text = text//buffer(i)
      end do
   end function c_text

   !> The message the Fortran API gives for α = 10.
   function fortran_message() result(text)
      character(len=:), allocatable :: text
      type(error_t), allocatable :: error
      call check_point(elastic_model_t(), hill_point_t(10.0_wp, 2.47_wp, 0.0_wp), error)
      text = error%message
   end function fortran_message

   subroutine c_last_error(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(c_double) :: s, log_abs
      integer(c_int) :: overflow, status, code
      character(kind=c_char) :: buffer(256), short(8)
      character(len=:), allocatable :: expected
      expected = fortran_message()
      status = hillstab_c_trace(1_c_int, 10.0_c_double, 2.47_c_double, 0.0_c_double, int(method_formula, c_int), &
         2_c_int, 1_c_int, 1.0e-10_c_double, s, log_abs, overflow)
      code = hillstab_c_last_error(buffer, size(buffer, kind=c_size_t))
      call check(ctx, code == status .and. status == err_invalid_parameter, "the failed call's status")
      call check(ctx, c_text(buffer) == expected, "same text as the Fortran message: '"//c_text(buffer)//"'")
      call check(ctx, index(c_text(buffer), "9.8696") > 0, "the message names the limit")
      code = hillstab_c_last_error(short, size(short, kind=c_size_t))
      call check(ctx, code == status .and. c_text(short) == expected(1:7), "cut to the buffer: "//c_text(short))
      status = hillstab_c_coefficient(1_c_int, 4.0_c_double, 6.0_c_double, 0.0_c_double, 1.0_c_double, s)
      code = hillstab_c_last_error(buffer, size(buffer, kind=c_size_t))
      call check(ctx, code == 0 .and. c_text(buffer) == "", "a successful call clears the record")
      status = hillstab_c_coefficient(1_c_int, 4.0_c_double, 6.0_c_double, -1.0_c_double, 1.0_c_double, s)
      code = hillstab_c_last_error(buffer, size(buffer, kind=c_size_t))
      call check(ctx, code == err_invalid_parameter .and. index(c_text(buffer), "epsilon") > 0, &
         "hillstab_q records its failure too: "//c_text(buffer))
   end subroutine c_last_error

   !> One thread fails, the other succeeds; each then reads its own outcome.
   subroutine c_last_error_per_thread(ctx)
      type(test_context_t), intent(inout) :: ctx
      integer(c_int) :: codes(0:1), n_threads
      character(len=256) :: texts(0:1)
      codes = -1
      texts = "unset"
      n_threads = 1
      !$omp parallel num_threads(2) default(none) shared(codes, texts, n_threads)
      block
         real(c_double) :: s, log_abs
         integer(c_int) :: overflow, status
         character(kind=c_char) :: buffer(256)
         integer :: me
         me = 0
         !$ me = omp_get_thread_num()
         !$ if (me == 0) n_threads = omp_get_num_threads()
         status = hillstab_c_trace(1_c_int, merge(10.0_c_double, 3.7_c_double, me == 0), 2.47_c_double, &
            0.0_c_double, int(method_formula, c_int), 2_c_int, 1_c_int, 1.0e-10_c_double, s, log_abs, overflow)
         !$omp barrier
         if (me <= 1) then
            codes(me) = hillstab_c_last_error(buffer, size(buffer, kind=c_size_t))
            texts(me) = c_text(buffer)
         end if
      end block
      !$omp end parallel
      call check(ctx, codes(0) == err_invalid_parameter .and. trim(texts(0)) == fortran_message(), &
         "the failing thread reads its own failure")
      if (n_threads >= 2) then
         call check(ctx, codes(1) == 0 .and. texts(1) == "", "the other thread reads its own success")
      end if
   end subroutine c_last_error_per_thread

   subroutine legacy_messages(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp) :: s, mu
      integer :: info, istab
      character(len=200) :: msg
      call hstrace(1, 10.0_wp, 2.47_wp, 0.0_wp, method_formula, 2, 1, 1.0e-10_wp, s, info)
      call hserrm(msg)
      call check(ctx, info == err_invalid_parameter .and. trim(msg) == fortran_message(), &
         "HSERRM gives the Fortran message: '"//trim(msg)//"'")
      call hsfloq(1, 3.7_wp, 2.47_wp, 0.0_wp, method_formula, 2, 1, 1.0e-10_wp, s, mu, istab, info)
      call hserrm(msg)
      call check(ctx, info == 0 .and. msg == "", "blank after a successful call")
      call hsfloq(1, 3.7_wp, 2.47_wp, 0.0_wp, 9, 2, 1, 1.0e-10_wp, s, mu, istab, info)
      call hserrm(msg)
      call check(ctx, info == err_invalid_parameter .and. index(msg, "method") > 0, "unknown method: "//trim(msg))
   end subroutine legacy_messages

   !> β = 0 near α = π² has S = 2 exactly, but double precision cannot reach 1e-14 there:
   !> INFO = 7 with the best value, not S = 0.
   subroutine legacy_roundoff_limited(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp) :: s, mu
      integer :: info, istab
      call hstrace(1, 9.86_wp, 0.0_wp, 0.0_wp, method_auto, 2, 1, 1.0e-14_wp, s, info)
      call check(ctx, info == err_accuracy, "INFO = 7")
      call check(ctx, s, 2.0_wp, abs=1.0e-8_wp)
      call hsfloq(1, 9.86_wp, 0.0_wp, 0.0_wp, method_auto, 2, 1, 1.0e-14_wp, s, mu, istab, info)
      call check(ctx, info == err_accuracy, "INFO = 7")
      call check(ctx, s, 2.0_wp, abs=1.0e-8_wp)
      call check(ctx, mu, 0.0_wp, abs=1.0e-4_wp)
      ! the C entry points as the FORTRAN 77 ones: status 7 with the best value
      block
         real(c_double) :: sc, log_abs
         integer(c_int) :: overflow, status
         character(kind=c_char) :: buffer(300)
         character(len=300) :: text
         integer :: k
         sc = -7.0_c_double
         status = hillstab_c_trace(1_c_int, 9.86_c_double, 0.0_c_double, 0.0_c_double, int(method_auto, c_int), &
            2_c_int, 1_c_int, 1.0e-14_c_double, sc, log_abs, overflow)
         call check(ctx, status == err_accuracy, "C: status 7")
         call check(ctx, real(sc, wp), 2.0_wp, abs=1.0e-8_wp)
         status = hillstab_c_last_error(buffer, 300_c_size_t)
         text = ""
         do k = 1, 300
            if (buffer(k) == c_null_char) exit
            text(k:k) = buffer(k)
         end do
         call check(ctx, index(text, "best value returned") > 0, "the message says what the outputs hold: "// &
            trim(text))
      end block
   end subroutine legacy_roundoff_limited

   !> Every invalid argument the guide page *Using the library* lists gives INFO = 1 and a message naming it.
   subroutine legacy_invalid_arguments(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp) :: s, nan
      integer :: info
      character(len=200) :: msg
      nan = ieee_value(0.0_wp, ieee_quiet_nan)
      call hstrace(9, 3.7_wp, 2.47_wp, 0.0_wp, method_auto, 2, 1, 1.0e-10_wp, s, info)
      call hserrm(msg)
      call check(ctx, info == 1 .and. index(msg, "model") > 0, "MODEL = 9: "//trim(msg))
      call hstrace(1, 3.7_wp, 2.47_wp, -1.0_wp, method_auto, 2, 1, 1.0e-10_wp, s, info)
      call hserrm(msg)
      call check(ctx, info == 1 .and. index(msg, "epsilon") > 0, "EPS < 0: "//trim(msg))
      call hstrace(1, 3.7_wp, 2.47_wp, 0.0_wp, method_segments, 0, 1, 1.0e-10_wp, s, info)
      call hserrm(msg)
      call check(ctx, info == 1, "NSEG = 0: "//trim(msg))
      call hstrace(1, 3.7_wp, 2.47_wp, 0.0_wp, method_segments, 8, 4, 1.0e-10_wp, s, info)
      call hserrm(msg)
      call check(ctx, info == 1 .and. index(msg, "sampling") > 0, "ISAMP = 4: "//trim(msg))
      call hstrace(1, 3.7_wp, 2.47_wp, 0.0_wp, method_auto, 2, 1, 0.0_wp, s, info)
      call hserrm(msg)
      call check(ctx, info == 1, "TOL = 0: "//trim(msg))
      call hstrace(1, 3.7_wp, nan, 0.0_wp, method_auto, 2, 1, 1.0e-10_wp, s, info)
      call hserrm(msg)
      call check(ctx, info == 1 .and. index(msg, "finite") > 0, "BETA = NaN: "//trim(msg))
      call check(ctx, s == 0.0_wp, "S = 0 on error")
   end subroutine legacy_invalid_arguments

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
   !> Extreme inputs: a status, never a silent NaN or Inf; HSFLOQ reports overflow as HSTRACE.
   subroutine extreme_inputs_status(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(c_double) :: s, log_abs, q, mu_c, log_moduli(2)
      integer(c_int) :: overflow, status, stable, stable_paper
      real(wp) :: sl, mu
      integer :: istab, info, info_trace
      status = hillstab_c_coefficient(1_c_int, 1.0_c_double, 2.0_c_double, 0.0_c_double, &
         ieee_value(1.0_c_double, ieee_quiet_nan), q)
      call check(ctx, status == err_invalid_parameter, "hillstab_q: tau = NaN is an invalid parameter")
      status = hillstab_c_trace(2_c_int, 1.0_c_double, 1.0e308_c_double, 0.0_c_double, int(method_formula, c_int), &
         2_c_int, 1_c_int, 1.0e-10_c_double, s, log_abs, overflow)
      call check(ctx, status == err_invalid_parameter, "beta = 1e308: invalid parameter")
      status = hillstab_c_floquet(1_c_int, 1.0_c_double, 2.0_c_double, 1.0e200_c_double, int(method_formula, c_int), &
         2_c_int, 1_c_int, 1.0e-10_c_double, s, log_moduli, mu_c, stable, stable_paper)
      call check(ctx, status == err_invalid_parameter, "epsilon = 1e200: invalid parameter")
      ! a huge trace: the formula at beta = -1e6 overflows; HSTRACE and HSFLOQ both say INFO = 2
      call hstrace(2, 0.0_wp, -1.0e6_wp, 0.0_wp, method_formula, 2, 1, 1.0e-10_wp, sl, info_trace)
      call hsfloq(2, 0.0_wp, -1.0e6_wp, 0.0_wp, method_formula, 2, 1, 1.0e-10_wp, sl, mu, istab, info)
      call check(ctx, info == info_trace, "HSFLOQ and HSTRACE agree on INFO")
      call check(ctx, info_trace == 2, "HSTRACE: overflow")
      status = hillstab_c_trace(2_c_int, 0.0_c_double, -1.0e6_c_double, 0.0_c_double, int(method_formula, c_int), &
         2_c_int, 1_c_int, 1.0e-10_c_double, s, log_abs, overflow)
      call check(ctx, status == 0, "C: a huge trace is no error")
      call check(ctx, overflow == 1 .eqv. info_trace == 2, "C overflow flag as HSTRACE")
      call check(ctx, log_abs > 1000.0_c_double .and. log_abs < huge(1.0_c_double), "ln|S| finite and large")
      ! the bounds of scenes hold for every entry point: 2**30 pieces are refused, not allocated
      status = hillstab_c_trace(1_c_int, 4.0_c_double, 6.0_c_double, 0.0_c_double, int(method_segments, c_int), &
         2_c_int**30, 1_c_int, 1.0e-10_c_double, s, log_abs, overflow)
      call check(ctx, status == err_invalid_parameter, "n_segments = 2**30: invalid parameter")
      call hstrace(1, 4.0_wp, 6.0_wp, 0.0_wp, method_segments, 2**30, 1, 1.0e-10_wp, sl, info_trace)
      call check(ctx, info_trace /= 0, "HSTRACE: n_segments = 2**30 refused")
      status = hillstab_c_trace(1_c_int, 4.0_c_double, 6.0_c_double, 0.0_c_double, int(method_segments, c_int), &
         100000_c_int, 1_c_int, 1.0e-10_c_double, s, log_abs, overflow)
      call check(ctx, status == 0, "n_segments = 1e5: computed")
   end subroutine extreme_inputs_status

   !> hillstab_trace_paper_checked: the closed form's value with a status, where
   !> hillstab_trace_paper can only return a number.
   subroutine trace_paper_checked(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(c_double) :: s, log_abs
      integer(c_int) :: overflow, status
      type(trace_t) :: tr
      tr = trace_two_segment_paper(1.48_wp, 2.47_wp)
      status = hillstab_c_trace_paper_checked(1.48_c_double, 2.47_c_double, 0.0_c_double, s, log_abs, overflow)
      call check(ctx, status == 0 .and. overflow == 0, "eq. (37): status 0, no overflow")
      call check(ctx, real(s, wp), tr%value, rel=1.0e-15_wp)
      call check(ctx, real(log_abs, wp), log(abs(tr%value)), rel=1.0e-14_wp)
      call check(ctx, real(s, wp), real(hillstab_c_trace_paper(1.48_c_double, 2.47_c_double, 0.0_c_double), wp), &
         rel=1.0e-15_wp)
      tr = trace_damped_paper(3.7_wp, 2.47_wp, 0.3_wp)
      status = hillstab_c_trace_paper_checked(3.7_c_double, 2.47_c_double, 0.3_c_double, s, log_abs, overflow)
      call check(ctx, status == 0, "eq. (48): status 0")
      call check(ctx, real(s, wp), tr%value, rel=1.0e-15_wp)
      ! outside the model: the unchecked function still returns a number; the checked one refuses
      call check(ctx, ieee_is_finite(hillstab_c_trace_paper(10.0_c_double, 2.47_c_double, 0.0_c_double)), &
         "alpha > pi**2: hillstab_trace_paper gives a finite number, nothing says it is meaningless")
      s = -7.0_c_double
      status = hillstab_c_trace_paper_checked(10.0_c_double, 2.47_c_double, 0.0_c_double, s, log_abs, overflow)
      call check(ctx, status == err_invalid_parameter, "alpha > pi**2: invalid parameter")
      call check(ctx, s == -7.0_c_double, "output untouched on error")
      status = hillstab_c_trace_paper_checked(ieee_value(1.0_c_double, ieee_quiet_nan), 2.47_c_double, &
         0.0_c_double, s, log_abs, overflow)
      call check(ctx, status == err_invalid_parameter, "alpha = NaN: invalid parameter")
      status = hillstab_c_trace_paper_checked(1.0_c_double, 2.47_c_double, -1.0_c_double, s, log_abs, overflow)
      call check(ctx, status == err_invalid_parameter, "epsilon < 0: invalid parameter")
      ! alpha = 0, beta = -1e6: both pieces are Q = -1e6, S = 2 cosh(2*1000), ln S = 2000 + ln(1 + e^-4000)
      status = hillstab_c_trace_paper_checked(0.0_c_double, -1.0e6_c_double, 0.0_c_double, s, log_abs, overflow)
      call check(ctx, status == 0 .and. overflow == 1, "S = 2 cosh 2000: status 0, overflow flag")
      call check(ctx, s == huge(1.0_c_double), "S written as DBL_MAX")
      call check(ctx, hillstab_c_trace_paper(0.0_c_double, -1.0e6_c_double, 0.0_c_double) == s, &
         "hillstab_trace_paper gives the same DBL_MAX, with nothing to tell it from a value")
      call check(ctx, real(log_abs, wp), 2000.0_wp, rel=1.0e-13_wp)
   end subroutine trace_paper_checked
end module test_capi

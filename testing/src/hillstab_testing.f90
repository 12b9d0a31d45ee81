!> Minimal unit-test harness in the spirit of test-drive: named suites of named
!> tests, checks with absolute and relative tolerances, selection of one suite
!> or one test from the command line, and a closing line `N passed, M failed`.
!>
!> A test is a subroutine taking a `test_context_t`; every failed check is
!> recorded with its message and the test fails if any check failed.
module hillstab_testing
   use hillstab_core_kinds, only: wp
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   implicit none
   private
   public :: test_context_t, unittest_t, testsuite_t, new_unittest, new_testsuite
   public :: check, check_close, check_true, run_testsuites, test_procedure

   !> State of one running test: its failures so far.
   type :: test_context_t
      integer :: n_checks = 0
      integer :: n_failures = 0
      character(len=:), allocatable :: log
   end type test_context_t

   abstract interface
      !> A unit test.
      subroutine test_procedure(ctx)
         import :: test_context_t
         type(test_context_t), intent(inout) :: ctx
      end subroutine test_procedure
   end interface

   !> A named test. Its name has a fixed length: gfortran 12 leaks the allocatable components
   !> of function results gathered in an array constructor (`[new_unittest(...), ...]`), which
   !> LeakSanitizer reports in `make test-sanitize` (scripts/sanitize/constructor_leak.f90).
   type :: unittest_t
      character(len=40) :: name = ""
      procedure(test_procedure), pointer, nopass :: run => null()
   end type unittest_t

   !> A named list of tests.
   type :: testsuite_t
      character(len=:), allocatable :: name
      type(unittest_t), allocatable :: tests(:)
   end type testsuite_t

   !> Compare a real value with a reference (absolute and relative tolerances),
   !> or check a logical condition.
   interface check
      module procedure check_close
      module procedure check_true
   end interface check

contains

   !> Create a named test.
   function new_unittest(name, run) result(test)
      character(len=*), intent(in) :: name
      procedure(test_procedure) :: run
      type(unittest_t) :: test
      if (len(name) > len(test%name)) error stop "new_unittest: name longer than unittest_t%name"
      test%name = name
      test%run => run
   end function new_unittest

   !> Create a named suite.
   function new_testsuite(name, tests) result(suite)
      character(len=*), intent(in) :: name
      type(unittest_t), intent(in) :: tests(:)
      type(testsuite_t) :: suite
      suite%name = name
      suite%tests = tests
   end function new_testsuite

   subroutine record_failure(ctx, message)
      type(test_context_t), intent(inout) :: ctx
      character(len=*), intent(in) :: message
      ctx%n_failures = ctx%n_failures + 1
      if (.not. allocated(ctx%log)) ctx%log = ""
      if (ctx%n_failures <= 5) ctx%log = ctx%log//"      "//message//new_line("a")
   end subroutine record_failure

   !> Pass when |actual − expected| ≤ max(abs, rel·|expected|); non-finite values always fail.
   subroutine check_close(ctx, actual, expected, rel, abs, message)
      type(test_context_t), intent(inout) :: ctx
      real(wp), intent(in) :: actual    !! computed value
      real(wp), intent(in) :: expected  !! independent reference
      real(wp), intent(in), optional :: rel  !! relative tolerance (default 0)
      real(wp), intent(in), optional :: abs  !! absolute tolerance (default 0)
      character(len=*), intent(in), optional :: message  !! context for the failure report
      real(wp) :: tol, r, a
      character(len=200) :: buffer
      r = 0.0_wp; a = 0.0_wp
      if (present(rel)) r = rel
      if (present(abs)) a = abs
      if (.not. present(rel) .and. .not. present(abs)) r = 10*epsilon(1.0_wp)
      ctx%n_checks = ctx%n_checks + 1
      if (.not. (ieee_is_finite(actual) .and. ieee_is_finite(expected))) then
         call record_failure(ctx, "non-finite value"//context(message))
         return
      end if
      tol = max(a, r*max_abs(expected))
      if (max_abs(actual - expected) > tol) then
         write (buffer, '(a,es23.15,a,es23.15,a,es9.2,a,es9.2)') "got ", actual, " expected ", expected, &
            " diff ", max_abs(actual - expected), " tol ", tol
         call record_failure(ctx, trim(buffer)//context(message))
      end if
   end subroutine check_close

   !> Pass when `condition` holds.
   subroutine check_true(ctx, condition, message)
      type(test_context_t), intent(inout) :: ctx
      logical, intent(in) :: condition
      character(len=*), intent(in), optional :: message
      ctx%n_checks = ctx%n_checks + 1
      if (.not. condition) call record_failure(ctx, "condition false"//context(message))
   end subroutine check_true

   pure real(wp) function max_abs(x)
      real(wp), intent(in) :: x
      max_abs = abs(x)
   end function max_abs

   pure function context(message) result(text)
      character(len=*), intent(in), optional :: message
      character(len=:), allocatable :: text
      text = ""
      if (present(message)) text = " ["//message//"]"
   end function context

   !> Run the suites, or only the suite named by the first command-line
   !> argument and, if a second is given, only that test; a first argument
   !> `--skip=SUITE[,SUITE...]` runs every suite but those. Prints one line per
   !> test and closes with `N passed, M failed`; returns the number of failures.
   subroutine run_testsuites(suites, n_failed)
      type(testsuite_t), intent(in) :: suites(:)
      integer, intent(out) :: n_failed
      character(len=256) :: suite_name, test_name
      character(len=:), allocatable :: skipped
      integer :: i, j, n_passed, n_selected
      type(test_context_t) :: ctx
      suite_name = ""; test_name = ""; skipped = ""
      if (command_argument_count() >= 1) call get_command_argument(1, suite_name)
      if (command_argument_count() >= 2) call get_command_argument(2, test_name)
      if (index(suite_name, "--skip=") == 1) then
         skipped = ","//trim(suite_name(len("--skip=") + 1:))//","
         suite_name = ""
      end if
      n_passed = 0; n_failed = 0; n_selected = 0
      do i = 1, size(suites)
         if (len_trim(suite_name) > 0 .and. suites(i)%name /= trim(suite_name)) cycle
         if (index(skipped, ","//suites(i)%name//",") > 0) then
            write (*, '(a)') "# suite "//suites(i)%name//" skipped"
            cycle
         end if
         write (*, '(a)') "# suite "//suites(i)%name
         do j = 1, size(suites(i)%tests)
            if (len_trim(test_name) > 0 .and. suites(i)%tests(j)%name /= trim(test_name)) cycle
            n_selected = n_selected + 1
            ctx = test_context_t()
            call suites(i)%tests(j)%run(ctx)
            if (ctx%n_failures == 0 .and. ctx%n_checks > 0) then
               n_passed = n_passed + 1
               write (*, '(a,i0,a)') "  PASS "//suites(i)%name//"/"//trim(suites(i)%tests(j)%name)//" (", &
                  ctx%n_checks, " checks)"
            else
               n_failed = n_failed + 1
               if (ctx%n_checks == 0) call record_failure(ctx, "test made no checks")
               write (*, '(a,i0,a,i0,a)') "  FAIL "//suites(i)%name//"/"//trim(suites(i)%tests(j)%name)//" (", &
                  ctx%n_failures, " of ", ctx%n_checks, " checks failed)"
               write (*, '(a)', advance="no") ctx%log
            end if
         end do
      end do
      if (n_selected == 0) then
         write (*, '(a)') "no test matches '"//trim(suite_name)//" "//trim(test_name)//"'"
         n_failed = n_failed + 1
      end if
      write (*, '(i0,a,i0,a)') n_passed, " passed, ", n_failed, " failed"
   end subroutine run_testsuites
end module hillstab_testing

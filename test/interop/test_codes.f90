!> The lists that must agree with the tables, checked against them: the C header's
!> HILLSTAB_MODEL_*, HILLSTAB_METHOD_* and HILLSTAB_SAMPLING_* enums (include/hillstab.h)
!> and the MODEL, METHOD and ISAMP codes documented in the F77 entry points
!> (src/hillstab/interop/legacy.f90, legacy_external.f90) against the model table
!> (hillstab_hill_models), the method table (hillstab_integrate_monodromy) and the
!> sampling table (hillstab_hill_coefficient); and the header's HILLSTAB_VERSION_* macros
!> against `version_string` (hillstab_core_kinds) and the version of fpm.toml; the guide's
!> table of models (docs/guide/model.md) against the model table. Paths are relative to the worktree root,
!> the directory `fpm test` runs in.
module test_codes
   use hillstab_core_text, only: lower_case
   use hillstab_core_kinds, only: version_string
   use hillstab_interop_capi, only: version_numbers
   use hillstab_hill_coefficient, only: sampling_count, sampling_name, sampling_from_name
   use hillstab_integrate_monodromy, only: method_table, method_name, method_from_name
   use hillstab_testing
   use hillstab_hill_models, only: model_count, model_names
   use hillstab_core_text, only: name_position, integer_text
   use hillstab_core_error, only: err_points_failed
   use hillstab_integrate_monodromy, only: need_verdict, need_growth, need_trace
   use hillstab_interop_capi_batch, only: value_trace, value_log_abs_trace, value_log10_abs_trace, value_overflow, &
      value_stable, value_stable_paper, value_lambda_max, value_log_modulus_max, value_log_modulus_min, &
      value_exponent, value_error_estimate, value_count
   implicit none
   private
   public :: collect_codes

   character(len=*), parameter :: header_path = "include/hillstab.h"
   character(len=*), parameter :: legacy_paths(2) = [character(len=40) :: "src/hillstab/interop/legacy.f90", &
      "src/hillstab/interop/legacy_external.f90"]

contains

   function collect_codes() result(suite)
      type(testsuite_t) :: suite
      suite = new_testsuite("codes", [ &
         new_unittest("c_header_enums", c_header_enums), &
         new_unittest("f77_codes", f77_codes), &
         new_unittest("c_header_version", c_header_version), &
         new_unittest("c_header_batch_enums", c_header_batch_enums), &
         new_unittest("citation_in_step", citation_in_step), &
         new_unittest("guide_lists_every_model", guide_lists_every_model)])
   end function collect_codes

   !> The whole file as one lower-case line (comment markers and line ends as blanks).
   function file_text(ctx, path) result(text)
      type(test_context_t), intent(inout) :: ctx
      character(len=*), intent(in) :: path
      character(len=:), allocatable :: text
      character(len=1000) :: line
      integer :: unit, ios
      text = ""
      open (newunit=unit, file=path, status="old", action="read", iostat=ios)
      call check(ctx, ios == 0, "cannot open "//path//" (run the tests from the worktree root)")
      if (ios /= 0) return
      do
         read (unit, '(a)', iostat=ios) line
         if (ios /= 0) exit
         text = text//" "//trim(line)
      end do
      close (unit)
   end function file_text

   !> The code of a model name in the model registry (−1 when it has no such model).
   integer function model_code_of(name) result(code)
      character(len=*), intent(in) :: name
      code = name_position(name, model_names)
      if (code == 0) code = -1
   end function model_code_of

   !> The code of a name in one of the three tables (−1 when the table has no such name).
   integer function table_code(table, name) result(code)
      character(len=*), intent(in) :: table, name
      select case (table)
      case ("model"); code = model_code_of(name)
      case ("method"); code = method_from_name(name)
      case default; code = sampling_from_name(name)
      end select
   end function table_code

   !> Every `HILLSTAB_<TABLE>_<NAME> = <code>` of the header: the name is in the table with
   !> that code, and every entry of the table is declared.
   subroutine c_header_enums(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=*), parameter :: tables(3) = [character(len=8) :: "model", "method", "sampling"]
      character(len=:), allocatable :: text, prefix, name
      integer :: t, at, start, finish, code, ios, k, n_found
      logical :: seen(0:20)
      text = file_text(ctx, header_path)
      do t = 1, size(tables)
         prefix = "HILLSTAB_"//upper(trim(tables(t)))//"_"
         seen = .false.
         n_found = 0
         at = 1
         do
            start = index(text(at:), prefix)
            if (start == 0) exit
            start = at + start - 1 + len(prefix)
            finish = start + verify(text(start:), "ABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789") - 2
            name = lower_case(text(start:finish))
            ! an enumerator is followed by "= <digits>" (elsewhere the name is only mentioned)
            at = finish + verify(text(finish + 1:), " ")
            if (text(at:at) /= "=") cycle
            at = at + verify(text(at + 1:), " ")
            ios = 1
            if (verify(text(at:at), "0123456789") == 0) then
               read (text(at:at + verify(text(at:), "0123456789") - 2), *, iostat=ios) code
            end if
            call check(ctx, ios == 0, "a code after "//prefix//upper(name))
            if (ios /= 0) exit
            n_found = n_found + 1
            call check(ctx, table_code(trim(tables(t)), name) == code, prefix//upper(name)//" is the "// &
               trim(tables(t))//" table's code of '"//name//"'")
            if (code >= 0 .and. code <= 20) seen(code) = .true.
         end do
         ! every entry of the table declared, under its name
         select case (trim(tables(t)))
         case ("model")
            call check(ctx, n_found == model_count .and. all(seen(1:model_count)), "every model in the C enum")
            do k = 1, model_count
               call check(ctx, index(text, prefix//upper(trim(model_names(k)))//" =") > 0, prefix//upper(trim(model_names(k))))
            end do
         case ("method")
            call check(ctx, n_found == size(method_table) .and. &
               all(seen(lbound(method_table, 1):ubound(method_table, 1))), "every method in the C enum")
            do k = lbound(method_table, 1), ubound(method_table, 1)
               call check(ctx, index(text, prefix//upper(method_name(k))//" =") > 0, prefix//upper(method_name(k)))
            end do
         case default
            call check(ctx, n_found == sampling_count .and. all(seen(1:sampling_count)), "every sampling in the C enum")
            do k = 1, sampling_count
               call check(ctx, index(text, prefix//upper(sampling_name(k))//" =") > 0, prefix//upper(sampling_name(k)))
            end do
         end select
      end do
   end subroutine c_header_enums

   !> In the F77 entry points' documentation every "<digit> <name>" naming an entry of a
   !> table gives that entry's code, and every entry of each table is documented.
   subroutine f77_codes(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=:), allocatable :: text, word
      integer :: f, i, j, code, k
      logical :: methods(0:20), models(0:20), samplings(0:20)
      do f = 1, size(legacy_paths)
         text = lower_case(file_text(ctx, trim(legacy_paths(f))))
         methods = .false.; models = .false.; samplings = .false.
         do i = 1, len(text) - 2
            if (index("0123456789", text(i:i)) == 0 .or. text(i + 1:i + 1) /= " ") cycle
            if (i > 1) then
               if (index("0123456789.e-", text(i - 1:i - 1)) > 0) cycle   ! part of a number
            end if
            j = i + 2
            do while (j <= len(text))
               if (index("abcdefghijklmnopqrstuvwxyz0123456789", text(j:j)) == 0) exit
               j = j + 1
            end do
            word = text(i + 2:j - 1)
            code = iachar(text(i:i)) - iachar("0")
            if (method_from_name(word) >= 0) then
               call check(ctx, method_from_name(word) == code, trim(legacy_paths(f))//": '"//text(i:j - 1)// &
                  "' names method code "//text(i:i))
               methods(code) = .true.
            end if
            if (model_code_of(word) >= 0) then
               call check(ctx, model_code_of(word) == code, trim(legacy_paths(f))//": '"//text(i:j - 1)// &
                  "' names model code "//text(i:i))
               models(code) = .true.
            end if
            if (sampling_from_name(word) >= 0) then
               call check(ctx, sampling_from_name(word) == code, trim(legacy_paths(f))//": '"//text(i:j - 1)// &
                  "' names sampling code "//text(i:i))
               samplings(code) = .true.
            end if
         end do
         do k = lbound(method_table, 1), ubound(method_table, 1)
            call check(ctx, methods(k), trim(legacy_paths(f))//" documents method "//method_name(k))
         end do
         do k = 1, model_count
            call check(ctx, models(k), trim(legacy_paths(f))//" documents model "//trim(model_names(k)))
         end do
         do k = 1, sampling_count
            call check(ctx, samplings(k), trim(legacy_paths(f))//" documents sampling "//sampling_name(k))
         end do
      end do
   end subroutine f77_codes

   !> The header's version macros, `version_string` and fpm.toml's `version = "..."` agree.
   subroutine c_header_version(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=*), parameter :: parts(3) = [character(len=5) :: "MAJOR", "MINOR", "PATCH"]
      character(len=:), allocatable :: text, manifest, macro
      integer :: numbers(3), k, at, value, ios
      numbers = version_numbers(version_string)
      call check(ctx, all(numbers >= 0), "version_string '"//version_string//"' is MAJOR.MINOR.PATCH")
      text = file_text(ctx, header_path)
      do k = 1, 3
         macro = "#define HILLSTAB_VERSION_"//trim(parts(k))//" "
         at = index(text, macro)
         call check(ctx, at > 0, macro//"in "//header_path)
         if (at == 0) cycle
         read (text(at + len(macro):), *, iostat=ios) value
         call check(ctx, ios == 0 .and. value == numbers(k), macro//"is the "//trim(parts(k))// &
            " number of version_string "//version_string)
      end do
      call check(ctx, index(text, '#define HILLSTAB_VERSION_STRING "'//version_string//'"') > 0, &
         "HILLSTAB_VERSION_STRING is version_string "//version_string)
      manifest = file_text(ctx, "fpm.toml")
      call check(ctx, index(manifest, ' version = "'//version_string//'"') > 0, &
         "fpm.toml's version is version_string "//version_string)
   end subroutine c_header_version

   !> CITATION.cff gives the version of fpm.toml (`version_string`) and a `date-released`
   !> (YYYY-MM-DD); the newest entry of CHANGELOG.md (its first `## ` heading) is that version
   !> on that date.
   subroutine citation_in_step(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=:), allocatable :: citation, changelog, heading, date
      integer :: at, next
      citation = file_text(ctx, "CITATION.cff")
      call check(ctx, index(citation, ' version: "'//version_string//'"') > 0, &
         "CITATION.cff's version is fpm.toml's "//version_string)
      at = index(citation, " date-released: ")
      call check(ctx, at > 0, "CITATION.cff has a date-released")
      if (at == 0) return
      date = adjustl(citation(at + len(" date-released: "):))
      if (date(1:1) == '"' .or. date(1:1) == "'") date = date(2:)
      date = date(:min(10, len(date)))
      call check(ctx, verify(date, "0123456789-") == 0 .and. len(date) == 10 .and. date(5:5) == "-" .and. &
         date(8:8) == "-", "date-released is YYYY-MM-DD: "//date)
      changelog = file_text(ctx, "CHANGELOG.md")
      at = index(changelog, " ## ")
      call check(ctx, at > 0, "CHANGELOG.md has a version heading (## )")
      if (at == 0) return
      next = index(changelog(at + 4:), " ## ")
      if (next == 0) next = len(changelog) - at - 3
      heading = changelog(at + 4:at + 3 + min(next - 1, 80))
      call check(ctx, index(heading, version_string//" ") == 1, "CHANGELOG.md's newest entry is version "// &
         version_string//": "//heading)
      call check(ctx, index(heading, date) > 0, "CHANGELOG.md's newest entry carries CITATION.cff's date-released "// &
         date//": "//heading)
   end subroutine citation_in_step

   pure function upper(text) result(up)
      character(len=*), intent(in) :: text
      character(len=len(text)) :: up
      integer :: i
      up = text
      do i = 1, len(text)
         if (text(i:i) >= "a" .and. text(i:i) <= "z") up(i:i) = achar(iachar(text(i:i)) - 32)
      end do
   end function upper
   !> The header's HILLSTAB_NEED_*, HILLSTAB_VALUE_* and HILLSTAB_ERR_POINTS_FAILED against the
   !> constants of the library (hillstab_integrate_monodromy need_*, hillstab_interop_capi_batch
   !> value_*, hillstab_core_error err_points_failed).
   subroutine c_header_batch_enums(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=:), allocatable :: text
      character(len=24), parameter :: values(value_count + 1) = [character(len=24) :: "TRACE", "LOG_ABS_TRACE", &
         "LOG10_ABS_TRACE", "OVERFLOW", "STABLE", "STABLE_PAPER", "LAMBDA_MAX", "LOG_MODULUS_MAX", "LOG_MODULUS_MIN", &
         "EXPONENT", "ERROR_ESTIMATE", "COUNT"]
      integer, parameter :: codes(value_count + 1) = [value_trace, value_log_abs_trace, value_log10_abs_trace, &
         value_overflow, value_stable, value_stable_paper, value_lambda_max, value_log_modulus_max, &
         value_log_modulus_min, value_exponent, value_error_estimate, value_count]
      integer :: k
      text = file_text(ctx, header_path)
      call expect("HILLSTAB_NEED_VERDICT", need_verdict)
      call expect("HILLSTAB_NEED_GROWTH", need_growth)
      call expect("HILLSTAB_NEED_TRACE", need_trace)
      call expect("HILLSTAB_ERR_POINTS_FAILED", err_points_failed)
      do k = 1, size(values)
         call expect("HILLSTAB_VALUE_"//trim(values(k)), codes(k))
      end do
      ! the values are 0 ... count - 1, each once
      do k = 0, value_count - 1
         call check(ctx, count(codes(:value_count) == k) == 1, "one value of index "//integer_text(k))
      end do
   contains
      subroutine expect(name, code)
         character(len=*), intent(in) :: name
         integer, intent(in) :: code
         call check(ctx, index(text, " "//name//" = "//integer_text(code)//",") > 0 .or. &
            index(text, " "//name//" = "//integer_text(code)//" ") > 0, name//" = "//integer_text(code))
      end subroutine expect
   end subroutine c_header_batch_enums
   !> The table of models on docs/guide/model.md: its rows "| `name` | code | ..." name
   !> exactly the registry's models, each with its code, in the order of the codes.
   subroutine guide_lists_every_model(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=*), parameter :: path = "docs/guide/model.md"
      character(len=1000) :: line
      character(len=:), allocatable :: name, rest
      integer :: unit, ios, n, code, close_quote, bar
      open (newunit=unit, file=path, status="old", action="read", iostat=ios)
      call check(ctx, ios == 0, "cannot open "//path//" (run the tests from the worktree root)")
      if (ios /= 0) return
      n = 0
      do
         read (unit, '(a)', iostat=ios) line
         if (ios /= 0) exit
         if (index(line, "| `") /= 1) cycle
         close_quote = index(line(4:), "`") + 2
         if (close_quote <= 3) cycle
         name = line(4:close_quote)
         rest = adjustl(line(close_quote + 2:))
         if (index(rest, "|") /= 1) cycle
         rest = adjustl(rest(2:))
         bar = index(rest, "|")
         if (bar == 0) cycle
         read (rest(:bar - 1), *, iostat=ios) code
         if (ios /= 0) cycle  ! another table of the page
         n = n + 1
         call check(ctx, model_code_of(name) == n .and. code == n, path//": row "//integer_text(n)//" is model '"// &
                    name//"' with code "//integer_text(code)//"; the registry's code "//integer_text(n)//" is '"// &
                    trim(model_names(min(max(n, 1), model_count)))//"'")
      end do
      close (unit)
      call check(ctx, n == model_count, path//" lists "//integer_text(n)//" models, the registry has "// &
                 integer_text(model_count))
   end subroutine guide_lists_every_model
end module test_codes

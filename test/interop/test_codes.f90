!> The lists that must agree with the tables, checked against them: the C header's
!> HILLSTAB_MODEL_*, HILLSTAB_METHOD_* and HILLSTAB_SAMPLING_* enums (include/hillstab.h)
!> and the MODEL, METHOD and ISAMP codes documented in the F77 entry points
!> (src/hillstab/interop/legacy.f90, legacy_external.f90) against the model table
!> (hillstab_hill_models), the method table (hillstab_integrate_monodromy) and the
!> sampling table (hillstab_hill_coefficient); and the header's HILLSTAB_VERSION_* macros
!> against `version_string` (hillstab_core_kinds) and the version of fpm.toml; the guide's
!> table of models (docs/guide/model.md) against the model table. Every code another language
!> copies is checked against the Fortran constant it copies (`known_codes`): every enumerator
!> of the header (models, methods, samplings, error codes, the characteristic kinds, NEED_*,
!> VALUE_*, the system verdicts and kinds, the region kinds and statuses), every code of the
!> Python package (python/hillstab: ERR_*, NEED_*, STATUS_*, VERDICT_*, KIND_*, REGION_*, the
!> dicts METHODS, SYSTEM_METHODS, SAMPLINGS and KIND_NAMES, the tuple VALUES), the status codes
!> the header and Python document, the methods the header says systems take; a missing entry
!> fails as a wrong one does, and so does a code no Fortran constant stands behind. Paths are
!> relative to the worktree root, the directory `fpm test` runs in.
module test_codes
   use hillstab_core_text, only: lower_case
   use hillstab_core_kinds, only: version_string
   use hillstab_interop_capi, only: version_numbers
   use hillstab_hill_coefficient, only: sampling_count, sampling_name, sampling_from_name
   use hillstab_integrate_monodromy, only: method_table, method_name, method_from_name
   use hillstab_batch_scene_group_chart, only: scale_linear, scale_log
   use hillstab_batch_tasks_floquet_columns, only: chart_keys
   use hillstab_testing
   use hillstab_hill_models, only: model_count, model_names
   use hillstab_core_text, only: name_position, integer_text
   use hillstab_core_error, only: err_points_failed, err_invalid_parameter, err_overflow, err_integration, err_io, &
      err_input, err_singular, err_accuracy, error_code_name
   use hillstab_core_status, only: status_ok, status_roundoff, status_failed, status_name
   use hillstab_integrate_monodromy, only: need_verdict, need_growth, need_trace, method_takes_systems
   use hillstab_hill_system_floquet, only: verdict_stable, verdict_unstable, verdict_marginal, kind_stable, &
      kind_plus_one, kind_minus_one, kind_combination, kind_damped, kind_undecided, kind_name
   use hillstab_curves_hill_method, only: block_periodic_even, block_periodic_odd, block_antiperiodic_even, &
      block_antiperiodic_odd, block_periodic, block_antiperiodic
   use hillstab_curves_regions, only: region_simple, region_sum, region_difference, region_found, region_closed, &
      region_unconfirmed, region_open_below, region_theory, region_same_signature, region_kind_name, &
      region_unassigned, region_uncovered, &
      region_status_name
   use hillstab_interop_capi_batch, only: value_trace, value_log_abs_trace, value_log10_abs_trace, value_overflow, &
      value_stable, value_stable_paper, value_lambda_max, value_log_modulus_max, value_log_modulus_min, &
      value_exponent, value_error_estimate, value_kind, value_argument, value_count
   implicit none
   private
   public :: collect_codes

   character(len=*), parameter :: header_path = "include/hillstab.h"
   character(len=*), parameter :: legacy_paths(2) = [character(len=40) :: "src/hillstab/interop/legacy.f90", &
      "src/hillstab/interop/legacy_external.f90"]
   !> The modules of the Python package (every one is read for codes).
   character(len=*), parameter :: python_paths(9) = [character(len=32) :: "python/hillstab/__init__.py", &
      "python/hillstab/_capi.py", "python/hillstab/curves.py", "python/hillstab/errors.py", &
      "python/hillstab/floquet.py", "python/hillstab/models.py", "python/hillstab/scenes.py", &
      "python/hillstab/spring.py", "python/hillstab/system.py"]
   !> The names of the values of a point, by their index (HILLSTAB_VALUE_*, Python's VALUES).
   character(len=*), parameter :: value_names(0:value_count - 1) = [character(len=16) :: "trace", "log_abs_trace", &
      "log10_abs_trace", "overflow", "stable", "stable_paper", "lambda_max", "log_modulus_max", "log_modulus_min", &
      "exponent", "error_estimate", "kind", "argument"]
   !> The same values by the files' names (the columns of chart and points files, Python's
   !> names, HILLSTAB_VALUE_S ...): "" where the value has no such name of its own; where it
   !> differs from `value_names` the header declares it too, an alias of the same index.
   character(len=*), parameter :: value_file_names(0:value_count - 1) = [character(len=16) :: "S", "log_abs_S", &
      "log10_abs_S", "overflow", "stable", "stable_paper", "lambda_max", "", "", "mu", "error_estimate", "kind", &
      "argument"]
   !> Of those, the ones no file column has (named in the same style).
   character(len=*), parameter :: no_column_names(1) = [character(len=16) :: "log_abs_S"]

   !> One code that another language copies: its name in include/hillstab.h after `HILLSTAB_`
   !> ("" when the header has no enumerator for it), its name in the Python package ("" when
   !> Python has no constant for it), and its value, the Fortran constant's.
   type :: known_code_t
      character(len=40) :: c_name = ""
      character(len=40) :: py_name = ""
      integer :: code = 0
   end type known_code_t

   !> One token of a Python literal: kind "s" a string (its text), "i" an integer, "n" a
   !> name, "p" one character of punctuation.
   type :: token_t
      character(len=1) :: kind = "p"
      character(len=80) :: text = ""
      integer :: value = 0
   end type token_t

contains

   function collect_codes() result(suite)
      type(testsuite_t) :: suite
      suite = new_testsuite("codes", [ &
         new_unittest("c_header_enums", c_header_enums), &
         new_unittest("f77_codes", f77_codes), &
         new_unittest("c_header_version", c_header_version), &
         new_unittest("c_header_batch_enums", c_header_batch_enums), &
         new_unittest("known_codes_complete", known_codes_complete), &
         new_unittest("c_header_every_enumerator", c_header_every_enumerator), &
         new_unittest("c_header_system_methods", c_header_system_methods), &
         new_unittest("python_codes", python_codes), &
         new_unittest("status_codes_documented", status_codes_documented), &
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
   !> table gives that entry's code, and every entry of each table is documented; so are the
   !> INFO codes "2 overflow", "7 round-off limited" and "1 invalid parameter" (hillstab_core_error).
   subroutine f77_codes(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=:), allocatable :: text, word
      integer :: f, i, j, code, k
      character(len=*), parameter :: info_words(3) = [character(len=8) :: "overflow", "round", "invalid"]
      integer, parameter :: info_codes(3) = [err_overflow, err_accuracy, err_invalid_parameter]
      logical :: methods(0:20), models(0:20), samplings(0:20), infos(size(info_words))
      do f = 1, size(legacy_paths)
         text = lower_case(file_text(ctx, trim(legacy_paths(f))))
         methods = .false.; models = .false.; samplings = .false.; infos = .false.
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
            ! INFO: "2 overflow", "7 round-off limited", "1 invalid parameter"
            do k = size(info_words), 1, -1
               if (info_words(k) == word) exit
            end do
            if (k > 0) then
               call check(ctx, info_codes(k) == code, trim(legacy_paths(f))//": '"//text(i:j - 1)// &
                  "' is INFO "//text(i:i)//", the error code is "//integer_text(info_codes(k)))
               infos(k) = .true.
            end if
         end do
         do k = 1, size(info_words)
            call check(ctx, infos(k), trim(legacy_paths(f))//" documents INFO "//integer_text(info_codes(k))//" "// &
                       trim(info_words(k)))
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

   !> Every code another language copies, from the Fortran constants and tables.
   function known_codes() result(codes)
      type(known_code_t), allocatable :: codes(:)
      integer :: k
      allocate (codes(0))
      do k = 1, model_count
         call add("MODEL_"//upper(trim(model_names(k))), "", k)
      end do
      do k = lbound(method_table, 1), ubound(method_table, 1)
         call add("METHOD_"//upper(method_name(k)), "", k)
      end do
      do k = 1, sampling_count
         call add("SAMPLING_"//upper(sampling_name(k)), "", k)
      end do
      call add("SCALE_LINEAR", "", scale_linear)
      call add("SCALE_LOG", "", scale_log)
      call add_both("ERR_INVALID_PARAMETER", err_invalid_parameter)
      call add_both("ERR_OVERFLOW", err_overflow)
      call add_both("ERR_INTEGRATION", err_integration)
      call add_both("ERR_IO", err_io)
      call add_both("ERR_INPUT", err_input)
      call add_both("ERR_SINGULAR", err_singular)
      call add_both("ERR_ACCURACY", err_accuracy)
      call add_both("ERR_POINTS_FAILED", err_points_failed)
      call add("KIND_PERIODIC_EVEN", "", block_periodic_even)
      call add("KIND_PERIODIC_ODD", "", block_periodic_odd)
      call add("KIND_ANTIPERIODIC_EVEN", "", block_antiperiodic_even)
      call add("KIND_ANTIPERIODIC_ODD", "", block_antiperiodic_odd)
      call add("KIND_PERIODIC", "", block_periodic)
      call add("KIND_ANTIPERIODIC", "", block_antiperiodic)
      call add_both("NEED_VERDICT", need_verdict)
      call add_both("NEED_GROWTH", need_growth)
      call add_both("NEED_TRACE", need_trace)
      do k = 0, value_count - 1
         call add("VALUE_"//upper(trim(value_names(k))), "", k)
      end do
      call add("VALUE_COUNT", "", value_count)
      do k = 0, value_count - 1
         if (value_file_names(k) == "" .or. value_file_names(k) == value_names(k)) cycle
         call add("VALUE_"//upper(trim(value_file_names(k))), "", k)
      end do
      call add("SYSTEM_VERDICT_UNSTABLE", "VERDICT_UNSTABLE", verdict_unstable)
      call add("SYSTEM_VERDICT_STABLE", "VERDICT_STABLE", verdict_stable)
      call add("SYSTEM_VERDICT_MARGINAL", "VERDICT_MARGINAL", verdict_marginal)
      call add("SYSTEM_KIND_STABLE", "KIND_STABLE", kind_stable)
      call add("SYSTEM_KIND_PLUS_ONE", "KIND_PLUS_ONE", kind_plus_one)
      call add("SYSTEM_KIND_MINUS_ONE", "KIND_MINUS_ONE", kind_minus_one)
      call add("SYSTEM_KIND_COMBINATION", "KIND_COMBINATION", kind_combination)
      call add("SYSTEM_KIND_DAMPED", "KIND_DAMPED", kind_damped)
      call add("SYSTEM_KIND_UNDECIDED", "KIND_UNDECIDED", kind_undecided)
      call add_both("REGION_SIMPLE", region_simple)
      call add_both("REGION_SUM", region_sum)
      call add_both("REGION_DIFFERENCE", region_difference)
      call add_both("REGION_FOUND", region_found)
      call add_both("REGION_CLOSED", region_closed)
      call add_both("REGION_UNCONFIRMED", region_unconfirmed)
      call add_both("REGION_OPEN_BELOW", region_open_below)
      call add_both("REGION_THEORY", region_theory)
      call add_both("REGION_SAME_SIGNATURE", region_same_signature)
      call add_both("REGION_UNASSIGNED", region_unassigned)
      call add_both("REGION_UNCOVERED", region_uncovered)
      call add("", "STATUS_OK", status_ok)
      call add("", "STATUS_ROUNDOFF", status_roundoff)
      call add("", "STATUS_FAILED", status_failed)
   contains
      subroutine add(c_name, py_name, code)
         character(len=*), intent(in) :: c_name, py_name
         integer, intent(in) :: code
         codes = [codes, known_code_t(c_name, py_name, code)]
      end subroutine add
      subroutine add_both(name, code)
         character(len=*), intent(in) :: name
         integer, intent(in) :: code
         call add(name, name, code)
      end subroutine add_both
   end function known_codes

   !> The index in `codes` of the code of that C or Python name (0: none).
   integer function code_named(codes, c_name, py_name) result(k)
      type(known_code_t), intent(in) :: codes(:)
      character(len=*), intent(in), optional :: c_name, py_name
      do k = 1, size(codes)
         if (present(c_name)) then
            if (codes(k)%c_name == c_name) return
         end if
         if (present(py_name)) then
            if (codes(k)%py_name == py_name) return
         end if
      end do
      k = 0
   end function code_named

   !> The hand-made part of `known_codes` covers the Fortran constants: every error code,
   !> system kind and status that has a name (`error_code_name`, `kind_name`, `status_name`)
   !> is listed and nothing else, the characteristic kinds are 1 … 6 and the values 0 …
   !> count − 1, each once, and no two entries share a name.
   subroutine known_codes_complete(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(known_code_t), allocatable :: codes(:)
      integer :: k
      codes = known_codes()
      do k = -5, 40
         call check(ctx, (error_code_name(k) /= "error") .eqv. listed("ERR_", k), "error code "//integer_text(k)// &
                    " ('"//error_code_name(k)//"') listed in known_codes exactly when it has a name")
         call check(ctx, (kind_name(k) /= "unknown") .eqv. listed("SYSTEM_KIND_", k), "system kind "// &
                    integer_text(k)//" ('"//kind_name(k)//"') listed exactly when it has a name")
         call check(ctx, (status_name(k) /= "unknown") .eqv. listed("STATUS_", k), "status "//integer_text(k)// &
                    " ('"//status_name(k)//"') listed exactly when it has a name")
         call check(ctx, (region_kind_name(k) /= "unknown") .eqv. listed_as("REGION_", k, region_kind_name(k)), &
                    "region kind "//integer_text(k)//" ('"//region_kind_name(k)//"') listed exactly when it has a name")
         call check(ctx, (region_status_name(k) /= "unknown") .eqv. listed_as("REGION_", k, region_status_name(k)), &
                    "region status "//integer_text(k)//" ('"//region_status_name(k)//"') listed exactly when it "// &
                    "has a name")
      end do
      do k = 1, 6
         call check(ctx, count(codes%code == k .and. index(codes%c_name, "KIND_") == 1) == 1, &
                    "one characteristic kind "//integer_text(k))
      end do
      do k = 1, size(codes)
         if (codes(k)%c_name /= "") call check(ctx, count(codes%c_name == codes(k)%c_name) == 1, &
                                              "one code named HILLSTAB_"//trim(codes(k)%c_name))
         if (codes(k)%py_name /= "") call check(ctx, count(codes%py_name == codes(k)%py_name) == 1, &
                                               "one code named "//trim(codes(k)%py_name)//" in Python")
      end do
   contains
      !> Whether a code is listed under prefix//NAME, NAME the upper-case `name` (blanks as _).
      logical function listed_as(prefix, code, name)
         character(len=*), intent(in) :: prefix, name
         integer, intent(in) :: code
         character(len=:), allocatable :: wanted
         integer :: i
         wanted = prefix//upper(name)
         do i = 1, len(wanted)
            if (wanted(i:i) == " ") wanted(i:i) = "_"
         end do
         listed_as = .false.
         do i = 1, size(codes)
            if (codes(i)%code == code .and. codes(i)%c_name == wanted) listed_as = .true.
         end do
      end function listed_as

      logical function listed(prefix, code)
         character(len=*), intent(in) :: prefix
         integer, intent(in) :: code
         integer :: i
         listed = .false.
         do i = 1, size(codes)
            if (codes(i)%code /= code) cycle
            if (index(codes(i)%c_name, prefix) == 1 .or. index(codes(i)%py_name, prefix) == 1) listed = .true.
         end do
      end function listed
   end subroutine known_codes_complete

   !> Every enumerator `HILLSTAB_<NAME> = <code>` of the header is a known code with the
   !> Fortran value (a code the test does not know fails: add it to `known_codes`, from its
   !> Fortran constant), and every known code with a C name is declared once.
   subroutine c_header_every_enumerator(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=*), parameter :: prefix = "HILLSTAB_"
      type(known_code_t), allocatable :: codes(:)
      character(len=:), allocatable :: text, name
      integer, allocatable :: found(:)
      integer :: at, start, finish, code, ios, k, sign
      codes = known_codes()
      allocate (found(size(codes)), source=0)
      text = file_text(ctx, header_path)
      at = 1
      do
         start = index(text(at:), prefix)
         if (start == 0) exit
         start = at + start - 1 + len(prefix)
         finish = start + verify(text(start:)//" ", "ABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_") - 2
         name = text(start:finish)
         at = finish + verify(text(finish + 1:)//"x", " ")
         if (at >= len(text)) exit
         if (text(at:at) /= "=" .or. text(at:at + 1) == "==") cycle   ! only mentioned, or a #define
         at = at + verify(text(at + 1:), " ")
         sign = 1
         if (text(at:at) == "-") then
            sign = -1
            at = at + 1
         end if
         ios = 1
         if (verify(text(at:at), "0123456789") == 0) then
            read (text(at:at + verify(text(at:), "0123456789") - 2), *, iostat=ios) code
         end if
         call check(ctx, ios == 0, "a code after "//prefix//name//" =")
         if (ios /= 0) cycle
         code = sign*code
         k = code_named(codes, c_name=name)
         call check(ctx, k > 0, header_path//": "//prefix//name//" = "//integer_text(code)// &
                    " is no code the test knows (add it to known_codes from its Fortran constant)")
         if (k == 0) cycle
         found(k) = found(k) + 1
         call check(ctx, codes(k)%code == code, header_path//": "//prefix//name//" = "//integer_text(code)// &
                    ", the Fortran code is "//integer_text(codes(k)%code))
      end do
      do k = 1, size(codes)
         if (codes(k)%c_name == "") cycle
         call check(ctx, found(k) == 1, header_path//" declares "//prefix//trim(codes(k)%c_name)//" once (found "// &
                    integer_text(found(k))//")")
      end do
   end subroutine c_header_every_enumerator

   !> The header's list of the methods systems take ("Methods: HILLSTAB_METHOD_AUTO, _MAGNUS4,
   !> ... or _GSL;") names exactly the method table's rows that say `systems`, in order.
   subroutine c_header_system_methods(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=:), allocatable :: text, listed, expected
      integer :: at, finish, k
      text = file_text(ctx, header_path)
      at = index(text, "Methods: HILLSTAB_METHOD_")
      call check(ctx, at > 0, header_path//" lists the methods of systems ('Methods: HILLSTAB_METHOD_...')")
      if (at == 0) return
      at = at + len("Methods: ")
      finish = at + index(text(at:), ";") - 2
      listed = text(at:finish)
      ! the comment's line breaks as single blanks
      do
         k = index(listed, " * ")
         if (k == 0) exit
         listed = listed(:k)//listed(k + 3:)
      end do
      do
         k = index(listed, "  ")
         if (k == 0) exit
         listed = listed(:k)//listed(k + 2:)
      end do
      expected = ""
      do k = lbound(method_table, 1), ubound(method_table, 1)
         if (.not. method_takes_systems(k)) cycle
         if (expected == "") then
            expected = "HILLSTAB_METHOD_"//upper(method_name(k))
         else if (k == last_system_method()) then
            expected = expected//" or _"//upper(method_name(k))
         else
            expected = expected//", _"//upper(method_name(k))
         end if
      end do
      call check(ctx, listed == expected, header_path//": the methods of systems are '"//listed// &
                 "', the method table's are '"//expected//"'")
   contains
      integer function last_system_method() result(last)
         integer :: i
         last = -1
         do i = lbound(method_table, 1), ubound(method_table, 1)
            if (method_takes_systems(i)) last = i
         end do
      end function last_system_method
   end subroutine c_header_system_methods

   !> The lines of a file (empty when it cannot be opened: a failed check).
   function file_lines(ctx, path) result(lines)
      type(test_context_t), intent(inout) :: ctx
      character(len=*), intent(in) :: path
      character(len=1000), allocatable :: lines(:)
      character(len=1000) :: line
      integer :: unit, ios
      integer :: n, k
      open (newunit=unit, file=path, status="old", action="read", iostat=ios)
      call check(ctx, ios == 0, "cannot open "//path//" (run the tests from the worktree root)")
      if (ios /= 0) then
         allocate (lines(0))
         return
      end if
      n = 0
      do
         read (unit, '(a)', iostat=ios) line
         if (ios /= 0) exit
         n = n + 1
      end do
      allocate (lines(n))
      rewind (unit)
      do k = 1, n
         read (unit, '(a)') lines(k)
      end do
      close (unit)
   end function file_lines

   !> The text of a line without its comment (a `#` outside quotes), and the change of the
   !> bracket depth along it.
   subroutine python_code(line, code, depth_change)
      character(len=*), intent(in) :: line
      character(len=:), allocatable, intent(out) :: code
      integer, intent(out) :: depth_change
      character(len=1) :: quote
      integer :: i
      quote = " "
      depth_change = 0
      code = trim(line)
      do i = 1, len_trim(line)
         if (quote /= " ") then
            if (line(i:i) == quote) quote = " "
            cycle
         end if
         select case (line(i:i))
         case ('"', "'"); quote = line(i:i)
         case ("#"); code = line(:i - 1); return
         case ("(", "[", "{"); depth_change = depth_change + 1
         case (")", "]", "}"); depth_change = depth_change - 1
         end select
      end do
   end subroutine python_code

   !> The tokens of a Python literal: strings, integers (a leading minus included), names and
   !> punctuation.
   function python_tokens(text) result(tokens)
      character(len=*), intent(in) :: text
      type(token_t), allocatable :: tokens(:)
      integer :: i, j, ios
      type(token_t) :: t
      allocate (tokens(0))
      i = 1
      do while (i <= len(text))
         if (text(i:i) == " ") then
            i = i + 1
            cycle
         end if
         t = token_t()
         if (text(i:i) == '"' .or. text(i:i) == "'") then
            j = index(text(i + 1:), text(i:i)) + i
            if (j == i) j = len(text) + 1
            t%kind = "s"
            t%text = text(i + 1:j - 1)
            i = j + 1
         else if (verify(text(i:i), "0123456789") == 0 .or. (text(i:i) == "-" .and. &
                  verify(text(min(i + 1, len(text)):min(i + 1, len(text))), "0123456789") == 0 .and. i < len(text))) then
            j = i + 1
            do while (j <= len(text))
               if (verify(text(j:j), "0123456789") /= 0) exit
               j = j + 1
            end do
            t%kind = "i"
            t%text = text(i:j - 1)
            read (t%text, *, iostat=ios) t%value
            if (ios /= 0) t%kind = "n"
            i = j
         else if (verify(text(i:i), "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz_") == 0) then
            j = i + 1
            do while (j <= len(text))
               if (verify(text(j:j), "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz_0123456789.") /= 0) exit
               j = j + 1
            end do
            t%kind = "n"
            t%text = text(i:j - 1)
            i = j
         else
            t%kind = "p"
            t%text = text(i:i)
            i = i + 1
         end if
         tokens = [tokens, t]
      end do
   end function python_tokens

   !> Every code of the Python package against the Fortran tables. A module-level assignment to
   !> upper-case names is read: integers (`ERR_IO = 4`, `NEED_VERDICT, NEED_GROWTH, NEED_TRACE
   !> = 1, 2, 3`) must be known codes with the Fortran value; the dicts METHODS (the method
   !> table), SYSTEM_METHODS (its rows for systems), SAMPLINGS (the sampling table) and
   !> KIND_NAMES (`kind_name`) must hold every entry of their table and nothing else, and
   !> VALUES the value names in the order of their codes; a dict of codes the test does not
   !> know fails. Every known code with a Python name must be there, once.
   subroutine python_codes(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=*), parameter :: tables(5) = [character(len=16) :: "METHODS", "SYSTEM_METHODS", "SAMPLINGS", &
         "KIND_NAMES", "VALUES"]
      type(known_code_t), allocatable :: codes(:)
      character(len=1000), allocatable :: lines(:)
      character(len=:), allocatable :: statement, code_text, lhs, rhs, place
      type(token_t), allocatable :: tokens(:)
      integer, allocatable :: found(:)
      integer :: f, i, depth, change, eq, tables_found(size(tables)), k
      logical :: value_count_seen
      codes = known_codes()
      allocate (found(size(codes)), source=0)
      tables_found = 0
      value_count_seen = .false.
      do f = 1, size(python_paths)
         lines = file_lines(ctx, trim(python_paths(f)))
         i = 0
         do while (i < size(lines))
            i = i + 1
            if (verify(lines(i)(1:1), "ABCDEFGHIJKLMNOPQRSTUVWXYZ") /= 0) cycle
            call python_code(lines(i), statement, depth)
            do while (depth > 0 .and. i < size(lines))
               i = i + 1
               call python_code(lines(i), code_text, change)
               statement = statement//" "//code_text
               depth = depth + change
            end do
            eq = index(statement, "=")
            if (eq == 0) cycle
            if (statement(eq:min(eq + 1, len(statement))) == "==") cycle
            lhs = trim(adjustl(statement(:eq - 1)))
            if (verify(lhs, "ABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_, ") /= 0) cycle
            rhs = trim(adjustl(statement(eq + 1:)))
            place = trim(python_paths(f))//":"//integer_text(i)//": "
            tokens = python_tokens(rhs)
            do k = size(tables), 1, -1
               if (tables(k) == lhs) exit
            end do
            if (k > 0) then
               tables_found(k) = tables_found(k) + 1
               call check_table(lhs, tokens, place)
            else if (lhs == "VALUE_COUNT") then
               value_count_seen = .true.
               call check(ctx, rhs == "len(VALUES)" .or. rhs == integer_text(value_count), place// &
                          "VALUE_COUNT = "//rhs//": len(VALUES) or "//integer_text(value_count))
            else if (all(tokens%kind == "i" .or. (tokens%kind == "p" .and. tokens%text == ","))) then
               call check_integers(lhs, tokens, place)
            else if (any(tokens%kind == "i") .and. size(tokens) > 0) then
               if (tokens(1)%text == "{" .or. tokens(1)%text == "(" .or. tokens(1)%text == "[") then
                  call check(ctx, .false., place//lhs//" holds codes the test does not know (add its Fortran table "// &
                             "to python_codes)")
               end if
            end if
         end do
      end do
      do k = 1, size(tables)
         call check(ctx, tables_found(k) == 1, "python/hillstab defines "//trim(tables(k))//" once (found "// &
                    integer_text(tables_found(k))//")")
      end do
      call check(ctx, value_count_seen, "python/hillstab defines VALUE_COUNT")
      do k = 1, size(codes)
         if (codes(k)%py_name == "") cycle
         call check(ctx, found(k) == 1, "python/hillstab defines "//trim(codes(k)%py_name)//" = "// &
                    integer_text(codes(k)%code)//" once (found "//integer_text(found(k))//")")
      end do
   contains
      !> `A, B = 1, 2`: each name a known code with the Fortran value.
      subroutine check_integers(lhs, tokens, place)
         character(len=*), intent(in) :: lhs, place
         type(token_t), intent(in) :: tokens(:)
         type(token_t), allocatable :: all_names(:), names(:)
         integer :: values(size(tokens)), j, c, n_values, n_names
         all_names = python_tokens(lhs)
         allocate (names(size(all_names)))
         n_names = 0
         do j = 1, size(all_names)
            if (all_names(j)%kind /= "n") cycle
            n_names = n_names + 1
            names(n_names) = all_names(j)
         end do
         names = names(:n_names)
         n_values = 0
         do j = 1, size(tokens)
            if (tokens(j)%kind /= "i") cycle
            n_values = n_values + 1
            values(n_values) = tokens(j)%value
         end do
         call check(ctx, n_names == n_values, place//lhs//": as many values as names")
         do j = 1, min(n_names, n_values)
            c = code_named(codes, py_name=names(j)%text)
            call check(ctx, c > 0, place//trim(names(j)%text)//" = "//integer_text(values(j))// &
                       " is no code the test knows (add it to known_codes from its Fortran constant)")
            if (c == 0) cycle
            found(c) = found(c) + 1
            call check(ctx, values(j) == codes(c)%code, place//trim(names(j)%text)//" = "// &
                       integer_text(values(j))//", the Fortran code is "//integer_text(codes(c)%code))
         end do
      end subroutine check_integers

      !> A dict or tuple of codes against its table.
      subroutine check_table(name, tokens, place)
         character(len=*), intent(in) :: name, place
         type(token_t), intent(in) :: tokens(:)
         character(len=80) :: keys(size(tokens))
         integer :: values(size(tokens)), j, expected, n, n_keys
         n_keys = 0
         call check(ctx, size(tokens) > 0, place//name//" has a value")
         if (size(tokens) == 0) return
         if (name == "VALUES") then
            call check(ctx, tokens(1)%text == "(" .or. tokens(1)%text == "[", place//"VALUES is a tuple")
            do j = 1, size(tokens)
               if (tokens(j)%kind /= "s") cycle
               n_keys = n_keys + 1
               keys(n_keys) = tokens(j)%text
            end do
            call check(ctx, n_keys == value_count, place//"VALUES has "//integer_text(n_keys)// &
                       " names, HILLSTAB_VALUE_COUNT is "//integer_text(value_count))
            do j = 1, min(n_keys, value_count)
               call check(ctx, keys(j) == value_names(j - 1), place//"VALUES["//integer_text(j - 1)//"] is '"// &
                          trim(keys(j))//"', the value of that index is '"//trim(value_names(j - 1))//"'")
            end do
            return
         end if
         call check(ctx, tokens(1)%text == "{", place//name//" is a dict")
         ! the entries "key": code (KIND_NAMES: code: "name")
         do j = 2, size(tokens) - 2
            if (tokens(j + 1)%text /= ":") cycle
            if (name == "KIND_NAMES") then
               call check(ctx, tokens(j)%kind == "i" .and. tokens(j + 2)%kind == "s", place//name// &
                          ": entries code: name")
               n_keys = n_keys + 1
               keys(n_keys) = tokens(j + 2)%text
               values(n_keys) = tokens(j)%value
            else
               call check(ctx, tokens(j)%kind == "s" .and. tokens(j + 2)%kind == "i", place//name// &
                          ": entries name: code")
               n_keys = n_keys + 1
               keys(n_keys) = tokens(j)%text
               values(n_keys) = tokens(j + 2)%value
            end if
         end do
         do j = 1, n_keys
            select case (name)
            case ("METHODS"); expected = method_from_name(trim(keys(j)))
            case ("SYSTEM_METHODS")
               expected = method_from_name(trim(keys(j)))
               if (.not. method_takes_systems(expected)) expected = -1
            case ("SAMPLINGS"); expected = sampling_from_name(trim(keys(j)))
            case default
               expected = -1
               if (kind_name(values(j)) == trim(keys(j))) expected = values(j)
            end select
            call check(ctx, expected == values(j) .and. expected /= -1, place//name//": '"//trim(keys(j))//"' "// &
                       integer_text(values(j))//", the Fortran table's code is "//integer_text(expected))
            call check(ctx, count(values(:n_keys) == values(j)) == 1, place//name//": code "// &
                       integer_text(values(j))//" once")
         end do
         ! every entry of the table there
         select case (name)
         case ("METHODS"); n = size(method_table)
         case ("SYSTEM_METHODS"); n = count(method_table%systems)
         case ("SAMPLINGS"); n = sampling_count
         case default; n = count([(kind_name(j) /= "unknown", j = -5, 40)])
         end select
         call check(ctx, n_keys == n, place//name//" has "//integer_text(n_keys)//" entries, the Fortran "// &
                    "table "//integer_text(n))
      end subroutine check_table
   end subroutine python_codes

   !> The status codes as the header and Python document them, "0 ok, 1 round-off limited,
   !> 2 failed" (`status_name`), in the header's text on batches and in Python's `floquet`.
   subroutine status_codes_documented(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=*), parameter :: paths(2) = [character(len=32) :: header_path, "python/hillstab/floquet.py"]
      character(len=:), allocatable :: text
      integer :: f, k
      do f = 1, size(paths)
         text = file_text(ctx, trim(paths(f)))
         ! the comment's line breaks as single blanks
         do
            k = index(text, " * ")
            if (k == 0) exit
            text = text(:k)//text(k + 3:)
         end do
         do
            k = index(text, "  ")
            if (k == 0) exit
            text = text(:k)//text(k + 2:)
         end do
         ! the header describes each ("1 round-off limited: the best value ..."), Python too
         do k = status_ok, status_failed
            call check(ctx, index(text, integer_text(k)//" "//status_name(k)) > 0, trim(paths(f))// &
                       " documents status "//integer_text(k)//" "//status_name(k))
         end do
         call check(ctx, index(text, "("//integer_text(status_ok)//" "//status_name(status_ok)//", ") > 0 .or. &
                    index(text, ": "//integer_text(status_ok)//" "//status_name(status_ok)//", ") > 0, &
                    trim(paths(f))//" lists the statuses from "//integer_text(status_ok)//" "//status_name(status_ok))
      end do
   end subroutine status_codes_documented

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
         "EXPONENT", "ERROR_ESTIMATE", "KIND", "ARGUMENT", "COUNT"]
      integer, parameter :: codes(value_count + 1) = [value_trace, value_log_abs_trace, value_log10_abs_trace, &
         value_overflow, value_stable, value_stable_paper, value_lambda_max, value_log_modulus_max, &
         value_log_modulus_min, value_exponent, value_error_estimate, value_kind, value_argument, value_count]
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
      ! the files' names: each an enumerator of the same index, and a column of chart and points
      ! files (a key of chart_keys) unless it is one of `no_column_names`
      do k = 0, value_count - 1
         if (value_file_names(k) == "") cycle
         call expect("HILLSTAB_VALUE_"//upper(trim(value_file_names(k))), codes(k + 1))
         if (any(no_column_names == value_file_names(k))) cycle
         call check(ctx, any(chart_keys == value_file_names(k)), &
                    "value "//integer_text(k)//" '"//trim(value_file_names(k))//"' is a column of chart and points files")
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

!> The `&points` group: a file of (α, β) points, one `alpha beta` pair a line, read and
!> checked here. Read by the points and lyapunov tasks.
!>
!>```fortran
!> real(wp), allocatable :: points(:, :)
!> type(error_t), allocatable :: error
!> call read_points_file("s.nml", model_elastic, "data/points/fig4.dat", points, error)
!>```
module hillstab_batch_scene_group_points
   use hillstab_core_kinds, only: wp
   use hillstab_core_error, only: error_t
   use hillstab_core_text, only: integer_text, real_text, lower => lower_case, read_text_line, fpe_state_t, &
      halting_off, halting_restore
   use hillstab_batch_scene_file, only: scene_file_t, fail, shortened, max_line_length, read_len, not_regular_file
   use hillstab_batch_scene_declaration, only: new_group, group_t, group_values_t, group_reader_t, variable, var_path, &
      begin_group, next_item, end_group
   use hillstab_batch_scene_checks, only: check_alpha_domain, max_magnitude, max_points
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use hillstab_hill_model, only: hill_model_t
   implicit none
   private
   public :: points_group, read_points_group, read_points_file

contains

   !> The declaration of `&points`.
   function points_group() result(group)
      type(group_t) :: group
      group = new_group("points", "the points of a file")
      call group%add("file", var_path, "", "required: one 'alpha beta' pair per line, '#' comments, extra columns "// &
         ""// &
         "ignored; relative to the current directory", example="'points.dat'", required=.true.)
   end function points_group

   !> Read `&points` and its file. With `optional`, a file without the group gives no points
   !> (`path` = "") and no error.
   subroutine read_points_group(scene_file, group, model, path, pairs, values, error, optional)
      type(scene_file_t), intent(in) :: scene_file  !! the scene file
      type(group_t), intent(in) :: group      !! the declaration (`points_group`)
      class(hill_model_t), intent(in), optional :: model  !! the model (the domain of α; absent: a system)
      character(len=:), allocatable, intent(out) :: path  !! the points file named
      real(wp), allocatable, intent(out) :: pairs(:, :)  !! (2, n): α, β in file order
      type(group_values_t), intent(out) :: values  !! the effective values
      type(error_t), allocatable, intent(out) :: error  !! err_input naming file, group and variable
      logical, intent(in), optional :: optional  !! the group and its file may be missing
      character(len=read_len) :: file
      namelist /points/ file
      type(group_reader_t) :: reader
      call begin_group(reader, scene_file, group, optional)
      read (reader%defaults, nml=points, iostat=reader%defaults_status, iomsg=reader%defaults_msg)
      if (reader%from_file) read (scene_file%unit, nml=points, iostat=reader%ios, iomsg=reader%msg)
      do while (next_item(reader, scene_file, group))
         read (reader%record, nml=points, iostat=reader%stat, iomsg=reader%message)
      end do
      write (reader%echo, nml=points, delim="apostrophe", iostat=reader%echo_status)
      call end_group(reader, scene_file, group, values, error)
      if (allocated(error)) return
      path = trim(file)
      allocate (pairs(2, 0))
      if (present(optional)) then
         if (optional .and. .not. values%given("file")) return
      end if
      if (len(path) == 0) then
         call fail(error, scene_file%path, group%name, "file", "no points file given")
         return
      end if
      call read_points_file(scene_file%path, model, path, pairs, error)
   end subroutine read_points_group

   !> Read the points file: one `alpha beta` pair per line, `#` starts a comment,
   !> blank lines (spaces and tabs) are skipped, further columns are ignored; a UTF-8
   !> byte-order mark at the start is skipped. A line is parsed as text:
   !> its first two blank-separated fields must be plain numbers (no list-directed
   !> shortcuts such as `/`, `,`, `3*`); at most max_points points, lines of at most
   !> max_line_length characters.
   subroutine read_points_file(source, model, path, points, error)
      character(len=*), intent(in) :: source  !! the scene file (for messages)
      class(hill_model_t), intent(in), optional :: model  !! the model (the domain of α; absent: a system)
      character(len=*), intent(in) :: path    !! the points file
      real(wp), allocatable, intent(out) :: points(:, :)  !! (2, n): α, β in file order
      type(error_t), allocatable, intent(out) :: error  !! err_input naming &points file
      character(len=*), parameter :: group = "points"
      character(len=*), parameter :: utf8_bom = achar(239)//achar(187)//achar(191)
      integer :: unit, ios, line_number, n, hash
      character(len=512) :: msg
      character(len=:), allocatable :: line, where
      real(wp) :: pair(2)
      real(wp), allocatable :: found(:, :)
      logical :: too_long

      if (len(not_regular_file(path)) > 0) then
         call fail(error, source, group, "file", "'"//path//"' "//not_regular_file(path)//", not a points file")
         return
      end if
      open (newunit=unit, file=path, status="old", action="read", iostat=ios, iomsg=msg)
      if (ios /= 0) then
         call fail(error, source, group, "file", "cannot open '"//path//"': "//trim(msg))
         return
      end if
      allocate (found(2, 16))
      n = 0
      line_number = 0
      do
         call read_text_line(unit, line, ios, max_line_length, too_long)
         if (ios /= 0 .and. .not. too_long) exit
         line_number = line_number + 1
         where = "'"//path//"' line "//integer_text(line_number)
         ! a UTF-8 byte-order mark (as some editors save): skipped, as scene files take it
         ! (it was refused, "got ''" with the mark unseen in the message; make fuzz found it)
         if (line_number == 1 .and. index(line, utf8_bom) == 1) line = line(len(utf8_bom) + 1:)
         if (too_long) then
            call fail(error, source, group, "file", where//": longer than "// &
               integer_text(max_line_length)//" characters")
            exit
         end if
         hash = index(line, "#")
         if (hash > 0) line = line(:hash - 1)
         ! blank: spaces, tabs, CRs only (len_trim sees only spaces: a tab-indented comment
         ! was refused as "expected two numbers, got '\x09'"; make fuzz found it)
         if (verify(line, " "//achar(9)//achar(13)) == 0) cycle
         call parse_pair(line, pair, ios)
         if (ios /= 0) then
            call fail(error, source, group, "file", where//": expected two numbers 'alpha beta' "// &
               "(then optional further columns), got '"//shortened(trim(line))//"'")
            exit
         end if
         if (.not. (ieee_is_finite(pair(1)) .and. ieee_is_finite(pair(2)))) then
            call fail(error, source, group, "file", where//": alpha and beta must be finite numbers, got '"// &
               shortened(trim(line))//"'")
            exit
         end if
         if (max(abs(pair(1)), abs(pair(2))) > max_magnitude) then
            call fail(error, source, group, "file", where//": alpha and beta must lie in ["// &
               real_text(-max_magnitude)//", "//real_text(max_magnitude)//"], got '"//shortened(trim(line))//"'")
            exit
         end if
         call check_alpha_domain(source, model, group, "file", pair(1), error, where)
         if (.not. allocated(error)) call check_alpha_domain(source, model, group, "file", pair(1), error, where, &
                                                             beta=pair(2))
         if (allocated(error)) exit
         if (n == max_points) then
            call fail(error, source, group, "file", where//": more than "//integer_text(max_points)// &
               " points (split the file, or use task chart for a grid)")
            exit
         end if
         if (n == size(found, 2)) found = reshape(found, [2, 2*n], pad=[0.0_wp])
         n = n + 1
         found(:, n) = pair
      end do
      close (unit)
      if (allocated(error)) return
      if (n == 0) then
         call fail(error, source, group, "file", "'"//path//"' holds no points")
         return
      end if
      points = found(:, :n)
   end subroutine read_points_file

   !> The first two fields of `line` (separated by blanks or one comma) as numbers; `ios` /= 0
   !> unless both are plain decimal numbers ([sign] digits [. digits] [exponent], or nan/inf).
   subroutine parse_pair(line, pair, ios)
      character(len=*), intent(in) :: line
      real(wp), intent(out) :: pair(2)
      integer, intent(out) :: ios
      integer :: k, first, last
      type(fpe_state_t) :: fpe
      pair = 0.0_wp
      last = 0
      do k = 1, 2
         first = last + 1
         do while (first <= len(line))
            if (.not. is_blank(line(first:first))) exit
            first = first + 1
         end do
         if (k == 2 .and. first <= len(line)) then
            ! one comma may separate the two numbers
            if (line(first:first) == ",") then
               first = first + 1
               do while (first <= len(line))
                  if (.not. is_blank(line(first:first))) exit
                  first = first + 1
               end do
            end if
         end if
         last = first
         do while (last <= len(line))
            if (is_blank(line(last:last)) .or. line(last:last) == ",") exit
            last = last + 1
         end do
         last = last - 1
         if (first > len(line) .or. .not. is_number(line(first:last))) then
            ios = 1
            return
         end if
         call halting_off(fpe)
         read (line(first:last), *, iostat=ios) pair(k)
         call halting_restore(fpe)
         if (ios /= 0) return
      end do
   end subroutine parse_pair

   elemental logical function is_blank(c)
      character, intent(in) :: c
      is_blank = c == " " .or. c == achar(9) .or. c == achar(13)
   end function is_blank

   !> Whether `text` is one plain number: [sign] digits [. [digits]] or . digits, then an
   !> optional exponent [eEdD] [sign] digits; or [sign] nan / inf / infinity.
   pure logical function is_number(text)
      character(len=*), intent(in) :: text
      integer :: i, n_digits
      character(len=:), allocatable :: low
      is_number = .false.
      if (len(text) == 0) return
      i = 1
      if (index("+-", text(1:1)) > 0) i = 2
      low = lower(text(i:))
      if (low == "nan" .or. low == "inf" .or. low == "infinity") then
         is_number = .true.
         return
      end if
      n_digits = 0
      do while (i <= len(text))
         if (.not. is_digit(text(i:i))) exit
         i = i + 1; n_digits = n_digits + 1
      end do
      if (i <= len(text)) then
         if (text(i:i) == ".") then
            i = i + 1
            do while (i <= len(text))
               if (.not. is_digit(text(i:i))) exit
               i = i + 1; n_digits = n_digits + 1
            end do
         end if
      end if
      if (n_digits == 0) return
      if (i <= len(text)) then
         if (index("eEdD", text(i:i)) == 0) return
         i = i + 1
         if (i <= len(text)) then
            if (index("+-", text(i:i)) > 0) i = i + 1
         end if
         n_digits = 0
         do while (i <= len(text))
            if (.not. is_digit(text(i:i))) exit
            i = i + 1; n_digits = n_digits + 1
         end do
         if (n_digits == 0) return
      end if
      is_number = i > len(text)
   end function is_number

   elemental logical function is_digit(c)
      character, intent(in) :: c
      is_digit = c >= "0" .and. c <= "9"
   end function is_digit
end module hillstab_batch_scene_group_points

!> The scene file as the namelist reader sees it: a scratch copy of its first bytes
!> (`open_scene_file`), a pre-scanner that finds a group and cuts its items
!> (`locate_group`, `group_items`: `#` header lines and `!` comments allowed, quotes
!> respected), and the diagnosis of a failed namelist read (`check_read`) that names the
!> file, the group and the variable. It reads no values itself: each group's reader
!> (hillstab_batch_scene_declaration) reads them with Fortran's namelist statement.
!>
!>```fortran
!> type(scene_file_t) :: file
!> type(error_t), allocatable :: error
!> call open_scene_file("data/scenes/fig4a.nml", file, error)
!> if (.not. allocated(error)) print *, group_sets(file%unit, "series", "alpha")
!> call close_scene_file(file)
!>```
module hillstab_batch_scene_file
   use hillstab_core_kinds, only: int64
   use hillstab_core_error, only: error_t, set_error, err_input
   use hillstab_core_text, only: integer_text, lower => lower_case, read_text_line
   use hillstab_ffi_libc, only: is_directory, is_special_file
   use, intrinsic :: iso_fortran_env, only: iostat_end
   implicit none
   private
   public :: scene_file_t, item_t, open_scene_file, close_scene_file
   public :: locate_group, group_present, group_sets, group_items, check_read, fail, shortened, joined, item_name
   public :: group_count, group_names, string_across_lines, long_item, repeated_item, item_subscripted
   public :: check_group_as_written, not_regular_file
   public :: max_line_length, max_scene_bytes, text_len, read_len

   !> Longest line of a scene or points file.
   integer, parameter :: max_line_length = 65536
   !> Bytes of a scene file read: its groups must lie within them (an output file given
   !> as scene has them in its header).
   integer(int64), parameter :: max_scene_bytes = 1048576
   !> Length of the character variables read from a namelist (paths included).
   integer, parameter :: text_len = 4096
   !> Length of the character variables a namelist is read into: longer than the longest
   !> value accepted (text_len between its quotes), so that a longer value, which the
   !> namelist read cuts here, is refused by `check_item_values` (from the text as
   !> written) with a message instead of being used cut. Every group's values are written
   !> back through the namelist at this length (the effective scene): 64 KiB here made
   !> reading a scene cost 12 million instructions, 4 KiB a sixteenth of that.
   integer, parameter :: read_len = text_len + 8

   !> One `name = value(s)` item of a namelist group, cut out of the file text.
   type :: item_t
      character(len=:), allocatable :: name  !! variable name, lower case, without subscript
      character(len=:), allocatable :: text  !! the whole item as written
   end type item_t

   !> A scene file open for the group readers.
   type :: scene_file_t
      character(len=:), allocatable :: path  !! the file named by the user
      integer :: unit = -1                   !! the scratch copy, a formatted unit
   end type scene_file_t

contains

   !> Copy the scene file (at most its first max_scene_bytes, lines of at most
   !> max_line_length characters, a final newline added when missing) to a scratch file:
   !> the namelist reads then never run endlessly (`hillstab /dev/zero`) and an output
   !> file given as scene is read only as far as its header.
   subroutine open_scene_file(path, file, error)
      character(len=*), intent(in) :: path  !! the scene file
      type(scene_file_t), intent(out) :: file  !! the copy, rewound
      type(error_t), allocatable, intent(out) :: error  !! err_input naming the file
      integer :: source, ios, line_number, unit
      integer(int64) :: bytes
      character(len=512) :: msg
      character(len=:), allocatable :: line
      logical :: too_long
      file%path = path
      if (is_directory(path)) then
         call set_error(error, err_input, path//": cannot read the scene file: it is a directory")
         return
      end if
      if (is_special_file(path)) then
         call set_error(error, err_input, path//": cannot read the scene file: it is not a regular file "// &
            "(a FIFO, device or socket); give a file")
         return
      end if
      open (newunit=source, file=path, status="old", action="read", form="formatted", iostat=ios, iomsg=msg)
      if (ios /= 0) then
         call set_error(error, err_input, path//": cannot open the scene file: "//trim(msg))
         return
      end if
      open (newunit=unit, status="scratch", action="readwrite", form="formatted", iostat=ios, iomsg=msg)
      if (ios /= 0) then
         close (source)
         call set_error(error, err_input, path//": cannot make a scratch copy of the scene file: "//trim(msg))
         return
      end if
      bytes = 0
      line_number = 0
      do
         call read_text_line(source, line, ios, max_line_length, too_long)
         if (too_long) then
            call set_error(error, err_input, path//": line "//integer_text(line_number + 1)//" is longer than "// &
               integer_text(max_line_length)//" characters (not a scene file?)")
            exit
         end if
         if (ios /= 0 .and. len(line) == 0) exit
         line_number = line_number + 1
         bytes = bytes + len(line) + 1
         if (bytes > max_scene_bytes) exit  ! the groups must lie in the first max_scene_bytes
         write (unit, '(a)', iostat=ios, iomsg=msg) line
         if (ios /= 0) then
            call set_error(error, err_input, path//": cannot make a scratch copy of the scene file: "//trim(msg))
            exit
         end if
      end do
      close (source)
      if (allocated(error)) then
         close (unit)
         return
      end if
      rewind (unit)
      file%unit = unit
   end subroutine open_scene_file

   !> Why a data file named in a scene (points, samples, a matrix) is not read, found
   !> before it is opened: "is a directory", "is not a regular file (a FIFO, device or
   !> socket)" (open() of a FIFO waits for a writer); "" for a regular file or a path that
   !> does not exist (open() then says why).
   function not_regular_file(path) result(text)
      character(len=*), intent(in) :: path  !! the data file
      character(len=:), allocatable :: text
      text = ""
      if (is_directory(path)) then
         text = "is a directory"
      else if (is_special_file(path)) then
         text = "is not a regular file (a FIFO, device or socket)"
      end if
   end function not_regular_file

   !> Close the scratch copy.
   subroutine close_scene_file(file)
      type(scene_file_t), intent(inout) :: file  !! the open scene file
      if (file%unit >= 0) close (file%unit)
      file%unit = -1
   end subroutine close_scene_file

   !> Turn the status of a namelist read into an error naming file, group and variable.
   subroutine check_read(unit, path, group, names, kinds, ios, msg, bad, error)
      integer, intent(in) :: unit               !! the scene file
      character(len=*), intent(in) :: path, group  !! the scene file
      character(len=*), intent(in) :: names(:)  !! variables of the group
      character(len=*), intent(in) :: kinds(:)  !! what each variable holds, for the message
      integer, intent(in) :: ios                !! iostat of the group read
      character(len=*), intent(in) :: msg       !! iomsg of the group read
      character(len=:), allocatable, intent(in) :: bad  !! the first item that fails alone, if any
      type(error_t), allocatable, intent(out) :: error  !! err_input naming file, group and variable; unallocated when fine
      integer :: k, eq
      character(len=:), allocatable :: name, body, next
      logical :: found, closed
      if (ios == 0) then
         call check_item_values(unit, path, group, error)
         return
      end if
      call locate_group(unit, group, found, body, closed, next)
      ! a closed group on the file's last line without a newline: gfortran has read every
      ! value up to the '/' and then meets the end of the file
      if (ios == iostat_end .and. found .and. closed) return
      if (found .and. .not. closed) then
         if (len(next) > 0) then
            call fail(error, path, group, open_item_name(body), "the group is not closed: no '/' before '&"// &
               next//"'"//open_quote_note(body))
         else
            call fail(error, path, group, open_item_name(body), "the group is not closed: no '/' before the end "// &
               "of the file"//open_quote_note(body))
         end if
         return
      end if
      if (ios == iostat_end) then
         call set_error(error, err_input, path//": &"//group//": the group is missing (no '&"//group// &
            " ... /' in the file)")
         return
      end if
      if (allocated(bad)) then
         if (len(bad) > 0) then
            eq = index(bad, "=")
            name = item_name(bad)
            do k = 1, size(names)
               if (name == trim(names(k))) then
                  call fail(error, path, group, name, "cannot read "//trim(adjustl(bad(eq + 1:)))// &
                     " as "//trim(kinds(k)))
                  return
               end if
            end do
            call fail(error, path, group, name, "unknown variable (the group has: "//joined(names)//")")
            return
         end if
      end if
      ! no single item fails alone: name the variable the run-time message names, else the
      ! group's first item
      name = ""
      do k = 1, size(names)
         if (index(" "//lower(msg)//" ", " "//trim(names(k))//" ") > 0) then
            name = trim(names(k))
            exit
         end if
      end do
      if (len(name) == 0 .and. allocated(bad)) then
         if (len(bad) > 0) name = item_name(bad)
      end if
      if (len(name) == 0) then
         name = first_word(body)
         if (len(name) == 0) name = "(syntax)"
      end if
      call fail(error, path, group, name, "cannot read the group here: "//trim(msg))
   end subroutine check_read

   !> The name of the item in which a group body leaves a string open (else its last item,
   !> else "(syntax)").
   function open_item_name(body) result(name)
      character(len=*), intent(in) :: body
      character(len=:), allocatable :: name
      character :: quote
      integer :: i, opened, eq, j
      quote = " "
      opened = 0
      do i = 1, len(body)
         if (quote == " " .and. (body(i:i) == "'" .or. body(i:i) == '"')) opened = i
         call track_quote(body(i:i), quote)
      end do
      if (quote == " ") opened = len(body) + 1
      ! the last '=' before the open quote (or the end), and the name before it
      eq = index(body(:opened - 1), "=", back=.true.)
      name = "(syntax)"
      if (eq <= 1) return
      j = eq - 1
      do while (j >= 1)
         if (body(j:j) /= " ") exit
         j = j - 1
      end do
      i = j
      do while (i > 1)
         if (.not. is_name_char(body(i - 1:i - 1))) exit
         i = i - 1
      end do
      if (j >= i .and. j >= 1) name = lower(body(i:j))
   end function open_item_name

   !> ", a string is not terminated" when the body leaves a quote open, else "".
   function open_quote_note(body) result(note)
      character(len=*), intent(in) :: body
      character(len=:), allocatable :: note
      character :: quote
      integer :: i
      quote = " "
      do i = 1, len(body)
         call track_quote(body(i:i), quote)
      end do
      note = ""
      if (quote /= " ") note = " (a string is not terminated)"
   end function open_quote_note

   !> The first name in a group body (letters, digits, underscores), lower case.
   pure function first_word(body) result(word)
      character(len=*), intent(in) :: body
      character(len=:), allocatable :: word
      integer :: i, j
      word = ""
      do i = 1, len(body)
         if (is_letter(body(i:i))) exit
      end do
      if (i > len(body)) return
      j = i
      do while (j < len(body))
         if (.not. is_name_char(body(j + 1:j + 1))) exit
         j = j + 1
      end do
      word = lower(body(i:j))
   end function first_word

   !> After a group read that succeeded: refuse an item without a value (`beta_max = -,`
   !> reads as "keep the default"). A value longer than the strings read (4096 characters)
   !> was refused before the read (`long_item`).
   subroutine check_item_values(unit, path, group, error)
      integer, intent(in) :: unit
      character(len=*), intent(in) :: path, group
      type(error_t), allocatable, intent(out) :: error
      type(item_t), allocatable :: items(:)
      character(len=:), allocatable :: value
      integer :: k, eq
      call group_items(unit, group, items)
      do k = 1, size(items)
         eq = index(items(k)%text, "=")
         value = item_value(items(k)%text(eq + 1:))
         if (value == "" .or. value == "+" .or. value == "-") then
            call fail(error, path, group, items(k)%name, "no value after '=' (got '"// &
               trim(adjustl(items(k)%text(eq + 1:)))//"')")
            return
         end if
      end do
   end subroutine check_item_values

   !> The name of the first item of `&group` whose value, as written, is longer than the
   !> strings a group is read into (`text_len` between quotes); "" when there is none. The
   !> readers ask before the namelist read, which would cut such a value with a runtime
   !> warning of its own on stderr, and refuse it.
   function long_item(unit, group) result(name)
      integer, intent(in) :: unit  !! the scratch copy of the scene file
      character(len=*), intent(in) :: group  !! the namelist group
      character(len=:), allocatable :: name
      type(item_t), allocatable :: items(:)
      integer :: k, eq
      name = ""
      call group_items(unit, group, items)
      do k = 1, size(items)
         eq = index(items(k)%text, "=")
         ! (the text as written is a bound on the value: closing commas may follow it)
         if (len_trim(adjustl(items(k)%text(eq + 1:))) <= text_len + 2) cycle
         if (len(item_value(items(k)%text(eq + 1:))) > text_len + 2) then
            name = items(k)%name
            return
         end if
      end do
   end function long_item

   !> An item's value as written after its '=': blanks and closing commas removed.
   pure function item_value(text) result(value)
      character(len=*), intent(in) :: text  !! what follows the '='
      character(len=:), allocatable :: value
      value = trim(adjustl(text))
      do while (len(value) > 0)
         if (value(len(value):) /= ",") exit
         value = trim(value(:len(value) - 1))
      end do
   end function item_value

   !> Find the first `&group` of the file (at the start of a line or after a blank, so
   !> `# &group` in output headers counts; `!` comments removed) and its body up to the
   !> closing `/` outside quotes. A group is not closed when another `&name` comes
   !> before its `/` (`next` is then that name) or when the file ends first (`next` = "").
   subroutine locate_group(unit, group, found, body, closed, next)
      integer, intent(in) :: unit  !! the scratch copy of the scene file
      character(len=*), intent(in) :: group  !! the namelist group
      logical, intent(out) :: found    !! the file has `&group`
      character(len=:), allocatable, intent(out) :: body  !! text between the name and the `/`
      logical, intent(out) :: closed   !! a `/` ends the group
      character(len=:), allocatable, intent(out) :: next  !! the group met before any `/`
      character(len=:), allocatable :: text, line
      integer :: ios, i, j, start
      character :: quote
      found = .false.
      closed = .false.
      body = ""
      next = ""
      text = ""
      rewind (unit)
      do
         call read_text_line(unit, line, ios)
         if (ios /= 0) exit
         ! in an output file the scene ends where the columns are named: the data that
         ! follow (raw bytes in a binary file) are no scene text
         if (index(line, "# columns:") == 1) exit
         text = text//strip_comment(line)//" "
      end do
      start = 0
      do i = 1, len(text) - len(group) - 1
         if (text(i:i) /= "&") cycle
         if (i > 1) then
            if (text(i - 1:i - 1) /= " ") cycle
         end if
         if (lower(text(i + 1:i + len(group))) /= lower(group)) cycle
         if (index(" /,", text(i + len(group) + 1:i + len(group) + 1)) == 0) cycle
         start = i + len(group) + 1
         exit
      end do
      if (start == 0) return
      found = .true.
      quote = " "
      body = text(start:)
      do i = 1, len(body)
         call track_quote(body(i:i), quote)
         if (quote /= " ") cycle
         if (body(i:i) == "/") then
            body = body(:i - 1)
            closed = .true.
            return
         end if
         if (body(i:i) == "&" .and. i > 1 .and. i < len(body)) then
            if (body(i - 1:i - 1) == " " .and. is_letter(body(i + 1:i + 1))) then
               j = i + 1
               do while (j < len(body))
                  if (.not. is_name_char(body(j + 1:j + 1))) exit
                  j = j + 1
               end do
               next = lower(body(i + 1:j))
               closed = next == "end"  ! '&end' closes a group in old-style namelists
               body = body(:i - 1)
               return
            end if
         end if
      end do
   end subroutine locate_group

   !> Whether the file has a `&group`.
   logical function group_present(unit, group)
      integer, intent(in) :: unit  !! the scratch copy of the scene file
      character(len=*), intent(in) :: group  !! the namelist group
      character(len=:), allocatable :: body, next
      logical :: closed
      call locate_group(unit, group, group_present, body, closed, next)
   end function group_present

   !> Whether the first `&group` of the file gives a value to `variable`.
   logical function group_sets(unit, group, variable)
      integer, intent(in) :: unit  !! the scratch copy of the scene file
      character(len=*), intent(in) :: group, variable  !! the namelist group
      type(item_t), allocatable :: items(:)
      integer :: k
      call group_items(unit, group, items)
      group_sets = .false.
      do k = 1, size(items)
         if (items(k)%name == variable) group_sets = .true.
      end do
   end function group_sets

   !> The items of the first `&group ... /` in the file, cut at each `name =`
   !> (outside quotes; `!` comments removed).
   subroutine group_items(unit, group, items)
      integer, intent(in) :: unit  !! the scratch copy of the scene file
      character(len=*), intent(in) :: group  !! the namelist group
      type(item_t), allocatable, intent(out) :: items(:)  !! the items of the group, in file order
      character(len=:), allocatable :: body, next
      integer :: i, j, k, n, last
      integer, allocatable :: starts(:)
      logical :: after_separator, found, closed
      character :: quote
      allocate (items(0))
      call locate_group(unit, group, found, body, closed, next)
      if (.not. found) return
      ! item starts: an identifier (optionally subscripted) after a blank or comma, then '='
      allocate (starts(0))
      quote = " "
      i = 1
      do while (i <= len(body))
         call track_quote(body(i:i), quote)
         if (quote == " " .and. is_letter(body(i:i))) then
            if (i == 1) then
               after_separator = .true.
            else
               after_separator = index(" ,", body(i - 1:i - 1)) > 0
            end if
            j = i
            do while (j < len(body))
               if (.not. is_name_char(body(j + 1:j + 1))) exit
               j = j + 1
            end do
            if (after_separator) then
               k = j + 1
               if (k <= len(body)) then
                  if (body(k:k) == "(") k = k + max(index(body(k:), ")"), 1)
               end if
               do while (k <= len(body))
                  if (body(k:k) /= " ") exit
                  k = k + 1
               end do
               if (k <= len(body)) then
                  if (body(k:k) == "=") starts = [starts, i]
               end if
            end if
            i = j
         end if
         i = i + 1
      end do
      n = size(starts)
      deallocate (items)
      allocate (items(n))
      do k = 1, n
         if (k < n) then
            last = starts(k + 1) - 1
         else
            last = len(body)
         end if
         items(k)%text = trim(adjustl(body(starts(k):last)))
         if (items(k)%text(len(items(k)%text):) == ",") items(k)%text = items(k)%text(:len(items(k)%text) - 1)
         items(k)%name = item_name(items(k)%text)
      end do
   end subroutine group_items

   !> The scene text as one string, lines joined by `separator`, up to the `# columns:`
   !> line of an output file, `!` comments removed.
   function scene_text(unit, separator) result(text)
      integer, intent(in) :: unit
      character, intent(in) :: separator
      character(len=:), allocatable :: text, line, code
      integer :: ios
      text = ""
      rewind (unit)
      do
         call read_text_line(unit, line, ios)
         if (ios /= 0) exit
         if (index(line, "# columns:") == 1) exit
         ! (a function result in a concatenation onto the same variable is miscopied by
         ! gfortran 12: the piece goes through a variable of its own)
         code = strip_comment(line)
         text = text//code//separator
      end do
   end function scene_text

   !> Positions just after each `&group` of `text` (lines joined by new lines) that opens
   !> a line, after blanks or an output header's `#`, or that follows the closing `/` of
   !> another group on its line: the groups a namelist read sees (not a `&series` named in
   !> a header's prose).
   function group_starts(text, group) result(starts)
      character(len=*), intent(in) :: text, group
      integer, allocatable :: starts(:)
      integer :: i, line_start, last
      character(len=:), allocatable :: before
      allocate (starts(0))
      do i = 1, len(text) - len(group) - 1
         if (text(i:i) /= "&") cycle
         line_start = index(text(:i), achar(10), back=.true.) + 1
         before = text(line_start:i - 1)
         if (verify(before, " #") /= 0) then
            ! after a group's closing '/' (outside quotes) on the same line
            last = len_trim(before)
            if (last == len(before) .or. before(last:last) /= "/") cycle
            if (string_open(before)) cycle
         end if
         if (lower(text(i + 1:i + len(group))) /= lower(group)) cycle
         if (index(" /,"//achar(10), text(i + len(group) + 1:i + len(group) + 1)) == 0) cycle
         starts = [starts, i + len(group) + 1]
      end do
   end function group_starts

   !> The position just after the first `&group` of `text` (lines joined by new lines)
   !> that follows a blank or a line break, as `locate_group` finds it; 0 when none.
   function first_group_start(text, group) result(start)
      character(len=*), intent(in) :: text, group
      integer :: start
      integer :: i
      start = 0
      do i = 1, len(text) - len(group) - 1
         if (text(i:i) /= "&") cycle
         if (i > 1) then
            if (index(" "//achar(10), text(i - 1:i - 1)) == 0) cycle
         end if
         if (lower(text(i + 1:i + len(group))) /= lower(group)) cycle
         if (index(" /,"//achar(10), text(i + len(group) + 1:i + len(group) + 1)) == 0) cycle
         start = i + len(group) + 1
         return
      end do
   end function first_group_start

   !> Whether a text leaves a quoted string open at its end.
   pure logical function string_open(text)
      character(len=*), intent(in) :: text
      character :: quote
      integer :: i
      quote = " "
      do i = 1, len(text)
         call track_quote(text(i:i), quote)
      end do
      string_open = quote /= " "
   end function string_open

   !> How many times `&group` opens in the file (a second one would be ignored by the
   !> namelist read).
   integer function group_count(unit, group)
      integer, intent(in) :: unit  !! the scratch copy of the scene file
      character(len=*), intent(in) :: group  !! the namelist group
      character(len=:), allocatable :: text
      text = scene_text(unit, achar(10))
      group_count = size(group_starts(text, group))
   end function group_count

   !> The groups the file opens, each once, in the order of their first `&name` (at the
   !> start of a line, after blanks or an output header's `#`, as `group_count` counts them;
   !> not the `&end` of old-style namelists), lower case.
   function group_names(unit) result(names)
      integer, intent(in) :: unit  !! the scratch copy of the scene file
      character(len=63), allocatable :: names(:)
      character(len=:), allocatable :: text
      character(len=63) :: name
      integer :: i, j, line_start
      allocate (names(0))
      text = scene_text(unit, achar(10))
      do i = 1, len(text) - 1
         if (text(i:i) /= "&") cycle
         line_start = index(text(:i), achar(10), back=.true.) + 1
         if (verify(text(line_start:i - 1), " #") /= 0) cycle
         if (.not. is_letter(text(i + 1:i + 1))) cycle
         j = i + 1
         do while (j < len(text))
            if (.not. is_name_char(text(j + 1:j + 1))) exit
            j = j + 1
         end do
         name = lower(text(i + 1:j))
         if (name == "end" .or. any(names == name)) cycle
         names = [character(len=63) :: names, name]
      end do
   end function group_names

   !> The item of the first `&group` whose quoted string runs past the end of its line
   !> ("" when none): the namelist read would join the lines and drop the line break.
   function string_across_lines(unit, group) result(name)
      integer, intent(in) :: unit  !! the scratch copy of the scene file
      character(len=*), intent(in) :: group  !! the namelist group
      character(len=:), allocatable :: name
      character(len=:), allocatable :: text
      integer, allocatable :: starts(:)
      integer :: i, opened, eq, j, first
      character :: quote
      name = ""
      text = scene_text(unit, achar(10))
      ! the group the readers read: the first `&group` after a blank or a line break
      ! (`locate_group`), also when it does not open its line
      starts = group_starts(text, group)
      first = first_group_start(text, group)
      if (first > 0) starts = [first]
      if (size(starts) == 0) return
      quote = " "
      opened = 0
      do i = starts(1), len(text)
         if (quote == " " .and. text(i:i) == "/") return
         if (quote /= " " .and. text(i:i) == achar(10)) then
            ! the variable: the name before the last '=' ahead of the opening quote
            eq = index(text(starts(1):opened), "=", back=.true.) + starts(1) - 1
            j = eq - 1
            do while (j > starts(1))
               if (text(j:j) /= " ") exit
               j = j - 1
            end do
            name = ""
            do while (j >= starts(1))
               if (.not. is_name_char(text(j:j))) exit
               name = text(j:j)//name
               j = j - 1
            end do
            name = lower(name)
            if (len(name) == 0) name = "?"
            return
         end if
         call track_quote(text(i:i), quote)
         if (quote /= " " .and. opened < i .and. (text(i:i) == "'" .or. text(i:i) == '"')) opened = i
      end do
   end function string_across_lines

   !> Refuse what the namelist read (or a model group's reader) would take otherwise than
   !> written: a second `&group` (ignored), a quoted string across a line break (the break
   !> read as a blank), a variable given twice (the last value kept). Every group of a
   !> scene, declared or a model's, goes through here.
   subroutine check_group_as_written(unit, path, group, error)
      integer, intent(in) :: unit  !! the scratch copy of the scene file
      character(len=*), intent(in) :: path, group  !! the scene file and the group
      type(error_t), allocatable, intent(out) :: error  !! err_input naming file, group and variable
      character(len=:), allocatable :: name
      integer :: count
      count = group_count(unit, group)
      if (count > 1) then
         call set_error(error, err_input, path//": &"//group//": the group is given "// &
            integer_text(count)//" times; all but the first would be ignored: give it once")
         return
      end if
      name = string_across_lines(unit, group)
      if (len(name) > 0) then
         call fail(error, path, group, name, "a quoted string runs on to the next line (the "// &
            "line break would be dropped): keep it on one line")
         return
      end if
      name = repeated_item(unit, group)
      if (len(name) > 0) call fail(error, path, group, name, "given twice in the group (the namelist would "// &
         "keep the last value): give it once")
   end subroutine check_group_as_written

   !> The first variable the first `&group` gives twice ("" when none): the namelist read
   !> would keep the last value in silence. Two items name the same variable when their
   !> names agree and either has no subscript (the whole variable) or their subscripts are
   !> written alike (blanks and case aside): `a(1) = 1, a(2) = 2` sets two elements and
   !> passes, `a = 1, a = 2` and `a = 1, 2, a(2) = 5` do not. A list that runs on over
   !> several lines (`mass = 1, 0,` then `0, 1`) is one item.
   function repeated_item(unit, group) result(name)
      integer, intent(in) :: unit  !! the scratch copy of the scene file
      character(len=*), intent(in) :: group  !! the namelist group
      character(len=:), allocatable :: name
      type(item_t), allocatable :: items(:)
      integer :: i, j
      name = ""
      call group_items(unit, group, items)
      do j = 2, size(items)
         do i = 1, j - 1
            if (items(i)%name /= items(j)%name) cycle
            if (item_subscripted(items(i)%text) .and. item_subscripted(items(j)%text)) then
               if (designator(items(i)%text) /= designator(items(j)%text)) cycle
            end if
            name = items(j)%name
            return
         end do
      end do
   end function repeated_item

   !> Whether an item `name(sub) = value` gives a subscript (one element or a section).
   pure logical function item_subscripted(item)
      character(len=*), intent(in) :: item  !! an item as `group_items` cuts it
      character(len=:), allocatable :: rest
      rest = adjustl(item(len(item_name(item)) + 1:))
      item_subscripted = .false.
      if (len(rest) > 0) item_subscripted = rest(1:1) == "("
   end function item_subscripted

   !> The designator of an item (its text before the first '=' outside quotes: name and
   !> subscript), lower case, blanks removed.
   pure function designator(item) result(text)
      character(len=*), intent(in) :: item
      character(len=:), allocatable :: text
      integer :: i, eq
      eq = index(item, "=")
      if (eq == 0) eq = len(item) + 1
      text = ""
      do i = 1, eq - 1
         if (item(i:i) /= " ") text = text//item(i:i)
      end do
      text = lower(text)
   end function designator

   !> Keep track of whether position i is inside a quoted string.
   pure subroutine track_quote(c, quote)
      character, intent(in) :: c
      character, intent(inout) :: quote  !! the open quote character, or blank outside strings
      if (quote == " ") then
         if (c == "'" .or. c == '"') quote = c
      else if (c == quote) then
         quote = " "  ! a doubled quote closes and reopens: same state after two characters
      end if
   end subroutine track_quote

   !> A line without its `!` comment (outside quotes).
   pure function strip_comment(line) result(code)
      character(len=*), intent(in) :: line
      character(len=:), allocatable :: code
      character :: quote
      integer :: i
      quote = " "
      code = line
      do i = 1, len(line)
         call track_quote(line(i:i), quote)
         if (quote == " " .and. line(i:i) == "!") then
            code = line(:i - 1)
            return
         end if
      end do
   end function strip_comment

   elemental logical function is_letter(c)
      character, intent(in) :: c
      is_letter = (c >= "a" .and. c <= "z") .or. (c >= "A" .and. c <= "Z")
   end function is_letter

   elemental logical function is_name_char(c)
      character, intent(in) :: c
      is_name_char = is_letter(c) .or. (c >= "0" .and. c <= "9") .or. c == "_"
   end function is_name_char

   !> The variable name of an item `name(sub) = value`, lower case.
   pure function item_name(item) result(name)
      character(len=*), intent(in) :: item  !! an item `name(sub) = value`
      character(len=:), allocatable :: name
      integer :: j
      j = 1
      do while (j < len(item))
         if (.not. is_name_char(item(j + 1:j + 1))) exit
         j = j + 1
      end do
      name = trim(lower(item(:j)))
   end function item_name

   !> Names joined by ", ".
   pure function joined(names) result(text)
      character(len=*), intent(in) :: names(:)  !! the names (trailing blanks dropped)
      character(len=:), allocatable :: text
      integer :: k
      text = trim(names(1))
      do k = 2, size(names)
         text = text//", "//trim(names(k))
      end do
   end function joined

   !> The error for a bad value: "file: &group: variable: message".
   pure subroutine fail(error, path, group, variable, message)
      type(error_t), allocatable, intent(out) :: error  !! err_input naming file, group and variable; unallocated when fine
      character(len=*), intent(in) :: path, group, variable, message  !! the scene file
      call set_error(error, err_input, path//": &"//group//": "//variable//": "//message)
   end subroutine fail

   !> At most 80 characters of `text` for a message (then "...").
   pure function shortened(text) result(short)
      character(len=*), intent(in) :: text  !! the text
      character(len=:), allocatable :: short
      if (len(text) <= 80) then
         short = text
      else
         short = text(:77)//"..."
      end if
   end function shortened
end module hillstab_batch_scene_file

!> Scene variables declared once. A namelist group is a `group_t`: its name, a line of
!> help and its variables (`variable_t`: name, kind, default, help, example), in the order
!> of the group's `namelist` statement. From this declaration come the reader's list of
!> names and kinds (and so its messages: "unknown variable (the group has: ...)", "cannot
!> read 'x' as a real number"), the defaults, the effective scene written into every
!> output header (`group_values_t%line`) and the templates of `hillstab --template`.
!>
!> Fortran needs the `namelist` statement itself; each group reader keeps it, with its
!> local variables, and follows this protocol, which passes no procedure around:
!>
!>```fortran
!> call begin_group(reader, file, group)
!> read (reader%defaults, nml=chart, iostat=reader%defaults_status, iomsg=reader%defaults_msg)
!> if (reader%from_file) read (file%unit, nml=chart, iostat=reader%ios, iomsg=reader%msg)
!> do while (next_item(reader, file, group))
!>    read (reader%record, nml=chart, iostat=reader%stat, iomsg=reader%message)
!> end do
!> write (reader%echo, nml=chart, delim="apostrophe", iostat=reader%echo_status)
!> call end_group(reader, file, group, values, error)
!>```
!>
!> The defaults are read through the namelist itself (`reader%defaults` is the group
!> written from its declaration), and the values come back the same way: the namelist
!> `write` into `reader%echo` is parsed by `end_group`, which checks that it names the
!> declared variables in the declared order, so a namelist statement that drifts from
!> its declaration is an error at the first read (every group is read by the tests).
!> An optional group the file lacks (`begin_group(..., optional=.true.)`) is not read from
!> the file (`reader%from_file` false): its values are the defaults.
module hillstab_batch_scene_declaration
   use hillstab_core_kinds, only: wp
   use hillstab_core_error, only: error_t, set_error, err_input
   use hillstab_core_text, only: real_text, quoted, integer_text, lower_case, fpe_state_t, halting_off, &
      halting_restore
   use hillstab_batch_scene_file, only: scene_file_t, item_t, group_items, group_present, check_read, fail, read_len, &
      long_item, text_len, &
      check_group_as_written
   implicit none
   private
   public :: variable_t, group_t, value_t, group_values_t, group_reader_t
   public :: var_real, var_integer, var_logical, var_name, var_path, var_words, var_real_list
   public :: new_group, variable, begin_group, next_item, end_group, unset_real, kind_text, real_list, values_of, list_value

   integer, parameter :: var_real = 1       !! a real number
   integer, parameter :: var_integer = 2    !! an integer
   integer, parameter :: var_logical = 3    !! .true. or .false.
   integer, parameter :: var_name = 4       !! a quoted keyword (task, method, ...), case-insensitive
   integer, parameter :: var_path = 5       !! a quoted path
   integer, parameter :: var_words = 6      !! quoted blank-separated names
   integer, parameter :: var_real_list = 7  !! a list of real numbers

   !> The unset elements of a list: a value no one types.
   real(wp), parameter :: unset_real = -huge(1.0_wp)

   !> One variable of a namelist group.
   type :: variable_t
      character(len=:), allocatable :: name     !! as in the namelist statement, lower case
      integer :: kind = var_real                !! var_* constant
      !> the default as a scene writes it ("9.8", "'auto'", ".false.", "4.0, 6.0"); "" when
      !> the variable has none (optional, or required)
      character(len=:), allocatable :: default
      character(len=:), allocatable :: help     !! one line: meaning, unit, range
      !> a value to show in templates when there is no default ("" for none)
      character(len=:), allocatable :: example
      integer :: max_count = 1                  !! var_real_list: the most values
      !> the scene must give it (a template shows it with its example, not commented out)
      logical :: required = .false.
   end type variable_t

   !> A namelist group and its variables, in the order of its namelist statement.
   type :: group_t
      character(len=:), allocatable :: name     !! the group name, lower case
      character(len=:), allocatable :: help     !! what the group describes (templates)
      type(variable_t), allocatable :: variables(:)  !! the variables
   contains
      !> a copy with another default for one variable
      procedure :: with_default => group_with_default
      !> the index of a variable, 0 when not declared
      procedure :: index_of => group_index_of
      !> declare the next variable (in the order of the namelist statement)
      procedure :: add => group_add
   end type group_t

   !> The effective value of one variable after a read.
   type :: value_t
      character(len=:), allocatable :: name  !! the variable
      integer :: kind = var_real             !! var_* constant
      logical :: given = .false.             !! the scene file sets it
      logical :: written = .true.            !! part of the effective scene
      !> the value as a scene writes it (real_text, quoted, .true.); "" when unset
      character(len=:), allocatable :: text
   end type value_t

   !> The effective values of one group.
   type :: group_values_t
      character(len=:), allocatable :: group   !! the group name
      logical :: present = .false.             !! the scene file has the group
      type(value_t), allocatable :: values(:)  !! in the declared order
   contains
      !> the group as one namelist line: `&group a = 1.0, b = 'x' /`
      procedure :: line => values_line
      !> whether the scene file sets a variable
      procedure :: given => values_given
      !> replace the effective text of a variable (a normalised or derived value)
      procedure :: set => values_set
      !> leave a variable out of the effective scene
      procedure :: hide => values_hide
      !> the effective text of a variable ("" when unset or not declared)
      procedure :: text => values_text
   end type group_values_t

   !> State of one group read (see the module header).
   type :: group_reader_t
      character(len=:), allocatable :: defaults    !! the group with its declared defaults, as namelist text
      integer :: defaults_status = 0               !! iostat of reading the defaults
      character(len=512) :: defaults_msg = ""      !! iomsg of reading the defaults
      logical :: from_file = .true.                !! the group is read from the file
      integer :: ios = 0                           !! iostat of the group read
      character(len=512) :: msg = ""               !! iomsg of the group read
      character(len=:), allocatable :: echo        !! the values written back by the namelist
      integer :: echo_status = 0                   !! iostat of that write
      type(item_t), allocatable :: items(:)        !! the items of the group (after a failed read)
      integer :: k = 0                             !! the item being tried
      integer :: stat = 0                          !! iostat of the item read
      character(len=:), allocatable :: record      !! `&group item /` for the item read
      character(len=512) :: message = ""           !! iomsg of the item read (unused)
      character(len=:), allocatable :: bad         !! the first item that fails alone
      type(fpe_state_t) :: fpe                     !! halting modes to restore
      !> an item whose value is longer than a string is read (not read: see `long_item`)
      character(len=:), allocatable :: too_long
   end type group_reader_t

contains

   !> A declared variable (`default` "" = none; `example` shows a value in templates).
   pure function variable(name, kind, default, help, example, max_count, required) result(v)
      character(len=*), intent(in) :: name     !! the name, lower case
      integer, intent(in) :: kind              !! var_* constant
      character(len=*), intent(in) :: default  !! the default as written in a scene, or ""
      character(len=*), intent(in) :: help     !! one line for templates
      character(len=*), intent(in), optional :: example  !! a value for templates when there is no default
      integer, intent(in), optional :: max_count  !! var_real_list: the most values (default 64)
      logical, intent(in), optional :: required   !! the scene must give it (default .false.)
      type(variable_t) :: v
      v%name = name
      v%kind = kind
      v%default = default
      v%help = help
      v%example = ""
      if (present(example)) v%example = example
      v%max_count = 1
      if (kind == var_real_list) v%max_count = 64
      if (present(max_count)) v%max_count = max_count
      if (present(required)) v%required = required
   end function variable

   !> A group with no variables yet (`add` declares them; an array constructor of variables
   !> would leak their strings in gfortran 12).
   function new_group(name, help) result(group)
      character(len=*), intent(in) :: name  !! the group name, lower case
      character(len=*), intent(in) :: help  !! what the group describes (templates)
      type(group_t) :: group
      group%name = name
      group%help = help
      allocate (group%variables(0))
   end function new_group

   !> Declare the next variable of the group (`variable` gives the meaning of the arguments).
   subroutine group_add(self, name, kind, default, help, example, max_count, required)
      class(group_t), intent(inout) :: self     !! the group
      character(len=*), intent(in) :: name     !! the name, lower case
      integer, intent(in) :: kind              !! var_* constant
      character(len=*), intent(in) :: default  !! the default as written in a scene, or ""
      character(len=*), intent(in) :: help     !! one line for templates
      character(len=*), intent(in), optional :: example  !! a value for templates when there is no default
      integer, intent(in), optional :: max_count  !! var_real_list: the most values (default 64)
      logical, intent(in), optional :: required   !! the scene must give it (default .false.)
      type(variable_t), allocatable :: grown(:)
      integer :: k, n
      n = size(self%variables)
      allocate (grown(n + 1))
      do k = 1, n
         grown(k) = self%variables(k)
      end do
      grown(n + 1) = variable(name, kind, default, help, example, max_count, required)
      call move_alloc(grown, self%variables)
   end subroutine group_add

   !> What a variable holds, for messages ("a real number", "a list of at most 64 real numbers").
   pure function kind_text(v) result(text)
      type(variable_t), intent(in) :: v  !! the variable
      character(len=:), allocatable :: text
      select case (v%kind)
      case (var_real); text = "a real number"
      case (var_integer); text = "an integer"
      case (var_logical); text = ".true. or .false."
      case (var_name); text = "a quoted name"
      case (var_path); text = "a quoted path"
      case (var_words); text = "quoted names"
      case default; text = "a list of at most "//integer_text(v%max_count)//" real numbers"
      end select
   end function kind_text

   !> A copy of the group with `text` as the default of `name`.
   pure function group_with_default(self, name, text) result(copy)
      class(group_t), intent(in) :: self  !! the group
      character(len=*), intent(in) :: name  !! a declared variable
      character(len=*), intent(in) :: text  !! its new default, as written in a scene
      type(group_t) :: copy
      integer :: k
      copy = self
      k = self%index_of(name)
      if (k > 0) copy%variables(k)%default = text
   end function group_with_default

   !> Index of variable `name` in the group (0 when not declared).
   pure integer function group_index_of(self, name) result(k)
      class(group_t), intent(in) :: self  !! the group
      character(len=*), intent(in) :: name  !! a variable name
      do k = 1, size(self%variables)
         if (self%variables(k)%name == name) return
      end do
      k = 0
   end function group_index_of

   !> Start reading `group`: halting off, the file rewound, the defaults written as namelist
   !> text (lists as unset elements: a list given replaces the default whole) and room made
   !> for the values written back.
   subroutine begin_group(reader, file, group, optional)
      type(group_reader_t), intent(out) :: reader  !! the read state
      type(scene_file_t), intent(in) :: file       !! the scene file
      type(group_t), intent(in) :: group           !! the declaration
      logical, intent(in), optional :: optional    !! the file may lack the group: then the defaults
      integer :: k, room
      call halting_off(reader%fpe)
      if (present(optional)) then
         if (optional) reader%from_file = group_present(file%unit, group%name)
      end if
      rewind (file%unit)
      reader%defaults = "&"//group%name
      room = 32 + len(group%name)
      do k = 1, size(group%variables)
         associate (v => group%variables(k))
            reader%defaults = reader%defaults//" "//v%name//" = "//default_literal(v)//","
            select case (v%kind)
            case (var_name, var_path, var_words)
               room = room + read_len + 2*len(v%name) + 32
            case (var_real_list)
               room = room + 40*v%max_count + len(v%name) + 32
            case default
               room = room + 64 + len(v%name)
            end select
         end associate
      end do
      reader%defaults = reader%defaults//" /"
      allocate (character(len=room) :: reader%echo)
      ! a value longer than the strings it would be read into is refused before the read
      ! (the namelist read would cut it with a runtime warning on stderr)
      reader%too_long = ""
      if (reader%from_file) then
         reader%too_long = long_item(file%unit, group%name)
         if (len(reader%too_long) > 0) reader%from_file = .false.
         rewind (file%unit)   ! the group is read from the start of the file
      end if
   end subroutine begin_group

   !> The default of a variable as namelist input: the declared one, else a neutral value
   !> (the variable is then unset unless the file gives it); lists start unset.
   function default_literal(v) result(text)
      type(variable_t), intent(in) :: v
      character(len=:), allocatable :: text
      if (v%kind == var_real_list) then
         text = integer_text(v%max_count)//"*"//real_text(unset_real)
      else if (len(v%default) > 0) then
         text = v%default
      else
         select case (v%kind)
         case (var_real); text = "0.0"
         case (var_integer); text = "0"
         case (var_logical); text = ".false."
         case default; text = "''"
         end select
      end if
   end function default_literal

   !> After a failed group read (`reader%ios` > 0): set `reader%record` to the next item
   !> alone and return true, until an item fails alone (`reader%stat` /= 0) or none is left.
   logical function next_item(reader, file, group)
      type(group_reader_t), intent(inout) :: reader  !! the read state
      type(scene_file_t), intent(in) :: file         !! the scene file
      type(group_t), intent(in) :: group             !! the declaration
      next_item = .false.
      if (reader%ios <= 0) return
      if (.not. allocated(reader%items)) then
         call group_items(file%unit, group%name, reader%items)
         reader%bad = ""
      else if (reader%stat /= 0) then
         reader%bad = reader%items(reader%k)%text
         return
      end if
      reader%k = reader%k + 1
      if (reader%k > size(reader%items)) return
      reader%record = "&"//group%name//" "//reader%items(reader%k)%text//" /"
      reader%stat = 0
      next_item = .true.
   end function next_item

   !> End a group read: the outcome checked (an error naming the file, the group and the
   !> variable), then the values written back by the namelist parsed into `values`.
   subroutine end_group(reader, file, group, values, error)
      type(group_reader_t), intent(inout) :: reader  !! the read state
      type(scene_file_t), intent(in) :: file         !! the scene file
      type(group_t), intent(in) :: group             !! the declaration
      type(group_values_t), intent(out) :: values    !! the effective values
      !> err_input naming file, group and variable; unallocated on success
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: names(:), kinds(:)
      type(item_t), allocatable :: items(:)
      integer :: k, j, n
      n = size(group%variables)
      allocate (character(len=maxval([(len(group%variables(k)%name), k=1, n)])) :: names(n))
      allocate (character(len=48) :: kinds(n))
      do k = 1, n
         names(k) = group%variables(k)%name
         kinds(k) = kind_text(group%variables(k))
      end do
      if (allocated(reader%too_long)) then
         if (len(reader%too_long) > 0) then
            call halting_restore(reader%fpe)
            call fail(error, file%path, group%name, reader%too_long, "value longer than "//integer_text(text_len)// &
               " characters")
            return
         end if
      end if
      if (reader%defaults_status /= 0) then
         call halting_restore(reader%fpe)
         call set_error(error, err_input, file%path//": &"//group%name//": the declared defaults do not read "// &
            "as the group's namelist ("//trim(reader%defaults_msg)//"): the declaration and the namelist statement differ")
         return
      end if
      call check_read(file%unit, file%path, group%name, names, kinds, reader%ios, reader%msg, reader%bad, error)
      if (allocated(error)) then
         call halting_restore(reader%fpe)
         return
      end if
      values%group = group%name
      values%present = group_present(file%unit, group%name)
      call group_items(file%unit, group%name, items)
      call check_written_as_read(error)
      if (allocated(error)) then
         call halting_restore(reader%fpe)
         return
      end if
      allocate (values%values(n))
      do k = 1, n
         values%values(k)%name = group%variables(k)%name
         values%values(k)%kind = group%variables(k)%kind
         do j = 1, size(items)
            if (items(j)%name == group%variables(k)%name) values%values(k)%given = .true.
         end do
      end do
      ! the texts are parsed with halting still off (a value may be nan or 1e400 before
      ! the group's checks refuse it)
      call parse_echo(reader, file, group, values, error)
      call halting_restore(reader%fpe)
   contains
      !> What the namelist read would take otherwise than written: a second `&group`
      !> (ignored), a quoted string across a line break (the break dropped), a variable
      !> given twice (the last value kept), an unquoted value of a text variable
      !> (`output = 12` read as the text 12).
      subroutine check_written_as_read(error)
         type(error_t), allocatable, intent(out) :: error
         character(len=:), allocatable :: value
         integer :: i, v
         call check_group_as_written(file%unit, file%path, group%name, error)
         if (allocated(error)) return
         do i = 1, size(items)
            v = group%index_of(items(i)%name)
            if (v == 0) cycle
            select case (group%variables(v)%kind)
            case (var_name, var_path, var_words)
               value = adjustl(items(i)%text(index(items(i)%text, "=") + 1:))
               if (len_trim(value) == 0) cycle
               if (value(1:1) /= "'" .and. value(1:1) /= '"') then
                  call fail(error, file%path, group%name, items(i)%name, "must be quoted, e.g. "// &
                     items(i)%name//" = '"//trim(value)//"' (got "//trim(value)//")")
                  return
               end if
            end select
         end do
      end subroutine check_written_as_read
   end subroutine end_group

   !> The values the namelist wrote back, one per declared variable in the declared order,
   !> turned into the effective scene's texts; a list with gaps is an error naming it.
   subroutine parse_echo(reader, file, group, values, error)
      type(group_reader_t), intent(in) :: reader
      type(scene_file_t), intent(in) :: file
      type(group_t), intent(in) :: group
      type(group_values_t), intent(inout) :: values
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: text, name, value
      integer :: pos, k
      if (reader%echo_status /= 0) then
         call set_error(error, err_input, file%path//": &"//group%name//": the values cannot be written back "// &
            "through the namelist (internal)")
         return
      end if
      text = trim(reader%echo)
      ! "&GROUP  NAME=value,  NAME=value, ... /"
      pos = index(text, " ")
      do k = 1, size(group%variables)
         call next_assignment(text, pos, name, value)
         if (lower_case(name) /= group%variables(k)%name) then
            call set_error(error, err_input, file%path//": &"//group%name//": the namelist statement lists '"// &
               lower_case(name)//"' where the declaration has '"//group%variables(k)%name// &
               "' (internal: keep the two in the same order)")
            return
         end if
         call value_text(group%variables(k), value, values%values(k), error)
         if (allocated(error)) then
            error%message = file%path//": &"//group%name//": "//group%variables(k)%name//": "//error%message
            return
         end if
         if (values%values(k)%kind == var_real_list .and. len(values%values(k)%text) == 0) then
            if (values%values(k)%given) then
               call fail(error, file%path, group%name, group%variables(k)%name, "no value given")
               return
            end if
            values%values(k)%text = normalised_list(group%variables(k)%default)
         end if
         if (.not. values%values(k)%given .and. len(group%variables(k)%default) == 0 .and. &
             group%variables(k)%kind /= var_real_list) values%values(k)%text = ""
      end do
      call next_assignment(text, pos, name, value)
      if (len(name) > 0) then
         call set_error(error, err_input, file%path//": &"//group%name//": the namelist statement lists '"// &
            lower_case(name)//"', which the declaration lacks (internal)")
      end if
   end subroutine parse_echo

   !> The next `NAME=value` of a namelist write from `pos` on (name "" at the closing `/`).
   pure subroutine next_assignment(text, pos, name, value)
      character(len=*), intent(in) :: text
      integer, intent(inout) :: pos
      character(len=:), allocatable, intent(out) :: name, value
      integer :: i, j, last, start, eq
      character :: quote
      name = ""
      value = ""
      i = pos
      do while (i <= len(text))
         if (text(i:i) /= " " .and. text(i:i) /= ",") exit
         i = i + 1
      end do
      if (i > len(text)) return
      if (text(i:i) == "/") return
      start = i
      eq = index(text(start:), "=")
      if (eq == 0) return
      name = trim(text(start:start + eq - 2))
      i = start + eq
      start = i
      quote = " "
      ! the value ends at the first ", NAME=" outside quotes, or at the closing "/"
      do while (i <= len(text))
         if (quote /= " ") then
            ! a string variable is written at its full length (64 KiB of blanks): skip
            ! blank runs 64 characters at a time, then find the next quote character
            do while (i <= len(text))
               last = min(len(text), i + 63)
               if (text(i:last) /= "") then
                  j = index(text(i:last), quote)
                  if (j > 0) exit
               end if
               i = last + 1
            end do
            if (i > len(text)) exit
            i = i + j - 1
            if (i < len(text)) then
               if (text(i + 1:i + 1) == quote) then
                  i = i + 2
                  cycle
               end if
            end if
            quote = " "
         else if (text(i:i) == "'" .or. text(i:i) == '"') then
            quote = text(i:i)
         else if (text(i:i) == "/") then
            exit
         else if (text(i:i) == "," .and. starts_assignment(text, i + 1)) then
            exit
         end if
         i = i + 1
      end do
      value = trim(adjustl(text(start:i - 1)))
      do while (len(value) > 0)
         if (value(len(value):) /= ",") exit
         value = trim(value(:len(value) - 1))
      end do
      pos = i
   end subroutine next_assignment

   !> Whether `NAME=` (a letter, name characters, blanks, '=') starts at or after blanks from i.
   pure logical function starts_assignment(text, i) result(yes)
      character(len=*), intent(in) :: text
      integer, intent(in) :: i
      integer :: j
      yes = .false.
      j = i
      do while (j <= len(text))
         if (text(j:j) /= " ") exit
         j = j + 1
      end do
      if (j > len(text)) return
      if (.not. is_alpha(text(j:j))) return
      do while (j <= len(text))
         if (.not. (is_alpha(text(j:j)) .or. (text(j:j) >= "0" .and. text(j:j) <= "9") .or. text(j:j) == "_")) exit
         j = j + 1
      end do
      if (j > len(text)) return
      yes = text(j:j) == "="
   end function starts_assignment

   elemental logical function is_alpha(c)
      character, intent(in) :: c
      is_alpha = (c >= "a" .and. c <= "z") .or. (c >= "A" .and. c <= "Z")
   end function is_alpha

   !> The effective text of one value written back by the namelist.
   subroutine value_text(v, raw, value, error)
      type(variable_t), intent(in) :: v
      character(len=*), intent(in) :: raw
      type(value_t), intent(inout) :: value
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: x
      integer :: n, ios
      real(wp), allocatable :: list(:)
      select case (v%kind)
      case (var_real)
         read (raw, *, iostat=ios) x
         value%text = real_text(x)
      case (var_integer)
         read (raw, *, iostat=ios) n
         value%text = integer_text(n)
      case (var_logical)
         value%text = merge(".true. ", ".false.", index("Tt", adjustl(raw(1:1))) > 0 .or. adjustl(raw) == ".true.")
         value%text = trim(value%text)
      case (var_name, var_path, var_words)
         value%text = quoted(unquoted(raw))
         if (v%kind == var_name) value%text = lower_case(value%text)
      case default
         list = expanded_list(raw)
         n = count(list /= unset_real)
         if (n > 0) then
            if (any(list(:n) == unset_real) .or. any(list(n + 1:) /= unset_real)) then
               call set_error(error, err_input, "the list has gaps")
               return
            end if
         end if
         value%text = joined_reals(list(:n))
      end select
   end subroutine value_text

   !> A namelist string constant without its quotes (doubled quotes undoubled) and
   !> without the blanks the namelist pads it with.
   pure function unquoted(raw) result(text)
      character(len=*), intent(in) :: raw
      character(len=:), allocatable :: text
      character(len=:), allocatable :: buffer
      character :: quote
      integer :: i, last, n
      text = ""
      if (len(raw) == 0) return
      quote = raw(1:1)
      if (quote /= "'" .and. quote /= '"') then
         text = trim(raw)
         return
      end if
      last = len(raw)
      if (raw(last:last) == quote .and. last > 1) last = last - 1
      last = len_trim(raw(:last))
      allocate (character(len=max(last, 1)) :: buffer)
      n = 0
      i = 2
      do while (i <= last)
         n = n + 1
         buffer(n:n) = raw(i:i)
         if (raw(i:i) == quote .and. i < last) then
            if (raw(i + 1:i + 1) == quote) i = i + 1
         end if
         i = i + 1
      end do
      text = buffer(:n)
   end function unquoted

   !> The reals of a written-back list (`r*value` repeats expanded).
   function expanded_list(raw) result(list)
      character(len=*), intent(in) :: raw
      real(wp), allocatable :: list(:)
      integer :: i, j, star, repeat_count, ios
      character(len=:), allocatable :: item
      real(wp) :: x
      allocate (list(0))
      i = 1
      do while (i <= len(raw))
         j = index(raw(i:), ",")
         if (j == 0) then
            item = trim(adjustl(raw(i:)))
            i = len(raw) + 1
         else
            item = trim(adjustl(raw(i:i + j - 2)))
            i = i + j
         end if
         if (len(item) == 0) cycle
         star = index(item, "*")
         repeat_count = 1
         if (star > 0) then
            read (item(:star - 1), *, iostat=ios) repeat_count
            item = item(star + 1:)
         end if
         read (item, *, iostat=ios) x
         list = [list, spread(x, 1, repeat_count)]
      end do
   end function expanded_list

   !> Reals joined by ", " (each as real_text).
   function joined_reals(list) result(text)
      real(wp), intent(in) :: list(:)
      character(len=:), allocatable :: text
      integer :: k
      text = ""
      do k = 1, size(list)
         if (k > 1) text = text//", "
         text = text//real_text(list(k))
      end do
   end function joined_reals

   !> A declared default list normalised as the effective scene writes lists.
   function normalised_list(default) result(text)
      character(len=*), intent(in) :: default
      character(len=:), allocatable :: text
      text = ""
      if (len(default) > 0) text = joined_reals(expanded_list(default))
   end function normalised_list

   !> The reals of a list's effective text (`values%text(name)`).
   function real_list(text) result(list)
      character(len=*), intent(in) :: text  !! the text, e.g. "4.0, 6.0"
      real(wp), allocatable :: list(:)
      type(fpe_state_t) :: fpe
      call halting_off(fpe)
      list = expanded_list(text)
      call halting_restore(fpe)
   end function real_list

   !> The value of a list variable as read: the elements the file gave (`array`, the
   !> namelist's variable, up to its last set element; nan and inf kept for the checks), or
   !> the declared default when the file does not give it.
   function list_value(values, name, array) result(list)
      type(group_values_t), intent(in) :: values  !! the effective values of the group
      character(len=*), intent(in) :: name        !! the list variable
      real(wp), intent(in) :: array(:)            !! the namelist variable after the read
      real(wp), allocatable :: list(:)
      integer :: n
      if (values%given(name)) then
         do n = size(array), 1, -1
            if (array(n) /= unset_real) exit
         end do
         list = array(:n)
      else
         list = real_list(values%text(name))
      end if
   end function list_value

   !> The values of a group as they would be read from the text of its defaults only (the
   !> effective values of a scene that gives the group empty), for templates and tests.
   function values_of(group) result(values)
      type(group_t), intent(in) :: group  !! the declaration
      type(group_values_t) :: values
      integer :: k
      values%group = group%name
      allocate (values%values(size(group%variables)))
      do k = 1, size(group%variables)
         values%values(k)%name = group%variables(k)%name
         values%values(k)%kind = group%variables(k)%kind
         if (group%variables(k)%kind == var_real_list) then
            values%values(k)%text = normalised_list(group%variables(k)%default)
         else
            values%values(k)%text = group%variables(k)%default
         end if
      end do
   end function values_of

   !> The group as one namelist line, every written value with a text.
   function values_line(self) result(line)
      class(group_values_t), intent(in) :: self  !! the effective values
      character(len=:), allocatable :: line
      integer :: k
      logical :: first
      line = "&"//self%group
      first = .true.
      do k = 1, size(self%values)
         associate (v => self%values(k))
            if (.not. v%written .or. len(v%text) == 0) cycle
            if (.not. first) line = line//","
            line = line//" "//v%name//" = "//v%text
            first = .false.
         end associate
      end do
      line = line//" /"
   end function values_line

   !> Whether the scene file sets variable `name`.
   pure logical function values_given(self, name) result(given)
      class(group_values_t), intent(in) :: self  !! the effective values
      character(len=*), intent(in) :: name       !! a declared variable
      integer :: k
      given = .false.
      do k = 1, size(self%values)
         if (self%values(k)%name == name) given = self%values(k)%given
      end do
   end function values_given

   !> Replace the effective text of `name`.
   pure subroutine values_set(self, name, text)
      class(group_values_t), intent(inout) :: self  !! the effective values
      character(len=*), intent(in) :: name          !! a declared variable
      character(len=*), intent(in) :: text          !! its text as a scene writes it
      integer :: k
      do k = 1, size(self%values)
         if (self%values(k)%name == name) self%values(k)%text = text
      end do
   end subroutine values_set

   !> Leave `name` out of the effective scene (an alternative another group gives).
   pure subroutine values_hide(self, name)
      class(group_values_t), intent(inout) :: self  !! the effective values
      character(len=*), intent(in) :: name          !! a declared variable
      integer :: k
      do k = 1, size(self%values)
         if (self%values(k)%name == name) self%values(k)%written = .false.
      end do
   end subroutine values_hide

   !> The effective text of `name` ("" when unset or not declared).
   pure function values_text(self, name) result(text)
      class(group_values_t), intent(in) :: self  !! the effective values
      character(len=*), intent(in) :: name       !! a declared variable
      character(len=:), allocatable :: text
      integer :: k
      text = ""
      do k = 1, size(self%values)
         if (self%values(k)%name == name) text = self%values(k)%text
      end do
   end function values_text
end module hillstab_batch_scene_declaration

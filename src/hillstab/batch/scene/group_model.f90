!> The scene group of a model that carries data: `&<model name>`, e.g. `&fourier cos = 1, 0.5 /`
!> for `&scene model = 'fourier'`. Its variables are the model's own (hillstab_hill_model
!> `variables`: lists of numbers, one number, or a file of numbers), read here from that
!> declaration alone, so that a new model with data needs no code in the scene reader: the
!> group's items are taken one by one (`group_items`), each number list read as Fortran
!> reads a list (`3*0.0` repeats), handed to the model's `set_values`, and the model then
!> asked whether it is complete (`check_values`). Every message names the file, the group
!> and the variable (a model's messages begin with the variables they concern). The
!> effective values go into every output header; a file's numbers are written there as the
!> list they stand for (`samples = ...`), so that the header repeats the run without the file.
!>
!>```fortran
!> call read_model_group(file, scene, error)   ! after &scene: scene%model is known
!>```
module hillstab_batch_scene_group_model
   use hillstab_core_kinds, only: wp
   use hillstab_core_error, only: error_t
   use hillstab_core_text, only: real_text, integer_text, quoted, read_text_line, fpe_state_t, halting_off, &
      halting_restore
   use hillstab_hill_model, only: model_variable_t, model_variable_real, model_variable_list, model_variable_file, &
      model_variable_text
   use hillstab_hill_model_base, only: model_base_t
   use hillstab_batch_scene_file, only: scene_file_t, item_t, group_items, group_present, fail, shortened, &
      max_line_length, check_group_as_written, item_subscripted, not_regular_file
   use hillstab_batch_scene_declaration, only: group_values_t, var_real, var_real_list, var_path, var_words
   use hillstab_batch_scene_types, only: scene_t
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   implicit none
   private
   public :: read_model_group, model_group_name

contains

   !> The name of the model's scene group ("" for a model without variables).
   function model_group_name(scene) result(name)
      type(scene_t), intent(in) :: scene  !! a scene whose `&scene` is read
      character(len=:), allocatable :: name
      name = ""
      if (allocated(scene%system)) then
         name = scene%system%name()
      else if (size(scene%model%variables()) > 0) then
         name = scene%model%name()
      end if
   end function model_group_name

   !> Read the model's group (when the model has variables), set the model's data and the
   !> effective values `scene%model_values`; err_input naming file, group and variable.
   subroutine read_model_group(file, scene, error)
      type(scene_file_t), intent(in) :: file  !! the scene file
      type(scene_t), intent(inout) :: scene   !! its model set from the group
      type(error_t), allocatable, intent(out) :: error  !! what is wrong, named
      integer, allocatable :: widths(:)
      integer :: v, n
      if (allocated(scene%system)) then
         call read_data_group(file, scene%system, scene%model_group, scene%model_values, widths, error)
         if (allocated(error)) return
         ! a matrix file holds its matrix row by row: n numbers a row
         n = scene%system%dof()
         do v = 1, size(widths)
            if (widths(v) == 0 .or. widths(v) == n) cycle
            call fail(error, file%path, scene%model_values%group, scene%model_values%values(v)%name, "the file "// &
               "has rows of "//integer_text(widths(v))//" numbers, and n = "//integer_text(n)//" needs rows of "// &
               integer_text(n)//" (a matrix file holds the rows of its n x n matrices, one row a line)")
            return
         end do
      else
         call read_data_group(file, scene%model, scene%model_group, scene%model_values, widths, error)
      end if
   end subroutine read_model_group

   !> The group of any model object (a scalar model or a system) from its variables.
   subroutine read_data_group(file, model, model_group, model_values, widths, error)
      type(scene_file_t), intent(in) :: file  !! the scene file
      class(model_base_t), intent(inout) :: model  !! set from the group
      logical, intent(out) :: model_group   !! the model has variables (and so a group)
      type(group_values_t), intent(inout) :: model_values  !! the effective values
      !> per variable, the numbers a row of the file of rows it was given as (0: not a file)
      integer, allocatable, intent(out) :: widths(:)
      type(error_t), allocatable, intent(out) :: error  !! what is wrong, named
      type(model_variable_t), allocatable :: variables(:)
      type(item_t), allocatable :: items(:)
      type(error_t), allocatable :: cause
      character(len=:), allocatable :: group, value, known
      real(wp), allocatable :: numbers(:)
      integer :: k, v, eq
      variables = model%variables()
      allocate (widths(size(variables)))
      widths = 0
      model_group = size(variables) > 0
      if (.not. model_group) return
      group = model%name()
      ! the effective values start at the declared defaults
      model_values%group = group
      model_values%present = group_present(file%unit, group)
      if (model_values%present) then
         call check_group_as_written(file%unit, file%path, group, error)
         if (allocated(error)) return
      end if
      allocate (model_values%values(size(variables)))
      known = ""
      do v = 1, size(variables)
         if (v > 1) known = known//", "
         known = known//trim(variables(v)%name)
         ! component by component: gfortran leaks the trimmed texts given to a structure constructor
         model_values%values(v)%name = trim(variables(v)%name)
         model_values%values(v)%kind = value_kind(variables(v)%kind)
         model_values%values(v)%given = .false.
         model_values%values(v)%written = .true.
         model_values%values(v)%text = trim(variables(v)%default)
      end do
      call group_items(file%unit, group, items)
      do k = 1, size(items)
         v = variable_index(variables, items(k)%name)
         if (v == 0) then
            call fail(error, file%path, group, items(k)%name, "unknown variable (the group has: "//known//")")
            return
         end if
         if (item_subscripted(items(k)%text)) then
            call fail(error, file%path, group, items(k)%name, "a model's variable is given whole, without a "// &
               "subscript (got '"//shortened(items(k)%text)//"')")
            return
         end if
         eq = index(items(k)%text, "=")
         value = ""
         if (eq > 0) value = trim(adjustl(items(k)%text(eq + 1:)))
         ! a last item's closing '/' and a trailing comma are not part of the value
         if (len(value) > 0) then
            if (value(len(value):) == "/") value = trim(value(:len(value) - 1))
         end if
         if (len(value) > 0) then
            if (value(len(value):) == ",") value = trim(value(:len(value) - 1))
         end if
         if (len(value) == 0) then
            call fail(error, file%path, group, items(k)%name, "no value")
            return
         end if
         select case (variables(v)%kind)
         case (model_variable_text)
            ! a text: quoted, handed to the model as it is (doubled quotes undoubled)
            if (len(value) < 2 .or. (value(1:1) /= "'" .and. value(1:1) /= '"') .or. &
                value(len(value):) /= value(1:1)) then
               call fail(error, file%path, group, items(k)%name, "must be quoted, e.g. "//items(k)%name// &
                  " = '"//shortened(value)//"' (got "//shortened(value)//")")
               return
            end if
            value = undoubled(value(2:len(value) - 1), value(1:1))
            call model%set_text(items(k)%name, value, cause)
            if (allocated(cause)) then
               call fail_from_model(file%path, group, items(k)%name, cause%message, error)
               return
            end if
            model_values%values(v)%given = .true.
            model_values%values(v)%text = quoted(value)
            cycle
         case (model_variable_file)
            call read_numbers_file(file%path, group, items(k)%name, unquoted(value), variables(v)%max_count, &
                                   numbers, error)
         case default
            if ((value(1:1) == "'" .or. value(1:1) == '"') .and. variables(v)%kind == model_variable_list) then
               ! a quoted path in place of the list: the numbers of a file, row by row
               call read_rows_file(file%path, group, items(k)%name, unquoted(value), variables(v)%max_count, &
                                   numbers, widths(v), error)
            else
               call read_number_list(file%path, group, items(k)%name, value, variables(v)%max_count, &
                                     variables(v)%kind == model_variable_real, numbers, error)
            end if
         end select
         if (allocated(error)) return
         call model%set_values(items(k)%name, numbers, cause)
         if (allocated(cause)) then
            call fail_from_model(file%path, group, items(k)%name, cause%message, error)
            return
         end if
         call record(model_values, variables, v, numbers)
      end do
      call model%check_values(cause)
      if (allocated(cause)) call fail_from_model(file%path, group, trim(variables(1)%name), cause%message, error)
   end subroutine read_data_group

   !> The declaration kind of a model variable's effective value.
   pure integer function value_kind(kind)
      integer, intent(in) :: kind  !! model_variable_*
      select case (kind)
      case (model_variable_real); value_kind = var_real
      case (model_variable_file); value_kind = var_path
      case (model_variable_text); value_kind = var_words
      case default; value_kind = var_real_list
      end select
   end function value_kind

   !> The position of `name` among the variables (0: none).
   pure integer function variable_index(variables, name) result(k)
      type(model_variable_t), intent(in) :: variables(:)
      character(len=*), intent(in) :: name
      do k = 1, size(variables)
         if (trim(variables(k)%name) == name) return
      end do
      k = 0
   end function variable_index

   !> The effective value of variable v: its numbers; a file's numbers as the first list
   !> variable (the file itself left out of the header: the numbers repeat the run).
   subroutine record(values, variables, v, numbers)
      type(group_values_t), intent(inout) :: values
      type(model_variable_t), intent(in) :: variables(:)
      integer, intent(in) :: v
      real(wp), intent(in) :: numbers(:)
      integer :: k, target
      character(len=:), allocatable :: text
      text = ""
      do k = 1, size(numbers)
         if (k > 1) text = text//", "
         if (variables(v)%whole .and. abs(numbers(k)) < 1.0e9_wp) then
            text = text//integer_text(nint(numbers(k)))
         else
            text = text//real_text(numbers(k))
         end if
      end do
      target = v
      if (variables(v)%kind == model_variable_file) then
         values%values(v)%given = .true.
         values%values(v)%written = .false.
         do k = 1, size(variables)
            if (variables(k)%kind == model_variable_list) then
               target = k
               exit
            end if
         end do
         if (target == v) return
      end if
      values%values(target)%given = .true.
      values%values(target)%text = text
   end subroutine record

   !> err_input from a model's message "<variables>: <text>": named by those variables
   !> (else by `variable`).
   subroutine fail_from_model(path, group, variable, message, error)
      character(len=*), intent(in) :: path, group, variable, message
      type(error_t), allocatable, intent(out) :: error
      integer :: colon
      colon = index(message, ": ")
      if (colon <= 1) then
         call fail(error, path, group, variable, message)
      else if (verify(message(:colon - 1), "abcdefghijklmnopqrstuvwxyz_0123456789, ") == 0) then
         call fail(error, path, group, message(:colon - 1), message(colon + 2:))
      else
         call fail(error, path, group, variable, message)
      end if
   end subroutine fail_from_model

   !> The numbers of a list value as Fortran reads a list (blanks or commas, `r*x` repeats),
   !> at most `max_count` (one with `single`).
   subroutine read_number_list(path, group, variable, value, max_count, single, numbers, error)
      character(len=*), intent(in) :: path, group, variable, value
      integer, intent(in) :: max_count
      logical, intent(in) :: single
      real(wp), allocatable, intent(out) :: numbers(:)
      type(error_t), allocatable, intent(out) :: error
      real(wp), allocatable :: buffer(:)
      integer :: ios, n
      type(fpe_state_t) :: fpe
      allocate (buffer(max_count + 1))
      buffer = -huge(1.0_wp)
      call halting_off(fpe)
      read (value, *, iostat=ios) buffer
      call halting_restore(fpe)
      if (ios > 0 .or. verify(value, " ,0123456789.+-eEdD*") /= 0 .and. .not. special_words(value)) then
         call fail(error, path, group, variable, "cannot read '"//shortened(value)//"' as "// &
            trim(merge("a number", "numbers ", single)))
         return
      end if
      n = findloc(buffer == -huge(1.0_wp), .true., dim=1) - 1
      if (n < 0) n = size(buffer)
      if (n == 0) then
         call fail(error, path, group, variable, "no value")
      else if (single .and. n > 1) then
         call fail(error, path, group, variable, "one number, got "//integer_text(n))
      else if (n > max_count) then
         call fail(error, path, group, variable, "at most "//integer_text(max_count)//" numbers")
      else
         numbers = buffer(:n)
      end if
   end subroutine read_number_list

   !> The value holds a word a number may be read from: nan, inf, infinity (refused later
   !> as not finite, with the model's message).
   pure logical function special_words(value)
      character(len=*), intent(in) :: value
      character(len=len(value)) :: lower
      integer :: i
      lower = value
      do i = 1, len(lower)
         if (lower(i:i) >= "A" .and. lower(i:i) <= "Z") lower(i:i) = achar(iachar(lower(i:i)) + 32)
      end do
      special_words = index(lower, "nan") > 0 .or. index(lower, "inf") > 0
   end function special_words

   !> The text inside a quoted value, a doubled quote undoubled.
   pure function undoubled(inside, quote) result(text)
      character(len=*), intent(in) :: inside  !! what lies between the quotes
      character, intent(in) :: quote          !! the quote
      character(len=:), allocatable :: text
      integer :: i
      text = ""
      i = 1
      do while (i <= len(inside))
         text = text//inside(i:i)
         if (inside(i:i) == quote .and. i < len(inside)) then
            if (inside(i + 1:i + 1) == quote) i = i + 1
         end if
         i = i + 1
      end do
   end function undoubled

   !> A quoted path without its quotes.
   pure function unquoted(value) result(path)
      character(len=*), intent(in) :: value
      character(len=:), allocatable :: path
      path = value
      if (len(path) >= 2) then
         if ((path(1:1) == "'" .or. path(1:1) == '"') .and. path(len(path):) == path(1:1)) &
            path = path(2:len(path) - 1)
      end if
   end function unquoted

   !> The numbers of a file: one a row, or τ and the number (τ equally spaced); `#` comments,
   !> blank lines skipped; every row of the same length; at most `max_count`.
   subroutine read_numbers_file(source, group, variable, path, max_count, numbers, error)
      character(len=*), intent(in) :: source, group, variable, path
      integer, intent(in) :: max_count
      real(wp), allocatable, intent(out) :: numbers(:)
      type(error_t), allocatable, intent(out) :: error
      integer :: unit, ios, line_number, n, width, row_width, hash
      character(len=512) :: msg
      character(len=:), allocatable :: line, where
      real(wp) :: row(3), tau0, step
      real(wp), allocatable :: taus(:)
      logical :: too_long
      type(fpe_state_t) :: fpe
      if (len(not_regular_file(path)) > 0) then
         call fail(error, source, group, variable, "'"//path//"' "//not_regular_file(path)//", not a file of numbers")
         return
      end if
      open (newunit=unit, file=path, status="old", action="read", iostat=ios, iomsg=msg)
      if (ios /= 0) then
         call fail(error, source, group, variable, "cannot open '"//path//"': "//trim(msg))
         return
      end if
      allocate (numbers(0), taus(0))
      n = 0
      width = 0
      line_number = 0
      call halting_off(fpe)
      do
         call read_text_line(unit, line, ios, max_line_length, too_long)
         if (ios /= 0 .and. .not. too_long) exit
         line_number = line_number + 1
         where = "'"//path//"' line "//integer_text(line_number)
         if (too_long) then
            call fail(error, source, group, variable, where//": longer than "//integer_text(max_line_length)// &
               " characters")
            exit
         end if
         hash = index(line, "#")
         if (hash > 0) line = line(:hash - 1)
         if (verify(line, " "//achar(9)//achar(13)) == 0) cycle
         if (empty_field(line)) then
            call fail(error, source, group, variable, where//": an empty field in '"//shortened(trim(line))// &
               "' (a leading comma or two commas with nothing between): give every number")
            exit
         end if
         row_width = fields(line)
         if (row_width < 1 .or. row_width > 2) then
            call fail(error, source, group, variable, where//": expected one number (a sample) or two (tau and "// &
               "the sample), got '"//shortened(trim(line))//"'")
            exit
         end if
         row = 0.0_wp
         read (line, *, iostat=ios) row(1:row_width)
         if (ios /= 0 .or. verify(line, " ,0123456789.+-eEdD"//achar(9)//achar(13)) /= 0) then
            call fail(error, source, group, variable, where//": cannot read '"//shortened(trim(line))// &
               "' as numbers")
            exit
         end if
         if (width == 0) width = row_width
         if (row_width /= width) then
            call fail(error, source, group, variable, where//": "//integer_text(row_width)//" numbers where "// &
               "the rows before have "//integer_text(width)//" (ragged rows)")
            exit
         end if
         n = n + 1
         if (n > max_count) then
            call fail(error, source, group, variable, "'"//path//"': more than "//integer_text(max_count)// &
               " rows")
            exit
         end if
         numbers = [numbers, row(width)]
         if (width == 2) taus = [taus, row(1)]
      end do
      close (unit)
      call halting_restore(fpe)
      if (allocated(error)) return
      if (width == 2 .and. n >= 2) then
         ! tau equally spaced
         tau0 = taus(1)
         step = taus(2) - taus(1)
         do line_number = 3, n
            if (abs(taus(line_number) - (tau0 + (line_number - 1)*step)) > 1.0e-9_wp*max(1.0_wp, abs(step)*n)) then
               call fail(error, source, group, variable, "'"//path//"': the tau column is not equally spaced "// &
                  "(row "//integer_text(line_number)//": "//real_text(taus(line_number))//", expected "// &
                  real_text(tau0 + (line_number - 1)*step)//")")
               return
            end if
         end do
      end if
   end subroutine read_numbers_file

   !> Every number of a file, row after row (a matrix's rows, `#` comments, blank lines
   !> skipped): a list variable given as a quoted path. Every row holds the same count of
   !> numbers (`row_width`), none left empty; a directory or a FIFO is refused before it
   !> is opened. Errors name the file and its line.
   subroutine read_rows_file(source, group, variable, path, max_count, numbers, row_width, error)
      character(len=*), intent(in) :: source, group, variable, path
      integer, intent(in) :: max_count
      real(wp), allocatable, intent(out) :: numbers(:)
      integer, intent(out) :: row_width  !! the numbers of each row (0: no row read)
      type(error_t), allocatable, intent(out) :: error
      integer :: unit, ios, line_number, width
      character(len=512) :: msg
      character(len=:), allocatable :: line
      real(wp), allocatable :: row(:)
      logical :: too_long
      type(fpe_state_t) :: fpe
      row_width = 0
      if (len(not_regular_file(path)) > 0) then
         call fail(error, source, group, variable, "'"//path//"' "//not_regular_file(path)//", not a matrix file")
         return
      end if
      open (newunit=unit, file=path, status="old", action="read", iostat=ios, iomsg=msg)
      if (ios /= 0) then
         call fail(error, source, group, variable, "cannot open '"//path//"': "//trim(msg))
         return
      end if
      allocate (numbers(0))
      line_number = 0
      call halting_off(fpe)
      do
         call read_text_line(unit, line, ios, max_line_length, too_long)
         if (ios /= 0 .and. .not. too_long) exit
         line_number = line_number + 1
         if (too_long) then
            call fail(error, source, group, variable, "'"//path//"' line "//integer_text(line_number)// &
               ": longer than "//integer_text(max_line_length)//" characters")
            exit
         end if
         if (index(line, "#") > 0) line = line(:index(line, "#") - 1)
         if (verify(line, " "//achar(9)//achar(13)) == 0) cycle
         if (empty_field(line)) then
            call fail(error, source, group, variable, "'"//path//"' line "//integer_text(line_number)// &
               ": an empty field in '"//shortened(trim(line))//"' (a leading comma or two commas with nothing "// &
               "between): give every number")
            exit
         end if
         width = fields(line)
         if (row_width == 0) row_width = width
         if (width /= row_width) then
            call fail(error, source, group, variable, "'"//path//"' line "//integer_text(line_number)//": "// &
               integer_text(width)//trim(merge(" number ", " numbers", width == 1))//" where the rows before have "// &
               integer_text(row_width)// &
               " (ragged rows: every row of a matrix holds n numbers)")
            exit
         end if
         allocate (row(width))
         read (line, *, iostat=ios) row
         if (ios /= 0 .or. verify(line, " ,0123456789.+-eEdD"//achar(9)//achar(13)) /= 0) then
            call fail(error, source, group, variable, "'"//path//"' line "//integer_text(line_number)// &
               ": cannot read '"//shortened(trim(line))//"' as numbers")
            exit
         end if
         if (.not. all(ieee_is_finite(row))) then
            call fail(error, source, group, variable, "'"//path//"' line "//integer_text(line_number)// &
               ": the numbers must be finite")
            exit
         end if
         numbers = [numbers, row]
         deallocate (row)
         if (size(numbers) > max_count) then
            call fail(error, source, group, variable, "'"//path//"': more than "//integer_text(max_count)// &
               " numbers")
            exit
         end if
      end do
      call halting_restore(fpe)
      close (unit)
      if (.not. allocated(error) .and. size(numbers) == 0) &
         call fail(error, source, group, variable, "'"//path//"' holds no numbers")
   end subroutine read_rows_file

   !> Whether a line of numbers leaves a field empty: a comma first, or two commas with
   !> only blanks between (a list-directed read takes such a field as "unchanged").
   pure logical function empty_field(line)
      character(len=*), intent(in) :: line
      integer :: i
      logical :: after_comma, started
      empty_field = .false.
      after_comma = .false.
      started = .false.
      do i = 1, len(line)
         if (index(" "//achar(9)//achar(13), line(i:i)) > 0) cycle
         if (line(i:i) == ",") then
            if (after_comma .or. .not. started) then
               empty_field = .true.
               return
            end if
            after_comma = .true.
         else
            after_comma = .false.
         end if
         started = .true.
      end do
   end function empty_field

   !> The number of blank- or comma-separated fields of a line.
   pure integer function fields(line) result(n)
      character(len=*), intent(in) :: line
      integer :: i
      logical :: in_field
      n = 0
      in_field = .false.
      do i = 1, len(line)
         if (index(" ,"//achar(9)//achar(13), line(i:i)) > 0) then
            in_field = .false.
         else if (.not. in_field) then
            in_field = .true.
            n = n + 1
         end if
      end do
   end function fields
end module hillstab_batch_scene_group_model

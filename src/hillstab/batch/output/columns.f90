!> Output columns declared once. A task describes each column of its file by a
!> `column_t` — name, unit, meaning, text style, the placeholder a failed point gets —
!> and computes a row as an array of values in its table's order. From the table come the
!> `# columns:` line, the header's line per column, `&scene columns` validation
!> (`find_columns`), the text rows (`put_row`) and the binary records (the values
!> themselves), so a column is added in one place: its task's table and value.
!>
!> The row writers allocate nothing (they run inside OpenMP loops, where gfortran 12's
!> deferred-length character results are not thread-safe) and produce the same bytes as
!> `put_es` of hillstab_core_text for every style.
!>
!>```fortran
!> type(column_t) :: table(2)
!> character(len=80) :: line
!> integer :: pos
!> table = [column_t("alpha", "", "a pi^2/rho", style_e17), column_t("stable", "", "1 stable", style_flag)]
!> pos = 0
!> call put_row(table, [1, 2], [1.5_wp, 1.0_wp], line, pos)   ! " 1.5000000000000000e+000 1"
!>```
module hillstab_batch_output_columns
   use hillstab_core_kinds, only: wp
   use hillstab_core_text, only: put_es, put_integer, lower_case
   implicit none
   private
   public :: column_t, style_e17, style_e11, style_e7, style_e4, style_flag, style_integer, style_fortran_e17
   public :: style_width2, style_width4
   public :: columns_text, find_columns, column_lines, put_row, put_value, failed_row, all_columns, column_index

   integer, parameter :: style_e17 = 1      !! 17 significant digits, d.dddde±xxx: reads back to the same double
   integer, parameter :: style_e11 = 2      !! 11 significant digits
   integer, parameter :: style_e7 = 3       !! 7 significant digits
   integer, parameter :: style_e4 = 4       !! 4 significant digits (error estimates)
   !> a flag or status: a small integer (0, 1, 2, -1) or 0.5 (undecided, marginal)
   integer, parameter :: style_flag = 5
   integer, parameter :: style_integer = 6  !! an integer, no blanks
   integer, parameter :: style_fortran_e17 = 7  !! Fortran's es24.16e3 (a right-aligned field of 24)
   integer, parameter :: style_width2 = 8   !! an integer right-aligned in 2 characters
   integer, parameter :: style_width4 = 9   !! an integer right-aligned in 4 characters

   !> One column of an output file.
   type :: column_t
      character(len=:), allocatable :: name     !! as in the `# columns:` line and `&scene columns`
      character(len=:), allocatable :: unit     !! "" when dimensionless, else e.g. "m", "1/s"
      character(len=:), allocatable :: meaning  !! one line for the header
      integer :: style = style_e17              !! style_* constant
      !> the value written at a failed point (a value outside the column's range)
      real(wp) :: placeholder = 0.0_wp
      logical :: keep_on_failure = .false.      !! a failed point keeps its own value (alpha, beta)
   end type column_t

contains

   !> Indices 1 … size(table).
   pure function all_columns(table) result(ids)
      type(column_t), intent(in) :: table(:)  !! the table
      integer, allocatable :: ids(:)
      integer :: k
      ids = [(k, k=1, size(table))]
   end function all_columns

   !> Index of the column `name` (0 when the table has none).
   pure integer function column_index(table, name) result(k)
      type(column_t), intent(in) :: table(:)  !! the table
      character(len=*), intent(in) :: name    !! a column name
      do k = 1, size(table)
         if (table(k)%name == name) return
      end do
      k = 0
   end function column_index

   !> Column names joined by blanks (the `# columns:` line).
   pure function columns_text(table, ids) result(text)
      type(column_t), intent(in) :: table(:)  !! the table
      integer, intent(in) :: ids(:)           !! the columns written, in file order
      character(len=:), allocatable :: text
      integer :: k
      text = ""
      do k = 1, size(ids)
         if (k > 1) text = text//" "
         text = text//table(ids(k))%name
      end do
   end function columns_text

   !> The columns named in `text` (blank- or comma-separated, case-insensitive), in the
   !> order given, each one of `available`, by its name or else its other name in `aliases`
   !> (one per column of the table, "" for none); `bad` names the first that is neither, or
   !> is named twice ("" when all are fine).
   pure subroutine find_columns(table, available, text, ids, bad, aliases)
      type(column_t), intent(in) :: table(:)  !! the table
      integer, intent(in) :: available(:)     !! indices this file offers
      character(len=*), intent(in) :: text    !! the names, as in `&scene columns`
      integer, allocatable, intent(out) :: ids(:)  !! the indices found, in order
      character(len=:), allocatable, intent(out) :: bad  !! the first unknown or repeated name, or ""
      character(len=*), intent(in), optional :: aliases(:)  !! another name of each column ("" none)
      character(len=:), allocatable :: word
      integer :: i, j, k, found
      allocate (ids(0))
      bad = ""
      i = 1
      do while (i <= len(text))
         if (index(" ,", text(i:i)) > 0) then
            i = i + 1
            cycle
         end if
         j = i
         do while (j < len(text))
            if (index(" ,", text(j + 1:j + 1)) > 0) exit
            j = j + 1
         end do
         word = lower_case(text(i:j))
         found = 0
         do k = 1, size(available)
            if (lower_case(table(available(k))%name) == word) found = available(k)
         end do
         if (found == 0 .and. present(aliases)) then
            do k = 1, size(available)
               if (len_trim(aliases(available(k))) > 0 .and. lower_case(trim(aliases(available(k)))) == word) &
                  found = available(k)
            end do
         end if
         if (found == 0 .or. any(ids == found)) then
            bad = text(i:j)
            return
         end if
         ids = [ids, found]
         i = j + 1
      end do
   end subroutine find_columns

   !> One header line per column written: "name [unit]: meaning".
   pure function column_lines(table, ids) result(lines)
      type(column_t), intent(in) :: table(:)  !! the table
      integer, intent(in) :: ids(:)           !! the columns written
      character(len=:), allocatable :: lines(:)
      integer :: k, width
      width = 1
      do k = 1, size(ids)
         width = max(width, len(line_of(table(ids(k)))))
      end do
      allocate (character(len=width) :: lines(size(ids)))
      do k = 1, size(ids)
         lines(k) = line_of(table(ids(k)))
      end do
   contains
      pure function line_of(column) result(line)
         type(column_t), intent(in) :: column
         character(len=:), allocatable :: line
         line = column%name
         if (len(column%unit) > 0) line = line//" ["//column%unit//"]"
         line = line//": "//column%meaning
      end function line_of
   end function column_lines

   !> The values of a failed point: the placeholders, except where the point keeps its own.
   pure subroutine failed_row(table, values)
      type(column_t), intent(in) :: table(:)  !! the table
      real(wp), intent(inout) :: values(:)    !! all the table's values; in: the point's own
      integer :: k
      do k = 1, size(table)
         if (.not. table(k)%keep_on_failure) values(k) = table(k)%placeholder
      end do
   end subroutine failed_row

   !> Append the columns `ids` of a row (`values` in table order), separated by one blank,
   !> to line(pos + 1:); pos is advanced. No allocation.
   pure subroutine put_row(table, ids, values, line, pos)
      type(column_t), intent(in) :: table(:)  !! the table
      integer, intent(in) :: ids(:)           !! the columns written, in file order
      real(wp), intent(in) :: values(:)       !! the row, in table order
      character(len=*), intent(inout) :: line  !! the line being built
      integer, intent(inout) :: pos            !! last position written
      integer :: k
      do k = 1, size(ids)
         if (k > 1) then
            line(pos + 1:pos + 1) = " "
            pos = pos + 1
         end if
         call put_value(table(ids(k))%style, values(ids(k)), line, pos)
      end do
   end subroutine put_row

   !> Append one value in a style.
   pure subroutine put_value(style, x, line, pos)
      integer, intent(in) :: style            !! style_* constant
      real(wp), intent(in) :: x               !! the value (finite)
      character(len=*), intent(inout) :: line  !! the line being built
      integer, intent(inout) :: pos            !! last position written
      character(len=24) :: field
      integer :: n, first
      select case (style)
      case (style_e17)
         call put_es(line, pos, x, 17)
      case (style_e11)
         call put_es(line, pos, x, 11)
      case (style_e7)
         call put_es(line, pos, x, 7)
      case (style_e4)
         call put_es(line, pos, x, 4)
      case (style_flag)
         if (x == 0.5_wp) then
            line(pos + 1:pos + 3) = "0.5"
            pos = pos + 3
         else if (x < 0.0_wp) then
            ! flags are small whole numbers: int(x + 0.5) rounds them without a library call
            line(pos + 1:pos + 2) = "-"//achar(iachar("0") + min(9, int(-x + 0.5_wp)))
            pos = pos + 2
         else
            line(pos + 1:pos + 1) = achar(iachar("0") + min(9, int(x + 0.5_wp)))
            pos = pos + 1
         end if
      case (style_integer)
         call put_integer(line, pos, nint(x))
      case (style_width2, style_width4)
         n = merge(2, 4, style == style_width2)
         first = 0
         call put_integer(field, first, nint(x))
         if (first < n) then
            line(pos + 1:pos + n - first) = repeat(" ", n - first)
            pos = pos + n - first
         end if
         line(pos + 1:pos + first) = field(1:first)
         pos = pos + first
      case default
         write (field, '(es24.16e3)') x
         line(pos + 1:pos + 24) = field
         pos = pos + 24
      end select
   end subroutine put_value
end module hillstab_batch_output_columns

!> Sizes passed from C as `size_t`. Fortran has no unsigned integers: a `size_t` arrives as
!> `integer(c_size_t)`, a signed 64-bit integer, so that the sizes from 2^63 to SIZE_MAX
!> read as negative numbers (SIZE_MAX as −1). Every entry point compares a count through
!> `count_refusal`, which reads the value as C wrote it: a count from 0 to `limit` (INT_MAX
!> by default) is accepted, any other size — INT_MAX + 1, 2^63, SIZE_MAX — is refused with
!> a message naming the argument and its value as C prints it (`%zu`). A buffer's length
!> goes through `buffer_length`: any length is a buffer of that many bytes, SIZE_MAX
!> included (a caller's buffer that large holds any text).
!>
!>```fortran
!> character(len=:), allocatable :: why
!> why = count_refusal("count", count)   ! "" when 0 <= count <= INT_MAX
!> if (len(why) > 0) call set_error(error, err_invalid_parameter, where//": "//why)
!>```
module hillstab_interop_sizes
   use, intrinsic :: iso_c_binding, only: c_size_t
   use, intrinsic :: iso_fortran_env, only: int64
   use hillstab_core_text, only: lower_case
   use hillstab_hill_model_base, only: model_base_t, model_variable_t
   implicit none
   private
   public :: count_refusal, size_text, buffer_length, values_count_refusal, row_extent

contains

   !> "" when the `size_t` value `count` lies in 0 … `limit` (default INT_MAX, the largest
   !> count an entry point takes); else "<name> = <value as C prints it> exceeds the limit
   !> <limit>".
   pure function count_refusal(name, count, limit) result(text)
      character(len=*), intent(in) :: name  !! the argument, as the C prototype names it
      integer(c_size_t), intent(in) :: count  !! its value (from 2^63 up: negative here)
      integer, intent(in), optional :: limit  !! the largest count accepted (default huge(1))
      character(len=:), allocatable :: text
      integer(int64) :: top
      top = int(huge(1), int64)
      if (present(limit)) top = int(limit, int64)
      text = ""
      if (count >= 0_c_size_t .and. int(count, int64) <= top) return
      text = name//" = "//size_text(count)//" exceeds the limit "//integer_decimal(top)
   end function count_refusal

   !> Whether `count` numbers may be read for the variable `name` of a model or system (its
   !> `variables`): `refusal` is "" when the count lies within what the variable takes, else
   !> names `count`, its value and the limit. `known` is false for a name the object does
   !> not have: then no number is read (its `set_values` refuses the name).
   pure subroutine values_count_refusal(object, name, count, known, refusal)
      class(model_base_t), intent(in) :: object  !! the model or system
      character(len=*), intent(in) :: name  !! the variable
      integer(c_size_t), intent(in) :: count  !! the count passed from C
      logical, intent(out) :: known  !! the object has the variable
      character(len=:), allocatable, intent(out) :: refusal  !! "" when the count is accepted
      type(model_variable_t), allocatable :: variables(:)
      integer :: k
      refusal = count_refusal("count", count)
      if (len(refusal) > 0) refusal = refusal//" (the values of '"//name//"')"
      variables = object%variables()
      known = .false.
      do k = 1, size(variables)
         if (lower_case(trim(variables(k)%name)) /= lower_case(trim(name))) cycle
         known = .true.
         if (len(refusal) == 0 .and. count > int(variables(k)%max_count, c_size_t)) &
            refusal = count_refusal("count", count, variables(k)%max_count)//", the most numbers '"//name// &
                      "' takes"
      end do
   end subroutine values_count_refusal

   !> The decimal text of a `size_t` value as C prints it (`%zu`): SIZE_MAX is
   !> "18446744073709551615", never "-1".
   pure function size_text(value) result(text)
      integer(c_size_t), intent(in) :: value  !! the value as Fortran sees it
      character(len=:), allocatable :: text
      integer(int64) :: high, low
      if (value >= 0_c_size_t) then
         text = integer_decimal(int(value, int64))
         return
      end if
      ! value + 2^64 = 10 high + low with 0 <= low < 10: shift right by one bit (2^63 + v/2)
      ! then divide by 5, keeping the parity of the low bit
      high = ishft(int(value, int64), -1)  ! (value + 2^64)/2, in [2^62, 2^63)
      low = 2*mod(high, 5_int64) + iand(int(value, int64), 1_int64)
      high = high/5
      if (low >= 10) then
         high = high + 1
         low = low - 10
      end if
      text = integer_decimal(high)//achar(iachar("0") + int(low))
   end function size_text

   !> The length of a C buffer as a non-negative count of bytes: sizes from 2^63 to SIZE_MAX
   !> (negative here) are read as huge(int64) bytes, more than any text needs.
   elemental function buffer_length(length) result(bytes)
      integer(c_size_t), intent(in) :: length  !! the `size_t` length passed from C
      integer(int64) :: bytes
      if (length < 0_c_size_t) then
         bytes = huge(1_int64)
      else
         bytes = int(length, int64)
      end if
   end function buffer_length

   !> The extent of a row of a C array of `n` entries as a dummy argument declares it, from
   !> 1 to INT_MAX: an `n` beyond INT_MAX (refused by the entry point before the array is
   !> touched) sets no larger extent, whose strides would overflow on entry.
   pure function row_extent(n) result(extent)
      integer(c_size_t), intent(in) :: n  !! the row length passed from C
      integer(c_size_t) :: extent
      extent = max(1_c_size_t, min(n, int(huge(1), c_size_t)))
   end function row_extent

   !> The decimal text of a non-negative integer.
   pure function integer_decimal(value) result(text)
      integer(int64), intent(in) :: value
      character(len=:), allocatable :: text
      character(len=24) :: buffer
      write (buffer, '(i0)') value
      text = trim(buffer)
   end function integer_decimal
end module hillstab_interop_sizes

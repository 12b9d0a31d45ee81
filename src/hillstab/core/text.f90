!> Fast text for reals in scientific notation, for large gnuplot-ready files; and the
!> small text helpers the writers, the tables and the scene reader share: `integer_text`,
!> `lower_case`, `alternatives_text`, `name_position`, `real_text` (the shortest text that
!> reads back to the same double), `quoted` (a namelist string constant), `read_text_line`
!> (one line of any length), and the switch that keeps floating-point traps off while
!> text is turned into numbers (`halting_off`).
!>
!> Fortran's formatted `write` costs about half a microsecond per number, which
!> is more than method auto needs to compute a chart point; this module writes
!> the same `d.ddd…e±xxx` text, correctly rounded, with a few floating-point and
!> integer operations: x times 10^p as a double-double (the table of
!> hillstab_core_powers_of_ten and an error-free product), whose integer part and
!> fraction decide the last digit exactly, except within 1e-9 of a tie (about one
!> number in 10^9 at random) or outside |x| in [1e-274, 1e290], where the text comes from
!> Fortran's own `es` edit descriptor, also correctly rounded. With 17 digits the text
!> reads back to the same double.
!>
!>```fortran
!> print '(a)', format_es(-1266.8019686641_wp, 12)   ! -1.26680196866e+003
!>```
module hillstab_core_text
   use hillstab_core_kinds, only: wp, int64
   use, intrinsic :: iso_fortran_env, only: int32
   use hillstab_core_powers_of_ten, only: power_min, power_max, power_hi, power_lo
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite, ieee_is_nan, ieee_usual, ieee_support_halting, &
      ieee_get_halting_mode, ieee_set_halting_mode, ieee_set_flag
   implicit none
   private
   public :: format_es, es_width, put_es, put_integer, integer_text, lower_case, alternatives_text, name_position
   public :: real_text, quoted, read_text_line, fpe_state_t, halting_off, halting_restore

   !> Decimal text of an integer of the default kind or of kind int64, without blanks.
   interface integer_text
      module procedure integer_text_default, integer_text_int64
   end interface integer_text

   integer(int64), parameter :: ten = 10_int64
   !> Powers of ten 10^0 … 10^8 in 32 bits.
   integer(int32), parameter :: int32_powers(0:8) = [1_int32, 10_int32, 100_int32, 1000_int32, 10000_int32, &
      100000_int32, 1000000_int32, 10000000_int32, 100000000_int32]
   !> "00", "01", … "99": digits are produced two at a time.
   character(len=200), parameter :: digit_pairs = &
      "0001020304050607080910111213141516171819202122232425262728293031323334353637383940414243444546474849"// &
      "5051525354555657585960616263646566676869707172737475767778798081828384858687888990919293949596979899"
   !> Exact integer powers of ten 10^0 … 10^18.
   integer(int64), parameter :: int_powers(0:18) = [1_int64, 10_int64, 100_int64, 1000_int64, &
      10000_int64, 100000_int64, 1000000_int64, 10000000_int64, 100000000_int64, 1000000000_int64, &
      10000000000_int64, 100000000000_int64, 1000000000000_int64, 10000000000000_int64, &
      100000000000000_int64, 1000000000000000_int64, 10000000000000000_int64, 100000000000000000_int64, &
      1000000000000000000_int64]

   !> Floating-point halting modes saved while a read runs with halting off.
   type :: fpe_state_t
      logical :: can_halt = .false.                 !! halting can be controlled here
      logical :: halting(size(ieee_usual)) = .false. !! the modes to restore
   end type fpe_state_t

contains

   !> Width of `format_es(x, digits)`: sign, digits, point, "e±xxx".
   pure integer function es_width(digits)
      integer, intent(in) :: digits  !! significant digits, 1 ... 17
      es_width = digits + 7
   end function es_width

   !> x in scientific notation with `digits` (1 … 17) significant digits and a
   !> three-digit exponent, right-aligned in es_width(digits) characters.
   !> Non-finite values give "nan", "inf" or "-inf" (callers keep them out of files).
   pure function format_es(x, digits) result(text)
      real(wp), intent(in) :: x  !! the value
      integer, intent(in) :: digits  !! significant digits, 1 ... 17
      character(len=digits + 7) :: text
      integer :: pos
      pos = 0
      call put_es(text, pos, x, digits)
   end function format_es

   !> Write format_es(x, digits) into buffer(pos + 1 : pos + digits + 7) and advance pos
   !> (no allocation: this runs once per number of a chart file). Correctly rounded.
   pure subroutine put_es(buffer, pos, x, digits)
      character(len=*), intent(inout) :: buffer  !! the line being built
      integer, intent(inout) :: pos  !! last position written; advanced past the number
      real(wp), intent(in) :: x  !! the value, finite
      integer, intent(in) :: digits  !! significant digits, 1 ... 17
      integer(int64) :: mantissa
      integer :: e, p, last, biased
      logical :: exact
      last = pos + digits + 7
      pos = last
      biased = int(ibits(transfer(x, 0_int64), 52, 11))
      if (biased == 0 .or. biased == 2047) then
         ! zero, subnormal, infinite or NaN
         if (.not. ieee_is_finite(x)) then
            buffer(last - digits - 6:last) = " "
            if (ieee_is_nan(x)) then
               buffer(last - 2:last) = "nan"
            else if (x > 0.0_wp) then
               buffer(last - 2:last) = "inf"
            else
               buffer(last - 3:last) = "-inf"
            end if
         else if (x == 0.0_wp) then
            call put_es_digits(buffer, last, digits, 0_int64, 0, .false.)   ! −0 without a sign, as 0
         else
            call put_es_fortran(buffer, last, x, digits)
         end if
         return
      end if
      ! the decimal exponent from the binary one, floor((biased − 1023) log10 2) in integers
      ! (78913/2^18 for log10 2: exact over the whole exponent range); it is floor(log10|x|)
      ! or one less, corrected by `scaled_digits`
      e = shifta((biased - 1023)*78913, 18)
      p = digits - 1 - e
      exact = p - 1 >= power_min .and. p <= power_max
      if (exact) call scaled_digits(abs(x), digits, p, mantissa, exact)
      if (.not. exact) then
         ! beyond the table, or within 1e-9 of a tie
         call put_es_fortran(buffer, last, x, digits)
         return
      end if
      call put_es_digits(buffer, last, digits, mantissa, digits - 1 - p, x < 0.0_wp)
   end subroutine put_es

   !> The text of ±mantissa·10^(e − digits + 1), mantissa of `digits` digits (or 0), into
   !> buffer(last − digits − 6 : last): [-]d.ddd…e±xxx filled from the right after its first
   !> two characters are blanked (one or two blanks lead the field; a digit or the sign
   !> overwrites the rest). The digit counts of the chart styles (17, 11, 7, 4) are written
   !> out; digits after the point go two at a time, in 32-bit pieces of at most 8 digits
   !> (64-bit division by a constant costs several times more).
   pure subroutine put_es_digits(buffer, last, digits, mantissa, e, negative)
      character(len=*), intent(inout) :: buffer  !! the line being built
      integer, intent(in) :: last     !! the field's last position
      integer, intent(in) :: digits   !! significant digits, 1 ... 17
      integer(int64), intent(in) :: mantissa  !! the digits, 0 ≤ mantissa < 10^digits
      integer, intent(in) :: e        !! the decimal exponent
      logical, intent(in) :: negative !! a minus sign first
      integer(int64) :: high, rest
      integer(int32) :: low, lead
      integer :: p, k, abs_e, n_after
      buffer(last - digits - 6:last - digits - 5) = "  "
      abs_e = abs(e)
      k = 2*mod(abs_e, 100)
      buffer(last - 1:last) = digit_pairs(k + 1:k + 2)
      buffer(last - 2:last - 2) = achar(iachar("0") + abs_e/100)
      if (e < 0) then
         buffer(last - 4:last - 3) = "e-"
      else
         buffer(last - 4:last - 3) = "e+"
      end if
      p = last - 5
      select case (digits)
      case (17)
         high = mantissa/100000000_int64
         call put_eight(buffer, p, int(mantissa - 100000000_int64*high, int32))
         lead = int(high/100000000_int64, int32)
         call put_eight(buffer, p, int(high - 100000000_int64*lead, int32))
      case (11)
         lead = int(mantissa/10000000000_int64, int32)
         rest = mantissa - 10000000000_int64*lead
         low = int(rest/100000000_int64, int32)
         call put_eight(buffer, p, int(rest - 100000000_int64*low, int32))
         buffer(p - 1:p) = digit_pairs(2*low + 1:2*low + 2)
         p = p - 2
      case (7)
         low = int(mantissa, int32)
         lead = low/1000000_int32
         call put_pairs(buffer, p, low - 1000000_int32*lead, 6)
      case (4)
         low = int(mantissa, int32)
         lead = low/1000_int32
         call put_pairs(buffer, p, low - 1000_int32*lead, 3)
      case default
         high = mantissa
         n_after = digits - 1
         if (n_after >= 8) then
            rest = high/100000000_int64
            call put_eight(buffer, p, int(high - 100000000_int64*rest, int32))
            high = rest
            n_after = n_after - 8
         end if
         low = int(high, int32)
         call put_pairs(buffer, p, mod(low, int32_powers(n_after)), n_after)
         lead = low/int32_powers(n_after)
      end select
      if (digits > 1) then
         buffer(p:p) = "."
         p = p - 1
      end if
      buffer(p:p) = achar(iachar("0") + lead)
      if (negative) buffer(p - 1:p - 1) = "-"
   end subroutine put_es_digits

   !> The 8 decimal digits of `value` (with leading zeros) into buffer(p − 7 : p); p moves
   !> left past them. All eight at once in the bytes of one 64-bit word: the two 4-digit
   !> halves in its 32-bit lanes, each split into two 2-digit numbers in 16-bit lanes, each
   !> of those into two digits in bytes (divisions by 100 and 10 as multiplications and
   !> shifts, exact for these ranges: 10486/2^20 for 1/100 below 10^4, 103/2^10 for 1/10
   !> below 100), then ASCII; the first digit is the lowest byte (little-endian order, as
   !> x86-64 and AArch64 Linux store it).
   pure subroutine put_eight(buffer, p, value)
      character(len=*), intent(inout) :: buffer  !! the line being built
      integer, intent(inout) :: p                !! the last position to fill; moved left
      integer(int32), intent(in) :: value        !! 0 ≤ value < 10^8
      integer(int64), parameter :: lanes_32 = int(z'0000007F0000007F', int64)
      integer(int64), parameter :: lanes_16 = int(z'000F000F000F000F', int64)
      integer(int64), parameter :: ascii = int(z'3030303030303030', int64)
      character(len=8), parameter :: mold = ""
      integer(int64) :: x, y
      integer(int32) :: high
      high = value/10000_int32
      x = ior(int(high, int64), shiftl(int(value - 10000_int32*high, int64), 32))
      y = iand(shiftr(x*10486_int64, 20), lanes_32)
      x = ior(y, shiftl(x - 100_int64*y, 16))
      y = iand(shiftr(x*103_int64, 10), lanes_16)
      x = ior(y, shiftl(x - 10_int64*y, 8))
      buffer(p - 7:p) = transfer(x + ascii, mold)
      p = p - 8
   end subroutine put_eight

   !> The `n` (≤ 7) decimal digits of `value` (with leading zeros) into buffer(p − n + 1 : p),
   !> two at a time from the right; p moves left past them.
   pure subroutine put_pairs(buffer, p, value, n)
      character(len=*), intent(inout) :: buffer  !! the line being built
      integer, intent(inout) :: p                !! the last position to fill; moved left
      integer(int32), intent(in) :: value        !! 0 ≤ value < 10^n
      integer, intent(in) :: n                   !! digits, 0 … 7
      integer(int32) :: rest
      integer :: i, k
      rest = value
      do i = 1, n/2
         k = 2*int(mod(rest, 100_int32))
         buffer(p - 1:p) = digit_pairs(k + 1:k + 2)
         rest = rest/100_int32
         p = p - 2
      end do
      if (mod(n, 2) == 1) then
         buffer(p:p) = achar(iachar("0") + int(rest))
         p = p - 1
      end if
   end subroutine put_pairs

   !> The `digits` significant digits of ax > 0, correctly rounded, as an integer
   !> mantissa in [10^(digits−1), 10^digits) with ax ≈ mantissa·10^(−p); p is the
   !> caller's guess, decreased by one when ax·10^p reaches 10^digits (before or after
   !> rounding). `exact` is false when the rounding cannot be decided here: ax·10^p
   !> within 1e-9 of a half-integer, or p out of the table.
   pure subroutine scaled_digits(ax, digits, p, mantissa, exact)
      real(wp), intent(in) :: ax
      integer, intent(in) :: digits
      integer, intent(inout) :: p
      integer(int64), intent(out) :: mantissa
      logical, intent(out) :: exact
      real(wp), parameter :: tie_margin = 1.0e-9_wp
      real(wp) :: product, error, whole, fraction, margin
      integer :: attempt
      exact = .false.
      mantissa = 0
      do attempt = 1, 2
         if (p < power_min .or. p > power_max) return
         if (digits <= 12) then
            ! few digits: the plain product decides unless its fraction lies within the
            ! product's own rounding and the neglected power_lo of a tie or of an integer
            product = ax*power_hi(p)
            whole = aint(product)
            fraction = product - whole
            margin = 4.0_wp*epsilon(1.0_wp)*product + ax*abs(power_lo(p))
            if (abs(fraction - 0.5_wp) <= margin .or. fraction <= margin .or. fraction >= 1.0_wp - margin) then
               call two_product(ax, power_hi(p), product, error)
               whole = aint(product)
               fraction = (product - whole) + (error + ax*power_lo(p))
            end if
         else
            ! ax·10^p = product + error + ax·power_lo(p), to about 2^-104 relative
            call two_product(ax, power_hi(p), product, error)
            whole = aint(product)
            fraction = (product - whole) + (error + ax*power_lo(p))
         end if
         mantissa = int(whole, int64)
         do while (fraction < 0.0_wp)
            mantissa = mantissa - 1
            fraction = fraction + 1.0_wp
         end do
         do while (fraction >= 1.0_wp)
            mantissa = mantissa + 1
            fraction = fraction - 1.0_wp
         end do
         if (mantissa >= int_powers(digits)) then
            p = p - 1   ! the guessed decimal exponent was one too small
            cycle
         end if
         if (abs(fraction - 0.5_wp) < tie_margin) return
         if (fraction > 0.5_wp) mantissa = mantissa + 1
         if (mantissa == int_powers(digits)) then   ! rounding carried: 9.99…5 → 10.0
            mantissa = int_powers(digits - 1)
            p = p - 1
         end if
         exact = .true.
         return
      end do
   end subroutine scaled_digits

   !> product + error = a·b exactly up to the rounding of the smallest partial product
   !> (about 2^-106 relative), by Dekker's splitting; the halves are cut from the bits, so
   !> the result does not depend on whether the compiler fuses multiply-adds.
   pure subroutine two_product(a, b, product, error)
      real(wp), intent(in) :: a, b
      real(wp), intent(out) :: product, error
      integer(int64), parameter :: high_mask = not(2_int64**27 - 1_int64)
      real(wp) :: a_hi, a_lo, b_hi, b_lo
      product = a*b
      a_hi = transfer(iand(transfer(a, 0_int64), high_mask), 1.0_wp)
      b_hi = transfer(iand(transfer(b, 0_int64), high_mask), 1.0_wp)
      a_lo = a - a_hi
      b_lo = b - b_hi
      error = ((a_hi*b_hi - product) + a_hi*b_lo + a_lo*b_hi) + a_lo*b_lo
   end subroutine two_product

   !> Write the decimal digits of n (a '-' first when negative) into buffer(pos + 1 : …) and
   !> advance pos. No allocation: inside an OpenMP loop this replaces `integer_text`, since
   !> gfortran (12) is not thread-safe with deferred-length character function results
   !> (measured: thousands of wrong strings in 2e6 calls on two threads).
   pure subroutine put_integer(buffer, pos, n)
      character(len=*), intent(inout) :: buffer  !! the line being built
      integer, intent(inout) :: pos  !! last position written; advanced past the number
      integer, intent(in) :: n  !! the integer
      character(len=20) :: digits
      integer(int64) :: m
      integer :: k
      m = abs(int(n, int64))
      k = len(digits) + 1
      do
         k = k - 1
         digits(k:k) = achar(iachar("0") + int(mod(m, ten)))
         m = m/ten
         if (m == 0) exit
      end do
      if (n < 0) then
         k = k - 1
         digits(k:k) = "-"
      end if
      buffer(pos + 1:pos + len(digits) - k + 1) = digits(k:)
      pos = pos + len(digits) - k + 1
   end subroutine put_integer

   !> Decimal text of a default integer.
   pure function integer_text_default(n) result(text)
      integer, intent(in) :: n  !! the integer
      character(len=:), allocatable :: text
      character(len=24) :: buffer
      write (buffer, '(i0)') n
      text = trim(buffer)
   end function integer_text_default

   !> Decimal text of a 64-bit integer.
   pure function integer_text_int64(n) result(text)
      integer(int64), intent(in) :: n  !! the integer
      character(len=:), allocatable :: text
      character(len=24) :: buffer
      write (buffer, '(i0)') n
      text = trim(buffer)
   end function integer_text_int64

   !> Lower-case copy of a string (ASCII letters).
   pure function lower_case(text) result(low)
      character(len=*), intent(in) :: text  !! any text
      character(len=len(text)) :: low
      integer :: i
      low = text
      do i = 1, len(text)
         if (text(i:i) >= "A" .and. text(i:i) <= "Z") low(i:i) = achar(iachar(text(i:i)) + 32)
      end do
   end function lower_case

   !> Position of `name` in `names` (any case, blanks around it ignored; the names lower
   !> case), 0 when it is none of them: the lookup of the tables' `*_from_name`.
   pure integer function name_position(name, names) result(position)
      character(len=*), intent(in) :: name      !! the name looked up
      character(len=*), intent(in) :: names(:)  !! the names, lower case
      integer :: i
      position = 0
      do i = 1, size(names)
         if (lower_case(trim(adjustl(name))) == trim(names(i))) then
            position = i
            return
         end if
      end do
   end function name_position

   !> The names as a choice for a message: "a", "a or b", "a, b or c" (each name trimmed).
   pure function alternatives_text(names) result(text)
      character(len=*), intent(in) :: names(:)  !! the names, in order
      character(len=:), allocatable :: text
      integer :: i
      text = ""
      do i = 1, size(names)
         if (i > 1 .and. i == size(names)) then
            text = text//" or "
         else if (i > 1) then
            text = text//", "
         end if
         text = text//trim(names(i))
      end do
   end function alternatives_text

   !> format_es through Fortran's `es` descriptor (correctly rounded; slower), into
   !> buffer(last − digits − 6 : last).
   pure subroutine put_es_fortran(buffer, last, x, digits)
      character(len=*), intent(inout) :: buffer
      integer, intent(in) :: last, digits
      real(wp), intent(in) :: x
      character(len=40) :: fmt, text
      integer :: i, width
      width = digits + 7
      write (fmt, '(a,i0,a,i0,a)') "(es", width + 1, ".", digits - 1, "e3)"
      write (text(1:width + 1), fmt) x
      i = index(text(1:width + 1), "E")
      if (i > 0) text(i:i) = "e"
      if (digits == 1) then
         ! "d.e±xxx" → "de±xxx": drop the point Fortran writes after a lone digit
         i = index(text(1:width + 1), ".")
         text(2:i) = text(1:i - 1)
         text(1:1) = " "
      end if
      buffer(last - width + 1:last) = text(2:width + 1)
   end subroutine put_es_fortran
   !> Shortest decimal text that reads back to exactly x (plain notation for
   !> 1e-4 <= |x| < 1e15, else mantissa and exponent), e.g. 9.8, 0.0, 1.0e-10.
   function real_text(x) result(text)
      real(wp), intent(in) :: x  !! a finite value
      character(len=:), allocatable :: text
      character(len=40) :: buffer, fmt
      character(len=:), allocatable :: digits, sign_text
      integer :: d, e_at, exponent10, ios
      real(wp) :: back
      type(fpe_state_t) :: fpe
      if (x == 0.0_wp) then
         text = "0.0"
         return
      end if
      if (.not. ieee_is_finite(x)) then
         text = "not a finite number"
         return
      end if
      ! a rounded candidate may overflow when read back (1.8e308): no trap, just a miss
      call halting_off(fpe)
      do d = 1, 17
         write (fmt, '(a,i0,a)') "(es40.", d - 1, "e3)"
         write (buffer, fmt) x
         read (buffer, *, iostat=ios) back
         if (ios == 0 .and. back == x) exit
      end do
      call halting_restore(fpe)
      buffer = adjustl(buffer)
      sign_text = ""
      if (buffer(1:1) == "-") then
         sign_text = "-"
         buffer = buffer(2:)
      end if
      e_at = index(buffer, "E")
      read (buffer(e_at + 1:), *) exponent10
      digits = buffer(1:1)//buffer(3:e_at - 1)  ! mantissa digits without the point
      if (exponent10 >= -4 .and. exponent10 < 15) then
         if (exponent10 >= 0) then
            if (len(digits) <= exponent10 + 1) digits = digits//repeat("0", exponent10 + 2 - len(digits))
            text = sign_text//digits(:exponent10 + 1)//"."//digits(exponent10 + 2:)
         else
            text = sign_text//"0."//repeat("0", -exponent10 - 1)//digits
         end if
      else
         if (len(digits) == 1) digits = digits//"0"
         text = sign_text//digits(1:1)//"."//digits(2:)//"e"//integer_text(exponent10)
      end if
   end function real_text

   !> A string as a namelist character constant (quotes doubled).
   pure function quoted(text) result(q)
      character(len=*), intent(in) :: text  !! the text
      character(len=:), allocatable :: q
      integer :: i
      q = "'"
      do i = 1, len(text)
         if (text(i:i) == "'") then
            q = q//"''"
         else
            q = q//text(i:i)
         end if
      end do
      q = q//"'"
   end function quoted


   !> Switch halting on overflow/invalid/divide-by-zero off (reading `1e400` or `nan`
   !> must give a message, not a trap, even in a build compiled with -ffpe-trap).
   subroutine halting_off(state)
      type(fpe_state_t), intent(out) :: state  !! the modes to restore
      integer :: k
      state%can_halt = .true.
      do k = 1, size(ieee_usual)
         state%can_halt = state%can_halt .and. ieee_support_halting(ieee_usual(k))
      end do
      if (state%can_halt) then
         call ieee_get_halting_mode(ieee_usual, state%halting)
         call ieee_set_halting_mode(ieee_usual, .false.)
      end if
   end subroutine halting_off

   !> Clear the flags raised meanwhile and restore the halting modes.
   subroutine halting_restore(state)
      type(fpe_state_t), intent(in) :: state  !! from halting_off
      call ieee_set_flag(ieee_usual, .false.)
      if (state%can_halt) call ieee_set_halting_mode(ieee_usual, state%halting)
   end subroutine halting_restore

   !> Read one whole line from a formatted unit; with `max_length`, stop after that many
   !> characters (`too_long` true, `ios` /= 0, the rest of the line unread).
   subroutine read_text_line(unit, line, ios, max_length, too_long)
      integer, intent(in) :: unit  !! a formatted unit open for reading
      character(len=:), allocatable, intent(out) :: line  !! the line, without its newline
      integer, intent(out) :: ios  !! 0, or iostat_end at the end of the file
      integer, intent(in), optional :: max_length  !! longest line accepted
      logical, intent(out), optional :: too_long   !! the line is longer than max_length
      character(len=1024) :: chunk
      integer :: got
      line = ""
      if (present(too_long)) too_long = .false.
      do
         read (unit, '(a)', advance="no", iostat=ios, size=got) chunk
         line = line//chunk(:got)
         if (present(max_length)) then
            if (len(line) > max_length) then
               if (present(too_long)) too_long = .true.
               ios = 1
               return
            end if
         end if
         if (ios /= 0) exit
      end do
      if (is_iostat_eor(ios)) ios = 0
   end subroutine read_text_line
end module hillstab_core_text

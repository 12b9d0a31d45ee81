!> Tests of hillstab_core_text (format_es, put_es) against Fortran's own formatted I/O:
!> numbers read back by a list-directed read (exactly, at 17 digits), exact text for
!> powers of ten and for roundings that carry into the exponent, the layout (width,
!> digits, exponent), agreement digit for digit with the correctly rounded `es` edit
!> descriptor (sample values, random bit patterns, near-ties), the table of powers of
!> ten, and non-finite values.
module test_format
   use hillstab_core_kinds, only: wp, int64
   use hillstab_core_text, only: format_es, es_width, put_es, put_integer
   use hillstab_core_powers_of_ten, only: power_min, power_max, power_hi, power_lo
   use hillstab_testing
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_positive_inf, ieee_negative_inf
   implicit none
   private
   public :: collect_format

contains

   function collect_format() result(suite)
      type(testsuite_t) :: suite
      suite = new_testsuite("format", [ &
         new_unittest("read_back", read_back), &
         new_unittest("powers_of_ten_exact", powers_of_ten_exact), &
         new_unittest("carry_into_exponent", carry_into_exponent), &
         new_unittest("layout", layout), &
         new_unittest("agrees_with_es_descriptor", agrees_with_es_descriptor), &
         new_unittest("random_bits_round_trip", random_bits_round_trip), &
         new_unittest("power_table", power_table), &
         new_unittest("put_es_buffer", put_es_buffer), &
         new_unittest("non_finite", non_finite), &
         new_unittest("put_integer_as_i0", put_integer_as_i0)])
   end function collect_format

   !> The test values: ±1, 0, powers of ten 1e-300 … 1e300, the subnormal 1e-308, huge,
   !> tiny, values just below powers of ten, and sin(k)·10^(k mod 40 − 20).
   function sample_values() result(x)
      real(wp), allocatable :: x(:)
      integer :: k
      x = [1.0_wp, -1.0_wp, 0.0_wp, huge(1.0_wp), -huge(1.0_wp), tiny(1.0_wp), 1.0e-308_wp, &
           0.99999999999999999_wp, nearest(1.0_wp, -1.0_wp), 9.9999999999999995e22_wp, 9.9999999999999995e-5_wp, &
           0.5_wp, 0.1_wp, 1.0_wp/3.0_wp, 2.0_wp/3.0_wp, 123456789.0_wp, 9007199254740993.0_wp, &
           -1266.8019686641_wp, 4.9e-300_wp, &
           ! extreme exponents where a scaling in several power-of-ten steps rounds several times
           9.9507626338162162e295_wp, 9.1106540509146868e-296_wp, 9.2564491479889706e-251_wp]
      do k = -300, 300, 7
         x = [x, power_of_ten(k), -power_of_ten(k)*3.0_wp]
      end do
      do k = 1, 400
         x = [x, sin(real(k, wp))*10.0_wp**(mod(k, 40) - 20)]
      end do
   end function sample_values

   !> The double nearest 10^k (the compiler's decimal conversion of "1e<k>").
   function power_of_ten(k) result(x)
      integer, intent(in) :: k
      real(wp) :: x
      character(len=16) :: text
      write (text, '(a,i0)') "1e", k
      read (text, *) x
   end function power_of_ten
   !> Decimal exponent E of x (|x| = m·10^E, 1 ≤ m < 10) from Fortran's own es descriptor.
   integer function decimal_exponent(x) result(e)
      real(wp), intent(in) :: x
      character(len=40) :: text
      write (text, '(es30.20e3)') x
      read (text(index(text, "E") + 1:), *) e
   end function decimal_exponent

   !> format_es(x, d) read back: within half a unit of the last printed digit for d = 16
   !> (the text is correctly rounded), and exactly x for d = 17 (17 significant digits
   !> identify a double). (±huge is not read: at 16 digits its correctly rounded text lies
   !> beyond huge.)
   subroutine read_back(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp), allocatable :: x(:)
      real(wp) :: y, bound, worst16, worst17, half_unit
      integer :: i, iostat
      character(len=60) :: label
      character(len=32) :: text
      x = sample_values()
      worst16 = 0.0_wp; worst17 = 0.0_wp
      do i = 1, size(x)
         if (abs(x(i)) == huge(1.0_wp)) cycle   ! below, as text
         write (label, '(a,es25.17e3)') "x = ", x(i)
         text = format_es(x(i), 17)
         read (text, *, iostat=iostat) y
         call check(ctx, iostat == 0, "17 digits readable, "//trim(label))
         call check(ctx, y == x(i), "17 digits read back exactly, "//trim(label))
         if (x(i) /= 0.0_wp) worst17 = max(worst17, abs(y - x(i))/max(abs(x(i)), tiny(1.0_wp)))
         text = format_es(x(i), 16)
         read (text, *, iostat=iostat) y
         call check(ctx, iostat == 0, "16 digits readable, "//trim(label))
         if (x(i) == 0.0_wp) then
            call check(ctx, y == 0.0_wp, "zero")
            cycle
         end if
         half_unit = 0.5_wp*power_of_ten(decimal_exponent(x(i)) - 15)
         bound = half_unit + spacing(y)
         call check(ctx, abs(y - x(i)) <= bound, "16 digits, "//trim(label))
         worst16 = max(worst16, abs(y - x(i))/bound)
      end do
      ! huge = 1.7976931348623157e308: 17 digits are enough, and the text must stay below
      ! the rounding threshold to infinity (…158079e308). Compared as text: reading a text
      ! beyond it would trap on overflow in the debug build.
      text = format_es(huge(1.0_wp), 17)
      call check(ctx, text(2:19) <= "1.7976931348623158" .and. text(2:19) >= "1.7976931348623156" &
                 .and. text(20:24) == "e+308", "huge at 17 digits must read back as huge: '"//trim(text)//"'")
      write (*, '(4x,a,i0,a,es9.2,a,f5.2,a)') "read back of ", size(x), " values: 17 digits max rel. error ", &
         worst17, ", 16 digits max error ", worst16, " x (half unit + 1 ulp)"
   end subroutine read_back

   !> An integer as text.
   pure function count_text(n) result(text)
      integer, intent(in) :: n
      character(len=12) :: text
      write (text, '(i0)') n
   end function count_text
   !> The double nearest 10^k prints as exactly 1.000…e±k with 16 digits (it is within
   !> 1.2e-16 relative of 10^k, far inside half a unit of the 16th digit).
   subroutine powers_of_ten_exact(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=23) :: expected
      integer :: k, n_wrong, e_pos
      n_wrong = 0
      do k = -307, 308
         ! the correctly rounded 16 digits of the double nearest 10^k (Fortran's es, which
         ! rounds correctly: e.g. 1e-307 is 9.99999999999999909e-308 → 9.999999999999999e-308)
         write (expected, '(es23.15e3)') power_of_ten(k)
         e_pos = index(expected, "E")
         if (e_pos > 0) expected(e_pos:e_pos) = "e"
         ! the correctly rounded text itself (the module's promise)
         if (format_es(power_of_ten(k), 16) /= expected) then
            n_wrong = n_wrong + 1
            if (n_wrong <= 3) call check(ctx, .false., "10^k: got '"//format_es(power_of_ten(k), 16)// &
                                         "' expected '"//expected//"'")
         end if
      end do
      call check(ctx, n_wrong == 0, "all powers of ten exact")
      write (*, '(4x,a,i0,a)') "powers of ten 1e-307 … 1e308 at 16 digits: ", n_wrong, " not correctly rounded"
   end subroutine powers_of_ten_exact

   !> Roundings that carry into the exponent: 9.99…5 → 1.0 × 10^(e+1).
   subroutine carry_into_exponent(ctx)
      type(test_context_t), intent(inout) :: ctx
      call check(ctx, format_es(0.99999999999999999_wp, 16) == " 1.000000000000000e+000", &
                 "0.99999999999999999 (= 1.0 in binary)")
      ! the double nearest 1e23 is 9.99999999999999991611392e22: its 16 digits do not carry
      call check(ctx, format_es(9.9999999999999995e22_wp, 16) == " 9.999999999999999e+022", "9.9999999999999995e22")
      ! the double nearest 1e24 is 999999999999999983222784: its 16 digits do carry
      call check(ctx, format_es(1.0e24_wp, 16) == " 1.000000000000000e+024", "1e24 (9.99999999999999983e23)")
      call check(ctx, format_es(9.96_wp, 2) == " 1.0e+001", "9.96 with 2 digits")
      call check(ctx, format_es(-9.96_wp, 2) == "-1.0e+001", "-9.96 with 2 digits")
      call check(ctx, format_es(0.0996_wp, 2) == " 1.0e-001", "0.0996 with 2 digits")
      call check(ctx, format_es(9.5_wp, 1) == "  1e+001", "9.5 with 1 digit")
      call check(ctx, format_es(999999.9_wp, 6) == " 1.00000e+006", "999999.9 with 6 digits")
      call check(ctx, format_es(9.99999999999e-100_wp, 10) == " 1.000000000e-099", "9.99999999999e-100, 10 digits")
      ! no carry where none is due
      call check(ctx, format_es(9.94_wp, 2) == " 9.9e+000", "9.94 with 2 digits")
      call check(ctx, format_es(1.0e-5_wp, 3) == " 1.00e-005", "1e-5 with 3 digits")
   end subroutine carry_into_exponent

   !> Width es_width(d), right-aligned: blank or '-', d significant digits (with a point
   !> after the first when d > 1), 'e', exponent sign and three digits.
   subroutine layout(ctx)
      type(test_context_t), intent(inout) :: ctx
      integer, parameter :: digit_counts(4) = [1, 10, 16, 17]
      real(wp), parameter :: values(6) = [3.0_wp, -2.5e-7_wp, 6.02214076e23_wp, -1.0e-300_wp, 0.0_wp, 1.0e100_wp]
      character(len=:), allocatable :: text
      integer :: i, k, d, w, start
      logical :: ok
      do k = 1, size(digit_counts)
         d = digit_counts(k)
         w = es_width(d)
         call check(ctx, w == d + 7, "es_width = digits + 7")
         do i = 1, size(values)
            text = format_es(values(i), d)
            call check(ctx, len(text) == w, "width")
            ok = text(w - 4:w - 4) == "e" .and. (text(w - 3:w - 3) == "+" .or. text(w - 3:w - 3) == "-") &
                 .and. verify(text(w - 2:w), "0123456789") == 0
            call check(ctx, ok, "exponent e, sign and three digits: '"//text//"'")
            ! the mantissa d.dd…d (d > 1) or d (d = 1) ends just before the exponent
            if (d > 1) then
               start = w - 5 - d
               ok = verify(text(start:start), "0123456789") == 0 .and. text(start + 1:start + 1) == "." &
                    .and. verify(text(start + 2:w - 5), "0123456789") == 0
            else
               start = w - 5
               ok = verify(text(start:start), "0123456789") == 0
            end if
            call check(ctx, ok, "mantissa of "//trim(adjustl(count_text(d)))//" digits: '"//text//"'")
            ! the sign slot just before it, blanks before that
            if (values(i) < 0.0_wp) then
               call check(ctx, text(start - 1:start - 1) == "-", "minus sign: '"//text//"'")
            else
               call check(ctx, text(start - 1:start - 1) == " ", "leading blank: '"//text//"'")
            end if
            call check(ctx, text(1:start - 2) == "", "blanks before the sign slot: '"//text//"'")
         end do
      end do
      call check(ctx, format_es(0.0_wp, 4) == " 0.000e+000", "zero")
      call check(ctx, format_es(sign(0.0_wp, -1.0_wp), 4) == " 0.000e+000", "negative zero without a sign")
      call check(ctx, format_es(-1266.8019686641_wp, 12) == "-1.26680196866e+003", "the module header's example")
      call check(ctx, format_es(6.02214076e23_wp, 10) == " 6.022140760e+023", "Avogadro")
      call check(ctx, format_es(3.0_wp, 1) == "  3e+000", "one digit: no point")
   end subroutine layout

   !> format_es(x, d) against gfortran's correctly rounded es(d+7).(d−1)e3 text, for every
   !> digit count 1 … 17 and every sample value, and for values a hair's breadth from a
   !> tie of the last digit (k + 1/2 units, moved by one ulp either way, and the exact
   !> ties k + 1/2 that a double can hold): the texts must be equal.
   subroutine agrees_with_es_descriptor(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp), allocatable :: x(:)
      real(wp) :: tie
      integer :: i, d, n_differ, n_values, k
      x = sample_values()
      ! near-ties: (k + 1/2)·10^e for a few digit counts, and its neighbours
      do k = 1, 40
         tie = (real(12345*k, wp) + 0.5_wp)*10.0_wp**(mod(k, 9) - 4)
         x = [x, tie, nearest(tie, 1.0_wp), nearest(tie, -1.0_wp), -tie]
      end do
      ! exact ties in binary: 0.125, 2.5, 1.0000000000000002 ... (k + 1/2)/2^j
      x = [x, 0.125_wp, 2.5_wp, 0.375_wp, 1.5_wp, 1234.5_wp, 9.5_wp, 0.5_wp**20]
      n_differ = 0
      n_values = 0
      do d = 1, 17
         do i = 1, size(x)
            n_values = n_values + 1
            if (.not. same_as_es(x(i), d)) then
               n_differ = n_differ + 1
               if (n_differ <= 5) call check(ctx, .false., "es descriptor vs format_es at "// &
                  trim(count_text(d))//" digits: '"//format_es(x(i), d)//"'")
            end if
         end do
      end do
      call check(ctx, n_differ == 0, "every text equal to the es descriptor's")
      write (*, '(4x,a,i0,a,i0,a)') "vs es descriptor, digits 1 ... 17: ", n_differ, " of ", n_values, " differ"
   end subroutine agrees_with_es_descriptor

   !> Whether format_es(x, d) equals Fortran's es text of x (its 'E' made 'e'; with one
   !> digit, the point Fortran writes after it dropped).
   logical function same_as_es(x, d) result(same)
      real(wp), intent(in) :: x
      integer, intent(in) :: d
      character(len=40) :: fmt, reference
      integer :: i
      write (fmt, '(a,i0,a,i0,a)') "(es", es_width(d) + 1, ".", d - 1, "e3)"
      write (reference, fmt) x
      call lower_case(reference)
      if (d == 1) then
         i = index(reference(1:es_width(d) + 1), ".")
         reference(2:i) = reference(1:i - 1)
         reference(1:1) = " "
      end if
      same = format_es(x, d) == reference(2:es_width(d) + 1)
   end function same_as_es

   !> 200 000 doubles drawn as random bit patterns (every exponent, subnormals included)
   !> and 200 000 drawn uniformly in [1e-12, 1e12]: at 17 digits each text reads back to
   !> the same double and equals the es descriptor's; at 11 and 4 digits it equals the es
   !> descriptor's.
   subroutine random_bits_round_trip(ctx)
      type(test_context_t), intent(inout) :: ctx
      integer, parameter :: n = 200000
      integer(int64) :: bits, state
      real(wp) :: x, y, u
      integer :: i, n_bad_read, n_bad_text, d, j
      character(len=32) :: text
      integer, parameter :: digit_counts(3) = [17, 11, 4]
      state = 88172645463325252_int64
      n_bad_read = 0
      n_bad_text = 0
      do i = 1, 2*n
         ! xorshift64: a fixed sequence, the same on every run
         state = ieor(state, ishft(state, 13))
         state = ieor(state, ishft(state, -7))
         state = ieor(state, ishft(state, 17))
         if (i <= n) then
            bits = iand(state, huge(1_int64))
            if (ishft(bits, -52) == 2047) cycle   ! NaN and Inf: not numbers
            x = transfer(bits, 1.0_wp)
            if (btest(state, 63)) x = -x
         else
            u = real(iand(ishft(state, -11), 2_int64**52 - 1), wp)/2.0_wp**52
            x = 10.0_wp**(24.0_wp*u - 12.0_wp)
         end if
         if (abs(x) == huge(1.0_wp)) cycle
         text = format_es(x, 17)
         read (text, *) y
         if (y /= x) n_bad_read = n_bad_read + 1
         do j = 1, size(digit_counts)
            d = digit_counts(j)
            if (.not. same_as_es(x, d)) then
               n_bad_text = n_bad_text + 1
               if (n_bad_text <= 3) call check(ctx, .false., "format_es vs es at "//trim(count_text(d))// &
                  " digits: '"//format_es(x, d)//"'")
            end if
         end do
      end do
      call check(ctx, n_bad_read == 0, "17 digits read back exactly: "//trim(count_text(n_bad_read))//" did not")
      call check(ctx, n_bad_text == 0, "texts equal to the es descriptor's: "//trim(count_text(n_bad_text))//" were not")
      write (*, '(4x,a,i0,a,i0,a,i0,a)') "random doubles: ", 2*n, " values, ", n_bad_read, &
         " not read back exactly, ", n_bad_text, " texts unlike the es descriptor's"
   end subroutine random_bits_round_trip

   !> The table of powers of ten: power_hi(p) is the double nearest 10^p (the compiler's
   !> conversion of "1e<p>"), |power_lo(p)| is at most half an ulp of it, and the pairs
   !> agree with 10 times the pair before to double-double accuracy (1e-30 relative).
   subroutine power_table(ctx)
      type(test_context_t), intent(inout) :: ctx
      integer :: p, n_hi, n_lo, n_step
      real(wp) :: hi, lo, e_hi, e_lo
      n_hi = 0; n_lo = 0; n_step = 0
      do p = power_min, power_max
         if (power_hi(p) /= power_of_ten(p)) n_hi = n_hi + 1
         if (abs(power_lo(p)) > 0.5_wp*spacing(power_hi(p))) n_lo = n_lo + 1
         if (p > power_min) then
            ! 10·(hi + lo) of p − 1 in double-double: exact products by 10 of each part
            ! (hi·10 as 8 hi + 2 hi, exact in binary), then compared with hi + lo of p
            hi = 10.0_wp*power_hi(p - 1)
            e_hi = (8.0_wp*power_hi(p - 1) - hi) + 2.0_wp*power_hi(p - 1)
            lo = 10.0_wp*power_lo(p - 1)
            e_lo = (hi - power_hi(p)) + (e_hi + lo - power_lo(p))
            if (abs(e_lo) > 1.0e-30_wp*power_hi(p)) n_step = n_step + 1
         end if
      end do
      call check(ctx, n_hi == 0, "power_hi(p) is the double nearest 10^p: "//trim(count_text(n_hi))//" are not")
      call check(ctx, n_lo == 0, "|power_lo(p)| <= ulp/2: "//trim(count_text(n_lo))//" are not")
      call check(ctx, n_step == 0, "pairs agree with 10 times the one before: "//trim(count_text(n_step))//" do not")
   end subroutine power_table

   !> 'E' of Fortran's es output to 'e'.
   pure subroutine lower_case(text)
      character(len=*), intent(inout) :: text
      integer :: i
      i = index(text, "E")
      if (i > 0) text(i:i) = "e"
   end subroutine lower_case
   !> put_es writes consecutive fields into one buffer and advances pos by es_width.
   subroutine put_es_buffer(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp), parameter :: values(4) = [2.47_wp, -9.8_wp, 1.0e-12_wp, 0.0_wp]
      character(len=100) :: buffer
      character(len=:), allocatable :: expected
      integer :: pos, i
      buffer = "XX"
      pos = 2
      expected = "XX"
      do i = 1, size(values)
         call put_es(buffer, pos, values(i), 12)
         expected = expected//format_es(values(i), 12)
      end do
      call check(ctx, pos == 2 + 4*es_width(12), "pos advanced by 4 widths")
      call check(ctx, buffer(1:pos) == expected, "fields equal format_es, concatenated")
      call check(ctx, buffer(pos + 1:) == "", "nothing written past pos")
   end subroutine put_es_buffer

   !> NaN and ±Inf give "nan", "inf", "-inf", right-aligned in the field.
   subroutine non_finite(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp) :: nan, plus_inf, minus_inf
      integer :: d, w
      nan = ieee_value(1.0_wp, ieee_quiet_nan)
      plus_inf = ieee_value(1.0_wp, ieee_positive_inf)
      minus_inf = ieee_value(1.0_wp, ieee_negative_inf)
      do d = 1, 17, 8
         w = es_width(d)
         call check(ctx, format_es(nan, d) == repeat(" ", w - 3)//"nan", "nan")
         call check(ctx, format_es(plus_inf, d) == repeat(" ", w - 3)//"inf", "inf")
         call check(ctx, format_es(minus_inf, d) == repeat(" ", w - 4)//"-inf", "-inf")
      end do
   end subroutine non_finite

   !> put_integer writes what the `i0` edit descriptor writes, after what the buffer holds.
   subroutine put_integer_as_i0(ctx)
      type(test_context_t), intent(inout) :: ctx
      integer, parameter :: values(9) = [0, 7, -7, 10, 99, -100, 123456789, huge(1), -huge(1)]
      character(len=40) :: buffer, expected
      integer :: k, pos
      do k = 1, size(values)
         buffer = "x"
         pos = 1
         call put_integer(buffer, pos, values(k))
         write (expected, '(a,i0)') "x", values(k)
         call check(ctx, buffer == expected .and. pos == len_trim(expected), &
                    "put_integer: '"//buffer(:pos)//"', expected '"//trim(expected)//"'")
      end do
   end subroutine put_integer_as_i0
end module test_format

!> A running checksum of bytes (two 32-bit multiplicative hashes of the bytes read as
!> little-endian 32-bit words, different multipliers, the length mixed in at the end), for
!> the checkpoint of a long run (hillstab_batch_output_checkpoint): the output writer feeds
!> it every byte of the partial file, the checkpoint's state records its value and that of
!> the state's own text, and `--resume` recomputes both before it trusts a byte. A changed,
!> added or missing byte anywhere changes the value (a random change goes unnoticed with a
!> chance of about 2^-64); it guards against damage, not against someone who recomputes it.
!>
!> The value depends on the bytes only, not on how they were cut into `digest_update` calls.
!> It costs a fraction of a nanosecond a byte: a 1000 x 1000 chart of 152 MB by formula (the
!> output dominates) took 0.62 s of CPU time against 0.575 s without it (release build,
!> medians of 6 runs; wall 0.77 against 0.76 s).
!>
!>```fortran
!> type(digest_t) :: digest
!> call digest_update(digest, "1.0 2.0 3.0"//new_line("a"))
!> print '(a)', digest_text(digest)   ! 16 hexadecimal digits
!>```
module hillstab_batch_output_digest
   use hillstab_core_kinds, only: int64
   implicit none
   private
   public :: digest_t, digest_update, digest_value, digest_text, text_digest

   !> The two lanes' multipliers (odd, below 2^31, so that a lane times one stays below 2^63).
   integer(int64), parameter :: multiplier(2) = [16777619_int64, 668265263_int64]
   !> The lanes' starting values.
   integer(int64), parameter :: start(2) = [2166136261_int64, 374761393_int64]
   !> 2^32 − 1.
   integer(int64), parameter :: low32 = 4294967295_int64

   !> The checksum of the bytes fed so far.
   type :: digest_t
      integer(int64) :: lane(2) = start  !! the two hashes, each in [0, 2^32)
      integer(int64) :: length = 0       !! bytes fed
      integer(int64) :: pending = 0      !! the bytes of an unfinished word, little-endian
      integer :: n_pending = 0           !! how many (0 … 3)
   end type digest_t

contains

   !> Feed `text` to the checksum.
   pure subroutine digest_update(digest, text)
      type(digest_t), intent(inout) :: digest  !! the checksum so far
      character(len=*), intent(in) :: text  !! the next bytes
      integer :: i, n
      integer(int64) :: word
      i = 1
      n = len(text)
      ! finish a word begun by an earlier call
      do while (digest%n_pending > 0 .and. i <= n)
         digest%pending = ior(digest%pending, ishft(int(iachar(text(i:i)), int64), 8*digest%n_pending))
         digest%n_pending = digest%n_pending + 1
         i = i + 1
         if (digest%n_pending == 4) then
            call mix(digest%lane, digest%pending)
            digest%pending = 0
            digest%n_pending = 0
         end if
      end do
      ! whole words
      do while (i + 3 <= n)
         word = ior(ior(int(iachar(text(i:i)), int64), ishft(int(iachar(text(i + 1:i + 1)), int64), 8)), &
                    ior(ishft(int(iachar(text(i + 2:i + 2)), int64), 16), ishft(int(iachar(text(i + 3:i + 3)), int64), 24)))
         call mix(digest%lane, word)
         i = i + 4
      end do
      ! the start of the next word
      do while (i <= n)
         digest%pending = ior(digest%pending, ishft(int(iachar(text(i:i)), int64), 8*digest%n_pending))
         digest%n_pending = digest%n_pending + 1
         i = i + 1
      end do
      digest%length = digest%length + n
   end subroutine digest_update

   !> Mix a 32-bit word into both lanes.
   pure subroutine mix(lane, word)
      integer(int64), intent(inout) :: lane(2)
      integer(int64), intent(in) :: word  !! in [0, 2^32)
      lane = iand(ieor(lane, word)*multiplier, low32)
   end subroutine mix

   !> The checksum of the bytes fed so far (the unfinished word and the length mixed into a
   !> copy: feeding may go on).
   pure function digest_value(digest) result(value)
      type(digest_t), intent(in) :: digest  !! the checksum so far
      integer(int64) :: value(2)  !! two numbers in [0, 2^32)
      value = digest%lane
      call mix(value, ior(digest%pending, ishft(int(digest%n_pending, int64), 32 - 2)))
      call mix(value, iand(digest%length, low32))
      call mix(value, iand(ishft(digest%length, -32), low32))
      ! a last round each, so that the final words reach every bit
      call mix(value, 0_int64)
   end function digest_value

   !> The checksum as 16 hexadecimal digits.
   pure function digest_text(digest) result(text)
      type(digest_t), intent(in) :: digest  !! the checksum so far
      character(len=16) :: text
      character(len=*), parameter :: hex = "0123456789abcdef"
      integer(int64) :: value(2), v
      integer :: k, j
      value = digest_value(digest)
      do j = 1, 2
         v = value(j)
         do k = 8*j, 8*j - 7, -1
            text(k:k) = hex(int(iand(v, 15_int64)) + 1:int(iand(v, 15_int64)) + 1)
            v = ishft(v, -4)
         end do
      end do
   end function digest_text

   !> The checksum of `text` alone, as 16 hexadecimal digits.
   pure function text_digest(text) result(hex)
      character(len=*), intent(in) :: text  !! the bytes
      character(len=16) :: hex
      type(digest_t) :: digest
      call digest_update(digest, text)
      hex = digest_text(digest)
   end function text_digest
end module hillstab_batch_output_digest

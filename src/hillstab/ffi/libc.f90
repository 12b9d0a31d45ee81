!> Interfaces of the C library and POSIX routines hillstab calls, declared once: files
!> (stdio streams, mkstemp, fdopen, fchmod, umask, rename, remove, unlink, fsync, link,
!> rmdir, lstat, fstat, ftruncate, fseek, flock), errno and its message, the process id and
!> effective user, signals and write(2) for the handler, whether a descriptor is a terminal,
!> free space (statvfs), random bytes (getrandom), a short sleep (nanosleep), the CPUs a thread
!> may run on (sched_getaffinity, sched_setaffinity, sched_getcpu), the names in a directory
!> (opendir, readdir, closedir: `names_with_prefix`). Bindings only:
!> the writers (hillstab_batch_output_file), the checkpoints (hillstab_batch_output_checkpoint), the
!> signal cleanup (hillstab_batch_output_signals), the resource limits (hillstab_batch_run_limits) and
!> the progress line use them; `remove_file` and `is_directory` are the two path helpers
!> every reader and writer needs, `try_lock` the lock test of the output and the checkpoint. Layouts (struct stat,
!> off_t, struct dirent) are those of 64-bit Linux.
!>
!>```fortran
!> integer(c_int) :: status
!> status = c_rename(c_string("a.part"), c_string("a"))   ! rename(2): 0 on success
!> if (status /= 0) print '(a)', errno_text()
!>```
module hillstab_ffi_libc
   use, intrinsic :: iso_c_binding, only: c_int, c_char, c_null_char, c_ptr, c_size_t, c_long, c_funptr, &
      c_f_pointer, c_associated
   implicit none
   private
   public :: c_mkstemp, c_fdopen, c_fchmod, c_umask, c_close, c_getrlimit, rlimit_t, rlimit_as, rlimit_stack, &
      c_getpagesize
   public :: c_rename, c_remove, c_unlink, c_getpid, c_fopen, c_fwrite, c_fwrite_raw, c_fflush, c_fclose, c_fileno, &
      c_fsync, c_signal, c_exit_now, c_isatty, c_statvfs, statvfs_t
   public :: errno_text, set_errno, c_string, remove_file, is_directory, is_special_file, c_mkdir
   public :: stat_t, c_lstat, c_fstat, c_link, c_rmdir, c_geteuid, c_ftruncate, c_fseek, c_flock, c_getrandom, &
      c_write, c_nanosleep, timespec_t, errno_value, file_type, file_type_regular, file_type_directory, &
      file_type_link, seek_end, lock_exclusive, lock_nonblocking, errno_exists, errno_no_entry, errno_would_block
   public :: c_mallopt, malloc_trim_threshold, malloc_top_pad, malloc_mmap_threshold
   public :: c_sched_getaffinity, c_sched_setaffinity, c_sched_getcpu, cpu_set_words, name_max, try_lock
   public :: names_with_prefix, lock_state, lock_taken, lock_busy, lock_unknown

   !> The file type bits of `stat_t%mode` (S_IFMT).
   integer(c_int), parameter :: file_type = int(o'170000', c_int)
   integer(c_int), parameter :: file_type_regular = int(o'100000', c_int)    !! S_IFREG: a regular file
   integer(c_int), parameter :: file_type_directory = int(o'040000', c_int)  !! S_IFDIR: a directory
   integer(c_int), parameter :: file_type_link = int(o'120000', c_int)       !! S_IFLNK: a symbolic link
   integer(c_int), parameter :: seek_end = 2           !! SEEK_END of fseek
   integer(c_int), parameter :: malloc_trim_threshold = -1  !! M_TRIM_THRESHOLD of mallopt
   integer(c_int), parameter :: malloc_top_pad = -2         !! M_TOP_PAD of mallopt
   integer(c_int), parameter :: malloc_mmap_threshold = -3  !! M_MMAP_THRESHOLD of mallopt
   integer(c_int), parameter :: lock_exclusive = 2     !! LOCK_EX of flock
   integer(c_int), parameter :: lock_nonblocking = 4   !! LOCK_NB of flock
   integer, parameter :: errno_no_entry = 2            !! ENOENT
   integer, parameter :: errno_would_block = 11        !! EWOULDBLOCK (EAGAIN) on Linux
   integer, parameter :: errno_exists = 17             !! EEXIST

   !> NAME_MAX of Linux: the longest file name (one path component), in bytes.
   integer, parameter :: name_max = 255
   !> Offset of d_name in struct dirent of 64-bit Linux (after d_ino, d_off, d_reclen, d_type).
   integer, parameter :: dirent_name_offset = 19

   !> What `lock_state` found: the lock was free and is now held by the caller
   integer, parameter :: lock_taken = 1
   !> another open file holds it (a running writer)
   integer, parameter :: lock_busy = 2
   !> the file system cannot say (no flock there)
   integer, parameter :: lock_unknown = 3

   !> cpu_set_t of glibc: 1024 bits, CPU k is bit mod(k, 64) of word k/64 (from 1 here).
   integer, parameter :: cpu_set_words = 16

   !> RLIMIT_AS (Linux): the largest address space of the process.
   integer(c_int), parameter :: rlimit_as = 9
   !> RLIMIT_STACK (Linux): the stack of the main thread (and glibc's default for new threads).
   integer(c_int), parameter :: rlimit_stack = 3

   !> struct rlimit on 64-bit Linux (RLIM_INFINITY is all ones: -1 here).
   type, bind(C) :: rlimit_t
      integer(c_long) :: cur  !! soft limit
      integer(c_long) :: max  !! hard limit
   end type rlimit_t

   !> struct stat on x86-64 Linux (144 bytes).
   type, bind(C) :: stat_t
      integer(c_long) :: dev        !! device of the file system
      integer(c_long) :: ino        !! inode number
      integer(c_long) :: nlink      !! number of hard links
      integer(c_int) :: mode        !! type and permission bits
      integer(c_int) :: uid         !! owner
      integer(c_int) :: gid         !! group
      integer(c_int) :: pad         !! padding
      integer(c_long) :: rdev       !! device (special files)
      integer(c_long) :: size       !! size in bytes
      integer(c_long) :: blksize    !! block size for i/o
      integer(c_long) :: blocks     !! 512-byte blocks allocated
      integer(c_long) :: times(6)   !! access, modification, change times (seconds, nanoseconds)
      integer(c_long) :: reserved(3)  !! reserved
   end type stat_t

   !> struct timespec on 64-bit Linux.
   type, bind(C) :: timespec_t
      integer(c_long) :: seconds      !! whole seconds
      integer(c_long) :: nanoseconds  !! and nanoseconds, 0 … 999999999
   end type timespec_t

   !> struct statvfs on 64-bit Linux.
   type, bind(C) :: statvfs_t
      integer(c_long) :: bsize    !! file system block size
      integer(c_long) :: frsize   !! fragment size (the unit of the counts)
      integer(c_long) :: blocks   !! size of the file system in frsize units
      integer(c_long) :: bfree    !! free blocks
      integer(c_long) :: bavail   !! free blocks for unprivileged users
      integer(c_long) :: files    !! inodes
      integer(c_long) :: ffree    !! free inodes
      integer(c_long) :: favail   !! free inodes for unprivileged users
      integer(c_long) :: fsid     !! file system id
      integer(c_long) :: flag     !! mount flags
      integer(c_long) :: namemax  !! longest file name
      integer(c_int) :: spare(6)  !! reserved
   end type statvfs_t

   interface
      !> mkstemp(3): create and open a new file from `template` (ending in XXXXXX, replaced in
      !> place by an unpredictable suffix) with O_CREAT | O_EXCL, mode 0600; the descriptor,
      !> or -1. O_EXCL: nothing placed at the name, a symbolic link included, is opened.
      function c_mkstemp(template) bind(C, name="mkstemp") result(fd)
         import :: c_int, c_char
         character(kind=c_char), intent(inout) :: template(*)  !! the path, NUL-terminated, ending in XXXXXX
         integer(c_int) :: fd
      end function c_mkstemp
      !> fdopen(3): a stdio stream on an open descriptor (NULL on failure).
      function c_fdopen(fd, mode) bind(C, name="fdopen") result(stream)
         import :: c_int, c_char, c_ptr
         integer(c_int), value :: fd  !! an open descriptor
         character(kind=c_char), intent(in) :: mode(*)  !! "w", NUL-terminated
         type(c_ptr) :: stream
      end function c_fdopen
      !> fchmod(2): 0 on success.
      function c_fchmod(fd, mode) bind(C, name="fchmod") result(status)
         import :: c_int
         integer(c_int), value :: fd    !! an open descriptor
         integer(c_int), value :: mode  !! permission bits
         integer(c_int) :: status
      end function c_fchmod
      !> umask(2): set the file mode creation mask, return the previous one.
      function c_umask(mask) bind(C, name="umask") result(previous)
         import :: c_int
         integer(c_int), value :: mask  !! the new mask
         integer(c_int) :: previous
      end function c_umask
      !> getrlimit(2): 0 on success.
      function c_getrlimit(resource, limit) bind(C, name="getrlimit") result(status)
         import :: c_int, rlimit_t
         integer(c_int), value :: resource  !! RLIMIT_* (rlimit_as)
         type(rlimit_t), intent(out) :: limit  !! the soft and hard limits
         integer(c_int) :: status
      end function c_getrlimit
      !> getpagesize(2): bytes in a memory page.
      function c_getpagesize() bind(C, name="getpagesize") result(bytes)
         import :: c_int
         integer(c_int) :: bytes
      end function c_getpagesize
      !> stat(2): 0 on success (follows symbolic links).
      function c_stat(path, info) bind(C, name="stat") result(status)
         import :: c_int, c_char, stat_t
         character(kind=c_char), intent(in) :: path(*)
         type(stat_t), intent(out) :: info
         integer(c_int) :: status
      end function c_stat
      !> lstat(2): 0 on success; a symbolic link is described, not followed.
      function c_lstat(path, info) bind(C, name="lstat") result(status)
         import :: c_int, c_char, stat_t
         character(kind=c_char), intent(in) :: path(*)  !! NUL-terminated path
         type(stat_t), intent(out) :: info  !! what the name is
         integer(c_int) :: status
      end function c_lstat
      !> opendir(3): a directory stream (NULL on failure).
      function c_opendir(path) bind(C, name="opendir") result(dir)
         import :: c_char, c_ptr
         character(kind=c_char), intent(in) :: path(*)  !! NUL-terminated path
         type(c_ptr) :: dir
      end function c_opendir
      !> readdir(3): the next entry (struct dirent), NULL at the end.
      function c_readdir(dir) bind(C, name="readdir") result(entry)
         import :: c_ptr
         type(c_ptr), value :: dir  !! from c_opendir
         type(c_ptr) :: entry
      end function c_readdir
      !> closedir(3): 0 on success.
      function c_closedir(dir) bind(C, name="closedir") result(status)
         import :: c_int, c_ptr
         type(c_ptr), value :: dir  !! from c_opendir
         integer(c_int) :: status
      end function c_closedir
      !> fstat(2): 0 on success.
      function c_fstat(fd, info) bind(C, name="fstat") result(status)
         import :: c_int, stat_t
         integer(c_int), value :: fd  !! an open descriptor
         type(stat_t), intent(out) :: info  !! the open file
         integer(c_int) :: status
      end function c_fstat
      !> link(2): a new name for an existing file, 0 on success; fails (EEXIST) when the new
      !> name exists, whatever it is (a symbolic link there is not followed).
      function c_link(old, new) bind(C, name="link") result(status)
         import :: c_int, c_char
         character(kind=c_char), intent(in) :: old(*)  !! NUL-terminated existing name
         character(kind=c_char), intent(in) :: new(*)  !! NUL-terminated new name
         integer(c_int) :: status
      end function c_link
      !> rmdir(2): remove an empty directory, 0 on success.
      function c_rmdir(path) bind(C, name="rmdir") result(status)
         import :: c_int, c_char
         character(kind=c_char), intent(in) :: path(*)  !! NUL-terminated path
         integer(c_int) :: status
      end function c_rmdir
      !> geteuid(2): the effective user id.
      function c_geteuid() bind(C, name="geteuid") result(uid)
         import :: c_int
         integer(c_int) :: uid
      end function c_geteuid
      !> ftruncate(2): cut (or extend) an open file to `length` bytes, 0 on success.
      function c_ftruncate(fd, length) bind(C, name="ftruncate") result(status)
         import :: c_int, c_long
         integer(c_int), value :: fd      !! an open descriptor
         integer(c_long), value :: length  !! the new size (off_t)
         integer(c_int) :: status
      end function c_ftruncate
      !> fseek(3): move the position of a stream, 0 on success.
      function c_fseek(stream, offset, whence) bind(C, name="fseek") result(status)
         import :: c_int, c_long, c_ptr
         type(c_ptr), value :: stream      !! the stream
         integer(c_long), value :: offset  !! bytes from `whence`
         integer(c_int), value :: whence   !! seek_end, …
         integer(c_int) :: status
      end function c_fseek
      !> flock(2): an advisory lock on an open file (released when the process ends), 0 on success.
      function c_flock(fd, operation) bind(C, name="flock") result(status)
         import :: c_int
         integer(c_int), value :: fd         !! an open descriptor
         integer(c_int), value :: operation  !! lock_exclusive, with lock_nonblocking
         integer(c_int) :: status
      end function c_flock
      !> getrandom(2): `length` random bytes from the kernel; the number given, or -1.
      function c_getrandom(buffer, length, flags) bind(C, name="getrandom") result(got)
         import :: c_char, c_size_t, c_int, c_long
         character(kind=c_char), intent(out) :: buffer(*)  !! the bytes
         integer(c_size_t), value :: length  !! how many
         integer(c_int), value :: flags      !! 0
         integer(c_long) :: got
      end function c_getrandom
      !> write(2) (async-signal-safe): the bytes written, or -1.
      function c_write(fd, buffer, length) bind(C, name="write") result(written)
         import :: c_int, c_char, c_size_t, c_long
         integer(c_int), value :: fd  !! the descriptor (2: stderr)
         character(kind=c_char), intent(in) :: buffer(*)  !! the bytes
         integer(c_size_t), value :: length  !! how many
         integer(c_long) :: written
      end function c_write
      !> mallopt(3) of glibc: set one parameter of the allocator; 1 on success.
      function c_mallopt(parameter, value) bind(C, name="mallopt") result(status)
         import :: c_int
         integer(c_int), value :: parameter  !! M_TRIM_THRESHOLD, M_TOP_PAD, M_MMAP_THRESHOLD, ...
         integer(c_int), value :: value      !! its value (bytes)
         integer(c_int) :: status
      end function c_mallopt
      !> nanosleep(2): sleep for `duration`, 0 when it elapsed.
      function c_nanosleep(duration, remaining) bind(C, name="nanosleep") result(status)
         import :: c_int, timespec_t
         type(timespec_t), intent(in) :: duration  !! how long
         type(timespec_t), intent(out) :: remaining  !! left when interrupted
         integer(c_int) :: status
      end function c_nanosleep
      !> sched_getaffinity(2): the CPUs thread `pid` (0: the caller) may run on; 0 on success.
      function c_sched_getaffinity(pid, size, mask) bind(C, name="sched_getaffinity") result(status)
         import :: c_int, c_size_t, c_long
         integer(c_int), value :: pid       !! the thread (0: the calling thread)
         integer(c_size_t), value :: size   !! bytes of `mask`
         integer(c_long), intent(out) :: mask(*)  !! cpu_set_t: `cpu_set_words` words
         integer(c_int) :: status
      end function c_sched_getaffinity
      !> sched_setaffinity(2): restrict thread `pid` (0: the caller) to the CPUs of `mask`.
      function c_sched_setaffinity(pid, size, mask) bind(C, name="sched_setaffinity") result(status)
         import :: c_int, c_size_t, c_long
         integer(c_int), value :: pid       !! the thread (0: the calling thread)
         integer(c_size_t), value :: size   !! bytes of `mask`
         integer(c_long), intent(in) :: mask(*)  !! cpu_set_t: `cpu_set_words` words
         integer(c_int) :: status
      end function c_sched_setaffinity
      !> sched_getcpu(3): the CPU the caller runs on, or −1.
      function c_sched_getcpu() bind(C, name="sched_getcpu") result(cpu)
         import :: c_int
         integer(c_int) :: cpu
      end function c_sched_getcpu
      !> close(2).
      function c_close(fd) bind(C, name="close") result(status)
         import :: c_int
         integer(c_int), value :: fd  !! the descriptor
         integer(c_int) :: status
      end function c_close
      !> rename(2): 0 on success.
      function c_rename(old, new) bind(C, name="rename") result(status)
         import :: c_int, c_char
         character(kind=c_char), intent(in) :: old(*)  !! NUL-terminated current name
         character(kind=c_char), intent(in) :: new(*)  !! NUL-terminated new name
         integer(c_int) :: status
      end function c_rename
      !> remove(3): 0 on success.
      function c_remove(path) bind(C, name="remove") result(status)
         import :: c_int, c_char
         character(kind=c_char), intent(in) :: path(*)  !! NUL-terminated path
         integer(c_int) :: status
      end function c_remove
      !> unlink(2) (async-signal-safe): 0 on success.
      function c_unlink(path) bind(C, name="unlink") result(status)
         import :: c_int, c_char
         character(kind=c_char), intent(in) :: path(*)  !! NUL-terminated path
         integer(c_int) :: status
      end function c_unlink
      !> getpid(2).
      function c_getpid() bind(C, name="getpid") result(pid)
         import :: c_int
         integer(c_int) :: pid
      end function c_getpid
      !> fopen(3): a C stream, or a null pointer (errno set).
      function c_fopen(path, mode) bind(C, name="fopen") result(stream)
         import :: c_char, c_ptr
         character(kind=c_char), intent(in) :: path(*)  !! NUL-terminated path
         character(kind=c_char), intent(in) :: mode(*)  !! NUL-terminated mode, e.g. "w"
         type(c_ptr) :: stream
      end function c_fopen
      !> fwrite(3) of characters: the number of items written.
      function c_fwrite(buffer, size, count, stream) bind(C, name="fwrite") result(written)
         import :: c_char, c_size_t, c_ptr
         character(kind=c_char), intent(in) :: buffer(*)  !! the bytes
         integer(c_size_t), value :: size   !! bytes per item
         integer(c_size_t), value :: count  !! items
         type(c_ptr), value :: stream       !! the stream
         integer(c_size_t) :: written
      end function c_fwrite
      !> fwrite(3) from an address (raw records).
      function c_fwrite_raw(buffer, size, count, stream) bind(C, name="fwrite") result(written)
         import :: c_ptr, c_size_t
         type(c_ptr), value :: buffer       !! address of the first byte
         integer(c_size_t), value :: size   !! bytes per item
         integer(c_size_t), value :: count  !! items
         type(c_ptr), value :: stream       !! the stream
         integer(c_size_t) :: written
      end function c_fwrite_raw
      !> fflush(3): 0 on success.
      function c_fflush(stream) bind(C, name="fflush") result(status)
         import :: c_int, c_ptr
         type(c_ptr), value :: stream  !! the stream
         integer(c_int) :: status
      end function c_fflush
      !> fclose(3): 0 on success.
      function c_fclose(stream) bind(C, name="fclose") result(status)
         import :: c_int, c_ptr
         type(c_ptr), value :: stream  !! the stream
         integer(c_int) :: status
      end function c_fclose
      !> fileno(3): the descriptor of a stream.
      function c_fileno(stream) bind(C, name="fileno") result(fd)
         import :: c_int, c_ptr
         type(c_ptr), value :: stream  !! the stream
         integer(c_int) :: fd
      end function c_fileno
      !> fsync(2): 0 once the file's data are on the disk.
      function c_fsync(fd) bind(C, name="fsync") result(status)
         import :: c_int
         integer(c_int), value :: fd  !! the descriptor
         integer(c_int) :: status
      end function c_fsync
      !> signal(2): the previous handler.
      function c_signal(signum, handler) bind(C, name="signal") result(previous)
         import :: c_int, c_funptr
         integer(c_int), value :: signum     !! the signal number
         type(c_funptr), value :: handler    !! a bind(C) handler, or SIG_IGN
         type(c_funptr) :: previous
      end function c_signal
      !> _exit(2) (async-signal-safe): end the process at once.
      subroutine c_exit_now(status) bind(C, name="_exit")
         import :: c_int
         integer(c_int), value :: status  !! the exit status
      end subroutine c_exit_now
      !> isatty(3): 1 when the descriptor is a terminal.
      function c_isatty(fd) bind(C, name="isatty") result(yes)
         import :: c_int
         integer(c_int), value :: fd  !! the descriptor
         integer(c_int) :: yes
      end function c_isatty
      !> mkdir(2): 0 on success (mode_t is an unsigned int on Linux).
      function c_mkdir(path, mode) bind(C, name="mkdir") result(status)
         import :: c_char, c_int
         character(kind=c_char), intent(in) :: path(*)  !! NUL-terminated path of the new directory
         integer(c_int), value :: mode                  !! permissions before the umask
         integer(c_int) :: status
      end function c_mkdir
      !> statvfs(3): 0 on success.
      function c_statvfs(path, info) bind(C, name="statvfs") result(status)
         import :: c_char, c_int, statvfs_t
         character(kind=c_char), intent(in) :: path(*)  !! NUL-terminated path on the file system
         type(statvfs_t), intent(out) :: info           !! the file system's counts
         integer(c_int) :: status
      end function c_statvfs
      function c_errno_location() bind(C, name="__errno_location") result(where)
         import :: c_ptr
         type(c_ptr) :: where
      end function c_errno_location
      function c_strerror(code) bind(C, name="strerror") result(text)
         import :: c_int, c_ptr
         integer(c_int), value :: code
         type(c_ptr) :: text
      end function c_strerror
   end interface

contains

   !> The message of the current errno ("unknown cause" when errno is 0).
   function errno_text() result(text)
      character(len=:), allocatable :: text
      integer(c_int), pointer :: code
      character(kind=c_char), pointer :: chars(:)
      integer :: n
      call c_f_pointer(c_errno_location(), code)
      if (code == 0) then
         text = "unknown cause"
         return
      end if
      call c_f_pointer(c_strerror(code), chars, [1024])
      n = 0
      do while (n < 1024)
         if (chars(n + 1) == c_null_char) exit
         n = n + 1
      end do
      allocate (character(len=n) :: text)
      text = transfer(chars(:n), text)
   end function errno_text

   !> The current errno (0 after `set_errno(0)` and a call that did not fail).
   integer function errno_value()
      integer(c_int), pointer :: code
      call c_f_pointer(c_errno_location(), code)
      errno_value = int(code)
   end function errno_value

   !> Set errno (to 0 before a call whose failure is then read with `errno_text`).
   subroutine set_errno(value)
      integer, intent(in) :: value  !! the new errno
      integer(c_int), pointer :: code
      call c_f_pointer(c_errno_location(), code)
      code = int(value, c_int)
   end subroutine set_errno

   !> A Fortran string as a NUL-terminated C string.
   pure function c_string(text) result(c)
      character(len=*), intent(in) :: text  !! the string
      character(kind=c_char) :: c(len(text) + 1)
      integer :: i
      do i = 1, len(text)
         c(i) = text(i:i)
      end do
      c(len(text) + 1) = c_null_char
   end function c_string

   !> Delete a file if it exists (no error if it does not).
   subroutine remove_file(path)
      character(len=*), intent(in) :: path  !! the file
      integer(c_int) :: status
      status = c_remove(c_string(path))
   end subroutine remove_file

   !> Whether `path` names an existing file that is neither a regular file nor a directory
   !> (a FIFO, a device, a socket): opening one to read may block forever or never end.
   logical function is_special_file(path)
      character(len=*), intent(in) :: path  !! any path
      type(stat_t) :: info
      integer(c_int), parameter :: type_mask = int(o'170000', c_int), regular = int(o'100000', c_int), &
         directory = int(o'040000', c_int)
      is_special_file = .false.
      if (len(path) == 0) return
      if (c_stat(c_string(path), info) /= 0) return
      is_special_file = iand(info%mode, type_mask) /= regular .and. iand(info%mode, type_mask) /= directory
   end function is_special_file

   !> Take an exclusive advisory lock (flock) on the open stream without waiting; true when
   !> another process holds it (false also where the file system has no locks). The lock
   !> goes with the stream's close or the process's end.
   function try_lock(stream) result(busy)
      type(c_ptr), intent(in) :: stream  !! an open stream
      logical :: busy
      busy = .false.
      call set_errno(0)
      if (c_flock(c_fileno(stream), ior(lock_exclusive, lock_nonblocking)) /= 0) busy = errno_value() == errno_would_block
   end function try_lock

   !> The lock of an open stream, tried without waiting: lock_taken (it was free and this
   !> stream holds it now), lock_busy (another open file holds it) or lock_unknown (the file
   !> system has no locks, or the call failed otherwise).
   integer function lock_state(stream)
      type(c_ptr), intent(in) :: stream  !! an open stream
      call set_errno(0)
      if (c_flock(c_fileno(stream), ior(lock_exclusive, lock_nonblocking)) == 0) then
         lock_state = lock_taken
      else if (errno_value() == errno_would_block) then
         lock_state = lock_busy
      else
         lock_state = lock_unknown
      end if
   end function lock_state

   !> The names in `directory` that begin with `prefix` and have `tail` more bytes, in the
   !> order readdir gives them (none when the directory cannot be read).
   subroutine names_with_prefix(directory, prefix, tail, names)
      character(len=*), intent(in) :: directory  !! the directory
      character(len=*), intent(in) :: prefix  !! the start of the names wanted
      integer, intent(in) :: tail  !! bytes after the prefix
      character(len=:), allocatable, intent(out) :: names(:)  !! the names (without the directory)
      character(len=len(prefix) + tail), allocatable :: found(:), grown(:)
      character(kind=c_char), pointer :: bytes(:)
      type(c_ptr) :: dir, entry
      integer(c_int) :: status
      integer :: n, k, length
      allocate (found(8))
      n = 0
      dir = c_opendir(c_string(directory))
      if (c_associated(dir)) then
         do
            entry = c_readdir(dir)
            if (.not. c_associated(entry)) exit
            call c_f_pointer(entry, bytes, [dirent_name_offset + name_max + 1])
            length = 0
            do k = dirent_name_offset + 1, dirent_name_offset + name_max + 1
               if (bytes(k) == c_null_char) exit
               length = length + 1
            end do
            if (length /= len(prefix) + tail) cycle
            if (any(bytes(dirent_name_offset + 1:dirent_name_offset + len(prefix)) /= transfer(prefix, "a", len(prefix)))) &
               cycle
            if (n == size(found)) then
               allocate (grown(2*n))
               grown(:n) = found
               call move_alloc(grown, found)
            end if
            n = n + 1
            do k = 1, length
               found(n)(k:k) = bytes(dirent_name_offset + k)
            end do
         end do
         status = c_closedir(dir)
      end if
      allocate (character(len=len(prefix) + tail) :: names(n))
      names = found(:n)
   end subroutine names_with_prefix

   !> Whether `path` names an existing directory.
   logical function is_directory(path)
      character(len=*), intent(in) :: path  !! any path
      if (len(path) == 0) then
         is_directory = .false.
         return
      end if
      inquire (file=path//"/.", exist=is_directory)
   end function is_directory
end module hillstab_ffi_libc

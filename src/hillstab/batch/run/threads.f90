!> Where the OpenMP threads of a run live: one thread per CPU, bound, unless the user set
!> OpenMP's own placement (`OMP_PROC_BIND`, `OMP_PLACES` or `GOMP_CPU_AFFINITY`; then
!> nothing is changed here, and `OMP_PROC_BIND=false` keeps the threads free).
!>
!> Why: Linux starts a new thread on the CPU of the thread that created it. When that CPU
!> stays busy (the creator waits for the new thread at the start of the first parallel
!> region, spinning, or goes on computing), the new thread waits for the scheduler's next
!> balancing, up to a few milliseconds later, while the other CPU idles; later regions
!> lose the same time whenever two threads share a CPU. Measured on 2 CPUs (a virtual
!> machine, 21 runs each): the 300 × 300 verdict chart took 12.5–27.6 ms (median 17.8)
!> with free threads and 12.4–13.0 ms (median 12.6) with bound threads; a 2 × 2 chart
!> 6.1–25.4 ms against 2.6–2.8 ms. Binding the threads once, before the first region, is
!> what `OMP_PROC_BIND=true` does.
!>
!> How: the first team is made one thread larger than later teams, so that libgomp counts
!> more threads than CPUs and its waiting threads sleep after a short spin instead of
!> holding the CPU a new thread waits for; in that team, thread t binds itself to the
!> t-th CPU the process may use (the creating thread keeps the CPU it runs on). Nothing is
!> bound when a run uses one thread, when the process may use fewer CPUs than threads
!> (a rank bound by its MPI launcher, a `taskset`), or when the calls fail.
!>
!>```fortran
!> call place_threads()   ! once, before the first parallel region of a run
!>```
module hillstab_batch_run_threads
   use, intrinsic :: iso_c_binding, only: c_int, c_long, c_size_t
   use hillstab_ffi_libc, only: c_sched_getaffinity, c_sched_setaffinity, c_sched_getcpu, cpu_set_words
   !$ use omp_lib, only: omp_get_max_threads, omp_get_thread_num
   implicit none
   private
   public :: place_threads, placement_by_openmp, allowed_cpus, bind_thread

   !> Bytes of a cpu_set_t.
   integer(c_size_t), parameter :: set_bytes = int(8*cpu_set_words, c_size_t)

   !> Whether `place_threads` already ran in this process.
   logical, save :: placement_done = .false.

contains

   !> Bind one thread per CPU (see the module), once per process; `bound` tells whether the
   !> threads were bound by this call.
   subroutine place_threads(bound)
      logical, intent(out), optional :: bound  !! the threads were bound here
      integer, allocatable :: cpus(:)
      integer :: n_threads, k, here
      logical :: done
      done = .false.
      if (present(bound)) bound = .false.
      if (placement_done) return
      placement_done = .true.
      n_threads = 1
      !$ n_threads = omp_get_max_threads()
      if (n_threads < 2 .or. placement_by_openmp()) return
      call allowed_cpus(cpus)
      if (size(cpus) < n_threads) return
      ! the creating thread keeps its CPU: it comes first
      here = c_sched_getcpu()
      k = findloc(cpus, here, dim=1)
      if (k > 1) then
         cpus(k) = cpus(1)
         cpus(1) = here
      end if
      call bind_team(cpus(1:n_threads), done)
      if (present(bound)) bound = done
   end subroutine place_threads

   !> The team of size(cpus) + 1 threads in which thread t binds itself to cpus(t + 1).
   subroutine bind_team(cpus, done)
      integer, intent(in) :: cpus(:)  !! a CPU for each thread of later teams
      logical, intent(out) :: done    !! every thread bound
      integer :: t, failures
      logical :: ok
      failures = 0
      !$omp parallel num_threads(size(cpus) + 1) default(shared) private(t, ok) reduction(+:failures)
      t = 0
      !$ t = omp_get_thread_num()
      if (t < size(cpus)) then
         call bind_thread(cpus(t + 1:t + 1), ok)
         if (.not. ok) failures = failures + 1
      end if
      !$omp end parallel
      done = failures == 0
   end subroutine bind_team

   !> Let the calling thread run on the CPUs `cpus` (numbers from 0) only.
   subroutine bind_thread(cpus, ok)
      integer, intent(in) :: cpus(:)  !! the CPUs
      logical, intent(out) :: ok      !! sched_setaffinity succeeded
      integer(c_long) :: mask(cpu_set_words)
      integer :: k
      mask = 0
      do k = 1, size(cpus)
         mask(cpus(k)/64 + 1) = ibset(mask(cpus(k)/64 + 1), mod(cpus(k), 64))
      end do
      ok = c_sched_setaffinity(0_c_int, set_bytes, mask) == 0
   end subroutine bind_thread

   !> The CPUs the calling thread may run on, in increasing order (none when unknown).
   subroutine allowed_cpus(cpus)
      integer, allocatable, intent(out) :: cpus(:)  !! CPU numbers (from 0), increasing
      integer(c_long) :: mask(cpu_set_words)
      integer :: cpu, n
      if (c_sched_getaffinity(0_c_int, set_bytes, mask) /= 0) then
         allocate (cpus(0))
         return
      end if
      allocate (cpus(sum(popcnt(mask))))
      n = 0
      do cpu = 0, 64*cpu_set_words - 1
         if (btest(mask(cpu/64 + 1), mod(cpu, 64))) then
            n = n + 1
            cpus(n) = cpu
         end if
      end do
   end subroutine allowed_cpus

   !> True when the user chose OpenMP's placement: `OMP_PROC_BIND`, `OMP_PLACES` or
   !> `GOMP_CPU_AFFINITY` is set (to anything).
   logical function placement_by_openmp()
      character(len=*), parameter :: names(3) = [character(len=17) :: "OMP_PROC_BIND", "OMP_PLACES", &
                                                 "GOMP_CPU_AFFINITY"]
      integer :: k, status
      placement_by_openmp = .false.
      do k = 1, size(names)
         call get_environment_variable(trim(names(k)), status=status)
         if (status /= 1) placement_by_openmp = .true.
      end do
   end function placement_by_openmp
end module hillstab_batch_run_threads

!> Work counters shared by the integrators, so that methods can be compared by
!> the work they do (steps, rejections, right-hand-side or Q evaluations).
module hillstab_core_stats
   use hillstab_core_kinds, only: int64
   implicit none
   private
   public :: work_stats_t, add_work

   !> Work done by one computation.
   type :: work_stats_t
      integer(int64) :: n_steps = 0        !! accepted steps (or pieces)
      integer(int64) :: n_rejected = 0     !! rejected steps
      integer(int64) :: n_evaluations = 0  !! evaluations of Q(τ) or of the right-hand side
   end type work_stats_t

contains

   !> total ← total + part.
   pure subroutine add_work(total, part)
      type(work_stats_t), intent(inout) :: total  !! the sum so far
      type(work_stats_t), intent(in) :: part  !! the work to add
      total%n_steps = total%n_steps + part%n_steps
      total%n_rejected = total%n_rejected + part%n_rejected
      total%n_evaluations = total%n_evaluations + part%n_evaluations
   end subroutine add_work
end module hillstab_core_stats

!> How many OpenMP threads a parallel region will use: what the tasks size their buffers
!> and blocks by, and what the drivers of units and the C entry points ask before they
!> start (1 in a build without OpenMP).
module hillstab_core_parallel
   !$ use omp_lib, only: omp_get_max_threads
   implicit none
   private
   public :: max_threads

contains

   !> Number of OpenMP threads a parallel region will use (1 without OpenMP).
   integer function max_threads()
      max_threads = 1
      !$ max_threads = omp_get_max_threads()
   end function max_threads
end module hillstab_core_parallel

!> A program with its own `pi` and `wp` (and `error_t`, `determinant`) that takes the
!> whole umbrella module: none of them clashes with a name `use hillstab` gives, which
!> carry the prefix `hillstab_`. Built and run against an installed copy by
!> config/export/check.sh (make check-install).
module own_names_helpers
   implicit none
   private
   public :: wp, pi, error_t, determinant

   integer, parameter :: wp = selected_real_kind(6)  !! the program's own working precision (single)
   real(wp), parameter :: pi = 3.14159_wp            !! the program's own, shorter pi

   !> the program's own error type
   type :: error_t
      integer :: code = 0  !! its own code
   end type error_t

contains

   !> The program's own determinant of a 2 x 2 matrix.
   pure real(wp) function determinant(a)
      real(wp), intent(in) :: a(2, 2)  !! the matrix
      determinant = a(1, 1)*a(2, 2) - a(1, 2)*a(2, 1)
   end function determinant
end module own_names_helpers

program own_names
   use hillstab
   use own_names_helpers, only: wp, pi, error_t, determinant
   implicit none
   type(trace_t) :: tr
   type(hillstab_error_t), allocatable :: failure
   type(error_t) :: mine
   real(wp) :: circle
   circle = 2*pi
   call monodromy_trace(elastic_model_t(), hill_point_t(2.57_hillstab_wp, 1.29_hillstab_wp, 0.0_hillstab_wp), &
      method_t(hillstab_method_segments, 4096, hillstab_sampling_average), tr, failure)
   if (allocated(failure)) error stop 1
   print '(a,f10.6,a,f8.5,a,i0)', "Fortran, own pi and wp: S at case (c) = ", tr%value, ", own 2 pi = ", &
      circle, ", own kind ", wp
   if (abs(tr%value + 1.6401_hillstab_wp) > 1.0e-3_hillstab_wp) error stop 1
   if (wp == hillstab_wp .or. abs(circle - 6.28318_wp) > 1.0e-4_wp) error stop 1
   if (determinant(reshape([1.0_wp, 0.0_wp, 0.0_wp, 1.0_wp], [2, 2])) /= 1.0_wp .or. mine%code /= 0) error stop 1
   if (abs(hillstab_pi - 3.14159265358979_hillstab_wp) > 1.0e-12_hillstab_wp) error stop 1
end program own_names

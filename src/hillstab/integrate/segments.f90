!> Method `segments`: the monodromy of one period with q replaced by N constant pieces
!> (endpoint, midpoint or exact-average sampling, hillstab_hill_coefficient), the product
!> of their exact transfer matrices (Meissner). Second order in 1/N; N = 2 with
!> endpoint sampling is the paper's eq. (28), whose closed form is method `formula`.
!>
!>```fortran
!> type(trace_t) :: tr
!> type(elastic_model_t) :: elastic
!> tr = trace_segmented(elastic, hill_point_t(3.7_wp, 2.47_wp, 0.0_wp), 256, sampling_average)
!>```
module hillstab_integrate_segments
   use hillstab_core_kinds, only: wp
   use hillstab_hill_model, only: hill_model_t, hill_point_t
   use hillstab_hill_coefficient, only: segment_coefficients
   use hillstab_hill_transfer, only: scaled_matrix_t, scaled_identity, multiply_transfer, trace_t, trace_of
   implicit none
   private
   public :: monodromy_segmented, trace_segmented

contains

   !> Monodromy of the χ equation over one period [0, P] (P = 2 unless the model's period
   !> differs) with q replaced by `n` constant pieces (exact transfer matrix per piece).
   pure function monodromy_segmented(model, point, n, sampling) result(a)
      class(hill_model_t), intent(in) :: model  !! the model
      type(hill_point_t), intent(in) :: point   !! α, β, ε
      integer, intent(in) :: n         !! number of pieces
      integer, intent(in) :: sampling  !! sampling_endpoint | sampling_midpoint | sampling_average
      type(scaled_matrix_t) :: a
      real(wp) :: q(n), h, carry
      integer :: i
      call segment_coefficients(model, point, n, sampling, q)
      h = model%period()/n
      a = scaled_identity()
      carry = 0.0_wp
      do i = 1, n
         ! the log scale summed with compensation (see `multiply_transfer`)
         call multiply_transfer(a, q(i), h, carry)
      end do
      a%log_scale = a%log_scale - carry
   end function monodromy_segmented

   !> Trace of `monodromy_segmented`.
   pure function trace_segmented(model, point, n, sampling) result(tr)
      class(hill_model_t), intent(in) :: model  !! the model
      type(hill_point_t), intent(in) :: point   !! α, β, ε
      integer, intent(in) :: n, sampling  !! number of pieces; sampling_* constant
      type(trace_t) :: tr
      tr = trace_of(monodromy_segmented(model, point, n, sampling))
   end function trace_segmented
end module hillstab_integrate_segments

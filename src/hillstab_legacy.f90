!> Old-style entry points for FORTRAN 77-era callers: implicit-interface-friendly
!> external subroutines with plain DOUBLE PRECISION/INTEGER arguments and an
!> INFO code (0 = success), thin wrappers over the modern API.
!>
!>```fortran
!>       DOUBLE PRECISION S
!>       INTEGER INFO
!>       CALL HSTRACE(1, 3.7D0, 2.47D0, 0.0D0, 2, 256, 3, 1.0D-10, S, INFO)
!>```
module hillstab_legacy
   use hillstab_kinds, only: wp
   use hillstab_error, only: error_t
   use hillstab_coefficient, only: hill_model_t
   use hillstab_transfer, only: trace_t
   use hillstab_floquet, only: floquet_t, floquet_from_trace
   use hillstab_monodromy, only: method_t, monodromy_trace
   implicit none
   private
   public :: hstrace, hsfloq

contains

   !> S (S₁ with damping) for MODEL (1 elastic, 2 mathieu), METHOD (0 auto … 6 gsl),
   !> NSEG pieces with sampling ISAMP (1 endpoint, 2 midpoint, 3 average), tolerance TOL.
   !> INFO = 0 on success, 2 if S overflowed (S = ±huge), else an error code.
   subroutine hstrace(model, alpha, beta, eps, method, nseg, isamp, tol, s, info)
      integer, intent(in) :: model, method, nseg, isamp
      real(wp), intent(in) :: alpha, beta, eps, tol
      real(wp), intent(out) :: s
      integer, intent(out) :: info
      type(trace_t) :: tr
      type(error_t), allocatable :: error
      s = 0.0_wp
      call monodromy_trace(hill_model_t(model, alpha, beta, eps), method_t(method, nseg, isamp, tol), tr, error)
      if (allocated(error)) then
         info = error%code
         return
      end if
      s = tr%value
      info = 0
      if (tr%overflow) info = 2
   end subroutine hstrace

   !> As HSTRACE, plus the Floquet exponent MU of the swing and ISTAB = 1 when stable
   !> (|S₁| < 2 cosh ε), else 0.
   subroutine hsfloq(model, alpha, beta, eps, method, nseg, isamp, tol, s, mu, istab, info)
      integer, intent(in) :: model, method, nseg, isamp
      real(wp), intent(in) :: alpha, beta, eps, tol
      real(wp), intent(out) :: s, mu
      integer, intent(out) :: istab, info
      type(trace_t) :: tr
      type(floquet_t) :: f
      type(error_t), allocatable :: error
      s = 0.0_wp; mu = 0.0_wp; istab = 0
      call monodromy_trace(hill_model_t(model, alpha, beta, eps), method_t(method, nseg, isamp, tol), tr, error)
      if (allocated(error)) then
         info = error%code
         return
      end if
      f = floquet_from_trace(tr, eps)
      s = f%trace%value
      mu = f%exponent
      istab = 0
      if (f%stable) istab = 1
      info = 0
   end subroutine hsfloq
end module hillstab_legacy

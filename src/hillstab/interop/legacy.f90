!> Explicit interfaces of the old-style entry points HSTRACE, HSFLOQ and HSERRM for
!> modern callers (`use hillstab_interop_legacy`). The routines themselves are external
!> procedures (src/hillstab/interop/legacy_external.f90, link symbols `hstrace_`,
!> `hsfloq_`, `hserrm_`), so FORTRAN 77 code calls them with no `USE`, through an
!> implicit interface, the way it calls LAPACK:
!>
!>```fortran
!>       DOUBLE PRECISION S
!>       INTEGER INFO
!>       CALL HSTRACE(1, 3.7D0, 2.47D0, 0.0D0, 2, 256, 3, 1.0D-10, S, INFO)
!>```
!>
!> Every argument and code is documented in the guide page *Using the library* (*Old-style entry points*).
module hillstab_interop_legacy
   use hillstab_core_kinds, only: wp
   implicit none
   private
   public :: hstrace, hsfloq, hserrm

   interface
      !> Trace S of the one-period monodromy (S₁ of the χ equation (47) when EPS > 0).
      subroutine hstrace(model, alpha, beta, eps, method, nseg, isamp, tol, s, info)
         import :: wp
         integer, intent(in) :: model   !! 1 elastic (eq. 25), 2 Mathieu, 3 Meissner
         real(wp), intent(in) :: alpha  !! α (elastic: 0 ≤ α < π²); ν for Mathieu
         real(wp), intent(in) :: beta   !! β
         real(wp), intent(in) :: eps    !! damping ε ≥ 0 of eq. (46)
         integer, intent(in) :: method  !! 0 auto, 1 formula, 2 segments, 3 magnus4, 4 magnus6, 5 rk, 6 gsl
         integer, intent(in) :: nseg    !! pieces per period (METHOD = 2), ≥ 1
         integer, intent(in) :: isamp   !! sampling of the pieces (METHOD = 2): 1 endpoint, 2 midpoint, 3 average
         real(wp), intent(in) :: tol    !! target error on S scaled by max(1, |S|) (exact methods), > 0
         real(wp), intent(out) :: s     !! the trace (±HUGE with INFO = 2; best value with INFO = 7)
         integer, intent(out) :: info   !! 0 success, 2 overflow, 7 round-off limited, else an error code
      end subroutine hstrace

      !> As HSTRACE, plus the Floquet exponent and the stability verdict of the swing x.
      subroutine hsfloq(model, alpha, beta, eps, method, nseg, isamp, tol, s, mu, istab, info)
         import :: wp
         integer, intent(in) :: model   !! 1 elastic (eq. 25), 2 Mathieu, 3 Meissner
         real(wp), intent(in) :: alpha  !! α (elastic: 0 ≤ α < π²); ν for Mathieu
         real(wp), intent(in) :: beta   !! β
         real(wp), intent(in) :: eps    !! damping ε ≥ 0 of eq. (46)
         integer, intent(in) :: method  !! 0 auto, 1 formula, 2 segments, 3 magnus4, 4 magnus6, 5 rk, 6 gsl
         integer, intent(in) :: nseg    !! pieces per period (METHOD = 2), ≥ 1
         integer, intent(in) :: isamp   !! sampling of the pieces (METHOD = 2): 1 endpoint, 2 midpoint, 3 average
         real(wp), intent(in) :: tol    !! target error on S scaled by max(1, |S|) (exact methods), > 0
         real(wp), intent(out) :: s     !! the trace, as in HSTRACE
         real(wp), intent(out) :: mu    !! Floquet exponent μ = ln|λ_max|/2 of x per unit τ
         integer, intent(out) :: istab  !! 1 when x is stable (|S| < 2 cosh ε), else 0
         integer, intent(out) :: info   !! 0 success, 2 overflow (as HSTRACE), 7 round-off limited, else an error code
      end subroutine hsfloq

      !> Message of the most recent HSTRACE or HSFLOQ call in this thread (blank after success).
      subroutine hserrm(msg)
         character(len=*), intent(out) :: msg  !! receives the message, cut or blank-padded to its length
      end subroutine hserrm
   end interface
end module hillstab_interop_legacy

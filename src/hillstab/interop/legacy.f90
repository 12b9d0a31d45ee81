!> Explicit interfaces of the old-style entry points HSTRACE, HSFLOQ, HSCHAR and HSERRM for
!> modern callers (`use hillstab_interop_legacy`). The routines themselves are external
!> procedures (src/hillstab/interop/legacy_external.f90, link symbols `hstrace_`,
!> `hsfloq_`, `hschar_`, `hserrm_`), so FORTRAN 77 code calls them with no `USE`, through an
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
   public :: hstrace, hsfloq, hserrm, hschar

   interface
      !> Trace S of the one-period monodromy (S₁ of the χ equation (47) when EPS > 0).
      subroutine hstrace(model, alpha, beta, eps, method, nseg, isamp, tol, s, info)
         import :: wp
         integer, intent(in) :: model   !! 1 elastic, 2 mathieu, 3 meissner, 4 fourier, 5 sampled, 6 modulated, 7 equation (a model that carries data or texts takes them through the C API)
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
         integer, intent(in) :: model   !! 1 elastic, 2 mathieu, 3 meissner, 4 fourier, 5 sampled, 6 modulated, 7 equation (a model that carries data or texts takes them through the C API)
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

      !> The first N transition values of β of each kind at ALPHA (the characteristic values).
      subroutine hschar(model, alpha, n, tol, ldim, nout, beta, iord, kind, errb, info)
         import :: wp
         integer, intent(in) :: model    !! 1 elastic (eq. 25), 2 Mathieu
         real(wp), intent(in) :: alpha   !! α (elastic: 0 ≤ α < π²); ν for Mathieu
         integer, intent(in) :: n        !! values of each kind, ≥ 1
         real(wp), intent(in) :: tol     !! target error of β relative to max(1, |β|), > 0
         integer, intent(in) :: ldim     !! length of BETA, IORD, KIND, ERRB (4N always suffices)
         integer, intent(out) :: nout    !! values returned (0 on failure)
         real(wp), intent(inout) :: beta(ldim)  !! the values, by kind then ascending
         integer, intent(inout) :: iord(ldim)   !! their orders n of a_n, b_n
         integer, intent(inout) :: kind(ldim)   !! 1 a_2m, 2 b_2m, 3 a_2m+1, 4 b_2m+1; 5 periodic, 6 antiperiodic
         real(wp), intent(inout) :: errb(ldim)  !! bound of each value's error
         integer, intent(out) :: info    !! 0 success, else an error code (1 invalid parameter, 6, 7)
      end subroutine hschar

      !> Message of the most recent HSTRACE, HSFLOQ or HSCHAR call in this thread (blank after success).
      subroutine hserrm(msg)
         character(len=*), intent(out) :: msg  !! receives the message, cut or blank-padded to its length
      end subroutine hserrm
   end interface
end module hillstab_interop_legacy

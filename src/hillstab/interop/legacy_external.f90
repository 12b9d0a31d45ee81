!> The old-style entry points as external procedures (no module): FORTRAN 77 code
!> calls them through an implicit interface and links the symbols `hstrace_`,
!> `hsfloq_` and `hserrm_`. Modern callers get their explicit interfaces from
!> `module hillstab_interop_legacy`. Plain DOUBLE PRECISION / INTEGER / CHARACTER arguments,
!> an INFO code; the guide page *Using the library* documents every argument and code, LAPACK-style.

!> Trace S of the one-period monodromy (S₁ of the χ equation (47) when EPS > 0) for
!> MODEL (1 elastic, 2 Mathieu) by METHOD (0 auto, 1 formula, 2 segments, 3 magnus4,
!> 4 magnus6, 5 rk, 6 gsl); NSEG pieces with sampling ISAMP (1 endpoint, 2 midpoint,
!> 3 average) for METHOD = 2; tolerance TOL for the exact methods.
!> INFO = 0 success; 2 S overflowed (S = ±HUGE); 7 TOL below the round-off level (S is
!> the best value); otherwise an error code (1 invalid parameter, 3 integration failure,
!> 6 singular problem) and S = 0. HSERRM gives the message.
subroutine hstrace(model, alpha, beta, eps, method, nseg, isamp, tol, s, info)
   use hillstab_core_kinds, only: wp
   use hillstab_interop_legacy, only: hsfloq
   implicit none
   integer, intent(in) :: model   !! 1 elastic (eq. 25), 2 Mathieu
   real(wp), intent(in) :: alpha  !! α (elastic: 0 ≤ α < π²); ν for Mathieu
   real(wp), intent(in) :: beta   !! β
   real(wp), intent(in) :: eps    !! damping ε ≥ 0 of eq. (46)
   integer, intent(in) :: method  !! 0 auto, 1 formula, 2 segments, 3 magnus4, 4 magnus6, 5 rk, 6 gsl
   integer, intent(in) :: nseg    !! pieces per period (METHOD = 2), ≥ 1
   integer, intent(in) :: isamp   !! sampling of the pieces (METHOD = 2): 1 endpoint, 2 midpoint, 3 average
   real(wp), intent(in) :: tol    !! target error on S scaled by max(1, |S|) (exact methods), > 0
   real(wp), intent(out) :: s     !! the trace (±HUGE with INFO = 2; best value with INFO = 7)
   integer, intent(out) :: info   !! 0 success, 2 overflow, 7 round-off limited, else an error code
   real(wp) :: mu
   integer :: istab
   ! HSFLOQ computes the same S and INFO; the Floquet data it adds are not returned
   call hsfloq(model, alpha, beta, eps, method, nseg, isamp, tol, s, mu, istab, info)
end subroutine hstrace

!> As HSTRACE, plus the Floquet exponent MU of the swing x per unit τ and ISTAB = 1
!> when x is stable (|S₁| < 2 cosh ε), else 0. INFO as HSTRACE: 0 success, 2 S
!> overflowed (S = ±HUGE, MU stays finite), 7 round-off limited (best values returned),
!> otherwise an error code with S = MU = 0, ISTAB = 0.
subroutine hsfloq(model, alpha, beta, eps, method, nseg, isamp, tol, s, mu, istab, info)
   use hillstab_core_kinds, only: wp
   use hillstab_core_error, only: error_t, err_accuracy
   use hillstab_hill_coefficient, only: hill_model_t
   use hillstab_hill_transfer, only: trace_t
   use hillstab_hill_floquet, only: floquet_t, floquet_from_trace
   use hillstab_integrate_monodromy, only: method_t, monodromy_trace
   use hillstab_interop_outcome, only: record_outcome
   implicit none
   integer, intent(in) :: model   !! 1 elastic (eq. 25), 2 Mathieu
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
   type(trace_t) :: tr
   type(floquet_t) :: f
   type(error_t), allocatable :: error
   s = 0.0_wp; mu = 0.0_wp; istab = 0
   call monodromy_trace(hill_model_t(model, alpha, beta, eps), method_t(method, nseg, isamp, tol), tr, error)
   call record_outcome(error)
   info = 0
   if (allocated(error)) then
      info = error%code
      if (error%code /= err_accuracy) return
   end if
   f = floquet_from_trace(tr, eps)
   s = f%trace%value
   mu = f%exponent + 0.0_wp   ! -epsilon/2 of a stable undamped swing is -0.0: written as +0.0
   if (f%stable) istab = 1
   if (info == 0 .and. tr%overflow) info = 2  ! S is +-HUGE
end subroutine hsfloq

!> MSG receives the message of the most recent HSTRACE or HSFLOQ call in this thread
!> (blank when that call succeeded), cut or blank-padded to the length of MSG.
subroutine hserrm(msg)
   use hillstab_interop_outcome, only: get_last_error
   implicit none
   character(len=*), intent(out) :: msg  !! receives the message
   character(len=:), allocatable :: text
   integer :: code
   call get_last_error(code, text)
   msg = text
end subroutine hserrm

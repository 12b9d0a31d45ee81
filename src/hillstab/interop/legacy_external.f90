!> The old-style entry points as external procedures (no module): FORTRAN 77 code
!> calls them through an implicit interface and links the symbols `hstrace_`,
!> `hsfloq_`, `hschar_` and `hserrm_`. Modern callers get their explicit interfaces from
!> `module hillstab_interop_legacy`. Plain DOUBLE PRECISION / INTEGER / CHARACTER arguments,
!> an INFO code; the guide page *Using the library* documents every argument and code, LAPACK-style.

!> Trace S of the one-period monodromy (S₁ of the χ equation (47) when EPS > 0) for
!> MODEL by METHOD (their codes at the arguments below: HILLSTAB_MODEL_*, HILLSTAB_METHOD_* of
!> the C header); NSEG pieces with sampling ISAMP (1 endpoint, 2 midpoint,
!> 3 average) for METHOD = 2; tolerance TOL for the exact methods.
!> INFO = 0 success; 2 S overflowed (S = ±HUGE); 7 TOL below the round-off level (S is
!> the best value); otherwise an error code (1 invalid parameter, 3 integration failure,
!> 6 singular problem) and S = 0. HSERRM gives the message.
subroutine hstrace(model, alpha, beta, eps, method, nseg, isamp, tol, s, info)
   use hillstab_core_kinds, only: wp
   use hillstab_interop_legacy, only: hsfloq
   implicit none
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
   use hillstab_hill_model, only: hill_model_t, hill_point_t
   use hillstab_hill_models, only: model_from_code
   use hillstab_hill_transfer, only: trace_t
   use hillstab_hill_floquet, only: floquet_t, floquet_from_trace
   use hillstab_integrate_monodromy, only: method_t, monodromy_trace
   use hillstab_interop_outcome, only: record_outcome
   implicit none
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
   type(trace_t) :: tr
   type(floquet_t) :: f
   type(error_t), allocatable :: error
   class(hill_model_t), allocatable :: q_model
   s = 0.0_wp; mu = 0.0_wp; istab = 0
   call model_from_code(model, q_model, error)
   if (.not. allocated(error)) call monodromy_trace(q_model, hill_point_t(alpha, beta, eps), &
      method_t(method, nseg, isamp, tol), tr, error)
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

!> The first N transition values of β of each kind at ALPHA for MODEL (1 elastic, 2 Mathieu:
!> Mathieu's a_n(q), b_n(q) are 4β/π² at ALPHA = ν = π²q/2), converged to TOL·max(1, |β|):
!> NOUT values in BETA, their orders in IORD (n of a_n, b_n), their kinds in KIND (1 periodic
!> even a_0, a_2, …; 2 periodic odd b_2, b_4, …; 3 antiperiodic even a_1, a_3, …; 4
!> antiperiodic odd b_1, b_3, …; 5 periodic and 6 antiperiodic where Q is not even) and the
!> bounds of their errors in ERRB, by kind then ascending; LDIM ≥ NOUT (4N always suffices).
!> INFO = 0 success; otherwise an error code (1 invalid parameter: N < 1, TOL ≤ 0, ALPHA
!> outside the model's domain, LDIM too small; 6 eigensolver failure; 7 not converged),
!> NOUT = 0 and the arrays untouched. HSERRM gives the message.
subroutine hschar(model, alpha, n, tol, ldim, nout, beta, iord, kind, errb, info)
   use hillstab_core_kinds, only: wp
   use hillstab_core_error, only: error_t, set_error, err_invalid_parameter
   use hillstab_core_text, only: integer_text
   use hillstab_hill_model, only: hill_model_t
   use hillstab_hill_models, only: model_from_code
   use hillstab_curves_hill_method, only: hill_boundary_t
   use hillstab_curves_characteristic, only: characteristic_values
   use hillstab_interop_outcome, only: record_outcome
   implicit none
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
   class(hill_model_t), allocatable :: q_model
   type(hill_boundary_t), allocatable :: values(:)
   type(error_t), allocatable :: error
   integer :: i
   nout = 0
   call model_from_code(model, q_model, error)
   if (.not. allocated(error)) call characteristic_values(q_model, alpha, n, values, error, tol)
   if (.not. allocated(error)) then
      if (size(values) > ldim) call set_error(error, err_invalid_parameter, "HSCHAR: LDIM = "// &
         integer_text(ldim)//" < the "//integer_text(size(values))//" values")
   end if
   call record_outcome(error)
   info = 0
   if (allocated(error)) then
      info = error%code
      return
   end if
   do i = 1, size(values)
      beta(i) = values(i)%beta
      iord(i) = values(i)%order
      kind(i) = values(i)%block
      errb(i) = values(i)%error_bound
   end do
   nout = size(values)
end subroutine hschar

!> MSG receives the message of the most recent HSTRACE, HSFLOQ or HSCHAR call in this thread
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

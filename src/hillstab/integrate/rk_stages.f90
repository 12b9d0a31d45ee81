!> The system a Runge–Kutta integration steps, and what hillstab_integrate_rk does with
!> it at every step: the stage workspace (`rk_stages_t`), one trial step of each embedded
!> pair (their tableaux in hillstab_integrate_rk_tableaux), f at the new point, the pairs'
!> own continuous extensions and the accepted step's cubic Hermite part.
!>
!> The system is an extension of the abstract type `rk_system_t`: its components carry
!> the parameters, its deferred binding `rhs` computes f, and its binding `observe`
!> (a no-op unless overridden) sees the initial point and every accepted step with its
!> continuous extension (`rk_step_t`) and may stop the integration. No procedure is passed
!> as an argument, so callers need no internal procedures (gfortran would build
!> trampolines for those and the program would need an executable stack).
!>
!> The kernels are the integrator's inner loop: module procedures with explicit-shape
!> arrays (no descriptors, no host association), one per pair (`rk_trial_step` chooses);
!> the driver hands them the workspace and the step record as two arguments (passing
!> the arrays and the outputs one by one cost DOPRI5 6 % more instructions per step). A
!> new pair is its kernel here, its tableau and its row of `rk_pairs` in
!> hillstab_integrate_rk_tableaux. (A system and its integration: the example of
!> hillstab_integrate_rk.)
!>
!>```fortran
!> type(rk_stages_t), target :: w
!> call rk_stages_start(w, rk_dop853, 4, 16, [1.0e-10_wp, 1.0e-10_wp, 1.0e-10_wp, 1.0e-10_wp], 1.0e-10_wp)
!>```
module hillstab_integrate_rk_stages
   use hillstab_core_kinds, only: wp, int64
   use hillstab_integrate_rk_tableaux, only: rk_dopri5, rk_dop853, rk_pd87, rk_vern98, dopri5, dop853, pd87, vern98
   implicit none
   private
   public :: rk_system_t, rk_rhs, rk_observe, rk_step_t, stage_view_t, stage_views_t
   public :: rk_stages_t, rk_stages_start, rk_trial_step, rk_evaluate, rk_evaluate_new_point, rk_dense_extension, &
      rk_accept_step

   !> One accepted step as handed to an observer: the interval [t_old, t], the state at
   !> t and the coefficients of the continuous extension on that interval. The
   !> interpolant is of order `dense_order`: 4 (DOPRI5), 7 (DOP853 with dense output),
   !> or 3 (DOP853 without, PD87, VERN98: the cubic Hermite interpolant from the end
   !> values and slopes).
   type :: rk_step_t
      integer :: method = rk_dop853  !! the pair that made the step (rk_dopri5, rk_dop853, rk_pd87, rk_vern98)
      integer(int64) :: index = 0        !! number of this accepted step (0: the initial point)
      real(wp) :: t_old = 0.0_wp         !! start of the step
      real(wp) :: t = 0.0_wp             !! end of the step
      real(wp) :: h = 0.0_wp             !! t − t_old
      integer :: dense_order = 0         !! order of the continuous extension (0: none yet)
      real(wp), allocatable :: y(:)      !! state at t
      real(wp), allocatable :: dense(:, :)  !! (n, 0:7) interpolation coefficients
   end type rk_step_t

   !> A system y' = f(t, y) with its data. Extend it, put the parameters in components,
   !> implement `rhs`; override `observe` to watch (or stop) the integration.
   type, abstract :: rk_system_t
   contains
      !> f(t, y)
      procedure(rk_rhs), deferred :: rhs
      !> Called after the initial point and after every accepted step (default: nothing)
      procedure :: observe => rk_observe
   end type rk_system_t

   abstract interface
      !> Right-hand side dydt = f(t, y) of the system.
      subroutine rk_rhs(self, t, y, dydt)
         import :: rk_system_t, wp
         class(rk_system_t), intent(inout) :: self  !! the system and its data
         real(wp), intent(in) :: t        !! independent variable
         real(wp), intent(in) :: y(:)     !! state
         real(wp), intent(out) :: dydt(:) !! derivative, same size as y
      end subroutine rk_rhs
   end interface

   !> A view of one stage vector (a column of the stage array, or the trial state).
   type :: stage_view_t
      real(wp), pointer, contiguous :: v(:) => null()  !! the vector
   end type stage_view_t

   !> Pointer views of the trial state, the new state and the stage derivatives, set
   !> once per integration: handing these to `rhs` passes an existing array descriptor,
   !> where an array section (k(:, j)) would build a fresh one on every evaluation.
   type :: stage_views_t
      type(stage_view_t) :: y_stage, y_new  !! the trial state of a stage; the state at the end of the step
      type(stage_view_t) :: f(17)           !! the columns of the stage array
   end type stage_views_t

   !> The stage workspace of one integration: what the kernels read and write per step.
   type :: rk_stages_t
      integer :: method = rk_dop853  !! the pair
      integer :: n = 0               !! components of the state
      real(wp) :: rtol = 0.0_wp      !! relative tolerance
      real(wp), allocatable :: atol(:)     !! absolute tolerance of each component
      real(wp), allocatable :: k(:, :)     !! stage derivatives (column 1: f at the start of the step)
      real(wp), allocatable :: y_stage(:)  !! the trial state of a stage
      real(wp), allocatable :: y_new(:)    !! the state at the end of the trial step
      type(stage_views_t) :: views   !! pointer views of y_stage, y_new and the columns of k
      logical :: finite = .true.     !! the last evaluation of f was finite
      integer(int64) :: n_evaluations = 0  !! evaluations of f
   end type rk_stages_t

contains

   !> Default observer: does nothing. Overrides are called after the initial point and
   !> after every accepted step; setting `stop` ends the integration there
   !> (rk_integrate then returns t = step%t, no error).
   subroutine rk_observe(self, step, stop)
      class(rk_system_t), intent(inout) :: self  !! the system and its data
      type(rk_step_t), intent(in) :: step       !! the step just accepted (index 0: initial point)
      logical, intent(inout) :: stop            !! set .true. to stop after this step
   end subroutine rk_observe

   !> The workspace of an integration by the pair `method` of an n-component system:
   !> the stage array with its pointer views (`w` must be a target that stays in place).
   subroutine rk_stages_start(w, method, n, columns, atol, rtol)
      type(rk_stages_t), intent(inout), target :: w  !! the workspace, (re)allocated
      integer, intent(in) :: method   !! rk_dopri5, rk_dop853, rk_pd87 or rk_vern98
      integer, intent(in) :: n        !! number of components
      integer, intent(in) :: columns  !! columns of the stage array the pair needs
      real(wp), intent(in) :: atol(n) !! absolute tolerances
      real(wp), intent(in) :: rtol    !! relative tolerance
      integer :: stage
      w%method = method
      w%n = n
      w%atol = atol
      w%rtol = rtol
      w%finite = .true.
      w%n_evaluations = 0
      if (allocated(w%k)) deallocate (w%k)
      if (allocated(w%y_stage)) deallocate (w%y_stage)
      if (allocated(w%y_new)) deallocate (w%y_new)
      allocate (w%k(n, columns), w%y_new(n), w%y_stage(n))
      w%views%y_stage%v => w%y_stage
      w%views%y_new%v => w%y_new
      do stage = 1, columns
         w%views%f(stage)%v => w%k(:, stage)
      end do
   end subroutine rk_stages_start

   !> One trial step of size hh from the last accepted point (step%t, step%y) by the
   !> workspace's pair: the stages into w%k, the new state into w%y_new and, with
   !> `with_error`, Hairer's scaled error norm into err; w%finite is false as soon as a
   !> derivative is not finite.
   subroutine rk_trial_step(w, system, step, hh, with_error, err)
      type(rk_stages_t), intent(inout), target :: w  !! the workspace (column 1 of w%k: f at step%t)
      class(rk_system_t), intent(inout) :: system    !! the system
      type(rk_step_t), intent(in) :: step            !! the last accepted step: where the trial starts
      real(wp), intent(in) :: hh                     !! size of the step
      logical, intent(in) :: with_error              !! compute the error norm
      real(wp), intent(out) :: err                   !! Hairer's scaled error norm (0 without with_error)
      associate (tau => step%t, y0 => step%y)
      select case (w%method)
      case (rk_dopri5)
         call dopri5_kernel(system, w%n, tau, hh, y0, w%k, w%y_stage, w%y_new, w%views, w%atol, w%rtol, &
                            with_error, err, w%finite, w%n_evaluations)
      case (rk_pd87)
         call pd87_kernel(system, w%n, tau, hh, y0, w%k, w%y_stage, w%y_new, w%views, w%atol, w%rtol, &
                          with_error, err, w%finite, w%n_evaluations)
      case (rk_vern98)
         call vern98_kernel(system, w%n, tau, hh, y0, w%k, w%y_stage, w%y_new, w%views, w%atol, w%rtol, &
                            with_error, err, w%finite, w%n_evaluations)
      case default
         call dop853_kernel(system, w%n, tau, hh, y0, w%k, w%y_stage, w%y_new, w%views, w%atol, w%rtol, &
                            with_error, err, w%finite, w%n_evaluations)
      end select
      end associate
   end subroutine rk_trial_step

   !> dydt = f(tau, state), counted, with the finiteness check of the kernels (w%finite).
   subroutine rk_evaluate(w, system, tau, state, dydt)
      type(rk_stages_t), intent(inout), target :: w  !! the workspace (its counter and flag)
      class(rk_system_t), intent(inout) :: system    !! the system
      real(wp), intent(in) :: tau                    !! where f is evaluated
      real(wp), intent(in) :: state(:)               !! the state there
      real(wp), intent(out) :: dydt(:)               !! f(tau, state)
      call system%rhs(tau, state, dydt)
      if (stage_failed(w%n, dydt, w%finite, w%n_evaluations)) return
   end subroutine rk_evaluate

   !> f at the new point of a trial step (w%y_new at t_new) into column `column` of the stages.
   subroutine rk_evaluate_new_point(w, system, t_new, column)
      type(rk_stages_t), intent(inout), target :: w  !! the workspace
      class(rk_system_t), intent(inout) :: system    !! the system
      real(wp), intent(in) :: t_new                  !! the end of the step
      integer, intent(in) :: column                  !! the column that receives f
      call system%rhs(t_new, w%views%y_new%v, w%views%f(column)%v)
      if (stage_failed(w%n, w%k(:, column), w%finite, w%n_evaluations)) return
   end subroutine rk_evaluate_new_point

   !> DOP853's 7th-order continuous extension of the trial step of size hh from (step%t,
   !> step%y) into step%dense(:, 4:7) (three more stages; `rk_accept_step` then adds the
   !> Hermite part). DOPRI5's extension is built by `rk_accept_step`; the other pairs have none.
   subroutine rk_dense_extension(w, system, step, hh)
      type(rk_stages_t), intent(inout), target :: w  !! the workspace, with the trial step's stages
      class(rk_system_t), intent(inout) :: system    !! the system
      type(rk_step_t), intent(inout) :: step         !! the last accepted step; its dense coefficients
      real(wp), intent(in) :: hh                     !! size of the trial step
      if (w%method == rk_dop853) call dop853_dense_kernel(system, w%n, step%t, hh, step%y, w%k, w%y_stage, w%views, &
                                                          step%dense, w%finite, w%n_evaluations)
   end subroutine rk_dense_extension

   !> Accept the trial step as the step from step%t to t_new: the cubic Hermite part of the
   !> continuous extension shared by all four pairs (Hairer's CONT(1..4)) into
   !> step%dense(:, 0:3) (for DOPRI5 also Shampine's term h·Σ d_i k_i into dense(:, 4), in
   !> the same loop), step%y ← w%y_new, column 1 of the stages ← column `new_column` (f at
   !> the new point, the first stage of the next step), and the step's times and index.
   subroutine rk_accept_step(w, step, t_new, new_column)
      type(rk_stages_t), intent(inout), target :: w  !! the workspace
      type(rk_step_t), intent(inout) :: step         !! the step record, advanced
      real(wp), intent(in) :: t_new                  !! the end of the step
      integer, intent(in) :: new_column              !! the column holding f at the new point
      real(wp) :: h_step
      h_step = t_new - step%t
      if (w%method == rk_dopri5) then
         call dopri5_accept_kernel(w%n, h_step, w%y_new, w%k, step%y, step%dense)
         step%dense_order = 4
      else
         call hermite_part(w%n, h_step, w%y_new, w%k, new_column, step%y, step%dense)
         step%dense_order = 3
      end if
      step%t_old = step%t
      step%t = t_new
      step%h = h_step
      step%index = step%index + 1
   end subroutine rk_accept_step

   !> The cubic Hermite part (see `rk_accept_step`) with explicit-shape arrays.
   subroutine hermite_part(n, h_step, y_new, k, j_new, y, dense)
      integer, intent(in) :: n, j_new
      real(wp), intent(in) :: h_step, y_new(n)
      real(wp), intent(inout) :: k(n, *), y(n), dense(n, 0:7)
      real(wp) :: d1, d2
      integer :: i
      !GCC$ novector
      do i = 1, n
         d1 = y_new(i) - y(i)
         d2 = h_step*k(i, 1) - d1
         dense(i, 0) = y(i)
         dense(i, 1) = d1
         dense(i, 2) = d2
         dense(i, 3) = d1 - h_step*k(i, j_new) - d2
         y(i) = y_new(i)
         k(i, 1) = k(i, j_new)
      end do
   end subroutine hermite_part


   !> `hermite_part` for DOPRI5, with Shampine's 4th-order term h·Σ d_i k_i into dense(:, 4)
   !> computed first in each component (it needs f at the old point, column 1); f at the
   !> new point is column 7 (FSAL).
   subroutine dopri5_accept_kernel(n, h_step, y_new, k, y, dense)
      integer, intent(in) :: n
      real(wp), intent(in) :: h_step, y_new(n)
      real(wp), intent(inout) :: k(n, *), y(n), dense(n, 0:7)
      real(wp) :: d1, d2
      integer :: i
      !GCC$ novector
      do i = 1, n
         dense(i, 4) = h_step*(dopri5%d1*k(i, 1) + dopri5%d3*k(i, 3) + dopri5%d4*k(i, 4) + dopri5%d5*k(i, 5) &
                               + dopri5%d6*k(i, 6) + dopri5%d7*k(i, 7))
         d1 = y_new(i) - y(i)
         d2 = h_step*k(i, 1) - d1
         dense(i, 0) = y(i)
         dense(i, 1) = d1
         dense(i, 2) = d2
         dense(i, 3) = d1 - h_step*k(i, 7) - d2
         y(i) = y_new(i)
         k(i, 1) = k(i, 7)
      end do
   end subroutine dopri5_accept_kernel
   !> DOP853's 7th-order continuous extension: three more stages (14–16) and the
   !> coefficients d4..d7 of CONTD8, into dense(:, 4:7). Uses the stages of the step from
   !> (tau, y0) with size hh; k(:, 13) holds f at the new point. `finite` is false as soon
   !> as a derivative is not finite.
   subroutine dop853_dense_kernel(system, n, tau, hh, y0, k, y_stage, views, dense, finite, n_evaluations)
      class(rk_system_t), intent(inout) :: system  !! the system
      integer, intent(in) :: n                      !! number of components
      real(wp), intent(in) :: tau, hh               !! start and size of the step
      real(wp), intent(in) :: y0(n)                 !! state at tau
      real(wp), intent(inout), target :: k(n, *)    !! the step's stages; columns 14–16 computed here
      real(wp), intent(out), target :: y_stage(n)   !! work: the state of a stage
      type(stage_views_t), intent(in) :: views      !! the same y_stage and columns of k
      real(wp), intent(inout) :: dense(n, 0:7)      !! interpolation coefficients
      logical, intent(out) :: finite                !! every derivative was finite
      integer(int64), intent(inout) :: n_evaluations  !! evaluation counter
      dense(:, 4) = dop853%d41*k(:, 1) + dop853%d46*k(:, 6) + dop853%d47*k(:, 7) + dop853%d48*k(:, 8) &
                    + dop853%d49*k(:, 9) + dop853%d410*k(:, 10) + dop853%d411*k(:, 11) + dop853%d412*k(:, 12)
      dense(:, 5) = dop853%d51*k(:, 1) + dop853%d56*k(:, 6) + dop853%d57*k(:, 7) + dop853%d58*k(:, 8) &
                    + dop853%d59*k(:, 9) + dop853%d510*k(:, 10) + dop853%d511*k(:, 11) + dop853%d512*k(:, 12)
      dense(:, 6) = dop853%d61*k(:, 1) + dop853%d66*k(:, 6) + dop853%d67*k(:, 7) + dop853%d68*k(:, 8) &
                    + dop853%d69*k(:, 9) + dop853%d610*k(:, 10) + dop853%d611*k(:, 11) + dop853%d612*k(:, 12)
      dense(:, 7) = dop853%d71*k(:, 1) + dop853%d76*k(:, 6) + dop853%d77*k(:, 7) + dop853%d78*k(:, 8) &
                    + dop853%d79*k(:, 9) + dop853%d710*k(:, 10) + dop853%d711*k(:, 11) + dop853%d712*k(:, 12)
      y_stage(:) = y0 + hh*(dop853%a141*k(:, 1) + dop853%a147*k(:, 7) + dop853%a148*k(:, 8) + dop853%a149*k(:, 9) &
                            + dop853%a1410*k(:, 10) + dop853%a1411*k(:, 11) + dop853%a1412*k(:, 12) &
                            + dop853%a1413*k(:, 13))
      call system%rhs(tau + dop853%c14*hh, views%y_stage%v, views%f(14)%v)
      if (stage_failed(n, k(:, 14), finite, n_evaluations)) return
      y_stage(:) = y0 + hh*(dop853%a151*k(:, 1) + dop853%a156*k(:, 6) + dop853%a157*k(:, 7) + dop853%a158*k(:, 8) &
                            + dop853%a1511*k(:, 11) + dop853%a1512*k(:, 12) + dop853%a1513*k(:, 13) &
                            + dop853%a1514*k(:, 14))
      call system%rhs(tau + dop853%c15*hh, views%y_stage%v, views%f(15)%v)
      if (stage_failed(n, k(:, 15), finite, n_evaluations)) return
      y_stage(:) = y0 + hh*(dop853%a161*k(:, 1) + dop853%a166*k(:, 6) + dop853%a167*k(:, 7) + dop853%a168*k(:, 8) &
                            + dop853%a169*k(:, 9) + dop853%a1613*k(:, 13) + dop853%a1614*k(:, 14) &
                            + dop853%a1615*k(:, 15))
      call system%rhs(tau + dop853%c16*hh, views%y_stage%v, views%f(16)%v)
      if (stage_failed(n, k(:, 16), finite, n_evaluations)) return
      dense(:, 4) = hh*(dense(:, 4) + dop853%d413*k(:, 13) + dop853%d414*k(:, 14) + dop853%d415*k(:, 15) &
                        + dop853%d416*k(:, 16))
      dense(:, 5) = hh*(dense(:, 5) + dop853%d513*k(:, 13) + dop853%d514*k(:, 14) + dop853%d515*k(:, 15) &
                        + dop853%d516*k(:, 16))
      dense(:, 6) = hh*(dense(:, 6) + dop853%d613*k(:, 13) + dop853%d614*k(:, 14) + dop853%d615*k(:, 15) &
                        + dop853%d616*k(:, 16))
      dense(:, 7) = hh*(dense(:, 7) + dop853%d713*k(:, 13) + dop853%d714*k(:, 14) + dop853%d715*k(:, 15) &
                        + dop853%d716*k(:, 16))
   end subroutine dop853_dense_kernel

   ! The stage loops below are written as scalar loops (`!GCC$ novector`): the right-hand
   ! side stores its result component by component, and a vector load of those components
   ! right after cannot be served from the store buffer (store-to-load forwarding fails),
   ! which stalled every stage for longer than its arithmetic takes on the small systems
   ! hillstab integrates (4 to 20 components). Measured on the pendulum (4 components):
   ! 35 → 28 ns per DOP853 evaluation (after the pointer views, 40 → 35).

   !> One trial step of size hh from (tau, y0): the stages into k, the new state into y_new
   !> and, with `with_error`, Hairer's scaled error norm. Module level with explicit-shape
   !> arrays (no host association, no descriptors) because this is the integrator's inner
   !> loop; `finite` is false as soon as a derivative is not finite (nothing more is done).
   subroutine dopri5_kernel(system, n, tau, hh, y0, k, y_stage, y_new, views, atol, rtol, with_error, err, finite, &
                            n_evaluations)
      class(rk_system_t), intent(inout) :: system
      integer, intent(in) :: n
      real(wp), intent(in) :: tau, hh, y0(n), atol(n), rtol
      real(wp), intent(inout), target :: k(n, *)
      real(wp), intent(out), target :: y_stage(n), y_new(n)
      type(stage_views_t), intent(in) :: views  !! the same y_stage, y_new and columns of k
      logical, intent(in) :: with_error
      real(wp), intent(out) :: err
      logical, intent(out) :: finite
      integer(int64), intent(inout) :: n_evaluations
      real(wp) :: e
      integer :: i
      err = 0.0_wp
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(dopri5%a21*k(i, 1))
      end do
      call system%rhs(tau + dopri5%c2*hh, views%y_stage%v, views%f(2)%v)
      if (stage_failed(n, k(:, 2), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(dopri5%a31*k(i, 1) + dopri5%a32*k(i, 2))
      end do
      call system%rhs(tau + dopri5%c3*hh, views%y_stage%v, views%f(3)%v)
      if (stage_failed(n, k(:, 3), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(dopri5%a41*k(i, 1) + dopri5%a42*k(i, 2) + dopri5%a43*k(i, 3))
      end do
      call system%rhs(tau + dopri5%c4*hh, views%y_stage%v, views%f(4)%v)
      if (stage_failed(n, k(:, 4), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(dopri5%a51*k(i, 1) + dopri5%a52*k(i, 2) + dopri5%a53*k(i, 3) + dopri5%a54*k(i, 4))
      end do
      call system%rhs(tau + dopri5%c5*hh, views%y_stage%v, views%f(5)%v)
      if (stage_failed(n, k(:, 5), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(dopri5%a61*k(i, 1) + dopri5%a62*k(i, 2) + dopri5%a63*k(i, 3) + dopri5%a64*k(i, 4) &
                                  + dopri5%a65*k(i, 5))
      end do
      call system%rhs(tau + hh, views%y_stage%v, views%f(6)%v)
      if (stage_failed(n, k(:, 6), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_new(i) = y0(i) + hh*(dopri5%a71*k(i, 1) + dopri5%a73*k(i, 3) + dopri5%a74*k(i, 4) + dopri5%a75*k(i, 5) &
                                + dopri5%a76*k(i, 6))
      end do
      ! stage 7 is f at the new point: first stage of the next step (FSAL)
      call system%rhs(tau + hh, views%y_new%v, views%f(7)%v)
      if (stage_failed(n, k(:, 7), finite, n_evaluations)) return
      if (with_error) then
         !GCC$ novector
         do i = 1, n
            e = hh*(dopri5%e1*k(i, 1) + dopri5%e3*k(i, 3) + dopri5%e4*k(i, 4) + dopri5%e5*k(i, 5) &
               + dopri5%e6*k(i, 6) &
                    + dopri5%e7*k(i, 7))/(atol(i) + rtol*max(abs(y0(i)), abs(y_new(i))))
            err = err + e**2
         end do
         err = sqrt(err/n)
      end if
   end subroutine dopri5_kernel

   !> One trial step of size hh from (tau, y0): the stages into k, the new state into y_new
   !> and, with `with_error`, Hairer's scaled error norm. Module level with explicit-shape
   !> arrays (no host association, no descriptors) because this is the integrator's inner
   !> loop; `finite` is false as soon as a derivative is not finite (nothing more is done).
   subroutine dop853_kernel(system, n, tau, hh, y0, k, y_stage, y_new, views, atol, rtol, with_error, err, finite, &
                            n_evaluations)
      class(rk_system_t), intent(inout) :: system
      integer, intent(in) :: n
      real(wp), intent(in) :: tau, hh, y0(n), atol(n), rtol
      real(wp), intent(inout), target :: k(n, *)
      real(wp), intent(out), target :: y_stage(n), y_new(n)
      type(stage_views_t), intent(in) :: views  !! the same y_stage, y_new and columns of k
      logical, intent(in) :: with_error
      real(wp), intent(out) :: err
      logical, intent(out) :: finite
      integer(int64), intent(inout) :: n_evaluations
      real(wp) :: scale, e3, e5, err5, err3, deno
      integer :: i
      err = 0.0_wp
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(dop853%a21*k(i, 1))
      end do
      call system%rhs(tau + dop853%c2*hh, views%y_stage%v, views%f(2)%v)
      if (stage_failed(n, k(:, 2), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(dop853%a31*k(i, 1) + dop853%a32*k(i, 2))
      end do
      call system%rhs(tau + dop853%c3*hh, views%y_stage%v, views%f(3)%v)
      if (stage_failed(n, k(:, 3), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(dop853%a41*k(i, 1) + dop853%a43*k(i, 3))
      end do
      call system%rhs(tau + dop853%c4*hh, views%y_stage%v, views%f(4)%v)
      if (stage_failed(n, k(:, 4), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(dop853%a51*k(i, 1) + dop853%a53*k(i, 3) + dop853%a54*k(i, 4))
      end do
      call system%rhs(tau + dop853%c5*hh, views%y_stage%v, views%f(5)%v)
      if (stage_failed(n, k(:, 5), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(dop853%a61*k(i, 1) + dop853%a64*k(i, 4) + dop853%a65*k(i, 5))
      end do
      call system%rhs(tau + dop853%c6*hh, views%y_stage%v, views%f(6)%v)
      if (stage_failed(n, k(:, 6), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(dop853%a71*k(i, 1) + dop853%a74*k(i, 4) + dop853%a75*k(i, 5) + dop853%a76*k(i, 6))
      end do
      call system%rhs(tau + dop853%c7*hh, views%y_stage%v, views%f(7)%v)
      if (stage_failed(n, k(:, 7), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(dop853%a81*k(i, 1) + dop853%a84*k(i, 4) + dop853%a85*k(i, 5) + dop853%a86*k(i, 6) &
                                  + dop853%a87*k(i, 7))
      end do
      call system%rhs(tau + dop853%c8*hh, views%y_stage%v, views%f(8)%v)
      if (stage_failed(n, k(:, 8), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(dop853%a91*k(i, 1) + dop853%a94*k(i, 4) + dop853%a95*k(i, 5) + dop853%a96*k(i, 6) &
                                  + dop853%a97*k(i, 7) + dop853%a98*k(i, 8))
      end do
      call system%rhs(tau + dop853%c9*hh, views%y_stage%v, views%f(9)%v)
      if (stage_failed(n, k(:, 9), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(dop853%a101*k(i, 1) + dop853%a104*k(i, 4) + dop853%a105*k(i, 5) &
            + dop853%a106*k(i, 6) &
                                  + dop853%a107*k(i, 7) + dop853%a108*k(i, 8) + dop853%a109*k(i, 9))
      end do
      call system%rhs(tau + dop853%c10*hh, views%y_stage%v, views%f(10)%v)
      if (stage_failed(n, k(:, 10), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(dop853%a111*k(i, 1) + dop853%a114*k(i, 4) + dop853%a115*k(i, 5) &
            + dop853%a116*k(i, 6) &
                                  + dop853%a117*k(i, 7) + dop853%a118*k(i, 8) + dop853%a119*k(i, 9) &
                                     + dop853%a1110*k(i, 10))
      end do
      call system%rhs(tau + dop853%c11*hh, views%y_stage%v, views%f(11)%v)
      if (stage_failed(n, k(:, 11), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(dop853%a121*k(i, 1) + dop853%a124*k(i, 4) + dop853%a125*k(i, 5) &
            + dop853%a126*k(i, 6) &
                                  + dop853%a127*k(i, 7) + dop853%a128*k(i, 8) + dop853%a129*k(i, 9) &
                                     + dop853%a1210*k(i, 10) &
                                  + dop853%a1211*k(i, 11))
      end do
      call system%rhs(tau + hh, views%y_stage%v, views%f(12)%v)
      if (stage_failed(n, k(:, 12), finite, n_evaluations)) return
      ! the 8th-order solution; k(:, 13) is kept for the increment b·k
      !GCC$ novector
      do i = 1, n
         k(i, 13) = dop853%b1*k(i, 1) + dop853%b6*k(i, 6) + dop853%b7*k(i, 7) + dop853%b8*k(i, 8) &
            + dop853%b9*k(i, 9) &
                    + dop853%b10*k(i, 10) + dop853%b11*k(i, 11) + dop853%b12*k(i, 12)
         y_new(i) = y0(i) + hh*k(i, 13)
      end do
      if (with_error) then
         ! Hairer's combined estimate err5²/sqrt(err5² + 0.01·err3²) (dop853.f, ERROR ESTIMATION)
         err3 = 0.0_wp
         err5 = 0.0_wp
         !GCC$ novector
         do i = 1, n
            scale = 1.0_wp/(atol(i) + rtol*max(abs(y0(i)), abs(y_new(i))))
            e3 = (k(i, 13) - dop853%bhh1*k(i, 1) - dop853%bhh2*k(i, 9) - dop853%bhh3*k(i, 12))*scale
            e5 = (dop853%er1*k(i, 1) + dop853%er6*k(i, 6) + dop853%er7*k(i, 7) + dop853%er8*k(i, 8) &
               + dop853%er9*k(i, 9) &
                  + dop853%er10*k(i, 10) + dop853%er11*k(i, 11) + dop853%er12*k(i, 12))*scale
            err3 = err3 + e3**2
            err5 = err5 + e5**2
         end do
         deno = err5 + 0.01_wp*err3
         if (deno <= 0.0_wp) deno = 1.0_wp
         err = abs(hh)*err5*sqrt(1.0_wp/(n*deno))
      end if
   end subroutine dop853_kernel

   !> One trial step of PD8(7) of size hh from (tau, y0): the 13 stages into k, the
   !> 8th-order state into y_new and, with `with_error`, Hairer's norm of its difference to
   !> the 7th-order one. Stage 13 does not use stage 12 (a(13, 12) = 0), so the two
   !> evaluations at tau + hh can overlap. Same conventions as `dop853_kernel`.
   subroutine pd87_kernel(system, n, tau, hh, y0, k, y_stage, y_new, views, atol, rtol, with_error, err, finite, &
                          n_evaluations)
      class(rk_system_t), intent(inout) :: system
      integer, intent(in) :: n
      real(wp), intent(in) :: tau, hh, y0(n), atol(n), rtol
      real(wp), intent(inout), target :: k(n, *)
      real(wp), intent(out), target :: y_stage(n), y_new(n)
      type(stage_views_t), intent(in) :: views  !! the same y_stage, y_new and columns of k
      logical, intent(in) :: with_error
      real(wp), intent(out) :: err
      logical, intent(out) :: finite
      integer(int64), intent(inout) :: n_evaluations
      real(wp) :: e
      integer :: i
      err = 0.0_wp
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(pd87%a21*k(i, 1))
      end do
      call system%rhs(tau + pd87%c2*hh, views%y_stage%v, views%f(2)%v)
      if (stage_failed(n, k(:, 2), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(pd87%a31*k(i, 1) + pd87%a32*k(i, 2))
      end do
      call system%rhs(tau + pd87%c3*hh, views%y_stage%v, views%f(3)%v)
      if (stage_failed(n, k(:, 3), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(pd87%a41*k(i, 1) + pd87%a43*k(i, 3))
      end do
      call system%rhs(tau + pd87%c4*hh, views%y_stage%v, views%f(4)%v)
      if (stage_failed(n, k(:, 4), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(pd87%a51*k(i, 1) + pd87%a53*k(i, 3) + pd87%a54*k(i, 4))
      end do
      call system%rhs(tau + pd87%c5*hh, views%y_stage%v, views%f(5)%v)
      if (stage_failed(n, k(:, 5), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(pd87%a61*k(i, 1) + pd87%a64*k(i, 4) + pd87%a65*k(i, 5))
      end do
      call system%rhs(tau + pd87%c6*hh, views%y_stage%v, views%f(6)%v)
      if (stage_failed(n, k(:, 6), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(pd87%a71*k(i, 1) + pd87%a74*k(i, 4) + pd87%a75*k(i, 5) + pd87%a76*k(i, 6))
      end do
      call system%rhs(tau + pd87%c7*hh, views%y_stage%v, views%f(7)%v)
      if (stage_failed(n, k(:, 7), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(pd87%a81*k(i, 1) + pd87%a84*k(i, 4) + pd87%a85*k(i, 5) + pd87%a86*k(i, 6) &
            + pd87%a87*k(i, 7))
      end do
      call system%rhs(tau + pd87%c8*hh, views%y_stage%v, views%f(8)%v)
      if (stage_failed(n, k(:, 8), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(pd87%a91*k(i, 1) + pd87%a94*k(i, 4) + pd87%a95*k(i, 5) + pd87%a96*k(i, 6) &
            + pd87%a97*k(i, 7) + pd87%a98*k(i, 8))
      end do
      call system%rhs(tau + pd87%c9*hh, views%y_stage%v, views%f(9)%v)
      if (stage_failed(n, k(:, 9), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(pd87%a101*k(i, 1) + pd87%a104*k(i, 4) + pd87%a105*k(i, 5) + pd87%a106*k(i, 6) &
            + pd87%a107*k(i, 7) + pd87%a108*k(i, 8) + pd87%a109*k(i, 9))
      end do
      call system%rhs(tau + pd87%c10*hh, views%y_stage%v, views%f(10)%v)
      if (stage_failed(n, k(:, 10), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(pd87%a111*k(i, 1) + pd87%a114*k(i, 4) + pd87%a115*k(i, 5) + pd87%a116*k(i, 6) &
            + pd87%a117*k(i, 7) + pd87%a118*k(i, 8) + pd87%a119*k(i, 9) + pd87%a1110*k(i, 10))
      end do
      call system%rhs(tau + pd87%c11*hh, views%y_stage%v, views%f(11)%v)
      if (stage_failed(n, k(:, 11), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(pd87%a121*k(i, 1) + pd87%a124*k(i, 4) + pd87%a125*k(i, 5) + pd87%a126*k(i, 6) &
            + pd87%a127*k(i, 7) + pd87%a128*k(i, 8) + pd87%a129*k(i, 9) + pd87%a1210*k(i, 10) + pd87%a1211*k(i, 11))
      end do
      call system%rhs(tau + hh, views%y_stage%v, views%f(12)%v)
      if (stage_failed(n, k(:, 12), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(pd87%a131*k(i, 1) + pd87%a134*k(i, 4) + pd87%a135*k(i, 5) + pd87%a136*k(i, 6) &
            + pd87%a137*k(i, 7) + pd87%a138*k(i, 8) + pd87%a139*k(i, 9) + pd87%a1310*k(i, 10) + pd87%a1311*k(i, 11))
      end do
      call system%rhs(tau + hh, views%y_stage%v, views%f(13)%v)
      if (stage_failed(n, k(:, 13), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_new(i) = y0(i) + hh*(pd87%b1*k(i, 1) + pd87%b6*k(i, 6) + pd87%b7*k(i, 7) + pd87%b8*k(i, 8) &
            + pd87%b9*k(i, 9) &
            + pd87%b10*k(i, 10) + pd87%b11*k(i, 11) + pd87%b12*k(i, 12) + pd87%b13*k(i, 13))
      end do
      if (with_error) then
         !GCC$ novector
         do i = 1, n
            e = hh*(pd87%e1*k(i, 1) + pd87%e6*k(i, 6) + pd87%e7*k(i, 7) + pd87%e8*k(i, 8) + pd87%e9*k(i, 9) &
               + pd87%e10*k(i, 10) + pd87%e11*k(i, 11) + pd87%e12*k(i, 12) + pd87%e13*k(i, 13))/(atol(i) &
               + rtol*max(abs(y0(i)), abs(y_new(i))))
            err = err + e**2
         end do
         err = sqrt(err/n)
      end if
   end subroutine pd87_kernel

   !> One trial step of Verner's 9(8) pair of size hh from (tau, y0): the 16 stages into k,
   !> the 9th-order state into y_new and, with `with_error`, Hairer's norm of its difference
   !> to the 8th-order one. Stage 16 serves only the error estimate (skipped without
   !> `with_error`, in fixed-step mode). Same conventions as `dop853_kernel`.
   subroutine vern98_kernel(system, n, tau, hh, y0, k, y_stage, y_new, views, atol, rtol, with_error, err, finite, &
                            n_evaluations)
      class(rk_system_t), intent(inout) :: system
      integer, intent(in) :: n
      real(wp), intent(in) :: tau, hh, y0(n), atol(n), rtol
      real(wp), intent(inout), target :: k(n, *)
      real(wp), intent(out), target :: y_stage(n), y_new(n)
      type(stage_views_t), intent(in) :: views  !! the same y_stage, y_new and columns of k
      logical, intent(in) :: with_error
      real(wp), intent(out) :: err
      logical, intent(out) :: finite
      integer(int64), intent(inout) :: n_evaluations
      real(wp) :: e
      integer :: i
      err = 0.0_wp
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(vern98%a21*k(i, 1))
      end do
      call system%rhs(tau + vern98%c2*hh, views%y_stage%v, views%f(2)%v)
      if (stage_failed(n, k(:, 2), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(vern98%a31*k(i, 1) + vern98%a32*k(i, 2))
      end do
      call system%rhs(tau + vern98%c3*hh, views%y_stage%v, views%f(3)%v)
      if (stage_failed(n, k(:, 3), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(vern98%a41*k(i, 1) + vern98%a43*k(i, 3))
      end do
      call system%rhs(tau + vern98%c4*hh, views%y_stage%v, views%f(4)%v)
      if (stage_failed(n, k(:, 4), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(vern98%a51*k(i, 1) + vern98%a53*k(i, 3) + vern98%a54*k(i, 4))
      end do
      call system%rhs(tau + vern98%c5*hh, views%y_stage%v, views%f(5)%v)
      if (stage_failed(n, k(:, 5), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(vern98%a61*k(i, 1) + vern98%a64*k(i, 4) + vern98%a65*k(i, 5))
      end do
      call system%rhs(tau + vern98%c6*hh, views%y_stage%v, views%f(6)%v)
      if (stage_failed(n, k(:, 6), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(vern98%a71*k(i, 1) + vern98%a74*k(i, 4) + vern98%a75*k(i, 5) + vern98%a76*k(i, 6))
      end do
      call system%rhs(tau + vern98%c7*hh, views%y_stage%v, views%f(7)%v)
      if (stage_failed(n, k(:, 7), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(vern98%a81*k(i, 1) + vern98%a86*k(i, 6) + vern98%a87*k(i, 7))
      end do
      call system%rhs(tau + vern98%c8*hh, views%y_stage%v, views%f(8)%v)
      if (stage_failed(n, k(:, 8), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(vern98%a91*k(i, 1) + vern98%a96*k(i, 6) + vern98%a97*k(i, 7) + vern98%a98*k(i, 8))
      end do
      call system%rhs(tau + vern98%c9*hh, views%y_stage%v, views%f(9)%v)
      if (stage_failed(n, k(:, 9), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(vern98%a101*k(i, 1) + vern98%a106*k(i, 6) + vern98%a107*k(i, 7) &
            + vern98%a108*k(i, 8) &
            + vern98%a109*k(i, 9))
      end do
      call system%rhs(tau + vern98%c10*hh, views%y_stage%v, views%f(10)%v)
      if (stage_failed(n, k(:, 10), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(vern98%a111*k(i, 1) + vern98%a116*k(i, 6) + vern98%a117*k(i, 7) &
            + vern98%a118*k(i, 8) &
            + vern98%a119*k(i, 9) + vern98%a1110*k(i, 10))
      end do
      call system%rhs(tau + vern98%c11*hh, views%y_stage%v, views%f(11)%v)
      if (stage_failed(n, k(:, 11), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(vern98%a121*k(i, 1) + vern98%a126*k(i, 6) + vern98%a127*k(i, 7) &
            + vern98%a128*k(i, 8) &
            + vern98%a129*k(i, 9) + vern98%a1210*k(i, 10) + vern98%a1211*k(i, 11))
      end do
      call system%rhs(tau + vern98%c12*hh, views%y_stage%v, views%f(12)%v)
      if (stage_failed(n, k(:, 12), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(vern98%a131*k(i, 1) + vern98%a136*k(i, 6) + vern98%a137*k(i, 7) &
            + vern98%a138*k(i, 8) &
            + vern98%a139*k(i, 9) + vern98%a1310*k(i, 10) + vern98%a1311*k(i, 11) + vern98%a1312*k(i, 12))
      end do
      call system%rhs(tau + vern98%c13*hh, views%y_stage%v, views%f(13)%v)
      if (stage_failed(n, k(:, 13), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(vern98%a141*k(i, 1) + vern98%a146*k(i, 6) + vern98%a147*k(i, 7) &
            + vern98%a148*k(i, 8) &
            + vern98%a149*k(i, 9) + vern98%a1410*k(i, 10) + vern98%a1411*k(i, 11) + vern98%a1412*k(i, 12) &
            + vern98%a1413*k(i, 13))
      end do
      call system%rhs(tau + vern98%c14*hh, views%y_stage%v, views%f(14)%v)
      if (stage_failed(n, k(:, 14), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(vern98%a151*k(i, 1) + vern98%a156*k(i, 6) + vern98%a157*k(i, 7) &
            + vern98%a158*k(i, 8) &
            + vern98%a159*k(i, 9) + vern98%a1510*k(i, 10) + vern98%a1511*k(i, 11) + vern98%a1512*k(i, 12) &
            + vern98%a1513*k(i, 13) + vern98%a1514*k(i, 14))
      end do
      call system%rhs(tau + hh, views%y_stage%v, views%f(15)%v)
      if (stage_failed(n, k(:, 15), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_new(i) = y0(i) + hh*(vern98%b1*k(i, 1) + vern98%b8*k(i, 8) + vern98%b9*k(i, 9) + vern98%b10*k(i, 10) &
            + vern98%b11*k(i, 11) + vern98%b12*k(i, 12) + vern98%b13*k(i, 13) + vern98%b14*k(i, 14) &
               + vern98%b15*k(i, 15))
      end do
      if (.not. with_error) return
      ! stage 16 serves only the 8th-order formula
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(vern98%a161*k(i, 1) + vern98%a166*k(i, 6) + vern98%a167*k(i, 7) &
            + vern98%a168*k(i, 8) &
            + vern98%a169*k(i, 9) + vern98%a1610*k(i, 10) + vern98%a1611*k(i, 11) + vern98%a1612*k(i, 12) &
            + vern98%a1613*k(i, 13))
      end do
      call system%rhs(tau + hh, views%y_stage%v, views%f(16)%v)
      if (stage_failed(n, k(:, 16), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         e = hh*(vern98%e1*k(i, 1) + vern98%e8*k(i, 8) + vern98%e9*k(i, 9) + vern98%e10*k(i, 10) &
            + vern98%e11*k(i, 11) &
            + vern98%e12*k(i, 12) + vern98%e13*k(i, 13) + vern98%e14*k(i, 14) + vern98%e15*k(i, 15) &
               + vern98%e16*k(i, 16)) &
            /(atol(i) + rtol*max(abs(y0(i)), abs(y_new(i))))
         err = err + e**2
      end do
      err = sqrt(err/n)
   end subroutine vern98_kernel

   !> Count one evaluation of f and say whether it failed: `finite` is false when a
   !> component is NaN or ±Inf (|f_i| <= huge is false for those: one compare per component).
   logical function stage_failed(n, f, finite, n_evaluations) result(failed)
      integer, intent(in) :: n                       !! number of components
      real(wp), intent(in) :: f(n)                   !! the derivative just computed
      logical, intent(out) :: finite                 !! all components finite
      integer(int64), intent(inout) :: n_evaluations !! evaluation counter
      integer :: i
      n_evaluations = n_evaluations + 1
      finite = .true.
      !GCC$ novector
      do i = 1, n
         finite = finite .and. abs(f(i)) <= huge(1.0_wp)
      end do
      failed = .not. finite
   end function stage_failed
end module hillstab_integrate_rk_stages

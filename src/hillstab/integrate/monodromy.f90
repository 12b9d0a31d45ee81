!> One entry point from a method choice to the monodromy trace of one period.
!>
!> Methods: `formula` (the paper's closed 2-piece forms), `segments`
!> (N-piece piecewise-constant product with endpoint/midpoint/average sampling)
!> and the exact methods (`auto`, Magnus, Runge–Kutta, GSL) as they are registered
!> here. All return the trace of the χ equation (47), i.e. S₁ when ε > 0.
module hillstab_integrate_monodromy
   use hillstab_core_kinds, only: wp
   use hillstab_core_error, only: error_t, set_error, err_invalid_parameter, err_accuracy
   use hillstab_hill_coefficient, only: hill_model_t, check_model, &
      segment_coefficients, hill_period, sampling_endpoint, sampling_midpoint, sampling_average
   use hillstab_hill_transfer, only: scaled_matrix_t, scaled_identity, multiply_transfer, multiply_matrix, &
      trace_t, trace_of
   use hillstab_hill_formulas, only: trace_formula
   use hillstab_core_stats, only: work_stats_t, add_work
   use hillstab_integrate_monodromy_gsl, only: trace_gsl
   use hillstab_integrate_monodromy_rk, only: trace_rk
   use hillstab_integrate_magnus, only: trace_magnus
   use hillstab_integrate_auto, only: trace_auto, trace_auto_batch, auto_plan_t, auto_prepare
   implicit none
   private
   public :: method_t, method_auto, method_formula, method_segments, method_magnus4, method_magnus6, &
      method_rk, method_gsl, method_name, method_from_name
   public :: monodromy_segmented, trace_segmented, swing_monodromy, monodromy_trace, monodromy_trace_batch
   public :: batch_plan_t, prepare_batch

   integer, parameter :: method_auto = 0     !! cheapest exact method meeting the tolerance
   integer, parameter :: method_formula = 1  !! the paper's closed forms, eq. (37)/(48)/(A3)
   integer, parameter :: method_segments = 2 !! N-piece piecewise-constant product
   integer, parameter :: method_magnus4 = 3  !! fourth-order Magnus integrator
   integer, parameter :: method_magnus6 = 4  !! sixth-order Magnus integrator
   integer, parameter :: method_rk = 5       !! hillstab's adaptive Runge–Kutta
   integer, parameter :: method_gsl = 6      !! GSL odeiv2 rk8pd reference

   !> How to compute the monodromy.
   type :: method_t
      integer :: kind = method_auto  !! one of the method_* constants
      integer :: n_segments = 2             !! pieces for method_segments
      integer :: sampling = sampling_endpoint  !! piece values for method_segments
      real(wp) :: tolerance = 1.0e-10_wp    !! target error on S, scaled by max(1, |S|)
   end type method_t

   !> Work shared by the batches of one chart row (the meshes of method auto).
   type :: batch_plan_t
      type(auto_plan_t) :: auto  !! meshes of method auto
   end type batch_plan_t

contains

   !> Prepare what batches of the points (model%kind, model%alpha, β_j, model%epsilon)
   !> can share; pass the plan to `monodromy_trace_batch`.
   subroutine prepare_batch(model, betas, method, plan)
      type(hill_model_t), intent(in) :: model  !! kind, alpha and epsilon of the batch (beta ignored)
      real(wp), intent(in) :: betas(:)  !! the betas of the batch
      type(method_t), intent(in) :: method  !! how the traces will be computed
      type(batch_plan_t), intent(out) :: plan  !! what the batches can share
      if (method%kind == method_auto) call auto_prepare(model%kind, model%alpha, model%epsilon, betas, &
                                                       method%tolerance, plan%auto)
   end subroutine prepare_batch

   !> Name of a method constant.
   pure function method_name(kind) result(name)
      integer, intent(in) :: kind  !! one of the method_* constants
      character(len=:), allocatable :: name
      select case (kind)
      case (method_auto); name = "auto"
      case (method_formula); name = "formula"
      case (method_segments); name = "segments"
      case (method_magnus4); name = "magnus4"
      case (method_magnus6); name = "magnus6"
      case (method_rk); name = "rk"
      case (method_gsl); name = "gsl"
      case default; name = "unknown"
      end select
   end function method_name

   !> Method constant from its name; −1 when unknown.
   pure integer function method_from_name(name) result(kind)
      character(len=*), intent(in) :: name  !! a method name, lower case
      integer :: k
      kind = -1
      do k = method_auto, method_gsl
         if (trim(name) == method_name(k)) kind = k
      end do
   end function method_from_name

   !> Monodromy of the χ equation over one period [0, 2] with q replaced by
   !> `n` constant pieces (exact transfer matrix per piece).
   pure function monodromy_segmented(model, n, sampling) result(a)
      type(hill_model_t), intent(in) :: model  !! model kind, alpha, beta, epsilon
      integer, intent(in) :: n         !! number of pieces
      integer, intent(in) :: sampling  !! sampling_endpoint | sampling_midpoint | sampling_average
      type(scaled_matrix_t) :: a
      real(wp) :: q(n), h, carry
      integer :: i
      call segment_coefficients(model, n, sampling, q)
      h = hill_period/n
      a = scaled_identity()
      carry = 0.0_wp
      do i = 1, n
         ! the log scale summed with compensation (see `multiply_transfer`)
         call multiply_transfer(a, q(i), h, carry)
      end do
      a%log_scale = a%log_scale - carry
   end function monodromy_segmented

   !> Trace of `monodromy_segmented`.
   pure function trace_segmented(model, n, sampling) result(tr)
      type(hill_model_t), intent(in) :: model  !! model kind, alpha, beta, epsilon
      integer, intent(in) :: n, sampling  !! number of pieces; sampling_* constant
      type(trace_t) :: tr
      tr = trace_of(monodromy_segmented(model, n, sampling))
   end function trace_segmented

   !> Monodromy of the damped swing x'' + ε x' + Q x = 0 from that of χ:
   !> M_x = e^{−ε} P M_χ P⁻¹ with P = [[1, 0], [−ε/2, 1]] (x = e^{−ετ/2} χ).
   pure function swing_monodromy(chi, epsilon) result(x)
      type(scaled_matrix_t), intent(in) :: chi  !! monodromy of the chi equation (47)
      real(wp), intent(in) :: epsilon  !! damping epsilon >= 0
      type(scaled_matrix_t) :: x
      real(wp) :: p(2, 2), p_inv(2, 2)
      p = reshape([1.0_wp, -0.5_wp*epsilon, 0.0_wp, 1.0_wp], [2, 2])
      p_inv = reshape([1.0_wp, 0.5_wp*epsilon, 0.0_wp, 1.0_wp], [2, 2])
      x = chi
      x%m = matmul(x%m, p_inv)
      call multiply_matrix(x, p)
      x%log_scale = x%log_scale - epsilon
   end function swing_monodromy

   !> Trace of the one-period monodromy of the χ equation by the chosen method.
   subroutine monodromy_trace(model, method, tr, error, stats)
      type(hill_model_t), intent(in) :: model  !! the Hill equation: model kind, alpha, beta, damping epsilon
      type(method_t), intent(in) :: method  !! method and its settings
      type(trace_t), intent(out) :: tr  !! the trace S (S1 of the chi equation when epsilon > 0)
      !> what failed (err_accuracy: tr is the best value); unallocated on success
      type(error_t), allocatable, intent(out) :: error
      type(work_stats_t), intent(out), optional :: stats  !! work done (Q evaluations, steps)
      type(work_stats_t) :: work
      call check_model(model, error)
      if (allocated(error)) return
      select case (method%kind)
      case (method_formula)
         tr = trace_formula(model)
         work = work_stats_t(2, 0, 2)
      case (method_segments)
         if (method%n_segments < 1) then
            call set_error(error, err_invalid_parameter, "n_segments must be >= 1")
            return
         end if
         if (all(method%sampling /= [sampling_endpoint, sampling_midpoint, sampling_average])) then
            call set_error(error, err_invalid_parameter, "unknown sampling")
            return
         end if
         tr = trace_segmented(model, method%n_segments, method%sampling)
         work = work_stats_t(method%n_segments, 0, method%n_segments)
      case (method_gsl)
         call trace_gsl(model, method%tolerance, tr, work, error)
      case (method_rk)
         call trace_rk(model, method%tolerance, tr, error, work)
      case (method_auto)
         call trace_auto(model, method%tolerance, tr, work, error)
      case (method_magnus4)
         call trace_magnus(model, 4, method%tolerance, tr, work, error)
      case (method_magnus6)
         call trace_magnus(model, 6, method%tolerance, tr, work, error)
      case default
         call set_error(error, err_invalid_parameter, "method '"//method_name(method%kind)// &
            "' is not available in this build")
      end select
      if (present(stats)) stats = work
   end subroutine monodromy_trace

   !> Traces of the points (α, β_j) of one model kind, α and ε, e.g. a chart row. Method
   !> auto shares its meshes and coefficient values across the batch (much faster than
   !> point by point); the other methods go point by point. `failed(j)` marks points that
   !> could not be computed; `error` describes the first of them.
   subroutine monodromy_trace_batch(model, betas, method, traces, failed, error, stats, plan, inaccurate)
      type(hill_model_t), intent(in) :: model  !! kind, alpha and epsilon of the batch (beta ignored)
      real(wp), intent(in) :: betas(:)  !! the betas of the batch
      type(method_t), intent(in) :: method  !! method and its settings
      type(trace_t), intent(out) :: traces(size(betas))  !! S of each beta
      logical, intent(out) :: failed(size(betas))  !! true where no value could be computed
      type(error_t), allocatable, intent(out) :: error  !! the first failure; unallocated when none failed
      type(work_stats_t), intent(out), optional :: stats  !! work done over the batch
      type(batch_plan_t), intent(in), optional :: plan  !! from `prepare_batch` for this row
      !> computed, but the tolerance is below the round-off level there (err_accuracy): the
      !> trace is the best double precision allows; not counted in `failed`
      logical, intent(out), optional :: inaccurate(size(betas))
      type(work_stats_t) :: work, part
      logical :: reached(size(betas)), roundoff(size(betas))
      type(error_t), allocatable :: point_error
      type(hill_model_t) :: point
      integer :: j
      failed = .false.
      if (present(inaccurate)) inaccurate = .false.
      work = work_stats_t()
      if (method%kind == method_auto) then
         if (present(plan)) then
            call trace_auto_batch(model%kind, model%alpha, model%epsilon, betas, method%tolerance, traces, work, &
               error, plan%auto, reached, roundoff)
         else
            call trace_auto_batch(model%kind, model%alpha, model%epsilon, betas, method%tolerance, traces, work, &
               error, reached=reached, roundoff=roundoff)
         end if
         if (allocated(error)) then
            ! only round-off limited points: their traces are the best values; a point that
            ! failed as well is located below, point by point
            if (error%code == err_accuracy .and. all(reached .or. roundoff)) then
               if (present(inaccurate)) inaccurate = roundoff
               if (present(stats)) stats = work
               return
            end if
         end if
         ! any other batch error (a point out of range, a tolerance not met) is located point by point
         if (.not. allocated(error)) then
            if (present(stats)) stats = work
            return
         end if
         deallocate (error)
      end if
      do j = 1, size(betas)
         point = model
         point%beta = betas(j)
         call monodromy_trace(point, method, traces(j), point_error, part)
         call add_work(work, part)
         if (allocated(point_error)) then
            if (point_error%code == err_accuracy) then
               if (present(inaccurate)) inaccurate(j) = .true.
               cycle
            end if
            failed(j) = .true.
            if (.not. allocated(error)) call move_alloc(point_error, error)
         end if
      end do
      if (present(stats)) stats = work
   end subroutine monodromy_trace_batch
end module hillstab_integrate_monodromy

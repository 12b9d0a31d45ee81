!> The values of the columns of a system's chart and points files at each point (the columns,
!> their order and each value from the one Floquet result: hillstab_batch_tasks_floquet_columns), as task
!> `chart` and `points` (hillstab_batch_tasks_system) and the C API
!> (hillstab_interop_capi_system_batch) compute them: the exact monodromy by the chosen
!> method (hillstab_integrate_system_point, the nodes shared along a chart row) and its
!> Floquet analysis (hillstab_hill_system_floquet). A system that is one scalar equation
!> (`hill_system_t%scalar_model`) takes, on method auto, the scalar method auto's lanes and
!> row-shared meshes instead (`scalar_values`): its trace S gives the same analysis
!> (`complete_from_trace`), at the scalar path's cost.
!>
!>```fortran
!> real(wp) :: v(n_fixed + 1)
!> call system_values(system, form, system_method_t(system_auto, 1.0e-10_wp), 2.0_wp, 0.5_wp, v, failed, message)
!>```
module hillstab_batch_tasks_system_values
   use hillstab_core_kinds, only: wp
   use hillstab_core_error, only: error_t, set_error, err_integration
   use hillstab_core_status, only: status_ok, status_roundoff, status_failed
   use hillstab_core_stats, only: work_stats_t
   use hillstab_hill_system, only: hill_system_t, system_form_t, prepare_system
   use hillstab_hill_system_floquet, only: complete_from_trace
   use hillstab_hill_model, only: hill_model_t, hill_point_t
   use hillstab_hill_floquet, only: floquet_t, floquet_from_trace
   use hillstab_hill_transfer, only: trace_t
   use hillstab_integrate_monodromy, only: monodromy_trace_batch, method_t, method_auto
   use hillstab_integrate_system, only: system_method_t, system_monodromy_t, system_nodes_t, system_auto
   use hillstab_integrate_system_point, only: system_point
   use hillstab_batch_tasks_floquet_columns, only: n_fixed, system_layout_t, system_layout, system_point_values
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   implicit none
   private
   public :: system_values, system_row_values, scalar_path, scalar_point, failure_text


contains




   !> One point: monodromy, analysis, values; `failed` with the error when it could not be computed.
   subroutine evaluate(system, form, layout, method, alpha, beta, nodes, v, failed, message, row_form_given)
      class(hill_system_t), intent(in) :: system
      type(system_form_t), intent(in) :: form
      type(system_layout_t), intent(in) :: layout  !! the columns' places (`system_layout`)
      type(system_method_t), intent(in) :: method
      real(wp), intent(in) :: alpha, beta
      type(system_nodes_t), intent(inout) :: nodes
      real(wp), intent(out) :: v(:)
      logical, intent(out) :: failed
      character(len=:), allocatable, intent(out) :: message
      !> `form` is the row's already (a row-dependent system prepared at α by the caller)
      logical, intent(in), optional :: row_form_given
      type(system_monodromy_t) :: r
      type(floquet_t) :: f
      type(error_t), allocatable :: error
      type(system_form_t) :: row_form
      type(system_nodes_t) :: point_nodes
      class(hill_system_t), allocatable :: local
      logical :: prepare, taken
      ! one equation on method auto: the scalar method auto on its scalar form
      call scalar_point(system, form, method, alpha, beta, f, r, taken, error)
      if (taken) then
         failed = allocated(error)
         message = ""
         if (failed) message = error%message
         v = system_point_values(layout, alpha, beta, f, r, failed)
         return
      end if
      prepare = system%row_dependent()
      if (present(row_form_given)) prepare = prepare .and. .not. row_form_given
      if (.not. system%shares_rows()) then
         ! the point alone: the system at its β, prepared there, its point (α, 0), its own nodes
         call system%at_point(alpha, beta, local)
         call prepare_system(local, form%epsilon, row_form, error, alpha)
         if (.not. allocated(error)) call system_point(local, row_form, alpha, 0.0_wp, method, point_nodes, r, f, error)
      else if (prepare) then
         ! C or G change with α (an equation's damping along a frequency axis): the form of the row
         call prepare_system(system, form%epsilon, row_form, error, alpha)
         if (.not. allocated(error)) call system_point(system, row_form, alpha, beta, method, nodes, r, f, error)
      else
         call system_point(system, form, alpha, beta, method, nodes, r, f, error)
      end if
      failed = allocated(error) .or. r%status == status_failed
      message = ""
      if (allocated(error)) message = error%message
      v = system_point_values(layout, alpha, beta, f, r, failed)
   end subroutine evaluate

   !> The values of the columns `system_column_names` at one point, computed alone (its own
   !> nodes): what task `points` writes, `hillstab_system_points` returns and one call of
   !> `hillstab_system_floquet` gives. `failed` (status 2 and placeholders) with the reason.
   subroutine system_values(system, form, method, alpha, beta, v, failed, message)
      class(hill_system_t), intent(in) :: system  !! the system
      type(system_form_t), intent(in) :: form  !! prepared at the point's damping
      type(system_method_t), intent(in) :: method  !! method and tolerance
      real(wp), intent(in) :: alpha, beta  !! the point
      real(wp), intent(out) :: v(:)  !! n_fixed + n values, in the columns' order
      logical, intent(out) :: failed  !! the point could not be computed
      character(len=:), allocatable, intent(out) :: message  !! why ("" when it could)
      type(system_nodes_t) :: nodes
      call evaluate(system, form, system_layout(form%n), method, alpha, beta, nodes, v, failed, message)
   end subroutine system_values

   !> Whether a system's points take the scalar path (`scalar_values`): method auto on a
   !> system that is one scalar equation.
   logical function scalar_path(system, method)
      class(hill_system_t), intent(in) :: system  !! the system
      integer, intent(in) :: method  !! the method's code
      class(hill_model_t), allocatable :: scalar
      scalar_path = .false.
      if (method /= system_auto) return
      call system%scalar_model(scalar)
      scalar_path = allocated(scalar)
   end function scalar_path

   !> The values of points (α, β_j) of one degree of freedom by the scalar method auto on the
   !> system's scalar form (`hill_system_t%scalar_model`): the traces of the batch on its lanes
   !> and shared meshes (hillstab_integrate_monodromy), the Floquet data of each at the row's
   !> damping (hillstab_hill_floquet) and the system's analysis from them (`complete_from_trace`):
   !> its error estimate is the trace's, relative to max(1, |S|), and its steps the batch's
   !> mean. `taken` is false (nothing computed) where the row's damping is not one the scalar
   !> form takes (not finite, or negative).
   subroutine scalar_values(model, form, method, alpha, betas, values, n_failed, failure, taken)
      class(hill_model_t), intent(in) :: model  !! the scalar form
      type(system_form_t), intent(in) :: form  !! the system prepared (its period)
      type(system_method_t), intent(in) :: method  !! method auto and the tolerance
      real(wp), intent(in) :: alpha  !! the row's α
      real(wp), intent(in) :: betas(:)  !! its β
      real(wp), intent(out) :: values(:, :)  !! (n_fixed + 1, size(betas))
      integer, intent(out) :: n_failed  !! points of status 2
      character(len=*), intent(out) :: failure  !! "alpha = …, beta = …: why" of the first ("" when none)
      logical, intent(out) :: taken  !! the points were computed here
      type(floquet_t) :: f(size(betas))
      type(system_monodromy_t) :: r(size(betas))
      logical :: failed(size(betas))
      type(error_t), allocatable :: cause
      type(system_layout_t) :: layout
      integer :: j
      n_failed = 0
      failure = ""
      layout = system_layout(form%n)
      call scalar_analyses(model, form, method, alpha, betas, f, r, failed, cause, taken)
      if (.not. taken) return
      do j = 1, size(betas)
         if (failed(j)) then
            n_failed = n_failed + 1
            if (n_failed == 1) then
               if (allocated(cause)) then
                  call failure_text(alpha, betas(j), cause%message, failure)
               else
                  call failure_text(alpha, betas(j), "no trace", failure)
               end if
            end if
         end if
         values(:, j) = system_point_values(layout, alpha, betas(j), f(j), r(j), failed(j))
      end do
   end subroutine scalar_values

   !> The analyses of points (α, β_j) on the scalar path (`scalar_values`): each point's
   !> `floquet_t` and the monodromy's status, error estimate and steps (no Φ).
   subroutine scalar_analyses(model, form, method, alpha, betas, f, r, failed, cause, taken)
      class(hill_model_t), intent(in) :: model  !! the scalar form
      type(system_form_t), intent(in) :: form  !! the system prepared (its period)
      type(system_method_t), intent(in) :: method  !! method auto and the tolerance
      real(wp), intent(in) :: alpha  !! the row's α
      real(wp), intent(in) :: betas(:)  !! its β
      type(floquet_t), intent(out) :: f(:)  !! the analyses (unset where failed)
      type(system_monodromy_t), intent(out) :: r(:)  !! status, error estimate, steps
      logical, intent(out) :: failed(:)  !! no value at the point
      type(error_t), allocatable, intent(out) :: cause  !! the first failure
      logical, intent(out) :: taken  !! the points were computed here
      type(trace_t) :: traces(size(betas))
      logical :: inaccurate(size(betas))
      type(work_stats_t) :: stats
      real(wp) :: damping, dampings(size(betas))
      integer :: j
      failed = .false.
      damping = model%point_damping(alpha, form%epsilon)
      taken = ieee_is_finite(damping) .and. damping >= 0.0_wp
      if (.not. taken) return
      call monodromy_trace_batch(model, hill_point_t(alpha, 0.0_wp, damping), betas, &
                                 method_t(kind=method_auto, tolerance=method%tolerance), traces, failed, cause, &
                                 stats=stats, inaccurate=inaccurate, dampings=dampings)
      do j = 1, size(betas)
         r(j)%steps = int(stats%n_steps/max(1, size(betas)))
         r(j)%status = merge(status_roundoff, status_ok, inaccurate(j))
         r(j)%error_estimate = max(traces(j)%error_estimate, 0.0_wp)
         if (failed(j)) then
            r(j)%status = status_failed
         else
            f(j) = floquet_from_trace(traces(j), dampings(j), method%tolerance, model%period())
            call complete_from_trace(f(j), form)
         end if
      end do
   end subroutine scalar_analyses

   !> One point on the scalar path when the system takes it (method auto on a system that is
   !> one scalar equation, at a damping its scalar form takes): its analysis and the
   !> monodromy's status, error estimate and steps (no Φ); `taken` false, nothing done,
   !> otherwise. `error` when the point failed.
   subroutine scalar_point(system, form, method, alpha, beta, f, r, taken, error)
      class(hill_system_t), intent(in) :: system  !! the system
      type(system_form_t), intent(in) :: form  !! prepared at the point's damping
      type(system_method_t), intent(in) :: method  !! method and tolerance
      real(wp), intent(in) :: alpha, beta  !! the point
      type(floquet_t), intent(out) :: f  !! its analysis
      type(system_monodromy_t), intent(out) :: r  !! status, error estimate, steps
      logical, intent(out) :: taken  !! computed here
      type(error_t), allocatable, intent(out) :: error  !! the point failed
      class(hill_model_t), allocatable :: scalar
      type(floquet_t) :: fs(1)
      type(system_monodromy_t) :: rs(1)
      logical :: failed(1)
      taken = .false.
      if (method%kind /= system_auto) return
      call system%scalar_model(scalar)
      if (.not. allocated(scalar)) return
      call scalar_analyses(scalar, form, method, alpha, [beta], fs, rs, failed, error, taken)
      if (.not. taken) return
      f = fs(1)
      r = rs(1)
      if (failed(1) .and. .not. allocated(error)) call set_error(error, err_integration, "no trace")
      if (.not. failed(1) .and. allocated(error)) deallocate (error)
   end subroutine scalar_point

   !> The values of a chart row (one α, the β in order), the points sharing their nodes:
   !> what task `chart` writes and `hillstab_system_chart` returns. `n_failed` points failed;
   !> `failure` names the first and why.
   subroutine system_row_values(system, form, method, alpha, betas, values, n_failed, failure)
      class(hill_system_t), intent(in) :: system  !! the system
      type(system_form_t), intent(in) :: form  !! prepared at the chart's damping
      type(system_method_t), intent(in) :: method  !! method and tolerance
      real(wp), intent(in) :: alpha  !! the row's α
      real(wp), intent(in) :: betas(:)  !! its β
      real(wp), intent(out) :: values(:, :)  !! (n_fixed + n, size(betas))
      integer, intent(out) :: n_failed  !! points of status 2
      character(len=*), intent(out) :: failure  !! "alpha = …, beta = …: why" of the first ("" when none)
      type(system_nodes_t) :: nodes
      type(system_form_t) :: row_form
      type(error_t), allocatable :: error
      character(len=:), allocatable :: message
      class(hill_model_t), allocatable :: scalar
      logical :: failed, taken, row_given
      type(system_layout_t) :: layout
      integer :: j
      n_failed = 0
      layout = system_layout(form%n)
      failure = ""
      if (method%kind == system_auto) then
         ! one equation: the scalar method auto's lanes and shared meshes on its scalar form
         call system%scalar_model(scalar)
         if (allocated(scalar)) then
            call scalar_values(scalar, form, method, alpha, betas, values, n_failed, failure, taken)
            if (taken) return
         end if
      end if
      ! the row's form once where its points share it (C or G change with α: an equation's
      ! damping along a frequency axis); else each point its own in `evaluate` (a system that
      ! does not share rows at each point's β; a row whose form failed, point by point)
      row_given = .true.
      row_form = form
      if (.not. system%shares_rows()) then
         row_given = .false.
      else if (system%row_dependent()) then
         call prepare_system(system, form%epsilon, row_form, error, alpha)
         if (allocated(error)) then
            row_given = .false.
            row_form = form
         end if
      end if
      do j = 1, size(betas)
         call evaluate(system, row_form, layout, method, alpha, betas(j), nodes, values(:, j), failed, message, &
                       row_given)
         if (failed .and. n_failed == 0) call failure_text(alpha, betas(j), message, failure)
         if (failed) n_failed = n_failed + 1
      end do
   end subroutine system_row_values

   !> "alpha = …, beta = …:  <message>" of a failed point, as the chart's error gives it.
   subroutine failure_text(alpha, beta, message, text)
      real(wp), intent(in) :: alpha, beta  !! the point
      character(len=*), intent(in) :: message  !! why it failed
      character(len=*), intent(out) :: text  !! the text
      write (text, '(a, es24.16, a, es24.16, a)') "alpha = ", alpha, ", beta = ", beta, ": "
      text = trim(text)//" "//message
   end subroutine failure_text


end module hillstab_batch_tasks_system_values

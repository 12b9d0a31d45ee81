!> Task `boundaries` of a system scene: the transition curves of a system of Hill equations
!> over the α of `&chart`, one block of curve points per α, found in the β window of
!> `&chart` from its n_beta samples (hillstab_curves_system_boundaries: simple resonances by
!> Hill's method with n × n blocks, the other edges by root-finding on a signed distance from
!> the stability threshold), each edge checked on both sides by the monodromy's verdict. Rows
!> run in parallel (OpenMP); the file is written atomically.
module hillstab_batch_tasks_system_boundaries
   use hillstab_core_kinds, only: wp, int64, version_string
   use hillstab_core_error, only: error_t, set_error, err_input, err_points_failed
   use hillstab_core_status, only: status_ok
   use hillstab_core_text, only: real_text, integer_text, put_es, put_integer
   use hillstab_hill_system, only: system_form_t, prepare_system, system_equation_text, system_description
   use hillstab_integrate_system, only: system_method_t
   use hillstab_batch_scene_types, only: scene_t, task_t, open_scene_output, scene_header
   use hillstab_batch_scene_declaration, only: group_t
   use hillstab_batch_scene_file, only: scene_file_t, fail
   use hillstab_batch_scene_checks, only: max_grid_count
   use hillstab_batch_scene_group_chart, only: chart_grid_t, chart_group, read_chart_group, grid_alpha, grid_beta, &
      grid_size_text, scale_linear
   use hillstab_batch_output_file, only: output_file_t, finish_output, write_header, write_text
   use hillstab_batch_output_progress, only: progress_t, progress_begin, progress_step, progress_end
   use hillstab_curves_system_boundaries, only: system_boundary_t, system_boundaries
   use hillstab_core_parallel, only: max_threads
   use hillstab_batch_tasks_system_cost, only: check_system_cost, extreme_name
   implicit none
   private
   public :: system_boundaries_task_t, system_boundaries_task

   !> `boundaries` on a system: the transition curves over the α of `&chart`.
   type, extends(task_t) :: system_boundaries_task_t
      type(chart_grid_t) :: grid  !! `&chart`: the α values, the β window and its n_beta samples
   contains
      procedure :: read => boundaries_read
      procedure :: run => boundaries_run
      procedure :: declarations => chart_declarations_b
      procedure :: size_variables => boundaries_size_variables
      procedure :: memory_bytes => boundaries_memory_bytes
   end type system_boundaries_task_t

contains

   !> A boundaries task of a system scene.
   function system_boundaries_task() result(task)
      type(system_boundaries_task_t) :: task
      task%name = "boundaries"
   end function system_boundaries_task

   !> `&chart`.
   function chart_declarations_b(self) result(groups)
      class(system_boundaries_task_t), intent(in) :: self  !! the task
      type(group_t), allocatable :: groups(:)
      allocate (groups(1))
      groups(1) = chart_group()
   end function chart_declarations_b

   !> The variables that set the work and the memory: the α grid and the β samples.
   function boundaries_size_variables(self) result(text)
      class(system_boundaries_task_t), intent(in) :: self  !! the task
      character(len=:), allocatable :: text
      text = grid_size_text(self%grid, .false.)
   end function boundaries_size_variables

   !> The curve points kept for every α (at most 4 n_beta + 64 each) and each row's
   !> message, the β samples, and each thread's work on a row (the samples' discriminant and
   !> verdicts, its curve points).
   function boundaries_memory_bytes(self, scene) result(bytes)
      class(system_boundaries_task_t), intent(in) :: self  !! the task
      type(scene_t), intent(in) :: scene  !! its scene
      integer(int64) :: bytes
      type(system_boundary_t) :: row
      integer(int64) :: per_row, samples
      samples = int(self%grid%n_beta, int64)
      per_row = (4*samples + 64)*(storage_size(row)/8)
      bytes = int(self%grid%n_alpha, int64)*(per_row + 400) + 8*samples + &
              int(max_threads(), int64)*(12*samples + per_row)
   end function boundaries_memory_bytes

   !> `&chart`: at least 2 β samples.
   subroutine boundaries_read(self, file, scene, error)
      class(system_boundaries_task_t), intent(inout) :: self  !! the task, its grid filled in
      type(scene_file_t), intent(in) :: file      !! the scene file
      type(scene_t), intent(in) :: scene          !! the `&scene` settings
      type(error_t), allocatable, intent(out) :: error  !! err_input naming file, group and variable
      allocate (self%groups(1))
      if (scene%system%row_dependent()) then
         ! the curves are found at one prepared form and from the drive's harmonics
         call fail(error, file%path, "scene", "task", "task 'boundaries' takes a system whose damping is the "// &
            "same at every alpha ('system'); the "//scene%system%name()//" system's changes along its alpha axis: "// &
            "chart it (task 'chart') or take its points (task 'points')")
         return
      end if
      call read_chart_group(file, chart_group(), grid=self%grid, values=self%groups(1), error=error)
      if (allocated(error)) return
      if (self%grid%beta_scale /= scale_linear) then
         ! the beta samples only bracket the curves, found between them
         call fail(error, file%path, "chart", "beta_scale", "task 'boundaries' finds the curves inside the "// &
            "beta window, not at grid values: beta_scale must be 'linear' (alpha_scale = 'log' spaces the alphas)")
         return
      end if
      if (self%grid%n_beta < 2 .or. .not. (self%grid%beta_max > self%grid%beta_min)) then
         call fail(error, file%path, "chart", "n_beta", "the boundaries of a system need a beta window "// &
            "(beta_max > beta_min) and n_beta >= 2 samples in it (the brackets of the combination tongues)")
         return
      end if
      if (int(self%grid%n_alpha, int64)*self%grid%n_beta > int(max_grid_count, int64)) then
         call fail(error, file%path, "chart", "n_beta", "n_alpha * n_beta exceeds the limit of 1e8 points")
         return
      end if
      call check_system_cost(scene, max(abs(self%grid%alpha_min), abs(self%grid%alpha_max)), &
                             max(abs(self%grid%beta_min), abs(self%grid%beta_max)), "chart", &
                             extreme_name("alpha", self%grid%alpha_min, self%grid%alpha_max), &
                             extreme_name("beta", self%grid%beta_min, self%grid%beta_max), error)
   end subroutine boundaries_read

   !> The curves, one block per α: `alpha beta kind route check error_estimate status`.
   subroutine boundaries_run(self, scene, quiet, error)
      class(system_boundaries_task_t), intent(in) :: self  !! the task
      type(scene_t), intent(in) :: scene  !! its scene
      logical, intent(in) :: quiet  !! no progress on stderr
      type(error_t), allocatable, intent(out) :: error  !! err_points_failed when a point is not confirmed
      type(output_file_t) :: file
      type(system_form_t) :: form
      type(error_t), allocatable :: cause
      type(system_boundary_t), allocatable :: rows(:, :)
      integer, allocatable :: counts(:)
      character(len=400), allocatable :: failures(:)
      real(wp), allocatable :: betas(:)
      character(len=400) :: extra(7)
      character(len=200) :: line
      type(progress_t) :: progress
      integer :: i, k, n_failed, length, alloc_status
      call prepare_system(scene%system, scene%epsilon, form, cause)
      if (allocated(cause)) then
         call fail(error, scene%source, "system", "mass", cause%message)
         return
      end if
      betas = [(grid_beta(self%grid, k), k=1, self%grid%n_beta)]
      allocate (rows(4*self%grid%n_beta + 64, self%grid%n_alpha), counts(self%grid%n_alpha), &
                failures(self%grid%n_alpha), stat=alloc_status)
      if (alloc_status /= 0) then
         call set_error(error, err_input, scene%source//": "//self%size_variables()//": the curve points of "// &
            integer_text(self%grid%n_alpha)//" alphas cannot be allocated (out of memory)")
         return
      end if
      counts = 0
      failures = ""
      call progress_begin(progress, int(self%grid%n_alpha, int64), quiet, "rows")
      !$omp parallel do schedule(dynamic, 1) default(shared) private(i, k, cause)
      do i = 1, self%grid%n_alpha
         call boundary_row(i, cause)
         if (allocated(cause)) failures(i) = cause%message
         call progress_step(progress)
      end do
      !$omp end parallel do
      call progress_end(progress)
      extra(1) = system_description(scene%system)
      extra(2) = "stability edges: simple resonances (a multiplier pair at +1 or -1) by Hill's method with n x n "// &
                 "blocks; the others by Brent's method on a signed distance q from the stability threshold over "// &
                 "the samples, refined around the combination resonances predicted at alpha = 0; every edge "// &
                 "checked on both sides by the monodromy's verdict"
      extra(3) = "column kind: 1 a multiplier at +1, 2 at -1, 3 a combination edge (off the real axis); "// &
                 "negated (-1, -2, -3) where both sides are unstable (no stability edge)"
      extra(4) = "column route: 1 Hill's method, 2 a root of Broucke's discriminant a1^2 - 4 a2 + 8 (Hamiltonian, "// &
                 "n = 2), 3 of Re (z_k - z_l)^2 of the nearest two z = lambda + 1/lambda (Hamiltonian, n >= 3), "// &
                 "4 of -ln max|lambda| (damped)"
      extra(5) = "column check: the distance of the nearest multiplier from +-1 at (alpha, beta) (route 1); "// &
                 "|q| there over its error bound (routes 2-4)"
      extra(6) = "column error_estimate: of beta (route 1: two truncations of Hill's matrix; 2-4: the final "// &
                 "bracket plus q's error bound over its slope)"
      extra(7) = "column status: 0 ok; 2 not confirmed: check > 1e-4 (route 1), or a side the verdict cannot "// &
                 "decide (routes 2-4)"
      call open_scene_output(scene, file, error)
      if (allocated(error)) return
      call write_header(file, scene_header(scene, "hillstab "//version_string//": transition curves of "// &
                        system_equation_text(scene%system), extra), &
                        "alpha beta kind route check error_estimate status", error)
      n_failed = 0
      do i = 1, self%grid%n_alpha
         if (allocated(error)) exit
         if (i > 1) call write_text(file, "", error)
         do k = 1, counts(i)
            if (allocated(error)) exit
            length = 0
            line = ""
            call put_es(line, length, rows(k, i)%alpha, 17)
            call put_es(line, length, rows(k, i)%beta, 17)
            length = length + 1
            call put_integer(line, length, rows(k, i)%kind)
            length = length + 1
            call put_integer(line, length, rows(k, i)%route)
            call put_es(line, length, rows(k, i)%check, 17)
            call put_es(line, length, rows(k, i)%error_estimate, 17)
            length = length + 1
            call put_integer(line, length, rows(k, i)%status)
            if (rows(k, i)%status /= status_ok) n_failed = n_failed + 1
            call write_text(file, line(:length), error)
         end do
      end do
      call finish_output(file, error)
      if (allocated(error)) return
      do i = 1, self%grid%n_alpha
         if (len_trim(failures(i)) > 0) then
            call set_error(error, err_points_failed, scene%source//": alpha = "//real_text(grid_alpha( &
               self%grid, i))//": "//trim(failures(i)))
            return
         end if
      end do
      if (n_failed > 0) call set_error(error, err_points_failed, scene%source//": "//integer_text(n_failed)// &
         " curve points not confirmed by the monodromy (status 2)")

   contains

      subroutine boundary_row(i, cause)
         integer, intent(in) :: i
         type(error_t), allocatable, intent(out) :: cause
         type(system_boundary_t), allocatable :: found(:)
         real(wp) :: alpha
         alpha = grid_alpha(self%grid, i)
         call system_boundaries(scene%system, form, alpha, betas, system_method_t(scene%method%kind, &
                                scene%method%tolerance), found, cause)
         counts(i) = min(size(found), size(rows, 1))
         rows(1:counts(i), i) = found(1:counts(i))
      end subroutine boundary_row
   end subroutine boundaries_run

end module hillstab_batch_tasks_system_boundaries

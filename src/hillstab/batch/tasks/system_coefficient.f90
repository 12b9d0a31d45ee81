!> Task `coefficient` of a system scene (`&scene model = 'system'`): the entries of
!> K(τ) = K0 + βB + α Σ (Kₖᶜ cos + Kₖˢ sin) over the τ of `&coefficient`, one block of rows
!> per α of its list, at its β; the file is written atomically.
module hillstab_batch_tasks_system_coefficient
   use hillstab_core_kinds, only: wp, int64, version_string
   use hillstab_core_error, only: error_t
   use hillstab_core_text, only: format_es, real_text, integer_text
   use hillstab_hill_system, only: system_equation_text, system_description
   use hillstab_batch_scene_types, only: scene_t, task_t, open_scene_output, scene_header
   use hillstab_batch_scene_declaration, only: group_t, new_group, group_reader_t, var_real, var_integer, &
      var_real_list, begin_group, next_item, end_group, list_value
   use hillstab_batch_scene_file, only: scene_file_t, fail
   use hillstab_batch_scene_checks, only: check_range, require_finite
   use hillstab_batch_scene_group_chart, only: grid_value
   use hillstab_batch_output_file, only: output_file_t, finish_output, write_header, write_text
   use hillstab_batch_output_progress, only: progress_t, progress_begin, progress_update, progress_end
   implicit none
   private
   public :: system_coefficient_task_t, system_coefficient_task

   !> `coefficient` on a system: the entries of K(τ).
   type, extends(task_t) :: system_coefficient_task_t
      real(wp), allocatable :: alphas(:)  !! one block per α
      real(wp) :: beta = 0.0_wp  !! β of every block
      integer :: n_tau = 401     !! τ values of a block
      real(wp) :: tau_min = 0.0_wp  !! the first τ
      real(wp) :: tau_max = 2.0_wp  !! the last τ
   contains
      procedure :: read => coefficient_read
      procedure :: run => coefficient_run
      procedure :: declarations => coefficient_declarations
   end type system_coefficient_task_t

contains

   !> A coefficient task of a system scene.
   function system_coefficient_task() result(task)
      type(system_coefficient_task_t) :: task
      task%name = "coefficient"
   end function system_coefficient_task

   !> The declaration of `&coefficient` for a system.
   function coefficient_group() result(group)
      type(group_t) :: group
      group = new_group("coefficient", "the entries of K(tau) = K0 + beta B + alpha sum_k (...) at one beta "// &
                        "for a list of alpha")
      call group%add("alphas", var_real_list, "0.0, 1.0", "one block of rows per alpha, up to 64", max_count=64)
      call group%add("beta", var_real, "1.0", "beta of every block")
      call group%add("n_tau", var_integer, "401", "number of tau values, >= 1")
      call group%add("tau_min", var_real, "0.0", "first tau")
      call group%add("tau_max", var_real, "2.0", "last tau (one period of the default P = 2)")
   end function coefficient_group

   !> `&coefficient`.
   function coefficient_declarations(self) result(groups)
      class(system_coefficient_task_t), intent(in) :: self  !! the task
      type(group_t), allocatable :: groups(:)
      allocate (groups(1))
      groups(1) = coefficient_group()
   end function coefficient_declarations

   !> Read `&coefficient`.
   subroutine coefficient_read(self, file, scene, error)
      class(system_coefficient_task_t), intent(inout) :: self  !! the task
      type(scene_file_t), intent(in) :: file      !! the scene file
      type(scene_t), intent(in) :: scene          !! the `&scene` settings
      type(error_t), allocatable, intent(out) :: error  !! err_input naming file, group and variable
      type(group_t) :: group
      type(group_reader_t) :: reader
      real(wp) :: alphas(64), beta, tau_min, tau_max
      integer :: n_tau, count, k
      namelist /coefficient/ alphas, beta, n_tau, tau_min, tau_max
      group = coefficient_group()
      call begin_group(reader, file, group)
      read (reader%defaults, nml=coefficient, iostat=reader%defaults_status, iomsg=reader%defaults_msg)
      if (reader%from_file) read (file%unit, nml=coefficient, iostat=reader%ios, iomsg=reader%msg)
      do while (next_item(reader, file, group))
         read (reader%record, nml=coefficient, iostat=reader%stat, iomsg=reader%message)
      end do
      write (reader%echo, nml=coefficient, delim="apostrophe", iostat=reader%echo_status)
      allocate (self%groups(1))
      call end_group(reader, file, group, self%groups(1), error)
      if (allocated(error)) return
      self%alphas = list_value(self%groups(1), "alphas", alphas)
      count = size(self%alphas)
      if (count == 0) then
         call fail(error, file%path, group%name, "alphas", "no alpha given")
         return
      end if
      do k = 1, count
         call require_finite(file%path, group%name, "alphas", self%alphas(k), error)
         if (allocated(error)) return
      end do
      call require_finite(file%path, group%name, "beta", beta, error)
      if (allocated(error)) return
      call check_range(file%path, group%name, "tau", tau_min, tau_max, n_tau, error)
      if (allocated(error)) return
      self%beta = beta
      self%n_tau = n_tau
      self%tau_min = tau_min
      self%tau_max = tau_max
      if (.not. allocated(scene%system)) call fail(error, file%path, "scene", "model", "not a system")
   end subroutine coefficient_read

   !> Rows `alpha tau k_11 k_12 … k_nn` (K row by row), one block per α.
   subroutine coefficient_run(self, scene, quiet, error)
      class(system_coefficient_task_t), intent(in) :: self  !! the task
      type(scene_t), intent(in) :: scene  !! its scene
      logical, intent(in) :: quiet  !! no progress on stderr
      type(error_t), allocatable, intent(out) :: error  !! err_io when writing fails
      type(output_file_t) :: file
      real(wp), allocatable :: p(:, :), b(:, :), k_tau(:, :)
      character(len=:), allocatable :: names, line
      character(len=300), allocatable :: extra(:)
      integer :: n, a, t, i, j
      real(wp) :: tau
      type(progress_t) :: progress
      character(len=:), allocatable :: entry, matrix
      n = scene%system%dof()
      ! a first-order system's coefficient is its state matrix A (in tau: (pi/Omega) A)
      entry = " k_"
      matrix = "K(tau)"
      if (scene%system%first_order()) then
         entry = " a_"
         matrix = "A(tau)"
      end if
      allocate (p(n, n), b(n, n), k_tau(n, n))
      names = "alpha tau"
      do i = 1, n
         do j = 1, n
            names = names//entry//integer_text(i)//"_"//integer_text(j)
         end do
      end do
      allocate (extra(2))
      extra(1) = system_description(scene%system)
      extra(2) = "one block per alpha (blank line between): "//matrix//" at beta = "//real_text(self%beta)// &
                 ", its entries row by row"
      call open_scene_output(scene, file, error)
      if (allocated(error)) return
      if (scene%system%first_order()) matrix = "state matrix A(tau)"
      if (.not. scene%system%first_order()) matrix = "stiffness K(tau)"
      call write_header(file, scene_header(scene, "hillstab "//version_string//": the "//matrix//" of "// &
                        system_equation_text(scene%system), extra), names, error)
      call progress_begin(progress, int(size(self%alphas), int64), quiet, "curves")
      do a = 1, size(self%alphas)
         if (allocated(error)) exit
         call progress_update(progress, int(a - 1, int64))
         if (a > 1) call write_text(file, "", error)
         do t = 1, self%n_tau
            if (allocated(error)) exit
            tau = grid_value(self%tau_min, self%tau_max, self%n_tau, t)
            call scene%system%stiffness(self%alphas(a), tau, p, b)
            k_tau = p + self%beta*b
            line = trim(format_es(self%alphas(a), 17))//" "//trim(format_es(tau, 17))
            do i = 1, n
               do j = 1, n
                  line = line//" "//trim(format_es(k_tau(i, j), 17))
               end do
            end do
            call write_text(file, line, error)
         end do
      end do
      call progress_end(progress)
      call finish_output(file, error)
   end subroutine coefficient_run
end module hillstab_batch_tasks_system_coefficient

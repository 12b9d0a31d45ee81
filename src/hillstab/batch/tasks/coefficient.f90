!> Task `coefficient`: Q(τ) and its N-piece segmented version (n_segments and sampling of
!> `&scene`) for a list of α at one β (the paper's Fig. 2), over a τ range; with
!> `&physical a` and r0 the curves are the pendulum's bounce amplitudes.
module hillstab_batch_tasks_coefficient
   use hillstab_core_kinds, only: wp, int64
   use hillstab_core_error, only: error_t, set_error, err_input
   use hillstab_core_text, only: real_text, integer_text
   use hillstab_hill_coefficient, only: segment_coefficients, sampling_name
   use hillstab_batch_scene_types, only: scene_t, task_t, open_scene_output
   use hillstab_batch_scene_physical, only: physical_points, pendulum_task_t
   use hillstab_batch_scene_file, only: scene_file_t, fail
   use hillstab_batch_scene_declaration, only: new_group, group_t, group_reader_t, variable, var_real, var_integer, var_real_list, &
      begin_group, next_item, end_group, list_value
   use hillstab_batch_scene_checks, only: require_finite, require_bounded, check_range, check_alpha_domain
   use hillstab_batch_scene_group_chart, only: grid_value
   use hillstab_batch_output_columns, only: column_t, style_fortran_e17, columns_text, put_row, all_columns
   use hillstab_batch_tasks_chart_columns, only: common_header, stacked, header_bytes
   use hillstab_batch_output_file, only: output_file_t, finish_output, write_header, write_text
   use hillstab_batch_output_progress, only: progress_t, progress_begin, progress_update, progress_end
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use hillstab_hill_model, only: hill_point_t, hill_coefficient
   implicit none
   private
   public :: coefficient_task_t, coefficient_task, coefficient_group

   !> Largest number of α values in `&coefficient alphas`.
   integer, parameter :: max_alphas = 64

   !> The coefficient task: Q(τ) at one β for a list of α.
   type, extends(pendulum_task_t) :: coefficient_task_t
      real(wp), allocatable :: alphas(:)  !! α of each curve
      real(wp) :: beta = 0.0_wp           !! β of every curve
      real(wp) :: tau_min = 0.0_wp        !! first τ
      real(wp) :: tau_max = 0.0_wp        !! last τ (one period is 2)
      integer :: n_tau = 1                !! number of τ values
      integer :: n_pieces = 2             !! pieces of Qseg (`&scene n_segments`)
   contains
      procedure :: read => coefficient_read
      procedure :: run => coefficient_run
      procedure :: declarations => coefficient_declarations
      procedure :: estimated_bytes => coefficient_estimated_bytes
      procedure :: size_variables => coefficient_size_variables
      procedure :: memory_bytes => coefficient_memory_bytes
      procedure :: memory_variables => coefficient_memory_variables
   end type coefficient_task_t

contains

   !> `&coefficient`.
   function coefficient_declarations(self) result(groups)
      class(coefficient_task_t), intent(in) :: self  !! the task
      type(group_t), allocatable :: groups(:)
      allocate (groups(1))
      groups(1) = coefficient_group()
   end function coefficient_declarations

   !> The variables that set the size of the file.
   function coefficient_size_variables(self) result(text)
      class(coefficient_task_t), intent(in) :: self  !! the task
      character(len=:), allocatable :: text
      text = "&coefficient: n_tau: "//integer_text(self%n_tau)//" rows"
   end function coefficient_size_variables

   !> The memory of a run: the pieces of every curve (n_segments values each), one row's
   !> numbers and text.
   function coefficient_memory_bytes(self, scene) result(bytes)
      class(coefficient_task_t), intent(in) :: self  !! the task
      type(scene_t), intent(in) :: scene  !! its scene
      integer(int64) :: bytes
      bytes = (int(scene%method%n_segments, int64)*8 + 33*2)*size(self%alphas) + 33
   end function coefficient_memory_bytes

   !> What sets the memory of a run: the pieces of every curve.
   function coefficient_memory_variables(self) result(text)
      class(coefficient_task_t), intent(in) :: self  !! the task
      character(len=:), allocatable :: text
      text = "&scene: n_segments: "//integer_text(self%n_pieces)//" pieces of "//integer_text(size(self%alphas))// &
             " curve(s) (&coefficient alphas)"
   end function coefficient_memory_variables

   !> A coefficient task before its scene is read.
   function coefficient_task() result(task)
      type(coefficient_task_t) :: task
      task%name = "coefficient"
      task%physical_use%amplitudes_replace = "alphas and beta from &coefficient"
      task%physical_use%takes_amplitudes = .true.
   end function coefficient_task

   !> The declaration of `&coefficient` (defaults: the paper's Fig. 2).
   function coefficient_group() result(group)
      type(group_t) :: group
      group = new_group("coefficient", "Q(tau) at one beta for a list of alpha")
      call group%add("alphas", var_real_list, "4.0, 6.0, 7.5, 8.0, 9.0, 9.7", "one curve per alpha, up to "// &
         ""// integer_text(max_alphas)//" values", max_count=max_alphas)
      call group%add("beta", var_real, "6.0", "beta of every curve")
      call group%add("n_tau", var_integer, "801", "number of tau values, >= 1")
      call group%add("tau_min", var_real, "0.0", "first tau")
      call group%add("tau_max", var_real, "2.0", "last tau (one period is 2)")
   end function coefficient_group

   !> `&coefficient`; with `&physical a` the group is optional and gives only τ.
   subroutine coefficient_read(self, file, scene, error)
      class(coefficient_task_t), intent(inout) :: self  !! the task, its curves filled in
      type(scene_file_t), intent(in) :: file      !! the scene file
      type(scene_t), intent(in) :: scene          !! the `&scene` settings
      type(error_t), allocatable, intent(out) :: error  !! err_input naming file, group and variable
      type(group_t) :: group
      real(wp) :: alphas(max_alphas), beta, tau_min, tau_max
      integer :: n_tau
      namelist /coefficient/ alphas, beta, n_tau, tau_min, tau_max
      type(group_reader_t) :: reader
      real(wp), allocatable :: points(:, :)
      logical :: from_physical
      integer :: k
      from_physical = size(self%physical%amplitudes) > 0
      if (size(self%physical%amplitudes) > max_alphas) then
         call fail(error, file%path, "physical", "n_a", "task 'coefficient' draws at most "// &
            integer_text(max_alphas)//" curves, got "//integer_text(size(self%physical%amplitudes))//" amplitudes")
         return
      end if
      group = coefficient_group()
      allocate (self%groups(1))
      call begin_group(reader, file, group, optional=from_physical)
      read (reader%defaults, nml=coefficient, iostat=reader%defaults_status, iomsg=reader%defaults_msg)
      if (reader%from_file) read (file%unit, nml=coefficient, iostat=reader%ios, iomsg=reader%msg)
      do while (next_item(reader, file, group))
         read (reader%record, nml=coefficient, iostat=reader%stat, iomsg=reader%message)
      end do
      write (reader%echo, nml=coefficient, delim="apostrophe", iostat=reader%echo_status)
      call end_group(reader, file, group, self%groups(1), error)
      if (allocated(error)) return
      associate (values => self%groups(1))
         if (from_physical) then
            ! the curves are the pendulum's amplitudes
            do k = 1, 2
               if (values%given(group%variables(k)%name)) then
                  call fail(error, file%path, group%name, group%variables(k)%name, "alpha and beta come "// &
                     "either from &coefficient alphas, beta or from &physical a and r0, not both")
                  return
               end if
            end do
            points = physical_points(self%physical, scene%model)
            self%alphas = points(1, :)
            beta = points(2, 1)
            call values%hide("alphas")
            call values%hide("beta")
         else
            self%alphas = list_value(values, "alphas", alphas)
         end if
      end associate
      do k = 1, size(self%alphas)
         if (.not. ieee_is_finite(self%alphas(k))) then
            call fail(error, file%path, group%name, "alphas", "value "//integer_text(k)//" is not a finite number")
            return
         end if
      end do
      do k = 1, size(self%alphas)
         call check_alpha_domain(file%path, scene%model, group%name, "alphas", self%alphas(k), error)
         if (allocated(error)) return
      end do
      call require_finite(file%path, group%name, "beta", beta, error)
      if (allocated(error)) return
      call require_bounded(file%path, group%name, "beta", beta, error)
      if (allocated(error)) return
      do k = 1, size(self%alphas)
         call require_bounded(file%path, group%name, "alphas", self%alphas(k), error)
         if (allocated(error)) return
         call check_alpha_domain(file%path, scene%model, group%name, "beta", self%alphas(k), error, beta=beta)
         if (allocated(error)) return
      end do
      call check_range(file%path, group%name, "tau", tau_min, tau_max, n_tau, error)
      if (allocated(error)) return
      self%beta = beta
      self%tau_min = tau_min
      self%tau_max = tau_max
      self%n_tau = n_tau
      self%n_pieces = scene%method%n_segments
   end subroutine coefficient_read

   !> Header plus n_tau rows of 1 + 2 n_alpha numbers.
   pure function coefficient_estimated_bytes(self, scene) result(bytes)
      class(coefficient_task_t), intent(in) :: self  !! the task
      type(scene_t), intent(in) :: scene  !! its scene
      integer(int64) :: bytes
      bytes = header_bytes + int(self%n_tau, int64)*25_int64*(1_int64 + 2_int64*size(self%alphas))
   end function coefficient_estimated_bytes

   !> The columns: tau, then Q(a) and Qseg(a) for each α = a.
   function coefficient_columns(self, scene) result(table)
      class(coefficient_task_t), intent(in) :: self
      type(scene_t), intent(in) :: scene
      type(column_t), allocatable :: table(:)
      character(len=:), allocatable :: a
      integer :: k
      allocate (table(1 + 2*size(self%alphas)))
      table(1) = column_t("tau", "", "dimensionless time, pi tau = omega t (one period is 2)", style_fortran_e17)
      ! component by component: a structure constructor given computed strings leaks them (gfortran 12)
      do k = 1, size(self%alphas)
         a = real_text(self%alphas(k))
         table(2*k)%name = "Q("//a//")"
         table(2*k)%unit = ""
         table(2*k)%meaning = "Q at alpha = "//a
         table(2*k)%style = style_fortran_e17
         table(2*k + 1)%name = "Qseg("//a//")"
         table(2*k + 1)%unit = ""
         table(2*k + 1)%meaning = "the segmented Q at alpha = "//a
         table(2*k + 1)%style = style_fortran_e17
      end do
   end function coefficient_columns

   !> The coefficient task: columns tau, then for each α: Q(τ) and its N-piece
   !> segmented value (n_segments and sampling of &scene).
   subroutine coefficient_run(self, scene, quiet, error)
      class(coefficient_task_t), intent(in) :: self  !! the task
      type(scene_t), intent(in) :: scene  !! its scene
      logical, intent(in) :: quiet  !! no progress on stderr (rows written)
      type(error_t), allocatable, intent(out) :: error  !! err_io when the file cannot be written
      type(output_file_t) :: file
      type(hill_point_t) :: point
      real(wp) :: period
      type(column_t), allocatable :: table(:)
      real(wp), allocatable :: pieces(:, :), row(:)
      character(len=:), allocatable :: lines(:), q_line, segments_line, columns_line, line
      real(wp) :: tau, h
      integer :: i, k, n_alpha, n_pieces, piece, pos
      type(progress_t) :: progress

      n_alpha = size(self%alphas)
      n_pieces = scene%method%n_segments
      period = scene%model%period()
      h = period/n_pieces
      allocate (pieces(n_pieces, n_alpha), row(1 + 2*n_alpha), stat=i)
      if (i /= 0) then
         call set_error(error, err_input, scene%source//": "//self%memory_variables()//": "// &
            integer_text(n_pieces)//" pieces of each curve cannot be allocated (out of memory)")
         return
      end if
      do k = 1, n_alpha
         point = hill_point_t(self%alphas(k), self%beta, scene%epsilon)
         call segment_coefficients(scene%model, point, n_pieces, scene%method%sampling, pieces(:, k))
      end do
      table = coefficient_columns(self, scene)
      q_line = "Q: the coefficient at beta = "//real_text(self%beta)// &
               " (minus epsilon^2/4 when epsilon > 0: the chi equation (47))"
      segments_line = "Qseg: Q replaced by "//integer_text(n_pieces)//" constant pieces on [0, 2), sampling "// &
                      sampling_name(scene%method%sampling)//" (2 pieces, endpoint: eq. (28) of the paper)"
      columns_line = "Q(a), Qseg(a): the two columns of alpha = a"
      if (size(self%physical%amplitudes) == n_alpha) then
         ! the curves in metres: each alpha is a bounce amplitude of &physical
         columns_line = columns_line//"; the amplitudes [m]:"
         do k = 1, n_alpha
            columns_line = columns_line//" a = "//real_text(self%physical%amplitudes(k))//" (alpha = "// &
                           real_text(self%alphas(k))//")"
            if (k < n_alpha) columns_line = columns_line//","
         end do
      end if
      lines = stacked(common_header(scene, self%physical), stacked([q_line], stacked([segments_line], [columns_line])))

      call open_scene_output(scene, file, error)
      if (allocated(error)) return
      call write_header(file, lines, columns_text(table, all_columns(table)), error)
      allocate (character(len=25*size(row)) :: line)
      call progress_begin(progress, int(self%n_tau, int64), quiet, "rows")
      do i = 1, self%n_tau
         if (allocated(error)) exit
         tau = grid_value(self%tau_min, self%tau_max, self%n_tau, i)
         piece = min(int(modulo(tau, period)/h) + 1, n_pieces)
         row(1) = tau
         do k = 1, n_alpha
            point = hill_point_t(self%alphas(k), self%beta, scene%epsilon)
            row(2*k) = hill_coefficient(scene%model, point, tau)
            row(2*k + 1) = pieces(piece, k)
         end do
         pos = 0
         call put_row(table, all_columns(table), row, line, pos)
         ! the rows end with one blank, as the files this task has always written
         call write_text(file, line(:pos)//" ", error)
         if (mod(i, 4096) == 0 .or. i == self%n_tau) call progress_update(progress, int(i, int64))
      end do
      call progress_end(progress)
      call finish_output(file, error)
   end subroutine coefficient_run
end module hillstab_batch_tasks_coefficient

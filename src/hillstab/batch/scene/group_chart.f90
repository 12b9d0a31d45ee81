!> The `&chart` group: an (α, β) grid, n values from min to max inclusive. Read by the
!> chart, boundaries and lyapunov tasks (each may give its own defaults, e.g. the
!> lyapunov task's grid covers the physical domain).
!>
!>```fortran
!> type(chart_grid_t) :: grid
!> grid = chart_grid_t(0.0_wp, 9.8_wp, 3, -2.0_wp, 12.0_wp, 5)
!> print *, grid_point(grid, 7_int64)   ! the second β of the second α
!>```
module hillstab_batch_scene_group_chart
   use hillstab_core_kinds, only: wp, int64
   use hillstab_core_error, only: error_t
   use hillstab_batch_scene_file, only: scene_file_t
   use hillstab_batch_scene_declaration, only: new_group, group_t, group_values_t, group_reader_t, variable, var_real, &
      var_integer, &
      begin_group, next_item, end_group
   use hillstab_batch_scene_checks, only: check_range, check_alpha_domain
   use hillstab_hill_model, only: hill_model_t
   implicit none
   private
   public :: chart_grid_t, chart_group, read_chart_group, grid_value, grid_point, grid_size_text

   !> The (α, β) grid of a chart: n values from min to max inclusive (n = 1: min only).
   type :: chart_grid_t
      real(wp) :: alpha_min = 0.0_wp  !! first α
      real(wp) :: alpha_max = 0.0_wp  !! last α (elastic model: < π²)
      integer :: n_alpha = 1          !! number of α values
      real(wp) :: beta_min = 0.0_wp   !! first β
      real(wp) :: beta_max = 0.0_wp   !! last β
      integer :: n_beta = 1           !! number of β values
   end type chart_grid_t

contains

   !> What sets the size of a grid's file, for messages: "&chart: n_alpha, n_beta: 200 x 200
   !> points", or with `physical` the (a, omega) grid of `&physical` (n_a x n_omega).
   function grid_size_text(grid, physical) result(text)
      type(chart_grid_t), intent(in) :: grid  !! n_alpha (n_a) by n_beta (n_omega)
      logical, intent(in) :: physical          !! the grid is &physical's (a, omega)
      character(len=:), allocatable :: text
      character(len=24) :: rows, columns
      write (rows, '(i0)') grid%n_alpha
      write (columns, '(i0)') grid%n_beta
      if (physical) then
         text = "&physical: n_a, n_omega: "//trim(rows)//" x "//trim(columns)//" points"
      else
         text = "&chart: n_alpha, n_beta: "//trim(rows)//" x "//trim(columns)//" points"
      end if
   end function grid_size_text

   !> The declaration of `&chart`, with the chart task's defaults (the paper's Fig. 3 window).
   function chart_group() result(group)
      type(group_t) :: group
      group = new_group("chart", "n values from min to max inclusive (n = 1: min only)")
      call group%add("alpha_min", var_real, "0.0", "first alpha = a pi^2/rho (elastic: 0 <= alpha < pi^2)")
      call group%add("alpha_max", var_real, "9.8", "last alpha, >= alpha_min")
      call group%add("n_alpha", var_integer, "200", "number of alpha values, >= 1")
      call group%add("beta_min", var_real, "-2.0", "first beta = g pi^2/(rho omega^2)")
      call group%add("beta_max", var_real, "12.0", "last beta, >= beta_min")
      call group%add("n_beta", var_integer, "200", "number of beta values, >= 1")
   end function chart_group

   !> Read and check `&chart` (the declaration `group` carries the task's defaults).
   subroutine read_chart_group(file, group, model, grid, values, error)
      type(scene_file_t), intent(in) :: file  !! the scene file
      type(group_t), intent(in) :: group      !! the declaration (`chart_group`, maybe other defaults)
      class(hill_model_t), intent(in), optional :: model  !! the model (the domain of α; absent: a system)
      type(chart_grid_t), intent(out) :: grid  !! the grid
      type(group_values_t), intent(out) :: values  !! the effective values
      type(error_t), allocatable, intent(out) :: error  !! err_input naming file, group and variable
      real(wp) :: alpha_min, alpha_max, beta_min, beta_max
      integer :: n_alpha, n_beta
      namelist /chart/ alpha_min, alpha_max, n_alpha, beta_min, beta_max, n_beta
      type(group_reader_t) :: reader
      call begin_group(reader, file, group)
      read (reader%defaults, nml=chart, iostat=reader%defaults_status, iomsg=reader%defaults_msg)
      if (reader%from_file) read (file%unit, nml=chart, iostat=reader%ios, iomsg=reader%msg)
      do while (next_item(reader, file, group))
         read (reader%record, nml=chart, iostat=reader%stat, iomsg=reader%message)
      end do
      write (reader%echo, nml=chart, delim="apostrophe", iostat=reader%echo_status)
      call end_group(reader, file, group, values, error)
      if (allocated(error)) return

      call check_range(file%path, group%name, "alpha", alpha_min, alpha_max, n_alpha, error)
      if (allocated(error)) return
      call check_alpha_domain(file%path, model, group%name, "alpha_min", alpha_min, error)
      if (allocated(error)) return
      call check_alpha_domain(file%path, model, group%name, "alpha_max", alpha_max, error)
      if (allocated(error)) return
      call check_range(file%path, group%name, "beta", beta_min, beta_max, n_beta, error)
      if (allocated(error)) return
      grid = chart_grid_t(alpha_min, alpha_max, n_alpha, beta_min, beta_max, n_beta)
   end subroutine read_chart_group

   !> The i-th of n equally spaced values from lo to hi (n = 1: lo).
   pure real(wp) function grid_value(lo, hi, n, i)
      real(wp), intent(in) :: lo, hi  !! first and last value
      integer, intent(in) :: n, i  !! number of values; index 1 ... n
      if (n <= 1) then
         grid_value = lo
      else if (i == n) then
         grid_value = hi  ! exact end point, no round-off
      else if (abs(0.5_wp*hi - 0.5_wp*lo) > 0.25_wp*huge(1.0_wp)/real(n, wp)) then
         ! a range near the largest double (a reader refuses it later): hi − lo or its product
         ! with i − 1 would overflow, a convex combination cannot
         grid_value = (1.0_wp - real(i - 1, wp)/real(n - 1, wp))*lo + (real(i - 1, wp)/real(n - 1, wp))*hi
      else
         grid_value = lo + (hi - lo)*real(i - 1, wp)/real(n - 1, wp)
      end if
   end function grid_value

   !> (α, β) of point k of a grid, the points numbered row by row (α outer, β inner).
   pure function grid_point(grid, k) result(point)
      type(chart_grid_t), intent(in) :: grid  !! the grid
      integer(int64), intent(in) :: k  !! point index, 1 … n_alpha n_beta
      real(wp) :: point(2)
      integer :: i, j
      i = int((k - 1)/grid%n_beta) + 1
      j = int(k - int(i - 1, int64)*grid%n_beta)
      point = [grid_value(grid%alpha_min, grid%alpha_max, grid%n_alpha, i), &
               grid_value(grid%beta_min, grid%beta_max, grid%n_beta, j)]
   end function grid_point
end module hillstab_batch_scene_group_chart

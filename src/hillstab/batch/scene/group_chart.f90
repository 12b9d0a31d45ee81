!> The `&chart` group: an (α, β) grid, n values from min to max inclusive, equally spaced
!> (`alpha_scale = 'linear'`, the default) or geometric (`'log'`: min > 0). Read by the
!> chart, boundaries and lyapunov tasks (each may give its own defaults, e.g. the
!> lyapunov task's grid covers the physical domain). Every value of a grid comes from
!> `grid_value` (`grid_alpha`, `grid_beta`, `grid_point`), so that a run, its units (MPI,
!> checkpoints) and the C API give the same values to the bit.
!>
!>```fortran
!> type(chart_grid_t) :: grid
!> grid = chart_grid_t(0.0_wp, 9.8_wp, 3, -2.0_wp, 12.0_wp, 5)
!> print *, grid_point(grid, 7_int64)   ! the second β of the second α
!>```
module hillstab_batch_scene_group_chart
   use hillstab_core_kinds, only: wp, int64
   use hillstab_core_error, only: error_t
   use hillstab_core_text, only: lower_case, real_text, integer_text
   use hillstab_batch_scene_file, only: scene_file_t, fail, read_len
   use hillstab_batch_scene_declaration, only: new_group, group_t, group_values_t, group_reader_t, variable, var_real, &
      var_integer, var_name, &
      begin_group, next_item, end_group
   use hillstab_batch_scene_checks, only: check_range, check_alpha_domain
   use hillstab_hill_model, only: hill_model_t
   implicit none
   private
   public :: chart_grid_t, chart_group, read_chart_group, grid_value, grid_point, grid_size_text, grid_alpha, grid_beta
   public :: scale_linear, scale_log, scale_name, scale_refusal

   !> An axis of equally spaced values (`'linear'`).
   integer, parameter :: scale_linear = 0
   !> An axis of geometric values, min > 0 (`'log'`).
   integer, parameter :: scale_log = 1

   !> The (α, β) grid of a chart: n values from min to max inclusive (n = 1: min only).
   type :: chart_grid_t
      real(wp) :: alpha_min = 0.0_wp  !! first α
      real(wp) :: alpha_max = 0.0_wp  !! last α (elastic model: < π²)
      integer :: n_alpha = 1          !! number of α values
      real(wp) :: beta_min = 0.0_wp   !! first β
      real(wp) :: beta_max = 0.0_wp   !! last β
      integer :: n_beta = 1           !! number of β values
      integer :: alpha_scale = scale_linear  !! scale_linear or scale_log
      integer :: beta_scale = scale_linear   !! scale_linear or scale_log
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
      call group%add("alpha_scale", var_name, "", "linear (unset): equally spaced | log: geometric, alpha_min > 0", &
                     example="'log'")
      call group%add("beta_min", var_real, "-2.0", "first beta = g pi^2/(rho omega^2)")
      call group%add("beta_max", var_real, "12.0", "last beta, >= beta_min")
      call group%add("n_beta", var_integer, "200", "number of beta values, >= 1")
      call group%add("beta_scale", var_name, "", "linear (unset): equally spaced | log: geometric, beta_min > 0 "// &
                     "(not task boundaries)", &
                     example="'log'")
   end function chart_group

   !> Read and check `&chart` (the declaration `group` carries the task's defaults). A scale
   !> left at 'linear' is not written into the effective scene (the files of scenes that do
   !> not name it stay as they were).
   subroutine read_chart_group(file, group, model, grid, values, error)
      type(scene_file_t), intent(in) :: file  !! the scene file
      type(group_t), intent(in) :: group      !! the declaration (`chart_group`, maybe other defaults)
      class(hill_model_t), intent(in), optional :: model  !! the model (the domain of α; absent: a system)
      type(chart_grid_t), intent(out) :: grid  !! the grid
      type(group_values_t), intent(out) :: values  !! the effective values
      type(error_t), allocatable, intent(out) :: error  !! err_input naming file, group and variable
      real(wp) :: alpha_min, alpha_max, beta_min, beta_max
      integer :: n_alpha, n_beta
      character(len=read_len) :: alpha_scale, beta_scale
      integer :: alpha_kind, beta_kind
      namelist /chart/ alpha_min, alpha_max, n_alpha, alpha_scale, beta_min, beta_max, n_beta, beta_scale
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
      ! the corners, where the model is taken a point at a time (its β in its frequency, ...)
      call check_alpha_domain(file%path, model, group%name, "beta_min", alpha_min, error, beta=beta_min)
      if (.not. allocated(error)) call check_alpha_domain(file%path, model, group%name, "beta_min", alpha_max, error, &
                                                          beta=beta_min)
      if (.not. allocated(error)) call check_alpha_domain(file%path, model, group%name, "beta_max", alpha_min, error, &
                                                          beta=beta_max)
      if (.not. allocated(error)) call check_alpha_domain(file%path, model, group%name, "beta_max", alpha_max, error, &
                                                          beta=beta_max)
      if (allocated(error)) return
      call read_scale(file%path, group%name, "alpha", alpha_scale, alpha_min, values, alpha_kind, error)
      if (allocated(error)) return
      call read_scale(file%path, group%name, "beta", beta_scale, beta_min, values, beta_kind, error)
      if (allocated(error)) return
      grid = chart_grid_t(alpha_min, alpha_max, n_alpha, beta_min, beta_max, n_beta, alpha_kind, beta_kind)
   end subroutine read_chart_group

   !> The scale of axis `name` (`<name>_scale`): 'linear' (or unset) or 'log', the latter
   !> with `<name>_min` > 0 (and so every value of the axis); 'linear' is left out of the
   !> effective scene.
   subroutine read_scale(path, group, name, text, lo, values, scale, error)
      character(len=*), intent(in) :: path, group, name  !! the scene file, the group, the axis
      character(len=*), intent(in) :: text  !! the value read
      real(wp), intent(in) :: lo  !! the first value of the axis (<= its last)
      type(group_values_t), intent(inout) :: values  !! the effective values
      integer, intent(out) :: scale  !! scale_linear or scale_log
      type(error_t), allocatable, intent(out) :: error  !! err_input naming file, group and variable
      scale = scale_linear
      select case (lower_case(trim(adjustl(text))))
      case ("", "linear")
         call values%hide(name//"_scale")
      case ("log")
         scale = scale_log
         if (.not. (lo > 0.0_wp)) call fail(error, path, group, name//"_min", name//"_scale = 'log' needs "// &
            name//"_min > 0, got "//real_text(lo))
      case default
         call fail(error, path, group, name//"_scale", "must be 'linear' or 'log', got '"//trim(adjustl(text))//"'")
      end select
   end subroutine read_scale

   !> The name of a scale as a scene writes it ('linear', 'log').
   pure function scale_name(scale) result(name)
      integer, intent(in) :: scale  !! scale_linear or scale_log
      character(len=:), allocatable :: name
      name = merge("log   ", "linear", scale == scale_log)
      name = trim(name)
   end function scale_name

   !> Why the scale of an axis given by a caller (the C API) cannot be taken, "" when it
   !> can: a code that is neither scale_linear nor scale_log, or a log axis whose ends are
   !> not in (0, 1e300].
   function scale_refusal(name, scale, lo, hi) result(text)
      character(len=*), intent(in) :: name  !! the axis ("alpha", "beta")
      integer, intent(in) :: scale  !! the code given
      real(wp), intent(in) :: lo, hi  !! the ends of the axis (finite)
      character(len=:), allocatable :: text
      text = ""
      if (scale /= scale_linear .and. scale /= scale_log) then
         text = name//"_scale must be 0 (linear) or 1 (log), got "//integer_text(scale)
      else if (scale == scale_log .and. .not. (lo > 0.0_wp .and. hi > 0.0_wp .and. max(lo, hi) <= 1.0e300_wp)) then
         text = "a log "//name//" axis needs "//name//"_min and "//name//"_max in (0, 1e300], got "// &
                real_text(lo)//" and "//real_text(hi)
      end if
   end function scale_refusal

   !> The i-th α of a grid.
   pure real(wp) function grid_alpha(grid, i)
      type(chart_grid_t), intent(in) :: grid  !! the grid
      integer, intent(in) :: i  !! index 1 … n_alpha
      grid_alpha = grid_value(grid%alpha_min, grid%alpha_max, grid%n_alpha, i, grid%alpha_scale == scale_log)
   end function grid_alpha

   !> The j-th β of a grid.
   pure real(wp) function grid_beta(grid, j)
      type(chart_grid_t), intent(in) :: grid  !! the grid
      integer, intent(in) :: j  !! index 1 … n_beta
      grid_beta = grid_value(grid%beta_min, grid%beta_max, grid%n_beta, j, grid%beta_scale == scale_log)
   end function grid_beta

   !> The i-th of n equally spaced values from lo to hi (n = 1: lo); with `geometric`, of n
   !> geometric values (lo > 0): 10 to the i-th equally spaced value from log10 lo to
   !> log10 hi, the ends exact.
   pure real(wp) function grid_value(lo, hi, n, i, geometric)
      real(wp), intent(in) :: lo, hi  !! first and last value
      integer, intent(in) :: n, i  !! number of values; index 1 ... n
      logical, intent(in), optional :: geometric  !! geometric values (lo > 0); default .false.
      real(wp) :: t
      logical :: log_scale
      log_scale = .false.
      if (present(geometric)) log_scale = geometric
      if (n <= 1) then
         grid_value = lo
      else if (i == n) then
         grid_value = hi  ! exact end point, no round-off
      else if (log_scale .and. i == 1) then
         grid_value = lo  ! exact, as 10**log10(lo) may not be
      else if (log_scale) then
         ! decimal logarithms of values in (0, 1e15] are bounded: neither the difference nor
         ! the power overflows; powers of ten whose exponents the spacing hits come out exact
         ! (1e-3 to 1e3 in 7 values: 0.001, 0.01, ..., 1000)
         ! (the exponent as the linear values: a product then a quotient, no fused
         ! multiply-add, so that another language's a + (b - a)(i - 1)/(n - 1) gives the bits)
         t = log10(lo) + (log10(hi) - log10(lo))*real(i - 1, wp)/real(n - 1, wp)
         grid_value = 10.0_wp**t
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
      point = [grid_alpha(grid, i), grid_beta(grid, j)]
   end function grid_point
end module hillstab_batch_scene_group_chart

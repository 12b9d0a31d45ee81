!> A scene is one namelist file describing one run (task, model, method, grid, output).
!> This module reads and validates it into a `scene_t`; it computes nothing and
!> writes nothing. Every error names the file, the namelist group and the variable.
!>
!>```fortran
!> type(scene_t) :: scene
!> type(error_t), allocatable :: error
!> call read_scene("data/scenes/default_exact.nml", scene, error)
!> if (.not. allocated(error)) print '(a)', scene_namelist(scene)
!>```
!>
!> Groups: `&scene` (always), then the group of the task: `&chart`, `&points`,
!> `&coefficient` or `&series`; optionally `&physical` (the pendulum in SI units, in place of the
!> dimensionless ε and, for points and coefficient, of α and β). Group order in the file does not matter and other groups are
!> ignored, so one file may hold several. Reading tolerates `#` lines before a group,
!> which lets a run be repeated from the header of its own output file.
module hillstab_batch_scene
   use hillstab_core_kinds, only: wp, int64, pi, pi2
   use hillstab_core_error, only: error_t, set_error, err_input
   use hillstab_hill_coefficient, only: model_elastic, model_mathieu, model_name, sampling_endpoint, &
      sampling_average, sampling_name
   use hillstab_integrate_monodromy, only: method_t, method_auto, method_name, method_from_name, method_magnus4, &
      method_magnus6, method_rk, method_gsl
   use hillstab_batch_output, only: default_chart_columns, find_chart_columns, chart_columns_text, is_directory
   use hillstab_core_text, only: integer_text, lower => lower_case
   use hillstab_hill_units, only: physical_t, physical_alpha, physical_beta, physical_epsilon, physical_nu, &
      check_physical, equilibrium_length
   use, intrinsic :: iso_fortran_env, only: iostat_end
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite, ieee_usual, ieee_support_halting, &
      ieee_get_halting_mode, ieee_set_halting_mode, ieee_set_flag
   implicit none
   private
   public :: scene_t, chart_grid_t, coefficient_plan_t, series_plan_t, max_series_lines, read_scene, &
      scene_namelist, default_scene
   public :: task_chart, task_points, task_coefficient, task_boundaries, task_series, task_name
   public :: task_lyapunov, task_poincare, poincare_plan_t, max_poincare_orbits
   public :: grid_value, real_text, integer_text, read_text_line, max_coefficient_alphas, output_path, scene_columns
   public :: scene_header, grid_point

   integer, parameter :: task_chart = 1        !! stability chart over an (α, β) grid
   integer, parameter :: task_points = 2       !! the chart's columns at listed (α, β) points
   integer, parameter :: task_coefficient = 3  !! Q(τ) and its segmented version (the paper's Fig. 2)
   integer, parameter :: task_boundaries = 4   !! transition curves over the α grid of `&chart`
   integer, parameter :: task_series = 5       !! time series of the nonlinear pendulum
   integer, parameter :: task_lyapunov = 6     !! largest Lyapunov exponent over `&chart` or `&points`
   integer, parameter :: task_poincare = 7     !! Poincaré sections of orbits from a list of φ0

   !> Longest line of a scene or points file.
   integer, parameter, public :: max_line_length = 65536
   !> Bytes of a scene file read: its groups must lie within them (an output file given
   !> as scene has them in its header).
   integer(int64), parameter, public :: max_scene_bytes = 1048576
   !> Largest `n_alpha`, `n_beta`, `n_tau` (and every other `n_` count of a range).
   integer, parameter, public :: max_grid_count = 100000000
   !> Largest `n_segments`: bounds the work and memory of one point.
   integer, parameter, public :: max_segments = 100000
   !> Smallest `tolerance` accepted (methods reach the round-off level of double precision
   !> near 1e-16 relative to max(1, |S|); below this the answer could only be round-off limited).
   real(wp), parameter, public :: min_tolerance = 1.0e-15_wp
   !> Largest |α|, |β|, |τ| accepted (grid spacings, Q and the methods' scalings stay finite).
   real(wp), parameter, public :: max_magnitude = 1.0e15_wp
   !> Largest |α| + |β| for the integrating methods (magnus4, magnus6, rk, gsl).
   real(wp), parameter, public :: max_integrated_magnitude = 1.0e8_wp
   !> Largest |α|, |β| of task boundaries.
   real(wp), parameter, public :: max_boundaries_magnitude = 1.0e6_wp
   !> Smallest β of the tasks that simulate the pendulum (series, lyapunov, poincare):
   !> below it ω = √(g π²/(ρ β)) and the time scales overflow.
   real(wp), parameter, public :: min_pendulum_beta = 1.0e-8_wp
   !> Largest damping ε.
   real(wp), parameter, public :: max_epsilon = 100.0_wp
   !> Largest number of points in a points file.
   integer, parameter, public :: max_points = 1000000
   !> Largest number of α values in `&coefficient alphas`.
   integer, parameter :: max_coefficient_alphas = 64
   !> Length of the character variables read from a namelist (paths included).
   integer, parameter :: text_len = 4096
   !> Length of the character variables a namelist is read into (longer than text_len,
   !> so that a longer value is refused with a message instead of cut with a warning).
   integer, parameter :: read_len = 65536
   !> Marks the unused tail of the `alphas` list (a value no one types).
   real(wp), parameter :: unset_alpha = -huge(1.0_wp)

   !> The (α, β) grid of a chart: n values from min to max inclusive (n = 1: min only).
   type :: chart_grid_t
      real(wp) :: alpha_min = 0.0_wp    !! first α
      real(wp) :: alpha_max = 9.8_wp    !! last α (elastic model: < π²)
      integer :: n_alpha = 200          !! number of α values
      real(wp) :: beta_min = -2.0_wp    !! first β
      real(wp) :: beta_max = 12.0_wp    !! last β
      integer :: n_beta = 200           !! number of β values
   end type chart_grid_t

   !> What the coefficient task tabulates: Q(τ) at one β for a list of α.
   type :: coefficient_plan_t
      real(wp), allocatable :: alphas(:)  !! α of each curve
      real(wp) :: beta = 6.0_wp           !! β of every curve (the paper's Fig. 2 uses 6)
      real(wp) :: tau_min = 0.0_wp        !! first τ
      real(wp) :: tau_max = 2.0_wp        !! last τ (one period is 2)
      integer :: n_tau = 801              !! number of τ values
   end type coefficient_plan_t

   !> What the series task simulates (`&series`): the nonlinear pendulum at (α, β) from
   !> eq. (38), sampled `samples_per_period` times per radial period.
   type :: series_plan_t
      real(wp) :: alpha = 1.48_wp            !! α, in [0, π²)
      real(wp) :: beta = 2.47_wp             !! β, in (0, π²)
      real(wp) :: phi0 = 0.017_wp            !! initial angle [rad]
      integer :: periods = 50                !! radial periods to simulate
      integer :: samples_per_period = 100    !! output rows per radial period
      real(wp) :: r0 = 0.1_wp                !! natural length [m]
      real(wp) :: g = 9.81_wp                !! gravity [m/s²]
      real(wp) :: vx0 = 0.0_wp               !! initial horizontal velocity [m/s]
      real(wp) :: vz0 = 0.0_wp               !! initial downward velocity [m/s]
   end type series_plan_t

   !> The default grid of the lyapunov task: the physical domain 0 ≤ α < π², 0 < β < π²
   !> (the pendulum exists only there), 100 × 100.
   type(chart_grid_t), parameter :: lyapunov_default_grid = chart_grid_t(0.0_wp, 9.8_wp, 100, 0.1_wp, 9.8_wp, 100)

   !> Largest number of orbits (φ0 values) of a Poincaré section.
   integer, parameter :: max_poincare_orbits = 64

   !> The orbits of the poincare task (`&poincare`), each started at rest at one φ0.
   type :: poincare_plan_t
      real(wp), allocatable :: phi0s(:)   !! initial angles [rad], |φ0| < π
      !> .true.: every orbit has the energy of the `&series` start (the radius at rest is
      !> chosen for it); .false.: each starts at r = ρ − a as eq. (38)
      logical :: same_energy = .true.
   end type poincare_plan_t

   !> A series scene writing more data lines than this is refused.
   integer(int64), parameter :: max_series_lines = 100000000_int64

   !> One validated run description.
   type :: scene_t
      character(len=:), allocatable :: source       !! path of the scene file
      integer :: task = task_chart                  !! task_* constant
      integer :: model = model_elastic              !! model_elastic or model_mathieu
      type(method_t) :: method                      !! method, n_segments, sampling, tolerance
      real(wp) :: epsilon = 0.0_wp                  !! damping ε of eq. (46)
      character(len=:), allocatable :: output       !! prefix: files are <output>_<task>.dat (.bin)
      !> chart and points: the columns to write, blank-separated ("" = all the task offers)
      character(len=:), allocatable :: columns
      logical :: binary = .false.      !! chart and points: float64 records after a text header
      logical :: names_line = .false.  !! text: a line of column names after the `#` header
      type(chart_grid_t) :: chart                   !! task_chart
      character(len=:), allocatable :: points_file  !! task_points: the file of α β lines
      real(wp), allocatable :: points(:, :)         !! task_points: (2, n) α, β in file order
      type(coefficient_plan_t) :: coefficient       !! task_coefficient
      type(series_plan_t) :: series                 !! task_series (and lyapunov, poincare: the pendulum)
      !> For task_lyapunov, .true. over the points of `&points` (`&lyapunov over = 'points'`),
      !> .false. over the grid of `&chart`
      logical :: lyapunov_points = .false.
      type(poincare_plan_t) :: poincare             !! task_poincare
      !> The scene has a `&physical` group: ε comes from κ and ω, and the outputs add
      !> rates per second (ω is known)
      logical :: physical = .false.
      type(physical_t) :: pendulum                  !! `&physical` r0, g, omega, kappa (a: `amplitudes`)
      !> `&physical a` (m): the points (task points) or the curves (task coefficient) at
      !> these amplitudes and the given r0; empty when α and β come from the task's group
      real(wp), allocatable :: amplitudes(:)
   end type scene_t

   !> One `name = value(s)` item of a namelist group, cut out of the file text.
   type :: item_t
      character(len=:), allocatable :: name  !! variable name, lower case, without subscript
      character(len=:), allocatable :: text  !! the whole item as written
   end type item_t

   !> Floating-point halting modes saved while a read runs with halting off.
   type :: fpe_state_t
      logical :: can_halt = .false.                 !! halting can be controlled here
      logical :: halting(size(ieee_usual)) = .false. !! the modes to restore
   end type fpe_state_t

   !> State of one namelist group read. Each group routine reads its own namelist (the
   !> namelist is local to it) in this pattern, which passes no procedure around:
   !>
   !>```fortran
   !> call begin_group_read(unit, reader)
   !> read (unit, nml=chart, iostat=reader%ios, iomsg=reader%msg)
   !> do while (next_item(reader, unit, group))
   !>    read (reader%record, nml=chart, iostat=reader%stat, iomsg=reader%message)
   !> end do
   !> call end_group_read(reader, unit, scene%source, group, names, kinds, error)
   !>```
   !>
   !> When the group read fails, each item is tried alone to find the first bad one.
   type :: group_read_t
      type(fpe_state_t) :: fpe                     !! halting modes to restore
      integer :: ios = 0                           !! iostat of the group read
      character(len=512) :: msg = ""               !! iomsg of the group read
      type(item_t), allocatable :: items(:)        !! the items of the group (after a failed read)
      integer :: k = 0                             !! the item being tried
      integer :: stat = 0                          !! iostat of the item read
      character(len=:), allocatable :: record      !! `&group item /` for the item read
      character(len=512) :: message = ""           !! iomsg of the item read (unused)
      character(len=:), allocatable :: bad         !! the first item that fails alone
   end type group_read_t

contains

   !> Name of a task constant.
   pure function task_name(task) result(name)
      integer, intent(in) :: task  !! one of the task_* constants
      character(len=:), allocatable :: name
      select case (task)
      case (task_chart); name = "chart"
      case (task_points); name = "points"
      case (task_coefficient); name = "coefficient"
      case (task_boundaries); name = "boundaries"
      case (task_series); name = "series"
      case (task_lyapunov); name = "lyapunov"
      case (task_poincare); name = "poincare"
      case default; name = "unknown"
      end select
   end function task_name

   !> The file a scene's task writes: `<output>_<task>.dat` (`.bin` for format = 'binary').
   pure function output_path(scene) result(path)
      type(scene_t), intent(in) :: scene  !! the scene
      character(len=:), allocatable :: path
      if (scene%binary) then
         path = scene%output//"_"//task_name(scene%task)//".bin"
      else
         path = scene%output//"_"//task_name(scene%task)//".dat"
      end if
   end function output_path

   !> The i-th of n equally spaced values from lo to hi (n = 1: lo).
   pure real(wp) function grid_value(lo, hi, n, i)
      real(wp), intent(in) :: lo, hi  !! first and last value
      integer, intent(in) :: n, i  !! number of values; index 1 ... n
      if (n <= 1) then
         grid_value = lo
      else if (i == n) then
         grid_value = hi  ! exact end point, no round-off
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

   !> A scene with every default filled in; `output` defaults to the scene file's
   !> base name without extension (files land in the current directory).
   function default_scene(path, task) result(scene)
      character(len=*), intent(in) :: path  !! scene file path
      !> the task, when its defaults differ (lyapunov: the grid covers the physical domain)
      integer, intent(in), optional :: task
      type(scene_t) :: scene
      integer :: slash, dot
      scene%source = path
      if (present(task)) then
         scene%task = task
         if (task == task_lyapunov) scene%chart = lyapunov_default_grid
      end if
      scene%method = method_t(kind=method_auto, n_segments=2, sampling=sampling_endpoint, tolerance=1.0e-10_wp)
      slash = index(path, "/", back=.true.)
      dot = index(path(slash + 1:), ".", back=.true.)
      if (dot > 1) then
         scene%output = path(slash + 1:slash + dot - 1)
      else
         scene%output = path(slash + 1:)
      end if
      if (len(scene%output) == 0) scene%output = "hillstab"
      scene%points_file = ""
      scene%columns = ""
      scene%coefficient%alphas = [4.0_wp, 6.0_wp, 7.5_wp, 8.0_wp, 9.0_wp, 9.7_wp]
      scene%poincare%phi0s = [0.05_wp, 0.1_wp, 0.15_wp, 0.2_wp, 0.3_wp]  ! below 0.35 rad: states at rest at the default &series energy exist
      allocate (scene%amplitudes(0))
   end function default_scene

   !> Read and validate the scene in `path`: `&scene`, then the group of its task.
   subroutine read_scene(path, scene, error)
      character(len=*), intent(in) :: path       !! scene file
      type(scene_t), intent(out) :: scene        !! the validated scene
      type(error_t), allocatable, intent(out) :: error  !! err_input naming file, group and variable; unallocated on success
      integer :: unit
      scene = default_scene(path)
      call open_scene_copy(path, unit, error)
      if (allocated(error)) return
      call read_scene_group(unit, scene, error)
      if (.not. allocated(error)) then
         if (group_present(unit, "physical")) call read_physical_group(unit, scene, error)
      end if
      if (.not. allocated(error)) then
         select case (scene%task)
         case (task_chart, task_boundaries)
            call read_chart_group(unit, scene, error)
            if (.not. allocated(error) .and. scene%task == task_boundaries) call check_boundaries_cost(scene, error)
         case (task_points)
            call read_points_group(unit, scene, error)
         case (task_coefficient)
            call read_coefficient_group(unit, scene, error)
         case (task_series)
            call read_series_group(unit, scene, error)
         case (task_lyapunov)
            scene%chart = lyapunov_default_grid
            call read_series_group(unit, scene, error)
            if (.not. allocated(error)) call read_lyapunov_group(unit, scene, error)
            if (.not. allocated(error)) then
               if (scene%lyapunov_points) then
                  call read_points_group(unit, scene, error)
               else
                  call read_chart_group(unit, scene, error)
               end if
            end if
            if (.not. allocated(error)) call check_lyapunov_domain(scene, error)
         case (task_poincare)
            call read_series_group(unit, scene, error)
            if (.not. allocated(error)) call read_poincare_group(unit, scene, error)
         end select
      end if
      if (.not. allocated(error)) call check_columns(scene, error)
      if (.not. allocated(error)) call check_integration_cost(scene, error)
      close (unit)
   end subroutine read_scene

   !> Copy the scene file (at most its first max_scene_bytes, lines of at most
   !> max_line_length characters, a final newline added when missing) to a scratch file
   !> open on `unit`: the namelist reads then never run endlessly (`hillstab /dev/zero`)
   !> and an output file given as scene is read only as far as its header.
   subroutine open_scene_copy(path, unit, error)
      character(len=*), intent(in) :: path  !! the scene file
      integer, intent(out) :: unit          !! the copy, rewound
      type(error_t), allocatable, intent(out) :: error
      integer :: source, ios, line_number
      integer(int64) :: bytes
      character(len=512) :: msg
      character(len=:), allocatable :: line
      logical :: too_long
      if (is_directory(path)) then
         call set_error(error, err_input, path//": cannot read the scene file: it is a directory")
         return
      end if
      open (newunit=source, file=path, status="old", action="read", form="formatted", iostat=ios, iomsg=msg)
      if (ios /= 0) then
         call set_error(error, err_input, path//": cannot open the scene file: "//trim(msg))
         return
      end if
      open (newunit=unit, status="scratch", action="readwrite", form="formatted", iostat=ios, iomsg=msg)
      if (ios /= 0) then
         close (source)
         call set_error(error, err_input, path//": cannot make a scratch copy of the scene file: "//trim(msg))
         return
      end if
      bytes = 0
      line_number = 0
      do
         call read_text_line(source, line, ios, max_line_length, too_long)
         if (too_long) then
            call set_error(error, err_input, path//": line "//integer_text(line_number + 1)//" is longer than "// &
               integer_text(max_line_length)//" characters (not a scene file?)")
            exit
         end if
         if (ios /= 0 .and. len(line) == 0) exit
         line_number = line_number + 1
         bytes = bytes + len(line) + 1
         if (bytes > max_scene_bytes) exit  ! the groups must lie in the first max_scene_bytes
         write (unit, '(a)', iostat=ios, iomsg=msg) line
         if (ios /= 0) then
            call set_error(error, err_input, path//": cannot make a scratch copy of the scene file: "//trim(msg))
            exit
         end if
      end do
      close (source)
      if (allocated(error)) then
         close (unit)
         return
      end if
      rewind (unit)
   end subroutine open_scene_copy

   !> `&scene columns`: each name one of the columns this scene's file offers (which depend
   !> on the model, the damping and `&physical`), none twice, at least one.
   subroutine check_columns(scene, error)
      type(scene_t), intent(in) :: scene
      type(error_t), allocatable, intent(out) :: error
      integer, allocatable :: ids(:)
      if (scene%task /= task_chart .and. scene%task /= task_points) return
      call scene_columns(scene, ids, error)
   end subroutine check_columns

   !> The columns a chart or points file of this scene holds: `&scene columns` when given,
   !> else all the task offers (`default_chart_columns`).
   subroutine scene_columns(scene, ids, error)
      type(scene_t), intent(in) :: scene  !! a chart or points scene
      integer, allocatable, intent(out) :: ids(:)  !! indices into hillstab_batch_output's chart_column_names, in file order
      type(error_t), allocatable, intent(out) :: error  !! err_input naming &scene columns when a name is not offered
      integer, allocatable :: available(:)
      character(len=:), allocatable :: bad
      available = default_chart_columns(scene%epsilon > 0.0_wp, scene%model == model_elastic, scene%physical)
      if (len_trim(scene%columns) == 0) then
         ids = available
         return
      end if
      call find_chart_columns(scene%columns, available, ids, bad)
      if (len(bad) > 0) then
         call fail(error, scene%source, "scene", "columns", "'"//bad//"' is not a column of this file or is "// &
            "named twice (available: "//chart_columns_text(available)//")")
      else if (size(ids) == 0) then
         call fail(error, scene%source, "scene", "columns", "no column named")
      end if
   end subroutine scene_columns

   !> `&scene`: task, model, method and its settings, damping, output prefix.
   subroutine read_scene_group(unit, this, error)
      integer, intent(in) :: unit
      type(scene_t), intent(inout) :: this
      type(error_t), allocatable, intent(out) :: error
      character(len=read_len) :: task, model, method, sampling, output, columns, format
      integer :: n_segments
      real(wp) :: tolerance, epsilon
      logical :: names_line
      namelist /scene/ task, model, method, n_segments, sampling, tolerance, epsilon, output, columns, format, &
         names_line
      character(len=*), parameter :: group = "scene"
      character(len=*), parameter :: names(11) = [character(len=10) :: "task", "model", "method", &
         "n_segments", "sampling", "tolerance", "epsilon", "output", "columns", "format", "names_line"]
      character(len=*), parameter :: kinds(11) = [character(len=17) :: "a quoted name", "a quoted name", &
         "a quoted name", "an integer", "a quoted name", "a real number", "a real number", "a quoted path", &
         "quoted names", "a quoted name", ".true. or .false."]
      integer :: k
      type(group_read_t) :: reader

      task = task_name(this%task); model = model_name(this%model); method = method_name(this%method%kind)
      n_segments = this%method%n_segments; sampling = sampling_name(this%method%sampling)
      tolerance = this%method%tolerance; epsilon = this%epsilon; output = this%output
      columns = this%columns; format = merge("binary", "text  ", this%binary); names_line = this%names_line
      call begin_group_read(unit, reader)
      read (unit, nml=scene, iostat=reader%ios, iomsg=reader%msg)
      do while (next_item(reader, unit, group))
         read (reader%record, nml=scene, iostat=reader%stat, iomsg=reader%message)
      end do
      call end_group_read(reader, unit, this%source, group, names, kinds, error)
      if (allocated(error)) return

      this%task = -1
      do k = task_chart, task_poincare
         if (lower(trim(task)) == task_name(k)) this%task = k
      end do
      if (this%task < 0) then
         call fail(error, this%source, group, "task", "unknown task '"//trim(task)// &
            "' (expected chart, points, coefficient, boundaries, series, lyapunov or poincare)")
      end if
      if (allocated(error)) return

      select case (lower(trim(model)))
      case ("elastic"); this%model = model_elastic
      case ("mathieu"); this%model = model_mathieu
      case default
         call fail(error, this%source, group, "model", "unknown model '"//trim(model)//"' (expected elastic or mathieu)")
         return
      end select

      this%method%kind = method_from_name(lower(trim(method)))
      if (this%method%kind < 0) then
         call fail(error, this%source, group, "method", "unknown method '"//trim(method)// &
            "' (expected auto, formula, segments, magnus4, magnus6, rk or gsl)")
         return
      end if

      this%method%sampling = -1
      do k = sampling_endpoint, sampling_average
         if (lower(trim(sampling)) == sampling_name(k)) this%method%sampling = k
      end do
      if (this%method%sampling < 0) then
         call fail(error, this%source, group, "sampling", "unknown sampling '"//trim(sampling)// &
            "' (expected endpoint, midpoint or average)")
         return
      end if

      call require_positive_count(this%source, group, "n_segments", n_segments, 1, error)
      if (allocated(error)) return
      if (n_segments > max_segments) then
         call fail(error, this%source, group, "n_segments", "must be <= "//integer_text(max_segments)// &
            " (the work of one point), got "//integer_text(n_segments))
         return
      end if
      this%method%n_segments = n_segments

      call require_finite(this%source, group, "tolerance", tolerance, error)
      if (allocated(error)) return
      if (.not. (tolerance >= min_tolerance .and. tolerance < 1.0_wp)) then
         call fail(error, this%source, group, "tolerance", "must be >= "//real_text(min_tolerance)// &
            " (the smallest error double precision can be asked for) and < 1, got "//real_text(tolerance))
         return
      end if
      this%method%tolerance = tolerance

      call require_finite(this%source, group, "epsilon", epsilon, error)
      if (allocated(error)) return
      if (epsilon < 0.0_wp .or. epsilon > max_epsilon) then
         call fail(error, this%source, group, "epsilon", "damping must be >= 0 and <= "//real_text(max_epsilon)// &
            " (exp(epsilon) must stay far from overflow), got "//real_text(epsilon))
         return
      end if
      this%epsilon = epsilon
      if (this%task == task_boundaries .and. epsilon > 0.0_wp) then
         call fail(error, this%source, group, "epsilon", "task 'boundaries' draws the undamped curves: epsilon must be 0")
         return
      end if

      if (len_trim(output) == 0) then
         call fail(error, this%source, group, "output", "the output prefix is empty")
         return
      end if
      this%output = trim(output)

      select case (lower(trim(format)))
      case ("text"); this%binary = .false.
      case ("binary"); this%binary = .true.
      case default
         call fail(error, this%source, group, "format", "unknown format '"//trim(format)//"' (expected text or binary)")
         return
      end select
      this%columns = trim(adjustl(columns))
      this%names_line = names_line
      if (this%task /= task_chart .and. this%task /= task_points .and. (this%binary .or. len(this%columns) > 0)) then
         call fail(error, this%source, group, merge("format ", "columns", this%binary), &
            "columns and format = 'binary' apply to tasks chart and points")
         return
      end if
      if (this%binary .and. this%names_line) then
         call fail(error, this%source, group, "names_line", "a line of column names is for format = 'text' only")
         return
      end if
   end subroutine read_scene_group

   !> `&physical`: the pendulum in SI units (eqs. (4), (15), (24), (46)). Gives ε (from κ)
   !> and ω (rates per second); with `a` and `r0`, also the α and β of a points or
   !> coefficient task. Mixing it with the dimensionless values is an error naming both.
   subroutine read_physical_group(unit, scene, error)
      integer, intent(in) :: unit
      type(scene_t), intent(inout) :: scene
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: r0, g, omega, a(max_coefficient_alphas), kappa
      namelist /physical/ r0, g, omega, a, kappa
      character(len=*), parameter :: group = "physical"
      character(len=*), parameter :: names(5) = [character(len=5) :: "r0", "g", "omega", "a", "kappa"]
      character(len=*), parameter :: kinds(5) = [character(len=33) :: "a real number", "a real number", &
         "a real number", "a list of at most 64 real numbers", "a real number"]
      integer :: n, k
      character(len=:), allocatable :: variable
      type(group_read_t) :: reader
      logical :: given_a, given_r0
      type(physical_t) :: p
      type(error_t), allocatable :: cause

      r0 = scene%pendulum%r0; g = scene%pendulum%g; omega = scene%pendulum%omega; kappa = scene%pendulum%kappa
      a = unset_alpha
      call begin_group_read(unit, reader)
      read (unit, nml=physical, iostat=reader%ios, iomsg=reader%msg)
      do while (next_item(reader, unit, group))
         read (reader%record, nml=physical, iostat=reader%stat, iomsg=reader%message)
      end do
      call end_group_read(reader, unit, scene%source, group, names, kinds, error)
      if (allocated(error)) return

      if (.not. group_sets(unit, group, "omega")) then
         call fail(error, scene%source, group, "omega", "the radial angular frequency omega = sqrt(k/m) (rad/s) "// &
            "is required")
         return
      end if
      if (group_sets(unit, "scene", "epsilon")) then
         call fail(error, scene%source, group, "kappa", "give the damping either as &scene epsilon "// &
            "(dimensionless) or as &physical kappa (1/s), not both")
         return
      end if
      n = 0
      do k = 1, max_coefficient_alphas
         if (a(k) /= unset_alpha) n = k
      end do
      if (any(a(:n) == unset_alpha)) then
         call fail(error, scene%source, group, "a", "the list has gaps")
         return
      end if
      given_a = n > 0
      given_r0 = group_sets(unit, group, "r0")
      if (given_a .neqv. given_r0) then
         call fail(error, scene%source, group, merge("r0", "a ", given_a), &
            "a (amplitudes, m) and r0 (natural length, m) go together")
         return
      end if
      p = physical_t(r0=r0, g=g, omega=omega, a=0.0_wp, kappa=kappa)
      do k = 1, max(n, 1)
         if (n > 0) p%a = a(k)
         call check_physical(p, cause, variable)
         if (allocated(cause)) then
            call fail(error, scene%source, group, variable, cause%message//"; got r0 = "//real_text(p%r0)// &
               ", g = "//real_text(p%g)//", omega = "//real_text(p%omega)//", a = "//real_text(p%a)// &
               ", kappa = "//real_text(p%kappa))
            return
         end if
      end do
      if (given_a .and. scene%task == task_chart) then
         call fail(error, scene%source, group, "a", "a chart runs over the grid of &chart (alpha, beta); "// &
            "amplitudes a with r0 make the points of task 'points' or the curves of task 'coefficient'")
         return
      end if
      scene%physical = .true.
      scene%pendulum = p
      scene%pendulum%a = 0.0_wp
      scene%amplitudes = a(:n)
      scene%epsilon = physical_epsilon(p)
   end subroutine read_physical_group

   !> α (elastic model) or ν of eq. (21) (Mathieu model) and β of the pendulum at each
   !> amplitude of `&physical a`: a (2, n) array like the points of a points file.
   pure function physical_points(scene) result(points)
      type(scene_t), intent(in) :: scene
      real(wp), allocatable :: points(:, :)
      type(physical_t) :: p
      integer :: k
      allocate (points(2, size(scene%amplitudes)))
      p = scene%pendulum
      do k = 1, size(scene%amplitudes)
         p%a = scene%amplitudes(k)
         if (scene%model == model_mathieu) then
            points(1, k) = physical_nu(p)
         else
            points(1, k) = physical_alpha(p)
         end if
         points(2, k) = physical_beta(p)
      end do
   end function physical_points

   !> `&chart`: the (α, β) grid.
   subroutine read_chart_group(unit, scene, error)
      integer, intent(in) :: unit
      type(scene_t), intent(inout) :: scene
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: alpha_min, alpha_max, beta_min, beta_max
      integer :: n_alpha, n_beta
      namelist /chart/ alpha_min, alpha_max, n_alpha, beta_min, beta_max, n_beta
      character(len=*), parameter :: group = "chart"
      character(len=*), parameter :: names(6) = [character(len=9) :: "alpha_min", "alpha_max", "n_alpha", &
         "beta_min", "beta_max", "n_beta"]
      character(len=*), parameter :: kinds(6) = [character(len=13) :: "a real number", "a real number", &
         "an integer", "a real number", "a real number", "an integer"]
      type(group_read_t) :: reader

      alpha_min = scene%chart%alpha_min; alpha_max = scene%chart%alpha_max; n_alpha = scene%chart%n_alpha
      beta_min = scene%chart%beta_min; beta_max = scene%chart%beta_max; n_beta = scene%chart%n_beta
      call begin_group_read(unit, reader)
      read (unit, nml=chart, iostat=reader%ios, iomsg=reader%msg)
      do while (next_item(reader, unit, group))
         read (reader%record, nml=chart, iostat=reader%stat, iomsg=reader%message)
      end do
      call end_group_read(reader, unit, scene%source, group, names, kinds, error)
      if (allocated(error)) return

      call check_range(scene%source, group, "alpha", alpha_min, alpha_max, n_alpha, error)
      if (allocated(error)) return
      call check_alpha_domain(scene, group, "alpha_min", alpha_min, error)
      if (allocated(error)) return
      call check_alpha_domain(scene, group, "alpha_max", alpha_max, error)
      if (allocated(error)) return
      call check_range(scene%source, group, "beta", beta_min, beta_max, n_beta, error)
      if (allocated(error)) return
      scene%chart = chart_grid_t(alpha_min, alpha_max, n_alpha, beta_min, beta_max, n_beta)
   end subroutine read_chart_group

   !> `&points`: the file of (α, β) points, read here.
   subroutine read_points_group(unit, scene, error)
      integer, intent(in) :: unit
      type(scene_t), intent(inout) :: scene
      type(error_t), allocatable, intent(out) :: error
      character(len=read_len) :: file
      namelist /points/ file
      character(len=*), parameter :: group = "points"
      character(len=*), parameter :: names(1) = [character(len=4) :: "file"]
      character(len=*), parameter :: kinds(1) = [character(len=13) :: "a quoted path"]
      type(group_read_t) :: reader

      if (size(scene%amplitudes) > 0) then
         ! the points are the pendulum's amplitudes: &points is optional and may not name a file
         if (group_sets(unit, group, "file")) then
            call fail(error, scene%source, group, "file", "the points come either from &points file (alpha, beta) "// &
               "or from &physical a and r0, not both")
            return
         end if
         scene%points = physical_points(scene)
         return
      end if
      file = scene%points_file
      call begin_group_read(unit, reader)
      read (unit, nml=points, iostat=reader%ios, iomsg=reader%msg)
      do while (next_item(reader, unit, group))
         read (reader%record, nml=points, iostat=reader%stat, iomsg=reader%message)
      end do
      call end_group_read(reader, unit, scene%source, group, names, kinds, error)
      if (allocated(error)) return
      if (len_trim(file) == 0) then
         call fail(error, scene%source, group, "file", "no points file given")
         return
      end if
      scene%points_file = trim(file)
      call read_points_file(scene, error)
   end subroutine read_points_group

   !> `&coefficient`: α list, β, τ range.
   subroutine read_coefficient_group(unit, scene, error)
      integer, intent(in) :: unit
      type(scene_t), intent(inout) :: scene
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: alphas(max_coefficient_alphas), beta, tau_min, tau_max
      integer :: n_tau
      namelist /coefficient/ alphas, beta, n_tau, tau_min, tau_max
      character(len=*), parameter :: group = "coefficient"
      character(len=*), parameter :: names(5) = [character(len=7) :: "alphas", "beta", "n_tau", "tau_min", "tau_max"]
      character(len=*), parameter :: kinds(5) = [character(len=33) :: "a list of at most 64 real numbers", "a real number", &
         "an integer", "a real number", "a real number"]
      integer :: n, k
      type(group_read_t) :: reader

      ! a namelist read overwrites only the elements given: start from an empty list
      alphas = unset_alpha
      beta = scene%coefficient%beta; n_tau = scene%coefficient%n_tau
      tau_min = scene%coefficient%tau_min; tau_max = scene%coefficient%tau_max
      if (size(scene%amplitudes) > 0) then
         ! the curves are the pendulum's amplitudes: &coefficient is optional and gives only tau
         do k = 1, 2
            if (group_sets(unit, group, trim(names(k)))) then
               call fail(error, scene%source, group, trim(names(k)), "alpha and beta come either from "// &
                  "&coefficient alphas, beta or from &physical a and r0, not both")
               return
            end if
         end do
         if (.not. group_present(unit, group)) then
            scene%coefficient = coefficient_plan_t(physical_points_alphas(), physical_points_beta(), tau_min, tau_max, &
                                                   n_tau)
            return
         end if
      end if
      call begin_group_read(unit, reader)
      read (unit, nml=coefficient, iostat=reader%ios, iomsg=reader%msg)
      do while (next_item(reader, unit, group))
         read (reader%record, nml=coefficient, iostat=reader%stat, iomsg=reader%message)
      end do
      call end_group_read(reader, unit, scene%source, group, names, kinds, error)
      if (allocated(error)) return
      if (size(scene%amplitudes) > 0) then
         n = size(scene%amplitudes)
         alphas(:n) = physical_points_alphas()
         beta = physical_points_beta()
      end if

      do k = 1, max_coefficient_alphas
         call require_finite_or_unset(k, error)
         if (allocated(error)) return
      end do
      n = 0
      do k = max_coefficient_alphas, 1, -1
         if (alphas(k) /= unset_alpha) then
            n = k
            exit
         end if
      end do
      if (n == 0) then
         n = size(scene%coefficient%alphas)
         alphas(:n) = scene%coefficient%alphas
      else if (any(alphas(:n) == unset_alpha)) then
         call fail(error, scene%source, group, "alphas", "the list has gaps")
         return
      end if
      do k = 1, n
         call check_alpha_domain(scene, group, "alphas", alphas(k), error)
         if (allocated(error)) return
      end do
      call require_finite(scene%source, group, "beta", beta, error)
      if (allocated(error)) return
      call require_bounded(scene%source, group, "beta", beta, error)
      if (allocated(error)) return
      do k = 1, n
         call require_bounded(scene%source, group, "alphas", alphas(k), error)
         if (allocated(error)) return
      end do
      call check_range(scene%source, group, "tau", tau_min, tau_max, n_tau, error)
      if (allocated(error)) return
      scene%coefficient = coefficient_plan_t(alphas(:n), beta, tau_min, tau_max, n_tau)
   contains
      function physical_points_alphas() result(values)
         real(wp), allocatable :: values(:)
         real(wp), allocatable :: points(:, :)
         points = physical_points(scene)
         values = points(1, :)
      end function physical_points_alphas
      real(wp) function physical_points_beta()
         real(wp), allocatable :: points(:, :)
         points = physical_points(scene)
         physical_points_beta = points(2, 1)
      end function physical_points_beta
      subroutine require_finite_or_unset(k, error)
         integer, intent(in) :: k
         type(error_t), allocatable, intent(out) :: error
         if (.not. ieee_is_finite(alphas(k))) then
            call fail(error, scene%source, group, "alphas", "value "//integer_text(k)//" is not a finite number")
         end if
      end subroutine require_finite_or_unset
   end subroutine read_coefficient_group

   !> `&series`: the pendulum, its start and the sampling (contract names of the task).
   subroutine read_series_group(unit, scene, error)
      integer, intent(in) :: unit
      type(scene_t), intent(inout) :: scene
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: alpha, beta, phi0, r0, g, vx0, vz0
      integer :: periods, samples_per_period
      namelist /series/ alpha, beta, phi0, periods, samples_per_period, r0, g, vx0, vz0
      character(len=*), parameter :: group = "series"
      character(len=*), parameter :: names(9) = [character(len=18) :: "alpha", "beta", "phi0", "periods", &
         "samples_per_period", "r0", "g", "vx0", "vz0"]
      character(len=*), parameter :: kinds(9) = [character(len=13) :: "a real number", "a real number", &
         "a real number", "an integer", "an integer", "a real number", "a real number", "a real number", &
         "a real number"]
      real(wp) :: values(7)
      integer :: k
      type(group_read_t) :: reader
      associate (plan => scene%series)
         alpha = plan%alpha; beta = plan%beta; phi0 = plan%phi0; periods = plan%periods
         samples_per_period = plan%samples_per_period; r0 = plan%r0; g = plan%g; vx0 = plan%vx0; vz0 = plan%vz0
      end associate
      call begin_group_read(unit, reader)
      read (unit, nml=series, iostat=reader%ios, iomsg=reader%msg)
      do while (next_item(reader, unit, group))
         read (reader%record, nml=series, iostat=reader%stat, iomsg=reader%message)
      end do
      call end_group_read(reader, unit, scene%source, group, names, kinds, error)
      if (allocated(error)) return
      values = [alpha, beta, phi0, r0, g, vx0, vz0]
      do k = 1, 7
         call require_finite(scene%source, group, trim(names(merge(k, k + 2, k <= 3))), values(k), error)
         if (allocated(error)) return
      end do
      if (scene%physical) then
         call fail(error, scene%source, "physical", "r0", "the series task takes r0 and g in &series and the "// &
            "damping as &scene epsilon; leave out &physical")
      else if (scene%model /= model_elastic) then
         call fail(error, scene%source, "scene", "model", "the series task simulates the elastic pendulum: "// &
            "model must be 'elastic'")
      else if (alpha < 0.0_wp .or. alpha >= pi2) then
         call fail(error, scene%source, group, "alpha", "must lie in [0, pi**2 = "//real_text(pi2)// &
            ") (amplitude a < rho), got "//real_text(alpha))
      else if (beta <= 0.0_wp .or. beta >= pi2) then
         call fail(error, scene%source, group, "beta", "must lie in (0, pi**2 = "//real_text(pi2)// &
            "), the physical domain (r0 > 0), got "//real_text(beta))
      else if (beta < min_pendulum_beta) then
         call fail(error, scene%source, group, "beta", "must be >= 1.0e-8 (smaller values make the "// &
            "pendulum's time scales overflow), got "//real_text(beta))
      else if (periods < 1) then
         call fail(error, scene%source, group, "periods", "must be >= 1, got "//integer_text(periods))
      else if (samples_per_period < 1) then
         call fail(error, scene%source, group, "samples_per_period", "must be >= 1, got "// &
            integer_text(samples_per_period))
      else if (.not. r0 > 0.0_wp) then
         call fail(error, scene%source, group, "r0", "the natural length must be > 0, got "//real_text(r0))
      else if (.not. g > 0.0_wp) then
         call fail(error, scene%source, group, "g", "gravity must be > 0, got "//real_text(g))
      else if (phi0 /= 0.0_wp .and. (abs(phi0) < 1.0e-300_wp .or. abs(phi0) > 1.0e3_wp)) then
         call fail(error, scene%source, group, "phi0", "must be 0 or lie in [1e-300, 1e3] in magnitude, got "// &
            real_text(phi0))
      else if (r0 < 1.0e-50_wp .or. r0 > 1.0e50_wp .or. g < 1.0e-50_wp .or. g > 1.0e50_wp) then
         call fail(error, scene%source, group, merge("r0", "g ", r0 < 1.0e-50_wp .or. r0 > 1.0e50_wp), &
            "must lie in [1e-50, 1e50]")
      else if (max(abs(vx0), abs(vz0)) > 1.0e50_wp) then
         call fail(error, scene%source, group, merge("vx0", "vz0", abs(vx0) > 1.0e50_wp), "must lie in [-1e50, 1e50]")
      else if (int(periods, int64)*samples_per_period + 1 > max_series_lines) then
         call fail(error, scene%source, group, "periods", "periods * samples_per_period + 1 = "// &
            integer_text(int(periods, int64)*samples_per_period + 1)// &
            " data lines exceed the limit of 1e8; lower periods or samples_per_period")
      end if
      if (allocated(error)) return
      scene%series = series_plan_t(alpha, beta, phi0, periods, samples_per_period, r0, g, vx0, vz0)
   end subroutine read_series_group

   !> Read the points file: one `alpha beta` pair per line, `#` starts a comment,
   !> blank lines are skipped, further columns are ignored. A line is parsed as text:
   !> its first two blank-separated fields must be plain numbers (no list-directed
   !> shortcuts such as `/`, `,`, `3*`); at most max_points points, lines of at most
   !> max_line_length characters.
   subroutine read_points_file(scene, error)
      type(scene_t), intent(inout) :: scene
      type(error_t), allocatable, intent(out) :: error
      character(len=*), parameter :: group = "points"
      integer :: unit, ios, line_number, n, hash
      character(len=512) :: msg
      character(len=:), allocatable :: line, where
      real(wp) :: pair(2)
      real(wp), allocatable :: found(:, :)
      logical :: too_long

      if (is_directory(scene%points_file)) then
         call fail(error, scene%source, group, "file", "'"//scene%points_file//"' is a directory, not a points file")
         return
      end if
      open (newunit=unit, file=scene%points_file, status="old", action="read", iostat=ios, iomsg=msg)
      if (ios /= 0) then
         call fail(error, scene%source, group, "file", "cannot open '"//scene%points_file//"': "//trim(msg))
         return
      end if
      allocate (found(2, 16))
      n = 0
      line_number = 0
      do
         call read_text_line(unit, line, ios, max_line_length, too_long)
         if (ios /= 0 .and. .not. too_long) exit
         line_number = line_number + 1
         where = "'"//scene%points_file//"' line "//integer_text(line_number)
         if (too_long) then
            call fail(error, scene%source, group, "file", where//": longer than "// &
               integer_text(max_line_length)//" characters")
            exit
         end if
         hash = index(line, "#")
         if (hash > 0) line = line(:hash - 1)
         if (len_trim(line) == 0) cycle
         call parse_pair(line, pair, ios)
         if (ios /= 0) then
            call fail(error, scene%source, group, "file", where//": expected two numbers 'alpha beta' "// &
               "(then optional further columns), got '"//shortened(trim(line))//"'")
            exit
         end if
         if (.not. (ieee_is_finite(pair(1)) .and. ieee_is_finite(pair(2)))) then
            call fail(error, scene%source, group, "file", where//": alpha and beta must be finite numbers, got '"// &
               shortened(trim(line))//"'")
            exit
         end if
         if (max(abs(pair(1)), abs(pair(2))) > max_magnitude) then
            call fail(error, scene%source, group, "file", where//": alpha and beta must lie in ["// &
               real_text(-max_magnitude)//", "//real_text(max_magnitude)//"], got '"//shortened(trim(line))//"'")
            exit
         end if
         call check_alpha_domain(scene, group, "file", pair(1), error, where)
         if (allocated(error)) exit
         if (n == max_points) then
            call fail(error, scene%source, group, "file", where//": more than "//integer_text(max_points)// &
               " points (split the file, or use task chart for a grid)")
            exit
         end if
         if (n == size(found, 2)) found = reshape(found, [2, 2*n], pad=[0.0_wp])
         n = n + 1
         found(:, n) = pair
      end do
      close (unit)
      if (allocated(error)) return
      if (n == 0) then
         call fail(error, scene%source, group, "file", "'"//scene%points_file//"' holds no points")
         return
      end if
      scene%points = found(:, :n)
   end subroutine read_points_file

   !> The first two fields of `line` (separated by blanks or one comma) as numbers; `ios` /= 0
   !> unless both are plain decimal numbers ([sign] digits [. digits] [exponent], or nan/inf).
   subroutine parse_pair(line, pair, ios)
      character(len=*), intent(in) :: line
      real(wp), intent(out) :: pair(2)
      integer, intent(out) :: ios
      integer :: k, first, last
      type(fpe_state_t) :: fpe
      pair = 0.0_wp
      last = 0
      do k = 1, 2
         first = last + 1
         do while (first <= len(line))
            if (.not. is_blank(line(first:first))) exit
            first = first + 1
         end do
         if (k == 2 .and. first <= len(line)) then
            ! one comma may separate the two numbers
            if (line(first:first) == ",") then
               first = first + 1
               do while (first <= len(line))
                  if (.not. is_blank(line(first:first))) exit
                  first = first + 1
               end do
            end if
         end if
         last = first
         do while (last <= len(line))
            if (is_blank(line(last:last)) .or. line(last:last) == ",") exit
            last = last + 1
         end do
         last = last - 1
         if (first > len(line) .or. .not. is_number(line(first:last))) then
            ios = 1
            return
         end if
         call halting_off(fpe)
         read (line(first:last), *, iostat=ios) pair(k)
         call halting_restore(fpe)
         if (ios /= 0) return
      end do
   end subroutine parse_pair

   elemental logical function is_blank(c)
      character, intent(in) :: c
      is_blank = c == " " .or. c == achar(9) .or. c == achar(13)
   end function is_blank

   !> Whether `text` is one plain number: [sign] digits [. [digits]] or . digits, then an
   !> optional exponent [eEdD] [sign] digits; or [sign] nan / inf / infinity.
   pure logical function is_number(text)
      character(len=*), intent(in) :: text
      integer :: i, n_digits
      character(len=:), allocatable :: low
      is_number = .false.
      if (len(text) == 0) return
      i = 1
      if (index("+-", text(1:1)) > 0) i = 2
      low = lower(text(i:))
      if (low == "nan" .or. low == "inf" .or. low == "infinity") then
         is_number = .true.
         return
      end if
      n_digits = 0
      do while (i <= len(text))
         if (.not. is_digit(text(i:i))) exit
         i = i + 1; n_digits = n_digits + 1
      end do
      if (i <= len(text)) then
         if (text(i:i) == ".") then
            i = i + 1
            do while (i <= len(text))
               if (.not. is_digit(text(i:i))) exit
               i = i + 1; n_digits = n_digits + 1
            end do
         end if
      end if
      if (n_digits == 0) return
      if (i <= len(text)) then
         if (index("eEdD", text(i:i)) == 0) return
         i = i + 1
         if (i <= len(text)) then
            if (index("+-", text(i:i)) > 0) i = i + 1
         end if
         n_digits = 0
         do while (i <= len(text))
            if (.not. is_digit(text(i:i))) exit
            i = i + 1; n_digits = n_digits + 1
         end do
         if (n_digits == 0) return
      end if
      is_number = i > len(text)
   end function is_number

   elemental logical function is_digit(c)
      character, intent(in) :: c
      is_digit = c >= "0" .and. c <= "9"
   end function is_digit

   !> At most 80 characters of `text` for a message (then "...").
   pure function shortened(text) result(short)
      character(len=*), intent(in) :: text
      character(len=:), allocatable :: short
      if (len(text) <= 80) then
         short = text
      else
         short = text(:77)//"..."
      end if
   end function shortened

   !> Switch halting on overflow/invalid/divide-by-zero off (reading `1e400` or `nan`
   !> must give a message, not a trap, even in a build compiled with -ffpe-trap).
   subroutine halting_off(state)
      type(fpe_state_t), intent(out) :: state  !! the modes to restore
      integer :: k
      state%can_halt = .true.
      do k = 1, size(ieee_usual)
         state%can_halt = state%can_halt .and. ieee_support_halting(ieee_usual(k))
      end do
      if (state%can_halt) then
         call ieee_get_halting_mode(ieee_usual, state%halting)
         call ieee_set_halting_mode(ieee_usual, .false.)
      end if
   end subroutine halting_off

   !> Clear the flags raised meanwhile and restore the halting modes.
   subroutine halting_restore(state)
      type(fpe_state_t), intent(in) :: state  !! from halting_off
      call ieee_set_flag(ieee_usual, .false.)
      if (state%can_halt) call ieee_set_halting_mode(ieee_usual, state%halting)
   end subroutine halting_restore

   !> Start a group read: halting off, the file rewound.
   subroutine begin_group_read(unit, reader)
      integer, intent(in) :: unit                  !! the scene file
      type(group_read_t), intent(out) :: reader
      call halting_off(reader%fpe)
      rewind (unit)
   end subroutine begin_group_read

   !> After a failed group read (`reader%ios` > 0): set `reader%record` to the next item
   !> alone and return true, until an item fails alone (`reader%stat` /= 0) or none is left.
   logical function next_item(reader, unit, group)
      type(group_read_t), intent(inout) :: reader
      integer, intent(in) :: unit                  !! the scene file
      character(len=*), intent(in) :: group        !! group name
      next_item = .false.
      if (reader%ios <= 0) return
      if (.not. allocated(reader%items)) then
         call group_items(unit, group, reader%items)
         reader%bad = ""
      else if (reader%stat /= 0) then
         reader%bad = reader%items(reader%k)%text
         return
      end if
      reader%k = reader%k + 1
      if (reader%k > size(reader%items)) return
      reader%record = "&"//group//" "//reader%items(reader%k)%text//" /"
      reader%stat = 0
      next_item = .true.
   end function next_item

   !> End a group read: halting restored, then its outcome checked (`check_read`, with the
   !> first item that fails alone: "" when none does, none when the group read succeeded).
   subroutine end_group_read(reader, unit, path, group, names, kinds, error)
      type(group_read_t), intent(inout) :: reader
      integer, intent(in) :: unit               !! the scene file
      character(len=*), intent(in) :: path, group
      character(len=*), intent(in) :: names(:)  !! variables of the group
      character(len=*), intent(in) :: kinds(:)  !! what each variable holds, for the message
      type(error_t), allocatable, intent(out) :: error  !! err_input naming file, group and variable
      call halting_restore(reader%fpe)
      call check_read(unit, path, group, names, kinds, reader%ios, reader%msg, reader%bad, error)
   end subroutine end_group_read

   !> Turn the status of a namelist read into an error naming file, group and variable.
   subroutine check_read(unit, path, group, names, kinds, ios, msg, bad, error)
      integer, intent(in) :: unit               !! the scene file
      character(len=*), intent(in) :: path, group
      character(len=*), intent(in) :: names(:)  !! variables of the group
      character(len=*), intent(in) :: kinds(:)  !! what each variable holds, for the message
      integer, intent(in) :: ios                !! iostat of the group read
      character(len=*), intent(in) :: msg       !! iomsg of the group read
      character(len=:), allocatable, intent(in) :: bad  !! the first item that fails alone, if any
      type(error_t), allocatable, intent(out) :: error
      integer :: k, eq
      character(len=:), allocatable :: name, body, next
      logical :: found, closed
      if (ios == 0) then
         call check_item_values(unit, path, group, error)
         return
      end if
      call locate_group(unit, group, found, body, closed, next)
      ! a closed group on the file's last line without a newline: gfortran has read every
      ! value up to the '/' and then meets the end of the file
      if (ios == iostat_end .and. found .and. closed) return
      if (found .and. .not. closed) then
         if (len(next) > 0) then
            call fail(error, path, group, open_item_name(body), "the group is not closed: no '/' before '&"// &
               next//"'"//open_quote_note(body))
         else
            call fail(error, path, group, open_item_name(body), "the group is not closed: no '/' before the end "// &
               "of the file"//open_quote_note(body))
         end if
         return
      end if
      if (ios == iostat_end) then
         call set_error(error, err_input, path//": &"//group//": the group is missing (no '&"//group// &
            " ... /' in the file)")
         return
      end if
      if (allocated(bad)) then
         if (len(bad) > 0) then
            eq = index(bad, "=")
            name = item_name(bad)
            do k = 1, size(names)
               if (name == trim(names(k))) then
                  call fail(error, path, group, name, "cannot read "//trim(adjustl(bad(eq + 1:)))// &
                     " as "//trim(kinds(k)))
                  return
               end if
            end do
            call fail(error, path, group, name, "unknown variable (the group has: "//joined(names)//")")
            return
         end if
      end if
      ! no single item fails alone: name the variable the run-time message names, else the
      ! group's first item
      name = ""
      do k = 1, size(names)
         if (index(" "//lower(msg)//" ", " "//trim(names(k))//" ") > 0) then
            name = trim(names(k))
            exit
         end if
      end do
      if (len(name) == 0 .and. allocated(bad)) then
         if (len(bad) > 0) name = item_name(bad)
      end if
      if (len(name) == 0) then
         name = first_word(body)
         if (len(name) == 0) name = "(syntax)"
      end if
      call fail(error, path, group, name, "cannot read the group here: "//trim(msg))
   end subroutine check_read

   !> The name of the item in which a group body leaves a string open (else its last item,
   !> else "(syntax)").
   function open_item_name(body) result(name)
      character(len=*), intent(in) :: body
      character(len=:), allocatable :: name
      character :: quote
      integer :: i, opened, eq, j
      quote = " "
      opened = 0
      do i = 1, len(body)
         if (quote == " " .and. (body(i:i) == "'" .or. body(i:i) == '"')) opened = i
         call track_quote(body(i:i), quote)
      end do
      if (quote == " ") opened = len(body) + 1
      ! the last '=' before the open quote (or the end), and the name before it
      eq = index(body(:opened - 1), "=", back=.true.)
      name = "(syntax)"
      if (eq <= 1) return
      j = eq - 1
      do while (j >= 1)
         if (body(j:j) /= " ") exit
         j = j - 1
      end do
      i = j
      do while (i > 1)
         if (.not. is_name_char(body(i - 1:i - 1))) exit
         i = i - 1
      end do
      if (j >= i .and. j >= 1) name = lower(body(i:j))
   end function open_item_name

   !> ", a string is not terminated" when the body leaves a quote open, else "".
   function open_quote_note(body) result(note)
      character(len=*), intent(in) :: body
      character(len=:), allocatable :: note
      character :: quote
      integer :: i
      quote = " "
      do i = 1, len(body)
         call track_quote(body(i:i), quote)
      end do
      note = ""
      if (quote /= " ") note = " (a string is not terminated)"
   end function open_quote_note

   !> The first name in a group body (letters, digits, underscores), lower case.
   pure function first_word(body) result(word)
      character(len=*), intent(in) :: body
      character(len=:), allocatable :: word
      integer :: i, j
      word = ""
      do i = 1, len(body)
         if (is_letter(body(i:i))) exit
      end do
      if (i > len(body)) return
      j = i
      do while (j < len(body))
         if (.not. is_name_char(body(j + 1:j + 1))) exit
         j = j + 1
      end do
      word = lower(body(i:j))
   end function first_word

   !> After a group read that succeeded: refuse an item without a value (`beta_max = -,`
   !> reads as "keep the default") and a value longer than the strings read (4096 characters).
   subroutine check_item_values(unit, path, group, error)
      integer, intent(in) :: unit
      character(len=*), intent(in) :: path, group
      type(error_t), allocatable, intent(out) :: error
      type(item_t), allocatable :: items(:)
      character(len=:), allocatable :: value
      integer :: k, eq
      call group_items(unit, group, items)
      do k = 1, size(items)
         eq = index(items(k)%text, "=")
         value = trim(adjustl(items(k)%text(eq + 1:)))
         do while (len(value) > 0)
            if (value(len(value):) /= ",") exit
            value = trim(value(:len(value) - 1))
         end do
         if (value == "" .or. value == "+" .or. value == "-") then
            call fail(error, path, group, items(k)%name, "no value after '=' (got '"// &
               trim(adjustl(items(k)%text(eq + 1:)))//"')")
            return
         end if
         if (len(value) > text_len + 2) then
            call fail(error, path, group, items(k)%name, "value longer than "//integer_text(text_len)//" characters")
            return
         end if
      end do
   end subroutine check_item_values

   !> Find the first `&group` of the file (at the start of a line or after a blank, so
   !> `# &group` in output headers counts; `!` comments removed) and its body up to the
   !> closing `/` outside quotes. A group is not closed when another `&name` comes
   !> before its `/` (`next` is then that name) or when the file ends first (`next` = "").
   subroutine locate_group(unit, group, found, body, closed, next)
      integer, intent(in) :: unit
      character(len=*), intent(in) :: group
      logical, intent(out) :: found    !! the file has `&group`
      character(len=:), allocatable, intent(out) :: body  !! text between the name and the `/`
      logical, intent(out) :: closed   !! a `/` ends the group
      character(len=:), allocatable, intent(out) :: next  !! the group met before any `/`
      character(len=:), allocatable :: text, line
      integer :: ios, i, j, start
      character :: quote
      found = .false.
      closed = .false.
      body = ""
      next = ""
      text = ""
      rewind (unit)
      do
         call read_text_line(unit, line, ios)
         if (ios /= 0) exit
         ! in an output file the scene ends where the columns are named: the data that
         ! follow (raw bytes in a binary file) are no scene text
         if (index(line, "# columns:") == 1) exit
         text = text//strip_comment(line)//" "
      end do
      start = 0
      do i = 1, len(text) - len(group) - 1
         if (text(i:i) /= "&") cycle
         if (i > 1) then
            if (text(i - 1:i - 1) /= " ") cycle
         end if
         if (lower(text(i + 1:i + len(group))) /= lower(group)) cycle
         if (index(" /,", text(i + len(group) + 1:i + len(group) + 1)) == 0) cycle
         start = i + len(group) + 1
         exit
      end do
      if (start == 0) return
      found = .true.
      quote = " "
      body = text(start:)
      do i = 1, len(body)
         call track_quote(body(i:i), quote)
         if (quote /= " ") cycle
         if (body(i:i) == "/") then
            body = body(:i - 1)
            closed = .true.
            return
         end if
         if (body(i:i) == "&" .and. i > 1 .and. i < len(body)) then
            if (body(i - 1:i - 1) == " " .and. is_letter(body(i + 1:i + 1))) then
               j = i + 1
               do while (j < len(body))
                  if (.not. is_name_char(body(j + 1:j + 1))) exit
                  j = j + 1
               end do
               next = lower(body(i + 1:j))
               closed = next == "end"  ! '&end' closes a group in old-style namelists
               body = body(:i - 1)
               return
            end if
         end if
      end do
   end subroutine locate_group

   !> Whether the file has a `&group`.
   logical function group_present(unit, group)
      integer, intent(in) :: unit
      character(len=*), intent(in) :: group
      character(len=:), allocatable :: body, next
      logical :: closed
      call locate_group(unit, group, group_present, body, closed, next)
   end function group_present

   !> Whether the first `&group` of the file gives a value to `variable`.
   logical function group_sets(unit, group, variable)
      integer, intent(in) :: unit
      character(len=*), intent(in) :: group, variable
      type(item_t), allocatable :: items(:)
      integer :: k
      call group_items(unit, group, items)
      group_sets = .false.
      do k = 1, size(items)
         if (items(k)%name == variable) group_sets = .true.
      end do
   end function group_sets

   !> The items of the first `&group ... /` in the file, cut at each `name =`
   !> (outside quotes; `!` comments removed).
   subroutine group_items(unit, group, items)
      integer, intent(in) :: unit
      character(len=*), intent(in) :: group
      type(item_t), allocatable, intent(out) :: items(:)
      character(len=:), allocatable :: body, next
      integer :: i, j, k, n, last
      integer, allocatable :: starts(:)
      logical :: after_separator, found, closed
      character :: quote
      allocate (items(0))
      call locate_group(unit, group, found, body, closed, next)
      if (.not. found) return
      ! item starts: an identifier (optionally subscripted) after a blank or comma, then '='
      allocate (starts(0))
      quote = " "
      i = 1
      do while (i <= len(body))
         call track_quote(body(i:i), quote)
         if (quote == " " .and. is_letter(body(i:i))) then
            if (i == 1) then
               after_separator = .true.
            else
               after_separator = index(" ,", body(i - 1:i - 1)) > 0
            end if
            j = i
            do while (j < len(body))
               if (.not. is_name_char(body(j + 1:j + 1))) exit
               j = j + 1
            end do
            if (after_separator) then
               k = j + 1
               if (k <= len(body)) then
                  if (body(k:k) == "(") k = k + max(index(body(k:), ")"), 1)
               end if
               do while (k <= len(body))
                  if (body(k:k) /= " ") exit
                  k = k + 1
               end do
               if (k <= len(body)) then
                  if (body(k:k) == "=") starts = [starts, i]
               end if
            end if
            i = j
         end if
         i = i + 1
      end do
      n = size(starts)
      deallocate (items)
      allocate (items(n))
      do k = 1, n
         if (k < n) then
            last = starts(k + 1) - 1
         else
            last = len(body)
         end if
         items(k)%text = trim(adjustl(body(starts(k):last)))
         if (items(k)%text(len(items(k)%text):) == ",") items(k)%text = items(k)%text(:len(items(k)%text) - 1)
         items(k)%name = item_name(items(k)%text)
      end do
   end subroutine group_items

   !> Keep track of whether position i is inside a quoted string.
   pure subroutine track_quote(c, quote)
      character, intent(in) :: c
      character, intent(inout) :: quote  !! the open quote character, or blank outside strings
      if (quote == " ") then
         if (c == "'" .or. c == '"') quote = c
      else if (c == quote) then
         quote = " "  ! a doubled quote closes and reopens: same state after two characters
      end if
   end subroutine track_quote

   !> A line without its `!` comment (outside quotes).
   pure function strip_comment(line) result(code)
      character(len=*), intent(in) :: line
      character(len=:), allocatable :: code
      character :: quote
      integer :: i
      quote = " "
      code = line
      do i = 1, len(line)
         call track_quote(line(i:i), quote)
         if (quote == " " .and. line(i:i) == "!") then
            code = line(:i - 1)
            return
         end if
      end do
   end function strip_comment

   elemental logical function is_letter(c)
      character, intent(in) :: c
      is_letter = (c >= "a" .and. c <= "z") .or. (c >= "A" .and. c <= "Z")
   end function is_letter

   elemental logical function is_name_char(c)
      character, intent(in) :: c
      is_name_char = is_letter(c) .or. (c >= "0" .and. c <= "9") .or. c == "_"
   end function is_name_char

   !> The variable name of an item `name(sub) = value`, lower case.
   pure function item_name(item) result(name)
      character(len=*), intent(in) :: item
      character(len=:), allocatable :: name
      integer :: j
      j = 1
      do while (j < len(item))
         if (.not. is_name_char(item(j + 1:j + 1))) exit
         j = j + 1
      end do
      name = trim(lower(item(:j)))
   end function item_name

   !> Names joined by ", ".
   pure function joined(names) result(text)
      character(len=*), intent(in) :: names(:)
      character(len=:), allocatable :: text
      integer :: k
      text = trim(names(1))
      do k = 2, size(names)
         text = text//", "//trim(names(k))
      end do
   end function joined

   !> The error for a bad value: "file: &group: variable: message".
   pure subroutine fail(error, path, group, variable, message)
      type(error_t), allocatable, intent(out) :: error
      character(len=*), intent(in) :: path, group, variable, message
      call set_error(error, err_input, path//": &"//group//": "//variable//": "//message)
   end subroutine fail

   !> |x| <= max_magnitude: beyond, grid spacings and the coefficient overflow.
   subroutine require_bounded(path, group, variable, x, error)
      character(len=*), intent(in) :: path, group, variable
      real(wp), intent(in) :: x
      type(error_t), allocatable, intent(out) :: error
      if (abs(x) > max_magnitude) call fail(error, path, group, variable, "must lie in ["// &
         real_text(-max_magnitude)//", "//real_text(max_magnitude)//"], got "//real_text(x))
   end subroutine require_bounded

   !> The integrating methods (magnus4, magnus6, rk, gsl) take steps in proportion to
   !> sqrt(|alpha| + |beta|): beyond max_integrated_magnitude one point would take seconds
   !> to minutes, so such scenes are refused (auto stops at its own step limit; formula and
   !> segments cost the same at any magnitude).
   subroutine check_integration_cost(scene, error)
      type(scene_t), intent(in) :: scene
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: why
      integer :: k
      select case (scene%method%kind)
      case (method_magnus4, method_magnus6, method_rk, method_gsl)
      case default
         return
      end select
      why = " for method '"//method_name(scene%method%kind)//"', whose steps grow with sqrt(|alpha| + |beta|)"// &
            " (method auto or segments take any magnitude)"
      select case (scene%task)
      case (task_chart)
         if (max(abs(scene%chart%alpha_min), abs(scene%chart%alpha_max)) + &
             max(abs(scene%chart%beta_min), abs(scene%chart%beta_max)) > max_integrated_magnitude) then
            call fail(error, scene%source, "chart", "alpha_max", "|alpha| + |beta| must be <= "// &
               real_text(max_integrated_magnitude)//why)
         end if
      case (task_points)
         if (.not. allocated(scene%points)) return
         do k = 1, size(scene%points, 2)
            if (abs(scene%points(1, k)) + abs(scene%points(2, k)) > max_integrated_magnitude) then
               call fail(error, scene%source, "points", "file", "point "//integer_text(k)// &
                  ": |alpha| + |beta| must be <= "//real_text(max_integrated_magnitude)//why)
               return
            end if
         end do
      end select
   end subroutine check_integration_cost

   !> The boundaries task (Hill's method, its matrix growing with sqrt|alpha|) is bounded
   !> to |alpha|, |beta| <= max_boundaries_magnitude.
   subroutine check_boundaries_cost(scene, error)
      type(scene_t), intent(in) :: scene
      type(error_t), allocatable, intent(out) :: error
      character(len=*), parameter :: why = " for task boundaries (the cost of Hill's method grows with the magnitude)"
      if (max(abs(scene%chart%alpha_min), abs(scene%chart%alpha_max)) > max_boundaries_magnitude) then
         call fail(error, scene%source, "chart", merge("alpha_max", "alpha_min", &
            abs(scene%chart%alpha_max) >= abs(scene%chart%alpha_min)), "|alpha| must be <= "// &
            real_text(max_boundaries_magnitude)//why)
      else if (max(abs(scene%chart%beta_min), abs(scene%chart%beta_max)) > max_boundaries_magnitude) then
         call fail(error, scene%source, "chart", merge("beta_max", "beta_min", &
            abs(scene%chart%beta_max) >= abs(scene%chart%beta_min)), "|beta| must be <= "// &
            real_text(max_boundaries_magnitude)//why)
      end if
   end subroutine check_boundaries_cost

   subroutine require_finite(path, group, variable, x, error)
      character(len=*), intent(in) :: path, group, variable
      real(wp), intent(in) :: x
      type(error_t), allocatable, intent(out) :: error
      if (.not. ieee_is_finite(x)) call fail(error, path, group, variable, "not a finite number")
   end subroutine require_finite

   subroutine require_positive_count(path, group, variable, n, smallest, error)
      character(len=*), intent(in) :: path, group, variable
      integer, intent(in) :: n, smallest
      type(error_t), allocatable, intent(out) :: error
      if (n < smallest) call fail(error, path, group, variable, "must be >= "//integer_text(smallest)// &
         ", got "//integer_text(n))
   end subroutine require_positive_count

   !> Check `<name>_min`, `<name>_max` (finite, min <= max) and `n_<name>` (>= 1).
   subroutine check_range(path, group, name, lo, hi, n, error)
      character(len=*), intent(in) :: path, group, name
      real(wp), intent(in) :: lo, hi
      integer, intent(in) :: n
      type(error_t), allocatable, intent(out) :: error
      call require_finite(path, group, name//"_min", lo, error)
      if (allocated(error)) return
      call require_finite(path, group, name//"_max", hi, error)
      if (allocated(error)) return
      call require_bounded(path, group, name//"_min", lo, error)
      if (allocated(error)) return
      call require_bounded(path, group, name//"_max", hi, error)
      if (allocated(error)) return
      if (lo > hi) then
         call fail(error, path, group, name//"_min", name//"_min = "//real_text(lo)//" is greater than "// &
            name//"_max = "//real_text(hi))
         return
      end if
      call require_positive_count(path, group, "n_"//name, n, 1, error)
      if (allocated(error)) return
      if (n > max_grid_count) call fail(error, path, group, "n_"//name, "must be <= "// &
         integer_text(max_grid_count)//", got "//integer_text(n))
   end subroutine check_range

   !> The elastic model needs 0 <= α < π² (a < ρ); the Mathieu model takes any finite ν.
   subroutine check_alpha_domain(scene, group, variable, alpha, error, where)
      type(scene_t), intent(in) :: scene
      character(len=*), intent(in) :: group, variable
      real(wp), intent(in) :: alpha  !! a finite value
      type(error_t), allocatable, intent(out) :: error
      character(len=*), intent(in), optional :: where  !! position in a data file
      character(len=:), allocatable :: prefix
      prefix = ""
      if (present(where)) prefix = where//": "
      if (scene%model /= model_elastic) return
      if (alpha < 0.0_wp .or. alpha >= pi2) then
         call fail(error, scene%source, group, variable, prefix//"the elastic model needs 0 <= alpha < pi**2 = "// &
            real_text(pi2)//" (amplitude a < rho), got alpha = "//real_text(alpha))
      end if
   end subroutine check_alpha_domain

   !> Shortest decimal text that reads back to exactly x (plain notation for
   !> 1e-4 <= |x| < 1e15, else mantissa and exponent), e.g. 9.8, 0.0, 1.0e-10.
   function real_text(x) result(text)
      real(wp), intent(in) :: x  !! a finite value
      character(len=:), allocatable :: text
      character(len=40) :: buffer, fmt
      character(len=:), allocatable :: digits, sign_text
      integer :: d, e_at, exponent10, ios
      real(wp) :: back
      type(fpe_state_t) :: fpe
      if (x == 0.0_wp) then
         text = "0.0"
         return
      end if
      if (.not. ieee_is_finite(x)) then
         text = "not a finite number"
         return
      end if
      ! a rounded candidate may overflow when read back (1.8e308): no trap, just a miss
      call halting_off(fpe)
      do d = 1, 17
         write (fmt, '(a,i0,a)') "(es40.", d - 1, "e3)"
         write (buffer, fmt) x
         read (buffer, *, iostat=ios) back
         if (ios == 0 .and. back == x) exit
      end do
      call halting_restore(fpe)
      buffer = adjustl(buffer)
      sign_text = ""
      if (buffer(1:1) == "-") then
         sign_text = "-"
         buffer = buffer(2:)
      end if
      e_at = index(buffer, "E")
      read (buffer(e_at + 1:), *) exponent10
      digits = buffer(1:1)//buffer(3:e_at - 1)  ! mantissa digits without the point
      if (exponent10 >= -4 .and. exponent10 < 15) then
         if (exponent10 >= 0) then
            if (len(digits) <= exponent10 + 1) digits = digits//repeat("0", exponent10 + 2 - len(digits))
            text = sign_text//digits(:exponent10 + 1)//"."//digits(exponent10 + 2:)
         else
            text = sign_text//"0."//repeat("0", -exponent10 - 1)//digits
         end if
      else
         if (len(digits) == 1) digits = digits//"0"
         text = sign_text//digits(1:1)//"."//digits(2:)//"e"//integer_text(exponent10)
      end if
   end function real_text

   !> A string as a namelist character constant (quotes doubled).
   pure function quoted(text) result(q)
      character(len=*), intent(in) :: text
      character(len=:), allocatable :: q
      integer :: i
      q = "'"
      do i = 1, len(text)
         if (text(i:i) == "'") then
            q = q//"''"
         else
            q = q//text(i:i)
         end if
      end do
      q = q//"'"
   end function quoted

   !> The effective scene as namelist groups, one group a line, every variable
   !> with its value (defaults filled in): `&scene`, the group of the task and, when the
   !> scene has one, `&physical`. Reading these lines back as a scene reproduces the run.
   function scene_namelist(scene) result(lines)
      type(scene_t), intent(in) :: scene  !! the scene
      character(len=:), allocatable :: lines(:)
      character(len=:), allocatable :: first, second, third
      integer :: k
      first = "&scene task = "//quoted(task_name(scene%task))//", model = "//quoted(model_name(scene%model))// &
         ", method = "//quoted(method_name(scene%method%kind))// &
         ", n_segments = "//integer_text(scene%method%n_segments)// &
         ", sampling = "//quoted(sampling_name(scene%method%sampling))// &
         ", tolerance = "//real_text(scene%method%tolerance)
      ! with &physical the damping is kappa; epsilon in &scene would be an error
      if (.not. scene%physical) first = first//", epsilon = "//real_text(scene%epsilon)
      first = first//", output = "//quoted(scene%output)
      if (scene%task == task_chart .or. scene%task == task_points) then
         first = first//", columns = "//quoted(scene%columns)//", format = "// &
            quoted(trim(merge("binary", "text  ", scene%binary)))
         if (scene%names_line) first = first//", names_line = .true."
      end if
      first = first//" /"
      select case (scene%task)
      case (task_chart, task_boundaries)
         second = chart_text(scene%chart)
      case (task_points)
         if (size(scene%amplitudes) > 0) then
            second = "&points /"
         else
            second = "&points file = "//quoted(scene%points_file)//" /"
         end if
      case (task_series)
         second = series_text(scene%series)
      case (task_lyapunov, task_poincare)
         lines = chaos_namelist(scene, first)
         return
      case (task_coefficient)
         second = "&coefficient "
         if (size(scene%amplitudes) == 0) then
            second = second//"alphas = "//real_text(scene%coefficient%alphas(1))
            do k = 2, size(scene%coefficient%alphas)
               second = second//", "//real_text(scene%coefficient%alphas(k))
            end do
            second = second//", beta = "//real_text(scene%coefficient%beta)//", "
         end if
         second = second//"n_tau = "//integer_text(scene%coefficient%n_tau)// &
            ", tau_min = "//real_text(scene%coefficient%tau_min)// &
            ", tau_max = "//real_text(scene%coefficient%tau_max)//" /"
      case default
         second = ""
      end select
      if (scene%physical) then
         third = "&physical omega = "//real_text(scene%pendulum%omega)//", g = "//real_text(scene%pendulum%g)// &
            ", kappa = "//real_text(scene%pendulum%kappa)
         if (size(scene%amplitudes) > 0) then
            third = third//", r0 = "//real_text(scene%pendulum%r0)//", a = "//real_text(scene%amplitudes(1))
            do k = 2, size(scene%amplitudes)
               third = third//", "//real_text(scene%amplitudes(k))
            end do
         end if
         third = third//" /"
         allocate (character(len=max(len(first), len(second), len(third))) :: lines(3))
         lines(3) = third
      else
         allocate (character(len=max(len(first), len(second))) :: lines(2))
      end if
      lines(1) = first
      lines(2) = second
   end function scene_namelist

   !> The lines an output file's header holds: `title`, the scene file, the effective scene
   !> (`scene_namelist`: given back as a scene, the file repeats its run), then `extra`.
   function scene_header(scene, title, extra) result(lines)
      type(scene_t), intent(in) :: scene  !! the scene of the run
      character(len=*), intent(in) :: title  !! the first line: the program, its version, what the file holds
      character(len=*), intent(in) :: extra(:)  !! the lines after the namelist groups
      character(len=:), allocatable :: lines(:)
      character(len=:), allocatable :: groups(:), source_line
      groups = scene_namelist(scene)
      source_line = "scene file: "//scene%source//" (the namelist lines below repeat this run)"
      allocate (character(len=max(len(title), len(source_line), len(groups), len(extra))) :: &
         lines(2 + size(groups) + size(extra)))
      lines(1) = title
      lines(2) = source_line
      lines(3:2 + size(groups)) = groups
      lines(3 + size(groups):) = extra
   end function scene_header

   !> The `&chart` line of the effective scene.
   function chart_text(grid) result(text)
      type(chart_grid_t), intent(in) :: grid
      character(len=:), allocatable :: text
      text = "&chart alpha_min = "//real_text(grid%alpha_min)//", alpha_max = "//real_text(grid%alpha_max)// &
         ", n_alpha = "//integer_text(grid%n_alpha)//", beta_min = "//real_text(grid%beta_min)// &
         ", beta_max = "//real_text(grid%beta_max)//", n_beta = "//integer_text(grid%n_beta)//" /"
   end function chart_text

   !> The `&series` line of the effective scene.
   function series_text(plan) result(text)
      type(series_plan_t), intent(in) :: plan
      character(len=:), allocatable :: text
      text = "&series alpha = "//real_text(plan%alpha)//", beta = "//real_text(plan%beta)// &
         ", phi0 = "//real_text(plan%phi0)//", periods = "//integer_text(plan%periods)// &
         ", samples_per_period = "//integer_text(plan%samples_per_period)//", r0 = "//real_text(plan%r0)// &
         ", g = "//real_text(plan%g)//", vx0 = "//real_text(plan%vx0)//", vz0 = "//real_text(plan%vz0)//" /"
   end function series_text

   !> The namelist lines of a lyapunov scene (&scene, &series, &lyapunov, &chart or
   !> &points) or a poincare scene (&scene, &series, &poincare).
   function chaos_namelist(scene, first) result(lines)
      type(scene_t), intent(in) :: scene
      character(len=*), intent(in) :: first  !! the &scene line
      character(len=:), allocatable :: lines(:)
      character(len=:), allocatable :: series, third, fourth
      integer :: k
      series = series_text(scene%series)
      if (scene%task == task_lyapunov) then
         if (scene%lyapunov_points) then
            third = "&lyapunov over = 'points' /"
            fourth = "&points file = "//quoted(scene%points_file)//" /"
         else
            third = "&lyapunov over = 'chart' /"
            fourth = chart_text(scene%chart)
         end if
      else
         third = "&poincare phi0s = "//real_text(scene%poincare%phi0s(1))
         do k = 2, size(scene%poincare%phi0s)
            third = third//", "//real_text(scene%poincare%phi0s(k))
         end do
         third = third//", same_energy = "//merge(".true. ", ".false.", scene%poincare%same_energy)
         third = trim(third)//" /"
         fourth = ""
      end if
      if (len(fourth) > 0) then
         allocate (character(len=max(len(first), len(series), len(third), len(fourth))) :: lines(4))
         lines(4) = fourth
      else
         allocate (character(len=max(len(first), len(series), len(third))) :: lines(3))
      end if
      lines(1) = first
      lines(2) = series
      lines(3) = third
   end function chaos_namelist

   !> `&lyapunov`: over the grid of `&chart` (default) or the points of `&points`.
   subroutine read_lyapunov_group(unit, scene, error)
      integer, intent(in) :: unit
      type(scene_t), intent(inout) :: scene
      type(error_t), allocatable, intent(out) :: error
      character(len=read_len) :: over
      namelist /lyapunov/ over
      character(len=*), parameter :: group = "lyapunov"
      character(len=*), parameter :: names(1) = [character(len=4) :: "over"]
      character(len=*), parameter :: kinds(1) = [character(len=13) :: "a quoted name"]
      type(group_read_t) :: reader
      over = merge("points", "chart ", scene%lyapunov_points)
      if (.not. group_present(unit, group)) return
      call begin_group_read(unit, reader)
      read (unit, nml=lyapunov, iostat=reader%ios, iomsg=reader%msg)
      do while (next_item(reader, unit, group))
         read (reader%record, nml=lyapunov, iostat=reader%stat, iomsg=reader%message)
      end do
      call end_group_read(reader, unit, scene%source, group, names, kinds, error)
      if (allocated(error)) return
      select case (lower(trim(over)))
      case ("chart"); scene%lyapunov_points = .false.
      case ("points"); scene%lyapunov_points = .true.
      case default
         call fail(error, scene%source, group, "over", "unknown value '"//trim(over)//"' (expected chart or points)")
      end select
   end subroutine read_lyapunov_group

   !> The lyapunov task integrates the pendulum: every point must lie in the physical
   !> domain 0 <= alpha < pi^2, 0 < beta < pi^2.
   subroutine check_lyapunov_domain(scene, error)
      type(scene_t), intent(in) :: scene
      type(error_t), allocatable, intent(out) :: error
      character(len=*), parameter :: why = " (the lyapunov task simulates the pendulum: 0 < beta < pi**2 = "
      integer :: k
      if (scene%lyapunov_points) then
         do k = 1, size(scene%points, 2)
            if (scene%points(2, k) <= 0.0_wp .or. scene%points(2, k) >= pi2) then
               call fail(error, scene%source, "points", "file", "point "//integer_text(k)//" of "// &
                  scene%points_file//" has beta = "//real_text(scene%points(2, k))//" outside the physical domain"// &
                  why//real_text(pi2)//")")
               return
            end if
            if (scene%points(2, k) < min_pendulum_beta) then
               call fail(error, scene%source, "points", "file", "point "//integer_text(k)//" of "// &
                  scene%points_file//" has beta = "//real_text(scene%points(2, k))//", below "// &
                  real_text(min_pendulum_beta)//" (smaller values make the pendulum's time scales overflow)")
               return
            end if
         end do
      else if (scene%chart%beta_min <= 0.0_wp) then
         call fail(error, scene%source, "chart", "beta_min", "must be > 0"//why//real_text(pi2)//"), got "// &
            real_text(scene%chart%beta_min))
      else if (scene%chart%beta_min < min_pendulum_beta) then
         call fail(error, scene%source, "chart", "beta_min", "must be >= "//real_text(min_pendulum_beta)// &
            " (smaller values make the pendulum's time scales overflow), got "//real_text(scene%chart%beta_min))
      else if (scene%chart%beta_max >= pi2) then
         call fail(error, scene%source, "chart", "beta_max", "must be < pi**2"//why//real_text(pi2)//"), got "// &
            real_text(scene%chart%beta_max))
      end if
   end subroutine check_lyapunov_domain

   !> `&poincare`: the initial angles of the orbits and whether they share one energy.
   subroutine read_poincare_group(unit, scene, error)
      integer, intent(in) :: unit
      type(scene_t), intent(inout) :: scene
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: phi0s(max_poincare_orbits)
      logical :: same_energy
      namelist /poincare/ phi0s, same_energy
      character(len=*), parameter :: group = "poincare"
      character(len=*), parameter :: names(2) = [character(len=11) :: "phi0s", "same_energy"]
      character(len=*), parameter :: kinds(2) = [character(len=33) :: "a list of at most 64 real numbers", "a logical"]
      real(wp), parameter :: unset = -huge(1.0_wp)
      integer :: n, k
      type(group_read_t) :: reader
      phi0s = unset
      same_energy = scene%poincare%same_energy
      ! the group is optional; a list it gives replaces the default list whole
      if (.not. group_sets(unit, group, "phi0s")) phi0s(:size(scene%poincare%phi0s)) = scene%poincare%phi0s
      if (group_present(unit, group)) then
         call begin_group_read(unit, reader)
         read (unit, nml=poincare, iostat=reader%ios, iomsg=reader%msg)
         do while (next_item(reader, unit, group))
            read (reader%record, nml=poincare, iostat=reader%stat, iomsg=reader%message)
         end do
         call end_group_read(reader, unit, scene%source, group, names, kinds, error)
         if (allocated(error)) return
      end if
      n = count(phi0s /= unset)
      if (n == 0) then
         call fail(error, scene%source, group, "phi0s", "no initial angle given")
         return
      end if
      if (any(phi0s(n + 1:) /= unset)) then
         call fail(error, scene%source, group, "phi0s", "the list has gaps")
         return
      end if
      do k = 1, n
         call require_finite(scene%source, group, "phi0s", phi0s(k), error)
         if (allocated(error)) return
         if (abs(phi0s(k)) >= pi) then
            call fail(error, scene%source, group, "phi0s", "each angle must lie in (-pi, pi), got "// &
               real_text(phi0s(k)))
            return
         end if
      end do
      scene%poincare%phi0s = phi0s(:n)
      scene%poincare%same_energy = same_energy
   end subroutine read_poincare_group

   !> Read one whole line from a formatted unit; with `max_length`, stop after that many
   !> characters (`too_long` true, `ios` /= 0, the rest of the line unread).
   subroutine read_text_line(unit, line, ios, max_length, too_long)
      integer, intent(in) :: unit  !! a formatted unit open for reading
      character(len=:), allocatable, intent(out) :: line  !! the line, without its newline
      integer, intent(out) :: ios  !! 0, or iostat_end at the end of the file
      integer, intent(in), optional :: max_length  !! longest line accepted
      logical, intent(out), optional :: too_long   !! the line is longer than max_length
      character(len=1024) :: chunk
      integer :: got
      line = ""
      if (present(too_long)) too_long = .false.
      do
         read (unit, '(a)', advance="no", iostat=ios, size=got) chunk
         line = line//chunk(:got)
         if (present(max_length)) then
            if (len(line) > max_length) then
               if (present(too_long)) too_long = .true.
               ios = 1
               return
            end if
         end if
         if (ios /= 0) exit
      end do
      if (is_iostat_eor(ios)) ios = 0
   end subroutine read_text_line
end module hillstab_batch_scene

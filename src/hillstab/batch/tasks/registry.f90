!> The tasks a scene can name, in one place: each registered task has a name, a line
!> saying what it computes, and a module extending `task_t` (hillstab_batch_task_*).
!> A new task is its module plus one line in `task_entries` and one `case` in `new_task`;
!> the scene reader, the command line's help, the templates, the dispatcher, the MPI
!> splitter and the limits find it here.
!>
!>```fortran
!> class(task_t), allocatable :: task
!> type(error_t), allocatable :: error
!> call new_task("chart", task, error)
!>```
module hillstab_batch_tasks_registry
   use hillstab_core_error, only: error_t, set_error, err_input
   use hillstab_batch_scene_types, only: task_t
   use hillstab_batch_tasks_chart, only: chart_task
   use hillstab_batch_tasks_points, only: points_task
   use hillstab_batch_tasks_coefficient, only: coefficient_task
   use hillstab_batch_tasks_boundaries, only: boundaries_task
   use hillstab_batch_tasks_series, only: series_task
   use hillstab_batch_tasks_lyapunov, only: lyapunov_task
   use hillstab_batch_tasks_poincare, only: poincare_task
   use hillstab_batch_tasks_system, only: system_chart_task, system_points_task, system_task_names
   use hillstab_batch_tasks_system_coefficient, only: system_coefficient_task
   use hillstab_batch_tasks_system_boundaries, only: system_boundaries_task
   use hillstab_batch_tasks_regions, only: regions_task, edges_task
   implicit none
   private
   public :: task_entry_t, task_entries, task_names, task_names_text, new_task

   !> A registered task.
   type :: task_entry_t
      character(len=:), allocatable :: name     !! as in `&scene task`
      character(len=:), allocatable :: purpose  !! what it computes, one line (help, templates)
   end type task_entry_t

contains

   !> Every registered task, in the order the help and the templates list them.
   function task_entries() result(entries)
      type(task_entry_t), allocatable :: entries(:)
      ! one entry at a time: an array constructor of them would leak their strings (gfortran 12)
      allocate (entries(9))
      entries(1) = task_entry_t("chart", "a stability chart over an (alpha, beta) grid: S, stability, multipliers, "// &
                                "exponent")
      entries(2) = task_entry_t("points", "the chart's columns at (alpha, beta) points listed in a file")
      entries(3) = task_entry_t("coefficient", "Q(tau) and its segmented version, one pair of columns per alpha "// &
                                "(the paper's Fig. 2)")
      entries(4) = task_entry_t("boundaries", "transition curves S = +-2 over the alpha grid of &chart, within its "// &
                                "beta window (exact methods: Hill's method; formula, segments: roots by Brent from "// &
                                "n_beta samples)")
      entries(5) = task_entry_t("series", "the nonlinear elastic pendulum from eq. (38), sampled from the dense "// &
                                "output at t = j T/samples_per_period (tolerance: the integrator's relative "// &
                                "tolerance; method: the core computing lambda_max)")
      entries(6) = task_entry_t("lyapunov", "the largest Lyapunov exponent of the nonlinear pendulum (per radial "// &
                                "period) over the grid of &chart or the points of &points, beside the chart's linear "// &
                                "verdict (tolerance: the integrator's relative tolerance; method: the core computing "// &
                                "lambda_max)")
      entries(7) = task_entry_t("poincare", "Poincare sections (phi = 0, phi' > 0: r, r') of orbits started at rest "// &
                                "at each angle of &poincare phi0s, at the (alpha, beta, r0, g) of &series, over "// &
                                "&series periods")
      entries(8) = task_entry_t("regions", "every resonance region up to &regions order over the ranges of &chart "// &
                                "(one axis the frequency, the other the drive): its tip (the least drive at which "// &
                                "it opens, and the frequency there), kind, width at the top drive and status")
      entries(9) = task_entry_t("edges", "the boundaries of the regions of task regions in the same plane, traced "// &
                                "from each tip up to the top drive at &edges levels, each point checked on both "// &
                                "sides (a stability boundary, or an overlap of two regions)")
   end function task_entries

   !> The task names, blank-padded to a common length.
   function task_names() result(names)
      character(len=:), allocatable :: names(:)
      type(task_entry_t), allocatable :: entries(:)
      integer :: k, width
      entries = task_entries()
      width = 0
      do k = 1, size(entries)
         width = max(width, len(entries(k)%name))
      end do
      allocate (character(len=width) :: names(size(entries)))
      do k = 1, size(entries)
         names(k) = entries(k)%name
      end do
   end function task_names

   !> The task names joined by `separator` (", " in messages, " | " in templates).
   function task_names_text(separator) result(text)
      character(len=*), intent(in) :: separator  !! between two names
      character(len=:), allocatable :: text
      character(len=:), allocatable :: names(:)
      integer :: k
      names = task_names()
      text = trim(names(1))
      do k = 2, size(names)
         text = text//separator//trim(names(k))
      end do
   end function task_names_text

   !> A task of the given name, before its groups are read; err_input naming the known
   !> tasks when there is none.
   subroutine new_task(name, task, error, system)
      character(len=*), intent(in) :: name  !! a task name, lower case
      class(task_t), allocatable, intent(out) :: task  !! the task
      type(error_t), allocatable, intent(out) :: error  !! unknown task
      !> the scene is a system (`&scene model = 'system'`): its own chart, points and coefficient
      logical, intent(in), optional :: system
      if (present(system)) then
         if (system) then
            select case (name)
            case ("chart"); allocate (task, source=system_chart_task())
            case ("points"); allocate (task, source=system_points_task())
            case ("coefficient"); allocate (task, source=system_coefficient_task())
            case ("boundaries"); allocate (task, source=system_boundaries_task())
            case ("regions"); allocate (task, source=regions_task())
            case ("edges"); allocate (task, source=edges_task())
            case default
               call set_error(error, err_input, "task '"//name//"' does not run on a system of Hill equations "// &
                  "(model = 'system' takes "//system_task_names//")")
            end select
            return
         end if
      end if
      select case (name)
      case ("chart"); allocate (task, source=chart_task())
      case ("points"); allocate (task, source=points_task())
      case ("coefficient"); allocate (task, source=coefficient_task())
      case ("boundaries"); allocate (task, source=boundaries_task())
      case ("series"); allocate (task, source=series_task())
      case ("lyapunov"); allocate (task, source=lyapunov_task())
      case ("poincare"); allocate (task, source=poincare_task())
      case ("regions"); allocate (task, source=regions_task())
      case ("edges"); allocate (task, source=edges_task())
      case default
         call set_error(error, err_input, "unknown task '"//name//"' (expected "//task_names_text(", ")//")")
      end select
   end subroutine new_task
end module hillstab_batch_tasks_registry

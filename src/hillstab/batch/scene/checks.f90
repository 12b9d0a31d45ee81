!> Checks every scene group shares, and the limits they enforce: finite values, bounded
!> magnitudes, ranges `<name>_min <= <name>_max` with `n_<name>` values, the domain of α
!> of the model; and the bounds beyond which a physical value is read with a warning. Each check names the file, the group and the variable in its message.
!>
!>```fortran
!> call check_range("s.nml", "chart", "alpha", 0.0_wp, 9.8_wp, 200, error)
!>```
module hillstab_batch_scene_checks
   use hillstab_core_kinds, only: wp, pi2
   use hillstab_core_error, only: error_t
   use hillstab_core_text, only: real_text, integer_text
   use hillstab_hill_model, only: hill_model_t
   use hillstab_integrate_monodromy, only: method_t, method_name, method_cost_grows, max_integrated_magnitude, max_segments
   use hillstab_batch_scene_file, only: fail
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   implicit none
   private
   public :: require_bounded, require_finite, require_positive_count, check_range, check_alpha_domain
   public :: check_integration_cost
   public :: max_grid_count, max_segments, min_tolerance, max_magnitude, max_boundaries_magnitude, &
      min_pendulum_beta, max_epsilon, max_points, longest_spring, slowest_omega

   !> Largest `n_alpha`, `n_beta`, `n_tau` (and every other `n_` count of a range).
   integer, parameter :: max_grid_count = 100000000
   !> Smallest `tolerance` accepted (methods reach the round-off level of double precision
   !> near 1e-16 relative to max(1, |S|); below this the answer could only be round-off limited).
   real(wp), parameter :: min_tolerance = 1.0e-15_wp
   !> Largest |α|, |β|, |τ| accepted (grid spacings, Q and the methods' scalings stay finite).
   real(wp), parameter :: max_magnitude = 1.0e15_wp
   !> Largest |α|, |β| of task boundaries.
   real(wp), parameter :: max_boundaries_magnitude = 1.0e6_wp
   !> Smallest β of the tasks that simulate the pendulum (series, lyapunov, poincare):
   !> below it ω = √(g π²/(ρ β)) and the time scales overflow.
   real(wp), parameter :: min_pendulum_beta = 1.0e-8_wp
   !> Largest damping ε.
   real(wp), parameter :: max_epsilon = 100.0_wp
   !> Largest number of points in a points file.
   integer, parameter :: max_points = 1000000
   !> A spring longer than this [m] (r0, or the loaded length ρ) is read with a warning: a
   !> length typed in centimetres, most likely.
   real(wp), parameter :: longest_spring = 100.0_wp
   !> A radial angular frequency below this [rad/s] (a period of 105 minutes) is read with a
   !> warning: k or m in the wrong unit, most likely.
   real(wp), parameter :: slowest_omega = 1.0e-3_wp

contains

   !> |x| <= max_magnitude: beyond, grid spacings and the coefficient overflow.
   subroutine require_bounded(path, group, variable, x, error)
      character(len=*), intent(in) :: path, group, variable  !! the scene file, the group and the variable named
      real(wp), intent(in) :: x  !! the value
      type(error_t), allocatable, intent(out) :: error  !! err_input naming file, group and variable; unallocated when fine
      if (abs(x) > max_magnitude) call fail(error, path, group, variable, "must lie in ["// &
         real_text(-max_magnitude)//", "//real_text(max_magnitude)//"], got "//real_text(x))
   end subroutine require_bounded

   !> x must be a finite number.
   subroutine require_finite(path, group, variable, x, error)
      character(len=*), intent(in) :: path, group, variable  !! the scene file, the group and the variable named
      real(wp), intent(in) :: x  !! the value
      type(error_t), allocatable, intent(out) :: error  !! err_input naming file, group and variable; unallocated when fine
      if (.not. ieee_is_finite(x)) call fail(error, path, group, variable, "not a finite number")
   end subroutine require_finite

   !> n must be at least `smallest`.
   subroutine require_positive_count(path, group, variable, n, smallest, error)
      character(len=*), intent(in) :: path, group, variable  !! the scene file, the group and the variable named
      integer, intent(in) :: n, smallest  !! the count
      type(error_t), allocatable, intent(out) :: error  !! err_input naming file, group and variable; unallocated when fine
      if (n < smallest) call fail(error, path, group, variable, "must be >= "//integer_text(smallest)// &
         ", got "//integer_text(n))
   end subroutine require_positive_count

   !> Check `<name>_min`, `<name>_max` (finite, min <= max) and `n_<name>` (>= 1).
   subroutine check_range(path, group, name, lo, hi, n, error)
      character(len=*), intent(in) :: path, group, name  !! the scene file
      real(wp), intent(in) :: lo, hi  !! first and last value
      integer, intent(in) :: n  !! the count
      type(error_t), allocatable, intent(out) :: error  !! err_input naming file, group and variable; unallocated when fine
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

   !> α must lie in the model's domain (the elastic model: 0 <= α < π², a < ρ; the Mathieu
   !> model takes any finite ν). With `beta`, for a model that does not share rows, the point
   !> (α, β) must lie in the domain of the model at β (`at_point`: an equation whose frequency,
   !> mass or damping is of the β axis).
   subroutine check_alpha_domain(path, model, group, variable, alpha, error, where, beta)
      character(len=*), intent(in) :: path  !! the scene file
      !> the model (the domain of α); absent for a system (any finite α)
      class(hill_model_t), intent(in), optional :: model
      character(len=*), intent(in) :: group, variable  !! the namelist group
      real(wp), intent(in) :: alpha  !! a finite value
      type(error_t), allocatable, intent(out) :: error  !! err_input naming file, group and variable; unallocated when fine
      character(len=*), intent(in), optional :: where  !! position in a data file
      real(wp), intent(in), optional :: beta  !! β of the point (a finite value)
      character(len=:), allocatable :: prefix
      class(hill_model_t), allocatable :: local
      prefix = ""
      if (present(where)) prefix = where//": "
      if (.not. present(model)) return
      if (present(beta)) then
         if (model%shares_rows()) return
         call model%at_point(alpha, beta, local)
         if (local%alpha_valid(alpha)) return
         call fail(error, path, group, variable, prefix//"the "//model%name()//" model needs "// &
            model%alpha_domain()//", got alpha = "//real_text(alpha)//", beta = "//real_text(beta))
         return
      end if
      ! a model taken a point at a time: α is checked at each point's β (with `beta`)
      if (.not. model%shares_rows()) return
      if (model%alpha_valid(alpha)) return
      call fail(error, path, group, variable, prefix//"the "//model%name()//" model needs "// &
         model%alpha_domain()//", got alpha = "//real_text(alpha))
   end subroutine check_alpha_domain

   !> The integrating methods (magnus4, magnus6, rk, gsl) take steps in proportion to
   !> sqrt(|alpha| + |beta|): beyond max_integrated_magnitude one point would take seconds
   !> to minutes, so such scenes are refused (auto stops at its own step limit; formula and
   !> segments cost the same at any magnitude). `magnitude` is the largest |alpha| + |beta|
   !> of the scene's points; the message names `group` and `variable`.
   subroutine check_integration_cost(path, group, variable, method, magnitude, error, where)
      character(len=*), intent(in) :: path, group, variable  !! the scene file; what to name
      type(method_t), intent(in) :: method  !! the scene's method
      real(wp), intent(in) :: magnitude  !! the largest |alpha| + |beta|
      type(error_t), allocatable, intent(out) :: error  !! err_input when too costly
      character(len=*), intent(in), optional :: where  !! a position to name (a point of a file)
      character(len=:), allocatable :: prefix
      if (.not. method_cost_grows(method%kind) .or. magnitude <= max_integrated_magnitude) return
      prefix = ""
      if (present(where)) prefix = where//": "
      call fail(error, path, group, variable, prefix//"|alpha| + |beta| must be <= "// &
         real_text(max_integrated_magnitude)//" for method '"//method_name(method%kind)// &
         "', whose steps grow with sqrt(|alpha| + |beta|) (method auto or segments take any magnitude)")
   end subroutine check_integration_cost
end module hillstab_batch_scene_checks

!> A scene's pendulum in SI units, `&physical` (eqs. (4), (15), (24), (46)): the spring as
!> the scene gives it (`physical_scene_t`, not given unless the scene has the group), what a
!> task takes of it (`physical_use_t`), and the tasks that take it (`pendulum_task_t`, an
!> extension of hillstab_batch_scene_types' `task_t`: the chart, points, coefficient,
!> series, lyapunov and boundaries tasks hold the group as read, and the header writes it
!> before their own groups). The abstract scene and task know nothing of the pendulum; a
!> scene whose task is not a pendulum task refuses the group. The header lines of a scene in
!> physical units and the (α, β) of its amplitudes are here too; the group is read by
!> hillstab_batch_run_read.
!>
!>```fortran
!> type(physical_scene_t) :: physical
!> physical%given = .true.
!> physical%pendulum = physical_t(r0=0.8_wp, g=9.81_wp, omega=6.0_wp, a=0.0_wp, kappa=0.0_wp)
!> physical%r0_given = .true.
!> physical%amplitudes = [0.1_wp, 0.2_wp]
!> print *, physical_points(physical, elastic)   ! (alpha, beta) at each amplitude
!>```
module hillstab_batch_scene_physical
   use hillstab_core_kinds, only: wp, pi
   use hillstab_core_text, only: real_text, integer_text
   use hillstab_hill_model, only: hill_model_t
   use hillstab_hill_units, only: physical_t, physical_beta, equilibrium_length
   use hillstab_hill_model_pendulum, only: pendulum_alpha
   use hillstab_batch_scene_declaration, only: group_values_t
   use hillstab_batch_scene_types, only: task_t, task_header_groups
   implicit none
   private
   public :: physical_scene_t, physical_use_t, pendulum_task_t, physical_points, physical_summary, grid_pendulum

   !> A scene's `&physical` group as read (`given` false and the arrays empty when the
   !> scene has none).
   type :: physical_scene_t
      !> the scene has a `&physical` group: ε comes from κ and ω, and the outputs add
      !> rates per second (ω is known)
      logical :: given = .false.
      type(physical_t) :: pendulum                  !! r0, g, omega, kappa (a: `amplitudes`)
      !> k (N/m) and m (kg) when the scene gives ω as √(k/m); 0 when it gives omega
      real(wp) :: k = 0.0_wp, m = 0.0_wp
      !> r0 is given: ρ = r0 + g/ω² is known and β fixed by the spring
      logical :: r0_given = .false.
      !> a (m): the points (task points) or the curves (task coefficient) at these
      !> amplitudes and the given r0; empty when α and β come from the task's group
      real(wp), allocatable :: amplitudes(:)
      !> omega_min, omega_max, n_omega (rad/s): the ω of a chart over (a, ω), r0 and g
      !> fixed; empty when ω is one value (`pendulum%omega`)
      real(wp), allocatable :: omegas(:)
      type(group_values_t) :: values                !! the effective values
   end type physical_scene_t

   !> What a pendulum task takes of `&physical` (every one takes ω, g and κ).
   type :: physical_use_t
      logical :: takes_amplitudes = .false.   !! its points can come from `a` with r0
      !> r0 without amplitudes: the task takes one spring (its β fixed by r0)
      logical :: takes_spring = .false.
      !> omega_min, omega_max, n_omega (with amplitudes): a grid over (a, ω)
      logical :: takes_omega_range = .false.
      !> with amplitudes: exactly one (a template shows one)
      logical :: single_amplitude = .false.
      !> what `a` with r0 replace, for the template ("&points file")
      character(len=:), allocatable :: amplitudes_replace
   end type physical_use_t

   !> A task that takes the pendulum in SI units, `&physical`, in place of its dimensionless
   !> values: what it takes of the group and the group as read, which the header writes
   !> before the task's own groups.
   type, abstract, extends(task_t) :: pendulum_task_t
      type(physical_use_t) :: physical_use  !! what it takes of `&physical`
      !> `&physical` as read (`given` false and the arrays empty when the scene has none)
      type(physical_scene_t) :: physical
   contains
      procedure :: header_groups => pendulum_header_groups
   end type pendulum_task_t

contains

   !> `&physical` when the scene has it, then the task's own groups.
   function pendulum_header_groups(self) result(groups)
      class(pendulum_task_t), intent(in) :: self  !! the task
      type(group_values_t), allocatable :: groups(:)
      groups = task_header_groups(self)
      if (self%physical%given) groups = [self%physical%values, groups]
   end function pendulum_header_groups

   !> α (elastic model) or ν of eq. (21) (Mathieu model) and β of the pendulum at each
   !> amplitude of `&physical a`: a (2, n) array like the points of a points file.
   pure function physical_points(physical, model) result(points)
      type(physical_scene_t), intent(in) :: physical  !! a scene's `&physical`, with amplitudes
      class(hill_model_t), intent(in) :: model        !! the scene's model
      real(wp), allocatable :: points(:, :)
      type(physical_t) :: p
      integer :: k
      allocate (points(2, size(physical%amplitudes)))
      p = physical%pendulum
      do k = 1, size(physical%amplitudes)
         p%a = physical%amplitudes(k)
         points(1, k) = pendulum_alpha(model, p)
         points(2, k) = physical_beta(p)
      end do
   end function physical_points

   !> Header lines of a scene in physical units: the spring as the run understood it —
   !> k and m (when given), ω, r0, g, ρ (when r0 is given), κ and ε, the radial period
   !> and the conversions (eqs. (4), (24), (46)).
   function physical_summary(physical, epsilon) result(lines)
      type(physical_scene_t), intent(in) :: physical  !! a scene's `&physical`
      real(wp), intent(in) :: epsilon                 !! the scene's ε (from κ and ω)
      character(len=:), allocatable :: lines(:)
      character(len=400) :: text(3)
      character(len=:), allocatable :: spring
      associate (p => physical%pendulum)
         if (size(physical%omegas) > 0) then
            spring = "omega = "//real_text(physical%omegas(1))//" ... "//real_text(physical%omegas(size(physical%omegas)))// &
                     " rad/s ("//integer_text(size(physical%omegas))//" values, the chart's second axis)"
         else if (physical%k > 0.0_wp) then
            spring = "k = "//real_text(physical%k)//" N/m, m = "//real_text(physical%m)// &
                     " kg, omega = sqrt(k/m) = "//real_text(p%omega)//" rad/s"
         else
            spring = "omega = "//real_text(p%omega)//" rad/s"
         end if
         if (size(physical%omegas) > 0) then
            spring = spring//", r0 = "//real_text(p%r0)//" m, g = "//real_text(p%g)//" m/s^2; rho = r0 + g/omega^2 "// &
                     "from "//real_text(p%r0 + p%g/physical%omegas(1)**2)//" m down to "// &
                     real_text(p%r0 + p%g/physical%omegas(size(physical%omegas))**2)//" m, beta = g pi^2/(rho omega^2) "// &
                     "from "//real_text(beta_at(physical%omegas(1)))//" down to "// &
                     real_text(beta_at(physical%omegas(size(physical%omegas))))
         else if (physical%r0_given) then
            spring = spring//", r0 = "//real_text(p%r0)//" m, g = "//real_text(p%g)//" m/s^2, rho = r0 + g/omega^2 = "// &
                     real_text(equilibrium_length(p))//" m, beta = "//real_text(physical_beta(p))
         else
            spring = spring//", g = "//real_text(p%g)//" m/s^2 (r0 not given: rho = g pi^2/(beta omega^2) varies with beta)"
         end if
         text(1) = "physical units (SI): rho = r0 + g/omega^2 (eq. (4)), tau = omega t/pi, alpha = a pi^2/rho, "// &
                   "beta = g pi^2/(rho omega^2) (eq. (24)), epsilon = kappa pi/omega (eq. (46))"
         text(2) = "spring: "//spring
         if (size(physical%omegas) > 0) then
            text(3) = "kappa = "//real_text(p%kappa)//" 1/s, epsilon = kappa pi/omega at each omega; radial "// &
                      "period 2 pi/omega from "//real_text(2.0_wp*pi/physical%omegas(1))//" s down to "// &
                      real_text(2.0_wp*pi/physical%omegas(size(physical%omegas)))//" s (2 units of tau)"
         else
            text(3) = "kappa = "//real_text(p%kappa)//" 1/s, epsilon = "//real_text(epsilon)// &
                      "; radial period 2 pi/omega = "//real_text(2.0_wp*pi/p%omega)//" s (2 units of tau)"
         end if
      end associate
      lines = text
   contains
      !> β of the spring at one ω of the chart (eq. (24)).
      pure real(wp) function beta_at(omega)
         real(wp), intent(in) :: omega
         type(physical_t) :: at
         at = physical%pendulum
         at%omega = omega
         beta_at = physical_beta(at)
      end function beta_at
   end function physical_summary

   !> The pendulum of a chart over `&physical` amplitudes and frequencies at its amplitude `i`
   !> and frequency `j`.
   elemental function grid_pendulum(physical, i, j) result(p)
      type(physical_scene_t), intent(in) :: physical  !! a scene's `&physical`, with amplitudes and frequencies
      integer, intent(in) :: i, j  !! the amplitude (a chart's row) and the frequency (the point along it)
      type(physical_t) :: p
      p = physical%pendulum
      p%a = physical%amplitudes(i)
      p%omega = physical%omegas(j)
   end function grid_pendulum

end module hillstab_batch_scene_physical

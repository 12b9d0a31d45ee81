!> What a system scene may ask of the methods: `check_system_cost` refuses, at reading, a
!> system whose frequencies over the period (at the largest |α| and |β| of the task's points)
!> or whose damping and gyroscopic rates take more steps than the methods' ladder holds,
!> naming the variable that can lower them. Shared by the system tasks chart, points and
!> boundaries.
module hillstab_batch_tasks_system_cost
   use hillstab_core_kinds, only: wp
   use hillstab_core_error, only: error_t
   use hillstab_core_text, only: real_text, fpe_state_t, halting_off, halting_restore
   use hillstab_hill_system_matrix, only: matrix_system_t
   use hillstab_hill_system, only: system_form_t, prepare_system
   use hillstab_batch_scene_types, only: scene_t
   use hillstab_batch_scene_file, only: fail
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   implicit none
   private
   public :: check_system_cost, extreme_name

contains

   !> Refuse a scene whose system or whose largest |α| and |β| make the system's frequencies
   !> so high that a period takes more steps than the methods' ladder holds: √‖M⁻¹K‖ over
   !> the period, and ‖D‖ (damping and gyroscopic rates), times the period, must stay below
   !> 2e3 (about 8000 Magnus steps). The message names the variable that can fix it: a
   !> `&system` matrix when its term alone is too large already (damping or gyroscopic;
   !> k0, the size at α = β = 0; cos or sin when the drive is too large at the largest |α|
   !> and at |α| = 1 already; b so for β), else the range variable of the larger of the α
   !> and β terms (`alpha_variable`, `beta_variable` of `group`). Sizes are computed with
   !> the floating-point traps off: a product that overflows is reported as such.
   subroutine check_system_cost(scene, alpha_abs, beta_abs, group, alpha_variable, beta_variable, error)
      type(scene_t), intent(in) :: scene  !! the scene, its system read
      real(wp), intent(in) :: alpha_abs  !! the largest |α| of the task's points
      real(wp), intent(in) :: beta_abs   !! the largest |β| of the task's points
      character(len=*), intent(in) :: group  !! the task's group that sets them ("chart", "points")
      character(len=*), intent(in) :: alpha_variable  !! its variable of that largest |α|
      character(len=*), intent(in) :: beta_variable   !! its variable of that largest |β|
      type(error_t), allocatable, intent(out) :: error  !! err_input naming file, group and variable
      type(system_form_t) :: form
      type(error_t), allocatable :: cause
      type(fpe_state_t) :: fpe
      real(wp), allocatable :: p(:, :), b(:, :), k0(:, :), c(:, :), g(:, :)
      real(wp) :: size_a, size_k0, size_drive, size_b, size_c, size_g, a, term
      character(len=:), allocatable :: variable, what
      integer :: k, n
      real(wp), parameter :: limit = 2.0e3_wp
      call halting_off(fpe)
      call prepare_system(scene%system, scene%epsilon, form, cause)
      if (allocated(cause)) then
         call halting_restore(fpe)
         call fail(error, scene%source, "system", "mass", cause%message)
         return
      end if
      n = form%n
      allocate (p(n, n), b(n, n), k0(n, n), c(n, n), g(n, n))
      call scene%system%stiffness(0.0_wp, 0.0_wp, k0, b)
      size_k0 = row_sum_norm(matmul(form%m_inverse, k0))
      size_b = row_sum_norm(matmul(form%m_inverse, b))
      size_a = 0.0_wp
      size_drive = 0.0_wp
      do k = 0, 15
         ! eight times of the period, at +|α| and −|α|
         ! b at the same α: a system whose stiffness depends on its row (an equations system,
         ! scaled by its drive frequency α) has none at α = 0
         a = merge(alpha_abs, -alpha_abs, k < 8)
         if (scene%system%alpha_valid(a)) then
            call scene%system%stiffness(a, 0.125_wp*mod(k, 8)*form%period, p, b)
            term = row_sum_norm(matmul(form%m_inverse, p)) + beta_abs*row_sum_norm(matmul(form%m_inverse, b))
            ! a term that overflowed (inf or nan) is beyond any limit
            if (.not. (term <= huge(1.0_wp))) term = huge(1.0_wp)
            size_a = max(size_a, term)
         end if
         ! the drive at |α| = 1 (K is linear in α)
         call scene%system%stiffness(1.0_wp, 0.125_wp*k*form%period/2.0_wp, p, b)
         size_drive = max(size_drive, row_sum_norm(matmul(form%m_inverse, p - k0)))
      end do
      term = row_sum_norm(form%d)**2
      if (term == term) size_a = max(size_a, term)
      if (sqrt(size_a)*form%period <= limit) then
         call halting_restore(fpe)
         return
      end if
      call scene%system%damping(c)
      call scene%system%gyroscopic(g)
      size_c = row_sum_norm(matmul(form%m_inverse, c))
      size_g = row_sum_norm(matmul(form%m_inverse, g))
      if (scene%system%row_dependent() .or. .not. (size_k0 <= huge(1.0_wp) .and. size_b <= huge(1.0_wp))) then
         ! K0, B and the drive alone are not the system's at α = 0 when every row has its own
         ! (an equations system, scaled by its drive frequency α: none at α = 0): name the
         ! chart's range
         variable = ""
         what = alpha_variable
      else if (too_fast(row_sum_norm(form%d)**2)) then
         variable = trim(merge("damping   ", "gyroscopic", .not. size_g > size_c))
         if (.not. (size_c > 0.0_wp .or. size_g > 0.0_wp)) variable = "(epsilon)"
         what = "the damping and gyroscopic rates reach |M^-1 (C + G)| = "// &
                size_text(row_sum_norm(form%d))//" (the "//variable//" matrix alone: "// &
                size_text(max(size_c, size_g))//")"
      else if (too_fast(size_k0)) then
         variable = "k0"
         what = "the system's frequencies reach sqrt(|M^-1 K0|) = "//size_text(sqrt(size_k0))// &
                " already at alpha = beta = 0"
      else if (too_fast(alpha_abs*size_drive) .and. too_fast(size_drive)) then
         variable = drive_variable(scene, form)
         what = "the system's frequencies reach sqrt(|M^-1 K_drive|) = "//size_text(sqrt(size_drive))// &
                " already at |alpha| = 1 (the drive matrices cos, sin)"
      else if (too_fast(beta_abs*size_b) .and. too_fast(size_b)) then
         variable = "b"
         what = "the system's frequencies reach sqrt(|M^-1 B|) = "//size_text(sqrt(size_b))// &
                " already at |beta| = 1"
      else
         variable = ""
         if (alpha_abs*size_drive > beta_abs*size_b) then
            what = alpha_variable
         else
            what = beta_variable
         end if
      end if
      call halting_restore(fpe)
      if (len(variable) > 0) then
         if (variable == "(epsilon)") then
            call fail(error, scene%source, "scene", "epsilon", what//": over the period that is beyond the "// &
               real_text(limit)//" radians the methods integrate (about 8000 steps)")
         else
            call fail(error, scene%source, "system", variable, what//": over the period that is beyond the "// &
               real_text(limit)//" radians the methods integrate (about 8000 steps)")
         end if
      else
         call fail(error, scene%source, group, what, "the system's frequencies reach sqrt(|M^-1 K|) = "// &
            size_text(sqrt(size_a))//" there: over the period that is beyond the "//real_text(limit)// &
            " radians the methods integrate (about 8000 steps)")
      end if
   contains
      !> The term `size` (a squared frequency) alone takes a period beyond the limit.
      logical function too_fast(size)
         real(wp), intent(in) :: size
         too_fast = .not. (sqrt(size)*form%period <= limit)
      end function too_fast
   end subroutine check_system_cost

   !> The bound of a range with the larger magnitude: `<axis>_min` or `<axis>_max`.
   pure function extreme_name(axis, low, high) result(name)
      character(len=*), intent(in) :: axis  !! "alpha" or "beta"
      real(wp), intent(in) :: low   !! the range's `<axis>_min`
      real(wp), intent(in) :: high  !! the range's `<axis>_max`
      character(len=:), allocatable :: name
      name = axis//"_max"
      if (abs(low) > abs(high)) name = axis//"_min"
   end function extreme_name

   !> The largest row sum of |a| (the ∞-norm; +inf or nan when the entries overflowed).
   pure real(wp) function row_sum_norm(a) result(norm)
      real(wp), intent(in) :: a(:, :)
      norm = maxval(sum(abs(a), dim=2))
   end function row_sum_norm

   !> A size for a message: its value, or the words for one that overflowed.
   function size_text(x) result(text)
      real(wp), intent(in) :: x
      character(len=:), allocatable :: text
      if (ieee_is_finite(x)) then
         text = real_text(x)
      else
         text = "more than the largest double (the products of the entries overflow)"
      end if
   end function size_text

   !> Which of `cos` and `sin` holds the larger drive (a matrix system; `cos` otherwise).
   function drive_variable(scene, form) result(name)
      type(scene_t), intent(in) :: scene
      type(system_form_t), intent(in) :: form
      character(len=:), allocatable :: name
      real(wp) :: size_cos, size_sin
      integer :: h
      name = "cos"
      select type (system => scene%system)
      type is (matrix_system_t)
         size_cos = 0.0_wp
         size_sin = 0.0_wp
         do h = 1, system%harmonics
            size_cos = max(size_cos, row_sum_norm(matmul(form%m_inverse, system%kc(:, :, h))))
            size_sin = max(size_sin, row_sum_norm(matmul(form%m_inverse, system%ks(:, :, h))))
         end do
         if (size_sin > size_cos) name = "sin"
      end select
   end function drive_variable
end module hillstab_batch_tasks_system_cost

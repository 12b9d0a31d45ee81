!> Problems written as users write them, shared by the suites of the regions and their edges:
!> the damped Mathieu equation x'' + 2ζx' + (1 + h cos Wt)x = 0 (axes W, h) as a scalar oracle,
!> Bolotin's damped column of three modes x'' + 2ζZx' + (W − (P0 + P1 cos Om t)S)x = 0 (axes
!> Om, P1; the scene data/scenes/column_equations.nml), and two uncoupled Mathieu equations
!> x_i'' + (w_i² + h cos Wt)x_i = 0 as one system (axes W, h), whose regions are those of each
!> equation alone.
module hillstab_test_problems
   use hillstab_core_kinds, only: wp
   use hillstab_core_error, only: error_t
   use hillstab_core_text, only: real_text
   use hillstab_hill_model_equation, only: equation_model_t
   use hillstab_hill_system_equation, only: equations_system_t
   use hillstab_integrate_monodromy, only: method_t
   use hillstab_curves_critical, only: along_beta
   use hillstab_curves_oracle, only: scalar_oracle_t
   implicit none
   private
   public :: damped_mathieu, damped_column, uncoupled_pair, mathieu_equation

contains

   !> x'' + 2ζx' + (w² + h cos Wt)x = 0 as an equation over (W, h).
   subroutine mathieu_equation(zeta, w, e, error)
      real(wp), intent(in) :: zeta                    !! the damping ratio ζ
      real(wp), intent(in) :: w                       !! the natural frequency
      type(equation_model_t), intent(out) :: e        !! the equation
      type(error_t), allocatable, intent(out) :: error  !! set when it is refused
      call e%set_text("parameters", "zeta = "//real_text(zeta)//", nu = "//real_text(w)//", h = 0, W = 2", error)
      if (.not. allocated(error)) call e%set_text("stiffness", "nu^2 + h*cos(W*t)", error)
      if (.not. allocated(error)) call e%set_text("damping", "2*zeta*nu", error)
      if (.not. allocated(error)) call e%set_text("frequency", "W", error)
      if (.not. allocated(error)) call e%set_text("alpha", "W", error)
      if (.not. allocated(error)) call e%set_text("beta", "h", error)
      if (.not. allocated(error)) call e%check_values(error)
   end subroutine mathieu_equation

   !> The damped Mathieu equation (w = 1) as a scalar oracle, drive h, method auto at 1e-12.
   subroutine damped_mathieu(zeta, oracle, error)
      real(wp), intent(in) :: zeta                      !! the damping ratio ζ
      type(scalar_oracle_t), intent(out) :: oracle      !! the oracle
      type(error_t), allocatable, intent(out) :: error  !! set when it is refused
      type(equation_model_t) :: e
      call mathieu_equation(zeta, 1.0_wp, e, error)
      if (allocated(error)) return
      allocate (oracle%model, source=e)
      oracle%drive_axis = along_beta
      oracle%method = method_t(tolerance=1.0e-12_wp)
   end subroutine damped_mathieu

   !> Bolotin's damped column of three modes (ζ = 0.01, P0 = 0.3).
   subroutine damped_column(column, error)
      type(equations_system_t), intent(out) :: column         !! the column
      type(error_t), allocatable, intent(out) :: error        !! set when it is refused
      call column%set_values("n", [3.0_wp], error)
      if (.not. allocated(error)) &
         call column%set_text("matrices", "W = [1, 0, 0; 0, 16, 0; 0, 0, 81], S = [1, 0.3, 0.1; 0.3, 4, 0.4; "// &
                              "0.1, 0.4, 9], Z = [1, 0, 0; 0, 4, 0; 0, 0, 9]", error)
      if (.not. allocated(error)) call column%set_text("parameters", "P0 = 0.3, P1 = 0, Om = 2, zeta = 0.01", error)
      if (.not. allocated(error)) call column%set_text("stiffness", "W - (P0 + P1*cos(Om*t))*S", error)
      if (.not. allocated(error)) call column%set_text("damping", "2*zeta*Z", error)
      if (.not. allocated(error)) call column%set_text("frequency", "Om", error)
      if (.not. allocated(error)) call column%set_text("alpha", "Om", error)
      if (.not. allocated(error)) call column%set_text("beta", "P1", error)
      if (.not. allocated(error)) call column%check_values(error)
   end subroutine damped_column

   !> x_i'' + (w_i² + h cos Wt)x_i = 0, i = 1, 2, uncoupled, as one undamped system over (W, h).
   subroutine uncoupled_pair(w, pair, error)
      real(wp), intent(in) :: w(2)                            !! the two natural frequencies
      type(equations_system_t), intent(out) :: pair           !! the system
      type(error_t), allocatable, intent(out) :: error        !! set when it is refused
      call pair%set_values("n", [2.0_wp], error)
      if (.not. allocated(error)) call pair%set_text("matrices", "K = [1, 0; 0, 0], L = [0, 0; 0, 1]", error)
      if (.not. allocated(error)) call pair%set_text("parameters", "a = "//real_text(w(1))//", b = "// &
                                                     real_text(w(2))//", h = 0, W = 2", error)
      if (.not. allocated(error)) call pair%set_text("stiffness", "a^2*K + b^2*L + h*cos(W*t)", error)
      if (.not. allocated(error)) call pair%set_text("frequency", "W", error)
      if (.not. allocated(error)) call pair%set_text("alpha", "W", error)
      if (.not. allocated(error)) call pair%set_text("beta", "h", error)
      if (.not. allocated(error)) call pair%check_values(error)
   end subroutine uncoupled_pair
end module hillstab_test_problems

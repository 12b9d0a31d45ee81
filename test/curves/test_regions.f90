!> Tests of the resonance regions and their tips (hillstab_curves_regions).
module test_regions
   use hillstab_core_kinds, only: wp, pi, pi2
   use hillstab_core_text, only: real_text
   use hillstab_core_error, only: error_t
   use hillstab_hill_model_mathieu, only: mathieu_model_t
   use hillstab_hill_model_equation, only: equation_model_t
   use hillstab_integrate_monodromy, only: method_t
   use hillstab_curves_critical, only: along_alpha, along_beta
   use hillstab_curves_oracle, only: scalar_oracle_t, system_oracle_t
   use hillstab_hill_system_equation, only: equations_system_t
   use hillstab_integrate_system, only: system_method_t
   use hillstab_curves_regions
   use hillstab_testing
   implicit none
   private
   public :: collect_regions

contains

   function collect_regions() result(suite)
      type(testsuite_t) :: suite
      suite = new_testsuite("regions", [ &
         new_unittest("damped_mathieu_tips", damped_mathieu_tips), &
         new_unittest("column_tips", column_tips)])
   end function collect_regions

   subroutine damped_equation(zeta, oracle, error)
      real(wp), intent(in) :: zeta
      type(scalar_oracle_t), intent(out) :: oracle
      type(error_t), allocatable, intent(out) :: error
      type(equation_model_t) :: e
      call e%set_text("parameters", "zeta = "//real_text(zeta)//", h = 0, W = 2", error)
      if (.not. allocated(error)) call e%set_text("stiffness", "1 + h*cos(W*t)", error)
      if (.not. allocated(error)) call e%set_text("damping", "2*zeta", error)
      if (.not. allocated(error)) call e%set_text("frequency", "W", error)
      if (.not. allocated(error)) call e%set_text("alpha", "W", error)
      if (.not. allocated(error)) call e%set_text("beta", "h", error)
      if (.not. allocated(error)) call e%check_values(error)
      if (allocated(error)) return
      allocate (oracle%model, source=e)
      oracle%drive_axis = along_beta
      oracle%method = method_t(tolerance=1.0e-12_wp)
   end subroutine damped_equation

   subroutine damped_mathieu_tips(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(scalar_oracle_t) :: oracle
      type(region_t), allocatable :: regions(:)
      type(error_t), allocatable :: error
      real(wp) :: zeta
      integer :: j, k
      do j = 1, 20
         zeta = 0.001_wp*1.25_wp**(j - 1)
         call damped_equation(zeta, oracle, error)
         call check(ctx, .not. allocated(error), "equation")
         if (allocated(error)) return
         call find_regions(oracle, 0.5_wp, 3.0_wp, 0.0_wp, 0.5_wp, 3, 1.0e-10_wp, 32, regions, error)
         call check(ctx, .not. allocated(error), "regions")
         if (allocated(error)) then
            print *, error%message
            return
         end if
         do k = 1, size(regions)
            print '(f8.5,i3,i3,f12.8,f12.8,es12.3,es16.8,es10.2,2f12.8,2i6, f12.8)', zeta, regions(k)%kind, regions(k)%order, &
               regions(k)%predicted, regions(k)%frequency, regions(k)%frequency_error, regions(k)%drive, &
               regions(k)%drive_error, regions(k)%edges, regions(k)%status, regions(k)%evaluations, &
               regions(k)%drive/(4*zeta)
         end do
      end do
   end subroutine damped_mathieu_tips

   subroutine column_tips(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(equations_system_t) :: column
      type(system_oracle_t) :: oracle
      type(region_t), allocatable :: regions(:)
      type(error_t), allocatable :: error
      integer :: k
      call column%set_values("n", [3.0_wp], error)
      call column%set_text("matrices", "W = [1, 0, 0; 0, 16, 0; 0, 0, 81], S = [1, 0.3, 0.1; 0.3, 4, 0.4; "// &
                           "0.1, 0.4, 9], Z = [1, 0, 0; 0, 4, 0; 0, 0, 9]", error)
      call column%set_text("parameters", "P0 = 0.3, P1 = 0, Om = 2, zeta = 0.01", error)
      call column%set_text("stiffness", "W - (P0 + P1*cos(Om*t))*S", error)
      call column%set_text("damping", "2*zeta*Z", error)
      call column%set_text("frequency", "Om", error)
      call column%set_text("alpha", "Om", error)
      call column%set_text("beta", "P1", error)
      call column%check_values(error)
      call check(ctx, .not. allocated(error), "the column")
      if (allocated(error)) return
      allocate (oracle%system, source=column)
      oracle%drive_axis = along_beta
      oracle%method = system_method_t(tolerance=1.0e-10_wp)
      call find_regions(oracle, 0.5_wp, 20.0_wp, 0.0_wp, 1.5_wp, 2, 1.0e-10_wp, 32, regions, error)
      call check(ctx, .not. allocated(error), "regions")
      if (allocated(error)) then
         print *, error%message
         return
      end if
      do k = 1, size(regions)
         print '(3i3,i3,f12.7,f12.7,es10.2,es16.8,es10.2,2f12.6,2i6)', regions(k)%kind, regions(k)%order, &
            regions(k)%modes, regions(k)%predicted, regions(k)%frequency, regions(k)%frequency_error, regions(k)%drive, &
            regions(k)%drive_error, regions(k)%edges, regions(k)%status, regions(k)%evaluations
      end do
   end subroutine column_tips
end module test_regions

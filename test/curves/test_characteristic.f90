!> Tests of the characteristic values as library calls (hillstab_curves_characteristic, the C
!> entry point hillstab_characteristic_values and the FORTRAN 77 HSCHAR): Mathieu's a_n, b_n
!> through β = π²a/4 at α = π²q/2 (published values and GSL), the first n of each kind of a
!> drive with sine terms against Hill's method over a window, the roots route (a model with no
!> form Hill's method knows) against the Fourier route of its twin, the exact routes of every
!> kind, and bad input (n < 1, too many values, a small capacity, a bad tolerance).
module test_characteristic
   use, intrinsic :: iso_c_binding, only: c_int, c_double
   use hillstab_core_kinds, only: wp, pi, pi2
   use hillstab_core_error, only: error_t, err_invalid_parameter
   use hillstab_hill_mathieu, only: mathieu_transition_beta, mathieu_kind_a, mathieu_kind_b
   use hillstab_hill_model_mathieu, only: mathieu_model_t
   use hillstab_hill_model_elastic, only: elastic_model_t
   use hillstab_curves_hill_method, only: hill_boundary_t, hill_boundaries, block_periodic_even, block_periodic_odd, &
      block_antiperiodic_even, block_antiperiodic_odd, block_periodic, block_antiperiodic, route_pencil, &
      route_fourier, route_roots
   use hillstab_curves_hill_fourier, only: fourier_boundaries
   use hillstab_curves_boundaries, only: curve_route
   use hillstab_curves_characteristic
   use hillstab_interop_capi, only: hillstab_c_characteristic_values
   use hillstab_interop_legacy, only: hschar
   use hillstab_testing
   use hillstab_test_drive_model, only: drive_model_t, drive_model
   implicit none
   private
   public :: collect_characteristic

contains

   function collect_characteristic() result(suite)
      type(testsuite_t) :: suite
      suite = new_testsuite("characteristic", [ &
         new_unittest("mathieu_published", mathieu_published), &
         new_unittest("mathieu_first_n_against_gsl", mathieu_first_n_against_gsl), &
         new_unittest("drive_first_n", drive_first_n), &
         new_unittest("roots_route", roots_route), &
         new_unittest("elastic_pencil", elastic_pencil), &
         new_unittest("c_entry_point", c_entry_point), &
         new_unittest("legacy_hschar", legacy_hschar), &
         new_unittest("bad_input", bad_input)])
   end function collect_characteristic

   !> q = 1, 10, 25: a = 4β/π² of the values at α = π²q/2 against the published a_n, b_n.
   subroutine mathieu_published(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(hill_boundary_t), allocatable :: v(:)
      type(error_t), allocatable :: error
      call characteristic_values(mathieu_model_t(), 0.5_wp*pi2*1.0_wp, 2, v, error, 1.0e-14_wp)
      call check(ctx, .not. allocated(error), "q = 1: no error")
      if (allocated(error)) return
      call check(ctx, size(v) == 8 .and. all(v%route == route_pencil), "2 of each of 4 kinds, by the pencil")
      if (size(v) /= 8) return
      call check(ctx, all(v%block == [1, 1, 2, 2, 3, 3, 4, 4]), "by kind")
      call check(ctx, all(v%order == [0, 2, 2, 4, 1, 3, 1, 3]), "orders")
      call check(ctx, 4*v(1)%beta/pi2, -0.455138604107_wp, abs=1.0e-12_wp, message="a0(1)")
      call check(ctx, 4*v(3)%beta/pi2, 3.917024772998_wp, abs=1.0e-12_wp, message="b2(1)")
      call check(ctx, 4*v(5)%beta/pi2, 1.859108072514_wp, abs=1.0e-12_wp, message="a1(1)")
      call check(ctx, 4*v(7)%beta/pi2, -0.110248816992_wp, abs=1.0e-12_wp, message="b1(1)")
      call check(ctx, all(v%error_bound < 1.0e-12_wp), "bounds")
      call characteristic_values(mathieu_model_t(), 0.5_wp*pi2*10.0_wp, 1, v, error, 1.0e-14_wp)
      call check(ctx, .not. allocated(error) .and. size(v) == 4, "q = 10")
      if (size(v) /= 4) return
      call check(ctx, 4*v(1)%beta/pi2, -13.936979956659_wp, abs=1.0e-11_wp, message="a0(10)")
      call check(ctx, 4*v(4)%beta/pi2, -13.936552479250_wp, abs=1.0e-11_wp, message="b1(10)")
      call characteristic_values(mathieu_model_t(), 0.5_wp*pi2*25.0_wp, 1, v, error, 1.0e-14_wp)
      call check(ctx, .not. allocated(error) .and. size(v) == 4, "q = 25")
      if (size(v) /= 4) return
      call check(ctx, 4*v(1)%beta/pi2, -40.256779546567_wp, abs=1.0e-11_wp, message="a0(25)")
      call check(ctx, 4*v(3)%beta/pi2, -21.314899690666_wp, abs=1.0e-11_wp, message="a1(25)")
   end subroutine mathieu_published

   !> n = 8 of each kind (orders 0 … 16) at ν = −3, 4, 30 against GSL to 1e-12·max(1, |β|).
   subroutine mathieu_first_n_against_gsl(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp), parameter :: nus(3) = [-3.0_wp, 4.0_wp, 30.0_wp]
      type(hill_boundary_t), allocatable :: v(:)
      type(error_t), allocatable :: error
      real(wp) :: ref
      integer :: f, i
      do f = 1, size(nus)
         call characteristic_values(mathieu_model_t(), nus(f), 8, v, error)
         call check(ctx, .not. allocated(error) .and. size(v) == 32, "32 values")
         if (allocated(error)) return
         do i = 1, size(v)
            call mathieu_transition_beta(merge(mathieu_kind_a, mathieu_kind_b, v(i)%parity == 1), v(i)%order, &
                                         nus(f), ref, error)
            if (allocated(error)) return
            call check(ctx, v(i)%beta, ref, abs=1.0e-12_wp*max(1.0_wp, abs(ref)), message="against GSL")
         end do
      end do
   end subroutine mathieu_first_n_against_gsl

   !> A drive with sine terms (period 4): the first 6 of the two coupled kinds are the lowest 6
   !> of each kind over a window by `fourier_boundaries`.
   subroutine drive_first_n(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(drive_model_t) :: model
      type(hill_boundary_t), allocatable :: v(:), w(:)
      type(error_t), allocatable :: error
      integer :: i, k, seen
      model = drive_model(4.0_wp, -0.2_wp, [0.5_wp, -1.0_wp, 0.0_wp, 0.3_wp], [0.4_wp, 0.0_wp, 0.2_wp, -0.1_wp])
      call characteristic_values(model, 2.0_wp, 6, v, error)
      call check(ctx, .not. allocated(error) .and. size(v) == 12, "12 values")
      if (size(v) /= 12) return
      call check(ctx, all(v%route == route_fourier) .and. all(v(:6)%block == block_periodic) .and. &
                 all(v(7:)%block == block_antiperiodic), "kinds 5 then 6")
      call check(ctx, all(v(:6)%order == [0, 2, 2, 4, 4, 6]) .and. all(v(7:)%order == [1, 1, 3, 3, 5, 5]), "orders")
      call fourier_boundaries(model, 2.0_wp, -20.0_wp, 60.0_wp, 1.0e-12_wp, w, error)
      if (allocated(error)) return
      do k = 1, 2
         seen = 0
         do i = 1, size(w)
            if (w(i)%trace_sign /= merge(2, -2, k == 1)) cycle
            seen = seen + 1
            if (seen > 6) exit
            call check(ctx, v(6*(k - 1) + seen)%beta, w(i)%beta, abs=1.0e-11_wp*max(1.0_wp, abs(w(i)%beta)), &
                       message="as over a window")
         end do
      end do
   end subroutine drive_first_n

   !> A model Hill's method does not know (an even drive whose harmonics are withheld) goes by
   !> the roots of S (method auto; the drive is even and of period 2, which auto's half period
   !> handles): its values agree with the Fourier route of its twin that gives them.
   subroutine roots_route(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(drive_model_t) :: twin, hidden
      type(hill_boundary_t), allocatable :: v(:), w(:)
      real(wp), allocatable :: joined(:), got(:)
      type(error_t), allocatable :: error
      twin = drive_model(2.0_wp, 0.2_wp, [-1.0_wp, 0.4_wp, 0.1_wp], [0.0_wp, 0.0_wp, 0.0_wp])
      hidden = twin
      hidden%withhold = .true.
      call check(ctx, curve_route(hidden) == route_roots .and. curve_route(twin) == route_fourier, "routes")
      call characteristic_values(hidden, 3.0_wp, 4, v, error, 1.0e-11_wp)
      call check(ctx, .not. allocated(error) .and. size(v) == 8, "8 values by the roots")
      if (allocated(error)) call check(ctx, .false., error%message)
      if (size(v) /= 8) return
      call check(ctx, all(v%route == route_roots) .and. all(v%parity == 0), "roots, no parity")
      call characteristic_values(twin, 3.0_wp, 4, w, error)
      if (allocated(error)) return
      ! the twin's four even/odd kinds, joined by kind of S and sorted, are the roots' two kinds
      joined = [pick(w, 1), pick(w, 2)]
      got = v(:4)%beta
      call check_all(ctx, sorted(joined), got, "periodic")
      joined = [pick(w, 3), pick(w, 4)]
      got = v(5:)%beta
      call check_all(ctx, sorted(joined), got, "antiperiodic")
   contains
      function pick(values, block) result(betas)
         type(hill_boundary_t), intent(in) :: values(:)
         integer, intent(in) :: block
         real(wp), allocatable :: betas(:)
         integer :: i
         allocate (betas(0))
         do i = 1, size(values)
            if (values(i)%block == block) betas = [betas, values(i)%beta]
         end do
      end function pick
      function sorted(x) result(y)
         real(wp), intent(in) :: x(:)
         real(wp) :: y(4)
         real(wp) :: t(size(x)), m
         integer :: a, b
         t = x
         do a = 1, size(t)
            do b = a + 1, size(t)
               if (t(b) < t(a)) then
                  m = t(a); t(a) = t(b); t(b) = m
               end if
            end do
         end do
         y = t(:4)
      end function sorted
      subroutine check_all(ctx, expected, got, label)
         type(test_context_t), intent(inout) :: ctx
         real(wp), intent(in) :: expected(:), got(:)
         character(len=*), intent(in) :: label
         integer :: k
         do k = 1, size(got)
            call check(ctx, got(k), expected(k), abs=1.0e-9_wp*max(1.0_wp, abs(expected(k))), message=label)
         end do
      end subroutine check_all
   end subroutine roots_route

   !> The elastic model by the pencil: its first values of each kind equal Hill's curves over
   !> a window, and β = 0 (a₀ … of the exact boundaries) at every α.
   subroutine elastic_pencil(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(hill_boundary_t), allocatable :: v(:), w(:)
      type(error_t), allocatable :: error
      integer :: i, j
      call characteristic_values(elastic_model_t(), 6.0_wp, 3, v, error)
      call check(ctx, .not. allocated(error) .and. size(v) == 12, "12 values")
      if (size(v) /= 12) return
      call hill_boundaries(elastic_model_t(), 6.0_wp, -20.0_wp, 200.0_wp, 1.0e-12_wp, w, error)
      if (allocated(error)) return
      do i = 1, size(v)
         do j = 1, size(w)
            if (w(j)%order == v(i)%order .and. w(j)%parity == v(i)%parity .and. w(j)%trace_sign == v(i)%trace_sign) &
               call check(ctx, v(i)%beta, w(j)%beta, abs=1.0e-11_wp*max(1.0_wp, abs(w(j)%beta)), message="pencil")
         end do
      end do
   end subroutine elastic_pencil

   !> hillstab_characteristic_values: the Mathieu model (code 2) at q = 1 through C, the
   !> capacity and n checked, the outputs untouched on failure.
   subroutine c_entry_point(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(c_double) :: beta(8), bound(8)
      integer(c_int) :: order(8), kind(8), count, status
      beta = -7.0_c_double
      count = -1
      status = hillstab_c_characteristic_values(2_c_int, 0.5_c_double*pi2, 2_c_int, 1.0e-13_c_double, 8_c_int, &
                                                count, beta, order, kind, bound)
      call check(ctx, status == 0 .and. count == 8, "status 0, 8 values")
      if (count /= 8) return
      call check(ctx, all(kind == [1, 1, 2, 2, 3, 3, 4, 4]) .and. all(order == [0, 2, 2, 4, 1, 3, 1, 3]), &
                 "kinds and orders")
      call check(ctx, 4*beta(1)/pi2, -0.455138604107_wp, abs=1.0e-12_wp, message="a0(1)")
      call check(ctx, 4*beta(7)/pi2, -0.110248816992_wp, abs=1.0e-12_wp, message="b1(1)")
      call check(ctx, all(bound > 0.0_wp .and. bound < 1.0e-12_wp), "bounds")
      beta = -7.0_c_double
      count = -1
      status = hillstab_c_characteristic_values(2_c_int, 1.0_c_double, 3_c_int, 1.0e-12_c_double, 8_c_int, &
                                                count, beta, order, kind, bound)
      call check(ctx, status == err_invalid_parameter .and. count == -1 .and. all(beta == -7.0_c_double), &
                 "capacity 8 < 12: refused, outputs untouched")
      status = hillstab_c_characteristic_values(2_c_int, 1.0_c_double, 0_c_int, 1.0e-12_c_double, 8_c_int, &
                                                count, beta, order, kind, bound)
      call check(ctx, status == err_invalid_parameter, "n = 0")
      status = hillstab_c_characteristic_values(9_c_int, 1.0_c_double, 1_c_int, 1.0e-12_c_double, 8_c_int, &
                                                count, beta, order, kind, bound)
      call check(ctx, status == err_invalid_parameter, "unknown model")
      status = hillstab_c_characteristic_values(1_c_int, 12.0_c_double, 1_c_int, 1.0e-12_c_double, 8_c_int, &
                                                count, beta, order, kind, bound)
      call check(ctx, status == err_invalid_parameter, "elastic alpha >= pi^2")
   end subroutine c_entry_point

   !> HSCHAR: as the C entry point, with INFO and NOUT = 0 on failure.
   subroutine legacy_hschar(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp) :: beta(12), errb(12)
      integer :: iord(12), kind(12), nout, info
      call hschar(2, 0.5_wp*pi2*25.0_wp, 3, 1.0e-13_wp, 12, nout, beta, iord, kind, errb, info)
      call check(ctx, info == 0 .and. nout == 12, "INFO 0, 12 values")
      if (nout /= 12) return
      call check(ctx, 4*beta(1)/pi2, -40.256779546567_wp, abs=1.0e-11_wp, message="a0(25)")
      call check(ctx, 4*beta(7)/pi2, -21.314899690666_wp, abs=1.0e-11_wp, message="a1(25)")
      call check(ctx, all(kind(1:3) == 1) .and. all(iord(7:9) == [1, 3, 5]), "kinds and orders")
      call hschar(2, 1.0_wp, 3, 1.0e-13_wp, 11, nout, beta, iord, kind, errb, info)
      call check(ctx, info == err_invalid_parameter .and. nout == 0, "LDIM 11 < 12")
      call hschar(2, 1.0_wp, 2, -1.0_wp, 12, nout, beta, iord, kind, errb, info)
      call check(ctx, info == err_invalid_parameter .and. nout == 0, "TOL < 0")
   end subroutine legacy_hschar

   !> n < 1, n too large, a bad tolerance, α outside the domain: errors, no values.
   subroutine bad_input(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(hill_boundary_t), allocatable :: v(:)
      type(error_t), allocatable :: error
      call characteristic_values(mathieu_model_t(), 1.0_wp, 0, v, error)
      call check(ctx, allocated(error) .and. size(v) == 0, "n = 0")
      if (allocated(error)) call check(ctx, index(error%message, "n must be") > 0, "says n")
      call characteristic_values(mathieu_model_t(), 1.0_wp, max_characteristic_count + 1, v, error)
      call check(ctx, allocated(error), "n too large")
      call characteristic_values(mathieu_model_t(), 1.0_wp, 2, v, error, 0.0_wp)
      call check(ctx, allocated(error), "tolerance 0")
      call characteristic_values(elastic_model_t(), pi2, 2, v, error)
      call check(ctx, allocated(error), "elastic alpha = pi^2")
      call check(ctx, characteristic_capacity(5) == 20, "capacity 4n")
   end subroutine bad_input
end module test_characteristic

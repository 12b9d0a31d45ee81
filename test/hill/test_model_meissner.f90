!> Tests of the Meissner model (hillstab_hill_model_meissner) against its closed forms: Q,
!> its segment means and Fourier series against their definitions; the trace of every
!> exact method, at three tolerances, against Meissner's closed-form trace written out
!> here (cos/cosh of √(β ± α), independent of the library's transfer matrices) at 105 points
!> with |β| up to 1e4, β ± α of opposite signs and damping; methods formula and segments
!> exact; the window's symmetry.
module test_model_meissner
   use hillstab_core_kinds, only: wp, pi
   use hillstab_core_error, only: error_t, err_accuracy
   use hillstab_hill_model, only: hill_model_t, hill_point_t, hill_window_t, hill_coefficient, segment_average, &
      harmonics_infinite
   use hillstab_hill_model_meissner, only: meissner_model_t
   use hillstab_hill_transfer, only: trace_t
   use hillstab_hill_coefficient, only: sampling_endpoint, sampling_average
   use hillstab_integrate_monodromy, only: method_t, monodromy_trace, method_auto, method_magnus4, method_magnus6, &
      method_rk, method_gsl, method_formula, method_segments, method_name
   use hillstab_curves_hill_method, only: hill_boundary_t, route_closed_form
   use hillstab_curves_characteristic, only: characteristic_values
   use hillstab_testing
   implicit none
   private
   public :: collect_model_meissner

   !> The exact methods and the tolerances every one is checked at.
   integer, parameter :: exact_methods(5) = [method_auto, method_magnus4, method_magnus6, method_rk, method_gsl]
   real(wp), parameter :: tolerances(3) = [1.0e-8_wp, 1.0e-10_wp, 1.0e-12_wp]

contains

   function collect_model_meissner() result(suite)
      type(testsuite_t) :: suite
      suite = new_testsuite("meissner", [ &
         new_unittest("coefficient_and_means", coefficient_and_means), &
         new_unittest("fourier_series", fourier_series), &
         new_unittest("window_symmetry", window_symmetry), &
         new_unittest("closed_form_methods", closed_form_methods), &
         new_unittest("exact_methods_closed_form", exact_methods_closed_form), &
         new_unittest("transition_values", transition_values)])
   end function collect_model_meissner

   !> Meissner's trace S = 2 c₊c₋ − (k₊/k₋ + k₋/k₊) s₊s₋ with k± = √(q±), q± = β ± α − ε²/4
   !> (cosh, sinh and √|q| where q < 0), written from the product of the two exact transfer
   !> matrices [[c, s/k], [∓k s, c]]; as ln|S| and its sign, so that large |S| stays finite.
   subroutine closed_form(alpha, beta, epsilon, sign_s, log_s, value)
      real(wp), intent(in) :: alpha, beta, epsilon
      real(wp), intent(out) :: sign_s, log_s, value
      real(wp) :: q(2), c(2), sk(2), ks(2), growth(2), product
      integer :: i
      q = [beta + alpha, beta - alpha] - 0.25_wp*epsilon**2
      do i = 1, 2
         ! c = cos k, sk = sin(k)/k, ks = k sin k (q > 0) or −k sinh k (q < 0), each times e^{-growth}
         if (q(i) > 0.0_wp) then
            growth(i) = 0.0_wp
            c(i) = cos(sqrt(q(i)))
            sk(i) = sin(sqrt(q(i)))/sqrt(q(i))
            ks(i) = sqrt(q(i))*sin(sqrt(q(i)))
         else if (q(i) < 0.0_wp) then
            growth(i) = sqrt(-q(i))
            c(i) = 0.5_wp*(1.0_wp + exp(-2.0_wp*growth(i)))
            sk(i) = 0.5_wp*(1.0_wp - exp(-2.0_wp*growth(i)))/growth(i)
            ks(i) = -growth(i)*0.5_wp*(1.0_wp - exp(-2.0_wp*growth(i)))
         else
            growth(i) = 0.0_wp
            c(i) = 1.0_wp
            sk(i) = 1.0_wp
            ks(i) = 0.0_wp
         end if
      end do
      ! tr([[c₂, s₂/k₂], [−k₂s₂, c₂]] [[c₁, s₁/k₁], [−k₁s₁, c₁]]) = 2c₁c₂ − (s₂/k₂)(k₁s₁) − (s₁/k₁)(k₂s₂)
      product = 2.0_wp*c(1)*c(2) - sk(2)*ks(1) - sk(1)*ks(2)
      sign_s = sign(1.0_wp, product)
      log_s = log(max(abs(product), tiny(1.0_wp))) + growth(1) + growth(2)
      value = 0.0_wp
      if (log_s < 700.0_wp) value = product*exp(growth(1) + growth(2))
   end subroutine closed_form

   !> |S − S_ref|/max(1, |S_ref|), through the logarithms where S_ref is large.
   real(wp) function trace_error(tr, sign_s, log_s, value) result(error)
      type(trace_t), intent(in) :: tr
      real(wp), intent(in) :: sign_s, log_s, value
      if (log_s > log(1.0e6_wp)) then
         error = abs(exp(min(tr%log_abs - log_s, 700.0_wp)) - 1.0_wp)
         if (sign(1.0_wp, tr%value) /= sign_s) error = 2.0_wp
      else
         error = abs(tr%value - value)/max(1.0_wp, abs(value))
      end if
   end function trace_error

   !> The 105 points (α, β, ε): a grid of α against β from −1e4 to 1e4 (β ± α of both signs),
   !> and 45 scattered points, a third damped.
   subroutine test_points(points)
      type(hill_point_t), allocatable, intent(out) :: points(:)
      real(wp), parameter :: alphas(5) = [0.3_wp, 1.0_wp, 2.5_wp, 5.0_wp, 12.0_wp]
      real(wp), parameter :: betas(12) = [-1.0e4_wp, -500.0_wp, -30.0_wp, -3.0_wp, -1.0_wp, 0.5_wp, 2.0_wp, &
                                          5.0_wp, 12.0_wp, 40.0_wp, 300.0_wp, 1.0e4_wp]
      real(wp), parameter :: epsilons(3) = [0.0_wp, 0.5_wp, 2.0_wp]
      integer :: i, j, n
      integer(8) :: state
      real(wp) :: u(3)
      allocate (points(size(alphas)*size(betas) + 45))
      n = 0
      do i = 1, size(alphas)
         do j = 1, size(betas)
            n = n + 1
            points(n) = hill_point_t(alphas(i), betas(j), 0.0_wp)
         end do
      end do
      ! a linear congruential sequence: α in (0, 20), β in (−200, 200)
      state = 12345_8
      do i = 1, 45
         do j = 1, 3
            ! 69069 s + 1 mod 2^31: no product leaves 64 bits (the sanitizer traps signed overflow)
            state = modulo(69069_8*state + 1_8, 2147483648_8)
            u(j) = real(modulo(state, 1000003_8), wp)/1000003.0_wp
         end do
         n = n + 1
         points(n) = hill_point_t(20.0_wp*u(1), 400.0_wp*u(2) - 200.0_wp, epsilons(1 + mod(i, 3)))
      end do
   end subroutine test_points

   !> Q = β ± α on the halves, periodic; segment means against the piecewise integral.
   subroutine coefficient_and_means(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(meissner_model_t) :: meissner
      type(hill_point_t) :: point
      real(wp) :: expected
      point = hill_point_t(1.5_wp, 4.0_wp, 1.0_wp)
      call check(ctx, hill_coefficient(meissner, point, 0.0_wp), 5.5_wp - 0.25_wp, rel=1.0e-15_wp, message="Q(0)")
      call check(ctx, hill_coefficient(meissner, point, 0.999_wp), 5.5_wp - 0.25_wp, rel=1.0e-15_wp, message="Q(0.999)")
      call check(ctx, hill_coefficient(meissner, point, 1.0_wp), 2.5_wp - 0.25_wp, rel=1.0e-15_wp, message="Q(1)")
      call check(ctx, hill_coefficient(meissner, point, -0.5_wp), 2.5_wp - 0.25_wp, rel=1.0e-15_wp, message="Q(-0.5)")
      call check(ctx, hill_coefficient(meissner, point, 7.25_wp), 2.5_wp - 0.25_wp, rel=1.0e-15_wp, message="Q(7.25)")
      ! [0.5, 1.75]: 0.5 at β + α, 0.75 at β − α
      expected = (0.5_wp*5.5_wp + 0.75_wp*2.5_wp)/1.25_wp - 0.25_wp
      call check(ctx, segment_average(meissner, point, 0.5_wp, 1.75_wp), expected, rel=1.0e-14_wp, message="mean")
      ! across a whole period and more: [-0.25, 3.5]
      expected = (1.0_wp*5.5_wp + 1.0_wp*2.5_wp + 0.75_wp*2.5_wp + 1.0_wp*5.5_wp)/3.75_wp - 0.25_wp
      call check(ctx, segment_average(meissner, point, -0.25_wp, 3.5_wp), expected, rel=1.0e-14_wp, &
                 message="mean over more than a period")
      call check(ctx, meissner%two_pieces_exact(), "the two pieces are Q")
   end subroutine coefficient_and_means

   !> The drive's harmonics against its Fourier integrals by quadrature over the pieces.
   subroutine fourier_series(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(meissner_model_t) :: meissner
      real(wp) :: mean, c(6), s(6), integral_c, integral_s
      integer :: m
      call check(ctx, meissner%drive_harmonic_count() == harmonics_infinite, "infinitely many harmonics")
      call meissner%drive_harmonics(2.0_wp, 6, mean, c, s)
      call check(ctx, mean, 0.0_wp, abs=1.0e-15_wp, message="no mean")
      do m = 1, 6
         ! (1/1)∫₀² g cos(mπτ) dτ, g = ±2: the pieces integrate in closed form
         integral_c = 2.0_wp*(sin(m*pi) - 0.0_wp)/(m*pi) - 2.0_wp*(sin(2.0_wp*m*pi) - sin(m*pi))/(m*pi)
         integral_s = 2.0_wp*(1.0_wp - cos(m*pi))/(m*pi) - 2.0_wp*(cos(m*pi) - cos(2.0_wp*m*pi))/(m*pi)
         call check(ctx, c(m), integral_c, abs=1.0e-14_wp, message="cosine coefficient")
         call check(ctx, s(m), integral_s, abs=1.0e-14_wp, message="sine coefficient")
      end do
   end subroutine fourier_series

   !> Q is even about the window's start, which holds the jump at τ = 1.
   subroutine window_symmetry(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(meissner_model_t) :: meissner
      type(hill_window_t) :: window
      type(hill_point_t) :: point
      integer :: j
      real(wp) :: s
      point = hill_point_t(3.0_wp, 1.0_wp, 0.0_wp)
      window = meissner%window(point%alpha)
      call check(ctx, window%half .and. window%n_breaks == 1, "half a period, one jump")
      call check(ctx, window%breaks(1) > window%start .and. window%breaks(1) < window%start + window%length, &
                 "the jump inside the window")
      do j = 1, 19
         s = 0.05_wp*j + 0.013_wp
         call check(ctx, hill_coefficient(meissner, point, window%start + s), &
                    hill_coefficient(meissner, point, window%start - s), rel=0.0_wp, message="even about the start")
      end do
   end subroutine window_symmetry

   !> Method formula (the paper's two pieces) and segments with an even number of pieces are
   !> exact for this model.
   subroutine closed_form_methods(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(meissner_model_t) :: meissner
      type(hill_point_t), allocatable :: points(:)
      type(trace_t) :: tr
      type(error_t), allocatable :: error
      real(wp) :: sign_s, log_s, value
      integer :: k
      call test_points(points)
      do k = 1, size(points)
         call closed_form(points(k)%alpha, points(k)%beta, points(k)%epsilon, sign_s, log_s, value)
         call monodromy_trace(meissner, points(k), method_t(method_formula), tr, error)
         call check(ctx, .not. allocated(error), "formula computes")
         call check(ctx, trace_error(tr, sign_s, log_s, value) <= 1.0e-12_wp, "formula is the closed form")
         call monodromy_trace(meissner, points(k), method_t(method_segments, n_segments=8, sampling=sampling_average), &
                              tr, error)
         call check(ctx, trace_error(tr, sign_s, log_s, value) <= 1.0e-12_wp, "8 averaged pieces are exact")
         call monodromy_trace(meissner, points(k), method_t(method_segments, n_segments=2, sampling=sampling_endpoint), &
                              tr, error)
         call check(ctx, trace_error(tr, sign_s, log_s, value) <= 1.0e-12_wp, "2 pieces by their start are exact")
      end do
   end subroutine closed_form_methods

   !> Every exact method at 1e-8, 1e-10 and 1e-12 at the 105 points: a value with status 0
   !> or 1 everywhere, its error within the tolerance at status 0 (within its estimate at
   !> status 1, round-off limited).
   subroutine exact_methods_closed_form(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(meissner_model_t) :: meissner
      type(hill_point_t), allocatable :: points(:)
      type(trace_t) :: tr
      type(error_t), allocatable :: error
      real(wp) :: sign_s, log_s, value, e, worst(size(exact_methods), size(tolerances))
      integer :: k, m, t, n_roundoff
      character(len=120) :: label
      call test_points(points)
      worst = 0.0_wp
      n_roundoff = 0
      do k = 1, size(points)
         call closed_form(points(k)%alpha, points(k)%beta, points(k)%epsilon, sign_s, log_s, value)
         do m = 1, size(exact_methods)
            do t = 1, size(tolerances)
               write (label, '(a,es9.2,a,3es11.3)') method_name(exact_methods(m))//" tol", tolerances(t), &
                  " at", points(k)%alpha, points(k)%beta, points(k)%epsilon
               call monodromy_trace(meissner, points(k), method_t(exact_methods(m), tolerance=tolerances(t)), tr, error)
               e = trace_error(tr, sign_s, log_s, value)
               if (allocated(error)) then
                  call check(ctx, error%code == err_accuracy, trim(label)//": a value (status 1): "//error%message)
                  if (error%code == err_accuracy) then
                     n_roundoff = n_roundoff + 1
                     call check(ctx, e <= 4.0_wp*tr%error_estimate, trim(label)//": round-off limited, within its estimate")
                  end if
               else
                  call check(ctx, e <= tolerances(t), trim(label)//": error within the tolerance")
                  worst(m, t) = max(worst(m, t), e/tolerances(t))
               end if
            end do
         end do
      end do
      do m = 1, size(exact_methods)
         print '(4x,a8,a,3es9.2)', method_name(exact_methods(m)), ": worst error/tolerance at 1e-8, 1e-10, 1e-12:", &
            worst(m, :)
      end do
      print '(4x,a,i0,a,i0)', "round-off limited: ", n_roundoff, " of ", size(points)*size(exact_methods)*size(tolerances)
   end subroutine exact_methods_closed_form
   !> The first 4 transition values of β of each kind (S = +2, S = −2) at α = 0.5, 3, 8
   !> against the roots of the test's own closed form, found by scanning β from below every
   !> curve (β ≥ −α − 1) in steps of 1e-3 and bisecting to 1e-14; the route is the closed form.
   subroutine transition_values(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp), parameter :: alphas(3) = [0.5_wp, 3.0_wp, 8.0_wp]
      type(meissner_model_t) :: meissner
      type(hill_boundary_t), allocatable :: values(:)
      type(error_t), allocatable :: error
      real(wp) :: expected(4), beta_a, beta_b, f_a, f_b, mid, f_mid, sgn, log_s, s
      integer :: i, kind, found, k, j, iteration
      do i = 1, size(alphas)
         call characteristic_values(meissner, alphas(i), 4, values, error, tolerance=1.0e-12_wp)
         if (allocated(error)) then
            call check(ctx, .false., "characteristic values: "//error%message)
            return
         end if
         call check(ctx, all(values%route == route_closed_form), "route: the closed form")
         do kind = 1, 2
            ! roots of S - 2 (kind 1) and S + 2 (kind 2) of the closed form
            found = 0
            beta_a = -alphas(i) - 1.0_wp
            call closed_form(alphas(i), beta_a, 0.0_wp, sgn, log_s, s)
            f_a = s - merge(2.0_wp, -2.0_wp, kind == 1)
            do while (found < 4)
               beta_b = beta_a + 1.0e-3_wp
               call closed_form(alphas(i), beta_b, 0.0_wp, sgn, log_s, s)
               f_b = s - merge(2.0_wp, -2.0_wp, kind == 1)
               if (f_a == 0.0_wp .or. f_a*f_b < 0.0_wp) then
                  do iteration = 1, 200
                     mid = 0.5_wp*(beta_a + beta_b)
                     if (beta_b - beta_a <= 1.0e-14_wp*max(1.0_wp, abs(mid))) exit
                     call closed_form(alphas(i), mid, 0.0_wp, sgn, log_s, s)
                     f_mid = s - merge(2.0_wp, -2.0_wp, kind == 1)
                     if (f_a*f_mid <= 0.0_wp) then
                        beta_b = mid
                     else
                        beta_a = mid
                        f_a = f_mid
                     end if
                  end do
                  found = found + 1
                  expected(found) = 0.5_wp*(beta_a + beta_b)
               end if
               beta_a = beta_b
               f_a = f_b
            end do
            j = 0
            do k = 1, size(values)
               if (values(k)%trace_sign /= merge(2, -2, kind == 1)) cycle
               j = j + 1
               if (j > 4) exit
               call check(ctx, values(k)%beta, expected(j), rel=2.0e-11_wp, abs=2.0e-11_wp, &
                          message="transition value against the closed form")
            end do
            call check(ctx, j == 4, "four values of each kind")
         end do
      end do
   end subroutine transition_values
end module test_model_meissner

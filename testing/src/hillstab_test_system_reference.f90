!> Test-only reference for systems of Hill equations: the one-period monodromy of
!> M x'' + (C + εM + G) x' + K(τ) x = 0 for a `matrix_system_t`, by a Taylor-series integrator
!> in quadruple precision (real128, about 33 digits). It shares no code with the library's
!> system methods: the Taylor coefficients of K come from those of cos and sin of the drive
!> harmonics at each step's start, the solution's from the recursion
!> (j + 1) Y_{j+1} = Σ_l A_l Y_{j−l}, summed until a term falls below 1e-30 of the sum, on
!> steps of at most 0.5/‖A‖ (so that the series converges fast) over the whole period
!> (no symmetry used). M⁻¹ is computed in quadruple precision by Gauss–Jordan elimination.
module hillstab_test_system_reference
   use, intrinsic :: iso_fortran_env, only: qp => real128
   use hillstab_core_kinds, only: wp
   use hillstab_hill_system_matrix, only: matrix_system_t
   implicit none
   private
   public :: reference_monodromy

   integer, parameter :: max_terms = 200

contains

   !> Φ over one period from τ = 0, rounded to double precision.
   subroutine reference_monodromy(system, alpha, beta, epsilon, phi)
      type(matrix_system_t), intent(in) :: system  !! an assembled matrix system
      real(wp), intent(in) :: alpha, beta, epsilon !! the point and the damping ε
      real(wp), intent(out) :: phi(:, :)           !! Φ (2n × 2n)
      integer :: n, m, k, steps, s, j, l, h_count
      real(qp) :: mi(system%n, system%n), d(system%n, system%n), theta, tau0, h, size_a, p
      real(qp), allocatable :: kj(:, :, :), lj(:, :, :), y(:, :, :), total(:, :)
      real(qp) :: term_norm, total_norm, pi_q, c0, s0, fk, powk
      n = system%n
      m = 2*n
      pi_q = 4.0_qp*atan(1.0_qp)
      p = real(system%p, qp)
      theta = 2.0_qp*pi_q/p
      call invert(real(system%m, qp), mi)
      d = -matmul(mi, real(system%c, qp) + real(system%g, qp)) - real(epsilon, qp)*identity(n)
      ! a bound of ‖A‖ over the period, for the step
      size_a = 1.0_qp + maxval(sum(abs(d), dim=2))
      size_a = max(size_a, maxval(sum(abs(matmul(mi, real(system%k0, qp) + real(beta, qp)*real(system%b, qp))), &
                                      dim=2)) + abs(real(alpha, qp))*sum(sum(sum(abs(real(system%kc, qp)), 1), 1) + &
                                      sum(sum(abs(real(system%ks, qp)), 1), 1))*maxval(abs(mi))*n)
      size_a = max(size_a, theta*max(1, system%harmonics))
      steps = max(8, ceiling(p*size_a/0.5_qp))
      h = p/steps
      allocate (kj(n, n, 0:max_terms), lj(n, n, 0:max_terms), y(m, m, 0:max_terms), total(m, m))
      total = identity(m)
      do s = 1, steps
         tau0 = (s - 1)*h
         ! Taylor coefficients of K at tau0 in the local variable (τ − tau0), in units of h
         kj = 0.0_qp
         kj(:, :, 0) = real(system%k0, qp) + real(beta, qp)*real(system%b, qp)
         do k = 1, system%harmonics
            c0 = cos(k*theta*tau0)
            s0 = sin(k*theta*tau0)
            fk = k*theta*h
            powk = 1.0_qp
            do j = 0, max_terms
               if (j > 0) powk = powk*fk/j
               ! d^j/ds^j of cos(kθ(τ0 + s)) and sin(...) at s = 0, divided by j!, times h^j
               select case (mod(j, 4))
               case (0)
                  kj(:, :, j) = kj(:, :, j) + real(alpha, qp)*powk*(c0*real(system%kc(:, :, k), qp) + &
                                                                    s0*real(system%ks(:, :, k), qp))
               case (1)
                  kj(:, :, j) = kj(:, :, j) + real(alpha, qp)*powk*(-s0*real(system%kc(:, :, k), qp) + &
                                                                    c0*real(system%ks(:, :, k), qp))
               case (2)
                  kj(:, :, j) = kj(:, :, j) + real(alpha, qp)*powk*(-c0*real(system%kc(:, :, k), qp) - &
                                                                    s0*real(system%ks(:, :, k), qp))
               case (3)
                  kj(:, :, j) = kj(:, :, j) + real(alpha, qp)*powk*(s0*real(system%kc(:, :, k), qp) - &
                                                                    c0*real(system%ks(:, :, k), qp))
               end select
            end do
         end do
         do j = 0, max_terms
            lj(:, :, j) = -matmul(mi, kj(:, :, j))
         end do
         ! y_j: the Taylor coefficients of Y(tau0 + σh), σ in [0, 1]
         y(:, :, 0) = total
         total_norm = maxval(abs(total))
         h_count = max_terms
         do j = 0, max_terms - 1
            ! (j + 1) y_{j+1} = h (A y)_j: top rows y's bottom rows; bottom rows Σ L_l top_{j−l} + D bottom_j
            y(1:n, :, j + 1) = h*y(n + 1:m, :, j)/(j + 1)
            y(n + 1:m, :, j + 1) = matmul(d, y(n + 1:m, :, j))
            do l = 0, j
               y(n + 1:m, :, j + 1) = y(n + 1:m, :, j + 1) + matmul(lj(:, :, l), y(1:n, :, j - l))
            end do
            y(n + 1:m, :, j + 1) = h*y(n + 1:m, :, j + 1)/(j + 1)
            term_norm = maxval(abs(y(:, :, j + 1)))
            if (j > 8 .and. term_norm < 1.0e-32_qp*total_norm) then
               h_count = j + 1
               exit
            end if
         end do
         total = 0.0_qp
         do j = h_count, 0, -1
            total = total + y(:, :, j)
         end do
      end do
      phi = real(total, wp)
   end subroutine reference_monodromy

   pure function identity(m) result(a)
      integer, intent(in) :: m
      real(qp) :: a(m, m)
      integer :: i
      a = 0.0_qp
      do i = 1, m
         a(i, i) = 1.0_qp
      end do
   end function identity

   !> Gauss–Jordan inverse with partial pivoting.
   pure subroutine invert(a, inverse)
      real(qp), intent(in) :: a(:, :)
      real(qp), intent(out) :: inverse(:, :)
      real(qp) :: w(size(a, 1), 2*size(a, 1)), row(2*size(a, 1))
      integer :: n, i, k, p
      n = size(a, 1)
      w(:, 1:n) = a
      w(:, n + 1:) = identity(n)
      do k = 1, n
         p = k - 1 + maxloc(abs(w(k:n, k)), 1)
         row = w(k, :)
         w(k, :) = w(p, :)
         w(p, :) = row
         w(k, :) = w(k, :)/w(k, k)
         do i = 1, n
            if (i /= k) w(i, :) = w(i, :) - w(i, k)*w(k, :)
         end do
      end do
      inverse = w(:, n + 1:)
   end subroutine invert
end module hillstab_test_system_reference

!> The matrix kernels of the systems' Magnus integrators (hillstab_integrate_system_magnus): the
!> sixth-order Magnus exponent from the three Gauss nodes (`magnus6_exponent`, in blocks
!> for y = (x, x'): `magnus6_exponent_blocks`), steps of a mesh (`magnus6_steps`, and the
!> unrolled n = 2 case `magnus6_steps_4`), the exponential of a 2n × 2n matrix by the Taylor
!> approximants of Bader, Blanes and Casas with scaling and squaring (`system_exponential`,
!> `exponential_explicit`, `exponential_4`), and the full period from the half period by the
!> symplectic inverse (`full_from_half`, `reversed_inverse`). Pure procedures, no state.
module hillstab_integrate_system_kernels
   use hillstab_core_kinds, only: wp
   use hillstab_hill_system, only: system_form_t
   implicit none
   private
   public :: node_level_t, magnus6_steps_4, magnus6_steps, magnus6_exponent_blocks, exponential_explicit, full_from_half, &
      reversed_inverse, magnus6_exponent, commutator, system_exponential

   !> K at the Gauss nodes of one mesh at one α: −M⁻¹p and −M⁻¹b.
   type :: node_level_t
      logical :: ready = .false.  !! the level is filled
      real(wp), allocatable :: lp(:, :, :)  !! −M⁻¹p at the nodes: n × n × (nodes)
      real(wp), allocatable :: lb(:, :, :)  !! −M⁻¹b at the nodes: n × n × (nodes)
   end type node_level_t

   real(wp), parameter :: sqrt15 = 3.87298334620741688_wp
   !> The Taylor approximants of Bader, Blanes and Casas (Mathematics 7, 1174, 2019), T₁₂ in four
   !> products and T₁₈ in five, and the norms up to which each has a backward error below the
   !> unit round-off: e^X ≈ T(X/2^j) squared j times.
   real(wp), parameter :: theta12 = 0.2996158913811580_wp, theta18 = 1.090863719290036_wp
   !> T₁₂ = q₁ + (q₂ + q₆) q₆, q₆ = q₃ + q₄², q_k = Σ_i t12(i, k) X^i (i = 0 … 3)
   real(wp), parameter :: t12(0:3, 4) = reshape([ &
      -0.0186023205146205532243437300433_wp, -0.00500702322573317730979741843919_wp, &
      -0.573420122960522263905952420789_wp, -0.133399693943892059700768926983_wp, &
      4.6_wp, 0.992875103538486836140479571505_wp, -0.132445561052799638845074997454_wp, 0.0017299_wp, &
      0.211693118299809442949323323336_wp, 0.158224384715726725371768893252_wp, &
      0.165635169436727415011171668419_wp, 0.0107862779315792425026320640108_wp, &
      0.0_wp, -0.131810610138301840156819349464_wp, -0.0202785554058925907933568229945_wp, &
      -0.00675951846863086359778560766482_wp], [4, 4])
   !> T₁₈ = q₁ + (q₂ + q₉) q₉, q₉ = q₅ q₄ + q₃, q_k = Σ t18(i, k) X^i over i = 0, 1, 2, 3, 6
   !> (index 4 standing for X⁶)
   real(wp), parameter :: t18(0:4, 5) = reshape([ &
      0.0_wp, 0.39784974949964507614519612771028_wp, 1.3678377846041171992252370687822_wp, &
      0.49828962252538267755685881726227_wp, -0.00063789819459472330924155005649193_wp, &
      -10.967639605296206259351746267537_wp, 1.6801581387890619718278540172481_wp, &
      0.057177984647886551270287171322525_wp, -0.0069821012248805208429046648380155_wp, &
      0.000033497501708607053831336734066844_wp, &
      -0.090431683239081056197146887701835_wp, -0.067640451907138190756007990037971_wp, &
      0.067596130177045964608279919507894_wp, 0.029555257042931552742606918224223_wp, &
      -0.000013918025751606070112473997934374_wp, &
      0.0_wp, 0.0_wp, -0.0923364619367118592764570775143_wp, -0.0169364939002081717191385115723_wp, &
      -0.0000140086798182036159794363205726_wp, &
      0.0_wp, -0.100365581030144620014614939405_wp, -0.00802924648241156960116919515244_wp, &
      -0.000892138498045729955685466128049_wp, 0.0_wp], [5, 5])

contains

   !> The steps of `magnus_mesh` for order 6 and n = 2 (4 × 4): fixed-size arrays, so that the
   !> compiler expands the products inline (the general path calls the library's matmul), and
   !> the exponent from 2 × 2 blocks (`magnus6_exponent_blocks_2`).
   subroutine magnus6_steps_4(d, beta, h, steps, level, y, log_scale)
      real(wp), intent(in) :: d(2, 2)  !! D = −M⁻¹(C + εM + G)
      real(wp), intent(in) :: beta     !! β (K = p + βb at the nodes)
      real(wp), intent(in) :: h        !! the step
      integer, intent(in) :: steps     !! steps to take
      type(node_level_t), intent(in) :: level  !! −M⁻¹p and −M⁻¹b at the mesh's Gauss nodes
      real(wp), intent(inout) :: y(4, 4)  !! the propagator, advanced by the steps
      real(wp), intent(inout) :: log_scale  !! ln of the power of two y is scaled by
      real(wp) :: l(2, 2, 3), big_omega(4, 4), e(4, 4), big, c, c2, hc, dc(2, 2)
      integer :: k, i
      ! balance: Z = S⁻¹YS, S = diag(cI, I), solves Z' = [[0, I/c], [cL, D]] Z, which is
      ! (1/c)[[0, I], [c²L, cD]]: steps h/c with L, D scaled; c = 2^−k ≈ ‖L‖^−½ (exact scaling)
      c = 1.0_wp
      big = maxval(sum(abs(level%lp(:, :, 1:3) + beta*level%lb(:, :, 1:3)), dim=2))
      if (big > 4.0_wp) c = 2.0_wp**(-nint(0.5_wp*log(big)/log(2.0_wp)))
      c2 = c*c
      hc = h/c
      dc = c*d
      do k = 1, steps
         do i = 1, 3
            l(:, :, i) = c2*(level%lp(:, :, 3*(k - 1) + i) + beta*level%lb(:, :, 3*(k - 1) + i))
         end do
         call magnus6_exponent_blocks_2(l(:, :, 1), l(:, :, 2), l(:, :, 3), dc, hc, big_omega)
         call exponential_4(big_omega, e)
         y = matmul(e, y)
         big = maxval(abs(y))
         if (big > 1.0e100_wp) then
            y = y*2.0_wp**(-exponent(big))
            log_scale = log_scale + exponent(big)*log(2.0_wp)
         end if
      end do
      y(1:2, 3:4) = c*y(1:2, 3:4)
      y(3:4, 1:2) = y(3:4, 1:2)/c
   end subroutine magnus6_steps_4

   !> The steps of `magnus_mesh` for order 6 and any n: explicit-shape work arrays, the
   !> exponent from n × n blocks (`magnus6_exponent_blocks`), balanced as `magnus6_steps_4`.
   subroutine magnus6_steps(n, d, beta, h, steps, level, y, log_scale)
      integer, intent(in) :: n      !! degrees of freedom
      integer, intent(in) :: steps  !! steps to take
      real(wp), intent(in) :: d(n, n)  !! D = −M⁻¹(C + εM + G)
      real(wp), intent(in) :: beta     !! β (K = p + βb at the nodes)
      real(wp), intent(in) :: h        !! the step
      type(node_level_t), intent(in) :: level  !! −M⁻¹p and −M⁻¹b at the mesh's Gauss nodes
      real(wp), intent(inout) :: y(2*n, 2*n)  !! the propagator, advanced by the steps
      real(wp), intent(inout) :: log_scale  !! ln of the power of two y is scaled by
      real(wp) :: l(n, n, 3), big_omega(2*n, 2*n), e(2*n, 2*n), big, c, c2, hc, dc(n, n)
      integer :: k, i
      c = 1.0_wp
      big = maxval(sum(abs(level%lp(:, :, 1:3) + beta*level%lb(:, :, 1:3)), dim=2))
      if (big > 4.0_wp) c = 2.0_wp**(-nint(0.5_wp*log(big)/log(2.0_wp)))
      c2 = c*c
      hc = h/c
      dc = c*d
      do k = 1, steps
         do i = 1, 3
            l(:, :, i) = c2*(level%lp(:, :, 3*(k - 1) + i) + beta*level%lb(:, :, 3*(k - 1) + i))
         end do
         call magnus6_exponent_blocks(n, l(:, :, 1), l(:, :, 2), l(:, :, 3), dc, hc, big_omega)
         call exponential_explicit(2*n, big_omega, e)
         call multiply(2*n, e, y, big_omega)
         y = big_omega
         big = maxval(abs(y))
         if (big > 1.0e100_wp) then
            y = y*2.0_wp**(-exponent(big))
            log_scale = log_scale + exponent(big)*log(2.0_wp)
         end if
      end do
      y(1:n, n + 1:2*n) = c*y(1:n, n + 1:2*n)
      y(n + 1:2*n, 1:n) = y(n + 1:2*n, 1:n)/c
   end subroutine magnus6_steps

   !> `magnus6_exponent_blocks_2` for any n.
   pure subroutine magnus6_exponent_blocks(n, l1, l2, l3, d, h, big_omega)
      integer, intent(in) :: n  !! degrees of freedom
      real(wp), intent(in) :: l1(n, n)  !! L = −M⁻¹K at the first Gauss node
      real(wp), intent(in) :: l2(n, n)  !! at the second
      real(wp), intent(in) :: l3(n, n)  !! at the third
      real(wp), intent(in) :: d(n, n)   !! D = −M⁻¹(C + εM + G)
      real(wp), intent(in) :: h         !! the step
      real(wp), intent(out) :: big_omega(2*n, 2*n)  !! the step's exponent Ω
      real(wp), dimension(n, n) :: p, q, dp, r, w1, w2, w3
      real(wp), dimension(2*n, 2*n) :: u, v, uv, vu
      real(wp) :: g
      integer :: i, m
      m = 2*n
      p = (sqrt15*h/3.0_wp)*(l3 - l1)
      q = (10.0_wp*h/3.0_wp)*(l3 - 2.0_wp*l2 + l1)
      call multiply(n, d, p, dp)
      r = 2.0_wp*q + h*dp
      g = -h/60.0_wp
      v(1:n, 1:n) = g*r
      v(1:n, n + 1:m) = (-2.0_wp*g*h)*p
      call multiply(n, l2, p, w1)
      call multiply(n, p, l2, w2)
      call multiply(n, d, r, w3)
      v(n + 1:m, 1:n) = p + g*(h*(w1 + w2) + w3)
      call multiply(n, p, d, w1)
      v(n + 1:m, n + 1:m) = g*(-h*(dp - w1) - r)
      u(1:n, 1:n) = h*p
      u(1:n, n + 1:m) = 0.0_wp
      do i = 1, n
         u(i, n + i) = -20.0_wp*h
      end do
      u(n + 1:m, 1:n) = -20.0_wp*h*l2 - q + h*dp
      u(n + 1:m, n + 1:m) = -20.0_wp*h*d - h*p
      call multiply(m, u, v, uv)
      call multiply(m, v, u, vu)
      big_omega = (uv - vu)/240.0_wp
      do i = 1, n
         big_omega(i, n + i) = big_omega(i, n + i) + h
      end do
      big_omega(n + 1:m, 1:n) = big_omega(n + 1:m, 1:n) + h*l2 + q/12.0_wp
      big_omega(n + 1:m, n + 1:m) = big_omega(n + 1:m, n + 1:m) + h*d
   end subroutine magnus6_exponent_blocks

   !> `system_exponential` on explicit-shape arrays (no temporaries of assumed shape).
   pure subroutine exponential_explicit(m, x, e)
      integer, intent(in) :: m  !! the order
      real(wp), intent(in) :: x(m, m)  !! X
      real(wp), intent(out) :: e(m, m)  !! e^X
      real(wp), dimension(m, m) :: a, a2, a3, a6, q1, q2, q4, w
      real(wp) :: norm
      integer :: j, k
      norm = maxval(sum(abs(x), dim=1))
      j = 0
      if (norm > theta18) j = exponent(norm/theta18)
      a = x*2.0_wp**(-j)
      call multiply(m, a, a, a2)
      call multiply(m, a2, a, a3)
      if (norm <= theta12) then
         q1 = t12(1, 1)*a + t12(2, 1)*a2 + t12(3, 1)*a3
         q2 = t12(1, 2)*a + t12(2, 2)*a2 + t12(3, 2)*a3
         q4 = t12(1, 4)*a + t12(2, 4)*a2 + t12(3, 4)*a3
         call multiply(m, q4, q4, w)
         e = w + t12(1, 3)*a + t12(2, 3)*a2 + t12(3, 3)*a3
         do k = 1, m
            q1(k, k) = q1(k, k) + t12(0, 1)
            q2(k, k) = q2(k, k) + t12(0, 2)
            e(k, k) = e(k, k) + t12(0, 3)
         end do
      else
         call multiply(m, a3, a3, a6)
         q1 = t18(1, 1)*a + t18(2, 1)*a2 + t18(3, 1)*a3 + t18(4, 1)*a6
         q2 = t18(1, 2)*a + t18(2, 2)*a2 + t18(3, 2)*a3 + t18(4, 2)*a6
         q4 = t18(2, 4)*a2 + t18(3, 4)*a3 + t18(4, 4)*a6
         e = t18(1, 5)*a + t18(2, 5)*a2 + t18(3, 5)*a3
         call multiply(m, e, q4, w)
         e = w + t18(1, 3)*a + t18(2, 3)*a2 + t18(3, 3)*a3 + t18(4, 3)*a6
         do k = 1, m
            q2(k, k) = q2(k, k) + t18(0, 2)
            e(k, k) = e(k, k) + t18(0, 3)
         end do
      end if
      q2 = q2 + e
      call multiply(m, q2, e, w)
      e = q1 + w
      do k = 1, j
         call multiply(m, e, e, w)
         e = w
      end do
   end subroutine exponential_explicit

   !> c = a b for m × m matrices: explicit loops (the compiler vectorises the inner one), no
   !> library call, for the small matrices of a step.
   pure subroutine multiply(m, a, b, c)
      integer, intent(in) :: m
      real(wp), intent(in) :: a(m, m), b(m, m)
      real(wp), intent(out) :: c(m, m)
      integer :: i, j, k
      do j = 1, m
         c(:, j) = a(:, 1)*b(1, j)
         do k = 2, m
            do i = 1, m
               c(i, j) = c(i, j) + a(i, k)*b(k, j)
            end do
         end do
      end do
   end subroutine multiply

   !> `magnus6_exponent` for n = 2 from the blocks of A_i = [[0, I], [L_i, D]]: α₂ = [[0, 0], [P, 0]]
   !> and α₃ = [[0, 0], [Q, 0]] have one block, C₁ = h[[P, 0], [DP, −P]], and C₂ = −[α₁, 2α₃ + C₁]/60
   !> = −(h/60)[[R, −2hP], [h(L₂P + PL₂) + DR, −h(DP − PD) − R]] with R = 2Q + hDP: five 2 × 2
   !> products in place of four 4 × 4 ones; the last commutator in 4 × 4.
   pure subroutine magnus6_exponent_blocks_2(l1, l2, l3, d, h, big_omega)
      real(wp), intent(in) :: l1(2, 2), l2(2, 2), l3(2, 2), d(2, 2), h
      real(wp), intent(out) :: big_omega(4, 4)
      real(wp), dimension(2, 2) :: p, q, dp, r
      real(wp), dimension(4, 4) :: u, v
      real(wp) :: g
      p = (sqrt15*h/3.0_wp)*(l3 - l1)
      q = (10.0_wp*h/3.0_wp)*(l3 - 2.0_wp*l2 + l1)
      dp = matmul(d, p)
      r = 2.0_wp*q + h*dp
      g = -h/60.0_wp
      ! v = α₂ + C₂
      v(1:2, 1:2) = g*r
      v(1:2, 3:4) = (-2.0_wp*g*h)*p
      v(3:4, 1:2) = p + g*(h*(matmul(l2, p) + matmul(p, l2)) + matmul(d, r))
      v(3:4, 3:4) = g*(-h*(dp - matmul(p, d)) - r)
      ! u = −20α₁ − α₃ + C₁
      u(1:2, 1:2) = h*p
      u(1:2, 3:4) = 0.0_wp
      u(1, 3) = -20.0_wp*h
      u(2, 4) = -20.0_wp*h
      u(3:4, 1:2) = -20.0_wp*h*l2 - q + h*dp
      u(3:4, 3:4) = -20.0_wp*h*d - h*p
      big_omega = (matmul(u, v) - matmul(v, u))/240.0_wp
      ! + α₁ + α₃/12
      big_omega(1, 3) = big_omega(1, 3) + h
      big_omega(2, 4) = big_omega(2, 4) + h
      big_omega(3:4, 1:2) = big_omega(3:4, 1:2) + h*l2 + q/12.0_wp
      big_omega(3:4, 3:4) = big_omega(3:4, 3:4) + h*d
   end subroutine magnus6_exponent_blocks_2

   !> `system_exponential` for 4 × 4 matrices.
   pure subroutine exponential_4(x, e)
      real(wp), intent(in) :: x(4, 4)
      real(wp), intent(out) :: e(4, 4)
      real(wp), dimension(4, 4) :: a, a2, a3, a6, q1, q2, q4
      real(wp) :: norm
      integer :: j, k
      norm = maxval(sum(abs(x), dim=1))
      j = 0
      if (norm > theta18) j = exponent(norm/theta18)
      a = x*2.0_wp**(-j)
      a2 = matmul(a, a)
      a3 = matmul(a2, a)
      if (norm <= theta12) then
         q1 = t12(1, 1)*a + t12(2, 1)*a2 + t12(3, 1)*a3
         q2 = t12(1, 2)*a + t12(2, 2)*a2 + t12(3, 2)*a3
         q4 = t12(1, 4)*a + t12(2, 4)*a2 + t12(3, 4)*a3
         e = matmul(q4, q4) + t12(1, 3)*a + t12(2, 3)*a2 + t12(3, 3)*a3
         do k = 1, 4
            q1(k, k) = q1(k, k) + t12(0, 1)
            q2(k, k) = q2(k, k) + t12(0, 2)
            e(k, k) = e(k, k) + t12(0, 3)
         end do
      else
         a6 = matmul(a3, a3)
         q1 = t18(1, 1)*a + t18(2, 1)*a2 + t18(3, 1)*a3 + t18(4, 1)*a6
         q2 = t18(1, 2)*a + t18(2, 2)*a2 + t18(3, 2)*a3 + t18(4, 2)*a6
         q4 = t18(2, 4)*a2 + t18(3, 4)*a3 + t18(4, 4)*a6
         e = matmul(t18(1, 5)*a + t18(2, 5)*a2 + t18(3, 5)*a3, q4) + &
             t18(1, 3)*a + t18(2, 3)*a2 + t18(3, 3)*a3 + t18(4, 3)*a6
         do k = 1, 4
            q2(k, k) = q2(k, k) + t18(0, 2)
            e(k, k) = e(k, k) + t18(0, 3)
         end do
      end if
      e = q1 + matmul(q2 + e, e)
      do k = 1, j
         a = matmul(e, e)
         e = a
      end do
   end subroutine exponential_4

   !> Φ = R Y⁻¹ R Y with Y⁻¹ = Ω⁻¹ Yᵀ Ω (Hamiltonian, G = 0, K even).
   pure subroutine full_from_half(form, y, phi)
      type(system_form_t), intent(in) :: form  !! the prepared system (M, M⁻¹)
      real(wp), intent(in) :: y(:, :)     !! Y over the first half period
      real(wp), intent(out) :: phi(:, :)  !! Φ over the period
      call full_from_half_explicit(form%n, form%m, form%m_inverse, y, phi)
   end subroutine full_from_half

   !> `full_from_half` on explicit-shape arrays: Φ = (R Y⁻¹ R) Y.
   pure subroutine full_from_half_explicit(n, mass, mass_inverse, y, phi)
      integer, intent(in) :: n
      real(wp), intent(in) :: mass(n, n), mass_inverse(n, n), y(2*n, 2*n)
      real(wp), intent(out) :: phi(2*n, 2*n)
      real(wp) :: z(2*n, 2*n)
      call reversed_inverse(n, mass, mass_inverse, y, z)
      call multiply(2*n, z, y, phi)
   end subroutine full_from_half_explicit

   !> z = R Y⁻¹ R for a symplectic Y: with Ω = [[0, M], [−M, 0]] (G = 0),
   !> R Y⁻¹ R = [[M⁻¹Y₂₂ᵀM, M⁻¹Y₁₂ᵀM], [M⁻¹Y₂₁ᵀM, M⁻¹Y₁₁ᵀM]] block by block: the propagator of
   !> the second half of the period from that of the first.
   pure subroutine reversed_inverse(n, mass, mass_inverse, y, z)
      integer, intent(in) :: n  !! degrees of freedom
      real(wp), intent(in) :: mass(n, n)  !! M
      real(wp), intent(in) :: mass_inverse(n, n)  !! M⁻¹
      real(wp), intent(in) :: y(2*n, 2*n)  !! Y (symplectic)
      real(wp), intent(out) :: z(2*n, 2*n)  !! R Y⁻¹ R
      real(wp) :: t(n, n), w(n, n)
      integer :: a, b
      do b = 0, 1
         do a = 0, 1
            ! block (a, b) of R Y⁻¹ R from block (1 − b, 1 − a) of Y, transposed
            t = transpose(y((1 - b)*n + 1:(2 - b)*n, (1 - a)*n + 1:(2 - a)*n))
            call multiply(n, mass_inverse, t, w)
            call multiply(n, w, mass, t)
            z(a*n + 1:(a + 1)*n, b*n + 1:(b + 1)*n) = t
         end do
      end do
   end subroutine reversed_inverse

   !> The sixth-order Magnus exponent of one step from A at the three Gauss nodes.
   pure function magnus6_exponent(a1, a2, a3, h) result(big_omega)
      real(wp), intent(in) :: a1(:, :)  !! A at the first Gauss node
      real(wp), intent(in) :: a2(:, :)  !! at the second
      real(wp), intent(in) :: a3(:, :)  !! at the third
      real(wp), intent(in) :: h         !! the step
      real(wp) :: big_omega(size(a1, 1), size(a1, 1))
      real(wp), dimension(size(a1, 1), size(a1, 1)) :: alpha1, alpha2, alpha3, c1, c2
      alpha1 = h*a2
      alpha2 = (sqrt15*h/3.0_wp)*(a3 - a1)
      alpha3 = (10.0_wp*h/3.0_wp)*(a3 - 2.0_wp*a2 + a1)
      c1 = commutator(alpha1, alpha2)
      c2 = -commutator(alpha1, 2.0_wp*alpha3 + c1)/60.0_wp
      big_omega = alpha1 + alpha3/12.0_wp + commutator(-20.0_wp*alpha1 - alpha3 + c1, alpha2 + c2)/240.0_wp
   end function magnus6_exponent

   !> [a, b] = ab − ba.
   pure function commutator(a, b) result(c)
      real(wp), intent(in) :: a(:, :)  !! a
      real(wp), intent(in) :: b(:, :)  !! b
      real(wp) :: c(size(a, 1), size(a, 1))
      c = matmul(a, b) - matmul(b, a)
   end function commutator

   !> e^X by scaling and squaring: X/2^j with ‖X/2^j‖₁ ≤ θ₁₈ = 1.09, the optimised Taylor
   !> approximant of Bader, Blanes and Casas of degree 12 (four products, ‖X‖₁ ≤ θ₁₂ = 0.30) or
   !> 18 (five products), squared j times; backward error below the unit round-off.
   pure subroutine system_exponential(x, e)
      real(wp), intent(in) :: x(:, :)     !! X (m × m)
      real(wp), intent(out) :: e(:, :)    !! e^X
      call exponential_explicit(size(x, 1), x, e)
   end subroutine system_exponential
end module hillstab_integrate_system_kernels

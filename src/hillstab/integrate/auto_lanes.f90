!> Method auto's kernel (hillstab_integrate_auto): the traces of many points on one mesh
!> (hillstab_integrate_auto_mesh), propagated together by sixth-order Magnus steps in
!> vectorised lanes, with each trace's round-off level.
module hillstab_integrate_auto_lanes
   use hillstab_core_kinds, only: wp
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_positive_inf
   use hillstab_hill_transfer, only: step_functions, cos_taylor, sinc_taylor, trace_t, trace_from_scaled, &
      scaled_matrix_t
   use hillstab_integrate_refine, only: roundoff_level, sensitivity_t, coefficient_level, roundoff_safety, &
      coefficient_roundings_c0, coefficient_roundings_c1, cancellation_limit
   use hillstab_integrate_auto_mesh, only: mesh_t
   implicit none
   private
   public :: lane_traces, lanes_plain, lanes_values, lanes_screen, lane_block

   !> √15, of the Gauss–Legendre 3-point nodes.
   real(wp), parameter :: sqrt15 = 3.87298334620741688517926539978239961_wp
   !> What `lane_traces` computes: S and its round-off level (`roundoff_level` and
   !> `coefficient_level`, their exponentials written out as plain products where the
   !> propagator was never rescaled, the usual case); or S alone (ln|S| left unset below
   !> |S| = e^300 ≈ 1.9e130); or S and its round-off level with ln|S| from the vectorised logarithm
   !> (the screening pass: its logarithms one by one were 2 % of a verdict chart).
   integer, parameter :: lanes_plain = 1, lanes_values = 2, lanes_screen = 3
   !> Lanes propagated together by `lane_traces` (work arrays of this size on the stack).
   integer, parameter :: lane_block = 64
   !> Rescale the propagator when an entry exceeds 2^rescale_exponent.
   integer, parameter :: rescale_exponent = 400

contains

   !> Traces of several points on one mesh, propagated together: the points are the
   !> lanes of structure-of-arrays loops that the compiler vectorises (same mesh, same
   !> control flow; a step where some lane leaves the polynomial range of the
   !> exponential is done lane by lane), in blocks of `lane_block` lanes whose work
   !> arrays live on the stack (arrays sized by the call would be allocated on the heap,
   !> about twenty times a call).
   pure subroutine lane_traces(mesh, c0, c1, phases, traces, floors, mode)
      type(mesh_t), intent(in) :: mesh   !! the mesh every lane is propagated on
      real(wp), intent(in) :: c0(:)      !! constant part of q of each lane: q = c0 + c1 w
      real(wp), intent(in) :: c1(:)      !! coefficient of the shape w of each lane
      real(wp), intent(in) :: phases(:)  !! phase bound of each lane (`split_phases`)
      type(trace_t), intent(out) :: traces(size(c0))  !! S of each lane, with ln|S| where it is large
      real(wp), intent(out) :: floors(size(c0))  !! round-off level of each S, relative to max(1, |S|)
      !> lanes_plain (default: S and its round-off level), lanes_values (S only: floors 0,
      !> and ln|S| left unset below |S| = e^300 where the propagator was never rescaled) or
      !> lanes_screen (S and its round-off level, ln|S| from the vectorised logarithm)
      integer, intent(in), optional :: mode
      integer :: first, last, how
      how = lanes_plain
      if (present(mode)) how = mode
      do first = 1, size(c0), lane_block
         last = min(size(c0), first + lane_block - 1)
         call lane_block_traces(mesh, c0(first:last), c1(first:last), phases(first:last), traces(first:last), &
                                floors(first:last), how)
      end do
   end subroutine lane_traces

   !> `lane_traces` of at most `lane_block` lanes.
   pure subroutine lane_block_traces(mesh, c0, c1, phases, traces, floors, how)
      type(mesh_t), intent(in) :: mesh   !! the mesh every lane is propagated on
      real(wp), intent(in) :: c0(:)      !! constant part of q of each lane: q = c0 + c1 w
      real(wp), intent(in) :: c1(:)      !! coefficient of the shape w of each lane
      real(wp), intent(in) :: phases(:)  !! phase bound of each lane (`split_phases`)
      type(trace_t), intent(out) :: traces(size(c0))  !! S of each lane, with ln|S| where it is large
      real(wp), intent(out) :: floors(size(c0))  !! round-off level of each S, relative to max(1, |S|)
      integer, intent(in) :: how  !! lanes_plain, lanes_values or lanes_screen
      real(wp), parameter :: c_d2 = -sqrt15/3.0_wp, c_d3 = -10.0_wp/3.0_wp, c_60 = 1.0_wp/30.0_wp
      real(wp), parameter :: c_240 = 1.0_wp/240.0_wp, c_120 = 1.0_wp/120.0_wp, c_12 = 1.0_wp/12.0_wp
      real(wp), dimension(lane_block) :: p11, p12, p21, p22, log_scale, ga, gb, gc, z, log_peak, peak, cs, sn
      ! the integrals of `sensitivity_t` (hillstab_integrate_refine), in units of e^{2 log_scale}·2^512
      ! (the propagator is rescaled only every eighth step, so its entries may pass 2^400; their
      ! squares times 2^-512 stay in range)
      real(wp), dimension(lane_block) :: su2, sv2, su2w, sv2w, su2a, sv2a
      ! and over a whole period (no symmetry) the cross terms ∫uv, ∫|uv|, ∫uv c₁w, ∫|uv c₁w|
      real(wp), dimension(lane_block) :: suv, suv_abs, suvw, suva
      logical :: whole  ! the window is the whole period (the cross terms are summed)
      real(wp), parameter :: clamp = 2.0_wp**500  ! largest entry squared in the conditioning
      real(wp), parameter :: square_unit = 2.0_wp**(-256)
      real(wp) :: z_max, uu, vv, sw, level, values_limit
      real(wp) :: h, w1, w2, w3, q1, q2, q3, d2, d3, x3, y1, y2, y3, ls, e11, e12, e21, e22, a, b, big
      real(wp) :: v1, v2, v3
      ! |c₀| of each lane, plus max|v| of an offset (`mesh_t%offset_size`): what the round-off
      ! level counts as the constant part of q
      real(wp) :: c0_size(lane_block)
      logical :: offset
      real(wp) :: big_max, big_min, root_n, size_s, m12, m21, d0, d1, size0, size1
      real(wp), dimension(lane_block) :: s_lane, log_abs
      logical :: special(lane_block)
      integer :: i, l, k, shift, nl
      logical :: rescaled(lane_block)
      nl = size(c0)
      offset = allocated(mesh%v)
      do l = 1, nl
         c0_size(l) = abs(c0(l)) + mesh%offset_size
      end do
      rescaled = .false.
      p11 = 1.0_wp; p12 = 0.0_wp; p21 = 0.0_wp; p22 = 1.0_wp
      log_scale = 0.0_wp
      log_peak = 0.0_wp
      peak = 2.0_wp
      su2 = 0.0_wp; sv2 = 0.0_wp; su2w = 0.0_wp; sv2w = 0.0_wp; su2a = 0.0_wp; sv2a = 0.0_wp
      whole = .not. mesh%half
      suv = 0.0_wp; suv_abs = 0.0_wp; suvw = 0.0_wp; suva = 0.0_wp
      do i = 1, mesh%n_steps
         h = mesh%h(i)
         w1 = mesh%w(1, i); w2 = mesh%w(2, i); w3 = mesh%w(3, i)
         ! sixth-order Gauss–Legendre Magnus generators Ω = [[ga, gb], [gc, −ga]] of all lanes:
         ! `magnus6_generator` of hillstab_integrate_magnus (Blanes, Casas, Oteo, Ros, Phys. Rep. 470 (2009) §5)
         ! written out in components (α₂, α₃ have only a lower-left entry) so that the loop vectorises
         z_max = 0.0_wp
         ! two copies of the generators' loop, with the offset and without: one loop adding a
         ! zero offset cost the elastic chart 1.2 % more instructions
         if (offset) then
            ! q = c₀ + c₁ w + v: the offset's values, the same in every lane
            v1 = mesh%v(1, i); v2 = mesh%v(2, i); v3 = mesh%v(3, i)
            do l = 1, nl
               q1 = c0(l) + c1(l)*w1 + v1
               q2 = c0(l) + c1(l)*w2 + v2
               q3 = c0(l) + c1(l)*w3 + v3
               d2 = c_d2*h*(q3 - q1)
               d3 = c_d3*h*((q3 - q2) + (q1 - q2))
               x3 = 20.0_wp*h*q2 - d3
               y1 = -c_60*h*d3
               y2 = c_60*h*h*d2
               y3 = d2 + c_60*h*h*q2*d2
               ga(l) = c_240*(-20.0_wp*h*y3 - x3*y2)
               gb(l) = h + c_120*(h*d2*y2 + 20.0_wp*h*y1)
               gc(l) = -h*q2 + c_12*d3 + c_120*(x3*y1 - h*d2*y3)
               z(l) = -(ga(l)*ga(l) + gb(l)*gc(l))
               z_max = max(z_max, abs(z(l)))   ! in the loop: a vectorised reduction (maxval is not)
            end do
         else
            do l = 1, nl
               q1 = c0(l) + c1(l)*w1
               q2 = c0(l) + c1(l)*w2
               q3 = c0(l) + c1(l)*w3
               d2 = c_d2*h*(q3 - q1)
               d3 = c_d3*h*((q3 - q2) + (q1 - q2))
               x3 = 20.0_wp*h*q2 - d3
               y1 = -c_60*h*d3
               y2 = c_60*h*h*d2
               y3 = d2 + c_60*h*h*q2*d2
               ga(l) = c_240*(-20.0_wp*h*y3 - x3*y2)
               gb(l) = h + c_120*(h*d2*y2 + 20.0_wp*h*y1)
               gc(l) = -h*q2 + c_12*d3 + c_120*(x3*y1 - h*d2*y3)
               z(l) = -(ga(l)*ga(l) + gb(l)*gc(l))
               z_max = max(z_max, abs(z(l)))   ! in the loop: a vectorised reduction (maxval is not)
            end do
         end if
         ! C, S of `cos_sinc_taylor` (hillstab_hill_transfer), its Horner loop written out here
         ! with its coefficients so that the loop over the lanes vectorises (through a call,
         ! even one per step for all lanes, the chart rows took 17 % to 33 % more instructions)
         if (z_max <= 0.02_wp) then
            ! the usual case (steps short against the local oscillation): degree 5 is enough
            ! (truncation below 1.3e-19)
            do l = 1, nl
               cs(l) = cos_taylor(5)
               sn(l) = sinc_taylor(5)
               do k = 4, 0, -1
                  cs(l) = cos_taylor(k) + z(l)*cs(l)
                  sn(l) = sinc_taylor(k) + z(l)*sn(l)
               end do
            end do
         else if (z_max <= 0.5_wp) then
            do l = 1, nl
               cs(l) = cos_taylor(10)
               sn(l) = sinc_taylor(10)
               do k = 9, 0, -1
                  cs(l) = cos_taylor(k) + z(l)*cs(l)
                  sn(l) = sinc_taylor(k) + z(l)*sn(l)
               end do
            end do
         else if (z_max <= 8.0_wp) then
            ! long steps (the coarse meshes of a verdict's screening pass): degree 16,
            ! truncation below 2e-21 at |z| = 8, still in vectorised lanes
            do l = 1, nl
               cs(l) = cos_taylor(16)
               sn(l) = sinc_taylor(16)
               do k = 15, 0, -1
                  cs(l) = cos_taylor(k) + z(l)*cs(l)
                  sn(l) = sinc_taylor(k) + z(l)*sn(l)
               end do
            end do
         else
            do l = 1, nl
               call step_functions(z(l), cs(l), sn(l), ls)
               log_scale(l) = log_scale(l) + ls
            end do
         end if
         if (how == lanes_values) then
            ! S only: the propagator, without the sensitivity integrals
            do l = 1, nl
               e11 = cs(l) + sn(l)*ga(l); e12 = sn(l)*gb(l)
               e21 = sn(l)*gc(l); e22 = cs(l) - sn(l)*ga(l)
               a = p11(l); b = p21(l)
               p11(l) = e11*a + e12*b
               p21(l) = e21*a + e22*b
               a = p12(l); b = p22(l)
               p12(l) = e11*a + e12*b
               p22(l) = e21*a + e22*b
            end do
         else
         do l = 1, nl
            e11 = cs(l) + sn(l)*ga(l); e12 = sn(l)*gb(l)
            e21 = sn(l)*gc(l); e22 = cs(l) - sn(l)*ga(l)
            a = p11(l); b = p21(l)
            p11(l) = e11*a + e12*b
            p21(l) = e21*a + e22*b
            a = p12(l); b = p22(l)
            p12(l) = e11*a + e12*b
            p22(l) = e21*a + e22*b
            ! the sensitivity integrals ∫u², ∫v², ∫u² c₁w, … (rectangle rule at the step end)
            uu = h*(square_unit*p11(l))**2
            vv = h*(square_unit*p12(l))**2
            sw = c1(l)*w2
            su2(l) = su2(l) + uu; sv2(l) = sv2(l) + vv
            su2w(l) = su2w(l) + uu*sw; sv2w(l) = sv2w(l) + vv*sw
            su2a(l) = su2a(l) + uu*abs(sw); sv2a(l) = sv2a(l) + vv*abs(sw)
         end do
         if (whole) then
            do l = 1, nl
               uu = h*(square_unit*p11(l))*(square_unit*p12(l))
               sw = c1(l)*w2
               suv(l) = suv(l) + uu; suv_abs(l) = suv_abs(l) + abs(uu)
               suvw(l) = suvw(l) + uu*sw; suva(l) = suva(l) + abs(uu*sw)
            end do
         end if
         end if
         if (iand(i, 7) == 0 .or. i == mesh%n_steps) then
            ! conditioning of the propagator, invariant under rescaling x' against x:
            ! min over diagonal D of ‖D Φ D⁻¹‖²_F = a² + d² + 2|b c| (kept at the current
            ! scale; folded into log_peak only when the scale changes, to keep log out of the loop);
            ! the largest and smallest entries, so that the lane-by-lane rescaling runs only
            ! where some lane needs it (all of this in vectorised loops)
            big_max = 0.0_wp
            big_min = huge(1.0_wp)
            do l = 1, nl
               big = max(abs(p11(l)), abs(p12(l)), abs(p21(l)), abs(p22(l)))
               big_max = max(big_max, big)
               big_min = min(big_min, big)
            end do
            if (big_max < clamp) then
               do l = 1, nl
                  peak(l) = max(peak(l), p11(l)**2 + p22(l)**2 + 2.0_wp*abs(p12(l)*p21(l)))
               end do
            else
               ! an entry beyond 2^500 (a growth of more than e^10 a step since the last
               ! check): its square would overflow; such a lane's condition is infinite, as
               ! an overflowing square made it, without raising the overflow flag
               do l = 1, nl
                  if (max(abs(p11(l)), abs(p12(l)), abs(p21(l)), abs(p22(l))) < clamp) then
                     peak(l) = max(peak(l), p11(l)**2 + p22(l)**2 + 2.0_wp*abs(p12(l)*p21(l)))
                  else
                     peak(l) = ieee_value(peak(l), ieee_positive_inf)
                  end if
               end do
            end if
            if (big_max > 2.0_wp**rescale_exponent .or. big_min < 2.0_wp**(-rescale_exponent)) then
            do l = 1, nl
               big = max(abs(p11(l)), abs(p12(l)), abs(p21(l)), abs(p22(l)))
               if (big > 2.0_wp**rescale_exponent .or. big < 2.0_wp**(-rescale_exponent)) then
                  rescaled(l) = .true.
                  log_peak(l) = max(log_peak(l), log(peak(l)) + 2.0_wp*log_scale(l))
                  peak(l) = 0.0_wp
                  shift = exponent(big)
                  p11(l) = scale(p11(l), -shift); p12(l) = scale(p12(l), -shift)
                  p21(l) = scale(p21(l), -shift); p22(l) = scale(p22(l), -shift)
                  su2(l) = scale(su2(l), -2*shift); sv2(l) = scale(sv2(l), -2*shift)
                  su2w(l) = scale(su2w(l), -2*shift); sv2w(l) = scale(sv2w(l), -2*shift)
                  su2a(l) = scale(su2a(l), -2*shift); sv2a(l) = scale(sv2a(l), -2*shift)
                  suv(l) = scale(suv(l), -2*shift); suv_abs(l) = scale(suv_abs(l), -2*shift)
                  suvw(l) = scale(suvw(l), -2*shift); suva(l) = scale(suva(l), -2*shift)
                  log_scale(l) = log_scale(l) + shift*log(2.0_wp)
               end if
            end do
            end if
         end if
      end do
      ! S of every lane, and, where the propagator was never rescaled (the usual case), its
      ! round-off level (`roundoff_level` and `coefficient_level` with their exponentials
      ! written out: log_scale = 0, log_peak = ln max(1, peak), the integrals in units of
      ! 2^-512), all in loops over the lanes that the compiler vectorises; the other lanes
      ! (`special`) one by one through the logarithms (`lane_result`); with S alone
      ! (lanes_values), also every lane beyond e^300 ≈ 1.9e130, where `trace_distance`
      ! compares logarithms (left unset, they made such points' screen bound huge)
      values_limit = merge(1.0e130_wp, 1.0e300_wp, how == lanes_values)
      if (mesh%half) then
         do l = 1, nl
            s_lane(l) = 2.0_wp*(p11(l)*p22(l) + p21(l)*p12(l))
            special(l) = rescaled(l) .or. log_scale(l) /= 0.0_wp .or. .not. abs(s_lane(l)) < values_limit
         end do
      else
         ! the whole period: S = tr Φ
         do l = 1, nl
            s_lane(l) = p11(l) + p22(l)
            special(l) = rescaled(l) .or. log_scale(l) /= 0.0_wp .or. .not. abs(s_lane(l)) < values_limit
         end do
      end if
      if (how == lanes_values) then
         do l = 1, nl
            floors(l) = 0.0_wp
         end do
      else if (.not. mesh%half) then
         ! the level of `coefficient_level` over the whole period (M = Φ, no factor 2, the
         ! cross terms of u v), and `roundoff_level`'s
         root_n = sqrt(real(max(mesh%n_steps, 1), wp))
         do l = 1, nl
            size_s = max(1.0_wp, abs(s_lane(l)))
            m21 = p21(l)
            m12 = p12(l)
            x3 = p22(l) - p11(l)
            d0 = c0_size(l)*abs(m21*sv2(l) - m12*su2(l) - x3*suv(l))
            size0 = c0_size(l)*(abs(m21)*sv2(l) + abs(m12)*su2(l) + abs(x3)*suv_abs(l))
            d1 = abs(m21*sv2w(l) - m12*su2w(l) - x3*suvw(l))
            size1 = abs(m21)*sv2a(l) + abs(m12)*su2a(l) + abs(x3)*suva(l)
            level = merge(coefficient_roundings_c0*d0, 0.0_wp, d0 > cancellation_limit*size0) + &
                    merge(coefficient_roundings_c1*d1, 0.0_wp, d1 > cancellation_limit*size1)
            ! beyond |S| = 1/cancellation_limit the sensitivity cancels below the limit by
            ! growth alone (terms of order S², result of order S): what is left is the step
            ! sums' error (`coefficient_level`)
            if (size_s > 1.0_wp/cancellation_limit) level = 0.0_wp
            special(l) = special(l) .or. .not. level < 2.0_wp**400
            ! (`roundoff_level` over the whole period: the amplification √κ)
            floors(l) = roundoff_safety*epsilon(1.0_wp)*root_n*sqrt(max(1.0_wp, peak(l)))/size_s + &
                        2.0_wp*epsilon(1.0_wp)*phases(l) + epsilon(1.0_wp)*(level*2.0_wp**512)/size_s
         end do
      else
         root_n = sqrt(real(max(mesh%n_steps, 1), wp))
         do l = 1, nl
            size_s = max(1.0_wp, abs(s_lane(l)))
            m21 = 2.0_wp*p11(l)*p21(l)
            m12 = 2.0_wp*p12(l)*p22(l)
            d0 = 2.0_wp*c0_size(l)*abs(m21*sv2(l) - m12*su2(l))
            size0 = 2.0_wp*c0_size(l)*(abs(m21)*sv2(l) + abs(m12)*su2(l))
            d1 = 2.0_wp*abs(m21*sv2w(l) - m12*su2w(l))
            size1 = 2.0_wp*(abs(m21)*sv2a(l) + abs(m12)*su2a(l))
            level = merge(coefficient_roundings_c0*d0, 0.0_wp, d0 > cancellation_limit*size0) + &
                    merge(coefficient_roundings_c1*d1, 0.0_wp, d1 > cancellation_limit*size1)
            ! beyond 2^400 the integrals times 2^512 may overflow: those lanes go the long way
            special(l) = special(l) .or. .not. level < 2.0_wp**400
            floors(l) = roundoff_safety*epsilon(1.0_wp)*root_n*max(1.0_wp, peak(l))/size_s + &
                        2.0_wp*epsilon(1.0_wp)*phases(l) + epsilon(1.0_wp)*(level*2.0_wp**512)/size_s
         end do
      end if
      if (how == lanes_screen) then
         ! ln|S| of every lane in a loop of its own, which the compiler vectorises (the
         ! logarithms four at a time, within a few ulp of the scalar one; one by one they were
         ! 2 % of a verdict chart); S = 0 has ln|S| = −huge, as in `trace_from_scaled`
         do l = 1, nl
            log_abs(l) = log(max(abs(s_lane(l)), tiny(1.0_wp)))
         end do
      end if
      do l = 1, nl
         if (special(l)) then
            call lane_result(p11(l), p12(l), p21(l), p22(l), log_scale(l), log_peak(l), peak(l), &
               sensitivity_t(2.0_wp*log_scale(l) + 512.0_wp*log(2.0_wp), su2(l), sv2(l), su2w(l), sv2w(l), &
               su2a(l), sv2a(l), suv(l), suv_abs(l), suvw(l), suva(l)), c0_size(l), mesh%n_steps, phases(l), traces(l), &
               floors(l), mesh%half)
            if (how == lanes_values) floors(l) = 0.0_wp
         else if (how == lanes_values) then
            ! ln|S| is left unset (below 1.9e130 nothing reads it)
            traces(l)%value = s_lane(l)
            traces(l)%overflow = .false.
         else if (how == lanes_screen) then
            traces(l)%value = s_lane(l)
            traces(l)%overflow = .false.
            traces(l)%log_abs = merge(log_abs(l), -huge(1.0_wp), s_lane(l) /= 0.0_wp)
         else
            traces(l) = trace_from_scaled(s_lane(l), 0.0_wp)
         end if
      end do
   end subroutine lane_block_traces

   !> S of one lane from its propagator Φ = [[p11, p12], [p21, p22]]·e^{log_scale} over the
   !> window (half a period: S = 2(u v' + u' v); the period: S = tr Φ) and its round-off
   !> level (`roundoff_level`, `coefficient_level`).
   pure subroutine lane_result(p11, p12, p21, p22, log_scale, log_peak, peak, sensitivity, c0, n_steps, phase, &
                               trace, floor, half)
      real(wp), intent(in) :: p11, p12, p21, p22, log_scale, peak, c0, phase
      real(wp), intent(in) :: log_peak  !! ln of the largest condition before the last rescaling
      type(sensitivity_t), intent(in) :: sensitivity  !! the integrals, in units of e^{2 log_scale}·2^512
      integer, intent(in) :: n_steps
      type(trace_t), intent(out) :: trace
      real(wp), intent(out) :: floor
      logical, intent(in) :: half  !! the window is half a period of an even q
      type(scaled_matrix_t) :: monodromy
      real(wp) :: peak_log
      if (.not. half) then
         ! the whole period: M = Φ
         trace = trace_from_scaled(p11 + p22, log_scale)
         peak_log = log_peak
         if (peak > 0.0_wp) peak_log = max(log_peak, log(peak) + 2.0_wp*log_scale)
         floor = roundoff_level(peak_log, trace%log_abs, n_steps, phase, half=.false.)
         monodromy%m = reshape([p11, p21, p12, p22], [2, 2])
         monodromy%log_scale = log_scale
         floor = floor + coefficient_level(sensitivity, c0, monodromy, trace%log_abs, half=.false.)
         return
      end if
      ! S = 2(u v' + u' v) from Φ(1) = [[u, v], [u', v']] (Floquet theory)
      trace = trace_from_scaled(2.0_wp*(p11*p22 + p21*p12), 2.0_wp*log_scale)
      peak_log = log_peak
      if (peak > 0.0_wp) peak_log = max(log_peak, log(peak) + 2.0_wp*log_scale)
      floor = roundoff_level(peak_log, trace%log_abs, n_steps, phase)
      ! the rounding of q itself, through the sensitivity of S to its constants; the corners
      ! of M = monodromy_from_half_period (its diagonal is not used), element by element,
      ! not through reshape, a library call per point
      monodromy%m(1, 1) = 0.0_wp
      monodromy%m(2, 1) = 2.0_wp*p11*p21
      monodromy%m(1, 2) = 2.0_wp*p12*p22
      monodromy%m(2, 2) = 0.0_wp
      monodromy%log_scale = 2.0_wp*log_scale
      floor = floor + coefficient_level(sensitivity, c0, monodromy, trace%log_abs)
   end subroutine lane_result
end module hillstab_integrate_auto_lanes

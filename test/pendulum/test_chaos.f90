!> Tests of the chaos indicators (hillstab_pendulum_chaos, hillstab_pendulum_chaos_track)
!> against independent references: MEGNO tends to 2 on the paper's regular cases (c)
!> and (d) and grows like λt/2 on the chaotic case (g); the verdicts agree with stored
!> verdicts of long reference runs (data/reference/chaos_verdicts.dat: 3000 radial
!> periods of `lyapunov_largest`, made by data/reference/make_chaos_reference.sh); the
!> DOP853 path gives `lyapunov_largest`'s exponent bit for bit and the symplectic path
!> the same exponent on regular orbits; the damped pendulum runs on DOP853 with λ → −ε;
!> the batch gives each orbit its own result; an orbit whose energy error the fixed step
!> cannot hold falls back to DOP853; bad arguments are refused.
module test_chaos
   use hillstab_core_kinds, only: wp
   use hillstab_core_error, only: error_t, err_invalid_parameter, err_accuracy
   use hillstab_pendulum_equations, only: pendulum_t, pendulum_initial_state
   use hillstab_pendulum_lyapunov, only: lyapunov_t, lyapunov_largest
   use hillstab_pendulum_symplectic, only: symplectic_scheme_count
   use hillstab_pendulum_chaos
   use hillstab_testing
   use hillstab_test_pendulum, only: pendulum_at
   implicit none
   private
   public :: collect_chaos

   !> The stored reference verdicts.
   character(len=*), parameter :: reference_file = "data/reference/chaos_verdicts.dat"

contains

   function collect_chaos() result(suite)
      type(testsuite_t) :: suite
      suite = new_testsuite("chaos", [ &
         new_unittest("megno_tends_to_two_on_regular_orbits", megno_tends_to_two_on_regular_orbits), &
         new_unittest("megno_grows_on_chaotic_orbit", megno_grows_on_chaotic_orbit), &
         new_unittest("early_stop_on_chaos_only", early_stop_on_chaos_only), &
         new_unittest("verdicts_match_reference", verdicts_match_reference), &
         new_unittest("dop853_path_is_lyapunov_largest", dop853_path_is_lyapunov_largest), &
         new_unittest("symplectic_agrees_with_dop853", symplectic_agrees_with_dop853), &
         new_unittest("damped_runs_on_dop853", damped_runs_on_dop853), &
         new_unittest("batch_equals_single_orbits", batch_equals_single_orbits), &
         new_unittest("energy_error_falls_back", energy_error_falls_back), &
         new_unittest("verdict_rule", verdict_rule), &
         new_unittest("bad_arguments", bad_arguments)])
   end function collect_chaos

   !> The indicators of one orbit from φ0 = 0.017 at rest; stops the test program if
   !> the library refuses (the suites only ask for valid runs).
   function run(alpha, beta, periods, options, epsilon) result(r)
      real(wp), intent(in) :: alpha, beta
      integer, intent(in) :: periods
      type(chaos_options_t), intent(in) :: options
      real(wp), intent(in), optional :: epsilon
      type(chaos_t) :: r
      type(error_t), allocatable :: error
      type(pendulum_t) :: p
      p = pendulum_at(alpha, beta, epsilon)
      call chaos_indicators(p, pendulum_initial_state(p, 0.017_wp), periods, 1.0e-10_wp, options, r, error)
      if (allocated(error)) error stop "test_chaos: "//error%message
   end function run

   !> Cases (c) and (d): ⟨Y⟩ rises towards 2 from below (the tangent vector's growth turns
   !> linear slowly on these near-bounce orbits): at 10⁴ radial periods within 0.15 of 2
   !> (measured 1.886 and 1.946), above its value at 10³; the verdict is regular.
   subroutine megno_tends_to_two_on_regular_orbits(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp), parameter :: cases(2, 2) = reshape([2.57_wp, 1.29_wp, 5.0_wp, 0.76_wp], [2, 2])
      type(chaos_t) :: short, long
      integer :: k
      do k = 1, 2
         short = run(cases(1, k), cases(2, k), 1000, chaos_options_t())
         long = run(cases(1, k), cases(2, k), 10000, chaos_options_t())
         call check(ctx, long%integrator == chaos_symplectic, "on the symplectic scheme")
         call check(ctx, long%megno, 2.0_wp, abs=0.15_wp, message="megno -> 2")
         call check(ctx, long%megno > short%megno, "megno rises towards 2")
         call check(ctx, long%chaotic == 0.0_wp .and. short%chaotic == 0.0_wp, "regular")
         call check(ctx, long%periods == 10000 .and. .not. long%stopped_early, "no early stop on a regular orbit")
         write (*, '(4x,a,2f6.2,a,f7.3,a,f7.3)') "case", cases(:, k), ": megno at 1e3 periods ", short%megno, &
            ", at 1e4 ", long%megno
      end do
   end subroutine megno_tends_to_two_on_regular_orbits

   !> Case (g) without early stop: ⟨Y⟩ grows like λn/2 — between 0.25 λn and λn at
   !> n = 400 and 800 (measured ⟨Y⟩ ≈ 0.44 λn), its ratio between the two in [1.5, 2.7]
   !> (2 for linear growth); the FLI grows like λn; the verdict is chaotic.
   subroutine megno_grows_on_chaotic_orbit(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(chaos_options_t) :: options
      type(chaos_t) :: a, b
      options%early_stop = .false.
      a = run(7.48_wp, 2.47_wp, 400, options)
      b = run(7.48_wp, 2.47_wp, 800, options)
      call check(ctx, a%megno > 0.25_wp*a%lyapunov*400 .and. a%megno < a%lyapunov*400, "megno ~ lambda n/2 at 400")
      call check(ctx, b%megno > 0.25_wp*b%lyapunov*800 .and. b%megno < b%lyapunov*800, "megno ~ lambda n/2 at 800")
      call check(ctx, b%megno/a%megno > 1.5_wp .and. b%megno/a%megno < 2.7_wp, "megno grows linearly")
      call check(ctx, b%fli > 0.5_wp*b%lyapunov*800, "fli ~ lambda n")
      call check(ctx, a%chaotic == 1.0_wp .and. b%chaotic == 1.0_wp, "chaotic")
      call check(ctx, b%max_abs_phi > 1.0_wp, "large swings")
      write (*, '(4x,a,2f9.2,a,2f7.3)') "case (g): megno at 400, 800 periods ", a%megno, b%megno, ", lambda ", &
         a%lyapunov, b%lyapunov
   end subroutine megno_grows_on_chaotic_orbit

   !> With early stopping (the default) the chaotic case (g) stops within 200 of 1000
   !> periods as chaotic, also from φ0 = 1e-12 where the linear growth of the swing
   !> lasts about 11 periods and lifts ⟨Y⟩ as chaos would (the transient allowance keeps
   !> it from stopping there: it stops well after); the regular case (c) runs all periods.
   subroutine early_stop_on_chaos_only(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(chaos_t) :: r
      type(pendulum_t) :: p
      type(error_t), allocatable :: error
      type(chaos_options_t) :: defaults
      r = run(7.48_wp, 2.47_wp, 1000, defaults)
      call check(ctx, r%stopped_early .and. r%periods < 200 .and. r%chaotic == 1.0_wp, "(g) stopped early, chaotic")
      call check(ctx, r%periods >= defaults%min_periods, "not before min_periods")
      p = pendulum_at(7.48_wp, 2.47_wp)
      call chaos_indicators(p, pendulum_initial_state(p, 1.0e-12_wp), 1000, 1.0e-10_wp, chaos_options_t(), r, error)
      call check(ctx, .not. allocated(error), "integrated")
      call check(ctx, r%stopped_early .and. r%periods > 50 .and. r%chaotic == 1.0_wp, &
         "(g) from 1e-12: stopped after the linear phase")
      call check(ctx, chaos_transient_allowance(p, pendulum_initial_state(p, 1.0e-12_wp)) > 25.0_wp, "allowance")
      r = run(2.57_wp, 1.29_wp, 1000, chaos_options_t())
      call check(ctx, .not. r%stopped_early .and. r%periods == 1000, "(c) runs all periods")
   end subroutine early_stop_on_chaos_only

   !> The stored reference verdicts (3000 radial periods of `lyapunov_largest`, DOP853 at
   !> 1e-11): every point the reference calls clearly regular or chaotic gets the same
   !> verdict from the default options at 1000 radial periods (measured on a 40 × 40 map:
   !> 1595 of 1595), the orbits computed in one batch.
   subroutine verdicts_match_reference(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp), allocatable :: rows(:, :)
      type(pendulum_t), allocatable :: pendula(:)
      real(wp), allocatable :: y0(:, :)
      type(chaos_t), allocatable :: results(:)
      integer :: k, n, n_clear, n_agree
      logical :: ok
      call read_reference(rows, ok)
      call check(ctx, ok, "reference table "//reference_file//" read")
      if (.not. ok) return
      n = size(rows, 2)
      allocate (pendula(n), y0(4, n), results(n))
      do k = 1, n
         pendula(k) = pendulum_at(rows(1, k), rows(2, k))
         y0(:, k) = pendulum_initial_state(pendula(k), 0.017_wp)
      end do
      call chaos_indicators_batch(pendula, y0, 1000, 1.0e-10_wp, chaos_options_t(), results)
      n_clear = 0
      n_agree = 0
      do k = 1, n
         call check(ctx, .not. allocated(results(k)%error), "integrated")
         if (rows(3, k) == 0.5_wp) cycle
         n_clear = n_clear + 1
         if (results(k)%chaotic == rows(3, k)) n_agree = n_agree + 1
         call check(ctx, results(k)%chaotic == rows(3, k), "verdict as the reference")
      end do
      call check(ctx, n_clear >= 60, "most reference points clear")
      write (*, '(4x,i0,a,i0,a,i0,a)') n_agree, " of ", n_clear, " clear reference verdicts met (", n, " points)"
   end subroutine verdicts_match_reference

   !> The table's (α, β, verdict) columns.
   subroutine read_reference(rows, ok)
      real(wp), allocatable, intent(out) :: rows(:, :)
      logical, intent(out) :: ok
      character(len=512) :: line
      real(wp) :: values(11), buffer(3, 1000)
      integer :: unit, ios, n
      ok = .false.
      open (newunit=unit, file=reference_file, status="old", action="read", iostat=ios)
      if (ios /= 0) return
      n = 0
      do
         read (unit, '(a)', iostat=ios) line
         if (ios /= 0) exit
         if (line(1:1) == "#" .or. len_trim(line) == 0) cycle
         read (line, *, iostat=ios) values
         if (ios /= 0 .or. n == size(buffer, 2)) then
            close (unit)
            return
         end if
         n = n + 1
         buffer(:, n) = [values(1), values(2), values(11)]
      end do
      close (unit)
      rows = buffer(:, 1:n)
      ok = n > 0
   end subroutine read_reference

   !> Integrator dop853 without early stop is `lyapunov_largest` with indicators: the same
   !> exponent, spread, energy drift and f-evaluations, bit for bit, on (c) and (g).
   subroutine dop853_path_is_lyapunov_largest(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp), parameter :: cases(2, 2) = reshape([2.57_wp, 1.29_wp, 7.48_wp, 2.47_wp], [2, 2])
      type(chaos_options_t) :: options
      type(chaos_t) :: r
      type(lyapunov_t) :: reference
      type(error_t), allocatable :: error
      type(pendulum_t) :: p
      integer :: k
      options%integrator = chaos_dop853
      options%early_stop = .false.
      do k = 1, 2
         p = pendulum_at(cases(1, k), cases(2, k))
         r = run(cases(1, k), cases(2, k), 120, options)
         call lyapunov_largest(p, pendulum_initial_state(p, 0.017_wp), 120, 1.0e-10_wp, reference, error)
         call check(ctx, .not. allocated(error), "integrated")
         call check(ctx, r%integrator == chaos_dop853 .and. r%periods == 120, "dop853, all periods")
         call check(ctx, r%lyapunov == reference%exponent, "the same exponent")
         call check(ctx, r%spread == reference%spread, "the same spread")
         call check(ctx, r%energy_drift == reference%energy_drift, "the same energy drift")
         call check(ctx, r%stats%n_evaluations == reference%stats%n_evaluations, "the same evaluations")
         call check(ctx, r%max_abs_phi, reference%max_abs_phi, rel=1.0e-14_wp, message="max |phi|")
      end do
   end subroutine dop853_path_is_lyapunov_largest

   !> The symplectic tangent map and DOP853 on the variational equations agree on regular
   !> orbits, (a) and (c) over 300 periods: λ to 1e-6 (measured 1e-8 and 3e-8), ⟨Y⟩ to
   !> 0.05, with less than half the evaluations (force evaluations against f-evaluations
   !> of the 8-D system; measured 2.3 times fewer).
   subroutine symplectic_agrees_with_dop853(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp), parameter :: cases(2, 2) = reshape([1.48_wp, 2.47_wp, 2.57_wp, 1.29_wp], [2, 2])
      type(chaos_options_t) :: symplectic, dop853
      type(chaos_t) :: a, b
      integer :: k
      symplectic%integrator = chaos_symplectic
      dop853%integrator = chaos_dop853
      do k = 1, 2
         a = run(cases(1, k), cases(2, k), 300, symplectic)
         b = run(cases(1, k), cases(2, k), 300, dop853)
         call check(ctx, a%integrator == chaos_symplectic .and. b%integrator == chaos_dop853, "integrators")
         call check(ctx, a%lyapunov, b%lyapunov, abs=1.0e-6_wp, message="lambda")
         call check(ctx, a%megno, b%megno, abs=0.05_wp, message="megno")
         call check(ctx, a%energy_error < 1.0e-6_wp, "energy error within the tolerance")
         call check(ctx, a%stats%n_evaluations < b%stats%n_evaluations/2, "fewer evaluations")
         write (*, '(4x,a,2f6.2,a,2es10.2,a,2f7.3,a,2i9)') "case", cases(:, k), ": lambda symplectic - dop853 ", &
            a%lyapunov - b%lyapunov, b%lyapunov, ", megno", a%megno, b%megno, ", evaluations", a%stats%n_evaluations, &
            b%stats%n_evaluations
      end do
   end subroutine symplectic_agrees_with_dop853

   !> Damping (ε = 0.4) at the stable case (c): auto runs DOP853 (not Hamiltonian); λ → −ε
   !> per radial period (to 1e-3 over 400 periods, as `lyapunov_largest`); ⟨Y⟩ < 0
   !> (contraction) gives a regular verdict; the symplectic integrator is refused.
   subroutine damped_runs_on_dop853(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(chaos_options_t) :: options
      type(chaos_t) :: r
      type(error_t), allocatable :: error
      type(pendulum_t) :: p
      r = run(2.57_wp, 1.29_wp, 400, chaos_options_t(), epsilon=0.4_wp)
      call check(ctx, r%integrator == chaos_dop853 .and. r%scheme == 0, "auto: dop853")
      call check(ctx, r%lyapunov, -0.4_wp, abs=1.0e-3_wp, message="lambda -> -epsilon")
      call check(ctx, r%megno < 0.0_wp .and. r%chaotic == 0.0_wp, "regular")
      options%integrator = chaos_symplectic
      p = pendulum_at(2.57_wp, 1.29_wp, 0.4_wp)
      call chaos_indicators(p, pendulum_initial_state(p, 0.017_wp), 10, 1.0e-10_wp, options, r, error)
      call check(ctx, allocated(error), "symplectic refused with damping")
      if (allocated(error)) call check(ctx, error%code == err_invalid_parameter, "invalid parameter")
   end subroutine damped_runs_on_dop853

   !> A batch in 4 lanes — regular, chaotic (stops early), near the pivot, damped, and one
   !> whose step the rule sets beyond max_steps_per_period (DOP853) — gives each orbit
   !> exactly what it gives alone.
   subroutine batch_equals_single_orbits(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp), parameter :: points(3, 6) = reshape([2.57_wp, 1.29_wp, 0.0_wp, 7.48_wp, 2.47_wp, 0.0_wp, &
         9.5_wp, 6.0_wp, 0.0_wp, 2.57_wp, 1.29_wp, 0.3_wp, 9.85_wp, 1.0_wp, 0.0_wp, 1.48_wp, 2.47_wp, 0.0_wp], [3, 6])
      type(pendulum_t) :: pendula(6)
      real(wp) :: y0(4, 6)
      type(chaos_t) :: results(6), alone
      type(chaos_options_t) :: options
      type(error_t), allocatable :: error
      integer :: k
      options%lanes = 4
      do k = 1, 6
         pendula(k) = pendulum_at(points(1, k), points(2, k), points(3, k))
         y0(:, k) = pendulum_initial_state(pendula(k), 0.017_wp)
      end do
      call chaos_indicators_batch(pendula, y0, 150, 1.0e-10_wp, options, results)
      do k = 1, 6
         call chaos_indicators(pendula(k), y0(:, k), 150, 1.0e-10_wp, options, alone, error)
         call check(ctx, .not. allocated(error) .and. .not. allocated(results(k)%error), "integrated")
         call check(ctx, results(k)%lyapunov == alone%lyapunov .and. results(k)%megno == alone%megno .and. &
            results(k)%fli == alone%fli .and. results(k)%periods == alone%periods .and. &
            results(k)%chaotic == alone%chaotic .and. results(k)%energy_error == alone%energy_error .and. &
            results(k)%integrator == alone%integrator .and. &
            results(k)%stats%n_evaluations == alone%stats%n_evaluations, "batch = alone")
      end do
      call check(ctx, results(2)%stopped_early, "the chaotic orbit stopped early")
      call check(ctx, results(4)%integrator == chaos_dop853, "damped: dop853")
      call check(ctx, results(5)%integrator == chaos_dop853 .and. results(5)%attempts == 0, &
         "next to the pivot: dop853 at once")
      call check(ctx, results(1)%integrator == chaos_symplectic .and. results(3)%integrator == chaos_symplectic, &
         "the others symplectic")
   end subroutine batch_equals_single_orbits

   !> An energy tolerance no fixed step meets (1e-13): auto repeats the orbit with twice
   !> the steps up to max_steps_per_period (here 64) and then runs it on DOP853, the work
   !> of every attempt counted; integrator symplectic returns the values of its last
   !> attempt with err_accuracy; a fixed steps_per_period is taken as given.
   subroutine energy_error_falls_back(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(chaos_options_t) :: options
      type(chaos_t) :: r, dop853
      type(error_t), allocatable :: error
      type(pendulum_t) :: p
      integer :: steps, attempts, last
      options%energy_tolerance = 1.0e-13_wp
      options%max_steps_per_period = 64
      options%early_stop = .false.
      r = run(7.48_wp, 2.47_wp, 50, options)
      options%integrator = chaos_dop853
      dop853 = run(7.48_wp, 2.47_wp, 50, options)
      p = pendulum_at(7.48_wp, 2.47_wp)
      steps = chaos_steps_per_period(p, pendulum_initial_state(p, 0.017_wp), options)
      attempts = 0
      do while (steps <= options%max_steps_per_period)
         attempts = attempts + 1
         last = steps
         steps = 2*steps
      end do
      call check(ctx, attempts >= 2, "more than one attempt")
      call check(ctx, r%integrator == chaos_dop853 .and. r%attempts == attempts, "auto: doubled steps, then dop853")
      call check(ctx, r%lyapunov == dop853%lyapunov, "the dop853 result")
      call check(ctx, r%stats%n_evaluations > dop853%stats%n_evaluations, "the symplectic attempts counted")
      options%integrator = chaos_symplectic
      call chaos_indicators(p, pendulum_initial_state(p, 0.017_wp), 50, 1.0e-10_wp, options, r, error)
      call check(ctx, allocated(error), "symplectic: error")
      if (allocated(error)) call check(ctx, error%code == err_accuracy, "err_accuracy")
      call check(ctx, r%integrator == chaos_symplectic .and. r%steps_per_period == last .and. r%periods > 0, &
         "with the values of the last attempt")
      options = chaos_options_t()
      options%steps_per_period = 24
      r = run(2.57_wp, 1.29_wp, 20, options)
      call check(ctx, r%steps_per_period == 24 .and. r%stats%n_evaluations == 1 + 20*24*11, "fixed steps per period")
   end subroutine energy_error_falls_back

   !> The rule of `chaos_verdict`: the end thresholds and the early stop (above
   !> megno_stop + allowance and still growing, not before min_periods).
   subroutine verdict_rule(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(chaos_options_t) :: o
      real(wp) :: v
      logical :: certain
      call chaos_verdict(o, 300, 300, 2.1_wp, 1.9_wp, 4.0_wp, v, certain)
      call check(ctx, v == 0.0_wp .and. certain, "regular at the end")
      call chaos_verdict(o, 300, 300, 3.2_wp, 3.0_wp, 4.0_wp, v, certain)
      call check(ctx, v == 0.5_wp .and. certain, "undecided at the end")
      call chaos_verdict(o, 300, 300, 4.0_wp, 3.9_wp, 4.0_wp, v, certain)
      call check(ctx, v == 1.0_wp .and. certain, "chaotic at the end")
      call chaos_verdict(o, 100, 300, 20.0_wp, 10.0_wp, 4.0_wp, v, certain)
      call check(ctx, v == 1.0_wp .and. certain, "certain: above, growing")
      call chaos_verdict(o, 100, 300, 20.0_wp, 15.0_wp, 4.0_wp, v, certain)
      call check(ctx, v == 1.0_wp .and. .not. certain, "not certain: not growing")
      call chaos_verdict(o, 100, 300, 20.0_wp, 10.0_wp, 17.0_wp, v, certain)
      call check(ctx, .not. certain, "not certain: below megno_stop + allowance")
      call chaos_verdict(o, 5, 300, 20.0_wp, 10.0_wp, 4.0_wp, v, certain)
      call check(ctx, .not. certain, "not certain before min_periods")
      call check(ctx, index(chaos_verdict_rule(o), "3.50") > 0 .and. index(chaos_verdict_rule(o), "3.00") > 0, &
         "the rule in words names the thresholds")
   end subroutine verdict_rule

   subroutine bad_arguments(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(chaos_options_t) :: o
      type(chaos_t) :: r, results(2)
      type(error_t), allocatable :: error
      type(pendulum_t) :: p
      real(wp) :: y0(4)
      p = pendulum_at(2.57_wp, 1.29_wp)
      y0 = pendulum_initial_state(p, 0.017_wp)
      call chaos_indicators(p, y0, 0, 1.0e-10_wp, o, r, error)
      call check(ctx, allocated(error), "periods = 0")
      call chaos_indicators(p, y0, 5, 0.0_wp, o, r, error)
      call check(ctx, allocated(error), "tolerance = 0")
      call chaos_indicators(p, [0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp], 5, 1.0e-10_wp, o, r, error)
      call check(ctx, allocated(error), "start at the pivot")
      o%integrator = 7
      call chaos_indicators(p, y0, 5, 1.0e-10_wp, o, r, error)
      call check(ctx, allocated(error), "unknown integrator")
      o = chaos_options_t(scheme=symplectic_scheme_count + 1)
      call chaos_indicators(p, y0, 5, 1.0e-10_wp, o, r, error)
      call check(ctx, allocated(error), "unknown scheme")
      o = chaos_options_t(megno_regular=5.0_wp, megno_chaotic=4.0_wp)
      call chaos_indicators(p, y0, 5, 1.0e-10_wp, o, r, error)
      call check(ctx, allocated(error), "thresholds inverted")
      if (allocated(error)) call check(ctx, error%code == err_invalid_parameter, "invalid parameter")
      call check(ctx, allocated(r%error), "the result carries the error too")
      o = chaos_options_t(lanes=0)
      call chaos_indicators_batch([p, p], reshape([y0, y0], [4, 2]), 5, 1.0e-10_wp, o, results)
      call check(ctx, allocated(results(1)%error) .and. allocated(results(2)%error), "batch: no lanes")
      call chaos_indicators_batch([p, p], reshape([y0, y0], [4, 2]), 5, 1.0e-10_wp, chaos_options_t(), results(1:1))
      call check(ctx, allocated(results(1)%error), "batch: results of the wrong size")
      call check(ctx, chaos_integrator_name(chaos_auto) == "auto" .and. chaos_integrator_name(chaos_dop853) == &
         "dop853" .and. chaos_integrator_name(chaos_symplectic) == "symplectic", "integrator names")
      call check(ctx, chaos_integrator_id("symplectic") == chaos_symplectic .and. chaos_integrator_id("auto") == &
         chaos_auto .and. chaos_integrator_id("rk4") == -1, "integrator ids")
      call check(ctx, index(chaos_method_text(chaos_options_t(), 1.0e-10_wp), "blanes_moan6") > 0 .and. &
         index(chaos_method_text(chaos_options_t(), 1.0e-10_wp), "DOP853") > 0, "method text")
   end subroutine bad_arguments
end module test_chaos

!> Tests of equations in physical time (hillstab_hill_model_equation): the built-in Mathieu
!> and elastic coefficients written as equations give the built-in models' S and verdicts
!> (damped and not, every exact method); the physical Kapitza pendulum and an equation with
!> a mass, damping and a sine term against an extended-precision monodromy of the physical
!> equation as written (data/reference/physical_set.dat, mpmath); a chart row equal to the
!> points task at the same parameters, its columns named after the axes and its header a
!> scene that repeats the run; the first-order form y' = A(t) y: the column written with six
!> states against the same reference and its second-order form, and a system of three states
!> (odd, which no second-order form writes) against the closed form at a constant A and
!> between two methods; bad input refused naming file, group and variable.
module test_model_equation
   use hillstab_core_kinds, only: wp, pi
   use hillstab_core_text, only: real_text, integer_text
   use hillstab_core_error, only: error_t, set_error, err_input, err_accuracy
   use hillstab_hill_model, only: hill_point_t
   use hillstab_hill_model_equation, only: equation_model_t
   use hillstab_hill_model_mathieu, only: mathieu_model_t
   use hillstab_hill_model_elastic, only: elastic_model_t
   use hillstab_hill_transfer, only: trace_t
   use hillstab_hill_floquet, only: floquet_t, floquet_from_trace
   use hillstab_integrate_monodromy, only: method_t, monodromy_trace, method_auto, method_magnus6, method_rk, &
      method_gsl, method_name
   use hillstab_hill_system, only: system_form_t, prepare_system
   use hillstab_hill_system_equation, only: equations_system_t
   use hillstab_integrate_system, only: system_method_t, system_monodromy_t, system_nodes_t, system_auto, &
      system_magnus4, system_magnus6, system_rk, system_gsl, system_method_name
   use hillstab_integrate_system_point, only: system_point
   use hillstab_batch_scene_types, only: scene_t
   use hillstab_batch_run_read, only: read_scene
   use hillstab_testing
   use hillstab_ffi_lapack, only: dgeev
   use hillstab_test_files, only: run_text_scene, check_rerun
   use hillstab_test_reference, only: auto_row_errors
   use hillstab_test_scratch, only: scratch_prefix, read_lines, file_exists, delete_file, write_file, padded
   implicit none
   private
   public :: collect_model_equation

   !> The exact methods every comparison runs.
   integer, parameter :: exact_methods(4) = [method_auto, method_magnus6, method_rk, method_gsl]

contains

   function collect_model_equation() result(suite)
      type(testsuite_t) :: suite
      suite = new_testsuite("model_equation", [ &
         new_unittest("mathieu_written_as_equation", mathieu_written_as_equation), &
         new_unittest("elastic_written_as_equation", elastic_written_as_equation), &
         new_unittest("physical_against_reference", physical_against_reference), &
         new_unittest("auto_chart_grid", auto_chart_grid), &
         new_unittest("column_against_reference", column_against_reference), &
         new_unittest("chart_row_equals_points", chart_row_equals_points), &
         new_unittest("beta_anywhere_closed_forms", beta_anywhere_closed_forms), &
         new_unittest("beta_anywhere_axes_swapped", beta_anywhere_axes_swapped), &
         new_unittest("system_beta_anywhere", system_beta_anywhere), &
         new_unittest("rates_per_unit_time", rates_per_unit_time), &
         new_unittest("tasks_on_equations", tasks_on_equations), &
         new_unittest("first_order_column", first_order_column), &
         new_unittest("first_order_three_states", first_order_three_states), &
         new_unittest("bad_scene_input", bad_scene_input)])
   end function collect_model_equation

   !> An equation from its texts; the test fails when it is refused.
   subroutine equation_of(ctx, texts, model)
      type(test_context_t), intent(inout) :: ctx
      character(len=*), intent(in) :: texts(:, :)  !! (2, n): variable, text
      type(equation_model_t), intent(out) :: model
      type(error_t), allocatable :: error
      integer :: k
      do k = 1, size(texts, 2)
         call model%set_text(trim(texts(1, k)), trim(texts(2, k)), error)
         call check(ctx, .not. allocated(error), "set "//trim(texts(1, k)))
      end do
      call model%check_values(error)
      if (allocated(error)) call check(ctx, .false., "the equation is refused: "//error%message)
   end subroutine equation_of

   !> A point of a fixed pseudo-random sequence in [lo, hi] (the golden-ratio sequence).
   pure real(wp) function spread(k, shift, lo, hi)
      integer, intent(in) :: k
      real(wp), intent(in) :: shift, lo, hi
      spread = lo + (hi - lo)*modulo(shift + 0.6180339887498949_wp*k, 1.0_wp)
   end function spread

   !> S of `model` and of the built-in at the same point by one method: both within the
   !> tolerance of the truth, so within twice of each other; the verdicts alike where |S|
   !> is clear of the threshold.
   subroutine compare_point(ctx, label, equation, builtin, alpha, beta, builtin_alpha, builtin_beta, epsilon, &
                            method, worst)
      type(test_context_t), intent(inout) :: ctx
      character(len=*), intent(in) :: label
      type(equation_model_t), intent(in) :: equation
      class(*), intent(in) :: builtin
      real(wp), intent(in) :: alpha, beta, builtin_alpha, builtin_beta, epsilon
      integer, intent(in) :: method
      real(wp), intent(inout) :: worst
      real(wp), parameter :: tolerance = 1.0e-10_wp
      type(trace_t) :: t_eq, t_in
      type(error_t), allocatable :: e_eq, e_in
      type(floquet_t) :: f_eq, f_in
      real(wp) :: eps_eq, d
      eps_eq = equation%point_damping(alpha, 0.0_wp)
      call check_close(ctx, eps_eq, epsilon, rel=1.0e-14_wp, message=label//": the equation's epsilon")
      call monodromy_trace(equation, hill_point_t(alpha, beta, eps_eq), method_t(method, tolerance=tolerance), t_eq, e_eq)
      select type (builtin)
      type is (mathieu_model_t)
         call monodromy_trace(builtin, hill_point_t(builtin_alpha, builtin_beta, epsilon), &
                              method_t(method, tolerance=tolerance), t_in, e_in)
      type is (elastic_model_t)
         call monodromy_trace(builtin, hill_point_t(builtin_alpha, builtin_beta, epsilon), &
                              method_t(method, tolerance=tolerance), t_in, e_in)
      end select
      if (allocated(e_eq)) then
         call check(ctx, e_eq%code == err_accuracy, label//": the equation computes: "//e_eq%message)
         return
      end if
      if (allocated(e_in)) return
      d = abs(t_eq%value - t_in%value)/max(1.0_wp, abs(t_in%value))
      worst = max(worst, d/tolerance)
      call check(ctx, d <= 2.0_wp*tolerance, label//": |S - S_builtin|/max(1, |S|) = "//real_text(d)//" <= 2 tol")
      f_eq = floquet_from_trace(t_eq, eps_eq, tolerance)
      f_in = floquet_from_trace(t_in, epsilon, tolerance)
      if (.not. (f_eq%marginal .or. f_in%marginal)) call check(ctx, f_eq%stable .eqv. f_in%stable, label//": verdict")
   end subroutine compare_point

   !> Mathieu's equation as an engineer writes it, x'' + c x' + (d − 2q cos 2t) x = 0
   !> (Ω = 2, so τ = 2t/π), against the built-in mathieu model q = β − α cos πτ at
   !> α = 2π²q/4·... : β = π² d/4, α = π² q/2, ε = πc/2, at 60 points (half damped), every
   !> exact method.
   subroutine mathieu_written_as_equation(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(equation_model_t) :: equation
      type(mathieu_model_t) :: mathieu
      character(len=80) :: texts(2, 6)
      real(wp) :: q, d, c, worst(size(exact_methods))
      integer :: k, m, half
      texts(:, 2) = [character(len=80) :: "stiffness", "d - 2*q*cos(2*t)"]
      texts(:, 3) = [character(len=80) :: "damping", "c"]
      texts(:, 4) = [character(len=80) :: "frequency", "2"]
      texts(:, 5) = [character(len=80) :: "alpha", "q"]
      texts(:, 6) = [character(len=80) :: "beta", "d"]
      worst = 0.0_wp
      do half = 0, 1
         texts(:, 1) = [character(len=80) :: "parameters", trim(merge("q = 1, d = 1, c = 0   ", &
                                                                      "q = 1, d = 1, c = 0.2 ", half == 0))]
         call equation_of(ctx, texts, equation)
         do k = 1, 30
            q = spread(k, 0.1_wp, 0.0_wp, 8.0_wp)
            d = spread(k, 0.37_wp, -2.0_wp, 16.0_wp)
            c = 0.2_wp*half
            do m = 1, size(exact_methods)
               call compare_point(ctx, "mathieu "//method_name(exact_methods(m)), equation, mathieu, q, d, &
                                  pi*pi*q/2.0_wp, pi*pi*d/4.0_wp, pi*c/2.0_wp, exact_methods(m), worst(m))
            end do
         end do
      end do
      do m = 1, size(exact_methods)
         print '(4x,a8,a,es9.2)', method_name(exact_methods(m)), ": worst |S - S_mathieu|/tolerance", worst(m)
      end do
   end subroutine mathieu_written_as_equation

   !> The elastic pendulum's coefficient (β − α cos πt)/(1 − (α/π²) cos πt) as an equation
   !> with Ω = π (τ = t) against the built-in elastic model, 50 points with α up to 9
   !> (the dip 1 − α/π² down to 0.09), half of them with damping c = ε = 0.15.
   subroutine elastic_written_as_equation(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(equation_model_t) :: equation
      type(elastic_model_t) :: elastic
      character(len=80) :: texts(2, 6)
      real(wp) :: a, b, worst(size(exact_methods))
      integer :: k, m, half
      texts(:, 2) = [character(len=80) :: "stiffness", "(b - a*cos(pi*t))/(1 - a/pi^2*cos(pi*t))"]
      texts(:, 3) = [character(len=80) :: "damping", "c"]
      texts(:, 4) = [character(len=80) :: "frequency", "pi"]
      texts(:, 5) = [character(len=80) :: "alpha", "a"]
      texts(:, 6) = [character(len=80) :: "beta", "b"]
      worst = 0.0_wp
      do half = 0, 1
         texts(:, 1) = [character(len=80) :: "parameters", trim(merge("a = 1, b = 1, c = 0   ", &
                                                                      "a = 1, b = 1, c = 0.15", half == 0))]
         call equation_of(ctx, texts, equation)
         do k = 1, 25
            a = spread(k, 0.21_wp, 0.0_wp, 9.0_wp)
            b = spread(k, 0.53_wp, -2.0_wp, 12.0_wp)
            do m = 1, size(exact_methods)
               call compare_point(ctx, "elastic "//method_name(exact_methods(m)), equation, elastic, a, b, a, b, &
                                  0.15_wp*half, exact_methods(m), worst(m))
            end do
         end do
      end do
      do m = 1, size(exact_methods)
         print '(4x,a8,a,es9.2)', method_name(exact_methods(m)), ": worst |S - S_elastic|/tolerance", worst(m)
      end do
   end subroutine elastic_written_as_equation

   !> Sets 1 and 2 of data/reference/physical_set.dat: the damped and undamped Kapitza
   !> pendulum θ'' + κθ' + (−g/l + (Aω²/l) cos ωt) θ = 0 over (ω, A), and
   !> 2.5 x'' + 0.3 x' + (40 + k1 cos Wt + 5 sin 2Wt) x = 0 over (W, k1): the trace and the
   !> multipliers of the physical monodromy over one period 2π/ω, by mpmath at 40 digits.
   !> S of χ is e^{κT/2} times the physical trace; the largest |multiplier| is the file's.
   !> Every exact method at 1e-10, status 0, within the tolerance.
   subroutine physical_against_reference(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=*), parameter :: path = "data/reference/physical_set.dat"
      real(wp), parameter :: tolerance = 1.0e-10_wp
      character(len=1024), allocatable :: lines(:)
      type(equation_model_t) :: kapitza(2), second
      character(len=80) :: texts(2, 6)
      type(trace_t) :: tr
      type(error_t), allocatable :: error
      type(floquet_t) :: f
      real(wp) :: row(16), s_ref, lam_ref, eps, period, d, worst(size(exact_methods))
      integer :: k, m, ios, set, n_points(2), n_stable
      texts(:, 2) = [character(len=80) :: "stiffness", "-g/l + A*w^2/l*cos(w*t)"]
      texts(:, 3) = [character(len=80) :: "damping", "kappa"]
      texts(:, 4) = [character(len=80) :: "frequency", "w"]
      texts(:, 5) = [character(len=80) :: "alpha", "w"]
      texts(:, 6) = [character(len=80) :: "beta", "A"]
      texts(:, 1) = [character(len=80) :: "parameters", "g = 9.81, l = 0.2, kappa = 0, A = 0, w = 100"]
      call equation_of(ctx, texts, kapitza(1))
      texts(:, 1) = [character(len=80) :: "parameters", "g = 9.81, l = 0.2, kappa = 0.2, A = 0, w = 100"]
      call equation_of(ctx, texts, kapitza(2))
      call equation_of(ctx, reshape([character(len=80) :: &
         "parameters", "m = 2.5, c = 0.3, k0 = 40, k1 = 0, k2 = 5, W = 10", &
         "stiffness", "k0 + k1*cos(W*t) + k2*sin(2*W*t)", "mass", "m", "damping", "c", "frequency", "W", &
         "alpha", "W", "beta", "k1"], [2, 7]), second)
      lines = read_lines(path)
      n_points = 0
      n_stable = 0
      worst = 0.0_wp
      do k = 1, size(lines)
         if (len_trim(lines(k)) == 0 .or. lines(k)(1:1) == "#") cycle
         read (lines(k), *, iostat=ios) set
         if (set == 3 .or. ios /= 0) cycle
         row = 0.0_wp
         if (set == 1) then
            ! set kappa w A trace re1 im1 re2 im2 ref_error
            read (lines(k), *, iostat=ios) row(1:10)
            period = 2.0_wp*pi/row(3)
            s_ref = exp(row(2)*period/2.0_wp)*row(5)
            lam_ref = max(hypot(row(6), row(7)), hypot(row(8), row(9)))
         else
            ! set W k1 trace re1 im1 re2 im2 ref_error
            read (lines(k), *, iostat=ios) row(1:9)
            period = 2.0_wp*pi/row(2)
            ! c/m = 0.12: S of chi = e^{(c/m) T/2} trace
            s_ref = exp(0.12_wp*period/2.0_wp)*row(4)
            lam_ref = max(hypot(row(5), row(6)), hypot(row(7), row(8)))
         end if
         call check(ctx, ios == 0, "reads line "//trim(lines(k)))
         if (ios /= 0) cycle
         n_points(set) = n_points(set) + 1
         do m = 1, size(exact_methods)
            if (set == 1) then
               associate (model => kapitza(merge(1, 2, row(2) == 0.0_wp)))
                  eps = model%point_damping(row(3), 0.0_wp)
                  call monodromy_trace(model, hill_point_t(row(3), row(4), eps), &
                                       method_t(exact_methods(m), tolerance=tolerance), tr, error)
               end associate
            else
               eps = second%point_damping(row(2), 0.0_wp)
               call monodromy_trace(second, hill_point_t(row(2), row(3), eps), &
                                    method_t(exact_methods(m), tolerance=tolerance), tr, error)
            end if
            call check(ctx, .not. allocated(error), "set "//real_text(real(set, wp))//" "// &
                       method_name(exact_methods(m))//": status 0 at "//trim(lines(k)(1:60)))
            if (allocated(error)) cycle
            d = abs(tr%value - s_ref)/max(1.0_wp, abs(s_ref))
            worst(m) = max(worst(m), d/tolerance)
            call check(ctx, d <= tolerance, method_name(exact_methods(m))//": S within the tolerance ("//real_text(d)// &
                       ") at "//trim(lines(k)(1:60)))
            f = floquet_from_trace(tr, eps, tolerance)
            ! the largest |multiplier| of x: relative error tol max(1, |S|)/sqrt|S^2 - 4| (the header's bound)
            d = abs(exp(f%log_modulus(1)) - lam_ref)/lam_ref
            call check(ctx, d <= 10.0_wp*tolerance*max(1.0_wp, abs(s_ref))/sqrt(max(abs(s_ref**2 - 4.0_wp), 1.0e-6_wp)) &
                       + 1.0e-12_wp, method_name(exact_methods(m))//": |lambda|_max within its bound ("//real_text(d)//")")
            if (m == 1 .and. f%stable) n_stable = n_stable + 1
         end do
      end do
      call check(ctx, n_points(1) >= 50 .and. n_points(2) >= 40, "reference points: "// &
                 real_text(real(n_points(1), wp))//" Kapitza, "//real_text(real(n_points(2), wp))//" second")
      call check(ctx, n_stable > 10 .and. n_stable < sum(n_points) - 10, "stable and unstable points both")
      do m = 1, size(exact_methods)
         print '(4x,a8,a,es9.2)', method_name(exact_methods(m)), ": worst |S - S_ref|/tolerance", worst(m)
      end do
   end subroutine physical_against_reference

   !> Method auto over chart rows as the chart task computes them (one row per ω, its
   !> damping κπ/ω, `monodromy_trace_batch`: shared meshes) against magnus6 at 1e-12: the
   !> damped Kapitza pendulum over the shipped scene's range (ω 60 … 700, A 0 … 0.1, 32 × 32)
   !> and the row ω = 167.023 through A = 0.022742, where a first mesh of 8 steps per unit τ
   !> made a Richardson pair whose difference was a twentieth of its error; every point within
   !> the tolerance at 1e-6 and 1e-10.
   subroutine auto_chart_grid(ctx)
      type(test_context_t), intent(inout) :: ctx
      integer, parameter :: n = 32
      real(wp), parameter :: tols(2) = [1.0e-6_wp, 1.0e-10_wp]
      type(equation_model_t) :: kapitza
      character(len=80) :: texts(2, 6)
      real(wp) :: amplitudes(n), worst, w
      integer :: i, j, t, n_checked
      texts(:, 1) = [character(len=80) :: "parameters", "g = 9.81, l = 0.2, kappa = 0.2, A = 0, w = 100"]
      texts(:, 2) = [character(len=80) :: "stiffness", "-g/l + A*w^2/l*cos(w*t)"]
      texts(:, 3) = [character(len=80) :: "damping", "kappa"]
      texts(:, 4) = [character(len=80) :: "frequency", "w"]
      texts(:, 5) = [character(len=80) :: "alpha", "w"]
      texts(:, 6) = [character(len=80) :: "beta", "A"]
      call equation_of(ctx, texts, kapitza)
      amplitudes = [(0.1_wp*(j - 1)/real(n - 1, wp), j=1, n)]
      do t = 1, size(tols)
         worst = 0.0_wp
         n_checked = 0
         do i = 1, n
            w = 60.0_wp + 640.0_wp*(i - 1)/real(n - 1, wp)
            call auto_row_errors(kapitza, w, amplitudes, tols(t), worst, n_checked, kapitza%point_damping(w, 0.0_wp))
         end do
         w = 1.6702341137123744e+002_wp
         call auto_row_errors(kapitza, w, [2.2742474916387961e-002_wp], tols(t), worst, n_checked, &
                              kapitza%point_damping(w, 0.0_wp))
         call check(ctx, worst <= 1.0_wp, "Kapitza at "//real_text(tols(t))//": worst error/tolerance "// &
                    real_text(worst))
         call check(ctx, n_checked >= n*n - 10, "points compared")
         print '(4x,a,es8.1,a,es9.2)', "Kapitza auto chart grid at", tols(t), ": worst error/tolerance", worst
      end do
   end subroutine auto_chart_grid

   !> Bolotin's damped column of 3 modes as its user writes it (set 3 of
   !> data/reference/physical_set.dat): M x'' + C x' + (W − (P0 + P1 cos Ωt) S) x = 0 over (Ω, P1),
   !> as the shipped scene data/scenes/column_equations.nml gives it.
   subroutine bolotin_column(column, error)
      type(equations_system_t), intent(out) :: column
      type(error_t), allocatable, intent(out) :: error
      type(scene_t) :: scene
      call read_scene("data/scenes/column_equations.nml", scene, error)
      if (allocated(error)) return
      select type (system => scene%system)
      type is (equations_system_t)
         column = system
      class default
         call set_error(error, err_input, "data/scenes/column_equations.nml: not an &equations system")
      end select
   end subroutine bolotin_column

   !> The rows of set 3 of data/reference/physical_set.dat, (17, points): set, Ω, P1, the trace,
   !> the six multipliers (re, im) and the reference's own error; a row that does not read
   !> fails a check.
   function column_reference(ctx) result(rows)
      type(test_context_t), intent(inout) :: ctx
      real(wp), allocatable :: rows(:, :)
      character(len=1024), allocatable :: lines(:)
      real(wp) :: row(17)
      integer :: k, ios, set
      lines = read_lines("data/reference/physical_set.dat")
      allocate (rows(17, 0))
      do k = 1, size(lines)
         if (len_trim(lines(k)) == 0 .or. lines(k)(1:1) == "#") cycle
         read (lines(k), *, iostat=ios) set
         if (ios /= 0 .or. set /= 3) cycle
         read (lines(k), *, iostat=ios) row
         call check(ctx, ios == 0, "reads "//trim(lines(k)(1:40)))
         if (ios /= 0) cycle
         rows = reshape([rows, row], [17, size(rows, 2) + 1])
      end do
   end function column_reference

   !> The worst of the six reference multipliers' distance to the nearest computed one (the
   !> two sets equal as multisets), relative to max(1, |λ|).
   pure real(wp) function multiplier_error(f, reference) result(worst)
      type(floquet_t), intent(in) :: f
      complex(wp), intent(in) :: reference(:)
      complex(wp) :: computed(size(f%multipliers))
      integer :: j
      computed = f%multipliers*exp(f%log_scale)
      worst = 0.0_wp
      do j = 1, size(reference)
         worst = max(worst, minval(abs(computed - reference(j)))/max(1.0_wp, abs(reference(j))))
      end do
   end function multiplier_error

   !> Set 3 of data/reference/physical_set.dat: a damped column of 3 modes written as its
   !> user writes it, M x'' + C x' + (W − (P0 + P1 cos Ωt) S) x = 0 with named matrices, over
   !> (Ω, P1) at 50 points near the simple and combination resonances: the trace and every
   !> multiplier (all six, as complex numbers, and the largest modulus) against the
   !> monodromy of the physical system by Taylor series in 45 digits, by every system method
   !> at 1e-10, status 0. The damping (π/Ω) C changes from row to row.
   subroutine column_against_reference(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp), parameter :: tolerance = 1.0e-10_wp
      integer, parameter :: methods(5) = [system_auto, system_magnus4, system_magnus6, system_rk, system_gsl]
      type(equations_system_t) :: column
      type(error_t), allocatable :: error
      type(system_form_t) :: form
      type(system_nodes_t) :: nodes
      type(system_monodromy_t) :: r
      type(floquet_t) :: f
      real(wp), allocatable :: rows(:, :)
      real(wp) :: row(17), scale, d_trace, d_lambda, worst_trace(size(methods)), worst_lambda(size(methods))
      complex(wp) :: reference(6)
      integer :: k, m, j, n_points, n_stable
      call bolotin_column(column, error)
      call check(ctx, .not. allocated(error), "the column is taken")
      if (allocated(error)) then
         call check(ctx, .false., error%message)
         return
      end if
      rows = column_reference(ctx)
      n_points = size(rows, 2)
      n_stable = 0
      worst_trace = 0.0_wp
      worst_lambda = 0.0_wp
      do k = 1, n_points
         row = rows(:, k)
         reference = [(cmplx(row(5 + 2*j), row(6 + 2*j), wp), j=0, 5)]
         call prepare_system(column, 0.0_wp, form, error, alpha=row(2))
         call check(ctx, .not. allocated(error), "prepared at Om = "//real_text(row(2)))
         if (allocated(error)) cycle
         do m = 1, size(methods)
            nodes = system_nodes_t()
            call system_point(column, form, row(2), row(3), system_method_t(methods(m), tolerance), nodes, r, f, error)
            call check(ctx, .not. allocated(error) .and. r%status == 0, system_method_name(methods(m))// &
                       ": status 0 at Om = "//real_text(row(2))//", P1 = "//real_text(row(3)))
            if (allocated(error) .or. r%status /= 0) cycle
            ! Φ's error is the tolerance relative to its largest entry; the trace sums 6 of them
            scale = max(1.0_wp, maxval(abs(r%phi))*exp(r%log_scale))
            d_trace = abs(f%a1 - row(4))/scale
            worst_trace(m) = max(worst_trace(m), d_trace/tolerance)
            call check(ctx, d_trace <= 6.0_wp*tolerance, system_method_name(methods(m))//": trace within 6 tol ("// &
                       real_text(d_trace)//") at Om = "//real_text(row(2))//", P1 = "//real_text(row(3)))
            ! every multiplier: the nearest computed one (the sets equal as multisets), within the
            ! tolerance relative to max(1, |lambda|)
            d_lambda = multiplier_error(f, reference)
            worst_lambda(m) = max(worst_lambda(m), d_lambda)
            call check(ctx, d_lambda <= tolerance, system_method_name(methods(m))//": every multiplier ("// &
                       real_text(d_lambda)//") at Om = "//real_text(row(2))//", P1 = "//real_text(row(3)))
            call check(ctx, abs(exp(f%log_modulus(1)) - abs(reference(1)))/abs(reference(1)) <= 1.0e-7_wp, &
                       system_method_name(methods(m))//": the largest modulus")
            if (m == 1 .and. f%verdict == 1) n_stable = n_stable + 1
         end do
      end do
      call check(ctx, n_points >= 50, "50 reference points, got "//real_text(real(n_points, wp)))
      do m = 1, size(methods)
         print '(4x,a8,a,es9.2,a,es9.2)', system_method_name(methods(m)), ": worst trace error/tolerance", &
            worst_trace(m), ", worst multiplier error", worst_lambda(m)
      end do
   end subroutine column_against_reference

   !> Bolotin's damped column written in first-order form, y = (x, x'), A = U + (P0 + P1
   !> cos Ωt) V with U = [[0, I], [−W, −C]] and V = [[0, 0], [S, 0]]: at the 50 points of the
   !> reference (set 3, mpmath) every multiplier within the tolerance by every system method
   !> (the Magnus ones on the full A), the trace and the verdict equal to the second-order
   !> form's (method auto), all six exponents reported, and Liouville's check met.
   subroutine first_order_column(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp), parameter :: tolerance = 1.0e-10_wp
      integer, parameter :: methods(5) = [system_auto, system_magnus4, system_magnus6, system_rk, system_gsl]
      type(equations_system_t) :: first, second
      type(error_t), allocatable :: error
      type(system_form_t) :: form, form2
      type(system_nodes_t) :: nodes
      type(system_monodromy_t) :: r, r2
      type(floquet_t) :: f, f2
      real(wp), allocatable :: rows(:, :)
      real(wp) :: row(17), scale, d_lambda, worst(size(methods))
      complex(wp) :: reference(6)
      integer :: k, m, j, n_points, n_verdicts
      call first%set_values("n", [6.0_wp], error)
      call first%set_text("matrices", "U = [0, 0, 0, 1, 0, 0; 0, 0, 0, 0, 1, 0; 0, 0, 0, 0, 0, 1; "// &
                          "-1, 0, 0, -2*zeta, 0, 0; 0, -16, 0, 0, -8*zeta, 0; 0, 0, -81, 0, 0, -18*zeta], "// &
                          "V = [0, 0, 0, 0, 0, 0; 0, 0, 0, 0, 0, 0; 0, 0, 0, 0, 0, 0; 1, 0.3, 0.1, 0, 0, 0; "// &
                          "0.3, 4, 0.4, 0, 0, 0; 0.1, 0.4, 9, 0, 0, 0]", error)
      call first%set_text("parameters", "P0 = 0.3, P1 = 0, Om = 2, zeta = 0.01", error)
      call first%set_text("state", "U + (P0 + P1*cos(Om*t))*V", error)
      call first%set_text("frequency", "Om", error)
      call first%set_text("alpha", "Om", error)
      call first%set_text("beta", "P1", error)
      call first%check_values(error)
      call check(ctx, .not. allocated(error), "the first-order column is taken")
      if (allocated(error)) then
         call check(ctx, .false., error%message)
         return
      end if
      call check(ctx, first%first_order() .and. first%dof() == 6, "first-order, six states")
      call bolotin_column(second, error)
      call check(ctx, .not. allocated(error), "the second-order column is taken")
      if (allocated(error)) return
      rows = column_reference(ctx)
      n_points = size(rows, 2)
      n_verdicts = 0
      worst = 0.0_wp
      do k = 1, n_points
         row = rows(:, k)
         reference = [(cmplx(row(5 + 2*j), row(6 + 2*j), wp), j=0, 5)]
         call prepare_system(first, 0.0_wp, form, error, alpha=row(2))
         call check(ctx, .not. allocated(error) .and. form%states == 6, "prepared, 6 states at Om = "// &
                    real_text(row(2)))
         if (allocated(error)) cycle
         call prepare_system(second, 0.0_wp, form2, error, alpha=row(2))
         if (allocated(error)) cycle
         nodes = system_nodes_t()
         call system_point(second, form2, row(2), row(3), system_method_t(system_auto, tolerance), nodes, r2, f2, error)
         if (allocated(error)) cycle
         do m = 1, size(methods)
            nodes = system_nodes_t()
            call system_point(first, form, row(2), row(3), system_method_t(methods(m), tolerance), nodes, r, f, error)
            call check(ctx, .not. allocated(error) .and. r%status == 0, system_method_name(methods(m))// &
                       ": status 0 at Om = "//real_text(row(2))//", P1 = "//real_text(row(3)))
            if (allocated(error) .or. r%status /= 0) cycle
            call check(ctx, size(f%multipliers) == 6 .and. size(f%exponents) == 6, "six multipliers and exponents")
            d_lambda = multiplier_error(f, reference)
            worst(m) = max(worst(m), d_lambda)
            call check(ctx, d_lambda <= tolerance, system_method_name(methods(m))//": every multiplier ("// &
                       real_text(d_lambda)//") at Om = "//real_text(row(2))//", P1 = "//real_text(row(3)))
            scale = max(1.0_wp, maxval(abs(r%phi))*exp(r%log_scale))
            call check(ctx, abs(f%a1 - f2%a1)/scale <= 12.0_wp*tolerance, system_method_name(methods(m))// &
                       ": the trace of the second-order form at Om = "//real_text(row(2)))
            call check(ctx, f%verdict == f2%verdict .and. f%kind == f2%kind, system_method_name(methods(m))// &
                       ": the verdict and kind of the second-order form at Om = "//real_text(row(2))// &
                       ", P1 = "//real_text(row(3)))
            if (f%verdict == f2%verdict) n_verdicts = n_verdicts + 1
            call check(ctx, f%defect <= 1.0e-9_wp, "Liouville's check ("//real_text(f%defect)//")")
         end do
      end do
      call check(ctx, n_points >= 50, "50 reference points, got "//real_text(real(n_points, wp)))
      do m = 1, size(methods)
         print '(4x,a8,a,es9.2)', system_method_name(methods(m)), ": first-order column, worst multiplier error", &
            worst(m)
      end do
   end subroutine first_order_column

   !> Three states (a damped plant x'' + 2ζx' + x = u under the gain u' = (−u − g(t) x)/T_a,
   !> g = g0 + g1 cos Ωt): at g1 = 0 the multipliers are e^{Tλ} with λ the eigenvalues of the
   !> constant A (LAPACK), T = 2π/Ω, by auto (Magnus 6) and rk; with the drive, auto, rk and
   !> gsl agree within the tolerance at 50 points of (Ω, g1), and the verdicts with them.
   subroutine first_order_three_states(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp), parameter :: tolerance = 1.0e-10_wp, zeta = 0.05_wp, ta = 0.2_wp, g0 = 0.5_wp
      type(equations_system_t) :: plant
      type(error_t), allocatable :: error
      type(system_form_t) :: form
      type(system_nodes_t) :: nodes
      type(system_monodromy_t) :: r, r2
      type(floquet_t) :: f, f2
      real(wp) :: a(3, 3), wr(3), wi(3), vl(1, 3), vr(1, 3), work(64), om, g1, d
      complex(wp) :: exact(3), computed(3)
      integer :: k, j, i, info, n_unstable
      call plant%set_values("n", [3.0_wp], error)
      call plant%set_text("parameters", "zeta = 0.05, Ta = 0.2, g0 = 0.5, g1 = 0, Om = 2", error)
      call plant%set_text("matrices", "P = [0, 1, 0; -1, -2*zeta, 1; 0, 0, -1/Ta], G = [0, 0, 0; 0, 0, 0; "// &
                          "-1/Ta, 0, 0]", error)
      call plant%set_text("state", "P + (g0 + g1*cos(Om*t))*G", error)
      call plant%set_text("frequency", "Om", error)
      call plant%set_text("alpha", "Om", error)
      call plant%set_text("beta", "g1", error)
      call plant%check_values(error)
      call check(ctx, .not. allocated(error), "three states are taken")
      if (allocated(error)) then
         call check(ctx, .false., error%message)
         return
      end if
      a = reshape([0.0_wp, -1.0_wp, -g0/ta, 1.0_wp, -2.0_wp*zeta, 0.0_wp, 0.0_wp, 1.0_wp, -1.0_wp/ta], [3, 3])
      call dgeev("N", "N", 3, a, 3, wr, wi, vl, 1, vr, 1, work, size(work), info)
      call check(ctx, info == 0, "dgeev")
      n_unstable = 0
      do k = 1, 50
         om = spread(k, 0.1_wp, 0.3_wp, 6.0_wp)
         call prepare_system(plant, 0.0_wp, form, error, alpha=om)
         call check(ctx, .not. allocated(error) .and. form%states == 3, "prepared, 3 states")
         if (allocated(error)) return
         ! the constant A: Φ = exp(T A)
         exact = exp(cmplx(wr, wi, wp)*(2.0_wp*pi/om))
         do i = 1, 2
            nodes = system_nodes_t()
            call system_point(plant, form, om, 0.0_wp, system_method_t(merge(system_auto, system_rk, i == 1), &
                              tolerance), nodes, r, f, error)
            call check(ctx, .not. allocated(error) .and. r%status == 0, "status 0 at g1 = 0, Om = "//real_text(om))
            if (allocated(error)) return
            computed = f%multipliers*exp(f%log_scale)
            d = 0.0_wp
            do j = 1, 3
               d = max(d, minval(abs(computed - exact(j))))
            end do
            call check(ctx, d <= tolerance, "the multipliers of exp(T A) at Om = "//real_text(om)//" ("// &
                       real_text(d)//")")
         end do
         ! with the drive: rk against gsl
         g1 = spread(k, 0.7_wp, 0.0_wp, 3.0_wp)
         nodes = system_nodes_t()
         call system_point(plant, form, om, g1, system_method_t(system_rk, tolerance), nodes, r, f, error)
         if (allocated(error)) return
         nodes = system_nodes_t()
         call system_point(plant, form, om, g1, system_method_t(system_gsl, tolerance), nodes, r2, f2, error)
         if (allocated(error)) return
         call check(ctx, r%status == 0 .and. r2%status == 0, "status 0 at Om = "//real_text(om)//", g1 = "// &
                    real_text(g1))
         d = maxval(abs(r%phi*exp(r%log_scale) - r2%phi*exp(r2%log_scale)))/ &
             max(1.0_wp, maxval(abs(r%phi))*exp(r%log_scale))
         call check(ctx, d <= 2.0_wp*tolerance, "rk and gsl agree ("//real_text(d)//") at Om = "//real_text(om)// &
                    ", g1 = "//real_text(g1))
         call check(ctx, f%verdict == f2%verdict, "the verdicts agree at Om = "//real_text(om))
         nodes = system_nodes_t()
         call system_point(plant, form, om, g1, system_method_t(system_auto, tolerance), nodes, r2, f2, error)
         if (allocated(error)) return
         d = maxval(abs(r%phi*exp(r%log_scale) - r2%phi*exp(r2%log_scale)))/ &
             max(1.0_wp, maxval(abs(r%phi))*exp(r%log_scale))
         call check(ctx, r2%status == 0 .and. d <= 2.0_wp*tolerance, "rk and auto agree ("//real_text(d)// &
                    ") at Om = "//real_text(om)//", g1 = "//real_text(g1))
         call check(ctx, f%verdict == f2%verdict, "the verdicts of auto at Om = "//real_text(om))
         call check(ctx, f%defect <= 1.0e-9_wp, "Liouville's check ("//real_text(f%defect)//")")
         if (f%verdict == 0) n_unstable = n_unstable + 1
      end do
      ! the sample crosses the regions: both verdicts occur
      call check(ctx, n_unstable > 0 .and. n_unstable < 50, "stable and unstable points, "// &
                 real_text(real(n_unstable, wp))//" unstable")
      ! refused, naming the variable, with nothing written
      call refused("chart", "auto", "stiffness = 'P', ", "&equations: stiffness, state:", "'P + (0.5 + g1*cos(Om*t))*G'")
      call refused("chart", "auto", "mass = '2', ", "&equations: mass, damping, gyroscopic:", "'P + (0.5 + g1*cos(Om*t))*G'")
      call refused("chart", "auto", "", "&equations: state: not of period", "'P + (0.5 + g1*cos(3*t))*G'")
      call refused("regions", "auto", "", "&scene: task:", "'P + (0.5 + g1*cos(Om*t))*G'")
   contains
      subroutine refused(task, method, extra, named, state)
         character(len=*), intent(in) :: task, method, extra, named, state
         character(len=400) :: lines(4)
         character(len=:), allocatable :: written, out
         type(error_t), allocatable :: error
         out = scratch_prefix("first_order_bad")
         lines(1) = "&scene task = '"//task//"', model = 'equations', method = '"//method//"', output = '"//out//"' /"
         lines(2) = "&equations n = 3, parameters = 'g1 = 0, Om = 2', matrices = 'P = [0, 1, 0; -1, -0.1, 1; 0, 0, "// &
                    "-5], G = [0, 0, 0; 0, 0, 0; -5, 0, 0]', "//extra//"state = "//state//","
         lines(3) = "  frequency = 'Om', alpha = 'Om', beta = 'g1' /"
         lines(4) = "&chart alpha_min = 1, alpha_max = 2, n_alpha = 2, beta_min = 0, beta_max = 1, n_beta = 2 /"
         call run_text_scene("first_order_bad", lines, error, written)
         call check(ctx, allocated(error), named//" refused")
         if (.not. allocated(error)) return
         call check(ctx, error%code == err_input .and. index(error%message, named) > 0, "named "//named//": "// &
                    error%message)
         call check(ctx, .not. file_exists(out//"_chart.dat") .and. .not. file_exists(out//"_regions.dat"), &
                    "nothing written")
      end subroutine refused
   end subroutine first_order_three_states

   !> The Kapitza chart's row at ω = 314.16 (6 values of A) and the points task at the same
   !> (ω, A): the same values to the tolerance (a row shares its meshes, a point is alone),
   !> the verdicts alike; both files name their axis columns w and A, and the chart's header
   !> repeats the run.
   subroutine chart_row_equals_points(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=200) :: common(3)
      character(len=200) :: chart_scene(5), points_scene(5)
      character(len=:), allocatable :: written, again, out, pairs
      character(len=1024), allocatable :: chart_lines(:), points_lines(:)
      type(error_t), allocatable :: error
      real(wp) :: c(11), p(11)
      integer :: k, j, n_compared
      logical :: ok
      common(1) = "&equation parameters = 'g = 9.81, l = 0.2, kappa = 0.2, A = 0.005, w = 314.16',"
      common(2) = "  stiffness = '-g/l + A*w^2/l*cos(w*t)', damping = 'kappa', frequency = 'w',"
      common(3) = "  alpha = 'w', beta = 'A' /"
      out = scratch_prefix("equation_chart")
      chart_scene(1) = "&scene task = 'chart', model = 'equation', tolerance = 1e-10, output = '"//out//"' /"
      chart_scene(2:4) = common
      chart_scene(5) = "&chart alpha_min = 314.16, alpha_max = 314.16, n_alpha = 1, beta_min = 0.0, "// &
                       "beta_max = 0.015, n_beta = 6 /"
      call run_text_scene("equation_chart", chart_scene, error, written)
      call check(ctx, .not. allocated(error), "the chart runs")
      if (allocated(error)) then
         call check(ctx, .false., error%message)
         return
      end if
      chart_lines = read_lines(written)
      call check(ctx, any(index(chart_lines, "# columns: w A S stable") == 1), "the chart's columns are named w, A")
      call check_rerun(ctx, written, chart_lines, again, ok)
      if (ok) call delete_file(again)
      pairs = scratch_prefix("equation_pairs")//".dat"
      call write_file(pairs, [(padded("314.16 "//trim(real_text(0.003_wp*j))), j=0, 5)])
      out = scratch_prefix("equation_points")
      points_scene(1) = "&scene task = 'points', model = 'equation', tolerance = 1e-10, output = '"//out//"' /"
      points_scene(2:4) = common
      points_scene(5) = "&points file = '"//pairs//"' /"
      call run_text_scene("equation_points", points_scene, error, written)
      call check(ctx, .not. allocated(error), "the points run")
      if (allocated(error)) then
         call check(ctx, .false., error%message)
         return
      end if
      points_lines = read_lines(written)
      call check(ctx, any(index(points_lines, "# columns: w A S stable") == 1), "the points' columns are named w, A")
      chart_lines = pack(chart_lines, chart_lines(:)(1:1) /= "#" .and. len_trim(chart_lines) > 0)
      points_lines = pack(points_lines, points_lines(:)(1:1) /= "#" .and. len_trim(points_lines) > 0)
      call check(ctx, size(chart_lines) == size(points_lines), "as many points as the row")
      n_compared = 0
      do k = 1, min(size(chart_lines), size(points_lines))
         read (chart_lines(k), *) c
         read (points_lines(k), *) p
         n_compared = n_compared + 1
         call check_close(ctx, p(1), c(1), rel=1.0e-15_wp, message="w of point "//real_text(real(k, wp)))
         call check_close(ctx, p(2), c(2), rel=1.0e-15_wp, message="A of point "//real_text(real(k, wp)))
         call check(ctx, abs(p(3) - c(3)) <= 2.0e-10_wp*max(1.0_wp, abs(c(3))), "S of point "// &
                    real_text(real(k, wp))//": "//real_text(p(3))//" and "//real_text(c(3)))
         call check(ctx, nint(p(4)) == nint(c(4)), "the verdict of point "//real_text(real(k, wp)))
      end do
      call check(ctx, n_compared == 6, "6 points compared")
      call delete_file(pairs)
   end subroutine chart_row_equals_points

   !> The data lines of a chart or points file as numbers (n_columns, points).
   function data_of(path, n_columns) result(values)
      character(len=*), intent(in) :: path
      integer, intent(in) :: n_columns
      real(wp), allocatable :: values(:, :)
      character(len=1024), allocatable :: lines(:)
      integer :: k
      lines = read_lines(path)
      lines = pack(lines, lines(:)(1:1) /= "#" .and. len_trim(lines) > 0)
      allocate (values(n_columns, size(lines)))
      do k = 1, size(lines)
         read (lines(k), *) values(:, k)
      end do
   end function data_of

   !> Run a scene: its data lines as numbers (n_columns, points), the file deleted; `ok`
   !> false (the test failed, naming why) when it did not run.
   subroutine run_data(ctx, what, scene, n_columns, v, ok)
      type(test_context_t), intent(inout) :: ctx
      character(len=*), intent(in) :: what
      character(len=*), intent(in) :: scene(:)
      integer, intent(in) :: n_columns
      real(wp), allocatable, intent(out) :: v(:, :)
      logical, intent(out) :: ok
      type(error_t), allocatable :: error
      character(len=:), allocatable :: written
      call run_text_scene("equation_data", scene, error, written)
      ok = .not. allocated(error)
      call check(ctx, ok, what//" runs")
      if (.not. ok) then
         call check(ctx, .false., error%message)
         return
      end if
      v = data_of(written, n_columns)
      call delete_file(written)
   end subroutine run_data

   !> The column mu_per_s of an equation: the Floquet exponent per unit of its time t at each
   !> point's Ω, against the closed form of constant stiffness (A = 0): x'' + c x' + k0 x = 0
   !> grows as e^{rt}, r = −c/2 + Re √(c²/4 − k0), whatever Ω (μ per unit τ = Ωt/π is r π/Ω,
   !> so that each point's Ω is what makes r). Over (w, A), whose rows share Ω, over (A, w),
   !> whose points each have their own, and in the points task; unstable (k0 < 0) and damped
   !> (k0 > 0). A file names mu_per_s only on request; a model without a time of its own
   !> (Mathieu) refuses it.
   subroutine rates_per_unit_time(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=300) :: scene(3)
      character(len=:), allocatable :: out, pairs, written
      character(len=1024), allocatable :: lines(:)
      type(error_t), allocatable :: error
      real(wp), allocatable :: v(:, :)
      real(wp), parameter :: c = 0.4_wp, k0s(2) = [-2.0_wp, 2.0_wp]
      real(wp) :: k0, r, w, a
      integer :: m, j, k, count
      logical :: ok, swapped
      out = scratch_prefix("equation_rates")
      do m = 1, size(k0s)
         k0 = k0s(m)
         r = -0.5_wp*c + merge(sqrt(max(0.25_wp*c*c - k0, 0.0_wp)), 0.0_wp, 0.25_wp*c*c - k0 > 0.0_wp)
         do j = 1, 3
            swapped = j == 2
            scene(1) = "&scene task = 'chart', model = 'equation', tolerance = 1e-11, columns = 'w A mu mu_per_s', "// &
                       "output = '"//out//"' /"
            scene(2) = "&equation parameters = 'k0 = "//real_text(k0)//", c = 0.4, A = 0, w = 3', stiffness = "// &
                       "'k0 + A*cos(w*t)', damping = 'c', frequency = 'w', alpha = '"//trim(merge("A", "w", swapped))// &
                       "', beta = '"//trim(merge("w", "A", swapped))//"' /"
            if (j == 1) then
               scene(3) = "&chart alpha_min = 1, alpha_max = 7, n_alpha = 4, beta_min = 0, beta_max = 0.5, n_beta = 3 /"
            else if (j == 2) then
               scene(3) = "&chart alpha_min = 0, alpha_max = 0.5, n_alpha = 3, beta_min = 1, beta_max = 7, n_beta = 4 /"
            else
               pairs = scratch_prefix("equation_rates_pairs")//".dat"
               call write_file(pairs, [padded("1.5 0"), padded("4 0"), padded("6.5 0.3")])
               scene(1) = "&scene task = 'points', model = 'equation', tolerance = 1e-11, columns = 'w A mu mu_per_s', "// &
                          "output = '"//out//"' /"
               scene(3) = "&points file = '"//pairs//"' /"
            end if
            call run_data(ctx, "k0 = "//real_text(k0)//", scene "//integer_text(j), scene, 4, v, ok)
            if (j == 3) call delete_file(pairs)
            if (.not. ok) return
            count = 0
            do k = 1, size(v, 2)
               ! the columns in the order &scene columns names them
               w = v(1, k)
               a = v(2, k)
               ! mu_per_s is mu at the point's own Omega/pi
               call check(ctx, abs(v(4, k) - v(3, k)*w/pi) <= 1.0e-10_wp*max(1.0_wp, abs(v(4, k))), &
                          "mu_per_s = mu w/pi at w = "//real_text(w)//", A = "//real_text(a))
               if (a /= 0.0_wp) cycle
               count = count + 1
               call check(ctx, abs(v(4, k) - r) <= 1.0e-9_wp, "k0 = "//real_text(k0)//", scene "// &
                          integer_text(j)//": mu_per_s at w = "//real_text(w)//": "//real_text(v(4, k))// &
                          " against "//real_text(r))
            end do
            call check(ctx, count >= 2, "the closed form at two frequencies at least")
         end do
      end do
      ! on request only: a file of every column does not hold it
      scene(1) = "&scene task = 'chart', model = 'equation', output = '"//out//"' /"
      scene(3) = "&chart alpha_min = 1, alpha_max = 7, n_alpha = 2, beta_min = 0, beta_max = 0.5, n_beta = 2 /"
      call run_text_scene("equation_rates", scene, error, written)
      call check(ctx, .not. allocated(error), "the chart of every column runs")
      if (.not. allocated(error)) then
         lines = read_lines(written)
         call check(ctx, .not. any(index(lines, "mu_per_s") > 0), "mu_per_s is written on request only")
         call delete_file(written)
      end if
      ! a model in tau alone has no time to give it
      scene(1) = "&scene task = 'chart', model = 'mathieu', columns = 'S mu_per_s', output = '"//out//"' /"
      scene(2) = " "
      scene(3) = "&chart alpha_min = 1, alpha_max = 2, n_alpha = 2, beta_min = 0, beta_max = 0.5, n_beta = 2 /"
      call run_text_scene("equation_rates", scene, error, written)
      call check(ctx, allocated(error), "mu_per_s of the Mathieu model is refused")
      if (allocated(error)) call check(ctx, error%code == err_input .and. index(error%message, "&scene: columns") > 0, &
                                       "named: "//error%message)
      call check(ctx, .not. file_exists(out//"_chart.dat"), "no file written")
   end subroutine rates_per_unit_time

   !> Run a scene and its twin with the axes swapped (`run_data`).
   subroutine run_pair(ctx, what, scene, swapped, n_columns, a, b, ok)
      type(test_context_t), intent(inout) :: ctx
      character(len=*), intent(in) :: what
      character(len=*), intent(in) :: scene(:), swapped(:)
      integer, intent(in) :: n_columns
      real(wp), allocatable, intent(out) :: a(:, :), b(:, :)
      logical, intent(out) :: ok
      call run_data(ctx, what//": the scene", scene, n_columns, a, ok)
      if (ok) call run_data(ctx, what//": the scene swapped", swapped, n_columns, b, ok)
   end subroutine run_pair

   !> The β axis entering the frequency, the damping and the stiffness other than affinely
   !> (each point then alone, the equation at its β), against closed forms of constant
   !> stiffness k0 (period T = 2π/Ω, roots λ = −c/2 ± √(c²/4 − k0), S₁ of the χ equation
   !> 2 cos(T√(k0 − c²/4)) or 2 cosh(T√(c²/4 − k0)), μ = Re λ_max T/2 a unit τ): the
   !> frequency along β by methods auto and rk, the damping along β from under- to
   !> over-damped, k = b² along β; and the points task at the chart's points.
   subroutine beta_anywhere_closed_forms(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=300) :: scene(3)
      character(len=:), allocatable :: written, out, pairs
      type(error_t), allocatable :: error
      real(wp), allocatable :: v(:, :), p(:, :)
      real(wp) :: k0, w, c, b, period, s, mu, r
      character(len=8), parameter :: methods(2) = [character(len=8) :: "auto", "rk"]
      integer :: k, m
      logical :: ok
      out = scratch_prefix("equation_beta")
      ! the frequency along beta
      do m = 1, size(methods)
         scene(1) = "&scene task = 'chart', model = 'equation', method = '"//trim(methods(m))//"', tolerance = 1e-11, "// &
                    "columns = 'k0 w S mu', output = '"//out//"' /"
         scene(2) = "&equation parameters = 'k0 = 2, w = 1', stiffness = 'k0', frequency = 'w', alpha = 'k0', "// &
                    "beta = 'w' /"
         scene(3) = "&chart alpha_min = 0.5, alpha_max = 3, n_alpha = 4, beta_min = 0.7, beta_max = 3.1, n_beta = 5 /"
         call run_data(ctx, trim(methods(m))//": the frequency along beta", scene, 4, v, ok)
         if (.not. ok) return
         call check(ctx, size(v, 2) == 20, "20 points")
         do k = 1, size(v, 2)
            k0 = v(1, k)
            w = v(2, k)
            period = 2.0_wp*pi/w
            s = 2.0_wp*cos(sqrt(k0)*period)
            call check(ctx, abs(v(3, k) - s) <= 1.0e-10_wp*max(1.0_wp, abs(s)), trim(methods(m))//": S at k0 = "// &
                       real_text(k0)//", w = "//real_text(w)//": "//real_text(v(3, k))//" against "//real_text(s))
         end do
      end do
      ! a frequency axis through 0: refused before anything is written, naming both axes
      scene(1) = "&scene task = 'chart', model = 'equation', columns = 'k0 w S mu', output = '"//out//"' /"
      scene(3) = "&chart alpha_min = 0.5, alpha_max = 3, n_alpha = 4, beta_min = -1, beta_max = 1, n_beta = 5 /"
      call run_text_scene("equation_beta", scene, error, written)
      call check(ctx, allocated(error), "a frequency through 0 is refused")
      if (allocated(error)) call check(ctx, error%code == err_input .and. index(error%message, "&chart: beta_min:") > 0 &
                                       .and. index(error%message, "the points (k0, w)") > 0 .and. &
                                       index(error%message, "beta = -1") > 0, "named: "//error%message)
      call check(ctx, .not. file_exists(out//"_chart.dat"), "no file written")
      ! the frequency along alpha through 0 (rows shared): refused naming alpha_min, in the
      ! equation's own terms (no pendulum amplitude in the message)
      scene(2) = "&equation parameters = 'k0 = 2, w = 1', stiffness = 'k0', frequency = 'w', alpha = 'w', "// &
                 "beta = 'k0' /"
      scene(3) = "&chart alpha_min = -1, alpha_max = 1, n_alpha = 4, beta_min = 0.7, beta_max = 3.1, n_beta = 5 /"
      call run_text_scene("equation_beta", scene, error, written)
      call check(ctx, allocated(error), "a frequency through 0 along alpha is refused")
      if (allocated(error)) call check(ctx, error%code == err_input .and. index(error%message, "&chart: alpha_min:") > 0 &
                                       .and. index(error%message, "got alpha = -1") > 0 .and. &
                                       index(error%message, "rho") == 0, "named, in the equation's terms: "//error%message)
      call check(ctx, .not. file_exists(out//"_chart.dat"), "no file written")
      scene(2) = "&equation parameters = 'k0 = 2, w = 1', stiffness = 'k0', frequency = 'w', alpha = 'k0', "// &
                 "beta = 'w' /"
      ! and a points file's pair there, naming its line
      pairs = scratch_prefix("equation_beta_pairs")//".dat"
      call write_file(pairs, [padded("1 2"), padded("0.5 -1")])
      scene(1) = "&scene task = 'points', model = 'equation', columns = 'k0 w S', output = '"//out//"' /"
      scene(3) = "&points file = '"//pairs//"' /"
      call run_text_scene("equation_beta", scene, error, written)
      call check(ctx, allocated(error), "a points file's pair at w = -1 is refused")
      if (allocated(error)) call check(ctx, error%code == err_input .and. index(error%message, "&points: file:") > 0 &
                                       .and. index(error%message, "line 2") > 0 .and. &
                                       index(error%message, "beta = -1") > 0, "named: "//error%message)
      call check(ctx, .not. file_exists(out//"_points.dat"), "no points file written")
      call delete_file(pairs)
      ! the damping along beta, under- and over-damped (c^2 = 4 k0 nowhere on the grid)
      scene(1) = "&scene task = 'chart', model = 'equation', tolerance = 1e-11, columns = 'k0 c S mu', output = '"// &
                 out//"' /"
      scene(2) = "&equation parameters = 'k0 = 2, c = 0.1, w = 1', stiffness = 'k0', damping = 'c', frequency = 'w', "// &
                 "alpha = 'k0', beta = 'c' /"
      scene(3) = "&chart alpha_min = 0.5, alpha_max = 3, n_alpha = 4, beta_min = 0, beta_max = 4.1, n_beta = 7 /"
      call run_data(ctx, "the damping along beta", scene, 4, v, ok)
      if (.not. ok) return
      call check(ctx, size(v, 2) == 28, "28 points")
      period = 2.0_wp*pi
      do k = 1, size(v, 2)
         k0 = v(1, k)
         c = v(2, k)
         r = 0.25_wp*c*c - k0
         if (r < 0.0_wp) then
            s = 2.0_wp*cos(period*sqrt(-r))
            mu = -0.5_wp*c*period/2.0_wp
         else
            s = 2.0_wp*cosh(period*sqrt(r))
            mu = (-0.5_wp*c + sqrt(r))*period/2.0_wp
         end if
         call check(ctx, abs(v(3, k) - s) <= 1.0e-10_wp*max(1.0_wp, abs(s)), "S1 at k0 = "//real_text(k0)// &
                    ", c = "//real_text(c)//": "//real_text(v(3, k))//" against "//real_text(s))
         call check(ctx, abs(v(4, k) - mu) <= 1.0e-9_wp*max(1.0_wp, abs(mu)), "mu at k0 = "//real_text(k0)// &
                    ", c = "//real_text(c)//": "//real_text(v(4, k))//" against "//real_text(mu))
      end do
      ! the points task at the chart's points: S to the tolerance
      pairs = scratch_prefix("equation_beta_pairs")//".dat"
      call write_file(pairs, [(padded(trim(real_text(v(1, k)))//" "//trim(real_text(v(2, k)))), k=1, size(v, 2))])
      p = v
      scene(3) = "&points file = '"//pairs//"' /"
      scene(1) = "&scene task = 'points', model = 'equation', tolerance = 1e-11, columns = 'k0 c S mu', output = '"// &
                 out//"' /"
      call run_data(ctx, "the points", scene, 4, v, ok)
      if (ok) then
         call check(ctx, size(v, 2) == size(p, 2), "as many points")
         if (size(v, 2) == size(p, 2)) then
            do k = 1, size(v, 2)
               ! the pairs file's text is the chart's to 12 digits: S alike to the tolerance
               call check(ctx, abs(v(3, k) - p(3, k)) <= 1.0e-10_wp*max(1.0_wp, abs(p(3, k))), "points S "// &
                          real_text(real(k, wp))//": "//real_text(v(3, k))//" and "//real_text(p(3, k)))
            end do
         end if
      end if
      call delete_file(pairs)
      ! k = b^2: not affine in the beta axis
      scene(1) = "&scene task = 'chart', model = 'equation', tolerance = 1e-11, columns = 'w b S', output = '"// &
                 out//"' /"
      scene(2) = "&equation parameters = 'w = 1, b = 1', stiffness = 'b^2', frequency = 'w', alpha = 'w', beta = 'b' /"
      scene(3) = "&chart alpha_min = 0.8, alpha_max = 2, n_alpha = 3, beta_min = -1.3, beta_max = 1.7, n_beta = 6 /"
      call run_data(ctx, "k = b^2", scene, 3, v, ok)
      if (.not. ok) return
      call check(ctx, size(v, 2) == 18, "18 points")
      do k = 1, size(v, 2)
         w = v(1, k)
         b = v(2, k)
         s = 2.0_wp*cos(2.0_wp*pi*abs(b)/w)
         call check(ctx, abs(v(3, k) - s) <= 1.0e-10_wp*max(1.0_wp, abs(s)), "S at w = "//real_text(w)//", b = "// &
                    real_text(b)//": "//real_text(v(3, k))//" against "//real_text(s))
      end do
   end subroutine beta_anywhere_closed_forms

   !> The damped Kapitza pendulum charted with its axes swapped (alpha = 'A', beta = 'w': the
   !> frequency and the damping κπ/ω along β, each point alone) against the chart over
   !> (w, A) (rows shared): S within twice the tolerance, μ, the verdicts and the kinds alike,
   !> at 48 points from stable to both kinds of instability; the same for the verdicts alone.
   subroutine beta_anywhere_axes_swapped(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=300) :: rows(3), swapped(3)
      character(len=:), allocatable :: out, what
      real(wp), allocatable :: a(:, :), b(:, :)
      logical :: ok
      character(len=*), parameter :: equation = "&equation parameters = 'g = 9.81, l = 0.2, kappa = 0.2, "// &
         "A = 0.005, w = 314.16', stiffness = '-g/l + A*w^2/l*cos(w*t)', damping = 'kappa', frequency = 'w', "
      integer :: k, j, n_kind(0:5), pass
      out = scratch_prefix("equation_swap")
      do pass = 1, 2
         what = trim(merge("all columns ", "verdicts    ", pass == 1))
         rows(1) = "&scene task = 'chart', model = 'equation', tolerance = 1e-10, columns = '"// &
                   trim(merge("w A S mu stable kind", "w A stable kind     ", pass == 1))//"', output = '"//out//"' /"
         rows(2) = equation//"alpha = 'w', beta = 'A' /"
         rows(3) = "&chart alpha_min = 60, alpha_max = 700, n_alpha = 6, beta_min = 0, beta_max = 0.1, n_beta = 8 /"
         swapped(1) = rows(1)
         swapped(2) = equation//"alpha = 'A', beta = 'w' /"
         swapped(3) = "&chart alpha_min = 0, alpha_max = 0.1, n_alpha = 8, beta_min = 60, beta_max = 700, n_beta = 6 /"
         call run_pair(ctx, what, rows, swapped, merge(6, 4, pass == 1), a, b, ok)
         if (.not. ok) return
         call check(ctx, size(a, 2) == 48 .and. size(b, 2) == 48, what//": 48 points each")
         if (size(a, 2) /= 48 .or. size(b, 2) /= 48) return
         n_kind = 0
         do k = 1, 48
            ! the point (w, A) of the first chart in the second: row A, column w
            j = 6*(modulo(k - 1, 8)) + (k - 1)/8 + 1
            call check(ctx, abs(a(1, k) - b(1, j)) <= 1.0e-13_wp*a(1, k) .and. abs(a(2, k) - b(2, j)) <= 1.0e-15_wp, &
                       what//": the same point "//real_text(real(k, wp)))
            if (pass == 1) then
               call check(ctx, abs(a(3, k) - b(3, j)) <= 2.0e-10_wp*max(1.0_wp, abs(a(3, k))), what//": S at w = "// &
                          real_text(a(1, k))//", A = "//real_text(a(2, k))//": "//real_text(a(3, k))//" and "// &
                          real_text(b(3, j)))
               call check(ctx, abs(a(4, k) - b(4, j)) <= 1.0e-9_wp*max(1.0_wp, abs(a(4, k))), what//": mu at point "// &
                          real_text(real(k, wp)))
            end if
            call check(ctx, nint(a(size(a, 1) - 1, k)) == nint(b(size(b, 1) - 1, j)) .and. &
                       nint(a(size(a, 1), k)) == nint(b(size(b, 1), j)), what//": verdict and kind at point "// &
                       real_text(real(k, wp)))
            n_kind(nint(a(size(a, 1), k))) = n_kind(nint(a(size(a, 1), k))) + 1
         end do
         call check(ctx, n_kind(1) > 0 .and. n_kind(2) > 0 .and. n_kind(4) > 0, what// &
                    ": the points reach +1, -1 and damped stability")
      end do
   end subroutine beta_anywhere_axes_swapped

   !> A system whose β axis enters its damping and frequency (each point the system at its β,
   !> prepared alone): two undamped-coupled modes K = diag(1.5, 4.2) with C = c I along β,
   !> tr Φ = Σ 2 e^{−cT/2} cos(T√(k_i − c²/4)) (cosh where over-damped) and μ = Re λ_max T/2,
   !> T = 2π/ω; Bolotin's damped column charted over (P1, Om) against the chart over (Om, P1)
   !> (rows shared): tr Φ, a₂ and μ within 1e-9, the verdicts and kinds alike; and its
   !> resonance regions found along α at frequencies along β: the tips of the chart over
   !> (Om, P1), within their error bounds.
   subroutine system_beta_anywhere(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=400) :: scene(4), swapped(4)
      character(len=:), allocatable :: out
      real(wp), allocatable :: v(:, :), a(:, :), b(:, :)
      real(wp) :: w, c, period, tr, mu, r, k(2), lambda
      integer :: i, j, m, n_found
      logical :: ok
      out = scratch_prefix("equations_beta")
      scene(1) = "&scene task = 'chart', model = 'equations', tolerance = 1e-10, columns = 'w c trace mu', "// &
                 "output = '"//out//"' /"
      scene(2) = "&equations n = 2, parameters = 'c = 0.1, w = 1', matrices = 'K = [1.5, 0; 0, 4.2]', "// &
                 "stiffness = 'K', damping = 'c', frequency = 'w', alpha = 'w', beta = 'c' /"
      scene(3) = "&chart alpha_min = 0.6, alpha_max = 2.4, n_alpha = 4, beta_min = 0, beta_max = 5, n_beta = 6 /"
      call run_data(ctx, "the system's damping along beta", scene(1:3), 4, v, ok)
      if (.not. ok) return
      call check(ctx, size(v, 2) == 24, "24 points")
      k = [1.5_wp, 4.2_wp]
      do j = 1, size(v, 2)
         w = v(1, j)
         c = v(2, j)
         period = 2.0_wp*pi/w
         tr = 0.0_wp
         mu = -huge(1.0_wp)
         do m = 1, 2
            r = 0.25_wp*c*c - k(m)
            if (r < 0.0_wp) then
               tr = tr + 2.0_wp*exp(-0.5_wp*c*period)*cos(period*sqrt(-r))
               lambda = -0.5_wp*c
            else
               tr = tr + 2.0_wp*exp(-0.5_wp*c*period)*cosh(period*sqrt(r))
               lambda = -0.5_wp*c + sqrt(r)
            end if
            mu = max(mu, lambda*period/2.0_wp)
         end do
         call check(ctx, abs(v(3, j) - tr) <= 1.0e-9_wp*max(1.0_wp, abs(tr)), "tr Phi at w = "//real_text(w)// &
                    ", c = "//real_text(c)//": "//real_text(v(3, j))//" against "//real_text(tr))
         call check(ctx, abs(v(4, j) - mu) <= 1.0e-8_wp*max(1.0_wp, abs(mu)), "mu at w = "//real_text(w)// &
                    ", c = "//real_text(c)//": "//real_text(v(4, j))//" against "//real_text(mu))
      end do
      ! Bolotin's column over (P1, Om) and over (Om, P1)
      scene(1) = "&scene task = 'chart', model = 'equations', tolerance = 1e-10, columns = 'Om P1 trace a2 mu "// &
                 "stable kind', output = '"//out//"' /"
      scene(2) = "&equations n = 3, parameters = 'P0 = 0.3, P1 = 0, Om = 2, zeta = 0.01', matrices = 'W = [1, 0, 0; "// &
                 "0, 16, 0; 0, 0, 81], S = [1, 0.3, 0.1; 0.3, 4, 0.4; 0.1, 0.4, 9], Z = [1, 0, 0; 0, 4, 0; 0, 0, 9]',"
      scene(3) = "  stiffness = 'W - (P0 + P1*cos(Om*t))*S', damping = '2*zeta*Z', frequency = 'Om', alpha = 'Om', "// &
                 "beta = 'P1' /"
      scene(4) = "&chart alpha_min = 0.5, alpha_max = 5, n_alpha = 7, beta_min = 0, beta_max = 1.5, n_beta = 5 /"
      swapped = scene
      swapped(3) = "  stiffness = 'W - (P0 + P1*cos(Om*t))*S', damping = '2*zeta*Z', frequency = 'Om', alpha = 'P1', "// &
                   "beta = 'Om' /"
      swapped(4) = "&chart alpha_min = 0, alpha_max = 1.5, n_alpha = 5, beta_min = 0.5, beta_max = 5, n_beta = 7 /"
      call run_pair(ctx, "the column over (Om, P1) and (P1, Om)", scene, swapped, 7, a, b, ok)
      if (.not. ok) return
      call check(ctx, size(a, 2) == 35 .and. size(b, 2) == 35, "35 points each")
      if (size(a, 2) /= 35 .or. size(b, 2) /= 35) return
      do i = 1, 35
         ! point i of the first (row Om) is in the second's row P1, column Om
         j = 7*modulo(i - 1, 5) + (i - 1)/5 + 1
         call check(ctx, abs(a(1, i) - b(1, j)) <= 1.0e-14_wp*a(1, i) .and. abs(a(2, i) - b(2, j)) <= 1.0e-15_wp, &
                    "the same point "//real_text(real(i, wp)))
         do m = 3, 5
            call check(ctx, abs(a(m, i) - b(m, j)) <= 1.0e-9_wp*max(1.0_wp, abs(a(m, i))), "column "// &
                       real_text(real(m, wp))//" at Om = "//real_text(a(1, i))//", P1 = "//real_text(a(2, i))//": "// &
                       real_text(a(m, i))//" and "//real_text(b(m, j)))
         end do
         call check(ctx, nint(a(6, i)) == nint(b(6, j)) .and. nint(a(7, i)) == nint(b(7, j)), &
                    "verdict and kind at point "//real_text(real(i, wp)))
      end do
      ! the regions: tips along the drive at each frequency, the frequency along beta
      scene(1) = "&scene task = 'regions', model = 'equations', tolerance = 1e-10, output = '"//out//"' /"
      scene(4) = "&chart alpha_min = 0.5, alpha_max = 5, n_alpha = 30, beta_min = 0, beta_max = 1.5, n_beta = 20 /"
      swapped(1) = scene(1)
      swapped(4) = "&chart alpha_min = 0, alpha_max = 1.5, n_alpha = 20, beta_min = 0.5, beta_max = 5, n_beta = 30 /"// &
                   " &regions order = 2, drive = 'alpha' /"
      scene(4) = trim(scene(4))//" &regions order = 2 /"
      call run_pair(ctx, "the regions over (Om, P1) and (P1, Om)", scene, swapped, 15, a, b, ok)
      if (.not. ok) return
      call check(ctx, size(a, 2) == size(b, 2) .and. size(a, 2) >= 3, "as many regions, "// &
                 real_text(real(size(a, 2), wp)))
      if (size(a, 2) /= size(b, 2)) return
      n_found = 0
      do i = 1, size(a, 2)
         call check(ctx, all(nint(a([1, 2, 3, 4, 14], i)) == nint(b([1, 2, 3, 4, 14], i))), "region "// &
                    real_text(real(i, wp))//": kind, order, modes and status alike")
         if (nint(a(14, i)) /= 0) cycle
         n_found = n_found + 1
         call check(ctx, abs(a(6, i) - b(6, i)) <= a(7, i) + b(7, i) + 1.0e-12_wp*a(6, i), "region "// &
                    real_text(real(i, wp))//": the tip's Om "//real_text(a(6, i))//" and "//real_text(b(6, i)))
         call check(ctx, abs(a(8, i) - b(8, i)) <= a(9, i) + b(9, i) + 1.0e-12_wp, "region "// &
                    real_text(real(i, wp))//": the tip's P1 "//real_text(a(8, i))//" and "//real_text(b(8, i)))
      end do
      call check(ctx, n_found >= 2, "tips found: "//real_text(real(n_found, wp)))
   end subroutine system_beta_anywhere

   !> The tasks an equation takes: `coefficient` (Q(τ) at the axes' values) for one equation
   !> and for a system, a system's chart naming its axis columns after its parameters (and
   !> `columns` taking those names or alpha/beta); `boundaries` refused for both, naming
   !> &scene task, with no file written.
   subroutine tasks_on_equations(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=300) :: one(3), system(4)
      character(len=:), allocatable :: written, out
      character(len=1024), allocatable :: lines(:)
      type(error_t), allocatable :: error
      one(2) = "&equation parameters = 'g = 9.81, l = 0.2, A = 0.005, w = 314.16', stiffness = "// &
               "'-g/l + A*w^2/l*cos(w*t)', frequency = 'w', alpha = 'w', beta = 'A' /"
      system(2) = "&equations n = 2, parameters = 'P1 = 0, Om = 2', matrices = 'W = [1, 0; 0, 4], "// &
                  "S = [1, 0.3; 0.3, 2]', stiffness = 'W - P1*cos(Om*t)*S', damping = '0.02*W',"
      system(3) = "  frequency = 'Om', alpha = 'Om', beta = 'P1' /"
      ! coefficient
      out = scratch_prefix("equation_task")
      one(1) = "&scene task = 'coefficient', model = 'equation', output = '"//out//"' /"
      one(3) = "&coefficient alphas = 314.16, beta = 0.01 /"
      call run_text_scene("equation_task", one, error, written)
      call check(ctx, .not. allocated(error), "one equation's coefficient runs")
      if (.not. allocated(error)) call delete_file(written)
      system(1) = "&scene task = 'coefficient', model = 'equations', output = '"//out//"' /"
      system(4) = "&coefficient alphas = 2.0 /"
      call run_text_scene("equation_task", system, error, written)
      call check(ctx, .not. allocated(error), "a system's coefficient runs")
      if (.not. allocated(error)) call delete_file(written)
      ! a system's chart: its axis columns named after the axes
      system(1) = "&scene task = 'chart', model = 'equations', columns = 'Om beta stable kind', output = '"// &
                  out//"' /"
      system(4) = "&chart alpha_min = 1.5, alpha_max = 2.5, n_alpha = 3, beta_min = 0, beta_max = 0.5, n_beta = 3 /"
      call run_text_scene("equation_task", system, error, written)
      call check(ctx, .not. allocated(error), "a system's chart runs")
      if (.not. allocated(error)) then
         lines = read_lines(written)
         call check(ctx, any(index(lines, "# columns: Om P1 stable kind") == 1), "the axis columns named Om, P1")
         call delete_file(written)
      end if
      ! boundaries refused
      one(1) = "&scene task = 'boundaries', model = 'equation', output = '"//out//"' /"
      one(3) = "&chart alpha_min = 300, alpha_max = 320, n_alpha = 2, beta_min = 0, beta_max = 0.01, n_beta = 20 /"
      call run_text_scene("equation_task", one, error, written)
      call check(ctx, allocated(error), "boundaries of an equation refused")
      if (allocated(error)) call check(ctx, error%code == err_input .and. index(error%message, "&scene: task:") > 0, &
                                       "named: "//error%message)
      call check(ctx, .not. file_exists(out//"_boundaries.dat"), "no file written")
      system(1) = "&scene task = 'boundaries', model = 'equations', output = '"//out//"' /"
      call run_text_scene("equation_task", system, error, written)
      call check(ctx, allocated(error), "boundaries of an equations system refused")
      if (allocated(error)) call check(ctx, error%code == err_input .and. index(error%message, "&scene: task:") > 0, &
                                       "named: "//error%message)
   end subroutine tasks_on_equations

   !> Bad equations: exit 2 naming the file, the group and the variable, with what is
   !> wrong (the column of a parse error, the known names, the parameters' values and t of
   !> a non-finite coefficient), and no file written.
   subroutine bad_scene_input(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=*), parameter :: base = "parameters = 'g = 9.81, l = 0.2, A = 0.005, w = 314.16', "// &
         "frequency = 'w', alpha = 'w', beta = 'A', "
      character(len=*), parameter :: k_ok = "stiffness = '-g/l + A*w^2/l*cos(w*t)'"
      call refused("&equation "//base//"stiffness = '-g/l + A*w^2/l*cos(w*t' /", "stiffness", "column 19")
      call refused("&equation "//base//"stiffness = '-g/l + B*cos(w*t)' /", "stiffness", "g, l, A, w")
      call refused("&equation "//base//"stiffness = '-g/l + A*w^2/l*sqrt(cos(w*t))' /", "stiffness", &
                   "not finite at t = ")
      call refused("&equation "//base//"stiffness = '-g/l + A*w^2/l*sqrt(cos(w*t))' /", "stiffness", &
                   "A = 5.00000000000e-003, w = 3.14160000000e+002): ")
      call refused("&equation "//base//"stiffness = '-g/l + A*w^2/l*cos(3*t)' /", "stiffness", "not of period")
      ! a term of the beta axis alone, 0 at its given value
      call refused("&equation parameters = 'g = 9.81, l = 0.2, A = 0, w = 314.16', frequency = 'w', alpha = 'w', "// &
                   "beta = 'A', stiffness = '-g/l + A*w^2/l*cos(w*t) + A*cos(3*t)' /", "stiffness", &
                   "with A = 1.00000000000e+000")
      call refused("&equation parameters = 'g = 9.81, l = 0.2, A = 0.005, w = 314.16', frequency = 'w', "// &
                   "alpha = 'omega', beta = 'A', "//k_ok//" /", "alpha", "g, l, A, w")
      call refused("&equation parameters = 'g = 9.81, l = 0.2, A = 0.005, w = 314.16, A = 1', frequency = 'w', "// &
                   "alpha = 'w', beta = 'A', "//k_ok//" /", "parameters", "twice")
      call refused("&equation parameters = 'g = 9.81, l = 0.2, A = 0.005, w = 314.16', frequency = 'w', "// &
                   "alpha = 'A', beta = 'A', "//k_ok//" /", "alpha, beta", "one parameter")
      call refused("&equation "//base//k_ok//", mass = '1 - l*5' /", "mass", "> 0")
      call refused("&equation "//base//k_ok//", damping = '-0.1' /", "damping", ">= 0")
      call refused("&equation "//base//"stiffness = '"//repeat("1 + ", 600)//"1' /", "stiffness", "2000")
      call refused("&equation "//base//k_ok//", period = '0.02' /", "frequency, period", "one of the two")
      call refused("&equation "//base//"stiffness = -g/l /", "stiffness", "quoted")
      call refused("&equation parameters = 'g = 9.81, l = 0.2, A = 0.005, f = 50, w = 2*pi*f', frequency = 'w', "// &
                   "alpha = 'f', beta = 'A', "//k_ok//" /", "alpha", "computed from the axis 'f'")
   contains
      subroutine refused(group, variable, what)
         character(len=*), intent(in) :: group, variable, what
         type(error_t), allocatable :: error
         character(len=:), allocatable :: written, out, scene
         character(len=3000) :: lines(3)
         out = scratch_prefix("equation_bad")
         scene = scratch_prefix("equation_bad_scene")//".nml"
         lines(1) = "&scene task = 'chart', model = 'equation', output = '"//out//"' /"
         lines(2) = "&chart alpha_min = 300, alpha_max = 320, n_alpha = 3, beta_min = 0, beta_max = 0.01, n_beta = 3 /"
         lines(3) = group
         call run_text_scene("equation_bad_scene", lines, error, written)
         call check(ctx, allocated(error), variable//" "//what//": refused")
         if (.not. allocated(error)) return
         call check(ctx, error%code == err_input, variable//" "//what//": an input error (exit 2)")
         call check(ctx, index(error%message, scene) > 0 .and. index(error%message, "&equation: "//variable//":") > 0 &
                    .and. index(error%message, what) > 0, "the message names file, group, variable and '"//what// &
                    "': "//error%message)
         call check(ctx, .not. file_exists(out//"_chart.dat"), variable//" "//what//": no file written")
      end subroutine refused
   end subroutine bad_scene_input
end module test_model_equation

!> Task `boundaries` for one spring (`&physical r0` without amplitudes): the critical bounce
!> amplitudes of the spring of `&physical`, every 0 <= a < ρ where a transition curve crosses
!> the spring's β, each checked by method auto, and in the header the unstable intervals of
!> a in metres.
module hillstab_batch_tasks_boundaries_spring
   use hillstab_core_kinds, only: wp, int64, pi2, version_string
   use hillstab_batch_output_progress, only: progress_t, progress_begin, progress_step, progress_end
   use hillstab_core_error, only: error_t, set_error, err_points_failed
   use hillstab_core_status, only: status_ok, status_roundoff, status_failed
   use hillstab_hill_model, only: hill_point_t, model_description
   use hillstab_hill_units, only: equilibrium_length, physical_beta
   use hillstab_hill_transfer, only: trace_t
   use hillstab_integrate_monodromy, only: monodromy_trace, method_t, method_auto
   use hillstab_curves_boundaries, only: boundary_check_t, verify_boundary, alpha_crossing_t, alpha_crossings, &
      crossing_search_gap
   use hillstab_batch_scene_types, only: scene_t, scene_header, output_path, open_scene_output
   use hillstab_batch_scene_physical, only: physical_summary, physical_scene_t
   use hillstab_batch_output_columns, only: column_t, style_e17, style_e4, style_integer, style_width2, &
      style_width4, columns_text, put_row, all_columns, column_lines
   use hillstab_batch_output_file, only: output_file_t, finish_output, discard_output, write_header, write_text
   use hillstab_core_text, only: real_text, integer_text
   implicit none
   private
   public :: spring_run

   !> The columns of the critical amplitudes of a spring: where `spring_columns` puts each
   !> column and `spring_run` its value.
   integer, parameter :: spring_a = 1, spring_alpha = 2, spring_beta = 3, spring_kind = 4, spring_order = 5, &
      spring_branch = 6, spring_status = 7, spring_check = 8, spring_a_error = 9, spring_alpha_error = 10, &
      spring_modes = 11
   integer, parameter :: n_spring_columns = 11  !! columns of a critical amplitudes file

contains

   !> The columns of the critical amplitudes of a spring, one record each, by its spring_*
   !> index (the file's order).
   function spring_columns() result(table)
      type(column_t) :: table(n_spring_columns)
      table(spring_a) = column_t("a", "m", "critical bounce amplitude: the stability of the bounce changes here", &
         style_e17)
      table(spring_alpha) = column_t("alpha", "", "alpha = a pi^2/rho of the crossing", style_e17)
      table(spring_beta) = column_t("beta", "", "the spring's beta = g pi^2/(rho omega^2)", style_e17)
      table(spring_kind) = column_t("kind", "", "S at the crossing: +2 periodic, -2 antiperiodic", style_integer)
      table(spring_order) = column_t("order", "", "n of the curve a_n/b_n crossed", style_width4)
      table(spring_branch) = column_t("branch", "", "1 = a_n (even), 2 = b_n (odd)", style_width2)
      table(spring_status) = column_t("status", "", "0 ok, 1 check by auto limited by round-off, 2 failed the "// &
         "check", style_integer)
      table(spring_check) = column_t("check", "", "S by method auto at (alpha, beta): +-2 within the tolerance", &
         style_e17)
      table(spring_a_error) = column_t("a_error", "m", "estimated error of a", style_e4)
      table(spring_alpha_error) = column_t("alpha_error", "", "estimated error of alpha", style_e4)
      table(spring_modes) = column_t("modes", "", "Fourier modes of Hill's truncation at the crossing", style_integer)
   end function spring_columns

   !> The critical amplitudes of the spring of `&physical`: every 0 <= a < rho where a
   !> transition curve crosses the spring's beta (alpha_crossings), each checked by auto;
   !> the header states the unstable intervals of a in metres, from S by auto between them.
   subroutine spring_run(scene, physical, quiet, error)
      type(scene_t), intent(in) :: scene  !! a boundaries scene of one spring
      type(physical_scene_t), intent(in) :: physical  !! its `&physical`, with r0
      logical, intent(in) :: quiet  !! no progress on stderr
      type(error_t), allocatable, intent(out) :: error  !! err_points_failed when a crossing fails its check
      type(progress_t) :: progress
      type(alpha_crossing_t), allocatable :: crossings(:)
      type(boundary_check_t), allocatable :: checks(:)
      integer, allocatable :: statuses(:)
      type(column_t) :: table(n_spring_columns)
      type(output_file_t) :: file
      type(error_t), allocatable :: cause
      real(wp) :: rho, beta, alpha_end, values(n_spring_columns)
      real(wp), allocatable :: cuts(:)
      logical, allocatable :: unstable(:)
      character(len=400) :: buffer
      character(len=:), allocatable :: intervals
      integer :: j, pos, n_failed
      rho = equilibrium_length(physical%pendulum)
      beta = physical_beta(physical%pendulum)
      alpha_end = pi2*(1.0_wp - crossing_search_gap)
      call open_scene_output(scene, file, error)
      if (allocated(error)) return
      call alpha_crossings(scene%model, beta, alpha_end, scene%method%tolerance, crossings, cause)
      if (allocated(cause)) then
         call discard_output(file)
         call set_error(error, cause%code, scene%source//": &physical: the critical amplitudes of the spring "// &
            "could not be found: "//cause%message)
         return
      end if
      allocate (checks(size(crossings)), statuses(size(crossings)))
      ! progress over the checks of the crossings and the verdicts between them, by auto
      call progress_begin(progress, int(2*size(crossings) + 1, int64), quiet, "auto checks")
      !$omp parallel do schedule(dynamic) default(shared) private(j, cause)
      do j = 1, size(crossings)
         statuses(j) = status_ok
         call verify_boundary(scene%model, crossings(j)%alpha, beta, crossings(j)%trace_sign, &
                              scene%method%tolerance, checks(j), cause)
         if (allocated(cause)) then
            statuses(j) = status_failed
         else if (.not. checks(j)%passed) then
            statuses(j) = status_failed
         else if (checks(j)%roundoff) then
            statuses(j) = status_roundoff
         end if
         call progress_step(progress)
      end do
      !$omp end parallel do
      ! the verdict between the critical amplitudes, by S of auto at the middle of each piece
      cuts = [0.0_wp, crossings%alpha, alpha_end]
      allocate (unstable(size(cuts) - 1))
      unstable = .false.
      !$omp parallel do schedule(dynamic) default(shared) private(j)
      do j = 1, size(cuts) - 1
         if (cuts(j + 1) > cuts(j)) unstable(j) = auto_unstable(scene, 0.5_wp*(cuts(j) + cuts(j + 1)), beta)
         call progress_step(progress)
      end do
      !$omp end parallel do
      call progress_end(progress)
      intervals = unstable_text(cuts, unstable, rho, alpha_end)
      table = spring_columns()
      call write_header(file, spring_header(scene, physical, table, rho, beta, alpha_end, intervals, &
                                            size(crossings)), &
                        columns_text(table, all_columns(table)), error)
      n_failed = 0
      do j = 1, size(crossings)
         if (allocated(error)) exit
         values(spring_a) = crossings(j)%alpha*rho/pi2
         values(spring_alpha) = crossings(j)%alpha
         values(spring_beta) = beta
         values(spring_kind) = real(crossings(j)%trace_sign, wp)
         values(spring_order) = real(crossings(j)%order, wp)
         values(spring_branch) = real(merge(1, 2, crossings(j)%parity == 1), wp)
         values(spring_status) = real(statuses(j), wp)
         values(spring_check) = checks(j)%trace
         values(spring_a_error) = crossings(j)%alpha_error*rho/pi2
         values(spring_alpha_error) = crossings(j)%alpha_error
         values(spring_modes) = real(crossings(j)%modes, wp)
         pos = 0
         call put_row(table, all_columns(table), values, buffer, pos)
         call write_text(file, buffer(:pos), error)
         if (statuses(j) == status_failed) n_failed = n_failed + 1
      end do
      if (allocated(error)) then
         call discard_output(file)
         return
      end if
      call finish_output(file, error)
      if (allocated(error)) return
      if (n_failed > 0) then
         j = findloc(statuses, status_failed, dim=1)
         call set_error(error, err_points_failed, scene%source//": &scene: method: "//integer_text(n_failed)// &
            " critical amplitude(s) failed the check by auto (status "//integer_text(status_failed)//" in "// &
            output_path(scene)//"); first at a = "//real_text(crossings(j)%alpha*rho/pi2)//" m, alpha = "// &
            real_text(crossings(j)%alpha))
      end if
   end subroutine spring_run

   !> Whether the bounce is unstable at (alpha, beta): |S| > 2 by method auto.
   logical function auto_unstable(scene, alpha, beta) result(unstable)
      type(scene_t), intent(in) :: scene
      real(wp), intent(in) :: alpha, beta
      type(trace_t) :: tr
      type(error_t), allocatable :: cause
      call monodromy_trace(scene%model, hill_point_t(alpha, beta, 0.0_wp), &
                           method_t(method_auto, tolerance=scene%method%tolerance), tr, cause)
      unstable = abs(tr%value) > 2.0_wp .or. tr%overflow
   end function auto_unstable

   !> "unstable for 0.003811 m <= a < 0.3981 m" (4 significant digits; an unstable interval
   !> reaching the end of the search ends at rho: inside the tongue there the bounce stays
   !> unstable up to the pivot), or "stable for every 0 m <= a <= (the end of the search)".
   function unstable_text(cuts, unstable, rho, alpha_end) result(text)
      real(wp), intent(in) :: cuts(:), rho, alpha_end
      logical, intent(in) :: unstable(:)
      character(len=:), allocatable :: text
      integer :: j
      text = ""
      do j = 1, size(unstable)
         if (.not. unstable(j)) cycle
         if (j > 1) then
            if (unstable(j - 1)) cycle   ! joined to the interval before (a crossing of a zero-width tongue)
         end if
         if (len(text) > 0) text = text//" and "
         block
            integer :: last, digits
            real(wp) :: low, high
            last = j
            do while (last < size(unstable))
               if (.not. unstable(last + 1)) exit
               last = last + 1
            end do
            low = cuts(j)*rho/pi2
            if (cuts(last + 1) >= alpha_end) then
               high = rho
            else
               high = cuts(last + 1)*rho/pi2
            end if
            ! 4 significant digits, more where 4 would print the two ends alike
            digits = 4
            do while (digits < 17 .and. significant_text(low, digits) == significant_text(high, digits))
               digits = digits + 1
            end do
            text = text//significant_text(low, digits)//" m <= a < "//significant_text(high, digits)//" m"
         end block
      end do
      if (len(text) == 0) then
         text = "stable for every 0 m <= a <= (1 - "//real_text(crossing_search_gap)//") rho (the end of "// &
                "the search; rho = "//digits4(rho)//" m)"
      else
         text = "unstable for "//text
      end if
   end function unstable_text

   !> x with 4 significant digits, plain decimal ("0.003811", "0.3981", "12.35").
   function digits4(x) result(text)
      real(wp), intent(in) :: x
      character(len=:), allocatable :: text
      text = significant_text(x, 4)
   end function digits4

   !> x with `digits` significant digits, plain decimal ("0.003811", "1.68982" at 6).
   function significant_text(x, digits) result(text)
      real(wp), intent(in) :: x
      integer, intent(in) :: digits
      character(len=:), allocatable :: text
      character(len=40) :: buffer, form
      integer :: e, decimals
      if (x == 0.0_wp) then
         text = "0"
         return
      end if
      e = floor(log10(abs(x)))
      decimals = max(0, digits - 1 - e)
      if (decimals > 20 .or. e > 15) then
         write (form, '(a, i0, a, i0, a)') "(es", digits + 8, ".", digits - 1, "e3)"
         write (buffer, form) x
      else
         write (form, '(a, i0, a)') "(f40.", decimals, ")"
         write (buffer, form) x
      end if
      text = trim(adjustl(buffer))
      if (text(1:1) == ".") text = "0"//text
   end function significant_text

   !> Header of the critical amplitudes: the spring, the method, the search, the verdicts.
   function spring_header(scene, physical, table, rho, beta, alpha_end, intervals, n) result(lines)
      type(scene_t), intent(in) :: scene
      type(physical_scene_t), intent(in) :: physical
      type(column_t), intent(in) :: table(:)
      real(wp), intent(in) :: rho, beta, alpha_end
      character(len=*), intent(in) :: intervals
      integer, intent(in) :: n
      character(len=:), allocatable :: lines(:), spring(:), per_column(:)
      character(len=400) :: text(8 + size(table))
      integer :: k, m
      spring = physical_summary(physical, scene%epsilon)
      m = 0
      m = m + 1; text(m) = model_description(scene%model)
      do k = 1, size(spring)
         m = m + 1; text(m) = spring(k)
      end do
      m = m + 1; text(m) = "critical amplitudes: every a where S = +-2 along alpha = a pi^2/rho at the spring's "// &
         "beta = "//real_text(beta)//", searched over 0 <= a <= (1 - "//real_text(crossing_search_gap)// &
         ") rho = "//real_text(alpha_end*rho/pi2)//" m"
      m = m + 1; text(m) = "method: the curves by Hill's method (tolerance "//real_text(scene%method%tolerance)// &
         "*max(1,|beta|)) at steps of 0.1 in alpha up to 0.9 pi^2, then 8 a decade in 1 - alpha/pi^2; each "// &
         "crossing refined in alpha and checked by method auto"
      m = m + 1; text(m) = integer_text(n)//" critical amplitude(s); verdicts between them by S of method auto: "// &
         intervals
      per_column = column_lines(table, all_columns(table))
      do k = 1, size(per_column)
         m = m + 1; text(m) = per_column(k)
      end do
      lines = scene_header(scene, "hillstab "//version_string//": x'' + Q(tau) x = 0, period 2 in tau; critical "// &
                           "amplitudes of a spring (S = +-2 along alpha)", text(:m))
   end function spring_header
end module hillstab_batch_tasks_boundaries_spring

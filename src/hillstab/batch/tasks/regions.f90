!> Task `regions`: every resonance region of the scene's problem (a scalar model, an equation
!> in physical time, a system) up to `&regions order`, each with its tip — the least drive at
!> which it opens and the frequency there — its kind, its width at the top of the drive range
!> and its status (hillstab_curves_regions). The two ranges are those of `&chart`: the drive
!> is the axis `&regions drive` names (the other axis is the frequency); one line per region,
!> written atomically.
!>
!> Task `edges`: the same regions' boundaries in the same plane, traced from each tip up to
!> the top drive at `&edges levels` drive levels (hillstab_curves_region_edges), every point
!> checked on both sides; one block per region (gnuplot `index`).
module hillstab_batch_tasks_regions
   use hillstab_core_kinds, only: wp, version_string
   use hillstab_core_error, only: error_t, set_error, err_input
   use hillstab_core_text, only: format_es, integer_text, real_text
   use hillstab_hill_system, only: system_equation_text, system_description
   use hillstab_integrate_monodromy, only: method_name
   use hillstab_integrate_system, only: system_method_t, system_method_name
   use hillstab_curves_critical, only: along_alpha, along_beta
   use hillstab_curves_oracle, only: oracle_t, scalar_oracle_t, system_oracle_t
   use hillstab_curves_regions, only: region_t, find_regions, max_region_order, region_kind_text, &
      region_status_name, region_found, region_theory, region_open_below, region_unconfirmed
   use hillstab_curves_region_edges, only: edge_point_t, trace_edges, max_edge_levels
   use hillstab_batch_scene_types, only: scene_t, task_t, open_scene_output, scene_header
   use hillstab_batch_scene_declaration, only: group_t, new_group, group_reader_t, var_integer, var_name, &
      begin_group, next_item, end_group
   use hillstab_batch_scene_file, only: scene_file_t, fail
   use hillstab_batch_scene_group_chart, only: chart_grid_t, chart_group, read_chart_group
   use hillstab_batch_output_file, only: output_file_t, finish_output, write_header, write_text
   implicit none
   private
   public :: regions_task_t, regions_task, edges_task_t, edges_task, chart_region_lines

   !> `regions`: the resonance regions and their tips.
   type, extends(task_t) :: regions_task_t
      type(chart_grid_t) :: grid          !! the ranges (`&chart`)
      integer :: drive = along_alpha      !! which axis is the drive
      integer :: order = 2                !! highest order
      integer :: n_samples = 32           !! samples of the drive range for a first root
      integer :: cover = 1000             !! samples of the top drive for instability outside every region
   contains
      procedure :: read => regions_read
      procedure :: run => regions_run
      procedure :: declarations => regions_declarations
   end type regions_task_t

   !> `edges`: the regions' boundaries by continuation from their tips.
   type, extends(regions_task_t) :: edges_task_t
      integer :: levels = 24              !! drive levels above each tip
   contains
      procedure :: read => edges_read
      procedure :: run => edges_run
      procedure :: declarations => edges_declarations
   end type edges_task_t

contains

   !> A regions task.
   function regions_task() result(task)
      type(regions_task_t) :: task
      task%name = "regions"
   end function regions_task

   !> An edges task.
   function edges_task() result(task)
      type(edges_task_t) :: task
      task%name = "edges"
   end function edges_task

   !> The declaration of `&edges`.
   function edges_group() result(group)
      type(group_t) :: group
      group = new_group("edges", "the regions' boundaries: how many drive levels above each tip")
      call group%add("levels", var_integer, "24", "drive levels from each tip up to the top drive (closer near "// &
                     "the tip), 1 to "//integer_text(max_edge_levels))
   end function edges_group

   !> `&chart`, `&regions` and `&edges`.
   function edges_declarations(self) result(groups)
      class(edges_task_t), intent(in) :: self  !! the task
      type(group_t), allocatable :: groups(:)
      allocate (groups(3))
      groups(1) = chart_group()
      groups(2) = regions_group()
      groups(3) = edges_group()
   end function edges_declarations

   !> Read `&chart`, `&regions` and `&edges` (optional: its defaults).
   subroutine edges_read(self, file, scene, error)
      class(edges_task_t), intent(inout) :: self  !! the task
      type(scene_file_t), intent(in) :: file      !! the scene file
      type(scene_t), intent(in) :: scene          !! the `&scene` settings
      type(error_t), allocatable, intent(out) :: error  !! err_input naming file, group and variable
      type(group_t) :: group
      type(group_reader_t) :: reader
      integer :: levels
      namelist /edges/ levels
      call read_regions_groups(self, file, scene, 3, error)
      if (allocated(error)) return
      group = edges_group()
      call begin_group(reader, file, group, optional=.true.)
      read (reader%defaults, nml=edges, iostat=reader%defaults_status, iomsg=reader%defaults_msg)
      if (reader%from_file) read (file%unit, nml=edges, iostat=reader%ios, iomsg=reader%msg)
      do while (next_item(reader, file, group))
         read (reader%record, nml=edges, iostat=reader%stat, iomsg=reader%message)
      end do
      write (reader%echo, nml=edges, delim="apostrophe", iostat=reader%echo_status)
      call end_group(reader, file, group, self%groups(3), error)
      if (allocated(error)) return
      if (levels < 1 .or. levels > max_edge_levels) then
         call fail(error, file%path, group%name, "levels", "must be 1 to "//integer_text(max_edge_levels)// &
                   ", got "//integer_text(levels))
         return
      end if
      self%levels = levels
   end subroutine edges_read

   !> The declaration of `&regions`.
   function regions_group() result(group)
      type(group_t) :: group
      group = new_group("regions", "the resonance regions: which axis is the drive, the highest order")
      call group%add("drive", var_name, "'auto'", "the axis of the drive amplitude: 'alpha', 'beta', or 'auto' "// &
                     "(beta for models equation and equations, alpha otherwise); the other axis is the frequency")
      call group%add("order", var_integer, "2", "highest order k of the resonances (k Omega = 2 omega_i, "// &
                     "omega_i + omega_j, |omega_i - omega_j|), 1 to "//integer_text(max_region_order))
      call group%add("n_samples", var_integer, "32", "samples of the drive range for the first critical drive "// &
                     "of a region, 2 to 100000")
      call group%add("cover", var_integer, "1000", "samples of the frequency range at the top drive: an unstable "// &
                     "stretch outside every region's edges there is listed (kind 0, status 6); 0 none, or 2 to 100000")
   end function regions_group

   !> `&chart` (the ranges) and `&regions`.
   function regions_declarations(self) result(groups)
      class(regions_task_t), intent(in) :: self  !! the task
      type(group_t), allocatable :: groups(:)
      allocate (groups(2))
      groups(1) = chart_group()
      groups(2) = regions_group()
   end function regions_declarations

   !> Read `&chart` and `&regions`.
   subroutine regions_read(self, file, scene, error)
      class(regions_task_t), intent(inout) :: self  !! the task
      type(scene_file_t), intent(in) :: file      !! the scene file
      type(scene_t), intent(in) :: scene          !! the `&scene` settings
      type(error_t), allocatable, intent(out) :: error  !! err_input naming file, group and variable
      call read_regions_groups(self, file, scene, 2, error)
   end subroutine regions_read

   !> Read `&chart` and `&regions` into the first two of `n_groups` groups.
   subroutine read_regions_groups(self, file, scene, n_groups, error)
      class(regions_task_t), intent(inout) :: self
      type(scene_file_t), intent(in) :: file
      type(scene_t), intent(in) :: scene
      integer, intent(in) :: n_groups
      type(error_t), allocatable, intent(out) :: error
      type(group_t) :: group
      type(group_reader_t) :: reader
      character(len=16) :: drive
      integer :: order, n_samples, cover
      class(oracle_t), allocatable :: oracle
      namelist /regions/ drive, order, n_samples, cover
      allocate (self%groups(n_groups))
      if (allocated(scene%system)) then
         call read_chart_group(file, chart_group(), grid=self%grid, values=self%groups(1), error=error)
      else
         call read_chart_group(file, chart_group(), scene%model, self%grid, self%groups(1), error)
      end if
      if (allocated(error)) return
      group = regions_group()
      call begin_group(reader, file, group)
      read (reader%defaults, nml=regions, iostat=reader%defaults_status, iomsg=reader%defaults_msg)
      if (reader%from_file) read (file%unit, nml=regions, iostat=reader%ios, iomsg=reader%msg)
      do while (next_item(reader, file, group))
         read (reader%record, nml=regions, iostat=reader%stat, iomsg=reader%message)
      end do
      write (reader%echo, nml=regions, delim="apostrophe", iostat=reader%echo_status)
      call end_group(reader, file, group, self%groups(2), error)
      if (allocated(error)) return
      select case (trim(drive))
      case ("alpha")
         self%drive = along_alpha
      case ("beta")
         self%drive = along_beta
      case ("auto")
         self%drive = along_alpha
         if (allocated(scene%system)) then
            if (scene%system%name() == "equations") self%drive = along_beta
         else
            if (scene%model%name() == "equation") self%drive = along_beta
         end if
      case default
         call fail(error, file%path, group%name, "drive", "must be 'alpha', 'beta' or 'auto', got '"//trim(drive)//"'")
         return
      end select
      if (order < 1 .or. order > max_region_order) then
         call fail(error, file%path, group%name, "order", "must be 1 to "//integer_text(max_region_order)// &
                   ", got "//integer_text(order))
         return
      end if
      if (n_samples < 2 .or. n_samples > 100000) then
         call fail(error, file%path, group%name, "n_samples", "must be 2 to 100000, got "//integer_text(n_samples))
         return
      end if
      if (cover /= 0 .and. (cover < 2 .or. cover > 100000)) then
         call fail(error, file%path, group%name, "cover", "must be 0 or 2 to 100000, got "//integer_text(cover))
         return
      end if
      self%order = order
      self%n_samples = n_samples
      self%cover = cover
      call new_oracle(self, scene, oracle)
      call check_ranges(self, oracle, file%path, error)
   end subroutine read_regions_groups

   !> The frequency and drive ranges checked against the problem: a point outside its domain
   !> names the `&chart` bound; a problem whose drive changes nothing in time names `&regions
   !> drive`.
   subroutine check_ranges(self, oracle, path, error)
      class(regions_task_t), intent(in) :: self
      class(oracle_t), intent(in) :: oracle
      character(len=*), intent(in) :: path
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: f(2), d(2)
      type(error_t), allocatable :: cause
      character(len=:), allocatable :: f_name, d_name
      integer :: i, j
      call ranges(self, f, d)
      f_name = trim(merge("beta ", "alpha", self%drive == along_alpha))
      d_name = trim(merge("alpha", "beta ", self%drive == along_alpha))
      if (.not. (d(2) > d(1))) then
         call fail(error, path, "chart", d_name//"_max", "the drive range is empty: "//d_name//"_max must exceed "// &
                   d_name//"_min")
         return
      end if
      if (.not. (f(2) > f(1))) then
         call fail(error, path, "chart", f_name//"_max", "the frequency range is empty: "//f_name// &
                   "_max must exceed "//f_name//"_min")
         return
      end if
      do i = 1, 2
         do j = 1, 2
            call oracle%check(f(i), d(j), cause)
            if (allocated(cause)) then
               call fail(error, path, "chart", merge(f_name//"_min", f_name//"_max", i == 1), trim(cause%message))
               return
            end if
         end do
      end do
      do i = 1, 2
         call oracle%check(f(i), 0.0_wp, cause)
         if (allocated(cause)) then
            call fail(error, path, "regions", "drive", "the undriven problem ("//d_name//" = 0) lies outside "// &
                      "the domain (the other axis?): "//trim(cause%message))
            return
         end if
      end do
      if (.not. oracle%driven(f(1), d(2))) &
         call fail(error, path, "regions", "drive", "the coefficient's time dependence does not change with "// &
                   d_name//": no drive to search (the other axis?)")
   end subroutine check_ranges

   !> The frequency range f and the drive range d of the grid.
   pure subroutine ranges(self, f, d)
      class(regions_task_t), intent(in) :: self
      real(wp), intent(out) :: f(2), d(2)
      if (self%drive == along_alpha) then
         d = [self%grid%alpha_min, self%grid%alpha_max]
         f = [self%grid%beta_min, self%grid%beta_max]
      else
         f = [self%grid%alpha_min, self%grid%alpha_max]
         d = [self%grid%beta_min, self%grid%beta_max]
      end if
   end subroutine ranges

   !> The header lines of a chart of an equation in physical time (model `equation`, or
   !> `equations` for a system) over (α, β), β its drive: every resonance region up to order
   !> 2 whose tip is known or not confirmed, with its tip and its width at the top drive, the
   !> regions narrower there than the α spacing of the grid said to be so (a chart can miss
   !> them), so that no region disappears from a chart silently. None for other models, a
   !> single line saying why when the regions cannot be searched (β no drive, the undriven
   !> problem outside the domain).
   function chart_region_lines(scene, grid) result(lines)
      type(scene_t), intent(in) :: scene          !! the chart's scene
      type(chart_grid_t), intent(in) :: grid      !! its grid
      character(len=300), allocatable :: lines(:)
      type(regions_task_t) :: task
      class(oracle_t), allocatable :: oracle
      type(region_t), allocatable :: regions(:)
      type(error_t), allocatable :: error
      character(len=:), allocatable :: f_axis, d_axis, line
      real(wp) :: spacing, width
      integer :: k, n
      logical :: equation
      allocate (lines(0))
      if (allocated(scene%system)) then
         equation = scene%system%name() == "equations"
      else
         equation = scene%model%name() == "equation"
      end if
      if (.not. equation .or. grid%n_alpha < 2 .or. .not. (grid%beta_max > grid%beta_min)) return
      task%grid = grid
      task%drive = along_beta
      task%order = 2
      call new_oracle(task, scene, oracle)
      call check_ranges(task, oracle, scene%source, error)
      if (.not. allocated(error)) call find_regions(oracle, grid%alpha_min, grid%alpha_max, grid%beta_min, &
                                                    grid%beta_max, task%order, scene%method%tolerance, &
                                                    task%n_samples, regions, error, cover=0)
      if (allocated(error)) then
         lines = [character(len=300) :: "regions: not listed ("//trim(error%message(1:min(len(error%message), &
                                        240)))//")"]
         return
      end if
      if (allocated(scene%system)) then
         f_axis = scene%system%axis_name(1)
         d_axis = scene%system%axis_name(2)
      else
         f_axis = scene%model%axis_name(1)
         d_axis = scene%model%axis_name(2)
      end if
      spacing = abs(grid%alpha_max - grid%alpha_min)/real(grid%n_alpha - 1, wp)
      n = count(regions%status == region_found .or. regions%status == region_theory .or. &
                regions%status == region_open_below .or. regions%status == region_unconfirmed)
      deallocate (lines)
      allocate (lines(n + 1))
      lines(1) = "regions up to order 2 (task regions: every order, task edges: their boundaries): "// &
                 integer_text(n)//" with a tip in the chart's ranges, each with its tip and its width at "// &
                 d_axis//" = "//trim(format_es(grid%beta_max, 6))
      n = 1
      do k = 1, size(regions)
         if (.not. (regions(k)%status == region_found .or. regions(k)%status == region_theory .or. &
                    regions(k)%status == region_open_below .or. regions(k)%status == region_unconfirmed)) cycle
         n = n + 1
         width = regions(k)%edges(2) - regions(k)%edges(1)
         line = "region "//region_kind_text(regions(k), f_axis)//": tip "//f_axis//" "// &
                trim(format_es(regions(k)%frequency, 6))//", "//d_axis//" "//trim(format_es(regions(k)%drive, 6))// &
                " ("//region_status_name(regions(k)%status)//"); width "//trim(format_es(width, 3))
         if (regions(k)%status == region_unconfirmed) then
            line = line//" (its least drive on its window's end, or not confirmed: perhaps a neighbour's flank)"
         else if (width < spacing) then
            line = line//": NARROWER than the "//f_axis//" spacing "//trim(format_es(spacing, 3))// &
                   ", the chart may not show it"
         end if
         lines(n) = line
      end do
   end function chart_region_lines

   !> The scene's problem as an oracle.
   subroutine new_oracle(self, scene, oracle)
      class(regions_task_t), intent(in) :: self
      type(scene_t), intent(in) :: scene
      class(oracle_t), allocatable, intent(out) :: oracle
      if (allocated(scene%system)) then
         block
            type(system_oracle_t) :: s
            allocate (s%system, source=scene%system)
            s%method = system_method_t(scene%method%kind, scene%method%tolerance)
            s%epsilon = scene%epsilon
            s%drive_axis = self%drive
            allocate (oracle, source=s)
         end block
      else
         block
            type(scalar_oracle_t) :: s
            allocate (s%model, source=scene%model)
            s%method = scene%method
            s%epsilon = scene%epsilon
            s%drive_axis = self%drive
            allocate (oracle, source=s)
         end block
      end if
   end subroutine new_oracle

   !> The scene's regions with their tips, and the lines that state the problem: its equation,
   !> model and method, the names of the frequency and drive axes, and the line of the ranges.
   subroutine scene_regions(self, scene, oracle, regions, equation, about, f_axis, d_axis, f, d, swept, error)
      class(regions_task_t), intent(in) :: self
      type(scene_t), intent(in) :: scene
      class(oracle_t), allocatable, intent(out) :: oracle
      type(region_t), allocatable, intent(out) :: regions(:)
      character(len=:), allocatable, intent(out) :: equation, f_axis, d_axis
      character(len=300), intent(out) :: about(3)
      real(wp), intent(out) :: f(2), d(2)
      integer, intent(out) :: swept
      type(error_t), allocatable, intent(out) :: error
      call new_oracle(self, scene, oracle)
      call ranges(self, f, d)
      call find_regions(oracle, f(1), f(2), d(1), d(2), self%order, scene%method%tolerance, self%n_samples, &
                        regions, error, cover=self%cover, swept=swept)
      if (allocated(error)) then
         call set_error(error, err_input, scene%source//": &regions: "//error%message)
         return
      end if
      if (allocated(scene%system)) then
         equation = system_equation_text(scene%system)
         about(1) = system_description(scene%system)
         about(2) = "method: "//system_method_name(scene%method%kind)//", tolerance "// &
                    real_text(scene%method%tolerance)//" on Phi's entries; the distance from stability is "// &
                    "ln|lambda| of the region's multipliers (those whose argument is nearest the resonance's); "// &
                    "epsilon "//real_text(scene%epsilon)//" adds C = epsilon M"
         f_axis = scene%system%axis_name(merge(2, 1, self%drive == along_alpha))
         d_axis = scene%system%axis_name(merge(1, 2, self%drive == along_alpha))
      else
         equation = scene%model%formula()
         about(1) = "model: "//scene%model%name()//", "//scene%model%formula()
         about(2) = "method: "//method_name(scene%method%kind)//", tolerance "// &
                    real_text(scene%method%tolerance)//" on S; the distance from stability is sigma S - 2 "// &
                    "cosh(eps P/2), sigma = (-1)^k of the region's order; epsilon "//real_text(scene%epsilon)
         f_axis = scene%model%axis_name(merge(2, 1, self%drive == along_alpha))
         d_axis = scene%model%axis_name(merge(1, 2, self%drive == along_alpha))
      end if
      about(3) = "frequency axis: "//f_axis//" in ["//trim(format_es(f(1), 9))//", "//trim(format_es(f(2), 9))// &
                 "]; drive axis: "//d_axis//" in ["//trim(format_es(d(1), 9))//", "//trim(format_es(d(2), 9))//"]"
   end subroutine scene_regions

   !> One line per region, ascending in its predicted frequency.
   subroutine regions_run(self, scene, quiet, error)
      class(regions_task_t), intent(in) :: self  !! the task
      type(scene_t), intent(in) :: scene  !! its scene
      logical, intent(in) :: quiet  !! no progress on stderr
      type(error_t), allocatable, intent(out) :: error  !! a point the method cannot compute; err_io
      class(oracle_t), allocatable :: oracle
      type(region_t), allocatable :: regions(:)
      type(output_file_t) :: file
      character(len=300) :: extra(8)
      character(len=:), allocatable :: f_axis, d_axis, equation, line, names
      real(wp) :: f(2), d(2)
      integer :: k, swept
      call scene_regions(self, scene, oracle, regions, equation, extra(1:3), f_axis, d_axis, f, d, swept, error)
      if (allocated(error)) return
      extra(4) = "kind: 1 simple (k Omega = 2 omega_i), 2 sum (omega_i + omega_j), 3 difference (|omega_i - "// &
                 "omega_j|), 0 unassigned (unstable at the top drive outside every region: order, modes and "// &
                 "predicted 0); order: k; mode_i, mode_j: i, j"
      extra(5) = "predicted: the frequency of the resonance at drive 0; frequency, drive: the tip (the least "// &
                 "drive at which the region is open) with their error bounds"
      extra(6) = "edge_low, edge_high: the region's edges at the top drive (0 0: not open there); clipped: the "// &
                 "edge is its window's end (the region is wider)"
      extra(7) = "status: 0 found and confirmed, 1 closed up to the top drive, 2 not confirmed, 3 open at the "// &
                 "lowest drive, 4 theory (undamped: the tip is the resonance at drive 0), 5 same signature "// &
                 "(a difference region that stays closed), 6 uncovered (kind 0: its edges at the top drive, "// &
                 "its frequency their middle, its tip not searched)"
      extra(8) = "cover: "//integer_text(self%cover)//" samples of the top drive for instability outside every "// &
                 "region ("//integer_text(swept)//" distances outside the regions' edges); an unstable stretch "// &
                 "narrower than their spacing can go unseen"
      call open_scene_output(scene, file, error)
      if (allocated(error)) return
      names = "kind order mode_i mode_j predicted "//f_axis//" "//f_axis//"_error "//d_axis//" "//d_axis// &
              "_error edge_low edge_high clipped_low clipped_high status evaluations"
      call write_header(file, scene_header(scene, "hillstab "//version_string//": the resonance regions of "// &
                        equation, extra), names, error)
      do k = 1, size(regions)
         if (allocated(error)) exit
         line = integer_text(regions(k)%kind)//" "//integer_text(regions(k)%order)//" "// &
                integer_text(regions(k)%modes(1))//" "//integer_text(regions(k)%modes(2))//" "// &
                trim(format_es(regions(k)%predicted, 17))//" "//trim(format_es(regions(k)%frequency, 17))//" "// &
                trim(format_es(regions(k)%frequency_error, 3))//" "//trim(format_es(regions(k)%drive, 17))//" "// &
                trim(format_es(regions(k)%drive_error, 3))//" "//trim(format_es(regions(k)%edges(1), 17))//" "// &
                trim(format_es(regions(k)%edges(2), 17))//" "//integer_text(merge(1, 0, regions(k)%clipped(1)))// &
                " "//integer_text(merge(1, 0, regions(k)%clipped(2)))//" "//integer_text(regions(k)%status)//" "// &
                integer_text(regions(k)%evaluations)
         call write_text(file, line, error)
      end do
      call finish_output(file, error)
   end subroutine regions_run

   !> One block per region that opens in the range (gnuplot `index`): its lower edge from the
   !> top drive down to the tip, the tip, its upper edge up to the top drive.
   subroutine edges_run(self, scene, quiet, error)
      class(edges_task_t), intent(in) :: self  !! the task
      type(scene_t), intent(in) :: scene  !! its scene
      logical, intent(in) :: quiet  !! no progress on stderr
      type(error_t), allocatable, intent(out) :: error  !! a point the method cannot compute; err_io
      class(oracle_t), allocatable :: oracle
      type(region_t), allocatable :: regions(:)
      type(edge_point_t), allocatable :: points(:)
      type(output_file_t) :: file
      character(len=300) :: about(3)
      character(len=300), allocatable :: extra(:)
      character(len=:), allocatable :: f_axis, d_axis, equation, line, names
      real(wp) :: f(2), d(2)
      integer :: k, j, swept
      call scene_regions(self, scene, oracle, regions, equation, about, f_axis, d_axis, f, d, swept, error)
      if (allocated(error)) return
      call trace_edges(oracle, regions, f(1), f(2), d(1), d(2), scene%method%tolerance, self%levels, points, error)
      if (allocated(error)) then
         call set_error(error, err_input, scene%source//": &edges: "//error%message)
         return
      end if
      allocate (extra(6 + size(regions)))
      extra(1:3) = about
      extra(4) = "region: its line below (and in task regions' file); kind, order, mode_i, mode_j as there; "// &
                 "branch: -1 the lower edge in "//f_axis//", 1 the upper, 0 the tip; "//f_axis//"_error: the "// &
                 "edge's error bound; "//d_axis//": the level (exact)"
      extra(5) = "status: 0 a stability boundary (checked: unstable inside, stable outside), 1 overlap (unstable "// &
                 "on both sides: another region overlaps, no stability boundary), 2 not confirmed, 3 still inside "// &
                 "at the range's end, 4 the tip; evaluations: distances computed for the point"
      extra(6) = "one block per region that opens in the range (gnuplot index), blocks separated by two blank lines"
      do k = 1, size(regions)
         extra(6 + k) = "region "//integer_text(k)//": "//region_kind_text(regions(k), f_axis)//"; tip "// &
                        f_axis//" "//trim(format_es(regions(k)%frequency, 9))//", "//d_axis//" "// &
                        trim(format_es(regions(k)%drive, 9))//"; "//region_status_name(regions(k)%status)
      end do
      call open_scene_output(scene, file, error)
      if (allocated(error)) return
      names = "region kind order mode_i mode_j branch "//f_axis//" "//f_axis//"_error "//d_axis//" status evaluations"
      call write_header(file, scene_header(scene, "hillstab "//version_string//": the boundaries of the "// &
                        "resonance regions of "//equation, extra), names, error)
      do j = 1, size(points)
         if (allocated(error)) exit
         k = points(j)%region
         if (j > 1) then
            if (k /= points(j - 1)%region) call write_text(file, new_line("a"), error)
         end if
         line = integer_text(k)//" "//integer_text(regions(k)%kind)//" "//integer_text(regions(k)%order)//" "// &
                integer_text(regions(k)%modes(1))//" "//integer_text(regions(k)%modes(2))//" "// &
                integer_text(points(j)%branch)//" "//trim(format_es(points(j)%frequency, 17))//" "// &
                trim(format_es(points(j)%frequency_error, 3))//" "//trim(format_es(points(j)%drive, 17))//" "// &
                integer_text(points(j)%status)//" "//integer_text(points(j)%evaluations)
         call write_text(file, line, error)
      end do
      call finish_output(file, error)
   end subroutine edges_run
end module hillstab_batch_tasks_regions

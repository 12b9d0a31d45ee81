!> Tests of scene reading: defaults, group order, the namelist written back into
!> output headers, exact real-to-text round trips, and every kind of bad input
!> (each must give an error naming the file, the group and the variable).
module test_scene
   use hillstab_core_kinds, only: wp, pi2, int64
   use hillstab_core_error, only: error_t, err_input
   use hillstab_core_text, only: real_text, read_text_line, integer_text
   use hillstab_hill_coefficient, only: sampling_endpoint, sampling_average
   use hillstab_integrate_monodromy, only: method_auto, method_segments
   use hillstab_batch_scene_types, only: scene_t, scene_namelist
   use hillstab_batch_run_read, only: read_scene
   use hillstab_batch_scene_file, only: max_line_length
   use hillstab_batch_scene_declaration, only: group_t
   use hillstab_batch_scene_group_chart, only: chart_grid_t, grid_value, grid_alpha, grid_beta, grid_point, scale_log, &
      scale_linear
   use hillstab_batch_tasks_chart, only: chart_task_t
   use hillstab_batch_tasks_points, only: points_task_t
   use hillstab_batch_tasks_coefficient, only: coefficient_task_t
   use hillstab_batch_tasks_series, only: series_task_t
   use hillstab_batch_tasks_lyapunov, only: lyapunov_task_t
   use hillstab_batch_tasks_registry, only: task_names, new_task
   use hillstab_batch_scene_types, only: task_t
   use hillstab_batch_run_templates, only: scene_template
   use hillstab_testing
   use hillstab_test_scratch, only: scratch_prefix, write_file, read_lines, file_exists, delete_file, contains_text, &
      padded
   use hillstab_test_bad_scenes, only: bad_case_t, bad_cases, bad_case_text, write_bad_points_files, &
      delete_bad_points_files
   use hillstab_hill_model_elastic, only: elastic_model_t
   use hillstab_hill_model_mathieu, only: mathieu_model_t
   implicit none
   private
   public :: collect_scene, grid_of, points_of, coefficient_of

contains

   function collect_scene() result(suite)
      type(testsuite_t) :: suite
      suite = new_testsuite("scene", [ &
         new_unittest("defaults", defaults), &
         new_unittest("group_order_and_comments", group_order_and_comments), &
         new_unittest("coefficient_list", coefficient_list), &
         new_unittest("points_file", points_file), &
         new_unittest("points_file_tab_lines", points_file_tab_lines), &
         new_unittest("points_file_line_ends", points_file_line_ends), &
         new_unittest("points_file_byte_order_mark", points_file_byte_order_mark), &
         new_unittest("real_text_round_trip", real_text_round_trip), &
         new_unittest("namelist_round_trip", namelist_round_trip), &
         new_unittest("bad_input_messages", bad_input_messages), &
         new_unittest("missing_scene_file", missing_scene_file), &
         new_unittest("hostile_scene_files", hostile_scene_files), &
         new_unittest("special_files_refused", special_files_refused), &
         new_unittest("read_as_written", read_as_written), &
         new_unittest("groups_declared_once", groups_declared_once), &
         new_unittest("start_angle_in_degrees", start_angle_in_degrees), &
         new_unittest("foreign_groups_warned", foreign_groups_warned), &
         new_unittest("implausible_spring_warned", implausible_spring_warned), &
         new_unittest("grid_near_the_largest_double", grid_near_the_largest_double), &
         new_unittest("log_grid_values", log_grid_values), &
         new_unittest("log_grid_read_and_echoed", log_grid_read_and_echoed)])
   end function collect_scene

   !> The grid of a chart scene (a zero grid for another task).
   function grid_of(scene) result(grid)
      type(scene_t), intent(in) :: scene
      type(chart_grid_t) :: grid
      select type (task => scene%task)
      type is (chart_task_t)
         grid = task%grid
      end select
   end function grid_of

   !> The points of a points scene (none for another task).
   function points_of(scene) result(points)
      type(scene_t), intent(in) :: scene
      real(wp), allocatable :: points(:, :)
      allocate (points(2, 0))
      select type (task => scene%task)
      type is (points_task_t)
         points = task%points
      end select
   end function points_of

   !> The task of a coefficient scene.
   function coefficient_of(scene) result(coefficient)
      type(scene_t), intent(in) :: scene
      type(coefficient_task_t) :: coefficient
      select type (task => scene%task)
      type is (coefficient_task_t)
         coefficient = task
      end select
   end function coefficient_of

   !> Write `lines` to a scratch scene file and read it.
   subroutine read_text_scene(name, lines, scene, error, path)
      character(len=*), intent(in) :: name
      character(len=*), intent(in) :: lines(:)
      type(scene_t), intent(out) :: scene
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable, intent(out) :: path
      path = scratch_prefix(name)//".nml"
      call write_file(path, lines)
      call read_scene(path, scene, error)
      call delete_file(path)
   end subroutine read_text_scene

   subroutine defaults(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(chart_grid_t) :: grid
      type(scene_t) :: scene
      type(error_t), allocatable :: error
      character(len=:), allocatable :: path
      call read_text_scene("defaults", ["&scene /", "&chart /"], scene, error, path)
      call check(ctx, .not. allocated(error), "defaults read")
      if (allocated(error)) return
      call check(ctx, scene%task%name == "chart", "task chart")
      call check(ctx, scene%model%name() == "elastic", "model elastic")
      call check(ctx, scene%method%kind == method_auto, "method auto")
      call check(ctx, scene%method%n_segments == 2, "n_segments 2")
      call check(ctx, scene%method%sampling == sampling_endpoint, "sampling endpoint")
      call check(ctx, scene%method%tolerance, 1.0e-10_wp)
      call check(ctx, scene%epsilon, 0.0_wp)
      ! output defaults to the scene file name without directory and extension
      call check(ctx, scene%output == path(len("build/") + 1:len(path) - len(".nml")), "default output "//scene%output)
      grid = grid_of(scene)
      call check(ctx, grid%alpha_min, 0.0_wp)
      call check(ctx, grid%alpha_max, 9.8_wp)
      call check(ctx, grid%beta_min, -2.0_wp)
      call check(ctx, grid%beta_max, 12.0_wp)
      call check(ctx, grid%n_alpha == 200 .and. grid%n_beta == 200, "200 x 200")
   end subroutine defaults

   subroutine group_order_and_comments(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(chart_grid_t) :: grid
      type(scene_t) :: scene
      type(error_t), allocatable :: error
      character(len=:), allocatable :: path
      call read_text_scene("order", [ &
         padded("! a comment line"), &
         padded("&chart n_alpha = 3, n_beta = 4,  ! trailing comment"), &
         padded("   alpha_max = 9.7 /"), &
         padded("&other x = 1 /"), &
         padded("&scene task = 'chart', model = 'Mathieu',"), &
         padded("  method = 'segments', n_segments = 64, sampling = 'average',"), &
         padded("  epsilon = 0.5, output = 'build/x!y' /")], scene, error, path)
      call check(ctx, .not. allocated(error), "scene read")
      if (allocated(error)) then
         call check(ctx, .false., error%message)
         return
      end if
      call check(ctx, scene%model%name() == "mathieu", "model name is case-insensitive")
      call check(ctx, scene%method%kind == method_segments .and. scene%method%n_segments == 64, "segments 64")
      call check(ctx, scene%method%sampling == sampling_average, "average")
      call check(ctx, scene%epsilon, 0.5_wp)
      call check(ctx, scene%output == "build/x!y", "'!' inside a string is not a comment")
      grid = grid_of(scene)
      call check(ctx, grid%n_alpha == 3 .and. grid%n_beta == 4, "chart counts")
      call check(ctx, grid%alpha_max, 9.7_wp)
      call check(ctx, grid%beta_max, 12.0_wp)
      call check(ctx, grid_value(0.0_wp, 9.7_wp, 3, 2), 4.85_wp)
      call check(ctx, grid_value(0.0_wp, 9.7_wp, 3, 3), 9.7_wp, abs=0.0_wp, rel=0.0_wp)
   end subroutine group_order_and_comments

   subroutine coefficient_list(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(coefficient_task_t) :: c
      type(scene_t) :: scene
      type(error_t), allocatable :: error
      character(len=:), allocatable :: path
      call read_text_scene("coef", [ padded("&scene task = 'coefficient' /"), &
         padded("&coefficient alphas = 4, 9.7, beta = 2.5, n_tau = 5 /")], scene, error, path)
      call check(ctx, .not. allocated(error), "coefficient read")
      if (allocated(error)) return
      ! two values given: exactly two, not the rest of the default list
      c = coefficient_of(scene)
      call check(ctx, size(c%alphas) == 2, "two alphas")
      if (size(c%alphas) == 2) call check(ctx, c%alphas(2), 9.7_wp)
      call check(ctx, c%beta, 2.5_wp)
      call check(ctx, c%n_tau == 5, "n_tau")
      call read_text_scene("coef2", [ padded("&scene task = 'coefficient' /"), padded("&coefficient /")], &
                           scene, error, path)
      call check(ctx, .not. allocated(error), "default coefficient read")
      if (allocated(error)) return
      c = coefficient_of(scene)
      call check(ctx, size(c%alphas) == 6, "the paper's six alphas by default")
      if (size(c%alphas) == 6) call check(ctx, c%alphas(6), 9.7_wp)
   end subroutine coefficient_list

   subroutine points_file(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp), allocatable :: pairs(:, :)
      type(scene_t) :: scene
      type(error_t), allocatable :: error
      character(len=:), allocatable :: path, points
      points = scratch_prefix("pts")//".dat"
      call write_file(points, [character(len=40) :: "# alpha beta", "1.48 2.47  # (a)", "", &
         "  3.70, 2.47", "5.0 0.76 extra columns ignored"])
      call read_text_scene("points", [ padded("&scene task = 'points' /"), &
         padded("&points file = '"//points//"' /")], scene, error, path)
      call delete_file(points)
      call check(ctx, .not. allocated(error), "points read")
      if (allocated(error)) return
      pairs = points_of(scene)
      call check(ctx, size(pairs, 2) == 3, "three points")
      if (size(pairs, 2) == 3) then
         call check(ctx, pairs(1, 2), 3.70_wp)
         call check(ctx, pairs(2, 3), 0.76_wp)
      end if
   end subroutine points_file

   !> A points file exactly as given, byte by byte (no line end added).
   subroutine write_bytes(path, text)
      character(len=*), intent(in) :: path, text
      integer :: unit
      open (newunit=unit, file=path, access="stream", form="unformatted", status="replace", action="write")
      write (unit) text
      close (unit)
   end subroutine write_bytes

   !> Read the points of a points file through a points scene.
   subroutine read_points_text(text, pairs, error)
      character(len=*), intent(in) :: text  !! the points file's bytes
      real(wp), allocatable, intent(out) :: pairs(:, :)
      type(error_t), allocatable, intent(out) :: error
      type(scene_t) :: scene
      character(len=:), allocatable :: path, points
      points = scratch_prefix("pts_bytes")//".dat"
      call write_bytes(points, text)
      call read_text_scene("points_bytes", [padded("&scene task = 'points' /"), &
                           padded("&points file = '"//points//"' /")], scene, error, path)
      call delete_file(points)
      allocate (pairs(2, 0))
      if (.not. allocated(error)) pairs = points_of(scene)
   end subroutine read_points_text

   !> Lines of blanks and tabs, tab-indented comments and a tab between the numbers (the
   !> fuzzer's points files: a tab-indented comment was refused, "got '\x09'").
   subroutine points_file_tab_lines(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=*), parameter :: lf = achar(10), tab = achar(9)
      real(wp), allocatable :: pairs(:, :)
      type(error_t), allocatable :: error
      call read_points_text("1.48 2.47"//lf//tab//lf//tab//"# a comment"//lf//" "//tab//" "//lf// &
                            "3.70"//tab//"2.47"//tab//"# (b)"//lf//"1.0 2.0 "//tab//lf, pairs, error)
      call check(ctx, .not. allocated(error), "read")
      if (allocated(error)) then
         call check(ctx, .false., error%message)
         return
      end if
      call check(ctx, size(pairs, 2) == 3, "three points")
      if (size(pairs, 2) == 3) call check(ctx, all(pairs == reshape([1.48_wp, 2.47_wp, 3.70_wp, 2.47_wp, &
                                                                     1.0_wp, 2.0_wp], [2, 3])), "their values")
   end subroutine points_file_tab_lines

   !> Line ends LF, CR LF and a lone CR (old Mac files; gfortran's formatted read ends a
   !> record at each); a message counts the lines as they end.
   subroutine points_file_line_ends(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=*), parameter :: lf = achar(10), cr = achar(13)
      character(len=*), parameter :: body(3) = [character(len=9) :: "1.48 2.47", "3.70 2.47", "5.0 0.76"]
      character(len=2), parameter :: ends(3) = [character(len=2) :: lf, cr//lf, cr]
      real(wp), allocatable :: pairs(:, :)
      type(error_t), allocatable :: error
      integer :: k
      do k = 1, size(ends)
         call read_points_text("# the paper's points"//trim(ends(k))//trim(body(1))//trim(ends(k))// &
                               trim(body(2))//"  # (b)"//trim(ends(k))//trim(ends(k))//trim(body(3))// &
                               trim(ends(k)), pairs, error)
         call check(ctx, .not. allocated(error), "read, line end "//integer_text(k))
         if (allocated(error)) then
            call check(ctx, .false., error%message)
            cycle
         end if
         call check(ctx, size(pairs, 2) == 3, "three points, line end "//integer_text(k))
         if (size(pairs, 2) == 3) call check(ctx, pairs(1, 3) == 5.0_wp .and. pairs(2, 2) == 2.47_wp, &
                                             "their values, line end "//integer_text(k))
      end do
      ! CR alone, then mixed with LF: the bad line is the one an editor shows as line 3
      call read_points_text("1 2"//cr//"3 4"//cr//"5"//cr//"7 8"//lf, pairs, error)
      call check(ctx, allocated(error), "a line with one number")
      if (allocated(error)) call check(ctx, index(error%message, "line 3: expected two numbers") > 0, &
                                       "names line 3: "//error%message)
      call read_points_text("1 2"//lf//"3 4"//cr//"5"//lf, pairs, error)
      call check(ctx, allocated(error), "a line with one number, mixed line ends")
      if (allocated(error)) call check(ctx, index(error%message, "line 3: expected two numbers") > 0, &
                                       "names line 3 (mixed line ends): "//error%message)
   end subroutine points_file_line_ends

   !> A UTF-8 byte-order mark at the start of a points file is skipped, as in a scene file
   !> (it was refused with the mark, unseen, in the message); elsewhere it is no number.
   subroutine points_file_byte_order_mark(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=*), parameter :: lf = achar(10), bom = achar(239)//achar(187)//achar(191)
      real(wp), allocatable :: pairs(:, :)
      type(error_t), allocatable :: error
      call read_points_text(bom//"1.48 2.47"//lf//"3.70 2.47"//lf, pairs, error)
      call check(ctx, .not. allocated(error), "read with the mark before a point")
      if (.not. allocated(error)) call check(ctx, size(pairs, 2) == 2 .and. pairs(1, 1) == 1.48_wp, "two points")
      call read_points_text(bom//"# comment"//lf//"3.70 2.47"//lf, pairs, error)
      call check(ctx, .not. allocated(error), "read with the mark before a comment")
      if (.not. allocated(error)) call check(ctx, size(pairs, 2) == 1, "one point")
      call read_points_text("1.48 2.47"//lf//bom//"3.70 2.47"//lf, pairs, error)
      call check(ctx, allocated(error), "the mark on line 2 is no number")
      if (allocated(error)) call check(ctx, index(error%message, "line 2: expected two numbers") > 0, &
                                       "names line 2: "//error%message)
   end subroutine points_file_byte_order_mark

   subroutine real_text_round_trip(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp) :: values(10), back
      character(len=:), allocatable :: text
      integer :: k
      values = [9.8_wp, 1.0e-10_wp, -2.0_wp, pi2, 1.0_wp/3.0_wp, 1.0e300_wp, -4.9e-324_wp, 0.1_wp, 123456.789_wp, &
                2.0_wp**60]
      do k = 1, size(values)
         text = real_text(values(k))
         read (text, *) back
         call check(ctx, back, values(k), rel=0.0_wp, abs=0.0_wp, message="round trip of "//text)
      end do
      call check(ctx, real_text(9.8_wp) == "9.8", "9.8 -> "//real_text(9.8_wp))
      call check(ctx, real_text(0.0_wp) == "0.0", "0.0")
      call check(ctx, real_text(12.0_wp) == "12.0", "12.0 -> "//real_text(12.0_wp))
      call check(ctx, real_text(1.0e-10_wp) == "1.0e-10", "1e-10 -> "//real_text(1.0e-10_wp))
      call check(ctx, real_text(-0.25_wp) == "-0.25", "-0.25 -> "//real_text(-0.25_wp))
   end subroutine real_text_round_trip

   !> The namelist lines of `scene_namelist`, read back as a scene, give the same scene.
   subroutine namelist_round_trip(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(coefficient_task_t) :: c
      type(scene_t) :: first, second
      type(error_t), allocatable :: error
      character(len=:), allocatable :: path, lines(:), header(:)
      call read_text_scene("nml1", [ &
         padded("&scene task='coefficient', model='elastic', method='segments', n_segments=7, sampling='midpoint',"), &
         padded("  tolerance=3e-9, epsilon=0.3, output='build/it''s' /"), &
         padded("&coefficient alphas = 0.1, 9.8696, beta = -1.5, n_tau = 11, tau_min = -1, tau_max = 4.25 /")], &
         first, error, path)
      call check(ctx, .not. allocated(error), "first read")
      if (allocated(error)) return
      lines = scene_namelist(first)
      ! as in an output header: '#' comment lines around the namelist lines
      allocate (character(len=len(lines) + 2) :: header(4))
      header(1) = "# hillstab header"
      header(2) = "# "//lines(1)
      header(3) = "# "//lines(2)
      header(4) = "# columns: tau"
      call read_text_scene("nml2", header, second, error, path)
      call check(ctx, .not. allocated(error), "second read")
      if (allocated(error)) then
         call check(ctx, .false., error%message)
         return
      end if
      call check(ctx, second%task%name == first%task%name .and. second%model%name() == first%model%name(), "task, model")
      call check(ctx, second%method%kind == first%method%kind .and. second%method%n_segments == 7 .and. &
                 second%method%sampling == first%method%sampling, "method")
      call check(ctx, second%method%tolerance, first%method%tolerance, rel=0.0_wp, abs=0.0_wp)
      call check(ctx, second%epsilon, first%epsilon, rel=0.0_wp, abs=0.0_wp)
      call check(ctx, second%output == "build/it's", "quote in output: "//second%output)
      c = coefficient_of(second)
      call check(ctx, size(c%alphas) == 2, "alphas")
      if (size(c%alphas) == 2) call check(ctx, c%alphas(2), 9.8696_wp, rel=0.0_wp, abs=0.0_wp)
      call check(ctx, c%beta, -1.5_wp, rel=0.0_wp, abs=0.0_wp)
      call check(ctx, c%tau_max, 4.25_wp, rel=0.0_wp, abs=0.0_wp)
      call check(ctx, c%n_tau == 11, "n_tau")
   end subroutine namelist_round_trip

   subroutine bad_input_messages(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(bad_case_t), allocatable :: cases(:)
      type(scene_t) :: scene
      type(error_t), allocatable :: error
      character(len=:), allocatable :: path, dir, text
      integer :: k
      dir = scratch_prefix("badpts")
      call write_bad_points_files(dir)
      cases = bad_cases()
      do k = 1, size(cases)
         text = bad_case_text(cases(k), "build/unused", dir)
         call read_text_scene("bad", [text], scene, error, path)
         call check(ctx, allocated(error), "no error for: "//text)
         if (.not. allocated(error)) cycle
         call check(ctx, error%code == err_input, "input error code: "//text)
         call check(ctx, contains_text(error%message, path//": "), "names the file: "//error%message)
         call check(ctx, contains_text(error%message, "&"//trim(cases(k)%group)//":"), &
                    "names the group "//trim(cases(k)%group)//": "//error%message)
         call check(ctx, contains_text(error%message, trim(cases(k)%variable)), &
                    "names "//trim(cases(k)%variable)//": "//error%message)
      end do
      call delete_bad_points_files(dir)
      ! the Mathieu model takes any finite nu: alpha_max = 12 is fine there
      call read_text_scene("mathieu", [ padded("&scene model='mathieu' /"), &
                                       padded("&chart alpha_max = 12 /")], scene, error, path)
      call check(ctx, .not. allocated(error), "mathieu accepts alpha >= pi**2")
   end subroutine bad_input_messages

   subroutine missing_scene_file(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(scene_t) :: scene
      type(error_t), allocatable :: error
      call read_scene("build/no_such_scene.nml", scene, error)
      call check(ctx, allocated(error), "missing scene file is an error")
      if (.not. allocated(error)) return
      call check(ctx, contains_text(error%message, "build/no_such_scene.nml"), "names the file: "//error%message)
   end subroutine missing_scene_file
   !> What a namelist read would take otherwise than written is refused, naming group and
   !> variable: a second `&scene` (ignored), `output = 12` unquoted (read as text), a
   !> quoted string across a line break (the break dropped). A `&series` named in prose
   !> (an output header's) is no second group.
   subroutine read_as_written(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(scene_t) :: scene
      type(error_t), allocatable :: error
      character(len=:), allocatable :: path
      type(coefficient_task_t) :: coefficient
      path = scratch_prefix("as_written")//".nml"
      call write_file(path, [padded("&scene task = 'chart' /"), padded("&scene task = 'points' /"), &
                             padded("&chart /")])
      call read_scene(path, scene, error)
      call check(ctx, allocated(error), "a second &scene refused")
      if (allocated(error)) call check(ctx, contains_text(error%message, path//": &scene: the group is given 2 "// &
         "times"), "says so: "//error%message)
      call write_file(path, [padded("&scene output = 12 /"), padded("&chart /")])
      call read_scene(path, scene, error)
      call check(ctx, allocated(error), "output = 12 refused")
      if (allocated(error)) call check(ctx, contains_text(error%message, path//": &scene: output: must be quoted"), &
         "names &scene output: "//error%message)
      call write_file(path, [padded("&scene output = 'out/a"), padded("b' /"), padded("&chart /")])
      call read_scene(path, scene, error)
      call check(ctx, allocated(error), "a string across lines refused")
      if (allocated(error)) call check(ctx, contains_text(error%message, path//": &scene: output: a quoted "// &
         "string runs on"), "names &scene output: "//error%message)
      call write_file(path, [padded("! the pendulum of &series, a chart of &chart"), padded("&scene /"), &
                             padded("&chart n_alpha = 2, n_beta = 2 /")])
      call read_scene(path, scene, error)
      call check(ctx, .not. allocated(error), "groups named in comments are no groups")
      ! elements given one by one and a list over several lines are no repeats
      call write_file(path, [padded("&scene task = 'coefficient' /"), padded("&coefficient alphas(1) = 4, "// &
                             "alphas(2) = 6,"), padded("   beta = 1.5 /")])
      call read_scene(path, scene, error)
      call check(ctx, .not. allocated(error), "alphas(1), alphas(2) accepted")
      if (.not. allocated(error)) then
         coefficient = coefficient_of(scene)
         call check(ctx, size(coefficient%alphas) == 2, "two alphas")
         if (size(coefficient%alphas) == 2) call check(ctx, coefficient%alphas(2), 6.0_wp, rel=0.0_wp, abs=0.0_wp)
      end if
      call write_file(path, [padded("&scene model = 'system' /"), padded("&system n = 2, mass = 1, 0,"), &
                             padded("   0, 0.25, cos = 1, 0,"), padded("   0, 1 /"), padded("&chart /")])
      call read_scene(path, scene, error)
      call check(ctx, .not. allocated(error), "a system's lists over several lines accepted")
      ! a second group after another's '/' on the same line
      call write_file(path, [padded("&scene / &chart n_alpha = 2 / &chart n_alpha = 3 /")])
      call read_scene(path, scene, error)
      call check(ctx, allocated(error), "a second &chart on one line refused")
      if (allocated(error)) call check(ctx, contains_text(error%message, path//": &chart: the group is given 2 "// &
         "times"), "says so: "//error%message)
      call delete_file(path)
   end subroutine read_as_written

   !> A FIFO without a writer (which would block a read forever) and a device, as the
   !> scene or as the points file: refused at once (exit 2) naming the file, nothing read.
   subroutine special_files_refused(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(scene_t) :: scene
      type(error_t), allocatable :: error
      character(len=:), allocatable :: fifo, path
      integer :: status
      fifo = scratch_prefix("fifo")
      call execute_command_line("rm -f '"//fifo//"'; mkfifo '"//fifo//"'", exitstat=status)
      call check(ctx, status == 0, "FIFO made")
      if (status /= 0) return
      call read_scene(fifo, scene, error)
      call check(ctx, allocated(error), "a FIFO as the scene is refused")
      if (allocated(error)) call check(ctx, error%code == err_input .and. contains_text(error%message, &
         fifo//": cannot read the scene file: it is not a regular file"), "names it: "//error%message)
      call read_scene("/dev/zero", scene, error)
      call check(ctx, allocated(error), "/dev/zero as the scene is refused")
      path = scratch_prefix("fifo_points")//".nml"
      call write_file(path, [padded("&scene task = 'points' /"), padded("&points file = '"//fifo//"' /")])
      call read_scene(path, scene, error)
      call check(ctx, allocated(error), "a FIFO as the points file is refused")
      if (allocated(error)) call check(ctx, contains_text(error%message, path//": &points: file: '"//fifo// &
         "' is not a regular file"), "names &points file: "//error%message)
      call delete_file(path)
      call execute_command_line("rm -f '"//fifo//"'")
   end subroutine special_files_refused

   !> Scene files a careless or hostile user may give: an endless line (as /dev/zero),
   !> no final newline, a string longer than the strings read, a points file with extra
   !> columns; a points file with a long line.
   subroutine hostile_scene_files(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(chart_grid_t) :: grid
      real(wp), allocatable :: pairs(:, :)
      type(scene_t) :: scene
      type(error_t), allocatable :: error
      character(len=:), allocatable :: path, points
      integer :: unit
      path = scratch_prefix("hostile")//".nml"
      ! one line longer than max_line_length
      open (newunit=unit, file=path, status="replace", action="write", access="stream")
      write (unit) "&scene output='x' / "//repeat(" ", max_line_length)//new_line("a")
      close (unit)
      call read_scene(path, scene, error)
      call check(ctx, allocated(error), "a line longer than the limit is refused")
      if (allocated(error)) call check(ctx, contains_text(error%message, path//": line 1 is longer than"), &
                                       "names file and line: "//error%message)
      ! no final newline
      open (newunit=unit, file=path, status="replace", action="write", access="stream")
      write (unit) "&scene method='formula' /"//new_line("a")//"&chart n_alpha = 3 /"
      close (unit)
      call read_scene(path, scene, error)
      call check(ctx, .not. allocated(error), "no final newline is accepted")
      if (.not. allocated(error)) then
         grid = grid_of(scene)
         call check(ctx, grid%n_alpha == 3, "the last line is read")
      end if
      ! a string longer than 4096 characters
      call write_file(path, ["&scene output='"//repeat("o", 5000)//"' /", "&chart /"//repeat(" ", 5010)])
      call read_scene(path, scene, error)
      call check(ctx, allocated(error), "a 5000-character output is refused")
      if (allocated(error)) call check(ctx, contains_text(error%message, ": &scene: output: value longer than 4096"), &
                                       "names the limit: "//error%message)
      ! extra columns in a points file are ignored; a very long points line is refused
      points = scratch_prefix("hostile")//"_pts.dat"
      call write_file(points, [character(len=40) :: "1.5 2.5 0 1 note", "  2 3", "1e-1	4.0"])
      call write_file(path, [padded("&scene task='points', method='formula' /"), padded("&points file='"//points//"' /")])
      call read_scene(path, scene, error)
      call check(ctx, .not. allocated(error), "extra columns accepted")
      if (.not. allocated(error)) then
         pairs = points_of(scene)
         call check(ctx, size(pairs, 2) == 3, "three points")
         if (size(pairs, 2) == 3) then
            call check(ctx, pairs(1, 1) == 1.5_wp .and. pairs(2, 1) == 2.5_wp, "first point")
            call check(ctx, pairs(1, 3) == 0.1_wp .and. pairs(2, 3) == 4.0_wp, "tab separated")
         end if
      end if
      open (newunit=unit, file=points, status="replace", action="write", access="stream")
      write (unit) "1 2"//new_line("a")//repeat("3", max_line_length + 10)//new_line("a")
      close (unit)
      call read_scene(path, scene, error)
      call check(ctx, allocated(error), "a long points line is refused")
      if (allocated(error)) call check(ctx, contains_text(error%message, "line 2: longer than"), &
                                       "names the line: "//error%message)
      call delete_file(points)
      call delete_file(path)
   end subroutine hostile_scene_files

   !> Every group of every task is declared once: its template reads back (so each group's
   !> namelist statement lists the declared variables in the declared order — the reader
   !> checks the values the namelist writes back against the declaration), and the
   !> effective scene names exactly the declared variables of each group it writes.
   subroutine groups_declared_once(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=:), allocatable :: names(:), text, path, lines(:), points
      class(task_t), allocatable :: task
      type(group_t), allocatable :: groups(:)
      type(scene_t) :: scene
      type(error_t), allocatable :: error
      integer :: k, g, v
      names = task_names()
      do k = 1, size(names)
         call scene_template(trim(names(k)), text, error)
         call check(ctx, .not. allocated(error), trim(names(k))//": a template")
         if (allocated(error)) cycle
         path = scratch_prefix("declared_"//trim(names(k)))//".nml"
         points = path//".dat"
         call write_file(points, ["1.0 2.0"])
         call write_file(path, [replaced_text(text, "'points.dat'", "'"//points//"'")])
         call read_scene(path, scene, error)
         call delete_file(path)
         call delete_file(points)
         call check(ctx, .not. allocated(error), trim(names(k))//": the template reads")
         if (allocated(error)) then
            call check(ctx, .false., error%message)
            cycle
         end if
         call new_task(trim(names(k)), task, error)
         groups = task%declarations()
         lines = scene_namelist(scene)
         do g = 1, size(groups)
            ! the task's groups follow &scene in the effective scene
            call check(ctx, index(lines(1 + g), "&"//groups(g)%name//" ") == 1 .or. &
               lines(1 + g) == "&"//groups(g)%name//" /", trim(names(k))//": group "//groups(g)%name// &
               " in the effective scene: "//trim(lines(1 + g)))
            do v = 1, size(groups(g)%variables)
               associate (name => groups(g)%variables(v)%name)
                  if (len(groups(g)%variables(v)%default) == 0 .and. .not. groups(g)%variables(v)%required) cycle
                  call check(ctx, index(lines(1 + g), " "//name//" = ") > 0, trim(names(k))//": &"// &
                     groups(g)%name//" writes "//name)
               end associate
            end do
         end do
      end do
   end subroutine groups_declared_once

   !> The start angle of the pendulum tasks in degrees: `&series phi0_degrees = 1` is
   !> 1° = π/180 rad (not 1 rad = 57.3°); the effective scene repeats it in degrees (and
   !> reads back to the same angle); phi0 alone stays radians.
   subroutine start_angle_in_degrees(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(scene_t) :: scene, again
      type(error_t), allocatable :: error
      character(len=:), allocatable :: path, lines(:), header(:)
      integer :: k
      call read_text_scene("degrees", [padded("&scene task = 'series' /"), &
         padded("&series phi0_degrees = 1, periods = 2 /")], scene, error, path)
      call check(ctx, .not. allocated(error), "phi0_degrees reads")
      if (allocated(error)) return
      call check(ctx, series_phi0(scene), 0.017453292519943295_wp, rel=1.0e-15_wp, abs=0.0_wp)
      lines = scene_namelist(scene)
      call check(ctx, contains_text(lines(2), "phi0_degrees = 1.0") .and. .not. contains_text(lines(2), " phi0 = "), &
         "the effective scene gives the angle in degrees: "//trim(lines(2)))
      allocate (character(len=len(lines) + 2) :: header(size(lines)))
      do k = 1, size(lines)
         header(k) = "# "//lines(k)
      end do
      call read_text_scene("degrees_again", header, again, error, path)
      call check(ctx, .not. allocated(error), "the effective scene reads back")
      if (.not. allocated(error)) call check(ctx, series_phi0(again), series_phi0(scene), rel=0.0_wp, abs=0.0_wp)
      ! radians as before, and the lyapunov task reads the same group
      call read_text_scene("radians", [padded("&scene task = 'series' /"), padded("&series phi0 = 1 /")], &
         scene, error, path)
      if (.not. allocated(error)) call check(ctx, series_phi0(scene), 1.0_wp)
      call read_text_scene("degrees_lyapunov", [padded("&scene task = 'lyapunov' /"), &
         padded("&series phi0_degrees = -2.5, periods = 2 /"), padded("&chart n_alpha = 2, n_beta = 2 /")], &
         scene, error, path)
      call check(ctx, .not. allocated(error), "lyapunov reads phi0_degrees")
      if (.not. allocated(error)) call check(ctx, series_phi0(scene), -2.5_wp*0.017453292519943295_wp, rel=1.0e-15_wp)
   end subroutine start_angle_in_degrees

   !> φ0 [rad] of a series or lyapunov scene.
   real(wp) function series_phi0(scene)
      type(scene_t), intent(in) :: scene
      series_phi0 = huge(1.0_wp)
      select type (task => scene%task)
      type is (series_task_t)
         series_phi0 = task%plan%phi0
      type is (lyapunov_task_t)
         series_phi0 = task%series%phi0
      end select
   end function series_phi0

   !> A group the task does not read runs with a warning naming the file and the group,
   !> for every task alike: another task's group (which tasks read it), a misspelt one (no
   !> task does). The shipped scenes read without a warning.
   subroutine foreign_groups_warned(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(scene_t) :: scene
      type(error_t), allocatable :: error
      character(len=:), allocatable :: path, names(:)
      character(len=*), parameter :: shipped(*) = [character(len=24) :: "default_exact", "fig4_points", "damped", &
         "spring_physical", "spring_boundaries", "spring_series", "spring_chart", "fig4e", "boundaries_exact", &
         "lyapunov_map", "lyapunov_fig4", "poincare_regular", "fig2_coefficient", "figA_mathieu_exact"]
      integer :: k
      call read_text_scene("foreign", [padded("&scene task = 'chart' /"), padded("&chart n_alpha = 2, n_beta = 2 /"), &
         padded("&series phi0 = 1 /")], scene, error, path)
      call check(ctx, .not. allocated(error), "a chart scene with &series runs")
      if (allocated(error)) return
      call check(ctx, contains_text(scene%warnings, path//": &series: ignored: task 'chart' reads &scene, &chart; "// &
         "tasks series, lyapunov, poincare read it"), "the chart warns of &series: "//scene%warnings)
      call read_text_scene("misspelt", [padded("&scene task = 'series' /"), padded("&serie periods = 2 /"), &
         padded("&series periods = 3 /")], scene, error, path)
      call check(ctx, .not. allocated(error), "a series scene with &serie runs")
      if (allocated(error)) return
      call check(ctx, contains_text(scene%warnings, path//": &serie: ignored: task 'series' reads &scene, &series; "// &
         "no task reads a group of that name"), "the misspelt group is named: "//scene%warnings)
      call check(ctx, .not. contains_text(scene%warnings, "&series:"), "not the group it reads: "//scene%warnings)
      ! every task: a group it does not read, here &coefficient (read by task coefficient only)
      names = task_names()
      do k = 1, size(names)
         if (trim(names(k)) == "coefficient") cycle
         call read_template_with(trim(names(k)), "&coefficient n_tau = 3 /", scene, error)
         call check(ctx, .not. allocated(error), trim(names(k))//": the template with &coefficient reads")
         if (allocated(error)) then
            call check(ctx, .false., error%message)
            cycle
         end if
         call check(ctx, contains_text(scene%warnings, ": &coefficient: ignored: task '"//trim(names(k))// &
            "' reads &scene") .and. contains_text(scene%warnings, "task coefficient reads it"), &
            trim(names(k))//" warns of &coefficient: "//scene%warnings)
         call read_template_with(trim(names(k)), "", scene, error)
         if (.not. allocated(error)) call check(ctx, len(scene%warnings) == 0, trim(names(k))// &
            ": its own template reads without a warning: "//scene%warnings)
      end do
      do k = 1, size(shipped)
         call read_scene("data/scenes/"//trim(shipped(k))//".nml", scene, error)
         call check(ctx, .not. allocated(error), trim(shipped(k))//" reads")
         if (.not. allocated(error)) call check(ctx, len(scene%warnings) == 0, trim(shipped(k))// &
            " reads without a warning: "//scene%warnings)
      end do
   end subroutine foreign_groups_warned

   !> Read the template of a task with one more line.
   subroutine read_template_with(task, line, scene, error)
      character(len=*), intent(in) :: task, line
      type(scene_t), intent(out) :: scene
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: text, path, points
      call scene_template(task, text, error)
      if (allocated(error)) return
      path = scratch_prefix("with_"//task)//".nml"
      points = path//".dat"
      call write_file(points, ["1.0 2.0"])
      call write_file(path, [replaced_text(text, "'points.dat'", "'"//points//"'")//achar(10)//line])
      call read_scene(path, scene, error)
      call delete_file(path)
      call delete_file(points)
   end subroutine read_template_with

   !> A spring in the wrong units runs, with a warning naming the variable: longer than
   !> 100 m (r0 of &physical or &series, or ρ = r0 + g/ω² through a tiny ω), ω below 1e-3
   !> rad/s. A lab spring (k = 40 N/m, m = 0.5 kg, r0 = 0.25 m), and the same one in
   !> centimetres (r0 = 25 m, short of the limit: its header shows ρ = 25.1 m), do not warn.
   subroutine implausible_spring_warned(ctx)
      type(test_context_t), intent(inout) :: ctx
      character(len=*), parameter :: points = "&scene task = 'points' /"
      call expect(points, "&physical k = 40, m = 0.5, g = 9.81, r0 = 0.25, a = 0.02 /", "")
      call expect(points, "&physical k = 40, m = 0.5, g = 9.81, r0 = 25, a = 2 /", "")
      call expect(points, "&physical k = 40, m = 0.5, g = 9.81, r0 = 250, a = 2 /", &
         "&physical: r0: a spring longer than 100.0 m: r0 = 250.0 m, rho = r0 + g/omega^2 = 250.122625 m")
      ! m in grams: omega = 0.28 rad/s, rho = 0.25 + 9.81/0.08 = 122.875 m
      call expect(points, "&physical k = 40, m = 500, g = 9.81, r0 = 0.25, a = 0.02 /", &
         "&physical: k: a spring longer than 100.0 m: r0 = 0.25 m, rho = r0 + g/omega^2 = 122.875 m")
      call expect("&scene task = 'chart' /", "&physical omega = 5e-4, g = 9.81 / &chart n_alpha = 2, n_beta = 2 /", &
         "&physical: omega: omega = 0.0005 rad/s is below 0.001 rad/s")
      call expect("&scene task = 'chart' /", "&physical omega_min = 2e-4, omega_max = 5, n_omega = 3, r0 = 0.3, "// &
         "a_min = 0, a_max = 0.1, n_a = 2 /", "&physical: omega_min: omega = 0.0002 rad/s is below 0.001 rad/s")
      ! &series: rho = r0/(1 - beta/pi^2)
      call expect("&scene task = 'series' /", "&series r0 = 150, periods = 1 /", "&series: r0: a spring longer "// &
         "than 100.0 m: r0 = 150.0 m, rho = r0/(1 - beta/pi^2) = "//real_text(150.0_wp/(1.0_wp - 2.47_wp/pi2)))
      call expect("&scene task = 'series' /", "&series r0 = 0.25, periods = 1 /", "")
   contains
      subroutine expect(first, second, warning)
         character(len=*), intent(in) :: first, second, warning
         type(scene_t) :: scene
         type(error_t), allocatable :: error
         character(len=:), allocatable :: path
         call read_text_scene("units", [padded(first), padded(second)], scene, error, path)
         call check(ctx, .not. allocated(error), "runs: "//second)
         if (allocated(error)) then
            call check(ctx, .false., error%message)
            return
         end if
         if (len(warning) == 0) then
            call check(ctx, len(scene%warnings) == 0, "no warning for "//second//": "//scene%warnings)
         else
            call check(ctx, contains_text(scene%warnings, path//": "//warning), "warns for "//second//": "// &
               scene%warnings)
         end if
      end subroutine expect
   end subroutine implausible_spring_warned

   function replaced_text(text, old, new) result(out)
      character(len=*), intent(in) :: text, old, new
      character(len=:), allocatable :: out
      integer :: at
      out = text
      at = index(out, old)
      if (at > 0) out = out(:at - 1)//new//out(at + len(old):)
   end function replaced_text
   !> A grid whose ends reach the largest double (a fuzzed a_max = 1.797e308 trapped in
   !> `grid_value` in a debug build, before the reader could refuse it): finite, ascending,
   !> its ends exact; an ordinary grid's values unchanged (the same expression, to the bit).
   subroutine grid_near_the_largest_double(ctx)
      type(test_context_t), intent(inout) :: ctx
      real(wp) :: v(151)
      integer :: i
      v = [(grid_value(0.0_wp, huge(1.0_wp), 151, i), i=1, 151)]
      call check(ctx, v(1) == 0.0_wp .and. v(151) == huge(1.0_wp), "the ends exact")
      call check(ctx, all(v(2:) > v(:150)), "ascending, all finite")
      v(1:3) = [(grid_value(-huge(1.0_wp), huge(1.0_wp), 3, i), i=1, 3)]
      call check(ctx, v(2) == 0.0_wp, "the middle of (-huge, huge) is 0")
      call check(ctx, grid_value(-2.0_wp, 12.0_wp, 200, 57) == -2.0_wp + 14.0_wp*56.0_wp/199.0_wp, &
                 "an ordinary grid to the bit")
   end subroutine grid_near_the_largest_double

   !> A log axis: n geometric values from min to max, both ends exact, a constant ratio
   !> (to round-off), ascending; decades that the spacing hits are the powers of ten; one
   !> value is min; `grid_point` and `grid_alpha`, `grid_beta` agree; linear unchanged.
   subroutine log_grid_values(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(chart_grid_t) :: grid
      real(wp) :: v(7), w(50), ratio
      integer :: i
      v = [(grid_value(1.0e-3_wp, 1.0e3_wp, 7, i, geometric=.true.), i=1, 7)]
      call check(ctx, v(1) == 1.0e-3_wp .and. v(7) == 1.0e3_wp, "the ends exact")
      do i = 2, 6
         call check(ctx, v(i), 10.0_wp**(i - 4), rel=2.0_wp*epsilon(1.0_wp), abs=0.0_wp)
      end do
      call check(ctx, v(4) == 1.0_wp .and. v(5) == 10.0_wp, "decades exact: "//real_text(v(4))//", "//real_text(v(5)))
      w = [(grid_value(0.3_wp, 9.7_wp, 50, i, geometric=.true.), i=1, 50)]
      call check(ctx, w(1) == 0.3_wp .and. w(50) == 9.7_wp, "the ends exact (no decades)")
      call check(ctx, all(w(2:) > w(:49)), "ascending")
      ratio = (9.7_wp/0.3_wp)**(1.0_wp/49.0_wp)
      call check(ctx, maxval(abs(w(2:)/w(:49) - ratio)) < 1.0e-13_wp, "geometric: a constant ratio")
      call check(ctx, grid_value(2.0_wp, 8.0_wp, 1, 1, geometric=.true.) == 2.0_wp, "n = 1: min")
      call check(ctx, grid_value(2.0_wp, 8.0_wp, 3, 2, geometric=.true.), 4.0_wp, rel=2.0_wp*epsilon(1.0_wp), abs=0.0_wp)
      grid = chart_grid_t(0.5_wp, 8.0_wp, 5, -2.0_wp, 12.0_wp, 8, scale_log, scale_linear)
      call check(ctx, grid_alpha(grid, 3) == grid_value(0.5_wp, 8.0_wp, 5, 3, geometric=.true.), "grid_alpha: log")
      call check(ctx, grid_beta(grid, 4) == grid_value(-2.0_wp, 12.0_wp, 8, 4), "grid_beta: linear")
      call check(ctx, all(grid_point(grid, 19_int64) == [grid_alpha(grid, 3), grid_beta(grid, 3)]), "grid_point")
      call check(ctx, grid_value(-2.0_wp, 12.0_wp, 200, 57, geometric=.false.) == -2.0_wp + 14.0_wp*56.0_wp/199.0_wp, &
                 "linear to the bit")
   end subroutine log_grid_values

   !> `alpha_scale`, `beta_scale` read (any case) into the grid; the effective scene names a
   !> log scale and leaves 'linear' out (a scene that names it writes the header of one that
   !> does not); read back, the effective scene gives the same grid.
   subroutine log_grid_read_and_echoed(ctx)
      type(test_context_t), intent(inout) :: ctx
      type(scene_t) :: scene, again
      type(error_t), allocatable :: error
      character(len=:), allocatable :: path, lines(:), plain(:)
      type(chart_grid_t) :: grid
      call read_text_scene("logscale", [padded("&scene /"), padded("&chart alpha_min = 0.1, alpha_scale = 'Log', "// &
         "beta_min = 1, beta_max = 100, beta_scale = 'linear' /")], scene, error, path)
      call check(ctx, .not. allocated(error), "read")
      if (allocated(error)) return
      grid = grid_of(scene)
      call check(ctx, grid%alpha_scale == scale_log .and. grid%beta_scale == scale_linear, "the scales")
      lines = scene_namelist(scene)
      call check(ctx, any(index(lines, "alpha_scale = 'log'") > 0), "alpha_scale = 'log' echoed")
      call check(ctx, .not. any(index(lines, "beta_scale") > 0), "beta_scale = 'linear' not echoed")
      call read_text_scene("logscale_again", lines, again, error, path)
      call check(ctx, .not. allocated(error), "the effective scene reads")
      if (allocated(error)) return
      grid = grid_of(again)
      call check(ctx, grid%alpha_scale == scale_log, "read back: log")
      call check(ctx, grid%alpha_min == 0.1_wp .and. grid%beta_max == 100.0_wp, "read back: the ends")
      call read_text_scene("logscale_plain", [padded("&scene /"), padded("&chart alpha_min = 0.1, beta_min = 1, "// &
         "beta_max = 100 /")], scene, error, path)
      call check(ctx, .not. allocated(error), "read")
      if (allocated(error)) return
      plain = scene_namelist(scene)
      call read_text_scene("logscale_plain", [padded("&scene /"), padded("&chart alpha_min = 0.1, beta_min = 1, "// &
         "beta_max = 100, alpha_scale = 'linear', beta_scale = 'LINEAR' /")], scene, error, path)
      call check(ctx, .not. allocated(error), "read")
      if (allocated(error)) return
      lines = scene_namelist(scene)
      call check(ctx, size(lines) == size(plain), "as many lines")
      if (size(lines) == size(plain)) call check(ctx, all(lines == plain), "'linear' named: the same effective scene")
   end subroutine log_grid_read_and_echoed
end module test_scene

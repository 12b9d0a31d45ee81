!> Commented scene templates: `hillstab --template TASK` prints a complete scene for a
!> task, every variable at its default with a comment saying what it means, so the
!> installed program documents its own input. The values come from `default_scene`,
!> so a template cannot drift from the defaults; the tests read every template back
!> and check that it names every variable of the task's effective scene.
!>
!> Adding a task: write a function returning its group (as `chart_group` below), add
!> its name to `template_task_names` and a `case` to `scene_template`.
!>
!>```fortran
!> character(len=:), allocatable :: text
!> type(error_t), allocatable :: error
!> call scene_template("chart", text, error)
!> if (.not. allocated(error)) write (*, '(a)') text
!>```
module hillstab_batch_templates
   use hillstab_core_error, only: error_t, set_error, err_input
   use hillstab_hill_coefficient, only: model_name, sampling_name
   use hillstab_integrate_monodromy, only: method_name
   use hillstab_hill_units, only: physical_t
   use hillstab_batch_scene, only: scene_t, default_scene, real_text, integer_text, task_chart, task_points, &
      task_coefficient, task_boundaries, task_series, task_lyapunov, task_poincare
   implicit none
   private
   public :: template_task_names, scene_template

   !> Line break inside a template text.
   character(len=*), parameter :: nl = new_line("a")
   !> Column at which the comments of the variables start.
   integer, parameter :: comment_column = 28
   !> Longest line of a template (longer comments are wrapped).
   integer, parameter :: line_width = 100

contains

   !> The tasks that have a template, in the order `--help` lists them.
   function template_task_names() result(names)
      character(len=:), allocatable :: names(:)  !! task names, blank-padded to a common length
      names = [character(len=11) :: "chart", "points", "coefficient", "boundaries", "series", "lyapunov", "poincare"]
   end function template_task_names

   !> The complete commented scene of `task` (lines separated by new_line('a'), no final
   !> newline); an `err_input` error naming the known tasks when there is no such template.
   subroutine scene_template(task, text, error)
      character(len=*), intent(in) :: task                  !! a task name, e.g. "chart"
      character(len=:), allocatable, intent(out) :: text    !! the scene
      type(error_t), allocatable, intent(out) :: error      !! unknown task
      type(scene_t) :: scene
      scene = default_scene(task//".nml")
      select case (task)
      case ("chart")
         scene%task = task_chart
         text = header(task, "a stability chart over an (alpha, beta) grid: S, stability, multipliers, exponent") &
                //scene_group(scene, task)//nl//chart_group(scene)//nl//nl//physical_group("")
      case ("points")
         scene%task = task_points
         text = header(task, "the chart's columns at (alpha, beta) points listed in a file") &
                //scene_group(scene, task)//nl//points_group()//nl//nl//physical_group("&points file")
      case ("coefficient")
         scene%task = task_coefficient
         text = header(task, "Q(tau) and its segmented version, one pair of columns per alpha (the paper's Fig. 2)") &
                //scene_group(scene, task)//nl//coefficient_group(scene)//nl//nl// &
                physical_group("&coefficient alphas and beta")
      case ("boundaries")
         scene%task = task_boundaries
         text = header(task, "transition curves S = +-2 over the alpha grid of &chart, within its beta window "// &
                "(exact methods: Hill's method; formula, segments: roots by Brent from n_beta samples)") &
                //scene_group(scene, task)//nl//chart_group(scene)//nl//nl//physical_group("")
      case ("series")
         scene%task = task_series
         text = header(task, "the nonlinear elastic pendulum from eq. (38), sampled from the dense output at "// &
                "t = j T/samples_per_period (tolerance: the integrator's relative tolerance; method: the core "// &
                "computing lambda_max)")//scene_group(scene, task)//nl//series_group(scene)
      case ("lyapunov")
         scene = default_scene(task//".nml", task_lyapunov)
         text = header(task, "the largest Lyapunov exponent of the nonlinear pendulum (per radial period) over "// &
                "the grid of &chart or the points of &points, beside the chart's linear verdict (tolerance: the "// &
                "integrator's relative tolerance; method: the core computing lambda_max)") &
                //scene_group(scene, task)//nl//series_group(scene)//nl//lyapunov_group()//nl//chart_group(scene)// &
                nl//"! with over = 'points': the points of a file instead of the grid"//nl//"! &points"//nl// &
                commented_item("file = 'points.dat'", "one 'alpha beta' pair per line, 0 < beta < pi^2")//"! /"
      case ("poincare")
         scene%task = task_poincare
         text = header(task, "Poincare sections (phi = 0, phi' > 0: r, r') of orbits started at rest at each "// &
                "angle of &poincare phi0s, at the (alpha, beta, r0, g) of &series, over &series periods") &
                //scene_group(scene, task)//nl//series_group(scene)//nl//poincare_group(scene)
      case default
         call set_error(error, err_input, "no template for task '"//task//"' (tasks: "// &
            joined(template_task_names(), ", ")//")")
         text = ""
      end select
   end subroutine scene_template

   !> The trimmed `names` separated by `separator`.
   function joined(names, separator) result(text)
      character(len=*), intent(in) :: names(:), separator
      character(len=:), allocatable :: text
      integer :: k
      text = trim(names(1))
      do k = 2, size(names)
         text = text//separator//trim(names(k))
      end do
   end function joined

   !> Comment lines opening a template.
   function header(task, purpose) result(text)
      character(len=*), intent(in) :: task, purpose
      character(len=:), allocatable :: text
      text = wrapped("! ", "hillstab scene, task '"//task//"': "//purpose//".")// &
             "! Run: hillstab FILE.nml. Every variable is shown at its default; delete what you do not change."//nl// &
             "! '!' starts a comment; names and keyword values are case-insensitive; group order does not matter."//nl
   end function header

   !> `words` after `lead`, wrapped at word boundaries into lines of at most `line_width`
   !> characters, each continuation starting with `lead`; every line ends with a new line.
   function wrapped(lead, words) result(text)
      character(len=*), intent(in) :: lead, words
      character(len=:), allocatable :: text
      character(len=:), allocatable :: rest
      integer :: cut, room
      text = ""
      rest = words
      room = line_width - len(lead)
      do while (len(rest) > room)
         cut = index(rest(:room + 1), " ", back=.true.)
         if (cut <= 1) cut = room + 1
         text = text//lead//rest(:cut - 1)//nl
         rest = trim(adjustl(rest(cut:)))
      end do
      text = text//lead//rest//nl
   end function wrapped

   !> `name = value` followed by its comment at a fixed column, the comment wrapped at
   !> word boundaries onto continuation comment lines so that no line passes `line_width`.
   function item(assignment, comment) result(text)
      character(len=*), intent(in) :: assignment, comment
      character(len=:), allocatable :: text
      character(len=:), allocatable :: line, rest
      integer :: cut, room
      line = "  "//assignment
      if (len(line) < comment_column - 1) line = line//repeat(" ", comment_column - 1 - len(line))
      line = line//" ! "
      text = ""
      rest = comment
      do
         room = line_width - len(line)
         if (len(rest) <= room) exit
         cut = index(rest(:room + 1), " ", back=.true.)
         if (cut <= 1) cut = room + 1
         text = text//line//rest(:cut - 1)//nl
         rest = adjustl(rest(cut:))
         rest = trim(rest)
         line = repeat(" ", comment_column)//"!   "
      end do
      text = text//line//rest//nl
   end function item

   !> The `&scene` group, common to every task.
   function scene_group(scene, task) result(text)
      type(scene_t), intent(in) :: scene
      character(len=*), intent(in) :: task
      character(len=:), allocatable :: text
      text = "&scene"//nl// &
         item("task = '"//task//"'", joined(template_task_names(), " | "))// &
         item("model = '"//model_name(scene%model)//"'", &
              "elastic: Q = (beta - alpha cos pi tau)/(1 - (alpha/pi^2) cos pi tau), eq. (25) | "// &
              "mathieu: Q = beta - alpha cos pi tau")// &
         item("method = '"//method_name(scene%method%kind)//"'", &
              "auto (exact to tolerance, fastest) | formula (the paper's 2 pieces, eq. (37)) | segments | "// &
              "magnus4 | magnus6 | rk | gsl")// &
         item("n_segments = "//integer_text(scene%method%n_segments), &
              "method segments (and Qseg of task coefficient): pieces per period, at least 1")// &
         item("sampling = '"//sampling_name(scene%method%sampling)//"'", &
              "segments: endpoint (eq. (28)) | midpoint | average (exact mean of Q per piece)")// &
         item("tolerance = "//real_text(scene%method%tolerance), &
              "exact methods: target error on S, scaled by max(1, |S|); > 0")// &
         item("epsilon = "//real_text(scene%epsilon), "damping eps = kappa pi/omega of eqs. (46)-(47); >= 0")// &
         item("! output = 'run1'", &
              "prefix: files are <output>_<task>.dat, relative to the current directory; "// &
              "default: the scene file's name without directory and extension")
      if (task == "chart" .or. task == "points") then
         text = text// &
            item("columns = ''", "columns to write, e.g. 'alpha beta stable mu'; '' = all (see the # columns: line)")// &
            item("format = 'text'", "text | binary (float64 records after the # header, <output>_<task>.bin; "// &
                 "the header gives the gnuplot and numpy commands)")// &
            item("names_line = .false.", "text: .true. adds an uncommented line of column names after the "// &
                 "# header, for gnuplot using 'alpha':'mu'")
      end if
      text = text//"/"//nl
   end function scene_group

   !> `&chart`.
   function chart_group(scene) result(text)
      type(scene_t), intent(in) :: scene
      character(len=:), allocatable :: text
      text = "&chart                     ! n values from min to max inclusive (n = 1: min only)"//nl// &
         item("alpha_min = "//real_text(scene%chart%alpha_min), "first alpha = a pi^2/rho (elastic: 0 <= alpha < pi^2)")// &
         item("alpha_max = "//real_text(scene%chart%alpha_max), "last alpha, >= alpha_min")// &
         item("n_alpha = "//integer_text(scene%chart%n_alpha), "number of alpha values, >= 1")// &
         item("beta_min = "//real_text(scene%chart%beta_min), "first beta = g pi^2/(rho omega^2)")// &
         item("beta_max = "//real_text(scene%chart%beta_max), "last beta, >= beta_min")// &
         item("n_beta = "//integer_text(scene%chart%n_beta), "number of beta values, >= 1")// &
         "/"
   end function chart_group

   !> `&series`.
   function series_group(scene) result(text)
      type(scene_t), intent(in) :: scene
      character(len=:), allocatable :: text
      associate (plan => scene%series)
         text = "&series"//nl// &
            item("alpha = "//real_text(plan%alpha), "alpha = a pi^2/rho, 0 <= alpha < pi^2")// &
            item("beta = "//real_text(plan%beta), "beta = g pi^2/(rho omega^2), 0 < beta < pi^2 (physical domain)")// &
            item("phi0 = "//real_text(plan%phi0), "initial angle from the downward vertical, rad (0: pure bounce)")// &
            item("periods = "//integer_text(plan%periods), "radial periods T = 2 pi/omega to simulate, >= 1")// &
            item("samples_per_period = "//integer_text(plan%samples_per_period), &
                 "output rows per radial period, >= 1; periods*samples_per_period + 1 <= 1e8")// &
            item("r0 = "//real_text(plan%r0), "natural length of the spring, m; > 0")// &
            item("g = "//real_text(plan%g), "gravity, m/s^2; > 0")// &
            item("vx0 = "//real_text(plan%vx0), "initial horizontal velocity, m/s")// &
            item("vz0 = "//real_text(plan%vz0), "initial downward velocity, m/s")// &
            "/"
      end associate
   end function series_group

   !> `&lyapunov`.
   function lyapunov_group() result(text)
      character(len=:), allocatable :: text
      text = "&lyapunov"//nl// &
         item("over = 'chart'", "chart: the grid of &chart (0 < beta < pi^2) | points: the points of &points")// &
         "/"
   end function lyapunov_group

   !> `&poincare`.
   function poincare_group(scene) result(text)
      type(scene_t), intent(in) :: scene
      character(len=:), allocatable :: text
      integer :: k
      character(len=:), allocatable :: values
      values = real_text(scene%poincare%phi0s(1))
      do k = 2, size(scene%poincare%phi0s)
         values = values//", "//real_text(scene%poincare%phi0s(k))
      end do
      text = "&poincare"//nl// &
         item("phi0s = "//values, "initial angles of the orbits, rad, |phi0| < pi, up to 64 (one block each)")// &
         item("same_energy = "//merge(".true. ", ".false.", scene%poincare%same_energy), &
              ".true.: every orbit starts at rest with the energy of the &series start (one section plane) | "// &
              ".false.: each at r = rho - a, eq. (38)")// &
         "/"
   end function poincare_group

   !> `&points` (the file name is an example: the file must exist).
   function points_group() result(text)
      character(len=:), allocatable :: text
      text = "&points"//nl// &
         item("file = 'points.dat'", "required: one 'alpha beta' pair per line, '#' comments, extra columns "// &
              "ignored; relative to the current directory")// &
         "/"
   end function points_group

   !> `item` commented out: its first column becomes `!`.
   function commented_item(assignment, comment) result(text)
      character(len=*), intent(in) :: assignment, comment
      character(len=:), allocatable :: text
      text = item(assignment, comment)
      text(1:1) = "!"
   end function commented_item

   !> The optional `&physical` group, commented out (a scene gives either it or the
   !> dimensionless values). `replaces`: the variables of the task that `r0` with `a`
   !> replace ("" when the task takes no amplitudes).
   function physical_group(replaces) result(text)
      character(len=*), intent(in) :: replaces
      character(len=:), allocatable :: text
      type(physical_t) :: p
      logical :: amplitudes
      amplitudes = len(replaces) > 0
      text = "! Optional, instead of the dimensionless values: the pendulum in SI units (remove the '!'s"// &
         nl//"! to use it; then no &scene epsilon"
      if (amplitudes) text = text//", and r0 with a replace "//replaces
      text = text//")."//nl//"! &physical"//nl// &
         commented_item("omega = 10.0", "required: radial angular frequency sqrt(k/m), rad/s; > 0")// &
         commented_item("g = "//real_text(p%g), "gravity, m/s^2; >= 0")// &
         commented_item("kappa = "//real_text(p%kappa), "damping rate of eqs. (40)-(42), 1/s: gives epsilon = "// &
                   "kappa pi/omega")
      if (amplitudes) then
         text = text// &
            commented_item("r0 = 0.3", "natural length of the spring, m; > 0 (with a)")// &
            commented_item("a = 0.05, 0.1, 0.2", "bounce amplitudes, m, up to 64; 0 <= a < rho = r0 + g/omega^2")
      end if
      text = text//"! /"
   end function physical_group

   !> `&coefficient`.
   function coefficient_group(scene) result(text)
      type(scene_t), intent(in) :: scene
      character(len=:), allocatable :: text
      character(len=:), allocatable :: alphas
      integer :: k
      alphas = real_text(scene%coefficient%alphas(1))
      do k = 2, size(scene%coefficient%alphas)
         alphas = alphas//", "//real_text(scene%coefficient%alphas(k))
      end do
      text = "&coefficient"//nl// &
         item("alphas = "//alphas, "one curve per alpha, up to 64 values")// &
         item("beta = "//real_text(scene%coefficient%beta), "beta of every curve")// &
         item("tau_min = "//real_text(scene%coefficient%tau_min), "first tau")// &
         item("tau_max = "//real_text(scene%coefficient%tau_max), "last tau (one period is 2)")// &
         item("n_tau = "//integer_text(scene%coefficient%n_tau), "number of tau values, >= 1")// &
         "/"
   end function coefficient_group
end module hillstab_batch_templates

!> The table of bad scenes that the scene suite reads and the tasks suite runs: each must be
!> refused with a message naming the file, the group and the variable, and nothing written.
module hillstab_test_bad_scenes
   use hillstab_test_scratch, only: write_file, delete_file
   implicit none
   private
   public :: bad_case_t, bad_cases, bad_case_text, write_bad_points_files, delete_bad_points_files

   !> One bad scene: its text (`@OUT@` stands for the output prefix, `@DIR@` for the
   !> scratch prefix of the points files), the group and variable the message must name.
   type :: bad_case_t
      character(len=400) :: text
      character(len=16) :: group
      character(len=120) :: variable
   end type bad_case_t

contains

   !> Bad scenes: the tasks suite runs the same table to check that no file is touched.
   function bad_cases() result(cases)
      type(bad_case_t), allocatable :: cases(:)
      character(len=*), parameter :: s = "&scene output='@OUT@', method='segments' "
      character(len=*), parameter :: sp = "&scene output='@OUT@', method='segments', task='points' / "
      !> a system scene (no method: the scalar's segments would be refused)
      character(len=*), parameter :: y = "&scene output='@OUT@', model='system' "
      cases = [ &
         bad_case_t(s//"foo=3 / &chart /", "scene", "foo"), &
         bad_case_t(s//"/ &chart n_alpha='abc' /", "chart", "n_alpha"), &
         bad_case_t(s//"/ &chart n_beta=1.5 /", "chart", "n_beta"), &
         bad_case_t(s//"/ &chart alpha_min=x1 /", "chart", "alpha_min"), &
         bad_case_t(s//"epsilon='high' / &chart /", "scene", "epsilon"), &
         bad_case_t(s//"/", "chart", "missing"), &
         bad_case_t("&chart / ! no &scene group, @OUT@", "scene", "missing"), &
         bad_case_t(sp, "points", "missing"), &
         bad_case_t(s//"task='coefficient' / &chart /", "coefficient", "missing"), &
         bad_case_t(s//"task='chrt' / &chart /", "scene", "task"), &
         bad_case_t(s//"task='boundaries', epsilon=0.5 / &chart /", "scene", "epsilon"), &
         bad_case_t(s//"model='spring' / &chart /", "scene", "model"), &
         bad_case_t("&scene output='@OUT@', method='euler' / &chart /", "scene", "method"), &
         bad_case_t(s//"sampling='left' / &chart /", "scene", "sampling"), &
         bad_case_t(s//"/ &chart alpha_max=9.8696044010893586 /", "chart", "alpha_max"), &
         bad_case_t(s//"/ &chart alpha_max=12 /", "chart", "alpha_max"), &
         bad_case_t(s//"/ &chart alpha_min=-0.5 /", "chart", "alpha_min"), &
         bad_case_t(s//"task='coefficient' / &coefficient alphas=4, 10 /", "coefficient", "alphas"), &
         bad_case_t(s//"/ &chart n_alpha=0 /", "chart", "n_alpha"), &
         bad_case_t(s//"/ &chart n_beta=-3 /", "chart", "n_beta"), &
         bad_case_t(s//"n_segments=0 / &chart /", "scene", "n_segments"), &
         bad_case_t(s//"task='coefficient' / &coefficient n_tau=0 /", "coefficient", "n_tau"), &
         bad_case_t(s//"/ &chart alpha_min=5, alpha_max=3 /", "chart", "alpha_min"), &
         bad_case_t(s//"/ &chart beta_min=1, beta_max=0.5 /", "chart", "beta_min"), &
         bad_case_t(s//"task='coefficient' / &coefficient tau_min=2, tau_max=0 /", "coefficient", "tau_min"), &
         bad_case_t(s//"tolerance=-1e-8 / &chart /", "scene", "tolerance"), &
         bad_case_t(s//"tolerance=0 / &chart /", "scene", "tolerance"), &
         bad_case_t(s//"epsilon=-0.5 / &chart /", "scene", "epsilon"), &
         bad_case_t(s//"/ &chart beta_max=nan /", "chart", "beta_max"), &
         bad_case_t(s//"/ &chart alpha_min=inf /", "chart", "alpha_min"), &
         bad_case_t(s//"/ &chart beta_min=-1e400 /", "chart", "beta_min"), &
         bad_case_t(s//"/ &chart alpha_scale='log' /", "chart", "alpha_min: alpha_scale = 'log' needs alpha_min > 0"), &
         bad_case_t(s//"/ &chart alpha_min=1, beta_scale='log' /", "chart", "beta_min: beta_scale = 'log' needs"), &
         bad_case_t(s//"/ &chart alpha_scale='logarithmic' /", "chart", "alpha_scale: must be 'linear' or 'log'"), &
         bad_case_t(s//"/ &chart beta_scale='lin' /", "chart", "beta_scale"), &
         bad_case_t(s//"task='boundaries' / &chart beta_min=1, beta_scale='log' /", "chart", "beta_scale: task 'boundaries'"), &
         bad_case_t(s//"epsilon=nan / &chart /", "scene", "epsilon"), &
         bad_case_t(s//"tolerance=inf / &chart /", "scene", "tolerance"), &
         bad_case_t(s//"task='coefficient' / &coefficient alphas=4, nan /", "coefficient", "alphas"), &
         bad_case_t(s//"task='coefficient' / &coefficient beta=nan /", "coefficient", "beta"), &
         bad_case_t("&scene output='', method='segments' / &chart /", "scene", "output"), &
         bad_case_t(sp//"&points file='@DIR@_none.dat' /", "points", "file"), &
         bad_case_t(sp//"&points /", "points", "file"), &
         bad_case_t(sp//"&points file='@DIR@_badline.dat' /", "points", "file"), &
         bad_case_t(sp//"&points file='@DIR@_nan.dat' /", "points", "file"), &
         bad_case_t(sp//"&points file='@DIR@_domain.dat' /", "points", "file"), &
         bad_case_t(sp//"&points file='@DIR@_empty.dat' /", "points", "file"), &
         bad_case_t(s//"epsilon=1 / &chart / &physical omega=3, kappa=1 /", "physical", "epsilon"), &
         bad_case_t(sp//"&points file='@DIR@_none.dat' / &physical omega=3, r0=1, a=0.5 /", "points", "file"), &
         bad_case_t(sp//"&physical omega=3, r0=1, a=5 /", "physical", "a"), &
         bad_case_t(sp//"&physical r0=1, a=0.5 /", "physical", "omega"), &
         bad_case_t(sp//"&physical omega=3, a=0.5 /", "physical", "r0"), &
         bad_case_t(sp//"&physical omega=3, r0=0, a=0.5 /", "physical", "r0"), &
         bad_case_t(sp//"&physical omega=3, r0=1, a=0.5, kappa=-1 /", "physical", "kappa"), &
         bad_case_t(s//"/ &chart / &physical omega=3, r0=1, a=0.5 /", "physical", "a"), &
         bad_case_t(s//"/ &chart / &physical omega=-3 /", "physical", "omega"), &
         bad_case_t(s//"/ &chart / &physical omega=3, k=2 /", "physical", "k"), &
         bad_case_t(sp//"&physical omega=10, k=25, m=0.25, r0=0.3, a=0.1 /", "physical", "k: omega and k are both"), &
         bad_case_t(sp//"&physical k=0, m=0.25, r0=0.3, a=0.1 /", "physical", "k: the spring constant must be > 0"), &
         bad_case_t(sp//"&physical k=-25, m=0.25, r0=0.3, a=0.1 /", "physical", "k: the spring constant must be > 0"), &
         bad_case_t(sp//"&physical k=25, m=0, r0=0.3, a=0.1 /", "physical", "m: the mass must be > 0"), &
         bad_case_t(sp//"&physical k=25, m=-1, r0=0.3, a=0.1 /", "physical", "m: the mass must be > 0"), &
         bad_case_t(sp//"&physical k=25, m=nan, r0=0.3, a=0.1 /", "physical", "m: not a finite number"), &
         bad_case_t(sp//"&physical k=25, r0=0.3, a=0.1 /", "physical", "m: k (spring constant"), &
         bad_case_t(sp//"&physical m=0.25, r0=0.3, a=0.1 /", "physical", "k: k (spring constant"), &
         bad_case_t(sp//"&physical k=25, m=0.25, r0=0.3, a=0.3981 /", "physical", "a: the amplitude must satisfy"), &
         bad_case_t(sp//"&physical k=25, m=0.25, r0=0.3, a_min=0, a_max=0.4, n_a=3 /", "physical", &
                    "a_max: the amplitude must satisfy"), &
         bad_case_t(sp//"&physical k=25, m=0.25, r0=0.3, a_min=-0.1, a_max=0.2, n_a=3 /", "physical", &
                    "a_min: the amplitude must satisfy"), &
         bad_case_t(sp//"&physical k=25, m=0.25, r0=0.3, a_min=0.2, a_max=0.1, n_a=3 /", "physical", &
                    "a_max: must be >= a_min"), &
         bad_case_t(sp//"&physical k=25, m=0.25, r0=0.3, a_min=0, a_max=0.1, n_a=0 /", "physical", "n_a: must be >= 1"), &
         bad_case_t(sp//"&physical k=25, m=0.25, r0=0.3, a_min=0, a_max=0.1 /", "physical", "n_a: a_min, a_max and n_a"), &
         bad_case_t(sp//"&physical k=25, m=0.25, r0=0.3, a=0.1, a_max=0.2 /", "physical", "a_max: give the amplitudes"), &
         bad_case_t(sp//"&physical k=25, m=0.25, a_min=0, a_max=0.1, n_a=3 /", "physical", "r0"), &
         bad_case_t(s//"task='coefficient' / &physical k=25, m=0.25, r0=0.3, a_min=0, a_max=0.1, n_a=65 /", &
                    "physical", "n_a: task 'coefficient' draws at most 64"), &
         bad_case_t("&scene output='@OUT@' / &physical r0=0.3, a_min=0, a_max=0.33, n_a=3, omega_min=5, "// &
                    "omega_max=20, n_omega=3 /", "physical", "a_max: a = 0.33 m reaches the pivot"), &
         bad_case_t("&scene output='@OUT@' / &physical r0=0.3, a_min=0, a_max=0.33, n_a=3, omega_min=5, "// &
                    "omega_max=20, n_omega=3 /", "physical", "largest valid a is rho(omega_max)"), &
         bad_case_t("&scene output='@OUT@' / &chart / &physical r0=0.3, a_min=0, a_max=0.2, n_a=3, omega_min=5, "// &
                    "omega_max=20, n_omega=3 /", "chart", "alpha_min: the chart runs either"), &
         bad_case_t(sp//"&physical r0=0.3, a_min=0, a_max=0.2, n_a=3, omega_min=5, omega_max=20, n_omega=3 /", &
                    "physical", "n_omega: a range of omega"), &
         bad_case_t("&scene output='@OUT@' / &physical omega=10, r0=0.3, a_min=0, a_max=0.2, n_a=3, "// &
                    "omega_min=5, omega_max=20, n_omega=3 /", "physical", "omega_min: give omega"), &
         bad_case_t("&scene output='@OUT@' / &physical r0=0.3, a_min=0, a_max=0.2, n_a=3, omega_min=5, "// &
                    "omega_max=20 /", "physical", "n_omega: omega_min, omega_max and"), &
         bad_case_t("&scene output='@OUT@' / &physical r0=0.3, a_min=0, a_max=0.2, n_a=3, omega_min=0, "// &
                    "omega_max=20, n_omega=3 /", "physical", "omega_min: must be > 0"), &
         bad_case_t("&scene output='@OUT@' / &physical r0=0.3, omega_min=5, omega_max=20, n_omega=3 /", &
                    "physical", "a_min: a chart over (a, omega) needs"), &
         bad_case_t(s//"task='coefficient' / &coefficient beta=2 / &physical omega=3, r0=1, a=0.5 /", &
                    "coefficient", "beta"), &
         bad_case_t(s//"&chart n_alpha=3 /", "scene", "not closed: no '/' before '&chart'"), &
         bad_case_t(s//"/ &chart n_alpha=3 ", "chart", "not closed: no '/' before the end"), &
         bad_case_t(s//"columns='alpha foo' / &chart /", "scene", "columns: 'foo'"), &
         bad_case_t(s//"columns='alpha alpha' / &chart /", "scene", "columns: 'alpha'"), &
         bad_case_t(s//"columns='stable_paper' / &chart /", "scene", "columns: 'stable_paper'"), &
         bad_case_t(s//"columns='mu_per_s' / &chart /", "scene", "columns: 'mu_per_s'"), &
         bad_case_t(s//"model='mathieu', columns='physical' / &chart /", "scene", "columns: 'physical'"), &
         bad_case_t(s//"columns=', ' / &chart /", "scene", "columns"), &
         bad_case_t(s//"format='hdf5' / &chart /", "scene", "format"), &
         bad_case_t(s//"format='binary', names_line=.true. / &chart /", "scene", "names_line"), &
         bad_case_t(s//"names_line=3 / &chart /", "scene", "names_line"), &
         bad_case_t(s//"task='coefficient', names_line=.true. / &coefficient /", "scene", "names_line: columns, format"), &
         bad_case_t(s//"task='boundaries', names_line=.true. / &chart /", "scene", "names_line: columns, format"), &
         bad_case_t(s//"task='series', names_line=.true. / &series /", "scene", "names_line: columns, format"), &
         bad_case_t(s//"task='series', columns='t' / &series /", "scene", "columns: columns, format"), &
         bad_case_t(s//"task='poincare', format='binary' / &series /", "scene", "format: columns, format"), &
         bad_case_t(s//"task='poincare' / &series / &physical omega=3, kappa=0.1 /", "physical", &
                    "omega: task 'poincare' takes its values dimensionless"), &
         bad_case_t(s//"task='regions' / &chart / &physical omega=3, kappa=0.1 /", "physical", &
                    "omega: task 'regions' takes its values dimensionless"), &
         bad_case_t(s//"task='edges' / &chart / &physical omega=3 /", "physical", "boundaries, series, lyapunov"), &
         bad_case_t(s//"task='series' / &series phi0=0.1, phi0_degrees=1 /", "series", "phi0_degrees: give the "// &
            "initial angle either as phi0 (radians) or as phi0_degrees"), &
         bad_case_t(s//"task='lyapunov' / &series phi0_degrees=nan, periods=2 / &chart /", "series", "phi0_degrees"), &
         bad_case_t(s//"task='series' / &series phi0_degrees=1e9 /", "series", "phi0_degrees: must be 0 or lie"), &
         bad_case_t(s//"task='coefficient', format='binary' / &coefficient /", "scene", "format"), &
         bad_case_t(s//"task='coefficient', columns='tau' / &coefficient /", "scene", "columns"), &
         bad_case_t(s//"/ &chart beta_max = -, /", "chart", "beta_max: no value"), &
         bad_case_t(s//"/ &chart n_alpha = 2147483647 /", "chart", "n_alpha: must be <= 100000000"), &
         bad_case_t(s//"n_segments = 2147483647 / &chart /", "scene", "n_segments: must be <= 100000"), &
         bad_case_t(s//"tolerance = 1e-300 / &chart /", "scene", "tolerance: must be >= 1.0e-15"), &
         bad_case_t(s//"tolerance = 1 / &chart /", "scene", "tolerance: must be >= 1.0e-15"), &
         bad_case_t(s//"/ &chart beta_max = 1e308 /", "chart", "beta_max: must lie in [-1.0e15, 1.0e15]"), &
         bad_case_t("&scene model='mathieu', method='rk' / &chart alpha_max = 1e14 /", "chart", &
                    "|alpha| + |beta| must be <= 100000000.0"), &
         bad_case_t(s//"model='mathieu' / &chart alpha_max = 1e20 /", "chart", "alpha_max: must lie in"), &
         bad_case_t(s//"epsilon = 1e200 / &chart /", "scene", "epsilon: damping must be >= 0 and <= 100"), &
         bad_case_t(s//"task='coefficient' / &coefficient beta = 1e308 /", "coefficient", "beta: must lie in"), &
         bad_case_t(s//"task='boundaries', model='mathieu' / &chart alpha_max = 1e8 /", "chart", &
                    "alpha_max: |alpha| must be <= 1000000.0"), &
         bad_case_t(s//"/ &chart n_alpha = , /", "chart", "n_alpha: no value"), &
         bad_case_t("&scene task 'chart' / &chart /", "scene", "task: cannot read"), &
         bad_case_t(s//"task='coefficient' / &coefficient alphas="//repeat("1,", 65)//"1 /", &
                    "coefficient", "alphas: cannot read"), &
         bad_case_t(s//"task='coefficient' / &coefficient alphas="//repeat("1,", 65)//"1 /", &
                    "coefficient", "at most 64"), &
         bad_case_t(s//"output='abc / &chart /", "scene", "output: the group is not closed"), &
         bad_case_t(sp//"&points file='@DIR@_dir' /", "points", "file: '"), &
         bad_case_t(sp//"&points file='@DIR@_dir' /", "points", "is a directory"), &
         bad_case_t(sp//"&points file='@DIR@_slash.dat' /", "points", "line 2: expected two numbers"), &
         bad_case_t(sp//"&points file='@DIR@_comma.dat' /", "points", "line 2: expected two numbers"), &
         bad_case_t(sp//"&points file='@DIR@_repeat.dat' /", "points", "line 3: expected two numbers"), &
         bad_case_t(sp//"&points file='@DIR@_first.dat' /", "points", "line 1: expected two numbers"), &
         bad_case_t(s//"task='lyapunov' / &series periods=2 / &chart beta_min=1e-320 /", "chart", &
                    "beta_min: must be >= 1.0e-8"), &
         bad_case_t(s//"task='lyapunov' / &series periods=2 / &lyapunov over='points' / "// &
                    "&points file='@DIR@_tinybeta.dat' /", "points", "beta = 1.0e-9, below 1.0e-8"), &
         bad_case_t(y//"/ &system n=2, cos=1,0,0,1 / &chart beta_scale='log' /", "chart", "beta_min"), &
         bad_case_t(y//", task='boundaries' / &system n=2, cos=1,0,0,1 / &chart beta_min=1, beta_scale='log' /", "chart", &
                    "beta_scale"), &
         bad_case_t(y//"/ &system n=2, mass=1,2,2,1, cos=1,0,0,1 / &chart /", "system", "mass: M must be positive"), &
         bad_case_t(y//"/ &system n=2, mass=1,0.5,0,1, cos=1,0,0,1 / &chart /", "system", "mass: M must be symmetric"), &
         bad_case_t(y//"/ &system n=2, gyroscopic=0,1,1,0, cos=1,0,0,1 / &chart /", "system", "gyroscopic: G must be skew"), &
         bad_case_t(y//"/ &system n=2, damping=0,1,-1,0, cos=1,0,0,1 / &chart /", "system", "damping: C must be symmetric"), &
         bad_case_t(y//"/ &system n=2, k0=1,2,3, cos=1,0,0,1 / &chart /", "system", "k0: n = 2 needs 4 numbers"), &
         bad_case_t(y//"/ &system n=2, cos=1,0,0,1,5 / &chart /", "system", "cos: n = 2 needs blocks of 4"), &
         bad_case_t(y//"/ &system n=21, cos=1 / &chart /", "system", "n: the degrees of freedom must be"), &
         bad_case_t(y//"/ &system n=2, mass=1,NaN,0,1, cos=1,0,0,1 / &chart /", "system", "mass"), &
         bad_case_t(y//"/ &system cos=1 / &chart /", "system", "n: the degrees of freedom are not given"), &
         bad_case_t(y//"/ &system n=1 / &chart /", "system", "cos, sin: the system needs at least one"), &
         bad_case_t(y//"/ &system n=1, cos=1, foo=2 / &chart /", "system", "foo: unknown variable"), &
         bad_case_t(y//"method='formula' / &system n=1, cos=1 / &chart /", "scene", &
                    "method: a system (model = 'system') takes method auto, magnus4, magnus6, rk, gsl, got 'formula'"), &
         bad_case_t(y//"task='series' / &system n=1, cos=1 / &series /", "scene", "task"), &
         bad_case_t(y//"columns='alpha S' / &system n=1, cos=1 / &chart /", "scene", "columns: 'S' is not a column of this file"), &
         bad_case_t(y//"/ &system n=1, cos=1 / &physical omega=10 / &chart /", "physical", "omega"), &
         bad_case_t(y//"/ &system n=1, cos=1 / &chart beta_max=1e12 /", "chart", "beta_max: the system's frequencies"), &
         bad_case_t(y//"task='boundaries' / &system n=1, cos=1 / &chart n_beta=1 /", "chart", "n_beta"), &
         ! read as written: a second group, a variable given twice, a path across a line break
         bad_case_t(y//"/ &system n=1, cos=1 /"//achar(10)//"&system n=1, cos=2 / &chart /", "system", &
                    "the group is given 2 times"), &
         bad_case_t(y//"/ &system n=1, cos=1, cos=2 / &chart /", "system", "cos: given twice in the group"), &
         bad_case_t(y//"/ &system n=1, cos=1, n=1 / &chart /", "system", "n: given twice in the group"), &
         bad_case_t(y//"/ &system n=1, cos(1)=1 / &chart /", "system", "cos: a model's variable is given whole"), &
         bad_case_t(s//"/ &chart n_alpha=3, n_alpha=4 /", "chart", "n_alpha: given twice in the group"), &
         bad_case_t(s//"/ &chart n_alpha=3, N_ALPHA = 4 /", "chart", "n_alpha: given twice in the group"), &
         bad_case_t(s//"task='coefficient' / &coefficient alphas=4, 6, alphas(2)=5 /", "coefficient", &
                    "alphas: given twice in the group"), &
         bad_case_t(s//"epsilon=0.1, epsilon=0.2 / &chart /", "scene", "epsilon: given twice"), &
         bad_case_t(s//"method='exact' / &chart /", "scene", "method: given twice"), &
         bad_case_t(y//"/ &system n=2, mass='@DIR@"//achar(10)//"_m_ok.txt', cos=1,0,0,1 / &chart /", "system", &
                    "mass: a quoted string runs on to the next line"), &
         ! matrix files
         bad_case_t(y//"/ &system n=2, mass='@DIR@_m_empty.txt', cos=1,0,0,1 / &chart /", "system", &
                    "mass: '"), &
         bad_case_t(y//"/ &system n=2, mass='@DIR@_m_empty.txt', cos=1,0,0,1 / &chart /", "system", &
                    "_m_empty.txt' line 2: an empty field in '5,,7'"), &
         bad_case_t(y//"/ &system n=2, mass='@DIR@_m_lead.txt', cos=1,0,0,1 / &chart /", "system", &
                    "_m_lead.txt' line 1: an empty field in ',1 0'"), &
         bad_case_t(y//"/ &system n=2, mass='@DIR@_m_commas.txt', cos=1,0,0,1 / &chart /", "system", &
                    "_m_commas.txt' line 2: an empty field in ','"), &
         bad_case_t(y//"/ &system n=2, mass='@DIR@_m_ragged.txt', cos=1,0,0,1 / &chart /", "system", &
                    "mass: '"), &
         bad_case_t(y//"/ &system n=2, mass='@DIR@_m_ragged.txt', cos=1,0,0,1 / &chart /", "system", &
                    "line 2: 1 number where the rows before have 3 (ragged rows"), &
         bad_case_t(y//"/ &system n=2, mass='@DIR@_m_wide.txt', cos=1,0,0,1 / &chart /", "system", &
                    "mass: the file has rows of 4 numbers, and n = 2 needs rows of 2"), &
         bad_case_t(y//"/ &system n=2, cos='@DIR@_m_wide.txt' / &chart /", "system", &
                    "cos: the file has rows of 4 numbers"), &
         bad_case_t(y//"/ &system n=2, mass='@DIR@_dir', cos=1,0,0,1 / &chart /", "system", &
                    "mass: '"), &
         bad_case_t(y//"/ &system n=2, mass='@DIR@_dir', cos=1,0,0,1 / &chart /", "system", &
                    "_dir' is a directory, not a matrix file"), &
         bad_case_t(y//"/ &system n=2, b='@DIR@_fifo', cos=1,0,0,1 / &chart /", "system", &
                    "b: '"), &
         bad_case_t(y//"/ &system n=2, b='@DIR@_fifo', cos=1,0,0,1 / &chart /", "system", &
                    "_fifo' is not a regular file (a FIFO, device or socket), not a matrix file"), &
         bad_case_t(sp//"&points file='@DIR@_fifo' /", "points", "file: '"), &
         bad_case_t(sp//"&points file='@DIR@_fifo' /", "points", "is not a regular file (a FIFO"), &
         bad_case_t("&scene output='@OUT@', model='sampled' / &sampled file='@DIR@_fifo' / &chart /", "sampled", &
                    "file: '"), &
         bad_case_t("&scene output='@OUT@', model='sampled' / &sampled file='@DIR@_fifo' / &chart /", "sampled", &
                    "_fifo' is not a regular file (a FIFO, device or socket), not a file of numbers"), &
         bad_case_t("&scene output='@OUT@', model='sampled' / &sampled file='@DIR@_dir' / &chart /", "sampled", &
                    "_dir' is a directory, not a file of numbers"), &
         bad_case_t("&scene output='@OUT@', model='sampled' / &sampled file='@DIR@_m_empty.txt' / &chart /", &
                    "sampled", "file: '"), &
         bad_case_t("&scene output='@OUT@', model='sampled' / &sampled file='@DIR@_m_empty.txt' / &chart /", &
                    "sampled", "_m_empty.txt' line 2: an empty field in '5,,7'"), &
         bad_case_t("&scene output='@OUT@', model='sampled' / &sampled period=2, period=4, samples=1,2 / &chart /", &
                    "sampled", "period: given twice in the group"), &
         ! sizes blamed on the variable that can fix them
         bad_case_t(y//"/ &system n=1, damping=1e15, cos=1 / &chart /", "system", &
                    "damping: the damping and gyroscopic rates reach |M^-1 (C + G)| = 1.0e15"), &
         bad_case_t(y//"/ &system n=2, gyroscopic=0,1e12,-1e12,0, cos=1,0,0,1 / &chart /", "system", &
                    "gyroscopic: the damping and gyroscopic rates"), &
         bad_case_t(y//"/ &system n=1, k0=1e308, cos=1 / &chart /", "system", &
                    "k0: the system's frequencies reach sqrt(|M^-1 K0|) = 1.0e154 already at alpha = beta = 0"), &
         bad_case_t(y//"/ &system n=1, cos=1e200 / &chart /", "system", &
                    "cos: the system's frequencies reach sqrt(|M^-1 K_drive|) = 1.0e100 already at |alpha| = 1"), &
         bad_case_t(y//"/ &system n=2, cos=1,0,0,1, sin=0,0,0,1e9 / &chart /", "system", "sin: the system's"), &
         bad_case_t(y//"/ &system n=1, b=1e308, cos=1 / &chart /", "system", &
                    "b: the system's frequencies reach sqrt(|M^-1 B|) = 1.0e154 already at |beta| = 1"), &
         bad_case_t(y//"/ &system n=1, damping=1e308, mass=0.5, cos=1 / &chart /", "system", &
                    "damping: the damping and gyroscopic rates reach |M^-1 (C + G)| = more than the largest double"), &
         bad_case_t(y//"/ &system n=1, cos=1 / &chart beta_min=-1e12 /", "chart", "beta_min: the system's frequencies"), &
         bad_case_t(y//"/ &system n=1, cos=1 / &chart alpha_max=1e12 /", "chart", "alpha_max: the system's frequencies"), &
         bad_case_t(y//"task='points' / &system n=1, cos=1 / &points file='@DIR@_bigbeta.dat' /", "points", &
                    "file: the system's frequencies"), &
         bad_case_t(y//"/ &system n=1, mass=1e-300, cos=1 / &chart /", "system", &
                    "mass: M is out of the range the methods take"), &
         bad_case_t(y//"task='boundaries' / &system n=2, mass=1,0,0,1e308, cos=1,0,0,1 / &chart n_beta=3 /", &
                    "system", "mass: M is out of the range the methods take (an entry above 1.0e280")]
   end function bad_cases

   !> Write the points files the bad cases refer to (`<dir>_badline.dat`, ...).
   subroutine write_bad_points_files(dir)
      character(len=*), intent(in) :: dir
      call write_file(dir//"_badline.dat", [character(len=20) :: "1.0 2.0", "3.0", "4.0 5.0"])
      call write_file(dir//"_nan.dat", [character(len=20) :: "1.0 nan"])
      call write_file(dir//"_domain.dat", [character(len=20) :: "1.0 2.0", "9.9 2.0"])
      call write_file(dir//"_tinybeta.dat", [character(len=20) :: "1.0 2.0", "1.0 1e-9"])
      call write_file(dir//"_empty.dat", [character(len=20) :: "# nothing here", ""])
      ! list-directed shortcuts that are not two numbers
      call write_file(dir//"_slash.dat", [character(len=20) :: "1 2", "5 /"])
      call write_file(dir//"_comma.dat", [character(len=20) :: "1 2", ",7"])
      call write_file(dir//"_repeat.dat", [character(len=20) :: "1 2", "# c", "3*"])
      call write_file(dir//"_first.dat", [character(len=20) :: "/", "1 2"])
      call write_file(dir//"_bigbeta.dat", [character(len=20) :: "0.5 1e12"])
      ! matrix files of &system
      call write_file(dir//"_m_ok.txt", [character(len=20) :: "1, 0,", "0, 0.25"])
      call write_file(dir//"_m_empty.txt", [character(len=20) :: "1 0", "5,,7"])
      call write_file(dir//"_m_lead.txt", [character(len=20) :: ",1 0", "0 1"])
      call write_file(dir//"_m_commas.txt", [character(len=20) :: "1 0", ",", "0 1"])
      call write_file(dir//"_m_ragged.txt", [character(len=20) :: "1 0 0", "0.25"])
      call write_file(dir//"_m_wide.txt", [character(len=20) :: "1 0 0 0.25"])
      call execute_command_line("mkdir -p "//dir//"_dir")
      call execute_command_line("rm -f "//dir//"_fifo && mkfifo "//dir//"_fifo")
   end subroutine write_bad_points_files

   subroutine delete_bad_points_files(dir)
      character(len=*), intent(in) :: dir
      call delete_file(dir//"_badline.dat")
      call delete_file(dir//"_nan.dat")
      call delete_file(dir//"_domain.dat")
      call delete_file(dir//"_tinybeta.dat")
      call delete_file(dir//"_empty.dat")
      call delete_file(dir//"_slash.dat")
      call delete_file(dir//"_comma.dat")
      call delete_file(dir//"_repeat.dat")
      call delete_file(dir//"_first.dat")
      call delete_file(dir//"_bigbeta.dat")
      call delete_file(dir//"_m_ok.txt")
      call delete_file(dir//"_m_empty.txt")
      call delete_file(dir//"_m_lead.txt")
      call delete_file(dir//"_m_commas.txt")
      call delete_file(dir//"_m_ragged.txt")
      call delete_file(dir//"_m_wide.txt")
      call execute_command_line("rmdir "//dir//"_dir")
      call execute_command_line("rm -f "//dir//"_fifo")
   end subroutine delete_bad_points_files

   !> Replace every `key` in `text` by `value`.
   function substituted(text, key, value) result(out)
      character(len=*), intent(in) :: text, key, value
      character(len=:), allocatable :: out
      integer :: at
      out = trim(text)
      do
         at = index(out, key)
         if (at == 0) exit
         out = out(:at - 1)//value//out(at + len(key):)
      end do
   end function substituted

   !> The scene text of a bad case with the placeholders filled in.
   function bad_case_text(case, output, dir) result(text)
      type(bad_case_t), intent(in) :: case
      character(len=*), intent(in) :: output, dir
      character(len=:), allocatable :: text
      text = substituted(substituted(case%text, "@OUT@", output), "@DIR@", dir)
   end function bad_case_text
end module hillstab_test_bad_scenes

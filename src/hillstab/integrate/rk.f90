!> Adaptive embedded Runge–Kutta integrators for first-order systems y' = f(t, y):
!> Dormand–Prince 5(4) (DOPRI5), Dormand–Prince 8(5,3) (DOP853), Prince–Dormand 8(7)
!> (PD87, the pair of GSL's rk8pd) and Verner's most efficient 9(8) pair (VERN98), the last
!> two without continuous extension of their own, with Hairer's error norm, PI step-size
!> control, initial step guess and continuous (dense) output,
!> plus a fixed-step mode without error control for convergence studies.
!>
!> The step control, error norms and dense output follow E. Hairer, S. P. Nørsett,
!> G. Wanner, *Solving Ordinary Differential Equations I*, 2nd ed., Springer 1993,
!> §II.4–II.6 and §IV.2, as implemented in Hairer's codes dopri5.f and dop853.f
!> (versions of 1996, www.unige.ch/~hairer/software.html). The Butcher coefficients are
!> copied from those codes (Dormand & Prince 1980 for DOPRI5 with Shampine's 1986 dense
!> output; Prince & Dormand 1981 / Hairer et al. for DOP853 and its 7th-order extension).
!> VERN98 is the 16-stage 9(8) pair "RKV98.IIa Efficient" of J. H. Verner, "Numerically
!> optimal Runge–Kutta pairs with interpolants", Numer. Algorithms 53 (2010) 383–396, from
!> Verner's coefficient file RKV98.IIa.Efficient.000000349.081209.FLOAT6040OnWeb
!> (www.sfu.ca/~jverner); the 40-digit values were read as reproduced in
!> github.com/jacobwilliams/rklib (src/rklib_variable_steps.f90, rkv98e) and agree to 3e-40
!> with github.com/vlovero/PyODEPack (pyodepack/include/verner98e.h); in 60-digit
!> arithmetic they satisfy all 486 order conditions of order ≤ 9 (the 8th-order weights
!> those of order ≤ 8) to 1e-39.
!>
!> The system is an extension of the abstract type `rk_system_t`: its components carry
!> the parameters, its deferred binding `rhs` computes f, and its binding `observe`
!> (a no-op unless overridden) sees the initial point and every accepted step with its
!> continuous extension (`rk_dense_value`) and may stop the integration. No procedure
!> is passed as an argument, so callers need no internal procedures (gfortran would
!> build trampolines for those and the program would need an executable stack). The
!> module has no state: independent integrations may run in parallel threads.
!>
!>```fortran
!> type, extends(rk_system_t) :: oscillator_t
!>    real(wp) :: omega = 1.0_wp
!> contains
!>    procedure :: rhs => oscillator_rhs
!> end type oscillator_t
!> ...
!> type(oscillator_t) :: oscillator
!> type(rk_options_t) :: options
!> type(error_t), allocatable :: error
!> real(wp) :: t, y(2), t_out(3), y_out(2, 3)
!> t = 0.0_wp; y = [1.0_wp, 0.0_wp]; t_out = [0.5_wp, 1.0_wp, 2.0_wp]
!> options = rk_options_t(method=rk_dop853, rtol=1.0e-10_wp, atol=1.0e-10_wp)
!> call rk_integrate(oscillator, t, 2.0_wp, y, options, error=error, t_out=t_out, y_out=y_out)
!> ...
!> subroutine oscillator_rhs(self, t, y, dydt)
!>    class(oscillator_t), intent(inout) :: self
!>    real(wp), intent(in) :: t, y(:)
!>    real(wp), intent(out) :: dydt(:)
!>    dydt = [y(2), -self%omega**2*y(1)]
!> end subroutine oscillator_rhs
!>```
module hillstab_integrate_rk
   use hillstab_core_kinds, only: wp, int64
   use hillstab_core_error, only: error_t, set_error, err_invalid_parameter, err_integration
   use hillstab_core_stats, only: work_stats_t
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   implicit none
   private
   public :: rk_system_t, rk_rhs, rk_observe, rk_options_t, rk_step_t, rk_integrate, rk_dense_value
   public :: rk_beta_limit
   public :: rk_dopri5, rk_dop853, rk_pd87, rk_vern98, rk_method_name, rk_method_order, rk_vern98_tableau

   !> Dormand–Prince 5(4), 7 stages (FSAL: 6 evaluations per step), 4th-order dense output.
   integer, parameter :: rk_dopri5 = 1
   !> Dormand–Prince 8(5,3), 12 stages (12 evaluations per accepted step), 7th-order dense
   !> output at 3 more evaluations per step.
   integer, parameter :: rk_dop853 = 2
   !> Prince–Dormand 8(7) (RK8(7)13M, the pair of GSL's rk8pd), 13 stages (13 evaluations
   !> per accepted step with f at the new point); no continuous extension of its own:
   !> observers get the cubic Hermite interpolant, `t_out` and `dense_output` are refused.
   integer, parameter :: rk_pd87 = 3
   !> Verner's most efficient 9(8) pair (RKV98.IIa, 2010), 16 stages (16 evaluations per
   !> accepted step with f at the new point: not FSAL, stage 16 serves only the error
   !> estimate); no continuous extension: as for rk_pd87, observers get the cubic Hermite
   !> interpolant, `t_out` and `dense_output` are refused.
   integer, parameter :: rk_vern98 = 4


   !> Options of `rk_integrate`. Zero (or negative) values of the step-control
   !> parameters select the defaults of Hairer's codes for the chosen method.
   type :: rk_options_t
      integer :: method = rk_dop853       !! rk_dopri5, rk_dop853, rk_pd87 or rk_vern98
      real(wp) :: rtol = 1.0e-10_wp       !! relative tolerance (≥ 0)
      real(wp) :: atol = 1.0e-10_wp       !! absolute tolerance (> 0)
      real(wp), allocatable :: atol_components(:)  !! per-component absolute tolerances (all > 0,
                                          !! size of the state); when allocated they replace
                                          !! `atol` (Hairer's ITOL = 1)
      real(wp) :: h_initial = 0.0_wp      !! first step; 0 → Hairer's initial guess (hinit)
      real(wp) :: h_max = 0.0_wp          !! largest |h|; 0 → |t_end − t|
      integer :: max_steps = 100000       !! attempted steps (accepted + rejected) before failing
      integer :: fixed_steps = 0          !! > 0: this many equal steps, no error control
      real(wp) :: safety = 0.9_wp         !! safety factor of the step prediction
      real(wp) :: beta = -1.0_wp          !! PI (Lund) stabilisation; < 0 → 0.04 (DOPRI5), 0 (others);
                                          !! must lie below `rk_beta_limit` (0.114 DOPRI5,
                                          !! 0.104 DOP853/PD87, 0.093 VERN98)
      real(wp) :: fac_min = 0.0_wp        !! smallest h_new/h; 0 → 0.2 (DOPRI5), 0.333 (others)
      real(wp) :: fac_max = 0.0_wp        !! largest h_new/h; 0 → 10 (DOPRI5), 6 (others)
      logical :: dense_output = .false.   !! build DOP853's 7th-order interpolant every step
                                          !! (3 more evaluations); implied by `t_out`;
                                          !! refused by rk_pd87 and rk_vern98
   end type rk_options_t

   !> One accepted step as handed to an observer: the interval [t_old, t], the state at
   !> t and the coefficients of the continuous extension on that interval. The
   !> interpolant is of order `dense_order`: 4 (DOPRI5), 7 (DOP853 with dense output),
   !> or 3 (DOP853 without, PD87, VERN98: the cubic Hermite interpolant from the end
   !> values and slopes).
   type :: rk_step_t
      integer :: method = rk_dop853  !! the pair that made the step (rk_dopri5, rk_dop853, rk_pd87, rk_vern98)
      integer(int64) :: index = 0        !! number of this accepted step (0: the initial point)
      real(wp) :: t_old = 0.0_wp         !! start of the step
      real(wp) :: t = 0.0_wp             !! end of the step
      real(wp) :: h = 0.0_wp             !! t − t_old
      integer :: dense_order = 0         !! order of the continuous extension (0: none yet)
      real(wp), allocatable :: y(:)      !! state at t
      real(wp), allocatable :: dense(:, :)  !! (n, 0:7) interpolation coefficients
   end type rk_step_t

   !> A system y' = f(t, y) with its data. Extend it, put the parameters in components,
   !> implement `rhs`; override `observe` to watch (or stop) the integration.
   type, abstract :: rk_system_t
   contains
      !> f(t, y)
      procedure(rk_rhs), deferred :: rhs
      !> Called after the initial point and after every accepted step (default: nothing)
      procedure :: observe => rk_observe
   end type rk_system_t

   abstract interface
      !> Right-hand side dydt = f(t, y) of the system.
      subroutine rk_rhs(self, t, y, dydt)
         import :: rk_system_t, wp
         class(rk_system_t), intent(inout) :: self  !! the system and its data
         real(wp), intent(in) :: t        !! independent variable
         real(wp), intent(in) :: y(:)     !! state
         real(wp), intent(out) :: dydt(:) !! derivative, same size as y
      end subroutine rk_rhs
   end interface

   ! ---------------------------------------------------------------------------------
   ! DOPRI5: Dormand & Prince (1980), coefficients as in Hairer's dopri5.f (CDOPRI);
   ! e = b − b̂ of the embedded 4th-order formula; d = Shampine's (1986) dense output.
   ! ---------------------------------------------------------------------------------
   real(wp), parameter :: p5_c2 = 0.2_wp, p5_c3 = 0.3_wp, p5_c4 = 0.8_wp, p5_c5 = 8.0_wp/9.0_wp
   real(wp), parameter :: p5_a21 = 0.2_wp
   real(wp), parameter :: p5_a31 = 3.0_wp/40.0_wp, p5_a32 = 9.0_wp/40.0_wp
   real(wp), parameter :: p5_a41 = 44.0_wp/45.0_wp, p5_a42 = -56.0_wp/15.0_wp, p5_a43 = 32.0_wp/9.0_wp
   real(wp), parameter :: p5_a51 = 19372.0_wp/6561.0_wp, p5_a52 = -25360.0_wp/2187.0_wp, &
      p5_a53 = 64448.0_wp/6561.0_wp, p5_a54 = -212.0_wp/729.0_wp
   real(wp), parameter :: p5_a61 = 9017.0_wp/3168.0_wp, p5_a62 = -355.0_wp/33.0_wp, &
      p5_a63 = 46732.0_wp/5247.0_wp, p5_a64 = 49.0_wp/176.0_wp, p5_a65 = -5103.0_wp/18656.0_wp
   real(wp), parameter :: p5_a71 = 35.0_wp/384.0_wp, p5_a73 = 500.0_wp/1113.0_wp, &
      p5_a74 = 125.0_wp/192.0_wp, p5_a75 = -2187.0_wp/6784.0_wp, p5_a76 = 11.0_wp/84.0_wp
   real(wp), parameter :: p5_e1 = 71.0_wp/57600.0_wp, p5_e3 = -71.0_wp/16695.0_wp, &
      p5_e4 = 71.0_wp/1920.0_wp, p5_e5 = -17253.0_wp/339200.0_wp, p5_e6 = 22.0_wp/525.0_wp, &
      p5_e7 = -1.0_wp/40.0_wp
   real(wp), parameter :: p5_d1 = -12715105075.0_wp/11282082432.0_wp, &
      p5_d3 = 87487479700.0_wp/32700410799.0_wp, p5_d4 = -10690763975.0_wp/1880347072.0_wp, &
      p5_d5 = 701980252875.0_wp/199316789632.0_wp, p5_d6 = -1453857185.0_wp/822651844.0_wp, &
      p5_d7 = 69997945.0_wp/29380423.0_wp

   ! ---------------------------------------------------------------------------------
   ! DOP853: coefficients as in Hairer's dop853.f (DP86CO, version of 25 April 1996).
   ! Stages 1–12 make the step, stage 13 is f at the new point (FSAL), stages 14–16
   ! serve only the 7th-order dense output. bhh: 3rd-order embedded weights; er: b − b̂₅.
   ! ---------------------------------------------------------------------------------
   real(wp), parameter :: p8_c2 = 0.526001519587677318785587544488e-01_wp
   real(wp), parameter :: p8_c3 = 0.789002279381515978178381316732e-01_wp
   real(wp), parameter :: p8_c4 = 0.118350341907227396726757197510e+00_wp
   real(wp), parameter :: p8_c5 = 0.281649658092772603273242802490e+00_wp
   real(wp), parameter :: p8_c6 = 0.333333333333333333333333333333e+00_wp
   real(wp), parameter :: p8_c7 = 0.25e+00_wp
   real(wp), parameter :: p8_c8 = 0.307692307692307692307692307692e+00_wp
   real(wp), parameter :: p8_c9 = 0.651282051282051282051282051282e+00_wp
   real(wp), parameter :: p8_c10 = 0.6e+00_wp
   real(wp), parameter :: p8_c11 = 0.857142857142857142857142857142e+00_wp
   real(wp), parameter :: p8_c14 = 0.1e+00_wp
   real(wp), parameter :: p8_c15 = 0.2e+00_wp
   real(wp), parameter :: p8_c16 = 0.777777777777777777777777777778e+00_wp

   real(wp), parameter :: p8_b1 = 5.42937341165687622380535766363e-2_wp
   real(wp), parameter :: p8_b6 = 4.45031289275240888144113950566e0_wp
   real(wp), parameter :: p8_b7 = 1.89151789931450038304281599044e0_wp
   real(wp), parameter :: p8_b8 = -5.8012039600105847814672114227e0_wp
   real(wp), parameter :: p8_b9 = 3.1116436695781989440891606237e-1_wp
   real(wp), parameter :: p8_b10 = -1.52160949662516078556178806805e-1_wp
   real(wp), parameter :: p8_b11 = 2.01365400804030348374776537501e-1_wp
   real(wp), parameter :: p8_b12 = 4.47106157277725905176885569043e-2_wp

   real(wp), parameter :: p8_bhh1 = 0.244094488188976377952755905512e+00_wp
   real(wp), parameter :: p8_bhh2 = 0.733846688281611857341361741547e+00_wp
   real(wp), parameter :: p8_bhh3 = 0.220588235294117647058823529412e-01_wp

   real(wp), parameter :: p8_er1 = 0.1312004499419488073250102996e-01_wp
   real(wp), parameter :: p8_er6 = -0.1225156446376204440720569753e+01_wp
   real(wp), parameter :: p8_er7 = -0.4957589496572501915214079952e+00_wp
   real(wp), parameter :: p8_er8 = 0.1664377182454986536961530415e+01_wp
   real(wp), parameter :: p8_er9 = -0.3503288487499736816886487290e+00_wp
   real(wp), parameter :: p8_er10 = 0.3341791187130174790297318841e+00_wp
   real(wp), parameter :: p8_er11 = 0.8192320648511571246570742613e-01_wp
   real(wp), parameter :: p8_er12 = -0.2235530786388629525884427845e-01_wp

   real(wp), parameter :: p8_a21 = 5.26001519587677318785587544488e-2_wp
   real(wp), parameter :: p8_a31 = 1.97250569845378994544595329183e-2_wp
   real(wp), parameter :: p8_a32 = 5.91751709536136983633785987549e-2_wp
   real(wp), parameter :: p8_a41 = 2.95875854768068491816892993775e-2_wp
   real(wp), parameter :: p8_a43 = 8.87627564304205475450678981324e-2_wp
   real(wp), parameter :: p8_a51 = 2.41365134159266685502369798665e-1_wp
   real(wp), parameter :: p8_a53 = -8.84549479328286085344864962717e-1_wp
   real(wp), parameter :: p8_a54 = 9.24834003261792003115737966543e-1_wp
   real(wp), parameter :: p8_a61 = 3.7037037037037037037037037037e-2_wp
   real(wp), parameter :: p8_a64 = 1.70828608729473871279604482173e-1_wp
   real(wp), parameter :: p8_a65 = 1.25467687566822425016691814123e-1_wp
   real(wp), parameter :: p8_a71 = 3.7109375e-2_wp
   real(wp), parameter :: p8_a74 = 1.70252211019544039314978060272e-1_wp
   real(wp), parameter :: p8_a75 = 6.02165389804559606850219397283e-2_wp
   real(wp), parameter :: p8_a76 = -1.7578125e-2_wp
   real(wp), parameter :: p8_a81 = 3.70920001185047927108779319836e-2_wp
   real(wp), parameter :: p8_a84 = 1.70383925712239993810214054705e-1_wp
   real(wp), parameter :: p8_a85 = 1.07262030446373284651809199168e-1_wp
   real(wp), parameter :: p8_a86 = -1.53194377486244017527936158236e-2_wp
   real(wp), parameter :: p8_a87 = 8.27378916381402288758473766002e-3_wp
   real(wp), parameter :: p8_a91 = 6.24110958716075717114429577812e-1_wp
   real(wp), parameter :: p8_a94 = -3.36089262944694129406857109825e0_wp
   real(wp), parameter :: p8_a95 = -8.68219346841726006818189891453e-1_wp
   real(wp), parameter :: p8_a96 = 2.75920996994467083049415600797e1_wp
   real(wp), parameter :: p8_a97 = 2.01540675504778934086186788979e1_wp
   real(wp), parameter :: p8_a98 = -4.34898841810699588477366255144e1_wp
   real(wp), parameter :: p8_a101 = 4.77662536438264365890433908527e-1_wp
   real(wp), parameter :: p8_a104 = -2.48811461997166764192642586468e0_wp
   real(wp), parameter :: p8_a105 = -5.90290826836842996371446475743e-1_wp
   real(wp), parameter :: p8_a106 = 2.12300514481811942347288949897e1_wp
   real(wp), parameter :: p8_a107 = 1.52792336328824235832596922938e1_wp
   real(wp), parameter :: p8_a108 = -3.32882109689848629194453265587e1_wp
   real(wp), parameter :: p8_a109 = -2.03312017085086261358222928593e-2_wp
   real(wp), parameter :: p8_a111 = -9.3714243008598732571704021658e-1_wp
   real(wp), parameter :: p8_a114 = 5.18637242884406370830023853209e0_wp
   real(wp), parameter :: p8_a115 = 1.09143734899672957818500254654e0_wp
   real(wp), parameter :: p8_a116 = -8.14978701074692612513997267357e0_wp
   real(wp), parameter :: p8_a117 = -1.85200656599969598641566180701e1_wp
   real(wp), parameter :: p8_a118 = 2.27394870993505042818970056734e1_wp
   real(wp), parameter :: p8_a119 = 2.49360555267965238987089396762e0_wp
   real(wp), parameter :: p8_a1110 = -3.0467644718982195003823669022e0_wp
   real(wp), parameter :: p8_a121 = 2.27331014751653820792359768449e0_wp
   real(wp), parameter :: p8_a124 = -1.05344954667372501984066689879e1_wp
   real(wp), parameter :: p8_a125 = -2.00087205822486249909675718444e0_wp
   real(wp), parameter :: p8_a126 = -1.79589318631187989172765950534e1_wp
   real(wp), parameter :: p8_a127 = 2.79488845294199600508499808837e1_wp
   real(wp), parameter :: p8_a128 = -2.85899827713502369474065508674e0_wp
   real(wp), parameter :: p8_a129 = -8.87285693353062954433549289258e0_wp
   real(wp), parameter :: p8_a1210 = 1.23605671757943030647266201528e1_wp
   real(wp), parameter :: p8_a1211 = 6.43392746015763530355970484046e-1_wp
   real(wp), parameter :: p8_a141 = 5.61675022830479523392909219681e-2_wp
   real(wp), parameter :: p8_a147 = 2.53500210216624811088794765333e-1_wp
   real(wp), parameter :: p8_a148 = -2.46239037470802489917441475441e-1_wp
   real(wp), parameter :: p8_a149 = -1.24191423263816360469010140626e-1_wp
   real(wp), parameter :: p8_a1410 = 1.5329179827876569731206322685e-1_wp
   real(wp), parameter :: p8_a1411 = 8.20105229563468988491666602057e-3_wp
   real(wp), parameter :: p8_a1412 = 7.56789766054569976138603589584e-3_wp
   real(wp), parameter :: p8_a1413 = -8.298e-3_wp
   real(wp), parameter :: p8_a151 = 3.18346481635021405060768473261e-2_wp
   real(wp), parameter :: p8_a156 = 2.83009096723667755288322961402e-2_wp
   real(wp), parameter :: p8_a157 = 5.35419883074385676223797384372e-2_wp
   real(wp), parameter :: p8_a158 = -5.49237485713909884646569340306e-2_wp
   real(wp), parameter :: p8_a1511 = -1.08347328697249322858509316994e-4_wp
   real(wp), parameter :: p8_a1512 = 3.82571090835658412954920192323e-4_wp
   real(wp), parameter :: p8_a1513 = -3.40465008687404560802977114492e-4_wp
   real(wp), parameter :: p8_a1514 = 1.41312443674632500278074618366e-1_wp
   real(wp), parameter :: p8_a161 = -4.28896301583791923408573538692e-1_wp
   real(wp), parameter :: p8_a166 = -4.69762141536116384314449447206e0_wp
   real(wp), parameter :: p8_a167 = 7.68342119606259904184240953878e0_wp
   real(wp), parameter :: p8_a168 = 4.06898981839711007970213554331e0_wp
   real(wp), parameter :: p8_a169 = 3.56727187455281109270669543021e-1_wp
   real(wp), parameter :: p8_a1613 = -1.39902416515901462129418009734e-3_wp
   real(wp), parameter :: p8_a1614 = 2.9475147891527723389556272149e0_wp
   real(wp), parameter :: p8_a1615 = -9.15095847217987001081870187138e0_wp

   real(wp), parameter :: p8_d41 = -0.84289382761090128651353491142e+01_wp
   real(wp), parameter :: p8_d46 = 0.56671495351937776962531783590e+00_wp
   real(wp), parameter :: p8_d47 = -0.30689499459498916912797304727e+01_wp
   real(wp), parameter :: p8_d48 = 0.23846676565120698287728149680e+01_wp
   real(wp), parameter :: p8_d49 = 0.21170345824450282767155149946e+01_wp
   real(wp), parameter :: p8_d410 = -0.87139158377797299206789907490e+00_wp
   real(wp), parameter :: p8_d411 = 0.22404374302607882758541771650e+01_wp
   real(wp), parameter :: p8_d412 = 0.63157877876946881815570249290e+00_wp
   real(wp), parameter :: p8_d413 = -0.88990336451333310820698117400e-01_wp
   real(wp), parameter :: p8_d414 = 0.18148505520854727256656404962e+02_wp
   real(wp), parameter :: p8_d415 = -0.91946323924783554000451984436e+01_wp
   real(wp), parameter :: p8_d416 = -0.44360363875948939664310572000e+01_wp
   real(wp), parameter :: p8_d51 = 0.10427508642579134603413151009e+02_wp
   real(wp), parameter :: p8_d56 = 0.24228349177525818288430175319e+03_wp
   real(wp), parameter :: p8_d57 = 0.16520045171727028198505394887e+03_wp
   real(wp), parameter :: p8_d58 = -0.37454675472269020279518312152e+03_wp
   real(wp), parameter :: p8_d59 = -0.22113666853125306036270938578e+02_wp
   real(wp), parameter :: p8_d510 = 0.77334326684722638389603898808e+01_wp
   real(wp), parameter :: p8_d511 = -0.30674084731089398182061213626e+02_wp
   real(wp), parameter :: p8_d512 = -0.93321305264302278729567221706e+01_wp
   real(wp), parameter :: p8_d513 = 0.15697238121770843886131091075e+02_wp
   real(wp), parameter :: p8_d514 = -0.31139403219565177677282850411e+02_wp
   real(wp), parameter :: p8_d515 = -0.93529243588444783865713862664e+01_wp
   real(wp), parameter :: p8_d516 = 0.35816841486394083752465898540e+02_wp
   real(wp), parameter :: p8_d61 = 0.19985053242002433820987653617e+02_wp
   real(wp), parameter :: p8_d66 = -0.38703730874935176555105901742e+03_wp
   real(wp), parameter :: p8_d67 = -0.18917813819516756882830838328e+03_wp
   real(wp), parameter :: p8_d68 = 0.52780815920542364900561016686e+03_wp
   real(wp), parameter :: p8_d69 = -0.11573902539959630126141871134e+02_wp
   real(wp), parameter :: p8_d610 = 0.68812326946963000169666922661e+01_wp
   real(wp), parameter :: p8_d611 = -0.10006050966910838403183860980e+01_wp
   real(wp), parameter :: p8_d612 = 0.77771377980534432092869265740e+00_wp
   real(wp), parameter :: p8_d613 = -0.27782057523535084065932004339e+01_wp
   real(wp), parameter :: p8_d614 = -0.60196695231264120758267380846e+02_wp
   real(wp), parameter :: p8_d615 = 0.84320405506677161018159903784e+02_wp
   real(wp), parameter :: p8_d616 = 0.11992291136182789328035130030e+02_wp
   real(wp), parameter :: p8_d71 = -0.25693933462703749003312586129e+02_wp
   real(wp), parameter :: p8_d76 = -0.15418974869023643374053993627e+03_wp
   real(wp), parameter :: p8_d77 = -0.23152937917604549567536039109e+03_wp
   real(wp), parameter :: p8_d78 = 0.35763911791061412378285349910e+03_wp
   real(wp), parameter :: p8_d79 = 0.93405324183624310003907691704e+02_wp
   real(wp), parameter :: p8_d710 = -0.37458323136451633156875139351e+02_wp
   real(wp), parameter :: p8_d711 = 0.10409964950896230045147246184e+03_wp
   real(wp), parameter :: p8_d712 = 0.29840293426660503123344363579e+02_wp
   real(wp), parameter :: p8_d713 = -0.43533456590011143754432175058e+02_wp
   real(wp), parameter :: p8_d714 = 0.96324553959188282948394950600e+02_wp
   real(wp), parameter :: p8_d715 = -0.39177261675615439165231486172e+02_wp
   real(wp), parameter :: p8_d716 = -0.14972683625798562581422125276e+03_wp

   ! ---------------------------------------------------------------------------------
   ! PD8(7): Prince & Dormand, "High order embedded Runge–Kutta formulae", J. Comput.
   ! Appl. Math. 7 (1981) 67–75, RK8(7)13M, with the paper's rational coefficients (the
   ! pair of GSL's rk8pd; the fractions read as reproduced in GSL's ode-initval2/rk8pd.c,
   ! and a step is bit-identical to GSL's, test rk/pd87_step_equals_gsl). The 8th-order
   ! formula propagates (local extrapolation); the error is its difference to the
   ! 7th-order one, pd_e = b̂ − b.
   ! ---------------------------------------------------------------------------------
   real(wp), parameter :: pd_c2 = 1.0_wp/18.0_wp, pd_c3 = 1.0_wp/12.0_wp, pd_c4 = 1.0_wp/8.0_wp, &
      pd_c5 = 5.0_wp/16.0_wp, pd_c6 = 3.0_wp/8.0_wp, pd_c7 = 59.0_wp/400.0_wp, pd_c8 = 93.0_wp/200.0_wp, &
      pd_c9 = 5490023248.0_wp/9719169821.0_wp, pd_c10 = 13.0_wp/20.0_wp, &
      pd_c11 = 1201146811.0_wp/1299019798.0_wp
   real(wp), parameter :: pd_a21 = 1.0_wp/18.0_wp
   real(wp), parameter :: pd_a31 = 1.0_wp/48.0_wp, pd_a32 = 1.0_wp/16.0_wp
   real(wp), parameter :: pd_a41 = 1.0_wp/32.0_wp, pd_a43 = 3.0_wp/32.0_wp
   real(wp), parameter :: pd_a51 = 5.0_wp/16.0_wp, pd_a53 = -75.0_wp/64.0_wp, pd_a54 = 75.0_wp/64.0_wp
   real(wp), parameter :: pd_a61 = 3.0_wp/80.0_wp, pd_a64 = 3.0_wp/16.0_wp, pd_a65 = 3.0_wp/20.0_wp
   real(wp), parameter :: pd_a71 = 29443841.0_wp/614563906.0_wp, pd_a74 = 77736538.0_wp/692538347.0_wp, &
      pd_a75 = -28693883.0_wp/1125000000.0_wp, pd_a76 = 23124283.0_wp/1800000000.0_wp
   real(wp), parameter :: pd_a81 = 16016141.0_wp/946692911.0_wp, pd_a84 = 61564180.0_wp/158732637.0_wp, &
      pd_a85 = 22789713.0_wp/633445777.0_wp, pd_a86 = 545815736.0_wp/2771057229.0_wp, &
      pd_a87 = -180193667.0_wp/1043307555.0_wp
   real(wp), parameter :: pd_a91 = 39632708.0_wp/573591083.0_wp, pd_a94 = -433636366.0_wp/683701615.0_wp, &
      pd_a95 = -421739975.0_wp/2616292301.0_wp, pd_a96 = 100302831.0_wp/723423059.0_wp, &
      pd_a97 = 790204164.0_wp/839813087.0_wp, pd_a98 = 800635310.0_wp/3783071287.0_wp
   real(wp), parameter :: pd_a101 = 246121993.0_wp/1340847787.0_wp, &
      pd_a104 = -37695042795.0_wp/15268766246.0_wp, pd_a105 = -309121744.0_wp/1061227803.0_wp, &
      pd_a106 = -12992083.0_wp/490766935.0_wp, pd_a107 = 6005943493.0_wp/2108947869.0_wp, &
      pd_a108 = 393006217.0_wp/1396673457.0_wp, pd_a109 = 123872331.0_wp/1001029789.0_wp
   real(wp), parameter :: pd_a111 = -1028468189.0_wp/846180014.0_wp, pd_a114 = 8478235783.0_wp/508512852.0_wp, &
      pd_a115 = 1311729495.0_wp/1432422823.0_wp, pd_a116 = -10304129995.0_wp/1701304382.0_wp, &
      pd_a117 = -48777925059.0_wp/3047939560.0_wp, pd_a118 = 15336726248.0_wp/1032824649.0_wp, &
      pd_a119 = -45442868181.0_wp/3398467696.0_wp, pd_a1110 = 3065993473.0_wp/597172653.0_wp
   real(wp), parameter :: pd_a121 = 185892177.0_wp/718116043.0_wp, pd_a124 = -3185094517.0_wp/667107341.0_wp, &
      pd_a125 = -477755414.0_wp/1098053517.0_wp, pd_a126 = -703635378.0_wp/230739211.0_wp, &
      pd_a127 = 5731566787.0_wp/1027545527.0_wp, pd_a128 = 5232866602.0_wp/850066563.0_wp, &
      pd_a129 = -4093664535.0_wp/808688257.0_wp, pd_a1210 = 3962137247.0_wp/1805957418.0_wp, &
      pd_a1211 = 65686358.0_wp/487910083.0_wp
   real(wp), parameter :: pd_a131 = 403863854.0_wp/491063109.0_wp, pd_a134 = -5068492393.0_wp/434740067.0_wp, &
      pd_a135 = -411421997.0_wp/543043805.0_wp, pd_a136 = 652783627.0_wp/914296604.0_wp, &
      pd_a137 = 11173962825.0_wp/925320556.0_wp, pd_a138 = -13158990841.0_wp/6184727034.0_wp, &
      pd_a139 = 3936647629.0_wp/1978049680.0_wp, pd_a1310 = -160528059.0_wp/685178525.0_wp, &
      pd_a1311 = 248638103.0_wp/1413531060.0_wp
   ! weights of the 8th-order formula
   real(wp), parameter :: pd_b1 = 14005451.0_wp/335480064.0_wp, pd_b6 = -59238493.0_wp/1068277825.0_wp, &
      pd_b7 = 181606767.0_wp/758867731.0_wp, pd_b8 = 561292985.0_wp/797845732.0_wp, &
      pd_b9 = -1041891430.0_wp/1371343529.0_wp, pd_b10 = 760417239.0_wp/1151165299.0_wp, &
      pd_b11 = 118820643.0_wp/751138087.0_wp, pd_b12 = -528747749.0_wp/2220607170.0_wp, pd_b13 = 1.0_wp/4.0_wp
   ! weights of the 7th-order formula, and the error weights b̂ − b
   real(wp), parameter :: pd_bh1 = 13451932.0_wp/455176623.0_wp, pd_bh6 = -808719846.0_wp/976000145.0_wp, &
      pd_bh7 = 1757004468.0_wp/5645159321.0_wp, pd_bh8 = 656045339.0_wp/265891186.0_wp, &
      pd_bh9 = -3867574721.0_wp/1518517206.0_wp, pd_bh10 = 465885868.0_wp/322736535.0_wp, &
      pd_bh11 = 53011238.0_wp/667516719.0_wp, pd_bh12 = 2.0_wp/45.0_wp
   real(wp), parameter :: pd_e1 = pd_bh1 - pd_b1, pd_e6 = pd_bh6 - pd_b6, pd_e7 = pd_bh7 - pd_b7, &
      pd_e8 = pd_bh8 - pd_b8, pd_e9 = pd_bh9 - pd_b9, pd_e10 = pd_bh10 - pd_b10, pd_e11 = pd_bh11 - pd_b11, &
      pd_e12 = pd_bh12 - pd_b12, pd_e13 = -pd_b13

   ! ---------------------------------------------------------------------------------
   ! VERN98: Verner (2010), RKV98.IIa Efficient, 16 stages (digits: see the header).
   ! Stages 15 and 16 are at c = 1; the 9th-order formula propagates (local
   ! extrapolation) and does not use stage 16, which only the 8th-order formula uses
   ! (a(16, 14) = a(16, 15) = 0). The error weights are v9_e = b̂ − b.
   ! ---------------------------------------------------------------------------------
   ! nodes
   real(wp), parameter :: v9_c2 = 0.3462e-1_wp
   real(wp), parameter :: v9_c3 = 0.9702435063878044594828361677100617517633e-1_wp
   real(wp), parameter :: v9_c4 = 0.1455365259581706689224254251565092627645_wp
   real(wp), parameter :: v9_c5 = 0.561_wp
   real(wp), parameter :: v9_c6 = 0.2290079115904850126662751771814700052182_wp
   real(wp), parameter :: v9_c7 = 0.5449920884095149873337248228185299947818_wp
   real(wp), parameter :: v9_c8 = 0.645_wp
   real(wp), parameter :: v9_c9 = 0.4837500000000000000000000000000000000000_wp
   real(wp), parameter :: v9_c10 = 0.6757e-1_wp
   real(wp), parameter :: v9_c11 = 0.2500_wp
   real(wp), parameter :: v9_c12 = 0.6590650618730998549405331618649220295334_wp
   real(wp), parameter :: v9_c13 = 0.8206_wp
   real(wp), parameter :: v9_c14 = 0.9012_wp
   ! coupling coefficients a(i, j), row by row (the zero ones omitted)
   real(wp), parameter :: v9_a21 = 0.3462e-1_wp
   real(wp), parameter :: v9_a31 = -0.389335438857287327017042687229284478532e-1_wp
   real(wp), parameter :: v9_a32 = 0.1359578945245091786499878854939346230295_wp
   real(wp), parameter :: v9_a41 = 0.3638413148954266723060635628912731569111e-1_wp
   real(wp), parameter :: v9_a43 = 0.1091523944686280016918190688673819470733_wp
   real(wp), parameter :: v9_a51 = 2.025763914393969636805657604282571047511_wp
   real(wp), parameter :: v9_a53 = -7.638023836496292020387602153091964592952_wp
   real(wp), parameter :: v9_a54 = 6.173259922102322383581944548809393545442_wp
   real(wp), parameter :: v9_a61 = 0.5112275589406060872792270881648288397197e-1_wp
   real(wp), parameter :: v9_a64 = 0.1770823794555021537929910813839068684087_wp
   real(wp), parameter :: v9_a65 = 0.80277624092225014536138698108025283759e-3_wp
   real(wp), parameter :: v9_a71 = 0.1316006357975216279279871693164256985334_wp
   real(wp), parameter :: v9_a74 = -0.2957276252669636417685183174672273730699_wp
   real(wp), parameter :: v9_a75 = 0.878137803564295237421124704053886667082e-1_wp
   real(wp), parameter :: v9_a76 = 0.6213052975225274774321435005639430026100_wp
   real(wp), parameter :: v9_a81 = 0.7166666666666666666666666666666666666667e-1_wp
   real(wp), parameter :: v9_a86 = 0.3305533578915319409260346730051472207728_wp
   real(wp), parameter :: v9_a87 = 0.2427799754418013924072986603281861125606_wp
   real(wp), parameter :: v9_a91 = 0.7180664062500000000000000000000000000000e-1_wp
   real(wp), parameter :: v9_a96 = 0.3294380283228177160744825466257672816401_wp
   real(wp), parameter :: v9_a97 = 0.1165190029271822839255174533742327183599_wp
   real(wp), parameter :: v9_a98 = -0.3401367187500000000000000000000000000000e-1_wp
   real(wp), parameter :: v9_a101 = 0.4836757646340646986611287718844085773549e-1_wp
   real(wp), parameter :: v9_a106 = 0.3928989925676163974333190042057047002852e-1_wp
   real(wp), parameter :: v9_a107 = 0.1054740945890344608263649267140088017604_wp
   real(wp), parameter :: v9_a108 = -0.2143865284648312665982642293830533996214e-1_wp
   real(wp), parameter :: v9_a109 = -0.1041229174627194437759832813847147895623_wp
   real(wp), parameter :: v9_a111 = -0.2664561487201478635337289243849737340534e-1_wp
   real(wp), parameter :: v9_a116 = 0.3333333333333333333333333333333333333333e-1_wp
   real(wp), parameter :: v9_a117 = -0.1631072244872467239162704487554706387141_wp
   real(wp), parameter :: v9_a118 = 0.3396081684127761199487954930015522928244e-1_wp
   real(wp), parameter :: v9_a119 = 0.1572319413814626097110769806810024118077_wp
   real(wp), parameter :: v9_a1110 = 0.2152267478031879552303534778794770376960_wp
   real(wp), parameter :: v9_a121 = 0.3689009248708622334786359863227633989718e-1_wp
   real(wp), parameter :: v9_a126 = -0.1465181576725542928653609891758501156785_wp
   real(wp), parameter :: v9_a127 = 0.2242577768172024345345469822625833796001_wp
   real(wp), parameter :: v9_a128 = 0.2294405717066072637090897902753790803034e-1_wp
   real(wp), parameter :: v9_a129 = -0.35850052905728761357394424889330334334e-2_wp
   real(wp), parameter :: v9_a1210 = 0.8669223316444385506869203619044453906053e-1_wp
   real(wp), parameter :: v9_a1211 = 0.4383840651968337846196219974168630120572_wp
   real(wp), parameter :: v9_a131 = -0.4866012215113340846662212357570395295088_wp
   real(wp), parameter :: v9_a136 = -6.304602650282852990657772792012007122988_wp
   real(wp), parameter :: v9_a137 = -0.281245618289472564778284183790118418111_wp
   real(wp), parameter :: v9_a138 = -2.679019236219849057687906597489223155566_wp
   real(wp), parameter :: v9_a139 = 0.518815663924157511565311164615012522024_wp
   real(wp), parameter :: v9_a1310 = 1.365353187603341710683633635235238678626_wp
   real(wp), parameter :: v9_a1311 = 5.885091088503946585721274891680604830712_wp
   real(wp), parameter :: v9_a1312 = 2.802808786272062889819965117517532194812_wp
   real(wp), parameter :: v9_a141 = 0.4185367457753471441471025246471931649633_wp
   real(wp), parameter :: v9_a146 = 6.724547581906459363100870806514855026676_wp
   real(wp), parameter :: v9_a147 = -0.425444280164611790606983409697113064616_wp
   real(wp), parameter :: v9_a148 = 3.343279153001265577811816947557982637749_wp
   real(wp), parameter :: v9_a149 = 0.617081663117537759528421117507709784737_wp
   real(wp), parameter :: v9_a1410 = -0.929966123939932833937749523988800852013_wp
   real(wp), parameter :: v9_a1411 = -6.099948804751010722472962837945508844846_wp
   real(wp), parameter :: v9_a1412 = -3.002206187889399044804158084895173690015_wp
   real(wp), parameter :: v9_a1413 = 0.2553202529443445472336424602988558373637_wp
   real(wp), parameter :: v9_a151 = -0.779374086122884664644623040843840506343_wp
   real(wp), parameter :: v9_a156 = -13.93734253810777678786523664804936051203_wp
   real(wp), parameter :: v9_a157 = 1.252048853379357320949735183924200895136_wp
   real(wp), parameter :: v9_a158 = -14.69150040801686878191527989293072091588_wp
   real(wp), parameter :: v9_a159 = -0.494705058533141685655191992136962873577_wp
   real(wp), parameter :: v9_a1510 = 2.242974909146236657906984549543692874755_wp
   real(wp), parameter :: v9_a1511 = 13.36789380382864375813864978592679139881_wp
   real(wp), parameter :: v9_a1512 = 14.39665048665068644512236935340272139005_wp
   real(wp), parameter :: v9_a1513 = -0.7975813331776800379127866056663258667437_wp
   real(wp), parameter :: v9_a1514 = 0.4409353709534277758753793068298041158235_wp
   real(wp), parameter :: v9_a161 = 2.058051337466886442151242368989994043993_wp
   real(wp), parameter :: v9_a166 = 22.35793772796803295519317565842520212899_wp
   real(wp), parameter :: v9_a167 = 0.90949810997556332745009198137971890783_wp
   real(wp), parameter :: v9_a168 = 35.89110098240264104710550686568482456493_wp
   real(wp), parameter :: v9_a169 = -3.442515027624453437985000403608480262211_wp
   real(wp), parameter :: v9_a1610 = -4.865481358036368826566013387928704014496_wp
   real(wp), parameter :: v9_a1611 = -18.90980381354342625688427480879773032857_wp
   real(wp), parameter :: v9_a1612 = -34.26354448030451782929251177395134170515_wp
   real(wp), parameter :: v9_a1613 = 1.264756521695642578827783499806516664686_wp
   ! weights of the 9th-order formula
   real(wp), parameter :: v9_b1 = 0.1461197685842315252051541915018784713459e-1_wp
   real(wp), parameter :: v9_b8 = -0.3915211862331339089410228267288242030810_wp
   real(wp), parameter :: v9_b9 = 0.2310932500289506415909675644868993669908_wp
   real(wp), parameter :: v9_b10 = 0.1274766769992852382560589467488989175618_wp
   real(wp), parameter :: v9_b11 = 0.2246434176204157731566981937082069688984_wp
   real(wp), parameter :: v9_b12 = 0.5684352689748512932705226972873692126743_wp
   real(wp), parameter :: v9_b13 = 0.5825871557215827200814768021863420902155e-1_wp
   real(wp), parameter :: v9_b14 = 0.1364317403482215641609022744494239843327_wp
   real(wp), parameter :: v9_b15 = 0.3057013983082797397721005067920369646664e-1_wp
   ! weights of the embedded 8th-order formula
   real(wp), parameter :: v9_bh1 = 0.1996996514886773085518508418098868756464e-1_wp
   real(wp), parameter :: v9_bh8 = 2.191499304949330054530747099310837524864_wp
   real(wp), parameter :: v9_bh9 = 0.8857071848208438030833722031786358862953e-1_wp
   real(wp), parameter :: v9_bh10 = 0.1140560234865965622484956605091432032674_wp
   real(wp), parameter :: v9_bh11 = 0.2533163805345107065564577734569651977347_wp
   real(wp), parameter :: v9_bh12 = -2.056564386240941011158999594595981300493_wp
   real(wp), parameter :: v9_bh13 = 0.3408096799013119935160094894224543812830_wp
   real(wp), parameter :: v9_bh16 = 0.4834231373823958314376726739772871714902e-1_wp
   real(wp), parameter :: v9_e1 = v9_bh1 - v9_b1, v9_e8 = v9_bh8 - v9_b8, v9_e9 = v9_bh9 - v9_b9, &
      v9_e10 = v9_bh10 - v9_b10, v9_e11 = v9_bh11 - v9_b11, v9_e12 = v9_bh12 - v9_b12, &
      v9_e13 = v9_bh13 - v9_b13, v9_e14 = -v9_b14, v9_e15 = -v9_b15, v9_e16 = v9_bh16

   !> A view of one stage vector (a column of the stage array, or the trial state).
   type :: stage_view_t
      real(wp), pointer, contiguous :: v(:) => null()
   end type stage_view_t

   !> Pointer views of the trial state, the new state and the stage derivatives, set
   !> once per integration: handing these to `rhs` passes an existing array descriptor,
   !> where an array section (k(:, j)) would build a fresh one on every evaluation.
   type :: stage_views_t
      type(stage_view_t) :: y_stage, y_new
      type(stage_view_t) :: f(17)
   end type stage_views_t

   !> Unit round-off used in the step-size underflow test (Hairer's UROUND).
   real(wp), parameter :: unit_roundoff = epsilon(1.0_wp)

   !> Step-control parameters resolved from the options and the method defaults.
   type :: controller_t
      real(wp) :: safety, beta, fac_min, fac_max, exponent, h_max
      real(wp) :: fac_old = 1.0e-4_wp   !! previous accepted error (Hairer's FACOLD)
   end type controller_t

contains

   !> Default observer: does nothing. Overrides are called after the initial point and
   !> after every accepted step; setting `stop` ends the integration there
   !> (rk_integrate then returns t = step%t, no error).
   subroutine rk_observe(self, step, stop)
      class(rk_system_t), intent(inout) :: self  !! the system and its data
      type(rk_step_t), intent(in) :: step       !! the step just accepted (index 0: initial point)
      logical, intent(inout) :: stop            !! set .true. to stop after this step
   end subroutine rk_observe

   !> Name of a method constant.
   pure function rk_method_name(method) result(name)
      integer, intent(in) :: method  !! rk_dopri5, rk_dop853, rk_pd87 or rk_vern98
      character(len=:), allocatable :: name
      select case (method)
      case (rk_dopri5); name = "dopri5"
      case (rk_dop853); name = "dop853"
      case (rk_pd87); name = "pd87"
      case (rk_vern98); name = "vern98"
      case default; name = "unknown"
      end select
   end function rk_method_name

   !> Classical order of the propagating formula (5, 8 or 9; 0 if unknown).
   pure integer function rk_method_order(method) result(order)
      integer, intent(in) :: method  !! rk_dopri5, rk_dop853, rk_pd87 or rk_vern98
      select case (method)
      case (rk_dopri5); order = 5
      case (rk_dop853, rk_pd87); order = 8
      case (rk_vern98); order = 9
      case default; order = 0
      end select
   end function rk_method_order

   !> The Butcher tableau of rk_vern98 (Verner's RKV98.IIa Efficient) as the integrator
   !> uses it, for checks of its order conditions: nodes c, coupling coefficients a (strictly
   !> lower triangular), weights b of the 9th-order and b_embedded of the 8th-order formula.
   pure subroutine rk_vern98_tableau(c, a, b, b_embedded)
      real(wp), intent(out) :: c(16)           !! nodes
      real(wp), intent(out) :: a(16, 16)       !! a(i, j), zero for j >= i
      real(wp), intent(out) :: b(16)           !! weights of the propagating 9th-order formula
      real(wp), intent(out) :: b_embedded(16)  !! weights of the 8th-order formula
      c = 0.0_wp
      a = 0.0_wp
      b = 0.0_wp
      b_embedded = 0.0_wp
      c(2:14) = [v9_c2, v9_c3, v9_c4, v9_c5, v9_c6, v9_c7, v9_c8, v9_c9, v9_c10, v9_c11, v9_c12, v9_c13, &
                  v9_c14]
      c(15:16) = 1.0_wp
      a(2, [1]) = [v9_a21]
      a(3, [1, 2]) = [v9_a31, v9_a32]
      a(4, [1, 3]) = [v9_a41, v9_a43]
      a(5, [1, 3, 4]) = [v9_a51, v9_a53, v9_a54]
      a(6, [1, 4, 5]) = [v9_a61, v9_a64, v9_a65]
      a(7, [1, 4, 5, 6]) = [v9_a71, v9_a74, v9_a75, v9_a76]
      a(8, [1, 6, 7]) = [v9_a81, v9_a86, v9_a87]
      a(9, [1, 6, 7, 8]) = [v9_a91, v9_a96, v9_a97, v9_a98]
      a(10, [1, 6, 7, 8, 9]) = [v9_a101, v9_a106, v9_a107, v9_a108, v9_a109]
      a(11, [1, 6, 7, 8, 9, 10]) = [v9_a111, v9_a116, v9_a117, v9_a118, v9_a119, v9_a1110]
      a(12, [1, 6, 7, 8, 9, 10, 11]) = [v9_a121, v9_a126, v9_a127, v9_a128, v9_a129, v9_a1210, v9_a1211]
      a(13, [1, 6, 7, 8, 9, 10, 11, 12]) = [v9_a131, v9_a136, v9_a137, v9_a138, v9_a139, v9_a1310, v9_a1311, v9_a1312]
      a(14, [1, 6, 7, 8, 9, 10, 11, 12, 13]) = [v9_a141, v9_a146, v9_a147, v9_a148, v9_a149, v9_a1410, &
         v9_a1411, v9_a1412, v9_a1413]
      a(15, [1, 6, 7, 8, 9, 10, 11, 12, 13, 14]) = [v9_a151, v9_a156, v9_a157, v9_a158, v9_a159, v9_a1510, &
         v9_a1511, v9_a1512, v9_a1513, v9_a1514]
      a(16, [1, 6, 7, 8, 9, 10, 11, 12, 13]) = [v9_a161, v9_a166, v9_a167, v9_a168, v9_a169, v9_a1610, &
         v9_a1611, v9_a1612, v9_a1613]
      b([1, 8, 9, 10, 11, 12, 13, 14, 15]) = [v9_b1, v9_b8, v9_b9, v9_b10, v9_b11, v9_b12, v9_b13, v9_b14, v9_b15]
      b_embedded([1, 8, 9, 10, 11, 12, 13, 16]) = [v9_bh1, v9_bh8, v9_bh9, v9_bh10, v9_bh11, v9_bh12, v9_bh13, &
                                                   v9_bh16]
   end subroutine rk_vern98_tableau

   !> Largest admissible PI parameter β of a method (exclusive). The controller divides h
   !> by err^(k − cβ)/err_old^β (k = 1/8 and c = 0.2 for the 8th-order pairs, 1/9 for
   !> VERN98, 1/5 and c = 0.75 for DOPRI5); with err = err_old = e in a steady state the
   !> step stays put where e^(k − (1 + c)β) = safety, which keeps e below 1 only while
   !> k − (1 + c)β > 0. At and above that β the fixed point moves to e > 1 (every step
   !> rejected) or, through the rejections, to e → 0: the steps collapse. Hairer's codes
   !> accept any β ≤ 0.2.
   pure real(wp) function rk_beta_limit(method) result(limit)
      integer, intent(in) :: method  !! a method constant
      select case (method)
      case (rk_dopri5); limit = 0.2_wp/1.75_wp
      case (rk_dop853, rk_pd87, rk_vern98); limit = (1.0_wp/rk_method_order(method))/1.2_wp
      case default; limit = 0.0_wp
      end select
   end function rk_beta_limit

   !> The continuous extension of `step` at time t (t in [t_old, t]; mild
   !> extrapolation is allowed but not accurate). `step` must come from rk_integrate
   !> (its arrays are allocated there). Hairer's CONTD5/CONTD8 form:
   !> y = d0 + s(d1 + s'(d2 + s(d3 + s'(d4 + s(d5 + s'(d6 + s d7)))))), s = (t − t_old)/h, s' = 1 − s.
   pure function rk_dense_value(step, t) result(y)
      type(rk_step_t), intent(in) :: step  !! an accepted step with its dense coefficients
      real(wp), intent(in) :: t            !! where to evaluate
      real(wp) :: y(size(step%y))
      real(wp) :: s, s1
      if (t == step%t .or. step%h == 0.0_wp) then
         y = step%y
         return
      end if
      s = (t - step%t_old)/step%h
      s1 = 1.0_wp - s
      associate (d => step%dense)
         y = d(:, 0) + s*(d(:, 1) + s1*(d(:, 2) + s*(d(:, 3) + s1*(d(:, 4) &
             + s*(d(:, 5) + s1*(d(:, 6) + s*d(:, 7)))))))
      end associate
   end function rk_dense_value

   !> Integrate y' = f(t, y) from t to t_end.
   !>
   !> Adaptive mode (default): local error per step kept below rtol·|y| + atol in
   !> Hairer's norm; fixed-step mode (`options%fixed_steps` = N > 0): N equal steps,
   !> no error control. On return t is where the integration ended (t_end unless an
   !> observer stopped it or it failed) and y the state there. On failure `error` is
   !> allocated (code err_integration or err_invalid_parameter) and t, y hold the last
   !> accepted point, never a non-finite value.
   subroutine rk_integrate(system, t, t_end, y, options, stats, error, t_out, y_out, h_next)
      class(rk_system_t), intent(inout) :: system  !! right-hand side, its data and its observer
      real(wp), intent(inout) :: t             !! start in, end reached out
      real(wp), intent(in) :: t_end            !! end of the interval (t_end < t integrates backwards)
      real(wp), intent(inout) :: y(:)          !! initial state in, final state out
      type(rk_options_t), intent(in) :: options  !! method, tolerances, step control
      type(work_stats_t), intent(out), optional :: stats  !! accepted steps, rejected steps (including
                                                          !! those of the first step, which Hairer's
                                                          !! codes do not count), f-evaluations
      type(error_t), allocatable, intent(out) :: error    !! allocated on failure
      real(wp), intent(in), optional :: t_out(:)  !! output times, monotone from t towards t_end
      real(wp), intent(out), optional :: y_out(:, :)  !! (size(y), size(t_out)) dense output there
      real(wp), intent(out), optional :: h_next  !! predicted next step (to resume an integration)

      type(work_stats_t) :: work
      type(controller_t) :: control
      type(rk_step_t) :: step
      real(wp), allocatable, target :: k(:, :), y_new(:), y_stage(:)
      real(wp), allocatable :: atol(:)
      type(stage_views_t) :: views
      real(wp) :: h, h_new, direction, err, fac11, fac, span
      integer :: n, n_stages, stage, next_out, attempts
      logical :: finite, last, rejected_before, stop, want_dense
      character(len=160) :: message

      n = size(y)
      work = work_stats_t()
      if (present(h_next)) h_next = 0.0_wp
      call check_arguments(error)
      if (allocated(error)) then
         if (present(stats)) stats = work
         return
      end if

      if (allocated(options%atol_components)) then
         atol = options%atol_components
      else
         allocate (atol(n), source=options%atol)
      end if
      want_dense = present(t_out) .or. options%dense_output
      select case (options%method)
      case (rk_dopri5); n_stages = 7
      case (rk_vern98); n_stages = 17   ! 16 stages and f at the new point
      case default; n_stages = 16
      end select
      allocate (k(n, n_stages), y_new(n), y_stage(n))
      views%y_stage%v => y_stage
      views%y_new%v => y_new
      do stage = 1, n_stages
         views%f(stage)%v => k(:, stage)
      end do
      allocate (step%y(n), step%dense(n, 0:7))
      step%method = options%method
      step%dense = 0.0_wp
      step%t_old = t; step%t = t; step%h = 0.0_wp; step%y = y
      direction = sign(1.0_wp, t_end - t)
      span = abs(t_end - t)
      next_out = 1
      if (present(t_out)) call fill_outputs()
      if (t == t_end) then
         call finish()
         return
      end if

      call evaluate(t, y, k(:, 1))
      if (.not. finite) then
         call fail_non_finite(t, "initial state")
         return
      end if

      stop = .false.
      call system%observe(step, stop)
      if (stop) then
         call finish()
         return
      end if

      if (options%fixed_steps > 0) then
         call integrate_fixed()
      else
         call integrate_adaptive()
      end if
      if (.not. allocated(error)) call finish()

   contains

      subroutine check_arguments(error)
         type(error_t), allocatable, intent(out) :: error
         if (options%method /= rk_dopri5 .and. options%method /= rk_dop853 .and. options%method /= rk_pd87 &
             .and. options%method /= rk_vern98) then
            call set_error(error, err_invalid_parameter, "rk_integrate: unknown method")
         else if ((options%method == rk_pd87 .or. options%method == rk_vern98) &
                  .and. (present(t_out) .or. options%dense_output)) then
            call set_error(error, err_invalid_parameter, "rk_integrate: "//rk_method_name(options%method)// &
               " has no continuous extension of its order; use dop853 for t_out or dense_output")
         else if (n < 1) then
            call set_error(error, err_invalid_parameter, "rk_integrate: empty state vector")
         else if (.not. (ieee_is_finite(t) .and. ieee_is_finite(t_end))) then
            call set_error(error, err_invalid_parameter, "rk_integrate: t and t_end must be finite")
         else if (.not. all(ieee_is_finite(y))) then
            call set_error(error, err_invalid_parameter, "rk_integrate: non-finite initial state")
         else if (.not. all(ieee_is_finite([options%rtol, options%atol, options%h_initial, options%h_max, &
                                            options%safety, options%beta, options%fac_min, options%fac_max]))) then
            call set_error(error, err_invalid_parameter, "rk_integrate: non-finite option")
         else if (options%fixed_steps < 0) then
            call set_error(error, err_invalid_parameter, "rk_integrate: fixed_steps must be >= 0")
         else if (options%fixed_steps == 0 .and. (options%rtol < 0.0_wp .or. options%atol <= 0.0_wp)) then
            call set_error(error, err_invalid_parameter, "rk_integrate: need rtol >= 0 and atol > 0")
         else if (.not. atol_components_valid()) then
            call set_error(error, err_invalid_parameter, &
               "rk_integrate: atol_components must have the size of y, be finite and > 0")
         else if (options%max_steps < 1) then
            call set_error(error, err_invalid_parameter, "rk_integrate: max_steps must be >= 1")
         else if (options%safety <= 1.0e-4_wp .or. options%safety >= 1.0_wp) then
            call set_error(error, err_invalid_parameter, "rk_integrate: safety must lie in (1e-4, 1)")
         else if (options%beta >= rk_beta_limit(options%method)) then
            write (message, '(a,es10.3,a,f6.4,a)') "rk_integrate: beta = ", options%beta, " must be < ", &
               rk_beta_limit(options%method), " for "//rk_method_name(options%method)// &
               " (above it the step control drives the error towards zero and the steps collapse)"
            call set_error(error, err_invalid_parameter, trim(message))
         else if (options%h_max < 0.0_wp) then
            call set_error(error, err_invalid_parameter, "rk_integrate: h_max must be >= 0")
         else if (options%fac_min > 1.0_wp .or. (options%fac_max > 0.0_wp .and. options%fac_max < 1.0_wp)) then
            call set_error(error, err_invalid_parameter, "rk_integrate: need fac_min <= 1 <= fac_max")
         else if (present(t_out) .neqv. present(y_out)) then
            call set_error(error, err_invalid_parameter, "rk_integrate: t_out and y_out go together")
         else if (present(t_out)) then
            if (size(y_out, 1) /= n .or. size(y_out, 2) /= size(t_out)) then
               call set_error(error, err_invalid_parameter, "rk_integrate: y_out must be (size(y), size(t_out))")
            else if (.not. all(ieee_is_finite(t_out))) then
               call set_error(error, err_invalid_parameter, "rk_integrate: non-finite output time")
            else if (.not. outputs_ordered()) then
               call set_error(error, err_invalid_parameter, &
                  "rk_integrate: t_out must be monotone from t towards t_end and lie in between")
            end if
         end if
      end subroutine check_arguments

      logical function atol_components_valid() result(valid)
         valid = .true.
         if (.not. allocated(options%atol_components)) return
         valid = size(options%atol_components) == n
         if (valid) valid = all(ieee_is_finite(options%atol_components)) .and. all(options%atol_components > 0.0_wp)
      end function atol_components_valid

      logical function outputs_ordered()
         real(wp) :: dir, previous
         integer :: j
         dir = sign(1.0_wp, t_end - t)
         previous = t
         outputs_ordered = .true.
         do j = 1, size(t_out)
            if ((t_out(j) - previous)*dir < 0.0_wp .or. (t_out(j) - t_end)*dir > 0.0_wp) then
               outputs_ordered = .false.
               return
            end if
            previous = t_out(j)
         end do
      end function outputs_ordered

      !> dydt = f(t, y), counted, with a finiteness check (sets `finite`).
      subroutine evaluate(tau, state, dydt)
         real(wp), intent(in) :: tau, state(:)
         real(wp), intent(out) :: dydt(:)
         call system%rhs(tau, state, dydt)
         if (stage_failed(n, dydt, finite, work%n_evaluations)) return
      end subroutine evaluate

      subroutine fail_non_finite(tau, where)
         real(wp), intent(in) :: tau
         character(len=*), intent(in) :: where
         write (message, '(a,es24.16,a)') "rk_integrate: non-finite derivative at t = ", tau, " ("//where//")"
         call set_error(error, err_integration, trim(message))
         call finish()
      end subroutine fail_non_finite

      !> Fill the outputs up to the current step (dense output on [t_old, t]).
      subroutine fill_outputs()
         do while (next_out <= size(t_out))
            if ((t_out(next_out) - step%t)*direction > 0.0_wp) exit
            if (t_out(next_out) == step%t) then
               y_out(:, next_out) = step%y
            else
               y_out(:, next_out) = rk_dense_value(step, t_out(next_out))
            end if
            next_out = next_out + 1
         end do
      end subroutine fill_outputs

      subroutine finish()
         t = step%t
         y = step%y
         if (present(stats)) stats = work
      end subroutine finish

      !> Record an accepted step from step%t to t_new with state y_new; k(:, 1) is
      !> f at the old point and k(:, j_new) f at the new point, which then moves into
      !> k(:, 1) for the next step.
      subroutine accept(t_new, j_new)
         real(wp), intent(in) :: t_new
         integer, intent(in) :: j_new
         real(wp) :: h_step, d1, d2
         integer :: i
         h_step = t_new - step%t
         ! cubic Hermite part shared by all four pairs (Hairer's CONT(1..4))
         !GCC$ novector
         do i = 1, n
            d1 = y_new(i) - step%y(i)
            d2 = h_step*k(i, 1) - d1
            step%dense(i, 0) = step%y(i)
            step%dense(i, 1) = d1
            step%dense(i, 2) = d2
            step%dense(i, 3) = d1 - h_step*k(i, j_new) - d2
            step%y(i) = y_new(i)
            k(i, 1) = k(i, j_new)
         end do
         step%dense_order = 3
         step%t_old = step%t
         step%t = t_new
         step%h = h_step
         step%index = step%index + 1
         work%n_steps = work%n_steps + 1
      end subroutine accept

      !> Hairer's HINIT: h such that h^order · max(‖f0‖, ‖f'‖) ≈ 0.01, using one Euler step.
      real(wp) function initial_step(order) result(h_guess)
         integer, intent(in) :: order
         real(wp) :: sk(n), dnf, dny, der2, der12, h0, h1
         sk = atol + options%rtol*abs(y)
         dnf = sum((k(:, 1)/sk)**2)
         dny = sum((y/sk)**2)
         if (dnf <= 1.0e-10_wp .or. dny <= 1.0e-10_wp) then
            h0 = 1.0e-6_wp
         else
            h0 = sqrt(dny/dnf)*0.01_wp
         end if
         h0 = min(h0, control%h_max)
         y_stage = y + direction*h0*k(:, 1)
         call evaluate(t + direction*h0, y_stage, k(:, 2))
         if (.not. finite) then
            h_guess = 1.0e-6_wp*span   ! the first real step will meet the problem and report it
            return
         end if
         der2 = sqrt(sum(((k(:, 2) - k(:, 1))/sk)**2))/h0
         der12 = max(der2, sqrt(dnf))
         if (der12 <= 1.0e-15_wp) then
            h1 = max(1.0e-6_wp, h0*1.0e-3_wp)
         else
            h1 = (0.01_wp/der12)**(1.0_wp/order)
         end if
         h_guess = min(100.0_wp*h0, h1, control%h_max)
      end function initial_step

      subroutine integrate_fixed()
         integer :: i
         h = (t_end - t)/options%fixed_steps
         do i = 1, options%fixed_steps
            call attempt(step%t, h, with_error=.false.)
            if (.not. finite) then
               call fail_non_finite(step%t, "fixed step")
               return
            end if
            if (i == options%fixed_steps) then
               call complete_step(t_end)
            else
               call complete_step(t + i*h)
            end if
            if (allocated(error)) return
            if (stop) exit
         end do
         if (present(h_next)) h_next = h
      end subroutine integrate_fixed

      subroutine integrate_adaptive()
         integer :: order
         order = rk_method_order(options%method)
         control%safety = options%safety
         if (options%method == rk_dopri5) then
            control%beta = merge(options%beta, 0.04_wp, options%beta >= 0.0_wp)
            control%fac_min = merge(options%fac_min, 0.2_wp, options%fac_min > 0.0_wp)
            control%fac_max = merge(options%fac_max, 10.0_wp, options%fac_max > 0.0_wp)
            control%exponent = 0.2_wp - 0.75_wp*control%beta
         else
            control%beta = merge(options%beta, 0.0_wp, options%beta >= 0.0_wp)
            control%fac_min = merge(options%fac_min, 0.333_wp, options%fac_min > 0.0_wp)
            control%fac_max = merge(options%fac_max, 6.0_wp, options%fac_max > 0.0_wp)
            ! the error estimate is of order p − 1 (local error ~ h^p, p the propagating order:
            ! 8, or 9 for VERN98): h ∝ err^(-1/p)
            control%exponent = 1.0_wp/order - 0.2_wp*control%beta
         end if
         control%h_max = merge(options%h_max, span, options%h_max > 0.0_wp)
         control%fac_old = 1.0e-4_wp

         if (options%h_initial /= 0.0_wp) then
            h = min(abs(options%h_initial), control%h_max)
         else
            h = initial_step(order)
         end if
         h = direction*h
         rejected_before = .false.
         last = .false.
         attempts = 0
         do
            if (attempts >= options%max_steps) then
               write (message, '(a,i0,a,es24.16)') "rk_integrate: more than max_steps = ", options%max_steps, &
                  " steps needed; stopped at t = ", step%t
               call set_error(error, err_integration, trim(message))
               call finish()
               return
            end if
            if (0.1_wp*abs(h) <= abs(step%t)*unit_roundoff .or. abs(h) < tiny(1.0_wp)) then
               write (message, '(a,es10.3,a,es24.16)') "rk_integrate: step size underflow, h = ", h, &
                  " at t = ", step%t
               call set_error(error, err_integration, trim(message))
               call finish()
               return
            end if
            if ((step%t + 1.01_wp*h - t_end)*direction > 0.0_wp) then
               h = t_end - step%t
               last = .true.
            else
               ! make t + h exact, so that the solution is advanced by exactly the time that
               ! t moves: otherwise each step's rounding of t is a jump of the coefficient
               ! (a phase error √q·ulp(t) per step, a random walk of 1e-12 in S over the
               ! ~1e4 steps of β = 1e5)
               h = (step%t + h) - step%t
            end if
            attempts = attempts + 1

            call attempt(step%t, h, with_error=.true., err=err)
            if (.not. finite) then
               call fail_non_finite(step%t, "trial step")
               return
            end if

            if (control%exponent == 0.125_wp) then
               fac11 = sqrt(sqrt(sqrt(err)))  ! DOP853's err^(1/8) without a pow call
            else
               fac11 = err**control%exponent
            end if
            ! Lund stabilisation (PI control): divide by the previous error to the power beta
            fac = fac11
            if (control%beta /= 0.0_wp) fac = fac11/control%fac_old**control%beta
            fac = max(1.0_wp/control%fac_max, min(1.0_wp/control%fac_min, fac/control%safety))
            h_new = h/fac
            if (err <= 1.0_wp) then
               control%fac_old = max(err, 1.0e-4_wp)
               if (last) then
                  call complete_step(t_end)
               else
                  call complete_step(step%t + h)
               end if
               if (allocated(error)) return
               if (last .or. stop) exit
               if (abs(h_new) > control%h_max) h_new = direction*control%h_max
               if (rejected_before) h_new = direction*min(abs(h_new), abs(h))
               rejected_before = .false.
            else
               h_new = h/min(1.0_wp/control%fac_min, fac11/control%safety)
               rejected_before = .true.
               last = .false.
               work%n_rejected = work%n_rejected + 1
            end if
            h = h_new
         end do
         if (present(h_next)) h_next = direction*min(abs(h_new), control%h_max)
      end subroutine integrate_adaptive

      !> Compute the stages of one step of size hh from (tau, step%y) into k and y_new;
      !> with_error: also the scaled error norm `err` (Hairer's). Sets `finite`.
      subroutine attempt(tau, hh, with_error, err)
         real(wp), intent(in) :: tau, hh
         logical, intent(in) :: with_error
         real(wp), intent(out), optional :: err
         select case (options%method)
         case (rk_dopri5)
            call dopri5_stages(tau, hh, with_error, err)
         case (rk_pd87)
            call pd87_stages(tau, hh, with_error, err)
         case (rk_vern98)
            call vern98_stages(tau, hh, with_error, err)
         case default
            call dop853_stages(tau, hh, with_error, err)
         end select
      end subroutine attempt

      subroutine dopri5_stages(tau, hh, with_error, err)
         real(wp), intent(in) :: tau, hh
         logical, intent(in) :: with_error
         real(wp), intent(out), optional :: err
         real(wp) :: e
         call dopri5_kernel(system, n, tau, hh, step%y, k, y_stage, y_new, views, atol, options%rtol, with_error, e, &
                            finite, work%n_evaluations)
         if (present(err)) err = e
      end subroutine dopri5_stages

      subroutine pd87_stages(tau, hh, with_error, err)
         real(wp), intent(in) :: tau, hh
         logical, intent(in) :: with_error
         real(wp), intent(out), optional :: err
         real(wp) :: e
         call pd87_kernel(system, n, tau, hh, step%y, k, y_stage, y_new, views, atol, options%rtol, with_error, e, &
                          finite, work%n_evaluations)
         if (present(err)) err = e
      end subroutine pd87_stages

      subroutine vern98_stages(tau, hh, with_error, err)
         real(wp), intent(in) :: tau, hh
         logical, intent(in) :: with_error
         real(wp), intent(out), optional :: err
         real(wp) :: e
         call vern98_kernel(system, n, tau, hh, step%y, k, y_stage, y_new, views, atol, options%rtol, with_error, e, &
                            finite, work%n_evaluations)
         if (present(err)) err = e
      end subroutine vern98_stages

      subroutine dop853_stages(tau, hh, with_error, err)
         real(wp), intent(in) :: tau, hh
         logical, intent(in) :: with_error
         real(wp), intent(out), optional :: err
         real(wp) :: e
         call dop853_kernel(system, n, tau, hh, step%y, k, y_stage, y_new, views, atol, options%rtol, with_error, e, &
                            finite, work%n_evaluations)
         if (present(err)) err = e
      end subroutine dop853_stages

      !> After a successful attempt: evaluate f at the new point (DOP853, PD87, VERN98; DOPRI5 has it),
      !> build the dense output, record the step (which moves f(new) into k(:, 1) for
      !> the next step), serve outputs and the observer.
      subroutine complete_step(t_new)
         real(wp), intent(in) :: t_new
         real(wp) :: hh
         integer :: i, j_new
         hh = t_new - step%t
         if (options%method == rk_dopri5) then
            ! Shampine's 4th-order interpolant: the Hermite part plus h·Σ d_i k_i
            !GCC$ novector
            do i = 1, n
               step%dense(i, 4) = hh*(p5_d1*k(i, 1) + p5_d3*k(i, 3) + p5_d4*k(i, 4) + p5_d5*k(i, 5) &
                                      + p5_d6*k(i, 6) + p5_d7*k(i, 7))
            end do
            call accept(t_new, 7)
            step%dense_order = 4
         else
            ! f at the new point, in the column after the stages (DOP853 13, PD87 14, VERN98 17)
            select case (options%method)
            case (rk_pd87); j_new = 14
            case (rk_vern98); j_new = 17
            case default; j_new = 13
            end select
            call evaluate(t_new, views%y_new%v, views%f(j_new)%v)
            if (.not. finite) then
               call fail_non_finite(t_new, "end of accepted step")
               return
            end if
            if (want_dense) then  ! DOP853 only: the others refuse dense output
               call dop853_dense(hh)
               if (.not. finite) then
                  call fail_non_finite(step%t, "dense output stage")
                  return
               end if
            end if
            call accept(t_new, j_new)
            if (want_dense) step%dense_order = 7
         end if
         if (present(t_out)) call fill_outputs()
         call system%observe(step, stop)
      end subroutine complete_step

      !> DOP853's 7th-order continuous extension: three more stages (14–16) and the
      !> coefficients d4..d7 of CONTD8, stored in step%dense(:, 4:7). Uses the stages of
      !> the step from step%t with size hh; k(:, 13) holds f at the new point.
      subroutine dop853_dense(hh)
         real(wp), intent(in) :: hh
         associate (y0 => step%y, d => step%dense)
            d(:, 4) = p8_d41*k(:, 1) + p8_d46*k(:, 6) + p8_d47*k(:, 7) + p8_d48*k(:, 8) + p8_d49*k(:, 9) &
                      + p8_d410*k(:, 10) + p8_d411*k(:, 11) + p8_d412*k(:, 12)
            d(:, 5) = p8_d51*k(:, 1) + p8_d56*k(:, 6) + p8_d57*k(:, 7) + p8_d58*k(:, 8) + p8_d59*k(:, 9) &
                      + p8_d510*k(:, 10) + p8_d511*k(:, 11) + p8_d512*k(:, 12)
            d(:, 6) = p8_d61*k(:, 1) + p8_d66*k(:, 6) + p8_d67*k(:, 7) + p8_d68*k(:, 8) + p8_d69*k(:, 9) &
                      + p8_d610*k(:, 10) + p8_d611*k(:, 11) + p8_d612*k(:, 12)
            d(:, 7) = p8_d71*k(:, 1) + p8_d76*k(:, 6) + p8_d77*k(:, 7) + p8_d78*k(:, 8) + p8_d79*k(:, 9) &
                      + p8_d710*k(:, 10) + p8_d711*k(:, 11) + p8_d712*k(:, 12)
            y_stage(:) = y0 + hh*(p8_a141*k(:, 1) + p8_a147*k(:, 7) + p8_a148*k(:, 8) + p8_a149*k(:, 9) &
                               + p8_a1410*k(:, 10) + p8_a1411*k(:, 11) + p8_a1412*k(:, 12) + p8_a1413*k(:, 13))
            call evaluate(step%t + p8_c14*hh, y_stage, k(:, 14)); if (.not. finite) return
            y_stage(:) = y0 + hh*(p8_a151*k(:, 1) + p8_a156*k(:, 6) + p8_a157*k(:, 7) + p8_a158*k(:, 8) &
                               + p8_a1511*k(:, 11) + p8_a1512*k(:, 12) + p8_a1513*k(:, 13) + p8_a1514*k(:, 14))
            call evaluate(step%t + p8_c15*hh, y_stage, k(:, 15)); if (.not. finite) return
            y_stage(:) = y0 + hh*(p8_a161*k(:, 1) + p8_a166*k(:, 6) + p8_a167*k(:, 7) + p8_a168*k(:, 8) &
                               + p8_a169*k(:, 9) + p8_a1613*k(:, 13) + p8_a1614*k(:, 14) + p8_a1615*k(:, 15))
            call evaluate(step%t + p8_c16*hh, y_stage, k(:, 16)); if (.not. finite) return
            d(:, 4) = hh*(d(:, 4) + p8_d413*k(:, 13) + p8_d414*k(:, 14) + p8_d415*k(:, 15) + p8_d416*k(:, 16))
            d(:, 5) = hh*(d(:, 5) + p8_d513*k(:, 13) + p8_d514*k(:, 14) + p8_d515*k(:, 15) + p8_d516*k(:, 16))
            d(:, 6) = hh*(d(:, 6) + p8_d613*k(:, 13) + p8_d614*k(:, 14) + p8_d615*k(:, 15) + p8_d616*k(:, 16))
            d(:, 7) = hh*(d(:, 7) + p8_d713*k(:, 13) + p8_d714*k(:, 14) + p8_d715*k(:, 15) + p8_d716*k(:, 16))
         end associate
      end subroutine dop853_dense
   end subroutine rk_integrate

   ! The stage loops below are written as scalar loops (`!GCC$ novector`): the right-hand
   ! side stores its result component by component, and a vector load of those components
   ! right after cannot be served from the store buffer (store-to-load forwarding fails),
   ! which stalled every stage for longer than its arithmetic takes on the small systems
   ! hillstab integrates (4 to 20 components). Measured on the pendulum (4 components):
   ! 35 → 28 ns per DOP853 evaluation (after the pointer views, 40 → 35).

   !> One trial step of size hh from (tau, y0): the stages into k, the new state into y_new
   !> and, with `with_error`, Hairer's scaled error norm. Module level with explicit-shape
   !> arrays (no host association, no descriptors) because this is the integrator's inner
   !> loop; `finite` is false as soon as a derivative is not finite (nothing more is done).
   subroutine dopri5_kernel(system, n, tau, hh, y0, k, y_stage, y_new, views, atol, rtol, with_error, err, finite, &
                            n_evaluations)
      class(rk_system_t), intent(inout) :: system
      integer, intent(in) :: n
      real(wp), intent(in) :: tau, hh, y0(n), atol(n), rtol
      real(wp), intent(inout), target :: k(n, *)
      real(wp), intent(out), target :: y_stage(n), y_new(n)
      type(stage_views_t), intent(in) :: views  !! the same y_stage, y_new and columns of k
      logical, intent(in) :: with_error
      real(wp), intent(out) :: err
      logical, intent(out) :: finite
      integer(int64), intent(inout) :: n_evaluations
      real(wp) :: e
      integer :: i
      err = 0.0_wp
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(p5_a21*k(i, 1))
      end do
      call system%rhs(tau + p5_c2*hh, views%y_stage%v, views%f(2)%v)
      if (stage_failed(n, k(:, 2), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(p5_a31*k(i, 1) + p5_a32*k(i, 2))
      end do
      call system%rhs(tau + p5_c3*hh, views%y_stage%v, views%f(3)%v)
      if (stage_failed(n, k(:, 3), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(p5_a41*k(i, 1) + p5_a42*k(i, 2) + p5_a43*k(i, 3))
      end do
      call system%rhs(tau + p5_c4*hh, views%y_stage%v, views%f(4)%v)
      if (stage_failed(n, k(:, 4), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(p5_a51*k(i, 1) + p5_a52*k(i, 2) + p5_a53*k(i, 3) + p5_a54*k(i, 4))
      end do
      call system%rhs(tau + p5_c5*hh, views%y_stage%v, views%f(5)%v)
      if (stage_failed(n, k(:, 5), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(p5_a61*k(i, 1) + p5_a62*k(i, 2) + p5_a63*k(i, 3) + p5_a64*k(i, 4) &
                                  + p5_a65*k(i, 5))
      end do
      call system%rhs(tau + hh, views%y_stage%v, views%f(6)%v)
      if (stage_failed(n, k(:, 6), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_new(i) = y0(i) + hh*(p5_a71*k(i, 1) + p5_a73*k(i, 3) + p5_a74*k(i, 4) + p5_a75*k(i, 5) &
                                + p5_a76*k(i, 6))
      end do
      ! stage 7 is f at the new point: first stage of the next step (FSAL)
      call system%rhs(tau + hh, views%y_new%v, views%f(7)%v)
      if (stage_failed(n, k(:, 7), finite, n_evaluations)) return
      if (with_error) then
         !GCC$ novector
         do i = 1, n
            e = hh*(p5_e1*k(i, 1) + p5_e3*k(i, 3) + p5_e4*k(i, 4) + p5_e5*k(i, 5) + p5_e6*k(i, 6) &
                    + p5_e7*k(i, 7))/(atol(i) + rtol*max(abs(y0(i)), abs(y_new(i))))
            err = err + e**2
         end do
         err = sqrt(err/n)
      end if
   end subroutine dopri5_kernel

   !> One trial step of size hh from (tau, y0): the stages into k, the new state into y_new
   !> and, with `with_error`, Hairer's scaled error norm. Module level with explicit-shape
   !> arrays (no host association, no descriptors) because this is the integrator's inner
   !> loop; `finite` is false as soon as a derivative is not finite (nothing more is done).
   subroutine dop853_kernel(system, n, tau, hh, y0, k, y_stage, y_new, views, atol, rtol, with_error, err, finite, &
                            n_evaluations)
      class(rk_system_t), intent(inout) :: system
      integer, intent(in) :: n
      real(wp), intent(in) :: tau, hh, y0(n), atol(n), rtol
      real(wp), intent(inout), target :: k(n, *)
      real(wp), intent(out), target :: y_stage(n), y_new(n)
      type(stage_views_t), intent(in) :: views  !! the same y_stage, y_new and columns of k
      logical, intent(in) :: with_error
      real(wp), intent(out) :: err
      logical, intent(out) :: finite
      integer(int64), intent(inout) :: n_evaluations
      real(wp) :: scale, e3, e5, err5, err3, deno
      integer :: i
      err = 0.0_wp
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(p8_a21*k(i, 1))
      end do
      call system%rhs(tau + p8_c2*hh, views%y_stage%v, views%f(2)%v)
      if (stage_failed(n, k(:, 2), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(p8_a31*k(i, 1) + p8_a32*k(i, 2))
      end do
      call system%rhs(tau + p8_c3*hh, views%y_stage%v, views%f(3)%v)
      if (stage_failed(n, k(:, 3), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(p8_a41*k(i, 1) + p8_a43*k(i, 3))
      end do
      call system%rhs(tau + p8_c4*hh, views%y_stage%v, views%f(4)%v)
      if (stage_failed(n, k(:, 4), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(p8_a51*k(i, 1) + p8_a53*k(i, 3) + p8_a54*k(i, 4))
      end do
      call system%rhs(tau + p8_c5*hh, views%y_stage%v, views%f(5)%v)
      if (stage_failed(n, k(:, 5), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(p8_a61*k(i, 1) + p8_a64*k(i, 4) + p8_a65*k(i, 5))
      end do
      call system%rhs(tau + p8_c6*hh, views%y_stage%v, views%f(6)%v)
      if (stage_failed(n, k(:, 6), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(p8_a71*k(i, 1) + p8_a74*k(i, 4) + p8_a75*k(i, 5) + p8_a76*k(i, 6))
      end do
      call system%rhs(tau + p8_c7*hh, views%y_stage%v, views%f(7)%v)
      if (stage_failed(n, k(:, 7), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(p8_a81*k(i, 1) + p8_a84*k(i, 4) + p8_a85*k(i, 5) + p8_a86*k(i, 6) &
                                  + p8_a87*k(i, 7))
      end do
      call system%rhs(tau + p8_c8*hh, views%y_stage%v, views%f(8)%v)
      if (stage_failed(n, k(:, 8), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(p8_a91*k(i, 1) + p8_a94*k(i, 4) + p8_a95*k(i, 5) + p8_a96*k(i, 6) &
                                  + p8_a97*k(i, 7) + p8_a98*k(i, 8))
      end do
      call system%rhs(tau + p8_c9*hh, views%y_stage%v, views%f(9)%v)
      if (stage_failed(n, k(:, 9), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(p8_a101*k(i, 1) + p8_a104*k(i, 4) + p8_a105*k(i, 5) + p8_a106*k(i, 6) &
                                  + p8_a107*k(i, 7) + p8_a108*k(i, 8) + p8_a109*k(i, 9))
      end do
      call system%rhs(tau + p8_c10*hh, views%y_stage%v, views%f(10)%v)
      if (stage_failed(n, k(:, 10), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(p8_a111*k(i, 1) + p8_a114*k(i, 4) + p8_a115*k(i, 5) + p8_a116*k(i, 6) &
                                  + p8_a117*k(i, 7) + p8_a118*k(i, 8) + p8_a119*k(i, 9) + p8_a1110*k(i, 10))
      end do
      call system%rhs(tau + p8_c11*hh, views%y_stage%v, views%f(11)%v)
      if (stage_failed(n, k(:, 11), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(p8_a121*k(i, 1) + p8_a124*k(i, 4) + p8_a125*k(i, 5) + p8_a126*k(i, 6) &
                                  + p8_a127*k(i, 7) + p8_a128*k(i, 8) + p8_a129*k(i, 9) + p8_a1210*k(i, 10) &
                                  + p8_a1211*k(i, 11))
      end do
      call system%rhs(tau + hh, views%y_stage%v, views%f(12)%v)
      if (stage_failed(n, k(:, 12), finite, n_evaluations)) return
      ! the 8th-order solution; k(:, 13) is kept for the increment b·k
      !GCC$ novector
      do i = 1, n
         k(i, 13) = p8_b1*k(i, 1) + p8_b6*k(i, 6) + p8_b7*k(i, 7) + p8_b8*k(i, 8) + p8_b9*k(i, 9) &
                    + p8_b10*k(i, 10) + p8_b11*k(i, 11) + p8_b12*k(i, 12)
         y_new(i) = y0(i) + hh*k(i, 13)
      end do
      if (with_error) then
         ! Hairer's combined estimate err5²/sqrt(err5² + 0.01·err3²) (dop853.f, ERROR ESTIMATION)
         err3 = 0.0_wp
         err5 = 0.0_wp
         !GCC$ novector
         do i = 1, n
            scale = 1.0_wp/(atol(i) + rtol*max(abs(y0(i)), abs(y_new(i))))
            e3 = (k(i, 13) - p8_bhh1*k(i, 1) - p8_bhh2*k(i, 9) - p8_bhh3*k(i, 12))*scale
            e5 = (p8_er1*k(i, 1) + p8_er6*k(i, 6) + p8_er7*k(i, 7) + p8_er8*k(i, 8) + p8_er9*k(i, 9) &
                  + p8_er10*k(i, 10) + p8_er11*k(i, 11) + p8_er12*k(i, 12))*scale
            err3 = err3 + e3**2
            err5 = err5 + e5**2
         end do
         deno = err5 + 0.01_wp*err3
         if (deno <= 0.0_wp) deno = 1.0_wp
         err = abs(hh)*err5*sqrt(1.0_wp/(n*deno))
      end if
   end subroutine dop853_kernel

   !> One trial step of PD8(7) of size hh from (tau, y0): the 13 stages into k, the
   !> 8th-order state into y_new and, with `with_error`, Hairer's norm of its difference to
   !> the 7th-order one. Stage 13 does not use stage 12 (a(13, 12) = 0), so the two
   !> evaluations at tau + hh can overlap. Same conventions as `dop853_kernel`.
   subroutine pd87_kernel(system, n, tau, hh, y0, k, y_stage, y_new, views, atol, rtol, with_error, err, finite, &
                          n_evaluations)
      class(rk_system_t), intent(inout) :: system
      integer, intent(in) :: n
      real(wp), intent(in) :: tau, hh, y0(n), atol(n), rtol
      real(wp), intent(inout), target :: k(n, *)
      real(wp), intent(out), target :: y_stage(n), y_new(n)
      type(stage_views_t), intent(in) :: views  !! the same y_stage, y_new and columns of k
      logical, intent(in) :: with_error
      real(wp), intent(out) :: err
      logical, intent(out) :: finite
      integer(int64), intent(inout) :: n_evaluations
      real(wp) :: e
      integer :: i
      err = 0.0_wp
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(pd_a21*k(i, 1))
      end do
      call system%rhs(tau + pd_c2*hh, views%y_stage%v, views%f(2)%v)
      if (stage_failed(n, k(:, 2), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(pd_a31*k(i, 1) + pd_a32*k(i, 2))
      end do
      call system%rhs(tau + pd_c3*hh, views%y_stage%v, views%f(3)%v)
      if (stage_failed(n, k(:, 3), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(pd_a41*k(i, 1) + pd_a43*k(i, 3))
      end do
      call system%rhs(tau + pd_c4*hh, views%y_stage%v, views%f(4)%v)
      if (stage_failed(n, k(:, 4), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(pd_a51*k(i, 1) + pd_a53*k(i, 3) + pd_a54*k(i, 4))
      end do
      call system%rhs(tau + pd_c5*hh, views%y_stage%v, views%f(5)%v)
      if (stage_failed(n, k(:, 5), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(pd_a61*k(i, 1) + pd_a64*k(i, 4) + pd_a65*k(i, 5))
      end do
      call system%rhs(tau + pd_c6*hh, views%y_stage%v, views%f(6)%v)
      if (stage_failed(n, k(:, 6), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(pd_a71*k(i, 1) + pd_a74*k(i, 4) + pd_a75*k(i, 5) + pd_a76*k(i, 6))
      end do
      call system%rhs(tau + pd_c7*hh, views%y_stage%v, views%f(7)%v)
      if (stage_failed(n, k(:, 7), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(pd_a81*k(i, 1) + pd_a84*k(i, 4) + pd_a85*k(i, 5) + pd_a86*k(i, 6) &
            + pd_a87*k(i, 7))
      end do
      call system%rhs(tau + pd_c8*hh, views%y_stage%v, views%f(8)%v)
      if (stage_failed(n, k(:, 8), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(pd_a91*k(i, 1) + pd_a94*k(i, 4) + pd_a95*k(i, 5) + pd_a96*k(i, 6) &
            + pd_a97*k(i, 7) + pd_a98*k(i, 8))
      end do
      call system%rhs(tau + pd_c9*hh, views%y_stage%v, views%f(9)%v)
      if (stage_failed(n, k(:, 9), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(pd_a101*k(i, 1) + pd_a104*k(i, 4) + pd_a105*k(i, 5) + pd_a106*k(i, 6) &
            + pd_a107*k(i, 7) + pd_a108*k(i, 8) + pd_a109*k(i, 9))
      end do
      call system%rhs(tau + pd_c10*hh, views%y_stage%v, views%f(10)%v)
      if (stage_failed(n, k(:, 10), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(pd_a111*k(i, 1) + pd_a114*k(i, 4) + pd_a115*k(i, 5) + pd_a116*k(i, 6) &
            + pd_a117*k(i, 7) + pd_a118*k(i, 8) + pd_a119*k(i, 9) + pd_a1110*k(i, 10))
      end do
      call system%rhs(tau + pd_c11*hh, views%y_stage%v, views%f(11)%v)
      if (stage_failed(n, k(:, 11), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(pd_a121*k(i, 1) + pd_a124*k(i, 4) + pd_a125*k(i, 5) + pd_a126*k(i, 6) &
            + pd_a127*k(i, 7) + pd_a128*k(i, 8) + pd_a129*k(i, 9) + pd_a1210*k(i, 10) + pd_a1211*k(i, 11))
      end do
      call system%rhs(tau + hh, views%y_stage%v, views%f(12)%v)
      if (stage_failed(n, k(:, 12), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(pd_a131*k(i, 1) + pd_a134*k(i, 4) + pd_a135*k(i, 5) + pd_a136*k(i, 6) &
            + pd_a137*k(i, 7) + pd_a138*k(i, 8) + pd_a139*k(i, 9) + pd_a1310*k(i, 10) + pd_a1311*k(i, 11))
      end do
      call system%rhs(tau + hh, views%y_stage%v, views%f(13)%v)
      if (stage_failed(n, k(:, 13), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_new(i) = y0(i) + hh*(pd_b1*k(i, 1) + pd_b6*k(i, 6) + pd_b7*k(i, 7) + pd_b8*k(i, 8) + pd_b9*k(i, 9) &
            + pd_b10*k(i, 10) + pd_b11*k(i, 11) + pd_b12*k(i, 12) + pd_b13*k(i, 13))
      end do
      if (with_error) then
         !GCC$ novector
         do i = 1, n
            e = hh*(pd_e1*k(i, 1) + pd_e6*k(i, 6) + pd_e7*k(i, 7) + pd_e8*k(i, 8) + pd_e9*k(i, 9) &
               + pd_e10*k(i, 10) + pd_e11*k(i, 11) + pd_e12*k(i, 12) + pd_e13*k(i, 13))/(atol(i) &
               + rtol*max(abs(y0(i)), abs(y_new(i))))
            err = err + e**2
         end do
         err = sqrt(err/n)
      end if
   end subroutine pd87_kernel

   !> One trial step of Verner's 9(8) pair of size hh from (tau, y0): the 16 stages into k,
   !> the 9th-order state into y_new and, with `with_error`, Hairer's norm of its difference
   !> to the 8th-order one. Stage 16 serves only the error estimate (skipped without
   !> `with_error`, in fixed-step mode). Same conventions as `dop853_kernel`.
   subroutine vern98_kernel(system, n, tau, hh, y0, k, y_stage, y_new, views, atol, rtol, with_error, err, finite, &
                            n_evaluations)
      class(rk_system_t), intent(inout) :: system
      integer, intent(in) :: n
      real(wp), intent(in) :: tau, hh, y0(n), atol(n), rtol
      real(wp), intent(inout), target :: k(n, *)
      real(wp), intent(out), target :: y_stage(n), y_new(n)
      type(stage_views_t), intent(in) :: views  !! the same y_stage, y_new and columns of k
      logical, intent(in) :: with_error
      real(wp), intent(out) :: err
      logical, intent(out) :: finite
      integer(int64), intent(inout) :: n_evaluations
      real(wp) :: e
      integer :: i
      err = 0.0_wp
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(v9_a21*k(i, 1))
      end do
      call system%rhs(tau + v9_c2*hh, views%y_stage%v, views%f(2)%v)
      if (stage_failed(n, k(:, 2), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(v9_a31*k(i, 1) + v9_a32*k(i, 2))
      end do
      call system%rhs(tau + v9_c3*hh, views%y_stage%v, views%f(3)%v)
      if (stage_failed(n, k(:, 3), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(v9_a41*k(i, 1) + v9_a43*k(i, 3))
      end do
      call system%rhs(tau + v9_c4*hh, views%y_stage%v, views%f(4)%v)
      if (stage_failed(n, k(:, 4), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(v9_a51*k(i, 1) + v9_a53*k(i, 3) + v9_a54*k(i, 4))
      end do
      call system%rhs(tau + v9_c5*hh, views%y_stage%v, views%f(5)%v)
      if (stage_failed(n, k(:, 5), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(v9_a61*k(i, 1) + v9_a64*k(i, 4) + v9_a65*k(i, 5))
      end do
      call system%rhs(tau + v9_c6*hh, views%y_stage%v, views%f(6)%v)
      if (stage_failed(n, k(:, 6), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(v9_a71*k(i, 1) + v9_a74*k(i, 4) + v9_a75*k(i, 5) + v9_a76*k(i, 6))
      end do
      call system%rhs(tau + v9_c7*hh, views%y_stage%v, views%f(7)%v)
      if (stage_failed(n, k(:, 7), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(v9_a81*k(i, 1) + v9_a86*k(i, 6) + v9_a87*k(i, 7))
      end do
      call system%rhs(tau + v9_c8*hh, views%y_stage%v, views%f(8)%v)
      if (stage_failed(n, k(:, 8), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(v9_a91*k(i, 1) + v9_a96*k(i, 6) + v9_a97*k(i, 7) + v9_a98*k(i, 8))
      end do
      call system%rhs(tau + v9_c9*hh, views%y_stage%v, views%f(9)%v)
      if (stage_failed(n, k(:, 9), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(v9_a101*k(i, 1) + v9_a106*k(i, 6) + v9_a107*k(i, 7) + v9_a108*k(i, 8) &
            + v9_a109*k(i, 9))
      end do
      call system%rhs(tau + v9_c10*hh, views%y_stage%v, views%f(10)%v)
      if (stage_failed(n, k(:, 10), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(v9_a111*k(i, 1) + v9_a116*k(i, 6) + v9_a117*k(i, 7) + v9_a118*k(i, 8) &
            + v9_a119*k(i, 9) + v9_a1110*k(i, 10))
      end do
      call system%rhs(tau + v9_c11*hh, views%y_stage%v, views%f(11)%v)
      if (stage_failed(n, k(:, 11), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(v9_a121*k(i, 1) + v9_a126*k(i, 6) + v9_a127*k(i, 7) + v9_a128*k(i, 8) &
            + v9_a129*k(i, 9) + v9_a1210*k(i, 10) + v9_a1211*k(i, 11))
      end do
      call system%rhs(tau + v9_c12*hh, views%y_stage%v, views%f(12)%v)
      if (stage_failed(n, k(:, 12), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(v9_a131*k(i, 1) + v9_a136*k(i, 6) + v9_a137*k(i, 7) + v9_a138*k(i, 8) &
            + v9_a139*k(i, 9) + v9_a1310*k(i, 10) + v9_a1311*k(i, 11) + v9_a1312*k(i, 12))
      end do
      call system%rhs(tau + v9_c13*hh, views%y_stage%v, views%f(13)%v)
      if (stage_failed(n, k(:, 13), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(v9_a141*k(i, 1) + v9_a146*k(i, 6) + v9_a147*k(i, 7) + v9_a148*k(i, 8) &
            + v9_a149*k(i, 9) + v9_a1410*k(i, 10) + v9_a1411*k(i, 11) + v9_a1412*k(i, 12) &
            + v9_a1413*k(i, 13))
      end do
      call system%rhs(tau + v9_c14*hh, views%y_stage%v, views%f(14)%v)
      if (stage_failed(n, k(:, 14), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(v9_a151*k(i, 1) + v9_a156*k(i, 6) + v9_a157*k(i, 7) + v9_a158*k(i, 8) &
            + v9_a159*k(i, 9) + v9_a1510*k(i, 10) + v9_a1511*k(i, 11) + v9_a1512*k(i, 12) &
            + v9_a1513*k(i, 13) + v9_a1514*k(i, 14))
      end do
      call system%rhs(tau + hh, views%y_stage%v, views%f(15)%v)
      if (stage_failed(n, k(:, 15), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         y_new(i) = y0(i) + hh*(v9_b1*k(i, 1) + v9_b8*k(i, 8) + v9_b9*k(i, 9) + v9_b10*k(i, 10) &
            + v9_b11*k(i, 11) + v9_b12*k(i, 12) + v9_b13*k(i, 13) + v9_b14*k(i, 14) + v9_b15*k(i, 15))
      end do
      if (.not. with_error) return
      ! stage 16 serves only the 8th-order formula
      !GCC$ novector
      do i = 1, n
         y_stage(i) = y0(i) + hh*(v9_a161*k(i, 1) + v9_a166*k(i, 6) + v9_a167*k(i, 7) + v9_a168*k(i, 8) &
            + v9_a169*k(i, 9) + v9_a1610*k(i, 10) + v9_a1611*k(i, 11) + v9_a1612*k(i, 12) &
            + v9_a1613*k(i, 13))
      end do
      call system%rhs(tau + hh, views%y_stage%v, views%f(16)%v)
      if (stage_failed(n, k(:, 16), finite, n_evaluations)) return
      !GCC$ novector
      do i = 1, n
         e = hh*(v9_e1*k(i, 1) + v9_e8*k(i, 8) + v9_e9*k(i, 9) + v9_e10*k(i, 10) + v9_e11*k(i, 11) &
            + v9_e12*k(i, 12) + v9_e13*k(i, 13) + v9_e14*k(i, 14) + v9_e15*k(i, 15) + v9_e16*k(i, 16)) &
            /(atol(i) + rtol*max(abs(y0(i)), abs(y_new(i))))
         err = err + e**2
      end do
      err = sqrt(err/n)
   end subroutine vern98_kernel

   !> Count one evaluation of f and say whether it failed: `finite` is false when a
   !> component is NaN or ±Inf (|f_i| <= huge is false for those: one compare per component).
   logical function stage_failed(n, f, finite, n_evaluations) result(failed)
      integer, intent(in) :: n                       !! number of components
      real(wp), intent(in) :: f(n)                   !! the derivative just computed
      logical, intent(out) :: finite                 !! all components finite
      integer(int64), intent(inout) :: n_evaluations !! evaluation counter
      integer :: i
      n_evaluations = n_evaluations + 1
      finite = .true.
      !GCC$ novector
      do i = 1, n
         finite = finite .and. abs(f(i)) <= huge(1.0_wp)
      end do
      failed = .not. finite
   end function stage_failed
end module hillstab_integrate_rk

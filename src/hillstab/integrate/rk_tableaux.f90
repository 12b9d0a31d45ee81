!> The four embedded Runge–Kutta pairs of hillstab_integrate_rk, as data: their codes,
!> what the driver needs to know of each (`rk_pairs`: name, order, stage columns, the
!> column of f at the new point, the order of its continuous extension, the defaults of the
!> step control) and their Butcher coefficients, one constant of a derived type per pair
!> (`dopri5`, `dop853`, `pd87`, `vern98`: components named as in the papers, a21 for
!> a(2, 1); the stage kernels read them as compile-time constants). A new pair is its
!> tableau here, its kernel in hillstab_integrate_rk_stages and its row in `rk_pairs`.
!>
!> The Butcher coefficients are copied from Hairer's codes dopri5.f and dop853.f
!> (versions of 1996, www.unige.ch/~hairer/software.html): Dormand & Prince 1980 for
!> DOPRI5 with Shampine's 1986 dense output; Prince & Dormand 1981 / Hairer et al. for
!> DOP853 and its 7th-order extension. PD87 is Prince & Dormand, "High order embedded
!> Runge–Kutta formulae", J. Comput. Appl. Math. 7 (1981) 67–75, RK8(7)13M, with the
!> paper's rational coefficients (the pair of GSL's rk8pd; the fractions read as
!> reproduced in GSL's ode-initval2/rk8pd.c, and a step is bit-identical to GSL's, test
!> rk/pd87_step_equals_gsl). VERN98 is the 16-stage 9(8) pair "RKV98.IIa Efficient" of
!> J. H. Verner, "Numerically optimal Runge–Kutta pairs with interpolants", Numer.
!> Algorithms 53 (2010) 383–396, from Verner's coefficient file
!> RKV98.IIa.Efficient.000000349.081209.FLOAT6040OnWeb (www.sfu.ca/~jverner); the
!> 40-digit values were read as reproduced in github.com/jacobwilliams/rklib
!> (src/rklib_variable_steps.f90, rkv98e) and agree to 3e-40 with
!> github.com/vlovero/PyODEPack (pyodepack/include/verner98e.h); in 60-digit arithmetic
!> they satisfy all 486 order conditions of order ≤ 9 (the 8th-order weights those of
!> order ≤ 8) to 1e-39.
!>
!>```fortran
!> print *, rk_method_name(rk_vern98), rk_method_order(rk_vern98), dop853%c2
!>```
module hillstab_integrate_rk_tableaux
   use hillstab_core_kinds, only: wp
   implicit none
   private
   public :: rk_dopri5, rk_dop853, rk_pd87, rk_vern98, rk_pair_t, rk_pairs, rk_pair
   public :: rk_method_name, rk_method_order, rk_beta_limit, rk_vern98_tableau
   public :: dopri5_tableau_t, dop853_tableau_t, pd87_tableau_t, vern98_tableau_t, dopri5, dop853, pd87, vern98

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

   !> What the driver needs to know of a pair (one row of `rk_pairs`; its code is its row).
   type :: rk_pair_t
      character(len=8) :: name = "unknown"  !! rk_method_name
      integer :: order = 0        !! classical order of the propagating formula
      integer :: columns = 0      !! columns of the stage array: stages, f at the new point, dense stages
      integer :: new_column = 0   !! the column that holds f at the new point after a step
      logical :: fsal = .false.   !! the last stage is f at the new point (no evaluation after the step)
      integer :: dense_order = 0  !! order of its own continuous extension (0: none, the cubic Hermite serves)
      !> PI control: the step exponent is 1/order − pi_weight·β, the admissible β below
      !> (1/order)/(1 + pi_weight) (`rk_beta_limit`)
      real(wp) :: pi_weight = 0.0_wp
      real(wp) :: beta = 0.0_wp     !! default PI parameter β (Hairer's)
      real(wp) :: fac_min = 0.0_wp  !! default smallest h_new/h
      real(wp) :: fac_max = 0.0_wp  !! default largest h_new/h
   end type rk_pair_t

   !> The pairs, in the order of their codes (DOP853: 12 stages, f at the new point in
   !> column 13, its dense stages in 14–16; PD87: 13 stages and f new in 14; VERN98: 16 and 17).
   type(rk_pair_t), parameter :: rk_pairs(4) = [ &
      rk_pair_t("dopri5", 5, 7, 7, .true., 4, 0.75_wp, 0.04_wp, 0.2_wp, 10.0_wp), &
      rk_pair_t("dop853", 8, 16, 13, .false., 7, 0.2_wp, 0.0_wp, 0.333_wp, 6.0_wp), &
      rk_pair_t("pd87", 8, 16, 14, .false., 0, 0.2_wp, 0.0_wp, 0.333_wp, 6.0_wp), &
      rk_pair_t("vern98", 9, 17, 17, .false., 0, 0.2_wp, 0.0_wp, 0.333_wp, 6.0_wp)]

   ! PD8(7) and VERN98: the weights of both formulas, named here because the error weights
   ! of the tableaux below are their differences. PD8(7): 8th-order weights b, 7th-order b̂
   real(wp), parameter :: pd_b1 = 14005451.0_wp/335480064.0_wp, pd_b6 = -59238493.0_wp/1068277825.0_wp, &
      pd_b7 = 181606767.0_wp/758867731.0_wp, pd_b8 = 561292985.0_wp/797845732.0_wp, &
      pd_b9 = -1041891430.0_wp/1371343529.0_wp, pd_b10 = 760417239.0_wp/1151165299.0_wp, &
      pd_b11 = 118820643.0_wp/751138087.0_wp, pd_b12 = -528747749.0_wp/2220607170.0_wp, pd_b13 = 1.0_wp/4.0_wp
   real(wp), parameter :: pd_bh1 = 13451932.0_wp/455176623.0_wp, pd_bh6 = -808719846.0_wp/976000145.0_wp, &
      pd_bh7 = 1757004468.0_wp/5645159321.0_wp, pd_bh8 = 656045339.0_wp/265891186.0_wp, &
      pd_bh9 = -3867574721.0_wp/1518517206.0_wp, pd_bh10 = 465885868.0_wp/322736535.0_wp, &
      pd_bh11 = 53011238.0_wp/667516719.0_wp, pd_bh12 = 2.0_wp/45.0_wp
   ! VERN98: 9th-order weights b, 8th-order b̂
   real(wp), parameter :: v9_b1 = 0.1461197685842315252051541915018784713459e-1_wp, &
      v9_b8 = -0.3915211862331339089410228267288242030810_wp, &
      v9_b9 = 0.2310932500289506415909675644868993669908_wp, &
      v9_b10 = 0.1274766769992852382560589467488989175618_wp, &
      v9_b11 = 0.2246434176204157731566981937082069688984_wp, &
      v9_b12 = 0.5684352689748512932705226972873692126743_wp, &
      v9_b13 = 0.5825871557215827200814768021863420902155e-1_wp, &
      v9_b14 = 0.1364317403482215641609022744494239843327_wp, &
      v9_b15 = 0.3057013983082797397721005067920369646664e-1_wp
   real(wp), parameter :: v9_bh1 = 0.1996996514886773085518508418098868756464e-1_wp, &
      v9_bh8 = 2.191499304949330054530747099310837524864_wp, &
      v9_bh9 = 0.8857071848208438030833722031786358862953e-1_wp, &
      v9_bh10 = 0.1140560234865965622484956605091432032674_wp, &
      v9_bh11 = 0.2533163805345107065564577734569651977347_wp, &
      v9_bh12 = -2.056564386240941011158999594595981300493_wp, &
      v9_bh13 = 0.3408096799013119935160094894224543812830_wp, &
      v9_bh16 = 0.4834231373823958314376726739772871714902e-1_wp

   !> The DOPRI5 pair of Dormand & Prince (1980), coefficients as in Hairer's dopri5.f (CDOPRI);
   !> e = b − b̂ of the embedded 4th-order formula; d = Shampine's (1986) dense output.
   type :: dopri5_tableau_t
      !> nodes c(i) (c(6) = c(7) = 1)
      real(wp) :: c2 = 0.2_wp, c3 = 0.3_wp, c4 = 0.8_wp, c5 = 8.0_wp/9.0_wp
      !> a(2, j), the couplings of stage 2
      real(wp) :: a21 = 0.2_wp
      !> a(3, j), the couplings of stage 3
      real(wp) :: a31 = 3.0_wp/40.0_wp, a32 = 9.0_wp/40.0_wp
      !> a(4, j), the couplings of stage 4
      real(wp) :: a41 = 44.0_wp/45.0_wp, a42 = -56.0_wp/15.0_wp, a43 = 32.0_wp/9.0_wp
      !> a(5, j), the couplings of stage 5
      real(wp) :: a51 = 19372.0_wp/6561.0_wp, a52 = -25360.0_wp/2187.0_wp, a53 = 64448.0_wp/6561.0_wp, &
         a54 = -212.0_wp/729.0_wp
      !> a(6, j), the couplings of stage 6
      real(wp) :: a61 = 9017.0_wp/3168.0_wp, a62 = -355.0_wp/33.0_wp, a63 = 46732.0_wp/5247.0_wp, &
         a64 = 49.0_wp/176.0_wp, a65 = -5103.0_wp/18656.0_wp
      !> a(7, j), the couplings of stage 7
      real(wp) :: a71 = 35.0_wp/384.0_wp, a73 = 500.0_wp/1113.0_wp, a74 = 125.0_wp/192.0_wp, &
         a75 = -2187.0_wp/6784.0_wp, a76 = 11.0_wp/84.0_wp
      !> error weights b(i) − b̂(i) against the embedded 4th-order formula
      real(wp) :: e1 = 71.0_wp/57600.0_wp, e3 = -71.0_wp/16695.0_wp, e4 = 71.0_wp/1920.0_wp, &
         e5 = -17253.0_wp/339200.0_wp, e6 = 22.0_wp/525.0_wp, e7 = -1.0_wp/40.0_wp
      !> Shampine's dense-output weights d(i)
      real(wp) :: d1 = -12715105075.0_wp/11282082432.0_wp, d3 = 87487479700.0_wp/32700410799.0_wp, &
         d4 = -10690763975.0_wp/1880347072.0_wp, d5 = 701980252875.0_wp/199316789632.0_wp, &
         d6 = -1453857185.0_wp/822651844.0_wp, d7 = 69997945.0_wp/29380423.0_wp
   end type dopri5_tableau_t

   !> The DOP853 pair, coefficients as in Hairer's dop853.f (DP86CO, version of 25 April 1996).
   !> Stages 1–12 make the step, stage 13 is f at the new point (FSAL), stages 14–16
   !> serve only the 7th-order dense output. bhh: 3rd-order embedded weights; er: b − b̂₅.
   type :: dop853_tableau_t
      !> nodes c(i) (c(12) = 1; c(14) … c(16) of the dense-output stages)
      real(wp) :: c2 = 0.526001519587677318785587544488e-01_wp, c3 = 0.789002279381515978178381316732e-01_wp, &
         c4 = 0.118350341907227396726757197510e+00_wp, c5 = 0.281649658092772603273242802490e+00_wp, &
         c6 = 0.333333333333333333333333333333e+00_wp, c7 = 0.25e+00_wp, &
         c8 = 0.307692307692307692307692307692e+00_wp, c9 = 0.651282051282051282051282051282e+00_wp, &
         c10 = 0.6e+00_wp, c11 = 0.857142857142857142857142857142e+00_wp, c14 = 0.1e+00_wp, c15 = 0.2e+00_wp, &
         c16 = 0.777777777777777777777777777778e+00_wp
      !> weights b(i) of the propagating formula
      real(wp) :: b1 = 5.42937341165687622380535766363e-2_wp, b6 = 4.45031289275240888144113950566e0_wp, &
         b7 = 1.89151789931450038304281599044e0_wp, b8 = -5.8012039600105847814672114227e0_wp, &
         b9 = 3.1116436695781989440891606237e-1_wp, b10 = -1.52160949662516078556178806805e-1_wp, &
         b11 = 2.01365400804030348374776537501e-1_wp, b12 = 4.47106157277725905176885569043e-2_wp
      !> weights of DOP853's embedded 3rd-order formula
      real(wp) :: bhh1 = 0.244094488188976377952755905512e+00_wp, &
         bhh2 = 0.733846688281611857341361741547e+00_wp, bhh3 = 0.220588235294117647058823529412e-01_wp
      !> error weights b(i) − b̂(i) against the embedded 5th-order formula
      real(wp) :: er1 = 0.1312004499419488073250102996e-01_wp, er6 = -0.1225156446376204440720569753e+01_wp, &
         er7 = -0.4957589496572501915214079952e+00_wp, er8 = 0.1664377182454986536961530415e+01_wp, &
         er9 = -0.3503288487499736816886487290e+00_wp, er10 = 0.3341791187130174790297318841e+00_wp, &
         er11 = 0.8192320648511571246570742613e-01_wp, er12 = -0.2235530786388629525884427845e-01_wp
      !> a(2, j), the couplings of stage 2
      real(wp) :: a21 = 5.26001519587677318785587544488e-2_wp
      !> a(3, j), the couplings of stage 3
      real(wp) :: a31 = 1.97250569845378994544595329183e-2_wp, a32 = 5.91751709536136983633785987549e-2_wp
      !> a(4, j), the couplings of stage 4
      real(wp) :: a41 = 2.95875854768068491816892993775e-2_wp, a43 = 8.87627564304205475450678981324e-2_wp
      !> a(5, j), the couplings of stage 5
      real(wp) :: a51 = 2.41365134159266685502369798665e-1_wp, a53 = -8.84549479328286085344864962717e-1_wp, &
         a54 = 9.24834003261792003115737966543e-1_wp
      !> a(6, j), the couplings of stage 6
      real(wp) :: a61 = 3.7037037037037037037037037037e-2_wp, a64 = 1.70828608729473871279604482173e-1_wp, &
         a65 = 1.25467687566822425016691814123e-1_wp
      !> a(7, j), the couplings of stage 7
      real(wp) :: a71 = 3.7109375e-2_wp, a74 = 1.70252211019544039314978060272e-1_wp, &
         a75 = 6.02165389804559606850219397283e-2_wp, a76 = -1.7578125e-2_wp
      !> a(8, j), the couplings of stage 8
      real(wp) :: a81 = 3.70920001185047927108779319836e-2_wp, a84 = 1.70383925712239993810214054705e-1_wp, &
         a85 = 1.07262030446373284651809199168e-1_wp, a86 = -1.53194377486244017527936158236e-2_wp, &
         a87 = 8.27378916381402288758473766002e-3_wp
      !> a(9, j), the couplings of stage 9
      real(wp) :: a91 = 6.24110958716075717114429577812e-1_wp, a94 = -3.36089262944694129406857109825e0_wp, &
         a95 = -8.68219346841726006818189891453e-1_wp, a96 = 2.75920996994467083049415600797e1_wp, &
         a97 = 2.01540675504778934086186788979e1_wp, a98 = -4.34898841810699588477366255144e1_wp
      !> a(10, j), the couplings of stage 10
      real(wp) :: a101 = 4.77662536438264365890433908527e-1_wp, a104 = -2.48811461997166764192642586468e0_wp, &
         a105 = -5.90290826836842996371446475743e-1_wp, a106 = 2.12300514481811942347288949897e1_wp, &
         a107 = 1.52792336328824235832596922938e1_wp, a108 = -3.32882109689848629194453265587e1_wp, &
         a109 = -2.03312017085086261358222928593e-2_wp
      !> a(11, j), the couplings of stage 11
      real(wp) :: a111 = -9.3714243008598732571704021658e-1_wp, a114 = 5.18637242884406370830023853209e0_wp, &
         a115 = 1.09143734899672957818500254654e0_wp, a116 = -8.14978701074692612513997267357e0_wp, &
         a117 = -1.85200656599969598641566180701e1_wp, a118 = 2.27394870993505042818970056734e1_wp, &
         a119 = 2.49360555267965238987089396762e0_wp, a1110 = -3.0467644718982195003823669022e0_wp
      !> a(12, j), the couplings of stage 12
      real(wp) :: a121 = 2.27331014751653820792359768449e0_wp, a124 = -1.05344954667372501984066689879e1_wp, &
         a125 = -2.00087205822486249909675718444e0_wp, a126 = -1.79589318631187989172765950534e1_wp, &
         a127 = 2.79488845294199600508499808837e1_wp, a128 = -2.85899827713502369474065508674e0_wp, &
         a129 = -8.87285693353062954433549289258e0_wp, a1210 = 1.23605671757943030647266201528e1_wp, &
         a1211 = 6.43392746015763530355970484046e-1_wp
      !> a(14, j), the couplings of stage 14
      real(wp) :: a141 = 5.61675022830479523392909219681e-2_wp, a147 = 2.53500210216624811088794765333e-1_wp, &
         a148 = -2.46239037470802489917441475441e-1_wp, a149 = -1.24191423263816360469010140626e-1_wp, &
         a1410 = 1.5329179827876569731206322685e-1_wp, a1411 = 8.20105229563468988491666602057e-3_wp, &
         a1412 = 7.56789766054569976138603589584e-3_wp, a1413 = -8.298e-3_wp
      !> a(15, j), the couplings of stage 15
      real(wp) :: a151 = 3.18346481635021405060768473261e-2_wp, a156 = 2.83009096723667755288322961402e-2_wp, &
         a157 = 5.35419883074385676223797384372e-2_wp, a158 = -5.49237485713909884646569340306e-2_wp, &
         a1511 = -1.08347328697249322858509316994e-4_wp, a1512 = 3.82571090835658412954920192323e-4_wp, &
         a1513 = -3.40465008687404560802977114492e-4_wp, a1514 = 1.41312443674632500278074618366e-1_wp
      !> a(16, j), the couplings of stage 16
      real(wp) :: a161 = -4.28896301583791923408573538692e-1_wp, a166 = -4.69762141536116384314449447206e0_wp, &
         a167 = 7.68342119606259904184240953878e0_wp, a168 = 4.06898981839711007970213554331e0_wp, &
         a169 = 3.56727187455281109270669543021e-1_wp, a1613 = -1.39902416515901462129418009734e-3_wp, &
         a1614 = 2.9475147891527723389556272149e0_wp, a1615 = -9.15095847217987001081870187138e0_wp
      !> d(4, j) of the 7th-order continuous extension (CONTD8)
      real(wp) :: d41 = -0.84289382761090128651353491142e+01_wp, d46 = 0.56671495351937776962531783590e+00_wp, &
         d47 = -0.30689499459498916912797304727e+01_wp, d48 = 0.23846676565120698287728149680e+01_wp, &
         d49 = 0.21170345824450282767155149946e+01_wp, d410 = -0.87139158377797299206789907490e+00_wp, &
         d411 = 0.22404374302607882758541771650e+01_wp, d412 = 0.63157877876946881815570249290e+00_wp, &
         d413 = -0.88990336451333310820698117400e-01_wp, d414 = 0.18148505520854727256656404962e+02_wp, &
         d415 = -0.91946323924783554000451984436e+01_wp, d416 = -0.44360363875948939664310572000e+01_wp
      !> d(5, j) of the 7th-order continuous extension (CONTD8)
      real(wp) :: d51 = 0.10427508642579134603413151009e+02_wp, d56 = 0.24228349177525818288430175319e+03_wp, &
         d57 = 0.16520045171727028198505394887e+03_wp, d58 = -0.37454675472269020279518312152e+03_wp, &
         d59 = -0.22113666853125306036270938578e+02_wp, d510 = 0.77334326684722638389603898808e+01_wp, &
         d511 = -0.30674084731089398182061213626e+02_wp, d512 = -0.93321305264302278729567221706e+01_wp, &
         d513 = 0.15697238121770843886131091075e+02_wp, d514 = -0.31139403219565177677282850411e+02_wp, &
         d515 = -0.93529243588444783865713862664e+01_wp, d516 = 0.35816841486394083752465898540e+02_wp
      !> d(6, j) of the 7th-order continuous extension (CONTD8)
      real(wp) :: d61 = 0.19985053242002433820987653617e+02_wp, d66 = -0.38703730874935176555105901742e+03_wp, &
         d67 = -0.18917813819516756882830838328e+03_wp, d68 = 0.52780815920542364900561016686e+03_wp, &
         d69 = -0.11573902539959630126141871134e+02_wp, d610 = 0.68812326946963000169666922661e+01_wp, &
         d611 = -0.10006050966910838403183860980e+01_wp, d612 = 0.77771377980534432092869265740e+00_wp, &
         d613 = -0.27782057523535084065932004339e+01_wp, d614 = -0.60196695231264120758267380846e+02_wp, &
         d615 = 0.84320405506677161018159903784e+02_wp, d616 = 0.11992291136182789328035130030e+02_wp
      !> d(7, j) of the 7th-order continuous extension (CONTD8)
      real(wp) :: d71 = -0.25693933462703749003312586129e+02_wp, &
         d76 = -0.15418974869023643374053993627e+03_wp, &
         d77 = -0.23152937917604549567536039109e+03_wp, d78 = 0.35763911791061412378285349910e+03_wp, &
         d79 = 0.93405324183624310003907691704e+02_wp, d710 = -0.37458323136451633156875139351e+02_wp, &
         d711 = 0.10409964950896230045147246184e+03_wp, d712 = 0.29840293426660503123344363579e+02_wp, &
         d713 = -0.43533456590011143754432175058e+02_wp, d714 = 0.96324553959188282948394950600e+02_wp, &
         d715 = -0.39177261675615439165231486172e+02_wp, d716 = -0.14972683625798562581422125276e+03_wp
   end type dop853_tableau_t

   !> PD8(7): Prince & Dormand (1981), RK8(7)13M. The 8th-order formula propagates (local
   !> extrapolation); the error is its difference to the 7th-order one, e = b̂ − b.
   type :: pd87_tableau_t
      !> nodes c(i) (c(12) = c(13) = 1)
      real(wp) :: c2 = 1.0_wp/18.0_wp, c3 = 1.0_wp/12.0_wp, c4 = 1.0_wp/8.0_wp, c5 = 5.0_wp/16.0_wp, &
         c6 = 3.0_wp/8.0_wp, c7 = 59.0_wp/400.0_wp, c8 = 93.0_wp/200.0_wp, &
         c9 = 5490023248.0_wp/9719169821.0_wp, c10 = 13.0_wp/20.0_wp, c11 = 1201146811.0_wp/1299019798.0_wp
      !> a(2, j), the couplings of stage 2
      real(wp) :: a21 = 1.0_wp/18.0_wp
      !> a(3, j), the couplings of stage 3
      real(wp) :: a31 = 1.0_wp/48.0_wp, a32 = 1.0_wp/16.0_wp
      !> a(4, j), the couplings of stage 4
      real(wp) :: a41 = 1.0_wp/32.0_wp, a43 = 3.0_wp/32.0_wp
      !> a(5, j), the couplings of stage 5
      real(wp) :: a51 = 5.0_wp/16.0_wp, a53 = -75.0_wp/64.0_wp, a54 = 75.0_wp/64.0_wp
      !> a(6, j), the couplings of stage 6
      real(wp) :: a61 = 3.0_wp/80.0_wp, a64 = 3.0_wp/16.0_wp, a65 = 3.0_wp/20.0_wp
      !> a(7, j), the couplings of stage 7
      real(wp) :: a71 = 29443841.0_wp/614563906.0_wp, a74 = 77736538.0_wp/692538347.0_wp, &
         a75 = -28693883.0_wp/1125000000.0_wp, a76 = 23124283.0_wp/1800000000.0_wp
      !> a(8, j), the couplings of stage 8
      real(wp) :: a81 = 16016141.0_wp/946692911.0_wp, a84 = 61564180.0_wp/158732637.0_wp, &
         a85 = 22789713.0_wp/633445777.0_wp, a86 = 545815736.0_wp/2771057229.0_wp, &
         a87 = -180193667.0_wp/1043307555.0_wp
      !> a(9, j), the couplings of stage 9
      real(wp) :: a91 = 39632708.0_wp/573591083.0_wp, a94 = -433636366.0_wp/683701615.0_wp, &
         a95 = -421739975.0_wp/2616292301.0_wp, a96 = 100302831.0_wp/723423059.0_wp, &
         a97 = 790204164.0_wp/839813087.0_wp, a98 = 800635310.0_wp/3783071287.0_wp
      !> a(10, j), the couplings of stage 10
      real(wp) :: a101 = 246121993.0_wp/1340847787.0_wp, a104 = -37695042795.0_wp/15268766246.0_wp, &
         a105 = -309121744.0_wp/1061227803.0_wp, a106 = -12992083.0_wp/490766935.0_wp, &
         a107 = 6005943493.0_wp/2108947869.0_wp, a108 = 393006217.0_wp/1396673457.0_wp, &
         a109 = 123872331.0_wp/1001029789.0_wp
      !> a(11, j), the couplings of stage 11
      real(wp) :: a111 = -1028468189.0_wp/846180014.0_wp, a114 = 8478235783.0_wp/508512852.0_wp, &
         a115 = 1311729495.0_wp/1432422823.0_wp, a116 = -10304129995.0_wp/1701304382.0_wp, &
         a117 = -48777925059.0_wp/3047939560.0_wp, a118 = 15336726248.0_wp/1032824649.0_wp, &
         a119 = -45442868181.0_wp/3398467696.0_wp, a1110 = 3065993473.0_wp/597172653.0_wp
      !> a(12, j), the couplings of stage 12
      real(wp) :: a121 = 185892177.0_wp/718116043.0_wp, a124 = -3185094517.0_wp/667107341.0_wp, &
         a125 = -477755414.0_wp/1098053517.0_wp, a126 = -703635378.0_wp/230739211.0_wp, &
         a127 = 5731566787.0_wp/1027545527.0_wp, a128 = 5232866602.0_wp/850066563.0_wp, &
         a129 = -4093664535.0_wp/808688257.0_wp, a1210 = 3962137247.0_wp/1805957418.0_wp, &
         a1211 = 65686358.0_wp/487910083.0_wp
      !> a(13, j), the couplings of stage 13
      real(wp) :: a131 = 403863854.0_wp/491063109.0_wp, a134 = -5068492393.0_wp/434740067.0_wp, &
         a135 = -411421997.0_wp/543043805.0_wp, a136 = 652783627.0_wp/914296604.0_wp, &
         a137 = 11173962825.0_wp/925320556.0_wp, a138 = -13158990841.0_wp/6184727034.0_wp, &
         a139 = 3936647629.0_wp/1978049680.0_wp, a1310 = -160528059.0_wp/685178525.0_wp, &
         a1311 = 248638103.0_wp/1413531060.0_wp
      !> weights b(i) of the propagating formula
      real(wp) :: b1 = pd_b1, b6 = pd_b6, b7 = pd_b7, b8 = pd_b8, b9 = pd_b9, b10 = pd_b10, b11 = pd_b11, &
         b12 = pd_b12, b13 = pd_b13
      !> weights b̂(i) of the embedded formula
      real(wp) :: bh1 = pd_bh1, bh6 = pd_bh6, bh7 = pd_bh7, bh8 = pd_bh8, bh9 = pd_bh9, bh10 = pd_bh10, &
         bh11 = pd_bh11, bh12 = pd_bh12
      !> error weights b̂(i) − b(i), 7th- against 8th-order formula
      real(wp) :: e1 = pd_bh1 - pd_b1, e6 = pd_bh6 - pd_b6, e7 = pd_bh7 - pd_b7, e8 = pd_bh8 - pd_b8, &
         e9 = pd_bh9 - pd_b9, e10 = pd_bh10 - pd_b10, e11 = pd_bh11 - pd_b11, e12 = pd_bh12 - pd_b12, &
         e13 = -pd_b13
   end type pd87_tableau_t

   !> The VERN98 pair of Verner (2010), RKV98.IIa Efficient, 16 stages. Stages 15 and 16 are at c = 1;
   !> the 9th-order formula propagates (local extrapolation) and does not use stage 16,
   !> which only the 8th-order formula uses (a(16, 14) = a(16, 15) = 0). e = b̂ − b.
   type :: vern98_tableau_t
      !> nodes c(i) (c(15) = c(16) = 1)
      real(wp) :: c2 = 0.3462e-1_wp, c3 = 0.9702435063878044594828361677100617517633e-1_wp, &
         c4 = 0.1455365259581706689224254251565092627645_wp, c5 = 0.561_wp, &
         c6 = 0.2290079115904850126662751771814700052182_wp, &
         c7 = 0.5449920884095149873337248228185299947818_wp, c8 = 0.645_wp, &
         c9 = 0.4837500000000000000000000000000000000000_wp, c10 = 0.6757e-1_wp, c11 = 0.2500_wp, &
         c12 = 0.6590650618730998549405331618649220295334_wp, c13 = 0.8206_wp, c14 = 0.9012_wp
      !> a(2, j), the couplings of stage 2
      real(wp) :: a21 = 0.3462e-1_wp
      !> a(3, j), the couplings of stage 3
      real(wp) :: a31 = -0.389335438857287327017042687229284478532e-1_wp, &
         a32 = 0.1359578945245091786499878854939346230295_wp
      !> a(4, j), the couplings of stage 4
      real(wp) :: a41 = 0.3638413148954266723060635628912731569111e-1_wp, &
         a43 = 0.1091523944686280016918190688673819470733_wp
      !> a(5, j), the couplings of stage 5
      real(wp) :: a51 = 2.025763914393969636805657604282571047511_wp, &
         a53 = -7.638023836496292020387602153091964592952_wp, &
         a54 = 6.173259922102322383581944548809393545442_wp
      !> a(6, j), the couplings of stage 6
      real(wp) :: a61 = 0.5112275589406060872792270881648288397197e-1_wp, &
         a64 = 0.1770823794555021537929910813839068684087_wp, &
         a65 = 0.80277624092225014536138698108025283759e-3_wp
      !> a(7, j), the couplings of stage 7
      real(wp) :: a71 = 0.1316006357975216279279871693164256985334_wp, &
         a74 = -0.2957276252669636417685183174672273730699_wp, &
         a75 = 0.878137803564295237421124704053886667082e-1_wp, &
         a76 = 0.6213052975225274774321435005639430026100_wp
      !> a(8, j), the couplings of stage 8
      real(wp) :: a81 = 0.7166666666666666666666666666666666666667e-1_wp, &
         a86 = 0.3305533578915319409260346730051472207728_wp, &
         a87 = 0.2427799754418013924072986603281861125606_wp
      !> a(9, j), the couplings of stage 9
      real(wp) :: a91 = 0.7180664062500000000000000000000000000000e-1_wp, &
         a96 = 0.3294380283228177160744825466257672816401_wp, &
         a97 = 0.1165190029271822839255174533742327183599_wp, &
         a98 = -0.3401367187500000000000000000000000000000e-1_wp
      !> a(10, j), the couplings of stage 10
      real(wp) :: a101 = 0.4836757646340646986611287718844085773549e-1_wp, &
         a106 = 0.3928989925676163974333190042057047002852e-1_wp, &
         a107 = 0.1054740945890344608263649267140088017604_wp, &
         a108 = -0.2143865284648312665982642293830533996214e-1_wp, &
         a109 = -0.1041229174627194437759832813847147895623_wp
      !> a(11, j), the couplings of stage 11
      real(wp) :: a111 = -0.2664561487201478635337289243849737340534e-1_wp, &
         a116 = 0.3333333333333333333333333333333333333333e-1_wp, &
         a117 = -0.1631072244872467239162704487554706387141_wp, &
         a118 = 0.3396081684127761199487954930015522928244e-1_wp, &
         a119 = 0.1572319413814626097110769806810024118077_wp, &
         a1110 = 0.2152267478031879552303534778794770376960_wp
      !> a(12, j), the couplings of stage 12
      real(wp) :: a121 = 0.3689009248708622334786359863227633989718e-1_wp, &
         a126 = -0.1465181576725542928653609891758501156785_wp, &
         a127 = 0.2242577768172024345345469822625833796001_wp, &
         a128 = 0.2294405717066072637090897902753790803034e-1_wp, &
         a129 = -0.35850052905728761357394424889330334334e-2_wp, &
         a1210 = 0.8669223316444385506869203619044453906053e-1_wp, &
         a1211 = 0.4383840651968337846196219974168630120572_wp
      !> a(13, j), the couplings of stage 13
      real(wp) :: a131 = -0.4866012215113340846662212357570395295088_wp, &
         a136 = -6.304602650282852990657772792012007122988_wp, &
         a137 = -0.281245618289472564778284183790118418111_wp, &
         a138 = -2.679019236219849057687906597489223155566_wp, &
         a139 = 0.518815663924157511565311164615012522024_wp, &
         a1310 = 1.365353187603341710683633635235238678626_wp, &
         a1311 = 5.885091088503946585721274891680604830712_wp, &
         a1312 = 2.802808786272062889819965117517532194812_wp
      !> a(14, j), the couplings of stage 14
      real(wp) :: a141 = 0.4185367457753471441471025246471931649633_wp, &
         a146 = 6.724547581906459363100870806514855026676_wp, &
         a147 = -0.425444280164611790606983409697113064616_wp, &
         a148 = 3.343279153001265577811816947557982637749_wp, &
         a149 = 0.617081663117537759528421117507709784737_wp, &
         a1410 = -0.929966123939932833937749523988800852013_wp, &
         a1411 = -6.099948804751010722472962837945508844846_wp, &
         a1412 = -3.002206187889399044804158084895173690015_wp, &
         a1413 = 0.2553202529443445472336424602988558373637_wp
      !> a(15, j), the couplings of stage 15
      real(wp) :: a151 = -0.779374086122884664644623040843840506343_wp, &
         a156 = -13.93734253810777678786523664804936051203_wp, &
         a157 = 1.252048853379357320949735183924200895136_wp, &
         a158 = -14.69150040801686878191527989293072091588_wp, &
         a159 = -0.494705058533141685655191992136962873577_wp, &
         a1510 = 2.242974909146236657906984549543692874755_wp, &
         a1511 = 13.36789380382864375813864978592679139881_wp, &
         a1512 = 14.39665048665068644512236935340272139005_wp, &
         a1513 = -0.7975813331776800379127866056663258667437_wp, &
         a1514 = 0.4409353709534277758753793068298041158235_wp
      !> a(16, j), the couplings of stage 16
      real(wp) :: a161 = 2.058051337466886442151242368989994043993_wp, &
         a166 = 22.35793772796803295519317565842520212899_wp, &
         a167 = 0.90949810997556332745009198137971890783_wp, &
         a168 = 35.89110098240264104710550686568482456493_wp, &
         a169 = -3.442515027624453437985000403608480262211_wp, &
         a1610 = -4.865481358036368826566013387928704014496_wp, &
         a1611 = -18.90980381354342625688427480879773032857_wp, &
         a1612 = -34.26354448030451782929251177395134170515_wp, &
         a1613 = 1.264756521695642578827783499806516664686_wp
      !> weights b(i) of the propagating formula
      real(wp) :: b1 = v9_b1, b8 = v9_b8, b9 = v9_b9, b10 = v9_b10, b11 = v9_b11, b12 = v9_b12, b13 = v9_b13, &
         b14 = v9_b14, b15 = v9_b15
      !> weights b̂(i) of the embedded formula
      real(wp) :: bh1 = v9_bh1, bh8 = v9_bh8, bh9 = v9_bh9, bh10 = v9_bh10, bh11 = v9_bh11, bh12 = v9_bh12, &
         bh13 = v9_bh13, bh16 = v9_bh16
      !> error weights b̂(i) − b(i), 8th- against 9th-order formula
      real(wp) :: e1 = v9_bh1 - v9_b1, e8 = v9_bh8 - v9_b8, e9 = v9_bh9 - v9_b9, e10 = v9_bh10 - v9_b10, &
         e11 = v9_bh11 - v9_b11, e12 = v9_bh12 - v9_b12, e13 = v9_bh13 - v9_b13, e14 = -v9_b14, e15 = -v9_b15, &
         e16 = v9_bh16
   end type vern98_tableau_t

   !> The coefficients of DOPRI5.
   type(dopri5_tableau_t), parameter :: dopri5 = dopri5_tableau_t()
   !> The coefficients of DOP853 and its continuous extension.
   type(dop853_tableau_t), parameter :: dop853 = dop853_tableau_t()
   !> The coefficients of PD8(7).
   type(pd87_tableau_t), parameter :: pd87 = pd87_tableau_t()
   !> The coefficients of VERN98.
   type(vern98_tableau_t), parameter :: vern98 = vern98_tableau_t()

contains

   !> The row of a pair code (a row named "unknown", of order 0, for any other code).
   pure function rk_pair(method) result(pair)
      integer, intent(in) :: method  !! rk_dopri5, rk_dop853, rk_pd87 or rk_vern98
      type(rk_pair_t) :: pair
      if (method >= 1 .and. method <= size(rk_pairs)) pair = rk_pairs(method)
   end function rk_pair

   !> Name of a method constant.
   pure function rk_method_name(method) result(name)
      integer, intent(in) :: method  !! rk_dopri5, rk_dop853, rk_pd87 or rk_vern98
      character(len=:), allocatable :: name
      type(rk_pair_t) :: pair
      pair = rk_pair(method)
      name = trim(pair%name)
   end function rk_method_name

   !> Classical order of the propagating formula (5, 8 or 9; 0 if unknown).
   pure integer function rk_method_order(method) result(order)
      integer, intent(in) :: method  !! rk_dopri5, rk_dop853, rk_pd87 or rk_vern98
      type(rk_pair_t) :: pair
      pair = rk_pair(method)
      order = pair%order
   end function rk_method_order

   !> Largest admissible PI parameter β of a method (exclusive). The controller divides h
   !> by err^(k − cβ)/err_old^β (k = 1/order, c = `pi_weight`: 0.2 for the 8th- and
   !> 9th-order pairs, 0.75 for DOPRI5); with err = err_old = e in a steady state the
   !> step stays put where e^(k − (1 + c)β) = safety, which keeps e below 1 only while
   !> k − (1 + c)β > 0. At and above that β the fixed point moves to e > 1 (every step
   !> rejected) or, through the rejections, to e → 0: the steps collapse. Hairer's codes
   !> accept any β ≤ 0.2. 0 for an unknown method.
   pure real(wp) function rk_beta_limit(method) result(limit)
      integer, intent(in) :: method  !! a method constant
      type(rk_pair_t) :: pair
      pair = rk_pair(method)
      limit = 0.0_wp
      if (pair%order > 0) limit = (1.0_wp/pair%order)/(1.0_wp + pair%pi_weight)
   end function rk_beta_limit

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
      c(2:14) = [vern98%c2, vern98%c3, vern98%c4, vern98%c5, vern98%c6, vern98%c7, vern98%c8, vern98%c9, &
                 vern98%c10, vern98%c11, vern98%c12, vern98%c13, vern98%c14]
      c(15:16) = 1.0_wp
      a(2, [1]) = [vern98%a21]
      a(3, [1, 2]) = [vern98%a31, vern98%a32]
      a(4, [1, 3]) = [vern98%a41, vern98%a43]
      a(5, [1, 3, 4]) = [vern98%a51, vern98%a53, vern98%a54]
      a(6, [1, 4, 5]) = [vern98%a61, vern98%a64, vern98%a65]
      a(7, [1, 4, 5, 6]) = [vern98%a71, vern98%a74, vern98%a75, vern98%a76]
      a(8, [1, 6, 7]) = [vern98%a81, vern98%a86, vern98%a87]
      a(9, [1, 6, 7, 8]) = [vern98%a91, vern98%a96, vern98%a97, vern98%a98]
      a(10, [1, 6, 7, 8, 9]) = [vern98%a101, vern98%a106, vern98%a107, vern98%a108, vern98%a109]
      a(11, [1, 6, 7, 8, 9, 10]) = [vern98%a111, vern98%a116, vern98%a117, vern98%a118, vern98%a119, vern98%a1110]
      a(12, [1, 6, 7, 8, 9, 10, 11]) = [vern98%a121, vern98%a126, vern98%a127, vern98%a128, vern98%a129, &
                                        vern98%a1210, vern98%a1211]
      a(13, [1, 6, 7, 8, 9, 10, 11, 12]) = [vern98%a131, vern98%a136, vern98%a137, vern98%a138, vern98%a139, &
                                            vern98%a1310, vern98%a1311, vern98%a1312]
      a(14, [1, 6, 7, 8, 9, 10, 11, 12, 13]) = [vern98%a141, vern98%a146, vern98%a147, vern98%a148, vern98%a149, &
                                                vern98%a1410, vern98%a1411, vern98%a1412, vern98%a1413]
      a(15, [1, 6, 7, 8, 9, 10, 11, 12, 13, 14]) = [vern98%a151, vern98%a156, vern98%a157, vern98%a158, &
                                                    vern98%a159, vern98%a1510, vern98%a1511, vern98%a1512, &
                                                    vern98%a1513, vern98%a1514]
      a(16, [1, 6, 7, 8, 9, 10, 11, 12, 13]) = [vern98%a161, vern98%a166, vern98%a167, vern98%a168, vern98%a169, &
                                                vern98%a1610, vern98%a1611, vern98%a1612, vern98%a1613]
      b([1, 8, 9, 10, 11, 12, 13, 14, 15]) = [vern98%b1, vern98%b8, vern98%b9, vern98%b10, vern98%b11, vern98%b12, &
                                              vern98%b13, vern98%b14, vern98%b15]
      b_embedded([1, 8, 9, 10, 11, 12, 13, 16]) = [vern98%bh1, vern98%bh8, vern98%bh9, vern98%bh10, vern98%bh11, &
                                                   vern98%bh12, vern98%bh13, vern98%bh16]
   end subroutine rk_vern98_tableau
end module hillstab_integrate_rk_tableaux

/* hillstab C interface: stability of the elastic pendulum through the Hill
 * equation x'' + Q(tau) x = 0, Q = (beta - alpha cos pi tau)/(1 - (alpha/pi^2) cos pi tau).
 * Shared library: cc $(pkg-config --cflags hillstab) app.c $(pkg-config --libs hillstab)
 * (-lhillstab alone: the library records its own dependencies).
 * Static library: name the archive, then its dependencies (the Libs.private of hillstab.pc,
 * which `pkg-config --static --libs hillstab` appends to -lhillstab):
 *   cc $(pkg-config --cflags hillstab) app.c "$(pkg-config --variable=libdir hillstab)/libhillstab.a" \
 *      -lgsl -lgslcblas -llapack -lblas -lgfortran -lgomp -lm
 * Both libraries are installed in one directory, so -lhillstab (also in the --static
 * output) picks the shared one.
 * Every int-returning function returns 0 on success or an error code (see
 * hillstab_error_message); outputs are untouched on failure, except
 * HILLSTAB_ERR_ACCURACY (7: the tolerance is below what double precision reaches there),
 * where they hold the best value, and hillstab_last_error gives the full message of
 * the failure. */
#ifndef HILLSTAB_H
#define HILLSTAB_H
#include <stddef.h>

/* The version this header belongs to (the library's: hillstab_version). */
#define HILLSTAB_VERSION_MAJOR 0
#define HILLSTAB_VERSION_MINOR 1
#define HILLSTAB_VERSION_PATCH 0
#define HILLSTAB_VERSION_STRING "0.1.0"

#ifdef __cplusplus
extern "C" {
#endif

enum {
  HILLSTAB_MODEL_ELASTIC = 1, HILLSTAB_MODEL_MATHIEU = 2, HILLSTAB_MODEL_MEISSNER = 3, HILLSTAB_MODEL_FOURIER = 4,
  HILLSTAB_MODEL_SAMPLED = 5, HILLSTAB_MODEL_MODULATED = 6, HILLSTAB_MODEL_EQUATION = 7
};
enum {
  HILLSTAB_METHOD_AUTO = 0, HILLSTAB_METHOD_FORMULA = 1, HILLSTAB_METHOD_SEGMENTS = 2, HILLSTAB_METHOD_MAGNUS4 = 3,
  HILLSTAB_METHOD_MAGNUS6 = 4, HILLSTAB_METHOD_RK = 5, HILLSTAB_METHOD_GSL = 6
};
enum { HILLSTAB_SAMPLING_ENDPOINT = 1, HILLSTAB_SAMPLING_MIDPOINT = 2, HILLSTAB_SAMPLING_AVERAGE = 3 };
/* The spacing of a chart's axis (hillstab_chart_scaled): equally spaced, or geometric. */
enum { HILLSTAB_SCALE_LINEAR = 0, HILLSTAB_SCALE_LOG = 1 };
enum {
  HILLSTAB_ERR_INVALID_PARAMETER = 1, HILLSTAB_ERR_OVERFLOW = 2, HILLSTAB_ERR_INTEGRATION = 3,
  HILLSTAB_ERR_IO = 4, HILLSTAB_ERR_INPUT = 5, HILLSTAB_ERR_SINGULAR = 6, HILLSTAB_ERR_ACCURACY = 7
};

/* Q(tau) including the damping shift -epsilon^2/4 of eq. (47). */
int hillstab_q(int model, double alpha, double beta, double epsilon, double tau, double *q);

/* One-period monodromy trace S (S1 of the chi equation when epsilon > 0).
 * On overflow: *trace = +-DBL_MAX, *overflow = 1, *log_abs_trace = ln|S|. */
int hillstab_trace(int model, double alpha, double beta, double epsilon, int method, int n_segments,
                   int sampling, double tolerance, double *trace, double *log_abs_trace, int *overflow);

/* Floquet data of the swing x: log_modulus[2] = ln|lambda| (largest first), exponent = ln|lambda_max|/2
 * per unit tau, stable = (|S1| < 2 cosh epsilon), stable_paper = (|S1| <= 2). */
int hillstab_floquet_data(int model, double alpha, double beta, double epsilon, int method, int n_segments,
                     int sampling, double tolerance, double *trace, double log_modulus[2], double *exponent,
                     int *stable, int *stable_paper);

/* The paper's closed forms eq. (37) (epsilon = 0) and eq. (48)-(50); +-DBL_MAX on overflow.
 * No error channel: bad parameters give a meaningless value silently (kept for compatibility). */
double hillstab_trace_paper(double alpha, double beta, double epsilon);

/* The same closed forms with a status (as hillstab_trace with HILLSTAB_METHOD_FORMULA on the
 * elastic model): parameters checked; on overflow *trace = +-DBL_MAX, *overflow = 1,
 * *log_abs_trace = ln|S|. */
int hillstab_trace_paper_checked(double alpha, double beta, double epsilon, double *trace,
                                 double *log_abs_trace, int *overflow);

/* The first n transition values of beta of each kind at alpha (the characteristic values;
 * Mathieu's a_n(q), b_n(q) for HILLSTAB_MODEL_MATHIEU: beta = pi^2 a/4 at alpha = nu = pi^2 q/2):
 * *count values in beta[], order[] (n of a_n, b_n), kind[] and error_bound[], by kind then
 * ascending. kind: HILLSTAB_KIND_* (1 periodic even a_0, a_2, ...; 2 periodic odd b_2, b_4, ...;
 * 3 antiperiodic even a_1, a_3, ...; 4 antiperiodic odd b_1, b_3, ... where Q is even, else
 * 5 periodic and 6 antiperiodic, both edges of each order). capacity: places in each array
 * (4 n always suffice); tolerance > 0: target error relative to max(1, |beta|). */
enum {
  HILLSTAB_KIND_PERIODIC_EVEN = 1, HILLSTAB_KIND_PERIODIC_ODD = 2, HILLSTAB_KIND_ANTIPERIODIC_EVEN = 3,
  HILLSTAB_KIND_ANTIPERIODIC_ODD = 4, HILLSTAB_KIND_PERIODIC = 5, HILLSTAB_KIND_ANTIPERIODIC = 6
};
int hillstab_characteristic_values(int model, double alpha, int n, double tolerance, int capacity, int *count,
                                   double beta[], int order[], int kind[], double error_bound[]);

/* A NUL-terminated description of a status code (the name of the code, e.g. "invalid parameter"). */
void hillstab_error_message(int status, char *buffer, size_t length);

/* The full message of the most recent status-returning hillstab call made by the calling
 * thread (e.g. "elastic model needs 0 <= alpha < pi**2 = 9.8696044010893586, got alpha = ..."),
 * NUL-terminated and cut to length bytes; "" when that call succeeded. Returns that call's status.
 * Each thread has its own record, so calls from several threads do not mix. */
int hillstab_last_error(char *buffer, size_t length);

/* The version of the library linked at run time, "MAJOR.MINOR.PATCH" (compare
 * HILLSTAB_VERSION_STRING, the version compiled against); a static string, never freed. */
const char *hillstab_version(void);

/* The same as three numbers. */
void hillstab_version_numbers(int *major, int *minor, int *patch);

/* ---- Models as values, batches of points, transition curves, scenes ----
 * A model is an opaque handle made from a name of the model registry
 * (hillstab_model_registry_name lists them); the batch functions take it, compute every
 * point inside the call (OpenMP threads: `threads`, 0 for the OpenMP default) and give
 * each point the values of a chart or points file and a status (0 ok, 1 round-off
 * limited: the best value double precision allows, 2 failed: the files' placeholders).
 * The values equal the command line's files to the bit for the same model, method and
 * tolerance. Bad input fails the whole call before any work (outputs untouched, the
 * message in hillstab_last_error). A handle may be used by several threads at once;
 * hillstab_model_set and hillstab_model_free not while another thread uses it. */
typedef struct hillstab_model hillstab_model;

/* What a batch must compute to the tolerance: the verdicts (a screening pass settles most
 * points), the growth (lambda_max, mu: exact where |S| < 2), or S at every point. */
enum { HILLSTAB_NEED_VERDICT = 1, HILLSTAB_NEED_GROWTH = 2, HILLSTAB_NEED_TRACE = 3 };

/* The values of a point, values[j][HILLSTAB_VALUE_*]: S (+-1e300 with overflow = 1 beyond),
 * ln|S|, log10|S| (at least -300), overflow, stable (1, 0, or 0.5 when marginal),
 * stable_paper (|S1| <= 2), lambda_max (at most 1e300), ln|lambda| of both multipliers of x
 * (largest first), mu = ln|lambda_max|/2 per unit tau, the method's error estimate (-1: none),
 * the kind (0 stable, 1 unstable at +1, 2 at -1, 4 damped, 5 undecided) and arg(lambda_max)/pi
 * (0 at +1, 1 at -1, the rotation number arccos(S/2)/pi where |S| < 2).
 * With damping S (and ln|S|, log10|S|, stable_paper) is S1, the trace of chi = e^(eps tau/2) x;
 * stable, lambda_max, the ln|lambda|, mu and the argument are of x. Below HILLSTAB_NEED_GROWTH a
 * chart leaves the logarithms, lambda_max, mu and the argument at 0. */
enum {
  HILLSTAB_VALUE_TRACE = 0, HILLSTAB_VALUE_LOG_ABS_TRACE = 1, HILLSTAB_VALUE_LOG10_ABS_TRACE = 2,
  HILLSTAB_VALUE_OVERFLOW = 3, HILLSTAB_VALUE_STABLE = 4, HILLSTAB_VALUE_STABLE_PAPER = 5,
  HILLSTAB_VALUE_LAMBDA_MAX = 6, HILLSTAB_VALUE_LOG_MODULUS_MAX = 7, HILLSTAB_VALUE_LOG_MODULUS_MIN = 8,
  HILLSTAB_VALUE_EXPONENT = 9, HILLSTAB_VALUE_ERROR_ESTIMATE = 10, HILLSTAB_VALUE_KIND = 11,
  HILLSTAB_VALUE_ARGUMENT = 12, HILLSTAB_VALUE_COUNT = 13
};

/* The values by the names of the columns of chart and points files (and of Python's results),
 * the one vocabulary: S, log10_abs_S and mu (the other values' names already are the files';
 * ln|S| has no column, LOG_ABS_S is in the same style). HILLSTAB_VALUE_TRACE, _LOG_ABS_TRACE,
 * _LOG10_ABS_TRACE and _EXPONENT stay as aliases for this release. */
enum {
  HILLSTAB_VALUE_S = 0, HILLSTAB_VALUE_LOG_ABS_S = 1, HILLSTAB_VALUE_LOG10_ABS_S = 2, HILLSTAB_VALUE_MU = 9
};

/* hillstab_run_scene: the file was written, but some of its points failed (status 2 rows). */
enum { HILLSTAB_ERR_POINTS_FAILED = 8 };

/* The registry: its number of models, and the name of model index (1 ... count, its
 * HILLSTAB_MODEL_* code). */
int hillstab_model_count(void);
int hillstab_model_registry_name(int index, char *buffer, size_t length);

/* A model of the registry by name (any case), its data at their defaults; free it with
 * hillstab_model_free (NULL is ignored). */
int hillstab_model_new(const char *name, hillstab_model **model);
void hillstab_model_free(hillstab_model *model);

/* Set a variable of a model that carries data (the elastic and Mathieu models have none);
 * hillstab_model_check: whether the model is complete (every computation checks too). */
int hillstab_model_set(hillstab_model *model, const char *variable, const double *values, size_t count);
/* Set a text variable (the equation model's parameters, stiffness, mass, damping, frequency
 * or period, alpha and beta: expressions and names, as in its scene group &equation). */
int hillstab_model_set_text(hillstab_model *model, const char *variable, const char *text);
int hillstab_model_check(const hillstab_model *model);

/* The model's name, its coefficient Q as output headers state it, its variables. */
int hillstab_model_name(const hillstab_model *model, char *buffer, size_t length);
int hillstab_model_formula(const hillstab_model *model, char *buffer, size_t length);
int hillstab_model_variable_count(const hillstab_model *model, int *count);
int hillstab_model_variable_name(const hillstab_model *model, int index, char *buffer, size_t length,
                                 int *max_count);

/* d tau/dt at the n points (alpha[j], beta[j]): rate[j] turns a rate per unit tau (mu) into one
 * per unit of the model's own time t (an equation: Omega/pi at the point); 0 for a model in tau
 * alone and at a point outside the domain. */
int hillstab_model_tau_rate(const hillstab_model *model, size_t n, const double *alpha, const double *beta,
                            double *rate);

/* The n points (alpha[j], beta[j], epsilon[j]) as task points computes them:
 * values[j][HILLSTAB_VALUE_*], status[j]. paper = 1 settles the paper's verdict too. */
int hillstab_points(const hillstab_model *model, size_t n, const double *alpha, const double *beta,
                    const double *epsilon, int method, int n_segments, int sampling, double tolerance,
                    int need, int paper, int threads, double *values, int *status);

/* The chart of task chart over n_alpha x n_beta grid values (ends included): alpha[i], beta[j],
 * values[i][j][HILLSTAB_VALUE_*], status[i][j]; HILLSTAB_NEED_VERDICT computes the verdicts only. */
int hillstab_chart(const hillstab_model *model, double alpha_min, double alpha_max, size_t n_alpha,
                   double beta_min, double beta_max, size_t n_beta, double epsilon, int method, int n_segments,
                   int sampling, double tolerance, int need, int paper, int threads, double *alpha,
                   double *beta, double *values, int *status);
/* hillstab_chart with a scale for each axis: HILLSTAB_SCALE_LINEAR (equally spaced, as
 * hillstab_chart) or HILLSTAB_SCALE_LOG (geometric, both ends in (0, 1e300]), the grid of
 * &chart alpha_scale, beta_scale. */
int hillstab_chart_scaled(const hillstab_model *model, double alpha_min, double alpha_max, size_t n_alpha,
                          int alpha_scale, double beta_min, double beta_max, size_t n_beta, int beta_scale,
                          double epsilon, int method, int n_segments, int sampling, double tolerance, int need,
                          int paper, int threads, double *alpha, double *beta, double *values, int *status);

/* alpha (elastic: a pi^2/rho), beta = g pi^2/(rho omega^2) and epsilon = kappa pi/omega of a
 * pendulum in SI units (r0 m, g m/s^2, omega = sqrt(k/m) rad/s, a m, kappa 1/s). */
int hillstab_physical(const hillstab_model *model, double r0, double g, double omega, double a, double kappa,
                      double *alpha, double *beta, double *epsilon);

/* The transition curves |S| = 2 crossing [beta_min, beta_max] at each alpha[i] by Hill's
 * method: count[i] curves by beta, the first `capacity` in row i of the [n_alpha][capacity]
 * arrays (beta, order n, parity +1 a_n / -1 b_n, trace_sign +2 / -2, error_bound,
 * coexistent 1 for a tongue of zero width); status[i] 2 where the method failed. */
int hillstab_transition_curves(const hillstab_model *model, size_t n_alpha, const double *alpha,
                               double beta_min, double beta_max, double tolerance, size_t capacity,
                               int threads, double *beta, int *order, int *parity, int *trace_sign,
                               double *error_bound, int *coexistent, size_t *count, int *status);

/* Run a namelist scene file as `hillstab SCENE.nml` does (quiet = 1: no progress on stderr);
 * the output file's path goes to written (on success and with HILLSTAB_ERR_POINTS_FAILED). */
int hillstab_run_scene(const char *path, int quiet, char *written, size_t length);

/* ---- Systems of Hill equations ----
 * M x'' + (C + eps M + G) x' + K(tau) x = 0, x in R^n (n = 1 ... 20), K = K0 + beta B +
 * alpha sum_k (Kc_k cos(2 pi k tau/P) + Ks_k sin(2 pi k tau/P)): an opaque handle made empty,
 * its variables set by name: "n" first, then "mass", "damping", "gyroscopic", "k0", "b" (n*n
 * numbers each, row by row; defaults I, 0, 0, 0, I), "cos", "sin" (H blocks of n*n numbers,
 * K_1 first; at least one nonzero) and "period" (a multiple of 2, default 2). Messages start
 * with the function's name and name the argument ("hillstab_system_set: mass: M must be
 * positive definite ..."). Methods: HILLSTAB_METHOD_AUTO, _MAGNUS4, _MAGNUS6, _RK or _GSL;
 * tolerance in (1e-15, 1). A monodromy no mesh brings to the tolerance fails the call
 * (HILLSTAB_ERR_INTEGRATION); *status is 0, or 1 when round-off limited (the best value). */
typedef struct hillstab_system hillstab_system;

/* The verdict of a system's point: decided within the monodromy's error bound, else marginal. */
enum {
  HILLSTAB_SYSTEM_VERDICT_UNSTABLE = 0, HILLSTAB_SYSTEM_VERDICT_STABLE = 1, HILLSTAB_SYSTEM_VERDICT_MARGINAL = -1
};

/* Where the largest multiplier leaves the unit circle: at +1, at -1, off the real axis (a
 * combination resonance, Krein collision); or stable, or damped (every |lambda| < 1), or
 * undecided (the verdict is marginal). */
enum {
  HILLSTAB_SYSTEM_KIND_STABLE = 0, HILLSTAB_SYSTEM_KIND_PLUS_ONE = 1, HILLSTAB_SYSTEM_KIND_MINUS_ONE = 2,
  HILLSTAB_SYSTEM_KIND_COMBINATION = 3, HILLSTAB_SYSTEM_KIND_DAMPED = 4,
  HILLSTAB_SYSTEM_KIND_UNDECIDED = 5
};

/* An empty system (free it with hillstab_system_free, NULL is ignored). */
int hillstab_system_new(hillstab_system **system);
void hillstab_system_free(hillstab_system *system);

/* An empty system of the kind `name` (any case): "system" (as hillstab_system_new) or
 * "equations", n coupled equations in physical time M x'' + (C + G) x' + K(t) x = 0 with
 * named parameters and matrices (the scene group &equations): "n" by hillstab_system_set,
 * its texts by hillstab_system_set_text. Its damping is its own, converted at each point's
 * alpha (the first axis' parameter): epsilon must be 0. */
int hillstab_system_new_named(const char *name, hillstab_system **system);

/* Set a variable to count numbers; once n is given the variable is checked on its own (its
 * size, M symmetric positive definite, C symmetric, G skew; the system unchanged on failure).
 * hillstab_system_check: whether the system is complete; hillstab_system_dof: n. */
int hillstab_system_set(hillstab_system *system, const char *variable, const double *values, size_t count);
int hillstab_system_check(const hillstab_system *system);
int hillstab_system_dof(const hillstab_system *system, int *n);
/* The size m of the state: 2n, or n for a system in first-order form (an equations system
 * given the text "state", y' = A(t) y): Phi is then n x n with n multipliers and n exponents. */
int hillstab_system_states(const hillstab_system *system, int *states);

/* Set a text variable of an equations system: parameters, matrices ("W = [1, 0; 0, 4], ..."),
 * stiffness (or state: A(t) of the first-order form y' = A(t) y), mass, damping, gyroscopic,
 * frequency or period, alpha, beta, as in &equations.
 * An unknown variable is refused here; what the texts say together by hillstab_system_check
 * and every computation, the message naming the variable. */
int hillstab_system_set_text(hillstab_system *system, const char *variable, const char *text);

/* The monodromy over one period, Phi = exp(log_scale) Phi~: phi[2n][2n] = Phi~ (row-major,
 * acting on (x, x'); phi[n][n] acting on y in first-order form), its error estimate relative
 * to max(1, max|Phi~_ij|). */
int hillstab_system_monodromy(const hillstab_system *system, double alpha, double beta, double epsilon,
                              int method, double tolerance, double *phi, double *log_scale,
                              double *error_estimate, int *status);

/* Floquet analysis (first-order form: n multipliers and n exponents, hillstab_system_states):
 * the 2n multipliers by decreasing modulus (Phi's own with *log_scale = 0
 * when they are at most 1e300, else Phi~'s: Phi's = exp(log_scale) times them), the exponents
 * ln|lambda_i|/P of the n largest (each to the tolerance, from the factored product where Phi
 * cannot resolve it), HILLSTAB_SYSTEM_VERDICT_*, HILLSTAB_SYSTEM_KIND_*, tr Phi and
 * a2 = sum lambda_i lambda_j (+-1e300 beyond), the structural defect relative to |Phi|^2 (or
 * to Hadamard's bound of det Phi when damped). A system of one equation ("equations", n = 1,
 * second order) on HILLSTAB_METHOD_AUTO takes the scalar method auto, as the tasks, points
 * and chart do: the same analysis from its trace S, a2 = det Phi exactly, defect 0, the error
 * estimate S's relative to max(1, |S|). */
int hillstab_system_floquet(const hillstab_system *system, double alpha, double beta, double epsilon,
                            int method, double tolerance, double *multipliers_re, double *multipliers_im,
                            double *log_scale, double *exponents, int *verdict, int *kind, double *trace,
                            double *a2, double *defect, double *error_estimate, int *status);

/* The critical drives at a fixed beta: every alpha of [alpha_min, alpha_max] where the
 * stability at beta and damping epsilon changes, ascending; *count of them, the first
 * `capacity` stored: alpha, the bound of its error, side (+1: S reaches +2 cosh(eps P/2),
 * -1: -2 cosh(eps P/2)), direction (+1: stable below, unstable above; -1 the reverse) and
 * status (0 confirmed by the verdicts on both sides, 2 not). S by `method` to `tolerance`
 * (also the target of alpha, relative to max(1, |alpha|)); n_samples >= 2 values of alpha
 * are sampled, and a region narrower than the samples is found where |S| comes near the
 * threshold at a neighbouring sample. */
int hillstab_critical_drives(const hillstab_model *model, double beta, double alpha_min, double alpha_max,
                             double epsilon, int method, double tolerance, int n_samples, size_t capacity,
                             double *alpha, double *alpha_error, int *side, int *direction, int *status,
                             size_t *count);
/* hillstab_critical_drives along either axis: axis 1 searches alpha in [low, high] at
 * beta = fixed, axis 2 beta at alpha = fixed (an equation's drive amplitude at one
 * frequency); each point's damping is the model's (epsilon 0 for an equation). */
int hillstab_critical_drives_along(const hillstab_model *model, int axis, double fixed, double low, double high,
                                   double epsilon, int method, double tolerance, int n_samples, size_t capacity,
                                   double *value, double *value_error, int *side, int *direction, int *status,
                                   size_t *count);

/* Many points at once, as the tasks compute them, on `threads` OpenMP threads (0: the
 * default): values[j][k] over the columns of a system's files (14 + n: alpha beta trace a2
 * overflow stable kind lambda_max mu argument mu_1 ... mu_n defect error_estimate status
 * steps; hillstab_system_column_name) and status[j] (0, 1 round-off limited, 2 failed with a
 * file's placeholders; HILLSTAB_ERR_POINTS_FAILED when any failed, every value written).
 * hillstab_system_points computes each point alone (task points); hillstab_system_chart the
 * grid of task chart (alpha index outer), a row's points sharing their nodes. */
int hillstab_system_column_count(const hillstab_system *system, int *count);
int hillstab_system_column_name(const hillstab_system *system, int index, char *name, size_t length);
/* d tau/dt at the n points (alpha[j], beta[j]): rate[j] turns a rate per unit tau (mu, mu_k) into
 * one per unit of the system's own time t (a system of equations: Omega/pi at the point); 0 for a
 * system in tau alone and at a point outside the domain. */
int hillstab_system_tau_rate(const hillstab_system *system, size_t n, const double *alpha, const double *beta,
                             double *rate);
int hillstab_system_points(const hillstab_system *system, size_t n, const double *alpha, const double *beta,
                           const double *epsilon, int method, double tolerance, int threads, double *values,
                           int *status);
int hillstab_system_chart(const hillstab_system *system, double alpha_min, double alpha_max, size_t n_alpha,
                          double beta_min, double beta_max, size_t n_beta, double epsilon, int method,
                          double tolerance, int threads, double *alpha, double *beta, double *values,
                          int *status);
/* hillstab_system_chart with a scale for each axis (HILLSTAB_SCALE_*, as hillstab_chart_scaled). */
int hillstab_system_chart_scaled(const hillstab_system *system, double alpha_min, double alpha_max, size_t n_alpha,
                                 int alpha_scale, double beta_min, double beta_max, size_t n_beta, int beta_scale,
                                 double epsilon, int method, double tolerance, int threads, double *alpha,
                                 double *beta, double *values, int *status);

/* ---- Resonance regions ----
 * For a driven problem, every resonance region of order k = 1 ... order (1 ... 8) predicted
 * from the natural frequencies nu_i(f) of the undriven problem (fractions of the drive
 * frequency) over f in [f_min, f_max]: simple (2 nu_i = k), sum (nu_i + nu_j = k) or
 * difference (|nu_i - nu_j| = k); for each, its tip (the least drive in [d_min, d_max] at
 * which it opens, and the frequency there, each with an error bound), its edges at d_max and
 * a status. drive_axis: 1 (the drive is alpha, f is beta: the built-in models, whose alpha is
 * the drive amplitude, and a system's alpha sum of drives) or 2 (the drive is beta, f is
 * alpha: an equation or equations in physical time, alpha its frequency). *count regions,
 * ascending in their predicted f; the first `capacity` stored in the parallel arrays: kind,
 * orders (k), modes (i, j: two a region), predicted (f at drive 0), window (the frequencies
 * searched, two a region), frequency and frequency_error, drive and drive_error (the tip),
 * edges (f of the edges at d_max, two a region, both 0 where it is not open there), clipped
 * (1 where an edge is the window's end, two a region), status and evaluations (distances
 * computed). With capacity 0 the arrays may be NULL. tolerance: the method's target and the
 * tips', relative to max(1, |x|); n_samples >= 2 drives sampled for a first root. Status:
 * found (confirmed on both sides), closed (stable up to d_max over the window: drive is
 * d_max), unconfirmed, open below (unstable at d_min already), theory (undamped and the
 * undriven problem constant in time: the tip is the resonance itself at drive 0), same
 * signature (a difference region of two modes of equal Krein signature: closed, not
 * searched), uncovered (kind unassigned: a stretch of d_max unstable outside every region's
 * edges, found by 1000 samples of it; its edges there, its tip not searched). */
enum { HILLSTAB_REGION_UNASSIGNED = 0, HILLSTAB_REGION_SIMPLE = 1, HILLSTAB_REGION_SUM = 2, HILLSTAB_REGION_DIFFERENCE = 3 };
enum {
  HILLSTAB_REGION_FOUND = 0, HILLSTAB_REGION_CLOSED = 1, HILLSTAB_REGION_UNCONFIRMED = 2,
  HILLSTAB_REGION_OPEN_BELOW = 3, HILLSTAB_REGION_THEORY = 4, HILLSTAB_REGION_SAME_SIGNATURE = 5,
  HILLSTAB_REGION_UNCOVERED = 6
};
/* The regions of a model's equation with damping epsilon (0 for a model with its own);
 * S by method (HILLSTAB_METHOD_*). */
int hillstab_regions(const hillstab_model *model, int drive_axis, double f_min, double f_max, double d_min,
                     double d_max, double epsilon, int method, double tolerance, int order, int n_samples,
                     size_t capacity, int *kind, int *orders, int *modes, double *predicted, double *window,
                     double *frequency, double *frequency_error, double *drive, double *drive_error,
                     double *edges, int *clipped, int *status, int *evaluations, size_t *count);
/* The regions of a system with damping epsilon M (0 for an equations system); Phi by a
 * system method, tolerance in (1e-15, 1); messages start with "hillstab_system_regions: ". */
int hillstab_system_regions(const hillstab_system *system, int drive_axis, double f_min, double f_max,
                            double d_min, double d_max, double epsilon, int method, double tolerance, int order,
                            int n_samples, size_t capacity, int *kind, int *orders, int *modes, double *predicted,
                            double *window, double *frequency, double *frequency_error, double *drive,
                            double *drive_error, double *edges, int *clipped, int *status, int *evaluations,
                            size_t *count);

#ifdef __cplusplus
}
#endif
#endif

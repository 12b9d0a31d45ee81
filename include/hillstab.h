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

enum { HILLSTAB_MODEL_ELASTIC = 1, HILLSTAB_MODEL_MATHIEU = 2, HILLSTAB_MODEL_MEISSNER = 3 };
enum {
  HILLSTAB_METHOD_AUTO = 0, HILLSTAB_METHOD_FORMULA = 1, HILLSTAB_METHOD_SEGMENTS = 2,
  HILLSTAB_METHOD_MAGNUS4 = 3, HILLSTAB_METHOD_MAGNUS6 = 4, HILLSTAB_METHOD_RK = 5, HILLSTAB_METHOD_GSL = 6
};
enum { HILLSTAB_SAMPLING_ENDPOINT = 1, HILLSTAB_SAMPLING_MIDPOINT = 2, HILLSTAB_SAMPLING_AVERAGE = 3 };
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

#ifdef __cplusplus
}
#endif
#endif

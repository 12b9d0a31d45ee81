/* The plain C program a user would write with GSL for the chart of the damped Kapitza
 * pendulum in physical time, the contender of `make bench-equation` (scripts/bench_equation.py).
 *
 *   cc -O2 bench/chart_gsl_kapitza.c -o build/chart_gsl_kapitza -lgsl -lgslcblas -lm
 *   build/chart_gsl_kapitza N_W N_A TOL [OUT]        the chart, w in [60, 700], A in [0, 0.1]
 *   build/chart_gsl_kapitza --points FILE TOL OUT    the points "w A" of FILE, one a line
 *
 * The equation of data/scenes/kapitza_chart.nml as written, in physical time t:
 *   theta'' + kappa theta' + (-g/l + (A w^2/l) cos(w t)) theta = 0,  g = 9.81, l = 0.2, kappa = 0.2.
 * At each point the 2 x 2 fundamental matrix (4 equations: the solutions from (1, 0) and from
 * (0, 1)) from t = 0 over one whole period T = 2 pi/w by gsl_odeiv2_driver_apply with rk8pd,
 * epsabs = epsrel = TOL, first step T/100; no symmetry used (the damping makes the equation as
 * written not even in t). One driver, reset for each point. The grid is hillstab's (w_i = lo +
 * (hi - lo)(i - 1)/(n - 1), the last value exactly hi), rows over w.
 *
 * Prints the wall time of the loop (seconds) and the right-hand-side evaluations; with OUT,
 * writes "w A trace S1 stable" per point after the timed loop: trace = trace of the monodromy
 * of (theta, theta'), S1 = exp(kappa T/2) trace (hillstab's S of a damped equation), stable = 1
 * when both multipliers are inside the unit circle (|trace| < 1 + det, det = exp(-kappa T)).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

static const double g = 9.81, l = 0.2, kappa = 0.2;

struct kapitza {
   double w, a_w2_l;   /* the drive frequency and A w^2/l */
   long evaluations;
};

static int rhs(double t, const double y[], double f[], void *params) {
   struct kapitza *p = params;
   double k = -g / l + p->a_w2_l * cos(p->w * t);
   p->evaluations++;
   f[0] = y[1];
   f[1] = -kappa * y[1] - k * y[0];
   f[2] = y[3];
   f[3] = -kappa * y[3] - k * y[2];
   return GSL_SUCCESS;
}

static double grid_value(double lo, double hi, int n, int i) {
   if (n <= 1) return lo;
   if (i == n) return hi;
   return lo + (hi - lo) * (double)(i - 1) / (double)(n - 1);
}

/* the trace of the one-period monodromy at (w, A); nonzero return: GSL failed */
static int monodromy_trace(gsl_odeiv2_driver *d, struct kapitza *p, double w, double amplitude, double *trace) {
   double period = 2.0 * M_PI / w, t = 0.0;
   double y[4] = {1.0, 0.0, 0.0, 1.0};
   p->w = w;
   p->a_w2_l = amplitude * w * w / l;
   gsl_odeiv2_driver_reset_hstart(d, period / 100.0);
   int status = gsl_odeiv2_driver_apply(d, &t, period, y);
   *trace = y[0] + y[3];
   return status != GSL_SUCCESS;
}

int main(int argc, char **argv) {
   int points_mode = argc == 5 && argv[1][0] == '-' && argv[1][1] == '-';
   if (!points_mode && argc != 4 && argc != 5) {
      fprintf(stderr, "usage: chart_gsl_kapitza N_W N_A TOL [OUT]\n"
                      "       chart_gsl_kapitza --points FILE TOL OUT\n");
      return 2;
   }
   int n = 0, n_w = 0, n_a = 0;
   double *w = NULL, *amplitude = NULL;
   double tol = atof(argv[3]);
   if (points_mode) {
      FILE *in = fopen(argv[2], "r");
      if (!in) {
         fprintf(stderr, "chart_gsl_kapitza: cannot read %s\n", argv[2]);
         return 2;
      }
      double a, b;
      int capacity = 64;
      w = malloc(sizeof(double) * capacity);
      amplitude = malloc(sizeof(double) * capacity);
      while (fscanf(in, "%lf %lf", &a, &b) == 2) {
         if (n == capacity) {
            capacity *= 2;
            w = realloc(w, sizeof(double) * capacity);
            amplitude = realloc(amplitude, sizeof(double) * capacity);
         }
         w[n] = a;
         amplitude[n] = b;
         n++;
      }
      fclose(in);
   } else {
      n_w = atoi(argv[1]);
      n_a = atoi(argv[2]);
      if (n_w < 1 || n_a < 1) {
         fprintf(stderr, "chart_gsl_kapitza: bad arguments\n");
         return 2;
      }
      n = n_w * n_a;
      w = malloc(sizeof(double) * (size_t)n);
      amplitude = malloc(sizeof(double) * (size_t)n);
      for (int i = 1; i <= n_w; i++)
         for (int j = 1; j <= n_a; j++) {
            w[(size_t)(i - 1) * n_a + (j - 1)] = grid_value(60.0, 700.0, n_w, i);
            amplitude[(size_t)(i - 1) * n_a + (j - 1)] = grid_value(0.0, 0.1, n_a, j);
         }
   }
   if (n < 1 || !(tol > 0.0)) {
      fprintf(stderr, "chart_gsl_kapitza: bad arguments\n");
      return 2;
   }
   double *trace = malloc(sizeof(double) * (size_t)n);
   struct kapitza p = {0.0, 0.0, 0};
   gsl_odeiv2_system sys = {rhs, NULL, 4, &p};
   gsl_odeiv2_driver *d = gsl_odeiv2_driver_alloc_y_new(&sys, gsl_odeiv2_step_rk8pd, 1e-4, tol, tol);
   int failed = 0;
   struct timespec t0, t1;
   clock_gettime(CLOCK_MONOTONIC, &t0);
   for (int k = 0; k < n; k++) failed += monodromy_trace(d, &p, w[k], amplitude[k], &trace[k]);
   clock_gettime(CLOCK_MONOTONIC, &t1);
   double seconds = (double)(t1.tv_sec - t0.tv_sec) + 1e-9 * (double)(t1.tv_nsec - t0.tv_nsec);
   printf("seconds %.6f evaluations %ld failed %d\n", seconds, p.evaluations, failed);
   const char *out_path = points_mode ? argv[4] : (argc == 5 ? argv[4] : NULL);
   if (out_path) {
      FILE *out = fopen(out_path, "w");
      if (!out) {
         fprintf(stderr, "chart_gsl_kapitza: cannot write %s\n", out_path);
         return 1;
      }
      for (int k = 0; k < n; k++) {
         double period = 2.0 * M_PI / w[k];
         double det = exp(-kappa * period);
         fprintf(out, "%.17g %.17g %.17g %.17g %d\n", w[k], amplitude[k], trace[k],
                 exp(0.5 * kappa * period) * trace[k], fabs(trace[k]) < 1.0 + det ? 1 : 0);
      }
      fclose(out);
   }
   gsl_odeiv2_driver_free(d);
   free(trace);
   free(w);
   free(amplitude);
   return failed ? 3 : 0;
}

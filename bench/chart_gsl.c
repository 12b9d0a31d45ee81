/* The plain C program a user would write for a stability chart of the elastic pendulum
 * with GSL, the contender of the chart benchmark (`make bench`, scripts/bench_chart.py).
 *
 *   cc -O2 bench/chart_gsl.c -o build/chart_gsl -lgsl -lgslcblas -lm
 *   build/chart_gsl N_ALPHA N_BETA TOL [OUT]
 *
 * The grid of hillstab's chart scenes: alpha in [0, 9.8], beta in [-2, 12], N_ALPHA x N_BETA
 * points, alpha_i = lo + (hi - lo)(i - 1)/(n - 1) with the last value exactly hi (as
 * hillstab's grid_value). At each point: x'' + Q(tau) x = 0 with
 * Q = (beta - alpha cos(pi tau))/(1 - (alpha/pi^2) cos(pi tau)) (eq. (25)), the even and the
 * odd solution together (4 equations) from tau = 0 to 1 by gsl_odeiv2_driver_apply with
 * rk8pd, epsabs = epsrel = TOL, and S = 2 (u(1) v'(1) + u'(1) v(1)) (Q is even: half a
 * period suffices). One driver, reset for each point. Verdict: stable when |S| < 2.
 *
 * Prints the wall time of the loop (seconds) and the right-hand-side evaluations; with OUT,
 * writes "alpha beta S stable" per point after the timed loop (nothing is written while timing).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

struct hill {
   double alpha, beta, k;
   long evaluations;
};

static int rhs(double t, const double y[], double f[], void *params) {
   struct hill *p = params;
   double c = cos(M_PI * t);
   double q = (p->beta - p->alpha * c) / (1.0 - p->k * c);
   p->evaluations++;
   f[0] = y[1];
   f[1] = -q * y[0];
   f[2] = y[3];
   f[3] = -q * y[2];
   return GSL_SUCCESS;
}

static double grid_value(double lo, double hi, int n, int i) {
   if (n <= 1) return lo;
   if (i == n) return hi;
   return lo + (hi - lo) * (double)(i - 1) / (double)(n - 1);
}

int main(int argc, char **argv) {
   if (argc != 4 && argc != 5) {
      fprintf(stderr, "usage: chart_gsl N_ALPHA N_BETA TOL [OUT]\n");
      return 2;
   }
   int n_alpha = atoi(argv[1]), n_beta = atoi(argv[2]);
   double tol = atof(argv[3]);
   if (n_alpha < 1 || n_beta < 1 || !(tol > 0.0)) {
      fprintf(stderr, "chart_gsl: bad arguments\n");
      return 2;
   }
   double *s = malloc(sizeof(double) * (size_t)n_alpha * (size_t)n_beta);
   struct hill p = {0.0, 0.0, 0.0, 0};
   gsl_odeiv2_system sys = {rhs, NULL, 4, &p};
   gsl_odeiv2_driver *d = gsl_odeiv2_driver_alloc_y_new(&sys, gsl_odeiv2_step_rk8pd, 1e-3, tol, tol);
   int failed = 0;
   struct timespec t0, t1;
   clock_gettime(CLOCK_MONOTONIC, &t0);
   for (int i = 1; i <= n_alpha; i++) {
      p.alpha = grid_value(0.0, 9.8, n_alpha, i);
      p.k = p.alpha / (M_PI * M_PI);
      for (int j = 1; j <= n_beta; j++) {
         p.beta = grid_value(-2.0, 12.0, n_beta, j);
         double y[4] = {1.0, 0.0, 0.0, 1.0}, t = 0.0;
         gsl_odeiv2_driver_reset(d);
         int status = gsl_odeiv2_driver_apply(d, &t, 1.0, y);
         if (status != GSL_SUCCESS) failed++;
         s[(size_t)(i - 1) * n_beta + (j - 1)] = 2.0 * (y[0] * y[3] + y[1] * y[2]);
      }
   }
   clock_gettime(CLOCK_MONOTONIC, &t1);
   double seconds = (double)(t1.tv_sec - t0.tv_sec) + 1e-9 * (double)(t1.tv_nsec - t0.tv_nsec);
   printf("seconds %.6f evaluations %ld failed %d\n", seconds, p.evaluations, failed);
   if (argc == 5) {
      FILE *out = fopen(argv[4], "w");
      if (!out) {
         fprintf(stderr, "chart_gsl: cannot write %s\n", argv[4]);
         return 1;
      }
      for (int i = 1; i <= n_alpha; i++)
         for (int j = 1; j <= n_beta; j++) {
            double v = s[(size_t)(i - 1) * n_beta + (j - 1)];
            fprintf(out, "%.17g %.17g %.17g %d\n", grid_value(0.0, 9.8, n_alpha, i), grid_value(-2.0, 12.0, n_beta, j),
                    v, fabs(v) < 2.0 ? 1 : 0);
         }
      fclose(out);
   }
   gsl_odeiv2_driver_free(d);
   free(s);
   return failed ? 3 : 0;
}

/* The plain C program a user would write with GSL for the stability chart of a Hill equation of
 * their own, the contender of the Fourier chart benchmark (scripts/bench_fourier_chart.py,
 * `make bench-fourier`):
 *
 *   cc -O2 bench/chart_gsl_fourier.c -o build/chart_gsl_fourier -lgsl -lgslcblas -lm
 *   build/chart_gsl_fourier N_ALPHA N_BETA TOL [OUT]
 *
 * Q(tau) = beta + alpha f(tau), f = cos(pi tau) + 0.4 cos(2 pi tau) + 0.3 sin(3 pi tau) (three
 * harmonics, a sine term: Q is not even, so the whole period [0, 2] is integrated), on the grid
 * alpha in [0, 9.8], beta in [-2, 12] of hillstab's chart scenes (alpha_i = lo + (hi - lo)(i - 1)/(n - 1),
 * the last value exactly hi). At each point the two fundamental solutions together (4 equations)
 * by gsl_odeiv2_driver_apply with rk8pd, epsabs = epsrel = TOL, and S = u(2) + v'(2). One
 * driver, reset for each point.
 *
 * Prints the wall time of the loop (seconds) and the right-hand-side evaluations; with OUT,
 * writes "alpha beta S" per point after the timed loop.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

struct hill {
   double alpha, beta;
   long evaluations;
};

static int rhs(double t, const double y[], double f[], void *params) {
   struct hill *p = params;
   double drive = cos(M_PI * t) + 0.4 * cos(2.0 * M_PI * t) + 0.3 * sin(3.0 * M_PI * t);
   double q = p->beta + p->alpha * drive;
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
      fprintf(stderr, "usage: chart_gsl_fourier N_ALPHA N_BETA TOL [OUT]\n");
      return 2;
   }
   int n_alpha = atoi(argv[1]), n_beta = atoi(argv[2]);
   double tol = atof(argv[3]);
   if (n_alpha < 1 || n_beta < 1 || !(tol > 0.0)) {
      fprintf(stderr, "chart_gsl_fourier: bad arguments\n");
      return 2;
   }
   double *s = malloc(sizeof(double) * (size_t)n_alpha * (size_t)n_beta);
   if (s == NULL) return 1;
   struct hill p = {0.0, 0.0, 0};
   gsl_odeiv2_system sys = {rhs, NULL, 4, &p};
   gsl_odeiv2_driver *d = gsl_odeiv2_driver_alloc_y_new(&sys, gsl_odeiv2_step_rk8pd, 1e-3, tol, tol);
   struct timespec t0, t1;
   clock_gettime(CLOCK_MONOTONIC, &t0);
   for (int i = 1; i <= n_alpha; i++) {
      p.alpha = grid_value(0.0, 9.8, n_alpha, i);
      for (int j = 1; j <= n_beta; j++) {
         p.beta = grid_value(-2.0, 12.0, n_beta, j);
         double y[4] = {1.0, 0.0, 0.0, 1.0};
         double t = 0.0;
         gsl_odeiv2_driver_reset(d);
         int status = gsl_odeiv2_driver_apply(d, &t, 2.0, y);
         if (status != GSL_SUCCESS) {
            fprintf(stderr, "chart_gsl_fourier: GSL status %d at alpha = %g, beta = %g\n", status, p.alpha, p.beta);
            return 1;
         }
         s[(size_t)(i - 1) * n_beta + (j - 1)] = y[0] + y[3];
      }
   }
   clock_gettime(CLOCK_MONOTONIC, &t1);
   printf("%.6f %ld\n", (t1.tv_sec - t0.tv_sec) + 1e-9 * (t1.tv_nsec - t0.tv_nsec), p.evaluations);
   gsl_odeiv2_driver_free(d);
   if (argc == 5) {
      FILE *out = fopen(argv[4], "w");
      if (out == NULL) return 1;
      for (int i = 1; i <= n_alpha; i++)
         for (int j = 1; j <= n_beta; j++)
            fprintf(out, "%.17g %.17g %.17g\n", grid_value(0.0, 9.8, n_alpha, i), grid_value(-2.0, 12.0, n_beta, j),
                    s[(size_t)(i - 1) * n_beta + (j - 1)]);
      fclose(out);
   }
   free(s);
   return 0;
}

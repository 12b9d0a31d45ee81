/* The plain C program a user would write for a stability chart of a 2-DOF system of Hill
 * equations with GSL, the contender of the system benchmark (app/hillstab_bench_system.f90,
 * `make bench-system`).
 *
 *   cc -O2 bench/chart_gsl_system.c -o build/chart_gsl_system -lgsl -lgslcblas -lm
 *   build/chart_gsl_system N_ALPHA N_BETA TOL [OUT]
 *
 * The pendula pair of the system tests (test/hill/test_system.f90, pendula_pair(0.8, 0.1)): two
 * pendula of lengths l1 = 1, l2 = 0.8 (in
 * units of l1) joined by a spring, their support shaken vertically,
 *   M x'' + (beta B - alpha cos(pi tau) D) x = 0,
 *   M = diag(1, 0.64), D = diag(1, 0.8), B = D + c [[1, -1], [-1, 1]], c = 0.1,
 * over alpha in [0, 2], beta in [0, 12] (the grid of hillstab_bench_system, alpha_i = lo + (hi - lo)
 * (i - 1)/(n - 1), the last value exactly hi). At each point the 4 x 4 fundamental matrix
 * (16 equations, y = (x, x') for each column) from tau = 0 to the period 2 by
 * gsl_odeiv2_driver_apply with rk8pd, epsabs = epsrel = TOL, one driver reset for each point;
 * then the trace a1 and a2 = (a1^2 - tr Phi^2)/2 and Broucke's verdict: stable when both roots
 * of z^2 - a1 z + a2 - 2 are real in (-2, 2).
 *
 * Prints the wall time of the loop (seconds) and the right-hand-side evaluations; with OUT,
 * writes "alpha beta a1 a2 stable phi_11 ... phi_44" per point after the timed loop.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

struct pair {
   double alpha, beta;
   long evaluations;
};

static const double mass[2] = {1.0, 0.64};
static const double drive[2] = {1.0, 0.8};
static const double coupling = 0.1;

static int rhs(double t, const double y[], double f[], void *params) {
   struct pair *p = params;
   double c = cos(M_PI * t);
   /* K = beta B - alpha cos(pi tau) D, then M^{-1} K */
   double k11 = p->beta * (drive[0] + coupling) - p->alpha * c * drive[0];
   double k22 = p->beta * (drive[1] + coupling) - p->alpha * c * drive[1];
   double k12 = -p->beta * coupling;
   double l11 = k11 / mass[0], l12 = k12 / mass[0], l21 = k12 / mass[1], l22 = k22 / mass[1];
   p->evaluations++;
   for (int col = 0; col < 4; col++) {
      const double *v = y + 4 * col;
      double *g = f + 4 * col;
      g[0] = v[2];
      g[1] = v[3];
      g[2] = -(l11 * v[0] + l12 * v[1]);
      g[3] = -(l21 * v[0] + l22 * v[1]);
   }
   return GSL_SUCCESS;
}

static double grid_value(double lo, double hi, int n, int i) {
   if (n <= 1) return lo;
   if (i == n) return hi;
   return lo + (hi - lo) * (double)(i - 1) / (double)(n - 1);
}

int main(int argc, char **argv) {
   if (argc != 4 && argc != 5) {
      fprintf(stderr, "usage: chart_gsl_system N_ALPHA N_BETA TOL [OUT]\n");
      return 2;
   }
   int n_alpha = atoi(argv[1]), n_beta = atoi(argv[2]);
   double tol = atof(argv[3]);
   if (n_alpha < 1 || n_beta < 1 || !(tol > 0.0)) {
      fprintf(stderr, "chart_gsl_system: N_ALPHA, N_BETA must be >= 1 and TOL > 0\n");
      return 2;
   }
   size_t n_points = (size_t)n_alpha * (size_t)n_beta;
   double *phi = malloc(sizeof(double) * 16 * n_points);
   if (!phi) {
      fprintf(stderr, "chart_gsl_system: out of memory\n");
      return 1;
   }
   gsl_set_error_handler_off();
   struct pair p = {0.0, 0.0, 0};
   gsl_odeiv2_system sys = {rhs, NULL, 16, &p};
   gsl_odeiv2_driver *d = gsl_odeiv2_driver_alloc_y_new(&sys, gsl_odeiv2_step_rk8pd, 1e-3, tol, tol);
   struct timespec t0, t1;
   clock_gettime(CLOCK_MONOTONIC, &t0);
   int failures = 0;
   for (int i = 1; i <= n_alpha; i++) {
      p.alpha = grid_value(0.0, 2.0, n_alpha, i);
      for (int j = 1; j <= n_beta; j++) {
         p.beta = grid_value(0.0, 12.0, n_beta, j);
         double y[16] = {0};
         for (int k = 0; k < 4; k++) y[5 * k] = 1.0;
         double t = 0.0;
         gsl_odeiv2_driver_reset(d);
         if (gsl_odeiv2_driver_apply(d, &t, 2.0, y) != GSL_SUCCESS) failures++;
         double *out = phi + 16 * ((size_t)(i - 1) * n_beta + (j - 1));
         /* column col of the fundamental matrix is y[4 col .. 4 col + 3]: out is row-major */
         for (int r = 0; r < 4; r++)
            for (int col = 0; col < 4; col++) out[4 * r + col] = y[4 * col + r];
      }
   }
   clock_gettime(CLOCK_MONOTONIC, &t1);
   gsl_odeiv2_driver_free(d);
   double seconds = (t1.tv_sec - t0.tv_sec) + 1e-9 * (t1.tv_nsec - t0.tv_nsec);
   printf("%.6f %ld %d\n", seconds, p.evaluations, failures);
   if (argc == 5) {
      FILE *f = fopen(argv[4], "w");
      if (!f) {
         fprintf(stderr, "chart_gsl_system: cannot write %s\n", argv[4]);
         return 1;
      }
      for (int i = 1; i <= n_alpha; i++)
         for (int j = 1; j <= n_beta; j++) {
            const double *m = phi + 16 * ((size_t)(i - 1) * n_beta + (j - 1));
            double a1 = m[0] + m[5] + m[10] + m[15], tr2 = 0.0;
            for (int r = 0; r < 4; r++)
               for (int c = 0; c < 4; c++) tr2 += m[4 * r + c] * m[4 * c + r];
            double a2 = 0.5 * (a1 * a1 - tr2), disc = a1 * a1 - 4.0 * a2 + 8.0;
            int stable = 0;
            if (disc > 0.0) {
               double z1 = 0.5 * (a1 + sqrt(disc)), z2 = 0.5 * (a1 - sqrt(disc));
               stable = fabs(z1) < 2.0 && fabs(z2) < 2.0;
            }
            fprintf(f, "%.17e %.17e %.17e %.17e %d", grid_value(0.0, 2.0, n_alpha, i),
                    grid_value(0.0, 12.0, n_beta, j), a1, a2, stable);
            for (int k = 0; k < 16; k++) fprintf(f, " %.17e", m[k]);
            fprintf(f, "\n");
         }
      fclose(f);
   }
   free(phi);
   return failures ? 1 : 0;
}

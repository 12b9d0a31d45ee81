/* The plain C program a user would write for a Lyapunov map of the elastic pendulum
 * with GSL, the contender of `make bench-lyapunov` (app/hillstab_bench_lyapunov.f90).
 *
 *   cc -O2 bench/lyapunov_gsl.c -o build/lyapunov_gsl -lgsl -lgslcblas -lm
 *   build/lyapunov_gsl POINTS PERIODS RTOL OUT
 *
 * For every (alpha, beta) line of POINTS: the pendulum of hillstab (r0 = 0.1 m,
 * g = 9.81 m/s^2, rho = r0 pi^2/(pi^2 - beta), omega^2 = g pi^2/(rho beta), a = alpha rho/pi^2),
 * started at r = rho - a, phi0 = 0.017 at rest (eq. (38) of the paper), Cartesian equations
 * x'' = -omega^2 (1 - r0/r) x, z'' = -omega^2 (1 - r0/r) z + g with one tangent vector
 * v' = J v: 8 equations. Benettin's method: gsl_odeiv2_driver_apply with rk8pd to the end
 * of every radial period, the tangent vector renormalised there (norm with the velocities
 * divided by omega, started as (1, 1, omega, omega)/2 as hillstab does), lambda = the mean
 * of the log growths per radial period. Error control: gsl_odeiv2_driver_alloc_y_new with
 * epsabs = epsrel = RTOL. Verdict: chaotic when lambda > 0.03 per radial period.
 *
 * Writes OUT: a header with the CPU time of the whole map (clock()), then per point
 * alpha beta lambda verdict f-evaluations max|dE|/scale (energy at the period ends, over
 * the sum of the energy terms' magnitudes at t = 0) status.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

struct pendulum {
   double omega2, r0, g;
   long evaluations;
};

static int rhs(double t, const double y[], double f[], void *params) {
   struct pendulum *p = params;
   double r2 = y[0] * y[0] + y[1] * y[1], r = sqrt(r2);
   double c = p->omega2 * (1.0 - p->r0 / r), q = p->omega2 * p->r0 / (r2 * r);
   (void)t;
   p->evaluations++;
   f[0] = y[2];
   f[1] = y[3];
   f[2] = -c * y[0];
   f[3] = -c * y[1] + p->g;
   /* tangent vector: d(dx)/dt = dv, d(dv)/dt = -(c I + q x x^T) dx */
   f[4] = y[6];
   f[5] = y[7];
   f[6] = -(c * y[4] + q * y[0] * (y[0] * y[4] + y[1] * y[5]));
   f[7] = -(c * y[5] + q * y[1] * (y[0] * y[4] + y[1] * y[5]));
   return GSL_SUCCESS;
}

static double energy(const struct pendulum *p, const double y[], double *scale) {
   double r = sqrt(y[0] * y[0] + y[1] * y[1]);
   double kinetic = 0.5 * (y[2] * y[2] + y[3] * y[3]), spring = 0.5 * p->omega2 * (r - p->r0) * (r - p->r0);
   if (scale) *scale = kinetic + spring + p->g * fabs(y[1]);
   return kinetic + spring - p->g * y[1];
}

int main(int argc, char **argv) {
   if (argc != 5) {
      fprintf(stderr, "usage: lyapunov_gsl POINTS PERIODS RTOL OUT\n");
      return 2;
   }
   const double pi = 3.14159265358979323846, pi2 = pi * pi, r0 = 0.1, g = 9.81, phi0 = 0.017;
   int periods = atoi(argv[2]);
   double rtol = atof(argv[3]);
   FILE *in = fopen(argv[1], "r");
   if (!in || periods < 1 || !(rtol > 0.0)) {
      fprintf(stderr, "lyapunov_gsl: bad arguments\n");
      return 2;
   }
   double alpha, beta;
   int n = 0, capacity = 1024;
   double *points = malloc(2 * capacity * sizeof(double));
   while (fscanf(in, "%lf %lf", &alpha, &beta) == 2) {
      if (n == capacity) points = realloc(points, 2 * (capacity *= 2) * sizeof(double));
      points[2 * n] = alpha;
      points[2 * n + 1] = beta;
      n++;
   }
   fclose(in);
   double *rows = malloc(6 * (size_t)n * sizeof(double));
   gsl_set_error_handler_off();

   clock_t start = clock();
   for (int k = 0; k < n; k++) {
      alpha = points[2 * k];
      beta = points[2 * k + 1];
      double rho = r0 * pi2 / (pi2 - beta), omega2 = g * pi2 / (rho * beta), omega = sqrt(omega2);
      double a = alpha * rho / pi2, period = 2.0 * pi / omega;
      struct pendulum p = {omega2, r0, g, 0};
      gsl_odeiv2_system sys = {rhs, NULL, 8, &p};
      gsl_odeiv2_driver *d = gsl_odeiv2_driver_alloc_y_new(&sys, gsl_odeiv2_step_rk8pd, 1e-3 * period, rtol, rtol);
      double y[8] = {(rho - a) * sin(phi0), (rho - a) * cos(phi0), 0.0, 0.0, 0.5, 0.5, 0.5 * omega, 0.5 * omega};
      double scale, e0 = energy(&p, y, &scale), de = 0.0, sum_log = 0.0, t = 0.0;
      int status = GSL_SUCCESS, m;
      for (m = 1; m <= periods && status == GSL_SUCCESS; m++) {
         status = gsl_odeiv2_driver_apply(d, &t, m * period, y);
         double norm = sqrt(y[4] * y[4] + y[5] * y[5] + (y[6] * y[6] + y[7] * y[7]) / omega2);
         for (int i = 4; i < 8; i++) y[i] /= norm;
         sum_log += log(norm);
         de = fmax(de, fabs(energy(&p, y, NULL) - e0) / scale);
      }
      gsl_odeiv2_driver_free(d);
      double lambda = sum_log / periods;
      rows[6 * k] = lambda;
      rows[6 * k + 1] = lambda > 0.03 ? 1.0 : 0.0;
      rows[6 * k + 2] = (double)p.evaluations;
      rows[6 * k + 3] = de;
      rows[6 * k + 4] = status;
      rows[6 * k + 5] = 0.0;
   }
   double seconds = (double)(clock() - start) / CLOCKS_PER_SEC;

   FILE *out = fopen(argv[4], "w");
   if (!out) {
      fprintf(stderr, "lyapunov_gsl: cannot write %s\n", argv[4]);
      return 1;
   }
   fprintf(out, "# lyapunov_gsl: %d points, %d radial periods, rk8pd driver, epsabs = epsrel = %g\n", n, periods, rtol);
   fprintf(out, "# cpu_seconds %.6f\n", seconds);
   fprintf(out, "# columns: alpha beta lambda chaotic f_evaluations energy_error status\n");
   for (int k = 0; k < n; k++)
      fprintf(out, "%.17g %.17g %.10e %.1f %.0f %.3e %.0f\n", points[2 * k], points[2 * k + 1], rows[6 * k],
              rows[6 * k + 1], rows[6 * k + 2], rows[6 * k + 3], rows[6 * k + 4]);
   fclose(out);
   free(points);
   free(rows);
   return 0;
}

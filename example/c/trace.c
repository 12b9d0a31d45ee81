/* Links against an installed hillstab through its C header: the version, eq. (37) and a
 * segmented trace at the paper's case (b), the growth rate of the swing at cases (b) and
 * (c), an error status (the outputs untouched) and an overflow. */
#include <stdio.h>
#include <string.h>
#include <math.h>
#include "hillstab.h"

int main(void) {
  double s, log_abs, paper, log_modulus[2], mu;
  int overflow, status, major, minor, patch, stable, stable_paper;
  char message[64];
  /* the library linked at run time is the one the header belongs to */
  hillstab_version_numbers(&major, &minor, &patch);
  printf("C: hillstab %s (header %s)\n", hillstab_version(), HILLSTAB_VERSION_STRING);
  if (strcmp(hillstab_version(), HILLSTAB_VERSION_STRING) != 0 || major != HILLSTAB_VERSION_MAJOR
      || minor != HILLSTAB_VERSION_MINOR || patch != HILLSTAB_VERSION_PATCH) return 1;
  status = hillstab_trace(HILLSTAB_MODEL_ELASTIC, 3.70, 2.47, 0.0, HILLSTAB_METHOD_SEGMENTS, 4096,
                          HILLSTAB_SAMPLING_AVERAGE, 1e-10, &s, &log_abs, &overflow);
  if (hillstab_trace_paper_checked(3.70, 2.47, 0.0, &paper, &log_abs, &overflow) != 0) return 1;
  printf("C: S(eq. 37) = %.6f, S(4096 pieces) = %.6f, status %d\n", paper, s, status);
  if (status != 0 || fabs(s + 2.9343) > 1e-3 || fabs(paper + 3.6282) > 1e-3) return 1;
  if (hillstab_trace_paper(3.70, 2.47, 0.0) != paper) return 1;
  /* the growth rate of the swing, the Floquet exponent mu per unit tau: (b) grows, mu =
   * acosh(|S|/2)/2 = 0.46621 with the S above; (c) is stable, mu = 0 (printed as 0, never -0) */
  status = hillstab_floquet_data(HILLSTAB_MODEL_ELASTIC, 3.70, 2.47, 0.0, HILLSTAB_METHOD_AUTO, 0, 0, 1e-10,
                                 &s, log_modulus, &mu, &stable, &stable_paper);
  printf("C: case (b): stable %d, growth rate mu = %.6f per unit tau\n", stable, mu);
  if (status != 0 || stable != 0 || fabs(mu - 0.46621) > 1e-5) return 1;
  status = hillstab_floquet_data(HILLSTAB_MODEL_ELASTIC, 2.57, 1.29, 0.0, HILLSTAB_METHOD_AUTO, 0, 0, 1e-10,
                                 &s, log_modulus, &mu, &stable, &stable_paper);
  printf("C: case (c): stable %d, growth rate mu = %g per unit tau\n", stable, mu);
  if (status != 0 || stable != 1 || mu != 0.0 || signbit(mu)) return 1;
  /* an error leaves the outputs as they were */
  s = -7.0; log_abs = -8.0; overflow = -9;
  status = hillstab_trace(HILLSTAB_MODEL_ELASTIC, 10.0, 2.47, 0.0, HILLSTAB_METHOD_FORMULA, 2, 1, 1e-10,
                          &s, &log_abs, &overflow);
  hillstab_error_message(status, message, sizeof message);
  printf("C: alpha = 10 -> status %d (%s), outputs %s\n", status, message,
         s == -7.0 && log_abs == -8.0 && overflow == -9 ? "untouched" : "CHANGED");
  if (status != HILLSTAB_ERR_INVALID_PARAMETER || s != -7.0 || log_abs != -8.0 || overflow != -9) return 1;
  /* alpha = 0, beta = -1e6: S = 2 cosh 2000 overflows; the checked closed form says so and
   * gives ln S, where hillstab_trace_paper returns DBL_MAX alone */
  status = hillstab_trace_paper_checked(0.0, -1.0e6, 0.0, &paper, &log_abs, &overflow);
  printf("C: eq. (37) at beta = -1e6 -> status %d, overflow %d, ln S = %.6f\n", status, overflow, log_abs);
  return status == 0 && overflow == 1 && fabs(log_abs - 2000.0) < 1e-9 ? 0 : 1;
}

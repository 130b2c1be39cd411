/* pd_log, the logarithm the bond loops can vectorize (pd_log.h), against
 * libm's log: within 1 ulp of it wherever the argument is a positive
 * finite number (libm's own error is below 1 ulp, so pd_log is within 2 ulp
 * of the exact value), and the same edges (0, negative, NaN, inf). The
 * arguments: 2 million strains 1 + f around 1 (|f| from 1e-15 to 0.5, the
 * bonds' range), 1 million values spread over all decades, subnormals and
 * every power of two. */
#include "check.h"
#include "pd_log.h"

#include <float.h>
#include <math.h>
#include <stdint.h>

/* |a - b| in units of the last place of b */
static double ulps(double a, double b)
{
  if (a == b) return 0.0;
  const double u = nextafter(fabs(b), INFINITY) - fabs(b);
  return fabs(a - b) / (u > 0.0 ? u : DBL_MIN);
}

/* a reproducible uniform number in [0, 1) */
static double uniform(uint64_t *state)
{
  *state = *state * 6364136223846793005ULL + 1442695040888963407ULL;
  return (double) (*state >> 11) * (1.0 / 9007199254740992.0);
}

static double worst = 0.0, worst_at = 0.0;
static void compare(double x)
{
  const double d = ulps(pd_log(x), log(x));
  if (d > worst || d != d) {
    worst = d;
    worst_at = x;
  }
}

int main(void)
{
  uint64_t state = 12345;
  for (int k = 0; k < 2000000; k++) {
    /* |f| log-uniform in [1e-15, 0.5], either sign */
    const double f = exp(log(1e-15) + uniform(&state) * (log(0.5) - log(1e-15)));
    compare(1.0 + (k & 1 ? f : -f));
  }
  const double near1 = worst;
  printf("strains 1 + f: worst %.3f ulp at %.17g\n", worst, worst_at);
  worst = 0.0;
  for (int k = 0; k < 1000000; k++) compare(exp(-700.0 + 1400.0 * uniform(&state)));
  for (int k = 0; k < 100000; k++) compare(DBL_MIN * uniform(&state));    /* subnormals */
  for (int e = -1074; e <= 1023; e++) compare(ldexp(1.0, e));
  compare(DBL_MAX);
  compare(DBL_MIN);
  compare(DBL_TRUE_MIN);
  printf("all decades: worst %.3f ulp at %.17g\n", worst, worst_at);
  check_true("within 1 ulp of libm's log for strains 1 + f, |f| in [1e-15, 0.5]", near1 <= 1.0);
  check_true("within 1 ulp of libm's log over all positive doubles tried", worst <= 1.0);
  check_true("log 1 = 0 exactly", pd_log(1.0) == 0.0);
  check_true("log 0 = -inf (a bond of zero length: the guard's non-finite force)",
             pd_log(0.0) == -INFINITY);
  check_true("log of a negative number is NaN", isnan(pd_log(-1.0)));
  check_true("log NaN is NaN", isnan(pd_log(NAN)));
  check_true("log inf = inf", pd_log(INFINITY) == INFINITY);
  return check_summary();
}

/* pd_log_ratio, the logarithm of a ratio that the bond loops can vectorize
 * (pd_log.h), against log(p / q) evaluated in long double: within 2.5 ulp
 * wherever p is a positive finite number and q a positive normal one. The
 * rounded sum and division leave s = (u - v) / (u + v) up to 2^-52 off
 * relative to itself, which is up to 2 ulp of a result just below a power
 * of 2, and the result follows 2 s; the last sum adds half an ulp
 * (measured: 1.93 ulp at worst). The arguments: 2 million strains, p = q (1 + f)
 * around q (|f| from 1e-15 to 0.5, the bonds' range, q the squares of bond
 * lengths from 1e-9 to 1e5), 1 million ratios spread over all decades,
 * subnormal p and every power of two; and the edges (0, negative, NaN,
 * inf). */
#include "check.h"
#include "pd_log.h"

#include <float.h>
#include <math.h>
#include <stdint.h>

/* log(p / q) to long double's precision: near 1 through log1p of the
 * difference (exact in long double), elsewhere as a difference of logs
 * (then |log(p / q)| > 0.69) */
static long double reference(double p, double q)
{
  const long double lp = p, lq = q;
  if (lp >= 0.5L * lq && lp <= 2.0L * lq) return log1pl((lp - lq) / lq);
  return logl(lp) - logl(lq);
}

/* |a - b| in units of the last place of b rounded to double */
static double ulps(double a, long double b)
{
  const double bd = (double) b;
  const double u = nextafter(fabs(bd), INFINITY) - fabs(bd);
  if (a == b) return 0.0;
  return (double) (fabsl((long double) a - b) / (u > 0.0 ? u : DBL_MIN));
}

/* a reproducible uniform number in [0, 1) */
static double uniform(uint64_t *state)
{
  *state = *state * 6364136223846793005ULL + 1442695040888963407ULL;
  return (double) (*state >> 11) * (1.0 / 9007199254740992.0);
}

static double worst = 0.0, worst_p = 0.0, worst_q = 0.0;
static void compare(double p, double q)
{
  const double d = ulps(pd_log_ratio(p, q), reference(p, q));
  if (d > worst || d != d) {
    worst = d;
    worst_p = p;
    worst_q = q;
  }
}

int main(void)
{
  uint64_t state = 12345;
  for (int k = 0; k < 2000000; k++) {
    /* |f| log-uniform in [1e-15, 0.5], either sign; q = |xi|^2, |xi| from
     * 3e-5 to 300 */
    const double f = exp(log(1e-15) + uniform(&state) * (log(0.5) - log(1e-15)));
    const double r0 = exp(log(3e-5) + uniform(&state) * (log(300.0) - log(3e-5)));
    const double q = r0 * r0;
    compare(q * (1.0 + (k & 1 ? f : -f)), q);
  }
  const double near1 = worst;
  printf("strains: worst %.3f ulp at p %.17g q %.17g\n", worst, worst_p, worst_q);
  worst = 0.0;
  for (int k = 0; k < 1000000; k++) {
    const double q = exp(-700.0 + 1400.0 * uniform(&state));
    compare(exp(-700.0 + 1400.0 * uniform(&state)), k & 1 ? q : 1.0);
  }
  for (int k = 0; k < 100000; k++) compare(DBL_MIN * uniform(&state), k & 1 ? 1.0 : 3.7e-7);
  for (int e = -1074; e <= 1023; e++) {
    compare(ldexp(1.0, e), 1.0);
    compare(ldexp(1.0, e), 0.3);
  }
  compare(DBL_MAX, 1.0);
  compare(DBL_MIN, 1.0);
  compare(DBL_TRUE_MIN, 1.0);
  compare(DBL_MAX, DBL_MIN);
  compare(DBL_TRUE_MIN, DBL_MAX);
  printf("all decades: worst %.3f ulp at p %.17g q %.17g\n", worst, worst_p, worst_q);
  check_true("within 2.5 ulp of log(p / q) for strains p = q (1 + f), |f| in [1e-15, 0.5]", near1 <= 2.5);
  check_true("within 2.5 ulp of log(p / q) over all positive p and normal q tried", worst <= 2.5);
  check_true("log of a ratio of 1 = 0 exactly", pd_log_ratio(2.5e-7, 2.5e-7) == 0.0 &&
                                                    pd_log_ratio(1.0, 1.0) == 0.0);
  check_true("log 0 = -inf (a bond of zero length: the guard's non-finite force)",
             pd_log_ratio(0.0, 2.5e-7) == -INFINITY);
  check_true("log of a negative number is NaN", isnan(pd_log_ratio(-1.0, 2.5e-7)));
  check_true("log NaN is NaN", isnan(pd_log_ratio(NAN, 2.5e-7)));
  check_true("log inf = inf", pd_log_ratio(INFINITY, 2.5e-7) == INFINITY);
  return check_summary();
}

/* The logarithm of a ratio, log(p / q), in plain arithmetic, so that a
 * loop that takes it still vectorizes (a call to libm's log keeps the whole
 * loop scalar): the log strain (m = 0) of pd/ordinary's bond loops, log of
 * |Y|^2 over |xi|^2. One divide for both the ratio and the logarithm (the
 * bond loop's m = 0 pass waited on its divides when the ratio was formed
 * first), and the same on every CPU. p is any double: log of 0 over q is
 * -inf, of a negative number or NaN NaN, of inf inf; q is a positive
 * normal number.
 *
 * p = 2^e u and q = 2^g v with u, v in [1, 2), one of them doubled so that
 * u / v lies in [sqrt(1/2), sqrt(2)]; then, with s = (u - v) / (u + v) (u - v
 * exact: the two are within a factor 2), |s| < 0.172,
 *   log(u / v) = 2 atanh(s) = 2 s + s T,  T = 2 s^2/3 + 2 s^4/5 + ...,
 * T in 7 terms fitted on |s| < 0.172 (tools/log_coefficients.py: within
 * 5e-18 of the result; Taylor's series took 10),
 * and (e - g) ln 2 with ln 2 in two parts (the first with 21 significant
 * bits, so that the exponent times it is exact). */
#ifndef PD_LOG_H
#define PD_LOG_H

#include "pd_macros.h"

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

/* The bits of a double, and back. */
PD_INLINE uint64_t pd_bits(double x)
{
  uint64_t b;
  memcpy(&b, &x, sizeof b);
  return b;
}
PD_INLINE double pd_from_bits(uint64_t b)
{
  double x;
  memcpy(&x, &b, sizeof x);
  return x;
}

/* the exponent of a positive normal double's bits, as a double: 2^52 plus
 * the biased exponent, by its bits, less 2^52 and the bias (exact, and no
 * conversion of a 64-bit integer, which AVX2 has not: the loop would stay
 * scalar there) */
PD_INLINE double pd_exponent(uint64_t bits)
{
  return pd_from_bits(0x4330000000000000ULL | ((bits >> 52) & 0x7ff)) - (4503599627370496.0 + 1023.0);
}
/* its significand, in [1, 2) */
PD_INLINE double pd_significand(uint64_t bits)
{
  return pd_from_bits((bits & 0x000fffffffffffffULL) | 0x3ff0000000000000ULL);
}

PD_INLINE double pd_log_ratio(double p, double q)
{
  static const double ln2_hi = 0.6931467056274414, ln2_lo = 4.7493250390316726e-07;
  static const double sqrt2 = 1.4142135623730951;
  /* subnormals scaled up by 2^54 first */
  const int tiny = p < DBL_MIN;
  const uint64_t bp = pd_bits(tiny ? p * 18014398509481984.0 : p), bq = pd_bits(q);
  double u = pd_significand(bp), v = pd_significand(bq);
  const int up = u > sqrt2 * v, down = sqrt2 * u < v;
  v = up ? 2.0 * v : v;
  u = down ? 2.0 * u : u;
  const double de = (pd_exponent(bp) - pd_exponent(bq)) - (tiny ? 54.0 : 0.0) +
                    (up ? 1.0 : 0.0) - (down ? 1.0 : 0.0);
  const double s = (u - v) / (u + v), z = s * s;
  const double t =
      z * (0.666666666666667 + z * (0.39999999999899444 + z * (0.2857142862600327 +
      z * (0.22222211130259878 + z * (0.18182889455674947 + z * (0.15331710618210773 +
      z * 0.14616585424888623))))));
  const double r = de * ln2_hi + ((s + s) + (s * t + de * ln2_lo));
  /* the edges (0 gives -inf, a negative number NaN, inf and NaN
   * themselves), blended in by bits: with a select on the result, or an &&,
   * GCC moves the arithmetic above into a branch and does not vectorize */
  const double edge = p == 0.0 ? -INFINITY : p < 0.0 ? NAN : p;
  const uint64_t normal = -(uint64_t) ((p > 0.0) & (p <= DBL_MAX));
  return pd_from_bits((pd_bits(r) & normal) | (pd_bits(edge) & ~normal));
}

#endif

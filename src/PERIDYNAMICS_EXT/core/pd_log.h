/* The natural logarithm in plain arithmetic, so that a loop that takes it
 * still vectorizes (a call to libm's log keeps the whole loop scalar):
 * the log strain (m = 0) of pd/ordinary's bond loops. Within 1 ulp of
 * libm's log (core.log checks it over many decades), and the same on every
 * CPU; log 0 is -inf, log of a negative number or NaN is NaN, log inf is
 * inf.
 *
 * x = 2^e y with y in [sqrt(1/2), sqrt(2)), f = y - 1 (exact), and
 * log(1 + f) = 2 atanh(s) with s = f / (2 + f), |s| < 0.172:
 *   2 atanh(s) = 2 s + s T,  T = 2 s^2/3 + 2 s^4/5 + ... (Taylor, 10 terms:
 *   the first left out is below 1e-18 of the result),
 * written f - s (f - T) since 2 s = f - s f: the exact f leads, the rounded
 * rest is about f^2 / 2. Then e ln 2 with ln 2 in two parts (the first with
 * 21 significant bits, so that e times it is exact). */
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

PD_INLINE double pd_log(double x)
{
  static const double ln2_hi = 0.6931467056274414, ln2_lo = 4.7493250390316726e-07;
  /* subnormals scaled up by 2^54 first */
  const int tiny = x < DBL_MIN;
  const double xs = tiny ? x * 18014398509481984.0 : x;
  const uint64_t bits = pd_bits(xs);
  /* the biased exponent as a double by its bits (2^52 + it, less 2^52):
   * exact, and no conversion of a 64-bit integer, which AVX2 has not (the
   * loop would stay scalar there) */
  const double biased = pd_from_bits(0x4330000000000000ULL | ((bits >> 52) & 0x7ff)) - 4503599627370496.0;
  double y = pd_from_bits((bits & 0x000fffffffffffffULL) | 0x3ff0000000000000ULL);
  /* y in [1, 2): halve the upper part into [sqrt(1/2), 1) */
  const int upper = y > 1.4142135623730951;
  y = upper ? 0.5 * y : y;
  const double de = biased - (tiny ? 1077.0 : 1023.0) + (upper ? 1.0 : 0.0);
  const double f = y - 1.0, s = f / (2.0 + f), z = s * s;
  const double t =
      z * (2.0 / 3 + z * (2.0 / 5 + z * (2.0 / 7 + z * (2.0 / 9 + z * (2.0 / 11 + z * (2.0 / 13 +
      z * (2.0 / 15 + z * (2.0 / 17 + z * (2.0 / 19 + z * (2.0 / 21))))))))));
  const double r = de * ln2_hi + ((f - s * (f - t)) + de * ln2_lo);
  /* the edges (0 gives -inf, a negative number NaN, inf and NaN
   * themselves), blended in by bits: with a select on the result, or an &&,
   * GCC moves the arithmetic above into a branch and does not vectorize */
  const double edge = x == 0.0 ? -INFINITY : x < 0.0 ? NAN : x;
  const uint64_t normal = -(uint64_t) ((x > 0.0) & (x <= DBL_MAX));
  return pd_from_bits((pd_bits(r) & normal) | (pd_bits(edge) & ~normal));
}

#endif

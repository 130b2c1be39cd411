/* The Seth-Hill bond strain's forms (pd_seth_hill.h) against the
 * definition eps = (c^m - 1)/(2m), eps_0 = log(c)/2 with c = |Y|^2/|xi|^2,
 * evaluated in long double from the same |Y|^2 and |xi|: m = 1/2, m = 0
 * (pd_log_ratio of |Y|^2 and |xi|^2), the negative integers (a polynomial
 * in 1/c, no square root) and an order in general (libm). The strains span 1e-12 to 0.6 in
 * tension and compression, the bonds' range. Tolerance: 8 ulp of
 * (1 + |eps|): the rounding of |xi|^2 alone leaves 1 ulp of 1 in c - 1, so
 * a small strain is known to that absolute error, a large one to a few ulp
 * of itself. The strain rate over the length, c^m/|Y|^2, the same
 * relative to itself. */
#include "check.h"
#include "pd_seth_hill.h"

#include <float.h>
#include <math.h>
#include <stdio.h>

static long double reference_strain(double m, double len2, double r0)
{
  const long double a = ((long double) len2 - (long double) r0 * r0) / ((long double) r0 * r0);
  if (m == 0.0) return 0.5L * log1pl(a);
  return expm1l((long double) m * log1pl(a)) / (2.0L * m);
}

static pd_bond bond_of(double r0, double stretch)
{
  pd_bond bd = {0};
  bd.r0 = r0;
  /* a bond along a skew direction, so that |Y|^2 carries rounding */
  const double len = r0 * (1.0 + stretch), u[3] = {0.48, 0.6, 0.64};
  for (int k = 0; k < 3; k++) bd.d[k] = len * u[k];
  bd.len2 = bd.d[0] * bd.d[0] + bd.d[1] * bd.d[1] + bd.d[2] * bd.d[2];
  bd.len = sqrt(bd.len2);
  return bd;
}

/* the worst error of one kind over the strains, in units of
 * DBL_EPSILON (1 + |eps|) for the strain and DBL_EPSILON |rate| for the
 * rate over the length */
static void worst_of(int kind, double m, double *strain_err, double *rate_err)
{
  *strain_err = *rate_err = 0.0;
  const double r0s[2] = {1.7e-3, 0.3};
  for (int ir = 0; ir < 2; ir++)
    for (int sign = -1; sign <= 1; sign += 2)
      for (double s = 1e-12; s < 0.6; s *= 1.37) {
        const pd_bond bd = bond_of(r0s[ir], sign * s);
        const long double ref = reference_strain(m, bd.len2, bd.r0);
        const double eps = pd_bond_strain(kind, m, &bd);
        const double e1 = (double) (fabsl(eps - ref) / (DBL_EPSILON * (1.0L + fabsl(ref))));
        /* c^m / |Y|^2 = (1 + 2 m eps) / |Y|^2 */
        const long double rate_ref = (1.0L + 2.0L * m * ref) / (long double) bd.len2;
        const double rate = pd_bond_strain_rate_per_length(kind, m, eps, &bd);
        const double e2 = (double) (fabsl(rate - rate_ref) / (DBL_EPSILON * fabsl(rate_ref)));
        if (!(e1 <= *strain_err)) *strain_err = e1;
        if (!(e2 <= *rate_err)) *rate_err = e2;
      }
}

int main(void)
{
  check_true("m = 1/2 is the stretch kind", pd_order_kind(0.5) == PD_ORDER_HALF);
  check_true("m = 0 is the log kind", pd_order_kind(0.0) == PD_ORDER_LOG);
  check_true("m = -1 .. -4 are the reciprocal kind",
             pd_order_kind(-1.0) == PD_ORDER_RECIPROCAL && pd_order_kind(-2.0) == PD_ORDER_RECIPROCAL &&
                 pd_order_kind(-3.0) == PD_ORDER_RECIPROCAL && pd_order_kind(-4.0) == PD_ORDER_RECIPROCAL);
  check_true("m = -0.5, 0.25, 1 take the general form", pd_order_kind(-0.5) == PD_ORDER_ANY &&
                                                            pd_order_kind(0.25) == PD_ORDER_ANY &&
                                                            pd_order_kind(1.0) == PD_ORDER_ANY);
  const struct {
    const char *name;
    int kind;
    double m;
  } cases[] = {
      {"m = 0 (pd_log_ratio of |Y|^2 and |xi|^2)", PD_ORDER_LOG, 0.0},
      {"m = -1 (reciprocal)", PD_ORDER_RECIPROCAL, -1.0},
      {"m = -2 (reciprocal)", PD_ORDER_RECIPROCAL, -2.0},
      {"m = -3 (reciprocal)", PD_ORDER_RECIPROCAL, -3.0},
      {"m = -4 (reciprocal)", PD_ORDER_RECIPROCAL, -4.0},
      {"m = -1 (general form)", PD_ORDER_ANY, -1.0},
      {"m = 0.25 (general form)", PD_ORDER_ANY, 0.25},
  };
  for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
    double es, er;
    worst_of(cases[k].kind, cases[k].m, &es, &er);
    char msg[160];
    snprintf(msg, sizeof msg, "%s: strain within 8 ulp of (1 + |eps|) (worst %.2f)", cases[k].name, es);
    check_true(msg, es <= 8.0);
    snprintf(msg, sizeof msg, "%s: strain rate over length within 8 ulp (worst %.2f)", cases[k].name, er);
    check_true(msg, er <= 8.0);
  }
  /* zero length: no force (the rate over the length is 0) */
  pd_bond zero = bond_of(1e-3, -1.0);
  check_true("m = -1 at zero length: no force",
             pd_bond_strain_rate_per_length(PD_ORDER_RECIPROCAL, -1.0, 0.0, &zero) == 0.0);
  check_true("m = 0 at zero length: no force", pd_bond_strain_rate_per_length(PD_ORDER_LOG, 0.0, 0.0, &zero) == 0.0);
  return check_summary();
}

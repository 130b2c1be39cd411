#include "pd_coefs.h"

#include <float.h>
#include <math.h>

int pd_coef_valid(const pd_coef *c, double v)
{
  switch (c->check) {
    /* a subnormal (below DBL_MIN, e.g. 1e-320) is no physical constant:
       its reciprocals (stable time step, stretch) overflow to inf */
    case PD_CHECK_POSITIVE: return v >= DBL_MIN;
    case PD_CHECK_RANGE: return v >= c->lo && v <= c->hi;
    default: return 1;
  }
}

double pd_coef_mixed(pd_coef_mix mix, double a, double b)
{
  if (isnan(a) || isnan(b)) return NAN;
  switch (mix) {
    case PD_MIX_MEAN: return 0.5 * (a + b);
    case PD_MIX_MAX: return a > b ? a : b;
    case PD_MIX_MIN: return a < b ? a : b;
    default: return NAN;
  }
}

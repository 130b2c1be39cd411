#include "pd_coefs.h"

#include <math.h>

int pd_coef_valid(const pd_coef *c, double v)
{
  switch (c->check) {
    case PD_CHECK_POSITIVE: return v > 0.0;
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

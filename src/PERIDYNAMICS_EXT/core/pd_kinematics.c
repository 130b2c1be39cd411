#include "pd_kinematics.h"

#include <math.h>

/* Below this |m| the series is used: (c^m - 1)/(2m) loses digits to
 * cancellation as m -> 0, and its limit is log(c)/2. */
#define PD_SMALL_ORDER 1e-8

double pd_seth_hill_strain(double c, double m)
{
  const double l = log(c);
  if (fabs(m) < PD_SMALL_ORDER) return 0.5 * l * (1.0 + 0.5 * m * l);
  return expm1(m * l) / (2.0 * m);
}

double pd_seth_hill_dstrain(double c, double m) { return 0.5 * pow(c, m - 1.0); }

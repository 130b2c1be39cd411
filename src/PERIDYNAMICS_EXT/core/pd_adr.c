/* Adaptive dynamic relaxation (KM10): the fictitious density and the
 * damping; the per-particle steps are inline in pd_adr.h. */
#include "pd_adr.h"

#include <math.h>

double pd_adr_density(double stiffness_sum, double safety)
{
  /* (1/4) dt^2 sum_j |K_ij| with dt = 1 and sum_j |K_ij| <= 2 S_i */
  return stiffness_sum > 0.0 ? 0.5 * safety * stiffness_sum : 0.0;
}

double pd_adr_damping(double uku, double uu)
{
  if (!(uu > 0.0) || !(uku > 0.0)) return 0.0;    /* no displacement yet, or softening */
  const double c = 2.0 * sqrt(uku / uu);
  return c < PD_ADR_CMAX ? c : PD_ADR_CMAX;
}

#include "pd_timestep.h"

#include <math.h>

double pd_stable_dt(double rho, double sum)
{
  return sum > 0.0 ? sqrt(2.0 * rho / sum) : INFINITY;
}

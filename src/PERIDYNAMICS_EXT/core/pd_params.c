#include "pd_params.h"

#include <math.h>

double pd_pmb_micromodulus_3d(double bulk, double delta)
{
  return 18.0 * bulk / (M_PI * delta * delta * delta * delta);
}

pd_lame pd_ordinary_lame_3d(double bulk, double shear)
{
  const double lambda = bulk - 2.0 * shear / 3.0;
  pd_lame l = {lambda - shear, 2.5 * shear};
  return l;
}

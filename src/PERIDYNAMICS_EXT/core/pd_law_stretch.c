#include "pd_law_stretch.h"

#include "pd_macros.h"

#include <math.h>

double pd_critical_stretch(int dim, int plane_strain, double E, double nu, double delta, double Gc)
{
  if (dim == 3) {
    const double K = E / (3.0 * (1.0 - 2.0 * nu));
    return sqrt(5.0 * Gc / (9.0 * K * delta));
  }
  if (plane_strain) return sqrt(5.0 * PD_PI * Gc / (12.0 * E * delta));
  return sqrt(4.0 * PD_PI * Gc / (9.0 * E * delta));
}

double pd_critical_stretch_factor(int dim, double delta, double thickness, double stiffness, double moment2)
{
  if (!(moment2 > 0.0) || !(stiffness > 0.0)) return 1.0;
  const double d4 = delta * delta * delta * delta;
  const double integral = dim == 3 ? 4.0 * PD_PI * d4 * delta / 5.0 : PD_PI * d4 * thickness / 2.0;
  return sqrt(integral / (stiffness * moment2));
}

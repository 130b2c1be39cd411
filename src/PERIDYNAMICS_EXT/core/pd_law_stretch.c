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

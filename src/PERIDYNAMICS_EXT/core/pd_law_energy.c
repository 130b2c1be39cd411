#include "pd_law_energy.h"

#include "pd_bond_loop.h"
#include "pd_macros.h"

#include <math.h>

/* Midpoint rule: the integrands are smooth on (0, delta) and at worst
 * integrably singular at 0; 200000 cells give ~1e-9 relative. */
#define NCELLS 200000

double pd_energy_failure_beta(pd_influence_kind kind, pd_energy_profile profile, int dim, double delta,
                              double Gc)
{
  const int q = pd_energy_profile_power(profile);
  if (dim == 2 && q == -2 && pd_influence_singular(kind)) return -1.0;
  const double h = delta / NCELLS;
  double norm = 0.0, moment = 0.0;
  for (int k = 0; k < NCELLS; k++) {
    const double r = (k + 0.5) * h;
    const double w = pd_influence(kind, dim, r, delta);
    norm += (dim == 3 ? 4.0 * PD_PI * r * r : 2.0 * PD_PI * r) * w * h;
    moment += pow(r, dim + q) * w * h;
  }
  /* omega = (d / norm) w; I for beta = 1 */
  const double scale = dim / norm;
  const double integral = (dim == 3 ? PD_PI : 2.0) * scale * moment;
  return Gc / (2.0 * integral);
}

double pd_energy_failure_beta_lattice(int dim, double Gc, double weighted_volume, double moment)
{
  const double mean_cos = dim == 3 ? 0.25 : 1.0 / PD_PI;
  return Gc * weighted_volume / (2.0 * dim * mean_cos * moment);
}


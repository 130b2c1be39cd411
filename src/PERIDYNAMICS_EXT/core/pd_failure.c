#include "pd_failure.h"

#include "pd_macros.h"

#include <math.h>
#include <stdlib.h>

/* Midpoint rule: the integrands are smooth on (0, delta) and at worst
 * integrably singular at 0; 200000 cells give ~1e-9 relative. */
#define NCELLS 200000

double pd_energy_failure_beta(pd_influence_kind kind, int dim, double delta, double Gc)
{
  if (dim == 2 && kind == PD_INFLUENCE_INVERSE) return -1.0;
  const double h = delta / NCELLS;
  double norm = 0.0, moment = 0.0;
  for (int k = 0; k < NCELLS; k++) {
    const double r = (k + 0.5) * h;
    const double w = pd_influence(kind, dim, r, delta);
    norm += (dim == 3 ? 4.0 * PD_PI * r * r : 2.0 * PD_PI * r) * w * h;
    moment += (dim == 3 ? r : 1.0) * w * h;
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

void pd_failure_moment(const pd_bond_view *b, const double *vol, double *moment)
{
  for (int i = 0; i < b->nowner; i++) {
    const int row = i * b->stride;
    for (int k = 0; k < b->count[i]; k++) {
      const int j = b->far[row + k];
      const double w = (b->weight ? b->weight[row + k] : 1.0) / fabs(b->len0[row + k]);
      moment[i] += w * vol[j];
      moment[j] += w * vol[i];
    }
  }
}

double pd_critical_stretch(int dim, int plane_strain, double E, double nu, double delta, double Gc)
{
  if (dim == 3) {
    const double K = E / (3.0 * (1.0 - 2.0 * nu));
    return sqrt(5.0 * Gc / (9.0 * K * delta));
  }
  if (plane_strain) return sqrt(5.0 * PD_PI * Gc / (12.0 * E * delta));
  return sqrt(4.0 * PD_PI * Gc / (9.0 * E * delta));
}

int pd_failure_note_fresh(pd_failure *f, int idx)
{
  if (f->nfresh == f->maxfresh) {
    const int room = f->maxfresh ? 2 * f->maxfresh : 256;
    int *grown = (int *) realloc(f->fresh, (size_t) room * sizeof(int));
    if (!grown) return 0;
    f->fresh = grown;
    f->maxfresh = room;
  }
  f->fresh[f->nfresh++] = idx;
  return 1;
}

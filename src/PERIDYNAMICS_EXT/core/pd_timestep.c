#include "pd_timestep.h"

#include <math.h>

void pd_pmb_stiffness(const pd_bond_view *b, const pd_pmb *mat, const int *type,
                      const double *vol, double *sum)
{
  for (int i = 0; i < b->nowner; i++) {
    const int row = i * b->stride;
    for (int k = 0; k < b->count[i]; k++) {
      const int j = b->far[row + k];
      const double w = b->weight ? b->weight[row + k] : 1.0;
      const double c = mat->c[type[i] * mat->ntypes + type[j]] * w / fabs(b->len0[row + k]);
      sum[i] += c * vol[j];
      sum[j] += c * vol[i];
    }
  }
}

void pd_ordinary_stiffness(const pd_bond_view *b, const double *kc,
                           const double *vol, double *sum)
{
  for (int i = 0; i < b->nowner; i++) {
    const int row = i * b->stride;
    for (int k = 0; k < b->count[i]; k++) {
      const int j = b->far[row + k];
      const double r0 = fabs(b->len0[row + k]); /* broken bonds may still push */
      const double w = b->weight ? b->weight[row + k] : 1.0;
      const double c = (kc[i] + kc[j]) * w / (r0 * r0);
      sum[i] += c * vol[j];
      sum[j] += c * vol[i];
    }
  }
}

double pd_stable_dt(double rho, double sum)
{
  return sum > 0.0 ? sqrt(2.0 * rho / sum) : INFINITY;
}

#include "pd_bonds.h"

void pd_weighted_volume(const pd_bond_view *b, const double *vol, double *m)
{
  for (int i = 0; i < b->nowner; i++) {
    const int row = i * b->stride;
    for (int k = 0; k < b->count[i]; k++) {
      const int j = b->far[row + k];
      const double w = b->weight ? b->weight[row + k] : 1.0;
      m[i] += w * vol[j];
      m[j] += w * vol[i];
    }
  }
}

void pd_intact_volume(const pd_bond_view *b, const double *vol, double *m)
{
  for (int i = 0; i < b->nowner; i++) {
    const int row = i * b->stride;
    for (int k = 0; k < b->count[i]; k++) {
      if (b->len0[row + k] < 0.0) continue;
      const int j = b->far[row + k];
      const double w = b->weight ? b->weight[row + k] : 1.0;
      m[i] += w * vol[j];
      m[j] += w * vol[i];
    }
  }
}

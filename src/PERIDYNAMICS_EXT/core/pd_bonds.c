#include "pd_bonds.h"

#include "pd_bond_loop.h"

static inline void weight_both_ends(const void *ctx, const pd_bond *bd, double *a, double *b)
{
  (void) ctx;
  *a = *b = bd->w;
}

void pd_weighted_volume(const pd_bond_view *b, const double *vol, double *m)
{
  pd_reference_volumes(b, vol, NULL, m);
}

void pd_reference_volumes(const pd_bond_view *b, const double *vol, double *family, double *weighted)
{
  for (int i = 0; i < b->nowner; i++) {
    const int row = i * b->stride;
    for (int k = 0; k < b->count[i]; k++) {
      const int j = b->far[row + k];
      const double w = b->weight ? b->weight[row + k] : 1.0;
      if (family) {
        family[i] += vol[j];
        family[j] += vol[i];
      }
      if (weighted) {
        weighted[i] += w * vol[j];
        weighted[j] += w * vol[i];
      }
    }
  }
}

void pd_intact_volume(const pd_bond_view *b, const double *vol, double *m)
{
  pd_reference_sums(b, NULL, 0, vol, m, NULL, weight_both_ends, 1);
}

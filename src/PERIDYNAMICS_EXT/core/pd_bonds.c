#include "pd_bonds.h"

#include "pd_bond_loop.h"

static inline void weight_both_ends(const void *ctx, const pd_bond *bd, double *a, double *b)
{
  (void) ctx;
  *a = *b = bd->w;
}

void pd_weighted_volume(const pd_bond_view *b, const double *vol, double *m)
{
  pd_reference_sums(b, NULL, 0, vol, m, NULL, weight_both_ends, 0);
}

void pd_intact_volume(const pd_bond_view *b, const double *vol, double *m)
{
  pd_reference_sums(b, NULL, 0, vol, m, NULL, weight_both_ends, 1);
}

/* Contact candidates and the short list (pd_contact_list.h). */
#include "pd_contact_list.h"

/* Copies to out[] the candidates closer than dist + skin now; returns how
 * many. */
int pd_contact_select(const pd_contact_cand *restrict cand, int n,
                      const double *restrict x, double skin,
                      pd_contact_cand *restrict out)
{
  int m = 0;
  for (int p = 0; p < n; p++) {
    const double *xi = x + 3 * cand[p].i, *xj = x + 3 * cand[p].j;
    const double dx = xj[0] - xi[0], dy = xj[1] - xi[1], dz = xj[2] - xi[2];
    const double reach = cand[p].dist + skin;
    if (dx * dx + dy * dy + dz * dz < reach * reach) out[m++] = cand[p];
  }
  return m;
}

/* 1 if one of the atoms[0..n-1] moved farther than `limit` from its
 * position in ref[] (3 per entry of atoms[], in its order). */
int pd_contact_moved(const int *restrict atoms, int n, const double *restrict x,
                     const double *restrict ref, double limit)
{
  const double limit2 = limit * limit;
  for (int k = 0; k < n; k++) {
    const double *xa = x + 3 * atoms[k], *r = ref + 3 * k;
    const double dx = xa[0] - r[0], dy = xa[1] - r[1], dz = xa[2] - r[2];
    if (dx * dx + dy * dy + dz * dz > limit2) return 1;
  }
  return 0;
}


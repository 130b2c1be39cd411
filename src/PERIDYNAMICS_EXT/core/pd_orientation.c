#include "pd_orientation.h"

#include "pd_macros.h"

#include <math.h>

double pd_release(const pd_family *f, pd_release_kind kind, const double n[3])
{
  /* sum (e.n)+ phi against its orientation average <cos+> sum phi, with
   * phi ~ w / |xi|^2 (energy law), w |xi| (bond-based) or w (ordinary,
   * critical stretch), per unit (xi.n) */
  double across = 0.0, all = 0.0;
  for (int k = 0; k < f->n; k++) {
    const pd_family_bond *b = f->bond + k;
    const double normal = b->xi[0] * n[0] + b->xi[1] * n[1] + b->xi[2] * n[2];
    const double phi = kind == PD_RELEASE_ENERGY_LAW  ? b->w / (b->r * b->r)
                       : kind == PD_RELEASE_BOND_BASED ? b->w * b->r
                                                       : b->w;
    all += phi * b->r;
    if (normal > 0.0) across += normal * phi;
  }
  const double mean_cos = f->dim == 3 ? 0.25 : 1.0 / PD_PI;
  return across / (mean_cos * all);
}

static void widen(double g, double *lo, double *hi)
{
  if (g < *lo) *lo = g;
  if (g > *hi) *hi = g;
}

void pd_release_range(const pd_family *f, pd_release_kind kind, double *lo, double *hi)
{
  *lo = INFINITY, *hi = -INFINITY;
  const int count = f->dim == 3 ? 4000 : 360;
  for (int k = 0; k < count; k++) {
    double n[3];
    if (f->dim == 3) {
      /* a Fibonacci spiral: even coverage without clustering at the poles */
      const double z = 1.0 - (2.0 * k + 1.0) / count, s = sqrt(1.0 - z * z);
      const double phi = k * PD_PI * (3.0 - sqrt(5.0));
      n[0] = s * cos(phi), n[1] = s * sin(phi), n[2] = z;
    } else {
      const double a = 2.0 * PD_PI * k / count;
      n[0] = cos(a), n[1] = sin(a), n[2] = 0.0;
    }
    widen(pd_release(f, kind, n), lo, hi);
  }
  /* the lattice axes, where the extremes of a cubic family often sit */
  for (int a = 0; a < f->dim; a++) {
    const double n[3] = {a == 0, a == 1, a == 2};
    widen(pd_release(f, kind, n), lo, hi);
  }
}

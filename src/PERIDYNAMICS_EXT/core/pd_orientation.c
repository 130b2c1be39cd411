#include "pd_orientation.h"

#include "pd_law_stretch.h"
#include "pd_macros.h"

#include <math.h>

double pd_release(const pd_family *f, pd_release_kind kind, const double n[3])
{
  /* sum (e.n)+ phi against its orientation average <cos+> sum phi, with
   * phi ~ w / |xi|^2 (energy law, opening), w |xi| (bond-based) or w
   * (energy law, uniform; ordinary, critical stretch), per unit (xi.n) */
  double across = 0.0, all = 0.0;
  for (int k = 0; k < f->n; k++) {
    const pd_family_bond *b = f->bond + k;
    const double normal = b->xi[0] * n[0] + b->xi[1] * n[1] + b->xi[2] * n[2];
    const double phi = kind == PD_RELEASE_ENERGY_OPENING ? b->w / (b->r * b->r)
                       : kind == PD_RELEASE_BOND_BASED    ? b->w * b->r
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

void pd_spread_normal(int dim, int k, int count, double n[3])
{
  if (dim == 3) {
    /* a Fibonacci spiral: even coverage without clustering at the poles */
    const double z = 1.0 - (2.0 * k + 1.0) / count, s = sqrt(1.0 - z * z);
    const double phi = k * PD_PI * (3.0 - sqrt(5.0));
    n[0] = s * cos(phi), n[1] = s * sin(phi), n[2] = z;
  } else {
    const double a = 2.0 * PD_PI * k / count;
    n[0] = cos(a), n[1] = sin(a), n[2] = 0.0;
  }
}

/* the smallest and largest of g over count spread normals and the lattice
 * axes (where the extremes of a cubic family often sit) */
typedef double (*release_fn)(const pd_family *f, const void *ctx, const double n[3]);
static void release_range(const pd_family *f, release_fn g, const void *ctx, int count, double *lo, double *hi)
{
  *lo = INFINITY, *hi = -INFINITY;
  for (int k = 0; k < count; k++) {
    double n[3];
    pd_spread_normal(f->dim, k, count, n);
    widen(g(f, ctx, n), lo, hi);
  }
  for (int a = 0; a < f->dim; a++) {
    const double n[3] = {a == 0, a == 1, a == 2};
    widen(g(f, ctx, n), lo, hi);
  }
}

static double release_of_kind(const pd_family *f, const void *kind, const double n[3])
{
  return pd_release(f, *(const pd_release_kind *) kind, n);
}

void pd_release_range(const pd_family *f, pd_release_kind kind, double *lo, double *hi)
{
  release_range(f, release_of_kind, &kind, f->dim == 3 ? 4000 : 360, lo, hi);
}

/* the calibration's denominator: <cos+> sum w |xi| (1 + kappa ratio),
 * then G(n) / G_c */
typedef struct ordinary_release {
  double ratio, norm;
} ordinary_release;

static ordinary_release ordinary_norm(const pd_family *f, double ratio)
{
  double sums[2] = {0.0, 0.0}, moment = 0.0;
  pd_ordinary_family_release(f, sums);
  for (int k = 0; k < f->n; k++) moment += f->bond[k].w * f->volume * f->bond[k].r;
  const double kappa = sums[1] > 0.0 ? sums[0] / sums[1] : 0.0;
  return (ordinary_release){ratio, (f->dim == 3 ? 0.25 : 1.0 / PD_PI) * moment * (1.0 + kappa * ratio)};
}

static double ordinary_at(const pd_family *f, const void *ctx, const double n[3])
{
  const ordinary_release *o = (const ordinary_release *) ctx;
  double pairs, across;
  pd_ordinary_release_at(f, n, &pairs, &across);
  return (across + o->ratio * pairs) / o->norm;
}

double pd_release_ordinary(const pd_family *f, double ratio, const double n[3])
{
  const ordinary_release o = ordinary_norm(f, ratio);
  return ordinary_at(f, &o, n);
}

void pd_release_ordinary_range(const pd_family *f, double ratio, double *lo, double *hi)
{
  const ordinary_release o = ordinary_norm(f, ratio);
  release_range(f, ordinary_at, &o, f->dim == 3 ? 1000 : 360, lo, hi);
}

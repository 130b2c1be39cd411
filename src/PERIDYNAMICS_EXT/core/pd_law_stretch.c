#include "pd_law_stretch.h"

#include "pd_lattice.h"
#include "pd_macros.h"
#include "pd_orientation.h"

#include <math.h>
#include <stdlib.h>

double pd_critical_stretch(int dim, int plane_strain, double E, double nu, double delta, double Gc)
{
  if (dim == 3) {
    const double K = E / (3.0 * (1.0 - 2.0 * nu));
    return sqrt(5.0 * Gc / (9.0 * K * delta));
  }
  if (plane_strain) return sqrt(5.0 * PD_PI * Gc / (12.0 * E * delta));
  return sqrt(4.0 * PD_PI * Gc / (9.0 * E * delta));
}

double pd_critical_stretch_ordinary(int dim, double Gc, double lambda, double mu, double kappa,
                                    double weighted_volume, double moment1)
{
  const double share = 1.0 + kappa * lambda / mu;
  if (!(mu > 0.0) || !(weighted_volume > 0.0) || !(moment1 > 0.0) || !(share > 0.0)) return NAN;
  const double mean_cos = dim == 3 ? 0.25 : 1.0 / PD_PI;
  return sqrt(Gc * weighted_volume / (2.0 * mu * dim * mean_cos * moment1 * share));
}

typedef struct crossing_bond {
  double opening;    /* u at which it breaks, s0 = delta = 1: |xi| / cos */
  double normal;     /* xi.n = |xi| cos */
  double weight;     /* omega dV */
  double strain;     /* strain per unit opening: cos / |xi| */
} crossing_bond;

static int by_opening(const void *a, const void *b)
{
  const double x = ((const crossing_bond *) a)->opening, y = ((const crossing_bond *) b)->opening;
  return (x > y) - (x < y);
}

double pd_ordinary_dilatation_release(pd_influence_kind kind, int dim)
{
  /* midpoint grid over the bonds pointing across (cos > 0): |xi| in
   * (0, 1], the angle to n in [0, pi/2) (3D: dV = 2 pi r^2 dr dcos; 2D:
   * r dr dphi over both sides of n) */
  enum { NR = 160, NA = 160, NZ = 64 };
  crossing_bond *bond = malloc(sizeof(crossing_bond) * NR * NA);
  if (!bond) return NAN;
  double m = 0.0, across = 0.0;
  int n = 0;
  for (int k = 0; k < NR; k++) {
    const double r = (k + 0.5) / NR, w = pd_influence(kind, dim, r, 1.0);
    for (int l = 0; l < NA; l++) {
      double c, dv;
      if (dim == 3) {
        c = (l + 0.5) / NA;
        dv = 2.0 * PD_PI * r * r / (NR * NA);
      } else {
        c = cos(-0.5 * PD_PI + PD_PI * (l + 0.5) / NA);
        dv = r * PD_PI / (NR * NA);
      }
      m += 2.0 * w * dv; /* the half pointing away counts the same */
      across += w * dv * r * c;
      bond[n++] = (crossing_bond){r / c, r * c, w * dv, c / r};
    }
  }
  qsort(bond, (size_t) n, sizeof *bond, by_opening);
  /* at depth z, each crossing bond at its own breaking opening u sees the
   * crossing bonds that break later (itself included) at strain u c / r */
  double sum = 0.0;
  for (int q = 0; q < NZ; q++) {
    const double z = (q + 0.5) / NZ;
    double later = 0.0;
    for (int b = n - 1; b >= 0; b--)
      if (bond[b].normal > z) {
        later += bond[b].weight * bond[b].strain;
        sum += bond[b].weight * (dim / m) * bond[b].opening * later / NZ;
      }
  }
  free(bond);
  return sum / across;
}

void pd_ordinary_release_at(const pd_family *f, const double n[3], double *pairs, double *across)
{
  *pairs = 0.0, *across = 0.0;
  crossing_bond *bond = malloc(sizeof(crossing_bond) * (f->n > 0 ? f->n : 1));
  if (!bond) return;
  double m = 0.0;
  int nc = 0;
  for (int b = 0; b < f->n; b++) {
    const pd_family_bond *e = f->bond + b;
    const double normal = e->xi[0] * n[0] + e->xi[1] * n[1] + e->xi[2] * n[2], w = e->w * f->volume;
    m += w;
    if (!(normal > 0.0) || !(e->r > 0.0)) continue;
    const double c = normal / e->r;
    *across += w * normal;
    bond[nc++] = (crossing_bond){e->r / c, normal, w, c / e->r};
  }
  /* (openings equal to round-off break together) */
  double sum = 0.0;
  for (int b = 0; b < nc; b++)
    for (int e = 0; e < nc; e++)
      if (bond[e].opening >= bond[b].opening * (1.0 - 1e-12))
        sum += bond[b].weight * bond[b].opening * bond[e].weight * bond[e].strain * fmin(bond[b].normal, bond[e].normal);
  if (m > 0.0) *pairs = sum * f->dim / m;
  free(bond);
}

void pd_ordinary_family_release(const pd_family *f, double sums[2])
{
  const int count = PD_RELEASE_NORMALS(f->dim);
  for (int k = 0; k < count; k++) {
    double n[3], pairs, across;
    pd_spread_normal(f->dim, k, count, n);
    pd_ordinary_release_at(f, n, &pairs, &across);
    sums[0] += pairs;
    sums[1] += across;
  }
}

double pd_critical_stretch_factor(int dim, double delta, double thickness, double stiffness, double moment2)
{
  if (!(moment2 > 0.0) || !(stiffness > 0.0)) return 1.0;
  const double d4 = delta * delta * delta * delta;
  const double integral = dim == 3 ? 4.0 * PD_PI * d4 * delta / 5.0 : PD_PI * d4 * thickness / 2.0;
  return sqrt(integral / (stiffness * moment2));
}

#include "pd_lattice.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static const char *names[] = {"chain", "sq", "hex", "sc", "fcc"};
#define NNAMES ((int) (sizeof(names) / sizeof(names[0])))

int pd_lattice_from_name(const char *name)
{
  for (int k = 0; k < NNAMES; k++)
    if (strcmp(name, names[k]) == 0) return k;
  return -1;
}

const char *pd_lattice_name(pd_lattice_kind kind)
{
  return (int) kind >= 0 && (int) kind < NNAMES ? names[kind] : "?";
}

int pd_lattice_make(pd_lattice_kind kind, double a, pd_lattice *out)
{
  if (!(a > 0.0) || (int) kind < 0 || (int) kind >= NNAMES) return -1;
  memset(out, 0, sizeof(*out));
  out->kind = kind;
  out->a = a;
  out->nearest = a;
  const double s3 = sqrt(3.0);
  switch (kind) {
  case PD_LATTICE_CHAIN: out->dim = 1; break;
  case PD_LATTICE_SQ: out->dim = 2; break;
  case PD_LATTICE_SC: out->dim = 3; break;
  case PD_LATTICE_HEX:
    /* sites (0,0) and (a/2, sqrt3 a/2) of an a x sqrt3 a cell: the grid of
     * steps (a/2, sqrt3 a/2) at even index sums */
    out->dim = 2;
    out->parity = 1;
    out->cell[1] = s3 * a;
    out->sub[0] = out->sub[1] = 2;
    break;
  case PD_LATTICE_FCC:
    /* cube corners and face centres: the grid of step a/2 at even sums */
    out->dim = 3;
    out->parity = 1;
    out->sub[0] = out->sub[1] = out->sub[2] = 2;
    out->nearest = a / sqrt(2.0);
    break;
  }
  for (int d = 0; d < 3; d++) {
    if (d >= out->dim) {
      out->cell[d] = 0.0;
      out->sub[d] = 1;
      continue;
    }
    if (out->cell[d] == 0.0) out->cell[d] = a;
    if (out->sub[d] == 0) out->sub[d] = 1;
    out->h[d] = out->cell[d] / out->sub[d];
  }
  double v = 1.0;
  int sites = 1;
  for (int d = 0; d < out->dim; d++) {
    v *= out->cell[d];
    sites *= out->sub[d];
  }
  /* half the grid points are sites with parity */
  out->volume = v / (out->parity ? sites / 2 : sites);
  return 0;
}

double pd_influence_weight_fn(const double xi[3], double r, void *ctx)
{
  (void) xi;
  const pd_influence_weight *w = (const pd_influence_weight *) ctx;
  return pd_influence(w->kind, w->dim, r, w->horizon);
}

/* Walk the grid offsets within the cutoff, with their weights (bonds of
 * weight 0 left out); store them when 'out' is set. Returns the count. */
static int walk(const pd_lattice *lat, double cutoff, pd_weight_fn weight, void *ctx,
                pd_family_bond *out)
{
  const double reach = cutoff * (1.0 + 1e-12);
  int lim[3] = {0, 0, 0};
  for (int d = 0; d < lat->dim; d++) lim[d] = (int) floor(reach / lat->h[d]);
  int n = 0;
  for (int i = -lim[0]; i <= lim[0]; i++)
    for (int j = -lim[1]; j <= lim[1]; j++)
      for (int k = -lim[2]; k <= lim[2]; k++) {
        if (!i && !j && !k) continue;
        if (lat->parity && ((i + j + k) % 2 != 0)) continue;
        const double xi[3] = {i * lat->h[0], j * lat->h[1], k * lat->h[2]};
        const double r = sqrt(xi[0] * xi[0] + xi[1] * xi[1] + xi[2] * xi[2]);
        if (r > reach) continue;
        const double w = weight ? weight(xi, r, ctx) : 1.0;
        if (w == 0.0) continue;
        if (out) {
          pd_family_bond *b = out + n;
          memcpy(b->xi, xi, sizeof(xi));
          b->r = r;
          b->w = w;
          b->p[0] = i, b->p[1] = j, b->p[2] = k;
        }
        n++;
      }
  return n;
}

int pd_lattice_family(const pd_lattice *lat, double cutoff, double thickness, pd_weight_fn weight,
                      void *ctx, pd_family *out)
{
  memset(out, 0, sizeof(*out));
  if (!lat || !(cutoff > 0.0) || !(lat->a > 0.0)) return -1;
  const int n = walk(lat, cutoff, weight, ctx, NULL);
  out->bond = malloc((n ? n : 1) * sizeof(pd_family_bond));
  if (!out->bond) return -1;
  walk(lat, cutoff, weight, ctx, out->bond);
  out->n = n;
  out->dim = lat->dim;
  out->volume = lat->volume * (lat->dim == 2 && thickness > 0.0 ? thickness : 1.0);
  return n;
}

void pd_family_free(pd_family *f)
{
  free(f->bond);
  f->bond = NULL;
  f->n = 0;
}

double pd_family_weighted_volume(const pd_family *f)
{
  double m = 0.0;
  for (int b = 0; b < f->n; b++) m += f->bond[b].w * f->volume;
  return m;
}

double pd_family_moment_sum(const pd_family *f, int power)
{
  double m = 0.0;
  for (int b = 0; b < f->n; b++) m += f->bond[b].w * f->volume * pow(f->bond[b].r, power);
  return m;
}

#include "pd_influence.h"

#include "pd_macros.h"

#include <math.h>
#include <string.h>

/* Each influence function: omega(r) for 0 < r <= delta. */
static double constant(int dim, double r, double delta)
{
  (void) dim, (void) r, (void) delta;
  return 1.0;
}

/* (through 1/r, as the bond loops compute it: pd_bond_view.weight_horizon) */
static double inverse(int dim, double r, double delta)
{
  (void) dim;
  return delta * (1.0 / r);
}

static double lps(int dim, double r, double delta)
{
  (void) dim;
  return r / delta;
}

static double tupek(int dim, double r, double delta)
{
  const double d3 = (delta - r) * (delta - r) * (delta - r);
  const double p = (3.0 * r + delta) * d3;
  const double d2 = delta * delta, d6 = d2 * d2 * d2;
  if (dim == 2) return 10.0 / (PD_PI * d6) * p;
  return 315.0 / (16.0 * PD_PI * d6 * delta) * p;
}

static double gaussian(int dim, double r, double delta)
{
  (void) dim;
  const double sigma = 0.5 * delta;
  return exp(-(r * r) / (sigma * sigma));
}

/* The declarations, in the order of pd_influence_kind. "gaussian", not
 * "gauss": under pair_style hybrid a value that is also a pair style's name
 * (gauss) would start a new sub-style. */
static const struct {
  const char *name;
  double (*omega)(int dim, double r, double delta);
  int singular; /* omega ~ 1/r at 0: the 2D G_c integral diverges */
} kinds[] = {
    {"constant", constant, 0},
    {"inverse", inverse, 1},
    {"lps", lps, 0},
    {"tupek", tupek, 0},
    {"gaussian", gaussian, 0},
};
#define NKINDS ((int) (sizeof(kinds) / sizeof(kinds[0])))

double pd_influence(pd_influence_kind kind, int dim, double r, double delta)
{
  if (r > delta || (int) kind < 0 || (int) kind >= NKINDS) return 0.0;
  return kinds[kind].omega(dim, r, delta);
}

int pd_influence_singular(pd_influence_kind kind)
{
  return (int) kind >= 0 && (int) kind < NKINDS && kinds[kind].singular;
}

int pd_influence_from_name(const char *name)
{
  for (int k = 0; k < NKINDS; k++)
    if (strcmp(name, kinds[k].name) == 0) return k;
  return -1;
}

const char *pd_influence_name(pd_influence_kind kind)
{
  return ((int) kind >= 0 && (int) kind < NKINDS) ? kinds[kind].name : "?";
}

const char *pd_influence_names(void)
{
  static char all[128];
  if (!all[0])
    for (int k = 0; k < NKINDS; k++) {
      if (k) strcat(all, ", ");
      strcat(all, kinds[k].name);
    }
  return all;
}

double pd_partial_volume_legacy(double r, double delta, double lc)
{
  const double half = 0.5 * lc;
  if (fabs(r - delta) > half) return 1.0;
  /* Same arithmetic order as PERI, so legacy runs agree to round-off. */
  return (-1.0 / (2 * half)) * r + (1.0 + ((delta - half) / (2 * half)));
}

double pd_influence_of_cell(pd_influence_kind kind, int dim, double r, double delta)
{
  return pd_influence(kind, dim, r < delta ? r : delta, delta);
}

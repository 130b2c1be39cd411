#include "pd_influence.h"

#include "pd_macros.h"

#include <math.h>
#include <string.h>

/* "gaussian", not "gauss": under pair_style hybrid a value that is also a
 * pair style's name (gauss) would start a new sub-style */
static const char *const names[] = {"constant", "inverse", "lps", "tupek", "gaussian"};
#define NKINDS ((int) (sizeof(names) / sizeof(names[0])))

double pd_influence(pd_influence_kind kind, int dim, double r, double delta)
{
  if (r > delta) return 0.0;
  switch (kind) {
  case PD_INFLUENCE_CONSTANT: return 1.0;
  case PD_INFLUENCE_INVERSE: return delta / r;
  case PD_INFLUENCE_LPS: return r / delta;
  case PD_INFLUENCE_TUPEK: {
    const double d3 = (delta - r) * (delta - r) * (delta - r);
    const double p = (3.0 * r + delta) * d3;
    const double d2 = delta * delta, d6 = d2 * d2 * d2;
    if (dim == 2) return 10.0 / (PD_PI * d6) * p;
    return 315.0 / (16.0 * PD_PI * d6 * delta) * p;
  }
  case PD_INFLUENCE_GAUSS: {
    const double sigma = 0.5 * delta;
    return exp(-(r * r) / (sigma * sigma));
  }
  }
  return 0.0;
}

int pd_influence_from_name(const char *name)
{
  for (int k = 0; k < NKINDS; k++)
    if (strcmp(name, names[k]) == 0) return k;
  return -1;
}

const char *pd_influence_name(pd_influence_kind kind)
{
  return (kind >= 0 && (int) kind < NKINDS) ? names[kind] : "?";
}

double pd_partial_volume_legacy(double r, double delta, double lc)
{
  const double half = 0.5 * lc;
  if (fabs(r - delta) > half) return 1.0;
  /* Same arithmetic order as PERI, so legacy runs agree to round-off. */
  return (-1.0 / (2 * half)) * r + (1.0 + ((delta - half) / (2 * half)));
}

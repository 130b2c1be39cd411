/* Seth-Hill bond strain of order m (T14 eq. 4.2), eps_m = (c^m - 1)/(2m)
 * with c = |Y|^2/|xi|^2, eps_0 = log(c)/2: the bond strain of pd/ordinary
 * and of extended correspondence (pd/corr). Three forms so that the common
 * orders pay for no pow(): m = 1/2 (the stretch), m = 0 (log). */
#ifndef PD_SETH_HILL_H
#define PD_SETH_HILL_H

#include "pd_bonds.h"
#include "pd_log.h"

#include <math.h>

enum { PD_ORDER_HALF, PD_ORDER_LOG, PD_ORDER_ANY };

static inline int pd_order_kind(double m)
{
  if (m == 0.5) return PD_ORDER_HALF;
  if (m == 0.0) return PD_ORDER_LOG;
  return PD_ORDER_ANY;
}

/* eps_0 = log(|Y|/|xi|) in a loop that vectorizes (pd_log, and 1/|xi|,
 * which the inverse weight shares), or in one that does not: libm's log is
 * faster there (pd/corr's bonds go one by one; pd_log made its extended
 * form 1.3x slower) */
PD_INLINE double pd_bond_log_strain(const pd_bond *bd, int vectorized)
{
  return vectorized ? pd_log(bd->len * (1.0 / bd->r0)) : log(bd->len / bd->r0);
}

PD_INLINE double
pd_bond_strain(int kind, double m, const pd_bond *bd)
{
  /* times 1/|xi|, a divide that need not wait for |Y| (through
   * pd_bond_inverse, it would: the dilatation pass is then slower) */
  if (kind == PD_ORDER_HALF) return (bd->len - bd->r0) * (1.0 / bd->r0);
  if (kind == PD_ORDER_LOG) return pd_bond_log_strain(bd, 1);
  return expm1(2.0 * m * pd_bond_log_strain(bd, 0)) / (2.0 * m);
}

/* d eps / d|Y| = c^(m-1) |Y| / |xi|^2 = (1 + 2 m eps) / |Y|. */
PD_INLINE double
pd_bond_strain_rate(int kind, double m, double eps, const pd_bond *bd)
{
  if (kind == PD_ORDER_HALF) return 1.0 / bd->r0;
  if (kind == PD_ORDER_LOG) return 1.0 / bd->len;
  return (1.0 + 2.0 * m * eps) / bd->len;
}

/* The same over |Y| (0 at zero length): what turns a force state into
 * the force per length; m = 1/2 takes no divide of its own. */
PD_INLINE double
pd_bond_strain_rate_per_length(int kind, double m, double eps, const pd_bond *bd)
{
  if (kind == PD_ORDER_HALF) return pd_bond_inverse(bd);
  const double inv2 = bd->len > 0.0 ? 1.0 / (bd->len * bd->len) : 0.0;
  if (kind == PD_ORDER_LOG) return inv2;
  return (1.0 + 2.0 * m * eps) * inv2;
}

/* The same strain of a principal stretch squared (an eigenvalue c of C),
 * given as a = c - 1 (small strains keep their digits), its derivative in
 * c, and the inverse (returning c - 1): the tensor forms of pd/corr. */
static inline double pd_seth_hill_excess(double m, double a)
{
  return m == 0.0 ? 0.5 * log1p(a) : expm1(m * log1p(a)) / (2.0 * m);
}
static inline double pd_seth_hill(double m, double c)
{
  return pd_seth_hill_excess(m, c - 1.0);
}
static inline double pd_seth_hill_slope(double m, double c)
{
  return 0.5 * pow(c, m - 1.0);
}
static inline double pd_seth_hill_inverse_excess(double m, double e)
{
  return m == 0.0 ? expm1(2.0 * e) : expm1(log1p(2.0 * m * e) / m);
}
static inline double pd_seth_hill_inverse(double m, double e)
{
  return 1.0 + pd_seth_hill_inverse_excess(m, e);
}

#endif

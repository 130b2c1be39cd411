/* Seth-Hill bond strain of order m (T14 eq. 4.2), eps_m = (c^m - 1)/(2m)
 * with c = |Y|^2/|xi|^2, eps_0 = log(c)/2: the bond strain of pd/ordinary
 * and of extended correspondence (pd/corr). Four forms so that the common
 * orders pay for no pow(): m = 1/2 (the stretch), m = 0 (log) and the
 * negative integers (a polynomial in 1/c); the last two from |Y|^2, with
 * no square root. */
#ifndef PD_SETH_HILL_H
#define PD_SETH_HILL_H

#include "pd_bonds.h"
#include "pd_log.h"

#include <math.h>

enum { PD_ORDER_HALF, PD_ORDER_LOG, PD_ORDER_RECIPROCAL, PD_ORDER_ANY, PD_ORDER_KINDS };

/* the negative integers that PD_ORDER_RECIPROCAL takes (m >= -4, the
 * range of pd/ordinary's m) */
enum { PD_RECIPROCAL_MAX = 4 };

static inline int pd_order_kind(double m)
{
  if (m == 0.5) return PD_ORDER_HALF;
  if (m == 0.0) return PD_ORDER_LOG;
  if (m < 0.0 && m >= -PD_RECIPROCAL_MAX && m == floor(m)) return PD_ORDER_RECIPROCAL;
  return PD_ORDER_ANY;
}

/* log(|Y|/|xi|) through libm, for the orders other than the above: their
 * loops take expm1 and stay scalar, and libm's log is faster there */
PD_INLINE double pd_bond_log_strain(const pd_bond *bd)
{
  return log(bd->len / bd->r0);
}

/* 1/|Y|^2 (0 at zero length): the one divide of the negative integer
 * orders, shared by their strain and force (the compiler merges it) */
PD_INLINE double pd_bond_inverse2(const pd_bond *bd)
{
  return bd->len2 > 0.0 ? 1.0 / bd->len2 : 0.0;
}

/* m = -n: with u = 1/c = |xi|^2/|Y|^2, c^m = u^n and
 * eps = (1 - u^n)/(2n) = (|Y|^2 - |xi|^2)/|Y|^2 (1 + u + ... + u^(n-1))/(2n),
 * the difference |Y|^2 - |xi|^2 first, so that small strains keep their
 * digits. Returns eps; *cm = c^m. (n is the same for every bond: the
 * selects below vectorize.) */
PD_INLINE double pd_reciprocal_strain(double m, const pd_bond *bd, double *cm)
{
  const double n = -m, r02 = bd->r0 * bd->r0, q = pd_bond_inverse2(bd), u = r02 * q;
  double un = u, sum = 1.0;
  for (int k = 1; k < PD_RECIPROCAL_MAX; ++k) {
    sum += k < n ? un : 0.0;
    un = k < n ? un * u : un;
  }
  *cm = un;
  return (bd->len2 - r02) * q * sum * (0.5 / n);
}

PD_INLINE double
pd_bond_strain(int kind, double m, const pd_bond *bd)
{
  double cm;
  /* times 1/|xi|, a divide that need not wait for |Y| (through
   * pd_bond_inverse, it would: the dilatation pass is then slower) */
  if (kind == PD_ORDER_HALF) return (bd->len - bd->r0) * (1.0 / bd->r0);
  if (kind == PD_ORDER_LOG) return 0.5 * pd_log_ratio(bd->len2, bd->r0 * bd->r0);
  if (kind == PD_ORDER_RECIPROCAL) return pd_reciprocal_strain(m, bd, &cm);
  return expm1(2.0 * m * pd_bond_log_strain(bd)) / (2.0 * m);
}

/* d eps / d|Y| = c^(m-1) |Y| / |xi|^2 = (1 + 2 m eps) / |Y|. */
PD_INLINE double pd_bond_strain_rate(int kind, double m, double eps, const pd_bond *bd)
{
  if (kind == PD_ORDER_HALF) return 1.0 / bd->r0;
  if (kind == PD_ORDER_LOG) return 1.0 / bd->len;
  return (1.0 + 2.0 * m * eps) / bd->len;
}

/* The same over |Y| (0 at zero length): what turns a force state into
 * the force per length; m = 1/2 takes no divide of its own, m = 0 and the
 * negative integers 1/|Y|^2. */
PD_INLINE double
pd_bond_strain_rate_per_length(int kind, double m, double eps, const pd_bond *bd)
{
  double cm;
  if (kind == PD_ORDER_HALF) return pd_bond_inverse(bd);
  if (kind == PD_ORDER_LOG) return pd_bond_inverse2(bd);
  if (kind == PD_ORDER_RECIPROCAL) {
    (void) pd_reciprocal_strain(m, bd, &cm);
    return cm * pd_bond_inverse2(bd);
  }
  const double inv2 = bd->len > 0.0 ? 1.0 / (bd->len * bd->len) : 0.0;
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
  /* (pow at m = 0 was 5% of classical correspondence's step) */
  if (m == 0.0) return 0.5 / c;
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

#include "pd_ordinary.h"

#include <math.h>
#include <stddef.h>

/* Strain of order m as a function of the length ratio; three variants so
 * the common orders pay for no pow(): m = 1/2 (LPS stretch), m = 0 (log). */
enum { ORDER_HALF, ORDER_LOG, ORDER_ANY };

PD_INLINE double
bond_strain(int kind, double m, double len, double r0)
{
  if (kind == ORDER_HALF) return (len - r0) / r0;
  if (kind == ORDER_LOG) return log(len / r0);
  return expm1(2.0 * m * log(len / r0)) / (2.0 * m);
}

/* d eps / d|Y| = c^(m-1) |Y| / |xi|^2 = (1 + 2 m eps) / |Y|. */
PD_INLINE double
bond_strain_rate(int kind, double m, double eps, double len, double r0)
{
  if (kind == ORDER_HALF) return 1.0 / r0;
  if (kind == ORDER_LOG) return 1.0 / len;
  return (1.0 + 2.0 * m * eps) / len;
}

static int order_kind(double m)
{
  if (m == 0.5) return ORDER_HALF;
  if (m == 0.0) return ORDER_LOG;
  return ORDER_ANY;
}

static inline double bond_weight(const pd_bond_view *b, int idx)
{
  return b->weight ? b->weight[idx] : 1.0;
}

static inline double bond_length(const double *restrict x, int i, int j, double d[3])
{
  d[0] = x[3 * j] - x[3 * i];
  d[1] = x[3 * j + 1] - x[3 * i + 1];
  d[2] = x[3 * j + 2] - x[3 * i + 2];
  return sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
}

PD_INLINE void
dilatation_loop(const pd_bond_view *restrict b, const pd_ordinary_state *st,
                const pd_failure *fail, const double *restrict x, const double *restrict vol,
                int kind, int cached, int failing)
{
  double *restrict sum = st->sum;
  for (int i = 0; i < b->nowner; i++) {
    const int n = b->count[i];
    const int row = i * b->stride;
    double si = 0.0;
    for (int k = 0; k < n; k++) {
      const int j = b->far[row + k];
      double d[3];
      const double len = bond_length(x, i, j, d);
      int broken = 0;
      const double r0 = failing ? pd_bond_reference(fail, b->len0[row + k], i, j, &broken) : b->len0[row + k];
      const double eps = bond_strain(kind, st->order, len, r0);
      if (cached) st->strain[row + k] = eps;
      if (failing && pd_bond_inactive(fail, broken, eps)) continue;
      const double we = bond_weight(b, row + k) * eps;
      si += we * vol[j];
      sum[j] += we * vol[i];
    }
    sum[i] += si;
  }
}

#define DILATATION_VARIANT(kind, cached, failing) \
  dilatation_loop(b, st, fail, x, vol, kind, cached, failing)

void pd_ordinary_dilatation(const pd_bond_view *b, const pd_ordinary_state *st,
                            const pd_failure *fail, const double *x, const double *vol)
{
  const int kind = order_kind(st->order);
  const int code = (st->strain != NULL && kind != ORDER_HALF) * 2 + (fail != NULL);
  switch (kind * 4 + code) {
  case ORDER_HALF * 4 + 0: DILATATION_VARIANT(ORDER_HALF, 0, 0); break;
  case ORDER_HALF * 4 + 1: DILATATION_VARIANT(ORDER_HALF, 0, 1); break;
  case ORDER_LOG * 4 + 0: DILATATION_VARIANT(ORDER_LOG, 0, 0); break;
  case ORDER_LOG * 4 + 1: DILATATION_VARIANT(ORDER_LOG, 0, 1); break;
  case ORDER_LOG * 4 + 2: DILATATION_VARIANT(ORDER_LOG, 1, 0); break;
  case ORDER_LOG * 4 + 3: DILATATION_VARIANT(ORDER_LOG, 1, 1); break;
  case ORDER_ANY * 4 + 0: DILATATION_VARIANT(ORDER_ANY, 0, 0); break;
  case ORDER_ANY * 4 + 1: DILATATION_VARIANT(ORDER_ANY, 0, 1); break;
  case ORDER_ANY * 4 + 2: DILATATION_VARIANT(ORDER_ANY, 1, 0); break;
  default: DILATATION_VARIANT(ORDER_ANY, 1, 1); break;
  }
}

PD_INLINE void
force_loop(const pd_bond_view *restrict b, const pd_ordinary_state *st, pd_failure *fail,
           const int *restrict type, const double *restrict x, const double *restrict vol,
           double *restrict f, pd_tally *tally, int kind, int tallied, int cached, int failing)
{
  const double *restrict ab = st->ab;
  const double m = st->order;
  const int nt = st->ntypes;
  pd_break_sums sums = {0.0, 0.0, 0};
  for (int i = 0; i < b->nowner; i++) {
    const int n = b->count[i];
    if (!n) continue;
    const int row = i * b->stride;
    const double ai = ab[2 * i], bi = ab[2 * i + 1], vi = vol[i];
    const double *restrict s0i = failing && fail->s0 ? fail->s0 + type[i] * nt : NULL;
    const double *restrict gci = failing && st->gc ? st->gc + type[i] * nt : NULL;
    double fi[3] = {0.0, 0.0, 0.0};
    for (int k = 0; k < n; k++) {
      const int j = b->far[row + k];
      double r0 = b->len0[row + k];
      int broken = 0;
      if (failing) {
        r0 = pd_bond_reference(fail, r0, i, j, &broken);
      }
      double d[3];
      const double len = bond_length(x, i, j, d);
      const double w = bond_weight(b, row + k);
      const double eps = cached ? st->strain[row + k] : bond_strain(kind, m, len, r0);
      if (failing && pd_bond_inactive(fail, broken, eps)) continue;
      const double aj = ab[2 * j], bj = ab[2 * j + 1];
      const double vj = vol[j];
      double share = 1.0;
      if (failing && (fail->law == PD_FAIL_STRETCH || fail->law == PD_FAIL_ENERGY) && !broken &&
          eps > 0.0) {
        /* instantaneous bond energy at each end, per partner volume (T14
         * eq. 6.5): s = w eps (A + B eps / 2). A bond that fails releases
         * that energy now and acts with half its force: the two half-kicks
         * around this step then carry it up to this step and no further,
         * so the balance of kinetic, elastic and dissipated energy stays
         * second order in dt (a bond dropped whole here would miss half a
         * kick: first order). */
        const double si = w * eps * (ai + 0.5 * bi * eps), sj = w * eps * (aj + 0.5 * bj * eps);
        const int breaks = fail->law == PD_FAIL_STRETCH
            ? len / r0 - 1.0 > s0i[type[j]]
            : (si + sj) * r0 * r0 >= w * (st->crit[i] + st->crit[j]) * gci[type[j]];
        if (breaks) {
          pd_break_bond(fail, &sums, row + k, r0, i, j, si, sj, vi, vj);
          share = 0.5;
        }
      }
      const double t = share * (ai + aj + (bi + bj) * eps) * w * bond_strain_rate(kind, m, eps, len, r0);
      const double tl = len > 0.0 ? t / len : 0.0;
      for (int c = 0; c < 3; c++) {
        fi[c] += vj * tl * d[c];
        f[3 * j + c] -= vi * tl * d[c];
      }
      if (tallied) {
        /* a breaking bond's energy is already booked as dissipated */
        const double we2 = share == 1.0 ? 0.5 * w * eps * eps : 0.0;
        tally->energy += we2 * (bi * vj + bj * vi);
        if (tally->eatom) {
          tally->eatom[i] += we2 * bi * vj;
          tally->eatom[j] += we2 * bj * vi;
        }
        const double dij[3] = {-d[0], -d[1], -d[2]};
        pd_tally_virial(tally, dij, -tl * vi * vj);
      }
      /* legacy PERI: the bond breaks after its force acted */
      if (failing && fail->law == PD_FAIL_LEGACY && !broken &&
          pd_legacy_failure(fail, type[i] * nt + type[j], i, j, len / r0 - 1.0)) {
        const double si = w * eps * (ai + 0.5 * bi * eps), sj = w * eps * (aj + 0.5 * bj * eps);
        pd_break_bond(fail, &sums, row + k, r0, i, j, si, sj, vi, vj);
      }
    }
    for (int c = 0; c < 3; c++) f[3 * i + c] += fi[c];
  }
  if (failing) pd_add_break_sums(fail, &sums);
}

#define FORCE_VARIANT(kind, tallied, cached, failing) \
  force_loop(b, st, fail, type, x, vol, f, (tallied) ? tally : NULL, kind, tallied, cached, failing)

/* Specialized copies: strain order x tally x strain cache (m != 1/2 only)
 * x failure. */
#define FORCE_BY_ORDER(kind, cached)                     \
  do {                                                   \
    if (tally) {                                         \
      if (fail) FORCE_VARIANT(kind, 1, cached, 1);       \
      else FORCE_VARIANT(kind, 1, cached, 0);            \
    } else {                                             \
      if (fail) FORCE_VARIANT(kind, 0, cached, 1);       \
      else FORCE_VARIANT(kind, 0, cached, 0);            \
    }                                                    \
  } while (0)

void pd_ordinary_forces(const pd_bond_view *b, const pd_ordinary_state *st, pd_failure *fail,
                        const int *type, const double *x, const double *vol, double *f,
                        pd_tally *tally)
{
  const int kind = order_kind(st->order);
  const int cached = st->strain != NULL && kind != ORDER_HALF;
  if (kind == ORDER_HALF) FORCE_BY_ORDER(ORDER_HALF, 0);
  else if (kind == ORDER_LOG) {
    if (cached) FORCE_BY_ORDER(ORDER_LOG, 1);
    else FORCE_BY_ORDER(ORDER_LOG, 0);
  } else {
    if (cached) FORCE_BY_ORDER(ORDER_ANY, 1);
    else FORCE_BY_ORDER(ORDER_ANY, 0);
  }
}

pd_ordinary_atom_out pd_ordinary_atom(double lambda, double mu, double norm, double sum)
{
  pd_ordinary_atom_out o;
  o.theta = norm * sum;
  o.a = lambda * o.theta * norm;
  o.b = 2.0 * mu * norm;
  o.energy = 0.5 * lambda * o.theta * o.theta;
  return o;
}

#include "pd_ordinary.h"

#include <math.h>
#include <stddef.h>

/* Strain of order m as a function of the length ratio; three variants so
 * the common orders pay for no pow(): m = 1/2 (LPS stretch), m = 0 (log). */
enum { ORDER_HALF, ORDER_LOG, ORDER_ANY };

static inline __attribute__((always_inline)) double
bond_strain(int kind, double m, double len, double r0)
{
  if (kind == ORDER_HALF) return (len - r0) / r0;
  if (kind == ORDER_LOG) return log(len / r0);
  return expm1(2.0 * m * log(len / r0)) / (2.0 * m);
}

/* d eps / d|Y| = c^(m-1) |Y| / |xi|^2 = (1 + 2 m eps) / |Y|. */
static inline __attribute__((always_inline)) double
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

static inline __attribute__((always_inline)) void
dilatation_loop(const pd_bond_view *restrict b, const pd_ordinary_state *st,
                const double *restrict x, const double *restrict vol, int kind, int cached)
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
      const double eps = bond_strain(kind, st->order, len, b->len0[row + k]);
      if (cached) st->strain[row + k] = eps;
      const double we = bond_weight(b, row + k) * eps;
      si += we * vol[j];
      sum[j] += we * vol[i];
    }
    sum[i] += si;
  }
}

void pd_ordinary_dilatation(const pd_bond_view *b, const pd_ordinary_state *st,
                            const double *x, const double *vol)
{
  const int cached = st->strain != NULL;
  switch (order_kind(st->order)) {
  case ORDER_HALF: dilatation_loop(b, st, x, vol, ORDER_HALF, 0); break;
  case ORDER_LOG:
    if (cached) dilatation_loop(b, st, x, vol, ORDER_LOG, 1);
    else dilatation_loop(b, st, x, vol, ORDER_LOG, 0);
    break;
  default:
    if (cached) dilatation_loop(b, st, x, vol, ORDER_ANY, 1);
    else dilatation_loop(b, st, x, vol, ORDER_ANY, 0);
  }
}

static inline __attribute__((always_inline)) void
force_loop(const pd_bond_view *restrict b, const pd_ordinary_state *st,
           const double *restrict x, const double *restrict vol,
           double *restrict f, pd_tally *tally, int kind, int tallied, int cached)
{
  const double *restrict ab = st->ab;
  const double m = st->order;
  for (int i = 0; i < b->nowner; i++) {
    const int n = b->count[i];
    if (!n) continue;
    const int row = i * b->stride;
    const double ai = ab[2 * i], bi = ab[2 * i + 1], vi = vol[i];
    double fi[3] = {0.0, 0.0, 0.0};
    for (int k = 0; k < n; k++) {
      const int j = b->far[row + k];
      const double r0 = b->len0[row + k];
      double d[3];
      const double len = bond_length(x, i, j, d);
      const double w = bond_weight(b, row + k);
      const double eps = cached ? st->strain[row + k] : bond_strain(kind, m, len, r0);
      const double bj = ab[2 * j + 1];
      const double t = (ai + ab[2 * j] + (bi + bj) * eps) * w *
                       bond_strain_rate(kind, m, eps, len, r0);
      const double tl = len > 0.0 ? t / len : 0.0;
      const double vj = vol[j];
      for (int c = 0; c < 3; c++) {
        fi[c] += vj * tl * d[c];
        f[3 * j + c] -= vi * tl * d[c];
      }
      if (tallied) {
        const double we2 = 0.5 * w * eps * eps;
        tally->energy += we2 * (bi * vj + bj * vi);
        if (tally->eatom) {
          tally->eatom[i] += we2 * bi * vj;
          tally->eatom[j] += we2 * bj * vi;
        }
        const double dij[3] = {-d[0], -d[1], -d[2]};
        pd_tally_virial(tally, dij, -tl * vi * vj);
      }
    }
    for (int c = 0; c < 3; c++) f[3 * i + c] += fi[c];
  }
}

/* Specialized copies: strain order x tally x strain cache (m != 1/2 only). */
#define FORCE_VARIANT(kind, tallied, cached) \
  force_loop(b, st, x, vol, f, (tallied) ? tally : NULL, kind, tallied, cached)

void pd_ordinary_forces(const pd_bond_view *b, const pd_ordinary_state *st,
                        const double *x, const double *vol, double *f,
                        pd_tally *tally)
{
  const int kind = order_kind(st->order);
  const int cached = st->strain != NULL && kind != ORDER_HALF;
  if (kind == ORDER_HALF) {
    if (tally) FORCE_VARIANT(ORDER_HALF, 1, 0);
    else FORCE_VARIANT(ORDER_HALF, 0, 0);
  } else if (kind == ORDER_LOG) {
    if (tally) {
      if (cached) FORCE_VARIANT(ORDER_LOG, 1, 1);
      else FORCE_VARIANT(ORDER_LOG, 1, 0);
    } else {
      if (cached) FORCE_VARIANT(ORDER_LOG, 0, 1);
      else FORCE_VARIANT(ORDER_LOG, 0, 0);
    }
  } else {
    if (tally) {
      if (cached) FORCE_VARIANT(ORDER_ANY, 1, 1);
      else FORCE_VARIANT(ORDER_ANY, 1, 0);
    } else {
      if (cached) FORCE_VARIANT(ORDER_ANY, 0, 1);
      else FORCE_VARIANT(ORDER_ANY, 0, 0);
    }
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
